// GLUT's geometric shapes (GLUT 3 API, section 11 of the GLUT specification): spheres, cubes,
// cones, tori, the five Platonic solids and the Utah teapot, plus freeglut's cylinder, drawn
// with OpenGL 1.1 immediate mode only (glBegin/glEnd, glNormal3f, glTexCoord2f, glVertex3f).
//
// The geometry follows freeglut 3.4, so that images agree with it: the same vertices and
// normals (computed in single precision the same way), the same primitive types (triangle
// strips for the round shapes, triangles for the solids and the teapot, line strips and loops
// for the wire versions) and the same vertex order. freeglut draws from client arrays, which
// leave the current normal and texture coordinate untouched; these functions put them back
// too, so GL state after a call is the same.

#include <GL/gl.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

extern "C" {
void glutSolidSphere(double radius, GLint slices, GLint stacks);
void glutWireSphere(double radius, GLint slices, GLint stacks);
void glutSolidCube(double size);
void glutWireCube(double size);
void glutSolidCone(double base, double height, GLint slices, GLint stacks);
void glutWireCone(double base, double height, GLint slices, GLint stacks);
void glutSolidTorus(double innerRadius, double outerRadius, GLint sides, GLint rings);
void glutWireTorus(double innerRadius, double outerRadius, GLint sides, GLint rings);
void glutSolidTetrahedron(void);
void glutWireTetrahedron(void);
void glutSolidOctahedron(void);
void glutWireOctahedron(void);
void glutSolidDodecahedron(void);
void glutWireDodecahedron(void);
void glutSolidIcosahedron(void);
void glutWireIcosahedron(void);
void glutSolidTeapot(double size);
void glutWireTeapot(double size);
void glutSolidCylinder(double radius, double height, GLint slices, GLint stacks);
void glutWireCylinder(double radius, double height, GLint slices, GLint stacks);
}

namespace {

constexpr double kPi = 3.14159265358979323846;

// Restores the current normal (and texture coordinate) on scope exit.
class KeepCurrent {
 public:
  explicit KeepCurrent(bool texCoord = false) : texCoord_(texCoord) {
    glGetFloatv(GL_CURRENT_NORMAL, normal_);
    if (texCoord_) glGetFloatv(GL_CURRENT_TEXTURE_COORDS, tex_);
  }
  ~KeepCurrent() {
    glNormal3fv(normal_);
    if (texCoord_) glTexCoord4fv(tex_);
  }
  KeepCurrent(const KeepCurrent&) = delete;
  KeepCurrent& operator=(const KeepCurrent&) = delete;

 private:
  bool texCoord_;
  GLfloat normal_[4] = {0, 0, 1, 0};
  GLfloat tex_[4] = {0, 0, 0, 1};
};

struct Vec3 {
  float x, y, z;
};

// Vertex positions and normals, drawn by index.
struct Mesh {
  std::vector<Vec3> p, n;
  void add(Vec3 pos, Vec3 nrm) {
    p.push_back(pos);
    n.push_back(nrm);
  }
  void emit(int i) const {
    glNormal3f(n[i].x, n[i].y, n[i].z);
    glVertex3f(p[i].x, p[i].y, p[i].z);
  }
};

// sin and cos at n+1 evenly spaced angles over a full circle (or half of one), in single
// precision. A negative n turns the other way. The last entry closes the circle exactly.
struct CircleTable {
  std::vector<float> s, c;
};

CircleTable circleTable(int n, bool half) {
  const int size = std::abs(n);
  const float step =
      static_cast<float>(half ? 1 : 2) * static_cast<float>(kPi) / static_cast<float>(n == 0 ? 1 : n);
  CircleTable t;
  t.s.resize(size + 1);
  t.c.resize(size + 1);
  t.s[0] = 0.0f;
  t.c[0] = 1.0f;
  for (int i = 1; i < size; i++) {
    const float a = step * static_cast<float>(i);
    t.s[i] = static_cast<float>(std::sin(static_cast<double>(a)));
    t.c[i] = static_cast<float>(std::cos(static_cast<double>(a)));
  }
  if (half) {
    t.s[size] = 0.0f;
    t.c[size] = -1.0f;
  } else {
    t.s[size] = t.s[0];
    t.c[size] = t.c[0];
  }
  return t;
}

// ---------------------------------------------------------------------------------------------
// Sphere: vertex 0 is the north pole (+z), then stacks-1 rings of `slices` vertices (from +x
// turning towards -y), then the south pole.

Mesh sphereMesh(double radiusD, int slices, int stacks) {
  Mesh m;
  const float radius = static_cast<float>(radiusD);
  const CircleTable around = circleTable(-slices, false);
  const CircleTable down = circleTable(stacks, true);
  m.add({0.0f, 0.0f, radius}, {0.0f, 0.0f, 1.0f});
  for (int i = 1; i < stacks; i++)
    for (int j = 0; j < slices; j++) {
      const float x = around.c[j] * down.s[i], y = around.s[j] * down.s[i], z = down.c[i];
      m.add({x * radius, y * radius, z * radius}, {x, y, z});
    }
  m.add({0.0f, 0.0f, -radius}, {0.0f, 0.0f, -1.0f});
  return m;
}

// ---------------------------------------------------------------------------------------------
// Cone: the centre of the base, a ring of base vertices with normal -z, then stacks+1 rings of
// side vertices from z = 0 up to the apex (radius and height stepped by repeated addition).

Mesh coneMesh(double base, double height, int slices, int stacks) {
  Mesh m;
  float z = 0.0f;
  float r = static_cast<float>(base);
  const float zStep = static_cast<float>(height) / static_cast<float>(stacks > 0 ? stacks : 1);
  const float rStep = static_cast<float>(base) / static_cast<float>(stacks > 0 ? stacks : 1);
  const float cosn = static_cast<float>(height / std::sqrt(height * height + base * base));
  const float sinn = static_cast<float>(base / std::sqrt(height * height + base * base));
  const CircleTable t = circleTable(-slices, false);
  m.add({0.0f, 0.0f, z}, {0.0f, 0.0f, -1.0f});
  for (int j = 0; j < slices; j++) m.add({t.c[j] * r, t.s[j] * r, z}, {0.0f, 0.0f, -1.0f});
  for (int i = 0; i <= stacks; i++) {
    for (int j = 0; j < slices; j++) m.add({t.c[j] * r, t.s[j] * r, z}, {t.c[j] * cosn, t.s[j] * cosn, sinn});
    z += zStep;
    r -= rStep;
  }
  return m;
}

// ---------------------------------------------------------------------------------------------
// Cylinder (a freeglut extension): the centre of the base and a ring with normal -z, stacks+1
// rings of side vertices from z = 0 up (z stepped by repeated addition, so the last ring can be
// an ulp off the height), the last ring again with normal +z, and the centre of the top.

Mesh cylinderMesh(double radiusD, double height, int slices, int stacks) {
  Mesh m;
  const float radius = static_cast<float>(radiusD), top = static_cast<float>(height);
  const float zStep = static_cast<float>(height) / static_cast<float>(stacks > 0 ? stacks : 1);
  const CircleTable t = circleTable(-slices, false);
  m.add({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f});
  for (int j = 0; j < slices; j++) m.add({t.c[j] * radius, t.s[j] * radius, 0.0f}, {0.0f, 0.0f, -1.0f});
  float z = 0.0f, last = 0.0f;
  for (int i = 0; i <= stacks; i++) {
    for (int j = 0; j < slices; j++) m.add({t.c[j] * radius, t.s[j] * radius, z}, {t.c[j], t.s[j], 0.0f});
    last = z;
    z += zStep;
  }
  for (int j = 0; j < slices; j++) m.add({t.c[j] * radius, t.s[j] * radius, last}, {0.0f, 0.0f, 1.0f});
  m.add({0.0f, 0.0f, top}, {0.0f, 0.0f, 1.0f});
  return m;
}

// ---------------------------------------------------------------------------------------------
// Torus around z: `rings` rings around z, each a circle of `sides` vertices.

Mesh torusMesh(double innerRadius, double outerRadius, int sides, int rings) {
  Mesh m;
  const float ir = static_cast<float>(innerRadius), orad = static_cast<float>(outerRadius);
  const CircleTable psi = circleTable(rings, false);
  const CircleTable phi = circleTable(-sides, false);
  for (int j = 0; j < rings; j++)
    for (int i = 0; i < sides; i++) {
      const float d = orad + phi.c[i] * ir;
      m.add({psi.c[j] * d, psi.s[j] * d, phi.s[i] * ir},
            {psi.c[j] * phi.c[i], psi.s[j] * phi.c[i], phi.s[i]});
    }
  return m;
}

// ---------------------------------------------------------------------------------------------
// Platonic solids: a vertex table and faces listed counter-clockwise from outside. Solids are
// drawn as triangles (a square as 0-1-2, 0-2-3; a pentagon as 0-1-2, 0-2-4, 4-2-3), wire
// frames as one line loop per face, every vertex of a face with the face's normal.

// How a face's normal is made. The solids are centred at the origin, so the normalised
// centroid is the unit normal; GLUT's tetrahedron uses the opposite vertex (the same vector,
// rounded differently), and its icosahedron the cross product of two edges, which is not of
// unit length (it is twice the face's area, about 0.957); lighting without GL_NORMALIZE
// shows the difference, so it is kept.
enum class NormalRule { Centroid, OppositeVertex, EdgeCross };

struct Polyhedron {
  std::vector<Vec3> vertices;
  int faceSize = 3;
  std::vector<int> faces;  // faceSize indices per face
  NormalRule rule = NormalRule::Centroid;
  std::vector<std::array<double, 3>> exact;  // unrounded vertices, for NormalRule::EdgeCross
};

Polyhedron makePolyhedron(std::vector<Vec3> vertices, int faceSize, std::vector<int> faces,
                          NormalRule rule = NormalRule::Centroid) {
  Polyhedron p;
  p.vertices = std::move(vertices);
  p.faceSize = faceSize;
  p.faces = std::move(faces);
  p.rule = rule;
  return p;
}

Vec3 faceNormal(const Polyhedron& p, int f) {
  const int* face = &p.faces[f * p.faceSize];
  double n[3] = {0, 0, 0};
  switch (p.rule) {
    case NormalRule::Centroid:
      for (int k = 0; k < p.faceSize; k++) {
        const Vec3& v = p.vertices[face[k]];
        n[0] += v.x;
        n[1] += v.y;
        n[2] += v.z;
      }
      break;
    case NormalRule::OppositeVertex: {
      // Face f of the tetrahedron is the one without vertex f.
      const Vec3& v = p.vertices[f];
      return {-v.x, -v.y, -v.z};
    }
    case NormalRule::EdgeCross: {
      const auto &a = p.exact[face[0]], &b = p.exact[face[1]], &c = p.exact[face[2]];
      const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      double x[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                     e1[0] * e2[1] - e1[1] * e2[0]};
      for (double& v : x)
        if (std::fabs(v) < 1e-12) v = 0;  // exact zeros, not rounding noise
      return {static_cast<float>(x[0]), static_cast<float>(x[1]), static_cast<float>(x[2])};
    }
  }
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  return {static_cast<float>(n[0] / len), static_cast<float>(n[1] / len), static_cast<float>(n[2] / len)};
}

void drawPolyhedron(const Polyhedron& p, bool wire, float scale = 1.0f) {
  static const int tri[] = {0, 1, 2};
  static const int quad[] = {0, 1, 2, 0, 2, 3};
  static const int pent[] = {0, 1, 2, 0, 2, 4, 4, 2, 3};
  const int* order = p.faceSize == 3 ? tri : p.faceSize == 4 ? quad : pent;
  const int count = p.faceSize == 3 ? 3 : p.faceSize == 4 ? 6 : 9;
  const int faces = static_cast<int>(p.faces.size()) / p.faceSize;
  KeepCurrent keep;
  auto vertex = [&](int f, int k) {
    const Vec3& v = p.vertices[p.faces[f * p.faceSize + k]];
    glVertex3f(v.x * scale, v.y * scale, v.z * scale);
  };
  if (wire) {
    for (int f = 0; f < faces; f++) {
      const Vec3 n = faceNormal(p, f);
      glBegin(GL_LINE_LOOP);
      glNormal3f(n.x, n.y, n.z);
      for (int k = 0; k < p.faceSize; k++) vertex(f, k);
      glEnd();
    }
    return;
  }
  glBegin(GL_TRIANGLES);
  for (int f = 0; f < faces; f++) {
    const Vec3 n = faceNormal(p, f);
    glNormal3f(n.x, n.y, n.z);
    for (int k = 0; k < count; k++) vertex(f, order[k]);
  }
  glEnd();
}

float f(double v) { return static_cast<float>(v); }

// Cube of edge 1 (scaled by the caller's size).
const Polyhedron& cube() {
  static const Polyhedron p =
      makePolyhedron({{.5f, .5f, .5f},
                      {-.5f, .5f, .5f},
                      {-.5f, -.5f, .5f},
                      {.5f, -.5f, .5f},
                      {.5f, -.5f, -.5f},
                      {.5f, .5f, -.5f},
                      {-.5f, .5f, -.5f},
                      {-.5f, -.5f, -.5f}},
                     4, {0, 1, 2, 3, 0, 3, 4, 5, 0, 5, 6, 1, 1, 6, 7, 2, 7, 4, 3, 2, 4, 7, 6, 5});
  return p;
}

// Tetrahedron inscribed in the unit sphere with a vertex on +x.
const Polyhedron& tetrahedron() {
  static const Polyhedron p =
      makePolyhedron({{1.0f, 0.0f, 0.0f},
                      {f(-1.0 / 3), f(2 * std::sqrt(2.0) / 3), 0.0f},
                      {f(-1.0 / 3), f(-std::sqrt(2.0) / 3), f(std::sqrt(6.0) / 3)},
                      {f(-1.0 / 3), f(-std::sqrt(2.0) / 3), f(-std::sqrt(6.0) / 3)}},
                     3, {1, 3, 2, 0, 2, 3, 0, 3, 1, 0, 1, 2}, NormalRule::OppositeVertex);
  return p;
}

// Octahedron with its vertices on the axes.
const Polyhedron& octahedron() {
  static const Polyhedron p =
      makePolyhedron({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}}, 3,
                     {0, 1, 2, 0, 5, 1, 0, 2, 4, 0, 4, 5, 3, 2, 1, 3, 1, 5, 3, 4, 2, 3, 5, 4});
  return p;
}

// Dodecahedron with vertices (+-1, +-1, +-1), (0, +-phi, +-1/phi) and its cyclic shifts.
const Polyhedron& dodecahedron() {
  static const float g = f((1 + std::sqrt(5.0)) / 2), h = f((std::sqrt(5.0) - 1) / 2);
  static const Polyhedron p = makePolyhedron(
      {{0, g, h},    {-1, 1, 1},  {-h, 0, g},  {h, 0, g},  {1, 1, 1},  {0, g, -h},  {1, 1, -1},
       {h, 0, -g},   {-h, 0, -g}, {-1, 1, -1}, {0, -g, h}, {1, -1, 1}, {-1, -1, 1}, {0, -g, -h},
       {-1, -1, -1}, {1, -1, -1}, {g, -h, 0},  {g, h, 0},  {-g, h, 0}, {-g, -h, 0}},
      5, {0,  1,  2,  3,  4, 5,  6,  7,  8,  9,  10, 11, 3,  2,  12, 13, 14, 8,  7,  15,
          3,  11, 16, 17, 4, 2,  1,  18, 19, 12, 7,  6,  17, 16, 15, 8,  14, 19, 18, 9,
          17, 6,  5,  0,  4, 16, 11, 10, 13, 15, 18, 1,  0,  5,  9,  19, 14, 13, 10, 12});
  return p;
}

// Icosahedron inscribed in the unit sphere with vertices on +-x: two rings of five at
// x = +-1/sqrt(5), the upper one starting at +y, the lower one turned by 36 degrees.
const Polyhedron& icosahedron() {
  static const Polyhedron p = [] {
    Polyhedron q;
    const double x = 1 / std::sqrt(5.0), r = 2 / std::sqrt(5.0);
    q.exact.push_back({1, 0, 0});
    for (int k = 0; k < 5; k++)
      q.exact.push_back({x, r * std::cos(k * 2 * kPi / 5), r * std::sin(k * 2 * kPi / 5)});
    for (int k = 0; k < 5; k++)
      q.exact.push_back({-x, r * std::cos((2 * k + 1) * kPi / 5), r * std::sin((2 * k + 1) * kPi / 5)});
    q.exact.push_back({-1, 0, 0});
    for (auto& v : q.exact) {
      for (double& c : v)
        if (std::fabs(c) < 1e-12) c = 0;  // sin(pi) is 0
      q.vertices.push_back({f(v[0]), f(v[1]), f(v[2])});
    }
    q.faceSize = 3;
    q.rule = NormalRule::EdgeCross;
    q.faces = {0, 1, 2, 0, 2,  3,  0,  3, 4,  0, 4,  5,  0, 5, 1,  1, 6, 2,  2, 7,
               3, 3, 8, 4, 4,  9,  5,  5, 10, 1, 1,  10, 6, 2, 6,  7, 3, 7,  8, 4,
               8, 9, 5, 9, 10, 11, 10, 9, 11, 6, 10, 11, 7, 6, 11, 8, 7, 11, 9, 8};
    return q;
  }();
  return p;
}

// ---------------------------------------------------------------------------------------------
// The Utah teapot: Martin Newell's 32 bicubic Bezier patches (public domain data), z up, in
// the coordinates of his original model. Control points are numbered from 0; each patch lists
// its 16 points row by row (rows are the first parameter, u).

constexpr float kTeapotPoints[306][3] = {
    {1.4f, 0.0f, 2.4f},
    {1.4f, -0.784f, 2.4f},
    {0.784f, -1.4f, 2.4f},
    {0.0f, -1.4f, 2.4f},  // 0
    {1.3375f, 0.0f, 2.53125f},
    {1.3375f, -0.749f, 2.53125f},
    {0.749f, -1.3375f, 2.53125f},
    {0.0f, -1.3375f, 2.53125f},  // 4
    {1.4375f, 0.0f, 2.53125f},
    {1.4375f, -0.805f, 2.53125f},
    {0.805f, -1.4375f, 2.53125f},
    {0.0f, -1.4375f, 2.53125f},  // 8
    {1.5f, 0.0f, 2.4f},
    {1.5f, -0.84f, 2.4f},
    {0.84f, -1.5f, 2.4f},
    {0.0f, -1.5f, 2.4f},  // 12
    {-0.784f, -1.4f, 2.4f},
    {-1.4f, -0.784f, 2.4f},
    {-1.4f, 0.0f, 2.4f},
    {-0.749f, -1.3375f, 2.53125f},  // 16
    {-1.3375f, -0.749f, 2.53125f},
    {-1.3375f, 0.0f, 2.53125f},
    {-0.805f, -1.4375f, 2.53125f},
    {-1.4375f, -0.805f, 2.53125f},  // 20
    {-1.4375f, 0.0f, 2.53125f},
    {-0.84f, -1.5f, 2.4f},
    {-1.5f, -0.84f, 2.4f},
    {-1.5f, 0.0f, 2.4f},  // 24
    {-1.4f, 0.784f, 2.4f},
    {-0.784f, 1.4f, 2.4f},
    {0.0f, 1.4f, 2.4f},
    {-1.3375f, 0.749f, 2.53125f},  // 28
    {-0.749f, 1.3375f, 2.53125f},
    {0.0f, 1.3375f, 2.53125f},
    {-1.4375f, 0.805f, 2.53125f},
    {-0.805f, 1.4375f, 2.53125f},  // 32
    {0.0f, 1.4375f, 2.53125f},
    {-1.5f, 0.84f, 2.4f},
    {-0.84f, 1.5f, 2.4f},
    {0.0f, 1.5f, 2.4f},  // 36
    {0.784f, 1.4f, 2.4f},
    {1.4f, 0.784f, 2.4f},
    {0.749f, 1.3375f, 2.53125f},
    {1.3375f, 0.749f, 2.53125f},  // 40
    {0.805f, 1.4375f, 2.53125f},
    {1.4375f, 0.805f, 2.53125f},
    {0.84f, 1.5f, 2.4f},
    {1.5f, 0.84f, 2.4f},  // 44
    {1.75f, 0.0f, 1.875f},
    {1.75f, -0.98f, 1.875f},
    {0.98f, -1.75f, 1.875f},
    {0.0f, -1.75f, 1.875f},  // 48
    {2.0f, 0.0f, 1.35f},
    {2.0f, -1.12f, 1.35f},
    {1.12f, -2.0f, 1.35f},
    {0.0f, -2.0f, 1.35f},  // 52
    {2.0f, 0.0f, 0.9f},
    {2.0f, -1.12f, 0.9f},
    {1.12f, -2.0f, 0.9f},
    {0.0f, -2.0f, 0.9f},  // 56
    {-0.98f, -1.75f, 1.875f},
    {-1.75f, -0.98f, 1.875f},
    {-1.75f, 0.0f, 1.875f},
    {-1.12f, -2.0f, 1.35f},  // 60
    {-2.0f, -1.12f, 1.35f},
    {-2.0f, 0.0f, 1.35f},
    {-1.12f, -2.0f, 0.9f},
    {-2.0f, -1.12f, 0.9f},  // 64
    {-2.0f, 0.0f, 0.9f},
    {-1.75f, 0.98f, 1.875f},
    {-0.98f, 1.75f, 1.875f},
    {0.0f, 1.75f, 1.875f},  // 68
    {-2.0f, 1.12f, 1.35f},
    {-1.12f, 2.0f, 1.35f},
    {0.0f, 2.0f, 1.35f},
    {-2.0f, 1.12f, 0.9f},  // 72
    {-1.12f, 2.0f, 0.9f},
    {0.0f, 2.0f, 0.9f},
    {0.98f, 1.75f, 1.875f},
    {1.75f, 0.98f, 1.875f},  // 76
    {1.12f, 2.0f, 1.35f},
    {2.0f, 1.12f, 1.35f},
    {1.12f, 2.0f, 0.9f},
    {2.0f, 1.12f, 0.9f},  // 80
    {2.0f, 0.0f, 0.45f},
    {2.0f, -1.12f, 0.45f},
    {1.12f, -2.0f, 0.45f},
    {0.0f, -2.0f, 0.45f},  // 84
    {1.5f, 0.0f, 0.225f},
    {1.5f, -0.84f, 0.225f},
    {0.84f, -1.5f, 0.225f},
    {0.0f, -1.5f, 0.225f},  // 88
    {1.5f, 0.0f, 0.15f},
    {1.5f, -0.84f, 0.15f},
    {0.84f, -1.5f, 0.15f},
    {0.0f, -1.5f, 0.15f},  // 92
    {-1.12f, -2.0f, 0.45f},
    {-2.0f, -1.12f, 0.45f},
    {-2.0f, 0.0f, 0.45f},
    {-0.84f, -1.5f, 0.225f},  // 96
    {-1.5f, -0.84f, 0.225f},
    {-1.5f, 0.0f, 0.225f},
    {-0.84f, -1.5f, 0.15f},
    {-1.5f, -0.84f, 0.15f},  // 100
    {-1.5f, 0.0f, 0.15f},
    {-2.0f, 1.12f, 0.45f},
    {-1.12f, 2.0f, 0.45f},
    {0.0f, 2.0f, 0.45f},  // 104
    {-1.5f, 0.84f, 0.225f},
    {-0.84f, 1.5f, 0.225f},
    {0.0f, 1.5f, 0.225f},
    {-1.5f, 0.84f, 0.15f},  // 108
    {-0.84f, 1.5f, 0.15f},
    {0.0f, 1.5f, 0.15f},
    {1.12f, 2.0f, 0.45f},
    {2.0f, 1.12f, 0.45f},  // 112
    {0.84f, 1.5f, 0.225f},
    {1.5f, 0.84f, 0.225f},
    {0.84f, 1.5f, 0.15f},
    {1.5f, 0.84f, 0.15f},  // 116
    {-1.6f, 0.0f, 2.025f},
    {-1.6f, -0.3f, 2.025f},
    {-1.5f, -0.3f, 2.25f},
    {-1.5f, 0.0f, 2.25f},  // 120
    {-2.3f, 0.0f, 2.025f},
    {-2.3f, -0.3f, 2.025f},
    {-2.5f, -0.3f, 2.25f},
    {-2.5f, 0.0f, 2.25f},  // 124
    {-2.7f, 0.0f, 2.025f},
    {-2.7f, -0.3f, 2.025f},
    {-3.0f, -0.3f, 2.25f},
    {-3.0f, 0.0f, 2.25f},  // 128
    {-2.7f, 0.0f, 1.8f},
    {-2.7f, -0.3f, 1.8f},
    {-3.0f, -0.3f, 1.8f},
    {-3.0f, 0.0f, 1.8f},  // 132
    {-1.5f, 0.3f, 2.25f},
    {-1.6f, 0.3f, 2.025f},
    {-2.5f, 0.3f, 2.25f},
    {-2.3f, 0.3f, 2.025f},  // 136
    {-3.0f, 0.3f, 2.25f},
    {-2.7f, 0.3f, 2.025f},
    {-3.0f, 0.3f, 1.8f},
    {-2.7f, 0.3f, 1.8f},  // 140
    {-2.7f, 0.0f, 1.575f},
    {-2.7f, -0.3f, 1.575f},
    {-3.0f, -0.3f, 1.35f},
    {-3.0f, 0.0f, 1.35f},  // 144
    {-2.5f, 0.0f, 1.125f},
    {-2.5f, -0.3f, 1.125f},
    {-2.65f, -0.3f, 0.9375f},
    {-2.65f, 0.0f, 0.9375f},  // 148
    {-2.0f, -0.3f, 0.9f},
    {-1.9f, -0.3f, 0.6f},
    {-1.9f, 0.0f, 0.6f},
    {-3.0f, 0.3f, 1.35f},  // 152
    {-2.7f, 0.3f, 1.575f},
    {-2.65f, 0.3f, 0.9375f},
    {-2.5f, 0.3f, 1.125f},
    {-1.9f, 0.3f, 0.6f},  // 156
    {-2.0f, 0.3f, 0.9f},
    {1.7f, 0.0f, 1.425f},
    {1.7f, -0.66f, 1.425f},
    {1.7f, -0.66f, 0.6f},  // 160
    {1.7f, 0.0f, 0.6f},
    {2.6f, 0.0f, 1.425f},
    {2.6f, -0.66f, 1.425f},
    {3.1f, -0.66f, 0.825f},  // 164
    {3.1f, 0.0f, 0.825f},
    {2.3f, 0.0f, 2.1f},
    {2.3f, -0.25f, 2.1f},
    {2.4f, -0.25f, 2.025f},  // 168
    {2.4f, 0.0f, 2.025f},
    {2.7f, 0.0f, 2.4f},
    {2.7f, -0.25f, 2.4f},
    {3.3f, -0.25f, 2.4f},  // 172
    {3.3f, 0.0f, 2.4f},
    {1.7f, 0.66f, 0.6f},
    {1.7f, 0.66f, 1.425f},
    {3.1f, 0.66f, 0.825f},  // 176
    {2.6f, 0.66f, 1.425f},
    {2.4f, 0.25f, 2.025f},
    {2.3f, 0.25f, 2.1f},
    {3.3f, 0.25f, 2.4f},  // 180
    {2.7f, 0.25f, 2.4f},
    {2.8f, 0.0f, 2.475f},
    {2.8f, -0.25f, 2.475f},
    {3.525f, -0.25f, 2.49375f},  // 184
    {3.525f, 0.0f, 2.49375f},
    {2.9f, 0.0f, 2.475f},
    {2.9f, -0.15f, 2.475f},
    {3.45f, -0.15f, 2.5125f},  // 188
    {3.45f, 0.0f, 2.5125f},
    {2.8f, 0.0f, 2.4f},
    {2.8f, -0.15f, 2.4f},
    {3.2f, -0.15f, 2.4f},  // 192
    {3.2f, 0.0f, 2.4f},
    {3.525f, 0.25f, 2.49375f},
    {2.8f, 0.25f, 2.475f},
    {3.45f, 0.15f, 2.5125f},  // 196
    {2.9f, 0.15f, 2.475f},
    {3.2f, 0.15f, 2.4f},
    {2.8f, 0.15f, 2.4f},
    {0.0f, 0.0f, 3.15f},  // 200
    {0.0f, -0.002f, 3.15f},
    {0.002f, 0.0f, 3.15f},
    {0.8f, 0.0f, 3.15f},
    {0.8f, -0.45f, 3.15f},  // 204
    {0.45f, -0.8f, 3.15f},
    {0.0f, -0.8f, 3.15f},
    {0.0f, 0.0f, 2.85f},
    {0.2f, 0.0f, 2.7f},  // 208
    {0.2f, -0.112f, 2.7f},
    {0.112f, -0.2f, 2.7f},
    {0.0f, -0.2f, 2.7f},
    {-0.002f, 0.0f, 3.15f},  // 212
    {-0.45f, -0.8f, 3.15f},
    {-0.8f, -0.45f, 3.15f},
    {-0.8f, 0.0f, 3.15f},
    {-0.112f, -0.2f, 2.7f},  // 216
    {-0.2f, -0.112f, 2.7f},
    {-0.2f, 0.0f, 2.7f},
    {0.0f, 0.002f, 3.15f},
    {-0.8f, 0.45f, 3.15f},  // 220
    {-0.45f, 0.8f, 3.15f},
    {0.0f, 0.8f, 3.15f},
    {-0.2f, 0.112f, 2.7f},
    {-0.112f, 0.2f, 2.7f},  // 224
    {0.0f, 0.2f, 2.7f},
    {0.45f, 0.8f, 3.15f},
    {0.8f, 0.45f, 3.15f},
    {0.112f, 0.2f, 2.7f},  // 228
    {0.2f, 0.112f, 2.7f},
    {0.4f, 0.0f, 2.55f},
    {0.4f, -0.224f, 2.55f},
    {0.224f, -0.4f, 2.55f},  // 232
    {0.0f, -0.4f, 2.55f},
    {1.3f, 0.0f, 2.55f},
    {1.3f, -0.728f, 2.55f},
    {0.728f, -1.3f, 2.55f},  // 236
    {0.0f, -1.3f, 2.55f},
    {1.3f, 0.0f, 2.4f},
    {1.3f, -0.728f, 2.4f},
    {0.728f, -1.3f, 2.4f},  // 240
    {0.0f, -1.3f, 2.4f},
    {-0.224f, -0.4f, 2.55f},
    {-0.4f, -0.224f, 2.55f},
    {-0.4f, 0.0f, 2.55f},  // 244
    {-0.728f, -1.3f, 2.55f},
    {-1.3f, -0.728f, 2.55f},
    {-1.3f, 0.0f, 2.55f},
    {-0.728f, -1.3f, 2.4f},  // 248
    {-1.3f, -0.728f, 2.4f},
    {-1.3f, 0.0f, 2.4f},
    {-0.4f, 0.224f, 2.55f},
    {-0.224f, 0.4f, 2.55f},  // 252
    {0.0f, 0.4f, 2.55f},
    {-1.3f, 0.728f, 2.55f},
    {-0.728f, 1.3f, 2.55f},
    {0.0f, 1.3f, 2.55f},  // 256
    {-1.3f, 0.728f, 2.4f},
    {-0.728f, 1.3f, 2.4f},
    {0.0f, 1.3f, 2.4f},
    {0.224f, 0.4f, 2.55f},  // 260
    {0.4f, 0.224f, 2.55f},
    {0.728f, 1.3f, 2.55f},
    {1.3f, 0.728f, 2.55f},
    {0.728f, 1.3f, 2.4f},  // 264
    {1.3f, 0.728f, 2.4f},
    {0.0f, 0.0f, 0.0f},
    {1.5f, 0.0f, 0.15f},
    {1.5f, 0.84f, 0.15f},  // 268
    {0.84f, 1.5f, 0.15f},
    {0.0f, 1.5f, 0.15f},
    {1.5f, 0.0f, 0.075f},
    {1.5f, 0.84f, 0.075f},  // 272
    {0.84f, 1.5f, 0.075f},
    {0.0f, 1.5f, 0.075f},
    {1.425f, 0.0f, 0.0f},
    {1.425f, 0.798f, 0.0f},  // 276
    {0.798f, 1.425f, 0.0f},
    {0.0f, 1.425f, 0.0f},
    {-0.84f, 1.5f, 0.15f},
    {-1.5f, 0.84f, 0.15f},  // 280
    {-1.5f, 0.0f, 0.15f},
    {-0.84f, 1.5f, 0.075f},
    {-1.5f, 0.84f, 0.075f},
    {-1.5f, 0.0f, 0.075f},  // 284
    {-0.798f, 1.425f, 0.0f},
    {-1.425f, 0.798f, 0.0f},
    {-1.425f, 0.0f, 0.0f},
    {-1.5f, -0.84f, 0.15f},  // 288
    {-0.84f, -1.5f, 0.15f},
    {0.0f, -1.5f, 0.15f},
    {-1.5f, -0.84f, 0.075f},
    {-0.84f, -1.5f, 0.075f},  // 292
    {0.0f, -1.5f, 0.075f},
    {-1.425f, -0.798f, 0.0f},
    {-0.798f, -1.425f, 0.0f},
    {0.0f, -1.425f, 0.0f},  // 296
    {0.84f, -1.5f, 0.15f},
    {1.5f, -0.84f, 0.15f},
    {0.84f, -1.5f, 0.075f},
    {1.5f, -0.84f, 0.075f},  // 300
    {0.798f, -1.425f, 0.0f},
    {1.425f, -0.798f, 0.0f},  // 304
};

// The lid's top row (patches 20-23) is nearly a point: the apex (point 203) and two of the
// points 0.002 away from it (204, 205, 215, 222), as in the data GLUT uses.
constexpr unsigned short kTeapotPatches[32][16] = {
    {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},                            // 0
    {3, 16, 17, 18, 7, 19, 20, 21, 11, 22, 23, 24, 15, 25, 26, 27},                    // 1
    {18, 28, 29, 30, 21, 31, 32, 33, 24, 34, 35, 36, 27, 37, 38, 39},                  // 2
    {30, 40, 41, 0, 33, 42, 43, 4, 36, 44, 45, 8, 39, 46, 47, 12},                     // 3
    {12, 13, 14, 15, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59},                  // 4
    {15, 25, 26, 27, 51, 60, 61, 62, 55, 63, 64, 65, 59, 66, 67, 68},                  // 5
    {27, 37, 38, 39, 62, 69, 70, 71, 65, 72, 73, 74, 68, 75, 76, 77},                  // 6
    {39, 46, 47, 12, 71, 78, 79, 48, 74, 80, 81, 52, 77, 82, 83, 56},                  // 7
    {56, 57, 58, 59, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95},                  // 8
    {59, 66, 67, 68, 87, 96, 97, 98, 91, 99, 100, 101, 95, 102, 103, 104},             // 9
    {68, 75, 76, 77, 98, 105, 106, 107, 101, 108, 109, 110, 104, 111, 112, 113},       // 10
    {77, 82, 83, 56, 107, 114, 115, 84, 110, 116, 117, 88, 113, 118, 119, 92},         // 11
    {120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135},  // 12
    {123, 136, 137, 120, 127, 138, 139, 124, 131, 140, 141, 128, 135, 142, 143, 132},  // 13
    {132, 133, 134, 135, 144, 145, 146, 147, 148, 149, 150, 151, 68, 152, 153, 154},   // 14
    {135, 142, 143, 132, 147, 155, 156, 144, 151, 157, 158, 148, 154, 159, 160, 68},   // 15
    {161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176},  // 16
    {164, 177, 178, 161, 168, 179, 180, 165, 172, 181, 182, 169, 176, 183, 184, 173},  // 17
    {173, 174, 175, 176, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196},  // 18
    {176, 183, 184, 173, 188, 197, 198, 185, 192, 199, 200, 189, 196, 201, 202, 193},  // 19
    {203, 204, 205, 203, 206, 207, 208, 209, 210, 210, 210, 210, 211, 212, 213, 214},  // 20
    {203, 215, 204, 203, 209, 216, 217, 218, 210, 210, 210, 210, 214, 219, 220, 221},  // 21
    {203, 222, 215, 203, 218, 223, 224, 225, 210, 210, 210, 210, 221, 226, 227, 228},  // 22
    {203, 205, 222, 203, 225, 229, 230, 206, 210, 210, 210, 210, 228, 231, 232, 211},  // 23
    {211, 212, 213, 214, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244},  // 24
    {214, 219, 220, 221, 236, 245, 246, 247, 240, 248, 249, 250, 244, 251, 252, 253},  // 25
    {221, 226, 227, 228, 247, 254, 255, 256, 250, 257, 258, 259, 253, 260, 261, 262},  // 26
    {228, 231, 232, 211, 256, 263, 264, 233, 259, 265, 266, 237, 262, 267, 268, 241},  // 27
    {269, 269, 269, 269, 278, 279, 280, 281, 274, 275, 276, 277, 270, 271, 272, 273},  // 28
    {269, 269, 269, 269, 281, 288, 289, 290, 277, 285, 286, 287, 273, 282, 283, 284},  // 29
    {269, 269, 269, 269, 290, 297, 298, 299, 287, 294, 295, 296, 284, 291, 292, 293},  // 30
    {269, 269, 269, 269, 299, 304, 305, 278, 296, 302, 303, 274, 293, 300, 301, 270},  // 31
};

// GLUT's teapot is symmetric: it evaluates ten patches and makes the other 22 from them. The
// rim, the body, the lid and the bottom are turned about the vertical axis by 90, 180 and 270
// degrees; the handle and the spout are mirrored in the plane of symmetry (rows in reverse
// order, so that the winding stays the same). Copies are made from the evaluated vertices and
// normals, so they agree with GLUT's to the last bit.
enum class Copies { Turn4, Mirror2 };
struct PatchGroup {
  unsigned char patch;  // index into kTeapotPatches
  Copies copies;
  signed char fixFirstRow;  // +1 / -1: the first row is a point; its normals are +y / -y
};
constexpr PatchGroup kTeapotGroups[10] = {
    {0, Copies::Turn4, 0},                               // rim
    {4, Copies::Turn4, 0},                               // body, upper part
    {8, Copies::Turn4, 0},                               // body, lower part
    {20, Copies::Turn4, 1},                              // lid, top
    {24, Copies::Turn4, 0},                              // lid, lower part
    {31, Copies::Turn4, -1},                             // bottom
    {12, Copies::Mirror2, 0}, {14, Copies::Mirror2, 0},  // handle
    {16, Copies::Mirror2, 0}, {18, Copies::Mirror2, 0},  // spout
};

// Evaluates the teapot on an n x n grid of parameters per patch, in GLUT's frame (y up, centred
// vertically, scaled by size/2). Vertex (patch, a, b) is at index (patch * n + a) * n + b, with
// a along the patch's first parameter; patches come in the order GLUT draws them.
// The control points are scaled before evaluation, as freeglut does, so vertices and normals
// are bit-identical to freeglut's for any size. (freeglut keeps the normals of its first call
// and reuses them for later sizes; those differ from these by about 1e-6.)
Mesh teapotMesh(double size, int n) {
  Mesh m;
  m.p.reserve(32 * n * n);
  m.n.reserve(32 * n * n);
  // Bernstein polynomials and their derivatives at the grid parameters.
  std::vector<float> b0(n * 4), b1(n * 4);
  for (int i = 0; i < n; i++) {
    const float t = static_cast<float>(i) / static_cast<float>(n - 1), s = 1.0f - t;
    const float t2 = t * t, s2 = s * s;
    b0[i * 4 + 0] = s2 * s;
    b0[i * 4 + 1] = 3 * t * s2;
    b0[i * 4 + 2] = 3 * t2 * s;
    b0[i * 4 + 3] = t2 * t;
    b1[i * 4 + 0] = -3 * s2;
    b1[i * 4 + 1] = 3 * s2 - 6 * t * s;
    b1[i * 4 + 2] = 6 * t * s - 3 * t2;
    b1[i * 4 + 3] = 3 * t2;
  }
  const float scale = static_cast<float>(0.5 * size);
  const int count = n * n;
  for (const PatchGroup& group : kTeapotGroups) {
    // The patch's control points in GLUT's frame: (x, z - 1.575, -y) * size / 2.
    float cp[4][4][3];
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++) {
        const float* src = kTeapotPoints[kTeapotPatches[group.patch][i * 4 + j]];
        cp[i][j][0] = src[0] * scale;
        cp[i][j][1] = (src[2] - 1.575f) * scale;
        cp[i][j][2] = -src[1] * scale;
      }
    const size_t first = m.p.size();
    for (int a = 0; a < n; a++)
      for (int b = 0; b < n; b++) {
        // Position and the derivatives along both parameters: each row first along the second
        // parameter, then the rows combined along the first.
        float pos[3] = {0, 0, 0}, dv[3] = {0, 0, 0}, du[3] = {0, 0, 0};
        for (int i = 0; i < 4; i++) {
          float row[3] = {0, 0, 0}, rowD[3] = {0, 0, 0};
          for (int j = 0; j < 4; j++)
            for (int k = 0; k < 3; k++) {
              row[k] += b0[b * 4 + j] * cp[i][j][k];
              rowD[k] += b1[b * 4 + j] * cp[i][j][k];
            }
          for (int k = 0; k < 3; k++) {
            pos[k] += b0[a * 4 + i] * row[k];
            dv[k] += b0[a * 4 + i] * rowD[k];
            du[k] += b1[a * 4 + i] * row[k];
          }
        }
        // The normal is dv x du (GLUT's teapot patches are wound that way).
        Vec3 nrm = {dv[1] * du[2] - dv[2] * du[1], dv[2] * du[0] - dv[0] * du[2],
                    dv[0] * du[1] - dv[1] * du[0]};
        const float len = std::sqrt(nrm.x * nrm.x + nrm.y * nrm.y + nrm.z * nrm.z);
        nrm = {nrm.x / len, nrm.y / len, nrm.z / len};
        if (a == 0 && group.fixFirstRow != 0) nrm = {0.0f, static_cast<float>(group.fixFirstRow), 0.0f};
        m.add({pos[0], pos[1], pos[2]}, nrm);
      }
    if (group.copies == Copies::Turn4) {
      // Quarter turns about y: (x, y, z) -> (z, y, -x), (-x, y, -z), (-z, y, x).
      for (int turn = 1; turn < 4; turn++)
        for (int k = 0; k < count; k++) {
          auto rotate = [turn](Vec3 v) -> Vec3 {
            if (turn == 1) return {v.z, v.y, -v.x};
            if (turn == 2) return {-v.x, v.y, -v.z};
            return {-v.z, v.y, v.x};
          };
          const Vec3 p = m.p[first + k], q = m.n[first + k];
          m.add(rotate(p), rotate(q));
        }
    } else {
      // Mirror image in z = 0, rows in reverse order.
      for (int a = 0; a < n; a++)
        for (int b = 0; b < n; b++) {
          const size_t k = first + static_cast<size_t>(n - 1 - a) * n + b;
          const Vec3 p = m.p[k], q = m.n[k];
          m.add({p.x, p.y, -p.z}, {q.x, q.y, -q.z});
        }
    }
  }
  return m;
}

void solidTeapot(double size) {
  constexpr int n = 8;  // 7 x 7 quads per patch
  const Mesh m = teapotMesh(size, n);
  KeepCurrent keep(true);
  auto vertex = [&](int p, int a, int b) {
    glTexCoord2f(static_cast<float>(a) / (n - 1), static_cast<float>(b) / (n - 1));
    m.emit((p * n + a) * n + b);
  };
  glBegin(GL_TRIANGLES);
  for (int p = 0; p < 32; p++)
    for (int a = 0; a < n - 1; a++)
      for (int b = 0; b < n - 1; b++) {
        vertex(p, a, b);
        vertex(p, a + 1, b);
        vertex(p, a + 1, b + 1);
        vertex(p, a, b);
        vertex(p, a + 1, b + 1);
        vertex(p, a, b + 1);
      }
  glEnd();
}

void wireTeapot(double size) {
  constexpr int n = 10;  // 10 x 10 grid lines per patch
  const Mesh m = teapotMesh(size, n);
  KeepCurrent keep;
  // Lines along the first parameter for every patch, then along the second.
  for (int p = 0; p < 32; p++)
    for (int b = 0; b < n; b++) {
      glBegin(GL_LINE_STRIP);
      for (int a = 0; a < n; a++) m.emit((p * n + a) * n + b);
      glEnd();
    }
  for (int p = 0; p < 32; p++)
    for (int a = 0; a < n; a++) {
      glBegin(GL_LINE_STRIP);
      for (int b = 0; b < n; b++) m.emit((p * n + a) * n + b);
      glEnd();
    }
}

}  // namespace

extern "C" {

// ---------------------------------------------------------------------------------------------
// Sphere: triangle strips from pole to pole (a fan-like strip at each pole that repeats the
// pole vertex); wire: one line strip per meridian, one line loop per ring.

void glutSolidSphere(double radius, GLint slices, GLint stacks) {
  if (slices < 1 || stacks < 2) return;
  const Mesh m = sphereMesh(radius, slices, stacks);
  KeepCurrent keep;
  const int south = 1 + (stacks - 1) * slices;
  auto ring = [&](int i, int j) { return 1 + (i - 1) * slices + (j % slices); };
  glBegin(GL_TRIANGLE_STRIP);
  for (int j = 0; j <= slices; j++) {
    m.emit(ring(1, j));
    m.emit(0);
  }
  glEnd();
  for (int i = 1; i < stacks - 1; i++) {
    glBegin(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= slices; j++) {
      m.emit(ring(i + 1, j));
      m.emit(ring(i, j));
    }
    glEnd();
  }
  glBegin(GL_TRIANGLE_STRIP);
  for (int j = 0; j <= slices; j++) {
    m.emit(south);
    m.emit(ring(stacks - 1, j));
  }
  glEnd();
}

void glutWireSphere(double radius, GLint slices, GLint stacks) {
  if (slices < 1 || stacks < 2) return;
  const Mesh m = sphereMesh(radius, slices, stacks);
  KeepCurrent keep;
  const int south = 1 + (stacks - 1) * slices;
  for (int j = 0; j < slices; j++) {
    glBegin(GL_LINE_STRIP);
    m.emit(0);
    for (int i = 1; i < stacks; i++) m.emit(1 + (i - 1) * slices + j);
    m.emit(south);
    glEnd();
  }
  for (int i = 1; i < stacks; i++) {
    glBegin(GL_LINE_LOOP);
    for (int j = 0; j < slices; j++) m.emit(1 + (i - 1) * slices + j);
    glEnd();
  }
}

// ---------------------------------------------------------------------------------------------
// Cube centred at the origin.

void glutSolidCube(double size) { drawPolyhedron(cube(), false, static_cast<float>(size)); }
void glutWireCube(double size) { drawPolyhedron(cube(), true, static_cast<float>(size)); }

// ---------------------------------------------------------------------------------------------
// Cone along +z with its base in z = 0: the base as a strip around its centre, the side as one
// triangle strip per stack; wire: a line from the base to the apex per slice and a line loop
// per stack.

void glutSolidCone(double base, double height, GLint slices, GLint stacks) {
  if (slices < 1 || stacks < 1) return;
  const Mesh m = coneMesh(base, height, slices, stacks);
  KeepCurrent keep;
  glBegin(GL_TRIANGLE_STRIP);
  for (int j = 0; j <= slices; j++) {
    m.emit(0);
    m.emit(1 + j % slices);
  }
  glEnd();
  auto side = [&](int i, int j) { return 1 + slices + i * slices + j % slices; };
  for (int i = 0; i < stacks; i++) {
    glBegin(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= slices; j++) {
      m.emit(side(i, j));
      m.emit(side(i + 1, j));
    }
    glEnd();
  }
}

void glutWireCone(double base, double height, GLint slices, GLint stacks) {
  if (slices < 1 || stacks < 1) return;
  const Mesh m = coneMesh(base, height, slices, stacks);
  KeepCurrent keep;
  auto side = [&](int i, int j) { return 1 + slices + i * slices + j; };
  glBegin(GL_LINES);
  for (int j = 0; j < slices; j++) {
    m.emit(side(0, j));
    m.emit(side(stacks, j));
  }
  glEnd();
  for (int i = 0; i < stacks; i++) {
    glBegin(GL_LINE_LOOP);
    for (int j = 0; j < slices; j++) m.emit(side(i, j));
    glEnd();
  }
}

// ---------------------------------------------------------------------------------------------
// Cylinder (freeglut extension) along +z from z = 0 to z = height: the base and the top as
// strips around their centres, the side as one triangle strip per stack; wire: a line per
// slice along the side and a line loop per ring (stacks + 1 of them).

void glutSolidCylinder(double radius, double height, GLint slices, GLint stacks) {
  if (slices < 1 || stacks < 1) return;
  const Mesh m = cylinderMesh(radius, height, slices, stacks);
  KeepCurrent keep;
  auto side = [&](int i, int j) { return 1 + slices + i * slices + j % slices; };
  const int topRing = 1 + slices + (stacks + 1) * slices, topCentre = topRing + slices;
  glBegin(GL_TRIANGLE_STRIP);
  for (int j = 0; j <= slices; j++) {
    m.emit(0);
    m.emit(1 + j % slices);
  }
  glEnd();
  for (int i = 0; i < stacks; i++) {
    glBegin(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= slices; j++) {
      m.emit(side(i, j));
      m.emit(side(i + 1, j));
    }
    glEnd();
  }
  glBegin(GL_TRIANGLE_STRIP);
  for (int j = 0; j <= slices; j++) {
    m.emit(topRing + j % slices);
    m.emit(topCentre);
  }
  glEnd();
}

void glutWireCylinder(double radius, double height, GLint slices, GLint stacks) {
  if (slices < 1 || stacks < 1) return;
  const Mesh m = cylinderMesh(radius, height, slices, stacks);
  KeepCurrent keep;
  auto side = [&](int i, int j) { return 1 + slices + i * slices + j; };
  glBegin(GL_LINES);
  for (int j = 0; j < slices; j++) {
    m.emit(side(0, j));
    m.emit(side(stacks, j));
  }
  glEnd();
  for (int i = 0; i <= stacks; i++) {
    glBegin(GL_LINE_LOOP);
    for (int j = 0; j < slices; j++) m.emit(side(i, j));
    glEnd();
  }
}

// ---------------------------------------------------------------------------------------------
// Torus around z: one triangle strip per side band; wire: a line loop per ring, then one per
// side.

void glutSolidTorus(double innerRadius, double outerRadius, GLint sides, GLint rings) {
  if (sides < 2 || rings < 2) return;
  const Mesh m = torusMesh(innerRadius, outerRadius, sides, rings);
  KeepCurrent keep;
  for (int i = 0; i < sides; i++) {
    glBegin(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= rings; j++) {
      const int r = (j % rings) * sides;
      m.emit(r + i);
      m.emit(r + (i + 1) % sides);
    }
    glEnd();
  }
}

void glutWireTorus(double innerRadius, double outerRadius, GLint sides, GLint rings) {
  if (sides < 2 || rings < 2) return;
  const Mesh m = torusMesh(innerRadius, outerRadius, sides, rings);
  KeepCurrent keep;
  for (int j = 0; j < rings; j++) {
    glBegin(GL_LINE_LOOP);
    for (int i = 0; i < sides; i++) m.emit(j * sides + i);
    glEnd();
  }
  for (int i = 0; i < sides; i++) {
    glBegin(GL_LINE_LOOP);
    for (int j = 0; j < rings; j++) m.emit(j * sides + i);
    glEnd();
  }
}

// ---------------------------------------------------------------------------------------------
// The Platonic solids, centred at the origin.

void glutSolidTetrahedron(void) { drawPolyhedron(tetrahedron(), false); }
void glutWireTetrahedron(void) { drawPolyhedron(tetrahedron(), true); }
void glutSolidOctahedron(void) { drawPolyhedron(octahedron(), false); }
void glutWireOctahedron(void) { drawPolyhedron(octahedron(), true); }
void glutSolidDodecahedron(void) { drawPolyhedron(dodecahedron(), false); }
void glutWireDodecahedron(void) { drawPolyhedron(dodecahedron(), true); }
void glutSolidIcosahedron(void) { drawPolyhedron(icosahedron(), false); }
void glutWireIcosahedron(void) { drawPolyhedron(icosahedron(), true); }

// ---------------------------------------------------------------------------------------------
// The teapot: solid as 7 x 7 quads (two triangles each, with texture coordinates) per patch,
// wire as a 10 x 10 grid of line strips per patch.

void glutSolidTeapot(double size) { solidTeapot(size); }
void glutWireTeapot(double size) { wireTeapot(size); }

}  // extern "C"
