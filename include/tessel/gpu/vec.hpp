// GLSL-like vectors over a lane type: Vec2<F>, Vec3<F>, Vec4<F> with the GLSL functions.
//
// Uniforms are scalar GLM values (glm::vec3, glm::mat4); whatever varies per vertex or
// fragment is a Vec over F. Mixed arithmetic broadcasts the scalar side.
#pragma once

#include <glm/glm.hpp>

#include "tessel/gpu/simd.hpp"

namespace tessel::gpu {

template <class F>
struct Vec2 {
  F x, y;
  Vec2() = default;
  Vec2(F a, F b) : x(a), y(b) {}
  explicit Vec2(F s) : x(s), y(s) {}
  Vec2(const glm::vec2& v) : x(v.x), y(v.y) {}
};
template <class F>
struct Vec3 {
  F x, y, z;
  Vec3() = default;
  Vec3(F a, F b, F c) : x(a), y(b), z(c) {}
  explicit Vec3(F s) : x(s), y(s), z(s) {}
  Vec3(const glm::vec3& v) : x(v.x), y(v.y), z(v.z) {}
  Vec2<F> xy() const { return {x, y}; }
};
template <class F>
struct Vec4 {
  F x, y, z, w;
  Vec4() = default;
  Vec4(F a, F b, F c, F d) : x(a), y(b), z(c), w(d) {}
  Vec4(const Vec3<F>& v, F d) : x(v.x), y(v.y), z(v.z), w(d) {}
  explicit Vec4(F s) : x(s), y(s), z(s), w(s) {}
  Vec4(const glm::vec4& v) : x(v.x), y(v.y), z(v.z), w(v.w) {}
  Vec3<F> xyz() const { return {x, y, z}; }
  Vec2<F> xy() const { return {x, y}; }
  Vec3<F> rgb() const { return {x, y, z}; }
};

// Componentwise operators, generated for each size.
#define TESSEL_VEC_OPS(V, APPLY)                                                      \
  template <class F>                                                                  \
  inline V<F> operator+(const V<F>& a, const V<F>& b) {                               \
    return APPLY(a, +, b);                                                            \
  }                                                                                   \
  template <class F>                                                                  \
  inline V<F> operator-(const V<F>& a, const V<F>& b) {                               \
    return APPLY(a, -, b);                                                            \
  }                                                                                   \
  template <class F>                                                                  \
  inline V<F> operator*(const V<F>& a, const V<F>& b) {                               \
    return APPLY(a, *, b);                                                            \
  }                                                                                   \
  template <class F>                                                                  \
  inline V<F> operator/(const V<F>& a, const V<F>& b) {                               \
    return APPLY(a, /, b);                                                            \
  }                                                                                   \
  template <class F>                                                                  \
  inline V<F> operator*(const V<F>& a, F s) {                                         \
    return a * V<F>(s);                                                               \
  }                                                                                   \
  template <class F>                                                                  \
  inline V<F> operator*(F s, const V<F>& a) {                                         \
    return V<F>(s) * a;                                                               \
  }                                                                                   \
  template <class F>                                                                  \
  inline V<F> operator/(const V<F>& a, F s) {                                         \
    return a / V<F>(s);                                                               \
  }                                                                                   \
  template <class F>                                                                  \
  requires(!std::is_same_v<F, float>) inline V<F> operator*(const V<F>& a, float s) { \
    return a * V<F>(F(s));                                                            \
  }                                                                                   \
  template <class F>                                                                  \
  requires(!std::is_same_v<F, float>) inline V<F> operator*(float s, const V<F>& a) { \
    return V<F>(F(s)) * a;                                                            \
  }                                                                                   \
  template <class F>                                                                  \
  requires(!std::is_same_v<F, float>) inline V<F> operator/(const V<F>& a, float s) { \
    return a / V<F>(F(s));                                                            \
  }                                                                                   \
  template <class F>                                                                  \
  inline V<F> operator-(const V<F>& a) {                                              \
    return V<F>(F(0.0f)) - a;                                                         \
  }                                                                                   \
  template <class F>                                                                  \
  inline V<F>& operator+=(V<F>& a, const V<F>& b) {                                   \
    return a = a + b;                                                                 \
  }                                                                                   \
  template <class F>                                                                  \
  inline V<F>& operator-=(V<F>& a, const V<F>& b) {                                   \
    return a = a - b;                                                                 \
  }                                                                                   \
  template <class F>                                                                  \
  inline V<F>& operator*=(V<F>& a, const V<F>& b) {                                   \
    return a = a * b;                                                                 \
  }                                                                                   \
  template <class F>                                                                  \
  inline V<F>& operator*=(V<F>& a, F s) {                                             \
    return a = a * s;                                                                 \
  }

#define TESSEL_APPLY2(a, op, b) \
  V2 { a.x op b.x, a.y op b.y }
#define TESSEL_APPLY3(a, op, b) \
  V3 { a.x op b.x, a.y op b.y, a.z op b.z }
#define TESSEL_APPLY4(a, op, b) \
  V4 { a.x op b.x, a.y op b.y, a.z op b.z, a.w op b.w }
#define V2 Vec2<F>
#define V3 Vec3<F>
#define V4 Vec4<F>
TESSEL_VEC_OPS(Vec2, TESSEL_APPLY2)
TESSEL_VEC_OPS(Vec3, TESSEL_APPLY3)
TESSEL_VEC_OPS(Vec4, TESSEL_APPLY4)
#undef V2
#undef V3
#undef V4
#undef TESSEL_APPLY2
#undef TESSEL_APPLY3
#undef TESSEL_APPLY4
#undef TESSEL_VEC_OPS

// Applies a function of one or more F to each component.
template <class F, class Fn>
inline Vec2<F> map(const Vec2<F>& a, Fn f) {
  return {f(a.x), f(a.y)};
}
template <class F, class Fn>
inline Vec3<F> map(const Vec3<F>& a, Fn f) {
  return {f(a.x), f(a.y), f(a.z)};
}
template <class F, class Fn>
inline Vec4<F> map(const Vec4<F>& a, Fn f) {
  return {f(a.x), f(a.y), f(a.z), f(a.w)};
}
template <class F, class Fn>
inline Vec2<F> map2(const Vec2<F>& a, const Vec2<F>& b, Fn f) {
  return {f(a.x, b.x), f(a.y, b.y)};
}
template <class F, class Fn>
inline Vec3<F> map2(const Vec3<F>& a, const Vec3<F>& b, Fn f) {
  return {f(a.x, b.x), f(a.y, b.y), f(a.z, b.z)};
}
template <class F, class Fn>
inline Vec4<F> map2(const Vec4<F>& a, const Vec4<F>& b, Fn f) {
  return {f(a.x, b.x), f(a.y, b.y), f(a.z, b.z), f(a.w, b.w)};
}

// --- geometric functions (GLSL 4.60 §8.5) ----------------------------------------------------
template <class F>
inline F dot(const Vec2<F>& a, const Vec2<F>& b) {
  return fma(a.y, b.y, a.x * b.x);
}
template <class F>
inline F dot(const Vec3<F>& a, const Vec3<F>& b) {
  return fma(a.z, b.z, fma(a.y, b.y, a.x * b.x));
}
template <class F>
inline F dot(const Vec4<F>& a, const Vec4<F>& b) {
  return fma(a.w, b.w, fma(a.z, b.z, fma(a.y, b.y, a.x * b.x)));
}
template <class F>
inline Vec3<F> cross(const Vec3<F>& a, const Vec3<F>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class V>
inline auto length(const V& a) {
  return sqrt(dot(a, a));
}
template <class V>
inline auto distance(const V& a, const V& b) {
  return length(a - b);
}
template <class V>
inline V normalize(const V& a) {
  auto inv = inversesqrt(dot(a, a));
  return a * inv;
}
// I - 2 dot(N, I) N
template <class F>
inline Vec3<F> reflect(const Vec3<F>& i, const Vec3<F>& n) {
  return i - n * (F(2.0f) * dot(n, i));
}
// GLSL refract: zero vector on total internal reflection.
template <class F>
inline Vec3<F> refract(const Vec3<F>& i, const Vec3<F>& n, F eta) {
  F d = dot(n, i);
  F k = F(1.0f) - eta * eta * (F(1.0f) - d * d);
  auto tir = k < F(0.0f);
  Vec3<F> r = i * eta - n * (eta * d + sqrt(max(k, F(0.0f))));
  return {select(tir, F(0.0f), r.x), select(tir, F(0.0f), r.y), select(tir, F(0.0f), r.z)};
}
template <class F>
inline Vec3<F> faceforward(const Vec3<F>& n, const Vec3<F>& i, const Vec3<F>& nref) {
  auto flip = dot(nref, i) < F(0.0f);
  return {select(flip, n.x, -n.x), select(flip, n.y, -n.y), select(flip, n.z, -n.z)};
}

// --- componentwise GLSL functions on vectors ---------------------------------------------------
#define TESSEL_VEC_FN1(name)                    \
  template <class F>                            \
  inline Vec2<F> name(const Vec2<F>& a) {       \
    return map(a, [](F v) { return name(v); }); \
  }                                             \
  template <class F>                            \
  inline Vec3<F> name(const Vec3<F>& a) {       \
    return map(a, [](F v) { return name(v); }); \
  }                                             \
  template <class F>                            \
  inline Vec4<F> name(const Vec4<F>& a) {       \
    return map(a, [](F v) { return name(v); }); \
  }
TESSEL_VEC_FN1(abs)
TESSEL_VEC_FN1(floor)
TESSEL_VEC_FN1(ceil)
TESSEL_VEC_FN1(fract)
TESSEL_VEC_FN1(sqrt)
TESSEL_VEC_FN1(exp)
TESSEL_VEC_FN1(exp2)
TESSEL_VEC_FN1(log)
TESSEL_VEC_FN1(log2)
TESSEL_VEC_FN1(saturate)
TESSEL_VEC_FN1(sin)
TESSEL_VEC_FN1(cos)
#undef TESSEL_VEC_FN1

#define TESSEL_VEC_FN2(name)                                \
  template <class F>                                        \
  inline Vec2<F> name(const Vec2<F>& a, const Vec2<F>& b) { \
    return map2(a, b, [](F u, F v) { return name(u, v); }); \
  }                                                         \
  template <class F>                                        \
  inline Vec3<F> name(const Vec3<F>& a, const Vec3<F>& b) { \
    return map2(a, b, [](F u, F v) { return name(u, v); }); \
  }                                                         \
  template <class F>                                        \
  inline Vec4<F> name(const Vec4<F>& a, const Vec4<F>& b) { \
    return map2(a, b, [](F u, F v) { return name(u, v); }); \
  }
TESSEL_VEC_FN2(min)
TESSEL_VEC_FN2(max)
TESSEL_VEC_FN2(pow)
TESSEL_VEC_FN2(step)
TESSEL_VEC_FN2(mod)
#undef TESSEL_VEC_FN2

template <class V, class F>
inline V mix(const V& a, const V& b, F t) {
  return a + (b - a) * t;
}
template <class F>
inline Vec3<F> clamp(const Vec3<F>& x, F lo, F hi) {
  return {clamp(x.x, lo, hi), clamp(x.y, lo, hi), clamp(x.z, lo, hi)};
}
template <class F>
inline Vec4<F> clamp(const Vec4<F>& x, F lo, F hi) {
  return {clamp(x.x, lo, hi), clamp(x.y, lo, hi), clamp(x.z, lo, hi), clamp(x.w, lo, hi)};
}
template <class F>
inline Vec3<F> select(MaskOf<F> m, const Vec3<F>& a, const Vec3<F>& b) {
  return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}
template <class F>
inline Vec4<F> select(MaskOf<F> m, const Vec4<F>& a, const Vec4<F>& b) {
  return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z), select(m, a.w, b.w)};
}

// --- scalar uniform matrices times lane vectors ---------------------------------------------
template <class F>
inline Vec4<F> operator*(const glm::mat4& m, const Vec4<F>& v) {
  auto row = [&](int r) {
    return fma(F(m[3][r]), v.w, fma(F(m[2][r]), v.z, fma(F(m[1][r]), v.y, F(m[0][r]) * v.x)));
  };
  return {row(0), row(1), row(2), row(3)};
}
template <class F>
inline Vec3<F> operator*(const glm::mat3& m, const Vec3<F>& v) {
  auto row = [&](int r) { return fma(F(m[2][r]), v.z, fma(F(m[1][r]), v.y, F(m[0][r]) * v.x)); };
  return {row(0), row(1), row(2)};
}

// --- derivatives ------------------------------------------------------------------------------
// Eight fragment lanes are two 2x2 quads side by side: lane i is quad i/4, and within a quad
// (i & 1) is x and (i >> 1 & 1) is y. dFdx/dFdy are the differences inside each quad (coarse:
// one value per quad row/column, as GLSL allows). One lane has no neighbours: zero.
inline Float8 dFdx(Float8 v) {
  vx::f32x8 r = __builtin_shufflevector(v.v, v.v, 1, 1, 3, 3, 5, 5, 7, 7);
  vx::f32x8 l = __builtin_shufflevector(v.v, v.v, 0, 0, 2, 2, 4, 4, 6, 6);
  return r - l;
}
inline Float8 dFdy(Float8 v) {
  vx::f32x8 t = __builtin_shufflevector(v.v, v.v, 2, 3, 2, 3, 6, 7, 6, 7);
  vx::f32x8 b = __builtin_shufflevector(v.v, v.v, 0, 1, 0, 1, 4, 5, 4, 5);
  return t - b;
}
// Sixteen lanes are two such groups of eight side by side (an 8x2 block).
inline Float16 dFdx(Float16 v) { return {dFdx(v.lo), dFdx(v.hi)}; }
inline Float16 dFdy(Float16 v) { return {dFdy(v.lo), dFdy(v.hi)}; }
inline float dFdx(float) { return 0.0f; }
inline float dFdy(float) { return 0.0f; }
template <class F>
inline F fwidth(F v) {
  return abs(dFdx(v)) + abs(dFdy(v));
}
template <class F>
inline Vec2<F> dFdx(const Vec2<F>& v) {
  return {dFdx(v.x), dFdx(v.y)};
}
template <class F>
inline Vec2<F> dFdy(const Vec2<F>& v) {
  return {dFdy(v.x), dFdy(v.y)};
}
template <class F>
inline Vec3<F> dFdx(const Vec3<F>& v) {
  return {dFdx(v.x), dFdx(v.y), dFdx(v.z)};
}
template <class F>
inline Vec3<F> dFdy(const Vec3<F>& v) {
  return {dFdy(v.x), dFdy(v.y), dFdy(v.z)};
}

// --- sixteen lanes as two halves of eight ------------------------------------------------------
inline Vec2<Float8> lo_half(const Vec2<Float16>& v) { return {lo_half(v.x), lo_half(v.y)}; }
inline Vec2<Float8> hi_half(const Vec2<Float16>& v) { return {hi_half(v.x), hi_half(v.y)}; }
inline Vec3<Float8> lo_half(const Vec3<Float16>& v) { return {lo_half(v.x), lo_half(v.y), lo_half(v.z)}; }
inline Vec3<Float8> hi_half(const Vec3<Float16>& v) { return {hi_half(v.x), hi_half(v.y), hi_half(v.z)}; }
inline Vec4<Float8> lo_half(const Vec4<Float16>& v) {
  return {lo_half(v.x), lo_half(v.y), lo_half(v.z), lo_half(v.w)};
}
inline Vec4<Float8> hi_half(const Vec4<Float16>& v) {
  return {hi_half(v.x), hi_half(v.y), hi_half(v.z), hi_half(v.w)};
}
inline Vec4<Float16> join(const Vec4<Float8>& a, const Vec4<Float8>& b) {
  return {join(a.x, b.x), join(a.y, b.y), join(a.z, b.z), join(a.w, b.w)};
}

}  // namespace tessel::gpu
