// GLU 1.3 polygon tessellation (chapter 5 of "The OpenGL Graphics System Utility Library,
// Version 1.3"): gluNewTess/gluDeleteTess, the begin/contour/vertex/end calls, callbacks,
// properties, gluTessNormal and the GLU 1.1 gluBeginPolygon/gluNextContour/gluEndPolygon.
//
// The tessellator itself never calls GL: everything it produces goes through the user's
// BEGIN/VERTEX/END/EDGE_FLAG/COMBINE/ERROR callbacks (GL_TRIANGLES, or GL_LINE_LOOPs in
// boundary-only mode), so the output can be fed to any GL 1.x.
//
// How a polygon is processed (gluTessEndPolygon):
//  1. The vertices are projected onto a plane: the one perpendicular to gluTessNormal, or to a
//     normal computed from the vertices (the plane through the two extreme vertices along the
//     longest axis and the vertex farthest from that line; its sign is chosen so that the sum of
//     the contours' signed areas is not negative, as section 5.3 asks). The projection drops the
//     normal's largest coordinate, which keeps axis-aligned input exact.
//  2. Vertices closer than a tolerance (1e-10 of the polygon's extent, at least 1e-13 of its
//     coordinates' magnitude: far below anything visible) are merged into one; the COMBINE
//     callback may supply the merged vertex, as the reference GLU does for coincident vertices
//     (it is not an error if there is none).
//  3. All edge intersections are computed (candidate pairs from a bounding-box hierarchy). A
//     vertex within the tolerance of an edge splits it (so nearly collinear, overlapping edges
//     are split at each other's ends rather than crossed at an ill-conditioned point); every
//     other crossing becomes a vertex made by the COMBINE callback, unless it lands within the
//     tolerance of an existing vertex, which is then reused. Edges between the same two
//     vertices are merged with their windings added (dropped when they cancel). The pass
//     repeats on the new edges until nothing changes (rounded intersection points can create
//     new crossings; in practice one extra pass, at most 8), leaving a planar graph.
//  4. A sweep over the graph (vertices in (s, t) order, with exact orientation tests) keeps the
//     edges crossing the sweep line in order; each region between two edges carries its winding
//     number and hence, by the winding rule, whether it is inside. Inside regions are
//     triangulated as they are swept, as y-monotone pieces: every region holds the usual stack
//     of the monotone-polygon triangulation algorithm, split and merge vertices are resolved by
//     the classic diagonals (split vertex to the region's last vertex, merge vertex to the next
//     vertex met by the merged region). Edge flags come for free: an edge of a triangle is a
//     boundary edge exactly when it is a graph edge with an outside region on its other side.
//  5. Boundary-only mode keeps the boundary edges instead, directed with the interior on their
//     left, and links them into loops (exterior loops counter-clockwise, holes clockwise).
// All triangles go out in one GL_TRIANGLES batch (with edge flags when an EDGE_FLAG callback is
// set), counter-clockwise with respect to the normal. The work is O(n log n) for ordinary
// input, plus the number of intersections; degenerate input (repeated points, zero-length
// edges, collinear or overlapping edges, zero-area contours) is absorbed by steps 2 and 3, and
// every loop is bounded. If a crossing needs a new vertex and there is no COMBINE callback (or
// it returns NULL), GLU_TESS_NEED_COMBINE_CALLBACK is reported once and nothing is drawn, as
// the reference GLU does.

#include <GL/gl.h>
#include <GL/glu.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <new>
#include <unordered_map>
#include <utility>
#include <vector>

namespace tessel_glu_tess {

using BeginFn = void(GLAPIENTRY*)(GLenum);
using BeginDataFn = void(GLAPIENTRY*)(GLenum, void*);
using EdgeFlagFn = void(GLAPIENTRY*)(GLboolean);
using EdgeFlagDataFn = void(GLAPIENTRY*)(GLboolean, void*);
using VertexFn = void(GLAPIENTRY*)(void*);
using VertexDataFn = void(GLAPIENTRY*)(void*, void*);
using EndFn = void(GLAPIENTRY*)(void);
using EndDataFn = void(GLAPIENTRY*)(void*);
using ErrorFn = void(GLAPIENTRY*)(GLenum);
using ErrorDataFn = void(GLAPIENTRY*)(GLenum, void*);
using CombineFn = void(GLAPIENTRY*)(GLdouble*, void**, GLfloat*, void**);
using CombineDataFn = void(GLAPIENTRY*)(GLdouble*, void**, GLfloat*, void**, void*);

enum class State { Dormant, InPolygon, InContour };

struct InputVertex {
  double xyz[3];
  void* data;
};

}  // namespace tessel_glu_tess

struct GLUtesselator {
  tessel_glu_tess::State state = tessel_glu_tess::State::Dormant;

  tessel_glu_tess::BeginFn begin = nullptr;
  tessel_glu_tess::BeginDataFn beginData = nullptr;
  tessel_glu_tess::EdgeFlagFn edgeFlag = nullptr;
  tessel_glu_tess::EdgeFlagDataFn edgeFlagData = nullptr;
  tessel_glu_tess::VertexFn vertex = nullptr;
  tessel_glu_tess::VertexDataFn vertexData = nullptr;
  tessel_glu_tess::EndFn end = nullptr;
  tessel_glu_tess::EndDataFn endData = nullptr;
  tessel_glu_tess::ErrorFn error = nullptr;
  tessel_glu_tess::ErrorDataFn errorData = nullptr;
  tessel_glu_tess::CombineFn combine = nullptr;
  tessel_glu_tess::CombineDataFn combineData = nullptr;

  GLenum windingRule = GLU_TESS_WINDING_ODD;
  bool boundaryOnly = false;
  double tolerance = 0.0;
  double normal[3] = {0.0, 0.0, 0.0};

  void* polygonData = nullptr;
  std::vector<tessel_glu_tess::InputVertex> vertices;
  std::vector<std::size_t> contourStarts;  // index of the first vertex of each contour
};

namespace tessel_glu_tess {
namespace {

// ---------------------------------------------------------------------------------------------
// Callbacks: the _DATA variant wins when both are set (section 5.2).

void callError(GLUtesselator* t, GLenum code) {
  if (t->errorData)
    t->errorData(code, t->polygonData);
  else if (t->error)
    t->error(code);
}

bool hasCombine(const GLUtesselator* t) { return t->combineData || t->combine; }

void* callCombine(GLUtesselator* t, double xyz[3], void* data[4], float weights[4]) {
  void* out = nullptr;
  if (t->combineData)
    t->combineData(xyz, data, weights, &out, t->polygonData);
  else if (t->combine)
    t->combine(xyz, data, weights, &out);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Geometry. Vertices live in the projected (s, t) plane; xyz and data are what the COMBINE and
// VERTEX callbacks need.

struct Vert {
  double s, t;
  double xyz[3];
  void* data;
};

// Exact sign of the orientation determinant, for the rare cases the floating-point filter
// cannot decide: the determinant expands into six products of coordinates, each split exactly
// into two doubles by an FMA, and the twelve terms are summed exactly as a non-overlapping
// expansion (Shewchuk's grow-expansion). The largest non-zero component has the sign (and,
// approximately, the magnitude) of the determinant.
double orientExact(double ax, double ay, double bx, double by, double cx, double cy) {
  double terms[12];
  int n = 0;
  auto product = [&](double p, double q, bool negate) {
    const double hi = p * q;
    const double lo = std::fma(p, q, -hi);
    terms[n++] = negate ? -hi : hi;
    terms[n++] = negate ? -lo : lo;
  };
  // (bx-ax)(cy-ay) - (by-ay)(cx-ax) = bx*cy - bx*ay - ax*cy - by*cx + by*ax + ay*cx
  product(bx, cy, false);
  product(bx, ay, true);
  product(ax, cy, true);
  product(by, cx, true);
  product(by, ax, false);
  product(ay, cx, false);
  double e[13];
  int m = 0;
  for (int k = 0; k < 12; ++k) {
    double q = terms[k];
    int mm = 0;
    for (int i = 0; i < m; ++i) {
      const double sum = q + e[i];
      const double bv = sum - q;
      const double av = sum - bv;
      const double err = (q - av) + (e[i] - bv);
      q = sum;
      if (err != 0.0) e[mm++] = err;
    }
    e[mm++] = q;
    m = mm;
  }
  for (int i = m - 1; i >= 0; --i)
    if (e[i] != 0.0) return e[i];
  return 0.0;
}

// > 0 when c lies to the left of the directed line a -> b ("above" it in the sweep), < 0 to
// the right, 0 when the three points are collinear; the sign is exact.
double orient(const Vert& a, const Vert& b, const Vert& c) {
  const double l = (b.s - a.s) * (c.t - a.t);
  const double r = (b.t - a.t) * (c.s - a.s);
  const double det = l - r;
  const double bound = 3.3306690738754716e-16 * (std::fabs(l) + std::fabs(r));
  if (det > bound || -det > bound) return det;
  return orientExact(a.s, a.t, b.s, b.t, c.s, c.t);
}

// The sweep order: by s, then by t.
bool lexLess(const Vert& a, const Vert& b) { return a.s < b.s || (a.s == b.s && a.t < b.t); }

bool windingInside(GLenum rule, int w) {
  switch (rule) {
    case GLU_TESS_WINDING_NONZERO: return w != 0;
    case GLU_TESS_WINDING_POSITIVE: return w > 0;
    case GLU_TESS_WINDING_NEGATIVE: return w < 0;
    case GLU_TESS_WINDING_ABS_GEQ_TWO: return w >= 2 || w <= -2;
    case GLU_TESS_WINDING_ODD:
    default: return (w & 1) != 0;
  }
}

struct Triangle {
  int v[3];
  bool flag[3];  // flag[i]: the edge v[i] -> v[i+1] lies on the boundary
};

// ---------------------------------------------------------------------------------------------
// One tessellation (gluTessEndPolygon).

class Tessellation {
 public:
  explicit Tessellation(GLUtesselator* tess) : tess_(tess) {}
  void run();

 private:
  // Step 1 and 2.
  void project();
  void mergeCoincident();
  // Step 3.
  struct DEdge {
    int a, b;  // a -> b
    int w;     // how many times the contours run a -> b (negative: b -> a)
  };
  struct Box {
    double s0, t0, s1, t1;
  };
  struct BNode {
    Box box;
    int left, right;  // children, or -1 for a leaf
    int begin, end;   // a leaf's edges in `items`
  };
  void intersectAll();
  void mergeDuplicateEdges(std::vector<char>& dirty);
  static int buildHierarchy(const std::vector<Box>& boxes, std::vector<int>& items, std::vector<BNode>& nodes,
                            int begin, int end);
  void testPair(std::size_t i, std::size_t j, std::vector<std::vector<int>>& splits);
  int vertexNear(double s, double t);
  void gridInsert(int v);
  std::uint64_t cellKey(long long ix, long long iy) const;
  bool strictlyBetween(int p, int a, int b) const;
  bool nearSegment(int p, int a, int b, double o) const;
  // Step 4.
  struct SEdge {
    int lo, hi;  // lo before hi in the sweep order
    int delta;   // winding change from below (right of lo -> hi) to above (left of it)
    bool flag;   // boundary edge: inside on one side only
  };
  struct Region {
    int wind = 0;
    bool inside = false;
    int poly = -1;    // the monotone piece being triangulated (inside regions)
    int mergeV = -1;  // pending merge vertex: poly lies below it, poly2 above it
    int poly2 = -1;
  };
  struct Active {
    int edge;    // -1 for the sentinel at the bottom
    Region reg;  // the region above the edge
  };
  enum Chain : signed char { kStart = 0, kLower = 1, kUpper = 2 };
  struct StackEntry {
    int v;
    Chain chain;
    bool flagPrev;  // boundary flag of the edge from the entry below to this one
  };
  struct Poly {
    std::vector<StackEntry> stack;
  };
  void buildGraph();
  void sweep();
  std::size_t locate(int v) const;
  std::size_t gatherLeft(int v, std::size_t& count);
  void insertRight(std::size_t p, int v, const Region& top);
  int newPoly(int v);
  void addToPoly(int pi, int u, Chain chain, bool flag);
  void finishPoly(int pi, int u, bool flagLo, bool flagHi);
  void toUpper(Region& r, int v, bool flag);
  void toLower(Region& r, int v, bool flag);
  void finishRegion(Region& r, int v, bool flagLo, bool flagHi);
  void splitRegion(const Region& r, int v, Region& lower, Region& upper);
  void emitTri(int a, int b, int c, bool fab, bool fbc, bool fca);
  // Output.
  void outputTriangles();
  void outputBoundary();

  GLUtesselator* tess_;
  std::vector<Vert> verts_;
  std::vector<int> inputToVert_;  // input vertex -> merged vertex
  std::vector<DEdge> dedges_;
  bool fatal_ = false;  // an intersection without a COMBINE result: no output

  double minS_ = 0, minT_ = 0, cell_ = 1;
  std::unordered_map<std::uint64_t, int> grid_;  // cell -> last vertex inserted there
  std::vector<int> gridNext_;

  std::vector<SEdge> sedges_;
  std::vector<int> order_;       // vertices in sweep order
  std::vector<int> rightStart_;  // per vertex: its edges to later vertices, sorted bottom to top
  std::vector<int> rightEdges_;
  std::vector<int> leftCount_;  // per vertex: number of edges from earlier vertices
  std::vector<Active> status_;
  std::vector<Poly> polys_;
  std::vector<Triangle> tris_;
  std::vector<std::pair<int, int>> boundary_;  // directed boundary edges, interior on the left
};

void Tessellation::run() {
  if (tess_->vertices.empty()) return;
  project();
  mergeCoincident();
  intersectAll();
  if (fatal_) return;
  buildGraph();
  sweep();
  if (tess_->boundaryOnly)
    outputBoundary();
  else
    outputTriangles();
}

// ---- Step 1: the projection plane -----------------------------------------------------------

void Tessellation::project() {
  const std::vector<InputVertex>& in = tess_->vertices;
  double n[3] = {tess_->normal[0], tess_->normal[1], tess_->normal[2]};
  const bool computed = n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0;
  if (computed) {
    // The extreme vertices along each axis; the longest extent gives two far-apart vertices,
    // and the vertex making the largest triangle with them fixes the plane.
    std::size_t minI[3] = {0, 0, 0}, maxI[3] = {0, 0, 0};
    for (std::size_t i = 1; i < in.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        if (in[i].xyz[k] < in[minI[k]].xyz[k]) minI[k] = i;
        if (in[i].xyz[k] > in[maxI[k]].xyz[k]) maxI[k] = i;
      }
    int axis = 0;
    double extent = in[maxI[0]].xyz[0] - in[minI[0]].xyz[0];
    for (int k = 1; k < 3; ++k) {
      const double e = in[maxI[k]].xyz[k] - in[minI[k]].xyz[k];
      if (e > extent) {
        extent = e;
        axis = k;
      }
    }
    if (!(extent > 0.0)) {
      n[2] = 1.0;  // all vertices coincide: any plane will do
    } else {
      const double* v1 = in[minI[axis]].xyz;
      const double* v2 = in[maxI[axis]].xyz;
      // Differences scaled by a power of two to about 1, so that the cross products below
      // neither underflow nor overflow.
      const double unit = std::ldexp(1.0, -std::ilogb(extent));
      const double d1[3] = {(v1[0] - v2[0]) * unit, (v1[1] - v2[1]) * unit, (v1[2] - v2[2]) * unit};
      double best = 0.0;
      for (const InputVertex& v : in) {
        const double d2[3] = {(v.xyz[0] - v2[0]) * unit, (v.xyz[1] - v2[1]) * unit,
                              (v.xyz[2] - v2[2]) * unit};
        const double c[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                             d1[0] * d2[1] - d1[1] * d2[0]};
        const double len2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
        if (len2 > best) {
          best = len2;
          n[0] = c[0];
          n[1] = c[1];
          n[2] = c[2];
        }
      }
      if (!(best > 0.0)) {
        // All vertices on one line: a plane containing it, perpendicular to its shortest axis.
        n[0] = n[1] = n[2] = 0.0;
        int shortAxis = 0;
        for (int k = 1; k < 3; ++k)
          if (std::fabs(d1[k]) < std::fabs(d1[shortAxis])) shortAxis = k;
        n[shortAxis] = 1.0;
      }
    }
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(n[k]) > std::fabs(n[axis])) axis = k;
  const int sAxis = (axis + 1) % 3, tAxis = (axis + 2) % 3;
  double tSign = n[axis] > 0.0 ? 1.0 : -1.0;

  verts_.resize(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    Vert& v = verts_[i];
    v.s = in[i].xyz[sAxis];
    v.t = tSign * in[i].xyz[tAxis];
    v.xyz[0] = in[i].xyz[0];
    v.xyz[1] = in[i].xyz[1];
    v.xyz[2] = in[i].xyz[2];
    v.data = in[i].data;
  }
  // Scale (s, t) by a power of two, exactly, so that the largest coordinate is about 1: the
  // products in the orientation tests then neither underflow (tiny polygons) nor overflow.
  double maxAbs = 0.0;
  for (const Vert& v : verts_) maxAbs = std::max(maxAbs, std::max(std::fabs(v.s), std::fabs(v.t)));
  if (maxAbs > 0.0 && std::isfinite(maxAbs)) {
    const double scale = std::ldexp(1.0, -std::ilogb(maxAbs));
    for (Vert& v : verts_) {
      v.s *= scale;
      v.t *= scale;
    }
  }
  if (computed) {
    // Section 5.3: the computed normal points so that the total signed area is not negative.
    const std::vector<std::size_t>& starts = tess_->contourStarts;
    double area = 0.0;
    for (std::size_t c = 0; c < starts.size(); ++c) {
      const std::size_t b = starts[c], e = c + 1 < starts.size() ? starts[c + 1] : in.size();
      for (std::size_t i = b; i < e; ++i) {
        const Vert& p = verts_[i];
        const Vert& q = verts_[i + 1 < e ? i + 1 : b];
        area += (p.s - q.s) * (p.t + q.t);  // shoelace: twice the signed area
      }
    }
    if (area < 0.0)
      for (Vert& v : verts_) v.t = -v.t;
  }
}

// ---- Step 2: coincident vertices --------------------------------------------------------------

void Tessellation::mergeCoincident() {
  std::vector<Vert> in;
  in.swap(verts_);
  const std::size_t n = in.size();
  double minS = in[0].s, maxS = in[0].s, minT = in[0].t, maxT = in[0].t, maxAbs = 0.0;
  for (const Vert& v : in) {
    minS = std::min(minS, v.s);
    maxS = std::max(maxS, v.s);
    minT = std::min(minT, v.t);
    maxT = std::max(maxT, v.t);
    maxAbs = std::max(maxAbs, std::max(std::fabs(v.s), std::fabs(v.t)));
  }
  minS_ = minS;
  minT_ = minT;
  // The merge tolerance: vertices closer than this are one vertex, an intersection point
  // closer than this to a vertex reuses it, and a vertex closer than this to an edge splits
  // the edge. Far below anything visible, far above the rounding error of an intersection
  // (hence the term in the coordinates' magnitude, for small shapes far from the origin).
  const double extent = std::max(maxS - minS, maxT - minT);
  cell_ = std::max({extent * 1e-10, maxAbs * 1e-13, std::numeric_limits<double>::min()});

  // In input order, each vertex joins the nearest earlier one within the tolerance (the
  // COMBINE callback may supply a merged vertex, as the reference GLU does for coincident
  // vertices; it is not an error if there is none) or starts a new one.
  verts_.reserve(n);
  grid_.reserve(n);
  inputToVert_.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const Vert& v = in[i];
    const int near = vertexNear(v.s, v.t);
    if (near < 0) {
      inputToVert_[i] = static_cast<int>(verts_.size());
      verts_.push_back(v);
      gridInsert(inputToVert_[i]);
      continue;
    }
    inputToVert_[i] = near;
    Vert& rep = verts_[near];
    double xyz[3];
    for (int c = 0; c < 3; ++c) xyz[c] = 0.5 * (rep.xyz[c] + v.xyz[c]);
    if (hasCombine(tess_)) {
      void* data[4] = {rep.data, v.data, nullptr, nullptr};
      float w[4] = {0.5f, 0.5f, 0.0f, 0.0f};
      void* out = callCombine(tess_, xyz, data, w);
      if (out) rep.data = out;
    }
    for (int c = 0; c < 3; ++c) rep.xyz[c] = xyz[c];
  }

  const std::vector<std::size_t>& starts = tess_->contourStarts;
  for (std::size_t c = 0; c < starts.size(); ++c) {
    const std::size_t b = starts[c], e = c + 1 < starts.size() ? starts[c + 1] : n;
    if (e - b < 2) continue;
    for (std::size_t i = b; i < e; ++i) {
      const int a = inputToVert_[i];
      const int d = inputToVert_[i + 1 < e ? i + 1 : b];
      if (a != d) dedges_.push_back({a, d, 1});
    }
  }
}

// ---- Step 3: intersections ---------------------------------------------------------------------

std::uint64_t Tessellation::cellKey(long long ix, long long iy) const {
  const std::uint64_t x = static_cast<std::uint64_t>(ix), y = static_cast<std::uint64_t>(iy);
  return x * 0x9E3779B97F4A7C15ull ^ (y + 0x632BE59BD9B4E019ull + (x << 6) + (x >> 2));
}

// The grid's cells are four tolerances wide, so that most lookups need one cell; vertices in a
// cell are chained through gridNext_.
void Tessellation::gridInsert(int v) {
  const double size = 4.0 * cell_;
  const long long ix = static_cast<long long>(std::floor((verts_[v].s - minS_) / size));
  const long long iy = static_cast<long long>(std::floor((verts_[v].t - minT_) / size));
  if (gridNext_.size() <= static_cast<std::size_t>(v)) gridNext_.resize(static_cast<std::size_t>(v) + 1, -1);
  auto ins = grid_.try_emplace(cellKey(ix, iy), v);
  if (!ins.second) {
    gridNext_[v] = ins.first->second;
    ins.first->second = v;
  }
}

// The nearest existing vertex within the tolerance of (s, t), or -1.
int Tessellation::vertexNear(double s, double t) {
  const double size = 4.0 * cell_;
  const double fx = (s - minS_) / size, fy = (t - minT_) / size;
  const long long ix = static_cast<long long>(std::floor(fx));
  const long long iy = static_cast<long long>(std::floor(fy));
  // Neighbouring cells only matter when (s, t) is within the tolerance of their side.
  const double rx = fx - static_cast<double>(ix), ry = fy - static_cast<double>(iy);
  const long long x0 = rx < 0.3 ? ix - 1 : ix, x1 = rx > 0.7 ? ix + 1 : ix;
  const long long y0 = ry < 0.3 ? iy - 1 : iy, y1 = ry > 0.7 ? iy + 1 : iy;
  int best = -1;
  double bestD = cell_ * cell_;
  for (long long x = x0; x <= x1; ++x)
    for (long long y = y0; y <= y1; ++y) {
      auto it = grid_.find(cellKey(x, y));
      if (it == grid_.end()) continue;
      for (int v = it->second; v >= 0; v = gridNext_[v]) {
        const double ds = verts_[v].s - s, dt = verts_[v].t - t;
        const double d = ds * ds + dt * dt;
        if (d <= bestD) {
          bestD = d;
          best = v;
        }
      }
    }
  return best;
}

// p, known to be collinear with a and b, lies strictly between them.
bool Tessellation::strictlyBetween(int p, int a, int b) const {
  const Vert &P = verts_[p], &A = verts_[a], &B = verts_[b];
  return (lexLess(A, P) && lexLess(P, B)) || (lexLess(B, P) && lexLess(P, A));
}

// p lies on segment a-b up to the merge tolerance: within cell_ of its line, and strictly
// between its ends along it.
bool Tessellation::nearSegment(int p, int a, int b, double o) const {
  const Vert &P = verts_[p], &A = verts_[a], &B = verts_[b];
  const double ds = B.s - A.s, dt = B.t - A.t;
  const double len2 = ds * ds + dt * dt;
  if (o != 0.0 && !(std::fabs(o) <= cell_ * std::sqrt(len2))) return false;
  const double along = (P.s - A.s) * ds + (P.t - A.t) * dt;
  if (o == 0.0) return strictlyBetween(p, a, b);
  return along > 0.0 && along < len2;
}

void Tessellation::testPair(std::size_t i, std::size_t j, std::vector<std::vector<int>>& splits) {
  const int a = dedges_[i].a, b = dedges_[i].b, c = dedges_[j].a, d = dedges_[j].b;
  const Vert &A = verts_[a], &B = verts_[b], &C = verts_[c], &D = verts_[d];
  if (a == c || a == d || b == c || b == d) {
    if ((a == c && b == d) || (a == d && b == c)) return;  // the same segment
    // Sharing one endpoint, they can only overlap along a line.
    const int eo = (a == c || a == d) ? b : a;
    const int fo = (c == a || c == b) ? d : c;
    if (nearSegment(fo, a, b, orient(A, B, verts_[fo]))) splits[i].push_back(fo);
    if (nearSegment(eo, c, d, orient(C, D, verts_[eo]))) splits[j].push_back(eo);
    return;
  }
  const double o1 = orient(A, B, C), o2 = orient(A, B, D);
  const double o3 = orient(C, D, A), o4 = orient(C, D, B);
  // An endpoint on (or within the tolerance of) the other segment: split there, no new vertex.
  // Nearly collinear overlapping edges end up split at each other's ends (and merged later)
  // instead of producing ill-conditioned crossings.
  bool touched = false;
  if (nearSegment(c, a, b, o1)) {
    splits[i].push_back(c);
    touched = true;
  }
  if (nearSegment(d, a, b, o2)) {
    splits[i].push_back(d);
    touched = true;
  }
  if (nearSegment(a, c, d, o3)) {
    splits[j].push_back(a);
    touched = true;
  }
  if (nearSegment(b, c, d, o4)) {
    splits[j].push_back(b);
    touched = true;
  }
  if (touched) return;
  if ((o1 >= 0 && o2 >= 0) || (o1 <= 0 && o2 <= 0)) return;
  if ((o3 >= 0 && o4 >= 0) || (o3 <= 0 && o4 <= 0)) return;
  // A proper crossing at parameter tp along a -> b and up along c -> d.
  double tp = o3 / (o3 - o4), up = o1 / (o1 - o2);
  tp = std::min(1.0, std::max(0.0, tp));
  up = std::min(1.0, std::max(0.0, up));
  double s = 0.5 * ((A.s + tp * (B.s - A.s)) + (C.s + up * (D.s - C.s)));
  double t = 0.5 * ((A.t + tp * (B.t - A.t)) + (C.t + up * (D.t - C.t)));
  // Keep the point inside both segments' bounding boxes.
  const double sLo = std::max(std::min(A.s, B.s), std::min(C.s, D.s));
  const double sHi = std::min(std::max(A.s, B.s), std::max(C.s, D.s));
  const double tLo = std::max(std::min(A.t, B.t), std::min(C.t, D.t));
  const double tHi = std::min(std::max(A.t, B.t), std::max(C.t, D.t));
  if (sLo <= sHi) s = std::min(sHi, std::max(sLo, s));
  if (tLo <= tHi) t = std::min(tHi, std::max(tLo, t));
  if (!std::isfinite(s) || !std::isfinite(t)) return;

  int w = vertexNear(s, t);
  if (w < 0) {
    float weights[4] = {static_cast<float>(0.5 * (1.0 - tp)), static_cast<float>(0.5 * tp),
                        static_cast<float>(0.5 * (1.0 - up)), static_cast<float>(0.5 * up)};
    Vert nv;
    nv.s = s;
    nv.t = t;
    for (int k = 0; k < 3; ++k)
      nv.xyz[k] =
          0.5 * ((1.0 - tp) * A.xyz[k] + tp * B.xyz[k]) + 0.5 * ((1.0 - up) * C.xyz[k] + up * D.xyz[k]);
    void* data[4] = {A.data, B.data, C.data, D.data};
    nv.data = hasCombine(tess_) ? callCombine(tess_, nv.xyz, data, weights) : nullptr;
    if (!nv.data && !fatal_) {
      callError(tess_, GLU_TESS_NEED_COMBINE_CALLBACK);
      fatal_ = true;
    }
    w = static_cast<int>(verts_.size());
    verts_.push_back(nv);
    gridInsert(w);
  }
  if (w != a && w != b) splits[i].push_back(w);
  if (w != c && w != d) splits[j].push_back(w);
}

int Tessellation::buildHierarchy(const std::vector<Box>& boxes, std::vector<int>& items,
                                 std::vector<BNode>& nodes, int begin, int end) {
  Box b = boxes[items[begin]];
  for (int k = begin + 1; k < end; ++k) {
    const Box& x = boxes[items[k]];
    b.s0 = std::min(b.s0, x.s0);
    b.t0 = std::min(b.t0, x.t0);
    b.s1 = std::max(b.s1, x.s1);
    b.t1 = std::max(b.t1, x.t1);
  }
  const int id = static_cast<int>(nodes.size());
  nodes.push_back({b, -1, -1, begin, end});
  if (end - begin <= 8) return id;
  const int mid = begin + (end - begin) / 2;
  const bool alongS = b.s1 - b.s0 >= b.t1 - b.t0;
  if (alongS)
    std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                     [&](int x, int y) { return boxes[x].s0 + boxes[x].s1 < boxes[y].s0 + boxes[y].s1; });
  else
    std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                     [&](int x, int y) { return boxes[x].t0 + boxes[x].t1 < boxes[y].t0 + boxes[y].t1; });
  const int left = buildHierarchy(boxes, items, nodes, begin, mid);
  const int right = buildHierarchy(boxes, items, nodes, mid, end);
  nodes[id].left = left;
  nodes[id].right = right;
  return id;
}

void Tessellation::intersectAll() {
  if (dedges_.empty()) return;
  // Hierarchy boxes are widened by this much, far more than the rounding error of the tests.
  const double margin = cell_ * 10.0;
  std::vector<char> dirty(dedges_.size(), 1);
  constexpr int kMaxRounds = 8;
  for (int round = 0; round < kMaxRounds; ++round) {
    mergeDuplicateEdges(dirty);
    const std::size_t m = dedges_.size();
    if (m == 0) return;
    std::vector<Box> boxes(m);
    for (std::size_t i = 0; i < m; ++i) {
      const Vert &A = verts_[dedges_[i].a], &B = verts_[dedges_[i].b];
      boxes[i] = {std::min(A.s, B.s), std::min(A.t, B.t), std::max(A.s, B.s), std::max(A.t, B.t)};
    }
    // Candidate pairs from a bounding-volume hierarchy over the edges, each edge walked down
    // the nodes its segment passes through (so long edges only meet their real neighbours).
    // Every pair of touching edges is found from both sides; it is tested once.
    std::vector<BNode> nodes;
    std::vector<int> items(m);
    for (std::size_t i = 0; i < m; ++i) items[i] = static_cast<int>(i);
    buildHierarchy(boxes, items, nodes, 0, static_cast<int>(m));
    std::vector<std::vector<int>> splits(m);
    std::vector<int> stack;
    for (std::size_t i = 0; i < m; ++i) {
      if (!dirty[i]) continue;
      const Box& bi = boxes[i];
      // (copies: testPair may add vertices)
      const double as = verts_[dedges_[i].a].s, at = verts_[dedges_[i].a].t;
      const double ds = verts_[dedges_[i].b].s - as, dt = verts_[dedges_[i].b].t - at;
      stack.assign(1, 0);
      while (!stack.empty()) {
        const BNode& nd = nodes[stack.back()];
        stack.pop_back();
        const double s0 = nd.box.s0 - margin, t0 = nd.box.t0 - margin;
        const double s1 = nd.box.s1 + margin, t1 = nd.box.t1 + margin;
        if (s0 > bi.s1 || t0 > bi.t1 || bi.s0 > s1 || bi.t0 > t1) continue;
        // The segment's line must pass between the box's corners.
        const double c0 = ds * (t0 - at) - dt * (s0 - as), c1 = ds * (t0 - at) - dt * (s1 - as);
        const double c2 = ds * (t1 - at) - dt * (s0 - as), c3 = ds * (t1 - at) - dt * (s1 - as);
        if ((c0 > 0 && c1 > 0 && c2 > 0 && c3 > 0) || (c0 < 0 && c1 < 0 && c2 < 0 && c3 < 0)) continue;
        if (nd.left >= 0) {
          stack.push_back(nd.left);
          stack.push_back(nd.right);
          continue;
        }
        for (int k = nd.begin; k < nd.end; ++k) {
          const std::size_t j = static_cast<std::size_t>(items[k]);
          if (j == i || (dirty[j] && j < i)) continue;
          const Box& bj = boxes[j];
          if (bj.s0 > bi.s1 + cell_ || bj.t0 > bi.t1 + cell_ || bi.s0 > bj.s1 + cell_ ||
              bi.t0 > bj.t1 + cell_)
            continue;
          testPair(i, j, splits);
        }
      }
    }
    bool any = false;
    std::vector<DEdge> next;
    std::vector<char> nextDirty;
    next.reserve(m);
    nextDirty.reserve(m);
    for (std::size_t i = 0; i < m; ++i) {
      const DEdge e = dedges_[i];
      std::vector<int>& sp = splits[i];
      if (sp.empty()) {
        next.push_back(e);
        nextDirty.push_back(0);
        continue;
      }
      any = true;
      const Vert &A = verts_[e.a], &B = verts_[e.b];
      const double ds = B.s - A.s, dt = B.t - A.t;
      auto param = [&](int v) { return (verts_[v].s - A.s) * ds + (verts_[v].t - A.t) * dt; };
      std::sort(sp.begin(), sp.end(), [&](int x, int y) { return param(x) < param(y); });
      sp.erase(std::unique(sp.begin(), sp.end()), sp.end());
      int prev = e.a;
      for (int v : sp) {
        if (v == prev || v == e.b) continue;
        next.push_back({prev, v, e.w});
        nextDirty.push_back(1);
        prev = v;
      }
      if (prev != e.b) {
        next.push_back({prev, e.b, e.w});
        nextDirty.push_back(1);
      }
    }
    dedges_.swap(next);
    dirty.swap(nextDirty);
    if (!any) break;
  }
  std::vector<char> unused(dedges_.size(), 0);
  mergeDuplicateEdges(unused);
}

// Edges between the same two vertices become one, their windings added; edges whose windings
// cancel are dropped (they change no winding number). Keeps the edge count bounded however
// often collinear edges are split.
void Tessellation::mergeDuplicateEdges(std::vector<char>& dirty) {
  struct Item {
    int a, b, w;
    char dirty;
  };
  std::vector<Item> items(dedges_.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    const DEdge& e = dedges_[i];
    items[i] = e.a < e.b ? Item{e.a, e.b, e.w, dirty[i]} : Item{e.b, e.a, -e.w, dirty[i]};
  }
  std::sort(items.begin(), items.end(),
            [](const Item& p, const Item& q) { return p.a < q.a || (p.a == q.a && p.b < q.b); });
  dedges_.clear();
  dirty.clear();
  for (std::size_t k = 0; k < items.size();) {
    const Item& first = items[k];
    int w = 0;
    char d = 0;
    std::size_t e = k;
    for (; e < items.size() && items[e].a == first.a && items[e].b == first.b; ++e) {
      w += items[e].w;
      d |= items[e].dirty;
    }
    if (w != 0) {
      dedges_.push_back({first.a, first.b, w});
      dirty.push_back(d);
    }
    k = e;
  }
}

// ---- Step 4: the sweep ---------------------------------------------------------------------

void Tessellation::buildGraph() {
  const int nv = static_cast<int>(verts_.size());
  std::vector<int> rank(nv);
  order_.resize(nv);
  for (int i = 0; i < nv; ++i) order_[i] = i;
  std::sort(order_.begin(), order_.end(), [&](int a, int b) {
    return lexLess(verts_[a], verts_[b]) || (!lexLess(verts_[b], verts_[a]) && a < b);
  });
  for (int i = 0; i < nv; ++i) rank[order_[i]] = i;

  // Undirected edges with their windings added; edges whose windings cancel are dropped.
  struct Key {
    int lo, hi, delta;
  };
  std::vector<Key> keys;
  keys.reserve(dedges_.size());
  for (const DEdge& e : dedges_) {
    if (rank[e.a] < rank[e.b])
      keys.push_back({e.a, e.b, e.w});
    else
      keys.push_back({e.b, e.a, -e.w});
  }
  std::sort(keys.begin(), keys.end(),
            [](const Key& x, const Key& y) { return x.lo < y.lo || (x.lo == y.lo && x.hi < y.hi); });
  for (std::size_t k = 0; k < keys.size();) {
    std::size_t e = k;
    int delta = 0;
    while (e < keys.size() && keys[e].lo == keys[k].lo && keys[e].hi == keys[k].hi) delta += keys[e++].delta;
    if (delta != 0) sedges_.push_back({keys[k].lo, keys[k].hi, delta, false});
    k = e;
  }

  rightStart_.assign(nv + 1, 0);
  leftCount_.assign(nv, 0);
  for (const SEdge& e : sedges_) {
    rightStart_[e.lo + 1]++;
    leftCount_[e.hi]++;
  }
  for (int i = 0; i < nv; ++i) rightStart_[i + 1] += rightStart_[i];
  rightEdges_.resize(sedges_.size());
  std::vector<int> fill(rightStart_.begin(), rightStart_.end() - 1);
  for (std::size_t i = 0; i < sedges_.size(); ++i) rightEdges_[fill[sedges_[i].lo]++] = static_cast<int>(i);
  for (int v = 0; v < nv; ++v) {
    // Bottom to top: all these edges point into the half-plane ahead of the sweep line, where
    // the orientation test orders directions.
    std::sort(
        rightEdges_.begin() + rightStart_[v], rightEdges_.begin() + rightStart_[v + 1],
        [&](int x, int y) { return orient(verts_[v], verts_[sedges_[x].hi], verts_[sedges_[y].hi]) > 0.0; });
  }
}

int Tessellation::newPoly(int v) {
  polys_.emplace_back();
  polys_.back().stack.push_back({v, kStart, false});
  return static_cast<int>(polys_.size()) - 1;
}

void Tessellation::emitTri(int a, int b, int c, bool fab, bool fbc, bool fca) {
  tris_.push_back({{a, b, c}, {fab, fbc, fca}});
}

// u joins the monotone piece on the given chain; flag is that of the edge from the previous
// vertex of that chain to u. The standard stack algorithm, one vertex at a time; triangles are
// emitted counter-clockwise.
void Tessellation::addToPoly(int pi, int u, Chain chain, bool flag) {
  if (pi < 0) return;
  std::vector<StackEntry>& S = polys_[pi].stack;
  if (S.size() == 1) {
    S.push_back({u, chain, flag});
    return;
  }
  if (S.back().chain != chain) {
    // u is on the other chain: it sees the whole stack.
    for (std::size_t i = 0; i + 1 < S.size(); ++i) {
      const StackEntry& A = S[i];
      const StackEntry& B = S[i + 1];
      const bool fAu = i == 0 ? flag : false;
      if (B.chain == kLower)
        emitTri(A.v, B.v, u, B.flagPrev, false, fAu);
      else
        emitTri(B.v, A.v, u, B.flagPrev, fAu, false);
    }
    const StackEntry top = S.back();
    S.clear();
    S.push_back(top);
    S.push_back({u, chain, false});
    return;
  }
  // Same chain: cut off the convex corners.
  StackEntry last = S.back();
  S.pop_back();
  bool cur = flag;  // flag of the edge last -> u
  while (!S.empty()) {
    const StackEntry prev = S.back();
    const double o = orient(verts_[prev.v], verts_[last.v], verts_[u]);
    if (chain == kLower ? !(o > 0.0) : !(o < 0.0)) break;
    if (chain == kLower)
      emitTri(prev.v, last.v, u, last.flagPrev, cur, false);
    else
      emitTri(prev.v, u, last.v, false, cur, last.flagPrev);
    cur = false;
    last = prev;
    S.pop_back();
  }
  S.push_back(last);
  S.push_back({u, chain, cur});
}

// u closes the piece (both chains end there).
void Tessellation::finishPoly(int pi, int u, bool flagLo, bool flagHi) {
  if (pi < 0) return;
  std::vector<StackEntry>& S = polys_[pi].stack;
  const std::size_t k = S.size() - 1;
  for (std::size_t i = 0; i < k; ++i) {
    const StackEntry& A = S[i];
    const StackEntry& B = S[i + 1];
    const bool lowerChain = B.chain == kLower;
    const bool fBu = i + 1 == k ? (lowerChain ? flagLo : flagHi) : false;
    const bool fAu = i == 0 ? (lowerChain ? flagHi : flagLo) : false;
    if (lowerChain)
      emitTri(A.v, B.v, u, B.flagPrev, fBu, fAu);
    else
      emitTri(B.v, A.v, u, B.flagPrev, fAu, fBu);
  }
  std::vector<StackEntry>().swap(S);
}

// v lies on the upper boundary of r (r's upper edge ends at v).
void Tessellation::toUpper(Region& r, int v, bool flag) {
  if (r.poly < 0) return;
  if (r.mergeV >= 0) {
    finishPoly(r.poly2, v, false, flag);
    addToPoly(r.poly, v, kUpper, false);
    r.mergeV = -1;
    r.poly2 = -1;
  } else {
    addToPoly(r.poly, v, kUpper, flag);
  }
}

// v lies on the lower boundary of r.
void Tessellation::toLower(Region& r, int v, bool flag) {
  if (r.poly < 0) return;
  if (r.mergeV >= 0) {
    finishPoly(r.poly, v, flag, false);
    addToPoly(r.poly2, v, kLower, false);
    r.poly = r.poly2;
    r.mergeV = -1;
    r.poly2 = -1;
  } else {
    addToPoly(r.poly, v, kLower, flag);
  }
}

// Both boundaries of r end at v.
void Tessellation::finishRegion(Region& r, int v, bool flagLo, bool flagHi) {
  if (r.poly < 0) return;
  if (r.mergeV >= 0) {
    finishPoly(r.poly, v, flagLo, false);
    finishPoly(r.poly2, v, false, flagHi);
  } else {
    finishPoly(r.poly, v, flagLo, flagHi);
  }
  r.poly = r.poly2 = r.mergeV = -1;
}

// v starts edges strictly inside the inside region r: r is cut in two by a diagonal from v to
// its latest vertex (the pending merge vertex if there is one).
void Tessellation::splitRegion(const Region& r, int v, Region& lower, Region& upper) {
  lower = upper = r;
  lower.mergeV = upper.mergeV = -1;
  lower.poly2 = upper.poly2 = -1;
  if (r.poly < 0) return;
  if (r.mergeV >= 0) {
    addToPoly(r.poly, v, kUpper, false);
    addToPoly(r.poly2, v, kLower, false);
    lower.poly = r.poly;
    upper.poly = r.poly2;
    return;
  }
  const StackEntry top = polys_[r.poly].stack.back();
  const bool onLower = polys_[r.poly].stack.size() >= 2 && top.chain == kLower;
  const int q = newPoly(top.v);
  if (onLower) {
    // Everything pending lies above the diagonal; below it a new piece starts at top.
    addToPoly(q, v, kUpper, false);
    addToPoly(r.poly, v, kLower, false);
    lower.poly = q;
    upper.poly = r.poly;
  } else {
    addToPoly(q, v, kLower, false);
    addToPoly(r.poly, v, kUpper, false);
    lower.poly = r.poly;
    upper.poly = q;
  }
}

// Index of the first status edge that is not below v (index 0 is the sentinel).
std::size_t Tessellation::locate(int v) const {
  std::size_t lo = 1, hi = status_.size();
  const Vert& p = verts_[v];
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    const SEdge& e = sedges_[status_[mid].edge];
    if (orient(verts_[e.lo], verts_[e.hi], p) > 0.0)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

// Fallback when the edges ending at v are not found side by side (only possible if rounding
// left two edges crossing): bring them together, the others above them.
std::size_t Tessellation::gatherLeft(int v, std::size_t& count) {
  std::vector<std::size_t> pos;
  for (std::size_t k = 1; k < status_.size(); ++k)
    if (sedges_[status_[k].edge].hi == v) pos.push_back(k);
  count = pos.size();
  if (pos.empty()) return 0;
  const std::size_t first = pos.front(), last = pos.back();
  std::vector<Active> left, others;
  for (std::size_t k = first; k <= last; ++k) {
    if (sedges_[status_[k].edge].hi == v)
      left.push_back(status_[k]);
    else
      others.push_back(status_[k]);
  }
  std::size_t k = first;
  for (const Active& a : left) status_[k++] = a;
  for (const Active& a : others) status_[k++] = a;
  return first;
}

// Inserts v's edges to later vertices at position p; the regions between them start at v, the
// one above the topmost is `top` (a region that continues past v).
void Tessellation::insertRight(std::size_t p, int v, const Region& top) {
  const std::size_t b = rightStart_[v], e = rightStart_[v + 1];
  const GLenum rule = tess_->windingRule;
  int wind = status_[p - 1].reg.wind;
  bool prevInside = status_[p - 1].reg.inside;
  std::vector<Active> ins;
  ins.reserve(e - b);
  for (std::size_t k = b; k < e; ++k) {
    const int ei = rightEdges_[k];
    SEdge& se = sedges_[ei];
    wind += se.delta;
    Region r;
    if (k + 1 == e) {
      r = top;
    } else {
      r.wind = wind;
      r.inside = windingInside(rule, wind);
      if (r.inside && !tess_->boundaryOnly) r.poly = newPoly(v);
    }
    se.flag = prevInside != r.inside;
    if (se.flag && tess_->boundaryOnly) {
      if (r.inside)
        boundary_.emplace_back(se.lo, se.hi);
      else
        boundary_.emplace_back(se.hi, se.lo);
    }
    prevInside = r.inside;
    ins.push_back({ei, r});
  }
  status_.insert(status_.begin() + static_cast<std::ptrdiff_t>(p), ins.begin(), ins.end());
}

void Tessellation::sweep() {
  status_.clear();
  status_.push_back({-1, Region()});
  for (int v : order_) {
    std::size_t left = static_cast<std::size_t>(leftCount_[v]);
    const bool hasRight = rightStart_[v + 1] > rightStart_[v];
    if (left == 0 && !hasRight) continue;  // isolated vertex
    std::size_t p = locate(v);
    if (left > 0) {
      bool together = p + left <= status_.size();
      for (std::size_t k = 0; together && k < left; ++k)
        if (sedges_[status_[p + k].edge].hi != v) together = false;
      if (!together) {
        const std::size_t q = gatherLeft(v, left);
        if (left > 0)
          p = q;
        else if (!hasRight)
          continue;
      }
    }
    if (left > 0) {
      Region below = status_[p - 1].reg;
      Region above = status_[p + left - 1].reg;
      for (std::size_t k = p; k + 1 < p + left; ++k)
        if (status_[k].reg.inside)
          finishRegion(status_[k].reg, v, sedges_[status_[k].edge].flag, sedges_[status_[k + 1].edge].flag);
      if (below.inside) toUpper(below, v, sedges_[status_[p].edge].flag);
      if (above.inside) toLower(above, v, sedges_[status_[p + left - 1].edge].flag);
      status_.erase(status_.begin() + static_cast<std::ptrdiff_t>(p),
                    status_.begin() + static_cast<std::ptrdiff_t>(p + left));
      if (!hasRight) {
        // A merge: the regions below and above become one.
        Region merged = below;
        if (below.inside && above.inside && below.poly >= 0 && above.poly >= 0) {
          merged.mergeV = v;
          merged.poly2 = above.poly;
        }
        status_[p - 1].reg = merged;
      } else {
        status_[p - 1].reg = below;
        insertRight(p, v, above);
      }
    } else {
      const Region r = status_[p - 1].reg;
      Region lower = r, upper = r;
      if (r.inside) splitRegion(r, v, lower, upper);
      status_[p - 1].reg = lower;
      insertRight(p, v, upper);
    }
  }
}

// ---- Output ----------------------------------------------------------------------------------

void Tessellation::outputTriangles() {
  if (tris_.empty()) return;
  GLUtesselator* t = tess_;
  const bool flags = t->edgeFlagData || t->edgeFlag;
  if (t->beginData)
    t->beginData(GL_TRIANGLES, t->polygonData);
  else if (t->begin)
    t->begin(GL_TRIANGLES);
  int lastFlag = -1;
  for (const Triangle& tri : tris_) {
    for (int k = 0; k < 3; ++k) {
      if (flags && static_cast<int>(tri.flag[k]) != lastFlag) {
        lastFlag = tri.flag[k];
        const GLboolean f = tri.flag[k] ? GL_TRUE : GL_FALSE;
        if (t->edgeFlagData)
          t->edgeFlagData(f, t->polygonData);
        else
          t->edgeFlag(f);
      }
      void* data = verts_[tri.v[k]].data;
      if (t->vertexData)
        t->vertexData(data, t->polygonData);
      else if (t->vertex)
        t->vertex(data);
    }
  }
  if (t->endData)
    t->endData(t->polygonData);
  else if (t->end)
    t->end();
}

void Tessellation::outputBoundary() {
  if (boundary_.empty()) return;
  GLUtesselator* t = tess_;
  const std::size_t n = boundary_.size();
  // Outgoing boundary edges per vertex.
  std::unordered_map<int, std::vector<std::size_t>> out;
  for (std::size_t i = 0; i < n; ++i) out[boundary_[i].first].push_back(i);
  std::vector<char> used(n, 0);
  std::vector<int> loop;
  for (std::size_t start = 0; start < n; ++start) {
    if (used[start]) continue;
    loop.clear();
    std::size_t cur = start;
    for (;;) {
      used[cur] = 1;
      loop.push_back(boundary_[cur].first);
      const int from = boundary_[cur].first, at = boundary_[cur].second;
      // Next: the edge out of `at` met first turning clockwise from the way back, which keeps
      // the interior on the left and separates loops that touch at a vertex. Reaching the
      // first edge again closes the loop.
      const double rs = verts_[from].s - verts_[at].s, rt = verts_[from].t - verts_[at].t;
      std::size_t best = n, bestUnused = n;
      double bestAngle = 0.0, bestUnusedAngle = 0.0;
      auto it = out.find(at);
      if (it != out.end())
        for (std::size_t cand : it->second) {
          if (used[cand] && cand != start) continue;
          const int to = boundary_[cand].second;
          const double ds = verts_[to].s - verts_[at].s, dt = verts_[to].t - verts_[at].t;
          double a = std::atan2(ds * rt - dt * rs, ds * rs + dt * rt);  // clockwise from back
          if (a <= 0.0) a += 2.0 * 3.14159265358979323846;
          if (best == n || a < bestAngle) {
            best = cand;
            bestAngle = a;
          }
          if (cand != start && (bestUnused == n || a < bestUnusedAngle)) {
            bestUnused = cand;
            bestUnusedAngle = a;
          }
        }
      if (best == start) break;
      best = bestUnused;
      if (best == n) break;
      cur = best;
    }
    if (t->beginData)
      t->beginData(GL_LINE_LOOP, t->polygonData);
    else if (t->begin)
      t->begin(GL_LINE_LOOP);
    for (int v : loop) {
      if (t->vertexData)
        t->vertexData(verts_[v].data, t->polygonData);
      else if (t->vertex)
        t->vertex(verts_[v].data);
    }
    if (t->endData)
      t->endData(t->polygonData);
    else if (t->end)
      t->end();
  }
}

// ---------------------------------------------------------------------------------------------
// The state machine (section 5.1): calls out of order report the missing call through the
// error callback and then behave as if it had been made (a missing gluTessEndPolygon discards
// the polygon).

void resetPolygon(GLUtesselator* t) {
  t->vertices.clear();
  t->contourStarts.clear();
  t->state = State::Dormant;
}

void beginPolygon(GLUtesselator* t, void* data);
void beginContour(GLUtesselator* t);
void endContour(GLUtesselator* t);

void gotoState(GLUtesselator* t, State target) {
  while (t->state != target) {
    if (t->state < target) {
      if (t->state == State::Dormant) {
        callError(t, GLU_TESS_MISSING_BEGIN_POLYGON);
        beginPolygon(t, nullptr);
      } else {
        callError(t, GLU_TESS_MISSING_BEGIN_CONTOUR);
        beginContour(t);
      }
    } else {
      if (t->state == State::InContour) {
        callError(t, GLU_TESS_MISSING_END_CONTOUR);
        endContour(t);
      } else {
        callError(t, GLU_TESS_MISSING_END_POLYGON);
        resetPolygon(t);
      }
    }
  }
}

void beginPolygon(GLUtesselator* t, void* data) {
  gotoState(t, State::Dormant);
  t->state = State::InPolygon;
  t->polygonData = data;
  t->vertices.clear();
  t->contourStarts.clear();
}

void beginContour(GLUtesselator* t) {
  gotoState(t, State::InPolygon);
  t->state = State::InContour;
  t->contourStarts.push_back(t->vertices.size());
}

void endContour(GLUtesselator* t) {
  gotoState(t, State::InContour);
  t->state = State::InPolygon;
}

}  // namespace
}  // namespace tessel_glu_tess

using namespace tessel_glu_tess;

extern "C" {

GLUtesselator* GLAPIENTRY gluNewTess(void) { return new (std::nothrow) GLUtesselator(); }

void GLAPIENTRY gluDeleteTess(GLUtesselator* tess) {
  if (!tess) return;
  gotoState(tess, State::Dormant);
  delete tess;
}

void GLAPIENTRY gluTessBeginPolygon(GLUtesselator* tess, GLvoid* data) {
  if (!tess) return;
  beginPolygon(tess, data);
}

void GLAPIENTRY gluTessBeginContour(GLUtesselator* tess) {
  if (!tess) return;
  beginContour(tess);
}

void GLAPIENTRY gluTessVertex(GLUtesselator* tess, GLdouble* location, GLvoid* data) {
  if (!tess || !location) return;
  gotoState(tess, State::InContour);
  InputVertex v;
  bool tooLarge = false;
  for (int k = 0; k < 3; ++k) {
    double x = location[k];
    if (x < -GLU_TESS_MAX_COORD) {
      x = -GLU_TESS_MAX_COORD;
      tooLarge = true;
    } else if (x > GLU_TESS_MAX_COORD) {
      x = GLU_TESS_MAX_COORD;
      tooLarge = true;
    } else if (x != x) {  // NaN: nothing sensible to clamp to
      x = 0.0;
      tooLarge = true;
    }
    v.xyz[k] = x;
  }
  if (tooLarge) callError(tess, GLU_TESS_COORD_TOO_LARGE);
  v.data = data;
  try {
    tess->vertices.push_back(v);
  } catch (const std::bad_alloc&) {
    callError(tess, GLU_OUT_OF_MEMORY);
  }
}

void GLAPIENTRY gluTessEndContour(GLUtesselator* tess) {
  if (!tess) return;
  endContour(tess);
}

void GLAPIENTRY gluTessEndPolygon(GLUtesselator* tess) {
  if (!tess) return;
  gotoState(tess, State::InPolygon);
  tess->state = State::Dormant;
  try {
    Tessellation(tess).run();
  } catch (const std::bad_alloc&) {
    callError(tess, GLU_OUT_OF_MEMORY);
  }
  resetPolygon(tess);
  tess->polygonData = nullptr;
}

void GLAPIENTRY gluTessCallback(GLUtesselator* tess, GLenum which, _GLUfuncptr fn) {
  if (!tess) return;
  switch (which) {
    case GLU_TESS_BEGIN: tess->begin = reinterpret_cast<BeginFn>(fn); break;
    case GLU_TESS_BEGIN_DATA: tess->beginData = reinterpret_cast<BeginDataFn>(fn); break;
    case GLU_TESS_EDGE_FLAG: tess->edgeFlag = reinterpret_cast<EdgeFlagFn>(fn); break;
    case GLU_TESS_EDGE_FLAG_DATA: tess->edgeFlagData = reinterpret_cast<EdgeFlagDataFn>(fn); break;
    case GLU_TESS_VERTEX: tess->vertex = reinterpret_cast<VertexFn>(fn); break;
    case GLU_TESS_VERTEX_DATA: tess->vertexData = reinterpret_cast<VertexDataFn>(fn); break;
    case GLU_TESS_END: tess->end = reinterpret_cast<EndFn>(fn); break;
    case GLU_TESS_END_DATA: tess->endData = reinterpret_cast<EndDataFn>(fn); break;
    case GLU_TESS_ERROR: tess->error = reinterpret_cast<ErrorFn>(fn); break;
    case GLU_TESS_ERROR_DATA: tess->errorData = reinterpret_cast<ErrorDataFn>(fn); break;
    case GLU_TESS_COMBINE: tess->combine = reinterpret_cast<CombineFn>(fn); break;
    case GLU_TESS_COMBINE_DATA: tess->combineData = reinterpret_cast<CombineDataFn>(fn); break;
    default: callError(tess, GLU_INVALID_ENUM); break;
  }
}

void GLAPIENTRY gluTessProperty(GLUtesselator* tess, GLenum which, GLdouble value) {
  if (!tess) return;
  switch (which) {
    case GLU_TESS_WINDING_RULE: {
      const bool valid = value == GLU_TESS_WINDING_ODD || value == GLU_TESS_WINDING_NONZERO ||
                         value == GLU_TESS_WINDING_POSITIVE || value == GLU_TESS_WINDING_NEGATIVE ||
                         value == GLU_TESS_WINDING_ABS_GEQ_TWO;
      if (!valid) {
        callError(tess, GLU_INVALID_VALUE);
        return;
      }
      tess->windingRule = static_cast<GLenum>(value);
      return;
    }
    case GLU_TESS_BOUNDARY_ONLY: tess->boundaryOnly = value != 0.0; return;
    case GLU_TESS_TOLERANCE:
      if (!(value >= 0.0 && value <= 1.0)) {
        callError(tess, GLU_INVALID_VALUE);
        return;
      }
      tess->tolerance = value;
      return;
    default: callError(tess, GLU_INVALID_ENUM); return;
  }
}

void GLAPIENTRY gluGetTessProperty(GLUtesselator* tess, GLenum which, GLdouble* value) {
  if (!tess || !value) return;
  switch (which) {
    case GLU_TESS_WINDING_RULE: *value = tess->windingRule; return;
    case GLU_TESS_BOUNDARY_ONLY: *value = tess->boundaryOnly ? 1.0 : 0.0; return;
    case GLU_TESS_TOLERANCE: *value = tess->tolerance; return;
    default:
      *value = 0.0;
      callError(tess, GLU_INVALID_ENUM);
      return;
  }
}

void GLAPIENTRY gluTessNormal(GLUtesselator* tess, GLdouble x, GLdouble y, GLdouble z) {
  if (!tess) return;
  tess->normal[0] = x;
  tess->normal[1] = y;
  tess->normal[2] = z;
}

// GLU 1.1 (section 5.7): a polygon is begun with its first contour open; the contour type
// given to gluNextContour is ignored, the winding rule decides.
void GLAPIENTRY gluBeginPolygon(GLUtesselator* tess) {
  gluTessBeginPolygon(tess, nullptr);
  gluTessBeginContour(tess);
}

void GLAPIENTRY gluNextContour(GLUtesselator* tess, GLenum type) {
  (void)type;
  gluTessEndContour(tess);
  gluTessBeginContour(tess);
}

void GLAPIENTRY gluEndPolygon(GLUtesselator* tess) {
  gluTessEndContour(tess);
  gluTessEndPolygon(tess);
}

}  // extern "C"
