/*
 * Tessel compatibility header: <GL/freeglut.h>, which course code includes for GLUT with the
 * freeglut additions (context version and profile, glutMainLoopEvent, glutLeaveMainLoop...).
 */
#ifndef TESSEL_COMPAT_GL_FREEGLUT_H
#define TESSEL_COMPAT_GL_FREEGLUT_H 1
#include <GL/freeglut_ext.h>
#include <GL/freeglut_std.h>
#endif
