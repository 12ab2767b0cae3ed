// Headless desktop OpenGL on Mesa llvmpipe: see headless_gl.hpp.
#include "headless_gl.hpp"

#define GL_GLEXT_PROTOTYPES 1
#define EGL_EGLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <type_traits>

namespace tessel::gl {

static_assert(std::is_same_v<GLuint, unsigned int> && std::is_same_v<GLenum, unsigned int>,
              "headless_gl.hpp passes GLuint and GLenum as unsigned int");
static_assert(std::is_same_v<EGLDisplay, void*> && std::is_same_v<EGLContext, void*>,
              "HeadlessContext stores EGLDisplay and EGLContext as void*");

std::string hex(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%04X", v);
  return buf;
}

const char* gl_error_name(uint32_t e) {
  switch (e) {
    case 0x0500: return "GL_INVALID_ENUM";
    case 0x0501: return "GL_INVALID_VALUE";
    case 0x0502: return "GL_INVALID_OPERATION";
    case 0x0506: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case 0x0505: return "GL_OUT_OF_MEMORY";
    case 0x0503: return "GL_STACK_OVERFLOW";
    case 0x0504: return "GL_STACK_UNDERFLOW";
    default: return "unknown GL error";
  }
}

namespace {

const char* egl_error_name(EGLint e) {
  switch (e) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return "unknown EGL error";
  }
}

// "<what> failed (EGL_BAD_MATCH, 0x3009)", from the thread's last EGL error.
std::string egl_err(const char* what) {
  const EGLint e = eglGetError();
  return std::string(what) + " failed (" + egl_error_name(e) + ", " + hex(uint32_t(e)) + ")";
}

// Whether the space-separated extension list contains exactly `name`.
bool has_ext(const char* list, const char* name) {
  if (!list) return false;
  const size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

// One EGLDisplay shared by all contexts; eglTerminate when the last one goes away (Mesa's
// eglInitialize is not reference counted, so terminating per context would break the others).
std::mutex g_display_mutex;
EGLDisplay g_display = EGL_NO_DISPLAY;
int g_display_refs = 0;
std::string g_platform_name;

// Returns the shared display (initialized) and its route, or EGL_NO_DISPLAY and *why.
EGLDisplay acquire_display(std::string* why, std::string* platform) {
  std::lock_guard<std::mutex> lock(g_display_mutex);
  if (g_display_refs > 0) {
    ++g_display_refs;
    *platform = g_platform_name;
    return g_display;
  }
  // Force Mesa's software rasterizer unless the user chose otherwise.
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
  setenv("GALLIUM_DRIVER", "llvmpipe", 0);

  const char* client_exts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  std::string errors;

  auto try_init = [&](EGLDisplay d, const char* name, const char* get_call) -> bool {
    if (d == EGL_NO_DISPLAY) {
      errors += std::string(name) + ": " + egl_err(get_call) + "; ";
      return false;
    }
    EGLint major = 0, minor = 0;
    if (!eglInitialize(d, &major, &minor)) {
      errors += std::string(name) + ": " + egl_err("eglInitialize") + "; ";
      return false;
    }
    g_display = d;
    g_platform_name = name;
    return true;
  };

  bool ok = false;
  // 1. EGL_MESA_platform_surfaceless: no window system, no GPU needed.
  if (get_platform_display && has_ext(client_exts, "EGL_MESA_platform_surfaceless")) {
    ok = try_init(get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
                  "surfaceless", "eglGetPlatformDisplay");
  } else {
    errors += "EGL_MESA_platform_surfaceless not advertised; ";
  }
  // 2. EGL_EXT_platform_device with Mesa's software device (EGL_MESA_device_software).
  if (!ok && get_platform_display && has_ext(client_exts, "EGL_EXT_platform_device")) {
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto query_device_string =
        reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (query_devices && query_device_string && query_devices(16, devices, &count)) {
      for (EGLint i = 0; i < count && !ok; ++i) {
        const char* dexts = query_device_string(devices[i], EGL_EXTENSIONS);
        if (!has_ext(dexts, "EGL_MESA_device_software")) continue;
        ok = try_init(get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr),
                      "device (EGL_MESA_device_software)", "eglGetPlatformDisplay");
      }
    }
  }
  // 3. The default display, steered to the surfaceless platform.
  if (!ok) {
    setenv("EGL_PLATFORM", "surfaceless", 0);
    ok = try_init(eglGetDisplay(EGL_DEFAULT_DISPLAY), "EGL_DEFAULT_DISPLAY", "eglGetDisplay");
  }
  if (!ok) {
    if (errors.size() >= 2) errors.resize(errors.size() - 2);  // the last "; "
    *why = "no usable EGL display: " + errors;
    return EGL_NO_DISPLAY;
  }
  g_display_refs = 1;
  *platform = g_platform_name;
  return g_display;
}

void release_display() {
  std::lock_guard<std::mutex> lock(g_display_mutex);
  if (g_display_refs > 0 && --g_display_refs == 0) {
    eglTerminate(g_display);
    eglReleaseThread();
    g_display = EGL_NO_DISPLAY;
  }
}

std::string gl_string(GLenum name) {
  const char* s = reinterpret_cast<const char*>(glGetString(name));
  return s ? s : "";
}

}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create(std::string* why, const HeadlessOptions& options) {
  std::string dummy;
  if (!why) why = &dummy;
  why->clear();
  try {
    // From here on the destructor releases whatever has been acquired, also on failure.
    std::unique_ptr<HeadlessContext> hc(new HeadlessContext());
    const EGLDisplay dpy = acquire_display(why, &hc->platform_);
    if (dpy == EGL_NO_DISPLAY) return nullptr;  // *why already set
    hc->display_ = dpy;

    const char* dpy_exts = eglQueryString(dpy, EGL_EXTENSIONS);
    if (!has_ext(dpy_exts, "EGL_KHR_surfaceless_context")) {
      *why = "EGL_KHR_surfaceless_context not supported";
      return nullptr;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
      *why = egl_err("eglBindAPI(EGL_OPENGL_API)");
      return nullptr;
    }

    // A config is irrelevant (only FBOs are drawn into); use EGL_NO_CONFIG_KHR if possible.
    EGLConfig config = nullptr;  // == EGL_NO_CONFIG_KHR
    if (!has_ext(dpy_exts, "EGL_KHR_no_config_context") &&
        !has_ext(dpy_exts, "EGL_MESA_configless_context")) {
      const EGLint cfg_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
      EGLint n = 0;
      if (!eglChooseConfig(dpy, cfg_attribs, &config, 1, &n) || n < 1) {
        *why = "no EGL config with EGL_OPENGL_BIT";
        return nullptr;
      }
    }

    // Desktop GL 3.3 core (not forward-compatible, so wide lines stay legal); optionally a
    // compatibility-profile context if core is refused.
    const EGLint core_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                   3,
                                   EGL_CONTEXT_MINOR_VERSION,
                                   3,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                   EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                   EGL_NONE};
    const EGLint legacy_attribs[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
    EGLContext ctx = EGL_NO_CONTEXT;
    if (options.compat_profile) {
      ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, legacy_attribs);
      if (ctx == EGL_NO_CONTEXT) {
        *why = egl_err("eglCreateContext(compatibility profile)");
        return nullptr;
      }
      hc->core_ = false;
    } else {
      ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, core_attribs);
    }
    if (ctx == EGL_NO_CONTEXT) {
      const std::string core_err = egl_err("eglCreateContext(3.3 core)");
      if (!options.compat_fallback) {
        *why = core_err;
        return nullptr;
      }
      const EGLint compat_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                                       EGL_NONE};
      ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, compat_attribs);
      if (ctx == EGL_NO_CONTEXT) {
        *why = core_err + "; " + egl_err("eglCreateContext(3.3 compat)");
        return nullptr;
      }
      hc->core_ = false;
    }
    hc->context_ = ctx;
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
      *why = egl_err("eglMakeCurrent(surfaceless)");
      return nullptr;
    }

    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const bool tessel = options.accept_tessel && renderer && std::strstr(renderer, "Tessel");
    if (!renderer || (!std::strstr(renderer, "llvmpipe") && !tessel)) {
      *why = std::string("GL_RENDERER is '") + (renderer ? renderer : "(null)") +
             "', not llvmpipe (check LIBGL_ALWAYS_SOFTWARE / GALLIUM_DRIVER)";
      return nullptr;
    }
    glGetError();  // discard anything left over from context creation
    return hc;
  } catch (const std::exception& e) {
    *why = e.what();
    return nullptr;
  }
}

HeadlessContext::~HeadlessContext() {
  if (display_ == EGL_NO_DISPLAY) return;
  if (context_ != EGL_NO_CONTEXT) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
  }
  release_display();
}

bool HeadlessContext::make_current(std::string* why) const noexcept {
  if (eglGetCurrentContext() == context_) return true;
  if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) return true;
  if (why) {
    try {
      *why = egl_err("eglMakeCurrent");
    } catch (...) {
    }
  }
  return false;
}

std::string HeadlessContext::renderer() const {
  return make_current() ? gl_string(GL_RENDERER) : std::string();
}

std::string HeadlessContext::version() const {
  return make_current() ? gl_string(GL_VERSION) : std::string();
}

unsigned int compile_shader(unsigned int type, const std::string& src) {
  const GLuint s = glCreateShader(type);
  const char* p = src.c_str();
  glShaderSource(s, 1, &p, nullptr);
  glCompileShader(s);
  GLint ok = GL_FALSE;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096] = {0};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    glDeleteShader(s);
    throw std::runtime_error(std::string("shader compile failed: ") + log);
  }
  return s;
}

unsigned int link_program(unsigned int vs, unsigned int fs) {
  const GLuint prog = glCreateProgram();
  glAttachShader(prog, vs);
  glAttachShader(prog, fs);
  glLinkProgram(prog);
  GLint ok = GL_FALSE;
  glGetProgramiv(prog, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {0};
    glGetProgramInfoLog(prog, sizeof log, nullptr, log);
    glDeleteProgram(prog);
    throw std::runtime_error(std::string("program link failed: ") + log);
  }
  return prog;
}

unsigned int build_program(const std::string& vs_src, const std::string& fs_src) {
  const GLuint vs = compile_shader(GL_VERTEX_SHADER, vs_src);
  GLuint fs = 0;
  try {
    fs = compile_shader(GL_FRAGMENT_SHADER, fs_src);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  GLuint prog = 0;
  try {
    prog = link_program(vs, fs);
  } catch (...) {
    glDeleteShader(vs);
    glDeleteShader(fs);
    throw;
  }
  glDeleteShader(vs);  // flagged for deletion; freed with the program
  glDeleteShader(fs);
  return prog;
}

}  // namespace tessel::gl
