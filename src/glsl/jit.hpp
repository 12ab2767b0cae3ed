// The native-code tier: one stage of a program compiled by LLVM (ORC JIT) to a function over
// sixteen lanes, from the same IR the interpreter runs, with the same results bit for bit
// (every operation is the same IEEE operation, in the same order; the library functions are
// the interpreter's own, called per sixteen lanes).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "interp.hpp"
#include "ir.hpp"

namespace tessel::glsl {

// Where a stage's inputs come from and its outputs go: byte offsets into the lanes structure
// the pipeline passes (gpu::VertexLanes or gpu::FragmentLanes), each a row of sixteen lanes.
struct StageIO {
  std::vector<std::pair<ir::Reg, uint32_t>> in, out;
  // Registers set from a 32-bit lane mask at an offset (gl_FrontFacing): all bits or none.
  std::vector<std::pair<ir::Reg, uint32_t>> in_mask;
};

// Runs the stage on all sixteen lanes of `lanes` (`mask` must be 0xFFFF); returns the lanes
// discarded.
using StageFn = uint32_t (*)(void* lanes, const uint32_t* uniforms, uint32_t uniform_words,
                             const RunInputs* in, uint32_t mask);

// Runs the fragment stage on two lane structures at once, as one 32-lane vector (the same
// lanes as two StageFn calls); returns the lanes discarded, those of `b` in bits 16-31.
using PairFn = uint32_t (*)(void* a, void* b, const uint32_t* uniforms, uint32_t uniform_words,
                            const RunInputs* in);

class JitCode {
 public:
  virtual ~JitCode() = default;
  virtual StageFn function(int stage) const = 0;  // 0 vertex, 1 fragment
  virtual PairFn fragment_pair() const = 0;
  bool from_cache = false;  // loaded from the disk cache rather than compiled
};

// Compiles both stages; nullptr (and *error) when LLVM cannot. Compiled code is kept in a disk
// cache, as Mesa keeps its shader cache: $TESSEL_SHADER_CACHE_DIR, else
// $XDG_CACHE_HOME/tessel, else ~/.cache/tessel (TESSEL_SHADER_CACHE=0 turns it off). A file is
// used only when its header, size, checksum and the machine it was made for all match.

// What a compile takes from the environment, read by the thread that links (the compile may
// run on another, and getenv is not safe beside a setenv): the cache folder ("" for none) and
// TESSEL_GLSL_DUMP=1 (print the optimized LLVM IR on stderr).
struct JitEnvironment {
  std::string cache_dir;
  bool dump = false;
};
JitEnvironment jit_environment();

// Compiles a small program that uses every kind of code the generator emits, so that the
// static objects LLVM makes lazily on its first compiles exist (and are destroyed at exit
// after whatever is registered later, see compile_queue.cpp).
void jit_warm_up();

std::unique_ptr<JitCode> jit_compile(const ir::Stage& vs, const StageIO& vio, const ir::Stage& fs,
                                     const StageIO& fio, const JitEnvironment& env, std::string* error);

}  // namespace tessel::glsl
