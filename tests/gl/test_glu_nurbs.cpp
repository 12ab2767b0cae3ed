// GLU NURBS (src/glu/nurbs.cpp) through the C entry points: properties, the tessellator mode's
// output measured (vertices on the surface, normals, the area a trimmed surface keeps), the
// renderer mode's pixels, and the GLU_NURBS_ERROR codes of bad input.
#include <GL/gl.h>
#include <GL/glu.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "../../src/gl/context.hpp"

namespace {

struct NurbsTest : ::testing::Test {
  tessel::gl::Context ctx{64, 64, true, true, true};
  GLUnurbs* nurb = nullptr;
  void SetUp() override {
    tessel::gl::make_current(&ctx);
    nurb = gluNewNurbsRenderer();
    errors().clear();
    gluNurbsCallback(nurb, GLU_NURBS_ERROR, reinterpret_cast<_GLUfuncptr>(&on_error));
  }
  void TearDown() override {
    gluDeleteNurbsRenderer(nurb);
    tessel::gl::make_current(nullptr);
  }
  static std::vector<GLenum>& errors() {
    static std::vector<GLenum> e;
    return e;
  }
  static void GLAPIENTRY on_error(GLenum e) { errors().push_back(e); }
};

// What the tessellator mode hands out: primitives with their vertices and normals.
struct Prim {
  GLenum type;
  std::vector<std::array<float, 3>> v, n;
};
struct Capture {
  std::vector<Prim> prims;
  static void GLAPIENTRY begin(GLenum t, void* self) {
    static_cast<Capture*>(self)->prims.push_back({t, {}, {}});
  }
  static void GLAPIENTRY vertex(GLfloat* p, void* self) {
    static_cast<Capture*>(self)->prims.back().v.push_back({p[0], p[1], p[2]});
  }
  static void GLAPIENTRY normal(GLfloat* p, void* self) {
    static_cast<Capture*>(self)->prims.back().n.push_back({p[0], p[1], p[2]});
  }
  static void GLAPIENTRY end(void*) {}
  void attach(GLUnurbs* n) {
    gluNurbsProperty(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
    gluNurbsCallbackData(n, this);
    gluNurbsCallback(n, GLU_NURBS_BEGIN_DATA, reinterpret_cast<_GLUfuncptr>(&begin));
    gluNurbsCallback(n, GLU_NURBS_VERTEX_DATA, reinterpret_cast<_GLUfuncptr>(&vertex));
    gluNurbsCallback(n, GLU_NURBS_NORMAL_DATA, reinterpret_cast<_GLUfuncptr>(&normal));
    gluNurbsCallback(n, GLU_NURBS_END_DATA, reinterpret_cast<_GLUfuncptr>(&end));
  }
  // The area (in x, y) covered by the triangles and quad strips.
  double area() const {
    double a = 0;
    auto tri = [&](const std::array<float, 3>& p, const std::array<float, 3>& q,
                   const std::array<float, 3>& r) {
      a += 0.5 * std::fabs(double(q[0] - p[0]) * (r[1] - p[1]) - double(r[0] - p[0]) * (q[1] - p[1]));
    };
    for (const Prim& p : prims) {
      if (p.type == GL_TRIANGLES)
        for (size_t i = 0; i + 2 < p.v.size(); i += 3) tri(p.v[i], p.v[i + 1], p.v[i + 2]);
      if (p.type == GL_QUAD_STRIP)
        for (size_t i = 0; i + 3 < p.v.size(); i += 2) {
          tri(p.v[i], p.v[i + 1], p.v[i + 2]);
          tri(p.v[i + 1], p.v[i + 3], p.v[i + 2]);
        }
    }
    return a;
  }
  size_t vertices() const {
    size_t k = 0;
    for (const Prim& p : prims) k += p.v.size();
    return k;
  }
};

// A flat bicubic patch over [0, 1]^2 in x, y (z = 0) with interior knots: x = u, y = v.
struct FlatPatch {
  GLfloat knots[9] = {0, 0, 0, 0, 0.5f, 1, 1, 1, 1};
  GLfloat ctl[5][5][3];
  FlatPatch() {
    // The Greville abscissae of the knots make the spline the identity map.
    const float g[5] = {0, 1.0f / 6, 0.5f, 5.0f / 6, 1};
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j) {
        ctl[i][j][0] = g[i];
        ctl[i][j][1] = g[j];
        ctl[i][j][2] = 0;
      }
  }
  void draw(GLUnurbs* n) {
    gluNurbsSurface(n, 9, knots, 9, knots, 15, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
  }
};

TEST_F(NurbsTest, PropertiesHaveTheSpecificationsDefaultsAndKeepValues) {
  GLfloat v = -1;
  gluGetNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, &v);
  EXPECT_EQ(v, 50.0f);
  gluGetNurbsProperty(nurb, GLU_PARAMETRIC_TOLERANCE, &v);
  EXPECT_EQ(v, 0.5f);
  gluGetNurbsProperty(nurb, GLU_U_STEP, &v);
  EXPECT_EQ(v, 100.0f);
  gluGetNurbsProperty(nurb, GLU_DISPLAY_MODE, &v);
  EXPECT_EQ(GLenum(v), GLenum(GLU_FILL));
  gluGetNurbsProperty(nurb, GLU_SAMPLING_METHOD, &v);
  EXPECT_EQ(GLenum(v), GLenum(GLU_PATH_LENGTH));
  gluGetNurbsProperty(nurb, GLU_AUTO_LOAD_MATRIX, &v);
  EXPECT_EQ(v, 1.0f);
  gluGetNurbsProperty(nurb, GLU_CULLING, &v);
  EXPECT_EQ(v, 0.0f);
  gluGetNurbsProperty(nurb, GLU_NURBS_MODE, &v);
  EXPECT_EQ(GLenum(v), GLenum(GLU_NURBS_RENDERER));
  gluNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, 12.5f);
  gluGetNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, &v);
  EXPECT_EQ(v, 12.5f);
  EXPECT_TRUE(errors().empty());
  // A bad value changes nothing; a bad property is NURBS error 26.
  gluNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, -1.0f);
  gluNurbsProperty(nurb, GLU_DISPLAY_MODE, 12345.0f);
  gluNurbsProperty(nurb, GLU_U_STEP, std::numeric_limits<float>::quiet_NaN());
  gluGetNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, &v);
  EXPECT_EQ(v, 12.5f);
  gluNurbsProperty(nurb, 4242, 1.0f);
  const std::vector<GLenum> want = {GLU_INVALID_VALUE, GLU_INVALID_VALUE, GLU_INVALID_VALUE,
                                    GLU_NURBS_ERROR26};
  EXPECT_EQ(errors(), want);
}

TEST_F(NurbsTest, DomainDistanceGridLiesOnTheSurfaceWithUnitNormals) {
  Capture cap;
  cap.attach(nurb);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(nurb, GLU_U_STEP, 8);  // 4 steps a span of 0.5
  gluNurbsProperty(nurb, GLU_V_STEP, 6);  // 3
  FlatPatch p;
  gluBeginSurface(nurb);
  p.draw(nurb);
  gluEndSurface(nurb);
  ASSERT_TRUE(errors().empty());
  // Four rectangles, each 3 rows of quad strips of 5 vertex pairs.
  ASSERT_EQ(cap.prims.size(), 12u);
  for (const Prim& pr : cap.prims) {
    EXPECT_EQ(pr.type, GLenum(GL_QUAD_STRIP));
    ASSERT_EQ(pr.v.size(), 10u);
    ASSERT_EQ(pr.n.size(), 10u);
    for (size_t i = 0; i < pr.v.size(); ++i) {
      // Grid points: u in steps of 1/8, v of 1/6 (x = u, y = v on this patch).
      EXPECT_NEAR(pr.v[i][0] * 8, std::round(pr.v[i][0] * 8), 1e-4);
      EXPECT_NEAR(pr.v[i][1] * 6, std::round(pr.v[i][1] * 6), 1e-4);
      EXPECT_EQ(pr.v[i][2], 0.0f);
      EXPECT_NEAR(std::fabs(pr.n[i][2]), 1.0f, 1e-6);
    }
  }
  EXPECT_NEAR(cap.area(), 1.0, 1e-6);
}

TEST_F(NurbsTest, TrimmingKeepsTheAreaInsideTheLoops) {
  Capture cap;
  cap.attach(nurb);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(nurb, GLU_U_STEP, 20);
  gluNurbsProperty(nurb, GLU_V_STEP, 20);
  FlatPatch p;
  // Outer square 0.1..0.9 (counter-clockwise), a square hole 0.2..0.4 (clockwise) and a
  // triangular island inside a hole 0.5..0.85, made of a pwl piece and a NURBS piece.
  GLfloat outer[5][2] = {{0.1f, 0.1f}, {0.9f, 0.1f}, {0.9f, 0.9f}, {0.1f, 0.9f}, {0.1f, 0.1f}};
  GLfloat hole[5][2] = {{0.2f, 0.2f}, {0.2f, 0.4f}, {0.4f, 0.4f}, {0.4f, 0.2f}, {0.2f, 0.2f}};
  GLfloat hole2[5][2] = {{0.5f, 0.5f}, {0.5f, 0.85f}, {0.85f, 0.85f}, {0.85f, 0.5f}, {0.5f, 0.5f}};
  GLfloat island_a[3][2] = {{0.6f, 0.6f}, {0.8f, 0.6f}, {0.7f, 0.8f}};
  GLfloat island_b[2][2] = {{0.7f, 0.8f}, {0.6f, 0.6f}};  // as an order-2 NURBS curve
  GLfloat lknots[4] = {0, 0, 1, 1};
  gluBeginSurface(nurb);
  p.draw(nurb);
  gluBeginTrim(nurb);
  gluPwlCurve(nurb, 5, &outer[0][0], 2, GLU_MAP1_TRIM_2);
  gluEndTrim(nurb);
  gluBeginTrim(nurb);
  gluPwlCurve(nurb, 5, &hole[0][0], 2, GLU_MAP1_TRIM_2);
  gluEndTrim(nurb);
  gluBeginTrim(nurb);
  gluPwlCurve(nurb, 5, &hole2[0][0], 2, GLU_MAP1_TRIM_2);
  gluEndTrim(nurb);
  gluBeginTrim(nurb);
  gluPwlCurve(nurb, 3, &island_a[0][0], 2, GLU_MAP1_TRIM_2);
  gluNurbsCurve(nurb, 4, lknots, 2, &island_b[0][0], 2, GLU_MAP1_TRIM_2);
  gluEndTrim(nurb);
  gluEndSurface(nurb);
  ASSERT_TRUE(errors().empty());
  const double want = 0.8 * 0.8 - 0.2 * 0.2 - 0.35 * 0.35 + 0.5 * 0.2 * 0.2;
  EXPECT_NEAR(cap.area(), want, 1e-5);
}

TEST_F(NurbsTest, OnlyHolesCutTheWholeDomainAndACircleKeepsItsArea) {
  Capture cap;
  cap.attach(nurb);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(nurb, GLU_U_STEP, 64);
  gluNurbsProperty(nurb, GLU_V_STEP, 64);
  FlatPatch p;
  // A clockwise circle of radius 0.25 around (0.5, 0.5): rational quadratic, 9 points.
  GLfloat circle[9][3];
  GLfloat knots[12] = {0, 0, 0, 0.25f, 0.25f, 0.5f, 0.5f, 0.75f, 0.75f, 1, 1, 1};
  const float dx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, dy[9] = {0, -1, -1, -1, 0, 1, 1, 1, 0};
  for (int i = 0; i < 9; ++i) {
    const float w = (i % 2) ? 0.70710678f : 1.0f;
    circle[i][0] = (0.5f + 0.25f * dx[i]) * w;
    circle[i][1] = (0.5f + 0.25f * dy[i]) * w;
    circle[i][2] = w;
  }
  gluBeginSurface(nurb);
  p.draw(nurb);
  gluBeginTrim(nurb);
  gluNurbsCurve(nurb, 12, knots, 3, &circle[0][0], 3, GLU_MAP1_TRIM_3);
  gluEndTrim(nurb);
  gluEndSurface(nurb);
  ASSERT_TRUE(errors().empty());
  const double pi = 3.14159265358979;
  EXPECT_NEAR(cap.area(), 1.0 - pi * 0.0625, 2e-3);
  EXPECT_GT(cap.area(), 1.0 - pi * 0.0625);  // the polygon inscribed in the circle is smaller
}

TEST_F(NurbsTest, CurvesGiveLineStripsAtTheDomainDistanceCount) {
  Capture cap;
  cap.attach(nurb);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(nurb, GLU_U_STEP, 5);
  GLfloat ctl[4][3] = {{0, 0, 0}, {1, 2, 0}, {2, -2, 0}, {3, 0, 0}};
  GLfloat knots[8] = {0, 0, 0, 0, 2, 2, 2, 2};
  gluBeginCurve(nurb);
  gluNurbsCurve(nurb, 8, knots, 3, &ctl[0][0], 4, GL_MAP1_VERTEX_3);
  gluEndCurve(nurb);
  ASSERT_TRUE(errors().empty());
  ASSERT_EQ(cap.prims.size(), 1u);
  EXPECT_EQ(cap.prims[0].type, GLenum(GL_LINE_STRIP));
  ASSERT_EQ(cap.prims[0].v.size(), 12u);  // floor(5 * 2) + 1 steps, as the reference GLU
  EXPECT_EQ(cap.prims[0].v.front()[0], 0.0f);
  EXPECT_NEAR(cap.prims[0].v.back()[0], 3.0f, 1e-6);
  // x runs linearly (control x 0, 1, 2, 3): the sixth point is at 5/11 of the way.
  EXPECT_NEAR(cap.prims[0].v[5][0], 15.0 / 11.0, 1e-5);
}

TEST_F(NurbsTest, RendererModeDrawsThroughTheEvaluators) {
  // The flat patch, scaled to cover the viewport, drawn filled in white: every pixel is set.
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 1, 0, 1, -1, 1);
  glColor3f(1, 1, 1);
  FlatPatch p;
  gluBeginSurface(nurb);
  p.draw(nurb);
  gluEndSurface(nurb);
  glFinish();
  std::vector<unsigned char> px(64 * 64 * 4);
  glReadPixels(0, 0, 64, 64, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  size_t white = 0;
  for (size_t i = 0; i < px.size(); i += 4) white += px[i] == 255;
  EXPECT_EQ(white, size_t(64 * 64));
  EXPECT_TRUE(errors().empty());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // The evaluator state is as before (GL_EVAL_BIT pushed and popped).
  EXPECT_FALSE(glIsEnabled(GL_MAP2_VERTEX_3));
}

TEST_F(NurbsTest, BadInputIsANurbsError) {
  FlatPatch p;
  GLfloat knots[9] = {0, 0, 0, 0, 0.5f, 1, 1, 1, 1};
  auto last = [] { return errors().empty() ? GLenum(0) : errors().back(); };
  // Order above GL_MAX_EVAL_ORDER (8), too few knots, decreasing, multiplicity, NaN.
  gluBeginSurface(nurb);
  gluNurbsSurface(nurb, 9, knots, 9, knots, 15, 3, &p.ctl[0][0][0], 9, 4, GL_MAP2_VERTEX_3);
  EXPECT_EQ(last(), GLenum(GLU_NURBS_ERROR1));
  gluNurbsSurface(nurb, 7, knots, 9, knots, 15, 3, &p.ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
  EXPECT_EQ(last(), GLenum(GLU_NURBS_ERROR2));
  GLfloat down[9] = {0, 0, 0, 0, 0.5f, 0.4f, 1, 1, 1};
  gluNurbsSurface(nurb, 9, down, 9, knots, 15, 3, &p.ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
  EXPECT_EQ(last(), GLenum(GLU_NURBS_ERROR4));
  GLfloat many[9] = {0, 0, 0, 0, 0, 1, 1, 1, 1};
  gluNurbsSurface(nurb, 9, many, 9, knots, 15, 3, &p.ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
  EXPECT_EQ(last(), GLenum(GLU_NURBS_ERROR5));
  GLfloat nan[9] = {0, 0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 1, 1, 1, 1};
  gluNurbsSurface(nurb, 9, nan, 9, knots, 15, 3, &p.ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
  EXPECT_EQ(last(), GLenum(GLU_NURBS_ERROR4));
  gluNurbsSurface(nurb, 9, knots, 9, knots, 15, 3, nullptr, 4, 4, GL_MAP2_VERTEX_3);
  EXPECT_EQ(last(), GLenum(GLU_NURBS_ERROR36));
  gluNurbsSurface(nurb, 9, knots, 9, knots, 15, 3, &p.ctl[0][0][0], 4, 4, GL_MAP1_VERTEX_3);
  EXPECT_EQ(last(), GLenum(GLU_NURBS_ERROR35));
  gluEndSurface(nurb);
  // Out-of-order calls.
  errors().clear();
  gluEndSurface(nurb);
  gluEndCurve(nurb);
  gluBeginTrim(nurb);
  gluEndTrim(nurb);
  GLfloat pts[2][2] = {{0, 0}, {1, 1}};
  gluPwlCurve(nurb, 2, &pts[0][0], 2, GLU_MAP1_TRIM_2);
  gluBeginSurface(nurb);
  gluBeginSurface(nurb);
  gluEndSurface(nurb);  // after an error nothing is drawn, and nothing more reported
  gluBeginSurface(nurb);
  gluEndSurface(nurb);  // no vertex map
  const std::vector<GLenum> want = {GLU_NURBS_ERROR13, GLU_NURBS_ERROR7,  GLU_NURBS_ERROR15,
                                    GLU_NURBS_ERROR17, GLU_NURBS_ERROR19, GLU_NURBS_ERROR27,
                                    GLU_NURBS_ERROR8};
  EXPECT_EQ(errors(), want);
  // An open trimming loop, and a duplicate pwl point.
  errors().clear();
  GLfloat open[3][2] = {{0.1f, 0.1f}, {0.9f, 0.1f}, {0.9f, 0.9f}};
  gluBeginSurface(nurb);
  p.draw(nurb);
  gluBeginTrim(nurb);
  gluPwlCurve(nurb, 3, &open[0][0], 2, GLU_MAP1_TRIM_2);
  gluEndTrim(nurb);
  gluEndSurface(nurb);
  EXPECT_EQ(last(), GLenum(GLU_NURBS_ERROR31));
  GLfloat dup[3][2] = {{0.1f, 0.1f}, {0.1f, 0.1f}, {0.9f, 0.1f}};
  gluBeginSurface(nurb);
  p.draw(nurb);
  gluBeginTrim(nurb);
  gluPwlCurve(nurb, 3, &dup[0][0], 2, GLU_MAP1_TRIM_2);
  gluEndTrim(nurb);
  gluEndSurface(nurb);
  // The duplicate is error 37; the loop is then empty (error 18).
  EXPECT_EQ(errors(), (std::vector<GLenum>{GLU_NURBS_ERROR31, GLU_NURBS_ERROR37, GLU_NURBS_ERROR18}));
  EXPECT_STREQ(reinterpret_cast<const char*>(gluErrorString(GLU_NURBS_ERROR31)), "unconnected trim curves");
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(NurbsTest, HugeSamplingIsBoundedAndNanControlPointsDoNotHang) {
  Capture cap;
  cap.attach(nurb);
  FlatPatch p;
  p.ctl[2][2][0] = std::numeric_limits<float>::quiet_NaN();
  p.ctl[1][3][2] = 1e30f;
  for (GLenum method : {GLU_PATH_LENGTH, GLU_PARAMETRIC_ERROR, GLU_DOMAIN_DISTANCE, GLU_OBJECT_PATH_LENGTH,
                        GLU_OBJECT_PARAMETRIC_ERROR}) {
    cap.prims.clear();
    gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLfloat(method));
    gluNurbsProperty(nurb, GLU_U_STEP, 1e30f);
    gluNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, 1e-30f);
    gluNurbsProperty(nurb, GLU_PARAMETRIC_TOLERANCE, 1e-30f);
    gluBeginSurface(nurb);
    p.draw(nurb);
    gluEndSurface(nurb);
    EXPECT_GT(cap.vertices(), 0u) << method;
    EXPECT_LE(cap.vertices(), size_t(4) << 20) << method;
  }
  EXPECT_TRUE(errors().empty());
}

}  // namespace
