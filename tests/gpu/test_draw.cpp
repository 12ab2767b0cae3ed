// End-to-end draws through the whole pipeline: topologies, indexing, instancing, clipping,
// perspective-correct interpolation, flat shading, determinism across thread counts.
#include <gtest/gtest.h>

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
  v.color[0] = c.r; v.color[1] = c.g; v.color[2] = c.b; v.color[3] = c.a;
  return v;
}

}  // namespace

TEST(Draw, TriangleCoversItsInterior) {
  Target t(32, 32);
  Context ctx(1);
  ctx.bind_framebuffer(&t.fb);
  ctx.clear({.color = {0, 0, 0, 1}});
  Mesh m({wv(2, 2, 0, 32, 32, {1, 0, 0, 1}), wv(30, 2, 0, 32, 32, {1, 0, 0, 1}), wv(2, 30, 0, 32, 32, {1, 0, 0, 1})});
  ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 3});
  ctx.finish();
  auto p = pixels(t.color);
  EXPECT_EQ(px(p, 32, 3, 3), 0xFF0000FFu);    // inside: red (bytes r,g,b,a little-endian)
  EXPECT_EQ(px(p, 32, 28, 28), 0xFF000000u);  // outside: black
  EXPECT_EQ(px(p, 32, 15, 15), 0xFF0000FFu);  // below the hypotenuse x + y = 32: centre sum 31
  EXPECT_EQ(px(p, 32, 16, 16), 0xFF000000u);  // centre sum 33 > 32
}
