// The scene engine rendering: the shader library against golden images, and the properties
// that show each shader does what its name says.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "golden.hpp"
#include "tessel/gpu/framebuffer.hpp"
#include "tessel/scene/shaders.hpp"

using namespace tessel;
using namespace tessel::scene;

namespace {

std::shared_ptr<gpu::Texture2D> checker_texture() {
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

// Two coarse spheres side by side (left Gouraud, right Phong) over a textured floor, one
// directional and one point light.
Scene make_scene(float shininess = 40.0f) {
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
  lamp.Le = glm::vec3(0.6f, 0.5f, 0.4f);
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
  auto& a = s.add(std::make_unique<Object>(sphere, red, gouraud));
  a.transform.position = glm::vec3(-1.2f, 1.0f, 0.0f);
  auto& b = s.add(std::make_unique<Object>(sphere, red, phong));
  b.transform.position = glm::vec3(1.2f, 1.0f, 0.0f);
  s.add(std::make_unique<Object>(floor, tiles, phong));
  return s;
}

void render_into(const Scene& s, gpu::Texture2D& color, int threads) {
  gpu::Texture2D depth(gpu::Format::Depth24Stencil8, color.width(), color.height());
  gpu::Framebuffer fb(&color, &depth);
  gpu::Context ctx(threads);
  ctx.bind_framebuffer(&fb);
  s.Render(ctx);
  ctx.finish();
}

std::vector<uint8_t> render(const Scene& s, int w, int h, int threads) {
  gpu::Texture2D color(gpu::Format::RGBA8, w, h);
  render_into(s, color, threads);
  return gpu::read_rgba8(color);
}

}  // namespace

TEST(SceneRender, GouraudAndPhongMatchTheirGoldenImage) {
  gpu::Texture2D color(gpu::Format::RGBA8, 240, 120);
  render_into(make_scene(), color, 2);
  test::expect_golden("gouraud_phong", color);
}

TEST(SceneRender, IdenticalForAnyThreadCount) {
  const Scene s = make_scene();
  const std::vector<uint8_t> one = render(s, 240, 120, 1);
  EXPECT_EQ(one, render(s, 240, 120, 2));
  EXPECT_EQ(one, render(s, 240, 120, 8));
}

// On a coarse sphere the per-vertex highlight is smeared over whole triangles and loses its
// peak; per-pixel shading keeps it. The brightest pixel of each sphere shows it.
TEST(SceneRender, PhongKeepsTheHighlightThatGouraudSmears) {
  const std::vector<uint8_t> px = render(make_scene(80.0f), 240, 120, 2);
  int peak[2] = {0, 0};
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 240; ++x) {
      const uint8_t* p = &px[(size_t(y) * 240 + size_t(x)) * 4];
      if (p[0] < 100 || p[1] > p[0]) continue;  // sphere pixels are red or white-hot
      const int side = x < 120 ? 0 : 1;
      peak[side] = std::max(peak[side], int(p[1]));  // green rises only in the highlight
    }
  EXPECT_GT(peak[1], peak[0] + 20) << "Gouraud peak " << peak[0] << ", Phong peak " << peak[1];
}

TEST(TestGolden, ToleranceCatchesAShininessChange) {
  const std::vector<uint8_t> a = render(make_scene(40.0f), 240, 120, 2);
  const std::vector<uint8_t> b = render(make_scene(44.0f), 240, 120, 2);
  const test::ImageDiff d = test::diff_rgba(a, b);
  EXPECT_FALSE(d.passes()) << d.differing << " of " << d.total << " pixels differ";
  EXPECT_TRUE(test::diff_rgba(a, a).passes());
}

TEST(SceneRender, TooManyLightsAndBadCamerasAreErrors) {
  Scene s = make_scene();
  s.lights.resize(kMaxLights + 1);
  EXPECT_THROW(render(s, 16, 16, 1), gpu::Error);
  Scene t = make_scene();
  t.camera.lookat = t.camera.eye;
  EXPECT_THROW(render(t, 16, 16, 1), gpu::Error);
  Mesh empty;
  EXPECT_THROW(Geometry(empty, "empty"), gpu::Error);
}

TEST(SceneRender, AnimateSpinsAndMoves) {
  Scene s = make_scene();
  s.objects[0]->spin = 1.5f;
  s.objects[0]->velocity = glm::vec3(0.0f, 0.0f, -2.0f);
  s.Animate(0.5f);
  EXPECT_FLOAT_EQ(s.objects[0]->transform.angle, 0.75f);
  EXPECT_FLOAT_EQ(s.objects[0]->transform.position.z, -1.0f);
}
