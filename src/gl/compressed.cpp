// RGTC blocks (ARB_texture_compression_rgtc, "RGTC Compressed Texture Image Formats"): a
// channel is 8 bytes - two 8-bit endpoints e0 and e1, then sixteen 3-bit codes, texel
// (x, y) of the block at bits 3 * (4y + x) of the little-endian 48-bit field. Code 0 is e0,
// code 1 is e1; with e0 > e1 codes 2-7 interpolate six steps between them, otherwise codes
// 2-5 interpolate four and codes 6 and 7 are the range's ends. RGTC1 has one channel (red),
// RGTC2 two (red, then green).
#include "compressed.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "tessel/gpu/texture.hpp"

namespace tessel::gl {

namespace {

// Value of `code` for endpoints e0, e1, as Mesa decodes it: integer steps, truncated.
int rgtc_value(int e0, int e1, int code, bool is_signed) {
  if (code == 0) return e0;
  if (code == 1) return e1;
  if (e0 > e1) return (e0 * (8 - code) + e1 * (code - 1)) / 7;
  if (code < 6) return (e0 * (6 - code) + e1 * (code - 1)) / 5;
  if (code == 6) return is_signed ? -128 : 0;
  return is_signed ? 127 : 255;
}

int channels_of(const TexFormat& f) { return compressed_block_bytes(f) / 8; }
bool signed_of(const TexFormat& f) { return f.kind == TexKind::Snorm; }

// The texel (as stored) of decoded channel values.
glm::vec4 texel_of(const TexFormat& f, const int v[2]) {
  glm::vec4 px(0.0f, 0.0f, 0.0f, 1.0f);
  for (int c = 0; c < channels_of(f); ++c)
    px[c] = signed_of(f) ? std::max(float(v[c]) / 127.0f, -1.0f) : float(v[c]) / 255.0f;
  return to_storage(f, px);
}

// A stored texel's channel as the integer an RGTC block encodes.
int channel_of(const TexFormat& f, const glm::vec4& stored, int c) {
  const float v = stored[c];
  if (signed_of(f)) return int(std::lrint(std::clamp(v, -1.0f, 1.0f) * 127.0f));
  return int(std::lrint(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

size_t texel_offset(const TextureImage& img, int x, int y, int z) {
  return ((size_t(z) * size_t(img.height) + size_t(y)) * size_t(img.width) + size_t(x)) *
         gpu::format_info(img.fmt.storage).bytes;
}

// The offset in img.blocks of block (bx, by) of layer z.
size_t block_offset(const TextureImage& img, int bx, int by, int z) {
  const size_t across = size_t(img.width + 3) / 4, down = size_t(img.height + 3) / 4;
  return ((size_t(z) * down + size_t(by)) * across + size_t(bx)) * size_t(compressed_block_bytes(img.fmt));
}

// Decodes block (bx, by) of layer z into the texels it covers.
void decode_block(TextureImage& img, int bx, int by, int z) {
  const uint8_t* b = img.blocks.data() + block_offset(img, bx, by, z);
  const bool s = signed_of(img.fmt);
  int values[2][16] = {};
  for (int c = 0; c < channels_of(img.fmt); ++c) rgtc_decode_channel(b + 8 * c, s, values[c]);
  for (int j = 0; j < 4 && by * 4 + j < img.height; ++j)
    for (int i = 0; i < 4 && bx * 4 + i < img.width; ++i) {
      const int v[2] = {values[0][4 * j + i], values[1][4 * j + i]};
      gpu::detail::encode_texel(img.fmt.storage,
                                img.data.data() + texel_offset(img, bx * 4 + i, by * 4 + j, z),
                                texel_of(img.fmt, v));
    }
}

// Encodes block (bx, by) of layer z from the texels it covers (a block past the image's edge
// repeats its last texels).
void encode_block(TextureImage& img, int bx, int by, int z) {
  uint8_t* b = img.blocks.data() + block_offset(img, bx, by, z);
  const bool s = signed_of(img.fmt);
  for (int c = 0; c < channels_of(img.fmt); ++c) {
    int values[16];
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        const int x = std::min(bx * 4 + i, img.width - 1), y = std::min(by * 4 + j, img.height - 1);
        const glm::vec4 t =
            gpu::detail::decode_texel(img.fmt.storage, img.data.data() + texel_offset(img, x, y, z));
        values[4 * j + i] = channel_of(img.fmt, t, c);
      }
    rgtc_encode_channel(values, s, b + 8 * c);
  }
}

void ensure_blocks(TextureImage& img) {
  const size_t n = compressed_bytes(img.fmt, img.width, img.height, img.depth);
  if (img.blocks.size() != n) img.blocks.assign(n, 0);
}

}  // namespace

int compressed_block_bytes(const TexFormat& f) {
  switch (f.internal) {
    case GL_COMPRESSED_RED_RGTC1:
    case GL_COMPRESSED_SIGNED_RED_RGTC1: return 8;
    case GL_COMPRESSED_RG_RGTC2:
    case GL_COMPRESSED_SIGNED_RG_RGTC2: return 16;
    default: return 0;
  }
}

size_t compressed_bytes(const TexFormat& f, int w, int h, int d) {
  return size_t(std::max(w, 0) + 3) / 4 * (size_t(std::max(h, 0) + 3) / 4) * size_t(std::max(d, 0)) *
         size_t(compressed_block_bytes(f));
}

void rgtc_decode_channel(const uint8_t* block, bool is_signed, int out[16]) {
  const int e0 = is_signed ? int(int8_t(block[0])) : int(block[0]);
  const int e1 = is_signed ? int(int8_t(block[1])) : int(block[1]);
  uint64_t codes = 0;
  for (int k = 0; k < 6; ++k) codes |= uint64_t(block[2 + k]) << (8 * k);
  for (int t = 0; t < 16; ++t) out[t] = rgtc_value(e0, e1, int((codes >> (3 * t)) & 7u), is_signed);
}

void rgtc_encode_channel(const int in[16], bool is_signed, uint8_t* block) {
  const int lo = *std::min_element(in, in + 16), hi = *std::max_element(in, in + 16);
  // Six interpolated steps between the block's extremes (e0 > e1); a flat block is e0 alone.
  const int e0 = hi, e1 = lo;
  int palette[8];
  for (int code = 0; code < 8; ++code) palette[code] = rgtc_value(e0, e1, code, is_signed);
  uint64_t codes = 0;
  for (int t = 0; t < 16; ++t) {
    int best = 0;
    for (int code = 1; code < 8 && e0 > e1; ++code)
      if (std::abs(palette[code] - in[t]) < std::abs(palette[best] - in[t])) best = code;
    codes |= uint64_t(best) << (3 * t);
  }
  block[0] = uint8_t(e0);
  block[1] = uint8_t(e1);
  for (int k = 0; k < 6; ++k) block[2 + k] = uint8_t(codes >> (8 * k));
}

void compress_region(TextureImage& img, int x, int y, int z, int w, int h, int d) {
  if (!compressed_block_bytes(img.fmt) || w <= 0 || h <= 0 || d <= 0) return;
  ensure_blocks(img);
  for (int k = z; k < z + d; ++k)
    for (int by = y / 4; by <= (y + h - 1) / 4; ++by)
      for (int bx = x / 4; bx <= (x + w - 1) / 4; ++bx) {
        encode_block(img, bx, by, k);
        decode_block(img, bx, by, k);
      }
}

void store_compressed(TextureImage& img, int x, int y, int z, int w, int h, int d, const uint8_t* src) {
  if (!compressed_block_bytes(img.fmt) || w <= 0 || h <= 0 || d <= 0) return;
  ensure_blocks(img);
  const size_t bytes = size_t(compressed_block_bytes(img.fmt));
  const int bw = (w + 3) / 4, bh = (h + 3) / 4;
  for (int k = 0; k < d; ++k)
    for (int j = 0; j < bh; ++j)
      for (int i = 0; i < bw; ++i) {
        std::memcpy(img.blocks.data() + block_offset(img, x / 4 + i, y / 4 + j, z + k),
                    src + ((size_t(k) * size_t(bh) + size_t(j)) * size_t(bw) + size_t(i)) * bytes, bytes);
        decode_block(img, x / 4 + i, y / 4 + j, z + k);
      }
}

}  // namespace tessel::gl
