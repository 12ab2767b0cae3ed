// The standard benchmark scenes of ../shared/scenes/README.md (spheres-100k, spheres-1m, fill,
// textured), as plain data: geometry, draws, camera, light and the texture. Both `tessel bench`
// and the llvmpipe peer (bench/peer/) build their frames from these, so the two render the
// same thing to the last number. No Tessel or GL types here; only glm.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tessel::scenes {

// Interleaved vertices: position xyz, normal xyz, uv (8 floats), and 32-bit indices.
struct Mesh {
  std::vector<float> vertices;
  std::vector<uint32_t> indices;
  static constexpr int kStride = 8;  // floats per vertex
};

// One draw call: a range of the index buffer, moved by `offset` (world space), coloured by
// `albedo` (a uniform).
struct Draw {
  uint32_t first_index = 0, index_count = 0;
  glm::vec3 offset{0.0f};
  glm::vec3 albedo{1.0f};
};

struct Scene {
  std::string name;
  int width = 0, height = 0;
  Mesh mesh;
  std::vector<Draw> draws;  // in submission order
  glm::vec3 eye{0.0f};
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};  // gluPerspective(45, w/h, 0.5, 100)
  glm::vec3 light{0.0f};       // point light position, world space
  bool textured = false;       // albedo = the scene texture at uv (texture_rgba8())
  // Drawn through OpenGL 1.x fixed-function lighting with vertex arrays (fixed_gl.hpp)
  // instead of the Blinn-Phong shader.
  bool fixed_function = false;
  // Every draw uses the same index range (the sphere grid): can be one instanced draw.
  bool instanceable = false;
  uint64_t triangles() const;  // per frame
};

// The UV sphere of the scenes README (unit radius; ring k = 0..stacks, column j = 0..slices,
// seam duplicated, counter-clockwise seen from outside); the demo scene uses it too.
Mesh sphere_mesh(int slices, int stacks);

// "spheres-100k", "spheres-1m", "fill", "textured", "fixed-100k".
const std::vector<std::string>& scene_names();
bool is_scene(const std::string& name);
// Builds a scene for a width x height image (the fill quads depend on the aspect ratio).
// Throws std::invalid_argument for an unknown name or a size below 1.
Scene make_scene(const std::string& name, int width, int height);

// The textured scene's texture: 1024x1024 RGBA8, level 0, row y = texel row t (bottom-up, as
// glTexImage2D takes it). Mipmaps are generated from it with a 2x2 box filter.
inline constexpr int kTextureSize = 1024;
std::vector<uint8_t> texture_rgba8();

// Blinn-Phong constants shared by the shaders of both renderers.
inline constexpr float kAmbient = 0.1f, kDiffuse = 0.8f, kSpecular = 0.5f, kShininess = 32.0f;

// The scenes' GLSL 3.30 program (scene_glsl.cpp): attributes 0-2 position, normal, uv (3-4
// per-instance offset and albedo when instanced); uniforms u_viewproj, u_offset, u_albedo,
// u_light, u_eye, u_tex.
std::string scene_vertex_glsl(bool textured, bool instanced);
std::string scene_fragment_glsl(bool textured, bool instanced);

}  // namespace tessel::scenes
