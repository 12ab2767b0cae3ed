// Pixel formats of textures and attachments, and the errors the gpu layer reports.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace tessel::gpu {

// Thrown for misuse of the API: a bad size, a missing attribute, an index out of range, an
// incomplete framebuffer. The message names what was wrong and where.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Format : uint8_t {
  RGBA8,            // unsigned normalized, 4 bytes
  R8,               // unsigned normalized, 1 byte
  RG8,              // unsigned normalized, 2 bytes
  RGBA16F,          // half floats, 8 bytes
  RGBA32F,          // floats, 16 bytes
  Depth24,          // 24-bit unsigned normalized depth in a 32-bit word
  Depth32F,         // float depth
  Depth24Stencil8,  // depth in the low 24 bits, stencil in the high 8
};

struct FormatInfo {
  const char* name;
  uint8_t bytes;     // per texel
  uint8_t channels;  // colour channels (depth formats: 1)
  bool depth;
  bool stencil;
};

constexpr FormatInfo format_info(Format f) {
  switch (f) {
    case Format::RGBA8: return {"RGBA8", 4, 4, false, false};
    case Format::R8: return {"R8", 1, 1, false, false};
    case Format::RG8: return {"RG8", 2, 2, false, false};
    case Format::RGBA16F: return {"RGBA16F", 8, 4, false, false};
    case Format::RGBA32F: return {"RGBA32F", 16, 4, false, false};
    case Format::Depth24: return {"DEPTH24", 4, 1, true, false};
    case Format::Depth32F: return {"DEPTH32F", 4, 1, true, false};
    case Format::Depth24Stencil8: return {"DEPTH24_STENCIL8", 4, 1, true, true};
  }
  return {"?", 0, 0, false, false};
}
constexpr bool is_depth_format(Format f) { return format_info(f).depth; }
constexpr bool is_color_format(Format f) { return !format_info(f).depth; }
// Unsigned normalized 8-bit colour formats (values clamp to [0, 1] when stored or blended).
constexpr bool is_unorm8_format(Format f) {
  return f == Format::RGBA8 || f == Format::R8 || f == Format::RG8;
}

// The components of an integer colour format. Integer texels are kept in a float format's
// slots as their 32 bits (an int32 or a uint32), so an RGBA32F image can hold any integer
// format; this says which values each component can hold.
struct IntegerRange {
  uint8_t bits[4] = {0, 0, 0, 0};  // per component, 1..32; 0: not an integer format
  bool is_signed = false;
  constexpr bool integer() const { return bits[0] != 0; }
};

// A component's integer bits (an int32 when signed, else a uint32) clamped to `bits` bits, as
// llvmpipe stores integer colours (GL leaves values out of range undefined).
constexpr uint32_t clamp_integer_bits(uint32_t v, int bits, bool is_signed) {
  if (bits <= 0 || bits >= 32) return v;
  if (!is_signed) {
    const uint32_t hi = (1u << bits) - 1u;
    return v < hi ? v : hi;
  }
  const int32_t sv = static_cast<int32_t>(v), hi = static_cast<int32_t>((1u << (bits - 1)) - 1u);
  const int32_t lo = -hi - 1;
  return static_cast<uint32_t>(sv < lo ? lo : sv > hi ? hi : sv);
}

// IEEE half <-> float, exact for every half; float -> half rounds to nearest even.
uint16_t float_to_half(float f);
float half_to_float(uint16_t h);

}  // namespace tessel::gpu
