/* 17_fog: glFog in GL_LINEAR (start 1, end 16), GL_EXP (density 0.16) and GL_EXP2 (density
 * 0.12) modes, one per horizontal viewport, on a finely tessellated checkerboard floor and
 * a line of spheres receding from the viewer. The floor quads are one unit deep so that
 * computing fog per vertex or per fragment gives the same picture within a rounding step.
 * The fog distance is the eye-space |z| (the approximation the GL spec allows and Mesa
 * uses). */
#include <GL/glut.h>
#include <math.h>

#define PI 3.14159265358979323846

static int win_w = 320, win_h = 240;

static void reshape(int w, int h) {
  win_w = w;
  win_h = h;
}

static void sphere(double r) {
  const int slices = 20, stacks = 12;
  for (int j = 0; j < stacks; ++j) {
    const double t0 = PI * j / stacks - PI / 2, t1 = PI * (j + 1) / stacks - PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= slices; ++i) {
      const double p = 2 * PI * i / slices;
      const double shade0 = 0.55 + 0.45 * sin(t0) * 0.5 + 0.25 * cos(p);
      const double shade1 = 0.55 + 0.45 * sin(t1) * 0.5 + 0.25 * cos(p);
      glColor3d(0.9 * shade1, 0.3 * shade1, 0.2 + 0.2 * shade1);
      glVertex3d(r * cos(t1) * sin(p), r * sin(t1), r * cos(t1) * cos(p));
      glColor3d(0.9 * shade0, 0.3 * shade0, 0.2 + 0.2 * shade0);
      glVertex3d(r * cos(t0) * sin(p), r * sin(t0), r * cos(t0) * cos(p));
    }
    glEnd();
  }
}

static void floor_grid(void) {
  glBegin(GL_QUADS);
  for (int z = 0; z < 24; ++z)
    for (int x = -8; x < 8; ++x) {
      if ((x + z) % 2)
        glColor3f(0.15f, 0.5f, 0.2f);
      else
        glColor3f(0.9f, 0.9f, 0.6f);
      glVertex3f((float)x, 0, (float)-z);
      glVertex3f((float)x + 1, 0, (float)-z);
      glVertex3f((float)x + 1, 0, (float)-z - 1);
      glVertex3f((float)x, 0, (float)-z - 1);
    }
  glEnd();
}

static void scene(void) {
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(22, 1, 0, 0);
  glTranslatef(0.3f, -2.4f, 0.0f);
  floor_grid();
  for (int i = 0; i < 7; ++i) {
    glPushMatrix();
    glTranslatef(-2.5f + 1.1f * i, 0.6f, -2.5f - 2.6f * i);
    sphere(0.6);
    glPopMatrix();
  }
}

static void display(void) {
  static const GLfloat fog_colour[4] = {0.7f, 0.75f, 0.82f, 1.0f};
  static const GLenum modes[3] = {GL_LINEAR, GL_EXP, GL_EXP2};
  const int band = win_h / 3;
  glClearColor(fog_colour[0], fog_colour[1], fog_colour[2], 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_FOG);
  glFogfv(GL_FOG_COLOR, fog_colour);
  glFogf(GL_FOG_START, 1.0f);
  glFogf(GL_FOG_END, 16.0f);
  for (int i = 0; i < 3; ++i) {
    glViewport(0, win_h - band * (i + 1), win_w, band - 2);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    const double aspect = (double)win_w / (band - 2);
    glFrustum(-0.25 * aspect, 0.25 * aspect, -0.25, 0.25, 0.5, 40.0);
    glFogi(GL_FOG_MODE, (GLint)modes[i]);
    glFogf(GL_FOG_DENSITY, i == 1 ? 0.16f : 0.12f);
    scene();
  }
  glDisable(GL_FOG);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(win_w, win_h);
  glutCreateWindow("17 fog");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
