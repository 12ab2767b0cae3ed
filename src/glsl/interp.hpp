// The IR interpreter: runs one stage of a program on sixteen lanes. It is the reference path
// (every operation written once, lane by lane, for clarity) that the tests compare with.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "ir.hpp"
#include "tessel/gpu/texture.hpp"

namespace tessel::glsl {

// A texture unit as a draw sees it.
struct TextureUnit {
  const gpu::Texture2D* texture_2d = nullptr;
  const gpu::TextureCube* texture_cube = nullptr;
  gpu::SamplerState sampler;
  const gpu::Texture3D* texture_3d = nullptr;
  const gpu::Texture2DArray* texture_2d_array = nullptr;
  const gpu::TextureBuffer* texture_buffer = nullptr;
  // GL_TEXTURE_SWIZZLE_*: each result component from 0-3 (R, G, B, A), 4 (zero) or 5 (one).
  std::array<uint8_t, 4> swizzle{0, 1, 2, 3};
  bool swizzled() const {
    uint32_t w;  // (one compare: std::array's operator!= is a call to memcmp)
    std::memcpy(&w, swizzle.data(), 4);
    return w != 0x03020100u;  // bytes 0, 1, 2, 3 in memory order (little-endian)
  }
};

struct alignas(64) LaneReg {
  uint32_t u[ir::kLanes];
};

struct RunInputs {
  const uint32_t* uniforms = nullptr;
  uint32_t uniform_words = 0;
  const TextureUnit* units = nullptr;
  int unit_count = 0;
  bool fragment = false;
  const ir::TexOp* textures = nullptr;  // the running stage's texture instructions
};

// The operands of a texture instruction as rows of lanes (a missing operand is a row of 0),
// and its four results: the interpreter and the JIT both call run_texture with them.
struct TexLanes {
  enum : int { kCoord = 0, kLod = 5, kDx = 6, kDy = 9, kOffset = 12, kRows = 15 };
  alignas(64) uint32_t in[kRows][ir::kLanes];
  alignas(64) uint32_t out[4][ir::kLanes];
};
void run_texture(const ir::TexOp& op, const RunInputs& in, TexLanes& lanes);
// texture(sampler2D, vec2) with an implicit LOD and a float result, the most common lookup:
// in a fragment stage it reads only the rows kCoord and kCoord + 1, and
// run_texture_2d_implicit runs it (as run_texture does) without the other rows set.
bool texture_2d_implicit(const ir::TexOp& op);
void run_texture_2d_implicit(const ir::TexOp& op, const RunInputs& in, TexLanes& lanes);
// Two lane structures' worth (a paired fragment call), as two run_texture_2d_implicit calls.
void run_texture_2d_implicit_pair(const ir::TexOp& op, const RunInputs& in, TexLanes& a, TexLanes& b);

// One of the library operations (bit fields, frexp/ldexp, halves, carries) on
// sixteen lanes: t = op(a, b, c, e).
void lane_math(ir::Op op, uint32_t* t, const uint32_t* a, const uint32_t* b, const uint32_t* c,
               const uint32_t* e);

// Runs `stage` on the registers `regs` (at least stage.registers of them, inputs already
// copied in) for the lanes in `mask`; fills constants, uniforms and zeroes variables first.
// Returns the lanes discarded.
uint32_t run_stage(const ir::Stage& stage, LaneReg* regs, uint32_t mask, const RunInputs& in);

}  // namespace tessel::glsl
