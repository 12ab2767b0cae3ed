/* 25_clip_planes: user clip planes (glClipPlane, GL_CLIP_PLANE0..5), each given under the
 * modelview in force when it is specified:
 *   a lit sphere sliced by one oblique plane, its inside showing through the cut in the
 *   back material (two-sided lighting);
 *   a lit torus with a quadrant removed by two planes (the two half-spaces intersect);
 *   a flat smooth-coloured checkerboard cut to a diamond by four planes set in a rotated
 *   frame. */
#include <GL/glut.h>
#include <math.h>

#define PI 3.14159265358979323846

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.35 * w / h, 0.35 * w / h, -0.35, 0.35, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
}

static void sphere(double r) {
  const int slices = 32, stacks = 18;
  for (int j = 0; j < stacks; ++j) {
    const double t0 = PI * j / stacks - PI / 2, t1 = PI * (j + 1) / stacks - PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= slices; ++i) {
      const double p = 2 * PI * i / slices;
      glNormal3d(cos(t1) * sin(p), sin(t1), cos(t1) * cos(p));
      glVertex3d(r * cos(t1) * sin(p), r * sin(t1), r * cos(t1) * cos(p));
      glNormal3d(cos(t0) * sin(p), sin(t0), cos(t0) * cos(p));
      glVertex3d(r * cos(t0) * sin(p), r * sin(t0), r * cos(t0) * cos(p));
    }
    glEnd();
  }
}

static void torus(double R, double r) {
  const int sides = 18, rings = 36;
  for (int i = 0; i < rings; ++i) {
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= sides; ++j)
      for (int k = 0; k <= 1; ++k) { /* counter-clockwise seen from outside */
        const double u = 2 * PI * (i + k) / rings, v = 2 * PI * j / sides;
        glNormal3d(cos(v) * cos(u), cos(v) * sin(u), sin(v));
        glVertex3d((R + r * cos(v)) * cos(u), (R + r * cos(v)) * sin(u), r * sin(v));
      }
    glEnd();
  }
}

static void checkerboard(void) {
  glBegin(GL_QUADS);
  for (int j = -5; j < 5; ++j)
    for (int i = -5; i < 5; ++i) {
      const float t = (float)(i + 5) / 10.0f, s = (float)(j + 5) / 10.0f;
      if ((i + j) % 2)
        glColor3f(0.9f * t + 0.1f, 0.3f, 0.9f - 0.6f * s);
      else
        glColor3f(0.95f, 0.95f, 0.8f);
      glVertex2f(0.2f * i, 0.2f * j);
      glVertex2f(0.2f * (i + 1), 0.2f * j);
      glVertex2f(0.2f * (i + 1), 0.2f * (j + 1));
      glVertex2f(0.2f * i, 0.2f * (j + 1));
    }
  glEnd();
}

static void material(GLenum face, float r, float g, float b) {
  const GLfloat c[4] = {r, g, b, 1}, s[4] = {0.5f, 0.5f, 0.5f, 1};
  glMaterialfv(face, GL_AMBIENT_AND_DIFFUSE, c);
  glMaterialfv(face, GL_SPECULAR, s);
  glMaterialf(face, GL_SHININESS, 30);
}

static void display(void) {
  glClearColor(0.12f, 0.14f, 0.18f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glLoadIdentity();
  const GLfloat light[4] = {-1.0f, 1.5f, 2.0f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHTING);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);

  /* Sliced sphere. */
  glPushMatrix();
  glTranslatef(-1.3f, 0.0f, -4.0f);
  glRotatef(-30, 0, 1, 0);
  {
    const GLdouble plane[4] = {-0.3, -0.7, -0.6, 0.25}; /* keeps a*x + b*y + c*z + d >= 0 */
    glClipPlane(GL_CLIP_PLANE0, plane);
  }
  glEnable(GL_CLIP_PLANE0);
  material(GL_FRONT, 0.9f, 0.35f, 0.2f);
  material(GL_BACK, 0.3f, 0.8f, 0.9f);
  sphere(0.8);
  glDisable(GL_CLIP_PLANE0);
  glPopMatrix();

  /* Torus with a quadrant removed: clipped away where x > 0 and y > 0. The two planes keep
     x <= 0 or y <= 0 only together, so the torus is drawn twice, once per plane, with the
     other half-space's complement. */
  glPushMatrix();
  glTranslatef(0.05f, 0.0f, -4.0f);
  glRotatef(-35, 1, 0, 0);
  material(GL_FRONT, 0.3f, 0.6f, 1.0f);
  material(GL_BACK, 1.0f, 0.9f, 0.3f);
  {
    const GLdouble keep_left[4] = {-1, 0, 0, 0}, keep_low[4] = {0, -1, 0, 0}, keep_right[4] = {1, 0, 0, 0};
    glClipPlane(GL_CLIP_PLANE1, keep_left);
    glEnable(GL_CLIP_PLANE1);
    torus(0.6, 0.25);
    glDisable(GL_CLIP_PLANE1);
    glClipPlane(GL_CLIP_PLANE1, keep_right);
    glClipPlane(GL_CLIP_PLANE2, keep_low);
    glEnable(GL_CLIP_PLANE1);
    glEnable(GL_CLIP_PLANE2);
    torus(0.6, 0.25);
    glDisable(GL_CLIP_PLANE1);
    glDisable(GL_CLIP_PLANE2);
  }
  glPopMatrix();
  glDisable(GL_LIGHTING);

  /* Diamond window: four planes specified in a frame rotated by 45 degrees. */
  glPushMatrix();
  glTranslatef(1.35f, 0.0f, -4.0f);
  glRotatef(-20, 1, 0, 0);
  glPushMatrix();
  glRotatef(45, 0, 0, 1);
  {
    const GLdouble planes[4][4] = {{1, 0, 0, 0.55}, {-1, 0, 0, 0.55}, {0, 1, 0, 0.55}, {0, -1, 0, 0.55}};
    for (int i = 0; i < 4; ++i) {
      glClipPlane(GL_CLIP_PLANE2 + i, planes[i]);
      glEnable(GL_CLIP_PLANE2 + i);
    }
  }
  glPopMatrix();
  checkerboard();
  for (int i = 0; i < 4; ++i) glDisable(GL_CLIP_PLANE2 + i);
  glPopMatrix();

  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(320, 160);
  glutCreateWindow("25 clip planes");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
