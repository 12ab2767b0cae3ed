/*
 * mesa_capture.c - frame capture shim for the Mesa (freeglut + libGL) builds of the
 * GL acceptance programs in tests/gl/programs.
 *
 * Linked into every glm_<name> executable with
 *     -Wl,--wrap=glutDisplayFunc -Wl,--wrap=glutSwapBuffers -Wl,--wrap=glutInitDisplayMode
 * so the program's calls land here first. It is inert unless the environment variable
 *     TESSEL_CAPTURE=frames:N,out:DIR          (N defaults to 1; the keys may come in any order)
 * is set. Then, after each run of the program's display callback, the visible image of the
 * window is written to DIR/frame-0000.png, DIR/frame-0001.png, ...:
 *   - GLUT_DOUBLE: the back buffer, read inside the wrapped glutSwapBuffers just before the
 *     real swap (that is what the swap makes visible);
 *   - GLUT_SINGLE: the front buffer, read after the display callback returns.
 * Pixels are read as RGBA8 after glFinish and flipped so that the PNG's first row is the top
 * of the window. The GL state the shim touches (read buffer, pack pixel-store state, bound
 * pixel-pack buffer) is saved and restored. After N frames the process exits with status 0;
 * before that, glutPostRedisplay is called after each frame to get the next one.
 *
 * Tessel's own GLUT honours the same contract natively through TESSEL_HEADLESS.
 */
#include <GL/freeglut.h> /* freeglut: glutGetProcAddress */

#include <stdlib.h>

#include "capture_core.h"

/* The real functions, resolved by the linker's --wrap. */
void __real_glutDisplayFunc(void (*func)(void));
void __real_glutSwapBuffers(void);
void __real_glutInitDisplayMode(unsigned int mode);

static int cap_swapped = 0; /* a capture happened inside glutSwapBuffers this callback */
static int cap_in_display = 0;
static int cap_mode_known = 0;
static unsigned int cap_mode = GLUT_RGB | GLUT_SINGLE;
static void (*user_display)(void) = NULL;

static int cap_double_buffered(void) {
  int db = glutGet(GLUT_WINDOW_DOUBLEBUFFER);
  if (db == 0 || db == 1) return db;
  return cap_mode_known ? (cap_mode & GLUT_DOUBLE) != 0 : 0;
}

static void cap_display(void) {
  cap_swapped = 0;
  cap_in_display = 1;
  if (user_display) user_display();
  cap_in_display = 0;
  if (!cap_enabled) return;
  if (!cap_swapped) {
    /* GLUT_SINGLE (or a double-buffered callback that never swapped): what is visible is
       the front buffer. */
    cap_write(GL_FRONT, glutGet(GLUT_WINDOW_WIDTH), glutGet(GLUT_WINDOW_HEIGHT), glutGetProcAddress);
  }
  if (cap_count >= cap_frames) exit(0);
  glutPostRedisplay();
}

void __wrap_glutInitDisplayMode(unsigned int mode) {
  cap_mode = mode;
  cap_mode_known = 1;
  __real_glutInitDisplayMode(mode);
}

void __wrap_glutDisplayFunc(void (*func)(void)) {
  cap_parse();
  user_display = func;
  __real_glutDisplayFunc(func ? cap_display : NULL);
}

void __wrap_glutSwapBuffers(void) {
  cap_parse();
  if (cap_enabled && cap_in_display && !cap_swapped && cap_double_buffered()) {
    cap_write(GL_BACK, glutGet(GLUT_WINDOW_WIDTH), glutGet(GLUT_WINDOW_HEIGHT), glutGetProcAddress);
    cap_swapped = 1;
  }
  __real_glutSwapBuffers();
}
