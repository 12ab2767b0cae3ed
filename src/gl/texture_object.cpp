// Texture objects: targets, completeness (GL 3.3 §3.8.14), the gpu texture made from the
// images, what rendering wrote copied back, and mipmap generation.
#define GL_GLEXT_PROTOTYPES 1
#include "texture_object.hpp"

#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "compressed.hpp"
#include "context.hpp"

namespace tessel::gl {

namespace {

constexpr GLenum kTargets[kTexTargetCount] = {GL_TEXTURE_1D,
                                              GL_TEXTURE_2D,
                                              GL_TEXTURE_3D,
                                              GL_TEXTURE_CUBE_MAP,
                                              GL_TEXTURE_1D_ARRAY,
                                              GL_TEXTURE_2D_ARRAY,
                                              GL_TEXTURE_RECTANGLE,
                                              GL_TEXTURE_BUFFER,
                                              GL_TEXTURE_2D_MULTISAMPLE,
                                              GL_TEXTURE_2D_MULTISAMPLE_ARRAY};
constexpr GLenum kBindings[kTexTargetCount] = {GL_TEXTURE_BINDING_1D,
                                               GL_TEXTURE_BINDING_2D,
                                               GL_TEXTURE_BINDING_3D,
                                               GL_TEXTURE_BINDING_CUBE_MAP,
                                               GL_TEXTURE_BINDING_1D_ARRAY,
                                               GL_TEXTURE_BINDING_2D_ARRAY,
                                               GL_TEXTURE_BINDING_RECTANGLE,
                                               GL_TEXTURE_BINDING_BUFFER,
                                               GL_TEXTURE_BINDING_2D_MULTISAMPLE,
                                               GL_TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY};

// Which sizes halve from level to level: width always, height except for 1D arrays (whose
// height is the layer count), depth only for 3D textures.
bool halves_height(TexTarget t) { return t != TexTarget::T1DArray && t != TexTarget::T1D; }
bool halves_depth(TexTarget t) { return t == TexTarget::T3D; }
// The targets of one level only (§3.8.4, §3.8.6).
bool single_level(TexTarget t) { return t == TexTarget::Rect || t == TexTarget::Buffer || is_multisample(t); }

// The number of levels from `base` that form a chain: each has the halved sizes of the one
// before and the base's internal format, down to 1x1(x1) and at most to max_level.
int chain_length(const TextureObject& t, int face, int base) {
  const TextureImage& b = t.image(face, base);
  if (!b.defined()) return 0;
  if (single_level(t.target)) return 1;
  int n = 1;
  for (int i = 1; base + i < kMaxTextureLevels && base + i <= t.max_level; ++i) {
    const int pw = std::max(1, b.width >> (i - 1));
    const int ph = halves_height(t.target) ? std::max(1, b.height >> (i - 1)) : b.height;
    const int pd = halves_depth(t.target) ? std::max(1, b.depth >> (i - 1)) : b.depth;
    if (pw == 1 && (ph == 1 || !halves_height(t.target)) && (pd == 1 || !halves_depth(t.target))) break;
    const TextureImage& l = t.image(face, base + i);
    const int w = std::max(1, b.width >> i);
    const int h = halves_height(t.target) ? std::max(1, b.height >> i) : b.height;
    const int d = halves_depth(t.target) ? std::max(1, b.depth >> i) : b.depth;
    if (l.width != w || l.height != h || l.depth != d || l.fmt.internal != b.fmt.internal) break;
    ++n;
  }
  return n;
}

// Levels needed for mipmapping from the base: floor(log2(largest size)) + 1, at most up to
// max_level (§3.8.14's q - base + 1).
int levels_needed(const TextureObject& t, int base) {
  const TextureImage& b = t.image(0, base);
  int m = b.width;
  if (halves_height(t.target)) m = std::max(m, b.height);
  if (halves_depth(t.target)) m = std::max(m, b.depth);
  int p = 0;
  while ((m >> p) > 1) ++p;
  return std::min(p, std::max(0, t.max_level - base)) + 1;
}

bool mipmapped(GLenum min_filter) { return min_filter != GL_NEAREST && min_filter != GL_LINEAR; }

gpu::Filter filter_of(GLenum f) {
  switch (f) {
    case GL_NEAREST: return gpu::Filter::Nearest;
    case GL_LINEAR: return gpu::Filter::Linear;
    case GL_NEAREST_MIPMAP_NEAREST: return gpu::Filter::NearestMipmapNearest;
    case GL_LINEAR_MIPMAP_NEAREST: return gpu::Filter::LinearMipmapNearest;
    case GL_NEAREST_MIPMAP_LINEAR: return gpu::Filter::NearestMipmapLinear;
    default: return gpu::Filter::LinearMipmapLinear;
  }
}

gpu::Wrap wrap_of(GLenum w) {
  switch (w) {
    case GL_CLAMP: return gpu::Wrap::Clamp;
    case GL_CLAMP_TO_EDGE: return gpu::Wrap::ClampToEdge;
    case GL_MIRRORED_REPEAT: return gpu::Wrap::MirroredRepeat;
    case GL_CLAMP_TO_BORDER: return gpu::Wrap::ClampToBorder;
    default: return gpu::Wrap::Repeat;
  }
}

// Fills the levels of a gpu texture from the images (the shape already matches).
template <class Upload>
void upload_levels(const TextureObject& t, int face, int base, int n, Upload&& up) {
  for (int i = 0; i < n; ++i) {
    const TextureImage& l = t.image(face, base + i);
    up(i, l.data.data(), l.data.size());
  }
}

}  // namespace

GLenum gl_target_of(TexTarget t) { return kTargets[size_t(t)]; }
GLenum binding_query_of(TexTarget t) { return kBindings[size_t(t)]; }

bool tex_target_of(GLenum target, TexTarget& out) {
  for (int i = 0; i < kTexTargetCount; ++i)
    if (kTargets[i] == target) {
      out = TexTarget(i);
      return true;
    }
  return false;
}

TextureRef make_texture(GLuint name, TexTarget target) {
  auto t = std::make_shared<TextureObject>();
  t->name = name;
  t->target = target;
  if (target == TexTarget::Rect) {
    t->sampler.min_filter = GL_LINEAR;
    t->sampler.wrap_s = t->sampler.wrap_t = t->sampler.wrap_r = GL_CLAMP_TO_EDGE;
  }
  return t;
}

int TextureObject::effective_base() const { return std::clamp(base_level, 0, kMaxTextureLevels - 1); }

bool texture_complete(const TextureObject& t, const SamplerParams& p) {
  if (t.target == TexTarget::Buffer) return t.buffer != nullptr;
  const int base = t.effective_base();
  const TextureImage& b = t.image(0, base);
  // A base level beyond the last level has no image: incomplete (§3.8.14).
  if (t.base_level >= kMaxTextureLevels || !b.defined() || t.base_level > t.max_level) return false;
  // A multisample texture has no filtering (texelFetch only): complete with its image.
  if (is_multisample(t.target)) return true;
  // Integer textures filter with NEAREST only (§3.8.14).
  if (b.fmt.integer() && (p.mag_filter != GL_NEAREST ||
                          (p.min_filter != GL_NEAREST && p.min_filter != GL_NEAREST_MIPMAP_NEAREST)))
    return false;
  const int need = mipmapped(p.min_filter) ? levels_needed(t, base) : 1;
  for (int f = 0; f < t.faces(); ++f) {
    const TextureImage& fb = t.image(f, base);
    // Cube completeness: six square faces of one size and format.
    if (!fb.defined() || fb.width != b.width || fb.height != b.height || fb.fmt.internal != b.fmt.internal ||
        (t.target == TexTarget::Cube && fb.width != fb.height))
      return false;
    if (chain_length(t, f, base) < need) return false;
  }
  return true;
}

bool update_gpu_texture(Context& c, TextureObject& t) {
  (void)c;
  if (t.target == TexTarget::Buffer) {
    if (!t.buffer) {
      t.tbuf.reset();
      return false;
    }
    // The view follows the buffer's store; remade when the binding changed (dirty).
    if (t.dirty || !t.tbuf) {
      try {
        t.tbuf = std::make_unique<gpu::TextureBuffer>(t.buffer_texel, t.buffer->data);
      } catch (const std::exception&) {
        t.tbuf.reset();
      }
      t.dirty = false;
    }
    return t.tbuf != nullptr;
  }
  if (!t.dirty) return t.gpu_levels > 0;
  t.dirty = false;
  const int base = t.effective_base();
  const TextureImage& b = t.image(0, base);
  if (!b.defined() || t.base_level >= kMaxTextureLevels) {
    t.gpu_levels = 0;
    return false;
  }
  int n = chain_length(t, 0, base);
  if (t.target == TexTarget::Cube)
    for (int f = 1; f < 6; ++f) {
      const TextureImage& fb = t.image(f, base);
      if (!fb.defined() || fb.width != b.width || fb.height != b.height ||
          fb.fmt.internal != b.fmt.internal) {
        n = 0;
        break;
      }
      n = std::min(n, chain_length(t, f, base));
    }
  if (n == 0 || (t.target == TexTarget::Cube && b.width != b.height)) {
    t.gpu_levels = 0;
    return false;
  }
  const gpu::Format fmt = b.fmt.storage;
  try {
    switch (t.target) {
      case TexTarget::T1D:
      case TexTarget::T2D:
      case TexTarget::Rect:
      case TexTarget::T2DMS:
        if (!t.tex2d || t.tex2d->format() != fmt || t.tex2d->width() != b.width ||
            t.tex2d->height() != b.height || t.tex2d->levels() != n)
          t.tex2d = std::make_unique<gpu::Texture2D>(fmt, b.width, b.height, n);
        upload_levels(t, 0, base, n, [&](int i, const void* d, size_t s) { t.tex2d->upload(i, d, s); });
        break;
      case TexTarget::Cube:
        if (!t.cube || t.cube->format() != fmt || t.cube->size() != b.width || t.cube->levels() != n)
          t.cube = std::make_unique<gpu::TextureCube>(fmt, b.width, n);
        for (int f = 0; f < 6; ++f)
          upload_levels(t, f, base, n,
                        [&](int i, const void* d, size_t s) { t.cube->face(f).upload(i, d, s); });
        break;
      case TexTarget::T3D:
        if (!t.tex3d || t.tex3d->format() != fmt || t.tex3d->width() != b.width ||
            t.tex3d->height() != b.height || t.tex3d->depth() != b.depth || t.tex3d->levels() != n)
          t.tex3d = std::make_unique<gpu::Texture3D>(fmt, b.width, b.height, b.depth, n);
        upload_levels(t, 0, base, n, [&](int i, const void* d, size_t s) { t.tex3d->upload(i, d, s); });
        break;
      case TexTarget::T1DArray:
      case TexTarget::T2DArray:
      case TexTarget::T2DMSArray: {
        const bool one = t.target == TexTarget::T1DArray;
        const int h = one ? 1 : b.height, layers = one ? b.height : b.depth;
        if (!t.array || t.array->format() != fmt || t.array->width() != b.width || t.array->height() != h ||
            t.array->layers() != layers || t.array->levels() != n)
          t.array = std::make_unique<gpu::Texture2DArray>(fmt, b.width, h, layers, n);
        upload_levels(t, 0, base, n, [&](int i, const void* d, size_t s) { t.array->upload(i, d, s); });
        break;
      }
      case TexTarget::Buffer: break;
    }
  } catch (const std::bad_alloc&) {
    t.gpu_levels = 0;
    return false;
  } catch (const std::exception&) {
    t.gpu_levels = 0;  // beyond the gpu's limits: treated as incomplete
    return false;
  }
  t.gpu_base = base;
  t.gpu_levels = n;
  return true;
}

void pull_rendered(Context& c, TextureObject& t) {
  if (!t.rendered) return;
  t.rendered = false;
  if (t.dirty || t.gpu_levels == 0) return;  // the images are newer (or nothing was made)
  c.finish();
  auto pull = [&](const gpu::Texture2D& g, int face) {
    for (int i = 0; i < t.gpu_levels && i < g.levels(); ++i) {
      TextureImage& img = t.image(face, t.gpu_base + i);
      const gpu::Level& l = g.level(i);
      if (img.data.size() == l.data.size()) std::memcpy(img.data.data(), l.data.data(), l.data.size());
    }
  };
  if ((t.target == TexTarget::T2D || t.target == TexTarget::T1D || t.target == TexTarget::Rect ||
       t.target == TexTarget::T2DMS) &&
      t.tex2d)
    pull(*t.tex2d, 0);
  if (t.target == TexTarget::Cube && t.cube)
    for (int f = 0; f < 6; ++f) pull(t.cube->face(f), f);
  // 3D and array textures (a 1D array's layers are its image's rows): every layer at once.
  auto pull_layers = [&](const auto& g) {
    for (int i = 0; i < t.gpu_levels && i < g.levels(); ++i) {
      TextureImage& img = t.image(0, t.gpu_base + i);
      const gpu::Level3D& l = g.level(i);
      if (img.data.size() == l.data.size()) std::memcpy(img.data.data(), l.data.data(), l.data.size());
    }
  };
  if (t.target == TexTarget::T3D && t.tex3d) pull_layers(*t.tex3d);
  if ((t.target == TexTarget::T2DArray || t.target == TexTarget::T1DArray ||
       t.target == TexTarget::T2DMSArray) &&
      t.array)
    pull_layers(*t.array);
}

gpu::SamplerState sampler_state_of(const SamplerParams& p, const TextureObject& t) {
  gpu::SamplerState st;
  st.min_filter = filter_of(p.min_filter);
  st.mag_filter = filter_of(p.mag_filter);
  st.wrap_s = wrap_of(p.wrap_s);
  st.wrap_t = wrap_of(p.wrap_t);
  st.wrap_r = wrap_of(p.wrap_r);
  st.border_color = p.border;
  st.lod_bias = p.lod_bias;
  st.min_lod = p.min_lod;
  st.max_lod = p.max_lod;
  const TextureImage& b = t.base_image();
  st.compare = p.compare_mode == GL_COMPARE_REF_TO_TEXTURE && b.defined() && b.fmt.is_depth();
  st.compare_func = compare_of(p.compare_func);
  return st;
}

std::array<uint8_t, 4> swizzle_of(const TextureObject& t, bool core) {
  auto code = [](GLenum s) -> uint8_t {
    switch (s) {
      case GL_RED: return 0;
      case GL_GREEN: return 1;
      case GL_BLUE: return 2;
      case GL_ALPHA: return 3;
      case GL_ZERO: return 4;
      default: return 5;  // GL_ONE
    }
  };
  std::array<uint8_t, 4> base{0, 1, 2, 3};
  const TextureImage& b = t.base_image();
  if (!core && b.defined() && b.fmt.is_depth()) {
    // GL 3.3 compatibility Table 3.23: depth textures read as luminance, intensity, alpha or red.
    switch (t.depth_mode) {
      case GL_LUMINANCE: base = {0, 0, 0, 5}; break;
      case GL_INTENSITY: base = {0, 0, 0, 0}; break;
      case GL_ALPHA: base = {4, 4, 4, 0}; break;
      default: base = {0, 4, 4, 5}; break;
    }
  }
  std::array<uint8_t, 4> out{};
  for (int k = 0; k < 4; ++k) {
    const uint8_t s = code(t.swizzle[size_t(k)]);
    out[size_t(k)] = s < 4 ? base[s] : s;
  }
  return out;
}

// Each texel of a new level is the bilinear sample of the level above at its centre (clamped
// to the edge): what llvmpipe's generation by blits gives, a 2x2 box where the level above
// has an even size. 3D textures also filter between two slices; arrays filter each layer.
// RGBA8 levels are filtered on the byte values and rounded to nearest, as llvmpipe does.
void generate_mipmaps(Context& c, TextureObject& t) {
  pull_rendered(c, t);
  const int base = t.effective_base();
  t.dirty = true;
  const bool h_halves = halves_height(t.target), d_halves = halves_depth(t.target);
  for (int f = 0; f < t.faces(); ++f) {
    if (!t.image(f, base).defined()) continue;
    for (int lv = base + 1; lv < kMaxTextureLevels && lv <= t.max_level; ++lv) {
      const TextureImage& src = t.image(f, lv - 1);
      if (src.width == 1 && (src.height == 1 || !h_halves) && (src.depth == 1 || !d_halves)) break;
      TextureImage& dst = t.image(f, lv);
      dst.width = std::max(1, src.width / 2);
      dst.height = h_halves ? std::max(1, src.height / 2) : src.height;
      dst.depth = d_halves ? std::max(1, src.depth / 2) : src.depth;
      dst.fmt = src.fmt;
      const gpu::Format sf = src.fmt.storage;
      const size_t bpp = gpu::format_info(sf).bytes;
      dst.data.assign(size_t(dst.width) * size_t(dst.height) * size_t(dst.depth) * bpp, std::byte{0});
      const float kx = float(src.width) / float(dst.width), ky = float(src.height) / float(dst.height);
      const float kz = float(src.depth) / float(dst.depth);
      auto taps = [](float s, int n, float k, int& i0, int& i1, float& fr) {
        const float p = (s + 0.5f) * k - 0.5f;
        i0 = std::clamp(int(std::floor(p)), 0, n - 1);
        i1 = std::min(i0 + 1, n - 1);
        fr = std::clamp(p - std::floor(p), 0.0f, 1.0f);
      };
      for (int z = 0; z < dst.depth; ++z) {
        int z0 = z, z1 = z;
        float fz = 0.0f;
        if (d_halves) taps(float(z), src.depth, kz, z0, z1, fz);
        for (int y = 0; y < dst.height; ++y) {
          int y0 = y, y1 = y;
          float fy = 0.0f;
          if (h_halves) taps(float(y), src.height, ky, y0, y1, fy);
          for (int x = 0; x < dst.width; ++x) {
            int x0, x1;
            float fx;
            taps(float(x), src.width, kx, x0, x1, fx);
            auto at = [&](int xx, int yy, int zz) {
              return src.data.data() +
                     ((size_t(zz) * size_t(src.height) + size_t(yy)) * size_t(src.width) + size_t(xx)) * bpp;
            };
            std::byte* out =
                dst.data.data() +
                ((size_t(z) * size_t(dst.height) + size_t(y)) * size_t(dst.width) + size_t(x)) * bpp;
            if (sf == gpu::Format::RGBA8 && !d_halves) {
              for (int k = 0; k < 4; ++k) {
                auto v8 = [&](int xx, int yy) { return float(uint8_t(at(xx, yy, z)[k])); };
                const float v = (v8(x0, y0) * (1 - fx) + v8(x1, y0) * fx) * (1 - fy) +
                                (v8(x0, y1) * (1 - fx) + v8(x1, y1) * fx) * fy;
                out[k] = std::byte(uint8_t(std::clamp(std::floor(v + 0.5f), 0.0f, 255.0f)));
              }
              continue;
            }
            auto px = [&](int xx, int yy, int zz) { return gpu::detail::decode_texel(sf, at(xx, yy, zz)); };
            auto plane = [&](int zz) {
              return (px(x0, y0, zz) * (1 - fx) + px(x1, y0, zz) * fx) * (1 - fy) +
                     (px(x0, y1, zz) * (1 - fx) + px(x1, y1, zz) * fx) * fy;
            };
            glm::vec4 v = plane(z0);
            if (d_halves) v = v * (1 - fz) + plane(z1) * fz;
            gpu::detail::encode_texel(sf, out, v);
          }
        }
      }
      dst.blocks.clear();
      compress_region(dst, 0, 0, 0, dst.width, dst.height, dst.depth);  // RGTC levels are compressed too
    }
  }
}

}  // namespace tessel::gl
