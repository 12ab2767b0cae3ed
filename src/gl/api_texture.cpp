// Texture objects and images (GL 2.1 §3.8): glGenTextures, glBindTexture, glTexImage2D,
// glTexSubImage2D, glCopyTexImage2D, glCopyTexSubImage2D, glTexParameter, glTexEnv,
// glTexGen and their queries. Only 2D textures are sampled (unit 0); 1D calls are accepted
// and checked but draw nothing.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "api.hpp"
#include "pixels.hpp"

namespace tessel::gl {

namespace {

int max_levels_for(int w, int h) {
  int n = 1;
  while ((w >> n) > 0 || (h >> n) > 0) ++n;
  return n;
}

}  // namespace

// A texture is complete (GL 2.1 §3.8.10) when its base level exists and, for a mipmapping
// minification filter, every level down to 1x1 exists with the halved sizes and the same
// internal format. Builds the gpu texture from the levels.
bool rebuild_texture(TextureObject& t) {
  t.dirty = false;
  t.complete = false;
  t.gpu.reset();
  const int base = std::clamp(t.base_level, 0, kMaxTextureLevels - 1);
  const TextureImage& b = t.levels[size_t(base)];
  if (!b.defined()) return false;
  int count = 1;
  if (t.min_filter != GL_NEAREST && t.min_filter != GL_LINEAR) {
    const int want = std::min(max_levels_for(b.width, b.height), std::max(0, t.max_level - base) + 1);
    for (int i = 1; i < want; ++i) {
      const TextureImage& l = t.levels[size_t(base + i)];
      if (base + i >= kMaxTextureLevels || l.width != std::max(1, b.width >> i) ||
          l.height != std::max(1, b.height >> i) || l.base != b.base)
        return false;
    }
    count = want;
  }
  try {
    auto tex = std::make_unique<gpu::Texture2D>(gpu::Format::RGBA8, b.width, b.height, count);
    for (int i = 0; i < count; ++i) {
      const TextureImage& l = t.levels[size_t(base + i)];
      tex->upload(i, l.rgba.data(), l.rgba.size());
    }
    t.gpu = std::move(tex);
  } catch (const std::exception&) {
    return false;  // treated as incomplete: texturing off for it
  }
  t.complete = true;
  return true;
}

namespace {

TextureObject* target_texture(Context& c, GLenum target) {
  if (target != GL_TEXTURE_2D) {
    c.error(GL_INVALID_ENUM);
    return nullptr;
  }
  return &c.bound_texture();
}

void mark_changed(Context& c, TextureObject& t) {
  c.touch();
  t.dirty = true;
}

bool check_image_args(Context& c, GLint level, GLsizei w, GLsizei h, GLint border) {
  if (level < 0 || level >= kMaxTextureLevels || w < 0 || h < 0 || w > kMaxTextureSize ||
      h > kMaxTextureSize || border != 0) {
    c.error(GL_INVALID_VALUE);
    return false;
  }
  return true;
}

struct ImageData {
  std::vector<glm::vec4> px;
};

// Levels base + 1 down to 1x1 (or max_level) made from the base level (glGenerateMipmap, and
// GL_GENERATE_MIPMAP when the base level changes): each texel is the bilinear sample of the
// level above at its centre, clamped to the edge, rounded to nearest. That is what llvmpipe's
// generation by blits gives: a 2x2 box where the level above has an even size.
void generate_mipmaps(TextureObject& t) {
  const int base = std::clamp(t.base_level, 0, kMaxTextureLevels - 1);
  if (!t.levels[size_t(base)].defined()) return;
  t.dirty = true;
  for (int l = base + 1; l < kMaxTextureLevels && l <= t.max_level; ++l) {
    const TextureImage& src = t.levels[size_t(l - 1)];
    if (src.width == 1 && src.height == 1) break;
    TextureImage& dst = t.levels[size_t(l)];
    dst.width = std::max(1, src.width / 2);
    dst.height = std::max(1, src.height / 2);
    dst.base = src.base;
    dst.internal_format = src.internal_format;
    dst.rgba.assign(size_t(dst.width) * size_t(dst.height) * 4, 0);
    const float kx = float(src.width) / float(dst.width), ky = float(src.height) / float(dst.height);
    for (int y = 0; y < dst.height; ++y) {
      const float sy = (float(y) + 0.5f) * ky - 0.5f;
      const int y0 = std::clamp(int(std::floor(sy)), 0, src.height - 1),
                y1 = std::min(y0 + 1, src.height - 1);
      const float fy = std::clamp(sy - std::floor(sy), 0.0f, 1.0f);
      for (int x = 0; x < dst.width; ++x) {
        const float sx = (float(x) + 0.5f) * kx - 0.5f;
        const int x0 = std::clamp(int(std::floor(sx)), 0, src.width - 1),
                  x1 = std::min(x0 + 1, src.width - 1);
        const float fx = std::clamp(sx - std::floor(sx), 0.0f, 1.0f);
        auto at = [&](int xx, int yy, int k) {
          return float(src.rgba[(size_t(yy) * size_t(src.width) + size_t(xx)) * 4 + size_t(k)]);
        };
        for (int k = 0; k < 4; ++k) {
          const float v = (at(x0, y0, k) * (1 - fx) + at(x1, y0, k) * fx) * (1 - fy) +
                          (at(x0, y1, k) * (1 - fx) + at(x1, y1, k) * fx) * fy;
          dst.rgba[(size_t(y) * size_t(dst.width) + size_t(x)) * 4 + size_t(k)] =
              uint8_t(std::clamp(std::floor(v + 0.5f), 0.0f, 255.0f));
        }
      }
    }
  }
}

void tex_image_2d(Context& c, GLenum target, GLint level, GLint internal, GLsizei w, GLsizei h, GLint border,
                  const std::shared_ptr<ImageData>& data) {
  GL_OUTSIDE_BEGIN();
  if (target == GL_PROXY_TEXTURE_2D) return;
  TextureObject* t = target_texture(c, target);
  if (!t) return;
  BaseFormat base;
  if (!base_format_of(internal, base)) return c.error(GL_INVALID_VALUE);
  if (!check_image_args(c, level, w, h, border)) return;
  mark_changed(c, *t);
  TextureImage& img = t->levels[size_t(level)];
  img.width = w;
  img.height = h;
  img.base = base;
  img.internal_format = GLenum(internal);
  if (data)
    to_texture_rgba8(data->px, base, img.rgba);
  else
    img.rgba.assign(size_t(w) * size_t(h) * 4, 0);
  if (t->generate_mipmap && level == t->base_level) generate_mipmaps(*t);  // GL 1.4 §3.8.8
}

void tex_sub_image_2d(Context& c, GLenum target, GLint level, GLint x, GLint y, GLsizei w, GLsizei h,
                      const std::shared_ptr<ImageData>& data) {
  GL_OUTSIDE_BEGIN();
  TextureObject* t = target_texture(c, target);
  if (!t) return;
  if (level < 0 || level >= kMaxTextureLevels) return c.error(GL_INVALID_VALUE);
  TextureImage& img = t->levels[size_t(level)];
  if (!img.defined()) return c.error(GL_INVALID_OPERATION);
  if (x < 0 || y < 0 || w < 0 || h < 0 || x + w > img.width || y + h > img.height)
    return c.error(GL_INVALID_VALUE);
  if (!data || w == 0 || h == 0) return;
  mark_changed(c, *t);
  std::vector<uint8_t> rgba;
  to_texture_rgba8(data->px, img.base, rgba);
  for (int j = 0; j < h; ++j)
    std::memcpy(&img.rgba[(size_t(y + j) * size_t(img.width) + size_t(x)) * 4],
                &rgba[size_t(j) * size_t(w) * 4], size_t(w) * 4);
  if (t->generate_mipmap && level == t->base_level) generate_mipmaps(*t);
}

// Pixels of the read buffer as floats, rows bottom-up (for glCopyTex*).
std::vector<glm::vec4> read_color(Context& c, GLint x, GLint y, GLsizei w, GLsizei h) {
  c.finish();
  std::vector<glm::vec4> out(size_t(w) * size_t(h), glm::vec4(0.0f));
  gpu::Texture2D* src = c.color_buffer(c.s.pixel.read_buffer);
  if (!src) return out;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const int sx = x + i, sy = y + j;
      if (sx < 0 || sy < 0 || sx >= src->width() || sy >= src->height()) continue;
      out[size_t(j) * size_t(w) + size_t(i)] = src->fetch(0, sx, sy);
    }
  return out;
}

void copy_tex_image_2d(Context& c, GLenum target, GLint level, GLenum internal, GLint x, GLint y, GLsizei w,
                       GLsizei h, GLint border) {
  GL_OUTSIDE_BEGIN();
  TextureObject* t = target_texture(c, target);
  if (!t) return;
  BaseFormat base;
  if (!base_format_of(GLint(internal), base)) return c.error(GL_INVALID_VALUE);
  if (!check_image_args(c, level, w, h, border)) return;
  auto data = std::make_shared<ImageData>();
  data->px = read_color(c, x, y, w, h);
  tex_image_2d(c, target, level, GLint(internal), w, h, border, data);
}

void copy_tex_sub_image_2d(Context& c, GLenum target, GLint level, GLint xo, GLint yo, GLint x, GLint y,
                           GLsizei w, GLsizei h) {
  GL_OUTSIDE_BEGIN();
  auto data = std::make_shared<ImageData>();
  data->px = read_color(c, x, y, std::max(w, 0), std::max(h, 0));
  tex_sub_image_2d(c, target, level, xo, yo, w, h, data);
}

bool valid_min_filter(GLenum f) {
  return f == GL_NEAREST || f == GL_LINEAR || f == GL_NEAREST_MIPMAP_NEAREST ||
         f == GL_LINEAR_MIPMAP_NEAREST || f == GL_NEAREST_MIPMAP_LINEAR || f == GL_LINEAR_MIPMAP_LINEAR;
}
// GL 2.1 §3.8.4 (GL_CLAMP, GL_CLAMP_TO_BORDER and GL_MIRRORED_REPEAT since 1.3/1.4).
bool valid_wrap(GLenum w) {
  return w == GL_REPEAT || w == GL_CLAMP || w == GL_CLAMP_TO_EDGE || w == GL_MIRRORED_REPEAT ||
         w == GL_CLAMP_TO_BORDER;
}

void tex_parameter(Context& c, GLenum target, GLenum pname, Vec4Arg p) {
  GL_OUTSIDE_BEGIN();
  if (target == GL_TEXTURE_1D) return;
  TextureObject* t = target_texture(c, target);
  if (!t) return;
  const GLenum e = GLenum(p[0]);
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER:
      if (!valid_min_filter(e)) return c.error(GL_INVALID_ENUM);
      mark_changed(c, *t);
      t->min_filter = e;
      break;
    case GL_TEXTURE_MAG_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR) return c.error(GL_INVALID_ENUM);
      mark_changed(c, *t);
      t->mag_filter = e;
      break;
    case GL_TEXTURE_WRAP_S:
    case GL_TEXTURE_WRAP_T:
      if (!valid_wrap(e)) return c.error(GL_INVALID_ENUM);
      c.touch();
      (pname == GL_TEXTURE_WRAP_S ? t->wrap_s : t->wrap_t) = e;
      break;
    case GL_TEXTURE_BORDER_COLOR:
      c.touch();
      t->border = glm::clamp(glm::vec4(p[0], p[1], p[2], p[3]), 0.0f, 1.0f);
      break;
    case GL_TEXTURE_PRIORITY: t->priority = std::clamp(p[0], 0.0f, 1.0f); break;
    case GL_TEXTURE_BASE_LEVEL:
      if (p[0] < 0.0f) return c.error(GL_INVALID_VALUE);
      mark_changed(c, *t);
      t->base_level = int(p[0]);
      break;
    case GL_TEXTURE_MAX_LEVEL:
      if (p[0] < 0.0f) return c.error(GL_INVALID_VALUE);
      mark_changed(c, *t);
      t->max_level = int(p[0]);
      break;
    case GL_GENERATE_MIPMAP: t->generate_mipmap = p[0] != 0.0f; break;
    default: c.error(GL_INVALID_ENUM); break;
  }
}

void tex_env(Context& c, GLenum target, GLenum pname, Vec4Arg p) {
  GL_OUTSIDE_BEGIN();
  if (target != GL_TEXTURE_ENV) return c.error(GL_INVALID_ENUM);
  switch (pname) {
    case GL_TEXTURE_ENV_MODE: {
      const GLenum m = GLenum(p[0]);
      if (m != GL_MODULATE && m != GL_REPLACE && m != GL_DECAL && m != GL_BLEND && m != GL_ADD)
        return c.error(GL_INVALID_ENUM);
      c.touch();
      c.s.unit().env_mode = m;
      break;
    }
    case GL_TEXTURE_ENV_COLOR:
      c.touch();
      c.s.unit().env_color = glm::clamp(glm::vec4(p[0], p[1], p[2], p[3]), 0.0f, 1.0f);
      break;
    default: c.error(GL_INVALID_ENUM); break;
  }
}

void tex_gen(Context& c, GLenum coord, GLenum pname, Vec4Arg p) {
  GL_OUTSIDE_BEGIN();
  if (coord < GL_S || coord > GL_Q) return c.error(GL_INVALID_ENUM);
  const size_t i = coord - GL_S;
  switch (pname) {
    case GL_TEXTURE_GEN_MODE: {
      const GLenum m = GLenum(p[0]);
      if (m != GL_OBJECT_LINEAR && m != GL_EYE_LINEAR && m != GL_SPHERE_MAP) return c.error(GL_INVALID_ENUM);
      if (m == GL_SPHERE_MAP && (coord == GL_R || coord == GL_Q)) return c.error(GL_INVALID_ENUM);
      c.touch();
      c.s.unit().gen_mode[i] = m;
      break;
    }
    case GL_OBJECT_PLANE:
      c.touch();
      c.s.unit().object_plane[i] = glm::vec4(p[0], p[1], p[2], p[3]);
      break;
    case GL_EYE_PLANE:
      c.touch();
      // GL 2.1 §2.12.4: (p1 p2 p3 p4) M^-1 with M the model-view matrix when specified.
      c.s.unit().eye_plane[i] = glm::vec4(p[0], p[1], p[2], p[3]) * glm::inverse(c.modelview());
      break;
    default: c.error(GL_INVALID_ENUM); break;
  }
}

template <class T>
Vec4Arg take(const T* v, int n) {
  Vec4Arg a{0.0f, 0.0f, 0.0f, 0.0f};
  if (v)
    for (int i = 0; i < n; ++i) a[size_t(i)] = float(v[i]);
  return a;
}

std::shared_ptr<ImageData> unpack(Context& c, GLsizei w, GLsizei h, GLenum format, GLenum type,
                                  const void* pixels) {
  if (!pixels || w <= 0 || h <= 0) return nullptr;
  auto d = std::make_shared<ImageData>();
  unpack_pixels(c.c.unpack, w, h, format, type, pixels, d->px);
  return d;
}

bool check_format_type(Context& c, GLenum format, GLenum type) {
  if (!valid_pixel_format(format) || !valid_pixel_type(type) || format == GL_DEPTH_COMPONENT ||
      format == GL_STENCIL_INDEX || format == GL_COLOR_INDEX) {
    c.error(GL_INVALID_ENUM);
    return false;
  }
  if (type == GL_BITMAP) {
    c.error(GL_INVALID_ENUM);
    return false;
  }
  return true;
}

}  // namespace
}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glGenTextures(GLsizei n, GLuint* names) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  for (GLsizei i = 0; i < n; ++i) {
    while (c.textures.count(c.next_texture_name)) ++c.next_texture_name;
    const GLuint name = c.next_texture_name++;
    c.textures[name].name = name;
    if (names) names[i] = name;
  }
}
void GLAPIENTRY glDeleteTextures(GLsizei n, const GLuint* names) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  if (!names) return;
  c.touch();
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = names[i];
    if (name == 0) continue;
    for (TextureUnitState& u : c.s.units)
      if (u.bound_2d == name) u.bound_2d = 0;  // GL 2.1 §3.8.12
    c.textures.erase(name);
  }
}
void GLAPIENTRY glBindTexture(GLenum target, GLuint name) {
  GL_CONTEXT();
  auto bind = [target, name](Context& c) {
    GL_OUTSIDE_BEGIN();
    if (target == GL_TEXTURE_1D) return;
    if (target != GL_TEXTURE_2D) return c.error(GL_INVALID_ENUM);
    c.touch();
    TextureObject& t = c.textures[name];
    t.name = name;
    c.s.unit().bound_2d = name;
  };
  GL_LISTED(bind(c));
  bind(c);
}
GLboolean GLAPIENTRY glIsTexture(GLuint name) {
  GL_CONTEXT(GLboolean(GL_FALSE));
  GL_OUTSIDE_BEGIN(GLboolean(GL_FALSE));
  return name != 0 && c.textures.count(name) ? GL_TRUE : GL_FALSE;
}
GLboolean GLAPIENTRY glAreTexturesResident(GLsizei n, const GLuint* names, GLboolean* residences) {
  GL_CONTEXT(GLboolean(GL_FALSE));
  GL_OUTSIDE_BEGIN(GLboolean(GL_FALSE));
  if (n < 0) {
    c.error(GL_INVALID_VALUE);
    return GL_FALSE;
  }
  for (GLsizei i = 0; i < n; ++i)
    if (names && (names[i] == 0 || !c.textures.count(names[i]))) {
      c.error(GL_INVALID_VALUE);
      return GL_FALSE;
    }
  (void)residences;  // all resident: GL leaves the array untouched when returning TRUE
  return GL_TRUE;
}
void GLAPIENTRY glPrioritizeTextures(GLsizei n, const GLuint* names, const GLclampf* priorities) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  for (GLsizei i = 0; i < n && names && priorities; ++i) {
    auto it = c.textures.find(names[i]);
    if (it != c.textures.end() && names[i] != 0) it->second.priority = std::clamp(priorities[i], 0.0f, 1.0f);
  }
}

void GLAPIENTRY glTexImage2D(GLenum target, GLint level, GLint internal, GLsizei w, GLsizei h, GLint border,
                             GLenum format, GLenum type, const GLvoid* pixels) {
  GL_CONTEXT();
  if (!c.compiling_only() && c.in_begin) return c.error(GL_INVALID_OPERATION);
  if (!check_format_type(c, format, type)) return;
  if (!check_image_args(c, level, w, h, border)) return;
  const auto data = unpack(c, w, h, format, type, pixels);
  GL_LISTED(tex_image_2d(c, target, level, internal, w, h, border, data));
  tex_image_2d(c, target, level, internal, w, h, border, data);
}
void GLAPIENTRY glTexImage1D(GLenum target, GLint level, GLint internal, GLsizei w, GLint border,
                             GLenum format, GLenum type, const GLvoid*) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  BaseFormat base;
  if (target != GL_TEXTURE_1D && target != GL_PROXY_TEXTURE_1D) return c.error(GL_INVALID_ENUM);
  if (!check_format_type(c, format, type)) return;
  if (!base_format_of(internal, base) || !check_image_args(c, level, w, 1, border)) return;
}
void GLAPIENTRY glTexSubImage2D(GLenum target, GLint level, GLint x, GLint y, GLsizei w, GLsizei h,
                                GLenum format, GLenum type, const GLvoid* pixels) {
  GL_CONTEXT();
  if (!check_format_type(c, format, type)) return;
  const auto data = unpack(c, w, h, format, type, pixels);
  GL_LISTED(tex_sub_image_2d(c, target, level, x, y, w, h, data));
  tex_sub_image_2d(c, target, level, x, y, w, h, data);
}
void GLAPIENTRY glTexSubImage1D(GLenum target, GLint, GLint, GLsizei, GLenum format, GLenum type,
                                const GLvoid*) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (target != GL_TEXTURE_1D) return c.error(GL_INVALID_ENUM);
  check_format_type(c, format, type);
}
void GLAPIENTRY glCopyTexImage2D(GLenum target, GLint level, GLenum internal, GLint x, GLint y, GLsizei w,
                                 GLsizei h, GLint border) {
  GL_CONTEXT();
  GL_LISTED(copy_tex_image_2d(c, target, level, internal, x, y, w, h, border));
  copy_tex_image_2d(c, target, level, internal, x, y, w, h, border);
}
void GLAPIENTRY glCopyTexSubImage2D(GLenum target, GLint level, GLint xo, GLint yo, GLint x, GLint y,
                                    GLsizei w, GLsizei h) {
  GL_CONTEXT();
  GL_LISTED(copy_tex_sub_image_2d(c, target, level, xo, yo, x, y, w, h));
  copy_tex_sub_image_2d(c, target, level, xo, yo, x, y, w, h);
}
void GLAPIENTRY glCopyTexImage1D(GLenum target, GLint, GLenum, GLint, GLint, GLsizei, GLint) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (target != GL_TEXTURE_1D) c.error(GL_INVALID_ENUM);
}
void GLAPIENTRY glCopyTexSubImage1D(GLenum target, GLint, GLint, GLint, GLint, GLsizei) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (target != GL_TEXTURE_1D) c.error(GL_INVALID_ENUM);
}

void GLAPIENTRY glTexParameterf(GLenum target, GLenum pname, GLfloat v) {
  GL_CONTEXT();
  if (pname == GL_TEXTURE_BORDER_COLOR) return c.error(GL_INVALID_ENUM);
  const Vec4Arg a{v, 0, 0, 0};
  GL_LISTED(tex_parameter(c, target, pname, a));
  tex_parameter(c, target, pname, a);
}
void GLAPIENTRY glTexParameteri(GLenum target, GLenum pname, GLint v) {
  glTexParameterf(target, pname, float(v));
}
void GLAPIENTRY glTexParameterfv(GLenum target, GLenum pname, const GLfloat* v) {
  GL_CONTEXT();
  const Vec4Arg a = take(v, pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1);
  GL_LISTED(tex_parameter(c, target, pname, a));
  tex_parameter(c, target, pname, a);
}
void GLAPIENTRY glTexParameteriv(GLenum target, GLenum pname, const GLint* v) {
  GL_CONTEXT();
  Vec4Arg a = take(v, pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1);
  if (pname == GL_TEXTURE_BORDER_COLOR && v)
    for (int i = 0; i < 4; ++i) a[size_t(i)] = float((2.0 * double(v[i]) + 1.0) / 4294967295.0);
  GL_LISTED(tex_parameter(c, target, pname, a));
  tex_parameter(c, target, pname, a);
}
void GLAPIENTRY glGetTexParameterfv(GLenum target, GLenum pname, GLfloat* out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  TextureObject* t = target_texture(c, target);
  if (!t || !out) return;
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER: out[0] = float(t->min_filter); break;
    case GL_TEXTURE_MAG_FILTER: out[0] = float(t->mag_filter); break;
    case GL_TEXTURE_WRAP_S: out[0] = float(t->wrap_s); break;
    case GL_TEXTURE_WRAP_T: out[0] = float(t->wrap_t); break;
    case GL_TEXTURE_BORDER_COLOR:
      for (int i = 0; i < 4; ++i) out[i] = t->border[i];
      break;
    case GL_TEXTURE_PRIORITY: out[0] = t->priority; break;
    case GL_TEXTURE_RESIDENT: out[0] = 1.0f; break;
    case GL_TEXTURE_BASE_LEVEL: out[0] = float(t->base_level); break;
    case GL_TEXTURE_MAX_LEVEL: out[0] = float(t->max_level); break;
    case GL_GENERATE_MIPMAP: out[0] = t->generate_mipmap ? 1.0f : 0.0f; break;
    default: c.error(GL_INVALID_ENUM); break;
  }
}
void GLAPIENTRY glGetTexParameteriv(GLenum target, GLenum pname, GLint* out) {
  GLfloat f[4] = {0, 0, 0, 0};
  glGetTexParameterfv(target, pname, f);
  if (!out) return;
  const int n = pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1;
  for (int i = 0; i < n; ++i)
    out[i] = pname == GL_TEXTURE_BORDER_COLOR ? GLint(std::lround(double(f[i]) * 2147483647.0)) : GLint(f[i]);
}
void GLAPIENTRY glGetTexLevelParameterfv(GLenum target, GLint level, GLenum pname, GLfloat* out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (target != GL_TEXTURE_2D && target != GL_PROXY_TEXTURE_2D) return c.error(GL_INVALID_ENUM);
  if (level < 0 || level >= kMaxTextureLevels) return c.error(GL_INVALID_VALUE);
  if (!out) return;
  const TextureImage& img = c.bound_texture().levels[size_t(level)];
  const BaseFormat b = img.base;
  const bool d = img.defined();
  auto bits = [&](bool has) { return d && has ? 8.0f : 0.0f; };
  switch (pname) {
    case GL_TEXTURE_WIDTH: out[0] = float(img.width); break;
    case GL_TEXTURE_HEIGHT: out[0] = float(img.height); break;
    case GL_TEXTURE_BORDER: out[0] = 0.0f; break;
    case GL_TEXTURE_INTERNAL_FORMAT: out[0] = d ? float(img.internal_format) : 1.0f; break;
    case GL_TEXTURE_RED_SIZE:
    case GL_TEXTURE_GREEN_SIZE:
    case GL_TEXTURE_BLUE_SIZE: out[0] = bits(b == BaseFormat::RGB || b == BaseFormat::RGBA); break;
    case GL_TEXTURE_ALPHA_SIZE:
      out[0] = bits(b == BaseFormat::Alpha || b == BaseFormat::LuminanceAlpha || b == BaseFormat::RGBA);
      break;
    case GL_TEXTURE_LUMINANCE_SIZE:
      out[0] = bits(b == BaseFormat::Luminance || b == BaseFormat::LuminanceAlpha);
      break;
    case GL_TEXTURE_INTENSITY_SIZE: out[0] = bits(b == BaseFormat::Intensity); break;
    default: c.error(GL_INVALID_ENUM); break;
  }
}
void GLAPIENTRY glGetTexLevelParameteriv(GLenum target, GLint level, GLenum pname, GLint* out) {
  GLfloat f = 0.0f;
  glGetTexLevelParameterfv(target, level, pname, &f);
  if (out) out[0] = GLint(f);
}
void GLAPIENTRY glGetTexImage(GLenum target, GLint level, GLenum format, GLenum type, GLvoid* pixels) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (target != GL_TEXTURE_2D) return c.error(GL_INVALID_ENUM);
  if (level < 0 || level >= kMaxTextureLevels) return c.error(GL_INVALID_VALUE);
  if (!check_format_type(c, format, type)) return;
  const TextureImage& img = c.bound_texture().levels[size_t(level)];
  if (!img.defined() || !pixels) return;
  std::vector<glm::vec4> px(size_t(img.width) * size_t(img.height));
  for (size_t i = 0; i < px.size(); ++i) {
    const uint8_t* p = &img.rgba[i * 4];
    glm::vec4 v(p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f, p[3] / 255.0f);
    // GL 2.1 §6.1.4: luminance is returned in R (G, B zero) for the luminance formats.
    if (img.base == BaseFormat::Luminance || img.base == BaseFormat::LuminanceAlpha ||
        img.base == BaseFormat::Intensity)
      v.g = v.b = 0.0f;
    px[i] = v;
  }
  pack_pixels(c.c.pack, img.width, img.height, format, type, px, pixels);
}

void GLAPIENTRY glTexEnvf(GLenum target, GLenum pname, GLfloat v) {
  GL_CONTEXT();
  if (pname == GL_TEXTURE_ENV_COLOR) return c.error(GL_INVALID_ENUM);
  const Vec4Arg a{v, 0, 0, 0};
  GL_LISTED(tex_env(c, target, pname, a));
  tex_env(c, target, pname, a);
}
void GLAPIENTRY glTexEnvi(GLenum target, GLenum pname, GLint v) { glTexEnvf(target, pname, float(v)); }
void GLAPIENTRY glTexEnvfv(GLenum target, GLenum pname, const GLfloat* v) {
  GL_CONTEXT();
  const Vec4Arg a = take(v, pname == GL_TEXTURE_ENV_COLOR ? 4 : 1);
  GL_LISTED(tex_env(c, target, pname, a));
  tex_env(c, target, pname, a);
}
void GLAPIENTRY glTexEnviv(GLenum target, GLenum pname, const GLint* v) {
  GL_CONTEXT();
  Vec4Arg a = take(v, pname == GL_TEXTURE_ENV_COLOR ? 4 : 1);
  if (pname == GL_TEXTURE_ENV_COLOR && v)
    for (int i = 0; i < 4; ++i) a[size_t(i)] = float((2.0 * double(v[i]) + 1.0) / 4294967295.0);
  GL_LISTED(tex_env(c, target, pname, a));
  tex_env(c, target, pname, a);
}
void GLAPIENTRY glGetTexEnvfv(GLenum target, GLenum pname, GLfloat* out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (target != GL_TEXTURE_ENV) return c.error(GL_INVALID_ENUM);
  if (!out) return;
  if (pname == GL_TEXTURE_ENV_MODE)
    out[0] = float(c.s.unit().env_mode);
  else if (pname == GL_TEXTURE_ENV_COLOR)
    for (int i = 0; i < 4; ++i) out[i] = c.s.unit().env_color[i];
  else
    c.error(GL_INVALID_ENUM);
}
void GLAPIENTRY glGetTexEnviv(GLenum target, GLenum pname, GLint* out) {
  GLfloat f[4] = {0, 0, 0, 0};
  glGetTexEnvfv(target, pname, f);
  if (!out) return;
  if (pname == GL_TEXTURE_ENV_COLOR)
    for (int i = 0; i < 4; ++i) out[i] = GLint(std::lround(double(f[i]) * 2147483647.0));
  else
    out[0] = GLint(f[0]);
}

void GLAPIENTRY glTexGenf(GLenum coord, GLenum pname, GLfloat v) {
  GL_CONTEXT();
  if (pname != GL_TEXTURE_GEN_MODE) return c.error(GL_INVALID_ENUM);
  const Vec4Arg a{v, 0, 0, 0};
  GL_LISTED(tex_gen(c, coord, pname, a));
  tex_gen(c, coord, pname, a);
}
void GLAPIENTRY glTexGeni(GLenum coord, GLenum pname, GLint v) { glTexGenf(coord, pname, float(v)); }
void GLAPIENTRY glTexGend(GLenum coord, GLenum pname, GLdouble v) { glTexGenf(coord, pname, float(v)); }
void GLAPIENTRY glTexGenfv(GLenum coord, GLenum pname, const GLfloat* v) {
  GL_CONTEXT();
  const Vec4Arg a = take(v, pname == GL_TEXTURE_GEN_MODE ? 1 : 4);
  GL_LISTED(tex_gen(c, coord, pname, a));
  tex_gen(c, coord, pname, a);
}
void GLAPIENTRY glTexGeniv(GLenum coord, GLenum pname, const GLint* v) {
  GL_CONTEXT();
  const Vec4Arg a = take(v, pname == GL_TEXTURE_GEN_MODE ? 1 : 4);
  GL_LISTED(tex_gen(c, coord, pname, a));
  tex_gen(c, coord, pname, a);
}
void GLAPIENTRY glTexGendv(GLenum coord, GLenum pname, const GLdouble* v) {
  GL_CONTEXT();
  const Vec4Arg a = take(v, pname == GL_TEXTURE_GEN_MODE ? 1 : 4);
  GL_LISTED(tex_gen(c, coord, pname, a));
  tex_gen(c, coord, pname, a);
}
void GLAPIENTRY glGetTexGenfv(GLenum coord, GLenum pname, GLfloat* out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (coord < GL_S || coord > GL_Q) return c.error(GL_INVALID_ENUM);
  if (!out) return;
  const size_t i = coord - GL_S;
  switch (pname) {
    case GL_TEXTURE_GEN_MODE: out[0] = float(c.s.unit().gen_mode[i]); break;
    case GL_OBJECT_PLANE:
      for (int k = 0; k < 4; ++k) out[k] = c.s.unit().object_plane[i][k];
      break;
    case GL_EYE_PLANE:
      for (int k = 0; k < 4; ++k) out[k] = c.s.unit().eye_plane[i][k];
      break;
    default: c.error(GL_INVALID_ENUM); break;
  }
}
void GLAPIENTRY glGetTexGeniv(GLenum coord, GLenum pname, GLint* out) {
  GLfloat f[4] = {0, 0, 0, 0};
  glGetTexGenfv(coord, pname, f);
  if (out)
    for (int i = 0; i < (pname == GL_TEXTURE_GEN_MODE ? 1 : 4); ++i) out[i] = GLint(f[i]);
}
void GLAPIENTRY glGetTexGendv(GLenum coord, GLenum pname, GLdouble* out) {
  GLfloat f[4] = {0, 0, 0, 0};
  glGetTexGenfv(coord, pname, f);
  if (out)
    for (int i = 0; i < (pname == GL_TEXTURE_GEN_MODE ? 1 : 4); ++i) out[i] = f[i];
}

// GL 3.0 §3.8.10: the mipmap levels of the bound texture made from its base level.
void GLAPIENTRY glGenerateMipmap(GLenum target) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (target != GL_TEXTURE_2D) return c.error(GL_INVALID_ENUM);
  TextureObject& t = c.bound_texture();
  if (!t.levels[size_t(std::clamp(t.base_level, 0, kMaxTextureLevels - 1))].defined())
    return c.error(GL_INVALID_OPERATION);
  mark_changed(c, t);
  generate_mipmaps(t);
}

// The texture image units: fixed-function texturing reads unit 0; GLSL samplers read any
// (GL 3.3 §3.8). The fixed-function coordinate sets beyond unit 0 are not drawn.
void GLAPIENTRY glActiveTexture(GLenum unit) {
  GL_CONTEXT();
  auto set = [unit](Context& c) {
    GL_OUTSIDE_BEGIN();
    if (unit < GL_TEXTURE0 || unit >= GL_TEXTURE0 + kMaxTextureUnits) return c.error(GL_INVALID_ENUM);
    c.s.active_unit = unit - GL_TEXTURE0;
  };
  GL_LISTED(set(c));
  set(c);
}
void GLAPIENTRY glClientActiveTexture(GLenum unit) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (unit != GL_TEXTURE0) return c.error(GL_INVALID_ENUM);  // GL_MAX_TEXTURE_COORDS is 1
  c.c.client_active_unit = unit - GL_TEXTURE0;
}

}  // extern "C"
