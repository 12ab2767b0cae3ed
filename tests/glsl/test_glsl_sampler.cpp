// The AVX-512 trilinear sampler of GLSL's texture(sampler2D, vec2) (src/glsl/texture_avx512.cpp)
// against the pipeline's own sampler on eight lanes (gpu::texture), bit for bit: random
// textures, coordinates in 2x2 quads at random scales, wrap modes, LOD bias and limits, and
// lanes holding NaN or infinity. Skipped on machines without AVX-512.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "tessel/gpu/texture.hpp"
#include "texture_avx512.hpp"

namespace tessel::glsl {
namespace {

gpu::Texture2D random_texture(std::mt19937& rng, int w, int h) {
  gpu::Texture2D t(gpu::Format::RGBA8, w, h, 0);
  std::vector<uint8_t> px(size_t(w) * size_t(h) * 4);
  for (auto& b : px) b = uint8_t(rng());
  t.upload_rgba8(0, px.data(), px.size());
  t.generate_mipmaps();
  return t;
}

// Sixteen lanes of a quad-ordered group: four 2x2 quads at random places, each with its own
// derivatives (scale picks the level).
void fill_quads(std::mt19937& rng, float scale, TexLanes& tl) {
  std::uniform_real_distribution<float> pos(-3.0f, 3.0f), dir(-1.0f, 1.0f);
  static constexpr int kDx[4] = {0, 1, 0, 1}, kDy[4] = {0, 0, 1, 1};
  std::memset(&tl, 0, sizeof tl);
  for (int q = 0; q < 4; ++q) {
    const float u0 = pos(rng), v0 = pos(rng);
    const float dudx = scale * dir(rng), dvdx = scale * dir(rng), dudy = scale * dir(rng),
                dvdy = scale * dir(rng);
    for (int i = 0; i < 4; ++i) {
      const float u = u0 + dudx * float(kDx[i]) + dudy * float(kDy[i]);
      const float v = v0 + dvdx * float(kDx[i]) + dvdy * float(kDy[i]);
      std::memcpy(&tl.in[TexLanes::kCoord][q * 4 + i], &u, 4);
      std::memcpy(&tl.in[TexLanes::kCoord + 1][q * 4 + i], &v, 4);
    }
  }
}

// What the pipeline's eight-lane sampler gives for the lanes of tl, as result rows.
void reference(const gpu::Texture2D& tex, const gpu::SamplerState& st, const TexLanes& tl,
               uint32_t out[4][16]) {
  const gpu::Sampler2D s{&tex, st};
  for (int h = 0; h < 2; ++h) {
    gpu::Vec2<gpu::Float8> uv{
        gpu::Float8::load(reinterpret_cast<const float*>(tl.in[TexLanes::kCoord]) + 8 * h),
        gpu::Float8::load(reinterpret_cast<const float*>(tl.in[TexLanes::kCoord + 1]) + 8 * h)};
    const gpu::Vec4<gpu::Float8> r = gpu::texture(s, uv);
    r.x.store(reinterpret_cast<float*>(out[0]) + 8 * h);
    r.y.store(reinterpret_cast<float*>(out[1]) + 8 * h);
    r.z.store(reinterpret_cast<float*>(out[2]) + 8 * h);
    r.w.store(reinterpret_cast<float*>(out[3]) + 8 * h);
  }
}

struct Case {
  int w, h;
  gpu::Wrap wrap;
  float bias, min_lod, max_lod;
};

TEST(GlslSampler, Avx512TrilinearMatchesPipelineSampler) {
  if (!avx512_sampling()) GTEST_SKIP() << "this machine has no AVX-512";
  std::mt19937 rng(1234);
  const Case cases[] = {
      {256, 256, gpu::Wrap::Repeat, 0.0f, -1000.0f, 1000.0f},
      {64, 32, gpu::Wrap::Repeat, 0.0f, -1000.0f, 1000.0f},
      {96, 80, gpu::Wrap::ClampToEdge, 0.0f, -1000.0f, 1000.0f},
      {128, 128, gpu::Wrap::Repeat, 0.7f, -1000.0f, 1000.0f},
      {128, 128, gpu::Wrap::ClampToEdge, 0.0f, 1.5f, 3.25f},
      {32, 128, gpu::Wrap::Repeat, -0.4f, 0.0f, 4.0f},
  };
  int fast = 0, lookups = 0;
  for (const Case& c : cases) {
    const gpu::Texture2D tex = random_texture(rng, c.w, c.h);
    gpu::SamplerState st;
    st.min_filter = gpu::Filter::LinearMipmapLinear;
    st.wrap_s = st.wrap_t = c.wrap;
    st.lod_bias = c.bias;
    st.min_lod = c.min_lod;
    st.max_lod = c.max_lod;
    for (int trial = 0; trial < 400; ++trial) {
      // Scales from a fraction of a texel to many texels a pixel: levels 0 to 6.
      const float scale = std::ldexp(1.0f, -int(rng() % 8)) * (0.5f + float(rng() % 1000) / 1000.0f);
      alignas(64) TexLanes a, b;
      fill_quads(rng, scale, a);
      // Sometimes the same level everywhere (one quad's scale for all), sometimes not.
      if (trial % 3 == 0) {
        b = a;
        for (int l = 0; l < 16; ++l) {
          float u;
          std::memcpy(&u, &b.in[TexLanes::kCoord][l], 4);
          u += 0.25f;
          std::memcpy(&b.in[TexLanes::kCoord][l], &u, 4);
        }
      } else {
        fill_quads(rng, scale * (trial % 3 == 1 ? 1.0f : 3.0f), b);
      }
      if (trial % 50 == 7) {  // a lane without a number: the sampler must refuse or agree
        const float bad = trial % 100 == 7 ? std::numeric_limits<float>::quiet_NaN() : INFINITY;
        std::memcpy(&b.in[TexLanes::kCoord + 1][int(rng() % 16)], &bad, 4);
      }
      uint32_t want_a[4][16], want_b[4][16];
      reference(tex, st, a, want_a);
      reference(tex, st, b, want_b);
      alignas(64) TexLanes got_a = a, got_b = b;
      if (trilinear_avx512(tex, st, got_a, got_b)) {
        ++fast;
        for (int k = 0; k < 4; ++k) {
          ASSERT_EQ(0, std::memcmp(got_a.out[k], want_a[k], sizeof want_a[k]))
              << "pair a, row " << k << " trial " << trial;
          ASSERT_EQ(0, std::memcmp(got_b.out[k], want_b[k], sizeof want_b[k]))
              << "pair b, row " << k << " trial " << trial;
        }
      }
      alignas(64) TexLanes one = a;
      if (trilinear_avx512(tex, st, one)) {
        ++fast;
        for (int k = 0; k < 4; ++k)
          ASSERT_EQ(0, std::memcmp(one.out[k], want_a[k], sizeof want_a[k]))
              << "single, row " << k << " trial " << trial;
      }
      lookups += 2;
    }
  }
  // The comparison means something only if the fast path ran often.
  EXPECT_GT(fast, lookups / 4) << fast << " of " << lookups;
}

TEST(GlslSampler, Avx512TrilinearDeclinesWhatItDoesNotCover) {
  if (!avx512_sampling()) GTEST_SKIP() << "this machine has no AVX-512";
  std::mt19937 rng(99);
  gpu::Texture2D tex = random_texture(rng, 64, 64);
  alignas(64) TexLanes tl;
  fill_quads(rng, 0.05f, tl);
  gpu::SamplerState st;
  st.min_filter = gpu::Filter::Linear;  // no mipmapping
  EXPECT_FALSE(trilinear_avx512(tex, st, tl));
  st.min_filter = gpu::Filter::LinearMipmapLinear;
  st.wrap_s = gpu::Wrap::MirroredRepeat;
  EXPECT_FALSE(trilinear_avx512(tex, st, tl));
  gpu::Texture2D one_level(gpu::Format::RGBA8, 64, 64, 1);
  st.wrap_s = gpu::Wrap::Repeat;
  EXPECT_FALSE(trilinear_avx512(one_level, st, tl));
  gpu::Texture2D floats(gpu::Format::RGBA32F, 64, 64, 0);
  EXPECT_FALSE(trilinear_avx512(floats, st, tl));
}

}  // namespace
}  // namespace tessel::glsl
