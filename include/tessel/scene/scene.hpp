// The scene engine (DESIGN.md, "Engine"), after the lecture notes' class design: a Scene holds
// one Camera, its Lights and a heterogeneous list of Objects; an Object refers to shared
// Geometry, Material and Shader and carries its modelling Transform; drawing goes through a
// RenderState that the scene and the object fill and the shader reads, so that neither the
// object nor the shader depends on the other.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tessel/gpu/buffer.hpp"
#include "tessel/gpu/context.hpp"
#include "tessel/gpu/texture.hpp"
#include "tessel/scene/camera.hpp"
#include "tessel/scene/geometry.hpp"
#include "tessel/scene/transform.hpp"

namespace tessel::scene {

inline constexpr int kMaxLights = 8;
// Deferred shading lights every pixel once from the G-buffer, so it takes many more lights.
inline constexpr int kMaxDeferredLights = 256;

// A light source at a homogeneous world position: w = 0 is a directional light shining from
// the direction xyz, w != 0 a point (xyz / w). La is its ambient and Le its emitted radiance
// (the notes' names). A spot light (spot_cos_cutoff > -1) lights only directions within the
// cutoff angle of spot_direction, weighted by cos^spot_exponent as in GL 1.x. A point light's
// Le is divided by c + l d + q d^2 at distance d, attenuation = (c, l, q) (GL 1.x's
// attenuation factors; the default (1, 0, 0) does not attenuate).
struct Light {
  glm::vec4 wLightPos{0.0f, 1.0f, 1.0f, 0.0f};
  glm::vec3 La{0.1f}, Le{1.0f};
  glm::vec3 attenuation{1.0f, 0.0f, 0.0f};
  glm::vec3 spot_direction{0.0f, -1.0f, 0.0f};
  float spot_cos_cutoff = -1.0f;
  float spot_exponent = 0.0f;
};

// The specular term's cosine: Blinn's max(N.H, 0) with the halfway vector H = normalize(L + V)
// (the notes' model), or Phong's max(R.V, 0) with the mirrored light direction
// R = 2 (N.L) N - L. For a similar highlight Phong's exponent is about a quarter of Blinn's.
enum class Specular : uint8_t { Blinn, Phong };

// The notes' material: ambient, diffuse and specular reflectance, shininess, plus emission
// and an optional texture that multiplies ka and kd. The last three are the ray tracer's.
struct Material {
  glm::vec3 ka{0.1f}, kd{0.7f}, ks{0.3f};
  float shininess = 32.0f;
  Specular specular = Specular::Blinn;
  glm::vec3 emission{0.0f};
  std::shared_ptr<const gpu::Texture2D> texture;
  // A tangent-space normal map (RGB = (n + 1) / 2, +z out of the surface, v up), used by
  // NormalMapShader.
  std::shared_ptr<const gpu::Texture2D> normal_map;
  glm::vec3 reflectance{0.0f}, transmittance{0.0f};
  float refractive_index = 1.0f;
};

// A mesh in GPU buffers, ready to draw (as a triangle list).
class Geometry {
 public:
  // Throws Error (naming `name`) when the mesh is invalid or empty.
  explicit Geometry(const Mesh& mesh, const std::string& name = "geometry");
  const Mesh& mesh() const { return mesh_; }
  const gpu::VertexLayout& layout() const { return layout_; }
  gpu::DrawCall draw_call() const;
  int triangles() const { return int(count_ / 3); }

 private:
  Mesh mesh_;
  gpu::Buffer vertices_, indices_;
  gpu::VertexLayout layout_;
  uint32_t count_ = 0;
};

// Shadow mapping: a depth pass from one light into a depth texture, then lit shaders that
// support it (PhongShader) compare each point's depth seen from the light with the map.
// Directional and spot lights render one map; a point light renders six (a cube of 90-degree
// frusta, at most 1024 texels a side), so it may stand among the objects.
struct ShadowSettings {
  bool enabled = false;
  int light = 0;               // the index of the light that casts shadows
  int size = 2048;             // the map's width and height in texels (16..8192)
  float slope_bias = 2.0f;     // the light pass's polygon offset: factor (slope-scaled, times
                               // pcf + 1, as the kernel reaches that many texels) ...
  float constant_bias = 4.0f;  // ... and units, against shadow acne
  int pcf = 1;                 // percentage-closer filtering: (2 pcf + 1)^2 bilinear compares,
                               // one texel apart (0: the 2x2 bilinear compare alone)
};

// Projected planar shadows (the notes' "black shadow" pass): after the objects are drawn,
// each object is drawn again flattened onto the plane a x + b y + c z + d = 0 along the
// rays from a light (the projection matrix (P.L) I - L P^T), in one colour, a little toward
// the camera so that it wins against the plane it lies on. Objects that lie in the plane
// (the floor itself) cast nothing; an object can opt out with Object::planar_shadow.
struct PlanarShadowSettings {
  bool enabled = false;
  int light = 0;
  glm::vec4 plane{0.0f, 1.0f, 0.0f, 0.0f};
  glm::vec3 color{0.0f};
};

// What flows from the scene and the object to the shader.
struct RenderState {
  glm::mat4 M{1.0f}, Minv{1.0f}, V{1.0f}, P{1.0f};
  glm::vec3 wEye{0.0f};
  float near = 0.1f, far = 100.0f;  // the camera's clipping distances (depth views)
  const Material* material = nullptr;
  std::vector<Light> lights;
  gpu::RenderState pipeline;  // depth test, culling, ...
  // Shadows (when shadow_map is set): light shadow_light's visibility comes from the map,
  // looked up at light_VP * (world position).
  const gpu::Texture2D* shadow_map = nullptr;
  glm::mat4 light_VP{1.0f};
  int shadow_light = -1;
  int pcf = 0;
  // A point light's six maps (GL cube face order), used instead when cube_shadow is set.
  bool cube_shadow = false;
  glm::vec3 cube_light{0.0f};
  std::array<const gpu::Texture2D*, 6> cube_maps{};
  std::array<glm::mat4, 6> cube_VP{};
};

// A way to draw geometry: fills its GPU uniforms from the render state and submits the draw.
class Shader {
 public:
  virtual ~Shader() = default;
  virtual void draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const = 0;
};

class Object {
 public:
  Object(std::shared_ptr<const Geometry> geometry, std::shared_ptr<const Material> material,
         std::shared_ptr<const Shader> shader)
      : geometry(std::move(geometry)), material(std::move(material)), shader(std::move(shader)) {}
  virtual ~Object() = default;

  Transform transform;
  std::shared_ptr<const Geometry> geometry;
  std::shared_ptr<const Material> material;
  std::shared_ptr<const Shader> shader;
  // Animation per second: a turn about transform.axis (radians), and a velocity.
  float spin = 0.0f;
  glm::vec3 velocity{0.0f};
  bool cull_back_faces = true;
  bool planar_shadow = true;  // casts a projected planar shadow when the scene draws them

  virtual void Animate(float dt);
  // Fills M, Minv and the material, and draws with the object's shader.
  virtual void Draw(gpu::Context& ctx, RenderState state) const;
};

// One pass of a frame, as Scene::Render reports it when asked: its name ("shadow" for the
// light pass, "objects", "planar_shadows", "gbuffer", "lighting"), the wall-clock time from
// its first submission to the end of its work, and what the pipeline counted in it.
struct PassStats {
  std::string name;
  double ms = 0.0;
  gpu::Stats counters;
};

class Scene {
 public:
  Camera camera;
  std::vector<Light> lights;
  std::vector<std::unique_ptr<Object>> objects;
  glm::vec4 background{0.0f, 0.0f, 0.0f, 1.0f};
  ShadowSettings shadows;
  PlanarShadowSettings planar_shadows;
  // Deferred shading: the objects write position, normal and material into a G-buffer (six
  // colour attachments drawn at once, MRT), then one full-screen pass lights every pixel with
  // the notes' Blinn-Phong formula from up to kMaxDeferredLights lights. Object shaders and
  // shadows are not used in this mode.
  bool deferred = false;

  Object& add(std::unique_ptr<Object> object);
  void Animate(float dt);
  // Clears the bound framebuffer to the background and draws every object with the camera's
  // V and P (the caller sets camera.aspect). Throws Error for an invalid camera or more than
  // kMaxLights lights (kMaxDeferredLights when deferred). With `passes`, each pass is
  // finished before the next starts and its time and counters are appended there (the image
  // is the same either way; without it the passes run as one stream of work).
  void Render(gpu::Context& ctx, std::vector<PassStats>* passes = nullptr) const;
  int triangles() const;
  // The smallest sphere around every object's vertices found by a bounding box (centre, radius).
  glm::vec4 bounding_sphere() const;
  // The light's view-projection for its shadow map (Error when the light cannot cast one).
  glm::mat4 shadow_matrix(const Light& light) const;

 private:
  class PassClock;
  void draw_planar_shadows(gpu::Context& ctx, const RenderState& state) const;
  void render_deferred(gpu::Context& ctx, const RenderState& state, PassClock& clock) const;
  mutable std::vector<std::unique_ptr<gpu::Texture2D>>
      gbuffer_;  // positions, normals, kd, ks, ka, emission, depth
  mutable std::vector<std::unique_ptr<gpu::Texture2D>> shadow_maps_;  // 1 or 6 (a point light's cube), reused
};

}  // namespace tessel::scene
