// Binning: a primitive goes into the list of every 64x64 tile it touches (Frame::bin, in
// frame.hpp, takes the one-tile case inline). Each worker has its own lists, tagged with the
// chunk number, so the raster phase can merge them in submission order.
#include <algorithm>
#include <span>

#include "frame.hpp"

namespace tessel::gpu {
using namespace detail;

void Context::Frame::bin_tiles(Worker& w, uint32_t chunk, const DrawRecord* d, const Prim* p) {
  const int tx0 = p->minx >> kTileShift, tx1 = p->maxx >> kTileShift;
  const int ty0 = p->miny >> kTileShift, ty1 = p->maxy >> kTileShift;
  for (int ty = ty0; ty <= ty1; ++ty) {
    for (int tx = tx0; tx <= tx1; ++tx) {
      if (p->kind != PrimKind::Clear && (tx1 > tx0 || ty1 > ty0)) {
        // Trivial reject of tiles the bbox touches but the triangle misses.
        const int x0 = std::max(tx * kTileSize, p->minx),
                  x1 = std::min(tx * kTileSize + kTileSize - 1, p->maxx);
        const int y0 = std::max(ty * kTileSize, p->miny),
                  y1 = std::min(ty * kTileSize + kTileSize - 1, p->maxy);
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
            if (hi <= 0) {
              out = true;
              break;
            }
          }
        }
        if (out) continue;
      }
      w.bins[size_t(ty) * tiles_x + tx].push_back({chunk, p, d});
    }
  }
}
}  // namespace tessel::gpu
