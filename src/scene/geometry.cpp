#include "tessel/scene/geometry.hpp"

#include <cmath>
#include <numbers>

#include "tessel/gpu/format.hpp"  // tessel::gpu::Error

namespace tessel::scene {

using gpu::Error;

void sincos_turns(float t, float& s, float& c) {
  // The fraction of a turn, exact (t - floor(t) is exact for |t| < 2^23), then its quadrant
  // and the angle inside it: 4 f and its integer part are exact too, so quarter turns give
  // r = 0 and sin = 0, cos = 1 exactly, and t + 1 the same bits as t.
  float f = t - std::floor(t);
  if (!(f < 1.0f)) f = 0.0f;  // t just below an integer can round up to 1; NaN -> 0
  const float q4 = f * 4.0f;
  const int q = int(q4);
  const float a = (q4 - float(q)) * (std::numbers::pi_v<float> * 0.5f);
  const float sa = std::sin(a), ca = std::cos(a);
  switch (q & 3) {
    case 0:
      s = sa;
      c = ca;
      break;
    case 1:
      s = ca;
      c = -sa;
      break;
    case 2:
      s = -sa;
      c = -ca;
      break;
    default:
      s = -ca;
      c = sa;
      break;
  }
}

std::vector<uint32_t> Mesh::triangle_list() const {
  std::vector<uint32_t> out;
  if (primitive == Primitive::Triangles) {
    out.assign(indices.begin(), indices.end() - std::ptrdiff_t(indices.size() % 3));
    return out;
  }
  if (strip_length < 3) return out;
  for (size_t s = 0; s + size_t(strip_length) <= indices.size(); s += size_t(strip_length)) {
    for (int k = 0; k + 2 < strip_length; ++k) {
      const uint32_t* p = &indices[s + size_t(k)];
      // Odd triangles of a strip swap their first two vertices (GL 4.6 §10.1.6).
      if (k & 1)
        out.insert(out.end(), {p[1], p[0], p[2]});
      else
        out.insert(out.end(), {p[0], p[1], p[2]});
    }
  }
  return out;
}

int Mesh::triangle_count() const {
  if (primitive == Primitive::Triangles) return int(indices.size() / 3);
  if (strip_length < 3) return 0;
  return int(indices.size() / size_t(strip_length)) * (strip_length - 2);
}

void Mesh::validate(const std::string& what) const {
  for (size_t i = 0; i < vertices.size(); ++i) {
    const VertexData& v = vertices[i];
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(v.pos[k]) || !std::isfinite(v.norm[k]))
        throw Error(what + ": vertex " + std::to_string(i) + " has a position or normal that is not finite");
  }
  for (size_t i = 0; i < indices.size(); ++i)
    if (indices[i] >= vertices.size())
      throw Error(what + ": index " + std::to_string(i) + " is " + std::to_string(indices[i]) +
                  ", but there are only " + std::to_string(vertices.size()) + " vertices");
  if (primitive == Primitive::Triangles && indices.size() % 3 != 0)
    throw Error(what + ": " + std::to_string(indices.size()) + " indices do not make whole triangles");
  if (primitive == Primitive::TriangleStrip &&
      (strip_length < 3 || indices.size() % size_t(strip_length) != 0))
    throw Error(what + ": strips of " + std::to_string(strip_length) + " indices do not divide " +
                std::to_string(indices.size()) + " indices");
}

Mesh ParamSurface::create(int N, int M) const {
  constexpr int kMax = 4096;
  if (N < 1 || M < 1 || N > kMax || M > kMax)
    throw Error("ParamSurface::create: " + std::to_string(N) + " x " + std::to_string(M) +
                " is outside 1..4096 rows and columns");
  Mesh m;
  m.vertices.resize(size_t(N + 1) * size_t(M + 1));
  for (int i = 0; i <= N; ++i) {
    for (int j = 0; j <= M; ++j) {
      VertexData& vd = m.vertices[size_t(i) * size_t(M + 1) + size_t(j)];
      const float u = float(j) / float(M), v = float(i) / float(N);
      vd.tex = glm::vec2(u, v);
      glm::vec3 n;
      eval(u, v, vd.pos, n);
      const float len = glm::length(n);
      vd.norm = len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
    }
  }
  // Which way round the strips go: a strip's triangles face r_v x r_u in the notes' order
  // (v0, v1 of each column). When the surface's normals point along r_u x r_v instead (the
  // flag, a plane), the rows swap, so that the triangles are counter-clockwise seen from the
  // side the normals point to and back-face culling keeps the right side.
  double votes = 0.0;
  const float h = 1e-3f;
  for (float su : {0.3f, 0.5f, 0.7f}) {
    for (float sv : {0.3f, 0.5f, 0.7f}) {
      glm::vec3 a, b, c, d, n, dummy;
      eval(su + h, sv, a, dummy);
      eval(su - h, sv, b, dummy);
      eval(su, sv + h, c, dummy);
      eval(su, sv - h, d, dummy);
      eval(su, sv, dummy, n);
      votes += glm::dot(glm::dvec3(n), glm::cross(glm::dvec3(a - b), glm::dvec3(c - d)));
    }
  }
  const bool swap_rows = votes > 0.0;
  m.primitive = Primitive::TriangleStrip;
  m.strip_length = 2 * (M + 1);
  m.indices.reserve(size_t(N) * size_t(m.strip_length));
  for (int i = 0; i < N; ++i) {
    const uint32_t lo = uint32_t(i * (M + 1)), hi = uint32_t((i + 1) * (M + 1));
    for (int j = 0; j <= M; ++j) {
      if (swap_rows)
        m.indices.insert(m.indices.end(), {hi + uint32_t(j), lo + uint32_t(j)});
      else
        m.indices.insert(m.indices.end(), {lo + uint32_t(j), hi + uint32_t(j)});
    }
  }
  return m;
}

void Sphere::eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const {
  float su, cu, sv, cv;
  sincos_turns(u, su, cu);
  sincos_turns(0.5f * v, sv, cv);  // V = pi v: half a turn
  norm = glm::vec3(cu * sv, su * sv, cv);
  pos = norm * radius_ + center_;
}

void Flag::eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const {
  const float pi = std::numbers::pi_v<float>;
  const float angle = u * K_ * pi + phase_;
  pos = glm::vec3(u * W_, v * H_, std::sin(angle) * D_);
  norm = glm::vec3(-K_ * pi * std::cos(angle) * D_, 0.0f, W_);
}

void Torus::eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const {
  float su, cu, sv, cv;
  sincos_turns(u, su, cu);
  sincos_turns(v, sv, cv);
  const glm::vec3 radial(cu, 0.0f, -su);  // counter-clockwise around +y seen from above
  norm = radial * cv + glm::vec3(0.0f, sv, 0.0f);
  pos = radial * R_ + norm * r_;
}

void Cylinder::eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const {
  float su, cu;
  sincos_turns(u, su, cu);
  norm = glm::vec3(cu, 0.0f, -su);
  pos = norm * radius_ + glm::vec3(0.0f, v * height_, 0.0f);
}

void Cone::eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const {
  float su, cu;
  sincos_turns(u, su, cu);
  const glm::vec3 radial(cu, 0.0f, -su);
  pos = radial * (radius_ * (1.0f - v)) + glm::vec3(0.0f, v * height_, 0.0f);
  // Perpendicular to the slant line from the rim (radius, 0) to the apex (0, height).
  norm = radial * height_ + glm::vec3(0.0f, radius_, 0.0f);
}

void Plane::eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const {
  pos = glm::vec3((u - 0.5f) * size_, 0.0f, (0.5f - v) * size_);
  norm = glm::vec3(0.0f, 1.0f, 0.0f);
}

void FunctionSurface::eval(float u, float v, glm::vec3& pos, glm::vec3& norm) const {
  pos = pos_(u, v);
  if (normal_) {
    norm = normal_(u, v);
    return;
  }
  const float h = 1e-3f;
  const glm::vec3 du = pos_(u + h, v) - pos_(u - h, v), dv = pos_(u, v + h) - pos_(u, v - h);
  norm = glm::cross(du, dv);
}

}  // namespace tessel::scene
