// A frame, top to bottom: how queued draws become pixels (frame.hpp lists the files of each
// stage). This file: the Context's set-up and flush(), which cuts the queued commands into
// chunks and runs the geometry and raster phases on the worker pool.
#include <algorithm>
#include <atomic>
#include <cstring>
#include <string>
#include <thread>

#include "frame.hpp"

namespace tessel::gpu {
using namespace detail;

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
  if (threads < 0 || threads > 64)
    throw Error("Context: thread count " + std::to_string(threads) + " is outside 0..64");
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
    if (!a) continue;
    t.color[i] = {a.data(), a.row_bytes(), a.format()};
    t.color_count = i + 1;
  }
  if (fb_->depth) {
    t.depth = fb_->depth.data();
    t.depth_row_bytes = fb_->depth.row_bytes();
    t.depth_format = fb_->depth.format();
    t.has_stencil = t.depth_format == Format::Depth24Stencil8;
  }
  return t;
}

bool Context::has_pending() const { return !frame_->commands.empty(); }

namespace {

// A draw's transform feedback: what its chunks captured, written in chunk order while every
// buffer has room for the whole primitive (GL 3.3 §2.15.2). Returns the primitives written.
uint64_t write_capture(Capture& cap, std::vector<uint32_t>* chunks, size_t nchunks) {
  const size_t verts = size_t(prim_size(cap.mode));
  size_t per_vertex = 0;
  for (const CaptureBuffer& b : cap.buffers) per_vertex += b.words.size();
  std::byte* base[kMaxCaptureBuffers] = {};
  size_t end[kMaxCaptureBuffers] = {};
  for (size_t i = 0; i < cap.buffers.size(); ++i) {
    CaptureBuffer& b = cap.buffers[i];
    base[i] = b.buffer->writable();  // the buffer's readers queued elsewhere run first
    end[i] = std::min(b.end, b.buffer->size());
  }
  uint64_t written = 0;
  for (size_t c = 0; c < nchunks; ++c) {
    const uint32_t* src = chunks[c].data();
    const size_t prims = per_vertex ? chunks[c].size() / (per_vertex * verts) : 0;
    for (size_t p = 0; p < prims; ++p, src += per_vertex * verts) {
      bool fits = cap.overflowed == 0;
      for (size_t i = 0; i < cap.buffers.size() && fits; ++i) {
        const CaptureBuffer& b = cap.buffers[i];
        fits = b.offset <= end[i] && (end[i] - b.offset) / 4 >= b.words.size() * verts;
      }
      if (!fits) {
        ++cap.overflowed;
        continue;
      }
      for (size_t v = 0; v < verts; ++v) {
        const uint32_t* word = src + v * per_vertex;
        for (size_t i = 0; i < cap.buffers.size(); ++i) {
          CaptureBuffer& b = cap.buffers[i];
          std::memcpy(base[i] + b.offset, word, b.words.size() * 4);
          b.offset += b.words.size() * 4;
          word += b.words.size();
        }
      }
      ++written;
    }
    chunks[c].clear();
  }
  cap.written += written;
  return written;
}

}  // namespace

void Context::flush() {
  Frame& fr = *frame_;
  if (fr.commands.empty()) return;
  // 1. Chunks, numbered in submission order.
  fr.chunks.clear();
  struct CaptureRange {
    Capture* capture;
    size_t first, count;  // chunks
  };
  std::vector<CaptureRange> captures;
  for (uint32_t c = 0; c < fr.commands.size(); ++c) {
    const Command& cmd = fr.commands[c];
    if (cmd.clear) {
      fr.chunks.push_back({c, 0, 0, 1});
      continue;
    }
    const DrawRecord& d = *fr.draws[cmd.index];
    const size_t first_chunk = fr.chunks.size();
    // Stippled lines carry the stipple counter from segment to segment: one chunk an instance.
    const bool stippled = d.state.line_stipple && prim_size(d.topology) == 2 && !d.program->geometry_input;
    const uint32_t step = stippled ? std::max(d.prim_count, 1u) : kChunkPrims;
    for (uint32_t inst = 0; inst < d.instance_count; ++inst)
      for (uint32_t b = 0; b < d.prim_count; b += step)
        fr.chunks.push_back({c, d.base_instance + inst, b, std::min(d.prim_count, b + step)});
    if (d.capture) captures.push_back({d.capture, first_chunk, fr.chunks.size() - first_chunk});
  }
  if (fr.captured.size() < fr.chunks.size()) fr.captured.resize(fr.chunks.size());
  run_frame();
  // Transform feedback is written once the frame's work is done and no longer queued, so
  // that the writes (which flush whatever reads the buffers first) find nothing of it.
  for (const CaptureRange& r : captures)
    stats_.primitives_written += write_capture(*r.capture, fr.captured.data() + r.first, r.count);
}

void Context::run_frame() {
  Frame& fr = *frame_;
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
    for (uint32_t c; (c = next_chunk.fetch_add(1, std::memory_order_relaxed)) < nchunks;)
      fr.process_chunk(w, c);
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
    stats_.primitives_generated += c.primitives_generated;
  }
}
}  // namespace tessel::gpu
