/*
 * Hidden-line rendering in a GL 3.3 core context (GLUT + GLEW), the CAD-viewer way: three
 * coarse meshes (a cube, a low-poly sphere, a hexagonal prism) drawn solid and shaded with
 * glEnable(GL_POLYGON_OFFSET_FILL) / glPolygonOffset(1, 1) pushing their depths back, then
 * the same index buffers again with glPolygonMode(GL_FRONT_AND_BACK, GL_LINE) in a dark
 * colour, so only the edges in front of the filled surfaces survive the depth test. Also
 * three GL_LINES axes and a GL_LINE_LOOP circle on the ground plane, all one pixel wide
 * (glLineWidth(1); the core profile has no wide lines). The camera is oblique so that no
 * line runs along a pixel row or column.
 */
#include "common.h"

#define LS_SLICES 10
#define LS_STACKS 6
#define CIRCLE_SEGS 48

static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 pos;\n"
    "layout(location = 1) in vec3 nrm;\n"
    "uniform mat4 model, vp;\n"
    "out vec3 normal;\n"
    "void main() {\n"
    "  normal = mat3(model) * nrm;\n"
    "  gl_Position = vp * model * vec4(pos, 1.0);\n"
    "}\n";
static const char* fs =
    "#version 330 core\n"
    "in vec3 normal;\n"
    "uniform vec3 color;\n"
    "uniform bool lit;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  if (!lit) { frag = vec4(color, 1.0); return; }\n"
    "  float d = max(dot(normalize(normal), normalize(vec3(0.5, 0.8, 0.35))), 0.0);\n"
    "  frag = vec4(color * (0.35 + 0.65 * d), 1.0);\n"
    "}\n";

struct mesh {
  GLuint vao;
  GLsizei count;
};

static GLuint prog, lines_vao;
static struct mesh meshes[3];
static float vp[16];

static struct mesh upload(const float* verts, int nverts, const unsigned short* idx, int nidx) {
  struct mesh m;
  GLuint b[2];
  glGenVertexArrays(1, &m.vao);
  glBindVertexArray(m.vao);
  glGenBuffers(2, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(nverts * 6 * sizeof(float)), verts, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)(3 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(nidx * sizeof(unsigned short)), idx, GL_STATIC_DRAW);
  m.count = nidx;
  return m;
}

static void build(void) {
  static float sv[(LS_SLICES + 1) * (LS_STACKS + 1) * 6], cv[24 * 6], pv[(12 + 14) * 6];
  static unsigned short si[LS_SLICES * LS_STACKS * 6], ci[36], pi[6 * 6 + 2 * 6 * 3];
  static float lv[(6 + CIRCLE_SEGS) * 6];
  int i, j, f, k = 0, n = 0;
  GLuint b;
  /* Low-poly sphere (smooth normals). */
  for (j = 0; j <= LS_STACKS; ++j)
    for (i = 0; i <= LS_SLICES; ++i) {
      const double th = 3.14159265358979 * j / LS_STACKS, ph = 2.0 * 3.14159265358979 * i / LS_SLICES;
      float* v = &sv[(j * (LS_SLICES + 1) + i) * 6];
      v[0] = v[3] = (float)(sin(th) * cos(ph));
      v[1] = v[4] = (float)cos(th);
      v[2] = v[5] = (float)(sin(th) * sin(ph));
    }
  for (j = 0; j < LS_STACKS; ++j)
    for (i = 0; i < LS_SLICES; ++i) {
      const unsigned short a = (unsigned short)(j * (LS_SLICES + 1) + i),
                           c = (unsigned short)(a + LS_SLICES + 1);
      si[k++] = a, si[k++] = (unsigned short)(a + 1), si[k++] = c;
      si[k++] = (unsigned short)(a + 1), si[k++] = (unsigned short)(c + 1), si[k++] = c;
    }
  meshes[0] = upload(sv, (LS_SLICES + 1) * (LS_STACKS + 1), si, k);
  /* Cube of half-size 0.5, four vertices per face. */
  k = 0;
  for (f = 0; f < 6; ++f) {
    const int axis = f / 2;
    const float sgn = (f % 2) ? -1.0f : 1.0f;
    for (i = 0; i < 4; ++i) {
      float* v = &cv[(f * 4 + i) * 6];
      v[axis] = 0.5f * sgn;
      v[(axis + 1) % 3] = ((i == 1 || i == 2) ? 0.5f : -0.5f) * sgn;
      v[(axis + 2) % 3] = (i >= 2) ? 0.5f : -0.5f;
      v[3] = v[4] = v[5] = 0.0f;
      v[3 + axis] = sgn;
    }
    ci[k++] = (unsigned short)(f * 4), ci[k++] = (unsigned short)(f * 4 + 1),
    ci[k++] = (unsigned short)(f * 4 + 2);
    ci[k++] = (unsigned short)(f * 4), ci[k++] = (unsigned short)(f * 4 + 2),
    ci[k++] = (unsigned short)(f * 4 + 3);
  }
  meshes[1] = upload(cv, 24, ci, k);
  /* Hexagonal prism: six side quads (12 vertices, flat normals) and two caps (7 vertices each). */
  k = 0;
  for (i = 0; i < 6; ++i) {
    const double a0 = 3.14159265358979 * i / 3.0, am = 3.14159265358979 * (i + 0.5) / 3.0;
    for (j = 0; j < 2; ++j) {
      float* v = &pv[(i * 2 + j) * 6];
      v[0] = (float)cos(a0) * 0.6f, v[1] = j ? 0.5f : -0.5f, v[2] = (float)sin(a0) * 0.6f;
      v[3] = (float)cos(am), v[4] = 0.0f, v[5] = (float)sin(am);
    }
  }
  /* Side face i spans edges i and i + 1: its normal blends from face i's to face i + 1's. */
  for (i = 0; i < 6; ++i) {
    const unsigned short a = (unsigned short)(i * 2), c = (unsigned short)(((i + 1) % 6) * 2);
    pi[k++] = a, pi[k++] = (unsigned short)(a + 1), pi[k++] = c;
    pi[k++] = c, pi[k++] = (unsigned short)(a + 1), pi[k++] = (unsigned short)(c + 1);
  }
  for (j = 0; j < 2; ++j) {
    const int base = 12 + j * 7;
    for (i = 0; i < 7; ++i) {
      float* v = &pv[(base + i) * 6];
      const double a = 3.14159265358979 * (i - 1) / 3.0;
      v[0] = i ? (float)cos(a) * 0.6f : 0.0f, v[1] = j ? 0.5f : -0.5f, v[2] = i ? (float)sin(a) * 0.6f : 0.0f;
      v[3] = 0.0f, v[4] = j ? 1.0f : -1.0f, v[5] = 0.0f;
    }
    for (i = 0; i < 6; ++i) {
      pi[k++] = (unsigned short)base;
      pi[k++] = (unsigned short)(base + 1 + (j ? (i + 1) % 6 : i));
      pi[k++] = (unsigned short)(base + 1 + (j ? i : (i + 1) % 6));
    }
  }
  meshes[2] = upload(pv, 26, pi, k);

  /* Axes (GL_LINES, three pairs) then the circle (GL_LINE_LOOP); the normal slot is unused. */
  {
    static const float axes[6][6] = {{0, 0, 0, 0.9f, 0.15f, 0.1f},  {1.9f, 0, 0, 0.9f, 0.15f, 0.1f},
                                     {0, 0, 0, 0.1f, 0.8f, 0.2f},   {0, 1.9f, 0, 0.1f, 0.8f, 0.2f},
                                     {0, 0, 0, 0.2f, 0.35f, 0.95f}, {0, 0, 1.9f, 0.2f, 0.35f, 0.95f}};
    memcpy(lv, axes, sizeof axes);
    n = 6;
    for (i = 0; i < CIRCLE_SEGS; ++i) {
      const double a = 2.0 * 3.14159265358979 * (i + 0.37) / CIRCLE_SEGS;
      float* v = &lv[(n + i) * 6];
      v[0] = (float)cos(a) * 2.37f, v[1] = 0.0f, v[2] = (float)sin(a) * 2.37f;
      v[3] = 0.95f, v[4] = 0.8f, v[5] = 0.2f;
    }
  }
  glGenVertexArrays(1, &lines_vao);
  glBindVertexArray(lines_vao);
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, sizeof lv, lv, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)(3 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
}

static void model_of(int i, float* m) {
  float t[16], r[16], r2[16];
  int j;
  if (i == 0) {
    mat_translate(m, -1.23f, 0.71f, 0.37f);
    m[0] = m[5] = m[10] = 0.69f;
  } else if (i == 1) {
    mat_translate(t, 0.93f, 0.61f, -0.83f);
    mat_rotate_y(r, 27.0f);
    mat_rotate_x(r2, 19.0f);
    mat_mul(r, r, r2);
    mat_mul(m, t, r);
    for (j = 0; j < 11; ++j)
      if (j % 4 != 3) m[j] *= 1.07f;
  } else {
    mat_translate(t, 0.71f, 0.52f, 1.13f);
    mat_rotate_y(r, 13.0f);
    mat_mul(m, t, r);
  }
}

static void display(void) {
  static const float colors[3][3] = {{0.85f, 0.45f, 0.3f}, {0.35f, 0.7f, 0.45f}, {0.45f, 0.5f, 0.85f}};
  float m[16], ident[16];
  int i;
  glClearColor(0.93f, 0.93f, 0.9f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glLineWidth(1.0f);
  glUseProgram(prog);
  glUniformMatrix4fv(glGetUniformLocation(prog, "vp"), 1, GL_FALSE, vp);

  /* Pass 1: filled, lit, pushed back by the polygon offset. */
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  glUniform1i(glGetUniformLocation(prog, "lit"), 1);
  for (i = 0; i < 3; ++i) {
    model_of(i, m);
    glUniformMatrix4fv(glGetUniformLocation(prog, "model"), 1, GL_FALSE, m);
    glUniform3fv(glGetUniformLocation(prog, "color"), 1, colors[i]);
    glBindVertexArray(meshes[i].vao);
    glDrawElements(GL_TRIANGLES, meshes[i].count, GL_UNSIGNED_SHORT, 0);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);

  /* Pass 2: the same triangles as lines, dark, not offset. */
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glUniform1i(glGetUniformLocation(prog, "lit"), 0);
  glUniform3f(glGetUniformLocation(prog, "color"), 0.08f, 0.08f, 0.14f);
  for (i = 0; i < 3; ++i) {
    model_of(i, m);
    glUniformMatrix4fv(glGetUniformLocation(prog, "model"), 1, GL_FALSE, m);
    glBindVertexArray(meshes[i].vao);
    glDrawElements(GL_TRIANGLES, meshes[i].count, GL_UNSIGNED_SHORT, 0);
  }
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);

  /* Axes and the ground circle, flat colours, depth-tested against the meshes. */
  mat_identity(ident);
  glUniformMatrix4fv(glGetUniformLocation(prog, "model"), 1, GL_FALSE, ident);
  glBindVertexArray(lines_vao);
  for (i = 0; i < 3; ++i) {
    static const float axis_colors[3][3] = {{0.9f, 0.15f, 0.1f}, {0.1f, 0.6f, 0.2f}, {0.2f, 0.35f, 0.95f}};
    glUniform3fv(glGetUniformLocation(prog, "color"), 1, axis_colors[i]);
    glDrawArrays(GL_LINES, i * 2, 2);
  }
  glUniform3f(glGetUniformLocation(prog, "color"), 0.75f, 0.5f, 0.1f);
  glDrawArrays(GL_LINE_LOOP, 6, CIRCLE_SEGS);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  float view[16], proj[16];
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "wireframe polygon offset");
  prog = link_program(vs, fs);
  build();
  mat_perspective(proj, 37.0f, 320.0f / 240.0f, 1.0f, 30.0f);
  mat_lookat(view, 3.71f, 3.13f, 5.29f, 0.07f, 0.43f, 0.11f, 0, 1, 0);
  mat_mul(vp, proj, view);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
