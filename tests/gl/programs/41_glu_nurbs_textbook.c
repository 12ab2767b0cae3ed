/* 41_glu_nurbs_textbook: the NURBS surface every OpenGL textbook shows first, with GLU's
 * defaults apart from the sampling tolerance: one bicubic Bezier patch (a 4 x 4 net, the inner
 * four points raised), GLU_PATH_LENGTH sampling at 25 pixels, GLU_FILL, lit with
 * GL_AUTO_NORMAL and GL_NORMALIZE, seen from a little above. Mesa's GLU and Tessel tessellate
 * the patch each in its own way within the tolerance, so the specular highlight may shift by
 * a few pixels. */
#include <GL/glut.h>

static GLfloat net[4][4][3];
static GLUnurbsObj* surface;

static void build_net(void) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const int inner = (i == 1 || i == 2) && (j == 1 || j == 2);
      net[i][j][0] = 2.0f * ((GLfloat)i - 1.5f);
      net[i][j][1] = 2.0f * ((GLfloat)j - 1.5f);
      net[i][j][2] = inner ? 3.0f : -3.0f;
    }
}

static void setup(void) {
  const GLfloat grey[] = {0.7f, 0.7f, 0.7f, 1.0f}, white[] = {1.0f, 1.0f, 1.0f, 1.0f};
  glClearColor(0, 0, 0, 0);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, grey);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 100.0f);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_NORMALIZE);
  build_net();
  surface = gluNewNurbsRenderer();
  gluNurbsProperty(surface, GLU_SAMPLING_TOLERANCE, 25.0f);
  gluNurbsProperty(surface, GLU_DISPLAY_MODE, GLU_FILL);
}

static void draw(void) {
  GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glPushMatrix();
  glRotatef(330.0f, 1, 0, 0);
  glScalef(0.5f, 0.5f, 0.5f);
  gluBeginSurface(surface);
  gluNurbsSurface(surface, 8, knots, 8, knots, 4 * 3, 3, &net[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
  gluEndSurface(surface);
  glPopMatrix();
  glFlush();
}

static void resize(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, (GLdouble)w / (GLdouble)h, 3.0, 8.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -5);
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(500, 500);
  glutCreateWindow("41_glu_nurbs_textbook");
  setup();
  glutReshapeFunc(resize);
  glutDisplayFunc(draw);
  glutMainLoop();
  return 0;
}
