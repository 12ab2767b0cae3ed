/*
 * Wireframes of quads and polygons drawn with a GLSL program in a compatibility context, the
 * way course code toggles glPolygonMode(GL_FRONT_AND_BACK, GL_LINE) over a scene of GL_QUADS:
 * only the boundary edges are drawn (GL 2.1 §2.6.2), never the diagonals the quads are cut
 * along. The edges come from glBegin(GL_QUADS) and glBegin(GL_POLYGON) (gl_Vertex and gl_Color
 * in the shader), glDrawArrays(GL_QUAD_STRIP) and glDrawElements(GL_QUADS) over generic
 * attributes in a buffer, glEdgeFlag(GL_FALSE) hiding chosen triangle edges, a quad cut by the
 * near plane (edges made by clipping), GL_POINT mode, a program with GL_FIRST_VERTEX_CONVENTION,
 * and fixed-function quads through a generated program (two texture units), one of them with
 * its back face filled.
 */
#include "common.h"

static const char* compat_vs =
    "#version 120\n"
    "varying vec4 c;\n"
    "void main() {\n"
    "  c = gl_Color;\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n"
    "}\n";
static const char* compat_fs =
    "#version 120\n"
    "varying vec4 c;\n"
    "void main() { gl_FragColor = vec4(c.rgb * 0.8 + 0.2, 1.0); }\n";
static const char* generic_vs =
    "#version 120\n"
    "attribute vec2 position;\n"
    "attribute vec3 colour;\n"
    "varying vec3 c;\n"
    "void main() {\n"
    "  c = colour;\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * vec4(position, 0.0, 1.0);\n"
    "}\n";
static const char* generic_fs =
    "#version 120\n"
    "varying vec3 c;\n"
    "void main() { gl_FragColor = vec4(c, 1.0); }\n";

static GLuint compat, generic, strip_vbo, quads_vbo, tex[2];

/* The panel (column, row) of a 4x2 grid of 80x120 cells, in [-1, 1] units inside it. */
static void panel(int col, int row) {
  glViewport(col * 80, row * 120, 80, 120);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.2, 1.2, -1.8, 1.8, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void quad(float x, float y, float w, float h, float r, float g, float b) {
  glColor3f(r, g, b);
  glVertex2f(x, y);
  glVertex2f(x + w, y + 0.1f);
  glVertex2f(x + w - 0.1f, y + h);
  glVertex2f(x + 0.05f, y + h - 0.15f);
}

static void display(void) {
  int i;
  glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);

  /* 1: immediate quads, gl_Vertex and gl_Color. */
  panel(0, 1);
  glUseProgram(compat);
  glBegin(GL_QUADS);
  quad(-1.0f, -1.5f, 1.7f, 1.2f, 1.0f, 0.4f, 0.2f);
  quad(-0.8f, 0.2f, 1.5f, 1.3f, 0.3f, 0.9f, 0.4f);
  glEnd();

  /* 2: a polygon (a fan inside) and, rotated, the same under the first-vertex convention. */
  panel(1, 1);
  glBegin(GL_POLYGON);
  for (i = 0; i < 7; ++i) {
    const double a = 2.0 * 3.14159265358979 * i / 7.0 + 0.2;
    glColor3f(0.3f + 0.1f * (float)i, 0.8f, 1.0f - 0.1f * (float)i);
    glVertex2f((float)(0.95 * cos(a)), (float)(0.8 + 0.75 * sin(a)));
  }
  glEnd();
  glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
  glBegin(GL_QUADS);
  quad(-0.9f, -1.6f, 1.7f, 1.3f, 1.0f, 0.9f, 0.3f);
  glEnd();
  glProvokingVertex(GL_LAST_VERTEX_CONVENTION);

  /* 3: a quad strip over generic attributes in a buffer. */
  panel(2, 1);
  glUseProgram(generic);
  glBindBuffer(GL_ARRAY_BUFFER, strip_vbo);
  glEnableVertexAttribArray(1);
  glEnableVertexAttribArray(6);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)0);
  glVertexAttribPointer(6, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)(2 * sizeof(float)));
  glDrawArrays(GL_QUAD_STRIP, 0, 10);

  /* 4: indexed quads, the same buffer layout; then the points of their corners. */
  panel(3, 1);
  glBindBuffer(GL_ARRAY_BUFFER, quads_vbo);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)0);
  glVertexAttribPointer(6, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)(2 * sizeof(float)));
  {
    static const GLubyte idx[12] = {0, 1, 2, 3, 4, 5, 6, 7, 1, 4, 7, 2};
    glDrawElements(GL_QUADS, 12, GL_UNSIGNED_BYTE, idx);
    panel(3, 0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointSize(3.0f);
    glDrawElements(GL_QUADS, 12, GL_UNSIGNED_BYTE, idx);
    glPointSize(1.0f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  }
  glDisableVertexAttribArray(1);
  glDisableVertexAttribArray(6);
  glBindBuffer(GL_ARRAY_BUFFER, 0);

  /* 5: triangles with edge flags: each triangle shows only the edges that start at a vertex
   * given with the flag true. */
  panel(0, 0);
  glUseProgram(compat);
  glBegin(GL_TRIANGLES);
  for (i = 0; i < 4; ++i) {
    const float y = -1.6f + 0.8f * (float)i;
    glColor3f(0.9f, 0.5f + 0.1f * (float)i, 0.2f);
    glEdgeFlag((i & 1) ? GL_FALSE : GL_TRUE);
    glVertex2f(-1.0f, y);
    glEdgeFlag(GL_TRUE);
    glVertex2f(0.9f, y + 0.1f);
    glEdgeFlag(i == 2 ? GL_FALSE : GL_TRUE);
    glVertex2f(-0.2f, y + 0.7f);
  }
  glEnd();
  glEdgeFlag(GL_TRUE);

  /* 6: quads in perspective, one crossing the near plane: the clipped edges. */
  glViewport(80, 0, 80, 120);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.3, 0.3, -0.45, 0.45, 0.5, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(-65.0f, 1.0f, 0.0f, 0.0f);
  glTranslatef(0.0f, 0.0f, -1.2f);
  glBegin(GL_QUADS);
  glColor3f(0.4f, 0.7f, 1.0f);
  glVertex3f(-0.9f, -1.0f, 0.0f);
  glVertex3f(0.9f, -1.0f, 0.0f);
  glVertex3f(0.9f, 3.0f, 0.0f);
  glVertex3f(-0.9f, 3.0f, 0.0f);
  glColor3f(1.0f, 0.6f, 0.8f);
  glVertex3f(-0.5f, -0.4f, 0.3f);
  glVertex3f(0.4f, -0.6f, 0.3f);
  glVertex3f(0.5f, 0.5f, 0.3f);
  glVertex3f(-0.4f, 0.4f, 0.3f);
  glEnd();
  glUseProgram(0);

  /* 7: fixed function with two texture units (a generated program): quads as lines, the
   * back faces of a second pair filled. */
  panel(2, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glEnable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glBegin(GL_QUADS);
  for (i = 0; i < 1; ++i) {
    const float y = -1.6f;
    glColor3f(1.0f, 1.0f, 1.0f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 0.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 0.0f);
    glVertex2f(-1.0f, y);
    glMultiTexCoord2f(GL_TEXTURE0, 1.0f, 0.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 0.0f);
    glVertex2f(0.9f, y + 0.2f);
    glMultiTexCoord2f(GL_TEXTURE0, 1.0f, 1.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 1.0f);
    glVertex2f(0.8f, y + 1.4f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 1.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 1.0f);
    glVertex2f(-0.9f, y + 1.3f);
  }
  glEnd();
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_FILL);
  /* A clockwise quad: its back face is filled. */
  glBegin(GL_QUADS);
  glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 0.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 0.0f);
  glVertex2f(-0.5f, 0.2f);
  glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 1.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 1.0f);
  glVertex2f(-0.6f, 1.6f);
  glMultiTexCoord2f(GL_TEXTURE0, 1.0f, 1.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 1.0f);
  glVertex2f(0.5f, 1.7f);
  glMultiTexCoord2f(GL_TEXTURE0, 1.0f, 0.0f);
  glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 0.0f);
  glVertex2f(0.6f, 0.3f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_TEXTURE_2D);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glViewport(0, 0, 320, 240);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static float strip[10][5], quads[8][5];
  static GLubyte checker[8][8][3], ramp[4][4][3];
  int i, j;
  open_window(&argc, argv, 0, 0, 0, "polygon mode edges with glsl");
  compat = link_program_bound(compat_vs, compat_fs, "position", 1, "colour", 6);
  generic = link_program_bound(generic_vs, generic_fs, "position", 1, "colour", 6);
  for (i = 0; i < 10; ++i) {
    strip[i][0] = (i & 1) ? 0.9f : -1.0f + 0.05f * (float)i;
    strip[i][1] = -1.6f + 0.36f * (float)(i / 2) * 2.0f + ((i & 1) ? 0.1f : 0.0f);
    strip[i][2] = 0.3f + 0.07f * (float)i;
    strip[i][3] = 1.0f - 0.08f * (float)i;
    strip[i][4] = 0.5f;
  }
  for (i = 0; i < 8; ++i) {
    const double a = 2.0 * 3.14159265358979 * i / 8.0;
    quads[i][0] = (float)(0.95 * cos(a));
    quads[i][1] = (float)(1.5 * sin(a));
    quads[i][2] = 1.0f;
    quads[i][3] = 0.4f + 0.07f * (float)i;
    quads[i][4] = 0.9f - 0.1f * (float)i;
  }
  glGenBuffers(1, &strip_vbo);
  glBindBuffer(GL_ARRAY_BUFFER, strip_vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof strip, strip, GL_STATIC_DRAW);
  glGenBuffers(1, &quads_vbo);
  glBindBuffer(GL_ARRAY_BUFFER, quads_vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof quads, quads, GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);

  for (j = 0; j < 8; ++j)
    for (i = 0; i < 8; ++i) {
      const int on = (i + j) & 1;
      checker[j][i][0] = (GLubyte)(on ? 240 : 90);
      checker[j][i][1] = (GLubyte)(on ? 200 : 60);
      checker[j][i][2] = (GLubyte)(on ? 80 : 160);
    }
  for (j = 0; j < 4; ++j)
    for (i = 0; i < 4; ++i) {
      ramp[j][i][0] = (GLubyte)(255 - 40 * i);
      ramp[j][i][1] = (GLubyte)(255 - 30 * j);
      ramp[j][i][2] = 255;
    }
  tex[0] = rgb_texture(8, 8, checker, GL_NEAREST);
  tex[1] = rgb_texture(4, 4, ramp, GL_NEAREST);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
