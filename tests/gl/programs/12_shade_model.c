/* 12_shade_model: glShadeModel(GL_FLAT) next to GL_SMOOTH for triangles, triangle strip,
 * triangle fan, quads, quad strip and polygon, every vertex a different colour, so that the
 * provoking vertex of each flat primitive is visible (the last vertex of a triangle, i+2 of
 * a strip or fan triangle, the fourth of a quad, 2i+2 of a quad-strip quad, the first of a
 * polygon). The last row draws flat-shaded lit quads and a lit polygon with a per-vertex
 * normal, where the lit colour of the provoking vertex is used. */
#include <GL/glut.h>
#include <math.h>

#define PI 3.14159265358979323846

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, w, 0, h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void hue(int i) {
  static const GLfloat c[12][3] = {{1, 0, 0},    {1, 0.6f, 0}, {1, 1, 0},    {0.4f, 1, 0},
                                   {0, 1, 0.5f}, {0, 1, 1},    {0, 0.5f, 1}, {0.3f, 0, 1},
                                   {0.8f, 0, 1}, {1, 0, 0.6f}, {1, 1, 1},    {0.5f, 0.5f, 0.5f}};
  glColor3fv(c[i % 12]);
}

/* The cells are 80 x 72; (x, y) is the lower-left corner. */
static void triangles(float x, float y) {
  glBegin(GL_TRIANGLES);
  hue(0);
  glVertex2f(x + 4, y + 4);
  hue(1);
  glVertex2f(x + 74, y + 8);
  hue(2);
  glVertex2f(x + 10, y + 50);
  hue(3);
  glVertex2f(x + 76, y + 20);
  hue(4);
  glVertex2f(x + 70, y + 68);
  hue(5);
  glVertex2f(x + 22, y + 62);
  glEnd();
}

static void strip(float x, float y) {
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 8; ++i) {
    hue(i);
    glVertex2f(x + 4 + 10 * i, y + (i % 2 ? 66 : 6) - 2 * i);
  }
  glEnd();
}

static void fan(float x, float y) {
  glBegin(GL_TRIANGLE_FAN);
  hue(10);
  glVertex2f(x + 40, y + 36);
  for (int i = 0; i <= 7; ++i) {
    const double a = 2 * PI * i / 8 + 0.2;
    hue(i);
    glVertex2d(x + 40 + 37 * cos(a), y + 36 + 33 * sin(a));
  }
  glEnd();
}

static void quads(float x, float y) {
  glBegin(GL_QUADS);
  hue(0);
  glVertex2f(x + 3, y + 3);
  hue(2);
  glVertex2f(x + 38, y + 5);
  hue(4);
  glVertex2f(x + 36, y + 68);
  hue(6);
  glVertex2f(x + 5, y + 66);
  hue(8);
  glVertex2f(x + 42, y + 4);
  hue(9);
  glVertex2f(x + 77, y + 3);
  hue(1);
  glVertex2f(x + 76, y + 69);
  hue(5);
  glVertex2f(x + 41, y + 64);
  glEnd();
}

static void quad_strip(float x, float y) {
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i < 5; ++i) {
    hue(2 * i);
    glVertex2f(x + 4 + 18 * i, y + 5 + (i % 2) * 6);
    hue(2 * i + 1);
    glVertex2f(x + 4 + 18 * i, y + 67 - (i % 2) * 6);
  }
  glEnd();
}

static void polygon(float x, float y) {
  glBegin(GL_POLYGON);
  for (int i = 0; i < 7; ++i) {
    const double a = 2 * PI * i / 7 + 1.0;
    hue(i * 3 + 1);
    glVertex2d(x + 40 + 37 * cos(a), y + 36 + 33 * sin(a));
  }
  glEnd();
}

static void lit_quads(float x, float y) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glBegin(GL_QUADS);
  for (int q = 0; q < 2; ++q)
    for (int k = 0; k < 4; ++k) {
      static const int cx[4] = {0, 1, 1, 0}, cy[4] = {0, 0, 1, 1};
      const double a = 0.4 * (q * 4 + k) - 1.2;
      glNormal3d(sin(a), 0.3 * cos(3 * a), cos(a));
      glVertex2f(x + 3 + 38 * q + 35 * cx[k], y + 4 + 64 * cy[k]);
    }
  glEnd();
  glDisable(GL_LIGHTING);
}

static void lit_polygon(float x, float y) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glBegin(GL_POLYGON);
  for (int i = 0; i < 6; ++i) {
    const double a = 2 * PI * i / 6 + 0.5;
    glNormal3d(0.7 * cos(a + 1.0), 0.7 * sin(a + 2.0), 0.7);
    glVertex2d(x + 40 + 37 * cos(a), y + 36 + 33 * sin(a));
  }
  glEnd();
  glDisable(GL_LIGHTING);
}

static void display(void) {
  typedef void (*Draw)(float, float);
  static const Draw draws[8] = {triangles, strip, fan, quads, quad_strip, polygon, lit_quads, lit_polygon};
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  for (int k = 0; k < 8; ++k)
    for (int smooth = 0; smooth < 2; ++smooth) {
      const int cell = k * 2 + smooth;
      glShadeModel(smooth ? GL_SMOOTH : GL_FLAT);
      draws[k]((float)(cell % 4) * 80, (float)(3 - cell / 4) * 72);
    }
  glShadeModel(GL_SMOOTH);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(320, 288);
  glutCreateWindow("12 shade model");
  glDisable(GL_DITHER);
  {
    const GLfloat light[4] = {0.2f, 0.4f, 1.0f, 0.0f}, diffuse[4] = {0.9f, 0.7f, 0.4f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diffuse);
  }
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
