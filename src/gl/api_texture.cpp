// Texture objects and images (GL 3.3 compatibility §3.8.1-§3.8.7, §3.8.16-§3.8.17, §6.1.4):
// glGenTextures, glBindTexture, glTexImage1D/2D/3D, glTexSubImage*, glCopyTexImage*,
// glCopyTexSubImage*, glTexBuffer, glGenerateMipmap and glGetTexImage, for every target, and
// the compressed images of §3.8.3 (glCompressedTex*Image*, glGetCompressedTexImage).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>

#include "api.hpp"
#include "compressed.hpp"
#include "pixels.hpp"

namespace tessel::gl {

namespace {

// Where an image call writes: the texture target, the cube face, or a proxy.
struct ImageTarget {
  TexTarget target = TexTarget::T2D;
  int face = 0;
  bool proxy = false;
};

// The targets glTexImage{1,2,3}D take (dims = 1, 2, 3); false: GL_INVALID_ENUM.
bool image_target(GLenum target, int dims, ImageTarget& out) {
  out = {};
  switch (target) {
    case GL_PROXY_TEXTURE_1D: out.proxy = true; [[fallthrough]];
    case GL_TEXTURE_1D: out.target = TexTarget::T1D; return dims == 1;
    case GL_PROXY_TEXTURE_2D: out.proxy = true; [[fallthrough]];
    case GL_TEXTURE_2D: out.target = TexTarget::T2D; return dims == 2;
    case GL_PROXY_TEXTURE_1D_ARRAY: out.proxy = true; [[fallthrough]];
    case GL_TEXTURE_1D_ARRAY: out.target = TexTarget::T1DArray; return dims == 2;
    case GL_PROXY_TEXTURE_RECTANGLE: out.proxy = true; [[fallthrough]];
    case GL_TEXTURE_RECTANGLE: out.target = TexTarget::Rect; return dims == 2;
    case GL_PROXY_TEXTURE_CUBE_MAP:
      out.proxy = true;
      out.target = TexTarget::Cube;
      return dims == 2;
    case GL_PROXY_TEXTURE_3D: out.proxy = true; [[fallthrough]];
    case GL_TEXTURE_3D: out.target = TexTarget::T3D; return dims == 3;
    case GL_PROXY_TEXTURE_2D_ARRAY: out.proxy = true; [[fallthrough]];
    case GL_TEXTURE_2D_ARRAY: out.target = TexTarget::T2DArray; return dims == 3;
    default:
      if (target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z) {
        out.target = TexTarget::Cube;
        out.face = int(target - GL_TEXTURE_CUBE_MAP_POSITIVE_X);
        return dims == 2;
      }
      return false;
  }
}

int max_size_of(TexTarget t) { return t == TexTarget::T3D ? kMax3DTextureSize : kMaxTextureSize; }

TextureObject& proxy_texture(Context& c, TexTarget t) {
  TextureRef& r = c.proxy_textures[size_t(t)];
  if (!r) r = make_texture(0, t);
  return *r;
}

TextureObject& target_object(Context& c, const ImageTarget& it) {
  return it.proxy ? proxy_texture(c, it.target) : c.bound_texture(it.target);
}

// The checks of glTexImage's sizes (§3.8.3): GL_INVALID_VALUE for a negative or too large
// size, a level beyond the largest, a border, a rectangle level other than 0, a cube face
// that is not square. Returns the error (GL_NO_ERROR when the sizes are fine).
GLenum check_sizes(const ImageTarget& it, GLint level, GLsizei w, GLsizei h, GLsizei d, GLint border) {
  const int max = max_size_of(it.target);
  int max_level = 0;
  while ((max >> max_level) > 1) ++max_level;
  if (level < 0 || level > max_level || border != 0 || w < 0 || h < 0 || d < 0) return GL_INVALID_VALUE;
  if (w > max || (it.target != TexTarget::T1DArray && h > max) ||
      (it.target == TexTarget::T1DArray && h > kMaxArrayTextureLayers) ||
      (it.target == TexTarget::T2DArray && d > kMaxArrayTextureLayers) ||
      (it.target == TexTarget::T3D && d > max))
    return GL_INVALID_VALUE;
  if (it.target == TexTarget::Rect && level != 0) return GL_INVALID_VALUE;
  if (it.target == TexTarget::Cube && w != h) return GL_INVALID_VALUE;
  return GL_NO_ERROR;
}

// The GL_INVALID_OPERATION cases of §3.8.3 between the internal format and the format: depth
// with non-depth, integer with non-integer, depth formats on 3D textures.
GLenum check_format_match(const TexFormat& f, GLenum format, TexTarget target) {
  const bool depth_format = format == GL_DEPTH_COMPONENT || format == GL_DEPTH_STENCIL;
  if (f.is_depth() != depth_format) return GL_INVALID_OPERATION;
  if (f.base == TexBase::DepthStencil && format != GL_DEPTH_STENCIL && format != GL_DEPTH_COMPONENT)
    return GL_INVALID_OPERATION;
  if (f.integer() != is_integer_format(format)) return GL_INVALID_OPERATION;
  if (f.is_depth() && target == TexTarget::T3D) return GL_INVALID_OPERATION;
  return GL_NO_ERROR;
}

// Unpacked texels of an image call, taken when the call is made (a display list keeps them).
struct ImageData {
  std::vector<glm::vec4> px;
};
using ImageRef = std::shared_ptr<const ImageData>;

// Where the images of a w x h x d block lie in client memory: each image's rows as the pixel
// store's layout says, images `image_stride` bytes apart from image `first` on. 3D calls
// (glTexImage3D, glTexSubImage3D, glGetTexImage of a 3D or array texture) use
// GL_*_IMAGE_HEIGHT and GL_*_SKIP_IMAGES (GL 3.3 §3.7.4, §6.1.4); the others do not.
struct BlockLayout {
  PixelLayout rows;
  size_t image_stride = 0, first = 0;
  size_t bytes = 0;  // from the start of the memory to the end of the last pixel
};
BlockLayout block_layout(const PixelStore& ps, GLsizei w, GLsizei h, GLsizei d, bool three_d, GLenum format,
                         GLenum type) {
  BlockLayout b;
  b.rows = pixel_layout(ps, w, format, type);
  const size_t rows_per_image = three_d && ps.image_height > 0 ? size_t(ps.image_height) : size_t(h);
  b.image_stride = b.rows.row_stride * rows_per_image;
  b.first = three_d ? size_t(ps.skip_images) : 0;
  b.bytes = b.rows.offset + (b.first + size_t(d) - 1) * b.image_stride + b.rows.row_stride * size_t(h - 1) +
            b.rows.pixel_stride * size_t(w);
  return b;
}

// The memory of a transfer: the client's pointer, or the pixel unpack/pack buffer's bytes at
// the offset `pixels` (GL 3.3 §3.7.1, §4.3.2). Null with `err` set when that buffer is mapped or
// too small, or the offset is not a multiple of the size of `type` (§3.7.2, §4.3.1); null
// without an error when there is nothing to read or write.
std::byte* transfer_memory(const BufferRef& pbo, void* pixels, size_t bytes, GLenum type, GLenum& err) {
  err = GL_NO_ERROR;
  if (!pbo) return static_cast<std::byte*>(pixels);
  const size_t offset = reinterpret_cast<size_t>(pixels);
  const size_t unit = size_t(std::max(1, type_bytes(type)));
  if (pbo->mapped || offset % unit != 0) {
    err = GL_INVALID_OPERATION;
    return nullptr;
  }
  if (offset + bytes > pbo->data.size() || offset + bytes < offset) {
    err = GL_INVALID_OPERATION;
    return nullptr;
  }
  return pbo->data.writable() + offset;
}

ImageRef unpack(Context& c, GLsizei w, GLsizei h, GLsizei d, bool three_d, GLenum format, GLenum type,
                const void* pixels, GLenum& err) {
  err = GL_NO_ERROR;
  if (w <= 0 || h <= 0 || d <= 0) return nullptr;
  const PixelStore& ps = c.c.unpack;
  const BlockLayout b = block_layout(ps, w, h, d, three_d, format, type);
  const std::byte* base =
      transfer_memory(c.pixel_unpack_buffer, const_cast<void*>(pixels), b.bytes, type, err);
  if (!base) return nullptr;
  auto data = std::make_shared<ImageData>();
  data->px.reserve(size_t(w) * size_t(h) * size_t(d));
  std::vector<glm::vec4> image;
  for (GLsizei k = 0; k < d; ++k) {
    unpack_pixels(ps, w, h, format, type, base + (b.first + size_t(k)) * b.image_stride, image);
    data->px.insert(data->px.end(), image.begin(), image.end());
  }
  return data;
}

// Fills `img` (already sized) at texel offset (x, y, z) with a w x h x d block of unpacked
// texels, converted to the storage format.
void store_block(TextureImage& img, int x, int y, int z, int w, int h, int d, const ImageData& data) {
  const size_t bpp = gpu::format_info(img.fmt.storage).bytes;
  for (int k = 0; k < d; ++k)
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const glm::vec4& px = data.px[(size_t(k) * size_t(h) + size_t(j)) * size_t(w) + size_t(i)];
        std::byte* out =
            img.data.data() +
            ((size_t(z + k) * size_t(img.height) + size_t(y + j)) * size_t(img.width) + size_t(x + i)) * bpp;
        gpu::detail::encode_texel(img.fmt.storage, out, to_storage(img.fmt, px));
      }
}

void texture_changed(Context& c, TextureObject& t) {
  c.touch();
  t.dirty = true;
}

void tex_image(Context& c, const ImageTarget& it, GLint level, const TexFormat& fmt, GLsizei w, GLsizei h,
               GLsizei d, const ImageRef& data) {
  GL_OUTSIDE_BEGIN();
  TextureObject& t = target_object(c, it);
  if (it.proxy) {
    // A proxy that fits records the sizes; one that does not has its state zeroed (§3.8.15).
    TextureImage& img = t.image(it.face, level);
    const size_t bytes = size_t(w) * size_t(h) * size_t(d) * gpu::format_info(fmt.storage).bytes;
    img = TextureImage{};
    if (bytes <= gpu::kMaxTextureBytes) {
      img.width = w, img.height = h, img.depth = d;
      img.fmt = fmt;
    }
    return;
  }
  pull_rendered(c, t);
  texture_changed(c, t);
  TextureImage& img = t.image(it.face, level);
  if (w == 0 || h == 0 || d == 0) {
    img = TextureImage{};  // a zero-sized image: the level is no longer defined
    return;
  }
  const size_t bytes = size_t(w) * size_t(h) * size_t(d) * gpu::format_info(fmt.storage).bytes;
  if (bytes > gpu::kMaxTextureBytes) return c.error(GL_OUT_OF_MEMORY);
  try {
    img.data.assign(bytes, std::byte{0});
  } catch (const std::bad_alloc&) {
    img = TextureImage{};
    return c.error(GL_OUT_OF_MEMORY);
  }
  img.width = w, img.height = h, img.depth = d;
  img.fmt = fmt;
  img.blocks.clear();
  if (data) {
    store_block(img, 0, 0, 0, w, h, d, *data);
  } else if (!fmt.is_depth()) {
    // No data: texels undefined in GL; (0, 0, 0, fixed alpha) here, as to_storage makes them.
    const glm::vec4 zero = to_storage(fmt, glm::vec4(0.0f));
    const size_t bpp = gpu::format_info(fmt.storage).bytes;
    for (size_t i = 0; i < bytes; i += bpp) gpu::detail::encode_texel(fmt.storage, img.data.data() + i, zero);
  }
  compress_region(img, 0, 0, 0, w, h, d);  // a compressed format samples as its blocks
  if (t.generate_mipmap && level == t.effective_base()) generate_mipmaps(c, t);  // GL 1.4 §3.8.8
}

// The errors of a glTexSubImage/glCopyTexSubImage region (§3.8.5): no such level or image, or
// a region outside the image (in 64 bits: x + w must not wrap).
GLenum sub_image_error(Context& c, const ImageTarget& it, GLint level, GLint x, GLint y, GLint z, GLsizei w,
                       GLsizei h, GLsizei d) {
  if (it.proxy) return GL_INVALID_ENUM;
  if (level < 0 || level >= kMaxTextureLevels) return GL_INVALID_VALUE;
  const TextureImage& img = c.bound_texture(it.target).image(it.face, level);
  if (!img.defined()) return GL_INVALID_OPERATION;
  if (x < 0 || y < 0 || z < 0 || w < 0 || h < 0 || d < 0 || int64_t(x) + w > img.width ||
      int64_t(y) + h > img.height || int64_t(z) + d > img.depth)
    return GL_INVALID_VALUE;
  // §3.8.3: a region of an RGTC image starts on a 4x4 block and spans whole blocks or reaches
  // the image's edge.
  if (img.fmt.rgtc() && (x % 4 || y % 4 || (w % 4 && x + w != img.width) || (h % 4 && y + h != img.height)))
    return GL_INVALID_OPERATION;
  return GL_NO_ERROR;
}

void tex_sub_image(Context& c, const ImageTarget& it, GLint level, GLint x, GLint y, GLint z, GLsizei w,
                   GLsizei h, GLsizei d, GLenum format, const ImageRef& data) {
  GL_OUTSIDE_BEGIN();
  if (const GLenum e = sub_image_error(c, it, level, x, y, z, w, h, d); e != GL_NO_ERROR) return c.error(e);
  TextureObject& t = c.bound_texture(it.target);
  TextureImage& img = t.image(it.face, level);
  if (format != GL_NONE) {
    const GLenum e = check_format_match(img.fmt, format, it.target);
    if (e != GL_NO_ERROR) return c.error(e);
  }
  if (!data || w == 0 || h == 0 || d == 0) return;
  pull_rendered(c, t);
  texture_changed(c, t);
  store_block(img, x, y, z, w, h, d, *data);
  compress_region(img, x, y, z, w, h, d);
  if (t.generate_mipmap && level == t.effective_base()) generate_mipmaps(c, t);
}

// §3.8.3: RGTC images are 2D - of 2D textures, cube map faces and 2D array layers. For the
// other targets (1D, rectangles, 3D) Mesa 22 gives GL_INVALID_ENUM.
GLenum compressed_target_error(const TexFormat& fmt, const ImageTarget& it) {
  if (!fmt.rgtc()) return GL_NO_ERROR;
  switch (it.target) {
    case TexTarget::T2D:
    case TexTarget::Cube:
    case TexTarget::T2DArray: return GL_NO_ERROR;
    default: return GL_INVALID_ENUM;
  }
}

// The entry points' common part: the checks that come before the pixels are read.
bool image_checks(Context& c, const ImageTarget& it, GLint level, GLint internal, GLsizei w, GLsizei h,
                  GLsizei d, GLint border, GLenum format, GLenum type, TexFormat& fmt) {
  const GLenum ft = check_format_type(format, type, c.core_profile);
  if (ft != GL_NO_ERROR) {
    c.error(ft);
    return false;
  }
  if (!tex_format_of(internal, c.core_profile, fmt)) {
    c.error(GL_INVALID_VALUE);
    return false;
  }
  if (const GLenum ce = compressed_target_error(fmt, it); ce != GL_NO_ERROR) {
    c.error(ce);
    return false;
  }
  const GLenum e = check_sizes(it, level, w, h, d, border);
  if (e != GL_NO_ERROR) {
    c.error(e);
    return false;
  }
  const GLenum m = check_format_match(fmt, format, it.target);
  if (m != GL_NO_ERROR) {
    c.error(m);
    return false;
  }
  return true;
}

void tex_image_entry(GLenum target, int dims, GLint level, GLint internal, GLsizei w, GLsizei h, GLsizei d,
                     GLint border, GLenum format, GLenum type, const void* pixels) {
  GL_CONTEXT();
  if (!c.compiling_only() && c.in_begin) return c.error(GL_INVALID_OPERATION);
  ImageTarget it;
  if (!image_target(target, dims, it)) return c.error(GL_INVALID_ENUM);
  TexFormat fmt;
  if (!image_checks(c, it, level, internal, w, h, d, border, format, type, fmt)) return;
  // What the image would take: more than a texture may hold is GL_OUT_OF_MEMORY, before the
  // client's pixels are read.
  if (!it.proxy &&
      uint64_t(w) * uint64_t(h) * uint64_t(d) * gpu::format_info(fmt.storage).bytes > gpu::kMaxTextureBytes)
    return c.error(GL_OUT_OF_MEMORY);
  GLenum err = GL_NO_ERROR;
  ImageRef data;
  try {
    if (!it.proxy) data = unpack(c, w, h, d, dims == 3, format, type, pixels, err);
  } catch (const std::bad_alloc&) {
    return c.error(GL_OUT_OF_MEMORY);
  }
  if (err != GL_NO_ERROR) return c.error(err);
  // Proxies are not compiled into display lists (GL 2.1 §5.4).
  if (!it.proxy) GL_LISTED(tex_image(c, it, level, fmt, w, h, d, data));
  tex_image(c, it, level, fmt, w, h, d, data);
}

void tex_sub_image_entry(GLenum target, int dims, GLint level, GLint x, GLint y, GLint z, GLsizei w,
                         GLsizei h, GLsizei d, GLenum format, GLenum type, const void* pixels) {
  GL_CONTEXT();
  if (!c.compiling_only() && c.in_begin) return c.error(GL_INVALID_OPERATION);
  ImageTarget it;
  if (!image_target(target, dims, it) || it.proxy) return c.error(GL_INVALID_ENUM);
  const GLenum ft = check_format_type(format, type, c.core_profile);
  if (ft != GL_NO_ERROR) return c.error(ft);
  // The region is checked against the texture before the client's pixels are read: a region
  // larger than the image reads nothing.
  if (const GLenum e = sub_image_error(c, it, level, x, y, z, w, h, d); e != GL_NO_ERROR) return c.error(e);
  GLenum err = GL_NO_ERROR;
  ImageRef data;
  try {
    data = unpack(c, w, h, d, dims == 3, format, type, pixels, err);
  } catch (const std::bad_alloc&) {
    return c.error(GL_OUT_OF_MEMORY);
  }
  if (err != GL_NO_ERROR) return c.error(err);
  GL_LISTED(tex_sub_image(c, it, level, x, y, z, w, h, d, format, data));
  tex_sub_image(c, it, level, x, y, z, w, h, d, format, data);
}

// --- compressed images (§3.8.3) ------------------------------------------------------------

using Blocks = std::shared_ptr<const std::vector<uint8_t>>;

// The client's compressed bytes, or the pixel unpack buffer's; null with `err` set as for
// pixels (a mapped or too small buffer).
Blocks read_blocks(Context& c, const void* data, GLsizei size, GLenum& err) {
  err = GL_NO_ERROR;
  if (size <= 0) return nullptr;
  const std::byte* src =
      transfer_memory(c.pixel_unpack_buffer, const_cast<void*>(data), size_t(size), GL_UNSIGNED_BYTE, err);
  if (!src) return nullptr;
  const auto* p = reinterpret_cast<const uint8_t*>(src);
  return std::make_shared<const std::vector<uint8_t>>(p, p + size);
}

void compressed_tex_image(Context& c, const ImageTarget& it, GLint level, const TexFormat& fmt, GLsizei w,
                          GLsizei h, GLsizei d, const Blocks& blocks) {
  GL_OUTSIDE_BEGIN();
  tex_image(c, it, level, fmt, w, h, d, nullptr);
  if (it.proxy || !blocks) return;
  TextureObject& t = target_object(c, it);
  TextureImage& img = t.image(it.face, level);
  if (!img.defined() || img.fmt.internal != fmt.internal) return;  // it did not fit
  store_compressed(img, 0, 0, 0, w, h, d, blocks->data());
  if (t.generate_mipmap && level == t.effective_base()) generate_mipmaps(c, t);
}

void compressed_image_entry(GLenum target, int dims, GLint level, GLenum internal, GLsizei w, GLsizei h,
                            GLsizei d, GLint border, GLsizei size, const void* data) {
  GL_CONTEXT();
  if (!c.compiling_only() && c.in_begin) return c.error(GL_INVALID_OPERATION);
  ImageTarget it;
  if (!image_target(target, dims, it)) return c.error(GL_INVALID_ENUM);
  // Only a specific compressed format: the generic ones (GL_COMPRESSED_RED, ...) are for
  // glTexImage to choose a format (§3.8.3).
  TexFormat fmt;
  if (!tex_format_of(GLint(internal), c.core_profile, fmt) || !fmt.rgtc()) return c.error(GL_INVALID_ENUM);
  if (const GLenum ce = compressed_target_error(fmt, it); ce != GL_NO_ERROR) return c.error(ce);
  if (const GLenum e = check_sizes(it, level, w, h, d, border); e != GL_NO_ERROR) return c.error(e);
  if (size < 0 || size_t(size) != compressed_bytes(fmt, w, h, d)) return c.error(GL_INVALID_VALUE);
  if (!it.proxy &&
      uint64_t(w) * uint64_t(h) * uint64_t(d) * gpu::format_info(fmt.storage).bytes > gpu::kMaxTextureBytes)
    return c.error(GL_OUT_OF_MEMORY);
  GLenum err = GL_NO_ERROR;
  Blocks blocks;
  try {
    if (!it.proxy) blocks = read_blocks(c, data, size, err);
  } catch (const std::bad_alloc&) {
    return c.error(GL_OUT_OF_MEMORY);
  }
  if (err != GL_NO_ERROR) return c.error(err);
  if (!it.proxy) GL_LISTED(compressed_tex_image(c, it, level, fmt, w, h, d, blocks));
  compressed_tex_image(c, it, level, fmt, w, h, d, blocks);
}

void compressed_tex_sub_image(Context& c, const ImageTarget& it, GLint level, GLint x, GLint y, GLint z,
                              GLsizei w, GLsizei h, GLsizei d, GLenum format, const Blocks& blocks) {
  GL_OUTSIDE_BEGIN();
  if (const GLenum e = sub_image_error(c, it, level, x, y, z, w, h, d); e != GL_NO_ERROR) return c.error(e);
  TextureObject& t = c.bound_texture(it.target);
  TextureImage& img = t.image(it.face, level);
  if (img.fmt.internal != format) return c.error(GL_INVALID_OPERATION);
  if (!blocks || w == 0 || h == 0 || d == 0) return;
  pull_rendered(c, t);
  texture_changed(c, t);
  store_compressed(img, x, y, z, w, h, d, blocks->data());
  if (t.generate_mipmap && level == t.effective_base()) generate_mipmaps(c, t);
}

void compressed_sub_image_entry(GLenum target, int dims, GLint level, GLint x, GLint y, GLint z, GLsizei w,
                                GLsizei h, GLsizei d, GLenum format, GLsizei size, const void* data) {
  GL_CONTEXT();
  if (!c.compiling_only() && c.in_begin) return c.error(GL_INVALID_OPERATION);
  ImageTarget it;
  if (!image_target(target, dims, it) || it.proxy) return c.error(GL_INVALID_ENUM);
  TexFormat fmt;
  if (!tex_format_of(GLint(format), c.core_profile, fmt) || !fmt.rgtc()) return c.error(GL_INVALID_ENUM);
  if (const GLenum e = sub_image_error(c, it, level, x, y, z, w, h, d); e != GL_NO_ERROR) return c.error(e);
  const TextureImage& img = c.bound_texture(it.target).image(it.face, level);
  if (img.fmt.internal != format) return c.error(GL_INVALID_OPERATION);
  if (size < 0 || size_t(size) != compressed_bytes(fmt, w, h, d)) return c.error(GL_INVALID_VALUE);
  GLenum err = GL_NO_ERROR;
  Blocks blocks;
  try {
    blocks = read_blocks(c, data, size, err);
  } catch (const std::bad_alloc&) {
    return c.error(GL_OUT_OF_MEMORY);
  }
  if (err != GL_NO_ERROR) return c.error(err);
  GL_LISTED(compressed_tex_sub_image(c, it, level, x, y, z, w, h, d, format, blocks));
  compressed_tex_sub_image(c, it, level, x, y, z, w, h, d, format, blocks);
}

// Pixels of the read buffer as floats, rows bottom-up (for glCopyTex*); outside the buffer
// (0, 0, 0, 0). Depth when `depth`.
std::vector<glm::vec4> read_block(Context& c, GLint x, GLint y, GLsizei w, GLsizei h, bool depth) {
  c.finish();
  std::vector<glm::vec4> out(size_t(w) * size_t(h), glm::vec4(0.0f));
  const gpu::Attachment a = depth ? c.read_depth() : c.read_color();
  if (!a) return out;
  const int aw = a.width(), ah = a.height();
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const int sx = x + i, sy = y + j;
      if (sx < 0 || sy < 0 || sx >= aw || sy >= ah) continue;
      out[size_t(j) * size_t(w) + size_t(i)] = a.fetch(sx, sy);
    }
  return out;
}

void copy_tex_image(Context& c, const ImageTarget& it, GLint level, GLint internal, GLint x, GLint y,
                    GLsizei w, GLsizei h, GLint border) {
  GL_OUTSIDE_BEGIN();
  TexFormat fmt;
  if (!tex_format_of(internal, c.core_profile, fmt)) return c.error(GL_INVALID_ENUM);
  if (const GLenum ce = compressed_target_error(fmt, it); ce != GL_NO_ERROR) return c.error(ce);
  const GLenum e = check_sizes(it, level, w, h, 1, border);
  if (e != GL_NO_ERROR) return c.error(e);
  if (!c.read_framebuffer_complete()) return c.error(GL_INVALID_FRAMEBUFFER_OPERATION);
  // §3.8.4: an integer image copies only from an integer colour buffer and a non-integer one
  // only from a non-integer buffer; a multisample read framebuffer is not copied (§4.3.1).
  if (!fmt.is_depth() && fmt.integer() != c.read_color_integer().integer())
    return c.error(GL_INVALID_OPERATION);
  if (c.read_fbo && c.read_fbo->samples() > 0) return c.error(GL_INVALID_OPERATION);
  if (!(fmt.is_depth() ? c.read_depth() : c.read_color())) return c.error(GL_INVALID_OPERATION);
  auto data = std::make_shared<ImageData>();
  try {
    data->px = read_block(c, x, y, w, it.target == TexTarget::T1D ? 1 : h, fmt.is_depth());
  } catch (const std::bad_alloc&) {
    return c.error(GL_OUT_OF_MEMORY);
  }
  if (fmt.is_depth() && fmt.has_stencil())
    for (glm::vec4& p : data->px) p.y = 0.0f;
  tex_image(c, it, level, fmt, w, it.target == TexTarget::T1D ? 1 : h, 1, data);
}

void copy_tex_sub_image(Context& c, const ImageTarget& it, GLint level, GLint xo, GLint yo, GLint zo, GLint x,
                        GLint y, GLsizei w, GLsizei h) {
  GL_OUTSIDE_BEGIN();
  if (const GLenum e = sub_image_error(c, it, level, xo, yo, zo, w, h, 1); e != GL_NO_ERROR)
    return c.error(e);
  const TextureImage& img = c.bound_texture(it.target).image(it.face, level);
  if (!c.read_framebuffer_complete()) return c.error(GL_INVALID_FRAMEBUFFER_OPERATION);
  const bool depth = img.fmt.is_depth();
  if (!depth && img.fmt.integer() != c.read_color_integer().integer()) return c.error(GL_INVALID_OPERATION);
  if (c.read_fbo && c.read_fbo->samples() > 0) return c.error(GL_INVALID_OPERATION);
  if (!(depth ? c.read_depth() : c.read_color())) return c.error(GL_INVALID_OPERATION);
  auto data = std::make_shared<ImageData>();
  try {
    data->px = read_block(c, x, y, w, h, depth);
  } catch (const std::bad_alloc&) {
    return c.error(GL_OUT_OF_MEMORY);
  }
  tex_sub_image(c, it, level, xo, yo, zo, w, h, 1, GL_NONE, data);
}

// glTexImage2DMultisample / glTexImage3DMultisample (GL 3.3 §3.8.6): level 0 of a 2D or 2D
// array texture of `samples` samples, stored with one (as multisample renderbuffers are).
// The errors are Mesa's: a format neither colour-, depth- nor stencil-renderable (compressed
// ones too) GL_INVALID_ENUM; samples < 1 or a bad size GL_INVALID_VALUE; more samples than
// GL_MAX_SAMPLES GL_INVALID_OPERATION. Any sample count reads back as 4, as llvmpipe's.
void tex_image_multisample(Context& c, GLenum target, GLsizei samples, GLenum internal, GLsizei w, GLsizei h,
                           GLsizei d, GLboolean fixed, bool array) {
  GL_OUTSIDE_BEGIN();
  const bool proxy =
      target == (array ? GL_PROXY_TEXTURE_2D_MULTISAMPLE_ARRAY : GL_PROXY_TEXTURE_2D_MULTISAMPLE);
  if (target != (array ? GL_TEXTURE_2D_MULTISAMPLE_ARRAY : GL_TEXTURE_2D_MULTISAMPLE) && !proxy)
    return c.error(GL_INVALID_ENUM);
  TexFormat fmt;
  if (!tex_format_of(GLint(internal), c.core_profile, fmt) || fmt.rgtc() ||
      (!fmt.color_renderable() && !fmt.is_depth() && !fmt.has_stencil()))
    return c.error(GL_INVALID_ENUM);
  if (samples < 1) return c.error(GL_INVALID_VALUE);
  if (samples > kMaxSamples) return c.error(GL_INVALID_OPERATION);
  if (w < 0 || h < 0 || d < 0 || w > kMaxTextureSize || h > kMaxTextureSize || d > kMaxArrayTextureLayers)
    return c.error(GL_INVALID_VALUE);
  const TexTarget tt = array ? TexTarget::T2DMSArray : TexTarget::T2DMS;
  TextureObject& t = proxy ? proxy_texture(c, tt) : c.bound_texture(tt);
  ImageTarget it;
  it.target = tt;
  it.proxy = proxy;
  tex_image(c, it, 0, fmt, w, h, array ? d : 1, nullptr);
  t.samples = kMaxSamples;
  t.fixed_sample_locations = fixed != GL_FALSE;
}

void bind_texture(Context& c, GLenum target, GLuint name) {
  GL_OUTSIDE_BEGIN();
  TexTarget t;
  if (!tex_target_of(target, t)) return c.error(GL_INVALID_ENUM);
  if (name == 0) {
    c.touch();
    c.s.unit().bound[size_t(t)] = nullptr;
    return;
  }
  auto it = c.textures.find(name);
  if (c.core_profile && it == c.textures.end()) return c.error(GL_INVALID_OPERATION);  // not generated
  TextureRef& r = c.textures[name];
  if (!r) r = make_texture(name, t);
  if (r->target != t) return c.error(GL_INVALID_OPERATION);  // §3.8.1: bound before to another target
  c.touch();
  c.s.unit().bound[size_t(t)] = r;
}

// GL 3.3 §3.8.7, Table 3.15: the formats a buffer texture reads - one, two or four
// components of 8- or 16-bit unsigned normalized, 16- or 32-bit float, or 8-, 16- or 32-bit
// signed or unsigned integers - and their layout in the buffer's bytes.
bool buffer_texel_of(const TexFormat& f, gpu::BufferTexel& out) {
  using C = gpu::BufferComponent;
  // Sized formats only: not GL_RGBA, GL_COMPRESSED_RED or an RGTC format of the same layout.
  static constexpr GLenum kTable[] = {
      GL_R8,     GL_R16,     GL_R16F,    GL_R32F,    GL_R8I,      GL_R16I,    GL_R32I,    GL_R8UI,
      GL_R16UI,  GL_R32UI,   GL_RG8,     GL_RG16,    GL_RG16F,    GL_RG32F,   GL_RG8I,    GL_RG16I,
      GL_RG32I,  GL_RG8UI,   GL_RG16UI,  GL_RG32UI,  GL_RGBA8,    GL_RGBA16,  GL_RGBA16F, GL_RGBA32F,
      GL_RGBA8I, GL_RGBA16I, GL_RGBA32I, GL_RGBA8UI, GL_RGBA16UI, GL_RGBA32UI};
  if (std::find(std::begin(kTable), std::end(kTable), f.internal) == std::end(kTable)) return false;
  // Each format of the table has 1, 2 or 4 components of r bits (8, 16 or 32).
  const int size = f.r == 8 ? 0 : f.r == 16 ? 1 : 2;
  switch (f.kind) {
    case TexKind::Unorm: out.component = size == 0 ? C::Unorm8 : C::Unorm16; break;
    case TexKind::Float: out.component = size == 1 ? C::Float16 : C::Float32; break;
    case TexKind::Int: out.component = C(int(C::Int8) + size); break;
    default: out.component = C(int(C::Uint8) + size); break;
  }
  out.channels = uint8_t(f.base == TexBase::Red ? 1 : f.base == TexBase::RG ? 2 : 4);
  return true;
}

}  // namespace
}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glGenTextures(GLsizei n, GLuint* names) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = fresh_name(c.textures, c.next_texture_name);
    c.textures[name] = nullptr;  // reserved; the object is made when first bound
    if (names) names[i] = name;
  }
}
void GLAPIENTRY glDeleteTextures(GLsizei n, const GLuint* names) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  if (!names) return;
  c.touch();
  for (GLsizei i = 0; i < n; ++i) {
    auto it = c.textures.find(names[i]);
    if (names[i] == 0 || it == c.textures.end()) continue;
    if (it->second) c.texture_deleted(*it->second);  // unbound from every unit and framebuffer
    c.textures.erase(it);
  }
}
void GLAPIENTRY glBindTexture(GLenum target, GLuint name) {
  GL_CONTEXT();
  GL_LISTED(bind_texture(c, target, name));
  bind_texture(c, target, name);
}
GLboolean GLAPIENTRY glIsTexture(GLuint name) {
  GL_CONTEXT(GLboolean(GL_FALSE));
  GL_OUTSIDE_BEGIN(GLboolean(GL_FALSE));
  auto it = c.textures.find(name);
  return name != 0 && it != c.textures.end() && it->second ? GL_TRUE : GL_FALSE;
}
GLboolean GLAPIENTRY glAreTexturesResident(GLsizei n, const GLuint* names, GLboolean* residences) {
  GL_COMPAT_CONTEXT(GLboolean(GL_FALSE));
  GL_OUTSIDE_BEGIN(GLboolean(GL_FALSE));
  if (n < 0) {
    c.error(GL_INVALID_VALUE);
    return GL_FALSE;
  }
  for (GLsizei i = 0; i < n; ++i)
    if (names && (names[i] == 0 || !c.textures.count(names[i]))) {
      c.error(GL_INVALID_VALUE);
      return GL_FALSE;
    }
  (void)residences;  // all resident: GL leaves the array untouched when returning TRUE
  return GL_TRUE;
}
void GLAPIENTRY glPrioritizeTextures(GLsizei n, const GLuint* names, const GLclampf* priorities) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  for (GLsizei i = 0; i < n && names && priorities; ++i) {
    auto it = c.textures.find(names[i]);
    if (it != c.textures.end() && names[i] != 0 && it->second)
      it->second->priority = std::clamp(priorities[i], 0.0f, 1.0f);
  }
}

void GLAPIENTRY glTexImage1D(GLenum target, GLint level, GLint internal, GLsizei w, GLint border,
                             GLenum format, GLenum type, const GLvoid* pixels) {
  tex_image_entry(target, 1, level, internal, w, 1, 1, border, format, type, pixels);
}
void GLAPIENTRY glTexImage2D(GLenum target, GLint level, GLint internal, GLsizei w, GLsizei h, GLint border,
                             GLenum format, GLenum type, const GLvoid* pixels) {
  tex_image_entry(target, 2, level, internal, w, h, 1, border, format, type, pixels);
}
void GLAPIENTRY glTexImage3D(GLenum target, GLint level, GLint internal, GLsizei w, GLsizei h, GLsizei d,
                             GLint border, GLenum format, GLenum type, const GLvoid* pixels) {
  tex_image_entry(target, 3, level, internal, w, h, d, border, format, type, pixels);
}
void GLAPIENTRY glTexSubImage1D(GLenum target, GLint level, GLint x, GLsizei w, GLenum format, GLenum type,
                                const GLvoid* pixels) {
  tex_sub_image_entry(target, 1, level, x, 0, 0, w, 1, 1, format, type, pixels);
}
void GLAPIENTRY glTexSubImage2D(GLenum target, GLint level, GLint x, GLint y, GLsizei w, GLsizei h,
                                GLenum format, GLenum type, const GLvoid* pixels) {
  tex_sub_image_entry(target, 2, level, x, y, 0, w, h, 1, format, type, pixels);
}
void GLAPIENTRY glTexSubImage3D(GLenum target, GLint level, GLint x, GLint y, GLint z, GLsizei w, GLsizei h,
                                GLsizei d, GLenum format, GLenum type, const GLvoid* pixels) {
  tex_sub_image_entry(target, 3, level, x, y, z, w, h, d, format, type, pixels);
}

void GLAPIENTRY glCopyTexImage1D(GLenum target, GLint level, GLenum internal, GLint x, GLint y, GLsizei w,
                                 GLint border) {
  GL_CONTEXT();
  ImageTarget it;
  if (!image_target(target, 1, it) || it.proxy) return c.error(GL_INVALID_ENUM);
  GL_LISTED(copy_tex_image(c, it, level, GLint(internal), x, y, w, 1, border));
  copy_tex_image(c, it, level, GLint(internal), x, y, w, 1, border);
}
void GLAPIENTRY glCopyTexImage2D(GLenum target, GLint level, GLenum internal, GLint x, GLint y, GLsizei w,
                                 GLsizei h, GLint border) {
  GL_CONTEXT();
  ImageTarget it;
  if (!image_target(target, 2, it) || it.proxy) return c.error(GL_INVALID_ENUM);
  GL_LISTED(copy_tex_image(c, it, level, GLint(internal), x, y, w, h, border));
  copy_tex_image(c, it, level, GLint(internal), x, y, w, h, border);
}
void GLAPIENTRY glCopyTexSubImage1D(GLenum target, GLint level, GLint xo, GLint x, GLint y, GLsizei w) {
  GL_CONTEXT();
  ImageTarget it;
  if (!image_target(target, 1, it) || it.proxy) return c.error(GL_INVALID_ENUM);
  GL_LISTED(copy_tex_sub_image(c, it, level, xo, 0, 0, x, y, w, 1));
  copy_tex_sub_image(c, it, level, xo, 0, 0, x, y, w, 1);
}
void GLAPIENTRY glCopyTexSubImage2D(GLenum target, GLint level, GLint xo, GLint yo, GLint x, GLint y,
                                    GLsizei w, GLsizei h) {
  GL_CONTEXT();
  ImageTarget it;
  if (!image_target(target, 2, it) || it.proxy) return c.error(GL_INVALID_ENUM);
  GL_LISTED(copy_tex_sub_image(c, it, level, xo, yo, 0, x, y, w, h));
  copy_tex_sub_image(c, it, level, xo, yo, 0, x, y, w, h);
}
void GLAPIENTRY glCopyTexSubImage3D(GLenum target, GLint level, GLint xo, GLint yo, GLint zo, GLint x,
                                    GLint y, GLsizei w, GLsizei h) {
  GL_CONTEXT();
  ImageTarget it;
  if (!image_target(target, 3, it) || it.proxy) return c.error(GL_INVALID_ENUM);
  GL_LISTED(copy_tex_sub_image(c, it, level, xo, yo, zo, x, y, w, h));
  copy_tex_sub_image(c, it, level, xo, yo, zo, x, y, w, h);
}

// GL 3.3 §6.1.4: a level's texels in the format and type asked for; depth textures only as
// GL_DEPTH_COMPONENT (or GL_DEPTH_STENCIL), colour textures never as depth.
void GLAPIENTRY glGetTexImage(GLenum target, GLint level, GLenum format, GLenum type, GLvoid* pixels) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ImageTarget it;
  const bool ok = image_target(target, 1, it) || image_target(target, 2, it) || image_target(target, 3, it);
  if (!ok || it.proxy) return c.error(GL_INVALID_ENUM);
  const GLenum ft = check_format_type(format, type, c.core_profile);
  if (ft != GL_NO_ERROR) return c.error(ft);
  if (level < 0 || level >= kMaxTextureLevels) return c.error(GL_INVALID_VALUE);
  if (it.target == TexTarget::Rect && level != 0) return c.error(GL_INVALID_VALUE);  // §6.1.4
  TextureObject& t = c.bound_texture(it.target);
  const TextureImage& img = t.image(it.face, level);
  if (!img.defined()) return;
  if (format == GL_STENCIL_INDEX || format == GL_COLOR_INDEX) return c.error(GL_INVALID_OPERATION);
  const GLenum m = check_format_match(img.fmt, format, TexTarget::T2D);
  if (m != GL_NO_ERROR) return c.error(m);
  const bool three_d = it.target == TexTarget::T3D || it.target == TexTarget::T2DArray;
  const int rows = three_d ? img.height : img.height * img.depth, images = three_d ? img.depth : 1;
  const BlockLayout b = block_layout(c.c.pack, img.width, rows, images, three_d, format, type);
  GLenum err = GL_NO_ERROR;
  std::byte* dst = transfer_memory(c.pixel_pack_buffer, pixels, b.bytes, type, err);
  if (err != GL_NO_ERROR) return c.error(err);
  if (!dst) return;
  pull_rendered(c, t);
  const size_t bpp = tessel::gpu::format_info(img.fmt.storage).bytes;
  std::vector<glm::vec4> px(size_t(img.width) * size_t(rows));
  for (int k = 0; k < images; ++k) {
    const std::byte* src = img.data.data() + size_t(k) * px.size() * bpp;
    for (size_t i = 0; i < px.size(); ++i)
      px[i] = from_storage(img.fmt, tessel::gpu::detail::decode_texel(img.fmt.storage, src + i * bpp));
    if (img.fmt.integer()) match_integer_sign(px, img.fmt.kind == TexKind::Int, type);
    pack_pixels(c.c.pack, img.width, rows, format, type, px, dst + (b.first + size_t(k)) * b.image_stride);
  }
}

void GLAPIENTRY glCompressedTexImage1D(GLenum target, GLint level, GLenum internal, GLsizei w, GLint border,
                                       GLsizei size, const GLvoid* data) {
  compressed_image_entry(target, 1, level, internal, w, 1, 1, border, size, data);
}
void GLAPIENTRY glCompressedTexImage2D(GLenum target, GLint level, GLenum internal, GLsizei w, GLsizei h,
                                       GLint border, GLsizei size, const GLvoid* data) {
  compressed_image_entry(target, 2, level, internal, w, h, 1, border, size, data);
}
void GLAPIENTRY glCompressedTexImage3D(GLenum target, GLint level, GLenum internal, GLsizei w, GLsizei h,
                                       GLsizei d, GLint border, GLsizei size, const GLvoid* data) {
  compressed_image_entry(target, 3, level, internal, w, h, d, border, size, data);
}
void GLAPIENTRY glCompressedTexSubImage1D(GLenum target, GLint level, GLint x, GLsizei w, GLenum format,
                                          GLsizei size, const GLvoid* data) {
  compressed_sub_image_entry(target, 1, level, x, 0, 0, w, 1, 1, format, size, data);
}
void GLAPIENTRY glCompressedTexSubImage2D(GLenum target, GLint level, GLint x, GLint y, GLsizei w, GLsizei h,
                                          GLenum format, GLsizei size, const GLvoid* data) {
  compressed_sub_image_entry(target, 2, level, x, y, 0, w, h, 1, format, size, data);
}
void GLAPIENTRY glCompressedTexSubImage3D(GLenum target, GLint level, GLint x, GLint y, GLint z, GLsizei w,
                                          GLsizei h, GLsizei d, GLenum format, GLsizei size,
                                          const GLvoid* data) {
  compressed_sub_image_entry(target, 3, level, x, y, z, w, h, d, format, size, data);
}

// §6.1.4: the blocks of a compressed image, as glCompressedTexImage takes them.
void GLAPIENTRY glGetCompressedTexImage(GLenum target, GLint level, GLvoid* pixels) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ImageTarget it;
  const bool ok = image_target(target, 1, it) || image_target(target, 2, it) || image_target(target, 3, it);
  if (!ok || it.proxy) return c.error(GL_INVALID_ENUM);
  if (level < 0 || level >= kMaxTextureLevels) return c.error(GL_INVALID_VALUE);
  const TextureImage& img = c.bound_texture(it.target).image(it.face, level);
  if (!img.defined() || !img.fmt.rgtc()) return c.error(GL_INVALID_OPERATION);
  GLenum err = GL_NO_ERROR;
  std::byte* dst = transfer_memory(c.pixel_pack_buffer, pixels, img.blocks.size(), GL_UNSIGNED_BYTE, err);
  if (err != GL_NO_ERROR) return c.error(err);
  if (dst) std::memcpy(dst, img.blocks.data(), img.blocks.size());
}

// GL 3.3 §3.8.7: a buffer texture reads a buffer object's store as an array of texels.
void GLAPIENTRY glTexBuffer(GLenum target, GLenum internal, GLuint buffer) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (target != GL_TEXTURE_BUFFER) return c.error(GL_INVALID_ENUM);
  TexFormat fmt;
  tessel::gpu::BufferTexel texel;
  if (!tex_format_of(GLint(internal), true, fmt) || !buffer_texel_of(fmt, texel))
    return c.error(GL_INVALID_ENUM);
  BufferRef ref;
  if (buffer != 0) {
    auto it = c.buffers.find(buffer);
    if (it == c.buffers.end() || !it->second) return c.error(GL_INVALID_OPERATION);
    ref = it->second;
  }
  TextureObject& t = c.bound_texture(TexTarget::Buffer);
  c.touch();
  t.buffer = ref;
  t.buffer_format = fmt;
  t.buffer_texel = texel;
  t.dirty = true;
}

void GLAPIENTRY glTexImage2DMultisample(GLenum target, GLsizei samples, GLenum internal, GLsizei w, GLsizei h,
                                        GLboolean fixed) {
  GL_CONTEXT();
  tex_image_multisample(c, target, samples, internal, w, h, 1, fixed, false);
}
void GLAPIENTRY glTexImage3DMultisample(GLenum target, GLsizei samples, GLenum internal, GLsizei w, GLsizei h,
                                        GLsizei d, GLboolean fixed) {
  GL_CONTEXT();
  tex_image_multisample(c, target, samples, internal, w, h, d, fixed, true);
}

// GL 3.3 §3.8.10: the mipmap levels of the bound texture made from its base level.
void GLAPIENTRY glGenerateMipmap(GLenum target) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  TexTarget tt;
  if (!tex_target_of(target, tt) || tt == TexTarget::Rect || tt == TexTarget::Buffer || is_multisample(tt))
    return c.error(GL_INVALID_ENUM);
  TextureObject& t = c.bound_texture(tt);
  const int base = t.effective_base();
  if (!t.image(0, base).defined()) return c.error(GL_INVALID_OPERATION);
  // Integer and depth-stencil images have no mipmaps to filter (Mesa refuses them too).
  const TexFormat& bf = t.image(0, base).fmt;
  if (bf.integer() || bf.base == TexBase::DepthStencil) return c.error(GL_INVALID_OPERATION);
  if (tt == TexTarget::Cube)
    for (int f = 1; f < 6; ++f) {
      const TextureImage& a = t.image(0, base);
      const TextureImage& b = t.image(f, base);
      if (!b.defined() || b.width != a.width || b.fmt.internal != a.fmt.internal)
        return c.error(GL_INVALID_OPERATION);  // not cube complete
    }
  c.touch();
  generate_mipmaps(c, t);
}

}  // extern "C"
