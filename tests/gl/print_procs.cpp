// Prints the GL entry points whose address glutGetProcAddress-style lookups give, one a line
// (tests/gl/proc_table_check.cmake compares them with the library's defined symbols).
#include <cstdio>

#include "../../src/gl/proc_address.hpp"

int main() {
  tessel::gl::for_each_proc([](const char* name, bool defined) {
    if (defined) std::printf("%s\n", name);
  });
  return tessel::gl::proc_address("glGenBuffers") && !tessel::gl::proc_address("glNoSuchCall") ? 0 : 1;
}
