/* 06_robot_arm: matrix stacks. An articulated, lit robot arm (base, shoulder, elbow, wrist,
 * three two-joint fingers) built with glTranslate/glRotate/glScale and nested
 * glPushMatrix/glPopMatrix; the camera is a hand-made column-major matrix given to
 * glLoadMatrixf, the base is sheared with glMultMatrixd; projection with glFrustum; a 2D
 * overlay (joint-angle bars) drawn by pushing the projection stack and loading glOrtho. */
#include <GL/glut.h>
#include <math.h>

static int win_w = 320, win_h = 240;

static void reshape(int w, int h) {
  win_w = w;
  win_h = h;
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5 * w / h, 0.5 * w / h, -0.5, 0.5, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
}

/* A box centred on the origin, unit size, with face normals. */
static void box(void) {
  static const GLfloat n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  static const GLfloat v[6][4][3] = {
      {{.5f, -.5f, -.5f}, {.5f, .5f, -.5f}, {.5f, .5f, .5f}, {.5f, -.5f, .5f}},
      {{-.5f, -.5f, .5f}, {-.5f, .5f, .5f}, {-.5f, .5f, -.5f}, {-.5f, -.5f, -.5f}},
      {{-.5f, .5f, -.5f}, {-.5f, .5f, .5f}, {.5f, .5f, .5f}, {.5f, .5f, -.5f}},
      {{-.5f, -.5f, .5f}, {-.5f, -.5f, -.5f}, {.5f, -.5f, -.5f}, {.5f, -.5f, .5f}},
      {{-.5f, -.5f, .5f}, {.5f, -.5f, .5f}, {.5f, .5f, .5f}, {-.5f, .5f, .5f}},
      {{.5f, -.5f, -.5f}, {-.5f, -.5f, -.5f}, {-.5f, .5f, -.5f}, {.5f, .5f, -.5f}}};
  glBegin(GL_QUADS);
  for (int f = 0; f < 6; ++f) {
    glNormal3fv(n[f]);
    for (int k = 0; k < 4; ++k) glVertex3fv(v[f][k]);
  }
  glEnd();
}

static void colour(float r, float g, float b) {
  const GLfloat c[4] = {r, g, b, 1.0f};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, c);
}

/* A segment of length len along +x from the current joint. */
static void segment(float len, float thick) {
  glPushMatrix();
  glTranslatef(len / 2, 0, 0);
  glScalef(len, thick, thick);
  box();
  glPopMatrix();
}

static const float shoulder = 35, elbow = -60, wrist = -25, finger_base[3] = {25, 0, -25}, finger_tip = -40;

static void finger(float spread, float yaw) {
  glPushMatrix();
  glRotatef(yaw, 0, 1, 0);
  glRotatef(spread, 0, 0, 1);
  colour(0.9f, 0.8f, 0.2f);
  segment(0.5f, 0.12f);
  glTranslatef(0.5f, 0, 0);
  glRotatef(finger_tip * (spread >= 0 ? 1 : -1), 0, 0, 1);
  colour(0.9f, 0.5f, 0.1f);
  segment(0.4f, 0.1f);
  glPopMatrix();
}

static void look_at(GLfloat m[16], const float eye[3], const float centre[3], const float up[3]) {
  float f[3] = {centre[0] - eye[0], centre[1] - eye[1], centre[2] - eye[2]};
  float fl = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  for (int i = 0; i < 3; ++i) f[i] /= fl;
  float s[3] = {f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0]};
  float sl = sqrtf(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  for (int i = 0; i < 3; ++i) s[i] /= sl;
  const float u[3] = {s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]};
  /* Column-major: m[col * 4 + row]. */
  m[0] = s[0];
  m[4] = s[1];
  m[8] = s[2];
  m[1] = u[0];
  m[5] = u[1];
  m[9] = u[2];
  m[2] = -f[0];
  m[6] = -f[1];
  m[10] = -f[2];
  m[3] = 0;
  m[7] = 0;
  m[11] = 0;
  m[15] = 1;
  m[12] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
  m[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
  m[14] = (f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2]);
}

static void floor_grid(void) {
  glNormal3f(0, 1, 0);
  for (int j = -5; j < 5; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (int i = -6; i <= 6; ++i) {
      glVertex3f(0.5f * i, 0, 0.5f * (j + 1));
      glVertex3f(0.5f * i, 0, 0.5f * j);
    }
    glEnd();
  }
}

static void overlay(void) {
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glOrtho(0, win_w, 0, win_h, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  const float angles[4] = {shoulder, elbow, wrist, finger_tip};
  for (int i = 0; i < 4; ++i) {
    glColor3f(0.2f, 0.2f, 0.3f);
    glRecti(8, win_h - 14 - 12 * i, 98, win_h - 6 - 12 * i);
    glColor3f(0.3f + 0.2f * i, 0.9f - 0.2f * i, 0.4f);
    glRectf(53, win_h - 13 - 12 * i, 53 + angles[i] / 2, win_h - 7 - 12 * i);
  }
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
}

static void display(void) {
  glClearColor(0.55f, 0.65f, 0.8f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glEnable(GL_NORMALIZE);

  GLfloat view[16];
  const float eye[3] = {1.6f, 2.6f, 4.4f}, centre[3] = {0.8f, 1.1f, 0.0f}, up[3] = {0, 1, 0};
  look_at(view, eye, centre, up);
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(view);
  const GLfloat l0[4] = {-2.0f, 5.0f, 4.0f, 1.0f}, l1[4] = {1.0f, 0.5f, 0.2f, 0.0f};
  const GLfloat dim[4] = {0.35f, 0.3f, 0.3f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, l0);
  glLightfv(GL_LIGHT1, GL_POSITION, l1);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, dim);

  colour(0.45f, 0.5f, 0.45f);
  floor_grid();

  glPushMatrix();
  /* The base: a sheared box (x += 0.3 y), given as a column-major double matrix. */
  const GLdouble shear[16] = {1, 0, 0, 0, 0.3, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  glPushMatrix();
  glTranslatef(0, 0.25f, 0);
  glMultMatrixd(shear);
  glScalef(1.2f, 0.5f, 1.0f);
  colour(0.3f, 0.3f, 0.8f);
  box();
  glPopMatrix();

  glTranslatef(0.1f, 0.5f, 0);
  glRotatef(20, 0, 1, 0);
  glRotatef(90 - shoulder, 0, 0, 1); /* shoulder */
  colour(0.8f, 0.2f, 0.2f);
  segment(1.6f, 0.3f);
  glTranslatef(1.6f, 0, 0);
  glRotatef(elbow - 40, 0, 0, 1); /* elbow */
  colour(0.2f, 0.7f, 0.3f);
  segment(1.3f, 0.24f);
  glTranslatef(1.3f, 0, 0);
  glRotatef(wrist, 0, 0, 1); /* wrist */
  colour(0.6f, 0.6f, 0.65f);
  glPushMatrix();
  glScalef(0.3f, 0.4f, 0.4f);
  box();
  glPopMatrix();
  glTranslatef(0.15f, 0, 0);
  for (int i = 0; i < 3; ++i) finger(finger_base[i], -35.0f + 35.0f * i);
  glPopMatrix();

  overlay();
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(win_w, win_h);
  glutCreateWindow("06 robot arm");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
