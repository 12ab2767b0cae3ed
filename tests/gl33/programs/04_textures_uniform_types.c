/*
 * Textures on several units and uniforms of every kind, in a 3.3 core context: two textures
 * (one uploaded from GL_FLOAT RGB data, one from bytes, with different filters and wraps) on
 * units 0 and 3 read through sampler uniforms; an array of structs, an int, a uint, a bool,
 * a mat2, a mat3 and a vec3 array set with glUniform*; vertices written through
 * glMapBufferRange and patched with glBufferSubData; glDrawElements with 32-bit indices.
 */
#include "common.h"

static const char* vs =
    "#version 330\n"
    "layout(location = 0) in vec2 pos;\n"
    "layout(location = 1) in vec2 uv;\n"
    "uniform mat2 spin;\n"
    "uniform mat3 place;\n"
    "out vec2 tc;\n"
    "void main() {\n"
    "  tc = uv;\n"
    "  vec3 p = place * vec3(spin * pos, 1.0);\n"
    "  gl_Position = vec4(p.xy, 0.0, 1.0);\n"
    "}\n";

static const char* fs =
    "#version 330\n"
    "struct Band { vec3 color; float edge; };\n"
    "uniform Band bands[3];\n"
    "uniform sampler2D smooth_tex;\n"
    "uniform sampler2D sharp_tex;\n"
    "uniform int mode;\n"
    "uniform uint stripes;\n"
    "uniform bool invert;\n"
    "uniform vec3 weights[2];\n"
    "in vec2 tc;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  vec3 a = texture(smooth_tex, tc).rgb;\n"
    "  vec3 b = texture(sharp_tex, tc * 2.0).rgb;\n"
    "  vec3 c = a * weights[0] + b * weights[1];\n"
    "  for (int i = 0; i < 3; ++i)\n"
    "    if (tc.x > bands[i].edge) c = mix(c, bands[i].color, 0.25);\n"
    "  if (mode == 2 && (uint(tc.y * 16.0) % stripes) == 0u) c *= 0.5;\n"
    "  if (invert) c = vec3(1.0) - c;\n"
    "  frag = vec4(c, 1.0);\n"
    "}\n";

static GLuint prog, vao, tex[2];

static void display(void) {
  const float spin[4] = {0.8660254f, 0.5f, -0.5f, 0.8660254f}; /* 30 degrees, column-major */
  const float place[9] = {0.8f, 0.0f, 0.0f, 0.0f, 0.8f, 0.0f, -0.1f, 0.05f, 1.0f};
  const float weights[6] = {0.7f, 0.6f, 0.5f, 0.4f, 0.5f, 0.6f};
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glUseProgram(prog);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glActiveTexture(GL_TEXTURE3);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glUniform1i(glGetUniformLocation(prog, "smooth_tex"), 0);
  glUniform1i(glGetUniformLocation(prog, "sharp_tex"), 3);
  glUniformMatrix2fv(glGetUniformLocation(prog, "spin"), 1, GL_FALSE, spin);
  glUniformMatrix3fv(glGetUniformLocation(prog, "place"), 1, GL_FALSE, place);
  glUniform3fv(glGetUniformLocation(prog, "weights"), 2, weights);
  glUniform3f(glGetUniformLocation(prog, "bands[0].color"), 1.0f, 0.0f, 0.0f);
  glUniform1f(glGetUniformLocation(prog, "bands[0].edge"), 0.3f);
  glUniform3f(glGetUniformLocation(prog, "bands[1].color"), 0.0f, 1.0f, 0.0f);
  glUniform1f(glGetUniformLocation(prog, "bands[1].edge"), 0.55f);
  glUniform3f(glGetUniformLocation(prog, "bands[2].color"), 0.0f, 0.0f, 1.0f);
  glUniform1f(glGetUniformLocation(prog, "bands[2].edge"), 0.8f);
  glUniform1i(glGetUniformLocation(prog, "mode"), 2);
  glUniform1ui(glGetUniformLocation(prog, "stripes"), 3u);
  glUniform1i(glGetUniformLocation(prog, "invert"), 0);
  glBindVertexArray(vao);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, (void*)0);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static float smooth[8 * 8 * 3];
  static unsigned char sharp[4 * 4 * 4];
  static const unsigned int idx[6] = {0, 1, 2, 2, 1, 3};
  GLuint vbo, ibo;
  float* v;
  int i, j;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "textures and uniform types");
  prog = link_program(vs, fs);
  for (j = 0; j < 8; ++j)
    for (i = 0; i < 8; ++i) {
      smooth[(j * 8 + i) * 3] = (float)i / 7.0f;
      smooth[(j * 8 + i) * 3 + 1] = (float)j / 7.0f;
      smooth[(j * 8 + i) * 3 + 2] = 0.5f;
    }
  for (i = 0; i < 16; ++i) {
    sharp[i * 4] = (unsigned char)((i * 53) % 256);
    sharp[i * 4 + 1] = (unsigned char)((i % 2) ? 220 : 30);
    sharp[i * 4 + 2] = (unsigned char)((i / 4) * 80);
    sharp[i * 4 + 3] = 255;
  }
  glGenTextures(2, tex);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 8, 8, 0, GL_RGB, GL_FLOAT, smooth);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, sharp);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);

  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, 16 * sizeof(float), NULL, GL_DYNAMIC_DRAW);
  v = (float*)glMapBufferRange(GL_ARRAY_BUFFER, 0, 16 * sizeof(float),
                               GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT);
  if (!v) return 1;
  for (i = 0; i < 4; ++i) {
    v[i * 4] = (i & 1) ? 1.0f : -1.0f;
    v[i * 4 + 1] = (i & 2) ? 1.0f : -1.0f;
    v[i * 4 + 2] = (i & 1) ? 1.0f : 0.0f;
    v[i * 4 + 3] = (i & 2) ? 1.0f : 0.0f;
  }
  glUnmapBuffer(GL_ARRAY_BUFFER);
  {
    const float corner[2] = {1.1f, 1.05f}; /* the last vertex moved out a little */
    glBufferSubData(GL_ARRAY_BUFFER, 12 * sizeof(float), sizeof corner, corner);
  }
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float), (void*)0);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float), (void*)(2 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glGenBuffers(1, &ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
