/*
 * LearnOpenGL's "shadow mapping" chapter (directional light) as a GLFW + glad program: a
 * 1024x1024 GL_DEPTH_COMPONENT/GL_FLOAT depth texture attached to an FBO with no colour buffer
 * (glDrawBuffers with GL_NONE, glReadBuffer(GL_NONE)), rendered from an orthographic light
 * with front-face culling for the cubes (against peter-panning); then the scene from the
 * camera with the chapter's ShadowCalculation: a slope-scaled bias from the normal/light
 * angle, 3x3 PCF with texel offsets from textureSize(shadowMap, 0), GL_CLAMP_TO_BORDER with
 * border colour 1.0, and projCoords.z > 1.0 meaning "not in shadow". A floor and three cubes
 * with a procedural wood texture (mipmapped), Blinn-Phong, transpose(inverse()) normal matrix.
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
#define SHADOW_WIDTH 1024
#define SHADOW_HEIGHT 1024

static const char* depth_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "uniform mat4 lightSpaceMatrix;\n"
    "uniform mat4 model;\n"
    "void main() { gl_Position = lightSpaceMatrix * model * vec4(aPos, 1.0); }\n";
static const char* depth_fs =
    "#version 330 core\n"
    "void main() { /* gl_FragDepth = gl_FragCoord.z; */ }\n";

static const char* scene_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec3 aNormal;\n"
    "layout (location = 2) in vec2 aTexCoords;\n"
    "out VS_OUT {\n"
    "  vec3 FragPos;\n"
    "  vec3 Normal;\n"
    "  vec2 TexCoords;\n"
    "  vec4 FragPosLightSpace;\n"
    "} vs_out;\n"
    "uniform mat4 projection;\n"
    "uniform mat4 view;\n"
    "uniform mat4 model;\n"
    "uniform mat4 lightSpaceMatrix;\n"
    "void main() {\n"
    "  vs_out.FragPos = vec3(model * vec4(aPos, 1.0));\n"
    "  vs_out.Normal = transpose(inverse(mat3(model))) * aNormal;\n"
    "  vs_out.TexCoords = aTexCoords;\n"
    "  vs_out.FragPosLightSpace = lightSpaceMatrix * vec4(vs_out.FragPos, 1.0);\n"
    "  gl_Position = projection * view * vec4(vs_out.FragPos, 1.0);\n"
    "}\n";
static const char* scene_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in VS_OUT {\n"
    "  vec3 FragPos;\n"
    "  vec3 Normal;\n"
    "  vec2 TexCoords;\n"
    "  vec4 FragPosLightSpace;\n"
    "} fs_in;\n"
    "uniform sampler2D diffuseTexture;\n"
    "uniform sampler2D shadowMap;\n"
    "uniform vec3 lightPos;\n"
    "uniform vec3 viewPos;\n"
    "float ShadowCalculation(vec4 fragPosLightSpace) {\n"
    "  vec3 projCoords = fragPosLightSpace.xyz / fragPosLightSpace.w;\n"
    "  projCoords = projCoords * 0.5 + 0.5;\n"
    "  float closestDepth = texture(shadowMap, projCoords.xy).r;\n"
    "  float currentDepth = projCoords.z;\n"
    "  vec3 normal = normalize(fs_in.Normal);\n"
    "  vec3 lightDir = normalize(lightPos - fs_in.FragPos);\n"
    "  float bias = max(0.05 * (1.0 - dot(normal, lightDir)), 0.005);\n"
    "  float shadow = 0.0;\n"
    "  vec2 texelSize = 1.0 / textureSize(shadowMap, 0);\n"
    "  for (int x = -1; x <= 1; ++x) {\n"
    "    for (int y = -1; y <= 1; ++y) {\n"
    "      float pcfDepth = texture(shadowMap, projCoords.xy + vec2(x, y) * texelSize).r;\n"
    "      shadow += currentDepth - bias > pcfDepth ? 1.0 : 0.0;\n"
    "    }\n"
    "  }\n"
    "  shadow /= 9.0;\n"
    "  if (projCoords.z > 1.0) shadow = 0.0;\n"
    "  return shadow;\n"
    "}\n"
    "void main() {\n"
    "  vec3 color = texture(diffuseTexture, fs_in.TexCoords).rgb;\n"
    "  vec3 normal = normalize(fs_in.Normal);\n"
    "  vec3 lightColor = vec3(0.85);\n"
    "  vec3 ambient = 0.3 * lightColor;\n"
    "  vec3 lightDir = normalize(lightPos - fs_in.FragPos);\n"
    "  float diff = max(dot(lightDir, normal), 0.0);\n"
    "  vec3 diffuse = diff * lightColor;\n"
    "  vec3 viewDir = normalize(viewPos - fs_in.FragPos);\n"
    "  vec3 halfwayDir = normalize(lightDir + viewDir);\n"
    "  float spec = pow(max(dot(normal, halfwayDir), 0.0), 64.0);\n"
    "  vec3 specular = spec * lightColor;\n"
    "  float shadow = ShadowCalculation(fs_in.FragPosLightSpace);\n"
    "  vec3 lighting = (ambient + (1.0 - shadow) * (diffuse + specular)) * color;\n"
    "  FragColor = vec4(lighting, 1.0);\n"
    "}\n";

static void framebuffer_size_callback(GLFWwindow* window, int width, int height) {
  (void)window;
  glViewport(0, 0, width, height);
}

/* The chapter's renderScene(): the floor, then three cubes (culling front faces of the cubes
 * only when `cull_cubes`, as the floor is a single plane). */
static void render_scene(GLuint prog, GLuint floor_vao, GLuint cube_vao, int cull_cubes) {
  const GLint loc = glGetUniformLocation(prog, "model");
  float model[16];
  mat_identity(model);
  glUniformMatrix4fv(loc, 1, GL_FALSE, model);
  glBindVertexArray(floor_vao);
  glDrawArrays(GL_TRIANGLES, 0, 6);
  if (cull_cubes) glEnable(GL_CULL_FACE);
  glBindVertexArray(cube_vao);
  mat_identity(model);
  mat_mul_translate(model, 0.03f, 1.5f, 0.02f);
  mat_mul_rotate(model, 17.0f, 0.0f, 1.0f, 0.0f);
  mat_mul_scale(model, 0.5f, 0.5f, 0.5f);
  glUniformMatrix4fv(loc, 1, GL_FALSE, model);
  glDrawArrays(GL_TRIANGLES, 0, 36);
  mat_identity(model);
  mat_mul_translate(model, 2.0f, 0.0f, 1.0f);
  mat_mul_rotate(model, -23.0f, 0.0f, 1.0f, 0.0f);
  mat_mul_scale(model, 0.5f, 0.5f, 0.5f);
  glUniformMatrix4fv(loc, 1, GL_FALSE, model);
  glDrawArrays(GL_TRIANGLES, 0, 36);
  mat_identity(model);
  mat_mul_translate(model, -1.0f, 0.0f, 2.0f);
  mat_mul_rotate(model, 60.0f, 1.0f, 0.0f, 1.0f);
  mat_mul_scale(model, 0.25f, 0.25f, 0.25f);
  glUniformMatrix4fv(loc, 1, GL_FALSE, model);
  glDrawArrays(GL_TRIANGLES, 0, 36);
  if (cull_cubes) glDisable(GL_CULL_FACE);
}

int main(void) {
  /* The floor: position, normal, texture coordinates (two triangles, counter-clockwise from above). */
  static const float plane[] = {12.0f,  -0.5f, 12.0f,  0.0f,  1.0f,   0.0f,  6.0f,   0.0f,  12.0f,  -0.5f,
                                -12.0f, 0.0f,  1.0f,   0.0f,  6.0f,   6.0f,  -12.0f, -0.5f, -12.0f, 0.0f,
                                1.0f,   0.0f,  0.0f,   6.0f,  12.0f,  -0.5f, 12.0f,  0.0f,  1.0f,   0.0f,
                                6.0f,   0.0f,  -12.0f, -0.5f, -12.0f, 0.0f,  1.0f,   0.0f,  0.0f,   6.0f,
                                -12.0f, -0.5f, 12.0f,  0.0f,  1.0f,   0.0f,  0.0f,   0.0f};
  /* Per face: outward normal n and the in-face axes u, v with u x v = n. */
  static const float axes[6][9] = {{0, 0, 1, 1, 0, 0, 0, 1, 0},  {0, 0, -1, -1, 0, 0, 0, 1, 0},
                                   {1, 0, 0, 0, 0, -1, 0, 1, 0}, {-1, 0, 0, 0, 0, 1, 0, 1, 0},
                                   {0, 1, 0, 1, 0, 0, 0, 0, -1}, {0, -1, 0, 1, 0, 0, 0, 0, 1}};
  static const float corner[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
  float cube[36 * 8];
  static unsigned char wood[64 * 64 * 3];
  GLFWwindow* window;
  GLuint vao[2], vbo[2], wood_tex, depth_map, depth_fbo, depth_prog, scene_prog;
  float light_projection[16], light_view[16], light_space[16], projection[16], view[16];
  const float light_pos[3] = {-2.0f, 4.0f, -1.0f}, eye[3] = {1.13f, 3.07f, 5.61f};
  const float center[3] = {0.07f, 0.21f, 0.33f}, up[3] = {0.0f, 1.0f, 0.0f};
  int f, k, i, x, y;

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
  depth_prog = link_program(depth_vs, depth_fs);
  scene_prog = link_program(scene_vs, scene_fs);

  /* A cube from -1 to 1 with outward normals and one texture copy per face. */
  for (f = 0; f < 6; ++f)
    for (k = 0; k < 6; ++k) {
      float* o = &cube[(f * 6 + k) * 8];
      const float* a = axes[f];
      for (i = 0; i < 3; ++i) o[i] = a[i] + a[3 + i] * corner[k][0] + a[6 + i] * corner[k][1];
      o[3] = a[0], o[4] = a[1], o[5] = a[2];
      o[6] = (corner[k][0] + 1.0f) * 0.5f, o[7] = (corner[k][1] + 1.0f) * 0.5f;
    }
  glGenVertexArrays(2, vao);
  glGenBuffers(2, vbo);
  for (i = 0; i < 2; ++i) {
    glBindVertexArray(vao[i]);
    glBindBuffer(GL_ARRAY_BUFFER, vbo[i]);
    if (i == 0)
      glBufferData(GL_ARRAY_BUFFER, sizeof plane, plane, GL_STATIC_DRAW);
    else
      glBufferData(GL_ARRAY_BUFFER, sizeof cube, cube, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 8 * sizeof(float), (void*)0);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 8 * sizeof(float), (void*)(3 * sizeof(float)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, 8 * sizeof(float), (void*)(6 * sizeof(float)));
  }
  glBindVertexArray(0);

  /* Procedural wood: planks along x, wavy grain rings, darker plank seams. */
  for (y = 0; y < 64; ++y)
    for (x = 0; x < 64; ++x) {
      unsigned char* p = &wood[(y * 64 + x) * 3];
      const float grain = (float)y * 0.45f + 2.2f * sinf((float)x * 0.21f + (float)(y / 16) * 1.7f);
      const float ring = 0.5f + 0.5f * sinf(grain);
      const int seam = (y % 16 == 0) || ((x + (y / 16) * 23) % 64 == 0);
      const float shade = seam ? 0.45f : 0.8f + 0.2f * ring;
      p[0] = (unsigned char)(shade * (170.0f + 40.0f * ring));
      p[1] = (unsigned char)(shade * (110.0f + 30.0f * ring));
      p[2] = (unsigned char)(shade * (60.0f + 15.0f * ring));
    }
  glGenTextures(1, &wood_tex);
  glBindTexture(GL_TEXTURE_2D, wood_tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, wood);
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

  /* The depth map: a depth texture alone in an FBO, no colour buffer drawn or read. */
  glGenFramebuffers(1, &depth_fbo);
  glGenTextures(1, &depth_map);
  glBindTexture(GL_TEXTURE_2D, depth_map);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, SHADOW_WIDTH, SHADOW_HEIGHT, 0, GL_DEPTH_COMPONENT,
               GL_FLOAT, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  {
    const float borderColor[] = {1.0f, 1.0f, 1.0f, 1.0f};
    const GLenum none = GL_NONE;
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, borderColor);
    glBindFramebuffer(GL_FRAMEBUFFER, depth_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_map, 0);
    glDrawBuffers(1, &none); /* glDrawBuffer(GL_NONE) */
    glReadBuffer(GL_NONE);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      fprintf(stderr, "ERROR::FRAMEBUFFER:: Framebuffer is not complete!\n");
      return 1;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  glUseProgram(scene_prog);
  glUniform1i(glGetUniformLocation(scene_prog, "diffuseTexture"), 0);
  glUniform1i(glGetUniformLocation(scene_prog, "shadowMap"), 1);

  /* The light's orthographic frustum and view; the camera. */
  mat_ortho(light_projection, -10.0f, 10.0f, -10.0f, 10.0f, 1.0f, 7.5f);
  mat_lookat(light_view, light_pos[0], light_pos[1], light_pos[2], 0.0f, 0.0f, 0.0f, up[0], up[1], up[2]);
  mat_mul(light_space, light_projection, light_view);
  mat_perspective(projection, 45.0f, (float)W / (float)H, 0.1f, 100.0f);
  mat_lookat(view, eye[0], eye[1], eye[2], center[0], center[1], center[2], up[0], up[1], up[2]);
  glCullFace(GL_FRONT);

  while (!glfwWindowShouldClose(window)) {
    if (glfwGetKey(window, GLFW_KEY_ESCAPE) == GLFW_PRESS) glfwSetWindowShouldClose(window, 1);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* 1. Render depth of the scene from the light's point of view. */
    glUseProgram(depth_prog);
    glUniformMatrix4fv(glGetUniformLocation(depth_prog, "lightSpaceMatrix"), 1, GL_FALSE, light_space);
    glViewport(0, 0, SHADOW_WIDTH, SHADOW_HEIGHT);
    glBindFramebuffer(GL_FRAMEBUFFER, depth_fbo);
    glClear(GL_DEPTH_BUFFER_BIT);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, wood_tex);
    render_scene(depth_prog, vao[0], vao[1], 1);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    /* 2. Render the scene as normal with the shadow map. */
    glViewport(0, 0, W, H);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(scene_prog);
    glUniformMatrix4fv(glGetUniformLocation(scene_prog, "projection"), 1, GL_FALSE, projection);
    glUniformMatrix4fv(glGetUniformLocation(scene_prog, "view"), 1, GL_FALSE, view);
    glUniform3fv(glGetUniformLocation(scene_prog, "viewPos"), 1, eye);
    glUniform3fv(glGetUniformLocation(scene_prog, "lightPos"), 1, light_pos);
    glUniformMatrix4fv(glGetUniformLocation(scene_prog, "lightSpaceMatrix"), 1, GL_FALSE, light_space);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, wood_tex);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, depth_map);
    render_scene(scene_prog, vao[0], vao[1], 0);

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
