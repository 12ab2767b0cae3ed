// Lowering of one linked glslang stage (its AST) to Tessel's IR (ir.hpp).
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "ir.hpp"

namespace glslang {
class TIntermediate;
}

namespace tessel::glsl {

enum class Base : uint8_t { Float, Int, Uint, Bool };

inline constexpr int kMaxGeometryVertices = 1024;  // GL_MAX_GEOMETRY_OUTPUT_VERTICES, as llvmpipe's

// A uniform of the default block as the lowering laid it out: components (32-bit words)
// from `word`, in GLSL order (arrays element by element, matrices column by column).
struct UniformSlot {
  std::string name;  // as GL names it: "m", "lights[0].pos" (arrays of structs are expanded)
  uint32_t gl_type = 0;
  int array_size = 1;  // elements (1 for a non-array)
  int components = 1;  // per element
  uint32_t word = 0;
  Base base = Base::Float;
  bool sampler = false;
  ir::SamplerDim dim = ir::SamplerDim::D2;
  bool shadow = false, array = false;
  bool builtin = false;  // gl_ModelViewMatrix and the other compatibility state
  bool active = false;   // read by some stage
};

// A stage input or output: its registers (consecutive), with what the link needs to know.
struct Interface {
  std::string name;
  ir::Reg reg = 0;
  int components = 0;  // all of it (arrays included)
  int array_size = 0;  // 0: not an array
  uint32_t gl_type = 0;
  Base base = Base::Float;
  int location = -1;  // layout(location), or -1
  int index = -1;     // layout(index) of a fragment output (dual-source blending), or -1
  bool flat = false, noperspective = false;
  bool builtin = false;  // gl_Position, gl_FragCoord, gl_Vertex, ...
  bool read = false, written = false;
  bool block = false;  // a whole interface block (its members are listed too)
  // A geometry stage's input arrays (one element a vertex of the primitive): `vertices`
  // elements of `components` each, vertex v's from reg + v * vertex_stride.
  int vertices = 0, vertex_stride = 0;
};

// What a geometry stage (GLSL 1.50) emits: each EmitVertex copies the registers `emit` into
// the next max_vertices-th of `buffer` (vertex v's at buffer + v * emit.size()), notes in
// starts + v whether it continues a strip (zero: it begins one), and counts it in `count`.
struct GeometryLayout {
  int input_vertices = 0;         // 1, 2, 3, 4 or 6
  uint32_t input_primitive = 0;   // GL_POINTS, GL_LINES, GL_LINES_ADJACENCY, GL_TRIANGLES, ...
  uint32_t output_primitive = 0;  // GL_POINTS, GL_LINE_STRIP or GL_TRIANGLE_STRIP
  int max_vertices = 0;
  std::vector<ir::Reg> emit;
  ir::Reg buffer = 0, starts = 0, count = 0;
};

struct LoweredStage {
  ir::Stage ir;
  std::vector<Interface> inputs, outputs;
  std::set<std::string> declared_outputs;  // declared, whether or not written
  GeometryLayout geometry;                 // a geometry stage's
};

// A uniform block (GLSL 1.40 / GL 3.1), laid out by std140 (GL 3.3 §2.11.4) in a run of
// uniform words that each draw fills from the buffer bound to its binding point.
struct BlockMember {
  std::string name;  // GL's name: "member", or "Block.member" for a block with an instance name
  uint32_t gl_type = 0;
  int array_size = 1;
  uint32_t offset = 0, array_stride = 0, matrix_stride = 0;  // bytes
  bool row_major = false;
};
struct UniformBlockLayout {
  std::string name;
  uint32_t word = 0;   // first uniform word
  uint32_t bytes = 0;  // data size (a multiple of 16)
  std::vector<BlockMember> members;
};

// Uniforms are shared between the stages of a program: both stages lower into one layout.
struct UniformLayout {
  std::vector<UniformSlot> slots;
  uint32_t words = 0;
  // Initial values from initializers (GLSL 1.20 `uniform float k = 2.0;`): variable name ->
  // its components as words.
  std::map<std::string, std::vector<uint32_t>> initial;
  std::vector<UniformBlockLayout> blocks;
  std::map<std::string, size_t> by_name;  // top-level variable name -> first slot
};

// Lowers `stage` (0 vertex, 1 fragment, 2 geometry). Throws std::runtime_error with a message for
// what it cannot lower (named with the source line).
LoweredStage lower_stage(const glslang::TIntermediate& stage, int which, UniformLayout& uniforms);

}  // namespace tessel::glsl
