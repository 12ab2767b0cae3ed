// The built-in demo scene: tessellated Blinn-Phong spheres and a torus on a textured floor,
// lit by one directional and one point light. Needs no file.
#pragma once

#include <string>

#include "tessel/gpu/context.hpp"

namespace tessel::apps {

struct DemoResult {
  double milliseconds = 0.0;  // the frame: clear, draws, finish
  int triangles = 0;          // submitted
  gpu::Stats stats;
};

// Renders the demo into a width x height RGBA8 image and writes it to `png` (atomically).
DemoResult render_demo(int width, int height, int threads, const std::string& png);

}  // namespace tessel::apps
