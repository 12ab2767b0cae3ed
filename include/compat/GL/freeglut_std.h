/*
 * Tessel compatibility header: <GL/freeglut_std.h>, the GLUT API (GL/glut.h).
 * Tessel's GL/glut.h declares GLUT 3.7 and the freeglut additions together.
 */
#ifndef TESSEL_COMPAT_GL_FREEGLUT_STD_H
#define TESSEL_COMPAT_GL_FREEGLUT_STD_H 1
#include <GL/glut.h>
#endif
