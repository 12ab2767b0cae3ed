// GLU 1.3 NURBS curves and surfaces (chapter 7 of "The OpenGL Graphics System Utility Library,
// Version 1.3"): gluNewNurbsRenderer and its properties, curves, surfaces with any number of
// maps (vertex, normal, colour, texture coordinates), trimming loops made of piecewise linear
// and NURBS trimming curves, the three display modes, the five sampling methods, the renderer
// and the tessellator modes (GLU_EXT_nurbs_tessellator), and the GLU_NURBS_ERROR1..37 errors.
//
// How a surface is drawn (gluEndSurface):
//  1. Each map is a tensor-product B-spline. The breakpoints of all maps (their distinct knots
//     inside the valid range) split the domain into rectangles on which every map is a
//     polynomial; each map's Bezier control points on a rectangle come from its blossom (de
//     Boor's algorithm with the rectangle's bounds as arguments), so knots need not be shared.
//  2. Each rectangle gets a number of steps per direction from the sampling method: the
//     maximum edge length in pixels (GLU_PATH_LENGTH) or object units (GLU_OBJECT_PATH_LENGTH)
//     from the Bezier net's largest first difference, the chord error (GLU_PARAMETRIC_ERROR,
//     GLU_OBJECT_PARAMETRIC_ERROR) from its largest second difference, or GLU_U_STEP and
//     GLU_V_STEP samples per unit of parameter (GLU_DOMAIN_DISTANCE, rounded down as the
//     reference GLU does). Rectangles in a column share the largest u count and those in a row
//     the largest v count, so neighbours meet at the same points.
//  3. Untrimmed, each rectangle is a grid: in the renderer mode a glMap2f per map and
//     glMapGrid2d + glEvalMesh2, as the reference GLU draws the inside of a patch (v runs from
//     the top, so the quads face the same way as there).
//  4. Trimmed, the trimming loops (closed polylines in the domain after the trimming curves
//     are sampled at the grid's density) keep the region of positive winding number (outer
//     loops counter-clockwise, holes clockwise, as section 7.4 says). Grid cells that no loop
//     crosses are wholly in or out (the winding number at their centre decides); the cells a
//     loop crosses are clipped against the loops (Sutherland-Hodgman per loop keeps the
//     winding number of every point in the cell) and triangulated by GLU's own tessellator.
//     Every vertex is then evaluated at its (u, v): glEvalCoord2d in the renderer mode, this
//     file's own Bezier evaluation in the tessellator mode (normals from GL_MAP2_NORMAL or else
//     from the partial derivatives, as GL_AUTO_NORMAL would).
// GLU_OUTLINE_POLYGON draws the same primitives with glPolygonMode(GL_LINE) (lines in the
// tessellator mode); GLU_OUTLINE_PATCH draws the domain's boundary or the trimming loops,
// mapped onto the surface. Curves are drawn the same way with glMap1f + glEvalMesh1.
//
// GL state: the renderer mode pushes GL_EVAL_BIT and GL_POLYGON_BIT around a curve or surface,
// so the maps' enables, the grid, GL_AUTO_NORMAL and the polygon mode are as before; the map
// control points themselves are not part of any attribute group and keep the last patch's.
// The sampling matrices are GL's current ones at gluEndCurve/gluEndSurface unless
// GLU_AUTO_LOAD_MATRIX is off (then gluLoadSamplingMatrices's).

#include <GL/gl.h>
#include <GL/glu.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <new>
#include <vector>

namespace {

using ErrorFn = void(GLAPIENTRY*)(GLenum);
using BeginFn = void(GLAPIENTRY*)(GLenum);
using BeginDataFn = void(GLAPIENTRY*)(GLenum, void*);
using ValueFn = void(GLAPIENTRY*)(GLfloat*);
using ValueDataFn = void(GLAPIENTRY*)(GLfloat*, void*);
using EndFn = void(GLAPIENTRY*)(void);
using EndDataFn = void(GLAPIENTRY*)(void*);

// At most this many steps per Bezier span and direction, and this many grid cells a surface
// (counts are scaled down to fit): bad or huge input must not make the tessellation unbounded.
constexpr int kMaxSpanSteps = 256;
constexpr double kMaxCells = 1 << 20;

// One gluNurbsCurve or gluNurbsSurface call, copied.
struct Map {
  GLenum type = 0;
  int dim = 0;
  int order[2] = {1, 1};
  int count[2] = {1, 1};         // control points per direction
  std::vector<double> knots[2];  // count + order each
  std::vector<double> ctl;       // count[0] * count[1] * dim, direction 0 (s) fastest
  double lo(int d) const { return knots[d][size_t(order[d] - 1)]; }
  double hi(int d) const { return knots[d][size_t(count[d])]; }
};

struct TrimPiece {
  bool pwl = true;
  std::vector<double> points;  // pwl: (u, v) pairs
  Map curve;                   // otherwise: a NURBS trimming curve (dim 2 or 3)
};
using TrimLoop = std::vector<TrimPiece>;

enum class Scope { None, Curve, Surface, Trim };

// Components of a map type, or 0 when `type` is not one of the kind (1 or 2 dimensions).
int components(GLenum type, int dims) {
  if (dims == 1) {
    switch (type) {
      case GL_MAP1_VERTEX_3:
      case GL_MAP1_NORMAL:
      case GL_MAP1_TEXTURE_COORD_3: return 3;
      case GL_MAP1_VERTEX_4:
      case GL_MAP1_COLOR_4:
      case GL_MAP1_TEXTURE_COORD_4: return 4;
      case GL_MAP1_INDEX:
      case GL_MAP1_TEXTURE_COORD_1: return 1;
      case GL_MAP1_TEXTURE_COORD_2: return 2;
      case GLU_MAP1_TRIM_2: return 2;
      case GLU_MAP1_TRIM_3: return 3;
      default: return 0;
    }
  }
  switch (type) {
    case GL_MAP2_VERTEX_3:
    case GL_MAP2_NORMAL:
    case GL_MAP2_TEXTURE_COORD_3: return 3;
    case GL_MAP2_VERTEX_4:
    case GL_MAP2_COLOR_4:
    case GL_MAP2_TEXTURE_COORD_4: return 4;
    case GL_MAP2_INDEX:
    case GL_MAP2_TEXTURE_COORD_1: return 1;
    case GL_MAP2_TEXTURE_COORD_2: return 2;
    default: return 0;
  }
}
bool is_vertex(GLenum t) {
  return t == GL_MAP1_VERTEX_3 || t == GL_MAP1_VERTEX_4 || t == GL_MAP2_VERTEX_3 || t == GL_MAP2_VERTEX_4;
}
bool is_trim(GLenum t) { return t == GLU_MAP1_TRIM_2 || t == GLU_MAP1_TRIM_3; }

// Bezier control points (order of them, dim components each) of the B-spline with `knots`
// and `pts` (point i at pts + i * step, dim components) over [a, b], which lies in the span
// knots[span] .. knots[span + 1]: the blossom at (a^(order-1-j), b^j) for j = 0 .. order-1.
void bezier(const std::vector<double>& knots, int order, int span, const double* pts, size_t step, int dim,
            double a, double b, double* out) {
  double d[32 * 4];
  for (int j = 0; j < order; ++j) {
    for (int k = 0; k < order; ++k)
      for (int c = 0; c < dim; ++c) d[k * dim + c] = pts[size_t(span - order + 1 + k) * step + size_t(c)];
    for (int r = 1; r < order; ++r) {
      const double x = r <= order - 1 - j ? a : b;
      for (int k = order - 1; k >= r; --k) {
        const int i = span - order + 1 + k;
        const double den = knots[size_t(i + order - r)] - knots[size_t(i)];
        const double al = den > 0 ? (x - knots[size_t(i)]) / den : 0.0;
        for (int c = 0; c < dim; ++c) d[k * dim + c] = (1 - al) * d[(k - 1) * dim + c] + al * d[k * dim + c];
      }
    }
    for (int c = 0; c < dim; ++c) out[j * dim + c] = d[(order - 1) * dim + c];
  }
}

// The span of `m` in direction d that holds [a, b] (a inside it, b at most its end).
int span_of(const Map& m, int d, double a) {
  int s = m.order[d] - 1;
  while (s + 1 < m.count[d] && m.knots[d][size_t(s + 1)] <= a) ++s;
  return s;
}

// Bezier form of a map on [a0, a1] x [b0, b1]: order[0] x order[1] points, s fastest.
struct Patch {
  const Map* map = nullptr;
  double a0 = 0, a1 = 1, b0 = 0, b1 = 1;
  std::vector<double> pts;
};
Patch make_patch(const Map& m, double a0, double a1, double b0, double b1) {
  Patch p;
  p.map = &m;
  p.a0 = a0, p.a1 = a1, p.b0 = b0, p.b1 = b1;
  const int so = m.order[0], to = m.order[1], dim = m.dim;
  const int ss = span_of(m, 0, a0);
  p.pts.assign(size_t(so * to * dim), 0.0);
  if (to == 1 && m.count[1] == 1) {  // a curve
    bezier(m.knots[0], so, ss, m.ctl.data(), size_t(dim), dim, a0, a1, p.pts.data());
    return p;
  }
  const int ts = span_of(m, 1, b0);
  std::vector<double> rows(size_t(to * so * dim));
  for (int k = 0; k < to; ++k) {
    const double* row = m.ctl.data() + size_t(ts - to + 1 + k) * size_t(m.count[0]) * size_t(dim);
    bezier(m.knots[0], so, ss, row, size_t(dim), dim, a0, a1, rows.data() + size_t(k * so * dim));
  }
  std::vector<double> col(size_t(to * dim));
  std::vector<double> full(size_t(m.count[1]) * size_t(dim));
  for (int j = 0; j < so; ++j) {
    // The column j of the rows, placed where the t-span's points sit.
    for (int k = 0; k < to; ++k)
      for (int c = 0; c < dim; ++c)
        full[size_t(ts - to + 1 + k) * size_t(dim) + size_t(c)] = rows[size_t((k * so + j) * dim + c)];
    bezier(m.knots[1], to, ts, full.data(), size_t(dim), dim, b0, b1, col.data());
    for (int k = 0; k < to; ++k)
      for (int c = 0; c < dim; ++c) p.pts[size_t((k * so + j) * dim + c)] = col[size_t(k * dim + c)];
  }
  return p;
}

// Bernstein polynomials of degree n = order - 1 at t in [0, 1], and their derivatives (per unit t).
void bernstein(int order, double t, double* b, double* db) {
  auto basis = [t](int deg, double* out) {
    for (int i = 0; i <= deg; ++i) {
      double c = 1;
      for (int k = 1; k <= i; ++k) c = c * double(deg - i + k) / double(k);
      out[i] = c * std::pow(t, i) * std::pow(1 - t, deg - i);
    }
  };
  const int n = order - 1;
  basis(n, b);
  if (n == 0) {
    db[0] = 0;
    return;
  }
  double lower[32];
  basis(n - 1, lower);
  for (int i = 0; i <= n; ++i) db[i] = n * ((i > 0 ? lower[i - 1] : 0.0) - (i < n ? lower[i] : 0.0));
}

// A patch's value at (u, v) in its own domain, and its partial derivatives (dim components).
void evaluate(const Patch& p, double u, double v, double* f, double* fu, double* fv) {
  const Map& m = *p.map;
  const int so = m.order[0], to = m.order[1], dim = m.dim;
  double bu[32], dbu[32], bv[32], dbv[32];
  const double su = p.a1 > p.a0 ? (u - p.a0) / (p.a1 - p.a0) : 0.0;
  const double sv = p.b1 > p.b0 ? (v - p.b0) / (p.b1 - p.b0) : 0.0;
  bernstein(so, su, bu, dbu);
  bernstein(to, sv, bv, dbv);
  for (int c = 0; c < dim; ++c) f[c] = fu[c] = fv[c] = 0.0;
  for (int k = 0; k < to; ++k)
    for (int j = 0; j < so; ++j) {
      const double* q = &p.pts[size_t((k * so + j) * dim)];
      for (int c = 0; c < dim; ++c) {
        f[c] += bu[j] * bv[k] * q[c];
        fu[c] += dbu[j] * bv[k] * q[c];
        fv[c] += bu[j] * dbv[k] * q[c];
      }
    }
  const double ku = p.a1 > p.a0 ? 1.0 / (p.a1 - p.a0) : 0.0, kv = p.b1 > p.b0 ? 1.0 / (p.b1 - p.b0) : 0.0;
  for (int c = 0; c < dim; ++c) fu[c] *= ku, fv[c] *= kv;
}

}  // namespace

struct GLUnurbs {
  // Properties (section 7.5; the defaults of the specification).
  bool auto_load = true;
  bool culling = false;
  float sampling_tolerance = 50.0f;
  float parametric_tolerance = 0.5f;
  GLenum display_mode = GLU_FILL;
  GLenum sampling_method = GLU_PATH_LENGTH;
  float u_step = 100.0f, v_step = 100.0f;
  GLenum mode = GLU_NURBS_RENDERER;
  double model[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  double proj[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  double view[4] = {0, 0, 1, 1};
  // Callbacks.
  ErrorFn error = nullptr;
  BeginFn begin = nullptr;
  BeginDataFn begin_data = nullptr;
  ValueFn vertex = nullptr, normal = nullptr, color = nullptr, texcoord = nullptr;
  ValueDataFn vertex_data = nullptr, normal_data = nullptr, color_data = nullptr, texcoord_data = nullptr;
  EndFn end = nullptr;
  EndDataFn end_data = nullptr;
  void* user_data = nullptr;
  // What is being described.
  Scope scope = Scope::None;
  bool failed = false;  // an error since the begin: nothing is drawn
  std::vector<Map> maps;
  std::vector<TrimLoop> loops;
};

namespace {

void report(GLUnurbs* n, int which) {
  n->failed = true;
  if (n->error) n->error(GLenum(GLU_NURBS_ERROR1 + which - 1));
}

// Copies and checks a curve's or surface's data (dims 1 or 2); false after reporting an error.
bool read_map(GLUnurbs* n, int dims, const GLint* kcount, GLfloat* const* knots, const GLint* stride,
              const GLfloat* control, const GLint* order, GLenum type, Map& m) {
  m.type = type;
  m.dim = components(type, dims);
  if (m.dim == 0) return report(n, 35), false;  // unknown type descriptor
  if (!control) return report(n, 36), false;
  GLint max_order = 8;
  glGetIntegerv(GL_MAX_EVAL_ORDER, &max_order);
  max_order = std::clamp(max_order, 2, 32);
  for (int d = 0; d < dims; ++d) {
    if (!knots[d]) return report(n, 36), false;
    if (order[d] < 2 || order[d] > max_order) return report(n, 1), false;
    if (kcount[d] < 0) return report(n, 33), false;
    if (kcount[d] < 2 * order[d]) return report(n, 2), false;
    if (stride[d] < 0) return report(n, 34), false;
    m.order[d] = order[d];
    m.count[d] = kcount[d] - order[d];
    m.knots[d].assign(knots[d], knots[d] + kcount[d]);
    int mult = 1;
    for (int i = 0; i < kcount[d]; ++i) {
      if (!std::isfinite(m.knots[d][size_t(i)])) return report(n, 4), false;
      if (i == 0) continue;
      if (m.knots[d][size_t(i)] < m.knots[d][size_t(i - 1)]) return report(n, 4), false;
      mult = m.knots[d][size_t(i)] == m.knots[d][size_t(i - 1)] ? mult + 1 : 1;
      if (mult > order[d]) return report(n, 5), false;
    }
    if (!(m.lo(d) < m.hi(d))) return report(n, 3), false;
  }
  const int c0 = m.count[0], c1 = dims == 2 ? m.count[1] : 1;
  m.ctl.resize(size_t(c0) * size_t(c1) * size_t(m.dim));
  for (int j = 0; j < c1; ++j)
    for (int i = 0; i < c0; ++i) {
      const GLfloat* p =
          control + size_t(i) * size_t(stride[0]) + (dims == 2 ? size_t(j) * size_t(stride[1]) : 0);
      for (int c = 0; c < m.dim; ++c)
        m.ctl[(size_t(j) * size_t(c0) + size_t(i)) * size_t(m.dim) + size_t(c)] = p[c];
    }
  return true;
}

// ---- Sampling -----------------------------------------------------------------------------

struct Sampler {
  const GLUnurbs* n;
  double mvp[16];  // proj * model, column-major
  // Homogeneous point of a vertex map's control point.
  static std::array<double, 4> homogeneous(const double* q, int dim) {
    return {q[0], q[1], q[2], dim == 4 ? q[3] : 1.0};
  }
  explicit Sampler(const GLUnurbs* nb) : n(nb) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) {
        double s = 0;
        for (int k = 0; k < 4; ++k) s += n->proj[k * 4 + r] * n->model[c * 4 + k];
        mvp[c * 4 + r] = s;
      }
  }
  std::array<double, 4> clip(const std::array<double, 4>& p) const {
    std::array<double, 4> r{};
    for (int i = 0; i < 4; ++i)
      r[size_t(i)] = mvp[i] * p[0] + mvp[4 + i] * p[1] + mvp[8 + i] * p[2] + mvp[12 + i] * p[3];
    return r;
  }
  // The point as the sampling method measures it (pixels or object units); false when it
  // cannot be projected (on or behind the eye).
  bool measure(const double* q, int dim, double out[3]) const {
    const auto h = homogeneous(q, dim);
    if (n->sampling_method == GLU_OBJECT_PATH_LENGTH || n->sampling_method == GLU_OBJECT_PARAMETRIC_ERROR) {
      if (!(std::fabs(h[3]) > 0)) return false;
      for (int c = 0; c < 3; ++c) out[c] = h[size_t(c)] / h[3];
      return true;
    }
    const auto c = clip(h);
    if (!(c[3] > 1e-12)) return false;
    out[0] = (c[0] / c[3] * 0.5 + 0.5) * n->view[2];
    out[1] = (c[1] / c[3] * 0.5 + 0.5) * n->view[3];
    out[2] = 0;
    return true;
  }
  static int clamp_steps(double x) {
    if (std::isnan(x)) return 1;
    if (!(x < kMaxSpanSteps)) return kMaxSpanSteps;
    return std::max(1, int(std::ceil(x)));
  }
  // Steps along direction d (0: s, 1: t) of a vertex patch over an interval of length len.
  // (GLU_DOMAIN_DISTANCE: the samples per unit times the length, rounded down, as the reference
  // GLU counts them: at least one step on a surface, one more and at least two on a curve.)
  int steps(const Patch& p, int d, double len, bool curve = false) const {
    const Map& m = *p.map;
    if (n->sampling_method == GLU_DOMAIN_DISTANCE) {
      const double x = double(d == 0 ? n->u_step : n->v_step) * len;
      const int k = std::isnan(x) ? 0 : int(std::min(x, double(kMaxSpanSteps)));
      return curve ? std::clamp(k + 1, 2, kMaxSpanSteps) : std::clamp(k, 1, kMaxSpanSteps);
    }
    const int so = m.order[0], to = m.order[1];
    const int od = m.order[d];
    if (od < 2) return 1;
    // Measured control points.
    std::vector<std::array<double, 3>> w(size_t(so * to));
    for (int i = 0; i < so * to; ++i)
      if (!measure(&p.pts[size_t(i * m.dim)], m.dim, w[size_t(i)].data())) return kMaxSpanSteps;
    const bool second =
        n->sampling_method == GLU_PARAMETRIC_ERROR || n->sampling_method == GLU_OBJECT_PARAMETRIC_ERROR;
    const int lines = d == 0 ? to : so;
    double big = 0;
    for (int l = 0; l < lines; ++l) {
      auto at = [&](int i) -> const std::array<double, 3>& {
        return d == 0 ? w[size_t(l * so + i)] : w[size_t(i * so + l)];
      };
      for (int i = 0; i + (second ? 2 : 1) < od; ++i) {
        double s = 0;
        for (int c = 0; c < 3; ++c) {
          const double v = second ? at(i + 2)[size_t(c)] - 2 * at(i + 1)[size_t(c)] + at(i)[size_t(c)]
                                  : at(i + 1)[size_t(c)] - at(i)[size_t(c)];
          s += v * v;
        }
        big = std::max(big, std::sqrt(s));
      }
    }
    if (second) {
      // Chord error of n steps <= |f''| / (8 n^2), |f''| <= (o-1)(o-2) max second difference.
      const double tol = n->parametric_tolerance;
      return clamp_steps(std::sqrt(double(od - 1) * double(od - 2) * big / (8.0 * tol)));
    }
    // Edge length of n steps <= |f'| / n, |f'| <= (o-1) max first difference; the reference
    // GLU is conservative by a factor of about two, and so is this.
    return clamp_steps(2.0 * double(od - 1) * big / double(n->sampling_tolerance));
  }
  // Whether the patch (its control hull) is wholly outside one clip plane.
  bool culled(const Patch& p) const {
    const Map& m = *p.map;
    const int cnt = m.order[0] * m.order[1];
    for (int plane = 0; plane < 6; ++plane) {
      bool all = true;
      for (int i = 0; i < cnt && all; ++i) {
        const auto c = clip(homogeneous(&p.pts[size_t(i * m.dim)], m.dim));
        const double v = c[size_t(plane / 2)];
        all = plane % 2 == 0 ? v < -c[3] : v > c[3];
      }
      if (all) return true;
    }
    return false;
  }
};

void load_matrices(GLUnurbs* n) {
  if (!n->auto_load) return;
  // (Without a current context the GL queries leave these as they are.)
  GLfloat m[16], p[16];
  GLint v[4];
  for (int i = 0; i < 16; ++i) m[i] = GLfloat(n->model[i]), p[i] = GLfloat(n->proj[i]);
  for (int i = 0; i < 4; ++i) v[i] = GLint(n->view[i]);
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  glGetFloatv(GL_PROJECTION_MATRIX, p);
  glGetIntegerv(GL_VIEWPORT, v);
  for (int i = 0; i < 16; ++i) n->model[i] = m[i], n->proj[i] = p[i];
  for (int i = 0; i < 4; ++i) n->view[i] = v[i];
}

// Breakpoints of the maps in direction d inside [lo, hi].
std::vector<double> breakpoints(const std::vector<const Map*>& maps, int d, double lo, double hi) {
  std::vector<double> b = {lo, hi};
  for (const Map* m : maps)
    for (double k : m->knots[d])
      if (k > lo && k < hi) b.push_back(k);
  std::sort(b.begin(), b.end());
  b.erase(std::unique(b.begin(), b.end()), b.end());
  return b;
}

// ---- Output: GL calls (renderer) or callbacks (tessellator) -------------------------------

class Output {
 public:
  Output(GLUnurbs* n, bool surface) : n_(n), surface_(surface) {}
  bool renderer() const { return n_->mode != GLU_NURBS_TESSELLATOR; }
  // The patches (one per map) of the current rectangle or segment.
  void use(std::vector<Patch>* patches) {
    patches_ = patches;
    if (!renderer()) return;
    for (const Patch& p : *patches) {
      const Map& m = *p.map;
      std::vector<GLfloat> f(p.pts.begin(), p.pts.end());
      if (surface_) {
        glMap2f(m.type, GLfloat(p.a0), GLfloat(p.a1), m.dim, m.order[0], GLfloat(p.b0), GLfloat(p.b1),
                m.dim * m.order[0], m.order[1], f.data());
      } else {
        glMap1f(m.type, GLfloat(p.a0), GLfloat(p.a1), m.dim, m.order[0], f.data());
      }
    }
  }
  void begin(GLenum prim) {
    prim_ = prim;
    if (renderer()) return glBegin(prim);
    loop_.clear();
    if (!outline_tess()) call_begin(prim);
  }
  void vertex(double u, double v) {
    if (renderer()) return surface_ ? glEvalCoord2d(u, v) : glEvalCoord1d(u);
    if (outline_tess()) {
      loop_.push_back({u, v});
      return;
    }
    emit(u, v);
  }
  void end() {
    if (renderer()) return glEnd();
    if (!outline_tess()) return call_end();
    // GLU_OUTLINE_POLYGON in the tessellator mode: each polygon's outline as a line loop.
    auto loop = [&](std::initializer_list<size_t> idx) {
      call_begin(GL_LINE_LOOP);
      for (size_t i : idx) emit(loop_[i][0], loop_[i][1]);
      call_end();
    };
    if (prim_ == GL_TRIANGLES)
      for (size_t i = 0; i + 2 < loop_.size(); i += 3) loop({i, i + 1, i + 2});
    else if (prim_ == GL_QUAD_STRIP)
      for (size_t i = 0; i + 3 < loop_.size(); i += 2) loop({i, i + 1, i + 3, i + 2});
  }

 private:
  bool outline_tess() const {
    return surface_ && n_->display_mode == GLU_OUTLINE_POLYGON &&
           (prim_ == GL_TRIANGLES || prim_ == GL_QUAD_STRIP);
  }
  void call_begin(GLenum prim) {
    if (n_->begin_data)
      n_->begin_data(prim, n_->user_data);
    else if (n_->begin)
      n_->begin(prim);
  }
  void call_end() {
    if (n_->end_data)
      n_->end_data(n_->user_data);
    else if (n_->end)
      n_->end();
  }
  void value(ValueFn f, ValueDataFn fd, GLfloat* v) {
    if (fd)
      fd(v, n_->user_data);
    else if (f)
      f(v);
  }
  // The tessellator mode's vertex: every map evaluated at (u, v), through the callbacks.
  void emit(double u, double v) {
    const Patch* vert = nullptr;
    const Patch* norm = nullptr;
    for (const Patch& p : *patches_) {
      if (is_vertex(p.map->type)) vert = &p;
      if (p.map->type == GL_MAP2_NORMAL || p.map->type == GL_MAP1_NORMAL) norm = &p;
    }
    double f[4], fu[4], fv[4];
    GLfloat out[4];
    for (const Patch& p : *patches_) {
      const GLenum t = p.map->type;
      if (is_vertex(t) || t == GL_MAP2_INDEX || t == GL_MAP1_INDEX) continue;
      evaluate(p, u, v, f, fu, fv);
      for (int c = 0; c < p.map->dim; ++c) out[c] = GLfloat(f[c]);
      if (t == GL_MAP2_NORMAL || t == GL_MAP1_NORMAL)
        value(n_->normal, n_->normal_data, out);
      else if (t == GL_MAP2_COLOR_4 || t == GL_MAP1_COLOR_4)
        value(n_->color, n_->color_data, out);
      else
        value(n_->texcoord, n_->texcoord_data, out);
    }
    if (!vert) return;
    evaluate(*vert, u, v, f, fu, fv);
    const double w = vert->map->dim == 4 ? f[3] : 1.0;
    if (surface_ && !norm && (n_->normal || n_->normal_data)) {
      // The normal of the projected point (x/w): partials by the quotient rule.
      double pu[3], pv[3];
      for (int c = 0; c < 3; ++c) {
        const double wu = vert->map->dim == 4 ? fu[3] : 0.0, wv = vert->map->dim == 4 ? fv[3] : 0.0;
        pu[c] = (fu[c] * w - f[c] * wu) / (w * w);
        pv[c] = (fv[c] * w - f[c] * wv) / (w * w);
      }
      double nx = pu[1] * pv[2] - pu[2] * pv[1], ny = pu[2] * pv[0] - pu[0] * pv[2],
             nz = pu[0] * pv[1] - pu[1] * pv[0];
      const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
      if (len > 0) nx /= len, ny /= len, nz /= len;
      GLfloat nn[3] = {GLfloat(nx), GLfloat(ny), GLfloat(nz)};
      value(n_->normal, n_->normal_data, nn);
    }
    GLfloat p[3] = {GLfloat(f[0] / w), GLfloat(f[1] / w), GLfloat(f[2] / w)};
    value(n_->vertex, n_->vertex_data, p);
  }

  GLUnurbs* n_;
  bool surface_;
  std::vector<Patch>* patches_ = nullptr;
  GLenum prim_ = GL_TRIANGLES;
  std::vector<std::array<double, 2>> loop_;
};

// Pushes the GL state a renderer-mode curve or surface changes, and restores it.
struct GlState {
  bool on;
  GLenum first, last;
  GlState(const GLUnurbs* n, bool surface, const std::vector<const Map*>& maps)
      : on(n->mode != GLU_NURBS_TESSELLATOR) {
    if (!on) return;
    glPushAttrib(GL_EVAL_BIT | GL_POLYGON_BIT);
    first = surface ? GL_MAP2_COLOR_4 : GL_MAP1_COLOR_4;
    last = surface ? GL_MAP2_VERTEX_4 : GL_MAP1_VERTEX_4;
    for (GLenum t = first; t <= last; ++t) glDisable(t);
    for (const Map* m : maps) glEnable(m->type);
    if (surface) glPolygonMode(GL_FRONT_AND_BACK, n->display_mode == GLU_OUTLINE_POLYGON ? GL_LINE : GL_FILL);
  }
  ~GlState() {
    if (on) glPopAttrib();
  }
};

// The maps of the curve or surface being drawn, and its vertex map: null (NURBS error 8
// reported) unless there is exactly one.
const Map* gather_maps(GLUnurbs* n, std::vector<const Map*>& maps) {
  const Map* vert = nullptr;
  for (const Map& m : n->maps) {
    maps.push_back(&m);
    if (is_vertex(m.type)) {
      if (vert) return report(n, 8), nullptr;
      vert = &m;
    }
  }
  if (!vert) report(n, 8);
  return vert;
}
// The domain all maps share in direction d; false (NURBS error 3 reported) when it is empty.
bool shared_domain(GLUnurbs* n, const std::vector<const Map*>& maps, int d, double& lo, double& hi) {
  lo = -HUGE_VAL, hi = HUGE_VAL;
  for (const Map* m : maps) lo = std::max(lo, m->lo(d)), hi = std::min(hi, m->hi(d));
  if (lo < hi) return true;
  report(n, 3);
  return false;
}

// ---- Curves -------------------------------------------------------------------------------

void draw_curve(GLUnurbs* n) {
  std::vector<const Map*> maps;
  const Map* vert = gather_maps(n, maps);
  double lo, hi;
  if (!vert || !shared_domain(n, maps, 0, lo, hi)) return;
  load_matrices(n);
  const Sampler sampler(n);
  const std::vector<double> br = breakpoints(maps, 0, lo, hi);
  GlState state(n, false, maps);
  Output out(n, false);
  for (size_t i = 0; i + 1 < br.size(); ++i) {
    std::vector<Patch> patches;
    for (const Map* m : maps) patches.push_back(make_patch(*m, br[i], br[i + 1], 0, 1));
    const Patch* vp = nullptr;
    for (const Patch& p : patches)
      if (p.map == vert) vp = &p;
    if (n->culling && sampler.culled(*vp)) continue;
    const int steps = sampler.steps(*vp, 0, br[i + 1] - br[i], true);
    out.use(&patches);
    if (out.renderer()) {
      glMapGrid1d(steps, br[i], br[i + 1]);
      glEvalMesh1(GL_LINE, 0, steps);
      continue;
    }
    out.begin(GL_LINE_STRIP);
    for (int k = 0; k <= steps; ++k) out.vertex(br[i] + (br[i + 1] - br[i]) * k / steps, 0);
    out.end();
  }
}

// ---- Trimming -----------------------------------------------------------------------------

using Polyline = std::vector<std::array<double, 2>>;

// A NURBS trimming curve sampled in the domain: each Bezier segment in enough steps that no
// step is longer than `step` (the grid's finest cell).
void sample_trim_curve(const Map& m, double step, Polyline& out) {
  std::vector<const Map*> one = {&m};
  const std::vector<double> br = breakpoints(one, 0, m.lo(0), m.hi(0));
  for (size_t i = 0; i + 1 < br.size(); ++i) {
    const Patch p = make_patch(m, br[i], br[i + 1], 0, 1);
    double len = 0;
    for (int k = 0; k + 1 < m.order[0]; ++k) {
      const double* a = &p.pts[size_t(k * m.dim)];
      const double* b = a + m.dim;
      const double wa = m.dim == 3 ? a[2] : 1.0, wb = m.dim == 3 ? b[2] : 1.0;
      len += std::hypot(b[0] / wb - a[0] / wa, b[1] / wb - a[1] / wa);
    }
    int steps = std::isfinite(len) && step > 0 ? int(std::ceil(std::min(len / step, 4096.0))) : 1;
    steps = std::max(steps, 2 * (m.order[0] - 1));
    for (int k = (out.empty() ? 0 : 1); k <= steps; ++k) {
      double f[4], fu[4], fv[4];
      evaluate(p, br[i] + (br[i + 1] - br[i]) * k / steps, 0, f, fu, fv);
      const double w = m.dim == 3 ? f[2] : 1.0;
      out.push_back({f[0] / w, f[1] / w});
    }
  }
}

// Winding number of the closed polylines around (x, y).
int winding(const std::vector<Polyline>& loops, double x, double y) {
  int w = 0;
  for (const Polyline& l : loops)
    for (size_t i = 0; i < l.size(); ++i) {
      const auto& a = l[i];
      const auto& b = l[(i + 1) % l.size()];
      const double cross = (b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1]);
      if (a[1] <= y) {
        if (b[1] > y && cross > 0) ++w;
      } else if (b[1] <= y && cross < 0) {
        --w;
      }
    }
  return w;
}

// Sutherland-Hodgman: the loop clipped to the rectangle, corners snapped onto its sides.
Polyline clip_loop(const Polyline& in, double x0, double x1, double y0, double y1) {
  Polyline a = in, b;
  for (int side = 0; side < 4 && !a.empty(); ++side) {
    const int c = side / 2;  // 0: x, 1: y
    const double lim = side == 0 ? x0 : side == 1 ? x1 : side == 2 ? y0 : y1;
    const bool keep_above = side % 2 == 0;
    auto inside = [&](const std::array<double, 2>& p) {
      return keep_above ? p[size_t(c)] >= lim : p[size_t(c)] <= lim;
    };
    b.clear();
    for (size_t i = 0; i < a.size(); ++i) {
      const auto& p = a[i];
      const auto& q = a[(i + 1) % a.size()];
      const bool pi = inside(p), qi = inside(q);
      if (pi) b.push_back(p);
      if (pi != qi) {
        const double t = (lim - p[size_t(c)]) / (q[size_t(c)] - p[size_t(c)]);
        std::array<double, 2> r = {p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t};
        r[size_t(c)] = lim;
        b.push_back(r);
      }
    }
    std::swap(a, b);
  }
  for (auto& p : a) {
    p[0] = std::clamp(p[0], x0, x1);
    p[1] = std::clamp(p[1], y0, y1);
  }
  return a;
}

// Triangles of the part of the rectangle inside the loops (positive winding), from GLU's
// tessellator; counter-clockwise in (u, v).
struct CellTess {
  GLUtesselator* tess = gluNewTess();
  std::deque<std::array<double, 3>> store;  // vertices handed to the tessellator
  std::vector<const double*> tri;
  static void GLAPIENTRY vertex_cb(void* v, void* self) {
    static_cast<CellTess*>(self)->tri.push_back(static_cast<const double*>(v));
  }
  static void GLAPIENTRY edge_cb(GLboolean, void*) {}
  static void GLAPIENTRY combine_cb(GLdouble c[3], void* [4], GLfloat[4], void** out, void* self) {
    auto* t = static_cast<CellTess*>(self);
    t->store.push_back({c[0], c[1], 0.0});
    *out = t->store.back().data();
  }
  CellTess() {
    if (!tess) return;
    gluTessCallback(tess, GLU_TESS_VERTEX_DATA, reinterpret_cast<_GLUfuncptr>(&vertex_cb));
    gluTessCallback(tess, GLU_TESS_EDGE_FLAG_DATA, reinterpret_cast<_GLUfuncptr>(&edge_cb));
    gluTessCallback(tess, GLU_TESS_COMBINE_DATA, reinterpret_cast<_GLUfuncptr>(&combine_cb));
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_POSITIVE);
    gluTessNormal(tess, 0, 0, 1);
  }
  ~CellTess() {
    if (tess) gluDeleteTess(tess);
  }
  CellTess(const CellTess&) = delete;
  CellTess& operator=(const CellTess&) = delete;
  void run(const std::vector<Polyline>& loops, double x0, double x1, double y0, double y1) {
    tri.clear();
    store.clear();
    if (!tess) return;
    gluTessBeginPolygon(tess, this);
    for (const Polyline& l : loops) {
      const Polyline c = clip_loop(l, x0, x1, y0, y1);
      if (c.size() < 3) continue;
      gluTessBeginContour(tess);
      for (const auto& p : c) {
        store.push_back({p[0], p[1], 0.0});
        gluTessVertex(tess, store.back().data(), store.back().data());
      }
      gluTessEndContour(tess);
    }
    gluTessEndPolygon(tess);
  }
};

// ---- Surfaces -----------------------------------------------------------------------------

void draw_surface(GLUnurbs* n) {
  std::vector<const Map*> maps;
  const Map* vert = gather_maps(n, maps);
  double lo[2], hi[2];
  if (!vert || !shared_domain(n, maps, 0, lo[0], hi[0]) || !shared_domain(n, maps, 1, lo[1], hi[1])) return;
  load_matrices(n);
  const Sampler sampler(n);
  const std::vector<double> bs = breakpoints(maps, 0, lo[0], hi[0]), bt = breakpoints(maps, 1, lo[1], hi[1]);
  const size_t ns = bs.size() - 1, nt = bt.size() - 1;
  // Patches per rectangle (every map's), and the steps per column and row.
  std::vector<std::vector<Patch>> patches(ns * nt);
  std::vector<int> su(ns, 1), sv(nt, 1);
  std::vector<char> culled(ns * nt, 0);
  for (size_t j = 0; j < nt; ++j)
    for (size_t i = 0; i < ns; ++i) {
      auto& ps = patches[j * ns + i];
      for (const Map* m : maps) ps.push_back(make_patch(*m, bs[i], bs[i + 1], bt[j], bt[j + 1]));
      const Patch& vp = ps[size_t(std::find(maps.begin(), maps.end(), vert) - maps.begin())];
      if (n->culling && sampler.culled(vp)) {
        culled[j * ns + i] = 1;
        continue;
      }
      su[i] = std::max(su[i], sampler.steps(vp, 0, bs[i + 1] - bs[i]));
      sv[j] = std::max(sv[j], sampler.steps(vp, 1, bt[j + 1] - bt[j]));
    }
  // Scale down a grid too large to draw.
  double cu = 0, cv = 0;
  for (int s : su) cu += s;
  for (int s : sv) cv += s;
  if (cu * cv > kMaxCells) {
    const double k = std::sqrt(kMaxCells / (cu * cv));
    for (int& s : su) s = std::max(1, int(s * k));
    for (int& s : sv) s = std::max(1, int(s * k));
  }

  // Trimming loops as closed polylines in the domain.
  std::vector<Polyline> loops;
  if (!n->loops.empty()) {
    double finest = HUGE_VAL;
    for (size_t i = 0; i < ns; ++i) finest = std::min(finest, (bs[i + 1] - bs[i]) / su[i]);
    for (size_t j = 0; j < nt; ++j) finest = std::min(finest, (bt[j + 1] - bt[j]) / sv[j]);
    const double eps = 1e-6 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
    double area = 0;
    for (const TrimLoop& tl : n->loops) {
      Polyline l;
      for (const TrimPiece& piece : tl) {
        Polyline p;
        if (piece.pwl) {
          for (size_t k = 0; k + 1 < piece.points.size(); k += 2)
            p.push_back({piece.points[k], piece.points[k + 1]});
        } else {
          sample_trim_curve(piece.curve, finest, p);
        }
        if (p.empty()) continue;
        if (!l.empty()) {
          if (std::hypot(p.front()[0] - l.back()[0], p.front()[1] - l.back()[1]) > eps) return report(n, 31);
          l.pop_back();
        }
        l.insert(l.end(), p.begin(), p.end());
      }
      if (l.size() < 2) return report(n, 18);
      if (std::hypot(l.front()[0] - l.back()[0], l.front()[1] - l.back()[1]) > eps) return report(n, 31);
      l.pop_back();
      if (l.size() < 3) continue;
      for (size_t k = 0; k < l.size(); ++k) {
        const auto &a = l[k], &b = l[(k + 1) % l.size()];
        area += a[0] * b[1] - b[0] * a[1];
      }
      loops.push_back(std::move(l));
    }
    // Only holes (clockwise loops): they are cut from the whole domain.
    if (area < 0) loops.push_back({{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}});
    if (loops.empty()) return;  // nothing is left of the surface
  }

  GlState state(n, true, maps);
  Output out(n, true);
  CellTess cells;
  for (size_t j = 0; j < nt; ++j)
    for (size_t i = 0; i < ns; ++i) {
      if (culled[j * ns + i]) continue;
      auto& ps = patches[j * ns + i];
      const int nu = su[i], nv = sv[j];
      const double u0 = bs[i], u1 = bs[i + 1], v0 = bt[j], v1 = bt[j + 1];
      auto ugrid = [&](int k) { return k == nu ? u1 : u0 + (u1 - u0) * k / nu; };
      auto vgrid = [&](int k) {
        return k == 0 ? v1 : k == nv ? v0 : v1 + (v0 - v1) * k / nv;
      };  // from the top
      out.use(&ps);
      if (n->display_mode == GLU_OUTLINE_PATCH) continue;
      if (loops.empty()) {
        if (out.renderer()) {
          glMapGrid2d(nu, u0, u1, nv, v1, v0);
          glEvalMesh2(n->display_mode == GLU_OUTLINE_POLYGON ? GL_LINE : GL_FILL, 0, nu, 0, nv);
          continue;
        }
        for (int r = 0; r < nv; ++r) {
          out.begin(GL_QUAD_STRIP);
          for (int k = 0; k <= nu; ++k) {
            out.vertex(ugrid(k), vgrid(r));
            out.vertex(ugrid(k), vgrid(r + 1));
          }
          out.end();
        }
        continue;
      }
      // Which cells the loops cross (their segments' boxes touch them).
      std::vector<char> crossed(size_t(nu) * size_t(nv), 0);
      const double du = (u1 - u0) / nu, dv = (v1 - v0) / nv;
      for (const Polyline& l : loops)
        for (size_t k = 0; k < l.size(); ++k) {
          const auto &a = l[k], &b = l[(k + 1) % l.size()];
          const double xa = std::min(a[0], b[0]), xb = std::max(a[0], b[0]);
          const double ya = std::min(a[1], b[1]), yb = std::max(a[1], b[1]);
          if (xb < u0 || xa > u1 || yb < v0 || ya > v1) continue;
          const int ia = std::clamp(int(std::floor((xa - u0) / du)) - 1, 0, nu - 1);
          const int ib = std::clamp(int(std::floor((xb - u0) / du)) + 1, 0, nu - 1);
          // Rows counted from the top (v1), as the grid runs.
          const int ja = std::clamp(int(std::floor((v1 - yb) / dv)) - 1, 0, nv - 1);
          const int jb = std::clamp(int(std::floor((v1 - ya) / dv)) + 1, 0, nv - 1);
          for (int r = ja; r <= jb; ++r)
            for (int c = ia; c <= ib; ++c) crossed[size_t(r) * size_t(nu) + size_t(c)] = 1;
        }
      for (int r = 0; r < nv; ++r) {
        const double vt = vgrid(r), vb = vgrid(r + 1);
        int c = 0;
        while (c < nu) {
          if (crossed[size_t(r) * size_t(nu) + size_t(c)]) {
            cells.run(loops, ugrid(c), ugrid(c + 1), vb, vt);
            if (!cells.tri.empty()) {
              out.begin(GL_TRIANGLES);
              for (const double* p : cells.tri) out.vertex(p[0], p[1]);
              out.end();
            }
            ++c;
            continue;
          }
          // A run of uncrossed cells: all in or all out.
          int e = c;
          while (e < nu && !crossed[size_t(r) * size_t(nu) + size_t(e)]) ++e;
          if (winding(loops, 0.5 * (ugrid(c) + ugrid(c + 1)), 0.5 * (vt + vb)) > 0) {
            out.begin(GL_QUAD_STRIP);
            for (int k = c; k <= e; ++k) {
              out.vertex(ugrid(k), vt);
              out.vertex(ugrid(k), vb);
            }
            out.end();
          }
          c = e;
        }
      }
    }

  if (n->display_mode != GLU_OUTLINE_PATCH) return;
  // GLU_OUTLINE_PATCH: the domain's boundary, or the trimming loops, on the surface. Each
  // segment is cut where it crosses a rectangle's side and at the grid's density, and each
  // piece drawn with its rectangle's maps.
  std::vector<Polyline> outline = loops;
  if (outline.empty()) outline.push_back({{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}});
  auto rect = [&](const std::vector<double>& b, double x) {
    return size_t(
        std::clamp(int(std::upper_bound(b.begin(), b.end(), x) - b.begin()) - 1, 0, int(b.size()) - 2));
  };
  for (const Polyline& l : outline) {
    for (size_t k = 0; k < l.size(); ++k) {
      const auto &a = l[k], &b = l[(k + 1) % l.size()];
      // Parameters where the segment meets the rectangles' sides, and grid-density steps.
      std::vector<double> ts = {0.0, 1.0};
      for (int d = 0; d < 2; ++d) {
        const std::vector<double>& br = d == 0 ? bs : bt;
        for (double x : br)
          if ((a[size_t(d)] - x) * (b[size_t(d)] - x) < 0)
            ts.push_back((x - a[size_t(d)]) / (b[size_t(d)] - a[size_t(d)]));
      }
      std::sort(ts.begin(), ts.end());
      for (size_t q = 0; q + 1 < ts.size(); ++q) {
        const double tm = 0.5 * (ts[q] + ts[q + 1]);
        const double mu = a[0] + (b[0] - a[0]) * tm, mv = a[1] + (b[1] - a[1]) * tm;
        if (mu < lo[0] || mu > hi[0] || mv < lo[1] || mv > hi[1]) continue;
        const size_t i = rect(bs, mu), j = rect(bt, mv);
        if (culled[j * ns + i]) continue;
        const double len_u = std::fabs(b[0] - a[0]) * (ts[q + 1] - ts[q]) / ((bs[i + 1] - bs[i]) / su[i]);
        const double len_v = std::fabs(b[1] - a[1]) * (ts[q + 1] - ts[q]) / ((bt[j + 1] - bt[j]) / sv[j]);
        const int steps = std::clamp(int(std::ceil(std::max(len_u, len_v))), 1, kMaxSpanSteps);
        out.use(&patches[j * ns + i]);
        out.begin(GL_LINE_STRIP);
        for (int s = 0; s <= steps; ++s) {
          const double t = ts[q] + (ts[q + 1] - ts[q]) * s / steps;
          out.vertex(a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t);
        }
        out.end();
      }
    }
  }
}

void reset(GLUnurbs* n) {
  n->maps.clear();
  n->loops.clear();
  n->failed = false;
}

}  // namespace

extern "C" {

GLUnurbs* GLAPIENTRY gluNewNurbsRenderer(void) { return new (std::nothrow) GLUnurbs(); }

void GLAPIENTRY gluDeleteNurbsRenderer(GLUnurbs* n) { delete n; }

void GLAPIENTRY gluNurbsProperty(GLUnurbs* n, GLenum property, GLfloat value) {
  if (!n) return;
  auto bad_value = [&] {
    if (n->error) n->error(GLU_INVALID_VALUE);
  };
  switch (property) {
    case GLU_AUTO_LOAD_MATRIX: n->auto_load = value != 0.0f; return;
    case GLU_CULLING: n->culling = value != 0.0f; return;
    case GLU_SAMPLING_TOLERANCE:
      if (!(value > 0.0f) || !std::isfinite(value)) return bad_value();
      n->sampling_tolerance = value;
      return;
    case GLU_PARAMETRIC_TOLERANCE:
      if (!(value > 0.0f) || !std::isfinite(value)) return bad_value();
      n->parametric_tolerance = value;
      return;
    case GLU_U_STEP:
    case GLU_V_STEP:
      if (!(value > 0.0f) || !std::isfinite(value)) return bad_value();
      (property == GLU_U_STEP ? n->u_step : n->v_step) = value;
      return;
    case GLU_DISPLAY_MODE: {
      const GLenum v = GLenum(value);
      if (v != GLU_FILL && v != GLU_OUTLINE_POLYGON && v != GLU_OUTLINE_PATCH) return bad_value();
      n->display_mode = v;
      return;
    }
    case GLU_SAMPLING_METHOD: {
      const GLenum v = GLenum(value);
      if (v != GLU_PATH_LENGTH && v != GLU_PARAMETRIC_ERROR && v != GLU_DOMAIN_DISTANCE &&
          v != GLU_OBJECT_PATH_LENGTH && v != GLU_OBJECT_PARAMETRIC_ERROR)
        return bad_value();
      n->sampling_method = v;
      return;
    }
    case GLU_NURBS_MODE: {
      const GLenum v = GLenum(value);
      if (v != GLU_NURBS_RENDERER && v != GLU_NURBS_TESSELLATOR) return bad_value();
      n->mode = v;
      return;
    }
    default:
      report(n, 26);
      n->failed = false;
      return;  // invalid property
  }
}

void GLAPIENTRY gluGetNurbsProperty(GLUnurbs* n, GLenum property, GLfloat* data) {
  if (!n || !data) return;
  switch (property) {
    case GLU_AUTO_LOAD_MATRIX: *data = n->auto_load ? 1.0f : 0.0f; return;
    case GLU_CULLING: *data = n->culling ? 1.0f : 0.0f; return;
    case GLU_SAMPLING_TOLERANCE: *data = n->sampling_tolerance; return;
    case GLU_PARAMETRIC_TOLERANCE: *data = n->parametric_tolerance; return;
    case GLU_U_STEP: *data = n->u_step; return;
    case GLU_V_STEP: *data = n->v_step; return;
    case GLU_DISPLAY_MODE: *data = GLfloat(n->display_mode); return;
    case GLU_SAMPLING_METHOD: *data = GLfloat(n->sampling_method); return;
    case GLU_NURBS_MODE: *data = GLfloat(n->mode); return;
    default:
      report(n, 26);
      n->failed = false;
      return;
  }
}

void GLAPIENTRY gluLoadSamplingMatrices(GLUnurbs* n, const GLfloat* model, const GLfloat* perspective,
                                        const GLint* view) {
  if (!n || !model || !perspective || !view) return;
  for (int i = 0; i < 16; ++i) n->model[i] = model[i], n->proj[i] = perspective[i];
  for (int i = 0; i < 4; ++i) n->view[i] = view[i];
}

void GLAPIENTRY gluNurbsCallback(GLUnurbs* n, GLenum which, _GLUfuncptr fn) {
  if (!n) return;
  switch (which) {
    case GLU_NURBS_ERROR: n->error = reinterpret_cast<ErrorFn>(fn); return;
    case GLU_NURBS_BEGIN: n->begin = reinterpret_cast<BeginFn>(fn); return;
    case GLU_NURBS_BEGIN_DATA: n->begin_data = reinterpret_cast<BeginDataFn>(fn); return;
    case GLU_NURBS_VERTEX: n->vertex = reinterpret_cast<ValueFn>(fn); return;
    case GLU_NURBS_VERTEX_DATA: n->vertex_data = reinterpret_cast<ValueDataFn>(fn); return;
    case GLU_NURBS_NORMAL: n->normal = reinterpret_cast<ValueFn>(fn); return;
    case GLU_NURBS_NORMAL_DATA: n->normal_data = reinterpret_cast<ValueDataFn>(fn); return;
    case GLU_NURBS_COLOR: n->color = reinterpret_cast<ValueFn>(fn); return;
    case GLU_NURBS_COLOR_DATA: n->color_data = reinterpret_cast<ValueDataFn>(fn); return;
    case GLU_NURBS_TEXTURE_COORD: n->texcoord = reinterpret_cast<ValueFn>(fn); return;
    case GLU_NURBS_TEXTURE_COORD_DATA: n->texcoord_data = reinterpret_cast<ValueDataFn>(fn); return;
    case GLU_NURBS_END: n->end = reinterpret_cast<EndFn>(fn); return;
    case GLU_NURBS_END_DATA: n->end_data = reinterpret_cast<EndDataFn>(fn); return;
    default:
      if (n->error) n->error(GLU_INVALID_ENUM);
      return;
  }
}

void GLAPIENTRY gluNurbsCallbackData(GLUnurbs* n, GLvoid* data) {
  if (n) n->user_data = data;
}

void GLAPIENTRY gluNurbsCallbackDataEXT(GLUnurbs* n, GLvoid* data) { gluNurbsCallbackData(n, data); }

void GLAPIENTRY gluBeginCurve(GLUnurbs* n) {
  if (!n) return;
  if (n->scope != Scope::None) return report(n, 6);
  reset(n);
  n->scope = Scope::Curve;
}

void GLAPIENTRY gluEndCurve(GLUnurbs* n) {
  if (!n) return;
  if (n->scope != Scope::Curve) return report(n, 7);
  n->scope = Scope::None;
  if (!n->failed) draw_curve(n);
  reset(n);
}

void GLAPIENTRY gluNurbsCurve(GLUnurbs* n, GLint knotCount, GLfloat* knots, GLint stride, GLfloat* control,
                              GLint order, GLenum type) {
  if (!n) return;
  if (n->scope == Scope::None || n->scope == Scope::Surface) return report(n, is_trim(type) ? 14 : 22);
  if ((n->scope == Scope::Trim) != is_trim(type)) return report(n, 14);
  Map m;
  if (!read_map(n, 1, &knotCount, &knots, &stride, control, &order, type, m)) return;
  if (n->scope == Scope::Trim) {
    TrimPiece p;
    p.pwl = false;
    p.curve = std::move(m);
    n->loops.back().push_back(std::move(p));
    return;
  }
  for (const Map& o : n->maps)
    if (o.type == type) return report(n, 23);  // referenced twice
  n->maps.push_back(std::move(m));
}

void GLAPIENTRY gluBeginSurface(GLUnurbs* n) {
  if (!n) return;
  if (n->scope != Scope::None) return report(n, 27);
  reset(n);
  n->scope = Scope::Surface;
}

void GLAPIENTRY gluNurbsSurface(GLUnurbs* n, GLint sKnotCount, GLfloat* sKnots, GLint tKnotCount,
                                GLfloat* tKnots, GLint sStride, GLint tStride, GLfloat* control, GLint sOrder,
                                GLint tOrder, GLenum type) {
  if (!n) return;
  if (n->scope != Scope::Surface) return report(n, n->scope == Scope::Trim ? 12 : 13);
  const GLint counts[2] = {sKnotCount, tKnotCount}, strides[2] = {sStride, tStride},
              orders[2] = {sOrder, tOrder};
  GLfloat* const knots[2] = {sKnots, tKnots};
  Map m;
  if (!read_map(n, 2, counts, knots, strides, control, orders, type, m)) return;
  for (const Map& o : n->maps)
    if (o.type == type) return report(n, 25);  // referenced twice
  n->maps.push_back(std::move(m));
}

void GLAPIENTRY gluEndSurface(GLUnurbs* n) {
  if (!n) return;
  if (n->scope == Scope::Trim) {
    report(n, 12);
    n->scope = Scope::None;
    reset(n);
    return;
  }
  if (n->scope != Scope::Surface) return report(n, 13);
  n->scope = Scope::None;
  if (!n->failed) draw_surface(n);
  reset(n);
}

void GLAPIENTRY gluBeginTrim(GLUnurbs* n) {
  if (!n) return;
  if (n->scope == Scope::Trim) return report(n, 16);
  if (n->scope != Scope::Surface) return report(n, 15);
  n->scope = Scope::Trim;
  n->loops.emplace_back();
}

void GLAPIENTRY gluEndTrim(GLUnurbs* n) {
  if (!n) return;
  if (n->scope != Scope::Trim) return report(n, 17);
  n->scope = Scope::Surface;
  if (n->loops.back().empty()) report(n, 18);
}

void GLAPIENTRY gluPwlCurve(GLUnurbs* n, GLint count, GLfloat* data, GLint stride, GLenum type) {
  if (!n) return;
  if (n->scope != Scope::Trim) return report(n, 19);
  if (type != GLU_MAP1_TRIM_2 && type != GLU_MAP1_TRIM_3) return report(n, 35);
  if (count < 0) return report(n, 33);
  if (stride < 0) return report(n, 34);
  if (!data) return report(n, 36);
  TrimPiece p;
  for (GLint i = 0; i < count; ++i) {
    const GLfloat* q = data + size_t(i) * size_t(stride);
    const double w = type == GLU_MAP1_TRIM_3 ? q[2] : 1.0;
    const double u = q[0] / w, v = q[1] / w;
    if (i > 0 && u == p.points[p.points.size() - 2] && v == p.points.back()) return report(n, 37);
    p.points.push_back(u);
    p.points.push_back(v);
  }
  n->loops.back().push_back(std::move(p));
}

}  // extern "C"
