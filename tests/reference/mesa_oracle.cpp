// Mesa llvmpipe reference oracle: see mesa_oracle.hpp.
//
// The headless EGL display and GL 3.3 context come from tessel_gl_headless (bench/gl). GL
// entry points come straight from libOpenGL (glvnd), which exports every core GL function and
// dispatches to the context made current through libEGL.
#include "mesa_oracle.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "headless_gl.hpp"

namespace tessel::reference {
namespace {

using tessel::gl::gl_error_name;
using tessel::gl::hex;

void check_gl(const char* what) {
  GLenum first = glGetError();
  if (first == GL_NO_ERROR) return;
  std::string msg = std::string("MesaOracle: GL error after ") + what + ": " + gl_error_name(first) + " (" +
                    hex(first) + ")";
  // Drain any further queued errors so the next check starts clean.
  for (int i = 0; i < 16; ++i) {
    GLenum e = glGetError();
    if (e == GL_NO_ERROR) break;
    msg += std::string(", ") + gl_error_name(e);
  }
  throw std::runtime_error(msg);
}

GLuint build_program(bool flat, bool textured) {
  const std::string interp = flat ? "flat " : "";
  const std::string vs =
      "#version 330 core\n"
      "layout(location = 0) in vec4 a_pos;\n"
      "layout(location = 1) in vec4 a_color;\n"
      "layout(location = 2) in vec2 a_uv;\n"
      "uniform float u_point_size;\n" +
      interp + "out vec4 v_color;\n" +
      "out vec2 v_uv;\n"
      "void main() {\n"
      "  gl_Position = a_pos;\n"
      "  gl_PointSize = u_point_size;\n"
      "  v_color = a_color;\n"
      "  v_uv = a_uv;\n"
      "}\n";
  const std::string fs =
      "#version 330 core\n" + interp + "in vec4 v_color;\n" +
      "in vec2 v_uv;\n"
      "uniform sampler2D u_tex;\n"
      "layout(location = 0) out vec4 o_color;\n"
      "void main() {\n" +
      (textured ? "  o_color = v_color * texture(u_tex, v_uv);\n" : "  o_color = v_color;\n") + "}\n";
  GLuint prog = 0;
  try {
    prog = tessel::gl::build_program(vs, fs);
  } catch (const std::runtime_error& e) {
    // "MesaOracle: shader compile failed: <log>" / "MesaOracle: program link failed: <log>"
    throw std::runtime_error(std::string("MesaOracle: ") + e.what());
  }
  glUseProgram(prog);
  glUniform1i(glGetUniformLocation(prog, "u_tex"), 0);
  glUseProgram(0);
  return prog;
}

}  // namespace

struct MesaOracle::Impl {
  // Declared first, so destroyed last: ~Impl deletes the GL objects while it still exists.
  std::unique_ptr<tessel::gl::HeadlessContext> gl;
  GLuint fbo = 0, color_rb = 0, depth_rb = 0;
  GLuint vao = 0, vbo = 0, texture = 0;
  GLuint programs[4] = {0, 0, 0, 0};  // index: flat + 2 * textured
  GLint point_size_loc[4] = {-1, -1, -1, -1};

  void make_current() {
    std::string err;
    if (!gl->make_current(&err)) throw std::runtime_error("MesaOracle: " + err);
  }

  GLuint program(bool flat, bool textured, GLint* psize_loc) {
    const int i = (flat ? 1 : 0) + (textured ? 2 : 0);
    if (!programs[i]) {
      programs[i] = build_program(flat, textured);
      point_size_loc[i] = glGetUniformLocation(programs[i], "u_point_size");
    }
    *psize_loc = point_size_loc[i];
    return programs[i];
  }

  ~Impl() {
    // The context and the shared display are released by ~HeadlessContext afterwards.
    if (gl && gl->make_current()) {
      for (GLuint p : programs)
        if (p) glDeleteProgram(p);
      if (texture) glDeleteTextures(1, &texture);
      if (vbo) glDeleteBuffers(1, &vbo);
      if (vao) glDeleteVertexArrays(1, &vao);
      if (fbo) glDeleteFramebuffers(1, &fbo);
      if (color_rb) glDeleteRenderbuffers(1, &color_rb);
      if (depth_rb) glDeleteRenderbuffers(1, &depth_rb);
    }
  }
};

MesaOracle::MesaOracle(std::unique_ptr<Impl> impl, int width, int height)
    : impl_(std::move(impl)), width_(width), height_(height) {}

MesaOracle::~MesaOracle() = default;

std::unique_ptr<MesaOracle> MesaOracle::create(int width, int height, std::string* why) {
  std::string dummy;
  if (!why) why = &dummy;
  why->clear();
  if (width <= 0 || height <= 0) {
    *why = "MesaOracle: invalid size " + std::to_string(width) + "x" + std::to_string(height);
    return nullptr;
  }
  try {
    auto impl = std::make_unique<Impl>();
    // Headless EGL + desktop GL 3.3 core (not forward-compatible, so wide lines stay legal),
    // or 3.3 compatibility if core is refused; current, on llvmpipe (else nullptr + reason).
    tessel::gl::HeadlessOptions gl_options;
    gl_options.compat_fallback = true;
    std::string gl_why;
    impl->gl = tessel::gl::HeadlessContext::create(&gl_why, gl_options);
    if (!impl->gl) {
      *why = "MesaOracle: " + gl_why;
      return nullptr;
    }

    // Framebuffer: RGBA8 colour + DEPTH24_STENCIL8, single-sampled.
    glGenFramebuffers(1, &impl->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, impl->fbo);
    glGenRenderbuffers(1, &impl->color_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, impl->color_rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, impl->color_rb);
    glGenRenderbuffers(1, &impl->depth_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, impl->depth_rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, impl->depth_rb);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      *why = "MesaOracle: framebuffer incomplete (" + hex(status) + ")";
      return nullptr;
    }
    const GLenum draw_buf = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &draw_buf);
    glReadBuffer(GL_COLOR_ATTACHMENT0);

    // Fixed state: no dithering, no multisampling, tight pixel packing.
    glDisable(GL_DITHER);
    glDisable(GL_MULTISAMPLE);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_PROGRAM_POINT_SIZE);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

    glGenVertexArrays(1, &impl->vao);
    glBindVertexArray(impl->vao);
    glGenBuffers(1, &impl->vbo);
    glBindBuffer(GL_ARRAY_BUFFER, impl->vbo);
    const GLsizei stride = sizeof(OracleVertex);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offsetof(OracleVertex, pos)));
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offsetof(OracleVertex, color)));
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offsetof(OracleVertex, uv)));
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glEnableVertexAttribArray(2);

    GLenum err = glGetError();
    if (err != GL_NO_ERROR) {
      *why = std::string("MesaOracle: GL error during setup: ") + gl_error_name(err);
      return nullptr;
    }
    return std::unique_ptr<MesaOracle>(new MesaOracle(std::move(impl), width, height));
  } catch (const std::exception& e) {
    *why = e.what();
    return nullptr;
  }
}

std::string MesaOracle::renderer() const {
  impl_->make_current();
  return impl_->gl->renderer();
}

std::string MesaOracle::version() const {
  impl_->make_current();
  return impl_->gl->version();
}

std::string MesaOracle::egl_platform() const { return impl_->gl->platform(); }

void MesaOracle::clear(const float rgba[4], float depth, int stencil) {
  impl_->make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, impl_->fbo);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glStencilMask(0xFFFFFFFFu);
  glClearColor(rgba[0], rgba[1], rgba[2], rgba[3]);
  glClearDepth(depth);
  glClearStencil(stencil);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  check_gl("glClear");
}

void MesaOracle::set_texture(const OracleTexture& t) {
  if (t.width <= 0 || t.height <= 0 || t.rgba.size() < size_t(t.width) * size_t(t.height) * 4)
    throw std::runtime_error("MesaOracle::set_texture: bad size / too little data");
  impl_->make_current();
  if (!impl_->texture) glGenTextures(1, &impl_->texture);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, impl_->texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, t.width, t.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.rgba.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  if (t.mipmaps) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
    glGenerateMipmap(GL_TEXTURE_2D);
  } else {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GLint(t.min_filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GLint(t.mag_filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GLint(t.wrap_s));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GLint(t.wrap_t));
  check_gl("set_texture");
}

void MesaOracle::draw(const std::vector<OracleVertex>& verts, const OracleState& s) {
  impl_->make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, impl_->fbo);
  glBindVertexArray(impl_->vao);
  glBindBuffer(GL_ARRAY_BUFFER, impl_->vbo);

  if (s.viewport[2] > 0 && s.viewport[3] > 0)
    glViewport(s.viewport[0], s.viewport[1], s.viewport[2], s.viewport[3]);
  else
    glViewport(0, 0, width_, height_);
  glDepthRange(0.0, 1.0);

  if (s.depth_test)
    glEnable(GL_DEPTH_TEST);
  else
    glDisable(GL_DEPTH_TEST);
  glDepthFunc(s.depth_func);
  glDepthMask(s.depth_write ? GL_TRUE : GL_FALSE);

  if (s.cull)
    glEnable(GL_CULL_FACE);
  else
    glDisable(GL_CULL_FACE);
  glCullFace(s.cull_face);
  glFrontFace(s.front_face);

  if (s.blend)
    glEnable(GL_BLEND);
  else
    glDisable(GL_BLEND);
  glBlendFuncSeparate(s.blend_src_rgb, s.blend_dst_rgb, s.blend_src_a, s.blend_dst_a);
  glBlendEquationSeparate(s.blend_eq_rgb, s.blend_eq_a);
  glBlendColor(s.blend_color[0], s.blend_color[1], s.blend_color[2], s.blend_color[3]);

  if (s.scissor)
    glEnable(GL_SCISSOR_TEST);
  else
    glDisable(GL_SCISSOR_TEST);
  glScissor(s.scissor_box[0], s.scissor_box[1], s.scissor_box[2], s.scissor_box[3]);

  if (s.polygon_offset)
    glEnable(GL_POLYGON_OFFSET_FILL);
  else
    glDisable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(s.offset_factor, s.offset_units);

  if (s.stencil_test)
    glEnable(GL_STENCIL_TEST);
  else
    glDisable(GL_STENCIL_TEST);
  glStencilFunc(s.stencil_func, s.stencil_ref, s.stencil_mask);
  glStencilOp(s.stencil_fail, s.stencil_zfail, s.stencil_zpass);
  glStencilMask(s.stencil_write_mask);

  glColorMask(s.color_mask[0], s.color_mask[1], s.color_mask[2], s.color_mask[3]);
  glLineWidth(s.line_width);
  glDisable(GL_DITHER);
  check_gl("setting draw state");

  GLint psize_loc = -1;
  const GLuint prog = impl_->program(s.flat, s.textured, &psize_loc);
  glUseProgram(prog);
  if (psize_loc >= 0) glUniform1f(psize_loc, s.point_size);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, s.textured ? impl_->texture : 0);

  if (!verts.empty()) {
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(verts.size() * sizeof(OracleVertex)), verts.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(s.primitive, 0, GLsizei(verts.size()));
  }
  check_gl("glDrawArrays");
}

std::vector<uint8_t> MesaOracle::read_rgba8() {
  impl_->make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, impl_->fbo);
  glFinish();
  std::vector<uint8_t> out(size_t(width_) * size_t(height_) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  check_gl("glReadPixels(GL_RGBA)");
  return out;
}

std::vector<float> MesaOracle::read_depth() {
  impl_->make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, impl_->fbo);
  glFinish();
  std::vector<float> out(size_t(width_) * size_t(height_));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, out.data());
  check_gl("glReadPixels(GL_DEPTH_COMPONENT)");
  return out;
}

std::vector<uint8_t> MesaOracle::read_stencil() {
  impl_->make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, impl_->fbo);
  glFinish();
  std::vector<uint8_t> out(size_t(width_) * size_t(height_));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, out.data());
  check_gl("glReadPixels(GL_STENCIL_INDEX)");
  return out;
}

std::vector<uint32_t> MesaOracle::read_depth24() {
  impl_->make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, impl_->fbo);
  glFinish();
  std::vector<uint32_t> out(size_t(width_) * size_t(height_));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width_, height_, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out.data());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  check_gl("glReadPixels(GL_DEPTH_STENCIL)");
  for (uint32_t& v : out) v >>= 8;  // drop the stencil byte
  return out;
}

}  // namespace tessel::reference
