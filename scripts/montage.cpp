// Puts PNG images side by side in a grid (for docs/scenes.png): montage OUT COLUMNS FILE...
#include <cstdio>
#include <string>
#include <vector>
#include "tessel/gpu/image.hpp"
int main(int argc, char** argv) {
  // montage OUT COLS file...
  const std::string out = argv[1];
  const int cols = std::atoi(argv[2]);
  std::vector<tessel::gpu::Image> ims;
  for (int i = 3; i < argc; ++i) ims.push_back(tessel::gpu::load_image(argv[i]));
  const int w = ims[0].width, h = ims[0].height, n = int(ims.size()), rows = (n + cols - 1) / cols, gap = 4;
  const int W = cols * w + (cols - 1) * gap, H = rows * h + (rows - 1) * gap;
  std::vector<uint8_t> px(size_t(W) * H * 4, 255);
  for (int i = 0; i < n; ++i) {
    const int cx = (i % cols) * (w + gap), cy = (rows - 1 - i / cols) * (h + gap);  // bottom-up rows
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 4; ++c)
          px[(size_t(cy + y) * W + size_t(cx + x)) * 4 + c] = ims[i].pixels[(size_t(y) * w + x) * 4 + c];
  }
  tessel::gpu::write_png(out, W, H, 4, px.data());
}
