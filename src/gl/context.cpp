// The GL context: buffers, the batching of vertices into gpu draws, and the translation of
// GL state into the gpu layer's RenderState and the fixed-function shader's uniforms.
#include "context.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace tessel::gl {

namespace {
thread_local Context* g_current = nullptr;

gpu::StencilOp stencil_op_of(GLenum op) {
  switch (op) {
    case GL_ZERO: return gpu::StencilOp::Zero;
    case GL_REPLACE: return gpu::StencilOp::Replace;
    case GL_INCR: return gpu::StencilOp::Incr;
    case GL_DECR: return gpu::StencilOp::Decr;
    case GL_INVERT: return gpu::StencilOp::Invert;
    case GL_INCR_WRAP: return gpu::StencilOp::IncrWrap;
    case GL_DECR_WRAP: return gpu::StencilOp::DecrWrap;
    default: return gpu::StencilOp::Keep;
  }
}

gpu::BlendFactor blend_of(GLenum f) {
  using B = gpu::BlendFactor;
  switch (f) {
    case GL_ZERO: return B::Zero;
    case GL_ONE: return B::One;
    case GL_SRC_COLOR: return B::SrcColor;
    case GL_ONE_MINUS_SRC_COLOR: return B::OneMinusSrcColor;
    case GL_DST_COLOR: return B::DstColor;
    case GL_ONE_MINUS_DST_COLOR: return B::OneMinusDstColor;
    case GL_SRC_ALPHA: return B::SrcAlpha;
    case GL_ONE_MINUS_SRC_ALPHA: return B::OneMinusSrcAlpha;
    case GL_DST_ALPHA: return B::DstAlpha;
    case GL_ONE_MINUS_DST_ALPHA: return B::OneMinusDstAlpha;
    case GL_SRC_ALPHA_SATURATE: return B::SrcAlphaSaturate;
    case GL_CONSTANT_COLOR: return B::ConstantColor;
    case GL_ONE_MINUS_CONSTANT_COLOR: return B::OneMinusConstantColor;
    case GL_CONSTANT_ALPHA: return B::ConstantAlpha;
    case GL_ONE_MINUS_CONSTANT_ALPHA: return B::OneMinusConstantAlpha;
    case GL_SRC1_COLOR: return B::Src1Color;
    case GL_ONE_MINUS_SRC1_COLOR: return B::OneMinusSrc1Color;
    case GL_SRC1_ALPHA: return B::Src1Alpha;
    case GL_ONE_MINUS_SRC1_ALPHA: return B::OneMinusSrc1Alpha;
    default: return B::One;
  }
}

gpu::PolygonMode polygon_mode_of(GLenum m) {
  return m == GL_LINE    ? gpu::PolygonMode::Line
         : m == GL_POINT ? gpu::PolygonMode::Point
                         : gpu::PolygonMode::Fill;
}

}  // namespace

std::array<uint8_t, 2> color_material_track(const LightState& L) {
  std::array<uint8_t, 2> track{};
  if (!L.color_material) return track;
  uint8_t bits = 0;
  switch (L.color_material_mode) {
    case GL_AMBIENT: bits = kTrackAmbient; break;
    case GL_DIFFUSE: bits = kTrackDiffuse; break;
    case GL_SPECULAR: bits = kTrackSpecular; break;
    case GL_EMISSION: bits = kTrackEmission; break;
    default: bits = kTrackAmbient | kTrackDiffuse; break;
  }
  if (L.color_material_face != GL_BACK) track[0] = bits;
  if (L.color_material_face != GL_FRONT) track[1] = bits;
  return track;
}

float rescale_factor(const glm::mat4& modelview) {
  // GL 2.1 §2.11.3: f = 1 / sqrt(m31^2 + m32^2 + m33^2) of the inverse model-view matrix.
  const glm::mat3 inv = glm::inverse(glm::mat3(modelview));
  const float l = std::sqrt(inv[0][2] * inv[0][2] + inv[1][2] * inv[1][2] + inv[2][2] * inv[2][2]);
  return l > 0.0f ? 1.0f / l : 1.0f;
}

// The base format the texture environment sees (GL 3.3 compatibility Table 3.25: RED and
// RG act as RGB; depth textures as their GL_DEPTH_TEXTURE_MODE says).
BaseFormat ff_base_format(const TextureObject& t) {
  switch (t.base_image().fmt.base) {
    case TexBase::Alpha: return BaseFormat::Alpha;
    case TexBase::Luminance: return BaseFormat::Luminance;
    case TexBase::LuminanceAlpha: return BaseFormat::LuminanceAlpha;
    case TexBase::Intensity: return BaseFormat::Intensity;
    case TexBase::RGBA: return BaseFormat::RGBA;
    case TexBase::Depth:
    case TexBase::DepthStencil:
      return t.depth_mode == GL_LUMINANCE   ? BaseFormat::Luminance
             : t.depth_mode == GL_INTENSITY ? BaseFormat::Intensity
             : t.depth_mode == GL_ALPHA     ? BaseFormat::Alpha
                                            : BaseFormat::RGB;
    default: return BaseFormat::RGB;
  }
}

namespace {

constexpr size_t kTransientFlushBytes = size_t(256) << 20;
}  // namespace

Context* current() { return g_current; }
void make_current(Context* c) { g_current = c; }

gpu::CompareFunc compare_of(GLenum f) {
  switch (f) {
    case GL_NEVER: return gpu::CompareFunc::Never;
    case GL_LESS: return gpu::CompareFunc::Less;
    case GL_EQUAL: return gpu::CompareFunc::Equal;
    case GL_LEQUAL: return gpu::CompareFunc::LessEqual;
    case GL_GREATER: return gpu::CompareFunc::Greater;
    case GL_NOTEQUAL: return gpu::CompareFunc::NotEqual;
    case GL_GEQUAL: return gpu::CompareFunc::GreaterEqual;
    default: return gpu::CompareFunc::Always;
  }
}

FFPostVertex lerp_post(const FFPostVertex& a, const FFPostVertex& b, float t) {
  FFPostVertex r;
  const float* pa = &a.pos[0];
  const float* pb = &b.pos[0];
  float* pr = &r.pos[0];
  for (size_t k = 0; k < sizeof(FFPostVertex) / sizeof(float); ++k) pr[k] = pa[k] + (pb[k] - pa[k]) * t;
  return r;
}

Context::Context(int width, int height, bool double_buffer, bool depth, bool stencil)
    : double_buffer_(double_buffer), has_depth_(depth || stencil), has_stencil_(stencil) {
  for (auto& m : matrices) m.assign(1, glm::mat4(1.0f));
  for (int i = 0; i < kTexTargetCount; ++i) default_textures[size_t(i)] = make_texture(0, TexTarget(i));
  s.color.draw_buffer = double_buffer ? GL_BACK : GL_FRONT;
  s.pixel.read_buffer = double_buffer ? GL_BACK : GL_FRONT;
  for (int i = 0; i < kMaxLights; ++i) s.light.spot_cutoff[size_t(i)] = 180.0f;
  s.light.light[0].diffuse = glm::vec4(1.0f);
  s.light.light[0].specular = glm::vec4(1.0f);
  s.light.material[0] = s.light.material[1] = FFMaterial{};
  set_version(2, 1, false);
  generic_type.fill(GL_FLOAT);
  for (auto& g : generic_current) g = {0, 0, 0, 0x3F800000u};  // (0, 0, 0, 1)
  gpu_ = std::make_unique<gpu::Context>();
  resize(width, height);
  s.viewport = {0, 0, width_, height_, 0.0, 1.0};
  s.scissor = {false, 0, 0, width_, height_};
}

Context::~Context() {
  if (g_current == this) g_current = nullptr;
  batch_ = {};
  gpu_->finish();
}

void Context::resize(int width, int height) {
  width = std::clamp(width, 1, gpu::kMaxViewportSize);
  height = std::clamp(height, 1, gpu::kMaxViewportSize);
  if (width == width_ && height == height_ && color_[0]) return;
  touch();
  gpu_->finish();
  fb_ = gpu::Framebuffer();
  fb_target_ = 0;
  gpu_->bind_framebuffer(nullptr);
  width_ = width;
  height_ = height;
  // New buffers start black (alpha 0) with depth 1, as a freshly mapped window would.
  for (int i = 0; i < (double_buffer_ ? 2 : 1); ++i)
    color_[i] = std::make_unique<gpu::Texture2D>(gpu::Format::RGBA8, width, height);
  if (!double_buffer_) color_[1].reset();
  if (has_depth_) {
    depth_ = std::make_unique<gpu::Texture2D>(gpu::Format::Depth24Stencil8, width, height);
    gpu::Framebuffer f(nullptr, depth_.get());
    gpu_->bind_framebuffer(&f);
    gpu::ClearValues cv;
    cv.clear_color = false;
    gpu_->clear(cv);
    gpu_->finish();
    gpu_->bind_framebuffer(nullptr);
  }
}

gpu::Texture2D* Context::color_buffer(GLenum which) {
  switch (which) {
    case GL_FRONT:
    case GL_FRONT_LEFT:
    case GL_LEFT:
    case GL_FRONT_AND_BACK: return color_[0].get();
    case GL_BACK:
    case GL_BACK_LEFT: return double_buffer_ ? color_[1].get() : nullptr;
    default: return nullptr;
  }
}

namespace {
constexpr GLenum kFramebufferObjectTarget = 0xFFFFFFFFu;  // fb_target_ while an FBO is bound
bool same_attachment(const gpu::Attachment& a, const gpu::Attachment& b) { return a == b; }
}  // namespace

bool Context::bind_draw_target(int layer) {
  if (conditional_render_skips()) return false;
  if (!draw_fbo && !has_default_framebuffer) {
    error(GL_INVALID_FRAMEBUFFER_OPERATION);
    return false;
  }
  if (!draw_fbo) {
    const GLenum target = s.color.draw_buffer;
    if (fb_target_ == target && gpu_->framebuffer() == &fb_) return true;
    fb_ = gpu::Framebuffer(color_buffer(target), depth_.get());
    if (!fb_.color[0].texture && !depth_) fb_.color[0].texture = color_[0].get();
    fb_target_ = target;
    gpu_->bind_framebuffer(&fb_);
    return true;
  }
  FramebufferObject& f = *draw_fbo;
  if (framebuffer_status(f) != GL_FRAMEBUFFER_COMPLETE) {
    error(GL_INVALID_FRAMEBUFFER_OPERATION);
    return false;
  }
  gpu::Framebuffer nf;
  bool any = false;
  auto take = [&](const Attachment& a, gpu::Attachment& out) {
    if (!gpu_image(a, out, layer)) return;
    any = true;
    if (a.type == GL_TEXTURE) a.texture->rendered = true;  // images pulled back before CPU access
  };
  for (int i = 0; i < kMaxDrawBuffers; ++i) {
    const GLenum db = f.draw_buffers[size_t(i)];
    if (db >= GL_COLOR_ATTACHMENT0 && db < GL_COLOR_ATTACHMENT0 + kMaxColorAttachments)
      take(f.color[db - GL_COLOR_ATTACHMENT0], nf.color[size_t(i)]);
  }
  take(f.depth ? f.depth : f.stencil, nf.depth);
  if (!any) return false;  // no draw buffer has an image: draws change nothing
  bool same = fb_target_ == kFramebufferObjectTarget && gpu_->framebuffer() == &fb_ &&
              same_attachment(fb_.depth, nf.depth);
  for (int i = 0; i < kMaxDrawBuffers && same; ++i)
    same = same_attachment(fb_.color[size_t(i)], nf.color[size_t(i)]);
  if (same) return true;
  fb_ = nf;
  fb_target_ = kFramebufferObjectTarget;
  bool ok = true;
  guarded([&] {
    ok = false;
    gpu_->bind_framebuffer(&fb_);
    ok = true;
  });
  if (!ok) fb_target_ = 0;
  return ok;
}

Context::TargetInfo Context::target_info() const {
  TargetInfo t;
  if (!draw_fbo) {
    t.depth = has_depth_;
    t.stencil = has_stencil_;
    t.channels[0] = 0xF;
    return t;
  }
  const FramebufferObject& f = *draw_fbo;
  TexFormat fmt;
  int w, h;
  for (int i = 0; i < kMaxDrawBuffers; ++i) {
    const GLenum db = f.draw_buffers[size_t(i)];
    if (db >= GL_COLOR_ATTACHMENT0 && db < GL_COLOR_ATTACHMENT0 + kMaxColorAttachments &&
        f.color[db - GL_COLOR_ATTACHMENT0].image(fmt, w, h)) {
      t.channels[size_t(i)] = fmt.channel_mask();
      t.integer[size_t(i)] = fmt.integer_range();
    }
  }
  t.depth = f.depth.image(fmt, w, h) && fmt.is_depth();
  t.stencil = f.stencil.image(fmt, w, h) && fmt.has_stencil();
  return t;
}

bool Context::gpu_image(const Attachment& a, gpu::Attachment& out, int layer) {
  out = {};
  if (a.type == GL_RENDERBUFFER) {
    if (!a.renderbuffer || !a.renderbuffer->image) return false;
    out.texture = a.renderbuffer->image.get();
    return true;
  }
  if (a.type != GL_TEXTURE || !a.texture) return false;
  TextureObject& t = *a.texture;
  if (!update_gpu_texture(*this, t)) return false;
  const int li = a.level - t.gpu_base;
  if (li < 0 || li >= t.gpu_levels) return false;
  const int at = a.layered ? layer : a.layer;
  switch (t.target) {
    case TexTarget::T1D:
    case TexTarget::T2D:
    case TexTarget::Rect:
    case TexTarget::T2DMS:
      if (!t.tex2d) return false;
      out.texture = t.tex2d.get();
      break;
    case TexTarget::Cube:
      if (!t.cube) return false;
      out.texture = &t.cube->face(a.layered ? layer : a.face);
      break;
    case TexTarget::T3D:
      if (!t.tex3d) return false;
      out.texture_3d = t.tex3d.get();
      out.layer = at;
      break;
    case TexTarget::T1DArray:
    case TexTarget::T2DArray:
    case TexTarget::T2DMSArray:
      if (!t.array) return false;
      out.texture_array = t.array.get();
      out.layer = at;
      break;
    default: return false;
  }
  out.level = li;
  if (!out.texture && (at < 0 || at >= out.layers())) return false;
  return true;
}

int Context::draw_layers() {
  if (!draw_fbo) return 0;
  int n = 0;
  bool layered = false;
  auto count = [&](const Attachment& a) {
    if (!a || !a.layered || !a.texture) return;
    TexFormat fmt;
    int w, h;
    if (!a.image(fmt, w, h)) return;
    const TextureObject& t = *a.texture;
    const TextureImage& img = t.image(0, a.level);
    const int layers = t.target == TexTarget::Cube       ? 6
                       : t.target == TexTarget::T1DArray ? img.height
                                                         : img.depth;
    n = layered ? std::min(n, layers) : layers;
    layered = true;
  };
  for (const Attachment& a : draw_fbo->color) count(a);
  count(draw_fbo->depth);
  count(draw_fbo->stencil);
  return layered ? n : 0;
}

GLenum Context::framebuffer_status(FramebufferObject& f) {
  const GLenum st = f.status();
  if (st != GL_FRAMEBUFFER_COMPLETE) return st;
  gpu::Attachment g;
  auto supported = [&](const Attachment& a) {
    if (!a) return true;
    TexFormat fmt;
    int w, h;
    if (!a.image(fmt, w, h)) return false;
    return gpu_image(a, g);
  };
  for (const Attachment& a : f.color)
    if (!supported(a)) return GL_FRAMEBUFFER_UNSUPPORTED;
  if (!supported(f.depth) || !supported(f.stencil)) return GL_FRAMEBUFFER_UNSUPPORTED;
  if (f.depth && f.stencil) {
    // One depth-stencil image serves both, or the pair is not supported (§4.4.4.2 allows it).
    const bool same = f.depth.type == f.stencil.type && f.depth.texture == f.stencil.texture &&
                      f.depth.renderbuffer == f.stencil.renderbuffer && f.depth.level == f.stencil.level &&
                      f.depth.face == f.stencil.face;
    if (!same) return GL_FRAMEBUFFER_UNSUPPORTED;
  }
  return GL_FRAMEBUFFER_COMPLETE;
}

gpu::Attachment Context::read_color() {
  if (!read_fbo) return {color_buffer(s.pixel.read_buffer), 0};
  const FramebufferObject& f = *read_fbo;
  gpu::Attachment g;
  if (f.read_buffer >= GL_COLOR_ATTACHMENT0 && f.read_buffer < GL_COLOR_ATTACHMENT0 + kMaxColorAttachments)
    gpu_image(f.color[f.read_buffer - GL_COLOR_ATTACHMENT0], g);
  return g;
}

gpu::IntegerRange Context::read_color_integer() const {
  if (!read_fbo) return {};
  const FramebufferObject& f = *read_fbo;
  TexFormat fmt;
  int w, h;
  if (f.read_buffer < GL_COLOR_ATTACHMENT0 || f.read_buffer >= GL_COLOR_ATTACHMENT0 + kMaxColorAttachments ||
      !f.color[f.read_buffer - GL_COLOR_ATTACHMENT0].image(fmt, w, h))
    return {};
  return fmt.integer_range();
}

gpu::Attachment Context::read_depth() {
  if (!read_fbo) return {depth_.get(), 0};
  const FramebufferObject& f = *read_fbo;
  gpu::Attachment g;
  gpu_image(f.depth ? f.depth : f.stencil, g);
  return g;
}

bool Context::read_has_stencil() {
  if (!read_fbo) return has_stencil_;
  TexFormat fmt;
  int w, h;
  return read_fbo->stencil.image(fmt, w, h) && fmt.has_stencil();
}

void Context::renderbuffer_deleted(const RenderbufferObject& r) {
  for (FramebufferRef* fb : {&draw_fbo, &read_fbo}) {
    if (!*fb) continue;
    for (Attachment* a : {&(*fb)->depth, &(*fb)->stencil})
      if (a->renderbuffer.get() == &r) *a = Attachment{};
    for (Attachment& a : (*fb)->color)
      if (a.renderbuffer.get() == &r) a = Attachment{};
  }
  if (bound_renderbuffer.get() == &r) bound_renderbuffer = nullptr;
}

const std::vector<const char*>& extensions(const Context&) {
  static const std::vector<const char*> list = {
      "GL_ARB_copy_buffer",
      "GL_ARB_depth_clamp",
      "GL_ARB_draw_elements_base_vertex",
      "GL_ARB_draw_instanced",
      "GL_ARB_explicit_attrib_location",
      "GL_ARB_fragment_shader",
      "GL_ARB_half_float_vertex",
      "GL_ARB_instanced_arrays",
      "GL_ARB_map_buffer_range",
      "GL_ARB_provoking_vertex",
      "GL_ARB_shader_objects",
      "GL_ARB_shading_language_100",
      "GL_ARB_uniform_buffer_object",
      "GL_ARB_vertex_array_bgra",
      "GL_ARB_vertex_array_object",
      "GL_ARB_vertex_buffer_object",
      "GL_ARB_vertex_shader",
      "GL_ARB_vertex_type_2_10_10_10_rev",
      "GL_EXT_bgra",
  };
  return list;
}

void Context::set_version(int major, int minor, bool core) {
  major_version = major;
  minor_version = minor;
  // Only 3.2 and later have profiles; GL 3.1 has no compatibility parts to remove from.
  core_profile = core && (major > 3 || (major == 3 && minor >= 2));
  // A core context has no default vertex array object (GL 3.3 core §2.10): name 0 is no object.
  if (core_profile)
    vertex_arrays.erase(0);
  else if (!vertex_arrays.count(0))
    vertex_arrays[0] = std::make_unique<VertexArrayObject>();
  version_string_ = std::to_string(major) + "." + std::to_string(minor) +
                    (core_profile                              ? " (Core Profile)"
                     : major > 3 || (major == 3 && minor >= 2) ? " (Compatibility Profile)"
                                                               : "") +
                    " Tessel 0.1";
  // GLSL 3.30 is compiled in every context (GL 3.3 §6.1.5 names the newest the context has).
  glsl_version_string_ = major > 3 || (major == 3 && minor >= 3) ? "3.30" : major == 3 ? "1.30" : "1.20";
  extension_string_.clear();
  for (const char* e : extensions(*this)) extension_string_ += std::string(e) + " ";
}

void Context::keep_until_finished(std::unique_ptr<gpu::Buffer> b) {
  transient_bytes_ += b->size();
  transient_buffers_.push_back(std::move(b));
  if (transient_bytes_ > kTransientFlushBytes) {
    gpu_->finish();
    release_transient();
  }
}

void Context::release_transient() {
  transient_buffers_.clear();
  transient_shared_.clear();
  transient_textures_.clear();
  transient_bytes_ = 0;
}

void Context::finish() {
  touch();
  guarded([&] { gpu_->finish(); });
  release_transient();
}

void Context::swap_buffers() {
  finish();
  if (!double_buffer_) return;
  std::swap(color_[0], color_[1]);
  fb_target_ = 0;  // the attachment pointers changed
  gpu_->bind_framebuffer(nullptr);
}

// --- immediate mode ---------------------------------------------------------------------

void Context::vertex(float x, float y, float z, float w) {
  FFVertex v;
  v.pos[0] = x;
  v.pos[1] = y;
  v.pos[2] = z;
  v.pos[3] = w;
  std::memcpy(v.normal, &s.current.normal[0], sizeof v.normal);
  std::memcpy(v.color, &s.current.color[0], sizeof v.color);
  std::memcpy(v.tex, &s.current.tex[0][0], sizeof v.tex);
  v.edge = s.current.edge ? 1.0f : 0.0f;
  if (!extras_touched) return prim.push(v);
  FFExtra e;
  current_extra(s.current, e);
  prim.push(v, e);
}

void current_extra(const CurrentState& cur, FFExtra& e) {
  for (int i = 1; i < kMaxTexCoords; ++i) std::memcpy(e.tex[i - 1], &cur.tex[size_t(i)][0], sizeof e.tex[0]);
  std::memcpy(e.secondary, &cur.secondary[0], sizeof e.secondary);
  e.fog_coord = cur.fog_coord;
  e.pad_[0] = e.pad_[1] = e.pad_[2] = 0.0f;
}

bool Context::extras_live() const {
  const CurrentState& cur = s.current;
  for (int i = 1; i < kMaxTexCoords; ++i)
    if (cur.tex[size_t(i)] != glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) || c.tex[size_t(i)].enabled) return true;
  return cur.secondary != glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) || cur.fog_coord != 0.0f || c.secondary.enabled ||
         c.fog.enabled;
}

void Context::end() {
  in_begin = false;
  FFVertices verts;
  std::swap(verts, prim);
  emit_mode(begin_mode, std::move(verts));
}

// Independent primitives in the order and with the provoking vertex of GL 2.1 §2.6.1 and
// Table 2.9: each triangle lists its provoking vertex last, or first with
// glProvokingVertex(GL_FIRST_VERTEX_CONVENTION) (GL 3.3 Table 2.12; the gpu layer's
// provoking_first takes element 0 of a list's primitive). Quads and quad strips keep their
// last vertex and polygons their first in both conventions, as Mesa does
// (GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION is false). They are cut the way Mesa cuts
// them, so that smooth colours across the inner diagonals agree with it (measured: tests/gl).
void Context::emit_mode(GLenum mode, FFVertices&& v) {
  const uint32_t n = uint32_t(v.size());
  const bool first = s.light.provoking_vertex == GL_FIRST_VERTEX_CONVENTION;
  if (mode != GL_QUADS) close_quad_run();
  std::vector<uint32_t> idx;
  PrimClass cls = PrimClass::Triangles;
  // For polygon-mode lines: the GL edge flag of each edge is kept in the vertex that starts
  // it; edges inside a decomposed quad or polygon are not drawn (GL 2.1 §2.6.2).
  auto tri = [&](uint32_t a, uint32_t b, uint32_t c) {
    idx.push_back(a);
    idx.push_back(b);
    idx.push_back(c);
  };
  switch (mode) {
    case GL_POINTS:
      cls = PrimClass::Points;
      for (uint32_t i = 0; i < n; ++i) idx.push_back(i);
      break;
    case GL_LINES:
      cls = PrimClass::Lines;
      for (uint32_t i = 0; i + 1 < n; i += 2) idx.insert(idx.end(), {i, i + 1});
      for (FFVertex& x : v.v) x.edge = 1.0f;  // each segment restarts the stipple
      break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      cls = PrimClass::Lines;
      for (uint32_t i = 0; i + 1 < n; ++i) idx.insert(idx.end(), {i, i + 1});
      if (mode == GL_LINE_LOOP && n >= 2) idx.insert(idx.end(), {n - 1, 0});
      // For lines the edge flag of a segment's first vertex says whether the line stipple
      // counter restarts there (GL 2.1 §3.4.2: at each glBegin of a strip or loop, and at
      // each segment of GL_LINES): the segments of one strip continue the count.
      for (uint32_t i = 1; i < n; ++i) v[i].edge = 0.0f;
      if (n) v[0].edge = 1.0f;
      break;
    case GL_TRIANGLES:
      for (uint32_t i = 0; i + 2 < n; i += 3) tri(i, i + 1, i + 2);
      break;
    case GL_TRIANGLE_STRIP:
      for (uint32_t i = 0; i + 2 < n; ++i) {
        if (i % 2 == 0)
          tri(i, i + 1, i + 2);
        else if (first)
          tri(i, i + 2, i + 1);  // vertex i provokes: first, the winding kept
        else
          tri(i + 1, i, i + 2);
      }
      break;
    case GL_TRIANGLE_FAN:
      for (uint32_t i = 1; i + 1 < n; ++i) {
        if (first)
          tri(i, i + 1, 0);
        else
          tri(0, i, i + 1);
      }
      break;
    case GL_QUADS:
    case GL_QUAD_STRIP:
    case GL_POLYGON: {
      // Decomposed polygons need their own vertex copies so that each triangle carries the
      // edge flags of its own edges.
      FFVertices out;
      auto put = [&](uint32_t i, bool edge) {
        FFVertex x = v[i];
        x.edge = edge && x.edge != 0.0f ? 1.0f : 0.0f;
        out.push_from(v, i, x);
      };
      if (mode == GL_QUADS) {
        const uint32_t whole = n - n % 4;
        if (list_depth > 0) {
          // Quads replayed from a display list: Mesa's lists always cut along v1-v3.
          close_quad_run();
          split_quads(v, whole, true, out, idx);
        } else {
          // Immediate quads join the run of quads that Mesa would draw together; how the
          // run is cut is known only when it ends (close_quad_run).
          for (uint32_t i = 0; i < whole; ++i) quad_run_clipped_ |= outside_view_volume(v[i]);
          v.v.resize(whole);
          if (v.wide()) v.x.resize(whole);
          quad_run_.append(v);
          return;
        }
      } else if (mode == GL_QUAD_STRIP) {
        // Quad i is v2i, v2i+1, v2i+3, v2i+2 in boundary order; its provoking vertex is v2i+3.
        for (uint32_t i = 0; i + 3 < n; i += 2) {
          const uint32_t base = uint32_t(out.size());
          // (v2, v0, v3) and (v0, v1, v3): v3 last in both. Boundary edges v0-v1, v1-v3,
          // v3-v2, v2-v0.
          put(i + 2, true);   // v2 -> v0
          put(i, false);      // v0 -> v3 inner
          put(i + 3, true);   // v3 -> v2
          put(i, true);       // v0 -> v1
          put(i + 1, true);   // v1 -> v3
          put(i + 3, false);  // v3 -> v0 inner
          tri(base, base + 1, base + 2);
          tri(base + 3, base + 4, base + 5);
        }
      } else if (n >= 3) {
        // (v_i, v_i+1, v0): edge v_i -> v_i+1 is a boundary edge; v_i+1 -> v0 only for the
        // last triangle; v0 -> v_i only for the first.
        for (uint32_t i = 1; i + 1 < n; ++i) {
          const uint32_t base = uint32_t(out.size());
          put(i, true);
          put(i + 1, i + 2 == n);
          put(0, i == 1);
          tri(base, base + 1, base + 2);
        }
      }
      v = std::move(out);
      provoking_vertex_first(idx);
      break;
    }
    default: return;
  }
  if (idx.empty()) return;
  emit(cls, std::move(v), std::move(idx));
}

// Triangles listed with their provoking vertex last, rotated to list it first: (a, b, c)
// becomes (c, a, b), which keeps the winding and each vertex's edge flag on its own edge.
void rotate_provoking_first(std::vector<uint32_t>& triangles) {
  for (size_t i = 0; i + 2 < triangles.size(); i += 3) {
    const uint32_t c = triangles[i + 2];
    triangles[i + 2] = triangles[i + 1];
    triangles[i + 1] = triangles[i];
    triangles[i] = c;
  }
}

void Context::provoking_vertex_first(std::vector<uint32_t>& idx) const {
  if (s.light.provoking_vertex == GL_FIRST_VERTEX_CONVENTION) rotate_provoking_first(idx);
}

// Mesa cuts a quad (v0, v1, v2, v3) in one of two ways, measured on 22.3 (tests/gl): along
// v0-v2, (v0, v1, v2), (v0, v2, v3), when its draw needs no clipping; along v1-v3,
// (v0, v1, v3), (v1, v2, v3), when any vertex of the draw (consecutive glBegin(GL_QUADS)
// without a state change in between) lies outside the view volume, and always for display
// lists. The provoking vertex is v3: with the v0-v2 cut the first triangle lacks it, so
// with flat shading that triangle's last vertex takes v3's colour and normal (its position
// and texture coordinates stay v2's). Edge flags mark the cut as an inner edge.
void Context::split_quads(const FFVertices& v, uint32_t n, bool along_v1v3, FFVertices& out,
                          std::vector<uint32_t>& idx) const {
  const bool flat = s.light.shade_model == GL_FLAT;
  auto put = [&](uint32_t i, const FFVertex& a, bool edge) {
    FFVertex x = a;
    x.edge = edge && a.edge != 0.0f ? 1.0f : 0.0f;
    idx.push_back(uint32_t(out.size()));
    out.push_from(v, i, x);
  };
  for (uint32_t i = 0; i + 3 < n; i += 4) {
    const FFVertex &a = v[i], &b = v[i + 1], &c = v[i + 2], &d = v[i + 3];
    if (along_v1v3) {
      put(i, a, true);       // a -> b
      put(i + 1, b, false);  // b -> d inner
      put(i + 3, d, true);   // d -> a
      put(i + 1, b, true);   // b -> c
      put(i + 2, c, true);   // c -> d
      put(i + 3, d, false);  // d -> b inner
    } else {
      FFVertex c_first = c;
      if (flat) {
        std::memcpy(c_first.normal, d.normal, sizeof c_first.normal);
        std::memcpy(c_first.color, d.color, sizeof c_first.color);
      }
      put(i, a, true);             // a -> b
      put(i + 1, b, true);         // b -> c
      put(i + 2, c_first, false);  // c -> a inner
      if (flat && v.wide())        // the secondary colour is flat shaded too
        std::memcpy(out.x.back().secondary, v.x[i + 3].secondary, sizeof out.x.back().secondary);
      put(i, a, false);     // a -> c inner
      put(i + 2, c, true);  // c -> d
      put(i + 3, d, true);  // d -> a
    }
  }
}

bool Context::outside_view_volume(const FFVertex& v) const {
  const glm::vec4 p(v.pos[0], v.pos[1], v.pos[2], v.pos[3]);
  const glm::vec4 eye = modelview() * p;
  const glm::vec4 c = projection() * eye;
  if (c.x < -c.w || c.x > c.w || c.y < -c.w || c.y > c.w || c.z < -c.w || c.z > c.w) return true;
  for (int i = 0; i < kMaxClipPlanes; ++i)
    if (s.transform.clip_enabled[size_t(i)] &&
        glm::dot(glm::dvec4(eye), s.transform.clip_plane[size_t(i)]) < 0.0)
      return true;
  return false;
}

void Context::close_quad_run() {
  if (quad_run_.empty()) return;
  FFVertices run;
  std::swap(run, quad_run_);
  const bool clipped = quad_run_clipped_;
  quad_run_clipped_ = false;
  FFVertices out;
  std::vector<uint32_t> idx;
  split_quads(run, uint32_t(run.size()), clipped, out, idx);
  provoking_vertex_first(idx);
  emit(PrimClass::Triangles, std::move(out), std::move(idx));
}

void Context::emit(PrimClass cls, FFVertices&& verts, std::vector<uint32_t>&& indices) {
  if (indices.empty() || compiling_only()) return;
  close_quad_run();  // earlier quads go first
  if (render_mode_ != GL_RENDER) {
    // Selection and feedback modes report primitives instead of drawing them.
    if (render_mode_ == GL_SELECT)
      select_primitives(cls, verts, indices);
    else
      feedback_primitives(cls, verts, indices);
    return;
  }
  if (!batch_.indices.empty() && batch_.cls != cls) send_batch();
  if (batch_.indices.empty()) {
    batch_.cls = cls;
    batch_.verts = std::move(verts);
    batch_.indices = std::move(indices);
  } else {
    const uint32_t base = uint32_t(batch_.verts.size());
    batch_.verts.append(verts);
    for (uint32_t i : indices) batch_.indices.push_back(base + i);
  }
  if (batch_.verts.size() > (1u << 20)) send_batch();
}

void Context::emit_shared(std::shared_ptr<const gpu::Buffer> vertices, std::vector<uint32_t>&& indices) {
  if (indices.empty() || compiling_only()) return;
  close_quad_run();
  if (!batch_.indices.empty()) send_batch();
  batch_.cls = PrimClass::Triangles;
  batch_.shared = std::move(vertices);
  batch_.indices = std::move(indices);
  send_batch();
}

void Context::texture_deleted(const TextureObject& t) {
  for (TextureUnitState& u : s.units)
    for (TextureRef& r : u.bound)
      if (r.get() == &t) r = nullptr;
  // §4.4.2.3: detached from the bound framebuffers (others keep it until they are changed).
  for (FramebufferRef* fb : {&draw_fbo, &read_fbo}) {
    if (!*fb) continue;
    for (Attachment* a : {&(*fb)->depth, &(*fb)->stencil})
      if (a->texture.get() == &t) *a = Attachment{};
    for (Attachment& a : (*fb)->color)
      if (a.texture.get() == &t) a = Attachment{};
  }
}

TextureObject* Context::texture_for_draw() {
  TexTarget target = TexTarget::T2D;
  TextureObject* t = ff_texture(0, target);
  return t && target == TexTarget::T2D ? t : nullptr;
}

const SamplerParams& Context::sampler_params(int unit, const TextureObject& t) const {
  const SamplerRef& so = s.units[size_t(unit)].sampler;
  return so ? so->p : t.sampler;
}

void Context::build_uniforms(FFUniforms& u, TextureObject* tex) const {
  const glm::mat4& mv = modelview();
  u.modelview = mv;
  u.mvp = projection() * mv;
  const glm::mat3 inv = glm::inverse(glm::mat3(mv));
  u.normal_matrix = glm::transpose(inv);
  u.normalize = s.transform.normalize;
  u.rescale = s.transform.rescale_normal && !s.transform.normalize ? rescale_factor(mv) : 1.0f;
  const LightState& L = s.light;
  u.lighting = L.lighting;
  if (u.lighting) {
    u.two_side = L.two_side;
    u.local_viewer = L.local_viewer;
    u.model_ambient = L.model_ambient;
    u.material = L.material;
    u.light_count = 0;
    for (int i = 0; i < kMaxLights; ++i)
      if (L.enabled[size_t(i)]) u.lights[size_t(u.light_count++)] = L.light[size_t(i)];
    u.track = color_material_track(L);
  }
  if (tex) {
    u.sampler.texture = tex->tex2d.get();
    u.sampler.state = sampler_state_of(sampler_params(0, *tex), *tex);
    u.base_format = ff_base_format(*tex);
    switch (s.units[0].env_mode) {
      case GL_REPLACE: u.env = TexEnv::Replace; break;
      case GL_DECAL: u.env = TexEnv::Decal; break;
      case GL_BLEND: u.env = TexEnv::Blend; break;
      case GL_ADD: u.env = TexEnv::Add; break;
      default: u.env = TexEnv::Modulate; break;
    }
    u.env_color = s.units[0].env_color;
    const glm::mat4& tm = texture_matrix(0);
    u.texture_matrix = tm;
    u.identity_texture_matrix = tm == glm::mat4(1.0f);
    for (int i = 0; i < 4; ++i) {
      u.texgen[size_t(i)] = s.units[0].gen_enabled[size_t(i)];
      const GLenum m = s.units[0].gen_mode[size_t(i)];
      u.texgen_mode[size_t(i)] = m == GL_OBJECT_LINEAR ? TexGenMode::ObjectLinear
                                 : m == GL_SPHERE_MAP  ? TexGenMode::SphereMap
                                                       : TexGenMode::EyeLinear;
      u.object_plane[size_t(i)] = s.units[0].object_plane[size_t(i)];
      u.eye_plane[size_t(i)] = s.units[0].eye_plane[size_t(i)];
    }
  }
  u.fog = s.fog.enabled;
  if (u.fog) {
    u.fog_mode = s.fog.mode == GL_LINEAR ? FogMode::Linear
                 : s.fog.mode == GL_EXP2 ? FogMode::Exp2
                                         : FogMode::Exp;
    u.fog_start = s.fog.start;
    u.fog_end = s.fog.end;
    u.fog_density = s.fog.density;
    u.fog_color = s.fog.color;
  }
  u.alpha_test = s.color.alpha_test && s.color.alpha_func != GL_ALWAYS;
  u.alpha_func = compare_of(s.color.alpha_func);
  u.alpha_ref = std::clamp(s.color.alpha_ref, 0.0f, 1.0f);
  u.stipple = s.polygon.stipple;
  u.stipple_rows = s.polygon_stipple;
}

gpu::RenderState Context::render_state(bool for_clear) const {
  gpu::RenderState r;
  r.rasterizer_discard = rasterizer_discard;
  const TargetInfo target = target_info();
  r.viewport = {s.viewport.x, s.viewport.y, s.viewport.width, s.viewport.height};
  r.depth_near = float(s.viewport.near_);
  r.depth_far = float(s.viewport.far_);
  r.scissor_test = s.scissor.test;
  r.scissor = {s.scissor.x, s.scissor.y, s.scissor.width, s.scissor.height};
  if (!for_clear) {
    const PolygonState& p = s.polygon;
    if (p.cull)
      r.cull = p.cull_face == GL_FRONT  ? gpu::CullMode::Front
               : p.cull_face == GL_BACK ? gpu::CullMode::Back
                                        : gpu::CullMode::FrontAndBack;
    r.front_face = p.front_face == GL_CW ? gpu::FrontFace::CW : gpu::FrontFace::CCW;
    r.polygon_mode = polygon_mode_of(p.mode_front);
    r.polygon_mode_per_face = p.mode_back != p.mode_front;
    r.polygon_mode_back = polygon_mode_of(p.mode_back);
    r.offset_fill = p.offset_fill;
    r.offset_line = p.offset_line;
    r.offset_point = p.offset_point;
    r.offset_factor = p.offset_factor;
    r.offset_units = p.offset_units;
    // Any positive width or size is accepted and used clamped to the supported range
    // (GL 2.1 §3.3, §3.4: ALIASED_POINT_SIZE_RANGE and ALIASED_LINE_WIDTH_RANGE are 1..255).
    r.line_width = std::clamp(s.line.width, 1.0f, 255.0f);
    r.point_size = std::clamp(s.point.size, 1.0f, 255.0f);
    r.point_sprite_lower_left = s.point.sprite_lower_left;
    const glm::mat4 inv_p = glm::inverse(projection());
    for (int i = 0; i < kMaxClipPlanes; ++i) {
      if (!s.transform.clip_enabled[size_t(i)]) continue;
      r.clip_plane_enable |= uint8_t(1u << i);
      // The gpu layer tests planes in clip space: p_clip = p_eye * P^-1 (as a row vector).
      const glm::vec4 pe(s.transform.clip_plane[size_t(i)]);
      r.clip_planes[size_t(i)] = pe * inv_p;
    }
    r.depth_test = s.depth.test && target.depth;
    r.depth_func = compare_of(s.depth.func);
  }
  r.depth_write = s.depth.mask && target.depth && (for_clear || s.depth.test);
  r.stencil_test = s.stencil.test && target.stencil;
  const StencilState& st = s.stencil;
  auto face = [](GLenum func, GLint ref, GLuint value_mask, GLuint write_mask, GLenum fail, GLenum zfail,
                 GLenum zpass) {
    gpu::StencilFace f;
    f.func = compare_of(func);
    f.ref = uint8_t(std::clamp(ref, 0, 255));
    f.read_mask = uint8_t(value_mask & 0xFF);
    f.write_mask = uint8_t(write_mask & 0xFF);
    f.fail = stencil_op_of(fail);
    f.depth_fail = stencil_op_of(zfail);
    f.pass = stencil_op_of(zpass);
    return f;
  };
  r.stencil_front = face(st.func, st.ref, st.value_mask, st.write_mask, st.fail, st.zfail, st.zpass);
  r.stencil_back = face(st.back_func, st.back_ref, st.back_value_mask, st.back_write_mask, st.back_fail,
                        st.back_zfail, st.back_zpass);
  auto equation = [](GLenum e) {
    switch (e) {
      case GL_FUNC_SUBTRACT: return gpu::BlendEquation::Subtract;
      case GL_FUNC_REVERSE_SUBTRACT: return gpu::BlendEquation::ReverseSubtract;
      case GL_MIN: return gpu::BlendEquation::Min;
      case GL_MAX: return gpu::BlendEquation::Max;
      default: return gpu::BlendEquation::Add;
    }
  };
  for (int i = 0; i < kMaxDrawBuffers; ++i) {
    gpu::BlendTarget& b = r.blend[size_t(i)];
    const std::array<bool, 4>& m = s.color.color_mask[size_t(i)];
    b.integer = target.integer[size_t(i)];
    b.enabled = !for_clear && s.color.blend[size_t(i)] && !b.integer.integer();
    b.eq_rgb = equation(s.color.blend_eq);
    b.eq_alpha = equation(s.color.blend_eq_alpha);
    b.src_rgb = blend_of(s.color.blend_src);
    b.dst_rgb = blend_of(s.color.blend_dst);
    b.src_alpha = blend_of(s.color.blend_src_alpha);
    b.dst_alpha = blend_of(s.color.blend_dst_alpha);
    // The channels the attachment's format stores (RGB keeps alpha 1, RED only red, ...).
    b.write_mask = uint8_t(((m[0] ? 1 : 0) | (m[1] ? 2 : 0) | (m[2] ? 4 : 0) | (m[3] ? 8 : 0)) &
                           target.channels[size_t(i)]);
  }
  r.blend_color = s.color.blend_color;
  r.logic_op_enabled = !for_clear && s.color.logic_op;
  r.logic_op = gpu::LogicOp(s.color.logic_op_mode - GL_CLEAR);
  r.provoking_first = s.light.provoking_vertex == GL_FIRST_VERTEX_CONVENTION;
  return r;
}

namespace {
template <bool Flat, bool Textured, bool Discards>
void draw_ff(gpu::Context& g, const FFUniforms& u, const gpu::VertexLayout& layout,
             const gpu::RenderState& rs, const gpu::DrawCall& call) {
  g.draw(FixedFunction<Flat, Textured, Discards>{}, u, layout, rs, call);
}
template <bool Flat, bool Discards>
void draw_lean(gpu::Context& g, const FFUniforms& u, const gpu::VertexLayout& layout,
               const gpu::RenderState& rs, const gpu::DrawCall& call) {
  g.draw(FixedFunction<Flat, false, Discards, true>{}, u, layout, rs, call);
}
using DrawFn = void (*)(gpu::Context&, const FFUniforms&, const gpu::VertexLayout&, const gpu::RenderState&,
                        const gpu::DrawCall&);
constexpr DrawFn kDraw[8] = {
    draw_ff<false, false, false>, draw_ff<false, false, true>, draw_ff<false, true, false>,
    draw_ff<false, true, true>,   draw_ff<true, false, false>, draw_ff<true, false, true>,
    draw_ff<true, true, false>,   draw_ff<true, true, true>,
};
// Draws that need only the front colour (no texture, fog, two-sided lighting or edges).
constexpr DrawFn kDrawLean[4] = {draw_lean<false, false>, draw_lean<false, true>, draw_lean<true, false>,
                                 draw_lean<true, true>};
}  // namespace

void Context::send_batch() {
  guarded([&] { send_batch_unchecked(); });
}

void Context::send_batch_unchecked() {
  Batch b;
  std::swap(b, batch_);
  if (b.indices.empty()) return;
  if (!bind_draw_target()) return;
  if (b.cls == PrimClass::Lines && s.line.stipple) return send_stippled_lines(b.verts, b.indices);
  std::unique_ptr<gpu::Buffer> own;
  if (!b.shared) own = std::make_unique<gpu::Buffer>(b.verts.v.data(), b.verts.size() * sizeof(FFVertex));
  const gpu::Buffer& vbuf = b.shared ? *b.shared : *own;
  auto ib = std::make_unique<gpu::Buffer>(b.indices.data(), b.indices.size() * sizeof(uint32_t));
  if (executable) {
    // A GLSL program reads the batch's vertices as the compatibility attributes.
    gpu::DrawCall call;
    call.topology = b.cls == PrimClass::Points  ? gpu::Topology::Points
                    : b.cls == PrimClass::Lines ? gpu::Topology::Lines
                                                : gpu::Topology::Triangles;
    call.count = uint32_t(b.indices.size());
    call.index_buffer = ib.get();
    call.index_type = gpu::IndexType::U32;
    gpu::RenderState rs = render_state(false);
    rs.edge_flag_varying = -1;
    draw_program_batch(executable_run(), vbuf, b.verts.x, call, rs);
  } else {
    draw_fixed_function(b, vbuf, *ib);
  }
  transient_bytes_ += vbuf.size() + ib->size();
  if (own)
    transient_buffers_.push_back(std::move(own));
  else
    transient_shared_.push_back(b.shared);
  transient_buffers_.push_back(std::move(ib));
  if (transient_bytes_ > kTransientFlushBytes) {
    gpu_->finish();
    release_transient();
  }
}

void Context::draw_fixed_function(const Batch& b, const gpu::Buffer& vbuf, const gpu::Buffer& ib) {
  FFProgramKey key;
  TextureObject* tex = nullptr;  // the key's look at unit 0 is the C++ shader's texture
  if (ff_program_key(b.cls, key, tex)) return draw_ff_program(key, b, vbuf, ib);
  gpu::VertexLayout layout;
  constexpr uint32_t stride = sizeof(FFVertex);
  layout.attrib(0, vbuf, 4, gpu::AttribType::F32, stride, offsetof(FFVertex, pos));
  layout.attrib(1, vbuf, 3, gpu::AttribType::F32, stride, offsetof(FFVertex, normal));
  layout.attrib(2, vbuf, 4, gpu::AttribType::F32, stride, offsetof(FFVertex, color));
  layout.attrib(3, vbuf, 4, gpu::AttribType::F32, stride, offsetof(FFVertex, tex));
  layout.attrib(4, vbuf, 1, gpu::AttribType::F32, stride, offsetof(FFVertex, edge));
  auto u = std::make_unique<FFUniforms>();
  build_uniforms(*u, tex);
  gpu::RenderState rs = render_state(false);
  rs.edge_flag_varying = kEdgeFlagVarying;
  gpu::DrawCall call;
  call.topology = b.cls == PrimClass::Points  ? gpu::Topology::Points
                  : b.cls == PrimClass::Lines ? gpu::Topology::Lines
                                              : gpu::Topology::Triangles;
  call.count = uint32_t(b.indices.size());
  call.index_buffer = &ib;
  call.index_type = gpu::IndexType::U32;
  const bool flat = s.light.shade_model == GL_FLAT;
  const bool discards = u->alpha_test || (u->stipple && b.cls == PrimClass::Triangles);
  if (b.cls != PrimClass::Triangles) u->stipple = false;
  const bool lean =
      !tex && !u->fog && !(u->lighting && u->two_side) &&
      (b.cls != PrimClass::Triangles || (s.polygon.mode_front == GL_FILL && s.polygon.mode_back == GL_FILL));
  if (lean) rs.edge_flag_varying = -1;
  const DrawFn draw = lean ? kDrawLean[(flat ? 2 : 0) + (discards ? 1 : 0)]
                           : kDraw[(flat ? 4 : 0) + (tex ? 2 : 0) + (discards ? 1 : 0)];
  draw(*gpu_, *u, layout, rs, call);
}

// The fixed-function vertex stage on one lane (the same shader the draws use).
FFPostVertex Context::post_vertex(const FFVertex& v, const FFUniforms& u, bool textured) const {
  gpu::VertexIn<float> in{};
  in.attr[0] = gpu::Vec4<float>(v.pos[0], v.pos[1], v.pos[2], v.pos[3]);
  in.attr[1] = gpu::Vec4<float>(v.normal[0], v.normal[1], v.normal[2], 0.0f);
  in.attr[2] = gpu::Vec4<float>(v.color[0], v.color[1], v.color[2], v.color[3]);
  in.attr[3] = gpu::Vec4<float>(v.tex[0], v.tex[1], v.tex[2], v.tex[3]);
  in.attr[4] = gpu::Vec4<float>(v.edge, 0.0f, 0.0f, 1.0f);
  FFVaryings<float> out;
  const gpu::Vec4<float> p = textured ? FixedFunction<false, true, false>{}.vertex(u, in, out)
                                      : FixedFunction<false, false, false>{}.vertex(u, in, out);
  FFPostVertex o;
  const float pv[4] = {p.x, p.y, p.z, p.w};
  const float fv[4] = {out.front.x, out.front.y, out.front.z, out.front.w};
  const float bv[4] = {out.back.x, out.back.y, out.back.z, out.back.w};
  const float tv[4] = {out.tex.x, out.tex.y, out.tex.z, out.tex.w};
  std::memcpy(o.pos, pv, sizeof pv);
  std::memcpy(o.front, fv, sizeof fv);
  std::memcpy(o.back, bv, sizeof bv);
  std::memcpy(o.tex, tv, sizeof tv);
  o.edge = v.edge;
  o.fog = out.fog;
  return o;
}

// Stippled lines (GL 2.1 §3.4.2) are cut into their drawn pieces on the CPU, as Mesa's draw
// module does: each vertex goes through the fixed-function vertex stage (the same shader on
// one lane), each segment is clipped to the view volume and taken to window coordinates,
// and the pieces where the pattern is on are drawn as pre-transformed lines. The counter
// steps once per pixel along the major axis and carries over between the segments of a
// strip; the pieces' ends are interpolated linearly in window space.
void Context::send_stippled_lines(const FFVertices& verts, const std::vector<uint32_t>& indices) {
  TextureObject* tex = texture_for_draw();
  FFUniforms u;
  build_uniforms(u, tex);
  u.stipple = false;
  // The vertex stage on one lane for every vertex the lines use.
  std::vector<FFPostVertex> post(verts.size());
  std::vector<bool> done(verts.size(), false);
  auto process = [&](uint32_t i) -> const FFPostVertex& {
    if (!done[i]) {
      post[i] = post_vertex(verts[i], u, tex != nullptr);
      done[i] = true;
    }
    return post[i];
  };
  const auto lerp = lerp_post;

  const ViewportState& vp = s.viewport;
  const float fw = float(fb_.width()), fh = float(fb_.height());
  // Window coordinates of a clip-space vertex, and back to the full-framebuffer clip space
  // the pieces are drawn in (viewport = framebuffer, depth range [0, 1], w = 1).
  auto to_window = [&](const FFPostVertex& c) {
    const float iw = 1.0f / c.pos[3];
    return glm::vec3(float(vp.x) + (c.pos[0] * iw + 1.0f) * 0.5f * float(vp.width),
                     float(vp.y) + (c.pos[1] * iw + 1.0f) * 0.5f * float(vp.height),
                     float(vp.near_ + (vp.far_ - vp.near_) * (double(c.pos[2] * iw) + 1.0) * 0.5));
  };
  const bool flat = s.light.shade_model == GL_FLAT;
  const glm::mat4& mv = modelview();
  std::vector<FFPostVertex> out;
  float counter = 0.0f;  // pixels along the major axis so far; whole pixels select the bit
  const int factor = std::max(1, s.line.stipple_factor);
  const unsigned pattern = s.line.stipple_pattern;
  for (size_t k = 0; k + 1 < indices.size(); k += 2) {
    const FFVertex& src0 = verts[indices[k]];
    FFPostVertex a = process(indices[k]), b = process(indices[k + 1]);
    if (src0.edge != 0.0f) counter = 0.0f;
    if (flat) {
      std::memcpy(a.front, b.front, sizeof a.front);
      std::memcpy(a.back, b.back, sizeof a.back);
    }
    // Clip against the view volume and the user planes (parametric, GL 2.1 §2.12).
    float t0 = 0.0f, t1 = 1.0f;
    bool visible = true;
    auto clip = [&](float da, float db) {
      if (da < 0.0f && db < 0.0f) return false;
      if (da < 0.0f)
        t0 = std::max(t0, da / (da - db));
      else if (db < 0.0f)
        t1 = std::min(t1, da / (da - db));
      return t0 <= t1;
    };
    for (int p = 0; p < 6 && visible; ++p) {
      const int axis = p / 2;
      const float sign = (p % 2) ? -1.0f : 1.0f;
      visible = clip(a.pos[3] + sign * a.pos[axis], b.pos[3] + sign * b.pos[axis]);
    }
    if (visible) {
      const glm::vec4 ea = mv * glm::vec4(src0.pos[0], src0.pos[1], src0.pos[2], src0.pos[3]);
      const FFVertex& src1 = verts[indices[k + 1]];
      const glm::vec4 eb = mv * glm::vec4(src1.pos[0], src1.pos[1], src1.pos[2], src1.pos[3]);
      for (int p = 0; p < kMaxClipPlanes && visible; ++p)
        if (s.transform.clip_enabled[size_t(p)])
          visible = clip(float(glm::dot(glm::dvec4(ea), s.transform.clip_plane[size_t(p)])),
                         float(glm::dot(glm::dvec4(eb), s.transform.clip_plane[size_t(p)])));
    }
    if (!visible) continue;
    const FFPostVertex ca = lerp(a, b, t0), cb = lerp(a, b, t1);
    const glm::vec3 wa = to_window(ca), wb = to_window(cb);
    // In window space from here on: the pieces interpolate linearly between the ends.
    FFPostVertex sa = ca, sb = cb;
    const float ws[2][3] = {{wa.x, wa.y, wa.z}, {wb.x, wb.y, wb.z}};
    FFPostVertex* e[2] = {&sa, &sb};
    for (int j = 0; j < 2; ++j) {
      e[j]->pos[0] = ws[j][0] * 2.0f / fw - 1.0f;
      e[j]->pos[1] = ws[j][1] * 2.0f / fh - 1.0f;
      e[j]->pos[2] = ws[j][2] * 2.0f - 1.0f;
      e[j]->pos[3] = 1.0f;
    }
    const float length = std::max(std::fabs(wb.x - wa.x), std::fabs(wb.y - wa.y));
    bool on = false;
    float start = 0.0f;
    auto piece = [&](float p0, float p1) {
      out.push_back(lerp(sa, sb, p0 / length));
      out.push_back(lerp(sa, sb, p1 / length));
    };
    for (int i = 0; float(i) < length; ++i) {
      const unsigned bit = unsigned((int(counter) + i) / factor) & 15u;
      const bool result = (pattern >> bit) & 1u;
      if (result != on) {
        if (on) {
          if (start != float(i)) piece(start, float(i));
        } else {
          start = float(i);
        }
        on = result;
      }
    }
    if (on && start < length) piece(start, length);
    counter += length;
  }
  if (out.empty()) return;
  auto vb = std::make_unique<gpu::Buffer>(out.data(), out.size() * sizeof(FFPostVertex));
  gpu::VertexLayout layout;
  constexpr uint32_t stride = sizeof(FFPostVertex);
  layout.attrib(0, *vb, 4, gpu::AttribType::F32, stride, offsetof(FFPostVertex, pos));
  layout.attrib(1, *vb, 4, gpu::AttribType::F32, stride, offsetof(FFPostVertex, back));
  layout.attrib(2, *vb, 4, gpu::AttribType::F32, stride, offsetof(FFPostVertex, front));
  layout.attrib(3, *vb, 4, gpu::AttribType::F32, stride, offsetof(FFPostVertex, tex));
  layout.attrib(4, *vb, 2, gpu::AttribType::F32, stride, offsetof(FFPostVertex, edge));
  u.pretransformed = true;
  gpu::RenderState rs = render_state(false);
  rs.viewport = {0, 0, fb_.width(), fb_.height()};
  rs.depth_near = 0.0f;
  rs.depth_far = 1.0f;
  rs.clip_plane_enable = 0;
  gpu::DrawCall call;
  call.topology = gpu::Topology::Lines;
  call.count = uint32_t(out.size());
  const bool discards = u.alpha_test;
  kDraw[(flat ? 4 : 0) + (tex ? 2 : 0) + (discards ? 1 : 0)](*gpu_, u, layout, rs, call);
  transient_bytes_ += vb->size();
  transient_buffers_.push_back(std::move(vb));
}

glm::vec4 Context::clear_color_for(const TargetInfo& target, int i, glm::vec4 color) const {
  const gpu::Attachment& t = fb_.color[size_t(i)];
  // Unsigned normalized buffers take the colour clamped to [0, 1], float ones as it is.
  if (!t) return color;
  if (gpu::is_unorm8_format(t.format())) return glm::clamp(color, 0.0f, 1.0f);
  // Integer buffers take the value's bits clamped to their range: glClear's float colour as
  // llvmpipe takes it (GL leaves it undefined), glClearBuffer{i,ui}v's integers as given.
  return clamp_integer_texel(target.integer[size_t(i)], color);
}

void Context::clear(GLbitfield mask) {
  if (rasterizer_discard) return;  // GL 3.3 §3.1: Clear is ignored too
  touch();
  for_each_clear_layer([&](int layer) { clear_layer(mask, layer); });
}

void Context::clear_layer(GLbitfield mask, int layer) {
  if (!bind_draw_target(layer)) return;
  const TargetInfo target = target_info();
  gpu::ClearValues cv;
  cv.clear_color = (mask & GL_COLOR_BUFFER_BIT) != 0;
  cv.color = s.color.clear_color;
  cv.clear_depth = target.depth && (mask & GL_DEPTH_BUFFER_BIT) != 0;
  cv.depth = float(std::clamp(s.depth.clear, 0.0, 1.0));
  cv.clear_stencil = target.stencil && (mask & GL_STENCIL_BUFFER_BIT) != 0;
  cv.stencil = uint8_t(s.stencil.clear & 0xFF);
  gpu::RenderState rs = render_state(true);
  rs.depth_write = s.depth.mask;
  bool any_color = false;
  for (int i = 0; i < kMaxDrawBuffers; ++i) {
    if (!fb_.color[size_t(i)]) continue;
    any_color = true;
    cv.attachment_colors[size_t(i)] = clear_color_for(target, i, cv.color);
  }
  cv.per_attachment = true;
  if (!any_color) cv.clear_color = false;
  if (!cv.clear_color && !cv.clear_depth && !cv.clear_stencil) return;
  guarded([&] { gpu_->clear(cv, rs); });
}

}  // namespace tessel::gl
