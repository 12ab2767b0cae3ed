// libFuzzer target: scene files (JSON). Any input must either parse or throw tessel::gpu::Error.
#include <cstddef>
#include <cstdint>
#include <string>

#include "tessel/gpu/format.hpp"
#include "tessel/scene/scene_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 65536) return -1;  // keeps each run quick; the parser has no size limit of its own
  try {
    tessel::scene::parse_scene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json",
                               "/nonexistent");
  } catch (const tessel::gpu::Error&) {
  }
  return 0;
}
