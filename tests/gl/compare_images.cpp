// compare_images: compares two PNG images pixel by pixel (the GL acceptance tests' judge).
//
//   compare_images A.png B.png [--tolerance T] [--min-match P] [--diff OUT.png]
//       A pixel matches when each of its R, G and B channels differs by at most T (0-255,
//       default 3); alpha is ignored. Prints the size, the percentage of matching pixels,
//       the largest channel difference and the number of differing pixels. Exit status:
//       0 when the match percentage is at least P (default 99.5), 1 when it is not,
//       2 when an input cannot be read, the sizes differ or the arguments are wrong.
//       --diff writes a picture of the differences: differing pixels in red over a dimmed
//       grey copy of A.
//
//   compare_images --not-blank A.png [--min-content P]
//       Checks that an image shows something: at least P percent (default 1.0) of its pixels
//       differ (by more than 3 in some channel) from its most common colour, the background.
//       Exit status 0 when it does, 1 when it is blank, 2 when it cannot be read.
#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, first row at the top
};

std::optional<Image> load(const std::string& path) {
  int w = 0, h = 0, comp = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &comp, 4);
  if (!data) {
    const char* why = stbi_failure_reason();
    std::fprintf(stderr, "compare_images: cannot read '%s': %s\n", path.c_str(), why ? why : "unknown error");
    return std::nullopt;
  }
  Image img;
  img.width = w;
  img.height = h;
  img.rgba.assign(data, data + static_cast<std::size_t>(w) * h * 4);
  stbi_image_free(data);
  return img;
}

[[noreturn]] void usage(const char* msg) {
  std::fprintf(stderr,
               "compare_images: %s\n"
               "usage: compare_images A.png B.png [--tolerance 3] [--min-match 99.5] [--diff OUT.png]\n"
               "       compare_images --not-blank A.png [--min-content 1.0]\n",
               msg);
  std::exit(2);
}

double parse_number(std::string_view opt, const char* text, double lo, double hi) {
  char* end = nullptr;
  double v = std::strtod(text, &end);
  if (!end || *end || end == text || !(v >= lo && v <= hi)) {
    std::string m = std::string(opt) + " needs a number in [" + std::to_string(lo) + ", " +
                    std::to_string(hi) + "], got '" + text + "'";
    usage(m.c_str());
  }
  return v;
}

int max_channel_diff(const std::uint8_t* a, const std::uint8_t* b) {
  int d = 0;
  for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
  return d;
}

int not_blank(const std::string& path, double min_content) {
  auto img = load(path);
  if (!img) return 2;
  const std::size_t n = static_cast<std::size_t>(img->width) * img->height;
  std::unordered_map<std::uint32_t, std::size_t> counts;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* p = &img->rgba[i * 4];
    ++counts[(std::uint32_t(p[0]) << 16) | (std::uint32_t(p[1]) << 8) | p[2]];
  }
  std::uint32_t bg = 0;
  std::size_t best = 0;
  for (auto [colour, count] : counts)
    if (count > best || (count == best && colour < bg)) bg = colour, best = count;
  const std::uint8_t bgc[3] = {std::uint8_t(bg >> 16), std::uint8_t(bg >> 8), std::uint8_t(bg)};
  std::size_t content = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (max_channel_diff(&img->rgba[i * 4], bgc) > 3) ++content;
  const double pct = n ? 100.0 * double(content) / double(n) : 0.0;
  std::printf(
      "image: %s\nsize: %dx%d\nbackground: #%02x%02x%02x\ncolours: %zu\ncontent: %.3f%% (%zu pixels)\n",
      path.c_str(), img->width, img->height, bgc[0], bgc[1], bgc[2], counts.size(), pct, content);
  if (pct < min_content) {
    std::printf("BLANK: only %.3f%% of the pixels differ from the background (need %.3f%%)\n", pct,
                min_content);
    return 1;
  }
  std::printf("not blank\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  int tolerance = 3;
  double min_match = 99.5;
  double min_content = 1.0;
  bool blank_mode = false;
  std::string diff_path;
  for (int i = 1; i < argc; ++i) {
    std::string_view a = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) usage((std::string(a) + " needs a value").c_str());
      return argv[++i];
    };
    if (a == "--tolerance")
      tolerance = int(parse_number(a, value(), 0, 255));
    else if (a == "--min-match")
      min_match = parse_number(a, value(), 0, 100);
    else if (a == "--min-content")
      min_content = parse_number(a, value(), 0, 100);
    else if (a == "--diff")
      diff_path = value();
    else if (a == "--not-blank")
      blank_mode = true;
    else if (a == "-h" || a == "--help")
      usage("compares two PNG images");
    else if (a.size() > 1 && a[0] == '-')
      usage(("unknown option " + std::string(a)).c_str());
    else
      files.emplace_back(a);
  }
  if (blank_mode) {
    if (files.size() != 1) usage("--not-blank takes one image");
    return not_blank(files[0], min_content);
  }
  if (files.size() != 2) usage("need two images");

  auto a = load(files[0]);
  auto b = load(files[1]);
  if (!a || !b) return 2;
  if (a->width != b->width || a->height != b->height) {
    std::fprintf(stderr, "compare_images: size mismatch: '%s' is %dx%d but '%s' is %dx%d\n", files[0].c_str(),
                 a->width, a->height, files[1].c_str(), b->width, b->height);
    return 2;
  }

  const std::size_t n = static_cast<std::size_t>(a->width) * a->height;
  std::size_t differing = 0;
  int max_diff = 0;
  std::vector<std::uint8_t> vis;
  if (!diff_path.empty()) vis.resize(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* pa = &a->rgba[i * 4];
    const std::uint8_t* pb = &b->rgba[i * 4];
    const int d = max_channel_diff(pa, pb);
    max_diff = std::max(max_diff, d);
    const bool bad = d > tolerance;
    differing += bad;
    if (!vis.empty()) {
      std::uint8_t* v = &vis[i * 3];
      if (bad) {
        v[0] = 255, v[1] = 0, v[2] = 0;
      } else {
        const int grey = (pa[0] * 77 + pa[1] * 150 + pa[2] * 29) >> 8;
        v[0] = v[1] = v[2] = std::uint8_t(32 + grey / 4);
      }
    }
  }
  const double match = n ? 100.0 * double(n - differing) / double(n) : 100.0;
  std::printf(
      "size: %dx%d\nmatch: %.3f%% of pixels within %d/255 (need %.3f%%)\nmax channel difference: %d\n"
      "differing pixels: %zu of %zu\n",
      a->width, a->height, match, tolerance, min_match, max_diff, differing, n);
  if (!vis.empty()) {
    if (!stbi_write_png(diff_path.c_str(), a->width, a->height, 3, vis.data(), a->width * 3)) {
      std::fprintf(stderr, "compare_images: cannot write the diff image '%s'\n", diff_path.c_str());
      return 2;
    }
    std::printf("diff image: %s\n", diff_path.c_str());
  }
  const bool pass = match >= min_match;
  std::printf("%s\n", pass ? "PASS" : "FAIL");
  return pass ? 0 : 1;
}
