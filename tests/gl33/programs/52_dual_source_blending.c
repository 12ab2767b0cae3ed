/*
 * Dual-source blending (GL 3.3 §4.1.8) in a 3.3 core context (GLUT + GLEW): a fragment shader
 * with two outputs at location 0, index 0 and index 1 (layout qualifiers in one program,
 * glBindFragDataLocationIndexed in another), blended over a gradient with GL_SRC1_COLOR,
 * GL_ONE_MINUS_SRC1_COLOR, GL_SRC1_ALPHA and GL_ONE_MINUS_SRC1_ALPHA in the four ways text
 * renderers and per-channel coverage use them (one panel each), into the window and into an
 * RGBA16F framebuffer object blitted into the window beside them. It checks
 * GL_MAX_DUAL_SOURCE_DRAW_BUFFERS, glGetFragDataIndex and glGetFragDataLocation.
 */
#include "common.h"

#define W 320
#define H 240

static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 p;\n"
    "out vec2 uv;\n"
    "void main() { uv = p * 0.5 + 0.5; gl_Position = vec4(p, 0.0, 1.0); }\n";
static const char* background_fs =
    "#version 330 core\n"
    "in vec2 uv;\n"
    "out vec4 c;\n"
    "void main() { c = vec4(uv.x, 0.3 + 0.4 * uv.y, 1.0 - uv.x, 0.5 + 0.5 * uv.y); }\n";
/* Coverage per channel, as subpixel text rendering writes it. */
static const char* layout_fs =
    "#version 330 core\n"
    "in vec2 uv;\n"
    "layout(location = 0, index = 0) out vec4 colour;\n"
    "layout(location = 0, index = 1) out vec4 coverage;\n"
    "void main() {\n"
    "  vec2 d = uv - 0.5;\n"
    "  float r = length(d);\n"
    "  colour = vec4(0.95, 0.85, 0.2, 0.7);\n"
    "  coverage = vec4(smoothstep(0.45, 0.2, r), smoothstep(0.45, 0.25, r + 0.05 * d.x),\n"
    "                  smoothstep(0.45, 0.3, r - 0.05 * d.y), 1.0 - uv.y);\n"
    "}\n";
/* The same, its outputs placed with glBindFragDataLocationIndexed. */
static const char* bound_fs =
    "#version 330 core\n"
    "in vec2 uv;\n"
    "out vec4 colour;\n"
    "out vec4 weight;\n"
    "void main() {\n"
    "  colour = vec4(0.1, 0.3, 0.9, 1.0) * (0.5 + uv.x);\n"
    "  weight = vec4(uv.y, 1.0 - uv.y, 0.5, uv.x);\n"
    "}\n";

static GLuint background, layout_prog, bound_prog, quad_vao, fbo, fbo_tex;

static GLuint link_with(const char* fs, int bind) {
  GLuint p = glCreateProgram();
  GLuint v = compile_shader(GL_VERTEX_SHADER, vs), f = compile_shader(GL_FRAGMENT_SHADER, fs);
  GLint ok = 0;
  glAttachShader(p, v);
  glAttachShader(p, f);
  if (bind) {
    glBindFragDataLocationIndexed(p, 0, 0, "colour");
    glBindFragDataLocationIndexed(p, 0, 1, "weight");
  }
  glLinkProgram(p);
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetProgramInfoLog(p, sizeof log, NULL, log);
    fprintf(stderr, "link failed: %s\n", log);
    exit(1);
  }
  return p;
}

static void draw_panels(int x0, int y0, int w, int h) {
  static const GLenum funcs[4][2] = {{GL_SRC1_COLOR, GL_ONE_MINUS_SRC1_COLOR},
                                     {GL_ONE, GL_ONE_MINUS_SRC1_COLOR},
                                     {GL_SRC1_ALPHA, GL_ONE_MINUS_SRC1_ALPHA},
                                     {GL_ONE_MINUS_SRC1_ALPHA, GL_SRC1_COLOR}};
  int i;
  glBindVertexArray(quad_vao);
  for (i = 0; i < 4; ++i) {
    glViewport(x0 + (i % 2) * w, y0 + (i / 2) * h, w, h);
    glDisable(GL_BLEND);
    glUseProgram(background);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(funcs[i][0], funcs[i][1], GL_ONE, GL_ONE_MINUS_SRC1_ALPHA);
    glUseProgram(i < 2 ? layout_prog : bound_prog);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  glDisable(GL_BLEND);
}

static void display(void) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  draw_panels(0, 0, 106, 120);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  draw_panels(0, 0, 54, 60);
  /* The float framebuffer's panels, 1:1 in the window. */
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, 108, 120, 212, 60, 320, 180, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  GLint v = 0;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "dual-source blending");
  glGetIntegerv(GL_MAX_DUAL_SOURCE_DRAW_BUFFERS, &v);
  if (v < 1) fprintf(stderr, "GL_MAX_DUAL_SOURCE_DRAW_BUFFERS %d\n", v);
  background = link_program(vs, background_fs);
  layout_prog = link_with(layout_fs, 0);
  bound_prog = link_with(bound_fs, 1);
  if (glGetFragDataIndex(layout_prog, "coverage") != 1 || glGetFragDataIndex(layout_prog, "colour") != 0 ||
      glGetFragDataIndex(bound_prog, "weight") != 1 || glGetFragDataLocation(bound_prog, "weight") != 0 ||
      glGetFragDataIndex(bound_prog, "nothing") != -1)
    fprintf(stderr, "fragment data indices %d %d %d %d\n", glGetFragDataIndex(layout_prog, "coverage"),
            glGetFragDataIndex(layout_prog, "colour"), glGetFragDataIndex(bound_prog, "weight"),
            glGetFragDataLocation(bound_prog, "weight"));
  quad_vao = window_strip();
  glGenTextures(1, &fbo_tex);
  glBindTexture(GL_TEXTURE_2D, fbo_tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, 128, 128, 0, GL_RGBA, GL_FLOAT, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, fbo_tex, 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    fprintf(stderr, "FBO incomplete\n");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
