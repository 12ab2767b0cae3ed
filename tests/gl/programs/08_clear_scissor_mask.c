/* 08_clear_scissor_mask: clears and the masks that govern them. glClearColor, glClearDepth,
 * glClearStencil; glScissor'ed clears (a mosaic); glClear under glColorMask (only some
 * channels cleared) and under glDepthMask(GL_FALSE) / glStencilMask (the clear leaves those
 * buffers alone); drawing under glColorMask; a depth buffer cleared to 0.5 in one half so
 * that only the near part of a slanted quad passes GL_LESS; a stencil buffer cleared to 1 in
 * a rectangle, tested with GL_EQUAL; scissored drawing. Single-buffered (glFlush). */
#include <GL/glut.h>
#include <math.h>

#define PI 3.14159265358979323846

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, w, 0, h, -1, 1); /* window z in [0, 1] maps from object z in [1, -1] */
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void clear_rect(int x, int y, int w, int h, GLbitfield mask) {
  glScissor(x, y, w, h);
  glEnable(GL_SCISSOR_TEST);
  glClear(mask);
  glDisable(GL_SCISSOR_TEST);
}

/* A quad from x0 to x1 whose depth goes from near (z = 0.9) at the bottom to far (z = -0.9)
   at the top: window depth 0.05 .. 0.95. */
static void slanted_quad(int x0, int y0, int x1, int y1) {
  glBegin(GL_QUADS);
  glColor3f(1.0f, 0.6f, 0.1f);
  glVertex3f((float)x0, (float)y0, 0.9f);
  glColor3f(0.9f, 0.1f, 0.5f);
  glVertex3f((float)x1, (float)y0, 0.9f);
  glColor3f(0.2f, 0.3f, 1.0f);
  glVertex3f((float)x1, (float)y1, -0.9f);
  glColor3f(0.1f, 0.9f, 0.6f);
  glVertex3f((float)x0, (float)y1, -0.9f);
  glEnd();
}

static void display(void) {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glStencilMask(0xff);
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  /* A mosaic of scissored clears (top band). */
  for (int i = 0; i < 8; ++i) {
    glClearColor(0.5f + 0.5f * (float)cos(i * 0.8), 0.5f + 0.5f * (float)sin(i * 1.3), i / 7.0f, 1.0f);
    clear_rect(4 + 39 * i, 196 + (i % 2) * 8, 35, 36 - (i % 2) * 8, GL_COLOR_BUFFER_BIT);
  }

  /* Colour-masked clears: white, then clear to black with only some channels writable. */
  glClearColor(1, 1, 1, 1);
  clear_rect(4, 128, 312, 62, GL_COLOR_BUFFER_BIT);
  glClearColor(0, 0, 0, 1);
  static const GLboolean masks[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
  for (int i = 0; i < 6; ++i) {
    glColorMask(masks[i][0], masks[i][1], masks[i][2], GL_TRUE);
    clear_rect(8 + 52 * i, 132, 44, 54, GL_COLOR_BUFFER_BIT);
  }
  /* Colour-masked drawing: a gradient band over the cleared cells, green channel locked. */
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glBegin(GL_QUADS);
  glColor3f(0.0f, 1.0f, 0.3f);
  glVertex2i(4, 150);
  glColor3f(1.0f, 1.0f, 0.8f);
  glVertex2i(316, 150);
  glColor3f(1.0f, 1.0f, 0.8f);
  glVertex2i(316, 166);
  glColor3f(0.0f, 1.0f, 0.3f);
  glVertex2i(4, 166);
  glEnd();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  /* Depth: the left box's depth cleared to 0.5, the middle box's clear blocked by the depth
     mask (stays 1.0), the right box cleared to 0.5 too; then a slanted quad in each. */
  glClearColor(0.1f, 0.1f, 0.3f, 1.0f);
  clear_rect(4, 4, 100, 120, GL_COLOR_BUFFER_BIT);
  clear_rect(110, 4, 100, 120, GL_COLOR_BUFFER_BIT);
  glClearDepth(0.5);
  clear_rect(4, 4, 100, 120, GL_DEPTH_BUFFER_BIT);
  glDepthMask(GL_FALSE);
  clear_rect(110, 4, 100, 120, GL_DEPTH_BUFFER_BIT);
  glDepthMask(GL_TRUE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  slanted_quad(10, 10, 98, 118);
  slanted_quad(116, 10, 204, 118);
  glDisable(GL_DEPTH_TEST);

  /* Stencil: 1 in an inner rectangle, a masked clear that must not change it, then a fan
     drawn where stencil == 1, and under a scissor. */
  glClearColor(0.3f, 0.1f, 0.1f, 1.0f);
  clear_rect(216, 4, 100, 120, GL_COLOR_BUFFER_BIT);
  glClearStencil(1);
  clear_rect(226, 20, 60, 90, GL_STENCIL_BUFFER_BIT);
  glClearStencil(0);
  glStencilMask(0x00);
  clear_rect(216, 4, 100, 120, GL_STENCIL_BUFFER_BIT);
  glStencilMask(0xff);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glScissor(216, 4, 88, 120);
  glEnable(GL_SCISSOR_TEST);
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1, 1, 1);
  glVertex2f(266, 64);
  for (int i = 0; i <= 12; ++i) {
    const double a = 2 * PI * i / 12;
    glColor3f(0.5f + 0.5f * (float)cos(a), 0.5f + 0.5f * (float)sin(a), i % 2 ? 1.0f : 0.2f);
    glVertex2d(266 + 70 * cos(a), 64 + 70 * sin(a));
  }
  glEnd();
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_STENCIL_TEST);
  glFlush();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH | GLUT_STENCIL);
  glutInitWindowSize(320, 240);
  glutCreateWindow("08 clears, scissor and masks");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
