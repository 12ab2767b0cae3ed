// GLUT's state: windows (each with its own GL context), menus, timers and callbacks, shared
// by the entry points (glut.cpp), the SDL2 window system (window_sdl.cpp) and the pop-up
// menus drawn by Tessel (menu.cpp).
#pragma once

#include "../gl/headless.hpp"

#include <GL/glut.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "../gl/context.hpp"

namespace tessel::glut {

struct MenuItem {
  std::string label;
  int value = 0;  // the callback's argument, or the submenu id
  bool submenu = false;
};

struct Menu {
  int id = 0;
  void (*callback)(int) = nullptr;
  std::vector<MenuItem> items;
};

struct Timer {
  double due_ms = 0.0;
  unsigned long seq = 0;  // registration order breaks ties
  void (*callback)(int) = nullptr;
  int value = 0;
  int window = 0;
};

struct NativeWindow;  // the window system's part (window_sdl.cpp)

// An open pop-up menu (a chain when submenus are open), in window pixel coordinates.
struct OpenMenu {
  int menu = 0;
  int x = 0, y = 0;  // top-left corner, y down
  int highlighted = -1;
};

struct Window {
  int id = 0;
  std::string title;
  // A subwindow (glutCreateSubWindow) has a parent, and its x, y are its top-left corner in
  // the parent's pixels (y down); it has no window of the window system: the top-level
  // window shows it over its own image, and passes it the input over it (as freeglut's
  // child windows).
  int parent = 0;
  std::vector<int> children;  // in creation order: later ones are drawn on top
  int x = 0, y = 0, width = 300, height = 300;
  unsigned mode = GLUT_RGBA | GLUT_SINGLE;
  std::unique_ptr<gl::Context> context;
  std::unique_ptr<NativeWindow> native;
  bool redisplay = true, reshape_pending = true, visible = true, shown_once = false;
  int menu_for_button[3] = {0, 0, 0};
  std::vector<OpenMenu> open_menus;  // pop-up menus being shown
  int menu_button = -1;              // the button that opened them

  void (*display)() = nullptr;
  void (*reshape)(int, int) = nullptr;
  void (*keyboard)(unsigned char, int, int) = nullptr;
  void (*keyboard_up)(unsigned char, int, int) = nullptr;
  void (*special)(int, int, int) = nullptr;
  void (*special_up)(int, int, int) = nullptr;
  void (*mouse)(int, int, int, int) = nullptr;
  void (*motion)(int, int) = nullptr;
  void (*passive_motion)(int, int) = nullptr;
  void (*entry)(int) = nullptr;
  void (*visibility)(int) = nullptr;
  void (*window_status)(int) = nullptr;
  void (*mouse_wheel)(int, int, int, int) = nullptr;
  void (*position)(int, int) = nullptr;
  void (*close)() = nullptr;

  Window();
  ~Window();  // both in window_sdl.cpp, where NativeWindow is complete
};

using Headless = gl::HeadlessSpec;

struct State {
  bool initialized = false;
  unsigned display_mode = GLUT_RGBA | GLUT_SINGLE;
  int init_width = 300, init_height = 300, init_x = -1, init_y = -1;
  std::vector<std::unique_ptr<Window>> windows;
  int current_window = 0;
  std::vector<std::unique_ptr<Menu>> menus;  // index = id - 1; null when destroyed
  int current_menu = 0;
  std::vector<Timer> timers;
  unsigned long timer_seq = 0;
  void (*idle)() = nullptr;
  void (*menu_status)(int, int, int) = nullptr;
  void (*menu_state)(int) = nullptr;
  Headless headless;
  double virtual_ms = 0.0;  // headless: time advances 1000/60 ms per frame
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  int modifiers = 0;   // valid inside input callbacks
  bool leave = false;  // glutLeaveMainLoop
  // A GLUT error (misuse that GLUT 3.7 calls fatal, or a headless frame that could not be
  // written) was reported: the offending call did nothing and glutMainLoop returns.
  bool failed = false;
  int action_on_close = GLUT_ACTION_EXIT;
  bool ignore_key_repeat = false;
  int program_argc = 0;
  // glutInitContextVersion/Profile: 0.0 is a legacy (compatibility) context.
  int context_major = 0, context_minor = 0;
  int context_profile = 0;  // 0: not given (a 3.2+ request is then a core context, as GLX gives)
};

State& state();
Window* window(int id);
Window* current_window();
Menu* menu(int id);
double now_ms();
void make_current(Window& w);

// Runs what a window needs now: pending reshape, then display when posted.
void service_window(Window& w);
// The top-level window that shows w (w itself when it has no parent).
Window& top_level(Window& w);
// What a window shows, as RGBA rows top-down of its size: its visible buffer with its
// visible subwindows (and theirs) over it at their places, opaque.
void visible_image(const Window& w, std::vector<uint8_t>& rgba_top_down);
// Shows w's top-level window again (w drew): on its native window when it has one.
void present(Window& w);
// The subwindow of `top` (or `top`) under the point (x, y) of top's pixels, y down; x and y
// become that window's own coordinates.
Window& window_at(Window& top, int& x, int& y);
// Fires the timers due by now, then idle once.
void run_timers_and_idle();

// The window system (window_sdl.cpp). open() returns false when no display can be used.
bool native_available();
bool native_open(Window& w);
void native_close(Window& w);
void native_present(Window& w);
void native_set_title(Window& w);
void native_resize(Window& w, int width, int height);
void native_fullscreen(Window& w, bool on);
// Waits up to timeout_ms for events and dispatches them to the callbacks.
void native_pump(double timeout_ms);

// Pop-up menus (menu.cpp): drawing over the presented image (RGBA rows top-down) and input.
// (ox, oy): where w's top-left corner is in the image, for a subwindow's menus.
void menu_draw(const Window& w, std::vector<uint8_t>& rgba_top_down, int width, int height, int ox = 0,
               int oy = 0);
void menu_open(Window& w, int menu_id, int button, int x, int y);
void menu_motion(Window& w, int x, int y);
// Button released: activates the highlighted entry (if any) and closes the menus.
void menu_release(Window& w, int x, int y);

}  // namespace tessel::glut
