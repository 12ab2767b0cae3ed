// Triangle setup: from window-space vertices to the edge equations and planes the raster
// phase evaluates (GL 4.6 §14.6; the exact rules are llvmpipe's, see RASTER_NOTES §2).
//
// Contract:
// - positions snap to 1/256 pixel: X = round_even((x - 0.5) * 256), so pixel (i, j) is
//   sampled at the lattice point (256 i, 256 j) (its centre);
// - facing and culling come from the sign of the snapped area; zero area is dropped;
// - edge E(i, j) = c + a i + b j is positive inside; samples exactly on an edge belong to the
//   triangle when the edge is a left edge (interior toward +x) or a horizontal edge with the
//   interior toward +y (D3D's top-left rule run on GL's y-up window coordinates, which is
//   what llvmpipe does for framebuffer objects) - so two triangles sharing an edge never
//   both cover a sample on it, and never both miss it;
// - depth, 1/w and varying/w are planes in screen space anchored at vertex 0.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "setup_triangle.hpp"

namespace tessel::gpu::detail {

float polygon_offset(const DrawRecord& d, const WinVert& v0, const WinVert& v1, const WinVert& v2) {
  const double dx1 = v1.x - v0.x, dy1 = v1.y - v0.y, dx2 = v2.x - v0.x, dy2 = v2.y - v0.y;
  const double det = dx1 * dy2 - dx2 * dy1;
  double m = 0.0;
  if (det != 0.0) {
    const double dz1 = v1.z - v0.z, dz2 = v2.z - v0.z;
    const double dzdx = (dz1 * dy2 - dz2 * dy1) / det;
    const double dzdy = (dz2 * dx1 - dz1 * dx2) / det;
    m = std::max(std::fabs(dzdx), std::fabs(dzdy));
  }
  double r = d.depth_resolution;
  if (d.depth_float) {
    // GL 4.6 §14.6.5: for floating-point depth, r = 2^(e - 23) with e the largest exponent
    // of the primitive's z values.
    const float zmax = std::max({std::fabs(v0.z), std::fabs(v1.z), std::fabs(v2.z)});
    int e = 0;
    std::frexp(zmax, &e);
    r = std::ldexp(1.0, e - 1 - 23);
  }
  return float(m * d.state.offset_factor + r * d.state.offset_units);
}

void finish_vertices(const DrawRecord& d, const ClipPlanes& planes, const float* soa, const float* vars,
                     int K, size_t n, unsigned* codes, WinVert* win) {
  const Float8 inf(std::numeric_limits<float>::infinity());
  const Float8 band(2.0f * kGuardBand), limit(2.0f * kGuardBand * float(kSubpixelOne));
  for (size_t base = 0; base < n; base += 8) {
    const float* b = soa + base * 4;
    const Float8 x = Float8::load(b), y = Float8::load(b + 8), z = Float8::load(b + 16),
                 w = Float8::load(b + 24);
    // clip_code: distances in the same order of operations, NaN outside.
    Int8 code(0);
    for (int i = 0; i < planes.count; ++i) {
      const glm::vec4& pn = planes.n[i];
      const Float8 dist =
          Float8(pn.x) * x + Float8(pn.y) * y + Float8(pn.z) * z + Float8(pn.w) * w + Float8(planes.d[i]);
      code = code | select(dist >= Float8(0.0f), Int8(0), Int8(int32_t(1u << i)));
    }
    const Mask8 finite = (abs(x) < inf) & (abs(y) < inf) & (abs(z) < inf) & (abs(w) < inf);
    code = select(finite, code, Int8(int32_t(kNotFinite)));
    // to_window and snap_vertex.
    const Float8 oow = Float8(1.0f) / w;
    const Float8 wx = x * oow * Float8(d.vp_scale[0]) + Float8(d.vp_offset[0]);
    const Float8 wy = y * oow * Float8(d.vp_scale[1]) + Float8(d.vp_offset[1]);
    const Float8 wz = z * oow * Float8(d.vp_scale[2]) + Float8(d.vp_offset[2]);
    const Mask8 usable = (abs(wx) < inf) & (abs(wy) < inf) & (abs(wz) < inf) & (abs(oow) < inf) &
                         (oow > Float8(0.0f)) & (abs(wx) <= band) & (abs(wy) <= band);
    auto snap8 = [&](Float8 v) {
      Float8 r = (v - Float8(0.5f)) * Float8(float(kSubpixelOne));
#if defined(__AVX__)
      r = Float8(__builtin_ia32_roundps256(r.v, 0x8));  // to nearest even, as nearbyint
#else
      for (int l = 0; l < 8; ++l) r[l] = std::nearbyint(r[l]);
#endif
      return select(usable, to_int(min(max(r, -limit), limit)), Int8(0));
    };
    const Int8 sx = snap8(wx), sy = snap8(wy);
    const int m = int(std::min<size_t>(8, n - base));
    for (int l = 0; l < m; ++l) {
      const size_t i = base + size_t(l);
      // Clip distances (their position test above passed): the vertex's own values.
      for (unsigned v = planes.var_planes; v; v &= v - 1) {
        const int p = __builtin_ctz(v);
        if (!(vars[i * size_t(K) + size_t(planes.var[p])] >= 0.0f)) code[l] |= int32_t(1u << p);
      }
      codes[i] = unsigned(code[l]);
      if (code[l] == 0) {
        WinVert& v = win[i];
        v.x = wx[l];
        v.y = wy[l];
        v.z = wz[l];
        v.oow = oow[l];
        v.var = vars + i * size_t(K);
        v.sx = sx[l];
        v.sy = sy[l];
        v.usable = usable[l];
      }
    }
  }
}

Prim* setup_triangle(const DrawRecord& d, const WinVert& v0, const WinVert& v1, const WinVert& v2,
                     const float* flat_src, uint32_t prim_id, Facing facing, bool apply_offset, Arena& arena,
                     Counters& c, bool* culled, const SmoothCoverage* smooth) {
  return setup_triangle_inline(d, SetupConstants(d), v0, v1, v2, flat_src, prim_id, facing, apply_offset,
                               arena, c, culled, smooth);
}

namespace {

// An antialiased line as llvmpipe's draw module draws it (draw_pipe_aaline.c): a quad half
// a pixel longer than the line at each end and `half width` to each side, with half width 1
// for lines up to 1 wide and width/2 + 1/2 above, drawn as two triangles (never culled) whose
// fragments get the coverage of SmoothCoverage.
int setup_smooth_line(const DrawRecord& d, const WinVert& v0, const WinVert& v1, const float* flat_src,
                      uint32_t prim_id, bool front, float z_offset, Arena& arena, Counters& c, Prim** out) {
  const float dx = v1.x - v0.x, dy = v1.y - v0.y;
  const float length = std::sqrt(dx * dx + dy * dy);
  if (!(length > 0.0f)) return 0;
  const float ca = dx / length, sa = dy / length;
  const float hw = d.state.line_width <= 1.0f ? 1.0f : 0.5f * d.state.line_width + 0.5f;
  const float hl = 0.5f * length + 0.5f;
  constexpr float tl = 0.5f;
  // Corners: 0 and 1 at v0's end (+ and - the perpendicular), 2 and 3 at v1's.
  WinVert q[4] = {v0, v0, v1, v1};
  q[0].x += -tl * ca - hw * sa;
  q[0].y += -tl * sa + hw * ca;
  q[1].x += -tl * ca + hw * sa;
  q[1].y += -tl * sa - hw * ca;
  q[2].x += tl * ca - hw * sa;
  q[2].y += tl * sa + hw * ca;
  q[3].x += tl * ca + hw * sa;
  q[3].y += tl * sa - hw * ca;
  for (auto& w : q) {
    w.z += z_offset;
    snap_vertex(w);
  }
  SmoothCoverage cov;
  cov.ox = 0.5f * (v0.x + v1.x);
  cov.oy = 0.5f * (v0.y + v1.y);
  cov.ux = -sa;  // across the line
  cov.uy = ca;
  cov.vx = ca;  // along it
  cov.vy = sa;
  cov.a = hw;
  cov.b = hl;
  cov.point = false;
  const Facing f = front ? Facing::Front : Facing::Back;
  int n = 0;
  if (Prim* p = setup_triangle(d, q[2], q[1], q[0], flat_src, prim_id, f, false, arena, c, nullptr, &cov))
    out[n++] = p;
  if (Prim* p = setup_triangle(d, q[3], q[1], q[2], flat_src, prim_id, f, false, arena, c, nullptr, &cov))
    out[n++] = p;
  return n;
}

}  // namespace

int setup_line(const DrawRecord& d, const WinVert& v0, const WinVert& v1, const float* flat_src,
               uint32_t prim_id, bool front, float z_offset, Arena& arena, Counters& c, Prim** out) {
  if (d.state.line_smooth)
    return setup_smooth_line(d, v0, v1, flat_src, prim_id, front, z_offset, arena, c, out);
  const float dx = v1.x - v0.x, dy = v1.y - v0.y;
  if (dx == 0.0f && dy == 0.0f) return 0;
  const float half = std::max(d.state.line_width, 1.0f) * 0.5f;
  const bool x_major = std::fabs(dx) >= std::fabs(dy);
  // Aliased lines (GL 4.6 §14.5.2.1): a parallelogram of the line's width along the minor
  // axis. The sample owned by the last endpoint is excluded and the first included, as the
  // diamond-exit rule gives: the parallelogram is moved by one sub-pixel step along the
  // direction of travel when that direction is negative, so that the fill rule's owned edge
  // is always at the start.
  // Built from its ends in major-axis order whichever way it was drawn, so that a line
  // drawn A->B and B->A gets the same depth and attributes at each sample (a shared edge
  // of two faces drawn twice then keeps the first one under GL_LESS, as on llvmpipe, which
  // also orders a line's ends along its major axis). Only the coverage depends on the
  // direction: the parallelogram's lattice position moves by one sub-pixel step along the
  // major axis for a line drawn backwards (the planes keep the unmoved float positions).
  const bool backwards = x_major ? dx < 0 : dy < 0;
  // The diamond-exit rule at the ends of a width-1 line (GL 4.6 §14.5.1): an end inside its
  // pixel's diamond (|x - xc| + |y - yc| < 1/2) decides that pixel itself — the last one
  // is not drawn (the line does not leave its diamond), the first one is (it does) —
  // where the parallelogram would decide by which side of the centre the end lies. Such an
  // end is moved along the line to the pixel centre for coverage only (as llvmpipe's
  // lp_setup_line does); depth and attributes keep the ends' own positions.
  float rx[2] = {v0.x, v1.x}, ry[2] = {v0.y, v1.y};  // the ends for coverage: start, end
  if (d.state.line_width < 1.5f) {
    const float dmaj = x_major ? dx : dy;
    for (int e = 0; e < 2; ++e) {
      const float cx = std::floor(rx[e]) + 0.5f, cy = std::floor(ry[e]) + 0.5f;
      if (!(std::fabs(rx[e] - cx) + std::fabs(ry[e] - cy) < 0.5f)) continue;
      const float past = (x_major ? rx[e] - cx : ry[e] - cy) * (dmaj > 0.0f ? 1.0f : -1.0f);
      if (!(past > 0.0f)) continue;  // already on the side of the centre the rule wants
      const float t = (x_major ? cx - rx[e] : cy - ry[e]) / dmaj;
      rx[e] += t * dx;
      ry[e] += t * dy;
      if (x_major)
        rx[e] = cx;
      else
        ry[e] = cy;
    }
  }
  WinVert a = v0, b = v1;
  if (backwards) {
    std::swap(a, b);
    std::swap(rx[0], rx[1]);
    std::swap(ry[0], ry[1]);
  }
  WinVert q[4] = {a, b, b, a};
  // Each corner's end (0: a, 1: b) for its coverage position.
  static constexpr int kEnd[4] = {0, 1, 1, 0};
  if (x_major) {
    q[0].y -= half;
    q[1].y -= half;
    q[2].y += half;
    q[3].y += half;
  } else {
    q[0].x += half;
    q[1].x += half;
    q[2].x -= half;
    q[3].x -= half;
  }
  for (int i = 0; i < 4; ++i) {
    WinVert& v = q[i];
    v.z += z_offset;
    // The lattice position comes from the coverage end (moved by the diamond rule, and one
    // sub-pixel step further for a line drawn backwards); the float position (for the
    // planes) stays.
    const float ox = v.x, oy = v.y;
    const int e = kEnd[i];
    v.x += rx[e] - (e == 0 ? a.x : b.x);
    v.y += ry[e] - (e == 0 ? a.y : b.y);
    if (backwards) {
      if (x_major)
        v.x += 1.0f / float(kSubpixelOne);
      else
        v.y += 1.0f / float(kSubpixelOne);
    }
    snap_vertex(v);
    v.x = ox;
    v.y = oy;
  }
  const Facing f = front ? Facing::Front : Facing::Back;
  int n = 0;
  if (Prim* p = setup_triangle(d, q[0], q[1], q[2], flat_src, prim_id, f, false, arena, c, nullptr))
    out[n++] = p;
  if (Prim* p = setup_triangle(d, q[0], q[2], q[3], flat_src, prim_id, f, false, arena, c, nullptr))
    out[n++] = p;
  return n;
}

int setup_point(const DrawRecord& d, const WinVert& v, uint32_t prim_id, bool front, float z_offset,
                Arena& arena, Counters& c, Prim** out) {
  const ProgramBase& prog = *d.program;
  // The size: the vertex shader's (gl_PointSize) with program_point_size, clamped as GL clamps
  // the derived size to ALIASED_POINT_SIZE_RANGE, which is 1..255 here as on llvmpipe.
  float size = d.state.point_size;
  const bool per_vertex = d.state.program_point_size && prog.point_size_var >= 0;
  if (per_vertex) size = v.var[prog.point_size_var];
  // An antialiased point (llvmpipe's draw_pipe_aapoint.c): a square of radius 1 for sizes up to
  // 2, size/2 above (the vertex's size / 2 as it is, with a per-vertex size), whose fragments
  // get the coverage of SmoothCoverage.
  const bool smooth = d.state.point_smooth;
  float half;
  if (smooth) {
    half = per_vertex ? 0.5f * size : size <= 2.0f ? 1.0f : 0.5f * std::min(size, 255.0f);
    if (!(half > 0.0f) || !std::isfinite(half)) return 0;
  } else {
    size = size >= 1.0f ? std::min(size, 255.0f) : 1.0f;  // NaN: 1
    half = size * 0.5f;
  }
  SmoothCoverage cov;
  if (smooth) {
    const float k = 1.0f / half;
    cov.ox = v.x;
    cov.oy = v.y;
    cov.ux = cov.vy = k;
    cov.uy = cov.vx = 0.0f;
    cov.a = 1.0f - 2.0f * k + k * k;  // (1 - 1/r)^2: the squared distance where attenuation starts
    cov.b = 0.0f;
    cov.point = true;
  }
  WinVert q[4] = {v, v, v, v};
  // gl_PointCoord (GL 3.3 §3.4.1): s = 1/2 + (x_f + 1/2 - x_w) / size, and t = 1/2 - (y_f + 1/2 -
  // y_w) / size with the upper-left origin (+ with the lower-left one): linear in the window,
  // so given at the corners (in the order below) and interpolated without perspective.
  float corner_var[4][kMaxVaryings];
  if (const int pc = prog.point_coord_var; pc >= 0) {
    const bool lower_left = d.state.point_sprite_lower_left;
    for (int i = 0; i < 4; ++i) {
      std::copy_n(v.var, prog.varyings, corner_var[i]);
      corner_var[i][pc] = i == 1 || i == 2 ? 1.0f : 0.0f;
      corner_var[i][pc + 1] = (i >= 2) == lower_left ? 1.0f : 0.0f;
      q[i].var = corner_var[i];
    }
  }
  q[0].x -= half;
  q[0].y -= half;
  q[1].x += half;
  q[1].y -= half;
  q[2].x += half;
  q[2].y += half;
  q[3].x -= half;
  q[3].y += half;
  for (auto& w : q) {
    w.z += z_offset;
    snap_vertex(w);
  }
  const Facing f = front ? Facing::Front : Facing::Back;
  const SmoothCoverage* sm = smooth ? &cov : nullptr;
  int n = 0;
  if (Prim* p = setup_triangle(d, q[0], q[1], q[2], v.var, prim_id, f, false, arena, c, nullptr, sm))
    out[n++] = p;
  if (Prim* p = setup_triangle(d, q[0], q[2], q[3], v.var, prim_id, f, false, arena, c, nullptr, sm))
    out[n++] = p;
  return n;
}

}  // namespace tessel::gpu::detail
