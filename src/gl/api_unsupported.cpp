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

// Pixel maps (GL 2.1 §3.6.3): kept so they can be queried.
std::map<GLenum, std::vector<float>>& pixel_maps() {
  static thread_local std::map<GLenum, std::vector<float>> maps;
  return maps;
}
bool valid_map(GLenum m) { return m >= GL_PIXEL_MAP_I_TO_I && m <= GL_PIXEL_MAP_A_TO_A; }

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

void GLAPIENTRY glPixelMapfv(GLenum map, GLsizei n, const GLfloat* values) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!valid_map(map)) return c.error(GL_INVALID_ENUM);
  if (n < 1 || n > 256) return c.error(GL_INVALID_VALUE);
  if (map <= GL_PIXEL_MAP_I_TO_A && (n & (n - 1))) return c.error(GL_INVALID_VALUE);
  pixel_maps()[map].assign(values, values + n);
}
void GLAPIENTRY glPixelMapuiv(GLenum map, GLsizei n, const GLuint* values) {
  GL_REMOVED_IN_CORE();
  std::vector<float> v(size_t(std::max(n, 0)));
  for (size_t i = 0; i < v.size() && values; ++i) v[i] = float(double(values[i]) / 4294967295.0);
  glPixelMapfv(map, n, v.data());
}
void GLAPIENTRY glPixelMapusv(GLenum map, GLsizei n, const GLushort* values) {
  GL_REMOVED_IN_CORE();
  std::vector<float> v(size_t(std::max(n, 0)));
  for (size_t i = 0; i < v.size() && values; ++i) v[i] = float(values[i]) / 65535.0f;
  glPixelMapfv(map, n, v.data());
}
void GLAPIENTRY glGetPixelMapfv(GLenum map, GLfloat* values) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!valid_map(map)) return c.error(GL_INVALID_ENUM);
  const auto it = pixel_maps().find(map);
  if (!values) return;
  if (it == pixel_maps().end())
    values[0] = 0.0f;
  else
    std::copy(it->second.begin(), it->second.end(), values);
}
void GLAPIENTRY glGetPixelMapuiv(GLenum map, GLuint* values) {
  GL_REMOVED_IN_CORE();
  GLfloat tmp[256] = {};
  glGetPixelMapfv(map, tmp);
  const auto it = pixel_maps().find(map);
  const size_t n = it == pixel_maps().end() ? 1 : it->second.size();
  for (size_t i = 0; i < n && values; ++i) values[i] = GLuint(double(tmp[i]) * 4294967295.0);
}
void GLAPIENTRY glGetPixelMapusv(GLenum map, GLushort* values) {
  GL_REMOVED_IN_CORE();
  GLfloat tmp[256] = {};
  glGetPixelMapfv(map, tmp);
  const auto it = pixel_maps().find(map);
  const size_t n = it == pixel_maps().end() ? 1 : it->second.size();
  for (size_t i = 0; i < n && values; ++i) values[i] = GLushort(tmp[i] * 65535.0f);
}

}  // extern "C"
