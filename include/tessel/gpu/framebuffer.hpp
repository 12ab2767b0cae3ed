// Framebuffers: up to eight colour attachments and one depth (or depth-stencil) attachment,
// each a level of a Texture2D (or of a cube face). Fragment output i goes to attachment i.
#pragma once

#include <array>
#include <string>

#include "tessel/gpu/state.hpp"
#include "tessel/gpu/texture.hpp"

namespace tessel::gpu {

struct Attachment {
  Texture2D* texture = nullptr;
  int level = 0;
  explicit operator bool() const { return texture != nullptr; }
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
  bool has_stencil() const { return depth.texture && depth.texture->format() == Format::Depth24Stencil8; }
};

}  // namespace tessel::gpu
