// The shader library: each scene::Shader fills the uniforms of a GPU shader (a struct with
// vertex() and fragment() on lanes, compiled here) from the RenderState and submits the draw.
#include "tessel/scene/shaders.hpp"

#include <array>

#include "tessel/gpu/shader.hpp"
#include "tessel/gpu/vec.hpp"

namespace tessel::scene {

using namespace tessel::gpu;

namespace {

// The lights and the material as the GPU shaders read them.
struct LightingUniforms {
  std::array<Light, kMaxLights> lights{};
  int count = 0;
  glm::vec3 ka{0.0f}, kd{0.0f}, ks{0.0f}, emission{0.0f};
  float shininess = 1.0f;
  glm::vec3 eye{0.0f};
  bool textured = false;
  Sampler2D tex;
};

struct TransformUniforms {
  glm::mat4 MVP{1.0f}, M{1.0f};
  glm::mat4 normal{1.0f};  // (M^-1)^T: normals stay perpendicular under non-uniform scale
};

LightingUniforms lighting(const RenderState& s) {
  LightingUniforms u;
  u.count = int(std::min<size_t>(s.lights.size(), kMaxLights));
  for (int i = 0; i < u.count; ++i) u.lights[size_t(i)] = s.lights[size_t(i)];
  const Material m = s.material ? *s.material : Material{};
  u.ka = m.ka;
  u.kd = m.kd;
  u.ks = m.ks;
  u.emission = m.emission;
  u.shininess = m.shininess;
  u.eye = s.wEye;
  u.textured = m.texture != nullptr;
  u.tex.texture = m.texture.get();
  u.tex.state.min_filter = Filter::LinearMipmapLinear;
  u.tex.state.mag_filter = Filter::Linear;
  return u;
}

TransformUniforms transforms(const RenderState& s) {
  return {s.P * s.V * s.M, s.M, glm::transpose(s.Minv)};
}

// The two parts of the notes' formula at a point: ambient + diffuse (to be multiplied by the
// texture) and specular.
template <class F> struct Radiance {
  Vec3<F> ambient_diffuse, specular;
};

template <class F>
Radiance<F> illuminate(const LightingUniforms& u, const Vec3<F>& p, const Vec3<F>& N) {
  const Vec3<F> V = normalize(Vec3<F>(u.eye) - p);
  Radiance<F> r{Vec3<F>(F(0.0f)), Vec3<F>(F(0.0f))};
  for (int i = 0; i < u.count; ++i) {
    const Light& l = u.lights[size_t(i)];
    // The notes' homogeneous light direction: light.xyz - p light.w (w = 0: directional).
    const Vec3<F> L = normalize(Vec3<F>(glm::vec3(l.wLightPos)) - p * F(l.wLightPos.w));
    F spot(1.0f);
    if (l.spot_cos_cutoff > -1.0f) {
      const F c = dot(-L, Vec3<F>(glm::normalize(l.spot_direction)));
      spot = select(c >= F(l.spot_cos_cutoff), l.spot_exponent == 0.0f ? F(1.0f) : pow(max(c, F(0.0f)), F(l.spot_exponent)),
                    F(0.0f));
    }
    const F cost = max(dot(N, L), F(0.0f));
    const Vec3<F> H = normalize(L + V);
    const F cosd = select(cost > F(0.0f), pow(max(dot(N, H), F(0.0f)), F(u.shininess)), F(0.0f));
    const Vec3<F> Le = Vec3<F>(l.Le) * spot;
    r.ambient_diffuse = r.ambient_diffuse + Vec3<F>(u.ka * l.La) + Vec3<F>(u.kd) * Le * cost;
    r.specular = r.specular + Vec3<F>(u.ks) * Le * cosd;
  }
  r.ambient_diffuse = r.ambient_diffuse + Vec3<F>(u.emission);
  return r;
}

struct GouraudGpu {
  struct Uniforms {
    TransformUniforms t;
    LightingUniforms l;
  };
  template <class F> struct Varyings {
    Vec3<F> ambient_diffuse, specular;
    Vec2<F> uv;
  };
  static constexpr uint32_t attributes = 0b111;

  template <class F> Vec4<F> vertex(const Uniforms& u, const VertexIn<F>& in, Varyings<F>& out) const {
    const Vec4<F> pos(in.attr[0].xyz(), F(1.0f));
    const Vec3<F> p = (u.t.M * pos).xyz();
    const Vec3<F> N = normalize((u.t.normal * Vec4<F>(in.attr[1].xyz(), F(0.0f))).xyz());
    const Radiance<F> r = illuminate(u.l, p, N);
    out.ambient_diffuse = r.ambient_diffuse;
    out.specular = r.specular;
    out.uv = in.attr[2].xy();
    return u.t.MVP * pos;
  }
  template <class F> void fragment(const Uniforms& u, const Varyings<F>& v, Fragment<F>& f) const {
    Vec3<F> c = v.ambient_diffuse;
    if (u.l.textured) c = c * texture(u.l.tex, v.uv).xyz();
    f.color[0] = Vec4<F>(c + v.specular, F(1.0f));
  }
};

struct PhongGpu {
  struct Uniforms {
    TransformUniforms t;
    LightingUniforms l;
  };
  template <class F> struct Varyings {
    Vec3<F> wPos, wNormal;
    Vec2<F> uv;
  };
  static constexpr uint32_t attributes = 0b111;

  template <class F> Vec4<F> vertex(const Uniforms& u, const VertexIn<F>& in, Varyings<F>& out) const {
    const Vec4<F> pos(in.attr[0].xyz(), F(1.0f));
    out.wPos = (u.t.M * pos).xyz();
    out.wNormal = (u.t.normal * Vec4<F>(in.attr[1].xyz(), F(0.0f))).xyz();
    out.uv = in.attr[2].xy();
    return u.t.MVP * pos;
  }
  template <class F> void fragment(const Uniforms& u, const Varyings<F>& v, Fragment<F>& f) const {
    const Radiance<F> r = illuminate(u.l, v.wPos, normalize(v.wNormal));
    Vec3<F> c = r.ambient_diffuse;
    if (u.l.textured) c = c * texture(u.l.tex, v.uv).xyz();
    f.color[0] = Vec4<F>(c + r.specular, F(1.0f));
  }
};

}  // namespace

void GouraudShader::draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const {
  ctx.draw(GouraudGpu{}, GouraudGpu::Uniforms{transforms(state), lighting(state)}, geometry.layout(), state.pipeline,
           geometry.draw_call());
}

void PhongShader::draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const {
  ctx.draw(PhongGpu{}, PhongGpu::Uniforms{transforms(state), lighting(state)}, geometry.layout(), state.pipeline,
           geometry.draw_call());
}

}  // namespace tessel::scene
