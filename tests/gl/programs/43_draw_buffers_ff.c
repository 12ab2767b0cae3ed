/* 43_draw_buffers_ff: where fixed-function fragments go (GL 2.1 section 4.2.1).
 *  - glDrawBuffer(GL_FRONT_AND_BACK) in a double-buffered window: a cleared background and a
 *    smooth triangle reach both buffers; then a quad drawn to GL_BACK only. The front buffer
 *    is read (glReadBuffer(GL_FRONT), glReadPixels) and drawn into the back buffer at the
 *    right: it has the triangle and not the quad.
 *  - a framebuffer object with two colour textures and glDrawBuffers of both: a smooth quad
 *    drawn by fixed function lands in both; the two textures are shown side by side at the
 *    bottom. */
#define GL_GLEXT_PROTOTYPES 1 /* GL/gl.h then declares the GL 2.0 and 3.0 calls of GL/glext.h */
#include <GL/glut.h>

static const int W = 320, H = 240;
static GLuint fbo, tex[2];

static void ortho(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void init(void) {
  glGenTextures(2, tex);
  for (int i = 0; i < 2; ++i) {
    glBindTexture(GL_TEXTURE_2D, tex[i]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex[1], 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

static void display(void) {
  ortho();
  glDrawBuffer(GL_FRONT_AND_BACK);
  glClearColor(0.1f, 0.15f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex2f(20, 120);
  glColor3f(0, 1, 0);
  glVertex2f(140, 120);
  glColor3f(0, 0, 1);
  glVertex2f(80, 230);
  glEnd();
  glDrawBuffer(GL_BACK);
  glColor3f(1, 1, 0);
  glRectf(100, 130, 150, 170);
  /* The front buffer, read and drawn at the right of the back one. */
  static GLubyte front[120][150][4];
  glReadBuffer(GL_FRONT);
  glReadPixels(10, 115, 150, 120, GL_RGBA, GL_UNSIGNED_BYTE, front);
  glReadBuffer(GL_BACK);
  glRasterPos2i(165, 115);
  glDrawPixels(150, 120, GL_RGBA, GL_UNSIGNED_BYTE, front);

  /* Fixed function into two colour attachments. */
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, both);
  glViewport(0, 0, 64, 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 64, 0, 64, -1, 1);
  glClearColor(0.3f, 0.3f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_QUADS);
  glColor3f(1, 0.5f, 0);
  glVertex2f(8, 8);
  glColor3f(0, 1, 0.5f);
  glVertex2f(56, 8);
  glColor3f(0.5f, 0, 1);
  glVertex2f(56, 56);
  glColor3f(1, 1, 1);
  glVertex2f(8, 56);
  glEnd();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDrawBuffer(GL_BACK);
  glViewport(0, 0, W, H);
  ortho();
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (int i = 0; i < 2; ++i) {
    glBindTexture(GL_TEXTURE_2D, tex[i]);
    const float x = 20.0f + 140.0f * (float)i;
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f(x, 10);
    glTexCoord2f(1, 0);
    glVertex2f(x + 96, 10);
    glTexCoord2f(1, 1);
    glVertex2f(x + 96, 106);
    glTexCoord2f(0, 1);
    glVertex2f(x, 106);
    glEnd();
  }
  glDisable(GL_TEXTURE_2D);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(W, H);
  glutCreateWindow("43_draw_buffers_ff");
  init();
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
