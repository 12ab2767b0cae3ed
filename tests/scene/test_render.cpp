// The scene engine rendering: the shader library against golden images, and the properties
// that show each shader does what its name says.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "golden.hpp"
#include "tessel/gpu/framebuffer.hpp"
#include "tessel/scene/shaders.hpp"
#include "test_scenes.hpp"

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
  for (size_t i = 0; i < px.size(); i += 4)
    ++colours[uint32_t(px[i]) | uint32_t(px[i + 1]) << 8 | uint32_t(px[i + 2]) << 16];
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
      if (px[(size_t(y) * 240 + size_t(x)) * 4 + 3] == 255 &&
          px[(size_t(y) * 240 + size_t(x)) * 4 + 1] > 200) {
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
      if (x < 120)
        left = std::max(left, g);
      else
        right = std::max(right, g);
    }
  EXPECT_GT(left, right + 10);
}

// --- shadow mapping ---------------------------------------------------------------------------

namespace {

// A floor, a cylinder standing on it at the origin, a directional light from the upper
// right: the cylinder's shadow falls along -x from its base.
Scene shadow_scene(bool with_cylinder, ShadowSettings settings) {
  Scene s;
  s.camera.eye = glm::vec3(0.0f, 6.0f, 6.0f);
  s.camera.lookat = glm::vec3(-1.0f, 0.0f, 0.0f);
  s.camera.fov = 0.8f;
  s.camera.aspect = 1.0f;
  s.camera.near = 1.0f;
  s.camera.far = 30.0f;
  Light sun;
  sun.wLightPos = glm::vec4(1.0f, 1.2f, 0.0f, 0.0f);
  sun.La = glm::vec3(0.1f);
  sun.Le = glm::vec3(0.9f);
  s.lights = {sun};
  s.shadows = settings;
  s.shadows.enabled = true;
  auto phong = std::make_shared<PhongShader>();
  auto grey = std::make_shared<Material>();
  grey->kd = glm::vec3(0.8f);
  grey->ka = glm::vec3(0.8f);
  grey->ks = glm::vec3(0.0f);
  s.add(
      std::make_unique<Object>(std::make_shared<Geometry>(Plane(12.0f).create(4, 4), "floor"), grey, phong));
  if (with_cylinder) {
    auto& c = s.add(std::make_unique<Object>(
        std::make_shared<Geometry>(Cylinder(0.4f, 2.0f).create(1, 32), "post"), grey, phong));
    c.cull_back_faces = false;
  }
  return s;
}

struct Shot {
  std::vector<uint8_t> px;
  glm::mat4 VP;
  int size;
  // The red channel where the world point p lands.
  int at(const glm::vec3& p) const {
    const glm::vec4 c = VP * glm::vec4(p, 1.0f);
    const int x = int((c.x / c.w * 0.5f + 0.5f) * float(size)),
              y = int((c.y / c.w * 0.5f + 0.5f) * float(size));
    return px[(size_t(y) * size_t(size) + size_t(x)) * 4];
  }
};

Shot shoot(const Scene& s, int size = 256) {
  return {render(s, size, size, 2), s.camera.P() * s.camera.V(), size};
}

}  // namespace

// Shadow acne: a floor with nothing above it must be lit everywhere, exactly as without
// shadows. Without the bias the floor shadows itself.
TEST(Shadows, NoAcneOnAnUnoccludedFloor) {
  Scene lit = shadow_scene(false, {});
  lit.shadows.enabled = false;
  const std::vector<uint8_t> ref = render(lit, 256, 256, 2);
  const test::ImageDiff d = test::diff_rgba(ref, render(shadow_scene(false, {}), 256, 256, 2));
  EXPECT_EQ(d.differing, 0) << d.differing << " floor pixels darkened by acne";
  ShadowSettings none;
  none.slope_bias = 0.0f;
  none.constant_bias = 0.0f;
  const test::ImageDiff acne = test::diff_rgba(ref, render(shadow_scene(false, none), 256, 256, 2));
  EXPECT_GT(acne.differing, 256 * 256 / 20) << "without bias the floor should show acne";
}

// Peter-panning: the shadow must start at the foot of the post, not a gap away from it. A
// constant bias far too large detaches it (which this test must notice).
TEST(Shadows, TheShadowTouchesTheFootOfTheCaster) {
  const Shot s = shoot(shadow_scene(true, {}));
  const int lit = s.at({-3.0f, 0.0f, 2.5f});        // open floor
  const int near_foot = s.at({-0.5f, 0.0f, 0.0f});  // 0.1 past the post's radius, toward the shadow
  const int mid = s.at({-1.2f, 0.0f, 0.0f});
  EXPECT_LT(near_foot, lit * 6 / 10) << "lit " << lit << ", beside the foot " << near_foot;
  EXPECT_LT(mid, lit * 6 / 10);
  ShadowSettings far;
  far.constant_bias = 4e6f;  // about 5 scene units of depth: more than the post is thick
  const Shot detached = shoot(shadow_scene(true, far));
  EXPECT_GT(detached.at({-0.5f, 0.0f, 0.0f}), lit * 8 / 10) << "a huge bias should detach the shadow";
}

// Percentage-closer filtering: a larger kernel widens the band of partly lit pixels along
// the shadow's edge.
TEST(Shadows, LargerPcfKernelsGiveSofterEdges) {
  auto penumbra = [](int pcf) {
    ShadowSettings st;
    st.pcf = pcf;
    st.size = 512;
    const Shot s = shoot(shadow_scene(true, st));
    const int lit = s.at({-3.0f, 0.0f, 2.5f}), dark = s.at({-1.5f, 0.0f, 0.0f});
    int n = 0;
    for (size_t i = 0; i < s.px.size(); i += 4) {
      const int v = s.px[i];
      if (v > dark + (lit - dark) / 10 && v < lit - (lit - dark) / 10) ++n;
    }
    return n;
  };
  const int hard = penumbra(0), soft = penumbra(2), softer = penumbra(4);
  EXPECT_GT(soft, hard + hard / 4) << "pcf 0: " << hard << ", pcf 2: " << soft;
  EXPECT_GT(softer, soft) << "pcf 2: " << soft << ", pcf 4: " << softer;
}

TEST(Shadows, BadSettingsAreErrors) {
  ShadowSettings st;
  st.light = 3;
  EXPECT_THROW(render(shadow_scene(true, st), 32, 32, 1), gpu::Error);
  ShadowSettings big;
  big.size = 9000;
  EXPECT_THROW(render(shadow_scene(true, big), 32, 32, 1), gpu::Error);
}

// A point light among the objects casts shadows every way (a cube of six maps): four posts
// around it each darken the floor behind them, and the floor between light and post is lit.
TEST(Shadows, APointLightCastsShadowsInEveryDirection) {
  Scene s = shadow_scene(false, {});
  s.lights[0].wLightPos = glm::vec4(0.0f, 1.0f, 0.0f, 1.0f);
  s.lights[0].attenuation = glm::vec3(1.0f, 0.0f, 0.0f);
  s.camera.eye = glm::vec3(0.0f, 12.0f, 0.01f);
  s.camera.lookat = glm::vec3(0.0f);
  auto post = std::make_shared<Geometry>(Cylinder(0.3f, 2.0f).create(1, 24), "post");
  const glm::vec3 at[4] = {{2, 0, 0}, {-2, 0, 0}, {0, 0, 2}, {0, 0, -2}};
  for (const glm::vec3& p : at) {
    auto& o = s.add(std::make_unique<Object>(post, s.objects[0]->material, std::make_shared<PhongShader>()));
    o.transform.position = p;
    o.cull_back_faces = false;
  }
  const Shot shot = shoot(s);
  for (const glm::vec3& p : at) {
    const glm::vec3 dir = glm::normalize(p);
    const int before = shot.at(dir * 1.2f), behind = shot.at(dir * 3.2f);
    EXPECT_GT(before, 40) << "between the light and the post at " << p.x << ", " << p.z;
    EXPECT_LT(behind, before / 3) << "behind the post at " << p.x << ", " << p.z << ": " << behind << " vs "
                                  << before;
  }
}

// PCF near a cube-face edge: a post's shadow on the floor crosses the edge between the -Y
// and +X maps (where the floor is 45 degrees from below the light). Taps past one face's
// edge are compared on the next face, so the shadow stays dark across it; read as lit,
// they drew a bright band across the shadow.
TEST(Shadows, PcfContinuesAcrossCubeFaceEdges) {
  ShadowSettings st;
  st.size = 64;
  st.pcf = 2;
  Scene s = shadow_scene(false, st);
  s.lights[0].wLightPos = glm::vec4(0.0f, 1.0f, 0.0f, 1.0f);
  s.camera.eye = glm::vec3(1.4f, 6.0f, 0.01f);
  s.camera.lookat = glm::vec3(1.4f, 0.0f, 0.0f);
  auto& post =
      s.add(std::make_unique<Object>(std::make_shared<Geometry>(Cylinder(0.15f, 0.8f).create(1, 24), "post"),
                                     s.objects[0]->material, std::make_shared<PhongShader>()));
  post.transform.position = glm::vec3(0.5f, 0.0f, 0.0f);
  post.cull_back_faces = false;
  const Shot shot = shoot(s);
  const int lit = shot.at({1.0f, 0.0f, 1.0f});
  int brightest = 0;
  float where = 0.0f;
  for (float x = 0.8f; x <= 2.0f; x += 0.005f)
    if (shot.at({x, 0.0f, 0.0f}) > brightest) {
      brightest = shot.at({x, 0.0f, 0.0f});
      where = x;
    }
  EXPECT_GT(lit, 60);
  EXPECT_LT(brightest, lit / 3) << "in the shadow at x = " << where << ": " << brightest << ", lit floor "
                                << lit;
  // Nor may a lit floor darken along the edges: the taps' compares there are the receiver's.
  s.objects.pop_back();
  const std::vector<uint8_t> open = render(s, 256, 256, 2);
  s.shadows.enabled = false;
  const test::ImageDiff d = test::diff_rgba(render(s, 256, 256, 2), open);
  EXPECT_EQ(d.differing, 0) << d.differing << " pixels of the unoccluded floor are shadowed";
}

// Projected planar shadows: the sphere's shadow is centred where the ray from the light
// through its centre meets the floor, in exactly the shadow colour; the floor itself (in the
// plane) casts nothing, so far from the sphere the floor keeps its shading.
TEST(PlanarShadows, TheShadowLiesAlongTheLightRay) {
  Scene s = shadow_scene(true, {});
  s.shadows.enabled = false;
  s.objects.pop_back();  // no post
  auto ball = std::make_shared<Geometry>(Sphere(0.5f).create(16, 32), "ball");
  auto& b = s.add(std::make_unique<Object>(ball, s.objects[0]->material, std::make_shared<PhongShader>()));
  b.transform.position = glm::vec3(0.0f, 1.5f, 0.0f);
  s.lights[0].wLightPos = glm::vec4(1.0f, 4.0f, 0.5f, 1.0f);  // a point light
  s.planar_shadows.enabled = true;
  s.planar_shadows.color = glm::vec3(0.0f, 0.0f, 1.0f);  // blue, to tell it from shading
  const Shot shot = shoot(s);
  // L + t (C - L) with y = 0: t = 4 / 2.5.
  const glm::vec3 L(1.0f, 4.0f, 0.5f), C(0.0f, 1.5f, 0.0f), X = L + (C - L) * (4.0f / 2.5f);
  auto pixel = [&](const glm::vec3& p) {
    const glm::vec4 c = shot.VP * glm::vec4(p, 1.0f);
    const int x = int((c.x / c.w * 0.5f + 0.5f) * 256.0f), y = int((c.y / c.w * 0.5f + 0.5f) * 256.0f);
    const uint8_t* q = &shot.px[(size_t(y) * 256 + size_t(x)) * 4];
    return glm::ivec3(q[0], q[1], q[2]);
  };
  EXPECT_EQ(pixel(X), glm::ivec3(0, 0, 255));
  EXPECT_NE(pixel(glm::vec3(-3.0f, 0.0f, 2.5f)), glm::ivec3(0, 0, 255));  // open floor
  EXPECT_NE(pixel(X + glm::vec3(1.2f, 0.0f, 0.0f)), glm::ivec3(0, 0, 255));
}

// Deferred shading computes the same formula as PhongShader from the G-buffer: the images of
// one scene agree (pixels off by more than 2/255 at most 0.1%).
TEST(Deferred, AgreesWithForwardPhong) {
  Scene fwd = tessel::test::make_scene(40.0f, /*gouraud_left=*/false);
  const std::vector<uint8_t> a = render(fwd, 240, 120, 2);
  Scene def = tessel::test::make_scene(40.0f, false);
  def.deferred = true;
  const std::vector<uint8_t> b = render(def, 240, 120, 2);
  const test::ImageDiff d = test::diff_rgba(a, b);
  EXPECT_TRUE(d.passes()) << d.differing << " of " << d.total << " pixels differ (max " << d.max_diff << ")";
  std::printf("deferred vs forward: %d of %d pixels differ by more than 2/255 (max %d)\n", d.differing,
              d.total, d.max_diff);
  // Identical for any thread count, and it takes more lights than forward shading.
  EXPECT_EQ(b, render(def, 240, 120, 1));
  def.lights.resize(40, def.lights[1]);
  EXPECT_NO_THROW(render(def, 32, 32, 1));
  fwd.lights.resize(40, fwd.lights[1]);
  EXPECT_THROW(render(fwd, 32, 32, 1), gpu::Error);
}

// Normal mapping: a map whose normals all lean toward +u must light a surface as if it were
// turned toward its d(position)/du: brighter under a light from that side, darker from the
// other. Checked at the middle of a floor and of a sphere (a left-handed parametrization),
// and a flat map (0, 0, 1) must give PhongShader's image.
TEST(NormalMap, TheMapTurnsTheSurfaceTheWayItSays) {
  auto constant_map = [](glm::vec3 n) {
    n = glm::normalize(n);
    std::vector<uint8_t> px(16 * 16 * 4);
    for (size_t i = 0; i < px.size(); i += 4) {
      for (int c = 0; c < 3; ++c) px[i + size_t(c)] = uint8_t(std::lround((n[c] * 0.5f + 0.5f) * 255.0f));
      px[i + 3] = 255;
    }
    auto t = std::make_shared<gpu::Texture2D>(gpu::Format::RGBA8, 16, 16, 0);
    t->upload_rgba8(0, px.data(), px.size());
    t->generate_mipmaps();
    return t;
  };
  auto centre_value = [&](std::shared_ptr<const Geometry> g, glm::vec3 light_dir,
                          std::shared_ptr<gpu::Texture2D> map, std::shared_ptr<const Shader> shader) {
    Scene s;
    s.camera.eye = glm::vec3(0.0f, 0.0f, 4.0f);
    s.camera.lookat = glm::vec3(0.0f);
    s.camera.aspect = 1.0f;
    Light l;
    l.wLightPos = glm::vec4(light_dir, 0.0f);
    l.La = glm::vec3(0.0f);
    s.lights = {l};
    auto m = std::make_shared<Material>();
    m->kd = glm::vec3(0.8f);
    m->ks = glm::vec3(0.0f);
    m->normal_map = map;
    s.add(std::make_unique<Object>(g, m, shader));
    const std::vector<uint8_t> px = render(s, 64, 64, 1);
    return int(px[(32 * 64 + 32) * 4]);
  };
  const auto nm = std::make_shared<NormalMapShader>();
  const auto lean = constant_map({0.6f, 0.0f, 0.8f}), flat = constant_map({0.0f, 0.0f, 1.0f});
  // A square facing the camera: the plane turned up toward +z, so u runs along +x.
  auto plane =
      std::make_shared<Object>(std::make_shared<Geometry>(Plane(2.0f).create(2, 2), "p"), nullptr, nm);
  Mesh square = Plane(2.0f).create(2, 2);
  for (VertexData& v : square.vertices) {
    v.pos = glm::vec3(v.pos.x, -v.pos.z, 0.0f);
    v.norm = glm::vec3(0.0f, 0.0f, 1.0f);
  }
  const auto sq = std::make_shared<Geometry>(square, "square");
  const glm::vec3 from_u(1.0f, 0.0f, 0.6f), from_minus_u(-1.0f, 0.0f, 0.6f);
  EXPECT_GT(centre_value(sq, from_u, lean, nm), centre_value(sq, from_u, flat, nm) + 20);
  EXPECT_LT(centre_value(sq, from_minus_u, lean, nm), centre_value(sq, from_minus_u, flat, nm) - 20);
  EXPECT_NEAR(centre_value(sq, from_u, flat, nm),
              centre_value(sq, from_u, flat, std::make_shared<PhongShader>()), 1);
  // The sphere's front point (u = 0.25, v = 0.5 faces +y in the notes' parametrization, so
  // turn it toward the camera): d(position)/du there is the direction to light from.
  Transform t;
  t.axis = glm::vec3(1.0f, 0.0f, 0.0f);
  t.angle = 1.5707963f;
  Mesh ball = Sphere().create(32, 64);
  for (VertexData& v : ball.vertices) {
    v.pos = glm::vec3(t.M() * glm::vec4(v.pos, 1.0f));
    v.norm = glm::vec3(t.M() * glm::vec4(v.norm, 0.0f));
  }
  glm::vec3 a, b, unused;
  Sphere().eval(0.26f, 0.5f, a, unused);
  Sphere().eval(0.24f, 0.5f, b, unused);
  const glm::vec3 du = glm::normalize(glm::vec3(t.M() * glm::vec4(a - b, 0.0f)));
  const auto sphere = std::make_shared<Geometry>(ball, "ball");
  const glm::vec3 light = du + glm::vec3(0.0f, 0.0f, 0.6f);
  EXPECT_GT(centre_value(sphere, light, lean, nm), centre_value(sphere, light, flat, nm) + 20)
      << "du " << du.x << " " << du.y << " " << du.z;
  (void)plane;
}

// The pipeline counts fragments the depth test rejects: none for one convex object, and the
// floor drawn after the spheres loses the pixels they cover (at most their pixel count).
TEST(SceneRender, FragmentsRejectedByDepthAreCounted) {
  auto stats_of = [](const Scene& s) {
    gpu::Texture2D color(gpu::Format::RGBA8, 240, 120), depth(gpu::Format::Depth24Stencil8, 240, 120);
    gpu::Framebuffer fb(&color, &depth);
    gpu::Context ctx(2);
    ctx.bind_framebuffer(&fb);
    s.Render(ctx);
    ctx.finish();
    return ctx.stats();
  };
  Scene one = tessel::test::make_scene();
  one.objects.resize(1);
  EXPECT_EQ(stats_of(one).fragments_rejected, 0u);
  Scene spheres = tessel::test::make_scene();
  spheres.objects.pop_back();
  const gpu::Stats a = stats_of(spheres), all = stats_of(tessel::test::make_scene());
  EXPECT_GT(all.fragments_rejected, 500u);
  EXPECT_LE(all.fragments_rejected, a.fragments_written);
  EXPECT_EQ(all.fragments_shaded, all.fragments_written);  // early depth: rejected ones are never shaded
}

// Render(ctx, &passes) reports each pass with its own counters, which add up to the frame's,
// and the image is the one Render(ctx) draws.
TEST(SceneRender, PassesAreTimedAndCountedApart) {
  auto run = [](const Scene& s, std::vector<PassStats>* passes, gpu::Stats& total) {
    gpu::Texture2D color(gpu::Format::RGBA8, 128, 128), depth(gpu::Format::Depth24Stencil8, 128, 128);
    gpu::Framebuffer fb(&color, &depth);
    gpu::Context ctx(2);
    ctx.bind_framebuffer(&fb);
    s.Render(ctx, passes);
    ctx.finish();
    total = ctx.stats();
    return gpu::read_rgba8(color);
  };
  auto names = [](const std::vector<PassStats>& p) {
    std::string n;
    for (const PassStats& x : p) n += (n.empty() ? "" : " ") + x.name;
    return n;
  };
  Scene s = shadow_scene(true, {});
  s.planar_shadows.enabled = true;
  gpu::Stats plain_total, total;
  std::vector<PassStats> passes;
  const std::vector<uint8_t> plain = run(s, nullptr, plain_total);
  EXPECT_EQ(run(s, &passes, total), plain);
  EXPECT_EQ(names(passes), "shadow objects planar_shadows");
  uint64_t tris = 0, frags = 0;
  for (const PassStats& p : passes) {
    EXPECT_GE(p.ms, 0.0);
    EXPECT_GT(p.counters.primitives_in, 0u) << p.name;
    tris += p.counters.primitives_in;
    frags += p.counters.fragments_written;
  }
  EXPECT_EQ(tris, total.primitives_in);
  EXPECT_EQ(frags, total.fragments_written);
  EXPECT_EQ(total.primitives_in, plain_total.primitives_in);
  // The light pass draws the floor and the post once each, from the light.
  EXPECT_EQ(passes[0].counters.primitives_in, uint64_t(s.triangles()));

  Scene d = shadow_scene(true, {});
  d.shadows.enabled = false;
  d.deferred = true;
  passes.clear();
  run(d, &passes, total);
  EXPECT_EQ(names(passes), "gbuffer lighting");
  EXPECT_EQ(passes[1].counters.primitives_in, 1u);  // one full-screen triangle
}

// Phong's specular model mirrors L about N and takes R.V: where Blinn's N.H is cos(a), R.V
// is about cos(2a), so with one exponent Phong's highlight is much smaller, and a quarter of
// Blinn's exponent gives about Blinn's highlight. The deferred pass reads the model from the
// G-buffer and agrees with forward shading.
TEST(SceneRender, PhongSpecularModelNarrowsTheHighlightAndDeferredAgrees) {
  auto with_model = [](Specular model, float shininess, bool deferred) {
    Scene s = tessel::test::make_scene(shininess, /*gouraud_left=*/false);
    s.objects.pop_back();  // the spheres alone
    for (auto& o : s.objects) {
      auto m = std::make_shared<Material>(*o->material);
      m->specular = model;
      o->material = m;
    }
    s.deferred = deferred;
    return s;
  };
  auto highlight = [](const std::vector<uint8_t>& px) {
    int n = 0;
    for (size_t i = 0; i < px.size(); i += 4)
      if (px[i] > 200 && px[i + 1] > 150) ++n;  // red spheres turn white only in the highlight
    return n;
  };
  const std::vector<uint8_t> phong = render(with_model(Specular::Phong, 60.0f, false), 240, 120, 2);
  const int hb = highlight(render(with_model(Specular::Blinn, 60.0f, false), 240, 120, 2)),
            hp = highlight(phong);
  const int hq = highlight(render(with_model(Specular::Phong, 15.0f, false), 240, 120, 2));
  EXPECT_GT(hp, 5);
  EXPECT_GT(hb, 2 * hp) << "Blinn " << hb << " highlight pixels, Phong " << hp;
  EXPECT_GT(hq, hb * 2 / 3) << "Blinn at 60: " << hb << ", Phong at 15: " << hq;
  EXPECT_LT(hq, hb * 3 / 2) << "Blinn at 60: " << hb << ", Phong at 15: " << hq;
  const test::ImageDiff d =
      test::diff_rgba(phong, render(with_model(Specular::Phong, 60.0f, true), 240, 120, 2));
  EXPECT_TRUE(d.passes()) << d.differing << " of " << d.total << " pixels differ (max " << d.max_diff << ")";
}
