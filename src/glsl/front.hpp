// The glslang front end behind plain data: the only files that touch glslang's classes
// (front.cpp, lower.cpp) are compiled without RTTI, as Debian builds glslang.
#pragma once

#include <string>
#include <vector>

#include "lower.hpp"

namespace tessel::glsl {

// Parses one stage (0 vertex, 1 fragment, 2 geometry); returns whether it compiled, and its info log.
bool front_compile(int stage, const std::string& source, std::string& log);

// Parses and links the stages (a geometry stage when `geometry` is not empty), each of one or more shader
// objects (GL's several compilation units: one of them has main()), and lowers them into `vs` and `fs`
// (uniforms into `layout`); false with the info log when glslang or the lowering refuses.
bool front_link(const std::vector<std::string>& vertex, const std::vector<std::string>& fragment,
                const std::vector<std::string>& geometry, UniformLayout& layout, LoweredStage& vs,
                LoweredStage& fs, LoweredStage& gs, std::string& log);

}  // namespace tessel::glsl
