// Scene files: a Scene and its render settings described in JSON (docs/scene-format.md has
// every field). Errors name the file and the place: "scenes/x.json:12:5: ..." for bad JSON,
// "scenes/x.json: objects[2].geometry.type: unknown surface 'cubee' (...)" for bad content.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "tessel/scene/scene.hpp"

namespace tessel::scene {

struct RenderSettings {
  int width = 800, height = 600;
  int threads = 0;    // 0: one per hardware thread
  float fps = 30.0f;  // frames per second of animation (--frames)
};

struct SceneFile {
  Scene scene;
  RenderSettings render;
};

// Reads and parses a scene file; texture files are found relative to the file's folder.
// Throws tessel::gpu::Error.
SceneFile load_scene_file(const std::string& path);
// The same from text; `name` stands for the file in messages, `folder` for relative paths.
SceneFile parse_scene(const std::string& text, const std::string& name, const std::string& folder = ".");

// A shader of the library by name: gouraud, phong, normalmap, npr, depth, normal (nullptr if
// unknown).
std::shared_ptr<const Shader> shader_by_name(const std::string& name);

}  // namespace tessel::scene
