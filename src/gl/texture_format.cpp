// The internal format table (GL 3.3 compatibility Tables 3.12-3.17).
#define GL_GLEXT_PROTOTYPES 1
#include "texture_format.hpp"

#include <GL/glext.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace tessel::gl {

namespace {

using F = gpu::Format;
using B = TexBase;
using K = TexKind;

struct Row {
  GLenum internal;
  B base;
  K kind;
  F storage;
  uint8_t r, g, b, a, l, i, d, s;
  bool compat_only;
};

// clang-format off
constexpr Row kFormats[] = {
    // GL 1.x unsized and compatibility formats
    {1, B::Luminance, K::Unorm, F::RGBA8, 0, 0, 0, 0, 8, 0, 0, 0, true},
    {2, B::LuminanceAlpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 8, 0, 0, 0, true},
    {3, B::RGB, K::Unorm, F::RGBA8, 8, 8, 8, 0, 0, 0, 0, 0, true},
    {4, B::RGBA, K::Unorm, F::RGBA8, 8, 8, 8, 8, 0, 0, 0, 0, true},
    {GL_ALPHA, B::Alpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 0, 0, 0, 0, true},
    {GL_ALPHA4, B::Alpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 0, 0, 0, 0, true},
    {GL_ALPHA8, B::Alpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 0, 0, 0, 0, true},
    {GL_ALPHA12, B::Alpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 0, 0, 0, 0, true},
    {GL_ALPHA16, B::Alpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 0, 0, 0, 0, true},
    {GL_LUMINANCE, B::Luminance, K::Unorm, F::RGBA8, 0, 0, 0, 0, 8, 0, 0, 0, true},
    {GL_LUMINANCE4, B::Luminance, K::Unorm, F::RGBA8, 0, 0, 0, 0, 8, 0, 0, 0, true},
    {GL_LUMINANCE8, B::Luminance, K::Unorm, F::RGBA8, 0, 0, 0, 0, 8, 0, 0, 0, true},
    {GL_LUMINANCE12, B::Luminance, K::Unorm, F::RGBA8, 0, 0, 0, 0, 8, 0, 0, 0, true},
    {GL_LUMINANCE16, B::Luminance, K::Unorm, F::RGBA8, 0, 0, 0, 0, 8, 0, 0, 0, true},
    {GL_LUMINANCE_ALPHA, B::LuminanceAlpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 8, 0, 0, 0, true},
    {GL_LUMINANCE4_ALPHA4, B::LuminanceAlpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 8, 0, 0, 0, true},
    {GL_LUMINANCE6_ALPHA2, B::LuminanceAlpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 8, 0, 0, 0, true},
    {GL_LUMINANCE8_ALPHA8, B::LuminanceAlpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 8, 0, 0, 0, true},
    {GL_LUMINANCE12_ALPHA4, B::LuminanceAlpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 8, 0, 0, 0, true},
    {GL_LUMINANCE12_ALPHA12, B::LuminanceAlpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 8, 0, 0, 0, true},
    {GL_LUMINANCE16_ALPHA16, B::LuminanceAlpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 8, 0, 0, 0, true},
    {GL_INTENSITY, B::Intensity, K::Unorm, F::RGBA8, 0, 0, 0, 0, 0, 8, 0, 0, true},
    {GL_INTENSITY4, B::Intensity, K::Unorm, F::RGBA8, 0, 0, 0, 0, 0, 8, 0, 0, true},
    {GL_INTENSITY8, B::Intensity, K::Unorm, F::RGBA8, 0, 0, 0, 0, 0, 8, 0, 0, true},
    {GL_INTENSITY12, B::Intensity, K::Unorm, F::RGBA8, 0, 0, 0, 0, 0, 8, 0, 0, true},
    {GL_INTENSITY16, B::Intensity, K::Unorm, F::RGBA8, 0, 0, 0, 0, 0, 8, 0, 0, true},
    {GL_SLUMINANCE, B::Luminance, K::Srgb, F::RGBA16F, 0, 0, 0, 0, 8, 0, 0, 0, true},
    {GL_SLUMINANCE8, B::Luminance, K::Srgb, F::RGBA16F, 0, 0, 0, 0, 8, 0, 0, 0, true},
    {GL_SLUMINANCE_ALPHA, B::LuminanceAlpha, K::Srgb, F::RGBA16F, 0, 0, 0, 8, 8, 0, 0, 0, true},
    {GL_SLUMINANCE8_ALPHA8, B::LuminanceAlpha, K::Srgb, F::RGBA16F, 0, 0, 0, 8, 8, 0, 0, 0, true},
    // unsigned normalized
    {GL_RED, B::Red, K::Unorm, F::R8, 8, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_R8, B::Red, K::Unorm, F::R8, 8, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_R16, B::Red, K::Unorm, F::RGBA32F, 16, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_RG, B::RG, K::Unorm, F::RG8, 8, 8, 0, 0, 0, 0, 0, 0, false},
    {GL_RG8, B::RG, K::Unorm, F::RG8, 8, 8, 0, 0, 0, 0, 0, 0, false},
    {GL_RG16, B::RG, K::Unorm, F::RGBA32F, 16, 16, 0, 0, 0, 0, 0, 0, false},
    {GL_RGB, B::RGB, K::Unorm, F::RGBA8, 8, 8, 8, 0, 0, 0, 0, 0, false},
    {GL_R3_G3_B2, B::RGB, K::Unorm, F::RGBA8, 3, 3, 2, 0, 0, 0, 0, 0, false},
    {GL_RGB4, B::RGB, K::Unorm, F::RGBA8, 4, 4, 4, 0, 0, 0, 0, 0, false},
    {GL_RGB5, B::RGB, K::Unorm, F::RGBA8, 5, 5, 5, 0, 0, 0, 0, 0, false},
    {GL_RGB8, B::RGB, K::Unorm, F::RGBA8, 8, 8, 8, 0, 0, 0, 0, 0, false},
    {GL_RGB10, B::RGB, K::Unorm, F::RGBA32F, 10, 10, 10, 0, 0, 0, 0, 0, false},
    {GL_RGB12, B::RGB, K::Unorm, F::RGBA32F, 12, 12, 12, 0, 0, 0, 0, 0, false},
    {GL_RGB16, B::RGB, K::Unorm, F::RGBA32F, 16, 16, 16, 0, 0, 0, 0, 0, false},
    {GL_RGBA, B::RGBA, K::Unorm, F::RGBA8, 8, 8, 8, 8, 0, 0, 0, 0, false},
    {GL_RGBA2, B::RGBA, K::Unorm, F::RGBA8, 2, 2, 2, 2, 0, 0, 0, 0, false},
    {GL_RGBA4, B::RGBA, K::Unorm, F::RGBA8, 4, 4, 4, 4, 0, 0, 0, 0, false},
    {GL_RGB5_A1, B::RGBA, K::Unorm, F::RGBA8, 5, 5, 5, 1, 0, 0, 0, 0, false},
    {GL_RGBA8, B::RGBA, K::Unorm, F::RGBA8, 8, 8, 8, 8, 0, 0, 0, 0, false},
    {GL_RGB10_A2, B::RGBA, K::Unorm, F::RGBA32F, 10, 10, 10, 2, 0, 0, 0, 0, false},
    {GL_RGBA12, B::RGBA, K::Unorm, F::RGBA32F, 12, 12, 12, 12, 0, 0, 0, 0, false},
    {GL_RGBA16, B::RGBA, K::Unorm, F::RGBA32F, 16, 16, 16, 16, 0, 0, 0, 0, false},
    {GL_COMPRESSED_RED, B::Red, K::Unorm, F::R8, 8, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_COMPRESSED_RG, B::RG, K::Unorm, F::RG8, 8, 8, 0, 0, 0, 0, 0, 0, false},
    {GL_COMPRESSED_RGB, B::RGB, K::Unorm, F::RGBA8, 8, 8, 8, 0, 0, 0, 0, 0, false},
    {GL_COMPRESSED_RGBA, B::RGBA, K::Unorm, F::RGBA8, 8, 8, 8, 8, 0, 0, 0, 0, false},
    {GL_COMPRESSED_ALPHA, B::Alpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 0, 0, 0, 0, true},
    {GL_COMPRESSED_LUMINANCE, B::Luminance, K::Unorm, F::RGBA8, 0, 0, 0, 0, 8, 0, 0, 0, true},
    {GL_COMPRESSED_LUMINANCE_ALPHA, B::LuminanceAlpha, K::Unorm, F::RGBA8, 0, 0, 0, 8, 8, 0, 0, 0, true},
    {GL_COMPRESSED_INTENSITY, B::Intensity, K::Unorm, F::RGBA8, 0, 0, 0, 0, 0, 8, 0, 0, true},
    // signed normalized
    {GL_R8_SNORM, B::Red, K::Snorm, F::RGBA32F, 8, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_RG8_SNORM, B::RG, K::Snorm, F::RGBA32F, 8, 8, 0, 0, 0, 0, 0, 0, false},
    {GL_RGB8_SNORM, B::RGB, K::Snorm, F::RGBA32F, 8, 8, 8, 0, 0, 0, 0, 0, false},
    {GL_RGBA8_SNORM, B::RGBA, K::Snorm, F::RGBA32F, 8, 8, 8, 8, 0, 0, 0, 0, false},
    {GL_R16_SNORM, B::Red, K::Snorm, F::RGBA32F, 16, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_RG16_SNORM, B::RG, K::Snorm, F::RGBA32F, 16, 16, 0, 0, 0, 0, 0, 0, false},
    {GL_RGB16_SNORM, B::RGB, K::Snorm, F::RGBA32F, 16, 16, 16, 0, 0, 0, 0, 0, false},
    {GL_RGBA16_SNORM, B::RGBA, K::Snorm, F::RGBA32F, 16, 16, 16, 16, 0, 0, 0, 0, false},
    // sRGB
    {GL_SRGB, B::RGB, K::Srgb, F::RGBA16F, 8, 8, 8, 0, 0, 0, 0, 0, false},
    {GL_SRGB8, B::RGB, K::Srgb, F::RGBA16F, 8, 8, 8, 0, 0, 0, 0, 0, false},
    {GL_SRGB_ALPHA, B::RGBA, K::Srgb, F::RGBA16F, 8, 8, 8, 8, 0, 0, 0, 0, false},
    {GL_SRGB8_ALPHA8, B::RGBA, K::Srgb, F::RGBA16F, 8, 8, 8, 8, 0, 0, 0, 0, false},
    // RGTC (GL 3.3 Table 3.14): blocks kept beside their decoded texels (compressed.hpp)
    {GL_COMPRESSED_RED_RGTC1, B::Red, K::Unorm, F::R8, 8, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_COMPRESSED_SIGNED_RED_RGTC1, B::Red, K::Snorm, F::RGBA32F, 8, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_COMPRESSED_RG_RGTC2, B::RG, K::Unorm, F::RG8, 8, 8, 0, 0, 0, 0, 0, 0, false},
    {GL_COMPRESSED_SIGNED_RG_RGTC2, B::RG, K::Snorm, F::RGBA32F, 8, 8, 0, 0, 0, 0, 0, 0, false},
    {GL_COMPRESSED_SRGB, B::RGB, K::Srgb, F::RGBA16F, 8, 8, 8, 0, 0, 0, 0, 0, false},
    {GL_COMPRESSED_SRGB_ALPHA, B::RGBA, K::Srgb, F::RGBA16F, 8, 8, 8, 8, 0, 0, 0, 0, false},
    // float
    {GL_R16F, B::Red, K::Float, F::RGBA16F, 16, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_RG16F, B::RG, K::Float, F::RGBA16F, 16, 16, 0, 0, 0, 0, 0, 0, false},
    {GL_RGB16F, B::RGB, K::Float, F::RGBA16F, 16, 16, 16, 0, 0, 0, 0, 0, false},
    {GL_RGBA16F, B::RGBA, K::Float, F::RGBA16F, 16, 16, 16, 16, 0, 0, 0, 0, false},
    {GL_R32F, B::Red, K::Float, F::RGBA32F, 32, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_RG32F, B::RG, K::Float, F::RGBA32F, 32, 32, 0, 0, 0, 0, 0, 0, false},
    {GL_RGB32F, B::RGB, K::Float, F::RGBA32F, 32, 32, 32, 0, 0, 0, 0, 0, false},
    {GL_RGBA32F, B::RGBA, K::Float, F::RGBA32F, 32, 32, 32, 32, 0, 0, 0, 0, false},
    {GL_R11F_G11F_B10F, B::RGB, K::Float, F::RGBA16F, 11, 11, 10, 0, 0, 0, 0, 0, false},
    {GL_RGB9_E5, B::RGB, K::Float, F::RGBA32F, 9, 9, 9, 0, 0, 0, 0, 0, false},
    // integer
    {GL_R8I, B::Red, K::Int, F::RGBA32F, 8, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_R8UI, B::Red, K::Uint, F::RGBA32F, 8, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_R16I, B::Red, K::Int, F::RGBA32F, 16, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_R16UI, B::Red, K::Uint, F::RGBA32F, 16, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_R32I, B::Red, K::Int, F::RGBA32F, 32, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_R32UI, B::Red, K::Uint, F::RGBA32F, 32, 0, 0, 0, 0, 0, 0, 0, false},
    {GL_RG8I, B::RG, K::Int, F::RGBA32F, 8, 8, 0, 0, 0, 0, 0, 0, false},
    {GL_RG8UI, B::RG, K::Uint, F::RGBA32F, 8, 8, 0, 0, 0, 0, 0, 0, false},
    {GL_RG16I, B::RG, K::Int, F::RGBA32F, 16, 16, 0, 0, 0, 0, 0, 0, false},
    {GL_RG16UI, B::RG, K::Uint, F::RGBA32F, 16, 16, 0, 0, 0, 0, 0, 0, false},
    {GL_RG32I, B::RG, K::Int, F::RGBA32F, 32, 32, 0, 0, 0, 0, 0, 0, false},
    {GL_RG32UI, B::RG, K::Uint, F::RGBA32F, 32, 32, 0, 0, 0, 0, 0, 0, false},
    {GL_RGB8I, B::RGB, K::Int, F::RGBA32F, 8, 8, 8, 0, 0, 0, 0, 0, false},
    {GL_RGB8UI, B::RGB, K::Uint, F::RGBA32F, 8, 8, 8, 0, 0, 0, 0, 0, false},
    {GL_RGB16I, B::RGB, K::Int, F::RGBA32F, 16, 16, 16, 0, 0, 0, 0, 0, false},
    {GL_RGB16UI, B::RGB, K::Uint, F::RGBA32F, 16, 16, 16, 0, 0, 0, 0, 0, false},
    {GL_RGB32I, B::RGB, K::Int, F::RGBA32F, 32, 32, 32, 0, 0, 0, 0, 0, false},
    {GL_RGB32UI, B::RGB, K::Uint, F::RGBA32F, 32, 32, 32, 0, 0, 0, 0, 0, false},
    {GL_RGBA8I, B::RGBA, K::Int, F::RGBA32F, 8, 8, 8, 8, 0, 0, 0, 0, false},
    {GL_RGBA8UI, B::RGBA, K::Uint, F::RGBA32F, 8, 8, 8, 8, 0, 0, 0, 0, false},
    {GL_RGBA16I, B::RGBA, K::Int, F::RGBA32F, 16, 16, 16, 16, 0, 0, 0, 0, false},
    {GL_RGBA16UI, B::RGBA, K::Uint, F::RGBA32F, 16, 16, 16, 16, 0, 0, 0, 0, false},
    {GL_RGBA32I, B::RGBA, K::Int, F::RGBA32F, 32, 32, 32, 32, 0, 0, 0, 0, false},
    {GL_RGBA32UI, B::RGBA, K::Uint, F::RGBA32F, 32, 32, 32, 32, 0, 0, 0, 0, false},
    {GL_RGB10_A2UI, B::RGBA, K::Uint, F::RGBA32F, 10, 10, 10, 2, 0, 0, 0, 0, false},
    // depth and depth-stencil
    {GL_DEPTH_COMPONENT, B::Depth, K::Depth, F::Depth24, 0, 0, 0, 0, 0, 0, 24, 0, false},
    {GL_DEPTH_COMPONENT16, B::Depth, K::Depth, F::Depth24, 0, 0, 0, 0, 0, 0, 16, 0, false},
    {GL_DEPTH_COMPONENT24, B::Depth, K::Depth, F::Depth24, 0, 0, 0, 0, 0, 0, 24, 0, false},
    {GL_DEPTH_COMPONENT32, B::Depth, K::Depth, F::Depth32F, 0, 0, 0, 0, 0, 0, 32, 0, false},
    {GL_DEPTH_COMPONENT32F, B::Depth, K::Depth, F::Depth32F, 0, 0, 0, 0, 0, 0, 32, 0, false},
    {GL_DEPTH_STENCIL, B::DepthStencil, K::Depth, F::Depth24Stencil8, 0, 0, 0, 0, 0, 0, 24, 8, false},
    {GL_DEPTH24_STENCIL8, B::DepthStencil, K::Depth, F::Depth24Stencil8, 0, 0, 0, 0, 0, 0, 24, 8, false},
    {GL_DEPTH32F_STENCIL8, B::DepthStencil, K::Depth, F::Depth24Stencil8, 0, 0, 0, 0, 0, 0, 32, 8, false},
};
// clang-format on

float quantize_unorm(float v, int bits) {
  v = std::clamp(v, 0.0f, 1.0f);
  if (bits >= 24 || bits <= 0) return v;
  const float m = float((1u << bits) - 1u);
  return std::nearbyint(v * m) / m;
}
float quantize_snorm(float v, int bits) {
  v = std::clamp(v, -1.0f, 1.0f);
  const float m = float((1u << (bits - 1)) - 1u);
  return std::nearbyint(v * m) / m;
}
// An integer component (its 32 bits in v: int32 for Int, uint32 for Uint) clamped to a
// format of `bits` bits, as bits again.
float quantize_int(float v, TexKind kind, int bits) {
  const uint32_t b = std::bit_cast<uint32_t>(v);
  int64_t x = kind == TexKind::Uint ? int64_t(b) : int64_t(int32_t(b));
  if (kind == TexKind::Uint)
    x = std::clamp<int64_t>(x, 0, (int64_t(1) << bits) - 1);
  else
    x = std::clamp<int64_t>(x, -(int64_t(1) << (bits - 1)), (int64_t(1) << (bits - 1)) - 1);
  return std::bit_cast<float>(uint32_t(x));
}

}  // namespace

bool TexFormat::color_renderable() const {
  if (is_depth() || shared_exponent || kind == TexKind::Snorm || rgtc()) return false;
  return base == TexBase::Red || base == TexBase::RG || base == TexBase::RGB || base == TexBase::RGBA;
}

GLenum TexFormat::component_type() const {
  switch (kind) {
    case TexKind::Unorm:
    case TexKind::Srgb:
    case TexKind::Depth: return GL_UNSIGNED_NORMALIZED;
    case TexKind::Snorm: return GL_SIGNED_NORMALIZED;
    case TexKind::Float: return GL_FLOAT;
    case TexKind::Int: return GL_INT;
    case TexKind::Uint: return GL_UNSIGNED_INT;
  }
  return GL_NONE;
}

glm::vec4 clamp_integer_texel(const gpu::IntegerRange& range, glm::vec4 texel) {
  if (!range.integer()) return texel;
  for (int k = 0; k < 4; ++k)
    texel[k] = std::bit_cast<float>(
        gpu::clamp_integer_bits(std::bit_cast<uint32_t>(texel[k]), range.bits[k], range.is_signed));
  return texel;
}

gpu::IntegerRange TexFormat::integer_range() const {
  gpu::IntegerRange out;
  if (!integer()) return out;
  const uint8_t sizes[4] = {r, g, b, a};
  for (int k = 0; k < 4; ++k) out.bits[k] = sizes[k] ? sizes[k] : 32;  // (absent: never written)
  out.is_signed = kind == TexKind::Int;
  return out;
}

uint8_t TexFormat::channel_mask() const {
  switch (base) {
    case TexBase::Red: return 0x1;
    case TexBase::RG: return 0x3;
    case TexBase::RGB: return 0x7;
    default: return 0xF;
  }
}

bool tex_format_of(GLint internal, bool core, TexFormat& out) {
  for (const Row& r : kFormats) {
    if (GLint(r.internal) != internal) continue;
    if (core && r.compat_only) return false;
    out = TexFormat{};
    out.internal = GLenum(internal);
    out.base = r.base;
    out.kind = r.kind;
    out.storage = r.storage;
    out.r = r.r, out.g = r.g, out.b = r.b, out.a = r.a, out.l = r.l, out.i = r.i;
    out.depth = r.d, out.stencil = r.s;
    out.shared_exponent = internal == GL_RGB9_E5;
    // A depth texture of DEPTH_COMPONENT32F keeps float depth; DEPTH32F_STENCIL8 keeps 24 bits.
    if (internal == GL_DEPTH32F_STENCIL8) out.kind = TexKind::Depth;
    return true;
  }
  return false;
}

float srgb_to_linear(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
float linear_to_srgb(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c < 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 0.41666f) - 0.055f;
}

glm::vec4 to_storage(const TexFormat& f, const glm::vec4& px) {
  glm::vec4 v;
  switch (f.base) {
    case TexBase::Alpha: v = {0.0f, 0.0f, 0.0f, px.a}; break;
    case TexBase::Luminance: v = {px.r, px.r, px.r, 1.0f}; break;
    case TexBase::LuminanceAlpha: v = {px.r, px.r, px.r, px.a}; break;
    case TexBase::Intensity: v = glm::vec4(px.r); break;
    case TexBase::Red: v = {px.r, 0.0f, 0.0f, 1.0f}; break;
    case TexBase::RG: v = {px.r, px.g, 0.0f, 1.0f}; break;
    case TexBase::RGB: v = {px.r, px.g, px.b, 1.0f}; break;
    case TexBase::RGBA: v = px; break;
    case TexBase::Depth: return {std::clamp(px.x, 0.0f, 1.0f), 0.0f, 0.0f, 1.0f};
    case TexBase::DepthStencil:
      return {std::clamp(px.x, 0.0f, 1.0f), std::clamp(std::nearbyint(px.y), 0.0f, 255.0f), 0.0f, 1.0f};
  }
  const uint8_t bits[4] = {uint8_t(f.r | f.l | f.i), uint8_t(f.g | f.l | f.i), uint8_t(f.b | f.l | f.i),
                           uint8_t(f.a | f.i)};
  for (int k = 0; k < 4; ++k) {
    if (bits[k] == 0) {
      // A component the format lacks keeps its fixed value: 0, or alpha 1 (for an integer
      // format, the integer's bits).
      if (f.integer()) v[k] = std::bit_cast<float>(k == 3 ? 1u : 0u);
      continue;
    }
    switch (f.kind) {
      case TexKind::Unorm: v[k] = quantize_unorm(v[k], bits[k]); break;
      case TexKind::Snorm: v[k] = quantize_snorm(v[k], bits[k]); break;
      case TexKind::Srgb:
        v[k] = k == 3 ? quantize_unorm(v[k], 8) : srgb_to_linear(quantize_unorm(v[k], 8));
        break;
      case TexKind::Float:
        if (f.internal == GL_R11F_G11F_B10F || f.internal == GL_RGB9_E5) v[k] = std::max(v[k], 0.0f);
        break;
      case TexKind::Int:
      case TexKind::Uint: v[k] = quantize_int(v[k], f.kind, bits[k]); break;
      case TexKind::Depth: break;
    }
  }
  return v;
}

glm::vec4 from_storage(const TexFormat& f, const glm::vec4& stored) {
  glm::vec4 v = stored;
  if (f.kind == TexKind::Srgb)
    for (int k = 0; k < 3; ++k) v[k] = linear_to_srgb(v[k]);
  // GL 3.3 compat §6.1.4: luminance and intensity come back in R, G and B zero.
  if (f.base == TexBase::Luminance || f.base == TexBase::LuminanceAlpha || f.base == TexBase::Intensity)
    v.g = v.b = 0.0f;
  return v;
}

}  // namespace tessel::gl
