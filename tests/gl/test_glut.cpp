// GLUT without a display: pop-up menus (opened, walked with the pointer, chosen, drawn),
// timers and idle in the headless clock, and the window queries.
#include <GL/glut.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include "../../src/glut/glut_internal.hpp"

namespace {

using tessel::glut::state;

int g_chosen = 0, g_chosen_menu = 0;
void on_menu(int value) {
  g_chosen = value;
  g_chosen_menu = glutGetMenu();
}
std::vector<int> g_fired;
void on_timer(int value) { g_fired.push_back(value); }
int g_idle = 0;
void on_idle() { ++g_idle; }
void on_display() {
  glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

// One GLUT for the whole test binary (glutInit runs once per process).
tessel::glut::Window& window() {
  static int id = [] {
    setenv("TESSEL_HEADLESS", "frames:1,out:.", 1);
    int argc = 1;
    char name[] = "test_glut";
    char* argv[] = {name, nullptr};
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE);
    glutInitWindowSize(200, 150);
    const int w = glutCreateWindow("test");
    glutDisplayFunc(on_display);
    return w;
  }();
  return *tessel::glut::window(id);
}

// Item i of a menu opened at (x, y) is at y + 1 + 19 i .. (see menu.cpp).
int item_y(int y, int i) { return y + 1 + 19 * i + 9; }

TEST(GlutMenu, ChooseAnEntry) {
  tessel::glut::Window& w = window();
  const int m = glutCreateMenu(on_menu);
  glutAddMenuEntry("Clear", 1);
  glutAddMenuEntry("Quit", 2);
  glutAttachMenu(GLUT_RIGHT_BUTTON);
  EXPECT_EQ(w.menu_for_button[GLUT_RIGHT_BUTTON], m);
  EXPECT_EQ(glutGet(GLUT_MENU_NUM_ITEMS), 2);
  g_chosen = 0;
  tessel::glut::menu_open(w, m, GLUT_RIGHT_BUTTON, 20, 10);
  ASSERT_EQ(w.open_menus.size(), 1u);
  tessel::glut::menu_motion(w, 30, item_y(10, 1));
  EXPECT_EQ(w.open_menus[0].highlighted, 1);
  tessel::glut::menu_release(w, 30, item_y(10, 1));
  EXPECT_EQ(g_chosen, 2);
  EXPECT_EQ(g_chosen_menu, m);  // glutGetMenu inside the callback names the menu
  EXPECT_TRUE(w.open_menus.empty());
  // Released outside every entry: nothing is chosen.
  g_chosen = 0;
  tessel::glut::menu_open(w, m, GLUT_RIGHT_BUTTON, 20, 10);
  tessel::glut::menu_release(w, 190, 140);
  EXPECT_EQ(g_chosen, 0);
}

TEST(GlutMenu, Submenus) {
  tessel::glut::Window& w = window();
  const int sub = glutCreateMenu(on_menu);
  glutAddMenuEntry("Red", 10);
  glutAddMenuEntry("Green", 11);
  const int top = glutCreateMenu(on_menu);
  glutAddMenuEntry("Reset", 1);
  glutAddSubMenu("Colour", sub);
  tessel::glut::menu_open(w, top, GLUT_RIGHT_BUTTON, 5, 5);
  tessel::glut::menu_motion(w, 10, item_y(5, 1));  // over "Colour": the submenu opens
  ASSERT_EQ(w.open_menus.size(), 2u);
  const tessel::glut::OpenMenu& s = w.open_menus[1];
  EXPECT_EQ(s.menu, sub);
  tessel::glut::menu_motion(w, s.x + 5, item_y(s.y, 1));
  g_chosen = 0;
  tessel::glut::menu_release(w, s.x + 5, item_y(s.y, 1));
  EXPECT_EQ(g_chosen, 11);
  EXPECT_EQ(g_chosen_menu, sub);
}

TEST(GlutMenu, ChangeAndRemoveEntries) {
  window();
  glutCreateMenu(on_menu);
  glutAddMenuEntry("a", 1);
  glutAddMenuEntry("b", 2);
  glutAddMenuEntry("c", 3);
  glutChangeToMenuEntry(2, "B", 20);
  glutRemoveMenuItem(1);
  EXPECT_EQ(glutGet(GLUT_MENU_NUM_ITEMS), 2);
  const tessel::glut::Menu* m = tessel::glut::menu(glutGetMenu());
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->items[0].label, "B");
  EXPECT_EQ(m->items[0].value, 20);
}

TEST(GlutMenu, IsDrawnOverTheImage) {
  tessel::glut::Window& w = window();
  const int m = glutCreateMenu(on_menu);
  glutAddMenuEntry("Wireframe", 1);
  glutAddMenuEntry("Solid", 2);
  tessel::glut::menu_open(w, m, GLUT_RIGHT_BUTTON, 30, 20);
  tessel::glut::menu_motion(w, 40, item_y(20, 0));
  std::vector<uint8_t> img(200 * 150 * 4, 0);
  tessel::glut::menu_draw(w, img, 200, 150);
  auto px = [&](int x, int y) { return &img[(size_t(y) * 200 + size_t(x)) * 4]; };
  EXPECT_EQ(px(0, 0)[0], 0);                 // outside the menu: untouched
  EXPECT_EQ(px(35, item_y(20, 0))[2], 204);  // the highlighted entry's blue
  EXPECT_EQ(px(35, item_y(20, 1))[0], 226);  // the menu's grey
  // Text: dark pixels inside the second entry's row.
  int dark = 0;
  for (int y = 20 + 1 + 19; y < 20 + 1 + 38; ++y)
    for (int x = 34; x < 100; ++x) dark += px(x, y)[0] < 60;
  EXPECT_GT(dark, 20);
  tessel::glut::menu_release(w, 199, 149);
}

TEST(GlutHeadless, TimersAndIdleInVirtualTime) {
  window();
  state().virtual_ms = 0.0;
  g_fired.clear();
  g_idle = 0;
  glutTimerFunc(20, on_timer, 2);
  glutTimerFunc(0, on_timer, 1);
  glutTimerFunc(20, on_timer, 3);  // same time as 2: registration order
  glutIdleFunc(on_idle);
  tessel::glut::run_timers_and_idle();
  EXPECT_EQ(g_fired, std::vector<int>({1}));
  EXPECT_EQ(g_idle, 1);
  state().virtual_ms += 1000.0 / 60.0;  // 16.7 ms: not yet
  tessel::glut::run_timers_and_idle();
  EXPECT_EQ(g_fired.size(), 1u);
  state().virtual_ms += 1000.0 / 60.0;  // 33.3 ms
  tessel::glut::run_timers_and_idle();
  EXPECT_EQ(g_fired, std::vector<int>({1, 2, 3}));
  EXPECT_EQ(g_idle, 3);
  EXPECT_EQ(glutGet(GLUT_ELAPSED_TIME), 33);
  glutIdleFunc(nullptr);
}

TEST(GlutHeadless, WindowQueriesAndDisplay) {
  tessel::glut::Window& w = window();
  EXPECT_EQ(glutGet(GLUT_WINDOW_WIDTH), 200);
  EXPECT_EQ(glutGet(GLUT_WINDOW_HEIGHT), 150);
  EXPECT_EQ(glutGet(GLUT_WINDOW_DOUBLEBUFFER), 1);
  w.redisplay = true;
  tessel::glut::service_window(w);
  glutSwapBuffers();
  const auto& front = w.context->front();
  const auto* p = reinterpret_cast<const uint8_t*>(front.level(0).data.data());
  EXPECT_EQ(p[0], 51);   // 0.2 * 255
  EXPECT_EQ(p[2], 102);  // 0.4 * 255
}

}  // namespace

namespace {

// glutGetProcAddress gives GLUT's own entry points (as freeglut's does) and GL's.
TEST(GlutProcs, GlutAndGlEntryPoints) {
  EXPECT_EQ(glutGetProcAddress("glutSolidTeapot"), reinterpret_cast<GLUTproc>(&glutSolidTeapot));
  EXPECT_EQ(glutGetProcAddress("glutInitContextVersion"),
            reinterpret_cast<GLUTproc>(&glutInitContextVersion));
  EXPECT_EQ(glutGetProcAddress("glutGetProcAddress"), reinterpret_cast<GLUTproc>(&glutGetProcAddress));
  EXPECT_NE(glutGetProcAddress("glGenBuffers"), nullptr);
  EXPECT_NE(glutGetProcAddress("glClampColor"), nullptr);
  EXPECT_EQ(glutGetProcAddress("glutNoSuchThing"), nullptr);
  EXPECT_EQ(glutGetProcAddress(nullptr), nullptr);
}

}  // namespace

// A window has alpha bits only when GLUT_ALPHA asks for them, as an X visual chosen by
// freeglut for GLUT_RGBA: without them alpha reads as 1 and GL_DST_ALPHA blends as 1 (the
// figures are Mesa 22.3's under Xvfb for the same calls).
TEST(GlutWindow, AlphaBitsOnlyWhenAskedFor) {
  window();
  auto probe = [](GLint& bits, GLubyte cleared[4], GLubyte blended[4]) {
    glGetIntegerv(GL_ALPHA_BITS, &bits);
    glClearColor(0.2f, 0.4f, 0.6f, 0.3f);
    glClear(GL_COLOR_BUFFER_BIT);
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, cleared);
    glEnable(GL_BLEND);
    glBlendFunc(GL_DST_ALPHA, GL_ZERO);
    glColor4f(1, 1, 1, 1);
    glRectf(-1, -1, 1, 1);
    glDisable(GL_BLEND);
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, blended);
  };
  GLint bits = -1;
  GLubyte cleared[4], blended[4];
  probe(bits, cleared, blended);  // the GLUT_RGB window
  EXPECT_EQ(bits, 0);
  EXPECT_EQ(cleared[0], 51);
  EXPECT_EQ(cleared[3], 255);
  EXPECT_EQ(blended[0], 255);
  EXPECT_EQ(blended[3], 255);
  const int current = glutGetWindow();
  glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_ALPHA);
  const int with_alpha = glutCreateWindow("alpha");
  probe(bits, cleared, blended);
  EXPECT_EQ(bits, 8);
  EXPECT_EQ(cleared[3], 76);
  EXPECT_EQ(blended[0], 76);
  EXPECT_EQ(blended[3], 76);
  glutDestroyWindow(with_alpha);
  glutSetWindow(current);
  glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE);
}

// gluBuild3DMipmaps / gluBuild3DMipmapLevels (GLU 1.3 §3.2): the levels and sizes they make,
// and the errors they return before touching any texture.
TEST(Glu, Build3DMipmapsLevelsAndErrors) {
  window();
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_3D, t);
  std::vector<GLubyte> texels(5 * 3 * 2 * 4, 200);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // 5x3x2 becomes 4x4x2 (GLU's nearest powers of two), then 2x2x1 and 1x1x1.
  ASSERT_EQ(gluBuild3DMipmaps(GL_TEXTURE_3D, GL_RGBA8, 5, 3, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels.data()), 0);
  const GLint sizes[3][3] = {{4, 4, 2}, {2, 2, 1}, {1, 1, 1}};
  for (int level = 0; level < 3; ++level) {
    GLint w = 0, h = 0, d = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_3D, level, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, level, GL_TEXTURE_HEIGHT, &h);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, level, GL_TEXTURE_DEPTH, &d);
    EXPECT_EQ(w, sizes[level][0]) << level;
    EXPECT_EQ(h, sizes[level][1]) << level;
    EXPECT_EQ(d, sizes[level][2]) << level;
  }
  GLubyte texel[4] = {};
  glGetTexImage(GL_TEXTURE_3D, 2, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  EXPECT_EQ(texel[0], 200);  // a constant volume stays constant through scaling and halving
  EXPECT_EQ(gluBuild3DMipmaps(GL_TEXTURE_3D, GL_RGBA8, 0, 3, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels.data()),
            GLU_INVALID_VALUE);
  EXPECT_EQ(gluBuild3DMipmaps(GL_TEXTURE_3D, GL_RGBA8, 5, 3, 2, GL_RGBA, GL_BITMAP, texels.data()),
            GLU_INVALID_ENUM);
  // Levels: base below the user's level, max past the last, max below base.
  EXPECT_EQ(gluBuild3DMipmapLevels(GL_TEXTURE_3D, GL_RGBA8, 4, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, 1, 0, 2,
                                   texels.data()),
            GLU_INVALID_VALUE);
  EXPECT_EQ(gluBuild3DMipmapLevels(GL_TEXTURE_3D, GL_RGBA8, 4, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 3,
                                   texels.data()),
            GLU_INVALID_VALUE);
  EXPECT_EQ(gluBuild3DMipmapLevels(GL_TEXTURE_3D, GL_RGBA8, 4, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, 0, 2, 1,
                                   texels.data()),
            GLU_INVALID_VALUE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glDeleteTextures(1, &t);
}

namespace {

void clear_red() {
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
}
void clear_green() {
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
}
int g_sub_reshape_w = 0, g_sub_reshape_h = 0;
void sub_reshape(int w, int h) {
  g_sub_reshape_w = w;
  g_sub_reshape_h = h;
  glViewport(0, 0, w, h);
}

// Subwindows sit inside their parent (GLUT 3.7 section 4.2, as freeglut draws them): the
// top-level window's image shows them over its own at their places (x, y from the parent's
// top-left, y down), nested ones inside theirs; input over them goes to them in their own
// coordinates; hidden ones are not shown; destroying the parent destroys them.
TEST(GlutWindow, SubwindowsAreNestedInTheirParent) {
  tessel::glut::Window& top = window();
  const int top_id = top.id;
  glutSetWindow(top_id);
  const int sub = glutCreateSubWindow(top_id, 20, 30, 60, 40);
  ASSERT_GT(sub, 0);
  glutDisplayFunc(clear_red);
  glutReshapeFunc(sub_reshape);
  EXPECT_EQ(glutGet(GLUT_WINDOW_PARENT), top_id);
  EXPECT_EQ(glutGet(GLUT_WINDOW_X), 20);
  EXPECT_EQ(glutGet(GLUT_WINDOW_Y), 30);
  EXPECT_EQ(glutGet(GLUT_WINDOW_WIDTH), 60);
  const int inner = glutCreateSubWindow(sub, 10, 5, 8, 6);
  glutDisplayFunc(clear_green);
  glutSetWindow(top_id);
  EXPECT_EQ(glutGet(GLUT_WINDOW_NUM_CHILDREN), 1);
  EXPECT_EQ(glutGet(GLUT_WINDOW_PARENT), 0);
  for (int id : {top_id, sub, inner}) {
    tessel::glut::Window* w = tessel::glut::window(id);
    w->redisplay = true;
    tessel::glut::service_window(*w);
    glutSetWindow(id);
    glutSwapBuffers();
  }
  EXPECT_EQ(g_sub_reshape_w, 60);
  EXPECT_EQ(g_sub_reshape_h, 40);
  std::vector<uint8_t> img;
  tessel::glut::visible_image(top, img);
  ASSERT_EQ(img.size(), size_t(200 * 150 * 4));
  auto px = [&](int x, int y) { return &img[(size_t(y) * 200 + size_t(x)) * 4]; };
  EXPECT_EQ(px(5, 5)[2], 102);    // the parent's own clear (0.2, 0.3, 0.4)
  EXPECT_EQ(px(20, 30)[0], 255);  // the subwindow's top-left corner: red
  EXPECT_EQ(px(79, 69)[0], 255);  // its bottom-right pixel
  EXPECT_EQ(px(80, 69)[0], 51);   // just outside it
  EXPECT_EQ(px(19, 30)[0], 51);
  EXPECT_EQ(px(30, 35)[1], 255);  // the nested one at (20 + 10, 30 + 5): green
  EXPECT_EQ(px(37, 40)[1], 255);
  EXPECT_EQ(px(38, 40)[1], 0);  // back in the red one
  EXPECT_EQ(px(38, 40)[0], 255);
  // Input: the window under a point of the top-level window, in its own coordinates.
  int x = 32, y = 36;
  EXPECT_EQ(tessel::glut::window_at(top, x, y).id, inner);
  EXPECT_EQ(x, 2);
  EXPECT_EQ(y, 1);
  x = 50, y = 60;
  EXPECT_EQ(tessel::glut::window_at(top, x, y).id, sub);
  EXPECT_EQ(x, 30);
  x = 150, y = 20;
  EXPECT_EQ(tessel::glut::window_at(top, x, y).id, top_id);
  // Moved and hidden.
  glutSetWindow(sub);
  glutPositionWindow(100, 10);
  tessel::glut::visible_image(top, img);
  EXPECT_EQ(px(20, 30)[0], 51);
  EXPECT_EQ(px(100, 10)[0], 255);
  glutHideWindow();
  tessel::glut::visible_image(top, img);
  EXPECT_EQ(px(100, 10)[0], 51);
  // Destroying the subwindow destroys the one inside it.
  glutDestroyWindow(sub);
  EXPECT_EQ(tessel::glut::window(sub), nullptr);
  EXPECT_EQ(tessel::glut::window(inner), nullptr);
  glutSetWindow(top_id);
  EXPECT_EQ(glutGet(GLUT_WINDOW_NUM_CHILDREN), 0);
}

}  // namespace
