// Bad draws return an error or drop the primitive; they never crash or read out of bounds.
// This file also runs in the sanitizer build (AddressSanitizer + UBSan) in CI.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "shaders.hpp"
#include "tessel/gpu/image.hpp"

using namespace tessel::test;

namespace {

TestVertex tv(float x, float y, float z, float w) {
  TestVertex v{};
  v.pos[0] = x;
  v.pos[1] = y;
  v.pos[2] = z;
  v.pos[3] = w;
  v.color[0] = v.color[3] = 1.0f;
  return v;
}

struct Scene {
  Target t{16, 16};
  Context ctx{2};
  Scene() {
    ctx.bind_framebuffer(&t.fb);
    ctx.clear({.color = {0, 0, 0, 0}});
  }
  size_t lit() {
    ctx.finish();
    const auto p = read_rgba8(t.color);
    size_t n = 0;
    for (size_t i = 3; i < p.size(); i += 4) n += p[i] != 0;
    return n;
  }
};

}  // namespace

TEST(Robustness, IndexOutOfRangeIsAnError) {
  Scene s;
  Mesh m({tv(-1, -1, 0, 1), tv(1, -1, 0, 1), tv(0, 1, 0, 1)});
  const uint32_t idx[] = {0, 1, 3};
  const Buffer ib(idx, sizeof idx);
  try {
    s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 3, .index_buffer = &ib});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("vertex attribute 0"), std::string::npos) << e.what();
  }
  // Index buffer too short for the count.
  EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 6, .index_buffer = &ib}),
               Error);
  // Vertex range past the buffer.
  EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.first = 1, .count = 3}), Error);
  // Base vertex making an index negative.
  EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{},
                          {.count = 3, .index_buffer = &ib, .base_vertex = -5}),
               Error);
  EXPECT_EQ(s.lit(), 0u);  // nothing was queued
}

// Draws read 32-bit index buffers in place and remember each range's largest index: a
// change to the buffer runs the queued draw first (with the old indices), and the next draw
// checks the new ones.
TEST(Robustness, IndexBufferChangedAfterADrawIsReadAsItWasAndCheckedAgain) {
  Scene s;
  Mesh m({tv(-1, -1, 0, 1), tv(1, -1, 0, 1), tv(-1, 1, 0, 1), tv(1, 1, 0, 1)});
  const uint32_t lower[] = {0, 1, 2};
  Buffer ib(lower, sizeof lower);
  s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 3, .index_buffer = &ib});
  const uint32_t upper[] = {1, 3, 2};
  ib.update(0, upper, sizeof upper);  // the lower-left triangle is drawn before this
  // The lower-left half without the 16 pixels on the diagonal (which the fill rule gives to
  // the upper-right triangle, 136 pixels).
  EXPECT_EQ(s.lit(), 120u);
  const uint32_t bad[] = {1, 4, 2};
  ib.update(0, bad, sizeof bad);
  try {
    s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 3, .index_buffer = &ib});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("vertex attribute 0"), std::string::npos) << e.what();
  }
  ib.update(0, upper, sizeof upper);
  s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 3, .index_buffer = &ib});
  EXPECT_EQ(s.lit(), 16u * 16u);
}

TEST(Robustness, MissingAttributeIsAnError) {
  Scene s;
  Mesh m({tv(-1, -1, 0, 1), tv(1, -1, 0, 1), tv(0, 1, 0, 1)});
  VertexLayout layout = m.layout;
  layout.attribs[1].enabled = false;  // ColorShader reads attribute 1
  EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, layout, RenderState{}, {.count = 3}), Error);
  layout = m.layout;
  layout.bindings[0].buffer = nullptr;
  EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, layout, RenderState{}, {.count = 3}), Error);
  layout = m.layout;
  layout.attribs[0].components = 7;
  EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, layout, RenderState{}, {.count = 3}), Error);
}

TEST(Robustness, IncompleteFramebufferAndNoFramebuffer) {
  Context ctx(1);
  Mesh m({tv(-1, -1, 0, 1), tv(1, -1, 0, 1), tv(0, 1, 0, 1)});
  EXPECT_THROW(ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 3}), Error);
  EXPECT_THROW(ctx.clear({}), Error);
  Framebuffer empty;
  EXPECT_THROW(ctx.bind_framebuffer(&empty), Error);
  Texture2D color(Format::RGBA8, 8, 8), depth(Format::Depth24, 8, 8);
  Framebuffer swapped(&depth, &color);  // depth texture in a colour slot and vice versa
  EXPECT_THROW(ctx.bind_framebuffer(&swapped), Error);
  Framebuffer bad_level(&color);
  bad_level.color[0].level = 3;
  EXPECT_THROW(ctx.bind_framebuffer(&bad_level), Error);
  Framebuffer ok(&color, &depth);
  EXPECT_NO_THROW(ctx.bind_framebuffer(&ok));
}

TEST(Robustness, ZeroAndHugeSizes) {
  EXPECT_THROW(Texture2D(Format::RGBA8, 0, 8), Error);
  EXPECT_THROW(Texture2D(Format::RGBA8, 8, -1), Error);
  EXPECT_THROW(Texture2D(Format::RGBA8, 1 << 20, 1 << 20), Error);
  Scene s;
  Mesh m({tv(-1, -1, 0, 1), tv(1, -1, 0, 1), tv(0, 1, 0, 1)});
  EXPECT_NO_THROW(s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 0}));  // nothing
  EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 0xFFFFFFFFu}), Error);
  RenderState st;
  st.viewport = {0, 0, 1 << 30, 1 << 30};  // clamped to the maximum viewport
  EXPECT_NO_THROW(s.ctx.draw(ColorShader{}, {}, m.layout, st, {.count = 3}));
  st = RenderState{};
  st.line_width = -1.0f;
  EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, m.layout, st, {.count = 3}), Error);
  st = RenderState{};
  st.point_size = NAN;
  EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, m.layout, st, {.count = 3}), Error);
  st = RenderState{};
  st.depth_func = CompareFunc(42);  // a wrong enum
  EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, m.layout, st, {.count = 3}), Error);
  DrawCall bad{.count = 3};
  bad.topology = Topology(99);
  EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, bad), Error);
  s.lit();
}

TEST(Robustness, NonFinitePositionsAreDropped) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  Scene s;
  Mesh m({tv(-1, -1, 0, 1), tv(1, -1, 0, 1), tv(0, 1, 0, nan),      // NaN w
          tv(-1, -1, 0, 1), tv(inf, -1, 0, 1), tv(0, 1, 0, 1),      // Inf x
          tv(nan, nan, nan, nan), tv(1, 1, 0, 1), tv(-1, 1, 0, 1),  // all NaN
          tv(-1, -1, 0, 1), tv(1, -1, 0, 1), tv(1, 1, 0, 1)});      // a good one
  s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 12});
  for (Topology t : {Topology::Lines, Topology::Points, Topology::LineLoop, Topology::TriangleStrip})
    s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.topology = t, .count = 9});
  EXPECT_GT(s.lit(), 0u);  // the good triangle (and the finite lines/points) still draw
}

TEST(Robustness, CoordinatesFarOutsideTheGuardBand) {
  Scene s;
  Mesh m({tv(-1e30f, -1e30f, 0, 1), tv(1e30f, -1e30f, 0, 1), tv(0, 1e30f, 0, 1), tv(-3e38f, 0, 0, 1e-30f),
          tv(3e38f, 1, 0, 1e-30f), tv(0, -3e38f, 0.5f, 1e-30f), tv(1e20f, 1e20f, 1e20f, 1e-20f),
          tv(-1, -1, 0, 1), tv(1, -1, 0, -1e-20f)});
  s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 9});
  RenderState st;
  st.polygon_mode = PolygonMode::Line;
  s.ctx.draw(ColorShader{}, {}, m.layout, st, {.count = 9});
  st.polygon_mode = PolygonMode::Point;
  st.point_size = 5000.0f;
  s.ctx.draw(ColorShader{}, {}, m.layout, st, {.count = 9});
  s.lit();  // no crash, no sanitizer report
}

TEST(Robustness, ResourceChangedWhileQueuedDrawsWait) {
  Scene s;
  std::vector<TestVertex> v = {tv(-1, -1, 0, 1), tv(1, -1, 0, 1), tv(-1, 1, 0, 1)};
  auto m = std::make_unique<Mesh>(v);
  s.ctx.draw(ColorShader{}, {}, m->layout, RenderState{}, {.count = 3});
  // Changing (or freeing) a buffer a queued draw reads runs the queued draw first.
  const std::vector<TestVertex> off = {tv(5, 5, 0, 1), tv(6, 5, 0, 1), tv(5, 6, 0, 1)};
  m->buffer.assign(off.data(), off.size() * sizeof(TestVertex));
  m.reset();
  EXPECT_EQ(s.lit(), 120u);  // below the diagonal x + y = 16 (its samples belong to the other side)
}

// Inputs found in review: each once reached undefined behaviour or an out-of-bounds read.
TEST(Robustness, ReviewedEdgeCases) {
  {  // gl_Position = vec4(0) hides a vertex; clipping must not produce w = 0 for setup.
    Scene s;
    Mesh m({tv(0, 0, 0, 0), tv(1, 0, 0, 1), tv(0, 1, 0, 1), tv(0, 0, 0, 1e8f), tv(0, 0, -2, 1),
            tv(1, 0.5f, 0, 1), tv(-3e38f, 0, 0, 1), tv(3e38f, 0, 0, 1), tv(0, 1, 0, 1)});
    s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 9});
    s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.topology = Topology::LineStrip, .count = 9});
    s.lit();
  }
  {  // Index offset so large that offset + size wraps around.
    Scene s;
    Mesh m({tv(-1, -1, 0, 1), tv(1, -1, 0, 1), tv(0, 1, 0, 1)});
    const uint32_t idx[] = {0, 1, 2};
    const Buffer ib(idx, sizeof idx);
    EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{},
                            {.count = 3, .index_buffer = &ib, .index_offset = SIZE_MAX - 3}),
                 Error);
    VertexLayout l = m.layout;
    l.bindings[0].offset = SIZE_MAX - 15;  // binding offset that wraps
    EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, l, RenderState{}, {.count = 3}), Error);
    l = m.layout;
    l.attribs[1].integer = true;  // integer attribute over float data
    EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, l, RenderState{}, {.count = 3}), Error);
    RenderState st;
    st.clip_plane_enable = 1;
    st.clip_planes[0] = {3e38f, 0, 0, 0};
    EXPECT_THROW(s.ctx.draw(ColorShader{}, {}, m.layout, st, {.count = 3}), Error);
    EXPECT_THROW(
        s.ctx.draw(ColorShader{}, {}, m.layout, RenderState{}, {.count = 3, .instance_count = 0xFFFFFFFFu}),
        Error);
    EXPECT_THROW(s.ctx.clear({.depth = NAN}), Error);
  }
  {  // The framebuffer changed after binding: checked again when a frame starts.
    Context ctx(2);
    Texture2D color(Format::RGBA8, 16, 16), r8(Format::R8, 16, 16);
    Framebuffer fb(&color);
    ctx.bind_framebuffer(&fb);
    fb.depth.texture = &r8;
    Mesh m({tv(-1, -1, 0, 1), tv(1, -1, 0, 1), tv(0, 1, 0, 1)});
    RenderState st;
    st.depth_test = true;
    EXPECT_THROW(ctx.draw(ColorShader{}, {}, m.layout, st, {.count = 3}), Error);
    fb.depth.texture = nullptr;
    fb.color[0].level = 3;
    EXPECT_THROW(ctx.clear({}), Error);
  }
}

// A run-time shader whose point size, point coordinate or clip distance components are not
// among its varyings is refused at draw() with an error naming them, before anything runs.
TEST(Robustness, RuntimeShapeComponentsOutOfRangeAreAnError) {
  struct Shader : tessel::gpu::RuntimeShader {
    tessel::gpu::RuntimeShape s;
    const tessel::gpu::RuntimeShape& shape() const override { return s; }
    void vertex(tessel::gpu::VertexLanes&) const override {}
    void fragment(tessel::gpu::FragmentLanes&) const override {}
  };
  Target t(8, 8);
  Context ctx(1);
  ctx.bind_framebuffer(&t.fb);
  const tessel::gpu::VertexLayout layout;
  auto draw = [&](auto set) {
    auto sh = std::make_shared<Shader>();
    sh->s.varyings = 4;
    set(sh->s);
    try {
      ctx.draw(sh, layout, RenderState{}, {.count = 3});
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(draw([](auto& s) { s.point_coord = 3; }).find("point coordinate"), std::string::npos);
  EXPECT_NE(draw([](auto& s) { s.point_size = 4; }).find("among its 4 varying components"),
            std::string::npos);
  EXPECT_NE(draw([](auto& s) {
              s.clip_distance = 2;
              s.clip_distances = 3;
            }).find("clip distance"),
            std::string::npos);
  EXPECT_NE(draw([](auto& s) {
              s.clip_distance = 0;
              s.clip_distances = 9;
            }).find("clip distance"),
            std::string::npos);
  EXPECT_EQ(draw([](auto& s) {
              s.point_coord = 2;
              s.clip_distance = 0;
              s.clip_distances = 2;
            }),
            "");
  ctx.finish();
}
