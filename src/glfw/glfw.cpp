// GLFW 3.3 over Tessel (include/compat/GLFW/glfw3.h): windows over SDL2, or headless; each
// window owns a Tessel GL context of the version and profile its hints ask for.
//
// Headless (TESSEL_HEADLESS=frames:N,out:DIR, or no display): every glfwSwapBuffers writes the
// window's picture to DIR/frame-NNNN.png; after N frames every window is asked to close, so
// the program's `while (!glfwWindowShouldClose(w))` loop ends and it exits as it would when a
// user closes the window. glfwGetTime then advances 1/60 s a frame, so what a program draws
// from the time is the same on every run.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "../gl/context.hpp"
#include "../gl/headless.hpp"
#include "../gl/proc_address.hpp"

#if TESSEL_HAVE_SDL2
#include <SDL2/SDL.h>
#endif

struct GLFWmonitor {
  void* user = nullptr;
};
struct GLFWcursor {
  int shape = 0;
};

struct GLFWwindow {
  std::unique_ptr<tessel::gl::Context> context;  // null for GLFW_NO_API windows
  std::string title;
  int width = 0, height = 0, x = 0, y = 0;
  bool should_close = false, visible = true, resizable = true, decorated = true, focused = true;
  bool iconified = false, maximized = false, floating = false;
  int frame = 0;  // frames swapped
  void* user = nullptr;
  int cursor_mode = GLFW_CURSOR_NORMAL;
  bool sticky_keys = false, sticky_buttons = false, lock_mods = false, raw_motion = false;
  std::array<signed char, GLFW_KEY_LAST + 1> keys{};
  std::array<signed char, GLFW_MOUSE_BUTTON_LAST + 1> buttons{};
  double cursor_x = 0.0, cursor_y = 0.0;
  float opacity = 1.0f;
  GLFWwindowposfun pos_cb = nullptr;
  GLFWwindowsizefun size_cb = nullptr;
  GLFWwindowclosefun close_cb = nullptr;
  GLFWwindowrefreshfun refresh_cb = nullptr;
  GLFWwindowfocusfun focus_cb = nullptr;
  GLFWwindowiconifyfun iconify_cb = nullptr;
  GLFWwindowmaximizefun maximize_cb = nullptr;
  GLFWframebuffersizefun fbsize_cb = nullptr;
  GLFWwindowcontentscalefun scale_cb = nullptr;
  GLFWmousebuttonfun button_cb = nullptr;
  GLFWcursorposfun cursor_cb = nullptr;
  GLFWcursorenterfun enter_cb = nullptr;
  GLFWscrollfun scroll_cb = nullptr;
  GLFWkeyfun key_cb = nullptr;
  GLFWcharfun char_cb = nullptr;
  GLFWcharmodsfun charmods_cb = nullptr;
  GLFWdropfun drop_cb = nullptr;
#if TESSEL_HAVE_SDL2
  SDL_Window* sdl = nullptr;
  SDL_Renderer* renderer = nullptr;
  SDL_Texture* texture = nullptr;
  int tex_w = 0, tex_h = 0;
  std::vector<uint8_t> staging;
#endif
};

namespace {

using Clock = std::chrono::steady_clock;

struct Hints {
  int client_api = GLFW_OPENGL_API;
  int major = 1, minor = 0;
  int profile = GLFW_OPENGL_ANY_PROFILE;
  int depth_bits = 24, stencil_bits = 8, alpha_bits = 8;
  bool double_buffer = true, resizable = true, visible = true, decorated = true, focused = true;
  bool floating = false, maximized = false;
};

struct State {
  bool initialized = false;
  Hints hints;
  std::vector<GLFWwindow*> windows;
  GLFWwindow* current = nullptr;
  GLFWerrorfun error_cb = nullptr;
  int error_code = GLFW_NO_ERROR;
  std::string error_text;
  tessel::gl::HeadlessSpec headless;
  bool sdl = false;
  Clock::time_point start = Clock::now();
  double time_offset = 0.0;
  double headless_time = 0.0;  // seconds: 1/60 per swapped frame
  std::string clipboard;
  GLFWmonitor monitor;
  GLFWmonitorfun monitor_cb = nullptr;
  GLFWjoystickfun joystick_cb = nullptr;
  std::array<void*, GLFW_JOYSTICK_LAST + 1> joystick_user{};
};

State& st() {
  static State s;
  return s;
}

void error(int code, const char* format, ...) {
  char text[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof text, format, args);
  va_end(args);
  State& s = st();
  s.error_code = code;
  s.error_text = text;
  if (s.error_cb) s.error_cb(code, text);
}

bool need_init() {
  if (st().initialized) return true;
  error(GLFW_NOT_INITIALIZED, "The GLFW library is not initialized");
  return false;
}

const GLFWvidmode kMode = {1920, 1080, 8, 8, 8, 60};

#if TESSEL_HAVE_SDL2
int key_of(SDL_Keycode k) {
  if (k >= SDLK_a && k <= SDLK_z) return GLFW_KEY_A + int(k - SDLK_a);
  if (k >= SDLK_0 && k <= SDLK_9) return GLFW_KEY_0 + int(k - SDLK_0);
  if (k >= SDLK_F1 && k <= SDLK_F12) return GLFW_KEY_F1 + int(k - SDLK_F1);
  if (k >= SDLK_KP_1 && k <= SDLK_KP_9) return GLFW_KEY_KP_1 + int(k - SDLK_KP_1);
  switch (k) {
    case SDLK_SPACE: return GLFW_KEY_SPACE;
    case SDLK_QUOTE: return GLFW_KEY_APOSTROPHE;
    case SDLK_COMMA: return GLFW_KEY_COMMA;
    case SDLK_MINUS: return GLFW_KEY_MINUS;
    case SDLK_PERIOD: return GLFW_KEY_PERIOD;
    case SDLK_SLASH: return GLFW_KEY_SLASH;
    case SDLK_SEMICOLON: return GLFW_KEY_SEMICOLON;
    case SDLK_EQUALS: return GLFW_KEY_EQUAL;
    case SDLK_LEFTBRACKET: return GLFW_KEY_LEFT_BRACKET;
    case SDLK_BACKSLASH: return GLFW_KEY_BACKSLASH;
    case SDLK_RIGHTBRACKET: return GLFW_KEY_RIGHT_BRACKET;
    case SDLK_BACKQUOTE: return GLFW_KEY_GRAVE_ACCENT;
    case SDLK_ESCAPE: return GLFW_KEY_ESCAPE;
    case SDLK_RETURN: return GLFW_KEY_ENTER;
    case SDLK_TAB: return GLFW_KEY_TAB;
    case SDLK_BACKSPACE: return GLFW_KEY_BACKSPACE;
    case SDLK_INSERT: return GLFW_KEY_INSERT;
    case SDLK_DELETE: return GLFW_KEY_DELETE;
    case SDLK_RIGHT: return GLFW_KEY_RIGHT;
    case SDLK_LEFT: return GLFW_KEY_LEFT;
    case SDLK_DOWN: return GLFW_KEY_DOWN;
    case SDLK_UP: return GLFW_KEY_UP;
    case SDLK_PAGEUP: return GLFW_KEY_PAGE_UP;
    case SDLK_PAGEDOWN: return GLFW_KEY_PAGE_DOWN;
    case SDLK_HOME: return GLFW_KEY_HOME;
    case SDLK_END: return GLFW_KEY_END;
    case SDLK_CAPSLOCK: return GLFW_KEY_CAPS_LOCK;
    case SDLK_SCROLLLOCK: return GLFW_KEY_SCROLL_LOCK;
    case SDLK_NUMLOCKCLEAR: return GLFW_KEY_NUM_LOCK;
    case SDLK_PRINTSCREEN: return GLFW_KEY_PRINT_SCREEN;
    case SDLK_PAUSE: return GLFW_KEY_PAUSE;
    case SDLK_KP_0: return GLFW_KEY_KP_0;
    case SDLK_KP_PERIOD: return GLFW_KEY_KP_DECIMAL;
    case SDLK_KP_DIVIDE: return GLFW_KEY_KP_DIVIDE;
    case SDLK_KP_MULTIPLY: return GLFW_KEY_KP_MULTIPLY;
    case SDLK_KP_MINUS: return GLFW_KEY_KP_SUBTRACT;
    case SDLK_KP_PLUS: return GLFW_KEY_KP_ADD;
    case SDLK_KP_ENTER: return GLFW_KEY_KP_ENTER;
    case SDLK_KP_EQUALS: return GLFW_KEY_KP_EQUAL;
    case SDLK_LSHIFT: return GLFW_KEY_LEFT_SHIFT;
    case SDLK_LCTRL: return GLFW_KEY_LEFT_CONTROL;
    case SDLK_LALT: return GLFW_KEY_LEFT_ALT;
    case SDLK_LGUI: return GLFW_KEY_LEFT_SUPER;
    case SDLK_RSHIFT: return GLFW_KEY_RIGHT_SHIFT;
    case SDLK_RCTRL: return GLFW_KEY_RIGHT_CONTROL;
    case SDLK_RALT: return GLFW_KEY_RIGHT_ALT;
    case SDLK_RGUI: return GLFW_KEY_RIGHT_SUPER;
    case SDLK_MENU: return GLFW_KEY_MENU;
    default: return GLFW_KEY_UNKNOWN;
  }
}

int mods_now() {
  const SDL_Keymod m = SDL_GetModState();
  int r = 0;
  if (m & KMOD_SHIFT) r |= GLFW_MOD_SHIFT;
  if (m & KMOD_CTRL) r |= GLFW_MOD_CONTROL;
  if (m & KMOD_ALT) r |= GLFW_MOD_ALT;
  if (m & KMOD_GUI) r |= GLFW_MOD_SUPER;
  if (m & KMOD_CAPS) r |= GLFW_MOD_CAPS_LOCK;
  if (m & KMOD_NUM) r |= GLFW_MOD_NUM_LOCK;
  return r;
}

GLFWwindow* window_of(Uint32 id) {
  for (GLFWwindow* w : st().windows)
    if (w->sdl && SDL_GetWindowID(w->sdl) == id) return w;
  return nullptr;
}

bool open_native(GLFWwindow& w) {
  Uint32 flags = SDL_WINDOW_SHOWN;
  if (w.resizable) flags |= SDL_WINDOW_RESIZABLE;
  if (!w.decorated) flags |= SDL_WINDOW_BORDERLESS;
  if (!w.visible) flags = (flags & ~Uint32(SDL_WINDOW_SHOWN)) | SDL_WINDOW_HIDDEN;
  w.sdl = SDL_CreateWindow(w.title.c_str(), SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, w.width,
                           w.height, flags);
  if (!w.sdl) return false;
  w.renderer = SDL_CreateRenderer(w.sdl, -1, SDL_RENDERER_SOFTWARE);
  if (!w.renderer) {
    SDL_DestroyWindow(w.sdl);
    w.sdl = nullptr;
    return false;
  }
  return true;
}

void close_native(GLFWwindow& w) {
  if (w.texture) SDL_DestroyTexture(w.texture);
  if (w.renderer) SDL_DestroyRenderer(w.renderer);
  if (w.sdl) SDL_DestroyWindow(w.sdl);
  w.texture = nullptr;
  w.renderer = nullptr;
  w.sdl = nullptr;
}

// Shows the context's front buffer (rows bottom-up) in the window.
void present(GLFWwindow& w) {
  if (!w.sdl || !w.context) return;
  const tessel::gpu::Texture2D& front = w.context->front();
  const int width = front.width(), height = front.height();
  if (!w.texture || w.tex_w != width || w.tex_h != height) {
    if (w.texture) SDL_DestroyTexture(w.texture);
    w.texture =
        SDL_CreateTexture(w.renderer, SDL_PIXELFORMAT_ABGR8888, SDL_TEXTUREACCESS_STREAMING, width, height);
    w.tex_w = width;
    w.tex_h = height;
  }
  if (!w.texture) return;
  const auto* src = reinterpret_cast<const uint8_t*>(front.level(0).data.data());
  const size_t row = size_t(width) * 4;
  w.staging.resize(row * size_t(height));
  for (int y = 0; y < height; ++y)
    std::memcpy(&w.staging[size_t(y) * row], src + size_t(height - 1 - y) * row, row);
  SDL_UpdateTexture(w.texture, nullptr, w.staging.data(), int(row));
  SDL_RenderClear(w.renderer);
  SDL_RenderCopy(w.renderer, w.texture, nullptr, nullptr);
  SDL_RenderPresent(w.renderer);
}

void resized(GLFWwindow& w, int width, int height) {
  if (width == w.width && height == w.height) return;
  w.width = width;
  w.height = height;
  if (w.context) w.context->resize(width, height);
  if (w.size_cb) w.size_cb(&w, width, height);
  if (w.fbsize_cb) w.fbsize_cb(&w, width, height);
}

void key_event(GLFWwindow& w, int key, int scancode, int action, int mods) {
  if (key >= 0 && key <= GLFW_KEY_LAST) {
    if (action == GLFW_RELEASE && w.sticky_keys)
      w.keys[size_t(key)] = 3;  // sticky: reads as pressed once more
    else
      w.keys[size_t(key)] = action == GLFW_RELEASE ? GLFW_RELEASE : GLFW_PRESS;
  }
  if (!w.lock_mods) mods &= ~(GLFW_MOD_CAPS_LOCK | GLFW_MOD_NUM_LOCK);
  if (w.key_cb) w.key_cb(&w, key, scancode, action, mods);
}

void dispatch(const SDL_Event& e) {
  switch (e.type) {
    case SDL_WINDOWEVENT: {
      GLFWwindow* w = window_of(e.window.windowID);
      if (!w) return;
      switch (e.window.event) {
        case SDL_WINDOWEVENT_CLOSE:
          w->should_close = true;
          if (w->close_cb) w->close_cb(w);
          break;
        case SDL_WINDOWEVENT_SIZE_CHANGED: resized(*w, e.window.data1, e.window.data2); break;
        case SDL_WINDOWEVENT_MOVED:
          w->x = e.window.data1;
          w->y = e.window.data2;
          if (w->pos_cb) w->pos_cb(w, w->x, w->y);
          break;
        case SDL_WINDOWEVENT_EXPOSED:
          if (w->refresh_cb) w->refresh_cb(w);
          break;
        case SDL_WINDOWEVENT_FOCUS_GAINED:
        case SDL_WINDOWEVENT_FOCUS_LOST:
          w->focused = e.window.event == SDL_WINDOWEVENT_FOCUS_GAINED;
          if (w->focus_cb) w->focus_cb(w, w->focused);
          break;
        case SDL_WINDOWEVENT_ENTER:
        case SDL_WINDOWEVENT_LEAVE:
          if (w->enter_cb) w->enter_cb(w, e.window.event == SDL_WINDOWEVENT_ENTER);
          break;
        case SDL_WINDOWEVENT_MINIMIZED:
        case SDL_WINDOWEVENT_RESTORED:
          w->iconified = e.window.event == SDL_WINDOWEVENT_MINIMIZED;
          if (w->iconify_cb) w->iconify_cb(w, w->iconified);
          break;
        case SDL_WINDOWEVENT_MAXIMIZED:
          w->maximized = true;
          if (w->maximize_cb) w->maximize_cb(w, 1);
          break;
        default: break;
      }
      return;
    }
    case SDL_KEYDOWN:
    case SDL_KEYUP: {
      GLFWwindow* w = window_of(e.key.windowID);
      if (!w) return;
      const int action = e.type == SDL_KEYUP ? GLFW_RELEASE : e.key.repeat ? GLFW_REPEAT : GLFW_PRESS;
      key_event(*w, key_of(e.key.keysym.sym), int(e.key.keysym.scancode), action, mods_now());
      return;
    }
    case SDL_TEXTINPUT: {
      GLFWwindow* w = window_of(e.text.windowID);
      if (!w) return;
      // UTF-8 to code points.
      const auto* p = reinterpret_cast<const unsigned char*>(e.text.text);
      while (*p) {
        unsigned cp = *p++;
        int extra = cp >= 0xF0 ? 3 : cp >= 0xE0 ? 2 : cp >= 0xC0 ? 1 : 0;
        if (extra) cp &= (0x3Fu >> extra);
        while (extra-- > 0 && (*p & 0xC0) == 0x80) cp = (cp << 6) | (*p++ & 0x3Fu);
        if (w->char_cb) w->char_cb(w, cp);
        if (w->charmods_cb) w->charmods_cb(w, cp, mods_now());
      }
      return;
    }
    case SDL_MOUSEMOTION: {
      GLFWwindow* w = window_of(e.motion.windowID);
      if (!w) return;
      if (w->cursor_mode == GLFW_CURSOR_DISABLED) {
        w->cursor_x += e.motion.xrel;
        w->cursor_y += e.motion.yrel;
      } else {
        w->cursor_x = e.motion.x;
        w->cursor_y = e.motion.y;
      }
      if (w->cursor_cb) w->cursor_cb(w, w->cursor_x, w->cursor_y);
      return;
    }
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP: {
      GLFWwindow* w = window_of(e.button.windowID);
      if (!w) return;
      const int b = e.button.button == SDL_BUTTON_LEFT    ? GLFW_MOUSE_BUTTON_LEFT
                    : e.button.button == SDL_BUTTON_RIGHT ? GLFW_MOUSE_BUTTON_RIGHT
                    : e.button.button == SDL_BUTTON_MIDDLE
                        ? GLFW_MOUSE_BUTTON_MIDDLE
                        : std::min(int(e.button.button) - 1, GLFW_MOUSE_BUTTON_LAST);
      const int action = e.type == SDL_MOUSEBUTTONDOWN ? GLFW_PRESS : GLFW_RELEASE;
      if (action == GLFW_RELEASE && w->sticky_buttons)
        w->buttons[size_t(b)] = 3;
      else
        w->buttons[size_t(b)] = static_cast<signed char>(action);
      if (w->button_cb) w->button_cb(w, b, action, mods_now());
      return;
    }
    case SDL_MOUSEWHEEL: {
      GLFWwindow* w = window_of(e.wheel.windowID);
      if (w && w->scroll_cb) w->scroll_cb(w, double(e.wheel.x), double(e.wheel.y));
      return;
    }
    case SDL_QUIT:
      for (GLFWwindow* w : st().windows) w->should_close = true;
      return;
    case SDL_DROPFILE: {
      GLFWwindow* w = window_of(e.drop.windowID);
      if (w && w->drop_cb && e.drop.file) {
        const char* paths[1] = {e.drop.file};
        w->drop_cb(w, 1, paths);
      }
      if (e.drop.file) SDL_free(e.drop.file);
      return;
    }
    default: return;
  }
}

void pump(double timeout_s) {
  if (!st().sdl) return;
  SDL_Event e;
  if (timeout_s > 0.0) {
    if (SDL_WaitEventTimeout(&e, int(std::min(timeout_s, 1e6) * 1000.0))) dispatch(e);
  } else if (timeout_s < 0.0) {
    if (SDL_WaitEvent(&e)) dispatch(e);
  }
  while (SDL_PollEvent(&e)) dispatch(e);
}
#else
bool open_native(GLFWwindow&) { return false; }
void close_native(GLFWwindow&) {}
void present(GLFWwindow&) {}
void pump(double) {}
#endif

GLFWwindow* checked(GLFWwindow* w) {
  if (!need_init()) return nullptr;
  if (!w) error(GLFW_INVALID_VALUE, "No window was given");
  return w;
}

}  // namespace

extern "C" {

int glfwInit(void) {
  State& s = st();
  if (s.initialized) return GLFW_TRUE;
  s.hints = Hints{};
  s.start = Clock::now();
  s.time_offset = 0.0;
  s.headless_time = 0.0;
  const char* h = std::getenv("TESSEL_HEADLESS");
  if (h && *h && std::strcmp(h, "0") != 0) {
    tessel::gl::parse_headless(s.headless, h, "tessel glfw");
  } else {
#if TESSEL_HAVE_SDL2
    // SIGINT and SIGTERM end the program, as they do a GLFW program (SDL would turn them into
    // quit events that nobody asked for).
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    s.sdl = SDL_Init(SDL_INIT_VIDEO) == 0;
#endif
    if (!s.sdl) tessel::gl::parse_headless(s.headless, "", "tessel glfw");
  }
  s.initialized = true;
  return GLFW_TRUE;
}

void glfwTerminate(void) {
  State& s = st();
  if (!s.initialized) return;
  while (!s.windows.empty()) glfwDestroyWindow(s.windows.back());
#if TESSEL_HAVE_SDL2
  if (s.sdl) SDL_QuitSubSystem(SDL_INIT_VIDEO);
#endif
  s.sdl = false;
  s.headless = {};
  s.initialized = false;
}

void glfwInitHint(int hint, int) {
  if (hint != GLFW_JOYSTICK_HAT_BUTTONS && hint != GLFW_COCOA_CHDIR_RESOURCES && hint != GLFW_COCOA_MENUBAR)
    error(GLFW_INVALID_ENUM, "Invalid init hint 0x%08X", hint);
}

void glfwGetVersion(int* major, int* minor, int* rev) {
  if (major) *major = GLFW_VERSION_MAJOR;
  if (minor) *minor = GLFW_VERSION_MINOR;
  if (rev) *rev = GLFW_VERSION_REVISION;
}

const char* glfwGetVersionString(void) { return "3.3.8 Tessel (SDL2 windows, headless PNG frames)"; }

int glfwGetError(const char** description) {
  State& s = st();
  const int code = s.error_code;
  if (description) *description = code == GLFW_NO_ERROR ? nullptr : s.error_text.c_str();
  s.error_code = GLFW_NO_ERROR;
  return code;
}

GLFWerrorfun glfwSetErrorCallback(GLFWerrorfun callback) {
  GLFWerrorfun old = st().error_cb;
  st().error_cb = callback;
  return old;
}

// --- monitors: one, as a headless server or a single display has -----------------------

GLFWmonitor** glfwGetMonitors(int* count) {
  static GLFWmonitor* list[1];
  if (count) *count = 0;
  if (!need_init()) return nullptr;
  list[0] = &st().monitor;
  if (count) *count = 1;
  return list;
}
GLFWmonitor* glfwGetPrimaryMonitor(void) { return need_init() ? &st().monitor : nullptr; }
void glfwGetMonitorPos(GLFWmonitor*, int* xpos, int* ypos) {
  if (xpos) *xpos = 0;
  if (ypos) *ypos = 0;
}
void glfwGetMonitorWorkarea(GLFWmonitor*, int* xpos, int* ypos, int* width, int* height) {
  if (xpos) *xpos = 0;
  if (ypos) *ypos = 0;
  if (width) *width = kMode.width;
  if (height) *height = kMode.height;
}
void glfwGetMonitorPhysicalSize(GLFWmonitor*, int* widthMM, int* heightMM) {
  // 96 dots per inch.
  if (widthMM) *widthMM = int(kMode.width * 25.4 / 96.0);
  if (heightMM) *heightMM = int(kMode.height * 25.4 / 96.0);
}
void glfwGetMonitorContentScale(GLFWmonitor*, float* xscale, float* yscale) {
  if (xscale) *xscale = 1.0f;
  if (yscale) *yscale = 1.0f;
}
const char* glfwGetMonitorName(GLFWmonitor* monitor) { return monitor ? "Tessel" : nullptr; }
void glfwSetMonitorUserPointer(GLFWmonitor* monitor, void* pointer) {
  if (monitor) monitor->user = pointer;
}
void* glfwGetMonitorUserPointer(GLFWmonitor* monitor) { return monitor ? monitor->user : nullptr; }
GLFWmonitorfun glfwSetMonitorCallback(GLFWmonitorfun callback) {
  GLFWmonitorfun old = st().monitor_cb;
  st().monitor_cb = callback;
  return old;
}
const GLFWvidmode* glfwGetVideoModes(GLFWmonitor* monitor, int* count) {
  if (count) *count = monitor ? 1 : 0;
  return monitor ? &kMode : nullptr;
}
const GLFWvidmode* glfwGetVideoMode(GLFWmonitor* monitor) { return monitor ? &kMode : nullptr; }
void glfwSetGamma(GLFWmonitor*, float gamma) {
  if (!(gamma > 0.0f)) error(GLFW_INVALID_VALUE, "Invalid gamma value %f", double(gamma));
}
const GLFWgammaramp* glfwGetGammaRamp(GLFWmonitor*) {
  error(GLFW_PLATFORM_ERROR, "Gamma ramps are not available");
  return nullptr;
}
void glfwSetGammaRamp(GLFWmonitor*, const GLFWgammaramp*) {
  error(GLFW_PLATFORM_ERROR, "Gamma ramps are not available");
}

// --- windows ---------------------------------------------------------------------------

void glfwDefaultWindowHints(void) {
  if (need_init()) st().hints = Hints{};
}

void glfwWindowHint(int hint, int value) {
  if (!need_init()) return;
  Hints& h = st().hints;
  switch (hint) {
    case GLFW_CLIENT_API: h.client_api = value; break;
    case GLFW_CONTEXT_VERSION_MAJOR: h.major = value; break;
    case GLFW_CONTEXT_VERSION_MINOR: h.minor = value; break;
    case GLFW_OPENGL_PROFILE: h.profile = value; break;
    case GLFW_DEPTH_BITS: h.depth_bits = value; break;
    case GLFW_STENCIL_BITS: h.stencil_bits = value; break;
    case GLFW_ALPHA_BITS: h.alpha_bits = value; break;
    case GLFW_DOUBLEBUFFER: h.double_buffer = value != 0; break;
    case GLFW_RESIZABLE: h.resizable = value != 0; break;
    case GLFW_VISIBLE: h.visible = value != 0; break;
    case GLFW_DECORATED: h.decorated = value != 0; break;
    case GLFW_FOCUSED: h.focused = value != 0; break;
    case GLFW_FLOATING: h.floating = value != 0; break;
    case GLFW_MAXIMIZED: h.maximized = value != 0; break;
    // Accepted; a Tessel context is what it is: 8-bit RGB (alpha as GLFW_ALPHA_BITS asks),
    // no multisampling, no sRGB.
    case GLFW_RED_BITS:
    case GLFW_GREEN_BITS:
    case GLFW_BLUE_BITS:
    case GLFW_ACCUM_RED_BITS:
    case GLFW_ACCUM_GREEN_BITS:
    case GLFW_ACCUM_BLUE_BITS:
    case GLFW_ACCUM_ALPHA_BITS:
    case GLFW_AUX_BUFFERS:
    case GLFW_STEREO:
    case GLFW_SAMPLES:
    case GLFW_SRGB_CAPABLE:
    case GLFW_REFRESH_RATE:
    case GLFW_AUTO_ICONIFY:
    case GLFW_CENTER_CURSOR:
    case GLFW_FOCUS_ON_SHOW:
    case GLFW_TRANSPARENT_FRAMEBUFFER:
    case GLFW_SCALE_TO_MONITOR:
    case GLFW_CONTEXT_CREATION_API:
    case GLFW_CONTEXT_REVISION:
    case GLFW_CONTEXT_ROBUSTNESS:
    case GLFW_CONTEXT_RELEASE_BEHAVIOR:
    case GLFW_CONTEXT_NO_ERROR:
    case GLFW_OPENGL_FORWARD_COMPAT:
    case GLFW_OPENGL_DEBUG_CONTEXT:
    case GLFW_COCOA_RETINA_FRAMEBUFFER:
    case GLFW_COCOA_GRAPHICS_SWITCHING: break;
    default: error(GLFW_INVALID_ENUM, "Invalid window hint 0x%08X", hint); break;
  }
}

void glfwWindowHintString(int hint, const char*) {
  if (!need_init()) return;
  if (hint != GLFW_COCOA_FRAME_NAME && hint != GLFW_X11_CLASS_NAME && hint != GLFW_X11_INSTANCE_NAME)
    error(GLFW_INVALID_ENUM, "Invalid window hint string 0x%08X", hint);
}

GLFWwindow* glfwCreateWindow(int width, int height, const char* title, GLFWmonitor* monitor, GLFWwindow*) {
  if (!need_init()) return nullptr;
  State& s = st();
  const Hints& h = s.hints;
  if (width <= 0 || height <= 0) {
    error(GLFW_INVALID_VALUE, "Invalid window size %ix%i", width, height);
    return nullptr;
  }
  if (h.client_api != GLFW_OPENGL_API && h.client_api != GLFW_NO_API) {
    error(GLFW_API_UNAVAILABLE, "Tessel has OpenGL only (no OpenGL ES)");
    return nullptr;
  }
  if (h.client_api == GLFW_OPENGL_API) {
    if (h.major < 1 || h.minor < 0 || (h.major == 1 && h.minor > 5) || (h.major == 2 && h.minor > 1) ||
        (h.major == 3 && h.minor > 3)) {
      error(GLFW_INVALID_VALUE, "Invalid OpenGL version %i.%i", h.major, h.minor);
      return nullptr;
    }
    if (h.profile != GLFW_OPENGL_ANY_PROFILE && h.profile != GLFW_OPENGL_CORE_PROFILE &&
        h.profile != GLFW_OPENGL_COMPAT_PROFILE) {
      error(GLFW_INVALID_ENUM, "Invalid OpenGL profile 0x%08X", h.profile);
      return nullptr;
    }
  }
  auto w = std::make_unique<GLFWwindow>();
  w->title = title ? title : "";
  w->width = monitor ? kMode.width : width;
  w->height = monitor ? kMode.height : height;
  w->resizable = h.resizable;
  w->visible = h.visible;
  w->decorated = h.decorated;
  w->focused = h.focused;
  w->floating = h.floating;
  if (h.client_api == GLFW_OPENGL_API) {
    w->context = std::make_unique<tessel::gl::Context>(w->width, w->height, h.double_buffer, h.depth_bits > 0,
                                                       h.stencil_bits > 0, h.alpha_bits != 0);
    // A 3.2+ request is a core context unless the compatibility profile is asked for (as GLX
    // gives), and 1.x/2.x requests are the default compatibility context. Tessel's newest
    // is 3.3: a newer request gets it (GL_VERSION says so).
    if (h.major >= 3) {
      const bool core = (h.major > 3 || h.minor >= 2) && h.profile != GLFW_OPENGL_COMPAT_PROFILE;
      const bool newer = h.major > 3 || (h.major == 3 && h.minor > 3);
      w->context->set_version(3, newer ? 3 : h.minor, core);
    }
  }
  if (!s.headless.on && !open_native(*w)) tessel::gl::parse_headless(s.headless, "", "tessel glfw");
  s.windows.push_back(w.get());
  return w.release();
}

void glfwDestroyWindow(GLFWwindow* window) {
  if (!need_init() || !window) return;
  State& s = st();
  if (s.current == window) glfwMakeContextCurrent(nullptr);
  close_native(*window);
  s.windows.erase(std::remove(s.windows.begin(), s.windows.end(), window), s.windows.end());
  delete window;
}

int glfwWindowShouldClose(GLFWwindow* window) { return checked(window) ? window->should_close : GLFW_FALSE; }
void glfwSetWindowShouldClose(GLFWwindow* window, int value) {
  if (checked(window)) window->should_close = value != 0;
}

void glfwSetWindowTitle(GLFWwindow* window, const char* title) {
  if (!checked(window)) return;
  window->title = title ? title : "";
#if TESSEL_HAVE_SDL2
  if (window->sdl) SDL_SetWindowTitle(window->sdl, window->title.c_str());
#endif
}
void glfwSetWindowIcon(GLFWwindow* window, int count, const GLFWimage*) {
  if (checked(window) && count < 0) error(GLFW_INVALID_VALUE, "Invalid image count");
}
void glfwGetWindowPos(GLFWwindow* window, int* xpos, int* ypos) {
  if (xpos) *xpos = checked(window) ? window->x : 0;
  if (ypos) *ypos = window ? window->y : 0;
}
void glfwSetWindowPos(GLFWwindow* window, int xpos, int ypos) {
  if (!checked(window)) return;
  window->x = xpos;
  window->y = ypos;
#if TESSEL_HAVE_SDL2
  if (window->sdl) SDL_SetWindowPosition(window->sdl, xpos, ypos);
#endif
}
void glfwGetWindowSize(GLFWwindow* window, int* width, int* height) {
  const bool ok = checked(window) != nullptr;
  if (width) *width = ok ? window->width : 0;
  if (height) *height = ok ? window->height : 0;
}
void glfwSetWindowSizeLimits(GLFWwindow* window, int, int, int, int) { checked(window); }
void glfwSetWindowAspectRatio(GLFWwindow* window, int, int) { checked(window); }
void glfwSetWindowSize(GLFWwindow* window, int width, int height) {
  if (!checked(window)) return;
  if (width <= 0 || height <= 0) return error(GLFW_INVALID_VALUE, "Invalid window size %ix%i", width, height);
#if TESSEL_HAVE_SDL2
  if (window->sdl) SDL_SetWindowSize(window->sdl, width, height);
#endif
  if (window->width == width && window->height == height) return;
  window->width = width;
  window->height = height;
  if (window->context) window->context->resize(width, height);
  if (window->size_cb) window->size_cb(window, width, height);
  if (window->fbsize_cb) window->fbsize_cb(window, width, height);
}
// The framebuffer has the window's size (no scaling between the two).
void glfwGetFramebufferSize(GLFWwindow* window, int* width, int* height) {
  glfwGetWindowSize(window, width, height);
}
void glfwGetWindowFrameSize(GLFWwindow* window, int* left, int* top, int* right, int* bottom) {
  checked(window);
  for (int* p : {left, top, right, bottom})
    if (p) *p = 0;
}
void glfwGetWindowContentScale(GLFWwindow* window, float* xscale, float* yscale) {
  checked(window);
  if (xscale) *xscale = 1.0f;
  if (yscale) *yscale = 1.0f;
}
float glfwGetWindowOpacity(GLFWwindow* window) { return checked(window) ? window->opacity : 1.0f; }
void glfwSetWindowOpacity(GLFWwindow* window, float opacity) {
  if (!checked(window)) return;
  if (!(opacity >= 0.0f && opacity <= 1.0f)) return error(GLFW_INVALID_VALUE, "Invalid window opacity");
  window->opacity = opacity;
}
void glfwIconifyWindow(GLFWwindow* window) {
  if (checked(window)) window->iconified = true;
}
void glfwRestoreWindow(GLFWwindow* window) {
  if (!checked(window)) return;
  window->iconified = false;
  window->maximized = false;
}
void glfwMaximizeWindow(GLFWwindow* window) {
  if (checked(window)) window->maximized = true;
}
void glfwShowWindow(GLFWwindow* window) {
  if (!checked(window)) return;
  window->visible = true;
#if TESSEL_HAVE_SDL2
  if (window->sdl) SDL_ShowWindow(window->sdl);
#endif
}
void glfwHideWindow(GLFWwindow* window) {
  if (!checked(window)) return;
  window->visible = false;
#if TESSEL_HAVE_SDL2
  if (window->sdl) SDL_HideWindow(window->sdl);
#endif
}
void glfwFocusWindow(GLFWwindow* window) {
  if (checked(window)) window->focused = true;
}
void glfwRequestWindowAttention(GLFWwindow* window) { checked(window); }
GLFWmonitor* glfwGetWindowMonitor(GLFWwindow* window) {
  checked(window);
  return nullptr;
}
void glfwSetWindowMonitor(GLFWwindow* window, GLFWmonitor*, int xpos, int ypos, int width, int height, int) {
  if (!checked(window)) return;
  glfwSetWindowPos(window, xpos, ypos);
  glfwSetWindowSize(window, width, height);
}

int glfwGetWindowAttrib(GLFWwindow* window, int attrib) {
  if (!checked(window)) return 0;
  const GLFWwindow& w = *window;
  const tessel::gl::Context* c = w.context.get();
  switch (attrib) {
    case GLFW_FOCUSED: return w.focused;
    case GLFW_ICONIFIED: return w.iconified;
    case GLFW_MAXIMIZED: return w.maximized;
    case GLFW_HOVERED: return GLFW_FALSE;
    case GLFW_VISIBLE: return w.visible;
    case GLFW_RESIZABLE: return w.resizable;
    case GLFW_DECORATED: return w.decorated;
    case GLFW_FLOATING: return w.floating;
    case GLFW_AUTO_ICONIFY: return GLFW_TRUE;
    case GLFW_FOCUS_ON_SHOW: return GLFW_TRUE;
    case GLFW_TRANSPARENT_FRAMEBUFFER: return GLFW_FALSE;
    case GLFW_CLIENT_API: return c ? GLFW_OPENGL_API : GLFW_NO_API;
    case GLFW_CONTEXT_CREATION_API: return GLFW_NATIVE_CONTEXT_API;
    case GLFW_CONTEXT_VERSION_MAJOR: return c ? c->major_version : 0;
    case GLFW_CONTEXT_VERSION_MINOR: return c ? c->minor_version : 0;
    case GLFW_CONTEXT_REVISION: return 0;
    case GLFW_OPENGL_PROFILE:
      if (!c || c->major_version < 3 || (c->major_version == 3 && c->minor_version < 2))
        return GLFW_OPENGL_ANY_PROFILE;
      return c->core_profile ? GLFW_OPENGL_CORE_PROFILE : GLFW_OPENGL_COMPAT_PROFILE;
    case GLFW_OPENGL_FORWARD_COMPAT:
    case GLFW_OPENGL_DEBUG_CONTEXT:
    case GLFW_CONTEXT_NO_ERROR: return GLFW_FALSE;
    case GLFW_CONTEXT_ROBUSTNESS: return GLFW_NO_ROBUSTNESS;
    case GLFW_CONTEXT_RELEASE_BEHAVIOR: return GLFW_ANY_RELEASE_BEHAVIOR;
    default: error(GLFW_INVALID_ENUM, "Invalid window attribute 0x%08X", attrib); return 0;
  }
}

void glfwSetWindowAttrib(GLFWwindow* window, int attrib, int value) {
  if (!checked(window)) return;
  switch (attrib) {
    case GLFW_RESIZABLE: window->resizable = value != 0; break;
    case GLFW_DECORATED: window->decorated = value != 0; break;
    case GLFW_FLOATING: window->floating = value != 0; break;
    case GLFW_AUTO_ICONIFY:
    case GLFW_FOCUS_ON_SHOW: break;
    default: error(GLFW_INVALID_ENUM, "Invalid window attribute 0x%08X", attrib); break;
  }
}

void glfwSetWindowUserPointer(GLFWwindow* window, void* pointer) {
  if (checked(window)) window->user = pointer;
}
void* glfwGetWindowUserPointer(GLFWwindow* window) { return checked(window) ? window->user : nullptr; }

#define TESSEL_GLFW_CALLBACK(NAME, TYPE, FIELD)  \
  TYPE NAME(GLFWwindow* window, TYPE callback) { \
    if (!checked(window)) return nullptr;        \
    TYPE old = window->FIELD;                    \
    window->FIELD = callback;                    \
    return old;                                  \
  }
TESSEL_GLFW_CALLBACK(glfwSetWindowPosCallback, GLFWwindowposfun, pos_cb)
TESSEL_GLFW_CALLBACK(glfwSetWindowSizeCallback, GLFWwindowsizefun, size_cb)
TESSEL_GLFW_CALLBACK(glfwSetWindowCloseCallback, GLFWwindowclosefun, close_cb)
TESSEL_GLFW_CALLBACK(glfwSetWindowRefreshCallback, GLFWwindowrefreshfun, refresh_cb)
TESSEL_GLFW_CALLBACK(glfwSetWindowFocusCallback, GLFWwindowfocusfun, focus_cb)
TESSEL_GLFW_CALLBACK(glfwSetWindowIconifyCallback, GLFWwindowiconifyfun, iconify_cb)
TESSEL_GLFW_CALLBACK(glfwSetWindowMaximizeCallback, GLFWwindowmaximizefun, maximize_cb)
TESSEL_GLFW_CALLBACK(glfwSetFramebufferSizeCallback, GLFWframebuffersizefun, fbsize_cb)
TESSEL_GLFW_CALLBACK(glfwSetWindowContentScaleCallback, GLFWwindowcontentscalefun, scale_cb)
TESSEL_GLFW_CALLBACK(glfwSetKeyCallback, GLFWkeyfun, key_cb)
TESSEL_GLFW_CALLBACK(glfwSetCharCallback, GLFWcharfun, char_cb)
TESSEL_GLFW_CALLBACK(glfwSetCharModsCallback, GLFWcharmodsfun, charmods_cb)
TESSEL_GLFW_CALLBACK(glfwSetMouseButtonCallback, GLFWmousebuttonfun, button_cb)
TESSEL_GLFW_CALLBACK(glfwSetCursorPosCallback, GLFWcursorposfun, cursor_cb)
TESSEL_GLFW_CALLBACK(glfwSetCursorEnterCallback, GLFWcursorenterfun, enter_cb)
TESSEL_GLFW_CALLBACK(glfwSetScrollCallback, GLFWscrollfun, scroll_cb)
TESSEL_GLFW_CALLBACK(glfwSetDropCallback, GLFWdropfun, drop_cb)
#undef TESSEL_GLFW_CALLBACK

// --- events and input ------------------------------------------------------------------

void glfwPollEvents(void) {
  if (need_init()) pump(0.0);
}
void glfwWaitEvents(void) {
  if (!need_init()) return;
  // Headless there is no event to wait for: the frames are what time advances by.
  if (st().sdl) pump(-1.0);
}
void glfwWaitEventsTimeout(double timeout) {
  if (!need_init()) return;
  if (!(timeout >= 0.0)) return error(GLFW_INVALID_VALUE, "Invalid time %f", timeout);
  if (st().sdl) pump(std::max(timeout, 1e-3));
}
void glfwPostEmptyEvent(void) {
#if TESSEL_HAVE_SDL2
  if (need_init() && st().sdl) {
    SDL_Event e{};
    e.type = SDL_USEREVENT;
    SDL_PushEvent(&e);
  }
#endif
}

int glfwGetInputMode(GLFWwindow* window, int mode) {
  if (!checked(window)) return 0;
  switch (mode) {
    case GLFW_CURSOR: return window->cursor_mode;
    case GLFW_STICKY_KEYS: return window->sticky_keys;
    case GLFW_STICKY_MOUSE_BUTTONS: return window->sticky_buttons;
    case GLFW_LOCK_KEY_MODS: return window->lock_mods;
    case GLFW_RAW_MOUSE_MOTION: return window->raw_motion;
    default: error(GLFW_INVALID_ENUM, "Invalid input mode 0x%08X", mode); return 0;
  }
}

void glfwSetInputMode(GLFWwindow* window, int mode, int value) {
  if (!checked(window)) return;
  switch (mode) {
    case GLFW_CURSOR:
      if (value != GLFW_CURSOR_NORMAL && value != GLFW_CURSOR_HIDDEN && value != GLFW_CURSOR_DISABLED)
        return error(GLFW_INVALID_ENUM, "Invalid cursor mode 0x%08X", value);
      window->cursor_mode = value;
#if TESSEL_HAVE_SDL2
      if (window->sdl) {
        SDL_ShowCursor(value == GLFW_CURSOR_NORMAL ? SDL_ENABLE : SDL_DISABLE);
        SDL_SetRelativeMouseMode(value == GLFW_CURSOR_DISABLED ? SDL_TRUE : SDL_FALSE);
      }
#endif
      break;
    case GLFW_STICKY_KEYS:
      window->sticky_keys = value != 0;
      if (!value)
        for (auto& k : window->keys)
          if (k == 3) k = GLFW_RELEASE;
      break;
    case GLFW_STICKY_MOUSE_BUTTONS:
      window->sticky_buttons = value != 0;
      if (!value)
        for (auto& b : window->buttons)
          if (b == 3) b = GLFW_RELEASE;
      break;
    case GLFW_LOCK_KEY_MODS: window->lock_mods = value != 0; break;
    case GLFW_RAW_MOUSE_MOTION: window->raw_motion = value != 0; break;
    default: error(GLFW_INVALID_ENUM, "Invalid input mode 0x%08X", mode); break;
  }
}

int glfwRawMouseMotionSupported(void) { return GLFW_FALSE; }

const char* glfwGetKeyName(int key, int) {
  static char name[2];
  if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) {
    name[0] = char('a' + (key - GLFW_KEY_A));
    return name;
  }
  if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) {
    name[0] = char('0' + (key - GLFW_KEY_0));
    return name;
  }
  return nullptr;
}
int glfwGetKeyScancode(int key) { return key >= 0 && key <= GLFW_KEY_LAST ? key : -1; }

int glfwGetKey(GLFWwindow* window, int key) {
  if (!checked(window)) return GLFW_RELEASE;
  if (key < GLFW_KEY_SPACE || key > GLFW_KEY_LAST) {
    error(GLFW_INVALID_ENUM, "Invalid key %i", key);
    return GLFW_RELEASE;
  }
  signed char& k = window->keys[size_t(key)];
  if (k == 3) {  // a sticky press, reported once
    k = GLFW_RELEASE;
    return GLFW_PRESS;
  }
  return k;
}

int glfwGetMouseButton(GLFWwindow* window, int button) {
  if (!checked(window)) return GLFW_RELEASE;
  if (button < 0 || button > GLFW_MOUSE_BUTTON_LAST) {
    error(GLFW_INVALID_ENUM, "Invalid mouse button %i", button);
    return GLFW_RELEASE;
  }
  signed char& b = window->buttons[size_t(button)];
  if (b == 3) {
    b = GLFW_RELEASE;
    return GLFW_PRESS;
  }
  return b;
}

void glfwGetCursorPos(GLFWwindow* window, double* xpos, double* ypos) {
  const bool ok = checked(window) != nullptr;
  if (xpos) *xpos = ok ? window->cursor_x : 0.0;
  if (ypos) *ypos = ok ? window->cursor_y : 0.0;
}
void glfwSetCursorPos(GLFWwindow* window, double xpos, double ypos) {
  if (!checked(window)) return;
  window->cursor_x = xpos;
  window->cursor_y = ypos;
#if TESSEL_HAVE_SDL2
  if (window->sdl && window->cursor_mode != GLFW_CURSOR_DISABLED)
    SDL_WarpMouseInWindow(window->sdl, int(xpos), int(ypos));
#endif
}

GLFWcursor* glfwCreateCursor(const GLFWimage* image, int, int) {
  if (!need_init()) return nullptr;
  if (!image || image->width <= 0 || image->height <= 0) {
    error(GLFW_INVALID_VALUE, "Invalid image dimensions for cursor");
    return nullptr;
  }
  return new GLFWcursor{0};
}
GLFWcursor* glfwCreateStandardCursor(int shape) {
  if (!need_init()) return nullptr;
  if (shape < GLFW_ARROW_CURSOR || shape > GLFW_VRESIZE_CURSOR) {
    error(GLFW_INVALID_ENUM, "Invalid standard cursor 0x%08X", shape);
    return nullptr;
  }
  return new GLFWcursor{shape};
}
void glfwDestroyCursor(GLFWcursor* cursor) { delete cursor; }
void glfwSetCursor(GLFWwindow* window, GLFWcursor*) { checked(window); }

// --- joysticks: none is attached -------------------------------------------------------

static bool valid_jid(int jid) {
  if (jid >= GLFW_JOYSTICK_1 && jid <= GLFW_JOYSTICK_LAST) return true;
  error(GLFW_INVALID_ENUM, "Invalid joystick ID %i", jid);
  return false;
}
int glfwJoystickPresent(int jid) {
  valid_jid(jid);
  return GLFW_FALSE;
}
const float* glfwGetJoystickAxes(int jid, int* count) {
  valid_jid(jid);
  if (count) *count = 0;
  return nullptr;
}
const unsigned char* glfwGetJoystickButtons(int jid, int* count) {
  valid_jid(jid);
  if (count) *count = 0;
  return nullptr;
}
const unsigned char* glfwGetJoystickHats(int jid, int* count) {
  valid_jid(jid);
  if (count) *count = 0;
  return nullptr;
}
const char* glfwGetJoystickName(int jid) {
  valid_jid(jid);
  return nullptr;
}
const char* glfwGetJoystickGUID(int jid) {
  valid_jid(jid);
  return nullptr;
}
void glfwSetJoystickUserPointer(int jid, void* pointer) {
  if (valid_jid(jid)) st().joystick_user[size_t(jid)] = pointer;
}
void* glfwGetJoystickUserPointer(int jid) {
  return valid_jid(jid) ? st().joystick_user[size_t(jid)] : nullptr;
}
int glfwJoystickIsGamepad(int jid) {
  valid_jid(jid);
  return GLFW_FALSE;
}
GLFWjoystickfun glfwSetJoystickCallback(GLFWjoystickfun callback) {
  GLFWjoystickfun old = st().joystick_cb;
  st().joystick_cb = callback;
  return old;
}
int glfwUpdateGamepadMappings(const char* string) { return string ? GLFW_TRUE : GLFW_FALSE; }
const char* glfwGetGamepadName(int jid) {
  valid_jid(jid);
  return nullptr;
}
int glfwGetGamepadState(int jid, GLFWgamepadstate* state) {
  valid_jid(jid);
  if (state) *state = GLFWgamepadstate{};
  return GLFW_FALSE;
}

// --- clipboard and time ----------------------------------------------------------------

void glfwSetClipboardString(GLFWwindow*, const char* string) {
  if (need_init()) st().clipboard = string ? string : "";
}
const char* glfwGetClipboardString(GLFWwindow*) { return need_init() ? st().clipboard.c_str() : nullptr; }

double glfwGetTime(void) {
  if (!need_init()) return 0.0;
  const State& s = st();
  const double t =
      s.headless.on ? s.headless_time : std::chrono::duration<double>(Clock::now() - s.start).count();
  return t + s.time_offset;
}
void glfwSetTime(double time) {
  if (!need_init()) return;
  if (!(time >= 0.0 && time <= 18446744073.0)) return error(GLFW_INVALID_VALUE, "Invalid time %f", time);
  st().time_offset = time - (glfwGetTime() - st().time_offset);
}
uint64_t glfwGetTimerValue(void) { return uint64_t(glfwGetTime() * 1e9); }
uint64_t glfwGetTimerFrequency(void) { return 1000000000u; }

// --- contexts --------------------------------------------------------------------------

void glfwMakeContextCurrent(GLFWwindow* window) {
  if (!need_init()) return;
  if (window && !window->context)
    return error(GLFW_NO_WINDOW_CONTEXT, "Cannot make current with a window that has no OpenGL context");
  st().current = window;
  tessel::gl::make_current(window ? window->context.get() : nullptr);
}
GLFWwindow* glfwGetCurrentContext(void) { return need_init() ? st().current : nullptr; }

void glfwSwapBuffers(GLFWwindow* window) {
  if (!checked(window)) return;
  if (!window->context)
    return error(GLFW_NO_WINDOW_CONTEXT, "Cannot swap buffers of a window that has no OpenGL context");
  State& s = st();
  window->context->swap_buffers();
  if (!s.headless.on) {
    present(*window);
    return;
  }
  const int index = int(std::find(s.windows.begin(), s.windows.end(), window) - s.windows.begin()) + 1;
  if (window->frame < s.headless.frames) {
    const std::string problem =
        tessel::gl::write_headless_frame(*window->context, s.headless.out, window->frame, index);
    if (!problem.empty()) error(GLFW_PLATFORM_ERROR, "%s", problem.c_str());
  }
  ++window->frame;
  s.headless_time = window->frame / 60.0;
  // The frames asked for are written: the program is asked to end, as a user closing the
  // window would (its close callback runs).
  if (window->frame >= s.headless.frames && !window->should_close) {
    window->should_close = true;
    if (window->close_cb) window->close_cb(window);
  }
}

void glfwSwapInterval(int) {
  if (need_init() && !st().current)
    error(GLFW_NO_CURRENT_CONTEXT, "Cannot set swap interval without a current OpenGL context");
}

int glfwExtensionSupported(const char* extension) {
  if (!need_init()) return GLFW_FALSE;
  if (!st().current) {
    error(GLFW_NO_CURRENT_CONTEXT, "Cannot query extension without a current OpenGL context");
    return GLFW_FALSE;
  }
  if (!extension || !*extension) {
    error(GLFW_INVALID_VALUE, "Extension name cannot be an empty string");
    return GLFW_FALSE;
  }
  for (const char* e : tessel::gl::extensions(*st().current->context))
    if (std::strcmp(e, extension) == 0) return GLFW_TRUE;
  return GLFW_FALSE;
}

GLFWglproc glfwGetProcAddress(const char* procname) {
  if (!need_init()) return nullptr;
  if (!st().current) {
    error(GLFW_NO_CURRENT_CONTEXT, "Cannot query entry point without a current OpenGL context");
    return nullptr;
  }
  return tessel::gl::proc_address(procname);
}

int glfwVulkanSupported(void) { return GLFW_FALSE; }

}  // extern "C"
