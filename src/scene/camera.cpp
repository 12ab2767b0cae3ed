#include "tessel/scene/camera.hpp"

#include <cmath>
#include <string>

#include "tessel/gpu/format.hpp"  // tessel::gpu::Error

namespace tessel::scene {

using gpu::Error;

namespace {
bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

void Camera::validate() const {
  if (!finite(eye) || !finite(lookat) || !finite(vup))
    throw Error("camera: eye, lookat and vup must be finite");
  const glm::vec3 w = eye - lookat;
  if (glm::dot(w, w) == 0.0f) throw Error("camera: eye and lookat are the same point");
  if (glm::length(glm::cross(vup, w)) <= 1e-6f * glm::length(vup) * glm::length(w))
    throw Error("camera: vup is parallel to the viewing direction (or zero)");
  if (!(aspect > 0.0f) || !std::isfinite(aspect)) throw Error("camera: aspect must be positive");
  if (!std::isfinite(near) || !std::isfinite(far)) throw Error("camera: near and far must be finite");
  if (orthographic) {
    if (!(ortho_height > 0.0f) || !std::isfinite(ortho_height))
      throw Error("camera: ortho_height must be positive");
    if (!(far > near)) throw Error("camera: far must be greater than near");
  } else {
    if (!(fov > 0.0f && fov < 3.14159265f)) throw Error("camera: fov must be between 0 and pi radians");
    if (!(near > 0.0f)) throw Error("camera: near must be positive for a perspective camera");
    if (!(far > near)) throw Error("camera: far must be greater than near");
  }
}

glm::mat4 Camera::V() const {
  // The camera's basis: w away from the view direction, u to the right, v up.
  const glm::vec3 w = glm::normalize(eye - lookat);
  const glm::vec3 u = glm::normalize(glm::cross(vup, w));
  const glm::vec3 v = glm::cross(w, u);
  glm::mat4 m(1.0f);
  for (int c = 0; c < 3; ++c) {
    m[c][0] = u[c];
    m[c][1] = v[c];
    m[c][2] = w[c];
  }
  m[3][0] = -glm::dot(u, eye);
  m[3][1] = -glm::dot(v, eye);
  m[3][2] = -glm::dot(w, eye);
  return m;
}

glm::mat4 Camera::P() const {
  glm::mat4 m(0.0f);
  if (orthographic) {
    // glOrtho(-w/2, w/2, -h/2, h/2, near, far).
    const float h = ortho_height, w = ortho_height * aspect;
    m[0][0] = 2.0f / w;
    m[1][1] = 2.0f / h;
    m[2][2] = -2.0f / (far - near);
    m[3][2] = -(far + near) / (far - near);
    m[3][3] = 1.0f;
    return m;
  }
  // gluPerspective: f = cot(fov / 2).
  const float f = 1.0f / std::tan(fov * 0.5f);
  m[0][0] = f / aspect;
  m[1][1] = f;
  m[2][2] = (far + near) / (near - far);
  m[2][3] = -1.0f;
  m[3][2] = 2.0f * far * near / (near - far);
  return m;
}

}  // namespace tessel::scene
