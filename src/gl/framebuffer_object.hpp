// Framebuffer and renderbuffer objects (GL 3.3 compatibility §4.4): what is attached where,
// and the completeness rules of §4.4.4.
#pragma once

#include <GL/gl.h>

#include <array>
#include <memory>

#include "tessel/gpu/state.hpp"
#include "tessel/gpu/texture.hpp"
#include "texture_object.hpp"

namespace tessel::gl {

inline constexpr int kMaxColorAttachments = gpu::kMaxColorAttachments;
inline constexpr int kMaxDrawBuffers = gpu::kMaxColorAttachments;
inline constexpr int kMaxRenderbufferSize = kMaxTextureSize;
inline constexpr int kMaxSamples = 4;  // GL_MAX_SAMPLES, as llvmpipe reports it

struct RenderbufferObject {
  GLuint name = 0;
  TexFormat fmt;  // GL_RGBA4 (the initial internal format) until storage is given
  int width = 0, height = 0, samples = 0;
  std::unique_ptr<gpu::Texture2D> image;  // null until glRenderbufferStorage
  RenderbufferObject() { tex_format_of(GL_RGBA4, false, fmt); }
};
using RenderbufferRef = std::shared_ptr<RenderbufferObject>;

// One attachment point: a texture level (a face of a cube, a layer of a 3D or array texture)
// or a renderbuffer, or nothing.
struct Attachment {
  GLenum type = GL_NONE;  // GL_NONE, GL_TEXTURE or GL_RENDERBUFFER
  TextureRef texture;
  RenderbufferRef renderbuffer;
  int level = 0, face = 0, layer = 0;
  bool layered = false;  // glFramebufferTexture of a 3D, array or cube texture
  explicit operator bool() const { return type != GL_NONE; }
  // The format and size of the attached image; false when there is no image.
  bool image(TexFormat& fmt, int& width, int& height) const;
};

struct FramebufferObject {
  GLuint name = 0;
  std::array<Attachment, kMaxColorAttachments> color{};
  Attachment depth, stencil;
  // glDrawBuffers: fragment output i goes to draw_buffers[i] (GL_COLOR_ATTACHMENTn or GL_NONE).
  std::array<GLenum, kMaxDrawBuffers> draw_buffers{GL_COLOR_ATTACHMENT0};
  GLenum read_buffer = GL_COLOR_ATTACHMENT0;
  Attachment* point(GLenum attachment);  // null for a name that is not an attachment point
  // GL_FRAMEBUFFER_COMPLETE or the status glCheckFramebufferStatus gives (§4.4.4.2).
  GLenum status() const;
  // GL_SAMPLES of the framebuffer: its renderbuffers' sample count (0: single-sampled).
  int samples() const;
};
using FramebufferRef = std::shared_ptr<FramebufferObject>;

}  // namespace tessel::gl
