#include "tessel/scene/transform.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace tessel::scene {

namespace {
glm::mat4 rotation(const glm::vec3& axis, float angle) {
  const float len = glm::length(axis);
  if (!(len > 0.0f) || angle == 0.0f) return glm::mat4(1.0f);
  return glm::rotate(glm::mat4(1.0f), angle, axis / len);
}
}  // namespace

glm::mat4 Transform::M() const {
  return glm::translate(glm::mat4(1.0f), position) * rotation(axis, angle) *
         glm::scale(glm::mat4(1.0f), scale);
}

glm::mat4 Transform::Minv() const {
  return glm::scale(glm::mat4(1.0f), 1.0f / scale) * rotation(axis, -angle) *
         glm::translate(glm::mat4(1.0f), -position);
}

glm::mat4 Transform::world() const {
  glm::mat4 m = M();
  // Bounded walk: a parent cycle would otherwise never end.
  int depth = 0;
  for (const Transform* p = parent; p && depth < 1024; p = p->parent, ++depth) m = p->M() * m;
  return m;
}

glm::mat4 Transform::world_inverse() const {
  glm::mat4 m = Minv();
  int depth = 0;
  for (const Transform* p = parent; p && depth < 1024; p = p->parent, ++depth) m = m * p->Minv();
  return m;
}

glm::mat3 Transform::normal_matrix() const { return glm::transpose(glm::mat3(world_inverse())); }

}  // namespace tessel::scene
