#include "demo.hpp"

#include <chrono>
#include <cmath>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes.hpp"
#include "tessel/gpu/image.hpp"

namespace tessel::apps {
using namespace tessel::gpu;

namespace {

struct MeshData {
  std::vector<float> vertices;  // position 3, normal 3, uv 2
  std::vector<uint32_t> indices;
  void add(glm::vec3 p, glm::vec3 n, glm::vec2 uv) {
    vertices.insert(vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y});
  }
};

// The UV sphere of the benchmark scenes (bench/scenes).
MeshData make_sphere(int slices, int stacks) {
  scenes::Mesh s = scenes::sphere_mesh(slices, stacks);
  MeshData m;
  m.vertices = std::move(s.vertices);
  m.indices = std::move(s.indices);
  return m;
}

// A torus around the y axis: major radius R, tube radius r.
MeshData make_torus(float R, float r, int n_major, int n_minor) {
  MeshData m;
  const float pi = 3.14159265358979f;
  for (int i = 0; i <= n_major; ++i) {
    const float u = 2.0f * pi * float(i) / float(n_major);
    for (int j = 0; j <= n_minor; ++j) {
      const float v = 2.0f * pi * float(j) / float(n_minor);
      const glm::vec3 c(std::cos(u), 0.0f, -std::sin(u));
      const glm::vec3 n = c * std::cos(v) + glm::vec3(0, 1, 0) * std::sin(v);
      m.add(c * R + n * r, n, {float(i) / float(n_major), float(j) / float(n_minor)});
    }
  }
  for (int i = 0; i < n_major; ++i)
    for (int j = 0; j < n_minor; ++j) {
      const uint32_t a = uint32_t(i * (n_minor + 1) + j), b = a + uint32_t(n_minor + 1);
      m.indices.insert(m.indices.end(), {a, b, b + 1, a, b + 1, a + 1});
    }
  return m;
}

MeshData make_floor(float half, float tiles) {
  MeshData m;
  const glm::vec3 n(0, 1, 0);
  m.add({-half, 0, half}, n, {0, 0});
  m.add({half, 0, half}, n, {tiles, 0});
  m.add({half, 0, -half}, n, {tiles, tiles});
  m.add({-half, 0, -half}, n, {0, tiles});
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

struct Material {
  glm::vec3 albedo;
  float ambient, diffuse, specular, shininess;
};

// Blinn-Phong in world space with one directional and one point light, optionally textured.
struct BlinnPhong {
  struct Uniforms {
    glm::mat4 mvp, model, normal_matrix;
    glm::vec3 eye;
    glm::vec3 sun_dir;      // direction toward the sun
    glm::vec3 sun_color;
    glm::vec3 lamp_pos;     // point light
    glm::vec3 lamp_color;
    Material mat;
    bool textured = false;
    Sampler2D tex;
  };
  template <class F> struct Varyings {
    Vec3<F> p, n;
    Vec2<F> uv;
  };
  static constexpr uint32_t attributes = 0b111;

  template <class F> Vec4<F> vertex(const Uniforms& u, const VertexIn<F>& in, Varyings<F>& out) const {
    const Vec4<F> pos(in.attr[0].xyz(), F(1.0f));
    out.p = (u.model * pos).xyz();
    out.n = (u.normal_matrix * Vec4<F>(in.attr[1].xyz(), F(0.0f))).xyz();
    out.uv = in.attr[2].xy();
    return u.mvp * pos;
  }

  template <class F> void fragment(const Uniforms& u, const Varyings<F>& v, Fragment<F>& f) const {
    const Vec3<F> N = normalize(v.n);
    const Vec3<F> V = normalize(Vec3<F>(u.eye) - v.p);
    Vec3<F> albedo(u.mat.albedo);
    if (u.textured) albedo = albedo * texture(u.tex, v.uv).xyz();
    Vec3<F> c = albedo * F(u.mat.ambient);
    auto light = [&](const Vec3<F>& L, const Vec3<F>& radiance) {
      const F ndl = max(dot(N, L), F(0.0f));
      const Vec3<F> H = normalize(L + V);
      const F spec = select(ndl > F(0.0f), pow(max(dot(N, H), F(0.0f)), F(u.mat.shininess)), F(0.0f));
      c = c + radiance * (albedo * (ndl * F(u.mat.diffuse)) + Vec3<F>(spec * F(u.mat.specular)));
    };
    light(Vec3<F>(glm::normalize(u.sun_dir)), Vec3<F>(u.sun_color));
    const Vec3<F> to_lamp = Vec3<F>(u.lamp_pos) - v.p;
    const F d2 = dot(to_lamp, to_lamp);
    const F atten = F(1.0f) / (F(1.0f) + F(0.02f) * d2);
    light(to_lamp * (F(1.0f) / sqrt(d2)), Vec3<F>(u.lamp_color) * atten);
    f.color[0] = Vec4<F>(c, F(1.0f));
  }
};

struct GpuMesh {
  Buffer vertices, indices;
  VertexLayout layout;
  uint32_t count;
  explicit GpuMesh(const MeshData& m)
      : vertices(m.vertices), indices(m.indices), count(uint32_t(m.indices.size())) {
    const uint32_t stride = 8 * sizeof(float);
    layout.attrib(0, vertices, 3, AttribType::F32, stride, 0);
    layout.attrib(1, vertices, 3, AttribType::F32, stride, 3 * sizeof(float));
    layout.attrib(2, vertices, 2, AttribType::F32, stride, 6 * sizeof(float));
  }
  DrawCall call() const {
    return {.topology = Topology::Triangles, .count = count, .index_buffer = &indices, .index_type = IndexType::U32};
  }
};

// A 256x256 two-tone checkerboard with a thin grout line, full mipmap chain.
Texture2D make_floor_texture() {
  const int n = 256;
  std::vector<uint8_t> px(size_t(n) * n * 4);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const bool check = ((x / 32) + (y / 32)) & 1;
      const bool grout = (x % 32) == 0 || (y % 32) == 0;
      uint8_t* p = &px[(size_t(y) * n + x) * 4];
      const uint8_t c = grout ? 60 : check ? 235 : 140;
      p[0] = c;
      p[1] = uint8_t(c * 0.92f);
      p[2] = uint8_t(c * 0.85f);
      p[3] = 255;
    }
  Texture2D t(Format::RGBA8, n, n, 0);
  t.upload_rgba8(0, px.data(), px.size());
  t.generate_mipmaps();
  return t;
}

}  // namespace

DemoResult render_demo(int width, int height, int threads, const std::string& png) {
  Texture2D color(Format::RGBA8, width, height);
  Texture2D depth(Format::Depth24Stencil8, width, height);
  Framebuffer fb(&color, &depth);
  Context ctx(threads);

  const GpuMesh sphere(make_sphere(48, 32));
  const GpuMesh torus(make_torus(1.0f, 0.35f, 64, 24));
  const GpuMesh floor(make_floor(8.0f, 8.0f));
  Texture2D floor_tex = make_floor_texture();

  const glm::vec3 eye(0.0f, 3.2f, 7.5f);
  const glm::mat4 view = glm::lookAt(eye, glm::vec3(0.0f, 0.6f, 0.0f), glm::vec3(0, 1, 0));
  const glm::mat4 proj = glm::perspective(glm::radians(45.0f), float(width) / float(height), 0.5f, 100.0f);

  BlinnPhong::Uniforms base;
  base.eye = eye;
  base.sun_dir = glm::vec3(-0.4f, 1.0f, 0.6f);
  base.sun_color = glm::vec3(0.85f, 0.82f, 0.75f);
  base.lamp_pos = glm::vec3(2.5f, 2.5f, 2.0f);
  base.lamp_color = glm::vec3(0.9f, 0.7f, 0.5f);

  struct Item {
    const GpuMesh* mesh;
    glm::mat4 model;
    Material mat;
    bool textured;
  };
  const Item items[] = {
      {&floor, glm::mat4(1.0f), {{1.0f, 1.0f, 1.0f}, 0.15f, 0.8f, 0.1f, 16.0f}, true},
      {&sphere, glm::scale(glm::translate(glm::mat4(1.0f), {-2.2f, 1.0f, 0.0f}), glm::vec3(1.0f)),
       {{0.85f, 0.2f, 0.15f}, 0.1f, 0.8f, 0.6f, 48.0f}, false},
      {&sphere, glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 0.7f, 1.4f}), glm::vec3(0.7f)),
       {{0.2f, 0.45f, 0.9f}, 0.1f, 0.8f, 0.8f, 96.0f}, false},
      {&sphere, glm::scale(glm::translate(glm::mat4(1.0f), {2.3f, 0.55f, 0.6f}), glm::vec3(0.55f)),
       {{0.95f, 0.8f, 0.2f}, 0.1f, 0.8f, 0.5f, 32.0f}, false},
      {&torus, glm::rotate(glm::translate(glm::mat4(1.0f), {0.3f, 1.25f, -1.6f}), glm::radians(60.0f), {1, 0, 0.3f}),
       {{0.3f, 0.8f, 0.4f}, 0.1f, 0.75f, 0.7f, 64.0f}, false},
  };

  RenderState state;
  state.depth_test = true;
  state.cull = CullMode::Back;

  DemoResult r;
  const auto t0 = std::chrono::steady_clock::now();
  ctx.bind_framebuffer(&fb);
  ctx.clear({.color = {0.55f, 0.68f, 0.85f, 1.0f}, .depth = 1.0f});
  for (const Item& it : items) {
    BlinnPhong::Uniforms u = base;
    u.model = it.model;
    u.mvp = proj * view * it.model;
    u.normal_matrix = glm::transpose(glm::inverse(it.model));
    u.mat = it.mat;
    u.textured = it.textured;
    u.tex.texture = &floor_tex;
    u.tex.state.min_filter = Filter::LinearMipmapLinear;
    u.tex.state.mag_filter = Filter::Linear;
    ctx.draw(BlinnPhong{}, u, it.mesh->layout, state, it.mesh->call());
    r.triangles += int(it.mesh->count / 3);
  }
  ctx.finish();
  r.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  r.stats = ctx.stats();
  write_png(png, color);
  return r;
}

}  // namespace tessel::apps
