/*
 * simple2.c -- simple.c with the usual program structure: main() sets up the
 * window, init() sets the state (clear colour, fill colour, projection), and
 * the display callback draws a white square on black.
 *
 * Copied from the lecture notes "NUS SoC SWS3005 Real-time 3D Graphics
 * Rendering", section II -> "Program Structure": "main()", "init()" and the
 * mydisplay() shown under "Orthographic Viewing and Transformation"
 * (seed 001_5665e12f7de930eb.txt). Only changes: the functions are put in the
 * order C needs (init and mydisplay before main), take (void), and main()
 * returns 0.
 */
#include <GL/glut.h>

void init(void) {
  glClearColor(0.0, 0.0, 0.0, 1.0);
  /* black clear color with opaque window */
  glColor3f(1.0, 1.0, 1.0); /* white fill color */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0); /* viewing volume */
}

void mydisplay(void) {
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_POLYGON);
  /* define as polygon */
  glVertex2f(-0.5, -0.5);
  glVertex2f(-0.5, 0.5);
  glVertex2f(0.5, 0.5);
  glVertex2f(0.5, -0.5);
  /* set 4 vertex to form 4-edges polygon */
  glEnd();
  glFlush();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
  glutInitWindowSize(500, 500);
  glutInitWindowPosition(0, 0);
  glutCreateWindow("simple2");
  glutDisplayFunc(mydisplay);
  init();
  glutMainLoop();
  return 0;
}
