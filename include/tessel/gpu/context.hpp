// The context: where draws are queued and executed.
//
//   gpu::Context ctx;                       // worker threads = hardware threads
//   gpu::Framebuffer fb(&color, &depth);
//   ctx.bind_framebuffer(&fb);
//   ctx.clear({.color = {0, 0, 0, 1}, .depth = 1.0f});
//   ctx.draw(MyShader{}, uniforms, layout, state, {.topology = Topology::Triangles, .count = 36});
//   ctx.finish();                           // the attachments now hold the image
//
// Draws are deferred: they are recorded with copies of their state and uniforms, and run
// together when the context flushes (finish(), a framebuffer change, a read, a change to a
// resource a queued draw uses). Execution is sort-middle and tiled on all worker threads; the
// image is bit-identical for any number of threads.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "tessel/gpu/buffer.hpp"
#include "tessel/gpu/detail/pipeline.hpp"
#include "tessel/gpu/detail/raster.hpp"
#include "tessel/gpu/framebuffer.hpp"
#include "tessel/gpu/runtime_shader.hpp"
#include "tessel/gpu/shader.hpp"
#include "tessel/gpu/state.hpp"

namespace tessel::gpu {

// Transform feedback (GL 3.3 §2.15): a draw's primitives as they leave the vertex stage, or
// the geometry stage when the program has one, written to buffers as independent points,
// lines or triangles (strips, fans and loops cut as GL cuts them: each triangle keeps its
// provoking vertex first or last), in the draw's order, before clipping.
inline constexpr int kMaxCaptureBuffers = 4;
// A captured word's source: the vertex's clip position component c is kCapturePosition - c.
inline constexpr int kCapturePosition = -1;
struct CaptureBuffer {
  Buffer* buffer = nullptr;
  size_t offset = 0;  // where the next vertex goes: advances as primitives are written
  size_t end = 0;     // the end of the range it may write (the buffer's size at most)
  // The 32-bit words of each vertex, in order: the varying component (RuntimeShape's
  // numbering, of the stage that feeds clipping) or the position component each one copies.
  std::vector<int> words;
};
struct Capture {
  Topology mode = Topology::Points;    // Points, Lines or Triangles
  std::vector<CaptureBuffer> buffers;  // at most kMaxCaptureBuffers
  // Primitives of every draw so far: those written and those that did not fit (once one does
  // not, none after it is written).
  uint64_t written = 0, overflowed = 0;
};

struct DrawCall {
  Topology topology = Topology::Triangles;
  uint32_t first = 0;                    // first vertex (arrays) or first index (indexed)
  uint32_t count = 0;                    // vertices or indices
  const Buffer* index_buffer = nullptr;  // indexed draw when set
  IndexType index_type = IndexType::U32;
  size_t index_offset = 0;  // bytes into index_buffer
  int32_t base_vertex = 0;
  uint32_t instance_count = 1;
  uint32_t base_instance = 0;
  // Transform feedback: when set, the draw also writes its primitives there, and runs at
  // once (the queued work with it), so that the buffers and counts are up to date when draw()
  // returns. The draw's topology must give primitives of capture->mode (after the geometry
  // stage). Throws Error when it does not, or for a word source the program does not have.
  Capture* capture = nullptr;
};

struct ClearValues {
  // Which attachments to clear: bit i = colour attachment i.
  uint8_t color_attachments = 0xFF;
  bool clear_color = true;
  glm::vec4 color{0.0f, 0.0f, 0.0f, 0.0f};
  // Per-attachment values (glClearBufferfv): when set, attachment i is cleared to
  // attachment_colors[i] instead of `color`.
  bool per_attachment = false;
  std::array<glm::vec4, kMaxColorAttachments> attachment_colors{};
  bool clear_depth = true;
  float depth = 1.0f;
  bool clear_stencil = true;
  uint8_t stencil = 0;
};

// Counters of everything run since the last reset_stats().
using Stats = detail::Counters;

class Context final : public PendingWork {
 public:
  // threads = 0: one worker per hardware thread.
  explicit Context(int threads = 0);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  int threads() const;
  void set_threads(int threads);  // flushes first

  // Binds where draws and clears go; flushes the queued work if the target changes. Throws
  // Error if the framebuffer is incomplete.
  void bind_framebuffer(Framebuffer* fb);
  Framebuffer* framebuffer() const { return fb_; }

  // Clears the bound framebuffer's attachments; obeys scissor and the write masks of `state`
  // (colour masks of blend[i].write_mask, depth_write, stencil_front.write_mask).
  void clear(const ClearValues& values, const RenderState& state = RenderState{});

  // Queues a draw. Throws Error (and queues nothing) for a draw that is invalid: no
  // framebuffer, an index or vertex range past its buffer, a required attribute that the
  // layout does not enable, a bad enum or size. Primitives with NaN/Inf positions are dropped.
  template <class S>
  void draw(const S& shader, const typename S::Uniforms& uniforms, const VertexLayout& layout,
            const RenderState& state, const DrawCall& call) {
    submit(std::make_unique<detail::Program<S>>(shader, uniforms), layout, state, call,
           detail::shader_attributes<S>());
  }

  // Queues a draw of a shader known only at run time (a GLSL program, runtime_shader.hpp).
  // The draw keeps `shader` until it has run. Throws Error as the draw above does, and for a
  // null shader or a shape the pipeline cannot take (too many varyings or outputs).
  void draw(std::shared_ptr<const RuntimeShader> shader, const VertexLayout& layout, const RenderState& state,
            const DrawCall& call);

  // Runs everything queued; afterwards the attachments hold the results.
  void flush() override;
  void finish() { flush(); }
  bool has_pending() const override;

  const Stats& stats() const { return stats_; }
  void reset_stats() { stats_ = {}; }

 private:
  void submit(std::unique_ptr<detail::ProgramBase> program, const VertexLayout& layout,
              const RenderState& state, const DrawCall& call, uint32_t required_attribs);
  detail::TargetView make_target() const;
  void run_frame();  // the chunks' geometry and raster phases (flush())
  void check_capture(const Capture& capture, const detail::DrawRecord& d) const;

  struct Frame;
  class WorkerPool;
  Framebuffer* fb_ = nullptr;
  std::unique_ptr<Frame> frame_;
  std::unique_ptr<WorkerPool> pool_;
  Stats stats_;
};

}  // namespace tessel::gpu
