/*
 * A GLFW + glad-style program in the shape of LearnOpenGL's "coordinate systems" chapter: a
 * 3.3 core context from GLFW's hints, the framebuffer-size callback setting the viewport,
 * processInput with glfwGetKey, the render loop `while (!glfwWindowShouldClose(window))`.
 * Five cubes with a procedural RGB texture (two samplers on two units, mixed), model, view
 * and projection matrices as uniforms, depth testing, then a blended translucent quad.
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
    "layout (location = 1) in vec2 aTexCoord;\n"
    "out vec2 TexCoord;\n"
    "uniform mat4 model;\n"
    "uniform mat4 view;\n"
    "uniform mat4 projection;\n"
    "void main() {\n"
    "  gl_Position = projection * view * model * vec4(aPos, 1.0);\n"
    "  TexCoord = vec2(aTexCoord.x, aTexCoord.y);\n"
    "}\n";

static const char* fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec2 TexCoord;\n"
    "uniform sampler2D texture1;\n"
    "uniform sampler2D texture2;\n"
    "uniform float alpha;\n"
    "void main() {\n"
    "  FragColor = vec4(mix(texture(texture1, TexCoord), texture(texture2, TexCoord), 0.3).rgb, alpha);\n"
    "}\n";

static void framebuffer_size_callback(GLFWwindow* window, int width, int height) {
  (void)window;
  glViewport(0, 0, width, height);
}

static void processInput(GLFWwindow* window) {
  if (glfwGetKey(window, GLFW_KEY_ESCAPE) == GLFW_PRESS) glfwSetWindowShouldClose(window, 1);
}

static GLuint shader(GLenum type, const char* src) {
  GLuint s = glCreateShader(type);
  int ok = 0;
  glShaderSource(s, 1, &src, NULL);
  glCompileShader(s);
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024];
    glGetShaderInfoLog(s, sizeof log, NULL, log);
    fprintf(stderr, "ERROR::SHADER::COMPILATION_FAILED\n%s\n", log);
    exit(1);
  }
  return s;
}

/* Column-major 4x4 helpers (the glm calls the chapter uses). */
static void identity(float* m) {
  int i;
  for (i = 0; i < 16; ++i) m[i] = (i % 5 == 0) ? 1.0f : 0.0f;
}
static void multiply(float* out, const float* a, const float* b) {
  float r[16];
  int c, i, k;
  for (c = 0; c < 4; ++c)
    for (i = 0; i < 4; ++i) {
      float s = 0.0f;
      for (k = 0; k < 4; ++k) s += a[k * 4 + i] * b[c * 4 + k];
      r[c * 4 + i] = s;
    }
  memcpy(out, r, sizeof r);
}
static void translate(float* m, float x, float y, float z) {
  float t[16];
  identity(t);
  t[12] = x;
  t[13] = y;
  t[14] = z;
  multiply(m, m, t);
}
static void rotate(float* m, float deg, float x, float y, float z) {
  const float a = deg * 3.14159265f / 180.0f, c = cosf(a), s = sinf(a), l = sqrtf(x * x + y * y + z * z);
  float r[16];
  x /= l;
  y /= l;
  z /= l;
  identity(r);
  r[0] = c + x * x * (1 - c);
  r[1] = y * x * (1 - c) + z * s;
  r[2] = z * x * (1 - c) - y * s;
  r[4] = x * y * (1 - c) - z * s;
  r[5] = c + y * y * (1 - c);
  r[6] = z * y * (1 - c) + x * s;
  r[8] = x * z * (1 - c) + y * s;
  r[9] = y * z * (1 - c) - x * s;
  r[10] = c + z * z * (1 - c);
  multiply(m, m, r);
}
static void perspective(float* m, float fovy_deg, float aspect, float n, float f) {
  const float t = 1.0f / tanf(fovy_deg * 3.14159265f / 360.0f);
  memset(m, 0, 16 * sizeof(float));
  m[0] = t / aspect;
  m[5] = t;
  m[10] = (f + n) / (n - f);
  m[11] = -1.0f;
  m[14] = 2.0f * f * n / (n - f);
}

int main(void) {
  static const float face[6][5] = {{-0.5f, -0.5f, 0, 0, 0}, {0.5f, -0.5f, 0, 1, 0}, {0.5f, 0.5f, 0, 1, 1},
                                   {0.5f, 0.5f, 0, 1, 1},   {-0.5f, 0.5f, 0, 0, 1}, {-0.5f, -0.5f, 0, 0, 0}};
  static const float positions[5][3] = {{0.0f, 0.0f, 0.0f},
                                        {2.0f, 1.5f, -6.0f},
                                        {-1.5f, -1.2f, -2.5f},
                                        {-2.8f, 1.0f, -5.0f},
                                        {1.4f, -1.0f, -1.5f}};
  float vertices[36 * 5];
  unsigned char tex1[16 * 16 * 3], tex2[4 * 4 * 3];
  unsigned int VBO, VAO, textures[2], shaderProgram;
  int f, k, i, j;
  GLFWwindow* window;

  glfwInit();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  window = glfwCreateWindow(320, 240, "LearnOpenGL", NULL, NULL);
  if (window == NULL) {
    fprintf(stderr, "Failed to create GLFW window\n");
    glfwTerminate();
    return -1;
  }
  glfwMakeContextCurrent(window);
  glfwSetFramebufferSizeCallback(window, framebuffer_size_callback);
  if (!load_gl(glfwGetProcAddress)) {
    fprintf(stderr, "Failed to initialize GLAD\n");
    return -1;
  }
  glEnable(GL_DEPTH_TEST);

  {
    GLuint v = shader(GL_VERTEX_SHADER, vs), fr = shader(GL_FRAGMENT_SHADER, fs);
    int ok = 0;
    shaderProgram = glCreateProgram();
    glAttachShader(shaderProgram, v);
    glAttachShader(shaderProgram, fr);
    glLinkProgram(shaderProgram);
    glGetProgramiv(shaderProgram, GL_LINK_STATUS, &ok);
    if (!ok) return 1;
    glDeleteShader(v);
    glDeleteShader(fr);
  }

  /* A cube: one face turned to each of the six directions. */
  for (f = 0; f < 6; ++f)
    for (k = 0; k < 6; ++k) {
      float* o = &vertices[(f * 6 + k) * 5];
      const float x = face[k][0], y = face[k][1];
      switch (f) {
        case 0: o[0] = x, o[1] = y, o[2] = 0.5f; break;
        case 1: o[0] = -x, o[1] = y, o[2] = -0.5f; break;
        case 2: o[0] = 0.5f, o[1] = y, o[2] = -x; break;
        case 3: o[0] = -0.5f, o[1] = y, o[2] = x; break;
        case 4: o[0] = x, o[1] = 0.5f, o[2] = -y; break;
        default: o[0] = x, o[1] = -0.5f, o[2] = y; break;
      }
      o[3] = face[k][3];
      o[4] = face[k][4];
    }
  glGenVertexArrays(1, &VAO);
  glGenBuffers(1, &VBO);
  glBindVertexArray(VAO);
  glBindBuffer(GL_ARRAY_BUFFER, VBO);
  glBufferData(GL_ARRAY_BUFFER, sizeof(vertices), vertices, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)0);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)(3 * sizeof(float)));
  glEnableVertexAttribArray(1);

  /* A brick-like texture and a small coloured one (what the chapter loads from files). */
  for (j = 0; j < 16; ++j)
    for (i = 0; i < 16; ++i) {
      const int mortar = (j % 4 == 0) || ((i + ((j / 4) % 2) * 4) % 8 == 0);
      unsigned char* p = &tex1[(j * 16 + i) * 3];
      p[0] = (unsigned char)(mortar ? 200 : 150 + (i * 7) % 40);
      p[1] = (unsigned char)(mortar ? 200 : 60 + (j * 5) % 30);
      p[2] = (unsigned char)(mortar ? 190 : 40);
    }
  for (i = 0; i < 16; ++i) {
    tex2[i * 3] = (unsigned char)(i * 16);
    tex2[i * 3 + 1] = (unsigned char)(255 - i * 12);
    tex2[i * 3 + 2] = (unsigned char)((i % 2) * 255);
  }
  glGenTextures(2, textures);
  glBindTexture(GL_TEXTURE_2D, textures[0]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, tex1);
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, tex2);

  glUseProgram(shaderProgram);
  glUniform1i(glGetUniformLocation(shaderProgram, "texture1"), 0);
  glUniform1i(glGetUniformLocation(shaderProgram, "texture2"), 1);

  while (!glfwWindowShouldClose(window)) {
    float view[16], projection[16], model[16];
    processInput(window);
    glClearColor(0.2f, 0.3f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, textures[0]);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, textures[1]);
    glUseProgram(shaderProgram);
    identity(view);
    translate(view, 0.0f, 0.0f, -3.0f);
    perspective(projection, 45.0f, 320.0f / 240.0f, 0.1f, 100.0f);
    glUniformMatrix4fv(glGetUniformLocation(shaderProgram, "view"), 1, GL_FALSE, view);
    glUniformMatrix4fv(glGetUniformLocation(shaderProgram, "projection"), 1, GL_FALSE, projection);
    glUniform1f(glGetUniformLocation(shaderProgram, "alpha"), 1.0f);
    glBindVertexArray(VAO);
    for (i = 0; i < 5; ++i) {
      identity(model);
      translate(model, positions[i][0], positions[i][1], positions[i][2]);
      rotate(model, 20.0f * (float)i + 25.0f, 1.0f, 0.3f, 0.5f);
      glUniformMatrix4fv(glGetUniformLocation(shaderProgram, "model"), 1, GL_FALSE, model);
      glDrawArrays(GL_TRIANGLES, 0, 36);
    }
    /* A translucent pane in front, blended over what is there. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUniform1f(glGetUniformLocation(shaderProgram, "alpha"), 0.4f);
    identity(model);
    translate(model, 0.6f, 0.1f, 0.8f);
    glUniformMatrix4fv(glGetUniformLocation(shaderProgram, "model"), 1, GL_FALSE, model);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glDisable(GL_BLEND);
    if (glGetError() != GL_NO_ERROR) {
      fprintf(stderr, "GL error\n");
      return 1;
    }
    glfwSwapBuffers(window);
    glfwPollEvents();
  }
  glfwTerminate();
  return 0;
}
