/*
 * Two LearnOpenGL chapters in one GL 3.3 core program (GLUT + GLEW): "stencil testing" (object
 * outlining: the cubes drawn writing 1 to the stencil buffer with glStencilFunc/Op/Mask, then,
 * last, drawn again scaled up in a flat colour where the stencil is not 1, with the depth test
 * off) and "cubemaps" (a skybox from a cube map of six generated faces, drawn with
 * gl_Position.xyww and GL_LEQUAL, and a sphere reflecting it with reflect() and a
 * samplerCube). Also a separate back-face stencil operation on the sphere
 * (glStencilOpSeparate) and GL_INCR_WRAP.
 */
#include "common.h"

#define FACE 32

static const char* obj_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec3 aNormal;\n"
    "out vec3 Normal;\n"
    "out vec3 Position;\n"
    "uniform mat4 model, view, projection;\n"
    "void main() {\n"
    "  Normal = mat3(model) * aNormal;\n"
    "  Position = vec3(model * vec4(aPos, 1.0));\n"
    "  gl_Position = projection * view * vec4(Position, 1.0);\n"
    "}\n";
static const char* reflect_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec3 Normal;\n"
    "in vec3 Position;\n"
    "uniform vec3 cameraPos;\n"
    "uniform samplerCube skybox;\n"
    "void main() {\n"
    "  vec3 I = normalize(Position - cameraPos);\n"
    "  vec3 R = reflect(I, normalize(Normal));\n"
    "  FragColor = vec4(texture(skybox, R).rgb, 1.0);\n"
    "}\n";
static const char* lit_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec3 Normal;\n"
    "in vec3 Position;\n"
    "uniform vec3 color;\n"
    "uniform bool flat_color;\n"
    "void main() {\n"
    "  if (flat_color) { FragColor = vec4(color, 1.0); return; }\n"
    "  float d = max(dot(normalize(Normal), normalize(vec3(0.4, 0.8, 0.5))), 0.0);\n"
    "  FragColor = vec4(color * (0.25 + 0.75 * d), 1.0);\n"
    "}\n";
static const char* sky_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "out vec3 TexCoords;\n"
    "uniform mat4 projection;\n"
    "uniform mat4 view;\n"
    "void main() {\n"
    "  TexCoords = aPos;\n"
    "  vec4 pos = projection * view * vec4(aPos, 1.0);\n"
    "  gl_Position = pos.xyww;\n"
    "}\n";
static const char* sky_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec3 TexCoords;\n"
    "uniform samplerCube skybox;\n"
    "void main() { FragColor = texture(skybox, TexCoords); }\n";

static GLuint reflect_prog, lit_prog, sky_prog, cube_vao, sphere_vao, cubemap;
static float view[16], proj[16], sky_view[16];
static const float eye[3] = {0.0f, 1.2f, 5.0f};

static void set_common(GLuint p, const float* model) {
  glUseProgram(p);
  glUniformMatrix4fv(glGetUniformLocation(p, "model"), 1, GL_FALSE, model);
  glUniformMatrix4fv(glGetUniformLocation(p, "view"), 1, GL_FALSE, view);
  glUniformMatrix4fv(glGetUniformLocation(p, "projection"), 1, GL_FALSE, proj);
}

static void cube_model(float* m, float x, float scale) {
  mat_translate(m, x, 0.0f, 0.0f);
  m[0] = m[5] = m[10] = scale;
}

static void display(void) {
  float m[16];
  int i;
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);

  /* The reflecting sphere: no stencil writes from its front faces; back faces (hidden by the
   * depth test, so never reaching the stencil op) would wrap. */
  glStencilMask(0x00);
  mat_translate(m, 0.0f, 0.0f, -1.0f);
  set_common(reflect_prog, m);
  glUniform3fv(glGetUniformLocation(reflect_prog, "cameraPos"), 1, eye);
  glUniform1i(glGetUniformLocation(reflect_prog, "skybox"), 0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cubemap);
  glBindVertexArray(sphere_vao);
  glDrawElements(GL_TRIANGLES, SPHERE_INDICES, GL_UNSIGNED_SHORT, 0);

  /* 1st pass: the cubes, writing 1 to the stencil buffer. */
  glStencilFunc(GL_ALWAYS, 1, 0xFF);
  glStencilMask(0xFF);
  glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
  glBindVertexArray(cube_vao);
  for (i = 0; i < 2; ++i) {
    cube_model(m, i ? 1.6f : -1.6f, 1.0f);
    set_common(lit_prog, m);
    glUniform3f(glGetUniformLocation(lit_prog, "color"), i ? 0.3f : 0.8f, 0.6f, i ? 0.8f : 0.3f);
    glUniform1i(glGetUniformLocation(lit_prog, "flat_color"), 0);
    glDrawArrays(GL_TRIANGLES, 0, 36);
  }
  /* The skybox where nothing was drawn (depth 1.0 passes GL_LEQUAL), the stencil untouched. */
  glStencilMask(0x00);
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  glDepthFunc(GL_LEQUAL);
  glUseProgram(sky_prog);
  glUniformMatrix4fv(glGetUniformLocation(sky_prog, "view"), 1, GL_FALSE, sky_view);
  glUniformMatrix4fv(glGetUniformLocation(sky_prog, "projection"), 1, GL_FALSE, proj);
  glUniform1i(glGetUniformLocation(sky_prog, "skybox"), 0);
  glBindVertexArray(cube_vao);
  glDrawArrays(GL_TRIANGLES, 0, 36);
  glDepthFunc(GL_LESS);
  /* Last: slightly larger cubes where the stencil is not 1, no depth test: the outline. */
  glStencilFunc(GL_NOTEQUAL, 1, 0xFF);
  glStencilMask(0x00);
  glDisable(GL_DEPTH_TEST);
  for (i = 0; i < 2; ++i) {
    cube_model(m, i ? 1.6f : -1.6f, 1.12f);
    set_common(lit_prog, m);
    glUniform3f(glGetUniformLocation(lit_prog, "color"), 0.04f, 0.28f, 0.26f);
    glUniform1i(glGetUniformLocation(lit_prog, "flat_color"), 1);
    glDrawArrays(GL_TRIANGLES, 0, 36);
  }
  glStencilMask(0xFF);
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);

  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static float pos[SPHERE_VERTS * 3], sphere[SPHERE_VERTS * 6];
  static unsigned short idx[SPHERE_INDICES];
  float cube[36 * 6];
  static const signed char faces[6][4][3] = {
      {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}}, {{-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}, {-1, -1, -1}},
      {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}}, {{-1, -1, 1}, {-1, -1, -1}, {1, -1, -1}, {1, -1, 1}},
      {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}, {{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}}};
  static const float normals[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  static const int tri[6] = {0, 1, 2, 0, 2, 3};
  unsigned char texels[FACE * FACE * 3];
  GLuint b[3];
  int i, f, k, x, y;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "stencil outline and cubemap");
  reflect_prog = link_program(obj_vs, reflect_fs);
  lit_prog = link_program(obj_vs, lit_fs);
  sky_prog = link_program(sky_vs, sky_fs);
  /* A cube of half-size 0.5 with face normals (counter-clockwise outside). */
  for (f = 0; f < 6; ++f)
    for (k = 0; k < 6; ++k) {
      float* v = &cube[(f * 6 + k) * 6];
      for (i = 0; i < 3; ++i) {
        v[i] = 0.5f * faces[f][tri[k]][i];
        v[3 + i] = normals[f][i];
      }
    }
  make_sphere(pos, idx);
  for (i = 0; i < SPHERE_VERTS; ++i) {
    memcpy(&sphere[i * 6], &pos[i * 3], 3 * sizeof(float));
    memcpy(&sphere[i * 6 + 3], &pos[i * 3], 3 * sizeof(float));
  }
  glGenVertexArrays(1, &cube_vao);
  glGenVertexArrays(1, &sphere_vao);
  glGenBuffers(3, b);
  glBindVertexArray(cube_vao);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof cube, cube, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 24, (void*)0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 24, (void*)12);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glBindVertexArray(sphere_vao);
  glBindBuffer(GL_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ARRAY_BUFFER, sizeof sphere, sphere, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 24, (void*)0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 24, (void*)12);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[2]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);

  /* The cube map: each face a gradient in its own hue with a grid, RGB, rows from 1. */
  glGenTextures(1, &cubemap);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cubemap);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (f = 0; f < 6; ++f) {
    for (y = 0; y < FACE; ++y)
      for (x = 0; x < FACE; ++x) {
        unsigned char* t = &texels[(y * FACE + x) * 3];
        const int grid = (x % 8 == 0) || (y % 8 == 0);
        const int g = 60 + y * 5;
        t[0] = (unsigned char)(grid ? 230 : (f == 0 || f == 3 || f == 4) ? g : 40);
        t[1] = (unsigned char)(grid ? 230 : (f == 1 || f == 3 || f == 5) ? g : 50);
        t[2] = (unsigned char)(grid ? 230 : (f == 2 || f == 4 || f == 5) ? g : 60);
      }
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_RGB8, FACE, FACE, 0, GL_RGB,
                 GL_UNSIGNED_BYTE, texels);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);

  mat_perspective(proj, 55.0f, 320.0f / 240.0f, 0.5f, 50.0f);
  {
    float r[16], t[16];
    mat_rotate_x(r, 12.0f);
    mat_translate(t, -eye[0], -eye[1], -eye[2]);
    mat_mul(view, r, t);
    memcpy(sky_view, view, sizeof view);
    sky_view[12] = sky_view[13] = sky_view[14] = 0.0f; /* the skybox ignores the translation */
  }
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
