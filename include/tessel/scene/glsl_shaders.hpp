// The scene engine's shaders written in GLSL and run through tessel::glsl: twins of the C++
// GouraudShader, PhongShader (Blinn or Phong specular, textures, 2D and cube shadow maps with
// PCF), NormalMapShader, NprShader, DepthShader and NormalShader that read the same
// RenderState and give the same images (within 1/255; tests/scene/test_glsl_twins.cpp). They
// show what the notes' GLSL looks like in this engine, and let `tessel render --shading
// glsl-phong` draw any scene file through the GLSL compiler.
#pragma once

#include <memory>
#include <string>

#include "tessel/scene/scene.hpp"

namespace tessel::scene {

class GlslShader : public Shader {
 public:
  enum class Kind { Gouraud, Phong, NormalMap, Npr, Depth, Normal };
  // Compiles and links the program (throws gpu::Error with the info log if it fails).
  explicit GlslShader(Kind kind, int npr_bands = 2, float npr_silhouette = 0.2f);
  ~GlslShader() override;
  void draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const override;
  // The program's GLSL source, vertex then fragment.
  static std::string vertex_source(Kind kind);
  static std::string fragment_source(Kind kind);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// "glsl-gouraud", "glsl-phong", "glsl-normalmap", "glsl-npr", "glsl-depth", "glsl-normal"
// (nullptr if unknown).
std::shared_ptr<const Shader> glsl_shader_by_name(const std::string& name);

}  // namespace tessel::scene
