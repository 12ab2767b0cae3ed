// GL entry points by name (proc_address.cpp).
#pragma once

#include <cstddef>

namespace tessel::gl {

// The entry point `name` ("glGenBuffers"), or null when Tessel has none of that name.
void (*proc_address(const char* name))();
// Every GL 1.0-3.3 entry point the table lists (and their ARB and EXT names, ext_aliases.cpp),
// and whether Tessel defines it.
void for_each_proc(void (*fn)(const char* name, bool defined));

}  // namespace tessel::gl
