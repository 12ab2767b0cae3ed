// What a shader sees, and what the pipeline reads from a shader type.
//
// A shader is a C++ type:
//
//   struct Phong {
//     struct Uniforms { glm::mat4 mvp; ... };                 // scalar, shared by all lanes
//     template <class F> struct Varyings { Vec3<F> n; Vec2<F> uv; };  // floats only
//     template <class F> Vec4<F> vertex(const Uniforms&, const VertexIn<F>&, Varyings<F>&) const;
//     template <class F> void fragment(const Uniforms&, const Varyings<F>&, Fragment<F>&) const;
//   };
//
// Varyings<F> must be made of F only (Vec2/3/4 of F, arrays of F): the pipeline treats it
// as an array of sizeof(Varyings<float>)/4 numbers to clip and interpolate. Optional
// members refine what the pipeline does:
//   static constexpr bool discards = true;       // fragment() may call frag.discard()
//   static constexpr bool writes_depth = true;   // fragment() sets frag.depth
//   static constexpr uint64_t flat = 0b...;      // varying components taken from the provoking vertex
//   static constexpr uint64_t noperspective = 0b...;  // components interpolated linearly in screen space
//   static constexpr uint32_t attributes = 0b...;     // attribute locations the layout must enable
//   static constexpr int outputs = 2;            // colour outputs written (MRT)
//   static constexpr bool lanes_independent = true;  // fragment() uses no dFdx/dFdy/fwidth
//                                                // and no implicit-LOD texture(): its lanes
//                                                // need not be 2x2 quads, so the pipeline may
//                                                // pack the covered pixels of several groups
//                                                // and triangles into one call
#pragma once

#include <array>
#include <cstdint>
#include <type_traits>

#include "tessel/gpu/buffer.hpp"
#include "tessel/gpu/state.hpp"
#include "tessel/gpu/vec.hpp"

namespace tessel::gpu {

inline constexpr int kMaxVaryings = 64;  // float components

template <class F>
struct VertexIn {
  std::array<Vec4<F>, kMaxVertexAttribs> attr;  // attribute locations, as floats
  IntOf<F> vertex_id;                           // gl_VertexID (the index, base vertex added)
  IntOf<F> instance_id;                         // gl_InstanceID
  // An integer attribute (VertexAttrib::integer) component: its bits as an integer.
  IntOf<F> iattr(int location, int component) const {
    const Vec4<F>& a = attr[location];
    return bits_of(component == 0 ? a.x : component == 1 ? a.y : component == 2 ? a.z : a.w);
  }
};

template <class F>
struct Fragment {
  Vec4<F> coord;                                    // gl_FragCoord: pixel centre x, y; window z; 1/w
  MaskOf<F> front_facing;                           // gl_FrontFacing
  IntOf<F> primitive_id;                            // gl_PrimitiveID
  std::array<Vec4<F>, kMaxColorAttachments> color;  // outputs; color[0] is the usual one
  F depth;                                          // gl_FragDepth, read when the shader writes depth
  MaskOf<F> killed;                                 // lanes discarded
  void discard(MaskOf<F> m) { killed = killed | m; }
  void discard() { killed = MaskOf<F>(true); }
};

namespace detail {
template <class S>
constexpr bool shader_discards() {
  if constexpr (requires { S::discards; })
    return S::discards;
  else
    return false;
}
template <class S>
constexpr bool shader_writes_depth() {
  if constexpr (requires { S::writes_depth; })
    return S::writes_depth;
  else
    return false;
}
template <class S>
constexpr uint64_t shader_flat() {
  if constexpr (requires { S::flat; })
    return S::flat;
  else
    return 0;
}
template <class S>
constexpr uint64_t shader_noperspective() {
  if constexpr (requires { S::noperspective; })
    return S::noperspective;
  else
    return 0;
}
template <class S>
constexpr uint32_t shader_attributes() {
  if constexpr (requires { S::attributes; })
    return S::attributes;
  else
    return 0;
}
template <class S>
constexpr bool shader_lanes_independent() {
  if constexpr (requires { S::lanes_independent; })
    return S::lanes_independent;
  else
    return false;
}
// A bridge to a shader known only at run time (runtime_shader.hpp): its flat components are
// copied bit for bit, and its number of outputs is ProgramBase::outputs.
template <class S>
constexpr bool shader_runtime() {
  if constexpr (requires { S::runtime; })
    return S::runtime;
  else
    return false;
}
template <class S>
constexpr int shader_outputs() {
  if constexpr (requires { S::outputs; })
    return S::outputs;
  else
    return 1;
}
template <class S>
constexpr int varying_count() {
  using V1 = typename S::template Varyings<float>;
  using V8 = typename S::template Varyings<Float8>;
  using V16 = typename S::template Varyings<Float16>;
  static_assert((std::is_empty_v<V1> && std::is_empty_v<V8> && std::is_empty_v<V16>) ||
                    (sizeof(V1) % sizeof(float) == 0 && sizeof(V8) == sizeof(V1) / 4 * sizeof(Float8) &&
                     sizeof(V16) == sizeof(V1) / 4 * sizeof(Float16)),
                "Varyings<F> must consist of F values only (or be empty)");
  static_assert(std::is_trivially_copyable_v<V1> && std::is_trivially_copyable_v<V8> &&
                std::is_trivially_copyable_v<V16>);
  constexpr int n = std::is_empty_v<V1> ? 0 : int(sizeof(V1) / sizeof(float));
  static_assert(n <= kMaxVaryings, "too many varyings");
  return n;
}
}  // namespace detail

}  // namespace tessel::gpu
