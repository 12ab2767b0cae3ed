// GLUT pop-up menus, drawn by Tessel over the window's image (not into the GL buffers, so a
// program's pixels are never touched) with the 9x15 bitmap font, and driven by the mouse:
// pressing the attached button opens the menu at the pointer, moving highlights entries (and
// opens submenus), releasing over an entry calls the menu's callback with its value.
#include <algorithm>

#include "fonts.hpp"
#include "glut_internal.hpp"

namespace tessel::glut {

namespace {

constexpr int kItemHeight = 19, kPadX = 8, kCharW = 9, kArrowW = 14;

int menu_width(const Menu& m) {
  size_t longest = 4;
  bool sub = false;
  for (const MenuItem& it : m.items) {
    longest = std::max(longest, it.label.size());
    sub |= it.submenu;
  }
  return int(longest) * kCharW + 2 * kPadX + (sub ? kArrowW : 0);
}

int menu_height(const Menu& m) { return std::max(1, int(m.items.size())) * kItemHeight + 2; }

// Which entry of an open menu is under (x, y), -1 if none.
int item_at(const OpenMenu& om, int x, int y) {
  const Menu* m = menu(om.menu);
  if (!m) return -1;
  if (x < om.x || x >= om.x + menu_width(*m) || y < om.y + 1 ||
      y >= om.y + 1 + int(m->items.size()) * kItemHeight)
    return -1;
  return (y - om.y - 1) / kItemHeight;
}

void fill(std::vector<uint8_t>& px, int width, int height, int x0, int y0, int x1, int y1, uint8_t r,
          uint8_t g, uint8_t b) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, width), y1 = std::min(y1, height);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      uint8_t* p = &px[(size_t(y) * size_t(width) + size_t(x)) * 4];
      p[0] = r, p[1] = g, p[2] = b, p[3] = 255;
    }
}

// Text with the 9x15 font; (x, baseline) in image pixels, y down.
void text(std::vector<uint8_t>& px, int width, int height, int x, int baseline, const std::string& s,
          uint8_t r, uint8_t g, uint8_t b) {
  for (unsigned char ch : s) {
    BitmapGlyphView gl;
    if (!bitmap_glyph(GLUT_BITMAP_9_BY_15, ch, gl)) {
      x += kCharW;
      continue;
    }
    const int bytes_per_row = (gl.width + 7) / 8;
    for (int row = 0; row < gl.height; ++row) {
      // Glyph rows are bottom-up; row 0 sits yorig pixels below the baseline.
      const int py = baseline + int(gl.yorig) - row - 1;
      for (int col = 0; col < gl.width; ++col) {
        const uint8_t byte = gl.bits[size_t(row * bytes_per_row + col / 8)];
        if (!((byte >> (7 - col % 8)) & 1)) continue;
        const int pxx = x - int(gl.xorig) + col;
        if (pxx < 0 || py < 0 || pxx >= width || py >= height) continue;
        uint8_t* p = &px[(size_t(py) * size_t(width) + size_t(pxx)) * 4];
        p[0] = r, p[1] = g, p[2] = b;
      }
    }
    x += int(gl.advance);
  }
}

}  // namespace

void menu_draw(const Window& w, std::vector<uint8_t>& px, int width, int height, int ox, int oy) {
  for (OpenMenu om : w.open_menus) {
    om.x += ox;
    om.y += oy;
    const Menu* m = menu(om.menu);
    if (!m) continue;
    const int mw = menu_width(*m), mh = menu_height(*m);
    fill(px, width, height, om.x + 2, om.y + 2, om.x + mw + 2, om.y + mh + 2, 60, 60, 60);  // shadow
    fill(px, width, height, om.x, om.y, om.x + mw, om.y + mh, 90, 90, 90);                  // border
    fill(px, width, height, om.x + 1, om.y + 1, om.x + mw - 1, om.y + mh - 1, 226, 226, 222);
    for (size_t i = 0; i < m->items.size(); ++i) {
      const int top = om.y + 1 + int(i) * kItemHeight;
      const bool hot = int(i) == om.highlighted;
      if (hot) fill(px, width, height, om.x + 1, top, om.x + mw - 1, top + kItemHeight, 51, 102, 204);
      const uint8_t c = hot ? 255 : 20;
      text(px, width, height, om.x + kPadX, top + 14, m->items[i].label, c, c, c);
      if (m->items[i].submenu) text(px, width, height, om.x + mw - kArrowW, top + 14, ">", c, c, c);
    }
  }
}

void menu_open(Window& w, int menu_id, int button, int x, int y) {
  const Menu* m = menu(menu_id);
  if (!m) return;
  // Keep the menu inside the window where it fits.
  const int mw = menu_width(*m), mh = menu_height(*m);
  const int ox = std::max(0, std::min(x, w.width - mw)), oy = std::max(0, std::min(y, w.height - mh));
  w.open_menus.assign(1, OpenMenu{menu_id, ox, oy, -1});
  w.menu_button = button;
  State& s = state();
  if (s.menu_state) s.menu_state(GLUT_MENU_IN_USE);
  if (s.menu_status) s.menu_status(GLUT_MENU_IN_USE, x, y);
}

void menu_motion(Window& w, int x, int y) {
  // The deepest open menu under the pointer keeps its chain; deeper ones close.
  for (size_t level = w.open_menus.size(); level-- > 0;) {
    OpenMenu& om = w.open_menus[level];
    const int item = item_at(om, x, y);
    if (item < 0) {
      if (level == 0) om.highlighted = -1;
      continue;
    }
    om.highlighted = item;
    w.open_menus.resize(level + 1);
    const Menu* m = menu(om.menu);
    if (m && m->items[size_t(item)].submenu && menu(m->items[size_t(item)].value)) {
      const int sx = om.x + menu_width(*m) - 2, sy = om.y + item * kItemHeight;
      w.open_menus.push_back(OpenMenu{m->items[size_t(item)].value, sx, sy, -1});
    }
    return;
  }
}

void menu_release(Window& w, int x, int y) {
  int chosen_menu = 0, value = 0;
  bool chosen = false;
  for (size_t level = w.open_menus.size(); level-- > 0 && !chosen;) {
    const OpenMenu& om = w.open_menus[level];
    const int item = item_at(om, x, y);
    const Menu* m = menu(om.menu);
    if (item >= 0 && m && !m->items[size_t(item)].submenu) {
      chosen = true;
      chosen_menu = om.menu;
      value = m->items[size_t(item)].value;
    }
  }
  w.open_menus.clear();
  w.menu_button = -1;
  State& s = state();
  if (s.menu_state) s.menu_state(GLUT_MENU_NOT_IN_USE);
  if (s.menu_status) s.menu_status(GLUT_MENU_NOT_IN_USE, x, y);
  if (!chosen) return;
  const Menu* m = menu(chosen_menu);
  if (!m || !m->callback) return;
  const int previous = s.current_menu;
  s.current_menu = chosen_menu;  // glutGetMenu inside the callback names the menu
  make_current(w);
  m->callback(value);
  if (menu(previous)) s.current_menu = previous;
  w.redisplay = true;
}

}  // namespace tessel::glut
