// The built-in demo scene, described with the scene engine's structures (the same ones a scene
// file fills): tessellated Blinn-Phong spheres and a torus on a textured floor, lit by one
// directional and one attenuated point light.
#include "demo.hpp"

#include <chrono>
#include <memory>
#include <vector>

#include "tessel/gpu/framebuffer.hpp"
#include "tessel/gpu/image.hpp"
#include "tessel/scene/shaders.hpp"

namespace tessel::apps {
using namespace tessel::gpu;

namespace {

// A two-tone checkerboard with a thin grout line, 16 squares a side, full mipmap chain.
std::shared_ptr<Texture2D> make_floor_texture() {
  const int n = 512;
  std::vector<uint8_t> px(size_t(n) * n * 4);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const bool check = ((x / 32) + (y / 32)) & 1;
      const bool grout = (x % 32) == 0 || (y % 32) == 0;
      uint8_t* p = &px[(size_t(y) * n + size_t(x)) * 4];
      const uint8_t c = grout ? 60 : check ? 235 : 140;
      p[0] = c;
      p[1] = uint8_t(c * 0.92f);
      p[2] = uint8_t(c * 0.85f);
      p[3] = 255;
    }
  auto t = std::make_shared<Texture2D>(Format::RGBA8, n, n, 0);
  t->upload_rgba8(0, px.data(), px.size());
  t->generate_mipmaps();
  return t;
}

std::shared_ptr<scene::Material> material(glm::vec3 albedo, float ambient, float diffuse, float specular,
                                          float shininess) {
  auto m = std::make_shared<scene::Material>();
  m->ka = albedo * ambient;
  m->kd = albedo * diffuse;
  m->ks = glm::vec3(specular);
  m->shininess = shininess;
  return m;
}

scene::Scene demo_scene(float aspect) {
  scene::Scene s;
  s.background = glm::vec4(0.55f, 0.68f, 0.85f, 1.0f);
  s.camera.eye = glm::vec3(0.0f, 3.2f, 7.5f);
  s.camera.lookat = glm::vec3(0.0f, 0.6f, 0.0f);
  s.camera.fov = glm::radians(45.0f);
  s.camera.aspect = aspect;
  s.camera.near = 0.5f;
  s.camera.far = 100.0f;
  scene::Light sun;
  sun.wLightPos = glm::vec4(-0.4f, 1.0f, 0.6f, 0.0f);
  sun.La = glm::vec3(1.0f);  // the materials' ka carry the ambient level
  sun.Le = glm::vec3(0.85f, 0.82f, 0.75f);
  scene::Light lamp;
  lamp.wLightPos = glm::vec4(2.5f, 2.5f, 2.0f, 1.0f);
  lamp.La = glm::vec3(0.0f);
  lamp.Le = glm::vec3(0.9f, 0.7f, 0.5f);
  lamp.attenuation = glm::vec3(1.0f, 0.0f, 0.02f);
  s.lights = {sun, lamp};

  const auto phong = std::make_shared<scene::PhongShader>();
  const auto sphere = std::make_shared<scene::Geometry>(scene::Sphere().create(32, 48), "sphere");
  const auto torus = std::make_shared<scene::Geometry>(scene::Torus(1.0f, 0.35f).create(24, 64), "torus");
  const auto floor = std::make_shared<scene::Geometry>(scene::Plane(16.0f).create(1, 1), "floor");
  auto tiles = material(glm::vec3(1.0f), 0.15f, 0.8f, 0.1f, 16.0f);
  tiles->texture = make_floor_texture();

  auto add = [&](std::shared_ptr<const scene::Geometry> g, std::shared_ptr<const scene::Material> m,
                 glm::vec3 pos, float scale) -> scene::Object& {
    auto& o = s.add(std::make_unique<scene::Object>(std::move(g), std::move(m), phong));
    o.transform.position = pos;
    o.transform.scale = glm::vec3(scale);
    return o;
  };
  add(floor, tiles, glm::vec3(0.0f), 1.0f);
  add(sphere, material({0.85f, 0.2f, 0.15f}, 0.1f, 0.8f, 0.6f, 48.0f), {-2.2f, 1.0f, 0.0f}, 1.0f);
  add(sphere, material({0.2f, 0.45f, 0.9f}, 0.1f, 0.8f, 0.8f, 96.0f), {0.0f, 0.7f, 1.4f}, 0.7f);
  add(sphere, material({0.95f, 0.8f, 0.2f}, 0.1f, 0.8f, 0.5f, 32.0f), {2.3f, 0.55f, 0.6f}, 0.55f);
  auto& ring = add(torus, material({0.3f, 0.8f, 0.4f}, 0.1f, 0.75f, 0.7f, 64.0f), {0.3f, 1.25f, -1.6f}, 1.0f);
  ring.transform.axis = glm::vec3(1.0f, 0.0f, 0.3f);
  ring.transform.angle = glm::radians(60.0f);
  return s;
}

}  // namespace

DemoResult render_demo(int width, int height, int threads, const std::string& png) {
  Texture2D color(Format::RGBA8, width, height);
  Texture2D depth(Format::Depth24Stencil8, width, height);
  Framebuffer fb(&color, &depth);
  Context ctx(threads);
  const scene::Scene s = demo_scene(float(width) / float(height));

  DemoResult r;
  const auto t0 = std::chrono::steady_clock::now();
  ctx.bind_framebuffer(&fb);
  s.Render(ctx);
  ctx.finish();
  r.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  r.triangles = s.triangles();
  r.stats = ctx.stats();
  write_png(png, color);
  return r;
}

}  // namespace tessel::apps
