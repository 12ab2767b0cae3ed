/*
 * LearnOpenGL's "instancing" chapter (the asteroid field) as a GLFW + glad program: a textured
 * planet (a UV sphere built in code, glDrawElements) inside a ring of 3000 small rocks (a jittered
 * icosahedron built in code, smooth normals) drawn with ONE glDrawElementsInstanced call. Each
 * rock's model matrix is a per-instance mat4 vertex attribute in locations 3..6 (four vec4
 * columns, glVertexAttribPointer with a 64-byte stride, glVertexAttribDivisor(3..6, 1)); the
 * matrices come from the chapter's recipe (angle around the ring, random displacement, scale and
 * rotation) driven by a fixed LCG, never rand(). Both objects are lit by a directional light with
 * normals through mat3(model); RGBA8 procedural textures, mipmapped, GL_LINEAR_MIPMAP_LINEAR,
 * GL_REPEAT. 3.3 core.
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
#define AMOUNT 3000
#define SLICES 32
#define STACKS 16

static const char* planet_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec3 aNormal;\n"
    "layout (location = 2) in vec2 aTexCoords;\n"
    "out vec2 TexCoords;\n"
    "out vec3 Normal;\n"
    "uniform mat4 projection;\n"
    "uniform mat4 view;\n"
    "uniform mat4 model;\n"
    "void main() {\n"
    "  TexCoords = aTexCoords;\n"
    "  Normal = mat3(model) * aNormal;\n"
    "  gl_Position = projection * view * model * vec4(aPos, 1.0);\n"
    "}\n";
static const char* asteroid_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec3 aNormal;\n"
    "layout (location = 2) in vec2 aTexCoords;\n"
    "layout (location = 3) in mat4 aInstanceMatrix;\n"
    "out vec2 TexCoords;\n"
    "out vec3 Normal;\n"
    "uniform mat4 projection;\n"
    "uniform mat4 view;\n"
    "void main() {\n"
    "  TexCoords = aTexCoords;\n"
    "  Normal = mat3(aInstanceMatrix) * aNormal;\n"
    "  gl_Position = projection * view * aInstanceMatrix * vec4(aPos, 1.0);\n"
    "}\n";
static const char* fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec2 TexCoords;\n"
    "in vec3 Normal;\n"
    "uniform sampler2D texture_diffuse1;\n"
    "uniform vec3 lightDir;\n"
    "void main() {\n"
    "  float diff = max(dot(normalize(Normal), -lightDir), 0.0);\n"
    "  vec3 color = texture(texture_diffuse1, TexCoords).rgb;\n"
    "  FragColor = vec4(color * (0.12 + 0.88 * diff), 1.0);\n"
    "}\n";

/* A fixed linear congruential generator (Numerical Recipes constants): the same field on every
 * platform, unlike rand(). */
static unsigned int lcg_state = 12345u;
static float lcg01(void) {
  lcg_state = lcg_state * 1664525u + 1013904223u;
  return (float)(lcg_state >> 8) / 16777216.0f;
}

static void framebuffer_size_callback(GLFWwindow* window, int width, int height) {
  (void)window;
  glViewport(0, 0, width, height);
}

static GLuint make_texture(const unsigned char* texels, int w, int h) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return t;
}

/* One vertex layout for both meshes: position, normal, texture coordinates. */
static void setup_mesh(GLuint vao, GLuint vbo, GLuint ebo, const float* v, GLsizeiptr vsize,
                       const unsigned short* idx, GLsizeiptr isize) {
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, vsize, v, GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, isize, idx, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 8 * sizeof(float), (void*)0);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 8 * sizeof(float), (void*)(3 * sizeof(float)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, 8 * sizeof(float), (void*)(6 * sizeof(float)));
}

int main(void) {
  static const unsigned short ico_faces[20][3] = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  static float sphere[(SLICES + 1) * (STACKS + 1) * 8], rock[12 * 8], matrices[AMOUNT * 16];
  static unsigned short sphere_idx[SLICES * STACKS * 6], rock_idx[60];
  static unsigned char planet_tex[128 * 64 * 4], rock_tex[32 * 32 * 4];
  const float eye[3] = {0.6f, 7.3f, 27.1f}, center[3] = {0.3f, -1.4f, 0.2f}, up[3] = {0.0f, 1.0f, 0.0f};
  const float light_dir[3] = {-0.6247f, -0.3123f, -0.7157f};
  GLuint vao[2], vbo[3], ebo[2], tex[2], planet_prog, asteroid_prog;
  int i, j, k;
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
  planet_prog = link_program(planet_vs, fs);
  asteroid_prog = link_program(asteroid_vs, fs);

  /* The planet: a UV sphere of radius 1, the seam column duplicated for the texture. */
  for (j = 0; j <= STACKS; ++j)
    for (i = 0; i <= SLICES; ++i) {
      const float phi = 3.14159265f * (float)j / STACKS, theta = 6.2831853f * (float)i / SLICES;
      float* o = &sphere[(j * (SLICES + 1) + i) * 8];
      o[0] = o[3] = sinf(phi) * cosf(theta);
      o[1] = o[4] = cosf(phi);
      o[2] = o[5] = -sinf(phi) * sinf(theta);
      o[6] = (float)i / SLICES, o[7] = (float)j / STACKS;
    }
  for (j = 0, k = 0; j < STACKS; ++j)
    for (i = 0; i < SLICES; ++i) {
      const unsigned short a = (unsigned short)(j * (SLICES + 1) + i), b = (unsigned short)(a + SLICES + 1);
      sphere_idx[k++] = a, sphere_idx[k++] = b, sphere_idx[k++] = (unsigned short)(a + 1);
      sphere_idx[k++] = (unsigned short)(a + 1), sphere_idx[k++] = b,
      sphere_idx[k++] = (unsigned short)(b + 1);
    }
  /* The rock: an icosahedron with each vertex pushed in or out at random; normals averaged over
   * the faces around each vertex. */
  {
    static const float ico[12][3] = {{-1, 1.618034f, 0},  {1, 1.618034f, 0},   {-1, -1.618034f, 0},
                                     {1, -1.618034f, 0},  {0, -1, 1.618034f},  {0, 1, 1.618034f},
                                     {0, -1, -1.618034f}, {0, 1, -1.618034f},  {1.618034f, 0, -1},
                                     {1.618034f, 0, 1},   {-1.618034f, 0, -1}, {-1.618034f, 0, 1}};
    memset(rock, 0, sizeof rock);
    for (i = 0; i < 12; ++i) {
      const float r = (0.75f + 0.4f * lcg01()) / 1.9021131f;
      float* o = &rock[i * 8];
      o[0] = ico[i][0] * r, o[1] = ico[i][1] * r, o[2] = ico[i][2] * r;
      o[6] = 0.5f * o[0] + 0.3f * o[2] + 0.5f, o[7] = 0.5f * o[1] - 0.2f * o[2] + 0.5f;
    }
    for (i = 0; i < 20; ++i) {
      const float *p0 = &rock[ico_faces[i][0] * 8], *p1 = &rock[ico_faces[i][1] * 8],
                  *p2 = &rock[ico_faces[i][2] * 8];
      const float e1[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
      const float e2[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
      const float n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                          e1[0] * e2[1] - e1[1] * e2[0]};
      for (j = 0; j < 3; ++j) {
        float* o = &rock[ico_faces[i][j] * 8];
        o[3] += n[0], o[4] += n[1], o[5] += n[2];
        rock_idx[i * 3 + j] = ico_faces[i][j];
      }
    }
  }
  /* The chapter's ring: around the circle, a random offset in the plane and a little out of it,
   * a random scale and a random rotation about (0.4, 0.6, 0.8). */
  {
    const float radius = 12.5f, offset = 2.2f;
    for (i = 0; i < AMOUNT; ++i) {
      float* m = &matrices[i * 16];
      const float angle = 6.2831853f * (float)i / (float)AMOUNT;
      const float x = sinf(angle) * radius + (lcg01() * 2.0f - 1.0f) * offset;
      const float y = (lcg01() * 2.0f - 1.0f) * offset * 0.4f;
      const float z = cosf(angle) * radius + (lcg01() * 2.0f - 1.0f) * offset;
      const float s = 0.12f + 0.26f * lcg01(), rot = 360.0f * lcg01();
      mat_identity(m);
      mat_mul_translate(m, x, y, z);
      mat_mul_scale(m, s, s, s);
      mat_mul_rotate(m, rot, 0.4f, 0.6f, 0.8f);
    }
  }
  glGenVertexArrays(2, vao);
  glGenBuffers(3, vbo);
  glGenBuffers(2, ebo);
  setup_mesh(vao[0], vbo[0], ebo[0], sphere, sizeof sphere, sphere_idx, sizeof sphere_idx);
  setup_mesh(vao[1], vbo[1], ebo[1], rock, sizeof rock, rock_idx, sizeof rock_idx);
  /* The instance matrices: a mat4 attribute takes four locations, one vec4 column each. */
  glBindBuffer(GL_ARRAY_BUFFER, vbo[2]);
  glBufferData(GL_ARRAY_BUFFER, sizeof matrices, matrices, GL_STATIC_DRAW);
  for (i = 0; i < 4; ++i) {
    glEnableVertexAttribArray(3 + i);
    glVertexAttribPointer(3 + i, 4, GL_FLOAT, GL_FALSE, 16 * sizeof(float), (void*)(i * 4 * sizeof(float)));
    glVertexAttribDivisor(3 + i, 1);
  }
  glBindVertexArray(0);

  /* "planet.png": banded like a gas giant; "rock.png": grey-brown noise. */
  for (j = 0; j < 64; ++j)
    for (i = 0; i < 128; ++i) {
      unsigned char* p = &planet_tex[(j * 128 + i) * 4];
      const double band = sin(j * 0.55 + 1.3 * sin(i * 0.098 + j * 0.2)) * 0.5 + 0.5;
      p[0] = (unsigned char)(150 + 90 * band), p[1] = (unsigned char)(100 + 70 * band);
      p[2] = (unsigned char)(60 + 40 * (1.0 - band)), p[3] = 255;
    }
  for (i = 0; i < 32 * 32; ++i) {
    const int g = 110 + (int)(70.0f * lcg01());
    rock_tex[i * 4 + 0] = (unsigned char)g, rock_tex[i * 4 + 1] = (unsigned char)(g - 12);
    rock_tex[i * 4 + 2] = (unsigned char)(g - 28), rock_tex[i * 4 + 3] = 255;
  }
  tex[0] = make_texture(planet_tex, 128, 64);
  tex[1] = make_texture(rock_tex, 32, 32);

  while (!glfwWindowShouldClose(window)) {
    float view[16], projection[16], model[16];
    glClearColor(0.02f, 0.02f, 0.05f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    mat_perspective(projection, 45.0f, (float)W / (float)H, 0.1f, 100.0f);
    mat_lookat(view, eye[0], eye[1], eye[2], center[0], center[1], center[2], up[0], up[1], up[2]);
    glActiveTexture(GL_TEXTURE0);

    /* draw planet */
    glUseProgram(planet_prog);
    glUniformMatrix4fv(glGetUniformLocation(planet_prog, "projection"), 1, GL_FALSE, projection);
    glUniformMatrix4fv(glGetUniformLocation(planet_prog, "view"), 1, GL_FALSE, view);
    glUniform3fv(glGetUniformLocation(planet_prog, "lightDir"), 1, light_dir);
    glUniform1i(glGetUniformLocation(planet_prog, "texture_diffuse1"), 0);
    mat_identity(model);
    mat_mul_translate(model, 0.0f, -1.5f, 0.0f);
    mat_mul_rotate(model, 21.0f, 0.3f, 0.1f, 1.0f);
    mat_mul_scale(model, 4.0f, 4.0f, 4.0f);
    glUniformMatrix4fv(glGetUniformLocation(planet_prog, "model"), 1, GL_FALSE, model);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glBindVertexArray(vao[0]);
    glDrawElements(GL_TRIANGLES, SLICES * STACKS * 6, GL_UNSIGNED_SHORT, 0);

    /* draw meteorites: one instanced call */
    glUseProgram(asteroid_prog);
    glUniformMatrix4fv(glGetUniformLocation(asteroid_prog, "projection"), 1, GL_FALSE, projection);
    glUniformMatrix4fv(glGetUniformLocation(asteroid_prog, "view"), 1, GL_FALSE, view);
    glUniform3fv(glGetUniformLocation(asteroid_prog, "lightDir"), 1, light_dir);
    glUniform1i(glGetUniformLocation(asteroid_prog, "texture_diffuse1"), 0);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glBindVertexArray(vao[1]);
    glDrawElementsInstanced(GL_TRIANGLES, 60, GL_UNSIGNED_SHORT, 0, AMOUNT);
    glBindVertexArray(0);

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
