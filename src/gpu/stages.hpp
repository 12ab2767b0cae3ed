// Private: the non-templated stages of the geometry phase, each a function of plain structs.
//   clip.cpp    clip codes and Sutherland-Hodgman clipping in homogeneous clip space
//   setup.cpp   perspective divide, viewport, snapping, facing/culling, edge and plane setup
//   arena.hpp   per-worker memory for the primitives of one frame
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "tessel/gpu/clip_space.hpp"
#include "tessel/gpu/detail/pipeline.hpp"

namespace tessel::gpu::detail {

// Bump allocator; memory lives until reset(). Blocks never move, so pointers stay valid.
class Arena {
 public:
  void* allocate(size_t bytes) {
    bytes = (bytes + 15) & ~size_t(15);
    if (used_ + bytes > cap_) grow(bytes);
    void* p = blocks_[current_].get() + used_;
    used_ += bytes;
    total_ += bytes;
    return p;
  }
  void reset() {
    current_ = 0;
    used_ = 0;
    total_ = 0;
    cap_ = blocks_.empty() ? 0 : sizes_[0];
  }
  size_t bytes_used() const { return total_; }

 private:
  void grow(size_t bytes) {
    // Move to the next block that fits, or add one.
    while (current_ + 1 < blocks_.size()) {
      ++current_;
      used_ = 0;
      cap_ = sizes_[current_];
      if (bytes <= cap_) return;
    }
    const size_t size = std::max<size_t>(bytes, size_t(1) << 20);
    blocks_.emplace_back(new std::byte[size]);
    sizes_.push_back(size);
    current_ = blocks_.size() - 1;
    used_ = 0;
    cap_ = size;
  }
  std::vector<std::unique_ptr<std::byte[]>> blocks_;
  std::vector<size_t> sizes_;
  size_t current_ = 0, used_ = 0, cap_ = 0, total_ = 0;
};

// --- clip.cpp ---------------------------------------------------------------------------------
// A vertex during clipping: clip-space position and its varyings.
struct ClipVert {
  glm::vec4 pos;
  float var[kMaxVaryings];
};

// The planes of a draw: w > 0, near and far (unless depth clamping), the guard band in x and
// y, and the enabled user planes or clip distances (clip_space.hpp has the rest of clipping).
ClipPlanes make_clip_planes(const DrawRecord& draw);
inline constexpr unsigned kNotFinite = 1u << 31;  // a clip code for NaN/Inf positions
// Clips the convex polygon in[0..n) against the planes in `mask` (clip_space.hpp's
// clip_polygon, with K varyings); returns the vertex count (0 when nothing is left) and
// points *out at the result (one of the two buffers). With edge_flag >= 0, var[edge_flag] is
// each vertex's edge flag (nonzero: the edge that starts there is drawn in polygon modes Line
// and Point), set for the vertices clipping makes as GL draws their edges; it is not
// interpolated, and may lie past the `varyings` components.
int clip_polygon(const ClipPlanes& planes, unsigned mask, ClipVert* a, int n, ClipVert* b, int varyings,
                 ClipVert** out, int edge_flag = -1);
// Clips the segment p0-p1 (varyings v0, v1), as clip_space.hpp's clip_segment: t0 is cut
// from p0's end, t1 from p1's; false if nothing is left.
bool clip_line(const ClipPlanes& planes, unsigned mask, const glm::vec4& p0, const glm::vec4& p1,
               const float* v0, const float* v1, float& t0, float& t1);

// --- setup.cpp --------------------------------------------------------------------------------
// A vertex in window coordinates: x, y in pixels (y up), z in the depth range, 1/w.
struct WinVert {
  float x, y, z, oow;
  const float* var;  // the vertex's varyings (clip-space values)
  int32_t sx, sy;    // x, y snapped to the sub-pixel lattice (snap_vertex)
  bool usable;       // finite, w > 0, inside twice the guard band: setup may use it
};
// Snapping to the sub-pixel lattice: X = round_even((x - 0.5) * 256), as _mm_cvtps_epi32
// does in llvmpipe. Callers pass finite positions within the guard band; the clamp keeps
// anything else defined.
inline int32_t snap(float x) {
  const float limit = 2.0f * kGuardBand * float(kSubpixelOne);
  const float v = std::nearbyint((x - 0.5f) * float(kSubpixelOne));
  return int32_t(std::clamp(v, -limit, limit));
}
// Recomputes sx, sy and usable after x or y changed.
inline void snap_vertex(WinVert& v) {
  v.usable = std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.oow) &&
             v.oow > 0.0f && std::fabs(v.x) <= 2.0f * kGuardBand && std::fabs(v.y) <= 2.0f * kGuardBand;
  v.sx = v.usable ? snap(v.x) : 0;
  v.sy = v.usable ? snap(v.y) : 0;
}
// Perspective divide and viewport transform, then snap_vertex. Inline: once per vertex.
inline void to_window(const DrawRecord& d, const glm::vec4& pos, const float* var, WinVert& v) {
  const float oow = 1.0f / pos.w;
  v.x = pos.x * oow * d.vp_scale[0] + d.vp_offset[0];
  v.y = pos.y * oow * d.vp_scale[1] + d.vp_offset[1];
  v.z = pos.z * oow * d.vp_scale[2] + d.vp_offset[2];
  v.oow = oow;
  v.var = var;
  snap_vertex(v);
}
inline WinVert to_window(const DrawRecord& d, const glm::vec4& pos, const float* var) {
  WinVert v;
  to_window(d, pos, var, v);
  return v;
}

// Clip codes (clip_code, kNotFinite for NaN/Inf) of n shaded vertices, and the window
// position (to_window) of each one inside every plane; eight at a time. `soa` holds the clip
// positions as blocks of eight x, eight y, eight z and eight w; vars the varyings, K per
// vertex. The same bits as the one-vertex functions.
void finish_vertices(const DrawRecord& d, const ClipPlanes& planes, const float* soa, const float* vars,
                     int K, size_t n, unsigned* codes, WinVert* win);

// How setup decides the facing of a triangle.
enum class Facing : int8_t { FromArea = -1, Back = 0, Front = 1 };

// Builds the Prim of one triangle in the arena: snap to 1/256 pixel, facing from the
// snapped area (culled per the draw's cull mode when facing == FromArea), the edge
// equations with the fill rule, the bbox cut to the render area, and the planes of depth,
// 1/w and every varying (flat components from `flat_src`). z_offset is added to depth.
// Returns nullptr when the triangle is culled, has zero area or covers no pixel.
// With `smooth`, the Prim is a Smooth one carrying that coverage (antialiased points and lines).
Prim* setup_triangle(const DrawRecord& d, const WinVert& v0, const WinVert& v1, const WinVert& v2,
                     const float* flat_src, uint32_t prim_id, Facing facing, bool apply_offset, Arena& arena,
                     Counters& c, bool* culled, const SmoothCoverage* smooth = nullptr);
// Polygon offset of GL 4.6 §14.6.5 for the plane through three window vertices.
float polygon_offset(const DrawRecord& d, const WinVert& v0, const WinVert& v1, const WinVert& v2);
// A line of the draw's line width between two window vertices, as up to two Prims
// (GL's aliased wide line: a parallelogram along the minor axis). Returns the count.
int setup_line(const DrawRecord& d, const WinVert& v0, const WinVert& v1, const float* flat_src,
               uint32_t prim_id, bool front, float z_offset, Arena& arena, Counters& c, Prim** out);
// A point of the draw's point size: a square, as up to two Prims.
int setup_point(const DrawRecord& d, const WinVert& v, uint32_t prim_id, bool front, float z_offset,
                Arena& arena, Counters& c, Prim** out);

}  // namespace tessel::gpu::detail
