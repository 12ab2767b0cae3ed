// Mesa llvmpipe reference "oracle" for Tessel's tests.
//
// Renders the same draws Tessel renders, with real OpenGL as implemented by Mesa's
// llvmpipe (headless: EGL surfaceless platform, desktop GL 3.3 core context, drawing into
// an FBO with an RGBA8 colour renderbuffer and a DEPTH24_STENCIL8 renderbuffer), and reads
// the pixels back so tests can compare them with Tessel's output.
//
// Deliberately plain: no Tessel or GL headers, GL enums are passed as uint32_t.
// All images are returned with rows bottom-up (row 0 = window y 0), as glReadPixels does.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tessel::reference {

struct OracleVertex {
  float pos[4];    // CLIP-space position (x, y, z, w); passed straight to gl_Position
  float color[4];  // RGBA, usually in [0,1]
  float uv[2];     // texture coordinate (used when OracleState::textured)
};

struct OracleTexture {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;     // level 0, width*height*4 bytes, rows bottom-up (t = 0 first)
  bool mipmaps = false;          // true: glGenerateMipmap (Mesa's box-filter chain);
                                 // false: GL_TEXTURE_MAX_LEVEL = 0, so the texture is complete
                                 // even with a *_MIPMAP_* min filter (which then uses level 0).
  uint32_t min_filter = 0x2600;  // GL_NEAREST
  uint32_t mag_filter = 0x2600;  // GL_NEAREST
  uint32_t wrap_s = 0x2901;      // GL_REPEAT
  uint32_t wrap_t = 0x2901;      // GL_REPEAT
};

struct OracleState {
  int viewport[4] = {0, 0, 0, 0};  // x, y, w, h; w <= 0 or h <= 0 means the whole target
  bool depth_test = false;
  uint32_t depth_func = 0x0201;  // GL_LESS
  bool depth_write = true;       // glDepthMask (GL never writes depth with the test disabled)
  bool cull = false;
  uint32_t cull_face = 0x0405;   // GL_BACK
  uint32_t front_face = 0x0901;  // GL_CCW
  bool blend = false;
  uint32_t blend_src_rgb = 1, blend_dst_rgb = 0;        // GL_ONE, GL_ZERO
  uint32_t blend_src_a = 1, blend_dst_a = 0;            // GL_ONE, GL_ZERO
  uint32_t blend_eq_rgb = 0x8006, blend_eq_a = 0x8006;  // GL_FUNC_ADD
  float blend_color[4] = {0, 0, 0, 0};
  bool scissor = false;
  int scissor_box[4] = {0, 0, 0, 0};  // x, y, w, h
  bool polygon_offset = false;        // enables GL_POLYGON_OFFSET_FILL
  float offset_factor = 0, offset_units = 0;
  bool textured = false;                 // colour = vertex colour * texture(uv)   (texture unit 0)
  bool flat = false;                     // colour is 'flat' (provoking vertex = last, the GL default)
  uint32_t primitive = 0x0004;           // GL_TRIANGLES; also GL_LINES, GL_LINE_STRIP, GL_POINTS,
                                         // GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN (any glDrawArrays mode)
  float point_size = 1, line_width = 1;  // gl_PointSize (GL_PROGRAM_POINT_SIZE), glLineWidth
  bool stencil_test = false;
  uint32_t stencil_func = 0x0207;  // GL_ALWAYS
  int stencil_ref = 0;
  uint32_t stencil_mask = 0xFF;
  uint32_t stencil_fail = 0x1E00, stencil_zfail = 0x1E00, stencil_zpass = 0x1E00;  // GL_KEEP
  uint32_t stencil_write_mask = 0xFF;
  bool color_mask[4] = {true, true, true, true};
};

class MesaOracle {
 public:
  // Creates a headless llvmpipe context and a width x height FBO. Returns nullptr (never
  // throws) and sets *why (if non-null) when EGL, the GL context or llvmpipe is unavailable.
  // Sets LIBGL_ALWAYS_SOFTWARE=1 and GALLIUM_DRIVER=llvmpipe unless already set.
  static std::unique_ptr<MesaOracle> create(int width, int height, std::string* why);
  ~MesaOracle();
  MesaOracle(const MesaOracle&) = delete;
  MesaOracle& operator=(const MesaOracle&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  std::string renderer() const;      // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version() const;       // GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6"
  std::string egl_platform() const;  // which EGL display route worked, e.g. "surfaceless"

  // Full-target clear of colour, depth and stencil (scissor off, all write masks on).
  void clear(const float rgba[4], float depth, int stencil);
  // Uploads the texture used by draws with state.textured (replaces the previous one).
  void set_texture(const OracleTexture& t);
  // glDrawArrays(state.primitive, 0, verts.size()) with every piece of state set from
  // `state`. Throws std::runtime_error on a GL error.
  void draw(const std::vector<OracleVertex>& verts, const OracleState& state);

  std::vector<uint8_t> read_rgba8();    // width*height*4, rows bottom-up (glReadPixels)
  std::vector<float> read_depth();      // width*height floats in [0,1] (GL_FLOAT readback)
  std::vector<uint8_t> read_stencil();  // width*height
  // Exact stored depth: width*height 24-bit unsigned normalized integers (0..0xFFFFFF),
  // read as GL_DEPTH_STENCIL / GL_UNSIGNED_INT_24_8. Handy for exact comparisons.
  std::vector<uint32_t> read_depth24();

 private:
  struct Impl;
  explicit MesaOracle(std::unique_ptr<Impl> impl, int width, int height);
  std::unique_ptr<Impl> impl_;
  int width_ = 0, height_ = 0;
};

}  // namespace tessel::reference
