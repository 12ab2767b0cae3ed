// libFuzzer target: glTF 2.0, JSON or binary (.glb). Any input must load or throw
// tessel::gpu::Error.
#include <cstddef>
#include <cstdint>

#include "tessel/gpu/format.hpp"
#include "tessel/scene/model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 65536) return -1;
  try {
    tessel::scene::parse_gltf(data, size, "fuzz.gltf", "/nonexistent");
  } catch (const tessel::gpu::Error&) {
  }
  return 0;
}
