/* 10_light_model: materials and the light model.
 * Top row, five spheres: glMaterial GL_AMBIENT (under a strong GL_LIGHT_MODEL_AMBIENT),
 * GL_DIFFUSE, GL_SPECULAR with high and low GL_SHININESS, GL_EMISSION.
 * Bottom left: an open half tube with GL_LIGHT_MODEL_TWO_SIDE, different GL_FRONT and
 * GL_BACK materials (the inside is lit with the back material and the reversed normal).
 * Bottom right: two shiny tessellated panels under a directional light, the left with the
 * infinite viewer, the right with GL_LIGHT_MODEL_LOCAL_VIEWER (the highlight moves). */
#include <GL/glut.h>
#include <math.h>

#define PI 3.14159265358979323846

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5 * w / h, 0.5 * w / h, -0.5, 0.5, 1.5, 30.0);
  glMatrixMode(GL_MODELVIEW);
}

static void sphere(double r, int slices, int stacks) {
  for (int j = 0; j < stacks; ++j) {
    const double t0 = PI * j / stacks - PI / 2, t1 = PI * (j + 1) / stacks - PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= slices; ++i) {
      const double p = 2 * PI * i / slices;
      glNormal3d(cos(t1) * cos(p), sin(t1), -cos(t1) * sin(p));
      glVertex3d(r * cos(t1) * cos(p), r * sin(t1), -r * cos(t1) * sin(p));
      glNormal3d(cos(t0) * cos(p), sin(t0), -cos(t0) * sin(p));
      glVertex3d(r * cos(t0) * cos(p), r * sin(t0), -r * cos(t0) * sin(p));
    }
    glEnd();
  }
}

/* Half a tube around the y axis, opening towards the viewer (+z), outward normals; wound
   so that the outside is front-facing and the inside, seen through the opening, back-facing. */
static void half_tube(double r, double h) {
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= 24; ++i) {
    const double a = PI * i / 24 + 0.35;
    glNormal3d(cos(a), 0, -sin(a));
    glVertex3d(r * cos(a), h / 2, -r * sin(a));
    glVertex3d(r * cos(a), -h / 2, -r * sin(a));
  }
  glEnd();
}

static void panel(float half) { /* unit normals: no scaling on the modelview */
  glNormal3f(0, 0, 1);
  for (int j = 0; j < 16; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= 16; ++i) {
      glVertex3f(half * (-1 + i / 8.0f), half * (-1 + (j + 1) / 8.0f), 0);
      glVertex3f(half * (-1 + i / 8.0f), half * (-1 + j / 8.0f), 0);
    }
    glEnd();
  }
}

static void set4(GLenum face, GLenum what, float r, float g, float b) {
  const GLfloat v[4] = {r, g, b, 1};
  glMaterialfv(face, what, v);
}

static void reset_material(void) {
  set4(GL_FRONT_AND_BACK, GL_AMBIENT, 0, 0, 0);
  set4(GL_FRONT_AND_BACK, GL_DIFFUSE, 0, 0, 0);
  set4(GL_FRONT_AND_BACK, GL_SPECULAR, 0, 0, 0);
  set4(GL_FRONT_AND_BACK, GL_EMISSION, 0, 0, 0);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0);
}

static void display(void) {
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLoadIdentity();
  const GLfloat l0_pos[4] = {-0.4f, 0.6f, 1.0f, 0.0f}, white[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, l0_pos);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glTranslatef(0, 0, -6);

  /* Top row of spheres. */
  const GLfloat strong_ambient[4] = {0.6f, 0.6f, 0.6f, 1};
  const GLfloat low_ambient[4] = {0.1f, 0.1f, 0.1f, 1};
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FALSE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  for (int i = 0; i < 5; ++i) {
    reset_material();
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, i == 0 ? strong_ambient : low_ambient);
    switch (i) {
      case 0: set4(GL_FRONT, GL_AMBIENT, 0.9f, 0.3f, 0.2f); break;
      case 1: set4(GL_FRONT, GL_DIFFUSE, 0.2f, 0.8f, 0.3f); break;
      case 2:
        set4(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, 0.2f, 0.3f, 0.8f);
        set4(GL_FRONT, GL_SPECULAR, 1, 1, 1);
        glMaterialf(GL_FRONT, GL_SHININESS, 80);
        break;
      case 3:
        set4(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, 0.2f, 0.3f, 0.8f);
        set4(GL_FRONT, GL_SPECULAR, 0.8f, 0.8f, 0.5f);
        glMaterialf(GL_FRONT, GL_SHININESS, 6);
        break;
      default:
        set4(GL_FRONT, GL_DIFFUSE, 0.3f, 0.3f, 0.3f);
        set4(GL_FRONT, GL_EMISSION, 0.5f, 0.35f, 0.0f);
        break;
    }
    glPushMatrix();
    glTranslatef(-2.1f + 1.05f * i, 0.95f, 0);
    sphere(0.46, 28, 16);
    glPopMatrix();
  }
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, low_ambient);

  /* Two-sided lighting on a half tube. */
  reset_material();
  set4(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, 0.9f, 0.7f, 0.2f);
  set4(GL_FRONT, GL_SPECULAR, 0.5f, 0.5f, 0.5f);
  glMaterialf(GL_FRONT, GL_SHININESS, 20);
  set4(GL_BACK, GL_AMBIENT, 0.1f, 0.1f, 0.4f);
  set4(GL_BACK, GL_DIFFUSE, 0.3f, 0.5f, 1.0f);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glPushMatrix();
  glTranslatef(-1.5f, -0.75f, 0);
  glRotatef(-40, 0, 1, 0);
  glRotatef(25, 1, 0, 0);
  half_tube(0.8, 1.3);
  glPopMatrix();
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);

  /* Infinite and local viewer on shiny panels. */
  reset_material();
  set4(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, 0.2f, 0.25f, 0.3f);
  set4(GL_FRONT, GL_SPECULAR, 0.7f, 0.6f, 0.5f);
  glMaterialf(GL_FRONT, GL_SHININESS, 30);
  for (int local = 0; local < 2; ++local) {
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, local);
    glPushMatrix();
    glTranslatef(0.2f + 1.5f * local, -0.75f, 0);
    glRotatef(-20, 1, 0, 0);
    panel(0.7f);
    glPopMatrix();
  }
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FALSE);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(320, 240);
  glutCreateWindow("10 light model and materials");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
