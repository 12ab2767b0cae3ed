/*
 * Rendering into texture layers in a 3.3 core context (GLUT + GLEW):
 *   left      LearnOpenGL's "point shadows": a depth cube map attached whole with
 *             glFramebufferTexture (a layered attachment), filled in one pass by a geometry
 *             shader that emits each triangle six times with gl_Layer = face and
 *             shadowMatrices[face], writing gl_FragDepth = distance / far; then the room
 *             (inside of a cube, reverse normals) and three cubes lit by the point light with
 *             the chapter's samplerCube shadow test
 *   top right a 2D array texture: one glClear of the layered framebuffer clears all three
 *             layers, a geometry shader sends triangle i to layer i % 3 (and one past the last
 *             layer, which llvmpipe clamps to the last), then glFramebufferTextureLayer draws
 *             into layer 1 alone; shown as three strips through a sampler2DArray
 *   bottom right a 3D texture, a triangle drawn into each of four slices attached with
 *             glFramebufferTextureLayer, shown through a sampler3D at each slice's centre,
 *             and one slice read back with glReadPixels
 */
#include <math.h>

#include "common.h"

#define W 320
#define H 240
#define SHADOW 128

static const char* depth_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "uniform mat4 model;\n"
    "void main() { gl_Position = model * vec4(aPos, 1.0); }\n";
static const char* depth_gs =
    "#version 330 core\n"
    "layout (triangles) in;\n"
    "layout (triangle_strip, max_vertices = 18) out;\n"
    "uniform mat4 shadowMatrices[6];\n"
    "out vec4 FragPos;\n"
    "void main() {\n"
    "  for (int face = 0; face < 6; ++face) {\n"
    "    gl_Layer = face;\n"
    "    for (int i = 0; i < 3; ++i) {\n"
    "      FragPos = gl_in[i].gl_Position;\n"
    "      gl_Position = shadowMatrices[face] * FragPos;\n"
    "      EmitVertex();\n"
    "    }\n"
    "    EndPrimitive();\n"
    "  }\n"
    "}\n";
static const char* depth_fs =
    "#version 330 core\n"
    "in vec4 FragPos;\n"
    "uniform vec3 lightPos;\n"
    "uniform float far_plane;\n"
    "void main() {\n"
    "  float lightDistance = length(FragPos.xyz - lightPos);\n"
    "  gl_FragDepth = lightDistance / far_plane;\n"
    "}\n";

static const char* scene_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec3 aNormal;\n"
    "out vec3 FragPos;\n"
    "out vec3 Normal;\n"
    "uniform mat4 projection;\n"
    "uniform mat4 view;\n"
    "uniform mat4 model;\n"
    "uniform bool reverse_normals;\n"
    "void main() {\n"
    "  FragPos = vec3(model * vec4(aPos, 1.0));\n"
    "  Normal = transpose(inverse(mat3(model))) * (reverse_normals ? -aNormal : aNormal);\n"
    "  gl_Position = projection * view * vec4(FragPos, 1.0);\n"
    "}\n";
static const char* scene_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec3 FragPos;\n"
    "in vec3 Normal;\n"
    "uniform samplerCube depthMap;\n"
    "uniform vec3 lightPos;\n"
    "uniform vec3 viewPos;\n"
    "uniform vec3 color;\n"
    "uniform float far_plane;\n"
    "float ShadowCalculation(vec3 fragPos) {\n"
    "  vec3 fragToLight = fragPos - lightPos;\n"
    "  float closestDepth = texture(depthMap, fragToLight).r * far_plane;\n"
    "  float currentDepth = length(fragToLight);\n"
    "  float bias = 0.05;\n"
    "  return currentDepth - bias > closestDepth ? 1.0 : 0.0;\n"
    "}\n"
    "void main() {\n"
    "  vec3 normal = normalize(Normal);\n"
    "  vec3 lightColor = vec3(0.6);\n"
    "  vec3 ambient = 0.3 * color;\n"
    "  vec3 lightDir = normalize(lightPos - FragPos);\n"
    "  float diff = max(dot(lightDir, normal), 0.0);\n"
    "  vec3 diffuse = diff * lightColor;\n"
    "  vec3 viewDir = normalize(viewPos - FragPos);\n"
    "  vec3 halfwayDir = normalize(lightDir + viewDir);\n"
    "  float spec = pow(max(dot(normal, halfwayDir), 0.0), 64.0);\n"
    "  vec3 specular = spec * lightColor;\n"
    "  float shadow = ShadowCalculation(FragPos);\n"
    "  FragColor = vec4((ambient + (1.0 - shadow) * (diffuse + specular)) * color, 1.0);\n"
    "}\n";

/* Triangles into the layers of an array texture: layer = gl_PrimitiveIDIn % 3, or 7. */
static const char* layer_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec2 p;\n"
    "void main() { gl_Position = vec4(p, 0.0, 1.0); }\n";
static const char* layer_gs =
    "#version 330 core\n"
    "layout (triangles) in;\n"
    "layout (triangle_strip, max_vertices = 3) out;\n"
    "out vec3 tint;\n"
    "void main() {\n"
    "  gl_Layer = gl_PrimitiveIDIn == 3 ? 7 : gl_PrimitiveIDIn % 3;\n"
    "  for (int i = 0; i < 3; ++i) {\n"
    "    tint = vec3(float(i == 0), float(i == 1), float(i == 2)) * 0.5 + 0.25 * float(gl_PrimitiveIDIn);\n"
    "    gl_Position = gl_in[i].gl_Position;\n"
    "    EmitVertex();\n"
    "  }\n"
    "}\n";
static const char* tint_fs =
    "#version 330 core\n"
    "in vec3 tint;\n"
    "out vec4 c;\n"
    "void main() { c = vec4(tint, 1.0); }\n";
static const char* flat_fs =
    "#version 330 core\n"
    "uniform vec4 colour;\n"
    "out vec4 c;\n"
    "void main() { c = colour; }\n";
/* Showing the textures: a quad with coordinates, reading a layer or a slice. */
static const char* show_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec2 p;\n"
    "out vec2 uv;\n"
    "void main() { uv = p * 0.5 + 0.5; gl_Position = vec4(p, 0.0, 1.0); }\n";
static const char* show_array_fs =
    "#version 330 core\n"
    "in vec2 uv;\n"
    "uniform sampler2DArray layers;\n"
    "out vec4 c;\n"
    "void main() { c = texture(layers, vec3(fract(uv.x * 3.0), uv.y, floor(uv.x * 3.0))); }\n";
static const char* show_3d_fs =
    "#version 330 core\n"
    "in vec2 uv;\n"
    "uniform sampler3D volume;\n"
    "out vec4 c;\n"
    "void main() { c = texture(volume, vec3(fract(uv.x * 4.0), uv.y, (floor(uv.x * 4.0) + 0.5) / 4.0)); }\n";

static GLuint depth_prog, scene_prog, layer_prog, flat_prog, show_array, show_3d;
static GLuint cube_vao, quad_vao, tri_vao, cube_map, depth_fbo, array_tex, array_fbo, vol_tex, vol_fbo;
static const float light_pos[3] = {0.3f, 0.6f, 0.2f};
static const float far_plane = 25.0f;

static void look_at(float* m, const float* eye, const float* dir, const float* up) {
  mat_lookat(m, eye[0], eye[1], eye[2], eye[0] + dir[0], eye[1] + dir[1], eye[2] + dir[2], up[0], up[1],
             up[2]);
}

static void model_of(float* m, float tx, float ty, float tz, float angle, float s) {
  mat_identity(m);
  mat_mul_translate(m, tx, ty, tz);
  if (angle != 0.0f) mat_mul_rotate(m, angle, 1.0f, 0.0f, 1.0f);
  mat_mul_scale(m, s, s, s);
}

static void render_scene(GLuint prog) {
  const GLint model_loc = glGetUniformLocation(prog, "model");
  const GLint color_loc = glGetUniformLocation(prog, "color");
  const GLint rev_loc = glGetUniformLocation(prog, "reverse_normals");
  float m[16];
  glBindVertexArray(cube_vao);
  /* The room: culling off, normals reversed for lighting inside. */
  model_of(m, 0.0f, 0.0f, 0.0f, 0.0f, 5.0f);
  glUniformMatrix4fv(model_loc, 1, GL_FALSE, m);
  if (color_loc >= 0) glUniform3f(color_loc, 0.8f, 0.75f, 0.65f);
  if (rev_loc >= 0) glUniform1i(rev_loc, 1);
  glDrawArrays(GL_TRIANGLES, 0, 36);
  if (rev_loc >= 0) glUniform1i(rev_loc, 0);
  if (color_loc >= 0) glUniform3f(color_loc, 0.4f, 0.6f, 0.9f);
  model_of(m, 2.0f, -2.5f, 1.0f, 0.0f, 0.5f);
  glUniformMatrix4fv(model_loc, 1, GL_FALSE, m);
  glDrawArrays(GL_TRIANGLES, 0, 36);
  model_of(m, -1.5f, 1.2f, 1.5f, 0.0f, 0.6f);
  glUniformMatrix4fv(model_loc, 1, GL_FALSE, m);
  glDrawArrays(GL_TRIANGLES, 0, 36);
  if (color_loc >= 0) glUniform3f(color_loc, 0.9f, 0.5f, 0.3f);
  model_of(m, -1.2f, -1.5f, -1.8f, 60.0f, 0.75f);
  glUniformMatrix4fv(model_loc, 1, GL_FALSE, m);
  glDrawArrays(GL_TRIANGLES, 0, 36);
}

static void display(void) {
  static const float dirs[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  static const float ups[6][3] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  float shadow_proj[16], shadow_view[16], shadow_mats[6][16], proj[16], view[16];
  const float eye[3] = {0.5f, 1.2f, 4.2f};
  char name[32];
  int i;

  /* 1. The depth cube map, all six faces in one draw per object. */
  mat_perspective(shadow_proj, 90.0f, 1.0f, 1.0f, far_plane);
  for (i = 0; i < 6; ++i) {
    look_at(shadow_view, light_pos, dirs[i], ups[i]);
    mat_mul(shadow_mats[i], shadow_proj, shadow_view);
  }
  glViewport(0, 0, SHADOW, SHADOW);
  glBindFramebuffer(GL_FRAMEBUFFER, depth_fbo);
  glEnable(GL_DEPTH_TEST);
  glClear(GL_DEPTH_BUFFER_BIT);
  glUseProgram(depth_prog);
  for (i = 0; i < 6; ++i) {
    sprintf(name, "shadowMatrices[%d]", i);
    glUniformMatrix4fv(glGetUniformLocation(depth_prog, name), 1, GL_FALSE, shadow_mats[i]);
  }
  glUniform1f(glGetUniformLocation(depth_prog, "far_plane"), far_plane);
  glUniform3fv(glGetUniformLocation(depth_prog, "lightPos"), 1, light_pos);
  render_scene(depth_prog);

  /* 2. The scene with the cube map's shadows, in the left half. */
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, W / 2, H);
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(scene_prog);
  mat_perspective(proj, 60.0f, (float)(W / 2) / (float)H, 0.1f, 100.0f);
  mat_lookat(view, eye[0], eye[1], eye[2], 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f);
  glUniformMatrix4fv(glGetUniformLocation(scene_prog, "projection"), 1, GL_FALSE, proj);
  glUniformMatrix4fv(glGetUniformLocation(scene_prog, "view"), 1, GL_FALSE, view);
  glUniform3fv(glGetUniformLocation(scene_prog, "lightPos"), 1, light_pos);
  glUniform3fv(glGetUniformLocation(scene_prog, "viewPos"), 1, eye);
  glUniform1f(glGetUniformLocation(scene_prog, "far_plane"), far_plane);
  glUniform1i(glGetUniformLocation(scene_prog, "depthMap"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube_map);
  render_scene(scene_prog);
  glDisable(GL_DEPTH_TEST);

  /* 3. The array texture's layers, top right; the 3D texture's slices, bottom right. */
  glViewport(W / 2, H / 2, W / 2, H / 2);
  glUseProgram(show_array);
  glUniform1i(glGetUniformLocation(show_array, "layers"), 1);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D_ARRAY, array_tex);
  glBindVertexArray(quad_vao);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glViewport(W / 2, 0, W / 2, H / 2);
  glUseProgram(show_3d);
  glUniform1i(glGetUniformLocation(show_3d, "volume"), 2);
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_3D, vol_tex);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glActiveTexture(GL_TEXTURE0);
  check_gl("display");
  glutSwapBuffers();
}

/* The array and 3D textures, rendered once. */
static void fill_layers(void) {
  GLint layered = 0;
  GLubyte px[4];
  int z;
  glBindFramebuffer(GL_FRAMEBUFFER, array_fbo);
  glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, array_tex, 0);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_LAYERED, &layered);
  if (!layered) fprintf(stderr, "the array attachment is not layered\n");
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    fprintf(stderr, "layered FBO incomplete\n");
  glViewport(0, 0, 32, 32);
  glClearColor(0.2f, 0.3f, 0.5f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT); /* every layer */
  glUseProgram(layer_prog);
  glBindVertexArray(tri_vao);
  glDrawArrays(GL_TRIANGLES, 0, 12);
  /* Layer 1 alone: a square in its middle. */
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, array_tex, 0, 1);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    fprintf(stderr, "layer FBO incomplete\n");
  glUseProgram(flat_prog);
  glUniform4f(glGetUniformLocation(flat_prog, "colour"), 1.0f, 1.0f, 0.2f, 1.0f);
  glBindVertexArray(quad_vao);
  glViewport(12, 12, 8, 8);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);

  /* The 3D texture: a cleared slice each, a triangle in it. */
  glBindFramebuffer(GL_FRAMEBUFFER, vol_fbo);
  glBindVertexArray(tri_vao);
  for (z = 0; z < 4; ++z) {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, vol_tex, 0, z);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      fprintf(stderr, "3D slice FBO incomplete\n");
    glViewport(0, 0, 16, 16);
    glClearColor(0.1f * (float)z, 0.15f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glUniform4f(glGetUniformLocation(flat_prog, "colour"), 0.9f, 0.25f * (float)z, 0.3f, 1.0f);
    glDrawArrays(GL_TRIANGLES, 3 * z, 3);
  }
  glReadPixels(3, 9, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px); /* inside slice 3's triangle */
  if (px[0] < 200) fprintf(stderr, "slice 3 reads back %d %d %d %d\n", px[0], px[1], px[2], px[3]);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("fill_layers");
}

int main(int argc, char** argv) {
  static const float axes[6][9] = {{0, 0, 1, 1, 0, 0, 0, 1, 0},  {0, 0, -1, -1, 0, 0, 0, 1, 0},
                                   {1, 0, 0, 0, 0, -1, 0, 1, 0}, {-1, 0, 0, 0, 0, 1, 0, 1, 0},
                                   {0, 1, 0, 1, 0, 0, 0, 0, -1}, {0, -1, 0, 1, 0, 0, 0, 0, 1}};
  static const float corner[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
  static const float tris[24] = {-0.9f, -0.9f, 0.6f,  -0.7f, -0.5f, 0.8f,  -0.2f, -0.8f,
                                 0.9f,  -0.1f, -0.3f, 0.9f,  0.1f,  0.1f,  0.9f,  0.6f,
                                 -0.1f, 0.95f, -0.9f, 0.2f,  -0.6f, -0.2f, -0.3f, 0.4f};
  float cube[36 * 6];
  GLuint vbo;
  int f, k, i;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "layered rendering");
  depth_prog = link_shaders(depth_vs, depth_gs, depth_fs);
  layer_prog = link_shaders(layer_vs, layer_gs, tint_fs);
  scene_prog = link_program(scene_vs, scene_fs);
  flat_prog = link_program(layer_vs, flat_fs);
  show_array = link_program(show_vs, show_array_fs);
  show_3d = link_program(show_vs, show_3d_fs);

  for (f = 0; f < 6; ++f)
    for (k = 0; k < 6; ++k) {
      float* o = &cube[(f * 6 + k) * 6];
      const float* a = axes[f];
      for (i = 0; i < 3; ++i) o[i] = a[i] + a[3 + i] * corner[k][0] + a[6 + i] * corner[k][1];
      o[3] = a[0], o[4] = a[1], o[5] = a[2];
    }
  glGenVertexArrays(1, &cube_vao);
  glBindVertexArray(cube_vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof cube, cube, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)(3 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  quad_vao = window_strip();
  tri_vao = vertex_array2(tris, 12);

  /* The depth cube map and its framebuffer (no colour buffer). */
  glGenTextures(1, &cube_map);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube_map);
  for (i = 0; i < 6; ++i)
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)i, 0, GL_DEPTH_COMPONENT, SHADOW, SHADOW, 0,
                 GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glGenFramebuffers(1, &depth_fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, depth_fbo);
  glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, cube_map, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    fprintf(stderr, "depth FBO incomplete\n");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  /* A 32x32 array of three layers, a 16x16x4 volume. */
  glGenTextures(1, &array_tex);
  glBindTexture(GL_TEXTURE_2D_ARRAY, array_tex);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, 32, 32, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glGenTextures(1, &vol_tex);
  glBindTexture(GL_TEXTURE_3D, vol_tex);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 16, 16, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glGenFramebuffers(1, &array_fbo);
  glGenFramebuffers(1, &vol_fbo);
  fill_layers();
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
