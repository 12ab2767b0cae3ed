/*
 * A GLFW program with a mipmapped texture, as LearnOpenGL's texture chapter sets one up:
 * glTexImage2D of the base level, glGenerateMipmap, GL_LINEAR_MIPMAP_LINEAR minification.
 * A floor plane recedes to the horizon, so every level is sampled (with trilinear blending
 * between levels), and a wall with GL_NEAREST_MIPMAP_NEAREST stands on it. Indexed drawing
 * with 16-bit indices, a 3.3 core context.
 */
#include "loader.h"
// clang-format off (the order matters)
#include <GLFW/glfw3.h>
// clang-format on

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char* vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec2 aUV;\n"
    "uniform mat4 mvp;\n"
    "out vec2 uv;\n"
    "void main() { uv = aUV; gl_Position = mvp * vec4(aPos, 1.0); }\n";

static const char* fs =
    "#version 330 core\n"
    "in vec2 uv;\n"
    "out vec4 FragColor;\n"
    "uniform sampler2D tex;\n"
    "void main() { FragColor = texture(tex, uv); }\n";

static GLuint compile(GLenum type, const char* src) {
  GLuint s = glCreateShader(type);
  int ok = 0;
  glShaderSource(s, 1, &src, NULL);
  glCompileShader(s);
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) exit(1);
  return s;
}

int main(void) {
  /* Floor: a 40x40 quad at y = -1 with UVs repeating 20 times; wall: a quad at z = -6. */
  static const float verts[] = {
      -20.0f, -1.0f,  2.0f,  0.0f,   0.0f,  20.0f, -1.0f, 2.0f,  20.0f, 0.0f,  20.0f, -1.0f, -38.0f, 20.0f,
      20.0f,  -20.0f, -1.0f, -38.0f, 0.0f,  20.0f, -1.5f, -1.0f, -6.0f, 0.0f,  0.0f,  1.5f,  -1.0f,  -6.0f,
      3.0f,   0.0f,   1.5f,  1.5f,   -6.0f, 3.0f,  2.5f,  -1.5f, 1.5f,  -6.0f, 0.0f,  2.5f,
  };
  static const unsigned short idx[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
  unsigned char texels[64 * 64 * 3];
  float proj[16];
  GLuint vao, vbo, ebo, tex[2], prog, v, f;
  int ok = 0, i, j;
  GLFWwindow* window;

  if (!glfwInit()) return 1;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  window = glfwCreateWindow(320, 240, "mipmapped floor", NULL, NULL);
  if (!window) return 1;
  glfwMakeContextCurrent(window);
  if (!load_gl(glfwGetProcAddress)) return 1;

  prog = glCreateProgram();
  v = compile(GL_VERTEX_SHADER, vs);
  f = compile(GL_FRAGMENT_SHADER, fs);
  glAttachShader(prog, v);
  glAttachShader(prog, f);
  glLinkProgram(prog);
  glGetProgramiv(prog, GL_LINK_STATUS, &ok);
  if (!ok) return 1;

  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)0);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)(3 * sizeof(float)));
  glEnableVertexAttribArray(1);
  glGenBuffers(1, &ebo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);

  /* A checkerboard with coloured stripes: averaging it down changes colour level by level. */
  for (j = 0; j < 64; ++j)
    for (i = 0; i < 64; ++i) {
      unsigned char* p = &texels[(j * 64 + i) * 3];
      const int check = ((i / 8) + (j / 8)) % 2;
      p[0] = (unsigned char)(check ? 230 : 30);
      p[1] = (unsigned char)(check ? 200 : (i % 4 == 0 ? 220 : 40));
      p[2] = (unsigned char)(check ? 60 : (j % 4 == 0 ? 240 : 90));
    }
  glGenTextures(2, tex);
  for (i = 0; i < 2; ++i) {
    glBindTexture(GL_TEXTURE_2D, tex[i]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                    i == 0 ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  }

  /* A perspective camera 1.2 above the floor looking slightly down (column-major). */
  {
    const float t = 1.0f / tanf(50.0f * 3.14159265f / 360.0f), a = 320.0f / 240.0f, n = 0.1f, fa = 100.0f;
    const float c = cosf(0.12f), s = sinf(0.12f);
    float p[16], vw[16];
    int r, k, q;
    memset(p, 0, sizeof p);
    p[0] = t / a;
    p[5] = t;
    p[10] = (fa + n) / (n - fa);
    p[11] = -1.0f;
    p[14] = 2.0f * fa * n / (n - fa);
    memset(vw, 0, sizeof vw); /* rotate about x by 0.12 rad, then move the floor down 0.2 */
    vw[0] = 1.0f;
    vw[5] = c;
    vw[6] = -s;
    vw[9] = s;
    vw[10] = c;
    vw[13] = -0.2f;
    vw[15] = 1.0f;
    for (q = 0; q < 4; ++q)
      for (r = 0; r < 4; ++r) {
        float sum = 0.0f;
        for (k = 0; k < 4; ++k) sum += p[k * 4 + r] * vw[q * 4 + k];
        proj[q * 4 + r] = sum;
      }
  }

  glEnable(GL_DEPTH_TEST);
  while (!glfwWindowShouldClose(window)) {
    glClearColor(0.55f, 0.7f, 0.9f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(prog);
    glUniformMatrix4fv(glGetUniformLocation(prog, "mvp"), 1, GL_FALSE, proj);
    glUniform1i(glGetUniformLocation(prog, "tex"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(vao);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, (void*)0);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, (void*)(6 * sizeof(unsigned short)));
    if (glGetError() != GL_NO_ERROR) return 1;
    glfwSwapBuffers(window);
    glfwPollEvents();
  }
  glfwTerminate();
  return 0;
}
