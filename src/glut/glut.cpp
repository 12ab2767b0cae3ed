// GLUT 3.7 (with the freeglut additions courses use) over Tessel's GL contexts.
//
// Each window owns a tessel::gl::Context whose buffers are the window's. With a display, the
// window is an SDL2 window that shows the front buffer (window_sdl.cpp). Without one — or
// when TESSEL_HEADLESS is set (`frames:N,out:DIR`) — glutMainLoop reshapes each window once,
// then for N frames fires the due timers and the idle callback (frames after the first),
// calls display and writes the window's visible image to DIR/frame-NNNN.png; then it
// returns, as it does when the last window closes (the program ends when main returns). Time in that mode is
// virtual: 1000/60 ms per frame, so a run is the same every time.
#include "../gl/headless.hpp"
#include "../gl/proc_address.hpp"
#include "glut_internal.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "tessel/gpu/image.hpp"

namespace tessel::glut {

namespace {
// Never destroyed: programs end the process from inside their callbacks, when the windows'
// contexts may still be in use and other statics (the gpu layer's) may already be gone.
State& g_state = *new State;

// GLUT 3.7 (§2) makes errors in using GLUT fatal; a library must not end the program, so
// Tessel reports them on stderr, ignores the call that made them and lets glutMainLoop return
// (the program then ends the way its main() does).
void report(const std::string& what) {
  std::fprintf(stderr, "tessel glut: %s\n", what.c_str());
  std::fflush(stderr);
  g_state.failed = true;
  g_state.leave = true;
}

void parse_headless(Headless& h, const char* spec) { gl::parse_headless(h, spec, "tessel glut"); }

void write_frame(Window& w, int frame) {
  // A subwindow is in its top-level window's image.
  if (w.parent) return;
  std::vector<uint8_t> rgba;
  visible_image(w, rgba);
  const gpu::Texture2D& front = w.context->front();
  const std::string problem =
      gl::write_headless_image(rgba, front.width(), front.height(), g_state.headless.out, frame, w.id);
  if (!problem.empty()) report(problem);
}

// The main loop ends by returning to the program, never by ending the process: with GLUT_ACTION_EXIT
// (the default) GLUT would end the process here, and a program's `glutMainLoop(); return 0;`
// does that itself, with its own cleanup and exit status.
void finish_main_loop() { g_state.leave = true; }

void headless_main_loop() {
  std::error_code ec;
  std::filesystem::create_directories(g_state.headless.out, ec);
  if (ec) return report("cannot create the output folder " + g_state.headless.out + ": " + ec.message());
  for (int frame = 0; frame < g_state.headless.frames && !g_state.leave; ++frame) {
    if (frame > 0) {
      g_state.virtual_ms += 1000.0 / 60.0;
      run_timers_and_idle();
    }
    // Each frame shows every window: display runs whether or not it was posted.
    for (size_t i = 0; i < g_state.windows.size(); ++i) {
      Window* w = g_state.windows[i].get();
      if (!w) continue;
      w->redisplay = true;
      service_window(*w);
    }
    for (size_t i = 0; i < g_state.windows.size(); ++i)
      if (Window* w = g_state.windows[i].get()) write_frame(*w, frame);
  }
  finish_main_loop();
}

void windowed_main_loop() {
  while (!g_state.leave) {
    bool any = false;
    for (auto& w : g_state.windows) any |= w != nullptr;
    if (!any) return finish_main_loop();
    for (size_t i = 0; i < g_state.windows.size(); ++i)
      if (Window* w = g_state.windows[i].get()) service_window(*w);
    // Wait for events until the next timer, or not at all when idle work or a redisplay waits.
    double timeout = 100.0;
    bool pending = g_state.idle != nullptr;
    for (auto& w : g_state.windows) pending |= w && (w->redisplay || w->reshape_pending);
    if (pending) timeout = 0.0;
    for (const Timer& t : g_state.timers) timeout = std::min(timeout, std::max(0.0, t.due_ms - now_ms()));
    native_pump(timeout);
    run_timers_and_idle();
  }
}

}  // namespace

State& state() { return g_state; }

Window* window(int id) {
  if (id < 1 || size_t(id) > g_state.windows.size()) return nullptr;
  return g_state.windows[size_t(id - 1)].get();
}

Window* current_window() { return window(g_state.current_window); }

Menu* menu(int id) {
  if (id < 1 || size_t(id) > g_state.menus.size()) return nullptr;
  return g_state.menus[size_t(id - 1)].get();
}

double now_ms() {
  if (g_state.headless.on) return g_state.virtual_ms;
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - g_state.start).count();
}

void make_current(Window& w) {
  g_state.current_window = w.id;
  gl::make_current(w.context.get());
}

void service_window(Window& w) {
  const int id = w.id;
  if (w.reshape_pending) {
    w.reshape_pending = false;
    make_current(w);
    if (w.reshape)
      w.reshape(w.width, w.height);
    else
      glViewport(0, 0, w.width, w.height);  // GLUT's default reshape
    if (!window(id)) return;
    if (!w.shown_once) {
      w.shown_once = true;
      if (w.visibility) w.visibility(GLUT_VISIBLE);
      if (w.window_status) w.window_status(GLUT_FULLY_RETAINED);
      if (!window(id)) return;
    }
  }
  if (w.redisplay && w.visible) {
    w.redisplay = false;
    make_current(w);
    if (!w.display) return report("no display callback registered for window " + std::to_string(id));
    w.display();
    if (!window(id)) return;
    // A single-buffered window shows what was drawn; a double-buffered one its front buffer.
    present(w);
  }
}

Window& top_level(Window& w) {
  Window* t = &w;
  for (int guard = 0; t->parent && guard < 1 << 16; ++guard) {
    Window* p = window(t->parent);
    if (!p) break;
    t = p;
  }
  return *t;
}

void present(Window& w) {
  Window& t = top_level(w);
  if (t.native) native_present(t);
}

void visible_image(const Window& w, std::vector<uint8_t>& out) {
  const gpu::Texture2D& front = w.context->front();
  const int width = front.width(), height = front.height();
  const size_t row = size_t(width) * 4;
  out.resize(row * size_t(height));
  const auto* src = reinterpret_cast<const uint8_t*>(front.level(0).data.data());
  for (int y = 0; y < height; ++y)
    std::memcpy(&out[size_t(y) * row], src + size_t(height - 1 - y) * row, row);
  for (size_t i = 3; i < out.size(); i += 4) out[i] = 255;  // a window is opaque
  std::vector<uint8_t> sub;
  for (int id : w.children) {
    const Window* c = window(id);
    if (!c || !c->visible) continue;
    visible_image(*c, sub);
    const int cw = c->context->front().width(), ch = c->context->front().height();
    for (int y = std::max(0, -c->y); y < ch && c->y + y < height; ++y) {
      const int x0 = std::max(0, -c->x), x1 = std::min(cw, width - c->x);
      if (x1 <= x0) break;
      std::memcpy(&out[size_t(c->y + y) * row + size_t(c->x + x0) * 4],
                  &sub[(size_t(y) * size_t(cw) + size_t(x0)) * 4], size_t(x1 - x0) * 4);
    }
  }
}

Window& window_at(Window& top, int& x, int& y) {
  // The last child (drawn on top) that holds the point, and so on down.
  for (auto it = top.children.rbegin(); it != top.children.rend(); ++it) {
    Window* c = window(*it);
    if (!c || !c->visible) continue;
    if (x >= c->x && y >= c->y && x < c->x + c->width && y < c->y + c->height) {
      x -= c->x;
      y -= c->y;
      return window_at(*c, x, y);
    }
  }
  return top;
}

void run_timers_and_idle() {
  const double now = now_ms();
  // Timers due now, earliest first, registration order for equal times; timers registered
  // by these callbacks wait for the next round.
  std::vector<Timer> due;
  auto& timers = g_state.timers;
  for (size_t i = 0; i < timers.size();) {
    if (timers[i].due_ms <= now) {
      due.push_back(timers[i]);
      timers.erase(timers.begin() + long(i));
    } else {
      ++i;
    }
  }
  std::sort(due.begin(), due.end(), [](const Timer& a, const Timer& b) {
    return a.due_ms != b.due_ms ? a.due_ms < b.due_ms : a.seq < b.seq;
  });
  for (const Timer& t : due) {
    if (Window* w = window(t.window)) make_current(*w);
    t.callback(t.value);
  }
  if (g_state.idle) {
    if (Window* w = current_window()) make_current(*w);
    g_state.idle();
  }
}

}  // namespace tessel::glut

using namespace tessel;
using namespace tessel::glut;

namespace {
// The current window, or nullptr after reporting that `fn` was called without one.
Window* need_window(const char* fn) {
  Window* w = current_window();
  if (!w) report(std::string(fn) + " called with no current window");
  return w;
}
// Whether glutInit has run (reported for `fn` when not).
bool need_init(const char* fn) {
  if (!state().initialized) report(std::string(fn) + " called before glutInit");
  return state().initialized;
}
// The version and profile glutInitContextVersion/Profile asked for. As GLX does for
// freeglut, a 3.2+ request without a profile is a core context; none is a compatibility one.
void apply_context_version(gl::Context& c) {
  const State& s = state();
  if (s.context_major == 0) return;
  const bool profiles = s.context_major > 3 || (s.context_major == 3 && s.context_minor >= 2);
  const bool core = profiles && s.context_profile != GLUT_COMPATIBILITY_PROFILE;
  // The highest version Tessel has is 3.3: a request above it gets 3.3 (what the program can
  // use is what it asked for, minus what is not there: GL_VERSION says which).
  int major = s.context_major, minor = s.context_minor;
  if (major > 3 || (major == 3 && minor > 3)) major = 3, minor = 3;
  c.set_version(major, minor, core);
}
}  // namespace

extern "C" {

void GLAPIENTRY glutInit(int* argcp, char** argv) {
  State& s = state();
  if (s.initialized) {
    std::fprintf(stderr, "tessel glut: glutInit called twice\n");
    return;
  }
  s.initialized = true;
  s.start = std::chrono::steady_clock::now();
  // The X options GLUT understands (GLUT 3.7 spec §2.1); -geometry sets the initial size.
  if (argcp && argv) {
    int out = 1;
    for (int i = 1; i < *argcp; ++i) {
      const char* a = argv[i];
      if (std::strcmp(a, "-geometry") == 0 && i + 1 < *argcp) {
        int w = 0, h = 0, x = 0, y = 0;
        const int n = std::sscanf(argv[i + 1], "%dx%d+%d+%d", &w, &h, &x, &y);
        if (n >= 2 && w > 0 && h > 0) s.init_width = w, s.init_height = h;
        if (n == 4) s.init_x = x, s.init_y = y;
        ++i;
      } else if (std::strcmp(a, "-display") == 0 && i + 1 < *argcp) {
        ++i;
      } else if (std::strcmp(a, "-iconic") == 0 || std::strcmp(a, "-direct") == 0 ||
                 std::strcmp(a, "-indirect") == 0 || std::strcmp(a, "-gldebug") == 0 ||
                 std::strcmp(a, "-sync") == 0) {
      } else {
        argv[out++] = argv[i];
      }
    }
    *argcp = out;
    argv[out] = nullptr;
  }
  const char* h = std::getenv("TESSEL_HEADLESS");
  if (h && *h && std::strcmp(h, "0") != 0)
    parse_headless(s.headless, h);
  else if (!native_available())
    parse_headless(s.headless, "");
}

void GLAPIENTRY glutInitDisplayMode(unsigned int mode) { state().display_mode = mode; }
void GLAPIENTRY glutInitDisplayString(const char* string) {
  // The common words: rgb(a), double, single, depth, stencil, alpha.
  unsigned mode = GLUT_RGBA;
  if (string) {
    const std::string s = string;
    if (s.find("double") != std::string::npos) mode |= GLUT_DOUBLE;
    if (s.find("depth") != std::string::npos) mode |= GLUT_DEPTH;
    if (s.find("stencil") != std::string::npos) mode |= GLUT_STENCIL;
    if (s.find("alpha") != std::string::npos) mode |= GLUT_ALPHA;
  }
  state().display_mode = mode;
}
void GLAPIENTRY glutInitWindowPosition(int x, int y) {
  state().init_x = x;
  state().init_y = y;
}
void GLAPIENTRY glutInitWindowSize(int w, int h) {
  if (w > 0 && h > 0) {
    state().init_width = w;
    state().init_height = h;
  }
}

void GLAPIENTRY glutInitContextVersion(int major, int minor) {
  state().context_major = major;
  state().context_minor = minor;
}
void GLAPIENTRY glutInitContextFlags(int) {}  // debug and forward-compatible contexts behave alike here
void GLAPIENTRY glutInitContextProfile(int profile) { state().context_profile = profile; }
// GLUT's own entry points first, as freeglut's glutGetProcAddress has them, then GL's.
GLUTproc GLAPIENTRY glutGetProcAddress(const char* name) {
  if (!name) return nullptr;
  struct Proc {
    const char* name;
    GLUTproc fn;
  };
  static const Proc kProcs[] = {
#define X(n) {#n, reinterpret_cast<GLUTproc>(&n)},
#include "glut_procs.inc"
#undef X
  };
  for (const Proc& p : kProcs)
    if (std::strcmp(p.name, name) == 0) return p.fn;
  return gl::proc_address(name);
}

int GLAPIENTRY glutCreateWindow(const char* title) {
  if (!need_init("glutCreateWindow")) return 0;
  State& s = state();
  auto w = std::make_unique<Window>();
  w->id = int(s.windows.size()) + 1;
  w->title = title ? title : "";
  w->width = s.init_width;
  w->height = s.init_height;
  w->x = std::max(0, s.init_x);
  w->y = std::max(0, s.init_y);
  w->mode = s.display_mode;
  const bool dbl = (w->mode & GLUT_DOUBLE) != 0;
  w->context = std::make_unique<gl::Context>(w->width, w->height, dbl, (w->mode & GLUT_DEPTH) != 0,
                                             (w->mode & GLUT_STENCIL) != 0, (w->mode & GLUT_ALPHA) != 0);
  apply_context_version(*w->context);
  if (!s.headless.on && !native_open(*w)) parse_headless(s.headless, "");
  Window& ref = *w;
  s.windows.push_back(std::move(w));
  make_current(ref);
  return ref.id;
}
int GLAPIENTRY glutCreateSubWindow(int win, int x, int y, int width, int height) {
  if (!need_init("glutCreateSubWindow")) return 0;
  State& s = state();
  Window* parent = window(win);
  if (!parent) return 0;
  auto w = std::make_unique<Window>();
  w->id = int(s.windows.size()) + 1;
  w->title = parent->title;
  w->parent = win;
  w->x = x;
  w->y = y;
  w->width = std::max(1, width);
  w->height = std::max(1, height);
  w->mode = s.display_mode;
  const bool dbl = (w->mode & GLUT_DOUBLE) != 0;
  w->context = std::make_unique<gl::Context>(w->width, w->height, dbl, (w->mode & GLUT_DEPTH) != 0,
                                             (w->mode & GLUT_STENCIL) != 0, (w->mode & GLUT_ALPHA) != 0);
  apply_context_version(*w->context);
  parent->children.push_back(w->id);
  Window& ref = *w;
  s.windows.push_back(std::move(w));
  make_current(ref);
  return ref.id;
}
void GLAPIENTRY glutDestroyWindow(int win) {
  State& s = state();
  Window* w = window(win);
  if (!w) return;
  // Its subwindows go with it (GLUT 3.7 section 4.3).
  const std::vector<int> children = w->children;
  for (int c : children) glutDestroyWindow(c);
  if (Window* p = window(w->parent)) {
    auto& v = p->children;
    v.erase(std::remove(v.begin(), v.end(), win), v.end());
    p->redisplay = true;
  }
  if (gl::current() == w->context.get()) gl::make_current(nullptr);
  s.windows[size_t(win - 1)].reset();
  if (s.current_window == win) s.current_window = 0;
}
int GLAPIENTRY glutGetWindow(void) { return current_window() ? state().current_window : 0; }
void GLAPIENTRY glutSetWindow(int win) {
  if (Window* w = window(win)) make_current(*w);
}
void GLAPIENTRY glutPostRedisplay(void) {
  if (Window* w = need_window("glutPostRedisplay")) w->redisplay = true;
}
void GLAPIENTRY glutPostWindowRedisplay(int win) {
  if (Window* w = window(win)) w->redisplay = true;
}
void GLAPIENTRY glutSwapBuffers(void) {
  Window* w = need_window("glutSwapBuffers");
  if (!w) return;
  w->context->swap_buffers();
  if (w->mode & GLUT_DOUBLE) present(*w);
}
void GLAPIENTRY glutSetWindowTitle(const char* title) {
  Window* w = need_window("glutSetWindowTitle");
  if (!w) return;
  w->title = title ? title : "";
  if (w->native) native_set_title(*w);
}
void GLAPIENTRY glutSetIconTitle(const char*) {}
void GLAPIENTRY glutPositionWindow(int x, int y) {
  Window* w = need_window("glutPositionWindow");
  if (!w) return;
  w->x = x;
  w->y = y;
  if (w->parent) present(*w);
}
void GLAPIENTRY glutReshapeWindow(int width, int height) {
  Window* w = need_window("glutReshapeWindow");
  if (!w) return;
  if (width <= 0 || height <= 0) return;
  if (w->native) native_resize(*w, width, height);
  w->width = width;
  w->height = height;
  w->context->resize(width, height);
  w->reshape_pending = true;
  w->redisplay = true;
}
void GLAPIENTRY glutPopWindow(void) {}
void GLAPIENTRY glutPushWindow(void) {}
void GLAPIENTRY glutIconifyWindow(void) {}
void GLAPIENTRY glutShowWindow(void) {
  Window* w = need_window("glutShowWindow");
  if (!w) return;
  w->visible = true;
  w->redisplay = true;
}
void GLAPIENTRY glutHideWindow(void) {
  Window* w = need_window("glutHideWindow");
  if (!w) return;
  w->visible = false;
  if (w->parent) present(*w);
}
void GLAPIENTRY glutFullScreen(void) {
  Window* w = need_window("glutFullScreen");
  if (!w) return;
  if (w->native) native_fullscreen(*w, true);
}
void GLAPIENTRY glutFullScreenToggle(void) { glutFullScreen(); }
void GLAPIENTRY glutLeaveFullScreen(void) {
  Window* w = need_window("glutLeaveFullScreen");
  if (!w) return;
  if (w->native) native_fullscreen(*w, false);
}
void GLAPIENTRY glutSetCursor(int) {}
void GLAPIENTRY glutWarpPointer(int, int) {}

void GLAPIENTRY glutMainLoop(void) {
  if (!need_init("glutMainLoop")) return;
  State& s = state();
  if (s.failed) return;  // an error already reported: the program ends as its main() does
  s.leave = false;
  if (s.headless.on)
    headless_main_loop();
  else
    windowed_main_loop();
}
void GLAPIENTRY glutMainLoopEvent(void) {
  State& s = state();
  if (!s.headless.on) native_pump(0.0);
  for (size_t i = 0; i < s.windows.size(); ++i)
    if (Window* w = s.windows[i].get()) service_window(*w);
  run_timers_and_idle();
}
void GLAPIENTRY glutLeaveMainLoop(void) { state().leave = true; }
void GLAPIENTRY glutExit(void) {
  state().windows.clear();
  state().leave = true;
}

// --- callbacks ---
#define SET_CALLBACK(name, member, type)               \
  void GLAPIENTRY name(decltype(Window::member) f) {   \
    if (Window* w = need_window(#name)) w->member = f; \
  }

SET_CALLBACK(glutDisplayFunc, display, void (*)(void))
SET_CALLBACK(glutKeyboardFunc, keyboard, void (*)(unsigned char, int, int))
SET_CALLBACK(glutKeyboardUpFunc, keyboard_up, void (*)(unsigned char, int, int))
SET_CALLBACK(glutSpecialFunc, special, void (*)(int, int, int))
SET_CALLBACK(glutSpecialUpFunc, special_up, void (*)(int, int, int))
SET_CALLBACK(glutMouseFunc, mouse, void (*)(int, int, int, int))
SET_CALLBACK(glutMotionFunc, motion, void (*)(int, int))
SET_CALLBACK(glutPassiveMotionFunc, passive_motion, void (*)(int, int))
SET_CALLBACK(glutEntryFunc, entry, void (*)(int))
SET_CALLBACK(glutVisibilityFunc, visibility, void (*)(int))
SET_CALLBACK(glutWindowStatusFunc, window_status, void (*)(int))
SET_CALLBACK(glutMouseWheelFunc, mouse_wheel, void (*)(int, int, int, int))
SET_CALLBACK(glutPositionFunc, position, void (*)(int, int))
SET_CALLBACK(glutCloseFunc, close, void (*)(void))
SET_CALLBACK(glutWMCloseFunc, close, void (*)(void))

void GLAPIENTRY glutReshapeFunc(void (*f)(int, int)) {
  Window* w = need_window("glutReshapeFunc");
  if (!w) return;
  w->reshape = f;
  w->reshape_pending = true;
}
void GLAPIENTRY glutIdleFunc(void (*f)(void)) { state().idle = f; }
void GLAPIENTRY glutTimerFunc(unsigned int ms, void (*f)(int), int value) {
  if (!need_init("glutTimerFunc") || !f) return;
  State& s = state();
  s.timers.push_back({now_ms() + double(ms), s.timer_seq++, f, value, s.current_window});
}
void GLAPIENTRY glutMenuStateFunc(void (*f)(int)) { state().menu_state = f; }
void GLAPIENTRY glutMenuStatusFunc(void (*f)(int, int, int)) { state().menu_status = f; }
void GLAPIENTRY glutOverlayDisplayFunc(void (*)(void)) {}
void GLAPIENTRY glutSpaceballMotionFunc(void (*)(int, int, int)) {}
void GLAPIENTRY glutSpaceballRotateFunc(void (*)(int, int, int)) {}
void GLAPIENTRY glutSpaceballButtonFunc(void (*)(int, int)) {}
void GLAPIENTRY glutButtonBoxFunc(void (*)(int, int)) {}
void GLAPIENTRY glutDialsFunc(void (*)(int, int)) {}
void GLAPIENTRY glutTabletMotionFunc(void (*)(int, int)) {}
void GLAPIENTRY glutTabletButtonFunc(void (*)(int, int, int, int)) {}
void GLAPIENTRY glutJoystickFunc(void (*)(unsigned int, int, int, int), int) {}
void GLAPIENTRY glutForceJoystickFunc(void) {}

// --- menus ---
int GLAPIENTRY glutCreateMenu(void (*callback)(int)) {
  if (!need_init("glutCreateMenu")) return 0;
  State& s = state();
  auto m = std::make_unique<Menu>();
  m->id = int(s.menus.size()) + 1;
  m->callback = callback;
  s.menus.push_back(std::move(m));
  s.current_menu = int(s.menus.size());
  return s.current_menu;
}
void GLAPIENTRY glutDestroyMenu(int id) {
  State& s = state();
  if (!menu(id)) return;
  s.menus[size_t(id - 1)].reset();
  if (s.current_menu == id) s.current_menu = 0;
}
int GLAPIENTRY glutGetMenu(void) { return menu(state().current_menu) ? state().current_menu : 0; }
void GLAPIENTRY glutSetMenu(int id) {
  if (menu(id)) state().current_menu = id;
}
void GLAPIENTRY glutAddMenuEntry(const char* label, int value) {
  if (Menu* m = menu(state().current_menu)) m->items.push_back({label ? label : "", value, false});
}
void GLAPIENTRY glutAddSubMenu(const char* label, int submenu) {
  if (Menu* m = menu(state().current_menu)) m->items.push_back({label ? label : "", submenu, true});
}
void GLAPIENTRY glutChangeToMenuEntry(int item, const char* label, int value) {
  Menu* m = menu(state().current_menu);
  if (!m || item < 1 || size_t(item) > m->items.size()) return;
  m->items[size_t(item - 1)] = {label ? label : "", value, false};
}
void GLAPIENTRY glutChangeToSubMenu(int item, const char* label, int submenu) {
  Menu* m = menu(state().current_menu);
  if (!m || item < 1 || size_t(item) > m->items.size()) return;
  m->items[size_t(item - 1)] = {label ? label : "", submenu, true};
}
void GLAPIENTRY glutRemoveMenuItem(int item) {
  Menu* m = menu(state().current_menu);
  if (!m || item < 1 || size_t(item) > m->items.size()) return;
  m->items.erase(m->items.begin() + (item - 1));
}
void GLAPIENTRY glutAttachMenu(int button) {
  Window* w = need_window("glutAttachMenu");
  if (!w) return;
  if (button >= 0 && button < 3) w->menu_for_button[button] = state().current_menu;
}
void GLAPIENTRY glutDetachMenu(int button) {
  Window* w = need_window("glutDetachMenu");
  if (!w) return;
  if (button >= 0 && button < 3) w->menu_for_button[button] = 0;
}

// --- state queries ---
int GLAPIENTRY glutGet(GLenum what) {
  State& s = state();
  Window* w = current_window();
  switch (what) {
    case GLUT_WINDOW_X: return w ? w->x : 0;
    case GLUT_WINDOW_Y: return w ? w->y : 0;
    case GLUT_WINDOW_WIDTH: return w ? w->width : 0;
    case GLUT_WINDOW_HEIGHT: return w ? w->height : 0;
    case GLUT_WINDOW_BUFFER_SIZE: return 32;
    case GLUT_WINDOW_STENCIL_SIZE: return w && (w->mode & GLUT_STENCIL) ? 8 : 0;
    case GLUT_WINDOW_DEPTH_SIZE: return w && (w->mode & GLUT_DEPTH) ? 24 : 0;
    case GLUT_WINDOW_RED_SIZE:
    case GLUT_WINDOW_GREEN_SIZE:
    case GLUT_WINDOW_BLUE_SIZE:
    case GLUT_WINDOW_ALPHA_SIZE: return 8;
    case GLUT_WINDOW_DOUBLEBUFFER: return w && (w->mode & GLUT_DOUBLE) ? 1 : 0;
    case GLUT_WINDOW_RGBA: return 1;
    case GLUT_WINDOW_PARENT: return w ? w->parent : 0;
    case GLUT_WINDOW_NUM_CHILDREN: return w ? int(w->children.size()) : 0;
    case GLUT_WINDOW_COLORMAP_SIZE:
    case GLUT_WINDOW_NUM_SAMPLES:
    case GLUT_WINDOW_STEREO:
    case GLUT_WINDOW_CURSOR: return 0;
    case GLUT_SCREEN_WIDTH: return 1920;
    case GLUT_SCREEN_HEIGHT: return 1080;
    case GLUT_SCREEN_WIDTH_MM: return 508;
    case GLUT_SCREEN_HEIGHT_MM: return 286;
    case GLUT_MENU_NUM_ITEMS: {
      Menu* m = menu(s.current_menu);
      return m ? int(m->items.size()) : 0;
    }
    case GLUT_DISPLAY_MODE_POSSIBLE: return 1;
    case GLUT_INIT_WINDOW_X: return s.init_x;
    case GLUT_INIT_WINDOW_Y: return s.init_y;
    case GLUT_INIT_WINDOW_WIDTH: return s.init_width;
    case GLUT_INIT_WINDOW_HEIGHT: return s.init_height;
    case GLUT_INIT_DISPLAY_MODE: return int(s.display_mode);
    case GLUT_ELAPSED_TIME: return int(now_ms());
    case GLUT_WINDOW_FORMAT_ID: return 1;
    case GLUT_ACTION_ON_WINDOW_CLOSE: return s.action_on_close;
    case GLUT_INIT_STATE: return s.initialized ? 1 : 0;
    default: return -1;
  }
}
int GLAPIENTRY glutDeviceGet(GLenum what) {
  switch (what) {
    case GLUT_HAS_KEYBOARD:
    case GLUT_HAS_MOUSE: return state().headless.on ? 0 : 1;
    case GLUT_NUM_MOUSE_BUTTONS: return 3;
    case GLUT_DEVICE_IGNORE_KEY_REPEAT: return state().ignore_key_repeat ? 1 : 0;
    case GLUT_DEVICE_KEY_REPEAT:
      return state().ignore_key_repeat ? GLUT_KEY_REPEAT_OFF : GLUT_KEY_REPEAT_DEFAULT;
    default: return 0;
  }
}
int GLAPIENTRY glutLayerGet(GLenum what) {
  switch (what) {
    case GLUT_LAYER_IN_USE: return GLUT_NORMAL;
    case GLUT_NORMAL_DAMAGED: return 0;
    default: return 0;
  }
}
int GLAPIENTRY glutGetModifiers(void) { return state().modifiers; }
int GLAPIENTRY glutExtensionSupported(const char*) { return 0; }
void GLAPIENTRY glutSetOption(GLenum option, int value) {
  if (option == GLUT_ACTION_ON_WINDOW_CLOSE) state().action_on_close = value;
}
void GLAPIENTRY glutIgnoreKeyRepeat(int ignore) { state().ignore_key_repeat = ignore != 0; }
void GLAPIENTRY glutSetKeyRepeat(int mode) { state().ignore_key_repeat = mode == GLUT_KEY_REPEAT_OFF; }
void GLAPIENTRY glutReportErrors(void) {
  GLenum e;
  while ((e = glGetError()) != GL_NO_ERROR) std::fprintf(stderr, "GL error: 0x%04x\n", unsigned(e));
}

// Overlays, colour maps, video resizing and game mode are not offered (GLUT lets a program
// ask: the queries say "not available").
void GLAPIENTRY glutEstablishOverlay(void) {}
void GLAPIENTRY glutRemoveOverlay(void) {}
void GLAPIENTRY glutUseLayer(GLenum) {}
void GLAPIENTRY glutPostOverlayRedisplay(void) {}
void GLAPIENTRY glutPostWindowOverlayRedisplay(int) {}
void GLAPIENTRY glutShowOverlay(void) {}
void GLAPIENTRY glutHideOverlay(void) {}
void GLAPIENTRY glutSetColor(int, GLfloat, GLfloat, GLfloat) {}
GLfloat GLAPIENTRY glutGetColor(int, int) { return -1.0f; }
void GLAPIENTRY glutCopyColormap(int) {}
int GLAPIENTRY glutVideoResizeGet(GLenum) { return 0; }
void GLAPIENTRY glutSetupVideoResizing(void) {}
void GLAPIENTRY glutStopVideoResizing(void) {}
void GLAPIENTRY glutVideoResize(int, int, int, int) {}
void GLAPIENTRY glutVideoPan(int, int, int, int) {}
void GLAPIENTRY glutGameModeString(const char*) {}
int GLAPIENTRY glutEnterGameMode(void) { return 0; }
void GLAPIENTRY glutLeaveGameMode(void) {}
int GLAPIENTRY glutGameModeGet(GLenum what) { return what == GLUT_GAME_MODE_POSSIBLE ? 0 : -1; }

}  // extern "C"
