// Models from files: Wavefront OBJ with its MTL materials (through tinyobjloader), and glTF 2.0
// (through tinygltf). A model is
// a list of parts, one per (shape, material) pair, each a triangle mesh with normals (smooth
// normals are computed where the file has none) and texture coordinates.
//
// MTL to the scene's Material: Ka -> ka, Kd -> kd, Ks -> ks, Ns -> shininess, Ke -> emission,
// map_Kd -> texture (relative to the .mtl's folder), Ni -> refractive_index,
// Tf -> transmittance. Errors name the file and the problem; indices that point outside the
// file's vertices, non-finite numbers and empty files are errors, never a crash.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tessel/scene/scene.hpp"

namespace tessel::scene {

struct Model {
  struct Part {
    std::string name;
    Mesh mesh;
    int material = -1;  // index into materials, -1: none given
  };
  std::vector<Part> parts;
  std::vector<std::shared_ptr<Material>> materials;
};

// Reads path (.obj) and the .mtl files it names, and the textures they name.
Model load_obj(const std::string& path);
// From text: mtl_text stands for the file an `mtllib` line of the OBJ names (without such a
// line there are no materials); `name` is used in messages, `folder` for texture paths.
Model parse_obj(const std::string& obj_text, const std::string& mtl_text, const std::string& name,
                const std::string& folder = ".");

// glTF 2.0 (.gltf, .glb): the default scene's meshes placed by their nodes' world matrices,
// base colour textures, and the PBR factors mapped to the Phong material (docs/scene-format.md).
Model load_gltf(const std::string& path);
// From bytes (.glb when they start with "glTF"); external buffers and images are looked up in
// `folder`.
Model parse_gltf(const void* data, size_t size, const std::string& name, const std::string& folder = ".");

// Corner normals for a triangle list without them: the area-weighted face normals around
// each position within 45 degrees of the corner's face (curves smooth, creases sharp).
void smooth_normals(Mesh& mesh);

}  // namespace tessel::scene
