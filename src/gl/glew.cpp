// GLEW's API (GL/glew.h) over Tessel's GL: there is nothing to load, so glewInit checks that a
// context is current and sets the flags of the versions and extensions that context has.
#include <GL/glew.h>

#include <cstring>
#include <string>

#include "context.hpp"

namespace {
struct VersionFlag {
  int major, minor;
  GLboolean* flag;
};
struct ExtensionFlag {
  const char* name;
  GLboolean* flag;
};
}  // namespace

extern "C" {

GLboolean glewExperimental = GL_FALSE;
#include "glew_flags.inc"

GLenum glewInit(void) {
  tessel::gl::Context* c = tessel::gl::current();
  if (!c) return GLEW_ERROR_NO_GL_VERSION;
  for (const VersionFlag& v : kVersionFlags)
    *v.flag = v.major < c->major_version || (v.major == c->major_version && v.minor <= c->minor_version);
  for (const ExtensionFlag& e : kExtensionFlags) *e.flag = GL_FALSE;
  for (const char* have : tessel::gl::extensions(*c))
    for (const ExtensionFlag& e : kExtensionFlags)
      if (std::strcmp(e.name, have) == 0) *e.flag = GL_TRUE;
  return GLEW_OK;
}

GLboolean glewGetExtension(const char* name) {
  tessel::gl::Context* c = tessel::gl::current();
  if (!c || !name) return GL_FALSE;
  for (const char* have : tessel::gl::extensions(*c))
    if (std::strcmp(have, name) == 0) return GL_TRUE;
  return GL_FALSE;
}

// "GL_VERSION_3_3" or extension names, separated by spaces: all of them must be there.
GLboolean glewIsSupported(const char* names) {
  tessel::gl::Context* c = tessel::gl::current();
  if (!c || !names) return GL_FALSE;
  const std::string all = names;
  size_t at = 0;
  while (at < all.size()) {
    const size_t end = std::min(all.find(' ', at), all.size());
    const std::string n = all.substr(at, end - at);
    at = end + 1;
    if (n.empty()) continue;
    int major = 0, minor = 0;
    if (std::sscanf(n.c_str(), "GL_VERSION_%d_%d", &major, &minor) == 2) {
      if (major > c->major_version || (major == c->major_version && minor > c->minor_version))
        return GL_FALSE;
    } else if (!glewGetExtension(n.c_str())) {
      return GL_FALSE;
    }
  }
  return GL_TRUE;
}

const GLubyte* glewGetErrorString(GLenum error) {
  switch (error) {
    case GLEW_OK: return reinterpret_cast<const GLubyte*>("No error");
    case GLEW_ERROR_NO_GL_VERSION: return reinterpret_cast<const GLubyte*>("Missing GL version");
    default: return reinterpret_cast<const GLubyte*>("Unknown error");
  }
}

const GLubyte* glewGetString(GLenum name) {
  switch (name) {
    case GLEW_VERSION: return reinterpret_cast<const GLubyte*>("2.2.0 (Tessel)");
    case GLEW_VERSION_MAJOR: return reinterpret_cast<const GLubyte*>("2");
    case GLEW_VERSION_MINOR: return reinterpret_cast<const GLubyte*>("2");
    case GLEW_VERSION_MICRO: return reinterpret_cast<const GLubyte*>("0");
    default: return nullptr;
  }
}

}  // extern "C"
