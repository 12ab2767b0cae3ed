// A sphere shaded per pixel by GLSL given as text, in the style of the lecture notes (seed
// 000: row vectors, `vec4(vtxPos, 1) * MVP` with matrices uploaded transposed), drawn by the
// gpu pipeline through tessel::glsl and written to a PNG.
//
//   glsl_phong_sphere [out.png]
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "tessel/glsl/program.hpp"
#include "tessel/gpu/image.hpp"

using namespace tessel;

static const char* kVertex = R"(#version 330
precision highp float;
uniform mat4 MVP, M, Minv;          // row-vector convention: p * M
uniform vec3 wEye, wLiPos;
layout(location = 0) in vec3 vtxPos;
layout(location = 1) in vec3 vtxNorm;
out vec3 wNormal, wView, wLight;
void main() {
  gl_Position = vec4(vtxPos, 1) * MVP;
  vec4 wPos = vec4(vtxPos, 1) * M;
  wLight = wLiPos - wPos.xyz;
  wView = wEye - wPos.xyz;
  wNormal = (Minv * vec4(vtxNorm, 0)).xyz;
}
)";

static const char* kFragment = R"(#version 330
precision highp float;
uniform vec3 kd, ks, ka, La, Le;
uniform float shine;
in vec3 wNormal, wView, wLight;
out vec4 fragmentColor;
void main() {
  vec3 N = normalize(wNormal), V = normalize(wView), L = normalize(wLight);
  vec3 H = normalize(L + V);
  float cost = max(dot(N, L), 0.0), cosd = max(dot(N, H), 0.0);
  vec3 color = ka * La + (kd * cost + ks * pow(cosd, shine)) * Le;
  // stripes from the normal, to show per-pixel control flow
  if (fract(atan(N.z, N.x) * 3.0) < 0.1) color *= 0.5;
  fragmentColor = vec4(color, 1);
}
)";

int main(int argc, char** argv) {
  const char* out = argc > 1 ? argv[1] : "glsl_phong_sphere.png";
  auto vs = glsl::Shader::compile(glsl::Stage::Vertex, kVertex);
  auto fs = glsl::Shader::compile(glsl::Stage::Fragment, kFragment);
  if (!vs->ok() || !fs->ok()) {
    std::fprintf(stderr, "%s%s", vs->info_log().c_str(), fs->info_log().c_str());
    return 1;
  }
  auto prog = glsl::Program::link(*vs, *fs);
  if (!prog->ok()) {
    std::fprintf(stderr, "%s", prog->info_log().c_str());
    return 1;
  }
  // A UV sphere: positions and normals, as triangles.
  const int N = 48, M = 24;
  std::vector<float> v;
  auto at = [&](int i, int j) {
    const float u = float(i) / N * 2.0f * float(M_PI), w = float(j) / M * float(M_PI);
    return glm::vec3(std::cos(u) * std::sin(w), std::cos(w), std::sin(u) * std::sin(w));
  };
  for (int j = 0; j < M; ++j)
    for (int i = 0; i < N; ++i)
      for (auto [a, b] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}}) {
        const glm::vec3 p = at(i + a, j + b);
        v.insert(v.end(), {p.x, p.y, p.z, p.x, p.y, p.z});
      }
  gpu::Buffer vbo(v);
  gpu::VertexLayout layout;
  layout.attrib(0, vbo, 3, gpu::AttribType::F32, 24, 0).attrib(1, vbo, 3, gpu::AttribType::F32, 24, 12);

  // Matrices for row vectors: GL's column-major upload of the transposed matrix.
  const glm::mat4 model = glm::rotate(glm::mat4(1), 0.4f, glm::vec3(1, 0, 0));
  const glm::vec3 eye(0, 0, 3);
  const glm::mat4 view = glm::lookAt(eye, glm::vec3(0), glm::vec3(0, 1, 0));
  const glm::mat4 proj = glm::perspective(glm::radians(45.0f), 4.0f / 3.0f, 0.1f, 10.0f);
  auto set_mat = [&](const char* name, const glm::mat4& m) {
    const glm::mat4 t = glm::transpose(m);
    prog->set_uniform(prog->uniform_location(name), glm::value_ptr(t), 16);
  };
  set_mat("MVP", proj * view * model);
  set_mat("M", model);
  set_mat("Minv", glm::inverse(model));
  auto set3 = [&](const char* name, glm::vec3 x) {
    prog->set_uniform(prog->uniform_location(name), &x.x, 3);
  };
  set3("wEye", eye);
  set3("wLiPos", glm::vec3(2, 3, 4));
  set3("kd", glm::vec3(0.8f, 0.3f, 0.2f));
  set3("ks", glm::vec3(0.6f));
  set3("ka", glm::vec3(0.2f));
  set3("La", glm::vec3(0.4f));
  set3("Le", glm::vec3(1.0f));
  const float shine = 40.0f;
  prog->set_uniform(prog->uniform_location("shine"), &shine, 1);

  gpu::Texture2D color(gpu::Format::RGBA8, 640, 480), depth(gpu::Format::Depth32F, 640, 480);
  gpu::Framebuffer fb(&color, &depth);
  gpu::Context ctx;
  ctx.bind_framebuffer(&fb);
  ctx.clear({.color = {0.1f, 0.1f, 0.15f, 1}});
  gpu::RenderState state;
  state.depth_test = true;
  prog->draw(ctx, layout, state, {.topology = gpu::Topology::Triangles, .count = uint32_t(v.size() / 6)});
  ctx.finish();
  gpu::write_png(out, color);
  std::printf("wrote %s\n", out);
  return 0;
}
