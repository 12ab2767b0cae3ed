/*
 * LearnOpenGL's "multiple lights" chapter as a GLFW + glad program: lit boxes on a floor slab
 * under a directional light, four coloured point lights held in a uniform array of structs
 * (pointLights[0].position ... with constant/linear/quadratic attenuation, set by name) and a
 * spotlight from the camera with a smooth edge between cutOff and outerCutOff. The fragment
 * shader is the chapter's: prototypes, then CalcDirLight/CalcPointLight/CalcSpotLight taking the
 * structs by value, a loop over the array. Diffuse and specular maps (procedural RGBA8 tiles,
 * mipmapped, GL_LINEAR_MIPMAP_LINEAR, GL_REPEAT with a texture-coordinate scale on the floor); the
 * floor is a non-uniformly scaled cube, so the normal matrix transpose(inverse(model)) matters.
 * The lamps are small cubes drawn with a second program in their lights' colours. 3.3 core.
 */
#include "loader.h"
// clang-format off (the order matters)
#include <GLFW/glfw3.h>
#include "util.h"
// clang-format on

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 320
#define H 240
#define NR_POINT_LIGHTS 4

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
    "uniform vec2 uvScale;\n"
    "void main() {\n"
    "  FragPos = vec3(model * vec4(aPos, 1.0));\n"
    "  Normal = mat3(transpose(inverse(model))) * aNormal;\n"
    "  TexCoords = aTexCoords * uvScale;\n"
    "  gl_Position = projection * view * vec4(FragPos, 1.0);\n"
    "}\n";
static const char* lighting_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "struct Material { sampler2D diffuse; sampler2D specular; float shininess; };\n"
    "struct DirLight { vec3 direction; vec3 ambient; vec3 diffuse; vec3 specular; };\n"
    "struct PointLight { vec3 position; float constant; float linear; float quadratic;\n"
    "  vec3 ambient; vec3 diffuse; vec3 specular; };\n"
    "struct SpotLight { vec3 position; vec3 direction; float cutOff; float outerCutOff;\n"
    "  float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };\n"
    "#define NR_POINT_LIGHTS 4\n"
    "in vec3 FragPos;\n"
    "in vec3 Normal;\n"
    "in vec2 TexCoords;\n"
    "uniform vec3 viewPos;\n"
    "uniform DirLight dirLight;\n"
    "uniform PointLight pointLights[NR_POINT_LIGHTS];\n"
    "uniform SpotLight spotLight;\n"
    "uniform Material material;\n"
    "// function prototypes\n"
    "vec3 CalcDirLight(DirLight light, vec3 normal, vec3 viewDir);\n"
    "vec3 CalcPointLight(PointLight light, vec3 normal, vec3 fragPos, vec3 viewDir);\n"
    "vec3 CalcSpotLight(SpotLight light, vec3 normal, vec3 fragPos, vec3 viewDir);\n"
    "void main() {\n"
    "  vec3 norm = normalize(Normal);\n"
    "  vec3 viewDir = normalize(viewPos - FragPos);\n"
    "  // phase 1: directional lighting\n"
    "  vec3 result = CalcDirLight(dirLight, norm, viewDir);\n"
    "  // phase 2: point lights\n"
    "  for (int i = 0; i < NR_POINT_LIGHTS; i++)\n"
    "    result += CalcPointLight(pointLights[i], norm, FragPos, viewDir);\n"
    "  // phase 3: spot light\n"
    "  result += CalcSpotLight(spotLight, norm, FragPos, viewDir);\n"
    "  FragColor = vec4(result, 1.0);\n"
    "}\n"
    "vec3 CalcDirLight(DirLight light, vec3 normal, vec3 viewDir) {\n"
    "  vec3 lightDir = normalize(-light.direction);\n"
    "  float diff = max(dot(normal, lightDir), 0.0);\n"
    "  vec3 reflectDir = reflect(-lightDir, normal);\n"
    "  float spec = pow(max(dot(viewDir, reflectDir), 0.0), material.shininess);\n"
    "  vec3 ambient = light.ambient * vec3(texture(material.diffuse, TexCoords));\n"
    "  vec3 diffuse = light.diffuse * diff * vec3(texture(material.diffuse, TexCoords));\n"
    "  vec3 specular = light.specular * spec * vec3(texture(material.specular, TexCoords));\n"
    "  return (ambient + diffuse + specular);\n"
    "}\n"
    "vec3 CalcPointLight(PointLight light, vec3 normal, vec3 fragPos, vec3 viewDir) {\n"
    "  vec3 lightDir = normalize(light.position - fragPos);\n"
    "  float diff = max(dot(normal, lightDir), 0.0);\n"
    "  vec3 reflectDir = reflect(-lightDir, normal);\n"
    "  float spec = pow(max(dot(viewDir, reflectDir), 0.0), material.shininess);\n"
    "  float distance = length(light.position - fragPos);\n"
    "  float attenuation = 1.0 / (light.constant + light.linear * distance +\n"
    "                             light.quadratic * (distance * distance));\n"
    "  vec3 ambient = light.ambient * vec3(texture(material.diffuse, TexCoords));\n"
    "  vec3 diffuse = light.diffuse * diff * vec3(texture(material.diffuse, TexCoords));\n"
    "  vec3 specular = light.specular * spec * vec3(texture(material.specular, TexCoords));\n"
    "  ambient *= attenuation;\n"
    "  diffuse *= attenuation;\n"
    "  specular *= attenuation;\n"
    "  return (ambient + diffuse + specular);\n"
    "}\n"
    "vec3 CalcSpotLight(SpotLight light, vec3 normal, vec3 fragPos, vec3 viewDir) {\n"
    "  vec3 lightDir = normalize(light.position - fragPos);\n"
    "  float diff = max(dot(normal, lightDir), 0.0);\n"
    "  vec3 reflectDir = reflect(-lightDir, normal);\n"
    "  float spec = pow(max(dot(viewDir, reflectDir), 0.0), material.shininess);\n"
    "  float distance = length(light.position - fragPos);\n"
    "  float attenuation = 1.0 / (light.constant + light.linear * distance +\n"
    "                             light.quadratic * (distance * distance));\n"
    "  // spotlight intensity, soft between the inner and the outer cone\n"
    "  float theta = dot(lightDir, normalize(-light.direction));\n"
    "  float epsilon = light.cutOff - light.outerCutOff;\n"
    "  float intensity = clamp((theta - light.outerCutOff) / epsilon, 0.0, 1.0);\n"
    "  vec3 ambient = light.ambient * vec3(texture(material.diffuse, TexCoords));\n"
    "  vec3 diffuse = light.diffuse * diff * vec3(texture(material.diffuse, TexCoords));\n"
    "  vec3 specular = light.specular * spec * vec3(texture(material.specular, TexCoords));\n"
    "  ambient *= attenuation * intensity;\n"
    "  diffuse *= attenuation * intensity;\n"
    "  specular *= attenuation * intensity;\n"
    "  return (ambient + diffuse + specular);\n"
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

/* The shader class's setVec3/setFloat, by uniform name. */
static void set_vec3(GLuint p, const char* name, float x, float y, float z) {
  glUniform3f(glGetUniformLocation(p, name), x, y, z);
}
static void set_float(GLuint p, const char* name, float v) { glUniform1f(glGetUniformLocation(p, name), v); }

int main(void) {
  static const float face[6][2] = {{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f},
                                   {0.5f, 0.5f},   {-0.5f, 0.5f}, {-0.5f, -0.5f}};
  static const float normals[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  static const float cubePositions[6][3] = {{0.0f, -0.45f, 0.0f},  {2.1f, 0.55f, -2.7f},
                                            {-1.6f, -0.3f, -1.9f}, {-2.3f, 0.9f, -4.1f},
                                            {1.45f, -0.6f, 1.2f},  {-0.65f, 1.15f, -3.3f}};
  static const float pointLightPositions[NR_POINT_LIGHTS][3] = {
      {0.85f, 0.35f, 1.6f}, {2.3f, -0.35f, -1.1f}, {-2.1f, 0.65f, -0.35f}, {0.15f, 1.45f, -2.2f}};
  static const float pointLightColors[NR_POINT_LIGHTS][3] = {
      {1.0f, 0.55f, 0.2f}, {0.25f, 0.85f, 0.35f}, {0.3f, 0.45f, 1.0f}, {1.0f, 0.3f, 0.7f}};
  float vertices[36 * 8];
  static unsigned char diffuse_map[128 * 128 * 4], specular_map[128 * 128 * 4];
  GLuint vbo, cube_vao, lamp_vao, tex[2], lighting_prog, lamp_prog;
  const float eye[3] = {0.55f, 1.65f, 5.3f}, center[3] = {-0.15f, -0.35f, -0.9f}, up[3] = {0.0f, 1.0f, 0.0f};
  const float spot_target[3] = {-0.95f, -1.43f, 0.85f};
  float spot_dir[3];
  int f, k, i, x, y;
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
  glGenVertexArrays(1, &lamp_vao);
  glBindVertexArray(lamp_vao);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 8 * sizeof(float), (void*)0);
  glEnableVertexAttribArray(0);

  /* Glazed tiles: 4x4 tiles of mottled colour in dark grout; the glaze is shiny, the grout not. */
  for (y = 0; y < 128; ++y)
    for (x = 0; x < 128; ++x) {
      unsigned char* d = &diffuse_map[(y * 128 + x) * 4];
      unsigned char* s = &specular_map[(y * 128 + x) * 4];
      const int tx = x / 32, ty = y / 32, gx = x % 32, gy = y % 32;
      const int grout = gx < 3 || gy < 3;
      const int mottle = (int)(14.0 * sin(x * 0.37 + y * 0.11) * cos(y * 0.29 - x * 0.05));
      if (grout) {
        d[0] = d[1] = d[2] = (unsigned char)(60 + (x * 5 + y * 3) % 16);
        s[0] = s[1] = s[2] = 8;
      } else {
        d[0] = (unsigned char)(120 + 50 * ((tx + ty) % 2) + mottle);
        d[1] = (unsigned char)(110 + 25 * (tx % 2) + mottle);
        d[2] = (unsigned char)(90 + 60 * (ty % 2) + mottle);
        s[0] = s[1] = s[2] = (unsigned char)(110 + mottle * 2);
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
  for (i = 0; i < 3; ++i) spot_dir[i] = spot_target[i] - eye[i]; /* the shader normalizes it */

  while (!glfwWindowShouldClose(window)) {
    float view[16], projection[16], model[16];
    char name[64];
    glClearColor(0.05f, 0.05f, 0.07f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    mat_perspective(projection, 45.0f, (float)W / (float)H, 0.1f, 100.0f);
    mat_lookat(view, eye[0], eye[1], eye[2], center[0], center[1], center[2], up[0], up[1], up[2]);

    glUseProgram(lighting_prog);
    glUniform3fv(glGetUniformLocation(lighting_prog, "viewPos"), 1, eye);
    set_float(lighting_prog, "material.shininess", 32.0f);
    /* directional light */
    set_vec3(lighting_prog, "dirLight.direction", -0.2f, -1.0f, -0.3f);
    set_vec3(lighting_prog, "dirLight.ambient", 0.05f, 0.05f, 0.05f);
    set_vec3(lighting_prog, "dirLight.diffuse", 0.15f, 0.15f, 0.18f);
    set_vec3(lighting_prog, "dirLight.specular", 0.2f, 0.2f, 0.2f);
    /* point lights, element by element and member by member */
    for (i = 0; i < NR_POINT_LIGHTS; ++i) {
      static const char* colour_members[3] = {"ambient", "diffuse", "specular"};
      static const char* falloff_members[3] = {"constant", "linear", "quadratic"};
      static const float weight[3] = {0.05f, 0.5f, 1.0f}, falloff[3] = {1.0f, 0.14f, 0.07f};
      const float* c = pointLightColors[i];
      snprintf(name, sizeof name, "pointLights[%d].position", i);
      glUniform3fv(glGetUniformLocation(lighting_prog, name), 1, pointLightPositions[i]);
      for (k = 0; k < 3; ++k) {
        snprintf(name, sizeof name, "pointLights[%d].%s", i, colour_members[k]);
        set_vec3(lighting_prog, name, weight[k] * c[0], weight[k] * c[1], weight[k] * c[2]);
        snprintf(name, sizeof name, "pointLights[%d].%s", i, falloff_members[k]);
        set_float(lighting_prog, name, falloff[k]);
      }
    }
    /* spotLight: a flashlight held at the camera, pointed down at the floor */
    glUniform3fv(glGetUniformLocation(lighting_prog, "spotLight.position"), 1, eye);
    glUniform3fv(glGetUniformLocation(lighting_prog, "spotLight.direction"), 1, spot_dir);
    set_vec3(lighting_prog, "spotLight.ambient", 0.0f, 0.0f, 0.0f);
    set_vec3(lighting_prog, "spotLight.diffuse", 1.0f, 1.0f, 1.0f);
    set_vec3(lighting_prog, "spotLight.specular", 1.0f, 1.0f, 1.0f);
    set_float(lighting_prog, "spotLight.constant", 1.0f);
    set_float(lighting_prog, "spotLight.linear", 0.045f);
    set_float(lighting_prog, "spotLight.quadratic", 0.0075f);
    set_float(lighting_prog, "spotLight.cutOff", cosf(8.5f * 3.14159265f / 180.0f));
    set_float(lighting_prog, "spotLight.outerCutOff", cosf(11.5f * 3.14159265f / 180.0f));
    glUniformMatrix4fv(glGetUniformLocation(lighting_prog, "projection"), 1, GL_FALSE, projection);
    glUniformMatrix4fv(glGetUniformLocation(lighting_prog, "view"), 1, GL_FALSE, view);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glBindVertexArray(cube_vao);
    /* the floor: a flat slab, its tiles repeated */
    mat_identity(model);
    mat_mul_translate(model, 0.0f, -1.53f, -1.0f);
    mat_mul_rotate(model, 7.0f, 0.0f, 1.0f, 0.0f);
    mat_mul_scale(model, 9.0f, 0.2f, 9.0f);
    glUniform2f(glGetUniformLocation(lighting_prog, "uvScale"), 4.0f, 4.0f);
    glUniformMatrix4fv(glGetUniformLocation(lighting_prog, "model"), 1, GL_FALSE, model);
    glDrawArrays(GL_TRIANGLES, 0, 36);
    glUniform2f(glGetUniformLocation(lighting_prog, "uvScale"), 1.0f, 1.0f);
    for (i = 0; i < 6; ++i) {
      mat_identity(model);
      mat_mul_translate(model, cubePositions[i][0], cubePositions[i][1], cubePositions[i][2]);
      mat_mul_rotate(model, 20.0f * (float)i + 13.0f, 1.0f, 0.3f, 0.5f);
      glUniformMatrix4fv(glGetUniformLocation(lighting_prog, "model"), 1, GL_FALSE, model);
      glDrawArrays(GL_TRIANGLES, 0, 36);
    }

    /* the lamps, in their lights' colours */
    glUseProgram(lamp_prog);
    glUniformMatrix4fv(glGetUniformLocation(lamp_prog, "projection"), 1, GL_FALSE, projection);
    glUniformMatrix4fv(glGetUniformLocation(lamp_prog, "view"), 1, GL_FALSE, view);
    glBindVertexArray(lamp_vao);
    for (i = 0; i < NR_POINT_LIGHTS; ++i) {
      mat_identity(model);
      mat_mul_translate(model, pointLightPositions[i][0], pointLightPositions[i][1],
                        pointLightPositions[i][2]);
      mat_mul_rotate(model, 11.0f + 9.0f * (float)i, 0.3f, 1.0f, 0.2f);
      mat_mul_scale(model, 0.17f, 0.17f, 0.17f);
      glUniformMatrix4fv(glGetUniformLocation(lamp_prog, "model"), 1, GL_FALSE, model);
      glUniform3fv(glGetUniformLocation(lamp_prog, "lampColor"), 1, pointLightColors[i]);
      glDrawArrays(GL_TRIANGLES, 0, 36);
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
