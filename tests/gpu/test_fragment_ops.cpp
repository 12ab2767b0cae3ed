// Per-sample operations: every depth function, every stencil op, every blend equation and
// factor, write masks, scissor, polygon offset, multiple render targets.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "shaders.hpp"
#include "stages.hpp"
#include "tessel/gpu/image.hpp"

using namespace tessel::test;

namespace {

constexpr int W = 8, H = 8;

TestVertex q(float x, float y, float z, glm::vec4 c) {
  TestVertex v{};
  v.pos[0] = x;
  v.pos[1] = y;
  v.pos[2] = z;
  v.pos[3] = 1.0f;
  v.color[0] = c.r;
  v.color[1] = c.g;
  v.color[2] = c.b;
  v.color[3] = c.a;
  return v;
}

// A full-screen quad at ndc depth z (or a plane from z0 at the left to z1 at the right).
std::vector<TestVertex> quad(float z0, glm::vec4 c, float z1 = NAN) {
  if (std::isnan(z1)) z1 = z0;
  return {q(-1, -1, z0, c), q(1, -1, z1, c), q(1, 1, z1, c),
          q(-1, -1, z0, c), q(1, 1, z1, c),  q(-1, 1, z0, c)};
}

struct Fixture {
  Target t{W, H};
  Context ctx{2};
  Fixture() { ctx.bind_framebuffer(&t.fb); }
  void draw(const std::vector<TestVertex>& v, const RenderState& st) {
    Mesh m(v);
    ctx.draw(ColorShader{}, {}, m.layout, st, {.count = m.count});
  }
  glm::vec4 pixel(int x = 3, int y = 3) {
    ctx.finish();
    return t.color.fetch(0, x, y);
  }
  float depth(int x = 3, int y = 3) {
    ctx.finish();
    return t.depth.fetch(0, x, y).x;
  }
  int stencil(int x = 3, int y = 3) {
    ctx.finish();
    return int(t.depth.fetch(0, x, y).y);
  }
};

}  // namespace

TEST(DepthTest, AllEightFunctions) {
  struct Case {
    CompareFunc f;
    bool pass_less, pass_equal, pass_greater;
  };
  const Case cases[] = {
      {CompareFunc::Never, false, false, false},      {CompareFunc::Less, true, false, false},
      {CompareFunc::Equal, false, true, false},       {CompareFunc::LessEqual, true, true, false},
      {CompareFunc::Greater, false, false, true},     {CompareFunc::NotEqual, true, false, true},
      {CompareFunc::GreaterEqual, false, true, true}, {CompareFunc::Always, true, true, true},
  };
  for (const Case& c : cases) {
    // Stored depth 0.5 (ndc 0); incoming 0.25, 0.5 and 0.75.
    const std::pair<float, bool> tries[] = {
        {-0.5f, c.pass_less}, {0.0f, c.pass_equal}, {0.5f, c.pass_greater}};
    for (auto [z, pass] : tries) {
      Fixture fx;
      fx.ctx.clear({.color = {0, 0, 0, 1}, .depth = 0.5f});
      RenderState st;
      st.depth_test = true;
      st.depth_func = c.f;
      fx.draw(quad(z, {1, 1, 1, 1}), st);
      EXPECT_EQ(fx.pixel().r, pass ? 1.0f : 0.0f) << "func " << int(c.f) << " z " << z;
      EXPECT_NEAR(fx.depth(), pass ? (z + 1) * 0.5f : 0.5f, 1e-6f);
    }
  }
}

TEST(DepthTest, WriteMaskAndDisabledTestLeaveDepth) {
  Fixture fx;
  fx.ctx.clear({.depth = 0.5f});
  RenderState st;
  st.depth_test = true;
  st.depth_write = false;
  fx.draw(quad(-0.5f, {1, 0, 0, 1}), st);
  EXPECT_EQ(fx.pixel().r, 1.0f);
  EXPECT_NEAR(fx.depth(), 0.5f, 1e-6f);
  st = RenderState{};  // depth test off: never writes depth (GL 4.6 §17.3.4)
  fx.draw(quad(-0.8f, {0, 1, 0, 1}), st);
  EXPECT_NEAR(fx.depth(), 0.5f, 1e-6f);
}

TEST(DepthTest, InterpolatesLinearlyInScreenSpace) {
  Fixture fx;
  fx.ctx.clear({.depth = 1.0f});
  RenderState st;
  st.depth_test = true;
  st.depth_func = CompareFunc::Always;
  fx.draw(quad(-1.0f, {1, 1, 1, 1}, 1.0f), st);  // depth 0 at x = -1 to 1 at x = +1
  for (int x = 0; x < W; ++x) EXPECT_NEAR(fx.depth(x, 2), (x + 0.5f) / W, 1.5e-7f * 8) << x;
}

TEST(Stencil, AllEightOps) {
  struct Case {
    StencilOp op;
    int from;
    int expect;
  };
  const Case cases[] = {
      {StencilOp::Keep, 5, 5},     {StencilOp::Zero, 5, 0}, {StencilOp::Replace, 5, 9},
      {StencilOp::Incr, 255, 255}, {StencilOp::Incr, 5, 6}, {StencilOp::IncrWrap, 255, 0},
      {StencilOp::Decr, 0, 0},     {StencilOp::Decr, 5, 4}, {StencilOp::DecrWrap, 0, 255},
      {StencilOp::Invert, 5, 250},
  };
  for (const Case& c : cases) {
    // The op as the pass op, the stencil-fail op and the depth-fail op.
    for (int which = 0; which < 3; ++which) {
      Fixture fx;
      fx.ctx.clear({.depth = 0.5f, .stencil = uint8_t(c.from)});
      RenderState st;
      st.stencil_test = true;
      st.depth_test = true;
      StencilFace f;
      f.ref = 9;
      f.func = which == 1 ? CompareFunc::Never : CompareFunc::Always;
      if (which == 0) f.pass = c.op;
      if (which == 1) f.fail = c.op;
      if (which == 2) f.depth_fail = c.op;
      st.stencil_front = st.stencil_back = f;
      fx.draw(quad(which == 2 ? 0.5f : -0.5f, {1, 1, 1, 1}), st);  // depth fails only for which == 2
      EXPECT_EQ(fx.stencil(), c.expect) << "op " << int(c.op) << " from " << c.from << " as " << which;
      EXPECT_EQ(fx.pixel().r, which == 0 ? 1.0f : 0.0f);
    }
  }
}

TEST(Stencil, FuncMasksAndFaces) {
  Fixture fx;
  fx.ctx.clear({.stencil = 0x0F});
  RenderState st;
  st.stencil_test = true;
  st.stencil_front = {.func = CompareFunc::Equal,
                      .ref = 0x3F,
                      .read_mask = 0x0F,
                      .write_mask = 0xF0,
                      .pass = StencilOp::Invert};
  st.stencil_back = {.func = CompareFunc::Never};
  fx.draw(quad(0, {1, 1, 1, 1}), st);
  EXPECT_EQ(fx.pixel().r, 1.0f);  // (0x3F & 0x0F) == (0x0F & 0x0F)
  EXPECT_EQ(fx.stencil(), 0xFF);  // ~0x0F = 0xF0, only the high bits written: 0xF0 | 0x0F
  // Back faces use the back state: Never.
  std::vector<TestVertex> back = quad(0, {0, 1, 0, 1});
  for (size_t i = 0; i < back.size(); i += 3) std::swap(back[i + 1], back[i + 2]);
  fx.draw(back, st);
  EXPECT_EQ(fx.pixel(), glm::vec4(1, 1, 1, 1));  // still the first draw's white
}

TEST(Blend, EveryEquationAndFactor) {
  const glm::vec4 src(0.8f, 0.4f, 0.2f, 0.6f), dst(0.2f, 0.6f, 1.0f, 0.4f), k(0.3f, 0.5f, 0.7f, 0.25f);
  auto fac = [&](BlendFactor f) -> glm::vec4 {
    switch (f) {
      case BlendFactor::Zero: return glm::vec4(0);
      case BlendFactor::One: return glm::vec4(1);
      case BlendFactor::SrcColor: return src;
      case BlendFactor::OneMinusSrcColor: return glm::vec4(1) - src;
      case BlendFactor::DstColor: return dst;
      case BlendFactor::OneMinusDstColor: return glm::vec4(1) - dst;
      case BlendFactor::SrcAlpha: return glm::vec4(src.a);
      case BlendFactor::OneMinusSrcAlpha: return glm::vec4(1 - src.a);
      case BlendFactor::DstAlpha: return glm::vec4(dst.a);
      case BlendFactor::OneMinusDstAlpha: return glm::vec4(1 - dst.a);
      case BlendFactor::ConstantColor: return k;
      case BlendFactor::OneMinusConstantColor: return glm::vec4(1) - k;
      case BlendFactor::ConstantAlpha: return glm::vec4(k.a);
      case BlendFactor::OneMinusConstantAlpha: return glm::vec4(1 - k.a);
      case BlendFactor::SrcAlphaSaturate: return glm::vec4(glm::vec3(std::min(src.a, 1 - dst.a)), 1.0f);
      // Dual-source factors read a second colour these draws do not have (the loop below
      // stops before them; gl33_dual_source_blending draws them).
      case BlendFactor::Src1Color:
      case BlendFactor::OneMinusSrc1Color:
      case BlendFactor::Src1Alpha:
      case BlendFactor::OneMinusSrc1Alpha: break;
    }
    return glm::vec4(0);
  };
  for (int eq = 0; eq <= int(BlendEquation::Max); ++eq) {
    for (int sf = 0; sf <= int(BlendFactor::SrcAlphaSaturate); ++sf) {
      const BlendFactor s = BlendFactor(sf), d = BlendFactor((sf * 7 + 3) % 15);
      Texture2D color(Format::RGBA32F, W, H);
      Framebuffer fb(&color);
      Context ctx(1);
      ctx.bind_framebuffer(&fb);
      ctx.clear({.color = dst});
      RenderState st;
      st.blend[0] = {.enabled = true,
                     .eq_rgb = BlendEquation(eq),
                     .eq_alpha = BlendEquation(eq),
                     .src_rgb = s,
                     .dst_rgb = d,
                     .src_alpha = s,
                     .dst_alpha = d};
      st.blend_color = k;
      Mesh m(quad(0, src));
      ctx.draw(ColorShader{}, {}, m.layout, st, {.count = m.count});
      ctx.finish();
      const glm::vec4 got = color.fetch(0, 4, 4);
      glm::vec4 fs = fac(s), fd = fac(d);
      glm::vec4 want;
      switch (BlendEquation(eq)) {
        case BlendEquation::Add: want = src * fs + dst * fd; break;
        case BlendEquation::Subtract: want = src * fs - dst * fd; break;
        case BlendEquation::ReverseSubtract: want = dst * fd - src * fs; break;
        case BlendEquation::Min: want = glm::min(src, dst); break;
        case BlendEquation::Max: want = glm::max(src, dst); break;
      }
      // Alpha uses the alpha of each factor.
      for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(got[c], want[c], 1e-5f) << "eq " << eq << " src " << sf << " ch " << c;
    }
  }
}

TEST(Blend, UnormTargetsClampAndRound) {
  Fixture fx;
  fx.ctx.clear({.color = {0.5f, 0.5f, 0.5f, 0.5f}});
  RenderState st;
  st.blend[0] = {.enabled = true,
                 .src_rgb = BlendFactor::One,
                 .dst_rgb = BlendFactor::One,
                 .src_alpha = BlendFactor::One,
                 .dst_alpha = BlendFactor::Zero};
  fx.draw(quad(0, {0.7f, -0.3f, 0.2f, 2.0f}), st);
  const glm::vec4 p = fx.pixel();
  EXPECT_EQ(p.r, 1.0f);                      // 0.7 + 0.5 clamped
  EXPECT_NEAR(p.g, 128.0f / 255.0f, 1e-6f);  // source clamped to 0 first
  EXPECT_NEAR(p.b, 179.0f / 255.0f, 1e-6f);  // 0.2 + 128/255 = 0.702 -> 179
  EXPECT_EQ(p.a, 1.0f);
}

// GL 3.3 §4.1.11: each of the sixteen operations on the 8-bit values of the fragment and the
// buffer, with blending (on) ignored.
TEST(LogicOp, EveryOperationOnUnormBytes) {
  const uint32_t d[4] = {0x5A, 0xF0, 0x0F, 0xFF}, sv[4] = {0x33, 0xCC, 0xFF, 0x00};
  auto expected = [](int op, uint32_t s, uint32_t d) -> uint32_t {
    switch (op) {
      case 0: return 0;
      case 1: return s & d;
      case 2: return s & ~d;
      case 3: return s;
      case 4: return ~s & d;
      case 5: return d;
      case 6: return s ^ d;
      case 7: return s | d;
      case 8: return ~(s | d);
      case 9: return ~(s ^ d);
      case 10: return ~d;
      case 11: return s | ~d;
      case 12: return ~s;
      case 13: return ~s | d;
      case 14: return ~(s & d);
      default: return ~0u;
    }
  };
  for (int op = 0; op < 16; ++op) {
    Fixture fx;
    fx.ctx.clear({.color = glm::vec4(float(d[0]), float(d[1]), float(d[2]), float(d[3])) / 255.0f});
    RenderState st;
    st.logic_op_enabled = true;
    st.logic_op = LogicOp(op);
    st.blend[0].enabled = true;
    st.blend[0].dst_rgb = BlendFactor::One;
    fx.draw(quad(0, glm::vec4(float(sv[0]), float(sv[1]), float(sv[2]), float(sv[3])) / 255.0f), st);
    const glm::vec4 p = fx.pixel();
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(int(std::lrint(p[k] * 255.0f)), int(expected(op, sv[k], d[k]) & 0xFFu))
          << "operation " << op << " component " << k;
  }
}

TEST(WriteMask, ColourChannelsAndScissor) {
  Fixture fx;
  fx.ctx.clear({.color = {0, 0, 0, 0}});
  RenderState st;
  st.blend[0].write_mask = 0b0101;  // red and blue
  st.scissor_test = true;
  st.scissor = {2, 3, 4, 2};
  fx.draw(quad(0, {1, 1, 1, 1}), st);
  fx.ctx.finish();
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const bool in = x >= 2 && x < 6 && y >= 3 && y < 5;
      const glm::vec4 p = fx.t.color.fetch(0, x, y);
      EXPECT_EQ(p, in ? glm::vec4(1, 0, 1, 0) : glm::vec4(0)) << x << "," << y;
    }
  // Clears obey the scissor too.
  fx.ctx.clear({.color = {0, 1, 0, 1}}, st);
  EXPECT_EQ(fx.pixel(3, 3), glm::vec4(0, 0, 0, 0));  // inside, but green is masked: red/blue cleared to 0
  EXPECT_EQ(fx.pixel(0, 0), glm::vec4(0, 0, 0, 0));
}

TEST(PolygonOffset, FactorAndUnits) {
  // A plane with slope dz/dx; the offset is factor * max slope + units * 2^-24 (D24).
  Fixture fx;
  fx.ctx.clear({.depth = 1.0f});
  RenderState st;
  st.depth_test = true;
  st.depth_func = CompareFunc::Always;
  st.offset_fill = true;
  st.offset_factor = 2.0f;
  st.offset_units = 1000.0f;
  fx.draw(quad(-0.5f, {1, 1, 1, 1}, 0.5f), st);  // window z from 0.25 to 0.75 over 8 px
  const float slope = 0.5f / W;
  const float plain = 0.25f + 0.5f * (3.5f / W);
  EXPECT_NEAR(fx.depth(3, 3), plain + 2.0f * slope + 1000.0f / 16777216.0f, 2e-7f);
  // Without offset the same draw lands on `plain`: the test would catch a missing offset.
  st.offset_fill = false;
  fx.draw(quad(-0.5f, {1, 1, 1, 1}, 0.5f), st);
  EXPECT_NEAR(fx.depth(3, 3), plain, 2e-7f);
}

namespace {
struct TwoTargets {
  struct Uniforms {};
  template <class F>
  struct Varyings {
    Vec4<F> color;
  };
  static constexpr int outputs = 3;
  template <class F>
  Vec4<F> vertex(const Uniforms&, const VertexIn<F>& in, Varyings<F>& out) const {
    out.color = in.attr[1];
    return in.attr[0];
  }
  template <class F>
  void fragment(const Uniforms&, const Varyings<F>& v, Fragment<F>& f) const {
    f.color[0] = v.color;
    f.color[1] = Vec4<F>(F(1.0f) - v.color.x, F(0.25f), F(0.5f), F(1.0f));
    f.color[2] = Vec4<F>(f.coord.x, f.coord.y, f.coord.z, F(1.0f));
  }
};
}  // namespace

TEST(MRT, EachOutputToItsAttachment) {
  Texture2D a(Format::RGBA8, W, H), b(Format::RG8, W, H), c(Format::RGBA32F, W, H);
  Framebuffer fb;
  fb.color[0].texture = &a;
  fb.color[1].texture = &b;
  fb.color[2].texture = &c;
  Context ctx(2);
  ctx.bind_framebuffer(&fb);
  ctx.clear({.color = {0, 0, 0, 0}});
  RenderState st;
  st.blend[1].write_mask = 0b0001;  // only red on attachment 1
  Mesh m(quad(0, {0.2f, 0.4f, 0.6f, 1.0f}));
  ctx.draw(TwoTargets{}, {}, m.layout, st, {.count = m.count});
  ctx.finish();
  EXPECT_NEAR(a.fetch(0, 1, 1).r, 51.0f / 255.0f, 1e-6f);
  EXPECT_NEAR(b.fetch(0, 1, 1).r, 204.0f / 255.0f, 1e-6f);
  EXPECT_EQ(b.fetch(0, 1, 1).g, 0.0f);                             // masked
  EXPECT_EQ(c.fetch(0, 5, 2), glm::vec4(5.5f, 2.5f, 0.5f, 1.0f));  // gl_FragCoord
}

TEST(Clear, EachAttachmentItsOwnValue) {
  Texture2D a(Format::RGBA8, W, H), b(Format::RGBA32F, W, H), d(Format::Depth24Stencil8, W, H);
  Framebuffer fb;
  fb.color[0].texture = &a;
  fb.color[1].texture = &b;
  fb.depth.texture = &d;
  Context ctx(1);
  ctx.bind_framebuffer(&fb);
  ClearValues v{.depth = 0.25f, .stencil = 7};
  v.per_attachment = true;
  v.attachment_colors[0] = {1, 0, 0, 1};
  v.attachment_colors[1] = {-2, 0.5f, 3, 1};
  ctx.clear(v);
  ctx.finish();
  EXPECT_EQ(a.fetch(0, 1, 1), glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(b.fetch(0, 7, 7), glm::vec4(-2, 0.5f, 3, 1));  // float targets are not clamped
  EXPECT_NEAR(d.fetch(0, 0, 0).x, 0.25f, 1e-7f);
  EXPECT_EQ(d.fetch(0, 0, 0).y, 7.0f);
  // Only attachment 1, depth untouched.
  ctx.clear({.color_attachments = 0b10, .color = {0, 0, 0, 0}, .clear_depth = false, .clear_stencil = false});
  ctx.finish();
  EXPECT_EQ(a.fetch(0, 1, 1), glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(b.fetch(0, 1, 1), glm::vec4(0));
  EXPECT_NEAR(d.fetch(0, 0, 0).x, 0.25f, 1e-7f);
}

namespace {
// Discards the left half of the screen and writes depth 0.9 - red * 0.5.
struct DiscardAndDepth {
  struct Uniforms {};
  template <class F>
  struct Varyings {
    Vec4<F> color;
  };
  static constexpr bool discards = true;
  static constexpr bool writes_depth = true;
  template <class F>
  Vec4<F> vertex(const Uniforms&, const VertexIn<F>& in, Varyings<F>& out) const {
    out.color = in.attr[1];
    return in.attr[0];
  }
  template <class F>
  void fragment(const Uniforms&, const Varyings<F>& v, Fragment<F>& f) const {
    f.discard(f.coord.x < F(4.0f));
    f.depth = F(0.9f) - v.color.x * F(0.5f);
    f.color[0] = v.color;
  }
};
}  // namespace

TEST(FragmentShader, DiscardAndDepthWriteUseLateTests) {
  Fixture fx;
  fx.ctx.clear({.color = {0, 0, 0, 1}, .depth = 0.6f});
  RenderState st;
  st.depth_test = true;
  Mesh m(quad(-0.9f, {1, 0, 0, 1}));  // interpolated depth 0.05 would pass; written 0.4 passes too
  fx.ctx.draw(DiscardAndDepth{}, {}, m.layout, st, {.count = m.count});
  EXPECT_EQ(fx.pixel(2, 2), glm::vec4(0, 0, 0, 1));  // discarded
  EXPECT_EQ(fx.pixel(6, 2), glm::vec4(1, 0, 0, 1));
  EXPECT_NEAR(fx.depth(6, 2), 0.4f, 1e-6f);  // the shader's depth, not the plane's
  EXPECT_NEAR(fx.depth(2, 2), 0.6f, 1e-6f);  // discarded fragments write nothing
  // Green at written depth 0.9 fails LESS against 0.4 although its plane depth (0.05) passes.
  Mesh g(quad(-0.9f, {0, 1, 0, 1}));
  fx.ctx.draw(DiscardAndDepth{}, {}, g.layout, st, {.count = g.count});
  EXPECT_EQ(fx.pixel(6, 2), glm::vec4(1, 0, 0, 1));
}

TEST(Viewport, MapsNdcToItsRectangleAndDepthRange) {
  Fixture fx;
  fx.ctx.clear({.color = {0, 0, 0, 0}, .depth = 1.0f});
  RenderState st;
  st.viewport = {2, 4, 4, 2};
  st.depth_near = 0.2f;
  st.depth_far = 0.6f;
  st.depth_test = true;
  st.depth_func = CompareFunc::Always;
  fx.draw(quad(0.5f, {1, 1, 1, 1}), st);
  fx.ctx.finish();
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const bool in = x >= 2 && x < 6 && y >= 4 && y < 6;
      EXPECT_EQ(fx.t.color.fetch(0, x, y).r, in ? 1.0f : 0.0f) << x << "," << y;
      if (in) {
        EXPECT_NEAR(fx.t.depth.fetch(0, x, y).x, 0.2f + 0.4f * 0.75f, 1e-6f);
      }
    }
}

// --- clears with scissor and partial write masks, every pixel checked -------------------------

namespace {

std::vector<std::byte> random_bytes(size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<std::byte> v(n);
  for (auto& b : v) b = std::byte(rng() >> 24);
  return v;
}

// Fills level 0 with random bytes; returns them.
std::vector<std::byte> randomize(Texture2D& t, uint32_t seed) {
  std::vector<std::byte> v = random_bytes(t.level(0).data.size(), seed);
  t.upload(0, v.data(), v.size());
  return v;
}

template <class T>
T read_at(const std::vector<std::byte>& v, size_t offset) {
  T x;
  std::memcpy(&x, v.data() + offset, sizeof x);
  return x;
}

uint32_t float_bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

constexpr int CW = 100, CH = 70;              // more than one 64x64 tile each way
constexpr Rect kClearScissor{13, 5, 70, 60};  // x 13..82, y 5..64
bool in_scissor(int x, int y) {
  return x >= kClearScissor.x && x < kClearScissor.x + kClearScissor.width && y >= kClearScissor.y &&
         y < kClearScissor.y + kClearScissor.height;
}

}  // namespace

TEST(Clear, ScissoredPartialMasksRgba8Depth24Stencil8) {
  Texture2D color(Format::RGBA8, CW, CH), ds(Format::Depth24Stencil8, CW, CH);
  Framebuffer fb(&color, &ds);
  Context ctx(2);
  ctx.bind_framebuffer(&fb);
  struct Config {
    bool depth_write, clear_stencil;
    uint8_t color_mask, stencil_mask;
  };
  const Config configs[] = {
      {true, true, 0b1010, 0x3C},   // depth and part of the stencil
      {false, true, 0b0001, 0x81},  // only part of the stencil
      {true, false, 0b0110, 0xFF},  // only depth, stencil kept
      {true, true, 0b1111, 0xFF},   // everything (plain fill)
      {true, true, 0b0000, 0x00},   // colour and stencil masked off: depth only
  };
  const glm::vec4 clear_color{0.2f, 0.4f, 0.6f, 0.8f};
  const uint8_t want_rgba[4] = {51, 102, 153, 204};
  const uint32_t want_z = uint32_t(std::lrint(double(0.3f) * 16777215.0));
  uint32_t seed = 10;
  for (const Config& cfg : configs) {
    const std::vector<std::byte> c0 = randomize(color, seed++), d0 = randomize(ds, seed++);
    RenderState st;
    st.scissor_test = true;
    st.scissor = kClearScissor;
    st.depth_write = cfg.depth_write;
    st.blend[0].write_mask = cfg.color_mask;
    st.stencil_front.write_mask = cfg.stencil_mask;
    ctx.clear({.color = clear_color, .depth = 0.3f, .clear_stencil = cfg.clear_stencil, .stencil = 0xA5}, st);
    ctx.finish();
    const std::vector<std::byte>& c1 = color.level(0).data;
    const std::vector<std::byte>& d1 = ds.level(0).data;
    for (int y = 0; y < CH; ++y)
      for (int x = 0; x < CW; ++x) {
        const size_t o = (size_t(y) * CW + size_t(x)) * 4;
        const bool in = in_scissor(x, y);
        for (int ch = 0; ch < 4; ++ch) {
          const uint8_t old = uint8_t(c0[o + size_t(ch)]);
          const uint8_t want = in && (cfg.color_mask & (1 << ch)) ? want_rgba[ch] : old;
          ASSERT_EQ(uint8_t(c1[o + size_t(ch)]), want) << x << "," << y << " channel " << ch;
        }
        const uint32_t old = read_at<uint32_t>(d0, o);
        uint32_t want = old;
        if (in) {
          if (cfg.depth_write) want = (want & 0xFF000000u) | want_z;
          if (cfg.clear_stencil) {
            const uint32_t m = uint32_t(cfg.stencil_mask) << 24;
            want = (want & ~m) | ((0xA5u << 24) & m);
          }
        }
        ASSERT_EQ(read_at<uint32_t>(d1, o), want) << x << "," << y;
      }
  }
  EXPECT_NEAR(ds.fetch(0, 40, 40).x, 0.3f, 1e-7f);
}

TEST(Clear, ScissoredPartialMasksFloatAndByteTargetsDepth32F) {
  Texture2D h(Format::RGBA16F, CW, CH), f(Format::RGBA32F, CW, CH), r(Format::R8, CW, CH),
      rg(Format::RG8, CW, CH), d(Format::Depth32F, CW, CH);
  Framebuffer fb;
  fb.color[0].texture = &h;
  fb.color[1].texture = &f;
  fb.color[2].texture = &r;
  fb.color[3].texture = &rg;
  fb.depth.texture = &d;
  Context ctx(2);
  ctx.bind_framebuffer(&fb);
  const glm::vec4 clear_color{-1.5f, 0.1f, 70000.0f, 0.3f};  // 70000 is infinity in half
  struct Config {
    bool depth_write;
    uint8_t masks[4];
  };
  const Config configs[] = {
      {true, {0b0101, 0b1110, 0b0001, 0b0010}},
      {false, {0b1010, 0b0001, 0b1110, 0b0001}},  // R8: only masked-off channels -> unchanged
      {true, {0b1111, 0b1111, 0b1111, 0b1111}},
  };
  uint32_t seed = 100;
  for (const Config& cfg : configs) {
    Texture2D* tex[4] = {&h, &f, &r, &rg};
    std::vector<std::byte> before[4];
    for (int i = 0; i < 4; ++i) before[i] = randomize(*tex[i], seed++);
    const std::vector<std::byte> d0 = randomize(d, seed++);
    RenderState st;
    st.scissor_test = true;
    st.scissor = kClearScissor;
    st.depth_write = cfg.depth_write;
    st.stencil_front.write_mask = 0x0F;  // no stencil in Depth32F: ignored
    for (int i = 0; i < 4; ++i) st.blend[i].write_mask = cfg.masks[i];
    ctx.clear({.color = clear_color, .depth = 1.5f, .stencil = 0xFF}, st);  // depth clamps to 1
    ctx.finish();
    for (int y = 0; y < CH; ++y)
      for (int x = 0; x < CW; ++x) {
        const bool in = in_scissor(x, y);
        const size_t px = size_t(y) * CW + size_t(x);
        for (int c = 0; c < 4; ++c) {
          const bool w = in && (cfg.masks[0] & (1 << c));
          const uint16_t old = read_at<uint16_t>(before[0], px * 8 + size_t(c) * 2);
          ASSERT_EQ(read_at<uint16_t>(h.level(0).data, px * 8 + size_t(c) * 2),
                    w ? float_to_half(clear_color[c]) : old)
              << "RGBA16F " << x << "," << y << " channel " << c;
        }
        for (int c = 0; c < 4; ++c) {
          const bool w = in && (cfg.masks[1] & (1 << c));
          const uint32_t old = read_at<uint32_t>(before[1], px * 16 + size_t(c) * 4);
          ASSERT_EQ(read_at<uint32_t>(f.level(0).data, px * 16 + size_t(c) * 4),
                    w ? float_bits(clear_color[c]) : old)
              << "RGBA32F " << x << "," << y << " channel " << c;
        }
        {
          const bool w = in && (cfg.masks[2] & 1);
          ASSERT_EQ(uint8_t(r.level(0).data[px]), w ? uint8_t(0) : uint8_t(before[2][px]))
              << "R8 " << x << "," << y;
        }
        for (int c = 0; c < 2; ++c) {
          const bool w = in && (cfg.masks[3] & (1 << c));
          const uint8_t want =
              w ? uint8_t(c == 0 ? 0 : 26) : uint8_t(before[3][px * 2 + size_t(c)]);  // 0.1 -> 26
          ASSERT_EQ(uint8_t(rg.level(0).data[px * 2 + size_t(c)]), want)
              << "RG8 " << x << "," << y << " channel " << c;
        }
        const uint32_t want_d = in && cfg.depth_write ? float_bits(1.0f) : read_at<uint32_t>(d0, px * 4);
        ASSERT_EQ(read_at<uint32_t>(d.level(0).data, px * 4), want_d) << "Depth32F " << x << "," << y;
      }
  }
}

namespace {

// The per-pixel clear as it was written first (store_color per pixel): the reference that
// clear_rect must match bit for bit.
void reference_clear(const detail::TargetView& t, const detail::ClearPrim& c, int x0, int y0, int x1,
                     int y1) {
  for (int i = 0; i < t.color_count; ++i) {
    const detail::ColorTarget& ct = t.color[i];
    if (!(c.color_mask_bits & (1u << i)) || !ct.data || !c.write_mask[i]) continue;
    const size_t bytes = format_info(ct.format).bytes;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        std::byte* p = ct.data + size_t(y) * ct.row_bytes + size_t(x) * bytes;
        glm::vec4 v = c.color[i];
        if ((c.write_mask[i] & 0xF) != 0xF) {
          const glm::vec4 old = detail::decode_texel(ct.format, p);
          for (int k = 0; k < 4; ++k)
            if (!(c.write_mask[i] & (1 << k))) v[k] = old[k];
        }
        detail::encode_texel(ct.format, p, v);
      }
  }
  if (t.depth && (c.clear_depth || (c.clear_stencil && t.has_stencil))) {
    const float z = std::clamp(c.depth, 0.0f, 1.0f);
    uint32_t zbits;
    if (t.depth_format == Format::Depth32F)
      std::memcpy(&zbits, &z, 4);
    else
      zbits = uint32_t(std::lrint(double(z) * 16777215.0));
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        std::byte* p = t.depth + size_t(y) * t.depth_row_bytes + size_t(x) * 4;
        uint32_t w;
        std::memcpy(&w, p, 4);
        if (c.clear_depth) w = t.depth_format == Format::Depth32F ? zbits : ((w & 0xFF000000u) | zbits);
        if (c.clear_stencil && t.has_stencil) {
          const uint8_t s = uint8_t(w >> 24);
          const uint8_t m = c.stencil_write_mask;
          w = (w & 0x00FFFFFFu) | (uint32_t(uint8_t((s & ~m) | (c.stencil & m))) << 24);
        }
        std::memcpy(p, &w, 4);
      }
  }
}

// An image with padded rows (the padding must stay untouched).
struct PaddedImage {
  size_t row_bytes;
  std::vector<std::byte> data;
  PaddedImage(int w, int h, size_t bytes, uint32_t seed)
      : row_bytes(size_t(w) * bytes + 24), data(random_bytes(row_bytes * size_t(h), seed)) {}
};

}  // namespace

TEST(ClearRect, MatchesPerPixelReferenceForEveryFormatAndMask) {
  constexpr int w = 83, h = 9;
  const Format colors[] = {Format::RGBA8, Format::R8, Format::RG8, Format::RGBA16F, Format::RGBA32F};
  const glm::vec4 values[] = {
      {0.2f, 0.4f, 0.6f, 0.8f}, {-3.0f, 1.5f, NAN, 65519.0f}, {1e-6f, -0.0f, 0.5f, 1.0f}};
  struct R {
    int x0, y0, x1, y1;
  };
  const R rects[] = {{0, 0, w, h}, {3, 1, 80, 8}, {17, 2, 18, 3}, {5, 4, 22, 9}};
  uint32_t seed = 1000;
  for (Format f : colors)
    for (unsigned mask = 1; mask < 16; ++mask)
      for (const glm::vec4& v : values)
        for (const R& r : rects) {
          const size_t bytes = format_info(f).bytes;
          PaddedImage a(w, h, bytes, seed++);
          PaddedImage b = a;
          detail::ClearPrim c;
          c.color_mask_bits = 0b10;
          c.color[1] = v;
          c.write_mask[1] = uint8_t(mask);
          detail::TargetView ta;
          ta.width = w;
          ta.height = h;
          ta.color_count = 2;
          ta.color[1] = {a.data.data(), a.row_bytes, f};
          detail::TargetView tb = ta;
          tb.color[1].data = b.data.data();
          detail::clear_rect(ta, c, r.x0, r.y0, r.x1, r.y1);
          reference_clear(tb, c, r.x0, r.y0, r.x1, r.y1);
          ASSERT_TRUE(a.data == b.data) << format_info(f).name << " mask " << mask << " rect " << r.x0 << ","
                                        << r.y0 << "-" << r.x1 << "," << r.y1;
        }
  // Every half (NaNs included) and every byte value survives a partially masked clear.
  for (unsigned mask = 1; mask < 15; ++mask) {
    for (Format f : {Format::RGBA16F, Format::RGBA8}) {
      const int side = f == Format::RGBA16F ? 128 : 8;  // 128 * 128 * 4 halves = all 65536
      detail::ColorTarget ct{nullptr, size_t(side) * format_info(f).bytes, f};
      std::vector<std::byte> a(ct.row_bytes * size_t(side));
      for (size_t i = 0; i < a.size() / 2; ++i) {
        const uint16_t u = f == Format::RGBA16F
                               ? uint16_t(i)
                               : uint16_t((2 * i) & 0xFF) | uint16_t(((2 * i + 1) & 0xFF) << 8);
        std::memcpy(a.data() + 2 * i, &u, 2);
      }
      std::vector<std::byte> b = a;
      detail::ClearPrim c;
      c.color_mask_bits = 1;
      c.color[0] = {0.25f, 0.5f, 0.75f, 1.0f};
      c.write_mask[0] = uint8_t(mask);
      detail::TargetView ta;
      ta.width = ta.height = side;
      ta.color_count = 1;
      ct.data = a.data();
      ta.color[0] = ct;
      detail::TargetView tb = ta;
      tb.color[0].data = b.data();
      detail::clear_rect(ta, c, 0, 0, side, side);
      reference_clear(tb, c, 0, 0, side, side);
      ASSERT_TRUE(a == b) << format_info(f).name << " mask " << mask;
    }
  }
  // Depth and stencil.
  const Format depths[] = {Format::Depth24, Format::Depth32F, Format::Depth24Stencil8};
  for (Format f : depths)
    for (int clear_depth = 0; clear_depth < 2; ++clear_depth)
      for (int clear_stencil = 0; clear_stencil < 2; ++clear_stencil)
        for (uint8_t smask : {uint8_t(0xFF), uint8_t(0x00), uint8_t(0x5A)})
          for (float z : {0.3f, -1.0f, 2.0f, 1.0f / 3.0f})
            for (const R& r : rects) {
              PaddedImage a(w, h, 4, seed++);
              PaddedImage b = a;
              detail::ClearPrim c;
              c.clear_depth = clear_depth;
              c.depth = z;
              c.clear_stencil = clear_stencil;
              c.stencil = 0xC3;
              c.stencil_write_mask = smask;
              detail::TargetView ta;
              ta.width = w;
              ta.height = h;
              ta.depth = a.data.data();
              ta.depth_row_bytes = a.row_bytes;
              ta.depth_format = f;
              ta.has_stencil = f == Format::Depth24Stencil8;
              detail::TargetView tb = ta;
              tb.depth = b.data.data();
              detail::clear_rect(ta, c, r.x0, r.y0, r.x1, r.y1);
              reference_clear(tb, c, r.x0, r.y0, r.x1, r.y1);
              ASSERT_TRUE(a.data == b.data) << format_info(f).name << " depth " << clear_depth << " stencil "
                                            << clear_stencil << " mask " << int(smask) << " z " << z;
            }
}

// Clears and tile copies into the target with non-temporal stores write what the plain ones
// write, on 16-byte aligned rows (streamed) and on rows that are not (the plain fallback).
TEST(ClearRect, StreamedStoresWriteWhatPlainStoresWrite) {
  struct R {
    int x0, y0, x1, y1;
  };
  const R rects[] = {{0, 0, 64, 8}, {4, 1, 36, 7}, {1, 2, 30, 5}, {16, 0, 17, 8}};
  uint32_t seed = 7000;
  for (Format f : {Format::RGBA8, Format::RGBA32F, Format::Depth24Stencil8, Format::Depth32F})
    for (size_t pad : {size_t(0), size_t(4)})
      for (const R& r : rects) {
        const bool depth = f == Format::Depth24Stencil8 || f == Format::Depth32F;
        const size_t bytes = format_info(f).bytes, row = 64 * bytes + pad;
        // 16-byte aligned storage (operator new aligns vectors to 16) plus an optional pad.
        std::vector<std::byte> a = random_bytes(row * 8, seed++), b = a;
        detail::ClearPrim c;
        c.color_mask_bits = 1;
        c.color[0] = {0.2f, 0.4f, 0.6f, 0.8f};
        c.write_mask[0] = 0xF;
        c.clear_depth = c.clear_stencil = true;
        c.depth = 0.3f;
        detail::TargetView ta;
        ta.width = 64;
        ta.height = 8;
        if (depth) {
          ta.depth_row_bytes = row;
          ta.depth_format = f;
          ta.has_stencil = f == Format::Depth24Stencil8;
        } else {
          ta.color_count = 1;
          ta.color[0] = {nullptr, row, f};
        }
        detail::TargetView tb = ta;
        (depth ? ta.depth : ta.color[0].data) = a.data();
        (depth ? tb.depth : tb.color[0].data) = b.data();
        detail::clear_rect(ta, c, r.x0, r.y0, r.x1, r.y1, true);
        detail::clear_rect(tb, c, r.x0, r.y0, r.x1, r.y1, false);
        ASSERT_TRUE(a == b) << format_info(f).name << " pad " << pad << " rect " << r.x0 << "," << r.y0;
        // A tile copied out, streamed and plain.
        const std::vector<std::byte> tile = random_bytes(64 * bytes * 8, seed++);
        const size_t off = size_t(r.y0) * row + size_t(r.x0) * bytes, n = size_t(r.x1 - r.x0) * bytes;
        detail::copy_rows(a.data() + off, row, tile.data(), 64 * bytes, n, r.y1 - r.y0, true);
        detail::copy_rows(b.data() + off, row, tile.data(), 64 * bytes, n, r.y1 - r.y0, false);
        ASSERT_TRUE(a == b) << format_info(f).name << " pad " << pad << " copy " << r.x0 << "," << r.y0;
      }
}
