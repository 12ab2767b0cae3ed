// Shaders and helpers shared by the tests: clip-space positions in, colours out.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "tessel/gpu/context.hpp"
#include "tessel/gpu/texture.hpp"

namespace tessel::test {
using namespace tessel::gpu;

// A vertex as the tests write it: clip position, colour, texture coordinate.
struct TestVertex {
  float pos[4];
  float color[4];
  float uv[2];
};

// Position straight through; colour interpolated (perspective-correct).
struct ColorShader {
  struct Uniforms {};
  template <class F>
  struct Varyings {
    Vec4<F> color;
  };
  static constexpr uint32_t attributes = 0b11;
  template <class F>
  Vec4<F> vertex(const Uniforms&, const VertexIn<F>& in, Varyings<F>& out) const {
    out.color = in.attr[1];
    return in.attr[0];
  }
  template <class F>
  void fragment(const Uniforms&, const Varyings<F>& v, Fragment<F>& f) const {
    f.color[0] = v.color;
  }
};

// The same with the colour taken from the provoking vertex.
struct FlatColorShader : ColorShader {
  static constexpr uint64_t flat = 0b1111;
};

// Colour times a texture sampled at the interpolated uv (implicit LOD from the quad).
struct TexturedShader {
  struct Uniforms {
    Sampler2D tex;
  };
  template <class F>
  struct Varyings {
    Vec4<F> color;
    Vec2<F> uv;
  };
  static constexpr uint32_t attributes = 0b111;
  template <class F>
  Vec4<F> vertex(const Uniforms&, const VertexIn<F>& in, Varyings<F>& out) const {
    out.color = in.attr[1];
    out.uv = in.attr[2].xy();
    return in.attr[0];
  }
  template <class F>
  void fragment(const Uniforms& u, const Varyings<F>& v, Fragment<F>& f) const {
    f.color[0] = v.color * texture(u.tex, v.uv);
  }
};

// A framebuffer of RGBA8 colour and depth-stencil, with its textures.
struct Target {
  Texture2D color;
  Texture2D depth;
  Framebuffer fb;
  Target(int w, int h, Format depth_format = Format::Depth24Stencil8)
      : color(Format::RGBA8, w, h), depth(depth_format, w, h), fb(&color, &depth) {}
};

// Uploads vertices and returns a layout reading pos (0), colour (1), uv (2).
struct Mesh {
  Buffer buffer;
  VertexLayout layout;
  uint32_t count = 0;
  explicit Mesh(const std::vector<TestVertex>& v) : buffer(v), count(uint32_t(v.size())) {
    const uint32_t s = sizeof(TestVertex);
    layout.attrib(0, buffer, 4, AttribType::F32, s, offsetof(TestVertex, pos));
    layout.attrib(1, buffer, 4, AttribType::F32, s, offsetof(TestVertex, color));
    layout.attrib(2, buffer, 2, AttribType::F32, s, offsetof(TestVertex, uv));
  }
};

// Clip position of window point (x, y) in a w x h viewport, at depth z_ndc and clip w.
inline void clip_from_window(float x, float y, float z, float w, int width, int height, float* out) {
  out[0] = (x / float(width) * 2.0f - 1.0f) * w;
  out[1] = (y / float(height) * 2.0f - 1.0f) * w;
  out[2] = z * w;
  out[3] = w;
}

}  // namespace tessel::test
