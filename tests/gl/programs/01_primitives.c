/* 01_primitives: every glBegin/glEnd primitive type, one per cell, smooth per-vertex colours.
 * GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLES, GL_TRIANGLE_STRIP,
 * GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON; single-buffered (glFlush). */
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

static void hue(double t) { /* a colour wheel, t in [0,1) */
  glColor3d(0.5 + 0.5 * cos(2 * PI * t), 0.5 + 0.5 * cos(2 * PI * (t - 1.0 / 3)),
            0.5 + 0.5 * cos(2 * PI * (t - 2.0 / 3)));
}

/* Each cell is 64 x 120 pixels; (x, y) is its lower-left corner. */
static void cell_points(float x, float y) {
  glPointSize(3.0f);
  glBegin(GL_POINTS);
  for (int j = 0; j < 19; ++j)
    for (int i = 0; i < 10; ++i) {
      hue((i + j) / 29.0);
      glVertex2f(x + 4.5f + 6 * i, y + 5.5f + 6 * j);
    }
  glEnd();
  glPointSize(1.0f);
}

static void cell_lines(float x, float y) {
  glBegin(GL_LINES);
  for (int i = 0; i < 24; ++i) {
    double a = 2 * PI * (i + 0.37) / 24;
    glColor3f(1, 1, 1);
    glVertex2d(x + 32 + 4 * cos(a), y + 60 + 4 * sin(a));
    hue(i / 24.0);
    glVertex2d(x + 32 + 30 * cos(a), y + 60 + 55 * sin(a));
  }
  glEnd();
}

static void cell_line_strip(float x, float y) {
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i < 40; ++i) {
    hue(i / 40.0);
    glVertex2d(x + 3.3 + (i % 2 ? 57.1 : 0.0) + 0.1 * i, y + 2.7 + 2.9 * i);
  }
  glEnd();
}

static void cell_line_loop(float x, float y) {
  for (int r = 0; r < 6; ++r) {
    glBegin(GL_LINE_LOOP);
    int n = 3 + r;
    for (int i = 0; i < n; ++i) {
      double a = 2 * PI * i / n + 0.3 * r + 0.05;
      hue((double)i / n);
      glVertex2d(x + 32 + (29 - 4.3 * r) * cos(a), y + 60 + (56 - 8.7 * r) * sin(a));
    }
    glEnd();
  }
}

static void cell_triangles(float x, float y) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex2f(x + 2, y + 4);
  glColor3f(0, 1, 0);
  glVertex2f(x + 62, y + 10);
  glColor3f(0, 0, 1);
  glVertex2f(x + 20, y + 70);
  glColor3f(1, 1, 0);
  glVertex2f(x + 60, y + 40);
  glColor3f(0, 1, 1);
  glVertex2f(x + 58, y + 117);
  glColor3f(1, 0, 1);
  glVertex2f(x + 5, y + 100);
  glEnd();
}

static void cell_triangle_strip(float x, float y) {
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 8; ++i) {
    hue(i / 8.0);
    glVertex2f(x + (i % 2 ? 60 : 4) - 2 * (i / 2), y + 4 + 15 * i);
  }
  glEnd();
}

static void cell_triangle_fan(float x, float y) {
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1, 1, 1);
  glVertex2f(x + 32, y + 60);
  for (int i = 0; i <= 7; ++i) {
    double a = 2 * PI * i / 9 + 0.2;
    hue(i / 9.0);
    glVertex2d(x + 32 + 30 * cos(a), y + 60 + 57 * sin(a));
  }
  glEnd();
}

static void cell_quads(float x, float y) {
  glBegin(GL_QUADS);
  glColor3f(1, 0, 0);
  glVertex2f(x + 3, y + 3);
  glColor3f(1, 1, 0);
  glVertex2f(x + 60, y + 8);
  glColor3f(0, 1, 0);
  glVertex2f(x + 55, y + 55);
  glColor3f(0, 0, 1);
  glVertex2f(x + 6, y + 50);
  glColor3f(0, 1, 1);
  glVertex2f(x + 10, y + 64);
  glColor3f(1, 0, 1);
  glVertex2f(x + 61, y + 70);
  glColor3f(1, 1, 1);
  glVertex2f(x + 50, y + 116);
  glColor3f(0.3f, 0.3f, 0.3f);
  glVertex2f(x + 2, y + 110);
  glEnd();
}

static void cell_quad_strip(float x, float y) {
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i < 6; ++i) {
    double s = sin(i * 0.9) * 8;
    hue(i / 6.0);
    glVertex2d(x + 4 + s, y + 3 + 22.6 * i);
    hue(i / 6.0 + 0.5);
    glVertex2d(x + 60 + s * 0.5, y + 3 + 22.6 * i + 3);
  }
  glEnd();
}

static void cell_polygon(float x, float y) {
  glBegin(GL_POLYGON);
  for (int i = 0; i < 7; ++i) {
    double a = 2 * PI * i / 7 + 0.1;
    hue(i / 7.0);
    glVertex2d(x + 32 + 30 * cos(a), y + 60 + 57 * sin(a));
  }
  glEnd();
}

static void display(void) {
  glClearColor(0.12f, 0.12f, 0.16f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  cell_points(0, 120);
  cell_lines(64, 120);
  cell_line_strip(128, 120);
  cell_line_loop(192, 120);
  cell_triangles(256, 120);
  cell_triangle_strip(0, 0);
  cell_triangle_fan(64, 0);
  cell_quads(128, 0);
  cell_quad_strip(192, 0);
  cell_polygon(256, 0);
  glFlush();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
  glutInitWindowSize(320, 240);
  glutCreateWindow("01 primitives");
  glDisable(GL_DITHER);
  glShadeModel(GL_SMOOTH);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
