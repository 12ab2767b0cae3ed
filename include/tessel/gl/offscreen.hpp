// An OpenGL 1.x context without a window: make it current and call the GL functions of
// <GL/gl.h> (include/compat); they draw into its buffers.
//
//   tessel::gl::Offscreen gl(640, 480);
//   gl.make_current();
//   glClear(GL_COLOR_BUFFER_BIT); ... glFinish();
//   std::vector<uint8_t> rgba = gl.read_rgba8();  // rows bottom-up, as glReadPixels
//
// GLUT programs do not need this: glutCreateWindow makes a context of its own.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

namespace tessel::gl {

class Context;

class Offscreen {
 public:
  // A single-buffered RGBA8 window-like framebuffer with a 24-bit depth buffer and an 8-bit
  // stencil buffer when asked. threads = 0: one worker per hardware thread.
  Offscreen(int width, int height, int threads = 0, bool depth = true, bool stencil = true);
  ~Offscreen();
  Offscreen(const Offscreen&) = delete;
  Offscreen& operator=(const Offscreen&) = delete;

  // GL calls of this thread go to this context from now on.
  void make_current();
  int width() const;
  int height() const;
  // The colour buffer after all queued work has run, RGBA8, rows bottom-up.
  std::vector<uint8_t> read_rgba8();
  // Fragments shaded since the context was made (the gpu layer's counter).
  uint64_t fragments_shaded() const;
  void reset_stats();

 private:
  std::unique_ptr<Context> ctx_;
};

}  // namespace tessel::gl
