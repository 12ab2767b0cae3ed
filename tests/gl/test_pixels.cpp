// Pixel transfer (src/gl/pixels.cpp): the GL 3.3 formats and types of §3.7.2 / §4.3.2 — packed
// types, half floats, RG, integer formats, depth-stencil — their layout and the format/type
// checks, next to a few of the GL 1.x combinations that must not change.
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <bit>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "../../src/gl/pixels.hpp"

using namespace tessel::gl;

namespace {

PixelStore store(int alignment = 1) {
  PixelStore ps;
  ps.alignment = alignment;
  return ps;
}

template <typename T>
glm::vec4 unpack1(GLenum format, GLenum type, T element) {
  std::vector<glm::vec4> out;
  unpack_pixels(store(), 1, 1, format, type, &element, out);
  return out.at(0);
}

template <typename T>
T pack1(GLenum format, GLenum type, glm::vec4 v) {
  T element{};
  pack_pixels(store(), 1, 1, format, type, {v}, &element);
  return element;
}

void expect_vec(glm::vec4 got, glm::vec4 want, float eps = 1e-6f) {
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(got[i], want[i], eps) << "component " << i;
}

struct PackedCase {
  GLenum type;
  int bytes;
  // The element holding each component alone at its maximum, in component order.
  uint32_t field[4];
  int n;
};

// Table 3.5/3.6: non-REV types hold the first component in the most significant bits.
const PackedCase kPacked[] = {
    {GL_UNSIGNED_BYTE_3_3_2, 1, {0xE0, 0x1C, 0x03}, 3},
    {GL_UNSIGNED_BYTE_2_3_3_REV, 1, {0x07, 0x38, 0xC0}, 3},
    {GL_UNSIGNED_SHORT_5_6_5, 2, {0xF800, 0x07E0, 0x001F}, 3},
    {GL_UNSIGNED_SHORT_5_6_5_REV, 2, {0x001F, 0x07E0, 0xF800}, 3},
    {GL_UNSIGNED_SHORT_4_4_4_4, 2, {0xF000, 0x0F00, 0x00F0, 0x000F}, 4},
    {GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, {0x000F, 0x00F0, 0x0F00, 0xF000}, 4},
    {GL_UNSIGNED_SHORT_5_5_5_1, 2, {0xF800, 0x07C0, 0x003E, 0x0001}, 4},
    {GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, {0x001F, 0x03E0, 0x7C00, 0x8000}, 4},
    {GL_UNSIGNED_INT_8_8_8_8, 4, {0xFF000000u, 0x00FF0000u, 0x0000FF00u, 0x000000FFu}, 4},
    {GL_UNSIGNED_INT_8_8_8_8_REV, 4, {0x000000FFu, 0x0000FF00u, 0x00FF0000u, 0xFF000000u}, 4},
    {GL_UNSIGNED_INT_10_10_10_2, 4, {0xFFC00000u, 0x003FF000u, 0x00000FFCu, 0x00000003u}, 4},
    {GL_UNSIGNED_INT_2_10_10_10_REV, 4, {0x000003FFu, 0x000FFC00u, 0x3FF00000u, 0xC0000000u}, 4},
};

uint32_t read_bytes(const uint8_t* p, int bytes) {
  uint32_t v = 0;
  std::memcpy(&v, p, size_t(bytes));  // little endian host
  return v;
}

}  // namespace

// Each field alone at its maximum is exactly one full component (RGB(A) order), and packing
// that colour gives back the element.
TEST(PixelsPacked, EachFieldIsItsComponent) {
  for (const PackedCase& pc : kPacked) {
    const GLenum format = pc.n == 3 ? GL_RGB : GL_RGBA;
    EXPECT_TRUE(is_packed_type(pc.type));
    EXPECT_EQ(type_bytes(pc.type), pc.bytes);
    for (int k = 0; k < pc.n; ++k) {
      SCOPED_TRACE(testing::Message() << "type 0x" << std::hex << pc.type << " field " << k);
      uint8_t mem[4] = {};
      std::memcpy(mem, &pc.field[k], size_t(pc.bytes));
      std::vector<glm::vec4> out;
      unpack_pixels(store(), 1, 1, format, pc.type, mem, out);
      glm::vec4 want(0.0f, 0.0f, 0.0f, pc.n == 3 ? 1.0f : 0.0f);
      want[k] = 1.0f;
      expect_vec(out[0], want);
      uint8_t back[4] = {};
      pack_pixels(store(), 1, 1, format, pc.type, out, back);
      EXPECT_EQ(read_bytes(back, pc.bytes), pc.field[k]);
    }
  }
}

// With BGRA the fields are B, G, R, A.
TEST(PixelsPacked, BgraSwapsRedAndBlue) {
  for (const PackedCase& pc : kPacked) {
    if (pc.n != 4) continue;
    SCOPED_TRACE(testing::Message() << "type 0x" << std::hex << pc.type);
    uint8_t mem[4] = {};
    std::memcpy(mem, &pc.field[0], size_t(pc.bytes));
    std::vector<glm::vec4> out;
    unpack_pixels(store(), 1, 1, GL_BGRA, pc.type, mem, out);
    expect_vec(out[0], {0, 0, 1, 0});
    uint8_t back[4] = {};
    pack_pixels(store(), 1, 1, GL_BGRA, pc.type, {glm::vec4(1, 0, 0, 0)}, back);
    EXPECT_EQ(read_bytes(back, pc.bytes), pc.field[2]);
  }
}

// Every element value of the 8- and 16-bit types (and many 32-bit ones) survives
// unpack -> pack, normalized and as integers.
TEST(PixelsPacked, RoundTripEveryBitPattern) {
  std::mt19937 rng(1234);
  for (const PackedCase& pc : kPacked) {
    const uint32_t count = pc.bytes == 4 ? 20000u : (1u << (8 * pc.bytes));
    std::vector<uint8_t> mem(size_t(count) * size_t(pc.bytes));
    for (uint32_t i = 0; i < count; ++i) {
      const uint32_t v = pc.bytes == 4 ? uint32_t(rng()) : i;
      std::memcpy(&mem[size_t(i) * size_t(pc.bytes)], &v, size_t(pc.bytes));
    }
    const GLenum formats3[] = {GL_RGB, GL_RGB_INTEGER};
    const GLenum formats4[] = {GL_RGBA, GL_BGRA, GL_RGBA_INTEGER, GL_BGRA_INTEGER};
    const GLenum* formats = pc.n == 3 ? formats3 : formats4;
    const int nformats = pc.n == 3 ? 2 : 4;
    for (int f = 0; f < nformats; ++f) {
      SCOPED_TRACE(testing::Message() << "type 0x" << std::hex << pc.type << " format 0x" << formats[f]);
      ASSERT_EQ(check_format_type(formats[f], pc.type), GLenum(GL_NO_ERROR));
      std::vector<glm::vec4> px;
      unpack_pixels(store(), int(count), 1, formats[f], pc.type, mem.data(), px);
      std::vector<uint8_t> back(mem.size(), 0xCD);
      pack_pixels(store(), int(count), 1, formats[f], pc.type, px, back.data());
      EXPECT_EQ(back, mem);
    }
  }
}

TEST(PixelsPacked, KnownPatterns) {
  // 0xF800 in 5_6_5 is pure red.
  expect_vec(unpack1(GL_RGB, GL_UNSIGNED_SHORT_5_6_5, uint16_t(0xF800)), {1, 0, 0, 1});
  EXPECT_EQ(pack1<uint16_t>(GL_RGB, GL_UNSIGNED_SHORT_5_6_5, {1, 0, 0, 1}), 0xF800);
  EXPECT_EQ(pack1<uint16_t>(GL_RGB, GL_UNSIGNED_SHORT_5_6_5, {1, 1, 1, 1}), 0xFFFF);
  // Fields normalize by their own width: 6-bit green 32/63.
  expect_vec(unpack1(GL_RGB, GL_UNSIGNED_SHORT_5_6_5, uint16_t(32 << 5)), {0, 32.0f / 63.0f, 0, 1});
  // 8_8_8_8_REV with BGRA is the bytes B, G, R, A in memory (little endian).
  const uint8_t bgra[4] = {0x10, 0x20, 0x30, 0x40};
  std::vector<glm::vec4> out;
  unpack_pixels(store(), 1, 1, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, bgra, out);
  std::vector<glm::vec4> same;
  unpack_pixels(store(), 1, 1, GL_BGRA, GL_UNSIGNED_BYTE, bgra, same);
  expect_vec(out[0], same[0]);
  expect_vec(out[0], {0x30 / 255.0f, 0x20 / 255.0f, 0x10 / 255.0f, 0x40 / 255.0f});
  uint8_t back[4] = {};
  pack_pixels(store(), 1, 1, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, out, back);
  EXPECT_EQ(std::vector<uint8_t>(back, back + 4), std::vector<uint8_t>(bgra, bgra + 4));
  // 8_8_8_8 with RGBA: red in the most significant byte.
  expect_vec(unpack1(GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, uint32_t(0xFF000080u)), {1, 0, 0, 128.0f / 255.0f});
  // Values outside [0, 1] are clamped when packed normalized.
  EXPECT_EQ(pack1<uint16_t>(GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, {2, -1, 0.5f, 1}), 0xF08F);
}

TEST(PixelsPacked, SwapBytesSwapsTheElement) {
  PixelStore ps = store();
  ps.swap_bytes = true;
  const uint8_t mem[2] = {0xF8, 0x00};  // 0x00F8 little endian, 0xF800 swapped
  std::vector<glm::vec4> out;
  unpack_pixels(ps, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, mem, out);
  expect_vec(out[0], {1, 0, 0, 1});
  uint8_t back[2] = {};
  pack_pixels(ps, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, out, back);
  EXPECT_EQ(back[0], 0xF8);
  EXPECT_EQ(back[1], 0x00);
}

TEST(PixelsPacked, R11G11B10Float) {
  // 1.0: exponent 15, mantissa 0, in each field (R bits 0-10, G 11-21, B 22-31).
  const uint32_t ones = 0x3C0u | (0x3C0u << 11) | (0x1E0u << 22);
  expect_vec(unpack1(GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV, ones), {1, 1, 1, 1});
  EXPECT_EQ(pack1<uint32_t>(GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV, {1, 1, 1, 1}), ones);
  // Exact values survive; negatives become 0; too large clamps to the largest finite value
  // (65024 with 11 bits, 64512 with 10).
  const glm::vec4 v(0.5f, 2.75f, 64512.0f, 1.0f);  // 64512: the largest 10-bit float
  expect_vec(unpack1(GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV,
                     pack1<uint32_t>(GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV, v)),
             v);
  const glm::vec4 got =
      unpack1(GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV,
              pack1<uint32_t>(GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV, {-3, 1e9f, 64512, 1}));
  expect_vec(got, {0, 65024, 64512, 1});
  // A denormal: the smallest 11-bit one is 2^-14 / 64.
  expect_vec(unpack1(GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV, uint32_t(1)), {std::ldexp(1.0f, -20), 0, 0, 1});
  // Rounding to the 6-bit mantissa: 1 + 1/64 is exact, 1 + 1/256 rounds to 1.
  expect_vec(unpack1(GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV,
                     pack1<uint32_t>(GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV,
                                     {1 + 1 / 64.0f, 1 + 1 / 256.0f, 0, 1})),
             {1 + 1 / 64.0f, 1, 0, 1});
}

TEST(PixelsPacked, Rgb9e5) {
  // 1.0 as the largest component: shared exponent 16, mantissa 256 (2^(16-15-9) = 1/256).
  const uint32_t e = 256u | (128u << 9) | (64u << 18) | (16u << 27);
  expect_vec(unpack1(GL_RGB, GL_UNSIGNED_INT_5_9_9_9_REV, e), {1, 0.5f, 0.25f, 1});
  EXPECT_EQ(pack1<uint32_t>(GL_RGB, GL_UNSIGNED_INT_5_9_9_9_REV, {1, 0.5f, 0.25f, 1}), e);
  EXPECT_EQ(pack1<uint32_t>(GL_RGB, GL_UNSIGNED_INT_5_9_9_9_REV, {0, 0, 0, 1}), 0u);
  // Large and small components share the exponent; negatives are 0.
  expect_vec(unpack1(GL_RGB, GL_UNSIGNED_INT_5_9_9_9_REV,
                     pack1<uint32_t>(GL_RGB, GL_UNSIGNED_INT_5_9_9_9_REV, {100, 3, -1, 1})),
             {100, 3, 0, 1}, 0.25f);
  // The largest value: 511/512 * 2^16.
  expect_vec(unpack1(GL_RGB, GL_UNSIGNED_INT_5_9_9_9_REV,
                     pack1<uint32_t>(GL_RGB, GL_UNSIGNED_INT_5_9_9_9_REV, {1e10f, 0, 0, 1})),
             {65408, 0, 0, 1});
}

TEST(PixelsHalf, UnpackPackNotNormalized) {
  const uint16_t h[4] = {0x3C00, 0xC000, 0x3800, 0x4200};  // 1, -2, 0.5, 3
  std::vector<glm::vec4> out;
  unpack_pixels(store(), 1, 1, GL_RGBA, GL_HALF_FLOAT, h, out);
  expect_vec(out[0], {1, -2, 0.5f, 3});
  uint16_t back[4] = {};
  pack_pixels(store(), 1, 1, GL_RGBA, GL_HALF_FLOAT, out, back);
  EXPECT_EQ(std::vector<uint16_t>(back, back + 4), std::vector<uint16_t>(h, h + 4));
  EXPECT_EQ(type_bytes(GL_HALF_FLOAT), 2);
  EXPECT_FALSE(is_packed_type(GL_HALF_FLOAT));
  // Two bytes per component: a 3-wide RG row is 12 bytes, padded to 12 at alignment 4.
  EXPECT_EQ(pixel_layout(store(4), 3, GL_RG, GL_HALF_FLOAT).row_stride, 12u);
  EXPECT_EQ(pixel_layout(store(8), 3, GL_RGB, GL_HALF_FLOAT).row_stride, 24u);
}

TEST(PixelsRG, UnpackPack) {
  EXPECT_EQ(format_components(GL_RG), 2);
  const uint8_t rg[2] = {255, 128};
  std::vector<glm::vec4> out;
  unpack_pixels(store(), 1, 1, GL_RG, GL_UNSIGNED_BYTE, rg, out);
  expect_vec(out[0], {1, 128.0f / 255.0f, 0, 1});
  uint8_t back[2] = {};
  pack_pixels(store(), 1, 1, GL_RG, GL_UNSIGNED_BYTE, out, back);
  EXPECT_EQ(back[0], 255);
  EXPECT_EQ(back[1], 128);
  const float f[2] = {-3.5f, 7.0f};
  unpack_pixels(store(), 1, 1, GL_RG, GL_FLOAT, f, out);
  expect_vec(out[0], {-3.5f, 7, 0, 1});
}

// Integer components travel as their 32 bits in the float (texture_format.hpp): I(v) is how
// the integer v looks there.
float I(int64_t v) { return std::bit_cast<float>(uint32_t(v)); }
glm::vec4 I4(int64_t r, int64_t g, int64_t b, int64_t a) { return {I(r), I(g), I(b), I(a)}; }
void expect_bits(const glm::vec4& got, const glm::vec4& want) {
  for (int k = 0; k < 4; ++k)
    EXPECT_EQ(std::bit_cast<uint32_t>(got[k]), std::bit_cast<uint32_t>(want[k])) << "component " << k;
}

TEST(PixelsInteger, ValuesAreNotNormalizedAndKeepTheirBits) {
  EXPECT_TRUE(is_integer_format(GL_RED_INTEGER));
  EXPECT_TRUE(is_integer_format(GL_BGRA_INTEGER));
  EXPECT_FALSE(is_integer_format(GL_RGBA));
  expect_bits(unpack1(GL_RED_INTEGER, GL_INT, int32_t(1000000)), I4(1000000, 0, 0, 1));
  expect_bits(unpack1(GL_RED_INTEGER, GL_INT, int32_t(-7)), I4(-7, 0, 0, 1));
  expect_bits(unpack1(GL_GREEN_INTEGER, GL_UNSIGNED_INT, uint32_t(4000000001u)), I4(0, 4000000001u, 0, 1));
  expect_bits(unpack1(GL_RED_INTEGER, GL_UNSIGNED_INT, uint32_t(0x7F800001u)), I4(0x7F800001u, 0, 0, 1));
  expect_bits(unpack1(GL_BLUE_INTEGER, GL_BYTE, int8_t(-5)), I4(0, 0, -5, 1));
  expect_bits(unpack1(GL_RED_INTEGER, GL_UNSIGNED_SHORT, uint16_t(65535)), I4(65535, 0, 0, 1));
  expect_bits(unpack1(GL_RED_INTEGER, GL_SHORT, int16_t(-32768)), I4(-32768, 0, 0, 1));
  expect_bits(unpack1(GL_RED_INTEGER, GL_UNSIGNED_BYTE, uint8_t(200)), I4(200, 0, 0, 1));
  const uint8_t bgra[4] = {1, 2, 3, 4};
  std::vector<glm::vec4> out;
  unpack_pixels(store(), 1, 1, GL_BGRA_INTEGER, GL_UNSIGNED_BYTE, bgra, out);
  expect_bits(out[0], I4(3, 2, 1, 4));
  const int32_t rgb[3] = {100000, -200000, 16777217};
  unpack_pixels(store(), 1, 1, GL_RGB_INTEGER, GL_INT, rgb, out);
  expect_bits(out[0], I4(100000, -200000, 16777217, 1));
  unpack_pixels(store(), 1, 1, GL_BGR_INTEGER, GL_INT, rgb, out);
  expect_bits(out[0], I4(16777217, -200000, 100000, 1));
  const uint16_t rg[2] = {1234, 4321};
  unpack_pixels(store(), 1, 1, GL_RG_INTEGER, GL_UNSIGNED_SHORT, rg, out);
  expect_bits(out[0], I4(1234, 4321, 0, 1));
  // Packed types with integer formats give the raw fields.
  expect_bits(unpack1(GL_RGBA_INTEGER, GL_UNSIGNED_INT_10_10_10_2, uint32_t(0xFFC00000u | 2u)),
              I4(1023, 0, 0, 2));
  expect_bits(unpack1(GL_RGB_INTEGER, GL_UNSIGNED_SHORT_5_6_5, uint16_t(0xF800 | (40 << 5))),
              I4(31, 40, 0, 1));
}

TEST(PixelsInteger, PackClampsToTheType) {
  EXPECT_EQ(pack1<int32_t>(GL_RED_INTEGER, GL_INT, I4(1000000, 0, 0, 1)), 1000000);
  EXPECT_EQ(pack1<int32_t>(GL_RED_INTEGER, GL_INT, I4(INT32_MIN, 0, 0, 1)), INT32_MIN);
  EXPECT_EQ(pack1<uint32_t>(GL_RED_INTEGER, GL_UNSIGNED_INT, I4(4000000001u, 0, 0, 1)), 4000000001u);
  EXPECT_EQ(pack1<uint32_t>(GL_RED_INTEGER, GL_UNSIGNED_INT, I4(0x7F800001u, 0, 0, 1)), 0x7F800001u);
  EXPECT_EQ(pack1<uint8_t>(GL_RED_INTEGER, GL_UNSIGNED_BYTE, I4(300, 0, 0, 1)), 255);
  EXPECT_EQ(pack1<uint8_t>(GL_RED_INTEGER, GL_UNSIGNED_BYTE, I4(3, 0, 0, 1)), 3);
  EXPECT_EQ(pack1<int8_t>(GL_RED_INTEGER, GL_BYTE, I4(-200, 0, 0, 1)), -128);
  EXPECT_EQ(pack1<int8_t>(GL_RED_INTEGER, GL_BYTE, I4(-5, 0, 0, 1)), -5);
  EXPECT_EQ(pack1<int16_t>(GL_GREEN_INTEGER, GL_SHORT, I4(0, 40000, 0, 1)), 32767);
  EXPECT_EQ(pack1<uint16_t>(GL_BLUE_INTEGER, GL_UNSIGNED_SHORT, I4(0, 0, 1234, 1)), 1234);
  uint8_t bgra[4] = {};
  pack_pixels(store(), 1, 1, GL_BGRA_INTEGER, GL_UNSIGNED_BYTE, {I4(3, 2, 1, 4)}, bgra);
  EXPECT_EQ(std::vector<uint8_t>(bgra, bgra + 4), (std::vector<uint8_t>{1, 2, 3, 4}));
  // Packed fields clamp to their width.
  EXPECT_EQ(pack1<uint32_t>(GL_RGBA_INTEGER, GL_UNSIGNED_INT_2_10_10_10_REV, I4(2000, 5, 3, 9)),
            1023u | (5u << 10) | (3u << 20) | (3u << 30));
}

TEST(PixelsDepthStencil, Uint24_8) {
  EXPECT_EQ(format_components(GL_DEPTH_STENCIL), 2);
  const glm::vec4 v = unpack1(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, uint32_t(0x8000005Au));
  EXPECT_NEAR(v.x, 0.5f, 1e-6f);
  EXPECT_EQ(v.y, float(0x5A));
  EXPECT_EQ(pack1<uint32_t>(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, {0.5f, 0x5A, 0, 1}), 0x8000005Au);
  EXPECT_EQ(pack1<uint32_t>(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, {1, 255, 0, 1}), 0xFFFFFFFFu);
  EXPECT_EQ(pack1<uint32_t>(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, {-1, 300, 0, 1}), 0x000000FFu);
  EXPECT_EQ(unpack1(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, uint32_t(0xFFFFFF00u)).x, 1.0f);
}

TEST(PixelsDepthStencil, Float32Uint24_8Rev) {
  EXPECT_EQ(type_bytes(GL_FLOAT_32_UNSIGNED_INT_24_8_REV), 8);
  struct {
    float depth;
    uint32_t stencil;
  } px[2] = {{0.25f, 0xFFFFFF5Au}, {0.75f, 0x00000003u}};
  std::vector<glm::vec4> out;
  unpack_pixels(store(), 2, 1, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, px, out);
  expect_vec(out[0], {0.25f, 0x5A, 0, 1});
  expect_vec(out[1], {0.75f, 3, 0, 1});
  uint32_t back[4];
  std::memset(back, 0xAB, sizeof back);
  pack_pixels(store(), 2, 1, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, out, back);
  float d0, d1;
  std::memcpy(&d0, &back[0], 4);
  std::memcpy(&d1, &back[2], 4);
  EXPECT_EQ(d0, 0.25f);
  EXPECT_EQ(back[1], 0x5Au);
  EXPECT_EQ(d1, 0.75f);
  EXPECT_EQ(back[3], 3u);
}

// A packed type is one element per pixel (§3.7.4 with one component of the element's size).
TEST(PixelsLayout, PackedTypesUseTheElementSize) {
  EXPECT_EQ(pixel_layout(store(4), 3, GL_RGB, GL_UNSIGNED_SHORT_5_6_5).row_stride, 8u);  // 6 -> 8
  EXPECT_EQ(pixel_layout(store(4), 3, GL_RGB, GL_UNSIGNED_SHORT_5_6_5).pixel_stride, 2u);
  EXPECT_EQ(pixel_layout(store(2), 3, GL_RGB, GL_UNSIGNED_SHORT_5_6_5).row_stride, 6u);
  EXPECT_EQ(pixel_layout(store(8), 3, GL_RGB, GL_UNSIGNED_SHORT_5_6_5).row_stride, 8u);
  EXPECT_EQ(pixel_layout(store(4), 3, GL_RGB, GL_UNSIGNED_BYTE_3_3_2).row_stride, 4u);
  EXPECT_EQ(pixel_layout(store(8), 3, GL_RGB, GL_UNSIGNED_BYTE_3_3_2).row_stride, 8u);
  EXPECT_EQ(pixel_layout(store(4), 3, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV).row_stride, 12u);
  EXPECT_EQ(pixel_layout(store(8), 3, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV).row_stride, 16u);
  EXPECT_EQ(pixel_layout(store(4), 3, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV).pixel_stride, 4u);
  EXPECT_EQ(pixel_layout(store(8), 3, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV).row_stride, 24u);
  EXPECT_EQ(pixel_layout(store(8), 3, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV).pixel_stride, 8u);
  EXPECT_EQ(pixel_layout(store(4), 3, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8).row_stride, 12u);
  // Skips count elements.
  PixelStore ps = store(4);
  ps.skip_pixels = 2;
  ps.skip_rows = 1;
  ps.row_length = 5;
  const PixelLayout L = pixel_layout(ps, 3, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4);
  EXPECT_EQ(L.row_stride, 12u);  // 5 * 2 = 10 -> 12
  EXPECT_EQ(L.offset, 2u * 2u + 12u);
}

// A 3 x 2 image of 5_6_5 at alignment 4: rows of 6 bytes padded to 8, read and written in place.
TEST(PixelsLayout, PackedRowsWithPadding) {
  const uint16_t mem[8] = {0xF800, 0x07E0, 0x001F, 0xDEAD, 0xFFFF, 0x0000, 0xF800, 0xBEEF};
  std::vector<glm::vec4> out;
  unpack_pixels(store(4), 3, 2, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, mem, out);
  ASSERT_EQ(out.size(), 6u);
  expect_vec(out[0], {1, 0, 0, 1});
  expect_vec(out[1], {0, 1, 0, 1});
  expect_vec(out[2], {0, 0, 1, 1});
  expect_vec(out[3], {1, 1, 1, 1});
  expect_vec(out[4], {0, 0, 0, 1});
  expect_vec(out[5], {1, 0, 0, 1});
  uint16_t back[8] = {0, 0, 0, 0x1111, 0, 0, 0, 0x2222};
  pack_pixels(store(4), 3, 2, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, out, back);
  const uint16_t want[8] = {0xF800, 0x07E0, 0x001F, 0x1111, 0xFFFF, 0x0000, 0xF800, 0x2222};
  EXPECT_EQ(std::vector<uint16_t>(back, back + 8), std::vector<uint16_t>(want, want + 8));
}

TEST(PixelsCheck, FormatTypeErrors) {
  const GLenum ok = GL_NO_ERROR, e_enum = GL_INVALID_ENUM, e_op = GL_INVALID_OPERATION;
  // The GL 1.x combinations.
  EXPECT_EQ(check_format_type(GL_RGBA, GL_UNSIGNED_BYTE), ok);
  EXPECT_EQ(check_format_type(GL_LUMINANCE, GL_FLOAT), ok);
  EXPECT_EQ(check_format_type(GL_DEPTH_COMPONENT, GL_UNSIGNED_INT), ok);
  EXPECT_EQ(check_format_type(GL_COLOR_INDEX, GL_BITMAP), ok);
  EXPECT_EQ(check_format_type(GL_STENCIL_INDEX, GL_BITMAP), ok);
  EXPECT_EQ(check_format_type(GL_RGBA, GL_BITMAP), e_enum);
  // Unknown enums.
  EXPECT_EQ(check_format_type(0x1234, GL_UNSIGNED_BYTE), e_enum);
  EXPECT_EQ(check_format_type(GL_RGBA, 0x1234), e_enum);
  EXPECT_EQ(check_format_type(GL_RGBA8, GL_UNSIGNED_BYTE), e_enum);  // an internal format
  EXPECT_EQ(check_format_type(GL_RGBA, GL_DOUBLE), e_enum);
  // New formats and types.
  EXPECT_EQ(check_format_type(GL_RG, GL_HALF_FLOAT), ok);
  EXPECT_EQ(check_format_type(GL_RGBA, GL_HALF_FLOAT), ok);
  EXPECT_EQ(check_format_type(GL_RG_INTEGER, GL_INT), ok);
  EXPECT_EQ(check_format_type(GL_BGRA_INTEGER, GL_UNSIGNED_SHORT), ok);
  EXPECT_EQ(check_format_type(GL_RGB, GL_UNSIGNED_SHORT_5_6_5), ok);
  EXPECT_EQ(check_format_type(GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV), ok);
  EXPECT_EQ(check_format_type(GL_RGB_INTEGER, GL_UNSIGNED_SHORT_5_6_5_REV), ok);
  EXPECT_EQ(check_format_type(GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV), ok);
  EXPECT_EQ(check_format_type(GL_RGBA_INTEGER, GL_UNSIGNED_INT_2_10_10_10_REV), ok);
  EXPECT_EQ(check_format_type(GL_BGRA_INTEGER, GL_UNSIGNED_SHORT_4_4_4_4), ok);
  EXPECT_EQ(check_format_type(GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV), ok);
  EXPECT_EQ(check_format_type(GL_RGB, GL_UNSIGNED_INT_5_9_9_9_REV), ok);
  EXPECT_EQ(check_format_type(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8), ok);
  EXPECT_EQ(check_format_type(GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV), ok);
  // Packed types whose components do not match the format.
  EXPECT_EQ(check_format_type(GL_RGBA, GL_UNSIGNED_SHORT_5_6_5), e_op);
  EXPECT_EQ(check_format_type(GL_BGR, GL_UNSIGNED_SHORT_5_6_5), e_op);
  EXPECT_EQ(check_format_type(GL_RGBA, GL_UNSIGNED_BYTE_3_3_2), e_op);
  EXPECT_EQ(check_format_type(GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4), e_op);
  EXPECT_EQ(check_format_type(GL_RGB, GL_UNSIGNED_INT_8_8_8_8_REV), e_op);
  EXPECT_EQ(check_format_type(GL_RED, GL_UNSIGNED_INT_10_10_10_2), e_op);
  EXPECT_EQ(check_format_type(GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT_1_5_5_5_REV), e_op);
  EXPECT_EQ(check_format_type(GL_RGBA, GL_UNSIGNED_INT_10F_11F_11F_REV), e_op);
  EXPECT_EQ(check_format_type(GL_BGR, GL_UNSIGNED_INT_5_9_9_9_REV), e_op);
  EXPECT_EQ(check_format_type(GL_RGB, GL_UNSIGNED_INT_24_8), e_op);
  EXPECT_EQ(check_format_type(GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8), e_op);
  EXPECT_EQ(check_format_type(GL_RGBA, GL_FLOAT_32_UNSIGNED_INT_24_8_REV), e_op);
  EXPECT_EQ(check_format_type(GL_DEPTH_STENCIL, GL_UNSIGNED_SHORT_5_6_5), e_op);
  // DEPTH_STENCIL with a non-packed type: INVALID_ENUM (as Mesa and the Khronos CTS).
  EXPECT_EQ(check_format_type(GL_DEPTH_STENCIL, GL_UNSIGNED_INT), e_enum);
  EXPECT_EQ(check_format_type(GL_DEPTH_STENCIL, GL_FLOAT), e_enum);
  // Integer formats with float types.
  EXPECT_EQ(check_format_type(GL_RGBA_INTEGER, GL_FLOAT), e_op);
  EXPECT_EQ(check_format_type(GL_RED_INTEGER, GL_HALF_FLOAT), e_op);
  EXPECT_EQ(check_format_type(GL_RGB_INTEGER, GL_UNSIGNED_INT_10F_11F_11F_REV), e_op);
  EXPECT_EQ(check_format_type(GL_RGB_INTEGER, GL_UNSIGNED_INT_5_9_9_9_REV), e_op);
  EXPECT_TRUE(valid_format_type(GL_RGB, GL_UNSIGNED_SHORT_5_6_5));
  EXPECT_FALSE(valid_format_type(GL_RGBA, GL_UNSIGNED_SHORT_5_6_5));
  EXPECT_FALSE(is_packed_type(GL_UNSIGNED_BYTE));
  EXPECT_TRUE(is_packed_type(GL_UNSIGNED_INT_24_8));
  EXPECT_TRUE(is_packed_type(GL_FLOAT_32_UNSIGNED_INT_24_8_REV));
}

// The GL 1.x combinations keep their conversions (golden images rely on them).
TEST(PixelsLegacy, Unchanged) {
  EXPECT_EQ(pixel_layout(store(4), 3, GL_RGB, GL_UNSIGNED_BYTE).row_stride, 12u);
  EXPECT_EQ(pixel_layout(store(4), 3, GL_RGB, GL_UNSIGNED_BYTE).pixel_stride, 3u);
  EXPECT_EQ(pixel_layout(store(1), 10, GL_COLOR_INDEX, GL_BITMAP).row_stride, 2u);
  EXPECT_EQ(type_bytes(GL_BITMAP), 0);
  EXPECT_EQ(format_components(GL_LUMINANCE_ALPHA), 2);
  expect_vec(unpack1(GL_RED, GL_BYTE, int8_t(-128)), {-1, 0, 0, 1});
  expect_vec(unpack1(GL_LUMINANCE, GL_UNSIGNED_BYTE, uint8_t(255)), {1, 1, 1, 1});
  expect_vec(unpack1(GL_ALPHA, GL_UNSIGNED_SHORT, uint16_t(65535)), {0, 0, 0, 1});
  EXPECT_NEAR(unpack1(GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, uint32_t(0x80000000u)).x, 0.5f, 1e-6f);
  EXPECT_EQ(pack1<uint8_t>(GL_RED, GL_UNSIGNED_BYTE, {2, 0, 0, 1}), 255);
  EXPECT_EQ(pack1<uint8_t>(GL_LUMINANCE, GL_UNSIGNED_BYTE, {0.2f, 0.2f, 0.2f, 1}), 153);
  EXPECT_EQ(pack1<int16_t>(GL_RED, GL_SHORT, {-1, 0, 0, 1}), -32768);
  EXPECT_EQ(pack1<float>(GL_RED, GL_FLOAT, {5, 0, 0, 1}), 5.0f);
}
