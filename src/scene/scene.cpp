#include "tessel/scene/scene.hpp"

#include <string>

#include "tessel/gpu/format.hpp"

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
  return {.topology = gpu::Topology::Triangles, .count = count_, .index_buffer = &indices_,
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

void Scene::Render(gpu::Context& ctx) const {
  camera.validate();
  if (lights.size() > size_t(kMaxLights))
    throw Error("scene: " + std::to_string(lights.size()) + " lights, at most " + std::to_string(kMaxLights));
  RenderState state;
  state.V = camera.V();
  state.P = camera.P();
  state.wEye = camera.eye;
  state.near = camera.near;
  state.far = camera.far;
  state.lights = lights;
  state.pipeline.depth_test = true;
  ctx.clear({.color = background, .depth = 1.0f});
  for (const auto& o : objects) o->Draw(ctx, state);
}

int Scene::triangles() const {
  int n = 0;
  for (const auto& o : objects)
    if (o->geometry) n += o->geometry->triangles();
  return n;
}

}  // namespace tessel::scene
