/*
 * Helpers the GL 3.3 acceptance programs share whatever window system they use (GLUT, GLFW):
 * shaders compiled from strings with their info logs printed, a program linked from two, a GL
 * error check, a window-filling quad, a few matrices (column-major, as glUniformMatrix4fv
 * takes them with transpose GL_FALSE) and a UV sphere.
 *
 * It declares no GL itself: include a GL header first (GLEW's GL/glew.h, as common.h does, or
 * loader.h), then this one.
 */
#ifndef TESSEL_GL33_UTIL_H
#define TESSEL_GL33_UTIL_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static inline GLuint compile_shader(GLenum type, const char* src) {
  GLuint s = glCreateShader(type);
  GLint ok = 0;
  glShaderSource(s, 1, &src, NULL);
  glCompileShader(s);
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetShaderInfoLog(s, sizeof log, NULL, log);
    fprintf(stderr, "shader compile failed:\n%s\n", log);
    exit(1);
  }
  return s;
}

/* A program of a vertex shader, and a geometry and a fragment shader where not NULL, the n
 * outputs named in `feedback` captured by transform feedback in `mode` (n = 0: none). */
static inline GLuint link_shaders_feedback(const char* vs, const char* gs, const char* fs, int n,
                                           const char* const* feedback, GLenum mode) {
  GLuint p = glCreateProgram();
  GLuint v = compile_shader(GL_VERTEX_SHADER, vs);
  GLuint g = gs ? compile_shader(GL_GEOMETRY_SHADER, gs) : 0;
  GLuint f = fs ? compile_shader(GL_FRAGMENT_SHADER, fs) : 0;
  GLint ok = 0;
  glAttachShader(p, v);
  if (g) glAttachShader(p, g);
  if (f) glAttachShader(p, f);
  if (n > 0) glTransformFeedbackVaryings(p, n, feedback, mode);
  glLinkProgram(p);
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetProgramInfoLog(p, sizeof log, NULL, log);
    fprintf(stderr, "program link failed:\n%s\n", log);
    exit(1);
  }
  glDeleteShader(v);
  if (g) glDeleteShader(g);
  if (f) glDeleteShader(f);
  return p;
}

/* A program of a vertex, an optional geometry (NULL: none) and a fragment shader. */
static inline GLuint link_shaders(const char* vs, const char* gs, const char* fs) {
  return link_shaders_feedback(vs, gs, fs, 0, NULL, 0);
}

static inline GLuint link_program(const char* vs, const char* fs) { return link_shaders(vs, NULL, fs); }

/* A program of a vertex and a fragment shader, attribute `a` bound to location la and `b` to lb
 * before linking (glBindAttribLocation, as GLSL 1.10/1.20 code does it). */
static inline GLuint link_program_bound(const char* vs, const char* fs, const char* a, GLuint la,
                                        const char* b, GLuint lb) {
  GLuint p = glCreateProgram(), v = compile_shader(GL_VERTEX_SHADER, vs),
         f = compile_shader(GL_FRAGMENT_SHADER, fs);
  GLint ok = 0;
  glAttachShader(p, v);
  glAttachShader(p, f);
  glBindAttribLocation(p, la, a);
  glBindAttribLocation(p, lb, b);
  glLinkProgram(p);
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    fprintf(stderr, "program link failed\n");
    exit(1);
  }
  return p;
}

/* An RGB8 2D texture of w x h tightly packed texels, `filter` for both filters, no mipmaps;
 * GL_TEXTURE_2D is left unbound. */
static inline GLuint rgb_texture(int w, int h, const void* texels, GLint filter) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, w, h, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  glBindTexture(GL_TEXTURE_2D, 0);
  return t;
}

/* A vertex array of n vec2 positions at attribute 0, in a buffer of its own; left bound. */
static inline GLuint vertex_array2(const float* xy, int n) {
  GLuint vao, vbo;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(float) * 2 * (size_t)n), xy, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glEnableVertexAttribArray(0);
  return vao;
}

/* A vertex array of the window-filling quad at attribute 0 (vec2 positions -1..1), drawn
 * with glDrawArrays(GL_TRIANGLE_STRIP, 0, 4); left bound. */
static inline GLuint window_strip(void) {
  static const float quad[8] = {-1.0f, -1.0f, 1.0f, -1.0f, -1.0f, 1.0f, 1.0f, 1.0f};
  return vertex_array2(quad, 4);
}

static inline void check_gl(const char* where) {
  GLenum e = glGetError();
  if (e != GL_NO_ERROR) {
    fprintf(stderr, "GL error 0x%04X at %s\n", e, where);
    exit(1);
  }
}

/* 4x4 matrices, column-major: m[col * 4 + row]. */
static inline void mat_identity(float* m) {
  int i;
  for (i = 0; i < 16; ++i) m[i] = (i % 5 == 0) ? 1.0f : 0.0f;
}

static inline void mat_mul(float* out, const float* a, const float* b) {
  float r[16];
  int c, k, i;
  for (c = 0; c < 4; ++c)
    for (i = 0; i < 4; ++i) {
      float s = 0.0f;
      for (k = 0; k < 4; ++k) s += a[k * 4 + i] * b[c * 4 + k];
      r[c * 4 + i] = s;
    }
  memcpy(out, r, sizeof r);
}

static inline void mat_perspective(float* m, float fovy_deg, float aspect, float n, float f) {
  const float t = 1.0f / (float)tan(fovy_deg * 3.14159265358979 / 360.0);
  memset(m, 0, 16 * sizeof(float));
  m[0] = t / aspect;
  m[5] = t;
  m[10] = (f + n) / (n - f);
  m[11] = -1.0f;
  m[14] = 2.0f * f * n / (n - f);
}

static inline void mat_translate(float* m, float x, float y, float z) {
  mat_identity(m);
  m[12] = x;
  m[13] = y;
  m[14] = z;
}

static inline void mat_rotate_y(float* m, float deg) {
  const float a = (float)(deg * 3.14159265358979 / 180.0), c = (float)cos(a), s = (float)sin(a);
  mat_identity(m);
  m[0] = c;
  m[2] = -s;
  m[8] = s;
  m[10] = c;
}

static inline void mat_rotate_x(float* m, float deg) {
  const float a = (float)(deg * 3.14159265358979 / 180.0), c = (float)cos(a), s = (float)sin(a);
  mat_identity(m);
  m[5] = c;
  m[6] = s;
  m[9] = -s;
  m[10] = c;
}

static inline void mat_transpose(float* out, const float* m) {
  float r[16];
  int i, j;
  for (i = 0; i < 4; ++i)
    for (j = 0; j < 4; ++j) r[i * 4 + j] = m[j * 4 + i];
  memcpy(out, r, sizeof r);
}

/* gluLookAt's matrix: the eye at e looking at c, up u. */
static inline void mat_lookat(float* m, float ex, float ey, float ez, float cx, float cy, float cz, float ux,
                              float uy, float uz) {
  float f[3] = {cx - ex, cy - ey, cz - ez}, s[3], u[3], l;
  int i;
  l = (float)sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  for (i = 0; i < 3; ++i) f[i] /= l;
  s[0] = f[1] * uz - f[2] * uy;
  s[1] = f[2] * ux - f[0] * uz;
  s[2] = f[0] * uy - f[1] * ux;
  l = (float)sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  for (i = 0; i < 3; ++i) s[i] /= l;
  u[0] = s[1] * f[2] - s[2] * f[1];
  u[1] = s[2] * f[0] - s[0] * f[2];
  u[2] = s[0] * f[1] - s[1] * f[0];
  mat_identity(m);
  for (i = 0; i < 3; ++i) {
    m[i * 4 + 0] = s[i];
    m[i * 4 + 1] = u[i];
    m[i * 4 + 2] = -f[i];
  }
  m[12] = -(s[0] * ex + s[1] * ey + s[2] * ez);
  m[13] = -(u[0] * ex + u[1] * ey + u[2] * ez);
  m[14] = f[0] * ex + f[1] * ey + f[2] * ez;
}

/* glOrtho's matrix. */
static inline void mat_ortho(float* m, float l, float r, float b, float t, float n, float f) {
  mat_identity(m);
  m[0] = 2.0f / (r - l);
  m[5] = 2.0f / (t - b);
  m[10] = -2.0f / (f - n);
  m[12] = -(r + l) / (r - l);
  m[13] = -(t + b) / (t - b);
  m[14] = -(f + n) / (f - n);
}

/* The scale matrix diag(x, y, z, 1). */
static inline void mat_scale(float* m, float x, float y, float z) {
  mat_identity(m);
  m[0] = x;
  m[5] = y;
  m[10] = z;
}

/* glRotatef's matrix: deg degrees about the axis (x, y, z), which need not be unit length. */
static inline void mat_rotate(float* m, float deg, float x, float y, float z) {
  const float a = deg * 3.14159265f / 180.0f, c = cosf(a), s = sinf(a), l = sqrtf(x * x + y * y + z * z);
  x /= l;
  y /= l;
  z /= l;
  mat_identity(m);
  m[0] = c + x * x * (1 - c);
  m[1] = y * x * (1 - c) + z * s;
  m[2] = z * x * (1 - c) - y * s;
  m[4] = x * y * (1 - c) - z * s;
  m[5] = c + y * y * (1 - c);
  m[6] = z * y * (1 - c) + x * s;
  m[8] = x * z * (1 - c) + y * s;
  m[9] = y * z * (1 - c) - x * s;
  m[10] = c + z * z * (1 - c);
}

/*
 * glm's in-place transforms (m = m * T), as glm::translate/rotate/scale(m, ...) and the fixed
 * function glTranslatef/glRotatef/glScalef apply them: the last one applied acts first.
 */
static inline void mat_mul_translate(float* m, float x, float y, float z) {
  float t[16];
  mat_translate(t, x, y, z);
  mat_mul(m, m, t);
}

static inline void mat_mul_rotate(float* m, float deg, float x, float y, float z) {
  float t[16];
  mat_rotate(t, deg, x, y, z);
  mat_mul(m, m, t);
}

static inline void mat_mul_scale(float* m, float x, float y, float z) {
  float t[16];
  mat_scale(t, x, y, z);
  mat_mul(m, m, t);
}

/* A UV sphere of radius 1: positions (= normals) and indices of triangles. */
#define SPHERE_SLICES 32
#define SPHERE_STACKS 16
#define SPHERE_VERTS ((SPHERE_SLICES + 1) * (SPHERE_STACKS + 1))
#define SPHERE_INDICES (SPHERE_SLICES * SPHERE_STACKS * 6)
static inline void make_sphere(float* pos, unsigned short* idx) {
  int i, j, k = 0;
  for (j = 0; j <= SPHERE_STACKS; ++j)
    for (i = 0; i <= SPHERE_SLICES; ++i) {
      const double th = 3.14159265358979 * j / SPHERE_STACKS, ph = 2.0 * 3.14159265358979 * i / SPHERE_SLICES;
      pos[k++] = (float)(sin(th) * cos(ph));
      pos[k++] = (float)cos(th);
      pos[k++] = (float)(sin(th) * sin(ph));
    }
  k = 0;
  for (j = 0; j < SPHERE_STACKS; ++j)
    for (i = 0; i < SPHERE_SLICES; ++i) {
      const unsigned short a = (unsigned short)(j * (SPHERE_SLICES + 1) + i),
                           b = (unsigned short)(a + SPHERE_SLICES + 1);
      idx[k++] = a;
      idx[k++] = (unsigned short)(a + 1);
      idx[k++] = b;
      idx[k++] = (unsigned short)(a + 1);
      idx[k++] = (unsigned short)(b + 1);
      idx[k++] = b;
    }
}

/* LearnOpenGL's renderQuad() (normal and parallax mapping): two triangles of a 2x2 quad in z = 0 facing +z,
 * each with the tangent and bitangent solved from its edges and UV deltas. `uv` gives the four corners' UVs
 * (top-left, bottom-left, bottom-right, top-right). */
static inline void mat_tangent_quad(float* out, const float uv[4][2]) {
  static const float pos[4][3] = {
      {-1.0f, 1.0f, 0.0f}, {-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, {1.0f, 1.0f, 0.0f}};
  static const int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
  int t, k, i;
  for (t = 0; t < 2; ++t) {
    const float* p1 = pos[tri[t][0]];
    const float* p2 = pos[tri[t][1]];
    const float* p3 = pos[tri[t][2]];
    const float* uv1 = uv[tri[t][0]];
    const float* uv2 = uv[tri[t][1]];
    const float* uv3 = uv[tri[t][2]];
    float edge1[3], edge2[3], tangent[3], bitangent[3];
    const float du1 = uv2[0] - uv1[0], dv1 = uv2[1] - uv1[1], du2 = uv3[0] - uv1[0], dv2 = uv3[1] - uv1[1];
    const float f = 1.0f / (du1 * dv2 - du2 * dv1);
    for (i = 0; i < 3; ++i) {
      edge1[i] = p2[i] - p1[i];
      edge2[i] = p3[i] - p1[i];
    }
    for (i = 0; i < 3; ++i) {
      tangent[i] = f * (dv2 * edge1[i] - dv1 * edge2[i]);
      bitangent[i] = f * (-du2 * edge1[i] + du1 * edge2[i]);
    }
    for (k = 0; k < 3; ++k) {
      float* o = out + (t * 3 + k) * 14;
      const int v = tri[t][k];
      o[0] = pos[v][0], o[1] = pos[v][1], o[2] = pos[v][2];
      o[3] = 0.0f, o[4] = 0.0f, o[5] = 1.0f;
      o[6] = uv[v][0], o[7] = uv[v][1];
      for (i = 0; i < 3; ++i) o[8 + i] = tangent[i], o[11 + i] = bitangent[i];
    }
  }
}

#endif
