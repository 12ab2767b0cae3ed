// The bridge from the pipeline's compiled-in shader loop (detail/raster.hpp, a template over a
// C++ shader type) to shaders known only at run time (runtime_shader.hpp).
//
// The raster loop needs the number of varyings at compile time, so the bridge is
// instantiated for a few sizes (kSizes) and a program runs in the smallest that holds its
// varyings; the unused components are zero. It is instantiated twice more for programs whose
// lanes are independent and that neither discard nor write depth: those may be packed.
#include <algorithm>
#include <array>
#include <cstring>
#include <type_traits>

#include "tessel/gpu/context.hpp"
#include "tessel/gpu/detail/raster.hpp"

namespace tessel::gpu {
namespace {

struct NoVaryings {};
template <class F, int K>
struct VaryingArray {
  F v[K];
};

template <int K, bool Packed>
struct RuntimeBridge {
  using Uniforms = std::shared_ptr<const RuntimeShader>;
  template <class F>
  using Varyings = std::conditional_t<K == 0, NoVaryings, VaryingArray<F, (K > 0 ? K : 1)>>;
  // The program's shape, copied when the draw is made (shape() is a virtual call).
  RuntimeShape shape_;
  static constexpr bool runtime = true;
  // Without packing, discarding and depth writes are taken as possible: when the program
  // does neither, `killed` stays clear and `depth` holds the interpolated depth, so the
  // results are the same; the pipeline still tests depth early (ProgramBase::discards).
  static constexpr bool discards = !Packed;
  static constexpr bool writes_depth = !Packed;
  static constexpr bool lanes_independent = Packed;
  static constexpr int outputs = Packed ? 1 : kMaxColorAttachments;
  ScopedDenormalFlush float_mode() const { return ScopedDenormalFlush(shape_.flush_denormals); }
  // The components the program reads (K rounds them up).
  int live_varyings() const { return shape_.varyings; }

  // Two batches of eight vertices (the pipeline fetches eight at a time) as one call of the
  // program's sixteen lanes; the second batch only when `both` (else lanes 8-15 hold an
  // earlier call's vertices, and their results are not read).
  void vertex_pair(const Uniforms& u, const VertexIn<Float8> (&in)[2], bool both, Varyings<Float8> (&out)[2],
                   Vec4<Float8> (&pos)[2]) const {
    thread_local VertexLanes lanes;
    const RuntimeShape& shape = shape_;
    for (int h = 0; h < (both ? 2 : 1); ++h) {
      const int at = h * 8;
      for (uint32_t m = shape.attributes; m; m &= m - 1) {
        const int loc = __builtin_ctz(m);
        if (loc >= kMaxVertexAttribs) break;
        const Vec4<Float8>& a = in[h].attr[size_t(loc)];
        a.x.store(lanes.attr[loc][0] + at);
        a.y.store(lanes.attr[loc][1] + at);
        a.z.store(lanes.attr[loc][2] + at);
        a.w.store(lanes.attr[loc][3] + at);
      }
      float_from_bits(in[h].vertex_id).store(reinterpret_cast<float*>(lanes.vertex_id) + at);
      float_from_bits(in[h].instance_id).store(reinterpret_cast<float*>(lanes.instance_id) + at);
    }
    lanes.count = both ? 16 : 8;
    u->vertex(lanes);
    for (int h = 0; h < (both ? 2 : 1); ++h) {
      const int at = h * 8;
      if constexpr (K > 0) {
        // With a geometry stage the vertex stage's components are that stage's inputs.
        const bool gs = shape.geometry_input != 0;
        const int n = std::min(K, gs ? shape.vertex_varyings : shape.varyings);
        for (int k = 0; k < n; ++k) out[h].v[k] = Float8::load(lanes.varyings[k] + at);
        for (int k = n; k < K; ++k) out[h].v[k] = Float8(0.0f);
        // gl_PointCoord is set by setup on points; the program does not write it (zero elsewhere).
        if (!gs && shape.point_coord >= 0 && shape.point_coord + 1 < K)
          out[h].v[shape.point_coord] = out[h].v[shape.point_coord + 1] = Float8(0.0f);
      }
      pos[h] = Vec4<Float8>(Float8::load(lanes.position[0] + at), Float8::load(lanes.position[1] + at),
                            Float8::load(lanes.position[2] + at), Float8::load(lanes.position[3] + at));
    }
  }

  void geometry(const Uniforms& u, GeometryLanes& lanes) const { u->geometry(lanes); }

  // The lane rows the fragment stage reads and writes on this thread, two sets (`slot` 0 and
  // 1) so that two calls' worth can be shaded together. The raster loop (detail/raster.hpp)
  // looks them up once, stores the interpolated varyings straight into them and calls
  // fragment_stored or fragment_stored_pair with them: a run-time shader has no fragment()
  // taking a Varyings struct.
  static FragmentLanes& fragment_lanes(int slot) {
    thread_local FragmentLanes lanes[2];
    return lanes[slot];
  }
  template <class F>
  void fragment_stored(const Uniforms& u, Fragment<F>& f, FragmentLanes& lanes) const {
    put(f, lanes);
    u->fragment(lanes);
    take(lanes, f);
  }
  // f0 in lane rows a and f1 in b, as fragment_stored on each in turn.
  void fragment_stored_pair(const Uniforms& u, Fragment<Float16>& f0, Fragment<Float16>& f1, FragmentLanes& a,
                            FragmentLanes& b) const {
    put(f0, a);
    put(f1, b);
    u->fragment_pair(a, b);
    take(a, f0);
    take(b, f1);
  }

 private:
  // The fragment's built-in inputs into the lane rows, and the shader's results out of them.
  template <class F>
  void put(const Fragment<F>& f, FragmentLanes& lanes) const {
    constexpr int N = lane_width<F>;
    const RuntimeShape& shape = shape_;
    f.coord.x.store(lanes.coord[0]);
    f.coord.y.store(lanes.coord[1]);
    f.coord.z.store(lanes.coord[2]);
    f.coord.w.store(lanes.coord[3]);
    float_from_bits(f.primitive_id).store(reinterpret_cast<float*>(lanes.primitive_id));
    lanes.front_facing = f.front_facing.bits();
    lanes.mask = N == 16 ? 0xFFFFu : 0xFFu;
    lanes.killed = 0;
    if (shape.writes_depth) f.coord.z.store(lanes.depth);
  }
  template <class F>
  void take(const FragmentLanes& lanes, Fragment<F>& f) const {
    const RuntimeShape& shape = shape_;
    const int outs = std::min(outputs, shape.outputs);
    for (int i = 0; i < outs; ++i) {
      f.color[size_t(i)] = Vec4<F>(F::load(lanes.color[i][0]), F::load(lanes.color[i][1]),
                                   F::load(lanes.color[i][2]), F::load(lanes.color[i][3]));
    }
    if constexpr (!Packed) {
      if (shape.writes_depth) f.depth = F::load(lanes.depth);
      if (lanes.killed) f.discard(MaskOf<F>::from_bits(lanes.killed));
    }
  }
};

constexpr std::array<int, 7> kSizes = {0, 4, 8, 16, 24, 32, kMaxVaryings};

template <int K, bool Packed>
std::unique_ptr<detail::ProgramBase> make_bridge(const std::shared_ptr<const RuntimeShader>& s) {
  auto p =
      std::make_unique<detail::Program<RuntimeBridge<K, Packed>>>(RuntimeBridge<K, Packed>{s->shape()}, s);
  const RuntimeShape& shape = s->shape();
  p->flat = shape.flat;
  p->noperspective = shape.noperspective;
  p->discards = shape.discards;
  p->writes_depth = shape.writes_depth;
  p->outputs = shape.outputs;
  p->point_size_var = shape.point_size;
  p->point_coord_var = shape.point_coord;
  p->clip_distance_var = shape.clip_distance;
  p->clip_distances = shape.clip_distances;
  p->geometry_input = shape.geometry_input;
  p->geometry_output = shape.geometry_output;
  p->geometry_max_vertices = shape.geometry_max_vertices;
  p->vertex_varyings = shape.vertex_varyings;
  p->primitive_id_var = shape.primitive_id;
  p->layer_var = shape.layer;
  return p;
}

template <bool Packed, size_t... I>
std::unique_ptr<detail::ProgramBase> pick(const std::shared_ptr<const RuntimeShader>& s, int varyings,
                                          std::index_sequence<I...>) {
  std::unique_ptr<detail::ProgramBase> r;
  ((r == nullptr && varyings <= kSizes[I] ? (void)(r = make_bridge<kSizes[I], Packed>(s)) : void()), ...);
  return r;
}

}  // namespace

void Context::draw(std::shared_ptr<const RuntimeShader> shader, const VertexLayout& layout,
                   const RenderState& state, const DrawCall& call) {
  if (!shader) throw Error("draw: no shader");
  const RuntimeShape& shape = shader->shape();
  if (shape.varyings < 0 || shape.varyings > kMaxVaryings)
    throw Error("draw: the program passes " + std::to_string(shape.varyings) +
                " varying components; at most " + std::to_string(kMaxVaryings) + " are supported");
  if (shape.outputs < 0 || shape.outputs > kMaxColorAttachments)
    throw Error("draw: the program writes " + std::to_string(shape.outputs) + " colour outputs; at most " +
                std::to_string(kMaxColorAttachments) + " are supported");
  // The components the pipeline reads or sets must be varyings of the program.
  auto inside = [&](int first, int n) { return first >= 0 && n >= 0 && first + n <= shape.varyings; };
  if ((shape.point_size != -1 && !inside(shape.point_size, 1)) ||
      (shape.point_coord != -1 && !inside(shape.point_coord, 2)) ||
      (shape.clip_distances != 0 && !inside(shape.clip_distance, shape.clip_distances)) ||
      shape.clip_distances < 0 || shape.clip_distances > kMaxClipPlanes)
    throw Error("draw: the program's point size, point coordinate or clip distance components (" +
                std::to_string(shape.point_size) + ", " + std::to_string(shape.point_coord) + ", " +
                std::to_string(shape.clip_distance) + " + " + std::to_string(shape.clip_distances) +
                ") are not among its " + std::to_string(shape.varyings) + " varying components");
  if (shape.geometry_input) {
    const int in = shape.geometry_input;
    const Topology out = shape.geometry_output;
    if ((in != 1 && in != 2 && in != 3 && in != 4 && in != 6) ||
        (out != Topology::Points && out != Topology::LineStrip && out != Topology::TriangleStrip) ||
        shape.geometry_max_vertices < 0 || shape.geometry_max_vertices > kMaxGeometryVertices ||
        shape.vertex_varyings < 0 || shape.vertex_varyings > kMaxVaryings ||
        (shape.primitive_id != -1 && !inside(shape.primitive_id, 1)) ||
        (shape.layer != -1 && !inside(shape.layer, 1)))
      throw Error("draw: the program's geometry stage (" + std::to_string(in) + " input vertices, " +
                  std::to_string(shape.geometry_max_vertices) + " output vertices, " +
                  std::to_string(shape.vertex_varyings) + " vertex components) is out of range");
  }
  const bool packed = shape.lanes_independent && !shape.discards && !shape.writes_depth && shape.outputs <= 1;
  // The vertex stage's components (for a geometry stage) and the fragment stage's share the
  // per-vertex storage, so the larger count picks the size.
  const int K = std::max(shape.varyings, shape.geometry_input ? shape.vertex_varyings : 0);
  auto program = packed ? pick<true>(shader, K, std::make_index_sequence<kSizes.size()>())
                        : pick<false>(shader, K, std::make_index_sequence<kSizes.size()>());
  submit(std::move(program), layout, state, call, shape.attributes);
}

}  // namespace tessel::gpu
