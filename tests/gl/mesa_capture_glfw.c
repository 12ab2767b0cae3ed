/*
 * mesa_capture_glfw.c - frame capture shim for the Mesa (GLFW + libGL) builds of the GLFW
 * acceptance programs in tests/gl33/programs (the GLFW twin of mesa_capture.c).
 *
 * Linked into every glm_<name> GLFW executable with -Wl,--wrap=glfwSwapBuffers. With
 *     TESSEL_CAPTURE=frames:N,out:DIR
 * each glfwSwapBuffers first writes the back buffer (what the swap makes visible) to
 * DIR/frame-NNNN.png; after N frames the process exits with status 0. Without it, inert.
 * Tessel's GLFW honours the same contract natively through TESSEL_HEADLESS.
 */
#include <GLFW/glfw3.h>

#include <stdlib.h>

#include "capture_core.h"

void __real_glfwSwapBuffers(GLFWwindow* window);

void __wrap_glfwSwapBuffers(GLFWwindow* window) {
  int w = 0, h = 0;
  cap_parse();
  if (cap_enabled) {
    glfwGetFramebufferSize(window, &w, &h);
    cap_write(GL_BACK, w, h, (cap_proc_fn)glfwGetProcAddress);
  }
  __real_glfwSwapBuffers(window);
  if (cap_enabled && cap_count >= cap_frames) exit(0);
}
