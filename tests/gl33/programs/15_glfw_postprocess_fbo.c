/*
 * LearnOpenGL's "framebuffers" chapter as a GLFW + glad program: the scene (two textured
 * cubes on a floor) rendered into a framebuffer object with a colour texture and a
 * GL_DEPTH24_STENCIL8 renderbuffer, then a screen quad that runs the chapter's blur kernel
 * over the texture (nine taps at 1/300 offsets) on the left half and inverts the colours on
 * the right. A second FBO is filled by glBlitFramebuffer from the first at half size
 * (GL_LINEAR) and shown, one texel to a pixel, as an inset. 3.3 core.
 */
#include "loader.h"
// clang-format off (the order matters)
#include <GLFW/glfw3.h>
// clang-format on

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 320
#define H 240

static const char* scene_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec2 aTexCoords;\n"
    "out vec2 TexCoords;\n"
    "uniform mat4 model;\n"
    "uniform mat4 view;\n"
    "uniform mat4 projection;\n"
    "void main() {\n"
    "  TexCoords = aTexCoords;\n"
    "  gl_Position = projection * view * model * vec4(aPos, 1.0);\n"
    "}\n";
static const char* scene_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec2 TexCoords;\n"
    "uniform sampler2D texture1;\n"
    "void main() { FragColor = texture(texture1, TexCoords); }\n";
static const char* screen_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec2 aPos;\n"
    "layout (location = 1) in vec2 aTexCoords;\n"
    "out vec2 TexCoords;\n"
    "void main() {\n"
    "  TexCoords = aTexCoords;\n"
    "  gl_Position = vec4(aPos.x, aPos.y, 0.0, 1.0);\n"
    "}\n";
static const char* screen_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec2 TexCoords;\n"
    "uniform sampler2D screenTexture;\n"
    "uniform int effect;\n"
    "const float offset = 1.0 / 300.0;\n"
    "void main() {\n"
    "  if (effect == 1) { FragColor = vec4(vec3(1.0 - texture(screenTexture, TexCoords)), 1.0); return; }\n"
    "  if (effect == 2) { FragColor = texture(screenTexture, TexCoords); return; }\n"
    "  vec2 offsets[9] = vec2[](\n"
    "    vec2(-offset, offset), vec2(0.0f, offset), vec2(offset, offset),\n"
    "    vec2(-offset, 0.0f), vec2(0.0f, 0.0f), vec2(offset, 0.0f),\n"
    "    vec2(-offset, -offset), vec2(0.0f, -offset), vec2(offset, -offset));\n"
    "  float kernel[9] = float[](1.0 / 16, 2.0 / 16, 1.0 / 16, 2.0 / 16, 4.0 / 16, 2.0 / 16, 1.0 / 16, 2.0 / "
    "16, 1.0 / 16);\n"
    "  vec3 sampleTex[9];\n"
    "  for (int i = 0; i < 9; i++) sampleTex[i] = vec3(texture(screenTexture, TexCoords.st + offsets[i]));\n"
    "  vec3 col = vec3(0.0);\n"
    "  for (int i = 0; i < 9; i++) col += sampleTex[i] * kernel[i];\n"
    "  FragColor = vec4(col, 1.0);\n"
    "}\n";

static GLuint compile(GLenum type, const char* src) {
  GLuint s = glCreateShader(type);
  GLint ok = 0;
  glShaderSource(s, 1, &src, NULL);
  glCompileShader(s);
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(s, sizeof log, NULL, log);
    fprintf(stderr, "%s\n", log);
    exit(1);
  }
  return s;
}
static GLuint program(const char* v, const char* f) {
  GLuint p = glCreateProgram();
  glAttachShader(p, compile(GL_VERTEX_SHADER, v));
  glAttachShader(p, compile(GL_FRAGMENT_SHADER, f));
  glLinkProgram(p);
  return p;
}

static void perspective(float* m, float fovy, float aspect, float n, float f) {
  const float t = 1.0f / (float)tan(fovy * 3.14159265358979 / 360.0);
  memset(m, 0, 16 * sizeof(float));
  m[0] = t / aspect, m[5] = t, m[10] = (f + n) / (n - f), m[11] = -1.0f, m[14] = 2.0f * f * n / (n - f);
}
static void translate_rotate(float* m, float x, float y, float z, float deg) {
  const float a = (float)(deg * 3.14159265358979 / 180.0), c = (float)cos(a), s = (float)sin(a);
  memset(m, 0, 16 * sizeof(float));
  m[0] = c, m[2] = -s, m[5] = 1.0f, m[8] = s, m[10] = c, m[15] = 1.0f;
  m[12] = x, m[13] = y, m[14] = z;
}

static void framebuffer_size_callback(GLFWwindow* window, int width, int height) {
  (void)window;
  glViewport(0, 0, width, height);
}

int main(void) {
  static const float cube[] = {
      -0.5f, -0.5f, -0.5f, 0, 0, 0.5f,  -0.5f, -0.5f, 1, 0, 0.5f,  0.5f,  -0.5f, 1, 1,
      0.5f,  0.5f,  -0.5f, 1, 1, -0.5f, 0.5f,  -0.5f, 0, 1, -0.5f, -0.5f, -0.5f, 0, 0,
      -0.5f, -0.5f, 0.5f,  0, 0, 0.5f,  -0.5f, 0.5f,  1, 0, 0.5f,  0.5f,  0.5f,  1, 1,
      0.5f,  0.5f,  0.5f,  1, 1, -0.5f, 0.5f,  0.5f,  0, 1, -0.5f, -0.5f, 0.5f,  0, 0,
      -0.5f, 0.5f,  0.5f,  1, 0, -0.5f, 0.5f,  -0.5f, 1, 1, -0.5f, -0.5f, -0.5f, 0, 1,
      -0.5f, -0.5f, -0.5f, 0, 1, -0.5f, -0.5f, 0.5f,  0, 0, -0.5f, 0.5f,  0.5f,  1, 0,
      0.5f,  0.5f,  0.5f,  1, 0, 0.5f,  0.5f,  -0.5f, 1, 1, 0.5f,  -0.5f, -0.5f, 0, 1,
      0.5f,  -0.5f, -0.5f, 0, 1, 0.5f,  -0.5f, 0.5f,  0, 0, 0.5f,  0.5f,  0.5f,  1, 0,
      -0.5f, -0.5f, -0.5f, 0, 1, 0.5f,  -0.5f, -0.5f, 1, 1, 0.5f,  -0.5f, 0.5f,  1, 0,
      0.5f,  -0.5f, 0.5f,  1, 0, -0.5f, -0.5f, 0.5f,  0, 0, -0.5f, -0.5f, -0.5f, 0, 1,
      -0.5f, 0.5f,  -0.5f, 0, 1, 0.5f,  0.5f,  -0.5f, 1, 1, 0.5f,  0.5f,  0.5f,  1, 0,
      0.5f,  0.5f,  0.5f,  1, 0, -0.5f, 0.5f,  0.5f,  0, 0, -0.5f, 0.5f,  -0.5f, 0, 1};
  static const float plane[] = {5.0f,  -0.5f, 5.0f,  2.0f, 0.0f, -5.0f, -0.5f, 5.0f,  0.0f, 0.0f,
                                -5.0f, -0.5f, -5.0f, 0.0f, 2.0f, 5.0f,  -0.5f, 5.0f,  2.0f, 0.0f,
                                -5.0f, -0.5f, -5.0f, 0.0f, 2.0f, 5.0f,  -0.5f, -5.0f, 2.0f, 2.0f};
  static const float quad[] = {-1.0f, 1.0f, 0.0f, 1.0f, -1.0f, -1.0f, 0.0f, 0.0f, 1.0f, -1.0f, 1.0f, 0.0f,
                               -1.0f, 1.0f, 0.0f, 1.0f, 1.0f,  -1.0f, 1.0f, 0.0f, 1.0f, 1.0f,  1.0f, 1.0f};
  GLFWwindow* window;
  GLuint vao[3], vbo[3], tex[2], fbo, rbo, small_fbo, small_tex, scene_prog, screen_prog;
  float view[16], proj[16], model[16];
  int i, x, y;
  unsigned char texels[2][64 * 64 * 4];

  glfwInit();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  window = glfwCreateWindow(W, H, "LearnOpenGL", NULL, NULL);
  if (!window) return 1;
  glfwMakeContextCurrent(window);
  glfwSetFramebufferSizeCallback(window, framebuffer_size_callback);
  if (!load_gl(glfwGetProcAddress)) return 1;

  scene_prog = program(scene_vs, scene_fs);
  screen_prog = program(screen_vs, screen_fs);
  glGenVertexArrays(3, vao);
  glGenBuffers(3, vbo);
  for (i = 0; i < 3; ++i) {
    const float* data = i == 0 ? cube : i == 1 ? plane : quad;
    const GLsizeiptr size = i == 0   ? (GLsizeiptr)sizeof cube
                            : i == 1 ? (GLsizeiptr)sizeof plane
                                     : (GLsizeiptr)sizeof quad;
    const int n = i == 2 ? 2 : 3;
    glBindVertexArray(vao[i]);
    glBindBuffer(GL_ARRAY_BUFFER, vbo[i]);
    glBufferData(GL_ARRAY_BUFFER, size, data, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, n, GL_FLOAT, GL_FALSE, (n + 2) * (GLsizei)sizeof(float), (void*)0);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, (n + 2) * (GLsizei)sizeof(float),
                          (void*)(n * sizeof(float)));
  }
  /* Procedural textures: a brick-like pattern for the cubes, a checker for the floor. */
  for (y = 0; y < 64; ++y)
    for (x = 0; x < 64; ++x) {
      unsigned char* a = &texels[0][(y * 64 + x) * 4];
      unsigned char* b = &texels[1][(y * 64 + x) * 4];
      const int mortar = (y % 16 == 0) || ((x + (y / 16 % 2) * 16) % 32 == 0);
      a[0] = (unsigned char)(mortar ? 200 : 150 + (x * 7 + y * 3) % 40);
      a[1] = (unsigned char)(mortar ? 200 : 60 + (x * 5) % 30);
      a[2] = (unsigned char)(mortar ? 190 : 40);
      a[3] = 255;
      b[0] = b[1] = b[2] = (unsigned char)(((x / 8 + y / 8) % 2) ? 180 : 90);
      b[3] = 255;
    }
  glGenTextures(2, tex);
  for (i = 0; i < 2; ++i) {
    glBindTexture(GL_TEXTURE_2D, tex[i]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels[i]);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  }

  /* The chapter's framebuffer: a colour texture and a depth-stencil renderbuffer. */
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glGenTextures(1, &small_tex);
  {
    GLuint textureColorbuffer;
    glGenTextures(1, &textureColorbuffer);
    glBindTexture(GL_TEXTURE_2D, textureColorbuffer);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, W, H, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, textureColorbuffer, 0);
    glGenRenderbuffers(1, &rbo);
    glBindRenderbuffer(GL_RENDERBUFFER, rbo);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, W, H);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rbo);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      fprintf(stderr, "ERROR::FRAMEBUFFER:: Framebuffer is not complete!\n");
      return 1;
    }
    /* A half-size copy for the inset, made by a blit. */
    glGenFramebuffers(1, &small_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, small_fbo);
    glBindTexture(GL_TEXTURE_2D, small_tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W / 2, H / 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, small_tex, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    perspective(proj, 45.0f, (float)W / (float)H, 0.1f, 100.0f);
    translate_rotate(view, 0.0f, -0.3f, -3.5f, 20.0f);
    while (!glfwWindowShouldClose(window)) {
      /* 1. The scene into the framebuffer object. */
      glBindFramebuffer(GL_FRAMEBUFFER, fbo);
      glEnable(GL_DEPTH_TEST);
      glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glUseProgram(scene_prog);
      glUniformMatrix4fv(glGetUniformLocation(scene_prog, "view"), 1, GL_FALSE, view);
      glUniformMatrix4fv(glGetUniformLocation(scene_prog, "projection"), 1, GL_FALSE, proj);
      glUniform1i(glGetUniformLocation(scene_prog, "texture1"), 0);
      glActiveTexture(GL_TEXTURE0);
      glBindVertexArray(vao[0]);
      glBindTexture(GL_TEXTURE_2D, tex[0]);
      translate_rotate(model, -1.0f, 0.0f, -1.0f, 30.0f);
      glUniformMatrix4fv(glGetUniformLocation(scene_prog, "model"), 1, GL_FALSE, model);
      glDrawArrays(GL_TRIANGLES, 0, 36);
      translate_rotate(model, 2.0f, 0.0f, 0.0f, -15.0f);
      glUniformMatrix4fv(glGetUniformLocation(scene_prog, "model"), 1, GL_FALSE, model);
      glDrawArrays(GL_TRIANGLES, 0, 36);
      glBindVertexArray(vao[1]);
      glBindTexture(GL_TEXTURE_2D, tex[1]);
      translate_rotate(model, 0.0f, 0.0f, 0.0f, 0.0f);
      glUniformMatrix4fv(glGetUniformLocation(scene_prog, "model"), 1, GL_FALSE, model);
      glDrawArrays(GL_TRIANGLES, 0, 6);

      /* 2. A half-size copy by a linear blit. */
      glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, small_fbo);
      glBlitFramebuffer(0, 0, W, H, 0, 0, W / 2, H / 2, GL_COLOR_BUFFER_BIT, GL_LINEAR);

      /* 3. Back to the default framebuffer: the texture through the kernels. */
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glDisable(GL_DEPTH_TEST);
      glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      glUseProgram(screen_prog);
      glUniform1i(glGetUniformLocation(screen_prog, "screenTexture"), 0);
      glBindVertexArray(vao[2]);
      glBindTexture(GL_TEXTURE_2D, textureColorbuffer);
      glViewport(0, 0, W / 2, H);
      glUniform1i(glGetUniformLocation(screen_prog, "effect"), 0);
      glDrawArrays(GL_TRIANGLES, 0, 6);
      glViewport(W / 2, 0, W / 2, H);
      glUniform1i(glGetUniformLocation(screen_prog, "effect"), 1);
      glDrawArrays(GL_TRIANGLES, 0, 6);
      glViewport(W / 2 - 40, 8, W / 2, H / 2);
      glUniform1i(glGetUniformLocation(screen_prog, "effect"), 2);
      glBindTexture(GL_TEXTURE_2D, small_tex);
      glDrawArrays(GL_TRIANGLES, 0, 6);
      glViewport(0, 0, W, H);
      if (glGetError() != GL_NO_ERROR) {
        fprintf(stderr, "GL error\n");
        return 1;
      }
      glfwSwapBuffers(window);
      glfwPollEvents();
    }
  }
  glfwTerminate();
  return 0;
}
