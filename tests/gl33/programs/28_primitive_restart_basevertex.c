/*
 * Primitive restart and base vertices in a 3.3 core context (GLUT + GLEW), the way a terrain
 * and props renderer packs its meshes: ONE vertex buffer holds three coloured copies of a
 * pyramid, a fence, a 16x10 height-field grid, three discs and two ribbons; ONE element
 * buffer holds unsigned byte, unsigned short and unsigned int index lists at aligned offsets.
 * The terrain is drawn as GL_TRIANGLE_STRIP rows separated by the restart index 0xFFFFFFFF
 * (unsigned int indices, glDrawElementsBaseVertex); the pyramids with glDrawRangeElements,
 * glDrawElementsBaseVertex, glDrawRangeElementsBaseVertex and glMultiDrawElementsBaseVertex
 * (unsigned byte indices); the fence as two strips split by restart index 0xFF (unsigned
 * byte); discs and ribbons with glMultiDrawArrays (fans, then strips); contour lines over the
 * terrain as GL_LINE_STRIP with restart index 0xFFFF (unsigned short, base vertex), and a
 * frame and axes as GL_LINES.
 */
#include "common.h"

#define GX 16
#define GZ 10
#define NPYR 3
#define PYR_V 5
#define FENCE_V 12
#define DISC_V 14
#define NDISC 3
#define RIB_V 10
#define NRIB 2
#define FIRST_FENCE (NPYR * PYR_V)
#define FIRST_TERRAIN (FIRST_FENCE + FENCE_V)
#define FIRST_DISC (FIRST_TERRAIN + GX * GZ)
#define FIRST_RIB (FIRST_DISC + NDISC * DISC_V)
#define FIRST_LINES (FIRST_RIB + NRIB * RIB_V)
#define LINE_V 14
#define NVERT (FIRST_LINES + LINE_V)

static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 position;\n"
    "layout(location = 1) in vec3 color;\n"
    "uniform mat4 mvp;\n"
    "uniform vec4 offset;  // xyz translation, w: 0 = vertex colour, 1 = line colour\n"
    "uniform vec3 line_color;\n"
    "out vec3 c;\n"
    "void main() {\n"
    "  c = mix(color, line_color, offset.w);\n"
    "  gl_Position = mvp * vec4(position + offset.xyz, 1.0);\n"
    "}\n";
static const char* fs =
    "#version 330 core\n"
    "in vec3 c;\n"
    "out vec4 frag;\n"
    "void main() { frag = vec4(c, 1.0); }\n";

static GLuint prog, vao;
static GLint u_mvp, u_offset, u_line;
static size_t off_pyr, off_fence, off_terrain, off_contour;
static int n_fence, n_terrain, n_contour;
static float world[16], hud[16];

static float height(float x, float z) {
  return 0.35f * (float)(sin(0.9 * x + 0.3) * cos(0.7 * z)) + 0.15f * (float)sin(1.7 * z + 0.4 * x);
}

static void put(float* v, int i, float x, float y, float z, float r, float g, float b) {
  v[i * 6 + 0] = x;
  v[i * 6 + 1] = y;
  v[i * 6 + 2] = z;
  v[i * 6 + 3] = r;
  v[i * 6 + 4] = g;
  v[i * 6 + 5] = b;
}

static void at(float x, float y, float z, float line) { glUniform4f(u_offset, x, y, z, line); }

static void display(void) {
  static const GLint fan_first[NDISC] = {FIRST_DISC, FIRST_DISC + DISC_V, FIRST_DISC + 2 * DISC_V};
  static const GLsizei fan_count[NDISC] = {DISC_V, DISC_V, DISC_V - 4};
  static const GLint rib_first[NRIB] = {FIRST_RIB, FIRST_RIB + RIB_V};
  static const GLsizei rib_count[NRIB] = {RIB_V, RIB_V - 2};
  GLsizei pyr_count[2] = {18, 12};
  const void* pyr_idx[2];
  GLint pyr_base[2] = {PYR_V * 2, PYR_V};
  pyr_idx[0] = (const void*)off_pyr;
  pyr_idx[1] = (const void*)(off_pyr + 6); /* only the four sides */

  glClearColor(0.55f, 0.7f, 0.85f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glUseProgram(prog);
  glBindVertexArray(vao);
  glUniformMatrix4fv(u_mvp, 1, GL_FALSE, world);
  glEnable(GL_PRIMITIVE_RESTART);

  /* The terrain: strips of unsigned int indices split by 0xFFFFFFFF, from base vertex. */
  glPrimitiveRestartIndex(0xFFFFFFFFu);
  at(0.0f, 0.0f, 0.0f, 0.0f);
  glDrawElementsBaseVertex(GL_TRIANGLE_STRIP, n_terrain, GL_UNSIGNED_INT, (void*)off_terrain, FIRST_TERRAIN);

  /* Pyramids: one mesh's byte indices, three colour copies picked by the base vertex. */
  at(-1.9f, height(-1.9f, -0.7f), -0.7f, 0.0f);
  glDrawRangeElements(GL_TRIANGLES, 0, PYR_V - 1, 18, GL_UNSIGNED_BYTE, (void*)off_pyr);
  at(0.3f - 0.7f, height(0.3f, -2.1f), -2.1f, 0.0f);
  glDrawElementsBaseVertex(GL_TRIANGLES, 18, GL_UNSIGNED_BYTE, (void*)off_pyr, PYR_V);
  at(1.7f - 1.4f, height(1.7f, -0.2f), -0.2f, 0.0f);
  glDrawRangeElementsBaseVertex(GL_TRIANGLES, 0, PYR_V - 1, 18, GL_UNSIGNED_BYTE, (void*)off_pyr, 2 * PYR_V);
  /* Two sub-draws: the blue copy whole, the green copy's sides only, side by side. */
  at(-2.6f, height(-1.5f, -2.6f) + 0.05f, -2.6f, 0.0f);
  glMultiDrawElementsBaseVertex(GL_TRIANGLES, pyr_count, GL_UNSIGNED_BYTE, pyr_idx, 2, pyr_base);

  /* The fence: two strips in one draw, split by the byte restart index. */
  glPrimitiveRestartIndex(0xFF);
  at(0.0f, 0.0f, 0.0f, 0.0f);
  glDrawElements(GL_TRIANGLE_STRIP, n_fence, GL_UNSIGNED_BYTE, (void*)off_fence);

  /* Contour lines just above the terrain: short indices, restart 0xFFFF, base vertex. */
  glPrimitiveRestartIndex(0xFFFF);
  glUniform3f(u_line, 0.15f, 0.12f, 0.05f);
  at(0.0f, 0.03f, 0.0f, 1.0f);
  glDrawElementsBaseVertex(GL_LINE_STRIP, n_contour, GL_UNSIGNED_SHORT, (void*)off_contour, FIRST_TERRAIN);
  glDisable(GL_PRIMITIVE_RESTART);

  /* Axes in the world, then a HUD: discs and ribbons with glMultiDrawArrays, a frame. */
  at(0.0f, 0.0f, 0.0f, 0.0f);
  glDrawArrays(GL_LINES, FIRST_LINES, 6);
  glDisable(GL_DEPTH_TEST);
  glUniformMatrix4fv(u_mvp, 1, GL_FALSE, hud);
  glMultiDrawArrays(GL_TRIANGLE_FAN, fan_first, fan_count, NDISC);
  glMultiDrawArrays(GL_TRIANGLE_STRIP, rib_first, rib_count, NRIB);
  glUniform3f(u_line, 1.0f, 1.0f, 0.9f);
  at(0.0f, 0.0f, 0.0f, 1.0f);
  glDrawArrays(GL_LINES, FIRST_LINES + 6, 8);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static float v[NVERT * 6];
  static unsigned char idx[8192];
  static const unsigned char pyr[18] = {1, 2, 3, 1, 3, 4, 0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1};
  float proj[16], view[16];
  GLuint vbo, ibo;
  size_t off = 0;
  int i, x, z, k;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "primitive restart base vertex");
  prog = link_program(vs, fs);
  u_mvp = glGetUniformLocation(prog, "mvp");
  u_offset = glGetUniformLocation(prog, "offset");
  u_line = glGetUniformLocation(prog, "line_color");

  /* Pyramids: apex then base square, three colour schemes. */
  for (i = 0; i < NPYR; ++i) {
    const float r = i == 0 ? 0.9f : 0.3f, g = i == 1 ? 0.85f : 0.35f, b = i == 2 ? 0.95f : 0.3f;
    const float dx = 0.7f * (float)i; /* copy i sits 0.7 * i to the right */
    put(v, i * PYR_V + 0, dx, 0.55f, 0.0f, r, g, b);
    put(v, i * PYR_V + 1, dx - 0.23f, -0.05f, -0.21f, r * 0.5f, g * 0.5f, b * 0.5f);
    put(v, i * PYR_V + 2, dx + 0.22f, -0.05f, -0.24f, r * 0.8f, g * 0.7f, b * 0.6f);
    put(v, i * PYR_V + 3, dx + 0.25f, -0.05f, 0.22f, r * 0.6f, g * 0.9f, b * 0.7f);
    put(v, i * PYR_V + 4, dx - 0.2f, -0.05f, 0.23f, r * 0.4f, g * 0.6f, b * 0.9f);
  }
  /* Fence: two walls of three posts each (vertex pairs bottom/top). */
  for (i = 0; i < FENCE_V; ++i) {
    const int wall = i / 6, post = (i % 6) / 2, top = i % 2;
    const float fx = wall ? 0.6f + 0.45f * (float)post : -2.7f + 0.5f * (float)post;
    const float fz = wall ? 0.35f - 0.2f * (float)post : -1.9f + 0.3f * (float)post;
    put(v, FIRST_FENCE + i, fx, height(fx, fz) + (top ? 0.32f : -0.02f), fz, 0.55f + 0.2f * (float)top,
        0.35f + 0.1f * (float)wall, 0.2f);
  }
  /* Terrain: GX x GZ heights, colour baked from height and a fake slope light. */
  for (z = 0; z < GZ; ++z)
    for (x = 0; x < GX; ++x) {
      const float px = -3.1f + 6.2f * (float)x / (GX - 1), pz = -3.4f + 4.5f * (float)z / (GZ - 1);
      const float h = height(px, pz), slope = height(px + 0.1f, pz) - height(px - 0.1f, pz);
      const float l = 0.75f + 1.2f * slope, t = (h + 0.5f);
      put(v, FIRST_TERRAIN + z * GX + x, px, h, pz, l * (0.25f + 0.5f * t), l * (0.55f - 0.1f * t),
          l * (0.2f + 0.1f * t));
    }
  /* Discs (fans around a centre) and ribbons (strips), in HUD pixels. */
  for (i = 0; i < NDISC; ++i) {
    const float cx = 30.3f + 40.0f * (float)i, cy = 208.6f, rad = 14.0f - 2.0f * (float)i;
    put(v, FIRST_DISC + i * DISC_V, cx, cy, 0.0f, 1.0f, 1.0f, 0.9f);
    for (k = 1; k < DISC_V; ++k) {
      const double a = 2.0 * 3.14159265358979 * (k - 1) / (DISC_V - 2) + 0.2 * i;
      put(v, FIRST_DISC + i * DISC_V + k, cx + rad * (float)cos(a), cy + rad * (float)sin(a), 0.0f,
          0.3f * (float)i + 0.2f, 0.5f + 0.4f * (float)(k % 2), 0.9f - 0.3f * (float)i);
    }
  }
  for (i = 0; i < NRIB; ++i)
    for (k = 0; k < RIB_V; ++k) {
      const float px = 150.2f + 15.5f * (float)(k / 2),
                  py = 198.3f + 17.0f * (float)i + 9.0f * (float)(k % 2) + 4.0f * (float)sin(0.9 * k);
      put(v, FIRST_RIB + i * RIB_V + k, px, py, 0.0f, 0.9f, 0.4f + 0.1f * (float)k, 0.3f + 0.5f * (float)i);
    }
  /* Lines: three world axes, then a HUD frame of four segments. */
  put(v, FIRST_LINES + 0, -2.2f, 0.5f, 0.4f, 1, 0, 0);
  put(v, FIRST_LINES + 1, -1.2f, 0.5f, 0.4f, 1, 0, 0);
  put(v, FIRST_LINES + 2, -2.2f, 0.5f, 0.4f, 0, 1, 0);
  put(v, FIRST_LINES + 3, -2.2f, 1.3f, 0.4f, 0, 1, 0);
  put(v, FIRST_LINES + 4, -2.2f, 0.5f, 0.4f, 0, 0, 1);
  put(v, FIRST_LINES + 5, -2.2f, 0.5f, -0.6f, 0, 0, 1);
  {
    const float fx[4] = {10.3f, 309.7f, 309.7f, 10.3f}, fy[4] = {186.4f, 186.4f, 231.6f, 231.6f};
    for (k = 0; k < 4; ++k) {
      put(v, FIRST_LINES + 6 + 2 * k, fx[k], fy[k], 0.0f, 1, 1, 1);
      put(v, FIRST_LINES + 7 + 2 * k, fx[(k + 1) % 4], fy[(k + 1) % 4], 0.0f, 1, 1, 1);
    }
  }

  /* The element buffer: bytes first, then shorts and ints at aligned offsets. */
  off_pyr = off;
  memcpy(idx + off, pyr, sizeof pyr);
  off += sizeof pyr;
  off_fence = off;
  for (i = 0; i < FENCE_V; ++i) {
    if (i == 6) idx[off++] = 0xFF;
    idx[off++] = (unsigned char)(FIRST_FENCE + i);
  }
  n_fence = (int)(off - off_fence);
  off = (off + 1) & ~(size_t)1;
  off_contour = off;
  {
    unsigned short* s = (unsigned short*)(idx + off);
    k = 0;
    for (z = 1; z < GZ; z += 2) {
      for (x = 0; x < GX; ++x) s[k++] = (unsigned short)(z * GX + x);
      s[k++] = 0xFFFF;
    }
    for (x = 2; x < GX; x += 4) {
      for (z = 0; z < GZ; ++z) s[k++] = (unsigned short)(z * GX + x);
      s[k++] = 0xFFFF;
    }
    n_contour = k;
    off += (size_t)k * 2;
  }
  off = (off + 3) & ~(size_t)3;
  off_terrain = off;
  {
    unsigned int* s = (unsigned int*)(idx + off);
    k = 0;
    for (z = 0; z < GZ - 1; ++z) {
      for (x = 0; x < GX; ++x) {
        s[k++] = (unsigned int)(z * GX + x);
        s[k++] = (unsigned int)((z + 1) * GX + x);
      }
      s[k++] = 0xFFFFFFFFu;
    }
    n_terrain = k;
    off += (size_t)k * 4;
  }

  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)(3 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glGenBuffers(1, &ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)off, idx, GL_STATIC_DRAW);

  mat_perspective(proj, 50.0f, 320.0f / 240.0f, 0.5f, 30.0f);
  mat_lookat(view, 0.13f, 2.4f, 3.9f, 0.02f, -0.1f, -1.1f, 0.0f, 1.0f, 0.0f);
  mat_mul(world, proj, view);
  mat_ortho(hud, 0.0f, 320.0f, 0.0f, 240.0f, -1.0f, 1.0f);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
