/*
 * User clip distances and facing in a GL 3.3 core context (GLUT + GLEW). The vertex shader
 * writes gl_ClipDistance[0] and [1] (redeclared with two elements) from two world-space
 * planes, and the fragment shader picks a front or a back material with gl_FrontFacing and
 * lights the back faces with the flipped normal. Three objects:
 *  - a sphere with glEnable(GL_CLIP_DISTANCE0) and GL_CLIP_DISTANCE1 and culling off, cut by
 *    a horizontal and a slanted plane, so its inside (back faces) shows through the cuts;
 *  - a cube with glEnable(GL_CULL_FACE) and glCullFace(GL_FRONT): only its inner walls;
 *  - a bowl (the lower half of a sphere) built clockwise seen from outside, drawn with
 *    glFrontFace(GL_CW) and glCullFace(GL_BACK): its outside is front-facing and drawn, its
 *    inside culled.
 * The distances are written for every object; the clip planes are enabled for the first only
 * (the others get planes that keep everything).
 */
#include "common.h"

static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 pos;\n"
    "layout(location = 1) in vec3 nrm;\n"
    "uniform mat4 model, vp;\n"
    "uniform vec4 planes[2];\n"
    "out vec3 wnrm;\n"
    "out float gl_ClipDistance[2];\n"
    "void main() {\n"
    "  vec4 w = model * vec4(pos, 1.0);\n"
    "  wnrm = mat3(model) * nrm;\n"
    "  gl_ClipDistance[0] = dot(w, planes[0]);\n"
    "  gl_ClipDistance[1] = dot(w, planes[1]);\n"
    "  gl_Position = vp * w;\n"
    "}\n";
static const char* fs =
    "#version 330 core\n"
    "in vec3 wnrm;\n"
    "uniform vec3 front_color, back_color;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  vec3 n = normalize(wnrm);\n"
    "  vec3 c = front_color;\n"
    "  if (!gl_FrontFacing) {\n"
    "    n = -n;\n"
    "    c = back_color;\n"
    "  }\n"
    "  float d = max(dot(n, normalize(vec3(0.3, 0.85, 0.45))), 0.0);\n"
    "  frag = vec4(c * (0.3 + 0.7 * d), 1.0);\n"
    "}\n";

static GLuint prog, sphere_vao, cube_vao, bowl_vao;
static GLsizei bowl_count;
static float vp[16];

static GLuint make_mesh(const float* verts, int nverts, const unsigned short* idx, int nidx) {
  GLuint v, b[2];
  glGenVertexArrays(1, &v);
  glBindVertexArray(v);
  glGenBuffers(2, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(nverts * 6 * sizeof(float)), verts, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)(3 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(nidx * sizeof(unsigned short)), idx, GL_STATIC_DRAW);
  return v;
}

static void draw(GLuint vao, GLsizei count, const float* model, const float* front, const float* back) {
  glUniformMatrix4fv(glGetUniformLocation(prog, "model"), 1, GL_FALSE, model);
  glUniform3fv(glGetUniformLocation(prog, "front_color"), 1, front);
  glUniform3fv(glGetUniformLocation(prog, "back_color"), 1, back);
  glBindVertexArray(vao);
  glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_SHORT, 0);
}

static void display(void) {
  /* Keep y below 0.43 (a horizontal cut) and 0.8 x - 0.35 y + 0.5 z below -0.43 (a slanted cut),
   * in world space around the sphere at (-1.3, 0.2, 0). */
  static const float planes[8] = {0.0f, -1.0f, 0.0f, 0.43f, -0.8f, 0.35f, -0.5f, -0.43f},
                     keep_all[8] = {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f};
  static const float orange[3] = {0.9f, 0.5f, 0.2f}, teal[3] = {0.15f, 0.65f, 0.6f},
                     white[3] = {0.85f, 0.85f, 0.8f}, purple[3] = {0.55f, 0.25f, 0.75f},
                     green[3] = {0.3f, 0.75f, 0.3f}, red[3] = {0.9f, 0.15f, 0.15f};
  float m[16], t[16], r[16], r2[16];
  int j;
  glClearColor(0.12f, 0.12f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glUseProgram(prog);
  glUniformMatrix4fv(glGetUniformLocation(prog, "vp"), 1, GL_FALSE, vp);
  glUniform4fv(glGetUniformLocation(prog, "planes"), 2, planes);

  /* 1: the cut sphere, both sides drawn. */
  glDisable(GL_CULL_FACE);
  glEnable(GL_CLIP_DISTANCE0);
  glEnable(GL_CLIP_DISTANCE1);
  mat_translate(m, -1.3f, 0.2f, 0.0f);
  m[0] = m[5] = m[10] = 0.93f;
  draw(sphere_vao, SPHERE_INDICES, m, orange, teal);
  glDisable(GL_CLIP_DISTANCE0);
  glDisable(GL_CLIP_DISTANCE1);
  /* The other objects still write distances, through planes that keep everything (w > 0):
   * Mesa 22.3 llvmpipe clips by written distances even when GL_CLIP_DISTANCEi is disabled. */
  glUniform4fv(glGetUniformLocation(prog, "planes"), 2, keep_all);

  /* 2: the cube, front faces culled: its inner walls, back-facing. */
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  mat_translate(t, 0.83f, 0.61f, -0.37f);
  mat_rotate_y(r, 37.0f);
  mat_rotate_x(r2, 21.0f);
  mat_mul(r, r, r2);
  mat_mul(m, t, r);
  for (j = 0; j < 11; ++j)
    if (j % 4 != 3) m[j] *= 1.33f;
  draw(cube_vao, 36, m, white, purple);

  /* 3: the clockwise bowl, GL_CW front faces, back faces culled. */
  glCullFace(GL_BACK);
  glFrontFace(GL_CW);
  mat_translate(t, 0.37f, -0.63f, 1.07f);
  mat_rotate_x(r, -57.0f);
  mat_mul(m, t, r);
  m[0] *= 0.81f, m[1] *= 0.81f, m[2] *= 0.81f;
  m[4] *= 0.81f, m[5] *= 0.81f, m[6] *= 0.81f;
  m[8] *= 0.81f, m[9] *= 0.81f, m[10] *= 0.81f;
  draw(bowl_vao, bowl_count, m, green, red);
  glFrontFace(GL_CCW);
  glDisable(GL_CULL_FACE);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static float pos[SPHERE_VERTS * 3], sphere[SPHERE_VERTS * 6], cube[24 * 6];
  static unsigned short sidx[SPHERE_INDICES], bidx[SPHERE_INDICES / 2], cidx[36];
  float view[16], proj[16];
  int i, f, k = 0;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "clip distance two sided");
  prog = link_program(vs, fs);

  /* make_sphere's triangles are counter-clockwise seen from outside. */
  make_sphere(pos, sidx);
  for (i = 0; i < SPHERE_VERTS; ++i) {
    memcpy(&sphere[i * 6], &pos[i * 3], 3 * sizeof(float));
    memcpy(&sphere[i * 6 + 3], &pos[i * 3], 3 * sizeof(float));
  }
  sphere_vao = make_mesh(sphere, SPHERE_VERTS, sidx, SPHERE_INDICES);
  /* The bowl: the lower half of the stacks, each triangle's winding reversed (clockwise). */
  for (i = SPHERE_INDICES / 2; i < SPHERE_INDICES; i += 3) {
    bidx[k++] = sidx[i];
    bidx[k++] = sidx[i + 2];
    bidx[k++] = sidx[i + 1];
  }
  bowl_count = k;
  bowl_vao = make_mesh(sphere, SPHERE_VERTS, bidx, k);
  /* A unit cube, four vertices per face, counter-clockwise outside. */
  k = 0;
  for (f = 0; f < 6; ++f) {
    const int axis = f / 2;
    const float sgn = (f % 2) ? -1.0f : 1.0f;
    for (i = 0; i < 4; ++i) {
      float* v = &cube[(f * 4 + i) * 6];
      v[axis] = 0.5f * sgn;
      v[(axis + 1) % 3] = ((i == 1 || i == 2) ? 0.5f : -0.5f) * sgn;
      v[(axis + 2) % 3] = (i >= 2) ? 0.5f : -0.5f;
      v[3] = v[4] = v[5] = 0.0f;
      v[3 + axis] = sgn;
    }
    cidx[k++] = (unsigned short)(f * 4), cidx[k++] = (unsigned short)(f * 4 + 1);
    cidx[k++] = (unsigned short)(f * 4 + 2), cidx[k++] = (unsigned short)(f * 4);
    cidx[k++] = (unsigned short)(f * 4 + 2), cidx[k++] = (unsigned short)(f * 4 + 3);
  }
  cube_vao = make_mesh(cube, 24, cidx, 36);

  mat_perspective(proj, 48.0f, 320.0f / 240.0f, 1.0f, 30.0f);
  mat_lookat(view, 0.61f, 2.93f, 5.37f, -0.07f, 0.13f, 0.03f, 0, 1, 0);
  mat_mul(vp, proj, view);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
