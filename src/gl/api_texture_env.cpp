// The texture environment and coordinate generation (GL 2.1 §3.8.13, §2.12.4): glTexEnv,
// glTexGen and their queries, and the active texture unit.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <algorithm>
#include <cmath>

#include "api.hpp"

namespace tessel::gl {

namespace {

bool combine_function(GLenum f, bool rgb) {
  switch (f) {
    case GL_REPLACE:
    case GL_MODULATE:
    case GL_ADD:
    case GL_ADD_SIGNED:
    case GL_INTERPOLATE:
    case GL_SUBTRACT: return true;
    case GL_DOT3_RGB:
    case GL_DOT3_RGBA: return rgb;
    default: return false;
  }
}

bool combine_source(GLenum s) {
  return s == GL_TEXTURE || s == GL_CONSTANT || s == GL_PRIMARY_COLOR || s == GL_PREVIOUS ||
         (s >= GL_TEXTURE0 && s < GLenum(GL_TEXTURE0 + kMaxTexCoords));
}

void tex_env(Context& c, GLenum target, GLenum pname, Vec4Arg p) {
  GL_OUTSIDE_BEGIN();
  // GL 1.4 §3.8.8: the unit's texture LOD bias; GL 2.0 §3.3.1: the point sprite coordinates.
  if (target == GL_TEXTURE_FILTER_CONTROL) {
    if (pname != GL_TEXTURE_LOD_BIAS) return c.error(GL_INVALID_ENUM);
    c.touch();
    c.s.unit().lod_bias = p[0];
    return;
  }
  if (target == GL_POINT_SPRITE) {
    if (pname != GL_COORD_REPLACE) return c.error(GL_INVALID_ENUM);
    if (p[0] != 0.0f && p[0] != 1.0f) return c.error(GL_INVALID_VALUE);
    c.touch();
    c.s.unit().coord_replace = p[0] != 0.0f;
    return;
  }
  if (target != GL_TEXTURE_ENV) return c.error(GL_INVALID_ENUM);
  TextureUnitState& u = c.s.unit();
  const GLenum e = enum_arg(p[0]);
  if (pname >= GL_SRC0_RGB && pname <= GL_SRC2_RGB) {
    if (!combine_source(e)) return c.error(GL_INVALID_ENUM);
    c.touch();
    u.src_rgb[pname - GL_SRC0_RGB] = e;
    return;
  }
  if (pname >= GL_SRC0_ALPHA && pname <= GL_SRC2_ALPHA) {
    if (!combine_source(e)) return c.error(GL_INVALID_ENUM);
    c.touch();
    u.src_alpha[pname - GL_SRC0_ALPHA] = e;
    return;
  }
  if (pname >= GL_OPERAND0_RGB && pname <= GL_OPERAND2_RGB) {
    if (e != GL_SRC_COLOR && e != GL_ONE_MINUS_SRC_COLOR && e != GL_SRC_ALPHA && e != GL_ONE_MINUS_SRC_ALPHA)
      return c.error(GL_INVALID_ENUM);
    c.touch();
    u.op_rgb[pname - GL_OPERAND0_RGB] = e;
    return;
  }
  if (pname >= GL_OPERAND0_ALPHA && pname <= GL_OPERAND2_ALPHA) {
    if (e != GL_SRC_ALPHA && e != GL_ONE_MINUS_SRC_ALPHA) return c.error(GL_INVALID_ENUM);
    c.touch();
    u.op_alpha[pname - GL_OPERAND0_ALPHA] = e;
    return;
  }
  switch (pname) {
    case GL_TEXTURE_ENV_MODE: {
      const GLenum m = enum_arg(p[0]);
      if (m != GL_MODULATE && m != GL_REPLACE && m != GL_DECAL && m != GL_BLEND && m != GL_ADD &&
          m != GL_COMBINE)
        return c.error(GL_INVALID_ENUM);
      c.touch();
      c.s.unit().env_mode = m;
      break;
    }
    case GL_COMBINE_RGB:
    case GL_COMBINE_ALPHA:
      if (!combine_function(e, pname == GL_COMBINE_RGB)) return c.error(GL_INVALID_ENUM);
      c.touch();
      (pname == GL_COMBINE_RGB ? u.combine_rgb : u.combine_alpha) = e;
      break;
    case GL_RGB_SCALE:
    case GL_ALPHA_SCALE:
      if (p[0] != 1.0f && p[0] != 2.0f && p[0] != 4.0f) return c.error(GL_INVALID_VALUE);
      c.touch();
      (pname == GL_RGB_SCALE ? u.rgb_scale : u.alpha_scale) = p[0];
      break;
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
      const GLenum m = enum_arg(p[0]);
      if (m != GL_OBJECT_LINEAR && m != GL_EYE_LINEAR && m != GL_SPHERE_MAP && m != GL_REFLECTION_MAP &&
          m != GL_NORMAL_MAP)
        return c.error(GL_INVALID_ENUM);
      // GL 2.1 §2.12.4: SPHERE_MAP for S and T only, REFLECTION_MAP and NORMAL_MAP not for Q.
      if (m == GL_SPHERE_MAP && (coord == GL_R || coord == GL_Q)) return c.error(GL_INVALID_ENUM);
      if ((m == GL_REFLECTION_MAP || m == GL_NORMAL_MAP) && coord == GL_Q) return c.error(GL_INVALID_ENUM);
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

}  // namespace
}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glTexEnvf(GLenum target, GLenum pname, GLfloat v) {
  GL_COMPAT_CONTEXT();
  if (pname == GL_TEXTURE_ENV_COLOR) return c.error(GL_INVALID_ENUM);
  const Vec4Arg a{v, 0, 0, 0};
  GL_LISTED(tex_env(c, target, pname, a));
  tex_env(c, target, pname, a);
}
void GLAPIENTRY glTexEnvi(GLenum target, GLenum pname, GLint v) { glTexEnvf(target, pname, float(v)); }
void GLAPIENTRY glTexEnvfv(GLenum target, GLenum pname, const GLfloat* v) {
  GL_COMPAT_CONTEXT();
  const Vec4Arg a = take(v, pname == GL_TEXTURE_ENV_COLOR ? 4 : 1);
  GL_LISTED(tex_env(c, target, pname, a));
  tex_env(c, target, pname, a);
}
void GLAPIENTRY glTexEnviv(GLenum target, GLenum pname, const GLint* v) {
  GL_COMPAT_CONTEXT();
  Vec4Arg a = take(v, pname == GL_TEXTURE_ENV_COLOR ? 4 : 1);
  if (pname == GL_TEXTURE_ENV_COLOR && v)
    for (int i = 0; i < 4; ++i) a[size_t(i)] = float((2.0 * double(v[i]) + 1.0) / 4294967295.0);
  GL_LISTED(tex_env(c, target, pname, a));
  tex_env(c, target, pname, a);
}
void GLAPIENTRY glGetTexEnvfv(GLenum target, GLenum pname, GLfloat* out) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  const TextureUnitState& u = c.s.unit();
  if (target == GL_TEXTURE_FILTER_CONTROL && pname == GL_TEXTURE_LOD_BIAS) {
    if (out) out[0] = u.lod_bias;
    return;
  }
  if (target == GL_POINT_SPRITE && pname == GL_COORD_REPLACE) {
    if (out) out[0] = u.coord_replace ? 1.0f : 0.0f;
    return;
  }
  if (target != GL_TEXTURE_ENV) return c.error(GL_INVALID_ENUM);
  if (!out) return;
  if (pname >= GL_SRC0_RGB && pname <= GL_SRC2_RGB)
    out[0] = float(u.src_rgb[pname - GL_SRC0_RGB]);
  else if (pname >= GL_SRC0_ALPHA && pname <= GL_SRC2_ALPHA)
    out[0] = float(u.src_alpha[pname - GL_SRC0_ALPHA]);
  else if (pname >= GL_OPERAND0_RGB && pname <= GL_OPERAND2_RGB)
    out[0] = float(u.op_rgb[pname - GL_OPERAND0_RGB]);
  else if (pname >= GL_OPERAND0_ALPHA && pname <= GL_OPERAND2_ALPHA)
    out[0] = float(u.op_alpha[pname - GL_OPERAND0_ALPHA]);
  else if (pname == GL_TEXTURE_ENV_MODE)
    out[0] = float(u.env_mode);
  else if (pname == GL_COMBINE_RGB)
    out[0] = float(u.combine_rgb);
  else if (pname == GL_COMBINE_ALPHA)
    out[0] = float(u.combine_alpha);
  else if (pname == GL_RGB_SCALE)
    out[0] = u.rgb_scale;
  else if (pname == GL_ALPHA_SCALE)
    out[0] = u.alpha_scale;
  else if (pname == GL_TEXTURE_ENV_COLOR)
    for (int i = 0; i < 4; ++i) out[i] = u.env_color[i];
  else
    c.error(GL_INVALID_ENUM);
}
void GLAPIENTRY glGetTexEnviv(GLenum target, GLenum pname, GLint* out) {
  GL_REMOVED_IN_CORE();
  GLfloat f[4] = {0, 0, 0, 0};
  glGetTexEnvfv(target, pname, f);
  if (!out) return;
  if (pname == GL_TEXTURE_ENV_COLOR)
    for (int i = 0; i < 4; ++i) out[i] = GLint(std::lround(double(f[i]) * 2147483647.0));
  else
    out[0] = GLint(f[0]);
}

void GLAPIENTRY glTexGenf(GLenum coord, GLenum pname, GLfloat v) {
  GL_COMPAT_CONTEXT();
  if (pname != GL_TEXTURE_GEN_MODE) return c.error(GL_INVALID_ENUM);
  const Vec4Arg a{v, 0, 0, 0};
  GL_LISTED(tex_gen(c, coord, pname, a));
  tex_gen(c, coord, pname, a);
}
void GLAPIENTRY glTexGeni(GLenum coord, GLenum pname, GLint v) { glTexGenf(coord, pname, float(v)); }
void GLAPIENTRY glTexGend(GLenum coord, GLenum pname, GLdouble v) { glTexGenf(coord, pname, float(v)); }
void GLAPIENTRY glTexGenfv(GLenum coord, GLenum pname, const GLfloat* v) {
  GL_COMPAT_CONTEXT();
  const Vec4Arg a = take(v, pname == GL_TEXTURE_GEN_MODE ? 1 : 4);
  GL_LISTED(tex_gen(c, coord, pname, a));
  tex_gen(c, coord, pname, a);
}
void GLAPIENTRY glTexGeniv(GLenum coord, GLenum pname, const GLint* v) {
  GL_COMPAT_CONTEXT();
  const Vec4Arg a = take(v, pname == GL_TEXTURE_GEN_MODE ? 1 : 4);
  GL_LISTED(tex_gen(c, coord, pname, a));
  tex_gen(c, coord, pname, a);
}
void GLAPIENTRY glTexGendv(GLenum coord, GLenum pname, const GLdouble* v) {
  GL_COMPAT_CONTEXT();
  const Vec4Arg a = take(v, pname == GL_TEXTURE_GEN_MODE ? 1 : 4);
  GL_LISTED(tex_gen(c, coord, pname, a));
  tex_gen(c, coord, pname, a);
}
void GLAPIENTRY glGetTexGenfv(GLenum coord, GLenum pname, GLfloat* out) {
  GL_COMPAT_CONTEXT();
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
  GL_REMOVED_IN_CORE();
  GLfloat f[4] = {0, 0, 0, 0};
  glGetTexGenfv(coord, pname, f);
  if (out)
    for (int i = 0; i < (pname == GL_TEXTURE_GEN_MODE ? 1 : 4); ++i) out[i] = GLint(f[i]);
}
void GLAPIENTRY glGetTexGendv(GLenum coord, GLenum pname, GLdouble* out) {
  GL_REMOVED_IN_CORE();
  GLfloat f[4] = {0, 0, 0, 0};
  glGetTexGenfv(coord, pname, f);
  if (out)
    for (int i = 0; i < (pname == GL_TEXTURE_GEN_MODE ? 1 : 4); ++i) out[i] = f[i];
}

// The texture image units (GL 3.3 §3.8): GLSL samplers read any of them; the first
// GL_MAX_TEXTURE_COORDS have a texture coordinate set and a texture matrix stack each.
void GLAPIENTRY glActiveTexture(GLenum unit) {
  GL_CONTEXT();
  auto set = [unit](Context& c) {
    GL_OUTSIDE_BEGIN();
    if (unit < GL_TEXTURE0 || unit >= GL_TEXTURE0 + kMaxTextureUnits) return c.error(GL_INVALID_ENUM);
    c.s.active_unit = unit - GL_TEXTURE0;
    if (c.s.active_unit < GLuint(kMaxTexCoords)) c.texture_stack = int(c.s.active_unit);
  };
  GL_LISTED(set(c));
  set(c);
}
void GLAPIENTRY glClientActiveTexture(GLenum unit) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (unit < GL_TEXTURE0 || unit >= GLenum(GL_TEXTURE0 + kMaxTexCoords)) return c.error(GL_INVALID_ENUM);
  c.c.client_active_unit = unit - GL_TEXTURE0;
}

}  // extern "C"
