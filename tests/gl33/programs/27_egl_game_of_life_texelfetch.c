/*
 * Conway's game of life as GPGPU code writes it, headless through EGL (a pbuffer, 3.3 core):
 * the initial board is an R8 texture filled from a deterministic pattern (a seeded LCG soup,
 * a glider, an R-pentomino); 20 generations ping-pong between two RGBA8 textures attached to
 * two FBOs, each step a full-screen pass that reads the eight neighbours with texelFetch,
 * wraps around with integer arithmetic ((p + d + size) % size on ivec2) and writes
 * alive / neighbour count / age. The final board is read back with glReadPixels from its FBO
 * and compared with the same simulation on the CPU; the pbuffer then shows the board scaled
 * up 4x (GL_NEAREST, a viewport), coloured by neighbour count and age with a grid drawn from
 * integer gl_FragCoord arithmetic, per-row live counts as scissored clears to its right, and
 * two bars at the bottom whose lengths are the live-cell counts of the GPU read-back and of
 * the CPU simulation (with ticks every 20 cells).
 */
#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 320
#define H 240
#define BW 64
#define BH 48
#define STEPS 20

static const char* quad_vs =
    "#version 330 core\n"
    "const vec2 corner[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(-1, 1), vec2(1, 1));\n"
    "out vec2 uv;\n"
    "void main() { uv = corner[gl_VertexID] * 0.5 + 0.5; gl_Position = vec4(corner[gl_VertexID], 0.0, 1.0); "
    "}\n";
static const char* step_fs =
    "#version 330 core\n"
    "uniform sampler2D state;\n"
    "out vec4 next;\n"
    "void main() {\n"
    "  ivec2 size = textureSize(state, 0);\n"
    "  ivec2 p = ivec2(gl_FragCoord.xy);\n"
    "  int n = 0;\n"
    "  for (int dy = -1; dy <= 1; ++dy)\n"
    "    for (int dx = -1; dx <= 1; ++dx) {\n"
    "      if (dx == 0 && dy == 0) continue;\n"
    "      ivec2 q = (p + ivec2(dx, dy) + size) % size;\n"
    "      n += texelFetch(state, q, 0).r > 0.5 ? 1 : 0;\n"
    "    }\n"
    "  vec4 cur = texelFetch(state, p, 0);\n"
    "  bool alive = cur.r > 0.5;\n"
    "  int age = int(cur.b * 255.0 + 0.5);\n"
    "  bool live = n == 3 || (alive && n == 2);\n"
    "  age = live ? min(age + 1, 15) : 0;\n"
    "  next = vec4(live ? 1.0 : 0.0, float(n) / 8.0, float(age) / 255.0, 1.0);\n"
    "}\n";
static const char* show_fs =
    "#version 330 core\n"
    "uniform sampler2D board;\n"
    "uniform ivec2 origin;\n"
    "in vec2 uv;\n"
    "out vec4 color;\n"
    "void main() {\n"
    "  vec4 s = texture(board, uv);\n"
    "  int n = int(s.g * 8.0 + 0.5);\n"
    "  int age = int(s.b * 255.0 + 0.5);\n"
    "  vec3 c;\n"
    "  switch (n) {\n"
    "  case 0: c = vec3(0.2, 0.2, 0.3); break;\n"
    "  case 1: c = vec3(0.2, 0.4, 0.9); break;\n"
    "  case 2: c = vec3(0.1, 0.8, 0.4); break;\n"
    "  case 3: c = vec3(1.0, 0.9, 0.2); break;\n"
    "  case 4: c = vec3(1.0, 0.5, 0.1); break;\n"
    "  default: c = vec3(0.9, 0.1, 0.2); break;\n"
    "  }\n"
    "  if (s.r > 0.5) c *= 0.5 + 0.5 * float(min(age, 10)) / 10.0;\n"
    "  else c *= 0.18;\n"
    "  ivec2 px = ivec2(gl_FragCoord.xy) - origin;\n"
    "  if ((px.x & 3) == 0 || px.y % 4 == 0) c *= 0.6;\n"
    "  if ((px.x >> 5) % 2 == 0 && px.y / 32 == 0) c += vec3(0.05);\n"
    "  color = vec4(c, 1.0);\n"
    "}\n";

static void die(const char* what) {
  fprintf(stderr, "egl_game_of_life: %s failed (EGL 0x%04X, GL 0x%04X)\n", what, eglGetError(), glGetError());
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

static GLuint board_texture(GLint internal, GLenum format, const void* pixels) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, internal, BW, BH, 0, format, GL_UNSIGNED_BYTE, pixels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

static void fill(int x, int y, int w, int h, float r, float g, float b) {
  glScissor(x, y, w, h);
  glClearColor(r, g, b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

int main(void) {
  static const EGLint cfg[] = {
      EGL_SURFACE_TYPE,    EGL_PBUFFER_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
      EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,  EGL_NONE};
  static const EGLint pb[] = {EGL_WIDTH, W, EGL_HEIGHT, H, EGL_NONE};
  static const EGLint ctx_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  static const int glider[5][2] = {{1, 0}, {2, 1}, {0, 2}, {1, 2}, {2, 2}};
  static const int rpent[5][2] = {{1, 0}, {2, 0}, {0, 1}, {1, 1}, {1, 2}};
  static unsigned char cells[BH][BW], tmp[BH][BW], back[BH][BW][4];
  EGLDisplay dpy;
  EGLConfig config;
  EGLint n;
  EGLSurface surf;
  EGLContext ctx;
  GLuint step, show, vao, init, tex[2], fbo[2];
  unsigned int seed = 12345u;
  int x, y, i, k, live_gpu = 0, live_cpu = 0, mismatches = 0, rows[BH];

  dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (!eglInitialize(dpy, NULL, NULL)) die("eglInitialize");
  if (!eglChooseConfig(dpy, cfg, &config, 1, &n) || n < 1) die("eglChooseConfig");
  surf = eglCreatePbufferSurface(dpy, config, pb);
  if (surf == EGL_NO_SURFACE) die("eglCreatePbufferSurface");
  eglBindAPI(EGL_OPENGL_API);
  ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctx_attribs);
  if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, surf, surf, ctx)) die("context");

  /* The initial board: a soup in the left half, a glider and an R-pentomino on the right. */
  memset(cells, 0, sizeof cells);
  for (y = 4; y < 40; ++y)
    for (x = 3; x < 30; ++x) {
      seed = seed * 1103515245u + 12345u;
      cells[y][x] = ((seed >> 16) % 100u) < 33u ? 255 : 0;
    }
  for (i = 0; i < 5; ++i) {
    cells[30 + glider[i][1]][44 + glider[i][0]] = 255;
    cells[12 + rpent[i][1]][50 + rpent[i][0]] = 255;
  }

  step = program(quad_vs, step_fs);
  show = program(quad_vs, show_fs);
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  init = board_texture(GL_R8, GL_RED, cells);
  for (i = 0; i < 2; ++i) {
    tex[i] = board_texture(GL_RGBA8, GL_RGBA, NULL);
    glGenFramebuffers(1, &fbo[i]);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo[i]);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[i], 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) die("framebuffer");
  }

  /* 20 generations: init -> tex[0] -> tex[1] -> tex[0] ... */
  glUseProgram(step);
  glUniform1i(glGetUniformLocation(step, "state"), 0);
  glActiveTexture(GL_TEXTURE0);
  glViewport(0, 0, BW, BH);
  for (k = 0; k < STEPS; ++k) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo[k % 2]);
    glBindTexture(GL_TEXTURE_2D, k == 0 ? init : tex[(k + 1) % 2]);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  if (glGetError() != GL_NO_ERROR) die("simulation");

  /* Read the last generation back from its FBO. */
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[(STEPS - 1) % 2]);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, BW, BH, GL_RGBA, GL_UNSIGNED_BYTE, back);
  if (glGetError() != GL_NO_ERROR) die("glReadPixels");

  /* The same generations on the CPU. */
  for (k = 0; k < STEPS; ++k) {
    for (y = 0; y < BH; ++y)
      for (x = 0; x < BW; ++x) {
        int dx, dy, c = 0;
        for (dy = -1; dy <= 1; ++dy)
          for (dx = -1; dx <= 1; ++dx)
            if ((dx || dy) && cells[(y + dy + BH) % BH][(x + dx + BW) % BW]) ++c;
        tmp[y][x] = (c == 3 || (cells[y][x] && c == 2)) ? 255 : 0;
      }
    memcpy(cells, tmp, sizeof cells);
  }
  for (y = 0; y < BH; ++y) {
    rows[y] = 0;
    for (x = 0; x < BW; ++x) {
      const int g = back[y][x][0] > 127;
      rows[y] += g;
      live_gpu += g;
      live_cpu += cells[y][x] != 0;
      mismatches += g != (cells[y][x] != 0);
    }
  }
  printf("live cells after %d generations: GPU %d, CPU %d, %d cells differ\n", STEPS, live_gpu, live_cpu,
         mismatches);

  /* The picture: the board 4x at (8, 40), row counts to its right, the two count bars. */
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, W, H);
  glClearColor(0.06f, 0.06f, 0.08f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glViewport(8, 40, BW * 4, BH * 4);
  glUseProgram(show);
  glUniform1i(glGetUniformLocation(show, "board"), 0);
  glUniform2i(glGetUniformLocation(show, "origin"), 8, 40);
  glBindTexture(GL_TEXTURE_2D, tex[(STEPS - 1) % 2]);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glEnable(GL_SCISSOR_TEST);
  for (y = 0; y < BH; ++y)
    if (rows[y])
      fill(268, 40 + 4 * y, (rows[y] * 2 < 48 ? rows[y] * 2 : 48) + 1, 3, 0.3f + 0.02f * (float)(y % 8), 0.7f,
           0.5f);
  fill(8, 22, (live_gpu < 400 ? live_gpu : 400) * 304 / 400 + 1, 12, 0.95f, 0.75f, 0.2f);
  fill(8, 8, (live_cpu < 400 ? live_cpu : 400) * 304 / 400 + 1, 8, 0.3f, 0.6f, 0.95f);
  for (i = 20; i * 304 / 400 < 304; i += 20) fill(8 + i * 304 / 400, 1, 1, i % 100 ? 3 : 6, 0.8f, 0.8f, 0.8f);
  fill(300, 216, 12, 12, mismatches ? 1.0f : 0.1f, mismatches ? 0.1f : 0.9f, 0.1f);
  glDisable(GL_SCISSOR_TEST);
  if (glGetError() != GL_NO_ERROR) die("drawing");
  if (!eglSwapBuffers(dpy, surf)) die("eglSwapBuffers");
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(dpy, ctx);
  eglDestroySurface(dpy, surf);
  eglTerminate(dpy);
  return 0;
}
