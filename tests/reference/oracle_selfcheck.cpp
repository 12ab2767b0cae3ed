// Self-check for the Mesa llvmpipe oracle: renders known primitives and checks exact
// values. Every expected value below follows from the GL rules alone (pixel centres
// strictly inside/outside primitives, colours that are exact in unorm8, depths that round
// the same way under any float->unorm24 conversion), not from observed output.
#include "mesa_oracle.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using tessel::reference::MesaOracle;
using tessel::reference::OracleState;
using tessel::reference::OracleTexture;
using tessel::reference::OracleVertex;

constexpr uint32_t kGL_TRIANGLES = 0x0004;
constexpr uint32_t kGL_TRIANGLE_STRIP = 0x0005;
constexpr uint32_t kGL_POINTS = 0x0000;
constexpr uint32_t kGL_ALWAYS = 0x0207;
constexpr uint32_t kGL_EQUAL = 0x0202;
constexpr uint32_t kGL_REPLACE = 0x1E01;
constexpr uint32_t kGL_ONE = 1;
constexpr uint32_t kGL_NEAREST = 0x2600;
constexpr uint32_t kGL_CLAMP_TO_EDGE = 0x812F;

using RGBA = std::array<int, 4>;

RGBA pixel(const std::vector<uint8_t>& img, int w, int x, int y) {
  const size_t i = (size_t(y) * size_t(w) + size_t(x)) * 4;
  return {img[i], img[i + 1], img[i + 2], img[i + 3]};
}

OracleVertex V(float x, float y, float z, float w, RGBA c, float u = 0, float v = 0) {
  return OracleVertex{{x, y, z, w}, {c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, c[3] / 255.0f}, {u, v}};
}

class OracleTest : public ::testing::Test {
 protected:
  std::unique_ptr<MesaOracle> make(int w, int h) {
    std::string why;
    auto o = MesaOracle::create(w, h, &why);
    EXPECT_NE(o, nullptr) << "Mesa oracle unavailable: " << why;
    return o;
  }
};

TEST_F(OracleTest, IsLlvmpipe) {
  auto o = make(4, 4);
  ASSERT_NE(o, nullptr);
  EXPECT_NE(o->renderer().find("llvmpipe"), std::string::npos) << o->renderer();
  std::printf("GL_RENDERER = %s\nGL_VERSION  = %s\nEGL platform = %s\n", o->renderer().c_str(),
              o->version().c_str(), o->egl_platform().c_str());
}

TEST_F(OracleTest, CreateFailsCleanlyOnBadSize) {
  std::string why;
  EXPECT_EQ(MesaOracle::create(0, 4, &why), nullptr);
  EXPECT_FALSE(why.empty());
}

// Lower-left half-screen triangle; clip coordinates with w = 2 (pos is passed straight to
// gl_Position, so the divide must happen in GL). z_ndc = 1/2 -> window depth 0.75.
TEST_F(OracleTest, TriangleColourClearAndDepth) {
  const int W = 16, H = 16;
  auto o = make(W, H);
  ASSERT_NE(o, nullptr);
  const float clear[4] = {0.0f, 0.0f, 1.0f, 1.0f};
  o->clear(clear, 1.0f, 0);

  const RGBA red = {255, 0, 0, 255};
  std::vector<OracleVertex> tri = {V(-2, -2, 1, 2, red), V(2, -2, 1, 2, red), V(-2, 2, 1, 2, red)};
  OracleState st;
  st.depth_test = true;
  o->draw(tri, st);

  const auto img = o->read_rgba8();
  ASSERT_EQ(img.size(), size_t(W * H * 4));
  // Inside: pixel centres with x + y + 1 < 16. Outside: x + y + 1 > 16.
  EXPECT_EQ(pixel(img, W, 0, 0), red);
  EXPECT_EQ(pixel(img, W, 2, 3), red);
  EXPECT_EQ(pixel(img, W, 14, 0), red);  // rows are bottom-up: y = 0 is the bottom row
  EXPECT_EQ(pixel(img, W, 0, 14), red);
  EXPECT_EQ(pixel(img, W, 13, 13), (RGBA{0, 0, 255, 255}));
  EXPECT_EQ(pixel(img, W, 15, 15), (RGBA{0, 0, 255, 255}));
  EXPECT_EQ(pixel(img, W, 15, 1), (RGBA{0, 0, 255, 255}));

  // Depth: 0.75 * (2^24 - 1) = 12582911.25 -> 12582911 (truncation and rounding agree).
  const auto d24 = o->read_depth24();
  ASSERT_EQ(d24.size(), size_t(W * H));
  EXPECT_EQ(d24[2 * W + 2], 12582911u);
  EXPECT_EQ(d24[15 * W + 15], 0xFFFFFFu);
  const auto d = o->read_depth();
  ASSERT_EQ(d.size(), size_t(W * H));
  EXPECT_EQ(d[2 * W + 2], float(12582911.0 / 16777215.0));
  EXPECT_EQ(d[15 * W + 15], 1.0f);

  // Depth test: a farther triangle (z_ndc = 0.9) over the same area must be rejected
  // where the first one is, and drawn elsewhere.
  const RGBA green = {0, 255, 0, 255};
  std::vector<OracleVertex> far_quad = {V(-1, -1, 0.9f, 1, green), V(1, -1, 0.9f, 1, green),
                                        V(-1, 1, 0.9f, 1, green), V(1, 1, 0.9f, 1, green)};
  st.primitive = kGL_TRIANGLE_STRIP;
  o->draw(far_quad, st);
  const auto img2 = o->read_rgba8();
  EXPECT_EQ(pixel(img2, W, 2, 3), red);
  EXPECT_EQ(pixel(img2, W, 13, 13), green);
}

// Flat shading uses the last vertex (GL's default provoking vertex).
TEST_F(OracleTest, FlatShadingUsesLastVertex) {
  const int W = 8, H = 8;
  auto o = make(W, H);
  ASSERT_NE(o, nullptr);
  const float clear[4] = {0, 0, 0, 0};
  o->clear(clear, 1.0f, 0);
  const RGBA a = {255, 0, 0, 255}, b = {0, 255, 0, 255}, c = {51, 102, 153, 204};
  std::vector<OracleVertex> tri = {V(-1, -1, 0, 1, a), V(3, -1, 0, 1, b), V(-1, 3, 0, 1, c)};
  OracleState st;
  st.flat = true;
  o->draw(tri, st);
  const auto img = o->read_rgba8();
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) EXPECT_EQ(pixel(img, W, x, y), c) << x << "," << y;
}

// Stencil REPLACE inside a triangle, then an EQUAL test restricting a full-screen draw.
TEST_F(OracleTest, StencilReplaceThenEqual) {
  const int W = 16, H = 16;
  auto o = make(W, H);
  ASSERT_NE(o, nullptr);
  const float clear[4] = {0, 0, 0, 1};
  o->clear(clear, 1.0f, 0);
  const RGBA white = {255, 255, 255, 255};
  OracleState st;
  st.stencil_test = true;
  st.stencil_func = kGL_ALWAYS;
  st.stencil_ref = 5;
  st.stencil_zpass = kGL_REPLACE;
  st.color_mask[0] = st.color_mask[1] = st.color_mask[2] = st.color_mask[3] = false;
  o->draw({V(-1, -1, 0, 1, white), V(1, -1, 0, 1, white), V(-1, 1, 0, 1, white)}, st);

  const auto s = o->read_stencil();
  ASSERT_EQ(s.size(), size_t(W * H));
  EXPECT_EQ(s[2 * W + 3], 5);
  EXPECT_EQ(s[13 * W + 13], 0);
  EXPECT_EQ(pixel(o->read_rgba8(), W, 2, 3), (RGBA{0, 0, 0, 255}));  // colour masked off

  OracleState st2;
  st2.stencil_test = true;
  st2.stencil_func = kGL_EQUAL;
  st2.stencil_ref = 5;
  o->draw({V(-1, -1, 0, 1, white), V(1, -1, 0, 1, white), V(-1, 1, 0, 1, white), V(1, 1, 0, 1, white)}, [&] {
    OracleState t = st2;
    t.primitive = kGL_TRIANGLE_STRIP;
    return t;
  }());
  const auto img = o->read_rgba8();
  EXPECT_EQ(pixel(img, W, 2, 3), white);
  EXPECT_EQ(pixel(img, W, 13, 13), (RGBA{0, 0, 0, 255}));
}

// 2x2 NEAREST texture on a full-screen quad of a 4x4 target: each texel covers 2x2 pixels.
// Texture rows are bottom-up, like the framebuffer. Vertex colour white -> texel colour.
TEST_F(OracleTest, NearestTextureQuadrants) {
  const int W = 4, H = 4;
  auto o = make(W, H);
  ASSERT_NE(o, nullptr);
  OracleTexture t;
  t.width = 2;
  t.height = 2;
  t.rgba = {255, 0, 0,   255, 0,   255, 0,   255,   // row 0 (bottom): red, green
            0,   0, 255, 255, 255, 255, 255, 255};  // row 1 (top): blue, white
  t.min_filter = t.mag_filter = kGL_NEAREST;
  t.wrap_s = t.wrap_t = kGL_CLAMP_TO_EDGE;
  o->set_texture(t);
  const float clear[4] = {0, 0, 0, 0};
  o->clear(clear, 1.0f, 0);
  const RGBA white = {255, 255, 255, 255};
  OracleState st;
  st.textured = true;
  st.primitive = kGL_TRIANGLE_STRIP;
  o->draw({V(-1, -1, 0, 1, white, 0, 0), V(1, -1, 0, 1, white, 1, 0), V(-1, 1, 0, 1, white, 0, 1),
           V(1, 1, 0, 1, white, 1, 1)},
          st);
  const auto img = o->read_rgba8();
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      const int tx = x / 2, ty = y / 2;
      const size_t i = size_t(ty * 2 + tx) * 4;
      const RGBA want = {t.rgba[i], t.rgba[i + 1], t.rgba[i + 2], t.rgba[i + 3]};
      EXPECT_EQ(pixel(img, W, x, y), want) << x << "," << y;
    }
  }
}

// Additive blending with colours exact in unorm8: 51 + 102 = 153; alpha 255 + 0 = 255.
TEST_F(OracleTest, AdditiveBlend) {
  const int W = 4, H = 4;
  auto o = make(W, H);
  ASSERT_NE(o, nullptr);
  const float clear[4] = {102 / 255.0f, 0, 204 / 255.0f, 0};
  o->clear(clear, 1.0f, 0);
  const RGBA c = {51, 51, 51, 255};
  OracleState st;
  st.blend = true;
  st.blend_src_rgb = st.blend_dst_rgb = st.blend_src_a = st.blend_dst_a = kGL_ONE;
  st.primitive = kGL_TRIANGLE_STRIP;
  o->draw({V(-1, -1, 0, 1, c), V(1, -1, 0, 1, c), V(-1, 1, 0, 1, c), V(1, 1, 0, 1, c)}, st);
  const auto img = o->read_rgba8();
  EXPECT_EQ(pixel(img, W, 1, 2), (RGBA{153, 51, 255, 255}));
}

// A size-2 point centred on window (4, 4) covers exactly pixels 3..4 x 3..4 (centres at
// 3.5 and 4.5 are strictly inside [3, 5]); viewport maps clip (0,0) to the target centre.
TEST_F(OracleTest, PointSizeTwo) {
  const int W = 8, H = 8;
  auto o = make(W, H);
  ASSERT_NE(o, nullptr);
  const float clear[4] = {0, 0, 0, 0};
  o->clear(clear, 1.0f, 0);
  const RGBA white = {255, 255, 255, 255};
  OracleState st;
  st.primitive = kGL_POINTS;
  st.point_size = 2;
  o->draw({V(0, 0, 0, 1, white)}, st);
  const auto img = o->read_rgba8();
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const bool in = (x == 3 || x == 4) && (y == 3 || y == 4);
      EXPECT_EQ(pixel(img, W, x, y), in ? white : (RGBA{0, 0, 0, 0})) << x << "," << y;
    }
}

// Viewport + scissor: the quad fills the viewport (x 4..11), the scissor keeps y 0..7.
TEST_F(OracleTest, ViewportAndScissor) {
  const int W = 16, H = 16;
  auto o = make(W, H);
  ASSERT_NE(o, nullptr);
  const float clear[4] = {0, 0, 0, 0};
  o->clear(clear, 1.0f, 0);
  const RGBA white = {255, 255, 255, 255};
  OracleState st;
  st.primitive = kGL_TRIANGLE_STRIP;
  st.viewport[0] = 4;
  st.viewport[1] = 0;
  st.viewport[2] = 8;
  st.viewport[3] = 16;
  st.scissor = true;
  st.scissor_box[0] = 0;
  st.scissor_box[1] = 0;
  st.scissor_box[2] = 16;
  st.scissor_box[3] = 8;
  o->draw({V(-1, -1, 0, 1, white), V(1, -1, 0, 1, white), V(-1, 1, 0, 1, white), V(1, 1, 0, 1, white)}, st);
  const auto img = o->read_rgba8();
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const bool in = x >= 4 && x < 12 && y < 8;
      EXPECT_EQ(pixel(img, W, x, y), in ? white : (RGBA{0, 0, 0, 0})) << x << "," << y;
    }
}

TEST_F(OracleTest, GlErrorThrows) {
  auto o = make(4, 4);
  ASSERT_NE(o, nullptr);
  OracleState st;
  st.primitive = 0x1234;  // not a primitive mode -> GL_INVALID_ENUM
  const RGBA white = {255, 255, 255, 255};
  EXPECT_THROW(o->draw({V(0, 0, 0, 1, white)}, st), std::runtime_error);
  // The oracle stays usable afterwards.
  OracleState ok;
  ok.primitive = kGL_POINTS;
  EXPECT_NO_THROW(o->draw({V(0, 0, 0, 1, white)}, ok));
}

TEST_F(OracleTest, TwoOraclesCoexist) {
  auto a = make(4, 4);
  auto b = make(8, 8);
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  const float ca[4] = {1, 0, 0, 1}, cb[4] = {0, 1, 0, 1};
  a->clear(ca, 1.0f, 0);
  b->clear(cb, 1.0f, 0);
  EXPECT_EQ(pixel(a->read_rgba8(), 4, 1, 1), (RGBA{255, 0, 0, 255}));
  EXPECT_EQ(pixel(b->read_rgba8(), 8, 5, 5), (RGBA{0, 255, 0, 255}));
  b.reset();
  EXPECT_EQ(pixel(a->read_rgba8(), 4, 3, 3), (RGBA{255, 0, 0, 255}));
}

}  // namespace
