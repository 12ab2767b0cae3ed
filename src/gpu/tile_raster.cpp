// The raster phase for one tile: the workers' bins merged by chunk number (so primitives run
// in submission order whatever the thread count), the attachments copied into tile-local
// buffers that stay in L1, runs of one draw's triangles handed to its program together.
#include <algorithm>
#include <cstring>
#include <utility>

#include "frame.hpp"

namespace tessel::gpu {
using namespace detail;

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
  return reinterpret_cast<std::byte*>(reinterpret_cast<uintptr_t>(local) - size_t(y0) * row_bytes -
                                      size_t(x0) * bpp);
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
        copy_rows(w.tile_color.data(), rb,
                  target.color[0].data + size_t(y0) * target.color[0].row_bytes + size_t(x0) * color_bpp,
                  target.color[0].row_bytes, size_t(tw) * color_bpp, y1 - y0);
    }
    if (target.depth) {
      const size_t rb = size_t(kTileSize) * 4;
      w.tile_depth.resize(rb * kTileSize);
      view.depth = tile_origin(w.tile_depth.data(), rb, 4, x0, y0);
      view.depth_row_bytes = rb;
      if (!fresh)
        copy_rows(w.tile_depth.data(), rb,
                  target.depth + size_t(y0) * target.depth_row_bytes + size_t(x0) * 4, target.depth_row_bytes,
                  size_t(tw) * 4, y1 - y0);
    }
  }

  // Consecutive triangles of one draw go to its program together (which pairs their 4x2
  // groups into sixteen-lane shading).
  const Prim* run[kRasterRun];
  int run_n = 0;
  const DrawRecord* run_draw = nullptr;
  auto flush_run = [&] {
    if (run_n) {
      if (run_draw->state.point_smooth || run_draw->state.line_smooth)
        run_draw->program->raster_smooth(*run_draw, view, run, run_n, x0, y0, x1, y1, w.counters);
      else
        run_draw->program->raster(*run_draw, view, run, run_n, x0, y0, x1, y1, w.counters);
    }
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
                target.color[0].row_bytes, w.tile_color.data(), size_t(kTileSize) * color_bpp,
                size_t(tw) * color_bpp, y1 - y0, fresh);
    if (target.depth)
      copy_rows(target.depth + size_t(y0) * target.depth_row_bytes + size_t(x0) * 4, target.depth_row_bytes,
                w.tile_depth.data(), size_t(kTileSize) * 4, size_t(tw) * 4, y1 - y0, fresh);
  }
}
}  // namespace tessel::gpu
