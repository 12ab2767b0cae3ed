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

  // A geometry stage (GL 3.2), between the vertex stage and clipping, when geometry_input is
  // not 0: the vertices of each primitive it takes (1, 2, 3, 4 or 6; the draw's topology must
  // match: points; lines and strips; triangles, strips and fans; and the adjacency kinds).
  // The vertex stage then writes vertex_varyings components for it, and everything above
  // (varyings, flat, point_size, clip_distance, ...) describes what the geometry stage emits.
  int geometry_input = 0;
  Topology geometry_output = Topology::Points;  // Points, LineStrip or TriangleStrip
  int geometry_max_vertices = 0;                // emitted per primitive (<= kMaxGeometryVertices)
  int vertex_varyings = 0;                      // <= kMaxVaryings
  // The varying component holding the bits of the geometry stage's gl_PrimitiveID, which the
  // fragment stage reads from the provoking vertex (-1: the input primitive's number).
  int primitive_id = -1;
  // The component holding the bits of its gl_Layer, for RenderState::layer (-1: none).
  int layer = -1;
};

inline constexpr int kMaxGeometryInputVertices = 6;
inline constexpr int kMaxGeometryVertices = 1024;

// One geometry call: up to sixteen primitives, one a lane.
struct GeometryLanes {
  int count = 0;  // primitives in lanes 0..count-1
  // Each input vertex's clip position and vertex_varyings components ([vertex][component][lane]),
  // and each primitive's number in the draw (gl_PrimitiveIDIn).
  alignas(64) float position[kMaxGeometryInputVertices][4][kRuntimeLanes];
  alignas(64) float varyings[kMaxGeometryInputVertices][kMaxVaryings][kRuntimeLanes];
  alignas(64) int32_t primitive_id[kRuntimeLanes];
  // Set by the caller: room for geometry_max_vertices vertices a lane, of out_stride
  // (>= 4 + varyings) components. The shader writes vertex v of lane l as its clip position
  // and then its varyings, component c at out[(v * out_stride + c) * kRuntimeLanes + l]
  // (the components past 4 + varyings are left alone), and strip_start[v * kRuntimeLanes + l],
  // not zero when that vertex begins a strip (the first one, and the first after EndPrimitive).
  float* out = nullptr;
  uint32_t* strip_start = nullptr;
  int out_stride = 0;
  // Written by the shader: the vertices each lane emitted.
  uint32_t emitted[kRuntimeLanes] = {};
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
  // The geometry stage, for a program whose shape() has one.
  virtual void geometry(GeometryLanes& lanes) const { (void)lanes; }
  // Two fragment calls' worth at once (the pipeline has them ready together), so that an
  // implementation can interleave their work; the results must be those of fragment(a) then
  // fragment(b).
  virtual void fragment_pair(FragmentLanes& a, FragmentLanes& b) const {
    fragment(a);
    fragment(b);
  }
};

}  // namespace tessel::gpu
