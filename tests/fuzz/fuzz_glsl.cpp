// libFuzzer target: GLSL programs. The input is a vertex shader, a line "//FRAGMENT", and a
// fragment shader. Each is compiled, the two are linked, and a program that links draws a
// triangle into a 4x4 target: nothing may crash, hang or read out of bounds; errors are
// info logs, and a draw of a program that did not link throws tessel::gpu::Error.
#include <cstddef>
#include <cstdint>
#include <string>

#include "tessel/glsl/program.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 16384) return -1;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto cut = text.find("//FRAGMENT");
  const std::string vs = cut == std::string::npos ? text : text.substr(0, cut);
  const std::string fs =
      cut == std::string::npos ? std::string("void main() { gl_FragColor = vec4(1.0); }") : text.substr(cut);
  using namespace tessel;
  auto v = glsl::Shader::compile(glsl::Stage::Vertex, vs);
  auto f = glsl::Shader::compile(glsl::Stage::Fragment, fs);
  glsl::LinkOptions options;
  options.native_code = glsl::NativeCode::AtLink;  // the native code draws, under the sanitizers
  auto p = glsl::Program::link(*v, *f, options);
  if (!p->ok()) return 0;
  static const float tri[] = {-1, -1, 0, 1, 3, -1, 0, 1, -1, 3, 0, 1};
  gpu::Buffer vbo(tri, sizeof tri);
  gpu::VertexLayout layout;
  for (const auto& a : p->attributes()) layout.attrib(a.location, vbo, 4, gpu::AttribType::F32, 16, 0);
  layout.attrib(glsl::kLocationVertex, vbo, 4, gpu::AttribType::F32, 16, 0);
  gpu::Texture2D color(gpu::Format::RGBA8, 4, 4);
  gpu::Texture2D tex(gpu::Format::RGBA8, 2, 2);
  glsl::TextureBinding units[2] = {{&tex, nullptr, {}}, {&tex, nullptr, {}}};
  gpu::Framebuffer fb(&color);
  gpu::Context ctx(1);
  try {
    ctx.bind_framebuffer(&fb);
    p->draw(ctx, layout, gpu::RenderState{}, {.topology = gpu::Topology::Triangles, .count = 3}, units);
    ctx.finish();
  } catch (const gpu::Error&) {
  }
  return 0;
}
