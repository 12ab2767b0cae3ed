/* 20_stencil: the stencil test.
 * Left: a star is written into the stencil buffer only (glColorMask off, GL_ALWAYS,
 * GL_REPLACE); diagonal stripes are then drawn where stencil == 1 and a dotted pattern where
 * stencil != 1 (stencil-masked drawing).
 * Right: overlaps are counted with GL_INCR (three discs), reduced with GL_DECR (a fourth
 * disc; 0 stays 0), and a bar toggles bit 2 with GL_INVERT under glStencilMask(0x04);
 * then each stencil value 0..7 is painted in its own colour with GL_EQUAL. */
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

static void disc(double cx, double cy, double r) {
  glBegin(GL_TRIANGLE_FAN);
  glVertex2d(cx, cy);
  for (int i = 0; i <= 40; ++i) glVertex2d(cx + r * cos(2 * PI * i / 40), cy + r * sin(2 * PI * i / 40));
  glEnd();
}

static void star(double cx, double cy, double r) {
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 5; ++i) {
    const double a = PI / 2 + 2 * PI * i / 5, b = a + 2 * PI / 10, c = a - 2 * PI / 10;
    glVertex2d(cx, cy);
    glVertex2d(cx + 0.4 * r * cos(c), cy + 0.4 * r * sin(c));
    glVertex2d(cx + r * cos(a), cy + r * sin(a));
    glVertex2d(cx, cy);
    glVertex2d(cx + r * cos(a), cy + r * sin(a));
    glVertex2d(cx + 0.4 * r * cos(b), cy + 0.4 * r * sin(b));
  }
  glEnd();
}

static void display(void) {
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClearStencil(0);
  glStencilMask(0xff);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);

  /* Left: the star mask. */
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  star(80, 98, 80);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glBegin(GL_QUADS);
  for (int i = -10; i < 16; ++i) {
    glColor3f(1.0f, 0.8f - 0.03f * i, 0.2f);
    glVertex2f(12.0f * i, 0);
    glVertex2f(12.0f * i + 6, 0);
    glVertex2f(12.0f * i + 206, 200);
    glColor3f(0.9f, 0.3f, 0.1f + 0.03f * i);
    glVertex2f(12.0f * i + 200, 200);
  }
  glEnd();
  glStencilFunc(GL_NOTEQUAL, 1, 0xff);
  glColor3f(0.3f, 0.6f, 0.9f);
  for (int y = 4; y < 200; y += 10)
    for (int x = 4 + (y / 10) % 2 * 5; x < 160; x += 10) glRecti(x, y, x + 4, y + 4);

  /* Right: counting. */
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  disc(215, 115, 50);
  disc(265, 115, 50);
  disc(240, 75, 50);
  glStencilOp(GL_KEEP, GL_KEEP, GL_DECR);
  disc(290, 40, 34);
  glStencilMask(0x04);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
  glRecti(170, 150, 310, 175);
  glStencilMask(0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  static const GLfloat level[8][3] = {{0.1f, 0.1f, 0.1f}, {0.2f, 0.4f, 0.9f}, {0.2f, 0.8f, 0.3f},
                                      {1.0f, 0.9f, 0.2f}, {0.9f, 0.2f, 0.7f}, {1.0f, 0.5f, 0.1f},
                                      {0.5f, 1.0f, 1.0f}, {1.0f, 1.0f, 1.0f}};
  for (int k = 0; k < 8; ++k) {
    glStencilFunc(GL_EQUAL, k, 0xff);
    glColor3fv(level[k]);
    glRecti(162, 0, 320, 200);
  }
  glDisable(GL_STENCIL_TEST);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_STENCIL);
  glutInitWindowSize(320, 200);
  glutCreateWindow("20 stencil");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
