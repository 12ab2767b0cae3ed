/* 07_viewports_depth_range: four glViewports in one window, each cleared to its own colour
 * through a glScissor'ed glClear, showing one scene (a cube with coloured faces pierced by a
 * tilted square, and a pyramid):
 *   lower left : front view, glOrtho;
 *   lower right: top view, glOrtho, with a reversed glDepthRange(1, 0), glClearDepth(0)
 *                and glDepthFunc(GL_GREATER) (looks like a normal depth test);
 *   upper left : perspective (glFrustum) with the cube in glDepthRange(0, 0.5) and the rest in
 *                glDepthRange(0.5, 1): the cube is never hidden by the square;
 *   upper right: the same perspective view with the full depth range. */
#include <GL/glut.h>

static int win_w = 320, win_h = 240;

static void reshape(int w, int h) {
  win_w = w;
  win_h = h;
}

static void cube(void) {
  static const GLfloat c[6][3] = {{1, 0.2f, 0.2f}, {0.2f, 1, 0.2f}, {0.2f, 0.2f, 1},
                                  {1, 1, 0.2f},    {1, 0.2f, 1},    {0.2f, 1, 1}};
  static const GLfloat v[6][4][3] = {
      {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}}, {{-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}, {-1, -1, -1}},
      {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}}, {{-1, -1, 1}, {-1, -1, -1}, {1, -1, -1}, {1, -1, 1}},
      {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}, {{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}}};
  glBegin(GL_QUADS);
  for (int f = 0; f < 6; ++f) {
    glColor3fv(c[f]);
    for (int k = 0; k < 4; ++k) glVertex3fv(v[f][k]);
  }
  glEnd();
}

static void square(void) {
  glPushMatrix();
  glRotatef(35, 1, 0, 0);
  glRotatef(-20, 0, 1, 0);
  glBegin(GL_QUADS);
  glColor3f(0.95f, 0.95f, 0.95f);
  glVertex3f(-2.2f, 0, -2.2f);
  glColor3f(0.6f, 0.6f, 0.65f);
  glVertex3f(-2.2f, 0, 2.2f);
  glColor3f(0.35f, 0.35f, 0.4f);
  glVertex3f(2.2f, 0, 2.2f);
  glColor3f(0.75f, 0.75f, 0.8f);
  glVertex3f(2.2f, 0, -2.2f);
  glEnd();
  glPopMatrix();
}

static void pyramid(void) {
  glPushMatrix();
  glTranslatef(2.3f, -1.0f, 0.6f);
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1, 1, 1);
  glVertex3f(0, 1.6f, 0);
  glColor3f(1, 0.5f, 0);
  glVertex3f(-0.7f, 0, 0.7f);
  glColor3f(0.5f, 0, 1);
  glVertex3f(0.7f, 0, 0.7f);
  glColor3f(0, 0.6f, 0.3f);
  glVertex3f(0.7f, 0, -0.7f);
  glColor3f(0.6f, 0.1f, 0.1f);
  glVertex3f(-0.7f, 0, -0.7f);
  glColor3f(1, 0.5f, 0);
  glVertex3f(-0.7f, 0, 0.7f);
  glEnd();
  glPopMatrix();
}

/* The scene under the current projection; split = put the cube in front. */
static void scene(int split) {
  glPushMatrix();
  glRotatef(25, 0, 1, 0);
  glRotatef(10, 1, 0, 0);
  if (split) glDepthRange(0.0, 0.5);
  glPushMatrix();
  glRotatef(30, 0, 1, 0);
  glScalef(0.9f, 0.9f, 0.9f);
  cube();
  glPopMatrix();
  if (split) glDepthRange(0.5, 1.0);
  square();
  pyramid();
  glPopMatrix();
  if (split) glDepthRange(0.0, 1.0);
}

static void begin_view(int x, int y, int w, int h, float r, float g, float b, double clear_depth) {
  glViewport(x, y, w, h);
  glScissor(x, y, w, h);
  glEnable(GL_SCISSOR_TEST);
  glClearColor(r, g, b, 1.0f);
  glClearDepth(clear_depth);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

static void display(void) {
  const int hw = win_w / 2, hh = win_h / 2;
  const double aspect = (double)hw / hh;
  glEnable(GL_DEPTH_TEST);

  /* Front view. */
  begin_view(0, 0, hw - 1, hh - 1, 0.15f, 0.15f, 0.25f, 1.0);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-3.2 * aspect, 3.2 * aspect, -3.2, 3.2, -10, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDepthFunc(GL_LESS);
  scene(0);

  /* Top view, reversed depth range. */
  begin_view(hw + 1, 0, win_w - hw - 1, hh - 1, 0.25f, 0.15f, 0.15f, 0.0);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-3.2 * aspect, 3.2 * aspect, -3.2, 3.2, -10, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(90, 1, 0, 0);
  glDepthRange(1.0, 0.0);
  glDepthFunc(GL_GREATER);
  scene(0);
  glDepthRange(0.0, 1.0);
  glDepthFunc(GL_LESS);

  /* Perspective views. */
  for (int split = 1; split >= 0; --split) {
    const int x = split ? 0 : hw + 1;
    begin_view(x, hh + 1, split ? hw - 1 : win_w - hw - 1, win_h - hh - 1, split ? 0.15f : 0.2f, 0.25f,
               split ? 0.15f : 0.2f, 1.0);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.45 * aspect, 0.45 * aspect, -0.45, 0.45, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.3f, -0.2f, -7.0f);
    glRotatef(20, 1, 0, 0);
    scene(split);
  }
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(win_w, win_h);
  glutCreateWindow("07 viewports and depth range");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
