// The address of a GL entry point by name, for loaders (glad, GLEW's own, SDL's and GLFW's
// GetProcAddress users): glutGetProcAddress, eglGetProcAddress and glfwGetProcAddress answer
// with it. The table lists every entry point of GL 1.0 to 3.3 and their ARB and EXT names
// (proc_names.inc, from the Khronos registry); those Tessel does not define are weak
// references, so their address is null, as a driver's GetProcAddress gives for what it does
// not have.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <algorithm>
#include <cstring>
#include <iterator>

#include "proc_address.hpp"

#define TESSEL_PRAGMA(x) _Pragma(#x)
#define TESSEL_PROC(name) TESSEL_PRAGMA(weak name)
#include "proc_names.inc"
#undef TESSEL_PROC

namespace tessel::gl {

namespace {

struct Proc {
  const char* name;
  void (*address)();
};

#define TESSEL_PROC(name) {#name, reinterpret_cast<void (*)()>(&name)},
const Proc kProcs[] = {
#include "proc_names.inc"
};
#undef TESSEL_PROC

}  // namespace

// The strong references that bring the entry points into a static link (proc_anchors.cpp).
extern void (*const kProcAnchors[])();

void (*proc_address(const char* name))() {
  if (!name) return nullptr;
  [[maybe_unused]] volatile auto keep = &kProcAnchors;
  const auto it = std::lower_bound(std::begin(kProcs), std::end(kProcs), name,
                                   [](const Proc& p, const char* n) { return std::strcmp(p.name, n) < 0; });
  if (it == std::end(kProcs) || std::strcmp(it->name, name) != 0) return nullptr;
  return it->address;
}

void for_each_proc(void (*fn)(const char* name, bool defined)) {
  for (const Proc& p : kProcs) fn(p.name, p.address != nullptr);
}

}  // namespace tessel::gl
