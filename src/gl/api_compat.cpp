// GL 1.3-1.4 and 3.3 calls that restate others (GL 3.3 compatibility profile): the transposed
// matrix loads (§2.12.1), glWindowPos (§2.13), glMultiTexCoord for the eight texture coordinate
// sets (GL_MAX_TEXTURE_COORDS), the secondary colour and fog coordinate of GL 1.4 (§2.7), and
// the packed generic attribute values glVertexAttribP* (§2.7).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>

#include "api.hpp"

namespace tessel::gl {

namespace {

template <class T>
glm::mat4 transposed(const T* m) {
  glm::mat4 r(1.0f);
  if (m)
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row) r[col][row] = float(m[row * 4 + col]);
  return r;
}

// GL 2.1 §2.13: the raster position given in window coordinates, always valid; z mapped
// into the depth range; colour and texture coordinates the current ones, unlit.
void window_pos(Context& c, float x, float y, float z) {
  GL_OUTSIDE_BEGIN();
  CurrentState& cur = c.s.current;
  const ViewportState& v = c.s.viewport;
  cur.raster_pos = glm::vec4(x, y, tessel::gpu::depth_in_range(z, v.near_, v.far_), 1.0f);
  cur.raster_valid = true;
  cur.raster_distance = 0.0f;
  cur.raster_color = glm::clamp(cur.color, 0.0f, 1.0f);
  cur.raster_tex = cur.tex;
}

void multi_tex(Context& c, GLenum unit, float s, float t, float r, float q) {
  if (unit < GL_TEXTURE0 || unit >= GLenum(GL_TEXTURE0 + kMaxTexCoords)) return c.error(GL_INVALID_ENUM);
  const size_t i = unit - GL_TEXTURE0;
  c.s.current.tex[i] = glm::vec4(s, t, r, q);
  if (i > 0) c.extras_touched = true;
}

void secondary_color(Context& c, float r, float g, float b) {
  c.s.current.secondary = glm::vec4(r, g, b, 1.0f);
  c.extras_touched = true;
}

void fog_coord(Context& c, float f) {
  c.s.current.fog_coord = f;
  c.extras_touched = true;
}

using namespace colour_arg;

// The packed fixed-function attributes (GL 3.3 compatibility §2.7, ARB_vertex_type_2_10_10_10_rev):
// the four components of `value`, or false (GL_INVALID_ENUM recorded) for another type.
bool unpack_p(Context& c, GLenum type, bool normalized, GLuint value, float* out) {
  if (type != GL_INT_2_10_10_10_REV && type != GL_UNSIGNED_INT_2_10_10_10_REV) {
    c.error(GL_INVALID_ENUM);
    return false;
  }
  unpack_2_10_10_10(value, type == GL_INT_2_10_10_10_REV, normalized, out);
  return true;
}

void attrib_p(Context& c, GLuint index, GLenum type, bool normalized, int n, GLuint value) {
  if (index >= GLuint(kMaxVertexAttribs)) return c.error(GL_INVALID_VALUE);
  if (type != GL_INT_2_10_10_10_REV && type != GL_UNSIGNED_INT_2_10_10_10_REV)
    return c.error(GL_INVALID_ENUM);
  float v[4];
  unpack_2_10_10_10(value, type == GL_INT_2_10_10_10_REV, normalized, v);
  const float w = n == 4 ? v[3] : 1.0f;
  glVertexAttrib4f(index, v[0], n >= 2 ? v[1] : 0.0f, n >= 3 ? v[2] : 0.0f, w);
}

}  // namespace
}  // namespace tessel::gl

using namespace tessel::gl;

#define WINDOW_POS(x, y, z)                                   \
  GL_COMPAT_CONTEXT();                                        \
  const float wx_ = float(x), wy_ = float(y), wz_ = float(z); \
  GL_LISTED(window_pos(c, wx_, wy_, wz_));                    \
  window_pos(c, wx_, wy_, wz_)

#define MULTI_TEX(u, s, t, r, q)                                              \
  GL_COMPAT_CONTEXT();                                                        \
  const GLenum mu_ = (u);                                                     \
  const float ms_ = float(s), mt_ = float(t), mr_ = float(r), mq_ = float(q); \
  GL_LISTED(multi_tex(c, mu_, ms_, mt_, mr_, mq_));                           \
  multi_tex(c, mu_, ms_, mt_, mr_, mq_)

#define SECONDARY(r, g, b)                                    \
  GL_COMPAT_CONTEXT();                                        \
  const float sr_ = float(r), sg_ = float(g), sb_ = float(b); \
  GL_LISTED(secondary_color(c, sr_, sg_, sb_));               \
  secondary_color(c, sr_, sg_, sb_)

#define FOG_COORD(f)           \
  GL_COMPAT_CONTEXT();         \
  const float f_ = float(f);   \
  GL_LISTED(fog_coord(c, f_)); \
  fog_coord(c, f_)

// Each packed form unpacks and calls the unpacked entry point (which records itself in a
// display list being compiled): positions and texture coordinates as integers, normals and
// colours normalized.
#define PACKED(normalized, value, call) \
  GL_COMPAT_CONTEXT();                  \
  float p_[4];                          \
  if (unpack_p(c, type, normalized, value, p_)) call

extern "C" {

void GLAPIENTRY glVertexP2ui(GLenum type, GLuint v) { PACKED(false, v, glVertex2f(p_[0], p_[1])); }
void GLAPIENTRY glVertexP2uiv(GLenum type, const GLuint* v) { PACKED(false, *v, glVertex2f(p_[0], p_[1])); }
void GLAPIENTRY glVertexP3ui(GLenum type, GLuint v) { PACKED(false, v, glVertex3f(p_[0], p_[1], p_[2])); }
void GLAPIENTRY glVertexP3uiv(GLenum type, const GLuint* v) {
  PACKED(false, *v, glVertex3f(p_[0], p_[1], p_[2]));
}
void GLAPIENTRY glVertexP4ui(GLenum type, GLuint v) {
  PACKED(false, v, glVertex4f(p_[0], p_[1], p_[2], p_[3]));
}
void GLAPIENTRY glVertexP4uiv(GLenum type, const GLuint* v) {
  PACKED(false, *v, glVertex4f(p_[0], p_[1], p_[2], p_[3]));
}
void GLAPIENTRY glTexCoordP1ui(GLenum type, GLuint v) { PACKED(false, v, glTexCoord1f(p_[0])); }
void GLAPIENTRY glTexCoordP1uiv(GLenum type, const GLuint* v) { PACKED(false, *v, glTexCoord1f(p_[0])); }
void GLAPIENTRY glTexCoordP2ui(GLenum type, GLuint v) { PACKED(false, v, glTexCoord2f(p_[0], p_[1])); }
void GLAPIENTRY glTexCoordP2uiv(GLenum type, const GLuint* v) {
  PACKED(false, *v, glTexCoord2f(p_[0], p_[1]));
}
void GLAPIENTRY glTexCoordP3ui(GLenum type, GLuint v) { PACKED(false, v, glTexCoord3f(p_[0], p_[1], p_[2])); }
void GLAPIENTRY glTexCoordP3uiv(GLenum type, const GLuint* v) {
  PACKED(false, *v, glTexCoord3f(p_[0], p_[1], p_[2]));
}
void GLAPIENTRY glTexCoordP4ui(GLenum type, GLuint v) {
  PACKED(false, v, glTexCoord4f(p_[0], p_[1], p_[2], p_[3]));
}
void GLAPIENTRY glTexCoordP4uiv(GLenum type, const GLuint* v) {
  PACKED(false, *v, glTexCoord4f(p_[0], p_[1], p_[2], p_[3]));
}
void GLAPIENTRY glMultiTexCoordP1ui(GLenum unit, GLenum type, GLuint v) {
  PACKED(false, v, glMultiTexCoord1f(unit, p_[0]));
}
void GLAPIENTRY glMultiTexCoordP1uiv(GLenum unit, GLenum type, const GLuint* v) {
  PACKED(false, *v, glMultiTexCoord1f(unit, p_[0]));
}
void GLAPIENTRY glMultiTexCoordP2ui(GLenum unit, GLenum type, GLuint v) {
  PACKED(false, v, glMultiTexCoord2f(unit, p_[0], p_[1]));
}
void GLAPIENTRY glMultiTexCoordP2uiv(GLenum unit, GLenum type, const GLuint* v) {
  PACKED(false, *v, glMultiTexCoord2f(unit, p_[0], p_[1]));
}
void GLAPIENTRY glMultiTexCoordP3ui(GLenum unit, GLenum type, GLuint v) {
  PACKED(false, v, glMultiTexCoord3f(unit, p_[0], p_[1], p_[2]));
}
void GLAPIENTRY glMultiTexCoordP3uiv(GLenum unit, GLenum type, const GLuint* v) {
  PACKED(false, *v, glMultiTexCoord3f(unit, p_[0], p_[1], p_[2]));
}
void GLAPIENTRY glMultiTexCoordP4ui(GLenum unit, GLenum type, GLuint v) {
  PACKED(false, v, glMultiTexCoord4f(unit, p_[0], p_[1], p_[2], p_[3]));
}
void GLAPIENTRY glMultiTexCoordP4uiv(GLenum unit, GLenum type, const GLuint* v) {
  PACKED(false, *v, glMultiTexCoord4f(unit, p_[0], p_[1], p_[2], p_[3]));
}
void GLAPIENTRY glNormalP3ui(GLenum type, GLuint v) { PACKED(true, v, glNormal3f(p_[0], p_[1], p_[2])); }
void GLAPIENTRY glNormalP3uiv(GLenum type, const GLuint* v) {
  PACKED(true, *v, glNormal3f(p_[0], p_[1], p_[2]));
}
void GLAPIENTRY glColorP3ui(GLenum type, GLuint v) { PACKED(true, v, glColor3f(p_[0], p_[1], p_[2])); }
void GLAPIENTRY glColorP3uiv(GLenum type, const GLuint* v) {
  PACKED(true, *v, glColor3f(p_[0], p_[1], p_[2]));
}
void GLAPIENTRY glColorP4ui(GLenum type, GLuint v) { PACKED(true, v, glColor4f(p_[0], p_[1], p_[2], p_[3])); }
void GLAPIENTRY glColorP4uiv(GLenum type, const GLuint* v) {
  PACKED(true, *v, glColor4f(p_[0], p_[1], p_[2], p_[3]));
}
void GLAPIENTRY glSecondaryColorP3ui(GLenum type, GLuint v) {
  PACKED(true, v, glSecondaryColor3f(p_[0], p_[1], p_[2]));
}
void GLAPIENTRY glSecondaryColorP3uiv(GLenum type, const GLuint* v) {
  PACKED(true, *v, glSecondaryColor3f(p_[0], p_[1], p_[2]));
}

void GLAPIENTRY glSecondaryColor3b(GLbyte r, GLbyte g, GLbyte b) { SECONDARY(sb(r), sb(g), sb(b)); }
void GLAPIENTRY glSecondaryColor3bv(const GLbyte* v) { SECONDARY(sb(v[0]), sb(v[1]), sb(v[2])); }
void GLAPIENTRY glSecondaryColor3s(GLshort r, GLshort g, GLshort b) { SECONDARY(ss(r), ss(g), ss(b)); }
void GLAPIENTRY glSecondaryColor3sv(const GLshort* v) { SECONDARY(ss(v[0]), ss(v[1]), ss(v[2])); }
void GLAPIENTRY glSecondaryColor3i(GLint r, GLint g, GLint b) { SECONDARY(si(r), si(g), si(b)); }
void GLAPIENTRY glSecondaryColor3iv(const GLint* v) { SECONDARY(si(v[0]), si(v[1]), si(v[2])); }
void GLAPIENTRY glSecondaryColor3ub(GLubyte r, GLubyte g, GLubyte b) { SECONDARY(ub(r), ub(g), ub(b)); }
void GLAPIENTRY glSecondaryColor3ubv(const GLubyte* v) { SECONDARY(ub(v[0]), ub(v[1]), ub(v[2])); }
void GLAPIENTRY glSecondaryColor3us(GLushort r, GLushort g, GLushort b) { SECONDARY(us(r), us(g), us(b)); }
void GLAPIENTRY glSecondaryColor3usv(const GLushort* v) { SECONDARY(us(v[0]), us(v[1]), us(v[2])); }
void GLAPIENTRY glSecondaryColor3ui(GLuint r, GLuint g, GLuint b) { SECONDARY(ui(r), ui(g), ui(b)); }
void GLAPIENTRY glSecondaryColor3uiv(const GLuint* v) { SECONDARY(ui(v[0]), ui(v[1]), ui(v[2])); }
void GLAPIENTRY glSecondaryColor3f(GLfloat r, GLfloat g, GLfloat b) { SECONDARY(r, g, b); }
void GLAPIENTRY glSecondaryColor3fv(const GLfloat* v) { SECONDARY(v[0], v[1], v[2]); }
void GLAPIENTRY glSecondaryColor3d(GLdouble r, GLdouble g, GLdouble b) { SECONDARY(r, g, b); }
void GLAPIENTRY glSecondaryColor3dv(const GLdouble* v) { SECONDARY(v[0], v[1], v[2]); }
void GLAPIENTRY glFogCoordf(GLfloat f) { FOG_COORD(f); }
void GLAPIENTRY glFogCoordfv(const GLfloat* f) { FOG_COORD(f[0]); }
void GLAPIENTRY glFogCoordd(GLdouble f) { FOG_COORD(f); }
void GLAPIENTRY glFogCoorddv(const GLdouble* f) { FOG_COORD(f[0]); }

void GLAPIENTRY glLoadTransposeMatrixf(const GLfloat* m) {
  GL_COMPAT_CONTEXT();
  const glm::mat4 a = transposed(m);
  GL_LISTED(load_matrix(c, a));
  load_matrix(c, a);
}
void GLAPIENTRY glLoadTransposeMatrixd(const GLdouble* m) {
  GL_COMPAT_CONTEXT();
  const glm::mat4 a = transposed(m);
  GL_LISTED(load_matrix(c, a));
  load_matrix(c, a);
}
void GLAPIENTRY glMultTransposeMatrixf(const GLfloat* m) {
  GL_COMPAT_CONTEXT();
  const glm::mat4 a = transposed(m);
  GL_LISTED(mult_matrix(c, a));
  mult_matrix(c, a);
}
void GLAPIENTRY glMultTransposeMatrixd(const GLdouble* m) {
  GL_COMPAT_CONTEXT();
  const glm::mat4 a = transposed(m);
  GL_LISTED(mult_matrix(c, a));
  mult_matrix(c, a);
}

void GLAPIENTRY glWindowPos2s(GLshort x, GLshort y) { WINDOW_POS(x, y, 0); }
void GLAPIENTRY glWindowPos2sv(const GLshort* v) { WINDOW_POS(v[0], v[1], 0); }
void GLAPIENTRY glWindowPos2i(GLint x, GLint y) { WINDOW_POS(x, y, 0); }
void GLAPIENTRY glWindowPos2iv(const GLint* v) { WINDOW_POS(v[0], v[1], 0); }
void GLAPIENTRY glWindowPos2f(GLfloat x, GLfloat y) { WINDOW_POS(x, y, 0); }
void GLAPIENTRY glWindowPos2fv(const GLfloat* v) { WINDOW_POS(v[0], v[1], 0); }
void GLAPIENTRY glWindowPos2d(GLdouble x, GLdouble y) { WINDOW_POS(x, y, 0); }
void GLAPIENTRY glWindowPos2dv(const GLdouble* v) { WINDOW_POS(v[0], v[1], 0); }
void GLAPIENTRY glWindowPos3s(GLshort x, GLshort y, GLshort z) { WINDOW_POS(x, y, z); }
void GLAPIENTRY glWindowPos3sv(const GLshort* v) { WINDOW_POS(v[0], v[1], v[2]); }
void GLAPIENTRY glWindowPos3i(GLint x, GLint y, GLint z) { WINDOW_POS(x, y, z); }
void GLAPIENTRY glWindowPos3iv(const GLint* v) { WINDOW_POS(v[0], v[1], v[2]); }
void GLAPIENTRY glWindowPos3f(GLfloat x, GLfloat y, GLfloat z) { WINDOW_POS(x, y, z); }
void GLAPIENTRY glWindowPos3fv(const GLfloat* v) { WINDOW_POS(v[0], v[1], v[2]); }
void GLAPIENTRY glWindowPos3d(GLdouble x, GLdouble y, GLdouble z) { WINDOW_POS(x, y, z); }
void GLAPIENTRY glWindowPos3dv(const GLdouble* v) { WINDOW_POS(v[0], v[1], v[2]); }
void GLAPIENTRY glMultiTexCoord1s(GLenum unit, GLshort s) { MULTI_TEX(unit, s, 0, 0, 1); }
void GLAPIENTRY glMultiTexCoord1sv(GLenum unit, const GLshort* v) { MULTI_TEX(unit, v[0], 0, 0, 1); }
void GLAPIENTRY glMultiTexCoord1i(GLenum unit, GLint s) { MULTI_TEX(unit, s, 0, 0, 1); }
void GLAPIENTRY glMultiTexCoord1iv(GLenum unit, const GLint* v) { MULTI_TEX(unit, v[0], 0, 0, 1); }
void GLAPIENTRY glMultiTexCoord1f(GLenum unit, GLfloat s) { MULTI_TEX(unit, s, 0, 0, 1); }
void GLAPIENTRY glMultiTexCoord1fv(GLenum unit, const GLfloat* v) { MULTI_TEX(unit, v[0], 0, 0, 1); }
void GLAPIENTRY glMultiTexCoord1d(GLenum unit, GLdouble s) { MULTI_TEX(unit, s, 0, 0, 1); }
void GLAPIENTRY glMultiTexCoord1dv(GLenum unit, const GLdouble* v) { MULTI_TEX(unit, v[0], 0, 0, 1); }
void GLAPIENTRY glMultiTexCoord2s(GLenum unit, GLshort s, GLshort t) { MULTI_TEX(unit, s, t, 0, 1); }
void GLAPIENTRY glMultiTexCoord2sv(GLenum unit, const GLshort* v) { MULTI_TEX(unit, v[0], v[1], 0, 1); }
void GLAPIENTRY glMultiTexCoord2i(GLenum unit, GLint s, GLint t) { MULTI_TEX(unit, s, t, 0, 1); }
void GLAPIENTRY glMultiTexCoord2iv(GLenum unit, const GLint* v) { MULTI_TEX(unit, v[0], v[1], 0, 1); }
void GLAPIENTRY glMultiTexCoord2f(GLenum unit, GLfloat s, GLfloat t) { MULTI_TEX(unit, s, t, 0, 1); }
void GLAPIENTRY glMultiTexCoord2fv(GLenum unit, const GLfloat* v) { MULTI_TEX(unit, v[0], v[1], 0, 1); }
void GLAPIENTRY glMultiTexCoord2d(GLenum unit, GLdouble s, GLdouble t) { MULTI_TEX(unit, s, t, 0, 1); }
void GLAPIENTRY glMultiTexCoord2dv(GLenum unit, const GLdouble* v) { MULTI_TEX(unit, v[0], v[1], 0, 1); }
void GLAPIENTRY glMultiTexCoord3s(GLenum unit, GLshort s, GLshort t, GLshort r) {
  MULTI_TEX(unit, s, t, r, 1);
}
void GLAPIENTRY glMultiTexCoord3sv(GLenum unit, const GLshort* v) { MULTI_TEX(unit, v[0], v[1], v[2], 1); }
void GLAPIENTRY glMultiTexCoord3i(GLenum unit, GLint s, GLint t, GLint r) { MULTI_TEX(unit, s, t, r, 1); }
void GLAPIENTRY glMultiTexCoord3iv(GLenum unit, const GLint* v) { MULTI_TEX(unit, v[0], v[1], v[2], 1); }
void GLAPIENTRY glMultiTexCoord3f(GLenum unit, GLfloat s, GLfloat t, GLfloat r) {
  MULTI_TEX(unit, s, t, r, 1);
}
void GLAPIENTRY glMultiTexCoord3fv(GLenum unit, const GLfloat* v) { MULTI_TEX(unit, v[0], v[1], v[2], 1); }
void GLAPIENTRY glMultiTexCoord3d(GLenum unit, GLdouble s, GLdouble t, GLdouble r) {
  MULTI_TEX(unit, s, t, r, 1);
}
void GLAPIENTRY glMultiTexCoord3dv(GLenum unit, const GLdouble* v) { MULTI_TEX(unit, v[0], v[1], v[2], 1); }
void GLAPIENTRY glMultiTexCoord4s(GLenum unit, GLshort s, GLshort t, GLshort r, GLshort q) {
  MULTI_TEX(unit, s, t, r, q);
}
void GLAPIENTRY glMultiTexCoord4sv(GLenum unit, const GLshort* v) { MULTI_TEX(unit, v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glMultiTexCoord4i(GLenum unit, GLint s, GLint t, GLint r, GLint q) {
  MULTI_TEX(unit, s, t, r, q);
}
void GLAPIENTRY glMultiTexCoord4iv(GLenum unit, const GLint* v) { MULTI_TEX(unit, v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glMultiTexCoord4f(GLenum unit, GLfloat s, GLfloat t, GLfloat r, GLfloat q) {
  MULTI_TEX(unit, s, t, r, q);
}
void GLAPIENTRY glMultiTexCoord4fv(GLenum unit, const GLfloat* v) { MULTI_TEX(unit, v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glMultiTexCoord4d(GLenum unit, GLdouble s, GLdouble t, GLdouble r, GLdouble q) {
  MULTI_TEX(unit, s, t, r, q);
}
void GLAPIENTRY glMultiTexCoord4dv(GLenum unit, const GLdouble* v) {
  MULTI_TEX(unit, v[0], v[1], v[2], v[3]);
}
void GLAPIENTRY glVertexAttribP1ui(GLuint index, GLenum type, GLboolean normalized, GLuint value) {
  GL_CONTEXT();
  attrib_p(c, index, type, normalized != GL_FALSE, 1, value);
}
void GLAPIENTRY glVertexAttribP1uiv(GLuint index, GLenum type, GLboolean normalized, const GLuint* value) {
  GL_CONTEXT();
  if (value) attrib_p(c, index, type, normalized != GL_FALSE, 1, *value);
}
void GLAPIENTRY glVertexAttribP2ui(GLuint index, GLenum type, GLboolean normalized, GLuint value) {
  GL_CONTEXT();
  attrib_p(c, index, type, normalized != GL_FALSE, 2, value);
}
void GLAPIENTRY glVertexAttribP2uiv(GLuint index, GLenum type, GLboolean normalized, const GLuint* value) {
  GL_CONTEXT();
  if (value) attrib_p(c, index, type, normalized != GL_FALSE, 2, *value);
}
void GLAPIENTRY glVertexAttribP3ui(GLuint index, GLenum type, GLboolean normalized, GLuint value) {
  GL_CONTEXT();
  attrib_p(c, index, type, normalized != GL_FALSE, 3, value);
}
void GLAPIENTRY glVertexAttribP3uiv(GLuint index, GLenum type, GLboolean normalized, const GLuint* value) {
  GL_CONTEXT();
  if (value) attrib_p(c, index, type, normalized != GL_FALSE, 3, *value);
}
void GLAPIENTRY glVertexAttribP4ui(GLuint index, GLenum type, GLboolean normalized, GLuint value) {
  GL_CONTEXT();
  attrib_p(c, index, type, normalized != GL_FALSE, 4, value);
}
void GLAPIENTRY glVertexAttribP4uiv(GLuint index, GLenum type, GLboolean normalized, const GLuint* value) {
  GL_CONTEXT();
  if (value) attrib_p(c, index, type, normalized != GL_FALSE, 4, *value);
}

}  // extern "C"
