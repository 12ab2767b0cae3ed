/*
 * lit.c -- a Gouraud-shaded scene lit with glLight and coloured with
 * glMaterial: a sphere and a torus standing on a floor.
 *
 * Based on the lecture notes "NUS SoC SWS3005 Real-time 3D Graphics Rendering",
 * section VII "Illumination" -> "Illumination in OpenGL" and "Shading"
 * (seed 001_5665e12f7de930eb.txt). The light source code is the notes'
 * "example code of using light" (diffuse0, ambient0, specular0, light0_pos and
 * the glEnable/glLightfv calls), with these changes:
 *   - the notes write light0_pos as {1.0, 2.0, 3,0, 1.0} (a typo: five values,
 *     which would make w = 0, a directional light); here it is the intended
 *     point light {1.0, 2.0, 3.0, 1.0};
 *   - the notes' light is pure red; a second, white light GL_LIGHT1 is added
 *     ("Must enable each light source individually: glEnable(GL_LIGHTi)") so
 *     that the materials' colours show.
 * Also from the notes: glNormal via the GLUT solids and the floor, the global
 * ambient light glLightModelfv(GL_LIGHT_MODEL_AMBIENT, global_ambient),
 * glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE), glEnable(GL_NORMALIZE),
 * glMaterialfv(GL_FRONT, ...) and Gouraud shading with glShadeModel(GL_SMOOTH).
 * The notes give no scene; the objects, materials, camera and keys are added.
 *
 * Keys: s  switch Gouraud (GL_SMOOTH) / flat (GL_FLAT) shading
 *       0  red light (GL_LIGHT0) on/off     1  white light (GL_LIGHT1) on/off
 *       q, Esc  quit
 */
#include <GL/glut.h>
#include <stdlib.h>

/* light 0: the notes' red light */
GLfloat diffuse0[] = {1.0, 0.0, 0.0, 1.0};
GLfloat ambient0[] = {1.0, 0.0, 0.0, 1.0};
GLfloat specular0[] = {1.0, 0.0, 0.0, 1.0};
GLfloat light0_pos[] = {1.0, 2.0, 3.0, 1.0};

/* light 1: a white light from the upper left (added) */
GLfloat diffuse1[] = {0.8, 0.8, 0.8, 1.0};
GLfloat ambient1[] = {0.0, 0.0, 0.0, 1.0};
GLfloat specular1[] = {1.0, 1.0, 1.0, 1.0};
GLfloat light1_pos[] = {-3.0, 4.0, 2.0, 1.0};

GLfloat global_ambient[] = {0.2, 0.2, 0.2, 1.0};

/* materials */
GLfloat sphere_ambient[] = {0.2, 0.2, 0.2, 1.0};
GLfloat sphere_diffuse[] = {0.8, 0.8, 0.8, 1.0};
GLfloat sphere_specular[] = {1.0, 1.0, 1.0, 1.0};
GLfloat sphere_shininess = 50.0;

GLfloat torus_ambient[] = {0.25, 0.2, 0.07, 1.0};
GLfloat torus_diffuse[] = {0.75, 0.6, 0.23, 1.0};
GLfloat torus_specular[] = {0.63, 0.56, 0.37, 1.0};
GLfloat torus_shininess = 40.0;

GLfloat floor_ambient[] = {0.1, 0.15, 0.25, 1.0};
GLfloat floor_diffuse[] = {0.3, 0.5, 0.8, 1.0};
GLfloat floor_specular[] = {0.0, 0.0, 0.0, 1.0};
GLfloat floor_shininess = 0.0;

int smooth = 1;
int light0_on = 1, light1_on = 1;

void setMaterial(GLfloat* ambient, GLfloat* diffuse, GLfloat* specular, GLfloat shininess) {
  glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, shininess);
}

/* the floor: a 10 x 10 grid of quads at y = -1, so the point lights fall off across it */
void drawFloor(void) {
  int i, j;
  const GLfloat s = 0.8f;
  glNormal3f(0.0, 1.0, 0.0);
  glBegin(GL_QUADS);
  for (i = -5; i < 5; i++)
    for (j = -5; j < 5; j++) {
      glVertex3f(i * s, -1.0f, (j + 1) * s);
      glVertex3f((i + 1) * s, -1.0f, (j + 1) * s);
      glVertex3f((i + 1) * s, -1.0f, j * s);
      glVertex3f(i * s, -1.0f, j * s);
    }
  glEnd();
}

void display(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glShadeModel(smooth ? GL_SMOOTH : GL_FLAT);

  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 2.5, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

  /* light positions are given here, after the camera, so they stay fixed in the world */
  glLightfv(GL_LIGHT0, GL_POSITION, light0_pos);
  glLightfv(GL_LIGHT1, GL_POSITION, light1_pos);

  setMaterial(floor_ambient, floor_diffuse, floor_specular, floor_shininess);
  drawFloor();

  glPushMatrix();
  glTranslatef(-1.3f, 0.0f, 0.0f);
  setMaterial(sphere_ambient, sphere_diffuse, sphere_specular, sphere_shininess);
  glutSolidSphere(1.0, 24, 16);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(1.4f, -0.05f, 0.0f);
  glRotatef(-35.0f, 0.0f, 1.0f, 0.0f);
  setMaterial(torus_ambient, torus_diffuse, torus_specular, torus_shininess);
  glutSolidTorus(0.3, 0.65, 16, 32);
  glPopMatrix();

  glutSwapBuffers();
}

void reshape(int w, int h) {
  if (h == 0) h = 1;
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (GLdouble)w / h, 1.0, 50.0);
  glMatrixMode(GL_MODELVIEW);
}

void keyboard(unsigned char key, int x, int y) {
  (void)x;
  (void)y;
  switch (key) {
    case 's':
    case 'S': smooth = !smooth; break;
    case '0':
      light0_on = !light0_on;
      if (light0_on)
        glEnable(GL_LIGHT0);
      else
        glDisable(GL_LIGHT0);
      break;
    case '1':
      light1_on = !light1_on;
      if (light1_on)
        glEnable(GL_LIGHT1);
      else
        glDisable(GL_LIGHT1);
      break;
    case 'q':
    case 'Q':
    case 27: exit(0);
    default: return;
  }
  glutPostRedisplay();
}

void init(void) {
  glClearColor(0.05, 0.05, 0.08, 1.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, light0_pos);
  glLightfv(GL_LIGHT0, GL_AMBIENT, ambient0);   /* def ambient */
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse0);   /* def diffuse */
  glLightfv(GL_LIGHT0, GL_SPECULAR, specular0); /* def spec */

  glEnable(GL_LIGHT1);
  glLightfv(GL_LIGHT1, GL_POSITION, light1_pos);
  glLightfv(GL_LIGHT1, GL_AMBIENT, ambient1);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, diffuse1);
  glLightfv(GL_LIGHT1, GL_SPECULAR, specular1);

  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, global_ambient);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);

  glShadeModel(GL_SMOOTH); /* Gouraud shading */
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(600, 450);
  glutCreateWindow("lit");
  init();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutKeyboardFunc(keyboard);
  glutMainLoop();
  return 0;
}
