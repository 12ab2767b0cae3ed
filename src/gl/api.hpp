// Shared by the GL entry points (api_*.cpp): finding the context, the begin/end rule, and
// display-list recording.
//
// Every entry point follows one pattern:
//   void GLAPIENTRY glFoo(args) {
//     GL_CONTEXT();                 // no current context: the call is ignored
//     GL_LISTED(foo(c, args));      // inside glNewList: recorded (and run for COMPILE_AND_EXECUTE)
//     foo(c, args);                 // validates (errors change nothing) and applies
//   }
// Pointer arguments are copied into values before GL_LISTED, so a list keeps the data the
// call was given (GL 2.1 §5.4).
#pragma once

#include <GL/gl.h>

#include <array>
#include <cmath>

#include "context.hpp"

#define GL_CONTEXT(...)                                  \
  ::tessel::gl::Context* ctx_ = ::tessel::gl::current(); \
  if (ctx_ == nullptr) return __VA_ARGS__;               \
  ::tessel::gl::Context& c = *ctx_

// An entry point the core profile removed (GL 3.2 core, appendix E.2.2; the Khronos registry's
// <remove profile="core"> list): in a core context it does nothing and records
// GL_INVALID_OPERATION, as Mesa's core contexts answer. GL_COMPAT_CONTEXT is GL_CONTEXT with
// that check; GL_REMOVED_IN_CORE is the check alone, for bodies that do not start with it.
#define GL_COMPAT_CONTEXT(...)     \
  GL_CONTEXT(__VA_ARGS__);         \
  if (c.core_profile) {            \
    c.error(GL_INVALID_OPERATION); \
    return __VA_ARGS__;            \
  }                                \
  static_assert(true)
#define GL_REMOVED_IN_CORE(...)                                                                    \
  if (::tessel::gl::Context* rc_ = ::tessel::gl::current(); rc_ != nullptr && rc_->core_profile) { \
    rc_->error(GL_INVALID_OPERATION);                                                              \
    return __VA_ARGS__;                                                                            \
  }                                                                                                \
  static_assert(true)

#define GL_LISTED(...)                                                 \
  do {                                                                 \
    if (c.compiling_list != 0 && !c.record([=]() {                     \
          if (::tessel::gl::Context* rec_ = ::tessel::gl::current()) { \
            [[maybe_unused]] ::tessel::gl::Context& c = *rec_;         \
            __VA_ARGS__;                                               \
          }                                                            \
        }))                                                            \
      return;                                                          \
  } while (0)

// Commands other than vertex attributes, glMaterial, glArrayElement and glCallList(s) are
// errors between glBegin and glEnd (GL 2.1 §2.6.3).
#define GL_OUTSIDE_BEGIN(...)        \
  do {                               \
    if (c.in_begin) {                \
      c.error(GL_INVALID_OPERATION); \
      return __VA_ARGS__;            \
    }                                \
  } while (0)

namespace tessel::gl {

using Vec4Arg = std::array<float, 4>;
// The first n values of a parameter array as floats (zeros where n < 4 or v is null).
template <class T>
inline Vec4Arg take(const T* v, int n) {
  Vec4Arg a{0.0f, 0.0f, 0.0f, 0.0f};
  if (v)
    for (int i = 0; i < n && i < 4; ++i) a[size_t(i)] = float(v[i]);
  return a;
}

// Number of values a glLight / glMaterial / glFog / glLightModel / glTexEnv / glTexGen
// parameter takes (0 when the name is not one of them).
int light_param_count(GLenum pname);
int material_param_count(GLenum pname);

// Internal commands shared by several entry points.
void begin(Context& c, GLenum mode);
void vertex(Context& c, float x, float y, float z, float w);
void call_list(Context& c, GLuint list);
void enable(Context& c, GLenum cap, bool on);
void draw_arrays(Context& c, GLenum mode, GLint first, GLsizei count);
// A draw call with the current program over the generic attribute arrays (draw_glsl.cpp):
// arrays when `type` is GL_NONE, else elements of `type` at `indices`. Validates as GL 3.3
// §2.8.3 says, then draws.
void draw_generic_call(Context& c, GLenum mode, GLint first, GLsizei count, GLsizei instances, GLenum type,
                       const void* indices, GLint base_vertex);
// Whether a draw call goes to draw_generic_call (api_arrays.cpp).
bool generic_draw(Context& c);
void array_element(Context& c, GLint i);
void raster_pos(Context& c, float x, float y, float z, float w);
void mult_matrix(Context& c, const glm::mat4& m);
void load_matrix(Context& c, const glm::mat4& m);
void clear_accum_buffer(Context& c);
// The four components of a packed GL_INT_2_10_10_10_REV / GL_UNSIGNED_INT_2_10_10_10_REV value
// (GL 3.3 §2.8.2), x in the low bits (draw_glsl.cpp).
void unpack_2_10_10_10(uint32_t w, bool is_signed, bool normalized, float* out);

// Object names are taken in increasing order, skipping any in use (GL 3.3 §2.5: unused names).
template <class Map>
GLuint fresh_name(const Map& used, GLuint& next) {
  while (next == 0 || used.count(next)) ++next;
  return next++;
}

// An enum given as a number (glTexParameterf, glFogf, glTexEnvf ...): values that are not a
// GLenum (negative, too large, NaN) become one no switch accepts, without the undefined
// float-to-unsigned conversion.
inline GLenum enum_arg(double v) { return v >= 0.0 && v <= 4294967295.0 ? GLenum(v) : GLenum(0xFFFFFFFFu); }

// Integer colour components as glColor* and glSecondaryColor* take them: to [-1, 1] or [0, 1]
// (GL 2.1 Table 2.9).
namespace colour_arg {
constexpr float ub(GLubyte v) { return float(v) / 255.0f; }
constexpr float us(GLushort v) { return float(v) / 65535.0f; }
constexpr float ui(GLuint v) { return float(double(v) / 4294967295.0); }
constexpr float sb(GLbyte v) { return (2.0f * float(v) + 1.0f) / 255.0f; }
constexpr float ss(GLshort v) { return (2.0f * float(v) + 1.0f) / 65535.0f; }
constexpr float si(GLint v) { return float((2.0 * double(v) + 1.0) / 4294967295.0); }
}  // namespace colour_arg

inline bool is_finite4(float a, float b, float c, float d) {
  return std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(d);
}

}  // namespace tessel::gl
