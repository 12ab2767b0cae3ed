// The shader library: each scene::Shader fills the uniforms of a GPU shader (a struct with
// vertex() and fragment() on lanes, compiled here) from the RenderState and submits the draw.
#include "tessel/scene/shaders.hpp"

#include <array>
#include <cmath>

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
  bool phong_specular = false;  // Specular::Phong: R.V instead of N.H
  glm::vec3 eye{0.0f};
  bool textured = false;
  Sampler2D tex;
  // Shadow mapping (PhongShader): the light whose Le the map scales, its matrix, the kernel.
  int shadow_light = -1;
  glm::mat4 light_VP{1.0f};
  Sampler2DShadow shadow;
  int pcf = 0;
  float texel = 0.0f;
  bool cube = false;
  glm::vec3 cube_light{0.0f};
  std::array<Sampler2DShadow, 6> cube_maps{};
  std::array<glm::mat4, 6> cube_VP{};
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
  u.phong_specular = m.specular == Specular::Phong;
  u.eye = s.wEye;
  u.textured = m.texture != nullptr;
  u.tex.texture = m.texture.get();
  u.tex.state.min_filter = Filter::LinearMipmapLinear;
  u.tex.state.mag_filter = Filter::Linear;
  if (s.shadow_map) {
    u.shadow_light = s.shadow_light;
    u.light_VP = s.light_VP;
    u.shadow.texture = s.shadow_map;
    // Outside the map is lit: the border (depth 1) passes every reference up to the far plane.
    u.shadow.state.wrap_s = u.shadow.state.wrap_t = Wrap::ClampToBorder;
    u.shadow.state.border_color = glm::vec4(1.0f);
    u.pcf = s.pcf;
    u.texel = 1.0f / float(s.shadow_map->width());
    if (s.cube_shadow) {
      u.cube = true;
      u.cube_light = s.cube_light;
      u.cube_VP = s.cube_VP;
      // A tap always lands on the face its direction picks, at most half a texel from
      // its edge: the edge texel, not the border, is its neighbour there.
      for (size_t f = 0; f < 6; ++f) {
        u.cube_maps[f] = u.shadow;
        u.cube_maps[f].state.wrap_s = u.cube_maps[f].state.wrap_t = Wrap::ClampToEdge;
        u.cube_maps[f].texture = s.cube_maps[f];
      }
    }
  }
  return u;
}

// The cube face a direction from the light falls in: the largest coordinate (GL 4.6 table
// 8.19), faces in GL's order +X, -X, +Y, -Y, +Z, -Z.
int cube_face(const glm::vec3& d) {
  const glm::vec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
  return d.z >= 0.0f ? 4 : 5;
}

// A point light's cube of maps. Each PCF tap is a point beside p, one texel of p's face
// apart along that face's two axes, and is looked up on the face its own direction falls
// in, so taps past a face's edge continue on the neighbouring face instead of reading as
// lit. The depth compared is always p's own, as that face sees it: a tap is off the
// receiver (in p's image plane, not on its surface), and its own depth on a face that sees
// the surface edge-on would fall behind the surface and shadow it.
template <class F>
F cube_visibility(const LightingUniforms& u, const Vec3<F>& p) {
  F vis(1.0f);
  const float n = float((2 * u.pcf + 1) * (2 * u.pcf + 1));
  for (int l = 0; l < lane_width<F>; ++l) {
    const glm::vec3 wp(p.x[l], p.y[l], p.z[l]), d = wp - u.cube_light;
    const int face = cube_face(d), major = face / 2;
    // A texel of a 90-degree face at the distance of p along the face's axis.
    const float step = 2.0f * std::fabs(d[major]) * u.texel;
    glm::vec3 ea(0.0f), eb(0.0f);
    ea[(major + 1) % 3] = step;
    eb[(major + 2) % 3] = step;
    // Per face a tap reaches: p and the two steps through that face's matrix (a tap's clip
    // position is then q0 + i qa + j qb), and p's depth there (2: beyond the far plane or
    // behind the light, lit). Computed when a tap first lands on the face.
    struct FaceView {
      bool ready = false;
      glm::vec4 q0, qa, qb;
      float ref;
    };
    FaceView views[6];
    float sum = 0.0f;
    for (int j = -u.pcf; j <= u.pcf; ++j)
      for (int i = -u.pcf; i <= u.pcf; ++i) {
        const int f = cube_face(d + float(i) * ea + float(j) * eb);
        FaceView& fv = views[f];
        if (!fv.ready) {
          const glm::mat4& VP = u.cube_VP[size_t(f)];
          fv.q0 = VP * glm::vec4(wp, 1.0f);
          fv.qa = VP * glm::vec4(ea, 0.0f);
          fv.qb = VP * glm::vec4(eb, 0.0f);
          const float z = fv.q0.z / fv.q0.w * 0.5f + 0.5f;
          fv.ref = fv.q0.w > 0.0f && z <= 1.0f ? z : 2.0f;
          fv.ready = true;
        }
        if (fv.ref > 1.0f) {
          sum += 1.0f;
          continue;
        }
        const glm::vec4 q = fv.q0 + float(i) * fv.qa + float(j) * fv.qb;
        sum += detail::sample_2d_compare(u.cube_maps[size_t(f)], q.x / q.w * 0.5f + 0.5f,
                                         q.y / q.w * 0.5f + 0.5f, fv.ref, 0.0f);
      }
    vis[l] = sum / n;
  }
  return vis;
}

// The fraction of the shadow map's percentage-closer compares that see p from the light.
template <class F>
F shadow_visibility(const LightingUniforms& u, const Vec3<F>& p) {
  const Vec4<F> q = u.light_VP * Vec4<F>(p, F(1.0f));
  const F inv = F(1.0f) / q.w;
  const F x = q.x * inv * F(0.5f) + F(0.5f), y = q.y * inv * F(0.5f) + F(0.5f),
          z = q.z * inv * F(0.5f) + F(0.5f);
  F sum(0.0f);
  for (int j = -u.pcf; j <= u.pcf; ++j)
    for (int i = -u.pcf; i <= u.pcf; ++i)
      sum = sum + texture(u.shadow, Vec3<F>(x + F(float(i) * u.texel), y + F(float(j) * u.texel), z));
  const float n = float((2 * u.pcf + 1) * (2 * u.pcf + 1));
  // Beyond the light's far plane or behind it: nothing to compare with, lit.
  return select((z > F(1.0f)) | (q.w <= F(0.0f)), F(1.0f), sum * F(1.0f / n));
}

TransformUniforms transforms(const RenderState& s) { return {s.P * s.V * s.M, s.M, glm::transpose(s.Minv)}; }

// The two parts of the notes' formula at a point: ambient + diffuse (to be multiplied by the
// texture) and specular.
template <class F>
struct Radiance {
  Vec3<F> ambient_diffuse, specular;
};

// The cosine the specular exponent applies to (before max(., 0)): Phong's R.V, R the light
// direction mirrored about N, or Blinn's N.H.
template <class F>
F specular_cosine(const Vec3<F>& N, const Vec3<F>& L, const Vec3<F>& V, bool phong) {
  return phong ? dot(reflect(-L, N), V) : dot(N, normalize(L + V));
}

template <class F>
Radiance<F> illuminate(const LightingUniforms& u, const Vec3<F>& p, const Vec3<F>& N,
                       const F* visibility = nullptr) {
  const Vec3<F> V = normalize(Vec3<F>(u.eye) - p);
  Radiance<F> r{Vec3<F>(F(0.0f)), Vec3<F>(F(0.0f))};
  for (int i = 0; i < u.count; ++i) {
    const Light& l = u.lights[size_t(i)];
    // The notes' homogeneous light direction: light.xyz - p light.w (w = 0: directional).
    const Vec3<F> L = normalize(Vec3<F>(glm::vec3(l.wLightPos)) - p * F(l.wLightPos.w));
    F spot(1.0f);
    if (l.spot_cos_cutoff > -1.0f) {
      const F c = dot(-L, Vec3<F>(glm::normalize(l.spot_direction)));
      spot = select(c >= F(l.spot_cos_cutoff),
                    l.spot_exponent == 0.0f ? F(1.0f) : pow(max(c, F(0.0f)), F(l.spot_exponent)), F(0.0f));
    }
    const F cost = max(dot(N, L), F(0.0f));
    const F cosd =
        select(cost > F(0.0f), pow(max(specular_cosine(N, L, V, u.phong_specular), F(0.0f)), F(u.shininess)),
               F(0.0f));
    if (l.wLightPos.w != 0.0f &&
        (l.attenuation.y != 0.0f || l.attenuation.z != 0.0f || l.attenuation.x != 1.0f)) {
      const Vec3<F> d = Vec3<F>(glm::vec3(l.wLightPos) / l.wLightPos.w) - p;
      const F d2 = dot(d, d);
      spot = spot / (F(l.attenuation.x) + F(l.attenuation.y) * sqrt(d2) + F(l.attenuation.z) * d2);
    }
    if (visibility && i == u.shadow_light) spot = spot * *visibility;
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
  template <class F>
  struct Varyings {
    Vec3<F> ambient_diffuse, specular;
    Vec2<F> uv;
  };
  static constexpr uint32_t attributes = 0b111;

  template <class F>
  Vec4<F> vertex(const Uniforms& u, const VertexIn<F>& in, Varyings<F>& out) const {
    const Vec4<F> pos(in.attr[0].xyz(), F(1.0f));
    const Vec3<F> p = (u.t.M * pos).xyz();
    const Vec3<F> N = normalize((u.t.normal * Vec4<F>(in.attr[1].xyz(), F(0.0f))).xyz());
    const Radiance<F> r = illuminate(u.l, p, N);
    out.ambient_diffuse = r.ambient_diffuse;
    out.specular = r.specular;
    out.uv = in.attr[2].xy();
    return u.t.MVP * pos;
  }
  template <class F>
  void fragment(const Uniforms& u, const Varyings<F>& v, Fragment<F>& f) const {
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
  template <class F>
  struct Varyings {
    Vec3<F> wPos, wNormal;
    Vec2<F> uv;
  };
  static constexpr uint32_t attributes = 0b111;

  template <class F>
  Vec4<F> vertex(const Uniforms& u, const VertexIn<F>& in, Varyings<F>& out) const {
    const Vec4<F> pos(in.attr[0].xyz(), F(1.0f));
    out.wPos = (u.t.M * pos).xyz();
    out.wNormal = (u.t.normal * Vec4<F>(in.attr[1].xyz(), F(0.0f))).xyz();
    out.uv = in.attr[2].xy();
    return u.t.MVP * pos;
  }
  template <class F>
  void fragment(const Uniforms& u, const Varyings<F>& v, Fragment<F>& f) const {
    Radiance<F> r;
    if (u.l.shadow_light >= 0) {
      const F vis = u.l.cube ? cube_visibility(u.l, v.wPos) : shadow_visibility(u.l, v.wPos);
      r = illuminate(u.l, v.wPos, normalize(v.wNormal), &vis);
    } else {
      r = illuminate(u.l, v.wPos, normalize(v.wNormal));
    }
    Vec3<F> c = r.ambient_diffuse;
    if (u.l.textured) c = c * texture(u.l.tex, v.uv).xyz();
    f.color[0] = Vec4<F>(c + r.specular, F(1.0f));
  }
};

struct NormalMapGpu {
  struct Uniforms {
    TransformUniforms t;
    LightingUniforms l;
    bool mapped = false;
    Sampler2D normal_map;
  };
  template <class F>
  using Varyings = PhongGpu::Varyings<F>;
  static constexpr uint32_t attributes = 0b111;
  template <class F>
  Vec4<F> vertex(const Uniforms& u, const VertexIn<F>& in, Varyings<F>& out) const {
    return PhongGpu{}.vertex(PhongGpu::Uniforms{u.t, u.l}, in, out);
  }
  template <class F>
  void fragment(const Uniforms& u, const Varyings<F>& v, Fragment<F>& f) const {
    Vec3<F> N = normalize(v.wNormal);
    if (u.mapped) {
      // The cotangent frame of the surface at the pixel from the derivatives of position and
      // uv (it needs no tangents in the mesh), scaled so that the larger axis has length 1.
      const Vec3<F> dp1 = dFdx(v.wPos), dp2 = dFdy(v.wPos);
      const Vec2<F> duv1 = dFdx(v.uv), duv2 = dFdy(v.uv);
      const Vec3<F> dp2perp = cross(dp2, N), dp1perp = cross(N, dp1);
      const Vec3<F> T = dp2perp * duv1.x + dp1perp * duv2.x;
      const Vec3<F> B = dp2perp * duv1.y + dp1perp * duv2.y;
      const F m = max(dot(T, T), dot(B, B));
      const F inv = select(m > F(0.0f), inversesqrt(m), F(0.0f));
      const Vec3<F> t = texture(u.normal_map, v.uv).xyz() * F(2.0f) - Vec3<F>(F(1.0f));
      const Vec3<F> mapped = T * (t.x * inv) + B * (t.y * inv) + N * t.z;
      // Where the frame is degenerate (uv constant over the quad) keep the interpolated normal.
      const auto ok = m > F(0.0f);
      const Vec3<F> n = normalize(mapped);
      N = Vec3<F>(select(ok, n.x, N.x), select(ok, n.y, N.y), select(ok, n.z, N.z));
    }
    const Radiance<F> r = illuminate(u.l, v.wPos, N);
    Vec3<F> c = r.ambient_diffuse;
    if (u.l.textured) c = c * texture(u.l.tex, v.uv).xyz();
    f.color[0] = Vec4<F>(c + r.specular, F(1.0f));
  }
};

// The notes' NPR shader: quantized diffuse light and a black silhouette.
struct NprGpu {
  struct Uniforms {
    TransformUniforms t;
    LightingUniforms l;
    float bands = 2.0f, silhouette = 0.2f;
  };
  template <class F>
  using Varyings = PhongGpu::Varyings<F>;
  static constexpr uint32_t attributes = 0b111;

  template <class F>
  Vec4<F> vertex(const Uniforms& u, const VertexIn<F>& in, Varyings<F>& out) const {
    return PhongGpu{}.vertex(PhongGpu::Uniforms{u.t, u.l}, in, out);
  }
  template <class F>
  void fragment(const Uniforms& u, const Varyings<F>& v, Fragment<F>& f) const {
    const Vec3<F> N = normalize(v.wNormal), V = normalize(Vec3<F>(u.l.eye) - v.wPos);
    F y(1.0f);
    if (u.l.count > 0) {
      const glm::vec4 lp = u.l.lights[0].wLightPos;
      const Vec3<F> L = normalize(Vec3<F>(glm::vec3(lp)) - v.wPos * F(lp.w));
      const F d = max(dot(N, L), F(0.0f));
      // Two bands are the notes' (1 above 0.5, 0.5 below); n bands step evenly up to 1.
      y = u.bands <= 2.0f ? select(d > F(0.5f), F(1.0f), F(0.5f))
                          : (floor(d * F(u.bands)) + F(1.0f)) * F(1.0f / u.bands);
      y = min(y, F(1.0f));
    }
    Vec3<F> c = Vec3<F>(u.l.kd) * y;
    if (u.l.textured) c = c * texture(u.l.tex, v.uv).xyz();
    const auto outline = abs(dot(N, V)) < F(u.silhouette);
    f.color[0] = Vec4<F>(select(outline, F(0.0f), c.x), select(outline, F(0.0f), c.y),
                         select(outline, F(0.0f), c.z), F(1.0f));
  }
};

struct DepthGpu {
  struct Uniforms {
    glm::mat4 MVP{1.0f}, MV{1.0f};
    float near = 0.1f, far = 100.0f;
  };
  template <class F>
  struct Varyings {
    F eye_depth;
  };
  static constexpr uint32_t attributes = 0b1;
  template <class F>
  Vec4<F> vertex(const Uniforms& u, const VertexIn<F>& in, Varyings<F>& out) const {
    const Vec4<F> pos(in.attr[0].xyz(), F(1.0f));
    out.eye_depth = -(u.MV * pos).z;
    return u.MVP * pos;
  }
  template <class F>
  void fragment(const Uniforms& u, const Varyings<F>& v, Fragment<F>& f) const {
    const F g = clamp((F(u.far) - v.eye_depth) * F(1.0f / (u.far - u.near)), F(0.0f), F(1.0f));
    f.color[0] = Vec4<F>(g, g, g, F(1.0f));
  }
};

struct NormalGpu {
  struct Uniforms {
    TransformUniforms t;
  };
  template <class F>
  struct Varyings {
    Vec3<F> wNormal;
  };
  static constexpr uint32_t attributes = 0b11;
  template <class F>
  Vec4<F> vertex(const Uniforms& u, const VertexIn<F>& in, Varyings<F>& out) const {
    const Vec4<F> pos(in.attr[0].xyz(), F(1.0f));
    out.wNormal = (u.t.normal * Vec4<F>(in.attr[1].xyz(), F(0.0f))).xyz();
    return u.t.MVP * pos;
  }
  template <class F>
  void fragment(const Uniforms&, const Varyings<F>& v, Fragment<F>& f) const {
    const Vec3<F> n = normalize(v.wNormal) * F(0.5f) + Vec3<F>(F(0.5f));
    f.color[0] = Vec4<F>(n, F(1.0f));
  }
};

struct DepthOnlyGpu {
  struct Uniforms {
    glm::mat4 MVP{1.0f};
  };
  template <class F>
  struct Varyings {};
  static constexpr uint32_t attributes = 0b1;
  template <class F>
  Vec4<F> vertex(const Uniforms& u, const VertexIn<F>& in, Varyings<F>&) const {
    return u.MVP * Vec4<F>(in.attr[0].xyz(), F(1.0f));
  }
  template <class F>
  void fragment(const Uniforms&, const Varyings<F>&, Fragment<F>&) const {}
};

struct FlatGpu {
  struct Uniforms {
    glm::mat4 MVP{1.0f};
    glm::vec3 color{0.0f};
  };
  template <class F>
  struct Varyings {};
  static constexpr uint32_t attributes = 0b1;
  template <class F>
  Vec4<F> vertex(const Uniforms& u, const VertexIn<F>& in, Varyings<F>&) const {
    return u.MVP * Vec4<F>(in.attr[0].xyz(), F(1.0f));
  }
  template <class F>
  void fragment(const Uniforms& u, const Varyings<F>&, Fragment<F>& f) const {
    f.color[0] = Vec4<F>(Vec3<F>(u.color), F(1.0f));
  }
};

struct GBufferGpu {
  struct Uniforms {
    TransformUniforms t;
    LightingUniforms l;
  };
  template <class F>
  using Varyings = PhongGpu::Varyings<F>;
  static constexpr uint32_t attributes = 0b111;
  static constexpr int outputs = 6;
  template <class F>
  Vec4<F> vertex(const Uniforms& u, const VertexIn<F>& in, Varyings<F>& out) const {
    return PhongGpu{}.vertex(PhongGpu::Uniforms{u.t, u.l}, in, out);
  }
  template <class F>
  void fragment(const Uniforms& u, const Varyings<F>& v, Fragment<F>& f) const {
    Vec3<F> tex(F(1.0f));
    if (u.l.textured) tex = texture(u.l.tex, v.uv).xyz();
    f.color[0] = Vec4<F>(v.wPos, F(u.l.shininess));
    f.color[1] = Vec4<F>(normalize(v.wNormal), F(1.0f));
    f.color[2] = Vec4<F>(Vec3<F>(u.l.kd) * tex, F(1.0f));
    f.color[3] = Vec4<F>(Vec3<F>(u.l.ks), F(u.l.phong_specular ? 0.0f : 1.0f));  // alpha: Blinn
    f.color[4] = Vec4<F>(Vec3<F>(u.l.ka) * tex, F(1.0f));
    f.color[5] = Vec4<F>(Vec3<F>(u.l.emission), F(1.0f));
  }
};

struct DeferredLightGpu {
  struct Uniforms {
    std::array<Sampler2D, 6> g;
    std::array<Light, kMaxDeferredLights> lights{};
    int count = 0;
    glm::vec3 eye{0.0f};
    glm::vec4 background{0.0f};
    bool phong_specular = false;  // some pixel's material takes Phong's R.V (ks's alpha 0)
  };
  template <class F>
  struct Varyings {};
  static constexpr uint32_t attributes = 0b1;
  template <class F>
  Vec4<F> vertex(const Uniforms&, const VertexIn<F>& in, Varyings<F>&) const {
    return Vec4<F>(in.attr[0].x, in.attr[0].y, F(0.0f), F(1.0f));
  }
  template <class F>
  void fragment(const Uniforms& u, const Varyings<F>&, Fragment<F>& f) const {
    const IntOf<F> x = to_int(f.coord.x), y = to_int(f.coord.y);
    const Vec4<F> g0 = texelFetch(u.g[0], x, y, 0), g1 = texelFetch(u.g[1], x, y, 0);
    const Vec4<F> g3 = texelFetch(u.g[3], x, y, 0);
    const Vec3<F> kd = texelFetch(u.g[2], x, y, 0).xyz(), ks = g3.xyz();
    const auto blinn = g3.w > F(0.5f);
    const Vec3<F> ka = texelFetch(u.g[4], x, y, 0).xyz(), em = texelFetch(u.g[5], x, y, 0).xyz();
    const Vec3<F> p = g0.xyz(), N = g1.xyz();
    const F shine = g0.w;
    const Vec3<F> V = normalize(Vec3<F>(u.eye) - p);
    Vec3<F> c = em;
    for (int i = 0; i < u.count; ++i) {
      const Light& l = u.lights[size_t(i)];
      const Vec3<F> L = normalize(Vec3<F>(glm::vec3(l.wLightPos)) - p * F(l.wLightPos.w));
      F k(1.0f);
      if (l.wLightPos.w != 0.0f &&
          (l.attenuation.y != 0.0f || l.attenuation.z != 0.0f || l.attenuation.x != 1.0f)) {
        const Vec3<F> d = Vec3<F>(glm::vec3(l.wLightPos) / l.wLightPos.w) - p;
        const F d2 = dot(d, d);
        k = F(1.0f) / (F(l.attenuation.x) + F(l.attenuation.y) * sqrt(d2) + F(l.attenuation.z) * d2);
      }
      if (l.spot_cos_cutoff > -1.0f) {
        const F cs = dot(-L, Vec3<F>(glm::normalize(l.spot_direction)));
        k = k * select(cs >= F(l.spot_cos_cutoff),
                       l.spot_exponent == 0.0f ? F(1.0f) : pow(max(cs, F(0.0f)), F(l.spot_exponent)),
                       F(0.0f));
      }
      const F cost = max(dot(N, L), F(0.0f));
      // The specular model and the shininess differ per pixel here: pow of a lane vector.
      F sc = specular_cosine(N, L, V, false);
      if (u.phong_specular) sc = select(blinn, sc, specular_cosine(N, L, V, true));
      const F cosd = select(cost > F(0.0f), pow(max(sc, F(1e-30f)), shine), F(0.0f));
      c = c + ka * Vec3<F>(l.La) + (kd * cost + ks * cosd) * (Vec3<F>(l.Le) * k);
    }
    const auto empty = g1.w == F(0.0f);
    f.color[0] = Vec4<F>(select(empty, F(u.background.r), c.x), select(empty, F(u.background.g), c.y),
                         select(empty, F(u.background.b), c.z), select(empty, F(u.background.a), F(1.0f)));
  }
};

}  // namespace

void draw_gbuffer(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) {
  ctx.draw(GBufferGpu{}, GBufferGpu::Uniforms{transforms(state), lighting(state)}, geometry.layout(),
           state.pipeline, geometry.draw_call());
}

void draw_deferred_lighting(gpu::Context& ctx, const std::vector<const gpu::Texture2D*>& gbuffer,
                            const std::vector<Light>& lights, const glm::vec3& eye,
                            const glm::vec4& background, bool phong_specular) {
  auto u = std::make_unique<DeferredLightGpu::Uniforms>();
  for (size_t i = 0; i < 6 && i < gbuffer.size(); ++i) {
    u->g[i].texture = gbuffer[i];
    u->g[i].state.min_filter = Filter::Nearest;
    u->g[i].state.mag_filter = Filter::Nearest;
  }
  u->count = int(std::min<size_t>(lights.size(), kMaxDeferredLights));
  for (int i = 0; i < u->count; ++i) u->lights[size_t(i)] = lights[size_t(i)];
  u->eye = eye;
  u->background = background;
  u->phong_specular = phong_specular;
  // One triangle that covers the viewport.
  static const float tri[6] = {-1.0f, -1.0f, 3.0f, -1.0f, -1.0f, 3.0f};
  const Buffer vb(tri, sizeof tri);
  VertexLayout layout;
  layout.attrib(0, vb, 2, AttribType::F32, 8, 0);
  gpu::RenderState pass;
  ctx.draw(DeferredLightGpu{}, *u, layout, pass, DrawCall{.topology = Topology::Triangles, .count = 3});
}

void draw_flat(gpu::Context& ctx, const glm::mat4& MVP, const glm::vec3& color, const Geometry& geometry,
               const gpu::RenderState& pipeline) {
  ctx.draw(FlatGpu{}, FlatGpu::Uniforms{MVP, color}, geometry.layout(), pipeline, geometry.draw_call());
}

void draw_shadow_depth(gpu::Context& ctx, const glm::mat4& MVP, const Geometry& geometry,
                       const gpu::RenderState& pipeline) {
  ctx.draw(DepthOnlyGpu{}, DepthOnlyGpu::Uniforms{MVP}, geometry.layout(), pipeline, geometry.draw_call());
}

void NormalMapShader::draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const {
  NormalMapGpu::Uniforms u{transforms(state), lighting(state), false, {}};
  if (state.material && state.material->normal_map) {
    u.mapped = true;
    u.normal_map.texture = state.material->normal_map.get();
    u.normal_map.state.min_filter = Filter::LinearMipmapLinear;
    u.normal_map.state.mag_filter = Filter::Linear;
  }
  ctx.draw(NormalMapGpu{}, u, geometry.layout(), state.pipeline, geometry.draw_call());
}

void NprShader::draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const {
  NprGpu::Uniforms u{transforms(state), lighting(state), float(bands_), silhouette_};
  ctx.draw(NprGpu{}, u, geometry.layout(), state.pipeline, geometry.draw_call());
}

void DepthShader::draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const {
  DepthGpu::Uniforms u{state.P * state.V * state.M, state.V * state.M, range_ ? from_ : state.near,
                       range_ ? to_ : state.far};
  ctx.draw(DepthGpu{}, u, geometry.layout(), state.pipeline, geometry.draw_call());
}

void NormalShader::draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const {
  ctx.draw(NormalGpu{}, NormalGpu::Uniforms{transforms(state)}, geometry.layout(), state.pipeline,
           geometry.draw_call());
}

void GouraudShader::draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const {
  ctx.draw(GouraudGpu{}, GouraudGpu::Uniforms{transforms(state), lighting(state)}, geometry.layout(),
           state.pipeline, geometry.draw_call());
}

void PhongShader::draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const {
  ctx.draw(PhongGpu{}, PhongGpu::Uniforms{transforms(state), lighting(state)}, geometry.layout(),
           state.pipeline, geometry.draw_call());
}

}  // namespace tessel::scene
