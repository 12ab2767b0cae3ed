/*
 * Logical operations (GL 3.3 §4.1.11) in a 3.3 core context (GLUT + GLEW): the sixteen
 * glLogicOp modes, each drawing a patterned square over a patterned background in the RGBA8
 * window (top two thirds: a 4x4 grid, GL_CLEAR at the lower left to GL_SET at the upper
 * right); blending is on as well, which GL_COLOR_LOGIC_OP turns off. Below, an offscreen
 * framebuffer with a GL_RGBA8UI, a GL_R16I and a GL_RGBA16F colour buffer is drawn twice, the
 * second time with GL_XOR, GL_INVERT, GL_OR_REVERSE ... on the integers at their stored
 * width (a uint value past 255 is clamped first, a negative int keeps its sign), while the
 * float buffer takes the fragment's value unblended. The three are shown through texelFetch.
 */
#include "common.h"

#define W 100
#define H 40

static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 position;\n"
    "void main() { gl_Position = vec4(position, 0.0, 1.0); }\n";

static const char* pattern_fs =
    "#version 330 core\n"
    "uniform int layer;  // 0: background, 1: the square drawn with the logic op\n"
    "layout(location = 0) out vec4 color;\n"
    "layout(location = 1) out uvec4 bytes;\n"
    "layout(location = 2) out int word;\n"
    "layout(location = 3) out vec4 wide;\n"
    "void main() {\n"
    "  ivec2 p = ivec2(gl_FragCoord.xy);\n"
    "  if (layer == 0) {\n"
    "    color = vec4(float(p.x % 20) / 19.0, float(p.y % 16) / 15.0, (p.x / 10 + p.y / 8) % 2 == 0 ? 0.8 : "
    "0.2, 0.5);\n"
    "    bytes = uvec4(uint(p.x) * 3u, uint(p.y) * 5u, uint(p.x ^ p.y), 77u);\n"
    "    word = (p.x - 50) * (p.y + 1) * 31;\n"
    "    wide = vec4(float(p.x) / 100.0, 0.25, 0.5, 1.0);\n"
    "  } else {\n"
    "    color = vec4(float(p.y % 10) / 9.0, 0.6, float(p.x % 7) / 6.0, 0.25);\n"
    "    bytes = uvec4(uint(p.y) * 9u, 0x5Au, uint(p.x) * 7u, 300u);  // 300: clamped to 255\n"
    "    word = p.x * 1000 - 40000;\n"
    "    wide = vec4(0.9, float(p.y) / 40.0, 0.1, 0.5);\n"
    "  }\n"
    "}\n";

static const char* show_fs =
    "#version 330 core\n"
    "uniform usampler2D bytes;\n"
    "uniform isampler2D words;\n"
    "uniform sampler2D wides;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  ivec2 q = ivec2(gl_FragCoord.xy);\n"
    "  int panel = q.x / 107;\n"
    "  ivec2 t = ivec2(min(q.x % 107, 99), q.y / 2);\n"
    "  vec3 c;\n"
    "  if (panel == 0) {\n"
    "    uvec4 b = texelFetch(bytes, t, 0);\n"
    "    c = vec3(b.rgb) / 255.0;\n"
    "    // alpha: 77 drawn once; 255 ^ 77 by XOR with 300 clamped, or by INVERT; 255 by OR_REVERSE\n"
    "    c *= b.a == 77u ? 0.5 : b.a == (255u ^ 77u) ? 1.0 : b.a == 255u ? 0.75 : 0.0;\n"
    "  } else if (panel == 1) {\n"
    "    int w = texelFetch(words, t, 0).r;\n"
    "    c = vec3(float(w & 255) / 255.0, float((w >> 8) & 255) / 255.0, w < 0 ? 1.0 : 0.0);\n"
    "  } else {\n"
    "    c = texelFetch(wides, t, 0).rgb;\n"
    "  }\n"
    "  frag = vec4(c, 1.0);\n"
    "}\n";

static GLuint pattern_prog, show_prog, vao, fbo, tex[4], layer_loc;

static void rect(float x0, float y0, float x1, float y1) {
  /* window pixels of the 320x240 window to clip coordinates, as two triangles */
  const float a = x0 / 160.0f - 1.0f, b = y0 / 120.0f - 1.0f, c = x1 / 160.0f - 1.0f, d = y1 / 120.0f - 1.0f;
  const float v[12] = {a, b, c, b, c, d, a, b, c, d, a, d};
  glBufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, 6);
}

static void display(void) {
  static const GLenum ops[16] = {
      GL_CLEAR, GL_AND,   GL_AND_REVERSE, GL_COPY,       GL_AND_INVERTED,  GL_NOOP,        GL_XOR,  GL_OR,
      GL_NOR,   GL_EQUIV, GL_INVERT,      GL_OR_REVERSE, GL_COPY_INVERTED, GL_OR_INVERTED, GL_NAND, GL_SET};
  static const GLenum fbo_ops[3] = {GL_XOR, GL_INVERT, GL_OR_REVERSE};
  static const GLenum buffers[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                    GL_COLOR_ATTACHMENT3};
  GLint op = 0, enabled = 0;
  int i;
  glBindVertexArray(vao);
  glUseProgram(pattern_prog);

  /* Offscreen: the background, then three bands with three operations (rect's coordinates
   * are the window's, scaled to the W x H viewport). */
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glDrawBuffers(4, buffers);
  glViewport(0, 0, W, H);
  glUniform1i((GLint)layer_loc, 0);
  rect(0, 0, 320, 240);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glEnable(GL_COLOR_LOGIC_OP);
  glUniform1i((GLint)layer_loc, 1);
  for (i = 0; i < 3; ++i) {
    glLogicOp(fbo_ops[i]);
    rect(320.0f * (float)i / 3.0f + 10.0f, 30.0f, 320.0f * (float)(i + 1) / 3.0f - 10.0f, 210.0f);
  }
  glDisable(GL_COLOR_LOGIC_OP);
  glDisable(GL_BLEND);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  /* The window: the sixteen operations over the background. */
  glViewport(0, 0, 320, 240);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glUniform1i((GLint)layer_loc, 0);
  rect(0, 80, 320, 240);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_COLOR_LOGIC_OP);
  glUniform1i((GLint)layer_loc, 1);
  for (i = 0; i < 16; ++i) {
    const float x = (float)(i % 4) * 80.0f, y = 80.0f + (float)(i / 4) * 40.0f;
    glLogicOp(ops[i]);
    rect(x + 10.0f, y + 6.0f, x + 70.0f, y + 34.0f);
  }
  glGetIntegerv(GL_LOGIC_OP_MODE, &op);
  glGetIntegerv(GL_COLOR_LOGIC_OP, &enabled);
  if (op != GL_SET || !enabled) fprintf(stderr, "logic op state: 0x%x %d\n", op, enabled);
  glDisable(GL_COLOR_LOGIC_OP);
  glDisable(GL_BLEND);

  /* The offscreen results, below. */
  for (i = 0; i < 3; ++i) {
    glActiveTexture(GL_TEXTURE0 + i);
    glBindTexture(GL_TEXTURE_2D, tex[i + 1]);
  }
  glUseProgram(show_prog);
  rect(0, 0, 320, 80);
  check_gl("display");
  glutSwapBuffers();
}

static GLuint texture(GLint internal, GLenum format, GLenum type) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, internal, W, H, 0, format, type, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}

int main(int argc, char** argv) {
  GLuint vbo;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "logic ops");
  pattern_prog = link_program(vs, pattern_fs);
  show_prog = link_program(vs, show_fs);
  layer_loc = (GLuint)glGetUniformLocation(pattern_prog, "layer");
  glUseProgram(show_prog);
  glUniform1i(glGetUniformLocation(show_prog, "bytes"), 0);
  glUniform1i(glGetUniformLocation(show_prog, "words"), 1);
  glUniform1i(glGetUniformLocation(show_prog, "wides"), 2);

  tex[0] = texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE);
  tex[1] = texture(GL_RGBA8UI, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE);
  tex[2] = texture(GL_R16I, GL_RED_INTEGER, GL_SHORT);
  tex[3] = texture(GL_RGBA16F, GL_RGBA, GL_FLOAT);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex[1], 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, tex[2], 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT3, GL_TEXTURE_2D, tex[3], 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    fprintf(stderr, "framebuffer incomplete\n");
    return 1;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glEnableVertexAttribArray(0);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
