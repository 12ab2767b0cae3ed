/*
 * Multisample textures (GL 3.2) in a 3.3 core context (GLUT + GLEW): a 4-sample RGBA8 texture
 * with a 4-sample depth renderbuffer as a framebuffer, drawn into with a full-window gradient
 * and a depth-tested second layer (no primitive edges inside, so every sample of a pixel holds
 * the same value: Tessel keeps one sample a pixel, and this program checks the plumbing, not
 * the antialiasing). Then, in four panels:
 *   texelFetch(sampler2DMS) of samples 0..3 across the panel, sized by textureSize
 *   the texture resolved into a single-sample texture with glBlitFramebuffer
 *   a 4-sample 2D array texture of two layers cleared to different colours
 *     (glFramebufferTextureLayer), read through sampler2DMSArray
 *   a 4-sample unsigned integer texture cleared with glClearBufferuiv, read through usampler2DMS
 * It checks what GL reports: GL_TEXTURE_SAMPLES, the fixed sample locations, framebuffer
 * completeness rules (GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE), glGetMultisamplefv and
 * glSampleMaski's state, and errors of a multisample target with the single-sample calls.
 */
#include "common.h"

#define W 320
#define H 240
#define S 64

static const char* quad_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 p;\n"
    "out vec2 uv;\n"
    "uniform float depth;\n"
    "void main() { uv = p * 0.5 + 0.5; gl_Position = vec4(p, depth, 1.0); }\n";
static const char* gradient_fs =
    "#version 330 core\n"
    "in vec2 uv;\n"
    "uniform vec3 tint;\n"
    "out vec4 c;\n"
    "void main() { c = vec4(uv.x * tint.x, uv.y * tint.y, 0.5 * tint.z + 0.25 * sin(uv.x * 9.0), 1.0); }\n";
static const char* fetch_fs =
    "#version 330 core\n"
    "in vec2 uv;\n"
    "uniform sampler2DMS ms;\n"
    "out vec4 c;\n"
    "void main() {\n"
    "  ivec2 size = textureSize(ms);\n"
    "  int s = int(uv.x * 4.0);\n"
    "  c = texelFetch(ms, ivec2(uv * vec2(size)), s);\n"
    "}\n";
static const char* show_fs =
    "#version 330 core\n"
    "in vec2 uv;\n"
    "uniform sampler2D tex;\n"
    "out vec4 c;\n"
    "void main() { c = texture(tex, uv); }\n";
static const char* layers_fs =
    "#version 330 core\n"
    "in vec2 uv;\n"
    "uniform sampler2DMSArray layers;\n"
    "uniform usampler2DMS counts;\n"
    "out vec4 c;\n"
    "void main() {\n"
    "  ivec3 size = textureSize(layers);\n"
    "  vec4 a = texelFetch(layers, ivec3(uv * vec2(size.xy), uv.y < 0.5 ? 0 : 1), 3);\n"
    "  uvec4 n = texelFetch(counts, ivec2(uv * vec2(textureSize(counts))), 1);\n"
    "  c = uv.x < 0.5 ? a : vec4(n) / 255.0;\n"
    "}\n";

static GLuint gradient, fetch, show, layers;
static GLuint quad_vao, ms_tex, ms_fbo, resolved_tex, resolved_fbo, array_tex, int_tex;

static void draw_quad(GLuint prog, float depth) {
  glUniform1f(glGetUniformLocation(prog, "depth"), depth);
  glBindVertexArray(quad_vao);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

static void display(void) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, W, H);
  glClearColor(0.05f, 0.05f, 0.08f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  glViewport(0, H / 2, W / 2, H / 2);
  glUseProgram(fetch);
  glUniform1i(glGetUniformLocation(fetch, "ms"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, ms_tex);
  draw_quad(fetch, 0.0f);
  glViewport(W / 2, H / 2, W / 2, H / 2);
  glUseProgram(show);
  glUniform1i(glGetUniformLocation(show, "tex"), 1);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, resolved_tex);
  draw_quad(show, 0.0f);
  glViewport(0, 0, W, H / 2);
  glUseProgram(layers);
  glUniform1i(glGetUniformLocation(layers, "layers"), 2);
  glUniform1i(glGetUniformLocation(layers, "counts"), 3);
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE_ARRAY, array_tex);
  glActiveTexture(GL_TEXTURE3);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, int_tex);
  draw_quad(layers, 0.0f);
  glActiveTexture(GL_TEXTURE0);
  check_gl("display");
  glutSwapBuffers();
}

static void expect(const char* what, GLint got, GLint want) {
  if (got != want) fprintf(stderr, "%s: %d (0x%x), expected %d (0x%x)\n", what, got, got, want, want);
}

int main(int argc, char** argv) {
  static const GLuint count_value[4] = {40, 120, 200, 255};
  GLuint depth_rb, layer_fbo, int_fbo, t2d, unfixed;
  GLint v = 0;
  GLfloat pos[2] = {0, 0};
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "multisample textures");
  gradient = link_program(quad_vs, gradient_fs);
  fetch = link_program(quad_vs, fetch_fs);
  show = link_program(quad_vs, show_fs);
  layers = link_program(quad_vs, layers_fs);
  quad_vao = window_strip();

  /* The multisample colour texture and depth renderbuffer. */
  glGenTextures(1, &ms_tex);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, ms_tex);
  glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GL_RGBA8, S, S, GL_TRUE);
  glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_SAMPLES, &v);
  expect("GL_TEXTURE_SAMPLES", v, 4);
  glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_FIXED_SAMPLE_LOCATIONS, &v);
  expect("GL_TEXTURE_FIXED_SAMPLE_LOCATIONS", v, GL_TRUE);
  glGetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &v);
  expect("GL_TEXTURE_BINDING_2D_MULTISAMPLE", v, (GLint)ms_tex);
  glTexParameteri(GL_TEXTURE_2D_MULTISAMPLE, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  expect("filter of a multisample texture", (GLint)glGetError(), GL_INVALID_ENUM);
  glGenerateMipmap(GL_TEXTURE_2D_MULTISAMPLE);
  expect("glGenerateMipmap of a multisample texture", (GLint)glGetError(), GL_INVALID_ENUM);
  glTexImage2D(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  expect("glTexImage2D of a multisample target", (GLint)glGetError(), GL_INVALID_ENUM);
  glGenRenderbuffers(1, &depth_rb);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_rb);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH_COMPONENT24, S, S);
  glGenFramebuffers(1, &ms_fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, ms_fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE, ms_tex, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb);
  expect("multisample framebuffer", (GLint)glCheckFramebufferStatus(GL_FRAMEBUFFER), GL_FRAMEBUFFER_COMPLETE);
  glGetIntegerv(GL_SAMPLES, &v);
  expect("GL_SAMPLES", v, 4);
  glGetMultisamplefv(GL_SAMPLE_POSITION, 1, pos);
  if (pos[0] <= 0.0f || pos[0] >= 1.0f || pos[1] <= 0.0f || pos[1] >= 1.0f)
    fprintf(stderr, "sample position %g %g\n", pos[0], pos[1]);
  glGetMultisamplefv(GL_SAMPLE_POSITION, 4, pos);
  expect("sample position 4", (GLint)glGetError(), GL_INVALID_VALUE);
  glSampleMaski(0, 0xF);
  glGetIntegeri_v(GL_SAMPLE_MASK_VALUE, 0, &v);
  expect("GL_SAMPLE_MASK_VALUE", v, 0xF);
  /* A texture without fixed sample locations beside the renderbuffer: incomplete. */
  glGenTextures(1, &unfixed);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, unfixed);
  glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GL_RGBA8, S, S, GL_FALSE);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D_MULTISAMPLE, unfixed, 0);
  expect("unfixed locations", (GLint)glCheckFramebufferStatus(GL_FRAMEBUFFER),
         GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D_MULTISAMPLE, 0, 0);
  /* A single-sample texture beside them: incomplete too. */
  glGenTextures(1, &t2d);
  glBindTexture(GL_TEXTURE_2D, t2d);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, S, S, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, t2d, 0);
  expect("mixed samples", (GLint)glCheckFramebufferStatus(GL_FRAMEBUFFER),
         GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, 0, 0);

  /* Drawn into: a gradient, and a tinted one in front where the depth test lets it. */
  glViewport(0, 0, S, S);
  glEnable(GL_DEPTH_TEST);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(gradient);
  glUniform3f(glGetUniformLocation(gradient, "tint"), 1.0f, 1.0f, 1.0f);
  draw_quad(gradient, 0.5f);
  glDepthFunc(GL_GREATER);
  glUniform3f(glGetUniformLocation(gradient, "tint"), 0.2f, 0.3f, 1.0f);
  draw_quad(gradient, 0.0f); /* behind the first: fails GL_LESS, passes GL_GREATER */
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);

  /* Resolved into a single-sample texture. */
  glGenTextures(1, &resolved_tex);
  glBindTexture(GL_TEXTURE_2D, resolved_tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, S, S, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glGenFramebuffers(1, &resolved_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_fbo);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, resolved_tex, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, ms_fbo);
  glBlitFramebuffer(0, 0, S, S, 0, 0, S, S, GL_COLOR_BUFFER_BIT, GL_NEAREST);

  /* A 4-sample array of two layers, each cleared through its own attachment. */
  glGenTextures(1, &array_tex);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE_ARRAY, array_tex);
  glTexImage3DMultisample(GL_TEXTURE_2D_MULTISAMPLE_ARRAY, 4, GL_RGBA8, 16, 16, 2, GL_TRUE);
  glGenFramebuffers(1, &layer_fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, layer_fbo);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, array_tex, 0, 0);
  glClearColor(0.9f, 0.4f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, array_tex, 0, 1);
  glClearColor(0.1f, 0.7f, 0.5f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  /* A 4-sample integer texture. */
  glGenTextures(1, &int_tex);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, int_tex);
  glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GL_RGBA8UI, 8, 8, GL_TRUE);
  glGenFramebuffers(1, &int_fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, int_fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE, int_tex, 0);
  expect("integer multisample framebuffer", (GLint)glCheckFramebufferStatus(GL_FRAMEBUFFER),
         GL_FRAMEBUFFER_COMPLETE);
  glClearBufferuiv(GL_COLOR, 0, count_value);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
