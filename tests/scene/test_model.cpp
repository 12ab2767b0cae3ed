// Models from OBJ/MTL files: parts and materials as the file says, normals where it has none
// (smooth, but creases kept), and bad files as errors naming the file, the face and the index.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "tessel/gpu/format.hpp"
#include "tessel/scene/model.hpp"

using namespace tessel;
using namespace tessel::scene;

namespace {
std::string error_of(const std::string& obj, const std::string& mtl = "") {
  try {
    parse_obj(obj, mtl, "bad.obj");
  } catch (const gpu::Error& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST(Obj, HouseHasItsPartsAndMaterials) {
  const Model m = load_obj(std::string(TESSEL_SCENES_DIR) + "/models/house.obj");
  ASSERT_EQ(m.parts.size(), 2u);
  ASSERT_EQ(m.materials.size(), 2u);
  const Model::Part& walls = m.parts[0];
  const Model::Part& roof = m.parts[1];
  EXPECT_EQ(walls.mesh.triangle_count(), 8);  // 4 quads
  EXPECT_EQ(roof.mesh.triangle_count(), 6);   // 2 triangles + 2 quads
  const Material& brick = *m.materials[size_t(walls.material)];
  EXPECT_EQ(brick.kd, glm::vec3(1.0f));
  EXPECT_FLOAT_EQ(brick.shininess, 8.0f);
  ASSERT_NE(brick.texture, nullptr);
  EXPECT_EQ(brick.texture->width(), 64);
  const Material& tiles = *m.materials[size_t(roof.material)];
  EXPECT_EQ(tiles.kd, glm::vec3(0.7f, 0.25f, 0.15f));
  EXPECT_EQ(tiles.texture, nullptr);
  // The walls' normals are the file's; the wall quad at z = 1 faces +z.
  EXPECT_EQ(walls.mesh.vertices[0].norm, glm::vec3(0.0f, 0.0f, 1.0f));
  walls.mesh.validate("walls");
  roof.mesh.validate("roof");
}

// The roof has no normals in the file: each face's corners get the face's own normal, since
// its neighbours all meet it at 90 degrees or more (the ridge and the gables stay sharp).
TEST(Obj, ComputedNormalsKeepCreasesAndSmoothCurves) {
  const Model m = load_obj(std::string(TESSEL_SCENES_DIR) + "/models/house.obj");
  const Mesh& roof = m.parts[1].mesh;
  for (size_t i = 0; i < roof.indices.size(); i += 3) {
    const VertexData &a = roof.vertices[roof.indices[i]], &b = roof.vertices[roof.indices[i + 1]],
                     &c = roof.vertices[roof.indices[i + 2]];
    const glm::vec3 n = glm::normalize(glm::cross(b.pos - a.pos, c.pos - a.pos));
    for (const VertexData* v : {&a, &b, &c}) EXPECT_GT(glm::dot(v->norm, n), 0.999f);
  }
  // A gently curved strip (faces 10 degrees apart) is smoothed: the shared edge gets the mean.
  const Model strip = parse_obj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 2 0.176\nv 1 2 0.176\nf 1 2 4 3\nf 3 4 6 5\n", "", "strip");
  const Mesh& s = strip.parts[0].mesh;
  int between = 0;
  for (const VertexData& v : s.vertices)
    if (v.pos.y == 1.0f) {
      EXPECT_NEAR(glm::length(v.norm), 1.0f, 1e-5f);
      EXPECT_LT(v.norm.z, 1.0f - 1e-4f);  // tilted away from the flat face's +z
      ++between;
    }
  EXPECT_EQ(between, 2);
}

TEST(Obj, BadFilesAreErrorsNamingWhatAndWhere) {
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n")
                .find("bad.obj: shape '', face 1: vertex index 99 is outside the 3 vertices"),
            std::string::npos)
      << error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//4\n")
                .find("normal index 4 is outside the 1 normals"),
            std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/3 2/1 3/1\nvt 0 0\n").find("texture coordinate index 3"),
            std::string::npos)
      << error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/3 2/1 3/1\nvt 0 0\n");
  EXPECT_NE(error_of("v 0 0 1e40\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").find("vertex 1 is not a finite number"),
            std::string::npos)
      << error_of("v 0 0 1e40\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(error_of("").find("bad.obj: no triangles"), std::string::npos);
  EXPECT_NE(error_of("# nothing\nv 1 2 3\n").find("no triangles"), std::string::npos);
  EXPECT_NE(error_of("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n",
                     "newmtl m\nmap_Kd /no/such.png\n")
                .find("bad.obj: material 'm': map_Kd: load_image: cannot open '/no/such.png'"),
            std::string::npos);
  try {
    load_obj("/no/such/model.obj");
    FAIL();
  } catch (const gpu::Error& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/model.obj: cannot open"), std::string::npos);
  }
}

// --- glTF 2.0 -------------------------------------------------------------------------------

namespace {
std::string read_text(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}
std::string gltf_error(const std::string& text) {
  try {
    parse_gltf(text.data(), text.size(), "bad.gltf");
  } catch (const gpu::Error& e) {
    return e.what();
  }
  return "(no error)";
}
std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}
}  // namespace

TEST(Gltf, NodeHierarchyMaterialsAndTexture) {
  const Model m = load_gltf(std::string(TESSEL_SCENES_DIR) + "/models/pyramids.gltf");
  ASSERT_EQ(m.parts.size(), 4u);  // big, small, mirror, top (base has no mesh)
  ASSERT_EQ(m.materials.size(), 2u);
  const Material& brick = *m.materials[0];
  ASSERT_NE(brick.texture, nullptr);
  EXPECT_EQ(brick.texture->width(), 64);
  EXPECT_EQ(brick.kd, glm::vec3(1.0f));
  EXPECT_NEAR(brick.ks.x, 0.04f, 1e-6f);  // a dielectric's Fresnel colour
  const Material& gold = *m.materials[1];
  EXPECT_NEAR(gold.ks.y, 0.76f, 1e-6f);  // a metal's is its base colour
  EXPECT_NEAR(gold.kd.y, 0.76f * 0.25f, 1e-6f);
  EXPECT_NEAR(gold.shininess, 2.0f / std::pow(0.35f, 4.0f) - 2.0f, 0.01f);
  // The apex of "top" (translation (0, 1, 0), scale 0.4, child of "small" at (1.5, 0, 0.4)
  // turned 45 degrees about y) lands at (1.5, 1.4, 0.4).
  bool found = false;
  for (const Model::Part& p : m.parts)
    for (const VertexData& v : p.mesh.vertices)
      found = found || glm::length(v.pos - glm::vec3(1.5f, 1.4f, 0.4f)) < 1e-5f;
  EXPECT_TRUE(found);
  // Every part, the mirrored one too, has its triangles facing its normals.
  for (const Model::Part& p : m.parts) {
    for (size_t i = 0; i < p.mesh.indices.size(); i += 3) {
      const VertexData &a = p.mesh.vertices[p.mesh.indices[i]], &b = p.mesh.vertices[p.mesh.indices[i + 1]],
                       &c = p.mesh.vertices[p.mesh.indices[i + 2]];
      EXPECT_GT(glm::dot(glm::cross(b.pos - a.pos, c.pos - a.pos), a.norm), 0.0f) << p.name;
    }
  }
}

TEST(Gltf, BinaryGlbGivesTheSameModel) {
  const Model a = load_gltf(std::string(TESSEL_SCENES_DIR) + "/models/pyramids.gltf");
  const Model b = load_gltf(std::string(TESSEL_SCENES_DIR) + "/models/pyramids.glb");
  ASSERT_EQ(a.parts.size(), b.parts.size());
  for (size_t i = 0; i < a.parts.size(); ++i) {
    ASSERT_EQ(a.parts[i].mesh.vertices.size(), b.parts[i].mesh.vertices.size());
    for (size_t v = 0; v < a.parts[i].mesh.vertices.size(); ++v)
      EXPECT_EQ(a.parts[i].mesh.vertices[v].pos, b.parts[i].mesh.vertices[v].pos);
  }
}

TEST(Gltf, BadFilesAreErrorsNamingWhatAndWhere) {
  const std::string good = read_text(std::string(TESSEL_SCENES_DIR) + "/models/pyramids.gltf");
  ASSERT_FALSE(good.empty());
  EXPECT_EQ(gltf_error(good), "(no error)");
  EXPECT_NE(gltf_error(good.substr(0, good.size() / 2)).find("bad.gltf: "), std::string::npos);
  EXPECT_NE(gltf_error("").find("bad.gltf: "), std::string::npos);
  EXPECT_NE(gltf_error("glTF\x02\0\0\0garbage").find("bad.gltf: "), std::string::npos);
  // An accessor whose elements run past its view.
  EXPECT_NE(gltf_error(replaced(good, "\"count\": 18,\n   \"type\": \"VEC2\"",
                                "\"count\": 40,\n   \"type\": \"VEC2\""))
                .find("TEXCOORD_0: accessor 2 reads past the end of its buffer"),
            std::string::npos)
      << gltf_error(replaced(good, "\"count\": 18,\n   \"type\": \"VEC2\"",
                             "\"count\": 40,\n   \"type\": \"VEC2\""));
  EXPECT_NE(gltf_error(replaced(good, "\"POSITION\": 0,", "\"POSITIONS\": 0,"))
                .find("mesh 'stone' primitive 0 has no POSITION"),
            std::string::npos);
  EXPECT_NE(gltf_error(replaced(good, "\"mesh\": 0,", "\"mesh\": 7,")).find("bad.gltf: "), std::string::npos);
  try {
    load_gltf("/no/such/model.glb");
    FAIL();
  } catch (const gpu::Error& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/model.glb: cannot open"), std::string::npos);
  }
}
