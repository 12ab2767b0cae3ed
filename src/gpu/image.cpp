// Image files in and out through stb_image / stb_image_write (linked from libstb).
#include "tessel/gpu/image.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include <stb_image.h>
#include <stb_image_write.h>

namespace tessel::gpu {

namespace {

// Reverses the row order of a tightly packed image in place (top-down <-> bottom-up).
template <class T>
void flip_rows(T* data, int width, int height, int channels) {
  const size_t row = size_t(width) * size_t(channels);
  std::vector<T> tmp(row);
  for (int y = 0; y < height / 2; ++y) {
    T* a = data + size_t(y) * row;
    T* b = data + size_t(height - 1 - y) * row;
    std::memcpy(tmp.data(), a, row * sizeof(T));
    std::memcpy(a, b, row * sizeof(T));
    std::memcpy(b, tmp.data(), row * sizeof(T));
  }
}

std::string reason() {
  const char* r = stbi_failure_reason();
  return r ? r : "unknown error";
}

struct StbFree {
  void operator()(void* p) const { stbi_image_free(p); }
};

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  const auto* p = static_cast<const uint8_t*>(data);
  out->insert(out->end(), p, p + size);
}

std::string temp_path_for(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  return path + ".tmp-" + std::to_string(long(::getpid())) + "-" + std::to_string(counter.fetch_add(1));
}

// Writes bytes to path atomically: a temporary file next to it, then rename.
void write_file_atomic(const std::string& path, const std::vector<uint8_t>& bytes) {
  // The folders on the way are made, as a user of `-o out/new/dir/x.png` expects.
  {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    if (ec) throw Error("write_png: cannot create the folder '" + parent.string() + "': " + ec.message());
  }
  const std::string tmp = temp_path_for(path);
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) {
    const int e = errno;
    throw Error("write_png: cannot create '" + path + "': " + std::strerror(e));
  }
  bool ok = bytes.empty() || std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  int e = ok ? 0 : errno;
  if (std::fflush(f) != 0 && ok) {
    ok = false;
    e = errno;
  }
  if (std::fclose(f) != 0 && ok) {
    ok = false;
    e = errno;
  }
  if (!ok) {
    std::remove(tmp.c_str());
    throw Error("write_png: cannot write '" + path + "': " + std::strerror(e));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    e = errno;
    std::remove(tmp.c_str());
    throw Error("write_png: cannot rename the temporary file to '" + path + "': " + std::strerror(e));
  }
}

inline uint8_t to_byte(float c) {
  c = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;  // NaN -> 0
  return uint8_t(std::lrint(c * 255.0f));
}

}  // namespace

Image load_image_from_memory(const void* data, size_t bytes, const std::string& name) {
  if (data == nullptr || bytes == 0) throw Error("load_image: '" + name + "' is empty");
  if (bytes > size_t(INT_MAX))
    throw Error("load_image: '" + name + "' is too large (" + std::to_string(bytes) + " bytes)");
  const auto* buf = static_cast<const stbi_uc*>(data);
  const int len = int(bytes);
  int w = 0, h = 0, comp = 0;
  if (!stbi_info_from_memory(buf, len, &w, &h, &comp))
    throw Error("load_image: cannot read '" + name + "': " + reason());
  if (w < 1 || h < 1 || w > kMaxTextureSize || h > kMaxTextureSize)
    throw Error("load_image: '" + name + "' is " + std::to_string(w) + "x" + std::to_string(h) +
                ", outside 1.." + std::to_string(kMaxTextureSize));
  Image img;
  if (stbi_is_hdr_from_memory(buf, len)) {
    std::unique_ptr<float, StbFree> p(stbi_loadf_from_memory(buf, len, &w, &h, &comp, 4));
    if (!p) throw Error("load_image: cannot decode '" + name + "': " + reason());
    img.hdr.assign(p.get(), p.get() + size_t(w) * size_t(h) * 4);
    flip_rows(img.hdr.data(), w, h, 4);
  } else {
    std::unique_ptr<stbi_uc, StbFree> p(stbi_load_from_memory(buf, len, &w, &h, &comp, 4));
    if (!p) throw Error("load_image: cannot decode '" + name + "': " + reason());
    img.pixels.assign(p.get(), p.get() + size_t(w) * size_t(h) * 4);
    flip_rows(img.pixels.data(), w, h, 4);
  }
  img.width = w;
  img.height = h;
  img.channels = 4;
  return img;
}

Image load_image(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) {
    const int e = errno;
    throw Error("load_image: cannot open '" + path + "': " + std::strerror(e));
  }
  std::vector<uint8_t> bytes;
  uint8_t chunk[65536];
  size_t n;
  while ((n = std::fread(chunk, 1, sizeof chunk, f)) > 0) bytes.insert(bytes.end(), chunk, chunk + n);
  const bool failed = std::ferror(f) != 0;
  const int e = errno;
  std::fclose(f);
  if (failed) throw Error("load_image: cannot read '" + path + "': " + std::strerror(e));
  return load_image_from_memory(bytes.data(), bytes.size(), path);
}

void write_png(const std::string& path, int width, int height, int channels, const uint8_t* rows_bottom_up) {
  if (width < 1 || height < 1 || size_t(width) * 4 > size_t(INT_MAX) ||
      size_t(height) > size_t(INT_MAX) / (size_t(width) * 4))
    throw Error("write_png: '" + path + "': bad size " + std::to_string(width) + "x" +
                std::to_string(height));
  if (channels < 1 || channels > 4)
    throw Error("write_png: '" + path + "': bad channel count " + std::to_string(channels));
  if (rows_bottom_up == nullptr) throw Error("write_png: '" + path + "': null pixels");
  const size_t row = size_t(width) * size_t(channels);
  std::vector<uint8_t> top_down(rows_bottom_up, rows_bottom_up + row * size_t(height));
  flip_rows(top_down.data(), width, height, channels);
  std::vector<uint8_t> png;
  if (!stbi_write_png_to_func(append_bytes, &png, width, height, channels, top_down.data(), int(row)))
    throw Error("write_png: cannot encode '" + path + "'");
  write_file_atomic(path, png);
}

std::vector<uint8_t> read_rgba8(const Texture2D& texture, int level) {
  if (level < 0 || level >= texture.levels())
    throw Error("read_rgba8: level " + std::to_string(level) + " out of range (texture has " +
                std::to_string(texture.levels()) + " levels)");
  const Level& l = texture.level(level);
  const size_t n = size_t(l.width) * size_t(l.height);
  std::vector<uint8_t> out(n * 4);
  const Format f = texture.format();
  if (f == Format::RGBA8) {
    std::memcpy(out.data(), l.data.data(), n * 4);
    return out;
  }
  const bool depth = is_depth_format(f);
  for (int y = 0; y < l.height; ++y)
    for (int x = 0; x < l.width; ++x) {
      const glm::vec4 c = texture.fetch(level, x, y);
      uint8_t* p = out.data() + (size_t(y) * size_t(l.width) + size_t(x)) * 4;
      if (depth) {
        p[0] = p[1] = p[2] = to_byte(c.x);
        p[3] = 255;
      } else {
        p[0] = to_byte(c.x);
        p[1] = to_byte(c.y);
        p[2] = to_byte(c.z);
        p[3] = to_byte(c.w);
      }
    }
  return out;
}

void write_png(const std::string& path, const Texture2D& texture, int level) {
  const std::vector<uint8_t> rgba = read_rgba8(texture, level);
  write_png(path, texture.width(level), texture.height(level), 4, rgba.data());
}

Texture2D make_texture(const Image& image, bool mipmaps) {
  const int w = image.width, h = image.height;
  if (w < 1 || h < 1 || w > kMaxTextureSize || h > kMaxTextureSize)
    throw Error("make_texture: bad image size " + std::to_string(w) + "x" + std::to_string(h));
  const size_t n = size_t(w) * size_t(h);
  const int levels = mipmaps ? 0 : 1;
  if (image.is_hdr()) {
    if (image.channels != 4 || image.hdr.size() != n * 4)
      throw Error("make_texture: a float image must be RGBA with " + std::to_string(n * 4) + " values, has " +
                  std::to_string(image.hdr.size()) + " in " + std::to_string(image.channels) + " channels");
    Texture2D t(Format::RGBA32F, w, h, levels);
    t.upload_rgba32f(0, image.hdr.data(), n * 16);
    if (mipmaps) t.generate_mipmaps();
    return t;
  }
  const int ch = image.channels;
  if (ch < 1 || ch > 4 || image.pixels.size() != n * size_t(ch))
    throw Error("make_texture: image of " + std::to_string(w) + "x" + std::to_string(h) + "x" +
                std::to_string(ch) + " needs " + std::to_string(n * size_t(std::max(ch, 0))) +
                " bytes, has " + std::to_string(image.pixels.size()));
  Texture2D t(Format::RGBA8, w, h, levels);
  if (ch == 4) {
    t.upload_rgba8(0, image.pixels.data(), n * 4);
  } else {
    // Expand as stb_image does: grey -> (g, g, g), grey+alpha -> (g, g, g, a), RGB -> alpha 255.
    std::vector<uint8_t> rgba(n * 4);
    for (size_t i = 0; i < n; ++i) {
      const uint8_t* s = image.pixels.data() + i * size_t(ch);
      uint8_t* d = rgba.data() + i * 4;
      if (ch <= 2) {
        d[0] = d[1] = d[2] = s[0];
        d[3] = ch == 2 ? s[1] : 255;
      } else {
        d[0] = s[0];
        d[1] = s[1];
        d[2] = s[2];
        d[3] = 255;
      }
    }
    t.upload_rgba8(0, rgba.data(), rgba.size());
  }
  if (mipmaps) t.generate_mipmaps();
  return t;
}

}  // namespace tessel::gpu
