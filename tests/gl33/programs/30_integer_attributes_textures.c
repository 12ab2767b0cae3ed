/*
 * Integers end to end in a 3.3 core context (GLUT + GLEW): vertex attributes read with
 * glVertexAttribIPointer as ivec2 (GL_INT, positions in 1/16 pixel), ivec2 (GL_SHORT, the
 * tile's corner) and uvec4 (GL_UNSIGNED_BYTE: mode, palette shift, vertex id, mask); flat int
 * and uint varyings (the provoking vertex is the last one of each triangle); integer math in
 * GLSL - &, |, ^, <<, >>, %, / on int and uint, uint multiplication that wraps, a switch on the
 * tile's mode; and integer textures sampled with texelFetch: a GL_R32UI texture and a
 * GL_RGBA8UI texture through usampler2D, a GL_R32I texture with negative values through
 * isampler2D (with textureSize). Both 32-bit textures hold values above 2^24 whose low bits
 * are shown, so every bit of a texel must survive. Six 96x96 tiles, one per mode, drawn with
 * one glDrawArrays into the normal RGBA8 window.
 */
#include "common.h"

#define TS 12 /* texture size: 12 texels of 8 pixels across a tile */

typedef struct {
  GLint pos[2];
  GLshort corner[2];
  GLubyte info[4];
} Vertex;

static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in ivec2 position;  // 1/16 pixel\n"
    "layout(location = 1) in ivec2 corner;\n"
    "layout(location = 2) in uvec4 info;\n"
    "flat out int mode;\n"
    "flat out ivec2 origin;\n"
    "flat out uint key;\n"
    "flat out int shift;\n"
    "void main() {\n"
    "  mode = int(info.x);\n"
    "  shift = int(info.y);\n"
    "  origin = corner;\n"
    "  key = (info.z << 8u) | (info.w ^ 0x5Au);\n"
    "  vec2 p = vec2(position >> 4) + vec2(position & 15) / 16.0;\n"
    "  gl_Position = vec4(p / vec2(160.0, 120.0) - 1.0, 0.0, 1.0);\n"
    "}\n";

static const char* fs =
    "#version 330 core\n"
    "flat in int mode;\n"
    "flat in ivec2 origin;\n"
    "flat in uint key;\n"
    "flat in int shift;\n"
    "uniform usampler2D hashes;  // GL_R32UI\n"
    "uniform isampler2D heights; // GL_R32I\n"
    "uniform usampler2D bytes;   // GL_RGBA8UI\n"
    "out vec4 frag;\n"
    "vec3 palette(int i) {\n"
    "  switch (i & 7) {\n"
    "  case 0: return vec3(0.1, 0.1, 0.2);\n"
    "  case 1: return vec3(0.9, 0.2, 0.2);\n"
    "  case 2: return vec3(0.2, 0.8, 0.3);\n"
    "  case 3: return vec3(0.2, 0.3, 0.9);\n"
    "  case 4: case 5: return vec3(0.9, 0.8, 0.2);\n"
    "  case 6: return vec3(0.8, 0.3, 0.9);\n"
    "  default: return vec3(0.9);\n"
    "  }\n"
    "}\n"
    "void main() {\n"
    "  ivec2 p = ivec2(gl_FragCoord.xy) - origin;\n"
    "  ivec2 t = clamp(p / 8, ivec2(0), ivec2(11));\n"
    "  vec3 c;\n"
    "  switch (mode) {\n"
    "  case 0: {  // checker and stripes from shifts and xor\n"
    "    int a = ((p.x >> 3) ^ (p.y >> 3)) & 1;\n"
    "    int b = (p.x + p.y) % 12 < 4 ? 2 : 0;\n"
    "    c = palette((a | b) + shift);\n"
    "    break;\n"
    "  }\n"
    "  case 1: {  // R32UI: a 32-bit hash per texel, split into bytes\n"
    "    uint v = texelFetch(hashes, t, 0).r;\n"
    "    c = vec3((v >> 24u) & 0xFFu, (v >> 16u) & 0xFFu, (v >> 8u) & 0xFFu) / 255.0;\n"
    "    if ((v & 3u) == 0u) c *= 0.5;\n"
    "    break;\n"
    "  }\n"
    "  case 2: {  // R32I: signed heights\n"
    "    int h = texelFetch(heights, t, 0).r;\n"
    "    ivec2 size = textureSize(heights, 0);\n"
    "    int a = abs(h);\n"
    "    float f = float((a >> 16) % 256) / 255.0, g = float(a & 0xFF) / 255.0;\n"
    "    c = h < 0 ? vec3(f, g, 0.2) : vec3(g, f, 0.5 * f);\n"
    "    if (t.x == size.x - 1 || t.y == size.y - 1) c += vec3(0.3);\n"
    "    break;\n"
    "  }\n"
    "  case 3: {  // RGBA8UI, inverted with ^ on odd texels\n"
    "    uvec4 b = texelFetch(bytes, t, 0);\n"
    "    if (((t.x + t.y) & 1) == 1) b ^= uvec4(0xFFu, 0xFFu, 0xFFu, 0u);\n"
    "    c = vec3(b.rgb) / 255.0;\n"
    "    break;\n"
    "  }\n"
    "  case 4: {  // Sierpinski from &, wrapping uint multiply\n"
    "    uint h = uint(p.x) * 2654435761u;\n"
    "    h ^= h >> 15u;\n"
    "    bool on = ((p.x >> 1) & (p.y >> 1)) == 0;\n"
    "    c = on ? palette(int(h >> 29u)) : vec3(0.05);\n"
    "    break;\n"
    "  }\n"
    "  default: {  // the flat key of each triangle's provoking (last) vertex\n"
    "    uint id = key >> 8u;\n"
    "    c = palette(int(id % 7u)) * (0.6 + 0.4 * float((key & 0xFFu) % 3u) / 2.0);\n"
    "    if ((uint(p.y) / 12u) % 2u == 1u) c *= 0.75;\n"
    "    break;\n"
    "  }\n"
    "  }\n"
    "  frag = vec4(c, 1.0);\n"
    "}\n";

static GLuint prog, vao, tex[3];

static void display(void) {
  glClearColor(0.15f, 0.15f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glUseProgram(prog);
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 36);
  check_gl("display");
  glutSwapBuffers();
}

static GLuint int_texture(GLint internal, GLenum format, GLenum type, const void* data) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, internal, TS, TS, 0, format, type, data);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}

int main(int argc, char** argv) {
  static const int quad[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
  Vertex v[36];
  GLuint hashes[TS * TS], vbo;
  GLint heights[TS * TS];
  GLubyte bytes[TS * TS * 4];
  int i, k, x, y;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "integer attributes textures");
  prog = link_program(vs, fs);

  /* Six tiles of 96x96 pixels, corners a fraction of a pixel off the pixel grid. */
  for (i = 0; i < 6; ++i) {
    const int cx = 8 + 104 * (i % 3), cy = 128 - 104 * (i / 3);
    for (k = 0; k < 6; ++k) {
      Vertex* p = &v[i * 6 + k];
      p->pos[0] = cx * 16 + 5 + quad[k][0] * (96 * 16 - 2);
      p->pos[1] = cy * 16 + 3 + quad[k][1] * (96 * 16 - 1);
      p->corner[0] = (GLshort)cx;
      p->corner[1] = (GLshort)cy;
      p->info[0] = (GLubyte)i;
      p->info[1] = (GLubyte)(i + 1);
      p->info[2] = (GLubyte)(i * 6 + k);
      p->info[3] = (GLubyte)(0xA0 + 7 * k);
    }
  }
  for (y = 0; y < TS; ++y)
    for (x = 0; x < TS; ++x) {
      unsigned int h = (unsigned int)(x * TS + y + 1) * 2654435761u;
      h ^= h >> 13;
      h *= 0x5bd1e995u;
      hashes[y * TS + x] = h ^ (h >> 15);
      /* large magnitudes: all 32 bits matter */
      heights[y * TS + x] =
          ((x - 6) * (y - 5) * 37 - 100 + ((x * y) % 3) * 1000) * 65536 + ((x * 37 + y * 91) & 0xFF);
      bytes[(y * TS + x) * 4 + 0] = (GLubyte)(x * 21);
      bytes[(y * TS + x) * 4 + 1] = (GLubyte)(y * 21);
      bytes[(y * TS + x) * 4 + 2] = (GLubyte)(255 - (x + y) * 10);
      bytes[(y * TS + x) * 4 + 3] = 255;
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glActiveTexture(GL_TEXTURE0);
  tex[0] = int_texture(GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, hashes);
  glActiveTexture(GL_TEXTURE1);
  tex[1] = int_texture(GL_R32I, GL_RED_INTEGER, GL_INT, heights);
  glActiveTexture(GL_TEXTURE2);
  tex[2] = int_texture(GL_RGBA8UI, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, bytes);
  glUseProgram(prog);
  glUniform1i(glGetUniformLocation(prog, "hashes"), 0);
  glUniform1i(glGetUniformLocation(prog, "heights"), 1);
  glUniform1i(glGetUniformLocation(prog, "bytes"), 2);

  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STATIC_DRAW);
  glVertexAttribIPointer(0, 2, GL_INT, sizeof(Vertex), (void*)0);
  glVertexAttribIPointer(1, 2, GL_SHORT, sizeof(Vertex), (void*)(2 * sizeof(GLint)));
  glVertexAttribIPointer(2, 4, GL_UNSIGNED_BYTE, sizeof(Vertex),
                         (void*)(2 * sizeof(GLint) + 2 * sizeof(GLshort)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glEnableVertexAttribArray(2);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
