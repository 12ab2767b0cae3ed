// Runs a GlslDrawSpec (tests/reference/glsl_oracle.hpp) on Tessel: the same GLSL, attributes,
// uniforms and textures that the Mesa oracle draws, into RGBA32F targets, read back the same
// way (rows bottom-up), so that the two results compare value for value.
#pragma once

#include <bit>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "glsl_oracle.hpp"
#include "tessel/glsl/program.hpp"

namespace tessel::testing {

struct TesselResult {
  bool ok = false;
  std::string log;
  std::vector<std::vector<float>> outputs;
};

inline gpu::Filter to_filter(uint32_t e) {
  switch (e) {
    case 0x2600: return gpu::Filter::Nearest;
    case 0x2601: return gpu::Filter::Linear;
    case 0x2700: return gpu::Filter::NearestMipmapNearest;
    case 0x2701: return gpu::Filter::LinearMipmapNearest;
    case 0x2702: return gpu::Filter::NearestMipmapLinear;
    default: return gpu::Filter::LinearMipmapLinear;
  }
}
inline gpu::Wrap to_wrap(uint32_t e) {
  switch (e) {
    case 0x812F: return gpu::Wrap::ClampToEdge;
    case 0x8370: return gpu::Wrap::MirroredRepeat;
    case 0x812D: return gpu::Wrap::ClampToBorder;
    default: return gpu::Wrap::Repeat;
  }
}

// `native`: AtLink runs the native code from the first draw, Off the interpreter (the
// reference tier the tests compare it with).
inline TesselResult run_tessel(const reference::GlslDrawSpec& spec, int threads = 2,
                               glsl::NativeCode native = glsl::NativeCode::AtLink) {
  TesselResult r;
  auto vs = glsl::Shader::compile(glsl::Stage::Vertex, spec.vertex);
  auto fs = glsl::Shader::compile(glsl::Stage::Fragment, spec.fragment);
  auto gs = glsl::Shader::compile(glsl::Stage::Geometry, spec.geometry);
  if (!vs->ok() || !fs->ok() || (!spec.geometry.empty() && !gs->ok())) {
    r.log = vs->info_log() + fs->info_log() + (spec.geometry.empty() ? "" : gs->info_log());
    return r;
  }
  glsl::LinkOptions options;
  options.native_code = native;
  std::vector<const glsl::Shader*> shaders = {vs.get(), fs.get()};
  if (!spec.geometry.empty()) shaders.push_back(gs.get());
  auto prog = glsl::Program::link(shaders, options);
  if (!prog->ok()) {
    r.log = prog->info_log();
    return r;
  }
  // The fixed-function matrices of a compatibility shader (identity unless given).
  if (!spec.modelview.empty() || !spec.projection.empty()) {
    glm::mat4 mv(1.0f), pr(1.0f);
    if (spec.modelview.size() == 16) std::memcpy(&mv[0][0], spec.modelview.data(), 64);
    if (spec.projection.size() == 16) std::memcpy(&pr[0][0], spec.projection.data(), 64);
    prog->set_compat_matrices(mv, pr);
  }
  // Attributes.
  std::vector<std::unique_ptr<gpu::Buffer>> buffers;
  gpu::VertexLayout layout;
  for (const auto& a : spec.attributes) {
    int loc = prog->attribute_location(a.name);
    // The compatibility built-ins are not active attributes (GL reports -1 for them too);
    // they have fixed locations, as the GL layer feeds them from glVertexPointer & co.
    if (loc < 0) loc = glsl::builtin_attribute_location(a.name);
    if (loc < 0) continue;
    if (a.integer) {
      buffers.push_back(std::make_unique<gpu::Buffer>(a.idata.data(), a.idata.size() * 4));
      layout.attrib(loc, *buffers.back(), a.components, gpu::AttribType::I32, 0, 0);
      layout.attribs[size_t(loc)].integer = true;
    } else {
      buffers.push_back(std::make_unique<gpu::Buffer>(a.data.data(), a.data.size() * 4));
      layout.attrib(loc, *buffers.back(), a.components, gpu::AttribType::F32, 0, 0);
    }
  }
  for (const auto& u : spec.uniforms) {
    const int loc = prog->uniform_location(u.name);
    if (loc < 0) continue;
    // Components per element: the count of values over the elements given.
    auto try_set = [&](auto* data, size_t n) {
      for (int comps : {16, 12, 9, 8, 6, 4, 3, 2, 1}) {
        if (n % size_t(comps) != 0) continue;
        if (prog->set_uniform(loc, data, comps, int(n / size_t(comps)))) return true;
      }
      return false;
    };
    bool done = false;
    if (!u.f.empty())
      done = try_set(u.f.data(), u.f.size());
    else if (!u.i.empty())
      done = try_set(u.i.data(), u.i.size());
    else if (!u.u.empty())
      done = try_set(u.u.data(), u.u.size());
    if (!done) r.log += "uniform '" + u.name + "' could not be set\n";
  }
  // Textures: 1D and rectangle ones as 2D, 1D arrays as height-1 2D arrays, buffer textures
  // as views of a buffer of RGBA32F texels (integer formats hold each value's 32 bits in the
  // float, which the isampler/usampler lookups read, as the GL layer stores them).
  std::vector<std::unique_ptr<gpu::Texture2D>> textures;
  std::vector<std::unique_ptr<gpu::TextureCube>> cubes;
  std::vector<std::unique_ptr<gpu::Texture3D>> volumes;
  std::vector<std::unique_ptr<gpu::Texture2DArray>> arrays;
  std::vector<std::unique_ptr<gpu::Buffer>> texel_buffers;
  std::vector<std::unique_ptr<gpu::TextureBuffer>> buffer_textures;
  std::vector<glsl::TextureBinding> units(16);
  for (const auto& t : spec.textures) {
    gpu::SamplerState st;
    st.min_filter = to_filter(t.min_filter);
    st.mag_filter = to_filter(t.mag_filter);
    st.wrap_s = st.wrap_t = st.wrap_r = to_wrap(t.wrap);
    st.compare = t.compare;
    st.compare_func = gpu::CompareFunc(t.compare_func - 0x0200u);  // GL_NEVER.. in GL's order
    if (!t.mipmaps) st.max_lod = 0.0f;
    const bool depth = t.internal_format == 0x8CAC;  // GL_DEPTH_COMPONENT32F
    const gpu::Format fmt = depth                         ? gpu::Format::Depth32F
                            : t.internal_format == 0x8058 ? gpu::Format::RGBA8
                                                          : gpu::Format::RGBA32F;
    // The data as RGBA floats (depth textures give one float per texel).
    std::vector<float> rgba = t.data;
    const bool sint = t.internal_format == 0x8D82 || t.internal_format == 0x8235,  // GL_RGBA32I, GL_R32I
        uint = t.internal_format == 0x8D70 || t.internal_format == 0x8236;         // GL_RGBA32UI, GL_R32UI
    if (sint || uint)
      for (float& v : rgba) v = std::bit_cast<float>(sint ? uint32_t(int32_t(v)) : uint32_t(v));
    if (depth) {
      rgba.assign(t.data.size() * 4, 0.0f);
      for (size_t i = 0; i < t.data.size(); ++i) rgba[i * 4] = t.data[i];
    }
    const int levels = t.mipmaps ? 0 : 1;
    glsl::TextureBinding& unit = units.at(size_t(t.unit));
    switch (t.target) {
      case 0x8513: {  // GL_TEXTURE_CUBE_MAP
        cubes.push_back(std::make_unique<gpu::TextureCube>(fmt, t.width, levels));
        const size_t face = size_t(t.width * t.height * 4);
        for (int f = 0; f < 6; ++f)
          cubes.back()->face(f).upload_rgba32f(0, rgba.data() + size_t(f) * face, face * 4);
        if (t.mipmaps) cubes.back()->generate_mipmaps();
        unit.texture_cube = cubes.back().get();
        break;
      }
      case 0x806F:  // GL_TEXTURE_3D
        volumes.push_back(std::make_unique<gpu::Texture3D>(fmt, t.width, t.height, t.depth, levels));
        volumes.back()->upload_rgba32f(0, rgba.data(), size_t(t.width * t.height * t.depth) * 16);
        if (t.mipmaps) volumes.back()->generate_mipmaps();
        unit.texture_3d = volumes.back().get();
        break;
      case 0x8C1A:    // GL_TEXTURE_2D_ARRAY
      case 0x8C18: {  // GL_TEXTURE_1D_ARRAY: height is the layer count
        const bool one = t.target == 0x8C18;
        arrays.push_back(std::make_unique<gpu::Texture2DArray>(fmt, t.width, one ? 1 : t.height,
                                                               one ? t.height : t.depth, levels));
        arrays.back()->upload_rgba32f(0, rgba.data(), size_t(t.width * t.height * (one ? 1 : t.depth)) * 16);
        if (t.mipmaps) arrays.back()->generate_mipmaps();
        unit.texture_2d_array = arrays.back().get();
        break;
      }
      case 0x8C2A:  // GL_TEXTURE_BUFFER
        texel_buffers.push_back(std::make_unique<gpu::Buffer>(rgba.data(), size_t(t.width) * 16));
        buffer_textures.push_back(
            std::make_unique<gpu::TextureBuffer>(gpu::Format::RGBA32F, *texel_buffers.back()));
        unit.texture_buffer = buffer_textures.back().get();
        break;
      default:
        textures.push_back(std::make_unique<gpu::Texture2D>(fmt, t.width, t.height, levels));
        textures.back()->upload_rgba32f(0, rgba.data(), size_t(t.width * t.height) * 16);
        if (t.mipmaps) textures.back()->generate_mipmaps();
        unit.texture_2d = textures.back().get();
        break;
    }
    unit.sampler = st;
  }
  // Targets.
  std::vector<std::unique_ptr<gpu::Texture2D>> colors;
  gpu::Framebuffer fb;
  for (int i = 0; i < spec.outputs; ++i) {
    colors.push_back(std::make_unique<gpu::Texture2D>(gpu::Format::RGBA32F, spec.width, spec.height));
    fb.color[size_t(i)].texture = colors.back().get();
  }
  std::unique_ptr<gpu::Texture2D> depth;
  if (spec.depth) {
    depth = std::make_unique<gpu::Texture2D>(gpu::Format::Depth32F, spec.width, spec.height);
    fb.depth.texture = depth.get();
  }
  try {
    gpu::Context ctx(threads);
    ctx.bind_framebuffer(&fb);
    gpu::ClearValues cv;
    cv.color = glm::vec4(spec.clear[0], spec.clear[1], spec.clear[2], spec.clear[3]);
    ctx.clear(cv);
    gpu::RenderState state;
    state.viewport = {0, 0, spec.width, spec.height};
    state.depth_test = spec.depth;
    state.clip_plane_enable = spec.clip_distances;
    state.program_point_size = true;  // as the oracle: GL_PROGRAM_POINT_SIZE, GL_POINT_SPRITE
    gpu::DrawCall call;
    call.count = uint32_t(spec.count);
    switch (spec.primitive) {
      case 0x0000: call.topology = gpu::Topology::Points; break;
      case 0x0001: call.topology = gpu::Topology::Lines; break;
      case 0x0003: call.topology = gpu::Topology::LineStrip; break;
      case 0x0005: call.topology = gpu::Topology::TriangleStrip; break;
      case 0x0006: call.topology = gpu::Topology::TriangleFan; break;
      case 0x000A: call.topology = gpu::Topology::LinesAdjacency; break;
      case 0x000B: call.topology = gpu::Topology::LineStripAdjacency; break;
      case 0x000C: call.topology = gpu::Topology::TrianglesAdjacency; break;
      case 0x000D: call.topology = gpu::Topology::TriangleStripAdjacency; break;
      default: call.topology = gpu::Topology::Triangles; break;
    }
    std::vector<std::unique_ptr<gpu::Buffer>> ubos;
    std::vector<glsl::BufferBinding> points;
    for (size_t i = 0; i < spec.uniform_buffers.size(); ++i) {
      const auto& ub = spec.uniform_buffers[i];
      const int index = prog->uniform_block_index(ub.block);
      ubos.push_back(std::make_unique<gpu::Buffer>(ub.data.data(), ub.data.size()));
      points.push_back({ubos.back().get(), 0, 0});
      if (index >= 0) prog->set_uniform_block_binding(index, int(i));
    }
    prog->draw(ctx, layout, state, call, units, points);
    ctx.finish();
  } catch (const std::exception& e) {
    r.log += e.what();
    return r;
  }
  for (const auto& c : colors) {
    std::vector<float> px(size_t(spec.width * spec.height) * 4);
    for (int y = 0; y < spec.height; ++y)
      for (int x = 0; x < spec.width; ++x) {
        const glm::vec4 v = c->fetch(0, x, y);
        std::memcpy(&px[(size_t(y) * size_t(spec.width) + size_t(x)) * 4], &v, 16);
      }
    r.outputs.push_back(std::move(px));
  }
  r.ok = true;
  return r;
}

}  // namespace tessel::testing
