// A shader whose code is known only at run time (a GLSL program), and how the pipeline calls
// it: sixteen lanes a call, in structure-of-arrays form.
//
//   class MyProgram : public gpu::RuntimeShader { ... };         // shape(), vertex(), fragment()
//   ctx.draw(std::make_shared<MyProgram>(...), layout, state, call);
//
// The object given to draw() is the draw's own: the pipeline keeps it alive until the draw has
// run (on any worker thread, so vertex() and fragment() must be safe to call concurrently),
// so it should hold everything the shader reads (uniform values, texture bindings) as they
// were when the draw was made.
//
// Lanes: a vertex call shades up to sixteen vertices. A fragment call shades two 4x2 pixel
// groups (lanes 0-7 and 8-15, each two 2x2 quads in the order of detail::kLaneDx/kLaneDy:
// (0,0) (1,0) (0,1) (1,1) per quad), so the difference between lanes l|1 and l&~1 is d/dx and
// between l|2 and l&~2 is d/dy, as on llvmpipe. When shape().lanes_independent is set the
// pipeline may instead fill the lanes with pixels of several triangles in any arrangement.
#pragma once

#include <cstdint>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

#include "tessel/gpu/shader.hpp"
#include "tessel/gpu/state.hpp"

namespace tessel::gpu {

inline constexpr int kRuntimeLanes = 16;

// What the pipeline must know of a program before it runs it.
struct RuntimeShape {
  int varyings = 0;                // float components from vertex to fragment (<= kMaxVaryings)
  uint64_t flat = 0;               // components taken from the provoking vertex, bit for bit
  uint64_t noperspective = 0;      // components interpolated linearly in screen space
  bool discards = false;           // fragment() may set `killed`
  bool writes_depth = false;       // fragment() sets `depth`
  bool lanes_independent = false;  // no derivatives and no implicit-LOD sampling
  int outputs = 1;                 // colour outputs 0..outputs-1 (MRT)
  uint32_t attributes = 0;         // attribute locations the vertex stage reads
  // Varying components with a meaning for the pipeline (-1: none). They count in `varyings`.
  int point_size = -1;     // the vertex's point size (gl_PointSize), for program_point_size
  int point_coord = -1;    // two components the pipeline sets to gl_PointCoord (s, t) on points
  int clip_distance = -1;  // the first of clip_distances (gl_ClipDistance[0..n)), for clipping
  int clip_distances = 0;
  // The shader's float arithmetic must run with denormals flushed (SSE flush-to-zero and
  // denormals-are-zero), as llvmpipe runs GLSL. vertex() and fragment() do not set the mode
  // themselves: the pipeline sets it around its work for the draw (the shading loops and
  // everything in them), and a direct caller with ScopedDenormalFlush.
  bool flush_denormals = false;
};

// Sets the SSE flush-to-zero and denormals-are-zero bits for the life of the object when
// `on` (and they are not set already), and restores the caller's mode after.
class ScopedDenormalFlush {
 public:
#if defined(__SSE__)
  explicit ScopedDenormalFlush(bool on) {
    if (!on) return;
    saved_ = _mm_getcsr();
    if ((saved_ & kBits) != kBits) {
      _mm_setcsr(saved_ | kBits);
      changed_ = true;
    }
  }
  ~ScopedDenormalFlush() {
    if (changed_) _mm_setcsr(saved_);
  }

 private:
  static constexpr unsigned kBits = 0x8040u;  // FTZ | DAZ
  unsigned saved_ = 0;
  bool changed_ = false;
#else
  explicit ScopedDenormalFlush(bool) {}
#endif
  ScopedDenormalFlush(const ScopedDenormalFlush&) = delete;
  ScopedDenormalFlush& operator=(const ScopedDenormalFlush&) = delete;
};

struct VertexLanes {
  int count = 0;  // lanes 0..count-1 hold vertices; the others repeat the last and are ignored
  // Attribute locations in shape().attributes, as four floats per lane (integer attributes
  // carry their bits).
  alignas(64) float attr[kMaxVertexAttribs][4][kRuntimeLanes];
  alignas(64) int32_t vertex_id[kRuntimeLanes];
  alignas(64) int32_t instance_id[kRuntimeLanes];
  // Written by the shader: the clip position and the varyings ([component][lane]).
  alignas(64) float position[4][kRuntimeLanes];
  alignas(64) float varyings[kMaxVaryings][kRuntimeLanes];
};

struct FragmentLanes {
  uint32_t mask = 0;  // lanes covered (bit per lane); the others only help derivatives
  // Interpolated varyings ([component][lane]) and gl_FragCoord (pixel centre, window z, 1/w).
  alignas(64) float varyings[kMaxVaryings][kRuntimeLanes];
  alignas(64) float coord[4][kRuntimeLanes];
  alignas(64) int32_t primitive_id[kRuntimeLanes];
  uint32_t front_facing = 0;  // bit per lane
  // Written by the shader: colours per output, depth when shape().writes_depth, and the lanes
  // discarded.
  alignas(64) float color[kMaxColorAttachments][4][kRuntimeLanes];
  alignas(64) float depth[kRuntimeLanes];
  uint32_t killed = 0;
};

class RuntimeShader {
 public:
  virtual ~RuntimeShader() = default;
  virtual const RuntimeShape& shape() const = 0;
  virtual void vertex(VertexLanes& lanes) const = 0;
  virtual void fragment(FragmentLanes& lanes) const = 0;
  // Two fragment calls' worth at once (the pipeline has them ready together), so that an
  // implementation can interleave their work; the results must be those of fragment(a) then
  // fragment(b).
  virtual void fragment_pair(FragmentLanes& a, FragmentLanes& b) const {
    fragment(a);
    fragment(b);
  }
};

}  // namespace tessel::gpu
