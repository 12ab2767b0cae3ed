// Per-sample operations: every depth function, every stencil op, every blend equation and
// factor, write masks, scissor, polygon offset, multiple render targets.
#include <gtest/gtest.h>

#include "shaders.hpp"
#include "tessel/gpu/image.hpp"

using namespace tessel::test;

namespace {

constexpr int W = 8, H = 8;

TestVertex q(float x, float y, float z, glm::vec4 c) {
  TestVertex v{};
  v.pos[0] = x; v.pos[1] = y; v.pos[2] = z; v.pos[3] = 1.0f;
  v.color[0] = c.r; v.color[1] = c.g; v.color[2] = c.b; v.color[3] = c.a;
  return v;
}

// A full-screen quad at ndc depth z (or a plane from z0 at the left to z1 at the right).
std::vector<TestVertex> quad(float z0, glm::vec4 c, float z1 = NAN) {
  if (std::isnan(z1)) z1 = z0;
  return {q(-1, -1, z0, c), q(1, -1, z1, c), q(1, 1, z1, c), q(-1, -1, z0, c), q(1, 1, z1, c), q(-1, 1, z0, c)};
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
  struct Case { CompareFunc f; bool pass_less, pass_equal, pass_greater; };
  const Case cases[] = {
      {CompareFunc::Never, false, false, false}, {CompareFunc::Less, true, false, false},
      {CompareFunc::Equal, false, true, false},  {CompareFunc::LessEqual, true, true, false},
      {CompareFunc::Greater, false, false, true}, {CompareFunc::NotEqual, true, false, true},
      {CompareFunc::GreaterEqual, false, true, true}, {CompareFunc::Always, true, true, true},
  };
  for (const Case& c : cases) {
    // Stored depth 0.5 (ndc 0); incoming 0.25, 0.5 and 0.75.
    const std::pair<float, bool> tries[] = {{-0.5f, c.pass_less}, {0.0f, c.pass_equal}, {0.5f, c.pass_greater}};
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
  struct Case { StencilOp op; int from; int expect; };
  const Case cases[] = {
      {StencilOp::Keep, 5, 5},       {StencilOp::Zero, 5, 0},      {StencilOp::Replace, 5, 9},
      {StencilOp::Incr, 255, 255},   {StencilOp::Incr, 5, 6},      {StencilOp::IncrWrap, 255, 0},
      {StencilOp::Decr, 0, 0},       {StencilOp::Decr, 5, 4},      {StencilOp::DecrWrap, 0, 255},
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
  st.stencil_front = {.func = CompareFunc::Equal, .ref = 0x3F, .read_mask = 0x0F, .write_mask = 0xF0,
                      .pass = StencilOp::Invert};
  st.stencil_back = {.func = CompareFunc::Never};
  fx.draw(quad(0, {1, 1, 1, 1}), st);
  EXPECT_EQ(fx.pixel().r, 1.0f);       // (0x3F & 0x0F) == (0x0F & 0x0F)
  EXPECT_EQ(fx.stencil(), 0xFF);       // ~0x0F = 0xF0, only the high bits written: 0xF0 | 0x0F
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
      st.blend[0] = {.enabled = true, .eq_rgb = BlendEquation(eq), .eq_alpha = BlendEquation(eq),
                     .src_rgb = s, .dst_rgb = d, .src_alpha = s, .dst_alpha = d};
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
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 1e-5f) << "eq " << eq << " src " << sf << " ch " << c;
    }
  }
}

TEST(Blend, UnormTargetsClampAndRound) {
  Fixture fx;
  fx.ctx.clear({.color = {0.5f, 0.5f, 0.5f, 0.5f}});
  RenderState st;
  st.blend[0] = {.enabled = true, .src_rgb = BlendFactor::One, .dst_rgb = BlendFactor::One,
                 .src_alpha = BlendFactor::One, .dst_alpha = BlendFactor::Zero};
  fx.draw(quad(0, {0.7f, -0.3f, 0.2f, 2.0f}), st);
  const glm::vec4 p = fx.pixel();
  EXPECT_EQ(p.r, 1.0f);                      // 0.7 + 0.5 clamped
  EXPECT_NEAR(p.g, 128.0f / 255.0f, 1e-6f);  // source clamped to 0 first
  EXPECT_NEAR(p.b, 179.0f / 255.0f, 1e-6f);  // 0.2 + 128/255 = 0.702 -> 179
  EXPECT_EQ(p.a, 1.0f);
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
  template <class F> struct Varyings { Vec4<F> color; };
  static constexpr int outputs = 3;
  template <class F> Vec4<F> vertex(const Uniforms&, const VertexIn<F>& in, Varyings<F>& out) const {
    out.color = in.attr[1];
    return in.attr[0];
  }
  template <class F> void fragment(const Uniforms&, const Varyings<F>& v, Fragment<F>& f) const {
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
  EXPECT_EQ(b.fetch(0, 1, 1).g, 0.0f);  // masked
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
  template <class F> struct Varyings { Vec4<F> color; };
  static constexpr bool discards = true;
  static constexpr bool writes_depth = true;
  template <class F> Vec4<F> vertex(const Uniforms&, const VertexIn<F>& in, Varyings<F>& out) const {
    out.color = in.attr[1];
    return in.attr[0];
  }
  template <class F> void fragment(const Uniforms&, const Varyings<F>& v, Fragment<F>& f) const {
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
  EXPECT_NEAR(fx.depth(6, 2), 0.4f, 1e-6f);           // the shader's depth, not the plane's
  EXPECT_NEAR(fx.depth(2, 2), 0.6f, 1e-6f);           // discarded fragments write nothing
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
