// The shader library of the scene engine. Each is the notes' illumination model
//   colour = emission + sum over lights of [ka La + (kd cos(theta) + ks cos(delta)^shininess) Le]
// (cos(theta) = max(N.L, 0), cos(delta) = max(N.H, 0) with the Blinn halfway vector H, or
// max(R.V, 0) for a material whose specular model is Specular::Phong; the specular term only
// where N.L > 0), evaluated in world space, with the texture (when the material has one)
// multiplying ka and kd.
#pragma once

#include "tessel/scene/scene.hpp"

namespace tessel::scene {

// Per-vertex (Gouraud) shading: the formula at the vertices, colours interpolated; the
// texture is applied per pixel to the ambient + diffuse part (the specular part is added
// after it, as GL's separate specular colour).
class GouraudShader : public Shader {
 public:
  void draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const override;
};

// The light pass of shadow mapping: the geometry's depth through MVP, nothing else.
void draw_shadow_depth(gpu::Context& ctx, const glm::mat4& MVP, const Geometry& geometry,
                       const gpu::RenderState& pipeline);

// A projected planar shadow: the geometry through MVP (which includes the projection onto
// the plane), in one colour.
void draw_flat(gpu::Context& ctx, const glm::mat4& MVP, const glm::vec3& color, const Geometry& geometry,
               const gpu::RenderState& pipeline);

// Deferred shading's two passes: an object into the G-buffer (attachments: world position
// and shininess, normal, kd, ks, ka, emission; the texture already applied to kd and ka), and
// the full-screen lighting pass that reads it (pixels the objects did not cover get
// `background`). `phong_specular`: some object's material uses Specular::Phong (else every
// pixel takes Blinn's N.H without looking).
void draw_gbuffer(gpu::Context& ctx, const RenderState& state, const Geometry& geometry);
void draw_deferred_lighting(gpu::Context& ctx, const std::vector<const gpu::Texture2D*>& gbuffer,
                            const std::vector<Light>& lights, const glm::vec3& eye,
                            const glm::vec4& background, bool phong_specular);

// Per-pixel (Phong) shading with the Blinn-Phong specular term: the normal and the position
// are interpolated and the formula is evaluated at each pixel. With a shadow map in the
// render state, the shadowing light's Le is scaled by the fraction of PCF compares that see
// the point (1 outside the map).
class PhongShader : public Shader {
 public:
  void draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const override;
};

// Phong shading with the material's normal map: the tangent frame comes per pixel from the
// screen-space derivatives of the position and the texture coordinates (no tangents are
// needed in the mesh), and the map's normal replaces the interpolated one. Without a normal
// map it draws as PhongShader.
class NormalMapShader : public Shader {
 public:
  void draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const override;
};

// Non-photorealistic (toon) shading after the notes: the diffuse colour in `bands` flat
// levels of max(N.L, 0) for the first light (2 bands: full where N.L > 0.5, half elsewhere),
// and black where |N.V| < silhouette, the outline of the object.
class NprShader : public Shader {
 public:
  explicit NprShader(int bands = 2, float silhouette = 0.2f)
      : bands_(bands < 1 ? 1 : bands), silhouette_(silhouette) {}
  void draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const override;

 private:
  int bands_;
  float silhouette_;
};

// The distance from the camera as grey, linear in eye-space depth: white at `from`, black at
// `to` (by default the camera's near and far planes).
class DepthShader : public Shader {
 public:
  DepthShader() = default;
  DepthShader(float from, float to) : from_(from), to_(to), range_(to > from) {}
  void draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const override;

 private:
  float from_ = 0.0f, to_ = 0.0f;
  bool range_ = false;
};

// The world-space shading normal as colour: 0.5 N + 0.5 (x red, y green, z blue).
class NormalShader : public Shader {
 public:
  void draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const override;
};

}  // namespace tessel::scene
