// Textures, samplers and the GLSL texture functions.
//
// A Texture2D owns its mip levels, each stored row by row from the bottom row up (GL's
// origin: the first row of uploaded data is t = 0). A level of a texture is also what a
// framebuffer renders into. Cube maps are six square faces with their own levels.
//
// Sampling follows GL 4.6 §8.14 (LOD), §8.14.2 (filters), §8.14.2 wrap modes, §8.13 (cube
// face selection) and §8.23 (depth comparison): implicit LOD comes from the derivatives of a
// 2x2 quad (one LOD per quad, as llvmpipe computes it), true trilinear between levels.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tessel/gpu/buffer.hpp"
#include "tessel/gpu/format.hpp"
#include "tessel/gpu/resource.hpp"
#include "tessel/gpu/vec.hpp"

namespace tessel::gpu {

inline constexpr int kMaxTextureSize = 16384;

enum class Filter : uint8_t {
  Nearest,
  Linear,
  NearestMipmapNearest,
  LinearMipmapNearest,
  NearestMipmapLinear,
  LinearMipmapLinear,
};
// Clamp is GL 1.x's GL_CLAMP: coordinates clamped to [0, 1], then edge texels for nearest
// and the border colour beyond the edge for linear filtering.
enum class Wrap : uint8_t { Repeat, ClampToEdge, MirroredRepeat, ClampToBorder, Clamp };
enum class CompareFunc : uint8_t { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };

// Whether `a <func> b` passes: the depth test, the stencil test and shadow comparisons. For
// scalars the result is a bool; for lane types (Float8, Int8) a mask per lane.
template <class T, class R = decltype(T() < T())>
__attribute__((always_inline)) constexpr R compare(CompareFunc f, T a, T b) {
  switch (f) {
    case CompareFunc::Never: return R(false);
    case CompareFunc::Less: return a < b;
    case CompareFunc::Equal: return a == b;
    case CompareFunc::LessEqual: return a <= b;
    case CompareFunc::Greater: return a > b;
    case CompareFunc::NotEqual: return a != b;
    case CompareFunc::GreaterEqual: return a >= b;
    case CompareFunc::Always: return R(true);
  }
  return R(false);
}

struct SamplerState {
  Filter min_filter = Filter::NearestMipmapLinear;  // GL's default
  Filter mag_filter = Filter::Linear;
  Wrap wrap_s = Wrap::Repeat, wrap_t = Wrap::Repeat, wrap_r = Wrap::Repeat;
  glm::vec4 border_color{0.0f};
  float lod_bias = 0.0f;
  float min_lod = -1000.0f, max_lod = 1000.0f;
  // Depth comparison (shadow maps): when on, a depth texture returns the fraction of the
  // filtered texels that pass `ref <compare_func> texel` (GL_COMPARE_REF_TO_TEXTURE).
  bool compare = false;
  CompareFunc compare_func = CompareFunc::LessEqual;
  // Cube maps (GL_TEXTURE_CUBE_MAP_SEAMLESS, GL 3.3 §3.8.8): a linear lookup next to a face's
  // edge reads the texels beyond it from the neighbouring face, and at a corner the average of
  // the three texels that meet there; otherwise each face clamps to its own edge.
  bool seamless = false;
};

// One mip level: width x height texels of the texture's format, rows bottom-up, tightly packed.
struct Level {
  int width = 0, height = 0;
  std::vector<std::byte> data;
  size_t row_bytes() const;
};

class Texture2D : public Resource {
 public:
  // levels = 0 means the full chain down to 1x1. Throws Error for a size outside
  // [1, kMaxTextureSize] or too many levels.
  Texture2D(Format format, int width, int height, int levels = 1);
  Texture2D(Texture2D&&) = default;
  // Queued draws that use this texture run before its memory goes.
  ~Texture2D() override { flush_before_destruction(); }

  Format format() const { return format_; }
  int width(int level = 0) const { return levels_.at(level).width; }
  int height(int level = 0) const { return levels_.at(level).height; }
  int levels() const { return int(levels_.size()); }
  const Level& level(int i) const { return levels_.at(i); }
  Level& level_for_write(int i);  // flushes pending draws that use this texture

  // Copies a whole level from tightly packed data in the texture's own format, rows bottom-up.
  void upload(int level, const void* data, size_t bytes);
  // Copies a whole level from RGBA8 data (rows bottom-up), converting to the texture's format.
  void upload_rgba8(int level, const uint8_t* rgba, size_t bytes);
  // Copies a whole level from float RGBA data, converting to the texture's format.
  void upload_rgba32f(int level, const float* rgba, size_t bytes);
  // Fills levels 1.. from level 0 by 2x2 box filtering (odd sizes: the last row/column is
  // averaged with weights so that no texel is dropped). Depth formats are averaged as floats.
  void generate_mipmaps();
  // Adds levels so that the chain reaches 1x1, then generate_mipmaps().
  void allocate_full_chain();

  // One texel as floats: colour formats give RGBA (missing channels 0, alpha 1), depth
  // formats give (depth, 0, 0, 1), stencil in .y for DEPTH24_STENCIL8.
  glm::vec4 fetch(int level, int x, int y) const;
  void store(int level, int x, int y, const glm::vec4& value);

 private:
  Format format_;
  std::vector<Level> levels_;
};

class TextureCube : public Resource {
 public:
  // Faces in GL order: +X, -X, +Y, -Y, +Z, -Z.
  TextureCube(Format format, int size, int levels = 1);
  Texture2D& face(int i) { return *faces_.at(i); }
  const Texture2D& face(int i) const { return *faces_.at(i); }
  Format format() const { return faces_[0]->format(); }
  int size() const { return faces_[0]->width(); }
  int levels() const { return faces_[0]->levels(); }
  void generate_mipmaps();

 private:
  std::array<std::unique_ptr<Texture2D>, 6> faces_;
};

// --- 3D, array and buffer textures ------------------------------------------------------
// The limits llvmpipe reports (GL_MAX_3D_TEXTURE_SIZE, GL_MAX_ARRAY_TEXTURE_LAYERS,
// GL_MAX_TEXTURE_BUFFER_SIZE), and a bound on the bytes of one texture's levels so that a
// huge request is an Error instead of an exhausted machine.
inline constexpr int kMax3DTextureSize = 2048;
inline constexpr int kMaxArrayTextureLayers = 2048;
inline constexpr size_t kMaxTextureBufferTexels = size_t(1) << 27;
inline constexpr size_t kMaxTextureBytes = size_t(1) << 32;

// One mip level of a 3D or array texture: `depth` slices (or layers) of width x height
// texels, each stored as a 2D Level is (rows bottom-up), slice 0 first, tightly packed.
struct Level3D {
  int width = 0, height = 0, depth = 0;
  std::vector<std::byte> data;
  size_t slice_bytes() const { return depth > 0 ? data.size() / size_t(depth) : 0; }
};

// A 3D texture (GL_TEXTURE_3D): levels halve all three sizes down to 1x1x1 (GL 4.6 §8.14.3).
// Colour formats only (GL has no 3D depth textures).
class Texture3D : public Resource {
 public:
  // levels = 0: the full chain. Throws Error for a size outside [1, kMax3DTextureSize], a
  // depth format, too many levels or more than kMaxTextureBytes in all.
  Texture3D(Format format, int width, int height, int depth, int levels = 1);
  Texture3D(Texture3D&&) = default;
  ~Texture3D() override { flush_before_destruction(); }

  Format format() const { return format_; }
  int width(int level = 0) const { return levels_.at(size_t(level)).width; }
  int height(int level = 0) const { return levels_.at(size_t(level)).height; }
  int depth(int level = 0) const { return levels_.at(size_t(level)).depth; }
  int levels() const { return int(levels_.size()); }
  const Level3D& level(int i) const { return levels_.at(size_t(i)); }

  // A whole level from tightly packed texels of the texture's format (glTexImage3D's order:
  // rows bottom-up, slices front to back); or from RGBA floats, converted.
  void upload(int level, const void* data, size_t bytes);
  void upload_rgba32f(int level, const float* rgba, size_t bytes);
  // Levels 1.. from level 0 by 2x2x2 box filtering (odd sizes weighted as Texture2D does).
  void generate_mipmaps();
  // One texel as floats (as Texture2D::fetch); Error outside the level.
  glm::vec4 fetch(int level, int x, int y, int z) const;
  void store(int level, int x, int y, int z, const glm::vec4& value);

 private:
  Format format_;
  std::vector<Level3D> levels_;
};

// A 2D array texture (GL_TEXTURE_2D_ARRAY), and a 1D array texture (GL_TEXTURE_1D_ARRAY) as
// one of height 1: `layers` images of one size; levels halve width and height, never the
// layer count. Depth formats are allowed (sampler2DArrayShadow, sampler1DArrayShadow).
class Texture2DArray : public Resource {
 public:
  // levels = 0: the full chain. Throws Error for a size outside [1, kMaxTextureSize], layers
  // outside [1, kMaxArrayTextureLayers], too many levels or more than kMaxTextureBytes.
  Texture2DArray(Format format, int width, int height, int layers, int levels = 1);
  Texture2DArray(Texture2DArray&&) = default;
  ~Texture2DArray() override { flush_before_destruction(); }

  Format format() const { return format_; }
  int width(int level = 0) const { return levels_.at(size_t(level)).width; }
  int height(int level = 0) const { return levels_.at(size_t(level)).height; }
  int layers() const { return levels_[0].depth; }
  int levels() const { return int(levels_.size()); }
  const Level3D& level(int i) const { return levels_.at(size_t(i)); }

  // A whole level, every layer (layer 0 first, as glTexImage3D takes them), or one layer.
  void upload(int level, const void* data, size_t bytes);
  void upload_rgba32f(int level, const float* rgba, size_t bytes);
  void upload_layer(int level, int layer, const void* data, size_t bytes);
  // Levels 1.. of every layer from level 0 (each layer as Texture2D::generate_mipmaps).
  void generate_mipmaps();
  glm::vec4 fetch(int level, int x, int y, int layer) const;
  void store(int level, int x, int y, int layer, const glm::vec4& value);

 private:
  Format format_;
  std::vector<Level3D> levels_;
};

// The texel layouts a buffer texture reads (GL 3.3 §3.8.7, Table 3.15): 1, 2 or 4
// components of one type, tightly packed. Integer components come back as their 32 bits
// (an int32 or a uint32) in the float slots, as integer textures keep them; components the
// layout lacks read 0, and alpha 1 (an integer 1 for integer layouts).
enum class BufferComponent : uint8_t {
  Unorm8,
  Unorm16,
  Float16,
  Float32,
  Int8,
  Int16,
  Int32,
  Uint8,
  Uint16,
  Uint32
};
struct BufferTexel {
  BufferComponent component = BufferComponent::Unorm8;
  uint8_t channels = 4;  // 1, 2 or 4
  int component_bytes() const;
  int bytes() const { return component_bytes() * channels; }
  bool integer() const { return component >= BufferComponent::Int8; }
  std::string name() const;  // as GL names the format: "RGBA8", "R16F", "RG32UI"
};
// The layout of a colour format (RGBA8, R8, RG8, RGBA16F, RGBA32F); throws Error for depth.
BufferTexel buffer_texel(Format format);

// A buffer texture (GL_TEXTURE_BUFFER, glTexBuffer / glTexBufferRange): texels of one layout
// read straight from a Buffer, which must outlive the view. Not filtered, no levels: shaders
// read it with texelFetch (samplerBuffer). With size kWholeBuffer the view follows the
// buffer's size as it changes; a range is read only as far as the buffer still reaches.
class TextureBuffer {
 public:
  static constexpr size_t kWholeBuffer = ~size_t(0);
  // Throws Error for a depth format or a layout of other than 1, 2 or 4 channels, an offset
  // not a multiple of the texel size, a range past the buffer's end, or more than
  // kMaxTextureBufferTexels texels.
  TextureBuffer(BufferTexel texel, const Buffer& buffer, size_t offset = 0, size_t size = kWholeBuffer);
  TextureBuffer(Format format, const Buffer& buffer, size_t offset = 0, size_t size = kWholeBuffer)
      : TextureBuffer(buffer_texel(format), buffer, offset, size) {}
  const BufferTexel& texel() const { return texel_; }
  const Buffer& buffer() const { return *buffer_; }
  size_t offset() const { return offset_; }
  // The texels readable now (textureSize): whole texels of the range that the buffer holds,
  // at most kMaxTextureBufferTexels.
  int size() const;
  // Texel i as floats (as Texture2D::fetch); (0, 0, 0, 0) outside [0, size()), as GL's
  // robust buffer access and llvmpipe give.
  glm::vec4 fetch(int i) const;

 private:
  BufferTexel texel_;
  const Buffer* buffer_;
  size_t offset_, size_;
};

// What a shader's uniforms hold to sample a texture.
struct Sampler2D {
  const Texture2D* texture = nullptr;
  SamplerState state;
};
struct SamplerCube {
  const TextureCube* texture = nullptr;
  SamplerState state;
};
// A depth texture with comparison on (sampler2DShadow).
struct Sampler2DShadow {
  const Texture2D* texture = nullptr;
  SamplerState state{.min_filter = Filter::Linear,
                     .mag_filter = Filter::Linear,
                     .wrap_s = Wrap::ClampToEdge,
                     .wrap_t = Wrap::ClampToEdge,
                     .wrap_r = Wrap::ClampToEdge,
                     .border_color = glm::vec4(1.0f),
                     .compare = true};
};

struct Sampler3D {
  const Texture3D* texture = nullptr;
  SamplerState state;
};
// 2D and 1D arrays; with state.compare a depth array compares (sampler2DArrayShadow).
struct Sampler2DArray {
  const Texture2DArray* texture = nullptr;
  SamplerState state;
};

// --- the sampling functions (texture.cpp has the scalar core; these apply it per lane) ----
namespace detail {
// One texel of format f at p as floats (as Texture2D::fetch), and back (as Texture2D::store,
// unorm values rounded to nearest after clamping). Used by the attachments' writes too.
glm::vec4 decode_texel(Format f, const std::byte* p);
void encode_texel(Format f, std::byte* p, const glm::vec4& c);
// Samples at an explicit level of detail. A missing texture samples as (0,0,0,1). `offset`
// is textureOffset's, in texels of each level sampled.
glm::vec4 sample_2d(const Sampler2D& s, float u, float v, float lod, glm::ivec2 offset = {});
glm::vec4 sample_cube(const SamplerCube& s, float x, float y, float z, float lod);
float sample_2d_compare(const Sampler2DShadow& s, float u, float v, float ref, float lod,
                        glm::ivec2 offset = {});
// LOD from the derivatives of the texture coordinates (GL 4.6 §8.14.1, equations 8.5-8.7).
float lod_from_derivatives(float dudx, float dvdx, float dudy, float dvdy, int width, int height);
glm::vec4 texel_fetch(const Texture2D* t, int x, int y, int level);

// 3D, array and cube-compare lookups at an explicit LOD; `offset` is a constant texel offset
// (textureOffset), added in the selected level's texel space. A missing texture samples as
// (0,0,0,1), a missing shadow texture as 0.
glm::vec4 sample_3d(const Sampler3D& s, float u, float v, float w, float lod, glm::ivec3 offset = {});
// The layer is round(layer) clamped to [0, layers - 1] (array_layer).
glm::vec4 sample_2d_array(const Sampler2DArray& s, float u, float v, float layer, float lod,
                          glm::ivec2 offset = {});
// state.compare on: the filtered fraction of texels that pass the comparison with ref.
float sample_2d_array_compare(const Sampler2DArray& s, float u, float v, float layer, float ref, float lod,
                              glm::ivec2 offset = {});
// samplerCubeShadow: the face is selected first, then its texels are compared and filtered.
float sample_cube_compare(const SamplerCube& s, float x, float y, float z, float ref, float lod);
// The array layer of a coordinate: round to nearest (ties to even, as llvmpipe rounds), then
// clamped to [0, layers - 1] (GL 4.6 §8.14.2).
int array_layer(float layer, int layers);
// The LOD from the derivatives of three coordinates (GL 4.6 eq. 8.7 with the 3D rho).
float lod_from_derivatives_3d(const glm::vec3& ddx, const glm::vec3& ddy, const glm::ivec3& size);
// The LOD of a cube lookup in a 2x2 quad from its origin lane and its x and y neighbours,
// all projected on the origin's face (as texture(SamplerCube) takes it).
float cube_quad_lod(const glm::vec3& origin, const glm::vec3& right, const glm::vec3& up, int size);
// The LOD of textureGrad on a cube: the direction's derivatives carried onto its face by the
// quotient rule (s = sc / |ma| / 2 + 1/2, so ds = (dsc - sc dma / ma) / ma / 2, and t alike),
// then eq. 8.7 as for a 2D texture of the face's size, as llvmpipe derives explicit gradients.
float cube_grad_lod(const glm::vec3& dir, const glm::vec3& ddx, const glm::vec3& ddy, int size);
// texelFetch: (0, 0, 0, 0) outside the level (and for a missing level), (0,0,0,1) without a texture.
glm::vec4 texel_fetch(const Texture3D* t, int x, int y, int z, int level);
glm::vec4 texel_fetch(const Texture2DArray* t, int x, int y, int layer, int level);
glm::vec4 texel_fetch(const TextureBuffer* t, int i);
}  // namespace detail

// Implicit-LOD sampling. On eight lanes the LOD is taken per 2x2 quad from its derivatives;
// on one lane there are no neighbours, and the base level (plus the bias) is used.
Vec4<float> texture(const Sampler2D& s, const Vec2<float>& uv);
Vec4<Float8> texture(const Sampler2D& s, const Vec2<Float8>& uv);
Vec4<float> textureLod(const Sampler2D& s, const Vec2<float>& uv, float lod);
Vec4<Float8> textureLod(const Sampler2D& s, const Vec2<Float8>& uv, Float8 lod);
Vec4<float> textureGrad(const Sampler2D& s, const Vec2<float>& uv, const Vec2<float>& dx,
                        const Vec2<float>& dy);
Vec4<Float8> textureGrad(const Sampler2D& s, const Vec2<Float8>& uv, const Vec2<Float8>& dx,
                         const Vec2<Float8>& dy);
// textureProj: uv divided by the last component.
template <class F>
Vec4<F> textureProj(const Sampler2D& s, const Vec3<F>& uvq) {
  return texture(s, Vec2<F>(uvq.x / uvq.z, uvq.y / uvq.z));
}
template <class F>
Vec4<F> textureProj(const Sampler2D& s, const Vec4<F>& uvzq) {
  return texture(s, Vec2<F>(uvzq.x / uvzq.w, uvzq.y / uvzq.w));
}
Vec4<float> texture(const SamplerCube& s, const Vec3<float>& dir);
Vec4<Float8> texture(const SamplerCube& s, const Vec3<Float8>& dir);
// Shadow lookup: (u, v, reference depth) -> fraction lit in [0, 1]; with LINEAR filtering the
// four texels' comparisons are bilinearly weighted (hardware PCF).
float texture(const Sampler2DShadow& s, const Vec3<float>& uvr);
Float8 texture(const Sampler2DShadow& s, const Vec3<Float8>& uvr);
template <class F>
F textureProj(const Sampler2DShadow& s, const Vec4<F>& p) {
  return texture(s, Vec3<F>(p.x / p.w, p.y / p.w, p.z / p.w));
}
Vec4<float> texelFetch(const Sampler2D& s, int x, int y, int level);
Vec4<Float8> texelFetch(const Sampler2D& s, Int8 x, Int8 y, int level);
glm::ivec2 textureSize(const Sampler2D& s, int level);

// The GLSL functions of 3D and array textures, one lane (no neighbours: implicit LOD is the
// base level plus bias). The glsl layer's programs sample them lane by lane with these cores.
Vec4<float> texture(const Sampler3D& s, const Vec3<float>& uvw);
Vec4<float> textureLod(const Sampler3D& s, const Vec3<float>& uvw, float lod);
Vec4<float> texelFetch(const Sampler3D& s, int x, int y, int z, int level);
glm::ivec3 textureSize(const Sampler3D& s, int level);
// (u, v, layer); a 1D array texture is a height-1 one read at v = 0.5.
Vec4<float> texture(const Sampler2DArray& s, const Vec3<float>& uvl);
Vec4<float> textureLod(const Sampler2DArray& s, const Vec3<float>& uvl, float lod);
Vec4<float> texelFetch(const Sampler2DArray& s, int x, int y, int layer, int level);
glm::ivec3 textureSize(const Sampler2DArray& s, int level);  // (width, height, layers)

// Sixteen lanes (two 4x2 groups side by side) sample as their two halves of eight; trilinear
// RGBA8 has a path of its own for sixteen lanes (detail/texture_simd.hpp), with the same result.
namespace detail {
inline bool trilinear16(const Texture2D& tex, const SamplerState& st, const Vec2<Float16>& uv,
                        Vec4<Float16>& out);
}
__attribute__((always_inline)) inline Vec4<Float16> texture(const Sampler2D& s, const Vec2<Float16>& uv) {
#if defined(__AVX2__)
  Vec4<Float16> r;
  if (s.texture != nullptr && detail::trilinear16(*s.texture, s.state, uv, r)) return r;
#endif
  return join(texture(s, lo_half(uv)), texture(s, hi_half(uv)));
}
inline Vec4<Float16> textureLod(const Sampler2D& s, const Vec2<Float16>& uv, Float16 lod) {
  return join(textureLod(s, lo_half(uv), lo_half(lod)), textureLod(s, hi_half(uv), hi_half(lod)));
}
inline Vec4<Float16> textureGrad(const Sampler2D& s, const Vec2<Float16>& uv, const Vec2<Float16>& dx,
                                 const Vec2<Float16>& dy) {
  return join(textureGrad(s, lo_half(uv), lo_half(dx), lo_half(dy)),
              textureGrad(s, hi_half(uv), hi_half(dx), hi_half(dy)));
}
inline Vec4<Float16> texture(const SamplerCube& s, const Vec3<Float16>& dir) {
  return join(texture(s, lo_half(dir)), texture(s, hi_half(dir)));
}
inline Float16 texture(const Sampler2DShadow& s, const Vec3<Float16>& uvr) {
  return join(texture(s, lo_half(uvr)), texture(s, hi_half(uvr)));
}
inline Vec4<Float16> texelFetch(const Sampler2D& s, Int16 x, Int16 y, int level) {
  return join(texelFetch(s, lo_half(x), lo_half(y), level), texelFetch(s, hi_half(x), hi_half(y), level));
}

}  // namespace tessel::gpu

#include "tessel/gpu/detail/texture_simd.hpp"
