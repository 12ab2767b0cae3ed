/*
 * Streaming vertex data in a 3.3 core context (GLUT + GLEW), the way dynamic geometry is fed
 * to a driver: a bar chart whose 16 bars are written in four rounds into the SAME 4-bar region
 * of one vertex buffer, each round drawn right after its update, so every draw must see the
 * data written just before it (and not the next round's):
 *   round 0: glMapBufferRange with GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT, glUnmapBuffer;
 *   round 1: GL_MAP_FLUSH_EXPLICIT_BIT, two glFlushMappedBufferRange calls (offsets relative
 *            to the mapped range), glUnmapBuffer;
 *   round 2: glBufferSubData;
 *   round 3: glCopyBufferSubData from a staging buffer (GL_COPY_READ_BUFFER ->
 *            GL_COPY_WRITE_BUFFER).
 * The chart's axes are written with glBufferSubData and drawn as lines; the bar indices are
 * written through glMapBuffer(GL_ELEMENT_ARRAY_BUFFER, GL_WRITE_ONLY). Below, three ribbons
 * (triangle strips) stream through a second buffer orphaned with glBufferData(NULL) before
 * each one and filled through GL_MAP_INVALIDATE_BUFFER_BIT. Positions are floats, colours
 * normalized unsigned bytes. A marker at the top right shows whether glGetBufferSubData read
 * back the copied bytes.
 */
#include "common.h"

#define NBARS 16
#define PER_ROUND 4
#define RIB_SEG 40
#define RIB_V (2 * (RIB_SEG + 1))

typedef struct {
  float x, y;
  unsigned char r, g, b, a;
} Vertex;

static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 position;\n"
    "layout(location = 1) in vec4 color;\n"
    "uniform mat4 proj;\n"
    "out vec4 c;\n"
    "void main() { c = color; gl_Position = proj * vec4(position, 0.0, 1.0); }\n";
static const char* fs =
    "#version 330 core\n"
    "in vec4 c;\n"
    "out vec4 frag;\n"
    "void main() { frag = c; }\n";

static GLuint prog, vao[2], vbo, ibo, ribbon, staging;

static void vert(Vertex* v, float x, float y, int r, int g, int b) {
  v->x = x;
  v->y = y;
  v->r = (unsigned char)r;
  v->g = (unsigned char)g;
  v->b = (unsigned char)b;
  v->a = 255;
}

/* Bar i as four corners (indexed as two triangles). */
static void bar(Vertex* v, int i) {
  const float x0 = 14.3f + 18.5f * (float)i, y0 = 118.4f, h = 24.0f + (float)((i * 37) % 83);
  const int r = 60 + (i * 50) % 190, g = 230 - 12 * i, b = 90 + (i % 4) * 50;
  vert(v + 0, x0, y0, r / 3, g / 3, b / 3);
  vert(v + 1, x0 + 13.0f, y0, r / 3, g / 3, b / 3);
  vert(v + 2, x0 + 13.0f, y0 + h, r, g, b);
  vert(v + 3, x0, y0 + h, r, g, b);
}

static void ribbon_vertices(Vertex* v, int k) {
  int i;
  for (i = 0; i <= RIB_SEG; ++i) {
    const float t = (float)i / RIB_SEG, x = 12.2f + 296.0f * t;
    const float y = 62.3f - 28.0f * (float)k + 14.0f * (float)sin(6.0 * t + 1.3 * k);
    const float w = 3.0f + 6.0f * t;
    const int r = k == 0 ? 250 : 80, g = 80 + (int)(170.0f * t), b = k == 2 ? 250 : 120;
    vert(v + 2 * i, x, y - w, r / 2, g / 2, b / 2);
    vert(v + 2 * i + 1, x, y + w, r, g, b);
  }
}

static void display(void) {
  Vertex tmp[PER_ROUND * 4], axes[4];
  Vertex* m;
  int round, i, ok;
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glUseProgram(prog);
  glBindVertexArray(vao[0]);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  for (round = 0; round < 4; ++round) {
    const GLsizeiptr size = sizeof tmp;
    for (i = 0; i < PER_ROUND; ++i) bar(tmp + 4 * i, round * PER_ROUND + i);
    switch (round) {
      case 0:
        m = glMapBufferRange(GL_ARRAY_BUFFER, 0, size, GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT);
        if (!m) {
          fprintf(stderr, "glMapBufferRange failed\n");
          exit(1);
        }
        memcpy(m, tmp, sizeof tmp);
        glUnmapBuffer(GL_ARRAY_BUFFER);
        break;
      case 1:
        /* Map 4 bars plus the axes after them; write and flush the bars in two halves. */
        m = glMapBufferRange(GL_ARRAY_BUFFER, 0, size + sizeof axes,
                             GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT);
        if (!m) {
          fprintf(stderr, "glMapBufferRange (flush explicit) failed\n");
          exit(1);
        }
        memcpy(m, tmp, sizeof tmp);
        glFlushMappedBufferRange(GL_ARRAY_BUFFER, size / 2, size / 2);
        glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, size / 2);
        glUnmapBuffer(GL_ARRAY_BUFFER);
        break;
      case 2: glBufferSubData(GL_ARRAY_BUFFER, 0, size, tmp); break;
      default:
        glBindBuffer(GL_COPY_READ_BUFFER, staging);
        glBindBuffer(GL_COPY_WRITE_BUFFER, vbo);
        glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, sizeof tmp, 0, size);
        break;
    }
    glDrawElements(GL_TRIANGLES, PER_ROUND * 6, GL_UNSIGNED_SHORT, (void*)0);
  }
  /* Did the copy land? Compare with what the staging buffer held for round 3. */
  {
    Vertex back[PER_ROUND * 4];
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, sizeof back, back);
    ok = memcmp(back, tmp, sizeof back) == 0;
  }
  /* Axes: two lines, then a marker quad, through glBufferSubData after the bars. */
  vert(axes + 0, 8.3f, 116.6f, 220, 220, 220);
  vert(axes + 1, 311.7f, 116.6f, 220, 220, 220);
  vert(axes + 2, 8.3f, 116.6f, 220, 220, 220);
  vert(axes + 3, 8.3f, 231.4f, 220, 220, 220);
  glBufferSubData(GL_ARRAY_BUFFER, sizeof tmp, sizeof axes, axes);
  glDrawArrays(GL_LINES, PER_ROUND * 4, 4);
  for (i = 0; i < 4; ++i)
    vert(axes + i, 296.2f + 14.0f * (float)(i == 1 || i == 2), 220.2f + 14.0f * (float)(i >= 2),
         ok ? 40 : 250, ok ? 220 : 30, 40);
  glBufferSubData(GL_ARRAY_BUFFER, sizeof tmp, sizeof axes, axes);
  glDrawArrays(GL_TRIANGLE_FAN, PER_ROUND * 4, 4);

  /* Ribbons: orphan, map the whole new store invalidated, fill, draw; three times. */
  glBindVertexArray(vao[1]);
  glBindBuffer(GL_ARRAY_BUFFER, ribbon);
  for (i = 0; i < 3; ++i) {
    glBufferData(GL_ARRAY_BUFFER, RIB_V * sizeof(Vertex), NULL, GL_STREAM_DRAW);
    m = glMapBufferRange(GL_ARRAY_BUFFER, 0, RIB_V * sizeof(Vertex),
                         GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT);
    if (!m) {
      fprintf(stderr, "glMapBufferRange (ribbon) failed\n");
      exit(1);
    }
    ribbon_vertices(m, i);
    if (!glUnmapBuffer(GL_ARRAY_BUFFER)) {
      fprintf(stderr, "glUnmapBuffer lost the data\n");
      exit(1);
    }
    glDrawArrays(GL_TRIANGLE_STRIP, 0, RIB_V);
  }
  check_gl("display");
  glutSwapBuffers();
}

static void attributes(void) {
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), (void*)0);
  glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex), (void*)(2 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
}

int main(int argc, char** argv) {
  Vertex stage[2 * PER_ROUND * 4];
  float proj[16];
  unsigned short* idx;
  int i;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "buffer mapping streaming");
  prog = link_program(vs, fs);
  mat_ortho(proj, 0.0f, 320.0f, 0.0f, 240.0f, -1.0f, 1.0f);
  glUseProgram(prog);
  glUniformMatrix4fv(glGetUniformLocation(prog, "proj"), 1, GL_FALSE, proj);

  glGenVertexArrays(2, vao);
  glBindVertexArray(vao[0]);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, (PER_ROUND * 4 + 4) * sizeof(Vertex), NULL, GL_DYNAMIC_DRAW);
  attributes();
  glGenBuffers(1, &ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, PER_ROUND * 6 * sizeof(unsigned short), NULL, GL_STATIC_DRAW);
  idx = glMapBuffer(GL_ELEMENT_ARRAY_BUFFER, GL_WRITE_ONLY);
  if (!idx) {
    fprintf(stderr, "glMapBuffer failed\n");
    return 1;
  }
  for (i = 0; i < PER_ROUND; ++i) {
    idx[i * 6 + 0] = (unsigned short)(i * 4);
    idx[i * 6 + 1] = (unsigned short)(i * 4 + 1);
    idx[i * 6 + 2] = (unsigned short)(i * 4 + 2);
    idx[i * 6 + 3] = (unsigned short)(i * 4);
    idx[i * 6 + 4] = (unsigned short)(i * 4 + 2);
    idx[i * 6 + 5] = (unsigned short)(i * 4 + 3);
  }
  glUnmapBuffer(GL_ELEMENT_ARRAY_BUFFER);

  /* The staging buffer: junk first, round 3's bars at byte offset sizeof one round. */
  memset(stage, 0x5A, sizeof stage);
  for (i = 0; i < PER_ROUND; ++i) bar(stage + PER_ROUND * 4 + 4 * i, 3 * PER_ROUND + i);
  glGenBuffers(1, &staging);
  glBindBuffer(GL_COPY_READ_BUFFER, staging);
  glBufferData(GL_COPY_READ_BUFFER, sizeof stage, stage, GL_STATIC_COPY);

  glBindVertexArray(vao[1]);
  glGenBuffers(1, &ribbon);
  glBindBuffer(GL_ARRAY_BUFFER, ribbon);
  glBufferData(GL_ARRAY_BUFFER, RIB_V * sizeof(Vertex), NULL, GL_STREAM_DRAW);
  attributes();
  glBindVertexArray(0);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
