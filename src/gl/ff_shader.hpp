// Fixed-function OpenGL 1.x as a shader of the gpu layer.
//
// The vertex stage is GL 2.1 §2.11-2.14 (the GL 1.x pipeline, restated there): transform to
// eye and clip space, the normal by the inverse transpose (GL_NORMALIZE, GL_RESCALE_NORMAL),
// the lighting equation of §2.14.1 for up to eight lights with colour material (§2.14.3), or
// the current colour when lighting is off, texture coordinate generation (§2.12.4) and the
// texture matrix. The fragment stage is texture environments (§3.8.13, Tables 3.20/3.21 of
// GL 1.5), fog (§3.10), polygon stipple (§3.5.2) and the alpha test (§4.1.4), all driven by
// uniforms. What must be known when the pipeline is built — flat shading (which varyings
// take the provoking vertex), whether a texture is read, whether fragments may be discarded
// (which decides early depth) — are template parameters; the GL layer picks one of the
// eight instances per draw.
#pragma once

#include <array>
#include <cstdint>
#include <type_traits>

#include "tessel/glsl/program.hpp"
#include "tessel/gpu/shader.hpp"
#include "tessel/gpu/texture.hpp"
#include "tessel/gpu/vec.hpp"

namespace tessel::gl {

// The vertex layout the GL layer writes (one interleaved float record per vertex).
struct FFVertex {
  float pos[4];
  float normal[3];
  float color[4];
  float tex[4];
  float edge;  // GL edge flag: 1 when the edge starting here is a boundary edge
};
static_assert(sizeof(FFVertex) == 16 * sizeof(float));

// The texture coordinate sets (GL_MAX_TEXTURE_COORDS) and fixed-function texture units
// (GL_MAX_TEXTURE_UNITS) of the compatibility context, as Mesa has them.
inline constexpr int kMaxTexCoords = glsl::kMaxTextureCoords;

// The attributes of a vertex beyond FFVertex's, carried only by draws that have them (GL 1.3
// multitexture §2.7, GL 1.4 secondary colour and fog coordinate): the texture coordinates of
// sets 1 to 7, the secondary colour and the fog coordinate.
struct FFExtra {
  float tex[kMaxTexCoords - 1][4];
  float secondary[4];
  float fog_coord;
  float pad_[3];
  // The values of a vertex given none of these: GL 2.1 Table 6.5's initial current values.
  static FFExtra defaults() {
    FFExtra e{};
    for (auto& t : e.tex) t[3] = 1.0f;
    e.secondary[3] = 1.0f;
    return e;
  }
};
static_assert(sizeof(FFExtra) == 36 * sizeof(float));

enum class TexEnv : uint8_t { Modulate, Replace, Decal, Blend, Add };
// The base internal format of a GL 1.x texture (what the environment tables distinguish).
enum class BaseFormat : uint8_t { Alpha, Luminance, LuminanceAlpha, Intensity, RGB, RGBA };
enum class TexGenMode : uint8_t { ObjectLinear, EyeLinear, SphereMap };
enum class FogMode : uint8_t { Linear, Exp, Exp2 };

struct FFLight {
  glm::vec4 position{0.0f, 0.0f, 1.0f, 0.0f};   // eye space (transformed when set)
  glm::vec3 spot_direction{0.0f, 0.0f, -1.0f};  // eye space
  float spot_exponent = 0.0f;
  float spot_cos_cutoff = -1.0f;  // cos(cutoff); cutoff 180 gives no spot at all
  bool spot = false;              // cutoff != 180
  float k0 = 1.0f, k1 = 0.0f, k2 = 0.0f;
  glm::vec4 ambient{0.0f, 0.0f, 0.0f, 1.0f}, diffuse{0.0f}, specular{0.0f};
  bool operator==(const FFLight&) const = default;
};

struct FFMaterial {
  glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1.0f}, diffuse{0.8f, 0.8f, 0.8f, 1.0f};
  glm::vec4 specular{0.0f, 0.0f, 0.0f, 1.0f}, emission{0.0f, 0.0f, 0.0f, 1.0f};
  float shininess = 0.0f;
  bool operator==(const FFMaterial&) const = default;
};

// Which material colours follow the current colour (glColorMaterial), as bits.
enum : uint8_t { kTrackAmbient = 1, kTrackDiffuse = 2, kTrackSpecular = 4, kTrackEmission = 8 };

struct FFUniforms {
  glm::mat4 mvp{1.0f}, modelview{1.0f};
  glm::mat3 normal_matrix{1.0f};
  float rescale = 1.0f;  // GL_RESCALE_NORMAL factor (1 when off)
  bool normalize = false;

  bool lighting = false, two_side = false, local_viewer = false;
  int light_count = 0;  // enabled lights, packed in order
  std::array<FFLight, 8> lights{};
  glm::vec4 model_ambient{0.2f, 0.2f, 0.2f, 1.0f};
  std::array<FFMaterial, 2> material{};  // front, back
  std::array<uint8_t, 2> track{};        // kTrack* bits per face (0 when COLOR_MATERIAL is off)

  // Texturing (unit 0).
  gpu::Sampler2D sampler;
  BaseFormat base_format = BaseFormat::RGBA;
  TexEnv env = TexEnv::Modulate;
  glm::vec4 env_color{0.0f};
  glm::mat4 texture_matrix{1.0f};
  bool identity_texture_matrix = true;
  std::array<bool, 4> texgen{};  // s, t, r, q
  std::array<TexGenMode, 4> texgen_mode{};
  std::array<glm::vec4, 4> object_plane{}, eye_plane{};  // eye planes already times MV^-1

  bool fog = false;
  FogMode fog_mode = FogMode::Exp;
  float fog_start = 0.0f, fog_end = 1.0f, fog_density = 1.0f;
  glm::vec4 fog_color{0.0f};

  bool alpha_test = false;
  gpu::CompareFunc alpha_func = gpu::CompareFunc::Always;
  float alpha_ref = 0.0f;

  bool stipple = false;
  std::array<uint32_t, 32> stipple_rows{};  // bit x of row y: pixel (x mod 32, y mod 32) drawn
};

// A vertex after the fixed-function vertex stage (feedback mode: post_vertex).
struct FFPostVertex {
  float pos[4];
  float back[4];
  float front[4];
  float tex[4];
  float edge, fog;
};

template <class F>
struct FFVaryings {
  gpu::Vec4<F> front, back;  // lit (or current) colour for front and back faces
  gpu::Vec4<F> tex;          // s, t, r, q after texgen and the texture matrix
  F fog;                     // eye distance |z_e| for fog
  F edge;                    // GL edge flag of the edge starting at this vertex (line mode)
};
inline constexpr int kEdgeFlagVarying = 13;  // offset of FFVaryings::edge in floats

// The varyings of draws that need only the front colour (no texture, fog, two-sided
// lighting or polygon-mode edges): a quarter of the interpolation and setup work.
template <class F>
struct FFLeanVaryings {
  gpu::Vec4<F> front;
};

namespace ffdetail {
using namespace ::tessel::gpu;

template <class F>
Vec4<F> pick(bool tracked, const Vec4<F>& color, const glm::vec4& fixed) {
  return tracked ? color : Vec4<F>(fixed);
}

// GL 2.1 §2.14.1, the lighting equation for one face; n faces the side being lit.
template <class F>
Vec4<F> light_face(const FFUniforms& u, int face, const Vec3<F>& V, const Vec3<F>& n, const Vec4<F>& color) {
  const FFMaterial& m = u.material[size_t(face)];
  const uint8_t tr = u.track[size_t(face)];
  const Vec4<F> ma = pick(tr & kTrackAmbient, color, m.ambient);
  const Vec4<F> md = pick(tr & kTrackDiffuse, color, m.diffuse);
  const Vec4<F> ms = pick(tr & kTrackSpecular, color, m.specular);
  const Vec4<F> me = pick(tr & kTrackEmission, color, m.emission);
  Vec3<F> c = me.xyz() + ma.xyz() * Vec3<F>(glm::vec3(u.model_ambient));
  Vec3<F> eye_dir;  // VP_e
  if (u.local_viewer)
    eye_dir = normalize(-V);
  else
    eye_dir = Vec3<F>(F(0.0f), F(0.0f), F(1.0f));
  const F zero(0.0f), one(1.0f);
  for (int i = 0; i < u.light_count; ++i) {
    const FFLight& L = u.lights[size_t(i)];
    Vec3<F> vp;
    F att = one;
    if (L.position.w != 0.0f) {
      const Vec3<F> d = Vec3<F>(glm::vec3(L.position) / L.position.w) - V;
      const F dist2 = dot(d, d);
      const F dist = sqrt(dist2);
      vp = d * (one / dist);
      if (L.k0 != 1.0f || L.k1 != 0.0f || L.k2 != 0.0f)
        att = one / (F(L.k0) + F(L.k1) * dist + F(L.k2) * dist2);
    } else {
      vp = Vec3<F>(glm::normalize(glm::vec3(L.position)));
    }
    if (L.spot) {
      const F sd = dot(-vp, Vec3<F>(glm::normalize(L.spot_direction)));
      const F s = select(sd >= F(L.spot_cos_cutoff), pow(max(sd, zero), F(L.spot_exponent)), zero);
      att = att * s;
    }
    const F ndl = max(dot(n, vp), zero);
    const Vec3<F> h = normalize(vp + eye_dir);
    const F ndh = max(dot(n, h), zero);
    const F spec = select(ndl > zero, pow(ndh, F(m.shininess)), zero);
    const Vec3<F> term = ma.xyz() * Vec3<F>(glm::vec3(L.ambient)) +
                         md.xyz() * Vec3<F>(glm::vec3(L.diffuse)) * ndl +
                         ms.xyz() * Vec3<F>(glm::vec3(L.specular)) * spec;
    c = c + term * att;
  }
  return Vec4<F>(clamp(c.x, zero, one), clamp(c.y, zero, one), clamp(c.z, zero, one), clamp(md.w, zero, one));
}

template <class F>
F texgen_coord(const FFUniforms& u, int i, const Vec4<F>& obj, const Vec4<F>& eye, const Vec3<F>& sphere,
               F given) {
  if (!u.texgen[size_t(i)]) return given;
  switch (u.texgen_mode[size_t(i)]) {
    case TexGenMode::ObjectLinear: return dot(obj, Vec4<F>(u.object_plane[size_t(i)]));
    case TexGenMode::EyeLinear: return dot(eye, Vec4<F>(u.eye_plane[size_t(i)]));
    case TexGenMode::SphereMap: return i == 0 ? sphere.x : i == 1 ? sphere.y : F(0.0f);
  }
  return given;
}
}  // namespace ffdetail

template <bool Flat, bool Textured, bool Discards, bool Lean = false>
struct FixedFunction {
  static_assert(!(Lean && Textured), "a textured draw needs its texture coordinates");
  using Uniforms = FFUniforms;
  template <class F>
  using Varyings = std::conditional_t<Lean, FFLeanVaryings<F>, FFVaryings<F>>;
  static constexpr uint64_t flat =
      Flat ? (Lean ? 0xFull : 0xFFull) : 0;  // the colours take the provoking vertex
  static constexpr bool discards = Discards;
  static constexpr uint32_t attributes = 0b11111;

  template <class F>
  gpu::Vec4<F> vertex(const Uniforms& u, const gpu::VertexIn<F>& in, Varyings<F>& out) const {
    using namespace ffdetail;
    const Vec4<F>& pos = in.attr[0];
    const Vec4<F>& color = in.attr[2];
    const Vec4<F> eye = u.modelview * pos;
    const bool need_normal =
        u.lighting ||
        (Textured && (u.texgen[0] || u.texgen[1]) &&
         (u.texgen_mode[0] == TexGenMode::SphereMap || u.texgen_mode[1] == TexGenMode::SphereMap));
    Vec3<F> n;
    if (need_normal) {
      n = u.normal_matrix * in.attr[1].xyz();
      if (u.normalize)
        n = normalize(n);
      else if (u.rescale != 1.0f)
        n = n * F(u.rescale);
    }
    if (u.lighting) {
      const Vec3<F> V = eye.xyz();
      out.front = light_face<F>(u, 0, V, n, color);
      if constexpr (!Lean) {
        if (u.two_side)
          out.back = light_face<F>(u, 1, V, -n, color);
        else
          out.back = out.front;
      }
    } else {
      const F zero(0.0f), one(1.0f);
      const Vec4<F> c(clamp(color.x, zero, one), clamp(color.y, zero, one), clamp(color.z, zero, one),
                      clamp(color.w, zero, one));
      out.front = c;
      if constexpr (!Lean) out.back = c;
    }
    if constexpr (Textured) {
      Vec4<F> t = in.attr[3];
      if (u.texgen[0] || u.texgen[1] || u.texgen[2] || u.texgen[3]) {
        Vec3<F> sphere;
        if ((u.texgen[0] && u.texgen_mode[0] == TexGenMode::SphereMap) ||
            (u.texgen[1] && u.texgen_mode[1] == TexGenMode::SphereMap)) {
          // GL 2.1 §2.12.4 eq. 2.4-2.6: the reflection of the eye vector about the normal.
          const Vec3<F> e = normalize(eye.xyz());
          const Vec3<F> nn = normalize(n);
          const Vec3<F> r = e - nn * (F(2.0f) * dot(nn, e));
          const F m = F(2.0f) * sqrt(r.x * r.x + r.y * r.y + (r.z + F(1.0f)) * (r.z + F(1.0f)));
          sphere = Vec3<F>(r.x / m + F(0.5f), r.y / m + F(0.5f), F(0.0f));
        }
        t = Vec4<F>(
            texgen_coord<F>(u, 0, pos, eye, sphere, t.x), texgen_coord<F>(u, 1, pos, eye, sphere, t.y),
            texgen_coord<F>(u, 2, pos, eye, sphere, t.z), texgen_coord<F>(u, 3, pos, eye, sphere, t.w));
      }
      if (!u.identity_texture_matrix) t = u.texture_matrix * t;
      out.tex = t;
    } else if constexpr (!Lean) {
      out.tex = Vec4<F>(F(0.0f));
    }
    if constexpr (!Lean) {
      out.fog = abs(eye.z);
      out.edge = in.attr[4].x;
    }
    return u.mvp * pos;
  }

  template <class F>
  void fragment(const Uniforms& u, const Varyings<F>& v, gpu::Fragment<F>& f) const {
    using namespace ffdetail;
    const F zero(0.0f), one(1.0f);
    Vec4<F> c = v.front;
    if constexpr (!Lean) {
      if (u.lighting && u.two_side) {
        const auto ff = f.front_facing;
        c = Vec4<F>(select(ff, v.front.x, v.back.x), select(ff, v.front.y, v.back.y),
                    select(ff, v.front.z, v.back.z), select(ff, v.front.w, v.back.w));
      }
    }
    if constexpr (Textured) {
      const F inv_q = one / v.tex.w;
      const F s = v.tex.x * inv_q, t = v.tex.y * inv_q;
      const Vec4<F> tc = texture(u.sampler, gpu::Vec2<F>(s, t));
      c = apply_env(u, c, tc);
    }
    if constexpr (!Lean) {
      if (u.fog) {
        F fac;
        switch (u.fog_mode) {
          case FogMode::Linear: fac = (F(u.fog_end) - v.fog) * F(1.0f / (u.fog_end - u.fog_start)); break;
          case FogMode::Exp: fac = exp(-F(u.fog_density) * v.fog); break;
          default: {
            const F d = F(u.fog_density) * v.fog;
            fac = exp(-(d * d));
            break;
          }
        }
        fac = clamp(fac, zero, one);
        const Vec3<F> fc(glm::vec3(u.fog_color));
        c = Vec4<F>(fc + (c.xyz() - fc) * fac, c.w);
      }
    }
    if constexpr (Discards) {
      if (u.alpha_test) f.discard(!gpu::compare(u.alpha_func, c.w, F(u.alpha_ref)));
      if (u.stipple) {
        using I = gpu::IntOf<F>;
        const I x = to_int(f.coord.x), y = to_int(f.coord.y);
        I bit;
        if constexpr (gpu::is_lanes<F>) {
          for (int l = 0; l < gpu::lane_width<F>; ++l)
            bit[l] = int32_t((u.stipple_rows[size_t(y[l] & 31)] >> (x[l] & 31)) & 1u);
        } else {
          bit = int32_t((u.stipple_rows[size_t(y & 31)] >> (x & 31)) & 1u);
        }
        f.discard(bit == I(0));
      }
    }
    f.color[0] = c;
  }

 private:
  // GL 1.5 Tables 3.22 and 3.23: how the texture colour (Ct, At) combines with the fragment's
  // (Cf, Af) for each base format.
  template <class F>
  static gpu::Vec4<F> apply_env(const Uniforms& u, const gpu::Vec4<F>& cf, const gpu::Vec4<F>& t) {
    using namespace ffdetail;
    const F one(1.0f), zero(0.0f);
    const BaseFormat b = u.base_format;
    const bool has_color = b != BaseFormat::Alpha;
    const bool has_alpha = b == BaseFormat::Alpha || b == BaseFormat::LuminanceAlpha ||
                           b == BaseFormat::Intensity || b == BaseFormat::RGBA;
    const Vec3<F> Cf = cf.xyz(), Ct = t.xyz();
    const F Af = cf.w, At = t.w;
    Vec3<F> C = Cf;
    F A = Af;
    switch (u.env) {
      case TexEnv::Replace:
        if (has_color) C = Ct;
        if (has_alpha) A = At;
        break;
      case TexEnv::Modulate:
        if (has_color) C = Cf * Ct;
        if (has_alpha) A = Af * At;
        break;
      case TexEnv::Decal:
        if (b == BaseFormat::RGB)
          C = Ct;
        else if (b == BaseFormat::RGBA)
          C = Cf * (one - At) + Ct * At;
        break;
      case TexEnv::Blend: {
        const Vec3<F> Cc(glm::vec3(u.env_color));
        if (has_color) C = Cf * (Vec3<F>(one) - Ct) + Cc * Ct;
        if (b == BaseFormat::Intensity)
          A = Af * (one - At) + F(u.env_color.w) * At;
        else if (has_alpha)
          A = Af * At;
        break;
      }
      case TexEnv::Add:
        if (has_color) C = Cf + Ct;
        if (b == BaseFormat::Intensity)
          A = Af + At;
        else if (has_alpha)
          A = Af * At;
        break;
    }
    return Vec4<F>(clamp(C.x, zero, one), clamp(C.y, zero, one), clamp(C.z, zero, one), clamp(A, zero, one));
  }
};

}  // namespace tessel::gl
