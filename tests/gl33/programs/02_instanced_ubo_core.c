/*
 * Instancing and uniform buffers in a 3.3 core context: a 6x4 grid of squares drawn with one
 * glDrawArraysInstanced (a triangle strip), per-instance offsets (float, divisor 1) and colours
 * (normalized unsigned bytes, divisor 2) next to per-vertex corners, gl_InstanceID, and a
 * std140 uniform block read from a range of a buffer (glUniformBlockBinding,
 * glBindBufferRange at a 256-byte offset). Then fans and strips from one index buffer with
 * glDrawElementsBaseVertex and primitive restart at 0xFFFF.
 */
#include "common.h"

static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 corner;\n"
    "layout(location = 3) in vec2 offset;\n"
    "layout(location = 5) in vec4 color;\n"
    "layout(std140) uniform Scene {\n"
    "  mat4 proj;\n"
    "  vec4 tint;\n"
    "  float scale;\n"
    "  ivec2 grid;\n"
    "};\n"
    "out vec4 vcolor;\n"
    "void main() {\n"
    "  float shade = float(gl_InstanceID % grid.x) / float(grid.x - 1);\n"
    "  vcolor = color * tint * vec4(vec3(0.5 + 0.5 * shade), 1.0);\n"
    "  gl_Position = proj * vec4(corner * scale + offset, 0.0, 1.0);\n"
    "}\n";

static const char* fs =
    "#version 330 core\n"
    "in vec4 vcolor;\n"
    "out vec4 frag;\n"
    "void main() { frag = vcolor; }\n";

static const char* vs2 =
    "#version 330 core\n"
    "layout(location = 0) in vec2 pos;\n"
    "uniform vec2 shift;\n"
    "flat out int id;\n"
    "void main() { id = gl_VertexID; gl_Position = vec4(pos + shift, 0.0, 1.0); }\n";

static const char* fs2 =
    "#version 330 core\n"
    "flat in int id;\n"
    "out vec4 frag;\n"
    "void main() { frag = vec4(float(id % 3) * 0.5, float(id % 2), float(id % 5) * 0.25, 1.0); }\n";

static GLuint prog, prog2, vao, vao2;

static void display(void) {
  glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glUseProgram(prog);
  glBindVertexArray(vao);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, 24);

  glUseProgram(prog2);
  glBindVertexArray(vao2);
  glEnable(GL_PRIMITIVE_RESTART);
  glPrimitiveRestartIndex(0xFFFF);
  glUniform2f(glGetUniformLocation(prog2, "shift"), 0.0f, -0.55f);
  /* Two fans of 5 vertices separated by a restart. */
  glDrawElementsBaseVertex(GL_TRIANGLE_FAN, 11, GL_UNSIGNED_SHORT, (void*)0, 0);
  glUniform2f(glGetUniformLocation(prog2, "shift"), 0.0f, -0.1f);
  /* The same indices on the next 10 vertices (a strip shape) as strips. */
  glDrawElementsBaseVertex(GL_TRIANGLE_STRIP, 11, GL_UNSIGNED_SHORT, (void*)0, 10);
  glDisable(GL_PRIMITIVE_RESTART);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static const float corners[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
  float offsets[48];
  unsigned char colors[12 * 4];
  unsigned char block[256 + 112];
  float verts[40];
  static const unsigned short idx[11] = {0, 1, 2, 3, 4, 0xFFFF, 5, 6, 7, 8, 9};
  GLuint vbo[3], ubo, ibo;
  GLint ok;
  int i;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "instanced ubo core");
  prog = link_program(vs, fs);
  prog2 = link_program(vs2, fs2);
  for (i = 0; i < 24; ++i) {
    offsets[i * 2] = -0.75f + 0.3f * (float)(i % 6);
    offsets[i * 2 + 1] = 0.2f + 0.2f * (float)(i / 6);
  }
  for (i = 0; i < 12; ++i) {
    colors[i * 4] = (unsigned char)(40 + 18 * i);
    colors[i * 4 + 1] = (unsigned char)(250 - 20 * i);
    colors[i * 4 + 2] = (unsigned char)((i * 97) % 256);
    colors[i * 4 + 3] = 255;
  }
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(3, vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, 0);
  glEnableVertexAttribArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, vbo[1]);
  glBufferData(GL_ARRAY_BUFFER, sizeof offsets, offsets, GL_STATIC_DRAW);
  glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, 0, 0);
  glVertexAttribDivisor(3, 1);
  glEnableVertexAttribArray(3);
  glBindBuffer(GL_ARRAY_BUFFER, vbo[2]);
  glBufferData(GL_ARRAY_BUFFER, sizeof colors, colors, GL_STATIC_DRAW);
  glVertexAttribPointer(5, 4, GL_UNSIGNED_BYTE, GL_TRUE, 0, 0);
  glVertexAttribDivisor(5, 2);
  glEnableVertexAttribArray(5);

  /* The uniform block at offset 256 of the buffer, at the offsets std140 gives. */
  {
    const GLuint index = glGetUniformBlockIndex(prog, "Scene");
    GLint size = 0;
    float proj[16], tint[4] = {1.0f, 0.9f, 0.8f, 1.0f}, scale = 0.12f;
    int grid[2] = {6, 4};
    glGetActiveUniformBlockiv(prog, index, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    if (size != 96) {
      fprintf(stderr, "Scene block is %d bytes, not 96\n", size);
      return 1;
    }
    mat_identity(proj);
    proj[0] = 0.9f;
    proj[5] = 0.95f;
    memset(block, 0, sizeof block);
    memcpy(block + 256, proj, 64);
    memcpy(block + 256 + 64, tint, 16);
    memcpy(block + 256 + 80, &scale, 4);
    memcpy(block + 256 + 88, grid, 8);
    glGenBuffers(1, &ubo);
    glBindBuffer(GL_UNIFORM_BUFFER, ubo);
    glBufferData(GL_UNIFORM_BUFFER, sizeof block, block, GL_STATIC_DRAW);
    glUniformBlockBinding(prog, index, 2);
    glBindBufferRange(GL_UNIFORM_BUFFER, 2, ubo, 256, 96);
  }

  /* Two pentagon fans, then the same indices over a zig-zag strip (base vertex 10). */
  for (i = 0; i < 5; ++i) {
    const double a = 2.0 * 3.14159265358979 * i / 5.0;
    verts[i * 2] = (float)(-0.5 + 0.2 * cos(a));
    verts[i * 2 + 1] = (float)(0.2 * sin(a));
    verts[10 + i * 2] = (float)(0.5 + 0.2 * cos(a + 0.3));
    verts[10 + i * 2 + 1] = (float)(0.2 * sin(a + 0.3));
    verts[20 + i * 2] = -0.9f + 0.18f * (float)i;
    verts[20 + i * 2 + 1] = (i % 2) ? 0.15f : 0.0f;
    verts[30 + i * 2] = 0.05f + 0.18f * (float)i;
    verts[30 + i * 2 + 1] = (i % 2) ? 0.0f : 0.15f;
  }
  glGenVertexArrays(1, &vao2);
  glBindVertexArray(vao2);
  glGenBuffers(1, &ibo);
  glBindBuffer(GL_ARRAY_BUFFER, ibo);
  glBufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, 0);
  glEnableVertexAttribArray(0);
  glGenBuffers(1, &ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
  glGetProgramiv(prog, GL_ACTIVE_UNIFORM_BLOCKS, &ok);
  if (ok != 1) return 1;
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
