// Eight- and sixteen-lane sampling of RGBA8 textures (REPEAT on power-of-two sizes, or
// CLAMP_TO_EDGE), in a header so that a shader's fragment function, which the raster loop
// compiles with everything it calls inlined, keeps its lane values in registers across the
// texture lookup (an out-of-line call would spill every live vector register around it).
// texture.cpp uses the same functions for the eight-lane path, so both give the same bits.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

#include "tessel/gpu/simd.hpp"
#include "tessel/gpu/texture.hpp"
#include "tessel/gpu/vec.hpp"

#define TESSEL_ALWAYS_INLINE inline __attribute__((always_inline))

namespace tessel::gpu::detail {

// NaN -> 0 and infinities to a large finite value, so index arithmetic stays defined.
constexpr float kNoCoord = 1.0e30f;

struct LevelRef {
  const std::byte* data;
  int w, h;
};

TESSEL_ALWAYS_INLINE LevelRef level_ref(const Texture2D& t, int i) {
  const Level& l = t.level(i);
  return {l.data.data(), l.width, l.height};
}

inline Int8 gather_u32(const std::byte* base, Int8 index) {
#if defined(__AVX2__)
  return Int8((vx::i32x8)_mm256_i32gather_epi32(reinterpret_cast<const int*>(base), (__m256i)index.v, 4));
#else
  Int8 r;
  for (int i = 0; i < kLanes; ++i) std::memcpy(&r.v[i], base + size_t(uint32_t(index.v[i])) * 4, 4);
  return r;
#endif
}

TESSEL_ALWAYS_INLINE Float8 sane8(Float8 s) {
  s = select(s == s, s, Float8(0.0f));
  return clamp(s, Float8(-kNoCoord), Float8(kNoCoord));
}

// floor_to_int for values that are already integral (or huge): clamp to +-2^30, convert.
TESSEL_ALWAYS_INLINE Int8 integral_to_int(Float8 f) {
  return to_int(clamp(f, Float8(-1073741824.0f), Float8(1073741824.0f)));
}

TESSEL_ALWAYS_INLINE Int8 wrap8(Int8 i, int size, Wrap mode) {
  if (mode == Wrap::Repeat) return i & Int8(size - 1);  // power-of-two size
  return min(max(i, Int8(0)), Int8(size - 1));          // ClampToEdge
}

TESSEL_ALWAYS_INLINE Vec4<Float8> decode_rgba8(Int8 t) {
  const Float8 k(1.0f / 255.0f);
  return {to_float(t & Int8(0xFF)) * k, to_float((t >> 8) & Int8(0xFF)) * k,
          to_float((t >> 16) & Int8(0xFF)) * k, to_float(Int8(vx::i32x8((vx::u32x8)t.v >> 24))) * k};
}

TESSEL_ALWAYS_INLINE Vec4<Float8> lerp8(const Vec4<Float8>& a, const Vec4<Float8>& b, Float8 t) {
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t, a.w + (b.w - a.w) * t};
}

inline bool vector_path(const Texture2D& tex, const SamplerState& st) {
  if (tex.format() != Format::RGBA8) return false;
  const bool pow2_w = (tex.width() & (tex.width() - 1)) == 0,
             pow2_h = (tex.height() & (tex.height() - 1)) == 0;
  const bool ok_s = st.wrap_s == Wrap::ClampToEdge || (st.wrap_s == Wrap::Repeat && pow2_w);
  const bool ok_t = st.wrap_t == Wrap::ClampToEdge || (st.wrap_t == Wrap::Repeat && pow2_h);
  // Gather indices are 32-bit: y * width + x must fit.
  return ok_s && ok_t && int64_t(tex.width()) * tex.height() < (int64_t(1) << 31);
}

#if defined(__AVX2__)
// Bilinear and trilinear filtering of RGBA8 texels in 16-bit fixed point, as llvmpipe's AoS
// path does (8-bit weights, each lerp rounded to 8 bits), but without shuffles: each lane's
// texel is split into its even bytes (R, B) and odd bytes (G, A) as 16-bit fields, and every
// lerp works on those fields in place.
struct Rgba16 {
  __m256i even, odd;  // per lane: R | B << 16 and G | A << 16, values 0..255
};

// The texels at index and index + 1 of each lane (32-bit texels from base), as two 64-bit
// gathers of four lanes each: lanes 0, 1, 4, 5 and 2, 3, 6, 7, so that one shuffle per 128-bit
// half puts the first and the second texels back in lane order.
TESSEL_ALWAYS_INLINE void gather_pairs(const std::byte* base, Int8 index, Int8& first, Int8& second) {
  alignas(32) int32_t at[8];
  index.store(at);
  auto pair = [&](int l) {
    return _mm_loadl_epi64(reinterpret_cast<const __m128i*>(base + size_t(uint32_t(at[l])) * 4));
  };
  auto two = [&](int l0, int l1) { return _mm_unpacklo_epi64(pair(l0), pair(l1)); };
  const __m256 a = _mm256_castsi256_ps(_mm256_set_m128i(two(4, 5), two(0, 1)));
  const __m256 b = _mm256_castsi256_ps(_mm256_set_m128i(two(6, 7), two(2, 3)));
  first = Int8((vx::i32x8)_mm256_castps_si256(_mm256_shuffle_ps(a, b, 0x88)));
  second = Int8((vx::i32x8)_mm256_castps_si256(_mm256_shuffle_ps(a, b, 0xDD)));
}

// A lerp weight w (0..256) as lerp16 takes it: -128 w, which fits in 16 bits for all of them.
TESSEL_ALWAYS_INLINE int16_t lerp_weight(int w) { return int16_t(-(w << 7)); }
// The weight of each lane (0..256) in both 16-bit halves of the lane, as lerp16 takes it.
TESSEL_ALWAYS_INLINE __m256i weight_pair(Int8 w) {
  const __m256i v = _mm256_slli_epi32((__m256i)w.v, 7);
  return _mm256_sub_epi16(_mm256_setzero_si256(), _mm256_or_si256(v, _mm256_slli_epi32(v, 16)));
}
// (a * (256 - w) + b * w + 128) >> 8 per 16-bit field, m = -128 w: that is
// a + floor(((b - a) w + 128) / 256), and vpmulhrsw gives floor((x y + 2^14) / 2^15), which
// for x = a - b and y = -128 w is that second term (the product never leaves 32 bits).
TESSEL_ALWAYS_INLINE __m256i lerp16(__m256i a, __m256i b, __m256i m) {
  return _mm256_add_epi16(a, _mm256_mulhrs_epi16(_mm256_sub_epi16(a, b), m));
}
TESSEL_ALWAYS_INLINE Rgba16 split(Int8 texels) {
  const __m256i t = (__m256i)texels.v;
  // Bytes 1 and 3 of each lane to 16-bit fields by one shuffle (-1: zero).
  const __m256i odd = _mm256_setr_epi8(1, -1, 3, -1, 5, -1, 7, -1, 9, -1, 11, -1, 13, -1, 15, -1, 1, -1, 3,
                                       -1, 5, -1, 7, -1, 9, -1, 11, -1, 13, -1, 15, -1);
  return {_mm256_and_si256(t, _mm256_set1_epi32(0x00FF00FF)), _mm256_shuffle_epi8(t, odd)};
}
TESSEL_ALWAYS_INLINE Rgba16 lerp16(const Rgba16& a, const Rgba16& b, __m256i w) {
  return {lerp16(a.even, b.even, w), lerp16(a.odd, b.odd, w)};
}

// The coordinates of the fixed-point path, clamped to +-65536 (whole repeats of the texture,
// where a float keeps under 8 bits of fraction anyway), so that s * size stays within 2^30
// and converts to an integer without a clamp of its own. NaN becomes -65536 (vmaxps returns
// its second operand then), which samples exactly as 0 does, the value sane8 gives NaN: a
// whole number of repeats for REPEAT, and the first texel for CLAMP_TO_EDGE.
TESSEL_ALWAYS_INLINE Float8 sane8_fixed(Float8 s) {
  const __m256 lo = _mm256_max_ps(__m256(s.v), _mm256_set1_ps(-65536.0f));
  return Float8(vx::f32x8(_mm256_min_ps(lo, _mm256_set1_ps(65536.0f))));
}

// The channels as floats in [0, 1] (decode_rgba8 of the packed texel, without packing it).
TESSEL_ALWAYS_INLINE Vec4<Float8> decode_rgba16(const Rgba16& c) {
  const Float8 k(1.0f / 255.0f);
  const Int8 e((vx::i32x8)c.even), o((vx::i32x8)c.odd), low(0xFFFF);
  return {to_float(e & low) * k, to_float(o & low) * k, to_float(e >> 16) * k, to_float(o >> 16) * k};
}

// s and t have been through sane8_fixed. Pairs: texels side by side in a row are read
// together (false: one by one, as a test compares).
template <bool Pairs = true>
TESSEL_ALWAYS_INLINE Rgba16 bilinear_rgba16_sane(const LevelRef& L, Wrap ws, Wrap wt, Float8 s, Float8 t) {
  const Float8 u = s * Float8(float(L.w)) - Float8(0.5f);
  const Float8 v = t * Float8(float(L.h)) - Float8(0.5f);
  const Float8 fu = floor(u), fv = floor(v);
  const __m256i wa = weight_pair(to_int((u - fu) * Float8(256.0f)));
  const __m256i wb = weight_pair(to_int((v - fv) * Float8(256.0f)));
  const Int8 i0 = to_int(fu), j0 = to_int(fv);
  const Int8 x0 = wrap8(i0, L.w, ws), x1 = wrap8(i0 + Int8(1), L.w, ws);
  Int8 y0 = wrap8(j0, L.h, wt), y1 = wrap8(j0 + Int8(1), L.h, wt);
  if ((L.w & (L.w - 1)) == 0) {  // rows of a power-of-two width: a shift, not a multiply
    const int shift = std::countr_zero(unsigned(L.w));
    y0 = y0 << shift;
    y1 = y1 << shift;
  } else {
    y0 = y0 * Int8(L.w);
    y1 = y1 * Int8(L.w);
  }
  if (Pairs && ((x1 - x0) == Int8(1)).bits() == 0xFF) {
    // Each lane's two texels of a row are side by side (no wrap or clamp between them): one
    // 64-bit element each, half the elements of gathering them one by one.
    Int8 a00, a10, a01, a11;
    gather_pairs(L.data, y0 + x0, a00, a10);
    gather_pairs(L.data, y1 + x0, a01, a11);
    return lerp16(lerp16(split(a00), split(a10), wa), lerp16(split(a01), split(a11), wa), wb);
  }
  const Rgba16 t00 = split(gather_u32(L.data, y0 + x0)), t10 = split(gather_u32(L.data, y0 + x1));
  const Rgba16 t01 = split(gather_u32(L.data, y1 + x0)), t11 = split(gather_u32(L.data, y1 + x1));
  return lerp16(lerp16(t00, t10, wa), lerp16(t01, t11, wa), wb);
}
TESSEL_ALWAYS_INLINE Rgba16 bilinear_rgba16(const LevelRef& L, Wrap ws, Wrap wt, Float8 s, Float8 t) {
  return bilinear_rgba16_sane(L, ws, wt, sane8_fixed(s), sane8_fixed(t));
}
#endif  // __AVX2__

#if defined(__AVX2__)
// llvmpipe's log2 of the level of detail (lod_log2 in texture.cpp) on eight lanes.
TESSEL_ALWAYS_INLINE Float8 lod_log2_8(Float8 x) {
  const Int8 b = bits_of(x);
  const Float8 e = to_float(((b >> 23) & Int8(0xFF)) - Int8(127));
  const Float8 m = float_from_bits((b & Int8(0x007FFFFF)) | Int8(0x3F800000));
  return e + (m - Float8(1.0f));
}

// rho^2 of quad_lods for eight lanes, each quad's value (from its origin lane) in all four.
TESSEL_ALWAYS_INLINE Float8 quad_rho2(const Float8& u, const Float8& v, int w, int h) {
  const Float8 fw{float(w)}, fh{float(h)};
  const Float8 ux = dFdx(u) * fw, vx = dFdx(v) * fh, uy = dFdy(u) * fw, vy = dFdy(v) * fh;
  const Float8 r = max(ux * ux + vx * vx, uy * uy + vy * vy);
  return Float8(__builtin_shufflevector(r.v, r.v, 0, 0, 0, 0, 4, 4, 4, 4));
}

// Sixteen lanes (four quads) of LINEAR_MIPMAP_LINEAR on an RGBA8 texture when every quad's
// LOD falls between the same two levels: the LOD, the mip selection and the blend weights
// on vectors (no per-quad plan), and both halves' texel addresses and gathers side by side,
// so that their latencies overlap. The arithmetic is that of texture() on eight lanes, step
// for step, so the result is bit-identical; false (nothing written) when it does not apply.
TESSEL_ALWAYS_INLINE bool trilinear16(const Texture2D& tex, const SamplerState& st, const Vec2<Float16>& uv,
                                      Vec4<Float16>& out) {
  if (st.min_filter != Filter::LinearMipmapLinear || tex.levels() < 2 || !vector_path(tex, st)) return false;
  const int W = tex.width(), H = tex.height();
  const Float8 r_lo = quad_rho2(uv.x.lo, uv.y.lo, W, H), r_hi = quad_rho2(uv.x.hi, uv.y.hi, W, H);
  const Float8 kMaxR(3.4e38f), zero(0.0f);
  if (((r_lo > zero) & (r_lo <= kMaxR) & (r_hi > zero) & (r_hi <= kMaxR)).bits() != 0xFF) return false;
  // make_plan: l = lod + bias, then max(l, min_lod) and min(l, max_lod) as std::max/min do.
  // With no bias and the default range (0.5 log2 of a positive finite float is in [-75, 64))
  // the three steps change nothing.
  const bool plain = st.lod_bias == 0.0f && st.min_lod <= -75.0f && st.max_lod >= 64.0f;
  auto level_of = [&](Float8 r) {
    Float8 l = Float8(0.5f) * lod_log2_8(r);
    if (plain) return l;
    l = l + Float8(st.lod_bias);
    l = select(l < Float8(st.min_lod), Float8(st.min_lod), l);
    l = select(Float8(st.max_lod) < l, Float8(st.max_lod), l);
    return l;
  };
  const Float8 l_lo = level_of(r_lo), l_hi = level_of(r_hi);
  const Float8 q(float(tex.levels() - 1));
  // Minification (l > 0; NaN fails) and below the last level, in every lane.
  if (((l_lo > zero) & (l_lo < q) & (l_hi > zero) & (l_hi < q)).bits() != 0xFF) return false;
  const Float8 d_lo = floor(l_lo), d_hi = floor(l_hi);
  const Int8 lv_lo = to_int(d_lo), lv_hi = to_int(d_hi);
  const int level = lv_lo[0];
  if (((lv_lo == Int8(level)) & (lv_hi == Int8(level))).bits() != 0xFF) return false;
  // The mip blend of each lane's quad as a 16-bit weight, lrint(blend * 256) as run_plan has it.
  const __m256i w_lo =
      weight_pair(Int8((vx::i32x8)_mm256_cvtps_epi32((__m256)((l_lo - d_lo) * Float8(256.0f)).v)));
  const __m256i w_hi =
      weight_pair(Int8((vx::i32x8)_mm256_cvtps_epi32((__m256)((l_hi - d_hi) * Float8(256.0f)).v)));

  const LevelRef L0 = level_ref(tex, level), L1 = level_ref(tex, level + 1);
  const Float8 s_lo = sane8_fixed(uv.x.lo), t_lo = sane8_fixed(uv.y.lo), s_hi = sane8_fixed(uv.x.hi),
               t_hi = sane8_fixed(uv.y.hi);
  const Rgba16 a_lo = bilinear_rgba16_sane(L0, st.wrap_s, st.wrap_t, s_lo, t_lo);
  const Rgba16 a_hi = bilinear_rgba16_sane(L0, st.wrap_s, st.wrap_t, s_hi, t_hi);
  const Rgba16 b_lo = bilinear_rgba16_sane(L1, st.wrap_s, st.wrap_t, s_lo, t_lo);
  const Rgba16 b_hi = bilinear_rgba16_sane(L1, st.wrap_s, st.wrap_t, s_hi, t_hi);
  const Rgba16 c_lo = lerp16(a_lo, b_lo, w_lo), c_hi = lerp16(a_hi, b_hi, w_hi);
  out = join(decode_rgba16(c_lo), decode_rgba16(c_hi));
  return true;
}
#endif

}  // namespace tessel::gpu::detail
