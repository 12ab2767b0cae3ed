// Pixel transfer (GL 2.1 §3.7 unpacking, §4.3.2 packing) for the formats and types of GL 1.x.
#pragma once

#include <cstdint>
#include <vector>

#include <GL/gl.h>
#include <glm/vec4.hpp>

#include "context.hpp"

namespace tessel::gl {

// Components per pixel of a format, 0 when the format is not a valid pixel format.
int format_components(GLenum format);
// Bytes of one component of a type (BITMAP: 0), -1 when the type is invalid.
int type_bytes(GLenum type);
bool valid_pixel_format(GLenum format);
bool valid_pixel_type(GLenum type);

// Bytes between the starts of two rows of a w-pixel-wide image, and the start of the image
// data after the skips (GL 2.1 §3.7.4, eq. 3.1-3.3).
struct PixelLayout {
  size_t row_stride = 0, pixel_stride = 0, offset = 0;
};
PixelLayout pixel_layout(const PixelStore& ps, int width, GLenum format, GLenum type);

// Reads w x h pixels of `format`/`type` into RGBA floats (rows in memory order, which is
// bottom-up in GL). Depth and stencil formats give the value in .x. Luminance gives
// (L, L, L, 1), alpha (0, 0, 0, A); missing components (0, 0, 0, 1).
void unpack_pixels(const PixelStore& ps, int w, int h, GLenum format, GLenum type, const void* data,
                   std::vector<glm::vec4>& out);
// A bitmap (GL_BITMAP, GL_COLOR_INDEX in 1 bit): out[y * w + x] = bit set.
void unpack_bitmap(const PixelStore& ps, int w, int h, const void* data, std::vector<uint8_t>& out);
// Writes RGBA floats (already clamped for unsigned normalized types) as `format`/`type`.
void pack_pixels(const PixelStore& ps, int w, int h, GLenum format, GLenum type,
                 const std::vector<glm::vec4>& in, void* data);

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
