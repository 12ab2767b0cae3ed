/* 27_glu_quadrics: GLU quadrics, lit, one per viewport (3 x 3):
 *   gluSphere filled, GLU_SMOOTH normals, gluQuadricTexture (a checker texture);
 *   gluCylinder (tapered) filled with GLU_FLAT normals;
 *   gluCylinder with GLU_LINE draw style;
 *   gluDisk with a hole, filled and textured;
 *   gluPartialDisk (start 30, sweep 240) filled, smooth;
 *   gluDisk with GLU_SILHOUETTE (outline only);
 *   gluSphere with GLU_POINT;
 *   an open gluCylinder with gluQuadricOrientation(GLU_INSIDE) (the inside is lit);
 *   gluPartialDisk with GLU_LINE. Projection by gluPerspective, camera by gluLookAt. */
#include <GL/glut.h>

static int win_w = 318, win_h = 240;
static GLuint checker;
static GLUquadric* q;

static void reshape(int w, int h) {
  win_w = w;
  win_h = h;
}

static void make_texture(void) {
  GLubyte t[8 * 8 * 3];
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const int on = (i + j) % 2;
      t[(j * 8 + i) * 3 + 0] = on ? 255 : 40;
      t[(j * 8 + i) * 3 + 1] = on ? 230 : 90;
      t[(j * 8 + i) * 3 + 2] = on ? 120 : 200;
    }
  glGenTextures(1, &checker);
  glBindTexture(GL_TEXTURE_2D, checker);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

static void cell(int i) {
  const int cw = win_w / 3, ch = win_h / 3;
  glViewport((i % 3) * cw, win_h - (i / 3 + 1) * ch, cw, ch);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)cw / ch, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 1.2, 3.6, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
  const GLfloat light[4] = {1.0f, 2.0f, 3.0f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
}

static void material(float r, float g, float b) {
  const GLfloat c[4] = {r, g, b, 1}, s[4] = {0.4f, 0.4f, 0.4f, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, c);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, s);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 25);
}

static void reset_quadric(void) {
  gluQuadricDrawStyle(q, GLU_FILL);
  gluQuadricNormals(q, GLU_SMOOTH);
  gluQuadricOrientation(q, GLU_OUTSIDE);
  gluQuadricTexture(q, GL_FALSE);
}

static void display(void) {
  glClearColor(0.1f, 0.12f, 0.14f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glBindTexture(GL_TEXTURE_2D, checker);

  /* 0: textured smooth sphere. */
  cell(0);
  reset_quadric();
  gluQuadricTexture(q, GL_TRUE);
  glEnable(GL_TEXTURE_2D);
  material(1, 1, 1);
  glRotatef(-70, 1, 0, 0);
  gluSphere(q, 1.0, 24, 16);
  glDisable(GL_TEXTURE_2D);

  /* 1: tapered cylinder, flat normals. */
  cell(1);
  reset_quadric();
  gluQuadricNormals(q, GLU_FLAT);
  material(0.9f, 0.4f, 0.3f);
  glRotatef(-90, 1, 0, 0);
  glTranslatef(0, 0, -0.7f);
  gluCylinder(q, 0.8, 0.3, 1.4, 16, 3);

  /* 2: cylinder as lines. */
  cell(2);
  reset_quadric();
  gluQuadricDrawStyle(q, GLU_LINE);
  material(0.4f, 0.9f, 0.5f);
  glRotatef(-60, 1, 0, 0);
  glTranslatef(0, 0, -0.8f);
  gluCylinder(q, 0.7, 0.7, 1.6, 14, 4);

  /* 3: textured disk with a hole. */
  cell(3);
  reset_quadric();
  gluQuadricTexture(q, GL_TRUE);
  glEnable(GL_TEXTURE_2D);
  material(1, 1, 1);
  glRotatef(-50, 1, 0, 0);
  gluDisk(q, 0.4, 1.2, 20, 3);
  glDisable(GL_TEXTURE_2D);

  /* 4: partial disk. */
  cell(4);
  reset_quadric();
  material(0.4f, 0.6f, 1.0f);
  glRotatef(-50, 1, 0, 0);
  gluPartialDisk(q, 0.3, 1.2, 24, 4, 30.0, 240.0);

  /* 5: silhouette disk. */
  cell(5);
  reset_quadric();
  gluQuadricDrawStyle(q, GLU_SILHOUETTE);
  glDisable(GL_LIGHTING);
  glColor3f(1.0f, 0.8f, 0.3f);
  glRotatef(-50, 1, 0, 0);
  gluDisk(q, 0.5, 1.2, 20, 4);
  glEnable(GL_LIGHTING);

  /* 6: sphere as points. */
  cell(6);
  reset_quadric();
  gluQuadricDrawStyle(q, GLU_POINT);
  glPointSize(3.0f);
  material(1.0f, 0.5f, 0.9f);
  glRotatef(-70, 1, 0, 0);
  gluSphere(q, 1.0, 20, 12);
  glPointSize(1.0f);

  /* 7: open cylinder lit from the inside. */
  cell(7);
  reset_quadric();
  gluQuadricOrientation(q, GLU_INSIDE);
  material(0.9f, 0.8f, 0.3f);
  glRotatef(-45, 1, 0, 0);
  glTranslatef(0, 0, -0.6f);
  gluCylinder(q, 0.9, 0.9, 1.2, 24, 2);

  /* 8: partial disk as lines. */
  cell(8);
  reset_quadric();
  gluQuadricDrawStyle(q, GLU_LINE);
  material(0.5f, 1.0f, 1.0f);
  glRotatef(-40, 1, 0, 0);
  gluPartialDisk(q, 0.2, 1.2, 16, 3, -45.0, 200.0);

  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(win_w, win_h);
  glutCreateWindow("27 GLU quadrics");
  glDisable(GL_DITHER);
  make_texture();
  q = gluNewQuadric();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
