// A small scene the scene tests share: two coarse spheres over a textured floor, lit by a
// directional and a point light.
#pragma once

#include <memory>
#include <vector>

#include "tessel/scene/shaders.hpp"

namespace tessel::test {
using namespace tessel::scene;

inline std::shared_ptr<gpu::Texture2D> checker_texture() {
  const int n = 64;
  std::vector<uint8_t> px(size_t(n) * n * 4);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const bool c = ((x / 8) + (y / 8)) & 1;
      uint8_t* p = &px[(size_t(y) * n + size_t(x)) * 4];
      p[0] = c ? 230 : 40;
      p[1] = c ? 200 : 90;
      p[2] = c ? 80 : 160;
      p[3] = 255;
    }
  auto t = std::make_shared<gpu::Texture2D>(gpu::Format::RGBA8, n, n, 0);
  t->upload_rgba8(0, px.data(), px.size());
  t->generate_mipmaps();
  return t;
}

// Two coarse spheres side by side (left Gouraud, or Phong too; right Phong) over a textured floor, one
// directional and one point light.
inline Scene make_scene(float shininess = 40.0f, bool gouraud_left = true) {
  Scene s;
  s.camera.eye = glm::vec3(0.0f, 1.5f, 6.0f);
  s.camera.lookat = glm::vec3(0.0f, 0.3f, 0.0f);
  s.camera.fov = 0.7f;
  s.camera.aspect = 2.0f;
  s.camera.near = 0.5f;
  s.camera.far = 50.0f;
  s.background = glm::vec4(0.2f, 0.25f, 0.3f, 1.0f);
  Light sun;
  sun.wLightPos = glm::vec4(-0.5f, 1.0f, 0.8f, 0.0f);
  sun.La = glm::vec3(0.15f);
  sun.Le = glm::vec3(0.8f);
  Light lamp;
  lamp.wLightPos = glm::vec4(2.0f, 2.0f, 2.0f, 1.0f);
  lamp.La = glm::vec3(0.0f);
  lamp.Le = glm::vec3(0.9f, 0.75f, 0.6f);
  lamp.attenuation = glm::vec3(1.0f, 0.0f, 0.05f);
  s.lights = {sun, lamp};
  auto sphere = std::make_shared<Geometry>(Sphere().create(8, 12), "sphere");
  auto floor = std::make_shared<Geometry>(Plane(8.0f).create(1, 1), "floor");
  auto red = std::make_shared<Material>();
  red->kd = glm::vec3(0.8f, 0.15f, 0.1f);
  red->ka = red->kd;
  red->ks = glm::vec3(0.8f);
  red->shininess = shininess;
  auto tiles = std::make_shared<Material>();
  tiles->kd = glm::vec3(1.0f);
  tiles->ka = glm::vec3(1.0f);
  tiles->ks = glm::vec3(0.0f);
  tiles->texture = checker_texture();
  auto gouraud = std::make_shared<GouraudShader>();
  auto phong = std::make_shared<PhongShader>();
  auto& a = s.add(
      std::make_unique<Object>(sphere, red, gouraud_left ? std::shared_ptr<const Shader>(gouraud) : phong));
  a.transform.position = glm::vec3(-1.2f, 1.0f, 0.0f);
  auto& b = s.add(std::make_unique<Object>(sphere, red, phong));
  b.transform.position = glm::vec3(1.2f, 1.0f, 0.0f);
  s.add(std::make_unique<Object>(floor, tiles, phong));
  return s;
}

}  // namespace tessel::test
