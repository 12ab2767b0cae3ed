// Evaluators (GL 2.1 §5.1): one- and two-dimensional Bezier maps of vertices, normals,
// colours and texture coordinates (glMap1/glMap2), evaluated at points (glEvalCoord,
// glEvalPoint) or over grids (glMapGrid + glEvalMesh), with GL_AUTO_NORMAL.
//
// An evaluated vertex goes through the same path as glVertex; the evaluated colour, normal
// and texture coordinates are used for it as if glColor etc. had been called, but the current
// values stay as they were (§5.1: "the current values are not updated").
#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "api.hpp"

namespace tessel::gl {

namespace {

constexpr int kMaxOrder = 8;  // GL_MAX_EVAL_ORDER

// Map targets in the order of their enums (GL_MAP1_COLOR_4 .. GL_MAP1_VERTEX_4).
enum MapIndex { kColor, kIndex, kNormal, kTex1, kTex2, kTex3, kTex4, kVertex3, kVertex4, kMapCount };
constexpr int kComponents[kMapCount] = {4, 1, 3, 1, 2, 3, 4, 3, 4};

struct Map1 {
  bool defined = false;
  double u1 = 0.0, u2 = 1.0;
  int order = 1;
  std::vector<double> points;  // order x components
};
struct Map2 {
  bool defined = false;
  double u1 = 0.0, u2 = 1.0, v1 = 0.0, v2 = 1.0;
  int uorder = 1, vorder = 1;
  std::vector<double> points;  // (vorder x uorder) x components, u fastest
};

struct Evaluators {
  std::array<Map1, kMapCount> map1;
  std::array<Map2, kMapCount> map2;
};

// Per context (a context's maps are its state; the thread_local map keeps them apart).
Evaluators& evaluators(Context& c) {
  static thread_local std::vector<std::pair<const Context*, std::unique_ptr<Evaluators>>> all;
  for (auto& e : all)
    if (e.first == &c) return *e.second;
  all.emplace_back(&c, std::make_unique<Evaluators>());
  return *all.back().second;
}

int map_index(GLenum target, GLenum base) {
  const int i = int(target) - int(base);
  return i >= 0 && i < kMapCount ? i : -1;
}

// Bernstein basis of degree n at t, and its derivative (de Casteljau-free closed form).
void bernstein(int order, double t, double* b, double* db) {
  const int n = order - 1;
  for (int i = 0; i < order; ++i) {
    double binom = 1.0;
    for (int k = 1; k <= i; ++k) binom = binom * double(n - k + 1) / double(k);
    auto pw = [](double x, int e) {
      double r = 1.0;
      for (int k = 0; k < e; ++k) r *= x;
      return r;
    };
    b[i] = binom * pw(t, i) * pw(1.0 - t, n - i);
    if (db) {
      // d/dt t^i (1-t)^(n-i) = i t^(i-1) (1-t)^(n-i) - (n-i) t^i (1-t)^(n-i-1)
      double d = 0.0;
      if (i > 0) d += double(i) * pw(t, i - 1) * pw(1.0 - t, n - i);
      if (n - i > 0) d -= double(n - i) * pw(t, i) * pw(1.0 - t, n - i - 1);
      db[i] = binom * d;
    }
  }
}

void eval1(const Map1& m, int k, double u, double* out) {
  double b[kMaxOrder];
  const double t = (u - m.u1) / (m.u2 - m.u1);
  bernstein(m.order, t, b, nullptr);
  for (int c = 0; c < k; ++c) {
    double s = 0.0;
    for (int i = 0; i < m.order; ++i) s += b[i] * m.points[size_t(i * k + c)];
    out[c] = s;
  }
}

// Value and, when du/dv are given, the partial derivatives (in the map's own parameters).
void eval2(const Map2& m, int k, double u, double v, double* out, double* du, double* dv) {
  double bu[kMaxOrder], bv[kMaxOrder], dbu[kMaxOrder], dbv[kMaxOrder];
  const double s = (u - m.u1) / (m.u2 - m.u1), t = (v - m.v1) / (m.v2 - m.v1);
  bernstein(m.uorder, s, bu, dbu);
  bernstein(m.vorder, t, bv, dbv);
  for (int c = 0; c < k; ++c) {
    double val = 0.0, pu = 0.0, pv = 0.0;
    for (int j = 0; j < m.vorder; ++j)
      for (int i = 0; i < m.uorder; ++i) {
        const double p = m.points[size_t((j * m.uorder + i) * k + c)];
        val += bu[i] * bv[j] * p;
        pu += dbu[i] * bv[j] * p;
        pv += bu[i] * dbv[j] * p;
      }
    out[c] = val;
    if (du) du[c] = pu;
    if (dv) dv[c] = pv;
  }
}

// Emits one evaluated vertex with the evaluated attributes, then restores the current ones.
void emit_evaluated(Context& c, const double* vertex, int vk, const double* color, const double* normal,
                    const double* tex, int tk) {
  if (!c.in_begin || !vertex) return;
  CurrentState& cur = c.s.current;
  const glm::vec4 old_color = cur.color, old_tex = cur.tex[0];
  const glm::vec3 old_normal = cur.normal;
  if (color) cur.color = glm::vec4(float(color[0]), float(color[1]), float(color[2]), float(color[3]));
  if (normal) cur.normal = glm::vec3(float(normal[0]), float(normal[1]), float(normal[2]));
  if (tex) {
    glm::vec4 t(0.0f, 0.0f, 0.0f, 1.0f);
    for (int i = 0; i < tk; ++i) t[i] = float(tex[i]);
    cur.tex[0] = t;  // evaluators give the coordinates of set 0, as Mesa's do
  }
  c.vertex(float(vertex[0]), float(vertex[1]), float(vertex[2]), vk == 4 ? float(vertex[3]) : 1.0f);
  cur.color = old_color;
  cur.normal = old_normal;
  cur.tex[0] = old_tex;
}

// The highest-numbered enabled texture-coordinate map (§5.1: only one is used).
int tex_map(const std::array<bool, 9>& enabled) {
  for (int i = kTex4; i >= kTex1; --i)
    if (enabled[size_t(i)]) return i;
  return -1;
}

}  // namespace

void eval_coord1(Context& c, double u) {
  Evaluators& e = evaluators(c);
  const EvalState& es = c.s.eval;
  auto on = [&](int i) { return es.map1_enabled[size_t(i)] && e.map1[size_t(i)].defined; };
  const int vi = on(kVertex4) ? kVertex4 : on(kVertex3) ? kVertex3 : -1;
  if (vi < 0) return;
  double vtx[4], col[4], nor[3], tex[4];
  eval1(e.map1[size_t(vi)], kComponents[vi], u, vtx);
  const bool has_color = on(kColor), has_normal = on(kNormal);
  if (has_color) eval1(e.map1[kColor], 4, u, col);
  if (has_normal) eval1(e.map1[kNormal], 3, u, nor);
  const int ti = tex_map(es.map1_enabled);
  const bool has_tex = ti >= 0 && e.map1[size_t(ti)].defined;
  if (has_tex) eval1(e.map1[size_t(ti)], kComponents[ti], u, tex);
  emit_evaluated(c, vtx, kComponents[vi], has_color ? col : nullptr, has_normal ? nor : nullptr,
                 has_tex ? tex : nullptr, has_tex ? kComponents[ti] : 0);
}

void eval_coord2(Context& c, double u, double v) {
  Evaluators& e = evaluators(c);
  const EvalState& es = c.s.eval;
  auto on = [&](int i) { return es.map2_enabled[size_t(i)] && e.map2[size_t(i)].defined; };
  const int vi = on(kVertex4) ? kVertex4 : on(kVertex3) ? kVertex3 : -1;
  if (vi < 0) return;
  const int vk = kComponents[vi];
  double vtx[4], du[4], dv[4], col[4], nor[3], tex[4];
  eval2(e.map2[size_t(vi)], vk, u, v, vtx, du, dv);
  const bool has_color = on(kColor);
  if (has_color) eval2(e.map2[kColor], 4, u, v, col, nullptr, nullptr);
  bool has_normal = false;
  if (es.auto_normal) {
    // GL 2.1 §5.1, eq. 5.4: the normal is the cross product of the partial derivatives (of
    // the position divided by w for four-component vertices) ...
    double pu[3], pv[3];
    for (int k = 0; k < 3; ++k) {
      if (vk == 4) {
        const double w = vtx[3];
        pu[k] = (du[k] * w - vtx[k] * du[3]) / (w * w);
        pv[k] = (dv[k] * w - vtx[k] * dv[3]) / (w * w);
      } else {
        pu[k] = du[k];
        pv[k] = dv[k];
      }
    }
    nor[0] = pu[1] * pv[2] - pu[2] * pv[1];
    nor[1] = pu[2] * pv[0] - pu[0] * pv[2];
    nor[2] = pu[0] * pv[1] - pu[1] * pv[0];
    // ... normalized (eq. 5.4: m / ||m||).
    const double len = std::sqrt(nor[0] * nor[0] + nor[1] * nor[1] + nor[2] * nor[2]);
    if (len > 0.0) nor[0] /= len, nor[1] /= len, nor[2] /= len;
    has_normal = true;
  } else if (on(kNormal)) {
    eval2(e.map2[kNormal], 3, u, v, nor, nullptr, nullptr);
    has_normal = true;
  }
  const int ti = tex_map(es.map2_enabled);
  const bool has_tex = ti >= 0 && e.map2[size_t(ti)].defined;
  if (has_tex) eval2(e.map2[size_t(ti)], kComponents[ti], u, v, tex, nullptr, nullptr);
  emit_evaluated(c, vtx, vk, has_color ? col : nullptr, has_normal ? nor : nullptr, has_tex ? tex : nullptr,
                 has_tex ? kComponents[ti] : 0);
}

namespace {

struct MapData {
  std::vector<double> points;
};

void map1(Context& c, GLenum target, double u1, double u2, int order, const std::shared_ptr<MapData>& data) {
  GL_OUTSIDE_BEGIN();
  const int i = map_index(target, GL_MAP1_COLOR_4);
  if (i < 0) return c.error(GL_INVALID_ENUM);
  if (u1 == u2 || order < 1 || order > kMaxOrder) return c.error(GL_INVALID_VALUE);
  Map1& m = evaluators(c).map1[size_t(i)];
  m.defined = true;
  m.u1 = u1;
  m.u2 = u2;
  m.order = order;
  m.points = data ? data->points : std::vector<double>(size_t(order * kComponents[i]), 0.0);
}

void map2(Context& c, GLenum target, double u1, double u2, int uorder, double v1, double v2, int vorder,
          const std::shared_ptr<MapData>& data) {
  GL_OUTSIDE_BEGIN();
  const int i = map_index(target, GL_MAP2_COLOR_4);
  if (i < 0) return c.error(GL_INVALID_ENUM);
  if (u1 == u2 || v1 == v2 || uorder < 1 || uorder > kMaxOrder || vorder < 1 || vorder > kMaxOrder)
    return c.error(GL_INVALID_VALUE);
  Map2& m = evaluators(c).map2[size_t(i)];
  m.defined = true;
  m.u1 = u1, m.u2 = u2, m.v1 = v1, m.v2 = v2;
  m.uorder = uorder;
  m.vorder = vorder;
  m.points = data ? data->points : std::vector<double>(size_t(uorder * vorder * kComponents[i]), 0.0);
}

// Copies control points (with the caller's strides) when the call is made, so a display list
// keeps them.
template <class T>
std::shared_ptr<MapData> copy1(Context& c, GLenum target, GLint stride, GLint order, const T* points) {
  const int i = map_index(target, GL_MAP1_COLOR_4);
  if (i < 0 || order < 1 || order > kMaxOrder || !points) return nullptr;
  const int k = kComponents[i];
  if (stride < k) {
    c.error(GL_INVALID_VALUE);
    return nullptr;
  }
  auto d = std::make_shared<MapData>();
  for (int o = 0; o < order; ++o)
    for (int comp = 0; comp < k; ++comp) d->points.push_back(double(points[o * stride + comp]));
  return d;
}

template <class T>
std::shared_ptr<MapData> copy2(Context& c, GLenum target, GLint ustride, GLint uorder, GLint vstride,
                               GLint vorder, const T* points) {
  const int i = map_index(target, GL_MAP2_COLOR_4);
  if (i < 0 || uorder < 1 || uorder > kMaxOrder || vorder < 1 || vorder > kMaxOrder || !points)
    return nullptr;
  const int k = kComponents[i];
  if (ustride < k || vstride < k) {
    c.error(GL_INVALID_VALUE);
    return nullptr;
  }
  auto d = std::make_shared<MapData>();
  for (int j = 0; j < vorder; ++j)
    for (int o = 0; o < uorder; ++o)
      for (int comp = 0; comp < k; ++comp)
        d->points.push_back(double(points[j * vstride + o * ustride + comp]));
  return d;
}

void map_grid1(Context& c, int n, double u1, double u2) {
  GL_OUTSIDE_BEGIN();
  if (n < 1) return c.error(GL_INVALID_VALUE);
  c.s.eval.grid1 = {n, u1, u2};
}

void map_grid2(Context& c, int nu, double u1, double u2, int nv, double v1, double v2) {
  GL_OUTSIDE_BEGIN();
  if (nu < 1 || nv < 1) return c.error(GL_INVALID_VALUE);
  c.s.eval.grid2u = {nu, u1, u2};
  c.s.eval.grid2v = {nv, v1, v2};
}

double grid_at(const EvalGrid& g, int i) { return g.u1 + (g.u2 - g.u1) * double(i) / double(g.n); }

void eval_mesh1(Context& c, GLenum mode, int i1, int i2) {
  GL_OUTSIDE_BEGIN();
  if (mode != GL_POINT && mode != GL_LINE) return c.error(GL_INVALID_ENUM);
  begin(c, mode == GL_POINT ? GL_POINTS : GL_LINE_STRIP);
  for (int i = i1; i <= i2; ++i) eval_coord1(c, grid_at(c.s.eval.grid1, i));
  c.end();
}

void eval_mesh2(Context& c, GLenum mode, int i1, int i2, int j1, int j2) {
  GL_OUTSIDE_BEGIN();
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) return c.error(GL_INVALID_ENUM);
  const EvalGrid &gu = c.s.eval.grid2u, &gv = c.s.eval.grid2v;
  if (mode == GL_POINT) {
    begin(c, GL_POINTS);
    for (int j = j1; j <= j2; ++j)
      for (int i = i1; i <= i2; ++i) eval_coord2(c, grid_at(gu, i), grid_at(gv, j));
    c.end();
  } else if (mode == GL_LINE) {
    for (int j = j1; j <= j2; ++j) {
      begin(c, GL_LINE_STRIP);
      for (int i = i1; i <= i2; ++i) eval_coord2(c, grid_at(gu, i), grid_at(gv, j));
      c.end();
    }
    for (int i = i1; i <= i2; ++i) {
      begin(c, GL_LINE_STRIP);
      for (int j = j1; j <= j2; ++j) eval_coord2(c, grid_at(gu, i), grid_at(gv, j));
      c.end();
    }
  } else {
    // GL 2.1 §5.1 describes quad strips; Mesa draws triangle strips (the other diagonal of
    // each cell), and Gouraud shading across a cell shows which: Tessel draws what Mesa does.
    for (int j = j1; j < j2; ++j) {
      begin(c, GL_TRIANGLE_STRIP);
      for (int i = i1; i <= i2; ++i) {
        eval_coord2(c, grid_at(gu, i), grid_at(gv, j));
        eval_coord2(c, grid_at(gu, i), grid_at(gv, j + 1));
      }
      c.end();
    }
  }
}

template <class T>
void get_map(GLenum target, GLenum query, T* out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  Evaluators& e = evaluators(c);
  const int i1 = map_index(target, GL_MAP1_COLOR_4), i2 = map_index(target, GL_MAP2_COLOR_4);
  if ((i1 < 0 && i2 < 0) || (query != GL_COEFF && query != GL_ORDER && query != GL_DOMAIN))
    return c.error(GL_INVALID_ENUM);
  if (!out) return;
  if (i1 >= 0) {
    const Map1& m = e.map1[size_t(i1)];
    if (query == GL_ORDER)
      out[0] = T(m.order);
    else if (query == GL_DOMAIN)
      out[0] = T(m.u1), out[1] = T(m.u2);
    else
      for (size_t k = 0; k < m.points.size(); ++k) out[k] = T(m.points[k]);
  } else {
    const Map2& m = e.map2[size_t(i2)];
    if (query == GL_ORDER)
      out[0] = T(m.uorder), out[1] = T(m.vorder);
    else if (query == GL_DOMAIN)
      out[0] = T(m.u1), out[1] = T(m.u2), out[2] = T(m.v1), out[3] = T(m.v2);
    else
      for (size_t k = 0; k < m.points.size(); ++k) out[k] = T(m.points[k]);
  }
}

}  // namespace
}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glMap1d(GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order,
                        const GLdouble* p) {
  GL_COMPAT_CONTEXT();
  const auto d = copy1(c, target, stride, order, p);
  GL_LISTED(map1(c, target, u1, u2, order, d));
  map1(c, target, u1, u2, order, d);
}
void GLAPIENTRY glMap1f(GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order, const GLfloat* p) {
  GL_COMPAT_CONTEXT();
  const auto d = copy1(c, target, stride, order, p);
  GL_LISTED(map1(c, target, u1, u2, order, d));
  map1(c, target, u1, u2, order, d);
}
void GLAPIENTRY glMap2d(GLenum target, GLdouble u1, GLdouble u2, GLint us, GLint uo, GLdouble v1, GLdouble v2,
                        GLint vs, GLint vo, const GLdouble* p) {
  GL_COMPAT_CONTEXT();
  const auto d = copy2(c, target, us, uo, vs, vo, p);
  GL_LISTED(map2(c, target, u1, u2, uo, v1, v2, vo, d));
  map2(c, target, u1, u2, uo, v1, v2, vo, d);
}
void GLAPIENTRY glMap2f(GLenum target, GLfloat u1, GLfloat u2, GLint us, GLint uo, GLfloat v1, GLfloat v2,
                        GLint vs, GLint vo, const GLfloat* p) {
  GL_COMPAT_CONTEXT();
  const auto d = copy2(c, target, us, uo, vs, vo, p);
  GL_LISTED(map2(c, target, u1, u2, uo, v1, v2, vo, d));
  map2(c, target, u1, u2, uo, v1, v2, vo, d);
}
void GLAPIENTRY glGetMapdv(GLenum target, GLenum query, GLdouble* v) {
  GL_REMOVED_IN_CORE();
  get_map(target, query, v);
}
void GLAPIENTRY glGetMapfv(GLenum target, GLenum query, GLfloat* v) {
  GL_REMOVED_IN_CORE();
  get_map(target, query, v);
}
void GLAPIENTRY glGetMapiv(GLenum target, GLenum query, GLint* v) {
  GL_REMOVED_IN_CORE();
  get_map(target, query, v);
}

void GLAPIENTRY glEvalCoord1d(GLdouble u) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(eval_coord1(c, u));
  eval_coord1(c, u);
}
void GLAPIENTRY glEvalCoord1f(GLfloat u) { glEvalCoord1d(u); }
void GLAPIENTRY glEvalCoord1dv(const GLdouble* u) { glEvalCoord1d(u[0]); }
void GLAPIENTRY glEvalCoord1fv(const GLfloat* u) { glEvalCoord1d(u[0]); }
void GLAPIENTRY glEvalCoord2d(GLdouble u, GLdouble v) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(eval_coord2(c, u, v));
  eval_coord2(c, u, v);
}
void GLAPIENTRY glEvalCoord2f(GLfloat u, GLfloat v) { glEvalCoord2d(u, v); }
void GLAPIENTRY glEvalCoord2dv(const GLdouble* u) { glEvalCoord2d(u[0], u[1]); }
void GLAPIENTRY glEvalCoord2fv(const GLfloat* u) { glEvalCoord2d(u[0], u[1]); }

void GLAPIENTRY glMapGrid1d(GLint n, GLdouble u1, GLdouble u2) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(map_grid1(c, n, u1, u2));
  map_grid1(c, n, u1, u2);
}
void GLAPIENTRY glMapGrid1f(GLint n, GLfloat u1, GLfloat u2) { glMapGrid1d(n, u1, u2); }
void GLAPIENTRY glMapGrid2d(GLint nu, GLdouble u1, GLdouble u2, GLint nv, GLdouble v1, GLdouble v2) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(map_grid2(c, nu, u1, u2, nv, v1, v2));
  map_grid2(c, nu, u1, u2, nv, v1, v2);
}
void GLAPIENTRY glMapGrid2f(GLint nu, GLfloat u1, GLfloat u2, GLint nv, GLfloat v1, GLfloat v2) {
  glMapGrid2d(nu, u1, u2, nv, v1, v2);
}
void GLAPIENTRY glEvalMesh1(GLenum mode, GLint i1, GLint i2) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(eval_mesh1(c, mode, i1, i2));
  eval_mesh1(c, mode, i1, i2);
}
void GLAPIENTRY glEvalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(eval_mesh2(c, mode, i1, i2, j1, j2));
  eval_mesh2(c, mode, i1, i2, j1, j2);
}
void GLAPIENTRY glEvalPoint1(GLint i) {
  GL_COMPAT_CONTEXT();
  auto run = [i](Context& c) { eval_coord1(c, grid_at(c.s.eval.grid1, i)); };
  GL_LISTED(run(c));
  run(c);
}
void GLAPIENTRY glEvalPoint2(GLint i, GLint j) {
  GL_COMPAT_CONTEXT();
  auto run = [i, j](Context& c) { eval_coord2(c, grid_at(c.s.eval.grid2u, i), grid_at(c.s.eval.grid2v, j)); };
  GL_LISTED(run(c));
  run(c);
}

}  // extern "C"
