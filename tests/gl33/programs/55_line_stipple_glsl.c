/*
 * Stippled lines drawn with a GLSL program in a compatibility context (GL 2.1 §3.4.2): the
 * pattern is applied after the program's vertex stage, the counter restarting at each
 * glBegin of a strip or loop, at each segment of GL_LINES, and carried along the segments of a
 * strip. Lines come from immediate mode (gl_Vertex, gl_Color), from glDrawArrays and
 * glDrawElements over generic attributes in a buffer, in perspective with a segment cut by the
 * near plane, wide (glLineWidth(3)), with factors 1 to 4; then fixed-function stippled lines
 * with two texture units (a generated program) and with one (the built-in shader).
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
    "void main() { gl_FragColor = vec4(c.rgb, 1.0); }\n";
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
    "void main() { gl_FragColor = vec4(c.bgr, 1.0); }\n";

static GLuint compat, generic, vbo, tex[2];

/* The cell (column, row) of a 4x2 grid of 80x120 cells, x and y in pixels inside it. */
static void cell(int col, int row) {
  glViewport(col * 80, row * 120, 80, 120);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 80.0, 0.0, 120.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void display(void) {
  int i;
  glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LINE_STIPPLE);

  /* 1: a strip (the counter carried across its corners) and a loop, immediate mode. */
  cell(0, 1);
  glUseProgram(compat);
  glLineStipple(1, 0x0F0F);
  glBegin(GL_LINE_STRIP);
  for (i = 0; i < 6; ++i) {
    glColor3f(1.0f, 0.3f + 0.1f * (float)i, 0.2f);
    glVertex2f(6.0f + 13.0f * (float)i, (i & 1) ? 50.0f : 10.0f);
  }
  glEnd();
  glLineStipple(2, 0x33FF);
  glBegin(GL_LINE_LOOP);
  glColor3f(0.3f, 1.0f, 0.5f);
  glVertex2f(10.5f, 65.5f);
  glVertex2f(70.5f, 70.5f);
  glColor3f(0.3f, 0.5f, 1.0f);
  glVertex2f(60.5f, 112.5f);
  glVertex2f(15.5f, 100.5f);
  glEnd();

  /* 2: independent segments (each restarts), a fan of them. */
  cell(1, 1);
  glLineStipple(3, 0x5F5F);
  glBegin(GL_LINES);
  for (i = 0; i < 8; ++i) {
    const double a = 3.14159265358979 * i / 8.0;
    glColor3f(0.9f, 0.9f - 0.1f * (float)i, 0.3f + 0.08f * (float)i);
    glVertex2f(40.0f, 60.0f);
    glVertex2f((float)(40.0 + 38.0 * cos(a)), (float)(60.0 + 55.0 * sin(a)));
  }
  glEnd();

  /* 3: generic attributes in a buffer: a strip by glDrawArrays, segments by glDrawElements. */
  cell(2, 1);
  glUseProgram(generic);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glEnableVertexAttribArray(1);
  glEnableVertexAttribArray(6);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)0);
  glVertexAttribPointer(6, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)(2 * sizeof(float)));
  glLineStipple(1, 0x00FF);
  glDrawArrays(GL_LINE_STRIP, 0, 8);
  {
    static const GLubyte idx[8] = {0, 7, 1, 6, 2, 5, 3, 4};
    glLineStipple(4, 0xA5A5);
    glPushMatrix();
    glTranslatef(0.0f, 58.0f, 0.0f);
    glDrawElements(GL_LINES, 8, GL_UNSIGNED_BYTE, idx);
    glPopMatrix();
  }
  glDisableVertexAttribArray(1);
  glDisableVertexAttribArray(6);
  glBindBuffer(GL_ARRAY_BUFFER, 0);

  /* 4: wide stippled lines. */
  cell(3, 1);
  glUseProgram(compat);
  glLineWidth(3.0f);
  glLineStipple(2, 0x1C47);
  glBegin(GL_LINE_STRIP);
  glColor3f(1.0f, 0.8f, 0.2f);
  glVertex2f(8.0f, 10.0f);
  glVertex2f(72.0f, 40.0f);
  glColor3f(0.2f, 0.8f, 1.0f);
  glVertex2f(10.0f, 70.0f);
  glVertex2f(60.0f, 110.0f);
  glEnd();
  glLineWidth(1.0f);

  /* 5: in perspective, a segment crossing the near plane: stippled after clipping. */
  glViewport(0, 0, 160, 120);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.4, 0.4, -0.3, 0.3, 0.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLineStipple(1, 0x3F3F);
  glBegin(GL_LINES);
  for (i = 0; i < 5; ++i) {
    glColor3f(0.4f + 0.12f * (float)i, 1.0f, 0.4f);
    glVertex3f(-1.5f + 0.7f * (float)i, -0.8f, 1.0f);
    glVertex3f(-1.0f + 0.5f * (float)i, 0.6f, -9.0f);
  }
  glEnd();
  glUseProgram(0);

  /* 6: fixed function, two texture units (a generated program) and one. */
  cell(2, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glEnable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glEnable(GL_TEXTURE_2D);
  glLineStipple(1, 0x7777);
  glBegin(GL_LINE_STRIP);
  for (i = 0; i < 7; ++i) {
    glMultiTexCoord2f(GL_TEXTURE0, (float)i / 6.0f, 0.3f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.5f, (float)i / 6.0f);
    glVertex2f(5.0f + 11.0f * (float)i, (i & 1) ? 100.0f : 20.0f);
  }
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);
  cell(3, 0);
  glLineStipple(2, 0x0F3F);
  glBegin(GL_LINE_LOOP);
  for (i = 0; i < 5; ++i) {
    const double a = 2.0 * 3.14159265358979 * i / 5.0;
    glTexCoord2f((float)i / 4.0f, 0.5f);
    glVertex2f((float)(40.0 + 34.0 * cos(a)), (float)(60.0 + 50.0 * sin(a)));
  }
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_LINE_STIPPLE);
  glViewport(0, 0, 320, 240);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static float strip[8][5];
  static GLubyte checker[8][8][3], ramp[4][4][3];
  int i, j;
  open_window(&argc, argv, 0, 0, 0, "line stipple with glsl");
  compat = link_program_bound(compat_vs, compat_fs, "position", 1, "colour", 6);
  generic = link_program_bound(generic_vs, generic_fs, "position", 1, "colour", 6);
  for (i = 0; i < 8; ++i) {
    strip[i][0] = 5.0f + 10.0f * (float)i;
    strip[i][1] = (i & 1) ? 48.0f : 6.0f + 3.0f * (float)i;
    strip[i][2] = 0.2f + 0.1f * (float)i;
    strip[i][3] = 1.0f - 0.1f * (float)i;
    strip[i][4] = 0.6f;
  }
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof strip, strip, GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  for (j = 0; j < 8; ++j)
    for (i = 0; i < 8; ++i) {
      const int on = (i + j) & 1;
      checker[j][i][0] = (GLubyte)(on ? 250 : 120);
      checker[j][i][1] = (GLubyte)(on ? 220 : 90);
      checker[j][i][2] = (GLubyte)(on ? 90 : 200);
    }
  for (j = 0; j < 4; ++j)
    for (i = 0; i < 4; ++i) {
      ramp[j][i][0] = (GLubyte)(255 - 30 * i);
      ramp[j][i][1] = 255;
      ramp[j][i][2] = (GLubyte)(255 - 50 * j);
    }
  tex[0] = rgb_texture(8, 8, checker, GL_NEAREST);
  tex[1] = rgb_texture(4, 4, ramp, GL_NEAREST);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
