/*
 * LearnOpenGL's "lighting maps" chapter as a GLFW + glad program: four rotated boxes lit by
 * Phong shading whose diffuse and specular colours come from two textures (a procedural
 * wooden crate with a steel rim and its specular map, RGBA8, glGenerateMipmap,
 * GL_LINEAR_MIPMAP_LINEAR, GL_REPEAT) on two texture units, through the chapter's
 * `struct Material { sampler2D diffuse; sampler2D specular; float shininess; }` and
 * `struct Light` uniforms set by name (material.diffuse, light.position, ...). The normal
 * matrix is computed in the vertex shader with transpose(inverse(model)). A small emissive
 * lamp cube at the light position is drawn with a second program. 3.3 core.
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

static const char* lighting_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec3 aNormal;\n"
    "layout (location = 2) in vec2 aTexCoords;\n"
    "out vec3 FragPos;\n"
    "out vec3 Normal;\n"
    "out vec2 TexCoords;\n"
    "uniform mat4 model;\n"
    "uniform mat4 view;\n"
    "uniform mat4 projection;\n"
    "void main() {\n"
    "  FragPos = vec3(model * vec4(aPos, 1.0));\n"
    "  Normal = mat3(transpose(inverse(model))) * aNormal;\n"
    "  TexCoords = aTexCoords;\n"
    "  gl_Position = projection * view * vec4(FragPos, 1.0);\n"
    "}\n";
static const char* lighting_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "struct Material {\n"
    "  sampler2D diffuse;\n"
    "  sampler2D specular;\n"
    "  float shininess;\n"
    "};\n"
    "struct Light {\n"
    "  vec3 position;\n"
    "  vec3 ambient;\n"
    "  vec3 diffuse;\n"
    "  vec3 specular;\n"
    "};\n"
    "in vec3 FragPos;\n"
    "in vec3 Normal;\n"
    "in vec2 TexCoords;\n"
    "uniform vec3 viewPos;\n"
    "uniform Material material;\n"
    "uniform Light light;\n"
    "void main() {\n"
    "  // ambient\n"
    "  vec3 ambient = light.ambient * texture(material.diffuse, TexCoords).rgb;\n"
    "  // diffuse\n"
    "  vec3 norm = normalize(Normal);\n"
    "  vec3 lightDir = normalize(light.position - FragPos);\n"
    "  float diff = max(dot(norm, lightDir), 0.0);\n"
    "  vec3 diffuse = light.diffuse * diff * texture(material.diffuse, TexCoords).rgb;\n"
    "  // specular\n"
    "  vec3 viewDir = normalize(viewPos - FragPos);\n"
    "  vec3 reflectDir = reflect(-lightDir, norm);\n"
    "  float spec = pow(max(dot(viewDir, reflectDir), 0.0), material.shininess);\n"
    "  vec3 specular = light.specular * spec * texture(material.specular, TexCoords).rgb;\n"
    "  FragColor = vec4(ambient + diffuse + specular, 1.0);\n"
    "}\n";
static const char* lamp_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "uniform mat4 model;\n"
    "uniform mat4 view;\n"
    "uniform mat4 projection;\n"
    "void main() { gl_Position = projection * view * model * vec4(aPos, 1.0); }\n";
static const char* lamp_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "uniform vec3 lampColor;\n"
    "void main() { FragColor = vec4(lampColor, 1.0); }\n";

static void framebuffer_size_callback(GLFWwindow* window, int width, int height) {
  (void)window;
  glViewport(0, 0, width, height);
}

int main(void) {
  static const float face[6][2] = {{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f},
                                   {0.5f, 0.5f},   {-0.5f, 0.5f}, {-0.5f, -0.5f}};
  static const float normals[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  static const float positions[4][3] = {
      {0.0f, 0.0f, 0.0f}, {-1.9f, 0.35f, -2.3f}, {1.7f, -0.45f, -1.6f}, {-1.3f, -1.1f, 0.8f}};
  float vertices[36 * 8];
  static unsigned char diffuse_map[128 * 128 * 4], specular_map[128 * 128 * 4];
  GLuint vbo, cube_vao, lamp_vao, tex[2], lighting_prog, lamp_prog;
  const float light_pos[3] = {0.8f, -1.25f, 1.35f};
  const float eye[3] = {0.35f, 1.25f, 4.6f}, center[3] = {-0.1f, -0.55f, -0.3f}, up[3] = {0.0f, 1.0f, 0.0f};
  int f, k, i, x, y;
  GLFWwindow* window;

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
  lighting_prog = link_program(lighting_vs, lighting_fs);
  lamp_prog = link_program(lamp_vs, lamp_fs);

  /* The chapter's cube: position, normal, texture coordinates; each face counter-clockwise. */
  for (f = 0; f < 6; ++f)
    for (k = 0; k < 6; ++k) {
      float* o = &vertices[(f * 6 + k) * 8];
      const float a = face[k][0], b = face[k][1];
      switch (f) {
        case 0: o[0] = a, o[1] = b, o[2] = 0.5f; break;
        case 1: o[0] = -a, o[1] = b, o[2] = -0.5f; break;
        case 2: o[0] = 0.5f, o[1] = b, o[2] = -a; break;
        case 3: o[0] = -0.5f, o[1] = b, o[2] = a; break;
        case 4: o[0] = a, o[1] = 0.5f, o[2] = -b; break;
        default: o[0] = a, o[1] = -0.5f, o[2] = b; break;
      }
      o[3] = normals[f][0], o[4] = normals[f][1], o[5] = normals[f][2];
      o[6] = a + 0.5f, o[7] = b + 0.5f;
    }
  glGenVertexArrays(1, &cube_vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof(vertices), vertices, GL_STATIC_DRAW);
  glBindVertexArray(cube_vao);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 8 * sizeof(float), (void*)0);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 8 * sizeof(float), (void*)(3 * sizeof(float)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, 8 * sizeof(float), (void*)(6 * sizeof(float)));
  glEnableVertexAttribArray(2);
  /* The lamp shares the buffer and reads positions only. */
  glGenVertexArrays(1, &lamp_vao);
  glBindVertexArray(lamp_vao);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 8 * sizeof(float), (void*)0);
  glEnableVertexAttribArray(0);

  /* "container2.png" and "container2_specular.png", generated: wooden planks with grain inside a
   * steel rim with rivets; the specular map is bright on the steel and almost black on the wood. */
  for (y = 0; y < 128; ++y)
    for (x = 0; x < 128; ++x) {
      unsigned char* d = &diffuse_map[(y * 128 + x) * 4];
      unsigned char* s = &specular_map[(y * 128 + x) * 4];
      const int ex = x < 127 - x ? x : 127 - x, ey = y < 127 - y ? y : 127 - y, edge = ex < ey ? ex : ey;
      const int rivet = ((ex - 6) * (ex - 6) + ((y % 32) - 16) * ((y % 32) - 16) < 10) ||
                        ((ey - 6) * (ey - 6) + ((x % 32) - 16) * ((x % 32) - 16) < 10);
      if (edge < 12 || rivet) {
        const int shade = 120 + (edge * 5) % 40 + (rivet ? 50 : 0);
        d[0] = (unsigned char)shade, d[1] = (unsigned char)(shade + 8), d[2] = (unsigned char)(shade + 20);
        s[0] = s[1] = s[2] = (unsigned char)(rivet ? 255 : 170 + (x * 3 + y * 5) % 60);
      } else {
        const int plank = (y - 12) / 26, grain = (int)(18.0 * sin(x * 0.21 + plank * 1.7 + y * 0.05));
        const int seam = (y - 12) % 26 < 2;
        d[0] = (unsigned char)(seam ? 70 : 160 + grain), d[1] = (unsigned char)(seam ? 40 : 100 + grain / 2);
        d[2] = (unsigned char)(seam ? 20 : 45);
        s[0] = s[1] = s[2] = (unsigned char)(seam ? 0 : 12 + (x * 7 + y * 11) % 20);
      }
      d[3] = s[3] = 255;
    }
  glGenTextures(2, tex);
  for (i = 0; i < 2; ++i) {
    glBindTexture(GL_TEXTURE_2D, tex[i]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 128, 128, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 i == 0 ? diffuse_map : specular_map);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  }

  glUseProgram(lighting_prog);
  glUniform1i(glGetUniformLocation(lighting_prog, "material.diffuse"), 0);
  glUniform1i(glGetUniformLocation(lighting_prog, "material.specular"), 1);

  while (!glfwWindowShouldClose(window)) {
    float view[16], projection[16], model[16];
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    mat_perspective(projection, 45.0f, (float)W / (float)H, 0.1f, 100.0f);
    mat_lookat(view, eye[0], eye[1], eye[2], center[0], center[1], center[2], up[0], up[1], up[2]);

    glUseProgram(lighting_prog);
    glUniform3fv(glGetUniformLocation(lighting_prog, "light.position"), 1, light_pos);
    glUniform3fv(glGetUniformLocation(lighting_prog, "viewPos"), 1, eye);
    glUniform3f(glGetUniformLocation(lighting_prog, "light.ambient"), 0.2f, 0.2f, 0.2f);
    glUniform3f(glGetUniformLocation(lighting_prog, "light.diffuse"), 0.5f, 0.5f, 0.5f);
    glUniform3f(glGetUniformLocation(lighting_prog, "light.specular"), 1.0f, 1.0f, 1.0f);
    glUniform1f(glGetUniformLocation(lighting_prog, "material.shininess"), 32.0f);
    glUniformMatrix4fv(glGetUniformLocation(lighting_prog, "projection"), 1, GL_FALSE, projection);
    glUniformMatrix4fv(glGetUniformLocation(lighting_prog, "view"), 1, GL_FALSE, view);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glBindVertexArray(cube_vao);
    for (i = 0; i < 4; ++i) {
      mat_identity(model);
      mat_mul_translate(model, positions[i][0], positions[i][1], positions[i][2]);
      mat_mul_rotate(model, 23.0f + 31.7f * (float)i, 1.0f, 0.3f + 0.2f * (float)i, 0.5f);
      if (i == 3) mat_mul_scale(model, 0.7f, 0.7f, 0.7f);
      glUniformMatrix4fv(glGetUniformLocation(lighting_prog, "model"), 1, GL_FALSE, model);
      glDrawArrays(GL_TRIANGLES, 0, 36);
    }

    /* The lamp: a small white cube at the light's position. */
    glUseProgram(lamp_prog);
    glUniformMatrix4fv(glGetUniformLocation(lamp_prog, "projection"), 1, GL_FALSE, projection);
    glUniformMatrix4fv(glGetUniformLocation(lamp_prog, "view"), 1, GL_FALSE, view);
    glUniform3f(glGetUniformLocation(lamp_prog, "lampColor"), 1.0f, 1.0f, 0.95f);
    mat_identity(model);
    mat_mul_translate(model, light_pos[0], light_pos[1], light_pos[2]);
    mat_mul_rotate(model, 17.0f, 0.2f, 1.0f, 0.1f);
    mat_mul_scale(model, 0.2f, 0.2f, 0.2f);
    glUniformMatrix4fv(glGetUniformLocation(lamp_prog, "model"), 1, GL_FALSE, model);
    glBindVertexArray(lamp_vao);
    glDrawArrays(GL_TRIANGLES, 0, 36);

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
