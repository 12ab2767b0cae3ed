// Where draws and clears go: the gpu framebuffer built from the draw buffers (the window's
// buffers or a framebuffer object's attachments, a layer of them for layered rendering),
// framebuffer completeness, the read buffers, and glClear.
#include "context.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace tessel::gl {

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
    // GL_FRONT_AND_BACK: the front buffer and the back one (render_state broadcasts output 0).
    if (target == GL_FRONT_AND_BACK && double_buffer_) fb_.color[1].texture = color_[1].get();
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
    t.channels[0] = has_alpha_ ? 0xF : 0x7;  // a window without alpha keeps its alpha at 1
    if (s.color.draw_buffer == GL_FRONT_AND_BACK && double_buffer_) t.channels[1] = t.channels[0];
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
