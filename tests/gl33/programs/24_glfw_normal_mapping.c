/*
 * LearnOpenGL's "normal mapping" chapter as a GLFW + glad program: quads whose tangents and
 * bitangents are computed on the CPU from positions and UVs (the chapter's deltaUV formula),
 * five vertex attributes (position, normal, UV, tangent, bitangent), a TBN matrix built in
 * the vertex shader (normal matrix = transpose(inverse(mat3(model))), Gram-Schmidt, B from
 * cross(N, T) with the CPU bitangent's handedness) whose transpose moves the light and view
 * positions into tangent space, and Blinn-Phong in the fragment shader with the normal read
 * from a normal map (RGB = n * 0.5 + 0.5). The normal map (bevelled bricks with bumps) and
 * the diffuse map are generated procedurally and mipmapped. Three quads: plain UVs, mirrored
 * U (a left-handed tangent frame) and UVs turned by 90 degrees.
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
#define TEX 64

static const char* vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec3 aNormal;\n"
    "layout (location = 2) in vec2 aTexCoords;\n"
    "layout (location = 3) in vec3 aTangent;\n"
    "layout (location = 4) in vec3 aBitangent;\n"
    "out VS_OUT {\n"
    "  vec3 FragPos;\n"
    "  vec2 TexCoords;\n"
    "  vec3 TangentLightPos;\n"
    "  vec3 TangentViewPos;\n"
    "  vec3 TangentFragPos;\n"
    "} vs_out;\n"
    "uniform mat4 projection;\n"
    "uniform mat4 view;\n"
    "uniform mat4 model;\n"
    "uniform vec3 lightPos;\n"
    "uniform vec3 viewPos;\n"
    "void main() {\n"
    "  vs_out.FragPos = vec3(model * vec4(aPos, 1.0));\n"
    "  vs_out.TexCoords = aTexCoords;\n"
    "  mat3 normalMatrix = transpose(inverse(mat3(model)));\n"
    "  vec3 T = normalize(normalMatrix * aTangent);\n"
    "  vec3 N = normalize(normalMatrix * aNormal);\n"
    "  T = normalize(T - dot(T, N) * N);\n"
    "  vec3 B = cross(N, T);\n"
    "  if (dot(B, normalMatrix * aBitangent) < 0.0) B = -B;\n"
    "  mat3 TBN = transpose(mat3(T, B, N));\n"
    "  vs_out.TangentLightPos = TBN * lightPos;\n"
    "  vs_out.TangentViewPos = TBN * viewPos;\n"
    "  vs_out.TangentFragPos = TBN * vs_out.FragPos;\n"
    "  gl_Position = projection * view * model * vec4(aPos, 1.0);\n"
    "}\n";
static const char* fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in VS_OUT {\n"
    "  vec3 FragPos;\n"
    "  vec2 TexCoords;\n"
    "  vec3 TangentLightPos;\n"
    "  vec3 TangentViewPos;\n"
    "  vec3 TangentFragPos;\n"
    "} fs_in;\n"
    "uniform sampler2D diffuseMap;\n"
    "uniform sampler2D normalMap;\n"
    "void main() {\n"
    "  // obtain normal from normal map in range [0,1] and transform it to [-1,1]\n"
    "  vec3 normal = texture(normalMap, fs_in.TexCoords).rgb;\n"
    "  normal = normalize(normal * 2.0 - 1.0);\n"
    "  vec3 color = texture(diffuseMap, fs_in.TexCoords).rgb;\n"
    "  vec3 ambient = 0.1 * color;\n"
    "  vec3 lightDir = normalize(fs_in.TangentLightPos - fs_in.TangentFragPos);\n"
    "  float diff = max(dot(lightDir, normal), 0.0);\n"
    "  vec3 diffuse = diff * color;\n"
    "  vec3 viewDir = normalize(fs_in.TangentViewPos - fs_in.TangentFragPos);\n"
    "  vec3 halfwayDir = normalize(lightDir + viewDir);\n"
    "  float spec = pow(max(dot(normal, halfwayDir), 0.0), 32.0);\n"
    "  vec3 specular = vec3(0.2) * spec;\n"
    "  FragColor = vec4(ambient + diffuse + specular, 1.0);\n"
    "}\n";

static void framebuffer_size_callback(GLFWwindow* window, int width, int height) {
  (void)window;
  glViewport(0, 0, width, height);
}

/* Height of the brick relief at texel (x, y), periodic in both directions: bevelled bricks
 * (32x16 texels, a running bond) in 2-texel mortar, with a gentle bumpy surface. */
static float height(int x, int y) {
  const int row = ((y % TEX) + TEX) % TEX / 16, yy = ((y % TEX) + TEX) % TEX % 16;
  const int xx = (((x % TEX) + TEX) % TEX + (row % 2) * 16) % 32;
  const float dx = (float)(xx < 16 ? xx : 31 - xx), dy = (float)(yy < 8 ? yy : 15 - yy);
  const float d = (dx < dy ? dx : dy) - 1.0f;
  const float bevel = d <= 0.0f ? 0.0f : (d >= 3.0f ? 1.0f : d / 3.0f);
  return bevel * (1.0f + 0.12f * sinf((float)x * 0.9f + (float)row) * sinf((float)y * 1.3f));
}

int main(void) {
  static const float uv_sets[3][4][2] = {
      {{0.0f, 1.0f}, {0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}}, /* as the chapter */
      {{1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}, {0.0f, 1.0f}}, /* U mirrored */
      {{1.0f, 1.0f}, {0.0f, 1.0f}, {0.0f, 0.0f}, {1.0f, 0.0f}}, /* turned by 90 degrees */
  };
  float quads[3][6 * 14];
  static unsigned char normal_texels[TEX * TEX * 3], diffuse_texels[TEX * TEX * 3];
  GLFWwindow* window;
  GLuint vao[3], vbo[3], tex[2], prog;
  float projection[16], view[16];
  const float light_pos[3] = {0.6f, 0.9f, 1.3f}, view_pos[3] = {0.03f, 0.02f, 3.4f};
  int i, x, y;

  glfwInit();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  window = glfwCreateWindow(W, H, "LearnOpenGL", NULL, NULL);
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

  prog = link_program(vs, fs);

  glGenVertexArrays(3, vao);
  glGenBuffers(3, vbo);
  for (i = 0; i < 3; ++i) {
    mat_tangent_quad(quads[i], uv_sets[i]);
    glBindVertexArray(vao[i]);
    glBindBuffer(GL_ARRAY_BUFFER, vbo[i]);
    glBufferData(GL_ARRAY_BUFFER, sizeof quads[i], quads[i], GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 14 * sizeof(float), (void*)0);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 14 * sizeof(float), (void*)(3 * sizeof(float)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, 14 * sizeof(float), (void*)(6 * sizeof(float)));
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 3, GL_FLOAT, GL_FALSE, 14 * sizeof(float), (void*)(8 * sizeof(float)));
    glEnableVertexAttribArray(4);
    glVertexAttribPointer(4, 3, GL_FLOAT, GL_FALSE, 14 * sizeof(float), (void*)(11 * sizeof(float)));
  }

  /* The normal map from the height field's central differences, and the bricks' colours. */
  for (y = 0; y < TEX; ++y)
    for (x = 0; x < TEX; ++x) {
      unsigned char* n = &normal_texels[(y * TEX + x) * 3];
      unsigned char* c = &diffuse_texels[(y * TEX + x) * 3];
      const float strength = 2.5f;
      const float gx = (height(x + 1, y) - height(x - 1, y)) * 0.5f * strength;
      const float gy = (height(x, y + 1) - height(x, y - 1)) * 0.5f * strength;
      const float len = sqrtf(gx * gx + gy * gy + 1.0f);
      const float nv[3] = {-gx / len, -gy / len, 1.0f / len};
      const int row = y / 16, brick = (x + (row % 2) * 16) / 32 + row * 3;
      const int mortar = height(x, y) == 0.0f;
      for (i = 0; i < 3; ++i) n[i] = (unsigned char)((nv[i] * 0.5f + 0.5f) * 255.0f + 0.5f);
      c[0] = (unsigned char)(mortar ? 150 : 150 + (brick * 37) % 50 + (x * 3 + y * 5) % 13);
      c[1] = (unsigned char)(mortar ? 145 : 62 + (brick * 23) % 25);
      c[2] = (unsigned char)(mortar ? 135 : 45 + (brick * 11) % 15);
    }
  glGenTextures(2, tex);
  for (i = 0; i < 2; ++i) {
    glBindTexture(GL_TEXTURE_2D, tex[i]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEX, TEX, 0, GL_RGB, GL_UNSIGNED_BYTE,
                 i == 0 ? diffuse_texels : normal_texels);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  }

  glUseProgram(prog);
  glUniform1i(glGetUniformLocation(prog, "diffuseMap"), 0);
  glUniform1i(glGetUniformLocation(prog, "normalMap"), 1);
  mat_perspective(projection, 45.0f, (float)W / (float)H, 0.1f, 100.0f);
  mat_identity(view);
  mat_mul_translate(view, -view_pos[0], -view_pos[1], -view_pos[2]);

  while (!glfwWindowShouldClose(window)) {
    if (glfwGetKey(window, GLFW_KEY_ESCAPE) == GLFW_PRESS) glfwSetWindowShouldClose(window, 1);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(prog);
    glUniformMatrix4fv(glGetUniformLocation(prog, "projection"), 1, GL_FALSE, projection);
    glUniformMatrix4fv(glGetUniformLocation(prog, "view"), 1, GL_FALSE, view);
    glUniform3fv(glGetUniformLocation(prog, "viewPos"), 1, view_pos);
    glUniform3fv(glGetUniformLocation(prog, "lightPos"), 1, light_pos);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    for (i = 0; i < 3; ++i) {
      float model[16];
      mat_identity(model);
      if (i == 0) {
        /* the chapter's quad, turned (a fixed time) about normalize(1, 0, 1) */
        mat_mul_translate(model, 0.01f, 0.13f, 0.0f);
        mat_mul_rotate(model, -26.0f, 1.0f, 0.0f, 1.0f);
        mat_mul_scale(model, 0.78f, 0.78f, 0.78f);
      } else {
        mat_mul_translate(model, i == 1 ? -1.47f : 1.44f, -0.47f, -0.9f);
        mat_mul_rotate(model, i == 1 ? 38.0f : -41.0f, 0.0f, 1.0f, 0.0f);
        mat_mul_rotate(model, -12.0f, 1.0f, 0.0f, 0.0f);
        mat_mul_scale(model, 0.63f, 0.47f, 1.0f);
      }
      glUniformMatrix4fv(glGetUniformLocation(prog, "model"), 1, GL_FALSE, model);
      glBindVertexArray(vao[i]);
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
