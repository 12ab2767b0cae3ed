/* 28_glu_camera: the GLU camera helpers. A small town of coloured boxes on a checkerboard,
 * seen through gluPerspective + gluLookAt from a corner; an inset viewport looks straight
 * down with gluLookAt and a non-default up vector (0, 0, -1) under a narrower
 * gluPerspective, and a third, rolled view uses an up vector tilted sideways; a 2D frame and
 * compass are drawn over the insets with gluOrtho2D. */
#include <GL/glut.h>

static int win_w = 320, win_h = 240;

static void reshape(int w, int h) {
  win_w = w;
  win_h = h;
}

static void box(float x, float z, float w, float d, float h, float r, float g, float b) {
  const float x0 = x - w / 2, x1 = x + w / 2, z0 = z - d / 2, z1 = z + d / 2;
  glBegin(GL_QUADS);
  glColor3f(r, g, b); /* +z */
  glVertex3f(x0, 0, z1);
  glVertex3f(x1, 0, z1);
  glVertex3f(x1, h, z1);
  glVertex3f(x0, h, z1);
  glColor3f(r * 0.7f, g * 0.7f, b * 0.7f); /* +x */
  glVertex3f(x1, 0, z1);
  glVertex3f(x1, 0, z0);
  glVertex3f(x1, h, z0);
  glVertex3f(x1, h, z1);
  glColor3f(r * 0.5f, g * 0.5f, b * 0.5f); /* -z */
  glVertex3f(x1, 0, z0);
  glVertex3f(x0, 0, z0);
  glVertex3f(x0, h, z0);
  glVertex3f(x1, h, z0);
  glColor3f(r * 0.6f, g * 0.6f, b * 0.6f); /* -x */
  glVertex3f(x0, 0, z0);
  glVertex3f(x0, 0, z1);
  glVertex3f(x0, h, z1);
  glVertex3f(x0, h, z0);
  glColor3f(r * 0.9f + 0.1f, g * 0.9f + 0.1f, b * 0.9f + 0.1f); /* top */
  glVertex3f(x0, h, z1);
  glVertex3f(x1, h, z1);
  glVertex3f(x1, h, z0);
  glVertex3f(x0, h, z0);
  glEnd();
}

static void town(void) {
  glBegin(GL_QUADS);
  for (int j = -6; j < 6; ++j)
    for (int i = -6; i < 6; ++i) {
      if ((i + j) % 2)
        glColor3f(0.35f, 0.45f, 0.35f);
      else
        glColor3f(0.55f, 0.6f, 0.5f);
      glVertex3f((float)i, 0, (float)j + 1);
      glVertex3f((float)i + 1, 0, (float)j + 1);
      glVertex3f((float)i + 1, 0, (float)j);
      glVertex3f((float)i, 0, (float)j);
    }
  glEnd();
  box(-3.0f, -3.0f, 1.5f, 1.5f, 3.0f, 0.9f, 0.3f, 0.3f);
  box(0.0f, -3.5f, 2.0f, 1.0f, 1.5f, 0.3f, 0.6f, 0.9f);
  box(3.0f, -2.5f, 1.0f, 2.0f, 2.2f, 0.9f, 0.8f, 0.3f);
  box(-2.5f, 1.0f, 1.2f, 2.5f, 1.0f, 0.6f, 0.3f, 0.8f);
  box(1.5f, 1.0f, 1.5f, 1.5f, 4.0f, 0.3f, 0.8f, 0.5f);
  box(3.5f, 3.5f, 1.0f, 1.0f, 0.8f, 0.9f, 0.6f, 0.2f);
  box(-1.0f, 4.0f, 3.0f, 0.8f, 0.6f, 0.7f, 0.7f, 0.9f);
}

static void frame(int x, int y, int w, int h) {
  glViewport(0, 0, win_w, win_h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, win_w, 0, win_h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glColor3f(1, 1, 1);
  glBegin(GL_LINE_LOOP);
  glVertex2f(x + 0.5f, y + 0.5f);
  glVertex2f(x + w - 0.5f, y + 0.5f);
  glVertex2f(x + w - 0.5f, y + h - 0.5f);
  glVertex2f(x + 0.5f, y + h - 0.5f);
  glEnd();
  glEnable(GL_DEPTH_TEST);
}

static void display(void) {
  glClearColor(0.5f, 0.7f, 0.9f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  /* Main view. */
  glViewport(0, 0, win_w, win_h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(50.0, (double)win_w / win_h, 0.5, 50.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(7.0, 6.0, 9.0, 0.0, 0.5, 0.0, 0.0, 1.0, 0.0);
  town();

  /* Top-down inset (upper right), north (-z) up. */
  const int iw = 100, ih = 76;
  glEnable(GL_SCISSOR_TEST);
  glScissor(win_w - iw, win_h - ih, iw, ih);
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glViewport(win_w - iw, win_h - ih, iw, ih);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(30.0, (double)iw / ih, 1.0, 50.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 24.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0);
  town();

  /* Rolled inset (upper left): up vector tilted. */
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, win_h - ih, iw, ih);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, win_h - ih, iw, ih);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60.0, (double)iw / ih, 0.5, 50.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(-6.0, 2.5, 6.0, 0.0, 1.0, 0.0, 0.5, 1.0, 0.2);
  town();

  frame(win_w - iw, win_h - ih, iw, ih);
  frame(0, win_h - ih, iw, ih);
  /* Compass: a north arrow below the top-down inset. */
  glBegin(GL_TRIANGLES);
  glColor3f(0.9f, 0.1f, 0.1f);
  glVertex2f(win_w - 20.0f, win_h - ih - 30.0f);
  glVertex2f(win_w - 10.0f, win_h - ih - 30.0f);
  glVertex2f(win_w - 15.0f, win_h - ih - 6.0f);
  glEnd();
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(win_w, win_h);
  glutCreateWindow("28 GLU camera");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
