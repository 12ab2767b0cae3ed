/*
 * GLSL 1.50 as the textbook of the GL 3.x years writes it (Angel and Shreiner's InitShader
 * style): `#version 150` shaders with `in vec4 vPosition; in vec4 vColor;`, attribute
 * locations asked with glGetAttribLocation after linking, positions and colours in one buffer
 * filled by two glBufferSubData calls, a model-view and a projection matrix as uniforms
 * (`uniform mat4 ModelView, Projection;`), a colour cube drawn as GL_TRIANGLES, and a
 * wireframe of its edges as GL_LINES through the same program. A 3.2 core context.
 */
#include "common.h"

static const char* vshader =
    "#version 150\n"
    "in  vec4 vPosition;\n"
    "in  vec4 vColor;\n"
    "out vec4 color;\n"
    "uniform mat4 ModelView;\n"
    "uniform mat4 Projection;\n"
    "uniform vec4 override;\n"
    "void main() {\n"
    "  gl_Position = Projection * ModelView * vPosition;\n"
    "  color = mix(vColor, override, override.a);\n"
    "}\n";

static const char* fshader =
    "#version 150\n"
    "in  vec4 color;\n"
    "out vec4 fColor;\n"
    "void main() { fColor = color; }\n";

static GLuint program, vao;
static int n_tri = 0, n_line = 0;

static void display(void) {
  float proj[16], mv[16], rx[16], ry[16], t[16];
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  mat_perspective(proj, 40.0f, 320.0f / 240.0f, 0.5f, 10.0f);
  mat_rotate_x(rx, 25.0f);
  mat_rotate_y(ry, -35.0f);
  mat_translate(t, 0.0f, 0.0f, -3.2f);
  mat_mul(mv, t, rx);
  mat_mul(mv, mv, ry);
  glUseProgram(program);
  glUniformMatrix4fv(glGetUniformLocation(program, "ModelView"), 1, GL_FALSE, mv);
  glUniformMatrix4fv(glGetUniformLocation(program, "Projection"), 1, GL_FALSE, proj);
  glUniform4f(glGetUniformLocation(program, "override"), 0, 0, 0, 0);
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, n_tri);
  /* The edges, pulled towards the eye so they win the depth test. */
  glUniform4f(glGetUniformLocation(program, "override"), 0.05f, 0.05f, 0.05f, 1.0f);
  glDepthFunc(GL_LEQUAL);
  mat_translate(t, 0.0f, 0.0f, -3.19f);
  mat_mul(mv, t, rx);
  mat_mul(mv, mv, ry);
  glUniformMatrix4fv(glGetUniformLocation(program, "ModelView"), 1, GL_FALSE, mv);
  glDrawArrays(GL_LINES, n_tri, n_line);
  glDepthFunc(GL_LESS);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static const float v[8][4] = {{-0.5f, -0.5f, 0.5f, 1}, {-0.5f, 0.5f, 0.5f, 1},   {0.5f, 0.5f, 0.5f, 1},
                                {0.5f, -0.5f, 0.5f, 1},  {-0.5f, -0.5f, -0.5f, 1}, {-0.5f, 0.5f, -0.5f, 1},
                                {0.5f, 0.5f, -0.5f, 1},  {0.5f, -0.5f, -0.5f, 1}};
  static const float c[8][4] = {{0, 0, 0, 1}, {1, 0, 0, 1}, {1, 1, 0, 1}, {0, 1, 0, 1},
                                {0, 0, 1, 1}, {1, 0, 1, 1}, {1, 1, 1, 1}, {0, 1, 1, 1}};
  static const int quads[6][4] = {{1, 0, 3, 2}, {2, 3, 7, 6}, {3, 0, 4, 7},
                                  {6, 5, 1, 2}, {4, 5, 6, 7}, {5, 4, 0, 1}};
  static const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                   {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  float points[60][4], colors[60][4];
  GLuint buffer;
  GLint vPosition, vColor;
  int q, e, k;
  open_window(&argc, argv, 3, 2, GLUT_CORE_PROFILE, "glsl 1.50 textbook");
  for (q = 0; q < 6; ++q) {
    const int order[6] = {0, 1, 2, 0, 2, 3};
    for (k = 0; k < 6; ++k) {
      memcpy(points[n_tri], v[quads[q][order[k]]], sizeof points[0]);
      memcpy(colors[n_tri], c[quads[q][order[k]]], sizeof colors[0]);
      ++n_tri;
    }
  }
  for (e = 0; e < 12; ++e)
    for (k = 0; k < 2; ++k) {
      memcpy(points[n_tri + n_line], v[edges[e][k]], sizeof points[0]);
      memcpy(colors[n_tri + n_line], c[0], sizeof colors[0]);
      ++n_line;
    }
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, sizeof points + sizeof colors, NULL, GL_STATIC_DRAW);
  glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof points, points);
  glBufferSubData(GL_ARRAY_BUFFER, sizeof points, sizeof colors, colors);
  program = link_program(vshader, fshader);
  glUseProgram(program);
  vPosition = glGetAttribLocation(program, "vPosition");
  vColor = glGetAttribLocation(program, "vColor");
  if (vPosition < 0 || vColor < 0) return 1;
  glEnableVertexAttribArray((GLuint)vPosition);
  glVertexAttribPointer((GLuint)vPosition, 4, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glEnableVertexAttribArray((GLuint)vColor);
  glVertexAttribPointer((GLuint)vColor, 4, GL_FLOAT, GL_FALSE, 0, (void*)sizeof points);
  glEnable(GL_DEPTH_TEST);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
