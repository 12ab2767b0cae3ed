// The geometry of primitives between the vertex stage and rasterization, written once for
// every path that does it on the CPU: the pipeline (src/gpu: clipping, setup, culling) and
// the GL layer's selection, feedback, stippled lines and raster positions (src/gl).
//
//   - the viewport and depth-range transform (GL 4.6 §13.8.1),
//   - facing and the cull rule (§14.6.1),
//   - clipping in homogeneous clip space (§13.7): planes, clip codes, polygons and segments,
//     done as llvmpipe's clipper (Mesa's draw module) does it, so that a clipped polygon is cut
//     into the same triangles and its new vertices round the same way.
#pragma once

#include <algorithm>
#include <cstdint>
#include <glm/glm.hpp>

#include "tessel/gpu/state.hpp"

namespace tessel::gpu {

// --- the viewport and depth-range transform ----------------------------------------------------
// x_w = x_ndc * w/2 + x + w/2 (and y alike), z_w = z_ndc * (f - n)/2 + (n + f)/2, as a scale
// and an offset in float, as llvmpipe applies them. The depth range is clamped to [0, 1].
struct ViewportTransform {
  glm::vec3 scale{1.0f}, offset{0.0f};
  ViewportTransform() = default;
  ViewportTransform(const Rect& viewport, float depth_near, float depth_far) {
    const float n = std::clamp(depth_near, 0.0f, 1.0f), f = std::clamp(depth_far, 0.0f, 1.0f);
    scale = {float(viewport.width) * 0.5f, float(viewport.height) * 0.5f, (f - n) * 0.5f};
    offset = {float(viewport.x) + float(viewport.width) * 0.5f,
              float(viewport.y) + float(viewport.height) * 0.5f, (n + f) * 0.5f};
  }
  // The window position of a clip-space position (after the divide by w).
  glm::vec3 window(const glm::vec4& clip) const {
    const float oow = 1.0f / clip.w;
    return {clip.x * oow * scale.x + offset.x, clip.y * oow * scale.y + offset.y,
            clip.z * oow * scale.z + offset.z};
  }
};

// A window depth given in [0, 1] (glWindowPos) placed in the depth range [n, f].
inline float depth_in_range(float z, double n, double f) {
  return float(n + std::clamp(double(z), 0.0, 1.0) * (f - n));
}

// --- facing and culling ------------------------------------------------------------------------
// A polygon whose window-space vertices run counter-clockwise (positive signed area) faces
// front when the front face is CCW, and the other way round.
inline bool front_facing(FrontFace front_face, bool counter_clockwise) {
  return (front_face == FrontFace::CCW) == counter_clockwise;
}
inline bool culled(CullMode mode, bool front) {
  return mode == CullMode::FrontAndBack || (mode == CullMode::Front && front) ||
         (mode == CullMode::Back && !front);
}

// --- clipping ----------------------------------------------------------------------------------
// The half-spaces a primitive is clipped against: inside where dot(n, pos) + d >= 0, or for a
// plane with var[i] >= 0 (a clip distance the vertex shader wrote) where the vertex's varying
// component var[i] is >= 0 (n and d are zero then).
struct ClipPlanes {
  static constexpr int kMax = 6 + kMaxClipPlanes + 1;
  int count = 0;
  glm::vec4 n[kMax];
  float d[kMax];
  int8_t var[kMax];
  unsigned var_planes = 0;   // bit i: plane i is a clip distance
  unsigned user_planes = 0;  // bit i: plane i is a user clip plane or clip distance
  void add(const glm::vec4& normal, float offset = 0.0f, int varying = -1) {
    n[count] = normal;
    d[count] = offset;
    var[count] = int8_t(varying);
    if (varying >= 0) var_planes |= 1u << count;
    ++count;
  }
  // The view volume -w <= x, y <= w, and -w <= z <= w unless `depth` is false (depth clamp).
  static ClipPlanes view_volume(bool depth = true) {
    ClipPlanes p;
    p.add({1, 0, 0, 1});
    p.add({-1, 0, 0, 1});
    p.add({0, 1, 0, 1});
    p.add({0, -1, 0, 1});
    if (depth) {
      p.add({0, 0, 1, 1});
      p.add({0, 0, -1, 1});
    }
    return p;
  }
};

// The signed distance of a vertex (clip position, varyings) from plane i.
inline float plane_distance(const ClipPlanes& p, int i, const glm::vec4& v, const float* var = nullptr) {
  if (p.var[i] >= 0) return var ? var[p.var[i]] : 0.0f;
  return p.n[i].x * v.x + p.n[i].y * v.y + p.n[i].z * v.z + p.n[i].w * v.w + p.d[i];
}
// Bit i set when the vertex is outside plane i; NaN is outside every plane.
inline unsigned clip_code(const ClipPlanes& planes, const glm::vec4& pos, const float* var = nullptr) {
  unsigned code = 0;
  for (int i = 0; i < planes.count; ++i)
    if (!(plane_distance(planes, i, pos, var) >= 0.0f)) code |= 1u << i;
  return code;
}

// Clips the convex polygon a[0..n) against the planes in `mask` (Sutherland-Hodgman), as
// Mesa's draw module does: for each edge (prev, cur) from vertex 0 on, prev when it is inside
// and then the crossing point when the edge crosses the plane, interpolated from the edge's
// outside end toward its inside end (so an edge two polygons share is cut at the same point in
// both). `distance(plane, v)` is a vertex's signed distance; `lerp(from, to, t, out)` sets out
// to from + (to - from) * t. a and b each have room for max_out vertices; returns the count
// (0 when fewer than three are left) and points *out at the buffer that holds them.
// `made(v, prev, plane, entering)` is told of each crossing point v made on the edge from prev
// (entering: the edge comes back inside plane; else it leaves, and the polygon's next edge
// runs along the plane), for edge flags.
struct NoCrossingHook {
  template <class V>
  void operator()(V&, const V&, int, bool) const {}
};
template <class V, class Distance, class Lerp, class Made = NoCrossingHook>
int clip_polygon(int plane_count, unsigned mask, V* a, int n, V* b, int max_out, Distance&& distance,
                 Lerp&& lerp, V** out, Made&& made = {}) {
  V* src = a;
  V* dst = b;
  for (int i = 0; i < plane_count && n > 0; ++i) {
    if (!(mask & (1u << i))) continue;
    int m = 0;
    float dprev = distance(i, src[0]);
    for (int j = 1; j <= n; ++j) {
      const V& prev = src[j - 1];
      const V& cur = src[j % n];
      const float dcur = distance(i, cur);
      const bool in_prev = dprev >= 0.0f, in_cur = dcur >= 0.0f;
      if (in_prev && m < max_out) dst[m++] = prev;
      if (in_prev != in_cur && m < max_out) {
        V& v = dst[m++];
        if (in_prev)
          lerp(cur, prev, dcur / (dcur - dprev), v);
        else
          lerp(prev, cur, dprev / (dprev - dcur), v);
        made(v, prev, i, !in_prev);
      }
      dprev = dcur;
    }
    n = m;
    std::swap(src, dst);
  }
  *out = src;
  return n < 3 ? 0 : n;
}

// Line stipple (GL 2.1 §3.4.2) of one segment `length` pixels long along its major axis, after
// clipping, as Mesa's draw module cuts it: piece(p0, p1) for each drawn piece, p0 and p1 in
// pixels from the segment's start. The counter (pixels since the stipple was reset) selects
// bit (counter / factor) mod 16 of the pattern for each pixel, and advances by `length`.
template <class Piece>
void stipple_segment(float length, float& counter, int factor, unsigned pattern, Piece&& piece) {
  factor = std::max(factor, 1);
  bool on = false;
  float start = 0.0f;
  for (int i = 0; float(i) < length; ++i) {
    const bool bit = (pattern >> (unsigned((int(counter) + i) / factor) & 15u)) & 1u;
    if (bit == on) continue;
    if (on && start != float(i)) piece(start, float(i));
    start = float(i);
    on = bit;
  }
  if (on && start < length) piece(start, length);
  counter += length;
}

// Clips the segment from end 0 to end 1 against the planes in `mask`, as Mesa's draw module
// does: t0 is the part cut from end 0 (the new end 0 is p0 + (p1 - p0) * t0), t1 the part cut
// from end 1 (the new end 1 is p1 + (p0 - p1) * t1). `distance(plane, end)` is an end's signed
// distance. False when nothing is left.
template <class Distance>
bool clip_segment(int plane_count, unsigned mask, Distance&& distance, float& t0, float& t1) {
  t0 = 0.0f;
  t1 = 0.0f;
  for (int i = 0; i < plane_count; ++i) {
    if (!(mask & (1u << i))) continue;
    const float d0 = distance(i, 0), d1 = distance(i, 1);
    if (!(d0 >= 0.0f) && !(d1 >= 0.0f)) return false;
    if (d1 < 0.0f) t1 = std::max(t1, d1 / (d1 - d0));
    if (d0 < 0.0f) t0 = std::max(t0, d0 / (d0 - d1));
    if (t0 + t1 >= 1.0f) return false;
  }
  return true;
}

}  // namespace tessel::gpu
