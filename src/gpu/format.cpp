#include "tessel/gpu/format.hpp"

#include <cstring>

namespace tessel::gpu {

namespace {
uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}
float from_bits(uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}
}  // namespace

uint16_t float_to_half(float f) {
  const uint32_t x = bits(f);
  const uint32_t sign = (x >> 16) & 0x8000u;
  const uint32_t a = x & 0x7FFFFFFFu;
  if (a >= 0x7F800000u) {
    if (a == 0x7F800000u) return uint16_t(sign | 0x7C00u);  // infinity
    // NaN: keep the top payload bits; a payload that would vanish becomes a quiet NaN.
    uint32_t payload = (a >> 13) & 0x3FFu;
    if (payload == 0) payload = 0x200u;
    return uint16_t(sign | 0x7C00u | payload);
  }
  // 65520 and above round to infinity (65504 is the largest finite half; 65520 is the tie,
  // and it rounds to the even neighbour, which is infinity).
  if (a >= 0x477FF000u) return uint16_t(sign | 0x7C00u);
  if (a >= 0x38800000u) {
    // Normal half: rebias the exponent and round the 13 dropped mantissa bits to nearest even.
    uint32_t h = (a - 0x38000000u) >> 13;
    const uint32_t rem = a & 0x1FFFu;
    if (rem > 0x1000u || (rem == 0x1000u && (h & 1u))) ++h;  // a carry moves into the exponent
    return uint16_t(sign | h);
  }
  // Below the smallest normal half (2^-14): a subnormal half counts units of 2^-24.
  if (a < 0x33000000u) return uint16_t(sign);  // below 2^-25: rounds to zero (2^-25 ties to 0)
  const uint32_t e = a >> 23;                  // biased exponent, 102..112
  const uint32_t m = (a & 0x7FFFFFu) | 0x800000u;
  const uint32_t shift = 126u - e;  // 14..24
  uint32_t h = m >> shift;
  const uint32_t rem = m & ((1u << shift) - 1u);
  const uint32_t half = 1u << (shift - 1u);
  if (rem > half || (rem == half && (h & 1u))) ++h;  // may become 0x400, the smallest normal
  return uint16_t(sign | h);
}

float half_to_float(uint16_t h) {
  const uint32_t sign = uint32_t(h & 0x8000u) << 16;
  const uint32_t e = (h >> 10) & 0x1Fu;
  const uint32_t m = h & 0x3FFu;
  if (e == 0x1Fu) return from_bits(sign | 0x7F800000u | (m << 13));  // inf / NaN
  if (e == 0) {
    // Zero or subnormal: m * 2^-24, exact in float.
    const float v = float(m) * 5.9604644775390625e-8f;
    return sign ? -v : v;
  }
  return from_bits(sign | ((e + 112u) << 23) | (m << 13));
}

}  // namespace tessel::gpu
