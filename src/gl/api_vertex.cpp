// glBegin/glEnd, the current vertex attributes (glVertex, glNormal, glColor, glTexCoord,
// glEdgeFlag in all their forms), glRect, and the raster position.
#include <GL/gl.h>

#include "api.hpp"

namespace tessel::gl {

void begin(Context& c, GLenum mode) {
  if (mode > GL_POLYGON) {
    c.error(GL_INVALID_ENUM);
    return;
  }
  GL_OUTSIDE_BEGIN();
  c.in_begin = true;
  c.begin_mode = mode;
  c.prim.clear();
  c.extras_touched = c.extras_live();
}

void vertex(Context& c, float x, float y, float z, float w) {
  // Outside glBegin/glEnd a vertex has no effect (GL 2.1 §2.6.3, "undefined"; nothing is drawn).
  if (!c.in_begin) return;
  c.vertex(x, y, z, w);
}

namespace {
void end(Context& c) {
  if (!c.in_begin) {
    c.error(GL_INVALID_OPERATION);
    return;
  }
  c.end();
}
void set_color(Context& c, float r, float g, float b, float a) { c.s.current.color = glm::vec4(r, g, b, a); }
void set_normal(Context& c, float x, float y, float z) { c.s.current.normal = glm::vec3(x, y, z); }
void set_tex(Context& c, float s, float t, float r, float q) { c.s.current.tex[0] = glm::vec4(s, t, r, q); }

using namespace colour_arg;
}  // namespace

void raster_pos(Context& c, float x, float y, float z, float w) {
  GL_OUTSIDE_BEGIN();
  // GL 2.1 §2.13: the raster position is transformed like a vertex and clipped as a point.
  const glm::vec4 eye = c.modelview() * glm::vec4(x, y, z, w);
  const glm::vec4 clip = c.projection() * eye;
  CurrentState& cur = c.s.current;
  const bool valid = clip.w != 0.0f && tessel::gpu::clip_code(c.cpu_clip_planes(), clip) == 0;
  cur.raster_valid = valid;
  if (!valid) return;
  const glm::vec3 window = c.viewport_transform().window(clip);
  // A valid raster position is a selection hit (GL 2.1 §5.2).
  if (c.render_mode() == GL_SELECT) c.select_hit(window.z);
  cur.raster_pos = glm::vec4(window, clip.w);
  cur.raster_distance = std::abs(eye.z);
  cur.raster_color = glm::clamp(cur.color, 0.0f, 1.0f);
  if (c.s.light.lighting) {
    // The raster colour is lit like a vertex (GL 2.1 §2.13): evaluate the shader's lighting.
    FFUniforms u;
    u.lighting = true;
    u.model_ambient = c.s.light.model_ambient;
    u.material = c.s.light.material;
    u.local_viewer = c.s.light.local_viewer;
    for (int i = 0; i < kMaxLights; ++i)
      if (c.s.light.enabled[size_t(i)]) u.lights[size_t(u.light_count++)] = c.s.light.light[size_t(i)];
    const glm::vec3 n =
        glm::normalize(glm::transpose(glm::inverse(glm::mat3(c.modelview()))) * c.s.current.normal);
    const gpu::Vec4<float> col(cur.color.r, cur.color.g, cur.color.b, cur.color.a);
    const gpu::Vec4<float> lit = ffdetail::light_face<float>(u, 0, gpu::Vec3<float>(eye.x, eye.y, eye.z),
                                                             gpu::Vec3<float>(n.x, n.y, n.z), col);
    cur.raster_color = glm::vec4(lit.x, lit.y, lit.z, lit.w);
  }
  cur.raster_tex = cur.tex;
}

}  // namespace tessel::gl

using namespace tessel::gl;

#define VERTEX4(x, y, z, w)                                                   \
  GL_COMPAT_CONTEXT();                                                        \
  const float vx_ = float(x), vy_ = float(y), vz_ = float(z), vw_ = float(w); \
  GL_LISTED(vertex(c, vx_, vy_, vz_, vw_));                                   \
  vertex(c, vx_, vy_, vz_, vw_)

extern "C" {

void GLAPIENTRY glBegin(GLenum mode) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(begin(c, mode));
  begin(c, mode);
}
void GLAPIENTRY glEnd(void) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(end(c));
  end(c);
}

void GLAPIENTRY glVertex2d(GLdouble x, GLdouble y) { VERTEX4(x, y, 0, 1); }
void GLAPIENTRY glVertex2f(GLfloat x, GLfloat y) { VERTEX4(x, y, 0, 1); }
void GLAPIENTRY glVertex2i(GLint x, GLint y) { VERTEX4(x, y, 0, 1); }
void GLAPIENTRY glVertex2s(GLshort x, GLshort y) { VERTEX4(x, y, 0, 1); }
void GLAPIENTRY glVertex3d(GLdouble x, GLdouble y, GLdouble z) { VERTEX4(x, y, z, 1); }
void GLAPIENTRY glVertex3f(GLfloat x, GLfloat y, GLfloat z) { VERTEX4(x, y, z, 1); }
void GLAPIENTRY glVertex3i(GLint x, GLint y, GLint z) { VERTEX4(x, y, z, 1); }
void GLAPIENTRY glVertex3s(GLshort x, GLshort y, GLshort z) { VERTEX4(x, y, z, 1); }
void GLAPIENTRY glVertex4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w) { VERTEX4(x, y, z, w); }
void GLAPIENTRY glVertex4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) { VERTEX4(x, y, z, w); }
void GLAPIENTRY glVertex4i(GLint x, GLint y, GLint z, GLint w) { VERTEX4(x, y, z, w); }
void GLAPIENTRY glVertex4s(GLshort x, GLshort y, GLshort z, GLshort w) { VERTEX4(x, y, z, w); }
void GLAPIENTRY glVertex2dv(const GLdouble* v) { VERTEX4(v[0], v[1], 0, 1); }
void GLAPIENTRY glVertex2fv(const GLfloat* v) { VERTEX4(v[0], v[1], 0, 1); }
void GLAPIENTRY glVertex2iv(const GLint* v) { VERTEX4(v[0], v[1], 0, 1); }
void GLAPIENTRY glVertex2sv(const GLshort* v) { VERTEX4(v[0], v[1], 0, 1); }
void GLAPIENTRY glVertex3dv(const GLdouble* v) { VERTEX4(v[0], v[1], v[2], 1); }
void GLAPIENTRY glVertex3fv(const GLfloat* v) { VERTEX4(v[0], v[1], v[2], 1); }
void GLAPIENTRY glVertex3iv(const GLint* v) { VERTEX4(v[0], v[1], v[2], 1); }
void GLAPIENTRY glVertex3sv(const GLshort* v) { VERTEX4(v[0], v[1], v[2], 1); }
void GLAPIENTRY glVertex4dv(const GLdouble* v) { VERTEX4(v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glVertex4fv(const GLfloat* v) { VERTEX4(v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glVertex4iv(const GLint* v) { VERTEX4(v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glVertex4sv(const GLshort* v) { VERTEX4(v[0], v[1], v[2], v[3]); }

#define COLOR4(r, g, b, a)                                \
  GL_COMPAT_CONTEXT();                                    \
  const float cr_ = (r), cg_ = (g), cb_ = (b), ca_ = (a); \
  GL_LISTED(set_color(c, cr_, cg_, cb_, ca_));            \
  set_color(c, cr_, cg_, cb_, ca_)

void GLAPIENTRY glColor3b(GLbyte r, GLbyte g, GLbyte b) { COLOR4(sb(r), sb(g), sb(b), 1.0f); }
void GLAPIENTRY glColor3d(GLdouble r, GLdouble g, GLdouble b) { COLOR4(float(r), float(g), float(b), 1.0f); }
void GLAPIENTRY glColor3f(GLfloat r, GLfloat g, GLfloat b) { COLOR4(r, g, b, 1.0f); }
void GLAPIENTRY glColor3i(GLint r, GLint g, GLint b) { COLOR4(si(r), si(g), si(b), 1.0f); }
void GLAPIENTRY glColor3s(GLshort r, GLshort g, GLshort b) { COLOR4(ss(r), ss(g), ss(b), 1.0f); }
void GLAPIENTRY glColor3ub(GLubyte r, GLubyte g, GLubyte b) { COLOR4(ub(r), ub(g), ub(b), 1.0f); }
void GLAPIENTRY glColor3ui(GLuint r, GLuint g, GLuint b) { COLOR4(ui(r), ui(g), ui(b), 1.0f); }
void GLAPIENTRY glColor3us(GLushort r, GLushort g, GLushort b) { COLOR4(us(r), us(g), us(b), 1.0f); }
void GLAPIENTRY glColor4b(GLbyte r, GLbyte g, GLbyte b, GLbyte a) { COLOR4(sb(r), sb(g), sb(b), sb(a)); }
void GLAPIENTRY glColor4d(GLdouble r, GLdouble g, GLdouble b, GLdouble a) {
  COLOR4(float(r), float(g), float(b), float(a));
}
void GLAPIENTRY glColor4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a) { COLOR4(r, g, b, a); }
void GLAPIENTRY glColor4i(GLint r, GLint g, GLint b, GLint a) { COLOR4(si(r), si(g), si(b), si(a)); }
void GLAPIENTRY glColor4s(GLshort r, GLshort g, GLshort b, GLshort a) { COLOR4(ss(r), ss(g), ss(b), ss(a)); }
void GLAPIENTRY glColor4ub(GLubyte r, GLubyte g, GLubyte b, GLubyte a) { COLOR4(ub(r), ub(g), ub(b), ub(a)); }
void GLAPIENTRY glColor4ui(GLuint r, GLuint g, GLuint b, GLuint a) { COLOR4(ui(r), ui(g), ui(b), ui(a)); }
void GLAPIENTRY glColor4us(GLushort r, GLushort g, GLushort b, GLushort a) {
  COLOR4(us(r), us(g), us(b), us(a));
}
void GLAPIENTRY glColor3bv(const GLbyte* v) { COLOR4(sb(v[0]), sb(v[1]), sb(v[2]), 1.0f); }
void GLAPIENTRY glColor3dv(const GLdouble* v) { COLOR4(float(v[0]), float(v[1]), float(v[2]), 1.0f); }
void GLAPIENTRY glColor3fv(const GLfloat* v) { COLOR4(v[0], v[1], v[2], 1.0f); }
void GLAPIENTRY glColor3iv(const GLint* v) { COLOR4(si(v[0]), si(v[1]), si(v[2]), 1.0f); }
void GLAPIENTRY glColor3sv(const GLshort* v) { COLOR4(ss(v[0]), ss(v[1]), ss(v[2]), 1.0f); }
void GLAPIENTRY glColor3ubv(const GLubyte* v) { COLOR4(ub(v[0]), ub(v[1]), ub(v[2]), 1.0f); }
void GLAPIENTRY glColor3uiv(const GLuint* v) { COLOR4(ui(v[0]), ui(v[1]), ui(v[2]), 1.0f); }
void GLAPIENTRY glColor3usv(const GLushort* v) { COLOR4(us(v[0]), us(v[1]), us(v[2]), 1.0f); }
void GLAPIENTRY glColor4bv(const GLbyte* v) { COLOR4(sb(v[0]), sb(v[1]), sb(v[2]), sb(v[3])); }
void GLAPIENTRY glColor4dv(const GLdouble* v) { COLOR4(float(v[0]), float(v[1]), float(v[2]), float(v[3])); }
void GLAPIENTRY glColor4fv(const GLfloat* v) { COLOR4(v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glColor4iv(const GLint* v) { COLOR4(si(v[0]), si(v[1]), si(v[2]), si(v[3])); }
void GLAPIENTRY glColor4sv(const GLshort* v) { COLOR4(ss(v[0]), ss(v[1]), ss(v[2]), ss(v[3])); }
void GLAPIENTRY glColor4ubv(const GLubyte* v) { COLOR4(ub(v[0]), ub(v[1]), ub(v[2]), ub(v[3])); }
void GLAPIENTRY glColor4uiv(const GLuint* v) { COLOR4(ui(v[0]), ui(v[1]), ui(v[2]), ui(v[3])); }
void GLAPIENTRY glColor4usv(const GLushort* v) { COLOR4(us(v[0]), us(v[1]), us(v[2]), us(v[3])); }

#define NORMAL3(x, y, z)                       \
  GL_COMPAT_CONTEXT();                         \
  const float nx_ = (x), ny_ = (y), nz_ = (z); \
  GL_LISTED(set_normal(c, nx_, ny_, nz_));     \
  set_normal(c, nx_, ny_, nz_)

void GLAPIENTRY glNormal3b(GLbyte x, GLbyte y, GLbyte z) { NORMAL3(sb(x), sb(y), sb(z)); }
void GLAPIENTRY glNormal3d(GLdouble x, GLdouble y, GLdouble z) { NORMAL3(float(x), float(y), float(z)); }
void GLAPIENTRY glNormal3f(GLfloat x, GLfloat y, GLfloat z) { NORMAL3(x, y, z); }
void GLAPIENTRY glNormal3i(GLint x, GLint y, GLint z) { NORMAL3(si(x), si(y), si(z)); }
void GLAPIENTRY glNormal3s(GLshort x, GLshort y, GLshort z) { NORMAL3(ss(x), ss(y), ss(z)); }
void GLAPIENTRY glNormal3bv(const GLbyte* v) { NORMAL3(sb(v[0]), sb(v[1]), sb(v[2])); }
void GLAPIENTRY glNormal3dv(const GLdouble* v) { NORMAL3(float(v[0]), float(v[1]), float(v[2])); }
void GLAPIENTRY glNormal3fv(const GLfloat* v) { NORMAL3(v[0], v[1], v[2]); }
void GLAPIENTRY glNormal3iv(const GLint* v) { NORMAL3(si(v[0]), si(v[1]), si(v[2])); }
void GLAPIENTRY glNormal3sv(const GLshort* v) { NORMAL3(ss(v[0]), ss(v[1]), ss(v[2])); }

#define TEX4(s, t, r, q)                                                      \
  GL_COMPAT_CONTEXT();                                                        \
  const float ts_ = float(s), tt_ = float(t), tr_ = float(r), tq_ = float(q); \
  GL_LISTED(set_tex(c, ts_, tt_, tr_, tq_));                                  \
  set_tex(c, ts_, tt_, tr_, tq_)

void GLAPIENTRY glTexCoord1d(GLdouble s) { TEX4(s, 0, 0, 1); }
void GLAPIENTRY glTexCoord1f(GLfloat s) { TEX4(s, 0, 0, 1); }
void GLAPIENTRY glTexCoord1i(GLint s) { TEX4(s, 0, 0, 1); }
void GLAPIENTRY glTexCoord1s(GLshort s) { TEX4(s, 0, 0, 1); }
void GLAPIENTRY glTexCoord2d(GLdouble s, GLdouble t) { TEX4(s, t, 0, 1); }
void GLAPIENTRY glTexCoord2f(GLfloat s, GLfloat t) { TEX4(s, t, 0, 1); }
void GLAPIENTRY glTexCoord2i(GLint s, GLint t) { TEX4(s, t, 0, 1); }
void GLAPIENTRY glTexCoord2s(GLshort s, GLshort t) { TEX4(s, t, 0, 1); }
void GLAPIENTRY glTexCoord3d(GLdouble s, GLdouble t, GLdouble r) { TEX4(s, t, r, 1); }
void GLAPIENTRY glTexCoord3f(GLfloat s, GLfloat t, GLfloat r) { TEX4(s, t, r, 1); }
void GLAPIENTRY glTexCoord3i(GLint s, GLint t, GLint r) { TEX4(s, t, r, 1); }
void GLAPIENTRY glTexCoord3s(GLshort s, GLshort t, GLshort r) { TEX4(s, t, r, 1); }
void GLAPIENTRY glTexCoord4d(GLdouble s, GLdouble t, GLdouble r, GLdouble q) { TEX4(s, t, r, q); }
void GLAPIENTRY glTexCoord4f(GLfloat s, GLfloat t, GLfloat r, GLfloat q) { TEX4(s, t, r, q); }
void GLAPIENTRY glTexCoord4i(GLint s, GLint t, GLint r, GLint q) { TEX4(s, t, r, q); }
void GLAPIENTRY glTexCoord4s(GLshort s, GLshort t, GLshort r, GLshort q) { TEX4(s, t, r, q); }
void GLAPIENTRY glTexCoord1dv(const GLdouble* v) { TEX4(v[0], 0, 0, 1); }
void GLAPIENTRY glTexCoord1fv(const GLfloat* v) { TEX4(v[0], 0, 0, 1); }
void GLAPIENTRY glTexCoord1iv(const GLint* v) { TEX4(v[0], 0, 0, 1); }
void GLAPIENTRY glTexCoord1sv(const GLshort* v) { TEX4(v[0], 0, 0, 1); }
void GLAPIENTRY glTexCoord2dv(const GLdouble* v) { TEX4(v[0], v[1], 0, 1); }
void GLAPIENTRY glTexCoord2fv(const GLfloat* v) { TEX4(v[0], v[1], 0, 1); }
void GLAPIENTRY glTexCoord2iv(const GLint* v) { TEX4(v[0], v[1], 0, 1); }
void GLAPIENTRY glTexCoord2sv(const GLshort* v) { TEX4(v[0], v[1], 0, 1); }
void GLAPIENTRY glTexCoord3dv(const GLdouble* v) { TEX4(v[0], v[1], v[2], 1); }
void GLAPIENTRY glTexCoord3fv(const GLfloat* v) { TEX4(v[0], v[1], v[2], 1); }
void GLAPIENTRY glTexCoord3iv(const GLint* v) { TEX4(v[0], v[1], v[2], 1); }
void GLAPIENTRY glTexCoord3sv(const GLshort* v) { TEX4(v[0], v[1], v[2], 1); }
void GLAPIENTRY glTexCoord4dv(const GLdouble* v) { TEX4(v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glTexCoord4fv(const GLfloat* v) { TEX4(v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glTexCoord4iv(const GLint* v) { TEX4(v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glTexCoord4sv(const GLshort* v) { TEX4(v[0], v[1], v[2], v[3]); }

void GLAPIENTRY glEdgeFlag(GLboolean flag) {
  GL_COMPAT_CONTEXT();
  const bool f = flag != GL_FALSE;
  GL_LISTED(c.s.current.edge = f);
  c.s.current.edge = f;
}
void GLAPIENTRY glEdgeFlagv(const GLboolean* flag) { glEdgeFlag(*flag); }

// glRect: a polygon (x1,y1), (x2,y1), (x2,y2), (x1,y2) in z = 0 (GL 2.1 §2.10).
#define RECT(x1, y1, x2, y2)                                                      \
  GL_COMPAT_CONTEXT();                                                            \
  const float ax_ = float(x1), ay_ = float(y1), bx_ = float(x2), by_ = float(y2); \
  auto rect_ = [=](Context& c) {                                                  \
    GL_OUTSIDE_BEGIN();                                                           \
    begin(c, GL_POLYGON);                                                         \
    vertex(c, ax_, ay_, 0, 1);                                                    \
    vertex(c, bx_, ay_, 0, 1);                                                    \
    vertex(c, bx_, by_, 0, 1);                                                    \
    vertex(c, ax_, by_, 0, 1);                                                    \
    c.end();                                                                      \
  };                                                                              \
  GL_LISTED(rect_(c));                                                            \
  rect_(c)

void GLAPIENTRY glRectd(GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2) { RECT(x1, y1, x2, y2); }
void GLAPIENTRY glRectf(GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2) { RECT(x1, y1, x2, y2); }
void GLAPIENTRY glRecti(GLint x1, GLint y1, GLint x2, GLint y2) { RECT(x1, y1, x2, y2); }
void GLAPIENTRY glRects(GLshort x1, GLshort y1, GLshort x2, GLshort y2) { RECT(x1, y1, x2, y2); }
void GLAPIENTRY glRectdv(const GLdouble* a, const GLdouble* b) { RECT(a[0], a[1], b[0], b[1]); }
void GLAPIENTRY glRectfv(const GLfloat* a, const GLfloat* b) { RECT(a[0], a[1], b[0], b[1]); }
void GLAPIENTRY glRectiv(const GLint* a, const GLint* b) { RECT(a[0], a[1], b[0], b[1]); }
void GLAPIENTRY glRectsv(const GLshort* a, const GLshort* b) { RECT(a[0], a[1], b[0], b[1]); }

#define RASTER4(x, y, z, w)                                                   \
  GL_COMPAT_CONTEXT();                                                        \
  const float rx_ = float(x), ry_ = float(y), rz_ = float(z), rw_ = float(w); \
  GL_LISTED(raster_pos(c, rx_, ry_, rz_, rw_));                               \
  raster_pos(c, rx_, ry_, rz_, rw_)

void GLAPIENTRY glRasterPos2d(GLdouble x, GLdouble y) { RASTER4(x, y, 0, 1); }
void GLAPIENTRY glRasterPos2f(GLfloat x, GLfloat y) { RASTER4(x, y, 0, 1); }
void GLAPIENTRY glRasterPos2i(GLint x, GLint y) { RASTER4(x, y, 0, 1); }
void GLAPIENTRY glRasterPos2s(GLshort x, GLshort y) { RASTER4(x, y, 0, 1); }
void GLAPIENTRY glRasterPos3d(GLdouble x, GLdouble y, GLdouble z) { RASTER4(x, y, z, 1); }
void GLAPIENTRY glRasterPos3f(GLfloat x, GLfloat y, GLfloat z) { RASTER4(x, y, z, 1); }
void GLAPIENTRY glRasterPos3i(GLint x, GLint y, GLint z) { RASTER4(x, y, z, 1); }
void GLAPIENTRY glRasterPos3s(GLshort x, GLshort y, GLshort z) { RASTER4(x, y, z, 1); }
void GLAPIENTRY glRasterPos4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w) { RASTER4(x, y, z, w); }
void GLAPIENTRY glRasterPos4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) { RASTER4(x, y, z, w); }
void GLAPIENTRY glRasterPos4i(GLint x, GLint y, GLint z, GLint w) { RASTER4(x, y, z, w); }
void GLAPIENTRY glRasterPos4s(GLshort x, GLshort y, GLshort z, GLshort w) { RASTER4(x, y, z, w); }
void GLAPIENTRY glRasterPos2dv(const GLdouble* v) { RASTER4(v[0], v[1], 0, 1); }
void GLAPIENTRY glRasterPos2fv(const GLfloat* v) { RASTER4(v[0], v[1], 0, 1); }
void GLAPIENTRY glRasterPos2iv(const GLint* v) { RASTER4(v[0], v[1], 0, 1); }
void GLAPIENTRY glRasterPos2sv(const GLshort* v) { RASTER4(v[0], v[1], 0, 1); }
void GLAPIENTRY glRasterPos3dv(const GLdouble* v) { RASTER4(v[0], v[1], v[2], 1); }
void GLAPIENTRY glRasterPos3fv(const GLfloat* v) { RASTER4(v[0], v[1], v[2], 1); }
void GLAPIENTRY glRasterPos3iv(const GLint* v) { RASTER4(v[0], v[1], v[2], 1); }
void GLAPIENTRY glRasterPos3sv(const GLshort* v) { RASTER4(v[0], v[1], v[2], 1); }
void GLAPIENTRY glRasterPos4dv(const GLdouble* v) { RASTER4(v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glRasterPos4fv(const GLfloat* v) { RASTER4(v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glRasterPos4iv(const GLint* v) { RASTER4(v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glRasterPos4sv(const GLshort* v) { RASTER4(v[0], v[1], v[2], v[3]); }

}  // extern "C"
