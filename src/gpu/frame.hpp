// Private: the state of a frame that the files of the frame share.
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
//
// The stages, one a file (as llvmpipe's lp_setup / lp_scene / lp_rast):
//   submit.cpp       submit() and clear(): validation, index reading, primitive restart
//   geometry.cpp     the geometry loop: vertex cache, shading, clipping, setup, binning
//   binning.cpp      a primitive into the tiles it touches
//   tile_raster.cpp  one tile: the merged bins in submission order, tile-local attachments
//   worker_pool.cpp  the threads that run the two phases
//   frame.cpp        flush(): chunks, the two phases, the counters; the Context's set-up
#pragma once

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "stages.hpp"
#include "tessel/gpu/context.hpp"
#include "tessel/gpu/runtime_shader.hpp"

namespace tessel::gpu {
namespace detail {

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
  // A geometry stage's call and what it emitted (as pos/vars/prim_slots are for vertices).
  std::unique_ptr<GeometryLanes> gs_lanes;
  std::vector<float> gs_out;
  std::vector<uint32_t> gs_start, gs_slots, gs_prim_ids;
  std::vector<glm::vec4> gs_pos;
  std::vector<float> gs_vars, gs_soa;
  // Tile-local copies of the colour and depth attachments during the raster phase.
  std::vector<std::byte> tile_color, tile_depth;
  ClipVert clip_a[24], clip_b[24];
};

// --- primitive assembly -----------------------------------------------------------------------
inline uint32_t prim_count(Topology t, uint32_t n) {
  switch (t) {
    case Topology::Points: return n;
    case Topology::Lines: return n / 2;
    case Topology::LineStrip: return n >= 2 ? n - 1 : 0;
    case Topology::LineLoop: return n >= 2 ? n : 0;
    case Topology::Triangles: return n / 3;
    case Topology::TriangleStrip:
    case Topology::TriangleFan: return n >= 3 ? n - 2 : 0;
    case Topology::LinesAdjacency: return n / 4;
    case Topology::LineStripAdjacency: return n >= 4 ? n - 3 : 0;
    case Topology::TrianglesAdjacency: return n / 6;
    case Topology::TriangleStripAdjacency: return n >= 6 ? (n - 4) / 2 : 0;
  }
  return 0;
}

inline int prim_size(Topology t) {
  switch (t) {
    case Topology::Points: return 1;
    case Topology::Lines:
    case Topology::LineStrip:
    case Topology::LineLoop: return 2;
    case Topology::LinesAdjacency:
    case Topology::LineStripAdjacency: return 4;
    case Topology::TrianglesAdjacency:
    case Topology::TriangleStripAdjacency: return 6;
    default: return 3;
  }
}

inline bool is_adjacency(Topology t) { return t >= Topology::LinesAdjacency; }

// Elements of primitive p, the provoking vertex last (GL 4.6 §10.1 and Table 13.2).
inline void prim_elements(Topology t, uint32_t p, uint32_t n, uint32_t* e) {
  switch (t) {
    case Topology::Points: e[0] = p; break;
    case Topology::Lines:
      e[0] = 2 * p;
      e[1] = 2 * p + 1;
      break;
    case Topology::LineStrip:
      e[0] = p;
      e[1] = p + 1;
      break;
    case Topology::LineLoop:
      e[0] = p;
      e[1] = (p + 1) % n;
      break;
    case Topology::Triangles:
      e[0] = 3 * p;
      e[1] = 3 * p + 1;
      e[2] = 3 * p + 2;
      break;
    case Topology::TriangleStrip:
      // Odd triangles swap their first two vertices to keep the winding.
      if (p & 1) {
        e[0] = p + 1;
        e[1] = p;
      } else {
        e[0] = p;
        e[1] = p + 1;
      }
      e[2] = p + 2;
      break;
    case Topology::TriangleFan:
      e[0] = 0;
      e[1] = p + 1;
      e[2] = p + 2;
      break;
    // With adjacency, in the geometry stage's order (gl_in[0..3] or [0..5]; GL 3.3 §2.6.1).
    case Topology::LinesAdjacency:
    case Topology::TrianglesAdjacency: {
      const uint32_t size = uint32_t(prim_size(t));
      for (uint32_t k = 0; k < size; ++k) e[k] = size * p + k;
      break;
    }
    case Topology::LineStripAdjacency:
      for (uint32_t k = 0; k < 4; ++k) e[k] = p + k;
      break;
    case Topology::TriangleStripAdjacency: {
      // GL 3.3 Table 2.4: triangle p's vertices are 2p, 2p + 2, 2p + 4 (the first two swapped
      // when p is odd), each followed by the vertex across the edge to the next; the ends of
      // the strip have no neighbour triangle and take the strip's own odd vertices.
      const uint32_t last = n >= 6 ? (n - 4) / 2 - 1 : 0;
      const uint32_t b = 2 * p;
      const bool odd = p & 1;
      e[0] = odd ? b + 2 : b;
      e[2] = odd ? b : b + 2;
      e[4] = b + 4;
      e[1] = p == 0 ? 1 : b - 2;
      e[3] = p == last ? (odd ? b + 3 : b + 5) : (odd ? b + 3 : b + 6);
      e[5] = p == last ? (odd ? b + 5 : b + 3) : (odd ? b + 6 : b + 3);
      break;
    }
  }
}

// Which of prim_elements' elements of primitive p is its provoking vertex (GL 3.3 Table
// 2.12): the last one, or with the first-vertex convention the first in GL's numbering,
// which for an odd strip triangle (listed with its first two swapped) and for a fan's
// triangle (whose vertex 0 is shared) is element 1.
inline int provoking_element(Topology t, uint32_t p, bool first) {
  if (is_adjacency(t)) return 0;  // only drawn through a geometry stage, which decides
  if (!first) return prim_size(t) - 1;
  if (t == Topology::TriangleFan) return 1;
  if (t == Topology::TriangleStrip) return int(p & 1);
  return 0;
}

// Expands a strip/fan/loop/list with primitive restart into an independent list (t becomes
// the list topology). Each primitive keeps its winding and its provoking vertex where
// provoking_element finds it in the list (with provoking_first, triangles are rotated).
std::vector<uint32_t> expand_restart(Topology& t, const std::vector<uint32_t>& idx, uint32_t restart,
                                     bool provoking_first);
// A topology with adjacency drawn without a geometry stage: the elements it draws, and t
// becomes lines, a line strip, triangles or a triangle strip (GL 3.3 §2.6.1).
std::vector<uint32_t> drop_adjacency(Topology& t, const std::vector<uint32_t>& idx);

// The list topology of what a geometry stage emitting `out` (Points, LineStrip or
// TriangleStrip) gives once its strips are cut.
inline Topology emitted_list(Topology out) {
  return out == Topology::TriangleStrip ? Topology::Triangles
         : out == Topology::LineStrip   ? Topology::Lines
                                        : Topology::Points;
}

// The list topology of a primitive of `size` vertices (1, 2, 3, 4 or 6).
inline Topology list_topology(int size) {
  switch (size) {
    case 1: return Topology::Points;
    case 2: return Topology::Lines;
    case 4: return Topology::LinesAdjacency;
    case 6: return Topology::TrianglesAdjacency;
    default: return Topology::Triangles;
  }
}

}  // namespace detail

// --- worker pool ------------------------------------------------------------------------------
class Context::WorkerPool {
 public:
  explicit WorkerPool(int n);
  ~WorkerPool();
  int size() const { return size_; }
  // Runs fn(i) for every worker i (0 on the calling thread) and waits for all, even when
  // one throws; then rethrows the first exception.
  void run(const std::function<void(int)>& fn);

 private:
  void loop(int index);
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
using namespace detail;
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
  void run_geometry(Worker& w, const Chunk& ch, const DrawRecord& d, uint32_t nprims);
  void capture(uint32_t chunk_index, const DrawRecord& d, Topology topo, uint32_t nprims,
               const uint32_t* slots, const glm::vec4* pos, const float* vars, uint32_t first_prim);
  // Transform feedback's words of each chunk (empty for the chunks of draws without it).
  std::vector<std::vector<uint32_t>> captured;
  void assemble(Worker& w, uint32_t chunk_index, const DrawRecord& d, Topology topo, uint32_t nprims,
                const uint32_t* slots, size_t nv, const glm::vec4* pos, const float* vars, const float* soa,
                const uint32_t* prim_ids, uint32_t first_prim);
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

}  // namespace tessel::gpu
