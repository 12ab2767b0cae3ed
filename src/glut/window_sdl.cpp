// GLUT windows over SDL2: an SDL window shows the GL context's front buffer (copied into a
// streaming texture, rows flipped, pop-up menus drawn on top); SDL events become GLUT
// callbacks. Built only when SDL2 is found; otherwise every window is headless.
#include "glut_internal.hpp"

#include <cstdlib>
#include <cstring>

#if TESSEL_HAVE_SDL2
#include <SDL2/SDL.h>
#endif

namespace tessel::glut {

#if TESSEL_HAVE_SDL2

struct NativeWindow {
  SDL_Window* window = nullptr;
  SDL_Renderer* renderer = nullptr;
  SDL_Texture* texture = nullptr;
  int tex_w = 0, tex_h = 0;
  std::vector<uint8_t> staging;
  int buttons_down = 0;
};

namespace {
bool g_sdl_ready = false;
bool g_sdl_failed = false;

bool init_sdl() {
  if (g_sdl_ready) return true;
  if (g_sdl_failed) return false;
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    g_sdl_failed = true;
    return false;
  }
  g_sdl_ready = true;
  return true;
}

Window* window_of(Uint32 sdl_id) {
  for (auto& w : state().windows)
    if (w && w->native && SDL_GetWindowID(w->native->window) == sdl_id) return w.get();
  return nullptr;
}

int modifiers_now() {
  const SDL_Keymod m = SDL_GetModState();
  int r = 0;
  if (m & KMOD_SHIFT) r |= GLUT_ACTIVE_SHIFT;
  if (m & KMOD_CTRL) r |= GLUT_ACTIVE_CTRL;
  if (m & KMOD_ALT) r |= GLUT_ACTIVE_ALT;
  return r;
}

int special_key(SDL_Keycode k) {
  switch (k) {
    case SDLK_F1: return GLUT_KEY_F1;
    case SDLK_F2: return GLUT_KEY_F2;
    case SDLK_F3: return GLUT_KEY_F3;
    case SDLK_F4: return GLUT_KEY_F4;
    case SDLK_F5: return GLUT_KEY_F5;
    case SDLK_F6: return GLUT_KEY_F6;
    case SDLK_F7: return GLUT_KEY_F7;
    case SDLK_F8: return GLUT_KEY_F8;
    case SDLK_F9: return GLUT_KEY_F9;
    case SDLK_F10: return GLUT_KEY_F10;
    case SDLK_F11: return GLUT_KEY_F11;
    case SDLK_F12: return GLUT_KEY_F12;
    case SDLK_LEFT: return GLUT_KEY_LEFT;
    case SDLK_UP: return GLUT_KEY_UP;
    case SDLK_RIGHT: return GLUT_KEY_RIGHT;
    case SDLK_DOWN: return GLUT_KEY_DOWN;
    case SDLK_PAGEUP: return GLUT_KEY_PAGE_UP;
    case SDLK_PAGEDOWN: return GLUT_KEY_PAGE_DOWN;
    case SDLK_HOME: return GLUT_KEY_HOME;
    case SDLK_END: return GLUT_KEY_END;
    case SDLK_INSERT: return GLUT_KEY_INSERT;
    default: return 0;
  }
}

// The ASCII a GLUT keyboard callback receives for a key press, or 0 for keys that arrive as
// text input instead (printable characters without Ctrl).
unsigned char control_key(const SDL_Keysym& k) {
  switch (k.sym) {
    case SDLK_ESCAPE: return 27;
    case SDLK_RETURN:
    case SDLK_KP_ENTER: return 13;
    case SDLK_BACKSPACE: return 8;
    case SDLK_TAB: return 9;
    case SDLK_DELETE: return 127;
    default: break;
  }
  if ((k.mod & KMOD_CTRL) && k.sym >= SDLK_a && k.sym <= SDLK_z) return (unsigned char)(k.sym - SDLK_a + 1);
  return 0;
}

void mouse_xy(Window& w, int x, int y, int& gx, int& gy) {
  int ww = 0, wh = 0;
  SDL_GetWindowSize(w.native->window, &ww, &wh);
  gx = ww > 0 ? x * w.width / ww : x;
  gy = wh > 0 ? y * w.height / wh : y;
}

// The window under `top` (or top) whose pop-up menus are open, and where its top-left corner
// is in top's pixels (added to ox, oy); null when no menu is open (one window at a time has).
Window* menu_window(Window& top, int& ox, int& oy) {
  if (!top.open_menus.empty()) return &top;
  for (int id : top.children) {
    Window* c = window(id);
    if (!c || !c->visible) continue;
    int cx = c->x, cy = c->y;
    if (Window* m = menu_window(*c, cx, cy)) {
      ox += cx;
      oy += cy;
      return m;
    }
  }
  return nullptr;
}

// The window an input event at native pixel (x, y) of top-level `top` belongs to, and the
// point in its coordinates: the window with open menus while they are open (the menus take
// the input), else the subwindow under the point.
Window& target(Window& top, int nx, int ny, int& x, int& y) {
  mouse_xy(top, nx, ny, x, y);
  int ox = 0, oy = 0;
  if (Window* m = menu_window(top, ox, oy)) {
    x -= ox;
    y -= oy;
    return *m;
  }
  return window_at(top, x, y);
}

// Entry callbacks as the pointer moves between a top-level window and its subwindows.
int g_pointer_window = 0;
void pointer_over(Window& w) {
  if (g_pointer_window == w.id) return;
  Window* old = window(g_pointer_window);
  g_pointer_window = w.id;
  if (old && old->entry && (old->parent || w.parent)) {
    make_current(*old);
    old->entry(GLUT_LEFT);
  }
  if (w.entry && (old && (old->parent || w.parent))) {
    make_current(w);
    w.entry(GLUT_ENTERED);
  }
}

void dispatch(const SDL_Event& e) {
  State& s = state();
  switch (e.type) {
    case SDL_QUIT:
      for (auto& w : s.windows)
        if (w && w->close) {
          make_current(*w);
          w->close();
        }
      s.leave = true;  // glutMainLoop returns; the program ends when main does
      return;
    case SDL_WINDOWEVENT: {
      Window* w = window_of(e.window.windowID);
      if (!w) return;
      switch (e.window.event) {
        case SDL_WINDOWEVENT_SIZE_CHANGED:
          if (e.window.data1 > 0 && e.window.data2 > 0 &&
              (e.window.data1 != w->width || e.window.data2 != w->height)) {
            w->width = e.window.data1;
            w->height = e.window.data2;
            w->context->resize(w->width, w->height);
            w->reshape_pending = true;
            w->redisplay = true;
          }
          break;
        case SDL_WINDOWEVENT_EXPOSED: w->redisplay = true; break;
        case SDL_WINDOWEVENT_ENTER:
        case SDL_WINDOWEVENT_LEAVE:
          if (w->entry) {
            make_current(*w);
            w->entry(e.window.event == SDL_WINDOWEVENT_ENTER ? GLUT_ENTERED : GLUT_LEFT);
          }
          break;
        case SDL_WINDOWEVENT_CLOSE:
          if (w->close) {
            make_current(*w);
            w->close();
          }
          s.leave = true;
          break;
        default: break;
      }
      return;
    }
    case SDL_TEXTINPUT: {
      Window* top = window_of(e.text.windowID);
      if (!top) return;
      int x = 0, y = 0;
      SDL_GetMouseState(&x, &y);
      Window* w = &target(*top, x, y, x, y);
      if (!w->keyboard) return;
      const unsigned char ch = (unsigned char)e.text.text[0];
      if (ch < 32 || ch >= 128 || e.text.text[1] != '\0') return;  // ASCII only, as GLUT
      s.modifiers = modifiers_now();
      make_current(*w);
      w->keyboard(ch, x, y);
      s.modifiers = 0;
      return;
    }
    case SDL_KEYDOWN:
    case SDL_KEYUP: {
      Window* top = window_of(e.key.windowID);
      if (!top) return;
      const bool down = e.type == SDL_KEYDOWN;
      if (down && e.key.repeat && s.ignore_key_repeat) return;
      int x = 0, y = 0;
      SDL_GetMouseState(&x, &y);
      Window* w = &target(*top, x, y, x, y);
      s.modifiers = modifiers_now();
      make_current(*w);
      if (const int sp = special_key(e.key.keysym.sym)) {
        if (down && w->special) w->special(sp, x, y);
        if (!down && w->special_up) w->special_up(sp, x, y);
      } else if (const unsigned char ch = control_key(e.key.keysym)) {
        if (down && w->keyboard) w->keyboard(ch, x, y);
        if (!down && w->keyboard_up) w->keyboard_up(ch, x, y);
      } else if (!down && w->keyboard_up && e.key.keysym.sym >= 32 && e.key.keysym.sym < 127) {
        unsigned char ch = (unsigned char)e.key.keysym.sym;
        if ((e.key.keysym.mod & KMOD_SHIFT) && ch >= 'a' && ch <= 'z') ch = (unsigned char)(ch - 'a' + 'A');
        w->keyboard_up(ch, x, y);
      }
      s.modifiers = 0;
      return;
    }
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP: {
      Window* top = window_of(e.button.windowID);
      if (!top) return;
      int button = -1;
      switch (e.button.button) {
        case SDL_BUTTON_LEFT: button = GLUT_LEFT_BUTTON; break;
        case SDL_BUTTON_MIDDLE: button = GLUT_MIDDLE_BUTTON; break;
        case SDL_BUTTON_RIGHT: button = GLUT_RIGHT_BUTTON; break;
        default: return;
      }
      int x = 0, y = 0;
      Window* w = &target(*top, e.button.x, e.button.y, x, y);
      const bool down = e.type == SDL_MOUSEBUTTONDOWN;
      if (!w->open_menus.empty()) {
        if (!down && button == w->menu_button) menu_release(*w, x, y);
        if (window(top->id)) native_present(*top);
        return;
      }
      if (down && w->menu_for_button[button] && menu(w->menu_for_button[button])) {
        menu_open(*w, w->menu_for_button[button], button, x, y);
        native_present(*top);
        return;
      }
      if (down)
        top->native->buttons_down |= 1 << button;
      else
        top->native->buttons_down &= ~(1 << button);
      if (w->mouse) {
        s.modifiers = modifiers_now();
        make_current(*w);
        w->mouse(button, down ? GLUT_DOWN : GLUT_UP, x, y);
        s.modifiers = 0;
        if (window(w->id) && window(top->id) && !(w->mode & GLUT_DOUBLE)) native_present(*top);
      }
      return;
    }
    case SDL_MOUSEWHEEL: {
      Window* top = window_of(e.wheel.windowID);
      if (!top || e.wheel.y == 0) return;
      int x = 0, y = 0;
      SDL_GetMouseState(&x, &y);
      Window* w = &target(*top, x, y, x, y);
      make_current(*w);
      const int dir = e.wheel.y > 0 ? 1 : -1;
      if (w->mouse_wheel)
        w->mouse_wheel(0, dir, x, y);
      else if (w->mouse) {
        // freeglut reports the wheel as buttons 3 (up) and 4 (down) without a wheel callback.
        w->mouse(dir > 0 ? 3 : 4, GLUT_DOWN, x, y);
        w->mouse(dir > 0 ? 3 : 4, GLUT_UP, x, y);
      }
      return;
    }
    case SDL_MOUSEMOTION: {
      Window* top = window_of(e.motion.windowID);
      if (!top) return;
      int x = 0, y = 0;
      Window* w = &target(*top, e.motion.x, e.motion.y, x, y);
      if (!w->open_menus.empty()) {
        menu_motion(*w, x, y);
        native_present(*top);
        return;
      }
      const int id = w->id;
      pointer_over(*w);
      if (!window(id) || !window(top->id)) return;
      make_current(*w);
      if (top->native->buttons_down) {
        if (w->motion) w->motion(x, y);
      } else if (w->passive_motion) {
        w->passive_motion(x, y);
      }
      if (window(id) && window(top->id) && !(w->mode & GLUT_DOUBLE)) native_present(*top);
      return;
    }
    default: return;
  }
}
}  // namespace

bool native_available() {
  const char* d = std::getenv("DISPLAY");
  const char* wl = std::getenv("WAYLAND_DISPLAY");
  return (d && *d) || (wl && *wl);
}

bool native_open(Window& w) {
  if (!native_available() || !init_sdl()) return false;
  auto n = std::make_unique<NativeWindow>();
  const int x = state().init_x >= 0 ? state().init_x : int(SDL_WINDOWPOS_UNDEFINED);
  const int y = state().init_y >= 0 ? state().init_y : int(SDL_WINDOWPOS_UNDEFINED);
  n->window =
      SDL_CreateWindow(w.title.c_str(), x, y, w.width, w.height, SDL_WINDOW_RESIZABLE | SDL_WINDOW_SHOWN);
  if (!n->window) return false;
  n->renderer = SDL_CreateRenderer(n->window, -1, SDL_RENDERER_SOFTWARE);
  if (!n->renderer) {
    SDL_DestroyWindow(n->window);
    return false;
  }
  SDL_StartTextInput();
  w.native = std::move(n);
  return true;
}

void native_close(Window& w) {
  NativeWindow* n = w.native.get();
  if (!n) return;
  if (n->texture) SDL_DestroyTexture(n->texture);
  if (n->renderer) SDL_DestroyRenderer(n->renderer);
  if (n->window) SDL_DestroyWindow(n->window);
  w.native.reset();
}

void native_present(Window& w) {
  NativeWindow* n = w.native.get();
  if (!n) return;
  // A single-buffered window shows its only buffer; a double-buffered one the front.
  const gpu::Texture2D& front = w.context->front();
  const int width = front.width(), height = front.height();
  if (!n->texture || n->tex_w != width || n->tex_h != height) {
    if (n->texture) SDL_DestroyTexture(n->texture);
    n->texture =
        SDL_CreateTexture(n->renderer, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STREAMING, width, height);
    n->tex_w = width;
    n->tex_h = height;
    if (!n->texture) return;
  }
  const size_t row = size_t(width) * 4;
  visible_image(w, n->staging);  // its subwindows over it
  // Open pop-up menus, this window's or a subwindow's at its place.
  int ox = 0, oy = 0;
  if (Window* m = menu_window(w, ox, oy)) menu_draw(*m, n->staging, width, height, ox, oy);
  SDL_UpdateTexture(n->texture, nullptr, n->staging.data(), int(row));
  SDL_RenderClear(n->renderer);
  SDL_RenderCopy(n->renderer, n->texture, nullptr, nullptr);
  SDL_RenderPresent(n->renderer);
}

void native_set_title(Window& w) {
  if (w.native) SDL_SetWindowTitle(w.native->window, w.title.c_str());
}
void native_resize(Window& w, int width, int height) {
  if (w.native) SDL_SetWindowSize(w.native->window, width, height);
}
void native_fullscreen(Window& w, bool on) {
  if (w.native) SDL_SetWindowFullscreen(w.native->window, on ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0);
}

void native_pump(double timeout_ms) {
  if (!g_sdl_ready) return;
  SDL_Event e;
  if (timeout_ms > 0.0) {
    if (SDL_WaitEventTimeout(&e, int(timeout_ms + 0.5)))
      dispatch(e);
    else
      return;
  }
  while (SDL_PollEvent(&e)) dispatch(e);
}

#else  // no SDL2: every window is headless

struct NativeWindow {};
bool native_available() { return false; }
bool native_open(Window&) { return false; }
void native_close(Window& w) { w.native.reset(); }
void native_present(Window&) {}
void native_set_title(Window&) {}
void native_resize(Window&, int, int) {}
void native_fullscreen(Window&, bool) {}
void native_pump(double) {}

#endif

Window::Window() = default;
Window::~Window() {
  if (native) native_close(*this);
}

}  // namespace tessel::glut
