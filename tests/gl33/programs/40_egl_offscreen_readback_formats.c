/*
 * Offscreen rendering and readback in many formats, headless through EGL (a pbuffer, 3.3
 * core), as server-side renderers and test harnesses write it: a lit scene (a floor and three
 * spheres) drawn into an FBO with two colour attachments, RGBA8 and RGBA16F (MRT, cleared
 * separately with glClearBufferfv), and a depth renderbuffer. The attachments are then read
 * back with glReadPixels as GL_RGBA/GL_UNSIGNED_BYTE, GL_BGRA/GL_UNSIGNED_INT_8_8_8_8_REV,
 * GL_RGB/GL_UNSIGNED_SHORT_5_6_5, GL_RGBA/GL_FLOAT (glReadBuffer(GL_COLOR_ATTACHMENT1)) and,
 * through a GL_PIXEL_PACK_BUFFER with GL_PACK_ALIGNMENT 1 and GL_PACK_ROW_LENGTH, as an odd
 * sub-rectangle in GL_RGB mapped with glMapBufferRange. CPU statistics (region means, a
 * luminance histogram, a column profile, cross-checks between the formats) go back up with
 * glTexSubImage2D into a small RGBA32F texture and as uniforms, and the pbuffer shows: the
 * RGBA8 attachment copied by glBlitFramebuffer (top left), the float readback re-uploaded and
 * tone-mapped (top right), and the statistics as swatches and soft-edged bars (bottom).
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
#define FW 160 /* the FBO: a quarter of the pbuffer */
#define FH 120
#define SLICES 24
#define STACKS 12
#define NV ((SLICES + 1) * (STACKS + 1))
#define NI (SLICES * STACKS * 6)
/* The sub-rectangle read through the pack buffer, into rows of PROW pixels. */
#define PX 17
#define PY 11
#define PW 101
#define PH 77
#define PROW 117

static const char* scene_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 position;\n"
    "layout(location = 1) in vec3 normal;\n"
    "uniform mat4 view_proj;\n"
    "uniform vec4 place; // xyz offset, w scale\n"
    "out vec3 world;\n"
    "out vec3 n;\n"
    "void main() {\n"
    "  world = position * place.w + place.xyz;\n"
    "  n = normal;\n"
    "  gl_Position = view_proj * vec4(world, 1.0);\n"
    "}\n";
static const char* scene_fs =
    "#version 330 core\n"
    "layout(location = 0) out vec4 ldr;\n"
    "layout(location = 1) out vec4 hdr;\n"
    "in vec3 world;\n"
    "in vec3 n;\n"
    "uniform vec3 albedo;\n"
    "uniform vec3 eye;\n"
    "void main() {\n"
    "  vec3 N = normalize(n), V = normalize(eye - world);\n"
    "  vec3 L1 = normalize(vec3(-0.5, 0.8, 0.45)), D = vec3(2.1, 1.7, 1.3) - world, L2 = normalize(D);\n"
    "  float d1 = max(dot(N, L1), 0.0), d2 = max(dot(N, L2), 0.0);\n"
    "  float s1 = pow(max(dot(N, normalize(L1 + V)), 0.0), 32.0);\n"
    "  vec3 lit = albedo * (0.18 + 0.9 * d1 + 1.6 * d2 * vec3(1.0, 0.8, 0.6) / (1.0 + 0.15 * dot(D, D))) + "
    "vec3(0.6) * s1;\n"
    "  ldr = vec4(clamp(lit, 0.0, 1.0), 1.0);\n"
    "  hdr = vec4(lit * 2.5, length(eye - world) * 0.1);\n"
    "}\n";
static const char* full_vs =
    "#version 330 core\n"
    "void main() {\n"
    "  vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID & 2) * 2 - 1));\n"
    "  gl_Position = vec4(p, 0.0, 1.0);\n"
    "}\n";
/* The float readback, re-uploaded, one texel per pixel, Reinhard tone-mapped. */
static const char* tone_fs =
    "#version 330 core\n"
    "uniform sampler2D image;\n"
    "uniform ivec2 origin;\n"
    "out vec4 color;\n"
    "void main() {\n"
    "  vec4 h = texelFetch(image, ivec2(gl_FragCoord.xy) - origin, 0);\n"
    "  vec3 c = h.rgb / (1.0 + h.rgb);\n"
    "  color = vec4(mix(c, vec3(0.2, 0.3, 0.5), clamp(h.a - 0.6, 0.0, 0.4)), 1.0);\n"
    "}\n";
/* The statistics panel, laid out on integer pixel coordinates. */
static const char* panel_fs =
    "#version 330 core\n"
    "uniform sampler2D stats; // 32x4: region means (RGBA8, 565, float), histogram + profile\n"
    "uniform vec3 checks;     // 1.0 where a cross-check between formats passed\n"
    "uniform vec3 pbo_mean;\n"
    "out vec4 color;\n"
    "float bar(float h, float y0) { return clamp((h + 0.37 - (gl_FragCoord.y - y0)) / 3.0 + 0.5, 0.0, 1.0); "
    "}\n"
    "void main() {\n"
    "  ivec2 p = ivec2(gl_FragCoord.xy);\n"
    "  vec3 c = vec3(0.08, 0.08, 0.11);\n"
    "  int q = max(p.x - 4, 0), cell = q / 26;\n"
    "  bool in_cell = p.x >= 4 && cell < 12 && q - cell * 26 < 24;\n"
    "  if (in_cell && p.y >= 102 && p.y < 116) c = texelFetch(stats, ivec2(cell, 0), 0).rgb;\n"
    "  else if (in_cell && p.y >= 86 && p.y < 100) c = texelFetch(stats, ivec2(cell, 1), 0).rgb;\n"
    "  else if (in_cell && p.y >= 70 && p.y < 84) {\n"
    "    vec3 h = texelFetch(stats, ivec2(cell, 2), 0).rgb;\n"
    "    c = h / (1.0 + h);\n"
    "  } else if (p.y >= 56 && p.y < 66 && p.x >= 4 && p.x < 112 && q % 36 < 30) {\n"
    "    float ok = checks[q / 36];\n"
    "    c = mix(vec3(0.9, 0.15, 0.1), vec3(0.2, 0.8, 0.3), ok);\n"
    "  } else if (p.y >= 56 && p.y < 66 && p.x >= 120 && p.x < 316) {\n"
    "    c = pbo_mean;\n"
    "  } else if (p.y >= 4 && p.y < 52 && p.x >= 4 && p.x < 164 && q % 10 < 8) {\n"
    "    float v = texelFetch(stats, ivec2(q / 10, 3), 0).r;\n"
    "    c = mix(c, vec3(0.95, 0.7, 0.2), bar(min(v * 160.0, 46.0), 4.0));\n"
    "  } else if (p.y >= 4 && p.y < 52 && p.x >= 168 && p.x < 312 && (p.x - 168) % 9 < 7) {\n"
    "    vec4 v = texelFetch(stats, ivec2(16 + (p.x - 168) / 9, 3), 0);\n"
    "    c = mix(c, v.rgb, bar(v.a * 44.0, 4.0));\n"
    "  }\n"
    "  color = vec4(c, 1.0);\n"
    "}\n";

static void die(const char* what) {
  fprintf(stderr, "egl_offscreen_readback_formats: %s failed (EGL 0x%04X, GL 0x%04X)\n", what, eglGetError(),
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

static GLuint texture(GLint internal, int w, int h, GLenum type) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, internal, w, h, 0, GL_RGBA, type, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}

/* view_proj = perspective(fovy 45, FW/FH, 0.5, 30) * lookAt(eye, target, +y). */
static void camera(float* m, const float* e, const float* t) {
  float f[3] = {t[0] - e[0], t[1] - e[1], t[2] - e[2]}, s[3], u[3], v[16], p[16], l;
  const float k = 1.0f / (float)tan(22.5 * 3.14159265358979 / 180.0), zn = 0.5f, zf = 30.0f;
  int i, r, c;
  l = (float)sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  for (i = 0; i < 3; ++i) f[i] /= l;
  s[0] = -f[2], s[1] = 0.0f, s[2] = f[0]; /* f x (0, 1, 0) */
  l = (float)sqrt(s[0] * s[0] + s[2] * s[2]);
  s[0] /= l, s[2] /= l;
  u[0] = s[1] * f[2] - s[2] * f[1], u[1] = s[2] * f[0] - s[0] * f[2], u[2] = s[0] * f[1] - s[1] * f[0];
  memset(v, 0, sizeof v);
  for (i = 0; i < 3; ++i) v[i * 4 + 0] = s[i], v[i * 4 + 1] = u[i], v[i * 4 + 2] = -f[i];
  v[12] = -(s[0] * e[0] + s[1] * e[1] + s[2] * e[2]);
  v[13] = -(u[0] * e[0] + u[1] * e[1] + u[2] * e[2]);
  v[14] = f[0] * e[0] + f[1] * e[1] + f[2] * e[2];
  v[15] = 1.0f;
  memset(p, 0, sizeof p);
  p[0] = k / ((float)FW / FH), p[5] = k;
  p[10] = (zf + zn) / (zn - zf), p[11] = -1.0f, p[14] = 2.0f * zf * zn / (zn - zf);
  for (c = 0; c < 4; ++c)
    for (r = 0; r < 4; ++r) {
      float a = 0.0f;
      for (i = 0; i < 4; ++i) a += p[i * 4 + r] * v[c * 4 + i];
      m[c * 4 + r] = a;
    }
}

int main(void) {
  static const EGLint cfg[] = {EGL_SURFACE_TYPE,
                               EGL_PBUFFER_BIT,
                               EGL_RED_SIZE,
                               8,
                               EGL_GREEN_SIZE,
                               8,
                               EGL_BLUE_SIZE,
                               8,
                               EGL_DEPTH_SIZE,
                               24,
                               EGL_RENDERABLE_TYPE,
                               EGL_OPENGL_BIT,
                               EGL_NONE};
  static const EGLint pb[] = {EGL_WIDTH, W, EGL_HEIGHT, H, EGL_NONE};
  static const EGLint ctx_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  static const float floor_v[] = {-6.1f, 0, 4.7f, 5.9f, 0, 4.7f, -6.1f, 0, -7.3f, 5.9f, 0, -7.3f};
  static const float balls[3][7] = {{-1.23f, 0.71f, -0.37f, 0.7f, 0.85f, 0.25f, 0.2f},
                                    {0.61f, 0.53f, 0.43f, 0.52f, 0.2f, 0.55f, 0.9f},
                                    {1.37f, 0.91f, -1.61f, 0.9f, 0.3f, 0.8f, 0.35f}};
  static const float eye[3] = {0.37f, 2.63f, 5.11f}, target[3] = {0.13f, 0.41f, -0.29f};
  static const float clear_ldr[4] = {0.1f, 0.12f, 0.2f, 1.0f}, clear_hdr[4] = {0.3f, 0.4f, 0.8f, 1.0f};
  static const float one = 1.0f;
  static float sphere[NV * 3];
  static unsigned short sidx[NI];
  static unsigned char rgba[FW * FH * 4], pbo_copy[PW * PH * 3];
  static unsigned int bgra[FW * FH];
  static unsigned short rgb565[FW * FH];
  static float hdr[FW * FH * 4], stats[4][32][4];
  const GLenum bufs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  float vp[16], checks[3] = {1, 1, 1}, pmean[3] = {0, 0, 0};
  double sum[3][12][4];
  long hist[16];
  EGLDisplay dpy;
  EGLConfig config;
  EGLint n;
  EGLSurface surf;
  EGLContext ctx;
  GLuint fbo, rbo, tex_ldr, tex_hdr, tex_up, tex_stats, pbo, vao[3], vbo[3], scene, tone, panel;
  const unsigned char* mapped;
  int i, j, k = 0, x, y;

  dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (!eglInitialize(dpy, NULL, NULL)) die("eglInitialize");
  if (!eglChooseConfig(dpy, cfg, &config, 1, &n) || n < 1) die("eglChooseConfig");
  surf = eglCreatePbufferSurface(dpy, config, pb);
  if (surf == EGL_NO_SURFACE) die("eglCreatePbufferSurface");
  eglBindAPI(EGL_OPENGL_API);
  ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctx_attribs);
  if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, surf, surf, ctx)) die("context");

  for (j = 0; j <= STACKS; ++j)
    for (i = 0; i <= SLICES; ++i) {
      const double th = 3.14159265358979 * j / STACKS, ph = 2.0 * 3.14159265358979 * i / SLICES;
      sphere[k++] = (float)(sin(th) * cos(ph));
      sphere[k++] = (float)cos(th);
      sphere[k++] = (float)(sin(th) * sin(ph));
    }
  k = 0;
  for (j = 0; j < STACKS; ++j)
    for (i = 0; i < SLICES; ++i) {
      const unsigned short a = (unsigned short)(j * (SLICES + 1) + i), b = (unsigned short)(a + SLICES + 1);
      sidx[k++] = a, sidx[k++] = (unsigned short)(a + 1), sidx[k++] = b;
      sidx[k++] = (unsigned short)(a + 1), sidx[k++] = (unsigned short)(b + 1), sidx[k++] = b;
    }
  scene = program(scene_vs, scene_fs);
  tone = program(full_vs, tone_fs);
  panel = program(full_vs, panel_fs);
  glGenVertexArrays(3, vao);
  glGenBuffers(3, vbo);
  /* vao 0: the spheres (positions are normals); vao 1: the floor, its normal a current value. */
  glBindVertexArray(vao[0]);
  glBindBuffer(GL_ARRAY_BUFFER, vbo[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof sphere, sphere, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, vbo[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof sidx, sidx, GL_STATIC_DRAW);
  glBindVertexArray(vao[1]);
  glBindBuffer(GL_ARRAY_BUFFER, vbo[2]);
  glBufferData(GL_ARRAY_BUFFER, sizeof floor_v, floor_v, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glEnableVertexAttribArray(0);

  /* The offscreen target: RGBA8 + RGBA16F + depth. */
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  tex_ldr = texture(GL_RGBA8, FW, FH, GL_UNSIGNED_BYTE);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex_ldr, 0);
  tex_hdr = texture(GL_RGBA16F, FW, FH, GL_FLOAT);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex_hdr, 0);
  glGenRenderbuffers(1, &rbo);
  glBindRenderbuffer(GL_RENDERBUFFER, rbo);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, FW, FH);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rbo);
  glDrawBuffers(2, bufs);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) die("FBO completeness");

  glViewport(0, 0, FW, FH);
  glClearBufferfv(GL_COLOR, 0, clear_ldr);
  glClearBufferfv(GL_COLOR, 1, clear_hdr);
  glClearBufferfv(GL_DEPTH, 0, &one);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glUseProgram(scene);
  camera(vp, eye, target);
  glUniformMatrix4fv(glGetUniformLocation(scene, "view_proj"), 1, GL_FALSE, vp);
  glUniform3fv(glGetUniformLocation(scene, "eye"), 1, eye);
  glBindVertexArray(vao[1]);
  glVertexAttrib3f(1, 0.0f, 1.0f, 0.0f);
  glUniform4f(glGetUniformLocation(scene, "place"), 0.0f, 0.0f, 0.0f, 1.0f);
  glUniform3f(glGetUniformLocation(scene, "albedo"), 0.55f, 0.5f, 0.45f);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glBindVertexArray(vao[0]);
  for (i = 0; i < 3; ++i) {
    glUniform4f(glGetUniformLocation(scene, "place"), balls[i][0], balls[i][1], balls[i][2], balls[i][3]);
    glUniform3fv(glGetUniformLocation(scene, "albedo"), 1, &balls[i][4]);
    glDrawElements(GL_TRIANGLES, NI, GL_UNSIGNED_SHORT, (void*)0);
  }
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  if (glGetError() != GL_NO_ERROR) die("scene");

  /* Readbacks of the FBO (bound as GL_READ_FRAMEBUFFER through GL_FRAMEBUFFER). */
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glReadPixels(0, 0, FW, FH, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, bgra);
  glReadPixels(0, 0, FW, FH, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, rgb565);
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glReadPixels(0, 0, FW, FH, GL_RGBA, GL_FLOAT, hdr);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glGenBuffers(1, &pbo);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, pbo);
  glBufferData(GL_PIXEL_PACK_BUFFER, ((PH - 1) * PROW + PW) * 3, NULL, GL_STREAM_READ);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, PROW);
  glReadPixels(PX, PY, PW, PH, GL_RGB, GL_UNSIGNED_BYTE, (void*)0);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  mapped = (const unsigned char*)glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, ((PH - 1) * PROW + PW) * 3,
                                                  GL_MAP_READ_BIT);
  if (!mapped) die("glMapBufferRange");
  for (y = 0; y < PH; ++y) memcpy(&pbo_copy[y * PW * 3], mapped + (size_t)y * PROW * 3, PW * 3);
  if (!glUnmapBuffer(GL_PIXEL_PACK_BUFFER)) die("glUnmapBuffer");
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  if (glGetError() != GL_NO_ERROR) die("readbacks");

  /* Statistics: per 40x40 region means of three readbacks, a luminance histogram of the
     BGRA one, a 16-bucket column profile of the pack-buffer one, and format cross-checks. */
  memset(sum, 0, sizeof sum);
  memset(hist, 0, sizeof hist);
  memset(stats, 0, sizeof stats);
  for (y = 0; y < FH; ++y)
    for (x = 0; x < FW; ++x) {
      const int p = y * FW + x, r = (y / 40) * 4 + x / 40;
      const unsigned int v = bgra[p], s = rgb565[p];
      const int br = (int)((v >> 16) & 255u), bg = (int)((v >> 8) & 255u), bb = (int)(v & 255u);
      const int r5 = (int)(s >> 11), g6 = (int)((s >> 5) & 63u), b5 = (int)(s & 31u);
      for (i = 0; i < 4; ++i) sum[0][r][i] += rgba[p * 4 + i] / 255.0;
      sum[1][r][0] += r5 / 31.0, sum[1][r][1] += g6 / 63.0, sum[1][r][2] += b5 / 31.0;
      for (i = 0; i < 4; ++i) sum[2][r][i] += hdr[p * 4 + i];
      hist[(br * 54 + bg * 183 + bb * 19) >> 12]++;
      if (br != rgba[p * 4] || bg != rgba[p * 4 + 1] || bb != rgba[p * 4 + 2] ||
          (int)(v >> 24) != rgba[p * 4 + 3])
        checks[0] = 0.0f;
      if (abs(r5 * 255 - rgba[p * 4] * 31) > 255 || abs(g6 * 255 - rgba[p * 4 + 1] * 63) > 255 ||
          abs(b5 * 255 - rgba[p * 4 + 2] * 31) > 255)
        checks[2] = 0.0f;
    }
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 12; ++j)
      for (k = 0; k < 4; ++k) stats[i][j][k] = (float)(sum[i][j][k] / 1600.0);
  for (j = 0; j < 16; ++j) stats[3][j][0] = (float)hist[j] / (FW * FH);
  for (x = 0; x < PW; ++x) {
    const int b = x * 16 / PW;
    for (y = 0; y < PH; ++y) {
      const unsigned char* c = &pbo_copy[(y * PW + x) * 3];
      const unsigned char* o = &rgba[((PY + y) * FW + PX + x) * 4];
      for (i = 0; i < 3; ++i) {
        stats[3][16 + b][i] += c[i] / 255.0f;
        pmean[i] += c[i] / 255.0f;
        if (c[i] != o[i]) checks[1] = 0.0f;
      }
      stats[3][16 + b][3] += (c[0] * 54 + c[1] * 183 + c[2] * 19) / 65280.0f;
    }
  }
  for (j = 0; j < 16; ++j) {
    const int cols = (j * PW + 15) / 16,
              cols_next = ((j + 1) * PW + 15) / 16; /* columns x with x*16/PW == j */
    for (i = 0; i < 4; ++i) stats[3][16 + j][i] /= (float)((cols_next - cols) * PH);
  }
  for (i = 0; i < 3; ++i) pmean[i] /= (float)(PW * PH);

  /* Upload: the float readback as an RGBA32F image, the statistics as a 32x4 texture. */
  tex_up = texture(GL_RGBA32F, FW, FH, GL_FLOAT);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, FW, FH, GL_RGBA, GL_FLOAT, hdr);
  tex_stats = texture(GL_RGBA32F, 32, 4, GL_FLOAT);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 32, 4, GL_RGBA, GL_FLOAT, stats);

  /* The final image in the pbuffer. */
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glViewport(0, 0, W, H);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBlitFramebuffer(0, 0, FW, FH, 0, FH, FW, 2 * FH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindVertexArray(vao[2]);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, tex_up);
  glUseProgram(tone);
  glUniform1i(glGetUniformLocation(tone, "image"), 0);
  glUniform2i(glGetUniformLocation(tone, "origin"), FW, FH);
  glViewport(FW, FH, FW, FH);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindTexture(GL_TEXTURE_2D, tex_stats);
  glUseProgram(panel);
  glUniform1i(glGetUniformLocation(panel, "stats"), 0);
  glUniform3fv(glGetUniformLocation(panel, "checks"), 1, checks);
  glUniform3fv(glGetUniformLocation(panel, "pbo_mean"), 1, pmean);
  glViewport(0, 0, W, FH);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  if (glGetError() != GL_NO_ERROR) die("drawing");
  fprintf(stderr, "checks: bgra %g, pbo %g, 565 %g\n", checks[0], checks[1], checks[2]);
  if (!eglSwapBuffers(dpy, surf)) die("eglSwapBuffers");
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglTerminate(dpy);
  return 0;
}
