// The matrix stacks (GL 2.1 §2.11.2): glMatrixMode, glLoadIdentity, glLoadMatrix,
// glMultMatrix (column-major, as GL stores them), glTranslate, glRotate, glScale, glFrustum,
// glOrtho, glPushMatrix, glPopMatrix; and glViewport / glDepthRange (§2.11.1).
#include <GL/gl.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "api.hpp"

namespace tessel::gl {

void mult_matrix(Context& c, const glm::mat4& m) {
  GL_OUTSIDE_BEGIN();
  c.touch();
  c.top() = c.top() * m;
}

void load_matrix(Context& c, const glm::mat4& m) {
  GL_OUTSIDE_BEGIN();
  c.touch();
  c.top() = m;
}

namespace {

void matrix_mode(Context& c, GLenum mode) {
  GL_OUTSIDE_BEGIN();
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) {
    c.error(GL_INVALID_ENUM);
    return;
  }
  // A texture unit without a coordinate set has no texture matrix (Mesa: GL_INVALID_OPERATION).
  if (mode == GL_TEXTURE && c.s.active_unit >= GLuint(kMaxTexCoords)) return c.error(GL_INVALID_OPERATION);
  c.s.transform.matrix_mode = mode;
}

void push_matrix(Context& c) {
  GL_OUTSIDE_BEGIN();
  auto& stack = c.matrices[size_t(c.matrix_index())];
  const int depth = c.matrix_index() == 0   ? kModelviewDepth
                    : c.matrix_index() == 1 ? kProjectionDepth
                                            : kTextureDepth;
  if (int(stack.size()) >= depth) {
    c.error(GL_STACK_OVERFLOW);
    return;
  }
  stack.push_back(stack.back());
}

void pop_matrix(Context& c) {
  GL_OUTSIDE_BEGIN();
  auto& stack = c.matrices[size_t(c.matrix_index())];
  if (stack.size() <= 1) {
    c.error(GL_STACK_UNDERFLOW);
    return;
  }
  c.touch();
  stack.pop_back();
}

// GL 2.1 §2.11.2, eq. for glRotate: the rotation by `angle` degrees about (x, y, z).
glm::mat4 rotation(float angle, float x, float y, float z) {
  const float len = std::sqrt(x * x + y * y + z * z);
  if (len == 0.0f) return glm::mat4(1.0f);
  x /= len, y /= len, z /= len;
  const float a = angle * float(M_PI / 180.0);
  const float cs = std::cos(a), sn = std::sin(a), t = 1.0f - cs;
  glm::mat4 m(1.0f);
  m[0][0] = x * x * t + cs, m[1][0] = x * y * t - z * sn, m[2][0] = x * z * t + y * sn;
  m[0][1] = y * x * t + z * sn, m[1][1] = y * y * t + cs, m[2][1] = y * z * t - x * sn;
  m[0][2] = z * x * t - y * sn, m[1][2] = z * y * t + x * sn, m[2][2] = z * z * t + cs;
  return m;
}

void frustum(Context& c, double l, double r, double b, double t, double n, double f) {
  GL_OUTSIDE_BEGIN();
  if (n <= 0.0 || f <= 0.0 || l == r || b == t || n == f) {
    c.error(GL_INVALID_VALUE);
    return;
  }
  glm::dmat4 m(0.0);
  m[0][0] = 2.0 * n / (r - l);
  m[1][1] = 2.0 * n / (t - b);
  m[2][0] = (r + l) / (r - l);
  m[2][1] = (t + b) / (t - b);
  m[2][2] = -(f + n) / (f - n);
  m[2][3] = -1.0;
  m[3][2] = -2.0 * f * n / (f - n);
  mult_matrix(c, glm::mat4(m));
}

void ortho(Context& c, double l, double r, double b, double t, double n, double f) {
  GL_OUTSIDE_BEGIN();
  if (l == r || b == t || n == f) {
    c.error(GL_INVALID_VALUE);
    return;
  }
  glm::dmat4 m(1.0);
  m[0][0] = 2.0 / (r - l);
  m[1][1] = 2.0 / (t - b);
  m[2][2] = -2.0 / (f - n);
  m[3][0] = -(r + l) / (r - l);
  m[3][1] = -(t + b) / (t - b);
  m[3][2] = -(f + n) / (f - n);
  mult_matrix(c, glm::mat4(m));
}

void viewport(Context& c, GLint x, GLint y, GLsizei w, GLsizei h) {
  GL_OUTSIDE_BEGIN();
  if (w < 0 || h < 0) {
    c.error(GL_INVALID_VALUE);
    return;
  }
  c.touch();
  c.s.viewport.x = x;
  c.s.viewport.y = y;
  c.s.viewport.width = std::min(w, GLsizei(gpu::kMaxViewportSize));
  c.s.viewport.height = std::min(h, GLsizei(gpu::kMaxViewportSize));
}

void depth_range(Context& c, double n, double f) {
  GL_OUTSIDE_BEGIN();
  c.touch();
  c.s.viewport.near_ = std::clamp(n, 0.0, 1.0);
  c.s.viewport.far_ = std::clamp(f, 0.0, 1.0);
}

template <class T>
glm::mat4 mat_from(const T* m) {
  glm::mat4 r;
  for (int i = 0; i < 16; ++i) glm::value_ptr(r)[i] = float(m[i]);
  return r;
}

}  // namespace
}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glMatrixMode(GLenum mode) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(matrix_mode(c, mode));
  matrix_mode(c, mode);
}
void GLAPIENTRY glLoadIdentity(void) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(load_matrix(c, glm::mat4(1.0f)));
  load_matrix(c, glm::mat4(1.0f));
}
void GLAPIENTRY glLoadMatrixf(const GLfloat* m) {
  GL_COMPAT_CONTEXT();
  const glm::mat4 a = mat_from(m);
  GL_LISTED(load_matrix(c, a));
  load_matrix(c, a);
}
void GLAPIENTRY glLoadMatrixd(const GLdouble* m) {
  GL_COMPAT_CONTEXT();
  const glm::mat4 a = mat_from(m);
  GL_LISTED(load_matrix(c, a));
  load_matrix(c, a);
}
void GLAPIENTRY glMultMatrixf(const GLfloat* m) {
  GL_COMPAT_CONTEXT();
  const glm::mat4 a = mat_from(m);
  GL_LISTED(mult_matrix(c, a));
  mult_matrix(c, a);
}
void GLAPIENTRY glMultMatrixd(const GLdouble* m) {
  GL_COMPAT_CONTEXT();
  const glm::mat4 a = mat_from(m);
  GL_LISTED(mult_matrix(c, a));
  mult_matrix(c, a);
}
void GLAPIENTRY glTranslatef(GLfloat x, GLfloat y, GLfloat z) {
  GL_COMPAT_CONTEXT();
  glm::mat4 m(1.0f);
  m[3] = glm::vec4(x, y, z, 1.0f);
  GL_LISTED(mult_matrix(c, m));
  mult_matrix(c, m);
}
void GLAPIENTRY glTranslated(GLdouble x, GLdouble y, GLdouble z) {
  glTranslatef(float(x), float(y), float(z));
}
void GLAPIENTRY glScalef(GLfloat x, GLfloat y, GLfloat z) {
  GL_COMPAT_CONTEXT();
  const glm::mat4 m(glm::vec4(x, 0, 0, 0), glm::vec4(0, y, 0, 0), glm::vec4(0, 0, z, 0),
                    glm::vec4(0, 0, 0, 1));
  GL_LISTED(mult_matrix(c, m));
  mult_matrix(c, m);
}
void GLAPIENTRY glScaled(GLdouble x, GLdouble y, GLdouble z) { glScalef(float(x), float(y), float(z)); }
void GLAPIENTRY glRotatef(GLfloat angle, GLfloat x, GLfloat y, GLfloat z) {
  GL_COMPAT_CONTEXT();
  const glm::mat4 m = rotation(angle, x, y, z);
  GL_LISTED(mult_matrix(c, m));
  mult_matrix(c, m);
}
void GLAPIENTRY glRotated(GLdouble angle, GLdouble x, GLdouble y, GLdouble z) {
  glRotatef(float(angle), float(x), float(y), float(z));
}
void GLAPIENTRY glFrustum(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(frustum(c, l, r, b, t, n, f));
  frustum(c, l, r, b, t, n, f);
}
void GLAPIENTRY glOrtho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(ortho(c, l, r, b, t, n, f));
  ortho(c, l, r, b, t, n, f);
}
void GLAPIENTRY glPushMatrix(void) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(push_matrix(c));
  push_matrix(c);
}
void GLAPIENTRY glPopMatrix(void) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(pop_matrix(c));
  pop_matrix(c);
}
void GLAPIENTRY glViewport(GLint x, GLint y, GLsizei w, GLsizei h) {
  GL_CONTEXT();
  GL_LISTED(viewport(c, x, y, w, h));
  viewport(c, x, y, w, h);
}
void GLAPIENTRY glDepthRange(GLclampd n, GLclampd f) {
  GL_CONTEXT();
  GL_LISTED(depth_range(c, n, f));
  depth_range(c, n, f);
}

}  // extern "C"
