// The GLSL of the standard scenes (scenes.hpp): what the llvmpipe peer draws with, and what
// `tessel bench --shaders glsl` gives Tessel's GLSL compiler, character for character.
#include <cstdio>
#include <string>

#include "scenes.hpp"

namespace tessel::scenes {
namespace {

// Blinn-Phong in world space (shared/scenes/README.md). Variants by #define: TEXTURED (albedo
// from u_tex) and INSTANCED (offset and albedo from per-instance attributes 3 and 4).
const char* const kVertexShader = R"(
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
#ifdef INSTANCED
layout(location = 3) in vec3 a_offset;
layout(location = 4) in vec3 a_albedo;
flat out vec3 v_albedo;
#else
uniform vec3 u_offset;
#endif
uniform mat4 u_viewproj;  // projection * view, computed on the CPU
out vec3 v_p;
out vec3 v_n;
out vec2 v_uv;
void main() {
#ifdef INSTANCED
  vec3 p = a_pos + a_offset;
  v_albedo = a_albedo;
#else
  vec3 p = a_pos + u_offset;
#endif
  v_p = p;
  v_n = a_normal;
  v_uv = a_uv;
  gl_Position = u_viewproj * vec4(p, 1.0);
}
)";

const char* const kFragmentShader = R"(
in vec3 v_p;
in vec3 v_n;
in vec2 v_uv;
#if defined(TEXTURED)
uniform sampler2D u_tex;
#elif defined(INSTANCED)
flat in vec3 v_albedo;
#else
uniform vec3 u_albedo;
#endif
uniform vec3 u_light;
uniform vec3 u_eye;
layout(location = 0) out vec4 o_color;
void main() {
  vec3 N = normalize(v_n);
  vec3 L = normalize(u_light - v_p);
  vec3 V = normalize(u_eye - v_p);
  vec3 H = normalize(L + V);
  float ndl = max(dot(N, L), 0.0);
  float spec = ndl > 0.0 ? pow(max(dot(N, H), 0.0), K_SHININESS) : 0.0;
#if defined(TEXTURED)
  vec3 albedo = texture(u_tex, v_uv).rgb;
#elif defined(INSTANCED)
  vec3 albedo = v_albedo;
#else
  vec3 albedo = u_albedo;
#endif
  o_color = vec4(K_AMBIENT * albedo + K_DIFFUSE * ndl * albedo + K_SPECULAR * spec * vec3(1.0),
                 1.0);
}
)";

// Version, variant defines and the material constants of scenes.hpp.
std::string header(bool textured, bool instanced) {
  auto f = [](float v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "float(%.9g)", double(v));
    return std::string(buf);
  };
  std::string head = "#version 330 core\n";
  if (textured) head += "#define TEXTURED 1\n";
  if (instanced) head += "#define INSTANCED 1\n";
  head += "#define K_AMBIENT " + f(kAmbient) + "\n#define K_DIFFUSE " + f(kDiffuse) +
          "\n#define K_SPECULAR " + f(kSpecular) + "\n#define K_SHININESS " + f(kShininess) + "\n";
  return head;
}

}  // namespace

std::string scene_vertex_glsl(bool textured, bool instanced) {
  return header(textured, instanced) + kVertexShader;
}
std::string scene_fragment_glsl(bool textured, bool instanced) {
  return header(textured, instanced) + kFragmentShader;
}

}  // namespace tessel::scenes
