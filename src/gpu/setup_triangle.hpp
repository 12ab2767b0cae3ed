// The body of triangle setup (setup.cpp's contract), inline so that the geometry phase's
// loop over a chunk's triangles makes no call per triangle.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>

#include "stages.hpp"
#include "tessel/gpu/simd.hpp"

namespace tessel::gpu::detail {

// Coverage of a small triangle (small_edges) whose bbox lies in the 8x8 pixels from
// (minx & ~3, miny & ~1), in Prim::cover's layout. Without loops or branches on the bbox's
// size (whose trip counts a branch predictor cannot know): the edges are tested on the four
// groups of the window's first four rows, or on all eight when the bbox is taller, and the
// result is cut to the bbox by two masks from tables.
__attribute__((always_inline)) inline uint64_t small_coverage(const EdgeEq* e, int minx, int miny, int maxx,
                                                              int maxy) {
  // Bits of Prim::cover for pixel columns [lo, hi] of the window (all rows), and for rows.
  static constexpr auto masks = [] {
    struct Tables {
      uint64_t col[4][8], row[2][8];
    } t{};
    for (int g = 0; g < 8; ++g)
      for (int l = 0; l < 8; ++l) {
        const int x = (g & 1) * 4 + kLaneDx[l], y = (g >> 1) * 2 + kLaneDy[l];
        const uint64_t bit = uint64_t(1) << (8 * g + l);
        for (int lo = 0; lo < 4; ++lo)
          for (int hi = 0; hi < 8; ++hi)
            if (x >= lo && x <= hi) t.col[lo][hi] |= bit;
        for (int lo = 0; lo < 2; ++lo)
          for (int hi = 0; hi < 8; ++hi)
            if (y >= lo && y <= hi) t.row[lo][hi] |= bit;
      }
    return t;
  }();
  const int gx0 = minx & ~3, gy0 = miny & ~1;
  const SmallEdgeLanes edges(e, gx0, gy0);
  // E - 1 for the groups at columns 0 and 4 of a row pair, stepped down the rows: a pixel is
  // inside when E > 0 for all three edges, that is when the sign bits of the three E - 1 are
  // all clear.
  Int8 left[3], right[3], down[3];
  for (int i = 0; i < 3; ++i) {
    left[i] = edges.base[i] - Int8(1);
    right[i] = left[i] + Int8(4 * edges.sa[i]);
    down[i] = Int8(2 * edges.sb[i]);
  }
  auto row = [&](int shift) __attribute__((always_inline)) {
    const unsigned l = ((left[0] | left[1] | left[2]) >= Int8(0)).bits();
    const unsigned r = ((right[0] | right[1] | right[2]) >= Int8(0)).bits();
    for (int i = 0; i < 3; ++i) {
      left[i] = left[i] + down[i];
      right[i] = right[i] + down[i];
    }
    return (uint64_t(l) | uint64_t(r) << 8) << shift;
  };
  uint64_t cover = row(0);
  cover |= row(16);
  if (maxy >= gy0 + 4) {
    cover |= row(32);
    cover |= row(48);
  }
  return cover & masks.col[minx - gx0][maxx - gx0] & masks.row[miny - gy0][maxy - gy0];
}

// Plane (value at v0, d/dx, d/dy) through three values at the vertices, written `stride`
// floats apart.
struct PlaneSolver {
  double dx1, dy1, dx2, dy2, inv_det;
  void solve(float a0, float a1, float a2, float* out, int stride = 1) const {
    const double d1 = double(a1) - a0, d2 = double(a2) - a0;
    out[0] = a0;
    out[stride] = float((d1 * dy2 - d2 * dy1) * inv_det);
    out[2 * stride] = float((d2 * dx1 - d1 * dx2) * inv_det);
  }
};

// What setup reads of a draw, taken out once per chunk: kept in registers through the loop
// over the chunk's triangles, where the DrawRecord's fields would be loaded again after each
// store into a Prim (which the compiler cannot tell from them).
struct SetupConstants {
  bool cull_ccw, cull_cw;  // culled when the snapped area is positive / negative (Facing::FromArea)
  bool ccw_front;          // front-facing when the area is positive
  int area_x0, area_y0, area_x1, area_y1;
  int varyings;
  uint64_t flat, linear;  // components from the provoking vertex; flat or noperspective
  explicit SetupConstants(const DrawRecord& d)
      : cull_ccw(culled(d.state.cull, front_facing(d.state.front_face, true))),
        cull_cw(culled(d.state.cull, front_facing(d.state.front_face, false))),
        ccw_front(front_facing(d.state.front_face, true)),
        area_x0(d.area_x0),
        area_y0(d.area_y0),
        area_x1(d.area_x1),
        area_y1(d.area_y1),
        varyings(d.program->varyings),
        flat(d.program->flat),
        linear(d.program->flat | d.program->noperspective) {}
};

// setup_triangle (stages.hpp), inline for the geometry phase's loop over a chunk's triangles.
__attribute__((always_inline)) inline Prim* setup_triangle_inline(
    const DrawRecord& d, const SetupConstants& sc, const WinVert& v0, const WinVert& v1, const WinVert& v2,
    const float* flat_src, uint32_t prim_id, Facing facing, bool apply_offset, Arena& arena, Counters& c,
    bool* culled, const SmoothCoverage* smooth = nullptr) {
  if (culled) *culled = false;
  // Clipping keeps positions finite and inside the guard band; a vertex that still is not
  // (w rounded to 0, overflow in the interpolation) drops the triangle.
  if (!v0.usable || !v1.usable || !v2.usable) return nullptr;
  int64_t X[3] = {v0.sx, v1.sx, v2.sx};
  int64_t Y[3] = {v0.sy, v1.sy, v2.sy};
  int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
  if (area == 0) return nullptr;

  bool front;
  if (facing == Facing::FromArea) {
    const bool ccw = area > 0;
    front = sc.ccw_front == ccw;
    if (ccw ? sc.cull_ccw : sc.cull_cw) {
      if (culled) *culled = true;
      return nullptr;
    }
  } else {
    front = facing == Facing::Front;
  }
  // Edges are set up on the counter-clockwise order.
  if (area < 0) {
    std::swap(X[1], X[2]);
    std::swap(Y[1], Y[2]);
  }

  int64_t minX = std::min({X[0], X[1], X[2]}), maxX = std::max({X[0], X[1], X[2]});
  int64_t minY = std::min({Y[0], Y[1], Y[2]}), maxY = std::max({Y[0], Y[1], Y[2]});
  // Pixels whose lattice point lies in [min, max): the last row/column can only be touched by
  // an edge that does not own it.
  int minx = int(minX >> kSubpixelBits), maxx = int((maxX - 1) >> kSubpixelBits);
  int miny = int(minY >> kSubpixelBits), maxy = int((maxY - 1) >> kSubpixelBits);
  if (minX & (kSubpixelOne - 1)) ++minx;  // first lattice point at or after min
  if (minY & (kSubpixelOne - 1)) ++miny;
  minx = std::max(minx, sc.area_x0);
  miny = std::max(miny, sc.area_y0);
  maxx = std::min(maxx, sc.area_x1 - 1);
  maxy = std::min(maxy, sc.area_y1 - 1);
  if (minx > maxx || miny > maxy) return nullptr;

  EdgeEq e[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const int64_t dx = X[j] - X[i], dy = Y[j] - Y[i];
    // E(P) = dx (Py - Yi) - dy (Px - Xi), positive to the left of i->j (the interior).
    const bool owns_ties = dy < 0 || (dy == 0 && dx > 0);
    e[i].a = -dy * kSubpixelOne;
    e[i].b = dx * kSubpixelOne;
    e[i].c = dy * X[i] - dx * Y[i] + (owns_ties ? 1 : 0);
  }
  // Most triangles of a tessellated mesh cover a few pixels, and a quarter of those none at
  // all: their coverage is found here, so the empty ones cost no planes, no memory and no
  // raster work, and the raster phase reads the others' groups from a mask.
  uint64_t cover = 0;
  const int gx0 = minx & ~3, gy0 = miny & ~1;
  if (!smooth && maxx < gx0 + 8 && maxy < gy0 + 8 && small_edges(e)) {
    cover = small_coverage(e, minx, miny, maxx, maxy);
    if (!cover) return nullptr;
  }

  const int K = sc.varyings;
  auto* p =
      static_cast<Prim*>(arena.allocate(Prim::bytes(K, cover == 0) + (smooth ? sizeof(SmoothCoverage) : 0)));
  // The frame's Prims do not fit in any cache: the lines a few Prims ahead are requested
  // now, so that their first stores do not wait on memory.
  for (int o = 0; o < 256; o += 64) __builtin_prefetch(reinterpret_cast<char*>(p) + 1024 + o, 1);
  new (p) Prim;  // no zeroing: every field is set below
  p->kind = smooth ? PrimKind::Smooth : PrimKind::Triangle;
  p->front = front;
  p->prim_id = prim_id;
  p->minx = minx;
  p->miny = miny;
  p->maxx = maxx;
  p->maxy = maxy;
  p->cover = cover;
  if (!cover) std::copy_n(e, 3, p->edges(K));
  if (smooth) *p->smooth(K) = *smooth;

  // Planes from the float window positions, anchored at v0.
  PlaneSolver s;
  s.dx1 = double(v1.x) - v0.x;
  s.dy1 = double(v1.y) - v0.y;
  s.dx2 = double(v2.x) - v0.x;
  s.dy2 = double(v2.y) - v0.y;
  double det = s.dx1 * s.dy2 - s.dx2 * s.dy1;
  if (std::fabs(det) < 1e-12) det = double(area) / double(kSubpixelOne * kSubpixelOne);
  s.inv_det = 1.0 / det;
  p->xr = v0.x;
  p->yr = v0.y;
  s.solve(v0.z, v1.z, v2.z, p->z);
  if (apply_offset) p->z[0] += polygon_offset(d, v0, v1, v2);
  s.solve(v0.oow, v1.oow, v2.oow, p->oow);
  // Varying planes (structure of arrays: values at the anchor, then d/dx, then d/dy).
  // Perspective-correct components are interpolated as value/w.
  float* pl = p->planes();
  const uint64_t flat = sc.flat, linear = sc.linear;
  int k = 0;
  // Four components at a time where all four are perspective-correct: PlaneSolver's
  // operations in float and double vectors, loaded straight from the vertices' varyings.
  using f4 = float __attribute__((vector_size(16)));
  using d4 = double __attribute__((vector_size(32)));
  auto load4 = [](const float* q) {
    f4 r;
    std::memcpy(&r, q, sizeof r);
    return r;
  };
  auto store4 = [](float* q, f4 r) { std::memcpy(q, &r, sizeof r); };
  const d4 dx1 = d4{} + s.dx1, dy1 = d4{} + s.dy1, dx2 = d4{} + s.dx2, dy2 = d4{} + s.dy2,
           inv = d4{} + s.inv_det;
  for (; k + 4 <= K && !((linear >> k) & 0xF); k += 4) {
    const f4 a0 = load4(v0.var + k) * v0.oow, a1 = load4(v1.var + k) * v1.oow,
             a2 = load4(v2.var + k) * v2.oow;
    const d4 b0 = __builtin_convertvector(a0, d4);
    const d4 d1 = __builtin_convertvector(a1, d4) - b0, d2 = __builtin_convertvector(a2, d4) - b0;
    store4(pl + k, a0);
    store4(pl + K + k, __builtin_convertvector((d1 * dy2 - d2 * dy1) * inv, f4));
    store4(pl + 2 * K + k, __builtin_convertvector((d2 * dx1 - d1 * dx2) * inv, f4));
  }
  for (; k < K; ++k) {
    const bool lin = (linear >> k) & 1;
    s.solve(lin ? v0.var[k] : v0.var[k] * v0.oow, lin ? v1.var[k] : v1.var[k] * v1.oow,
            lin ? v2.var[k] : v2.var[k] * v2.oow, pl + k, K);
  }
  for (uint64_t f = flat; f; f &= f - 1) {
    const int k = __builtin_ctzll(f);
    if (k >= K) break;
    pl[k] = flat_src[k];
    pl[K + k] = pl[2 * K + k] = 0.0f;
  }
  ++c.triangles_setup;
  return p;
}

}  // namespace tessel::gpu::detail
