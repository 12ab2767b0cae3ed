// Headless windows, shared by Tessel's GLUT and GLFW: TESSEL_HEADLESS=frames:N,out:DIR asks
// for N frames, each written as DIR/frame-NNNN.png (frame-NNNN-wK.png for window K > 1).
#pragma once

#include <string>
#include <vector>

namespace tessel::gl {

class Context;

struct HeadlessSpec {
  bool on = false;
  int frames = 1;
  std::string out = ".";
};

// Parses "frames:N,out:DIR" (either may be missing) into `h` and turns it on; what it does
// not understand is reported on stderr, prefixed by `who` ("tessel glut").
void parse_headless(HeadlessSpec& h, const char* spec, const char* who);

// Writes the context's front buffer (RGB, top row first) as frame `frame` of window `window`
// under `dir`. Returns "" or what went wrong.
std::string write_headless_frame(Context& c, const std::string& dir, int frame, int window);
// The same for an image already composed: RGBA rows, top row first (a window with subwindows).
std::string write_headless_image(const std::vector<uint8_t>& rgba_top_down, int width, int height,
                                 const std::string& dir, int frame, int window);

}  // namespace tessel::gl
