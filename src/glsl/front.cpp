// glslang: preprocessing, parsing, type checking and linking of the two stages (front.hpp).
#include "front.hpp"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <exception>
#include <mutex>

namespace tessel::glsl {
namespace {

// glslang keeps process-wide tables (its built-in symbol tables): set up once, and used by
// one thread at a time.
std::mutex& glslang_mutex() {
  static std::mutex m;
  return m;
}
void init_glslang() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

// The number of the source's #version directive (110 without one, as GLSL says); comments
// and blank lines may come before it.
int version_of(const std::string& source) {
  size_t i = 0;
  while (i < source.size()) {
    if (std::isspace(static_cast<unsigned char>(source[i]))) {
      ++i;
    } else if (source.compare(i, 2, "//") == 0) {
      i = source.find('\n', i);
      if (i == std::string::npos) return 110;
    } else if (source.compare(i, 2, "/*") == 0) {
      i = source.find("*/", i + 2);
      if (i == std::string::npos) return 110;
      i += 2;
    } else {
      break;
    }
  }
  if (source.compare(i, 1, "#") != 0) return 110;
  ++i;
  while (i < source.size() && (source[i] == ' ' || source[i] == '\t')) ++i;
  if (source.compare(i, 7, "version") != 0) return 110;
  i += 7;
  while (i < source.size() && (source[i] == ' ' || source[i] == '\t')) ++i;
  int v = 0;
  for (int digits = 0; i < source.size() && std::isdigit(static_cast<unsigned char>(source[i])) && digits < 4;
       ++i, ++digits)
    v = v * 10 + (source[i] - '0');
  return v ? v : 110;
}

// Parses one stage at its #version (1.10 without one); the shader object must outlive any
// program that links it.
bool parse(glslang::TShader& sh, const std::string& source, std::string& log) {
  const char* text = source.c_str();
  const int length = int(std::min<size_t>(source.size(), size_t(INT32_MAX)));
  sh.setStringsWithLengths(&text, &length, 1);
  // ftransform() (GLSL 1.20 section 8.5, compatibility vertex shaders) is the fixed-function
  // transform, gl_ModelViewProjectionMatrix * gl_Vertex, which is how Mesa defines it too:
  // given as that expression it lowers to the same operations as the product written out.
  // (In a core shader gl_Vertex is not declared, and the compile fails there.)
  // inverse() is a GLSL 1.40 built-in (section 8.5) that glslang's 1.40 symbol table lacks:
  // for #version 140 it is declared here, and the lowering takes calls to these three as
  // the built-in (lower.cpp, kInverse140).
  static const std::string vertex_preamble =
      "#define ftransform() (gl_ModelViewProjectionMatrix * gl_Vertex)\n";
  static const std::string inverse_140 =
      "mat2 inverse(mat2 m) { return m; }\nmat3 inverse(mat3 m) { return m; }\nmat4 inverse(mat4 m) { return "
      "m; }\n";
  static const std::string both = vertex_preamble + inverse_140;
  const bool v140 = version_of(source) == 140;
  if (sh.getStage() == EShLangVertex)
    sh.setPreamble(v140 ? both.c_str() : vertex_preamble.c_str());
  else if (v140)
    sh.setPreamble(inverse_140.c_str());
  const bool ok = sh.parse(GetDefaultResources(), 110, ENoProfile, false, false, EShMsgDefault);
  log = sh.getInfoLog();
  return ok;
}

}  // namespace

bool front_compile(int stage, const std::string& source, std::string& log) {
  init_glslang();
  std::lock_guard lock(glslang_mutex());
  try {
    glslang::TShader sh(stage == 0 ? EShLangVertex : EShLangFragment);
    return parse(sh, source, log);
  } catch (const std::exception& e) {
    log = std::string("0:0: error: ") + e.what() + "\n";
    return false;
  }
}

bool front_link(const std::string& vertex, const std::string& fragment, UniformLayout& layout,
                LoweredStage& vs, LoweredStage& fs, std::string& log) {
  init_glslang();
  std::lock_guard lock(glslang_mutex());
  try {
    glslang::TShader tvs(EShLangVertex), tfs(EShLangFragment);
    if (!parse(tvs, vertex, log) || !parse(tfs, fragment, log)) return false;
    glslang::TProgram prog;
    prog.addShader(&tvs);
    prog.addShader(&tfs);
    if (!prog.link(EShMsgDefault)) {
      log = prog.getInfoLog();
      if (log.empty()) log = "error: link failed\n";
      return false;
    }
    vs = lower_stage(*prog.getIntermediate(EShLangVertex), 0, layout);
    fs = lower_stage(*prog.getIntermediate(EShLangFragment), 1, layout);
    return true;
  } catch (const std::exception& e) {
    log = std::string(e.what()) + "\n";
    return false;
  }
}

}  // namespace tessel::glsl
