// Fixed-function state of a draw: viewport, rasterizer, depth/stencil, blending, masks.
// Plain values with GL's defaults; a draw copies the state it is given.
#pragma once

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "tessel/gpu/texture.hpp"  // CompareFunc

namespace tessel::gpu {

inline constexpr int kMaxColorAttachments = 8;
inline constexpr int kMaxClipPlanes = 8;
inline constexpr int kMaxViewportSize = 16384;

// The last four carry adjacent vertices for a geometry stage (GL 3.3 §2.6.1): a program
// without one draws them as lines, a line strip, triangles and a triangle strip of their
// other vertices.
enum class Topology : uint8_t {
  Points,
  Lines,
  LineStrip,
  LineLoop,
  Triangles,
  TriangleStrip,
  TriangleFan,
  LinesAdjacency,
  LineStripAdjacency,
  TrianglesAdjacency,
  TriangleStripAdjacency,
};
// Whether a geometry stage taking primitives of `input_vertices` vertices (1, 2, 3, 4 or 6)
// takes topology t (GL 3.3 §2.12.1, "Geometry Shader Input Primitives").
inline bool geometry_takes(int input_vertices, Topology t) {
  switch (t) {
    case Topology::Points: return input_vertices == 1;
    case Topology::Lines:
    case Topology::LineStrip:
    case Topology::LineLoop: return input_vertices == 2;
    case Topology::Triangles:
    case Topology::TriangleStrip:
    case Topology::TriangleFan: return input_vertices == 3;
    case Topology::LinesAdjacency:
    case Topology::LineStripAdjacency: return input_vertices == 4;
    case Topology::TrianglesAdjacency:
    case Topology::TriangleStripAdjacency: return input_vertices == 6;
  }
  return false;
}

enum class CullMode : uint8_t { None, Front, Back, FrontAndBack };
enum class FrontFace : uint8_t { CCW, CW };
enum class PolygonMode : uint8_t { Fill, Line, Point };
enum class IndexType : uint8_t { U8, U16, U32 };

enum class StencilOp : uint8_t { Keep, Zero, Replace, Incr, IncrWrap, Decr, DecrWrap, Invert };
enum class BlendEquation : uint8_t { Add, Subtract, ReverseSubtract, Min, Max };
// The sixteen logical operations of GL 3.3 §4.1.11 (Table 4.3), in GL's order: s is the
// fragment's value, d the buffer's.
enum class LogicOp : uint8_t {
  Clear,         // 0
  And,           // s & d
  AndReverse,    // s & ~d
  Copy,          // s
  AndInverted,   // ~s & d
  Noop,          // d
  Xor,           // s ^ d
  Or,            // s | d
  Nor,           // ~(s | d)
  Equiv,         // ~(s ^ d)
  Invert,        // ~d
  OrReverse,     // s | ~d
  CopyInverted,  // ~s
  OrInverted,    // ~s | d
  Nand,          // ~(s & d)
  Set,           // all ones
};
enum class BlendFactor : uint8_t {
  Zero,
  One,
  SrcColor,
  OneMinusSrcColor,
  DstColor,
  OneMinusDstColor,
  SrcAlpha,
  OneMinusSrcAlpha,
  DstAlpha,
  OneMinusDstAlpha,
  ConstantColor,
  OneMinusConstantColor,
  ConstantAlpha,
  OneMinusConstantAlpha,
  SrcAlphaSaturate,
  // Dual-source blending (GL 3.3 §4.1.8): the fragment's second colour for attachment 0.
  Src1Color,
  OneMinusSrc1Color,
  Src1Alpha,
  OneMinusSrc1Alpha,
};

struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
};

struct StencilFace {
  CompareFunc func = CompareFunc::Always;
  uint8_t ref = 0;
  uint8_t read_mask = 0xFF;
  uint8_t write_mask = 0xFF;
  StencilOp fail = StencilOp::Keep;        // stencil test failed
  StencilOp depth_fail = StencilOp::Keep;  // stencil passed, depth failed
  StencilOp pass = StencilOp::Keep;        // both passed
};

struct BlendTarget {
  bool enabled = false;
  // An integer colour attachment (format.hpp): the fragment shader's output carries each
  // component's 32 bits, stored clamped to this range and never blended (GL 4.6 §17.3.6.1:
  // blending applies to fixed- and floating-point buffers only).
  IntegerRange integer{};
  BlendEquation eq_rgb = BlendEquation::Add, eq_alpha = BlendEquation::Add;
  BlendFactor src_rgb = BlendFactor::One, dst_rgb = BlendFactor::Zero;
  BlendFactor src_alpha = BlendFactor::One, dst_alpha = BlendFactor::Zero;
  // Colour write mask, bit 0 = red .. bit 3 = alpha.
  uint8_t write_mask = 0xF;
};

struct RenderState {
  // An empty viewport (width 0) means the whole framebuffer.
  Rect viewport;
  float depth_near = 0.0f, depth_far = 1.0f;
  bool scissor_test = false;
  Rect scissor;

  CullMode cull = CullMode::None;
  FrontFace front_face = FrontFace::CCW;
  PolygonMode polygon_mode = PolygonMode::Fill;
  // GL 1.x glPolygonMode(GL_BACK, ...): when set, back faces use polygon_mode_back and
  // polygon_mode is for front faces only.
  bool polygon_mode_per_face = false;
  PolygonMode polygon_mode_back = PolygonMode::Fill;
  // Polygon offset for each polygon mode (GL_POLYGON_OFFSET_FILL / _LINE / _POINT).
  bool offset_fill = false, offset_line = false, offset_point = false;
  float offset_factor = 0.0f, offset_units = 0.0f;
  float line_width = 1.0f;
  // Line stipple (GL 2.1 §3.4.2): line segments are drawn where the pattern's bit
  // (counter / factor) mod 16 is set, the counter counting pixels along the major axis from
  // the start of each independent segment, strip or loop (and, for a draw with edge_masks,
  // from each segment whose mask has bit 0 set). Not for lines a geometry stage makes.
  bool line_stipple = false;
  uint16_t line_stipple_pattern = 0xFFFF;
  uint16_t line_stipple_factor = 1;
  float point_size = 1.0f;
  // GL_PROGRAM_POINT_SIZE: a point's size is the one its vertex shader wrote (gl_PointSize,
  // RuntimeShape::point_size) instead of point_size.
  bool program_point_size = false;
  // GL_POINT_SPRITE_COORD_ORIGIN: where gl_PointCoord's t is 0 (upper left, GL's default).
  bool point_sprite_lower_left = false;
  bool depth_clamp = false;  // GL_DEPTH_CLAMP: no near/far clipping, depth clamped instead
  // GL edge flags (GL 2.1 §2.6.2): with polygon mode Line or Point, when >= 0 this varying
  // component of a triangle's vertex says whether the edge that starts at it is a boundary
  // edge (nonzero) to be drawn, or an inner edge of a decomposed polygon (zero).
  int8_t edge_flag_varying = -1;
  // Edge flags by triangle, for programs whose varyings have no room for them: when set, bit
  // k of edge_masks[id] (id: the triangle's primitive id, below edge_mask_count) says whether
  // the edge from its vertex k to vertex k + 1 is a boundary edge; a triangle past the count
  // has all three. With edge_flag_varying, an edge is drawn when both say so. The bytes are the
  // caller's and must outlive the draw.
  const uint8_t* edge_masks = nullptr;
  uint32_t edge_mask_count = 0;

  // User clip planes in clip space: a vertex is kept where dot(plane, clip_position) >= 0.
  // For a run-time shader that writes clip distances (gl_ClipDistance, RuntimeShape), an
  // enabled plane i below their count keeps where distance i >= 0 instead.
  uint8_t clip_plane_enable = 0;  // bit i enables plane i
  std::array<glm::vec4, kMaxClipPlanes> clip_planes{};

  bool depth_test = false;
  CompareFunc depth_func = CompareFunc::Less;
  bool depth_write = true;

  bool stencil_test = false;
  StencilFace stencil_front, stencil_back;

  std::array<BlendTarget, kMaxColorAttachments> blend{};
  glm::vec4 blend_color{0.0f};
  // GL_COLOR_LOGIC_OP (GL 3.3 §4.1.11): when enabled, blending is off for every target and
  // unsigned normalized targets store logic_op of the fragment's and the buffer's 8-bit
  // values, integer targets of their integer bits (at the format's width); float targets
  // store the fragment's value.
  bool logic_op_enabled = false;
  LogicOp logic_op = LogicOp::Copy;

  // glProvokingVertex (GL 3.3 §2.18, Table 2.12): flat varyings come from each primitive's
  // first vertex in GL's numbering instead of its last (for a fan's triangles, the second).
  bool provoking_first = false;

  bool primitive_restart = false;  // index 0xFF / 0xFFFF / 0xFFFFFFFF restarts (fixed index)

  // Dual-source blending: fragment output 1 is the second source colour of attachment 0's
  // blend (the Src1 factors), and only attachment 0 is written.
  bool dual_source = false;
  // Output 0 is written to every colour attachment (each with its own blend state and mask):
  // fixed-function fragments go to every draw buffer (GL 2.1 §4.2.1), as does any fragment
  // drawn to GL_FRONT_AND_BACK.
  bool broadcast_color = false;

  // Layered rendering (GL 3.3 §4.4.7), one layer of the framebuffer a draw: with a program
  // whose geometry stage writes gl_Layer (RuntimeShape::layer), this draw keeps the primitives
  // whose provoking vertex gives `layer` (values past the last of layer_count layers count
  // as the last, as llvmpipe clamps them). -1: every primitive.
  int layer = -1;
  int layer_count = 0;

  // GL_RASTERIZER_DISCARD (GL 3.3 §3.1): primitives go no further than transform feedback
  // (DrawCall::capture) and the counters; nothing is rasterized.
  bool rasterizer_discard = false;

  // GL_POINT_SMOOTH and GL_LINE_SMOOTH (GL 3.3 §3.4.2, §3.5.2) as llvmpipe draws them: a
  // point or line becomes a quad whose fragments' alpha is multiplied by their coverage (and
  // a point's corners outside its circle are discarded). gpu/detail/pipeline.hpp's
  // SmoothCoverage says how.
  bool point_smooth = false;
  bool line_smooth = false;
};

}  // namespace tessel::gpu
