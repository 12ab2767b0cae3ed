/*
 * What compatibility contexts still allow with GLSL programs, as GL 2.x course code uses it:
 * generic attributes read from client memory (vertex array object 0, no buffer bound), in
 * GL_DOUBLE, normalized GL_SHORT and packed GL_INT_2_10_10_10_REV; a disabled attribute
 * that reads its current value (glVertexAttrib4f); glBindAttribLocation instead of layout
 * qualifiers; GL_QUADS, GL_QUAD_STRIP and GL_POLYGON drawn by glDrawArrays and glDrawElements
 * with client-side indices; GLSL 1.30 with `in`/`out` and a flat-shaded output.
 */
#include "common.h"

static const char* vs =
    "#version 130\n"
    "in vec2 position;\n"
    "in vec3 tint;\n"
    "in vec4 pk;\n"
    "in vec4 constant_color;\n"
    "out vec3 color;\n"
    "flat out vec4 flat_color;\n"
    "void main() {\n"
    "  color = tint * constant_color.rgb + 0.25 * pk.xyz;\n"
    "  flat_color = vec4(pk.w, tint.g, constant_color.b, 1.0);\n"
    "  gl_Position = vec4(position, 0.0, 1.0);\n"
    "}\n";

static const char* fs =
    "#version 130\n"
    "in vec3 color;\n"
    "flat in vec4 flat_color;\n"
    "uniform float flat_share;\n"
    "void main() { gl_FragColor = vec4(mix(color, flat_color.rgb, flat_share), 1.0); }\n";

static GLuint prog;
static double pos[32][2];
static short tints[32][3];
static unsigned int packed[32];

static unsigned int pack(int x, int y, int z, int w) {
  return ((unsigned)x & 1023u) | (((unsigned)y & 1023u) << 10) | (((unsigned)z & 1023u) << 20) |
         (((unsigned)w & 3u) << 30);
}

static void display(void) {
  static const unsigned char quad_idx[8] = {8, 9, 10, 11, 12, 13, 14, 15};
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glUseProgram(prog);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glVertexAttribPointer(0, 2, GL_DOUBLE, GL_FALSE, 0, pos);
  glVertexAttribPointer(1, 3, GL_SHORT, GL_TRUE, 0, tints);
  glVertexAttribPointer(2, 4, GL_INT_2_10_10_10_REV, GL_TRUE, 0, packed);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glEnableVertexAttribArray(2);
  glDisableVertexAttribArray(3);
  glVertexAttrib4f(3, 0.9f, 0.8f, 0.6f, 1.0f);
  glUniform1f(glGetUniformLocation(prog, "flat_share"), 0.0f);
  glDrawArrays(GL_QUADS, 0, 8);                            /* two quads */
  glDrawElements(GL_QUADS, 8, GL_UNSIGNED_BYTE, quad_idx); /* two more, by index */
  glUniform1f(glGetUniformLocation(prog, "flat_share"), 0.6f);
  glDrawArrays(GL_QUAD_STRIP, 16, 8); /* three quads in a strip */
  glDrawArrays(GL_POLYGON, 24, 8);    /* an octagon */
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  int i;
  open_window(&argc, argv, 0, 0, 0, "client arrays compat");
  {
    GLuint v = compile_shader(GL_VERTEX_SHADER, vs), f = compile_shader(GL_FRAGMENT_SHADER, fs);
    GLint ok = 0;
    prog = glCreateProgram();
    glAttachShader(prog, v);
    glAttachShader(prog, f);
    glBindAttribLocation(prog, 0, "position");
    glBindAttribLocation(prog, 1, "tint");
    glBindAttribLocation(prog, 2, "pk");
    glBindAttribLocation(prog, 3, "constant_color");
    glLinkProgram(prog);
    glGetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok || glGetAttribLocation(prog, "tint") != 1) return 1;
  }
  /* Four quads in a row at the top, a strip in the middle, an octagon at the bottom. */
  for (i = 0; i < 16; ++i) {
    const int q = i / 4, k = i % 4;
    pos[i][0] = -0.9 + 0.45 * q + ((k == 1 || k == 2) ? 0.35 : 0.0);
    pos[i][1] = 0.4 + ((k >= 2) ? 0.45 : 0.0) - 0.05 * q;
  }
  for (i = 0; i < 8; ++i) {
    pos[16 + i][0] = -0.8 + 0.22 * (i / 2);
    pos[16 + i][1] = (i % 2) ? -0.1 + 0.03 * i : 0.25;
  }
  for (i = 0; i < 8; ++i) {
    const double a = 2.0 * 3.14159265358979 * i / 8.0 + 0.2;
    pos[24 + i][0] = 0.45 + 0.35 * cos(a);
    pos[24 + i][1] = -0.5 + 0.4 * sin(a);
  }
  for (i = 0; i < 32; ++i) {
    tints[i][0] = (short)((i * 2311) % 32767);
    tints[i][1] = (short)(32767 - (i * 997) % 32767);
    tints[i][2] = (short)((i % 3) * 12000 - 5000);
    packed[i] = pack((i * 37) % 511, (i * 91) % 511 - 255, 300 - i * 11, i % 2);
  }
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
