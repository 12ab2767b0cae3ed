// Per-sample operations after the fragment shader (GL 4.6 §17.3): stencil test, depth test,
// blending, colour write masks, and the conversion to each attachment's format.
//
// Contract: only lanes whose bit is set in `mask` read or write an attachment; helper lanes
// (run for derivatives) never write. Depth is compared in the buffer's own precision: 24-bit
// buffers compare round(z * (2^24 - 1)).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#if defined(__AVX2__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "stages.hpp"
#include "tessel/gpu/detail/fast_ops.hpp"

namespace tessel::gpu::detail {
namespace {

inline uint8_t stencil_op(StencilOp op, uint8_t s, uint8_t ref) {
  switch (op) {
    case StencilOp::Keep: return s;
    case StencilOp::Zero: return 0;
    case StencilOp::Replace: return ref;
    case StencilOp::Incr: return s == 255 ? 255 : uint8_t(s + 1);
    case StencilOp::IncrWrap: return uint8_t(s + 1);
    case StencilOp::Decr: return s == 0 ? 0 : uint8_t(s - 1);
    case StencilOp::DecrWrap: return uint8_t(s - 1);
    case StencilOp::Invert: return uint8_t(~s);
  }
  return s;
}

inline uint32_t quantize24(float z) { return uint32_t(std::lrint(double(z) * 16777215.0)); }

size_t texel_bytes(Format f) { return format_info(f).bytes; }

glm::vec4 load_color(const ColorTarget& t, int x, int y) {
  return decode_texel(t.format, t.data + size_t(y) * t.row_bytes + size_t(x) * texel_bytes(t.format));
}

// Writes the channels in `wmask` (bit 0 = red); the others keep their stored values.
void store_color(const ColorTarget& t, int x, int y, glm::vec4 c, uint8_t wmask) {
  std::byte* p = t.data + size_t(y) * t.row_bytes + size_t(x) * texel_bytes(t.format);
  if ((wmask & 0xF) != 0xF) {
    const glm::vec4 old = decode_texel(t.format, p);
    for (int i = 0; i < 4; ++i)
      if (!(wmask & (1 << i))) c[i] = old[i];
  }
  encode_texel(t.format, p, c);
}

inline glm::vec3 factor_rgb(BlendFactor f, const glm::vec4& s, const glm::vec4& d, const glm::vec4& k,
                            const glm::vec4& s1) {
  switch (f) {
    case BlendFactor::Zero: return glm::vec3(0.0f);
    case BlendFactor::One: return glm::vec3(1.0f);
    case BlendFactor::SrcColor: return glm::vec3(s);
    case BlendFactor::OneMinusSrcColor: return glm::vec3(1.0f) - glm::vec3(s);
    case BlendFactor::DstColor: return glm::vec3(d);
    case BlendFactor::OneMinusDstColor: return glm::vec3(1.0f) - glm::vec3(d);
    case BlendFactor::SrcAlpha: return glm::vec3(s.a);
    case BlendFactor::OneMinusSrcAlpha: return glm::vec3(1.0f - s.a);
    case BlendFactor::DstAlpha: return glm::vec3(d.a);
    case BlendFactor::OneMinusDstAlpha: return glm::vec3(1.0f - d.a);
    case BlendFactor::ConstantColor: return glm::vec3(k);
    case BlendFactor::OneMinusConstantColor: return glm::vec3(1.0f) - glm::vec3(k);
    case BlendFactor::ConstantAlpha: return glm::vec3(k.a);
    case BlendFactor::OneMinusConstantAlpha: return glm::vec3(1.0f - k.a);
    case BlendFactor::SrcAlphaSaturate: return glm::vec3(std::min(s.a, 1.0f - d.a));
    case BlendFactor::Src1Color: return glm::vec3(s1);
    case BlendFactor::OneMinusSrc1Color: return glm::vec3(1.0f) - glm::vec3(s1);
    case BlendFactor::Src1Alpha: return glm::vec3(s1.a);
    case BlendFactor::OneMinusSrc1Alpha: return glm::vec3(1.0f - s1.a);
  }
  return glm::vec3(0.0f);
}

inline float factor_alpha(BlendFactor f, const glm::vec4& s, const glm::vec4& d, const glm::vec4& k,
                          const glm::vec4& s1) {
  switch (f) {
    case BlendFactor::Zero: return 0.0f;
    case BlendFactor::One: return 1.0f;
    case BlendFactor::SrcColor:
    case BlendFactor::SrcAlpha: return s.a;
    case BlendFactor::OneMinusSrcColor:
    case BlendFactor::OneMinusSrcAlpha: return 1.0f - s.a;
    case BlendFactor::DstColor:
    case BlendFactor::DstAlpha: return d.a;
    case BlendFactor::OneMinusDstColor:
    case BlendFactor::OneMinusDstAlpha: return 1.0f - d.a;
    case BlendFactor::ConstantColor:
    case BlendFactor::ConstantAlpha: return k.a;
    case BlendFactor::OneMinusConstantColor:
    case BlendFactor::OneMinusConstantAlpha: return 1.0f - k.a;
    case BlendFactor::SrcAlphaSaturate: return 1.0f;
    case BlendFactor::Src1Color:
    case BlendFactor::Src1Alpha: return s1.a;
    case BlendFactor::OneMinusSrc1Color:
    case BlendFactor::OneMinusSrc1Alpha: return 1.0f - s1.a;
  }
  return 0.0f;
}

template <class T>
inline T apply_equation(BlendEquation eq, T s, T sf, T d, T df) {
  switch (eq) {
    case BlendEquation::Add: return s * sf + d * df;
    case BlendEquation::Subtract: return s * sf - d * df;
    case BlendEquation::ReverseSubtract: return d * df - s * sf;
    case BlendEquation::Min: return glm::min(s, d);  // factors unused (GL 4.6 §17.3.6.1)
    case BlendEquation::Max: return glm::max(s, d);
  }
  return s;
}

// GL 4.6 §17.3.6: blending, with source, destination and constant clamped to [0, 1] for
// fixed-point (unsigned normalized) attachments.
glm::vec4 blend(const BlendTarget& b, glm::vec4 s, glm::vec4 d, glm::vec4 k, bool unorm, glm::vec4 s1) {
  if (unorm) {
    s = glm::clamp(s, 0.0f, 1.0f);
    k = glm::clamp(k, 0.0f, 1.0f);
    s1 = glm::clamp(s1, 0.0f, 1.0f);
  }
  const glm::vec3 rgb = apply_equation(b.eq_rgb, glm::vec3(s), factor_rgb(b.src_rgb, s, d, k, s1),
                                       glm::vec3(d), factor_rgb(b.dst_rgb, s, d, k, s1));
  const float a = apply_equation(b.eq_alpha, s.a, factor_alpha(b.src_alpha, s, d, k, s1), d.a,
                                 factor_alpha(b.dst_alpha, s, d, k, s1));
  return {rgb, a};
}

// GL 3.3 §4.1.11, Table 4.3.
inline uint32_t logic_op(LogicOp op, uint32_t s, uint32_t d) {
  switch (op) {
    case LogicOp::Clear: return 0;
    case LogicOp::And: return s & d;
    case LogicOp::AndReverse: return s & ~d;
    case LogicOp::Copy: return s;
    case LogicOp::AndInverted: return ~s & d;
    case LogicOp::Noop: return d;
    case LogicOp::Xor: return s ^ d;
    case LogicOp::Or: return s | d;
    case LogicOp::Nor: return ~(s | d);
    case LogicOp::Equiv: return ~(s ^ d);
    case LogicOp::Invert: return ~d;
    case LogicOp::OrReverse: return s | ~d;
    case LogicOp::CopyInverted: return ~s;
    case LogicOp::OrInverted: return ~s | d;
    case LogicOp::Nand: return ~(s & d);
    case LogicOp::Set: return ~0u;
  }
  return s;
}

// The logical operation on one pixel: unsigned normalized values as their 8-bit integers
// (the fragment's rounded as it would be stored), integer values as the format's bits (the
// fragment's clamped to the format first, the result kept to the component's width and
// sign-extended, as llvmpipe operates on the stored width). Float targets take s.
glm::vec4 apply_logic_op(LogicOp op, const BlendTarget& b, bool unorm, glm::vec4 s, const glm::vec4& d) {
  if (b.integer.integer()) {
    for (int k = 0; k < 4; ++k) {
      const int bits = b.integer.bits[k];
      const uint32_t sv = clamp_integer_bits(std::bit_cast<uint32_t>(s[k]), bits, b.integer.is_signed);
      uint32_t r = logic_op(op, sv, std::bit_cast<uint32_t>(d[k]));
      if (bits > 0 && bits < 32) {
        r &= (1u << bits) - 1u;
        if (b.integer.is_signed && (r >> (bits - 1)) & 1u) r |= ~((1u << bits) - 1u);
      }
      s[k] = std::bit_cast<float>(r);
    }
    return s;
  }
  if (!unorm) return s;
  for (int k = 0; k < 4; ++k) {
    const float c = s[k] > 0.0f ? (s[k] < 1.0f ? s[k] : 1.0f) : 0.0f;  // NaN -> 0
    const uint32_t sv = uint32_t(std::lrint(c * 255.0f)), dv = uint32_t(std::lrint(d[k] * 255.0f));
    s[k] = float(logic_op(op, sv, dv) & 0xFFu) * (1.0f / 255.0f);
  }
  return s;
}

// Non-temporal stores (RASTER_NOTES: the target's lines are written whole, and reading them
// first only to overwrite them doubles the memory traffic of a frame's last writes).
bool streamable(const void* p, size_t stride, size_t bytes) {
  return ((reinterpret_cast<uintptr_t>(p) | stride | bytes) & 15) == 0;
}
// Without SSE2 (a portable build off x86) they are plain stores.
void stream_row(std::byte* dst, const std::byte* src, size_t bytes) {
#if defined(__SSE2__)
  for (size_t off = 0; off < bytes; off += 16)
    _mm_stream_si128(reinterpret_cast<__m128i*>(dst + off),
                     _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + off)));
#else
  std::memcpy(dst, src, bytes);
#endif
}
// Orders the streamed stores before what follows (the next phase may read them).
void stream_fence() {
#if defined(__SSE2__)
  _mm_sfence();
#endif
}

// Sets the texels [x0, x1) x [y0, y1) of an image with `bytes`-byte texels (a divisor of 64)
// to (old & keep) | set per byte, keep and set being one texel's pattern (set has no bits in
// keep). keep all zero is a plain fill and never reads; keep all ones changes nothing.
void fill_rect(std::byte* data, size_t row_bytes, size_t bytes, const uint8_t* keep, const uint8_t* set,
               int x0, int y0, int x1, int y1, bool stream) {
  bool reads = false, writes = false;
  for (size_t i = 0; i < bytes; ++i) {
    reads |= keep[i] != 0;
    writes |= keep[i] != 0xFF;
  }
  if (!writes) return;
  // The pattern repeated over 64 bytes, so every 64-byte step of a row starts on a texel.
  uint8_t kb[64], sb[64];
  for (size_t i = 0; i < 64; ++i) {
    kb[i] = keep[i % bytes];
    sb[i] = set[i % bytes];
  }
  uint64_t kw[8], sw[8];
  std::memcpy(kw, kb, 64);
  std::memcpy(sw, sb, 64);
  const size_t n = size_t(x1 - x0) * bytes;
  if (!reads && stream && streamable(data + size_t(y0) * row_bytes + size_t(x0) * bytes, row_bytes, n) &&
      64 % bytes == 0) {
    // Every 16-byte step of a row starts on a texel (the bytes per texel divide 64).
    for (int y = y0; y < y1; ++y)
      for (size_t off = 0; off < n; off += 64)
        stream_row(data + size_t(y) * row_bytes + size_t(x0) * bytes + off,
                   reinterpret_cast<const std::byte*>(sb), std::min<size_t>(64, n - off));
    stream_fence();
    return;
  }
  for (int y = y0; y < y1; ++y) {
    std::byte* p = data + size_t(y) * row_bytes + size_t(x0) * bytes;
    size_t off = 0;
    if (!reads) {
      for (; off + 64 <= n; off += 64) std::memcpy(p + off, sb, 64);
      std::memcpy(p + off, sb, n - off);
      continue;
    }
    for (; off + 64 <= n; off += 64) {
      uint64_t w[8];
      std::memcpy(w, p + off, 64);
      for (int j = 0; j < 8; ++j) w[j] = (w[j] & kw[j]) | sw[j];
      std::memcpy(p + off, w, 64);
    }
    for (int j = 0; off + 8 <= n; off += 8, ++j) {
      uint64_t w;
      std::memcpy(&w, p + off, 8);
      w = (w & kw[j]) | sw[j];
      std::memcpy(p + off, &w, 8);
    }
    for (; off < n; ++off) {
      const size_t k = off % 64;
      p[off] = std::byte((uint8_t(p[off]) & kb[k]) | sb[k]);
    }
  }
}

}  // namespace

unsigned depth_stencil_test(const DrawRecord& d, const TargetView& t, int gx, int gy, unsigned mask,
                            const Float8& z, bool front) {
  if (!t.depth) return mask;  // no depth attachment: both tests pass (GL 4.6 §17.3.3, §17.3.4)
  if (d.fast_depth && gx + 4 <= t.width && gy + 2 <= t.height) return depth_test8(d, t, gx, gy, mask, z);
  const RenderState& st = d.state;
  const bool stencil = st.stencil_test && t.has_stencil;
  const bool depth = st.depth_test;
  if (!stencil && !depth) return mask;
  const StencilFace& sf = front ? st.stencil_front : st.stencil_back;
  unsigned out = 0;
  for (unsigned m = mask; m; m &= m - 1) {
    const int l = __builtin_ctz(m);
    const int x = gx + kLaneDx[l], y = gy + kLaneDy[l];
    std::byte* p = t.depth + size_t(y) * t.depth_row_bytes + size_t(x) * 4;
    uint32_t word;
    std::memcpy(&word, p, 4);
    const float zf = z[l];
    bool pass = true;
    uint8_t s = uint8_t(word >> 24);
    uint8_t s_new = s;
    if (stencil) {
      const bool spass = compare<uint8_t>(sf.func, sf.ref & sf.read_mask, s & sf.read_mask);
      if (!spass) {
        s_new = stencil_op(sf.fail, s, sf.ref);
        pass = false;
      }
    }
    bool zpass = true;
    if (pass && depth) {
      if (t.depth_format == Format::Depth32F) {
        float stored;
        std::memcpy(&stored, &word, 4);
        zpass = compare(st.depth_func, zf, stored);
      } else {
        zpass = compare(st.depth_func, quantize24(zf), word & 0xFFFFFFu);
      }
      if (!zpass) pass = false;
      if (stencil && !zpass) s_new = stencil_op(sf.depth_fail, s, sf.ref);
    }
    if (pass && stencil) s_new = stencil_op(sf.pass, s, sf.ref);
    uint32_t new_word = word;
    if (pass && depth && st.depth_write) {
      if (t.depth_format == Format::Depth32F)
        std::memcpy(&new_word, &zf, 4);
      else
        new_word = (word & 0xFF000000u) | quantize24(zf);
    }
    if (stencil && s_new != s) {
      const uint8_t wm = sf.write_mask;
      const uint8_t merged = uint8_t((s & ~wm) | (s_new & wm));
      new_word = (new_word & 0x00FFFFFFu) | (uint32_t(merged) << 24);
    }
    if (new_word != word) std::memcpy(p, &new_word, 4);
    if (pass) out |= 1u << l;
  }
  return out;
}

void write_colors(const DrawRecord& d, const TargetView& t, int gx, int gy, unsigned mask,
                  const Vec4<Float8>* colors, int outputs) {
  if (d.fast_color && gx + 4 <= t.width && gy + 2 <= t.height)
    return write_rgba8(t.color[0], gx, gy, mask, colors[0]);
  // With dual-source blending output 1 is attachment 0's second source, not a colour.
  const bool dual = d.state.dual_source && outputs >= 2;
  const bool broadcast = d.state.broadcast_color && !dual;
  const int n = dual        ? std::min(1, t.color_count)
                : broadcast ? t.color_count
                            : std::min(outputs, t.color_count);
  for (int i = 0; i < n; ++i) {
    const ColorTarget& ct = t.color[i];
    if (!ct.data) continue;
    const BlendTarget& b = d.state.blend[i];
    if (b.write_mask == 0) continue;
    const bool unorm = is_unorm8_format(ct.format);
    const bool logic = d.state.logic_op_enabled;
    const Vec4<Float8>& c = colors[broadcast ? 0 : i];
    for (unsigned m = mask; m; m &= m - 1) {
      const int l = __builtin_ctz(m);
      const int x = gx + kLaneDx[l], y = gy + kLaneDy[l];
      glm::vec4 s(c.x[l], c.y[l], c.z[l], c.w[l]);
      if (logic) {
        s = apply_logic_op(d.state.logic_op, b, unorm, s, load_color(ct, x, y));
      } else if (b.integer.integer()) {
        for (int k = 0; k < 4; ++k)
          s[k] = std::bit_cast<float>(
              clamp_integer_bits(std::bit_cast<uint32_t>(s[k]), b.integer.bits[k], b.integer.is_signed));
      } else if (b.enabled) {
        const glm::vec4 s1 = dual ? glm::vec4(colors[1].x[l], colors[1].y[l], colors[1].z[l], colors[1].w[l])
                                  : glm::vec4(0.0f);
        s = blend(b, s, load_color(ct, x, y), d.state.blend_color, unorm, s1);
      }
      store_color(ct, x, y, s, b.write_mask);
    }
  }
}

void copy_rows(std::byte* dst, size_t dst_stride, const std::byte* src, size_t src_stride, size_t row_bytes,
               int rows, bool stream) {
  if (!stream || !streamable(dst, dst_stride, row_bytes)) {
    for (int y = 0; y < rows; ++y)
      std::memcpy(dst + size_t(y) * dst_stride, src + size_t(y) * src_stride, row_bytes);
    return;
  }
  for (int y = 0; y < rows; ++y)
    stream_row(dst + size_t(y) * dst_stride, src + size_t(y) * src_stride, row_bytes);
  stream_fence();
}

void clear_rect(const TargetView& t, const ClearPrim& c, int x0, int y0, int x1, int y1, bool stream) {
  if (x0 >= x1 || y0 >= y1) return;
  // Colour: the clear colour is encoded once; the channels outside the write mask keep their
  // bytes. Every colour format stores each channel in its own bytes and decodes and encodes
  // stored values exactly, so this is what store_color does per pixel.
  for (int i = 0; i < t.color_count; ++i) {
    const ColorTarget& ct = t.color[i];
    const uint8_t wmask = c.write_mask[i];
    if (!(c.color_mask_bits & (1u << i)) || !ct.data || !wmask) continue;
    const FormatInfo info = format_info(ct.format);
    uint8_t set[16] = {}, keep[16] = {};
    encode_texel(ct.format, reinterpret_cast<std::byte*>(set), c.color[i]);
    const int per_channel = info.bytes / info.channels;
    for (int ch = 0; ch < info.channels; ++ch) {
      if (wmask & (1 << ch)) continue;
      for (int b = 0; b < per_channel; ++b) {
        keep[ch * per_channel + b] = 0xFF;
        set[ch * per_channel + b] = 0;
      }
    }
    fill_rect(ct.data, ct.row_bytes, info.bytes, keep, set, x0, y0, x1, y1, stream);
  }
  // Depth and stencil share one 32-bit word: new = (old & keep) | set.
  if (t.depth && (c.clear_depth || (c.clear_stencil && t.has_stencil))) {
    uint32_t keep = 0xFFFFFFFFu, set = 0;
    if (c.clear_depth) {
      const float z = std::clamp(c.depth, 0.0f, 1.0f);
      if (t.depth_format == Format::Depth32F) {
        keep = 0;
        std::memcpy(&set, &z, 4);
      } else {
        keep = 0xFF000000u;  // 24-bit depth: the high byte (stencil) stays
        set = quantize24(z);
      }
    }
    if (c.clear_stencil && t.has_stencil) {
      const uint32_t m = uint32_t(c.stencil_write_mask) << 24;
      keep &= ~m;
      set = (set & ~m) | ((uint32_t(c.stencil) << 24) & m);
    }
    uint8_t kb[4], sb[4];
    std::memcpy(kb, &keep, 4);
    std::memcpy(sb, &set, 4);
    fill_rect(t.depth, t.depth_row_bytes, 4, kb, sb, x0, y0, x1, y1, stream);
  }
}

}  // namespace tessel::gpu::detail
