// The records that flow between the stages of a frame. Internal: used by the templated
// shading code (detail/raster.hpp) that is instantiated in the user's translation unit.
//
// A draw becomes a DrawRecord; the geometry phase turns its primitives into Prim records
// (one per rasterized triangle, each followed by its attribute planes) and bins them into
// 64x64 tiles; the raster phase runs each tile's Prims in submission order.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "tessel/gpu/buffer.hpp"
#include "tessel/gpu/shader.hpp"
#include "tessel/gpu/state.hpp"
#include "tessel/gpu/vec.hpp"

namespace tessel::gpu {

struct DrawCall;
struct Capture;
struct GeometryLanes;

namespace detail {

inline constexpr int kTileSize = 64;
inline constexpr int kTileShift = 6;
inline constexpr int kSubpixelBits = 8;
inline constexpr int kSubpixelOne = 1 << kSubpixelBits;
// Window coordinates are kept within +-kGuardBand pixels; beyond that, x and y are clipped.
// With 8 sub-pixel bits that keeps positions under 2^24 and edge products under 2^49.
inline constexpr float kGuardBand = 32768.0f;

// Smooth: a triangle of an antialiased point or line (GL_POINT_SMOOTH, GL_LINE_SMOOTH), whose
// SmoothCoverage follows its edges.
enum class PrimKind : uint8_t { Triangle, Clear, Smooth };

// The coverage of an antialiased point or line at a pixel, as llvmpipe's draw module computes
// it (draw_pipe_aapoint.c, draw_pipe_aaline.c): from the pixel centre p, u = dot(p - origin,
// u_axis) and v = dot(p - origin, v_axis). A point (u, v in units of its radius) discards
// where d = u^2 + v^2 > 1 and multiplies alpha by (1 - d) / (1 - a) where d <= a, else by 1
// (the selection llvmpipe's NIR lowering makes). A line multiplies alpha by
// saturate(a - |u|) * saturate(b - |v|), a the quad's half width and b its half length.
struct SmoothCoverage {
  float ox, oy;  // origin: the point's centre, the line's midpoint (window coordinates)
  float ux, uy, vx, vy;
  float a, b;
  bool point;
};

// Edge function at pixel (i, j): E = c + a*i + b*j; the pixel centre is inside when E > 0
// (c already carries the fill rule's +1 for edges that own their samples).
struct EdgeEq {
  int64_t c, a, b;
};

// Whether the edges of a triangle are short enough that at any pixel of its bbox their
// values fit 32-bit lanes: when every edge spans under 56 pixels in x and y (|a|, |b| =
// 256 |dy|, 256 |dx| with dx, dy in 1/256 pixel), the whole triangle does, and at any pixel
// of its bbox E = dx (256 j - Y) - dy (256 i - X) stays below 2 * (60 * 256)^2 < 2^29 in
// magnitude. (The bbox alone is not enough: it is cut to the render area, and a huge
// triangle can show a small part.)
inline bool small_edges(const EdgeEq* e) {
  constexpr int64_t kSmall = int64_t(56) << (2 * kSubpixelBits);
  bool small = true;
  for (int i = 0; i < 3; ++i)
    small = small && e[i].a > -kSmall && e[i].a < kSmall && e[i].b > -kSmall && e[i].b < kSmall;
  return small;
}

// The three edges of a small triangle (small_edges) in 32-bit lanes over the 4x2 groups
// from (gx0, gy0): at(ox, oy) is the lane mask (kLaneDx/kLaneDy order) of the group at
// (gx0 + ox, gy0 + oy) inside all three. Setup (Prim::cover) and the raster phase's small
// triangles use it.
struct SmallEdgeLanes {
  Int8 base[3];
  int32_t sa[3], sb[3];
  SmallEdgeLanes(const EdgeEq* e, int gx0, int gy0) {
    const Int8 lane_dx(vx::i32x8{0, 1, 0, 1, 2, 3, 2, 3}), lane_dy(vx::i32x8{0, 0, 1, 1, 0, 0, 1, 1});
    for (int i = 0; i < 3; ++i) {
      sa[i] = int32_t(e[i].a);
      sb[i] = int32_t(e[i].b);
      base[i] =
          Int8(int32_t(e[i].c + e[i].a * gx0 + e[i].b * gy0)) + Int8(sa[i]) * lane_dx + Int8(sb[i]) * lane_dy;
    }
  }
  unsigned at(int ox, int oy) const {
    return (((base[0] + Int8(sa[0] * ox + sb[0] * oy)) > Int8(0)) &
            ((base[1] + Int8(sa[1] * ox + sb[1] * oy)) > Int8(0)) &
            ((base[2] + Int8(sa[2] * ox + sb[2] * oy)) > Int8(0)))
        .bits();
  }
};

// A triangle ready for the raster phase (64 bytes), followed in memory by 3 * varyings
// floats: the planes of value/w (or of the value itself for flat and noperspective
// components), as three arrays of `varyings` floats: the values at the anchor, then d/dx,
// then d/dy; and then, unless `cover` says where it covers, its three edge equations.
struct Prim {
  PrimKind kind = PrimKind::Triangle;
  bool front = true;
  uint32_t prim_id = 0;
  int minx = 0, miny = 0, maxx = -1, maxy = -1;  // inclusive pixel bbox within the render area
  // For a small triangle, its coverage worked out at setup (0 when not): the 4x2 groups of
  // the 8x8 pixels from (minx & ~3, miny & ~1), group (col, row) in byte 2 row + col, lanes
  // in kLaneDx/kLaneDy order, already cut to the bbox. The raster phase then needs no edges,
  // and the Prim has none.
  uint64_t cover = 0;
  float xr = 0, yr = 0;      // anchor of the planes, window coordinates
  float z[3] = {0, 0, 0};    // window depth plane
  float oow[3] = {0, 0, 0};  // 1/w plane
  const float* planes() const { return reinterpret_cast<const float*>(this + 1); }
  float* planes() { return reinterpret_cast<float*>(this + 1); }
  // The edges (only when cover == 0), after the planes of `varyings` components.
  static size_t edges_offset(int varyings) { return (sizeof(float) * 3 * size_t(varyings) + 7) & ~size_t(7); }
  const EdgeEq* edges(int varyings) const {
    return reinterpret_cast<const EdgeEq*>(reinterpret_cast<const char*>(this + 1) + edges_offset(varyings));
  }
  EdgeEq* edges(int varyings) {
    return reinterpret_cast<EdgeEq*>(reinterpret_cast<char*>(this + 1) + edges_offset(varyings));
  }
  // Bytes of a triangle's Prim with its planes, and its edges unless it has a cover.
  static size_t bytes(int varyings, bool with_edges) {
    return sizeof(Prim) + edges_offset(varyings) + (with_edges ? 3 * sizeof(EdgeEq) : 0);
  }
  // A Smooth prim's coverage, after its edges (it always has them).
  const SmoothCoverage* smooth(int varyings) const {
    return reinterpret_cast<const SmoothCoverage*>(edges(varyings) + 3);
  }
  SmoothCoverage* smooth(int varyings) { return reinterpret_cast<SmoothCoverage*>(edges(varyings) + 3); }
};
static_assert(sizeof(Prim) == 64);

// What a clear command does to the pixels in its rectangle.
struct ClearPrim {
  Prim base;                    // kind == Clear; minx..maxy is the rectangle
  uint8_t color_mask_bits = 0;  // attachments to clear
  std::array<glm::vec4, kMaxColorAttachments> color{};
  std::array<uint8_t, kMaxColorAttachments> write_mask{};  // per attachment RGBA mask
  bool clear_depth = false;
  float depth = 1.0f;
  bool clear_stencil = false;
  uint8_t stencil = 0;
  uint8_t stencil_write_mask = 0xFF;
};

struct ColorTarget {
  std::byte* data = nullptr;
  size_t row_bytes = 0;
  Format format = Format::RGBA8;
};

// Where a draw's fragments go: the attachments of the bound framebuffer, as plain pointers.
struct TargetView {
  int width = 0, height = 0;
  int color_count = 0;  // highest used attachment + 1
  std::array<ColorTarget, kMaxColorAttachments> color{};
  std::byte* depth = nullptr;
  size_t depth_row_bytes = 0;
  Format depth_format = Format::Depth32F;
  bool has_stencil = false;
};

// Counters of one frame (summed over threads).
struct Counters {
  uint64_t vertices_shaded = 0;
  uint64_t primitives_in = 0;
  uint64_t primitives_clipped = 0;  // needed clipping
  uint64_t primitives_culled = 0;
  uint64_t triangles_setup = 0;
  uint64_t fragments_shaded = 0;    // lanes covered when the shader ran
  uint64_t fragments_written = 0;   // samples that passed every test
  uint64_t fragments_rejected = 0;  // samples the depth or stencil test rejected
  // Primitives out of the vertex or geometry stage (GL_PRIMITIVES_GENERATED), and those
  // transform feedback wrote (GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN).
  uint64_t primitives_generated = 0;
  uint64_t primitives_written = 0;
};

// What was counted between two readings (a later one minus an earlier one).
inline Counters operator-(const Counters& a, const Counters& b) {
  return {a.vertices_shaded - b.vertices_shaded,           a.primitives_in - b.primitives_in,
          a.primitives_clipped - b.primitives_clipped,     a.primitives_culled - b.primitives_culled,
          a.triangles_setup - b.triangles_setup,           a.fragments_shaded - b.fragments_shaded,
          a.fragments_written - b.fragments_written,       a.fragments_rejected - b.fragments_rejected,
          a.primitives_generated - b.primitives_generated, a.primitives_written - b.primitives_written};
}

class ProgramBase;

// One queued draw, with everything it needs copied out of the caller's objects.
struct DrawRecord {
  std::unique_ptr<ProgramBase> program;
  RenderState state;
  VertexLayout layout;
  Topology topology = Topology::Triangles;  // after primitive-restart expansion
  // The element stream: either `count` consecutive vertices from `first`, or `count`
  // indices at `elements`: the index buffer's own memory when its 32-bit indices can be used
  // as they are (a buffer flushes queued work before it changes or goes, so they stay valid),
  // otherwise `indices`, converted or expanded by primitive restart, base vertex added.
  bool indexed = false;
  uint32_t first = 0, count = 0;
  const uint32_t* elements = nullptr;
  std::vector<uint32_t> indices;
  uint32_t instance_count = 1, base_instance = 0;
  uint32_t prim_count = 0;  // per instance
  TargetView target;
  // Derived once per draw: the viewport transform and the render area (viewport cut by
  // scissor and framebuffer).
  float vp_scale[3], vp_offset[3];
  int area_x0, area_y0, area_x1, area_y1;  // inclusive-exclusive pixel rectangle
  float guard_x, guard_y;                  // |x_clip| <= guard * w keeps x within the guard band
  float depth_min, depth_max;
  float depth_resolution;  // r of GL 4.6 §14.6.5 for units of polygon offset (fixed formats)
  bool depth_float = false;
  bool early_depth = true;  // the shader neither discards nor writes depth
  // Common states that fragment_ops.cpp runs eight lanes at a time: a depth test without
  // stencil; one RGBA8 colour attachment without blending, all channels written.
  bool fast_depth = false;
  bool fast_color = false;
  // Whether primitives go on to clipping and rasterization (not when the rasterizer
  // discards them, or the render area is empty), and where transform feedback writes them.
  bool raster = true;
  Capture* capture = nullptr;
};

// The shader of a draw with its uniforms; the two virtual calls are the only places where
// the pipeline enters user code.
class ProgramBase {
 public:
  virtual ~ProgramBase() = default;
  int varyings = 0;
  uint64_t flat = 0, noperspective = 0;
  bool discards = false, writes_depth = false;
  int outputs = 1;
  // Varying components the pipeline reads or sets itself (RuntimeShape; -1: none).
  int point_size_var = -1, point_coord_var = -1, clip_distance_var = -1, clip_distances = 0;
  // A geometry stage (RuntimeShape): input vertices per primitive (0: none), what it emits,
  // the components the vertex stage writes for it, and the gl_PrimitiveID component.
  int geometry_input = 0;
  Topology geometry_output = Topology::Points;
  int geometry_max_vertices = 0, vertex_varyings = 0, primitive_id_var = -1, layer_var = -1;
  // Fetches and shades n vertices (element ids, base vertex added) of one instance; writes
  // clip positions and n * varyings floats, and, unless soa is null, the clip positions again
  // as blocks of eight x, eight y, eight z and eight w (n rounded up to a multiple of 8).
  virtual void shade_vertices(const DrawRecord& d, const uint32_t* ids, int n, uint32_t instance,
                              glm::vec4* pos, float* vars, float* soa = nullptr) const = 0;
  // Runs the geometry stage on lanes.count primitives (the caller fills the inputs and
  // lanes.out / lanes.strip_start; see RuntimeShader::geometry).
  virtual void shade_geometry(GeometryLanes& lanes) const { (void)lanes; }
  // Rasterizes and shades n consecutive triangles of one draw, in order, inside the tile
  // rectangle [x0,x1) x [y0,y1), writing through `t` (the draw's attachments, or the raster
  // phase's tile-local copies of them).
  virtual void raster(const DrawRecord& d, const TargetView& t, const Prim* const* prims, int n, int x0,
                      int y0, int x1, int y1, Counters& c) const = 0;
  // The same for a draw of antialiased points or lines (RenderState::point_smooth, line_smooth).
  virtual void raster_smooth(const DrawRecord& d, const TargetView& t, const Prim* const* prims, int n,
                             int x0, int y0, int x1, int y1, Counters& c) const = 0;
};

// --- stage functions (each in its own .cpp) --------------------------------------------------

// vertex_fetch.cpp: reads attribute `location` of vertex `id` in `instance` as 4 floats
// (integers keep their bits when the attribute is an integer attribute).
void fetch_attributes(const VertexLayout& layout, uint32_t id, uint32_t instance, float out[][4]);
// The same for the eight lanes of a vertex batch: vertices ids[0..n) (1 <= n <= 8; lanes n..7
// repeat ids[n-1]) of `instance`, every location, vertex_id and instance_id; the values are
// bit for bit those of fetch_attributes. With per_vertex_only, the locations that are the
// same for every vertex of the instance (not enabled, or with a divisor) are left as a
// previous call of the same instance wrote them.
void fetch_attributes8(const VertexLayout& layout, const uint32_t* ids, int n, uint32_t instance,
                       VertexIn<Float8>& in, bool per_vertex_only = false);
// Throws Error when a draw would read past a buffer (names the attribute and the numbers).
void validate_vertex_range(const VertexLayout& layout, uint32_t max_id, uint32_t instance_end,
                           uint32_t required_attribs);

// fragment_ops.cpp: the per-sample tests and writes for one 4x2 group of lanes at pixel
// (gx, gy); lanes are laid out as in vec.hpp's dFdx. `mask` bit i = lane i alive.
unsigned depth_stencil_test(const DrawRecord& d, const TargetView& t, int gx, int gy, unsigned mask,
                            const Float8& z, bool front);
void write_colors(const DrawRecord& d, const TargetView& t, int gx, int gy, unsigned mask,
                  const Vec4<Float8>* colors, int outputs);
// `stream`: the rectangle is in the whole target (not a tile-local copy) and nothing will read
// it back soon, so whole rows are written with non-temporal stores, without first reading
// the lines they overwrite.
void clear_rect(const TargetView& t, const ClearPrim& c, int x0, int y0, int x1, int y1, bool stream = false);
// Copies `rows` rows of `row_bytes` (between a tile-local buffer and the target); with
// `stream`, into the target with non-temporal stores where the addresses allow (16-byte
// aligned).
void copy_rows(std::byte* dst, size_t dst_stride, const std::byte* src, size_t src_stride, size_t row_bytes,
               int rows, bool stream = false);

// Lane offsets of a 4x2 group (two 2x2 quads side by side).
inline constexpr int kLaneDx[8] = {0, 1, 0, 1, 2, 3, 2, 3};
inline constexpr int kLaneDy[8] = {0, 0, 1, 1, 0, 0, 1, 1};

}  // namespace detail
}  // namespace tessel::gpu
