/* 34_evaluators: Bezier evaluators. Left: a cubic curve through glMap1f(GL_MAP1_VERTEX_3)
 * drawn with glEvalCoord1f in a line strip, and again with glMapGrid1f + glEvalMesh1, with a
 * GL_MAP1_COLOR_4 map colouring it; its control points as points. Right: a 4 x 4 Bezier patch
 * (glMap2f GL_MAP2_VERTEX_3) lit with GL_AUTO_NORMAL, glMapGrid2f + glEvalMesh2(GL_FILL), a
 * second patch as GL_MAP2_VERTEX_4 (rational) with a GL_MAP2_COLOR_4 map in GL_LINE mode,
 * and glEvalPoint2 points over it. */
#include <GL/glut.h>

static const int W = 320, H = 240;

static const GLfloat curve[4][3] = {{-0.9f, -0.6f, 0}, {-0.7f, 0.9f, 0}, {-0.3f, -0.9f, 0}, {-0.1f, 0.6f, 0}};
static const GLfloat curve_colour[2][4] = {{1, 0.2f, 0.2f, 1}, {0.2f, 0.4f, 1, 1}};

static GLfloat patch[4][4][3];
static GLfloat patch4[4][4][4];
static const GLfloat patch_colour[2][2][4] = {{{1, 1, 0, 1}, {0, 1, 1, 1}}, {{1, 0, 1, 1}, {1, 1, 1, 1}}};

static void init(void) {
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      patch[j][i][0] = -1.5f + i;
      patch[j][i][1] = -1.5f + j;
      patch[j][i][2] = ((i == 1 || i == 2) && (j == 1 || j == 2)) ? 2.0f : -0.5f + 0.3f * i;
      const float w = (i + j) % 2 ? 2.0f : 1.0f; /* weights: a rational patch */
      patch4[j][i][0] = (-1.2f + 0.8f * i) * w;
      patch4[j][i][1] = (-1.2f + 0.8f * j) * w;
      patch4[j][i][2] = 0.4f * (float)((i * j) % 3) * w;
      patch4[j][i][3] = w;
    }
}

static void display(void) {
  glClearColor(0.1f, 0.1f, 0.12f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  /* Left half: curves in 2D. */
  glViewport(0, 0, W / 2, H);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 0, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_LIGHTING);
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &curve[0][0]);
  glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 4, 2, &curve_colour[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP1_COLOR_4);
  glLineWidth(2);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i <= 30; ++i) glEvalCoord1f((GLfloat)i / 30.0f);
  glEnd();
  glPushMatrix();
  glTranslatef(0.0f, -0.25f, 0);
  glMapGrid1f(12, 0.0f, 1.0f);
  glEvalMesh1(GL_LINE, 0, 12);
  glPointSize(4);
  glEvalMesh1(GL_POINT, 0, 12);
  glPopMatrix();
  glDisable(GL_MAP1_COLOR_4);
  glColor3f(1, 1, 1);
  glBegin(GL_POINTS);
  for (int i = 0; i < 4; ++i) glVertex3fv(curve[i]);
  glEnd();
  glDisable(GL_MAP1_VERTEX_3);

  /* Right half: patches in 3D. */
  glViewport(W / 2, 0, W / 2, H);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45, (double)(W / 2) / H, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0, -4, 4.5, 0, 0, 0.3, 0, 0, 1);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat light[4] = {-1, -4, 6, 1}, diffuse[4] = {0.9f, 0.6f, 0.3f, 1},
                spec[4] = {0.6f, 0.6f, 0.6f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_NORMALIZE);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &patch[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glMapGrid2f(16, 0.0f, 1.0f, 16, 0.0f, 1.0f);
  glPushMatrix();
  glTranslatef(-0.2f, 0.9f, 0);
  glScalef(0.7f, 0.7f, 0.7f);
  glEvalMesh2(GL_FILL, 0, 16, 0, 16);
  glPopMatrix();
  glDisable(GL_MAP2_VERTEX_3);
  glDisable(GL_LIGHTING);
  glDisable(GL_AUTO_NORMAL);

  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 4, 4, 0, 1, 16, 4, &patch4[0][0][0]);
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, &patch_colour[0][0][0]);
  glEnable(GL_MAP2_VERTEX_4);
  glEnable(GL_MAP2_COLOR_4);
  glPushMatrix();
  glTranslatef(-0.3f, -1.4f, 0.2f);
  glScalef(0.8f, 0.8f, 0.8f);
  glMapGrid2f(10, 0.0f, 1.0f, 8, 0.0f, 1.0f);
  glLineWidth(1);
  glEvalMesh2(GL_LINE, 0, 10, 0, 8);
  glPointSize(3);
  glBegin(GL_POINTS);
  for (int j = 0; j <= 8; j += 2)
    for (int i = 0; i <= 10; i += 2) glEvalPoint2(i, j);
  glEnd();
  glPopMatrix();
  glDisable(GL_MAP2_VERTEX_4);
  glDisable(GL_MAP2_COLOR_4);
  glDisable(GL_DEPTH_TEST);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(W, H);
  glutCreateWindow("34 evaluators");
  glDisable(GL_DITHER);
  init();
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
