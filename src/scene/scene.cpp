#include "tessel/scene/scene.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "tessel/gpu/format.hpp"
#include "tessel/gpu/framebuffer.hpp"
#include "tessel/scene/shaders.hpp"

namespace tessel::scene {

using gpu::Error;

Geometry::Geometry(const Mesh& mesh, const std::string& name) : mesh_(mesh) {
  mesh_.validate(name);
  const std::vector<uint32_t> tris = mesh_.triangle_list();
  if (tris.empty()) throw Error(name + ": the mesh has no triangles");
  static_assert(sizeof(VertexData) == 8 * sizeof(float), "VertexData is position, normal, uv");
  vertices_.assign(mesh_.vertices.data(), mesh_.vertices.size() * sizeof(VertexData));
  indices_.assign(tris.data(), tris.size() * sizeof(uint32_t));
  count_ = uint32_t(tris.size());
  const uint32_t stride = sizeof(VertexData);
  layout_.attrib(0, vertices_, 3, gpu::AttribType::F32, stride, offsetof(VertexData, pos));
  layout_.attrib(1, vertices_, 3, gpu::AttribType::F32, stride, offsetof(VertexData, norm));
  layout_.attrib(2, vertices_, 2, gpu::AttribType::F32, stride, offsetof(VertexData, tex));
}

gpu::DrawCall Geometry::draw_call() const {
  return {.topology = gpu::Topology::Triangles,
          .count = count_,
          .index_buffer = &indices_,
          .index_type = gpu::IndexType::U32};
}

void Object::Animate(float dt) {
  transform.angle += spin * dt;
  transform.position += velocity * dt;
}

void Object::Draw(gpu::Context& ctx, RenderState state) const {
  if (!geometry || !shader) return;
  state.M = transform.world();
  state.Minv = transform.world_inverse();
  state.material = material.get();
  state.pipeline.cull = cull_back_faces ? gpu::CullMode::Back : gpu::CullMode::None;
  shader->draw(ctx, state, *geometry);
}

Object& Scene::add(std::unique_ptr<Object> object) {
  if (!object) throw Error("Scene::add: no object");
  objects.push_back(std::move(object));
  return *objects.back();
}

void Scene::Animate(float dt) {
  for (auto& o : objects) o->Animate(dt);
}

glm::vec4 Scene::bounding_sphere() const {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const auto& o : objects) {
    if (!o->geometry) continue;
    const glm::mat4 M = o->transform.world();
    for (const VertexData& v : o->geometry->mesh().vertices) {
      const glm::vec3 p = glm::vec3(M * glm::vec4(v.pos, 1.0f));
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  if (lo.x > hi.x) return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  return glm::vec4((lo + hi) * 0.5f, std::max(glm::length(hi - lo) * 0.5f, 1e-3f));
}

glm::mat4 Scene::shadow_matrix(const Light& light) const {
  const glm::vec4 b = bounding_sphere();
  const glm::vec3 c(b), w = glm::vec3(light.wLightPos);
  const float r = b.w;
  auto up_for = [](const glm::vec3& dir) {
    return std::fabs(glm::normalize(dir).y) > 0.99f ? glm::vec3(1.0f, 0.0f, 0.0f)
                                                    : glm::vec3(0.0f, 1.0f, 0.0f);
  };
  if (light.wLightPos.w == 0.0f) {
    // Directional: an orthographic box around the bounding sphere, looking along -direction.
    const glm::vec3 d = glm::normalize(w);
    const glm::mat4 V = glm::lookAt(c + d * (2.0f * r), c, up_for(d));
    return glm::ortho(-r, r, -r, r, r * 0.9f, r * 3.1f) * V;
  }
  const glm::vec3 p = w / light.wLightPos.w;
  const float dist = glm::length(c - p);
  if (light.spot_cos_cutoff > -1.0f) {
    const glm::vec3 d = glm::normalize(light.spot_direction);
    const float half = std::acos(std::clamp(light.spot_cos_cutoff, -1.0f, 1.0f));
    if (half > glm::radians(85.0f))
      throw Error("shadows: a spot light wider than 170 degrees cannot cast a shadow map");
    const float far = std::max(dist + r, 1e-2f),
                near = std::max(far * 1e-3f, dist - r > 0.0f ? (dist - r) * 0.9f : far * 1e-3f);
    return glm::perspective(2.0f * half + glm::radians(2.0f), 1.0f, near, far) *
           glm::lookAt(p, p + d, up_for(d));
  }
  if (dist <= r * 1.01f)
    throw Error(
        "shadows: the point light is inside the scene's bounding sphere (omnidirectional shadow maps are not "
        "supported yet; use a spot or directional light)");
  const glm::vec3 d = (c - p) / dist;
  const float half = std::asin(std::min(r / dist, 0.999f));
  return glm::perspective(2.0f * half, 1.0f, (dist - r) * 0.9f, dist + r) * glm::lookAt(p, c, up_for(d));
}

// Cuts a frame into passes for Render's caller: end(name) finishes the work queued since the
// previous end and records it. Without a list to fill it does nothing, so the passes stay
// one stream of work for the pipeline.
class Scene::PassClock {
 public:
  PassClock(gpu::Context& ctx, std::vector<PassStats>* passes) : ctx_(ctx), passes_(passes) { restart(); }
  void end(const char* name) {
    if (!passes_) return;
    ctx_.finish();
    PassStats p;
    p.name = name;
    p.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0_).count();
    p.counters = ctx_.stats() - before_;
    passes_->push_back(std::move(p));
    restart();
  }

 private:
  void restart() {
    if (!passes_) return;
    before_ = ctx_.stats();
    t0_ = std::chrono::steady_clock::now();
  }
  gpu::Context& ctx_;
  std::vector<PassStats>* passes_;
  gpu::Stats before_;
  std::chrono::steady_clock::time_point t0_;
};

void Scene::Render(gpu::Context& ctx, std::vector<PassStats>* passes) const {
  PassClock clock(ctx, passes);
  camera.validate();
  const size_t max_lights = size_t(deferred ? kMaxDeferredLights : kMaxLights);
  if (lights.size() > max_lights)
    throw Error("scene: " + std::to_string(lights.size()) + " lights, at most " + std::to_string(max_lights) +
                (deferred ? "" : " (deferred shading takes " + std::to_string(kMaxDeferredLights) + ")"));
  RenderState state;
  if (deferred) {
    state.V = camera.V();
    state.P = camera.P();
    state.wEye = camera.eye;
    state.near = camera.near;
    state.far = camera.far;
    state.pipeline.depth_test = true;
    render_deferred(ctx, state, clock);
    return;
  }
  if (shadows.enabled) {
    if (shadows.light < 0 || size_t(shadows.light) >= lights.size())
      throw Error("shadows: light " + std::to_string(shadows.light) + " does not exist (the scene has " +
                  std::to_string(lights.size()) + ")");
    if (shadows.size < 16 || shadows.size > 8192) throw Error("shadows: the map size must be 16..8192");
    if (shadows.pcf < 0 || shadows.pcf > 8) throw Error("shadows: pcf must be 0..8");
    const Light& sl = lights[size_t(shadows.light)];
    // A point light (not a spot) sees every direction: six 90-degree maps, one per cube face.
    const bool cube = sl.wLightPos.w != 0.0f && !(sl.spot_cos_cutoff > -1.0f);
    const int faces = cube ? 6 : 1;
    std::array<glm::mat4, 6> vp{};
    if (cube) {
      const glm::vec3 p = glm::vec3(sl.wLightPos) / sl.wLightPos.w;
      const glm::vec4 b = bounding_sphere();
      const float far = glm::length(glm::vec3(b) - p) + b.w * 1.01f, near = std::max(far * 1e-3f, 1e-3f);
      // GL's cube face order and orientation (GL 4.6 table 8.19): +X, -X, +Y, -Y, +Z, -Z.
      const glm::vec3 dir[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      const glm::vec3 up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
      const glm::mat4 P = glm::perspective(glm::radians(90.0f), 1.0f, near, far);
      for (int f = 0; f < 6; ++f) vp[size_t(f)] = P * glm::lookAt(p, p + dir[f], up[f]);
    } else {
      vp[0] = shadow_matrix(sl);
    }
    const int size = cube ? std::min(shadows.size, 1024) : shadows.size;
    if (shadow_maps_.size() != size_t(faces) || shadow_maps_[0]->width() != size) {
      shadow_maps_.clear();
      for (int f = 0; f < faces; ++f)
        shadow_maps_.push_back(std::make_unique<gpu::Texture2D>(gpu::Format::Depth32F, size, size));
    }
    // The light pass: depth only, both faces, pushed back by the slope-scaled and constant bias.
    gpu::Framebuffer* previous = ctx.framebuffer();
    gpu::RenderState pass;
    pass.depth_test = true;
    pass.offset_fill = true;
    // A PCF tap k texels away meets the receiver's own depth k slopes further on: the slope
    // bias grows with the kernel (receiver-plane acne otherwise, in rings on a floor).
    pass.offset_factor = shadows.slope_bias * float(1 + shadows.pcf);
    pass.offset_units = shadows.constant_bias;
    std::vector<gpu::Framebuffer> fbs;
    fbs.reserve(size_t(faces));
    for (int f = 0; f < faces; ++f) {
      fbs.emplace_back(nullptr, shadow_maps_[size_t(f)].get());
      ctx.bind_framebuffer(&fbs.back());
      ctx.clear({.clear_color = false, .depth = 1.0f});
      for (const auto& o : objects)
        if (o->geometry) draw_shadow_depth(ctx, vp[size_t(f)] * o->transform.world(), *o->geometry, pass);
    }
    ctx.bind_framebuffer(previous);
    clock.end("shadow");
    state.light_VP = vp[0];
    state.shadow_map = shadow_maps_[0].get();
    if (cube) {
      state.cube_shadow = true;
      state.cube_light = glm::vec3(sl.wLightPos) / sl.wLightPos.w;
      for (int f = 0; f < 6; ++f) {
        state.cube_maps[size_t(f)] = shadow_maps_[size_t(f)].get();
        state.cube_VP[size_t(f)] = vp[size_t(f)];
      }
    }
    state.shadow_light = shadows.light;
    state.pcf = shadows.pcf;
  }
  state.V = camera.V();
  state.P = camera.P();
  state.wEye = camera.eye;
  state.near = camera.near;
  state.far = camera.far;
  state.lights = lights;
  state.pipeline.depth_test = true;
  ctx.clear({.color = background, .depth = 1.0f});
  for (const auto& o : objects) o->Draw(ctx, state);
  clock.end("objects");
  if (planar_shadows.enabled) {
    draw_planar_shadows(ctx, state);
    clock.end("planar_shadows");
  }
}

void Scene::render_deferred(gpu::Context& ctx, const RenderState& base, PassClock& clock) const {
  gpu::Framebuffer* target = ctx.framebuffer();
  if (!target) throw Error("scene: no framebuffer bound");
  const int w = target->width(), h = target->height();
  if (gbuffer_.empty() || gbuffer_[0]->width() != w || gbuffer_[0]->height() != h) {
    gbuffer_.clear();
    const gpu::Format formats[6] = {gpu::Format::RGBA32F, gpu::Format::RGBA32F, gpu::Format::RGBA8,
                                    gpu::Format::RGBA8,   gpu::Format::RGBA8,   gpu::Format::RGBA8};
    for (gpu::Format f : formats) gbuffer_.push_back(std::make_unique<gpu::Texture2D>(f, w, h));
    gbuffer_.push_back(std::make_unique<gpu::Texture2D>(gpu::Format::Depth24, w, h));
  }
  // Pass 1: geometry into the G-buffer, all six attachments at once.
  gpu::Framebuffer g;
  for (int i = 0; i < 6; ++i) g.color[size_t(i)].texture = gbuffer_[size_t(i)].get();
  g.depth.texture = gbuffer_[6].get();
  ctx.bind_framebuffer(&g);
  ctx.clear({.color = glm::vec4(0.0f), .depth = 1.0f});
  for (const auto& o : objects) {
    if (!o->geometry) continue;
    RenderState state = base;
    state.M = o->transform.world();
    state.Minv = o->transform.world_inverse();
    state.material = o->material.get();
    state.pipeline.cull = o->cull_back_faces ? gpu::CullMode::Back : gpu::CullMode::None;
    draw_gbuffer(ctx, state, *o->geometry);
  }
  clock.end("gbuffer");
  // Pass 2: one full-screen triangle lights every pixel from the G-buffer.
  ctx.bind_framebuffer(target);
  ctx.clear({.color = background, .depth = 1.0f});
  std::vector<const gpu::Texture2D*> views;
  for (int i = 0; i < 6; ++i) views.push_back(gbuffer_[size_t(i)].get());
  const bool phong = std::any_of(objects.begin(), objects.end(), [](const auto& o) {
    return o->geometry && o->material && o->material->specular == Specular::Phong;
  });
  draw_deferred_lighting(ctx, views, lights, camera.eye, background, phong);
  clock.end("lighting");
}

void Scene::draw_planar_shadows(gpu::Context& ctx, const RenderState& state) const {
  const PlanarShadowSettings& ps = planar_shadows;
  if (ps.light < 0 || size_t(ps.light) >= lights.size())
    throw Error("planar shadows: light " + std::to_string(ps.light) + " does not exist (the scene has " +
                std::to_string(lights.size()) + ")");
  const float nlen = glm::length(glm::vec3(ps.plane));
  if (!(nlen > 0.0f) || !std::isfinite(nlen) || !std::isfinite(ps.plane.w))
    throw Error("planar shadows: the plane has no normal");
  const glm::vec4 P = ps.plane / nlen;
  const glm::vec4 L = lights[size_t(ps.light)].wLightPos;
  // Projection onto the plane from L (homogeneous, so directional lights work too):
  // S = (P.L) I - L P^T, column-major: S[c][r] = (P.L) delta(r, c) - L[r] P[c].
  const float pl = glm::dot(P, L);
  glm::mat4 S(0.0f);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) S[c][r] = (r == c ? pl : 0.0f) - L[r] * P[c];
  gpu::RenderState pass = state.pipeline;
  pass.cull = gpu::CullMode::None;  // the flattening can reverse the winding
  pass.offset_fill = true;
  pass.offset_factor = -1.0f;
  pass.offset_units = -4.0f;
  const glm::mat4 VP = state.P * state.V;
  for (const auto& o : objects) {
    if (!o->geometry || !o->planar_shadow) continue;
    const glm::mat4 M = o->transform.world();
    // Objects lying in the plane (the receiver) cast nothing; nor do those entirely on the
    // side away from the light.
    bool in_plane = true, lit_side = false;
    for (const VertexData& v : o->geometry->mesh().vertices) {
      const float dist = glm::dot(P, M * glm::vec4(v.pos, 1.0f));
      in_plane = in_plane && std::fabs(dist) < 1e-4f;
      lit_side = lit_side || (pl > 0.0f ? dist > 1e-4f : dist < -1e-4f);
    }
    if (in_plane || !lit_side) continue;
    draw_flat(ctx, VP * S * M, ps.color, *o->geometry, pass);
  }
}

int Scene::triangles() const {
  int n = 0;
  for (const auto& o : objects)
    if (o->geometry) n += o->geometry->triangles();
  return n;
}

}  // namespace tessel::scene
