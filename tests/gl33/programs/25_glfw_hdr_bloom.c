/*
 * LearnOpenGL's "bloom" chapter as a GLFW + glad program: textured cubes (an sRGB diffuse
 * texture) lit by four bright coloured point lights (1/d^2 attenuation, colours up to 15.0)
 * rendered into a floating-point FBO with two GL_RGBA16F colour attachments and a depth
 * renderbuffer; the fragment shaders write both through layout(location = 0/1) outputs with
 * glDrawBuffers(2, ...), the second getting only what is brighter than 1.0 (luminance
 * weights 0.2126, 0.7152, 0.0722). Two RGBA16F ping-pong FBOs then run ten passes of the
 * chapter's separable 5-tap Gaussian (alternating horizontal/vertical, texel offsets from
 * textureSize), and a final screen quad adds the blur to the HDR scene, tone-maps with an
 * exposure (1 - exp(-hdr * exposure)) and applies gamma 2.2.
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

static const char* scene_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec3 aNormal;\n"
    "layout (location = 2) in vec2 aTexCoords;\n"
    "out VS_OUT {\n"
    "  vec3 FragPos;\n"
    "  vec3 Normal;\n"
    "  vec2 TexCoords;\n"
    "} vs_out;\n"
    "uniform mat4 projection;\n"
    "uniform mat4 view;\n"
    "uniform mat4 model;\n"
    "void main() {\n"
    "  vs_out.FragPos = vec3(model * vec4(aPos, 1.0));\n"
    "  vs_out.TexCoords = aTexCoords;\n"
    "  mat3 normalMatrix = transpose(inverse(mat3(model)));\n"
    "  vs_out.Normal = normalize(normalMatrix * aNormal);\n"
    "  gl_Position = projection * view * model * vec4(aPos, 1.0);\n"
    "}\n";
static const char* bloom_fs =
    "#version 330 core\n"
    "layout (location = 0) out vec4 FragColor;\n"
    "layout (location = 1) out vec4 BrightColor;\n"
    "in VS_OUT {\n"
    "  vec3 FragPos;\n"
    "  vec3 Normal;\n"
    "  vec2 TexCoords;\n"
    "} fs_in;\n"
    "struct Light {\n"
    "  vec3 Position;\n"
    "  vec3 Color;\n"
    "};\n"
    "uniform Light lights[4];\n"
    "uniform sampler2D diffuseTexture;\n"
    "uniform vec3 viewPos;\n"
    "void main() {\n"
    "  vec3 color = texture(diffuseTexture, fs_in.TexCoords).rgb;\n"
    "  vec3 normal = normalize(fs_in.Normal);\n"
    "  vec3 ambient = 0.02 * color;\n"
    "  vec3 lighting = vec3(0.0);\n"
    "  for (int i = 0; i < 4; i++) {\n"
    "    vec3 lightDir = normalize(lights[i].Position - fs_in.FragPos);\n"
    "    float diff = max(dot(lightDir, normal), 0.0);\n"
    "    vec3 result = lights[i].Color * diff * color;\n"
    "    float distance = length(fs_in.FragPos - lights[i].Position);\n"
    "    result *= 1.0 / (distance * distance);\n"
    "    lighting += result;\n"
    "  }\n"
    "  vec3 result = ambient + lighting;\n"
    "  float brightness = dot(result, vec3(0.2126, 0.7152, 0.0722));\n"
    "  if (brightness > 1.0)\n"
    "    BrightColor = vec4(result, 1.0);\n"
    "  else\n"
    "    BrightColor = vec4(0.0, 0.0, 0.0, 1.0);\n"
    "  FragColor = vec4(result, 1.0);\n"
    "}\n";
static const char* light_box_fs =
    "#version 330 core\n"
    "layout (location = 0) out vec4 FragColor;\n"
    "layout (location = 1) out vec4 BrightColor;\n"
    "uniform vec3 lightColor;\n"
    "void main() {\n"
    "  FragColor = vec4(lightColor, 1.0);\n"
    "  float brightness = dot(FragColor.rgb, vec3(0.2126, 0.7152, 0.0722));\n"
    "  if (brightness > 1.0)\n"
    "    BrightColor = vec4(FragColor.rgb, 1.0);\n"
    "  else\n"
    "    BrightColor = vec4(0.0, 0.0, 0.0, 1.0);\n"
    "}\n";
static const char* quad_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec2 aTexCoords;\n"
    "out vec2 TexCoords;\n"
    "void main() {\n"
    "  TexCoords = aTexCoords;\n"
    "  gl_Position = vec4(aPos, 1.0);\n"
    "}\n";
static const char* blur_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec2 TexCoords;\n"
    "uniform sampler2D image;\n"
    "uniform bool horizontal;\n"
    "uniform float weight[5] = float[] (0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216);\n"
    "void main() {\n"
    "  vec2 tex_offset = 1.0 / textureSize(image, 0); // gets size of single texel\n"
    "  vec3 result = texture(image, TexCoords).rgb * weight[0];\n"
    "  if (horizontal) {\n"
    "    for (int i = 1; i < 5; ++i) {\n"
    "      result += texture(image, TexCoords + vec2(tex_offset.x * i, 0.0)).rgb * weight[i];\n"
    "      result += texture(image, TexCoords - vec2(tex_offset.x * i, 0.0)).rgb * weight[i];\n"
    "    }\n"
    "  } else {\n"
    "    for (int i = 1; i < 5; ++i) {\n"
    "      result += texture(image, TexCoords + vec2(0.0, tex_offset.y * i)).rgb * weight[i];\n"
    "      result += texture(image, TexCoords - vec2(0.0, tex_offset.y * i)).rgb * weight[i];\n"
    "    }\n"
    "  }\n"
    "  FragColor = vec4(result, 1.0);\n"
    "}\n";
static const char* final_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec2 TexCoords;\n"
    "uniform sampler2D scene;\n"
    "uniform sampler2D bloomBlur;\n"
    "uniform bool bloom;\n"
    "uniform float exposure;\n"
    "void main() {\n"
    "  const float gamma = 2.2;\n"
    "  vec3 hdrColor = texture(scene, TexCoords).rgb;\n"
    "  vec3 bloomColor = texture(bloomBlur, TexCoords).rgb;\n"
    "  if (bloom) hdrColor += bloomColor; // additive blending\n"
    "  // tone mapping\n"
    "  vec3 result = vec3(1.0) - exp(-hdrColor * exposure);\n"
    "  // also gamma correct while we're at it\n"
    "  result = pow(result, vec3(1.0 / gamma));\n"
    "  FragColor = vec4(result, 1.0);\n"
    "}\n";

static void framebuffer_size_callback(GLFWwindow* window, int width, int height) {
  (void)window;
  glViewport(0, 0, width, height);
}

static GLuint color_texture(void) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, W, H, 0, GL_RGBA, GL_FLOAT, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  /* clamp to the edge as the blur filter would otherwise sample repeated texture values */
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

int main(void) {
  /* Per face: outward normal n and the in-face axes u, v with u x v = n. */
  static const float axes[6][9] = {{0, 0, 1, 1, 0, 0, 0, 1, 0},  {0, 0, -1, -1, 0, 0, 0, 1, 0},
                                   {1, 0, 0, 0, 0, -1, 0, 1, 0}, {-1, 0, 0, 0, 0, 1, 0, 1, 0},
                                   {0, 1, 0, 1, 0, 0, 0, 0, -1}, {0, -1, 0, 1, 0, 0, 0, 0, 1}};
  static const float corner[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
  static const float quad[] = {-1.0f, 1.0f, 0.0f, 0.0f, 1.0f, -1.0f, -1.0f, 0.0f, 0.0f, 0.0f,
                               1.0f,  1.0f, 0.0f, 1.0f, 1.0f, 1.0f,  -1.0f, 0.0f, 1.0f, 0.0f};
  static const float light_positions[4][3] = {
      {0.02f, 0.53f, 1.47f}, {-3.97f, 0.51f, -3.02f}, {3.03f, 0.49f, 1.01f}, {-0.79f, 2.42f, -1.03f}};
  static const float light_colors[4][3] = {
      {5.0f, 5.0f, 5.0f}, {10.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 15.0f}, {0.0f, 5.0f, 0.0f}};
  /* The chapter's cubes: translation, rotation (degrees about normalize(1, 0, 1)), scale. */
  static const float cubes[7][6] = {
      {0.0f, -1.0f, 0.0f, 0.0f, 12.5f, 0.5f},   {0.0f, 1.5f, 0.0f, 0.0f, 0.5f, 0.5f},
      {2.0f, 0.0f, 1.0f, 0.0f, 0.5f, 0.5f},     {-1.0f, -1.0f, 2.0f, 60.0f, 1.0f, 1.0f},
      {1.1f, 2.4f, -1.9f, 23.0f, 0.75f, 0.75f}, {-2.0f, 1.0f, -3.0f, 124.0f, 1.0f, 1.0f},
      {-3.0f, 0.0f, 0.0f, 0.0f, 0.5f, 0.5f}};
  float cube[36 * 8];
  static unsigned char wood[64 * 64 * 3];
  GLFWwindow* window;
  GLuint vaos[2], vbos[2], wood_tex, hdr_fbo, rbo_depth, color_buffers[2];
  GLuint pingpong_fbo[2], pingpong_buffers[2], shader, shader_light, shader_blur, shader_final;
  float projection[16], view[16], model[16];
  const float view_pos[3] = {0.013f, 2.61f, 8.3f};
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
  shader = link_program(scene_vs, bloom_fs);
  shader_light = link_program(scene_vs, light_box_fs);
  shader_blur = link_program(quad_vs, blur_fs);
  shader_final = link_program(quad_vs, final_fs);

  /* A cube from -1 to 1 (position, normal, UV), and the screen quad as a triangle strip. */
  for (f = 0; f < 6; ++f)
    for (k = 0; k < 6; ++k) {
      float* o = &cube[(f * 6 + k) * 8];
      const float* a = axes[f];
      for (i = 0; i < 3; ++i) o[i] = a[i] + a[3 + i] * corner[k][0] + a[6 + i] * corner[k][1];
      o[3] = a[0], o[4] = a[1], o[5] = a[2];
      o[6] = (corner[k][0] + 1.0f) * 0.5f, o[7] = (corner[k][1] + 1.0f) * 0.5f;
    }
  glGenVertexArrays(2, vaos);
  glGenBuffers(2, vbos);
  for (i = 0; i < 2; ++i) { /* cube: position, normal, UV; quad: position, UV */
    const GLsizei stride = (i == 0 ? 8 : 5) * (GLsizei)sizeof(float);
    glBindVertexArray(vaos[i]);
    glBindBuffer(GL_ARRAY_BUFFER, vbos[i]);
    if (i == 0)
      glBufferData(GL_ARRAY_BUFFER, sizeof cube, cube, GL_STATIC_DRAW);
    else
      glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, (void*)0);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, i == 0 ? 3 : 2, GL_FLOAT, GL_FALSE, stride, (void*)(3 * sizeof(float)));
    if (i == 0) glEnableVertexAttribArray(2);
    if (i == 0) glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, (void*)(6 * sizeof(float)));
  }
  glBindVertexArray(0);

  /* A wooden-container-like texture, loaded as sRGB (the chapter's gamma-corrected load). */
  for (y = 0; y < 64; ++y)
    for (x = 0; x < 64; ++x) {
      unsigned char* p = &wood[(y * 64 + x) * 3];
      const int frame = x < 6 || x >= 58 || y < 6 || y >= 58 || abs(x - y) < 4;
      const float ring = 0.5f + 0.5f * sinf((float)x * 0.6f + 1.8f * sinf((float)y * 0.15f));
      p[0] = (unsigned char)(frame ? 120 : 175 + 50 * ring);
      p[1] = (unsigned char)(frame ? 85 : 120 + 35 * ring);
      p[2] = (unsigned char)(frame ? 45 : 60 + 20 * ring);
    }
  glGenTextures(1, &wood_tex);
  glBindTexture(GL_TEXTURE_2D, wood_tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, wood);
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

  /* The floating point framebuffer: two colour buffers (normal and bright) and depth. */
  glGenFramebuffers(1, &hdr_fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, hdr_fbo);
  for (i = 0; i < 2; ++i) {
    color_buffers[i] = color_texture();
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_TEXTURE_2D, color_buffers[i], 0);
  }
  glGenRenderbuffers(1, &rbo_depth);
  glBindRenderbuffer(GL_RENDERBUFFER, rbo_depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, W, H);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rbo_depth);
  {
    const GLenum attachments[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, attachments);
  }
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    fprintf(stderr, "Framebuffer not complete!\n");
    return 1;
  }
  /* The ping-pong framebuffers for blurring. */
  glGenFramebuffers(2, pingpong_fbo);
  for (i = 0; i < 2; ++i) {
    glBindFramebuffer(GL_FRAMEBUFFER, pingpong_fbo[i]);
    pingpong_buffers[i] = color_texture();
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, pingpong_buffers[i], 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      fprintf(stderr, "Framebuffer not complete!\n");
      return 1;
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  glUseProgram(shader);
  glUniform1i(glGetUniformLocation(shader, "diffuseTexture"), 0);
  glUseProgram(shader_blur);
  glUniform1i(glGetUniformLocation(shader_blur, "image"), 0);
  glUseProgram(shader_final);
  glUniform1i(glGetUniformLocation(shader_final, "scene"), 0);
  glUniform1i(glGetUniformLocation(shader_final, "bloomBlur"), 1);
  mat_perspective(projection, 45.0f, (float)W / (float)H, 0.1f, 100.0f);
  mat_identity(view);
  mat_mul_rotate(view, 15.0f, 1.0f, 0.0f, 0.0f);
  mat_mul_translate(view, -view_pos[0], -view_pos[1], -view_pos[2]);

  while (!glfwWindowShouldClose(window)) {
    int horizontal = 1, first_iteration = 1;
    const int amount = 10;
    if (glfwGetKey(window, GLFW_KEY_ESCAPE) == GLFW_PRESS) glfwSetWindowShouldClose(window, 1);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* 1. Render the scene into the floating point framebuffer. */
    glBindFramebuffer(GL_FRAMEBUFFER, hdr_fbo);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(shader);
    glUniformMatrix4fv(glGetUniformLocation(shader, "projection"), 1, GL_FALSE, projection);
    glUniformMatrix4fv(glGetUniformLocation(shader, "view"), 1, GL_FALSE, view);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, wood_tex);
    for (i = 0; i < 4; ++i) {
      char name[64];
      snprintf(name, sizeof name, "lights[%d].Position", i);
      glUniform3fv(glGetUniformLocation(shader, name), 1, light_positions[i]);
      snprintf(name, sizeof name, "lights[%d].Color", i);
      glUniform3fv(glGetUniformLocation(shader, name), 1, light_colors[i]);
    }
    glUniform3fv(glGetUniformLocation(shader, "viewPos"), 1, view_pos);
    glBindVertexArray(vaos[0]);
    for (i = 0; i < 7; ++i) {
      mat_identity(model);
      mat_mul_translate(model, cubes[i][0], cubes[i][1], cubes[i][2]);
      if (cubes[i][3] != 0.0f) mat_mul_rotate(model, cubes[i][3], 1.0f, 0.0f, 1.0f);
      mat_mul_scale(model, cubes[i][4], cubes[i][5], cubes[i][4]);
      glUniformMatrix4fv(glGetUniformLocation(shader, "model"), 1, GL_FALSE, model);
      glDrawArrays(GL_TRIANGLES, 0, 36);
    }
    /* the light sources as bright cubes */
    glUseProgram(shader_light);
    glUniformMatrix4fv(glGetUniformLocation(shader_light, "projection"), 1, GL_FALSE, projection);
    glUniformMatrix4fv(glGetUniformLocation(shader_light, "view"), 1, GL_FALSE, view);
    for (i = 0; i < 4; ++i) {
      mat_identity(model);
      mat_mul_translate(model, light_positions[i][0], light_positions[i][1], light_positions[i][2]);
      mat_mul_scale(model, 0.25f, 0.25f, 0.25f);
      glUniformMatrix4fv(glGetUniformLocation(shader_light, "model"), 1, GL_FALSE, model);
      glUniform3fv(glGetUniformLocation(shader_light, "lightColor"), 1, light_colors[i]);
      glDrawArrays(GL_TRIANGLES, 0, 36);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    /* 2. Blur bright fragments with a two-pass Gaussian blur. */
    glUseProgram(shader_blur);
    glBindVertexArray(vaos[1]);
    glActiveTexture(GL_TEXTURE0);
    for (i = 0; i < amount; ++i) {
      glBindFramebuffer(GL_FRAMEBUFFER, pingpong_fbo[horizontal]);
      glUniform1i(glGetUniformLocation(shader_blur, "horizontal"), horizontal);
      glBindTexture(GL_TEXTURE_2D, first_iteration ? color_buffers[1] : pingpong_buffers[!horizontal]);
      glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
      horizontal = !horizontal;
      if (first_iteration) first_iteration = 0;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    /* 3. Render the HDR colour buffer plus the blurred bloom, tone-mapped, to the window. */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(shader_final);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, color_buffers[0]);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, pingpong_buffers[!horizontal]);
    glUniform1i(glGetUniformLocation(shader_final, "bloom"), 1);
    glUniform1f(glGetUniformLocation(shader_final, "exposure"), 1.0f);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);

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
