// Texture and sampler objects (GL 3.3 compatibility §3.8): the images each level holds, the
// sampling parameters, and the gpu texture made from them.
//
// The images are the texture's contents as GL defines them: any level may have any size and
// format, and a texture is complete or not at the moment it is used. When a draw samples it or
// renders to it, the consistent chain of levels from the base level is made into one gpu
// texture (Texture2D, TextureCube, Texture3D, Texture2DArray or TextureBuffer), updated in
// place when its shape is unchanged. A framebuffer renders into that gpu texture; the texture
// is then `rendered`, and before the images are read or changed (glTexSubImage, glGetTexImage,
// glGenerateMipmap, ...) pull_rendered() copies the gpu levels back.
#pragma once

#include <GL/gl.h>

#include <array>
#include <memory>
#include <vector>

#include <glm/vec4.hpp>

#include "objects.hpp"
#include "tessel/gpu/texture.hpp"
#include "texture_format.hpp"

namespace tessel::gl {

inline constexpr int kMaxTextureSize = 8192;
inline constexpr int kMaxTextureLevels = 14;  // 8192 = 2^13
inline constexpr int kMax3DTextureSize = 2048, kMaxArrayTextureLayers = 2048;

// The binding targets of glBindTexture, in the order of the per-unit binding table.
// The multisample targets (GL 3.2) keep one sample of each texel: their images are level 0
// of a 2D or 2D array texture, drawn into and read (texelFetch) as that.
enum class TexTarget : uint8_t { T1D, T2D, T3D, Cube, T1DArray, T2DArray, Rect, Buffer, T2DMS, T2DMSArray };
inline constexpr int kTexTargetCount = 10;
inline bool is_multisample(TexTarget t) { return t == TexTarget::T2DMS || t == TexTarget::T2DMSArray; }
GLenum gl_target_of(TexTarget t);
// A glBindTexture target; false for anything else.
bool tex_target_of(GLenum target, TexTarget& out);
// The GL_TEXTURE_BINDING_* query of a target.
GLenum binding_query_of(TexTarget t);

// The sampling state a texture object holds and a sampler object overrides (Table 6.23).
struct SamplerParams {
  GLenum min_filter = GL_NEAREST_MIPMAP_LINEAR, mag_filter = GL_LINEAR;
  GLenum wrap_s = GL_REPEAT, wrap_t = GL_REPEAT, wrap_r = GL_REPEAT;
  glm::vec4 border{0.0f};
  float min_lod = -1000.0f, max_lod = 1000.0f, lod_bias = 0.0f;
  GLenum compare_mode = GL_NONE, compare_func = GL_LEQUAL;
};

struct SamplerObject {
  GLuint name = 0;
  SamplerParams p;
};
using SamplerRef = std::shared_ptr<SamplerObject>;

// One level of one face: width x height texels, `depth` slices (3D) or layers (2D arrays;
// a 1D array has its layers as rows, height = layer count), stored in fmt.storage rows
// bottom-up, slices in order, tightly packed.
struct TextureImage {
  int width = 0, height = 0, depth = 0;
  TexFormat fmt;
  std::vector<std::byte> data;
  // A compressed format's blocks (compressed.hpp), of which `data` holds the decoded texels.
  std::vector<uint8_t> blocks;
  bool defined() const { return width > 0; }
};

struct TextureObject {
  GLuint name = 0;
  TexTarget target = TexTarget::T2D;
  std::array<std::array<TextureImage, kMaxTextureLevels>, 6> images{};  // [face][level]
  SamplerParams sampler;
  int base_level = 0, max_level = 1000;
  std::array<GLenum, 4> swizzle{GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA};
  GLenum depth_mode = GL_LUMINANCE;  // GL_DEPTH_TEXTURE_MODE (compatibility contexts)
  float priority = 1.0f;
  bool generate_mipmap = false;
  // GL_TEXTURE_BUFFER (glTexBuffer): the buffer, the texel format it is read as, and that
  // format's layout in the buffer's bytes.
  BufferRef buffer;
  TexFormat buffer_format;
  gpu::BufferTexel buffer_texel;

  // glTexImage2D/3DMultisample: the samples GL reports (the storage keeps one) and
  // GL_TEXTURE_FIXED_SAMPLE_LOCATIONS.
  int samples = 0;
  bool fixed_sample_locations = true;

  // The gpu texture (one of them, by target) and how many levels from base_level it has.
  std::unique_ptr<gpu::Texture2D> tex2d;  // 1D, 2D, rectangle, 2D multisample
  std::unique_ptr<gpu::TextureCube> cube;
  std::unique_ptr<gpu::Texture3D> tex3d;
  std::unique_ptr<gpu::Texture2DArray> array;  // 1D and 2D arrays, 2D multisample arrays
  std::unique_ptr<gpu::TextureBuffer> tbuf;
  int gpu_base = 0, gpu_levels = 0;
  bool dirty = true;      // the images changed since the gpu texture was made
  bool rendered = false;  // a framebuffer may have written the gpu texture since

  TextureImage& image(int face, int level) { return images[size_t(face)][size_t(level)]; }
  const TextureImage& image(int face, int level) const { return images[size_t(face)][size_t(level)]; }
  int faces() const { return target == TexTarget::Cube ? 6 : 1; }
  int effective_base() const;
  const TextureImage& base_image() const { return image(0, effective_base()); }
};
using TextureRef = std::shared_ptr<TextureObject>;

class Context;

// A new texture object of a target, with that target's initial state (rectangle textures
// filter linearly and clamp to the edge, GL 3.3 §3.8.5).
TextureRef make_texture(GLuint name, TexTarget target);

// Makes the gpu texture from the images when they changed (the chain from the base level).
// Returns false when there is none (no base image, or sizes beyond the gpu's limits).
bool update_gpu_texture(Context& c, TextureObject& t);
// Whether the texture can be sampled with these parameters (§3.8.14 completeness).
bool texture_complete(const TextureObject& t, const SamplerParams& p);
// Copies what a framebuffer rendered back into the images (before they are read or changed).
void pull_rendered(Context& c, TextureObject& t);
// The gpu sampler state of the parameters for this texture.
gpu::SamplerState sampler_state_of(const SamplerParams& p, const TextureObject& t);
// The texture's swizzle with the compatibility depth texture mode folded in, as the glsl
// layer takes it (0-3 = R, G, B, A; 4 = zero; 5 = one).
std::array<uint8_t, 4> swizzle_of(const TextureObject& t, bool core);
// Levels base + 1 .. from the base level (glGenerateMipmap, GL_GENERATE_MIPMAP).
void generate_mipmaps(Context& c, TextureObject& t);

}  // namespace tessel::gl
