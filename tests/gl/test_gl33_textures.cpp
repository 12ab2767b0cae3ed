// Textures, samplers and framebuffer objects of GL 3.3: every texture target sampled by a
// GLSL program, internal formats (what is stored, what reads back), sampler objects,
// swizzles, depth comparison, render to texture with MRT, renderbuffers, completeness,
// glClearBuffer and glBlitFramebuffer, queries, conditional rendering and sync objects, and
// their errors. Also built with AddressSanitizer.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../../src/gl/context.hpp"

namespace {

struct TexTest : ::testing::Test {
  tessel::gl::Context ctx{32, 32, false, true, true};
  void SetUp() override {
    ctx.set_version(3, 3, false);
    tessel::gl::make_current(&ctx);
  }
  void TearDown() override { tessel::gl::make_current(nullptr); }
};
struct TexCoreTest : TexTest {
  void SetUp() override {
    ctx.set_version(3, 3, true);
    tessel::gl::make_current(&ctx);
  }
};

GLenum err() { return glGetError(); }
GLint get_int_value(GLenum name) {
  GLint v[4] = {};
  glGetIntegerv(name, v);
  return v[0];
}

GLuint program(const std::string& vs, const std::string& fs) {
  GLuint p = glCreateProgram();
  for (auto [type, src] :
       {std::pair{GLenum(GL_VERTEX_SHADER), vs}, std::pair{GLenum(GL_FRAGMENT_SHADER), fs}}) {
    GLuint s = glCreateShader(type);
    const char* text = src.c_str();
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    glAttachShader(p, s);
    glDeleteShader(s);
  }
  glLinkProgram(p);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(p, sizeof log, nullptr, log);
    ADD_FAILURE() << log;
  }
  return p;
}

// A full-screen quad drawn with a fragment shader body `fs_main` over `decls`; v in [0, 1]^2.
// With `unit` >= 0 the sampler uniform `s` reads that texture unit.
void draw_quad(const std::string& decls, const std::string& fs_main, int unit = -1) {
  static const float quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
  const std::string vs =
      "#version 330\nlayout(location = 0) in vec2 p;\nout vec2 v;\n"
      "void main() { v = p * 0.5 + 0.5; gl_Position = vec4(p, 0.0, 1.0); }\n";
  const std::string fs = "#version 330\nin vec2 v;\n" + decls + "\nvoid main() {\n" + fs_main + "\n}\n";
  GLuint prog = program(vs, fs);
  glUseProgram(prog);
  if (unit >= 0) glUniform1i(glGetUniformLocation(prog, "s"), unit);
  GLuint vao, vbo;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glDeleteBuffers(1, &vbo);
  glDeleteVertexArrays(1, &vao);
  glUseProgram(0);
  glDeleteProgram(prog);
}

std::array<int, 4> pixel(int x, int y) {
  std::array<GLubyte, 4> px{};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  return {px[0], px[1], px[2], px[3]};
}
std::array<float, 4> pixelf(int x, int y) {
  std::array<float, 4> px{};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_FLOAT, px.data());
  return px;
}

#define EXPECT_PX(p, r, g, b, a) \
  do {                           \
    const auto q = (p);          \
    EXPECT_NEAR(q[0], r, 1);     \
    EXPECT_NEAR(q[1], g, 1);     \
    EXPECT_NEAR(q[2], b, 1);     \
    EXPECT_NEAR(q[3], a, 1);     \
  } while (0)

TEST_F(TexTest, InternalFormatsStoreWhatTheyHold) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  const GLubyte rgba[4] = {200, 100, 50, 25};
  // RGB8: alpha reads 1. R8: green and blue 0, alpha 1. LUMINANCE: (L, L, L, 1).
  struct Case {
    GLenum internal;
    std::array<int, 4> want;
  } cases[] = {
      {GL_RGBA8, {200, 100, 50, 25}},   {GL_RGB8, {200, 100, 50, 255}},       {GL_R8, {200, 0, 0, 255}},
      {GL_RG8, {200, 100, 0, 255}},     {GL_LUMINANCE, {200, 200, 200, 255}}, {GL_ALPHA, {0, 0, 0, 25}},
      {GL_RGBA16F, {200, 100, 50, 25}}, {GL_RGB32F, {200, 100, 50, 255}}};
  for (const Case& k : cases) {
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(k.internal), 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    ASSERT_EQ(err(), GLenum(GL_NO_ERROR)) << k.internal;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    draw_quad("uniform sampler2D s;\nout vec4 c;", "c = texture(s, v);");
    SCOPED_TRACE(k.internal);
    EXPECT_PX(pixel(16, 16), k.want[0], k.want[1], k.want[2], k.want[3]);
    GLint internal = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
    EXPECT_EQ(GLenum(internal), k.internal);
  }
  // A float texture keeps values outside [0, 1]; glGetTexImage gives them back.
  const float big[4] = {4.5f, -2.0f, 0.25f, 1.0f};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, big);
  float back[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, back);
  for (int i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(back[i], big[i]);
  GLint type = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_TYPE, &type);
  EXPECT_EQ(type, GL_FLOAT);
  // Depth textures take depth data only; integer textures integer data only (§3.8.3).
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 1, 1, 0, GL_RGBA, GL_FLOAT, big);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32I, 1, 1, 0, GL_RGBA, GL_FLOAT, big);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 1, 1, 0, GL_RGBA, GL_FLOAT, big);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 1, GL_RGBA, GL_FLOAT, big);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  // After all the errors the texture is still the float one.
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, back);
  EXPECT_FLOAT_EQ(back[0], 4.5f);
  glDeleteTextures(1, &t);
}

TEST_F(TexTest, IntegerTexturesReadByTexelFetch) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  const GLint v[4] = {100000, -7, 3, 1};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32I, 1, 1, 0, GL_RGBA_INTEGER, GL_INT, v);
  ASSERT_EQ(err(), GLenum(GL_NO_ERROR));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  draw_quad("uniform isampler2D s;\nout vec4 c;",
            "ivec4 k = texelFetch(s, ivec2(0), 0);\n"
            "c = vec4(k.x == 100000 ? 1.0 : 0.0, k.y == -7 ? 1.0 : 0.0, float(k.z) / 4.0, 1.0);");
  EXPECT_PX(pixel(5, 5), 255, 255, 191, 255);
  // With LINEAR filtering an integer texture is incomplete: (0, 0, 0, 1) as floats, 0 here.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  draw_quad("uniform isampler2D s;\nout vec4 c;",
            "ivec4 k = texelFetch(s, ivec2(0), 0);\nc = vec4(k) / 4.0;");
  EXPECT_PX(pixel(5, 5), 0, 0, 0, 64);
  glDeleteTextures(1, &t);
}

// 32-bit integer texels are kept exactly, whatever their bits would mean as floats (values
// past 2^24, NaN and infinity patterns), through upload, texelFetch and glGetTexImage.
TEST_F(TexTest, ThirtyTwoBitIntegerTexelsAreExact) {
  GLuint t[2];
  glGenTextures(2, t);
  const GLuint u[4] = {0xFFFFFFFFu, 0x7F800001u, 0x98F87620u, 16777217u};
  glBindTexture(GL_TEXTURE_2D, t[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, 4, 1, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, u);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  GLuint back[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, back);
  ASSERT_EQ(err(), GLenum(GL_NO_ERROR));
  for (int i = 0; i < 4; ++i) EXPECT_EQ(back[i], u[i]) << i;
  draw_quad("uniform usampler2D s;\nout vec4 c;",
            "uvec4 a = texelFetch(s, ivec2(0, 0), 0), b = texelFetch(s, ivec2(1, 0), 0),\n"
            "      d = texelFetch(s, ivec2(2, 0), 0), e = texelFetch(s, ivec2(3, 0), 0);\n"
            "c = vec4(a.x == 0xFFFFFFFFu && b.x == 0x7F800001u ? 1.0 : 0.0,\n"
            "         d.x == 0x98F87620u && e.x == 16777217u ? 1.0 : 0.0, a.a == 1u ? 1.0 : 0.0, 1.0);");
  EXPECT_PX(pixel(5, 5), 255, 255, 255, 255);
  const GLint i[2] = {-123456789, int(0x80000000u)};
  glBindTexture(GL_TEXTURE_2D, t[1]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32I, 2, 1, 0, GL_RED_INTEGER, GL_INT, i);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  draw_quad("uniform isampler2D s;\nout vec4 c;",
            "ivec4 a = texelFetch(s, ivec2(0, 0), 0), b = texelFetch(s, ivec2(1, 0), 0);\n"
            "c = vec4(a.x == -123456789 ? 1.0 : 0.0, b.x == int(0x80000000u) ? 1.0 : 0.0, 0.0, 1.0);");
  EXPECT_PX(pixel(5, 5), 255, 255, 0, 255);
  // Narrower formats clamp; reading back as a narrower type clamps too.
  const GLint wide[2] = {300, -5};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8I, 2, 1, 0, GL_RED_INTEGER, GL_INT, wide);
  GLshort s16[2] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED_INTEGER, GL_SHORT, s16);
  EXPECT_EQ(s16[0], 127);
  EXPECT_EQ(s16[1], -5);
  // There are no mipmaps to filter from integer images.
  glGenerateMipmap(GL_TEXTURE_2D);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glDeleteTextures(2, t);
}

// glClampColor(GL_CLAMP_READ_COLOR): glReadPixels of a float buffer returns its values as
// they are (GL_FIXED_ONLY, the default, or GL_FALSE) or clamped to [0, 1] (GL_TRUE).
TEST_F(TexTest, ClampReadColorAppliesToFloatBuffers) {
  GLuint fb, rb;
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, 4, 4);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  const GLfloat value[4] = {2.5f, -1.0f, 0.25f, 1.0f};
  glClearBufferfv(GL_COLOR, 0, value);
  GLfloat px[4] = {};
  EXPECT_EQ(get_int_value(GL_CLAMP_READ_COLOR), GL_FIXED_ONLY);
  glReadPixels(1, 1, 1, 1, GL_RGBA, GL_FLOAT, px);
  EXPECT_EQ(px[0], 2.5f);
  EXPECT_EQ(px[1], -1.0f);
  glClampColor(GL_CLAMP_READ_COLOR, GL_TRUE);
  glReadPixels(1, 1, 1, 1, GL_RGBA, GL_FLOAT, px);
  EXPECT_EQ(px[0], 1.0f);
  EXPECT_EQ(px[1], 0.0f);
  EXPECT_EQ(px[2], 0.25f);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glClampColor(GL_CLAMP_READ_COLOR, GL_RGBA);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glClampColor(0x1234, GL_TRUE);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int_value(GL_CLAMP_READ_COLOR), GL_TRUE);
  glClampColor(GL_CLAMP_VERTEX_COLOR, GL_FALSE);  // compatibility only
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_int_value(GL_CLAMP_VERTEX_COLOR), GL_FALSE);
  ctx.set_version(3, 3, true);
  glClampColor(GL_CLAMP_VERTEX_COLOR, GL_TRUE);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glDeleteFramebuffers(1, &fb);
  glDeleteRenderbuffers(1, &rb);
}

TEST_F(TexTest, EveryTargetIsSampled) {
  GLuint tex[7];
  glGenTextures(7, tex);
  // 1D: four texels, the third green.
  const GLubyte row[16] = {255, 0, 0, 255, 255, 0, 0, 255, 0, 255, 0, 255, 255, 0, 0, 255};
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_1D, tex[0]);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, row);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  // 3D: 2x2x2, slice 1 blue.
  std::vector<GLubyte> vol(2 * 2 * 2 * 4, 0);
  for (int i = 4; i < 8; ++i) vol[size_t(i) * 4 + 2] = vol[size_t(i) * 4 + 3] = 255;
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_3D, tex[1]);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol.data());
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  // A cube map: face i has red = 40 * i.
  glActiveTexture(GL_TEXTURE3);
  glBindTexture(GL_TEXTURE_CUBE_MAP, tex[2]);
  for (int f = 0; f < 6; ++f) {
    const GLubyte px[4] = {GLubyte(40 * f), 0, 0, 255};
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(f), 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 px);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  // A 2D array of three layers: layer 2 white.
  std::vector<GLubyte> layers(3 * 4, 0);
  layers[8] = layers[9] = layers[10] = layers[11] = 255;
  glActiveTexture(GL_TEXTURE4);
  glBindTexture(GL_TEXTURE_2D_ARRAY, tex[3]);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, 1, 1, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, layers.data());
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  // A rectangle texture, read with texel coordinates: (3, 1) is yellow.
  std::vector<GLubyte> rect(4 * 2 * 4, 0);
  rect[(1 * 4 + 3) * 4 + 0] = rect[(1 * 4 + 3) * 4 + 1] = rect[(1 * 4 + 3) * 4 + 3] = 255;
  glActiveTexture(GL_TEXTURE5);
  glBindTexture(GL_TEXTURE_RECTANGLE, tex[4]);
  glTexImage2D(GL_TEXTURE_RECTANGLE, 0, GL_RGBA8, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, rect.data());
  glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));  // no mipmaps for rectangles
  glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  // A buffer texture of RGBA32F texels.
  const float texels[8] = {0, 0, 0, 0, 0.5f, 0.25f, 1.0f, 1.0f};
  GLuint buf;
  glGenBuffers(1, &buf);
  glBindBuffer(GL_TEXTURE_BUFFER, buf);
  glBufferData(GL_TEXTURE_BUFFER, sizeof texels, texels, GL_STATIC_DRAW);
  glActiveTexture(GL_TEXTURE6);
  glBindTexture(GL_TEXTURE_BUFFER, tex[5]);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, buf);
  ASSERT_EQ(err(), GLenum(GL_NO_ERROR));

  // A full-screen quad whose sampler `s` reads `unit`; the centre pixel.
  auto run = [&](const std::string& decl, const std::string& body, int unit) {
    draw_quad(decl + "\nout vec4 c;", body, unit);
    return pixel(16, 16);
  };
  EXPECT_PX(run("uniform sampler1D s;", "c = texture(s, 0.6);", 1), 0, 255, 0, 255);
  EXPECT_PX(run("uniform sampler3D s;", "c = texture(s, vec3(0.5, 0.5, 0.75));", 2), 0, 0, 255, 255);
  EXPECT_PX(run("uniform sampler3D s;", "c = texture(s, vec3(0.5, 0.5, 0.25));", 2), 0, 0, 0, 0);
  for (int f = 0; f < 6; ++f) {
    const char* dirs[6] = {"vec3(1,0,0)",  "vec3(-1,0,0)", "vec3(0,1,0)",
                           "vec3(0,-1,0)", "vec3(0,0,1)",  "vec3(0,0,-1)"};
    EXPECT_PX(run("uniform samplerCube s;", std::string("c = texture(s, ") + dirs[f] + ");", 3), 40 * f, 0, 0,
              255);
  }
  EXPECT_PX(run("uniform sampler2DArray s;", "c = texture(s, vec3(0.5, 0.5, 2.0));", 4), 255, 255, 255, 255);
  EXPECT_PX(run("uniform sampler2DArray s;", "c = texture(s, vec3(0.5, 0.5, 1.0));", 4), 0, 0, 0, 0);
  EXPECT_PX(run("uniform sampler2DRect s;", "c = texture(s, vec2(3.5, 1.5));", 5), 255, 255, 0, 255);
  EXPECT_PX(run("uniform samplerBuffer s;", "c = texelFetch(s, 1);", 6), 128, 64, 255, 255);
  // Two sampler types on one unit: the draw is GL_INVALID_OPERATION (§2.11.7).
  glGetError();
  run("uniform sampler2D s;\nuniform samplerCube s2;", "c = texture(s, v) + texture(s2, vec3(1.0));", 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // A texture bound to one target cannot be bound to another.
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glDeleteTextures(7, tex);
  glDeleteBuffers(1, &buf);
}

TEST_F(TexTest, SamplerObjectsAndSwizzleOverride) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  // 2x1: red, blue. Sampled at the middle, LINEAR gives the mix, NEAREST one of them.
  const GLubyte px[8] = {255, 0, 0, 255, 0, 0, 255, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  const std::string decl = "uniform sampler2D s;\nout vec4 c;";
  draw_quad(decl, "c = texture(s, vec2(0.5, 0.5));");
  EXPECT_PX(pixel(16, 16), 128, 0, 128, 255);
  GLuint smp;
  glGenSamplers(1, &smp);
  EXPECT_TRUE(glIsSampler(smp));
  glSamplerParameteri(smp, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(smp, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glBindSampler(0, smp);
  draw_quad(decl, "c = texture(s, vec2(0.74, 0.5));");
  EXPECT_PX(pixel(16, 16), 0, 0, 255, 255);
  GLint v = 0;
  glGetSamplerParameteriv(smp, GL_TEXTURE_MAG_FILTER, &v);
  EXPECT_EQ(v, GL_NEAREST);
  glSamplerParameteri(smp, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glSamplerParameteri(smp, GL_TEXTURE_BASE_LEVEL, 1);  // a texture parameter only
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glBindSampler(0, smp + 100);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glBindSampler(48, smp);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glDeleteSamplers(1, &smp);
  EXPECT_FALSE(glIsSampler(smp));
  // Unbound by the deletion: the texture's own LINEAR again.
  draw_quad(decl, "c = texture(s, vec2(0.5, 0.5));");
  EXPECT_PX(pixel(16, 16), 128, 0, 128, 255);
  // Swizzle: (B, ONE, ZERO, R).
  const GLint sw[4] = {GL_BLUE, GL_ONE, GL_ZERO, GL_RED};
  glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, sw);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  draw_quad(decl, "c = texture(s, vec2(0.25, 0.5));");
  EXPECT_PX(pixel(16, 16), 0, 255, 0, 255);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_G, GL_RGBA);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  GLint got[4] = {};
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, got);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(got[i], sw[i]);
  // LOD bias and limits are kept and read back.
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.5f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 3.0f);
  float f = 0;
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, &f);
  EXPECT_FLOAT_EQ(f, 1.5f);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, &f);
  EXPECT_FLOAT_EQ(f, 3.0f);
  glDeleteTextures(1, &t);
}

// A framebuffer object with two colour textures and a depth renderbuffer: MRT writes both,
// the depth test works in it, and the textures are then sampled in the window.
TEST_F(TexTest, RenderToTexturesWithMrtAndDepth) {
  GLuint tex[2], fbo, rb;
  glGenTextures(2, tex);
  for (GLuint t : tex) {
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 8, 8);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex[1], 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  const GLenum bufs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, bufs);
  glViewport(0, 0, 8, 8);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  // A near quad (z = -0.5) in red/green, then a far one (z = 0.5) in blue that must not show.
  const std::string vs =
      "#version 330\nlayout(location = 0) in vec2 p;\nuniform float z;\n"
      "void main() { gl_Position = vec4(p, z, 1.0); }\n";
  const std::string fs =
      "#version 330\nuniform vec4 a, b;\nlayout(location = 0) out vec4 o0;\nlayout(location = 1) out vec4 "
      "o1;\n"
      "void main() { o0 = a; o1 = b; }\n";
  GLuint prog = program(vs, fs);
  glUseProgram(prog);
  static const float quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
  GLuint vao, vbo;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glUniform1f(glGetUniformLocation(prog, "z"), -0.5f);
  glUniform4f(glGetUniformLocation(prog, "a"), 1, 0, 0, 1);
  glUniform4f(glGetUniformLocation(prog, "b"), 0, 1, 0, 1);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glUniform1f(glGetUniformLocation(prog, "z"), 0.5f);
  glUniform4f(glGetUniformLocation(prog, "a"), 0, 0, 1, 1);
  glUniform4f(glGetUniformLocation(prog, "b"), 0, 0, 1, 1);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  // Read back through the framebuffer: each attachment by glReadBuffer.
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  EXPECT_PX(pixel(4, 4), 0, 255, 0, 255);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  EXPECT_PX(pixel(4, 4), 255, 0, 0, 255);
  // glGetTexImage sees what was rendered.
  std::vector<GLubyte> img(8 * 8 * 4);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  EXPECT_EQ(img[(3 * 8 + 3) * 4 + 1], 255);
  // Back to the window: the second texture sampled.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, 32, 32);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(0);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  draw_quad("uniform sampler2D s;\nout vec4 c;", "c = texture(s, v);");
  EXPECT_PX(pixel(16, 16), 0, 255, 0, 255);
  // Changing the texture after rendering keeps what was rendered elsewhere.
  const GLubyte white[4] = {255, 255, 255, 255};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  EXPECT_EQ(img[0], 255);
  EXPECT_EQ(img[(3 * 8 + 3) * 4 + 0], 0);
  EXPECT_EQ(img[(3 * 8 + 3) * 4 + 1], 255);
  // Deleting an attached texture while the framebuffer is bound detaches it (§4.4.2.3).
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glDeleteTextures(1, &tex[1]);
  GLint type = -1;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  EXPECT_EQ(type, GL_NONE);
  // Draw buffer 1 has no image now: not an incomplete framebuffer (as Mesa with
  // ARB_ES2_compatibility), and reading from it is an error.
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  pixel(0, 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // An attachment without an image is: draws and clears are GL_INVALID_FRAMEBUFFER_OPERATION.
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 0, 0);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT));
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(err(), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fbo);
  glDeleteRenderbuffers(1, &rb);
  glDeleteTextures(1, &tex[0]);
  glDeleteBuffers(1, &vbo);
  glDeleteVertexArrays(1, &vao);
  glDeleteProgram(prog);
}

// A depth texture rendered in a framebuffer object and read by sampler2DShadow: the
// comparison with linear filtering gives fractions (PCF), and NEAREST gives 0 or 1.
TEST_F(TexTest, ShadowMapThroughDepthTexture) {
  GLuint depth, fbo;
  glGenTextures(1, &depth);
  glBindTexture(GL_TEXTURE_2D, depth);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 16, 16, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, 16, 16);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  // An occluder on the left half at depth 0.25 (window z = 0.25 for NDC z = -0.5).
  const std::string vs =
      "#version 330\nlayout(location = 0) in vec2 p;\n"
      "void main() { gl_Position = vec4(p.x * 0.5 - 0.5, p.y, -0.5, 1.0); }\n";
  GLuint occ = program(vs, "#version 330\nvoid main() {}\n");
  glUseProgram(occ);
  static const float quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
  GLuint vao, vbo;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, 32, 32);
  glDeleteProgram(occ);
  glDeleteBuffers(1, &vbo);
  glDeleteVertexArrays(1, &vao);
  // Receivers at depth 0.5: in shadow on the left, lit on the right.
  const std::string decl = "uniform sampler2DShadow s;\nout vec4 c;";
  draw_quad(decl, "c = vec4(texture(s, vec3(v, 0.5)));");
  EXPECT_PX(pixel(4, 16), 0, 0, 0, 0);
  EXPECT_PX(pixel(28, 16), 255, 255, 255, 255);
  // Linear filtering: the texel edge at u = 0.5 is half in shadow.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  draw_quad(decl, "c = vec4(texture(s, vec3(0.5, 0.5, 0.5)));");
  EXPECT_PX(pixel(16, 16), 128, 128, 128, 128);
  glDeleteFramebuffers(1, &fbo);
  glDeleteTextures(1, &depth);
}

TEST_F(TexTest, FramebufferCompletenessAndErrors) {
  GLuint fbo, tex, rb;
  glGenFramebuffers(1, &fbo);
  glGenTextures(1, &tex);
  glGenRenderbuffers(1, &rb);
  // The default framebuffer has no attachment points.
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glCheckFramebufferStatus(0x1234);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  EXPECT_TRUE(glIsFramebuffer(fbo));
  // A texture name never bound is not a texture yet.
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glBindTexture(GL_TEXTURE_2D, tex);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  // Attached, but no image yet: an incomplete attachment.
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  // A draw buffer naming an empty attachment point: complete (see RenderToTexturesWithMrtAndDepth).
  const GLenum two[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT3};
  glDrawBuffers(2, two);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  const GLenum dup[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT0};
  glDrawBuffers(2, dup);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  const GLenum back[1] = {GL_BACK};
  glDrawBuffers(1, back);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));  // names several buffers: never in glDrawBuffers (as Mesa)
  glDrawBuffers(9, two);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  // Renderbuffers: errors of storage.
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 4);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));  // none bound
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, -1, 4);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glRenderbufferStorage(GL_RENDERBUFFER, 0x1234, 4, 4);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 64, GL_RGBA8, 4, 4);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));  // more samples than there are (as Mesa)
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, 4, 4);
  GLint w = 0;
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &w);
  EXPECT_EQ(w, 4);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_STENCIL_SIZE, &w);
  EXPECT_EQ(w, 8);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  GLint name = 0;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
  EXPECT_EQ(GLuint(name), rb);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb + 50);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + 8, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));  // past the last colour attachment (as Mesa)
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X, tex, 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, -1);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  // Deleting the bound framebuffer binds 0.
  glDeleteFramebuffers(1, &fbo);
  GLint binding = -1;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &binding);
  EXPECT_EQ(binding, 0);
  EXPECT_FALSE(glIsFramebuffer(fbo));
  glDeleteRenderbuffers(1, &rb);
  glDeleteTextures(1, &tex);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

TEST_F(TexTest, ClearBufferAndBlit) {
  GLuint tex[2], fbo[2];
  glGenTextures(2, tex);
  glGenFramebuffers(2, fbo);
  for (int i = 0; i < 2; ++i) {
    glBindTexture(GL_TEXTURE_2D, tex[i]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 4, 4, 0, GL_RGBA, GL_FLOAT, nullptr);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo[i]);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[i], 0);
  }
  // A float buffer keeps a clear value above 1.
  glBindFramebuffer(GL_FRAMEBUFFER, fbo[0]);
  const float value[4] = {2.0f, 0.5f, -1.0f, 1.0f};
  glClearBufferfv(GL_COLOR, 0, value);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  const auto p = pixelf(1, 1);
  EXPECT_FLOAT_EQ(p[0], 2.0f);
  EXPECT_FLOAT_EQ(p[2], -1.0f);
  glClearBufferfv(GL_COLOR, 8, value);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glClearBufferfv(GL_STENCIL, 0, value);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  // One texel of the source different, then a 2x magnifying blit of the 2x2 corner.
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  const float one[4] = {0.0f, 1.0f, 0.0f, 1.0f};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGBA, GL_FLOAT, one);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[0]);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo[1]);
  glBlitFramebuffer(0, 0, 2, 2, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[1]);
  EXPECT_FLOAT_EQ(pixelf(3, 3)[1], 1.0f);
  EXPECT_FLOAT_EQ(pixelf(2, 2)[1], 1.0f);
  EXPECT_FLOAT_EQ(pixelf(1, 1)[0], 2.0f);
  // LINEAR: the pixel between the two texels mixes them.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[0]);
  glBlitFramebuffer(0, 1, 2, 2, 0, 0, 4, 1, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[1]);
  const auto mid = pixelf(1, 0);  // source x = 0.75: 3/4 of texel 0 (green 0.5), 1/4 of texel 1 (1.0)
  EXPECT_NEAR(mid[1], 0.625f, 1e-5);
  // Errors: a bad mask, a bad filter, LINEAR with depth.
  glBlitFramebuffer(0, 0, 1, 1, 0, 0, 1, 1, 0x10, GL_NEAREST);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glBlitFramebuffer(0, 0, 1, 1, 0, 0, 1, 1, GL_COLOR_BUFFER_BIT, GL_LINEAR_MIPMAP_LINEAR);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glBlitFramebuffer(0, 0, 1, 1, 0, 0, 1, 1, GL_DEPTH_BUFFER_BIT, GL_LINEAR);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // Into the window: the blit's destination is the default framebuffer.
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[0]);
  glBlitFramebuffer(0, 0, 4, 4, 0, 0, 32, 32, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  EXPECT_PX(pixel(12, 12), 0, 255, 0, 255);
  EXPECT_PX(pixel(2, 2), 255, 128, 0, 255);
  glDeleteFramebuffers(2, fbo);
  glDeleteTextures(2, tex);
}

TEST_F(TexTest, BlendEquationsAndSeparateFunctions) {
  glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  glBlendEquationSeparate(GL_FUNC_REVERSE_SUBTRACT, GL_MAX);
  glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  draw_quad("out vec4 c;", "c = vec4(0.25, 0.75, 0.0, 0.25);");
  // RGB: dst - src, clamped; alpha: max.
  EXPECT_PX(pixel(16, 16), 64, 0, 128, 128);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_CONSTANT_COLOR, GL_ZERO);
  glBlendColor(0.5f, 0.0f, 1.0f, 1.0f);
  draw_quad("out vec4 c;", "c = vec4(1.0, 1.0, 0.5, 1.0);");
  EXPECT_PX(pixel(16, 16), 128, 0, 128, 255);
  glBlendEquation(0x1234);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  GLint eq = 0;
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &eq);
  EXPECT_EQ(eq, GL_FUNC_ADD);
  glDisable(GL_BLEND);
  glColorMaski(0, GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  draw_quad("out vec4 c;", "c = vec4(0.0, 1.0, 0.0, 1.0);");
  EXPECT_PX(pixel(16, 16), 0, 0, 0, 255);
  GLboolean m[4] = {};
  glGetBooleani_v(GL_COLOR_WRITEMASK, 0, m);
  EXPECT_EQ(m[1], GL_FALSE);
  glColorMaski(8, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
}

// Occlusion and primitive queries count what the pipeline did; conditional rendering skips
// draws after a query that counted nothing; fences are signaled.
TEST_F(TexTest, QueriesConditionalRenderingAndSyncs) {
  GLuint q[3];
  glGenQueries(3, q);
  EXPECT_FALSE(glIsQuery(q[0]));  // a name until glBeginQuery
  glBeginQuery(GL_SAMPLES_PASSED, q[0]);
  EXPECT_TRUE(glIsQuery(q[0]));
  GLint current = 0;
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &current);
  EXPECT_EQ(GLuint(current), q[0]);
  glBeginQuery(GL_SAMPLES_PASSED, q[1]);  // one active query per target
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  GLuint result = 0;
  glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &result);  // not while active
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // The left half of the 32x32 window: 512 samples.
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 16, 32);
  draw_quad("out vec4 c;", "c = vec4(1.0);");
  glDisable(GL_SCISSOR_TEST);
  glEndQuery(GL_SAMPLES_PASSED);
  glGetQueryObjectuiv(q[0], GL_QUERY_RESULT_AVAILABLE, &result);
  EXPECT_EQ(result, 1u);
  glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &result);
  EXPECT_EQ(result, 512u);
  glBeginQuery(GL_TIME_ELAPSED, q[0]);  // a query keeps its target
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // Nothing passes the depth test: zero, and the conditional draw is skipped.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_NEVER);
  glBeginQuery(GL_ANY_SAMPLES_PASSED, q[1]);
  draw_quad("out vec4 c;", "c = vec4(1.0);");
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  glDisable(GL_DEPTH_TEST);
  GLuint64 any = 7;
  glGetQueryObjectui64v(q[1], GL_QUERY_RESULT, &any);
  EXPECT_EQ(any, 0u);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBeginConditionalRender(q[1], GL_QUERY_WAIT);
  draw_quad("out vec4 c;", "c = vec4(1.0);");
  glEndConditionalRender();
  EXPECT_PX(pixel(16, 16), 0, 0, 0, 255);
  glBeginConditionalRender(q[0], GL_QUERY_WAIT);
  draw_quad("out vec4 c;", "c = vec4(1.0);");
  glEndConditionalRender();
  EXPECT_PX(pixel(16, 16), 255, 255, 255, 255);
  glEndConditionalRender();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // Primitives generated: two triangles of the strip.
  glBeginQuery(GL_PRIMITIVES_GENERATED, q[2]);
  draw_quad("out vec4 c;", "c = vec4(1.0);");
  glEndQuery(GL_PRIMITIVES_GENERATED);
  glGetQueryObjectuiv(q[2], GL_QUERY_RESULT, &result);
  EXPECT_EQ(result, 2u);
  glEndQuery(GL_PRIMITIVES_GENERATED);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glBeginQuery(0x1234, q[2]);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glDeleteQueries(3, q);
  EXPECT_FALSE(glIsQuery(q[0]));
  // Timer: a timestamp later than one before it.
  GLint64 t0 = 0, t1 = 0;
  glGetInteger64v(GL_TIMESTAMP, &t0);
  GLuint tq;
  glGenQueries(1, &tq);
  glQueryCounter(tq, GL_TIMESTAMP);
  glGetQueryObjecti64v(tq, GL_QUERY_RESULT, &t1);
  EXPECT_GE(t1, t0);
  glDeleteQueries(1, &tq);
  // Syncs.
  GLsync s = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  ASSERT_NE(s, nullptr);
  EXPECT_TRUE(glIsSync(s));
  EXPECT_EQ(glClientWaitSync(s, GL_SYNC_FLUSH_COMMANDS_BIT, 1000000), GLenum(GL_ALREADY_SIGNALED));
  GLint status = 0;
  GLsizei len = 0;
  glGetSynciv(s, GL_SYNC_STATUS, 1, &len, &status);
  EXPECT_EQ(status, GL_SIGNALED);
  glWaitSync(s, 1, GL_TIMEOUT_IGNORED);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glDeleteSync(s);
  EXPECT_FALSE(glIsSync(s));
  glDeleteSync(s);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(glFenceSync(0x1234, 0), nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
}

// Regions past the image, sizes that would not fit, and a base level beyond the last level:
// errors and incomplete textures, never a write out of bounds or an abort.
TEST_F(TexTest, HugeAndOverflowingRegionsAreErrors) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  const GLubyte px[4] = {1, 2, 3, 4};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0x7fffffff, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 100000, 100000, GL_RGBA, GL_UNSIGNED_BYTE, px);  // not read
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0x7fffffff, 0, 0, 0, 1, 1);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 100000, 100000);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  // A 2D array as large as the limits allow, in a float format: more than a texture may hold.
  glBindTexture(GL_TEXTURE_2D_ARRAY, t + 1000);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, 8192, 8192, 2048, 0, GL_RGBA, GL_FLOAT, nullptr);
  EXPECT_EQ(err(), GLenum(GL_OUT_OF_MEMORY));
  // Base level 20: no image there, so the texture is incomplete and samples (0, 0, 0, 1).
  glBindTexture(GL_TEXTURE_2D, t);
  const GLubyte white[4 * 16] = {255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
                                 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
                                 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
                                 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
                                 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  draw_quad("uniform sampler2D s;\nout vec4 c;", "c = texture(s, v);");
  EXPECT_PX(pixel(16, 16), 255, 255, 255, 255);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 20);
  draw_quad("uniform sampler2D s;\nout vec4 c;", "c = texture(s, v);");
  EXPECT_PX(pixel(16, 16), 0, 0, 0, 255);
  glDeleteTextures(1, &t);
}

// A blit into an RGB texture keeps its alpha at 1, and each draw buffer's colour mask holds.
TEST_F(TexTest, BlitKeepsTheDestinationsChannelsAndMasks) {
  GLuint tex[3], fbo[2];
  glGenTextures(3, tex);
  glGenFramebuffers(2, fbo);
  const float half[4] = {0.2f, 0.4f, 0.6f, 0.5f};
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  std::vector<float> src(4 * 4 * 4);
  for (size_t i = 0; i < src.size(); ++i) src[i] = half[i % 4];
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_FLOAT, src.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[0]);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 0);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo[1]);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[1], 0);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex[2], 0);
  const GLenum bufs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, bufs);
  glColorMaski(1, GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  GLubyte out[4 * 16] = {};
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(out[0], 51);
  EXPECT_EQ(out[3], 255);  // RGB: alpha reads 1
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(out[0], 51);
  EXPECT_EQ(out[1], 0);  // green masked off for draw buffer 1
  EXPECT_EQ(out[3], 128);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(2, fbo);
  glDeleteTextures(3, tex);
}

// 3D images with GL_UNPACK_IMAGE_HEIGHT and GL_UNPACK_SKIP_IMAGES, read back with the pack
// equivalents (GL 3.3 §3.7.4, §6.1.4).
TEST_F(TexTest, ImageHeightAndSkipImagesForThreeDimensionalImages) {
  // Client memory: 4 images of 3 rows of 2 RGBA8 texels; the texture takes 2x2x2 from it,
  // skipping the first image and each image's last row.
  std::vector<GLubyte> mem(4 * 3 * 2 * 4);
  for (size_t i = 0; i < mem.size(); ++i) mem[i] = GLubyte(i);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 3);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
  EXPECT_EQ(get_int_value(GL_UNPACK_IMAGE_HEIGHT), 3);
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_3D, t);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, mem.data());
  ASSERT_EQ(err(), GLenum(GL_NO_ERROR));
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  std::vector<GLubyte> back(2 * 2 * 2 * 4, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back.data());
  // Texel (x, y, z) came from image z + 1, row y, column x.
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x)
        EXPECT_EQ(back[size_t(((z * 2 + y) * 2 + x) * 4)], GLubyte((((z + 1) * 3 + y) * 2 + x) * 4))
            << x << "," << y << "," << z;
  // Packed back the same way: the skipped image and rows are left alone.
  std::vector<GLubyte> out(mem.size(), 0xEE);
  glPixelStorei(GL_PACK_IMAGE_HEIGHT, 3);
  glPixelStorei(GL_PACK_SKIP_IMAGES, 1);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_EQ(out[0], 0xEE);
  EXPECT_EQ(out[size_t((1 * 3 + 0) * 2 * 4)], mem[size_t((1 * 3 + 0) * 2 * 4)]);
  EXPECT_EQ(out[size_t((1 * 3 + 2) * 2 * 4)], 0xEE);  // row 2 of image 1: not part of the texture
  glPixelStorei(GL_PACK_IMAGE_HEIGHT, -1);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glPixelStorei(GL_PACK_IMAGE_HEIGHT, 0);
  glPixelStorei(GL_PACK_SKIP_IMAGES, 0);
  glDeleteTextures(1, &t);
}

// Random texture and framebuffer calls, valid and not: never a crash (with ASan), every
// error one GL names.
TEST_F(TexCoreTest, RandomTextureAndFramebufferCallsNeverCrash) {
  std::mt19937 rng(7);
  auto pick = [&](int n) { return int(rng() % unsigned(n)); };
  GLuint tex[4], fbo[2], rb[2];
  glGenTextures(4, tex);
  glGenFramebuffers(2, fbo);
  glGenRenderbuffers(2, rb);
  const GLenum targets[] = {GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_3D, GL_TEXTURE_2D_ARRAY, 0x1234};
  const GLint formats[] = {GL_RGBA8, GL_RGB16F, GL_DEPTH_COMPONENT24, GL_R32I, GL_DEPTH24_STENCIL8, 0x1234};
  std::vector<float> data(16 * 16 * 16 * 4, 0.5f);
  for (int step = 0; step < 3000; ++step) {
    switch (pick(12)) {
      case 0: glBindTexture(targets[pick(5)], tex[pick(4)]); break;
      case 1: {
        const GLint f = formats[pick(6)];
        const GLenum fmt = f == GL_DEPTH_COMPONENT24  ? GL_DEPTH_COMPONENT
                           : f == GL_R32I             ? GL_RED_INTEGER
                           : f == GL_DEPTH24_STENCIL8 ? GL_DEPTH_STENCIL
                                                      : GL_RGBA;
        const GLenum type = f == GL_DEPTH24_STENCIL8 ? GL_UNSIGNED_INT_24_8
                            : f == GL_R32I           ? GL_INT
                                                     : GL_FLOAT;
        glTexImage2D(GL_TEXTURE_2D, pick(3), f, pick(17) - 1, pick(17), 0, fmt, type,
                     pick(2) ? data.data() : nullptr);
        break;
      }
      case 2:
        glTexImage3D(pick(2) ? GL_TEXTURE_3D : GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, pick(9), pick(9), pick(9), 0,
                     GL_RGBA, GL_FLOAT, data.data());
        break;
      case 3:
        glTexSubImage2D(GL_TEXTURE_2D, pick(2), pick(10) - 2, pick(10) - 2, pick(8), pick(8), GL_RGBA,
                        GL_FLOAT, data.data());
        break;
      case 4:
        glBindFramebuffer(pick(2) ? GL_FRAMEBUFFER : GL_READ_FRAMEBUFFER, pick(3) ? fbo[pick(2)] : 0);
        break;
      case 5:
        glFramebufferTexture2D(GL_FRAMEBUFFER,
                               pick(2) ? GL_COLOR_ATTACHMENT0 + GLenum(pick(3)) : GL_DEPTH_ATTACHMENT,
                               GL_TEXTURE_2D, tex[pick(4)], pick(3));
        break;
      case 6:
        glBindRenderbuffer(GL_RENDERBUFFER, rb[pick(2)]);
        glRenderbufferStorage(GL_RENDERBUFFER, pick(2) ? GL_RGBA8 : GL_DEPTH24_STENCIL8, pick(20), pick(20));
        glFramebufferRenderbuffer(GL_FRAMEBUFFER,
                                  pick(2) ? GL_COLOR_ATTACHMENT1 : GL_DEPTH_STENCIL_ATTACHMENT,
                                  GL_RENDERBUFFER, rb[pick(2)]);
        break;
      case 7: glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT); break;
      case 8:
        glBlitFramebuffer(pick(20) - 4, pick(20) - 4, pick(20), pick(20), pick(40) - 8, pick(40) - 8,
                          pick(40), pick(40), GL_COLOR_BUFFER_BIT | (pick(2) ? GL_DEPTH_BUFFER_BIT : 0),
                          GL_NEAREST);
        break;
      case 9: {
        std::vector<float> out(64 * 64 * 4);
        glReadPixels(pick(10) - 2, pick(10) - 2, pick(9), pick(9), GL_RGBA, GL_FLOAT, out.data());
        glGetTexImage(GL_TEXTURE_2D, pick(3), GL_RGBA, GL_FLOAT, out.data());
        break;
      }
      case 10:
        if (pick(4) == 0) {
          const GLuint t = tex[pick(4)];
          glDeleteTextures(1, &t);
          glGenTextures(1, &tex[pick(4)]);
        } else {
          glGenerateMipmap(GL_TEXTURE_2D);
        }
        break;
      case 11: {
        const GLenum bufs[3] = {GL_COLOR_ATTACHMENT0, GLenum(pick(2) ? GL_NONE : GL_COLOR_ATTACHMENT2),
                                GL_COLOR_ATTACHMENT1};
        glDrawBuffers(pick(4), bufs);
        glCheckFramebufferStatus(GL_FRAMEBUFFER);
        break;
      }
    }
    const GLenum e = glGetError();
    EXPECT_TRUE(e == GL_NO_ERROR || e == GL_INVALID_ENUM || e == GL_INVALID_VALUE ||
                e == GL_INVALID_OPERATION || e == GL_INVALID_FRAMEBUFFER_OPERATION)
        << "step " << step << " error " << std::hex << e;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glFinish();
}

}  // namespace
