// Lighting state (GL 2.1 §2.14): glLight, glLightModel, glMaterial, glColorMaterial,
// glShadeModel; and fog (§3.10): glFog.
#include <GL/gl.h>

#include <algorithm>
#include <cmath>

#include "api.hpp"

namespace tessel::gl {

int light_param_count(GLenum pname) {
  switch (pname) {
    case GL_AMBIENT:
    case GL_DIFFUSE:
    case GL_SPECULAR:
    case GL_POSITION: return 4;
    case GL_SPOT_DIRECTION: return 3;
    case GL_SPOT_EXPONENT:
    case GL_SPOT_CUTOFF:
    case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION: return 1;
    default: return 0;
  }
}

int material_param_count(GLenum pname) {
  switch (pname) {
    case GL_AMBIENT:
    case GL_DIFFUSE:
    case GL_SPECULAR:
    case GL_EMISSION:
    case GL_AMBIENT_AND_DIFFUSE: return 4;
    case GL_SHININESS: return 1;
    case GL_COLOR_INDEXES: return 3;
    default: return 0;
  }
}

namespace {

void light(Context& c, GLenum which, GLenum pname, Vec4Arg p) {
  GL_OUTSIDE_BEGIN();
  if (which < GL_LIGHT0 || which >= GL_LIGHT0 + kMaxLights || light_param_count(pname) == 0) {
    c.error(GL_INVALID_ENUM);
    return;
  }
  const size_t i = which - GL_LIGHT0;
  FFLight& L = c.s.light.light[i];
  const glm::vec4 v(p[0], p[1], p[2], p[3]);
  switch (pname) {
    case GL_SPOT_EXPONENT:
      if (p[0] < 0.0f || p[0] > 128.0f) return c.error(GL_INVALID_VALUE);
      break;
    case GL_SPOT_CUTOFF:
      if ((p[0] < 0.0f || p[0] > 90.0f) && p[0] != 180.0f) return c.error(GL_INVALID_VALUE);
      break;
    case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION:
      if (p[0] < 0.0f) return c.error(GL_INVALID_VALUE);
      break;
    default: break;
  }
  c.touch();
  switch (pname) {
    case GL_AMBIENT: L.ambient = v; break;
    case GL_DIFFUSE: L.diffuse = v; break;
    case GL_SPECULAR: L.specular = v; break;
    // Positions and directions are stored in eye coordinates, transformed by the model-view
    // matrix current when they are specified (GL 2.1 §2.14.2).
    case GL_POSITION: L.position = c.modelview() * v; break;
    case GL_SPOT_DIRECTION: L.spot_direction = glm::mat3(c.modelview()) * glm::vec3(v); break;
    case GL_SPOT_EXPONENT: L.spot_exponent = p[0]; break;
    case GL_SPOT_CUTOFF:
      c.s.light.spot_cutoff[i] = p[0];
      L.spot = p[0] != 180.0f;
      L.spot_cos_cutoff = std::cos(p[0] * float(M_PI / 180.0));
      break;
    case GL_CONSTANT_ATTENUATION: L.k0 = p[0]; break;
    case GL_LINEAR_ATTENUATION: L.k1 = p[0]; break;
    case GL_QUADRATIC_ATTENUATION: L.k2 = p[0]; break;
    default: break;
  }
}

void light_model(Context& c, GLenum pname, Vec4Arg p) {
  GL_OUTSIDE_BEGIN();
  c.touch();
  switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT: c.s.light.model_ambient = glm::vec4(p[0], p[1], p[2], p[3]); break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: c.s.light.local_viewer = p[0] != 0.0f; break;
    case GL_LIGHT_MODEL_TWO_SIDE: c.s.light.two_side = p[0] != 0.0f; break;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
      if (p[0] != float(GL_SINGLE_COLOR) && p[0] != float(GL_SEPARATE_SPECULAR_COLOR))
        return c.error(GL_INVALID_ENUM);
      c.s.light.separate_specular = p[0] == float(GL_SEPARATE_SPECULAR_COLOR);
      break;
    default: c.error(GL_INVALID_ENUM); break;
  }
}

// glMaterial is allowed between glBegin and glEnd; the primitive then takes the material
// current at glEnd.
void material(Context& c, GLenum face, GLenum pname, Vec4Arg p) {
  if ((face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) ||
      material_param_count(pname) == 0) {
    c.error(GL_INVALID_ENUM);
    return;
  }
  if (pname == GL_SHININESS && (p[0] < 0.0f || p[0] > 128.0f)) {
    c.error(GL_INVALID_VALUE);
    return;
  }
  if (!c.in_begin) c.touch();
  const glm::vec4 v(p[0], p[1], p[2], p[3]);
  for (int f = 0; f < 2; ++f) {
    if ((f == 0 && face == GL_BACK) || (f == 1 && face == GL_FRONT)) continue;
    FFMaterial& m = c.s.light.material[size_t(f)];
    switch (pname) {
      case GL_AMBIENT: m.ambient = v; break;
      case GL_DIFFUSE: m.diffuse = v; break;
      case GL_SPECULAR: m.specular = v; break;
      case GL_EMISSION: m.emission = v; break;
      case GL_AMBIENT_AND_DIFFUSE: m.ambient = m.diffuse = v; break;
      case GL_SHININESS: m.shininess = p[0]; break;
      default: break;  // colour indexes: no colour-index mode
    }
  }
}

void color_material(Context& c, GLenum face, GLenum mode) {
  GL_OUTSIDE_BEGIN();
  if ((face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) ||
      (mode != GL_AMBIENT && mode != GL_DIFFUSE && mode != GL_SPECULAR && mode != GL_EMISSION &&
       mode != GL_AMBIENT_AND_DIFFUSE)) {
    c.error(GL_INVALID_ENUM);
    return;
  }
  c.touch();
  c.s.light.color_material_face = face;
  c.s.light.color_material_mode = mode;
}

void shade_model(Context& c, GLenum mode) {
  GL_OUTSIDE_BEGIN();
  if (mode != GL_FLAT && mode != GL_SMOOTH) return c.error(GL_INVALID_ENUM);
  c.touch();
  c.s.light.shade_model = mode;
}

void fog(Context& c, GLenum pname, Vec4Arg p) {
  GL_OUTSIDE_BEGIN();
  FogState& f = c.s.fog;
  switch (pname) {
    case GL_FOG_MODE: {
      const GLenum m = enum_arg(p[0]);
      if (m != GL_LINEAR && m != GL_EXP && m != GL_EXP2) return c.error(GL_INVALID_ENUM);
      c.touch();
      f.mode = m;
      break;
    }
    case GL_FOG_DENSITY:
      if (p[0] < 0.0f) return c.error(GL_INVALID_VALUE);
      c.touch();
      f.density = p[0];
      break;
    case GL_FOG_START:
      c.touch();
      f.start = p[0];
      break;
    case GL_FOG_COORD_SRC: {
      const GLenum m = enum_arg(p[0]);
      if (m != GL_FOG_COORD && m != GL_FRAGMENT_DEPTH) return c.error(GL_INVALID_ENUM);
      c.touch();
      f.coord_src = m;
      break;
    }
    case GL_FOG_END:
      c.touch();
      f.end = p[0];
      break;
    case GL_FOG_COLOR:
      c.touch();
      f.color = glm::clamp(glm::vec4(p[0], p[1], p[2], p[3]), 0.0f, 1.0f);
      break;
    case GL_FOG_INDEX: break;
    default: c.error(GL_INVALID_ENUM); break;
  }
}

int fog_param_count(GLenum pname) { return pname == GL_FOG_COLOR ? 4 : 1; }
int light_model_count(GLenum pname) { return pname == GL_LIGHT_MODEL_AMBIENT ? 4 : 1; }

// Integer forms of colour parameters map to [-1, 1] (GL 2.1 §2.14.2); other integers stay.
Vec4Arg take_color_int(const GLint* v, int n) {
  Vec4Arg a{0.0f, 0.0f, 0.0f, 0.0f};
  if (v)
    for (int i = 0; i < n && i < 4; ++i) a[size_t(i)] = float((2.0 * double(v[i]) + 1.0) / 4294967295.0);
  return a;
}
bool is_color_param(GLenum pname) {
  return pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR || pname == GL_EMISSION ||
         pname == GL_AMBIENT_AND_DIFFUSE || pname == GL_LIGHT_MODEL_AMBIENT || pname == GL_FOG_COLOR;
}

}  // namespace
}  // namespace tessel::gl

using namespace tessel::gl;

#define LIGHT_CALL(fn, ...)      \
  GL_COMPAT_CONTEXT();           \
  GL_LISTED(fn(c, __VA_ARGS__)); \
  fn(c, __VA_ARGS__)

extern "C" {

void GLAPIENTRY glLightf(GLenum l, GLenum pname, GLfloat v) {
  GL_REMOVED_IN_CORE();
  const Vec4Arg a{v, 0, 0, 0};
  GL_CONTEXT();
  if (light_param_count(pname) != 1) return c.error(GL_INVALID_ENUM);
  GL_LISTED(light(c, l, pname, a));
  light(c, l, pname, a);
}
void GLAPIENTRY glLighti(GLenum l, GLenum pname, GLint v) { glLightf(l, pname, float(v)); }
void GLAPIENTRY glLightfv(GLenum l, GLenum pname, const GLfloat* v) {
  GL_REMOVED_IN_CORE();
  const Vec4Arg a = take(v, light_param_count(pname));
  LIGHT_CALL(light, l, pname, a);
}
void GLAPIENTRY glLightiv(GLenum l, GLenum pname, const GLint* v) {
  GL_REMOVED_IN_CORE();
  const int n = light_param_count(pname);
  const Vec4Arg a = is_color_param(pname) ? take_color_int(v, n) : take(v, n);
  LIGHT_CALL(light, l, pname, a);
}
void GLAPIENTRY glLightModelf(GLenum pname, GLfloat v) {
  GL_REMOVED_IN_CORE();
  const Vec4Arg a{v, 0, 0, 0};
  GL_CONTEXT();
  if (pname == GL_LIGHT_MODEL_AMBIENT) return c.error(GL_INVALID_ENUM);
  GL_LISTED(light_model(c, pname, a));
  light_model(c, pname, a);
}
void GLAPIENTRY glLightModeli(GLenum pname, GLint v) { glLightModelf(pname, float(v)); }
void GLAPIENTRY glLightModelfv(GLenum pname, const GLfloat* v) {
  GL_REMOVED_IN_CORE();
  const Vec4Arg a = take(v, light_model_count(pname));
  LIGHT_CALL(light_model, pname, a);
}
void GLAPIENTRY glLightModeliv(GLenum pname, const GLint* v) {
  GL_REMOVED_IN_CORE();
  const int n = light_model_count(pname);
  const Vec4Arg a = is_color_param(pname) ? take_color_int(v, n) : take(v, n);
  LIGHT_CALL(light_model, pname, a);
}
void GLAPIENTRY glMaterialf(GLenum face, GLenum pname, GLfloat v) {
  GL_REMOVED_IN_CORE();
  const Vec4Arg a{v, 0, 0, 0};
  GL_CONTEXT();
  if (pname != GL_SHININESS) return c.error(GL_INVALID_ENUM);
  GL_LISTED(material(c, face, pname, a));
  material(c, face, pname, a);
}
void GLAPIENTRY glMateriali(GLenum face, GLenum pname, GLint v) { glMaterialf(face, pname, float(v)); }
void GLAPIENTRY glMaterialfv(GLenum face, GLenum pname, const GLfloat* v) {
  GL_REMOVED_IN_CORE();
  const Vec4Arg a = take(v, material_param_count(pname));
  LIGHT_CALL(material, face, pname, a);
}
void GLAPIENTRY glMaterialiv(GLenum face, GLenum pname, const GLint* v) {
  GL_REMOVED_IN_CORE();
  const int n = material_param_count(pname);
  const Vec4Arg a = is_color_param(pname) ? take_color_int(v, n) : take(v, n);
  LIGHT_CALL(material, face, pname, a);
}
void GLAPIENTRY glColorMaterial(GLenum face, GLenum mode) { LIGHT_CALL(color_material, face, mode); }
void GLAPIENTRY glShadeModel(GLenum mode) { LIGHT_CALL(shade_model, mode); }

// GL 3.3 §2.18: which vertex of a primitive flat-shaded values come from.
void GLAPIENTRY glProvokingVertex(GLenum mode) {
  GL_CONTEXT();
  auto set = [mode](Context& c) {
    GL_OUTSIDE_BEGIN();
    if (mode != GL_FIRST_VERTEX_CONVENTION && mode != GL_LAST_VERTEX_CONVENTION)
      return c.error(GL_INVALID_ENUM);
    c.touch();
    c.s.light.provoking_vertex = mode;
  };
  GL_LISTED(set(c));
  set(c);
}

void GLAPIENTRY glFogf(GLenum pname, GLfloat v) {
  GL_REMOVED_IN_CORE();
  const Vec4Arg a{v, 0, 0, 0};
  GL_CONTEXT();
  if (pname == GL_FOG_COLOR) return c.error(GL_INVALID_ENUM);
  GL_LISTED(fog(c, pname, a));
  fog(c, pname, a);
}
void GLAPIENTRY glFogi(GLenum pname, GLint v) { glFogf(pname, float(v)); }
void GLAPIENTRY glFogfv(GLenum pname, const GLfloat* v) {
  GL_REMOVED_IN_CORE();
  const Vec4Arg a = take(v, fog_param_count(pname));
  LIGHT_CALL(fog, pname, a);
}
void GLAPIENTRY glFogiv(GLenum pname, const GLint* v) {
  GL_REMOVED_IN_CORE();
  const int n = fog_param_count(pname);
  const Vec4Arg a = is_color_param(pname) ? take_color_int(v, n) : take(v, n);
  LIGHT_CALL(fog, pname, a);
}

}  // extern "C"
