// Framebuffer completeness (GL 3.3 compatibility §4.4.4).
#define GL_GLEXT_PROTOTYPES 1
#include "framebuffer_object.hpp"

#include <GL/glext.h>

#include <algorithm>

namespace tessel::gl {

bool Attachment::image(TexFormat& fmt, int& width, int& height) const {
  if (type == GL_RENDERBUFFER) {
    if (!renderbuffer || !renderbuffer->image) return false;
    fmt = renderbuffer->fmt;
    width = renderbuffer->width;
    height = renderbuffer->height;
    return true;
  }
  if (type != GL_TEXTURE || !texture || level < 0 || level >= kMaxTextureLevels) return false;
  const TextureImage& img = texture->image(texture->target == TexTarget::Cube ? face : 0, level);
  if (!img.defined()) return false;
  // A layer of a 3D or array texture must exist (§4.4.4.1).
  const bool has_layers = texture->target == TexTarget::T3D || texture->target == TexTarget::T2DArray ||
                          texture->target == TexTarget::T2DMSArray || texture->target == TexTarget::T1DArray;
  if (has_layers && !layered) {
    const int layers = texture->target == TexTarget::T1DArray ? img.height : img.depth;
    if (layer < 0 || layer >= layers) return false;
  }
  fmt = img.fmt;
  width = img.width;
  height = texture->target == TexTarget::T1DArray ? 1 : img.height;
  return true;
}

Attachment* FramebufferObject::point(GLenum attachment) {
  if (attachment >= GL_COLOR_ATTACHMENT0 && attachment < GL_COLOR_ATTACHMENT0 + kMaxColorAttachments)
    return &color[attachment - GL_COLOR_ATTACHMENT0];
  if (attachment == GL_DEPTH_ATTACHMENT) return &depth;
  if (attachment == GL_STENCIL_ATTACHMENT) return &stencil;
  return nullptr;
}

int FramebufferObject::samples() const {
  int n = 0;
  auto take = [&](const Attachment& a) {
    if (a.type == GL_RENDERBUFFER && a.renderbuffer) n = std::max(n, a.renderbuffer->samples);
    if (a.type == GL_TEXTURE && a.texture && is_multisample(a.texture->target))
      n = std::max(n, a.texture->samples);
  };
  for (const Attachment& a : color) take(a);
  take(depth);
  take(stencil);
  return n;
}

GLenum FramebufferObject::status() const {
  bool any = false;
  TexFormat fmt;
  int w = 0, h = 0;
  int samples = -1, fixed = -1;
  int layered_kind = -1;  // 0: none layered, 1: all layered
  auto check = [&](const Attachment& a, int kind) -> GLenum {
    if (!a) return GL_FRAMEBUFFER_COMPLETE;
    if (!a.image(fmt, w, h) || w <= 0 || h <= 0) return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
    const bool ok = kind == 0 ? fmt.color_renderable() : kind == 1 ? fmt.is_depth() : fmt.has_stencil();
    if (!ok) return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
    any = true;
    // Every attachment of one sample count, and multisample textures all with fixed sample
    // locations or none; renderbuffers count as fixed (§4.4.4.2).
    const bool ms_texture = a.type == GL_TEXTURE && is_multisample(a.texture->target);
    const int s = a.type == GL_RENDERBUFFER ? a.renderbuffer->samples : ms_texture ? a.texture->samples : 0;
    if (samples >= 0 && s != samples) return GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE;
    samples = s;
    const int f = ms_texture ? int(a.texture->fixed_sample_locations) : 1;
    if (samples > 0 && fixed >= 0 && f != fixed) return GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE;
    fixed = f;
    const int l = a.layered ? 1 : 0;
    if (layered_kind >= 0 && l != layered_kind) return GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS;
    layered_kind = l;
    return GL_FRAMEBUFFER_COMPLETE;
  };
  for (const Attachment& a : color)
    if (GLenum e = check(a, 0); e != GL_FRAMEBUFFER_COMPLETE) return e;
  if (GLenum e = check(depth, 1); e != GL_FRAMEBUFFER_COMPLETE) return e;
  if (GLenum e = check(stencil, 2); e != GL_FRAMEBUFFER_COMPLETE) return e;
  if (!any) return GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT;
  // GL 3.3's FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER and _READ_BUFFER are not reported: Mesa drops
  // them with ARB_ES2_compatibility (as GL 4.1 does), and programs written against it (seed
  // 001's FBO example among them) leave the read buffer at an empty COLOR_ATTACHMENT0. A draw
  // buffer without an image is not written; reading from one is GL_INVALID_OPERATION.
  return GL_FRAMEBUFFER_COMPLETE;
}

}  // namespace tessel::gl
