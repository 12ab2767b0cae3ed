// 3D, array and buffer textures: sizes and bad input (gpu::Error, never a crash), storage,
// mipmaps, and the sampling rules of their third coordinate (GL 4.6 §8.14). Their results
// against Mesa llvmpipe are in tests/glsl/test_glsl_textures.cpp.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <string>
#include <vector>

#include "tessel/gpu/texture.hpp"

using namespace tessel::gpu;

namespace {

// The message of the Error that fn throws ("" when it throws none).
template <class Fn>
std::string error_of(Fn&& fn) {
  try {
    fn();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

bool mentions(const std::string& message, const std::string& what) {
  return message.find(what) != std::string::npos;
}

// An RGBA32F 3D texture (or array) whose texel (x, y, z) is (x, y, z, 100 * level).
template <class T>
void fill_marked(T& t, int level) {
  const Level3D& l = t.level(level);
  std::vector<float> data;
  for (int z = 0; z < l.depth; ++z)
    for (int y = 0; y < l.height; ++y)
      for (int x = 0; x < l.width; ++x)
        data.insert(data.end(), {float(x), float(y), float(z), 100.0f * float(level)});
  t.upload(level, data.data(), data.size() * sizeof(float));
}

SamplerState nearest(Wrap w) {
  SamplerState s;
  s.min_filter = s.mag_filter = Filter::Nearest;
  s.wrap_s = s.wrap_t = s.wrap_r = w;
  return s;
}

TEST(Texture3D, BadSizesThrowNamingTheSize) {
  EXPECT_TRUE(mentions(error_of([] { Texture3D(Format::RGBA8, 0, 4, 4); }), "0x4x4"));
  EXPECT_TRUE(mentions(error_of([] { Texture3D(Format::RGBA8, 4, -1, 4); }), "4x-1x4"));
  EXPECT_TRUE(mentions(error_of([] { Texture3D(Format::RGBA8, 4, 4, 0); }), "4x4x0"));
  EXPECT_TRUE(mentions(error_of([] { Texture3D(Format::RGBA8, kMax3DTextureSize + 1, 1, 1); }), "2049x1x1"));
  EXPECT_TRUE(mentions(error_of([] { Texture3D(Format::Depth32F, 4, 4, 4); }), "DEPTH32F"));
  EXPECT_TRUE(mentions(error_of([] { Texture3D(Format::RGBA8, 8, 2, 4, 5); }), "at most 4"));
  EXPECT_THROW(Texture3D(Format::RGBA8, 8, 8, 8, -1), Error);
  // Within the size limits but far more memory than a texture may take: an Error, before any
  // allocation.
  const std::string huge = error_of([] { Texture3D(Format::RGBA32F, 2048, 2048, 2048, 0); });
  EXPECT_TRUE(mentions(huge, "bytes")) << huge;
  EXPECT_NO_THROW(Texture3D(Format::R8, kMax3DTextureSize, 1, 1));
  EXPECT_NO_THROW(Texture3D(Format::RGBA8, 1, 1, kMax3DTextureSize, 0));
}

TEST(Texture3D, LevelSizesHalveAllThreeAxes) {
  Texture3D t(Format::RGBA8, 8, 2, 4, 0);
  ASSERT_EQ(t.levels(), 4);  // 8x2x4, 4x1x2, 2x1x1, 1x1x1
  EXPECT_EQ(t.width(1), 4);
  EXPECT_EQ(t.height(1), 1);
  EXPECT_EQ(t.depth(1), 2);
  EXPECT_EQ(t.depth(2), 1);
  EXPECT_EQ(t.width(3), 1);
  EXPECT_EQ(t.level(0).data.size(), 8u * 2u * 4u * 4u);
  EXPECT_EQ(t.level(0).slice_bytes(), 8u * 2u * 4u);
  EXPECT_EQ(Texture3D(Format::RGBA8, 1, 1, 16, 0).levels(), 5);  // depth alone sets the chain
}

TEST(Texture3D, UploadFetchAndStoreCheckTheirInput) {
  Texture3D t(Format::RGBA8, 4, 4, 2, 2);
  std::vector<uint8_t> data(4 * 4 * 2 * 4, 9);
  EXPECT_TRUE(
      mentions(error_of([&] { t.upload(0, data.data(), data.size() - 1); }), "needs 128 bytes, got 127"));
  EXPECT_THROW(t.upload(0, data.data(), data.size() + 4), Error);
  EXPECT_THROW(t.upload(2, data.data(), data.size()), Error);  // no level 2
  EXPECT_THROW(t.upload(-1, data.data(), data.size()), Error);
  EXPECT_THROW(t.upload(0, nullptr, data.size()), Error);
  EXPECT_THROW(t.upload_rgba32f(0, reinterpret_cast<const float*>(data.data()), data.size()),
               Error);  // needs 512
  EXPECT_NO_THROW(t.upload(0, data.data(), data.size()));
  EXPECT_NEAR(t.fetch(0, 3, 3, 1).x, 9.0f / 255.0f, 1e-7f);
  EXPECT_TRUE(mentions(error_of([&] { (void)t.fetch(0, 0, 0, 2); }), "(0, 0, 2)"));
  EXPECT_THROW((void)t.fetch(1, 2, 0, 0), Error);  // level 1 is 2x2x1
  EXPECT_THROW(t.store(0, -1, 0, 0, glm::vec4(1.0f)), Error);
  t.store(1, 1, 1, 0, glm::vec4(1.0f, 0.0f, 0.5f, 1.0f));
  EXPECT_EQ(t.fetch(1, 1, 1, 0), glm::vec4(1.0f, 0.0f, 128.0f / 255.0f, 1.0f));
}

TEST(Texture3D, MipmapsAverageEightTexels) {
  Texture3D t(Format::RGBA32F, 2, 2, 2, 0);
  std::vector<float> data;
  for (int k = 0; k < 8; ++k) data.insert(data.end(), {float(k), float(k & 1), 1.0f, 0.5f});
  t.upload(0, data.data(), data.size() * 4);
  t.generate_mipmaps();
  EXPECT_EQ(t.fetch(1, 0, 0, 0), glm::vec4(3.5f, 0.5f, 1.0f, 0.5f));
}

TEST(Texture3D, SamplingSelectsSlicesAndWrapsR) {
  Texture3D t(Format::RGBA32F, 4, 4, 4, 0);
  for (int l = 0; l < t.levels(); ++l) fill_marked(t, l);
  // Nearest: texel (1, 2, 3) at its centre; R wraps on its own mode.
  Sampler3D s{&t, nearest(Wrap::Repeat)};
  EXPECT_EQ(detail::sample_3d(s, 1.5f / 4, 2.5f / 4, 3.5f / 4, 0.0f), glm::vec4(1, 2, 3, 0));
  EXPECT_EQ(detail::sample_3d(s, 1.5f / 4, 2.5f / 4, 1.0f + 0.5f / 4, 0.0f).z, 0.0f);
  s.state.wrap_r = Wrap::ClampToEdge;
  EXPECT_EQ(detail::sample_3d(s, 0.1f, 0.1f, 7.0f, 0.0f).z, 3.0f);
  s.state.wrap_r = Wrap::ClampToBorder;
  s.state.border_color = glm::vec4(-1.0f);
  EXPECT_EQ(detail::sample_3d(s, 0.1f, 0.1f, 1.2f, 0.0f), glm::vec4(-1.0f));
  // Linear: halfway between slices 1 and 2.
  s.state = nearest(Wrap::ClampToEdge);
  s.state.min_filter = s.state.mag_filter = Filter::Linear;
  EXPECT_FLOAT_EQ(detail::sample_3d(s, 0.5f, 0.5f, 0.5f, 0.0f).z, 1.5f);
  // A texel offset moves in the selected level's texels; LOD 1 reads level 1.
  s.state = nearest(Wrap::ClampToEdge);
  s.state.min_filter = Filter::NearestMipmapNearest;
  EXPECT_EQ(detail::sample_3d(s, 0.1f, 0.1f, 0.1f, 1.0f, {1, 0, 1}), glm::vec4(1, 0, 1, 100));
  // The 3D rho: a derivative along r alone selects a level.
  EXPECT_FLOAT_EQ(detail::lod_from_derivatives_3d({0, 0, 0.5f}, {0, 0, 0}, {4, 4, 4}), 1.0f);
  EXPECT_EQ(textureSize(s, 1), glm::ivec3(2, 2, 2));
  EXPECT_EQ(textureSize(s, 3), glm::ivec3(0));
  EXPECT_EQ(detail::texel_fetch(&t, 3, 3, 4, 0), glm::vec4(0.0f));
  EXPECT_EQ(detail::texel_fetch(static_cast<const Texture3D*>(nullptr), 0, 0, 0, 0), glm::vec4(0, 0, 0, 1));
}

TEST(Texture2DArray, BadSizesThrow) {
  EXPECT_TRUE(mentions(error_of([] { Texture2DArray(Format::RGBA8, 0, 4, 4); }), "0x4"));
  EXPECT_TRUE(mentions(error_of([] { Texture2DArray(Format::RGBA8, 4, 4, 0); }), "0 layers"));
  EXPECT_TRUE(mentions(error_of([] { Texture2DArray(Format::RGBA8, 4, 4, kMaxArrayTextureLayers + 1); }),
                       "2049 layers"));
  EXPECT_THROW(Texture2DArray(Format::RGBA8, kMaxTextureSize + 1, 1, 1), Error);
  EXPECT_THROW(Texture2DArray(Format::RGBA8, 4, 4, 2, 4), Error);  // 4x4 has 3 levels
  const std::string huge = error_of([] { Texture2DArray(Format::RGBA32F, 16384, 16384, 2048); });
  EXPECT_TRUE(mentions(huge, "bytes")) << huge;
  EXPECT_NO_THROW(Texture2DArray(Format::Depth32F, 4, 4, 3, 0));
}

TEST(Texture2DArray, LevelsKeepTheLayersAndUploadsCheckSizes) {
  Texture2DArray t(Format::RGBA8, 4, 2, 3, 0);
  ASSERT_EQ(t.levels(), 3);
  EXPECT_EQ(t.layers(), 3);
  EXPECT_EQ(t.level(2).depth, 3);
  EXPECT_EQ(t.width(2), 1);
  std::vector<uint8_t> layer(4 * 2 * 4, 200);
  EXPECT_THROW(t.upload_layer(0, 3, layer.data(), layer.size()), Error);
  EXPECT_THROW(t.upload_layer(0, -1, layer.data(), layer.size()), Error);
  EXPECT_TRUE(mentions(error_of([&] { t.upload_layer(0, 1, layer.data(), 31); }), "needs 32 bytes, got 31"));
  EXPECT_THROW(t.upload(0, layer.data(), layer.size()), Error);  // one layer is not the level
  EXPECT_NO_THROW(t.upload_layer(0, 1, layer.data(), layer.size()));
  t.generate_mipmaps();
  EXPECT_NEAR(t.fetch(1, 1, 0, 1).x, 200.0f / 255.0f, 1e-7f);
  EXPECT_EQ(t.fetch(1, 1, 0, 0).x, 0.0f);
  EXPECT_THROW((void)t.fetch(0, 0, 0, 3), Error);
}

TEST(Texture2DArray, LayerRoundsToEvenAndClamps) {
  EXPECT_EQ(detail::array_layer(-3.0f, 4), 0);
  EXPECT_EQ(detail::array_layer(0.5f, 4), 0);
  EXPECT_EQ(detail::array_layer(0.51f, 4), 1);
  EXPECT_EQ(detail::array_layer(1.5f, 4), 2);
  EXPECT_EQ(detail::array_layer(2.5f, 4), 2);
  EXPECT_EQ(detail::array_layer(9.0f, 4), 3);
  EXPECT_EQ(detail::array_layer(NAN, 4), 0);
  EXPECT_EQ(detail::array_layer(INFINITY, 4), 3);
  Texture2DArray t(Format::RGBA32F, 2, 2, 4, 0);
  fill_marked(t, 0);
  fill_marked(t, 1);
  Sampler2DArray s{&t, nearest(Wrap::Repeat)};
  EXPECT_EQ(detail::sample_2d_array(s, 0.75f, 0.25f, 2.4f, 0.0f), glm::vec4(1, 0, 2, 0));
  EXPECT_EQ(detail::sample_2d_array(s, 0.75f, 0.25f, 7.0f, 0.0f).z, 3.0f);
  EXPECT_EQ(textureSize(s, 1), glm::ivec3(1, 1, 4));
  EXPECT_EQ(detail::texel_fetch(&t, 0, 0, 4, 0), glm::vec4(0.0f));  // integer layers do not clamp
  EXPECT_EQ(detail::texel_fetch(&t, 1, 1, 3, 0), glm::vec4(1, 1, 3, 0));
}

TEST(Texture2DArray, ShadowComparesInTheLayer) {
  Texture2DArray t(Format::Depth32F, 1, 1, 2);
  const float depths[2] = {0.25f, 0.75f};
  t.upload(0, depths, sizeof depths);
  Sampler2DArray s{&t, nearest(Wrap::ClampToEdge)};
  s.state.compare = true;
  s.state.compare_func = CompareFunc::LessEqual;
  EXPECT_EQ(detail::sample_2d_array_compare(s, 0.5f, 0.5f, 0.0f, 0.5f, 0.0f), 0.0f);
  EXPECT_EQ(detail::sample_2d_array_compare(s, 0.5f, 0.5f, 1.0f, 0.5f, 0.0f), 1.0f);
}

TEST(TextureBuffer, BadRangesThrow) {
  Buffer b(64);
  EXPECT_TRUE(mentions(error_of([&] { TextureBuffer(Format::Depth32F, b); }), "DEPTH32F"));
  EXPECT_TRUE(mentions(error_of([&] { TextureBuffer(Format::RGBA32F, b, 8); }), "multiple"));
  EXPECT_TRUE(mentions(error_of([&] { TextureBuffer(Format::RGBA32F, b, 80); }), "past the end"));
  EXPECT_THROW(TextureBuffer(Format::RGBA32F, b, 16, 64), Error);
  EXPECT_NO_THROW(TextureBuffer(Format::RGBA32F, b, 64));  // empty, at the end
  EXPECT_NO_THROW(TextureBuffer(Format::R8, b, 3, 61));
}

TEST(TextureBuffer, FetchesInRangeAndZeroOutside) {
  std::vector<float> texels;
  for (int i = 0; i < 8; ++i) texels.insert(texels.end(), {float(i), 1.0f, 2.0f, 3.0f});
  Buffer b(texels);
  TextureBuffer whole(Format::RGBA32F, b);
  TextureBuffer range(Format::RGBA32F, b, 32, 48);
  EXPECT_EQ(whole.size(), 8);
  EXPECT_EQ(range.size(), 3);
  EXPECT_EQ(whole.fetch(7), glm::vec4(7, 1, 2, 3));
  EXPECT_EQ(range.fetch(0), glm::vec4(2, 1, 2, 3));
  EXPECT_EQ(range.fetch(3), glm::vec4(0.0f));
  EXPECT_EQ(whole.fetch(-1), glm::vec4(0.0f));
  EXPECT_EQ(whole.fetch(8), glm::vec4(0.0f));
  // The view follows the buffer: a smaller buffer shortens both, a larger one the whole view.
  b.assign(texels.data(), 2 * 16);
  EXPECT_EQ(whole.size(), 2);
  EXPECT_EQ(range.size(), 0);
  EXPECT_EQ(range.fetch(0), glm::vec4(0.0f));
  b.assign(texels.data(), texels.size() * 4);
  EXPECT_EQ(whole.size(), 8);
  EXPECT_EQ(range.size(), 3);
}

// Every layout of GL 3.3 Table 3.15, read from the same bytes: unorm, half and float as values,
// integers as their sign- or zero-extended 32 bits; missing components 0, alpha 1 (integer 1).
TEST(TextureBuffer, EveryLayoutReadsItsBytes) {
  const uint8_t bytes[16] = {0xFF, 0x80, 0x00, 0x3C, 0x01, 0x00, 0x00, 0xC0,
                             0x7F, 0x00, 0x00, 0x00, 0x00, 0x00, 0x80, 0x3F};
  Buffer b(bytes, sizeof bytes);
  using C = BufferComponent;
  // Integer texels compared as bits (some are NaN patterns as floats).
  auto bits = [](glm::vec4 v) {
    return glm::uvec4(std::bit_cast<uint32_t>(v.x), std::bit_cast<uint32_t>(v.y),
                      std::bit_cast<uint32_t>(v.z), std::bit_cast<uint32_t>(v.w));
  };
  auto fetch = [&](C c, int channels, int i) {
    return TextureBuffer(BufferTexel{c, uint8_t(channels)}, b).fetch(i);
  };
  EXPECT_EQ(fetch(C::Unorm8, 1, 0), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  EXPECT_EQ(fetch(C::Unorm8, 2, 0), glm::vec4(1.0f, 128.0f / 255.0f, 0.0f, 1.0f));
  EXPECT_EQ(fetch(C::Unorm16, 1, 0), glm::vec4(float(0x80FF) * (1.0f / 65535.0f), 0.0f, 0.0f, 1.0f));
  EXPECT_EQ(fetch(C::Float16, 2, 0).y, 1.0f);   // 0x3C00
  EXPECT_EQ(fetch(C::Float16, 4, 0).w, -2.0f);  // 0xC000
  EXPECT_EQ(fetch(C::Float32, 1, 3), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  EXPECT_EQ(bits(fetch(C::Int8, 4, 0)), glm::uvec4(0xFFFFFFFFu, 0xFFFFFF80u, 0, 0x3C));
  EXPECT_EQ(bits(fetch(C::Uint8, 1, 1)), glm::uvec4(0x80, 0u, 0u, 1u));
  EXPECT_EQ(bits(fetch(C::Int16, 2, 1)), glm::uvec4(0x0001, 0xFFFFC000u, 0u, 1u));
  EXPECT_EQ(bits(fetch(C::Uint16, 1, 3)), glm::uvec4(0xC000, 0u, 0u, 1u));
  EXPECT_EQ(bits(fetch(C::Int16, 1, 3)), glm::uvec4(0xFFFFC000u, 0u, 0u, 1u));
  EXPECT_EQ(bits(fetch(C::Int32, 2, 1)), glm::uvec4(0x7F, 0x3F800000u, 0u, 1u));
  EXPECT_EQ(bits(fetch(C::Uint32, 4, 0)).x, 0x3C0080FFu);
  // Sizes follow the texel size; a layout GL does not have is an error naming it.
  EXPECT_EQ(TextureBuffer(BufferTexel{C::Uint16, 2}, b).size(), 4);
  EXPECT_EQ(TextureBuffer(BufferTexel{C::Float32, 4}, b).size(), 1);
  EXPECT_EQ((BufferTexel{C::Uint16, 2}).name(), "RG16UI");
  EXPECT_EQ((BufferTexel{C::Float16, 4}).name(), "RGBA16F");
  EXPECT_TRUE(mentions(error_of([&] { TextureBuffer(BufferTexel{C::Int8, 3}, b); }), "3 channels"));
  EXPECT_TRUE(mentions(error_of([&] { TextureBuffer(BufferTexel{C::Int32, 2}, b, 4); }), "RG32I"));
}

}  // namespace
