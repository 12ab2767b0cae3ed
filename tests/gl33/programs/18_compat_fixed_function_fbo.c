/*
 * Render to texture the way GL 2.1 course code does it, with no shaders at all (GLUT + GLEW,
 * the default compatibility context): a framebuffer object with a 128x128 RGBA8 texture and a
 * depth renderbuffer, a lit, smooth-shaded scene drawn into it with glBegin/glEnd and the
 * fixed-function pipeline, then glGenerateMipmap on what was rendered, and the texture mapped
 * with GL_MODULATE and trilinear filtering onto a spinning cube in the window, over a
 * glClear of a scissored region. Light, materials and matrices are GL 1.x state throughout.
 */
#include "common.h"

static GLuint fbo, tex, depth_rb;

static void draw_cube(float s) {
  static const float n[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  static const float v[6][4][3] = {
      {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}, {{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}},
      {{1, -1, 1}, {1, -1, -1}, {1, 1, -1}, {1, 1, 1}}, {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}},
      {{-1, 1, 1}, {1, 1, 1}, {1, 1, -1}, {-1, 1, -1}}, {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}}};
  static const float t[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  int f, i;
  glBegin(GL_QUADS);
  for (f = 0; f < 6; ++f) {
    glNormal3fv(n[f]);
    for (i = 0; i < 4; ++i) {
      glTexCoord2fv(t[i]);
      glVertex3f(v[f][i][0] * s, v[f][i][1] * s, v[f][i][2] * s);
    }
  }
  glEnd();
}

static void render_texture_scene(void) {
  const GLfloat light_pos[4] = {2.0f, 3.0f, 4.0f, 1.0f};
  const GLfloat red[4] = {0.9f, 0.25f, 0.2f, 1.0f}, blue[4] = {0.2f, 0.35f, 0.9f, 1.0f};
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, 128, 128);
  glClearColor(0.95f, 0.9f, 0.6f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -1, 1, 2, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -5);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_TEXTURE_2D);
  glPushMatrix();
  glRotatef(30, 1, 1, 0);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, red);
  draw_cube(0.8f);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0.9f, -0.7f, 0.6f);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, blue);
  draw_cube(0.35f);
  glPopMatrix();
  glDisable(GL_LIGHTING);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  /* Mipmaps of what was just rendered, for the minified faces below. */
  glBindTexture(GL_TEXTURE_2D, tex);
  glGenerateMipmap(GL_TEXTURE_2D);
}

static void display(void) {
  render_texture_scene();
  glViewport(0, 0, 320, 240);
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(20, 20, 280, 200);
  glClearColor(0.25f, 0.3f, 0.35f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, 320.0 / 240.0, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -6);
  glRotatef(25, 1, 0, 0);
  glRotatef(35, 0, 1, 0);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor3f(1.0f, 0.95f, 0.9f);
  draw_cube(1.2f);
  /* A small far copy that samples the smaller levels. */
  glLoadIdentity();
  glTranslatef(2.6f, -1.4f, -10.0f);
  glRotatef(40, 1, 1, 0);
  draw_cube(0.6f);
  glDisable(GL_TEXTURE_2D);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  open_window(&argc, argv, 0, 0, 0, "fixed function fbo");
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 128, 128, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glGenRenderbuffers(1, &depth_rb);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 128, 128);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    fprintf(stderr, "framebuffer incomplete\n");
    return 1;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
