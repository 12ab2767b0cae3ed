/* 09_lights: several lights at once, per-vertex lighting on finely tessellated geometry.
 * LIGHT0 directional, dim white; LIGHT1 positional red with linear attenuation; LIGHT2 a
 * green spot (cutoff 25, exponent 8); LIGHT3 a blue spot (cutoff 40, exponent 2) with
 * constant + quadratic attenuation; LIGHT4 positional white with specular, lighting three
 * shiny spheres; GL_LIGHT_MODEL_AMBIENT raised. Positions given under the camera's
 * modelview; projection by glFrustum. */
#include <GL/glut.h>
#include <math.h>

#define PI 3.14159265358979323846

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double t = tan(22.5 * PI / 180.0); /* a 45 degree vertical field of view */
  glFrustum(-t * w / h, t * w / h, -t, t, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
}

static void sphere(double r, int slices, int stacks) {
  for (int j = 0; j < stacks; ++j) {
    const double t0 = PI * j / stacks - PI / 2, t1 = PI * (j + 1) / stacks - PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= slices; ++i) {
      const double p = 2 * PI * i / slices;
      glNormal3d(cos(t1) * cos(p), sin(t1), cos(t1) * sin(p));
      glVertex3d(r * cos(t1) * cos(p), r * sin(t1), r * cos(t1) * sin(p));
      glNormal3d(cos(t0) * cos(p), sin(t0), cos(t0) * sin(p));
      glVertex3d(r * cos(t0) * cos(p), r * sin(t0), r * cos(t0) * sin(p));
    }
    glEnd();
  }
}

static void floor_plane(void) {
  const int n = 48;
  const float size = 12.0f;
  glNormal3f(0, 1, 0);
  for (int j = 0; j < n; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= n; ++i) {
      const float x = -size / 2 + size * i / n;
      glVertex3f(x, 0, -size / 2 + size * (j + 1) / n);
      glVertex3f(x, 0, -size / 2 + size * j / n);
    }
    glEnd();
  }
}

static void material(float r, float g, float b, float spec, float shininess) {
  const GLfloat d[4] = {r, g, b, 1}, s[4] = {spec, spec, spec, 1};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, d);
  glMaterialfv(GL_FRONT, GL_SPECULAR, s);
  glMaterialf(GL_FRONT, GL_SHININESS, shininess);
}

static void display(void) {
  glClearColor(0.02f, 0.02f, 0.05f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glLoadIdentity();
  /* The eye at (0, 5, 9) looking at the origin. */
  glTranslated(0.0, 0.0, -sqrt(5.0 * 5.0 + 9.0 * 9.0));
  glRotated(atan2(5.0, 9.0) * 180.0 / PI, 1.0, 0.0, 0.0);

  const GLfloat black[4] = {0, 0, 0, 1};
  const GLfloat model_ambient[4] = {0.12f, 0.1f, 0.1f, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model_ambient);

  /* LIGHT0: directional, dim. */
  const GLfloat l0_dir[4] = {-0.3f, 1.0f, 0.5f, 0.0f}, l0_col[4] = {0.25f, 0.25f, 0.3f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, l0_dir);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, l0_col);
  glLightfv(GL_LIGHT0, GL_SPECULAR, black);

  /* LIGHT1: positional red, linear attenuation, low over the left. */
  const GLfloat l1_pos[4] = {-3.5f, 1.2f, 1.5f, 1.0f}, l1_col[4] = {1.0f, 0.25f, 0.2f, 1};
  glLightfv(GL_LIGHT1, GL_POSITION, l1_pos);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, l1_col);
  glLightfv(GL_LIGHT1, GL_SPECULAR, black);
  glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.2f);
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.5f);

  /* LIGHT2: green spot from above, pointing down and forward. */
  const GLfloat l2_pos[4] = {1.5f, 4.0f, 2.0f, 1.0f}, l2_dir[3] = {0.2f, -1.0f, 0.3f},
                l2_col[4] = {0.2f, 1.0f, 0.3f, 1};
  glLightfv(GL_LIGHT2, GL_POSITION, l2_pos);
  glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, l2_dir);
  glLightfv(GL_LIGHT2, GL_DIFFUSE, l2_col);
  glLightfv(GL_LIGHT2, GL_SPECULAR, black);
  glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 25.0f);
  glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 8.0f);

  /* LIGHT3: blue spot from the back right, quadratic attenuation. */
  const GLfloat l3_pos[4] = {3.5f, 2.5f, -3.0f, 1.0f}, l3_dir[3] = {-0.6f, -1.0f, 0.5f},
                l3_col[4] = {0.4f, 0.5f, 1.0f, 1};
  glLightfv(GL_LIGHT3, GL_POSITION, l3_pos);
  glLightfv(GL_LIGHT3, GL_SPOT_DIRECTION, l3_dir);
  glLightfv(GL_LIGHT3, GL_DIFFUSE, l3_col);
  glLightfv(GL_LIGHT3, GL_SPECULAR, black);
  glLightf(GL_LIGHT3, GL_SPOT_CUTOFF, 40.0f);
  glLightf(GL_LIGHT3, GL_SPOT_EXPONENT, 2.0f);
  glLightf(GL_LIGHT3, GL_CONSTANT_ATTENUATION, 0.5f);
  glLightf(GL_LIGHT3, GL_QUADRATIC_ATTENUATION, 0.04f);

  /* LIGHT4: white positional key light with specular, in front. */
  const GLfloat l4_pos[4] = {2.0f, 3.0f, 5.0f, 1.0f}, l4_col[4] = {0.5f, 0.5f, 0.5f, 1},
                l4_spec[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT4, GL_POSITION, l4_pos);
  glLightfv(GL_LIGHT4, GL_DIFFUSE, l4_col);
  glLightfv(GL_LIGHT4, GL_SPECULAR, l4_spec);

  glEnable(GL_LIGHTING);
  for (int i = 0; i < 5; ++i) glEnable(GL_LIGHT0 + i);
  glEnable(GL_DEPTH_TEST);

  material(0.8f, 0.8f, 0.8f, 0.0f, 1.0f);
  floor_plane();

  glPushMatrix();
  glTranslatef(-2.2f, 1.0f, 0.0f);
  material(0.9f, 0.9f, 0.9f, 0.8f, 40.0f);
  sphere(1.0, 32, 20);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(0.6f, 0.9f, 1.2f);
  material(1.0f, 0.8f, 0.5f, 0.6f, 15.0f);
  sphere(0.9, 32, 20);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(2.4f, 0.7f, -1.2f);
  material(0.6f, 0.7f, 1.0f, 1.0f, 90.0f);
  sphere(0.7, 32, 20);
  glPopMatrix();

  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(320, 240);
  glutCreateWindow("09 lights");
  glDisable(GL_DITHER);
  glShadeModel(GL_SMOOTH);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
