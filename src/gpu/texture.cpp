// Textures: storage, conversion, mipmap generation, and the scalar sampling core.
#include "tessel/gpu/texture.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <type_traits>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

// Sampling helpers are forced inline: a glm::vec4 returned across a call boundary goes
// through two 8-byte registers and stalls store forwarding when reloaded whole.
#define TESSEL_INLINE inline __attribute__((always_inline))
#define TESSEL_INLINE_LAMBDA __attribute__((always_inline))

namespace tessel::gpu {
using namespace detail;

namespace {

std::string size_string(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

int full_chain_levels(int w, int h) {
  int m = std::max(w, h), n = 1;
  while (m > 1) {
    m >>= 1;
    ++n;
  }
  return n;
}

// --- texel encoding ----------------------------------------------------------------------

constexpr double kD24Max = 16777215.0;

inline float unorm8_to_float(uint8_t v) { return float(v) * (1.0f / 255.0f); }
inline float sat(float c) { return c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f; }  // NaN -> 0
// GL's float -> unorm conversion: round to nearest of clamp(c, 0, 1) * 255.
inline uint8_t float_to_unorm8(float c) { return uint8_t(std::lrint(sat(c) * 255.0f)); }
inline uint32_t float_to_unorm24(float d) { return uint32_t(std::llrint(double(sat(d)) * kD24Max)); }
inline float unorm24_to_float(uint32_t d) { return float(double(d & 0xFFFFFFu) * (1.0 / kD24Max)); }

template <Format F>
TESSEL_INLINE glm::vec4 decode(const std::byte* p) {
  if constexpr (F == Format::RGBA8) {
    uint8_t b[4];
    std::memcpy(b, p, 4);
    return {unorm8_to_float(b[0]), unorm8_to_float(b[1]), unorm8_to_float(b[2]), unorm8_to_float(b[3])};
  } else if constexpr (F == Format::R8) {
    return {unorm8_to_float(uint8_t(p[0])), 0.0f, 0.0f, 1.0f};
  } else if constexpr (F == Format::RG8) {
    return {unorm8_to_float(uint8_t(p[0])), unorm8_to_float(uint8_t(p[1])), 0.0f, 1.0f};
  } else if constexpr (F == Format::RGBA16F) {
    uint16_t h[4];
    std::memcpy(h, p, 8);
    return {half_to_float(h[0]), half_to_float(h[1]), half_to_float(h[2]), half_to_float(h[3])};
  } else if constexpr (F == Format::RGBA32F) {
    glm::vec4 v;
    std::memcpy(&v[0], p, 16);
    return v;
  } else if constexpr (F == Format::Depth24) {
    uint32_t w;
    std::memcpy(&w, p, 4);
    return {unorm24_to_float(w), 0.0f, 0.0f, 1.0f};
  } else if constexpr (F == Format::Depth32F) {
    float d;
    std::memcpy(&d, p, 4);
    return {d, 0.0f, 0.0f, 1.0f};
  } else {
    static_assert(F == Format::Depth24Stencil8);
    uint32_t w;
    std::memcpy(&w, p, 4);
    return {unorm24_to_float(w), float(w >> 24), 0.0f, 1.0f};
  }
}

// Calls fn(std::integral_constant<Format, F>{}) for the runtime format f.
template <class Fn>
decltype(auto) with_format(Format f, Fn&& fn) {
  using F = Format;
  switch (f) {
    case F::RGBA8: return fn(std::integral_constant<F, F::RGBA8>{});
    case F::R8: return fn(std::integral_constant<F, F::R8>{});
    case F::RG8: return fn(std::integral_constant<F, F::RG8>{});
    case F::RGBA16F: return fn(std::integral_constant<F, F::RGBA16F>{});
    case F::RGBA32F: return fn(std::integral_constant<F, F::RGBA32F>{});
    case F::Depth24: return fn(std::integral_constant<F, F::Depth24>{});
    case F::Depth32F: return fn(std::integral_constant<F, F::Depth32F>{});
    case F::Depth24Stencil8: break;
  }
  return fn(std::integral_constant<F, F::Depth24Stencil8>{});
}

}  // namespace

glm::vec4 detail::decode_texel(Format f, const std::byte* p) {
  return with_format(f, [p](auto tag) { return decode<decltype(tag)::value>(p); });
}

void detail::encode_texel(Format f, std::byte* p, const glm::vec4& c) {
  switch (f) {
    case Format::RGBA8: {
      const uint8_t b[4] = {float_to_unorm8(c.x), float_to_unorm8(c.y), float_to_unorm8(c.z),
                            float_to_unorm8(c.w)};
      std::memcpy(p, b, 4);
      return;
    }
    case Format::R8: p[0] = std::byte(float_to_unorm8(c.x)); return;
    case Format::RG8:
      p[0] = std::byte(float_to_unorm8(c.x));
      p[1] = std::byte(float_to_unorm8(c.y));
      return;
    case Format::RGBA16F: {
      const uint16_t h[4] = {float_to_half(c.x), float_to_half(c.y), float_to_half(c.z), float_to_half(c.w)};
      std::memcpy(p, h, 8);
      return;
    }
    case Format::RGBA32F: std::memcpy(p, &c[0], 16); return;
    case Format::Depth24: {
      const uint32_t w = float_to_unorm24(c.x);
      std::memcpy(p, &w, 4);
      return;
    }
    case Format::Depth32F: {
      const float d = sat(c.x);  // depth values are clamped to [0, 1]
      std::memcpy(p, &d, 4);
      return;
    }
    case Format::Depth24Stencil8: {
      const float s = c.y > 0.0f ? (c.y < 255.0f ? c.y : 255.0f) : 0.0f;
      const uint32_t w = float_to_unorm24(c.x) | (uint32_t(std::lrint(s)) << 24);
      std::memcpy(p, &w, 4);
      return;
    }
  }
}

namespace {
using detail::decode_texel;
using detail::encode_texel;

bool is_unorm8(Format f) { return is_unorm8_format(f); }

// --- mipmap generation -------------------------------------------------------------------

// The source texels (up to three) and weights that make one destination texel along an axis.
// Even sizes: two texels, 1/2 each. Odd sizes 2n+1 -> n: texel x covers the source span
// [x (2n+1)/n, (x+1)(2n+1)/n), i.e. texels 2x, 2x+1, 2x+2 with weights (n-x), n, (x+1) over
// 2n+1, so every source texel contributes its full share. Size 1 stays 1.
struct Taps {
  int index[3];
  float weight[3];
  int count;
};

std::vector<Taps> axis_taps(int src, int dst) {
  std::vector<Taps> taps(static_cast<size_t>(dst));
  for (int x = 0; x < dst; ++x) {
    Taps& t = taps[size_t(x)];
    if (src == 1) {
      t = {{0, 0, 0}, {1.0f, 0.0f, 0.0f}, 1};
    } else if (src % 2 == 0) {
      t = {{2 * x, 2 * x + 1, 0}, {0.5f, 0.5f, 0.0f}, 2};
    } else {
      const int n = dst;
      const float inv = 1.0f / float(src);
      t = {{2 * x, 2 * x + 1, 2 * x + 2}, {float(n - x) * inv, float(n) * inv, float(x + 1) * inv}, 3};
    }
  }
  return taps;
}

void downsample(Format f, const Level& src, Level& dst) {
  const std::vector<Taps> tx = axis_taps(src.width, dst.width);
  const std::vector<Taps> ty = axis_taps(src.height, dst.height);
  const size_t bpp = format_info(f).bytes;
  if (is_unorm8(f)) {
    // Average the stored bytes directly (exact for the 2x2 case), round half up.
    const int ch = int(bpp);
    const uint8_t* s = reinterpret_cast<const uint8_t*>(src.data.data());
    uint8_t* d = reinterpret_cast<uint8_t*>(dst.data.data());
    for (int y = 0; y < dst.height; ++y) {
      const Taps& yt = ty[size_t(y)];
      for (int x = 0; x < dst.width; ++x) {
        const Taps& xt = tx[size_t(x)];
        float acc[4] = {0, 0, 0, 0};
        for (int j = 0; j < yt.count; ++j) {
          const uint8_t* row = s + size_t(yt.index[j]) * size_t(src.width) * bpp;
          for (int i = 0; i < xt.count; ++i) {
            const float w = yt.weight[j] * xt.weight[i];
            const uint8_t* px = row + size_t(xt.index[i]) * bpp;
            for (int c = 0; c < ch; ++c) acc[c] += w * float(px[c]);
          }
        }
        uint8_t* out = d + (size_t(y) * size_t(dst.width) + size_t(x)) * bpp;
        for (int c = 0; c < ch; ++c) out[c] = uint8_t(std::min(255.0f, std::floor(acc[c] + 0.5f)));
      }
    }
    return;
  }
  for (int y = 0; y < dst.height; ++y) {
    const Taps& yt = ty[size_t(y)];
    for (int x = 0; x < dst.width; ++x) {
      const Taps& xt = tx[size_t(x)];
      glm::vec4 acc(0.0f);
      for (int j = 0; j < yt.count; ++j)
        for (int i = 0; i < xt.count; ++i) {
          const std::byte* px =
              src.data.data() + (size_t(yt.index[j]) * size_t(src.width) + size_t(xt.index[i])) * bpp;
          acc += (yt.weight[j] * xt.weight[i]) * decode_texel(f, px);
        }
      encode_texel(f, dst.data.data() + (size_t(y) * size_t(dst.width) + size_t(x)) * bpp, acc);
    }
  }
}

}  // namespace

// --- Level / Texture2D -------------------------------------------------------------------

size_t Level::row_bytes() const { return height > 0 ? data.size() / size_t(height) : 0; }

Texture2D::Texture2D(Format format, int width, int height, int levels) : format_(format) {
  const FormatInfo info = format_info(format);
  if (info.bytes == 0) throw Error("Texture2D: unknown format " + std::to_string(int(format)));
  if (width < 1 || width > kMaxTextureSize || height < 1 || height > kMaxTextureSize)
    throw Error("Texture2D: size " + size_string(width, height) + " is outside 1.." +
                std::to_string(kMaxTextureSize) + " (" + info.name + ")");
  const int full = full_chain_levels(width, height);
  if (levels < 0 || levels > full)
    throw Error("Texture2D: " + std::to_string(levels) + " mip levels requested for a " +
                size_string(width, height) + " texture, which has at most " + std::to_string(full));
  if (levels == 0) levels = full;
  levels_.resize(size_t(levels));
  for (int i = 0; i < levels; ++i) {
    Level& l = levels_[size_t(i)];
    l.width = std::max(1, width >> i);
    l.height = std::max(1, height >> i);
    l.data.assign(size_t(l.width) * size_t(l.height) * info.bytes, std::byte{0});
  }
}

Level& Texture2D::level_for_write(int i) {
  before_write();
  if (i < 0 || i >= levels())
    throw Error("Texture2D::level_for_write: level " + std::to_string(i) + " out of range (texture has " +
                std::to_string(levels()) + " levels)");
  return levels_[size_t(i)];
}

void Texture2D::upload(int level, const void* data, size_t bytes) {
  before_write();
  if (level < 0 || level >= levels())
    throw Error("Texture2D::upload: level " + std::to_string(level) + " out of range (texture has " +
                std::to_string(levels()) + " levels)");
  Level& l = levels_[size_t(level)];
  if (bytes != l.data.size())
    throw Error("Texture2D::upload: level " + std::to_string(level) + " of a " +
                size_string(l.width, l.height) + " " + format_info(format_).name + " texture needs " +
                std::to_string(l.data.size()) + " bytes, got " + std::to_string(bytes));
  if (data == nullptr) throw Error("Texture2D::upload: null data");
  std::memcpy(l.data.data(), data, bytes);
}

void Texture2D::upload_rgba8(int level, const uint8_t* rgba, size_t bytes) {
  before_write();
  if (level < 0 || level >= levels())
    throw Error("Texture2D::upload_rgba8: level " + std::to_string(level) + " out of range (texture has " +
                std::to_string(levels()) + " levels)");
  Level& l = levels_[size_t(level)];
  const size_t n = size_t(l.width) * size_t(l.height);
  if (bytes != n * 4)
    throw Error("Texture2D::upload_rgba8: level " + std::to_string(level) + " of a " +
                size_string(l.width, l.height) + " texture needs " + std::to_string(n * 4) + " bytes, got " +
                std::to_string(bytes));
  if (rgba == nullptr) throw Error("Texture2D::upload_rgba8: null data");
  if (format_ == Format::RGBA8) {
    std::memcpy(l.data.data(), rgba, bytes);
    return;
  }
  const size_t bpp = format_info(format_).bytes;
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* s = rgba + i * 4;
    glm::vec4 c(unorm8_to_float(s[0]), unorm8_to_float(s[1]), unorm8_to_float(s[2]), unorm8_to_float(s[3]));
    if (format_ == Format::Depth24Stencil8) c.y = float(s[1]);  // stencil from green, as an integer
    encode_texel(format_, l.data.data() + i * bpp, c);
  }
}

void Texture2D::upload_rgba32f(int level, const float* rgba, size_t bytes) {
  before_write();
  if (level < 0 || level >= levels())
    throw Error("Texture2D::upload_rgba32f: level " + std::to_string(level) + " out of range (texture has " +
                std::to_string(levels()) + " levels)");
  Level& l = levels_[size_t(level)];
  const size_t n = size_t(l.width) * size_t(l.height);
  if (bytes != n * 16)
    throw Error("Texture2D::upload_rgba32f: level " + std::to_string(level) + " of a " +
                size_string(l.width, l.height) + " texture needs " + std::to_string(n * 16) + " bytes, got " +
                std::to_string(bytes));
  if (rgba == nullptr) throw Error("Texture2D::upload_rgba32f: null data");
  if (format_ == Format::RGBA32F) {
    std::memcpy(l.data.data(), rgba, bytes);
    return;
  }
  const size_t bpp = format_info(format_).bytes;
  for (size_t i = 0; i < n; ++i) {
    const float* s = rgba + i * 4;
    encode_texel(format_, l.data.data() + i * bpp, glm::vec4(s[0], s[1], s[2], s[3]));
  }
}

void Texture2D::generate_mipmaps() {
  before_write();
  for (size_t i = 1; i < levels_.size(); ++i) downsample(format_, levels_[i - 1], levels_[i]);
}

void Texture2D::allocate_full_chain() {
  before_write();
  const int w = levels_[0].width, h = levels_[0].height;
  const int full = full_chain_levels(w, h);
  const size_t bpp = format_info(format_).bytes;
  for (int i = levels(); i < full; ++i) {
    Level l;
    l.width = std::max(1, w >> i);
    l.height = std::max(1, h >> i);
    l.data.assign(size_t(l.width) * size_t(l.height) * bpp, std::byte{0});
    levels_.push_back(std::move(l));
  }
  generate_mipmaps();
}

glm::vec4 Texture2D::fetch(int level, int x, int y) const {
  if (level < 0 || level >= levels())
    throw Error("Texture2D::fetch: level " + std::to_string(level) + " out of range (texture has " +
                std::to_string(levels()) + " levels)");
  const Level& l = levels_[size_t(level)];
  if (x < 0 || y < 0 || x >= l.width || y >= l.height)
    throw Error("Texture2D::fetch: texel (" + std::to_string(x) + ", " + std::to_string(y) +
                ") outside level " + std::to_string(level) + " of size " + size_string(l.width, l.height));
  const size_t bpp = format_info(format_).bytes;
  return decode_texel(format_, l.data.data() + (size_t(y) * size_t(l.width) + size_t(x)) * bpp);
}

void Texture2D::store(int level, int x, int y, const glm::vec4& value) {
  before_write();
  if (level < 0 || level >= levels())
    throw Error("Texture2D::store: level " + std::to_string(level) + " out of range (texture has " +
                std::to_string(levels()) + " levels)");
  Level& l = levels_[size_t(level)];
  if (x < 0 || y < 0 || x >= l.width || y >= l.height)
    throw Error("Texture2D::store: texel (" + std::to_string(x) + ", " + std::to_string(y) +
                ") outside level " + std::to_string(level) + " of size " + size_string(l.width, l.height));
  const size_t bpp = format_info(format_).bytes;
  encode_texel(format_, l.data.data() + (size_t(y) * size_t(l.width) + size_t(x)) * bpp, value);
}

// --- TextureCube -------------------------------------------------------------------------

TextureCube::TextureCube(Format format, int size, int levels) {
  if (size < 1 || size > kMaxTextureSize)
    throw Error("TextureCube: face size " + std::to_string(size) + " is outside 1.." +
                std::to_string(kMaxTextureSize));
  for (auto& f : faces_) f = std::make_unique<Texture2D>(format, size, size, levels);
}

void TextureCube::generate_mipmaps() {
  before_write();
  for (auto& f : faces_) f->generate_mipmaps();
}

// --- sampling ----------------------------------------------------------------------------

namespace {

// NaN -> 0 and infinities to a large finite value, so index arithmetic stays defined.
TESSEL_INLINE float sane(float s) {
  if (!(s == s)) return 0.0f;
  return s < -kNoCoord ? -kNoCoord : (s > kNoCoord ? kNoCoord : s);
}

TESSEL_INLINE int floor_to_int(float x) {
  constexpr float lim = 1073741824.0f;  // 2^30: keeps i + 1 and the wrap arithmetic in range
  if (!(x == x)) return 0;
  if (x <= -lim) return -int(lim);
  if (x >= lim) return int(lim);
  return int(std::floor(x));
}

// GL 4.6 Table 8.20 applied to an integer texel coordinate; -1 means "border texel".
TESSEL_INLINE int wrap_texel(int i, int size, Wrap mode) {
  if (unsigned(i) < unsigned(size)) return i;  // inside: every mode leaves it alone
  switch (mode) {
    case Wrap::Repeat: {
      int r = i % size;
      return r < 0 ? r + size : r;
    }
    case Wrap::ClampToEdge: return i < 0 ? 0 : (i >= size ? size - 1 : i);
    case Wrap::ClampToBorder: return (i < 0 || i >= size) ? -1 : i;
    case Wrap::Clamp: return i < 0 ? 0 : (i >= size ? size - 1 : i);  // sample_level resolves it first
    case Wrap::MirroredRepeat: {
      const int m2 = 2 * size;
      int r = i % m2;
      if (r < 0) r += m2;
      const int a = r - size;                      // fmod(coord, 2 size) - size
      const int mirrored = a >= 0 ? a : -(1 + a);  // mirror(a)
      return (size - 1) - mirrored;
    }
  }
  return 0;
}

inline bool is_linear(Filter f) {
  return f == Filter::Linear || f == Filter::LinearMipmapNearest || f == Filter::LinearMipmapLinear;
}

// The border colour as a texel of the format: unsigned normalized formats clamp it to [0, 1],
// missing channels read as 0 (alpha 1), depth formats read (d, 0, 0, 1).
glm::vec4 border_for(Format f, const glm::vec4& b) {
  switch (f) {
    case Format::RGBA8: return glm::vec4(sat(b.x), sat(b.y), sat(b.z), sat(b.w));
    case Format::R8: return glm::vec4(sat(b.x), 0.0f, 0.0f, 1.0f);
    case Format::RG8: return glm::vec4(sat(b.x), sat(b.y), 0.0f, 1.0f);
    case Format::RGBA16F:
    case Format::RGBA32F: return b;
    case Format::Depth24:
    case Format::Depth24Stencil8: return glm::vec4(sat(b.x), 0.0f, 0.0f, 1.0f);
    case Format::Depth32F: return glm::vec4(b.x, 0.0f, 0.0f, 1.0f);
  }
  return b;
}

struct Identity {
  glm::vec4 operator()(const glm::vec4& v) const { return v; }
};

// Depth comparison applied to a texel: 1 if `ref <func> depth` passes, else 0 (in .x).
struct Compare {
  CompareFunc func;
  float ref;
  bool clamp_depth;
  glm::vec4 operator()(const glm::vec4& v) const {
    const float d = clamp_depth ? sat(v.x) : v.x;
    return glm::vec4(compare(func, ref, d) ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
  }
};

TESSEL_INLINE glm::vec4 lerp(const glm::vec4& a, const glm::vec4& b, float t) { return a + (b - a) * t; }

// Filters one level at (s, t) in [0,1] texture space (GL 4.6 §8.14.2, equations 8.9-8.11).
// `border` is already passed through `xf`.
template <Format F, class Xf>
TESSEL_INLINE glm::vec4 sample_level(const LevelRef& L, Wrap ws, Wrap wt, float s, float t, bool linear,
                                     const glm::vec4& border, const Xf& xf) {
  constexpr size_t bpp = format_info(F).bytes;
  // GL 1.x CLAMP (GL 2.1 §3.8.7): the coordinate is clamped to [0, 1]; a nearest lookup then
  // stays on the edge texels, a linear one blends with the border beyond them.
  if (ws == Wrap::Clamp) {
    s = std::clamp(sane(s), 0.0f, 1.0f);
    ws = linear ? Wrap::ClampToBorder : Wrap::ClampToEdge;
  }
  if (wt == Wrap::Clamp) {
    t = std::clamp(sane(t), 0.0f, 1.0f);
    wt = linear ? Wrap::ClampToBorder : Wrap::ClampToEdge;
  }
  const float u = sane(s) * float(L.w);
  const float v = sane(t) * float(L.h);
  auto texel = [&](int i, int j) TESSEL_INLINE_LAMBDA -> glm::vec4 {
    if (i < 0 || j < 0) return border;
    return xf(decode<F>(L.data + (size_t(j) * size_t(L.w) + size_t(i)) * bpp));
  };
  if (!linear) return texel(wrap_texel(floor_to_int(u), L.w, ws), wrap_texel(floor_to_int(v), L.h, wt));
  const float uu = u - 0.5f, vv = v - 0.5f;
  const float fu = std::floor(uu), fv = std::floor(vv);
  const float a = uu - fu, b = vv - fv;  // in [0, 1)
  const int i0 = floor_to_int(fu), j0 = floor_to_int(fv);
  const int x0 = wrap_texel(i0, L.w, ws), x1 = wrap_texel(i0 + 1, L.w, ws);
  const int y0 = wrap_texel(j0, L.h, wt), y1 = wrap_texel(j0 + 1, L.h, wt);
  const glm::vec4 bottom = lerp(texel(x0, y0), texel(x1, y0), a);
  const glm::vec4 top = lerp(texel(x0, y1), texel(x1, y1), a);
  return lerp(bottom, top, b);
}

// Which levels to read and how: the mag/min decision and mipmap selection of GL 4.6
// §8.14 - §8.14.3 for one LOD.
struct Plan {
  int level0 = 0;
  int level1 = -1;  // second level for *_MIPMAP_LINEAR, -1 if none
  float blend = 0.0f;
  bool linear = false;
};

Plan make_plan(const SamplerState& st, int levels, float lod) {
  float l = lod + st.lod_bias;
  if (!(l == l)) l = 0.0f;
  l = std::max(l, st.min_lod);
  l = std::min(l, st.max_lod);
  Plan p;
  // Magnification when lambda <= 0 (c = 0, as GL 4.6 and llvmpipe have it).
  if (l <= 0.0f) {
    p.linear = is_linear(st.mag_filter);
    return p;
  }
  p.linear = is_linear(st.min_filter);
  const int q = levels - 1;  // the last level the texture has (its effective MAX_LEVEL)
  switch (st.min_filter) {
    case Filter::Nearest:
    case Filter::Linear: return p;
    case Filter::NearestMipmapNearest:
    case Filter::LinearMipmapNearest: {
      if (l > 0.5f) p.level0 = int(std::min(std::ceil(l + 0.5f) - 1.0f, float(q)));
      return p;
    }
    case Filter::NearestMipmapLinear:
    case Filter::LinearMipmapLinear: {
      if (l >= float(q)) {
        p.level0 = q;
        return p;
      }
      const float d1 = std::floor(l);
      p.level0 = int(d1);
      p.level1 = p.level0 + 1;
      p.blend = l - d1;
      return p;
    }
  }
  return p;
}

// A texel offset (textureOffset) moves s and t by whole texels of each level sampled (GL 3.3
// §3.8.11, as llvmpipe applies it): o / size, exact for power-of-two sizes.
template <Format F, class Xf>
TESSEL_INLINE glm::vec4 run_plan(const Texture2D& tex, const Plan& p, const SamplerState& st, float s,
                                 float t, const glm::vec4& border, const Xf& xf, glm::ivec2 off = {}) {
  auto one = [&](int level) {
    const LevelRef L = level_ref(tex, level);
    const float ls = off.x ? s + float(off.x) / float(L.w) : s,
                lt = off.y ? t + float(off.y) / float(L.h) : t;
    return sample_level<F>(L, st.wrap_s, st.wrap_t, ls, lt, p.linear, border, xf);
  };
  const glm::vec4 c0 = one(p.level0);
  if (p.level1 < 0 || p.blend == 0.0f) return c0;
  return lerp(c0, one(p.level1), p.blend);
}

inline bool fixed_point_depth(Format f) {
  return f != Format::Depth32F && f != Format::RGBA16F && f != Format::RGBA32F;
}

Compare make_compare(const Sampler2DShadow& s, float ref) {
  const bool fixed = fixed_point_depth(s.texture->format());
  if (fixed && ref == ref) ref = sat(ref);
  return Compare{s.state.compare_func, ref, fixed};
}

// Cube map face selection, GL 4.6 §8.13 Table 8.19.
struct FaceAxes {
  int face;
  float sc, tc, ma;
};

inline int select_face(float x, float y, float z) {
  const float ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
  if (ax >= ay && ax >= az) return x >= 0.0f ? 0 : 1;
  if (ay >= az) return y >= 0.0f ? 2 : 3;
  return z >= 0.0f ? 4 : 5;
}

inline FaceAxes face_axes(int face, float x, float y, float z) {
  switch (face) {
    case 0: return {0, -z, -y, std::fabs(x)};
    case 1: return {1, z, -y, std::fabs(x)};
    case 2: return {2, x, z, std::fabs(y)};
    case 3: return {3, x, -z, std::fabs(y)};
    case 4: return {4, x, -y, std::fabs(z)};
    default: return {5, -x, -y, std::fabs(z)};
  }
}

inline void face_st(int face, float x, float y, float z, float& s, float& t) {
  const FaceAxes a = face_axes(face, x, y, z);
  s = (a.sc / a.ma + 1.0f) * 0.5f;
  t = (a.tc / a.ma + 1.0f) * 0.5f;
}

// Texel (i, j) of a cube face's level where i or j (not both) may be one step outside the face
// (a linear lookup at its edge; GL 3.3 §3.8.8 with TEXTURE_CUBE_MAP_SEAMLESS): the texel of
// the face the texel's centre direction falls on. (Corners are sample_cube_seamless's.)
glm::vec4 seamless_texel(const TextureCube& cube, int level, int face, int i, int j) {
  const int n = cube.face(face).width(level);
  const bool out_i = i < 0 || i >= n, out_j = j < 0 || j >= n;
  if (!out_i && !out_j) return cube.face(face).fetch(level, i, j);
  // The texel centre's face coordinates, past the edge on one axis, and its direction
  // (face_axes inverted).
  const float sc = 2.0f * (float(i) + 0.5f) / float(n) - 1.0f,
              tc = 2.0f * (float(j) + 0.5f) / float(n) - 1.0f;
  glm::vec3 d;
  switch (face) {
    case 0: d = {1.0f, -tc, -sc}; break;
    case 1: d = {-1.0f, -tc, sc}; break;
    case 2: d = {sc, 1.0f, tc}; break;
    case 3: d = {sc, -1.0f, -tc}; break;
    case 4: d = {sc, -tc, 1.0f}; break;
    default: d = {-sc, -tc, -1.0f}; break;
  }
  const int nf = select_face(d.x, d.y, d.z);
  float s, t;
  face_st(nf, d.x, d.y, d.z, s, t);
  const int m = cube.face(nf).width(level);
  return cube.face(nf).fetch(level, std::clamp(floor_to_int(s * float(m)), 0, m - 1),
                             std::clamp(floor_to_int(t * float(m)), 0, m - 1));
}

// A linear lookup of face `face` at (fs, ft) that reads past the face's edges (seamless_texel),
// each texel passed through `xf` (a depth comparison for shadow cube maps) before filtering.
template <class Xf>
glm::vec4 sample_cube_seamless(const TextureCube& cube, const Plan& p, int face, float fs, float ft,
                               const Xf& xf) {
  auto one = [&](int level) {
    const int n = cube.face(face).width(level);
    const float u = sane(fs) * float(n) - 0.5f, v = sane(ft) * float(n) - 0.5f;
    const float fu = std::floor(u), fv = std::floor(v);
    const float a = u - fu, b = v - fv;
    const int i0 = floor_to_int(fu), j0 = floor_to_int(fv);
    auto tap = [&](int i, int j) {
      const int ci = std::clamp(i, 0, n - 1), cj = std::clamp(j, 0, n - 1);
      if (ci == i || cj == j) return xf(seamless_texel(cube, level, face, i, j));
      // A corner: the three texels that meet there, each through xf (each compared, for a
      // shadow lookup, as llvmpipe does), averaged.
      return (xf(seamless_texel(cube, level, face, ci, cj)) + xf(seamless_texel(cube, level, face, i, cj)) +
              xf(seamless_texel(cube, level, face, ci, j))) *
             (1.0f / 3.0f);
    };
    const glm::vec4 bottom = lerp(tap(i0, j0), tap(i0 + 1, j0), a);
    const glm::vec4 top = lerp(tap(i0, j0 + 1), tap(i0 + 1, j0 + 1), a);
    return lerp(bottom, top, b);
  };
  const glm::vec4 c0 = one(p.level0);
  if (p.level1 < 0 || p.blend == 0.0f) return c0;
  return lerp(c0, one(p.level1), p.blend);
}

SamplerState cube_face_state(const SamplerState& st) {
  SamplerState f = st;
  f.wrap_s = f.wrap_t = f.wrap_r = Wrap::ClampToEdge;
  return f;
}

const glm::vec4 kMissing(0.0f, 0.0f, 0.0f, 1.0f);

// LOD of a 2x2 quad from lanes 4q (origin), 4q+1 (x neighbour), 4q+2 (y neighbour).
inline float quad_lod(const Float8& u, const Float8& v, int q, int w, int h) {
  const int o = q * 4;
  return detail::lod_from_derivatives(u[o + 1] - u[o], v[o + 1] - v[o], u[o + 2] - u[o], v[o + 2] - v[o], w,
                                      h);
}

// log2 as llvmpipe takes it for the level of detail (its lp_build_fast_log2): the exponent
// plus the mantissa minus one, exact at powers of two and at most 0.086 low in between.
// Measured against Mesa 22.3 llvmpipe: at lambda = log2(3) its mip blend is 0.5625, which is
// 0.5 * fast_log2(rho^2) = 0.5 * (3 + 0.125); the exact value 0.585 differs by 3-4 steps of
// 8-bit colour between two levels.
inline float lod_log2(float x) {
  int32_t b;
  std::memcpy(&b, &x, 4);
  const float e = float(((b >> 23) & 0xFF) - 127);
  const int32_t mb = (b & 0x007FFFFF) | 0x3F800000;
  float m;
  std::memcpy(&m, &mb, 4);
  return e + (m - 1.0f);
}

// The LOD of both quads of eight lanes: 0.5 log2(max(|d(uv)/dx|^2, |d(uv)/dy|^2)) in texels
// (GL 4.6 eq. 8.7 with rho^2, so no square roots), from vector derivatives.
inline void quad_lods(const Float8& u, const Float8& v, int w, int h, float lod[2]) {
  const Float8 fw{float(w)}, fh{float(h)};
  const Float8 ux = dFdx(u) * fw, vx = dFdx(v) * fh, uy = dFdy(u) * fw, vy = dFdy(v) * fh;
  const Float8 rho2 = max(ux * ux + vx * vx, uy * uy + vy * vy);
  for (int q = 0; q < 2; ++q) {
    const float r = rho2[4 * q];
    if (r > 0.0f && r <= 3.4e38f)
      lod[q] = 0.5f * lod_log2(r);
    else
      lod[q] = r == 0.0f ? -1000.0f : (r > 0.0f ? 1000.0f : r);  // 0: magnified; inf; NaN stays NaN
  }
}

}  // namespace

namespace detail {

glm::vec4 sample_2d(const Sampler2D& s, float u, float v, float lod, glm::ivec2 offset) {
  if (s.texture == nullptr) return kMissing;
  const Texture2D& tex = *s.texture;
  const Plan p = make_plan(s.state, tex.levels(), lod);
  const glm::vec4 border = border_for(tex.format(), s.state.border_color);
  return with_format(tex.format(), [&](auto tag) {
    return run_plan<decltype(tag)::value>(tex, p, s.state, u, v, border, Identity{}, offset);
  });
}

glm::vec4 sample_cube(const SamplerCube& s, float x, float y, float z, float lod) {
  if (s.texture == nullptr) return kMissing;
  const int face = select_face(x, y, z);
  float fs, ft;
  face_st(face, x, y, z, fs, ft);
  const Texture2D& ftex = s.texture->face(face);
  const Sampler2D face_sampler{&ftex, cube_face_state(s.state)};
  if (!s.state.seamless) return sample_2d(face_sampler, fs, ft, lod);
  const Plan p = make_plan(s.state, ftex.levels(), lod);
  if (!p.linear) return sample_2d(face_sampler, fs, ft, lod);  // nearest never leaves the face
  return sample_cube_seamless(*s.texture, p, face, fs, ft, Identity{});
}

float sample_2d_compare(const Sampler2DShadow& s, float u, float v, float ref, float lod, glm::ivec2 offset) {
  if (s.texture == nullptr) return 0.0f;
  const Texture2D& tex = *s.texture;
  const Plan p = make_plan(s.state, tex.levels(), lod);
  const glm::vec4 border = border_for(tex.format(), s.state.border_color);
  if (!s.state.compare) {
    return with_format(tex.format(), [&](auto tag) {
      return run_plan<decltype(tag)::value>(tex, p, s.state, u, v, border, Identity{}, offset).x;
    });
  }
  const Compare cmp = make_compare(s, ref);
  const glm::vec4 cborder = cmp(border);
  return with_format(tex.format(), [&](auto tag) {
    return run_plan<decltype(tag)::value>(tex, p, s.state, u, v, cborder, cmp, offset).x;
  });
}

float lod_from_derivatives(float dudx, float dvdx, float dudy, float dvdy, int width, int height) {
  const float w = float(width), h = float(height);
  const float ux = dudx * w, vx = dvdx * h, uy = dudy * w, vy = dvdy * h;
  // GL 4.6 eq. 8.7 with rho^2 (no square root): lambda = 0.5 log2(rho^2), log2 as llvmpipe.
  const float rho2 = std::max(ux * ux + vx * vx, uy * uy + vy * vy);
  // As quad_lods, so one lane and eight agree: 0 magnifies, inf minifies, NaN stays NaN.
  if (rho2 > 0.0f && rho2 <= 3.4e38f) return 0.5f * lod_log2(rho2);
  return rho2 == 0.0f ? -1000.0f : (rho2 > 0.0f ? 1000.0f : rho2);
}

glm::vec4 texel_fetch(const Texture2D* t, int x, int y, int level) {
  if (t == nullptr) return kMissing;
  if (level < 0 || level >= t->levels()) return glm::vec4(0.0f);
  const Level& l = t->level(level);
  if (x < 0 || y < 0 || x >= l.width || y >= l.height) return glm::vec4(0.0f);
  const size_t bpp = format_info(t->format()).bytes;
  return decode_texel(t->format(), l.data.data() + (size_t(y) * size_t(l.width) + size_t(x)) * bpp);
}

}  // namespace detail

// --- the GLSL functions ------------------------------------------------------------------

namespace {

inline Vec4<float> to_vec(const glm::vec4& c) { return {c.x, c.y, c.z, c.w}; }
TESSEL_INLINE void put(Vec4<Float8>& r, int i, const glm::vec4& c) {
  r.x[i] = c.x;
  r.y[i] = c.y;
  r.z[i] = c.z;
  r.w[i] = c.w;
}
inline Vec4<Float8> missing8() { return {Float8(0.0f), Float8(0.0f), Float8(0.0f), Float8(1.0f)}; }

}  // namespace

Vec4<float> texture(const Sampler2D& s, const Vec2<float>& uv) {
  return to_vec(detail::sample_2d(s, uv.x, uv.y, 0.0f));
}

namespace {

// --- eight lanes at once for RGBA8 textures with REPEAT (power-of-two sizes) or
// CLAMP_TO_EDGE: the same arithmetic as sample_level/run_plan above, lane-parallel, so the
// results are bit-identical to the per-lane path.

Vec4<Float8> sample_level_rgba8(const LevelRef& L, Wrap ws, Wrap wt, Float8 s, Float8 t, bool linear) {
  const Float8 u = sane8(s) * Float8(float(L.w));
  const Float8 v = sane8(t) * Float8(float(L.h));
  const Int8 row(L.w);
  if (!linear) {
    const Int8 x = wrap8(integral_to_int(floor(u)), L.w, ws), y = wrap8(integral_to_int(floor(v)), L.h, wt);
    return decode_rgba8(gather_u32(L.data, y * row + x));
  }
  const Float8 uu = u - Float8(0.5f), vv = v - Float8(0.5f);
  const Float8 fu = floor(uu), fv = floor(vv);
  const Float8 a = uu - fu, b = vv - fv;
  const Int8 i0 = integral_to_int(fu), j0 = integral_to_int(fv);
  const Int8 x0 = wrap8(i0, L.w, ws), x1 = wrap8(i0 + Int8(1), L.w, ws);
  const Int8 y0 = wrap8(j0, L.h, wt) * row, y1 = wrap8(j0 + Int8(1), L.h, wt) * row;
  const Vec4<Float8> t00 = decode_rgba8(gather_u32(L.data, y0 + x0)),
                     t10 = decode_rgba8(gather_u32(L.data, y0 + x1));
  const Vec4<Float8> t01 = decode_rgba8(gather_u32(L.data, y1 + x0)),
                     t11 = decode_rgba8(gather_u32(L.data, y1 + x1));
  return lerp8(lerp8(t00, t10, a), lerp8(t01, t11, a), b);
}

#if defined(__AVX2__)
// Both quads use levels p.level0 and p.level1 (if any); quad q blends them by blend[q].
Vec4<Float8> run_plan_rgba8_linear(const Texture2D& tex, const Plan& p, const float blend[2],
                                   const SamplerState& st, const Vec2<Float8>& uv) {
  Rgba16 c = bilinear_rgba16(level_ref(tex, p.level0), st.wrap_s, st.wrap_t, uv.x, uv.y);
  if (p.level1 >= 0 && (blend[0] != 0.0f || blend[1] != 0.0f)) {
    const Rgba16 c1 = bilinear_rgba16(level_ref(tex, p.level1), st.wrap_s, st.wrap_t, uv.x, uv.y);
    const int16_t w0 = lerp_weight(int(std::lrint(blend[0] * 256.0f))),
                  w1 = lerp_weight(int(std::lrint(blend[1] * 256.0f)));
    c = lerp16(c, c1, _mm256_setr_epi16(w0, w0, w0, w0, w0, w0, w0, w0, w1, w1, w1, w1, w1, w1, w1, w1));
  }
  const __m256i packed = _mm256_or_si256(c.even, _mm256_slli_epi32(c.odd, 8));
  return decode_rgba8(Int8((vx::i32x8)packed));
}
#endif

Vec4<Float8> run_plan_rgba8(const Texture2D& tex, const Plan& p, const SamplerState& st,
                            const Vec2<Float8>& uv) {
#if defined(__AVX2__)
  if (p.linear) {
    const float blend[2] = {p.blend, p.blend};
    return run_plan_rgba8_linear(tex, p, blend, st, uv);
  }
#endif
  const Vec4<Float8> c0 =
      sample_level_rgba8(level_ref(tex, p.level0), st.wrap_s, st.wrap_t, uv.x, uv.y, p.linear);
  if (p.level1 < 0 || p.blend == 0.0f) return c0;
  const Vec4<Float8> c1 =
      sample_level_rgba8(level_ref(tex, p.level1), st.wrap_s, st.wrap_t, uv.x, uv.y, p.linear);
  return lerp8(c0, c1, Float8(p.blend));
}

struct LevelGuess {
  const Texture2D* texture = nullptr;
  int level0 = 0, level1 = -1;
};

}  // namespace

Vec4<Float8> texture(const Sampler2D& s, const Vec2<Float8>& uv) {
  if (s.texture == nullptr) return missing8();
  const Texture2D& tex = *s.texture;
  if (vector_path(tex, s.state)) {
    float lod[2];
    quad_lods(uv.x, uv.y, tex.width(), tex.height(), lod);
    const Plan p0 = make_plan(s.state, tex.levels(), lod[0]);
    const Plan p1 = make_plan(s.state, tex.levels(), lod[1]);
#if defined(__AVX2__)
    // Two quads on the same levels (the LOD differs only in the mip blend): one pass.
    if (p0.linear && p1.linear && p0.level0 == p1.level0 && p0.level1 == p1.level1) {
      const float blend[2] = {p0.blend, p1.blend};
      // The levels are taken from the previous call on this thread when they are the same
      // (they nearly always are): then the texel addresses and gathers need not wait for
      // this call's LOD, only the final mip blend does. The asm hides the equality from the
      // compiler, which would otherwise read the levels from the plan again. The result is
      // the same either way.
      thread_local LevelGuess guess;
      if (guess.texture == &tex && guess.level0 == p0.level0 && guess.level1 == p0.level1) {
        Plan p;
        p.level0 = guess.level0;
        p.level1 = guess.level1;
        p.linear = true;
        asm("" : "+r"(p.level0), "+r"(p.level1));
        return run_plan_rgba8_linear(tex, p, blend, s.state, uv);
      }
      guess = {&tex, p0.level0, p0.level1};
      return run_plan_rgba8_linear(tex, p0, blend, s.state, uv);
    }
#endif
    const Vec4<Float8> r0 = run_plan_rgba8(tex, p0, s.state, uv);
    if (p0.level0 == p1.level0 && p0.level1 == p1.level1 && p0.blend == p1.blend && p0.linear == p1.linear)
      return r0;
    const Vec4<Float8> r1 = run_plan_rgba8(tex, p1, s.state, uv);
    const Mask8 first = Mask8::from_bits(0x0F);
    return {select(first, r0.x, r1.x), select(first, r0.y, r1.y), select(first, r0.z, r1.z),
            select(first, r0.w, r1.w)};
  }
  const glm::vec4 border = border_for(tex.format(), s.state.border_color);
  Vec4<Float8> r;
  with_format(tex.format(), [&](auto tag) {
    constexpr Format F = decltype(tag)::value;
    for (int q = 0; q < kLanes / 4; ++q) {
      const Plan p = make_plan(s.state, tex.levels(), quad_lod(uv.x, uv.y, q, tex.width(), tex.height()));
      for (int i = q * 4; i < q * 4 + 4; ++i)
        put(r, i, run_plan<F>(tex, p, s.state, uv.x[i], uv.y[i], border, Identity{}));
    }
    return 0;
  });
  return r;
}

Vec4<float> textureLod(const Sampler2D& s, const Vec2<float>& uv, float lod) {
  return to_vec(detail::sample_2d(s, uv.x, uv.y, lod));
}

Vec4<Float8> textureLod(const Sampler2D& s, const Vec2<Float8>& uv, Float8 lod) {
  if (s.texture == nullptr) return missing8();
  Vec4<Float8> r;
  for (int i = 0; i < kLanes; ++i) put(r, i, detail::sample_2d(s, uv.x[i], uv.y[i], lod[i]));
  return r;
}

Vec4<float> textureGrad(const Sampler2D& s, const Vec2<float>& uv, const Vec2<float>& dx,
                        const Vec2<float>& dy) {
  if (s.texture == nullptr) return to_vec(kMissing);
  const float lod =
      detail::lod_from_derivatives(dx.x, dx.y, dy.x, dy.y, s.texture->width(), s.texture->height());
  return to_vec(detail::sample_2d(s, uv.x, uv.y, lod));
}

Vec4<Float8> textureGrad(const Sampler2D& s, const Vec2<Float8>& uv, const Vec2<Float8>& dx,
                         const Vec2<Float8>& dy) {
  if (s.texture == nullptr) return missing8();
  const int w = s.texture->width(), h = s.texture->height();
  Vec4<Float8> r;
  for (int i = 0; i < kLanes; ++i) {
    const float lod = detail::lod_from_derivatives(dx.x[i], dx.y[i], dy.x[i], dy.y[i], w, h);
    put(r, i, detail::sample_2d(s, uv.x[i], uv.y[i], lod));
  }
  return r;
}

Vec4<float> texture(const SamplerCube& s, const Vec3<float>& dir) {
  return to_vec(detail::sample_cube(s, dir.x, dir.y, dir.z, 0.0f));
}

Vec4<Float8> texture(const SamplerCube& s, const Vec3<Float8>& dir) {
  if (s.texture == nullptr) return missing8();
  const int size = s.texture->size();
  Vec4<Float8> r;
  for (int q = 0; q < kLanes / 4; ++q) {
    const int o = q * 4;
    // Derivatives of the face coordinates, all three lanes projected on the origin's face.
    const int face = select_face(dir.x[o], dir.y[o], dir.z[o]);
    float s0, t0, s1, t1, s2, t2;
    face_st(face, dir.x[o], dir.y[o], dir.z[o], s0, t0);
    face_st(face, dir.x[o + 1], dir.y[o + 1], dir.z[o + 1], s1, t1);
    face_st(face, dir.x[o + 2], dir.y[o + 2], dir.z[o + 2], s2, t2);
    const float lod = detail::lod_from_derivatives(s1 - s0, t1 - t0, s2 - s0, t2 - t0, size, size);
    for (int i = o; i < o + 4; ++i) put(r, i, detail::sample_cube(s, dir.x[i], dir.y[i], dir.z[i], lod));
  }
  return r;
}

float texture(const Sampler2DShadow& s, const Vec3<float>& uvr) {
  return detail::sample_2d_compare(s, uvr.x, uvr.y, uvr.z, 0.0f);
}

Float8 texture(const Sampler2DShadow& s, const Vec3<Float8>& uvr) {
  if (s.texture == nullptr) return Float8(0.0f);
  const Texture2D& tex = *s.texture;
  Float8 r;
  for (int q = 0; q < kLanes / 4; ++q) {
    const float lod = quad_lod(uvr.x, uvr.y, q, tex.width(), tex.height());
    for (int i = q * 4; i < q * 4 + 4; ++i)
      r[i] = detail::sample_2d_compare(s, uvr.x[i], uvr.y[i], uvr.z[i], lod);
  }
  return r;
}

Vec4<float> texelFetch(const Sampler2D& s, int x, int y, int level) {
  return to_vec(detail::texel_fetch(s.texture, x, y, level));
}

Vec4<Float8> texelFetch(const Sampler2D& s, Int8 x, Int8 y, int level) {
  Vec4<Float8> r;
  for (int i = 0; i < kLanes; ++i) put(r, i, detail::texel_fetch(s.texture, x[i], y[i], level));
  return r;
}

glm::ivec2 textureSize(const Sampler2D& s, int level) {
  if (s.texture == nullptr || level < 0 || level >= s.texture->levels()) return glm::ivec2(0);
  return glm::ivec2(s.texture->width(level), s.texture->height(level));
}

}  // namespace tessel::gpu

#include "texture_layered.inc"
