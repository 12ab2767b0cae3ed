/*
 * Mipmap level selection made visible, in a GL 3.3 core context (GLUT + GLEW): a 64x64 texture
 * whose seven levels are uploaded one by one with glTexImage2D, each a checkerboard in its own
 * colour (red, orange, yellow, green, blue, violet, grey), so the level a pixel reads shows.
 *  - Bottom: a receding floor, its left half (glScissor) sampled through a sampler object with
 *    GL_NEAREST_MIPMAP_NEAREST, its right half through one with GL_LINEAR_MIPMAP_LINEAR; both
 *    override the texture's own filters.
 *  - Top, four panels with the texture's own parameters (GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST
 *    magnification): textureLod with an explicit LOD per band; textureGrad with explicit,
 *    anisotropic gradients per band (bands on even rows, whole 2x2 quads); textureOffset next
 *    to plain texture() on the magnified level 0; and a second texture object with the same
 *    levels limited by GL_TEXTURE_BASE_LEVEL 1 / GL_TEXTURE_MAX_LEVEL 4, GL_TEXTURE_MIN_LOD 0.5
 *    / GL_TEXTURE_MAX_LOD 2.6 and GL_TEXTURE_LOD_BIAS 0.75, seen in a perspective warp.
 * The panels start on even window rows and their coordinates carry small odd offsets, so no
 * pixel centre sits on a texel edge.
 */
#include "common.h"

#define TEX_SIZE 64
#define LEVELS 7

static const char* floor_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 pos;\n"
    "uniform mat4 mvp;\n"
    "out vec2 uv;\n"
    "void main() { uv = pos.xz * 0.25 + vec2(0.013, 0.029); gl_Position = mvp * vec4(pos, 1.0); }\n";
static const char* floor_fs =
    "#version 330 core\n"
    "in vec2 uv;\n"
    "uniform sampler2D tex;\n"
    "out vec4 frag;\n"
    "void main() { frag = texture(tex, uv); }\n";

static const char* panel_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 corner;\n"
    "out vec2 uv;\n"
    "void main() { uv = corner * 0.5 + 0.5; gl_Position = vec4(corner, 0.0, 1.0); }\n";
static const char* panel_fs =
    "#version 330 core\n"
    "in vec2 uv;\n"
    "uniform sampler2D tex;\n"
    "uniform int mode;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  int band = int(uv.y * 4.0);\n"
    "  if (mode == 0) {\n"
    "    /* Explicit LODs, blending the levels around them. */\n"
    "    float lods[4] = float[4](0.3, 1.6, 2.85, 4.2);\n"
    "    frag = textureLod(tex, uv * vec2(1.37, 1.21) + vec2(0.0071, 0.0033), lods[band]);\n"
    "  } else if (mode == 1) {\n"
    "    /* Gradients in texture coordinates per pixel: x and y differ, the larger wins. */\n"
    "    float g = exp2(float(band) * 1.1 - 5.3);\n"
    "    vec2 dx = vec2(g, 0.2 * g), dy = vec2(0.0, 0.45 * g);\n"
    "    frag = textureGrad(tex, uv * vec2(1.13, 0.97) + vec2(0.0093, 0.0047), dx, dy);\n"
    "  } else if (mode == 2) {\n"
    "    /* Magnified level 0: plain on the left, moved by (3, -2) texels on the right. */\n"
    "    vec2 t = uv * vec2(0.53, 0.61) + vec2(0.0057, 0.0089);\n"
    "    if (uv.x < 0.5) frag = texture(tex, t);\n"
    "    else frag = textureOffset(tex, t, ivec2(3, -2));\n"
    "  } else {\n"
    "    /* A perspective warp: the implicit LOD grows towards the top. */\n"
    "    float z = 1.0 / (1.07 - uv.y);\n"
    "    vec2 t = vec2((uv.x - 0.5) * z * 0.31 + 0.0061, z * 0.23 + 0.0037);\n"
    "    frag = texture(tex, t);\n"
    "  }\n"
    "}\n";

static GLuint floor_prog, panel_prog, floor_vao, panel_vao, tex, tex_limited, samp_nearest, samp_linear;

static void display(void) {
  float proj[16], view[16], mvp[16], r[16], t[16];
  int i;
  glClearColor(0.55f, 0.65f, 0.8f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glActiveTexture(GL_TEXTURE0);

  /* The floor: the lower 128 rows, left half nearest-nearest, right half trilinear. */
  glViewport(0, 0, 320, 128);
  mat_perspective(proj, 40.0f, 320.0f / 128.0f, 0.2f, 80.0f);
  mat_rotate_x(r, 9.3f);
  mat_translate(t, -0.13f, -1.07f, 0.0f);
  mat_mul(view, r, t);
  mat_mul(mvp, proj, view);
  glUseProgram(floor_prog);
  glUniformMatrix4fv(glGetUniformLocation(floor_prog, "mvp"), 1, GL_FALSE, mvp);
  glUniform1i(glGetUniformLocation(floor_prog, "tex"), 0);
  glBindTexture(GL_TEXTURE_2D, tex);
  glBindVertexArray(floor_vao);
  glEnable(GL_SCISSOR_TEST);
  for (i = 0; i < 2; ++i) {
    glScissor(i * 160, 0, 160, 128);
    glBindSampler(0, i ? samp_linear : samp_nearest);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  glDisable(GL_SCISSOR_TEST);
  glBindSampler(0, 0);

  /* The panels: 74x104 pixels each, starting at row 130. */
  glUseProgram(panel_prog);
  glUniform1i(glGetUniformLocation(panel_prog, "tex"), 0);
  glBindVertexArray(panel_vao);
  for (i = 0; i < 4; ++i) {
    glViewport(6 + i * 78, 130, 74, 104);
    glBindTexture(GL_TEXTURE_2D, i == 3 ? tex_limited : tex);
    glUniform1i(glGetUniformLocation(panel_prog, "mode"), i);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  glViewport(0, 0, 320, 240);
  check_gl("display");
  glutSwapBuffers();
}

/* Uploads the seven levels: checkers of cell size max(1, 8 >> level) in the level's colour. */
static void upload_levels(void) {
  static const unsigned char colors[LEVELS][3] = {{230, 50, 40},  {245, 150, 30}, {230, 225, 40},
                                                  {50, 190, 70},  {40, 120, 230}, {140, 60, 210},
                                                  {200, 200, 200}};
  static unsigned char texels[TEX_SIZE * TEX_SIZE * 4];
  int level, x, y;
  for (level = 0; level < LEVELS; ++level) {
    const int size = TEX_SIZE >> level, cell = (8 >> level) > 0 ? (8 >> level) : 1;
    for (y = 0; y < size; ++y)
      for (x = 0; x < size; ++x) {
        unsigned char* p = &texels[(y * size + x) * 4];
        const int dark = ((x / cell) + (y / cell)) % 2;
        p[0] = (unsigned char)(dark ? colors[level][0] / 3 : colors[level][0]);
        p[1] = (unsigned char)(dark ? colors[level][1] / 3 : colors[level][1]);
        p[2] = (unsigned char)(dark ? colors[level][2] / 3 : colors[level][2]);
        p[3] = 255;
      }
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  }
}

int main(int argc, char** argv) {
  static const float floor_verts[4 * 3] = {-30.0f, 0.0f, 0.3f,   30.0f, 0.0f, 0.3f,
                                           -30.0f, 0.0f, -60.0f, 30.0f, 0.0f, -60.0f};
  static const float corners[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
  GLuint b[2];
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "mipmap lod samplers");
  floor_prog = link_program(floor_vs, floor_fs);
  panel_prog = link_program(panel_vs, panel_fs);
  glGenVertexArrays(1, &floor_vao);
  glGenVertexArrays(1, &panel_vao);
  glGenBuffers(2, b);
  glBindVertexArray(floor_vao);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof floor_verts, floor_verts, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, 0);
  glEnableVertexAttribArray(0);
  glBindVertexArray(panel_vao);
  glBindBuffer(GL_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, 0);
  glEnableVertexAttribArray(0);

  /* The full texture: its own filters trilinear for minification, nearest for magnification. */
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  upload_levels();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, LEVELS - 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);

  /* The same levels, limited: levels 1-4 only, LOD clamped to [0.5, 2.6] after a bias of 0.75. */
  glGenTextures(1, &tex_limited);
  glBindTexture(GL_TEXTURE_2D, tex_limited);
  upload_levels();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 4);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 0.5f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 2.6f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0.75f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);

  /* Sampler objects for the floor, overriding the texture's filters. */
  glGenSamplers(1, &samp_nearest);
  glSamplerParameteri(samp_nearest, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glSamplerParameteri(samp_nearest, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glGenSamplers(1, &samp_linear);
  glSamplerParameteri(samp_linear, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glSamplerParameteri(samp_linear, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
