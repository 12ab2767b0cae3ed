// Texture parameters and sampler objects (GL 3.3 compatibility §3.8.2, §3.8.8, §6.1.3,
// §6.1.5): glTexParameter*, glSamplerParameter*, glGenSamplers ... glBindSampler, and
// glGetTexParameter*, glGetSamplerParameter*, glGetTexLevelParameter*.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>

#include "api.hpp"
#include "compressed.hpp"

namespace tessel::gl {

namespace {

// A parameter as the call gave it: up to four values, and whether they came as integers
// (glTexParameteriv's border colour is normalized; the I forms' are not).
struct Param {
  std::array<double, 4> v{};
  enum class From : uint8_t { Float, Int, PureInt } from = From::Float;
};

bool vector_pname(GLenum pname) {
  return pname == GL_TEXTURE_BORDER_COLOR || pname == GL_TEXTURE_SWIZZLE_RGBA;
}

bool valid_compare_func(GLenum f) { return f >= GL_NEVER && f <= GL_ALWAYS; }

bool valid_swizzle(GLenum s) {
  return s == GL_RED || s == GL_GREEN || s == GL_BLUE || s == GL_ALPHA || s == GL_ZERO || s == GL_ONE;
}

// Sets a parameter that both textures and samplers have. Returns GL_NO_ERROR, an error, or
// GL_INVALID_INDEX when the name is not a sampler parameter. `rect`: a rectangle texture
// (no mipmap filters, no repeat, §3.8.5).
GLenum set_sampling(SamplerParams& p, GLenum pname, const Param& a, bool core, bool rect) {
  const GLenum e = enum_arg(a.v[0]);
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR && e != GL_NEAREST_MIPMAP_NEAREST &&
          e != GL_LINEAR_MIPMAP_NEAREST && e != GL_NEAREST_MIPMAP_LINEAR && e != GL_LINEAR_MIPMAP_LINEAR)
        return GL_INVALID_ENUM;
      if (rect && e != GL_NEAREST && e != GL_LINEAR) return GL_INVALID_ENUM;
      p.min_filter = e;
      return GL_NO_ERROR;
    case GL_TEXTURE_MAG_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR) return GL_INVALID_ENUM;
      p.mag_filter = e;
      return GL_NO_ERROR;
    case GL_TEXTURE_WRAP_S:
    case GL_TEXTURE_WRAP_T:
    case GL_TEXTURE_WRAP_R: {
      const bool ok = e == GL_REPEAT || e == GL_CLAMP_TO_EDGE || e == GL_MIRRORED_REPEAT ||
                      e == GL_CLAMP_TO_BORDER || (e == GL_CLAMP && !core);
      if (!ok || (rect && (e == GL_REPEAT || e == GL_MIRRORED_REPEAT))) return GL_INVALID_ENUM;
      (pname == GL_TEXTURE_WRAP_S ? p.wrap_s : pname == GL_TEXTURE_WRAP_T ? p.wrap_t : p.wrap_r) = e;
      return GL_NO_ERROR;
    }
    case GL_TEXTURE_BORDER_COLOR:
      for (int k = 0; k < 4; ++k) {
        double x = a.v[size_t(k)];
        if (a.from == Param::From::Int) x = (2.0 * x + 1.0) / 4294967295.0;
        // Normalized (float) border colours are clamped to [0, 1] in GL 3.3 (§3.8.8).
        if (a.from != Param::From::PureInt) x = std::clamp(x, 0.0, 1.0);
        p.border[k] = float(x);
      }
      return GL_NO_ERROR;
    case GL_TEXTURE_MIN_LOD: p.min_lod = float(a.v[0]); return GL_NO_ERROR;
    case GL_TEXTURE_MAX_LOD: p.max_lod = float(a.v[0]); return GL_NO_ERROR;
    case GL_TEXTURE_LOD_BIAS: p.lod_bias = float(a.v[0]); return GL_NO_ERROR;
    case GL_TEXTURE_COMPARE_MODE:
      if (e != GL_NONE && e != GL_COMPARE_REF_TO_TEXTURE) return GL_INVALID_ENUM;
      p.compare_mode = e;
      return GL_NO_ERROR;
    case GL_TEXTURE_COMPARE_FUNC:
      if (!valid_compare_func(e)) return GL_INVALID_ENUM;
      p.compare_func = e;
      return GL_NO_ERROR;
    default: return GL_INVALID_INDEX;
  }
}

// Reads a parameter both have into `out` (4 values); false when the name is not one.
bool get_sampling(const SamplerParams& p, GLenum pname, std::array<double, 4>& out) {
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER: out[0] = p.min_filter; return true;
    case GL_TEXTURE_MAG_FILTER: out[0] = p.mag_filter; return true;
    case GL_TEXTURE_WRAP_S: out[0] = p.wrap_s; return true;
    case GL_TEXTURE_WRAP_T: out[0] = p.wrap_t; return true;
    case GL_TEXTURE_WRAP_R: out[0] = p.wrap_r; return true;
    case GL_TEXTURE_BORDER_COLOR:
      for (int k = 0; k < 4; ++k) out[size_t(k)] = p.border[k];
      return true;
    case GL_TEXTURE_MIN_LOD: out[0] = p.min_lod; return true;
    case GL_TEXTURE_MAX_LOD: out[0] = p.max_lod; return true;
    case GL_TEXTURE_LOD_BIAS: out[0] = p.lod_bias; return true;
    case GL_TEXTURE_COMPARE_MODE: out[0] = p.compare_mode; return true;
    case GL_TEXTURE_COMPARE_FUNC: out[0] = p.compare_func; return true;
    default: return false;
  }
}

// The texture of a glTexParameter/glGetTexParameter target (GL_INVALID_ENUM: null).
TextureObject* param_texture(Context& c, GLenum target) {
  TexTarget t;
  if (!tex_target_of(target, t) || t == TexTarget::Buffer) {
    c.error(GL_INVALID_ENUM);
    return nullptr;
  }
  return &c.bound_texture(t);
}

void tex_parameter(Context& c, GLenum target, GLenum pname, Param a) {
  GL_OUTSIDE_BEGIN();
  TextureObject* t = param_texture(c, target);
  if (!t) return;
  const bool rect = t->target == TexTarget::Rect;
  SamplerParams p = t->sampler;
  const GLenum e = set_sampling(p, pname, a, c.core_profile, rect);
  if (e != GL_INVALID_INDEX) {
    // Multisample textures have no sampling state (GL 3.3 §3.8.8; Mesa: GL_INVALID_ENUM).
    if (is_multisample(t->target)) return c.error(GL_INVALID_ENUM);
    if (e != GL_NO_ERROR) return c.error(e);
    c.touch();
    t->sampler = p;
    return;
  }
  const GLenum v = enum_arg(a.v[0]);
  switch (pname) {
    case GL_TEXTURE_BASE_LEVEL:
    case GL_TEXTURE_MAX_LEVEL: {
      if (a.v[0] < 0.0) return c.error(GL_INVALID_VALUE);
      if ((rect || is_multisample(t->target)) && pname == GL_TEXTURE_BASE_LEVEL && a.v[0] != 0.0)
        return c.error(GL_INVALID_OPERATION);
      pull_rendered(c, *t);
      c.touch();
      const int level = int(std::min(a.v[0], 1e9));
      (pname == GL_TEXTURE_BASE_LEVEL ? t->base_level : t->max_level) = level;
      t->dirty = true;
      return;
    }
    case GL_TEXTURE_SWIZZLE_R:
    case GL_TEXTURE_SWIZZLE_G:
    case GL_TEXTURE_SWIZZLE_B:
    case GL_TEXTURE_SWIZZLE_A:
      if (!valid_swizzle(v)) return c.error(GL_INVALID_ENUM);
      c.touch();
      t->swizzle[pname - GL_TEXTURE_SWIZZLE_R] = v;
      return;
    case GL_TEXTURE_SWIZZLE_RGBA:
      for (int k = 0; k < 4; ++k)
        if (!valid_swizzle(enum_arg(a.v[size_t(k)]))) return c.error(GL_INVALID_ENUM);
      c.touch();
      for (int k = 0; k < 4; ++k) t->swizzle[size_t(k)] = enum_arg(a.v[size_t(k)]);
      return;
    case GL_DEPTH_TEXTURE_MODE:
      if (c.core_profile) return c.error(GL_INVALID_ENUM);
      if (v != GL_LUMINANCE && v != GL_INTENSITY && v != GL_ALPHA && v != GL_RED)
        return c.error(GL_INVALID_ENUM);
      c.touch();
      t->depth_mode = v;
      return;
    case GL_GENERATE_MIPMAP:
      if (c.core_profile) return c.error(GL_INVALID_ENUM);
      t->generate_mipmap = a.v[0] != 0.0;
      return;
    case GL_TEXTURE_PRIORITY:
      if (c.core_profile) return c.error(GL_INVALID_ENUM);
      t->priority = float(std::clamp(a.v[0], 0.0, 1.0));
      return;
    default: return c.error(GL_INVALID_ENUM);
  }
}

// The values of a texture parameter (GL_INVALID_ENUM: false).
bool get_tex_parameter(Context& c, GLenum target, GLenum pname, std::array<double, 4>& out) {
  if (c.in_begin) {
    c.error(GL_INVALID_OPERATION);
    return false;
  }
  TextureObject* t = param_texture(c, target);
  if (!t) return false;
  if (get_sampling(t->sampler, pname, out)) return true;
  switch (pname) {
    case GL_TEXTURE_BASE_LEVEL: out[0] = t->base_level; return true;
    case GL_TEXTURE_MAX_LEVEL: out[0] = t->max_level; return true;
    case GL_TEXTURE_SWIZZLE_R:
    case GL_TEXTURE_SWIZZLE_G:
    case GL_TEXTURE_SWIZZLE_B:
    case GL_TEXTURE_SWIZZLE_A: out[0] = t->swizzle[pname - GL_TEXTURE_SWIZZLE_R]; return true;
    case GL_TEXTURE_SWIZZLE_RGBA:
      for (int k = 0; k < 4; ++k) out[size_t(k)] = t->swizzle[size_t(k)];
      return true;
    case GL_DEPTH_TEXTURE_MODE:
      if (c.core_profile) break;
      out[0] = t->depth_mode;
      return true;
    case GL_GENERATE_MIPMAP:
      if (c.core_profile) break;
      out[0] = t->generate_mipmap ? 1 : 0;
      return true;
    case GL_TEXTURE_PRIORITY:
      if (c.core_profile) break;
      out[0] = t->priority;
      return true;
    case GL_TEXTURE_RESIDENT:
      if (c.core_profile) break;
      out[0] = 1;
      return true;
    default: break;
  }
  c.error(GL_INVALID_ENUM);
  return false;
}

int values_of(GLenum pname) { return vector_pname(pname) ? 4 : 1; }

template <class T>
void put_values(GLenum pname, const std::array<double, 4>& v, T* out, Param::From as) {
  if (!out) return;
  for (int k = 0; k < values_of(pname); ++k) {
    double x = v[size_t(k)];
    if constexpr (std::is_integral_v<T>) {
      // glGet*iv of a normalized colour maps [0, 1] to the integer range (GL 3.3 §6.1.2).
      if (pname == GL_TEXTURE_BORDER_COLOR && as == Param::From::Int) x = x * 2147483647.0;
      out[k] = T(std::llround(x));
    } else {
      out[k] = T(x);
    }
  }
}

template <class T>
Param param_of(const T* v, GLenum pname, Param::From from) {
  Param a;
  a.from = from;
  if (v)
    for (int k = 0; k < values_of(pname); ++k) a.v[size_t(k)] = double(v[k]);
  return a;
}

// --- sampler objects (GL 3.3 §3.8.2) ---

SamplerObject* sampler_object(Context& c, GLuint name) {
  auto it = c.samplers.find(name);
  if (name == 0 || it == c.samplers.end()) return nullptr;
  if (!it->second) {
    it->second = std::make_shared<SamplerObject>();
    it->second->name = name;
  }
  return it->second.get();
}

void sampler_parameter(Context& c, GLuint sampler, GLenum pname, const Param& a) {
  SamplerObject* s = sampler_object(c, sampler);
  if (!s) return c.error(GL_INVALID_OPERATION);
  SamplerParams p = s->p;
  const GLenum e = set_sampling(p, pname, a, c.core_profile, false);
  if (e == GL_INVALID_INDEX) return c.error(GL_INVALID_ENUM);
  if (e != GL_NO_ERROR) return c.error(e);
  c.touch();
  s->p = p;
}

bool get_sampler_parameter(Context& c, GLuint sampler, GLenum pname, std::array<double, 4>& out) {
  SamplerObject* s = sampler_object(c, sampler);
  if (!s) {
    c.error(GL_INVALID_OPERATION);
    return false;
  }
  if (get_sampling(s->p, pname, out)) return true;
  c.error(GL_INVALID_ENUM);
  return false;
}

// --- level parameters (§6.1.3) ---

bool level_target(GLenum target, TexTarget& t, int& face, bool& proxy) {
  face = 0;
  proxy = false;
  switch (target) {
    case GL_PROXY_TEXTURE_1D:
      proxy = true;
      t = TexTarget::T1D;
      return true;
    case GL_PROXY_TEXTURE_2D:
      proxy = true;
      t = TexTarget::T2D;
      return true;
    case GL_PROXY_TEXTURE_3D:
      proxy = true;
      t = TexTarget::T3D;
      return true;
    case GL_PROXY_TEXTURE_CUBE_MAP:
      proxy = true;
      t = TexTarget::Cube;
      return true;
    case GL_PROXY_TEXTURE_1D_ARRAY:
      proxy = true;
      t = TexTarget::T1DArray;
      return true;
    case GL_PROXY_TEXTURE_2D_ARRAY:
      proxy = true;
      t = TexTarget::T2DArray;
      return true;
    case GL_PROXY_TEXTURE_RECTANGLE:
      proxy = true;
      t = TexTarget::Rect;
      return true;
    case GL_PROXY_TEXTURE_2D_MULTISAMPLE:
      proxy = true;
      t = TexTarget::T2DMS;
      return true;
    case GL_PROXY_TEXTURE_2D_MULTISAMPLE_ARRAY:
      proxy = true;
      t = TexTarget::T2DMSArray;
      return true;
    case GL_TEXTURE_CUBE_MAP: return false;
    default:
      if (target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z) {
        t = TexTarget::Cube;
        face = int(target - GL_TEXTURE_CUBE_MAP_POSITIVE_X);
        return true;
      }
      return tex_target_of(target, t);
  }
}

bool get_level_parameter(Context& c, GLenum target, GLint level, GLenum pname, double& out) {
  if (c.in_begin) {
    c.error(GL_INVALID_OPERATION);
    return false;
  }
  TexTarget tt;
  int face;
  bool proxy;
  if (!level_target(target, tt, face, proxy)) {
    c.error(GL_INVALID_ENUM);
    return false;
  }
  // §6.1.3: rectangle, buffer and multisample textures have level 0 only.
  if (level < 0 || level >= kMaxTextureLevels ||
      ((tt == TexTarget::Rect || tt == TexTarget::Buffer || is_multisample(tt)) && level != 0)) {
    c.error(GL_INVALID_VALUE);
    return false;
  }
  TextureObject* t = &c.bound_texture(tt);
  if (proxy) {
    TextureRef& r = c.proxy_textures[size_t(tt)];
    if (!r) r = make_texture(0, tt);
    t = r.get();
  }
  // The image's sizes and format (not its texels); a buffer texture's from its buffer.
  TextureImage img;
  if (tt == TexTarget::Buffer) {
    if (t->buffer && level == 0) {
      img.fmt = t->buffer_format;
      img.width = int(t->buffer->data.size() / size_t(t->buffer_texel.bytes()));
      img.height = img.depth = 1;
    }
  } else {
    const TextureImage& src = t->image(face, level);
    img.width = src.width, img.height = src.height, img.depth = src.depth;
    img.fmt = src.fmt;
  }
  const bool d = img.defined();
  const TexFormat& f = img.fmt;
  auto bits = [&](uint8_t b) { return d ? double(b) : 0.0; };
  auto type = [&](uint8_t b) { return d && b ? double(f.component_type()) : double(GL_NONE); };
  switch (pname) {
    case GL_TEXTURE_WIDTH: out = d ? img.width : 0; return true;
    case GL_TEXTURE_HEIGHT: out = d ? img.height : 0; return true;
    case GL_TEXTURE_DEPTH: out = d ? img.depth : 0; return true;
    case GL_TEXTURE_BORDER: out = 0; return true;
    case GL_TEXTURE_INTERNAL_FORMAT:
      out = d ? double(f.internal) : (c.core_profile ? GL_RGBA : 1.0);
      return true;
    case GL_TEXTURE_RED_SIZE: out = bits(f.r); return true;
    case GL_TEXTURE_GREEN_SIZE: out = bits(f.g); return true;
    case GL_TEXTURE_BLUE_SIZE: out = bits(f.b); return true;
    case GL_TEXTURE_ALPHA_SIZE: out = bits(f.a); return true;
    case GL_TEXTURE_DEPTH_SIZE: out = bits(f.depth); return true;
    case GL_TEXTURE_STENCIL_SIZE: out = bits(f.stencil); return true;
    case GL_TEXTURE_SHARED_SIZE: out = d && f.shared_exponent ? 5 : 0; return true;
    case GL_TEXTURE_RED_TYPE: out = type(f.r); return true;
    case GL_TEXTURE_GREEN_TYPE: out = type(f.g); return true;
    case GL_TEXTURE_BLUE_TYPE: out = type(f.b); return true;
    case GL_TEXTURE_ALPHA_TYPE: out = type(f.a); return true;
    case GL_TEXTURE_DEPTH_TYPE: out = type(f.depth); return true;
    case GL_TEXTURE_COMPRESSED: out = d && f.rgtc() ? 1 : 0; return true;
    case GL_TEXTURE_COMPRESSED_IMAGE_SIZE:
      if (d && f.rgtc()) {
        out = double(compressed_bytes(f, img.width, img.height, img.depth));
        return true;
      }
      c.error(GL_INVALID_OPERATION);
      return false;
    case GL_TEXTURE_BUFFER_DATA_STORE_BINDING: out = t->buffer ? t->buffer->name : 0; return true;
    case GL_TEXTURE_SAMPLES: out = d && is_multisample(tt) ? t->samples : 0; return true;
    case GL_TEXTURE_FIXED_SAMPLE_LOCATIONS:
      out = d && is_multisample(tt) ? t->fixed_sample_locations : GL_TRUE;
      return true;
    default: break;
  }
  if (!c.core_profile) switch (pname) {
      case GL_TEXTURE_LUMINANCE_SIZE: out = bits(f.l); return true;
      case GL_TEXTURE_INTENSITY_SIZE: out = bits(f.i); return true;
      case GL_TEXTURE_LUMINANCE_TYPE: out = type(f.l); return true;
      case GL_TEXTURE_INTENSITY_TYPE: out = type(f.i); return true;
      default: break;
    }
  c.error(GL_INVALID_ENUM);
  return false;
}

}  // namespace
}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glTexParameterf(GLenum target, GLenum pname, GLfloat v) {
  GL_CONTEXT();
  if (vector_pname(pname)) return c.error(GL_INVALID_ENUM);
  const Param a = param_of(&v, pname, Param::From::Float);
  GL_LISTED(tex_parameter(c, target, pname, a));
  tex_parameter(c, target, pname, a);
}
void GLAPIENTRY glTexParameteri(GLenum target, GLenum pname, GLint v) {
  GL_CONTEXT();
  if (vector_pname(pname)) return c.error(GL_INVALID_ENUM);
  const Param a = param_of(&v, pname, Param::From::Int);
  GL_LISTED(tex_parameter(c, target, pname, a));
  tex_parameter(c, target, pname, a);
}
void GLAPIENTRY glTexParameterfv(GLenum target, GLenum pname, const GLfloat* v) {
  GL_CONTEXT();
  const Param a = param_of(v, pname, Param::From::Float);
  GL_LISTED(tex_parameter(c, target, pname, a));
  tex_parameter(c, target, pname, a);
}
void GLAPIENTRY glTexParameteriv(GLenum target, GLenum pname, const GLint* v) {
  GL_CONTEXT();
  const Param a = param_of(v, pname, Param::From::Int);
  GL_LISTED(tex_parameter(c, target, pname, a));
  tex_parameter(c, target, pname, a);
}
void GLAPIENTRY glTexParameterIiv(GLenum target, GLenum pname, const GLint* v) {
  GL_CONTEXT();
  const Param a = param_of(v, pname, Param::From::PureInt);
  tex_parameter(c, target, pname, a);
}
void GLAPIENTRY glTexParameterIuiv(GLenum target, GLenum pname, const GLuint* v) {
  GL_CONTEXT();
  const Param a = param_of(v, pname, Param::From::PureInt);
  tex_parameter(c, target, pname, a);
}
void GLAPIENTRY glGetTexParameterfv(GLenum target, GLenum pname, GLfloat* out) {
  GL_CONTEXT();
  std::array<double, 4> v{};
  if (get_tex_parameter(c, target, pname, v)) put_values(pname, v, out, Param::From::Float);
}
void GLAPIENTRY glGetTexParameteriv(GLenum target, GLenum pname, GLint* out) {
  GL_CONTEXT();
  std::array<double, 4> v{};
  if (get_tex_parameter(c, target, pname, v)) put_values(pname, v, out, Param::From::Int);
}
void GLAPIENTRY glGetTexParameterIiv(GLenum target, GLenum pname, GLint* out) {
  GL_CONTEXT();
  std::array<double, 4> v{};
  if (get_tex_parameter(c, target, pname, v)) put_values(pname, v, out, Param::From::PureInt);
}
void GLAPIENTRY glGetTexParameterIuiv(GLenum target, GLenum pname, GLuint* out) {
  GL_CONTEXT();
  std::array<double, 4> v{};
  if (get_tex_parameter(c, target, pname, v)) put_values(pname, v, out, Param::From::PureInt);
}
void GLAPIENTRY glGetTexLevelParameterfv(GLenum target, GLint level, GLenum pname, GLfloat* out) {
  GL_CONTEXT();
  double v = 0.0;
  if (get_level_parameter(c, target, level, pname, v) && out) out[0] = float(v);
}
void GLAPIENTRY glGetTexLevelParameteriv(GLenum target, GLint level, GLenum pname, GLint* out) {
  GL_CONTEXT();
  double v = 0.0;
  if (get_level_parameter(c, target, level, pname, v) && out) out[0] = GLint(v);
}

void GLAPIENTRY glGenSamplers(GLsizei n, GLuint* names) {
  GL_CONTEXT();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = fresh_name(c.samplers, c.next_sampler_name);
    // GL 3.3 §3.8.2: glGenSamplers makes the objects (unlike textures, which wait for a bind).
    auto s = std::make_shared<SamplerObject>();
    s->name = name;
    c.samplers[name] = s;
    if (names) names[i] = name;
  }
}
void GLAPIENTRY glDeleteSamplers(GLsizei n, const GLuint* names) {
  GL_CONTEXT();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  if (!names) return;
  c.touch();
  for (GLsizei i = 0; i < n; ++i) {
    auto it = c.samplers.find(names[i]);
    if (names[i] == 0 || it == c.samplers.end()) continue;
    for (TextureUnitState& u : c.s.units)
      if (u.sampler && u.sampler->name == names[i]) u.sampler = nullptr;
    c.samplers.erase(it);
  }
}
GLboolean GLAPIENTRY glIsSampler(GLuint name) {
  GL_CONTEXT(GLboolean(GL_FALSE));
  return name != 0 && c.samplers.count(name) ? GL_TRUE : GL_FALSE;
}
void GLAPIENTRY glBindSampler(GLuint unit, GLuint sampler) {
  GL_CONTEXT();
  if (unit >= GLuint(kMaxTextureUnits)) return c.error(GL_INVALID_VALUE);
  if (sampler == 0) {
    c.touch();
    c.s.units[unit].sampler = nullptr;
    return;
  }
  if (!sampler_object(c, sampler)) return c.error(GL_INVALID_OPERATION);
  c.touch();
  c.s.units[unit].sampler = c.samplers[sampler];
}
void GLAPIENTRY glSamplerParameteri(GLuint s, GLenum pname, GLint v) {
  GL_CONTEXT();
  if (vector_pname(pname)) return c.error(GL_INVALID_ENUM);
  sampler_parameter(c, s, pname, param_of(&v, pname, Param::From::Int));
}
void GLAPIENTRY glSamplerParameterf(GLuint s, GLenum pname, GLfloat v) {
  GL_CONTEXT();
  if (vector_pname(pname)) return c.error(GL_INVALID_ENUM);
  sampler_parameter(c, s, pname, param_of(&v, pname, Param::From::Float));
}
void GLAPIENTRY glSamplerParameteriv(GLuint s, GLenum pname, const GLint* v) {
  GL_CONTEXT();
  sampler_parameter(c, s, pname, param_of(v, pname, Param::From::Int));
}
void GLAPIENTRY glSamplerParameterfv(GLuint s, GLenum pname, const GLfloat* v) {
  GL_CONTEXT();
  sampler_parameter(c, s, pname, param_of(v, pname, Param::From::Float));
}
void GLAPIENTRY glSamplerParameterIiv(GLuint s, GLenum pname, const GLint* v) {
  GL_CONTEXT();
  sampler_parameter(c, s, pname, param_of(v, pname, Param::From::PureInt));
}
void GLAPIENTRY glSamplerParameterIuiv(GLuint s, GLenum pname, const GLuint* v) {
  GL_CONTEXT();
  sampler_parameter(c, s, pname, param_of(v, pname, Param::From::PureInt));
}
void GLAPIENTRY glGetSamplerParameteriv(GLuint s, GLenum pname, GLint* out) {
  GL_CONTEXT();
  std::array<double, 4> v{};
  if (get_sampler_parameter(c, s, pname, v)) put_values(pname, v, out, Param::From::Int);
}
void GLAPIENTRY glGetSamplerParameterfv(GLuint s, GLenum pname, GLfloat* out) {
  GL_CONTEXT();
  std::array<double, 4> v{};
  if (get_sampler_parameter(c, s, pname, v)) put_values(pname, v, out, Param::From::Float);
}
void GLAPIENTRY glGetSamplerParameterIiv(GLuint s, GLenum pname, GLint* out) {
  GL_CONTEXT();
  std::array<double, 4> v{};
  if (get_sampler_parameter(c, s, pname, v)) put_values(pname, v, out, Param::From::PureInt);
}
void GLAPIENTRY glGetSamplerParameterIuiv(GLuint s, GLenum pname, GLuint* out) {
  GL_CONTEXT();
  std::array<double, 4> v{};
  if (get_sampler_parameter(c, s, pname, v)) put_values(pname, v, out, Param::From::PureInt);
}

}  // extern "C"
