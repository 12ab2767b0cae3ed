// Compressed texture images: the RGTC formats GL 3.3 requires (§3.8.3, Table 3.14;
// ARB_texture_compression_rgtc, whose Appendix gives the block encoding). An RGTC image keeps
// two forms: its 4x4 blocks as the application gave them or as Tessel compressed them
// (TextureImage::blocks, what glGetCompressedTexImage returns), and the decoded texels in the
// image's storage format, which sampling reads. Every change keeps the two in step: blocks
// given are decoded, texels given (glTexImage, glTexSubImage, glCopyTex*, mipmap generation)
// are compressed block by block and decoded again, so a texture samples as its blocks say.
#pragma once

#include <cstddef>
#include <cstdint>

#include "texture_object.hpp"

namespace tessel::gl {

// Bytes of one 4x4 block (8 for RGTC1, 16 for RGTC2), 0 for an uncompressed format.
int compressed_block_bytes(const TexFormat& f);
// Bytes of a w x h x d image or region (d layers of blocks).
size_t compressed_bytes(const TexFormat& f, int w, int h, int d);

// Compresses the blocks covering the texel region of `img` (its texels already written) into
// img.blocks, then writes the blocks' decoded texels back.
void compress_region(TextureImage& img, int x, int y, int z, int w, int h, int d);
// Stores compressed data for a block-aligned region (blocks row by row, layer by layer, as
// glCompressedTexSubImage reads them) and decodes it into the texels.
void store_compressed(TextureImage& img, int x, int y, int z, int w, int h, int d, const uint8_t* src);

// One RGTC channel block (8 bytes) decoded to 16 values (row by row), in 8-bit steps as Mesa
// decodes them: unsigned 0..255, signed -127..127 (-128 reads as -127).
void rgtc_decode_channel(const uint8_t* block, bool is_signed, int out[16]);
// 16 values (0..255 or -127..127) encoded into one channel block.
void rgtc_encode_channel(const int in[16], bool is_signed, uint8_t* block);

}  // namespace tessel::gl
