// Pixel transfer (GL 3.3 §3.7.2 unpacking, §4.3.2 packing, Tables 3.2-3.5): the formats and types
// of GL 1.x and those GL 3.3 adds (RG, the *_INTEGER formats, DEPTH_STENCIL, HALF_FLOAT and the
// packed types).
#pragma once

#include <cstdint>
#include <vector>

#include <GL/gl.h>
#include <glm/vec4.hpp>

#include "context.hpp"

namespace tessel::gl {

// Components per pixel of a format, 0 when the format is not a valid pixel format
// (DEPTH_STENCIL: 2).
int format_components(GLenum format);
// Bytes of one component of a type (BITMAP: 0), -1 when the type is invalid. A packed type is
// one element per pixel: its size (FLOAT_32_UNSIGNED_INT_24_8_REV: 8).
int type_bytes(GLenum type);
bool valid_pixel_format(GLenum format);
bool valid_pixel_type(GLenum type);
// The *_INTEGER formats (components are integers, not normalized).
bool is_integer_format(GLenum format);
// The packed types of Table 3.5 (one element holds the whole pixel).
bool is_packed_type(GLenum type);
// Whether a format and type can be used together (§3.7.2): GL_NO_ERROR; GL_INVALID_ENUM for an
// unknown format or type, BITMAP with a format other than COLOR_INDEX/STENCIL_INDEX, or
// DEPTH_STENCIL with a type that is not packed; GL_INVALID_OPERATION for a packed type whose
// components do not match the format, and for an integer format with a float type.
GLenum check_format_type(GLenum format, GLenum type);
// The same for a context of `core` profile: GL 3.3 core Table 3.3 has no GL_ALPHA,
// GL_LUMINANCE, GL_LUMINANCE_ALPHA or GL_COLOR_INDEX (Appendix E.2.2), which are
// GL_INVALID_ENUM there (Mesa 22 accepts them; the specification is followed).
GLenum check_format_type(GLenum format, GLenum type, bool core);
bool valid_format_type(GLenum format, GLenum type);

// Bytes between the starts of two rows of a w-pixel-wide image, and the start of the image
// data after the skips (GL 2.1 §3.7.4, eq. 3.1-3.3). A packed type counts as one component of
// its element size.
struct PixelLayout {
  size_t row_stride = 0, pixel_stride = 0, offset = 0;
};
PixelLayout pixel_layout(const PixelStore& ps, int width, GLenum format, GLenum type);

// Reads w x h pixels of `format`/`type` into RGBA floats (rows in memory order, which is
// bottom-up in GL). Depth and stencil formats give the value in .x; DEPTH_STENCIL gives depth
// in .x ([0, 1]) and the stencil value (an integer, not normalized) in .y; colour and stencil
// indices give the index itself in .x (integer types not normalized). Luminance gives
// (L, L, L, 1), alpha (0, 0, 0, A); missing components (0, 0, 0, 1). *_INTEGER formats give the
// integer values themselves; HALF_FLOAT and FLOAT are not normalized; the fields of packed
// types are unsigned normalized by their own width (raw with *_INTEGER formats).
void unpack_pixels(const PixelStore& ps, int w, int h, GLenum format, GLenum type, const void* data,
                   std::vector<glm::vec4>& out);
// A bitmap (GL_BITMAP, GL_COLOR_INDEX in 1 bit): out[y * w + x] = bit set.
void unpack_bitmap(const PixelStore& ps, int w, int h, const void* data, std::vector<uint8_t>& out);
// Writes RGBA floats (already clamped for unsigned normalized types) as `format`/`type`: the
// inverse of unpack_pixels. *_INTEGER formats write the values rounded and clamped to the
// type's (or the packed field's) range; DEPTH_STENCIL writes depth from .x, stencil from .y.
void pack_pixels(const PixelStore& ps, int w, int h, GLenum format, GLenum type,
                 const std::vector<glm::vec4>& in, void* data);
// Integer texels (their bits: int32 when `source_signed`, else uint32) prepared for
// pack_pixels with `type`, which reads the bits as signed for the signed types: a value the
// type's signedness cannot hold becomes the nearest one it can (negative values 0 for the
// unsigned types, values above INT32_MAX that for the signed ones), so it clamps right.
void match_integer_sign(std::vector<glm::vec4>& px, bool source_signed, GLenum type);

// The base internal format of a glTexImage internal format; false when it is not one.
bool base_format_of(GLint internal_format, BaseFormat& base);
// Converts unpacked RGBA to the stored RGBA8 of a base format (the §3.8.1 conversion:
// luminance from R, intensity from R).
void to_texture_rgba8(const std::vector<glm::vec4>& in, BaseFormat base, std::vector<uint8_t>& out);

inline uint8_t unorm8(float v) {
  v = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
  return uint8_t(v * 255.0f + 0.5f);
}

}  // namespace tessel::gl
