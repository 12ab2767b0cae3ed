// The standard scenes' shader (../shared/scenes/README.md): Blinn-Phong per fragment in
// world space, for Tessel. `tessel bench` draws the scenes with it and bench/micro.cpp times
// it; bench/peer/peer.cpp has the same shader in GLSL for llvmpipe.
#pragma once

#include "scenes.hpp"
#include "tessel/gpu/shader.hpp"
#include "tessel/gpu/texture.hpp"
#include "tessel/gpu/vec.hpp"

namespace tessel::scenes {
using namespace tessel::gpu;

// What ScenePhong interpolates: position and normal; uv when textured; the albedo when it
// comes per instance (otherwise it is a uniform, as in the peer's GLSL, whose compiler drops
// unused varyings just as these types do).
template <class F, bool Textured, bool Instanced>
struct PhongVaryings {
  Vec3<F> p, n;
};
template <class F>
struct PhongVaryings<F, true, false> {
  Vec3<F> p, n;
  Vec2<F> uv;
};
template <class F>
struct PhongVaryings<F, false, true> {
  Vec3<F> p, n;
  Vec3<F> albedo;
};

// The scenes' Blinn-Phong (scenes README), per fragment in world space. Textured: the albedo
// is the texture. Instanced: offset and albedo come from per-instance attributes 3 and 4.
template <bool Textured, bool Instanced>
struct ScenePhong {
  static_assert(!(Textured && Instanced), "the textured scene is not instanced");
  struct Uniforms {
    glm::mat4 viewproj{1.0f};
    glm::vec3 offset{0.0f}, albedo{0.8f, 0.6f, 0.4f}, eye{0.0f, 0.0f, 3.0f}, light{1.0f, 2.0f, 2.0f};
    Sampler2D tex;
  };
  template <class F>
  using Varyings = PhongVaryings<F, Textured, Instanced>;
  static constexpr uint32_t attributes = Instanced ? 0b11111 : 0b111;
  // No derivatives, and no texture LOD unless textured: the pipeline may pack its lanes.
  static constexpr bool lanes_independent = !Textured;

  template <class F>
  Vec4<F> vertex(const Uniforms& u, const VertexIn<F>& in, Varyings<F>& out) const {
    if constexpr (Instanced) {
      out.p = in.attr[0].xyz() + in.attr[3].xyz();
      out.albedo = in.attr[4].xyz();
    } else {
      out.p = in.attr[0].xyz() + Vec3<F>(u.offset);
    }
    out.n = in.attr[1].xyz();
    if constexpr (Textured) out.uv = in.attr[2].xy();
    return u.viewproj * Vec4<F>(out.p, F(1.0f));
  }

  template <class F>
  void fragment(const Uniforms& u, const Varyings<F>& v, Fragment<F>& f) const {
    const Vec3<F> N = normalize(v.n);
    const Vec3<F> L = normalize(Vec3<F>(u.light) - v.p);
    const Vec3<F> V = normalize(Vec3<F>(u.eye) - v.p);
    const Vec3<F> H = normalize(L + V);
    const F ndl = max(dot(N, L), F(0.0f));
    const F spec = select(ndl > F(0.0f), pow(max(dot(N, H), F(0.0f)), F(kShininess)), F(0.0f));
    Vec3<F> albedo;
    if constexpr (Textured)
      albedo = texture(u.tex, v.uv).xyz();
    else if constexpr (Instanced)
      albedo = v.albedo;
    else
      albedo = Vec3<F>(u.albedo);
    const Vec3<F> c = albedo * F(kAmbient) + albedo * (ndl * F(kDiffuse)) + Vec3<F>(spec * F(kSpecular));
    f.color[0] = Vec4<F>(c, F(1.0f));
  }
};

}  // namespace tessel::scenes
