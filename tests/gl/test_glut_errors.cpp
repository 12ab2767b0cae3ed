// GLUT misuse that GLUT 3.7 calls fatal is reported on stderr and ignored, and glutMainLoop
// returns: the library never ends the program (each test reaching its end shows that).
#include <GL/glut.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "../../src/glut/glut_internal.hpp"

namespace {

using tessel::glut::state;

int g_displayed = 0;
void on_display() { ++g_displayed; }

// Runs f and returns what it wrote to stderr.
template <class F>
std::string stderr_of(F f) {
  testing::internal::CaptureStderr();
  f();
  return testing::internal::GetCapturedStderr();
}

void init_headless(const char* spec) {
  setenv("TESSEL_HEADLESS", spec, 1);
  int argc = 1;
  char name[] = "test_glut_errors";
  char* argv[] = {name, nullptr};
  glutInit(&argc, argv);
}

}  // namespace

// Runs first: nothing is initialized yet in this process.
TEST(GlutErrors, CallsBeforeGlutInitAreReportedAndIgnored) {
  int id = -1;
  const std::string err = stderr_of([&] {
    id = glutCreateWindow("early");
    glutDisplayFunc(on_display);
    glutPostRedisplay();
    glutTimerFunc(
        10, [](int) {}, 0);
    glutMainLoop();
  });
  EXPECT_EQ(id, 0);
  EXPECT_NE(err.find("tessel glut: glutCreateWindow called before glutInit"), std::string::npos) << err;
  EXPECT_NE(err.find("tessel glut: glutDisplayFunc called with no current window"), std::string::npos) << err;
  EXPECT_NE(err.find("tessel glut: glutPostRedisplay called with no current window"), std::string::npos)
      << err;
  EXPECT_NE(err.find("tessel glut: glutMainLoop called before glutInit"), std::string::npos) << err;
  EXPECT_TRUE(state().windows.empty());
  EXPECT_TRUE(state().timers.empty());
}

// A window without a display callback: reported, the loop returns, and once an error was
// reported glutMainLoop returns at once (as the program would have ended in GLUT).
TEST(GlutErrors, AWindowWithoutADisplayCallbackEndsTheMainLoop) {
  state().failed = false;
  init_headless("frames:3,out:.");
  ASSERT_TRUE(state().initialized);
  const int id = glutCreateWindow("no display");
  ASSERT_GT(id, 0);
  std::string err = stderr_of([] { glutMainLoop(); });
  EXPECT_NE(err.find("tessel glut: no display callback registered for window " + std::to_string(id)),
            std::string::npos)
      << err;
  EXPECT_TRUE(state().failed);
  glutDisplayFunc(on_display);
  g_displayed = 0;
  glutMainLoop();
  EXPECT_EQ(g_displayed, 0) << "after an error glutMainLoop must not run";
}

// A headless frame that cannot be written: reported with the folder, the loop returns.
TEST(GlutErrors, AnUnwritableOutputFolderIsReported) {
  state().failed = false;
  glutDisplayFunc(on_display);
  state().headless.out = "/proc/tessel-no-such-folder/frames";
  g_displayed = 0;
  const std::string err = stderr_of([] { glutMainLoop(); });
  EXPECT_NE(err.find("tessel glut: cannot create the output folder /proc/tessel-no-such-folder/frames"),
            std::string::npos)
      << err;
  EXPECT_EQ(g_displayed, 0);
  // With a writable folder the same window renders its frames.
  state().failed = false;
  state().headless.out = testing::TempDir();
  glutMainLoop();
  EXPECT_EQ(g_displayed, 3);
  EXPECT_FALSE(state().failed);
}
