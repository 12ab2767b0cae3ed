// The GLSL twins of the scene shaders (tessel/scene/glsl_shaders.hpp) against the C++ shaders
// on every shipped scene: at most 0.01% of the pixels may differ by more than 1/255.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tessel/gpu/framebuffer.hpp"
#include "tessel/gpu/image.hpp"
#include "tessel/scene/glsl_shaders.hpp"
#include "tessel/scene/scene_file.hpp"

using namespace tessel;

namespace {

std::vector<uint8_t> render(const std::string& path, const std::string& shading, bool glsl, int w, int h) {
  scene::SceneFile file = scene::load_scene_file(path);
  const auto shader = glsl ? scene::glsl_shader_by_name("glsl-" + shading) : scene::shader_by_name(shading);
  EXPECT_TRUE(shader != nullptr);
  for (auto& obj : file.scene.objects) obj->shader = shader;
  file.scene.camera.aspect = float(w) / float(h);
  gpu::Texture2D color(gpu::Format::RGBA8, w, h), depth(gpu::Format::Depth24Stencil8, w, h);
  gpu::Framebuffer fb(&color, &depth);
  gpu::Context ctx(2);
  ctx.bind_framebuffer(&fb);
  file.scene.Render(ctx);
  ctx.finish();
  return gpu::read_rgba8(color);
}

double percent_over(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b, int tolerance) {
  size_t n = 0;
  for (size_t i = 0; i + 3 < a.size(); i += 4) {
    bool d = false;
    for (int c = 0; c < 4; ++c) d = d || std::abs(int(a[i + c]) - int(b[i + c])) > tolerance;
    n += d;
  }
  return 100.0 * double(n) / double(a.size() / 4);
}

std::vector<std::string> scene_files() {
  std::vector<std::string> v;
  for (const auto& e : std::filesystem::directory_iterator(TESSEL_SCENES_DIR))
    if (e.path().extension() == ".json") v.push_back(e.path().string());
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

class Twins : public ::testing::TestWithParam<std::string> {};

TEST_P(Twins, GlslRendersTheShippedScenesAsTheCppShaders) {
  const std::string shading = GetParam();
  const auto files = scene_files();
  ASSERT_GE(files.size(), 10u);
  int compared = 0;
  double worst = 0.0;
  for (const std::string& path : files) {
    SCOPED_TRACE(path);
    const auto cpp = render(path, shading, false, 320, 180);
    const auto twin = render(path, shading, true, 320, 180);
    ASSERT_EQ(cpp.size(), twin.size());
    const double pct = percent_over(cpp, twin, 1);
    EXPECT_LE(pct, 0.01) << shading << " on " << path << ": " << pct
                         << "% of the pixels differ by more than 1/255";
    worst = std::max(worst, pct);
    ++compared;
  }
  std::printf("%s: %d scenes compared, at most %.4f%% of a scene's pixels more than 1/255 apart\n",
              shading.c_str(), compared, worst);
}
INSTANTIATE_TEST_SUITE_P(Scene, Twins,
                         ::testing::Values("gouraud", "phong", "normalmap", "npr", "depth", "normal"));

// The tolerance catches a real difference: the NPR twin against the C++ Phong shader.
TEST(TwinsTolerance, CatchesADifferentShader) {
  const std::string path = std::string(TESSEL_SCENES_DIR) + "/gouraud_vs_phong.json";
  const auto cpp = render(path, "phong", false, 320, 180);
  const auto other = render(path, "gouraud", true, 320, 180);
  EXPECT_GT(percent_over(cpp, other, 1), 0.01);
}
