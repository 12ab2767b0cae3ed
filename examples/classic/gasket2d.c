/*
 * gasket2d.c -- the 2D Sierpinski gasket by recursive triangle subdivision.
 *
 * Based on the lecture notes "NUS SoC SWS3005 Real-time 3D Graphics Rendering",
 * section II "Elementary OpenGL Programming" -> "3D OpenGL" -> "Gasket Program"
 * (seed 001_5665e12f7de930eb.txt). The notes give display(), myinit() and main()
 * verbatim; they are copied unchanged. The notes only *describe* the recursion
 * ("Using algorithm of Recursion!") and do not list v[], n, triangle() or
 * divide_triangle(); those are completed here in the same style (they are the
 * classic textbook versions the notes' code calls).
 *
 * The notes build the gasket by subdivision, not by plotting random points, so
 * the picture is fully deterministic: no rand() is involved.
 *
 * Optional: the first command-line argument overrides the number of
 * subdivision steps n (default 4, as in the notes), e.g. ./classic_gasket2d 6
 * (an addition to the notes).
 */
#include <GL/glut.h>
#include <stdlib.h>

/* initial triangle (roughly equilateral, centred on the origin) */
GLfloat v[3][2] = {{-1.0f, -0.58f}, {1.0f, -0.58f}, {0.0f, 1.15f}};

int n; /* number of recursive subdivision steps */

/* display one triangle */
void triangle(GLfloat* a, GLfloat* b, GLfloat* c) {
  glVertex2fv(a);
  glVertex2fv(b);
  glVertex2fv(c);
}

/* triangle subdivision using vertex numbers */
void divide_triangle(GLfloat* a, GLfloat* b, GLfloat* c, int m) {
  GLfloat v0[2], v1[2], v2[2];
  int j;
  if (m > 0) {
    for (j = 0; j < 2; j++) v0[j] = (a[j] + b[j]) / 2;
    for (j = 0; j < 2; j++) v1[j] = (a[j] + c[j]) / 2;
    for (j = 0; j < 2; j++) v2[j] = (b[j] + c[j]) / 2;
    divide_triangle(a, v0, v1, m - 1);
    divide_triangle(c, v1, v2, m - 1);
    divide_triangle(b, v2, v0, m - 1);
  } else {
    triangle(a, b, c); /* draw triangle at end of recursion */
  }
}

void display(void) {
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  divide_triangle(v[0], v[1], v[2], n);
  glEnd();
  glFlush();
}

void myinit(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(-2.0, 2.0, -2.0, 2.0);
  glMatrixMode(GL_MODELVIEW);
  glClearColor(1.0, 1.0, 1.0, 1.0); /* white background */
  glColor3f(0.0, 0.0, 0.0);         /* black triangles */
}

int main(int argc, char** argv) {
  n = 4;
  glutInit(&argc, argv);
  if (argc > 1) n = atoi(argv[1]); /* addition: optional subdivision depth */
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
  glutInitWindowSize(500, 500);
  glutCreateWindow("Sierpinski Gasket");
  glutDisplayFunc(display);
  myinit();
  glutMainLoop();
  return 0;
}
