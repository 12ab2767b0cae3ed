// The internal formats of textures and renderbuffers (GL 3.3 compatibility §3.8.3, Tables
// 3.12-3.17): what each holds, how it is stored in the gpu layer, what glGetTexLevelParameter
// reports, and whether a framebuffer can render to it (§4.4.4).
//
// Storage: the gpu layer has a few formats, and every GL internal format is kept in one of
// them without losing what the format holds, except as noted:
// - 8-bit unsigned normalized formats: RGBA8 (R8 and RG8 for the red and red-green ones);
//   luminance, intensity and alpha formats are expanded at upload (GL 3.3 compat Table 3.15),
//   and RGB formats store alpha 1.
// - float, snorm, 16-bit unorm, sRGB and integer formats: RGBA16F (half formats and
//   R11F_G11F_B10F) or RGBA32F (the rest). Values are rounded to the format's own precision
//   at upload. Integer texels are kept exactly: each component's 32 bits (int32 or uint32) in
//   the float slot, from pixel transfer (pixels.hpp) to GLSL's integer samplers, which read the
//   bits (glsl/interp.cpp); nothing does float arithmetic on them. sRGB texels are stored as
//   linear values (§3.8.15's decoding at upload instead of at sampling).
// - depth formats: DEPTH_COMPONENT16 and 24 as Depth24 (16-bit depth keeps 24 bits),
//   DEPTH_COMPONENT32 and 32F as Depth32F; depth-stencil as Depth24Stencil8.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include <glm/vec4.hpp>

#include "tessel/gpu/format.hpp"

namespace tessel::gl {

enum class TexBase : uint8_t {
  Alpha,
  Luminance,
  LuminanceAlpha,
  Intensity,
  Red,
  RG,
  RGB,
  RGBA,
  Depth,
  DepthStencil,
};
enum class TexKind : uint8_t { Unorm, Snorm, Float, Int, Uint, Srgb, Depth };

struct TexFormat {
  GLenum internal = GL_RGBA;  // as the program gave it (GL_TEXTURE_INTERNAL_FORMAT)
  TexBase base = TexBase::RGBA;
  TexKind kind = TexKind::Unorm;
  gpu::Format storage = gpu::Format::RGBA8;
  // GL_TEXTURE_{RED,GREEN,BLUE,ALPHA,LUMINANCE,INTENSITY,DEPTH}_SIZE, GL_TEXTURE_STENCIL_SIZE
  uint8_t r = 0, g = 0, b = 0, a = 0, l = 0, i = 0, depth = 0, stencil = 0;
  bool shared_exponent = false;  // RGB9_E5

  bool integer() const { return kind == TexKind::Int || kind == TexKind::Uint; }
  // One of the four RGTC formats: stored compressed as well (compressed.hpp).
  bool rgtc() const {
    return internal >= GL_COMPRESSED_RED_RGTC1 && internal <= GL_COMPRESSED_SIGNED_RG_RGTC2;
  }
  bool is_depth() const { return base == TexBase::Depth || base == TexBase::DepthStencil; }
  bool has_stencil() const { return base == TexBase::DepthStencil; }
  bool color() const { return !is_depth(); }
  // §4.4.4: color-renderable (RED, RG, RGB, RGBA bases, not snorm or shared exponent),
  // depth-renderable, stencil-renderable.
  bool color_renderable() const;
  // GL_TEXTURE_RED_TYPE and the others: GL_UNSIGNED_NORMALIZED, GL_SIGNED_NORMALIZED,
  // GL_FLOAT, GL_INT, GL_UNSIGNED_INT, or GL_NONE for a component the format lacks.
  GLenum component_type() const;
  // The colour-channel write mask (bit 0 red .. bit 3 alpha) of the channels the format
  // stores: rendering must not change the others (alpha of RGB formats reads 1).
  uint8_t channel_mask() const;
  // The bits of each component of an integer format (not integer for the others).
  gpu::IntegerRange integer_range() const;
};

// The format of a glTexImage / glRenderbufferStorage internal format; false when GL does not
// know it (GL_INVALID_VALUE for textures, GL_INVALID_ENUM for renderbuffers). `core`: the
// compatibility-only formats (luminance, intensity, alpha, 1-4) are unknown.
bool tex_format_of(GLint internal, bool core, TexFormat& out);

// An integer texel (each component's 32 bits in its float slot) clamped to the component sizes
// of `range`, as integer colour buffers store values (unchanged when range is not integer).
glm::vec4 clamp_integer_texel(const gpu::IntegerRange& range, glm::vec4 texel);

// A texel as unpacked (glTexImage's RGBA floats; depth in .x, stencil in .y) turned into the
// value the storage holds: the base format's components selected (Table 3.15), values clamped
// and rounded to the format's precision, sRGB decoded.
glm::vec4 to_storage(const TexFormat& f, const glm::vec4& px);
// A stored texel as glGetTexImage sees it (§6.1.4): luminance in R, sRGB encoded again.
glm::vec4 from_storage(const TexFormat& f, const glm::vec4& stored);

// sRGB <-> linear (GL 3.3 §3.8.15 equation 3.27 and §4.1.8 equation 4.3).
float srgb_to_linear(float c);
float linear_to_srgb(float c);

}  // namespace tessel::gl
