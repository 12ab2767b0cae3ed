// Rasterization rules: the fill rule on shared edges, coverage against an independent
// point-in-triangle test, and the bounding-box edges.
#include <gtest/gtest.h>

#include <random>

#include "setup_triangle.hpp"
#include "shaders.hpp"
#include "stages.hpp"

using namespace tessel::test;
using namespace tessel::gpu::detail;

namespace {

// Draws the triangles additively into a float target: each pixel counts its coverage.
std::vector<float> coverage_count(int W, int H, const std::vector<TestVertex>& v,
                                  Topology topo = Topology::Triangles, int threads = 2) {
  Texture2D color(Format::RGBA32F, W, H);
  Framebuffer fb(&color);
  Context ctx(threads);
  ctx.bind_framebuffer(&fb);
  ctx.clear({.color = {0, 0, 0, 0}});
  RenderState st;
  st.blend[0] = {.enabled = true,
                 .src_rgb = BlendFactor::One,
                 .dst_rgb = BlendFactor::One,
                 .src_alpha = BlendFactor::One,
                 .dst_alpha = BlendFactor::One};
  Mesh m(v);
  ctx.draw(ColorShader{}, {}, m.layout, st, {.topology = topo, .count = m.count});
  ctx.finish();
  std::vector<float> out(size_t(W) * H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) out[size_t(y) * W + x] = color.fetch(0, x, y).r;
  return out;
}

TestVertex at(float x, float y, int W, int H) {
  TestVertex v{};
  clip_from_window(x, y, 0.0f, 1.0f, W, H, v.pos);
  v.color[0] = 1.0f;
  v.color[3] = 1.0f;
  return v;
}

// A jittered grid of vertices (border vertices outside the target), triangulated with
// random diagonals: every pixel centre must be covered exactly once.
void expect_watertight(const std::vector<float>& count, int W, int H, const char* what) {
  int zero = 0, twice = 0;
  for (float c : count) {
    if (c == 0.0f) ++zero;
    if (c > 1.0f) ++twice;
  }
  EXPECT_EQ(zero, 0) << what << ": pixels never covered";
  EXPECT_EQ(twice, 0) << what << ": pixels covered twice";
  (void)W;
  (void)H;
}

}  // namespace

TEST(FillRule, JitteredGridCoversEveryPixelOnce) {
  const int W = 160, H = 120, N = 20;
  std::mt19937 rng(5);
  // Up to a quarter cell: every grid quad stays convex, so either diagonal is valid.
  std::uniform_real_distribution<float> jitter(-0.24f, 0.24f);
  std::bernoulli_distribution flip(0.5);
  for (int round = 0; round < 4; ++round) {
    // Grid of (N+1)^2 points spanning beyond the target.
    std::vector<glm::vec2> g((N + 1) * (N + 1));
    const float cw = (W + 8.0f) / N, ch = (H + 8.0f) / N;
    for (int j = 0; j <= N; ++j)
      for (int i = 0; i <= N; ++i) {
        const bool border = i == 0 || j == 0 || i == N || j == N;
        // Positions on the 1/256 lattice and off it, some exactly on pixel centres.
        float x = -4.0f + i * cw + (border ? 0.0f : jitter(rng) * cw);
        float y = -4.0f + j * ch + (border ? 0.0f : jitter(rng) * ch);
        if (round == 1) {
          x = std::round(x) + 0.5f;
          y = std::round(y) + 0.5f;
        }  // on centres
        if (round == 2) {
          x = std::round(x * 2.0f) / 2.0f;
          y = std::round(y);
        }  // on edges
        g[size_t(j) * (N + 1) + i] = {x, y};
      }
    std::vector<TestVertex> v;
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i) {
        const glm::vec2 a = g[size_t(j) * (N + 1) + i], b = g[size_t(j) * (N + 1) + i + 1];
        const glm::vec2 c = g[size_t(j + 1) * (N + 1) + i + 1], d = g[size_t(j + 1) * (N + 1) + i];
        const bool cw_order = flip(rng);  // mixed windings: the rule must not depend on it
        auto tri = [&](glm::vec2 p, glm::vec2 q, glm::vec2 r) {
          if (cw_order) std::swap(q, r);
          v.push_back(at(p.x, p.y, W, H));
          v.push_back(at(q.x, q.y, W, H));
          v.push_back(at(r.x, r.y, W, H));
        };
        if (flip(rng)) {
          tri(a, b, c);
          tri(a, c, d);
        } else {
          tri(a, b, d);
          tri(b, c, d);
        }
      }
    expect_watertight(coverage_count(W, H, v), W, H, "grid");
  }
}

TEST(FillRule, FansAndStripsCoverEveryPixelOnce) {
  const int W = 128, H = 128;
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int round = 0; round < 8; ++round) {
    // A fan around a random centre, its rim far outside the target.
    std::vector<TestVertex> fan;
    const float cx = 20.0f + 88.0f * u(rng), cy = 20.0f + 88.0f * u(rng);
    fan.push_back(at(cx, cy, W, H));
    const int n = 7 + round * 5;
    for (int k = 0; k <= n; ++k) {
      const float a = 6.2831853f * (float(k) + (k == n || k == 0 ? 0.0f : 0.6f * u(rng) - 0.3f)) / float(n);
      fan.push_back(at(cx + 400.0f * std::cos(a), cy + 400.0f * std::sin(a), W, H));
    }
    expect_watertight(coverage_count(W, H, fan, Topology::TriangleFan), W, H, "fan");

    // A strip zig-zagging across the target in columns of random width.
    std::vector<TestVertex> strip;
    float x = -3.0f;
    while (x < W + 3.0f) {
      strip.push_back(at(x, -3.0f + u(rng) * 0.0f, W, H));
      strip.push_back(at(x, H + 3.0f, W, H));
      x += 0.3f + 7.0f * u(rng);
    }
    strip.push_back(at(x, -3.0f, W, H));
    strip.push_back(at(x, H + 3.0f, W, H));
    expect_watertight(coverage_count(W, H, strip, Topology::TriangleStrip), W, H, "strip");
  }
}

// Thousands of random pairs sharing an edge: on the shared edge no sample is covered twice,
// and the union covers exactly the quad's samples.
TEST(FillRule, RandomPairsSharingAnEdge) {
  const int W = 64, H = 64;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-8.0f, 72.0f);
  int cases = 0;
  for (int batch = 0; batch < 40; ++batch) {
    // 100 pairs per batch, each drawn additively; a pixel covered twice shows as 2 only when
    // the same pair covers it twice or two pairs overlap, so draw each batch pair-by-pair
    // into separate counts.
    for (int i = 0; i < 25; ++i, ++cases) {
      glm::vec2 a(u(rng), u(rng)), b(u(rng), u(rng)), c(u(rng), u(rng)), d(u(rng), u(rng));
      if (i % 5 == 0) {
        a = glm::round(a * 4.0f) / 4.0f;
        b = glm::round(b);
      }  // on the lattice
      // c and d on opposite sides of the shared edge a-b.
      const auto side = [&](glm::vec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
      if (side(c) * side(d) >= 0.0f) d = a + b - c;  // mirror c through the edge's midpoint
      if (side(c) * side(d) >= 0.0f) continue;
      const std::vector<TestVertex> v = {at(a.x, a.y, W, H), at(b.x, b.y, W, H), at(c.x, c.y, W, H),
                                         at(b.x, b.y, W, H), at(a.x, a.y, W, H), at(d.x, d.y, W, H)};
      const auto count = coverage_count(W, H, v, Topology::Triangles, 1);
      for (float k : count) ASSERT_LE(k, 1.0f) << "case " << cases << ": a sample covered twice";
      // Whatever the two cover together is what one quad would (when it is convex).
      const std::vector<TestVertex> t1 = {v[0], v[1], v[2]}, t2 = {v[3], v[4], v[5]};
      const auto c1 = coverage_count(W, H, t1, Topology::Triangles, 1);
      const auto c2 = coverage_count(W, H, t2, Topology::Triangles, 1);
      for (size_t p = 0; p < count.size(); ++p) ASSERT_EQ(count[p], c1[p] + c2[p]);
    }
  }
  EXPECT_GE(cases, 900);
}

// An independent statement of the rule, in doubles on the snapped positions: sample (i, j)
// is covered when it is strictly inside, or on an edge that owns it.
TEST(Coverage, MatchesIndependentEdgeTest) {
  const int W = 48, H = 48;
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> u(-10.0f, 58.0f);
  for (int t = 0; t < 300; ++t) {
    glm::vec2 p[3] = {{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}};
    if (t % 3 == 0)
      for (auto& q : p) q = glm::round(q * 2.0f) / 2.0f;  // many samples exactly on edges
    const std::vector<TestVertex> v = {at(p[0].x, p[0].y, W, H), at(p[1].x, p[1].y, W, H),
                                       at(p[2].x, p[2].y, W, H)};
    const auto count = coverage_count(W, H, v, Topology::Triangles, 1);
    // Snapped positions, exactly as the pipeline computes window coordinates.
    double X[3], Y[3];
    for (int k = 0; k < 3; ++k) {
      const float wx = v[k].pos[0] / v[k].pos[3] * (W * 0.5f) + W * 0.5f;
      const float wy = v[k].pos[1] / v[k].pos[3] * (H * 0.5f) + H * 0.5f;
      X[k] = std::nearbyint((wx - 0.5f) * 256.0f) / 256.0;
      Y[k] = std::nearbyint((wy - 0.5f) * 256.0f) / 256.0;
    }
    const double area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
    for (int j = 0; j < H; ++j)
      for (int i = 0; i < W; ++i) {
        bool inside = area != 0.0;
        for (int e = 0; e < 3 && inside; ++e) {
          int a = e, b = (e + 1) % 3;
          if (area < 0) std::swap(a, b);  // walk counter-clockwise
          const double dx = X[b] - X[a], dy = Y[b] - Y[a];
          const double E = dx * (j - Y[a]) - dy * (i - X[a]);
          const bool owns = dy < 0 || (dy == 0 && dx > 0);
          inside = E > 0 || (E == 0 && owns);
        }
        ASSERT_EQ(count[size_t(j) * W + i], inside ? 1.0f : 0.0f)
            << "triangle " << t << " pixel " << i << "," << j;
      }
  }
}

// The raster phase shades the 4x2 groups of consecutive triangles of one draw two at a
// time; where two such groups cover the same pixels, the older must be blended first. Tiny
// triangles piled on a few pixels with non-commutative blending, as one draw and as one draw
// each (never paired): the same bits.
TEST(Order, OverlappingTinyTrianglesOfOneDrawBlendInOrder) {
  const int W = 70, H = 20;  // across the tile edge at x = 64
  std::mt19937 rng(77);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<TestVertex> v;
  for (int t = 0; t < 600; ++t) {
    const float cx = 56.0f + 12.0f * u(rng), cy = 4.0f + 10.0f * u(rng);
    const float col[4] = {u(rng), u(rng), u(rng), 0.2f + 0.6f * u(rng)};
    for (int k = 0; k < 3; ++k) {
      TestVertex a = at(cx + 5.0f * u(rng) - 2.5f, cy + 5.0f * u(rng) - 2.5f, W, H);
      std::copy_n(col, 4, a.color);
      v.push_back(a);
    }
  }
  RenderState st;
  st.blend[0] = {.enabled = true,
                 .src_rgb = BlendFactor::SrcAlpha,
                 .dst_rgb = BlendFactor::OneMinusSrcAlpha,
                 .src_alpha = BlendFactor::One,
                 .dst_alpha = BlendFactor::OneMinusSrcAlpha};
  auto render = [&](bool one_draw, int threads) {
    Texture2D color(Format::RGBA32F, W, H);
    Framebuffer fb(&color);
    Context ctx(threads);
    ctx.bind_framebuffer(&fb);
    ctx.clear({.color = {0, 0, 0, 0}});
    Mesh m(v);
    if (one_draw) {
      ctx.draw(ColorShader{}, {}, m.layout, st, {.topology = Topology::Triangles, .count = m.count});
    } else {
      for (uint32_t i = 0; i < m.count; i += 3)
        ctx.draw(ColorShader{}, {}, m.layout, st, {.topology = Topology::Triangles, .first = i, .count = 3});
    }
    ctx.finish();
    std::vector<float> out;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const glm::vec4 c = color.fetch(0, x, y);
        out.insert(out.end(), {c.r, c.g, c.b, c.a});
      }
    return out;
  };
  const auto separate = render(false, 1);
  EXPECT_EQ(render(true, 1), separate);
  EXPECT_EQ(render(true, 2), separate);
}

namespace {

// Colour from every fragment input: varyings, gl_FragCoord, gl_PrimitiveID, gl_FrontFacing.
// With Packed the shader says its lanes are independent, so the raster phase packs the
// covered pixels of several groups and triangles into one call.
template <bool Packed>
struct FragmentInputsShader : ColorShader {
  static constexpr bool lanes_independent = Packed;
  template <class F>
  void fragment(const Uniforms&, const Varyings<F>& v, Fragment<F>& f) const {
    const F id = to_float(f.primitive_id & IntOf<F>(7)) * F(1.0f / 7.0f);
    const F fx = f.coord.x * F(0.37f) + f.coord.y * F(0.11f) + v.color.x;
    f.color[0] = Vec4<F>(fx - floor(fx), mix(id, v.color.y, F(0.5f)),
                         select(f.front_facing, v.color.z, F(1.0f) - v.color.z),
                         f.coord.z * F(0.5f) + f.coord.w * F(0.5f));
  }
};

}  // namespace

// Packed shading (shader.hpp's lanes_independent) must give what shading by 4x2 groups
// gives, bit for bit: overlapping tiny, small and large triangles of both facings at random
// depths across a tile edge, with and without the depth test (without it, the last
// fragment on a pixel must win, so colour writes must keep their order), on 1 and 2 threads.
TEST(Packed, IndependentLanesGiveWhatQuadsGive) {
  const int W = 80, H = 40;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<TestVertex> v;
  for (int t = 0; t < 900; ++t) {
    const float cx = 54.0f + 20.0f * u(rng), cy = 10.0f + 16.0f * u(rng),
                size = t % 9 == 0   ? 30.0f
                       : t % 3 == 0 ? 11.0f
                                    : 4.0f;
    const float col[4] = {u(rng), u(rng), u(rng), 1.0f};
    for (int k = 0; k < 3; ++k) {
      TestVertex a{};
      const float w = 0.5f + 2.0f * u(rng);  // perspective: 1/w differs across the triangle
      clip_from_window(cx + size * (u(rng) - 0.5f), cy + size * (u(rng) - 0.5f), 2.0f * u(rng) - 1.0f, w, W,
                       H, a.pos);
      std::copy_n(col, 4, a.color);
      v.push_back(a);
    }
  }
  auto render = [&](auto shader, bool depth, int threads, std::vector<uint8_t>& pixels,
                    std::vector<float>& depths) {
    Texture2D color(Format::RGBA8, W, H), z(Format::Depth32F, W, H);
    Framebuffer fb(&color, &z);
    Context ctx(threads);
    ctx.bind_framebuffer(&fb);
    ctx.clear({.color = {0.1f, 0.2f, 0.3f, 0.4f}, .depth = 1.0f});
    RenderState st;
    st.depth_test = depth;
    Mesh m(v);
    ctx.draw(shader, {}, m.layout, st, {.topology = Topology::Triangles, .count = m.count});
    ctx.finish();
    pixels.clear();
    depths.clear();
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const glm::vec4 c = color.fetch(0, x, y);
        for (int k = 0; k < 4; ++k) pixels.push_back(uint8_t(std::lround(c[k] * 255.0f)));
        depths.push_back(z.fetch(0, x, y).r);
      }
    return ctx.stats();
  };
  for (bool depth : {true, false}) {
    std::vector<uint8_t> quads, packed;
    std::vector<float> quads_z, packed_z;
    const Stats a = render(FragmentInputsShader<false>{}, depth, 1, quads, quads_z);
    for (int threads : {1, 2}) {
      const Stats b = render(FragmentInputsShader<true>{}, depth, threads, packed, packed_z);
      EXPECT_EQ(packed, quads) << "depth test " << depth << ", " << threads << " threads";
      EXPECT_EQ(packed_z, quads_z);
      EXPECT_EQ(b.fragments_shaded, a.fragments_shaded);
      EXPECT_EQ(b.fragments_written, a.fragments_written);
      EXPECT_EQ(b.fragments_rejected, a.fragments_rejected);
    }
    EXPECT_GT(a.fragments_written, 1200u);
    if (depth) {
      EXPECT_GT(a.fragments_rejected, 500u);
    }
  }
}

// Setup's cover of a small triangle (small_coverage) against the edge functions evaluated
// pixel by pixel, for every bbox shape that fits the 8x8 window (one to eight rows, one to
// eight columns, each alignment) and random edges.
TEST(Setup, SmallCoverageIsTheEdgeTestAtEachPixelOfTheBbox) {
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> coord(-12 * kSubpixelOne, 20 * kSubpixelOne);
  int tested = 0, tall = 0;
  for (int t = 0; t < 20000; ++t) {
    int64_t X[3], Y[3];
    for (int k = 0; k < 3; ++k) {
      X[k] = coord(rng);
      Y[k] = coord(rng);
    }
    if ((X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]) <= 0)
      std::swap(X[1], X[2]), std::swap(Y[1], Y[2]);
    EdgeEq e[3];
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const int64_t dx = X[j] - X[i], dy = Y[j] - Y[i];
      e[i] = {dy * X[i] - dx * Y[i] + ((dy < 0 || (dy == 0 && dx > 0)) ? 1 : 0), -dy * kSubpixelOne,
              dx * kSubpixelOne};
    }
    if (!small_edges(e)) continue;
    // Any bbox inside the window from an aligned origin.
    const int gx0 = 4 * int(rng() % 3), gy0 = 2 * int(rng() % 5);
    const int minx = gx0 + int(rng() % 4), miny = gy0 + int(rng() % 2);
    const int maxx = minx + int(rng() % unsigned(gx0 + 8 - minx)),
              maxy = miny + int(rng() % unsigned(gy0 + 8 - miny));
    const uint64_t cover = small_coverage(e, minx, miny, maxx, maxy);
    for (int y = gy0; y < gy0 + 8; ++y)
      for (int x = gx0; x < gx0 + 8; ++x) {
        const int ox = x - gx0, oy = y - gy0;
        const int lane = (ox & 1) + 2 * (oy & 1) + 4 * ((ox >> 1) & 1);
        const int group = (oy >> 1) * 2 + (ox >> 2);
        bool inside = x >= minx && x <= maxx && y >= miny && y <= maxy;
        for (const EdgeEq& q : e) inside = inside && q.c + q.a * x + q.b * y > 0;
        ASSERT_EQ(((cover >> (8 * group + lane)) & 1) != 0, inside)
            << "case " << t << " pixel " << x << "," << y;
      }
    ++tested;
    if (maxy >= gy0 + 4) ++tall;
  }
  EXPECT_GT(tested, 5000);
  EXPECT_GT(tall, 1000);
}

TEST(Setup, SnapsToEighthBitSubpixelsAndCullsZeroArea) {
  DrawRecord d;
  ColorShader s;
  d.program = std::make_unique<Program<ColorShader>>(s, ColorShader::Uniforms{});
  d.area_x0 = d.area_y0 = 0;
  d.area_x1 = d.area_y1 = 64;
  Arena arena;
  Counters c;
  const float var[4] = {0, 0, 0, 0};
  // Two vertices 1/1024 pixel apart snap to the same point: zero area, dropped.
  auto vert = [&](float x, float y) {
    WinVert v{};
    v.x = x;
    v.y = y;
    v.oow = 1.0f;
    v.var = var;
    snap_vertex(v);
    return v;
  };
  const WinVert a = vert(10.0f, 10.0f), b = vert(20.0f, 10.0f), e = vert(10.0f + 1.0f / 1024.0f, 10.0f);
  EXPECT_EQ(setup_triangle(d, a, b, e, var, 0, Facing::FromArea, false, arena, c, nullptr), nullptr);
  // Counter-clockwise is front by default; clockwise culled with CullMode::Back.
  const WinVert t = vert(10.0f, 20.0f);
  Prim* p = setup_triangle(d, a, b, t, var, 0, Facing::FromArea, false, arena, c, nullptr);
  ASSERT_NE(p, nullptr);
  EXPECT_TRUE(p->front);
  d.state.cull = CullMode::Back;
  bool culled = false;
  EXPECT_EQ(setup_triangle(d, a, t, b, var, 0, Facing::FromArea, false, arena, c, &culled), nullptr);
  EXPECT_TRUE(culled);
  d.state.front_face = FrontFace::CW;
  EXPECT_NE(setup_triangle(d, a, t, b, var, 0, Facing::FromArea, false, arena, c, &culled), nullptr);
  // Bounding box: pixel centres in [min, max) of the snapped positions.
  d.state = RenderState{};
  p = setup_triangle(d, a, b, t, var, 0, Facing::FromArea, false, arena, c, nullptr);
  EXPECT_EQ(p->minx, 10);  // centre 10.5 is the first at or right of x = 10 - 0.5... snapped 9.5
  EXPECT_EQ(p->maxx, 19);
  EXPECT_EQ(p->miny, 10);
  EXPECT_EQ(p->maxy, 19);
}
