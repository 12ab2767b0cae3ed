/* 15_tex_sub_copy: texture image updates.
 *  - glTexImage2D of a 64x64 RGB checkerboard, then glTexSubImage2D patches: an RGB
 *    gradient 13 texels wide (odd row length, GL_UNPACK_ALIGNMENT 1), a region cut out of a
 *    larger client image with GL_UNPACK_ROW_LENGTH / SKIP_PIXELS / SKIP_ROWS, and a
 *    GL_LUMINANCE patch with alignment 4;
 *  - glCopyTexImage2D: a small scene (a smooth triangle and a ring) rendered into the
 *    corner of the back buffer, copied into a 64x64 texture, the buffer cleared, then the
 *    texture mapped on rotated quads; glCopyTexSubImage2D copies a second rendering into a
 *    quarter of it. */
#include <GL/glut.h>
#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

static GLuint patched, copied;
static int win_w = 320, win_h = 240;

static void reshape(int w, int h) {
  win_w = w;
  win_h = h;
}

static void ortho(void) {
  glViewport(0, 0, win_w, win_h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, win_w, 0, win_h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void make_patched(void) {
  static GLubyte base[64 * 64 * 3];
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) {
      const int on = (i / 8 + j / 8) % 2;
      GLubyte* t = &base[(j * 64 + i) * 3];
      t[0] = on ? 240 : 40;
      t[1] = on ? 240 : 60;
      t[2] = on ? 230 : 90;
    }
  glGenTextures(1, &patched);
  glBindTexture(GL_TEXTURE_2D, patched);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, base);

  /* 13 x 20 RGB gradient, tightly packed rows of 39 bytes. */
  GLubyte grad[13 * 20 * 3];
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 13; ++i) {
      grad[(j * 13 + i) * 3 + 0] = (GLubyte)(i * 19);
      grad[(j * 13 + i) * 3 + 1] = (GLubyte)(j * 12);
      grad[(j * 13 + i) * 3 + 2] = 255;
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 5, 7, 13, 20, GL_RGB, GL_UNSIGNED_BYTE, grad);

  /* A 40 x 30 client image of which the 17 x 11 region at (9, 6) is sent. */
  static GLubyte big[30 * 40 * 3];
  for (int j = 0; j < 30; ++j)
    for (int i = 0; i < 40; ++i) {
      const int inside = i >= 9 && i < 26 && j >= 6 && j < 17;
      GLubyte* t = &big[(j * 40 + i) * 3];
      t[0] = inside ? (GLubyte)(255 - (i - 9) * 12) : 0;
      t[1] = inside ? 40 : 255; /* green would show if the skips were wrong */
      t[2] = inside ? (GLubyte)((j - 6) * 22) : 0;
    }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 40);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 9);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 6);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 30, 40, 17, 11, GL_RGB, GL_UNSIGNED_BYTE, big);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);

  /* A 10 x 9 luminance patch with the default alignment of 4: rows padded to 12 bytes. */
  GLubyte lum[9 * 12];
  memset(lum, 0, sizeof lum);
  for (int j = 0; j < 9; ++j)
    for (int i = 0; i < 10; ++i) lum[j * 12 + i] = (GLubyte)((i + j) % 3 == 0 ? 255 : 20 * i);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 44, 10, 10, 9, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
}

/* Something to copy: drawn in the 64x64 square at the window's lower left. */
static void draw_source(int variant) {
  glViewport(0, 0, 64, 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, 64, 0, 64);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(variant ? 0.9f : 0.1f, 0.2f, variant ? 0.2f : 0.4f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex2f(4, 4);
  glColor3f(0, 1, 0);
  glVertex2f(60, 10);
  glColor3f(0, 0, 1);
  glVertex2f(variant ? 50.0f : 20.0f, 60);
  glEnd();
  glColor3f(1, 1, variant ? 1.0f : 0.0f);
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= 20; ++i) {
    const double a = 2 * PI * i / 20;
    glVertex2d(40 + 10 * cos(a), 40 + 10 * sin(a));
    glVertex2d(40 + 16 * cos(a), 40 + 16 * sin(a));
  }
  glEnd();
}

static void display(void) {
  /* Render, copy into a texture, render again, copy into a quarter of it. */
  draw_source(0);
  glBindTexture(GL_TEXTURE_2D, copied);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 64, 64, 0);
  draw_source(1);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 32, 32, 8, 8, 32, 32);

  ortho();
  glClearColor(0.2f, 0.2f, 0.25f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  /* The patched texture at 2x. */
  glBindTexture(GL_TEXTURE_2D, patched);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2i(16, 56);
  glTexCoord2f(1, 0);
  glVertex2i(144, 56);
  glTexCoord2f(1, 1);
  glVertex2i(144, 184);
  glTexCoord2f(0, 1);
  glVertex2i(16, 184);
  glEnd();

  /* The copied texture, rotated, and straight at 1.5x. */
  glBindTexture(GL_TEXTURE_2D, copied);
  glPushMatrix();
  glTranslatef(230, 150, 0);
  glRotatef(20, 0, 0, 1);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(-60, -60);
  glTexCoord2f(1, 0);
  glVertex2f(60, -60);
  glTexCoord2f(1, 1);
  glVertex2f(60, 60);
  glTexCoord2f(0, 1);
  glVertex2f(-60, 60);
  glEnd();
  glPopMatrix();
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2i(180, 4);
  glTexCoord2f(1, 0);
  glVertex2i(276, 4);
  glTexCoord2f(1, 1);
  glVertex2i(276, 52);
  glTexCoord2f(0, 1);
  glVertex2i(180, 52);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(win_w, win_h);
  glutCreateWindow("15 texture sub-image and copy");
  glDisable(GL_DITHER);
  make_patched();
  glGenTextures(1, &copied);
  glBindTexture(GL_TEXTURE_2D, copied);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
