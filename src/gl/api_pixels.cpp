// Pixel rectangles (GL 2.1 §3.6-3.7, §4.3): glPixelStore, glPixelZoom, glPixelTransfer,
// glReadPixels, glDrawPixels, glCopyPixels and glBitmap.
//
// glDrawPixels and glBitmap make fragments like any primitive: they are drawn through the
// gpu pipeline as a window-aligned rectangle whose fragment shader reads the image, so the
// scissor, alpha, stencil and depth tests, blending and the masks all apply.
#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "api.hpp"
#include "pixels.hpp"

namespace tessel::gl {

namespace {

// A window-aligned rectangle of an image: position in window coordinates, texture NEAREST.
struct PixelRect {
  struct Uniforms {
    glm::vec2 scale{1.0f}, offset{0.0f};  // window -> clip
    float z = 0.0f;                       // clip z (window depth in [0, 1] mapped to [-1, 1])
    gpu::Sampler2D image;
    bool bitmap = false;  // fragments only where the image's alpha is set, in `color`
    glm::vec4 color{1.0f};
    bool alpha_test = false;
    gpu::CompareFunc alpha_func = gpu::CompareFunc::Always;
    float alpha_ref = 0.0f;
  };
  template <class F>
  struct Varyings {
    gpu::Vec2<F> uv;
  };
  static constexpr bool discards = true;
  static constexpr uint32_t attributes = 0b11;
  template <class F>
  gpu::Vec4<F> vertex(const Uniforms& u, const gpu::VertexIn<F>& in, Varyings<F>& out) const {
    out.uv = in.attr[1].xy();
    return gpu::Vec4<F>(in.attr[0].x * F(u.scale.x) + F(u.offset.x),
                        in.attr[0].y * F(u.scale.y) + F(u.offset.y), F(u.z), F(1.0f));
  }
  template <class F>
  void fragment(const Uniforms& u, const Varyings<F>& v, gpu::Fragment<F>& f) const {
    gpu::Vec4<F> c = texture(u.image, v.uv);
    if (u.bitmap) {
      f.discard(c.w == F(0.0f));
      c = gpu::Vec4<F>(u.color);
    }
    if (u.alpha_test) f.discard(!gpu::compare(u.alpha_func, c.w, F(u.alpha_ref)));
    f.color[0] = c;
  }
};

}  // namespace

void Context::draw_pixels_rgba(float x, float y, int w, int h, const std::vector<uint8_t>& rgba, float zoom_x,
                               float zoom_y, const glm::vec4* color) {
  if (w <= 0 || h <= 0 || zoom_x == 0.0f || zoom_y == 0.0f) return;
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(zoom_x) || !std::isfinite(zoom_y)) return;
  touch();
  if (!bind_draw_target()) return;
  auto tex = std::make_unique<gpu::Texture2D>(gpu::Format::RGBA8, w, h);
  tex->upload(0, rgba.data(), rgba.size());
  const float x1 = x + float(w) * zoom_x, y1 = y + float(h) * zoom_y;
  const float quad[4][4] = {{x, y, 0, 0}, {x1, y, 1, 0}, {x1, y1, 1, 1}, {x, y1, 0, 1}};
  const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
  auto vb = std::make_unique<gpu::Buffer>(quad, sizeof quad);
  auto ib = std::make_unique<gpu::Buffer>(idx, sizeof idx);
  gpu::VertexLayout layout;
  layout.attrib(0, *vb, 2, gpu::AttribType::F32, 16, 0);
  layout.attrib(1, *vb, 2, gpu::AttribType::F32, 16, 8);
  PixelRect::Uniforms u;
  const int fw = fb_.width(), fh = fb_.height();
  u.scale = glm::vec2(2.0f / float(fw), 2.0f / float(fh));
  u.offset = glm::vec2(-1.0f, -1.0f);
  u.z = s.current.raster_pos.z * 2.0f - 1.0f;
  u.image.texture = tex.get();
  u.image.state.min_filter = gpu::Filter::Nearest;
  u.image.state.mag_filter = gpu::Filter::Nearest;
  u.image.state.wrap_s = u.image.state.wrap_t = gpu::Wrap::ClampToEdge;
  if (color) {
    u.bitmap = true;
    u.color = *color;
  }
  u.alpha_test = s.color.alpha_test && s.color.alpha_func != GL_ALWAYS;
  u.alpha_func = compare_of(s.color.alpha_func);
  u.alpha_ref = s.color.alpha_ref;
  gpu::RenderState rs = render_state(false);
  rs.viewport = {0, 0, fw, fh};
  rs.depth_near = 0.0f;
  rs.depth_far = 1.0f;
  rs.cull = gpu::CullMode::None;
  rs.polygon_mode = gpu::PolygonMode::Fill;
  rs.offset_fill = false;
  rs.clip_plane_enable = 0;
  rs.depth_clamp = true;
  gpu::DrawCall call;
  call.count = 6;
  call.index_buffer = ib.get();
  guarded([&] { gpu_->draw(PixelRect{}, u, layout, rs, call); });
  transient_buffers_.push_back(std::move(vb));
  transient_buffers_.push_back(std::move(ib));
  transient_textures_.push_back(std::move(tex));
}

namespace {

void pixel_store(Context& c, GLenum pname, float v) {
  GL_OUTSIDE_BEGIN();
  PixelStore* ps = nullptr;
  switch (pname) {
    case GL_PACK_SWAP_BYTES:
    case GL_PACK_LSB_FIRST:
    case GL_PACK_ROW_LENGTH:
    case GL_PACK_SKIP_ROWS:
    case GL_PACK_SKIP_PIXELS:
    case GL_PACK_IMAGE_HEIGHT:
    case GL_PACK_SKIP_IMAGES:
    case GL_PACK_ALIGNMENT: ps = &c.c.pack; break;
    case GL_UNPACK_SWAP_BYTES:
    case GL_UNPACK_LSB_FIRST:
    case GL_UNPACK_ROW_LENGTH:
    case GL_UNPACK_SKIP_ROWS:
    case GL_UNPACK_SKIP_PIXELS:
    case GL_UNPACK_IMAGE_HEIGHT:
    case GL_UNPACK_SKIP_IMAGES:
    case GL_UNPACK_ALIGNMENT: ps = &c.c.unpack; break;
    default: return c.error(GL_INVALID_ENUM);
  }
  const GLint i = GLint(std::lround(v));
  switch (pname) {
    case GL_PACK_SWAP_BYTES:
    case GL_UNPACK_SWAP_BYTES: ps->swap_bytes = v != 0.0f; break;
    case GL_PACK_LSB_FIRST:
    case GL_UNPACK_LSB_FIRST: ps->lsb_first = v != 0.0f; break;
    case GL_PACK_ALIGNMENT:
    case GL_UNPACK_ALIGNMENT:
      if (i != 1 && i != 2 && i != 4 && i != 8) return c.error(GL_INVALID_VALUE);
      ps->alignment = i;
      break;
    default:
      if (i < 0) return c.error(GL_INVALID_VALUE);
      if (pname == GL_PACK_ROW_LENGTH || pname == GL_UNPACK_ROW_LENGTH)
        ps->row_length = i;
      else if (pname == GL_PACK_SKIP_ROWS || pname == GL_UNPACK_SKIP_ROWS)
        ps->skip_rows = i;
      else if (pname == GL_PACK_IMAGE_HEIGHT || pname == GL_UNPACK_IMAGE_HEIGHT)
        ps->image_height = i;
      else if (pname == GL_PACK_SKIP_IMAGES || pname == GL_UNPACK_SKIP_IMAGES)
        ps->skip_images = i;
      else
        ps->skip_pixels = i;
      break;
  }
}

void pixel_zoom(Context& c, float x, float y) {
  GL_OUTSIDE_BEGIN();
  c.s.pixel.zoom_x = x;
  c.s.pixel.zoom_y = y;
}

void pixel_transfer(Context& c, GLenum pname, float v) {
  GL_OUTSIDE_BEGIN();
  PixelModeState& p = c.s.pixel;
  switch (pname) {
    case GL_MAP_COLOR: p.map_color = v != 0.0f; break;
    case GL_MAP_STENCIL: p.map_stencil = v != 0.0f; break;
    case GL_INDEX_SHIFT: p.index_shift = GLint(v); break;
    case GL_INDEX_OFFSET: p.index_offset = GLint(v); break;
    case GL_RED_SCALE: p.red_scale = v; break;
    case GL_RED_BIAS: p.red_bias = v; break;
    case GL_GREEN_SCALE: p.green_scale = v; break;
    case GL_GREEN_BIAS: p.green_bias = v; break;
    case GL_BLUE_SCALE: p.blue_scale = v; break;
    case GL_BLUE_BIAS: p.blue_bias = v; break;
    case GL_ALPHA_SCALE: p.alpha_scale = v; break;
    case GL_ALPHA_BIAS: p.alpha_bias = v; break;
    case GL_DEPTH_SCALE: p.depth_scale = v; break;
    case GL_DEPTH_BIAS: p.depth_bias = v; break;
    default: c.error(GL_INVALID_ENUM); break;
  }
}

// GL 2.1 §3.6.5, RGBA groups: each component scaled and biased, clamped to [0, 1], and with
// GL_MAP_COLOR looked up in its GL_PIXEL_MAP_c_TO_c (at round(c (size - 1))).
float map_lookup(const std::vector<float>& m, float v) {
  const float i = std::round(std::clamp(v, 0.0f, 1.0f) * float(m.size() - 1));
  return m[size_t(std::clamp(i, 0.0f, float(m.size() - 1)))];
}
void transfer(const ServerState& s, std::vector<glm::vec4>& px) {
  const PixelModeState& p = s.pixel;
  const glm::vec4 scale(p.red_scale, p.green_scale, p.blue_scale, p.alpha_scale);
  const glm::vec4 bias(p.red_bias, p.green_bias, p.blue_bias, p.alpha_bias);
  if (scale != glm::vec4(1.0f) || bias != glm::vec4(0.0f))
    for (glm::vec4& v : px) v = glm::clamp(v * scale + bias, 0.0f, 1.0f);
  if (!p.map_color) return;
  const size_t first = GL_PIXEL_MAP_R_TO_R - GL_PIXEL_MAP_I_TO_I;
  for (glm::vec4& v : px)
    for (int k = 0; k < 4; ++k) v[k] = map_lookup(s.pixel_maps[first + size_t(k)], v[k]);
}

// Index groups (colour and stencil indices, §3.6.5): shifted by GL_INDEX_SHIFT (left when
// positive) and offset by GL_INDEX_OFFSET.
int64_t index_arithmetic(const PixelModeState& p, int64_t i) {
  const int sh = std::clamp(p.index_shift, -62, 62);
  i = sh >= 0 ? int64_t(uint64_t(i) << sh) : (i >> -sh);
  return i + p.index_offset;
}
// A table entry for index i of a power-of-two map (the index masked to its size).
float index_lookup(const std::vector<float>& m, int64_t i) { return m[size_t(i & int64_t(m.size() - 1))]; }

// A stencil index after the transfer operations: arithmetic, then S_TO_S with GL_MAP_STENCIL.
int64_t stencil_transfer(const ServerState& s, float v) {
  int64_t i = index_arithmetic(s.pixel, int64_t(std::floor(double(v))));
  if (s.pixel.map_stencil)
    i = int64_t(std::lround(index_lookup(s.pixel_maps[GL_PIXEL_MAP_S_TO_S - GL_PIXEL_MAP_I_TO_I], i)));
  return i;
}

struct Pixels {
  std::vector<glm::vec4> px;
};

void draw_pixels(Context& c, GLsizei w, GLsizei h, GLenum format, const std::shared_ptr<Pixels>& data) {
  GL_OUTSIDE_BEGIN();
  if (!c.s.current.raster_valid || !data) return;
  if (format == GL_STENCIL_INDEX || format == GL_DEPTH_COMPONENT) {
    // Depth and stencil rectangles write those buffers directly (no colour).
    c.finish();
    gpu::Texture2D* d = c.depth_buffer();
    if (!d) return;
    const int x0 = int(std::floor(c.s.current.raster_pos.x)), y0 = int(std::floor(c.s.current.raster_pos.y));
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const int x = x0 + i, y = y0 + j;
        if (x < 0 || y < 0 || x >= d->width() || y >= d->height()) continue;
        glm::vec4 t = d->fetch(0, x, y);
        const float v = data->px[size_t(j) * size_t(w) + size_t(i)].x;
        if (format == GL_DEPTH_COMPONENT)
          t.x = std::clamp(v * c.s.pixel.depth_scale + c.s.pixel.depth_bias, 0.0f, 1.0f);
        else
          t.y = float(uint8_t(stencil_transfer(c.s, v) & 0xFF));
        d->store(0, x, y, t);
      }
    return;
  }
  std::vector<glm::vec4> px = data->px;
  if (format == GL_COLOR_INDEX) {
    // §3.6.5: index arithmetic, I_TO_I with GL_MAP_COLOR, and (an RGBA window) the index to
    // RGBA lookup through I_TO_R, I_TO_G, I_TO_B and I_TO_A.
    const auto& maps = c.s.pixel_maps;
    for (glm::vec4& v : px) {
      int64_t i = index_arithmetic(c.s.pixel, int64_t(std::floor(double(v.x))));
      if (c.s.pixel.map_color) i = int64_t(std::lround(index_lookup(maps[0], i)));
      for (int k = 0; k < 4; ++k)
        v[k] = std::clamp(index_lookup(maps[GL_PIXEL_MAP_I_TO_R - GL_PIXEL_MAP_I_TO_I + size_t(k)], i), 0.0f,
                          1.0f);
    }
  } else {
    transfer(c.s, px);
  }
  std::vector<uint8_t> rgba(px.size() * 4);
  for (size_t i = 0; i < px.size(); ++i)
    for (int k = 0; k < 4; ++k) rgba[i * 4 + size_t(k)] = unorm8(px[i][k]);
  // The image starts at the raster position rounded to a whole pixel, as Mesa does (the
  // zoomed rectangle of GL 2.1 §3.6.4 then covers the same pixel centres).
  c.draw_pixels_rgba(std::round(c.s.current.raster_pos.x), std::round(c.s.current.raster_pos.y), w, h, rgba,
                     c.s.pixel.zoom_x, c.s.pixel.zoom_y, nullptr);
}

void bitmap(Context& c, GLsizei w, GLsizei h, float xo, float yo, float xm, float ym,
            const std::shared_ptr<std::vector<uint8_t>>& bits) {
  GL_OUTSIDE_BEGIN();
  if (w < 0 || h < 0) return c.error(GL_INVALID_VALUE);
  CurrentState& cur = c.s.current;
  if (!cur.raster_valid) return;
  if (bits && w > 0 && h > 0) {
    std::vector<uint8_t> rgba(size_t(w) * size_t(h) * 4, 0);
    for (size_t i = 0; i < bits->size(); ++i) rgba[i * 4 + 3] = (*bits)[i] ? 255 : 0;
    // GL 2.1 §3.7: the lower-left corner is (floor(xr - xo), floor(yr - yo)); with Mesa's
    // 1e-4 before the floor, so a raster position that should be 6 and is 5.9999943 after
    // the transforms still lands on 6.
    c.draw_pixels_rgba(std::floor(cur.raster_pos.x - xo + 1e-4f), std::floor(cur.raster_pos.y - yo + 1e-4f),
                       w, h, rgba, 1.0f, 1.0f, &cur.raster_color);
  }
  cur.raster_pos.x += xm;
  cur.raster_pos.y += ym;
}

void copy_pixels(Context& c, GLint x, GLint y, GLsizei w, GLsizei h, GLenum type) {
  GL_OUTSIDE_BEGIN();
  if (w < 0 || h < 0) return c.error(GL_INVALID_VALUE);
  if (type != GL_COLOR && type != GL_DEPTH && type != GL_STENCIL) return c.error(GL_INVALID_ENUM);
  if (!c.s.current.raster_valid || w == 0 || h == 0) return;
  c.finish();
  auto data = std::make_shared<Pixels>();
  data->px.assign(size_t(w) * size_t(h), glm::vec4(0.0f));
  const gpu::Attachment a = type == GL_COLOR ? c.read_color() : c.read_depth();
  if (!a) return;
  const int aw = a.width(), ah = a.height();
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      if (x + i >= 0 && y + j >= 0 && x + i < aw && y + j < ah) {
        glm::vec4 v = a.fetch(x + i, y + j);
        if (type == GL_STENCIL) v.x = v.y;
        data->px[size_t(j) * size_t(w) + size_t(i)] = v;
      }
  draw_pixels(c, w, h,
              type == GL_COLOR   ? GL_RGBA
              : type == GL_DEPTH ? GL_DEPTH_COMPONENT
                                 : GL_STENCIL_INDEX,
              data);
}

}  // namespace
}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glPixelStoref(GLenum pname, GLfloat v) {
  GL_CONTEXT();
  pixel_store(c, pname, v);
}
void GLAPIENTRY glPixelStorei(GLenum pname, GLint v) { glPixelStoref(pname, float(v)); }
void GLAPIENTRY glPixelZoom(GLfloat x, GLfloat y) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(pixel_zoom(c, x, y));
  pixel_zoom(c, x, y);
}
void GLAPIENTRY glPixelTransferf(GLenum pname, GLfloat v) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(pixel_transfer(c, pname, v));
  pixel_transfer(c, pname, v);
}
void GLAPIENTRY glPixelTransferi(GLenum pname, GLint v) { glPixelTransferf(pname, float(v)); }

void GLAPIENTRY glReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type,
                             GLvoid* pixels) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (w < 0 || h < 0) return c.error(GL_INVALID_VALUE);
  if (const GLenum e = check_format_type(format, type, c.core_profile); e != GL_NO_ERROR) return c.error(e);
  if (format == GL_COLOR_INDEX || type == GL_BITMAP) return c.error(GL_INVALID_ENUM);
  if (!c.read_framebuffer_complete()) return c.error(GL_INVALID_FRAMEBUFFER_OPERATION);
  if (c.read_fbo && c.read_fbo->samples() > 0) return c.error(GL_INVALID_OPERATION);  // §4.3.1
  const bool depth_stencil = format == GL_DEPTH_STENCIL;
  const bool depth = format == GL_DEPTH_COMPONENT || depth_stencil, stencil = format == GL_STENCIL_INDEX;
  const tessel::gpu::Attachment a = depth || stencil ? c.read_depth() : c.read_color();
  if (!a) return c.error(GL_INVALID_OPERATION);
  // §4.3.1: integer formats read integer colour buffers, the others the rest.
  const tessel::gpu::IntegerRange integer =
      depth || stencil ? tessel::gpu::IntegerRange{} : c.read_color_integer();
  if (!depth && !stencil && is_integer_format(format) != integer.integer())
    return c.error(GL_INVALID_OPERATION);
  if ((stencil || depth_stencil) && !c.read_has_stencil()) return c.error(GL_INVALID_OPERATION);
  void* dst = pixels;
  if (c.pixel_pack_buffer) {
    BufferObject& b = *c.pixel_pack_buffer;
    const PixelLayout L = pixel_layout(c.c.pack, w, format, type);
    const size_t offset = reinterpret_cast<size_t>(pixels);
    const size_t need =
        offset + L.offset + L.row_stride * size_t(std::max(h, 1) - 1) + L.pixel_stride * size_t(w);
    if (b.mapped || need > b.data.size() || need < offset) return c.error(GL_INVALID_OPERATION);
    // §4.3.1: the offset a multiple of the type's size.
    if (offset % size_t(std::max(1, type_bytes(type))) != 0) return c.error(GL_INVALID_OPERATION);
    dst = b.data.writable() + offset;
  }
  if (w == 0 || h == 0 || !dst) return;
  c.finish();
  const int aw = a.width(), ah = a.height();
  std::vector<glm::vec4> px(size_t(w) * size_t(h), glm::vec4(0.0f));
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const int sx = x + i, sy = y + j;
      if (sx < 0 || sy < 0 || sx >= aw || sy >= ah) continue;
      glm::vec4 v = a.fetch(sx, sy);
      if (stencil) v.x = v.y;
      px[size_t(j) * size_t(w) + size_t(i)] = v;
    }
  if (integer.integer()) {
    // Integer values skip the pixel transfer operations and clamping (§4.3.2).
    match_integer_sign(px, integer.is_signed, type);
    return pack_pixels(c.c.pack, w, h, format, type, px, dst);
  }
  if (!depth && !stencil) transfer(c.s, px);
  // Depth values are scaled and biased, stencil indices go through the index operations
  // (§4.3.2).
  if (depth && !depth_stencil && (c.s.pixel.depth_scale != 1.0f || c.s.pixel.depth_bias != 0.0f))
    for (glm::vec4& v : px) v.x = std::clamp(v.x * c.s.pixel.depth_scale + c.s.pixel.depth_bias, 0.0f, 1.0f);
  if (stencil)
    for (glm::vec4& v : px) v.x = float(stencil_transfer(c.s, v.x) & 0xFF);
  const bool fixed_point = a.format() == tessel::gpu::Format::RGBA8 ||
                           a.format() == tessel::gpu::Format::R8 || a.format() == tessel::gpu::Format::RG8;
  if (!depth && !stencil &&
      (c.s.pixel.clamp_read == GL_TRUE || (c.s.pixel.clamp_read == GL_FIXED_ONLY && fixed_point)))
    for (glm::vec4& v : px) v = glm::clamp(v, 0.0f, 1.0f);
  if (stencil) {
    // Stencil values are integers: GL_UNSIGNED_BYTE 5 reads as 5, not 5/255.
    for (glm::vec4& v : px) v.x = type == GL_FLOAT || type == GL_HALF_FLOAT ? v.x : v.x / 255.0f;
  }
  pack_pixels(c.c.pack, w, h, format, type, px, dst);
}

void GLAPIENTRY glClampColor(GLenum target, GLenum clamp) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (clamp != GL_TRUE && clamp != GL_FALSE && clamp != GL_FIXED_ONLY) return c.error(GL_INVALID_ENUM);
  PixelModeState& p = c.s.pixel;
  switch (c.core_profile ? (target == GL_CLAMP_READ_COLOR ? target : GLenum(0)) : target) {
    case GL_CLAMP_READ_COLOR: p.clamp_read = clamp; break;
    case GL_CLAMP_VERTEX_COLOR: p.clamp_vertex = clamp; break;
    case GL_CLAMP_FRAGMENT_COLOR: p.clamp_fragment = clamp; break;
    default: return c.error(GL_INVALID_ENUM);
  }
}

void GLAPIENTRY glDrawPixels(GLsizei w, GLsizei h, GLenum format, GLenum type, const GLvoid* pixels) {
  GL_COMPAT_CONTEXT();
  if (w < 0 || h < 0) return c.error(GL_INVALID_VALUE);
  if (const GLenum e = check_format_type(format, type); e != GL_NO_ERROR) return c.error(e);
  if (format == GL_DEPTH_STENCIL || is_integer_format(format)) return c.error(GL_INVALID_OPERATION);
  std::shared_ptr<Pixels> data;
  if (pixels && w > 0 && h > 0) {
    data = std::make_shared<Pixels>();
    unpack_pixels(c.c.unpack, w, h, format, type, pixels, data->px);
  }
  GL_LISTED(draw_pixels(c, w, h, format, data));
  draw_pixels(c, w, h, format, data);
}

void GLAPIENTRY glCopyPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum type) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(copy_pixels(c, x, y, w, h, type));
  copy_pixels(c, x, y, w, h, type);
}

void GLAPIENTRY glBitmap(GLsizei w, GLsizei h, GLfloat xo, GLfloat yo, GLfloat xm, GLfloat ym,
                         const GLubyte* b) {
  GL_COMPAT_CONTEXT();
  std::shared_ptr<std::vector<uint8_t>> bits;
  if (b && w > 0 && h > 0) {
    bits = std::make_shared<std::vector<uint8_t>>();
    unpack_bitmap(c.c.unpack, w, h, b, *bits);
  }
  GL_LISTED(bitmap(c, w, h, xo, yo, xm, ym, bits));
  bitmap(c, w, h, xo, yo, xm, ym, bits);
}

// Pixel maps (GL 2.1 §3.6.3). Colour component entries given as integers are normalized; index
// entries (I_TO_I, S_TO_S) are the integers themselves, and read back as such.
}  // extern "C"
namespace {
bool valid_map(GLenum m) { return m >= GL_PIXEL_MAP_I_TO_I && m <= GL_PIXEL_MAP_A_TO_A; }
bool index_map(GLenum m) { return m == GL_PIXEL_MAP_I_TO_I || m == GL_PIXEL_MAP_S_TO_S; }
template <class T>
void pixel_map(GLenum map, GLsizei n, const T* values, double scale) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!valid_map(map)) return c.error(GL_INVALID_ENUM);
  if (n < 1 || n > 256) return c.error(GL_INVALID_VALUE);
  if (map <= GL_PIXEL_MAP_I_TO_A && (n & (n - 1))) return c.error(GL_INVALID_VALUE);
  if (!values) return;
  std::vector<float>& m = c.s.pixel_maps[map - GL_PIXEL_MAP_I_TO_I];
  m.resize(size_t(n));
  for (size_t i = 0; i < m.size(); ++i) {
    const double v = index_map(map) ? double(values[i]) : double(values[i]) / scale;
    m[i] = map == GL_PIXEL_MAP_S_TO_S ? float(std::round(v)) : float(v);
  }
}
template <class T>
void get_pixel_map(GLenum map, T* values, double scale) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!valid_map(map)) return c.error(GL_INVALID_ENUM);
  if (!values) return;
  const std::vector<float>& m = c.s.pixel_maps[map - GL_PIXEL_MAP_I_TO_I];
  for (size_t i = 0; i < m.size(); ++i) {
    if (index_map(map) || scale == 1.0) {
      values[i] = T(m[i]);
    } else {
      values[i] = T(std::lround(std::clamp(double(m[i]), 0.0, 1.0) * scale));
    }
  }
}
}  // namespace
extern "C" {

void GLAPIENTRY glPixelMapfv(GLenum map, GLsizei n, const GLfloat* values) { pixel_map(map, n, values, 1.0); }
void GLAPIENTRY glPixelMapuiv(GLenum map, GLsizei n, const GLuint* values) {
  pixel_map(map, n, values, 4294967295.0);
}
void GLAPIENTRY glPixelMapusv(GLenum map, GLsizei n, const GLushort* values) {
  pixel_map(map, n, values, 65535.0);
}
void GLAPIENTRY glGetPixelMapfv(GLenum map, GLfloat* values) { get_pixel_map(map, values, 1.0); }
void GLAPIENTRY glGetPixelMapuiv(GLenum map, GLuint* values) { get_pixel_map(map, values, 4294967295.0); }
void GLAPIENTRY glGetPixelMapusv(GLenum map, GLushort* values) { get_pixel_map(map, values, 65535.0); }

}  // extern "C"
