// EGL 1.5 over Tessel (src/egl): displays, configs, pbuffers, contexts of each version and
// profile, current without a surface, syncs, eglGetProcAddress, and the error each misuse
// gives (EGL 1.5 §3). Linked statically; the shared libraries are exercised by the EGL
// programs of tests/gl33, run unchanged on them.
#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace {

struct EglTest : ::testing::Test {
  EGLDisplay dpy = EGL_NO_DISPLAY;
  void SetUp() override {
    dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    ASSERT_NE(dpy, EGL_NO_DISPLAY);
    EGLint major = 0, minor = 0;
    ASSERT_TRUE(eglInitialize(dpy, &major, &minor));
    EXPECT_EQ(major, 1);
    EXPECT_EQ(minor, 5);
  }
  void TearDown() override {
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglTerminate(dpy);
  }
};

TEST(Egl, ErrorsBeforeInitialize) {
  EXPECT_EQ(eglGetDisplay(reinterpret_cast<EGLNativeDisplayType>(0x1234)), EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);  // read once
  EXPECT_FALSE(eglInitialize(reinterpret_cast<EGLDisplay>(0x10), nullptr, nullptr));
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  EGLint n = 0;
  EXPECT_FALSE(eglGetConfigs(d, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
  // The client extensions are there before any display.
  const char* ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  ASSERT_NE(ext, nullptr);
  EXPECT_NE(std::strstr(ext, "EGL_MESA_platform_surfaceless"), nullptr);
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  ASSERT_NE(get_platform_display, nullptr);
  EXPECT_EQ(get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), d);
  EXPECT_EQ(get_platform_display(EGL_PLATFORM_X11_KHR, EGL_DEFAULT_DISPLAY, nullptr), EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

TEST_F(EglTest, ConfigsAreChosenBySize) {
  EGLint n = 0;
  ASSERT_TRUE(eglGetConfigs(dpy, nullptr, 0, &n));
  EXPECT_EQ(n, 2);
  const EGLint want_depth[] = {EGL_DEPTH_SIZE, 16, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
  EGLConfig c = nullptr;
  ASSERT_TRUE(eglChooseConfig(dpy, want_depth, &c, 1, &n));
  ASSERT_EQ(n, 1);
  EGLint v = 0;
  EXPECT_TRUE(eglGetConfigAttrib(dpy, c, EGL_DEPTH_SIZE, &v));
  EXPECT_EQ(v, 24);
  // No depth asked: the config without depth comes first (§3.4.1.2: smaller depth first).
  const EGLint any[] = {EGL_RED_SIZE, 8, EGL_NONE};
  EGLConfig two[2];
  ASSERT_TRUE(eglChooseConfig(dpy, any, two, 2, &n));
  ASSERT_EQ(n, 2);
  EXPECT_TRUE(eglGetConfigAttrib(dpy, two[0], EGL_DEPTH_SIZE, &v));
  EXPECT_EQ(v, 0);
  // Nothing has windows or ES.
  const EGLint window[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_NONE};
  ASSERT_TRUE(eglChooseConfig(dpy, window, &c, 1, &n));
  EXPECT_EQ(n, 0);
  const EGLint bad[] = {0x1234, 1, EGL_NONE};
  EXPECT_FALSE(eglChooseConfig(dpy, bad, &c, 1, &n));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_FALSE(eglGetConfigAttrib(dpy, reinterpret_cast<EGLConfig>(0x99), EGL_DEPTH_SIZE, &v));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);
}

TEST_F(EglTest, ContextsOfEachVersionAndProfile) {
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  EXPECT_FALSE(eglBindAPI(EGL_OPENGL_ES_API));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  struct Case {
    EGLint major, minor, profile;
    const char* version;
  } cases[] = {{0, 0, 0, "2.1 Tessel"},
               {3, 3, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, "3.3 (Core Profile) Tessel"},
               {3, 2, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, "3.2 (Compatibility Profile) Tessel"},
               {3, 0, 0, "3.0 Tessel"}};
  for (const Case& k : cases) {
    EGLint attribs[8] = {EGL_NONE};
    int i = 0;
    if (k.major) {
      attribs[i++] = EGL_CONTEXT_MAJOR_VERSION, attribs[i++] = k.major;
      attribs[i++] = EGL_CONTEXT_MINOR_VERSION, attribs[i++] = k.minor;
    }
    if (k.profile) attribs[i++] = EGL_CONTEXT_OPENGL_PROFILE_MASK, attribs[i++] = k.profile;
    attribs[i] = EGL_NONE;
    EGLContext ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    ASSERT_NE(ctx, EGL_NO_CONTEXT) << k.version;
    ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
    EXPECT_EQ(eglGetCurrentContext(), ctx);
    const std::string v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    EXPECT_EQ(v.rfind(k.version, 0), 0u) << v;
    ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    EXPECT_TRUE(eglDestroyContext(dpy, ctx));
  }
  const EGLint too_new[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5, EGL_NONE};
  EXPECT_EQ(eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, too_new), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  const EGLint bad[] = {0x1234, 1, EGL_NONE};
  EXPECT_EQ(eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, bad), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_FALSE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, reinterpret_cast<EGLContext>(0x55)));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
}

// Current without a surface, framebuffer 0 does not exist (GL 3.3 §4.4.4.2): its status is
// GL_FRAMEBUFFER_UNDEFINED and drawing, clearing or reading there is
// GL_INVALID_FRAMEBUFFER_OPERATION; a framebuffer object works as ever.
TEST_F(EglTest, SurfacelessHasNoDefaultFramebuffer) {
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                            3,
                            EGL_CONTEXT_MINOR_VERSION,
                            3,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK,
                            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                            EGL_NONE};
  EGLContext ctx = eglCreateContext(dpy, nullptr, EGL_NO_CONTEXT, attribs);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_UNDEFINED));
  GLuint vao;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  GLubyte px[4] = {};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  GLuint fbo, rb;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 4);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(px[1], 255);
  glDeleteFramebuffers(1, &fbo);
  glDeleteRenderbuffers(1, &rb);
  glDeleteVertexArrays(1, &vao);
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(dpy, ctx);
}

TEST_F(EglTest, PbufferIsTheDefaultFramebuffer) {
  const EGLint cfg_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_DEPTH_SIZE, 24, EGL_NONE};
  EGLConfig cfg;
  EGLint n = 0;
  ASSERT_TRUE(eglChooseConfig(dpy, cfg_attribs, &cfg, 1, &n));
  const EGLint pb[] = {EGL_WIDTH, 64, EGL_HEIGHT, 32, EGL_NONE};
  EGLSurface s = eglCreatePbufferSurface(dpy, cfg, pb);
  ASSERT_NE(s, EGL_NO_SURFACE);
  EGLint w = 0, h = 0;
  EXPECT_TRUE(eglQuerySurface(dpy, s, EGL_WIDTH, &w));
  EXPECT_TRUE(eglQuerySurface(dpy, s, EGL_HEIGHT, &h));
  EXPECT_EQ(w, 64);
  EXPECT_EQ(h, 32);
  const EGLint big[] = {EGL_WIDTH, 100000, EGL_HEIGHT, 1, EGL_NONE};
  EXPECT_EQ(eglCreatePbufferSurface(dpy, cfg, big), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_ALLOC);
  EXPECT_EQ(eglCreateWindowSurface(dpy, cfg, 0, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EGLContext ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, nullptr);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, ctx));
  EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), s);
  glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  GLubyte px[4] = {};
  glReadPixels(63, 31, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[1], 255);
  GLint vp[4] = {};
  glGetIntegerv(GL_VIEWPORT, vp);
  EXPECT_EQ(vp[2], 64);
  EXPECT_TRUE(eglSwapBuffers(dpy, s));
  // A sync: signaled once the work before it is done.
  EGLSync sync = eglCreateSync(dpy, EGL_SYNC_FENCE, nullptr);
  ASSERT_NE(sync, EGL_NO_SYNC);
  EXPECT_EQ(eglClientWaitSync(dpy, sync, 0, EGL_FOREVER), EGL_CONDITION_SATISFIED);
  EGLAttrib status = 0;
  EXPECT_TRUE(eglGetSyncAttrib(dpy, sync, EGL_SYNC_STATUS, &status));
  EXPECT_EQ(status, EGL_SIGNALED);
  EXPECT_TRUE(eglDestroySync(dpy, sync));
  EXPECT_FALSE(eglDestroySync(dpy, sync));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  // Another context of this thread takes the surface over (EGL_BAD_ACCESS is for other threads).
  EGLContext other = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, nullptr);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, other));
  EXPECT_EQ(eglGetCurrentContext(), other);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, ctx));
  eglDestroyContext(dpy, other);
  // A destroyed current surface lives until it is released.
  EXPECT_TRUE(eglDestroySurface(dpy, s));
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_FALSE(eglDestroySurface(dpy, s));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  eglDestroyContext(dpy, ctx);
}

TEST_F(EglTest, ProcAddressesOfEglAndGl) {
  EXPECT_EQ(reinterpret_cast<void*>(eglGetProcAddress("eglMakeCurrent")),
            reinterpret_cast<void*>(&eglMakeCurrent));
  EXPECT_NE(eglGetProcAddress("glGenFramebuffers"), nullptr);
  EXPECT_NE(eglGetProcAddress("glDrawElementsInstanced"), nullptr);
  EXPECT_EQ(eglGetProcAddress("glNoSuchThing"), nullptr);
  EXPECT_EQ(eglGetProcAddress("eglNoSuchThing"), nullptr);
  EXPECT_EQ(eglGetProcAddress(nullptr), nullptr);
}

}  // namespace
