// Scene files (docs/scene-format.md): JSON read with nlohmann-json, checked field by field so
// that every mistake is reported with the file and the path of the value ("objects[2].scale").
#include "tessel/scene/scene_file.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tessel/gpu/format.hpp"
#include "tessel/gpu/image.hpp"
#include "tessel/scene/model.hpp"
#include "tessel/scene/shaders.hpp"

namespace tessel::scene {

using gpu::Error;
using nlohmann::json;

namespace {

constexpr float kDeg = 3.14159265358979f / 180.0f;

// A JSON value with its place in the file, for messages.
class Node {
 public:
  Node(const json& j, std::string path, const std::string& file)
      : jp_(&j), path_(std::move(path)), fp_(&file) {}
  const json& json_value() const { return *jp_; }
  const std::string& path() const { return path_; }

  [[noreturn]] void fail(const std::string& what) const { throw Error(*fp_ + ": " + path_ + ": " + what); }

  bool has(const char* key) const { return j().is_object() && j().contains(key); }
  Node at(const char* key) const {
    if (!has(key)) fail(std::string("missing field '") + key + "'");
    return Node(j().at(key), path_ + "." + key, *fp_);
  }
  Node item(size_t i) const { return Node(j().at(i), path_ + "[" + std::to_string(i) + "]", *fp_); }
  // Every key must be one of `allowed` (a misspelt field is an error, not silently ignored).
  void only(std::initializer_list<const char*> allowed) const {
    if (!j().is_object()) fail("expected an object");
    for (auto it = j().begin(); it != j().end(); ++it) {
      bool ok = false;
      for (const char* a : allowed) ok = ok || it.key() == a;
      if (!ok) {
        std::string list;
        for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
        fail("unknown field '" + it.key() + "' (expected one of: " + list + ")");
      }
    }
  }

  float number(float lo = -1e30f, float hi = 1e30f) const {
    if (!j().is_number()) fail("expected a number");
    const double v = j().get<double>();
    if (!std::isfinite(v) || v < lo || v > hi)
      fail("value " + j().dump() + " is outside " + fmt(lo) + " .. " + fmt(hi));
    return float(v);
  }
  int integer(int lo, int hi) const {
    if (!j().is_number_integer()) fail("expected a whole number");
    const int64_t v = j().get<int64_t>();
    if (v < lo || v > hi)
      fail("value " + std::to_string(v) + " is outside " + std::to_string(lo) + " .. " + std::to_string(hi));
    return int(v);
  }
  bool boolean() const {
    if (!j().is_boolean()) fail("expected true or false");
    return j().get<bool>();
  }
  std::string string() const {
    if (!j().is_string()) fail("expected a string");
    return j().get<std::string>();
  }
  template <int N>
  glm::vec<N, float> vec(float lo = -1e30f, float hi = 1e30f) const {
    if (!j().is_array() || j().size() != size_t(N))
      fail("expected an array of " + std::to_string(N) + " numbers");
    glm::vec<N, float> v;
    for (int i = 0; i < N; ++i) v[i] = item(size_t(i)).number(lo, hi);
    return v;
  }
  // A colour: [r, g, b] (or a single number for grey).
  glm::vec3 colour() const {
    if (j().is_number()) return glm::vec3(number(0.0f, 1e6f));
    return vec<3>(0.0f, 1e6f);
  }

 private:
  static std::string fmt(float v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }
  const json* jp_;
  std::string path_;
  const std::string* fp_;
  const json& j() const { return *jp_; }
};

// An object whose parametric surface changes over time (the waving flag's phase).
class WavingObject : public Object {
 public:
  WavingObject(std::shared_ptr<Flag> flag, int rows, int columns, float phase_speed,
               std::shared_ptr<const Material> material, std::shared_ptr<const Shader> shader)
      : Object(std::make_shared<Geometry>(flag->create(rows, columns), "flag"), std::move(material),
               std::move(shader)),
        flag_(std::move(flag)),
        rows_(rows),
        columns_(columns),
        phase_speed_(phase_speed) {}
  void Animate(float dt) override {
    Object::Animate(dt);
    if (phase_speed_ == 0.0f || dt == 0.0f) return;
    flag_->set_phase(flag_->phase() + phase_speed_ * dt);
    geometry = std::make_shared<Geometry>(flag_->create(rows_, columns_), "flag");
  }

 private:
  std::shared_ptr<Flag> flag_;
  int rows_, columns_;
  float phase_speed_;
};

std::shared_ptr<const gpu::Texture2D> read_texture(const Node& n, const std::string& folder) {
  n.only({"file", "checker", "bumps"});
  if (int(n.has("file")) + int(n.has("checker")) + int(n.has("bumps")) != 1)
    n.fail("give one of 'file', 'checker' or 'bumps'");
  if (n.has("bumps")) {
    // A tangent-space normal map of round bumps: count x count of them, `height` scaling
    // their slope, for NormalMapShader.
    const Node b = n.at("bumps");
    b.only({"size", "count", "height"});
    const int size = b.has("size") ? b.at("size").integer(4, 4096) : 256;
    const int count = b.has("count") ? b.at("count").integer(1, size / 2) : 8;
    const float height = b.has("height") ? b.at("height").number(0.0f, 10.0f) : 1.0f;
    std::vector<uint8_t> px(size_t(size) * size_t(size) * 4);
    const float cell = float(size) / float(count);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const float dx = (std::fmod(float(x) + 0.5f, cell) / cell - 0.5f) * 2.0f;
        const float dy = (std::fmod(float(y) + 0.5f, cell) / cell - 0.5f) * 2.0f;
        const float r2 = dx * dx + dy * dy;
        // Bump height h = height (1 - r^2 / 0.81)^2 inside radius 0.9 of the cell: its slope
        // falls to 0 at the rim, so the map has no seams; the normal is (-dh/dx, -dh/dy, 1).
        glm::vec3 nrm(0.0f, 0.0f, 1.0f);
        if (r2 < 0.81f) {
          const float f = 1.0f - r2 / 0.81f, k = 4.0f * height * f / 0.81f;
          nrm = glm::normalize(glm::vec3(k * dx, k * dy, 1.0f));
        }
        uint8_t* p = &px[(size_t(y) * size_t(size) + size_t(x)) * 4];
        for (int i = 0; i < 3; ++i) p[i] = uint8_t(std::lround((nrm[i] * 0.5f + 0.5f) * 255.0f));
        p[3] = 255;
      }
    auto t = std::make_shared<gpu::Texture2D>(gpu::Format::RGBA8, size, size, 0);
    t->upload_rgba8(0, px.data(), px.size());
    t->generate_mipmaps();
    return t;
  }
  if (n.has("file")) {
    std::string f = n.at("file").string();
    if (!f.empty() && f[0] != '/') f = folder + "/" + f;
    return std::make_shared<gpu::Texture2D>(gpu::make_texture(gpu::load_image(f), true));
  }
  const Node c = n.at("checker");
  c.only({"size", "squares", "colors"});
  const int size = c.has("size") ? c.at("size").integer(1, 4096) : 256;
  const int squares = c.has("squares") ? c.at("squares").integer(1, size) : 8;
  glm::vec3 col[2] = {glm::vec3(0.9f), glm::vec3(0.2f)};
  if (c.has("colors")) {
    const Node cs = c.at("colors");
    if (!cs.json_value().is_array() || cs.json_value().size() != 2) cs.fail("expected two colours");
    col[0] = cs.item(0).colour();
    col[1] = cs.item(1).colour();
  }
  std::vector<uint8_t> px(size_t(size) * size_t(size) * 4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::vec3& k = col[((x * squares / size) + (y * squares / size)) & 1];
      uint8_t* p = &px[(size_t(y) * size_t(size) + size_t(x)) * 4];
      for (int i = 0; i < 3; ++i) p[i] = uint8_t(std::lround(std::clamp(k[i], 0.0f, 1.0f) * 255.0f));
      p[3] = 255;
    }
  auto t = std::make_shared<gpu::Texture2D>(gpu::Format::RGBA8, size, size, 0);
  t->upload_rgba8(0, px.data(), px.size());
  t->generate_mipmaps();
  return t;
}

std::shared_ptr<Material> read_material(
    const Node& n, const std::map<std::string, std::shared_ptr<const gpu::Texture2D>>& textures) {
  n.only({"ka", "kd", "ks", "shininess", "specular", "emission", "texture", "normal_map", "reflectance",
          "transmittance", "refractive_index"});
  auto m = std::make_shared<Material>();
  if (n.has("kd")) m->kd = n.at("kd").colour();
  m->ka = n.has("ka") ? n.at("ka").colour() : m->kd * 0.1f;
  if (n.has("ks")) m->ks = n.at("ks").colour();
  if (n.has("shininess")) m->shininess = n.at("shininess").number(0.0f, 10000.0f);
  if (n.has("specular")) {
    const std::string sp = n.at("specular").string();
    if (sp == "blinn")
      m->specular = Specular::Blinn;
    else if (sp == "phong")
      m->specular = Specular::Phong;
    else
      n.at("specular").fail("unknown specular model '" + sp + "' (expected blinn or phong)");
  }
  if (n.has("emission")) m->emission = n.at("emission").colour();
  if (n.has("reflectance")) m->reflectance = n.at("reflectance").colour();
  if (n.has("transmittance")) m->transmittance = n.at("transmittance").colour();
  if (n.has("refractive_index")) m->refractive_index = n.at("refractive_index").number(0.01f, 100.0f);
  if (n.has("normal_map")) {
    const Node t = n.at("normal_map");
    const auto it = textures.find(t.string());
    if (it == textures.end()) t.fail("no texture named '" + t.string() + "'");
    m->normal_map = it->second;
  }
  if (n.has("texture")) {
    const Node t = n.at("texture");
    const auto it = textures.find(t.string());
    if (it == textures.end()) t.fail("no texture named '" + t.string() + "'");
    m->texture = it->second;
  }
  return m;
}

Light read_light(const Node& n) {
  n.only({"position", "direction", "ambient", "color", "spot", "attenuation"});
  Light l;
  if (n.has("position") == n.has("direction"))
    n.fail("give either 'position' (a point light) or 'direction' (toward the light)");
  l.wLightPos = n.has("position") ? glm::vec4(n.at("position").vec<3>(), 1.0f)
                                  : glm::vec4(n.at("direction").vec<3>(), 0.0f);
  if (n.has("direction") && glm::length(glm::vec3(l.wLightPos)) == 0.0f)
    n.at("direction").fail("the direction is zero");
  l.La = n.has("ambient") ? n.at("ambient").colour() : glm::vec3(0.0f);
  l.Le = n.has("color") ? n.at("color").colour() : glm::vec3(1.0f);
  if (n.has("attenuation")) {
    if (!n.has("position")) n.at("attenuation").fail("only a point light is attenuated");
    l.attenuation = n.at("attenuation").vec<3>(0.0f, 1e6f);
    if (l.attenuation == glm::vec3(0.0f)) n.at("attenuation").fail("the factors are all zero");
  }
  if (n.has("spot")) {
    const Node s = n.at("spot");
    s.only({"direction", "cutoff", "exponent"});
    l.spot_direction = s.at("direction").vec<3>();
    if (glm::length(l.spot_direction) == 0.0f) s.at("direction").fail("the direction is zero");
    l.spot_cos_cutoff = std::cos(s.at("cutoff").number(0.0f, 90.0f) * kDeg);
    l.spot_exponent = s.has("exponent") ? s.at("exponent").number(0.0f, 128.0f) : 0.0f;
  }
  return l;
}

const char* kSurfaces = "sphere, flag, torus, cylinder, cone, plane, mesh";

}  // namespace

std::shared_ptr<const Shader> shader_by_name(const std::string& name) {
  static const std::map<std::string, std::shared_ptr<const Shader>> library = {
      {"gouraud", std::make_shared<GouraudShader>()}, {"phong", std::make_shared<PhongShader>()},
      {"npr", std::make_shared<NprShader>()},         {"depth", std::make_shared<DepthShader>()},
      {"normal", std::make_shared<NormalShader>()},   {"normalmap", std::make_shared<NormalMapShader>()}};
  const auto it = library.find(name);
  return it == library.end() ? nullptr : it->second;
}

SceneFile parse_scene(const std::string& text, const std::string& name, const std::string& folder) {
  json doc;
  try {
    doc = json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    // The byte offset as line:column.
    size_t line = 1, col = 1;
    for (size_t i = 0; i < std::min(e.byte > 0 ? e.byte - 1 : 0, text.size()); ++i) {
      if (text[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    // nlohmann's text is "[json.exception.parse_error.101] parse error at line L, column C: what".
    std::string msg = e.what();
    const auto colon = msg.find(": ", msg.find("parse error"));
    if (colon != std::string::npos) msg = msg.substr(colon + 2);
    throw Error(name + ":" + std::to_string(line) + ":" + std::to_string(col) + ": " + msg);
  } catch (const json::exception& e) {
    // Not a syntax error but still the text's fault: a number too large for a double.
    std::string msg = e.what();
    const auto bracket = msg.find("] ");
    throw Error(name + ": " + (bracket == std::string::npos ? msg : msg.substr(bracket + 2)));
  }
  SceneFile out;
  Scene& s = out.scene;
  const Node root(doc, "scene", name);
  root.only({"render", "camera", "lights", "textures", "materials", "objects"});

  std::string default_shader = "phong";
  if (root.has("render")) {
    const Node r = root.at("render");
    r.only({"size", "background", "threads", "fps", "shading", "shadows", "planar_shadows", "deferred"});
    if (r.has("deferred")) s.deferred = r.at("deferred").boolean();
    if (r.has("planar_shadows")) {
      const Node ps = r.at("planar_shadows");
      ps.only({"light", "plane", "color"});
      s.planar_shadows.enabled = true;
      if (ps.has("light")) s.planar_shadows.light = ps.at("light").integer(0, kMaxLights - 1);
      if (ps.has("plane")) {
        s.planar_shadows.plane = ps.at("plane").vec<4>();
        if (glm::length(glm::vec3(s.planar_shadows.plane)) == 0.0f)
          ps.at("plane").fail("the plane's normal (a, b, c) is zero");
      }
      if (ps.has("color")) s.planar_shadows.color = ps.at("color").colour();
    }
    if (r.has("shadows")) {
      const Node sh = r.at("shadows");
      ShadowSettings& ss = s.shadows;
      if (sh.json_value().is_boolean()) {
        ss.enabled = sh.boolean();
      } else {
        sh.only({"light", "size", "pcf", "slope_bias", "constant_bias"});
        ss.enabled = true;
        if (sh.has("light")) ss.light = sh.at("light").integer(0, kMaxLights - 1);
        if (sh.has("size")) ss.size = sh.at("size").integer(16, 8192);
        if (sh.has("pcf")) ss.pcf = sh.at("pcf").integer(0, 8);
        if (sh.has("slope_bias")) ss.slope_bias = sh.at("slope_bias").number(-100.0f, 100.0f);
        if (sh.has("constant_bias")) ss.constant_bias = sh.at("constant_bias").number(-1e6f, 1e6f);
      }
    }
    if (r.has("size")) {
      const Node sz = r.at("size");
      if (!sz.json_value().is_array() || sz.json_value().size() != 2) sz.fail("expected [width, height]");
      out.render.width = sz.item(0).integer(1, 16384);
      out.render.height = sz.item(1).integer(1, 16384);
    }
    if (r.has("background")) {
      const Node b = r.at("background");
      s.background = b.json_value().is_array() && b.json_value().size() == 4 ? b.vec<4>(0.0f, 1.0f)
                                                                             : glm::vec4(b.colour(), 1.0f);
    }
    if (r.has("threads")) out.render.threads = r.at("threads").integer(0, 64);
    if (r.has("fps")) out.render.fps = r.at("fps").number(0.001f, 10000.0f);
    if (r.has("shading")) {
      default_shader = r.at("shading").string();
      if (!shader_by_name(default_shader))
        r.at("shading").fail("unknown shading '" + default_shader +
                             "' (expected gouraud, phong, normalmap, npr, depth, normal)");
    }
  }

  if (root.has("camera")) {
    const Node c = root.at("camera");
    c.only({"eye", "lookat", "vup", "fov", "near", "far", "orthographic", "height"});
    if (c.has("eye")) s.camera.eye = c.at("eye").vec<3>();
    if (c.has("lookat")) s.camera.lookat = c.at("lookat").vec<3>();
    if (c.has("vup")) s.camera.vup = c.at("vup").vec<3>();
    if (c.has("fov")) s.camera.fov = c.at("fov").number(0.01f, 179.0f) * kDeg;
    if (c.has("near")) s.camera.near = c.at("near").number();
    if (c.has("far")) s.camera.far = c.at("far").number();
    if (c.has("orthographic")) s.camera.orthographic = c.at("orthographic").boolean();
    if (c.has("height")) s.camera.ortho_height = c.at("height").number(1e-6f, 1e6f);
  }
  s.camera.aspect = float(out.render.width) / float(out.render.height);
  try {
    s.camera.validate();
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }

  if (root.has("lights")) {
    const Node ls = root.at("lights");
    if (!ls.json_value().is_array()) ls.fail("expected an array of lights");
    const size_t max_lights = size_t(s.deferred ? kMaxDeferredLights : kMaxLights);
    if (ls.json_value().size() > max_lights)
      ls.fail("at most " + std::to_string(max_lights) + " lights" +
              (s.deferred ? "" : " (with render.deferred: " + std::to_string(kMaxDeferredLights) + ")"));
    for (size_t i = 0; i < ls.json_value().size(); ++i) s.lights.push_back(read_light(ls.item(i)));
  }

  if (s.planar_shadows.enabled && size_t(s.planar_shadows.light) >= s.lights.size())
    root.at("render")
        .at("planar_shadows")
        .fail("light " + std::to_string(s.planar_shadows.light) + " does not exist (there are " +
              std::to_string(s.lights.size()) + " lights)");
  if (s.shadows.enabled && size_t(s.shadows.light) >= s.lights.size())
    root.at("render").at("shadows").fail("light " + std::to_string(s.shadows.light) +
                                         " does not exist (there are " + std::to_string(s.lights.size()) +
                                         " lights)");

  std::map<std::string, std::shared_ptr<const gpu::Texture2D>> textures;
  if (root.has("textures")) {
    const Node ts = root.at("textures");
    if (!ts.json_value().is_object()) ts.fail("expected an object of named textures");
    for (auto it = ts.json_value().begin(); it != ts.json_value().end(); ++it) {
      const Node t(it.value(), ts.path() + "." + it.key(), name);
      try {
        textures[it.key()] = read_texture(t, folder);
      } catch (const Error& e) {
        const std::string m = e.what();
        if (m.rfind(name + ": ", 0) == 0) throw;
        t.fail(m);
      }
    }
  }
  std::map<std::string, std::shared_ptr<const Material>> materials;
  if (root.has("materials")) {
    const Node ms = root.at("materials");
    if (!ms.json_value().is_object()) ms.fail("expected an object of named materials");
    for (auto it = ms.json_value().begin(); it != ms.json_value().end(); ++it)
      materials[it.key()] = read_material(Node(it.value(), ms.path() + "." + it.key(), name), textures);
  }
  const auto default_material = std::make_shared<Material>();

  if (root.has("objects")) {
    const Node os = root.at("objects");
    if (!os.json_value().is_array()) os.fail("expected an array of objects");
    std::map<std::string, Object*> named;
    std::vector<std::pair<Object*, Node>> parents;
    for (size_t i = 0; i < os.json_value().size(); ++i) {
      const Node o = os.item(i);
      o.only({"name", "geometry", "material", "shader", "position", "scale", "rotation", "parent", "animate",
              "cull", "planar_shadow"});
      const Node g = o.at("geometry");
      g.only({"type", "rows", "columns", "radius", "center", "width", "height", "depth", "waves", "phase",
              "major", "minor", "size", "file"});
      const std::string type = g.at("type").string();
      const int rows = g.has("rows") ? g.at("rows").integer(1, 4096) : 16;
      const int cols = g.has("columns") ? g.at("columns").integer(1, 4096) : 32;
      auto num = [&](const char* k, float d, float lo = 1e-6f) {
        return g.has(k) ? g.at(k).number(lo, 1e6f) : d;
      };
      std::shared_ptr<const Material> mat = default_material;
      if (o.has("material")) {
        const Node m = o.at("material");
        const auto it = materials.find(m.string());
        if (it == materials.end()) m.fail("no material named '" + m.string() + "'");
        mat = it->second;
      }
      std::string shader_name = default_shader;
      if (o.has("shader")) shader_name = o.at("shader").string();
      auto shader = shader_by_name(shader_name);
      if (!shader)
        (o.has("shader") ? o.at("shader") : o)
            .fail("unknown shader '" + shader_name +
                  "' (expected gouraud, phong, normalmap, npr, depth, normal)");
      float phase_speed = 0.0f;
      Node anim = o;
      if (o.has("animate")) {
        anim = o.at("animate");
        anim.only({"spin", "velocity", "flag_phase"});
        if (anim.has("flag_phase")) {
          if (type != "flag") anim.at("flag_phase").fail("only a flag has a phase");
          phase_speed = anim.at("flag_phase").number();
        }
      }
      std::unique_ptr<Object> obj;
      std::vector<std::unique_ptr<Object>> extra_parts;  // a model's parts after the first
      if (type == "mesh") {
        std::string file = g.at("file").string();
        if (!file.empty() && file[0] != '/') file = folder + "/" + file;
        Model model;
        try {
          const auto dot = file.rfind('.');
          const std::string ext = dot == std::string::npos ? "" : file.substr(dot);
          model = ext == ".gltf" || ext == ".glb" ? load_gltf(file) : load_obj(file);
        } catch (const Error& e) {
          g.at("file").fail(e.what());
        }
        for (size_t k = 0; k < model.parts.size(); ++k) {
          const Model::Part& part = model.parts[k];
          std::shared_ptr<const Material> pm =
              o.has("material") || part.material < 0 ? mat : model.materials[size_t(part.material)];
          auto po = std::make_unique<Object>(std::make_shared<Geometry>(part.mesh, file + ": " + part.name),
                                             pm, shader);
          if (k == 0)
            obj = std::move(po);
          else
            extra_parts.push_back(std::move(po));
        }
      } else if (type == "flag") {
        auto flag =
            std::make_shared<Flag>(num("width", 1.0f), num("height", 1.0f), num("depth", 0.1f, -1e6f),
                                   num("waves", 2.0f, -1e6f), g.has("phase") ? g.at("phase").number() : 0.0f);
        obj = std::make_unique<WavingObject>(flag, rows, cols, phase_speed, mat, shader);
      } else {
        std::unique_ptr<ParamSurface> surf;
        if (type == "sphere")
          surf = std::make_unique<Sphere>(num("radius", 1.0f),
                                          g.has("center") ? g.at("center").vec<3>() : glm::vec3(0.0f));
        else if (type == "torus")
          surf = std::make_unique<Torus>(num("major", 1.0f), num("minor", 0.25f));
        else if (type == "cylinder")
          surf = std::make_unique<Cylinder>(num("radius", 1.0f), num("height", 1.0f));
        else if (type == "cone")
          surf = std::make_unique<Cone>(num("radius", 1.0f), num("height", 1.0f));
        else if (type == "plane")
          surf = std::make_unique<Plane>(num("size", 1.0f));
        else
          g.at("type").fail("unknown surface '" + type + "' (expected " + kSurfaces + ")");
        obj =
            std::make_unique<Object>(std::make_shared<Geometry>(surf->create(rows, cols), type), mat, shader);
      }
      Transform& t = obj->transform;
      if (o.has("position")) t.position = o.at("position").vec<3>();
      if (o.has("scale")) {
        const Node sc = o.at("scale");
        t.scale = sc.json_value().is_number() ? glm::vec3(sc.number(1e-6f, 1e6f)) : sc.vec<3>(1e-6f, 1e6f);
      }
      if (o.has("rotation")) {
        const Node r = o.at("rotation");
        r.only({"axis", "angle"});
        t.axis = r.at("axis").vec<3>();
        if (glm::length(t.axis) == 0.0f) r.at("axis").fail("the axis is zero");
        t.angle = r.at("angle").number() * kDeg;
      }
      if (o.has("animate")) {
        if (anim.has("spin")) obj->spin = anim.at("spin").number() * kDeg;
        if (anim.has("velocity")) obj->velocity = anim.at("velocity").vec<3>();
      }
      if (o.has("cull")) obj->cull_back_faces = o.at("cull").boolean();
      if (o.has("planar_shadow")) obj->planar_shadow = o.at("planar_shadow").boolean();
      Object& added = s.add(std::move(obj));
      for (auto& part : extra_parts) {
        part->transform.parent = &added.transform;
        part->cull_back_faces = added.cull_back_faces;
        part->planar_shadow = added.planar_shadow;
        s.add(std::move(part));
      }
      if (o.has("name")) {
        const std::string nm = o.at("name").string();
        if (!named.emplace(nm, &added).second)
          o.at("name").fail("another object is already named '" + nm + "'");
      }
      if (o.has("parent")) parents.emplace_back(&added, o.at("parent"));
    }
    for (auto& [obj, p] : parents) {
      const auto it = named.find(p.string());
      if (it == named.end()) p.fail("no object named '" + p.string() + "'");
      obj->transform.parent = &it->second->transform;
    }
    // A chain of parents must end.
    for (auto& [obj, p] : parents) {
      int depth = 0;
      for (const Transform* t = &obj->transform; t; t = t->parent)
        if (++depth > int(s.objects.size())) p.fail("the parents form a cycle");
    }
  }
  return out;
}

SceneFile load_scene_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw Error(path + ": cannot open the scene file");
  std::ostringstream text;
  text << f.rdbuf();
  if (f.bad()) throw Error(path + ": read error");
  const auto slash = path.find_last_of('/');
  return parse_scene(text.str(), path, slash == std::string::npos ? "." : path.substr(0, slash));
}

}  // namespace tessel::scene
