// The fragment operations of the common states, eight lanes at a time and inline, so the
// raster loop (raster.hpp) calls them without leaving the shader's code: a depth test
// without stencil, and an unblended RGBA8 write of all channels (DrawRecord::fast_depth,
// fast_color). fragment_ops.cpp runs the same functions behind its general entry points.
// Contract as there: only lanes set in `mask` read or write; 24-bit depth compares
// round(z * (2^24 - 1)).
#pragma once

#include <cmath>
#include <cstring>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

#include "tessel/gpu/detail/pipeline.hpp"
#include "tessel/gpu/texture.hpp"

namespace tessel::gpu::detail {

#define TESSEL_FAST_INLINE inline __attribute__((always_inline))

// A 4x2 group is two rows of four pixels; lanes map to them as kLaneDx/kLaneDy say.
using i32x4 = int32_t __attribute__((vector_size(16)));

TESSEL_FAST_INLINE Int8 load_group(const std::byte* row0, const std::byte* row1) {
  i32x4 a, b;
  std::memcpy(&a, row0, 16);
  std::memcpy(&b, row1, 16);
  return Int8(__builtin_shufflevector(a, b, 0, 1, 4, 5, 2, 3, 6, 7));
}
TESSEL_FAST_INLINE void store_group(std::byte* row0, std::byte* row1, Int8 v) {
  const i32x4 a = __builtin_shufflevector(v.v, v.v, 0, 1, 4, 5);
  const i32x4 b = __builtin_shufflevector(v.v, v.v, 2, 3, 6, 7);
  std::memcpy(row0, &a, 16);
  std::memcpy(row1, &b, 16);
}

// round(z * (2^24 - 1)) in double, per lane (z already in [0, 1]).
TESSEL_FAST_INLINE Int8 quantize24x8(const Float8& z) {
#if defined(__AVX2__)
  const __m256 v = (__m256)z.v;
  const __m256d k = _mm256_set1_pd(16777215.0);
  const __m128i lo = _mm256_cvtpd_epi32(_mm256_mul_pd(_mm256_cvtps_pd(_mm256_castps256_ps128(v)), k));
  const __m128i hi = _mm256_cvtpd_epi32(_mm256_mul_pd(_mm256_cvtps_pd(_mm256_extractf128_ps(v, 1)), k));
  return Int8((vx::i32x8)_mm256_set_m128i(hi, lo));
#else
  Int8 r;
  for (int i = 0; i < kLanes; ++i) r.v[i] = int32_t(std::lrint(double(z[i]) * 16777215.0));
  return r;
#endif
}

// Depth test (and write) of the group at (gx, gy); needs d.fast_depth and the group inside
// the target. Returns the passing lanes.
TESSEL_FAST_INLINE unsigned depth_test8(const DrawRecord& d, const TargetView& t, int gx, int gy,
                                        unsigned mask, const Float8& z) {
  std::byte* row0 = t.depth + size_t(gy) * t.depth_row_bytes + size_t(gx) * 4;
  std::byte* row1 = row0 + t.depth_row_bytes;
  const Int8 stored = load_group(row0, row1);
  const Mask8 live = Mask8::from_bits(mask);
  Mask8 pass;
  Int8 value;
  if (t.depth_format == Format::Depth32F) {
    pass = compare(d.state.depth_func, z, float_from_bits(stored)) & live;
    value = bits_of(z);
  } else {
    const Int8 q = quantize24x8(z);
    pass = compare(d.state.depth_func, q, stored & Int8(0xFFFFFF)) & live;
    value = (stored & Int8(int32_t(0xFF000000u))) | q;
  }
  const unsigned bits = pass.bits();
  if (bits && d.state.depth_write) store_group(row0, row1, select(pass, value, stored));
  return bits;
}

TESSEL_FAST_INLINE Int8 to_unorm8(Float8 c) {
  c = min(max(c, Float8(0.0f)), Float8(1.0f)) * Float8(255.0f);  // NaN -> 0, as sat()
#if defined(__AVX2__)
  return Int8((vx::i32x8)_mm256_cvtps_epi32((__m256)c.v));  // round to nearest even, as lrint
#else
  Int8 r;
  for (int i = 0; i < kLanes; ++i) r.v[i] = int32_t(std::lrint(c[i]));
  return r;
#endif
}

// Unblended write of all four channels of an RGBA8 attachment (d.fast_color).
TESSEL_FAST_INLINE void write_rgba8(const ColorTarget& ct, int gx, int gy, unsigned mask,
                                    const Vec4<Float8>& c) {
  std::byte* row0 = ct.data + size_t(gy) * ct.row_bytes + size_t(gx) * 4;
  std::byte* row1 = row0 + ct.row_bytes;
  const Int8 px = to_unorm8(c.x) | (to_unorm8(c.y) << 8) | (to_unorm8(c.z) << 16) | (to_unorm8(c.w) << 24);
  if (mask == 0xFF) return store_group(row0, row1, px);
  store_group(row0, row1, select(Mask8::from_bits(mask), px, load_group(row0, row1)));
}

#undef TESSEL_FAST_INLINE

}  // namespace tessel::gpu::detail
