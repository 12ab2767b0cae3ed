/*
 * LearnOpenGL's "parallax mapping" chapter, parallax occlusion variant, as a GLFW + glad
 * program: quads with CPU tangents and bitangents, the chapter's vertex shader (TBN from
 * mat3(model) moving light, view and fragment positions into tangent space), and its
 * fragment shader: ParallaxMapping() with a layer count that varies with the view angle
 * (mix(maxLayers, minLayers, abs(dot(vec3(0, 0, 1), viewDir)))), a while loop that steps
 * the texcoords along viewDir.xy / viewDir.z * heightScale until the layer depth passes the
 * depth map and so stops early, linear interpolation between the last two layers, discard
 * where the displaced texcoords leave [0, 1], then Blinn-Phong with the normal map. The
 * depth map (GL_R8, bricks raised from deep mortar, gently bumped), its normal map and the
 * diffuse map are generated in code; they have no mipmaps (GL_LINEAR) so that the level of
 * detail of the displaced texcoords, whose derivatives jump where the layer count changes,
 * cannot matter. Three quads: a floor seen at a grazing angle and two turned walls.
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
    "  vec3 T = normalize(mat3(model) * aTangent);\n"
    "  vec3 B = normalize(mat3(model) * aBitangent);\n"
    "  vec3 N = normalize(mat3(model) * aNormal);\n"
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
    "uniform sampler2D depthMap;\n"
    "uniform float heightScale;\n"
    "vec2 ParallaxMapping(vec2 texCoords, vec3 viewDir) {\n"
    "  // number of depth layers\n"
    "  const float minLayers = 8;\n"
    "  const float maxLayers = 32;\n"
    "  float numLayers = mix(maxLayers, minLayers, abs(dot(vec3(0.0, 0.0, 1.0), viewDir)));\n"
    "  // calculate the size of each layer\n"
    "  float layerDepth = 1.0 / numLayers;\n"
    "  // depth of current layer\n"
    "  float currentLayerDepth = 0.0;\n"
    "  // the amount to shift the texture coordinates per layer (from vector P)\n"
    "  vec2 P = viewDir.xy / viewDir.z * heightScale;\n"
    "  vec2 deltaTexCoords = P / numLayers;\n"
    "  // get initial values\n"
    "  vec2 currentTexCoords = texCoords;\n"
    "  float currentDepthMapValue = texture(depthMap, currentTexCoords).r;\n"
    "  while (currentLayerDepth < currentDepthMapValue) {\n"
    "    // shift texture coordinates along direction of P\n"
    "    currentTexCoords -= deltaTexCoords;\n"
    "    // get depthmap value at current texture coordinates\n"
    "    currentDepthMapValue = texture(depthMap, currentTexCoords).r;\n"
    "    // get depth of next layer\n"
    "    currentLayerDepth += layerDepth;\n"
    "  }\n"
    "  // get texture coordinates before collision (reverse operations)\n"
    "  vec2 prevTexCoords = currentTexCoords + deltaTexCoords;\n"
    "  // get depth after and before collision for linear interpolation\n"
    "  float afterDepth = currentDepthMapValue - currentLayerDepth;\n"
    "  float beforeDepth = texture(depthMap, prevTexCoords).r - currentLayerDepth + layerDepth;\n"
    "  // interpolation of texture coordinates\n"
    "  float weight = afterDepth / (afterDepth - beforeDepth);\n"
    "  vec2 finalTexCoords = prevTexCoords * weight + currentTexCoords * (1.0 - weight);\n"
    "  return finalTexCoords;\n"
    "}\n"
    "void main() {\n"
    "  // offset texture coordinates with Parallax Mapping\n"
    "  vec3 viewDir = normalize(fs_in.TangentViewPos - fs_in.TangentFragPos);\n"
    "  vec2 texCoords = fs_in.TexCoords;\n"
    "  texCoords = ParallaxMapping(fs_in.TexCoords, viewDir);\n"
    "  if (texCoords.x > 1.0 || texCoords.y > 1.0 || texCoords.x < 0.0 || texCoords.y < 0.0) discard;\n"
    "  // obtain normal from normal map\n"
    "  vec3 normal = texture(normalMap, texCoords).rgb;\n"
    "  normal = normalize(normal * 2.0 - 1.0);\n"
    "  // get diffuse color\n"
    "  vec3 color = texture(diffuseMap, texCoords).rgb;\n"
    "  // ambient\n"
    "  vec3 ambient = 0.1 * color;\n"
    "  // diffuse\n"
    "  vec3 lightDir = normalize(fs_in.TangentLightPos - fs_in.TangentFragPos);\n"
    "  float diff = max(dot(lightDir, normal), 0.0);\n"
    "  vec3 diffuse = diff * color;\n"
    "  // specular\n"
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
  static const float uv[4][2] = {{0.0f, 1.0f}, {0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}};
  float quad[6 * 14];
  static unsigned char normal_texels[TEX * TEX * 3], diffuse_texels[TEX * TEX * 3], depth_texels[TEX * TEX];
  GLFWwindow* window;
  GLuint vao, vbo, tex[3], prog;
  float projection[16], view[16];
  const float light_pos[3] = {0.5f, 1.0f, 1.6f}, view_pos[3] = {0.0f, 0.25f, 3.3f};
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

  mat_tangent_quad(quad, uv);
  glGenVertexArrays(1, &vao);
  glGenBuffers(1, &vbo);
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
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

  /* The depth map (1 - height: deep mortar, raised bricks), the normal map from the height
   * field's central differences, and the bricks' colours. */
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
      depth_texels[y * TEX + x] = (unsigned char)((0.9f - 0.75f * height(x, y)) * 255.0f + 0.5f);
      c[0] = (unsigned char)(mortar ? 170 : 150 + (brick * 37) % 50 + (x * 3 + y * 5) % 13);
      c[1] = (unsigned char)(mortar ? 165 : 62 + (brick * 23) % 25);
      c[2] = (unsigned char)(mortar ? 150 : 45 + (brick * 11) % 15);
    }
  glGenTextures(3, tex);
  for (i = 0; i < 3; ++i) {
    glBindTexture(GL_TEXTURE_2D, tex[i]);
    if (i == 2)
      glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, TEX, TEX, 0, GL_RED, GL_UNSIGNED_BYTE, depth_texels);
    else
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEX, TEX, 0, GL_RGB, GL_UNSIGNED_BYTE,
                   i == 0 ? diffuse_texels : normal_texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  }

  glUseProgram(prog);
  glUniform1i(glGetUniformLocation(prog, "diffuseMap"), 0);
  glUniform1i(glGetUniformLocation(prog, "normalMap"), 1);
  glUniform1i(glGetUniformLocation(prog, "depthMap"), 2);
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
    glUniform1f(glGetUniformLocation(prog, "heightScale"), 0.1f);
    for (i = 0; i < 3; ++i) {
      glActiveTexture(GL_TEXTURE0 + i);
      glBindTexture(GL_TEXTURE_2D, tex[i]);
    }
    glBindVertexArray(vao);
    for (i = 0; i < 3; ++i) {
      float model[16];
      mat_identity(model);
      if (i == 0) {
        /* a floor, seen at a grazing angle */
        mat_mul_translate(model, 0.03f, -0.62f, -0.55f);
        mat_mul_rotate(model, -71.0f, 1.0f, 0.0f, 0.0f);
        mat_mul_rotate(model, 8.0f, 0.0f, 0.0f, 1.0f);
        mat_mul_scale(model, 0.92f, 0.92f, 0.92f);
      } else {
        /* two walls turned towards the middle */
        mat_mul_translate(model, i == 1 ? -1.12f : 1.08f, 0.5f, -0.6f);
        mat_mul_rotate(model, i == 1 ? 52.0f : -33.0f, 0.0f, 1.0f, 0.0f);
        mat_mul_rotate(model, i == 1 ? 6.0f : -14.0f, 1.0f, 0.0f, 0.0f);
        mat_mul_scale(model, 0.82f, 0.82f, 0.82f);
      }
      glUniformMatrix4fv(glGetUniformLocation(prog, "model"), 1, GL_FALSE, model);
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
