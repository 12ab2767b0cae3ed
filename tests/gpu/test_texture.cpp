// Textures: formats, half floats, storage, mipmaps, and the GL sampling rules.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#if defined(__F16C__)
#include <immintrin.h>
#endif

#include "tessel/gpu/detail/pipeline.hpp"
#include "tessel/gpu/texture.hpp"

using namespace tessel::gpu;

namespace {

uint32_t fbits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}
float from_fbits(uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

// An RGBA32F texture whose texel (x, y) is given by fn(x, y), rows bottom-up.
template <class Fn>
Texture2D make_f32(int w, int h, Fn fn) {
  Texture2D t(Format::RGBA32F, w, h);
  std::vector<float> data;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::vec4 c = fn(x, y);
      data.insert(data.end(), {c.x, c.y, c.z, c.w});
    }
  t.upload(0, data.data(), data.size() * sizeof(float));
  return t;
}

SamplerState nearest(Wrap w = Wrap::ClampToEdge) {
  SamplerState s;
  s.min_filter = s.mag_filter = Filter::Nearest;
  s.wrap_s = s.wrap_t = w;
  return s;
}
SamplerState linear(Wrap w = Wrap::ClampToEdge) {
  SamplerState s = nearest(w);
  s.min_filter = s.mag_filter = Filter::Linear;
  return s;
}

// A texture with `levels` levels where every texel of level L is (L, L, L, 1) - or, if
// `distinct`, red = 100 L + (x + y * width) so texels can be told apart.
Texture2D level_marked(int size, bool distinct = false) {
  Texture2D t(Format::RGBA32F, size, size, 0);
  for (int l = 0; l < t.levels(); ++l) {
    const int w = t.width(l), h = t.height(l);
    std::vector<float> d;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const float r = distinct ? float(100 * l + x + y * w) : float(l);
        d.insert(d.end(), {r, float(l), float(l), 1.0f});
      }
    t.upload(l, d.data(), d.size() * sizeof(float));
  }
  return t;
}

// Deferred work that is pending while armed; a flush disarms it.
struct CountingWork final : PendingWork {
  int flushes = 0;
  bool armed = false;
  void flush() override {
    armed = false;
    ++flushes;
  }
  bool has_pending() const override { return armed; }
};

}  // namespace

// --- half floats --------------------------------------------------------------------------

TEST(Half, ExhaustiveRoundTripOfAll65536Halves) {
  int nans = 0;
  for (uint32_t h = 0; h < 65536; ++h) {
    const float f = half_to_float(uint16_t(h));
#if defined(__F16C__)
    // The hardware conversion is exact for every half.
    const float hw = _cvtsh_ss(uint16_t(h));
    if (std::isnan(hw)) {
      ASSERT_TRUE(std::isnan(f)) << h;
    } else {
      ASSERT_EQ(fbits(f), fbits(hw)) << "half " << h;
    }
#endif
    if (std::isnan(f)) ++nans;
    ASSERT_EQ(float_to_half(f), uint16_t(h)) << "half 0x" << std::hex << h;
  }
  EXPECT_EQ(nans, 2 * 1023);
}

TEST(Half, KnownValues) {
  EXPECT_EQ(float_to_half(0.0f), 0x0000);
  EXPECT_EQ(float_to_half(-0.0f), 0x8000);
  EXPECT_EQ(float_to_half(1.0f), 0x3C00);
  EXPECT_EQ(float_to_half(-2.0f), 0xC000);
  EXPECT_EQ(float_to_half(65504.0f), 0x7BFF);
  EXPECT_EQ(float_to_half(65519.99f), 0x7BFF);
  EXPECT_EQ(float_to_half(65520.0f), 0x7C00);  // the tie rounds to even: infinity
  EXPECT_EQ(float_to_half(1.0e10f), 0x7C00);
  EXPECT_EQ(float_to_half(-INFINITY), 0xFC00);
  EXPECT_EQ(float_to_half(std::ldexp(1.0f, -24)), 0x0001);  // smallest subnormal
  EXPECT_EQ(float_to_half(std::ldexp(1.0f, -25)), 0x0000);  // tie -> even (0)
  EXPECT_EQ(float_to_half(std::ldexp(1.5f, -25)), 0x0001);
  EXPECT_EQ(float_to_half(std::ldexp(3.0f, -25)), 0x0002);             // 1.5 ulp ties to even 2
  EXPECT_EQ(float_to_half(std::ldexp(1.0f, -14)), 0x0400);             // smallest normal
  EXPECT_EQ(float_to_half(std::ldexp(1023.5f, -24)), 0x0400);          // subnormal rounding up into normal
  EXPECT_EQ(float_to_half(1.0f + std::ldexp(1.0f, -11)), 0x3C00);      // tie, even stays
  EXPECT_EQ(float_to_half(1.0f + 3 * std::ldexp(1.0f, -11)), 0x3C02);  // tie, odd rounds up
  EXPECT_EQ(float_to_half(0.1f), 0x2E66);
  EXPECT_TRUE(std::isnan(half_to_float(float_to_half(NAN))));
  EXPECT_EQ(half_to_float(0x3555), 0.333251953125f);
  EXPECT_EQ(half_to_float(0x0001), std::ldexp(1.0f, -24));
  EXPECT_EQ(half_to_float(0x7C00), INFINITY);
}

#if defined(__F16C__)
TEST(Half, FloatToHalfMatchesHardwareOnASweepOfFloats) {
  // Every 251st float bit pattern (about 17 million values), both signs, all exponents.
  for (uint64_t b = 0; b <= 0xFFFFFFFFull; b += 251) {
    const float f = from_fbits(uint32_t(b));
    const uint16_t hw = _cvtss_sh(f, _MM_FROUND_TO_NEAREST_INT);
    const uint16_t sw = float_to_half(f);
    if (std::isnan(f)) {
      ASSERT_EQ(sw & 0x7C00, 0x7C00);
      ASSERT_NE(sw & 0x3FF, 0);
    } else {
      ASSERT_EQ(sw, hw) << "float bits 0x" << std::hex << b;
    }
  }
}
#endif

// --- construction and storage ----------------------------------------------------------------

TEST(Texture2D, BadSizesThrowNamingTheSize) {
  EXPECT_THROW(Texture2D(Format::RGBA8, 0, 4), Error);
  EXPECT_THROW(Texture2D(Format::RGBA8, 4, -1), Error);
  EXPECT_THROW(Texture2D(Format::RGBA8, kMaxTextureSize + 1, 1), Error);
  try {
    Texture2D t(Format::RGBA8, 16385, 7);
    FAIL() << "no exception";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("16385x7"), std::string::npos) << e.what();
  }
  EXPECT_THROW(Texture2D(Format::RGBA8, 8, 8, 5), Error);  // 8x8 has 4 levels at most
  EXPECT_THROW(Texture2D(Format::RGBA8, 8, 8, -1), Error);
  EXPECT_NO_THROW(Texture2D(Format::RGBA8, 8, 8, 4));
  EXPECT_NO_THROW(Texture2D(Format::R8, kMaxTextureSize, 1));
}

TEST(Texture2D, LevelSizesAndFullChain) {
  Texture2D t(Format::RGBA8, 8, 2, 0);
  ASSERT_EQ(t.levels(), 4);
  EXPECT_EQ(t.width(0), 8);
  EXPECT_EQ(t.height(0), 2);
  EXPECT_EQ(t.width(1), 4);
  EXPECT_EQ(t.height(1), 1);
  EXPECT_EQ(t.width(2), 2);
  EXPECT_EQ(t.width(3), 1);
  EXPECT_EQ(t.height(3), 1);
  EXPECT_EQ(t.level(0).data.size(), 8u * 2u * 4u);
  EXPECT_EQ(t.level(0).row_bytes(), 32u);
  Texture2D one(Format::Depth24Stencil8, 1, 1, 0);
  EXPECT_EQ(one.levels(), 1);
  Texture2D odd(Format::RGBA16F, 5, 3, 0);
  EXPECT_EQ(odd.levels(), 3);  // 5x3, 2x1, 1x1
  EXPECT_EQ(odd.level(1).data.size(), 2u * 1u * 8u);
}

TEST(Texture2D, UploadWithWrongByteCountThrows) {
  Texture2D t(Format::RGBA8, 4, 4);
  std::vector<uint8_t> data(64, 7);
  EXPECT_THROW(t.upload(0, data.data(), 60), Error);
  EXPECT_THROW(t.upload(0, data.data(), 68), Error);
  EXPECT_THROW(t.upload(1, data.data(), 64), Error);  // no level 1
  EXPECT_THROW(t.upload_rgba8(0, data.data(), 63), Error);
  EXPECT_THROW(t.upload_rgba32f(0, reinterpret_cast<const float*>(data.data()), 64), Error);
  try {
    t.upload(0, data.data(), 60);
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("64"), std::string::npos) << m;
    EXPECT_NE(m.find("60"), std::string::npos) << m;
  }
  EXPECT_NO_THROW(t.upload(0, data.data(), 64));
  EXPECT_NEAR(t.fetch(0, 3, 3).x, 7.0f / 255.0f, 1e-7f);
  EXPECT_NEAR(t.fetch(0, 3, 3).w, 7.0f / 255.0f, 1e-7f);
}

TEST(Texture2D, FormatsStoreAndFetch) {
  {
    Texture2D t(Format::RGBA8, 1, 1);
    t.store(0, 0, 0, {0.2f, 0.4f, 0.6f, 0.8f});
    const auto* b = reinterpret_cast<const uint8_t*>(t.level(0).data.data());
    EXPECT_EQ(b[0], 51);
    EXPECT_EQ(b[1], 102);
    EXPECT_EQ(b[2], 153);
    EXPECT_EQ(b[3], 204);
    EXPECT_FLOAT_EQ(t.fetch(0, 0, 0).y, 102.0f / 255.0f);
  }
  {
    Texture2D t(Format::R8, 1, 1);
    t.store(0, 0, 0, {1.0f, 0.5f, 0.5f, 0.5f});
    EXPECT_EQ(t.fetch(0, 0, 0), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  }
  {
    Texture2D t(Format::RG8, 1, 1);
    t.store(0, 0, 0, {0.0f, 1.0f, 0.5f, 0.5f});
    EXPECT_EQ(t.fetch(0, 0, 0), glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
  }
  {
    Texture2D t(Format::RGBA16F, 1, 1);
    t.store(0, 0, 0, {0.1f, -2.5f, 65504.0f, 1e6f});
    const glm::vec4 c = t.fetch(0, 0, 0);
    EXPECT_EQ(c.x, half_to_float(0x2E66));
    EXPECT_EQ(c.y, -2.5f);
    EXPECT_EQ(c.z, 65504.0f);
    EXPECT_EQ(c.w, INFINITY);
    uint16_t h[4];
    std::memcpy(h, t.level(0).data.data(), 8);
    EXPECT_EQ(h[0], 0x2E66);
    EXPECT_EQ(h[1], 0xC100);
  }
  {
    Texture2D t(Format::RGBA32F, 1, 1);
    t.store(0, 0, 0, {-3.25f, 1e20f, 0.1f, 7.0f});
    EXPECT_EQ(t.fetch(0, 0, 0), glm::vec4(-3.25f, 1e20f, 0.1f, 7.0f));
  }
  {
    Texture2D t(Format::Depth24, 1, 1);
    t.store(0, 0, 0, {0.5f, 0, 0, 0});
    uint32_t w;
    std::memcpy(&w, t.level(0).data.data(), 4);
    EXPECT_EQ(w, 8388608u);  // 0.5 * (2^24 - 1) = 8388607.5 rounds to even
    EXPECT_FLOAT_EQ(t.fetch(0, 0, 0).x, float(8388608.0 / 16777215.0));
    EXPECT_EQ(t.fetch(0, 0, 0).w, 1.0f);
    t.store(0, 0, 0, {1.0f, 0, 0, 0});
    EXPECT_EQ(t.fetch(0, 0, 0), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  }
  {
    Texture2D t(Format::Depth32F, 2, 1);
    t.store(0, 0, 0, {0.25f, 0, 0, 0});
    t.store(0, 1, 0, {1.5f, 0, 0, 0});  // depth is clamped to [0, 1]
    EXPECT_EQ(t.fetch(0, 0, 0), glm::vec4(0.25f, 0.0f, 0.0f, 1.0f));
    EXPECT_EQ(t.fetch(0, 1, 0).x, 1.0f);
  }
  {
    Texture2D t(Format::Depth24Stencil8, 1, 1);
    t.store(0, 0, 0, {0.75f, 200.0f, 0, 0});
    uint32_t w;
    std::memcpy(&w, t.level(0).data.data(), 4);
    EXPECT_EQ(w >> 24, 200u);
    EXPECT_EQ(w & 0xFFFFFFu, uint32_t(std::llrint(0.75 * 16777215.0)));
    const glm::vec4 c = t.fetch(0, 0, 0);
    EXPECT_FLOAT_EQ(c.x, 0.75f);
    EXPECT_EQ(c.y, 200.0f);
    EXPECT_EQ(c.w, 1.0f);
  }
}

TEST(Texture2D, AllUnorm8ValuesRoundTrip) {
  Texture2D t(Format::RGBA8, 256, 1);
  for (int i = 0; i < 256; ++i) t.store(0, i, 0, glm::vec4(float(i) / 255.0f));
  const auto* b = reinterpret_cast<const uint8_t*>(t.level(0).data.data());
  for (int i = 0; i < 256; ++i) {
    ASSERT_EQ(b[i * 4], i);
    Texture2D u(Format::R8, 1, 1);
    u.store(0, 0, 0, t.fetch(0, i, 0));
    ASSERT_EQ(uint8_t(u.level(0).data[0]), i);
  }
}

TEST(Texture2D, UploadRgba32fConvertsLikeGL) {
  Texture2D t(Format::RGBA8, 2, 1);
  const float src[8] = {0.5f, 1.2f, -1.0f, NAN, 0.498f, 0.502f, 1.0f / 255.0f, 0.0f};
  t.upload_rgba32f(0, src, sizeof src);
  const auto* b = reinterpret_cast<const uint8_t*>(t.level(0).data.data());
  EXPECT_EQ(b[0], 128);  // 127.5 -> 128 (to even)
  EXPECT_EQ(b[1], 255);
  EXPECT_EQ(b[2], 0);
  EXPECT_EQ(b[3], 0);
  EXPECT_EQ(b[4], 127);
  EXPECT_EQ(b[5], 128);
  EXPECT_EQ(b[6], 1);
  EXPECT_EQ(b[7], 0);

  Texture2D f(Format::RGBA32F, 1, 1);
  const uint8_t px[4] = {0, 51, 255, 128};
  f.upload_rgba8(0, px, 4);
  const glm::vec4 fc = f.fetch(0, 0, 0);
  EXPECT_EQ(fc.x, 0.0f);
  EXPECT_NEAR(fc.y, 51.0f / 255.0f, 1e-7f);
  EXPECT_EQ(fc.z, 1.0f);
  EXPECT_NEAR(fc.w, 128.0f / 255.0f, 1e-7f);
}

TEST(Texture2D, FetchAndStoreOutOfRangeThrow) {
  Texture2D t(Format::RGBA8, 2, 2);
  EXPECT_THROW(t.fetch(0, 2, 0), Error);
  EXPECT_THROW(t.fetch(0, 0, -1), Error);
  EXPECT_THROW(t.fetch(1, 0, 0), Error);
  EXPECT_THROW(t.store(0, -1, 0, glm::vec4(1.0f)), Error);
}

TEST(Texture2D, MutationsFlushPendingWorkFirst) {
  CountingWork work;
  Texture2D t(Format::RGBA8, 2, 2, 0);
  TextureCube c(Format::RGBA8, 2);
  note_draw_submitted();  // a draw queued after the textures were made may read them
  std::vector<uint8_t> d(16, 1);
  int expected = 0;
  auto check = [&](const char* what, auto&& fn) {
    work.armed = true;
    fn();
    EXPECT_EQ(work.flushes, ++expected) << what;
    EXPECT_FALSE(work.armed) << what;
  };
  check("upload", [&] { t.upload(0, d.data(), d.size()); });
  check("upload_rgba8", [&] { t.upload_rgba8(0, d.data(), d.size()); });
  check("upload_rgba32f", [&] {
    const float f[4] = {1, 2, 3, 4};
    t.upload_rgba32f(1, f, sizeof f);
  });
  check("store", [&] { t.store(0, 0, 0, glm::vec4(1.0f)); });
  check("generate_mipmaps", [&] { t.generate_mipmaps(); });
  check("allocate_full_chain", [&] { t.allocate_full_chain(); });
  check("level_for_write", [&] { (void)t.level_for_write(0); });
  check("cube generate_mipmaps", [&] { c.generate_mipmaps(); });
  check("cube face store", [&] { c.face(3).store(0, 0, 0, glm::vec4(1.0f)); });
  // Reading does not flush.
  work.armed = true;
  (void)t.fetch(0, 0, 0);
  (void)texture(Sampler2D{&t, {}}, Vec2<float>(0.5f, 0.5f));
  EXPECT_EQ(work.flushes, expected);
  work.armed = false;
}

// A texture made after the last draw was submitted cannot be read by queued work: filling it
// does not flush (the GL layer makes one per glDrawPixels and per texture rebuild).
TEST(Texture2D, FreshTextureWritesDoNotFlush) {
  CountingWork work;
  note_draw_submitted();
  Texture2D t(Format::RGBA8, 2, 2, 0);
  std::vector<uint8_t> d(16, 1);
  work.armed = true;
  t.upload(0, d.data(), d.size());
  t.generate_mipmaps();
  EXPECT_EQ(work.flushes, 0);
  note_draw_submitted();  // now a draw may use it
  t.upload(0, d.data(), d.size());
  EXPECT_EQ(work.flushes, 1);
  work.armed = false;
}

// --- mipmaps --------------------------------------------------------------------------------

TEST(Mipmaps, FourByFourBoxFilter) {
  Texture2D t(Format::R8, 4, 4, 0);
  std::vector<uint8_t> d(16);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) d[size_t(y * 4 + x)] = uint8_t(10 * x + 40 * y);
  t.upload(0, d.data(), d.size());
  t.generate_mipmaps();
  ASSERT_EQ(t.levels(), 3);
  auto r = [&](int l, int x, int y) { return int(std::lround(t.fetch(l, x, y).x * 255.0f)); };
  EXPECT_EQ(r(1, 0, 0), 25);   // (0 + 10 + 40 + 50) / 4
  EXPECT_EQ(r(1, 1, 0), 45);   // (20 + 30 + 60 + 70) / 4
  EXPECT_EQ(r(1, 0, 1), 105);  // (80 + 90 + 120 + 130) / 4
  EXPECT_EQ(r(1, 1, 1), 125);
  EXPECT_EQ(r(2, 0, 0), 75);
}

TEST(Mipmaps, OddSizesWeightEveryTexel) {
  // 3x3 -> 1x1 is the plain mean of all nine texels.
  Texture2D t = make_f32(
      3, 3, [](int x, int y) { return glm::vec4(x == 2 && y == 2 ? 9.0f : 0.0f, float(x + 3 * y), 0, 1); });
  t.allocate_full_chain();
  ASSERT_EQ(t.levels(), 2);
  EXPECT_NEAR(t.fetch(1, 0, 0).x, 1.0f, 1e-6f);
  EXPECT_NEAR(t.fetch(1, 0, 0).y, 4.0f, 1e-6f);

  // 5 -> 2: weights (2, 2, 1)/5 and (1, 2, 2)/5; the middle texel counts for both halves.
  Texture2D u = make_f32(5, 1, [](int x, int) { return glm::vec4(10.0f * float(x), 0, 0, 1); });
  u.allocate_full_chain();
  ASSERT_EQ(u.levels(), 3);
  ASSERT_EQ(u.width(1), 2);
  EXPECT_NEAR(u.fetch(1, 0, 0).x, 8.0f, 1e-5f);   // 0*.4 + 10*.4 + 20*.2
  EXPECT_NEAR(u.fetch(1, 1, 0).x, 32.0f, 1e-5f);  // 20*.2 + 30*.4 + 40*.4
  EXPECT_NEAR(u.fetch(2, 0, 0).x, 20.0f, 1e-5f);  // the overall mean survives
  EXPECT_NEAR(u.fetch(2, 0, 0).w, 1.0f, 1e-6f);
}

TEST(Mipmaps, DepthAveragedAsFloats) {
  Texture2D t(Format::Depth32F, 2, 2, 0);
  const float d[4] = {0.1f, 0.2f, 0.3f, 0.6f};
  t.upload(0, d, sizeof d);
  t.generate_mipmaps();
  EXPECT_NEAR(t.fetch(1, 0, 0).x, 0.3f, 1e-6f);
}

// --- filtering and wrapping -------------------------------------------------------------------

TEST(Sampling, NearestAndLinearMagnificationByHand) {
  // Rows bottom-up: (0,0)=0 (1,0)=1 / (0,1)=2 (1,1)=3.
  Texture2D t = make_f32(2, 2, [](int x, int y) { return glm::vec4(float(x + 2 * y), 0, 0, 1); });
  Sampler2D n{&t, nearest()};
  Sampler2D l{&t, linear()};
  EXPECT_EQ(texture(n, Vec2<float>(0.25f, 0.25f)).x, 0.0f);  // first uploaded row is t = 0
  EXPECT_EQ(texture(n, Vec2<float>(0.375f, 0.625f)).x, 2.0f);
  EXPECT_EQ(texture(n, Vec2<float>(0.75f, 0.75f)).x, 3.0f);
  EXPECT_EQ(texture(l, Vec2<float>(0.5f, 0.5f)).x, 1.5f);
  // u = 0.75 -> a = 0.25; v = 1.25 -> b = 0.75: (0 + .25) * .25 + (2 + .25) * .75
  EXPECT_FLOAT_EQ(texture(l, Vec2<float>(0.375f, 0.625f)).x, 1.75f);
  // Texel centres give the texel exactly.
  EXPECT_EQ(texture(l, Vec2<float>(0.25f, 0.75f)).x, 2.0f);
  EXPECT_EQ(texture(l, Vec2<float>(0.75f, 0.25f)).w, 1.0f);

  Texture2D b(Format::RGBA8, 2, 1);
  const uint8_t px[8] = {0, 0, 0, 255, 255, 255, 255, 255};
  b.upload_rgba8(0, px, 8);
  const Vec4<float> c = texture(Sampler2D{&b, linear()}, Vec2<float>(0.5f, 0.5f));
  EXPECT_NEAR(c.x, 0.5f, 1e-6f);
  EXPECT_EQ(c.w, 1.0f);
}

TEST(Sampling, WrapModesNearest) {
  // Five texels, red = index.
  Texture2D t = make_f32(5, 1, [](int x, int) { return glm::vec4(float(x), 0, 0, 1); });
  auto at = [&](Wrap w, float s) {
    SamplerState st = nearest(w);
    st.border_color = glm::vec4(0.25f, 0.5f, 0.75f, 1.0f);
    return texture(Sampler2D{&t, st}, Vec2<float>(s, 0.5f));
  };
  // u = s * 5 = -1.25, 6.25, 13.75
  EXPECT_EQ(at(Wrap::Repeat, -0.25f).x, 3.0f);
  EXPECT_EQ(at(Wrap::Repeat, 1.25f).x, 1.0f);
  EXPECT_EQ(at(Wrap::Repeat, 2.75f).x, 3.0f);
  EXPECT_EQ(at(Wrap::ClampToEdge, -0.25f).x, 0.0f);
  EXPECT_EQ(at(Wrap::ClampToEdge, 1.25f).x, 4.0f);
  EXPECT_EQ(at(Wrap::ClampToEdge, 2.75f).x, 4.0f);
  EXPECT_EQ(at(Wrap::MirroredRepeat, -0.25f).x, 1.0f);  // mirrors to 0.25
  EXPECT_EQ(at(Wrap::MirroredRepeat, 1.25f).x, 3.0f);   // mirrors to 0.75
  EXPECT_EQ(at(Wrap::MirroredRepeat, 2.75f).x, 3.0f);   // period 2: 0.75
  EXPECT_EQ(at(Wrap::MirroredRepeat, 0.5f).x, 2.0f);
  const glm::vec4 border(0.25f, 0.5f, 0.75f, 1.0f);
  for (float s : {-0.25f, 1.25f, 2.75f}) {
    const Vec4<float> c = at(Wrap::ClampToBorder, s);
    EXPECT_EQ(glm::vec4(c.x, c.y, c.z, c.w), border) << s;
  }
  EXPECT_EQ(at(Wrap::ClampToBorder, 0.5f).x, 2.0f);
  EXPECT_EQ(at(Wrap::ClampToBorder, 0.999f).x, 4.0f);
}

TEST(Sampling, WrapModesLinear) {
  Texture2D t = make_f32(5, 1, [](int x, int) { return glm::vec4(float(x), 0, 0, 1); });
  auto at = [&](Wrap w, float s) {
    SamplerState st = linear(w);
    st.wrap_t = Wrap::ClampToEdge;
    st.border_color = glm::vec4(0.25f, 0.5f, 0.75f, 1.0f);
    return texture(Sampler2D{&t, st}, Vec2<float>(s, 0.5f)).x;
  };
  // s = -0.25: u - 0.5 = -1.75 -> texels -2, -1 with weights .75, .25
  EXPECT_FLOAT_EQ(at(Wrap::Repeat, -0.25f), 3.25f);          // texels 3, 4
  EXPECT_FLOAT_EQ(at(Wrap::ClampToEdge, -0.25f), 0.0f);      // both clamp to 0
  EXPECT_FLOAT_EQ(at(Wrap::MirroredRepeat, -0.25f), 0.75f);  // -2 -> 1 (.75), -1 -> 0 (.25)
  EXPECT_FLOAT_EQ(at(Wrap::ClampToBorder, -0.25f), 0.25f);
  // s = 1.25: u - 0.5 = 5.75 -> texels 5, 6 with weights .25, .75
  EXPECT_FLOAT_EQ(at(Wrap::Repeat, 1.25f), 0.75f);  // texels 0 (.25), 1 (.75)
  EXPECT_FLOAT_EQ(at(Wrap::ClampToEdge, 1.25f), 4.0f);
  EXPECT_FLOAT_EQ(at(Wrap::MirroredRepeat, 1.25f), 3.25f);  // texels 4 (.25), 3 (.75)
  // s = 2.75: u - 0.5 = 13.25 -> texels 13, 14 weights .75, .25 -> repeat 3, 4
  EXPECT_FLOAT_EQ(at(Wrap::Repeat, 2.75f), 3.25f);
  EXPECT_FLOAT_EQ(at(Wrap::MirroredRepeat, 2.75f), 3.25f);  // 13 -> 3, 14 -> 4
  // Half a texel inside the left edge with a border: 0.75 of texel 0 and 0.25 of the border.
  EXPECT_FLOAT_EQ(at(Wrap::ClampToBorder, 0.05f), 0.0625f);
}

TEST(Sampling, BorderColourFollowsTheFormat) {
  Texture2D t(Format::RGBA8, 2, 2);
  SamplerState st = nearest(Wrap::ClampToBorder);
  st.border_color = glm::vec4(2.0f, -1.0f, 0.5f, 1.0f);
  Vec4<float> c = texture(Sampler2D{&t, st}, Vec2<float>(-1.0f, 0.5f));
  EXPECT_EQ(c.x, 1.0f);  // unsigned normalized: clamped
  EXPECT_EQ(c.y, 0.0f);
  EXPECT_EQ(c.z, 0.5f);
  Texture2D r(Format::R8, 2, 2);
  c = texture(Sampler2D{&r, st}, Vec2<float>(0.5f, 3.0f));
  EXPECT_EQ(c.x, 1.0f);
  EXPECT_EQ(c.y, 0.0f);
  EXPECT_EQ(c.z, 0.0f);
  EXPECT_EQ(c.w, 1.0f);
}

TEST(Sampling, NaNAndHugeCoordinatesAreSafe) {
  Texture2D t = make_f32(4, 4, [](int x, int y) { return glm::vec4(float(x + 4 * y), 0, 0, 1); });
  for (Wrap w : {Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat, Wrap::ClampToBorder}) {
    for (SamplerState st : {nearest(w), linear(w)}) {
      const Sampler2D s{&t, st};
      // NaN is treated as 0.
      const Vec4<float> a = texture(s, Vec2<float>(NAN, NAN));
      const Vec4<float> z = texture(s, Vec2<float>(0.0f, 0.0f));
      EXPECT_EQ(a.x, z.x);
      for (float v : {INFINITY, -INFINITY, 1e30f, -3e9f, 7e8f}) {
        const Vec4<float> c = texture(s, Vec2<float>(v, v));
        EXPECT_FALSE(std::isnan(c.x)) << v;
      }
      (void)textureLod(s, Vec2<float>(0.5f, 0.5f), NAN);
    }
  }
  Texture2D m = level_marked(8);
  SamplerState st = linear(Wrap::Repeat);
  st.min_filter = Filter::LinearMipmapLinear;
  Float8 u(0.5f), v(0.5f);
  u[1] = NAN;
  v[6] = INFINITY;
  const Vec4<Float8> c = texture(Sampler2D{&m, st}, Vec2<Float8>(u, v));
  for (int i = 0; i < kLanes; ++i) EXPECT_FALSE(std::isnan(c.w[i]));

  // The RGBA8 fixed-point path also samples NaN as 0, in both wrap modes.
  Texture2D r(Format::RGBA8, 8, 8, 1);
  std::vector<uint8_t> px(8 * 8 * 4);
  for (size_t i = 0; i < px.size(); ++i) px[i] = uint8_t(i * 37 + 11);
  r.upload_rgba8(0, px.data(), px.size());
  for (Wrap w : {Wrap::Repeat, Wrap::ClampToEdge}) {
    const Sampler2D rs{&r, linear(w)};
    Float8 a(0.3f), b(0.6f);
    a[2] = NAN;
    b[5] = NAN;
    const Vec4<Float8> n = texture(rs, Vec2<Float8>(a, b));
    a[2] = 0.0f;
    b[5] = 0.0f;
    const Vec4<Float8> z = texture(rs, Vec2<Float8>(a, b));
    for (int i = 0; i < kLanes; ++i) {
      EXPECT_EQ(n.x[i], z.x[i]) << i;
      EXPECT_EQ(n.y[i], z.y[i]) << i;
    }
  }
}

TEST(Sampling, NullTextureIsOpaqueBlack) {
  const Sampler2D s{};
  const Vec4<float> c = texture(s, Vec2<float>(0.5f, 0.5f));
  EXPECT_EQ(glm::vec4(c.x, c.y, c.z, c.w), glm::vec4(0, 0, 0, 1));
  const Vec4<Float8> c8 = texture(s, Vec2<Float8>(Float8(0.5f), Float8(0.5f)));
  EXPECT_EQ(c8.w[5], 1.0f);
  EXPECT_EQ(c8.x[5], 0.0f);
  EXPECT_EQ(textureSize(s, 0), glm::ivec2(0));
  EXPECT_EQ(texture(SamplerCube{}, Vec3<float>(1, 0, 0)).w, 1.0f);
}

TEST(Sampling, DepthTextureReadsAsRed) {
  Texture2D t(Format::Depth32F, 1, 1);
  const float d = 0.375f;
  t.upload(0, &d, 4);
  const Vec4<float> c = texture(Sampler2D{&t, nearest()}, Vec2<float>(0.5f, 0.5f));
  EXPECT_EQ(glm::vec4(c.x, c.y, c.z, c.w), glm::vec4(0.375f, 0, 0, 1));
}

TEST(Sampling, TexelFetchBoundsAndSize) {
  Texture2D t = make_f32(3, 2, [](int x, int y) { return glm::vec4(float(x), float(y), 5, 6); });
  const Sampler2D s{&t, nearest()};
  Vec4<float> c = texelFetch(s, 2, 1, 0);
  EXPECT_EQ(glm::vec4(c.x, c.y, c.z, c.w), glm::vec4(2, 1, 5, 6));
  const glm::ivec3 outside[] = {{3, 0, 0}, {0, 2, 0},  {-1, 0, 0},     {0, -1, 0},
                                {0, 0, 1}, {0, 0, -1}, {1 << 30, 0, 0}};
  for (const glm::ivec3& o : outside) {
    c = texelFetch(s, o.x, o.y, o.z);
    EXPECT_EQ(glm::vec4(c.x, c.y, c.z, c.w), glm::vec4(0.0f)) << o.x << "," << o.y << "," << o.z;
  }
  const Int8 xs = Int8(vx::i32x8{0, 1, 2, 3, -1, 2, 0, 100});
  const Int8 ys = Int8(vx::i32x8{0, 0, 1, 0, 0, 1, 2, 0});
  const Vec4<Float8> c8 = texelFetch(s, xs, ys, 0);
  const float expect_x[8] = {0, 1, 2, 0, 0, 2, 0, 0};
  const float expect_w[8] = {6, 6, 6, 0, 0, 6, 0, 0};
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(c8.x[i], expect_x[i]) << i;
    EXPECT_EQ(c8.w[i], expect_w[i]) << i;
  }
  EXPECT_EQ(textureSize(s, 0), glm::ivec2(3, 2));
  Texture2D m(Format::RGBA8, 8, 4, 0);
  EXPECT_EQ(textureSize(Sampler2D{&m, {}}, 2), glm::ivec2(2, 1));
  EXPECT_EQ(textureSize(Sampler2D{&m, {}}, 4), glm::ivec2(0, 0));
}

// --- level of detail --------------------------------------------------------------------------

TEST(Lod, FromDerivatives) {
  EXPECT_FLOAT_EQ(detail::lod_from_derivatives(0.25f, 0.0f, 0.0f, 0.25f, 16, 16), 2.0f);
  EXPECT_FLOAT_EQ(detail::lod_from_derivatives(0.25f, 0.0f, 0.0f, 0.0625f, 16, 16), 2.0f);  // max of both
  EXPECT_FLOAT_EQ(detail::lod_from_derivatives(0.0f, 0.0f, 0.0f, 0.5f, 4, 16), 3.0f);
  EXPECT_FLOAT_EQ(detail::lod_from_derivatives(1.0f / 16, 0.0f, 0.0f, 1.0f / 16, 16, 16), 0.0f);
  // Diagonal: |(3, 4)| = 5 texels per pixel; rho^2 = 25 = 2^4 * 1.5625, and the level of
  // detail takes log2 as llvmpipe does (exponent + mantissa - 1): 0.5 * 4.5625.
  EXPECT_FLOAT_EQ(detail::lod_from_derivatives(3.0f / 64, 4.0f / 64, 0.0f, 0.0f, 64, 64), 2.28125f);
  // 3 texels per pixel: 0.5 * (3 + 0.125), where the exact log2(3) would be 1.585 (the mip
  // blend llvmpipe was measured to use in tests/gl 14_tex_filter_mipmap).
  EXPECT_FLOAT_EQ(detail::lod_from_derivatives(3.0f / 32, 0.0f, 0.0f, 0.0f, 32, 32), 1.5625f);
  EXPECT_LE(detail::lod_from_derivatives(0, 0, 0, 0, 16, 16), -1000.0f);
}

namespace {
// Two quads: lane i at pixel (x, y) = (i & 1, (i >> 1) & 1) within quad i / 4, uv = origin + pixel * step.
Vec2<Float8> quad_uv(float u0, float v0, float step_q0, float step_q1) {
  Vec2<Float8> uv{Float8(0.0f), Float8(0.0f)};
  for (int i = 0; i < kLanes; ++i) {
    const float step = i < 4 ? step_q0 : step_q1;
    uv.x[i] = u0 + float(i & 1) * step;
    uv.y[i] = v0 + float((i >> 1) & 1) * step;
  }
  return uv;
}
}  // namespace

TEST(Lod, QuadWithFourTexelsPerPixelSelectsLevelTwo) {
  Texture2D t = level_marked(16, true);
  ASSERT_EQ(t.levels(), 5);
  SamplerState st = nearest(Wrap::Repeat);
  st.min_filter = Filter::NearestMipmapNearest;
  const Sampler2D s{&t, st};
  // Quad 0: 4 texels (of level 0) per pixel -> lod 2. Quad 1: 1 texel per pixel -> lod 0 (mag).
  const Vec2<Float8> uv = quad_uv(0.1f, 0.1f, 4.0f / 16.0f, 1.0f / 16.0f);
  const Vec4<Float8> c = texture(s, uv);
  for (int i = 0; i < 4; ++i) {
    const int x = int(std::floor(uv.x[i] * 4.0f)), y = int(std::floor(uv.y[i] * 4.0f));
    EXPECT_EQ(c.x[i], t.fetch(2, x, y).x) << "lane " << i;
    EXPECT_EQ(c.y[i], 2.0f) << "lane " << i;
  }
  for (int i = 4; i < 8; ++i) {
    const int x = int(std::floor(uv.x[i] * 16.0f)), y = int(std::floor(uv.y[i] * 16.0f));
    EXPECT_EQ(c.x[i], t.fetch(0, x, y).x) << "lane " << i;
  }
  // Scalar texture() has no neighbours: level 0 (plus bias).
  EXPECT_EQ(texture(s, Vec2<float>(0.1f, 0.1f)).y, 0.0f);
  SamplerState biased = st;
  biased.lod_bias = 3.0f;
  EXPECT_EQ(texture(Sampler2D{&t, biased}, Vec2<float>(0.1f, 0.1f)).y, 3.0f);
}

TEST(Lod, NearestMipmapLevelRounding) {
  Texture2D t = level_marked(16);
  SamplerState st = nearest();
  st.min_filter = Filter::NearestMipmapNearest;
  const Sampler2D s{&t, st};
  auto level_at = [&](float lod) { return textureLod(s, Vec2<float>(0.3f, 0.3f), lod).y; };
  EXPECT_EQ(level_at(0.4f), 0.0f);
  EXPECT_EQ(level_at(0.5f), 0.0f);  // lambda <= 1/2 -> base level
  EXPECT_EQ(level_at(0.6f), 1.0f);
  EXPECT_EQ(level_at(1.4f), 1.0f);
  EXPECT_EQ(level_at(1.6f), 2.0f);
  EXPECT_EQ(level_at(3.7f), 4.0f);
  EXPECT_EQ(level_at(50.0f), 4.0f);  // the last level
  EXPECT_EQ(level_at(-3.0f), 0.0f);
}

TEST(Lod, TrilinearBlendAtFractionalLod) {
  Texture2D t = level_marked(16);
  SamplerState st = linear();
  st.min_filter = Filter::LinearMipmapLinear;
  const Sampler2D s{&t, st};
  EXPECT_FLOAT_EQ(textureLod(s, Vec2<float>(0.3f, 0.7f), 1.25f).y, 1.25f);
  EXPECT_FLOAT_EQ(textureLod(s, Vec2<float>(0.3f, 0.7f), 0.5f).y, 0.5f);
  EXPECT_FLOAT_EQ(textureLod(s, Vec2<float>(0.3f, 0.7f), 3.9f).y, 3.9f);
  EXPECT_FLOAT_EQ(textureLod(s, Vec2<float>(0.3f, 0.7f), 4.5f).y, 4.0f);
  SamplerState nl = st;
  nl.min_filter = Filter::NearestMipmapLinear;
  EXPECT_FLOAT_EQ(textureLod(Sampler2D{&t, nl}, Vec2<float>(0.3f, 0.7f), 2.75f).y, 2.75f);
  // Bias and the [min_lod, max_lod] clamp.
  SamplerState b = st;
  b.lod_bias = 1.0f;
  EXPECT_FLOAT_EQ(textureLod(Sampler2D{&t, b}, Vec2<float>(0.3f, 0.7f), 0.25f).y, 1.25f);
  b.max_lod = 1.5f;
  EXPECT_FLOAT_EQ(textureLod(Sampler2D{&t, b}, Vec2<float>(0.3f, 0.7f), 3.0f).y, 1.5f);
  b.min_lod = 1.75f;
  b.max_lod = 1000.0f;
  EXPECT_FLOAT_EQ(textureLod(Sampler2D{&t, b}, Vec2<float>(0.3f, 0.7f), -5.0f).y, 1.75f);
  // A non-mipmapped minification filter stays on level 0.
  SamplerState lin = linear();
  EXPECT_EQ(textureLod(Sampler2D{&t, lin}, Vec2<float>(0.3f, 0.7f), 2.5f).y, 0.0f);

  // Implicit LOD from a quad: 2^1.5 texels per pixel -> lod 1.5.
  const float step = std::exp2(1.5f) / 16.0f;
  const Vec4<Float8> c = texture(s, quad_uv(0.2f, 0.3f, step, step));
  for (int i = 0; i < kLanes; ++i) EXPECT_NEAR(c.y[i], 1.5f, 1e-5f) << i;

  // textureGrad with explicit derivatives: 8 texels per pixel -> lod 3, per lane.
  Vec2<Float8> uv{Float8(0.4f), Float8(0.4f)};
  Vec2<Float8> dx{Float8(0.5f), Float8(0.0f)}, dy{Float8(0.0f), Float8(0.0f)};
  dx.x[7] = 2.0f / 16.0f;  // lane 7: lod 1
  const Vec4<Float8> g = textureGrad(s, uv, dx, dy);
  EXPECT_FLOAT_EQ(g.y[0], 3.0f);
  EXPECT_FLOAT_EQ(g.y[7], 1.0f);
  EXPECT_FLOAT_EQ(textureGrad(s, Vec2<float>(0.4f, 0.4f), Vec2<float>(0.5f, 0.0f), Vec2<float>(0.0f, 0.0f)).y,
                  3.0f);
  Float8 lods(2.25f);
  lods[3] = 0.75f;
  const Vec4<Float8> l8 = textureLod(s, uv, lods);
  EXPECT_FLOAT_EQ(l8.y[0], 2.25f);
  EXPECT_FLOAT_EQ(l8.y[3], 0.75f);
}

TEST(Lod, MagnificationSwitchUsesMagFilter) {
  // Default filters (min NEAREST_MIPMAP_LINEAR, mag LINEAR): lambda <= 0 uses the mag filter.
  Texture2D t = make_f32(2, 1, [](int x, int) { return glm::vec4(float(x), 0, 0, 1); });
  SamplerState st;
  st.wrap_s = st.wrap_t = Wrap::ClampToEdge;
  const Sampler2D s{&t, st};
  EXPECT_FLOAT_EQ(textureLod(s, Vec2<float>(0.5f, 0.5f), 0.0f).x, 0.5f);   // LINEAR
  EXPECT_FLOAT_EQ(textureLod(s, Vec2<float>(0.5f, 0.5f), 0.25f).x, 1.0f);  // NEAREST (min)
}

// --- cube maps --------------------------------------------------------------------------------

TEST(Cube, FaceSelectionForEachAxis) {
  TextureCube cube(Format::RGBA32F, 2);
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) cube.face(f).store(0, x, y, glm::vec4(float(10 * f + x + 2 * y), 0, 0, 1));
  SamplerCube s{&cube, nearest()};
  struct Case {
    glm::vec3 dir;
    float expect;
  };
  const Case cases[] = {
      {{1.0f, 0.5f, -0.5f}, 1.0f},    // +X: sc = -z, tc = -y -> texel (1, 0)
      {{-1.0f, 0.5f, -0.5f}, 10.0f},  // -X: sc = z, tc = -y -> (0, 0)
      {{0.5f, 1.0f, -0.5f}, 21.0f},   // +Y: sc = x, tc = z -> (1, 0)
      {{0.5f, -1.0f, -0.5f}, 33.0f},  // -Y: sc = x, tc = -z -> (1, 1)
      {{0.5f, -0.5f, 1.0f}, 43.0f},   // +Z: sc = x, tc = -y -> (1, 1)
      {{0.5f, -0.5f, -1.0f}, 52.0f},  // -Z: sc = -x, tc = -y -> (0, 1)
  };
  for (const Case& c : cases) {
    EXPECT_EQ(texture(s, Vec3<float>(c.dir.x, c.dir.y, c.dir.z)).x, c.expect)
        << c.dir.x << "," << c.dir.y << "," << c.dir.z;
    // Scaling the direction does not matter.
    EXPECT_EQ(detail::sample_cube(s, 7 * c.dir.x, 7 * c.dir.y, 7 * c.dir.z, 0.0f).x, c.expect);
  }
  // Eight lanes: the same per lane.
  Vec3<Float8> d{Float8(0.0f), Float8(0.0f), Float8(0.0f)};
  for (int i = 0; i < kLanes; ++i) {
    const glm::vec3 v = cases[i % 6].dir;
    d.x[i] = v.x;
    d.y[i] = v.y;
    d.z[i] = v.z;
  }
  const Vec4<Float8> r = texture(s, d);
  for (int i = 0; i < kLanes; ++i) EXPECT_EQ(r.x[i], cases[i % 6].expect) << i;
  // Linear filtering clamps to the face edge.
  SamplerCube sl{&cube, linear(Wrap::Repeat)};
  EXPECT_FLOAT_EQ(texture(sl, Vec3<float>(1.0f, 1.0f - 1e-3f, -0.9999f)).x, 1.0f);
  EXPECT_FALSE(std::isnan(texture(sl, Vec3<float>(0.0f, 0.0f, 0.0f)).x));
}

// --- shadow comparison ------------------------------------------------------------------------

TEST(Shadow, NearestAndLinearPcf) {
  Texture2D t(Format::Depth32F, 2, 2);
  const float d[4] = {0.2f, 0.8f, 0.6f, 0.6f};  // (0,0) (1,0) / (0,1) (1,1)
  t.upload(0, d, sizeof d);
  Sampler2DShadow s{&t};
  s.state.min_filter = s.state.mag_filter = Filter::Nearest;
  EXPECT_EQ(texture(s, Vec3<float>(0.25f, 0.25f, 0.5f)), 0.0f);  // 0.5 <= 0.2 fails
  EXPECT_EQ(texture(s, Vec3<float>(0.75f, 0.25f, 0.5f)), 1.0f);  // 0.5 <= 0.8
  EXPECT_EQ(texture(s, Vec3<float>(0.25f, 0.25f, 0.2f)), 1.0f);  // equal passes LEQUAL
  s.state.compare_func = CompareFunc::Greater;
  EXPECT_EQ(texture(s, Vec3<float>(0.25f, 0.25f, 0.5f)), 1.0f);
  EXPECT_EQ(texture(s, Vec3<float>(0.75f, 0.25f, 0.5f)), 0.0f);
  s.state.compare_func = CompareFunc::Never;
  EXPECT_EQ(texture(s, Vec3<float>(0.75f, 0.25f, 0.5f)), 0.0f);
  s.state.compare_func = CompareFunc::Always;
  EXPECT_EQ(texture(s, Vec3<float>(0.25f, 0.25f, 0.5f)), 1.0f);

  // LINEAR: the four results (0, 1 / 1, 1) weighted bilinearly.
  Sampler2DShadow l{&t};
  EXPECT_FLOAT_EQ(texture(l, Vec3<float>(0.5f, 0.5f, 0.5f)), 0.75f);
  // a = b = 0.25: bottom = lerp(0, 1, .25) = .25, top = 1 -> .25 + .75 * .25
  EXPECT_FLOAT_EQ(texture(l, Vec3<float>(0.375f, 0.375f, 0.5f)), 0.4375f);
  EXPECT_FLOAT_EQ(texture(l, Vec3<float>(0.375f, 0.375f, 0.9f)), 0.0f);
  EXPECT_FLOAT_EQ(texture(l, Vec3<float>(0.375f, 0.375f, 0.1f)), 1.0f);
  // Eight lanes agree with one.
  Vec3<Float8> p{Float8(0.375f), Float8(0.375f), Float8(0.5f)};
  p.x[5] = 0.5f;
  p.y[5] = 0.5f;
  const Float8 r = texture(l, p);
  EXPECT_FLOAT_EQ(r[0], 0.4375f);
  EXPECT_FLOAT_EQ(r[5], 0.75f);
  EXPECT_EQ(texture(Sampler2DShadow{}, Vec3<float>(0.5f, 0.5f, 0.5f)), 0.0f);
}

TEST(Shadow, ReferenceClampedForFixedPointDepthOnly) {
  Texture2D d24(Format::Depth24, 1, 1);
  d24.store(0, 0, 0, glm::vec4(1.0f));
  Sampler2DShadow s{&d24};
  EXPECT_EQ(texture(s, Vec3<float>(0.5f, 0.5f, 1.5f)), 1.0f);  // ref clamps to 1 <= 1
  Texture2D d32(Format::Depth32F, 1, 1);
  d32.store(0, 0, 0, glm::vec4(1.0f));
  Sampler2DShadow f{&d32};
  EXPECT_EQ(texture(f, Vec3<float>(0.5f, 0.5f, 1.5f)), 0.0f);  // float depth: no clamp
  // Border texels compare the border's red.
  Sampler2DShadow b{&d32};
  b.state.wrap_s = b.state.wrap_t = Wrap::ClampToBorder;
  b.state.min_filter = b.state.mag_filter = Filter::Nearest;
  b.state.border_color = glm::vec4(0.3f);
  EXPECT_EQ(texture(b, Vec3<float>(2.0f, 0.5f, 0.2f)), 1.0f);
  EXPECT_EQ(texture(b, Vec3<float>(2.0f, 0.5f, 0.4f)), 0.0f);
}

// GL 1.x GL_CLAMP: coordinates clamped to [0, 1]; nearest stays on the edge texels, linear
// blends half of the border colour in at the edge.
TEST(Wrap, LegacyClamp) {
  Texture2D t(Format::RGBA8, 2, 1);
  const uint8_t px[8] = {255, 0, 0, 255, 0, 0, 255, 255};  // red, blue
  t.upload(0, px, sizeof px);
  Sampler2D s;
  s.texture = &t;
  s.state.wrap_s = s.state.wrap_t = Wrap::Clamp;
  s.state.border_color = glm::vec4(0, 1, 0, 1);
  s.state.min_filter = s.state.mag_filter = Filter::Nearest;
  EXPECT_EQ(detail::sample_2d(s, 1.5f, 0.5f, 0.0f), glm::vec4(0, 0, 1, 1));   // s = 1: last texel
  EXPECT_EQ(detail::sample_2d(s, -0.5f, 0.5f, 0.0f), glm::vec4(1, 0, 0, 1));  // s = 0: first texel
  s.state.min_filter = s.state.mag_filter = Filter::Linear;
  const glm::vec4 edge = detail::sample_2d(s, 2.0f, 0.5f, 0.0f);  // s = 1, on the texel row
  EXPECT_NEAR(edge.b, 0.5f, 1e-6f);                               // half the last texel ...
  EXPECT_NEAR(edge.g, 0.5f, 1e-6f);                               // ... half the border
}

// Sixteen lanes of trilinear RGBA8 have a path of their own (detail/texture_simd.hpp); it must
// give the bits of the two halves sampled as eight lanes each, whichever way each call goes:
// all four quads between the same two levels (the sixteen-lane path), quads on different
// levels, magnification, beyond the last level, NaN coordinates (the eight-lane fallbacks).
#if defined(__AVX2__)
// The eight-lane fixed-point bilinear filter reads a lane's two texels of a row as one 64-bit
// load when they are side by side; it must give the bits of reading them one by one, on a
// power-of-two texture with REPEAT (pairs that wrap) and a non-power-of-two one with
// CLAMP_TO_EDGE (pairs clamped at the edges), coordinates over several repeats.
TEST(Sampling, BilinearTexelPairsGiveTheBitsOfSingleTexels) {
  std::mt19937 rng(12);
  int pairs = 0, calls = 0;
  for (int wrap = 0; wrap < 2; ++wrap) {
    const int W = wrap ? 37 : 32, H = wrap ? 19 : 16;
    Texture2D t(Format::RGBA8, W, H, 1);
    std::vector<uint8_t> px(size_t(W) * H * 4);
    for (auto& p : px) p = uint8_t(rng());
    t.upload_rgba8(0, px.data(), px.size());
    const Wrap mode = wrap ? Wrap::ClampToEdge : Wrap::Repeat;
    const detail::LevelRef L = detail::level_ref(t, 0);
    // Spread coordinates, or a row of neighbours (most lanes then have pairs side by side).
    std::uniform_real_distribution<float> pos(-2.0f, 3.0f), near(0.0f, 0.3f);
    for (int iter = 0; iter < 4000; ++iter, ++calls) {
      Float8 s, u;
      const float s0 = pos(rng), u0 = pos(rng);
      for (int l = 0; l < 8; ++l) {
        s[l] = iter % 2 ? pos(rng) : s0 + near(rng);
        u[l] = iter % 2 ? pos(rng) : u0 + near(rng);
      }
      s = detail::sane8_fixed(s);
      u = detail::sane8_fixed(u);
      const Vec4<Float8> a = detail::decode_rgba16(detail::bilinear_rgba16_sane<true>(L, mode, mode, s, u));
      const Vec4<Float8> b = detail::decode_rgba16(detail::bilinear_rgba16_sane<false>(L, mode, mode, s, u));
      for (int l = 0; l < 8; ++l) {
        ASSERT_EQ(fbits(a.x[l]), fbits(b.x[l])) << "wrap " << wrap << " iter " << iter << " lane " << l;
        ASSERT_EQ(fbits(a.y[l]), fbits(b.y[l])) << l;
        ASSERT_EQ(fbits(a.z[l]), fbits(b.z[l])) << l;
        ASSERT_EQ(fbits(a.w[l]), fbits(b.w[l])) << l;
      }
      bool side_by_side = true;
      for (int l = 0; l < 8; ++l) {
        const int i0 = int(std::floor(s[l] * float(W) - 0.5f));
        const int x0 = wrap ? std::clamp(i0, 0, W - 1) : (i0 & (W - 1));
        const int x1 = wrap ? std::clamp(i0 + 1, 0, W - 1) : ((i0 + 1) & (W - 1));
        side_by_side = side_by_side && x1 == x0 + 1;
      }
      pairs += side_by_side;
    }
  }
  EXPECT_GT(pairs, 500);  // both ways of reading were taken
  EXPECT_LT(pairs, calls - 500);
}
#endif

// An RGBA8 texture of random texels with its full mip chain.
static void fill_random_mipmapped(Texture2D& t, std::mt19937& rng) {
  std::vector<uint8_t> px(size_t(t.width()) * size_t(t.height()) * 4);
  for (auto& p : px) p = uint8_t(rng());
  t.upload_rgba8(0, px.data(), px.size());
  t.generate_mipmaps();
}

TEST(Sampling, SixteenLanesGiveTheBitsOfTwoHalvesOfEight) {
  Texture2D t(Format::RGBA8, 256, 128, 0);
  std::mt19937 rng(11);
  fill_random_mipmapped(t, rng);
  std::uniform_real_distribution<float> pos(-3.0f, 3.0f), lod(-1.5f, 9.5f);
  int fast = 0;
  for (int wrap = 0; wrap < 2; ++wrap) {
    for (int variant = 0; variant < 3; ++variant) {
      SamplerState st;
      st.min_filter = Filter::LinearMipmapLinear;
      st.mag_filter = Filter::Linear;
      st.wrap_s = st.wrap_t = wrap ? Wrap::ClampToEdge : Wrap::Repeat;
      if (variant == 1) st.lod_bias = 0.75f;
      if (variant == 2) {
        st.min_lod = 1.5f;
        st.max_lod = 4.25f;
      }
      const Sampler2D s{&t, st};
      for (int iter = 0; iter < 3000; ++iter) {
        // Four 2x2 quads; one scale for all of them, or one each (every 4th call).
        Vec2<Float16> uv;
        const float x0 = pos(rng), y0 = pos(rng);
        float scale[4];
        for (int q = 0; q < 4; ++q)
          scale[q] = (q == 0 || iter % 4 == 0) ? std::exp2(lod(rng)) / 256.0f : scale[0];
        for (int l = 0; l < 16; ++l) {
          const int q = l / 4, g = l / 8;  // quad, 4x2 group
          const float px_x = float(detail::kLaneDx[l % 8] + 4 * g), px_y = float(detail::kLaneDy[l % 8]);
          uv.x[l] = x0 + px_x * scale[q];
          uv.y[l] = y0 + px_y * scale[q] * 0.75f;
        }
        if (iter % 97 == 5) uv.x[iter % 16] = std::numeric_limits<float>::quiet_NaN();
        Vec4<Float16> r16;
        if (detail::trilinear16(t, st, uv, r16)) ++fast;
        const Vec4<Float16> a = texture(s, uv);
        const Vec4<Float8> lo = texture(s, lo_half(uv)), hi = texture(s, hi_half(uv));
        for (int l = 0; l < 16; ++l) {
          const Vec4<Float8>& h = l < 8 ? lo : hi;
          const int i = l % 8;
          ASSERT_EQ(fbits(a.x[l]), fbits(h.x[i]))
              << "wrap " << wrap << " variant " << variant << " iter " << iter << " lane " << l;
          ASSERT_EQ(fbits(a.y[l]), fbits(h.y[i])) << l;
          ASSERT_EQ(fbits(a.z[l]), fbits(h.z[i])) << l;
          ASSERT_EQ(fbits(a.w[l]), fbits(h.w[i])) << l;
        }
      }
    }
  }
  // Both kinds of call happened: the sixteen-lane path and the fallbacks.
  EXPECT_GT(fast, 3000);
  EXPECT_LT(fast, 15000);
}

#if defined(__AVX2__)
// Thirty-two lanes (a paired GLSL fragment call's lookups) give the bits of two sixteen-lane
// lookups, on the fast path and when it falls back (quads on different levels, NaN, bias).
TEST(Sampling, ThirtyTwoLanesGiveTheBitsOfTwoSixteenLaneLookups) {
  Texture2D t(Format::RGBA8, 512, 256, 0);
  std::mt19937 rng(12);
  fill_random_mipmapped(t, rng);
  std::uniform_real_distribution<float> pos(-3.0f, 3.0f), lod(-1.5f, 9.5f);
  int fast = 0, calls = 0;
  for (int wrap = 0; wrap < 2; ++wrap) {
    for (int variant = 0; variant < 2; ++variant) {
      SamplerState st;
      st.min_filter = Filter::LinearMipmapLinear;
      st.mag_filter = Filter::Linear;
      st.wrap_s = st.wrap_t = wrap ? Wrap::ClampToEdge : Wrap::Repeat;
      if (variant == 1) st.lod_bias = -0.5f;
      const Sampler2D s{&t, st};
      for (int iter = 0; iter < 3000; ++iter) {
        // Eight 2x2 quads; one scale for all (most calls), or one each (every 5th call).
        Vec2<Float16> uv[2];
        const float x0 = pos(rng), y0 = pos(rng);
        float scale[8];
        for (int q = 0; q < 8; ++q)
          scale[q] = (q == 0 || iter % 5 == 0) ? std::exp2(lod(rng)) / 512.0f : scale[0];
        for (int l = 0; l < 32; ++l) {
          const int q = l / 4, g = l / 8;
          uv[l / 16].x[l % 16] = x0 + float(detail::kLaneDx[l % 8] + 4 * g) * scale[q];
          uv[l / 16].y[l % 16] = y0 + float(detail::kLaneDy[l % 8]) * scale[q] * 0.6f;
        }
        if (iter % 89 == 7) uv[iter % 2].y[iter % 16] = std::numeric_limits<float>::quiet_NaN();
        Vec4<Float16> r[2];
        ++calls;
        if (!detail::trilinear32(t, st, uv[0], uv[1], r[0], r[1])) continue;
        ++fast;
        for (int k = 0; k < 2; ++k) {
          const Vec4<Float16> want = texture(s, uv[k]);
          for (int l = 0; l < 16; ++l) {
            ASSERT_EQ(fbits(r[k].x[l]), fbits(want.x[l]))
                << "wrap " << wrap << " variant " << variant << " iter " << iter << " lane " << 16 * k + l;
            ASSERT_EQ(fbits(r[k].y[l]), fbits(want.y[l])) << l;
            ASSERT_EQ(fbits(r[k].z[l]), fbits(want.z[l])) << l;
            ASSERT_EQ(fbits(r[k].w[l]), fbits(want.w[l])) << l;
          }
        }
      }
    }
  }
  // Both kinds of call happened.
  EXPECT_GT(fast, 2000);
  EXPECT_LT(fast, calls - 2000);
}

// The 16-bit lerp of RGBA8 filtering is llvmpipe's (a (256 - w) + b w + 128) >> 8, computed
// with vpmulhrsw: every a, b in 0..255 and every weight 0..256.
TEST(Sampling, FixedPointLerpIsExactForEveryInput) {
  for (int w = 0; w <= 256; ++w) {
    const __m256i m = _mm256_set1_epi16(detail::lerp_weight(w));
    for (int a = 0; a < 256; ++a) {
      for (int b0 = 0; b0 < 256; b0 += 16) {
        alignas(32) int16_t bs[16], out[16];
        for (int k = 0; k < 16; ++k) bs[k] = int16_t(b0 + k);
        const __m256i r = detail::lerp16(_mm256_set1_epi16(int16_t(a)),
                                         _mm256_load_si256(reinterpret_cast<const __m256i*>(bs)), m);
        _mm256_store_si256(reinterpret_cast<__m256i*>(out), r);
        for (int k = 0; k < 16; ++k)
          ASSERT_EQ(out[k], (a * (256 - w) + (b0 + k) * w + 128) >> 8)
              << "a " << a << " b " << b0 + k << " w " << w;
      }
    }
  }
}
#endif
