// Golden-image comparison for the scene tests. An image passes when at most 0.1% of its pixels
// differ from the golden file by more than 2/255 in some channel (the same tolerance as the
// comparisons with llvmpipe; TestGolden.ToleranceCatchesAShininessChange shows a 10% change of
// one material parameter fails it). TESSEL_UPDATE_GOLDEN=1 writes the files instead.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "tessel/gpu/image.hpp"

namespace tessel::test {

struct ImageDiff {
  int differing = 0, total = 0, max_diff = 0;
  bool passes() const { return total > 0 && differing * 1000 <= total; }
};

inline ImageDiff diff_rgba(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  ImageDiff d;
  if (a.size() != b.size() || a.empty()) return d;
  d.total = int(a.size() / 4);
  for (size_t p = 0; p < a.size(); p += 4) {
    int m = 0;
    for (int c = 0; c < 4; ++c) m = std::max(m, std::abs(int(a[p + size_t(c)]) - int(b[p + size_t(c)])));
    d.max_diff = std::max(d.max_diff, m);
    if (m > 2) ++d.differing;
  }
  return d;
}

inline void expect_golden(const std::string& name, const gpu::Texture2D& color) {
  const std::string path = std::string(TESSEL_GOLDEN_DIR) + "/scene/" + name + ".png";
  const std::vector<uint8_t> got = gpu::read_rgba8(color);
  const char* update = std::getenv("TESSEL_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    gpu::write_png(path, color.width(), color.height(), 4, got.data());
    return;
  }
  gpu::Image want;
  try {
    want = gpu::load_image(path);
  } catch (const std::exception& e) {
    gpu::write_png(name + ".new.png", color.width(), color.height(), 4, got.data());
    FAIL() << "no golden image for " << name << " (" << e.what() << "); wrote " << name
           << ".new.png here; TESSEL_UPDATE_GOLDEN=1 writes the golden files";
  }
  ASSERT_EQ(want.width, color.width()) << name;
  ASSERT_EQ(want.height, color.height()) << name;
  const ImageDiff d = diff_rgba(got, want.pixels);
  if (!d.passes()) gpu::write_png(name + ".got.png", color.width(), color.height(), 4, got.data());
  EXPECT_TRUE(d.passes()) << name << ": " << d.differing << " of " << d.total
                          << " pixels differ by more than 2/255 (max " << d.max_diff
                          << "); this run's image is " << name << ".got.png in the test's folder";
}

}  // namespace tessel::test
