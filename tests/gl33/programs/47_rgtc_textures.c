/*
 * RGTC compressed textures (GL 3.3 §3.8.3, GLUT + GLEW, 3.3 core): blocks written by hand -
 * both of RGTC's block modes (e0 > e1: six interpolated steps; e0 <= e1: four, and the range's
 * ends), signed endpoints down to -128 - uploaded with glCompressedTexImage2D as
 * GL_COMPRESSED_RED_RGTC1, GL_COMPRESSED_SIGNED_RED_RGTC1, GL_COMPRESSED_RG_RGTC2 and
 * GL_COMPRESSED_SIGNED_RG_RGTC2, one of them 30x18 (blocks past the edge), one partly replaced
 * by glCompressedTexSubImage2D; a texture given uncompressed texels with glTexImage2D (two
 * values per block, which any encoder keeps exactly); the blocks read back with
 * glGetCompressedTexImage and uploaded again into a 2D array layer. Six panels sample them with
 * texelFetch and texture() (GL_LINEAR); a wrong GL_TEXTURE_COMPRESSED or image size query
 * paints a magenta bar.
 */
#include "common.h"

#define S 64

static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 position;\n"
    "void main() { gl_Position = vec4(position, 0.0, 1.0); }\n";

static const char* fs =
    "#version 330 core\n"
    "uniform sampler2D red, sred, rg, srg, small, encoded;\n"
    "uniform sampler2DArray copies;\n"
    "uniform bool bad;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  ivec2 q = ivec2(gl_FragCoord.xy);\n"
    "  int panel = q.x / 80 + 4 * (q.y / 120);\n"
    "  ivec2 t = ivec2(q.x % 80, q.y % 120);\n"
    "  vec2 uv = (vec2(t) + 0.5) / vec2(80.0, 120.0);\n"
    "  vec3 c = vec3(0.0);\n"
    "  if (t.x < 64 && t.y < 64) {\n"
    "    if (panel == 0) c = vec3(texelFetch(red, t, 0).r);\n"
    "    else if (panel == 1) c = vec3(texelFetch(sred, t, 0).r * 0.5 + 0.5, 0.2, 0.2);\n"
    "    else if (panel == 2) c = vec3(texelFetch(rg, t, 0).rg, 0.3);\n"
    "    else if (panel == 3) c = vec3(texelFetch(srg, t, 0).rg * 0.5 + 0.5, 0.6);\n"
    "    else if (panel == 4) c = vec3(texelFetch(encoded, t, 0).r, 0.1, texelFetch(encoded, t, 0).a);\n"
    "    else if (panel == 5) c = vec3(texelFetch(copies, ivec3(t, 1), 0).rg, 0.9);\n"
    "    else if (panel == 6) c = vec3(texture(rg, uv * 1.3).rg, texture(red, uv).r);\n"
    "    else c = vec3(texture(small, uv * 1.6 - 0.2).r, texture(sred, uv).r * 0.5 + 0.5, 0.5);\n"
    "  } else if (panel == 7 && t.y >= 64) {\n"
    "    c = vec3(texelFetch(small, ivec2(t.x % 30, (t.y - 64) % 18), 0).r);\n"
    "  }\n"
    "  if (bad && q.y > 110 && q.y < 130) c = vec3(1.0, 0.0, 1.0);\n"
    "  frag = vec4(c, 1.0);\n"
    "}\n";

static GLuint prog, vao, tex[7];
static int bad = 0;

static void display(void) {
  int i;
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glUseProgram(prog);
  glUniform1i(glGetUniformLocation(prog, "bad"), bad);
  for (i = 0; i < 7; ++i) {
    glActiveTexture(GL_TEXTURE0 + i);
    glBindTexture(i == 6 ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D, tex[i]);
  }
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  check_gl("display");
  glutSwapBuffers();
}

/* One channel block: endpoints e0, e1 and a code per texel from a hash. */
static void channel_block(unsigned char* b, int e0, int e1, unsigned seed) {
  unsigned long long codes = 0;
  int t;
  b[0] = (unsigned char)e0;
  b[1] = (unsigned char)e1;
  for (t = 0; t < 16; ++t) {
    seed = seed * 1103515245u + 12345u;
    codes |= (unsigned long long)((seed >> 16) & 7u) << (3 * t);
  }
  for (t = 0; t < 6; ++t) b[2 + t] = (unsigned char)(codes >> (8 * t));
}

/* Blocks of a w x h image with `channels` channels; signed endpoints when `sgn`. */
static size_t make_blocks(unsigned char* out, int w, int h, int channels, int sgn, unsigned salt) {
  const int bw = (w + 3) / 4, bh = (h + 3) / 4;
  int bx, by, c;
  size_t n = 0;
  for (by = 0; by < bh; ++by)
    for (bx = 0; bx < bw; ++bx)
      for (c = 0; c < channels; ++c) {
        const unsigned k = (unsigned)(by * bw + bx) * 7u + (unsigned)c * 13u + salt;
        int e0, e1;
        if (sgn) {
          e0 = (int)(k * 37u % 256u) - 128;
          e1 = (int)(k * 91u % 256u) - 128;
          if ((bx + by) % 5 == 0) e0 = -128; /* -128 reads as -1 */
        } else {
          e0 = (int)(k * 37u % 256u);
          e1 = (int)(k * 91u % 256u);
        }
        channel_block(out + n, e0, e1, k * 2654435761u);
        n += 8;
      }
  return n;
}

static GLuint texture2d(void) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

int main(int argc, char** argv) {
  static const char* names[7] = {"red", "sred", "rg", "srg", "small", "encoded", "copies"};
  static unsigned char blocks[S * S * 2], patch[16 * 16 * 2], texels[S * S * 4], back[S * S * 2];
  GLint compressed = 0, size = 0;
  size_t n;
  int i, x, y;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "rgtc textures");
  prog = link_program(vs, fs);

  tex[0] = texture2d();
  n = make_blocks(blocks, S, S, 1, 0, 1);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RED_RGTC1, S, S, 0, (GLsizei)n, blocks);
  /* a 16x16 patch at (16, 32) replaced */
  n = make_blocks(patch, 16, 16, 1, 0, 99);
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 16, 32, 16, 16, GL_COMPRESSED_RED_RGTC1, (GLsizei)n, patch);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &compressed);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
  if (!compressed || size != S * S / 2) bad = 1;

  tex[1] = texture2d();
  n = make_blocks(blocks, S, S, 1, 1, 2);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_SIGNED_RED_RGTC1, S, S, 0, (GLsizei)n, blocks);
  tex[2] = texture2d();
  n = make_blocks(blocks, S, S, 2, 0, 3);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RG_RGTC2, S, S, 0, (GLsizei)n, blocks);
  /* the RG blocks read back, into layer 1 of a 2D array */
  glGetCompressedTexImage(GL_TEXTURE_2D, 0, back);
  tex[3] = texture2d();
  n = make_blocks(blocks, S, S, 2, 1, 4);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_SIGNED_RG_RGTC2, S, S, 0, (GLsizei)n, blocks);
  tex[4] = texture2d();
  n = make_blocks(blocks, 30, 18, 1, 0, 5);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RED_RGTC1, 30, 18, 0, (GLsizei)n, blocks);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
  if (size != 8 * 5 * 8) bad = 1;

  /* Uncompressed texels compressed by GL: two values in each 4x4 block. */
  for (y = 0; y < S; ++y)
    for (x = 0; x < S; ++x) {
      const int b = (y / 4) * 16 + x / 4, on = ((x * 7 + y * 3) % 5) < 2;
      texels[(y * S + x) * 4 + 0] = (unsigned char)(on ? (b * 29) % 256 : (b * 53 + 100) % 256);
      texels[(y * S + x) * 4 + 1] = (unsigned char)(on ? 200 : 40);
      texels[(y * S + x) * 4 + 2] = 0;
      texels[(y * S + x) * 4 + 3] = 255;
    }
  tex[5] = texture2d();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RG_RGTC2, S, S, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &compressed);
  if (!compressed) bad = 1;

  glGenTextures(1, &tex[6]);
  glBindTexture(GL_TEXTURE_2D_ARRAY, tex[6]);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glCompressedTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_COMPRESSED_RG_RGTC2, S, S, 2, 0, S * S * 2, NULL);
  glCompressedTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 1, S, S, 1, GL_COMPRESSED_RG_RGTC2, S * S, back);

  glUseProgram(prog);
  for (i = 0; i < 7; ++i) glUniform1i(glGetUniformLocation(prog, names[i]), i);
  vao = window_strip();
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
