// Geometry of the scene engine: triangle meshes on the CPU, and parametric surfaces
// tessellated into them (the lecture notes' ParamSurface::create(N, M): the unit square of
// (u, v) cut into N rows and M columns, each row one triangle strip, with the analytic
// normal and (u, v) as texture coordinates at every vertex).
//
// Watertight by construction: the angle functions below take turns (1 = 360 degrees) and are
// exact at quarter turns, and whole turns give the bits of zero turns, so the u = 0 and u = 1
// columns of a sphere or a torus are the same points, and a sphere's pole row is one point.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tessel::scene {

struct VertexData {
  glm::vec3 pos{0.0f};
  glm::vec3 norm{0.0f, 0.0f, 1.0f};
  glm::vec2 tex{0.0f};
};

enum class Primitive : uint8_t { Triangles, TriangleStrip };

// sin and cos of 2 pi t, exact at every quarter turn (0, +-1); an integer t gives exactly
// (0, 1), the same bits as t = 0.
void sincos_turns(float t, float& s, float& c);

// A triangle mesh on the CPU: vertices (position, normal, texture coordinates) and indices,
// drawn as `strips` triangle strips of `strip_length` indices each, or as a triangle list.
class Mesh {
 public:
  std::vector<VertexData> vertices;
  std::vector<uint32_t> indices;
  Primitive primitive = Primitive::Triangles;
  int strip_length = 0;  // TriangleStrip: indices per strip (the strips follow each other)

  // The triangles as index triples, counter-clockwise seen from the side the normals point to;
  // strips are unrolled with their alternating winding, zero-area triangles kept.
  std::vector<uint32_t> triangle_list() const;
  int triangle_count() const;
  // Throws Error naming the problem: an index out of range, a strip length that does not
  // divide the indices, a position or normal that is not finite.
  void validate(const std::string& what) const;
};

// A parametric surface r(u, v), (u, v) in [0, 1]^2, with its normal n(u, v) (not necessarily
// unit length: create() normalizes it).
class ParamSurface {
 public:
  virtual ~ParamSurface() = default;
  virtual void eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const = 0;
  // N rows of M quads, each row a strip of 2 (M + 1) vertices (the notes' layout), N, M >= 1
  // and at most 4096 (Error otherwise). Vertex (i, j) of the grid is at u = j / M, v = i / N.
  Mesh create(int N, int M) const;
};

// The notes' sphere: centre + r (cos U sin V, sin U sin V, cos V), U = 2 pi u, V = pi v.
class Sphere : public ParamSurface {
 public:
  explicit Sphere(float radius = 1.0f, glm::vec3 center = glm::vec3(0.0f))
      : radius_(radius), center_(center) {}
  void eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const override;

 private:
  float radius_;
  glm::vec3 center_;
};

// The notes' waving flag: (u W, v H, D sin(K pi u + phase)), normal (-K pi D cos(...), 0, W)
// (the cross product of the partial derivatives, divided by H).
class Flag : public ParamSurface {
 public:
  Flag(float width = 1.0f, float height = 1.0f, float depth = 0.1f, float waves = 2.0f, float phase = 0.0f)
      : W_(width), H_(height), D_(depth), K_(waves), phase_(phase) {}
  void eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const override;
  void set_phase(float phase) { phase_ = phase; }
  float phase() const { return phase_; }

 private:
  float W_, H_, D_, K_, phase_;
};

// A torus around the y axis: major radius R (centre of the tube), tube radius r;
// u goes around the axis, v around the tube.
class Torus : public ParamSurface {
 public:
  explicit Torus(float major = 1.0f, float minor = 0.25f) : R_(major), r_(minor) {}
  void eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const override;

 private:
  float R_, r_;
};

// An open cylinder around the y axis from y = 0 to y = height (no caps).
class Cylinder : public ParamSurface {
 public:
  explicit Cylinder(float radius = 1.0f, float height = 1.0f) : radius_(radius), height_(height) {}
  void eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const override;

 private:
  float radius_, height_;
};

// An open cone around the y axis: base of the given radius at y = 0, apex at y = height.
class Cone : public ParamSurface {
 public:
  explicit Cone(float radius = 1.0f, float height = 1.0f) : radius_(radius), height_(height) {}
  void eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const override;

 private:
  float radius_, height_;
};

// The square [-size/2, size/2]^2 in the y = 0 plane, normal +y.
class Plane : public ParamSurface {
 public:
  explicit Plane(float size = 1.0f) : size_(size) {}
  void eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const override;

 private:
  float size_;
};

// A surface given as a function: pos(u, v), and the normal either given too or, when
// `normal` is empty, from central differences of pos (cross of d/du and d/dv).
class FunctionSurface : public ParamSurface {
 public:
  using PosFn = std::function<glm::vec3(float, float)>;
  explicit FunctionSurface(PosFn pos, PosFn normal = {}) : pos_(std::move(pos)), normal_(std::move(normal)) {}
  void eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const override;

 private:
  PosFn pos_, normal_;
};

}  // namespace tessel::scene
