// `tessel bench`: renders the standard scenes (bench/scenes) with Tessel, optionally side by
// side with the llvmpipe peer (bench/peer), and reports medians, rates, memory and image
// differences.
#pragma once

#include <string>
#include <vector>

namespace tessel::apps {

struct BenchOptions {
  std::vector<std::string> scenes;         // empty: all
  std::vector<std::pair<int, int>> sizes;  // empty: 1920x1080 and 640x480
  std::vector<int> threads;                // empty: 1 and 2
  int frames = 10, warmup = 3;
  bool instanced = false;
  bool peer = false;
  std::string peer_path;         // the tessel_peer program; empty: next to this program, then PATH
  std::string json;              // write results here
  std::string images;            // write images into this folder
  double max_diff_percent = -1;  // with peer: fail when more pixels than this differ by > 2/255
  std::string shaders = "cpp";   // "cpp": the C++ shader; "glsl": the peer's GLSL through tessel::glsl
  // "engine": Tessel's side is the engine in this process (the shaders above). "gl33": Tessel's
  // side is the peer program itself, unchanged, on Tessel's libEGL.so.1 and libOpenGL.so.0
  // (LD_LIBRARY_PATH=glvnd_path): the same GL calls and the same GLSL as on llvmpipe.
  std::string api = "engine";
  std::string glvnd_path;  // empty: the build's glvnd folder next to this program
};

// Runs the benchmark and prints its table; returns the process exit code. Throws on errors
// that stop the whole run (bad scene name, unwritable output).
int run_bench(const BenchOptions& options);

}  // namespace tessel::apps
