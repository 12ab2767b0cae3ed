/*
 * A program that loads its GL entry points itself, as glad-generated code does: it includes
 * GL/glcorearb.h for the types and enums only (and keeps GL/gl.h out), declares a function
 * pointer per entry point, and fills them from glutGetProcAddress. Everything GL does here
 * goes through those pointers: a 3.3 core context, a cube of 36 vertices with per-face
 * colours, depth testing, face culling, glDrawElements over an element buffer, and a uniform
 * matrix written with transpose = GL_FALSE as LearnOpenGL's code does.
 */
#include <GL/glcorearb.h>
#define __gl_h_ 1 /* as glad's header does: no other GL header after this one */
#define __GL_H__ 1
// clang-format off (the order matters)
#include <GL/freeglut.h>
// clang-format on

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GL_FUNCTIONS(X)                                          \
  X(PFNGLCREATESHADERPROC, glCreateShader)                       \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                       \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                     \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                         \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                     \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                       \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                         \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                       \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                           \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)           \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)               \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                 \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                 \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                           \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                           \
  X(PFNGLBUFFERDATAPROC, glBufferData)                           \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)         \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray) \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                       \
  X(PFNGLCLEARCOLORPROC, glClearColor)                           \
  X(PFNGLCLEARPROC, glClear)                                     \
  X(PFNGLENABLEPROC, glEnable)                                   \
  X(PFNGLCULLFACEPROC, glCullFace)                               \
  X(PFNGLGETERRORPROC, glGetError)                               \
  X(PFNGLGETSTRINGPROC, glGetString)

#define DECLARE(type, name) static type my_##name;
GL_FUNCTIONS(DECLARE)
#undef DECLARE

static int load_gl(void) {
  int missing = 0;
#define LOAD(type, name)                                       \
  my_##name = (type)(void (*)(void))glutGetProcAddress(#name); \
  if (!my_##name) {                                            \
    fprintf(stderr, "no %s\n", #name);                         \
    missing = 1;                                               \
  }
  GL_FUNCTIONS(LOAD)
#undef LOAD
  return !missing;
}

static const char* vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec3 aColor;\n"
    "uniform mat4 transform;\n"
    "out vec3 ourColor;\n"
    "void main() { gl_Position = transform * vec4(aPos, 1.0); ourColor = aColor; }\n";

static const char* fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec3 ourColor;\n"
    "void main() { FragColor = vec4(ourColor, 1.0); }\n";

static GLuint prog, vao;

static void display(void) {
  float m[16];
  const float ax = 0.5f, ay = 0.7f, ca = cosf(ax), sa = sinf(ax), cb = cosf(ay), sb = sinf(ay);
  /* transform = scale(0.5) * rotate_x(ax) * rotate_y(ay), with z scaled into the depth range. */
  const float r[9] = {cb, sa * sb, -ca * sb, 0.0f, ca, sa, sb, -sa * cb, ca * cb}; /* column-major */
  memset(m, 0, sizeof m);
  m[0] = 0.5f * r[0] * 0.75f;
  m[1] = 0.5f * r[1];
  m[2] = 0.5f * r[2];
  m[4] = 0.5f * r[3] * 0.75f;
  m[5] = 0.5f * r[4];
  m[6] = 0.5f * r[5];
  m[8] = 0.5f * r[6] * 0.75f;
  m[9] = 0.5f * r[7];
  m[10] = 0.5f * r[8];
  m[15] = 1.0f;
  my_glClearColor(0.2f, 0.3f, 0.3f, 1.0f);
  my_glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  my_glUseProgram(prog);
  my_glUniformMatrix4fv(my_glGetUniformLocation(prog, "transform"), 1, GL_FALSE, m);
  my_glBindVertexArray(vao);
  my_glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_INT, 0);
  if (my_glGetError() != GL_NO_ERROR) {
    fprintf(stderr, "GL error\n");
    exit(1);
  }
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  /* 8 corners; each face's colour comes from its first corner (faces share no vertex here:
   * 24 vertices, 4 per face). */
  static const float corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                     {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  static const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 4, 7, 3},
                                  {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}};
  static const float colors[6][3] = {{1, 0.3f, 0.3f}, {0.3f, 1, 0.3f}, {0.3f, 0.3f, 1},
                                     {1, 1, 0.3f},    {0.3f, 1, 1},    {1, 0.3f, 1}};
  float verts[24 * 6];
  unsigned int idx[36];
  GLuint vbo, ebo, vsh, fsh;
  GLint ok = 0;
  int f, k;
  glutInit(&argc, argv);
  glutInitContextVersion(3, 3);
  glutInitContextProfile(GLUT_CORE_PROFILE);
  glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH);
  glutInitWindowSize(320, 240);
  glutCreateWindow("loader core");
  if (!load_gl()) return 1;
  if (strncmp((const char*)my_glGetString(GL_VERSION), "3.", 2) < 0) return 1;
  for (f = 0; f < 6; ++f)
    for (k = 0; k < 4; ++k) {
      float* v = &verts[(f * 4 + k) * 6];
      memcpy(v, corner[faces[f][k]], 3 * sizeof(float));
      v[3] = colors[f][0] * (k == 2 ? 0.6f : 1.0f);
      v[4] = colors[f][1];
      v[5] = colors[f][2] * (k == 1 ? 0.5f : 1.0f);
    }
  for (f = 0; f < 6; ++f) {
    const unsigned int b = (unsigned int)f * 4u;
    const unsigned int quad[6] = {b, b + 1, b + 2, b, b + 2, b + 3};
    memcpy(&idx[f * 6], quad, sizeof quad);
  }
  vsh = my_glCreateShader(GL_VERTEX_SHADER);
  my_glShaderSource(vsh, 1, &vs, NULL);
  my_glCompileShader(vsh);
  fsh = my_glCreateShader(GL_FRAGMENT_SHADER);
  my_glShaderSource(fsh, 1, &fs, NULL);
  my_glCompileShader(fsh);
  prog = my_glCreateProgram();
  my_glAttachShader(prog, vsh);
  my_glAttachShader(prog, fsh);
  my_glLinkProgram(prog);
  my_glGetProgramiv(prog, GL_LINK_STATUS, &ok);
  if (!ok) return 1;
  my_glGenVertexArrays(1, &vao);
  my_glBindVertexArray(vao);
  my_glGenBuffers(1, &vbo);
  my_glBindBuffer(GL_ARRAY_BUFFER, vbo);
  my_glBufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STATIC_DRAW);
  my_glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)0);
  my_glEnableVertexAttribArray(0);
  my_glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)(3 * sizeof(float)));
  my_glEnableVertexAttribArray(1);
  my_glGenBuffers(1, &ebo);
  my_glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
  my_glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
  my_glEnable(GL_DEPTH_TEST);
  my_glEnable(GL_CULL_FACE);
  my_glCullFace(GL_BACK);
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
