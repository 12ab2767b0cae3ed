/*
 * A program with a vertex shader and no fragment shader, as GL 2.0 allows (§2.15.4): fixed
 * function's fragment processing follows the shader. The shaders write gl_FrontColor,
 * gl_FrontSecondaryColor, gl_TexCoord[0..1] and gl_FogFragCoord, and the fixed-function state
 * does the rest: GL_MODULATE and GL_ADD texturing on two units, the colour sum, linear and
 * exponential fog, the alpha test. The vertex shaders take uniforms (a float, a vec2 array, a
 * mat2) that must reach every state's draw, set before and between draws.
 */
#include "common.h"

static const char* wave_vs =
    "#version 110\n"
    "uniform float phase;\n"
    "uniform vec2 shift[2];\n"
    "uniform mat2 spin;\n"
    "void main() {\n"
    "  vec4 v = gl_Vertex;\n"
    "  v.xy = spin * v.xy + shift[0] + shift[1];\n"
    "  v.z += 0.3 * sin(3.0 * v.x + phase);\n"
    "  vec4 eye = gl_ModelViewMatrix * v;\n"
    "  gl_Position = gl_ProjectionMatrix * eye;\n"
    "  gl_FrontColor = vec4(0.5 + 0.5 * gl_Normal, 1.0) * gl_Color;\n"
    "  gl_FrontSecondaryColor = vec4(0.25 * max(sin(phase + v.y * 4.0), 0.0));\n"
    "  gl_TexCoord[0] = gl_MultiTexCoord0 * 2.0;\n"
    "  gl_TexCoord[1] = vec4(v.xy * 0.5 + 0.5, 0.0, 1.0);\n"
    "  gl_FogFragCoord = -eye.z;\n"
    "}\n";

static GLuint wave, tex[2];

static void grid(void) {
  int i, j;
  for (j = 0; j < 8; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i <= 8; ++i) {
      const float x = -1.0f + 0.25f * (float)i;
      glNormal3f(0.6f * x, 0.5f, 0.6f);
      glColor4f(1.0f, 0.9f - 0.05f * (float)j, 0.8f, (float)(i + j) / 16.0f);
      glMultiTexCoord2f(GL_TEXTURE0, (float)i / 8.0f, (float)j / 8.0f);
      glVertex3f(x, -1.0f + 0.25f * (float)j, 0.0f);
      glMultiTexCoord2f(GL_TEXTURE0, (float)i / 8.0f, (float)(j + 1) / 8.0f);
      glVertex3f(x, -1.0f + 0.25f * (float)(j + 1), 0.0f);
    }
    glEnd();
  }
}

static void panel(int col, int row) {
  glViewport(col * 160, row * 120, 160, 120);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.53, 0.53, -0.4, 0.4, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -2.6f);
  glRotatef(-35.0f, 1.0f, 0.0f, 0.0f);
}

static void display(void) {
  static const float shift[4] = {0.1f, -0.05f, -0.1f, 0.05f};
  static const float spin[4] = {0.94f, 0.34f, -0.34f, 0.94f};
  static const float fog_color[4] = {0.55f, 0.6f, 0.7f, 1.0f};
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glUseProgram(wave);
  glUniform1f(glGetUniformLocation(wave, "phase"), 0.7f);
  glUniform2fv(glGetUniformLocation(wave, "shift"), 2, shift);
  glUniformMatrix2fv(glGetUniformLocation(wave, "spin"), 1, GL_FALSE, spin);

  /* 1: no texturing: the colour (and its alpha) as the shader gave it. */
  panel(0, 1);
  grid();

  /* 2: unit 0 modulates a checkerboard, unit 1 adds a ramp. */
  panel(1, 1);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  glUniform1f(glGetUniformLocation(wave, "phase"), 2.1f);
  grid();
  glDisable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);

  /* 3: the colour sum and linear fog, unit 0 textured. */
  panel(0, 0);
  glEnable(GL_COLOR_SUM);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 1.8f);
  glFogf(GL_FOG_END, 3.6f);
  glFogfv(GL_FOG_COLOR, fog_color);
  grid();
  glDisable(GL_COLOR_SUM);

  /* 4: exponential fog and the alpha test, no texture. */
  panel(1, 0);
  glDisable(GL_TEXTURE_2D);
  glFogi(GL_FOG_MODE, GL_EXP);
  glFogf(GL_FOG_DENSITY, 0.35f);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.3f);
  grid();
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_FOG);
  glUseProgram(0);
  glViewport(0, 0, 320, 240);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static GLubyte checker[8][8][3], ramp[4][4][3];
  int i, j;
  GLint ok = 0;
  GLuint v;
  open_window(&argc, argv, 0, 0, 0, "vertex shader only");
  v = compile_shader(GL_VERTEX_SHADER, wave_vs);
  wave = glCreateProgram();
  glAttachShader(wave, v);
  glLinkProgram(wave);
  glGetProgramiv(wave, GL_LINK_STATUS, &ok);
  if (!ok) {
    fprintf(stderr, "link failed\n");
    return 1;
  }
  for (j = 0; j < 8; ++j)
    for (i = 0; i < 8; ++i) {
      const int on = (i + j) & 1;
      checker[j][i][0] = (GLubyte)(on ? 250 : 110);
      checker[j][i][1] = (GLubyte)(on ? 230 : 120);
      checker[j][i][2] = (GLubyte)(on ? 200 : 160);
    }
  for (j = 0; j < 4; ++j)
    for (i = 0; i < 4; ++i) {
      ramp[j][i][0] = (GLubyte)(20 * i);
      ramp[j][i][1] = (GLubyte)(15 * j);
      ramp[j][i][2] = (GLubyte)(10 * (i + j));
    }
  tex[0] = rgb_texture(8, 8, checker, GL_NEAREST);
  tex[1] = rgb_texture(4, 4, ramp, GL_LINEAR);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
