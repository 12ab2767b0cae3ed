// Immediate mode into primitives (GL 2.1 §2.6): glVertex collects vertices with the current
// attributes; glEnd cuts the mode into points, lines and triangles (quads split along a
// diagonal, polygons into fans, edge flags kept for polygon modes, provoking vertices where GL
// puts them), and emit() hands them to batching, selection or feedback.
#include "context.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace tessel::gl {

void Context::vertex(float x, float y, float z, float w) {
  FFVertex v;
  v.pos[0] = x;
  v.pos[1] = y;
  v.pos[2] = z;
  v.pos[3] = w;
  std::memcpy(v.normal, &s.current.normal[0], sizeof v.normal);
  std::memcpy(v.color, &s.current.color[0], sizeof v.color);
  std::memcpy(v.tex, &s.current.tex[0][0], sizeof v.tex);
  v.edge = s.current.edge ? 1.0f : 0.0f;
  if (!extras_touched) return prim.push(v);
  FFExtra e;
  current_extra(s.current, e);
  prim.push(v, e);
}

void current_extra(const CurrentState& cur, FFExtra& e) {
  for (int i = 1; i < kMaxTexCoords; ++i) std::memcpy(e.tex[i - 1], &cur.tex[size_t(i)][0], sizeof e.tex[0]);
  std::memcpy(e.secondary, &cur.secondary[0], sizeof e.secondary);
  e.fog_coord = cur.fog_coord;
  e.pad_[0] = e.pad_[1] = e.pad_[2] = 0.0f;
}

bool Context::extras_live() const {
  const CurrentState& cur = s.current;
  for (int i = 1; i < kMaxTexCoords; ++i)
    if (cur.tex[size_t(i)] != glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) || c.tex[size_t(i)].enabled) return true;
  return cur.secondary != glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) || cur.fog_coord != 0.0f || c.secondary.enabled ||
         c.fog.enabled;
}

void Context::end() {
  in_begin = false;
  FFVertices verts;
  std::swap(verts, prim);
  emit_mode(begin_mode, std::move(verts));
}

// Independent primitives in the order and with the provoking vertex of GL 2.1 §2.6.1 and
// Table 2.9: each triangle lists its provoking vertex last, or first with
// glProvokingVertex(GL_FIRST_VERTEX_CONVENTION) (GL 3.3 Table 2.12; the gpu layer's
// provoking_first takes element 0 of a list's primitive). Quads and quad strips keep their
// last vertex and polygons their first in both conventions, as Mesa does
// (GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION is false). They are cut the way Mesa cuts
// them, so that smooth colours across the inner diagonals agree with it (measured: tests/gl).
void Context::emit_mode(GLenum mode, FFVertices&& v) {
  const uint32_t n = uint32_t(v.size());
  const bool first = s.light.provoking_vertex == GL_FIRST_VERTEX_CONVENTION;
  if (mode != GL_QUADS) close_quad_run();
  std::vector<uint32_t> idx;
  PrimClass cls = PrimClass::Triangles;
  // For polygon-mode lines: the GL edge flag of each edge is kept in the vertex that starts
  // it; edges inside a decomposed quad or polygon are not drawn (GL 2.1 §2.6.2).
  auto tri = [&](uint32_t a, uint32_t b, uint32_t c) {
    idx.push_back(a);
    idx.push_back(b);
    idx.push_back(c);
  };
  switch (mode) {
    case GL_POINTS:
      cls = PrimClass::Points;
      for (uint32_t i = 0; i < n; ++i) idx.push_back(i);
      break;
    case GL_LINES:
      cls = PrimClass::Lines;
      for (uint32_t i = 0; i + 1 < n; i += 2) idx.insert(idx.end(), {i, i + 1});
      for (FFVertex& x : v.v) x.edge = 1.0f;  // each segment restarts the stipple
      break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      cls = PrimClass::Lines;
      for (uint32_t i = 0; i + 1 < n; ++i) idx.insert(idx.end(), {i, i + 1});
      if (mode == GL_LINE_LOOP && n >= 2) idx.insert(idx.end(), {n - 1, 0});
      // For lines the edge flag of a segment's first vertex says whether the line stipple
      // counter restarts there (GL 2.1 §3.4.2: at each glBegin of a strip or loop, and at
      // each segment of GL_LINES): the segments of one strip continue the count.
      for (uint32_t i = 1; i < n; ++i) v[i].edge = 0.0f;
      if (n) v[0].edge = 1.0f;
      break;
    case GL_TRIANGLES:
      for (uint32_t i = 0; i + 2 < n; i += 3) tri(i, i + 1, i + 2);
      break;
    case GL_TRIANGLE_STRIP:
      for (uint32_t i = 0; i + 2 < n; ++i) {
        if (i % 2 == 0)
          tri(i, i + 1, i + 2);
        else if (first)
          tri(i, i + 2, i + 1);  // vertex i provokes: first, the winding kept
        else
          tri(i + 1, i, i + 2);
      }
      break;
    case GL_TRIANGLE_FAN:
      for (uint32_t i = 1; i + 1 < n; ++i) {
        if (first)
          tri(i, i + 1, 0);
        else
          tri(0, i, i + 1);
      }
      break;
    case GL_QUADS:
    case GL_QUAD_STRIP:
    case GL_POLYGON: {
      // Decomposed polygons need their own vertex copies so that each triangle carries the
      // edge flags of its own edges.
      FFVertices out;
      auto put = [&](uint32_t i, bool edge) {
        FFVertex x = v[i];
        x.edge = edge && x.edge != 0.0f ? 1.0f : 0.0f;
        out.push_from(v, i, x);
      };
      if (mode == GL_QUADS) {
        const uint32_t whole = n - n % 4;
        if (list_depth > 0) {
          // Quads replayed from a display list: Mesa's lists always cut along v1-v3.
          close_quad_run();
          split_quads(v, whole, true, out, idx);
        } else {
          // Immediate quads join the run of quads that Mesa would draw together; how the
          // run is cut is known only when it ends (close_quad_run).
          const gpu::ClipPlanes planes = cpu_clip_planes();
          const glm::mat4 mvp = projection() * modelview();
          for (uint32_t i = 0; i < whole; ++i)
            quad_run_clipped_ |= gpu::clip_code(planes, mvp * glm::vec4(v[i].pos[0], v[i].pos[1], v[i].pos[2],
                                                                        v[i].pos[3])) != 0;
          v.v.resize(whole);
          if (v.wide()) v.x.resize(whole);
          quad_run_.append(v);
          return;
        }
      } else if (mode == GL_QUAD_STRIP) {
        // Quad i is v2i, v2i+1, v2i+3, v2i+2 in boundary order; its provoking vertex is v2i+3.
        for (uint32_t i = 0; i + 3 < n; i += 2) {
          const uint32_t base = uint32_t(out.size());
          // (v2, v0, v3) and (v0, v1, v3): v3 last in both. Boundary edges v0-v1, v1-v3,
          // v3-v2, v2-v0.
          put(i + 2, true);   // v2 -> v0
          put(i, false);      // v0 -> v3 inner
          put(i + 3, true);   // v3 -> v2
          put(i, true);       // v0 -> v1
          put(i + 1, true);   // v1 -> v3
          put(i + 3, false);  // v3 -> v0 inner
          tri(base, base + 1, base + 2);
          tri(base + 3, base + 4, base + 5);
        }
      } else if (n >= 3) {
        // (v_i, v_i+1, v0): edge v_i -> v_i+1 is a boundary edge; v_i+1 -> v0 only for the
        // last triangle; v0 -> v_i only for the first.
        for (uint32_t i = 1; i + 1 < n; ++i) {
          const uint32_t base = uint32_t(out.size());
          put(i, true);
          put(i + 1, i + 2 == n);
          put(0, i == 1);
          tri(base, base + 1, base + 2);
        }
      }
      v = std::move(out);
      provoking_vertex_first(idx);
      break;
    }
    default: return;
  }
  if (idx.empty()) return;
  emit(cls, std::move(v), std::move(idx));
}

// Triangles listed with their provoking vertex last, rotated to list it first: (a, b, c)
// becomes (c, a, b), which keeps the winding and each vertex's edge flag on its own edge.
void rotate_provoking_first(std::vector<uint32_t>& triangles) {
  for (size_t i = 0; i + 2 < triangles.size(); i += 3) {
    const uint32_t c = triangles[i + 2];
    triangles[i + 2] = triangles[i + 1];
    triangles[i + 1] = triangles[i];
    triangles[i] = c;
  }
}

void Context::provoking_vertex_first(std::vector<uint32_t>& idx) const {
  if (s.light.provoking_vertex == GL_FIRST_VERTEX_CONVENTION) rotate_provoking_first(idx);
}

// Mesa cuts a quad (v0, v1, v2, v3) in one of two ways, measured on 22.3 (tests/gl): along
// v0-v2, (v0, v1, v2), (v0, v2, v3), when its draw needs no clipping; along v1-v3,
// (v0, v1, v3), (v1, v2, v3), when any vertex of the draw (consecutive glBegin(GL_QUADS)
// without a state change in between) lies outside the view volume, and always for display
// lists. The provoking vertex is v3: with the v0-v2 cut the first triangle lacks it, so
// with flat shading that triangle's last vertex takes v3's colour and normal (its position
// and texture coordinates stay v2's). Edge flags mark the cut as an inner edge.
void Context::split_quads(const FFVertices& v, uint32_t n, bool along_v1v3, FFVertices& out,
                          std::vector<uint32_t>& idx) const {
  const bool flat = s.light.shade_model == GL_FLAT;
  auto put = [&](uint32_t i, const FFVertex& a, bool edge) {
    FFVertex x = a;
    x.edge = edge && a.edge != 0.0f ? 1.0f : 0.0f;
    idx.push_back(uint32_t(out.size()));
    out.push_from(v, i, x);
  };
  for (uint32_t i = 0; i + 3 < n; i += 4) {
    const FFVertex &a = v[i], &b = v[i + 1], &c = v[i + 2], &d = v[i + 3];
    if (along_v1v3) {
      put(i, a, true);       // a -> b
      put(i + 1, b, false);  // b -> d inner
      put(i + 3, d, true);   // d -> a
      put(i + 1, b, true);   // b -> c
      put(i + 2, c, true);   // c -> d
      put(i + 3, d, false);  // d -> b inner
    } else {
      FFVertex c_first = c;
      if (flat) {
        std::memcpy(c_first.normal, d.normal, sizeof c_first.normal);
        std::memcpy(c_first.color, d.color, sizeof c_first.color);
      }
      put(i, a, true);             // a -> b
      put(i + 1, b, true);         // b -> c
      put(i + 2, c_first, false);  // c -> a inner
      if (flat && v.wide())        // the secondary colour is flat shaded too
        std::memcpy(out.x.back().secondary, v.x[i + 3].secondary, sizeof out.x.back().secondary);
      put(i, a, false);     // a -> c inner
      put(i + 2, c, true);  // c -> d
      put(i + 3, d, true);  // d -> a
    }
  }
}

void Context::close_quad_run() {
  if (quad_run_.empty()) return;
  FFVertices run;
  std::swap(run, quad_run_);
  const bool clipped = quad_run_clipped_;
  quad_run_clipped_ = false;
  FFVertices out;
  std::vector<uint32_t> idx;
  split_quads(run, uint32_t(run.size()), clipped, out, idx);
  provoking_vertex_first(idx);
  emit(PrimClass::Triangles, std::move(out), std::move(idx));
}

void Context::emit(PrimClass cls, FFVertices&& verts, std::vector<uint32_t>&& indices) {
  if (indices.empty() || compiling_only()) return;
  close_quad_run();  // earlier quads go first
  if (render_mode_ != GL_RENDER) {
    // Selection and feedback modes report primitives instead of drawing them.
    if (render_mode_ == GL_SELECT)
      select_primitives(cls, verts, indices);
    else
      feedback_primitives(cls, verts, indices);
    return;
  }
  if (!batch_.indices.empty() && batch_.cls != cls) send_batch();
  if (batch_.indices.empty()) {
    batch_.cls = cls;
    batch_.verts = std::move(verts);
    batch_.indices = std::move(indices);
  } else {
    const uint32_t base = uint32_t(batch_.verts.size());
    batch_.verts.append(verts);
    for (uint32_t i : indices) batch_.indices.push_back(base + i);
  }
  if (batch_.verts.size() > (1u << 20)) send_batch();
}

void Context::emit_shared(std::shared_ptr<const gpu::Buffer> vertices, std::vector<uint32_t>&& indices) {
  if (indices.empty() || compiling_only()) return;
  close_quad_run();
  if (!batch_.indices.empty()) send_batch();
  batch_.cls = PrimClass::Triangles;
  batch_.shared = std::move(vertices);
  batch_.indices = std::move(indices);
  send_batch();
}

}  // namespace tessel::gl
