// glTF 2.0 models (.gltf with external or embedded buffers, .glb) through tinygltf, into the
// same Model as OBJ files: the default scene's node hierarchy is applied (each mesh instance's
// positions and normals are placed by its node's world matrix), and the PBR material is mapped
// to the Phong one (docs/scene-format.md). Every accessor is checked against its buffer.
#include <cmath>
#include <cstring>
#include <fstream>

#include <tiny_gltf.h>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "tessel/gpu/format.hpp"
#include "tessel/scene/model.hpp"

namespace tessel::scene {

using gpu::Error;

namespace {

constexpr size_t kMaxCount = size_t(1) << 26;

size_t component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int components(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;
  }
}

class Reader {
 public:
  Reader(const tinygltf::Model& m, const std::string& name) : m_(m), name_(name) {}
  [[noreturn]] void fail(const std::string& what) const { throw Error(name_ + ": " + what); }

  // The accessor's elements as floats (n components each; normalized integers to 0..1 or -1..1).
  std::vector<float> floats(int index, int n, const char* what) const {
    const Span s = span(index, what);
    if (s.comps != n)
      fail(std::string(what) + ": accessor " + std::to_string(index) + " has " + std::to_string(s.comps) +
           " components, expected " + std::to_string(n));
    std::vector<float> out(s.count * size_t(n));
    for (size_t i = 0; i < s.count; ++i)
      for (int c = 0; c < n; ++c) {
        const unsigned char* p = s.base + i * s.stride + size_t(c) * s.csize;
        float v = 0.0f;
        switch (s.ctype) {
          case TINYGLTF_COMPONENT_TYPE_FLOAT: std::memcpy(&v, p, 4); break;
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: v = float(p[0]) / (s.normalized ? 255.0f : 1.0f); break;
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t u;
            std::memcpy(&u, p, 2);
            v = float(u) / (s.normalized ? 65535.0f : 1.0f);
            break;
          }
          case TINYGLTF_COMPONENT_TYPE_BYTE:
            v = std::max(float(int8_t(p[0])) / (s.normalized ? 127.0f : 1.0f), -1.0f);
            break;
          case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t u;
            std::memcpy(&u, p, 2);
            v = std::max(float(u) / (s.normalized ? 32767.0f : 1.0f), -1.0f);
            break;
          }
          default:
            fail(std::string(what) + ": accessor " + std::to_string(index) + ": unsupported component type");
        }
        if (!std::isfinite(v))
          fail(std::string(what) + ": accessor " + std::to_string(index) + " element " + std::to_string(i) +
               " is not finite");
        out[i * size_t(n) + size_t(c)] = v;
      }
    return out;
  }

  std::vector<uint32_t> indices(int index) const {
    const Span s = span(index, "indices");
    if (s.comps != 1) fail("indices: accessor " + std::to_string(index) + " is not scalar");
    std::vector<uint32_t> out(s.count);
    for (size_t i = 0; i < s.count; ++i) {
      const unsigned char* p = s.base + i * s.stride;
      switch (s.ctype) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: out[i] = p[0]; break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
          uint16_t u;
          std::memcpy(&u, p, 2);
          out[i] = u;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: std::memcpy(&out[i], p, 4); break;
        default: fail("indices: accessor " + std::to_string(index) + " must hold unsigned integers");
      }
    }
    return out;
  }

 private:
  struct Span {
    const unsigned char* base;
    size_t count, stride, csize;
    int comps, ctype;
    bool normalized;
  };
  Span span(int index, const char* what) const {
    const std::string w = std::string(what) + ": accessor " + std::to_string(index);
    if (index < 0 || size_t(index) >= m_.accessors.size()) fail(w + " does not exist");
    const tinygltf::Accessor& a = m_.accessors[size_t(index)];
    if (a.sparse.isSparse) fail(w + " is sparse (not supported)");
    if (a.bufferView < 0 || size_t(a.bufferView) >= m_.bufferViews.size()) fail(w + ": no buffer view");
    const tinygltf::BufferView& v = m_.bufferViews[size_t(a.bufferView)];
    if (v.buffer < 0 || size_t(v.buffer) >= m_.buffers.size())
      fail(w + ": buffer view " + std::to_string(a.bufferView) + " has no buffer");
    const std::vector<unsigned char>& data = m_.buffers[size_t(v.buffer)].data;
    const size_t csize = component_size(a.componentType);
    const int comps = components(a.type);
    if (!csize || !comps) fail(w + ": unsupported type");
    if (a.count == 0 || a.count > kMaxCount) fail(w + ": " + std::to_string(a.count) + " elements");
    const size_t elem = csize * size_t(comps);
    const size_t stride = v.byteStride ? v.byteStride : elem;
    if (stride < elem || stride > 252) fail(w + ": byte stride " + std::to_string(stride));
    // Everything the accessor reads lies inside the view, and the view inside the buffer.
    const uint64_t need = uint64_t(a.byteOffset) + uint64_t(stride) * (a.count - 1) + elem;
    if (need > v.byteLength || uint64_t(v.byteOffset) + v.byteLength > data.size())
      fail(w + " reads past the end of its buffer");
    return {data.data() + v.byteOffset + a.byteOffset,
            a.count,
            stride,
            csize,
            comps,
            a.componentType,
            a.normalized};
  }
  const tinygltf::Model& m_;
  const std::string& name_;
};

glm::mat4 node_matrix(const tinygltf::Node& n) {
  if (n.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = float(n.matrix[size_t(i)]);
    return m;
  }
  glm::mat4 m(1.0f);
  if (n.translation.size() == 3)
    m = glm::translate(m,
                       glm::vec3(float(n.translation[0]), float(n.translation[1]), float(n.translation[2])));
  if (n.rotation.size() == 4) {
    const glm::quat q(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]));
    m = m * glm::mat4_cast(glm::normalize(q));
  }
  if (n.scale.size() == 3)
    m = glm::scale(m, glm::vec3(float(n.scale[0]), float(n.scale[1]), float(n.scale[2])));
  return m;
}

std::shared_ptr<Material> convert_material(const tinygltf::Model& m, const tinygltf::Material& mt,
                                           std::vector<std::shared_ptr<const gpu::Texture2D>>& textures,
                                           const Reader& r) {
  auto mat = std::make_shared<Material>();
  const auto& pbr = mt.pbrMetallicRoughness;
  glm::vec3 base(1.0f);
  if (pbr.baseColorFactor.size() == 4)
    base = glm::vec3(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                     float(pbr.baseColorFactor[2]));
  base = glm::clamp(base, glm::vec3(0.0f), glm::vec3(1.0f));
  const float metallic = std::clamp(float(pbr.metallicFactor), 0.0f, 1.0f);
  const float rough = std::clamp(float(pbr.roughnessFactor), 0.02f, 1.0f);
  // The mapping (docs/scene-format.md): specular is the Fresnel colour at normal incidence
  // (0.04 for dielectrics, the base colour for metals) and the Blinn-Phong exponent comes from
  // the roughness as 2 / alpha^2 - 2, alpha = r^2. Diffuse is the base colour, dimmed to a
  // quarter for metals: a metal has no diffuse reflection, but without the environment it
  // reflects, Phong would draw it black apart from its highlights.
  mat->kd = base * (1.0f - 0.75f * metallic);
  mat->ka = base * 0.1f;
  mat->ks = glm::mix(glm::vec3(0.04f), base, metallic);
  const float alpha = rough * rough;
  mat->shininess = std::clamp(2.0f / (alpha * alpha) - 2.0f, 1.0f, 2048.0f);
  if (mt.emissiveFactor.size() == 3)
    mat->emission =
        glm::vec3(float(mt.emissiveFactor[0]), float(mt.emissiveFactor[1]), float(mt.emissiveFactor[2]));
  const int ti = pbr.baseColorTexture.index;
  if (ti >= 0) {
    if (size_t(ti) >= m.textures.size())
      r.fail("material '" + mt.name + "': texture " + std::to_string(ti) + " does not exist");
    const int src = m.textures[size_t(ti)].source;
    if (src < 0 || size_t(src) >= m.images.size()) r.fail("texture " + std::to_string(ti) + ": no image");
    auto& t = textures[size_t(src)];
    if (!t) {
      const tinygltf::Image& img = m.images[size_t(src)];
      if (img.width <= 0 || img.height <= 0 || img.bits != 8 || img.component < 1 || img.component > 4 ||
          img.image.size() != size_t(img.width) * size_t(img.height) * size_t(img.component))
        r.fail("image " + std::to_string(src) + " ('" + img.uri.substr(0, 64) +
               "'): not an 8-bit image tessel can use");
      if (img.width > gpu::kMaxTextureSize || img.height > gpu::kMaxTextureSize)
        r.fail("image " + std::to_string(src) + " is too large");
      // glTF images have their first row at the top; Tessel's textures at the bottom.
      std::vector<uint8_t> rgba(size_t(img.width) * size_t(img.height) * 4);
      for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
          const unsigned char* s = &img.image[(size_t(img.height - 1 - y) * size_t(img.width) + size_t(x)) *
                                              size_t(img.component)];
          uint8_t* d = &rgba[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
          d[0] = s[0];
          d[1] = img.component >= 3 ? s[1] : s[0];
          d[2] = img.component >= 3 ? s[2] : s[0];
          d[3] = img.component == 4 ? s[3] : img.component == 2 ? s[1] : 255;
        }
      auto tex = std::make_shared<gpu::Texture2D>(gpu::Format::RGBA8, img.width, img.height, 0);
      tex->upload_rgba8(0, rgba.data(), rgba.size());
      tex->generate_mipmaps();
      t = tex;
    }
    mat->texture = t;
  }
  return mat;
}

Model convert(const tinygltf::Model& m, const std::string& name) {
  Reader r(m, name);
  Model out;
  std::vector<std::shared_ptr<const gpu::Texture2D>> textures(m.images.size());
  for (const tinygltf::Material& mt : m.materials)
    out.materials.push_back(convert_material(m, mt, textures, r));
  const int scene = m.defaultScene >= 0 ? m.defaultScene : 0;
  std::vector<std::pair<int, glm::mat4>> stack;
  if (size_t(scene) < m.scenes.size()) {
    for (int n : m.scenes[size_t(scene)].nodes) stack.emplace_back(n, glm::mat4(1.0f));
  } else {
    for (size_t n = 0; n < m.nodes.size(); ++n)
      stack.emplace_back(int(n), glm::mat4(1.0f));  // no scene: every node
  }
  size_t visited = 0;
  while (!stack.empty()) {
    auto [ni, parent] = stack.back();
    stack.pop_back();
    if (ni < 0 || size_t(ni) >= m.nodes.size()) r.fail("node " + std::to_string(ni) + " does not exist");
    if (++visited > 4 * m.nodes.size() + 16) r.fail("the node hierarchy has a cycle");
    const tinygltf::Node& node = m.nodes[size_t(ni)];
    const glm::mat4 world = parent * node_matrix(node);
    for (int c : node.children) stack.emplace_back(c, world);
    if (node.mesh < 0) continue;
    if (size_t(node.mesh) >= m.meshes.size())
      r.fail("node " + std::to_string(ni) + ": mesh " + std::to_string(node.mesh) + " does not exist");
    const tinygltf::Mesh& mesh = m.meshes[size_t(node.mesh)];
    const glm::mat3 nm = glm::transpose(glm::inverse(glm::mat3(world)));
    for (size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
      const tinygltf::Primitive& p = mesh.primitives[pi];
      if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
          p.mode != TINYGLTF_MODE_TRIANGLE_FAN && p.mode != -1)
        continue;  // points and lines are not surfaces
      const auto pos_it = p.attributes.find("POSITION");
      if (pos_it == p.attributes.end())
        r.fail("mesh '" + mesh.name + "' primitive " + std::to_string(pi) + " has no POSITION");
      const std::vector<float> pos = r.floats(pos_it->second, 3, "POSITION");
      const size_t nv = pos.size() / 3;
      std::vector<float> nor, uv;
      if (auto it = p.attributes.find("NORMAL"); it != p.attributes.end())
        nor = r.floats(it->second, 3, "NORMAL");
      if (auto it = p.attributes.find("TEXCOORD_0"); it != p.attributes.end())
        uv = r.floats(it->second, 2, "TEXCOORD_0");
      if ((!nor.empty() && nor.size() != pos.size()) || (!uv.empty() && uv.size() / 2 != nv))
        r.fail("mesh '" + mesh.name + "' primitive " + std::to_string(pi) +
               ": attributes of different lengths");
      std::vector<uint32_t> idx;
      if (p.indices >= 0)
        idx = r.indices(p.indices);
      else
        for (uint32_t i = 0; i < nv; ++i) idx.push_back(i);
      for (uint32_t i : idx)
        if (i >= nv)
          r.fail("mesh '" + mesh.name + "' primitive " + std::to_string(pi) + ": index " + std::to_string(i) +
                 " is outside the " + std::to_string(nv) + " vertices");
      Model::Part part;
      part.name = mesh.name.empty() ? "mesh " + std::to_string(node.mesh) : mesh.name;
      part.material = p.material >= 0 && size_t(p.material) < out.materials.size() ? p.material : -1;
      Mesh& me = part.mesh;
      me.vertices.resize(nv);
      for (size_t i = 0; i < nv; ++i) {
        VertexData& v = me.vertices[i];
        v.pos = glm::vec3(world * glm::vec4(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], 1.0f));
        if (!nor.empty()) v.norm = nm * glm::vec3(nor[3 * i], nor[3 * i + 1], nor[3 * i + 2]);
        if (!uv.empty()) v.tex = glm::vec2(uv[2 * i], 1.0f - uv[2 * i + 1]);  // glTF's v runs down the image
      }
      const int mode = p.mode == -1 ? TINYGLTF_MODE_TRIANGLES : p.mode;
      me.primitive = Primitive::Triangles;
      if (mode == TINYGLTF_MODE_TRIANGLES) {
        me.indices.assign(idx.begin(), idx.end() - std::ptrdiff_t(idx.size() % 3));
      } else {
        for (size_t k = 0; k + 2 < idx.size(); ++k) {
          if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
            me.indices.insert(me.indices.end(), {idx[0], idx[k + 1], idx[k + 2]});
          else if (k & 1)
            me.indices.insert(me.indices.end(), {idx[k + 1], idx[k], idx[k + 2]});
          else
            me.indices.insert(me.indices.end(), {idx[k], idx[k + 1], idx[k + 2]});
        }
      }
      // A mirroring node matrix turns the winding round; undo it so front faces stay front.
      if (glm::determinant(glm::mat3(world)) < 0.0f)
        for (size_t k = 0; k + 2 < me.indices.size(); k += 3) std::swap(me.indices[k + 1], me.indices[k + 2]);
      if (me.indices.empty()) continue;
      if (nor.empty()) smooth_normals(me);
      for (VertexData& v : me.vertices) {
        const float len = glm::length(v.norm);
        v.norm = len > 0.0f && std::isfinite(len) ? v.norm / len : glm::vec3(0.0f, 1.0f, 0.0f);
      }
      out.parts.push_back(std::move(part));
    }
  }
  if (out.parts.empty()) r.fail("no triangles");
  return out;
}

}  // namespace

Model parse_gltf(const void* data, size_t size, const std::string& name, const std::string& folder) {
  if (size > (size_t(1) << 31)) throw Error(name + ": the file is too large");
  tinygltf::TinyGLTF loader;
  tinygltf::Model m;
  std::string err, warn;
  const auto* bytes = static_cast<const unsigned char*>(data);
  const bool glb = size >= 4 && std::memcmp(bytes, "glTF", 4) == 0;
  const bool ok = glb ? loader.LoadBinaryFromMemory(&m, &err, &warn, bytes, unsigned(size), folder)
                      : loader.LoadASCIIFromString(&m, &err, &warn, reinterpret_cast<const char*>(bytes),
                                                   unsigned(size), folder);
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    throw Error(name + ": " + (err.empty() ? std::string("not a glTF file") : err));
  }
  return convert(m, name);
}

Model load_gltf(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw Error(path + ": cannot open the model file");
  const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const auto slash = path.find_last_of('/');
  return parse_gltf(bytes.data(), bytes.size(), path,
                    slash == std::string::npos ? "." : path.substr(0, slash));
}

}  // namespace tessel::scene
