// libFuzzer target: texture images (PNG, JPEG, BMP, TGA, HDR through stb_image). Any input
// must either decode or throw tessel::gpu::Error.
#include <cstddef>
#include <cstdint>

#include "tessel/gpu/format.hpp"
#include "tessel/gpu/image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const tessel::gpu::Image img = tessel::gpu::load_image_from_memory(data, size, "fuzz.png");
    if (img.width > 0 && img.height > 0 && !img.is_hdr() && img.width * img.height <= (1 << 20))
      (void)tessel::gpu::make_texture(img, true);
  } catch (const tessel::gpu::Error&) {
  }
  return 0;
}
