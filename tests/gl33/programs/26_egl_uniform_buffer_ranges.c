/*
 * Uniform buffer ranges, headless through EGL (a pbuffer, 3.3 core): three std140 uniform
 * blocks - a Camera block (mat4, vec3 + float packed into one vec4 slot), a Palette block
 * with an array of structs { vec3 color; float width; } and an array of vec4, and an Object
 * block with mat4 and mat3 members, vec3 + float packing, an array of vec4, a struct array,
 * a vec2 after a float and an ivec2. All of them live in ONE big uniform buffer: the camera at
 * offset 0, two palettes and six copies of the per-object data after it, each at an offset
 * rounded up to GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT (queried with glGetIntegerv), bound per
 * draw with glBindBufferRange. The blocks go to non-zero binding points with
 * glUniformBlockBinding; a second program (the background) uses the Camera and Palette
 * blocks at other block indices. The std140 offsets are checked with glGetActiveUniformsiv.
 * Six tiles that differ only by block content: rotation/scale, stripes, rings, a colour
 * matrix, gloss.
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
#define NOBJ 6

static const char* blocks =
    "#version 330 core\n"
    "struct Band { vec3 color; float width; };\n"
    "layout(std140) uniform Camera {\n"
    "  mat4 view_proj;\n"
    "  vec3 light_dir;\n"
    "  float ambient;\n"
    "} cam;\n"
    "layout(std140) uniform Palette {\n"
    "  Band rings[3];\n"
    "  vec4 sky[2];\n"
    "};\n";
static const char* obj_block =
    "layout(std140) uniform Object {\n"
    "  mat4 model;\n"
    "  mat3 color_xform;\n"
    "  vec3 base_color;\n"
    "  float gloss;\n"
    "  vec4 stripes[3];\n"
    "  Band edge[2];\n"
    "  float stripe_freq;\n"
    "  vec2 center;\n"
    "  ivec2 pattern;\n"
    "};\n";
static const char* obj_vs =
    "layout(location = 0) in vec2 corner;\n"
    "out vec2 uv;\n"
    "void main() { uv = corner; gl_Position = cam.view_proj * (model * vec4(corner, 0.0, 1.0)); }\n";
static const char* obj_fs =
    "in vec2 uv;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  vec2 p = uv - center;\n"
    "  float r = length(p);\n"
    "  int k = int(floor((uv.x + uv.y * 0.37) * stripe_freq + 8.0)) % 3;\n"
    "  vec3 c = mix(base_color, stripes[k].rgb, stripes[k].a);\n"
    "  if (pattern.x == 1) {\n"
    "    if (r < rings[0].width) c = rings[0].color;\n"
    "    else if (r < rings[1].width) c = mix(c, rings[1].color, 0.5);\n"
    "    else if (r < rings[2].width) c = c * rings[2].color;\n"
    "  }\n"
    "  float e = max(abs(uv.x), abs(uv.y));\n"
    "  if (e > 1.0 - edge[0].width) c = edge[0].color;\n"
    "  else if (e > 1.0 - edge[0].width - edge[1].width) c = mix(c, edge[1].color, 0.6);\n"
    "  vec3 n = normalize(vec3(uv * 0.7, 1.0));\n"
    "  float d = max(dot(n, cam.light_dir), 0.0);\n"
    "  float s = pattern.y > 0 ? pow(max(dot(reflect(-cam.light_dir, n), vec3(0, 0, 1)), 0.0), gloss) : "
    "0.0;\n"
    "  frag = vec4(color_xform * (c * (cam.ambient + (1.0 - cam.ambient) * d)) + vec3(0.4 * s), 1.0);\n"
    "}\n";
static const char* bg_vs =
    "const vec2 corner[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(-1, 1), vec2(1, 1));\n"
    "out vec2 p;\n"
    "void main() { p = corner[gl_VertexID]; gl_Position = vec4(corner[gl_VertexID], 0.0, 1.0); }\n";
static const char* bg_fs =
    "in vec2 p;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  vec3 c = mix(sky[0].rgb, sky[1].rgb, p.y * 0.5 + 0.5);\n"
    "  float band = step(0.5, fract(p.x * 3.1 + 0.27));\n"
    "  frag = vec4(mix(c, rings[1].color * cam.ambient, 0.15 * band), 1.0);\n"
    "}\n";

static void die(const char* what) {
  fprintf(stderr, "egl_uniform_buffer_ranges: %s failed (EGL 0x%04X, GL 0x%04X)\n", what, eglGetError(),
          glGetError());
  exit(1);
}

static GLuint program(const char* v0, const char* v1, const char* v2, const char* f1, const char* f2) {
  GLuint p = glCreateProgram();
  const char* src[2][3] = {{v0, v1, v2}, {v0, f1, f2}};
  GLenum type[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
  GLint ok = 0;
  int i;
  for (i = 0; i < 2; ++i) {
    GLuint s = glCreateShader(type[i]);
    glShaderSource(s, 3, src[i], NULL);
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

/* The std140 layout the blocks must have, checked against what the GL reports. */
static void check_offsets(GLuint prog, const char* block, GLint size, int n, const char** names,
                          const GLint* offsets) {
  GLuint idx[8];
  GLint got[8], data_size = 0;
  int i;
  glGetActiveUniformBlockiv(prog, glGetUniformBlockIndex(prog, block), GL_UNIFORM_BLOCK_DATA_SIZE,
                            &data_size);
  if (data_size != size) {
    fprintf(stderr, "block %s is %d bytes, not %d\n", block, data_size, size);
    exit(1);
  }
  glGetUniformIndices(prog, n, names, idx);
  for (i = 0; i < n; ++i)
    if (idx[i] == GL_INVALID_INDEX) {
      fprintf(stderr, "no uniform %s\n", names[i]);
      exit(1);
    }
  glGetActiveUniformsiv(prog, n, idx, GL_UNIFORM_OFFSET, got);
  for (i = 0; i < n; ++i)
    if (got[i] != offsets[i]) {
      fprintf(stderr, "%s at offset %d, not %d\n", names[i], got[i], offsets[i]);
      exit(1);
    }
}

static void put(unsigned char* base, int offset, const float* v, int n) { memcpy(base + offset, v, n * 4); }

static void rgb(float* out, float r, float g, float b, float w) {
  out[0] = r;
  out[1] = g;
  out[2] = b;
  out[3] = w;
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
  static const char* obj_names[] = {"model",   "color_xform",   "base_color", "gloss",
                                    "stripes", "edge[1].width", "center",     "pattern"};
  static const GLint obj_offsets[] = {0, 64, 112, 124, 128, 204, 216, 224};
  static const char* pal_names[] = {"rings[0].color", "rings[1].width", "rings[2].color", "sky"};
  static const GLint pal_offsets[] = {0, 28, 32, 48};
  static const char* cam_names[] = {"Camera.view_proj", "Camera.light_dir", "Camera.ambient"};
  static const GLint cam_offsets[] = {0, 64, 76};
  static const float corners[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
  EGLDisplay dpy;
  EGLConfig config;
  EGLint n;
  EGLSurface surf;
  EGLContext ctx;
  GLuint prog, bg, vao, vbo, ubo;
  GLint align = 0, cam_stride, pal_stride, obj_stride, total;
  unsigned char* data;
  float v[16];
  int i;

  dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (!eglInitialize(dpy, NULL, NULL)) die("eglInitialize");
  if (!eglChooseConfig(dpy, cfg, &config, 1, &n) || n < 1) die("eglChooseConfig");
  surf = eglCreatePbufferSurface(dpy, config, pb);
  if (surf == EGL_NO_SURFACE) die("eglCreatePbufferSurface");
  eglBindAPI(EGL_OPENGL_API);
  ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctx_attribs);
  if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, surf, surf, ctx)) die("context");

  prog = program(blocks, obj_block, obj_vs, obj_block, obj_fs);
  bg = program(blocks, "", bg_vs, "", bg_fs);
  check_offsets(prog, "Object", 240, 8, obj_names, obj_offsets);
  check_offsets(prog, "Palette", 80, 4, pal_names, pal_offsets);
  check_offsets(prog, "Camera", 80, 3, cam_names, cam_offsets);
  check_offsets(bg, "Palette", 80, 4, pal_names, pal_offsets);
  /* Non-zero binding points: the camera at 1, palettes at 4, objects at 7. */
  glUniformBlockBinding(prog, glGetUniformBlockIndex(prog, "Camera"), 1);
  glUniformBlockBinding(prog, glGetUniformBlockIndex(prog, "Palette"), 4);
  glUniformBlockBinding(prog, glGetUniformBlockIndex(prog, "Object"), 7);
  glUniformBlockBinding(bg, glGetUniformBlockIndex(bg, "Camera"), 1);
  glUniformBlockBinding(bg, glGetUniformBlockIndex(bg, "Palette"), 4);

  glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &align);
  if (align < 1) die("GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT");
  cam_stride = (80 + align - 1) / align * align;
  pal_stride = (80 + align - 1) / align * align;
  obj_stride = (240 + align - 1) / align * align;
  total = cam_stride + 2 * pal_stride + NOBJ * obj_stride;
  data = calloc((size_t)total, 1);
  if (!data) die("calloc");

  /* Camera: an orthographic view of [-1.6, 1.6] x [-1.2, 1.2], slightly off-centre. */
  memset(v, 0, sizeof v);
  v[0] = 1.0f / 1.6f;
  v[5] = 1.0f / 1.2f;
  v[10] = -1.0f;
  v[12] = 0.013f;
  v[13] = -0.011f;
  v[15] = 1.0f;
  put(data, 0, v, 16);
  {
    const float l[4] = {-0.36f, 0.48f, 0.8f, 0.3f}; /* unit light direction, then ambient */
    put(data, 64, l, 4);
  }
  /* Two palettes: three rings (colour, radius) and two sky colours each. */
  for (i = 0; i < 2; ++i) {
    unsigned char* p = data + cam_stride + i * pal_stride;
    float c[4];
    rgb(c, i ? 0.1f : 1.0f, 0.9f, i ? 1.0f : 0.2f, 0.18f);
    put(p, 0, c, 4);
    rgb(c, i ? 0.9f : 0.2f, 0.2f, i ? 0.3f : 0.9f, 0.37f);
    put(p, 16, c, 4);
    rgb(c, 0.5f, i ? 1.0f : 0.6f, 0.5f, 0.52f);
    put(p, 32, c, 4);
    rgb(c, 0.08f, 0.07f + 0.1f * i, 0.15f, 1.0f);
    put(p, 48, c, 4);
    rgb(c, 0.35f, 0.4f, 0.6f - 0.3f * i, 1.0f);
    put(p, 64, c, 4);
  }
  /* Six objects, each a different copy of the Object block. */
  for (i = 0; i < NOBJ; ++i) {
    unsigned char* p = data + cam_stride + 2 * pal_stride + i * obj_stride;
    const float a = 0.21f * (float)i + 0.1f, s = 0.42f + 0.04f * (float)(i % 3);
    const float ca = (float)cos(a), sa = (float)sin(a);
    const int ip[2] = {i % 2 == 0 ? 1 : 0, i % 3 != 1 ? 1 : 0};
    float c[12];
    memset(v, 0, sizeof v);
    v[0] = s * ca;
    v[1] = s * sa;
    v[4] = -s * sa;
    v[5] = s * ca;
    v[10] = 1.0f;
    v[12] = -1.05f + 1.04f * (float)(i % 3);
    v[13] = 0.58f - 1.13f * (float)(i / 3);
    v[15] = 1.0f;
    put(p, 0, v, 16);
    memset(c, 0, sizeof c); /* mat3: three columns, each padded to a vec4 */
    switch (i % 4) {
      case 0: c[0] = c[5] = c[10] = 1.0f; break; /* identity */
      case 1: c[1] = c[6] = c[8] = 1.0f; break;  /* rgb -> gbr */
      case 2: c[0] = c[1] = c[2] = 0.33f, c[4] = c[5] = c[6] = 0.5f, c[8] = c[9] = c[10] = 0.17f; break;
      default:
        c[0] = 0.9f, c[1] = 0.7f, c[2] = 0.5f, c[4] = 0.4f, c[5] = 0.35f, c[6] = 0.25f, c[10] = 0.3f;
        break;
    }
    put(p, 64, c, 12);
    rgb(c, 0.2f + 0.12f * (float)i, 0.8f - 0.1f * (float)i, 0.5f, 4.0f + 12.0f * (float)i);
    put(p, 112, c, 4);
    rgb(c, 1.0f, 0.3f, 0.2f, 0.2f + 0.1f * (float)i);
    put(p, 128, c, 4);
    rgb(c, 0.2f, 0.3f + 0.1f * (float)(i % 3), 1.0f, 0.8f);
    put(p, 144, c, 4);
    rgb(c, 0.95f, 0.95f, 0.3f, 0.5f * (float)(i % 2));
    put(p, 160, c, 4);
    rgb(c, 0.05f * (float)i, 0.05f, 0.1f, 0.07f + 0.015f * (float)i);
    put(p, 176, c, 4);
    rgb(c, 1.0f, 1.0f, 1.0f, 0.06f);
    put(p, 192, c, 4);
    c[0] = 1.3f + 0.9f * (float)i; /* stripe_freq at 208, then center at 216 */
    c[1] = 0.0f;
    c[2] = 0.13f * (float)(i % 3) - 0.11f;
    c[3] = 0.09f - 0.07f * (float)(i % 2);
    put(p, 208, c, 4);
    memcpy(p + 224, ip, sizeof ip);
  }
  glGenBuffers(1, &ubo);
  glBindBuffer(GL_UNIFORM_BUFFER, ubo);
  glBufferData(GL_UNIFORM_BUFFER, total, data, GL_STATIC_DRAW);
  free(data);
  glBindBufferRange(GL_UNIFORM_BUFFER, 1, ubo, 0, 80);

  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, 0);
  glEnableVertexAttribArray(0);
  if (glGetError() != GL_NO_ERROR) die("setup");

  glViewport(0, 0, W, H);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  /* The background with the second palette. */
  glUseProgram(bg);
  glBindBufferRange(GL_UNIFORM_BUFFER, 4, ubo, cam_stride + pal_stride, 80);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glUseProgram(prog);
  for (i = 0; i < NOBJ; ++i) {
    glBindBufferRange(GL_UNIFORM_BUFFER, 4, ubo, cam_stride + (i / 3) * pal_stride, 80);
    glBindBufferRange(GL_UNIFORM_BUFFER, 7, ubo, cam_stride + 2 * pal_stride + i * obj_stride, 240);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  if (glGetError() != GL_NO_ERROR) die("drawing");
  if (!eglSwapBuffers(dpy, surf)) die("eglSwapBuffers");
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(dpy, ctx);
  eglDestroySurface(dpy, surf);
  eglTerminate(dpy);
  return 0;
}
