// Headless windows (headless.hpp).
#include "headless.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "context.hpp"
#include "tessel/gpu/image.hpp"

namespace tessel::gl {

void parse_headless(HeadlessSpec& h, const char* spec, const char* who) {
  h.on = true;
  const std::string s = spec ? spec : "";
  size_t pos = 0;
  while (pos < s.size()) {
    size_t end = s.find(',', pos);
    if (end == std::string::npos) end = s.size();
    const std::string item = s.substr(pos, end - pos);
    if (item.rfind("frames:", 0) == 0) {
      char* stop = nullptr;
      const long n = std::strtol(item.c_str() + 7, &stop, 10);
      if (stop && *stop == '\0' && n >= 0 && n <= 1000000)
        h.frames = int(n);
      else
        std::fprintf(stderr, "%s: TESSEL_HEADLESS: bad frame count in '%s' (using %d)\n", who, item.c_str(),
                     h.frames);
    } else if (item.rfind("out:", 0) == 0) {
      h.out = item.substr(4);
      if (h.out.empty()) h.out = std::string(1, '.');
    } else if (!item.empty() && item != "1") {
      std::fprintf(stderr, "%s: TESSEL_HEADLESS: unknown item '%s' (expected frames:N or out:DIR)\n", who,
                   item.c_str());
    }
    pos = end + 1;
  }
}

namespace {
std::string write_rgb(const std::vector<uint8_t>& rgb_bottom_up, int width, int height,
                      const std::string& dir, int frame, int window) {
  char name[64];
  if (window == 1)
    std::snprintf(name, sizeof name, "frame-%04d.png", frame);
  else
    std::snprintf(name, sizeof name, "frame-%04d-w%d.png", frame, window);
  const std::string path = (std::filesystem::path(dir) / name).string();
  try {
    gpu::write_png(path, width, height, 3, rgb_bottom_up.data());
  } catch (const std::exception& e) {
    return "cannot write " + path + ": " + e.what();
  }
  return "";
}
}  // namespace

std::string write_headless_frame(Context& c, const std::string& dir, int frame, int window) {
  const gpu::Texture2D& front = c.front();
  const int width = front.width(), height = front.height();
  std::vector<uint8_t> rgb(size_t(width) * size_t(height) * 3);
  const auto* src = reinterpret_cast<const uint8_t*>(front.level(0).data.data());
  for (size_t i = 0; i < size_t(width) * size_t(height); ++i) {
    rgb[i * 3 + 0] = src[i * 4 + 0];
    rgb[i * 3 + 1] = src[i * 4 + 1];
    rgb[i * 3 + 2] = src[i * 4 + 2];
  }
  return write_rgb(rgb, width, height, dir, frame, window);
}

std::string write_headless_image(const std::vector<uint8_t>& rgba_top_down, int width, int height,
                                 const std::string& dir, int frame, int window) {
  std::vector<uint8_t> rgb(size_t(width) * size_t(height) * 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = &rgba_top_down[(size_t(height - 1 - y) * size_t(width) + size_t(x)) * 4];
      uint8_t* q = &rgb[(size_t(y) * size_t(width) + size_t(x)) * 3];
      q[0] = p[0], q[1] = p[1], q[2] = p[2];
    }
  return write_rgb(rgb, width, height, dir, frame, window);
}

}  // namespace tessel::gl
