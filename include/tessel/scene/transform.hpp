// Modelling transformations (the lecture notes' Object animation parameters): scale, then a
// rotation by `angle` radians about `axis`, then a translation to `position`; optionally below
// a parent, whose world matrix applies after this one (hierarchies such as the robot arm).
#pragma once

#include <glm/glm.hpp>

namespace tessel::scene {

struct Transform {
  glm::vec3 scale{1.0f};
  glm::vec3 axis{0.0f, 1.0f, 0.0f};
  float angle = 0.0f;
  glm::vec3 position{0.0f};
  const Transform* parent = nullptr;  // not owned; must outlive this one

  // The local matrix T R S and its inverse S^-1 R^-1 T^-1 (computed from the parameters, not
  // by inverting: exact where the parameters are). A zero axis means no rotation; a zero scale
  // component gives a non-finite inverse.
  glm::mat4 M() const;
  glm::mat4 Minv() const;
  // With the parents' matrices: parent.world() * M(), and its inverse.
  glm::mat4 world() const;
  glm::mat4 world_inverse() const;
  // The matrix for normals: the inverse transpose of the world matrix's upper 3x3 (normals
  // stay perpendicular to surfaces under non-uniform scale).
  glm::mat3 normal_matrix() const;
};

}  // namespace tessel::scene
