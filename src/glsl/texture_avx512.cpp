// LINEAR_MIPMAP_LINEAR on RGBA8 textures, sixteen lanes to a register, for machines with
// AVX-512 (texture_avx512.hpp). Tessel is built for AVX2, and so is the sampler every shader
// path shares (gpu/detail/texture_simd.hpp, trilinear_halves); the JIT code that calls this
// one already runs in 512-bit registers. The arithmetic is that of trilinear_halves step for
// step (the same float operations in the same order, the same 16-bit fixed-point lerps), so
// the bits are the same on either kind of machine; test_glsl_texture compares the two.
//
// Only the functions below are compiled for AVX-512 (target attributes, intrinsics only):
// nothing here is an inline function shared with the AVX2 code, so no copy built for one
// instruction set can stand in for the other's.
#include "texture_avx512.hpp"

#include <bit>

#include "tessel/gpu/detail/texture_simd.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
// GCC 12's AVX-512 intrinsics start some results from an "undefined" value, which its
// -Wmaybe-uninitialized reports falsely when they are inlined.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>
#define TESSEL_AVX512 __attribute__((target("avx512f,avx512bw,avx512vl,avx512dq"), always_inline)) inline
#define TESSEL_AVX512_ENTRY __attribute__((target("avx512f,avx512bw,avx512vl,avx512dq"), noinline))
#endif

namespace tessel::glsl {

#if defined(TESSEL_AVX512)
namespace {

struct LevelView {
  const std::byte* data;
  int w, h;
};

// A 16-bit lerp weight w (0..256) in both halves of each lane: -128 w (weight_pair).
TESSEL_AVX512 __m512i weight_pair(__m512i w) {
  const __m512i v = _mm512_slli_epi32(w, 7);
  return _mm512_sub_epi16(_mm512_setzero_si512(), _mm512_or_si512(v, _mm512_slli_epi32(v, 16)));
}
// a + floor(((b - a) w + 128) / 256) per 16-bit field, m = -128 w (lerp16).
TESSEL_AVX512 __m512i lerp16(__m512i a, __m512i b, __m512i m) {
  return _mm512_add_epi16(a, _mm512_mulhrs_epi16(_mm512_sub_epi16(a, b), m));
}
TESSEL_AVX512 __m512i wrap(__m512i i, int size, gpu::Wrap mode) {
  if (mode == gpu::Wrap::Repeat) return _mm512_and_si512(i, _mm512_set1_epi32(size - 1));
  return _mm512_min_epi32(_mm512_max_epi32(i, _mm512_setzero_si512()), _mm512_set1_epi32(size - 1));
}
TESSEL_AVX512 __m512 floor16(__m512 x) {
  return _mm512_roundscale_ps(x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
}

// The 64-bit elements at base + 4 at[l] and base + 4 at[l + 1].
TESSEL_AVX512 __m128i load_two(const std::byte* base, const uint32_t* at, int l) {
  return _mm_unpacklo_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(base + size_t(at[l]) * 4)),
                            _mm_loadl_epi64(reinterpret_cast<const __m128i*>(base + size_t(at[l + 1]) * 4)));
}
TESSEL_AVX512 __m512i load_eight(const std::byte* base, const uint32_t* at, int l) {
  const __m256i a =
      _mm256_inserti128_si256(_mm256_castsi128_si256(load_two(base, at, l)), load_two(base, at, l + 2), 1);
  const __m256i b = _mm256_inserti128_si256(_mm256_castsi128_si256(load_two(base, at, l + 4)),
                                            load_two(base, at, l + 6), 1);
  return _mm512_inserti64x4(_mm512_castsi256_si512(a), b, 1);
}
// Each lane's texel at `index` and the one after it (texels 4 bytes from base): one 64-bit
// load per lane (scalar loads: a gather is slower on some machines with AVX-512).
TESSEL_AVX512 void load_pairs(const std::byte* base, __m512i index, __m512i& first, __m512i& second) {
  alignas(64) uint32_t at[16];
  _mm512_store_si512(at, index);
  const __m512i lo = load_eight(base, at, 0), hi = load_eight(base, at, 8);
  const __m512i even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
  first = _mm512_permutex2var_epi32(lo, even, hi);
  second = _mm512_permutex2var_epi32(lo, _mm512_add_epi32(even, _mm512_set1_epi32(1)), hi);
}

struct Rgba16 {
  __m512i even, odd;  // per lane: R | B << 16 and G | A << 16
};
TESSEL_AVX512 Rgba16 split(__m512i t) {
  const __m512i m = _mm512_set1_epi32(0x00FF00FF);
  return {_mm512_and_si512(t, m), _mm512_and_si512(_mm512_srli_epi32(t, 8), m)};
}
TESSEL_AVX512 Rgba16 lerp16(const Rgba16& a, const Rgba16& b, __m512i w) {
  return {lerp16(a.even, b.even, w), lerp16(a.odd, b.odd, w)};
}

// bilinear_rgba16_sane on sixteen lanes (s and t already clamped to +-65536).
TESSEL_AVX512 Rgba16 bilinear(const LevelView& L, gpu::Wrap ws, gpu::Wrap wt, __m512 s, __m512 t) {
  const __m512 u = _mm512_sub_ps(_mm512_mul_ps(s, _mm512_set1_ps(float(L.w))), _mm512_set1_ps(0.5f));
  const __m512 v = _mm512_sub_ps(_mm512_mul_ps(t, _mm512_set1_ps(float(L.h))), _mm512_set1_ps(0.5f));
  const __m512 fu = floor16(u), fv = floor16(v);
  const __m512 k256 = _mm512_set1_ps(256.0f);
  const __m512i wa = weight_pair(_mm512_cvttps_epi32(_mm512_mul_ps(_mm512_sub_ps(u, fu), k256)));
  const __m512i wb = weight_pair(_mm512_cvttps_epi32(_mm512_mul_ps(_mm512_sub_ps(v, fv), k256)));
  const __m512i i0 = _mm512_cvttps_epi32(fu), j0 = _mm512_cvttps_epi32(fv);
  const __m512i one = _mm512_set1_epi32(1);
  const __m512i x0 = wrap(i0, L.w, ws), x1 = wrap(_mm512_add_epi32(i0, one), L.w, ws);
  __m512i y0 = wrap(j0, L.h, wt), y1 = wrap(_mm512_add_epi32(j0, one), L.h, wt);
  y0 = _mm512_mullo_epi32(y0, _mm512_set1_epi32(L.w));
  y1 = _mm512_mullo_epi32(y1, _mm512_set1_epi32(L.w));
  if (_mm512_cmpeq_epi32_mask(_mm512_sub_epi32(x1, x0), one) == 0xFFFF) {
    __m512i a00, a10, a01, a11;
    load_pairs(L.data, _mm512_add_epi32(y0, x0), a00, a10);
    load_pairs(L.data, _mm512_add_epi32(y1, x0), a01, a11);
    return lerp16(lerp16(split(a00), split(a10), wa), lerp16(split(a01), split(a11), wa), wb);
  }
  const Rgba16 t00 = split(_mm512_i32gather_epi32(_mm512_add_epi32(y0, x0), L.data, 4));
  const Rgba16 t10 = split(_mm512_i32gather_epi32(_mm512_add_epi32(y0, x1), L.data, 4));
  const Rgba16 t01 = split(_mm512_i32gather_epi32(_mm512_add_epi32(y1, x0), L.data, 4));
  const Rgba16 t11 = split(_mm512_i32gather_epi32(_mm512_add_epi32(y1, x1), L.data, 4));
  return lerp16(lerp16(t00, t10, wa), lerp16(t01, t11, wa), wb);
}

// rho^2 of each lane's 2x2 quad (the four lanes of its 128-bit block), as quads_rho2:
// max(ux^2 + vx^2, uy^2 + vy^2) with ux = (u1 - u0) w, uy = (u2 - u0) w, and v with h.
TESSEL_AVX512 __m512 quad_rho2(__m512 u, __m512 v, float w, float h) {
  const __m512 W = _mm512_set1_ps(w), H = _mm512_set1_ps(h);
  const __m512 u0 = _mm512_permute_ps(u, 0x00), u1 = _mm512_permute_ps(u, 0x55),
               u2 = _mm512_permute_ps(u, 0xAA);
  const __m512 v0 = _mm512_permute_ps(v, 0x00), v1 = _mm512_permute_ps(v, 0x55),
               v2 = _mm512_permute_ps(v, 0xAA);
  const __m512 ux = _mm512_mul_ps(_mm512_sub_ps(u1, u0), W), uy = _mm512_mul_ps(_mm512_sub_ps(u2, u0), W);
  const __m512 vx = _mm512_mul_ps(_mm512_sub_ps(v1, v0), H), vy = _mm512_mul_ps(_mm512_sub_ps(v2, v0), H);
  const __m512 rx = _mm512_add_ps(_mm512_mul_ps(ux, ux), _mm512_mul_ps(vx, vx));
  const __m512 ry = _mm512_add_ps(_mm512_mul_ps(uy, uy), _mm512_mul_ps(vy, vy));
  return _mm512_max_ps(rx, ry);
}

// N groups of sixteen lanes; false (nothing written) unless every quad's LOD falls between
// the same two levels, as trilinear_halves.
template <int N>
TESSEL_AVX512_ENTRY bool trilinear(const gpu::Texture2D& tex, const gpu::SamplerState& st,
                                   TexLanes* const* tl) {
  __m512 u[N], v[N], l[N], d[N];
  const __m512 zero = _mm512_setzero_ps();
  const bool clamp_lod = st.lod_bias != 0.0f || st.min_lod > -75.0f || st.max_lod < 64.0f;
  const __m512 top = _mm512_set1_ps(float(tex.levels() - 1));
  for (int n = 0; n < N; ++n) {
    u[n] = _mm512_load_ps(reinterpret_cast<const float*>(tl[n]->in[TexLanes::kCoord]));
    v[n] = _mm512_load_ps(reinterpret_cast<const float*>(tl[n]->in[TexLanes::kCoord + 1]));
    const __m512 r = quad_rho2(u[n], v[n], float(tex.width()), float(tex.height()));
    if ((_mm512_cmp_ps_mask(r, zero, _CMP_GT_OQ) &
         _mm512_cmp_ps_mask(r, _mm512_set1_ps(3.4e38f), _CMP_LE_OQ)) != 0xFFFF)
      return false;
    // lod_log2_8: exponent plus (mantissa - 1), halved (rho^2 to rho).
    const __m512i b = _mm512_castps_si512(r);
    const __m512 e = _mm512_cvtepi32_ps(_mm512_sub_epi32(
        _mm512_and_si512(_mm512_srli_epi32(b, 23), _mm512_set1_epi32(0xFF)), _mm512_set1_epi32(127)));
    const __m512 m = _mm512_castsi512_ps(
        _mm512_or_si512(_mm512_and_si512(b, _mm512_set1_epi32(0x007FFFFF)), _mm512_set1_epi32(0x3F800000)));
    __m512 x = _mm512_mul_ps(_mm512_set1_ps(0.5f), _mm512_add_ps(e, _mm512_sub_ps(m, _mm512_set1_ps(1.0f))));
    if (clamp_lod) {
      x = _mm512_add_ps(x, _mm512_set1_ps(st.lod_bias));
      const __m512 lo = _mm512_set1_ps(st.min_lod), hi = _mm512_set1_ps(st.max_lod);
      x = _mm512_mask_blend_ps(_mm512_cmp_ps_mask(x, lo, _CMP_LT_OQ), x, lo);
      x = _mm512_mask_blend_ps(_mm512_cmp_ps_mask(hi, x, _CMP_LT_OQ), x, hi);
    }
    if ((_mm512_cmp_ps_mask(x, zero, _CMP_GT_OQ) & _mm512_cmp_ps_mask(x, top, _CMP_LT_OQ)) != 0xFFFF)
      return false;
    l[n] = x;
  }
  for (int n = 0; n < N; ++n) d[n] = floor16(l[n]);  // each quad's lower level
  const int level = _mm_cvtsi128_si32(_mm512_castsi512_si128(_mm512_cvttps_epi32(d[0])));
  for (int n = 0; n < N; ++n)
    if (_mm512_cmpeq_epi32_mask(_mm512_cvttps_epi32(d[n]), _mm512_set1_epi32(level)) != 0xFFFF) return false;
  const gpu::Level &a = tex.level(level), &b = tex.level(level + 1);
  const LevelView L0{a.data.data(), a.width, a.height}, L1{b.data.data(), b.width, b.height};
  const __m512 lim = _mm512_set1_ps(65536.0f), neg = _mm512_set1_ps(-65536.0f),
               k = _mm512_set1_ps(1.0f / 255.0f);
  const __m512i low = _mm512_set1_epi32(0xFFFF);
  for (int n = 0; n < N; ++n) {
    const __m512i w =
        weight_pair(_mm512_cvtps_epi32(_mm512_mul_ps(_mm512_sub_ps(l[n], d[n]), _mm512_set1_ps(256.0f))));
    // sane8_fixed: NaN becomes -65536 (vmaxps returns its second operand then).
    const __m512 s = _mm512_min_ps(_mm512_max_ps(u[n], neg), lim);
    const __m512 t = _mm512_min_ps(_mm512_max_ps(v[n], neg), lim);
    const Rgba16 c =
        lerp16(bilinear(L0, st.wrap_s, st.wrap_t, s, t), bilinear(L1, st.wrap_s, st.wrap_t, s, t), w);
    _mm512_store_ps(reinterpret_cast<float*>(tl[n]->out[0]),
                    _mm512_mul_ps(_mm512_cvtepi32_ps(_mm512_and_si512(c.even, low)), k));
    _mm512_store_ps(reinterpret_cast<float*>(tl[n]->out[1]),
                    _mm512_mul_ps(_mm512_cvtepi32_ps(_mm512_and_si512(c.odd, low)), k));
    _mm512_store_ps(reinterpret_cast<float*>(tl[n]->out[2]),
                    _mm512_mul_ps(_mm512_cvtepi32_ps(_mm512_srli_epi32(c.even, 16)), k));
    _mm512_store_ps(reinterpret_cast<float*>(tl[n]->out[3]),
                    _mm512_mul_ps(_mm512_cvtepi32_ps(_mm512_srli_epi32(c.odd, 16)), k));
  }
  return true;
}

bool usable(const gpu::Texture2D& tex, const gpu::SamplerState& st) {
  return st.min_filter == gpu::Filter::LinearMipmapLinear && tex.levels() >= 2 &&
         gpu::detail::vector_path(tex, st);
}

}  // namespace

bool avx512_sampling() {
  static const bool on = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
                         __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq");
  return on;
}

bool trilinear_avx512(const gpu::Texture2D& tex, const gpu::SamplerState& st, TexLanes& a) {
  TexLanes* tl[1] = {&a};
  return avx512_sampling() && usable(tex, st) && trilinear<1>(tex, st, tl);
}
bool trilinear_avx512(const gpu::Texture2D& tex, const gpu::SamplerState& st, TexLanes& a, TexLanes& b) {
  TexLanes* tl[2] = {&a, &b};
  return avx512_sampling() && usable(tex, st) && trilinear<2>(tex, st, tl);
}

#else

bool avx512_sampling() { return false; }
bool trilinear_avx512(const gpu::Texture2D&, const gpu::SamplerState&, TexLanes&) { return false; }
bool trilinear_avx512(const gpu::Texture2D&, const gpu::SamplerState&, TexLanes&, TexLanes&) { return false; }

#endif

}  // namespace tessel::glsl
