// The GLSL twins of the scene shaders (glsl_shaders.hpp): the notes' illumination model in
// GLSL 3.30, with the uniforms filled from the RenderState as the C++ shaders fill theirs
// (src/scene/shaders.cpp).
#include "tessel/scene/glsl_shaders.hpp"

#include <array>
#include <map>
#include <mutex>

#include "tessel/glsl/program.hpp"

namespace tessel::scene {
namespace {

const char* kLighting = R"(
struct Light {
  vec4 wLightPos;  // w = 0: directional
  vec3 La, Le, attenuation, spotDirection;
  float spotCosCutoff, spotExponent;
};
uniform Light lights[8];
uniform int nLights;
uniform vec3 ka, kd, ks, emission;
uniform float shininess;
uniform bool phongSpecular;  // R.V instead of Blinn's N.H
uniform vec3 wEye;
uniform bool textured;
uniform sampler2D tex;
uniform int shadowLight;     // -1: no shadow map
uniform mat4 lightVP;
uniform sampler2DShadow shadowMap;
uniform int pcf;
uniform float texel;
// A point light's cube of six 2D maps (faces in GL's order +X, -X, +Y, -Y, +Z, -Z).
uniform bool cubeShadow;
uniform vec3 cubeLight;
uniform mat4 cubeVP[6];
uniform sampler2DShadow cubeMaps[6];

// The fraction of the (2 pcf + 1)^2 bilinear compares that see p from the light.
float shadowVisibility(vec3 p) {
  vec4 q = lightVP * vec4(p, 1.0);
  float inv = 1.0 / q.w;
  vec3 s = vec3(q.x * inv * 0.5 + 0.5, q.y * inv * 0.5 + 0.5, q.z * inv * 0.5 + 0.5);
  float sum = 0.0;
  for (int j = -pcf; j <= pcf; ++j)
    for (int i = -pcf; i <= pcf; ++i)
      sum += texture(shadowMap, vec3(s.x + float(i) * texel, s.y + float(j) * texel, s.z));
  float n = float((2 * pcf + 1) * (2 * pcf + 1));
  return (s.z > 1.0 || q.w <= 0.0) ? 1.0 : sum * (1.0 / n);
}

// The face a direction from the light falls in: its largest coordinate (GL 4.6 table 8.19).
int cubeFace(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}

// Samplers in an array are indexed by constants in GLSL 3.30.
float cubeCompare(int f, vec3 c) {
  switch (f) {
    case 0: return texture(cubeMaps[0], c);
    case 1: return texture(cubeMaps[1], c);
    case 2: return texture(cubeMaps[2], c);
    case 3: return texture(cubeMaps[3], c);
    case 4: return texture(cubeMaps[4], c);
    default: return texture(cubeMaps[5], c);
  }
}

// Each PCF tap is a point beside p, a texel of p's face apart along that face's two axes,
// looked up on the face its own direction falls in (so taps past an edge continue on the
// neighbouring face); the depth compared is p's own as that face sees it.
float cubeVisibility(vec3 p) {
  vec3 d = p - cubeLight;
  int major = cubeFace(d) / 2;
  float step = 2.0 * abs(d[major]) * texel;
  vec3 ea = vec3(0.0), eb = vec3(0.0);
  ea[(major + 1) % 3] = step;
  eb[(major + 2) % 3] = step;
  float sum = 0.0;
  for (int j = -pcf; j <= pcf; ++j)
    for (int i = -pcf; i <= pcf; ++i) {
      int f = cubeFace(d + float(i) * ea + float(j) * eb);
      vec4 q0 = cubeVP[f] * vec4(p, 1.0);
      float z = q0.z / q0.w * 0.5 + 0.5;
      if (!(q0.w > 0.0 && z <= 1.0)) {  // beyond the far plane or behind the light: lit
        sum += 1.0;
        continue;
      }
      vec4 q = q0 + float(i) * (cubeVP[f] * vec4(ea, 0.0)) + float(j) * (cubeVP[f] * vec4(eb, 0.0));
      sum += cubeCompare(f, vec3(q.x / q.w * 0.5 + 0.5, q.y / q.w * 0.5 + 0.5, z));
    }
  return sum / float((2 * pcf + 1) * (2 * pcf + 1));
}

// The texture (when there is one) multiplies the ambient and diffuse part; the specular part
// is added after it, as GL's separate specular colour.
vec4 surfaceColor(vec3 ambientDiffuse, vec3 specular, vec2 uv) {
  vec3 c = ambientDiffuse;
  if (textured) c *= texture(tex, uv).xyz;
  return vec4(c + specular, 1.0);
}

// colour = emission + sum over lights of ka La + (kd cos(theta) + ks cos(delta)^shininess) Le
void illuminate(vec3 p, vec3 N, float visibility, out vec3 ambientDiffuse, out vec3 specular) {
  vec3 V = normalize(wEye - p);
  ambientDiffuse = vec3(0.0);
  specular = vec3(0.0);
  for (int i = 0; i < nLights; ++i) {
    vec3 L = normalize(lights[i].wLightPos.xyz - p * lights[i].wLightPos.w);
    float spot = 1.0;
    if (lights[i].spotCosCutoff > -1.0) {
      float c = dot(-L, normalize(lights[i].spotDirection));
      spot = c >= lights[i].spotCosCutoff
                 ? (lights[i].spotExponent == 0.0 ? 1.0 : pow(max(c, 0.0), lights[i].spotExponent))
                 : 0.0;
    }
    float cost = max(dot(N, L), 0.0);
    float sc = phongSpecular ? dot(reflect(-L, N), V) : dot(N, normalize(L + V));
    float cosd = cost > 0.0 ? pow(max(sc, 0.0), shininess) : 0.0;
    vec3 att = lights[i].attenuation;
    if (lights[i].wLightPos.w != 0.0 && (att.y != 0.0 || att.z != 0.0 || att.x != 1.0)) {
      vec3 d = lights[i].wLightPos.xyz / lights[i].wLightPos.w - p;
      float d2 = dot(d, d);
      spot = spot / (att.x + att.y * sqrt(d2) + att.z * d2);
    }
    if (i == shadowLight) spot *= visibility;
    vec3 Le = lights[i].Le * spot;
    ambientDiffuse += ka * lights[i].La + kd * Le * cost;
    specular += ks * Le * cosd;
  }
  ambientDiffuse += emission;
}
)";

const char* kVertexHead = R"(#version 330
layout(location = 0) in vec3 vtxPos;
layout(location = 1) in vec3 vtxNorm;
layout(location = 2) in vec2 vtxUV;
uniform mat4 MVP, M, Mnormal;  // Mnormal = (M^-1)^T
)";

const char* kPhongVertex = R"(
out vec3 wPos, wNormal;
out vec2 uv;
void main() {
  vec4 pos = vec4(vtxPos, 1.0);
  wPos = (M * pos).xyz;
  wNormal = (Mnormal * vec4(vtxNorm, 0.0)).xyz;
  uv = vtxUV;
  gl_Position = MVP * pos;
}
)";

const char* kPhongFragment = R"(
in vec3 wPos, wNormal;
in vec2 uv;
out vec4 fragmentColor;
void main() {
  float visibility = shadowLight < 0 ? 1.0 : cubeShadow ? cubeVisibility(wPos) : shadowVisibility(wPos);
  vec3 ambientDiffuse, specular;
  illuminate(wPos, normalize(wNormal), visibility, ambientDiffuse, specular);
  fragmentColor = surfaceColor(ambientDiffuse, specular, uv);
}
)";

const char* kGouraudVertex = R"(
out vec3 ambientDiffuse, specular;
out vec2 uv;
void main() {
  vec4 pos = vec4(vtxPos, 1.0);
  vec3 p = (M * pos).xyz;
  vec3 N = normalize((Mnormal * vec4(vtxNorm, 0.0)).xyz);
  illuminate(p, N, 1.0, ambientDiffuse, specular);
  uv = vtxUV;
  gl_Position = MVP * pos;
}
)";

const char* kGouraudFragment = R"(
in vec3 ambientDiffuse, specular;
in vec2 uv;
out vec4 fragmentColor;
void main() {
  fragmentColor = surfaceColor(ambientDiffuse, specular, uv);
}
)";

// Phong with a normal map: the cotangent frame at the pixel from the derivatives of the
// position and uv (no tangents needed in the mesh), scaled so that its larger axis has
// length 1; where uv is constant over the quad the interpolated normal stays.
const char* kNormalMapFragment = R"(
uniform bool mapped;
uniform sampler2D normalMap;
in vec3 wPos, wNormal;
in vec2 uv;
out vec4 fragmentColor;
void main() {
  vec3 N = normalize(wNormal);
  if (mapped) {
    vec3 dp1 = dFdx(wPos), dp2 = dFdy(wPos);
    vec2 duv1 = dFdx(uv), duv2 = dFdy(uv);
    vec3 dp2perp = cross(dp2, N), dp1perp = cross(N, dp1);
    vec3 T = dp2perp * duv1.x + dp1perp * duv2.x;
    vec3 B = dp2perp * duv1.y + dp1perp * duv2.y;
    float m = max(dot(T, T), dot(B, B));
    float inv = m > 0.0 ? inversesqrt(m) : 0.0;
    vec3 t = texture(normalMap, uv).xyz * 2.0 - vec3(1.0);
    vec3 n = normalize(T * (t.x * inv) + B * (t.y * inv) + N * t.z);
    if (m > 0.0) N = n;
  }
  vec3 ambientDiffuse, specular;
  illuminate(wPos, N, 1.0, ambientDiffuse, specular);
  fragmentColor = surfaceColor(ambientDiffuse, specular, uv);
}
)";

// The distance from the camera as grey: white at the near plane, black at the far one.
const char* kDepthVertex = R"(
uniform mat4 MV;
out float eyeDepth;
void main() {
  vec4 pos = vec4(vtxPos, 1.0);
  eyeDepth = -(MV * pos).z;
  gl_Position = MVP * pos;
}
)";
const char* kDepthFragment = R"(
uniform float far, invRange;  // invRange = 1 / (far - near)
in float eyeDepth;
out vec4 fragmentColor;
void main() {
  float g = clamp((far - eyeDepth) * invRange, 0.0, 1.0);
  fragmentColor = vec4(g, g, g, 1.0);
}
)";

// The world-space normal as colour.
const char* kNormalFragment = R"(
in vec3 wPos, wNormal;
in vec2 uv;
out vec4 fragmentColor;
void main() { fragmentColor = vec4(normalize(wNormal) * 0.5 + vec3(0.5), 1.0); }
)";

// The notes' NPR: quantized diffuse light and a black silhouette where |N.V| is small.
const char* kNprFragment = R"(
uniform float bands, silhouette;
in vec3 wPos, wNormal;
in vec2 uv;
out vec4 fragmentColor;
void main() {
  vec3 N = normalize(wNormal), V = normalize(wEye - wPos);
  float y = 1.0;
  if (nLights > 0) {
    vec4 lp = lights[0].wLightPos;
    vec3 L = normalize(lp.xyz - wPos * lp.w);
    float d = max(dot(N, L), 0.0);
    y = bands <= 2.0 ? (d > 0.5 ? 1.0 : 0.5) : (floor(d * bands) + 1.0) * (1.0 / bands);
    y = min(y, 1.0);
  }
  vec3 c = kd * y;
  if (textured) c *= texture(tex, uv).xyz;
  fragmentColor = abs(dot(N, V)) < silhouette ? vec4(0.0, 0.0, 0.0, 1.0) : vec4(c, 1.0);
}
)";

}  // namespace

std::string GlslShader::vertex_source(Kind kind) {
  if (kind == Kind::Depth) return std::string(kVertexHead) + kDepthVertex;
  return std::string(kVertexHead) + kLighting + (kind == Kind::Gouraud ? kGouraudVertex : kPhongVertex);
}
std::string GlslShader::fragment_source(Kind kind) {
  switch (kind) {
    case Kind::Gouraud: return std::string("#version 330\n") + kLighting + kGouraudFragment;
    case Kind::Phong: return std::string("#version 330\n") + kLighting + kPhongFragment;
    case Kind::NormalMap: return std::string("#version 330\n") + kLighting + kNormalMapFragment;
    case Kind::Npr: return std::string("#version 330\n") + kLighting + kNprFragment;
    case Kind::Depth: return std::string("#version 330\n") + kDepthFragment;
    case Kind::Normal: return std::string("#version 330\n") + kNormalFragment;
  }
  return {};
}

struct GlslShader::Impl {
  Kind kind;
  float bands, silhouette;
  std::shared_ptr<glsl::Program> program;
  std::mutex mutex;  // draw() sets the program's uniforms
  // The uniforms' locations, looked up once (-1 for those a kind does not use).
  enum : int {
    kLightPos,
    kLa,
    kLe,
    kAttenuation,
    kSpotDirection,
    kSpotCosCutoff,
    kSpotExponent,
    kLightFields
  };
  static constexpr const char* kLightField[kLightFields] = {
      "wLightPos", "La", "Le", "attenuation", "spotDirection", "spotCosCutoff", "spotExponent"};
  std::array<std::array<int, kLightFields>, kMaxLights> light{};
  int MVP, M, Mnormal, nLights, ka, kd, ks, emission, shininess, phongSpecular, wEye, textured, tex,
      shadowMap, bands_loc, silhouette_loc, shadowLight, lightVP, pcf, texel, cubeShadow, cubeLight, cubeVP,
      cubeMaps, mapped, normalMap, MV, far, invRange;
  void locate() {
    const glsl::Program& p = *program;
    auto at = [&](const std::string& n) { return p.uniform_location(n); };
    MVP = at("MVP"), M = at("M"), Mnormal = at("Mnormal"), nLights = at("nLights");
    ka = at("ka"), kd = at("kd"), ks = at("ks"), emission = at("emission"), shininess = at("shininess");
    phongSpecular = at("phongSpecular"), wEye = at("wEye"), textured = at("textured"), tex = at("tex");
    shadowMap = at("shadowMap"), bands_loc = at("bands"), silhouette_loc = at("silhouette");
    shadowLight = at("shadowLight"), lightVP = at("lightVP"), pcf = at("pcf"), texel = at("texel");
    cubeShadow = at("cubeShadow"), cubeLight = at("cubeLight"), cubeVP = at("cubeVP"),
    cubeMaps = at("cubeMaps");
    mapped = at("mapped"), normalMap = at("normalMap"), MV = at("MV"), far = at("far"),
    invRange = at("invRange");
    for (int i = 0; i < kMaxLights; ++i)
      for (int f = 0; f < kLightFields; ++f)
        light[size_t(i)][size_t(f)] = at("lights[" + std::to_string(i) + "]." + kLightField[f]);
  }
};

GlslShader::GlslShader(Kind kind, int npr_bands, float npr_silhouette) : impl_(std::make_unique<Impl>()) {
  impl_->kind = kind;
  impl_->bands = float(npr_bands < 1 ? 1 : npr_bands);
  impl_->silhouette = npr_silhouette;
  auto vs = glsl::Shader::compile(glsl::Stage::Vertex, vertex_source(kind));
  auto fs = glsl::Shader::compile(glsl::Stage::Fragment, fragment_source(kind));
  if (!vs->ok() || !fs->ok()) throw gpu::Error("GLSL scene shader: " + vs->info_log() + fs->info_log());
  impl_->program = glsl::Program::link(*vs, *fs);
  if (!impl_->program->ok()) throw gpu::Error("GLSL scene shader: " + impl_->program->info_log());
  impl_->locate();
}

GlslShader::~GlslShader() = default;

void GlslShader::draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const {
  std::lock_guard lock(impl_->mutex);
  Impl& u = *impl_;
  glsl::Program& p = *u.program;
  auto m4 = [&](int loc, const glm::mat4& m) { p.set_uniform(loc, &m[0][0], 16); };
  auto v3 = [&](int loc, const glm::vec3& v) { p.set_uniform(loc, &v.x, 3); };
  auto f1 = [&](int loc, float v) { p.set_uniform(loc, &v, 1); };
  auto i1 = [&](int loc, int32_t v) { p.set_uniform(loc, &v, 1); };
  m4(u.MVP, state.P * state.V * state.M);
  if (u.kind == Kind::Depth) {
    m4(u.MV, state.V * state.M);
    f1(u.far, state.far);
    f1(u.invRange, 1.0f / (state.far - state.near));
    p.draw(ctx, geometry.layout(), state.pipeline, geometry.draw_call());
    return;
  }
  m4(u.M, state.M);
  m4(u.Mnormal, glm::transpose(state.Minv));
  const int n = int(std::min<size_t>(state.lights.size(), kMaxLights));
  i1(u.nLights, n);
  for (int i = 0; i < n; ++i) {
    const Light& l = state.lights[size_t(i)];
    const auto& at = u.light[size_t(i)];
    p.set_uniform(at[Impl::kLightPos], &l.wLightPos.x, 4);
    v3(at[Impl::kLa], l.La);
    v3(at[Impl::kLe], l.Le);
    v3(at[Impl::kAttenuation], l.attenuation);
    v3(at[Impl::kSpotDirection], l.spot_direction);
    f1(at[Impl::kSpotCosCutoff], l.spot_cos_cutoff);
    f1(at[Impl::kSpotExponent], l.spot_exponent);
  }
  const Material m = state.material ? *state.material : Material{};
  v3(u.ka, m.ka);
  v3(u.kd, m.kd);
  v3(u.ks, m.ks);
  v3(u.emission, m.emission);
  f1(u.shininess, m.shininess);
  i1(u.phongSpecular, m.specular == Specular::Phong);
  v3(u.wEye, state.wEye);
  i1(u.textured, m.texture != nullptr);
  i1(u.tex, 0);
  i1(u.shadowMap, 1);
  f1(u.bands_loc, u.bands);
  f1(u.silhouette_loc, u.silhouette);
  // Units: 0 the material's texture, 1 the shadow map, 2 the normal map, 3..8 a cube's faces.
  glsl::TextureBinding units[9];
  units[0].texture_2d = m.texture.get();
  units[0].sampler.min_filter = gpu::Filter::LinearMipmapLinear;
  units[0].sampler.mag_filter = gpu::Filter::Linear;
  i1(u.normalMap, 2);
  i1(u.mapped, m.normal_map != nullptr);
  units[2] = units[0];
  units[2].texture_2d = m.normal_map.get();
  const bool shadow = state.shadow_map && u.kind == Kind::Phong;
  i1(u.shadowLight, shadow ? state.shadow_light : -1);
  if (shadow) {
    m4(u.lightVP, state.light_VP);
    i1(u.pcf, state.pcf);
    f1(u.texel, 1.0f / float(state.shadow_map->width()));
    units[1].texture_2d = state.shadow_map;
    // Outside the map is lit: the border (depth 1) passes every reference up to the far plane.
    units[1].sampler = gpu::Sampler2DShadow{}.state;
    units[1].sampler.wrap_s = units[1].sampler.wrap_t = gpu::Wrap::ClampToBorder;
    units[1].sampler.border_color = glm::vec4(1.0f);
    i1(u.cubeShadow, state.cube_shadow);
    if (state.cube_shadow) {
      v3(u.cubeLight, state.cube_light);
      p.set_uniform(u.cubeVP, &state.cube_VP[0][0][0], 16, 6);
      const int32_t faces[6] = {3, 4, 5, 6, 7, 8};
      p.set_uniform(u.cubeMaps, faces, 1, 6);
      // A tap always lands on the face its direction picks, at most half a texel from its
      // edge: the edge texel, not the border, is its neighbour there.
      for (size_t f = 0; f < 6; ++f) {
        units[3 + f] = units[1];
        units[3 + f].sampler.wrap_s = units[3 + f].sampler.wrap_t = gpu::Wrap::ClampToEdge;
        units[3 + f].texture_2d = state.cube_maps[f];
      }
    }
  }
  p.draw(ctx, geometry.layout(), state.pipeline, geometry.draw_call(), units);
}

std::shared_ptr<const Shader> glsl_shader_by_name(const std::string& name) {
  static std::mutex m;
  static std::map<std::string, std::shared_ptr<const Shader>> made;
  std::lock_guard lock(m);
  auto it = made.find(name);
  if (it != made.end()) return it->second;
  std::shared_ptr<const Shader> s;
  if (name == "glsl-gouraud")
    s = std::make_shared<GlslShader>(GlslShader::Kind::Gouraud);
  else if (name == "glsl-phong")
    s = std::make_shared<GlslShader>(GlslShader::Kind::Phong);
  else if (name == "glsl-npr")
    s = std::make_shared<GlslShader>(GlslShader::Kind::Npr);
  else if (name == "glsl-normalmap")
    s = std::make_shared<GlslShader>(GlslShader::Kind::NormalMap);
  else if (name == "glsl-depth")
    s = std::make_shared<GlslShader>(GlslShader::Kind::Depth);
  else if (name == "glsl-normal")
    s = std::make_shared<GlslShader>(GlslShader::Kind::Normal);
  if (s) made[name] = s;
  return s;
}

}  // namespace tessel::scene
