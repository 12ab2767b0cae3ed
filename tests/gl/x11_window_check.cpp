// x11_window_check FRAME.png SHOT.png [--timeout SECONDS]
//
// Run inside an X server (Xvfb) while a GLUT program shows its window: takes screenshots of
// the whole screen (XGetImage on the root window) until the program's picture — FRAME.png,
// the same program's headless frame — is shown by a window of its size, and exits 0 then.
// The last screenshot is written to SHOT.png either way. Exit 1 when the picture did not
// appear in time, 2 for bad input or no display. This is the "a real window shows it" test.
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

namespace {

struct Image {
  int w = 0, h = 0;
  std::vector<unsigned char> rgb;
  const unsigned char* at(int x, int y) const { return &rgb[(size_t(y) * size_t(w) + size_t(x)) * 3]; }
};

bool close_enough(const unsigned char* a, const unsigned char* b, int tol) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(int(a[k]) - int(b[k])) > tol) return false;
  return true;
}

bool screenshot(Display* d, Image& out) {
  const Window root = DefaultRootWindow(d);
  XWindowAttributes attr;
  XGetWindowAttributes(d, root, &attr);
  XImage* img = XGetImage(d, root, 0, 0, unsigned(attr.width), unsigned(attr.height), AllPlanes, ZPixmap);
  if (!img) return false;
  out.w = attr.width;
  out.h = attr.height;
  out.rgb.resize(size_t(out.w) * size_t(out.h) * 3);
  const unsigned long rm = img->red_mask, gm = img->green_mask, bm = img->blue_mask;
  auto shift = [](unsigned long m) {
    int s = 0;
    while (m && !(m & 1)) m >>= 1, ++s;
    return s;
  };
  const int rs = shift(rm), gs = shift(gm), bs = shift(bm);
  for (int y = 0; y < out.h; ++y)
    for (int x = 0; x < out.w; ++x) {
      const unsigned long p = XGetPixel(img, x, y);
      unsigned char* o = &out.rgb[(size_t(y) * size_t(out.w) + size_t(x)) * 3];
      o[0] = (unsigned char)((p & rm) >> rs);
      o[1] = (unsigned char)((p & gm) >> gs);
      o[2] = (unsigned char)((p & bm) >> bs);
    }
  XDestroyImage(img);
  return true;
}

// The most common colour of the frame: its background.
const unsigned char* background_of(const Image& frame) {
  std::vector<std::pair<unsigned, size_t>> counts;
  auto key = [&](int i, int j) {
    const unsigned char* p = frame.at(i, j);
    return unsigned(p[0]) << 16 | unsigned(p[1]) << 8 | p[2];
  };
  std::vector<unsigned> keys;
  keys.reserve(size_t(frame.w) * size_t(frame.h));
  for (int j = 0; j < frame.h; ++j)
    for (int i = 0; i < frame.w; ++i) keys.push_back(key(i, j));
  std::sort(keys.begin(), keys.end());
  unsigned best = keys.empty() ? 0 : keys[0];
  size_t best_n = 0;
  for (size_t a = 0; a < keys.size();) {
    size_t b = a;
    while (b < keys.size() && keys[b] == keys[a]) ++b;
    if (b - a > best_n) best_n = b - a, best = keys[a];
    a = b;
  }
  for (int j = 0; j < frame.h; ++j)
    for (int i = 0; i < frame.w; ++i)
      if (key(i, j) == best) return frame.at(i, j);
  return frame.rgb.data();
}

// How much of the frame is on the screen at (x, y), within 3/255: the smaller of the
// fraction of all its pixels and the fraction of its non-background pixels (so a sparse
// picture on a window that is still blank does not count as shown).
double match_at(const Image& screen, const Image& frame, int x, int y) {
  if (x < 0 || y < 0 || x + frame.w > screen.w || y + frame.h > screen.h) return 0.0;
  const unsigned char* bg = background_of(frame);
  size_t same = 0, content = 0, content_same = 0;
  for (int j = 0; j < frame.h; ++j)
    for (int i = 0; i < frame.w; ++i) {
      const bool ok = close_enough(screen.at(x + i, y + j), frame.at(i, j), 3);
      same += ok;
      if (!close_enough(frame.at(i, j), bg, 3)) content += 1, content_same += ok;
    }
  const double all = double(same) / double(size_t(frame.w) * size_t(frame.h));
  return content ? std::min(all, double(content_same) / double(content)) : all;
}

// Where the windows of the frame's size are (top-left, in root coordinates): the places to
// look first.
std::vector<std::pair<int, int>> windows_of_size(Display* d, int w, int h) {
  std::vector<std::pair<int, int>> found;
  const Window root = DefaultRootWindow(d);
  std::vector<Window> todo{root};
  while (!todo.empty()) {
    const Window win = todo.back();
    todo.pop_back();
    Window r, parent, *children = nullptr;
    unsigned n = 0;
    if (!XQueryTree(d, win, &r, &parent, &children, &n)) continue;
    for (unsigned i = 0; i < n; ++i) {
      XWindowAttributes a;
      if (XGetWindowAttributes(d, children[i], &a) && a.map_state == IsViewable) {
        if (a.width == w && a.height == h) {
          int x = 0, y = 0;
          Window child;
          XTranslateCoordinates(d, children[i], root, 0, 0, &x, &y, &child);
          found.emplace_back(x, y);
        }
        todo.push_back(children[i]);
      }
    }
    if (children) XFree(children);
  }
  return found;
}

// Windows come and go while the program starts (SDL makes and drops helper windows): a query
// about one that is gone fails, which the callers check, instead of ending the process as
// Xlib's default error handler would.
int ignore_x_errors(Display*, XErrorEvent*) { return 0; }

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: x11_window_check FRAME.png SHOT.png [--timeout SECONDS]\n");
    return 2;
  }
  double timeout = 20.0;
  for (int i = 3; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--timeout") == 0) timeout = std::atof(argv[i + 1]);
  Image frame;
  int n = 0;
  unsigned char* data = stbi_load(argv[1], &frame.w, &frame.h, &n, 3);
  if (!data) {
    std::fprintf(stderr, "x11_window_check: cannot read %s: %s\n", argv[1], stbi_failure_reason());
    return 2;
  }
  frame.rgb.assign(data, data + size_t(frame.w) * size_t(frame.h) * 3);
  stbi_image_free(data);
  XSetErrorHandler(ignore_x_errors);
  Display* d = XOpenDisplay(nullptr);
  if (!d) {
    std::fprintf(stderr, "x11_window_check: no X display (DISPLAY=%s)\n",
                 std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "");
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  Image screen;
  double best = 0.0;
  int bx = -1, by = -1;
  for (;;) {
    if (screenshot(d, screen)) {
      // The windows of the picture's size (found through the X window tree).
      const auto places = windows_of_size(d, frame.w, frame.h);
      best = 0.0;
      for (auto [x, y] : places) {
        const double f = match_at(screen, frame, x, y);
        if (f > best) best = f, bx = x, by = y;
      }
      if (best >= 0.99) break;
    }
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > timeout) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  if (screen.w > 0) stbi_write_png(argv[2], screen.w, screen.h, 3, screen.rgb.data(), screen.w * 3);
  XCloseDisplay(d);
  if (best >= 0.99) {
    std::printf("window found at (%d, %d): %.3f%% of %s's pixels on screen within 3/255\n", bx, by,
                best * 100.0, argv[1]);
    return 0;
  }
  std::printf("the picture of %s was not on screen after %.0f s (best %.3f%%); screenshot: %s\n", argv[1],
              timeout, best * 100.0, argv[2]);
  return 1;
}
