/* 33_glu_tess: the GLU polygon tessellator, one shape per cell (4 x 3), each in one flat
 * colour (the triangulation may differ between implementations, the covered pixels may not):
 *   row 1: a concave arrow (one contour); a square with a diamond hole (ODD); a pentagram
 *          under ODD with a COMBINE callback and an EDGE_FLAG callback (glEdgeFlag), filled and
 *          then outlined in GL_LINE polygon mode (only boundary edges show); a clockwise
 *          pentagram under NEGATIVE with gluTessNormal(0, 0, 1);
 *   row 2: two rectangles and a circle, all counter-clockwise, under ODD, NONZERO and
 *          ABS_GEQ_TWO (the last through the _DATA callbacks, colour from the polygon data);
 *          the same with the circle clockwise under POSITIVE;
 *   row 3: that again under POSITIVE with gluTessNormal(0, 0, -1) (the signs flip); the ODD
 *          regions of the first set as GL_LINE_LOOPs (GLU_TESS_BOUNDARY_ONLY); a hexagon with
 *          a triangular hole through the GLU 1.1 gluBeginPolygon/gluNextContour/gluEndPolygon;
 *          a {7/3} star on a tilted plane (z varies, normal computed by GLU) under NONZERO.
 * Callbacks are the classic glBegin/glVertex3dv/glEnd/glEdgeFlag. */
#include <GL/glut.h>
#include <math.h>
#include <stdio.h>

#define PI 3.14159265358979323846

static int win_w = 320, win_h = 240;
static GLUtesselator* tess;

/* Vertices made by the COMBINE callbacks live here until the frame is drawn. */
static GLdouble combined[1024][3];
static int ncombined;

static void combine(GLdouble coords[3], void* data[4], GLfloat weight[4], void** out) {
  (void)data;
  (void)weight;
  GLdouble* v = combined[ncombined < 1023 ? ncombined++ : 1023];
  v[0] = coords[0];
  v[1] = coords[1];
  v[2] = coords[2];
  *out = v;
}

static void tess_error(GLenum code) {
  fprintf(stderr, "tessellation error: %s\n", (const char*)gluErrorString(code));
}

/* _DATA callbacks: the polygon data is the colour. */
static void begin_data(GLenum type, void* polygon) {
  glColor3fv((const GLfloat*)polygon);
  glBegin(type);
}
static void vertex_data(void* vertex, void* polygon) {
  (void)polygon;
  glVertex3dv((const GLdouble*)vertex);
}
static void end_data(void* polygon) {
  (void)polygon;
  glEnd();
}
static void combine_data(GLdouble coords[3], void* data[4], GLfloat weight[4], void** out, void* polygon) {
  (void)polygon;
  combine(coords, data, weight, out);
}

static void reshape(int w, int h) {
  win_w = w;
  win_h = h;
}

/* Cell (col, row) of the 4 x 3 grid, row 0 at the top, 80 x 80 units. */
static void cell(int col, int row) {
  glLoadIdentity();
  glTranslated(80.0 * col, 240.0 - 80.0 * (row + 1), 0.0);
}

static void contour(GLdouble (*v)[3], int n) {
  gluTessBeginContour(tess);
  for (int i = 0; i < n; ++i) gluTessVertex(tess, v[i], v[i]);
  gluTessEndContour(tess);
}

static void rule(GLenum r) { gluTessProperty(tess, GLU_TESS_WINDING_RULE, r); }

/* Shapes. */
static GLdouble arrow[7][3] = {{8.3, 30.2, 0},  {44.1, 30.2, 0}, {44.1, 12.6, 0}, {72.4, 40.3, 0},
                               {44.1, 68.1, 0}, {44.1, 50.4, 0}, {8.3, 50.4, 0}};
static GLdouble square[4][3] = {{8.3, 8.6, 0}, {71.7, 8.6, 0}, {71.7, 71.4, 0}, {8.3, 71.4, 0}};
static GLdouble diamond[4][3]; /* clockwise */
static GLdouble star5[5][3], star5cw[5][3];
static GLdouble rectA[4][3] = {{6.1, 8.1, 0}, {50.9, 8.1, 0}, {50.9, 48.1, 0}, {6.1, 48.1, 0}};
static GLdouble rectB[4][3] = {{27.1, 30.1, 0}, {73.1, 30.1, 0}, {73.1, 72.9, 0}, {27.1, 72.9, 0}};
static GLdouble circ[28][3], circcw[28][3];
static GLdouble hexagon[6][3], hole[3][3];
static GLdouble star7[7][3];

static void make_shapes(void) {
  for (int i = 0; i < 4; ++i) {
    const double a = -2 * PI * i / 4; /* clockwise */
    diamond[i][0] = 40.2 + 21.0 * cos(a);
    diamond[i][1] = 39.7 + 21.0 * sin(a);
  }
  for (int i = 0; i < 5; ++i) {
    const double a = PI / 2 + 0.07 + 4 * PI * i / 5;
    star5[i][0] = 40.3 + 35.0 * cos(a);
    star5[i][1] = 39.1 + 35.0 * sin(a);
    star5cw[4 - i][0] = star5[i][0];
    star5cw[4 - i][1] = star5[i][1];
  }
  for (int i = 0; i < 28; ++i) {
    const double a = 0.05 + 2 * PI * i / 28;
    circ[i][0] = 41.2 + 21.0 * cos(a);
    circ[i][1] = 37.7 + 21.0 * sin(a);
    circcw[27 - i][0] = circ[i][0];
    circcw[27 - i][1] = circ[i][1];
  }
  for (int i = 0; i < 6; ++i) {
    const double a = 0.2 + 2 * PI * i / 6;
    hexagon[i][0] = 40.1 + 34.0 * cos(a);
    hexagon[i][1] = 40.3 + 34.0 * sin(a);
  }
  for (int i = 0; i < 3; ++i) {
    const double a = 0.4 - 2 * PI * i / 3; /* clockwise */
    hole[i][0] = 42.3 + 17.0 * cos(a);
    hole[i][1] = 38.4 + 17.0 * sin(a);
  }
  for (int i = 0; i < 7; ++i) {
    const double a = 0.3 + 6 * PI * i / 7;
    star7[i][0] = 40.2 + 36.0 * cos(a);
    star7[i][1] = 40.4 + 36.0 * sin(a);
    star7[i][2] = 0.006 * (star7[i][0] - 40.0) - 0.004 * (star7[i][1] - 40.0); /* a tilted plane */
  }
}

/* The rectangles and the circle (counter-clockwise or clockwise) as one polygon. */
static void three(GLdouble (*c)[3], void* data) {
  gluTessBeginPolygon(tess, data);
  contour(rectA, 4);
  contour(rectB, 4);
  contour(c, 28);
  gluTessEndPolygon(tess);
}

static void display(void) {
  ncombined = 0;
  glClearColor(0.12f, 0.12f, 0.14f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glViewport(0, 0, win_w, win_h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, 320, 0, 240);
  glMatrixMode(GL_MODELVIEW);
  gluTessNormal(tess, 0, 0, 0);
  gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, GL_FALSE);

  /* Row 1. */
  cell(0, 0);
  rule(GLU_TESS_WINDING_ODD);
  glColor3f(1.0f, 0.55f, 0.1f);
  gluTessBeginPolygon(tess, NULL);
  contour(arrow, 7);
  gluTessEndPolygon(tess);

  cell(1, 0);
  glColor3f(0.25f, 0.45f, 1.0f);
  gluTessBeginPolygon(tess, NULL);
  contour(square, 4);
  contour(diamond, 4);
  gluTessEndPolygon(tess);

  cell(2, 0);
  gluTessCallback(tess, GLU_TESS_EDGE_FLAG, (_GLUfuncptr)glEdgeFlag);
  glColor3f(1.0f, 0.9f, 0.2f);
  gluTessBeginPolygon(tess, NULL);
  contour(star5, 5);
  gluTessEndPolygon(tess);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glColor3f(0.75f, 0.1f, 0.1f);
  gluTessBeginPolygon(tess, NULL);
  contour(star5, 5);
  gluTessEndPolygon(tess);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  gluTessCallback(tess, GLU_TESS_EDGE_FLAG, NULL);
  glEdgeFlag(GL_TRUE);

  cell(3, 0);
  rule(GLU_TESS_WINDING_NEGATIVE);
  gluTessNormal(tess, 0, 0, 1);
  glColor3f(0.3f, 0.85f, 0.35f);
  gluTessBeginPolygon(tess, NULL);
  contour(star5cw, 5);
  gluTessEndPolygon(tess);
  gluTessNormal(tess, 0, 0, 0);

  /* Row 2. */
  cell(0, 1);
  rule(GLU_TESS_WINDING_ODD);
  glColor3f(0.9f, 0.25f, 0.8f);
  three(circ, NULL);

  cell(1, 1);
  rule(GLU_TESS_WINDING_NONZERO);
  glColor3f(0.15f, 0.75f, 0.75f);
  three(circ, NULL);

  cell(2, 1);
  {
    static GLfloat purple[3] = {0.6f, 0.35f, 1.0f};
    rule(GLU_TESS_WINDING_ABS_GEQ_TWO);
    gluTessCallback(tess, GLU_TESS_BEGIN_DATA, (_GLUfuncptr)begin_data);
    gluTessCallback(tess, GLU_TESS_VERTEX_DATA, (_GLUfuncptr)vertex_data);
    gluTessCallback(tess, GLU_TESS_END_DATA, (_GLUfuncptr)end_data);
    gluTessCallback(tess, GLU_TESS_COMBINE_DATA, (_GLUfuncptr)combine_data);
    three(circ, purple);
    gluTessCallback(tess, GLU_TESS_BEGIN_DATA, NULL);
    gluTessCallback(tess, GLU_TESS_VERTEX_DATA, NULL);
    gluTessCallback(tess, GLU_TESS_END_DATA, NULL);
    gluTessCallback(tess, GLU_TESS_COMBINE_DATA, NULL);
  }

  cell(3, 1);
  rule(GLU_TESS_WINDING_POSITIVE);
  glColor3f(0.55f, 0.8f, 1.0f);
  three(circcw, NULL);

  /* Row 3. */
  cell(0, 2);
  gluTessNormal(tess, 0, 0, -1);
  glColor3f(0.85f, 0.6f, 0.35f);
  three(circcw, NULL);
  gluTessNormal(tess, 0, 0, 0);

  cell(1, 2);
  rule(GLU_TESS_WINDING_ODD);
  gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, GL_TRUE);
  glColor3f(1.0f, 1.0f, 1.0f);
  three(circ, NULL);
  gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, GL_FALSE);

  cell(2, 2);
  glColor3f(0.95f, 0.3f, 0.3f);
  gluBeginPolygon(tess);
  for (int i = 0; i < 6; ++i) gluTessVertex(tess, hexagon[i], hexagon[i]);
  gluNextContour(tess, GLU_INTERIOR);
  for (int i = 0; i < 3; ++i) gluTessVertex(tess, hole[i], hole[i]);
  gluEndPolygon(tess);

  cell(3, 2);
  rule(GLU_TESS_WINDING_NONZERO);
  glColor3f(0.65f, 0.95f, 0.55f);
  gluTessBeginPolygon(tess, NULL);
  contour(star7, 7);
  gluTessEndPolygon(tess);

  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(win_w, win_h);
  glutCreateWindow("33 GLU tessellator");
  glDisable(GL_DITHER);
  make_shapes();
  tess = gluNewTess();
  gluTessCallback(tess, GLU_TESS_BEGIN, (_GLUfuncptr)glBegin);
  gluTessCallback(tess, GLU_TESS_VERTEX, (_GLUfuncptr)glVertex3dv);
  gluTessCallback(tess, GLU_TESS_END, (_GLUfuncptr)glEnd);
  gluTessCallback(tess, GLU_TESS_COMBINE, (_GLUfuncptr)combine);
  gluTessCallback(tess, GLU_TESS_ERROR, (_GLUfuncptr)tess_error);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
