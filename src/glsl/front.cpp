// glslang: preprocessing, parsing, type checking and linking of the two stages (front.hpp).
#include "front.hpp"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <string>

#include "tessel/glsl/program.hpp"
#include "tessel/gpu/buffer.hpp"
#include "tessel/gpu/shader.hpp"
#include "tessel/gpu/state.hpp"

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

// The limits shaders see as built-in constants (gl_MaxVertexAttribs, gl_MaxDrawBuffers,
// gl_MaxVaryingComponents, ...; GLSL 3.30 section 7.4): what the GL layer reports for the
// same GL_MAX_* queries, where glslang's defaults are those of a large GPU (64 attributes, 32
// draw buffers, 32 texture coordinate sets). gl_TexCoord[] and gl_FragData[] take their
// sizes from them.
const TBuiltInResource& resources() {
  static const TBuiltInResource r = [] {
    TBuiltInResource x = *GetDefaultResources();
    x.maxVertexAttribs = gpu::kMaxVertexAttribs;
    x.maxDrawBuffers = gpu::kMaxColorAttachments;
    x.maxTextureCoords = kMaxTextureCoords;
    x.maxTextureUnits = kMaxTextureCoords;  // GL_MAX_TEXTURE_UNITS
    x.maxTextureImageUnits = kMaxStageTextureUnits;
    x.maxVertexTextureImageUnits = kMaxStageTextureUnits;
    x.maxGeometryTextureImageUnits = kMaxStageTextureUnits;
    x.maxCombinedTextureImageUnits = kMaxCombinedTextureUnits;
    x.maxVertexUniformComponents = kMaxUniformComponents;
    x.maxFragmentUniformComponents = kMaxUniformComponents;
    x.maxGeometryUniformComponents = kMaxUniformComponents;
    x.maxVaryingFloats = gpu::kMaxVaryings;
    x.maxVaryingComponents = gpu::kMaxVaryings;
    x.maxVaryingVectors = gpu::kMaxVaryings / 4;
    x.maxVertexOutputComponents = gpu::kMaxVaryings;
    x.maxGeometryInputComponents = gpu::kMaxVaryings;
    x.maxFragmentInputComponents = gpu::kMaxVaryings;
    x.maxClipDistances = gpu::kMaxClipPlanes;
    x.maxClipPlanes = gpu::kMaxClipPlanes;  // GL_MAX_CLIP_PLANES is the same query
    x.maxGeometryOutputVertices = kMaxGeometryVertices;
    x.maxGeometryTotalOutputComponents = 1024;
    x.maxGeometryOutputComponents = 128;
    return x;
  }();
  return r;
}

// glslang's log in the form GL drivers give: "ERROR: 0:4: 'foo' : undeclared identifier"
// becomes "0:4: error: 'foo' : undeclared identifier" (string:line first, as Mesa and the
// proprietary drivers print it, so editors and course tools find the line), WARNING lines
// alike, and a line without a location ("ERROR: 1 compilation errors...") starts "error: ".
std::string gl_log_form(const std::string& log) {
  std::string out;
  size_t at = 0;
  while (at < log.size()) {
    size_t end = log.find('\n', at);
    if (end == std::string::npos) end = log.size();
    std::string line = log.substr(at, end - at);
    at = end + 1;
    for (const char* kind : {"ERROR", "WARNING"}) {
      const std::string tag = std::string(kind) + ": ";
      if (line.compare(0, tag.size(), tag) != 0) continue;
      const std::string lower = kind[0] == 'E' ? "error: " : "warning: ";
      std::string rest = line.substr(tag.size());
      // A location is "<string>:<line>: " of digits.
      size_t p = 0;
      while (p < rest.size() && std::isdigit(static_cast<unsigned char>(rest[p]))) ++p;
      size_t q = p < rest.size() && rest[p] == ':' && p > 0 ? p + 1 : 0;
      const size_t line_start = q;
      while (q > 0 && q < rest.size() && std::isdigit(static_cast<unsigned char>(rest[q]))) ++q;
      if (q > line_start && rest.compare(q, 2, ": ") == 0)
        line = rest.substr(0, q + 2) + lower + rest.substr(q + 2);
      else
        line = lower + rest;
      break;
    }
    if (!line.empty()) out += line + "\n";
  }
  return out;
}

// Line continuations (a backslash at the end of a line) joined, as C's translation phase 2
// and Mesa's preprocessor join them in every GLSL version; glslang accepts them only from
// GLSL 4.20 (and ES 3.00). The newlines taken out are put back after the joined line, so
// every later line keeps its number in the info log.
std::string splice_lines(const std::string& source) {
  if (source.find('\\') == std::string::npos) return source;
  std::string out;
  out.reserve(source.size());
  int owed = 0;
  for (size_t i = 0; i < source.size(); ++i) {
    const char c = source[i];
    if (c == '\\') {
      size_t j = i + 1;
      if (j < source.size() && source[j] == '\r') ++j;
      if (j < source.size() && source[j] == '\n') {
        ++owed;
        i = j;
        continue;
      }
    }
    out += c;
    if (c == '\n') out.append(size_t(owed), '\n'), owed = 0;
  }
  out.append(size_t(owed), '\n');
  return out;
}

// The #version a source declares (110 without one).
int declared_version(const std::string& source) {
  const size_t at = source.find("#version");
  if (at == std::string::npos) return 110;
  size_t p = at + 8;
  while (p < source.size() && (source[p] == ' ' || source[p] == '\t')) ++p;
  int v = 0;
  while (p < source.size() && std::isdigit(static_cast<unsigned char>(source[p])) && v < 100000)
    v = v * 10 + (source[p++] - '0');
  return v;
}

// Parses one stage at its #version (1.10 without one); the shader object must outlive any
// program that links it.
bool parse(glslang::TShader& sh, const std::string& original, std::string& log) {
  const std::string source = splice_lines(original);
  const char* text = source.c_str();
  const int length = int(std::min<size_t>(source.size(), size_t(INT32_MAX)));
  sh.setStringsWithLengths(&text, &length, 1);
  // ftransform() (GLSL 1.20 section 8.5, compatibility vertex shaders) is the fixed-function
  // transform, gl_ModelViewProjectionMatrix * gl_Vertex, which is how Mesa defines it too:
  // given as that expression it lowers to the same operations as the product written out.
  // (In a core shader gl_Vertex is not declared, and the compile fails there.)
  // inverse() is a GLSL 1.40 built-in (section 8.5) that glslang's 1.40 symbol table lacks:
  // a 1.40 shader gets it declared here (glslang takes the version from the shader, not the
  // preamble, so __VERSION__ is the shader's), and the lowering takes calls to these three
  // as the built-in (lower.cpp).
  static const std::string kInverse140 =
      "#if __VERSION__ == 140\nmat2 inverse(mat2 m) { return m; }\nmat3 inverse(mat3 m) { return m; }\n"
      "mat4 inverse(mat4 m) { return m; }\n#endif\n";
  static const std::string kVertex =
      "#define ftransform() (gl_ModelViewProjectionMatrix * gl_Vertex)\n" + kInverse140;
  // GLSL 1.50 lets a vertex or geometry shader redeclare the gl_PerVertex blocks (section
  // 7.1) to list the members it uses; glslang allows that only from 4.10 or with
  // ARB_separate_shader_objects, which a 1.50 to 4.00 shader that names gl_PerVertex gets.
  std::string preamble = sh.getStage() == EShLangVertex ? kVertex : kInverse140;
  const int version = declared_version(source);
  if (version >= 150 && version < 410 && source.find("gl_PerVertex") != std::string::npos)
    preamble = "#extension GL_ARB_separate_shader_objects : enable\n" + preamble;
  sh.setPreamble(preamble.c_str());
  const bool ok = sh.parse(&resources(), 110, ENoProfile, false, false, EShMsgDefault);
  log = gl_log_form(sh.getInfoLog());
  return ok;
}

EShLanguage language(int stage) {
  return stage == 0 ? EShLangVertex : stage == 1 ? EShLangFragment : EShLangGeometry;
}

}  // namespace

bool front_compile(int stage, const std::string& source, std::string& log) {
  init_glslang();
  std::lock_guard lock(glslang_mutex());
  try {
    glslang::TShader sh(language(stage));
    return parse(sh, source, log);
  } catch (const std::exception& e) {
    log = std::string("0:0: error: ") + e.what() + "\n";
    return false;
  }
}

bool front_link(const std::vector<std::string>& vertex, const std::vector<std::string>& fragment,
                const std::vector<std::string>& geometry, UniformLayout& layout, LoweredStage& vs,
                LoweredStage& fs, LoweredStage& gs, std::string& log) {
  init_glslang();
  std::lock_guard lock(glslang_mutex());
  try {
    // The shader objects outlive the program that links them (glslang's rule).
    std::vector<std::unique_ptr<glslang::TShader>> units;
    glslang::TProgram prog;
    for (int stage = 0; stage < 3; ++stage) {
      for (const std::string& source : stage == 0 ? vertex : stage == 1 ? fragment : geometry) {
        units.push_back(std::make_unique<glslang::TShader>(language(stage)));
        if (!parse(*units.back(), source, log)) return false;
        prog.addShader(units.back().get());
      }
    }
    if (!prog.link(EShMsgDefault)) {
      log = gl_log_form(prog.getInfoLog());
      if (log.empty()) log = "error: link failed\n";
      return false;
    }
    vs = lower_stage(*prog.getIntermediate(EShLangVertex), 0, layout);
    if (!geometry.empty()) gs = lower_stage(*prog.getIntermediate(EShLangGeometry), 2, layout);
    fs = lower_stage(*prog.getIntermediate(EShLangFragment), 1, layout);
    return true;
  } catch (const std::exception& e) {
    log = std::string(e.what()) + "\n";
    return false;
  }
}

}  // namespace tessel::glsl
