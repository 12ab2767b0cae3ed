#include "tessel/scene/model.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

#include <tiny_obj_loader.h>

#include "tessel/gpu/format.hpp"
#include "tessel/gpu/image.hpp"

namespace tessel::scene {

using gpu::Error;

namespace {

glm::vec3 v3(const tinyobj::real_t* a) { return glm::vec3(float(a[0]), float(a[1]), float(a[2])); }

}  // namespace

// Normals for a mesh that has none: at each corner, the area-weighted sum of the normals of
// the faces around that position that turn less than 45 degrees from the corner's own face,
// so that curved surfaces shade smoothly and creases (a roof's ridge, a cube's edges) stay
// sharp. Corners that end up with different normals get vertices of their own.
void smooth_normals(Mesh& mesh) {
  const size_t nf = mesh.indices.size() / 3;
  std::vector<glm::vec3> face(nf);
  std::map<std::tuple<float, float, float>, std::vector<size_t>> around;  // position -> faces
  auto key = [](const glm::vec3& p) { return std::make_tuple(p.x, p.y, p.z); };
  for (size_t f = 0; f < nf; ++f) {
    const VertexData &a = mesh.vertices[mesh.indices[3 * f]], &b = mesh.vertices[mesh.indices[3 * f + 1]],
                     &c = mesh.vertices[mesh.indices[3 * f + 2]];
    face[f] = glm::cross(b.pos - a.pos, c.pos - a.pos);
    for (int k = 0; k < 3; ++k) around[key(mesh.vertices[mesh.indices[3 * f + size_t(k)]].pos)].push_back(f);
  }
  const float cos_limit = std::cos(45.0f * 3.14159265f / 180.0f);
  std::vector<VertexData> out;
  std::map<std::tuple<uint32_t, float, float, float>, uint32_t> seen;
  std::vector<uint32_t> indices(mesh.indices.size());
  for (size_t f = 0; f < nf; ++f) {
    const glm::vec3 own = face[f];
    const float own_len = glm::length(own);
    for (int k = 0; k < 3; ++k) {
      const uint32_t vi = mesh.indices[3 * f + size_t(k)];
      glm::vec3 n(0.0f);
      for (size_t g : around[key(mesh.vertices[vi].pos)]) {
        const float gl = glm::length(face[g]);
        if (g == f || (own_len > 0.0f && gl > 0.0f && glm::dot(own, face[g]) > cos_limit * own_len * gl))
          n += face[g];
      }
      const float len = glm::length(n);
      if (len > 0.0f && std::isfinite(len)) n /= len;
      auto [it, fresh] = seen.emplace(std::make_tuple(vi, n.x, n.y, n.z), uint32_t(out.size()));
      if (fresh) {
        VertexData v = mesh.vertices[vi];
        v.norm = n;
        out.push_back(v);
      }
      indices[3 * f + size_t(k)] = it->second;
    }
  }
  mesh.vertices = std::move(out);
  mesh.indices = std::move(indices);
}

namespace {

Model convert(const tinyobj::ObjReader& r, const std::string& name, const std::string& folder) {
  const tinyobj::attrib_t& at = r.GetAttrib();
  const size_t nv = at.vertices.size() / 3, nn = at.normals.size() / 3, nt = at.texcoords.size() / 2;
  for (size_t i = 0; i < at.vertices.size(); ++i)
    if (!std::isfinite(at.vertices[i]))
      throw Error(name + ": vertex " + std::to_string(i / 3 + 1) + " is not a finite number");
  Model m;
  std::map<std::string, std::shared_ptr<const gpu::Texture2D>> textures;
  for (const tinyobj::material_t& mt : r.GetMaterials()) {
    auto mat = std::make_shared<Material>();
    mat->ka = v3(mt.ambient);
    mat->kd = v3(mt.diffuse);
    mat->ks = v3(mt.specular);
    mat->emission = v3(mt.emission);
    mat->transmittance = v3(mt.transmittance);
    mat->shininess = std::isfinite(mt.shininess) ? std::clamp(float(mt.shininess), 0.0f, 10000.0f) : 32.0f;
    mat->refractive_index = std::isfinite(mt.ior) && mt.ior > 0.0f ? float(mt.ior) : 1.0f;
    if (!mt.diffuse_texname.empty()) {
      auto& t = textures[mt.diffuse_texname];
      if (!t) {
        const std::string f =
            mt.diffuse_texname[0] == '/' ? mt.diffuse_texname : folder + "/" + mt.diffuse_texname;
        try {
          t = std::make_shared<gpu::Texture2D>(gpu::make_texture(gpu::load_image(f), true));
        } catch (const Error& e) {
          throw Error(name + ": material '" + mt.name + "': map_Kd: " + e.what());
        }
      }
      mat->texture = t;
      // A texture multiplies ka and kd; OBJ files often leave Kd at 0 with a map, meaning white.
      if (mat->kd == glm::vec3(0.0f)) mat->kd = glm::vec3(1.0f);
    }
    m.materials.push_back(mat);
  }
  const int nmat = int(m.materials.size());
  for (const tinyobj::shape_t& sh : r.GetShapes()) {
    // One part per material used by the shape, in the order they first appear.
    std::map<int, size_t> part_of;
    std::vector<std::map<std::tuple<int, int, int>, uint32_t>> lookup;
    std::vector<bool> has_normals;
    size_t offset = 0;
    for (size_t f = 0; f < sh.mesh.num_face_vertices.size(); ++f) {
      const int fv = sh.mesh.num_face_vertices[f];
      if (fv != 3 || offset + 3 > sh.mesh.indices.size()) {
        offset += size_t(fv);
        continue;  // triangulation leaves only triangles; anything else is skipped
      }
      int mid = f < sh.mesh.material_ids.size() ? sh.mesh.material_ids[f] : -1;
      if (mid < -1 || mid >= nmat) mid = -1;
      auto it = part_of.find(mid);
      if (it == part_of.end()) {
        it = part_of.emplace(mid, m.parts.size()).first;
        m.parts.push_back(
            {sh.name + (mid >= 0 ? "/" + r.GetMaterials()[size_t(mid)].name : ""), Mesh{}, mid});
        lookup.emplace_back();
        has_normals.push_back(true);
      }
      const size_t pi = it->second;
      const size_t li = pi - (m.parts.size() - lookup.size());
      Model::Part& part = m.parts[pi];
      for (int k = 0; k < 3; ++k) {
        const tinyobj::index_t ix = sh.mesh.indices[offset + size_t(k)];
        if (ix.vertex_index < 0 || size_t(ix.vertex_index) >= nv)
          throw Error(name + ": shape '" + sh.name + "', face " + std::to_string(f + 1) + ": vertex index " +
                      std::to_string(ix.vertex_index + 1) + " is outside the " + std::to_string(nv) +
                      " vertices");
        if (ix.normal_index >= 0 && size_t(ix.normal_index) >= nn)
          throw Error(name + ": shape '" + sh.name + "', face " + std::to_string(f + 1) + ": normal index " +
                      std::to_string(ix.normal_index + 1) + " is outside the " + std::to_string(nn) +
                      " normals");
        if (ix.texcoord_index >= 0 && size_t(ix.texcoord_index) >= nt)
          throw Error(name + ": shape '" + sh.name + "', face " + std::to_string(f + 1) +
                      ": texture coordinate index " + std::to_string(ix.texcoord_index + 1) +
                      " is outside the " + std::to_string(nt) + " coordinates");
        const auto key = std::make_tuple(ix.vertex_index, ix.normal_index, ix.texcoord_index);
        auto [slot, fresh] = lookup[li].emplace(key, uint32_t(part.mesh.vertices.size()));
        if (fresh) {
          VertexData vd;
          vd.pos = v3(&at.vertices[size_t(ix.vertex_index) * 3]);
          if (ix.normal_index >= 0)
            vd.norm = v3(&at.normals[size_t(ix.normal_index) * 3]);
          else
            has_normals[li] = false;
          if (ix.texcoord_index >= 0)
            vd.tex = glm::vec2(float(at.texcoords[size_t(ix.texcoord_index) * 2]),
                               float(at.texcoords[size_t(ix.texcoord_index) * 2 + 1]));
          part.mesh.vertices.push_back(vd);
        }
        part.mesh.indices.push_back(slot->second);
      }
      offset += 3;
    }
    for (size_t li = 0; li < lookup.size(); ++li) {
      Mesh& mesh = m.parts[m.parts.size() - lookup.size() + li].mesh;
      mesh.primitive = Primitive::Triangles;
      if (!has_normals[li]) smooth_normals(mesh);
      for (VertexData& v : mesh.vertices) {
        const float len = glm::length(v.norm);
        v.norm = len > 0.0f && std::isfinite(len) ? v.norm / len : glm::vec3(0.0f, 1.0f, 0.0f);
      }
    }
  }
  if (m.parts.empty()) throw Error(name + ": no triangles");
  return m;
}

std::string folder_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

}  // namespace

Model parse_obj(const std::string& obj_text, const std::string& mtl_text, const std::string& name,
                const std::string& folder) {
  tinyobj::ObjReaderConfig cfg;
  cfg.triangulate = true;
  cfg.vertex_color = false;
  tinyobj::ObjReader r;
  if (!r.ParseFromString(obj_text, mtl_text, cfg))
    throw Error(name + ": " + (r.Error().empty() ? "cannot parse" : r.Error()));
  return convert(r, name, folder);
}

Model load_obj(const std::string& path) {
  std::ifstream probe(path);
  if (!probe) throw Error(path + ": cannot open the model file");
  tinyobj::ObjReaderConfig cfg;
  cfg.triangulate = true;
  cfg.vertex_color = false;
  cfg.mtl_search_path = folder_of(path);
  tinyobj::ObjReader r;
  if (!r.ParseFromFile(path, cfg))
    throw Error(path + ": " + (r.Error().empty() ? "cannot parse" : r.Error()));
  // A missing .mtl is only a warning to tinyobjloader; to us a material that cannot be found
  // is an error worth naming.
  if (r.Warning().find("Material file [") != std::string::npos &&
      r.Warning().find("not found") != std::string::npos)
    throw Error(path + ": " + r.Warning().substr(0, r.Warning().find('\n')));
  return convert(r, path, folder_of(path));
}

}  // namespace tessel::scene
