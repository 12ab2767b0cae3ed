#include "scenes.hpp"

#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

namespace tessel::scenes {

namespace {

void add_vertex(Mesh& m, glm::vec3 p, glm::vec3 n, glm::vec2 uv) {
  m.vertices.insert(m.vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y});
}

// The UV sphere of the scenes README: ring k = 0..stacks (theta = pi k / stacks), column
// j = 0..slices (phi = 2 pi j / slices), seam duplicated, counter-clockwise from outside.
void add_sphere(Mesh& m, int slices, int stacks) {
  const double pi = 3.14159265358979323846;
  for (int k = 0; k <= stacks; ++k) {
    const double theta = pi * k / stacks;
    for (int j = 0; j <= slices; ++j) {
      const double phi = 2.0 * pi * j / slices;
      const glm::vec3 n(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                        float(-std::sin(theta) * std::sin(phi)));
      add_vertex(m, n, n, {float(j) / float(slices), float(k) / float(stacks)});
    }
  }
  auto id = [&](int k, int j) { return uint32_t(k * (slices + 1) + j); };
  for (int k = 0; k < stacks; ++k)
    for (int j = 0; j < slices; ++j) {
      const uint32_t a = id(k, j), b = id(k + 1, j), c = id(k + 1, j + 1), d = id(k, j + 1);
      if (k == 0)
        m.indices.insert(m.indices.end(), {a, b, c});
      else if (k == stacks - 1)
        m.indices.insert(m.indices.end(), {a, b, d});
      else
        m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
    }
}

Scene spheres(int slices, int stacks) {
  Scene s;
  s.mesh = sphere_mesh(slices, stacks);
  const auto count = uint32_t(s.mesh.indices.size());
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      Draw d;
      d.first_index = 0;
      d.index_count = count;
      d.offset = glm::vec3((float(i) - 4.5f) * 3.0f, 0.0f, (float(j) - 4.5f) * 3.0f);
      d.albedo = glm::vec3(0.2f + 0.6f * float(i) / 9.0f, 0.5f, 0.2f + 0.6f * float(j) / 9.0f);
      s.draws.push_back(d);
    }
  s.eye = glm::vec3(0.0f, 14.0f, 26.0f);
  s.view = glm::lookAt(s.eye, glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  s.light = glm::vec3(10.0f, 20.0f, 15.0f);
  s.instanceable = true;
  return s;
}

Scene fill(float aspect) {
  Scene s;
  for (int k = 0; k < 20; ++k) {
    const float d = float(40 - k);
    const float hx = 0.5f * d * aspect, hy = 0.5f * d;
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const auto base = uint32_t(s.mesh.vertices.size() / Mesh::kStride);
    for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
      const float x = c.x * hx, y = c.y * hy;
      add_vertex(s.mesh, {x, y, -d}, n, {2.0f * x / d, 2.0f * y / d});
    }
    s.mesh.indices.insert(s.mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    const float t = float(k) / 19.0f;
    Draw dr;
    dr.first_index = uint32_t(6 * k);
    dr.index_count = 6;
    dr.albedo = glm::vec3(0.2f + 0.6f * t, 0.6f, 0.8f - 0.6f * t);
    s.draws.push_back(dr);
  }
  s.eye = glm::vec3(0.0f);
  s.view = glm::mat4(1.0f);
  s.light = glm::vec3(8.0f, 6.0f, -10.0f);
  return s;
}

}  // namespace

Mesh sphere_mesh(int slices, int stacks) {
  Mesh m;
  add_sphere(m, slices, stacks);
  return m;
}

uint64_t Scene::triangles() const {
  uint64_t n = 0;
  for (const Draw& d : draws) n += d.index_count / 3;
  return n;
}

const std::vector<std::string>& scene_names() {
  static const std::vector<std::string> names = {"spheres-100k", "spheres-1m", "fill", "textured",
                                                 "fixed-100k"};
  return names;
}

bool is_scene(const std::string& name) {
  for (const auto& n : scene_names())
    if (n == name) return true;
  return false;
}

Scene make_scene(const std::string& name, int width, int height) {
  if (width < 1 || height < 1) throw std::invalid_argument("scene size must be at least 1x1");
  const float aspect = float(width) / float(height);
  Scene s;
  if (name == "spheres-100k")
    s = spheres(25, 21);
  else if (name == "spheres-1m")
    s = spheres(100, 51);
  else if (name == "fill")
    s = fill(aspect);
  else if (name == "textured") {
    s = fill(aspect);
    s.textured = true;
  } else if (name == "fixed-100k") {
    s = spheres(25, 21);
    s.fixed_function = true;
    s.instanceable = false;
  } else {
    std::string known;
    for (const auto& n : scene_names()) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown scene '" + name + "' (known: " + known + ")");
  }
  s.name = name;
  s.width = width;
  s.height = height;
  s.projection = glm::perspective(glm::radians(45.0f), aspect, 0.5f, 100.0f);
  return s;
}

std::vector<uint8_t> texture_rgba8() {
  const int n = kTextureSize;
  std::vector<uint8_t> px(size_t(n) * n * 4);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int c = ((x >> 6) + (y >> 6)) & 1;
      uint8_t* p = &px[(size_t(y) * n + x) * 4];
      p[0] = uint8_t(c ? 220 : 30);
      p[1] = uint8_t((x ^ y) & 255);
      p[2] = uint8_t((y * 255) / 1023);
      p[3] = 255;
    }
  return px;
}

}  // namespace tessel::scenes
