/*
 * glProvokingVertex in a 3.3 core context (GLUT + GLEW): the same primitives drawn with
 * GL_LAST_VERTEX_CONVENTION (bottom half) and GL_FIRST_VERTEX_CONVENTION (top half), their
 * colours from flat varyings - a vec3 and a flat uint index into a palette - so each
 * primitive takes the colour of the vertex GL 3.3 Table 2.12 names: triangle lists, strips
 * (odd triangles too), fans (the second vertex of each triangle with the first convention),
 * lines, line strips and loops, and an indexed strip cut by primitive restart. A smooth
 * varying scales every colour: only the flat values may move between the halves.
 */
#include <math.h>

#include "common.h"

static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 position;\n"
    "layout(location = 1) in uint id;\n"
    "flat out uint index;\n"
    "flat out vec3 tint;\n"
    "out float shade;\n"
    "uniform vec2 offset;\n"
    "void main() {\n"
    "  index = id;\n"
    "  tint = vec3(float(id & 1u), float((id >> 1u) & 1u), float((id >> 2u) & 1u));\n"
    "  shade = 0.6 + 0.4 * fract(float(id) * 0.37);\n"
    "  gl_Position = vec4(position + offset, 0.0, 1.0);\n"
    "}\n";

static const char* fs =
    "#version 330 core\n"
    "flat in uint index;\n"
    "flat in vec3 tint;\n"
    "in float shade;\n"
    "out vec4 frag;\n"
    "const vec3 palette[8] = vec3[8](vec3(0.9, 0.2, 0.2), vec3(0.2, 0.8, 0.2), vec3(0.2, 0.3, 0.9),\n"
    "    vec3(0.9, 0.9, 0.2), vec3(0.8, 0.3, 0.9), vec3(0.2, 0.9, 0.9), vec3(0.95, 0.6, 0.2),\n"
    "    vec3(0.9, 0.9, 0.9));\n"
    "void main() {\n"
    "  vec3 c = palette[index % 8u] * 0.75 + tint * 0.25;\n"
    "  frag = vec4(c * shade, 1.0);\n"
    "}\n";

typedef struct {
  GLfloat x, y;
  GLuint id;
} Vertex;

#define NV 64
static Vertex verts[NV];
static GLuint prog, vao, offset_loc;
static GLushort restart_indices[11] = {0, 1, 2, 3, 4, 0xFFFF, 5, 6, 7, 8, 9};

/* x, y in a 320x120 half, as clip coordinates of the bottom half */
static void put(int i, float x, float y, unsigned id) {
  verts[i].x = x / 160.0f - 1.0f;
  verts[i].y = y / 120.0f - 1.0f;
  verts[i].id = id;
}

static void draw_set(void) {
  glDrawArrays(GL_TRIANGLES, 0, 6);
  glDrawArrays(GL_TRIANGLE_STRIP, 6, 6);
  glDrawArrays(GL_TRIANGLE_FAN, 12, 6);
  glDrawArrays(GL_LINES, 18, 6);
  glDrawArrays(GL_LINE_STRIP, 24, 5);
  glDrawArrays(GL_LINE_LOOP, 29, 4);
  glEnable(GL_PRIMITIVE_RESTART);
  glPrimitiveRestartIndex(0xFFFF);
  glDrawElementsBaseVertex(GL_TRIANGLE_STRIP, 11, GL_UNSIGNED_SHORT, 0, 33);
  glDisable(GL_PRIMITIVE_RESTART);
}

static void display(void) {
  GLint pv = 0;
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glUseProgram(prog);
  glBindVertexArray(vao);
  glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
  glUniform2f((GLint)offset_loc, 0.0f, 0.0f);
  draw_set();
  glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
  glGetIntegerv(GL_PROVOKING_VERTEX, &pv);
  if (pv != GL_FIRST_VERTEX_CONVENTION) fprintf(stderr, "provoking vertex state: 0x%x\n", pv);
  glUniform2f((GLint)offset_loc, 0.0f, 1.0f);
  draw_set();
  glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  GLuint vbo, ebo;
  int i;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "provoking vertex");
  prog = link_program(vs, fs);
  offset_loc = (GLuint)glGetUniformLocation(prog, "offset");
  /* 0-5: two triangles */
  put(0, 4, 8, 1), put(1, 50, 10, 2), put(2, 22, 60, 3);
  put(3, 30, 70, 4), put(4, 62, 20, 5), put(5, 64, 110, 6);
  /* 6-11: a strip of four triangles */
  for (i = 0; i < 6; ++i) put(6 + i, 68.0f + 14.0f * (float)i, (i & 1) ? 100.0f : 12.0f, (unsigned)(i + 1));
  /* 12-17: a fan of four triangles around (175, 50) */
  put(12, 175, 50, 0);
  for (i = 0; i < 5; ++i) {
    const float a = 0.3f + 1.1f * (float)i;
    put(13 + i, 175.0f + 35.0f * (float)cos(a), 50.0f + 35.0f * (float)sin(a), (unsigned)(i + 1));
  }
  /* 18-23: three lines; 24-28: a line strip; 29-32: a loop */
  put(18, 250, 10, 1), put(19, 310, 30, 2), put(20, 250, 40, 3);
  put(21, 310, 20, 4), put(22, 245, 60, 5), put(23, 315, 62, 6);
  for (i = 0; i < 5; ++i) put(24 + i, 250.0f + 15.0f * (float)i, (i & 1) ? 70.0f : 85.0f, (unsigned)(i + 3));
  put(29, 255, 92, 1), put(30, 310, 95, 2), put(31, 305, 116, 5), put(32, 258, 112, 6);
  /* 33-42: an indexed strip of ten vertices cut in two by the restart index */
  for (i = 0; i < 10; ++i)
    put(33 + i, 140.0f + 10.0f * (float)(i % 5) + (i >= 5 ? 55.0f : 0.0f), ((i % 5) & 1) ? 118.0f : 90.0f,
        (unsigned)(i + 1));

  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), (void*)0);
  glVertexAttribIPointer(1, 1, GL_UNSIGNED_INT, sizeof(Vertex), (void*)(2 * sizeof(GLfloat)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glGenBuffers(1, &ebo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof restart_indices, restart_indices, GL_STATIC_DRAW);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
