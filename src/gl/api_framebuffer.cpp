// Framebuffer and renderbuffer objects (GL 3.3 compatibility §4.4), the draw and read buffers
// of framebuffer objects (§4.2.1, §4.3.3), glClearBuffer* (§4.2.3), glBlitFramebuffer
// (§4.3.2), and the indexed colour masks and blend enables (§4.1.8, §4.2.2).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <bit>
#include <cmath>

#include "api.hpp"

namespace tessel::gl {

namespace {

// The framebuffer bindings a target names (GL_FRAMEBUFFER: both); false: GL_INVALID_ENUM.
bool fbo_targets(GLenum target, bool& draw, bool& read) {
  draw = target == GL_FRAMEBUFFER || target == GL_DRAW_FRAMEBUFFER;
  read = target == GL_FRAMEBUFFER || target == GL_READ_FRAMEBUFFER;
  return draw || read;
}

// The framebuffer object an attachment call changes (null: error raised).
FramebufferObject* target_fbo(Context& c, GLenum target) {
  bool draw, read;
  if (!fbo_targets(target, draw, read)) {
    c.error(GL_INVALID_ENUM);
    return nullptr;
  }
  FramebufferRef& r = draw ? c.draw_fbo : c.read_fbo;
  if (!r) c.error(GL_INVALID_OPERATION);  // the default framebuffer has no attachment points
  return r.get();
}

// The attachment points a call names: one, or depth and stencil for DEPTH_STENCIL_ATTACHMENT.
bool attachment_points(FramebufferObject& f, GLenum attachment, Attachment*& a, Attachment*& b) {
  b = nullptr;
  if (attachment == GL_DEPTH_STENCIL_ATTACHMENT) {
    a = &f.depth;
    b = &f.stencil;
    return true;
  }
  a = f.point(attachment);
  return a != nullptr;
}

// The error of an attachment point that is not one: COLOR_ATTACHMENTm past the last is
// GL_INVALID_OPERATION (GL 4.6 §9.2.7, as Mesa answers), anything else GL_INVALID_ENUM.
GLenum attachment_error(GLenum attachment) {
  return attachment >= GL_COLOR_ATTACHMENT0 && attachment < GL_COLOR_ATTACHMENT0 + 16 ? GL_INVALID_OPERATION
                                                                                      : GL_INVALID_ENUM;
}

// glClearBuffer* on an incomplete framebuffer: GL_INVALID_FRAMEBUFFER_OPERATION, reported
// before the arguments are looked at, as by Mesa.
bool incomplete_for_clear(Context& c) {
  if (c.in_begin || c.draw_framebuffer_complete()) return false;
  c.error(GL_INVALID_FRAMEBUFFER_OPERATION);
  return true;
}

void changed(Context& c) { c.touch(); }

void attach_texture(Context& c, GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                    GLint level, GLint layer, int dims) {
  GL_OUTSIDE_BEGIN();
  FramebufferObject* f = target_fbo(c, target);
  if (!f) return;
  Attachment *a, *b;
  if (!attachment_points(*f, attachment, a, b)) return c.error(attachment_error(attachment));
  Attachment n;
  if (texture != 0) {
    auto it = c.textures.find(texture);
    // Not a texture object: glFramebufferTexture names it GL_INVALID_VALUE (GL 3.3 §4.4.2), the
    // target-specific calls GL_INVALID_OPERATION.
    if (it == c.textures.end() || !it->second)
      return c.error(dims == 0 ? GL_INVALID_VALUE : GL_INVALID_OPERATION);
    const TextureRef& t = it->second;
    n.type = GL_TEXTURE;
    n.texture = t;
    n.level = level;
    n.layer = layer;
    // The texture target the call names must be the texture's (§4.4.2.4).
    switch (dims) {
      case 1:
        if (textarget != GL_TEXTURE_1D || t->target != TexTarget::T1D) return c.error(GL_INVALID_OPERATION);
        break;
      case 2:
        if (textarget == GL_TEXTURE_2D || textarget == GL_TEXTURE_RECTANGLE ||
            textarget == GL_TEXTURE_2D_MULTISAMPLE) {
          const TexTarget want = textarget == GL_TEXTURE_2D          ? TexTarget::T2D
                                 : textarget == GL_TEXTURE_RECTANGLE ? TexTarget::Rect
                                                                     : TexTarget::T2DMS;
          if (t->target != want) return c.error(GL_INVALID_OPERATION);
        } else if (textarget >= GL_TEXTURE_CUBE_MAP_POSITIVE_X &&
                   textarget <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z) {
          if (t->target != TexTarget::Cube) return c.error(GL_INVALID_OPERATION);
          n.face = int(textarget - GL_TEXTURE_CUBE_MAP_POSITIVE_X);
        } else {
          return c.error(GL_INVALID_ENUM);
        }
        break;
      case 3:
        if (textarget != GL_TEXTURE_3D || t->target != TexTarget::T3D) return c.error(GL_INVALID_OPERATION);
        if (layer < 0 || layer >= kMax3DTextureSize) return c.error(GL_INVALID_VALUE);
        break;
      case 4:  // glFramebufferTextureLayer
        if (t->target != TexTarget::T3D && t->target != TexTarget::T1DArray &&
            t->target != TexTarget::T2DArray && t->target != TexTarget::T2DMSArray)
          return c.error(GL_INVALID_OPERATION);
        // §4.4.2: the layer below MAX_3D_TEXTURE_SIZE or MAX_ARRAY_TEXTURE_LAYERS.
        if (layer < 0 || layer >= (t->target == TexTarget::T3D ? kMax3DTextureSize : kMaxArrayTextureLayers))
          return c.error(GL_INVALID_VALUE);
        break;
      case 0:  // glFramebufferTexture: layered for 3D, array and cube textures
        if (t->target == TexTarget::Buffer) return c.error(GL_INVALID_OPERATION);
        n.layered = t->target == TexTarget::T3D || t->target == TexTarget::T1DArray ||
                    t->target == TexTarget::T2DArray || t->target == TexTarget::Cube ||
                    t->target == TexTarget::T2DMSArray;
        break;
      default: break;
    }
    if ((t->target == TexTarget::Rect || is_multisample(t->target)) && level != 0)
      return c.error(GL_INVALID_VALUE);
    int max_level = 0;
    while (((t->target == TexTarget::T3D ? kMax3DTextureSize : kMaxTextureSize) >> max_level) > 1)
      ++max_level;
    if (level < 0 || level > max_level) return c.error(GL_INVALID_VALUE);
  }
  changed(c);
  *a = n;
  if (b) *b = n;
}

void attach_renderbuffer(Context& c, GLenum target, GLenum attachment, GLenum rbtarget, GLuint rb) {
  GL_OUTSIDE_BEGIN();
  FramebufferObject* f = target_fbo(c, target);
  if (!f) return;
  Attachment *a, *b;
  if (!attachment_points(*f, attachment, a, b)) return c.error(attachment_error(attachment));
  if (rbtarget != GL_RENDERBUFFER) return c.error(GL_INVALID_ENUM);
  Attachment n;
  if (rb != 0) {
    auto it = c.renderbuffers.find(rb);
    if (it == c.renderbuffers.end() || !it->second) return c.error(GL_INVALID_OPERATION);
    n.type = GL_RENDERBUFFER;
    n.renderbuffer = it->second;
  }
  changed(c);
  *a = n;
  if (b) *b = n;
}

void renderbuffer_storage(Context& c, GLenum target, GLsizei samples, GLenum internal, GLsizei w, GLsizei h) {
  GL_OUTSIDE_BEGIN();
  if (target != GL_RENDERBUFFER) return c.error(GL_INVALID_ENUM);
  if (!c.bound_renderbuffer) return c.error(GL_INVALID_OPERATION);
  TexFormat fmt;
  const bool stencil_only = internal == GL_STENCIL_INDEX || internal == GL_STENCIL_INDEX1 ||
                            internal == GL_STENCIL_INDEX4 || internal == GL_STENCIL_INDEX8 ||
                            internal == GL_STENCIL_INDEX16;
  if (stencil_only) {
    tex_format_of(GL_DEPTH24_STENCIL8, false, fmt);  // kept in a depth-stencil image
    fmt.internal = internal;
    fmt.depth = 0;
    fmt.stencil = 8;
  } else if (!tex_format_of(GLint(internal), c.core_profile, fmt) ||
             (!fmt.color_renderable() && !fmt.is_depth())) {
    return c.error(GL_INVALID_ENUM);
  }
  if (w < 0 || h < 0 || w > kMaxRenderbufferSize || h > kMaxRenderbufferSize)
    return c.error(GL_INVALID_VALUE);
  if (samples < 0) return c.error(GL_INVALID_VALUE);
  // More samples than the format has: GL_INVALID_OPERATION (GL 4.6 §9.2.4, as Mesa answers).
  if (samples > kMaxSamples) return c.error(GL_INVALID_OPERATION);
  RenderbufferObject& r = *c.bound_renderbuffer;
  c.touch();
  c.finish();
  r.fmt = fmt;
  r.width = w;
  r.height = h;
  r.samples = samples > 0 ? kMaxSamples : 0;  // any sample count gives llvmpipe's one (4)
  r.image.reset();
  if (w == 0 || h == 0) return;
  try {
    r.image = std::make_unique<gpu::Texture2D>(fmt.storage, w, h);
    // Unsigned normalized colour starts (0, 0, 0, 0) and RGB formats read alpha 1; depth 0.
    if (!fmt.is_depth() && fmt.channel_mask() != 0xF) {
      gpu::Level& l = r.image->level_for_write(0);
      const size_t bpp = gpu::format_info(fmt.storage).bytes;
      const glm::vec4 v = to_storage(fmt, glm::vec4(0.0f));
      for (size_t i = 0; i < l.data.size(); i += bpp)
        gpu::detail::encode_texel(fmt.storage, l.data.data() + i, v);
    }
  } catch (const std::bad_alloc&) {
    r.image.reset();
    r.width = r.height = 0;
    c.error(GL_OUT_OF_MEMORY);
  }
}

// glDrawBuffers (and glDrawBuffer) on a framebuffer object: GL_NONE or GL_COLOR_ATTACHMENTi,
// each at most once (§4.2.1).
void draw_buffers(Context& c, GLsizei n, const std::array<GLenum, kMaxDrawBuffers>& bufs) {
  GL_OUTSIDE_BEGIN();
  if (n < 0 || n > kMaxDrawBuffers) return c.error(GL_INVALID_VALUE);
  if (!c.draw_fbo) {
    // The default framebuffer: one buffer as glDrawBuffer takes it, the rest GL_NONE.
    for (int i = 0; i < n; ++i) {
      const GLenum b = bufs[size_t(i)];
      if (b >= GL_COLOR_ATTACHMENT0 && b < GL_COLOR_ATTACHMENT0 + 16) return c.error(GL_INVALID_OPERATION);
      if (i > 0 && b != GL_NONE) return c.error(GL_INVALID_OPERATION);  // one colour buffer of a window
      if (b == GL_FRONT || b == GL_BACK || b == GL_FRONT_AND_BACK || b == GL_LEFT || b == GL_RIGHT)
        return c.error(GL_INVALID_ENUM);
    }
    if (n == 0) return;
    const GLenum b = bufs[0];
    if (b != GL_NONE && b != GL_FRONT_LEFT && b != GL_BACK_LEFT && b != GL_FRONT_RIGHT && b != GL_BACK_RIGHT)
      return c.error(GL_INVALID_ENUM);
    if (b != GL_NONE && !c.color_buffer(b)) return c.error(GL_INVALID_OPERATION);
    c.touch();
    c.s.color.draw_buffer = b;
    return;
  }
  std::array<GLenum, kMaxDrawBuffers> v{};
  for (int i = 0; i < n; ++i) {
    const GLenum b = bufs[size_t(i)];
    if (b == GL_NONE) continue;
    if (b >= GL_COLOR_ATTACHMENT0 && b < GL_COLOR_ATTACHMENT0 + 16) {
      if (b >= GL_COLOR_ATTACHMENT0 + kMaxColorAttachments) return c.error(GL_INVALID_OPERATION);
    } else if (b == GL_FRONT || b == GL_BACK || b == GL_LEFT || b == GL_RIGHT || b == GL_FRONT_AND_BACK) {
      return c.error(GL_INVALID_ENUM);  // names of several buffers: never in glDrawBuffers (§4.2.1)
    } else if (b == GL_FRONT_LEFT || b == GL_FRONT_RIGHT || b == GL_BACK_LEFT || b == GL_BACK_RIGHT ||
               (b >= GL_AUX0 && b <= GL_AUX3)) {
      return c.error(GL_INVALID_OPERATION);  // a window's buffer named for a framebuffer object
    } else {
      return c.error(GL_INVALID_ENUM);
    }
    for (int j = 0; j < i; ++j)
      if (bufs[size_t(j)] == b) return c.error(GL_INVALID_OPERATION);
    v[size_t(i)] = b;
  }
  c.touch();
  c.draw_fbo->draw_buffers = v;
}

// Clears one draw buffer, or the depth/stencil buffer, as glClear would with the masks and
// the scissor (§4.2.3).
// The kind of value glClearBuffer{f,i,ui}v gives: a colour of floats or of integers (their bits
// in `color`).
enum class ClearKind { Float, Int, Uint };

void clear_buffer_layer(Context& c, GLenum buffer, GLint drawbuffer, glm::vec4 color, float depth,
                        int stencil, ClearKind kind, int layer);

void clear_buffer(Context& c, GLenum buffer, GLint drawbuffer, glm::vec4 color, float depth, int stencil,
                  ClearKind kind) {
  GL_OUTSIDE_BEGIN();
  switch (buffer) {
    case GL_COLOR:
      if (drawbuffer < 0 || drawbuffer >= kMaxDrawBuffers) return c.error(GL_INVALID_VALUE);
      break;
    case GL_DEPTH:
    case GL_STENCIL:
    case GL_DEPTH_STENCIL:
      if (drawbuffer != 0) return c.error(GL_INVALID_VALUE);
      break;
    default: return c.error(GL_INVALID_ENUM);
  }
  if (c.rasterizer_discard) return;  // GL 3.3 §3.1: ClearBuffer* is ignored too
  c.touch();
  c.for_each_clear_layer(
      [&](int layer) { clear_buffer_layer(c, buffer, drawbuffer, color, depth, stencil, kind, layer); });
}

void clear_buffer_layer(Context& c, GLenum buffer, GLint drawbuffer, glm::vec4 color, float depth,
                        int stencil, ClearKind kind, int layer) {
  if (!c.bind_draw_target(layer)) return;
  const gpu::Framebuffer& fb = c.framebuffer();
  const Context::TargetInfo target = c.target_info();
  gpu::ClearValues cv;
  cv.clear_color = cv.clear_depth = cv.clear_stencil = false;
  if (buffer == GL_COLOR) {
    if (!fb.color[size_t(drawbuffer)]) return;
    // Integers into a buffer that is not integer (undefined, §4.2.3): their values as floats.
    if (kind != ClearKind::Float && !target.integer[size_t(drawbuffer)].integer())
      for (int k = 0; k < 4; ++k) {
        const uint32_t bits = std::bit_cast<uint32_t>(color[k]);
        color[k] = kind == ClearKind::Int ? float(int32_t(bits)) : float(bits);
      }
    cv.clear_color = true;
    cv.color_attachments = uint8_t(1u << drawbuffer);
    cv.per_attachment = true;
    cv.attachment_colors[size_t(drawbuffer)] = c.clear_color_for(target, drawbuffer, color);
  } else {
    cv.clear_depth = target.depth && (buffer == GL_DEPTH || buffer == GL_DEPTH_STENCIL);
    cv.depth = std::clamp(depth, 0.0f, 1.0f);
    cv.clear_stencil = target.stencil && (buffer == GL_STENCIL || buffer == GL_DEPTH_STENCIL);
    cv.stencil = uint8_t(stencil & 0xFF);
  }
  gpu::RenderState rs = c.render_state(true);
  rs.depth_write = c.s.depth.mask;
  if (!cv.clear_color && !cv.clear_depth && !cv.clear_stencil) return;
  try {
    c.gpu().clear(cv, rs);
  } catch (const std::exception&) {
    c.error(GL_INVALID_OPERATION);
  }
}

// §4.3.2: copies a rectangle of the read framebuffer to the draw framebuffer, scaled; each
// destination pixel reads the source at its centre mapped back (nearest texel or bilinear,
// clamped to the source image), as llvmpipe's blit by a textured quad does. Source pixels
// outside the read buffer leave their destination unchanged.
void blit(Context& c, GLint sx0, GLint sy0, GLint sx1, GLint sy1, GLint dx0, GLint dy0, GLint dx1, GLint dy1,
          GLbitfield mask, GLenum filter) {
  GL_OUTSIDE_BEGIN();
  if (mask & ~GLbitfield(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT))
    return c.error(GL_INVALID_VALUE);
  if (filter != GL_NEAREST && filter != GL_LINEAR) return c.error(GL_INVALID_ENUM);
  if (filter == GL_LINEAR && (mask & (GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT)))
    return c.error(GL_INVALID_OPERATION);
  if (!c.read_framebuffer_complete() || !c.draw_framebuffer_complete())
    return c.error(GL_INVALID_FRAMEBUFFER_OPERATION);
  // §4.3.2: a multisample read framebuffer is resolved only into a rectangle of its own size,
  // and into a multisample draw framebuffer only of the same sample count.
  const int read_samples = c.read_fbo ? c.read_fbo->samples() : 0;
  const int draw_samples = c.draw_fbo ? c.draw_fbo->samples() : 0;
  if (read_samples > 0) {
    const bool same_size =
        std::abs(sx1 - sx0) == std::abs(dx1 - dx0) && std::abs(sy1 - sy0) == std::abs(dy1 - dy0);
    if (!same_size || (draw_samples > 0 && draw_samples != read_samples))
      return c.error(GL_INVALID_OPERATION);
  }
  c.touch();
  if (!c.bind_draw_target()) return;
  c.finish();
  const gpu::Framebuffer& fb = c.framebuffer();
  struct Pass {
    gpu::Attachment src, dst;
    bool depth;
    uint8_t channels;           // the colour channels written: the draw buffer's mask and format
    gpu::IntegerRange integer;  // an integer draw buffer's range
  };
  std::vector<Pass> passes;
  if (mask & GL_COLOR_BUFFER_BIT) {
    const gpu::Attachment src = c.read_color();
    const Context::TargetInfo target = c.target_info();
    if (src) {
      const gpu::IntegerRange src_int = c.read_color_integer();
      for (int i = 0; i < kMaxDrawBuffers; ++i) {
        const gpu::Attachment& d = fb.color[size_t(i)];
        if (!d) continue;
        // Float and fixed-point may mix; integer buffers blit only into integer buffers of the
        // same signedness (as Mesa checks), and never with GL_LINEAR (§4.3.2).
        const gpu::IntegerRange dst_int = target.integer[size_t(i)];
        if (src_int.integer() != dst_int.integer() ||
            (src_int.integer() && src_int.is_signed != dst_int.is_signed))
          return c.error(GL_INVALID_OPERATION);
        if (src_int.integer() && filter == GL_LINEAR) return c.error(GL_INVALID_OPERATION);
        const std::array<bool, 4>& cm = c.s.color.color_mask[size_t(i)];
        const uint8_t m = uint8_t((cm[0] ? 1 : 0) | (cm[1] ? 2 : 0) | (cm[2] ? 4 : 0) | (cm[3] ? 8 : 0));
        passes.push_back({src, d, false, uint8_t(m & target.channels[size_t(i)]), dst_int});
      }
    }
  }
  if (mask & (GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT)) {
    const gpu::Attachment src = c.read_depth();
    const gpu::Attachment dst = fb.depth;
    if (src && dst) {
      // The depth formats must match in bits and kind (as Mesa checks): D24 with D24S8 is
      // fine, float depth with fixed-point is not.
      const bool src_float = src.format() == gpu::Format::Depth32F;
      const bool dst_float = dst.format() == gpu::Format::Depth32F;
      if (src_float != dst_float) return c.error(GL_INVALID_OPERATION);
      passes.push_back({src, dst, true, 0, {}});
    }
  }
  if (sx0 == sx1 || sy0 == sy1 || dx0 == dx1 || dy0 == dy1) return;
  const ScissorState& sc = c.s.scissor;
  const double kx = double(sx1 - sx0) / double(dx1 - dx0), ky = double(sy1 - sy0) / double(dy1 - dy0);
  const int xa = std::min(dx0, dx1), xb = std::max(dx0, dx1), ya = std::min(dy0, dy1),
            yb = std::max(dy0, dy1);
  for (const Pass& p : passes) {
    const gpu::Attachment &dt = p.dst, &st = p.src;
    const int sw = st.width(), sh = st.height();
    int x0 = std::max(xa, 0), x1 = std::min(xb, dt.width());
    int y0 = std::max(ya, 0), y1 = std::min(yb, dt.height());
    if (sc.test) {
      x0 = std::max(x0, sc.x), x1 = std::min(x1, sc.x + sc.width);
      y0 = std::max(y0, sc.y), y1 = std::min(y1, sc.y + sc.height);
    }
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const double u = double(sx0) + (double(x) + 0.5 - double(dx0)) * kx;
        const double v = double(sy0) + (double(y) + 0.5 - double(dy0)) * ky;
        glm::vec4 out;
        if (filter == GL_NEAREST || p.depth) {
          const int ix = int(std::floor(u)), iy = int(std::floor(v));
          if (ix < 0 || iy < 0 || ix >= sw || iy >= sh) continue;
          out = st.fetch(ix, iy);
        } else {
          if (u < 0.0 || v < 0.0 || u >= double(sw) || v >= double(sh)) continue;
          const double fu = u - 0.5, fv = v - 0.5;
          const int i0 = int(std::floor(fu)), j0 = int(std::floor(fv));
          const float ax = float(fu - std::floor(fu)), ay = float(fv - std::floor(fv));
          auto at = [&](int i, int j) {
            return st.fetch(std::clamp(i, 0, sw - 1), std::clamp(j, 0, sh - 1));
          };
          out = (at(i0, j0) * (1 - ax) + at(i0 + 1, j0) * ax) * (1 - ay) +
                (at(i0, j0 + 1) * (1 - ax) + at(i0 + 1, j0 + 1) * ax) * ay;
        }
        const glm::vec4 old = dt.fetch(x, y);
        if (p.depth) {
          if (!(mask & GL_DEPTH_BUFFER_BIT)) out.x = old.x;
          if (!(mask & GL_STENCIL_BUFFER_BIT)) out.y = old.y;
        } else {
          out = clamp_integer_texel(p.integer, out);
          for (int k = 0; k < 4; ++k)
            if (!(p.channels & (1u << k))) out[k] = old[k];
        }
        dt.store(x, y, out);
      }
  }
}

template <class T>
void gen_names(Context& c, GLsizei n, GLuint* names, std::unordered_map<GLuint, T>& map, GLuint& next) {
  if (n < 0) return c.error(GL_INVALID_VALUE);
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = fresh_name(map, next);
    map[name] = nullptr;
    if (names) names[i] = name;
  }
}

void bind_framebuffer(Context& c, GLenum target, GLuint name) {
  GL_OUTSIDE_BEGIN();
  bool draw, read;
  if (!fbo_targets(target, draw, read)) return c.error(GL_INVALID_ENUM);
  FramebufferRef ref;
  if (name != 0) {
    auto it = c.framebuffers.find(name);
    if (it == c.framebuffers.end() && c.core_profile) return c.error(GL_INVALID_OPERATION);
    FramebufferRef& r = c.framebuffers[name];
    if (!r) {
      r = std::make_shared<FramebufferObject>();
      r->name = name;
    }
    ref = r;
  }
  c.touch();
  if (draw) c.draw_fbo = ref;
  if (read) c.read_fbo = ref;
}

// glGetFramebufferAttachmentParameteriv of a framebuffer object's attachment (§6.1.13).
bool attachment_parameter(Context& c, const Attachment& a, GLenum pname, GLint& out) {
  TexFormat fmt;
  int w = 0, h = 0;
  const bool has = a.image(fmt, w, h);
  if (pname == GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) {
    out = GLint(a.type);
    return true;
  }
  if (!a) {
    if (pname == GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME) {
      out = 0;
      return true;
    }
    c.error(GL_INVALID_OPERATION);  // §6.1.13: only the type and name of an empty point
    return false;
  }
  auto bits = [&](uint8_t b) { return has ? GLint(b) : 0; };
  switch (pname) {
    case GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME:
      out = a.type == GL_TEXTURE ? GLint(a.texture->name) : GLint(a.renderbuffer->name);
      return true;
    case GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE: out = bits(fmt.r ? fmt.r : fmt.l ? fmt.l : fmt.i); return true;
    case GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE: out = bits(fmt.g ? fmt.g : fmt.l ? fmt.l : fmt.i); return true;
    case GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE: out = bits(fmt.b ? fmt.b : fmt.l ? fmt.l : fmt.i); return true;
    case GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE: out = bits(fmt.a ? fmt.a : fmt.i); return true;
    case GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE: out = bits(fmt.depth); return true;
    case GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE: out = bits(fmt.stencil); return true;
    case GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE:
      out =
          has ? GLint(fmt.has_stencil() && fmt.depth == 0 ? GL_UNSIGNED_INT : fmt.component_type()) : GL_NONE;
      return true;
    case GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING:
      out = has && fmt.kind == TexKind::Srgb ? GL_SRGB : GL_LINEAR;
      return true;
    default: break;
  }
  if (a.type == GL_TEXTURE) switch (pname) {
      case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL: out = a.level; return true;
      case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE:
        out = a.texture->target == TexTarget::Cube && !a.layered
                  ? GLint(GL_TEXTURE_CUBE_MAP_POSITIVE_X + a.face)
                  : 0;
        return true;
      case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER: out = a.layer; return true;
      case GL_FRAMEBUFFER_ATTACHMENT_LAYERED: out = a.layered ? 1 : 0; return true;
      default: break;
    }
  c.error(GL_INVALID_ENUM);
  return false;
}

}  // namespace
}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glGenFramebuffers(GLsizei n, GLuint* names) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  gen_names(c, n, names, c.framebuffers, c.next_framebuffer_name);
}
void GLAPIENTRY glDeleteFramebuffers(GLsizei n, const GLuint* names) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  if (!names) return;
  for (GLsizei i = 0; i < n; ++i) {
    auto it = c.framebuffers.find(names[i]);
    if (names[i] == 0 || it == c.framebuffers.end()) continue;
    if (it->second) {
      c.touch();
      // §4.4.1: deleting a bound framebuffer binds 0 in its place.
      if (c.draw_fbo == it->second) c.draw_fbo = nullptr;
      if (c.read_fbo == it->second) c.read_fbo = nullptr;
    }
    c.framebuffers.erase(it);
  }
}
void GLAPIENTRY glBindFramebuffer(GLenum target, GLuint fb) {
  GL_CONTEXT();
  bind_framebuffer(c, target, fb);
}
GLboolean GLAPIENTRY glIsFramebuffer(GLuint fb) {
  GL_CONTEXT(GLboolean(GL_FALSE));
  GL_OUTSIDE_BEGIN(GLboolean(GL_FALSE));
  auto it = c.framebuffers.find(fb);
  return fb != 0 && it != c.framebuffers.end() && it->second ? GL_TRUE : GL_FALSE;
}
GLenum GLAPIENTRY glCheckFramebufferStatus(GLenum target) {
  GL_CONTEXT(GLenum(0));
  GL_OUTSIDE_BEGIN(GLenum(0));
  bool draw, read;
  if (!fbo_targets(target, draw, read)) {
    c.error(GL_INVALID_ENUM);
    return 0;
  }
  FramebufferRef& r = draw ? c.draw_fbo : c.read_fbo;
  if (r) return c.framebuffer_status(*r);
  return c.has_default_framebuffer ? GLenum(GL_FRAMEBUFFER_COMPLETE) : GLenum(GL_FRAMEBUFFER_UNDEFINED);
}
void GLAPIENTRY glFramebufferTexture1D(GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                                       GLint level) {
  GL_CONTEXT();
  attach_texture(c, target, attachment, textarget, texture, level, 0, 1);
}
void GLAPIENTRY glFramebufferTexture2D(GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                                       GLint level) {
  GL_CONTEXT();
  attach_texture(c, target, attachment, textarget, texture, level, 0, 2);
}
void GLAPIENTRY glFramebufferTexture3D(GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                                       GLint level, GLint layer) {
  GL_CONTEXT();
  attach_texture(c, target, attachment, textarget, texture, level, layer, 3);
}
void GLAPIENTRY glFramebufferTextureLayer(GLenum target, GLenum attachment, GLuint texture, GLint level,
                                          GLint layer) {
  GL_CONTEXT();
  attach_texture(c, target, attachment, GL_NONE, texture, level, layer, 4);
}
void GLAPIENTRY glFramebufferTexture(GLenum target, GLenum attachment, GLuint texture, GLint level) {
  GL_CONTEXT();
  attach_texture(c, target, attachment, GL_NONE, texture, level, 0, 0);
}
void GLAPIENTRY glFramebufferRenderbuffer(GLenum target, GLenum attachment, GLenum rbtarget, GLuint rb) {
  GL_CONTEXT();
  attach_renderbuffer(c, target, attachment, rbtarget, rb);
}
void GLAPIENTRY glGetFramebufferAttachmentParameteriv(GLenum target, GLenum attachment, GLenum pname,
                                                      GLint* params) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  bool draw, read;
  if (!fbo_targets(target, draw, read)) return c.error(GL_INVALID_ENUM);
  FramebufferRef& r = draw ? c.draw_fbo : c.read_fbo;
  GLint v = 0;
  if (!r) {
    // The default framebuffer's buffers (§6.1.13): GL_FRAMEBUFFER_DEFAULT, 8-bit RGBA, D24S8.
    const bool color = attachment == GL_FRONT_LEFT || attachment == GL_BACK_LEFT ||
                       attachment == GL_FRONT_RIGHT || attachment == GL_BACK_RIGHT;
    const bool depth = attachment == GL_DEPTH, stencil = attachment == GL_STENCIL;
    if (!color && !depth && !stencil) return c.error(GL_INVALID_ENUM);
    const bool exists = color   ? c.color_buffer(attachment) != nullptr
                        : depth ? c.has_depth()
                                : c.has_stencil();
    switch (pname) {
      case GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE: v = exists ? GL_FRAMEBUFFER_DEFAULT : GL_NONE; break;
      case GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE:
      case GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE:
      case GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE:
      case GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE: v = exists && color ? 8 : 0; break;
      case GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE: v = exists && depth ? 24 : 0; break;
      case GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE: v = exists && stencil ? 8 : 0; break;
      case GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE:
        v = !exists ? GL_NONE : stencil ? GL_UNSIGNED_INT : GL_UNSIGNED_NORMALIZED;
        break;
      case GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING: v = GL_LINEAR; break;
      default: return c.error(GL_INVALID_ENUM);
    }
    if (params) *params = v;
    return;
  }
  Attachment* a = nullptr;
  if (attachment == GL_DEPTH_STENCIL_ATTACHMENT) {
    const bool same = r->depth.type == r->stencil.type && r->depth.texture == r->stencil.texture &&
                      r->depth.renderbuffer == r->stencil.renderbuffer;
    if (!same) return c.error(GL_INVALID_OPERATION);
    a = &r->depth;
  } else {
    a = r->point(attachment);
  }
  if (!a) return c.error(GL_INVALID_ENUM);
  if (attachment_parameter(c, *a, pname, v) && params) *params = v;
}

void GLAPIENTRY glGenRenderbuffers(GLsizei n, GLuint* names) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  gen_names(c, n, names, c.renderbuffers, c.next_renderbuffer_name);
}
void GLAPIENTRY glDeleteRenderbuffers(GLsizei n, const GLuint* names) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  if (!names) return;
  for (GLsizei i = 0; i < n; ++i) {
    auto it = c.renderbuffers.find(names[i]);
    if (names[i] == 0 || it == c.renderbuffers.end()) continue;
    if (it->second) {
      c.touch();
      c.renderbuffer_deleted(*it->second);
    }
    c.renderbuffers.erase(it);
  }
}
void GLAPIENTRY glBindRenderbuffer(GLenum target, GLuint rb) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (target != GL_RENDERBUFFER) return c.error(GL_INVALID_ENUM);
  if (rb == 0) {
    c.bound_renderbuffer = nullptr;
    return;
  }
  auto it = c.renderbuffers.find(rb);
  if (it == c.renderbuffers.end() && c.core_profile) return c.error(GL_INVALID_OPERATION);
  RenderbufferRef& r = c.renderbuffers[rb];
  if (!r) {
    r = std::make_shared<RenderbufferObject>();
    r->name = rb;
  }
  c.bound_renderbuffer = r;
}
GLboolean GLAPIENTRY glIsRenderbuffer(GLuint rb) {
  GL_CONTEXT(GLboolean(GL_FALSE));
  GL_OUTSIDE_BEGIN(GLboolean(GL_FALSE));
  auto it = c.renderbuffers.find(rb);
  return rb != 0 && it != c.renderbuffers.end() && it->second ? GL_TRUE : GL_FALSE;
}
void GLAPIENTRY glRenderbufferStorage(GLenum target, GLenum internal, GLsizei w, GLsizei h) {
  GL_CONTEXT();
  renderbuffer_storage(c, target, 0, internal, w, h);
}
void GLAPIENTRY glRenderbufferStorageMultisample(GLenum target, GLsizei samples, GLenum internal, GLsizei w,
                                                 GLsizei h) {
  GL_CONTEXT();
  renderbuffer_storage(c, target, samples, internal, w, h);
}
// GL 3.3 §4.1.3: the sample mask word (one, GL_MAX_SAMPLE_MASK_WORDS).
void GLAPIENTRY glSampleMaski(GLuint index, GLbitfield mask) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (index != 0) return c.error(GL_INVALID_VALUE);
  c.touch();
  c.sample_mask = mask;
}

// GL 3.3 §3.3.1: where sample `index` of the draw framebuffer's pixels lies, as llvmpipe's
// four-sample pattern places it; an index past GL_SAMPLES is GL_INVALID_VALUE.
void GLAPIENTRY glGetMultisamplefv(GLenum pname, GLuint index, GLfloat* val) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (pname != GL_SAMPLE_POSITION) return c.error(GL_INVALID_ENUM);
  const int samples = c.draw_fbo ? c.draw_fbo->samples() : 0;
  if (index >= GLuint(samples)) return c.error(GL_INVALID_VALUE);
  static const float kPositions[4][2] = {
      {0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
  if (!val) return;
  val[0] = kPositions[index % 4][0];
  val[1] = kPositions[index % 4][1];
}

void GLAPIENTRY glGetRenderbufferParameteriv(GLenum target, GLenum pname, GLint* params) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (target != GL_RENDERBUFFER) return c.error(GL_INVALID_ENUM);
  if (!c.bound_renderbuffer) return c.error(GL_INVALID_OPERATION);
  const RenderbufferObject& r = *c.bound_renderbuffer;
  const bool has = r.image != nullptr;
  GLint v = 0;
  switch (pname) {
    case GL_RENDERBUFFER_WIDTH: v = r.width; break;
    case GL_RENDERBUFFER_HEIGHT: v = r.height; break;
    case GL_RENDERBUFFER_INTERNAL_FORMAT: v = GLint(r.fmt.internal); break;
    case GL_RENDERBUFFER_SAMPLES: v = r.samples; break;
    case GL_RENDERBUFFER_RED_SIZE: v = has ? r.fmt.r : 0; break;
    case GL_RENDERBUFFER_GREEN_SIZE: v = has ? r.fmt.g : 0; break;
    case GL_RENDERBUFFER_BLUE_SIZE: v = has ? r.fmt.b : 0; break;
    case GL_RENDERBUFFER_ALPHA_SIZE: v = has ? r.fmt.a : 0; break;
    case GL_RENDERBUFFER_DEPTH_SIZE: v = has ? r.fmt.depth : 0; break;
    case GL_RENDERBUFFER_STENCIL_SIZE: v = has ? r.fmt.stencil : 0; break;
    default: return c.error(GL_INVALID_ENUM);
  }
  if (params) *params = v;
}

void GLAPIENTRY glDrawBuffers(GLsizei n, const GLenum* bufs) {
  GL_CONTEXT();
  std::array<GLenum, kMaxDrawBuffers> v{};
  if (n > 0 && n <= kMaxDrawBuffers && bufs)
    for (GLsizei i = 0; i < n; ++i) v[size_t(i)] = bufs[i];
  if (n > 0 && !bufs) return c.error(GL_INVALID_VALUE);
  draw_buffers(c, n, v);
}

void GLAPIENTRY glClearBufferfv(GLenum buffer, GLint drawbuffer, const GLfloat* value) {
  GL_CONTEXT();
  if (!value) return;
  if (incomplete_for_clear(c)) return;
  if (buffer == GL_STENCIL || buffer == GL_DEPTH_STENCIL) return c.error(GL_INVALID_ENUM);
  const glm::vec4 col =
      buffer == GL_COLOR ? glm::vec4(value[0], value[1], value[2], value[3]) : glm::vec4(0.0f);
  clear_buffer(c, buffer, drawbuffer, col, value[0], 0, ClearKind::Float);
}
void GLAPIENTRY glClearBufferiv(GLenum buffer, GLint drawbuffer, const GLint* value) {
  GL_CONTEXT();
  if (!value) return;
  if (incomplete_for_clear(c)) return;
  if (buffer == GL_DEPTH || buffer == GL_DEPTH_STENCIL) return c.error(GL_INVALID_ENUM);
  glm::vec4 col(0.0f);
  if (buffer == GL_COLOR)
    for (int k = 0; k < 4; ++k) col[k] = std::bit_cast<float>(value[k]);
  clear_buffer(c, buffer, drawbuffer, col, 0.0f, value[0], ClearKind::Int);
}
void GLAPIENTRY glClearBufferuiv(GLenum buffer, GLint drawbuffer, const GLuint* value) {
  GL_CONTEXT();
  if (!value) return;
  if (incomplete_for_clear(c)) return;
  if (buffer != GL_COLOR) return c.error(GL_INVALID_ENUM);
  glm::vec4 col;
  for (int k = 0; k < 4; ++k) col[k] = std::bit_cast<float>(value[k]);
  clear_buffer(c, buffer, drawbuffer, col, 0.0f, 0, ClearKind::Uint);
}
void GLAPIENTRY glClearBufferfi(GLenum buffer, GLint drawbuffer, GLfloat depth, GLint stencil) {
  GL_CONTEXT();
  if (buffer != GL_DEPTH_STENCIL) return c.error(GL_INVALID_ENUM);  // (checked first here, as by Mesa)
  if (incomplete_for_clear(c)) return;
  clear_buffer(c, buffer, drawbuffer, glm::vec4(0.0f), depth, stencil, ClearKind::Float);
}

void GLAPIENTRY glBlitFramebuffer(GLint sx0, GLint sy0, GLint sx1, GLint sy1, GLint dx0, GLint dy0, GLint dx1,
                                  GLint dy1, GLbitfield mask, GLenum filter) {
  GL_CONTEXT();
  blit(c, sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1, mask, filter);
}

void GLAPIENTRY glColorMaski(GLuint buf, GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (buf >= GLuint(kMaxDrawBuffers)) return c.error(GL_INVALID_VALUE);
  c.touch();
  c.s.color.color_mask[buf] = {r != GL_FALSE, g != GL_FALSE, b != GL_FALSE, a != GL_FALSE};
}
void GLAPIENTRY glEnablei(GLenum cap, GLuint index) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (cap != GL_BLEND) return c.error(GL_INVALID_ENUM);
  if (index >= GLuint(kMaxDrawBuffers)) return c.error(GL_INVALID_VALUE);
  c.touch();
  c.s.color.blend[index] = true;
}
void GLAPIENTRY glDisablei(GLenum cap, GLuint index) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (cap != GL_BLEND) return c.error(GL_INVALID_ENUM);
  if (index >= GLuint(kMaxDrawBuffers)) return c.error(GL_INVALID_VALUE);
  c.touch();
  c.s.color.blend[index] = false;
}
GLboolean GLAPIENTRY glIsEnabledi(GLenum cap, GLuint index) {
  GL_CONTEXT(GLboolean(GL_FALSE));
  GL_OUTSIDE_BEGIN(GLboolean(GL_FALSE));
  if (cap != GL_BLEND) {
    c.error(GL_INVALID_ENUM);
    return GL_FALSE;
  }
  if (index >= GLuint(kMaxDrawBuffers)) {
    c.error(GL_INVALID_VALUE);
    return GL_FALSE;
  }
  return c.s.color.blend[index] ? GL_TRUE : GL_FALSE;
}

}  // extern "C"
