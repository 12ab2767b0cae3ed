// Clipping in homogeneous clip space, before the perspective divide (GL 4.6 §13.7).
//
// Contract: a primitive is kept where every enabled half-space dot(n, pos) + d >= 0 holds.
// The planes are: near (z >= -w) and far (z <= w) unless depth clamping is on; the guard
// band in x and y (only primitives reaching far outside the viewport are cut there, the
// rasterizer's bbox does the rest); w > 0; and the user clip planes. Each new vertex is
// interpolated from the inside vertex toward the outside one, so an edge shared by two
// triangles is cut at the same point in both.
#include <algorithm>
#include <cmath>

#include "stages.hpp"

namespace tessel::gpu::detail {

ClipPlanes make_clip_planes(const DrawRecord& d) {
  ClipPlanes p;
  auto add = [&](glm::vec4 n, float off, int var = -1) {
    p.n[p.count] = n;
    p.d[p.count] = off;
    p.var[p.count] = int8_t(var);
    if (var >= 0) p.var_planes |= 1u << p.count;
    ++p.count;
  };
  // w must stay positive for the divide; the guard band planes imply w >= 0, this keeps w
  // away from zero (and handles depth clamp, which has no near plane).
  add({0, 0, 0, 1}, -1e-30f);
  if (!d.state.depth_clamp) {
    add({0, 0, 1, 1}, 0.0f);   // near: z + w >= 0
    add({0, 0, -1, 1}, 0.0f);  // far: w - z >= 0
  }
  add({-1, 0, 0, d.guard_x}, 0.0f);
  add({1, 0, 0, d.guard_x}, 0.0f);
  add({0, -1, 0, d.guard_y}, 0.0f);
  add({0, 1, 0, d.guard_y}, 0.0f);
  // A user plane is the program's clip distance i where it writes one (gl_ClipDistance),
  // else a plane in clip space.
  const int distances = d.program ? d.program->clip_distances : 0;
  for (int i = 0; i < kMaxClipPlanes; ++i) {
    if (!(d.state.clip_plane_enable & (1u << i))) continue;
    if (i < distances)
      add(glm::vec4(0.0f), 0.0f, d.program->clip_distance_var + i);
    else
      add(d.state.clip_planes[i], 0.0f);
  }
  return p;
}

static void lerp_vertex(const ClipVert& in, const ClipVert& out, float t, int varyings, ClipVert& r) {
  r.pos = in.pos + (out.pos - in.pos) * t;
  for (int k = 0; k < varyings; ++k) r.var[k] = in.var[k] + (out.var[k] - in.var[k]) * t;
}

int clip_polygon(const ClipPlanes& planes, unsigned mask, ClipVert* a, int n, ClipVert* b, int varyings,
                 ClipVert** out) {
  ClipVert* src = a;
  ClipVert* dst = b;
  constexpr int kMaxOut = 3 + 6 + kMaxClipPlanes + 1;
  for (int i = 0; i < planes.count && n > 0; ++i) {
    if (!(mask & (1u << i))) continue;
    int m = 0;
    float dprev = plane_distance(planes, i, src[n - 1].pos, src[n - 1].var);
    for (int j = 0; j < n; ++j) {
      const ClipVert& prev = src[(j + n - 1) % n];
      const ClipVert& cur = src[j];
      const float dcur = plane_distance(planes, i, cur.pos, cur.var);
      const bool in_prev = dprev >= 0.0f, in_cur = dcur >= 0.0f;
      if (in_prev != in_cur && m < kMaxOut) {
        // Always interpolate from the inside vertex to the outside one.
        if (in_prev)
          lerp_vertex(prev, cur, dprev / (dprev - dcur), varyings, dst[m++]);
        else
          lerp_vertex(cur, prev, dcur / (dcur - dprev), varyings, dst[m++]);
      }
      if (in_cur && m < kMaxOut) {
        dst[m].pos = cur.pos;
        for (int k = 0; k < varyings; ++k) dst[m].var[k] = cur.var[k];
        ++m;
      }
      dprev = dcur;
    }
    n = m;
    std::swap(src, dst);
  }
  *out = src;
  return n < 3 ? 0 : n;
}

bool clip_line(const ClipPlanes& planes, unsigned mask, const glm::vec4& p0, const glm::vec4& p1,
               const float* v0, const float* v1, float& t0, float& t1) {
  t0 = 0.0f;
  t1 = 1.0f;
  for (int i = 0; i < planes.count; ++i) {
    if (!(mask & (1u << i))) continue;
    const float d0 = plane_distance(planes, i, p0, v0), d1 = plane_distance(planes, i, p1, v1);
    if (!(d0 >= 0.0f) && !(d1 >= 0.0f)) return false;
    if (d0 < 0.0f)
      t0 = std::max(t0, d0 / (d0 - d1));
    else if (d1 < 0.0f)
      t1 = std::min(t1, d0 / (d0 - d1));
  }
  return t0 < t1;
}

}  // namespace tessel::gpu::detail
