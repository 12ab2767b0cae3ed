/*
 * glProvokingVertex with the fixed function and glBegin/glEnd (GLUT + GLEW, a compatibility
 * context): flat-shaded, lit and unlit, every primitive mode - triangles, strips, fans,
 * quads, quad strips, polygons, lines, line strips and loops - drawn with the last-vertex
 * convention (bottom half) and the first-vertex convention (top half), each vertex its own
 * colour. Quads and quad strips keep their last vertex and polygons their first in both, as
 * GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION (false in Mesa) says. The same modes drawn
 * again through glDrawArrays from client arrays, and a display list replays one set.
 */
#include <math.h>

#include "common.h"

static const float colors[8][3] = {{0.9f, 0.2f, 0.2f},  {0.2f, 0.8f, 0.2f}, {0.2f, 0.3f, 0.9f},
                                   {0.9f, 0.9f, 0.2f},  {0.8f, 0.3f, 0.9f}, {0.2f, 0.9f, 0.9f},
                                   {0.95f, 0.6f, 0.2f}, {0.9f, 0.9f, 0.9f}};

static GLuint list;
static float array_pos[64][2], array_col[64][3];

static void vertex(int k, float x, float y) {
  glColor3fv(colors[k % 8]);
  glVertex2f(x, y);
}

/* The modes in a 320x120 band whose lower edge is y0. */
static void draw_modes(float y0) {
  int i;
  glBegin(GL_TRIANGLES);
  vertex(0, 4, y0 + 8), vertex(1, 40, y0 + 10), vertex(2, 18, y0 + 50);
  glEnd();
  glBegin(GL_TRIANGLE_STRIP);
  for (i = 0; i < 6; ++i) vertex(i + 1, 44.0f + 10.0f * (float)i, y0 + ((i & 1) ? 55.0f : 5.0f));
  glEnd();
  glBegin(GL_TRIANGLE_FAN);
  vertex(7, 130, y0 + 30);
  for (i = 0; i < 5; ++i)
    vertex(i, 130.0f + 25.0f * (float)cos(0.3 + 1.1 * i), y0 + 30.0f + 25.0f * (float)sin(0.3 + 1.1 * i));
  glEnd();
  glBegin(GL_QUADS);
  vertex(0, 165, y0 + 5), vertex(1, 195, y0 + 8), vertex(2, 198, y0 + 50), vertex(3, 162, y0 + 45);
  glEnd();
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i < 6; ++i) vertex(i + 2, 205.0f + 12.0f * (float)(i / 2), y0 + ((i & 1) ? 55.0f : 5.0f));
  glEnd();
  glBegin(GL_POLYGON);
  for (i = 0; i < 5; ++i)
    vertex(i + 3, 270.0f + 22.0f * (float)cos(1.3 * i), y0 + 30.0f + 22.0f * (float)sin(1.3 * i));
  glEnd();
  glBegin(GL_LINES);
  vertex(1, 10, y0 + 70), vertex(2, 90, y0 + 75), vertex(3, 10, y0 + 80), vertex(4, 90, y0 + 90);
  glEnd();
  glBegin(GL_LINE_STRIP);
  for (i = 0; i < 5; ++i) vertex(i + 2, 100.0f + 15.0f * (float)i, y0 + ((i & 1) ? 70.0f : 90.0f));
  glEnd();
  glBegin(GL_LINE_LOOP);
  vertex(5, 180, y0 + 68), vertex(6, 230, y0 + 72), vertex(7, 225, y0 + 95), vertex(0, 185, y0 + 92);
  glEnd();
}

/* Strips, fans, quads and polygons from client arrays (glDrawArrays). */
static void draw_arrays(float y0) {
  int i;
  for (i = 0; i < 64; ++i) {
    array_col[i][0] = colors[i % 8][0], array_col[i][1] = colors[i % 8][1],
    array_col[i][2] = colors[i % 8][2];
  }
  for (i = 0; i < 6; ++i)
    array_pos[i][0] = 250.0f + 12.0f * (float)(i / 2),
    array_pos[i][1] = y0 + 68.0f + ((i & 1) ? 22.0f : 0.0f);
  for (i = 0; i < 6; ++i)
    array_pos[6 + i][0] = 240.0f + 14.0f * (float)i, array_pos[6 + i][1] = y0 + ((i & 1) ? 118.0f : 96.0f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, array_pos);
  glColorPointer(3, GL_FLOAT, 0, array_col);
  glDrawArrays(GL_QUAD_STRIP, 0, 6);
  glDrawArrays(GL_TRIANGLE_STRIP, 6, 6);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
}

static void display(void) {
  GLint follow = -1;
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glShadeModel(GL_FLAT);
  glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
  draw_modes(0);
  draw_arrays(0);
  glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
  glGetIntegerv(GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION, &follow);
  if (follow != GL_FALSE) fprintf(stderr, "quads follow the provoking vertex convention: %d\n", follow);
  draw_modes(120);
  draw_arrays(120);
  /* A display list compiled under the last convention replays under the first: the state
   * at execution decides. */
  glCallList(list);
  glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  open_window(&argc, argv, 0, 0, 0, "provoking vertex compat");
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 320, 0, 240, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBegin(GL_TRIANGLE_STRIP);
  vertex(0, 296, 2), vertex(1, 318, 2), vertex(2, 296, 30), vertex(3, 318, 30);
  glEnd();
  glEndList();
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
