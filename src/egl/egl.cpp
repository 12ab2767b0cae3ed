// EGL 1.5 over Tessel's OpenGL (EGL 1.5 specification, Khronos, 2014): one display on the
// surfaceless platform (EGL_MESA_platform_surfaceless; the default display is the same),
// two configs (RGBA8888 with and without depth/stencil), pbuffer surfaces, desktop OpenGL
// contexts of any version up to 3.3 with the core or compatibility profile, current without
// a surface (EGL_KHR_surfaceless_context), fence syncs, and eglGetProcAddress for every EGL
// and GL entry point. Errors are the ones the specification names, per thread (eglGetError).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "../gl/context.hpp"
#include "../gl/proc_address.hpp"

namespace {

using tessel::gl::Context;

thread_local EGLint t_error = EGL_SUCCESS;
thread_local EGLenum t_api = EGL_OPENGL_API;

template <class T>
T fail(EGLint e, T result) {
  t_error = e;
  return result;
}
EGLBoolean fail(EGLint e) { return fail(e, EGLBoolean(EGL_FALSE)); }
template <class T>
T ok(T result) {
  t_error = EGL_SUCCESS;
  return result;
}

struct Config {
  EGLint id, depth, stencil;
};
// Both render with OpenGL into pbuffers; the first has depth and stencil.
constexpr Config kConfigs[] = {{1, 24, 8}, {2, 0, 0}};
constexpr int kMaxPbufferSize = 8192;

struct Surface {
  const Config* config;
  int width, height;
  bool current = false, destroyed = false;
};

struct ContextObject {
  const Config* config;  // null: EGL_NO_CONFIG_KHR
  int major, minor;
  bool core;
  std::unique_ptr<Context> gl;
  Surface* draw = nullptr;
  bool current = false, destroyed = false;
  bool ever_drawn = false;  // made current with a surface before
};

struct Sync {
  EGLenum type;
};

// The one display. Objects are handles to heap objects the display owns; a handle is valid
// while the display lists it.
struct Display {
  std::mutex mutex;
  bool initialized = false;
  std::set<ContextObject*> contexts;
  std::set<Surface*> surfaces;
  std::set<Sync*> syncs;
};
Display g_display;
const EGLDisplay kDisplay = reinterpret_cast<EGLDisplay>(&g_display);

thread_local ContextObject* t_context = nullptr;

Display* display_of(EGLDisplay dpy) { return dpy == kDisplay ? &g_display : nullptr; }

// The display of a call that needs it initialized; sets the error otherwise.
Display* initialized(EGLDisplay dpy) {
  Display* d = display_of(dpy);
  if (!d) return fail(EGL_BAD_DISPLAY, static_cast<Display*>(nullptr));
  if (!d->initialized) return fail(EGL_NOT_INITIALIZED, static_cast<Display*>(nullptr));
  return d;
}

const Config* config_of(EGLConfig c) {
  for (const Config& k : kConfigs)
    if (reinterpret_cast<EGLConfig>(const_cast<Config*>(&k)) == c) return &k;
  return nullptr;
}
EGLConfig handle(const Config& c) { return reinterpret_cast<EGLConfig>(const_cast<Config*>(&c)); }

bool config_attrib(const Config& c, EGLint attr, EGLint& v) {
  switch (attr) {
    case EGL_BUFFER_SIZE: v = 32; return true;
    case EGL_RED_SIZE:
    case EGL_GREEN_SIZE:
    case EGL_BLUE_SIZE:
    case EGL_ALPHA_SIZE: v = 8; return true;
    case EGL_LUMINANCE_SIZE:
    case EGL_ALPHA_MASK_SIZE:
    case EGL_LEVEL:
    case EGL_NATIVE_VISUAL_ID:
    case EGL_NATIVE_VISUAL_TYPE:
    case EGL_SAMPLES:
    case EGL_SAMPLE_BUFFERS:
    case EGL_MIN_SWAP_INTERVAL:
    case EGL_MAX_SWAP_INTERVAL:
    case EGL_TRANSPARENT_RED_VALUE:
    case EGL_TRANSPARENT_GREEN_VALUE:
    case EGL_TRANSPARENT_BLUE_VALUE: v = 0; return true;
    case EGL_DEPTH_SIZE: v = c.depth; return true;
    case EGL_STENCIL_SIZE: v = c.stencil; return true;
    case EGL_CONFIG_ID: v = c.id; return true;
    case EGL_CONFIG_CAVEAT: v = EGL_NONE; return true;
    case EGL_COLOR_BUFFER_TYPE: v = EGL_RGB_BUFFER; return true;
    case EGL_SURFACE_TYPE: v = EGL_PBUFFER_BIT; return true;
    case EGL_RENDERABLE_TYPE:
    case EGL_CONFORMANT: v = EGL_OPENGL_BIT; return true;
    case EGL_NATIVE_RENDERABLE:
    case EGL_BIND_TO_TEXTURE_RGB:
    case EGL_BIND_TO_TEXTURE_RGBA: v = EGL_FALSE; return true;
    case EGL_TRANSPARENT_TYPE: v = EGL_NONE; return true;
    case EGL_MAX_PBUFFER_WIDTH:
    case EGL_MAX_PBUFFER_HEIGHT: v = kMaxPbufferSize; return true;
    case EGL_MAX_PBUFFER_PIXELS: v = kMaxPbufferSize * kMaxPbufferSize; return true;
    default: return false;
  }
}

// EGL 1.5 §3.4.1.2: which configs match the attributes, and in what order.
bool choose(const EGLint* attribs, std::vector<const Config*>& out, EGLint& error) {
  out.clear();
  struct Want {
    EGLint attr, value;
  };
  std::vector<Want> wants;
  for (const EGLint* a = attribs; a && *a != EGL_NONE; a += 2) {
    EGLint probe;
    if (!config_attrib(kConfigs[0], a[0], probe) && a[0] != EGL_MATCH_NATIVE_PIXMAP) {
      error = EGL_BAD_ATTRIBUTE;
      return false;
    }
    wants.push_back({a[0], a[1]});
  }
  for (const Config& c : kConfigs) {
    bool match = true;
    for (const Want& w : wants) {
      if (w.value == EGL_DONT_CARE) continue;
      EGLint v = 0;
      if (!config_attrib(c, w.attr, v)) continue;
      switch (w.attr) {
        case EGL_SURFACE_TYPE:
        case EGL_RENDERABLE_TYPE:
        case EGL_CONFORMANT: match = match && (v & w.value) == w.value; break;
        case EGL_CONFIG_ID:
        case EGL_CONFIG_CAVEAT:
        case EGL_COLOR_BUFFER_TYPE:
        case EGL_LEVEL:
        case EGL_TRANSPARENT_TYPE:
        case EGL_NATIVE_RENDERABLE:
        case EGL_BIND_TO_TEXTURE_RGB:
        case EGL_BIND_TO_TEXTURE_RGBA:
        case EGL_NATIVE_VISUAL_TYPE:
        case EGL_MIN_SWAP_INTERVAL:
        case EGL_MAX_SWAP_INTERVAL: match = match && v == w.value; break;
        case EGL_MAX_PBUFFER_WIDTH:
        case EGL_MAX_PBUFFER_HEIGHT:
        case EGL_MAX_PBUFFER_PIXELS:
        case EGL_NATIVE_VISUAL_ID: break;  // ignored in matching (Table 3.4)
        default: match = match && v >= w.value; break;
      }
    }
    if (match) out.push_back(&c);
  }
  // Sorted by depth and stencil sizes ascending (§3.4.1.2, rule 7), then by config id.
  std::stable_sort(out.begin(), out.end(), [](const Config* a, const Config* b) {
    if (a->depth != b->depth) return a->depth < b->depth;
    return a->id < b->id;
  });
  return true;
}

ContextObject* context_of(Display& d, EGLContext c) {
  auto* p = static_cast<ContextObject*>(c);
  return d.contexts.count(p) ? p : nullptr;
}
Surface* surface_of(Display& d, EGLSurface s) {
  auto* p = static_cast<Surface*>(s);
  return d.surfaces.count(p) ? p : nullptr;
}

// Frees what was destroyed (or terminated) once it is no longer current.
void collect(Display& d) {
  for (auto it = d.contexts.begin(); it != d.contexts.end();) {
    if ((*it)->destroyed && !(*it)->current) {
      delete *it;
      it = d.contexts.erase(it);
    } else {
      ++it;
    }
  }
  for (auto it = d.surfaces.begin(); it != d.surfaces.end();) {
    if ((*it)->destroyed && !(*it)->current) {
      delete *it;
      it = d.surfaces.erase(it);
    } else {
      ++it;
    }
  }
}

void release_current(Display& d) {
  ContextObject* c = t_context;
  if (!c) return;
  if (c->gl) c->gl->finish();
  c->current = false;
  if (c->draw) c->draw->current = false;
  c->draw = nullptr;
  t_context = nullptr;
  tessel::gl::make_current(nullptr);
  collect(d);
}

const char* kClientExtensions =
    "EGL_EXT_client_extensions EGL_EXT_platform_base EGL_KHR_client_get_all_proc_addresses "
    "EGL_MESA_platform_surfaceless";
const char* kDisplayExtensions =
    "EGL_KHR_create_context EGL_KHR_fence_sync EGL_KHR_get_all_proc_addresses EGL_KHR_no_config_context "
    "EGL_KHR_surfaceless_context EGL_MESA_configless_context";

EGLDisplay platform_display(EGLenum platform, void* native, bool attrib_ok) {
  if (!attrib_ok) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_DISPLAY);
  if (platform != EGL_PLATFORM_SURFACELESS_MESA) return fail(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);
  if (native != EGL_DEFAULT_DISPLAY) return fail(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);
  return ok(kDisplay);
}

}  // namespace

extern "C" {

EGLint EGLAPIENTRY eglGetError(void) {
  const EGLint e = t_error;
  t_error = EGL_SUCCESS;
  return e;
}

EGLDisplay EGLAPIENTRY eglGetDisplay(EGLNativeDisplayType native) {
  // Only the default display: Tessel draws without a window system.
  if (native != EGL_DEFAULT_DISPLAY) return fail(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);
  return ok(kDisplay);
}
EGLDisplay EGLAPIENTRY eglGetPlatformDisplay(EGLenum platform, void* native, const EGLAttrib* attribs) {
  return platform_display(platform, native, !attribs || attribs[0] == EGL_NONE);
}
EGLDisplay EGLAPIENTRY eglGetPlatformDisplayEXT(EGLenum platform, void* native, const EGLint* attribs) {
  return platform_display(platform, native, !attribs || attribs[0] == EGL_NONE);
}

EGLBoolean EGLAPIENTRY eglInitialize(EGLDisplay dpy, EGLint* major, EGLint* minor) {
  Display* d = display_of(dpy);
  if (!d) return fail(EGL_BAD_DISPLAY);
  std::lock_guard<std::mutex> lock(d->mutex);
  d->initialized = true;
  if (major) *major = 1;
  if (minor) *minor = 5;
  return ok(EGLBoolean(EGL_TRUE));
}

EGLBoolean EGLAPIENTRY eglTerminate(EGLDisplay dpy) {
  Display* d = display_of(dpy);
  if (!d) return fail(EGL_BAD_DISPLAY);
  std::lock_guard<std::mutex> lock(d->mutex);
  // Every object is marked for deletion; current ones go when they stop being current.
  for (ContextObject* c : d->contexts) c->destroyed = true;
  for (Surface* s : d->surfaces) s->destroyed = true;
  for (Sync* s : d->syncs) delete s;
  d->syncs.clear();
  collect(*d);
  d->initialized = false;
  return ok(EGLBoolean(EGL_TRUE));
}

const char* EGLAPIENTRY eglQueryString(EGLDisplay dpy, EGLint name) {
  if (dpy == EGL_NO_DISPLAY) {
    if (name == EGL_EXTENSIONS) return ok(kClientExtensions);
    if (name == EGL_VERSION) return ok("1.5");
    return fail(EGL_BAD_DISPLAY, static_cast<const char*>(nullptr));
  }
  if (!initialized(dpy)) return nullptr;
  switch (name) {
    case EGL_VENDOR: return ok("Tessel");
    case EGL_VERSION: return ok("1.5 Tessel");
    case EGL_CLIENT_APIS: return ok("OpenGL");
    case EGL_EXTENSIONS: return ok(kDisplayExtensions);
    default: return fail(EGL_BAD_PARAMETER, static_cast<const char*>(nullptr));
  }
}

EGLBoolean EGLAPIENTRY eglGetConfigs(EGLDisplay dpy, EGLConfig* configs, EGLint size, EGLint* num) {
  if (!initialized(dpy)) return EGL_FALSE;
  if (!num) return fail(EGL_BAD_PARAMETER);
  EGLint n = 0;
  for (const Config& c : kConfigs) {
    if (configs && n >= size) break;
    if (configs) configs[n] = handle(c);
    ++n;
  }
  *num = n;
  return ok(EGLBoolean(EGL_TRUE));
}

EGLBoolean EGLAPIENTRY eglChooseConfig(EGLDisplay dpy, const EGLint* attribs, EGLConfig* configs, EGLint size,
                                       EGLint* num) {
  if (!initialized(dpy)) return EGL_FALSE;
  if (!num) return fail(EGL_BAD_PARAMETER);
  std::vector<const Config*> found;
  EGLint error = EGL_SUCCESS;
  if (!choose(attribs, found, error)) return fail(error);
  EGLint n = 0;
  for (const Config* c : found) {
    if (configs && n >= size) break;
    if (configs) configs[n] = handle(*c);
    ++n;
  }
  *num = n;
  return ok(EGLBoolean(EGL_TRUE));
}

EGLBoolean EGLAPIENTRY eglGetConfigAttrib(EGLDisplay dpy, EGLConfig config, EGLint attr, EGLint* value) {
  if (!initialized(dpy)) return EGL_FALSE;
  const Config* c = config_of(config);
  if (!c) return fail(EGL_BAD_CONFIG);
  EGLint v = 0;
  if (!config_attrib(*c, attr, v)) return fail(EGL_BAD_ATTRIBUTE);
  if (value) *value = v;
  return ok(EGLBoolean(EGL_TRUE));
}

EGLSurface EGLAPIENTRY eglCreatePbufferSurface(EGLDisplay dpy, EGLConfig config, const EGLint* attribs) {
  Display* d = initialized(dpy);
  if (!d) return EGL_NO_SURFACE;
  const Config* c = config_of(config);
  if (!c) return fail(EGL_BAD_CONFIG, EGL_NO_SURFACE);
  int w = 0, h = 0;
  for (const EGLint* a = attribs; a && *a != EGL_NONE; a += 2) {
    switch (a[0]) {
      case EGL_WIDTH: w = a[1]; break;
      case EGL_HEIGHT: h = a[1]; break;
      case EGL_LARGEST_PBUFFER:
      case EGL_TEXTURE_FORMAT:
      case EGL_TEXTURE_TARGET:
      case EGL_MIPMAP_TEXTURE:
      case EGL_GL_COLORSPACE:
      case EGL_VG_ALPHA_FORMAT:
      case EGL_VG_COLORSPACE: break;
      default: return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SURFACE);
    }
  }
  if (w < 0 || h < 0) return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
  if (w > kMaxPbufferSize || h > kMaxPbufferSize) return fail(EGL_BAD_ALLOC, EGL_NO_SURFACE);
  std::lock_guard<std::mutex> lock(d->mutex);
  auto* s = new Surface{c, w, h};
  d->surfaces.insert(s);
  return ok(static_cast<EGLSurface>(s));
}
// No window system: window and pixmap surfaces are not supported by any config (EGL_BAD_MATCH).
EGLSurface EGLAPIENTRY eglCreateWindowSurface(EGLDisplay dpy, EGLConfig config, EGLNativeWindowType,
                                              const EGLint*) {
  if (!initialized(dpy)) return EGL_NO_SURFACE;
  if (!config_of(config)) return fail(EGL_BAD_CONFIG, EGL_NO_SURFACE);
  return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
}
EGLSurface EGLAPIENTRY eglCreatePlatformWindowSurface(EGLDisplay dpy, EGLConfig config, void*,
                                                      const EGLAttrib*) {
  return eglCreateWindowSurface(dpy, config, 0, nullptr);
}
EGLSurface EGLAPIENTRY eglCreatePixmapSurface(EGLDisplay dpy, EGLConfig config, EGLNativePixmapType,
                                              const EGLint*) {
  return eglCreateWindowSurface(dpy, config, 0, nullptr);
}
EGLSurface EGLAPIENTRY eglCreatePlatformPixmapSurface(EGLDisplay dpy, EGLConfig config, void*,
                                                      const EGLAttrib*) {
  return eglCreateWindowSurface(dpy, config, 0, nullptr);
}
EGLSurface EGLAPIENTRY eglCreatePbufferFromClientBuffer(EGLDisplay dpy, EGLenum, EGLClientBuffer,
                                                        EGLConfig config, const EGLint*) {
  if (!initialized(dpy)) return EGL_NO_SURFACE;
  if (!config_of(config)) return fail(EGL_BAD_CONFIG, EGL_NO_SURFACE);
  return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
}

EGLBoolean EGLAPIENTRY eglDestroySurface(EGLDisplay dpy, EGLSurface surface) {
  Display* d = initialized(dpy);
  if (!d) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(d->mutex);
  Surface* s = surface_of(*d, surface);
  if (!s || s->destroyed) return fail(EGL_BAD_SURFACE);
  s->destroyed = true;
  collect(*d);
  return ok(EGLBoolean(EGL_TRUE));
}

EGLBoolean EGLAPIENTRY eglQuerySurface(EGLDisplay dpy, EGLSurface surface, EGLint attr, EGLint* value) {
  Display* d = initialized(dpy);
  if (!d) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(d->mutex);
  Surface* s = surface_of(*d, surface);
  if (!s) return fail(EGL_BAD_SURFACE);
  EGLint v = 0;
  switch (attr) {
    case EGL_WIDTH: v = s->width; break;
    case EGL_HEIGHT: v = s->height; break;
    case EGL_CONFIG_ID: v = s->config->id; break;
    case EGL_LARGEST_PBUFFER:
    case EGL_MIPMAP_TEXTURE:
    case EGL_MIPMAP_LEVEL: v = 0; break;
    case EGL_TEXTURE_FORMAT:
    case EGL_TEXTURE_TARGET: v = EGL_NO_TEXTURE; break;
    case EGL_RENDER_BUFFER: v = EGL_BACK_BUFFER; break;
    case EGL_SWAP_BEHAVIOR: v = EGL_BUFFER_PRESERVED; break;
    case EGL_MULTISAMPLE_RESOLVE: v = EGL_MULTISAMPLE_RESOLVE_DEFAULT; break;
    case EGL_GL_COLORSPACE: v = EGL_GL_COLORSPACE_LINEAR; break;
    case EGL_HORIZONTAL_RESOLUTION:
    case EGL_VERTICAL_RESOLUTION:
    case EGL_PIXEL_ASPECT_RATIO: v = EGL_UNKNOWN; break;
    default: return fail(EGL_BAD_ATTRIBUTE);
  }
  if (value) *value = v;
  return ok(EGLBoolean(EGL_TRUE));
}
EGLBoolean EGLAPIENTRY eglSurfaceAttrib(EGLDisplay dpy, EGLSurface surface, EGLint attr, EGLint) {
  Display* d = initialized(dpy);
  if (!d) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(d->mutex);
  if (!surface_of(*d, surface)) return fail(EGL_BAD_SURFACE);
  if (attr != EGL_SWAP_BEHAVIOR && attr != EGL_MIPMAP_LEVEL && attr != EGL_MULTISAMPLE_RESOLVE)
    return fail(EGL_BAD_ATTRIBUTE);
  return ok(EGLBoolean(EGL_TRUE));
}
EGLBoolean EGLAPIENTRY eglBindTexImage(EGLDisplay dpy, EGLSurface, EGLint) {
  if (!initialized(dpy)) return EGL_FALSE;
  return fail(EGL_BAD_MATCH);  // no config binds to textures
}
EGLBoolean EGLAPIENTRY eglReleaseTexImage(EGLDisplay dpy, EGLSurface, EGLint) {
  if (!initialized(dpy)) return EGL_FALSE;
  return fail(EGL_BAD_MATCH);
}

EGLBoolean EGLAPIENTRY eglBindAPI(EGLenum api) {
  // Desktop OpenGL only: OpenGL ES and OpenVG are not there (EGL_CLIENT_APIS says so).
  if (api != EGL_OPENGL_API) return fail(EGL_BAD_PARAMETER);
  t_api = api;
  return ok(EGLBoolean(EGL_TRUE));
}
EGLenum EGLAPIENTRY eglQueryAPI(void) { return ok(t_api); }

EGLContext EGLAPIENTRY eglCreateContext(EGLDisplay dpy, EGLConfig config, EGLContext share,
                                        const EGLint* attribs) {
  Display* d = initialized(dpy);
  if (!d) return EGL_NO_CONTEXT;
  const Config* c = nullptr;
  if (config != EGL_NO_CONFIG_KHR) {
    c = config_of(config);
    if (!c) return fail(EGL_BAD_CONFIG, EGL_NO_CONTEXT);
  }
  if (t_api != EGL_OPENGL_API) return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
  int major = 1, minor = 0;
  EGLint profile = EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT;
  for (const EGLint* a = attribs; a && *a != EGL_NONE; a += 2) {
    switch (a[0]) {
      case EGL_CONTEXT_MAJOR_VERSION: major = a[1]; break;
      case EGL_CONTEXT_MINOR_VERSION: minor = a[1]; break;
      case EGL_CONTEXT_OPENGL_PROFILE_MASK: profile = a[1]; break;
      case EGL_CONTEXT_OPENGL_DEBUG:
      case EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE:
      case EGL_CONTEXT_OPENGL_ROBUST_ACCESS:
      case EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY:
      case EGL_CONTEXT_FLAGS_KHR: break;
      default: return fail(EGL_BAD_ATTRIBUTE, EGL_NO_CONTEXT);
    }
  }
  if (major < 1 || minor < 0 || (major == 1 && minor > 5) || (major == 2 && minor > 1) || major > 4)
    return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
  // Versions above 3.3 are not there (EGL 1.5 §3.7.1.1: EGL_BAD_MATCH).
  if (major > 3 || (major == 3 && minor > 3)) return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
  if (profile & ~(EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT | EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT))
    return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
  std::lock_guard<std::mutex> lock(d->mutex);
  if (share != EGL_NO_CONTEXT) {
    // Contexts keep their objects to themselves: sharing is not supported.
    if (!context_of(*d, share)) return fail(EGL_BAD_CONTEXT, EGL_NO_CONTEXT);
    return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
  }
  // Profiles exist from 3.2; below it (and for the compatibility bit) a compatibility context.
  const bool profiles = major > 3 || (major == 3 && minor >= 2);
  const bool core = profiles && (profile & EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT) != 0;
  auto* ctx = new ContextObject{c, major, minor, core, nullptr};
  try {
    const bool depth = !c || c->depth > 0;
    // Pbuffers are back buffers (EGL_RENDER_BUFFER is EGL_BACK_BUFFER): GL_BACK is the buffer drawn and read.
    ctx->gl = std::make_unique<Context>(1, 1, true, depth, depth);
    // 1.x and 2.x requests get the default 2.1 compatibility context; 3.x what was asked.
    if (major >= 3) ctx->gl->set_version(major, minor, core);
    // The rendering threads: TESSEL_THREADS, else llvmpipe's LP_NUM_THREADS (0 there means
    // none besides the caller's: one here), else one per hardware thread.
    // TESSEL_THREADS=0 keeps one per hardware thread; at most gpu's limit of 64.
    const char* tessel_threads = std::getenv("TESSEL_THREADS");
    const char* lp_threads = std::getenv("LP_NUM_THREADS");
    long n = -1;
    if (tessel_threads && *tessel_threads)
      n = std::strtol(tessel_threads, nullptr, 10);
    else if (lp_threads && *lp_threads)
      n = std::max(1L, std::strtol(lp_threads, nullptr, 10));
    if (n > 0) ctx->gl->gpu().set_threads(int(std::min(n, 64L)));
  } catch (const std::exception&) {
    delete ctx;
    return fail(EGL_BAD_ALLOC, EGL_NO_CONTEXT);
  }
  d->contexts.insert(ctx);
  return ok(static_cast<EGLContext>(ctx));
}

EGLBoolean EGLAPIENTRY eglDestroyContext(EGLDisplay dpy, EGLContext context) {
  Display* d = initialized(dpy);
  if (!d) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(d->mutex);
  ContextObject* c = context_of(*d, context);
  if (!c || c->destroyed) return fail(EGL_BAD_CONTEXT);
  c->destroyed = true;
  collect(*d);
  return ok(EGLBoolean(EGL_TRUE));
}

EGLBoolean EGLAPIENTRY eglMakeCurrent(EGLDisplay dpy, EGLSurface draw, EGLSurface read, EGLContext context) {
  Display* d = display_of(dpy);
  if (!d) return fail(EGL_BAD_DISPLAY);
  std::lock_guard<std::mutex> lock(d->mutex);
  if (context == EGL_NO_CONTEXT) {
    if (draw != EGL_NO_SURFACE || read != EGL_NO_SURFACE) return fail(EGL_BAD_MATCH);
    release_current(*d);
    return ok(EGLBoolean(EGL_TRUE));
  }
  if (!d->initialized) return fail(EGL_NOT_INITIALIZED);
  ContextObject* c = context_of(*d, context);
  if (!c || c->destroyed) return fail(EGL_BAD_CONTEXT);
  if (c->current && c != t_context) return fail(EGL_BAD_ACCESS);  // current in another thread
  Surface* s = nullptr;
  if (draw != EGL_NO_SURFACE || read != EGL_NO_SURFACE) {
    s = surface_of(*d, draw);
    if (!s || s->destroyed || surface_of(*d, read) != s) return fail(EGL_BAD_SURFACE);
    if (c->config && s->config != c->config) return fail(EGL_BAD_MATCH);
    // Current in another thread's context (not this thread's, which is released below).
    const bool ours = t_context && t_context->draw == s;
    if (s->current && s != c->draw && !ours) return fail(EGL_BAD_ACCESS);
  }
  if (t_context && t_context != c) release_current(*d);
  if (c->draw && c->draw != s) c->draw->current = false;
  c->current = true;
  c->draw = s;
  c->gl->has_default_framebuffer = s != nullptr;
  if (s) {
    s->current = true;
    // The context's default framebuffer is the surface's size (surfaceless: 1x1, never shown).
    c->gl->resize(std::max(s->width, 1), std::max(s->height, 1));
    // EGL 1.5 §3.7.3: the first surface a context draws to sets its viewport and scissor box.
    if (!c->ever_drawn) {
      c->ever_drawn = true;
      c->gl->s.viewport = {0, 0, s->width, s->height, 0.0, 1.0};
      c->gl->s.scissor = {false, 0, 0, s->width, s->height};
    }
  }
  t_context = c;
  tessel::gl::make_current(c->gl.get());
  collect(*d);
  return ok(EGLBoolean(EGL_TRUE));
}

EGLContext EGLAPIENTRY eglGetCurrentContext(void) { return ok(static_cast<EGLContext>(t_context)); }
EGLDisplay EGLAPIENTRY eglGetCurrentDisplay(void) { return ok(t_context ? kDisplay : EGL_NO_DISPLAY); }
EGLSurface EGLAPIENTRY eglGetCurrentSurface(EGLint which) {
  if (which != EGL_DRAW && which != EGL_READ) return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
  return ok(t_context && t_context->draw ? static_cast<EGLSurface>(t_context->draw) : EGL_NO_SURFACE);
}

EGLBoolean EGLAPIENTRY eglQueryContext(EGLDisplay dpy, EGLContext context, EGLint attr, EGLint* value) {
  Display* d = initialized(dpy);
  if (!d) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(d->mutex);
  ContextObject* c = context_of(*d, context);
  if (!c) return fail(EGL_BAD_CONTEXT);
  EGLint v = 0;
  switch (attr) {
    case EGL_CONFIG_ID: v = c->config ? c->config->id : 0; break;
    case EGL_CONTEXT_CLIENT_TYPE: v = EGL_OPENGL_API; break;
    case EGL_CONTEXT_CLIENT_VERSION: v = c->major; break;
    case EGL_RENDER_BUFFER: v = c->draw ? EGL_BACK_BUFFER : EGL_NONE; break;
    default: return fail(EGL_BAD_ATTRIBUTE);
  }
  if (value) *value = v;
  return ok(EGLBoolean(EGL_TRUE));
}

EGLBoolean EGLAPIENTRY eglSwapBuffers(EGLDisplay dpy, EGLSurface surface) {
  Display* d = initialized(dpy);
  if (!d) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(d->mutex);
  Surface* s = surface_of(*d, surface);
  if (!s) return fail(EGL_BAD_SURFACE);
  if (!t_context || t_context->draw != s) return fail(EGL_BAD_SURFACE);
  t_context->gl->finish();  // a pbuffer has one buffer: nothing is swapped
  return ok(EGLBoolean(EGL_TRUE));
}
EGLBoolean EGLAPIENTRY eglCopyBuffers(EGLDisplay dpy, EGLSurface, EGLNativePixmapType) {
  if (!initialized(dpy)) return EGL_FALSE;
  return fail(EGL_BAD_NATIVE_PIXMAP);
}
EGLBoolean EGLAPIENTRY eglSwapInterval(EGLDisplay dpy, EGLint) {
  if (!initialized(dpy)) return EGL_FALSE;
  if (!t_context) return fail(EGL_BAD_CONTEXT);
  return ok(EGLBoolean(EGL_TRUE));
}

EGLBoolean EGLAPIENTRY eglWaitClient(void) {
  if (t_context) t_context->gl->finish();
  return ok(EGLBoolean(EGL_TRUE));
}
EGLBoolean EGLAPIENTRY eglWaitGL(void) { return eglWaitClient(); }
EGLBoolean EGLAPIENTRY eglWaitNative(EGLint engine) {
  if (engine != EGL_CORE_NATIVE_ENGINE) return fail(EGL_BAD_PARAMETER);
  return ok(EGLBoolean(EGL_TRUE));
}
EGLBoolean EGLAPIENTRY eglReleaseThread(void) {
  std::lock_guard<std::mutex> lock(g_display.mutex);
  release_current(g_display);
  t_api = EGL_OPENGL_API;
  return ok(EGLBoolean(EGL_TRUE));
}

// Fence syncs (EGL 1.5 §3.8.1): GL commands run in order, so a fence is signaled once the
// context has finished the work before it; eglCreateSync finishes it.
EGLSync EGLAPIENTRY eglCreateSync(EGLDisplay dpy, EGLenum type, const EGLAttrib* attribs) {
  Display* d = initialized(dpy);
  if (!d) return EGL_NO_SYNC;
  if (type != EGL_SYNC_FENCE) return fail(EGL_BAD_PARAMETER, EGL_NO_SYNC);
  if (attribs && attribs[0] != EGL_NONE) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SYNC);
  if (!t_context) return fail(EGL_BAD_MATCH, EGL_NO_SYNC);
  t_context->gl->finish();
  std::lock_guard<std::mutex> lock(d->mutex);
  auto* s = new Sync{type};
  d->syncs.insert(s);
  return ok(static_cast<EGLSync>(s));
}
EGLSyncKHR EGLAPIENTRY eglCreateSyncKHR(EGLDisplay dpy, EGLenum type, const EGLint* attribs) {
  if (attribs && attribs[0] != EGL_NONE) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SYNC_KHR);
  return eglCreateSync(dpy, type, nullptr);
}
EGLBoolean EGLAPIENTRY eglDestroySync(EGLDisplay dpy, EGLSync sync) {
  Display* d = initialized(dpy);
  if (!d) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(d->mutex);
  auto* s = static_cast<Sync*>(sync);
  if (!d->syncs.count(s)) return fail(EGL_BAD_PARAMETER);
  d->syncs.erase(s);
  delete s;
  return ok(EGLBoolean(EGL_TRUE));
}
EGLBoolean EGLAPIENTRY eglDestroySyncKHR(EGLDisplay dpy, EGLSyncKHR sync) {
  return eglDestroySync(dpy, sync);
}
EGLint EGLAPIENTRY eglClientWaitSync(EGLDisplay dpy, EGLSync sync, EGLint, EGLTime) {
  Display* d = initialized(dpy);
  if (!d) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(d->mutex);
  if (!d->syncs.count(static_cast<Sync*>(sync))) return fail(EGL_BAD_PARAMETER, EGLint(EGL_FALSE));
  return ok(EGLint(EGL_CONDITION_SATISFIED));
}
EGLint EGLAPIENTRY eglClientWaitSyncKHR(EGLDisplay dpy, EGLSyncKHR sync, EGLint flags, EGLTimeKHR timeout) {
  return eglClientWaitSync(dpy, sync, flags, timeout);
}
EGLBoolean EGLAPIENTRY eglWaitSync(EGLDisplay dpy, EGLSync sync, EGLint flags) {
  Display* d = initialized(dpy);
  if (!d) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(d->mutex);
  if (!d->syncs.count(static_cast<Sync*>(sync))) return fail(EGL_BAD_PARAMETER);
  if (flags != 0) return fail(EGL_BAD_PARAMETER);
  return ok(EGLBoolean(EGL_TRUE));
}
EGLBoolean EGLAPIENTRY eglGetSyncAttrib(EGLDisplay dpy, EGLSync sync, EGLint attr, EGLAttrib* value) {
  Display* d = initialized(dpy);
  if (!d) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(d->mutex);
  auto* s = static_cast<Sync*>(sync);
  if (!d->syncs.count(s)) return fail(EGL_BAD_PARAMETER);
  EGLAttrib v;
  switch (attr) {
    case EGL_SYNC_TYPE: v = s->type; break;
    case EGL_SYNC_STATUS: v = EGL_SIGNALED; break;
    case EGL_SYNC_CONDITION: v = EGL_SYNC_PRIOR_COMMANDS_COMPLETE; break;
    default: return fail(EGL_BAD_ATTRIBUTE);
  }
  if (value) *value = v;
  return ok(EGLBoolean(EGL_TRUE));
}
EGLBoolean EGLAPIENTRY eglGetSyncAttribKHR(EGLDisplay dpy, EGLSyncKHR sync, EGLint attr, EGLint* value) {
  EGLAttrib v = 0;
  if (!eglGetSyncAttrib(dpy, sync, attr, &v)) return EGL_FALSE;
  if (value) *value = EGLint(v);
  return EGL_TRUE;
}

// EGLImages need a client buffer or a native pixmap: none can be made here.
EGLImage EGLAPIENTRY eglCreateImage(EGLDisplay dpy, EGLContext, EGLenum, EGLClientBuffer, const EGLAttrib*) {
  if (!initialized(dpy)) return EGL_NO_IMAGE;
  return fail(EGL_BAD_PARAMETER, EGL_NO_IMAGE);
}
EGLBoolean EGLAPIENTRY eglDestroyImage(EGLDisplay dpy, EGLImage) {
  if (!initialized(dpy)) return EGL_FALSE;
  return fail(EGL_BAD_PARAMETER);
}

__eglMustCastToProperFunctionPointerType EGLAPIENTRY eglGetProcAddress(const char* name);

}  // extern "C"

namespace {

struct EglProc {
  const char* name;
  __eglMustCastToProperFunctionPointerType fn;
};
#define EGL_PROC(f) \
  { #f, reinterpret_cast < __eglMustCastToProperFunctionPointerType>(&f) }
const EglProc kEglProcs[] = {
    EGL_PROC(eglBindAPI),
    EGL_PROC(eglBindTexImage),
    EGL_PROC(eglChooseConfig),
    EGL_PROC(eglClientWaitSync),
    EGL_PROC(eglClientWaitSyncKHR),
    EGL_PROC(eglCopyBuffers),
    EGL_PROC(eglCreateContext),
    EGL_PROC(eglCreateImage),
    EGL_PROC(eglCreatePbufferFromClientBuffer),
    EGL_PROC(eglCreatePbufferSurface),
    EGL_PROC(eglCreatePixmapSurface),
    EGL_PROC(eglCreatePlatformPixmapSurface),
    EGL_PROC(eglCreatePlatformWindowSurface),
    EGL_PROC(eglCreateSync),
    EGL_PROC(eglCreateSyncKHR),
    EGL_PROC(eglCreateWindowSurface),
    EGL_PROC(eglDestroyContext),
    EGL_PROC(eglDestroyImage),
    EGL_PROC(eglDestroySurface),
    EGL_PROC(eglDestroySync),
    EGL_PROC(eglDestroySyncKHR),
    EGL_PROC(eglGetConfigAttrib),
    EGL_PROC(eglGetConfigs),
    EGL_PROC(eglGetCurrentContext),
    EGL_PROC(eglGetCurrentDisplay),
    EGL_PROC(eglGetCurrentSurface),
    EGL_PROC(eglGetDisplay),
    EGL_PROC(eglGetError),
    EGL_PROC(eglGetPlatformDisplay),
    EGL_PROC(eglGetPlatformDisplayEXT),
    EGL_PROC(eglGetProcAddress),
    EGL_PROC(eglGetSyncAttrib),
    EGL_PROC(eglGetSyncAttribKHR),
    EGL_PROC(eglInitialize),
    EGL_PROC(eglMakeCurrent),
    EGL_PROC(eglQueryAPI),
    EGL_PROC(eglQueryContext),
    EGL_PROC(eglQueryString),
    EGL_PROC(eglQuerySurface),
    EGL_PROC(eglReleaseTexImage),
    EGL_PROC(eglReleaseThread),
    EGL_PROC(eglSurfaceAttrib),
    EGL_PROC(eglSwapBuffers),
    EGL_PROC(eglSwapInterval),
    EGL_PROC(eglTerminate),
    EGL_PROC(eglWaitClient),
    EGL_PROC(eglWaitGL),
    EGL_PROC(eglWaitNative),
    EGL_PROC(eglWaitSync),
};
#undef EGL_PROC

}  // namespace

extern "C" __eglMustCastToProperFunctionPointerType EGLAPIENTRY eglGetProcAddress(const char* name) {
  if (!name) return nullptr;
  for (const EglProc& p : kEglProcs)
    if (std::strcmp(p.name, name) == 0) return p.fn;
  // Every GL entry point Tessel defines (EGL_KHR_get_all_proc_addresses).
  return reinterpret_cast<__eglMustCastToProperFunctionPointerType>(tessel::gl::proc_address(name));
}
