// The scene engine's geometry, camera and transforms: parametric surfaces tessellated without
// cracks and facing the right way, analytic normals that agree with the surface, and the
// matrices of the lecture notes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <random>
#include <tuple>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "tessel/gpu/format.hpp"
#include "tessel/scene/camera.hpp"
#include "tessel/scene/geometry.hpp"
#include "tessel/scene/transform.hpp"

using namespace tessel::scene;

namespace {

using Key = std::tuple<uint32_t, uint32_t, uint32_t>;
Key key(const glm::vec3& p) {
  uint32_t b[3];
  std::memcpy(b, &p, 12);
  return {b[0], b[1], b[2]};
}

// Every edge of the non-degenerate triangles, by the exact bits of its end points, used once
// in each direction: a closed surface with consistent winding and no cracks.
void expect_watertight(const Mesh& m, const char* name) {
  std::map<std::pair<Key, Key>, int> directed;
  const std::vector<uint32_t> t = m.triangle_list();
  int degenerate = 0;
  for (size_t i = 0; i < t.size(); i += 3) {
    const glm::vec3 p[3] = {m.vertices[t[i]].pos, m.vertices[t[i + 1]].pos, m.vertices[t[i + 2]].pos};
    if (key(p[0]) == key(p[1]) || key(p[1]) == key(p[2]) || key(p[0]) == key(p[2])) {
      ++degenerate;
      continue;
    }
    for (int k = 0; k < 3; ++k) ++directed[{key(p[k]), key(p[(k + 1) % 3])}];
  }
  int bad = 0;
  for (const auto& [e, n] : directed) {
    const auto it = directed.find({e.second, e.first});
    if (n != 1 || it == directed.end() || it->second != 1) ++bad;
  }
  EXPECT_EQ(bad, 0) << name << ": " << bad << " of " << directed.size()
                    << " edges are not shared exactly once each way";
  EXPECT_GT(directed.size(), 0u) << name;
  (void)degenerate;
}

// Counter-clockwise triangles seen from the side the normals point to.
void expect_facing_normals(const Mesh& m, const char* name) {
  const std::vector<uint32_t> t = m.triangle_list();
  int wrong = 0, counted = 0;
  for (size_t i = 0; i < t.size(); i += 3) {
    const VertexData &a = m.vertices[t[i]], &b = m.vertices[t[i + 1]], &c = m.vertices[t[i + 2]];
    const glm::vec3 g = glm::cross(b.pos - a.pos, c.pos - a.pos);
    if (glm::length(g) < 1e-9f) continue;
    ++counted;
    if (glm::dot(g, a.norm + b.norm + c.norm) <= 0.0f) ++wrong;
  }
  EXPECT_GT(counted, 0) << name;
  EXPECT_EQ(wrong, 0) << name << ": " << wrong << " of " << counted
                      << " triangles face away from their normals";
}

}  // namespace

TEST(Turns, ExactAtQuarterAndWholeTurns) {
  const float quarters[][3] = {{0.0f, 0.0f, 1.0f},   {0.25f, 1.0f, 0.0f}, {0.5f, 0.0f, -1.0f},
                               {0.75f, -1.0f, 0.0f}, {1.0f, 0.0f, 1.0f},  {-0.25f, -1.0f, 0.0f},
                               {3.5f, 0.0f, -1.0f}};
  for (const auto& q : quarters) {
    float s, c;
    sincos_turns(q[0], s, c);
    EXPECT_EQ(s, q[1]) << q[0];
    EXPECT_EQ(c, q[2]) << q[0];
  }
  for (int M : {3, 7, 25, 100, 1000}) {
    for (int j = 0; j <= M; ++j) {
      const float t = float(j) / float(M);
      float s0, c0, s1, c1;
      sincos_turns(t, s0, c0);
      sincos_turns(float(j % M) / float(M), s1, c1);  // j = M: one whole turn gives the bits of none
      EXPECT_EQ(s0, s1) << t;
      EXPECT_EQ(c0, c1) << t;
      EXPECT_NEAR(s0, std::sin(2.0 * M_PI * double(t)), 2e-6) << t;
      EXPECT_NEAR(c0, std::cos(2.0 * M_PI * double(t)), 2e-6) << t;
    }
  }
  float s, c;
  sincos_turns(NAN, s, c);
  EXPECT_EQ(s, 0.0f);
  EXPECT_EQ(c, 1.0f);
}

TEST(ParamSurface, NotesStripLayout) {
  const Mesh m = Sphere().create(4, 6);
  EXPECT_EQ(m.primitive, Primitive::TriangleStrip);
  EXPECT_EQ(m.strip_length, 2 * (6 + 1));
  EXPECT_EQ(m.indices.size(), size_t(4 * 2 * 7));
  EXPECT_EQ(m.vertices.size(), size_t(5 * 7));
  EXPECT_EQ(m.triangle_count(), 4 * 12);
  EXPECT_EQ(m.triangle_list().size(), size_t(3 * 4 * 12));
  // Texture coordinates are (u, v) = (j / M, i / N).
  EXPECT_EQ(m.vertices[7 * 2 + 3].tex, glm::vec2(3.0f / 6.0f, 2.0f / 4.0f));
  m.validate("sphere");
}

TEST(ParamSurface, SphereAndTorusAreWatertightAtTheirSeams) {
  for (int n : {3, 8, 21, 50}) {
    expect_watertight(Sphere(1.0f).create(n, 2 * n + 1), "sphere");
    expect_watertight(Sphere(2.5f, glm::vec3(1, 2, 3)).create(n, n), "offset sphere");
    expect_watertight(Torus(1.0f, 0.3f).create(n, 2 * n), "torus");
  }
}

TEST(ParamSurface, TrianglesFaceTheirNormals) {
  expect_facing_normals(Sphere().create(12, 24), "sphere");
  expect_facing_normals(Torus().create(12, 24), "torus");
  expect_facing_normals(Flag(2.0f, 1.0f, 0.2f, 3.0f, 0.7f).create(10, 30), "flag");
  expect_facing_normals(Cylinder().create(4, 16), "cylinder");
  expect_facing_normals(Cone().create(4, 16), "cone");
  expect_facing_normals(Plane(3.0f).create(3, 3), "plane");
  expect_facing_normals(FunctionSurface([](float u, float v) { return glm::vec3(u, v, u * v); }).create(5, 5),
                        "function");
}

TEST(ParamSurface, AnalyticNormalsMatchFiniteDifferences) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> uv(0.05f, 0.95f);
  std::vector<std::unique_ptr<ParamSurface>> surfaces;
  surfaces.push_back(std::make_unique<Flag>(2.0f, 1.0f, 0.3f, 3.0f, 0.4f));
  surfaces.push_back(std::make_unique<Flag>(1.0f, 1.5f, 0.05f, 1.0f, 2.0f));
  surfaces.push_back(std::make_unique<Sphere>(1.5f));
  surfaces.push_back(std::make_unique<Torus>(1.0f, 0.4f));
  surfaces.push_back(std::make_unique<Cylinder>(0.5f, 2.0f));
  surfaces.push_back(std::make_unique<Cone>(1.0f, 2.0f));
  for (size_t s = 0; s < surfaces.size(); ++s) {
    for (int i = 0; i < 200; ++i) {
      const float u = uv(rng), v = uv(rng), h = 1e-3f;
      glm::vec3 p, n, a, b, c, d, unused;
      surfaces[s]->eval(u, v, p, n);
      surfaces[s]->eval(u + h, v, a, unused);
      surfaces[s]->eval(u - h, v, b, unused);
      surfaces[s]->eval(u, v + h, c, unused);
      surfaces[s]->eval(u, v - h, d, unused);
      const glm::dvec3 fd = glm::normalize(glm::cross(glm::dvec3(a - b), glm::dvec3(c - d)));
      // Same line (the orientation is the surface's convention; create() orders the strips).
      EXPECT_GT(std::fabs(glm::dot(fd, glm::normalize(glm::dvec3(n)))), 0.9999)
          << "surface " << s << " at " << u << ", " << v;
    }
  }
}

TEST(ParamSurface, CreateNormalizesAndSphereNormalsAreRadial) {
  const glm::vec3 c(1.0f, -2.0f, 0.5f);
  const Mesh m = Sphere(2.0f, c).create(10, 20);
  for (const VertexData& v : m.vertices) {
    EXPECT_NEAR(glm::length(v.norm), 1.0f, 1e-6f);
    EXPECT_LT(glm::length(v.norm - (v.pos - c) / 2.0f), 1e-5f);
  }
  for (const VertexData& v : Flag(2.0f, 1.0f, 0.5f, 4.0f).create(5, 40).vertices)
    EXPECT_NEAR(glm::length(v.norm), 1.0f, 1e-6f);
}

TEST(ParamSurface, BadSizesAndBadMeshesAreErrors) {
  EXPECT_THROW(Sphere().create(0, 4), tessel::gpu::Error);
  EXPECT_THROW(Sphere().create(4, -1), tessel::gpu::Error);
  EXPECT_THROW(Sphere().create(5000, 4), tessel::gpu::Error);
  Mesh m = Plane().create(1, 1);
  m.indices[2] = 99;
  try {
    m.validate("floor");
    FAIL() << "no error";
  } catch (const tessel::gpu::Error& e) {
    EXPECT_NE(std::string(e.what()).find("floor: index 2 is 99"), std::string::npos) << e.what();
  }
  Mesh n = Plane().create(1, 1);
  n.vertices[1].pos.x = NAN;
  EXPECT_THROW(n.validate("nan"), tessel::gpu::Error);
}

TEST(Camera, MatchesGluLookAtPerspectiveAndOrtho) {
  Camera cam;
  cam.eye = glm::vec3(3.0f, 4.0f, 5.0f);
  cam.lookat = glm::vec3(0.0f, 1.0f, -1.0f);
  cam.vup = glm::vec3(0.0f, 1.0f, 0.2f);
  cam.fov = 0.9f;
  cam.aspect = 1.6f;
  cam.near = 0.25f;
  cam.far = 80.0f;
  cam.validate();
  const glm::mat4 V = glm::lookAt(cam.eye, cam.lookat, cam.vup);
  const glm::mat4 P = glm::perspective(cam.fov, cam.aspect, cam.near, cam.far);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(cam.V()[c][r], V[c][r], 1e-5f);
      EXPECT_NEAR(cam.P()[c][r], P[c][r], 1e-5f);
    }
  // The eye maps to the origin, the look-at point onto -z.
  const glm::vec4 e = cam.V() * glm::vec4(cam.eye, 1.0f), l = cam.V() * glm::vec4(cam.lookat, 1.0f);
  EXPECT_LT(glm::length(glm::vec3(e)), 1e-5f);
  EXPECT_LT(std::fabs(l.x) + std::fabs(l.y), 1e-5f);
  EXPECT_LT(l.z, 0.0f);
  cam.orthographic = true;
  cam.ortho_height = 4.0f;
  const glm::mat4 O = glm::ortho(-3.2f, 3.2f, -2.0f, 2.0f, 0.25f, 80.0f);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(cam.P()[c][r], O[c][r], 1e-6f);
}

TEST(Camera, DegenerateCamerasAreErrors) {
  Camera c;
  c.lookat = c.eye;
  EXPECT_THROW(c.validate(), tessel::gpu::Error);
  c = Camera();
  c.vup = glm::vec3(0.0f, 0.0f, 1.0f);  // along the view direction
  EXPECT_THROW(c.validate(), tessel::gpu::Error);
  c = Camera();
  c.near = 0.0f;
  EXPECT_THROW(c.validate(), tessel::gpu::Error);
  c = Camera();
  c.far = c.near;
  EXPECT_THROW(c.validate(), tessel::gpu::Error);
  c = Camera();
  c.fov = 3.2f;
  EXPECT_THROW(c.validate(), tessel::gpu::Error);
  c = Camera();
  c.aspect = NAN;
  EXPECT_THROW(c.validate(), tessel::gpu::Error);
}

TEST(Transform, InverseAndHierarchy) {
  Transform base;
  base.position = glm::vec3(1, 2, 3);
  base.axis = glm::vec3(0, 1, 0);
  base.angle = 0.7f;
  Transform arm;
  arm.parent = &base;
  arm.scale = glm::vec3(2.0f, 0.5f, 1.0f);
  arm.axis = glm::vec3(1, 1, 0);
  arm.angle = -0.4f;
  arm.position = glm::vec3(0, 1, 0);
  const glm::mat4 I = arm.world() * arm.world_inverse();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(I[c][r], c == r ? 1.0f : 0.0f, 1e-5f);
  const glm::mat4 expect = base.M() * arm.M();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(arm.world()[c][r], expect[c][r], 1e-6f);
  // Scale first, then rotate, then translate: the origin lands on the position.
  const glm::vec4 o = base.M() * glm::vec4(0, 0, 0, 1);
  EXPECT_EQ(glm::vec3(o), base.position);
}

// The classic bug: normals transformed by M instead of its inverse transpose tilt under
// non-uniform scale. The normal of a 45-degree plane must stay perpendicular to it.
TEST(Transform, NormalsUseTheInverseTranspose) {
  Transform t;
  t.scale = glm::vec3(4.0f, 1.0f, 1.0f);
  t.axis = glm::vec3(0, 0, 1);
  t.angle = 0.3f;
  const glm::vec3 tangent = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f)),
                  normal = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
  const glm::vec3 wt = glm::mat3(t.world()) * tangent;
  const glm::vec3 good = t.normal_matrix() * normal;
  const glm::vec3 naive = glm::mat3(t.world()) * normal;
  EXPECT_LT(std::fabs(glm::dot(glm::normalize(wt), glm::normalize(good))), 1e-6f);
  EXPECT_GT(std::fabs(glm::dot(glm::normalize(wt), glm::normalize(naive))), 0.5f);  // what the bug gives
}
