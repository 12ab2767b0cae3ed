/* 40_glu_nurbs: GLU NURBS (GLU 1.3 chapter 7). Top left: a lit bicubic NURBS surface with
 * two spans each way (interior knot 0.5), GL_AUTO_NORMAL, GLU_DOMAIN_DISTANCE sampling. Top
 * right: a rational surface (GL_MAP2_VERTEX_4) with a GL_MAP2_COLOR_4 map whose knots differ
 * from the vertex map's, unlit. Bottom left: a trimmed surface: an outer piecewise linear loop
 * (counter-clockwise), a hole made of a NURBS circle (clockwise), and a triangular island inside
 * a square hole, path-length sampling at 4 pixels. Bottom right: NURBS curves, a
 * rational quadratic circle and a cubic with a colour map, and the same surface as top left in
 * GLU_OUTLINE_POLYGON mode. */
#include <GL/glut.h>

static const int W = 400, H = 320;

static GLfloat ctl[5][5][3];
static GLfloat ctl4[4][4][4];
static GLfloat colours[2][2][4] = {{{1, 0.2f, 0.2f, 1}, {0.2f, 1, 0.2f, 1}},
                                   {{0.2f, 0.3f, 1, 1}, {1, 1, 0.3f, 1}}};
static GLUnurbs* nurb;

static void init(void) {
  for (int u = 0; u < 5; ++u)
    for (int v = 0; v < 5; ++v) {
      ctl[u][v][0] = -1.6f + 0.8f * u;
      ctl[u][v][1] = -1.6f + 0.8f * v;
      ctl[u][v][2] = (u >= 1 && u <= 3 && v >= 1 && v <= 3) ? ((u == 2 && v == 2) ? 1.6f : 0.8f) : -0.6f;
    }
  for (int u = 0; u < 4; ++u)
    for (int v = 0; v < 4; ++v) {
      const float w = (u == 1 || u == 2) && (v == 1 || v == 2) ? 2.0f : 1.0f;
      ctl4[u][v][0] = (-1.2f + 0.8f * u) * w;
      ctl4[u][v][1] = (-1.2f + 0.8f * v) * w;
      ctl4[u][v][2] = 0.3f * (float)((u + v) % 3) * w;
      ctl4[u][v][3] = w;
    }
  nurb = gluNewNurbsRenderer();
}

static void camera(int x, int y) {
  glViewport(x, y, W / 2, H / 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)W / H, 2.0, 12.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0, -4.5, 4.5, 0, 0, 0, 0, 0, 1);
}

static void lit_surface(void) {
  static GLfloat knots[9] = {0, 0, 0, 0, 0.5f, 1, 1, 1, 1};
  gluBeginSurface(nurb);
  gluNurbsSurface(nurb, 9, knots, 9, knots, 5 * 3, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
  gluEndSurface(nurb);
}

static void display(void) {
  glClearColor(0.08f, 0.08f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  /* Top left: lit, two spans each way. */
  camera(0, H / 2);
  GLfloat pos[4] = {1, -2, 3, 0}, diffuse[4] = {0.9f, 0.7f, 0.3f, 1}, spec[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_NORMALIZE);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(nurb, GLU_U_STEP, 24);
  gluNurbsProperty(nurb, GLU_V_STEP, 20);
  lit_surface();

  /* Top right: rational vertices, a colour map on other knots. */
  camera(W / 2, H / 2);
  glDisable(GL_LIGHTING);
  glRotatef(25, 0, 0, 1);
  {
    static GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    static GLfloat cknots[4] = {0, 0, 1, 1};
    gluNurbsProperty(nurb, GLU_U_STEP, 16);
    gluNurbsProperty(nurb, GLU_V_STEP, 16);
    gluBeginSurface(nurb);
    gluNurbsSurface(nurb, 8, knots, 8, knots, 4 * 4, 4, &ctl4[0][0][0], 4, 4, GL_MAP2_VERTEX_4);
    gluNurbsSurface(nurb, 4, cknots, 4, cknots, 2 * 4, 4, &colours[0][0][0], 2, 2, GL_MAP2_COLOR_4);
    gluEndSurface(nurb);
  }

  /* Bottom left: trimmed, path length 4 pixels. */
  camera(0, 0);
  glEnable(GL_LIGHTING);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_PATH_LENGTH);
  gluNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, 4);
  {
    static GLfloat knots[9] = {0, 0, 0, 0, 0.5f, 1, 1, 1, 1};
    static GLfloat outer[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    /* A circle of radius 0.15 around (0.3, 0.3), clockwise: 9 rational quadratic points. */
    static GLfloat circle[9][3];
    static GLfloat cknots[12] = {0, 0, 0, 0.25f, 0.25f, 0.5f, 0.5f, 0.75f, 0.75f, 1, 1, 1};
    static GLfloat square[5][2] = {
        {0.55f, 0.55f}, {0.55f, 0.9f}, {0.9f, 0.9f}, {0.9f, 0.55f}, {0.55f, 0.55f}};
    static GLfloat tri[4][2] = {{0.6f, 0.6f}, {0.85f, 0.6f}, {0.72f, 0.85f}, {0.6f, 0.6f}};
    static const float dx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, dy[9] = {0, -1, -1, -1, 0, 1, 1, 1, 0};
    for (int i = 0; i < 9; ++i) {
      const float w = (i % 2) ? 0.70710678f : 1.0f;
      circle[i][0] = (0.3f + 0.15f * dx[i]) * w;
      circle[i][1] = (0.3f + 0.15f * dy[i]) * w;
      circle[i][2] = w;
    }
    gluBeginSurface(nurb);
    gluNurbsSurface(nurb, 9, knots, 9, knots, 5 * 3, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    gluBeginTrim(nurb);
    gluPwlCurve(nurb, 5, &outer[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nurb);
    gluBeginTrim(nurb);
    gluNurbsCurve(nurb, 12, cknots, 3, &circle[0][0], 3, GLU_MAP1_TRIM_3);
    gluEndTrim(nurb);
    gluBeginTrim(nurb);
    gluPwlCurve(nurb, 5, &square[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nurb);
    gluBeginTrim(nurb);
    gluPwlCurve(nurb, 4, &tri[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nurb);
    gluEndSurface(nurb);
  }

  /* Bottom right: curves, and the lit surface's tessellation as outlines. */
  camera(W / 2, 0);
  glDisable(GL_LIGHTING);
  glColor3f(0.5f, 0.6f, 0.7f);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(nurb, GLU_U_STEP, 6);
  gluNurbsProperty(nurb, GLU_V_STEP, 6);
  gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_OUTLINE_POLYGON);
  lit_surface();
  gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_FILL);
  glDisable(GL_DEPTH_TEST);
  glLineWidth(2);
  {
    static GLfloat circle[9][4];
    static GLfloat cknots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    static const float dx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, dy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    for (int i = 0; i < 9; ++i) {
      const float w = (i % 2) ? 0.70710678f : 1.0f;
      circle[i][0] = 1.2f * dx[i] * w;
      circle[i][1] = 1.2f * dy[i] * w;
      circle[i][2] = 1.0f * w;
      circle[i][3] = w;
    }
    gluNurbsProperty(nurb, GLU_U_STEP, 12);
    glColor3f(1, 0.8f, 0.2f);
    gluBeginCurve(nurb);
    gluNurbsCurve(nurb, 12, cknots, 4, &circle[0][0], 3, GL_MAP1_VERTEX_4);
    gluEndCurve(nurb);

    static GLfloat wave[6][3] = {{-1.5f, -1, 0}, {-1, 1, 0.5f}, {-0.3f, -1, 0},
                                 {0.3f, 1, 0},   {1, -1, 0.5f}, {1.5f, 1, 0}};
    static GLfloat wknots[10] = {0, 0, 0, 0, 1, 2, 3, 3, 3, 3};
    glColor3f(0.3f, 0.9f, 1);
    gluBeginCurve(nurb);
    gluNurbsCurve(nurb, 10, wknots, 3, &wave[0][0], 4, GL_MAP1_VERTEX_3);
    gluEndCurve(nurb);
    /* One span with a colour map of its own order. */
    static GLfloat arc[4][3] = {{-1.5f, 1.2f, 0}, {-0.5f, 2.2f, 0}, {0.5f, 0.2f, 0}, {1.5f, 1.2f, 0}};
    static GLfloat aknots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    static GLfloat acol[2][4] = {{0.2f, 1, 0.4f, 1}, {1, 0.2f, 0.8f, 1}};
    static GLfloat acknots[4] = {0, 0, 1, 1};
    gluBeginCurve(nurb);
    gluNurbsCurve(nurb, 8, aknots, 3, &arc[0][0], 4, GL_MAP1_VERTEX_3);
    gluNurbsCurve(nurb, 4, acknots, 4, &acol[0][0], 2, GL_MAP1_COLOR_4);
    gluEndCurve(nurb);
  }
  glLineWidth(1);
  glFlush();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(W, H);
  glutCreateWindow("40_glu_nurbs");
  init();
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
