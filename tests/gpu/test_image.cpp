// Image files: PNG round trips, row order, atomic writes and error reporting.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <stb_image.h>
#include <stb_image_write.h>

#include "tessel/gpu/image.hpp"

using namespace tessel::gpu;
namespace fs = std::filesystem;

namespace {

class ImageFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("tessel-image-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> files() const {
    std::vector<std::string> r;
    for (const auto& e : fs::directory_iterator(dir_)) r.push_back(e.path().filename().string());
    return r;
  }
  static std::vector<uint8_t> read_bytes(const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
  }
  static void write_bytes(const std::string& p, const void* data, size_t n) {
    std::ofstream f(p, std::ios::binary);
    f.write(static_cast<const char*>(data), std::streamsize(n));
  }
  static void expect_error_naming(const std::string& p, const std::string& name) {
    try {
      (void)load_image(p);
      ADD_FAILURE() << "no exception for " << p;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
  fs::path dir_;
};

// 3x2 RGBA, rows bottom-up: bottom row reds, top row greens.
std::vector<uint8_t> sample_pixels() {
  return {
      10, 0,  0, 255, 20, 0,  0, 200, 30, 0,  0, 100,  // y = 0 (bottom)
      0,  40, 0, 255, 0,  50, 0, 128, 0,  60, 7, 0,    // y = 1 (top)
  };
}

}  // namespace

TEST_F(ImageFiles, PngRoundTripKeepsBottomUpRows) {
  const std::vector<uint8_t> px = sample_pixels();
  const std::string p = path("a.png");
  write_png(p, 3, 2, 4, px.data());
  const Image img = load_image(p);
  EXPECT_EQ(img.width, 3);
  EXPECT_EQ(img.height, 2);
  EXPECT_EQ(img.channels, 4);
  EXPECT_FALSE(img.is_hdr());
  EXPECT_EQ(img.pixels, px);

  // In the file the first row is the top one: memory's last row.
  int w = 0, h = 0, c = 0;
  stbi_uc* raw = stbi_load(p.c_str(), &w, &h, &c, 4);
  ASSERT_NE(raw, nullptr);
  EXPECT_EQ(std::vector<uint8_t>(raw, raw + 12), std::vector<uint8_t>(px.begin() + 12, px.end()));
  EXPECT_EQ(std::vector<uint8_t>(raw + 12, raw + 24), std::vector<uint8_t>(px.begin(), px.begin() + 12));
  stbi_image_free(raw);
  EXPECT_EQ(files(), std::vector<std::string>{"a.png"});  // no temporary left behind
}

TEST_F(ImageFiles, GreyAndRgbExpandToRgba) {
  const uint8_t grey[4] = {0, 85, 170, 255};  // 2x2
  write_png(path("g.png"), 2, 2, 1, grey);
  Image g = load_image(path("g.png"));
  ASSERT_EQ(g.pixels.size(), 16u);
  EXPECT_EQ(g.pixels[4 * 1 + 0], 85);
  EXPECT_EQ(g.pixels[4 * 1 + 1], 85);
  EXPECT_EQ(g.pixels[4 * 1 + 2], 85);
  EXPECT_EQ(g.pixels[4 * 1 + 3], 255);
  EXPECT_EQ(g.pixels[4 * 3 + 0], 255);
  const uint8_t rgb[6] = {1, 2, 3, 4, 5, 6};  // 1x2: bottom (1,2,3), top (4,5,6)
  write_png(path("c.png"), 1, 2, 3, rgb);
  Image c = load_image(path("c.png"));
  EXPECT_EQ(c.pixels, (std::vector<uint8_t>{1, 2, 3, 255, 4, 5, 6, 255}));
}

// The folders of the path are made, as a user of `-o out/new/dir/x.png` expects.
TEST_F(ImageFiles, WriteToMissingFolderMakesIt) {
  const std::vector<uint8_t> px = sample_pixels();
  const std::string p = path("no/such/folder/x.png");
  write_png(p, 3, 2, 4, px.data());
  EXPECT_TRUE(fs::exists(p));
  EXPECT_EQ(load_image(p).width, 3);
}

// A folder that cannot be made (a file is in its way) is an error naming the path, and
// nothing is left behind.
TEST_F(ImageFiles, WriteWhereNoFolderCanBeMadeThrowsAndLeavesNothing) {
  const std::vector<uint8_t> px = sample_pixels();
  { std::ofstream(path("blocker")) << "a file, not a folder"; }
  const std::string p = path("blocker/sub/x.png");
  try {
    write_png(p, 3, 2, 4, px.data());
    FAIL() << "no exception";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("blocker"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(p));
  EXPECT_EQ(files().size(), 1u);  // the blocker alone
}

TEST_F(ImageFiles, FailedRenameRemovesTheTemporary) {
  // The target is a directory: the temporary is written, the rename fails.
  fs::create_directory(path("target.png"));
  const std::vector<uint8_t> px = sample_pixels();
  EXPECT_THROW(write_png(path("target.png"), 3, 2, 4, px.data()), Error);
  EXPECT_EQ(files(), std::vector<std::string>{"target.png"});
  EXPECT_TRUE(fs::is_directory(path("target.png")));
}

TEST_F(ImageFiles, OverwriteReplacesTheFile) {
  const std::vector<uint8_t> px = sample_pixels();
  write_png(path("o.png"), 3, 2, 4, px.data());
  const uint8_t one[4] = {9, 8, 7, 6};
  write_png(path("o.png"), 1, 1, 4, one);
  const Image img = load_image(path("o.png"));
  EXPECT_EQ(img.width, 1);
  EXPECT_EQ(img.pixels, (std::vector<uint8_t>{9, 8, 7, 6}));
  EXPECT_EQ(files().size(), 1u);
}

TEST_F(ImageFiles, BadWriteArgumentsThrow) {
  const uint8_t px[4] = {};
  EXPECT_THROW(write_png(path("b.png"), 0, 1, 4, px), Error);
  EXPECT_THROW(write_png(path("b.png"), 1, 1, 5, px), Error);
  EXPECT_THROW(write_png(path("b.png"), 1, 1, 4, nullptr), Error);
  EXPECT_TRUE(files().empty());
}

TEST_F(ImageFiles, LoadErrorsNameTheFile) {
  expect_error_naming(path("missing.png"), "missing.png");

  const std::string text = "this is not an image at all\n";
  write_bytes(path("notes.png"), text.data(), text.size());
  expect_error_naming(path("notes.png"), "notes.png");

  // A real PNG cut in half.
  std::vector<uint8_t> big(64 * 64 * 4);
  for (size_t i = 0; i < big.size(); ++i) big[i] = uint8_t(i * 7919u >> 3);
  write_png(path("full.png"), 64, 64, 4, big.data());
  std::vector<uint8_t> bytes = read_bytes(path("full.png"));
  ASSERT_GT(bytes.size(), 100u);
  write_bytes(path("cut.png"), bytes.data(), bytes.size() / 2);
  expect_error_naming(path("cut.png"), "cut.png");

  write_bytes(path("empty.png"), "", 0);
  expect_error_naming(path("empty.png"), "empty.png");

  try {
    (void)load_image_from_memory(text.data(), text.size(), "in-memory-name");
    ADD_FAILURE() << "no exception";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("in-memory-name"), std::string::npos) << e.what();
  }
}

TEST_F(ImageFiles, TooLargeImagesAreRejected) {
  std::vector<uint8_t> row(size_t(kMaxTextureSize) + 1, 128);
  write_png(path("wide.png"), kMaxTextureSize + 1, 1, 1, row.data());
  try {
    (void)load_image(path("wide.png"));
    FAIL() << "no exception";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("wide.png"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("16385"), std::string::npos) << e.what();
  }
}

TEST_F(ImageFiles, FromMemoryAndHdr) {
  const std::vector<uint8_t> px = sample_pixels();
  write_png(path("m.png"), 3, 2, 4, px.data());
  const std::vector<uint8_t> bytes = read_bytes(path("m.png"));
  const Image img = load_image_from_memory(bytes.data(), bytes.size(), "m");
  EXPECT_EQ(img.pixels, px);

  // HDR stays float; rows flip the same way (file top row = memory's last).
  const float top_down[2 * 3] = {4.0f, 0.5f, 0.25f, 1.0f, 2.0f, 8.0f};  // 1x2, RGB
  ASSERT_TRUE(stbi_write_hdr(path("h.hdr").c_str(), 1, 2, 3, top_down));
  const Image hdr = load_image(path("h.hdr"));
  ASSERT_TRUE(hdr.is_hdr());
  ASSERT_EQ(hdr.hdr.size(), 8u);
  EXPECT_TRUE(hdr.pixels.empty());
  EXPECT_NEAR(hdr.hdr[0], 1.0f, 0.02f);  // bottom row = file's second row
  EXPECT_NEAR(hdr.hdr[2], 8.0f, 0.1f);
  EXPECT_NEAR(hdr.hdr[4], 4.0f, 0.05f);
  EXPECT_EQ(hdr.hdr[7], 1.0f);
  const Texture2D t = make_texture(hdr, false);
  EXPECT_EQ(t.format(), Format::RGBA32F);
  EXPECT_NEAR(t.fetch(0, 0, 1).x, 4.0f, 0.05f);
}

TEST_F(ImageFiles, TextureToPngConvertsFormats) {
  Texture2D r8(Format::R8, 2, 1);
  const uint8_t r[2] = {51, 204};
  r8.upload(0, r, 2);
  write_png(path("r8.png"), r8);
  EXPECT_EQ(load_image(path("r8.png")).pixels, (std::vector<uint8_t>{51, 0, 0, 255, 204, 0, 0, 255}));

  Texture2D f(Format::RGBA32F, 1, 1);
  const float c[4] = {2.0f, -1.0f, 0.5f, 1.0f};
  f.upload(0, c, sizeof c);
  EXPECT_EQ(read_rgba8(f), (std::vector<uint8_t>{255, 0, 128, 255}));

  Texture2D d(Format::Depth32F, 1, 2);
  const float dv[2] = {0.0f, 0.6f};
  d.upload(0, dv, sizeof dv);
  write_png(path("d.png"), d);
  EXPECT_EQ(load_image(path("d.png")).pixels, (std::vector<uint8_t>{0, 0, 0, 255, 153, 153, 153, 255}));

  Texture2D m(Format::RGBA8, 4, 2, 0);
  EXPECT_THROW(read_rgba8(m, 4), Error);
  write_png(path("level2.png"), m, 2);
  EXPECT_EQ(load_image(path("level2.png")).width, 1);
}

TEST_F(ImageFiles, MakeTextureWithMipmaps) {
  Image img;
  img.width = 2;
  img.height = 2;
  img.channels = 4;
  img.pixels = {0, 0, 0, 255, 100, 0, 0, 255, 0, 200, 0, 255, 100, 200, 40, 255};
  const Texture2D t = make_texture(img, true);
  EXPECT_EQ(t.format(), Format::RGBA8);
  ASSERT_EQ(t.levels(), 2);
  EXPECT_EQ(read_rgba8(t, 0), img.pixels);
  EXPECT_EQ(read_rgba8(t, 1), (std::vector<uint8_t>{50, 100, 10, 255}));
  EXPECT_EQ(make_texture(img, false).levels(), 1);

  Image grey;
  grey.width = 2;
  grey.height = 1;
  grey.channels = 2;
  grey.pixels = {10, 20, 30, 40};
  EXPECT_EQ(read_rgba8(make_texture(grey, false)), (std::vector<uint8_t>{10, 10, 10, 20, 30, 30, 30, 40}));

  Image bad = img;
  bad.pixels.pop_back();
  EXPECT_THROW(make_texture(bad, false), Error);
  bad = img;
  bad.width = 0;
  EXPECT_THROW(make_texture(bad, false), Error);
}
