// Tessel's shader IR: what a GLSL stage becomes after the front end, and what the
// interpreter (interp.cpp) runs.
//
// Every value is one scalar component over sixteen lanes (a register of 16 x 32 bits):
// vectors, matrices, structs and arrays are lowered to their components, so every operation
// is a lane-wise scalar operation. Booleans are lane masks (all bits set or clear).
//
// Control flow is kept structured, as a tree of nodes, and runs under execution masks as
// llvmpipe runs it: both arms of an `if` run with the lanes that take them, a loop runs
// while any lane is still in it (at most kMaxLoopIterations times), and break, continue,
// return and discard clear lanes from the masks until the construct they leave ends.
// Registers that hold variables are written under the current mask (Op::Store); temporaries
// are written whole.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tessel::glsl::ir {

inline constexpr int kLanes = 16;
// A loop is cut after this many iterations, as llvmpipe cuts it (LP_MAX_TGSI_LOOP_ITERATIONS),
// so that every draw ends.
inline constexpr int kMaxLoopIterations = 65535;
// And all the loops of one run together after this many iterations, so that nested loops
// cannot multiply their limits into hours.
inline constexpr uint32_t kMaxTotalLoopIterations = 1u << 20;

using Reg = uint32_t;

enum class Op : uint8_t {
  // dst = a (whole)
  Mov,
  // dst = a in the lanes of the current mask, dst elsewhere
  Store,
  // dst = uniform word (imm + a[lane]); a is a clamped word offset
  UniformIndexed,
  // dst = register (b + a[lane])[lane]: a is a clamped component offset into a variable
  LoadIndexed,
  // register (dst + a[lane])[lane] = b[lane] in the lanes of the mask
  StoreIndexed,
  // dst = a ? b : c (a is a mask)
  Select,

  // float, lane-wise
  // (transcendental functions are sequences of these: lower_math.inc)
  FAdd,
  FSub,
  FMul,
  FDiv,
  FNeg,
  FAbs,
  FSign,
  FMin,
  FMax,
  FFma,
  FFloor,
  FCeil,
  FTrunc,
  FRoundEven,
  FFract,
  FMod,
  FSqrt,
  FRsq,
  FLdexp,
  FFrexpMant,
  FFrexpExp,
  FLt,
  FLe,
  FGt,
  FGe,
  FEq,
  FNe,
  FIsNan,
  FIsInf,
  // integer (two's complement 32 bits); division and shifts are defined for every input
  IAdd,
  ISub,
  IMul,
  IDiv,
  UDiv,
  UMod,
  INeg,
  IAbs,
  ISign,
  IMin,
  IMax,
  UMin,
  UMax,
  And,
  Or,
  Xor,
  Not,
  Shl,
  ShrA,
  ShrL,
  ILt,
  ILe,
  IGt,
  IGe,
  ULt,
  ULe,
  UGt,
  UGe,
  IEq,
  INe,
  BitCount,
  FindLSB,
  IFindMSB,
  UFindMSB,
  BitReverse,
  IBitExtract,
  UBitExtract,
  BitInsert,
  UAddCarry,
  USubBorrow,
  // conversions
  I2F,
  U2F,
  F2I,
  F2U,
  PackHalf,
  UnpackHalfLo,
  UnpackHalfHi,
  // derivatives inside each 2x2 quad (fragment stage)
  Ddx,
  Ddy,
  // texture access: imm indexes Stage::textures
  Texture,
};

struct Inst {
  Op op;
  Reg dst = 0, a = 0, b = 0, c = 0, d = 0;
  uint32_t imm = 0;
};

enum class TexKind : uint8_t { Sample, Fetch, Size, QueryLod };
enum class SamplerDim : uint8_t { D1, D2, D3, Cube, Rect, Buffer };

// One texture instruction's operands (registers; a missing one is kNone).
struct TexOp {
  static constexpr Reg kNone = ~0u;
  TexKind kind = TexKind::Sample;
  SamplerDim dim = SamplerDim::D2;
  bool array = false, shadow = false, proj = false;
  bool has_lod = false, has_bias = false, has_grad = false;
  int sampler = 0;  // uniform word that holds the texture unit
  int coords = 0;   // coordinate components given (including array layer and ref)
  Reg coord[5] = {kNone, kNone, kNone, kNone, kNone};
  Reg ref = kNone;  // depth reference of a shadow lookup
  Reg lod = kNone;  // explicit LOD, bias, or the level of texelFetch/textureSize
  Reg dx[3] = {kNone, kNone, kNone}, dy[3] = {kNone, kNone, kNone};
  int offset[3] = {0, 0, 0};  // constant texel offset
  Reg offset_reg[3] = {kNone, kNone, kNone};
  Reg dst[4] = {kNone, kNone, kNone, kNone};
  int result = 0;  // 0 float, 1 int, 2 uint
};

struct Node;
using Block = std::vector<Node>;

struct Node {
  enum class Kind : uint8_t {
    Code,      // code
    If,        // if (cond) a else b
    Loop,      // loop { a; continue-point: b }
    Break,     // leave the innermost loop or switch
    Continue,  // go to the continue point of the innermost loop
    Return,    // leave the innermost function (or main)
    Discard,   // end the invocation (fragment stage)
    Function,  // a: an inlined function body; `return` in it ends here
    Switch,    // a: a switch body; `break` in it ends here
  };
  Kind kind = Kind::Code;
  Reg cond = 0;
  std::vector<Inst> code;
  Block a, b;
};

// One compiled stage.
struct Stage {
  Block body;
  uint32_t registers = 0;
  // Registers filled before each run: constants, and uniform components (broadcast).
  std::vector<std::pair<Reg, uint32_t>> constants;  // register, bits
  std::vector<std::pair<Reg, uint32_t>> uniforms;   // register, uniform word
  // Registers of variables (first, count): zero at the start of each run, so that a
  // variable read before it is written reads 0 whatever ran before on the same thread.
  std::vector<std::pair<Reg, uint32_t>> variables;
  std::vector<TexOp> textures;
  bool uses_derivatives = false;  // dFdx/dFdy/fwidth or implicit-LOD sampling
  bool discards = false;
  bool writes_depth = false;
};

}  // namespace tessel::glsl::ir
