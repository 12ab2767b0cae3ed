// libFuzzer target: Wavefront OBJ (and MTL: the text after a line "#MTL" is the material file).
// Any input must either load or throw tessel::gpu::Error.
#include <cstddef>
#include <cstdint>
#include <string>

#include "tessel/gpu/format.hpp"
#include "tessel/scene/model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 65536) return -1;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto cut = text.find("\n#MTL\n");
  const std::string obj = cut == std::string::npos ? text : text.substr(0, cut);
  const std::string mtl = cut == std::string::npos ? std::string() : text.substr(cut + 6);
  try {
    tessel::scene::parse_obj(obj, mtl, "fuzz.obj", "/nonexistent");
  } catch (const tessel::gpu::Error&) {
  }
  return 0;
}
