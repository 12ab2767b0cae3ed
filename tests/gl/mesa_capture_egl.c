/*
 * mesa_capture_egl.c - frame capture shim for the EGL acceptance programs in
 * tests/gl33/programs (the EGL twin of mesa_capture.c).
 *
 * Linked into every EGL program with -Wl,--wrap=eglSwapBuffers. With
 *     TESSEL_CAPTURE=frames:N,out:DIR
 * each eglSwapBuffers first writes the surface's back buffer to DIR/frame-NNNN.png and prints
 * the GL renderer once on stderr; after N frames the process exits with status 0. Without
 * it, inert. The same binary runs on Mesa and, with LD_LIBRARY_PATH naming Tessel's
 * libEGL.so.1 and libOpenGL.so.0, on Tessel: the shim only calls EGL and GL.
 */
#include <EGL/egl.h>

#include <stdio.h>
#include <stdlib.h>

#include "capture_core.h"

EGLBoolean __real_eglSwapBuffers(EGLDisplay dpy, EGLSurface surface);

EGLBoolean __wrap_eglSwapBuffers(EGLDisplay dpy, EGLSurface surface) {
  EGLint w = 0, h = 0;
  EGLBoolean r;
  cap_parse();
  if (cap_enabled) {
    if (cap_count == 0) {
      const GLubyte* (*get_string)(GLenum) = (const GLubyte* (*)(GLenum))eglGetProcAddress("glGetString");
      const GLubyte* renderer = get_string ? get_string(GL_RENDERER) : NULL;
      fprintf(stderr, "renderer: %s\n", renderer ? (const char*)renderer : "(none)");
    }
    eglQuerySurface(dpy, surface, EGL_WIDTH, &w);
    eglQuerySurface(dpy, surface, EGL_HEIGHT, &h);
    cap_write(GL_BACK, w, h, (cap_proc_fn)eglGetProcAddress);
  }
  r = __real_eglSwapBuffers(dpy, surface);
  if (cap_enabled && cap_count >= cap_frames) exit(0);
  return r;
}
