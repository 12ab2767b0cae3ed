// Lane types: the numbers a shader computes with.
//
// A shader is written once as a template over a float type F. With F = float it runs on one
// lane (the reference path, pixel history, unit tests); with F = Float8 it runs on eight
// lanes at once (the fast path): a 4x2 pixel block made of two 2x2 quads, or eight vertices.
// Masks follow F: bool for one lane, Mask8 for eight.
//
// The types are thin wrappers over GCC/Clang vector extensions, so the compiler emits AVX2
// (or SSE, or AVX-512) from the same source, depending on the build's -march.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace tessel::gpu {

inline constexpr int kLanes = 8;

namespace vx {
using f32x8 = float __attribute__((vector_size(32)));
using i32x8 = int32_t __attribute__((vector_size(32)));
using u32x8 = uint32_t __attribute__((vector_size(32)));
}  // namespace vx

struct Float8;
struct Int8;

// Eight lane predicates; each lane is all ones (true) or zero (false).
struct Mask8 {
  vx::i32x8 v;
  Mask8() = default;
  constexpr explicit Mask8(vx::i32x8 m) : v(m) {}
  explicit Mask8(bool b) : v(vx::i32x8{} + (b ? -1 : 0)) {}
  static Mask8 from_bits(unsigned bits) {
    const vx::i32x8 bit = {1, 2, 4, 8, 16, 32, 64, 128};
    return Mask8(((vx::i32x8{} + int(bits)) & bit) != 0);
  }
  unsigned bits() const {
#if defined(__AVX__)
    return unsigned(__builtin_ia32_movmskps256((float __attribute__((vector_size(32))))v));
#else
    unsigned b = 0;
    for (int i = 0; i < kLanes; ++i) b |= (v[i] != 0 ? 1u : 0u) << i;
    return b;
#endif
  }
  bool operator[](int i) const { return v[i] != 0; }
  friend Mask8 operator&(Mask8 a, Mask8 b) { return Mask8(a.v & b.v); }
  friend Mask8 operator|(Mask8 a, Mask8 b) { return Mask8(a.v | b.v); }
  friend Mask8 operator^(Mask8 a, Mask8 b) { return Mask8(a.v ^ b.v); }
  friend Mask8 operator!(Mask8 a) { return Mask8(~a.v); }
  friend Mask8 operator~(Mask8 a) { return Mask8(~a.v); }
  friend Mask8 operator&&(Mask8 a, Mask8 b) { return a & b; }
  friend Mask8 operator||(Mask8 a, Mask8 b) { return a | b; }
  Mask8& operator&=(Mask8 b) { v &= b.v; return *this; }
  Mask8& operator|=(Mask8 b) { v |= b.v; return *this; }
};

inline bool any(Mask8 m) { return m.bits() != 0; }
inline bool all(Mask8 m) { return m.bits() == 0xFFu; }
inline bool none(Mask8 m) { return m.bits() == 0; }
inline bool any(bool b) { return b; }
inline bool all(bool b) { return b; }
inline bool none(bool b) { return !b; }

// Eight 32-bit integers.
struct Int8 {
  vx::i32x8 v;
  Int8() = default;
  constexpr Int8(vx::i32x8 x) : v(x) {}
  Int8(int32_t s) : v(vx::i32x8{} + s) {}
  int32_t operator[](int i) const { return v[i]; }
  int32_t& operator[](int i) { return v[i]; }
  friend Int8 operator+(Int8 a, Int8 b) { return a.v + b.v; }
  friend Int8 operator-(Int8 a, Int8 b) { return a.v - b.v; }
  friend Int8 operator*(Int8 a, Int8 b) { return a.v * b.v; }
  friend Int8 operator&(Int8 a, Int8 b) { return a.v & b.v; }
  friend Int8 operator|(Int8 a, Int8 b) { return a.v | b.v; }
  friend Int8 operator^(Int8 a, Int8 b) { return a.v ^ b.v; }
  friend Int8 operator<<(Int8 a, int s) { return a.v << s; }
  friend Int8 operator>>(Int8 a, int s) { return a.v >> s; }
  friend Mask8 operator==(Int8 a, Int8 b) { return Mask8(a.v == b.v); }
  friend Mask8 operator!=(Int8 a, Int8 b) { return Mask8(a.v != b.v); }
  friend Mask8 operator<(Int8 a, Int8 b) { return Mask8(a.v < b.v); }
  friend Mask8 operator<=(Int8 a, Int8 b) { return Mask8(a.v <= b.v); }
  friend Mask8 operator>(Int8 a, Int8 b) { return Mask8(a.v > b.v); }
  friend Mask8 operator>=(Int8 a, Int8 b) { return Mask8(a.v >= b.v); }
};

// Eight floats.
struct Float8 {
  vx::f32x8 v;
  Float8() = default;
  constexpr Float8(vx::f32x8 x) : v(x) {}
  Float8(float s) : v(vx::f32x8{} + s) {}
  static Float8 load(const float* p) {
    Float8 r;
    std::memcpy(&r.v, p, sizeof r.v);
    return r;
  }
  void store(float* p) const { std::memcpy(p, &v, sizeof v); }
  float operator[](int i) const { return v[i]; }
  float& operator[](int i) { return v[i]; }
  friend Float8 operator+(Float8 a, Float8 b) { return a.v + b.v; }
  friend Float8 operator-(Float8 a, Float8 b) { return a.v - b.v; }
  friend Float8 operator*(Float8 a, Float8 b) { return a.v * b.v; }
  friend Float8 operator/(Float8 a, Float8 b) { return a.v / b.v; }
  friend Float8 operator-(Float8 a) { return -a.v; }
  Float8& operator+=(Float8 b) { v += b.v; return *this; }
  Float8& operator-=(Float8 b) { v -= b.v; return *this; }
  Float8& operator*=(Float8 b) { v *= b.v; return *this; }
  Float8& operator/=(Float8 b) { v /= b.v; return *this; }
  friend Mask8 operator<(Float8 a, Float8 b) { return Mask8(a.v < b.v); }
  friend Mask8 operator<=(Float8 a, Float8 b) { return Mask8(a.v <= b.v); }
  friend Mask8 operator>(Float8 a, Float8 b) { return Mask8(a.v > b.v); }
  friend Mask8 operator>=(Float8 a, Float8 b) { return Mask8(a.v >= b.v); }
  friend Mask8 operator==(Float8 a, Float8 b) { return Mask8(a.v == b.v); }
  friend Mask8 operator!=(Float8 a, Float8 b) { return Mask8(a.v != b.v); }
};

// --- what goes with a float type ----------------------------------------------------------
template <class F> struct LaneTraits;
template <> struct LaneTraits<float> {
  using Mask = bool;
  using Int = int32_t;
  static constexpr int width = 1;
};
template <> struct LaneTraits<Float8> {
  using Mask = Mask8;
  using Int = Int8;
  static constexpr int width = kLanes;
};
template <class F> using MaskOf = typename LaneTraits<F>::Mask;
template <class F> using IntOf = typename LaneTraits<F>::Int;
template <class F> inline constexpr int lane_width = LaneTraits<F>::width;
template <class F> inline constexpr bool is_lanes = lane_width<F> > 1;

// --- bit casts and conversions -------------------------------------------------------------
inline Int8 bits_of(Float8 a) { return Int8((vx::i32x8)a.v); }
inline Float8 float_from_bits(Int8 a) { return Float8((vx::f32x8)a.v); }
inline int32_t bits_of(float a) { int32_t r; std::memcpy(&r, &a, 4); return r; }
inline float float_from_bits(int32_t a) { float r; std::memcpy(&r, &a, 4); return r; }
inline Float8 to_float(Int8 a) { return __builtin_convertvector(a.v, vx::f32x8); }
inline float to_float(int32_t a) { return float(a); }
// Truncation toward zero, like a C cast.
inline Int8 to_int(Float8 a) { return __builtin_convertvector(a.v, vx::i32x8); }
inline int32_t to_int(float a) { return int32_t(a); }

// --- selection -----------------------------------------------------------------------------
inline Float8 select(Mask8 m, Float8 a, Float8 b) {
  return float_from_bits(Int8((bits_of(a).v & m.v) | (bits_of(b).v & ~m.v)));
}
inline Int8 select(Mask8 m, Int8 a, Int8 b) { return Int8((a.v & m.v) | (b.v & ~m.v)); }
inline Mask8 select(Mask8 m, Mask8 a, Mask8 b) { return Mask8((a.v & m.v) | (b.v & ~m.v)); }
inline float select(bool m, float a, float b) { return m ? a : b; }
inline int32_t select(bool m, int32_t a, int32_t b) { return m ? a : b; }
inline bool select(bool m, bool a, bool b) { return m ? a : b; }

// --- elementwise math, one definition for both widths where possible -----------------------
inline Float8 min(Float8 a, Float8 b) { return Float8(a.v < b.v ? a.v : b.v); }
inline Float8 max(Float8 a, Float8 b) { return Float8(a.v > b.v ? a.v : b.v); }
inline float min(float a, float b) { return a < b ? a : b; }
inline float max(float a, float b) { return a > b ? a : b; }
inline Int8 min(Int8 a, Int8 b) { return Int8(a.v < b.v ? a.v : b.v); }
inline Int8 max(Int8 a, Int8 b) { return Int8(a.v > b.v ? a.v : b.v); }
inline Float8 abs(Float8 a) { return float_from_bits(Int8(bits_of(a).v & 0x7FFFFFFF)); }
inline float abs(float a) { return std::fabs(a); }

// a * b + c with one rounding (GLSL fma). The same instruction for one lane and eight, so
// both paths give the same bits; the library uses it for dot products, matrix products,
// polynomials and interpolation.
inline float fma(float a, float b, float c) { return __builtin_fmaf(a, b, c); }
inline Float8 fma(Float8 a, Float8 b, Float8 c) {
#if defined(__FMA__)
  return Float8(__builtin_ia32_vfmaddps256(a.v, b.v, c.v));
#else
  Float8 r;
  for (int i = 0; i < kLanes; ++i) r.v[i] = __builtin_fmaf(a.v[i], b.v[i], c.v[i]);
  return r;
#endif
}

inline Float8 sqrt(Float8 a) {
  Float8 r;
  for (int i = 0; i < kLanes; ++i) r.v[i] = __builtin_sqrtf(a.v[i]);
  return r;
}
inline float sqrt(float a) { return __builtin_sqrtf(a); }

// floor/ceil/round via the conversion instructions; valid for |x| < 2^31, and values beyond
// 2^23 are already integers.
template <class F> inline F floor(F a) {
  F t = to_float(to_int(a));
  t = select(t > a, t - F(1.0f), t);
  return select(abs(a) < F(8388608.0f), t, a);
}
template <class F> inline F ceil(F a) { return -floor(-a); }
template <class F> inline F fract(F a) { return a - floor(a); }
template <class F> inline F trunc(F a) { return select(abs(a) < F(8388608.0f), to_float(to_int(a)), a); }
template <class F> inline F mod(F a, F b) { return a - b * floor(a / b); }
template <class F> inline F sign(F a) {
  return select(a > F(0.0f), F(1.0f), select(a < F(0.0f), F(-1.0f), F(0.0f)));
}
template <class F> inline F clamp(F x, F lo, F hi) { return min(max(x, lo), hi); }
template <class F> inline F saturate(F x) { return clamp(x, F(0.0f), F(1.0f)); }
template <class F> inline F mix(F a, F b, F t) { return a + (b - a) * t; }
template <class F> inline F step(F edge, F x) { return select(x < edge, F(0.0f), F(1.0f)); }
template <class F> inline F smoothstep(F e0, F e1, F x) {
  F t = saturate((x - e0) / (e1 - e0));
  return t * t * (F(3.0f) - F(2.0f) * t);
}
// 1/sqrt(a): the hardware estimate (12 bits) and one Newton step, about 22 correct bits;
// 0 -> +inf, +inf -> 0, negative or NaN -> NaN. Used by normalize(). The scalar and the
// eight-lane estimates are the same instruction per element, so both paths agree.
inline Float8 inversesqrt(Float8 a) {
#if defined(__AVX__)
  const Float8 y = Float8(__builtin_ia32_rsqrtps256(a.v));
  const Float8 r = y * fma(Float8(-0.5f) * a, y * y, Float8(1.5f));
  return select(r == r, r, y);
#else
  return Float8(1.0f) / sqrt(a);
#endif
}
inline float inversesqrt(float a) {
#if defined(__AVX__)
  using f4 = float __attribute__((vector_size(16)));
  const float y = __builtin_ia32_rsqrtss(f4{a, 0.0f, 0.0f, 0.0f})[0];
  const float r = y * fma(-0.5f * a, y * y, 1.5f);
  return r == r ? r : y;
#else
  return 1.0f / sqrt(a);
#endif
}

// exp2 and log2 by range reduction and minimax polynomials (relative error about 2e-7).
// The same code runs for one lane and eight, so the reference path and the fast path agree
// to the last bit.
template <class F> inline F exp2(F x) {
  using I = IntOf<F>;
  x = clamp(x, F(-126.0f), F(127.0f));
  // Nearest integer: adding and subtracting 1.5 * 2^23 rounds to nearest even (exact for
  // |x| < 2^22, which the clamp guarantees; NaN stays NaN and is caught by the clamp order).
  F fi = (x + F(12582912.0f)) - F(12582912.0f);
  F f = x - fi;  // [-0.5, 0.5]
  // 2^f = e^(f ln 2): Taylor series to degree 7 (error below 1.2e-7 on this interval).
  // Estrin's scheme: the same polynomial with a short dependency chain.
  const F f2 = f * f, f4 = f2 * f2;
  const F p01 = fma(F(6.9314718e-1f), f, F(1.0f)), p23 = fma(F(5.5504109e-2f), f, F(2.4022651e-1f));
  const F p45 = fma(F(1.3333558e-3f), f, F(9.6181291e-3f)), p67 = fma(F(1.5252734e-5f), f, F(1.5403530e-4f));
  const F p = fma(fma(p67, f2, p45), f4, fma(p23, f2, p01));
  I e = (to_int(fi) + I(127)) << 23;
  return p * float_from_bits(e);
}
namespace detail {
// log2 for finite x > 0 (no special cases).
template <class F> inline F log2_positive(F x) {
  using I = IntOf<F>;
  // x = m * 2^e with m in [sqrt(1/2), sqrt(2)); log2(m) through atanh-series in s=(m-1)/(m+1).
  I bits = bits_of(x);
  I e = ((bits >> 23) & I(0xFF)) - I(127);
  F m = float_from_bits((bits & I(0x007FFFFF)) | I(0x3F800000));  // [1, 2)
  auto big = m > F(1.41421356f);
  m = select(big, m * F(0.5f), m);
  F ef = to_float(e) + select(big, F(1.0f), F(0.0f));
  F s = (m - F(1.0f)) / (m + F(1.0f));
  F s2 = s * s;
  const F s4 = s2 * s2;
  // 2 + 2/3 s2 + 2/5 s2^2 + 2/7 s2^3 + 2/9 s2^4, by Estrin's scheme (short dependency chain).
  const F p = fma(fma(F(0.2222222f), s4, fma(F(0.2857143f), s2, F(0.4f))), s4, fma(F(0.6666667f), s2, F(2.0f)));
  return fma(s * p, F(1.44269504f), ef);
}
}  // namespace detail
template <class F> inline F log2(F x) {
  F r = detail::log2_positive(x);
  // log2 of 0 is -inf, of a negative or NaN is NaN, of +inf is +inf.
  r = select(x == F(0.0f), F(-INFINITY), r);
  r = select(x < F(0.0f) || x != x, F(NAN), r);
  r = select(x == F(INFINITY), F(INFINITY), r);
  return r;
}
template <class F> inline F exp(F x) { return exp2(x * F(1.44269504f)); }
template <class F> inline F log(F x) { return log2(x) * F(0.69314718f); }
// GLSL pow: undefined for x < 0; here pow(0, y>0) = 0 and pow(x, 0) = 1.
template <class F> inline F pow(F x, F y) {
  F r = exp2(y * detail::log2_positive(x));
  r = select(x == F(0.0f), select(y == F(0.0f), F(1.0f), F(0.0f)), r);
  return select(y == F(0.0f), F(1.0f), r);
}

// sin and cos: Cody-Waite reduction to [-pi/4, pi/4] and minimax polynomials.
template <class F> inline void sincos(F x, F& s, F& c) {
  using I = IntOf<F>;
  F q = floor(x * F(0.63661977f) + F(0.5f));  // nearest multiple of pi/2
  F r = x - q * F(1.5707963f);
  r = r - q * F(-4.3711388e-8f);
  I qi = to_int(q);
  F r2 = r * r;
  F sp = F(-1.9515296e-4f);
  sp = fma(sp, r2, F(8.3321608e-3f));
  sp = fma(sp, r2, F(-1.6666654e-1f));
  F sr = r + r * r2 * sp;
  F cp = F(2.4433157e-5f);
  cp = fma(cp, r2, F(-1.3887316e-3f));
  cp = fma(cp, r2, F(4.1666646e-2f));
  F cr = F(1.0f) - F(0.5f) * r2 + r2 * r2 * cp;
  auto swap = (qi & I(1)) != I(0);
  F s0 = select(swap, cr, sr);
  F c0 = select(swap, sr, cr);
  s = select((qi & I(2)) != I(0), -s0, s0);
  c = select(((qi + I(1)) & I(2)) != I(0), -c0, c0);
}
template <class F> inline F sin(F x) { F s, c; sincos(x, s, c); return s; }
template <class F> inline F cos(F x) { F s, c; sincos(x, s, c); return c; }

}  // namespace tessel::gpu
