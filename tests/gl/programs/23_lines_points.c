/* 23_lines_points: glLineWidth, glPointSize and glLineStipple (aliased; odd widths and sizes,
 * points at pixel centres).
 *  top left : a starburst of lines of widths 1, 3, 5 and 7;
 *  top right: rows of points of sizes 1, 3, 5 and 7, smooth colours;
 *  bottom   : stippled lines: patterns 0x00FF, 0x0C0F, 0xAAAA, 0x1C47 with repeat factors
 *             1-4, one and three pixels wide; GL_LINES (the pattern restarts with every
 *             segment), a GL_LINE_STRIP zigzag and a GL_LINE_LOOP (the pattern runs on
 *             across vertices). */
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

static void display(void) {
  glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  /* Starburst. */
  static const float widths[4] = {1, 3, 5, 7};
  for (int g = 0; g < 4; ++g) {
    glLineWidth(widths[g]);
    glBegin(GL_LINES);
    for (int k = 0; k < 5; ++k) {
      const double a = 2 * PI * (g * 5 + k) / 20 + 0.11;
      glColor3f(1, 1, 1);
      glVertex2d(80 + 10 * cos(a), 178 + 10 * sin(a));
      glColor3d(0.5 + 0.5 * cos(a), 0.5 + 0.5 * sin(a), 0.3 + 0.1 * g);
      glVertex2d(80 + 74 * cos(a), 178 + 56 * sin(a));
    }
    glEnd();
  }
  glLineWidth(1);

  /* Points. */
  static const float sizes[4] = {1, 3, 5, 7};
  for (int r = 0; r < 4; ++r) {
    glPointSize(sizes[r]);
    glBegin(GL_POINTS);
    for (int i = 0; i < 12; ++i) {
      glColor3f(i / 11.0f, 1.0f - r * 0.25f, 1.0f - i / 11.0f);
      glVertex2f(172.5f + 12 * i, 228.5f - 16 * r - (r > 1 ? (r - 1) * 4 : 0));
    }
    glEnd();
  }
  glPointSize(1);

  /* Stippled lines. */
  glEnable(GL_LINE_STIPPLE);
  static const GLushort patterns[4] = {0x00FF, 0x0C0F, 0xAAAA, 0x1C47};
  for (int i = 0; i < 8; ++i) {
    glLineStipple(1 + i % 4, patterns[i % 4]);
    glLineWidth(i < 4 ? 1.0f : 3.0f);
    glBegin(GL_LINES);
    glColor3f(1.0f, 0.9f - 0.1f * i, 0.2f + 0.1f * i);
    glVertex2f(6.5f, 112.5f - 9 * i);
    glColor3f(0.3f + 0.1f * i, 0.8f, 1.0f);
    glVertex2f(157.5f, 112.5f - 9 * i);
    /* A second, shorter segment in the same glBegin: the pattern restarts. */
    glVertex2f(6.5f, 108.5f - 9 * i);
    glVertex2f(73.5f, 108.5f - 9 * i);
    glEnd();
  }
  glLineWidth(1);
  glLineStipple(2, 0x33FF);
  glColor3f(0.9f, 0.5f, 1.0f);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i < 12; ++i) glVertex2f(168.5f + 13 * i, i % 2 ? 110.5f : 64.5f);
  glEnd();
  glLineStipple(1, 0x0F0F);
  glLineWidth(3);
  glBegin(GL_LINE_LOOP);
  for (int i = 0; i < 6; ++i) {
    const double a = 2 * PI * i / 6 + 0.3;
    glColor3d(0.5 + 0.5 * cos(a), 0.5 + 0.5 * sin(a), 0.8);
    glVertex2d(240 + 68 * cos(a), 32 + 26 * sin(a));
  }
  glEnd();
  glLineWidth(1);
  glDisable(GL_LINE_STIPPLE);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(320, 240);
  glutCreateWindow("23 lines and points");
  glDisable(GL_DITHER);
  glDisable(GL_LINE_SMOOTH);
  glDisable(GL_POINT_SMOOTH);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
