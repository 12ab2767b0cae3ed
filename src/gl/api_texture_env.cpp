// The texture environment and coordinate generation (GL 2.1 §3.8.13, §2.12.4): glTexEnv,
// glTexGen and their queries, and the active texture unit.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <algorithm>
#include <cmath>

#include "api.hpp"

namespace tessel::gl {

namespace {

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
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (unit != GL_TEXTURE0) return c.error(GL_INVALID_ENUM);  // GL_MAX_TEXTURE_COORDS is 1
  c.c.client_active_unit = unit - GL_TEXTURE0;
}

}  // extern "C"
