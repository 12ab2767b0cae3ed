/* What the Mesa capture shims share (capture_core.c). */
#ifndef TESSEL_CAPTURE_CORE_H
#define TESSEL_CAPTURE_CORE_H

#include <GL/gl.h>

typedef void (*(*cap_proc_fn)(const char* name))(void);

extern int cap_enabled; /* TESSEL_CAPTURE was given */
extern int cap_frames;  /* frames to write */
extern int cap_count;   /* frames written so far */

void cap_fail(const char* what);
void cap_parse(void);
void cap_write(GLenum buffer, int w, int h, cap_proc_fn proc);

#endif
