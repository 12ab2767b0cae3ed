// The camera of the scene engine (the lecture notes' Camera): eye, lookat, vup, vertical field
// of view, aspect, near and far; V() is the view matrix (world -> camera space, the camera at
// the origin looking down -z with y up), P() the projection (GL's clip space: gluPerspective,
// or glOrtho for an orthographic camera). Matrices act on column vectors (glm, GL).
#pragma once

#include <glm/glm.hpp>

namespace tessel::scene {

class Camera {
 public:
  glm::vec3 eye{0.0f, 0.0f, 5.0f}, lookat{0.0f}, vup{0.0f, 1.0f, 0.0f};
  float fov = 0.785398163f;  // vertical, radians (45 degrees)
  float aspect = 1.0f;       // width / height
  float near = 0.1f, far = 100.0f;
  bool orthographic = false;
  float ortho_height = 2.0f;  // the height of the view volume when orthographic

  // Throws tessel::gpu::Error naming the field for a camera that has no view: eye == lookat,
  // vup parallel to the view direction, fov outside (0, pi), aspect <= 0, near <= 0 for a
  // perspective camera, far <= near, or a value that is not finite.
  void validate() const;
  glm::mat4 V() const;
  glm::mat4 P() const;
  glm::mat4 VP() const { return P() * V(); }
};

}  // namespace tessel::scene
