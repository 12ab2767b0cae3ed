/*
 * LearnOpenGL's "blending" chapter as a GLFW + glad program: an opaque floor and two opaque
 * marble cubes, grass quads whose texture is cut out by the chapter's alpha test
 * (`if (texColor.a < 0.1) discard;`, GL_CLAMP_TO_EDGE so the top row does not bleed), and
 * semi-transparent tinted window quads sorted back to front by their distance to the camera on
 * the CPU and blended with glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) with depth writes
 * on. Blending is enabled for the whole frame, as in the chapter. The cubes are wound clockwise
 * and drawn with face culling on (glEnable(GL_CULL_FACE), glCullFace(GL_BACK),
 * glFrontFace(GL_CW)), so the faces that survive are the ones facing the camera. RGBA8 textures
 * generated in code, all mipmapped (GL_LINEAR_MIPMAP_LINEAR). 3.3 core.
 */
#include "loader.h"
// clang-format off (the order matters)
#include <GLFW/glfw3.h>
#include "util.h"
// clang-format on

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 320
#define H 240

static const char* vs =
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
static const char* fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec2 TexCoords;\n"
    "uniform sampler2D texture1;\n"
    "uniform vec4 tint;\n"
    "void main() {\n"
    "  vec4 texColor = texture(texture1, TexCoords) * tint;\n"
    "  if (texColor.a < 0.1)\n"
    "    discard;\n"
    "  FragColor = texColor;\n"
    "}\n";

static void framebuffer_size_callback(GLFWwindow* window, int width, int height) {
  (void)window;
  glViewport(0, 0, width, height);
}

static GLuint make_texture(const unsigned char* texels, int size, GLenum wrap) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return t;
}

int main(void) {
  static const float face[6][2] = {{-0.5f, -0.5f}, {0.5f, 0.5f},   {0.5f, -0.5f},
                                   {0.5f, 0.5f},   {-0.5f, -0.5f}, {-0.5f, 0.5f}};
  /* The floor (texture coordinates past 1 repeat) and the chapter's transparent quad. */
  static const float planeVertices[] = {5.0f,  -0.5f, 5.0f,  2.0f, 0.0f, -5.0f, -0.5f, 5.0f,  0.0f, 0.0f,
                                        -5.0f, -0.5f, -5.0f, 0.0f, 2.0f, 5.0f,  -0.5f, 5.0f,  2.0f, 0.0f,
                                        -5.0f, -0.5f, -5.0f, 0.0f, 2.0f, 5.0f,  -0.5f, -5.0f, 2.0f, 2.0f};
  static const float transparentVertices[] = {0.0f, 0.5f,  0.0f, 0.0f, 0.0f, 0.0f, -0.5f, 0.0f, 0.0f, 1.0f,
                                              1.0f, -0.5f, 0.0f, 1.0f, 1.0f, 0.0f, 0.5f,  0.0f, 0.0f, 0.0f,
                                              1.0f, -0.5f, 0.0f, 1.0f, 1.0f, 1.0f, 0.5f,  0.0f, 1.0f, 0.0f};
  static const float vegetation[4][3] = {
      {-1.55f, 0.0f, -0.43f}, {1.15f, 0.0f, 0.63f}, {-0.85f, 0.0f, 0.93f}, {0.47f, 0.0f, -2.05f}};
  static const float windows[5][3] = {{-0.33f, 0.0f, -2.27f},
                                      {0.52f, 0.0f, -0.58f},
                                      {0.04f, 0.0f, 0.71f},
                                      {-1.05f, 0.0f, 0.13f},
                                      {1.62f, 0.0f, -1.24f}};
  static const float window_tints[5][4] = {{1.0f, 1.0f, 1.0f, 1.0f},
                                           {0.4f, 1.0f, 0.5f, 1.0f},
                                           {1.0f, 1.0f, 1.0f, 0.9f},
                                           {0.5f, 0.6f, 1.0f, 1.0f},
                                           {1.0f, 0.9f, 0.3f, 0.8f}};
  const float eye[3] = {0.31f, 0.93f, 4.27f}, center[3] = {0.07f, -0.19f, -0.55f}, up[3] = {0.0f, 1.0f, 0.0f};
  float cubeVertices[36 * 5];
  static unsigned char metal[64 * 64 * 4], marble[64 * 64 * 4], grass[64 * 64 * 4], glass[64 * 64 * 4];
  GLuint vao[3], vbo[3], floorTexture, cubeTexture, grassTexture, windowTexture, shader;
  int f, k, i, x, y, order[5];
  float dist[5];
  GLFWwindow* window;

  glfwInit();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  window = glfwCreateWindow(W, H, "LearnOpenGL", NULL, NULL);
  if (window == NULL) return -1;
  glfwMakeContextCurrent(window);
  glfwSetFramebufferSizeCallback(window, framebuffer_size_callback);
  if (!load_gl(glfwGetProcAddress)) return -1;

  glEnable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  shader = link_program(vs, fs);

  /* A cube whose faces are all wound clockwise seen from outside. */
  for (f = 0; f < 6; ++f)
    for (k = 0; k < 6; ++k) {
      float* o = &cubeVertices[(f * 6 + k) * 5];
      const float a = face[k][0], b = face[k][1];
      switch (f) {
        case 0: o[0] = a, o[1] = b, o[2] = 0.5f; break;
        case 1: o[0] = -a, o[1] = b, o[2] = -0.5f; break;
        case 2: o[0] = 0.5f, o[1] = b, o[2] = -a; break;
        case 3: o[0] = -0.5f, o[1] = b, o[2] = a; break;
        case 4: o[0] = a, o[1] = 0.5f, o[2] = -b; break;
        default: o[0] = a, o[1] = -0.5f, o[2] = b; break;
      }
      o[3] = a + 0.5f, o[4] = b + 0.5f;
    }
  glGenVertexArrays(3, vao);
  glGenBuffers(3, vbo);
  for (i = 0; i < 3; ++i) {
    const float* data = i == 0 ? cubeVertices : i == 1 ? planeVertices : transparentVertices;
    const GLsizeiptr size = i == 0   ? (GLsizeiptr)sizeof cubeVertices
                            : i == 1 ? (GLsizeiptr)sizeof planeVertices
                                     : (GLsizeiptr)sizeof transparentVertices;
    glBindVertexArray(vao[i]);
    glBindBuffer(GL_ARRAY_BUFFER, vbo[i]);
    glBufferData(GL_ARRAY_BUFFER, size, data, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)0);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)(3 * sizeof(float)));
  }
  glBindVertexArray(0);

  /* The chapter's images, generated: brushed metal plates, marble, grass blades on a transparent
   * background (row 0 at the top, as the chapter's quad expects) and a stained-glass pane. */
  for (y = 0; y < 64; ++y)
    for (x = 0; x < 64; ++x) {
      const int i4 = (y * 64 + x) * 4, plate = (x % 32 < 2) || (y % 32 < 2);
      const double vein = sin(x * 0.23 + 3.0 * sin(y * 0.19) + 1.4 * sin((x + y) * 0.11));
      const double t = y / 63.0;
      int blade, a = 0;
      metal[i4 + 0] = metal[i4 + 1] = (unsigned char)(plate ? 70 : 140 + (x * 13 + y * 3) % 25);
      metal[i4 + 2] = (unsigned char)(plate ? 80 : 150 + (x * 13 + y * 3) % 25);
      marble[i4 + 0] = (unsigned char)(205 + 40 * vein);
      marble[i4 + 1] = (unsigned char)(200 + 40 * vein);
      marble[i4 + 2] = (unsigned char)(190 + 30 * vein);
      /* Five tapered, leaning blades: each covers |x - centre(y)| < width(y). */
      for (blade = 0; blade < 5; ++blade) {
        const double base = 9.3 + blade * 11.2, lean = (blade % 2 ? 7.0 : -5.0) * (1.0 - t) * (1.0 - t);
        const double top = 0.12 + 0.13 * (blade % 3), width = 4.3 * (t - top) / (1.0 - top);
        if (t > top && fabs(x + 0.5 - base - lean) < width) a = 255;
      }
      grass[i4 + 0] = (unsigned char)(40 + 40 * t);
      grass[i4 + 1] = (unsigned char)(150 - 60 * t);
      grass[i4 + 2] = (unsigned char)(30 + (x * 7) % 20);
      grass[i4 + 3] = (unsigned char)a;
      {
        const int frame = x < 4 || x > 59 || y < 4 || y > 59 || (x > 30 && x < 33) || (y > 30 && y < 33);
        glass[i4 + 0] = (unsigned char)(frame ? 90 : 235);
        glass[i4 + 1] = (unsigned char)(frame ? 20 : 200 + (x + y) % 30);
        glass[i4 + 2] = (unsigned char)(frame ? 25 : 215);
        glass[i4 + 3] = (unsigned char)(frame ? 255 : 110 + (int)(40 * sin(x * 0.3 - y * 0.2)));
      }
      metal[i4 + 3] = marble[i4 + 3] = 255;
    }
  floorTexture = make_texture(metal, 64, GL_REPEAT);
  cubeTexture = make_texture(marble, 64, GL_REPEAT);
  grassTexture = make_texture(grass, 64, GL_CLAMP_TO_EDGE);
  windowTexture = make_texture(glass, 64, GL_CLAMP_TO_EDGE);
  glUseProgram(shader);
  glUniform1i(glGetUniformLocation(shader, "texture1"), 0);

  while (!glfwWindowShouldClose(window)) {
    float view[16], projection[16], model[16];
    /* Sort the windows by distance to the camera, farthest first (the chapter's std::map). */
    for (i = 0; i < 5; ++i) {
      const float dx = eye[0] - windows[i][0], dy = eye[1] - windows[i][1], dz = eye[2] - windows[i][2];
      dist[i] = sqrtf(dx * dx + dy * dy + dz * dz);
      for (k = i; k > 0 && dist[order[k - 1]] < dist[i]; --k) order[k] = order[k - 1];
      order[k] = i;
    }

    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(shader);
    mat_perspective(projection, 45.0f, (float)W / (float)H, 0.1f, 100.0f);
    mat_lookat(view, eye[0], eye[1], eye[2], center[0], center[1], center[2], up[0], up[1], up[2]);
    glUniformMatrix4fv(glGetUniformLocation(shader, "view"), 1, GL_FALSE, view);
    glUniformMatrix4fv(glGetUniformLocation(shader, "projection"), 1, GL_FALSE, projection);
    glUniform4f(glGetUniformLocation(shader, "tint"), 1.0f, 1.0f, 1.0f, 1.0f);
    glActiveTexture(GL_TEXTURE0);

    /* cubes, with back faces culled */
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CW);
    glBindVertexArray(vao[0]);
    glBindTexture(GL_TEXTURE_2D, cubeTexture);
    mat_identity(model);
    mat_mul_translate(model, -1.0f, 0.01f, -1.0f);
    mat_mul_rotate(model, 27.0f, 0.0f, 1.0f, 0.0f);
    glUniformMatrix4fv(glGetUniformLocation(shader, "model"), 1, GL_FALSE, model);
    glDrawArrays(GL_TRIANGLES, 0, 36);
    mat_identity(model);
    mat_mul_translate(model, 1.9f, 0.01f, 0.05f);
    mat_mul_rotate(model, -14.0f, 0.0f, 1.0f, 0.0f);
    glUniformMatrix4fv(glGetUniformLocation(shader, "model"), 1, GL_FALSE, model);
    glDrawArrays(GL_TRIANGLES, 0, 36);
    glDisable(GL_CULL_FACE);

    /* floor */
    glBindVertexArray(vao[1]);
    glBindTexture(GL_TEXTURE_2D, floorTexture);
    mat_identity(model);
    glUniformMatrix4fv(glGetUniformLocation(shader, "model"), 1, GL_FALSE, model);
    glDrawArrays(GL_TRIANGLES, 0, 6);

    /* vegetation: alpha-tested */
    glBindVertexArray(vao[2]);
    glBindTexture(GL_TEXTURE_2D, grassTexture);
    for (i = 0; i < 4; ++i) {
      mat_identity(model);
      mat_mul_translate(model, vegetation[i][0], vegetation[i][1], vegetation[i][2]);
      mat_mul_rotate(model, 8.0f - 13.0f * (float)i, 0.0f, 1.0f, 0.0f);
      glUniformMatrix4fv(glGetUniformLocation(shader, "model"), 1, GL_FALSE, model);
      glDrawArrays(GL_TRIANGLES, 0, 6);
    }

    /* windows: blended, back to front */
    glBindTexture(GL_TEXTURE_2D, windowTexture);
    for (i = 0; i < 5; ++i) {
      const int w = order[i];
      mat_identity(model);
      mat_mul_translate(model, windows[w][0], windows[w][1], windows[w][2]);
      glUniformMatrix4fv(glGetUniformLocation(shader, "model"), 1, GL_FALSE, model);
      glUniform4fv(glGetUniformLocation(shader, "tint"), 1, window_tints[w]);
      glDrawArrays(GL_TRIANGLES, 0, 6);
    }

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
