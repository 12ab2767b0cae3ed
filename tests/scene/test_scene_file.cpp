// Scene files: every shipped scene renders as its golden image, animation advances, and bad
// files are errors that name the file, the place and the problem.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "golden.hpp"
#include "tessel/gpu/framebuffer.hpp"
#include "tessel/scene/scene_file.hpp"

using namespace tessel;
using namespace tessel::scene;

namespace {

gpu::Texture2D render_small(SceneFile& f, int w, int h) {
  gpu::Texture2D color(gpu::Format::RGBA8, w, h), depth(gpu::Format::Depth24Stencil8, w, h);
  f.scene.camera.aspect = float(w) / float(h);
  gpu::Framebuffer fb(&color, &depth);
  gpu::Context ctx(2);
  ctx.bind_framebuffer(&fb);
  f.scene.Render(ctx);
  ctx.finish();
  return color;
}

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "bad.json");
  } catch (const gpu::Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(SceneFile, EveryShippedSceneMatchesItsGoldenImage) {
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(TESSEL_SCENES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    SceneFile f = load_scene_file(entry.path().string());
    EXPECT_GT(f.scene.objects.size(), 0u) << entry.path();
    const gpu::Texture2D img = render_small(f, 200, 150);
    test::expect_golden("file_" + entry.path().stem().string(), img);
    ++n;
  }
  EXPECT_GE(n, 4);
}

TEST(SceneFile, FieldsReachTheScene) {
  SceneFile f = parse_scene(R"({
    "render": {"size": [320, 200], "background": [0.1, 0.2, 0.3], "threads": 2, "fps": 24},
    "camera": {"eye": [1, 2, 3], "lookat": [0, 0, 0], "fov": 60, "near": 0.2, "far": 20},
    "lights": [{"position": [1, 1, 1], "ambient": 0.2, "color": [1, 0.5, 0.25],
                "spot": {"direction": [0, -1, 0], "cutoff": 30, "exponent": 4}}],
    "materials": {"m": {"kd": [0.5, 0.25, 1], "ks": 0.5, "shininess": 12, "specular": "phong"}},
    "objects": [{"name": "a", "geometry": {"type": "torus", "major": 2, "minor": 0.5, "rows": 4, "columns": 8},
                 "material": "m", "shader": "gouraud", "position": [1, 0, 0], "scale": 2,
                 "rotation": {"axis": [0, 0, 1], "angle": 90}, "animate": {"spin": 180, "velocity": [0, 1, 0]}},
                {"parent": "a", "geometry": {"type": "plane"}}]
  })",
                            "fields.json");
  EXPECT_EQ(f.render.width, 320);
  EXPECT_EQ(f.render.threads, 2);
  EXPECT_FLOAT_EQ(f.render.fps, 24.0f);
  EXPECT_NEAR(f.scene.camera.fov, 60.0f * 3.14159265f / 180.0f, 1e-6f);
  EXPECT_FLOAT_EQ(f.scene.camera.aspect, 1.6f);
  ASSERT_EQ(f.scene.lights.size(), 1u);
  EXPECT_EQ(f.scene.lights[0].wLightPos, glm::vec4(1, 1, 1, 1));
  EXPECT_NEAR(f.scene.lights[0].spot_cos_cutoff, std::cos(30.0f * 3.14159265f / 180.0f), 1e-6f);
  ASSERT_EQ(f.scene.objects.size(), 2u);
  const Object& a = *f.scene.objects[0];
  EXPECT_EQ(a.material->kd, glm::vec3(0.5f, 0.25f, 1.0f));
  EXPECT_EQ(a.material->ka, glm::vec3(0.05f, 0.025f, 0.1f));  // 0.1 kd when not given
  EXPECT_EQ(a.material->specular, Specular::Phong);
  EXPECT_EQ(f.scene.objects[1]->material->specular, Specular::Blinn);
  EXPECT_EQ(a.transform.scale, glm::vec3(2.0f));
  EXPECT_EQ(a.geometry->triangles(), 4 * 8 * 2);
  EXPECT_EQ(f.scene.objects[1]->transform.parent, &a.transform);
  f.scene.Animate(0.5f);
  EXPECT_NEAR(a.transform.angle, 3.14159265f, 1e-5f);  // 90 + 180 * 0.5 degrees
  EXPECT_EQ(a.transform.position, glm::vec3(1.0f, 0.5f, 0.0f));
}

TEST(SceneFile, TheFlagWaves) {
  SceneFile f = parse_scene(R"({"objects": [{"geometry": {"type": "flag", "rows": 2, "columns": 8},
                                "animate": {"flag_phase": 1.5}}]})",
                            "flag.json");
  const auto before = f.scene.objects[0]->geometry;
  f.scene.Animate(0.25f);
  const auto after = f.scene.objects[0]->geometry;
  ASSERT_NE(before, after);
  EXPECT_NE(before->mesh().vertices[1].pos.z, after->mesh().vertices[1].pos.z);
}

TEST(SceneFile, MistakesNameTheFileThePlaceAndTheProblem) {
  const std::pair<const char*, const char*> cases[] = {
      {"{\n  \"objects\": [\n    {\"geometry\": }\n  ]\n}",
       "bad.json:3:18: syntax error while parsing value"},
      {"[1, 2]", "bad.json: scene: expected an object"},
      {"444e440000000088",
       "bad.json: number overflow parsing '444e440000000088'"},  // found by fuzz_scene_file
      {R"({"objectz": []})", "bad.json: scene: unknown field 'objectz'"},
      {R"({"objects": [{"geometry": {"type": "cubee"}}]})",
       "bad.json: scene.objects[0].geometry.type: unknown surface 'cubee'"},
      {R"({"objects": [{"material": "x"}]})", "bad.json: scene.objects[0]: missing field 'geometry'"},
      {R"({"objects": [{"geometry": {"type": "sphere"}, "material": "gold"}]})",
       "scene.objects[0].material: no material named 'gold'"},
      {R"({"objects": [{"geometry": {"type": "sphere", "rows": 0}}]})",
       "scene.objects[0].geometry.rows: value 0 is outside 1 .. 4096"},
      {R"({"objects": [{"geometry": {"type": "sphere", "radius": "big"}}]})",
       "scene.objects[0].geometry.radius: expected a number"},
      {R"({"objects": [{"geometry": {"type": "sphere"}, "position": [1, 2]}]})",
       "scene.objects[0].position: expected an array of 3 numbers"},
      {R"({"objects": [{"geometry": {"type": "sphere"}, "shader": "toon"}]})",
       "scene.objects[0].shader: unknown shader 'toon'"},
      {R"({"objects": [{"name": "a", "parent": "b", "geometry": {"type": "sphere"}},
                       {"name": "b", "parent": "a", "geometry": {"type": "sphere"}}]})",
       "the parents form a cycle"},
      {R"({"objects": [{"parent": "nobody", "geometry": {"type": "sphere"}}]})",
       "scene.objects[0].parent: no object named 'nobody'"},
      {R"({"camera": {"eye": [0, 0, 0], "lookat": [0, 0, 0]}})",
       "bad.json: camera: eye and lookat are the same point"},
      {R"({"lights": [{"color": 1}]})", "scene.lights[0]: give either 'position'"},
      {R"({"render": {"size": [0, 10]}})", "scene.render.size[0]: value 0 is outside 1 .. 16384"},
      {R"({"textures": {"t": {"file": "no/such.png"}}})", "scene.textures.t: "},
      {R"({"materials": {"m": {"texture": "t"}}})", "scene.materials.m.texture: no texture named 't'"},
      {R"({"materials": {"m": {"specular": "cook"}}})",
       "scene.materials.m.specular: unknown specular model 'cook' (expected blinn or phong)"},
      {R"({"objects": [{"geometry": {"type": "sphere"}, "animate": {"flag_phase": 1}}]})",
       "only a flag has a phase"},
  };
  for (const auto& [text, expect] : cases) {
    const std::string e = error_of(text);
    EXPECT_NE(e.find(expect), std::string::npos)
        << "for " << text << "\n got: " << e << "\n want: " << expect;
  }
  try {
    load_scene_file("/no/such/scene.json");
    FAIL();
  } catch (const gpu::Error& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/scene.json: cannot open"), std::string::npos) << e.what();
  }
}
