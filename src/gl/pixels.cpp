// Pixel transfer: unpacking client images into RGBA, packing RGBA into client memory.
#include "pixels.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace tessel::gl {

int format_components(GLenum format) {
  switch (format) {
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_LUMINANCE:
    case GL_DEPTH_COMPONENT:
    case GL_STENCIL_INDEX:
    case GL_COLOR_INDEX: return 1;
    case GL_LUMINANCE_ALPHA: return 2;
    case GL_RGB:
    case GL_BGR: return 3;
    case GL_RGBA:
    case GL_BGRA: return 4;
    default: return 0;
  }
}

int type_bytes(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT:
    case GL_SHORT: return 2;
    case GL_UNSIGNED_INT:
    case GL_INT:
    case GL_FLOAT: return 4;
    case GL_BITMAP: return 0;
    default: return -1;
  }
}

bool valid_pixel_format(GLenum format) { return format_components(format) > 0; }
bool valid_pixel_type(GLenum type) { return type_bytes(type) >= 0; }

PixelLayout pixel_layout(const PixelStore& ps, int width, GLenum format, GLenum type) {
  PixelLayout L;
  const size_t n = size_t(format_components(format));
  const size_t l = size_t(ps.row_length > 0 ? ps.row_length : width);
  const size_t a = size_t(ps.alignment);
  if (type == GL_BITMAP) {
    L.row_stride = a * ((l + 8 * a - 1) / (8 * a));
    L.pixel_stride = 0;
    L.offset = size_t(ps.skip_rows) * L.row_stride;  // skip_pixels is applied in bits
    return L;
  }
  const size_t s = size_t(type_bytes(type));
  size_t k;  // elements per row (GL 2.1 eq. 3.1)
  if (s >= a)
    k = n * l;
  else
    k = (a / s) * ((s * n * l + a - 1) / a);
  L.row_stride = k * s;
  L.pixel_stride = n * s;
  L.offset = size_t(ps.skip_pixels) * n * s + size_t(ps.skip_rows) * L.row_stride;
  return L;
}

namespace {

// GL_*_SWAP_BYTES for a 2- or 4-byte component.
void swap_bytes(uint8_t* b, int size) {
  if (size == 2) {
    std::swap(b[0], b[1]);
  } else if (size == 4) {
    std::swap(b[0], b[3]);
    std::swap(b[1], b[2]);
  }
}

float read_component(const uint8_t* p, GLenum type, bool swap) {
  uint8_t b[4] = {0, 0, 0, 0};
  const int sz = std::clamp(type_bytes(type), 1, 4);
  std::memcpy(b, p, size_t(sz));
  if (swap) swap_bytes(b, sz);
  switch (type) {
    case GL_UNSIGNED_BYTE: return float(b[0]) / 255.0f;
    case GL_BYTE: return (2.0f * float(int8_t(b[0])) + 1.0f) / 255.0f;
    case GL_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, b, 2);
      return float(v) / 65535.0f;
    }
    case GL_SHORT: {
      int16_t v;
      std::memcpy(&v, b, 2);
      return (2.0f * float(v) + 1.0f) / 65535.0f;
    }
    case GL_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, b, 4);
      return float(double(v) / 4294967295.0);
    }
    case GL_INT: {
      int32_t v;
      std::memcpy(&v, b, 4);
      return float((2.0 * double(v) + 1.0) / 4294967295.0);
    }
    default: {
      float v;
      std::memcpy(&v, b, 4);
      return v;
    }
  }
}

void write_component(uint8_t* p, GLenum type, float v, bool swap) {
  uint8_t b[4] = {0, 0, 0, 0};
  const int sz = std::clamp(type_bytes(type), 1, 4);
  const double c = std::clamp(double(v),
                              type == GL_FLOAT                                          ? -1e38
                              : (type == GL_BYTE || type == GL_SHORT || type == GL_INT) ? -1.0
                                                                                        : 0.0,
                              type == GL_FLOAT ? 1e38 : 1.0);
  switch (type) {
    case GL_UNSIGNED_BYTE: b[0] = uint8_t(std::lround(c * 255.0)); break;
    case GL_BYTE: b[0] = uint8_t(int8_t(std::lround((c * 255.0 - 1.0) / 2.0))); break;
    case GL_UNSIGNED_SHORT: {
      const uint16_t x = uint16_t(std::lround(c * 65535.0));
      std::memcpy(b, &x, 2);
      break;
    }
    case GL_SHORT: {
      const int16_t x = int16_t(std::lround((c * 65535.0 - 1.0) / 2.0));
      std::memcpy(b, &x, 2);
      break;
    }
    case GL_UNSIGNED_INT: {
      const uint32_t x = uint32_t(std::llround(c * 4294967295.0));
      std::memcpy(b, &x, 4);
      break;
    }
    case GL_INT: {
      const int32_t x = int32_t(std::llround((c * 4294967295.0 - 1.0) / 2.0));
      std::memcpy(b, &x, 4);
      break;
    }
    default: {
      const float x = float(c);
      std::memcpy(b, &x, 4);
      break;
    }
  }
  if (swap) swap_bytes(b, sz);
  std::memcpy(p, b, size_t(sz));
}

}  // namespace

void unpack_pixels(const PixelStore& ps, int w, int h, GLenum format, GLenum type, const void* data,
                   std::vector<glm::vec4>& out) {
  out.assign(size_t(w) * size_t(h), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  if (!data || w <= 0 || h <= 0) return;
  if (type == GL_BITMAP) {
    std::vector<uint8_t> bits;
    unpack_bitmap(ps, w, h, data, bits);
    for (size_t i = 0; i < bits.size(); ++i) out[i] = glm::vec4(bits[i] ? 1.0f : 0.0f);
    return;
  }
  const PixelLayout L = pixel_layout(ps, w, format, type);
  const int n = format_components(format);
  const size_t cs = size_t(type_bytes(type));
  const uint8_t* base = static_cast<const uint8_t*>(data) + L.offset;
  const bool swap = ps.swap_bytes && cs > 1;
  for (int y = 0; y < h; ++y) {
    const uint8_t* row = base + size_t(y) * L.row_stride;
    for (int x = 0; x < w; ++x) {
      const uint8_t* p = row + size_t(x) * L.pixel_stride;
      float c[4] = {0, 0, 0, 1};
      for (int k = 0; k < n; ++k) c[k] = read_component(p + size_t(k) * cs, type, swap);
      glm::vec4& o = out[size_t(y) * size_t(w) + size_t(x)];
      switch (format) {
        case GL_RED: o = {c[0], 0, 0, 1}; break;
        case GL_GREEN: o = {0, c[0], 0, 1}; break;
        case GL_BLUE: o = {0, 0, c[0], 1}; break;
        case GL_ALPHA: o = {0, 0, 0, c[0]}; break;
        case GL_LUMINANCE: o = {c[0], c[0], c[0], 1}; break;
        case GL_LUMINANCE_ALPHA: o = {c[0], c[0], c[0], c[1]}; break;
        case GL_RGB: o = {c[0], c[1], c[2], 1}; break;
        case GL_BGR: o = {c[2], c[1], c[0], 1}; break;
        case GL_RGBA: o = {c[0], c[1], c[2], c[3]}; break;
        case GL_BGRA: o = {c[2], c[1], c[0], c[3]}; break;
        default: o = {c[0], 0, 0, 1}; break;  // depth, stencil, index: the value in .x
      }
    }
  }
}

void unpack_bitmap(const PixelStore& ps, int w, int h, const void* data, std::vector<uint8_t>& out) {
  out.assign(size_t(std::max(w, 0)) * size_t(std::max(h, 0)), 0);
  if (!data || w <= 0 || h <= 0) return;
  const PixelLayout L = pixel_layout(ps, w, GL_COLOR_INDEX, GL_BITMAP);
  const uint8_t* base = static_cast<const uint8_t*>(data) + L.offset;
  for (int y = 0; y < h; ++y) {
    const uint8_t* row = base + size_t(y) * L.row_stride;
    for (int x = 0; x < w; ++x) {
      const int bit = x + ps.skip_pixels;
      const uint8_t byte = row[bit / 8];
      const int shift = ps.lsb_first ? (bit % 8) : (7 - bit % 8);
      out[size_t(y) * size_t(w) + size_t(x)] = (byte >> shift) & 1;
    }
  }
}

void pack_pixels(const PixelStore& ps, int w, int h, GLenum format, GLenum type,
                 const std::vector<glm::vec4>& in, void* data) {
  if (!data || w <= 0 || h <= 0) return;
  const PixelLayout L = pixel_layout(ps, w, format, type);
  const size_t cs = size_t(type_bytes(type));
  uint8_t* base = static_cast<uint8_t*>(data) + L.offset;
  const bool swap = ps.swap_bytes && cs > 1;
  for (int y = 0; y < h; ++y) {
    uint8_t* row = base + size_t(y) * L.row_stride;
    for (int x = 0; x < w; ++x) {
      uint8_t* p = row + size_t(x) * L.pixel_stride;
      const glm::vec4& c = in[size_t(y) * size_t(w) + size_t(x)];
      float v[4];
      int n = 0;
      switch (format) {
        case GL_RED: v[n++] = c.r; break;
        case GL_GREEN: v[n++] = c.g; break;
        case GL_BLUE: v[n++] = c.b; break;
        case GL_ALPHA: v[n++] = c.a; break;
        // GL 2.1 §4.3.2: luminance is R + G + B (clamped).
        case GL_LUMINANCE: v[n++] = std::min(1.0f, c.r + c.g + c.b); break;
        case GL_LUMINANCE_ALPHA:
          v[n++] = std::min(1.0f, c.r + c.g + c.b);
          v[n++] = c.a;
          break;
        case GL_RGB: v[0] = c.r, v[1] = c.g, v[2] = c.b, n = 3; break;
        case GL_BGR: v[0] = c.b, v[1] = c.g, v[2] = c.r, n = 3; break;
        case GL_RGBA: v[0] = c.r, v[1] = c.g, v[2] = c.b, v[3] = c.a, n = 4; break;
        case GL_BGRA: v[0] = c.b, v[1] = c.g, v[2] = c.r, v[3] = c.a, n = 4; break;
        default: v[n++] = c.x; break;
      }
      for (int k = 0; k < n; ++k) write_component(p + size_t(k) * cs, type, v[k], swap);
    }
  }
}

bool base_format_of(GLint f, BaseFormat& base) {
  switch (f) {
    case 1:
    case GL_LUMINANCE:
    case GL_LUMINANCE4:
    case GL_LUMINANCE8:
    case GL_LUMINANCE12:
    case GL_LUMINANCE16: base = BaseFormat::Luminance; return true;
    case 2:
    case GL_LUMINANCE_ALPHA:
    case GL_LUMINANCE4_ALPHA4:
    case GL_LUMINANCE6_ALPHA2:
    case GL_LUMINANCE8_ALPHA8:
    case GL_LUMINANCE12_ALPHA4:
    case GL_LUMINANCE12_ALPHA12:
    case GL_LUMINANCE16_ALPHA16: base = BaseFormat::LuminanceAlpha; return true;
    case GL_ALPHA:
    case GL_ALPHA4:
    case GL_ALPHA8:
    case GL_ALPHA12:
    case GL_ALPHA16: base = BaseFormat::Alpha; return true;
    case GL_INTENSITY:
    case GL_INTENSITY4:
    case GL_INTENSITY8:
    case GL_INTENSITY12:
    case GL_INTENSITY16: base = BaseFormat::Intensity; return true;
    case 3:
    case GL_RGB:
    case GL_R3_G3_B2:
    case GL_RGB4:
    case GL_RGB5:
    case GL_RGB8:
    case GL_RGB10:
    case GL_RGB12:
    case GL_RGB16: base = BaseFormat::RGB; return true;
    case 4:
    case GL_RGBA:
    case GL_RGBA2:
    case GL_RGBA4:
    case GL_RGB5_A1:
    case GL_RGBA8:
    case GL_RGB10_A2:
    case GL_RGBA12:
    case GL_RGBA16: base = BaseFormat::RGBA; return true;
    default: return false;
  }
}

void to_texture_rgba8(const std::vector<glm::vec4>& in, BaseFormat base, std::vector<uint8_t>& out) {
  out.resize(in.size() * 4);
  for (size_t i = 0; i < in.size(); ++i) {
    const glm::vec4& c = in[i];
    uint8_t* o = &out[i * 4];
    switch (base) {
      case BaseFormat::Alpha: o[0] = o[1] = o[2] = 0, o[3] = unorm8(c.a); break;
      case BaseFormat::Luminance: o[0] = o[1] = o[2] = unorm8(c.r), o[3] = 255; break;
      case BaseFormat::LuminanceAlpha: o[0] = o[1] = o[2] = unorm8(c.r), o[3] = unorm8(c.a); break;
      case BaseFormat::Intensity: o[0] = o[1] = o[2] = o[3] = unorm8(c.r); break;
      case BaseFormat::RGB: o[0] = unorm8(c.r), o[1] = unorm8(c.g), o[2] = unorm8(c.b), o[3] = 255; break;
      case BaseFormat::RGBA:
        o[0] = unorm8(c.r), o[1] = unorm8(c.g), o[2] = unorm8(c.b), o[3] = unorm8(c.a);
        break;
    }
  }
}

}  // namespace tessel::gl
