/*
 * capture_core.c - what the Mesa capture shims share (mesa_capture.c for freeglut programs,
 * mesa_capture_glfw.c for GLFW ones): TESSEL_CAPTURE=frames:N,out:DIR parsed, and a colour
 * buffer of the current GL context read and written as DIR/frame-NNNN.png (top row first).
 */
#include "capture_core.h"

#include <stb/stb_image_write.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef GL_PIXEL_PACK_BUFFER_BINDING
#define GL_PIXEL_PACK_BUFFER_BINDING 0x88ED
#endif
#ifndef GL_PIXEL_PACK_BUFFER
#define GL_PIXEL_PACK_BUFFER 0x88EB
#endif

int cap_enabled = 0;
int cap_frames = 1;
int cap_count = 0;
static int cap_parsed = 0;
static char cap_dir[4096];

void cap_fail(const char* what) {
  fprintf(stderr, "mesa_capture: %s\n", what);
  exit(3);
}

void cap_parse(void) {
  if (cap_parsed) return;
  cap_parsed = 1;
  const char* env = getenv("TESSEL_CAPTURE");
  if (!env || !*env) return;
  char buf[4096 + 64];
  if (strlen(env) >= sizeof buf) cap_fail("TESSEL_CAPTURE is too long");
  strcpy(buf, env);
  /* Keys are separated by commas; the out: value runs up to a following ",frames:" or the end
     of the string, so the directory name may itself contain commas. */
  char* p = buf;
  while (p && *p) {
    char* next = NULL;
    if (strncmp(p, "out:", 4) == 0) {
      char* f = strstr(p, ",frames:");
      if (f) {
        *f = '\0';
        next = f + 1;
      }
      if (strlen(p + 4) >= sizeof cap_dir) cap_fail("TESSEL_CAPTURE out: directory is too long");
      strcpy(cap_dir, p + 4);
    } else {
      char* c = strchr(p, ',');
      if (c) {
        *c = '\0';
        next = c + 1;
      }
      if (strncmp(p, "frames:", 7) == 0) {
        char* end = NULL;
        long n = strtol(p + 7, &end, 10);
        if (!end || *end || n < 1 || n > 100000)
          cap_fail("TESSEL_CAPTURE frames: must be a positive integer");
        cap_frames = (int)n;
      } else if (*p) {
        fprintf(stderr, "mesa_capture: unknown TESSEL_CAPTURE key in '%s' (expected frames:N,out:DIR)\n", p);
        exit(3);
      }
    }
    p = next;
  }
  if (!cap_dir[0]) cap_fail("TESSEL_CAPTURE needs out:DIR (e.g. TESSEL_CAPTURE=frames:1,out:/tmp/shots)");
  cap_enabled = 1;
}

/* Reads the given colour buffer (w x h) of the current context and writes the next frame
 * file; `proc` finds glBindBuffer, to unbind a pixel-pack buffer for the read. */
void cap_write(GLenum buffer, int w, int h, cap_proc_fn proc) {
  if (w <= 0 || h <= 0) cap_fail("the window has no size");

  GLint saved_read = 0, saved_pack_buffer = 0;
  GLint saved_align = 4, saved_row = 0, saved_skip_rows = 0, saved_skip_pixels = 0;
  GLint saved_swap = 0, saved_lsb = 0;
  glFinish();
  glGetIntegerv(GL_READ_BUFFER, &saved_read);
  glGetIntegerv(GL_PACK_ALIGNMENT, &saved_align);
  glGetIntegerv(GL_PACK_ROW_LENGTH, &saved_row);
  glGetIntegerv(GL_PACK_SKIP_ROWS, &saved_skip_rows);
  glGetIntegerv(GL_PACK_SKIP_PIXELS, &saved_skip_pixels);
  glGetIntegerv(GL_PACK_SWAP_BYTES, &saved_swap);
  glGetIntegerv(GL_PACK_LSB_FIRST, &saved_lsb);
  while (glGetError() != GL_NO_ERROR) {
  }
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &saved_pack_buffer);
  if (glGetError() != GL_NO_ERROR) saved_pack_buffer = -1; /* not supported: leave alone */

  typedef void (*BindBufferFn)(GLenum, GLuint);
  BindBufferFn bind_buffer = NULL;
  if (saved_pack_buffer > 0) {
    bind_buffer = (BindBufferFn)proc("glBindBuffer");
    if (bind_buffer) bind_buffer(GL_PIXEL_PACK_BUFFER, 0);
  }

  glReadBuffer(buffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
  glPixelStorei(GL_PACK_LSB_FIRST, GL_FALSE);

  size_t stride = (size_t)w * 4;
  unsigned char* pixels = (unsigned char*)malloc(stride * (size_t)h);
  unsigned char* row = (unsigned char*)malloc(stride);
  if (!pixels || !row) cap_fail("out of memory");
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  GLenum err = glGetError();

  glReadBuffer((GLenum)saved_read);
  glPixelStorei(GL_PACK_ALIGNMENT, saved_align);
  glPixelStorei(GL_PACK_ROW_LENGTH, saved_row);
  glPixelStorei(GL_PACK_SKIP_ROWS, saved_skip_rows);
  glPixelStorei(GL_PACK_SKIP_PIXELS, saved_skip_pixels);
  glPixelStorei(GL_PACK_SWAP_BYTES, saved_swap);
  glPixelStorei(GL_PACK_LSB_FIRST, saved_lsb);
  if (bind_buffer) bind_buffer(GL_PIXEL_PACK_BUFFER, (GLuint)saved_pack_buffer);
  if (err != GL_NO_ERROR) {
    fprintf(stderr, "mesa_capture: glReadPixels failed with GL error 0x%04x\n", err);
    exit(3);
  }

  /* GL's first row is the bottom of the window; the PNG's is the top. */
  for (int y = 0; y < h / 2; ++y) {
    unsigned char* a = pixels + (size_t)y * stride;
    unsigned char* b = pixels + (size_t)(h - 1 - y) * stride;
    memcpy(row, a, stride);
    memcpy(a, b, stride);
    memcpy(b, row, stride);
  }

  char final_name[4200], temp_name[4300];
  snprintf(final_name, sizeof final_name, "%s/frame-%04d.png", cap_dir, cap_count);
  snprintf(temp_name, sizeof temp_name, "%s/.frame-%04d.png.tmp", cap_dir, cap_count);
  if (!stbi_write_png(temp_name, w, h, 4, pixels, (int)stride)) {
    fprintf(stderr, "mesa_capture: cannot write %s (does the directory exist?)\n", temp_name);
    remove(temp_name);
    exit(3);
  }
  if (rename(temp_name, final_name) != 0) {
    fprintf(stderr, "mesa_capture: cannot rename %s to %s: %s\n", temp_name, final_name, strerror(errno));
    remove(temp_name);
    exit(3);
  }
  free(row);
  free(pixels);
  if (cap_count == 0) {
    const char* renderer = (const char*)glGetString(GL_RENDERER);
    fprintf(stderr, "mesa_capture: %dx%d %s-buffered, renderer: %s\n", w, h,
            buffer == GL_BACK ? "double" : "single", renderer ? renderer : "?");
  }
  fprintf(stderr, "mesa_capture: wrote %s\n", final_name);
  ++cap_count;
}
