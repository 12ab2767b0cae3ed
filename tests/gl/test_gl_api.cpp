// The GL 1.x state machine through its C entry points: glGetError for each error class
// (GL 2.1 §2.5: the offending command has no other effect), display lists and attribute
// stacks, and a randomized sequence of thousands of calls — wrong enums, bad values, calls
// between glBegin and glEnd that are not allowed there — that must never crash and must
// leave the state queryable.
#include <GL/gl.h>

#include <gtest/gtest.h>

#include <climits>
#include <random>
#include <vector>

#include "../../src/gl/context.hpp"

namespace {

struct GLTest : ::testing::Test {
  tessel::gl::Context ctx{64, 48, true, true, true};
  void SetUp() override { tessel::gl::make_current(&ctx); }
  void TearDown() override { tessel::gl::make_current(nullptr); }
};

GLint get_int(GLenum name) {
  GLint v[16] = {};
  glGetIntegerv(name, v);
  return v[0];
}

TEST_F(GLTest, NoErrorAtStart) { EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)); }

TEST_F(GLTest, InvalidEnumChangesNothing) {
  glEnable(0x1234);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glDepthFunc(GL_GREATER);
  glDepthFunc(GL_TRUE);  // not a comparison
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_GREATER);
  glMatrixMode(GL_COLOR_MATERIAL);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_MATRIX_MODE), GL_MODELVIEW);
  glBegin(GL_POLYGON + 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glEnd();  // not inside glBegin: the bad glBegin started nothing
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(GLTest, InvalidValueChangesNothing) {
  glLineWidth(3.0f);
  glLineWidth(-1.0f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLfloat w = 0.0f;
  glGetFloatv(GL_LINE_WIDTH, &w);
  EXPECT_EQ(w, 3.0f);
  glViewport(1, 2, 30, 20);
  glViewport(0, 0, -5, 10);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLint vp[4];
  glGetIntegerv(GL_VIEWPORT, vp);
  EXPECT_EQ(vp[2], 30);
  const GLfloat cutoff = 120.0f;  // outside [0, 90] and not 180
  glLightfv(GL_LIGHT0, GL_SPOT_CUTOFF, &cutoff);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLfloat got = 0.0f;
  glGetLightfv(GL_LIGHT0, GL_SPOT_CUTOFF, &got);
  EXPECT_EQ(got, 180.0f);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 3);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_UNPACK_ALIGNMENT), 4);
}

TEST_F(GLTest, InvalidOperationInsideBeginEnd) {
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glClear(GL_COLOR_BUFFER_BIT);  // not allowed between glBegin and glEnd
  glEnable(GL_LIGHTING);
  glColor3f(1, 0, 0);   // allowed
  glNormal3f(0, 0, 1);  // allowed
  GLfloat red[4] = {1, 0, 0, 1};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);  // allowed
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));  // read once, then cleared
  EXPECT_EQ(glIsEnabled(GL_LIGHTING), GL_FALSE);
  glEndList();  // no list is being compiled
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(GLTest, FirstErrorIsKept) {
  glEnable(0x1234);    // INVALID_ENUM
  glLineWidth(-1.0f);  // INVALID_VALUE, not recorded: an error is pending
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(GLTest, StackOverflowAndUnderflow) {
  EXPECT_EQ(get_int(GL_MAX_MODELVIEW_STACK_DEPTH), 32);
  for (int i = 1; i < 32; ++i) glPushMatrix();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_MODELVIEW_STACK_DEPTH), 32);
  glPushMatrix();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_OVERFLOW));
  EXPECT_EQ(get_int(GL_MODELVIEW_STACK_DEPTH), 32);
  for (int i = 1; i < 32; ++i) glPopMatrix();
  glPopMatrix();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_UNDERFLOW));
  EXPECT_EQ(get_int(GL_MODELVIEW_STACK_DEPTH), 1);
  glMatrixMode(GL_TEXTURE);
  glPopMatrix();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_UNDERFLOW));
  glPopAttrib();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_UNDERFLOW));
  for (int i = 0; i < get_int(GL_MAX_ATTRIB_STACK_DEPTH); ++i) glPushAttrib(GL_ALL_ATTRIB_BITS);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glPushAttrib(GL_ENABLE_BIT);
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_OVERFLOW));
}

TEST_F(GLTest, OutOfMemory) {
  // More display-list names than can be reserved: GL_OUT_OF_MEMORY, and no names.
  EXPECT_EQ(glGenLists(INT_MAX), 0u);
  EXPECT_EQ(glGetError(), GLenum(GL_OUT_OF_MEMORY));
  const GLuint base = glGenLists(3);
  EXPECT_NE(base, 0u);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(GLTest, PushPopAttribRestoresGroups) {
  glEnable(GL_DEPTH_TEST);
  glLineWidth(2.0f);
  glPushAttrib(GL_ENABLE_BIT | GL_LINE_BIT);
  glDisable(GL_DEPTH_TEST);
  glLineWidth(5.0f);
  glDepthFunc(GL_ALWAYS);  // depth buffer group: not saved, so it stays
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_TRUE);
  GLfloat w = 0.0f;
  glGetFloatv(GL_LINE_WIDTH, &w);
  EXPECT_EQ(w, 2.0f);
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_ALWAYS);
}

TEST_F(GLTest, DisplayListsRecordValuesAndNest) {
  const GLuint list = glGenLists(2);
  glNewList(list, GL_COMPILE);
  glColor3f(0.25f, 0.5f, 0.75f);
  glCallList(list + 1);  // defined later: bound by name when the list runs
  glEndList();
  glNewList(list + 1, GL_COMPILE);
  glLineWidth(4.0f);
  glEndList();
  GLfloat c[4];
  glGetFloatv(GL_CURRENT_COLOR, c);
  EXPECT_EQ(c[0], 1.0f);  // GL_COMPILE does not execute
  glCallList(list);
  glGetFloatv(GL_CURRENT_COLOR, c);
  EXPECT_EQ(c[1], 0.5f);
  GLfloat w = 0.0f;
  glGetFloatv(GL_LINE_WIDTH, &w);
  EXPECT_EQ(w, 4.0f);
  EXPECT_EQ(glIsList(list), GL_TRUE);
  glDeleteLists(list, 2);
  EXPECT_EQ(glIsList(list), GL_FALSE);
  glCallList(list);  // a deleted list is nothing, not an error
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // A list that calls itself stops at the nesting limit instead of recursing forever.
  glNewList(7, GL_COMPILE);
  glCallList(7);
  glEndList();
  glCallList(7);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(GLTest, DrawingReachesTheBuffers) {
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 0, 0);
  glRectf(-1, -1, 1, 1);
  GLubyte px[4] = {};
  glReadPixels(10, 10, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[0], 255);
  EXPECT_EQ(px[1], 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_STREQ(reinterpret_cast<const char*>(glGetString(GL_VENDOR)), "Tessel");
}

// Vertex arrays are read when the draw is issued: a second glDrawElements after the program
// changed the array (same pointer) draws the new data, not a reused conversion.
TEST_F(GLTest, ChangedArraysAreReadAgain) {
  GLfloat v[4][2] = {{-1, -1}, {0, -1}, {0, 0}, {-1, 0}};  // the lower-left quarter
  const GLubyte idx[6] = {0, 1, 2, 0, 2, 3};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, v);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 0, 0);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, idx);
  for (auto& p : v) p[0] += 1.0f, p[1] += 1.0f;  // now the upper-right quarter, same colour
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, idx);
  glDisableClientState(GL_VERTEX_ARRAY);
  GLubyte ll[4], ur[4];
  glReadPixels(10, 10, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, ll);
  glReadPixels(50, 40, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, ur);
  EXPECT_EQ(ll[0], 255);
  EXPECT_EQ(ur[0], 255);  // black if the first draw's vertices had been reused
}

// Selection mode: hit records (names, depths scaled to 2^32 - 1), overflow, name stack errors.
TEST_F(GLTest, SelectionHitRecords) {
  GLuint buf[64] = {};
  glRenderMode(GL_SELECT);  // no buffer yet
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glSelectBuffer(64, buf);
  EXPECT_EQ(glRenderMode(GL_SELECT), 0);
  EXPECT_EQ(get_int(GL_RENDER_MODE), GL_SELECT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -1, 1);  // z_window = (1 - z) / 2 for these (z_ndc = -z)
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glInitNames();
  glPushName(10);
  glRectf(-0.5f, -0.5f, 0.5f, 0.5f);  // z = 0: depth 0.5
  glPushName(11);
  glBegin(GL_POINTS);
  glVertex3f(0, 0, 0.5f);  // depth 0.25
  glVertex3f(3, 0, 0);     // outside: no hit
  glEnd();
  glPopName();
  glLoadName(12);
  glBegin(GL_LINES);
  glVertex2f(5, 5);  // wholly outside
  glVertex2f(6, 6);
  glEnd();
  EXPECT_EQ(glRenderMode(GL_RENDER), 2);
  EXPECT_EQ(buf[0], 1u);           // names
  EXPECT_EQ(buf[1], 2147483648u);  // 0.5 * (2^32 - 1), rounded
  EXPECT_EQ(buf[2], 2147483648u);
  EXPECT_EQ(buf[3], 10u);
  EXPECT_EQ(buf[4], 2u);
  EXPECT_EQ(buf[5], 1073741824u);  // 0.25
  EXPECT_EQ(buf[7], 10u);
  EXPECT_EQ(buf[8], 11u);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // Too small a buffer: glRenderMode returns -1.
  glSelectBuffer(2, buf);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(1);
  glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
  EXPECT_EQ(glRenderMode(GL_RENDER), -1);
  // Name stack errors in selection mode.
  glSelectBuffer(64, buf);
  glRenderMode(GL_SELECT);
  glInitNames();
  glLoadName(3);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glPopName();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_UNDERFLOW));
  glSelectBuffer(64, buf);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glRenderMode(GL_RENDER);
}

// Feedback mode: tokens and window coordinates, pass-through, overflow.
TEST_F(GLTest, FeedbackTokens) {
  GLfloat buf[64] = {};
  glRenderMode(GL_FEEDBACK);  // no buffer yet
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glFeedbackBuffer(64, GL_2D, buf);
  glRenderMode(GL_FEEDBACK);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 64, 0, 48, -1, 1);  // object coordinates are window coordinates
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glPassThrough(7.0f);
  glBegin(GL_POINTS);
  glVertex2f(10.5f, 20.5f);
  glVertex2f(100, 20);  // outside: nothing
  glEnd();
  glBegin(GL_LINES);
  glVertex2f(1, 2);
  glVertex2f(3, 4);
  glEnd();
  EXPECT_EQ(glRenderMode(GL_RENDER), 2 + 3 + 5);
  EXPECT_EQ(buf[0], float(GL_PASS_THROUGH_TOKEN));
  EXPECT_EQ(buf[1], 7.0f);
  EXPECT_EQ(buf[2], float(GL_POINT_TOKEN));
  EXPECT_FLOAT_EQ(buf[3], 10.5f);
  EXPECT_FLOAT_EQ(buf[4], 20.5f);
  EXPECT_EQ(buf[5], float(GL_LINE_TOKEN));
  EXPECT_FLOAT_EQ(buf[8], 3.0f);
  glFeedbackBuffer(2, GL_2D, buf);  // too small for a point
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_POINTS);
  glVertex2f(10, 10);
  glEnd();
  EXPECT_EQ(glRenderMode(GL_RENDER), -1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Thousands of calls with random arguments: enums drawn from a pool of valid and invalid
// values, numbers including negatives, NaN and huge ones, and calls inside glBegin/glEnd.
// Pixel maps in the transfers (GL 2.1 section 3.6.5) with the values the specification gives:
// colour maps looked up at round(c (size - 1)), index arithmetic (shift, then offset), I_TO_I
// under GL_MAP_COLOR, the I_TO_R/G/B/A palette, S_TO_S under GL_MAP_STENCIL; maps are kept
// per context, outside the attribute groups, and read back as given.
TEST_F(GLTest, PixelTransferIndexOperationsAndMaps) {
  glRasterPos2i(0, 0);  // the window's centre, (32, 24)
  GLubyte got[4];
  auto draw_read = [&](GLenum format, GLenum type, const void* px) {
    glDrawPixels(1, 1, format, type, px);
    // (Read without the colour maps: they apply to reads too.)
    GLint map = 0;
    glGetIntegerv(GL_MAP_COLOR, &map);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
    glReadPixels(32, 24, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, got);
    glPixelTransferi(GL_MAP_COLOR, map);
  };
  // R_TO_R of 4: red 0.75 is entry round(2.25) = 2.
  const GLfloat r_map[4] = {0.9f, 0.6f, 0.3f, 0.1f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, r_map);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  const GLfloat rgba[4] = {0.75f, 0.5f, 0.5f, 1.0f};
  draw_read(GL_RGBA, GL_FLOAT, rgba);
  EXPECT_NEAR(got[0], 77, 1);
  EXPECT_EQ(got[1], 0);  // G_TO_G is still one entry of 0
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  // A colour index: shifted left 1, offset 1, then the palette (masked to its size).
  const GLfloat i_to_r[4] = {0.0f, 0.25f, 0.5f, 1.0f}, one = 1.0f;
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, i_to_r);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 1, &one);
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  const GLubyte index = 1;  // (1 << 1) + 1 = 3: red 1.0
  draw_read(GL_COLOR_INDEX, GL_UNSIGNED_BYTE, &index);
  EXPECT_EQ(got[0], 255);
  EXPECT_EQ(got[3], 255);
  const GLuint reverse[4] = {3, 2, 1, 0};  // I_TO_I: index entries are integers
  glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 4, reverse);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  draw_read(GL_COLOR_INDEX, GL_UNSIGNED_BYTE, &index);  // 3 -> I_TO_I -> 0: red 0
  EXPECT_EQ(got[0], 0);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  glPixelTransferi(GL_INDEX_SHIFT, -1);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  const GLushort wide = 5;  // 5 >> 1 = 2: red 0.5
  draw_read(GL_COLOR_INDEX, GL_UNSIGNED_SHORT, &wide);
  EXPECT_NEAR(got[0], 128, 1);
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  // Stencil: offset 1, then S_TO_S; read back with and without the map.
  const GLfloat s_map[4] = {5, 4, 3, 2};
  glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 4, s_map);
  glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  const GLubyte st = 2;  // 3 -> S_TO_S[3] = 2
  glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &st);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
  GLubyte sv = 0;
  glReadPixels(32, 24, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &sv);
  EXPECT_EQ(sv, 2);
  glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
  glReadPixels(32, 24, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &sv);
  EXPECT_EQ(sv, 3);  // S_TO_S[2]
  glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
  // Queries: sizes, entries as given (index entries unnormalized), not pushed with the
  // pixel mode attributes.
  EXPECT_EQ(get_int(GL_PIXEL_MAP_R_TO_R_SIZE), 4);
  EXPECT_EQ(get_int(GL_PIXEL_MAP_G_TO_G_SIZE), 1);
  GLuint back[4] = {};
  glGetPixelMapuiv(GL_PIXEL_MAP_I_TO_I, back);
  EXPECT_EQ(back[0], 3u);
  GLushort rback[4] = {};
  glGetPixelMapusv(GL_PIXEL_MAP_R_TO_R, rback);
  EXPECT_EQ(rback[1], GLushort(39321));  // 0.6 * 65535
  glPushAttrib(GL_PIXEL_MODE_BIT);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 1, &one);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_PIXEL_MAP_R_TO_R_SIZE), 1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // Errors: a colour index map not a power of two, too large, a bad name.
  const GLfloat three[3] = {0, 0, 0};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 3, three);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 257, three);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glPixelMapfv(GL_RED_SCALE, 1, three);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_PIXEL_MAP_I_TO_G_SIZE), 1);
}

TEST_F(GLTest, RandomCallSequenceNeverCrashes) {
  std::mt19937 rng(12345);
  const GLenum enums[] = {GL_TRIANGLES,
                          GL_QUADS,
                          GL_POLYGON,
                          GL_LINES,
                          GL_POINTS,
                          GL_DEPTH_TEST,
                          GL_LIGHTING,
                          GL_LIGHT0,
                          GL_LIGHT7,
                          GL_TEXTURE_2D,
                          GL_BLEND,
                          GL_FOG,
                          GL_CULL_FACE,
                          GL_FRONT,
                          GL_BACK,
                          GL_FRONT_AND_BACK,
                          GL_LINE,
                          GL_FILL,
                          GL_POINT,
                          GL_MODELVIEW,
                          GL_PROJECTION,
                          GL_TEXTURE,
                          GL_RGBA,
                          GL_RGB,
                          GL_LUMINANCE,
                          GL_UNSIGNED_BYTE,
                          GL_FLOAT,
                          GL_AMBIENT,
                          GL_DIFFUSE,
                          GL_POSITION,
                          GL_SPOT_CUTOFF,
                          GL_SHININESS,
                          GL_COMPILE,
                          GL_COMPILE_AND_EXECUTE,
                          GL_NEAREST,
                          GL_LINEAR_MIPMAP_LINEAR,
                          GL_REPEAT,
                          GL_CLAMP,
                          GL_MODULATE,
                          GL_DECAL,
                          GL_LESS,
                          GL_ALWAYS,
                          GL_SRC_ALPHA,
                          GL_ONE_MINUS_SRC_ALPHA,
                          GL_KEEP,
                          GL_INCR,
                          GL_STENCIL_TEST,
                          GL_ALPHA_TEST,
                          GL_POLYGON_STIPPLE,
                          GL_LINE_STIPPLE,
                          GL_FLAT,
                          GL_SMOOTH,
                          GL_VERTEX_ARRAY,
                          GL_COLOR_ARRAY,
                          0,
                          1,
                          0x1234,
                          0xFFFF,
                          0x7FFFFFFF};
  auto e = [&] { return enums[rng() % (sizeof enums / sizeof enums[0])]; };
  const float numbers[] = {0.0f, 1.0f, -1.0f, 0.5f, 2.0f, 100.0f, -1e30f, 1e30f, NAN, INFINITY, 3.0f, 64.0f};
  auto f = [&] { return numbers[rng() % (sizeof numbers / sizeof numbers[0])]; };
  auto i = [&] { return int(rng() % 9) - 2; };
  std::vector<GLubyte> image(16 * 16 * 4, 200);
  GLfloat v[16];
  for (int n = 0; n < 20000; ++n) {
    for (float& x : v) x = f();
    switch (rng() % 40) {
      case 0: glBegin(e()); break;
      case 1: glEnd(); break;
      case 2: glVertex3f(f(), f(), f()); break;
      case 3: glColor4f(f(), f(), f(), f()); break;
      case 4: glNormal3f(f(), f(), f()); break;
      case 5: glTexCoord2f(f(), f()); break;
      case 6: glEnable(e()); break;
      case 7: glDisable(e()); break;
      case 8: glMatrixMode(e()); break;
      case 9: glPushMatrix(); break;
      case 10: glPopMatrix(); break;
      case 11: glLoadIdentity(); break;
      case 12: glRotatef(f(), f(), f(), f()); break;
      case 13: glTranslatef(f(), f(), f()); break;
      case 14: glFrustum(f(), f(), f(), f(), f(), f()); break;
      case 15: glOrtho(-1, 1, -1, 1, f(), f()); break;
      case 16: glLightfv(e(), e(), v); break;
      case 17: glMaterialfv(e(), e(), v); break;
      case 18: glNewList(GLuint(i() + 3), e()); break;
      case 19: glEndList(); break;
      case 20: glCallList(GLuint(i() + 3)); break;
      case 21: glClear(GLbitfield(rng())); break;
      case 22: glViewport(i(), i(), i() * 10, i() * 10); break;
      case 23: glTexImage2D(e(), i(), GLint(e()), 16, 16, i(), e(), e(), image.data()); break;
      case 24: glTexParameteri(GL_TEXTURE_2D, e(), GLint(e())); break;
      case 25: glBindTexture(e(), GLuint(i() + 2)); break;
      case 26: glPolygonMode(e(), e()); break;
      case 27: glBlendFunc(e(), e()); break;
      case 28: glDepthFunc(e()); break;
      case 29: glLineWidth(f()); break;
      case 30: glPointSize(f()); break;
      case 31: glPushAttrib(GLbitfield(rng())); break;
      case 32: glPopAttrib(); break;
      case 33: glRectf(f(), f(), f(), f()); break;
      case 34: glDrawArrays(e(), i(), i() * 3); break;
      case 35: glFogf(e(), f()); break;
      case 36: glShadeModel(e()); break;
      case 37: glTexEnvi(e(), e(), GLint(e())); break;
      case 38: {
        GLubyte px[4 * 4 * 4];
        glReadPixels(i(), i(), 4, 4, e(), e(), px);
        break;
      }
      default: glFlush(); break;
    }
    const GLenum err = glGetError();
    ASSERT_TRUE(err == GL_NO_ERROR || err == GL_INVALID_ENUM || err == GL_INVALID_VALUE ||
                err == GL_INVALID_OPERATION || err == GL_STACK_OVERFLOW || err == GL_STACK_UNDERFLOW ||
                err == GL_OUT_OF_MEMORY)
        << "call " << n << " gave 0x" << std::hex << err;
  }
  // Still a working context: leave any glBegin and list, then query and draw.
  glEnd();
  glEndList();
  glGetError();
  GLint depth = 0;
  glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &depth);
  EXPECT_GE(depth, 1);
  EXPECT_LE(depth, 32);
  glFinish();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
