// Headless desktop OpenGL on Mesa llvmpipe, shared by the benchmark peer (bench/peer) and the
// reference oracle of the tests (tests/reference): an EGL display without a window system, a
// desktop GL 3.3 core context made current on it, and shader/program building.
//
// Deliberately free of EGL and GL headers: GL names and enums are plain `unsigned int`, which
// is what GLuint and GLenum are. GL entry points come straight from libOpenGL (glvnd), which
// dispatches to the context made current through libEGL.
//
// Messages carry no prefix; callers prepend their own ("tessel_peer: ", "MesaOracle: ").
#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace tessel::gl {

struct HeadlessOptions {
  // If a desktop GL 3.3 core context is refused, try a 3.3 compatibility-profile context.
  bool compat_fallback = false;
  // Ask for a compatibility-profile context first (for OpenGL 1.x fixed function).
  bool compat_profile = false;
  // Accept Tessel's own GL as well as llvmpipe (the peer run on Tessel's libEGL.so.1 and
  // libOpenGL.so.0 by LD_LIBRARY_PATH, as `tessel bench --api gl33` does). Any other
  // renderer (a hardware driver) is refused either way.
  bool accept_tessel = false;
};

// A desktop GL 3.3 context on Mesa llvmpipe, current on the creating thread, with no surface
// (draw into an FBO). The EGLDisplay is shared by every HeadlessContext of the process and
// terminated when the last one is destroyed (Mesa's eglInitialize is not reference counted).
class HeadlessContext {
 public:
  // Never throws. Returns nullptr and sets *why (if non-null) when no EGL display, no GL 3.3
  // context or no llvmpipe renderer is available. The first call sets LIBGL_ALWAYS_SOFTWARE=1
  // and GALLIUM_DRIVER=llvmpipe unless already set (set LP_NUM_THREADS etc. before calling).
  // EGL display routes, in order: EGL_MESA_platform_surfaceless; EGL_EXT_platform_device with
  // an EGL_MESA_device_software device; eglGetDisplay(EGL_DEFAULT_DISPLAY) with
  // EGL_PLATFORM=surfaceless.
  static std::unique_ptr<HeadlessContext> create(std::string* why, const HeadlessOptions& options = {});
  ~HeadlessContext();  // releases the context, and the display with the last context
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  // Makes this context current on the calling thread (a no-op if it already is). Never throws;
  // on failure returns false and sets *why (if non-null) to "eglMakeCurrent failed (...)".
  bool make_current(std::string* why = nullptr) const noexcept;

  std::string platform() const { return platform_; }  // the EGL route that worked
  bool core_profile() const { return core_; }         // false: the compatibility fallback
  // GL_RENDERER and GL_VERSION of this context (made current first; "" if that fails), e.g.
  // "llvmpipe (LLVM 15.0.6, 256 bits)" and "4.5 (Core Profile) Mesa 22.3.6".
  std::string renderer() const;
  std::string version() const;

 private:
  HeadlessContext() = default;
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext (EGL_NO_CONTEXT == nullptr)
  std::string platform_;
  bool core_ = true;
};

// The following need a current context and throw std::runtime_error with the info log.

// glCreateShader + glShaderSource + glCompileShader. Throws "shader compile failed: <log>"
// (the shader is deleted first).
// A GL or EGL enum or error code as "0x0500".
std::string hex(uint32_t v);
// The name of a glGetError code ("GL_INVALID_ENUM"), or "unknown GL error".
const char* gl_error_name(uint32_t e);

unsigned int compile_shader(unsigned int type, const std::string& src);
// glCreateProgram, attaches vs and fs, links. The shaders stay the caller's. Throws
// "program link failed: <log>" (the program is deleted first).
unsigned int link_program(unsigned int vs, unsigned int fs);
// Compiles both stages, links them and deletes the shader objects (also on failure).
unsigned int build_program(const std::string& vs_src, const std::string& fs_src);

}  // namespace tessel::gl
