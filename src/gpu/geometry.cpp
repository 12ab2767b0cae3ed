// The geometry loop of one chunk of a draw: element ids, the post-transform vertex cache,
// vertex shading, clip codes and window positions, then per primitive: assembly, clipping
// (Sutherland-Hodgman in clip space), setup (setup.cpp, setup_triangle.hpp) and binning.
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>

#include "frame.hpp"
#include "setup_triangle.hpp"

namespace tessel::gpu {
using namespace detail;

void Context::Frame::process_chunk(Worker& w, uint32_t chunk_index) {
  const Chunk& ch = chunks[chunk_index];
  const Command& cmd = commands[ch.command];
  if (cmd.clear) {
    bin(w, chunk_index, nullptr, &clears[cmd.index]->base);
    return;
  }
  process_draw_chunk(w, chunk_index, ch, *draws[cmd.index]);
}

void Context::Frame::process_draw_chunk(Worker& w, uint32_t chunk_index, const Chunk& ch,
                                        const DrawRecord& d) {
  const int K = d.program->varyings;
  const int ps = prim_size(d.topology);
  const uint32_t n_elements = d.count;
  const uint32_t nprims = ch.end - ch.begin;

  // 1. Vertex ids of the chunk's primitives, each shaded once (post-transform cache).
  const size_t total = size_t(nprims) * ps;
  w.prim_slots.resize(total);
  uint32_t* ids = w.prim_slots.data();  // element ids first, replaced by slots below
  if (d.topology == Topology::Triangles) {
    const size_t e0 = size_t(ch.begin) * 3;
    if (d.indexed)
      std::memcpy(ids, d.elements + e0, total * sizeof(uint32_t));
    else
      for (size_t i = 0; i < total; ++i) ids[i] = d.first + uint32_t(e0 + i);
  } else {
    uint32_t e[kMaxGeometryInputVertices];
    for (uint32_t p = 0; p < nprims; ++p) {
      prim_elements(d.topology, ch.begin + p, n_elements, e);
      for (int k = 0; k < ps; ++k) {
        uint32_t id = d.first + e[k];
        if (d.indexed) std::memcpy(&id, d.elements + e[k], 4);  // may be a buffer's bytes
        ids[size_t(p) * ps + k] = id;
      }
    }
  }
  w.ids.clear();
  uint32_t lo = UINT32_MAX, hi = 0;
  for (size_t i = 0; i < total; ++i) {
    lo = std::min(lo, ids[i]);
    hi = std::max(hi, ids[i]);
  }
  const size_t range = size_t(hi - lo) + 1;
  if (range * 3 <= total) {
    // A dense range (a mesh's chunk, whose ids a few rows of vertices span, each used about
    // six times): every id in the range is shaded, in order, and its slot is id - lo. Ids the
    // chunk does not use cost a vertex each, but no more than a third of the chunk's indices,
    // still fewer vertices than an unindexed draw shades.
    w.ids.resize(range);
    for (size_t i = 0; i < range; ++i) w.ids[i] = lo + uint32_t(i);
    for (size_t i = 0; i < total; ++i) ids[i] -= lo;
  } else if (range <= 4 * total) {
    // A compact range of ids: a table indexed by id - lo, without branches (whether an id
    // is new is as good as random, and a mispredicted branch per new id cost more than the
    // loop's other work).
    w.direct.assign(range, UINT32_MAX);
    w.ids.resize(total);
    uint32_t* table = w.direct.data();
    uint32_t* unique = w.ids.data();
    uint32_t count = 0;
    for (size_t i = 0; i < total; ++i) {
      const uint32_t id = ids[i];
      const uint32_t seen = table[id - lo];
      const bool fresh = seen == UINT32_MAX;
      const uint32_t slot = fresh ? count : seen;
      table[id - lo] = slot;
      unique[count] = id;  // kept only when fresh: count moves on
      count += fresh;
      ids[i] = slot;
    }
    w.ids.resize(count);
  } else {
    // Scattered ids: a direct-mapped hash cache (a vertex may be shaded twice on a collision).
    const size_t cache_size = size_t(1) << kCacheBits;
    if (w.cache_tag.size() != cache_size) {
      w.cache_tag.assign(cache_size, 0);
      w.cache_slot.assign(cache_size, 0);
    }
    ++w.stamp;
    for (size_t i = 0; i < total; ++i) {
      const uint32_t id = ids[i];
      const size_t h = (id * 2654435761u) >> (32 - kCacheBits);
      const uint64_t tag = (uint64_t(w.stamp) << 32) | id;
      if (w.cache_tag[h] != tag) {
        w.cache_tag[h] = tag;
        w.cache_slot[h] = uint32_t(w.ids.size());
        w.ids.push_back(id);
      }
      ids[i] = w.cache_slot[h];
    }
  }
  const size_t nv = w.ids.size();
  w.pos.resize(nv);
  w.vars.resize(nv * size_t(K) + 1);
  w.soa.resize((nv + 7) / 8 * 32);
  d.program->shade_vertices(d, w.ids.data(), int(nv), ch.instance, w.pos.data(), w.vars.data(), w.soa.data());
  w.counters.vertices_shaded += nv;
  w.counters.primitives_in += nprims;
  if (d.program->geometry_input) {
    run_geometry(w, ch, d, nprims);
    const Topology list = emitted_list(d.program->geometry_output);
    const uint32_t n_out = uint32_t(w.gs_slots.size() / size_t(prim_size(list)));
    if (d.capture)
      capture(chunk_index, d, list, n_out, w.gs_slots.data(), w.gs_pos.data(), w.gs_vars.data(), 0);
    if (d.raster)
      assemble(w, chunk_index, d, list, n_out, w.gs_slots.data(), w.gs_pos.size(), w.gs_pos.data(),
               w.gs_vars.data(), w.gs_soa.data(), w.gs_prim_ids.data(), 0);
    return;
  }
  w.counters.primitives_generated += nprims;
  if (d.capture)
    capture(chunk_index, d, d.topology, nprims, w.prim_slots.data(), w.pos.data(), w.vars.data(), ch.begin);
  if (d.raster)
    assemble(w, chunk_index, d, d.topology, nprims, w.prim_slots.data(), nv, w.pos.data(), w.vars.data(),
             w.soa.data(), nullptr, ch.begin);
}

// Transform feedback of a chunk's primitives (nprims of topology `topo`, prim_size(topo)
// vertex slots each, in prim_elements' order): each vertex's captured words, in the order
// GL writes them, into the chunk's own list; flush() writes the lists to the buffers in chunk
// order. Strip and fan triangles are listed as prim_elements gives them, and with the
// first-vertex convention turned to start at their provoking vertex, as llvmpipe writes them.
void Context::Frame::capture(uint32_t chunk_index, const DrawRecord& d, Topology topo, uint32_t nprims,
                             const uint32_t* slots, const glm::vec4* pos, const float* vars,
                             uint32_t first_prim) {
  const int K = d.program->varyings;
  const int ps = prim_size(topo);
  const bool first = d.state.provoking_first;
  size_t per_vertex = 0;
  for (const CaptureBuffer& b : d.capture->buffers) per_vertex += b.words.size();
  std::vector<uint32_t>& out = captured[chunk_index];
  out.resize(size_t(nprims) * size_t(ps) * per_vertex);
  uint32_t* o = out.data();
  for (uint32_t p = 0; p < nprims; ++p) {
    const uint32_t* s = slots + size_t(p) * ps;
    const int rot = ps == 3 && first ? provoking_element(topo, first_prim + p, true) : 0;
    for (int k = 0; k < ps; ++k) {
      const uint32_t v = s[(k + rot) % ps];
      for (const CaptureBuffer& b : d.capture->buffers)
        for (const int src : b.words)
          std::memcpy(o++, src >= 0 ? &vars[size_t(v) * K + size_t(src)] : &pos[v][kCapturePosition - src],
                      4);
    }
  }
}

// The geometry stage over the chunk's primitives, sixteen a call: what they emit becomes the
// vertices (gs_pos, gs_vars, gs_soa) and list primitives (gs_slots, gs_prim_ids) that
// assemble() takes. Strips are cut into lines and triangles here, each triangle listed so that
// it keeps the strip's winding and the list's provoking vertex is the strip's.
void Context::Frame::run_geometry(Worker& w, const Chunk& ch, const DrawRecord& d, uint32_t nprims) {
  const ProgramBase& prog = *d.program;
  const int K = prog.varyings;
  const int ps = prim_size(d.topology);
  const int kv = std::min(prog.vertex_varyings, K);
  const int maxv = std::clamp(prog.geometry_max_vertices, 0, kMaxGeometryVertices);
  const int stride = 4 + K;
  constexpr int L = kRuntimeLanes;
  if (!w.gs_lanes) w.gs_lanes = std::make_unique<GeometryLanes>();
  GeometryLanes& g = *w.gs_lanes;
  w.gs_out.assign(size_t(maxv) * size_t(stride) * L, 0.0f);
  w.gs_start.assign(size_t(maxv) * L, 0u);
  g.out = w.gs_out.data();
  g.strip_start = w.gs_start.data();
  g.out_stride = stride;
  w.gs_pos.clear();
  w.gs_vars.clear();
  w.gs_slots.clear();
  w.gs_prim_ids.clear();
  const Topology out_t = prog.geometry_output;
  const bool first = d.state.provoking_first;
  const int pid = prog.primitive_id_var;
  // Of a layered framebuffer drawn a layer at a time, the primitives of other layers go.
  const int layer_var = d.state.layer >= 0 ? prog.layer_var : -1;
  const uint32_t last_layer = uint32_t(std::max(1, d.state.layer_count) - 1);
  const uint32_t* slots = w.prim_slots.data();
  for (uint32_t p0 = 0; p0 < nprims; p0 += L) {
    const int n = int(std::min<uint32_t>(L, nprims - p0));
    g.count = n;
    for (int l = 0; l < L; ++l) {
      const uint32_t p = p0 + uint32_t(std::min(l, n - 1));  // idle lanes repeat the last primitive
      const uint32_t* s = slots + size_t(p) * ps;
      for (int v = 0; v < ps; ++v) {
        const glm::vec4& pos = w.pos[s[v]];
        for (int c = 0; c < 4; ++c) g.position[v][c][l] = pos[c];
        const float* src = &w.vars[size_t(s[v]) * K];
        for (int k = 0; k < kv; ++k) g.varyings[v][k][l] = src[k];
      }
      g.primitive_id[l] = int32_t(ch.begin + p);
      g.emitted[l] = 0;
    }
    prog.shade_geometry(g);
    for (int l = 0; l < n; ++l) {
      const uint32_t ne = std::min<uint32_t>(g.emitted[l], uint32_t(maxv));
      const uint32_t base = uint32_t(w.gs_pos.size());
      for (uint32_t v = 0; v < ne; ++v) {
        const float* row = g.out + size_t(v) * stride * L + l;
        w.gs_pos.emplace_back(row[0], row[L], row[2 * L], row[3 * L]);
        for (int k = 0; k < K; ++k) w.gs_vars.push_back(row[size_t(4 + k) * L]);
      }
      auto add = [&](std::initializer_list<uint32_t> vs, uint32_t provoking) {
        // Counted once for a draw run a layer at a time: in its first layer's run.
        if (d.state.layer <= 0) ++w.counters.primitives_generated;
        if (layer_var >= 0) {
          uint32_t layer;
          std::memcpy(&layer, &w.gs_vars[size_t(base + provoking) * K + size_t(layer_var)], 4);
          if (std::min(layer, last_layer) != uint32_t(d.state.layer)) return;
        }
        for (uint32_t v : vs) w.gs_slots.push_back(base + v);
        uint32_t id = ch.begin + p0 + uint32_t(l);
        if (pid >= 0) std::memcpy(&id, &w.gs_vars[size_t(base + provoking) * K + size_t(pid)], 4);
        w.gs_prim_ids.push_back(id);
      };
      uint32_t run = 0;  // where the current strip began
      for (uint32_t v = 0; v < ne; ++v) {
        if (g.strip_start[size_t(v) * L + l]) run = v;
        if (out_t == Topology::Points) {
          add({v}, v);
        } else if (out_t == Topology::LineStrip) {
          if (v >= run + 1) add({v - 1, v}, first ? v - 1 : v);
        } else if (v >= run + 2) {
          const bool odd = (v - run) & 1;  // (v - run - 2) odd
          if (first)
            odd ? add({v - 2, v, v - 1}, v - 2) : add({v - 2, v - 1, v}, v - 2);
          else
            odd ? add({v - 1, v - 2, v}, v) : add({v - 2, v - 1, v}, v);
        }
      }
    }
  }
  const size_t nv = w.gs_pos.size();
  w.gs_vars.push_back(0.0f);  // never empty
  w.gs_soa.assign((nv + 7) / 8 * 32, 0.0f);
  for (size_t i = 0; i < nv; ++i)
    for (int c = 0; c < 4; ++c) w.gs_soa[i / 8 * 32 + size_t(c) * 8 + i % 8] = w.gs_pos[i][c];
  // Lanes past the last vertex of a block repeat it, as shade_vertices leaves them.
  for (size_t i = nv; i < (nv + 7) / 8 * 8; ++i)
    for (int c = 0; c < 4; ++c) w.gs_soa[i / 8 * 32 + size_t(c) * 8 + i % 8] = w.gs_pos[nv - 1][c];
}

// Clipping, setup and binning of nprims primitives of topology `topo` (slots: prim_size
// vertex slots each) over nv shaded vertices (pos, vars with K components each, soa as
// shade_vertices writes it); each primitive's id is prim_ids[p], or first_prim + p.
void Context::Frame::assemble(Worker& w, uint32_t chunk_index, const DrawRecord& d, Topology topo,
                              uint32_t nprims, const uint32_t* slots, size_t nv, const glm::vec4* pos,
                              const float* vars, const float* soa, const uint32_t* prim_ids,
                              uint32_t first_prim) {
  const int K = d.program->varyings;
  const int ps = prim_size(topo);
  // 2. Per vertex: clip code, and the window position of the vertices inside every plane.
  const ClipPlanes planes = make_clip_planes(d);
  w.codes.resize(nv);
  w.win.resize(nv);
  finish_vertices(d, planes, soa, vars, K, nv, w.codes.data(), w.win.data());

  // 3. Assembly, clipping, setup, binning.
  const PolygonMode mode_front = d.state.polygon_mode;
  const PolygonMode mode_back = d.state.polygon_mode_per_face ? d.state.polygon_mode_back : mode_front;
  const bool fill = mode_front == PolygonMode::Fill && mode_back == PolygonMode::Fill;
  Prim* out[2];
  const bool filled_triangles = ps == 3 && fill;
  // Read through locals in the loop: stores into Prims could alias the vectors' and the
  // DrawRecord's fields as far as the compiler knows, so it would load them again each time.
  const SetupConstants sc(d);
  const unsigned* const codes = w.codes.data();
  const WinVert* const win = w.win.data();
  const bool offset_fill = d.state.offset_fill;
  const bool provoking_first = d.state.provoking_first;
  const int list_provoking = provoking_first ? 0 : ps - 1;  // of a point, line or triangle list
  const bool is_list = topo == Topology::Points || topo == Topology::Lines || topo == Topology::Triangles;
  uint64_t culled_count = 0;
  // Stippled lines: a chunk holds every segment of an instance (Frame::run), so the counter
  // carries along strips here.
  const bool stipple = ps == 2 && d.state.line_stipple && !d.program->geometry_input;
  const bool strip = topo == Topology::LineStrip || topo == Topology::LineLoop;
  float stipple_counter = 0.0f;
  uint32_t stipple_end = ~0u;
  // The drawn pieces of the window-space segment a-b: their ends, and their varyings
  // (clip-space values), interpolated linearly in window space, as Mesa's stipple stage does.
  auto stipple_line = [&](const WinVert& a, const WinVert& b, const float* flat_src, uint32_t prim_id) {
    const float length = std::max(std::fabs(b.x - a.x), std::fabs(b.y - a.y));
    float va[kMaxVaryings], vb[kMaxVaryings];
    auto at = [&](float p, float* var) {
      const float t = p / length;
      WinVert v;
      v.x = a.x + (b.x - a.x) * t;
      v.y = a.y + (b.y - a.y) * t;
      v.z = a.z + (b.z - a.z) * t;
      v.oow = a.oow + (b.oow - a.oow) * t;
      for (int k = 0; k < K; ++k) var[k] = a.var[k] + (b.var[k] - a.var[k]) * t;
      v.var = var;
      snap_vertex(v);
      return v;
    };
    stipple_segment(length, stipple_counter, d.state.line_stipple_factor, d.state.line_stipple_pattern,
                    [&](float p0, float p1) {
                      const WinVert pa = at(p0, va), pb = at(p1, vb);
                      const int n =
                          setup_line(d, pa, pb, flat_src, prim_id, true, 0.0f, w.arena, w.counters, out);
                      for (int i = 0; i < n; ++i) bin(w, chunk_index, &d, out[i]);
                    });
  };
  for (uint32_t p = 0; p < nprims; ++p) {
    const uint32_t prim_id = prim_ids ? prim_ids[p] : first_prim + p;
    const uint32_t* s = slots + size_t(p) * ps;
    const uint32_t provoking =
        s[is_list ? list_provoking : provoking_element(topo, first_prim + p, provoking_first)];
    if (filled_triangles && (codes[s[0]] | codes[s[1]] | codes[s[2]]) == 0) {
      // The common case: a filled triangle inside every plane, set up here without a call.
      bool culled = false;
      Prim* pr = setup_triangle_inline(d, sc, win[s[0]], win[s[1]], win[s[2]], vars + size_t(provoking) * K,
                                       prim_id, Facing::FromArea, offset_fill, w.arena, w.counters, &culled);
      culled_count += culled;
      if (pr) bin(w, chunk_index, &d, pr);
      continue;
    }
    unsigned any_code = 0;
    for (int k = 0; k < ps; ++k) any_code |= w.codes[s[k]];
    if (any_code & kNotFinite) continue;  // NaN or Inf position: the primitive is dropped
    auto var_of = [&](uint32_t slot) { return &vars[size_t(slot) * K]; };

    if (ps == 1) {
      // A point is kept whole or discarded by where its centre is (GL 3.3 §2.20): the view
      // volume's sides too, not the guard band, so a wide point just outside draws nothing.
      const glm::vec4& c = pos[s[0]];
      if (w.codes[s[0]] || !(std::fabs(c.x) <= c.w && std::fabs(c.y) <= c.w)) continue;
      const int n = setup_point(d, w.win[s[0]], prim_id, true, 0.0f, w.arena, w.counters, out);
      for (int i = 0; i < n; ++i) bin(w, chunk_index, &d, out[i]);
      continue;
    }
    if (ps == 2) {
      const glm::vec4 &p0 = pos[s[0]], &p1 = pos[s[1]];
      const unsigned c0 = w.codes[s[0]], c1 = w.codes[s[1]];
      if (c0 & c1) continue;
      const float* flat_src = var_of(provoking);
      WinVert a, b;
      if ((c0 | c1) == 0) {
        a = w.win[s[0]];
        b = w.win[s[1]];
      } else {
        float t0, t1;
        if (!clip_line(planes, c0 | c1, p0, p1, var_of(s[0]), var_of(s[1]), t0, t1)) continue;
        ++w.counters.primitives_clipped;
        ClipVert& ca = w.clip_a[0];
        ClipVert& cb = w.clip_a[1];
        ca.pos = p0 + (p1 - p0) * t0;
        cb.pos = p1 + (p0 - p1) * t1;
        const float *va = var_of(s[0]), *vb = var_of(s[1]);
        for (int k = 0; k < K; ++k) {
          ca.var[k] = va[k] + (vb[k] - va[k]) * t0;
          cb.var[k] = vb[k] + (va[k] - vb[k]) * t1;
        }
        a = to_window(d, ca.pos, ca.var);
        b = to_window(d, cb.pos, cb.var);
      }
      if (stipple) {
        // The counter restarts at each independent segment, at each strip's first (a segment
        // not starting where the one before ended: a restart, or a new instance's chunk), or
        // where the draw's edge mask says.
        const bool reset = d.state.edge_masks
                               ? prim_id >= d.state.edge_mask_count || (d.state.edge_masks[prim_id] & 1u)
                               : !strip || s[0] != stipple_end;
        stipple_end = s[1];
        if (reset) stipple_counter = 0.0f;
        stipple_line(a, b, flat_src, prim_id);
        continue;
      }
      const int n = setup_line(d, a, b, flat_src, prim_id, true, 0.0f, w.arena, w.counters, out);
      for (int i = 0; i < n; ++i) bin(w, chunk_index, &d, out[i]);
      continue;
    }

    // Triangles.
    const float* flat_src = var_of(provoking);
    const unsigned c0 = w.codes[s[0]], c1 = w.codes[s[1]], c2 = w.codes[s[2]];
    if (c0 & c1 & c2) continue;
    WinVert wv[24];
    int nw;
    // Polygon modes Line and Point: whether the edge that starts at each vertex is a boundary
    // edge, from the triangle's edge mask and the edge flag varying. Clipping sets the flags of
    // the vertices it makes as GL draws their edges (clip_polygon), in the component past the
    // K varyings.
    bool boundary[24];
    unsigned flags = 7u;
    if (!fill) {
      if (d.state.edge_masks && prim_id < d.state.edge_mask_count) flags = d.state.edge_masks[prim_id] & 7u;
      const int ef = d.state.edge_flag_varying;
      if (ef >= 0 && ef < K)
        for (int k = 0; k < 3; ++k)
          if (var_of(s[k])[ef] == 0.0f) flags &= ~(1u << k);
    }
    if ((c0 | c1 | c2) == 0) {
      wv[0] = w.win[s[0]];
      wv[1] = w.win[s[1]];
      wv[2] = w.win[s[2]];
      nw = 3;
      for (int k = 0; k < 3; ++k) boundary[k] = (flags >> k) & 1u;
    } else {
      ++w.counters.primitives_clipped;
      const int slot = !fill && K < kMaxVaryings ? K : -1;
      for (int k = 0; k < 3; ++k) {
        w.clip_a[k].pos = pos[s[k]];
        std::copy_n(var_of(s[k]), K, w.clip_a[k].var);
        if (slot >= 0) w.clip_a[k].var[slot] = float((flags >> k) & 1u);
      }
      ClipVert* poly;
      nw = clip_polygon(planes, c0 | c1 | c2, w.clip_a, 3, w.clip_b, K, &poly, slot);
      for (int i = 0; i < nw; ++i) {
        wv[i] = to_window(d, poly[i].pos, poly[i].var);
        boundary[i] = slot < 0 || poly[i].var[slot] != 0.0f;
      }
    }
    if (nw < 3) continue;
    if (fill) {
      for (int i = 1; i + 1 < nw; ++i) {
        bool culled = false;
        Prim* pr = setup_triangle(d, wv[0], wv[i], wv[i + 1], flat_src, prim_id, Facing::FromArea,
                                  d.state.offset_fill, w.arena, w.counters, &culled);
        if (culled) ++w.counters.primitives_culled;
        if (pr) bin(w, chunk_index, &d, pr);
      }
      continue;
    }
    // Polygon mode line or point: facing of the whole (clipped) polygon, then its edges or
    // its vertices (GL 4.6 §14.6.4).
    double area = 0.0;
    for (int i = 0; i < nw; ++i) {
      const WinVert &a = wv[i], &b = wv[(i + 1) % nw];
      area += double(a.x) * b.y - double(b.x) * a.y;
    }
    if (area == 0.0) continue;
    const bool front = front_facing(d.state.front_face, area > 0.0);
    if (culled(d.state.cull, front)) {
      ++w.counters.primitives_culled;
      continue;
    }
    const PolygonMode mode = front ? mode_front : mode_back;
    if (mode == PolygonMode::Fill) {
      const Facing facing = front ? Facing::Front : Facing::Back;
      for (int i = 1; i + 1 < nw; ++i) {
        Prim* pr = setup_triangle(d, wv[0], wv[i], wv[i + 1], flat_src, prim_id, facing, d.state.offset_fill,
                                  w.arena, w.counters, nullptr);
        if (pr) bin(w, chunk_index, &d, pr);
      }
      continue;
    }
    const bool line = mode == PolygonMode::Line;
    const bool offset = line ? d.state.offset_line : d.state.offset_point;
    const float zoff = offset ? polygon_offset(d, wv[0], wv[1], wv[2]) : 0.0f;
    for (int i = 0; i < nw; ++i) {
      if (!boundary[i]) continue;
      const int n = line ? setup_line(d, wv[i], wv[(i + 1) % nw], flat_src, prim_id, front, zoff, w.arena,
                                      w.counters, out)
                         : setup_point(d, wv[i], prim_id, front, zoff, w.arena, w.counters, out);
      for (int j = 0; j < n; ++j) bin(w, chunk_index, &d, out[j]);
    }
  }
  w.counters.primitives_culled += culled_count;
}
}  // namespace tessel::gpu
