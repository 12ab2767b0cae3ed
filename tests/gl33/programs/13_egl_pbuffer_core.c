/*
 * Headless OpenGL through EGL as server-side code writes it (the pattern of NVIDIA's "EGL
 * Eye" article): eglGetDisplay(EGL_DEFAULT_DISPLAY), eglChooseConfig for a pbuffer with
 * depth, eglCreatePbufferSurface, eglBindAPI(EGL_OPENGL_API), a 3.3 core context from the
 * version and profile attributes, and a frame drawn into the pbuffer: lit spheres from one
 * VAO, instanced with a per-instance offset and colour (glVertexAttribDivisor), over a
 * gradient background drawn first with the depth test off. Linked with -lEGL -lOpenGL only.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 320
#define H 240
#define SLICES 24
#define STACKS 12
#define NV ((SLICES + 1) * (STACKS + 1))
#define NI (SLICES * STACKS * 6)

static const EGLint config_attribs[] = {EGL_SURFACE_TYPE,
                                        EGL_PBUFFER_BIT,
                                        EGL_BLUE_SIZE,
                                        8,
                                        EGL_GREEN_SIZE,
                                        8,
                                        EGL_RED_SIZE,
                                        8,
                                        EGL_DEPTH_SIZE,
                                        8,
                                        EGL_RENDERABLE_TYPE,
                                        EGL_OPENGL_BIT,
                                        EGL_NONE};
static const EGLint pbuffer_attribs[] = {EGL_WIDTH, W, EGL_HEIGHT, H, EGL_NONE};
static const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         3,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};

static const char* bg_vs =
    "#version 330 core\n"
    "const vec2 corner[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(-1, 1), vec2(1, 1));\n"
    "out float t;\n"
    "void main() { t = corner[gl_VertexID].y * 0.5 + 0.5; gl_Position = vec4(corner[gl_VertexID], 0, 1); }\n";
static const char* bg_fs =
    "#version 330 core\n"
    "in float t;\n"
    "out vec4 color;\n"
    "void main() { color = vec4(mix(vec3(0.05, 0.05, 0.1), vec3(0.3, 0.4, 0.6), t), 1.0); }\n";
static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 position;\n"
    "layout(location = 1) in vec3 offset;   // per instance\n"
    "layout(location = 2) in vec3 albedo;   // per instance\n"
    "uniform mat4 projection;\n"
    "out vec3 n;\n"
    "out vec3 c;\n"
    "void main() {\n"
    "  n = position;\n"
    "  c = albedo;\n"
    "  gl_Position = projection * vec4(position * 0.45 + offset, 1.0);\n"
    "}\n";
static const char* fs =
    "#version 330 core\n"
    "in vec3 n;\n"
    "in vec3 c;\n"
    "out vec4 color;\n"
    "void main() {\n"
    "  vec3 l = normalize(vec3(-0.4, 0.7, 0.6));\n"
    "  vec3 nn = normalize(n);\n"
    "  float d = max(dot(nn, l), 0.0);\n"
    "  float s = pow(max(dot(reflect(-l, nn), vec3(0, 0, 1)), 0.0), 24.0);\n"
    "  color = vec4(c * (0.2 + 0.8 * d) + vec3(0.5) * s, 1.0);\n"
    "}\n";

static void die(const char* what) {
  fprintf(stderr, "egl_pbuffer_core: %s failed (EGL error 0x%04X, GL error 0x%04X)\n", what, eglGetError(),
          glGetError());
  exit(1);
}

static GLuint program(const char* v, const char* f) {
  GLuint p = glCreateProgram();
  const char* src[2] = {v, f};
  GLenum type[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
  GLint ok = 0;
  int i;
  for (i = 0; i < 2; ++i) {
    GLuint s = glCreateShader(type[i]);
    glShaderSource(s, 1, &src[i], NULL);
    glCompileShader(s);
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[2048];
      glGetShaderInfoLog(s, sizeof log, NULL, log);
      fprintf(stderr, "%s\n", log);
      die("glCompileShader");
    }
    glAttachShader(p, s);
    glDeleteShader(s);
  }
  glLinkProgram(p);
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) die("glLinkProgram");
  return p;
}

int main(void) {
  EGLDisplay dpy;
  EGLConfig config;
  EGLint major, minor, n;
  EGLSurface surface;
  EGLContext context;
  static float pos[NV * 3];
  static unsigned short idx[NI];
  float inst[12 * 6];
  float proj[16];
  GLuint vao, buf[3], bg_prog, prog, empty_vao;
  int i, j, k = 0;

  dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor)) die("eglInitialize");
  if (!eglChooseConfig(dpy, config_attribs, &config, 1, &n) || n != 1) die("eglChooseConfig");
  surface = eglCreatePbufferSurface(dpy, config, pbuffer_attribs);
  if (surface == EGL_NO_SURFACE) die("eglCreatePbufferSurface");
  if (!eglBindAPI(EGL_OPENGL_API)) die("eglBindAPI");
  context = eglCreateContext(dpy, config, EGL_NO_CONTEXT, context_attribs);
  if (context == EGL_NO_CONTEXT) die("eglCreateContext");
  if (!eglMakeCurrent(dpy, surface, surface, context)) die("eglMakeCurrent");

  for (j = 0; j <= STACKS; ++j)
    for (i = 0; i <= SLICES; ++i) {
      const double th = 3.14159265358979 * j / STACKS, ph = 2.0 * 3.14159265358979 * i / SLICES;
      pos[k++] = (float)(sin(th) * cos(ph));
      pos[k++] = (float)cos(th);
      pos[k++] = (float)(sin(th) * sin(ph));
    }
  k = 0;
  for (j = 0; j < STACKS; ++j)
    for (i = 0; i < SLICES; ++i) {
      const unsigned short a = (unsigned short)(j * (SLICES + 1) + i), b = (unsigned short)(a + SLICES + 1);
      idx[k++] = a;
      idx[k++] = b;
      idx[k++] = (unsigned short)(a + 1);
      idx[k++] = (unsigned short)(a + 1);
      idx[k++] = b;
      idx[k++] = (unsigned short)(b + 1);
    }
  for (i = 0; i < 12; ++i) {
    inst[i * 6 + 0] = (float)(i % 4) - 1.5f;
    inst[i * 6 + 1] = (float)(i / 4) - 1.0f;
    inst[i * 6 + 2] = -4.0f - 0.3f * (float)(i % 3);
    inst[i * 6 + 3] = 0.3f + 0.6f * (float)((i * 7) % 5) / 4.0f;
    inst[i * 6 + 4] = 0.3f + 0.6f * (float)((i * 3) % 4) / 3.0f;
    inst[i * 6 + 5] = 0.9f - 0.6f * (float)(i % 6) / 5.0f;
  }
  memset(proj, 0, sizeof proj);
  proj[0] = 1.8f / ((float)W / (float)H);
  proj[5] = 1.8f;
  proj[10] = -(20.0f + 1.0f) / (20.0f - 1.0f);
  proj[11] = -1.0f;
  proj[14] = -2.0f * 20.0f * 1.0f / (20.0f - 1.0f);

  bg_prog = program(bg_vs, bg_fs);
  prog = program(vs, fs);
  glGenVertexArrays(1, &empty_vao);
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(3, buf);
  glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof pos, pos, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, 0);
  glEnableVertexAttribArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, buf[1]);
  glBufferData(GL_ARRAY_BUFFER, sizeof inst, inst, GL_STATIC_DRAW);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), 0);
  glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)(3 * sizeof(float)));
  glVertexAttribDivisor(1, 1);
  glVertexAttribDivisor(2, 1);
  glEnableVertexAttribArray(1);
  glEnableVertexAttribArray(2);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buf[2]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);

  glViewport(0, 0, W, H);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(bg_prog);
  glBindVertexArray(empty_vao);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glUseProgram(prog);
  glUniformMatrix4fv(glGetUniformLocation(prog, "projection"), 1, GL_FALSE, proj);
  glBindVertexArray(vao);
  glDrawElementsInstanced(GL_TRIANGLES, NI, GL_UNSIGNED_SHORT, 0, 12);
  if (glGetError() != GL_NO_ERROR) die("drawing");
  if (!eglSwapBuffers(dpy, surface)) die("eglSwapBuffers");

  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(dpy, context);
  eglDestroySurface(dpy, surface);
  eglTerminate(dpy);
  return 0;
}
