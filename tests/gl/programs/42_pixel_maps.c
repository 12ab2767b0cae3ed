/* 42_pixel_maps: pixel maps (GL 2.1 section 3.6.3) in the transfers where Mesa's llvmpipe
 * follows the specification, which are compared here:
 *  - GL_COLOR_INDEX images (GL_UNSIGNED_BYTE and GL_UNSIGNED_SHORT indices, and a GL_BITMAP)
 *    drawn in the RGBA window through an I_TO_R/G/B/A palette of 16 entries given with
 *    glPixelMapusv (the index masked to the map's size);
 *  - glReadPixels with GL_MAP_COLOR on: R_TO_R (an inverting map of 256 entries), G_TO_G (4
 *    steps) and B_TO_B (a 2-entry threshold) after scale and bias, drawn back plainly;
 *  - a GL_STENCIL_INDEX rectangle shown through the stencil test.
 * glDrawPixels with GL_MAP_COLOR, GL_INDEX_SHIFT/OFFSET, I_TO_I and S_TO_S are not compared:
 * llvmpipe draws pixel rectangles through a shader that looks colour maps up at floor(c size)
 * rather than round(c (size - 1)) and skips the index operations, where Tessel does what the
 * specification says (test_gl_api PixelTransfer* checks those values). */
#include <GL/glut.h>
#include <string.h>

static const int W = 320, H = 240;
static GLubyte grad[32][48][3];
static GLubyte idx8[24][40];
static GLushort idx16[24][40];
static GLubyte bits[16][4];
static GLubyte stencil_img[30][60];

static void make_images(void) {
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 48; ++x) {
      grad[y][x][0] = (GLubyte)(x * 255 / 47);
      grad[y][x][1] = (GLubyte)(y * 255 / 31);
      grad[y][x][2] = (GLubyte)((x + y) * 3);
    }
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 40; ++x) {
      idx8[y][x] = (GLubyte)((x / 5 + y / 6 * 3) % 16);
      idx16[y][x] = (GLushort)(((x / 4) ^ (y / 4)) + 300);
    }
  memset(bits, 0, sizeof bits);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x)
      if ((x / 4 + y / 4) % 2) bits[y][x / 8] |= (GLubyte)(0x80 >> (x % 8));
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 60; ++x) stencil_img[y][x] = (GLubyte)(x / 15 + (y / 15) * 4);
}

static void set_maps(void) {
  GLfloat inv[256], post[4], thr[2] = {0.1f, 0.9f};
  for (int i = 0; i < 256; ++i) inv[i] = 1.0f - (float)i / 255.0f;
  for (int i = 0; i < 4; ++i) post[i] = (float)i / 3.0f;
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 256, inv);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 4, post);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 2, thr);
  GLushort r[16], g[16], b[16], a[16];
  for (int i = 0; i < 16; ++i) {
    r[i] = (GLushort)((i & 1) ? 65535 : 8000 * (i / 2));
    g[i] = (GLushort)(4369 * i);
    b[i] = (GLushort)((i & 4) ? 60000 : 12000);
    a[i] = 65535;
  }
  glPixelMapusv(GL_PIXEL_MAP_I_TO_R, 16, r);
  glPixelMapusv(GL_PIXEL_MAP_I_TO_G, 16, g);
  glPixelMapusv(GL_PIXEL_MAP_I_TO_B, 16, b);
  glPixelMapusv(GL_PIXEL_MAP_I_TO_A, 16, a);
  GLuint ii[16];
  for (int i = 0; i < 16; ++i) ii[i] = (GLuint)(15 - i);
  glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 16, ii);
  GLfloat ss[8] = {7, 6, 5, 4, 3, 2, 1, 0};
  glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 8, ss);
}

static void display(void) {
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

  /* The source of the read-backs. */
  glRasterPos2i(8, 196);
  glDrawPixels(48, 32, GL_RGB, GL_UNSIGNED_BYTE, grad);

  /* Colour indices through the palette. */
  glRasterPos2i(8, 160);
  glDrawPixels(40, 24, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx8);
  glRasterPos2i(56, 160);
  glDrawPixels(40, 24, GL_COLOR_INDEX, GL_UNSIGNED_SHORT, idx16);
  glRasterPos2i(104, 160);
  glDrawPixels(32, 16, GL_COLOR_INDEX, GL_BITMAP, bits);

  /* Stencil indices, shown by the stencil test. */
  glRasterPos2i(8, 100);
  glDrawPixels(60, 30, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil_img);
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  for (int k = 0; k < 8; ++k) {
    glStencilFunc(GL_EQUAL, k, 0xFF);
    glColor3f((float)(k & 1), (float)((k >> 1) & 1) * 0.8f + 0.2f, (float)(k >> 2) * 0.7f + 0.1f);
    glRecti(8, 100, 68, 130);
  }
  glDisable(GL_STENCIL_TEST);

  /* Read back with the maps on (and scale and bias), drawn back with them off. */
  static GLubyte back[32][48][3];
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glReadPixels(8, 196, 48, 32, GL_RGB, GL_UNSIGNED_BYTE, back);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  glRasterPos2i(64, 196);
  glDrawPixels(48, 32, GL_RGB, GL_UNSIGNED_BYTE, back);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_BIAS, 0.3f);
  glReadPixels(8, 196, 48, 32, GL_RGB, GL_UNSIGNED_BYTE, back);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  glPixelTransferf(GL_GREEN_BIAS, 0.0f);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  glRasterPos2i(120, 196);
  glDrawPixels(48, 32, GL_RGB, GL_UNSIGNED_BYTE, back);
  /* The palette image read back through the maps. */
  static GLubyte back2[24][40][3];
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glReadPixels(8, 160, 40, 24, GL_RGB, GL_UNSIGNED_BYTE, back2);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  glRasterPos2i(176, 160);
  glDrawPixels(40, 24, GL_RGB, GL_UNSIGNED_BYTE, back2);
  glFlush();
}

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, w, 0, h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_STENCIL);
  glutInitWindowSize(W, H);
  glutCreateWindow("42_pixel_maps");
  make_images();
  set_maps();
  glutReshapeFunc(reshape);
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
