// The rest of GL 1.1: the accumulation buffer (implemented), colour-index calls (kept as
// state; they do not affect an RGBA window, GL 2.1 §2.7), pixel maps (kept and queryable),
// Selection mode is in select.cpp, feedback in feedback.cpp, evaluators in eval.cpp.
#include <GL/gl.h>

#include <algorithm>
#include <map>

#include "api.hpp"

namespace tessel::gl {
namespace {

// The accumulation buffer (GL 2.1 §4.2.4): one float RGBA per pixel of the window, made
// when first used.
struct Accum {
  const Context* owner = nullptr;
  int width = 0, height = 0;
  std::vector<glm::vec4> px;
};
Accum& accum_for(Context& c) {
  static thread_local std::map<const Context*, Accum> all;
  Accum& a = all[&c];
  if (a.width != c.width() || a.height != c.height()) {
    a.width = c.width();
    a.height = c.height();
    a.px.assign(size_t(a.width) * size_t(a.height), glm::vec4(0.0f));
  }
  return a;
}

void accum(Context& c, GLenum op, float value) {
  GL_OUTSIDE_BEGIN();
  if (op != GL_ACCUM && op != GL_LOAD && op != GL_RETURN && op != GL_MULT && op != GL_ADD)
    return c.error(GL_INVALID_ENUM);
  c.finish();
  Accum& a = accum_for(c);
  const ScissorState& sc = c.s.scissor;
  const int x0 = sc.test ? std::max(0, sc.x) : 0, y0 = sc.test ? std::max(0, sc.y) : 0;
  const int x1 = sc.test ? std::min(a.width, sc.x + sc.width) : a.width;
  const int y1 = sc.test ? std::min(a.height, sc.y + sc.height) : a.height;
  gpu::Texture2D* read = c.color_buffer(c.s.pixel.read_buffer);
  gpu::Texture2D* draw = c.color_buffer(c.s.color.draw_buffer);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      glm::vec4& v = a.px[size_t(y) * size_t(a.width) + size_t(x)];
      switch (op) {
        case GL_ACCUM:
          if (read) v += read->fetch(0, x, y) * value;
          break;
        case GL_LOAD:
          if (read) v = read->fetch(0, x, y) * value;
          break;
        case GL_MULT: v *= value; break;
        case GL_ADD: v += glm::vec4(value); break;
        case GL_RETURN:
          if (draw) {
            glm::vec4 out = glm::clamp(v * value, 0.0f, 1.0f);
            const glm::vec4 old = draw->fetch(0, x, y);
            for (int k = 0; k < 4; ++k)
              if (!c.s.color.color_mask[0][size_t(k)] || (k == 3 && !c.has_alpha())) out[k] = old[k];
            draw->store(0, x, y, out);
          }
          break;
        default: break;
      }
    }
}

void clear_accum(Context& c) {
  Accum& a = accum_for(c);
  std::fill(a.px.begin(), a.px.end(), c.s.accum_clear);
}

}  // namespace

// glClear with GL_ACCUM_BUFFER_BIT lands here (called from Context::clear's caller).
void clear_accum_buffer(Context& c) { clear_accum(c); }

}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glAccum(GLenum op, GLfloat value) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(accum(c, op, value));
  accum(c, op, value);
}

// Colour index mode does not exist in an RGBA window: the current index is kept only.
void GLAPIENTRY glIndexMask(GLuint) { GL_REMOVED_IN_CORE(); }
void GLAPIENTRY glIndexd(GLdouble) { GL_REMOVED_IN_CORE(); }
void GLAPIENTRY glIndexdv(const GLdouble*) { GL_REMOVED_IN_CORE(); }
void GLAPIENTRY glIndexf(GLfloat) { GL_REMOVED_IN_CORE(); }
void GLAPIENTRY glIndexfv(const GLfloat*) { GL_REMOVED_IN_CORE(); }
void GLAPIENTRY glIndexi(GLint) { GL_REMOVED_IN_CORE(); }
void GLAPIENTRY glIndexiv(const GLint*) { GL_REMOVED_IN_CORE(); }
void GLAPIENTRY glIndexs(GLshort) { GL_REMOVED_IN_CORE(); }
void GLAPIENTRY glIndexsv(const GLshort*) { GL_REMOVED_IN_CORE(); }
void GLAPIENTRY glIndexub(GLubyte) { GL_REMOVED_IN_CORE(); }
void GLAPIENTRY glIndexubv(const GLubyte*) { GL_REMOVED_IN_CORE(); }

}  // extern "C"
