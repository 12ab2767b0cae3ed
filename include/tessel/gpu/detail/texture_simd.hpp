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

// rho^2 of quad_lods for the quads of H halves of eight lanes (two 2x2 quads each), one
// quad's value per lane: [h0q0 h0q0 h1q0 h1q0 | h0q1 h0q1 h1q1 h1q1] for H = 2 and
// [h0q0 h1q0 h2q0 h3q0 | h0q1 h1q1 h2q1 h3q1] for H = 4. Each quad's arithmetic is that of
// dFdx/dFdy at its origin lane (x: lane 1 - lane 0, y: lane 2 - lane 0), step for step; the
// order of max's operands differs, which matters only for NaN, which the caller rejects.
template <int H>
TESSEL_ALWAYS_INLINE Float8 quads_rho2(const Float8* u, const Float8* v, int w, int h) {
  static_assert(H == 2 || H == 4);
  const __m256 scale =
      _mm256_setr_ps(float(w), float(w), float(h), float(h), float(w), float(w), float(h), float(h));
  __m256 m[H];
#pragma GCC unroll 4
  for (int i = 0; i < H; ++i) {
    const __m256 uu = __m256(u[i].v), vv = __m256(v[i].v);
    const __m256 a = _mm256_shuffle_ps(uu, vv, _MM_SHUFFLE(2, 1, 2, 1));  // u1 u2 v1 v2 of each quad
    const __m256 o = _mm256_shuffle_ps(uu, vv, _MM_SHUFFLE(0, 0, 0, 0));  // u0 u0 v0 v0
    const __m256 d = _mm256_mul_ps(_mm256_sub_ps(a, o), scale);           // ux uy vx vy
    const __m256 sq = _mm256_mul_ps(d, d);
    const __m256 r = _mm256_add_ps(sq, _mm256_permute_ps(sq, _MM_SHUFFLE(1, 0, 3, 2)));  // rx ry rx ry
    m[i] = _mm256_max_ps(r, _mm256_permute_ps(r, _MM_SHUFFLE(2, 3, 0, 1)));
  }
  __m256 out;
  if constexpr (H == 2) {
    out = _mm256_shuffle_ps(m[0], m[1], _MM_SHUFFLE(0, 0, 0, 0));
  } else {
    const __m256 p = _mm256_shuffle_ps(m[0], m[1], _MM_SHUFFLE(0, 0, 0, 0));
    const __m256 q = _mm256_shuffle_ps(m[2], m[3], _MM_SHUFFLE(0, 0, 0, 0));
    out = _mm256_shuffle_ps(p, q, _MM_SHUFFLE(2, 0, 2, 0));
  }
  return Float8(vx::f32x8(out));
}

// H halves of eight lanes (H = 2: sixteen lanes, four quads; H = 4: thirty-two, eight quads)
// of LINEAR_MIPMAP_LINEAR on an RGBA8 texture when every quad's LOD falls between the same
// two levels: the LOD, the mip selection and the blend weights once for all quads, and every
// half's texel addresses and gathers side by side, so that their latencies overlap. The
// arithmetic is that of texture() on eight lanes, step for step, so the result is
// bit-identical; false (nothing written) when it does not apply.
template <int H>
TESSEL_ALWAYS_INLINE bool trilinear_halves(const Texture2D& tex, const SamplerState& st, const Float8* u,
                                           const Float8* v, Vec4<Float8>* out) {
  if (st.min_filter != Filter::LinearMipmapLinear || tex.levels() < 2 || !vector_path(tex, st)) return false;
  const Float8 r = quads_rho2<H>(u, v, tex.width(), tex.height());
  const Float8 kMaxR(3.4e38f), zero(0.0f);
  if (((r > zero) & (r <= kMaxR)).bits() != 0xFF) return false;
  // make_plan: l = lod + bias, then max(l, min_lod) and min(l, max_lod) as std::max/min do.
  // With no bias and the default range (0.5 log2 of a positive finite float is in [-75, 64))
  // the three steps change nothing.
  Float8 l = Float8(0.5f) * lod_log2_8(r);
  if (st.lod_bias != 0.0f || st.min_lod > -75.0f || st.max_lod < 64.0f) {
    l = l + Float8(st.lod_bias);
    l = select(l < Float8(st.min_lod), Float8(st.min_lod), l);
    l = select(Float8(st.max_lod) < l, Float8(st.max_lod), l);
  }
  // Minification (l > 0; NaN fails) and below the last level, in every quad.
  if (((l > zero) & (l < Float8(float(tex.levels() - 1)))).bits() != 0xFF) return false;
  const Float8 d = floor(l);
  const Int8 lv = to_int(d);
  const int level = lv[0];
  if ((lv == Int8(level)).bits() != 0xFF) return false;
  // The mip blend of each quad as a 16-bit weight, lrint(blend * 256) as run_plan has it,
  // then each half's lanes given their quad's.
  const __m256i wq = weight_pair(Int8((vx::i32x8)_mm256_cvtps_epi32((__m256)((l - d) * Float8(256.0f)).v)));
  const LevelRef L0 = level_ref(tex, level), L1 = level_ref(tex, level + 1);
  Float8 s[H], t[H];
  __m256i w[H];
#pragma GCC unroll 4
  for (int i = 0; i < H; ++i) {
    const int k = H == 2 ? 2 * i : i;
    w[i] = _mm256_permutevar8x32_epi32(wq, _mm256_setr_epi32(k, k, k, k, k + 4, k + 4, k + 4, k + 4));
    s[i] = sane8_fixed(u[i]);
    t[i] = sane8_fixed(v[i]);
  }
  Rgba16 a[H], b[H];
#pragma GCC unroll 4
  for (int i = 0; i < H; ++i) a[i] = bilinear_rgba16_sane(L0, st.wrap_s, st.wrap_t, s[i], t[i]);
#pragma GCC unroll 4
  for (int i = 0; i < H; ++i) b[i] = bilinear_rgba16_sane(L1, st.wrap_s, st.wrap_t, s[i], t[i]);
#pragma GCC unroll 4
  for (int i = 0; i < H; ++i) out[i] = decode_rgba16(lerp16(a[i], b[i], w[i]));
  return true;
}

// Sixteen lanes (four quads) as trilinear_halves<2>.
TESSEL_ALWAYS_INLINE bool trilinear16(const Texture2D& tex, const SamplerState& st, const Vec2<Float16>& uv,
                                      Vec4<Float16>& out) {
  const Float8 u[2] = {uv.x.lo, uv.x.hi}, v[2] = {uv.y.lo, uv.y.hi};
  Vec4<Float8> r[2];
  if (!trilinear_halves<2>(tex, st, u, v, r)) return false;
  out = join(r[0], r[1]);
  return true;
}

// Two sixteen-lane lookups at once (eight quads, all between the same two levels), as
// trilinear_halves<4>: the same bits as two trilinear16 calls, with twice the independent
// work in flight.
TESSEL_ALWAYS_INLINE bool trilinear32(const Texture2D& tex, const SamplerState& st, const Vec2<Float16>& uv_a,
                                      const Vec2<Float16>& uv_b, Vec4<Float16>& out_a, Vec4<Float16>& out_b) {
  const Float8 u[4] = {uv_a.x.lo, uv_a.x.hi, uv_b.x.lo, uv_b.x.hi};
  const Float8 v[4] = {uv_a.y.lo, uv_a.y.hi, uv_b.y.lo, uv_b.y.hi};
  Vec4<Float8> r[4];
  if (!trilinear_halves<4>(tex, st, u, v, r)) return false;
  out_a = join(r[0], r[1]);
  out_b = join(r[2], r[3]);
  return true;
}
#endif

}  // namespace tessel::gpu::detail
