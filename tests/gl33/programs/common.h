/*
 * What the GLUT acceptance programs share: GLEW and freeglut included in the order they need,
 * the window-system-independent helpers of util.h (shaders compiled from strings with their
 * info logs printed, a program linked from two, matrices, a sphere), and open_window.
 */
#ifndef TESSEL_GL33_COMMON_H
#define TESSEL_GL33_COMMON_H

// GLEW first: it must come before any other GL header.
#include <GL/glew.h>
// clang-format off (the order matters)
#include <GL/freeglut.h>
// clang-format on

#include "util.h"

/* GLUT + GLEW set-up of every program: a 320x240 RGBA window with depth and stencil. */
static inline void open_window(int* argc, char** argv, int major, int minor, int profile, const char* title) {
  GLenum err;
  glutInit(argc, argv);
  if (major) {
    glutInitContextVersion(major, minor);
    if (profile) glutInitContextProfile(profile);
  }
  glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH | GLUT_STENCIL);
  glutInitWindowSize(320, 240);
  glutCreateWindow(title);
  glewExperimental = GL_TRUE;
  err = glewInit();
  if (err != GLEW_OK) {
    fprintf(stderr, "glewInit: %s\n", (const char*)glewGetErrorString(err));
    exit(1);
  }
  (void)glGetError(); /* GLEW on a core context leaves GL_INVALID_ENUM behind */
}

#endif
