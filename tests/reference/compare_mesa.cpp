// Tessel against Mesa llvmpipe (the oracle): the same draws, the same clip-space vertices,
// compared pixel by pixel.
//
// Tolerances:
// - coverage: identical on at least 99.99% of the compared pixels (in practice 0 mismatches
//   are expected: both snap to 1/256 pixel and use the same fill rule);
// - shaded colour: at most kColorTolerance (in 8-bit steps) per channel on pixels both cover,
//   and at most 0.1% of pixels off by more than 1 step.
// The suite shows that the coverage tolerance catches a real bug: the same draws offset by
// half a pixel must fail it.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "mesa_oracle.hpp"
#include "shaders.hpp"
#include "tessel/gpu/image.hpp"

using namespace tessel::test;
using tessel::reference::MesaOracle;
using tessel::reference::OracleState;
using tessel::reference::OracleVertex;

namespace {

constexpr int kColorTolerance = 2;

struct Compared {
  size_t pixels = 0;   // pixels compared
  size_t covered = 0;  // covered by either
  size_t coverage_mismatch = 0;
  int max_channel_diff = 0;
  size_t over_one = 0;  // pixels with a channel off by more than 1 (both covered)
};

// Coverage: a pixel is covered when it differs from the clear colour (alpha 0 clear, every
// drawn colour has alpha 255).
Compared compare(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  Compared c;
  c.pixels = a.size() / 4;
  for (size_t i = 0; i < c.pixels; ++i) {
    const bool ca = a[i * 4 + 3] != 0, cb = b[i * 4 + 3] != 0;
    if (ca || cb) ++c.covered;
    if (ca != cb) {
      ++c.coverage_mismatch;
      continue;
    }
    if (!ca) continue;
    int m = 0;
    for (int k = 0; k < 4; ++k) m = std::max(m, std::abs(int(a[i * 4 + k]) - int(b[i * 4 + k])));
    c.max_channel_diff = std::max(c.max_channel_diff, m);
    if (m > 1) ++c.over_one;
  }
  return c;
}

std::unique_ptr<MesaOracle> make_oracle(int w, int h) {
  std::string why;
  auto o = MesaOracle::create(w, h, &why);
  if (!o) ADD_FAILURE() << "Mesa llvmpipe is not available: " << why;
  return o;
}

// The oracle's vertices as the tests' vertex layout (the same clip-space numbers).
std::vector<TestVertex> to_test_vertices(const std::vector<OracleVertex>& verts) {
  std::vector<TestVertex> tv(verts.size());
  for (size_t i = 0; i < verts.size(); ++i) {
    std::copy_n(verts[i].pos, 4, tv[i].pos);
    std::copy_n(verts[i].color, 4, tv[i].color);
    std::copy_n(verts[i].uv, 2, tv[i].uv);
  }
  return tv;
}

// Renders the vertices with Tessel under the state that corresponds to `os`.
std::vector<uint8_t> render_tessel(int w, int h, const std::vector<OracleVertex>& verts,
                                   const RenderState& st, Topology topo, bool flat, int threads = 2,
                                   const float clear_depth = 1.0f) {
  Target t(w, h);
  Context ctx(threads);
  ctx.bind_framebuffer(&t.fb);
  ctx.clear({.color = {0, 0, 0, 0}, .depth = clear_depth});
  Mesh m(to_test_vertices(verts));
  if (flat)
    ctx.draw(FlatColorShader{}, {}, m.layout, st, {.topology = topo, .count = m.count});
  else
    ctx.draw(ColorShader{}, {}, m.layout, st, {.topology = topo, .count = m.count});
  ctx.finish();
  return read_rgba8(t.color);
}

std::vector<uint8_t> render_mesa(MesaOracle& o, const std::vector<OracleVertex>& verts, const OracleState& s,
                                 float clear_depth = 1.0f) {
  const float clear[4] = {0, 0, 0, 0};
  o.clear(clear, clear_depth, 0);
  o.draw(verts, s);
  return o.read_rgba8();
}

OracleVertex vertex_at(float x, float y, float z, float w, int W, int H, const float* color) {
  OracleVertex v{};
  clip_from_window(x, y, z, w, W, H, v.pos);
  std::copy_n(color, 4, v.color);
  return v;
}

// Random small triangles, one in each 32x32 cell of the target so they never overlap; random
// sub-pixel positions, random winding, random clip w (so the divide is exercised too).
// cell and span: the cell size and how far the vertices may be from the cell's corner + 1.
std::vector<OracleVertex> cell_triangles(std::mt19937& rng, int W, int H, float offset, bool colorful,
                                         int cell = 32, float span = 30.0f) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<OracleVertex> v;
  for (int cy = 0; cy < H / cell; ++cy) {
    for (int cx = 0; cx < W / cell; ++cx) {
      const float w = 0.5f + 3.0f * u(rng);
      const float white[4] = {1, 1, 1, 1};
      for (int k = 0; k < 3; ++k) {
        const float c[4] = {u(rng), u(rng), u(rng), 1.0f};
        const float x = float(cx * cell) + 1.0f + span * u(rng) + offset;
        const float y = float(cy * cell) + 1.0f + span * u(rng) + offset;
        v.push_back(vertex_at(x, y, u(rng) * 2.0f - 1.0f, w, W, H, colorful ? c : white));
      }
    }
  }
  return v;
}

}  // namespace

TEST(Mesa, OracleIsLlvmpipe) {
  auto o = make_oracle(16, 16);
  ASSERT_TRUE(o);
  EXPECT_NE(o->renderer().find("llvmpipe"), std::string::npos) << o->renderer();
}

// Thousands of random triangles at random sub-pixel positions: coverage identical on at
// least 99.99% of pixels.
TEST(Mesa, CoverageOfRandomTrianglesMatches) {
  const int W = 512, H = 256;
  auto o = make_oracle(W, H);
  ASSERT_TRUE(o);
  std::mt19937 rng(1234);
  size_t pixels = 0, covered = 0, mismatch = 0, triangles = 0;
  for (int pass = 0; pass < 16; ++pass) {
    const auto verts = cell_triangles(rng, W, H, 0.0f, false);
    triangles += verts.size() / 3;
    OracleState s;
    const auto ref = render_mesa(*o, verts, s);
    const auto got = render_tessel(W, H, verts, RenderState{}, Topology::Triangles, false);
    const Compared c = compare(got, ref);
    pixels += c.pixels;
    covered += c.covered;
    mismatch += c.coverage_mismatch;
  }
  std::printf("coverage: %zu triangles, %zu covered pixels, %zu mismatches\n", triangles, covered, mismatch);
  EXPECT_GE(triangles, 2000u);
  EXPECT_LE(double(mismatch), 1e-4 * double(pixels));
  EXPECT_LE(double(mismatch), 1e-4 * double(covered)) << "mismatch rate over covered pixels";
}

// Triangles of a few pixels, as a tessellated mesh makes them, whose coverage setup works
// out itself (Prim::cover), many of them across the 64-pixel tile edges. As for the larger
// ones, at most 1e-4 of the covered pixels may differ (one does, as before Prim::cover: a
// vertex whose divide by w rounds differently); a wrong group or tile cut misses hundreds.
TEST(Mesa, CoverageOfTinyTrianglesMatches) {
  const int W = 256, H = 192;
  auto o = make_oracle(W, H);
  ASSERT_TRUE(o);
  std::mt19937 rng(4321);
  size_t covered = 0, mismatch = 0, triangles = 0;
  for (int pass = 0; pass < 8; ++pass) {
    // Cells of 9 pixels do not line up with the tiles, so some triangles straddle them.
    const auto verts = cell_triangles(rng, W, H, 0.0f, false, 9, 7.0f);
    triangles += verts.size() / 3;
    const auto ref = render_mesa(*o, verts, OracleState{});
    const auto got = render_tessel(W, H, verts, RenderState{}, Topology::Triangles, false);
    const Compared c = compare(got, ref);
    covered += c.covered;
    mismatch += c.coverage_mismatch;
  }
  std::printf("tiny: %zu triangles, %zu covered pixels, %zu mismatches\n", triangles, covered, mismatch);
  EXPECT_GE(triangles, 4000u);
  EXPECT_LE(double(mismatch), 1e-4 * double(covered));
}

// Large triangles reaching beyond the target (guard band, long edges), drawn one by one.
TEST(Mesa, CoverageOfLargeTrianglesMatches) {
  const int W = 128, H = 128;
  auto o = make_oracle(W, H);
  ASSERT_TRUE(o);
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> u(-400.0f, 528.0f);
  size_t covered = 0, mismatch = 0;
  for (int i = 0; i < 300; ++i) {
    const float white[4] = {1, 1, 1, 1};
    std::vector<OracleVertex> v;
    for (int k = 0; k < 3; ++k) v.push_back(vertex_at(u(rng), u(rng), 0.0f, 1.0f, W, H, white));
    const auto ref = render_mesa(*o, v, OracleState{});
    const auto got = render_tessel(W, H, v, RenderState{}, Topology::Triangles, false, 1);
    const Compared c = compare(got, ref);
    covered += c.covered;
    mismatch += c.coverage_mismatch;
  }
  std::printf("large triangles: %zu covered pixels, %zu mismatches\n", covered, mismatch);
  EXPECT_LE(double(mismatch), 1e-4 * double(covered));
}

// The tolerance catches a real bug: Tessel's vertices moved by half a pixel must fail it.
TEST(Mesa, HalfPixelOffsetWouldFail) {
  const int W = 512, H = 256;
  auto o = make_oracle(W, H);
  ASSERT_TRUE(o);
  std::mt19937 rng_a(1234), rng_b(1234);
  const auto verts = cell_triangles(rng_a, W, H, 0.0f, false);
  const auto shifted = cell_triangles(rng_b, W, H, 0.5f, false);
  const auto ref = render_mesa(*o, verts, OracleState{});
  const auto bad = render_tessel(W, H, shifted, RenderState{}, Topology::Triangles, false);
  const Compared c = compare(bad, ref);
  std::printf("half-pixel offset: %zu of %zu covered pixels differ\n", c.coverage_mismatch, c.covered);
  EXPECT_GT(double(c.coverage_mismatch), 1e-4 * double(c.covered));
}

// Gouraud-interpolated colours with perspective (random w per vertex).
TEST(Mesa, GouraudColoursMatch) {
  const int W = 512, H = 256;
  auto o = make_oracle(W, H);
  ASSERT_TRUE(o);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<OracleVertex> v;
  // Per-vertex w differs inside each triangle, so perspective correction matters.
  for (int cy = 0; cy < H / 32; ++cy)
    for (int cx = 0; cx < W / 32; ++cx)
      for (int k = 0; k < 3; ++k) {
        const float c[4] = {u(rng), u(rng), u(rng), 1.0f};
        v.push_back(vertex_at(cx * 32 + 1 + 30 * u(rng), cy * 32 + 1 + 30 * u(rng), 0.0f, 0.5f + 3 * u(rng),
                              W, H, c));
      }
  const auto ref = render_mesa(*o, v, OracleState{});
  const auto got = render_tessel(W, H, v, RenderState{}, Topology::Triangles, false);
  const Compared c = compare(got, ref);
  std::printf("gouraud: %zu covered, %zu coverage mismatches, max channel diff %d, %zu pixels > 1\n",
              c.covered, c.coverage_mismatch, c.max_channel_diff, c.over_one);
  EXPECT_LE(double(c.coverage_mismatch), 1e-4 * double(c.covered));
  EXPECT_LE(c.max_channel_diff, kColorTolerance);
  EXPECT_LE(double(c.over_one), 1e-3 * double(c.covered));
}

TEST(Mesa, FlatColoursMatch) {
  const int W = 256, H = 256;
  auto o = make_oracle(W, H);
  ASSERT_TRUE(o);
  std::mt19937 rng(8);
  const auto v = cell_triangles(rng, W, H, 0.0f, true);
  OracleState s;
  s.flat = true;
  const auto ref = render_mesa(*o, v, s);
  const auto got = render_tessel(W, H, v, RenderState{}, Topology::Triangles, true);
  const Compared c = compare(got, ref);
  EXPECT_EQ(c.coverage_mismatch, 0u);
  EXPECT_LE(c.max_channel_diff, 1);
}

// Overlapping triangles with random depths, depth test LESS, then blended on top.
TEST(Mesa, DepthTestedAndBlendedMatch) {
  const int W = 256, H = 256;
  auto o = make_oracle(W, H);
  ASSERT_TRUE(o);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<OracleVertex> v;
  for (int i = 0; i < 200; ++i)
    for (int k = 0; k < 3; ++k) {
      const float c[4] = {u(rng), u(rng), u(rng), 1.0f};
      v.push_back(vertex_at(u(rng) * 256, u(rng) * 256, u(rng) * 1.8f - 0.9f, 1.0f, W, H, c));
    }
  OracleState s;
  s.depth_test = true;
  RenderState st;
  st.depth_test = true;
  auto ref = render_mesa(*o, v, s);
  auto got = render_tessel(W, H, v, st, Topology::Triangles, false);
  Compared c = compare(got, ref);
  std::printf("depth: %zu covered, %zu mismatches, max diff %d, %zu > 1\n", c.covered, c.coverage_mismatch,
              c.max_channel_diff, c.over_one);
  EXPECT_LE(double(c.coverage_mismatch), 1e-4 * double(c.covered));
  EXPECT_LE(double(c.over_one), 2e-3 * double(c.covered));

  // Blending: src alpha over.
  for (auto& x : v) x.color[3] = 0.5f;
  s.depth_test = false;
  s.blend = true;
  s.blend_src_rgb = 0x0302;  // GL_SRC_ALPHA
  s.blend_dst_rgb = 0x0303;  // GL_ONE_MINUS_SRC_ALPHA
  s.blend_src_a = 1;
  s.blend_dst_a = 1;
  st = RenderState{};
  st.blend[0] = {.enabled = true,
                 .src_rgb = BlendFactor::SrcAlpha,
                 .dst_rgb = BlendFactor::OneMinusSrcAlpha,
                 .src_alpha = BlendFactor::One,
                 .dst_alpha = BlendFactor::One};
  ref = render_mesa(*o, v, s);
  got = render_tessel(W, H, v, st, Topology::Triangles, false);
  c = compare(got, ref);
  std::printf("blend: %zu covered, %zu mismatches, max diff %d, %zu > 1\n", c.covered, c.coverage_mismatch,
              c.max_channel_diff, c.over_one);
  EXPECT_LE(double(c.coverage_mismatch), 1e-4 * double(c.covered));
  EXPECT_LE(c.max_channel_diff, kColorTolerance + 1);
}

namespace {

// A 64x64 texture of smooth gradients and a checkerboard, rows bottom-up.
tessel::reference::OracleTexture test_texture(int n) {
  tessel::reference::OracleTexture t;
  t.width = t.height = n;
  t.rgba.resize(size_t(n) * n * 4);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      uint8_t* p = &t.rgba[(size_t(y) * n + x) * 4];
      p[0] = uint8_t(x * 255 / (n - 1));
      p[1] = uint8_t(y * 255 / (n - 1));
      p[2] = ((x / 8 + y / 8) & 1) ? 230 : 20;
      p[3] = 255;
    }
  return t;
}

struct TexResult {
  Compared c;
  double mean_diff = 0;
  size_t over_eight = 0;
};

TexResult compare_textured(int W, int H, const std::vector<OracleVertex>& v,
                           const tessel::reference::OracleTexture& ot, Filter min, Filter mag,
                           uint32_t gl_min, uint32_t gl_mag) {
  auto o = make_oracle(W, H);
  if (!o) return {};
  tessel::reference::OracleTexture t = ot;
  t.min_filter = gl_min;
  t.mag_filter = gl_mag;
  t.mipmaps = true;
  o->set_texture(t);
  OracleState s;
  s.textured = true;
  const auto ref = render_mesa(*o, v, s);

  Texture2D tex(Format::RGBA8, t.width, t.height, 0);
  tex.upload_rgba8(0, t.rgba.data(), t.rgba.size());
  tex.generate_mipmaps();
  Target tg(W, H);
  Context ctx(2);
  ctx.bind_framebuffer(&tg.fb);
  ctx.clear({.color = {0, 0, 0, 0}});
  Mesh m(to_test_vertices(v));
  TexturedShader::Uniforms u;
  u.tex = {&tex, {.min_filter = min, .mag_filter = mag}};
  ctx.draw(TexturedShader{}, u, m.layout, RenderState{}, {.count = m.count});
  ctx.finish();
  const auto got = read_rgba8(tg.color);
  TexResult r;
  r.c = compare(got, ref);
  size_t n = 0;
  for (size_t i = 0; i < got.size(); i += 4) {
    if (!got[i + 3] || !ref[i + 3]) continue;
    int m8 = 0;
    for (int k = 0; k < 3; ++k) {
      const int d = std::abs(int(got[i + k]) - int(ref[i + k]));
      r.mean_diff += d;
      m8 = std::max(m8, d);
      ++n;
    }
    if (m8 > 8) ++r.over_eight;
  }
  r.mean_diff /= double(std::max<size_t>(n, 1));
  return r;
}

// A floor quad receding to the horizon: magnified near the camera, minified far away.
std::vector<OracleVertex> tilted_quad(float repeat) {
  auto v = [&](float x, float z, float s, float t) {
    OracleVertex r{};
    r.pos[0] = x;
    r.pos[1] = -0.6f;
    r.pos[2] = 0.0f;
    r.pos[3] = -z;
    r.color[0] = r.color[1] = r.color[2] = r.color[3] = 1.0f;
    r.uv[0] = s * repeat;
    r.uv[1] = t * repeat;
    return r;
  };
  return {v(-1.5f, -0.7f, 0, 0), v(1.5f, -0.7f, 1, 0), v(1.5f, -12, 1, 1),
          v(-1.5f, -0.7f, 0, 0), v(1.5f, -12, 1, 1),   v(-1.5f, -12, 0, 1)};
}

}  // namespace

// Perspective-correct, bilinearly magnified texturing: within 2 steps of llvmpipe.
TEST(Mesa, TexturedBilinearMatches) {
  const auto r = compare_textured(256, 256, tilted_quad(0.5f), test_texture(64), Filter::Linear,
                                  Filter::Linear, 0x2601, 0x2601);
  std::printf(
      "textured bilinear: %zu covered, %zu coverage mismatches, max diff %d, %zu pixels > 1, mean %.3f\n",
      r.c.covered, r.c.coverage_mismatch, r.c.max_channel_diff, r.c.over_one, r.mean_diff);
  EXPECT_LE(double(r.c.coverage_mismatch), 1e-4 * double(r.c.covered));
  EXPECT_LE(r.c.max_channel_diff, kColorTolerance);
  EXPECT_GT(r.c.covered, 20000u);
}

// Trilinear minification: LOD from the quad's derivatives and a box-filtered mip chain. The
// LOD formulas and mip chains may differ in the last bits, so the tolerance is wider than for
// bilinear: at most 8 steps on any channel and a mean difference under 0.5 steps (measured:
// max 5, mean 0.23).
TEST(Mesa, TexturedTrilinearMatches) {
  const auto r = compare_textured(256, 256, tilted_quad(8.0f), test_texture(64), Filter::LinearMipmapLinear,
                                  Filter::Linear, 0x2703, 0x2601);
  std::printf(
      "textured trilinear: %zu covered, %zu coverage mismatches, max diff %d, mean %.3f, %zu pixels > 8\n",
      r.c.covered, r.c.coverage_mismatch, r.c.max_channel_diff, r.mean_diff, r.over_eight);
  EXPECT_LE(double(r.c.coverage_mismatch), 1e-4 * double(r.c.covered));
  EXPECT_LE(r.c.max_channel_diff, 8);
  EXPECT_LT(r.mean_diff, 0.5);
  EXPECT_EQ(r.over_eight, 0u);
}
