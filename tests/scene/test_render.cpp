// The scene engine rendering: the shader library against golden images, and the properties
// that show each shader does what its name says.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <vector>

#include "golden.hpp"
#include "test_scenes.hpp"
#include "tessel/gpu/framebuffer.hpp"
#include "tessel/scene/shaders.hpp"

using namespace tessel;
using namespace tessel::scene;

namespace {

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
  render_into(tessel::test::make_scene(), color, 2);
  test::expect_golden("gouraud_phong", color);
}

TEST(SceneRender, IdenticalForAnyThreadCount) {
  const Scene s = tessel::test::make_scene();
  const std::vector<uint8_t> one = render(s, 240, 120, 1);
  EXPECT_EQ(one, render(s, 240, 120, 2));
  EXPECT_EQ(one, render(s, 240, 120, 8));
}

// On a coarse sphere the per-vertex highlight is smeared over whole triangles and loses its
// peak; per-pixel shading keeps it. The brightest pixel of each sphere shows it.
TEST(SceneRender, PhongKeepsTheHighlightThatGouraudSmears) {
  const std::vector<uint8_t> px = render(tessel::test::make_scene(80.0f), 240, 120, 2);
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
  const std::vector<uint8_t> a = render(tessel::test::make_scene(40.0f), 240, 120, 2);
  const std::vector<uint8_t> b = render(tessel::test::make_scene(44.0f), 240, 120, 2);
  const test::ImageDiff d = test::diff_rgba(a, b);
  EXPECT_FALSE(d.passes()) << d.differing << " of " << d.total << " pixels differ";
  EXPECT_TRUE(test::diff_rgba(a, a).passes());
}

TEST(SceneRender, TooManyLightsAndBadCamerasAreErrors) {
  Scene s = tessel::test::make_scene();
  s.lights.resize(kMaxLights + 1);
  EXPECT_THROW(render(s, 16, 16, 1), gpu::Error);
  Scene t = tessel::test::make_scene();
  t.camera.lookat = t.camera.eye;
  EXPECT_THROW(render(t, 16, 16, 1), gpu::Error);
  Mesh empty;
  EXPECT_THROW(Geometry(empty, "empty"), gpu::Error);
}

TEST(SceneRender, AnimateSpinsAndMoves) {
  Scene s = tessel::test::make_scene();
  s.objects[0]->spin = 1.5f;
  s.objects[0]->velocity = glm::vec3(0.0f, 0.0f, -2.0f);
  s.Animate(0.5f);
  EXPECT_FLOAT_EQ(s.objects[0]->transform.angle, 0.75f);
  EXPECT_FLOAT_EQ(s.objects[0]->transform.position.z, -1.0f);
}

namespace {
Scene with_shader(std::shared_ptr<const Shader> shader) {
  Scene s = tessel::test::make_scene();
  for (auto& o : s.objects) o->shader = shader;
  return s;
}
}  // namespace

TEST(SceneRender, NprDepthAndNormalViewsMatchTheirGoldenImages) {
  const std::pair<const char*, std::shared_ptr<const Shader>> shaders[] = {
      {"npr", std::make_shared<NprShader>()},
      {"npr4", std::make_shared<NprShader>(4, 0.3f)},
      {"depth", std::make_shared<DepthShader>(4.0f, 12.0f)},
      {"normal", std::make_shared<NormalShader>()}};
  for (const auto& [name, shader] : shaders) {
    gpu::Texture2D color(gpu::Format::RGBA8, 240, 120);
    render_into(with_shader(shader), color, 2);
    test::expect_golden(name, color);
  }
}

// The notes' toon shading: on an untextured sphere only the two bands of its diffuse colour
// and the black outline appear (plus the background).
TEST(SceneRender, NprHasFlatBandsAndAnOutline) {
  Scene s = with_shader(std::make_shared<NprShader>());
  s.objects.pop_back();  // no floor
  const std::vector<uint8_t> px = render(s, 240, 120, 1);
  std::map<uint32_t, int> colours;
  for (size_t i = 0; i < px.size(); i += 4) ++colours[uint32_t(px[i]) | uint32_t(px[i + 1]) << 8 | uint32_t(px[i + 2]) << 16];
  EXPECT_EQ(colours.size(), 4u);  // background, black, kd, kd / 2
  EXPECT_GT(colours[0], 50);      // the outline
}

// The normal view of a sphere: up-facing pixels are green, the depth view is brighter for
// the nearer sphere.
TEST(SceneRender, NormalAndDepthViewsEncodeWhatTheySay) {
  Scene s = with_shader(std::make_shared<NormalShader>());
  s.objects.pop_back();
  s.objects.pop_back();  // the left sphere alone
  std::vector<uint8_t> px = render(s, 240, 120, 1);
  int top_y = -1, top_x = 0;
  for (int y = 119; y >= 0 && top_y < 0; --y)
    for (int x = 0; x < 240; ++x)
      if (px[(size_t(y) * 240 + size_t(x)) * 4 + 3] == 255 && px[(size_t(y) * 240 + size_t(x)) * 4 + 1] > 200) {
        top_y = y;
        top_x = x;
        break;
      }
  ASSERT_GE(top_y, 0) << "no up-facing pixel";
  EXPECT_LT(top_x, 120);  // the left sphere
  Scene d = with_shader(std::make_shared<DepthShader>());
  d.objects.pop_back();
  d.objects[1]->transform.position.z = -3.0f;  // push the right sphere back
  px = render(d, 240, 120, 1);
  auto grey_at = [&](int x, int y) { return int(px[(size_t(y) * 240 + size_t(x)) * 4]); };
  int left = 0, right = 0;
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 240; ++x) {
      const int g = grey_at(x, y);
      if (x < 120) left = std::max(left, g);
      else right = std::max(right, g);
    }
  EXPECT_GT(left, right + 10);
}
