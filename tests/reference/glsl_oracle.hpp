// Mesa llvmpipe "GLSL oracle" for Tessel's tests.
//
// Runs an arbitrary GLSL vertex + fragment program with real OpenGL as implemented by Mesa's
// llvmpipe (headless: EGL surfaceless platform, a COMPATIBILITY-profile context of the
// highest version Mesa offers, so #version 110/120 shaders with gl_ModelViewMatrix & co.
// compile as well as 330 core ones) and returns the raw float pixels it wrote into RGBA32F
// colour attachments, so Tessel's own GLSL compiler can be compared with Mesa's.
//
// Deliberately plain: no Tessel or GL headers, GL enums are passed as uint32_t.
// All images are returned with rows bottom-up (row 0 = window y 0), as glReadPixels does.
//
// Each run() builds everything it uses (program, VAO, one VBO per attribute, textures, FBO)
// and deletes it all afterwards, and sets every piece of GL state it relies on, so runs do
// not see each other. GL state that run() relies on, besides the GL defaults:
//  * no colour clamping anywhere (GL_CLAMP_VERTEX_COLOR, GL_CLAMP_FRAGMENT_COLOR and
//    GL_CLAMP_READ_COLOR are GL_FALSE): the point is to read raw shader results, so even a
//    compatibility gl_FrontColor outside [0,1] reaches the fragment shader unclamped;
//  * GL_PROGRAM_POINT_SIZE and GL_POINT_SPRITE are enabled (gl_PointSize is honoured and
//    gl_PointCoord is defined for points, as in a core context);
//  * no dithering, no multisampling, no sRGB conversion; viewport = the whole target,
//    depth range [0,1]; provoking vertex = last (the GL default);
//  * the fixed-function matrices are identity unless GlslDrawSpec::modelview / projection
//    are given; every other compatibility state (lights, fog, texture matrices, ...) and
//    every current vertex attribute (gl_Color = (1,1,1,1), generic ones = (0,0,0,1), ...)
//    is at its GL default.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tessel::reference {

struct GlslAttribute {
  // The attribute's name in the vertex shader, located with glGetAttribLocation after linking
  // (an inactive name, location -1, is skipped). A matrix attribute (mat2..mat4, matCxR)
  // takes C*R components per vertex, column-major, and fills its C consecutive locations.
  // Extension for compatibility shaders: the built-ins "gl_Vertex", "gl_Color",
  // "gl_SecondaryColor", "gl_Normal", "gl_FogCoord" and "gl_MultiTexCoord0".."7" are fed
  // through glVertexPointer, glColorPointer, ... (from a VBO as well).
  std::string name;
  int components = 4;       // 1..4 (16 etc. for a matrix)
  std::vector<float> data;  // components floats per vertex, at least count vertices
  bool integer = false;     // true: idata through glVertexAttribIPointer (GL_INT)
  std::vector<int32_t> idata;
};

struct GlslUniform {
  // The GL name as glGetUniformLocation takes it: "k", "m[2]", "lights[1].pos". A name not
  // found (location -1, e.g. optimized away) is skipped silently.
  std::string name;
  // Exactly one of these must be non-empty. glGetActiveUniform's type decides which
  // glUniform*v / glUniformMatrix*fv (transpose GL_FALSE, column-major data) is called;
  // count = data size / components of the type (from the location named, so "k[1]" with 2
  // values sets k[1] and k[2]). Values are converted to the type's base type when they do
  // not match it (f for an int uniform or a sampler, i for a float, ...); bool uniforms get
  // the variant given (GL takes f, i and u for them).
  std::vector<float> f;
  std::vector<int32_t> i;
  std::vector<uint32_t> u;
};

struct GlslTexture {
  int unit = 0;  // texture image unit (the sampler uniform must be set to it by the caller)
  // GL_TEXTURE_2D; also GL_TEXTURE_1D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP (6 faces stacked
  // in data, +X -X +Y -Y +Z -Z), GL_TEXTURE_2D_ARRAY (depth = layers), GL_TEXTURE_1D_ARRAY
  // (height = layers), GL_TEXTURE_RECTANGLE, GL_TEXTURE_BUFFER (width texels, uploaded with
  // glBufferData, 16 bytes each, so the internal format must be GL_RGBA32F, GL_RGBA32I or
  // GL_RGBA32UI; read with glTexBuffer; it has no sampler state, so the fields below the data
  // are ignored). Depth formats work for 2D, 1D, array and cube targets.
  uint32_t target = 0x0DE1;
  int width = 1, height = 1, depth = 1;
  // GL_RGBA32F; also GL_RGBA8 (the floats are converted by GL), any other float or
  // normalized colour format (uploaded as GL_RGBA / GL_FLOAT), the depth formats
  // GL_DEPTH_COMPONENT16/24/32/32F (one float per texel, uploaded as GL_DEPTH_COMPONENT /
  // GL_FLOAT) and the integer formats GL_R*/RG*/RGB*/RGBA* 8I..32UI (the floats converted to
  // int32 / uint32 and uploaded as GL_RGBA_INTEGER). In a compatibility context a depth
  // texture sampled without compare returns (d, d, d, 1) (GL_DEPTH_TEXTURE_MODE LUMINANCE).
  uint32_t internal_format = 0x8814;
  std::vector<float> data;  // RGBA floats per texel (one per texel for depth formats),
                            // level 0, rows bottom-up, then layers / slices / faces
  bool mipmaps = false;     // true: glGenerateMipmap; false: GL_TEXTURE_MAX_LEVEL = 0
  uint32_t min_filter = 0x2600, mag_filter = 0x2600;  // GL_NEAREST
  uint32_t wrap = 0x2901;          // GL_REPEAT, for S, T and R. A RECTANGLE texture cannot repeat:
                                   // there GL_REPEAT / GL_MIRRORED_REPEAT leave its CLAMP_TO_EDGE.
  bool compare = false;            // GL_TEXTURE_COMPARE_MODE = GL_COMPARE_REF_TO_TEXTURE
  uint32_t compare_func = 0x0203;  // GL_LEQUAL
};

struct GlslDrawSpec {
  std::string vertex, fragment;  // GLSL source, any #version 110..330 (+ compatibility)
  std::string geometry;          // a geometry shader between them, when not empty
  std::vector<GlslAttribute> attributes;
  std::vector<GlslUniform> uniforms;  // set in this order after glUseProgram
  std::vector<GlslTexture> textures;
  // Uniform blocks: the named block reads binding point i (glUniformBlockBinding), which holds
  // a buffer of these bytes (glBindBufferBase). Blocks not found are skipped.
  struct UniformBuffer {
    std::string block;
    std::vector<uint8_t> data;
  };
  std::vector<UniformBuffer> uniform_buffers;
  uint32_t primitive = 0x0004;  // GL_TRIANGLES; glDrawArrays(primitive, 0, count)
  int count = 0;
  int width = 16, height = 16;
  int outputs = 1;             // RGBA32F colour attachments 0..outputs-1, glDrawBuffers on all (0..8)
  bool depth = false;          // a GL_DEPTH_COMPONENT32F attachment, cleared to 1, GL_LESS test
  uint8_t clip_distances = 0;  // bit i: glEnable(GL_CLIP_DISTANCE0 + i)
  // GL_PROGRAM_POINT_SIZE and GL_POINT_SPRITE are always on (gl_PointSize and gl_PointCoord as
  // in core GL).
  float clear[4] = {0, 0, 0, 0};  // every colour attachment is cleared to this
  // Fixed-function state for the compatibility built-ins (gl_ModelViewMatrix, ...):
  // 16 floats, column-major, loaded with glLoadMatrixf when non-empty (else identity).
  std::vector<float> modelview, projection;
};

struct GlslResult {
  bool compiled = false, linked = false;
  // compiled && linked, the spec was usable (sizes, names of built-in attributes, unit
  // numbers, ...), no GL error was raised and the pixels were read. When false, `log` says
  // why; outputs may still hold what was drawn (e.g. after a GL error at a uniform).
  bool ok = false;
  // The info logs (each under a "vertex shader:", "fragment shader:", "program:" heading,
  // when non-empty), then any GL errors (with the GL debug output's text when Mesa gives
  // one) and problems with the spec, one per line.
  std::string log;
  std::vector<std::vector<float>> outputs;  // per attachment, width*height*4 floats, rows
                                            // bottom-up (glReadPixels GL_RGBA GL_FLOAT)
  std::vector<float> depth;                 // width*height when spec.depth
};

class GlslOracle {
 public:
  // Creates the headless compatibility-profile context on llvmpipe. Returns nullptr (never
  // throws) and sets *why (if non-null) when EGL, the context or llvmpipe is unavailable.
  // Sets LIBGL_ALWAYS_SOFTWARE=1, GALLIUM_DRIVER=llvmpipe and MESA_SHADER_CACHE_DISABLE=true
  // unless already set (the latter only takes effect if no other headless context of the
  // process exists yet, since they share one EGL display and so one Mesa screen).
  static std::unique_ptr<GlslOracle> create(std::string* why);
  ~GlslOracle();
  GlslOracle(const GlslOracle&) = delete;
  GlslOracle& operator=(const GlslOracle&) = delete;

  // Compiles, links and draws `spec`; never throws. A compile or link failure, a GL error or
  // a bad spec is reported in the result (ok = false, log).
  GlslResult run(const GlslDrawSpec& spec);

  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version() const;   // GL_VERSION, e.g. "4.5 (Compatibility Profile) Mesa 22.3.6"

 private:
  struct Impl;
  explicit GlslOracle(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tessel::reference
