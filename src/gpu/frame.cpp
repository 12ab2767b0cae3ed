// A frame, top to bottom: how queued draws become pixels.
//
//   submit()    validates a draw and records it with copies of everything it reads
//   flush()
//     1. chunks        every draw is cut into numbered chunks of primitives, in submission
//                      order (a clear is one chunk)
//     2. geometry      all workers claim chunks: fetch + vertex shader (post-transform cache),
//                      primitive assembly, clipping, divide + viewport, culling, setup, and
//                      binning into the worker's own per-tile lists, tagged with the chunk
//     3. raster        all workers claim 64x64 tiles; a tile's lists from every worker are
//                      merged by chunk number, so primitives run in submission order and the
//                      image does not depend on the number of threads or on timing
//
// Sort-middle, as in RASTER_NOTES §1; llvmpipe threads only step 3.
#include <algorithm>
#include <atomic>
#include <exception>
#include <climits>
#include <cstring>
#include <cmath>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <span>
#include <string>
#include <utility>
#include <thread>

#include "setup_triangle.hpp"
#include "stages.hpp"
#include "tessel/gpu/context.hpp"

namespace tessel::gpu {
using namespace detail;

namespace {

constexpr uint32_t kChunkPrims = 1024;
// Queued primitives beyond this flush early, so memory stays bounded.
constexpr uint64_t kMaxPendingPrims = 4u << 20;
constexpr int kCacheBits = 12;

struct Command {
  bool clear;
  uint32_t index;
};

struct Chunk {
  uint32_t command;
  uint32_t instance;
  uint32_t begin, end;  // primitives
};

struct BinEntry {
  uint32_t chunk;
  const Prim* prim;
  const DrawRecord* draw;
};

struct Worker {
  Arena arena;
  std::vector<std::vector<BinEntry>> bins;
  Counters counters;
  // Post-transform vertex cache of the current chunk: element id -> slot.
  std::vector<uint64_t> cache_tag;
  std::vector<uint32_t> cache_slot;
  uint32_t stamp = 0;
  std::vector<uint32_t> ids;
  std::vector<uint32_t> prim_slots;
  std::vector<uint32_t> direct;  // id - lo -> slot, for chunks with a compact id range
  std::vector<glm::vec4> pos;
  std::vector<float> vars;
  // Per shaded vertex: clip code (kNotFinite when a coordinate is NaN/Inf) and, when the
  // code is 0, the window position (computed once, shared by every primitive using it).
  std::vector<unsigned> codes;
  std::vector<WinVert> win;
  std::vector<float> soa;  // clip positions as blocks of 8 x, 8 y, 8 z, 8 w
  // Tile-local copies of the colour and depth attachments during the raster phase.
  std::vector<std::byte> tile_color, tile_depth;
  ClipVert clip_a[24], clip_b[24];
};

uint32_t prim_count(Topology t, uint32_t n) {
  switch (t) {
    case Topology::Points: return n;
    case Topology::Lines: return n / 2;
    case Topology::LineStrip: return n >= 2 ? n - 1 : 0;
    case Topology::LineLoop: return n >= 2 ? n : 0;
    case Topology::Triangles: return n / 3;
    case Topology::TriangleStrip:
    case Topology::TriangleFan: return n >= 3 ? n - 2 : 0;
  }
  return 0;
}

int prim_size(Topology t) {
  switch (t) {
    case Topology::Points: return 1;
    case Topology::Lines: case Topology::LineStrip: case Topology::LineLoop: return 2;
    default: return 3;
  }
}

// Elements of primitive p, the provoking vertex last (GL 4.6 §10.1 and Table 13.2).
void prim_elements(Topology t, uint32_t p, uint32_t n, uint32_t* e) {
  switch (t) {
    case Topology::Points: e[0] = p; break;
    case Topology::Lines: e[0] = 2 * p; e[1] = 2 * p + 1; break;
    case Topology::LineStrip: e[0] = p; e[1] = p + 1; break;
    case Topology::LineLoop: e[0] = p; e[1] = (p + 1) % n; break;
    case Topology::Triangles: e[0] = 3 * p; e[1] = 3 * p + 1; e[2] = 3 * p + 2; break;
    case Topology::TriangleStrip:
      // Odd triangles swap their first two vertices to keep the winding.
      if (p & 1) { e[0] = p + 1; e[1] = p; } else { e[0] = p; e[1] = p + 1; }
      e[2] = p + 2;
      break;
    case Topology::TriangleFan: e[0] = 0; e[1] = p + 1; e[2] = p + 2; break;
  }
}

// Expands a strip/fan/loop/list with primitive restart into an independent list.
std::vector<uint32_t> expand_restart(Topology& t, const std::vector<uint32_t>& idx, uint32_t restart) {
  std::vector<uint32_t> out;
  const Topology in = t;
  size_t start = 0;
  auto flush_run = [&](size_t a, size_t b) {  // [a, b)
    const uint32_t n = uint32_t(b - a);
    const uint32_t np = prim_count(in, n);
    uint32_t e[3];
    for (uint32_t p = 0; p < np; ++p) {
      prim_elements(in, p, n, e);
      for (int k = 0; k < prim_size(in); ++k) out.push_back(idx[a + e[k]]);
    }
  };
  for (size_t i = 0; i <= idx.size(); ++i) {
    if (i == idx.size() || idx[i] == restart) {
      flush_run(start, i);
      start = i + 1;
    }
  }
  t = prim_size(in) == 1 ? Topology::Points : prim_size(in) == 2 ? Topology::Lines : Topology::Triangles;
  return out;
}

}  // namespace

// --- worker pool ------------------------------------------------------------------------------
class Context::WorkerPool {
 public:
  explicit WorkerPool(int n) : size_(n) {
    for (int i = 1; i < n; ++i) threads_.emplace_back([this, i] { loop(i); });
  }
  ~WorkerPool() {
    {
      std::lock_guard lock(m_);
      stop_ = true;
      ++generation_;
    }
    cv_.notify_all();
    for (auto& t : threads_) t.join();
  }
  int size() const { return size_; }
  // Runs fn(i) for every worker i (0 on the calling thread) and waits for all, even when
  // one throws; then rethrows the first exception.
  void run(const std::function<void(int)>& fn) {
    error_ = nullptr;
    if (size_ == 1) {
      fn(0);
      return;
    }
    {
      std::lock_guard lock(m_);
      job_ = &fn;
      running_ = size_ - 1;
      ++generation_;
    }
    cv_.notify_all();
    std::exception_ptr mine;
    try {
      fn(0);
    } catch (...) {
      mine = std::current_exception();
    }
    std::unique_lock lock(m_);
    done_.wait(lock, [&] { return running_ == 0; });
    job_ = nullptr;
    if (mine) std::rethrow_exception(mine);
    if (error_) std::rethrow_exception(error_);
  }

 private:
  void loop(int index) {
    uint64_t seen = 0;
    for (;;) {
      const std::function<void(int)>* job;
      {
        std::unique_lock lock(m_);
        cv_.wait(lock, [&] { return generation_ != seen; });
        seen = generation_;
        if (stop_) return;
        job = job_;
      }
      std::exception_ptr e;
      try {
        (*job)(index);
      } catch (...) {
        e = std::current_exception();
      }
      {
        std::lock_guard lock(m_);
        if (e && !error_) error_ = e;
        if (--running_ == 0) done_.notify_one();
      }
    }
  }
  int size_;
  std::vector<std::thread> threads_;
  std::mutex m_;
  std::condition_variable cv_, done_;
  const std::function<void(int)>* job_ = nullptr;
  int running_ = 0;
  uint64_t generation_ = 0;
  bool stop_ = false;
  std::exception_ptr error_;
};

// --- the frame --------------------------------------------------------------------------------
struct Context::Frame {
  std::vector<std::unique_ptr<DrawRecord>> draws;
  // Records of finished draws, kept so that the next frame reuses their index storage
  // instead of allocating (and page-faulting) it again.
  std::vector<std::unique_ptr<DrawRecord>> spare;
  std::vector<std::unique_ptr<ClearPrim>> clears;
  std::vector<Command> commands;
  std::vector<Chunk> chunks;
  std::vector<Worker> workers;
  TargetView target;
  int tiles_x = 0, tiles_y = 0;
  uint64_t pending_prims = 0;

  void process_chunk(Worker& w, uint32_t chunk_index);
  void process_draw_chunk(Worker& w, uint32_t chunk_index, const Chunk& ch, const DrawRecord& d);
  // Bins a Prim into the tiles it touches: inline for one tile (most small triangles),
  // bin_tiles for more.
  void bin(Worker& w, uint32_t chunk, const DrawRecord* d, const Prim* p) {
    const int tx = p->minx >> kTileShift, ty = p->miny >> kTileShift;
    if (tx == p->maxx >> kTileShift && ty == p->maxy >> kTileShift)
      w.bins[size_t(ty) * tiles_x + tx].push_back({chunk, p, d});
    else
      bin_tiles(w, chunk, d, p);
  }
  void bin_tiles(Worker& w, uint32_t chunk, const DrawRecord* d, const Prim* p);
  void raster_tile(Worker& w, int tile);
};

void Context::Frame::bin_tiles(Worker& w, uint32_t chunk, const DrawRecord* d, const Prim* p) {
  const int tx0 = p->minx >> kTileShift, tx1 = p->maxx >> kTileShift;
  const int ty0 = p->miny >> kTileShift, ty1 = p->maxy >> kTileShift;
  for (int ty = ty0; ty <= ty1; ++ty) {
    for (int tx = tx0; tx <= tx1; ++tx) {
      if (p->kind == PrimKind::Triangle && (tx1 > tx0 || ty1 > ty0)) {
        // Trivial reject of tiles the bbox touches but the triangle misses.
        const int x0 = std::max(tx * kTileSize, p->minx), x1 = std::min(tx * kTileSize + kTileSize - 1, p->maxx);
        const int y0 = std::max(ty * kTileSize, p->miny), y1 = std::min(ty * kTileSize + kTileSize - 1, p->maxy);
        bool out = false;
        if (p->cover) {
          // Covered groups are 4x2 aligned and tiles are multiples of them: a tile is touched
          // when one of its groups is in the cover.
          const int gx0 = p->minx & ~3, gy0 = p->miny & ~1;
          out = true;
          for (int g = 0; g < 8 && out; ++g) {
            const int gx = gx0 + (g & 1) * 4, gy = gy0 + (g >> 1) * 2;
            out = !(((p->cover >> (8 * g)) & 0xFF) && (gx >> kTileShift) == tx && (gy >> kTileShift) == ty);
          }
        } else {
          for (const EdgeEq& e : std::span(p->edges(d->program->varyings), 3)) {
            const int64_t hi = e.c + std::max(e.a * x0, e.a * x1) + std::max(e.b * y0, e.b * y1);
            if (hi <= 0) { out = true; break; }
          }
        }
        if (out) continue;
      }
      w.bins[size_t(ty) * tiles_x + tx].push_back({chunk, p, d});
    }
  }
}

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
    if (d.indexed) std::memcpy(ids, d.elements + e0, total * sizeof(uint32_t));
    else for (size_t i = 0; i < total; ++i) ids[i] = d.first + uint32_t(e0 + i);
  } else {
    uint32_t e[3];
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

  // 2. Per vertex: clip code, and the window position of the vertices inside every plane.
  const ClipPlanes planes = make_clip_planes(d);
  w.codes.resize(nv);
  w.win.resize(nv);
  finish_vertices(d, planes, w.soa.data(), w.vars.data(), K, nv, w.codes.data(), w.win.data());

  // 3. Assembly, clipping, setup, binning.
  const PolygonMode mode_front = d.state.polygon_mode;
  const PolygonMode mode_back = d.state.polygon_mode_per_face ? d.state.polygon_mode_back : mode_front;
  const bool fill = mode_front == PolygonMode::Fill && mode_back == PolygonMode::Fill;
  Prim* out[2];
  const bool filled_triangles = ps == 3 && fill;
  // Read through locals in the loop: stores into Prims could alias the vectors' and the
  // DrawRecord's fields as far as the compiler knows, so it would load them again each time.
  const SetupConstants sc(d);
  const uint32_t* const slots = w.prim_slots.data();
  const unsigned* const codes = w.codes.data();
  const WinVert* const win = w.win.data();
  const float* const vars = w.vars.data();
  const bool offset_fill = d.state.offset_fill;
  uint64_t culled_count = 0;
  w.counters.primitives_in += nprims;
  for (uint32_t p = 0; p < nprims; ++p) {
    const uint32_t prim_id = ch.begin + p;
    const uint32_t* s = slots + size_t(p) * ps;
    if (filled_triangles && (codes[s[0]] | codes[s[1]] | codes[s[2]]) == 0) {
      // The common case: a filled triangle inside every plane, set up here without a call.
      bool culled = false;
      Prim* pr = setup_triangle_inline(d, sc, win[s[0]], win[s[1]], win[s[2]], vars + size_t(s[2]) * K, prim_id,
                                       Facing::FromArea, offset_fill, w.arena, w.counters, &culled);
      culled_count += culled;
      if (pr) bin(w, chunk_index, &d, pr);
      continue;
    }
    unsigned any_code = 0;
    for (int k = 0; k < ps; ++k) any_code |= w.codes[s[k]];
    if (any_code & kNotFinite) continue;  // NaN or Inf position: the primitive is dropped
    auto var_of = [&](uint32_t slot) { return &w.vars[size_t(slot) * K]; };

    if (ps == 1) {
      if (w.codes[s[0]]) continue;
      const int n = setup_point(d, w.win[s[0]], prim_id, true, 0.0f, w.arena, w.counters, out);
      for (int i = 0; i < n; ++i) bin(w, chunk_index, &d, out[i]);
      continue;
    }
    if (ps == 2) {
      const glm::vec4 &p0 = w.pos[s[0]], &p1 = w.pos[s[1]];
      const unsigned c0 = w.codes[s[0]], c1 = w.codes[s[1]];
      if (c0 & c1) continue;
      const float* flat_src = var_of(s[1]);
      WinVert a, b;
      if ((c0 | c1) == 0) {
        a = w.win[s[0]];
        b = w.win[s[1]];
      } else {
        float t0, t1;
        if (!clip_line(planes, c0 | c1, p0, p1, t0, t1)) continue;
        ++w.counters.primitives_clipped;
        ClipVert& ca = w.clip_a[0];
        ClipVert& cb = w.clip_a[1];
        ca.pos = p0 + (p1 - p0) * t0;
        cb.pos = p0 + (p1 - p0) * t1;
        const float *va = var_of(s[0]), *vb = var_of(s[1]);
        for (int k = 0; k < K; ++k) {
          ca.var[k] = va[k] + (vb[k] - va[k]) * t0;
          cb.var[k] = va[k] + (vb[k] - va[k]) * t1;
        }
        a = to_window(d, ca.pos, ca.var);
        b = to_window(d, cb.pos, cb.var);
      }
      const int n = setup_line(d, a, b, flat_src, prim_id, true, 0.0f, w.arena, w.counters, out);
      for (int i = 0; i < n; ++i) bin(w, chunk_index, &d, out[i]);
      continue;
    }

    // Triangles.
    const float* flat_src = var_of(s[2]);
    const unsigned c0 = w.codes[s[0]], c1 = w.codes[s[1]], c2 = w.codes[s[2]];
    if (c0 & c1 & c2) continue;
    WinVert wv[24];
    int nw;
    if ((c0 | c1 | c2) == 0) {
      wv[0] = w.win[s[0]];
      wv[1] = w.win[s[1]];
      wv[2] = w.win[s[2]];
      nw = 3;
    } else {
      ++w.counters.primitives_clipped;
      for (int k = 0; k < 3; ++k) {
        w.clip_a[k].pos = w.pos[s[k]];
        std::copy_n(var_of(s[k]), K, w.clip_a[k].var);
      }
      ClipVert* poly;
      nw = clip_polygon(planes, c0 | c1 | c2, w.clip_a, 3, w.clip_b, K, &poly);
      for (int i = 0; i < nw; ++i) wv[i] = to_window(d, poly[i].pos, poly[i].var);
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
    const bool front = (d.state.front_face == FrontFace::CCW) == (area > 0.0);
    const CullMode cm = d.state.cull;
    if (cm == CullMode::FrontAndBack || (cm == CullMode::Front && front) || (cm == CullMode::Back && !front)) {
      ++w.counters.primitives_culled;
      continue;
    }
    const PolygonMode mode = front ? mode_front : mode_back;
    if (mode == PolygonMode::Fill) {
      const Facing facing = front ? Facing::Front : Facing::Back;
      for (int i = 1; i + 1 < nw; ++i) {
        Prim* pr = setup_triangle(d, wv[0], wv[i], wv[i + 1], flat_src, prim_id, facing, d.state.offset_fill, w.arena,
                                  w.counters, nullptr);
        if (pr) bin(w, chunk_index, &d, pr);
      }
      continue;
    }
    const bool line = mode == PolygonMode::Line;
    const bool offset = line ? d.state.offset_line : d.state.offset_point;
    const float zoff = offset ? polygon_offset(d, wv[0], wv[1], wv[2]) : 0.0f;
    const int ef = d.state.edge_flag_varying;
    for (int i = 0; i < nw; ++i) {
      // A vertex made by clipping carries the flag interpolated from its edge's ends.
      if (ef >= 0 && ef < K && wv[i].var[ef] == 0.0f) continue;
      const int n = line ? setup_line(d, wv[i], wv[(i + 1) % nw], flat_src, prim_id, front, zoff, w.arena, w.counters, out)
                         : setup_point(d, wv[i], prim_id, front, zoff, w.arena, w.counters, out);
      for (int j = 0; j < n; ++j) bin(w, chunk_index, &d, out[j]);
    }
  }
  w.counters.primitives_culled += culled_count;
}

// Whether a clear rewrites every byte of the tile rectangle in every attachment, so the
// tile's old contents need not be read.
static bool clears_everything(const TargetView& t, const ClearPrim& c, int x0, int y0, int x1, int y1) {
  if (c.base.minx > x0 || c.base.miny > y0 || c.base.maxx < x1 - 1 || c.base.maxy < y1 - 1) return false;
  for (int i = 0; i < t.color_count; ++i)
    if (t.color[i].data && (!(c.color_mask_bits & (1u << i)) || c.write_mask[i] != 0xF)) return false;
  if (t.depth) {
    if (!c.clear_depth) return false;
    if (t.has_stencil && (!c.clear_stencil || c.stencil_write_mask != 0xFF)) return false;
  }
  return true;
}

// A pointer p such that p + y * row_bytes + x * bpp addresses (x, y) of a tile-local buffer
// whose first byte holds pixel (x0, y0).
static std::byte* tile_origin(std::byte* local, size_t row_bytes, size_t bpp, int x0, int y0) {
  return reinterpret_cast<std::byte*>(reinterpret_cast<uintptr_t>(local) - size_t(y0) * row_bytes - size_t(x0) * bpp);
}

// The most triangles handed to a program's raster() at once.
constexpr int kRasterRun = 32;

void Context::Frame::raster_tile(Worker& w, int tile) {
  const int tx = tile % tiles_x, ty = tile / tiles_x;
  const int x0 = tx * kTileSize, y0 = ty * kTileSize;
  const int x1 = std::min(x0 + kTileSize, target.width), y1 = std::min(y0 + kTileSize, target.height);
  const size_t nw = workers.size();
  size_t head[64] = {};
  // The next entry in submission order: the workers' lists merged by chunk number (each list
  // is already in chunk order; everything of one chunk in one list runs before the next chunk).
  int cur = -1;
  uint32_t cur_chunk = 0;
  auto next = [&]() -> const BinEntry* {
    if (cur >= 0) {
      const auto& list = workers[size_t(cur)].bins[size_t(tile)];
      if (head[cur] < list.size() && list[head[cur]].chunk == cur_chunk) return &list[head[cur]++];
    }
    cur = -1;
    uint32_t best_chunk = UINT32_MAX;
    for (size_t i = 0; i < nw; ++i) {
      const auto& list = workers[i].bins[size_t(tile)];
      if (head[i] < list.size() && list[head[i]].chunk < best_chunk) {
        best_chunk = list[head[i]].chunk;
        cur = int(i);
      }
    }
    if (cur < 0) return nullptr;
    cur_chunk = best_chunk;
    return &workers[size_t(cur)].bins[size_t(tile)][head[cur]++];
  };
  const BinEntry* e = next();
  if (!e) return;  // nothing touches this tile
  const BinEntry* second = next();
  auto run_clear = [&](const TargetView& v, const BinEntry& entry, bool stream) {
    const auto* c = reinterpret_cast<const ClearPrim*>(entry.prim);
    const int cx0 = std::max(x0, c->base.minx), cx1 = std::min(x1, c->base.maxx + 1);
    const int cy0 = std::max(y0, c->base.miny), cy1 = std::min(y1, c->base.maxy + 1);
    if (cx0 < cx1 && cy0 < cy1) clear_rect(v, *c, cx0, cy0, cx1, cy1, stream);
  };
  // A tile whose first command clears every attachment whole: its old contents are not read,
  // and a frame that starts that way is taken to be written once and not read back by the
  // next one, so its lines go to the target with non-temporal stores (a frame that keeps
  // something, the stencil say, reads the target back next time: the lines stay cached).
  const bool fresh = e->prim->kind == PrimKind::Clear &&
                     clears_everything(target, *reinterpret_cast<const ClearPrim*>(e->prim), x0, y0, x1, y1);
  if (!second && e->prim->kind == PrimKind::Clear) {
    run_clear(target, *e, fresh);  // a tile that is only cleared needs no local copy
    return;
  }

  // Tile-local copies of the attachments (one colour attachment at most, and depth): 64 rows
  // of 64 pixels packed together stay in the L1 cache, where rows of the whole image would
  // evict each other. They are loaded unless the first command clears the whole tile, and
  // stored back at the end.
  TargetView view = target;
  const bool local = target.color_count <= 1 && (target.color[0].data || target.depth);
  const int tw = x1 - x0;
  size_t color_bpp = 0;
  if (local) {
    if (target.color[0].data) {
      color_bpp = format_info(target.color[0].format).bytes;
      const size_t rb = size_t(kTileSize) * color_bpp;
      w.tile_color.resize(rb * kTileSize);
      view.color[0].data = tile_origin(w.tile_color.data(), rb, color_bpp, x0, y0);
      view.color[0].row_bytes = rb;
      if (!fresh)
        copy_rows(w.tile_color.data(), rb, target.color[0].data + size_t(y0) * target.color[0].row_bytes + size_t(x0) * color_bpp,
                  target.color[0].row_bytes, size_t(tw) * color_bpp, y1 - y0);
    }
    if (target.depth) {
      const size_t rb = size_t(kTileSize) * 4;
      w.tile_depth.resize(rb * kTileSize);
      view.depth = tile_origin(w.tile_depth.data(), rb, 4, x0, y0);
      view.depth_row_bytes = rb;
      if (!fresh)
        copy_rows(w.tile_depth.data(), rb, target.depth + size_t(y0) * target.depth_row_bytes + size_t(x0) * 4,
                  target.depth_row_bytes, size_t(tw) * 4, y1 - y0);
    }
  }

  // Consecutive triangles of one draw go to its program together (which pairs their 4x2
  // groups into sixteen-lane shading).
  const Prim* run[kRasterRun];
  int run_n = 0;
  const DrawRecord* run_draw = nullptr;
  auto flush_run = [&] {
    if (run_n) run_draw->program->raster(*run_draw, view, run, run_n, x0, y0, x1, y1, w.counters);
    run_n = 0;
  };
  for (; e; e = second ? std::exchange(second, nullptr) : next()) {
    if (!e->draw) {  // a clear (reading the Prim's kind here would wait on memory)
      flush_run();
      run_clear(view, *e, false);
      continue;
    }
    if (e->draw != run_draw || run_n == kRasterRun) {
      flush_run();
      run_draw = e->draw;
    }
    run[run_n++] = e->prim;  // not touched here: raster() prefetches the run's Prims ahead
  }
  flush_run();

  if (local) {
    if (target.color[0].data)
      copy_rows(target.color[0].data + size_t(y0) * target.color[0].row_bytes + size_t(x0) * color_bpp,
                target.color[0].row_bytes, w.tile_color.data(), size_t(kTileSize) * color_bpp, size_t(tw) * color_bpp, y1 - y0,
                fresh);
    if (target.depth)
      copy_rows(target.depth + size_t(y0) * target.depth_row_bytes + size_t(x0) * 4, target.depth_row_bytes,
                w.tile_depth.data(), size_t(kTileSize) * 4, size_t(tw) * 4, y1 - y0, fresh);
  }
}

// --- Context ----------------------------------------------------------------------------------
Context::Context(int threads) : frame_(std::make_unique<Frame>()) { set_threads(threads); }

Context::~Context() {
  try {
    flush();
  } catch (...) {
  }
}

int Context::threads() const { return pool_ ? pool_->size() : 1; }

void Context::set_threads(int threads) {
  if (threads < 0 || threads > 64) throw Error("Context: thread count " + std::to_string(threads) + " is outside 0..64");
  flush();
  if (threads == 0) threads = int(std::max(1u, std::min(64u, std::thread::hardware_concurrency())));
  pool_.reset();
  pool_ = std::make_unique<WorkerPool>(threads);
}

void Context::bind_framebuffer(Framebuffer* fb) {
  if (fb) {
    const std::string why = fb->incomplete_reason();
    if (!why.empty()) throw Error("bind_framebuffer: incomplete framebuffer: " + why);
    if (fb->width() > kMaxViewportSize || fb->height() > kMaxViewportSize)
      throw Error("bind_framebuffer: " + std::to_string(fb->width()) + "x" + std::to_string(fb->height()) +
                  " is larger than " + std::to_string(kMaxViewportSize) + " pixels a side");
  }
  flush();
  fb_ = fb;
}

TargetView Context::make_target() const {
  // The framebuffer's fields are public: check it again whenever a frame starts using it.
  const std::string why = fb_->incomplete_reason();
  if (!why.empty()) throw Error("framebuffer became incomplete after it was bound: " + why);
  TargetView t;
  t.width = fb_->width();
  t.height = fb_->height();
  for (int i = 0; i < kMaxColorAttachments; ++i) {
    const Attachment& a = fb_->color[i];
    if (!a.texture) continue;
    // Attachments are written by the raster phase; the texture is not otherwise changed
    // while the frame runs (any change flushes first).
    Level& lv = const_cast<Level&>(a.texture->level(a.level));
    t.color[i] = {lv.data.data(), lv.row_bytes(), a.texture->format()};
    t.color_count = i + 1;
  }
  if (fb_->depth.texture) {
    Level& lv = const_cast<Level&>(fb_->depth.texture->level(fb_->depth.level));
    t.depth = lv.data.data();
    t.depth_row_bytes = lv.row_bytes();
    t.depth_format = fb_->depth.texture->format();
    t.has_stencil = t.depth_format == Format::Depth24Stencil8;
  }
  return t;
}

bool Context::has_pending() const { return !frame_->commands.empty(); }

static Rect render_area(const RenderState& s, int width, int height) {
  Rect r{0, 0, width, height};
  if (s.scissor_test) {
    const int x0 = std::max(r.x, s.scissor.x), y0 = std::max(r.y, s.scissor.y);
    const int x1 = std::min<int64_t>(int64_t(r.x) + r.width, int64_t(s.scissor.x) + std::max(0, s.scissor.width));
    const int y1 = std::min<int64_t>(int64_t(r.y) + r.height, int64_t(s.scissor.y) + std::max(0, s.scissor.height));
    r = {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
  }
  return r;
}

void Context::clear(const ClearValues& v, const RenderState& state) {
  if (!fb_) throw Error("clear: no framebuffer bound");
  if (!std::isfinite(v.depth)) throw Error("clear: depth value is not finite");
  if (frame_->commands.empty()) frame_->target = make_target();
  const Rect r = render_area(state, frame_->target.width, frame_->target.height);
  if (r.width <= 0 || r.height <= 0) return;
  auto c = std::make_unique<ClearPrim>();
  c->base.kind = PrimKind::Clear;
  c->base.minx = r.x;
  c->base.miny = r.y;
  c->base.maxx = r.x + r.width - 1;
  c->base.maxy = r.y + r.height - 1;
  c->color_mask_bits = v.clear_color ? v.color_attachments : 0;
  for (int i = 0; i < kMaxColorAttachments; ++i) {
    c->color[i] = v.per_attachment ? v.attachment_colors[i] : v.color;
    c->write_mask[i] = state.blend[i].write_mask;
  }
  c->clear_depth = v.clear_depth && state.depth_write;
  c->depth = v.depth;
  c->clear_stencil = v.clear_stencil;
  c->stencil = v.stencil;
  c->stencil_write_mask = state.stencil_front.write_mask;
  frame_->commands.push_back({true, uint32_t(frame_->clears.size())});
  frame_->clears.push_back(std::move(c));
}

void Context::submit(std::unique_ptr<ProgramBase> program, const VertexLayout& layout,
                     const RenderState& state, const DrawCall& call, uint32_t required_attribs) {
  note_draw_submitted();  // from now on earlier resources may be read by queued work
  if (!fb_) throw Error("draw: no framebuffer bound");
  if (unsigned(call.topology) > unsigned(Topology::TriangleFan)) throw Error("draw: invalid topology " + std::to_string(int(call.topology)));
  if (unsigned(state.cull) > unsigned(CullMode::FrontAndBack) || unsigned(state.front_face) > 1 ||
      unsigned(state.polygon_mode) > 2 || unsigned(state.polygon_mode_back) > 2 || unsigned(state.depth_func) > 7)
    throw Error("draw: invalid enum in render state");
  if (!(state.line_width > 0.0f) || !(state.point_size > 0.0f) || state.line_width > 1024.0f || state.point_size > 8192.0f)
    throw Error("draw: line width " + std::to_string(state.line_width) + " / point size " +
                std::to_string(state.point_size) + " out of range");
  if (!std::isfinite(state.depth_near) || !std::isfinite(state.depth_far) ||
      !std::isfinite(state.offset_factor) || !std::isfinite(state.offset_units))
    throw Error("draw: depth range and polygon offset must be finite");
  if (call.count == 0 || call.instance_count == 0) return;
  if (uint64_t(call.base_instance) + call.instance_count > UINT32_MAX) throw Error("draw: instance range overflows");
  for (int i = 0; i < kMaxClipPlanes; ++i)
    if ((state.clip_plane_enable >> i) & 1)
      for (int k = 0; k < 4; ++k)
        if (!std::isfinite(state.clip_planes[i][k]) || std::fabs(state.clip_planes[i][k]) > 1e18f)
          throw Error("draw: clip plane " + std::to_string(i) + " is not finite or too large");

  std::unique_ptr<DrawRecord> d;
  if (frame_->spare.empty()) {
    d = std::make_unique<DrawRecord>();
  } else {
    d = std::move(frame_->spare.back());
    frame_->spare.pop_back();
    std::vector<uint32_t> storage = std::move(d->indices);
    *d = DrawRecord{};
    storage.clear();
    d->indices = std::move(storage);
  }
  d->program = std::move(program);
  d->state = state;
  d->layout = layout;
  d->topology = call.topology;
  d->instance_count = call.instance_count;
  d->base_instance = call.base_instance;
  uint32_t max_id = 0;
  if (call.index_buffer) {
    const size_t isz = call.index_type == IndexType::U8 ? 1 : call.index_type == IndexType::U16 ? 2 : 4;
    if (unsigned(call.index_type) > 2) throw Error("draw: invalid index type");
    if (call.index_offset % isz) throw Error("draw: index offset " + std::to_string(call.index_offset) + " is not aligned to the index size");
    // Overflow-safe: the indices [first, first + count) must lie in the buffer after the offset.
    const size_t size = call.index_buffer->size();
    const uint64_t available = call.index_offset <= size ? (size - call.index_offset) / isz : 0;
    if (call.index_offset > size || uint64_t(call.first) + call.count > available)
      throw Error("draw: indices [" + std::to_string(call.first) + ", " + std::to_string(uint64_t(call.first) + call.count) +
                  ") at byte offset " + std::to_string(call.index_offset) + " are past the end of an index buffer of " +
                  std::to_string(size) + " bytes");
    const uint64_t begin = uint64_t(call.index_offset) + uint64_t(call.first) * isz;
    const std::byte* src = call.index_buffer->data() + begin;
    const uint32_t restart = isz == 1 ? 0xFFu : isz == 2 ? 0xFFFFu : 0xFFFFFFFFu;
    if (isz == 4 && !state.primitive_restart && call.base_vertex == 0) {
      // The common case: 32-bit indices read where they are, checked against their maximum.
      const uint32_t m = call.index_buffer->max_u32(begin, call.count);
      if (m > uint32_t(INT32_MAX)) {
        for (uint32_t at = 0; at < call.count; ++at) {
          uint32_t id;
          std::memcpy(&id, src + size_t(at) * 4, 4);
          if (id > uint32_t(INT32_MAX))
            throw Error("draw: index " + std::to_string(id) + " at position " + std::to_string(at) +
                        " plus base vertex 0 is out of range");
        }
      }
      max_id = m;
      d->elements = reinterpret_cast<const uint32_t*>(src);  // read with memcpy only
      d->count = call.count;
    }
    std::vector<uint32_t> raw(d->elements ? 0 : call.count);
    for (uint32_t i = 0; i < uint32_t(raw.size()); ++i) {
      uint32_t v = 0;
      std::memcpy(&v, src + size_t(i) * isz, isz);
      raw[i] = v;
    }
    if (state.primitive_restart) raw = expand_restart(d->topology, raw, restart);
    if (!raw.empty()) d->indices.resize(raw.size());
    for (size_t i = 0; i < raw.size(); ++i) {
      const int64_t id = int64_t(raw[i]) + call.base_vertex;
      if (id < 0 || id > INT32_MAX)
        throw Error("draw: index " + std::to_string(raw[i]) + " at position " + std::to_string(i) +
                    " plus base vertex " + std::to_string(call.base_vertex) + " is out of range");
      d->indices[i] = uint32_t(id);
      max_id = std::max(max_id, uint32_t(id));
    }
    d->indexed = true;
    if (!d->elements) {
      d->elements = d->indices.data();
      d->count = uint32_t(d->indices.size());
    }
  } else {
    if (uint64_t(call.first) + call.count > uint64_t(INT32_MAX)) throw Error("draw: vertex range overflows");
    d->first = call.first;
    d->count = call.count;
    max_id = call.first + call.count - 1;
  }
  validate_vertex_range(layout, max_id, call.base_instance + call.instance_count, required_attribs);
  d->prim_count = prim_count(d->topology, d->count);
  if (d->prim_count == 0) return;
  // One draw runs as one frame, so its size bounds the frame's memory: at most 2^13 chunks
  // of 1024 primitives (about 8 M primitives, instances included). Running huge draws in
  // windows is still to do.
  const uint64_t chunks = uint64_t(d->instance_count) * ((d->prim_count + kChunkPrims - 1) / kChunkPrims);
  if (chunks > (uint64_t(1) << 13))
    throw Error("draw: " + std::to_string(uint64_t(d->prim_count) * d->instance_count) +
                " primitives (instances included) in one draw is more than Tessel runs at once; split the draw");

  if (frame_->commands.empty()) frame_->target = make_target();
  d->target = frame_->target;
  const int W = d->target.width, H = d->target.height;
  Rect vp = state.viewport;
  if (vp.width <= 0 || vp.height <= 0) vp = {0, 0, W, H};
  vp.width = std::min(vp.width, kMaxViewportSize);
  vp.height = std::min(vp.height, kMaxViewportSize);
  vp.x = std::clamp(vp.x, -kMaxViewportSize, kMaxViewportSize);
  vp.y = std::clamp(vp.y, -kMaxViewportSize, kMaxViewportSize);
  // GL 4.6 §13.8.1: x_w = (x_ndc + 1) w/2 + x, as scale and offset.
  d->vp_scale[0] = float(vp.width) * 0.5f;
  d->vp_scale[1] = float(vp.height) * 0.5f;
  d->vp_offset[0] = float(vp.x) + float(vp.width) * 0.5f;
  d->vp_offset[1] = float(vp.y) + float(vp.height) * 0.5f;
  const float n = std::clamp(state.depth_near, 0.0f, 1.0f), f = std::clamp(state.depth_far, 0.0f, 1.0f);
  d->vp_scale[2] = (f - n) * 0.5f;
  d->vp_offset[2] = (n + f) * 0.5f;
  d->depth_min = std::min(n, f);
  d->depth_max = std::max(n, f);
  // |x_w| stays under the guard band: |x_ndc * s + o| <= G for |x_ndc| <= (G - |o|) / s.
  d->guard_x = (kGuardBand - std::fabs(d->vp_offset[0])) / d->vp_scale[0];
  d->guard_y = (kGuardBand - std::fabs(d->vp_offset[1])) / d->vp_scale[1];
  // Primitives are clipped against the guard band, not the view volume's sides, so the
  // viewport rectangle bounds the fragments as the sides would (GL 4.6 §13.7); llvmpipe,
  // which also uses a guard band, does the same.
  Rect area = render_area(state, W, H);
  {
    const int x0 = std::max(area.x, vp.x), y0 = std::max(area.y, vp.y);
    const int x1 = std::min<int64_t>(int64_t(area.x) + area.width, int64_t(vp.x) + vp.width);
    const int y1 = std::min<int64_t>(int64_t(area.y) + area.height, int64_t(vp.y) + vp.height);
    area = {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
  }
  d->area_x0 = area.x;
  d->area_y0 = area.y;
  d->area_x1 = area.x + area.width;
  d->area_y1 = area.y + area.height;
  if (area.width <= 0 || area.height <= 0) return;
  d->depth_float = d->target.depth && d->target.depth_format == Format::Depth32F;
  d->depth_resolution = 1.0f / 16777216.0f;  // 2^-24 for 24-bit depth
  d->early_depth = !d->program->discards && !d->program->writes_depth;
  d->fast_depth = d->target.depth && d->state.depth_test && !(d->state.stencil_test && d->target.has_stencil);
  d->fast_color = d->target.color_count == 1 && d->target.color[0].data && d->target.color[0].format == Format::RGBA8 &&
                  !d->state.blend[0].enabled && d->state.blend[0].write_mask == 0xF && d->program->outputs >= 1;

  frame_->pending_prims += uint64_t(d->prim_count) * d->instance_count;
  frame_->commands.push_back({false, uint32_t(frame_->draws.size())});
  frame_->draws.push_back(std::move(d));
  if (frame_->pending_prims > kMaxPendingPrims) flush();
}

void Context::flush() {
  Frame& fr = *frame_;
  if (fr.commands.empty()) return;
  // 1. Chunks, numbered in submission order.
  fr.chunks.clear();
  for (uint32_t c = 0; c < fr.commands.size(); ++c) {
    const Command& cmd = fr.commands[c];
    if (cmd.clear) {
      fr.chunks.push_back({c, 0, 0, 1});
      continue;
    }
    const DrawRecord& d = *fr.draws[cmd.index];
    for (uint32_t inst = 0; inst < d.instance_count; ++inst)
      for (uint32_t b = 0; b < d.prim_count; b += kChunkPrims)
        fr.chunks.push_back({c, d.base_instance + inst, b, std::min(d.prim_count, b + kChunkPrims)});
  }
  fr.tiles_x = (fr.target.width + kTileSize - 1) / kTileSize;
  fr.tiles_y = (fr.target.height + kTileSize - 1) / kTileSize;
  const int ntiles = fr.tiles_x * fr.tiles_y;
  const int nthreads = pool_->size();
  fr.workers.resize(size_t(nthreads));
  for (Worker& w : fr.workers) {
    w.arena.reset();
    w.bins.resize(size_t(ntiles));
    for (auto& b : w.bins) b.clear();
    w.counters = {};
  }

  // Whatever happens below, the queued work is consumed: a failed frame is dropped whole.
  struct Drop {
    Frame& fr;
    ~Drop() {
      fr.commands.clear();
      for (auto& d : fr.draws) {
        if (fr.spare.size() >= 1024) break;
        d->program.reset();
        fr.spare.push_back(std::move(d));
      }
      fr.draws.clear();
      fr.clears.clear();
      fr.pending_prims = 0;
    }
  } drop{fr};
  // 2. Geometry phase.
  std::atomic<uint32_t> next_chunk{0};
  const uint32_t nchunks = uint32_t(fr.chunks.size());
  pool_->run([&](int wi) {
    Worker& w = fr.workers[size_t(wi)];
    for (uint32_t c; (c = next_chunk.fetch_add(1, std::memory_order_relaxed)) < nchunks;) fr.process_chunk(w, c);
  });
  // 3. Raster phase.
  std::atomic<int> next_tile{0};
  pool_->run([&](int wi) {
    Worker& w = fr.workers[size_t(wi)];
    for (int t; (t = next_tile.fetch_add(1, std::memory_order_relaxed)) < ntiles;) fr.raster_tile(w, t);
  });

  for (const Worker& w : fr.workers) {
    const Counters& c = w.counters;
    stats_.vertices_shaded += c.vertices_shaded;
    stats_.primitives_in += c.primitives_in;
    stats_.primitives_clipped += c.primitives_clipped;
    stats_.primitives_culled += c.primitives_culled;
    stats_.triangles_setup += c.triangles_setup;
    stats_.fragments_shaded += c.fragments_shaded;
    stats_.fragments_written += c.fragments_written;
    stats_.fragments_rejected += c.fragments_rejected;
  }
}

}  // namespace tessel::gpu
