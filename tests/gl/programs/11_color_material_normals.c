/* 11_color_material_normals: glColorMaterial and normal scaling.
 * Top row, glEnable(GL_COLOR_MATERIAL) with per-vertex rainbow colours tracking
 * GL_AMBIENT_AND_DIFFUSE, GL_DIFFUSE, GL_SPECULAR and GL_EMISSION (on GL_FRONT).
 * Bottom row, unit spheres under scaling modelviews: non-uniform glScalef with GL_NORMALIZE,
 * uniform glScalef(0.6) with GL_RESCALE_NORMAL, the same uniform scale with neither (normals
 * too long: brighter, sharper highlight), and non-uniform with neither. */
#include <GL/glut.h>
#include <math.h>

#define PI 3.14159265358979323846

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-2.0 * w / h, 2.0 * w / h, -2.0, 2.0, -10, 10);
  glMatrixMode(GL_MODELVIEW);
}

static void rainbow(double u, double v) {
  glColor3d(0.5 + 0.5 * cos(2 * PI * u), 0.5 + 0.5 * cos(2 * PI * (u - 1.0 / 3) + v),
            0.5 + 0.5 * cos(2 * PI * (u - 2.0 / 3)));
}

/* A unit sphere with unit normals, optionally coloured per vertex. */
static void sphere(int coloured) {
  const int slices = 30, stacks = 18;
  for (int j = 0; j < stacks; ++j) {
    const double t0 = PI * j / stacks - PI / 2, t1 = PI * (j + 1) / stacks - PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= slices; ++i) {
      const double p = 2 * PI * i / slices;
      if (coloured) rainbow((double)i / slices, t1);
      glNormal3d(cos(t1) * sin(p), sin(t1), cos(t1) * cos(p));
      glVertex3d(cos(t1) * sin(p), sin(t1), cos(t1) * cos(p));
      if (coloured) rainbow((double)i / slices, t0);
      glNormal3d(cos(t0) * sin(p), sin(t0), cos(t0) * cos(p));
      glVertex3d(cos(t0) * sin(p), sin(t0), cos(t0) * cos(p));
    }
    glEnd();
  }
}

static void material(float ar, float ag, float ab, float dr, float dg, float db, float s, float shin) {
  const GLfloat a[4] = {ar, ag, ab, 1}, d[4] = {dr, dg, db, 1}, sp[4] = {s, s, s, 1}, e[4] = {0, 0, 0, 1};
  glMaterialfv(GL_FRONT, GL_AMBIENT, a);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, d);
  glMaterialfv(GL_FRONT, GL_SPECULAR, sp);
  glMaterialfv(GL_FRONT, GL_EMISSION, e);
  glMaterialf(GL_FRONT, GL_SHININESS, shin);
}

static void display(void) {
  static const GLenum modes[4] = {GL_AMBIENT_AND_DIFFUSE, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION};
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLoadIdentity();
  const GLfloat light[4] = {-0.5f, 0.7f, 1.0f, 0.0f}, amb[4] = {0.3f, 0.3f, 0.3f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);

  for (int i = 0; i < 4; ++i) {
    material(0.2f, 0.2f, 0.2f, 0.5f, 0.5f, 0.5f, 0.6f, 20);
    glColorMaterial(GL_FRONT, modes[i]);
    glEnable(GL_COLOR_MATERIAL);
    glPushMatrix();
    glTranslatef(-1.98f + 1.32f * i, 0.95f, 0);
    glRotatef(20, 1, 0, 0);
    glScalef(0.62f, 0.62f, 0.62f);
    glEnable(GL_NORMALIZE);
    sphere(1);
    glDisable(GL_NORMALIZE);
    glPopMatrix();
    glDisable(GL_COLOR_MATERIAL);
  }

  for (int i = 0; i < 4; ++i) {
    material(0.1f, 0.1f, 0.1f, 0.4f, 0.6f, 0.9f, 0.7f, 30);
    glPushMatrix();
    glTranslatef(-1.98f + 1.32f * i, -0.95f, 0);
    glRotatef(30, 0, 0, 1);
    if (i == 0 || i == 3)
      glScalef(0.62f, 0.42f, 0.9f);
    else
      glScalef(0.6f, 0.6f, 0.6f);
    if (i == 0) glEnable(GL_NORMALIZE);
    if (i == 1) glEnable(GL_RESCALE_NORMAL);
    sphere(0);
    glDisable(GL_NORMALIZE);
    glDisable(GL_RESCALE_NORMAL);
    glPopMatrix();
  }
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(320, 200);
  glutCreateWindow("11 colour material and normals");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
