// Shared by the GLSL-against-Mesa tests (test_glsl_mesa.cpp, test_glsl_conformance.cpp): the
// llvmpipe oracle, a full-screen quad whose fragment shader runs a body per pixel, and
// run_case(), which compares Tessel's JIT with Mesa and the interpreter with the JIT.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "compare.hpp"
#include "glsl_oracle.hpp"
#include "tessel_runner.hpp"

namespace tessel::testing {

inline reference::GlslOracle* oracle() {
  static std::unique_ptr<reference::GlslOracle> o = [] {
    std::string why;
    auto p = reference::GlslOracle::create(&why);
    if (!p) std::fprintf(stderr, "no Mesa oracle: %s\n", why.c_str());
    return p;
  }();
  return o.get();
}

inline const char* const kVertex330 = R"(#version 330
layout(location = 0) in vec2 pos;
out vec2 p;
void main() { p = pos * 0.5 + 0.5; gl_Position = vec4(pos, 0.0, 1.0); }
)";

// A fragment shader whose main() runs `body` with `t` in [0, 1] across the 256 pixels
// (one value per pixel, the same on both sides), `i` the pixel index, writing vec4 `c`.
inline std::string fragment330(const std::string& decl, const std::string& body) {
  return "#version 330\nin vec2 p;\nout vec4 c;\n" + decl +
         "\nvoid main() {\n  int i = int(gl_FragCoord.x) + 16 * int(gl_FragCoord.y);\n  float t = float(i) / "
         "255.0;\n  " +
         body + "\n}\n";
}

inline reference::GlslDrawSpec quad_spec(const std::string& vs, const std::string& fs) {
  reference::GlslDrawSpec s;
  s.vertex = vs;
  s.fragment = fs;
  s.attributes.push_back({"pos", 2, {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1}});
  s.count = 6;
  return s;
}

struct Case {
  std::string name;
  std::string decl, body;
  Tolerance tol;
  unsigned channels = 0xF;
  std::vector<reference::GlslUniform> uniforms = {};
  std::vector<reference::GlslTexture> textures = {};
};

// Shaders compared against Mesa so far in this process (each distinct shader once).
inline int& shaders_compared() {
  static int n = 0;
  return n;
}

// Tessel's JIT against Mesa (within `tol` on the `channels` of c), and the interpreter
// against the JIT (bit for bit). With `mesa` false only the two tiers are compared (for
// programs whose result GLSL leaves undefined, e.g. reads out of an array's range).
inline void run_spec(const std::string& name, const reference::GlslDrawSpec& spec, Tolerance tol,
                     unsigned channels = 0xF, bool mesa = true) {
  if (!oracle()) GTEST_SKIP() << "Mesa llvmpipe is not available";
  ++shaders_compared();
  reference::GlslResult m;
  if (mesa) {
    m = oracle()->run(spec);
    ASSERT_TRUE(m.ok) << name << ": Mesa: " << m.log << "\n" << spec.fragment;
  }
  const TesselResult ours = run_tessel(spec);
  ASSERT_TRUE(ours.ok) << name << ": Tessel: " << ours.log << "\n" << spec.vertex << "\n" << spec.fragment;
  if (mesa) {
    ASSERT_EQ(ours.outputs.size(), m.outputs.size());
    for (size_t o = 0; o < ours.outputs.size(); ++o) {
      const Mismatch mm = compare_floats(ours.outputs[o], m.outputs[o], spec.width, tol, channels);
      EXPECT_EQ(mm.count, 0) << name << ": output " << o << ":" << mm.first << "\n"
                             << spec.vertex << "\n"
                             << spec.fragment;
    }
  }
  // The interpreter (the reference tier) gives the JIT's bits exactly.
  const TesselResult interp = run_tessel(spec, 2, glsl::NativeCode::Off);
  ASSERT_TRUE(interp.ok) << interp.log;
  for (size_t o = 0; o < ours.outputs.size(); ++o) {
    size_t k = 0;
    // Bit for bit, except that any NaN matches any NaN: GLSL leaves NaNs' sign and payload
    // open, and where two different NaNs meet (cosh(NaN) adds exp(NaN) and exp(-NaN)), x86
    // returns the first operand's, an order LLVM may swap in a commutative operation.
    auto same = [&](size_t k) {
      const float x = interp.outputs[o][k], y = ours.outputs[o][k];
      return std::memcmp(&x, &y, 4) == 0 || (std::isnan(x) && std::isnan(y));
    };
    while (k < ours.outputs[o].size() && same(k)) ++k;
    if (k == ours.outputs[o].size()) continue;
    uint32_t a, b;
    std::memcpy(&a, &interp.outputs[o][k], 4);
    std::memcpy(&b, &ours.outputs[o][k], 4);
    ADD_FAILURE() << name << ": the interpreter and the JIT differ: output " << o << " pixel " << k / 4 << "."
                  << "rgba"[k % 4] << ": interp 0x" << std::hex << a << " jit 0x" << b << std::dec << "\n"
                  << spec.fragment;
  }
}

inline void run_case(const Case& c, bool mesa = true) {
  reference::GlslDrawSpec spec = quad_spec(kVertex330, fragment330(c.decl, c.body));
  spec.uniforms = c.uniforms;
  spec.textures = c.textures;
  run_spec(c.name, spec, c.tol, c.channels, mesa);
}

}  // namespace tessel::testing
