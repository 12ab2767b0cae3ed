/* 21_cull_faces: face culling. A box with its front face missing (so its inside shows) and
 * a closed pyramid, in six viewports: no culling; glCullFace(GL_BACK); GL_FRONT;
 * GL_FRONT_AND_BACK (nothing filled, but the box's white edges, drawn as lines on top, are
 * not culled);
 * glFrontFace(GL_CW) with GL_BACK; and GL_BACK with the modelview mirrored by
 * glScalef(-1, 1, 1) (a mirror flips the winding in window space). */
#include <GL/glut.h>

static int win_w = 318, win_h = 212;

static void reshape(int w, int h) {
  win_w = w;
  win_h = h;
}

static void open_box(void) {
  /* Faces wound counter-clockwise seen from outside; the +z face is left out. */
  static const GLfloat c[5][3] = {
      {0.9f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.2f}, {0.2f, 0.4f, 1.0f}, {0.95f, 0.85f, 0.2f}, {0.8f, 0.3f, 0.9f}};
  static const GLfloat v[5][4][3] = {{{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},
                                     {{-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}, {-1, -1, -1}},
                                     {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}},
                                     {{-1, -1, 1}, {-1, -1, -1}, {1, -1, -1}, {1, -1, 1}},
                                     {{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}}};
  glBegin(GL_QUADS);
  for (int f = 0; f < 5; ++f) {
    glColor3fv(c[f]);
    for (int k = 0; k < 4; ++k) glVertex3fv(v[f][k]);
  }
  glEnd();
}

/* The box's edges as lines, drawn without the depth test (lines lying on polygon edges
   would otherwise z-fight with them, which conforming implementations resolve differently). */
static void box_edges(void) {
  static const GLfloat v[5][4][3] = {{{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},
                                     {{-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}, {-1, -1, -1}},
                                     {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}},
                                     {{-1, -1, 1}, {-1, -1, -1}, {1, -1, -1}, {1, -1, 1}},
                                     {{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}}};
  glDisable(GL_DEPTH_TEST);
  glColor3f(1, 1, 1);
  for (int f = 0; f < 5; ++f) {
    glBegin(GL_LINE_LOOP);
    for (int k = 0; k < 4; ++k) glVertex3fv(v[f][k]);
    glEnd();
  }
  glEnable(GL_DEPTH_TEST);
}

static void pyramid(void) {
  glBegin(GL_TRIANGLES);
  static const GLfloat apex[3] = {0, 1.2f, 0};
  static const GLfloat base[4][3] = {
      {-0.8f, -0.6f, 0.8f}, {0.8f, -0.6f, 0.8f}, {0.8f, -0.6f, -0.8f}, {-0.8f, -0.6f, -0.8f}};
  for (int i = 0; i < 4; ++i) {
    glColor3f(0.3f + 0.2f * i, 0.9f - 0.2f * i, 0.5f);
    glVertex3fv(base[i]);
    glVertex3fv(base[(i + 1) % 4]);
    glVertex3fv(apex);
  }
  glColor3f(0.4f, 0.4f, 0.4f);
  glVertex3fv(base[0]);
  glVertex3fv(base[2]);
  glVertex3fv(base[1]);
  glVertex3fv(base[0]);
  glVertex3fv(base[3]);
  glVertex3fv(base[2]);
  glEnd();
}

static void display(void) {
  const int cw = win_w / 3, ch = win_h / 2;
  glClearColor(0.12f, 0.12f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  for (int cell = 0; cell < 6; ++cell) {
    glViewport((cell % 3) * cw + 1, win_h - (cell / 3 + 1) * ch + 1, cw - 2, ch - 2);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.5, 0.5, 1.5, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -6);
    glRotatef(25, 1, 0, 0);
    glRotatef(-35, 0, 1, 0);
    if (cell == 5) glScalef(-1, 1, 1);

    glFrontFace(GL_CCW);
    glDisable(GL_CULL_FACE);
    switch (cell) {
      case 1:
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        break;
      case 2:
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
        break;
      case 3:
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT_AND_BACK);
        break;
      case 4:
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFrontFace(GL_CW);
        break;
      case 5:
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        break;
      default: break;
    }
    glPushMatrix();
    glTranslatef(-0.4f, 0, 0.3f);
    glScalef(0.85f, 0.85f, 0.85f);
    open_box();
    glPopMatrix();
    glPushMatrix();
    glTranslatef(1.0f, -0.2f, -1.9f);
    glScalef(0.8f, 0.8f, 0.8f);
    pyramid();
    glPopMatrix();
    glPushMatrix();
    glTranslatef(-0.4f, 0, 0.3f);
    glScalef(0.85f, 0.85f, 0.85f);
    box_edges();
    glPopMatrix();
  }
  glDisable(GL_CULL_FACE);
  glFrontFace(GL_CCW);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(win_w, win_h);
  glutCreateWindow("21 face culling");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
