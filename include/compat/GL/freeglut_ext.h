/*
 * Tessel compatibility header: <GL/freeglut_ext.h>, the freeglut additions (declared in GL/glut.h).
 * Tessel's GL/glut.h declares GLUT 3.7 and the freeglut additions together.
 */
#ifndef TESSEL_COMPAT_GL_FREEGLUT_EXT_H
#define TESSEL_COMPAT_GL_FREEGLUT_EXT_H 1
#include <GL/glut.h>
#endif
