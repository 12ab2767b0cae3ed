/*
 * simple.c -- the smallest GLUT program: a white square on a black background.
 *
 * Copied from the lecture notes "NUS SoC SWS3005 Real-time 3D Graphics
 * Rendering", section II "Elementary OpenGL Programming" -> "Simple Concept"
 * -> "Examples" (seed 001_5665e12f7de930eb.txt). Only changes: mydisplay(void)
 * instead of mydisplay(), and main() returns 0.
 *
 * Everything is left at OpenGL's and GLUT's defaults: a single-buffered RGBA
 * window of the default size, black clear colour, white current colour, and
 * identity matrices, so the square spans the middle half of the window.
 */
#include <GL/glut.h>

void mydisplay(void) {
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_POLYGON);
  glVertex2f(-0.5, -0.5);
  glVertex2f(-0.5, 0.5);
  glVertex2f(0.5, 0.5);
  glVertex2f(0.5, -0.5);
  glEnd();
  glFlush();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutCreateWindow("simple");
  glutDisplayFunc(mydisplay);
  glutMainLoop();
  return 0;
}
