/*
 * A 3D scene with a 2D text overlay as course frameworks draw one (a GLFW + glad program):
 * three Phong-lit coloured cubes, then a HUD. The font is a 5x7 bitmap table (digits,
 * capitals, a few symbols) built in code into a 128x64 GL_R8 atlas: one glTexSubImage2D per
 * glyph at the odd width 5 with glPixelStorei(GL_UNPACK_ALIGNMENT, 1), plus a solid block
 * that the panel samples (the "white pixel" trick). GL_TEXTURE_SWIZZLE_R/G/B/A make the
 * shader read (1, 1, 1, r), so FragColor = textColor * texel. Each string is built on the
 * CPU as textured quads in pixel coordinates (an orthographic projection, y down), written
 * with glBufferSubData into one GL_DYNAMIC_DRAW VBO (the same bytes overwritten between
 * draws) and drawn with alpha blending on and depth test off: a semi-transparent panel,
 * a title at scale 3 with GL_NEAREST magnification, small lines at scale 2 with GL_LINEAR,
 * in two colours. Quads sit 0.3 px off the pixel grid so no texel edge hits a pixel centre.
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
#define ATLAS_W 128
#define ATLAS_H 64
#define MAX_CHARS 64

static const char* scene_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec3 aNormal;\n"
    "out vec3 FragPos;\n"
    "out vec3 Normal;\n"
    "uniform mat4 model;\n"
    "uniform mat4 view;\n"
    "uniform mat4 projection;\n"
    "void main() {\n"
    "  FragPos = vec3(model * vec4(aPos, 1.0));\n"
    "  Normal = mat3(transpose(inverse(model))) * aNormal;\n"
    "  gl_Position = projection * view * vec4(FragPos, 1.0);\n"
    "}\n";
static const char* scene_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec3 FragPos;\n"
    "in vec3 Normal;\n"
    "uniform vec3 objectColor;\n"
    "uniform vec3 lightPos;\n"
    "uniform vec3 viewPos;\n"
    "void main() {\n"
    "  vec3 ambient = 0.15 * objectColor;\n"
    "  vec3 norm = normalize(Normal);\n"
    "  vec3 lightDir = normalize(lightPos - FragPos);\n"
    "  vec3 diffuse = max(dot(norm, lightDir), 0.0) * objectColor;\n"
    "  vec3 viewDir = normalize(viewPos - FragPos);\n"
    "  vec3 reflectDir = reflect(-lightDir, norm);\n"
    "  float spec = pow(max(dot(viewDir, reflectDir), 0.0), 16.0);\n"
    "  FragColor = vec4(ambient + diffuse + vec3(0.4) * spec, 1.0);\n"
    "}\n";
/* The text shader of the "text rendering" chapter: vertex = <vec2 pos, vec2 tex>. */
static const char* text_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec4 vertex;\n"
    "out vec2 TexCoords;\n"
    "uniform mat4 projection;\n"
    "void main() {\n"
    "  gl_Position = projection * vec4(vertex.xy, 0.0, 1.0);\n"
    "  TexCoords = vertex.zw;\n"
    "}\n";
static const char* text_fs =
    "#version 330 core\n"
    "in vec2 TexCoords;\n"
    "out vec4 color;\n"
    "uniform sampler2D text;\n"
    "uniform vec4 textColor;\n"
    "void main() {\n"
    "  vec4 sampled = texture(text, TexCoords); // (1, 1, 1, r) by the swizzle\n"
    "  color = textColor * sampled;\n"
    "}\n";

/* 5x7 glyphs, one byte a row (top row first), bit 4 = leftmost column. */
static const struct {
  char c;
  unsigned char rows[7];
} font[] = {
    {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}},
    {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}},
    {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
    {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}},
    {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
    {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}},
    {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}},
    {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
    {'A', {0x0E, 0x11, 0x11, 0x11, 0x1F, 0x11, 0x11}},
    {'B', {0x1E, 0x11, 0x11, 0x1E, 0x11, 0x11, 0x1E}},
    {'C', {0x0E, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0E}},
    {'D', {0x1C, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1C}},
    {'E', {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F}},
    {'F', {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x10}},
    {'G', {0x0E, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0F}},
    {'H', {0x11, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11}},
    {'I', {0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'J', {0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0C}},
    {'K', {0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11}},
    {'L', {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F}},
    {'M', {0x11, 0x1B, 0x15, 0x15, 0x11, 0x11, 0x11}},
    {'N', {0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11}},
    {'O', {0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}},
    {'P', {0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10}},
    {'Q', {0x0E, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0D}},
    {'R', {0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11}},
    {'S', {0x0F, 0x10, 0x10, 0x0E, 0x01, 0x01, 0x1E}},
    {'T', {0x1F, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04}},
    {'U', {0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}},
    {'V', {0x11, 0x11, 0x11, 0x11, 0x11, 0x0A, 0x04}},
    {'W', {0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0A}},
    {'X', {0x11, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x11}},
    {'Y', {0x11, 0x11, 0x11, 0x0A, 0x04, 0x04, 0x04}},
    {'Z', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1F}},
    {' ', {0, 0, 0, 0, 0, 0, 0}},
    {'.', {0, 0, 0, 0, 0, 0x0C, 0x0C}},
    {':', {0, 0x0C, 0x0C, 0, 0x0C, 0x0C, 0}},
    {'-', {0, 0, 0, 0x1F, 0, 0, 0}},
    {'+', {0, 0x04, 0x04, 0x1F, 0x04, 0x04, 0}},
    {'=', {0, 0, 0x1F, 0, 0x1F, 0, 0}},
    {'/', {0, 0x01, 0x02, 0x04, 0x08, 0x10, 0}},
    {'%', {0x18, 0x19, 0x02, 0x04, 0x08, 0x13, 0x03}},
    {'(', {0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02}},
    {')', {0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08}},
    {'!', {0x04, 0x04, 0x04, 0x04, 0x04, 0, 0x04}},
    {'?', {0x0E, 0x11, 0x01, 0x02, 0x04, 0, 0x04}},
    {'#', {0x0A, 0x0A, 0x1F, 0x0A, 0x1F, 0x0A, 0x0A}},
    {'<', {0x02, 0x04, 0x08, 0x10, 0x08, 0x04, 0x02}},
    {'>', {0x08, 0x04, 0x02, 0x01, 0x02, 0x04, 0x08}},
    {',', {0, 0, 0, 0, 0x0C, 0x04, 0x08}},
};
#define NUM_GLYPHS ((int)(sizeof font / sizeof font[0]))
/* Glyph i's top-left texel in the atlas: 8x10 cells, so at least 2 empty texels between. */
#define GLYPH_X(i) (2 + ((i) % 16) * 8)
#define GLYPH_Y(i) (2 + ((i) / 16) * 10)
/* The solid 4x4 block the panel samples. */
#define SOLID_X 120
#define SOLID_Y 56

/* translate(x, y, z) * rotate(deg about y) * rotate(tilt about x) * scale(s) */
static void model_matrix(float* m, float x, float y, float z, float deg, float tilt, float s) {
  const float a = deg * 3.14159265f / 180.0f, b = tilt * 3.14159265f / 180.0f;
  const float ca = cosf(a), sa = sinf(a), cb = cosf(b), sb = sinf(b);
  memset(m, 0, 16 * sizeof(float));
  m[0] = ca * s, m[1] = 0.0f, m[2] = -sa * s;
  m[4] = sa * sb * s, m[5] = cb * s, m[6] = ca * sb * s;
  m[8] = sa * cb * s, m[9] = -sb * s, m[10] = ca * cb * s;
  m[12] = x, m[13] = y, m[14] = z, m[15] = 1.0f;
}

static void framebuffer_size_callback(GLFWwindow* window, int width, int height) {
  (void)window;
  glViewport(0, 0, width, height);
}

static int glyph_index(char c) {
  int i;
  for (i = 0; i < NUM_GLYPHS; ++i)
    if (font[i].c == c) return i;
  return 36; /* space */
}

static void put_quad(float* o, float x0, float y0, float x1, float y1, float u0, float v0, float u1,
                     float v1) {
  const float q[6][4] = {{x0, y1, u0, v1}, {x1, y0, u1, v0}, {x0, y0, u0, v0},
                         {x0, y1, u0, v1}, {x1, y1, u1, v1}, {x1, y0, u1, v0}};
  memcpy(o, q, sizeof q);
}

/* RenderText: one quad per character at (x, y) (top-left, pixels, y down), 6 px advance a
 * font unit; the quads go into the dynamic VBO with glBufferSubData and are drawn. */
static void render_text(GLuint prog, GLuint vbo, const char* s, float x, float y, float scale,
                        const float* color) {
  static float verts[MAX_CHARS * 6 * 4];
  int n = 0;
  for (; *s && n < MAX_CHARS; ++s, ++n) {
    const int g = glyph_index(*s);
    const float u0 = (float)GLYPH_X(g) / ATLAS_W, v0 = (float)GLYPH_Y(g) / ATLAS_H;
    const float u1 = (float)(GLYPH_X(g) + 5) / ATLAS_W, v1 = (float)(GLYPH_Y(g) + 7) / ATLAS_H;
    const float x0 = x + (float)n * 6.0f * scale;
    put_quad(verts + n * 24, x0, y, x0 + 5.0f * scale, y + 7.0f * scale, u0, v0, u1, v1);
  }
  glUniform4fv(glGetUniformLocation(prog, "textColor"), 1, color);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)(n * 24 * sizeof(float)), verts);
  glDrawArrays(GL_TRIANGLES, 0, n * 6);
}

/* A panel: a quad whose texcoords all point into the solid block. */
static void render_panel(GLuint prog, GLuint vbo, float x0, float y0, float x1, float y1,
                         const float* color) {
  float verts[24];
  const float u = (SOLID_X + 1.5f) / ATLAS_W, v = (SOLID_Y + 1.5f) / ATLAS_H;
  put_quad(verts, x0, y0, x1, y1, u, v, u, v);
  glUniform4fv(glGetUniformLocation(prog, "textColor"), 1, color);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof verts, verts);
  glDrawArrays(GL_TRIANGLES, 0, 6);
}

int main(void) {
  /* A unit cube: position, normal (36 vertices). */
  static float cube[36 * 6];
  static unsigned char zeros[ATLAS_W * ATLAS_H], glyph[35], solid[16];
  static const float cube_pos[3][3] = {{-1.25f, -0.1f, -0.4f}, {0.35f, 0.2f, -1.6f}, {1.45f, -0.35f, 0.1f}};
  static const float cube_col[3][3] = {{0.9f, 0.3f, 0.25f}, {0.3f, 0.75f, 0.35f}, {0.3f, 0.45f, 0.95f}};
  static const float cube_rot[3][2] = {{28.0f, 17.0f}, {-37.0f, 24.0f}, {61.0f, -13.0f}};
  const float light_pos[3] = {1.7f, 2.6f, 2.9f}, view_pos[3] = {0.0f, 0.45f, 4.2f};
  const float panel_color[4] = {0.02f, 0.04f, 0.12f, 0.6f};
  const float title_color[4] = {1.0f, 0.84f, 0.2f, 1.0f};
  const float info_color[4] = {0.55f, 0.9f, 1.0f, 0.9f};
  GLFWwindow* window;
  GLuint vao[2], vbo[2], atlas, scene_prog, text_prog;
  float proj[16], view[16], model[16], hud[16];
  int i, f, k, r, c;

  glfwInit();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  window = glfwCreateWindow(W, H, "Text overlay", NULL, NULL);
  if (!window) return 1;
  glfwMakeContextCurrent(window);
  glfwSetFramebufferSizeCallback(window, framebuffer_size_callback);
  if (!load_gl(glfwGetProcAddress)) return 1;

  scene_prog = link_program(scene_vs, scene_fs);
  text_prog = link_program(text_vs, text_fs);

  /* The cube: two triangles a face, counter-clockwise seen from outside. */
  for (f = 0; f < 6; ++f) {
    static const float corner[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {1, 1}, {-1, 1}, {-1, -1}};
    const int axis = f / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
    const float sgn = (f % 2) ? 1.0f : -1.0f;
    for (k = 0; k < 6; ++k) {
      float* o = cube + (f * 6 + k) * 6;
      const int kk = sgn > 0 ? k : 5 - k;
      o[axis] = 0.5f * sgn, o[u] = 0.5f * corner[kk][0], o[v] = 0.5f * corner[kk][1];
      o[3] = o[4] = o[5] = 0.0f;
      o[3 + axis] = sgn;
    }
  }
  glGenVertexArrays(2, vao);
  glGenBuffers(2, vbo);
  glBindVertexArray(vao[0]);
  glBindBuffer(GL_ARRAY_BUFFER, vbo[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof cube, cube, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)0);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)(3 * sizeof(float)));
  /* The text VBO: storage for MAX_CHARS quads, refilled for every string. */
  glBindVertexArray(vao[1]);
  glBindBuffer(GL_ARRAY_BUFFER, vbo[1]);
  glBufferData(GL_ARRAY_BUFFER, MAX_CHARS * 6 * 4 * sizeof(float), NULL, GL_DYNAMIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), (void*)0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindVertexArray(0);

  /* The font atlas: cleared, then one 5x7 upload a glyph (rows of 5 bytes: alignment 1). */
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glGenTextures(1, &atlas);
  glBindTexture(GL_TEXTURE_2D, atlas);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, ATLAS_W, ATLAS_H, 0, GL_RED, GL_UNSIGNED_BYTE, zeros);
  for (i = 0; i < NUM_GLYPHS; ++i) {
    for (r = 0; r < 7; ++r)
      for (c = 0; c < 5; ++c) glyph[r * 5 + c] = (font[i].rows[r] >> (4 - c)) & 1 ? 255 : 0;
    glTexSubImage2D(GL_TEXTURE_2D, 0, GLYPH_X(i), GLYPH_Y(i), 5, 7, GL_RED, GL_UNSIGNED_BYTE, glyph);
  }
  memset(solid, 255, sizeof solid);
  glTexSubImage2D(GL_TEXTURE_2D, 0, SOLID_X, SOLID_Y, 4, 4, GL_RED, GL_UNSIGNED_BYTE, solid);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_R, GL_ONE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_G, GL_ONE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_B, GL_ONE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_A, GL_RED);

  mat_perspective(proj, 45.0f, (float)W / (float)H, 0.1f, 100.0f);
  memset(view, 0, sizeof view);
  view[0] = view[5] = view[10] = view[15] = 1.0f;
  view[12] = -view_pos[0], view[13] = -view_pos[1], view[14] = -view_pos[2];
  mat_ortho(hud, 0.0f, (float)W, (float)H, 0.0f, -1.0f, 1.0f); /* pixel coordinates, y down */

  while (!glfwWindowShouldClose(window)) {
    if (glfwGetKey(window, GLFW_KEY_ESCAPE) == GLFW_PRESS) glfwSetWindowShouldClose(window, 1);
    /* 1. The scene. */
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glClearColor(0.2f, 0.22f, 0.26f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(scene_prog);
    glUniformMatrix4fv(glGetUniformLocation(scene_prog, "projection"), 1, GL_FALSE, proj);
    glUniformMatrix4fv(glGetUniformLocation(scene_prog, "view"), 1, GL_FALSE, view);
    glUniform3fv(glGetUniformLocation(scene_prog, "lightPos"), 1, light_pos);
    glUniform3fv(glGetUniformLocation(scene_prog, "viewPos"), 1, view_pos);
    glBindVertexArray(vao[0]);
    for (i = 0; i < 3; ++i) {
      model_matrix(model, cube_pos[i][0], cube_pos[i][1], cube_pos[i][2], cube_rot[i][0], cube_rot[i][1],
                   i == 1 ? 1.3f : 1.0f);
      glUniformMatrix4fv(glGetUniformLocation(scene_prog, "model"), 1, GL_FALSE, model);
      glUniform3fv(glGetUniformLocation(scene_prog, "objectColor"), 1, cube_col[i]);
      glDrawArrays(GL_TRIANGLES, 0, 36);
    }

    /* 2. The overlay: no depth test, "over" blending. */
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(text_prog);
    glUniformMatrix4fv(glGetUniformLocation(text_prog, "projection"), 1, GL_FALSE, hud);
    glUniform1i(glGetUniformLocation(text_prog, "text"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, atlas);
    glBindVertexArray(vao[1]);
    render_panel(text_prog, vbo[1], 6.3f, 6.3f, 250.3f, 96.3f, panel_color);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    render_text(text_prog, vbo[1], "TESSEL 3.3!", 12.3f, 12.3f, 3.0f, title_color);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    render_text(text_prog, vbo[1], "FPS: 59.9 (16.7 MS)", 12.3f, 42.3f, 2.0f, info_color);
    render_text(text_prog, vbo[1], "CUBES: 3 TRIS: 36", 12.3f, 60.3f, 2.0f, info_color);
    render_text(text_prog, vbo[1], "X=1.25 Y=-0.50 #7", 12.3f, 78.3f, 2.0f, info_color);
    render_panel(text_prog, vbo[1], 6.3f, 194.3f, 234.3f, 239.3f, panel_color);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    render_text(text_prog, vbo[1], "<HP 100%>", 12.3f, 199.3f, 3.0f, info_color);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    render_text(text_prog, vbo[1], "SCORE+42, LIVES/3?", 12.3f, 223.3f, 2.0f, title_color);
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
