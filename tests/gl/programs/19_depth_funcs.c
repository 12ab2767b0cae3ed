/* 19_depth_funcs: the eight depth functions, one per viewport, and glDepthMask.
 * In each cell a red sphere is drawn with GL_LESS; then, with the function under test, the
 * same sphere again in blue (exactly the same depths: passes only for EQUAL, LEQUAL, GEQUAL
 * and ALWAYS) and a tilted, green-yellow square cutting through it (in front of the sphere
 * for LESS/LEQUAL/NOTEQUAL, behind it for GREATER/GEQUAL, everywhere for ALWAYS, nowhere
 * for NEVER, and, where there is no sphere, only where it passes against the cleared 1.0).
 * The ninth cell draws the square with glDepthMask(GL_FALSE) before the sphere: the
 * sphere then shows whole. The spheres are drawn with back faces culled, so that no
 * fragment's depth ties with another's except for the deliberate repaint. */
#include <GL/glut.h>
#include <math.h>

#define PI 3.14159265358979323846

static int win_w = 318, win_h = 240;

static void reshape(int w, int h) {
  win_w = w;
  win_h = h;
}

static void sphere(float r, float g, float b) {
  const int slices = 24, stacks = 14;
  for (int j = 0; j < stacks; ++j) {
    const double t0 = PI * j / stacks - PI / 2, t1 = PI * (j + 1) / stacks - PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= slices; ++i) {
      const double p = 2 * PI * i / slices;
      const float s1 = (float)(0.45 + 0.35 * sin(t1) + 0.2 * cos(p)),
                  s0 = (float)(0.45 + 0.35 * sin(t0) + 0.2 * cos(p));
      glColor3f(r * s1, g * s1, b * s1);
      glVertex3d(cos(t1) * sin(p), sin(t1), cos(t1) * cos(p));
      glColor3f(r * s0, g * s0, b * s0);
      glVertex3d(cos(t0) * sin(p), sin(t0), cos(t0) * cos(p));
    }
    glEnd();
  }
}

static void square(void) {
  glPushMatrix();
  glRotatef(50, 1, 0, 0);
  glRotatef(25, 0, 1, 0);
  glBegin(GL_QUADS);
  glColor3f(0.2f, 0.8f, 0.2f);
  glVertex3f(-1.6f, -1.6f, 0);
  glColor3f(0.9f, 0.9f, 0.2f);
  glVertex3f(1.6f, -1.6f, 0);
  glColor3f(0.6f, 1.0f, 0.5f);
  glVertex3f(1.6f, 1.6f, 0);
  glColor3f(0.9f, 0.7f, 0.1f);
  glVertex3f(-1.6f, 1.6f, 0);
  glEnd();
  glPopMatrix();
}

static void display(void) {
  static const GLenum funcs[8] = {GL_NEVER,   GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                                  GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
  const int cw = win_w / 3, ch = win_h / 3;
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_SCISSOR_TEST);
  for (int cell = 0; cell < 9; ++cell) {
    const int x = (cell % 3) * cw, y = win_h - (cell / 3 + 1) * ch;
    glViewport(x + 1, y + 1, cw - 2, ch - 2);
    glScissor(x, y, cw, ch);
    glClearColor(0.1f + 0.03f * cell, 0.1f, 0.15f, 1.0f);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    const double aspect = (double)(cw - 2) / (ch - 2);
    glOrtho(-1.45 * aspect, 1.45 * aspect, -1.45, 1.45, -3, 3);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(20, 1, 0, 0);
    if (cell < 8) {
      glDepthFunc(GL_LESS);
      glEnable(GL_CULL_FACE);
      sphere(1.0f, 0.3f, 0.25f);
      glDepthFunc(funcs[cell]);
      sphere(0.3f, 0.45f, 1.0f);
      glDisable(GL_CULL_FACE);
      square();
    } else {
      glDepthFunc(GL_LESS);
      glDepthMask(GL_FALSE);
      square();
      glDepthMask(GL_TRUE);
      glEnable(GL_CULL_FACE);
      sphere(1.0f, 0.3f, 0.25f);
      glDisable(GL_CULL_FACE);
    }
  }
  glDisable(GL_SCISSOR_TEST);
  glDepthFunc(GL_LESS);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(win_w, win_h);
  glutCreateWindow("19 depth functions");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
