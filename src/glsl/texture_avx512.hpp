// texture(sampler2D, vec2) with LINEAR_MIPMAP_LINEAR on an RGBA8 texture, sixteen lanes to a
// 512-bit register, on machines with AVX-512 (F, BW, VL, DQ), chosen when the program runs.
// The same bits as the AVX2 sampler (gpu::detail::trilinear_halves) on every input.
#pragma once

#include "interp.hpp"
#include "tessel/gpu/texture.hpp"

namespace tessel::glsl {

// True when this machine runs the functions below (they return false everywhere else).
bool avx512_sampling();
// The lookup of the coordinate rows kCoord and kCoord + 1 of one lane structure, or of two,
// into their result rows, when every 2x2 quad's LOD falls between the same two levels of a
// texture the vector path takes (gpu::detail::vector_path); false, with nothing written,
// otherwise.
bool trilinear_avx512(const gpu::Texture2D& tex, const gpu::SamplerState& st, TexLanes& a);
bool trilinear_avx512(const gpu::Texture2D& tex, const gpu::SamplerState& st, TexLanes& a, TexLanes& b);

}  // namespace tessel::glsl
