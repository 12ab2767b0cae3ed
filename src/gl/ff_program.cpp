// Fixed function as generated GLSL, for the state the C++ fixed-function shader (ff_shader.hpp)
// does not cover: texture units other than 0, 1D, 3D and cube map targets, depth textures
// compared (GL_TEXTURE_COMPARE_MODE), the reflection and normal map coordinate generation,
// the secondary colour (GL_COLOR_SUM, GL_SEPARATE_SPECULAR_COLOR) and the fog coordinate.
// This is how Mesa runs all of fixed function (its ff_fragment_shader and ffvertex_prog): the
// state that decides the code is a key, each key is one program written in GLSL 1.30 with the
// compatibility built-ins, compiled once and kept; the rest of the state (matrices, lights,
// materials, planes, fog) reaches it through the built-in uniforms, as it reaches any
// compatibility program (Context::feed_compat_state).
//
// The equations are those of the C++ shader (GL 2.1 §2.14.1 lighting, §2.12.4 coordinate
// generation, Tables 3.22/3.23 of GL 1.5 for the texture environments, §3.9 colour sum,
// §3.10 fog, §4.1.4 alpha test, §3.5.2 polygon stipple), unit after unit, each unit's result
// the next one's incoming colour (GL 1.3 §3.8.15).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "api.hpp"

namespace tessel::gl {

namespace {

// Targets as the key stores them.
enum : uint8_t { kNoTexture = 0, kTex1D, kTex2D, kTex3D, kTexCube };

const char* kStr = "STRQ";

// `base` followed by the digit i (units, lights and faces are below 10).
std::string name(const char* base, int i) {
  std::string s = base;
  s.push_back(char('0' + i));
  return s;
}

std::string light_function(const FFProgramKey& k, int face) {
  const char* mat = face ? "gl_BackMaterial" : "gl_FrontMaterial";
  const uint8_t tr = k.track[size_t(face)];
  auto comp = [&](uint8_t bit, const char* name) {
    return (tr & bit) ? std::string("col") : std::string(mat) + "." + name;
  };
  std::string s;
  s += "vec4 ff_light" + std::to_string(face) + "(vec3 V, vec3 n, vec4 col, out vec4 sec) {\n";
  s += "  vec4 ma = " + comp(kTrackAmbient, "ambient") + ";\n";
  s += "  vec4 md = " + comp(kTrackDiffuse, "diffuse") + ";\n";
  s += "  vec4 ms = " + comp(kTrackSpecular, "specular") + ";\n";
  s += "  vec4 me = " + comp(kTrackEmission, "emission") + ";\n";
  s += "  vec3 c = me.rgb + ma.rgb * gl_LightModel.ambient.rgb;\n";
  s += "  vec3 sp = vec3(0.0);\n";
  s += k.local_viewer ? "  vec3 eye_dir = normalize(-V);\n" : "  vec3 eye_dir = vec3(0.0, 0.0, 1.0);\n";
  for (int i = 0; i < kMaxLights; ++i) {
    if (!(k.lights & (1u << i))) continue;
    const std::string L = "gl_LightSource[" + std::to_string(i) + "]";
    s += "  {\n";
    s += "    vec3 vp;\n    float att = 1.0;\n";
    s += "    vec4 P = " + L + ".position;\n";
    s += "    if (P.w != 0.0) {\n";
    s += "      vec3 d = P.xyz / P.w - V;\n";
    s += "      float d2 = dot(d, d);\n      float dist = sqrt(d2);\n      vp = d * (1.0 / dist);\n";
    s += "      att = 1.0 / (" + L + ".constantAttenuation + " + L + ".linearAttenuation * dist + " + L +
         ".quadraticAttenuation * d2);\n";
    s += "    } else {\n      vp = normalize(P.xyz);\n    }\n";
    s += "    if (" + L + ".spotCutoff != 180.0) {\n";
    s += "      float sd = dot(-vp, normalize(" + L + ".spotDirection));\n";
    s += "      att *= sd >= " + L + ".spotCosCutoff ? pow(max(sd, 0.0), " + L + ".spotExponent) : 0.0;\n";
    s += "    }\n";
    s += "    float ndl = max(dot(n, vp), 0.0);\n";
    s += "    float ndh = max(dot(n, normalize(vp + eye_dir)), 0.0);\n";
    s += "    float f = ndl > 0.0 ? (" + std::string(mat) + ".shininess == 0.0 ? 1.0 : pow(ndh, " + mat +
         ".shininess)) : 0.0;\n";
    s += "    c += (ma.rgb * " + L + ".ambient.rgb + md.rgb * " + L + ".diffuse.rgb * ndl) * att;\n";
    s += "    sp += ms.rgb * " + L + ".specular.rgb * f * att;\n";
    s += "  }\n";
  }
  // GL 1.2 §2.13.1: with SEPARATE_SPECULAR_COLOR the specular terms are the secondary colour.
  if (k.separate_specular) {
    s += "  sec = vec4(clamp(sp, 0.0, 1.0), 0.0);\n";
  } else {
    s += "  c += sp;\n  sec = vec4(0.0);\n";
  }
  s += "  return vec4(clamp(c, 0.0, 1.0), clamp(md.a, 0.0, 1.0));\n}\n";
  return s;
}

std::string vertex_source(const FFProgramKey& k) {
  const char* q = k.flat ? "flat " : "";
  std::string s = "#version 130\n";
  s += std::string(q) + "out vec4 ff_front, ff_back, ff_front2, ff_back2;\n";
  s += "out float ff_fogc;\n";
  for (int u = 0; u < kMaxTexCoords; ++u)
    if (k.units[size_t(u)].target != kNoTexture) s += "out vec4 ff_tc" + std::to_string(u) + ";\n";
  s += "uniform float ff_rescale;\n";
  if (k.lighting) {
    s += light_function(k, 0);
    if (k.two_side) s += light_function(k, 1);
  }
  s += "void main() {\n";
  s += "  vec4 eye = gl_ModelViewMatrix * gl_Vertex;\n";
  s += "  gl_Position = ftransform();\n";
  s += "  vec3 n = gl_NormalMatrix * gl_Normal;\n";
  if (k.normalize)
    s += "  n = normalize(n);\n";
  else if (k.rescale)
    s += "  n *= ff_rescale;\n";
  if (k.lighting) {
    s += "  vec4 sec0, sec1;\n";
    s += "  ff_front = ff_light0(eye.xyz, n, gl_Color, sec0);\n";
    s += "  ff_front2 = sec0;\n";
    if (k.two_side) {
      s += "  ff_back = ff_light1(eye.xyz, -n, gl_Color, sec1);\n";
      s += "  ff_back2 = sec1;\n";
    } else {
      s += "  ff_back = ff_front;\n  ff_back2 = ff_front2;\n";
    }
  } else {
    s += "  ff_front = clamp(gl_Color, 0.0, 1.0);\n  ff_back = ff_front;\n";
    s += "  ff_front2 = clamp(gl_SecondaryColor, 0.0, 1.0);\n  ff_back2 = ff_front2;\n";
  }
  for (int u = 0; u < kMaxTexCoords; ++u) {
    const FFProgramKey::Unit& unit = k.units[size_t(u)];
    if (unit.target == kNoTexture) continue;
    const std::string us = std::to_string(u), idx = "[" + us + "]";
    s += "  {\n    vec4 t = gl_MultiTexCoord" + us + ";\n";
    bool sphere = false, reflect = false;
    for (int c = 0; c < 4; ++c) {
      sphere |= unit.gen[size_t(c)] == GL_SPHERE_MAP;
      reflect |= unit.gen[size_t(c)] == GL_REFLECTION_MAP;
    }
    if (sphere) {
      // GL 2.1 §2.12.4 eq. 2.4-2.6, as the C++ shader computes it.
      s += "    vec3 e = normalize(eye.xyz);\n    vec3 nn = normalize(n);\n";
      s += "    vec3 r = e - nn * (2.0 * dot(nn, e));\n";
      s += "    float m = 2.0 * sqrt(r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0));\n";
      s += "    vec2 sphere = r.xy / m + 0.5;\n";
    }
    if (reflect) s += "    vec3 refl = reflect(normalize(eye.xyz), n);\n";
    static const char* comp = "xyzw";
    for (int c = 0; c < 4; ++c) {
      const std::string dst = std::string("    t.") + comp[c] + " = ";
      const std::string plane = std::string(1, kStr[c]) + idx;
      switch (unit.gen[size_t(c)]) {
        case GL_OBJECT_LINEAR: s += dst + "dot(gl_Vertex, gl_ObjectPlane" + plane + ");\n"; break;
        case GL_EYE_LINEAR: s += dst + "dot(eye, gl_EyePlane" + plane + ");\n"; break;
        case GL_SPHERE_MAP: s += dst + (c == 0 ? "sphere.x" : c == 1 ? "sphere.y" : "0.0") + ";\n"; break;
        case GL_REFLECTION_MAP: s += dst + "refl." + comp[c] + ";\n"; break;
        case GL_NORMAL_MAP: s += dst + "n." + comp[c] + ";\n"; break;
        default: break;
      }
    }
    s += "    ff_tc" + us + " = gl_TextureMatrix" + idx + " * t;\n  }\n";
  }
  s += k.fog_coord ? "  ff_fogc = gl_FogCoord;\n" : "  ff_fogc = abs(eye.z);\n";
  s += "}\n";
  return s;
}

// GL 1.5 Tables 3.22 and 3.23: how a unit's texture colour t combines with the incoming c.
std::string env_code(const FFProgramKey::Unit& u, const std::string& cc) {
  const BaseFormat b = BaseFormat(u.base);
  const bool has_color = b != BaseFormat::Alpha;
  const bool has_alpha = b == BaseFormat::Alpha || b == BaseFormat::LuminanceAlpha ||
                         b == BaseFormat::Intensity || b == BaseFormat::RGBA;
  std::string s;
  switch (u.env) {
    case GL_REPLACE:
      if (has_color) s += "    c.rgb = t.rgb;\n";
      if (has_alpha) s += "    c.a = t.a;\n";
      break;
    case GL_DECAL:
      if (b == BaseFormat::RGB)
        s += "    c.rgb = t.rgb;\n";
      else if (b == BaseFormat::RGBA)
        s += "    c.rgb = c.rgb * (1.0 - t.a) + t.rgb * t.a;\n";
      break;
    case GL_BLEND:
      if (has_color) s += "    c.rgb = c.rgb * (vec3(1.0) - t.rgb) + " + cc + ".rgb * t.rgb;\n";
      if (b == BaseFormat::Intensity)
        s += "    c.a = c.a * (1.0 - t.a) + " + cc + ".a * t.a;\n";
      else if (has_alpha)
        s += "    c.a = c.a * t.a;\n";
      break;
    case GL_ADD:
      if (has_color) s += "    c.rgb = c.rgb + t.rgb;\n";
      if (b == BaseFormat::Intensity)
        s += "    c.a = c.a + t.a;\n";
      else if (has_alpha)
        s += "    c.a = c.a * t.a;\n";
      break;
    default:  // GL_MODULATE
      if (has_color) s += "    c.rgb = c.rgb * t.rgb;\n";
      if (has_alpha) s += "    c.a = c.a * t.a;\n";
      break;
  }
  s += "    c = clamp(c, 0.0, 1.0);\n";
  return s;
}

// GL 1.3 Table 3.24's operand of a GL_COMBINE source value `v` (rgb, or alpha).
std::string operand(const std::string& v, uint16_t op, bool rgb) {
  switch (op) {
    case GL_ONE_MINUS_SRC_COLOR: return "(vec3(1.0) - " + v + ".rgb)";
    case GL_SRC_ALPHA: return rgb ? "vec3(" + v + ".a)" : v + ".a";
    case GL_ONE_MINUS_SRC_ALPHA: return rgb ? "vec3(1.0 - " + v + ".a)" : "(1.0 - " + v + ".a)";
    default: return v + ".rgb";  // GL_SRC_COLOR
  }
}

// GL 1.3 Table 3.25's functions.
std::string combine_function(uint16_t f, const std::string a[3], bool rgb) {
  const std::string half = rgb ? "vec3(0.5)" : "0.5";
  switch (f) {
    case GL_REPLACE: return a[0];
    case GL_ADD: return "(" + a[0] + " + " + a[1] + ")";
    case GL_ADD_SIGNED: return "(" + a[0] + " + " + a[1] + " - " + half + ")";
    case GL_INTERPOLATE: return "(" + a[0] + " * " + a[2] + " + " + a[1] + " * (1.0 - " + a[2] + "))";
    case GL_SUBTRACT: return "(" + a[0] + " - " + a[1] + ")";
    case GL_DOT3_RGB:
    case GL_DOT3_RGBA: return "vec3(4.0 * dot(" + a[0] + " - vec3(0.5), " + a[1] + " - vec3(0.5)))";
    default: return "(" + a[0] + " * " + a[1] + ")";  // GL_MODULATE
  }
}

// GL_COMBINE of unit `u` (t its texture's colour, c the incoming colour, prim the primary).
std::string combine_code(const FFProgramKey& k, int u, const std::string& cc) {
  const FFProgramKey::Unit& unit = k.units[size_t(u)];
  auto source = [&](uint16_t src) -> std::string {
    switch (src) {
      case GL_CONSTANT: return cc;
      case GL_PRIMARY_COLOR: return "prim";
      case GL_PREVIOUS: return "c";
      case GL_TEXTURE: return name("t", u);
      default: {  // GL_TEXTUREi (GL 1.4 crossbar): a unit that does not texture gives (0, 0, 0, 1)
        const int i = int(src) - GL_TEXTURE0;
        if (i >= 0 && i < kMaxTexCoords && k.units[size_t(i)].target != kNoTexture) return name("t", i);
        return "vec4(0.0, 0.0, 0.0, 1.0)";
      }
    }
  };
  std::string rgb[3], alpha[3];
  for (int i = 0; i < 3; ++i) {
    rgb[i] = operand(source(unit.src_rgb[size_t(i)]), unit.op_rgb[size_t(i)], true);
    alpha[i] = operand(source(unit.src_alpha[size_t(i)]), unit.op_alpha[size_t(i)], false);
  }
  std::string s = "    vec3 rgb = " + combine_function(unit.combine_rgb, rgb, true) + ";\n";
  const std::string rs = std::to_string(int(unit.rgb_scale)) + ".0";
  if (unit.combine_rgb == GL_DOT3_RGBA) {
    // The dot product goes to alpha too, scaled as the colour is (as Mesa does).
    s += "    c = clamp(vec4(rgb, rgb.r) * " + rs + ", 0.0, 1.0);\n";
    return s;
  }
  s += "    float alpha = " + combine_function(unit.combine_alpha, alpha, false) + ";\n";
  s += "    c = clamp(vec4(rgb * " + rs + ", alpha * " + std::to_string(int(unit.alpha_scale)) +
       ".0), 0.0, 1.0);\n";
  return s;
}

std::string fragment_source(const FFProgramKey& k) {
  const char* q = k.flat ? "flat " : "";
  std::string s = "#version 130\n";
  s += std::string(q) + "in vec4 ff_front, ff_back, ff_front2, ff_back2;\n";
  s += "in float ff_fogc;\n";
  for (int u = 0; u < kMaxTexCoords; ++u) {
    const FFProgramKey::Unit& unit = k.units[size_t(u)];
    if (unit.target == kNoTexture) continue;
    const std::string us = std::to_string(u);
    s += "in vec4 ff_tc" + us + ";\n";
    const char* type = unit.target == kTex1D     ? "sampler1D"
                       : unit.target == kTex3D   ? "sampler3D"
                       : unit.target == kTexCube ? "samplerCube"
                                                 : (unit.shadow ? "sampler2DShadow" : "sampler2D");
    s += std::string("uniform ") + type + " ff_tex" + us + ";\n";
  }
  for (int u = 0; u < kMaxTexCoords; ++u)
    if (k.units[size_t(u)].bias) s += "uniform float ff_bias" + std::to_string(u) + ";\n";
  if (k.alpha_func) s += "uniform float ff_alpha_ref;\n";
  if (k.stipple) s += "uniform int ff_stipple[32];\n";
  s += "void main() {\n";
  if (k.stipple) {
    s += "  ivec2 sp = ivec2(gl_FragCoord.xy) & 31;\n";
    s += "  if (((ff_stipple[sp.y] >> sp.x) & 1) == 0) discard;\n";
  }
  if (k.lighting && k.two_side) {
    s += "  vec4 c = gl_FrontFacing ? ff_front : ff_back;\n";
    s += "  vec4 sec = gl_FrontFacing ? ff_front2 : ff_back2;\n";
  } else {
    s += "  vec4 c = ff_front;\n  vec4 sec = ff_front2;\n";
  }
  // Every unit's texture colour first (GL_COMBINE may read any unit's), then the
  // environments in unit order.
  s += "  vec4 prim = c;\n";
  for (int u = 0; u < kMaxTexCoords; ++u) {
    const FFProgramKey::Unit& unit = k.units[size_t(u)];
    if (unit.target == kNoTexture) continue;
    const std::string us = std::to_string(u), tex = "ff_tex" + us, t = "t" + us;
    // Point sprites with GL_COORD_REPLACE: (s, t, r, q) = (gl_PointCoord, 0, 1).
    const std::string tc = unit.coord_replace ? "vec4(gl_PointCoord, 0.0, 1.0)" : "ff_tc" + us;
    const std::string bias = unit.bias ? ", ff_bias" + us : "";
    switch (unit.target) {
      case kTex1D: s += "  vec4 " + t + " = textureProj(" + tex + ", " + tc + ".xw" + bias + ");\n"; break;
      case kTex3D: s += "  vec4 " + t + " = textureProj(" + tex + ", " + tc + bias + ");\n"; break;
      case kTexCube: s += "  vec4 " + t + " = texture(" + tex + ", " + tc + ".xyz" + bias + ");\n"; break;
      default:
        if (unit.shadow) {
          // The comparison's result as the depth texture mode says (ff_base_format).
          const std::string d = "textureProj(" + tex + ", " + tc + bias + ")";
          const BaseFormat b = BaseFormat(unit.base);
          s += "  float d" + us + " = " + d + ";\n";
          const std::string dv = "d" + us;
          s += "  vec4 " + t + " = " +
               (b == BaseFormat::Luminance   ? "vec4(" + dv + ", " + dv + ", " + dv + ", 1.0)"
                : b == BaseFormat::Intensity ? "vec4(" + dv + ")"
                : b == BaseFormat::Alpha     ? "vec4(0.0, 0.0, 0.0, " + dv + ")"
                                             : "vec4(" + dv + ", 0.0, 0.0, 1.0)") +
               ";\n";
        } else {
          s += "  vec4 " + t + " = textureProj(" + tex + ", " + tc + bias + ");\n";
        }
        break;
    }
  }
  for (int u = 0; u < kMaxTexCoords; ++u) {
    const FFProgramKey::Unit& unit = k.units[size_t(u)];
    if (unit.target == kNoTexture) continue;
    const std::string us = std::to_string(u), cc = "gl_TextureEnvColor[" + us + "]";
    s += "  {\n    vec4 t = t" + us + ";\n";
    s += unit.env == GL_COMBINE ? combine_code(k, u, cc) : env_code(unit, cc);
    s += "  }\n";
  }
  // GL 1.4 §3.9: the secondary colour is added when COLOR_SUM is on, and always with lighting
  // (it is zero there unless the specular colour is separate). The specification clamps the
  // sum; Mesa's generated shaders do not (fog then blends the unclamped colour, and the
  // framebuffer clamps): as Mesa, since its images are the reference.
  if (k.color_sum || k.lighting) s += "  c.rgb = c.rgb + sec.rgb;\n";
  if (k.fog) {
    switch (k.fog_mode) {
      case GL_LINEAR: s += "  float fog = (gl_Fog.end - ff_fogc) * gl_Fog.scale;\n"; break;
      case GL_EXP2: s += "  float fd = gl_Fog.density * ff_fogc;\n  float fog = exp(-(fd * fd));\n"; break;
      default: s += "  float fog = exp(-gl_Fog.density * ff_fogc);\n"; break;
    }
    s += "  fog = clamp(fog, 0.0, 1.0);\n";
    s += "  c.rgb = gl_Fog.color.rgb + (c.rgb - gl_Fog.color.rgb) * fog;\n";
  }
  if (k.alpha_func) {
    const char* op = nullptr;
    switch (k.alpha_func) {
      case GL_NEVER: s += "  discard;\n"; break;
      case GL_LESS: op = "<"; break;
      case GL_EQUAL: op = "=="; break;
      case GL_LEQUAL: op = "<="; break;
      case GL_GREATER: op = ">"; break;
      case GL_NOTEQUAL: op = "!="; break;
      case GL_GEQUAL: op = ">="; break;
      default: break;
    }
    if (op) s += std::string("  if (!(c.a ") + op + " ff_alpha_ref)) discard;\n";
  }
  s += "  gl_FragColor = c;\n}\n";
  return s;
}

}  // namespace

std::string FFProgramKey::bytes() const {
  return std::string(reinterpret_cast<const char*>(this), sizeof *this);
}

std::string ff_vertex_source(const FFProgramKey& k) { return vertex_source(k); }

// The fragment stage of fixed function after an application's vertex shader (a program
// without a fragment shader, GL 2.0 §2.15.4): the same code, reading the built-in varyings
// the vertex shader writes (gl_FrontColor and the rest arrive as gl_Color, gl_SecondaryColor,
// gl_TexCoord[] and gl_FogFragCoord) instead of the generated vertex shader's.
std::string ff_fragment_source_after_vertex_shader(const FFProgramKey& k) {
  const std::string generated = fragment_source(k);
  std::string s =
      "#version 130\n#define ff_front gl_Color\n#define ff_back gl_Color\n"
      "#define ff_front2 gl_SecondaryColor\n#define ff_back2 gl_SecondaryColor\n"
      "#define ff_fogc gl_FogFragCoord\n";
  for (int u = 0; u < kMaxTexCoords; ++u)
    s += "#define ff_tc" + std::to_string(u) + " gl_TexCoord[" + std::to_string(u) + "]\n";
  // The generated declarations of those inputs (whole lines "in ..." or "flat in ...") go.
  size_t at = generated.find('\n') + 1;  // past #version
  while (at < generated.size()) {
    const size_t end = generated.find('\n', at);
    const std::string line =
        generated.substr(at, end == std::string::npos ? std::string::npos : end - at + 1);
    if (line.rfind("in ", 0) != 0 && line.rfind("flat in ", 0) != 0) s += line;
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return s;
}
std::string ff_fragment_source(const FFProgramKey& k) { return fragment_source(k); }

// The texture a unit's fixed-function texturing reads: its highest enabled target (cube map,
// 3D, 2D, 1D; GL 2.1 §3.8.16), when that target's texture is complete (else the unit does not
// texture, §3.8.10).
TextureObject* Context::ff_texture(int unit, TexTarget& target) {
  const TextureUnitState& us = s.units[size_t(unit)];
  const std::pair<bool, TexTarget> order[4] = {{us.enabled_cube, TexTarget::Cube},
                                               {us.enabled_3d, TexTarget::T3D},
                                               {us.enabled_2d, TexTarget::T2D},
                                               {us.enabled_1d, TexTarget::T1D}};
  for (const auto& [on, t] : order) {
    if (!on) continue;
    target = t;
    TextureObject& tex = bound_texture(t, unit);
    if (!update_gpu_texture(*this, tex)) return nullptr;
    const bool has = t == TexTarget::Cube  ? bool(tex.cube)
                     : t == TexTarget::T3D ? bool(tex.tex3d)
                                           : bool(tex.tex2d);
    if (!has || !texture_complete(tex, sampler_params(unit, tex))) return nullptr;
    return &tex;
  }
  return nullptr;
}

// The key of the generated program for this state, and whether the draw needs it (the C++
// shader draws everything else).
bool Context::ff_program_key(PrimClass cls, FFProgramKey& k, TextureObject*& unit0) {
  k = FFProgramKey{};
  unit0 = nullptr;
  bool needed = false;
  for (int u = 0; u < kMaxTexCoords; ++u) {
    TexTarget target = TexTarget::T2D;
    TextureObject* tex = ff_texture(u, target);
    if (!tex) continue;
    if (u == 0) unit0 = tex;
    FFProgramKey::Unit& ku = k.units[size_t(u)];
    const TextureUnitState& us = s.units[size_t(u)];
    ku.target = target == TexTarget::T1D    ? kTex1D
                : target == TexTarget::T3D  ? kTex3D
                : target == TexTarget::Cube ? kTexCube
                                            : kTex2D;
    const TexBase base = tex->base_image().fmt.base;
    ku.shadow = (base == TexBase::Depth || base == TexBase::DepthStencil) &&
                sampler_params(u, *tex).compare_mode == GL_COMPARE_REF_TO_TEXTURE;
    ku.base = uint8_t(ff_base_format(*tex));
    ku.env = us.env_mode;
    for (int c = 0; c < 4; ++c)
      ku.gen[size_t(c)] = us.gen_enabled[size_t(c)] ? uint16_t(us.gen_mode[size_t(c)]) : uint16_t(0);
    if (us.env_mode == GL_COMBINE) {
      ku.combine_rgb = uint16_t(us.combine_rgb);
      ku.combine_alpha = uint16_t(us.combine_alpha);
      for (size_t i = 0; i < 3; ++i) {
        ku.src_rgb[i] = uint16_t(us.src_rgb[i]);
        ku.src_alpha[i] = uint16_t(us.src_alpha[i]);
        ku.op_rgb[i] = uint16_t(us.op_rgb[i]);
        ku.op_alpha[i] = uint16_t(us.op_alpha[i]);
      }
      ku.rgb_scale = uint8_t(us.rgb_scale);
      ku.alpha_scale = uint8_t(us.alpha_scale);
      needed = true;
    }
    ku.bias = us.lod_bias != 0.0f;
    ku.coord_replace = us.coord_replace && s.point.sprite && cls == PrimClass::Points;
    needed |= ku.bias || ku.coord_replace;
    if (u > 0 || target != TexTarget::T2D || ku.shadow) needed = true;
    for (int c = 0; c < 4; ++c)
      if (ku.gen[size_t(c)] == GL_REFLECTION_MAP || ku.gen[size_t(c)] == GL_NORMAL_MAP) needed = true;
  }
  const LightState& L = s.light;
  k.lighting = L.lighting;
  if (L.lighting) {
    k.two_side = L.two_side;
    k.local_viewer = L.local_viewer;
    k.separate_specular = L.separate_specular;
    for (int i = 0; i < kMaxLights; ++i)
      if (L.enabled[size_t(i)]) k.lights = uint8_t(k.lights | (1u << i));
    k.track = color_material_track(L);
    needed |= L.separate_specular;
  }
  k.normalize = s.transform.normalize;
  k.rescale = s.transform.rescale_normal && !s.transform.normalize;
  k.flat = L.shade_model == GL_FLAT;
  k.fog = s.fog.enabled;
  if (k.fog) {
    k.fog_mode = uint16_t(s.fog.mode);
    k.fog_coord = s.fog.coord_src == GL_FOG_COORD;
    needed |= k.fog_coord;
  }
  k.color_sum = s.fog.color_sum;
  needed |= k.color_sum;
  if (s.color.alpha_test && s.color.alpha_func != GL_ALWAYS) k.alpha_func = uint16_t(s.color.alpha_func);
  k.stipple = s.polygon.stipple && cls == PrimClass::Triangles;
  return needed;
}

// The uniforms of a generated program (key k) that are not compatibility state: the units'
// samplers and LOD biases, the rescale factor, the alpha reference, the polygon stipple. A
// uniform the program does not have (location -1) is left alone.
void Context::set_ff_uniforms(glsl::Program& p, const FFProgramKey& k) const {
  for (int u = 0; u < kMaxTexCoords; ++u) {
    if (k.units[size_t(u)].target == kNoTexture) continue;
    const int32_t unit = u;
    p.set_uniform(p.uniform_location("ff_tex" + std::to_string(u)), &unit, 1);
  }
  for (int u = 0; u < kMaxTexCoords; ++u) {
    if (!k.units[size_t(u)].bias) continue;
    // GL 1.4 §3.8.8: the unit's bias, clamped to GL_MAX_TEXTURE_LOD_BIAS.
    const float bias = std::clamp(s.units[size_t(u)].lod_bias, -16.0f, 16.0f);
    p.set_uniform(p.uniform_location("ff_bias" + std::to_string(u)), &bias, 1);
  }
  if (k.rescale) {
    const float f = rescale_factor(modelview());
    p.set_uniform(p.uniform_location("ff_rescale"), &f, 1);
  }
  if (k.alpha_func) {
    const float ref = std::clamp(s.color.alpha_ref, 0.0f, 1.0f);
    p.set_uniform(p.uniform_location("ff_alpha_ref"), &ref, 1);
  }
  if (k.stipple) {
    std::array<int32_t, 32> rows;
    for (size_t i = 0; i < 32; ++i) rows[i] = int32_t(s.polygon_stipple[i]);
    p.set_uniform(p.uniform_location("ff_stipple"), rows.data(), 1, 32);
  }
}

void Context::draw_ff_program(const FFProgramKey& k, const Batch& b, const gpu::Buffer& vbuf,
                              const gpu::Buffer& ib) {
  FFProgram& entry = ff_programs_[k.bytes()];
  if (!entry.program) {
    const auto vs = glsl::Shader::compile(glsl::Stage::Vertex, ff_vertex_source(k));
    const auto fs = glsl::Shader::compile(glsl::Stage::Fragment, ff_fragment_source(k));
    entry.program = glsl::Program::link(*vs, *fs);
  }
  if (!entry.program->ok()) return error(GL_INVALID_OPERATION);  // never: the sources are Tessel's own
  glsl::Program& p = *entry.program;
  set_ff_uniforms(p, k);
  const gpu::DrawCall call = b.call(ib);
  gpu::RenderState rs = render_state(false);
  rs.edge_flag_varying = -1;
  draw_program_batch({p, entry.cache}, vbuf, b.verts.x, call, rs);
}

}  // namespace tessel::gl
