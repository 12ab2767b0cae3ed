/*
 * Buffer textures of every kind of GL 3.3 Table 3.15 (GLUT + GLEW, 3.3 core): twelve
 * GL_TEXTURE_BUFFER textures over three buffer objects - one of hashed bytes read as
 * GL_R16, GL_RG8, GL_RGBA16, GL_RGBA8I, GL_RG16I, GL_R32I, GL_RGBA8UI, GL_RG16UI and GL_RGBA32UI,
 * one of floats read as GL_R32F and GL_RG32F, one of halves read as GL_RGBA16F - sampled with
 * texelFetch through samplerBuffer, isamplerBuffer and usamplerBuffer, plus textureSize. Each
 * 80x80 panel shows 100 texels (10x10 cells of 8 pixels); a cell's colour is made of the
 * texel's components, so a component read from the wrong byte, with the wrong sign or width,
 * or a missing component not 0 (alpha 1) changes the picture; texels past the buffer's end
 * read 0. The byte buffer is given a new store of twice the size and partly rewritten after the
 * textures were made: they read the store as it is at the draw.
 */
#include "common.h"

#define BYTES 4096

static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 position;\n"
    "void main() { gl_Position = vec4(position, 0.0, 1.0); }\n";

static const char* fs =
    "#version 330 core\n"
    "uniform samplerBuffer r16, rg8, rgba16, r32f, rg32f, rgba16f;\n"
    "uniform isamplerBuffer rgba8i, rg16i, r32i;\n"
    "uniform usamplerBuffer rgba8ui, rg16ui, rgba32ui;\n"
    "out vec4 frag;\n"
    "vec3 signed_bytes(ivec4 v) {\n"
    "  return vec3(v.xyz & 255) / 255.0 * (v.x < 0 ? 0.6 : 1.0) + (v.w == 1 ? 0.0 : 0.2);\n"
    "}\n"
    "void main() {\n"
    "  ivec2 q = ivec2(gl_FragCoord.xy);\n"
    "  int panel = q.x / 80 + 4 * (q.y / 80);\n"
    "  ivec2 cell = (q % 80) / 8;\n"
    "  // RGBA32UI has 256 texels: its last 24 cells are past the end\n"
    "  int i = cell.y * 10 + cell.x + (panel == 8 ? 180 : 37 * panel);\n"
    "  vec3 c;\n"
    "  switch (panel) {\n"
    "  case 0: { vec4 v = texelFetch(r16, i); c = vec3(v.x, fract(v.x * 256.0), v.y + v.z) * v.w; break; }\n"
    "  case 1: { vec4 v = texelFetch(rg8, i); c = vec3(v.xy, v.z) * v.w; break; }\n"
    "  case 2: { c = texelFetch(rgba16, i).xyz * texelFetch(rgba16, i).w; break; }\n"
    "  case 3: c = signed_bytes(texelFetch(rgba8i, i)); break;\n"
    "  case 4: {\n"
    "    ivec4 v = texelFetch(rg16i, i);\n"
    "    c = vec3(v.x >> 8 & 255, v.y & 255, v.x < 0 ? 255 : 0) / 255.0;\n"
    "    if (v.z != 0 || v.w != 1) c = vec3(1.0, 0.0, 1.0);\n"
    "    break;\n"
    "  }\n"
    "  case 5: {\n"
    "    ivec4 v = texelFetch(r32i, i);\n"
    "    c = vec3(v.x >> 24 & 255, v.x >> 12 & 255, v.x & 255) / 255.0;\n"
    "    if (v.x < 0) c = c.bgr;\n"
    "    if (v.y != 0 || v.z != 0 || v.w != 1) c = vec3(1.0, 0.0, 1.0);\n"
    "    break;\n"
    "  }\n"
    "  case 6: { uvec4 v = texelFetch(rgba8ui, i); c = vec3(v.xyz ^ (v.www >> 1u)) / 255.0; break; }\n"
    "  case 7: {\n"
    "    uvec4 v = texelFetch(rg16ui, i);\n"
    "    c = vec3(v.x >> 8u, v.y >> 8u, (v.x ^ v.y) & 255u) / 255.0;\n"
    "    if (v.z != 0u || v.w != 1u) c = vec3(1.0, 0.0, 1.0);\n"
    "    break;\n"
    "  }\n"
    "  case 8: { uvec4 v = texelFetch(rgba32ui, i); c = vec3(v.xyz >> 24u) / 255.0 + vec3(v.w & 1u) * 0.1; "
    "break; }\n"
    "  case 9: { vec4 v = texelFetch(r32f, i); c = vec3(fract(v.x), fract(v.x * 0.37), v.w * 0.5); break; }\n"
    "  case 10: { vec4 v = texelFetch(rg32f, i); c = vec3(fract(v.xy), v.z + 0.5 * v.w); break; }\n"
    "  default: c = texelFetch(rgba16f, i).xyz * texelFetch(rgba16f, i).w; break;\n"
    "  }\n"
    "  // a line of textureSize in each panel's top row of pixels\n"
    "  if (q.y % 80 == 79) {\n"
    "    int sizes[12] = int[12](textureSize(r16), textureSize(rg8), textureSize(rgba16), "
    "textureSize(rgba8i),\n"
    "        textureSize(rg16i), textureSize(r32i), textureSize(rgba8ui), textureSize(rg16ui),\n"
    "        textureSize(rgba32ui), textureSize(r32f), textureSize(rg32f), textureSize(rgba16f));\n"
    "    c = vec3(q.x % 80 < sizes[panel] / 32 ? 1.0 : 0.0);\n"
    "  }\n"
    "  frag = vec4(c, 1.0);\n"
    "}\n";

static GLuint prog, vao;

static void display(void) {
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glUseProgram(prog);
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  check_gl("display");
  glutSwapBuffers();
}

static GLuint buffer_of(const void* data, size_t size) {
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_TEXTURE_BUFFER, b);
  glBufferData(GL_TEXTURE_BUFFER, (GLsizeiptr)size, data, GL_DYNAMIC_DRAW);
  return b;
}

int main(int argc, char** argv) {
  static const char* names[12] = {"r16",     "rg8",    "rgba16",   "rgba8i", "rg16i", "r32i",
                                  "rgba8ui", "rg16ui", "rgba32ui", "r32f",   "rg32f", "rgba16f"};
  static const GLenum formats[12] = {GL_R16,     GL_RG8,    GL_RGBA16,   GL_RGBA8I, GL_RG16I, GL_R32I,
                                     GL_RGBA8UI, GL_RG16UI, GL_RGBA32UI, GL_R32F,   GL_RG32F, GL_RGBA16F};
  static unsigned char bytes[BYTES];
  static float floats[BYTES / 4];
  static unsigned short halves[BYTES / 2];
  GLuint buffers[3], tex[12];
  unsigned int h = 2166136261u;
  int i;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "buffer texture formats");
  prog = link_program(vs, fs);
  for (i = 0; i < BYTES; ++i) {
    h = (h ^ (unsigned int)i) * 16777619u;
    bytes[i] = (unsigned char)(h >> 13);
  }
  for (i = 0; i < BYTES / 4; ++i) floats[i] = (float)((i * 37) % 101) * 0.173f - 4.0f;
  /* halves between 0.125 and 1: exponents 12..14, any mantissa */
  for (i = 0; i < BYTES / 2; ++i)
    halves[i] = (unsigned short)(0x3000 + ((bytes[i] << 4 | bytes[i + 1]) % 0x0C00));
  buffers[0] = buffer_of(bytes, sizeof bytes / 2);
  buffers[1] = buffer_of(floats, sizeof floats);
  buffers[2] = buffer_of(halves, sizeof halves);
  glGenTextures(12, tex);
  glUseProgram(prog);
  for (i = 0; i < 12; ++i) {
    glActiveTexture(GL_TEXTURE0 + i);
    glBindTexture(GL_TEXTURE_BUFFER, tex[i]);
    glTexBuffer(GL_TEXTURE_BUFFER, formats[i], buffers[i < 9 ? 0 : i < 11 ? 1 : 2]);
    glUniform1i(glGetUniformLocation(prog, names[i]), i);
  }
  /* The byte buffer grows to its full size after the textures were made. */
  glBindBuffer(GL_TEXTURE_BUFFER, buffers[0]);
  glBufferData(GL_TEXTURE_BUFFER, sizeof bytes, bytes, GL_DYNAMIC_DRAW);
  glBufferSubData(GL_TEXTURE_BUFFER, 0, 64, bytes + 1000);

  vao = window_strip();
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
