// Lane types: the numbers a shader computes with.
//
// A shader is written once as a template over a float type F. With F = float it runs on one
// lane (the reference path, pixel history, unit tests); with F = Float8 it runs on eight
// lanes at once: eight vertices, or a 4x2 pixel block made of two 2x2 quads; with F = Float16
// on sixteen: an 8x2 block (two 4x2 blocks side by side). Masks follow F: bool, Mask8, Mask16.
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
template <int N>
struct Vectors;
template <>
struct Vectors<8> {
  using f = f32x8;
  using i = i32x8;
  using u = u32x8;
};
}  // namespace vx

// Eight lanes: one 256-bit vector. The free functions are hidden friends: found by
// argument-dependent lookup, and plain (non-template) functions, so a float argument
// converts implicitly. Sixteen lanes (below) are two eight-lane halves.
template <int N>
struct FloatN;
template <int N>
struct IntN;

// Lane predicates; each lane is all ones (true) or zero (false).
template <int N>
struct MaskN {
  using V = typename vx::Vectors<N>::i;
  V v;
  MaskN() = default;
  constexpr explicit MaskN(V m) : v(m) {}
  explicit MaskN(bool b) : v(V{} + (b ? -1 : 0)) {}
  static MaskN from_bits(unsigned bits) {
    V bit;
    for (int i = 0; i < N; ++i) bit[i] = int32_t(1u << i);
    return MaskN(((V{} + int(bits)) & bit) != 0);
  }
  unsigned bits() const {
#if defined(__AVX__)
    return unsigned(__builtin_ia32_movmskps256((vx::f32x8)v));
#else
    unsigned b = 0;
    for (int i = 0; i < N; ++i) b |= (v[i] != 0 ? 1u : 0u) << i;
    return b;
#endif
  }
  bool operator[](int i) const { return v[i] != 0; }
  friend MaskN operator&(MaskN a, MaskN b) { return MaskN(a.v & b.v); }
  friend MaskN operator|(MaskN a, MaskN b) { return MaskN(a.v | b.v); }
  friend MaskN operator^(MaskN a, MaskN b) { return MaskN(a.v ^ b.v); }
  friend MaskN operator!(MaskN a) { return MaskN(~a.v); }
  friend MaskN operator~(MaskN a) { return MaskN(~a.v); }
  friend MaskN operator&&(MaskN a, MaskN b) { return a & b; }
  friend MaskN operator||(MaskN a, MaskN b) { return a | b; }
  MaskN& operator&=(MaskN b) {
    v &= b.v;
    return *this;
  }
  MaskN& operator|=(MaskN b) {
    v |= b.v;
    return *this;
  }
  friend bool any(MaskN m) { return m.bits() != 0; }
  friend bool all(MaskN m) { return m.bits() == (1u << N) - 1u; }
  friend bool none(MaskN m) { return m.bits() == 0; }
  friend MaskN select(MaskN m, MaskN a, MaskN b) { return MaskN((a.v & m.v) | (b.v & ~m.v)); }
};

// 32-bit integers.
template <int N>
struct IntN {
  using V = typename vx::Vectors<N>::i;
  V v;
  IntN() = default;
  constexpr IntN(V x) : v(x) {}
  IntN(int32_t s) : v(V{} + s) {}
  static IntN load(const int32_t* p) {
    IntN r;
    std::memcpy(&r.v, p, sizeof r.v);
    return r;
  }
  void store(int32_t* p) const { std::memcpy(p, &v, sizeof v); }
  int32_t operator[](int i) const { return v[i]; }
#if defined(__clang__)
  int32_t& operator[](int i) {
    return reinterpret_cast<int32_t*>(&v)[i];
  }  // clang: no references to vector elements
#else
  int32_t& operator[](int i) { return v[i]; }
#endif
  friend IntN operator+(IntN a, IntN b) { return a.v + b.v; }
  friend IntN operator-(IntN a, IntN b) { return a.v - b.v; }
  friend IntN operator*(IntN a, IntN b) { return a.v * b.v; }
  friend IntN operator&(IntN a, IntN b) { return a.v & b.v; }
  friend IntN operator|(IntN a, IntN b) { return a.v | b.v; }
  friend IntN operator^(IntN a, IntN b) { return a.v ^ b.v; }
  friend IntN operator<<(IntN a, int s) { return a.v << s; }
  friend IntN operator>>(IntN a, int s) { return a.v >> s; }
  friend MaskN<N> operator==(IntN a, IntN b) { return MaskN<N>(a.v == b.v); }
  friend MaskN<N> operator!=(IntN a, IntN b) { return MaskN<N>(a.v != b.v); }
  friend MaskN<N> operator<(IntN a, IntN b) { return MaskN<N>(a.v < b.v); }
  friend MaskN<N> operator<=(IntN a, IntN b) { return MaskN<N>(a.v <= b.v); }
  friend MaskN<N> operator>(IntN a, IntN b) { return MaskN<N>(a.v > b.v); }
  friend MaskN<N> operator>=(IntN a, IntN b) { return MaskN<N>(a.v >= b.v); }
  friend IntN select(MaskN<N> m, IntN a, IntN b) { return IntN((a.v & m.v) | (b.v & ~m.v)); }
  friend IntN min(IntN a, IntN b) { return IntN(a.v < b.v ? a.v : b.v); }
  friend IntN max(IntN a, IntN b) { return IntN(a.v > b.v ? a.v : b.v); }
};

// Floats.
template <int N>
struct FloatN {
  using V = typename vx::Vectors<N>::f;
  using I = typename vx::Vectors<N>::i;
  V v;
  FloatN() = default;
  constexpr FloatN(V x) : v(x) {}
  // A broadcast (not 0 + s: GCC may not fold a float add of zero, so that would cost an
  // add in front of every broadcast).
  FloatN(float s) : v(V{s, s, s, s, s, s, s, s}) { static_assert(N == 8); }
  static FloatN load(const float* p) {
    FloatN r;
    std::memcpy(&r.v, p, sizeof r.v);
    return r;
  }
  void store(float* p) const { std::memcpy(p, &v, sizeof v); }
  float operator[](int i) const { return v[i]; }
#if defined(__clang__)
  float& operator[](int i) { return reinterpret_cast<float*>(&v)[i]; }
#else
  float& operator[](int i) { return v[i]; }
#endif
  friend FloatN operator+(FloatN a, FloatN b) { return a.v + b.v; }
  friend FloatN operator-(FloatN a, FloatN b) { return a.v - b.v; }
  friend FloatN operator*(FloatN a, FloatN b) { return a.v * b.v; }
  friend FloatN operator/(FloatN a, FloatN b) { return a.v / b.v; }
  friend FloatN operator-(FloatN a) { return -a.v; }
  FloatN& operator+=(FloatN b) {
    v += b.v;
    return *this;
  }
  FloatN& operator-=(FloatN b) {
    v -= b.v;
    return *this;
  }
  FloatN& operator*=(FloatN b) {
    v *= b.v;
    return *this;
  }
  FloatN& operator/=(FloatN b) {
    v /= b.v;
    return *this;
  }
  friend MaskN<N> operator<(FloatN a, FloatN b) { return MaskN<N>(a.v < b.v); }
  friend MaskN<N> operator<=(FloatN a, FloatN b) { return MaskN<N>(a.v <= b.v); }
  friend MaskN<N> operator>(FloatN a, FloatN b) { return MaskN<N>(a.v > b.v); }
  friend MaskN<N> operator>=(FloatN a, FloatN b) { return MaskN<N>(a.v >= b.v); }
  friend MaskN<N> operator==(FloatN a, FloatN b) { return MaskN<N>(a.v == b.v); }
  friend MaskN<N> operator!=(FloatN a, FloatN b) { return MaskN<N>(a.v != b.v); }

  friend IntN<N> bits_of(FloatN a) { return IntN<N>((I)a.v); }
  // Truncation toward zero, like a C cast.
  friend IntN<N> to_int(FloatN a) { return __builtin_convertvector(a.v, I); }
  friend FloatN select(MaskN<N> m, FloatN a, FloatN b) {
    return FloatN((V)((((I)a.v) & m.v) | (((I)b.v) & ~m.v)));
  }
  friend FloatN min(FloatN a, FloatN b) { return FloatN(a.v < b.v ? a.v : b.v); }
  friend FloatN max(FloatN a, FloatN b) { return FloatN(a.v > b.v ? a.v : b.v); }
  friend FloatN abs(FloatN a) { return FloatN((V)(((I)a.v) & 0x7FFFFFFF)); }
  friend FloatN sqrt(FloatN a) {
    FloatN r;
    for (int i = 0; i < N; ++i) r.v[i] = __builtin_sqrtf(a.v[i]);
    return r;
  }
  // a * b + c with one rounding (GLSL fma): the same instruction for one lane and N, so
  // both paths give the same bits. Dot and matrix products, polynomials and interpolation
  // use it.
  friend FloatN fma(FloatN a, FloatN b, FloatN c) {
#if defined(__FMA__)
    return FloatN(__builtin_ia32_vfmaddps256(a.v, b.v, c.v));
#else
    FloatN r;
    for (int i = 0; i < N; ++i) r.v[i] = __builtin_fmaf(a.v[i], b.v[i], c.v[i]);
    return r;
#endif
  }
  // 1/sqrt(a) for a > 0 (GLSL leaves a <= 0 undefined; here 0 and +inf give NaN): the
  // hardware estimate (12 bits) and one Newton step, about 22 correct bits. Used by
  // normalize(). The one-lane and N-lane estimates are the same instruction per element.
  friend FloatN inversesqrt(FloatN a) {
#if defined(__AVX__)
    const FloatN y = FloatN(__builtin_ia32_rsqrtps256(a.v));
    return y * fma(FloatN(-0.5f) * a, y * y, FloatN(1.5f));
#else
    return FloatN(1.0f) / sqrt(a);
#endif
  }
};

template <int N>
inline FloatN<N> float_from_bits(IntN<N> a) {
  return FloatN<N>((typename vx::Vectors<N>::f)a.v);
}
template <int N>
inline FloatN<N> to_float(IntN<N> a) {
  return FloatN<N>(__builtin_convertvector(a.v, typename vx::Vectors<N>::f));
}

using Mask8 = MaskN<8>;
using Int8 = IntN<8>;
using Float8 = FloatN<8>;

// Sixteen lanes: two groups of eight side by side (an 8x2 pixel block). Every operation is
// two independent eight-lane operations, which the CPU overlaps: a long dependent chain of
// shading math keeps both vector pipes busy.
using Mask16 = MaskN<16>;
using Int16 = IntN<16>;
using Float16 = FloatN<16>;
template <>
struct MaskN<16> {
  Mask8 lo, hi;
  MaskN() = default;
  MaskN(Mask8 l, Mask8 h) : lo(l), hi(h) {}
  explicit MaskN(bool b) : lo(b), hi(b) {}
  static MaskN from_bits(unsigned bits) {
    return {Mask8::from_bits(bits & 0xFF), Mask8::from_bits(bits >> 8)};
  }
  unsigned bits() const { return lo.bits() | (hi.bits() << 8); }
  bool operator[](int i) const { return i < 8 ? lo[i] : hi[i - 8]; }
  friend MaskN operator&(MaskN a, MaskN b) { return {a.lo & b.lo, a.hi & b.hi}; }
  friend MaskN operator|(MaskN a, MaskN b) { return {a.lo | b.lo, a.hi | b.hi}; }
  friend MaskN operator^(MaskN a, MaskN b) { return {a.lo ^ b.lo, a.hi ^ b.hi}; }
  friend MaskN operator!(MaskN a) { return {!a.lo, !a.hi}; }
  friend MaskN operator~(MaskN a) { return {~a.lo, ~a.hi}; }
  friend MaskN operator&&(MaskN a, MaskN b) { return a & b; }
  friend MaskN operator||(MaskN a, MaskN b) { return a | b; }
  MaskN& operator&=(MaskN b) { return *this = *this & b; }
  MaskN& operator|=(MaskN b) { return *this = *this | b; }
  friend bool any(MaskN m) { return m.bits() != 0; }
  friend bool all(MaskN m) { return m.bits() == 0xFFFFu; }
  friend bool none(MaskN m) { return m.bits() == 0; }
  friend MaskN select(MaskN m, MaskN a, MaskN b) {
    return {select(m.lo, a.lo, b.lo), select(m.hi, a.hi, b.hi)};
  }
};

template <>
struct IntN<16> {
  Int8 lo, hi;
  IntN() = default;
  IntN(Int8 l, Int8 h) : lo(l), hi(h) {}
  IntN(int32_t s) : lo(s), hi(s) {}
  int32_t operator[](int i) const { return i < 8 ? lo[i] : hi[i - 8]; }
  int32_t& operator[](int i) { return i < 8 ? lo[i] : hi[i - 8]; }
// clang-format off
#define TESSEL_TWIN_OP(op) \
  friend IntN operator op(IntN a, IntN b) { return {a.lo op b.lo, a.hi op b.hi}; }
  TESSEL_TWIN_OP(+) TESSEL_TWIN_OP(-) TESSEL_TWIN_OP(*) TESSEL_TWIN_OP(&) TESSEL_TWIN_OP(|) TESSEL_TWIN_OP(^)
#undef TESSEL_TWIN_OP
  friend IntN operator<<(IntN a, int s) { return {a.lo << s, a.hi << s}; }
  friend IntN operator>>(IntN a, int s) { return {a.lo >> s, a.hi >> s}; }
#define TESSEL_TWIN_CMP(op) \
  friend Mask16 operator op(IntN a, IntN b) { return {a.lo op b.lo, a.hi op b.hi}; }
  TESSEL_TWIN_CMP(==) TESSEL_TWIN_CMP(!=) TESSEL_TWIN_CMP(<) TESSEL_TWIN_CMP(<=) TESSEL_TWIN_CMP(>) TESSEL_TWIN_CMP(>=)
#undef TESSEL_TWIN_CMP
      // clang-format on
      friend IntN select(Mask16 m, IntN a, IntN b) {
    return {select(m.lo, a.lo, b.lo), select(m.hi, a.hi, b.hi)};
  }
  friend IntN min(IntN a, IntN b) { return {min(a.lo, b.lo), min(a.hi, b.hi)}; }
  friend IntN max(IntN a, IntN b) { return {max(a.lo, b.lo), max(a.hi, b.hi)}; }
};

template <>
struct FloatN<16> {
  Float8 lo, hi;
  FloatN() = default;
  FloatN(Float8 l, Float8 h) : lo(l), hi(h) {}
  FloatN(float s) : lo(s), hi(s) {}
  static FloatN load(const float* p) { return {Float8::load(p), Float8::load(p + 8)}; }
  void store(float* p) const {
    lo.store(p);
    hi.store(p + 8);
  }
  float operator[](int i) const { return i < 8 ? lo[i] : hi[i - 8]; }
  float& operator[](int i) { return i < 8 ? lo[i] : hi[i - 8]; }
// clang-format off
#define TESSEL_TWIN_OP(op) \
  friend FloatN operator op(FloatN a, FloatN b) { return {a.lo op b.lo, a.hi op b.hi}; } \
  FloatN& operator op##=(FloatN b) { return *this = *this op b; }
  TESSEL_TWIN_OP(+) TESSEL_TWIN_OP(-) TESSEL_TWIN_OP(*) TESSEL_TWIN_OP(/)
#undef TESSEL_TWIN_OP
  friend FloatN operator-(FloatN a) { return {-a.lo, -a.hi}; }
#define TESSEL_TWIN_CMP(op) \
  friend Mask16 operator op(FloatN a, FloatN b) { return {a.lo op b.lo, a.hi op b.hi}; }
  TESSEL_TWIN_CMP(==) TESSEL_TWIN_CMP(!=) TESSEL_TWIN_CMP(<) TESSEL_TWIN_CMP(<=) TESSEL_TWIN_CMP(>) TESSEL_TWIN_CMP(>=)
#undef TESSEL_TWIN_CMP
      // clang-format on
      friend Int16 bits_of(FloatN a) {
    return {bits_of(a.lo), bits_of(a.hi)};
  }
  friend Int16 to_int(FloatN a) { return {to_int(a.lo), to_int(a.hi)}; }
  friend FloatN select(Mask16 m, FloatN a, FloatN b) {
    return {select(m.lo, a.lo, b.lo), select(m.hi, a.hi, b.hi)};
  }
  friend FloatN min(FloatN a, FloatN b) { return {min(a.lo, b.lo), min(a.hi, b.hi)}; }
  friend FloatN max(FloatN a, FloatN b) { return {max(a.lo, b.lo), max(a.hi, b.hi)}; }
  friend FloatN abs(FloatN a) { return {abs(a.lo), abs(a.hi)}; }
  friend FloatN sqrt(FloatN a) { return {sqrt(a.lo), sqrt(a.hi)}; }
  friend FloatN fma(FloatN a, FloatN b, FloatN c) { return {fma(a.lo, b.lo, c.lo), fma(a.hi, b.hi, c.hi)}; }
  friend FloatN inversesqrt(FloatN a) { return {inversesqrt(a.lo), inversesqrt(a.hi)}; }
};
inline Float16 float_from_bits(Int16 a) { return {float_from_bits(a.lo), float_from_bits(a.hi)}; }
inline Float16 to_float(Int16 a) { return {to_float(a.lo), to_float(a.hi)}; }

// Halves of sixteen lanes as eight, and back.
inline Float8 lo_half(Float16 a) { return a.lo; }
inline Float8 hi_half(Float16 a) { return a.hi; }
inline Float16 join(Float8 lo, Float8 hi) { return {lo, hi}; }
inline Int8 lo_half(Int16 a) { return a.lo; }
inline Int8 hi_half(Int16 a) { return a.hi; }
inline Int16 join(Int8 lo, Int8 hi) { return {lo, hi}; }
inline Mask8 lo_half(Mask16 a) { return a.lo; }
inline Mask8 hi_half(Mask16 a) { return a.hi; }
inline Mask16 join(Mask8 lo, Mask8 hi) { return {lo, hi}; }

inline bool any(bool b) { return b; }
inline bool all(bool b) { return b; }
inline bool none(bool b) { return !b; }

// --- what goes with a float type ----------------------------------------------------------
template <class F>
struct LaneTraits;
template <>
struct LaneTraits<float> {
  using Mask = bool;
  using Int = int32_t;
  static constexpr int width = 1;
};
template <int N>
struct LaneTraits<FloatN<N>> {
  using Mask = MaskN<N>;
  using Int = IntN<N>;
  static constexpr int width = N;
};
template <class F>
using MaskOf = typename LaneTraits<F>::Mask;
template <class F>
using IntOf = typename LaneTraits<F>::Int;
template <class F>
inline constexpr int lane_width = LaneTraits<F>::width;
template <class F>
inline constexpr bool is_lanes = lane_width<F> > 1;

// --- one lane -------------------------------------------------------------------------------
inline int32_t bits_of(float a) {
  int32_t r;
  std::memcpy(&r, &a, 4);
  return r;
}
inline float float_from_bits(int32_t a) {
  float r;
  std::memcpy(&r, &a, 4);
  return r;
}
inline float to_float(int32_t a) { return float(a); }
inline int32_t to_int(float a) { return int32_t(a); }
inline float select(bool m, float a, float b) { return m ? a : b; }
inline int32_t select(bool m, int32_t a, int32_t b) { return m ? a : b; }
inline bool select(bool m, bool a, bool b) { return m ? a : b; }
inline float min(float a, float b) { return a < b ? a : b; }
inline float max(float a, float b) { return a > b ? a : b; }
inline float abs(float a) { return std::fabs(a); }
inline float sqrt(float a) { return __builtin_sqrtf(a); }
inline float fma(float a, float b, float c) { return __builtin_fmaf(a, b, c); }
inline float inversesqrt(float a) {
#if defined(__AVX__)
  using f4 = float __attribute__((vector_size(16)));
  const float y = __builtin_ia32_rsqrtss(f4{a, 0.0f, 0.0f, 0.0f})[0];
  return y * fma(-0.5f * a, y * y, 1.5f);
#else
  return 1.0f / sqrt(a);
#endif
}

// floor/ceil/round via the conversion instructions; valid for |x| < 2^31, and values beyond
// 2^23 are already integers.
template <class F>
inline F floor(F a) {
  F t = to_float(to_int(a));
  t = select(t > a, t - F(1.0f), t);
  return select(abs(a) < F(8388608.0f), t, a);
}
#if defined(__AVX__)
// One rounding instruction (the result differs from the above only for -0.0, kept here).
inline Float8 floor(Float8 a) {
  return Float8(__builtin_ia32_roundps256(a.v, 0x9));
}  // toward -inf, no exceptions
inline Float16 floor(Float16 a) { return {floor(a.lo), floor(a.hi)}; }
#endif
template <class F>
inline F ceil(F a) {
  return -floor(-a);
}
template <class F>
inline F fract(F a) {
  return a - floor(a);
}
template <class F>
inline F trunc(F a) {
  return select(abs(a) < F(8388608.0f), to_float(to_int(a)), a);
}
template <class F>
inline F mod(F a, F b) {
  return a - b * floor(a / b);
}
template <class F>
inline F sign(F a) {
  return select(a > F(0.0f), F(1.0f), select(a < F(0.0f), F(-1.0f), F(0.0f)));
}
template <class F>
inline F clamp(F x, F lo, F hi) {
  return min(max(x, lo), hi);
}
template <class F>
inline F saturate(F x) {
  return clamp(x, F(0.0f), F(1.0f));
}
template <class F>
inline F mix(F a, F b, F t) {
  return a + (b - a) * t;
}
template <class F>
inline F step(F edge, F x) {
  return select(x < edge, F(0.0f), F(1.0f));
}
template <class F>
inline F smoothstep(F e0, F e1, F x) {
  F t = saturate((x - e0) / (e1 - e0));
  return t * t * (F(3.0f) - F(2.0f) * t);
}
// exp2 and log2 by range reduction and minimax polynomials (relative error about 2e-7).
// The same code runs for one lane and eight, so the reference path and the fast path agree
// to the last bit.
template <class F>
inline F exp2(F x) {
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
template <class F>
inline F log2_positive(F x) {
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
  const F p =
      fma(fma(F(0.2222222f), s4, fma(F(0.2857143f), s2, F(0.4f))), s4, fma(F(0.6666667f), s2, F(2.0f)));
  return fma(s * p, F(1.44269504f), ef);
}
}  // namespace detail
template <class F>
inline F log2(F x) {
  F r = detail::log2_positive(x);
  // log2 of 0 is -inf, of a negative or NaN is NaN, of +inf is +inf.
  r = select(x == F(0.0f), F(-INFINITY), r);
  r = select(x < F(0.0f) || x != x, F(NAN), r);
  r = select(x == F(INFINITY), F(INFINITY), r);
  return r;
}
template <class F>
inline F exp(F x) {
  return exp2(x * F(1.44269504f));
}
template <class F>
inline F log(F x) {
  return log2(x) * F(0.69314718f);
}
namespace detail {
inline float first_lane(float v) { return v; }
template <int N>
inline float first_lane(const FloatN<N>& v) {
  return v[0];
}
// x^n for n >= 1 by repeated squaring.
template <class F>
inline F pow_int(F x, int n) {
  F r(1.0f);
  for (;;) {
    if (n & 1) r = r * x;
    n >>= 1;
    if (n == 0) return r;
    x = x * x;
  }
}
}  // namespace detail
// GLSL pow: undefined for x < 0; here pow(0, y>0) = 0 and pow(x, 0) = 1. An exponent that is
// the same whole number 1..64 in every lane (a material's shininess, usually a constant the
// compiler sees) is computed by repeated squaring: exact to a few roundings and a fraction
// of the cost of exp2(y log2 x).
template <class F>
inline F pow(F x, F y) {
  const float y0 = detail::first_lane(y);
  if (y0 >= 1.0f && y0 <= 64.0f && y0 == float(int(y0)) && all(y == F(y0)))
    return detail::pow_int(x, int(y0));
  F r = exp2(y * detail::log2_positive(x));
  r = select(x == F(0.0f), select(y == F(0.0f), F(1.0f), F(0.0f)), r);
  return select(y == F(0.0f), F(1.0f), r);
}

// sin and cos: Cody-Waite reduction to [-pi/4, pi/4] and minimax polynomials.
template <class F>
inline void sincos(F x, F& s, F& c) {
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
template <class F>
inline F sin(F x) {
  F s, c;
  sincos(x, s, c);
  return s;
}
template <class F>
inline F cos(F x) {
  F s, c;
  sincos(x, s, c);
  return c;
}

}  // namespace tessel::gpu
