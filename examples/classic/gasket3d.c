/*
 * gasket3d.c -- the 3D Sierpinski gasket: a tetrahedron whose four faces are
 * each subdivided like the 2D gasket, drawn with the z-buffer.
 *
 * Based on the lecture notes "NUS SoC SWS3005 Real-time 3D Graphics Rendering",
 * section II -> "Move to 3D triangle" and "Using the z-buffer Algorithm"
 * (seed 001_5665e12f7de930eb.txt), which say: add an extra vertex to form a
 * tetrahedron, subdivide like the 2D triangle ("In our example, we subdivided
 * the surface of each face"), request GLUT_DEPTH in main(), enable
 * GL_DEPTH_TEST in init() and clear GL_DEPTH_BUFFER_BIT in the display
 * callback. The notes give those three lines only; the rest is completed in
 * the style of gasket2d.c (same display()/myinit()/main() shape, same
 * divide_triangle() in 3D), with one colour per face so the faces can be told
 * apart, and the reshape callback myReshape() copied from the notes' section
 * III "Reshape Callback".
 *
 * Looking down -z at the apex v[0], three faces are visible (red, blue,
 * black); the green face is at the back and must be hidden by the depth test.
 */
#include <GL/glut.h>
#include <stdlib.h>

/* initial tetrahedron */
GLfloat v[4][3] = {{0.0f, 0.0f, 1.0f},
                   {0.0f, 0.942809f, -0.333333f},
                   {-0.816497f, -0.471405f, -0.333333f},
                   {0.816497f, -0.471405f, -0.333333f}};

int n; /* number of recursive subdivision steps */

void triangle(GLfloat* a, GLfloat* b, GLfloat* c) {
  glVertex3fv(a);
  glVertex3fv(b);
  glVertex3fv(c);
}

void divide_triangle(GLfloat* a, GLfloat* b, GLfloat* c, int m) {
  GLfloat v0[3], v1[3], v2[3];
  int j;
  if (m > 0) {
    for (j = 0; j < 3; j++) v0[j] = (a[j] + b[j]) / 2;
    for (j = 0; j < 3; j++) v1[j] = (a[j] + c[j]) / 2;
    for (j = 0; j < 3; j++) v2[j] = (b[j] + c[j]) / 2;
    divide_triangle(a, v0, v1, m - 1);
    divide_triangle(c, v1, v2, m - 1);
    divide_triangle(b, v2, v0, m - 1);
  } else {
    triangle(a, b, c);
  }
}

/* apply triangle subdivision to the faces of the tetrahedron */
void tetrahedron(int m) {
  glColor3f(1.0, 0.0, 0.0);
  divide_triangle(v[0], v[1], v[2], m);
  glColor3f(0.0, 1.0, 0.0);
  divide_triangle(v[3], v[2], v[1], m);
  glColor3f(0.0, 0.0, 1.0);
  divide_triangle(v[0], v[3], v[1], m);
  glColor3f(0.0, 0.0, 0.0);
  divide_triangle(v[0], v[2], v[3], m);
}

void display(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  tetrahedron(n);
  glEnd();
  glFlush();
}

void myReshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION); /* switch matrix mode */
  glLoadIdentity();
  if (w <= h)
    gluOrtho2D(-2.0, 2.0, -2.0 * (GLfloat)h / w, 2.0 * (GLfloat)h / w);
  else
    gluOrtho2D(-2.0 * (GLfloat)w / h, 2.0 * (GLfloat)w / h, -2.0, 2.0);
  glMatrixMode(GL_MODELVIEW); /* return to modelview mode */
}

void myinit(void) {
  glClearColor(1.0, 1.0, 1.0, 1.0); /* white background */
  glEnable(GL_DEPTH_TEST);          /* z-buffer hidden-surface removal */
}

int main(int argc, char** argv) {
  n = 3;
  glutInit(&argc, argv);
  if (argc > 1) n = atoi(argv[1]); /* optional subdivision depth */
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(500, 500);
  glutCreateWindow("3D Gasket");
  glutReshapeFunc(myReshape);
  glutDisplayFunc(display);
  myinit();
  glutMainLoop();
  return 0;
}
