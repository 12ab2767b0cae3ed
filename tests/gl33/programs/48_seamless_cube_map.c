/*
 * GL_TEXTURE_CUBE_MAP_SEAMLESS (GL 3.3 §3.8.8; GLUT + GLEW, 3.3 core), as skybox and image
 * based lighting code enables it: a cube map of 4x4 faces, each face its own colour with a
 * pattern of texels, magnified with GL_LINEAR so every texel is a large soft square, seen
 * towards a corner where three faces meet. The left half is drawn with the capability off -
 * each face clamps to its own edge, hard seams - and the right half with it on: across an
 * edge the lookup blends with the neighbouring face's texels, and at the corner with the three
 * that meet there. A second cube map with mipmaps is read with textureLod at level 1.5, and a
 * depth cube map through samplerCubeShadow (each texel compared, then filtered).
 */
#include "common.h"

static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 position;\n"
    "out vec2 p;\n"
    "void main() { p = position; gl_Position = vec4(position, 0.0, 1.0); }\n";

static const char* fs =
    "#version 330 core\n"
    "in vec2 p;\n"
    "uniform samplerCube sky, mips;\n"
    "uniform samplerCubeShadow depths;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  // looking at the corner (1, 1, -1) from the centre\n"
    "  vec2 q = vec2(mod(gl_FragCoord.x, 160.0) / 80.0 - 1.0, p.y * 1.5);  // each half the same view\n"
    "  vec3 f = normalize(vec3(1.0, 1.0, -1.0));\n"
    "  vec3 r = normalize(cross(f, vec3(0.0, 1.0, 0.0)));\n"
    "  vec3 u = cross(r, f);\n"
    "  vec3 d = f + 0.55 * (q.x * r + q.y * u);\n"
    "  if (p.y > -0.4) frag = texture(sky, d);\n"
    "  else if (p.y > -0.7) frag = textureLod(mips, d, 1.5);\n"
    "  else frag = vec4(texture(depths, vec4(d, 0.5)), 0.3, 0.1, 1.0);  // the fraction passing\n"
    "}\n";

static GLuint prog, vao, tex[3];

/* 2x2 depth faces, each face its own depth around the reference 0.5. */
static GLuint depth_cube(void) {
  static const float depth[6] = {0.2f, 0.7f, 0.45f, 0.9f, 0.6f, 0.8f};
  float px[4];
  GLuint t;
  int f, i;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_CUBE_MAP, t);
  for (f = 0; f < 6; ++f) {
    for (i = 0; i < 4; ++i) px[i] = depth[f] + (i == 1 ? 0.25f : 0.0f) - (i == 2 ? 0.25f : 0.0f);
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_DEPTH_COMPONENT24, 2, 2, 0, GL_DEPTH_COMPONENT,
                 GL_FLOAT, px);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  return t;
}

static void display(void) {
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glUseProgram(prog);
  glBindVertexArray(vao);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 160, 240);
  glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glScissor(160, 0, 160, 240);
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  if (glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS)) glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  glDisable(GL_SCISSOR_TEST);
  check_gl("display");
  glutSwapBuffers();
}

static GLuint cube(int size, int mipmaps) {
  static const unsigned char colors[6][3] = {{230, 60, 50},  {60, 200, 80},  {60, 90, 230},
                                             {230, 210, 60}, {200, 70, 220}, {70, 210, 220}};
  static unsigned char px[64 * 64 * 4];
  GLuint t;
  int f, i;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_CUBE_MAP, t);
  for (f = 0; f < 6; ++f) {
    for (i = 0; i < size * size; ++i) {
      const int x = i % size, y = i / size, k = (x + y) % 3;
      px[i * 4 + 0] = (unsigned char)(colors[f][0] * (3 - k) / 3 + 40 * k);
      px[i * 4 + 1] = (unsigned char)(colors[f][1] * (2 + (x & 1)) / 3);
      px[i * 4 + 2] = (unsigned char)(colors[f][2] * (2 + (y & 1)) / 3);
      px[i * 4 + 3] = 255;
    }
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 px);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  if (mipmaps) glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  return t;
}

int main(int argc, char** argv) {
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "seamless cube map");
  prog = link_program(vs, fs);
  glActiveTexture(GL_TEXTURE0);
  tex[0] = cube(4, 0);
  glActiveTexture(GL_TEXTURE1);
  tex[1] = cube(16, 1);
  glActiveTexture(GL_TEXTURE2);
  tex[2] = depth_cube();
  glUseProgram(prog);
  glUniform1i(glGetUniformLocation(prog, "sky"), 0);
  glUniform1i(glGetUniformLocation(prog, "mips"), 1);
  glUniform1i(glGetUniformLocation(prog, "depths"), 2);
  vao = window_strip();
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
