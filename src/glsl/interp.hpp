// The IR interpreter: runs one stage of a program on sixteen lanes. It is the reference path
// (every operation written once, lane by lane, for clarity) that the tests compare with.
#pragma once

#include <cstdint>
#include <vector>

#include "ir.hpp"
#include "tessel/gpu/texture.hpp"

namespace tessel::glsl {

// A texture unit as a draw sees it.
struct TextureUnit {
  const gpu::Texture2D* texture_2d = nullptr;
  const gpu::TextureCube* texture_cube = nullptr;
  gpu::SamplerState sampler;
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
};

// Runs `stage` on the registers `regs` (at least stage.registers of them, inputs already
// copied in) for the lanes in `mask`; fills constants, uniforms and zeroes variables first.
// Returns the lanes discarded.
uint32_t run_stage(const ir::Stage& stage, LaneReg* regs, uint32_t mask, const RunInputs& in);

}  // namespace tessel::glsl
