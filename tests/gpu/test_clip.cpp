// Clipping in homogeneous clip space: the clipper itself, and whole draws crossing the near
// plane or reaching behind the eye (w <= 0), which must render exactly as their clipped parts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "shaders.hpp"
#include "stages.hpp"
#include "tessel/gpu/image.hpp"

using namespace tessel::test;
using namespace tessel::gpu::detail;

namespace {

DrawRecord record_for(int W, int H) {
  DrawRecord d;
  d.program = std::make_unique<Program<ColorShader>>(ColorShader{}, ColorShader::Uniforms{});
  d.vp_scale[0] = W * 0.5f;
  d.vp_scale[1] = H * 0.5f;
  d.vp_offset[0] = W * 0.5f;
  d.vp_offset[1] = H * 0.5f;
  d.guard_x = (kGuardBand - d.vp_offset[0]) / d.vp_scale[0];
  d.guard_y = (kGuardBand - d.vp_offset[1]) / d.vp_scale[1];
  return d;
}

std::vector<uint8_t> draw(int W, int H, const std::vector<TestVertex>& v, Topology t = Topology::Triangles) {
  Target tg(W, H);
  Context ctx(1);
  ctx.bind_framebuffer(&tg.fb);
  ctx.clear({.color = {0, 0, 0, 0}});
  Mesh m(v);
  ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.topology = t, .count = m.count});
  ctx.finish();
  return read_rgba8(tg.color);
}

TestVertex cv(glm::vec4 p, glm::vec4 c) {
  TestVertex v{};
  v.pos[0] = p.x;
  v.pos[1] = p.y;
  v.pos[2] = p.z;
  v.pos[3] = p.w;
  v.color[0] = c.r;
  v.color[1] = c.g;
  v.color[2] = c.b;
  v.color[3] = c.a;
  return v;
}

// The triangle clipped against the near plane z >= -w by hand (inside -> outside lerp, as
// GL's clipping produces it), as a fan of triangles that need no clipping.
std::vector<TestVertex> clip_near_by_hand(const std::vector<TestVertex>& tri) {
  std::vector<TestVertex> poly;
  for (int i = 0; i < 3; ++i) {
    const TestVertex& a = tri[(i + 2) % 3];
    const TestVertex& b = tri[i];
    const float da = a.pos[2] + a.pos[3], db = b.pos[2] + b.pos[3];
    if ((da >= 0) != (db >= 0)) {
      const TestVertex& in = da >= 0 ? a : b;
      const TestVertex& out = da >= 0 ? b : a;
      const float din = da >= 0 ? da : db, dout = da >= 0 ? db : da;
      const float t = din / (din - dout);
      TestVertex r{};
      for (int k = 0; k < 4; ++k) r.pos[k] = in.pos[k] + (out.pos[k] - in.pos[k]) * t;
      for (int k = 0; k < 4; ++k) r.color[k] = in.color[k] + (out.color[k] - in.color[k]) * t;
      poly.push_back(r);
    }
    if (db >= 0) poly.push_back(b);
  }
  std::vector<TestVertex> fan;
  for (size_t i = 1; i + 1 < poly.size(); ++i) {
    fan.push_back(poly[0]);
    fan.push_back(poly[i]);
    fan.push_back(poly[i + 1]);
  }
  return fan;
}

void expect_same_image(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  size_t coverage = 0;
  int maxdiff = 0;
  for (size_t i = 0; i < a.size(); i += 4) {
    if ((a[i + 3] != 0) != (b[i + 3] != 0)) ++coverage;
    for (int k = 0; k < 4; ++k) maxdiff = std::max(maxdiff, std::abs(int(a[i + k]) - int(b[i + k])));
  }
  EXPECT_EQ(coverage, 0u) << "coverage differs";
  EXPECT_LE(maxdiff, 1) << "colours differ";
}

}  // namespace

TEST(Clip, PolygonAgainstNearPlane) {
  DrawRecord d = record_for(64, 64);
  const ClipPlanes planes = make_clip_planes(d);
  ClipVert a[24], b[24];
  a[0].pos = {0, 0, -2, 1};  // behind the near plane (z < -w)
  a[1].pos = {1, 0, 0, 1};
  a[2].pos = {0, 1, 0, 1};
  a[0].var[0] = 0.0f;
  a[1].var[0] = 1.0f;
  a[2].var[0] = 1.0f;
  const unsigned code =
      clip_code(planes, a[0].pos) | clip_code(planes, a[1].pos) | clip_code(planes, a[2].pos);
  ASSERT_NE(code, 0u);
  ClipVert* out;
  const int n = clip_polygon(planes, code, a, 3, b, 1, &out);
  ASSERT_EQ(n, 4);  // a quad
  for (int i = 0; i < n; ++i) {
    EXPECT_GE(out[i].pos.z + out[i].pos.w, -1e-6f);
    EXPECT_GE(out[i].var[0], 0.5f - 1e-6f);  // the cut is halfway from a[0]
  }
}

TEST(Clip, CodesAndTrivialCases) {
  DrawRecord d = record_for(64, 64);
  const ClipPlanes planes = make_clip_planes(d);
  EXPECT_EQ(clip_code(planes, {0, 0, 0, 1}), 0u);
  EXPECT_NE(clip_code(planes, {0, 0, 2, 1}), 0u);     // beyond far
  EXPECT_NE(clip_code(planes, {0, 0, 0, -1}), 0u);    // behind the eye
  EXPECT_NE(clip_code(planes, {NAN, 0, 0, 1}), 0u);   // NaN is outside
  EXPECT_EQ(clip_code(planes, {100, 0, 0, 1}), 0u);   // outside the viewport, inside the guard band
  EXPECT_NE(clip_code(planes, {3000, 0, 0, 1}), 0u);  // beyond the guard band
  float t0, t1;
  // t0 is cut from the first end, t1 from the second (each measured from its own end).
  ASSERT_TRUE(clip_line(planes, ~0u, {0, 0, -3, 1}, {0, 0, 1, 1}, nullptr, nullptr, t0, t1));
  EXPECT_NEAR(t0, 0.5f, 1e-6f);
  EXPECT_EQ(t1, 0.0f);
  ASSERT_TRUE(clip_line(planes, ~0u, {0, 0, 0, 1}, {0, 0, 3, 1}, nullptr, nullptr, t0, t1));
  EXPECT_EQ(t0, 0.0f);
  EXPECT_NEAR(t1, 2.0f / 3.0f, 1e-6f);  // the far plane: the new end is at z = 1
  EXPECT_FALSE(clip_line(planes, ~0u, {0, 0, -3, 1}, {0, 0, -2, 1}, nullptr, nullptr, t0, t1));
}

// The polygon clipper's order is Mesa's (draw_pipe_clip.c): for each edge from vertex 0 on,
// its first vertex when inside, then the crossing point, which is interpolated from the
// outside end; so a clipped polygon starts at its first vertex when that one is inside, and
// the two triangles sharing a cut edge get the same new vertex.
TEST(Clip, PolygonOrderAndSharedEdges) {
  const ClipPlanes planes = ClipPlanes::view_volume();
  const glm::vec4 tri[3] = {{0, 0, 0, 1}, {2, 0, 0, 1}, {0, 0.5f, 0, 1}};  // v1 beyond x = w
  glm::vec4 a[8] = {tri[0], tri[1], tri[2]}, b[8];
  glm::vec4* out = nullptr;
  auto distance = [&](int i, const glm::vec4& v) { return plane_distance(planes, i, v); };
  auto lerp = [](const glm::vec4& from, const glm::vec4& to, float t, glm::vec4& r) {
    r = from + (to - from) * t;
  };
  ASSERT_EQ(clip_polygon(planes.count, ~0u, a, 3, b, 8, distance, lerp, &out), 4);
  const std::vector<glm::vec4> first(out, out + 4);
  EXPECT_EQ(first[0], tri[0]);
  EXPECT_EQ(first[1], glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(first[3], tri[2]);
  // The edge v1-v2 walked the other way (a second triangle v2, v1, v3) is cut at the same point.
  glm::vec4 c[8] = {tri[2], tri[1], {2, 2, 0, 1}}, d[8];
  ASSERT_GT(clip_polygon(planes.count, ~0u, c, 3, d, 8, distance, lerp, &out), 0);
  EXPECT_EQ(out[0], tri[2]);
  EXPECT_EQ(out[1], first[2]);
}

// The geometry phase computes clip codes and window positions eight vertices at a time
// (finish_vertices); they must be the one-vertex functions' bit for bit, NaN, Inf, w <= 0,
// the guard band and a user plane included, for a count that is not a multiple of eight.
TEST(Clip, EightVerticesAtATimeMatchOneAtATime) {
  DrawRecord d = record_for(640, 480);
  d.vp_scale[2] = d.vp_offset[2] = 0.5f;
  d.state.clip_plane_enable = 1;
  d.state.clip_planes[0] = {0.3f, -0.2f, 0.1f, 0.9f};
  const ClipPlanes planes = make_clip_planes(d);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), uw(-0.2f, 2.0f);
  const size_t n = 1003;
  const int K = 2;
  std::vector<glm::vec4> pos(n);
  std::vector<float> soa((n + 7) / 8 * 32), vars(n * K);
  const float specials[] = {NAN, INFINITY, -INFINITY, 0.0f, -0.0f, 1e30f, 1e-30f};
  for (size_t i = 0; i < n; ++i) {
    const float w = uw(rng);
    glm::vec4 p{80.0f * u(rng) * w, 80.0f * u(rng) * w, 1.2f * u(rng) * w, w};
    if (i % 17 == 0) p[int(i / 17) % 4] = specials[(i / 68) % 7];
    pos[i] = p;
    for (int c = 0; c < 4; ++c) soa[i / 8 * 32 + size_t(c) * 8 + i % 8] = p[c];
  }
  std::vector<unsigned> codes(n);
  std::vector<WinVert> win(n);
  finish_vertices(d, planes, soa.data(), vars.data(), K, n, codes.data(), win.data());
  size_t inside = 0;
  for (size_t i = 0; i < n; ++i) {
    const glm::vec4& p = pos[i];
    const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
    const unsigned code = finite ? clip_code(planes, p) : kNotFinite;
    ASSERT_EQ(codes[i], code) << "vertex " << i;
    if (code) continue;
    ++inside;
    const WinVert v = to_window(d, p, &vars[i * K]);
    auto bits = [](float f) {
      uint32_t b;
      std::memcpy(&b, &f, 4);
      return b;
    };
    EXPECT_EQ(bits(win[i].x), bits(v.x)) << i;
    EXPECT_EQ(bits(win[i].y), bits(v.y)) << i;
    EXPECT_EQ(bits(win[i].z), bits(v.z)) << i;
    EXPECT_EQ(bits(win[i].oow), bits(v.oow)) << i;
    EXPECT_EQ(win[i].sx, v.sx) << i;
    EXPECT_EQ(win[i].sy, v.sy) << i;
    EXPECT_EQ(win[i].usable, v.usable) << i;
    EXPECT_EQ(win[i].var, v.var) << i;
  }
  EXPECT_GT(inside, n / 3);
  EXPECT_LT(inside, n);
}

TEST(Clip, UserPlanes) {
  DrawRecord d = record_for(64, 64);
  d.state.clip_plane_enable = 1;
  d.state.clip_planes[0] = {1, 0, 0, 0};  // keep x >= 0
  const ClipPlanes planes = make_clip_planes(d);
  EXPECT_EQ(clip_code(planes, {0.5f, 0, 0, 1}), 0u);
  EXPECT_NE(clip_code(planes, {-0.5f, 0, 0, 1}), 0u);
  // Drawn: only the right half of a full-screen quad remains.
  Target tg(32, 32);
  Context ctx(2);
  ctx.bind_framebuffer(&tg.fb);
  ctx.clear({.color = {0, 0, 0, 0}});
  RenderState st;
  st.clip_plane_enable = 1;
  st.clip_planes[0] = {1, 0, 0, 0};
  Mesh m({cv({-1, -1, 0, 1}, glm::vec4(1)), cv({1, -1, 0, 1}, glm::vec4(1)), cv({1, 1, 0, 1}, glm::vec4(1)),
          cv({-1, -1, 0, 1}, glm::vec4(1)), cv({1, 1, 0, 1}, glm::vec4(1)), cv({-1, 1, 0, 1}, glm::vec4(1))});
  ctx.draw(ColorShader{}, {}, m.layout, st, {.count = 6});
  ctx.finish();
  const auto p = read_rgba8(tg.color);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      EXPECT_EQ(p[(size_t(y) * 32 + x) * 4 + 3], x >= 16 ? 255 : 0) << x << "," << y;
}

TEST(Clip, TriangleCrossingNearPlaneRendersAsItsClippedPart) {
  const int W = 96, H = 96;
  const std::vector<TestVertex> tri = {cv({-0.8f, -0.7f, -1.6f, 1.0f}, {1, 0, 0, 1}),
                                       cv({0.9f, -0.5f, 0.3f, 1.2f}, {0, 1, 0, 1}),
                                       cv({0.1f, 0.8f, 0.5f, 0.9f}, {0, 0, 1, 1})};
  const auto whole = draw(W, H, tri);
  const auto parts = draw(W, H, clip_near_by_hand(tri));
  expect_same_image(whole, parts);
  size_t lit = 0;
  for (size_t i = 3; i < whole.size(); i += 4) lit += whole[i] != 0;
  EXPECT_GT(lit, 500u);
}

TEST(Clip, VerticesBehindTheEyeRenderAsTheClippedPart) {
  const int W = 96, H = 96;
  // One vertex with w < 0 (behind the eye), one with w = 0.
  for (float w : {-0.5f, 0.0f}) {
    const std::vector<TestVertex> tri = {cv({-0.5f, -0.5f, 0.0f, 1.0f}, {1, 0, 0, 1}),
                                         cv({0.5f, -0.4f, 0.2f, 1.0f}, {0, 1, 0, 1}),
                                         cv({0.2f, 0.6f, -0.9f, w}, {0, 0, 1, 1})};
    const auto whole = draw(W, H, tri);
    const auto parts = draw(W, H, clip_near_by_hand(tri));
    expect_same_image(whole, parts);
  }
}

TEST(Clip, HugeCoordinatesBeyondTheGuardBand) {
  // A triangle reaching 1e7 pixels out: clipped to the guard band, the visible part matches a
  // full-screen quad's coverage.
  const int W = 64, H = 64;
  const auto p = draw(W, H,
                      {cv({-1e5f, -1e5f, 0, 1}, glm::vec4(1)), cv({1e5f, -1e5f, 0, 1}, glm::vec4(1)),
                       cv({0, 1e5f, 0, 1}, glm::vec4(1))});
  for (size_t i = 3; i < p.size(); i += 4) ASSERT_EQ(p[i], 255);
}
