// Self-check for the Mesa llvmpipe GLSL oracle: runs small programs whose results follow
// from the GL rules alone (pixel centres strictly inside or outside primitives, values that
// are exact in float, texels fetched without filtering) and checks them exactly. Each test
// pins one piece of the oracle's plumbing, so a mistake in it (a uniform set through the
// wrong call, a float pointer for an integer attribute, a matrix left loaded from an earlier
// run, clamped colours, a texture uploaded in the wrong layout) fails a test.
#include "glsl_oracle.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace {

using tessel::reference::GlslAttribute;
using tessel::reference::GlslDrawSpec;
using tessel::reference::GlslOracle;
using tessel::reference::GlslResult;
using tessel::reference::GlslTexture;
using tessel::reference::GlslUniform;

constexpr uint32_t kGL_TEXTURE_1D = 0x0DE0;
constexpr uint32_t kGL_TEXTURE_3D = 0x806F;
constexpr uint32_t kGL_TEXTURE_2D_ARRAY = 0x8C1A;
constexpr uint32_t kGL_TEXTURE_RECTANGLE = 0x84F5;
constexpr uint32_t kGL_TEXTURE_CUBE_MAP = 0x8513;
constexpr uint32_t kGL_DEPTH_COMPONENT32F = 0x8CAC;
constexpr uint32_t kGL_CLAMP_TO_EDGE = 0x812F;
constexpr uint32_t kGL_LEQUAL = 0x0203;

using Px = std::array<float, 4>;

Px px(const std::vector<float>& img, int w, int x, int y) {
  const size_t i = (size_t(y) * size_t(w) + size_t(x)) * 4;
  return {img[i], img[i + 1], img[i + 2], img[i + 3]};
}

std::string str(const Px& p) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "(%.9g, %.9g, %.9g, %.9g)", p[0], p[1], p[2], p[3]);
  return buf;
}

// Two triangles covering the whole target: lower-right (below the diagonal y = x) first,
// then upper-left. Pixel centres (x + 0.5, y + 0.5) with x != y are strictly inside one.
GlslAttribute full_screen_pos(const char* name = "pos") {
  return GlslAttribute{name, 2, {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1}, false, {}};
}

const char* kVs330 =
    "#version 330 core\n"
    "in vec2 pos;\n"
    "void main() { gl_Position = vec4(pos, 0.0, 1.0); }\n";

class GlslOracleTest : public ::testing::Test {
 protected:
  // One oracle for the whole suite: later tests run on a context earlier runs have used,
  // which is how the oracle is meant to be used.
  static void SetUpTestSuite() {
    std::string why;
    oracle_ = GlslOracle::create(&why);
    why_ = why;
  }
  static void TearDownTestSuite() { oracle_.reset(); }

  void SetUp() override { ASSERT_NE(oracle_, nullptr) << "GLSL oracle unavailable: " << why_; }

  static GlslResult run(const GlslDrawSpec& spec) { return oracle_->run(spec); }

  static std::unique_ptr<GlslOracle> oracle_;
  static std::string why_;
};

std::unique_ptr<GlslOracle> GlslOracleTest::oracle_;
std::string GlslOracleTest::why_;

#define EXPECT_RAN(r)                     \
  do {                                    \
    EXPECT_TRUE((r).compiled) << (r).log; \
    EXPECT_TRUE((r).linked) << (r).log;   \
    ASSERT_TRUE((r).ok) << (r).log;       \
  } while (0)

TEST_F(GlslOracleTest, CompatibilityContextOnLlvmpipe) {
  const std::string renderer = oracle_->renderer(), version = oracle_->version();
  std::printf("GL_RENDERER = %s\nGL_VERSION  = %s\n", renderer.c_str(), version.c_str());
  EXPECT_NE(renderer.find("llvmpipe"), std::string::npos) << renderer;
  EXPECT_NE(version.find("Compatibility"), std::string::npos) << version;
  // #version 330 core shaders need at least GL 3.3.
  ASSERT_GE(version.size(), 3u);
  EXPECT_TRUE(version[0] > '3' || (version[0] == '3' && version[2] >= '3')) << version;
}

// (1) gl_FragCoord at pixel (x, y) is (x + 0.5, y + 0.5); /16 is exact.
TEST_F(GlslOracleTest, FragCoord330) {
  GlslDrawSpec s;
  s.vertex = kVs330;
  s.fragment =
      "#version 330 core\n"
      "out vec4 o;\n"
      "void main() { o = vec4(gl_FragCoord.xy / 16.0, 0.25, 1.0); }\n";
  s.attributes = {full_screen_pos()};
  s.count = 6;
  const GlslResult r = run(s);
  EXPECT_RAN(r);
  ASSERT_EQ(r.outputs.size(), 1u);
  ASSERT_EQ(r.outputs[0].size(), size_t(16 * 16 * 4));
  EXPECT_TRUE(r.depth.empty());
  EXPECT_EQ(px(r.outputs[0], 16, 0, 0), (Px{0.03125f, 0.03125f, 0.25f, 1.0f}));
  EXPECT_EQ(px(r.outputs[0], 16, 15, 15), (Px{0.96875f, 0.96875f, 0.25f, 1.0f}));
  EXPECT_EQ(px(r.outputs[0], 16, 3, 10), (Px{3.5f / 16, 10.5f / 16, 0.25f, 1.0f}));
  EXPECT_EQ(px(r.outputs[0], 16, 12, 1), (Px{12.5f / 16, 1.5f / 16, 0.25f, 1.0f}));
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      ASSERT_EQ(px(r.outputs[0], 16, x, y), (Px{(x + 0.5f) / 16, (y + 0.5f) / 16, 0.25f, 1.0f}))
          << x << "," << y;
}

// (2) #version 120 with gl_ModelViewProjectionMatrix: a full-screen quad scaled by 0.5
// covers NDC [-0.5, 0.5]^2 = window [4, 12]^2, i.e. pixels 4..11. Then a projection that
// shifts by +0.5 in x, then no matrices at all (which must not inherit the earlier ones).
TEST_F(GlslOracleTest, Version120ModelViewProjection) {
  GlslDrawSpec s;
  s.vertex =
      "#version 120\n"
      "attribute vec4 pos;\n"
      "void main() { gl_Position = gl_ModelViewProjectionMatrix * pos; }\n";
  s.fragment =
      "#version 120\n"
      "void main() { gl_FragColor = vec4(1.0, 0.5, 0.25, 1.0); }\n";
  s.attributes = {full_screen_pos()};
  s.count = 6;
  s.clear[2] = 1.0f;  // blue background
  s.modelview = {0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 1};
  const Px fg = {1.0f, 0.5f, 0.25f, 1.0f}, bg = {0, 0, 1, 0};

  GlslResult r = run(s);
  EXPECT_RAN(r);
  ASSERT_EQ(r.outputs.size(), 1u);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const bool in = x >= 4 && x <= 11 && y >= 4 && y <= 11;
      EXPECT_EQ(px(r.outputs[0], 16, x, y), in ? fg : bg) << x << "," << y;
    }

  // projection * modelview: x_ndc = 0.5 * x + 0.5 in [0, 1] -> pixels x 8..15.
  s.projection = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, 0, 0, 1};  // column-major
  r = run(s);
  EXPECT_RAN(r);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const bool in = x >= 8 && y >= 4 && y <= 11;
      EXPECT_EQ(px(r.outputs[0], 16, x, y), in ? fg : bg) << x << "," << y;
    }

  s.modelview.clear();
  s.projection.clear();
  r = run(s);
  EXPECT_RAN(r);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) EXPECT_EQ(px(r.outputs[0], 16, x, y), fg) << x << "," << y;
}

// (3) Uniforms by name: a float array (whole, then one element from "k[2]"), a struct's
// members, a member of an array-of-structs element, a mat3, a uint, a bool; an unknown name
// is skipped silently.
TEST_F(GlslOracleTest, UniformArraysStructsByName) {
  GlslDrawSpec s;
  s.vertex = kVs330;
  s.fragment =
      "#version 330 core\n"
      "struct S { vec2 a; float b; int c; };\n"
      "struct Light { vec3 pos; float power; };\n"
      "uniform float k[3];\n"
      "uniform S s;\n"
      "uniform Light lights[2];\n"
      "uniform mat3 m;\n"
      "uniform uint uu;\n"
      "uniform bool flag;\n"
      "layout(location = 0) out vec4 o0;\n"
      "layout(location = 1) out vec4 o1;\n"
      "layout(location = 2) out vec4 o2;\n"
      "void main() {\n"
      "  o0 = vec4(k[0], k[1], k[2], s.b);\n"
      "  o1 = vec4(s.a, float(s.c), lights[1].pos.y);\n"
      "  o2 = vec4(lights[1].power, m[2][0], float(uu), flag ? 1.0 : -1.0);\n"
      "}\n";
  s.attributes = {full_screen_pos()};
  s.count = 6;
  s.width = s.height = 4;
  s.outputs = 3;
  s.uniforms = {
      {"k", {1, 2, 3}, {}, {}},
      {"k[2]", {7}, {}, {}},
      {"s.a", {0.5f, 0.25f}, {}, {}},
      {"s.b", {3}, {}, {}},
      {"s.c", {}, {-4}, {}},
      {"lights[0].pos", {-1, -1, -1}, {}, {}},  // unused by the shader: skipped
      {"lights[1].pos", {10, 20, 30}, {}, {}},
      {"lights[1].power", {2.5f}, {}, {}},
      {"m", {11, 12, 13, 14, 15, 16, 17, 18, 19}, {}, {}},  // m[2][0] = element 6
      {"uu", {}, {}, {42}},
      {"flag", {}, {1}, {}},
      {"no_such_uniform", {1}, {}, {}},
  };
  const GlslResult r = run(s);
  EXPECT_RAN(r);
  ASSERT_EQ(r.outputs.size(), 3u);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      EXPECT_EQ(px(r.outputs[0], 4, x, y), (Px{1, 2, 7, 3})) << x << "," << y;
      EXPECT_EQ(px(r.outputs[1], 4, x, y), (Px{0.5f, 0.25f, -4, 20})) << x << "," << y;
      EXPECT_EQ(px(r.outputs[2], 4, x, y), (Px{2.5f, 17, 42, 1})) << x << "," << y;
    }
}

// (4) Two colour outputs, the second by layout(location = 1); values far outside [0, 1]
// come back unclamped, and each attachment starts from the clear colour.
TEST_F(GlslOracleTest, TwoOutputsUnclamped) {
  GlslDrawSpec s;
  s.vertex = kVs330;
  s.fragment =
      "#version 330 core\n"
      "layout(location = 1) out vec4 second;\n"
      "layout(location = 0) out vec4 first;\n"
      "void main() {\n"
      "  first = vec4(1.0, 2.0, 3.0, 4.0);\n"
      "  second = vec4(-1.0, 0.5, 100.0, -8.0);\n"
      "}\n";
  // Only the lower-right triangle: the upper-left pixels keep the clear colour.
  s.attributes = {full_screen_pos()};
  s.count = 3;
  s.outputs = 2;
  s.width = s.height = 8;
  s.clear[0] = -2.0f;
  s.clear[3] = 7.0f;
  const GlslResult r = run(s);
  EXPECT_RAN(r);
  ASSERT_EQ(r.outputs.size(), 2u);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      if (x == y) continue;  // on the diagonal edge: the tie-break rule decides
      const bool in = x > y;
      EXPECT_EQ(px(r.outputs[0], 8, x, y), in ? (Px{1, 2, 3, 4}) : (Px{-2, 0, 0, 7})) << x << "," << y;
      EXPECT_EQ(px(r.outputs[1], 8, x, y), in ? (Px{-1, 0.5f, 100, -8}) : (Px{-2, 0, 0, 7})) << x << "," << y;
    }
}

// (5) A syntax error on line 4 of the fragment shader: not compiled, not linked, not ok, no
// pixels, and Mesa's "0:4(col): error: ..." in the log. Then a link error (a varying of
// different types in the two stages): compiled but not linked.
TEST_F(GlslOracleTest, CompileAndLinkErrorsAreReported) {
  GlslDrawSpec s;
  s.vertex = kVs330;
  s.fragment =
      "#version 330 core\n"
      "out vec4 o;\n"
      "void main() {\n"
      "  o = vec4(1.0) +;\n"
      "}\n";
  s.attributes = {full_screen_pos()};
  s.count = 6;
  GlslResult r = run(s);
  EXPECT_FALSE(r.compiled);
  EXPECT_FALSE(r.linked);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(r.outputs.empty());
  EXPECT_NE(r.log.find("fragment shader:"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("0:4("), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("error"), std::string::npos) << r.log;
  std::printf("compile log:\n%s", r.log.c_str());

  s.vertex =
      "#version 330 core\n"
      "in vec2 pos;\n"
      "out vec2 v;\n"
      "void main() { v = pos; gl_Position = vec4(pos, 0.0, 1.0); }\n";
  s.fragment =
      "#version 330 core\n"
      "in vec3 v;\n"
      "out vec4 o;\n"
      "void main() { o = vec4(v, 1.0); }\n";
  r = run(s);
  EXPECT_TRUE(r.compiled) << r.log;
  EXPECT_FALSE(r.linked);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(r.outputs.empty());
  EXPECT_NE(r.log.find("program:"), std::string::npos) << r.log;
  std::printf("link log:\n%s", r.log.c_str());

  // The oracle is fine afterwards.
  s.fragment =
      "#version 330 core\n"
      "in vec2 v;\n"
      "out vec4 o;\n"
      "void main() { o = vec4(0.5); }\n";
  r = run(s);
  EXPECT_RAN(r);
  EXPECT_EQ(px(r.outputs[0], 16, 5, 9), (Px{0.5f, 0.5f, 0.5f, 0.5f}));
}

// (6) An RGBA32F texture on unit 2 read with texelFetch gives the stored floats bit for bit
// (including values that are not exact decimals and ones far outside [0, 1]).
TEST_F(GlslOracleTest, TexelFetchRgba32fExact) {
  const int TW = 4, TH = 3;
  auto texel = [](int x, int y) -> Px {
    return {float(x) + 0.125f, float(y) * 1000.5f - 3.0f, 0.3f * float(x + 1), -1e-3f * float(y + 1)};
  };
  GlslTexture t;
  t.unit = 2;
  t.width = TW;
  t.height = TH;
  for (int y = 0; y < TH; ++y)
    for (int x = 0; x < TW; ++x)
      for (float v : texel(x, y)) t.data.push_back(v);

  GlslDrawSpec s;
  s.vertex = kVs330;
  s.fragment =
      "#version 330 core\n"
      "uniform sampler2D tex;\n"
      "out vec4 o;\n"
      "void main() { o = texelFetch(tex, ivec2(gl_FragCoord.xy) % ivec2(4, 3), 0); }\n";
  s.attributes = {full_screen_pos()};
  s.count = 6;
  s.width = 8;
  s.height = 6;
  s.textures = {t};
  s.uniforms = {{"tex", {}, {2}, {}}};
  const GlslResult r = run(s);
  EXPECT_RAN(r);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x)
      EXPECT_EQ(px(r.outputs[0], 8, x, y), texel(x % TW, y % TH))
          << x << "," << y << ": " << str(px(r.outputs[0], 8, x, y));
}

// (7) An integer attribute (glVertexAttribIPointer) through a flat varying: each triangle
// shows its LAST vertex's values (GL's default provoking vertex). Fed as floats, the ints
// would arrive as garbage.
TEST_F(GlslOracleTest, IntegerAttributeFlat) {
  GlslDrawSpec s;
  s.vertex =
      "#version 330 core\n"
      "in vec2 pos;\n"
      "in ivec2 id;\n"
      "flat out ivec2 vid;\n"
      "void main() { vid = id; gl_Position = vec4(pos, 0.0, 1.0); }\n";
  s.fragment =
      "#version 330 core\n"
      "flat in ivec2 vid;\n"
      "out vec4 o;\n"
      "void main() { o = vec4(vec2(vid), 0.0, 1.0); }\n";
  GlslAttribute id{"id", 2, {}, true, {1, 10, 2, 20, 3, -30, 4, 40, 5, 50, -6, 123456}};
  s.attributes = {full_screen_pos(), id};
  s.count = 6;
  const GlslResult r = run(s);
  EXPECT_RAN(r);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      if (x == y) continue;
      EXPECT_EQ(px(r.outputs[0], 16, x, y), x > y ? (Px{3, -30, 0, 1}) : (Px{-6, 123456, 0, 1}))
          << x << "," << y;
    }
}

// Compatibility built-in inputs: gl_Vertex and gl_Color from arrays, gl_FrontColor doubled
// past 1 and negative (not clamped). Then the same without a gl_Color array: gl_Color is
// the default current colour (1, 1, 1, 1), not anything the previous run left behind.
TEST_F(GlslOracleTest, CompatibilityBuiltinAttributesUnclamped) {
  GlslDrawSpec s;
  s.vertex =
      "#version 110\n"
      "void main() { gl_Position = gl_Vertex; gl_FrontColor = gl_Color * 2.0; }\n";
  s.fragment =
      "#version 110\n"
      "void main() { gl_FragColor = gl_Color; }\n";
  std::vector<float> colour;
  for (int i = 0; i < 6; ++i) colour.insert(colour.end(), {0.75f, 0.25f, -0.5f, 1.0f});
  s.attributes = {full_screen_pos("gl_Vertex"), GlslAttribute{"gl_Color", 4, colour, false, {}}};
  s.count = 6;
  s.width = s.height = 4;
  GlslResult r = run(s);
  EXPECT_RAN(r);
  // A constant varying: interpolation gives it back (to rounding, which GL does not pin).
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const Px p = px(r.outputs[0], 4, x, y);
      EXPECT_NEAR(p[0], 1.5f, 1e-6f);
      EXPECT_NEAR(p[1], 0.5f, 1e-6f);
      EXPECT_NEAR(p[2], -1.0f, 1e-6f);
      EXPECT_NEAR(p[3], 2.0f, 1e-6f);
    }

  s.attributes.pop_back();
  r = run(s);
  EXPECT_RAN(r);
  EXPECT_EQ(px(r.outputs[0], 4, 1, 2), (Px{2, 2, 2, 2}));
}

// The depth attachment: cleared to 1, GL_LESS. Quad A (z_ndc 0.5, window 0.75) over all,
// quad B (z_ndc 0, window 0.5) over the left half, quad C (z_ndc 0.8) over all, rejected.
TEST_F(GlslOracleTest, DepthAttachmentLess) {
  GlslDrawSpec s;
  s.vertex =
      "#version 330 core\n"
      "in vec3 pos;\n"
      "in vec4 col;\n"
      "flat out vec4 c;\n"
      "void main() { c = col; gl_Position = vec4(pos, 1.0); }\n";
  s.fragment =
      "#version 330 core\n"
      "flat in vec4 c;\n"
      "out vec4 o;\n"
      "void main() { o = c; }\n";
  std::vector<float> pos, col;
  auto quad = [&](float x0, float x1, float z, Px c) {
    const float v[6][2] = {{x0, -1}, {x1, -1}, {x1, 1}, {x0, -1}, {x1, 1}, {x0, 1}};
    for (const auto& p : v) {
      pos.insert(pos.end(), {p[0], p[1], z});
      col.insert(col.end(), c.begin(), c.end());
    }
  };
  quad(-1, 1, 0.5f, {1, 0, 0, 1});
  quad(-1, 0, 0.0f, {0, 1, 0, 1});
  quad(-1, 1, 0.8f, {0, 0, 1, 1});
  s.attributes = {GlslAttribute{"pos", 3, pos, false, {}}, GlslAttribute{"col", 4, col, false, {}}};
  s.count = 18;
  s.width = s.height = 8;
  s.depth = true;
  const GlslResult r = run(s);
  EXPECT_RAN(r);
  ASSERT_EQ(r.depth.size(), size_t(64));
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const bool left = x < 4;
      EXPECT_EQ(px(r.outputs[0], 8, x, y), left ? (Px{0, 1, 0, 1}) : (Px{1, 0, 0, 1})) << x << "," << y;
      EXPECT_FLOAT_EQ(r.depth[size_t(y * 8 + x)], left ? 0.5f : 0.75f) << x << "," << y;
    }
}

// Layout of every other texture target: texel (x, y, z) of each holds (target, x, y, z)
// (a cube face holds (5, face, 0, 0)), fetched back per pixel. A wrong row, slice or face
// order gives other numbers.
TEST_F(GlslOracleTest, TextureTargetsLayout) {
  auto fill = [](GlslTexture& t, float id, int w, int h, int d) {
    t.width = w;
    t.height = h;
    t.depth = d;
    for (int z = 0; z < d; ++z)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) t.data.insert(t.data.end(), {id, float(x), float(y), float(z)});
  };
  GlslTexture t1, t3, ta, tr, tc;
  t1.unit = 0, t1.target = kGL_TEXTURE_1D;
  fill(t1, 1, 4, 1, 1);
  t3.unit = 1, t3.target = kGL_TEXTURE_3D;
  fill(t3, 2, 4, 2, 3);
  ta.unit = 2, ta.target = kGL_TEXTURE_2D_ARRAY;
  fill(ta, 3, 4, 2, 3);
  tr.unit = 3, tr.target = kGL_TEXTURE_RECTANGLE;  // default GL_REPEAT must not be an error
  fill(tr, 4, 4, 4, 1);
  tc.unit = 4, tc.target = kGL_TEXTURE_CUBE_MAP, tc.width = tc.height = 1;
  tc.wrap = kGL_CLAMP_TO_EDGE;
  for (int face = 0; face < 6; ++face) tc.data.insert(tc.data.end(), {5, float(face), 0, 0});

  GlslDrawSpec s;
  s.vertex = kVs330;
  s.fragment =
      "#version 330 core\n"
      "uniform sampler1D t1;\n"
      "uniform sampler3D t3;\n"
      "uniform sampler2DArray ta;\n"
      "uniform sampler2DRect tr;\n"
      "uniform samplerCube tc;\n"
      "layout(location = 0) out vec4 o1;\n"
      "layout(location = 1) out vec4 o3;\n"
      "layout(location = 2) out vec4 oa;\n"
      "layout(location = 3) out vec4 or_;\n"
      "layout(location = 4) out vec4 oc;\n"
      "const vec3 dirs[6] = vec3[6](vec3(1, 0.1, 0.2), vec3(-1, 0.2, -0.1),\n"
      "                             vec3(0.1, 1, 0.2), vec3(0.2, -1, 0.1),\n"
      "                             vec3(-0.1, 0.2, 1), vec3(0.2, 0.1, -1));\n"
      "void main() {\n"
      "  ivec2 p = ivec2(gl_FragCoord.xy);\n"
      "  o1 = texelFetch(t1, p.x, 0);\n"
      "  o3 = texelFetch(t3, ivec3(p.x, p.y % 2, p.y % 3), 0);\n"
      "  oa = texelFetch(ta, ivec3(p.x, p.y % 2, p.y % 3), 0);\n"
      "  or_ = texelFetch(tr, p);\n"
      "  oc = texture(tc, dirs[(p.x + p.y) % 6]);\n"
      "}\n";
  s.attributes = {full_screen_pos()};
  s.count = 6;
  s.width = s.height = 4;
  s.outputs = 5;
  s.textures = {t1, t3, ta, tr, tc};
  s.uniforms = {{"t1", {}, {0}, {}},
                {"t3", {}, {1}, {}},
                {"ta", {}, {2}, {}},
                {"tr", {}, {3}, {}},
                {"tc", {3.0f + 1.0f}, {}, {}}};  // f converted to int
  const GlslResult r = run(s);
  EXPECT_RAN(r);
  ASSERT_EQ(r.outputs.size(), 5u);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const float fx = float(x), fy = float(y);
      EXPECT_EQ(px(r.outputs[0], 4, x, y), (Px{1, fx, 0, 0})) << x << "," << y;
      EXPECT_EQ(px(r.outputs[1], 4, x, y), (Px{2, fx, float(y % 2), float(y % 3)})) << x << "," << y;
      EXPECT_EQ(px(r.outputs[2], 4, x, y), (Px{3, fx, float(y % 2), float(y % 3)})) << x << "," << y;
      EXPECT_EQ(px(r.outputs[3], 4, x, y), (Px{4, fx, fy, 0})) << x << "," << y;
      EXPECT_EQ(px(r.outputs[4], 4, x, y), (Px{5, float((x + y) % 6), 0, 0})) << x << "," << y;
    }
}

// A DEPTH_COMPONENT32F texture with GL_LEQUAL compare: texels 0.25 and 0.75 against
// reference 0.5 give 0 and 1.
TEST_F(GlslOracleTest, ShadowCompare) {
  GlslTexture t;
  t.width = 2;
  t.height = 1;
  t.internal_format = kGL_DEPTH_COMPONENT32F;
  t.data = {0.25f, 0.75f};
  t.compare = true;
  t.compare_func = kGL_LEQUAL;
  t.wrap = kGL_CLAMP_TO_EDGE;
  GlslDrawSpec s;
  s.vertex = kVs330;
  s.fragment =
      "#version 330 core\n"
      "uniform sampler2DShadow ts;\n"
      "out vec4 o;\n"
      "void main() { o = vec4(texture(ts, vec3(gl_FragCoord.x / 2.0, 0.5, 0.5))); }\n";
  s.attributes = {full_screen_pos()};
  s.count = 6;
  s.width = 2;
  s.height = 1;
  s.textures = {t};
  s.uniforms = {{"ts", {}, {0}, {}}};
  const GlslResult r = run(s);
  EXPECT_RAN(r);
  EXPECT_EQ(px(r.outputs[0], 2, 0, 0), (Px{0, 0, 0, 0}));
  EXPECT_EQ(px(r.outputs[0], 2, 1, 0), (Px{1, 1, 1, 1}));
}

// Problems are reported, not hidden: too little attribute data (nothing drawn), and a GL
// error (a non-array float given 2 values: GL_INVALID_OPERATION from glUniform1fv).
TEST_F(GlslOracleTest, BadSpecAndGlErrorsAreReported) {
  GlslDrawSpec s;
  s.vertex = kVs330;
  s.fragment =
      "#version 330 core\n"
      "uniform float k;\n"
      "out vec4 o;\n"
      "void main() { o = vec4(k); }\n";
  s.attributes = {full_screen_pos()};
  s.count = 7;  // 14 floats needed, 12 given
  GlslResult r = run(s);
  EXPECT_TRUE(r.compiled && r.linked) << r.log;
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(r.outputs.empty());
  EXPECT_NE(r.log.find("attribute 'pos'"), std::string::npos) << r.log;

  s.count = 6;
  s.uniforms = {{"k", {1, 2}, {}, {}}};
  r = run(s);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.log.find("GL_INVALID_OPERATION"), std::string::npos) << r.log;
  std::printf("GL error log:\n%s", r.log.c_str());

  // Nothing of that sticks: a good spec afterwards is ok.
  s.uniforms = {{"k", {0.75f}, {}, {}}};
  r = run(s);
  EXPECT_RAN(r);
  EXPECT_EQ(px(r.outputs[0], 16, 7, 7), (Px{0.75f, 0.75f, 0.75f, 0.75f}));
}

}  // namespace
