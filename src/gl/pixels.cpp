// Pixel transfer: unpacking client images into RGBA, packing RGBA into client memory.
#include "pixels.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <limits>

#include "tessel/gpu/format.hpp"

namespace tessel::gl {

int format_components(GLenum format) {
  switch (format) {
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_LUMINANCE:
    case GL_DEPTH_COMPONENT:
    case GL_STENCIL_INDEX:
    case GL_COLOR_INDEX:
    case GL_RED_INTEGER:
    case GL_GREEN_INTEGER:
    case GL_BLUE_INTEGER: return 1;
    case GL_LUMINANCE_ALPHA:
    case GL_RG:
    case GL_RG_INTEGER:
    case GL_DEPTH_STENCIL: return 2;
    case GL_RGB:
    case GL_BGR:
    case GL_RGB_INTEGER:
    case GL_BGR_INTEGER: return 3;
    case GL_RGBA:
    case GL_BGRA:
    case GL_RGBA_INTEGER:
    case GL_BGRA_INTEGER: return 4;
    default: return 0;
  }
}

int type_bytes(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE:
    case GL_UNSIGNED_BYTE_3_3_2:
    case GL_UNSIGNED_BYTE_2_3_3_REV: return 1;
    case GL_UNSIGNED_SHORT:
    case GL_SHORT:
    case GL_HALF_FLOAT:
    case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV:
    case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1:
    case GL_UNSIGNED_SHORT_1_5_5_5_REV: return 2;
    case GL_UNSIGNED_INT:
    case GL_INT:
    case GL_FLOAT:
    case GL_UNSIGNED_INT_8_8_8_8:
    case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2:
    case GL_UNSIGNED_INT_2_10_10_10_REV:
    case GL_UNSIGNED_INT_24_8:
    case GL_UNSIGNED_INT_10F_11F_11F_REV:
    case GL_UNSIGNED_INT_5_9_9_9_REV: return 4;
    case GL_FLOAT_32_UNSIGNED_INT_24_8_REV: return 8;
    case GL_BITMAP: return 0;
    default: return -1;
  }
}

bool valid_pixel_format(GLenum format) { return format_components(format) > 0; }
bool valid_pixel_type(GLenum type) { return type_bytes(type) >= 0; }

bool is_integer_format(GLenum format) {
  switch (format) {
    case GL_RED_INTEGER:
    case GL_GREEN_INTEGER:
    case GL_BLUE_INTEGER:
    case GL_RG_INTEGER:
    case GL_RGB_INTEGER:
    case GL_BGR_INTEGER:
    case GL_RGBA_INTEGER:
    case GL_BGRA_INTEGER: return true;
    default: return false;
  }
}

namespace {

// The fields of a packed type (Table 3.5/3.6), widths in component order. Non-REV types hold
// the first component in the most significant bits, REV types in the least significant ones.
struct PackedLayout {
  int n = 0;          // fields (components)
  int width[4] = {};  // bits of each
  int total = 0;      // bits of the element
  bool rev = false;
};

bool packed_layout(GLenum type, PackedLayout& P) {
  auto set = [&](int total, bool rev, std::initializer_list<int> w) {
    P.n = 0;
    for (int x : w) P.width[P.n++] = x;
    P.total = total;
    P.rev = rev;
    return true;
  };
  switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2: return set(8, false, {3, 3, 2});
    case GL_UNSIGNED_BYTE_2_3_3_REV: return set(8, true, {3, 3, 2});
    case GL_UNSIGNED_SHORT_5_6_5: return set(16, false, {5, 6, 5});
    case GL_UNSIGNED_SHORT_5_6_5_REV: return set(16, true, {5, 6, 5});
    case GL_UNSIGNED_SHORT_4_4_4_4: return set(16, false, {4, 4, 4, 4});
    case GL_UNSIGNED_SHORT_4_4_4_4_REV: return set(16, true, {4, 4, 4, 4});
    case GL_UNSIGNED_SHORT_5_5_5_1: return set(16, false, {5, 5, 5, 1});
    case GL_UNSIGNED_SHORT_1_5_5_5_REV: return set(16, true, {5, 5, 5, 1});
    case GL_UNSIGNED_INT_8_8_8_8: return set(32, false, {8, 8, 8, 8});
    case GL_UNSIGNED_INT_8_8_8_8_REV: return set(32, true, {8, 8, 8, 8});
    case GL_UNSIGNED_INT_10_10_10_2: return set(32, false, {10, 10, 10, 2});
    case GL_UNSIGNED_INT_2_10_10_10_REV: return set(32, true, {10, 10, 10, 2});
    default: return false;
  }
}

// Bit position of field k.
int field_shift(const PackedLayout& P, int k) {
  int before = 0;
  for (int i = 0; i < k; ++i) before += P.width[i];
  return P.rev ? before : P.total - before - P.width[k];
}

}  // namespace

bool is_packed_type(GLenum type) {
  PackedLayout P;
  return packed_layout(type, P) || type == GL_UNSIGNED_INT_24_8 || type == GL_UNSIGNED_INT_10F_11F_11F_REV ||
         type == GL_UNSIGNED_INT_5_9_9_9_REV || type == GL_FLOAT_32_UNSIGNED_INT_24_8_REV;
}

GLenum check_format_type(GLenum format, GLenum type) {
  if (!valid_pixel_format(format) || !valid_pixel_type(type)) return GL_INVALID_ENUM;
  if (type == GL_BITMAP) {
    return format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX ? GL_NO_ERROR : GL_INVALID_ENUM;
  }
  const bool integer = is_integer_format(format);
  switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2:
    case GL_UNSIGNED_BYTE_2_3_3_REV:
    case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV:
      if (format != GL_RGB && format != GL_RGB_INTEGER) return GL_INVALID_OPERATION;
      break;
    case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1:
    case GL_UNSIGNED_SHORT_1_5_5_5_REV:
    case GL_UNSIGNED_INT_8_8_8_8:
    case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2:
    case GL_UNSIGNED_INT_2_10_10_10_REV:
      if (format != GL_RGBA && format != GL_BGRA && format != GL_RGBA_INTEGER && format != GL_BGRA_INTEGER)
        return GL_INVALID_OPERATION;
      break;
    case GL_UNSIGNED_INT_10F_11F_11F_REV:
    case GL_UNSIGNED_INT_5_9_9_9_REV:
      if (format != GL_RGB) return GL_INVALID_OPERATION;  // RGB_INTEGER too (float type)
      break;
    case GL_UNSIGNED_INT_24_8:
    case GL_FLOAT_32_UNSIGNED_INT_24_8_REV:
      if (format != GL_DEPTH_STENCIL) return GL_INVALID_OPERATION;
      break;
    default: break;
  }
  // DEPTH_STENCIL with a type that is not one of the two depth-stencil types: INVALID_ENUM
  // (the ARB_framebuffer_object / GL 3.0 wording, as Mesa and the Khronos CTS have it). A
  // packed colour type with DEPTH_STENCIL was already INVALID_OPERATION above.
  if (format == GL_DEPTH_STENCIL && type != GL_UNSIGNED_INT_24_8 && type != GL_FLOAT_32_UNSIGNED_INT_24_8_REV)
    return GL_INVALID_ENUM;
  if (integer && (type == GL_FLOAT || type == GL_HALF_FLOAT)) return GL_INVALID_OPERATION;
  return GL_NO_ERROR;
}

bool valid_format_type(GLenum format, GLenum type) { return check_format_type(format, type) == GL_NO_ERROR; }

GLenum check_format_type(GLenum format, GLenum type, bool core) {
  if (core && (format == GL_ALPHA || format == GL_LUMINANCE || format == GL_LUMINANCE_ALPHA ||
               format == GL_COLOR_INDEX || type == GL_BITMAP))
    return GL_INVALID_ENUM;
  return check_format_type(format, type);
}

PixelLayout pixel_layout(const PixelStore& ps, int width, GLenum format, GLenum type) {
  PixelLayout L;
  const size_t n = is_packed_type(type) ? 1 : size_t(format_components(format));
  const size_t l = size_t(ps.row_length > 0 ? ps.row_length : width);
  const size_t a = size_t(ps.alignment);
  if (type == GL_BITMAP) {
    L.row_stride = a * ((l + 8 * a - 1) / (8 * a));
    L.pixel_stride = 0;
    L.offset = size_t(ps.skip_rows) * L.row_stride;  // skip_pixels is applied in bits
    return L;
  }
  const size_t s = size_t(type_bytes(type));
  size_t k;  // elements per row (GL 2.1 eq. 3.1)
  if (s >= a)
    k = n * l;
  else
    k = (a / s) * ((s * n * l + a - 1) / a);
  L.row_stride = k * s;
  L.pixel_stride = n * s;
  L.offset = size_t(ps.skip_pixels) * n * s + size_t(ps.skip_rows) * L.row_stride;
  return L;
}

namespace {

// GL_*_SWAP_BYTES for a 2- or 4-byte component.
void swap_bytes(uint8_t* b, int size) {
  if (size == 2) {
    std::swap(b[0], b[1]);
  } else if (size == 4) {
    std::swap(b[0], b[3]);
    std::swap(b[1], b[2]);
  }
}

// A component of a non-packed type as its integer value (the *_INTEGER formats), not
// normalized: the value's 32 bits (as int32 or uint32, by the type's sign) in the float, so
// that integer texels travel exactly (texture_format.hpp).
float int_bits(int64_t v) { return std::bit_cast<float>(uint32_t(v)); }
float read_integer_component(const uint8_t* b, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return int_bits(b[0]);
    case GL_BYTE: return int_bits(int8_t(b[0]));
    case GL_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, b, 2);
      return int_bits(v);
    }
    case GL_SHORT: {
      int16_t v;
      std::memcpy(&v, b, 2);
      return int_bits(v);
    }
    case GL_UNSIGNED_INT:
    case GL_INT: {
      float v;
      std::memcpy(&v, b, 4);
      return v;
    }
    default: return 0.0f;  // (no float type goes with an *_INTEGER format: checked before)
  }
}

// A colour or stencil index of an integer type: the integer itself, as a float (indices are
// not normalized, GL 2.1 §3.6.4).
float index_component(const uint8_t* p, GLenum type, bool swap) {
  uint8_t b[4] = {0, 0, 0, 0};
  const int sz = std::clamp(type_bytes(type), 1, 4);
  std::memcpy(b, p, size_t(sz));
  if (swap) swap_bytes(b, sz);
  const uint32_t bits = std::bit_cast<uint32_t>(read_integer_component(b, type));
  switch (type) {
    case GL_BYTE: return float(int8_t(bits));
    case GL_SHORT: return float(int16_t(bits));
    case GL_INT: return float(int32_t(bits));
    case GL_UNSIGNED_BYTE:
    case GL_UNSIGNED_SHORT:
    case GL_UNSIGNED_INT: return float(bits);
    default: return 0.0f;
  }
}

float read_component(const uint8_t* p, GLenum type, bool swap, bool integer) {
  uint8_t b[4] = {0, 0, 0, 0};
  const int sz = std::clamp(type_bytes(type), 1, 4);
  std::memcpy(b, p, size_t(sz));
  if (swap) swap_bytes(b, sz);
  if (integer) return read_integer_component(b, type);
  switch (type) {
    case GL_UNSIGNED_BYTE: return float(b[0]) / 255.0f;
    case GL_BYTE: return (2.0f * float(int8_t(b[0])) + 1.0f) / 255.0f;
    case GL_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, b, 2);
      return float(v) / 65535.0f;
    }
    case GL_SHORT: {
      int16_t v;
      std::memcpy(&v, b, 2);
      return (2.0f * float(v) + 1.0f) / 65535.0f;
    }
    case GL_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, b, 4);
      return float(double(v) / 4294967295.0);
    }
    case GL_INT: {
      int32_t v;
      std::memcpy(&v, b, 4);
      return float((2.0 * double(v) + 1.0) / 4294967295.0);
    }
    case GL_HALF_FLOAT: {
      uint16_t v;
      std::memcpy(&v, b, 2);
      return gpu::half_to_float(v);
    }
    default: {
      float v;
      std::memcpy(&v, b, 4);
      return v;
    }
  }
}

// A value rounded and clamped to [lo, hi] (NaN gives 0).
double round_clamp(float v, double lo, double hi) {
  if (std::isnan(v)) return 0.0;
  return std::clamp(std::nearbyint(double(v)), lo, hi);
}

// An integer component (its 32 bits in v, as read_integer_component gives them) as `type`:
// read as signed for the signed types and unsigned for the others, then clamped.
void write_integer_component(uint8_t* b, GLenum type, float v) {
  const uint32_t bits = std::bit_cast<uint32_t>(v);
  const int64_t sv = int32_t(bits), uv = bits;
  switch (type) {
    case GL_UNSIGNED_BYTE: b[0] = uint8_t(std::min<int64_t>(uv, 255)); break;
    case GL_BYTE: b[0] = uint8_t(int8_t(std::clamp<int64_t>(sv, -128, 127))); break;
    case GL_UNSIGNED_SHORT: {
      const uint16_t x = uint16_t(std::min<int64_t>(uv, 65535));
      std::memcpy(b, &x, 2);
      break;
    }
    case GL_SHORT: {
      const int16_t x = int16_t(std::clamp<int64_t>(sv, -32768, 32767));
      std::memcpy(b, &x, 2);
      break;
    }
    default: std::memcpy(b, &bits, 4); break;  // GL_INT, GL_UNSIGNED_INT: the bits
  }
}

void write_half(uint8_t* b, float v) {
  const uint16_t x = gpu::float_to_half(v);
  std::memcpy(b, &x, 2);
}

void write_component(uint8_t* p, GLenum type, float v, bool swap, bool integer) {
  uint8_t b[4] = {0, 0, 0, 0};
  const int sz = std::clamp(type_bytes(type), 1, 4);
  if (integer || type == GL_HALF_FLOAT) {
    if (integer)
      write_integer_component(b, type, v);
    else
      write_half(b, v);
    if (swap) swap_bytes(b, sz);
    std::memcpy(p, b, size_t(sz));
    return;
  }
  const double c = std::clamp(double(v),
                              type == GL_FLOAT                                          ? -1e38
                              : (type == GL_BYTE || type == GL_SHORT || type == GL_INT) ? -1.0
                                                                                        : 0.0,
                              type == GL_FLOAT ? 1e38 : 1.0);
  switch (type) {
    case GL_UNSIGNED_BYTE: b[0] = uint8_t(std::lround(c * 255.0)); break;
    case GL_BYTE: b[0] = uint8_t(int8_t(std::lround((c * 255.0 - 1.0) / 2.0))); break;
    case GL_UNSIGNED_SHORT: {
      const uint16_t x = uint16_t(std::lround(c * 65535.0));
      std::memcpy(b, &x, 2);
      break;
    }
    case GL_SHORT: {
      const int16_t x = int16_t(std::lround((c * 65535.0 - 1.0) / 2.0));
      std::memcpy(b, &x, 2);
      break;
    }
    case GL_UNSIGNED_INT: {
      const uint32_t x = uint32_t(std::llround(c * 4294967295.0));
      std::memcpy(b, &x, 4);
      break;
    }
    case GL_INT: {
      const int32_t x = int32_t(std::llround((c * 4294967295.0 - 1.0) / 2.0));
      std::memcpy(b, &x, 4);
      break;
    }
    default: {
      const float x = float(c);
      std::memcpy(b, &x, 4);
      break;
    }
  }
  if (swap) swap_bytes(b, sz);
  std::memcpy(p, b, size_t(sz));
}

// Unsigned floats of 5 exponent bits and `mbits` mantissa bits (the 11- and 10-bit floats of
// UNSIGNED_INT_10F_11F_11F_REV, GL 3.3 §2.1.3-2.1.4).
float ufloat_to_float(uint32_t bits, int mbits) {
  const uint32_t e = (bits >> mbits) & 31u, m = bits & ((1u << mbits) - 1u);
  if (e == 0) return std::ldexp(float(m), -14 - mbits);
  if (e == 31) return m ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
  return std::ldexp(1.0f + float(m) / float(1u << mbits), int(e) - 15);
}

uint32_t float_to_ufloat(float v, int mbits) {
  const uint32_t inf = 31u << mbits, max_finite = inf - 1u;
  if (std::isnan(v)) return inf | 1u;
  if (!(v > 0.0f)) return 0;  // negative values and zero
  if (std::isinf(v)) return inf;
  int e;
  std::frexp(double(v), &e);  // v = f * 2^e, f in [0.5, 1)
  const int biased = e - 1 + 15;
  uint32_t bits;
  if (biased <= 0) {  // denormal: m * 2^(-14 - mbits); rounding up to 2^mbits gives exponent 1
    bits = uint32_t(std::lround(std::ldexp(double(v), 14 + mbits)));
  } else {
    const long m = std::lround((std::ldexp(double(v), -(e - 1)) - 1.0) * double(1u << mbits));
    bits = (uint32_t(biased) << mbits) + uint32_t(m);  // a carry moves into the exponent
  }
  return std::min(bits, max_finite);
}

// GL_UNSIGNED_INT_5_9_9_9_REV: three 9-bit mantissas and a shared 5-bit exponent (GL 3.3 §3.8.3,
// the RGB9_E5 conversion).
glm::vec3 rgb9e5_to_float(uint32_t v) {
  const int e = int(v >> 27) - 15 - 9;
  return {std::ldexp(float(v & 511u), e), std::ldexp(float((v >> 9) & 511u), e),
          std::ldexp(float((v >> 18) & 511u), e)};
}

uint32_t float_to_rgb9e5(float r, float g, float b) {
  constexpr int N = 9, B = 15, Emax = 31;
  const double max = double((1 << N) - 1) / double(1 << N) * std::ldexp(1.0, Emax - B);
  auto clampc = [&](float x) { return x > 0.0f ? std::min(double(x), max) : 0.0; };  // NaN: 0
  const double rc = clampc(r), gc = clampc(g), bc = clampc(b);
  const double maxc = std::max({rc, gc, bc});
  int exp_shared = std::max(-B - 1, maxc > 0.0 ? int(std::floor(std::log2(maxc))) : -B - 1) + 1 + B;
  const double maxs = std::floor(maxc / std::ldexp(1.0, exp_shared - B - N) + 0.5);
  if (maxs >= double(1 << N)) ++exp_shared;
  const double scale = std::ldexp(1.0, exp_shared - B - N);
  auto mant = [&](double x) { return std::min(uint32_t(std::floor(x / scale + 0.5)), 511u); };
  return mant(rc) | (mant(gc) << 9) | (mant(bc) << 18) | (uint32_t(exp_shared) << 27);
}

uint32_t read_element(const uint8_t* p, int size, bool swap) {
  uint8_t b[4] = {0, 0, 0, 0};
  std::memcpy(b, p, size_t(size));
  if (swap) swap_bytes(b, size);
  switch (size) {
    case 1: return b[0];
    case 2: {
      uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    default: {
      uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
  }
}

void write_element(uint8_t* p, int size, uint32_t v, bool swap) {
  uint8_t b[4] = {0, 0, 0, 0};
  switch (size) {
    case 1: b[0] = uint8_t(v); break;
    case 2: {
      const uint16_t x = uint16_t(v);
      std::memcpy(b, &x, 2);
      break;
    }
    default: std::memcpy(b, &v, 4); break;
  }
  if (swap) swap_bytes(b, size);
  std::memcpy(p, b, size_t(size));
}

// The components of one packed pixel, in the type's (the format's) order; depth-stencil as
// (depth, stencil). Returns how many.
int read_packed(const uint8_t* p, GLenum type, bool swap, bool integer, float c[4]) {
  PackedLayout P;
  if (packed_layout(type, P)) {
    const uint32_t v = read_element(p, P.total / 8, swap);
    for (int k = 0; k < P.n; ++k) {
      const uint32_t mask = (1u << P.width[k]) - 1u;
      const uint32_t f = (v >> field_shift(P, k)) & mask;
      c[k] = integer ? int_bits(f) : float(f) / float(mask);
    }
    return P.n;
  }
  switch (type) {
    case GL_UNSIGNED_INT_10F_11F_11F_REV: {
      const uint32_t v = read_element(p, 4, swap);
      c[0] = ufloat_to_float(v & 0x7FFu, 6);
      c[1] = ufloat_to_float((v >> 11) & 0x7FFu, 6);
      c[2] = ufloat_to_float(v >> 22, 5);
      return 3;
    }
    case GL_UNSIGNED_INT_5_9_9_9_REV: {
      const glm::vec3 rgb = rgb9e5_to_float(read_element(p, 4, swap));
      c[0] = rgb.r, c[1] = rgb.g, c[2] = rgb.b;
      return 3;
    }
    case GL_UNSIGNED_INT_24_8: {
      const uint32_t v = read_element(p, 4, swap);
      c[0] = float(double(v >> 8) / 16777215.0);
      c[1] = float(v & 0xFFu);
      return 2;
    }
    case GL_FLOAT_32_UNSIGNED_INT_24_8_REV: {
      const uint32_t d = read_element(p, 4, swap), s = read_element(p + 4, 4, swap);
      std::memcpy(&c[0], &d, 4);
      c[1] = float(s & 0xFFu);
      return 2;
    }
    default: return 0;
  }
}

void write_packed(uint8_t* p, GLenum type, bool swap, bool integer, const float c[4]) {
  PackedLayout P;
  if (packed_layout(type, P)) {
    uint32_t v = 0;
    for (int k = 0; k < P.n; ++k) {
      const uint32_t mask = (1u << P.width[k]) - 1u;
      const double m = double(mask);
      uint32_t f;
      if (integer) {
        f = std::min(std::bit_cast<uint32_t>(c[k]), mask);
      } else {
        const double x = std::isnan(c[k]) ? 0.0 : std::clamp(double(c[k]), 0.0, 1.0);
        f = uint32_t(std::lround(x * m));
      }
      v |= (f & mask) << field_shift(P, k);
    }
    write_element(p, P.total / 8, v, swap);
    return;
  }
  switch (type) {
    case GL_UNSIGNED_INT_10F_11F_11F_REV:
      write_element(
          p, 4,
          float_to_ufloat(c[0], 6) | (float_to_ufloat(c[1], 6) << 11) | (float_to_ufloat(c[2], 5) << 22),
          swap);
      break;
    case GL_UNSIGNED_INT_5_9_9_9_REV: write_element(p, 4, float_to_rgb9e5(c[0], c[1], c[2]), swap); break;
    case GL_UNSIGNED_INT_24_8: {
      const double d = std::isnan(c[0]) ? 0.0 : std::clamp(double(c[0]), 0.0, 1.0);
      const uint32_t depth = uint32_t(std::llround(d * 16777215.0));
      write_element(p, 4, (depth << 8) | uint32_t(round_clamp(c[1], 0, 255)), swap);
      break;
    }
    case GL_FLOAT_32_UNSIGNED_INT_24_8_REV: {
      uint32_t d;
      std::memcpy(&d, &c[0], 4);
      write_element(p, 4, d, swap);
      write_element(p + 4, 4, uint32_t(round_clamp(c[1], 0, 255)), swap);
      break;
    }
    default: break;
  }
}

}  // namespace

void unpack_pixels(const PixelStore& ps, int w, int h, GLenum format, GLenum type, const void* data,
                   std::vector<glm::vec4>& out) {
  out.assign(size_t(w) * size_t(h), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  if (!data || w <= 0 || h <= 0) return;
  if (type == GL_BITMAP) {
    std::vector<uint8_t> bits;
    unpack_bitmap(ps, w, h, data, bits);
    for (size_t i = 0; i < bits.size(); ++i) out[i] = glm::vec4(bits[i] ? 1.0f : 0.0f);
    return;
  }
  const PixelLayout L = pixel_layout(ps, w, format, type);
  const int n = format_components(format);
  const bool packed = is_packed_type(type);
  const bool integer = is_integer_format(format);
  const size_t cs = size_t(type_bytes(type));
  const uint8_t* base = static_cast<const uint8_t*>(data) + L.offset;
  const bool swap = ps.swap_bytes && cs > 1;
  const bool index = format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX;
  for (int y = 0; y < h; ++y) {
    const uint8_t* row = base + size_t(y) * L.row_stride;
    for (int x = 0; x < w; ++x) {
      const uint8_t* p = row + size_t(x) * L.pixel_stride;
      float c[4] = {0, 0, 0, 1};
      if (packed)
        read_packed(p, type, swap, integer, c);
      else if (index && type != GL_FLOAT && type != GL_HALF_FLOAT)
        c[0] = index_component(p, type, swap);
      else
        for (int k = 0; k < n; ++k) c[k] = read_component(p + size_t(k) * cs, type, swap, integer);
      glm::vec4& o = out[size_t(y) * size_t(w) + size_t(x)];
      switch (format) {
        case GL_RED:
        case GL_RED_INTEGER: o = {c[0], 0, 0, 1}; break;
        case GL_GREEN:
        case GL_GREEN_INTEGER: o = {0, c[0], 0, 1}; break;
        case GL_BLUE:
        case GL_BLUE_INTEGER: o = {0, 0, c[0], 1}; break;
        case GL_ALPHA: o = {0, 0, 0, c[0]}; break;
        case GL_LUMINANCE: o = {c[0], c[0], c[0], 1}; break;
        case GL_LUMINANCE_ALPHA: o = {c[0], c[0], c[0], c[1]}; break;
        case GL_RG:
        case GL_RG_INTEGER:
        case GL_DEPTH_STENCIL: o = {c[0], c[1], 0, 1}; break;
        case GL_RGB:
        case GL_RGB_INTEGER: o = {c[0], c[1], c[2], 1}; break;
        case GL_BGR:
        case GL_BGR_INTEGER: o = {c[2], c[1], c[0], 1}; break;
        case GL_RGBA:
        case GL_RGBA_INTEGER: o = {c[0], c[1], c[2], c[3]}; break;
        case GL_BGRA:
        case GL_BGRA_INTEGER: o = {c[2], c[1], c[0], c[3]}; break;
        default: o = {c[0], 0, 0, 1}; break;  // depth, stencil, index: the value in .x
      }
      // An integer format without alpha gives alpha 1 as an integer (its bits, as above).
      if (integer && format != GL_RGBA_INTEGER && format != GL_BGRA_INTEGER) o.a = int_bits(1);
    }
  }
}

void unpack_bitmap(const PixelStore& ps, int w, int h, const void* data, std::vector<uint8_t>& out) {
  out.assign(size_t(std::max(w, 0)) * size_t(std::max(h, 0)), 0);
  if (!data || w <= 0 || h <= 0) return;
  const PixelLayout L = pixel_layout(ps, w, GL_COLOR_INDEX, GL_BITMAP);
  const uint8_t* base = static_cast<const uint8_t*>(data) + L.offset;
  for (int y = 0; y < h; ++y) {
    const uint8_t* row = base + size_t(y) * L.row_stride;
    for (int x = 0; x < w; ++x) {
      const int bit = x + ps.skip_pixels;
      const uint8_t byte = row[bit / 8];
      const int shift = ps.lsb_first ? (bit % 8) : (7 - bit % 8);
      out[size_t(y) * size_t(w) + size_t(x)] = (byte >> shift) & 1;
    }
  }
}

void pack_pixels(const PixelStore& ps, int w, int h, GLenum format, GLenum type,
                 const std::vector<glm::vec4>& in, void* data) {
  if (!data || w <= 0 || h <= 0) return;
  const PixelLayout L = pixel_layout(ps, w, format, type);
  const bool packed = is_packed_type(type);
  const bool integer = is_integer_format(format);
  const size_t cs = size_t(type_bytes(type));
  uint8_t* base = static_cast<uint8_t*>(data) + L.offset;
  const bool swap = ps.swap_bytes && cs > 1;
  for (int y = 0; y < h; ++y) {
    uint8_t* row = base + size_t(y) * L.row_stride;
    for (int x = 0; x < w; ++x) {
      uint8_t* p = row + size_t(x) * L.pixel_stride;
      const glm::vec4& c = in[size_t(y) * size_t(w) + size_t(x)];
      float v[4] = {0, 0, 0, 0};
      int n = 0;
      switch (format) {
        case GL_RED:
        case GL_RED_INTEGER: v[n++] = c.r; break;
        case GL_GREEN:
        case GL_GREEN_INTEGER: v[n++] = c.g; break;
        case GL_BLUE:
        case GL_BLUE_INTEGER: v[n++] = c.b; break;
        case GL_ALPHA: v[n++] = c.a; break;
        // GL 2.1 §4.3.2: luminance is R + G + B (clamped).
        case GL_LUMINANCE: v[n++] = std::min(1.0f, c.r + c.g + c.b); break;
        case GL_LUMINANCE_ALPHA:
          v[n++] = std::min(1.0f, c.r + c.g + c.b);
          v[n++] = c.a;
          break;
        case GL_RG:
        case GL_RG_INTEGER:
        case GL_DEPTH_STENCIL: v[0] = c.r, v[1] = c.g, n = 2; break;
        case GL_RGB:
        case GL_RGB_INTEGER: v[0] = c.r, v[1] = c.g, v[2] = c.b, n = 3; break;
        case GL_BGR:
        case GL_BGR_INTEGER: v[0] = c.b, v[1] = c.g, v[2] = c.r, n = 3; break;
        case GL_RGBA:
        case GL_RGBA_INTEGER: v[0] = c.r, v[1] = c.g, v[2] = c.b, v[3] = c.a, n = 4; break;
        case GL_BGRA:
        case GL_BGRA_INTEGER: v[0] = c.b, v[1] = c.g, v[2] = c.r, v[3] = c.a, n = 4; break;
        default: v[n++] = c.x; break;
      }
      if (packed)
        write_packed(p, type, swap, integer, v);
      else
        for (int k = 0; k < n; ++k) write_component(p + size_t(k) * cs, type, v[k], swap, integer);
    }
  }
}

void match_integer_sign(std::vector<glm::vec4>& px, bool source_signed, GLenum type) {
  const bool type_signed = type == GL_BYTE || type == GL_SHORT || type == GL_INT;
  if (source_signed == type_signed) return;
  for (glm::vec4& v : px)
    for (int k = 0; k < 4; ++k) {
      const uint32_t bits = std::bit_cast<uint32_t>(v[k]);
      if (bits > 0x7FFFFFFFu) v[k] = std::bit_cast<float>(source_signed ? 0u : 0x7FFFFFFFu);
    }
}

bool base_format_of(GLint f, BaseFormat& base) {
  switch (f) {
    case 1:
    case GL_LUMINANCE:
    case GL_LUMINANCE4:
    case GL_LUMINANCE8:
    case GL_LUMINANCE12:
    case GL_LUMINANCE16: base = BaseFormat::Luminance; return true;
    case 2:
    case GL_LUMINANCE_ALPHA:
    case GL_LUMINANCE4_ALPHA4:
    case GL_LUMINANCE6_ALPHA2:
    case GL_LUMINANCE8_ALPHA8:
    case GL_LUMINANCE12_ALPHA4:
    case GL_LUMINANCE12_ALPHA12:
    case GL_LUMINANCE16_ALPHA16: base = BaseFormat::LuminanceAlpha; return true;
    case GL_ALPHA:
    case GL_ALPHA4:
    case GL_ALPHA8:
    case GL_ALPHA12:
    case GL_ALPHA16: base = BaseFormat::Alpha; return true;
    case GL_INTENSITY:
    case GL_INTENSITY4:
    case GL_INTENSITY8:
    case GL_INTENSITY12:
    case GL_INTENSITY16: base = BaseFormat::Intensity; return true;
    case 3:
    case GL_RGB:
    case GL_R3_G3_B2:
    case GL_RGB4:
    case GL_RGB5:
    case GL_RGB8:
    case GL_RGB10:
    case GL_RGB12:
    case GL_RGB16: base = BaseFormat::RGB; return true;
    case 4:
    case GL_RGBA:
    case GL_RGBA2:
    case GL_RGBA4:
    case GL_RGB5_A1:
    case GL_RGBA8:
    case GL_RGB10_A2:
    case GL_RGBA12:
    case GL_RGBA16: base = BaseFormat::RGBA; return true;
    default: return false;
  }
}

void to_texture_rgba8(const std::vector<glm::vec4>& in, BaseFormat base, std::vector<uint8_t>& out) {
  out.resize(in.size() * 4);
  for (size_t i = 0; i < in.size(); ++i) {
    const glm::vec4& c = in[i];
    uint8_t* o = &out[i * 4];
    switch (base) {
      case BaseFormat::Alpha: o[0] = o[1] = o[2] = 0, o[3] = unorm8(c.a); break;
      case BaseFormat::Luminance: o[0] = o[1] = o[2] = unorm8(c.r), o[3] = 255; break;
      case BaseFormat::LuminanceAlpha: o[0] = o[1] = o[2] = unorm8(c.r), o[3] = unorm8(c.a); break;
      case BaseFormat::Intensity: o[0] = o[1] = o[2] = o[3] = unorm8(c.r); break;
      case BaseFormat::RGB: o[0] = unorm8(c.r), o[1] = unorm8(c.g), o[2] = unorm8(c.b), o[3] = 255; break;
      case BaseFormat::RGBA:
        o[0] = unorm8(c.r), o[1] = unorm8(c.g), o[2] = unorm8(c.b), o[3] = unorm8(c.a);
        break;
    }
  }
}

}  // namespace tessel::gl
