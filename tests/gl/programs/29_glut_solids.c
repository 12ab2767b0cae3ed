/* 29_glut_solids: the GLUT solid objects, lit, one per viewport (3 x 3): glutSolidSphere,
 * glutSolidCube, glutSolidCone, glutSolidTorus, glutSolidDodecahedron,
 * glutSolidOctahedron, glutSolidTetrahedron, glutSolidIcosahedron, glutSolidTeapot.
 * Two lights (a white key light with specular, a dim blue fill). */
#include <GL/glut.h>

static int win_w = 300, win_h = 300;

static void reshape(int w, int h) {
  win_w = w;
  win_h = h;
}

static void cell(int i, float r, float g, float b) {
  const int cw = win_w / 3, ch = win_h / 3;
  glViewport((i % 3) * cw, win_h - (i / 3 + 1) * ch, cw, ch);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.3, 0.3, -0.3, 0.3, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const GLfloat key[4] = {2.0f, 3.0f, 4.0f, 1.0f}, fill[4] = {-1.0f, -0.5f, 0.5f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, key);
  glLightfv(GL_LIGHT1, GL_POSITION, fill);
  glTranslatef(0, 0, -5);
  glRotatef(25, 1, 0, 0);
  glRotatef(-30, 0, 1, 0);
  const GLfloat c[4] = {r, g, b, 1}, s[4] = {0.7f, 0.7f, 0.7f, 1};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, c);
  glMaterialfv(GL_FRONT, GL_SPECULAR, s);
  glMaterialf(GL_FRONT, GL_SHININESS, 40);
}

static void display(void) {
  glClearColor(0.12f, 0.12f, 0.14f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glEnable(GL_NORMALIZE);

  cell(0, 0.9f, 0.3f, 0.3f);
  glutSolidSphere(1.0, 24, 16);
  cell(1, 0.3f, 0.8f, 0.4f);
  glutSolidCube(1.4);
  cell(2, 0.3f, 0.5f, 1.0f);
  glRotatef(-90, 1, 0, 0);
  glTranslatef(0, 0, -0.7f);
  glutSolidCone(0.9, 1.6, 20, 6);
  cell(3, 0.9f, 0.8f, 0.3f);
  glutSolidTorus(0.3, 0.75, 16, 28);
  cell(4, 0.8f, 0.4f, 0.9f);
  glScalef(0.62f, 0.62f, 0.62f);
  glutSolidDodecahedron();
  cell(5, 0.3f, 0.9f, 0.9f);
  glutSolidOctahedron();
  cell(6, 1.0f, 0.6f, 0.3f);
  glutSolidTetrahedron();
  cell(7, 0.7f, 0.7f, 0.75f);
  glutSolidIcosahedron();
  cell(8, 0.85f, 0.65f, 0.45f);
  glutSolidTeapot(0.75);

  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(win_w, win_h);
  glutCreateWindow("29 GLUT solids");
  glDisable(GL_DITHER);
  {
    const GLfloat dim_blue[4] = {0.15f, 0.2f, 0.4f, 1}, black[4] = {0, 0, 0, 1};
    glLightfv(GL_LIGHT1, GL_DIFFUSE, dim_blue);
    glLightfv(GL_LIGHT1, GL_SPECULAR, black);
  }
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
