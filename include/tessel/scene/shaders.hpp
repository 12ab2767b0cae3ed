// The shader library of the scene engine. Each is the notes' illumination model
//   colour = emission + sum over lights of [ka La + (kd cos(theta) + ks cos(delta)^shininess) Le]
// (cos(theta) = max(N.L, 0), cos(delta) = max(N.H, 0) with the Blinn halfway vector H, the
// specular term only where N.L > 0), evaluated in world space, with the texture (when the
// material has one) multiplying ka and kd.
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

// Per-pixel (Phong) shading with the Blinn-Phong specular term: the normal and the position
// are interpolated and the formula is evaluated at each pixel.
class PhongShader : public Shader {
 public:
  void draw(gpu::Context& ctx, const RenderState& state, const Geometry& geometry) const override;
};

}  // namespace tessel::scene
