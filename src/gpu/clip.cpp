// Clipping in homogeneous clip space, before the perspective divide (GL 4.6 §13.7), for the
// pipeline: its planes, and clip_space.hpp's polygon and segment clipping over ClipVerts.
//
// Contract: a primitive is kept where every enabled half-space dot(n, pos) + d >= 0 holds.
// The planes are: near (z >= -w) and far (z <= w) unless depth clamping is on; the guard
// band in x and y (only primitives reaching far outside the viewport are cut there, the
// rasterizer's bbox does the rest); w > 0; and the user clip planes.
#include <algorithm>
#include <cmath>

#include "stages.hpp"

namespace tessel::gpu::detail {

ClipPlanes make_clip_planes(const DrawRecord& d) {
  ClipPlanes p;
  // w must stay positive for the divide; the guard band planes imply w >= 0, this keeps w
  // away from zero (and handles depth clamp, which has no near plane).
  p.add({0, 0, 0, 1}, -1e-30f);
  if (!d.state.depth_clamp) {
    p.add({0, 0, 1, 1});   // near: z + w >= 0
    p.add({0, 0, -1, 1});  // far: w - z >= 0
  }
  p.add({-1, 0, 0, d.guard_x});
  p.add({1, 0, 0, d.guard_x});
  p.add({0, -1, 0, d.guard_y});
  p.add({0, 1, 0, d.guard_y});
  // A user plane is the program's clip distance i where it writes one (gl_ClipDistance),
  // else a plane in clip space.
  const int distances = d.program ? d.program->clip_distances : 0;
  for (int i = 0; i < kMaxClipPlanes; ++i) {
    if (!(d.state.clip_plane_enable & (1u << i))) continue;
    if (i < distances)
      p.add(glm::vec4(0.0f), 0.0f, d.program->clip_distance_var + i);
    else
      p.add(d.state.clip_planes[i]);
    p.user_planes |= 1u << (p.count - 1);
  }
  return p;
}

int clip_polygon(const ClipPlanes& planes, unsigned mask, ClipVert* a, int n, ClipVert* b, int varyings,
                 ClipVert** out, int edge_flag) {
  constexpr int kMaxOut = 3 + 6 + kMaxClipPlanes + 1;
  return gpu::clip_polygon(
      planes.count, mask, a, n, b, kMaxOut,
      [&](int i, const ClipVert& v) { return plane_distance(planes, i, v.pos, v.var); },
      [&](const ClipVert& from, const ClipVert& to, float t, ClipVert& r) {
        r.pos = from.pos + (to.pos - from.pos) * t;
        for (int k = 0; k < varyings; ++k) r.var[k] = from.var[k] + (to.var[k] - from.var[k]) * t;
      },
      out,
      [&](ClipVert& v, const ClipVert& prev, int plane, bool entering) {
        // Edge flags as Mesa's draw module (and NVIDIA) set them: a point where the polygon
        // comes back inside starts the rest of the edge it lies on; one where it leaves starts
        // an edge along the plane, drawn for a user clip plane and not for the view volume's.
        if (edge_flag < 0) return;
        const float along = (planes.user_planes >> plane) & 1u ? 1.0f : 0.0f;
        v.var[edge_flag] = entering ? prev.var[edge_flag] : along;
      });
}

bool clip_line(const ClipPlanes& planes, unsigned mask, const glm::vec4& p0, const glm::vec4& p1,
               const float* v0, const float* v1, float& t0, float& t1) {
  return clip_segment(
      planes.count, mask,
      [&](int i, int end) {
        return end == 0 ? plane_distance(planes, i, p0, v0) : plane_distance(planes, i, p1, v1);
      },
      t0, t1);
}

}  // namespace tessel::gpu::detail
