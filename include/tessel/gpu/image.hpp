// Images in and out: PNG/JPEG/HDR files to textures, attachments to PNG files.
//
// Files have their first row at the top; GL (and Tessel) keep the bottom row first. Every
// function here flips between the two, so callers always work bottom-up.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tessel/gpu/texture.hpp"

namespace tessel::gpu {

// Pixels in memory, rows bottom-up, tightly packed; 8-bit (channels 1-4) or float.
struct Image {
  int width = 0, height = 0, channels = 4;
  std::vector<uint8_t> pixels;  // 8-bit images
  std::vector<float> hdr;       // float images (HDR files); pixels is then empty
  bool is_hdr() const { return !hdr.empty(); }
};

// Reads PNG, JPEG, BMP, TGA or HDR. Throws Error naming the file and the reason (missing,
// not an image, truncated, too large). 8-bit files are expanded to RGBA; HDR stays float RGBA.
Image load_image(const std::string& path);
// The same from bytes in memory; `name` is used in error messages.
Image load_image_from_memory(const void* data, size_t bytes, const std::string& name);

// Writes an 8-bit image (rows bottom-up) to PNG atomically: a temporary file in the same
// folder, then rename, so a reader never sees half a file and a failure leaves nothing.
// Throws Error on failure.
void write_png(const std::string& path, int width, int height, int channels, const uint8_t* rows_bottom_up);
// Writes a colour attachment level as 8-bit RGBA PNG (float formats are clamped to [0,1];
// depth formats are written as grey levels).
void write_png(const std::string& path, const Texture2D& texture, int level = 0);

// Reads a whole level back as RGBA8, rows bottom-up (as glReadPixels with GL_RGBA,
// GL_UNSIGNED_BYTE would).
std::vector<uint8_t> read_rgba8(const Texture2D& texture, int level = 0);

// Makes an RGBA8 texture from an image (float images become RGBA32F), optionally with a full
// mipmap chain.
Texture2D make_texture(const Image& image, bool mipmaps);

}  // namespace tessel::gpu
