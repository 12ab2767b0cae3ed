/*
 * GLSL 1.10 as the shader textbooks of the GL 2.0 years write it (the Orange Book, Lighthouse3D
 * tutorials): a compatibility context, `#version 110` shaders and one with no #version line at
 * all, `attribute`/`varying`/`gl_FragColor`/`texture2D`/`uniform sampler2D`, attribute
 * locations fixed with glBindAttribLocation before glLinkProgram, and the fixed-function
 * matrices (gluPerspective + gluLookAt + glTranslate/glRotate/glScale, then glOrtho for an
 * overlay) read in the shaders through gl_ModelViewProjectionMatrix, gl_ModelViewMatrix and
 * gl_NormalMatrix (a non-uniform scale makes the normal matrix matter). A toon (cel) shader
 * does a 1D lookup through a 2D ramp texture of height 1 (GL_NEAREST) and hatches its darkest
 * band with gl_FragCoord stripes. A torus comes from client arrays (glVertexAttribPointer with
 * a client pointer, no buffer bound, client-side indices) and a sphere from a VBO and an
 * element buffer. Uniform arrays are set with glUniform2fv/3fv/4fv/Matrix2fv/Matrix3fv with
 * count > 1 (one of them transposed, one updated from element 1 by its "name[1]" location).
 */
#include "common.h"

#include <GL/glu.h>

#define TU 40
#define TV 20
#define TORUS_VERTS ((TU + 1) * (TV + 1))
#define TORUS_INDICES (TU * TV * 6)

static const char* toon_vs =
    "#version 110\n"
    "attribute vec4 position;\n"
    "attribute vec3 normal;\n"
    "varying vec3 N;\n"
    "varying vec3 V;\n"
    "void main() {\n"
    "  N = gl_NormalMatrix * normal;\n"
    "  V = vec3(gl_ModelViewMatrix * position);\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * position;\n"
    "}\n";

/* No #version line: GLSL 1.10 by default. */
static const char* toon_fs =
    "uniform sampler2D ramp;\n"
    "uniform vec3 lightDir[2];\n"
    "uniform vec4 tint[4];\n"
    "uniform mat3 grade[2];\n"
    "uniform vec2 stripe[2];\n"
    "uniform float which;\n"
    "varying vec3 N;\n"
    "varying vec3 V;\n"
    "void main() {\n"
    "  vec3 n = normalize(N);\n"
    "  float d = 0.8 * max(dot(n, lightDir[0]), 0.0) + 0.3 * max(dot(n, lightDir[1]), 0.0);\n"
    "  vec3 band = texture2D(ramp, vec2(d * 0.93 + 0.02, 0.5)).rgb;\n"
    "  vec4 base = mix(tint[0], tint[1], which);\n"
    "  vec3 c = base.rgb * band;\n"
    "  float h = floor((gl_FragCoord.x + gl_FragCoord.y + 0.25) / stripe[0].x);\n"
    "  if (band.g < 0.4) c *= 1.0 - stripe[0].y * step(0.5, mod(h, 2.0));\n"
    "  float rim = 1.0 - max(dot(n, normalize(-V)), 0.0);\n"
    "  c += tint[2].rgb * tint[2].a * smoothstep(0.55, 0.95, rim);\n"
    "  gl_FragColor = vec4(grade[0] * c + tint[3].rgb * base.a, 1.0);\n"
    "}\n";

static const char* hud_vs =
    "#version 110\n"
    "attribute vec2 corner;\n"
    "attribute vec2 uv;\n"
    "varying vec2 st;\n"
    "void main() {\n"
    "  st = uv;\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * vec4(corner, 0.0, 1.0);\n"
    "}\n";

static const char* hud_fs =
    "#version 110\n"
    "uniform sampler2D ramp;\n"
    "uniform mat2 shear[2];\n"
    "uniform vec2 stripe[2];\n"
    "uniform mat3 grade[2];\n"
    "uniform vec4 tint[4];\n"
    "uniform float panel;\n"
    "varying vec2 st;\n"
    "void main() {\n"
    "  // Shears with entries that are small powers of two keep the stripe values exact.\n"
    "  vec2 q = (panel < 0.5 ? shear[0] : shear[1]) * gl_FragCoord.xy + vec2(0.0625);\n"
    "  vec2 k = mod(floor(q / stripe[1]), 2.0);\n"
    "  vec3 c;\n"
    "  if (panel < 0.5) {\n"
    "    c = texture2D(ramp, vec2(st.x, 0.5)).rgb * mix(tint[0].rgb, tint[1].rgb, st.y);\n"
    "    c *= 0.75 + 0.25 * k.x;\n"
    "  } else {\n"
    "    c = grade[1] * vec3(st, 1.0 - st.x) * (0.6 + 0.2 * k.x + 0.2 * k.y);\n"
    "  }\n"
    "  gl_FragColor = vec4(c, 1.0);\n"
    "}\n";

static GLuint toon, hud, sphere_vbo, sphere_ibo, ramp_tex;
static float torus[TORUS_VERTS][6];
static unsigned short torus_idx[TORUS_INDICES];

/* glBindAttribLocation between attaching and linking, as the Orange Book does it. */
static GLuint build(const char* vs, const char* fs, const char* a0, const char* a3) {
  GLuint p = glCreateProgram(), v = compile_shader(GL_VERTEX_SHADER, vs),
         f = compile_shader(GL_FRAGMENT_SHADER, fs);
  GLint ok = 0;
  glAttachShader(p, v);
  glAttachShader(p, f);
  glBindAttribLocation(p, 0, a0);
  glBindAttribLocation(p, 3, a3);
  glLinkProgram(p);
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetProgramInfoLog(p, sizeof log, NULL, log);
    fprintf(stderr, "program link failed:\n%s\n", log);
    exit(1);
  }
  if (glGetAttribLocation(p, a0) != 0 || glGetAttribLocation(p, a3) != 3) {
    fprintf(stderr, "glBindAttribLocation was not honoured\n");
    exit(1);
  }
  return p;
}

static void set_arrays(GLuint p) {
  /* lightDir[2] (eye space, unit length), tint[4], grade[2], stripe[2], shear[2]. */
  static const float light[2][3] = {{-0.48f, 0.64f, 0.6f}, {0.8f, -0.36f, 0.48f}};
  static const float tint[4][4] = {{0.95f, 0.45f, 0.2f, 0.0f},
                                   {0.25f, 0.55f, 0.95f, 1.0f},
                                   {0.0f, 0.0f, 0.0f, 0.0f},
                                   {0.0f, 0.0f, 0.0f, 0.0f}};
  static const float tint_tail[3][4] = {
      {0.3f, 0.6f, 1.0f, 1.0f}, {1.0f, 0.9f, 0.6f, 0.7f}, {0.05f, 0.0f, 0.08f, 1.0f}};
  /* grade[0] as columns; grade[1] given row-major with transpose = GL_TRUE below. */
  static const float grade0[2][9] = {{0.9f, 0.05f, 0.05f, 0.1f, 0.85f, 0.05f, 0.0f, 0.1f, 0.9f},
                                     {1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f}};
  static const float grade1_rows[2][9] = {{1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f},
                                          {0.7f, 0.3f, 0.0f, 0.1f, 0.5f, 0.4f, 0.2f, 0.0f, 0.8f}};
  static const float stripe[2][2] = {{6.0f, 0.45f}, {8.0f, 4.0f}};
  static const float shear[2][4] = {{1.0f, 0.5f, -0.25f, 1.0f}, {0.5f, -1.0f, 1.0f, 0.75f}};
  GLint loc;
  glUseProgram(p);
  if ((loc = glGetUniformLocation(p, "lightDir")) >= 0) glUniform3fv(loc, 2, &light[0][0]);
  if ((loc = glGetUniformLocation(p, "tint")) >= 0) glUniform4fv(loc, 4, &tint[0][0]);
  /* Elements 1..3 again, from the location of "tint[1]". */
  if ((loc = glGetUniformLocation(p, "tint[1]")) >= 0) glUniform4fv(loc, 3, &tint_tail[0][0]);
  if ((loc = glGetUniformLocation(p, "grade")) >= 0) {
    if (p == hud)
      glUniformMatrix3fv(loc, 2, GL_TRUE, &grade1_rows[0][0]);
    else
      glUniformMatrix3fv(loc, 2, GL_FALSE, &grade0[0][0]);
  }
  if ((loc = glGetUniformLocation(p, "stripe")) >= 0) glUniform2fv(loc, 2, &stripe[0][0]);
  if ((loc = glGetUniformLocation(p, "shear")) >= 0) glUniformMatrix2fv(loc, 2, GL_FALSE, &shear[0][0]);
  glUniform1i(glGetUniformLocation(p, "ramp"), 0);
  check_gl("uniform arrays");
}

static void display(void) {
  /* Two quads for the overlay, in window pixels (glOrtho), corners off the pixel grid. */
  static const float hud_corner[8][2] = {{12.3f, 10.3f},  {152.3f, 10.3f}, {152.3f, 38.7f}, {12.3f, 38.7f},
                                         {167.7f, 10.3f}, {307.7f, 10.3f}, {307.7f, 38.7f}, {167.7f, 38.7f}};
  static const float hud_uv[8][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {1, 1}, {0, 1}};
  static const unsigned char quad_idx[12] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
  glClearColor(0.93f, 0.91f, 0.84f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(38.0, 320.0 / 240.0, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.13, 1.37, 6.31, 0.07, -0.33, 0.0, 0.0, 1.0, 0.0);
  glEnable(GL_DEPTH_TEST);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, ramp_tex);
  glUseProgram(toon);

  /* The torus: client memory, no buffer object bound. */
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), &torus[0][0]);
  glVertexAttribPointer(3, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), &torus[0][3]);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(3);
  glUniform1f(glGetUniformLocation(toon, "which"), 0.0f);
  glPushMatrix();
  glTranslatef(-1.17f, 0.23f, 0.11f);
  glRotatef(58.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(-21.0f, 0.0f, 1.0f, 0.0f);
  glDrawElements(GL_TRIANGLES, TORUS_INDICES, GL_UNSIGNED_SHORT, torus_idx);
  glPopMatrix();

  /* The sphere: a VBO (positions are normals) and an element buffer, squashed by glScalef. */
  glBindBuffer(GL_ARRAY_BUFFER, sphere_vbo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, sphere_ibo);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glVertexAttribPointer(3, 3, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glUniform1f(glGetUniformLocation(toon, "which"), 1.0f);
  glPushMatrix();
  glTranslatef(1.31f, 0.07f, -0.41f);
  glRotatef(-27.0f, 0.0f, 0.0f, 1.0f);
  glScalef(0.8f, 1.25f, 0.9f);
  glDrawElements(GL_TRIANGLES, SPHERE_INDICES, GL_UNSIGNED_SHORT, (void*)0);
  glPopMatrix();
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);

  /* The overlay: glOrtho in window pixels, client arrays again. */
  glDisable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 320.0, 0.0, 240.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glUseProgram(hud);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, hud_corner);
  glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, 0, hud_uv);
  glUniform1f(glGetUniformLocation(hud, "panel"), 0.0f);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, quad_idx);
  glUniform1f(glGetUniformLocation(hud, "panel"), 1.0f);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, quad_idx + 6);
  glDisableVertexAttribArray(0);
  glDisableVertexAttribArray(3);
  glUseProgram(0);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  /* The toon ramp: four bands, a 4x1 RGB texture read as a 1D table. */
  static const unsigned char ramp[4][3] = {{70, 60, 80}, {150, 145, 150}, {215, 212, 205}, {255, 255, 250}};
  static float sphere[SPHERE_VERTS * 3];
  static unsigned short sidx[SPHERE_INDICES];
  int i, j, k = 0;
  open_window(&argc, argv, 0, 0, 0, "glsl 1.10 textbook compat");
  toon = build(toon_vs, toon_fs, "position", "normal");
  hud = build(hud_vs, hud_fs, "corner", "uv");
  set_arrays(toon);
  set_arrays(hud);

  for (j = 0; j <= TV; ++j)
    for (i = 0; i <= TU; ++i) {
      const double u = 2.0 * 3.14159265358979 * i / TU, v = 2.0 * 3.14159265358979 * j / TV;
      const double R = 0.82, r = 0.36;
      torus[k][0] = (float)((R + r * cos(v)) * cos(u));
      torus[k][1] = (float)((R + r * cos(v)) * sin(u));
      torus[k][2] = (float)(r * sin(v));
      torus[k][3] = (float)(cos(v) * cos(u));
      torus[k][4] = (float)(cos(v) * sin(u));
      torus[k][5] = (float)sin(v);
      ++k;
    }
  k = 0;
  for (j = 0; j < TV; ++j)
    for (i = 0; i < TU; ++i) {
      const unsigned short a = (unsigned short)(j * (TU + 1) + i), b = (unsigned short)(a + TU + 1);
      torus_idx[k++] = a, torus_idx[k++] = (unsigned short)(a + 1), torus_idx[k++] = b;
      torus_idx[k++] = (unsigned short)(a + 1), torus_idx[k++] = (unsigned short)(b + 1), torus_idx[k++] = b;
    }
  make_sphere(sphere, sidx);
  glGenBuffers(1, &sphere_vbo);
  glBindBuffer(GL_ARRAY_BUFFER, sphere_vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof sphere, sphere, GL_STATIC_DRAW);
  glGenBuffers(1, &sphere_ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, sphere_ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof sidx, sidx, GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);

  glGenTextures(1, &ramp_tex);
  glBindTexture(GL_TEXTURE_2D, ramp_tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, ramp);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
