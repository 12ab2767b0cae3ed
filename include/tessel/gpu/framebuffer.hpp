// Framebuffers: up to eight colour attachments and one depth (or depth-stencil) attachment,
// each a level of a Texture2D (or of a cube face), or one layer of a level of a Texture3D or
// Texture2DArray. Fragment output i goes to attachment i.
#pragma once

#include <array>
#include <string>

#include "tessel/gpu/state.hpp"
#include "tessel/gpu/texture.hpp"

namespace tessel::gpu {

struct Attachment {
  Texture2D* texture = nullptr;
  int level = 0;
  // Or a layer of a 3D or array texture (texture null, one of these set).
  Texture3D* texture_3d = nullptr;
  Texture2DArray* texture_array = nullptr;
  int layer = 0;
  explicit operator bool() const { return texture || texture_3d || texture_array; }
  // Of the attached texture (which must be there):
  Format format() const;
  int levels() const;
  int layers() const;  // 1 for a Texture2D
  int width() const;   // of the attached level
  int height() const;
  // The attached image's texels (the layer's, bottom row first) and its row size; null when
  // the level or layer does not exist.
  std::byte* data() const;
  size_t row_bytes() const;
  // One texel of the attached image as floats, and a store of one (as the textures' own).
  glm::vec4 fetch(int x, int y) const;
  void store(int x, int y, const glm::vec4& value) const;
  bool operator==(const Attachment&) const = default;
};

class Framebuffer {
 public:
  std::array<Attachment, kMaxColorAttachments> color{};
  Attachment depth;  // Depth24, Depth32F or Depth24Stencil8 (which also gives the stencil)

  Framebuffer() = default;
  // The common case: one colour texture and an optional depth texture.
  Framebuffer(Texture2D* color0, Texture2D* depth_tex = nullptr) {
    color[0].texture = color0;
    depth.texture = depth_tex;
  }

  // Empty when complete, else why not (GL 4.6 §9.4.2, simplified: every attachment has a
  // level that exists, colour slots hold colour formats and the depth slot a depth format,
  // and there is at least one attachment).
  std::string incomplete_reason() const;
  bool complete() const { return incomplete_reason().empty(); }
  // The drawable size: the smallest width and height over the attachments.
  int width() const;
  int height() const;
  bool has_stencil() const { return depth && depth.format() == Format::Depth24Stencil8; }
};

}  // namespace tessel::gpu
