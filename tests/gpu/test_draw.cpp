// End-to-end draws through the whole pipeline: topologies, indexing, instancing, clipping,
// perspective-correct interpolation, flat shading, determinism across thread counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "shaders.hpp"
#include "tessel/gpu/image.hpp"

using namespace tessel::test;

namespace {

std::vector<uint8_t> pixels(const Texture2D& t) { return read_rgba8(t); }
uint32_t px(const std::vector<uint8_t>& p, int w, int x, int y) {
  const uint8_t* q = &p[(size_t(y) * w + x) * 4];
  return uint32_t(q[0]) | uint32_t(q[1]) << 8 | uint32_t(q[2]) << 16 | uint32_t(q[3]) << 24;
}

TestVertex wv(float x, float y, float z, int w, int h, glm::vec4 c = glm::vec4(1), float cw = 1.0f) {
  TestVertex v{};
  clip_from_window(x, y, z, cw, w, h, v.pos);
  v.color[0] = c.r;
  v.color[1] = c.g;
  v.color[2] = c.b;
  v.color[3] = c.a;
  return v;
}

}  // namespace

TEST(Draw, TriangleCoversItsInterior) {
  Target t(32, 32);
  Context ctx(1);
  ctx.bind_framebuffer(&t.fb);
  ctx.clear({.color = {0, 0, 0, 1}});
  Mesh m({wv(2, 2, 0, 32, 32, {1, 0, 0, 1}), wv(30, 2, 0, 32, 32, {1, 0, 0, 1}),
          wv(2, 30, 0, 32, 32, {1, 0, 0, 1})});
  ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 3});
  ctx.finish();
  auto p = pixels(t.color);
  EXPECT_EQ(px(p, 32, 3, 3), 0xFF0000FFu);    // inside: red (bytes r,g,b,a little-endian)
  EXPECT_EQ(px(p, 32, 28, 28), 0xFF000000u);  // outside: black
  EXPECT_EQ(px(p, 32, 15, 15), 0xFF0000FFu);  // below the hypotenuse x + y = 32: centre sum 31
  EXPECT_EQ(px(p, 32, 16, 16), 0xFF000000u);  // centre sum 33 > 32
}

namespace {

struct Offsets {
  struct Uniforms {};
  template <class F>
  struct Varyings {
    Vec4<F> color;
  };
  static constexpr uint32_t attributes = 0b1011;
  // attr 3: per-instance offset (x, y) and colour in z.
  template <class F>
  Vec4<F> vertex(const Uniforms&, const VertexIn<F>& in, Varyings<F>& out) const {
    out.color = Vec4<F>(in.attr[3].z, F(1.0f), to_float(in.instance_id) * F(0.25f), F(1.0f));
    return Vec4<F>(in.attr[0].x + in.attr[3].x, in.attr[0].y + in.attr[3].y, in.attr[0].z, in.attr[0].w);
  }
  template <class F>
  void fragment(const Uniforms&, const Varyings<F>& v, Fragment<F>& f) const {
    f.color[0] = v.color;
  }
};

std::vector<uint8_t> render(int W, int H, const std::vector<TestVertex>& v, const DrawCall& call,
                            const RenderState& st = RenderState{}, int threads = 2, bool flat = false) {
  Target t(W, H);
  Context ctx(threads);
  ctx.bind_framebuffer(&t.fb);
  ctx.clear({.color = {0, 0, 0, 0}});
  Mesh m(v);
  if (flat)
    ctx.draw(FlatColorShader{}, {}, m.layout, st, call);
  else
    ctx.draw(ColorShader{}, {}, m.layout, st, call);
  ctx.finish();
  return read_rgba8(t.color);
}

size_t lit(const std::vector<uint8_t>& p) {
  size_t n = 0;
  for (size_t i = 3; i < p.size(); i += 4) n += p[i] != 0;
  return n;
}

}  // namespace

TEST(Draw, IndexedMatchesArraysForEveryIndexType) {
  const int W = 32, H = 32;
  std::vector<TestVertex> v = {wv(2, 2, 0, W, H), wv(30, 3, 0, W, H), wv(28, 29, 0, W, H),
                               wv(3, 27, 0, W, H)};
  const auto arrays = render(W, H, {v[0], v[1], v[2], v[0], v[2], v[3]}, {.count = 6});
  const uint8_t i8[] = {0, 1, 2, 0, 2, 3};
  const uint16_t i16[] = {0, 1, 2, 0, 2, 3};
  const uint32_t i32[] = {0, 1, 2, 0, 2, 3};
  const Buffer b8(i8, sizeof i8), b16(i16, sizeof i16), b32(i32, sizeof i32);
  EXPECT_EQ(render(W, H, v, {.count = 6, .index_buffer = &b8, .index_type = IndexType::U8}), arrays);
  EXPECT_EQ(render(W, H, v, {.count = 6, .index_buffer = &b16, .index_type = IndexType::U16}), arrays);
  EXPECT_EQ(render(W, H, v, {.count = 6, .index_buffer = &b32, .index_type = IndexType::U32}), arrays);
  // Base vertex: indices shifted down by one, base vertex 1, with a dummy vertex first.
  std::vector<TestVertex> shifted = v;
  shifted.insert(shifted.begin(), wv(0, 0, 0, W, H));
  EXPECT_EQ(render(W, H, shifted, {.count = 6, .index_buffer = &b32, .base_vertex = 1}), arrays);
  EXPECT_GT(lit(arrays), 600u);
}

// The geometry phase finds a chunk's distinct vertices three ways: every id of a dense range
// (unused ids in it are shaded too), a table over a wider range, a hash for scattered ids.
// A grid mesh with `junk` NaN vertices after each row (never indexed: 4 keeps the mesh's
// chunks dense, 40 makes them take the table, 400 shuffled the hash), in mesh order and in
// shuffled triangle order, must give what the same triangles give unindexed.
TEST(Draw, IndexedGridMatchesArraysWithUnusedNaNVertices) {
  const int W = 64, H = 48, NX = 41, NY = 31;
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int junk : {4, 40, 400}) {
    for (bool shuffled : {false, true}) {
      std::vector<TestVertex> v;
      auto id = [&](int i, int j) { return uint32_t(j * (NX + junk) + i); };
      for (int j = 0; j < NY; ++j) {
        for (int i = 0; i < NX; ++i)
          v.push_back(wv(-2.0f + 68.0f * i / (NX - 1) + 0.3f * u(rng),
                         -2.0f + 52.0f * j / (NY - 1) + 0.3f * u(rng), 0, W, H, {u(rng), u(rng), u(rng), 1}));
        for (int k = 0; k < junk; ++k) v.push_back(wv(NAN, NAN, NAN, W, H));
      }
      std::vector<std::array<uint32_t, 3>> tris;
      for (int j = 0; j + 1 < NY; ++j)
        for (int i = 0; i + 1 < NX; ++i) {
          tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
          tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
      if (shuffled) std::shuffle(tris.begin(), tris.end(), rng);
      std::vector<uint32_t> indices;
      std::vector<TestVertex> expanded;
      for (const auto& t : tris)
        for (uint32_t k : t) {
          indices.push_back(k);
          expanded.push_back(v[k]);
        }
      const Buffer ib(indices.data(), indices.size() * 4);
      const auto arrays = render(W, H, expanded, {.count = uint32_t(expanded.size())});
      EXPECT_EQ(render(W, H, v, {.count = uint32_t(indices.size()), .index_buffer = &ib}), arrays)
          << "junk " << junk << (shuffled ? ", shuffled" : "");
      EXPECT_EQ(lit(arrays), size_t(W) * H);
    }
  }
}

TEST(Draw, StripsFansAndListsAgree) {
  const int W = 32, H = 32;
  const TestVertex a = wv(2, 2, 0, W, H), b = wv(30, 2, 0, W, H), c = wv(2, 30, 0, W, H),
                   d = wv(30, 30, 0, W, H);
  const auto list = render(W, H, {a, b, c, c, b, d}, {.count = 6});
  EXPECT_EQ(render(W, H, {a, b, c, d}, {.topology = Topology::TriangleStrip, .count = 4}), list);
  EXPECT_EQ(render(W, H, {a, b, d, c}, {.topology = Topology::TriangleFan, .count = 4}), list);
  // With back-face culling, a strip's odd triangle keeps its winding (not culled).
  RenderState st;
  st.cull = CullMode::Back;
  EXPECT_EQ(render(W, H, {a, b, c, d}, {.topology = Topology::TriangleStrip, .count = 4}, st), list);
}

TEST(Draw, PrimitiveRestart) {
  const int W = 32, H = 32;
  std::vector<TestVertex> v = {wv(2, 2, 0, W, H),   wv(14, 2, 0, W, H),  wv(2, 14, 0, W, H),
                               wv(14, 14, 0, W, H), wv(18, 18, 0, W, H), wv(30, 18, 0, W, H),
                               wv(18, 30, 0, W, H), wv(30, 30, 0, W, H)};
  const uint16_t idx[] = {0, 1, 2, 3, 0xFFFF, 4, 5, 6, 7};
  const Buffer ib(idx, sizeof idx);
  RenderState st;
  st.primitive_restart = true;
  const auto got = render(
      W, H, v,
      {.topology = Topology::TriangleStrip, .count = 9, .index_buffer = &ib, .index_type = IndexType::U16},
      st);
  const auto want =
      render(W, H, {v[0], v[1], v[2], v[2], v[1], v[3], v[4], v[5], v[6], v[6], v[5], v[7]}, {.count = 12});
  EXPECT_EQ(got, want);
  // Without restart, 0xFFFF is an index past the buffer: an error, nothing drawn.
  Target t(W, H);
  Context ctx(1);
  ctx.bind_framebuffer(&t.fb);
  Mesh m(v);
  EXPECT_THROW(ctx.draw(ColorShader{}, {}, m.layout, RenderState{},
                        {.topology = Topology::TriangleStrip,
                         .count = 9,
                         .index_buffer = &ib,
                         .index_type = IndexType::U16}),
               Error);
}

TEST(Draw, InstancingWithDivisor) {
  const int W = 32, H = 32;
  Target t(W, H);
  Context ctx(2);
  ctx.bind_framebuffer(&t.fb);
  ctx.clear({.color = {0, 0, 0, 0}});
  Mesh m({wv(0, 0, 0, W, H), wv(8, 0, 0, W, H), wv(0, 8, 0, W, H)});
  const float offsets[] = {0.0f, 0.0f, 0.2f, 1.0f, 0.0f, 0.6f, 0.0f, 1.0f, 1.0f};  // ndc offsets: 16 px
  const Buffer inst(offsets, sizeof offsets);
  VertexLayout layout = m.layout;
  layout.attrib(3, inst, 3, AttribType::F32, 12, 0, false, 1);
  ctx.draw(Offsets{}, {}, layout, RenderState{}, {.count = 3, .instance_count = 3});
  ctx.finish();
  const auto p = read_rgba8(t.color);
  auto at = [&](int x, int y) { return &p[(size_t(y) * W + x) * 4]; };
  EXPECT_EQ(at(1, 1)[0], 51);    // instance 0: red 0.2
  EXPECT_EQ(at(17, 1)[0], 153);  // instance 1 at +16 x: red 0.6
  EXPECT_EQ(at(17, 1)[2], 64);   // gl_InstanceID 1 -> blue 0.25
  EXPECT_EQ(at(1, 17)[0], 255);  // instance 2 at +16 y
  EXPECT_EQ(at(1, 17)[2], 128);
  // Past the instance buffer: 4 instances need 4 elements, the buffer has 3.
  EXPECT_THROW(ctx.draw(Offsets{}, {}, layout, RenderState{}, {.count = 3, .instance_count = 4}), Error);
}

TEST(Draw, FlatTakesTheProvokingVertex) {
  const int W = 16, H = 16;
  const std::vector<TestVertex> v = {wv(0, 0, 0, W, H, {1, 0, 0, 1}), wv(16, 0, 0, W, H, {0, 1, 0, 1}),
                                     wv(0, 16, 0, W, H, {0, 0, 1, 1})};
  const auto p = render(W, H, v, {.count = 3}, RenderState{}, 1, true);
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(p[(1 * W + 1) * 4 + i], i == 2 || i == 3 ? 255 : 0);  // last vertex: blue
  // Strip triangle 1 is (v2, v1, v3) in GL order: its provoking vertex is v3.
  const std::vector<TestVertex> s = {wv(0, 0, 0, W, H, {1, 0, 0, 1}), wv(16, 0, 0, W, H, {0, 1, 0, 1}),
                                     wv(0, 16, 0, W, H, {0, 0, 1, 1}), wv(16, 16, 0, W, H, {1, 1, 0, 1})};
  const auto q = render(W, H, s, {.topology = Topology::TriangleStrip, .count = 4}, RenderState{}, 1, true);
  EXPECT_EQ(q[(14 * W + 14) * 4 + 0], 255);
  EXPECT_EQ(q[(14 * W + 14) * 4 + 1], 255);
}

TEST(Draw, PerspectiveCorrectCheckerboard) {
  // A quad tilted away from the camera, textured with an 8x8 checkerboard (nearest): the
  // checker boundaries must lie where the projection puts them, not where screen-linear
  // interpolation would.
  const int W = 64, H = 64;
  Target t(W, H);
  Context ctx(2);
  ctx.bind_framebuffer(&t.fb);
  ctx.clear({.color = {0, 0, 0, 0}});
  std::vector<uint8_t> checker(8 * 8 * 4);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      for (int k = 0; k < 4; ++k) checker[(y * 8 + x) * 4 + k] = ((x + y) & 1) ? 255 : 0;
  Texture2D tex(Format::RGBA8, 8, 8);
  tex.upload_rgba8(0, checker.data(), checker.size());
  // Eye space: a floor quad from z = -1 (near) to z = -5 (far), x in [-1, 1], y = -0.5,
  // projected with a 90-degree frustum: clip = (x, y, ..., -z).
  auto v = [&](float x, float z, float s, float tt) {
    TestVertex r{};
    r.pos[0] = x;
    r.pos[1] = -0.5f;
    r.pos[2] = 0.0f;
    r.pos[3] = -z;
    r.color[0] = r.color[1] = r.color[2] = r.color[3] = 1.0f;
    r.uv[0] = s;
    r.uv[1] = tt;
    return r;
  };
  Mesh m({v(-1, -1, 0, 0), v(1, -1, 1, 0), v(1, -5, 1, 1), v(-1, -1, 0, 0), v(1, -5, 1, 1), v(-1, -5, 0, 1)});
  TexturedShader::Uniforms u;
  u.tex = {&tex, {.min_filter = Filter::Nearest, .mag_filter = Filter::Nearest}};
  ctx.draw(TexturedShader{}, u, m.layout, RenderState{}, {.count = 6});
  ctx.finish();
  const auto p = read_rgba8(t.color);
  // For each row, the expected texel from the exact inverse projection: window y -> eye z.
  int checked = 0;
  for (int y = 0; y < H; ++y) {
    const float yn = (y + 0.5f) / H * 2.0f - 1.0f;  // ndc y = -0.5 / -z
    const float z = 0.5f / yn;                      // eye z (negative below the horizon)
    if (!(z <= -1.0f && z >= -5.0f)) continue;
    const float tcoord = (-z - 1.0f) / 4.0f;
    for (int x = 0; x < W; ++x) {
      const float xn = (x + 0.5f) / W * 2.0f - 1.0f;
      const float ex = xn * -z;
      if (ex < -1.0f || ex > 1.0f) continue;
      const float s = (ex + 1.0f) / 2.0f;
      const float fs = s * 8.0f, ft = tcoord * 8.0f;
      // Skip samples within 5% of a texel of a boundary (float rounding may go either way);
      // screen-linear interpolation is off by up to half a texel here, so it still fails.
      if (std::fabs(fs - std::round(fs)) < 0.05f || std::fabs(ft - std::round(ft)) < 0.05f) continue;
      const int want = ((int(fs) + int(ft)) & 1) ? 255 : 0;
      ASSERT_EQ(p[(size_t(y) * W + x) * 4], want) << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);
}

TEST(Draw, LinesAndPoints) {
  const int W = 16, H = 16;
  // A horizontal line from x = 2.5 to 12.5 at y = 5.5: pixels 2..11 (the last excluded).
  auto line = render(W, H, {wv(2.5f, 5.5f, 0, W, H), wv(12.5f, 5.5f, 0, W, H)},
                     {.topology = Topology::Lines, .count = 2});
  for (int x = 0; x < W; ++x) EXPECT_EQ(line[(5 * W + x) * 4 + 3], x >= 2 && x < 12 ? 255 : 0) << x;
  EXPECT_EQ(lit(line), 10u);
  // The same line drawn backwards covers 3..12 (diamond exit: the start is kept).
  auto back = render(W, H, {wv(12.5f, 5.5f, 0, W, H), wv(2.5f, 5.5f, 0, W, H)},
                     {.topology = Topology::Lines, .count = 2});
  EXPECT_EQ(lit(back), 10u);
  EXPECT_EQ(back[(5 * W + 12) * 4 + 3], 255);
  // A wide line: 3 pixels tall.
  RenderState st;
  st.line_width = 3.0f;
  auto wide = render(W, H, {wv(2.5f, 5.5f, 0, W, H), wv(12.5f, 5.5f, 0, W, H)},
                     {.topology = Topology::Lines, .count = 2}, st);
  EXPECT_EQ(lit(wide), 30u);
  // A diagonal line lights one pixel per column.
  auto diag = render(W, H, {wv(1.5f, 1.2f, 0, W, H), wv(14.5f, 10.3f, 0, W, H)},
                     {.topology = Topology::Lines, .count = 2});
  EXPECT_EQ(lit(diag), 13u);
  // Points: size 1 one pixel, size 4 a 4x4 square.
  auto pt = render(W, H, {wv(4.5f, 4.5f, 0, W, H)}, {.topology = Topology::Points, .count = 1});
  EXPECT_EQ(lit(pt), 1u);
  EXPECT_EQ(pt[(4 * W + 4) * 4 + 3], 255);
  st = RenderState{};
  st.point_size = 4.0f;
  auto big = render(W, H, {wv(8.0f, 8.0f, 0, W, H)}, {.topology = Topology::Points, .count = 1}, st);
  EXPECT_EQ(lit(big), 16u);
  // Line strip and loop: a square outline.
  const std::vector<TestVertex> sq = {wv(2.5f, 2.5f, 0, W, H), wv(12.5f, 2.5f, 0, W, H),
                                      wv(12.5f, 12.5f, 0, W, H), wv(2.5f, 12.5f, 0, W, H)};
  EXPECT_EQ(lit(render(W, H, sq, {.topology = Topology::LineStrip, .count = 4})), 30u);
  EXPECT_EQ(lit(render(W, H, sq, {.topology = Topology::LineLoop, .count = 4})), 40u);
}

TEST(Draw, PolygonModes) {
  const int W = 16, H = 16;
  const std::vector<TestVertex> tri = {wv(2.5f, 2.5f, 0, W, H), wv(12.5f, 2.5f, 0, W, H),
                                       wv(2.5f, 12.5f, 0, W, H)};
  RenderState st;
  st.polygon_mode = PolygonMode::Point;
  EXPECT_EQ(lit(render(W, H, tri, {.count = 3}, st)), 3u);
  st.polygon_mode = PolygonMode::Line;
  const auto lines = render(W, H, tri, {.count = 3}, st);
  EXPECT_GE(lit(lines), 28u);
  EXPECT_EQ(lines[(5 * W + 5) * 4 + 3], 0);  // the inside stays empty
  st.cull = CullMode::Front;                 // counter-clockwise is front: culled
  EXPECT_EQ(lit(render(W, H, tri, {.count = 3}, st)), 0u);
}

TEST(Draw, SameImageForAnyThreadCount) {
  const int W = 200, H = 150;
  std::vector<TestVertex> v;
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 3000 * 3; ++i)
    v.push_back(wv(u(rng) * W, u(rng) * H, u(rng) * 2 - 1, W, H, {u(rng), u(rng), u(rng), 0.5f}));
  RenderState st;
  st.depth_test = true;
  st.blend[0] = {.enabled = true, .src_rgb = BlendFactor::SrcAlpha, .dst_rgb = BlendFactor::OneMinusSrcAlpha};
  const auto one = render(W, H, v, {.count = uint32_t(v.size())}, st, 1);
  EXPECT_EQ(render(W, H, v, {.count = uint32_t(v.size())}, st, 2), one);
  EXPECT_EQ(render(W, H, v, {.count = uint32_t(v.size())}, st, 3), one);
  EXPECT_EQ(render(W, H, v, {.count = uint32_t(v.size())}, st, 8), one);
}

TEST(Draw, MipmapLevelFromQuadDerivatives) {
  // A 64x64 texture whose levels are solid, distinct colours, drawn on a 16x16 target so
  // that one pixel steps 4 texels (LOD 2) and, scaled 2x, 8 texels (LOD 3).
  Texture2D tex(Format::RGBA8, 64, 64, 0);
  const glm::vec4 level_colors[] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 0, 1},
                                    {0, 1, 1, 1}, {1, 0, 1, 1}, {1, 1, 1, 1}};
  for (int l = 0; l < tex.levels(); ++l)
    for (int y = 0; y < tex.height(l); ++y)
      for (int x = 0; x < tex.width(l); ++x) tex.store(l, x, y, level_colors[l]);
  for (float repeat : {1.0f, 2.0f}) {
    const int W = 16, H = 16;
    Target t(W, H);
    Context ctx(2);
    ctx.bind_framebuffer(&t.fb);
    ctx.clear({.color = {0, 0, 0, 0}});
    auto v = [&](float x, float y) {
      TestVertex r = wv(x, y, 0, W, H);
      r.uv[0] = x / W * repeat;
      r.uv[1] = y / H * repeat;
      return r;
    };
    Mesh m({v(0, 0), v(16, 0), v(16, 16), v(0, 0), v(16, 16), v(0, 16)});
    TexturedShader::Uniforms u;
    u.tex = {&tex, {.min_filter = Filter::NearestMipmapNearest, .mag_filter = Filter::Nearest}};
    ctx.draw(TexturedShader{}, u, m.layout, RenderState{}, {.count = 6});
    ctx.finish();
    const glm::vec4 want = level_colors[repeat == 1.0f ? 2 : 3];
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        ASSERT_EQ(t.color.fetch(0, x, y), want) << x << "," << y << " repeat " << repeat;
  }
}

// --- behaviours the GL 1.x layer relies on ---------------------------------------------------

// Fragments stay inside the viewport rectangle even where the guard band keeps a primitive
// unclipped (GL 4.6 §13.7): a triangle far larger than a small viewport fills exactly it.
TEST(Draw, ViewportBoundsFragments) {
  RenderState st;
  st.viewport = {8, 4, 10, 6};
  const glm::vec4 red(1, 0, 0, 1);
  // In clip space, reaching far outside [-1, 1] (inside the guard band).
  std::vector<TestVertex> v(3);
  const float P[3][2] = {{-5, -5}, {9, -5}, {-5, 9}};
  for (int i = 0; i < 3; ++i) {
    v[size_t(i)] = TestVertex{{P[i][0], P[i][1], 0, 1}, {red.r, red.g, red.b, red.a}, {0, 0}};
  }
  const auto p = render(32, 16, v, {.count = 3}, st);
  EXPECT_EQ(lit(p), size_t(10 * 6));
  EXPECT_NE(px(p, 32, 8, 4), 0u);
  EXPECT_NE(px(p, 32, 17, 9), 0u);
  EXPECT_EQ(px(p, 32, 7, 4), 0u);
  EXPECT_EQ(px(p, 32, 18, 9), 0u);
}

// A line drawn A->B and then B->A with GL_LESS: the second finds the same depths and loses
// everywhere (llvmpipe behaves the same), so a shared edge keeps its first colour.
TEST(Draw, ReversedLineHasTheSameDepth) {
  Target t(48, 48);
  Context ctx(2);
  ctx.bind_framebuffer(&t.fb);
  ctx.clear({.color = {0, 0, 0, 0}, .depth = 1.0f});
  RenderState st;
  st.depth_test = true;
  const TestVertex a = wv(3.3f, 5.1f, 0.2f, 48, 48, {1, 0, 0, 1}),
                   b = wv(44.7f, 31.9f, 0.7f, 48, 48, {1, 0, 0, 1});
  TestVertex a2 = a, b2 = b;
  a2.color[0] = b2.color[0] = 0.0f;
  a2.color[1] = b2.color[1] = 1.0f;
  Mesh m({a, b, b2, a2});
  ctx.draw(ColorShader{}, {}, m.layout, st, {.topology = Topology::Lines, .count = 4});
  ctx.finish();
  const auto p = read_rgba8(t.color);
  size_t red = 0, green = 0;
  for (size_t i = 0; i < p.size(); i += 4) red += p[i] == 255, green += p[i + 1] == 255;
  EXPECT_GT(red, 35u);
  EXPECT_LE(green, 1u);  // only the pixel of B, which the diamond-exit rule gives the second line
}

// Polygon mode per face (glPolygonMode(GL_FRONT, ...) and (GL_BACK, ...)): a front-facing
// triangle filled, a back-facing one outlined.
TEST(Draw, PolygonModePerFace) {
  RenderState st;
  st.polygon_mode = PolygonMode::Fill;
  st.polygon_mode_per_face = true;
  st.polygon_mode_back = PolygonMode::Line;
  const glm::vec4 c(1, 1, 1, 1);
  // Left triangle counter-clockwise (front), right one clockwise (back).
  const auto p =
      render(64, 32,
             {wv(2, 2, 0, 64, 32, c), wv(30, 2, 0, 64, 32, c), wv(2, 30, 0, 64, 32, c),
              wv(34.5f, 2.5f, 0, 64, 32, c), wv(34.5f, 29.5f, 0, 64, 32, c), wv(61.5f, 2.5f, 0, 64, 32, c)},
             {.count = 6}, st);
  EXPECT_NE(px(p, 64, 8, 8), 0u);    // inside the front one: filled
  EXPECT_EQ(px(p, 64, 40, 8), 0u);   // inside the back one: empty
  EXPECT_NE(px(p, 64, 34, 16), 0u);  // on the back one's left edge: drawn
}

namespace {
// The colour and, in varying component 4, a GL edge flag taken from the colour's alpha.
struct EdgeFlagShader {
  struct Uniforms {};
  template <class F>
  struct Varyings {
    Vec4<F> color;
    F edge;
  };
  static constexpr uint32_t attributes = 0b11;
  template <class F>
  Vec4<F> vertex(const Uniforms&, const VertexIn<F>& in, Varyings<F>& out) const {
    out.color = Vec4<F>(in.attr[1].x, in.attr[1].y, in.attr[1].z, F(1.0f));
    out.edge = in.attr[1].w;
    return in.attr[0];
  }
  template <class F>
  void fragment(const Uniforms&, const Varyings<F>& v, Fragment<F>& f) const {
    f.color[0] = v.color;
  }
};
}  // namespace

// Edge flags: in line mode only the edges whose starting vertex is flagged are drawn (the
// inner diagonal of a decomposed quad is not).
TEST(Draw, EdgeFlagsHideInnerEdges) {
  Target t(32, 32);
  Context ctx(1);
  ctx.bind_framebuffer(&t.fb);
  ctx.clear({.color = {0, 0, 0, 0}});
  RenderState st;
  st.polygon_mode = PolygonMode::Line;
  st.edge_flag_varying = 4;
  // Triangle (a, b, c): edges a->b and b->c flagged, c->a (the diagonal) not.
  TestVertex a = wv(4.5f, 4.5f, 0, 32, 32, {1, 1, 1, 1}), b = wv(28.5f, 4.5f, 0, 32, 32, {1, 1, 1, 1}),
             c = wv(28.5f, 28.5f, 0, 32, 32, {1, 1, 1, 0});
  Mesh m({a, b, c});
  ctx.draw(EdgeFlagShader{}, {}, m.layout, st, {.count = 3});
  ctx.finish();
  const auto p = read_rgba8(t.color);
  EXPECT_NE(px(p, 32, 16, 4), 0u);   // a->b
  EXPECT_NE(px(p, 32, 28, 16), 0u);  // b->c
  EXPECT_EQ(px(p, 32, 16, 16), 0u);  // the diagonal c->a is not drawn
}
