/*
 * Multitexturing through the fixed-function state in GLSL 1.20, as GL 2.x game code writes it
 * (compatibility context, GLUT + GLEW): a base texture on unit 0 and a light-map on unit 1,
 * each unit with its own texture matrix (glActiveTexture, glMatrixMode(GL_TEXTURE),
 * glTranslate/glRotate/glScale) read in the vertex shader as gl_TextureMatrix[0] and [1]
 * applied to gl_MultiTexCoord0 and gl_MultiTexCoord1; per-pixel lighting from
 * gl_LightSource[0] and gl_FrontMaterial with gl_ModelViewMatrix and gl_NormalMatrix,
 * ftransform(), and the vertex colour passed as gl_FrontColor and read back as gl_Color.
 * A floor and a back wall are given in immediate mode (glBegin/glEnd with glMultiTexCoord2f
 * for both units, glNormal3f, glColor3f); a cube is given with client arrays, its two
 * texture coordinate sets chosen with glClientActiveTexture before glTexCoordPointer.
 */
#include "common.h"

#include <GL/glu.h>

static const char* vs =
    "#version 120\n"
    "varying vec2 uv0, uv1;\n"
    "varying vec3 n, v;\n"
    "void main() {\n"
    "  uv0 = (gl_TextureMatrix[0] * gl_MultiTexCoord0).st;\n"
    "  uv1 = (gl_TextureMatrix[1] * gl_MultiTexCoord1).st;\n"
    "  n = gl_NormalMatrix * gl_Normal;\n"
    "  v = vec3(gl_ModelViewMatrix * gl_Vertex);\n"
    "  gl_FrontColor = gl_Color;\n"
    "  gl_Position = ftransform();\n"
    "}\n";

static const char* fs =
    "#version 120\n"
    "uniform sampler2D base;\n"
    "uniform sampler2D lightmap;\n"
    "varying vec2 uv0, uv1;\n"
    "varying vec3 n, v;\n"
    "void main() {\n"
    "  vec3 N = normalize(n);\n"
    "  vec3 L = normalize(gl_LightSource[0].position.xyz - v);\n"
    "  vec3 E = normalize(-v);\n"
    "  vec3 H = normalize(L + E);\n"
    "  vec4 albedo = texture2D(base, uv0) * gl_Color;\n"
    "  vec3 light = texture2D(lightmap, uv1).rgb * 1.6;\n"
    "  vec3 diffuse = gl_LightSource[0].diffuse.rgb * gl_FrontMaterial.diffuse.rgb * max(dot(N, L), 0.0);\n"
    "  vec3 ambient = gl_LightSource[0].ambient.rgb * gl_FrontMaterial.ambient.rgb;\n"
    "  float s = pow(max(dot(N, H), 0.0), gl_FrontMaterial.shininess);\n"
    "  vec3 spec = gl_LightSource[0].specular.rgb * gl_FrontMaterial.specular.rgb * s;\n"
    "  gl_FragColor = vec4(albedo.rgb * (ambient + diffuse) * light + spec, 1.0);\n"
    "}\n";

static GLuint prog, tex[2];
static float cube_pos[72], cube_nrm[72], cube_col[72], cube_uv0[48], cube_uv1[48];

static void texture_matrices(void) {
  glActiveTexture(GL_TEXTURE0);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(0.13f, 0.07f, 0.0f);
  glRotatef(12.0f, 0.0f, 0.0f, 1.0f);
  glScalef(2.0f, 2.0f, 1.0f);
  glActiveTexture(GL_TEXTURE1);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(0.5f, 0.5f, 0.0f);
  glScalef(0.85f, 0.85f, 1.0f);
  glTranslatef(-0.5f, -0.5f, 0.0f);
  glMatrixMode(GL_MODELVIEW);
}

static void corner(float s0, float t0, float s1, float t1, float x, float y, float z) {
  glMultiTexCoord2f(GL_TEXTURE0, s0, t0);
  glMultiTexCoord2f(GL_TEXTURE1, s1, t1);
  glVertex3f(x, y, z);
}

static void display(void) {
  const GLfloat light_pos[4] = {1.5f, 3.0f, 2.0f, 1.0f};
  const GLfloat white[4] = {1, 1, 1, 1}, grey[4] = {0.35f, 0.35f, 0.4f, 1};
  const GLfloat mat_amb[4] = {0.6f, 0.6f, 0.6f, 1}, mat_dif[4] = {0.9f, 0.9f, 0.85f, 1};
  const GLfloat mat_spec[4] = {0.3f, 0.3f, 0.3f, 1};
  glClearColor(0.1f, 0.12f, 0.18f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(50.0, 320.0 / 240.0, 0.5, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.11, 1.6, 4.2, 0.03, 0.2, 0.0, 0, 1, 0);
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glLightfv(GL_LIGHT0, GL_AMBIENT, grey);
  glMaterialfv(GL_FRONT, GL_AMBIENT, mat_amb);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, mat_dif);
  glMaterialfv(GL_FRONT, GL_SPECULAR, mat_spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
  texture_matrices();

  glUseProgram(prog);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glActiveTexture(GL_TEXTURE0);

  /* The floor and the back wall, immediate mode, both texture units. */
  glBegin(GL_QUADS);
  glNormal3f(0.0f, 1.0f, 0.0f);
  glColor3f(1.0f, 0.95f, 0.85f);
  corner(0, 0, 0, 0, -2.6f, -0.5f, 1.4f);
  corner(1, 0, 1, 0, 2.6f, -0.5f, 1.4f);
  glColor3f(0.8f, 0.9f, 1.0f);
  corner(1, 1, 1, 1, 2.6f, -0.5f, -1.9f);
  corner(0, 1, 0, 1, -2.6f, -0.5f, -1.9f);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glColor3f(0.9f, 0.75f, 0.6f);
  corner(0, 0, 0, 1, -2.6f, -0.5f, -1.9f);
  corner(1.5f, 0, 1, 1, 2.6f, -0.5f, -1.9f);
  glColor3f(0.7f, 0.6f, 0.9f);
  corner(1.5f, 0.8f, 1, 0, 2.6f, 1.8f, -1.9f);
  corner(0, 0.8f, 0, 0, -2.6f, 1.8f, -1.9f);
  glEnd();

  /* The cube: client arrays, two texture coordinate sets. */
  glPushMatrix();
  glTranslatef(0.35f, 0.05f, -0.3f);
  glRotatef(31.0f, 0.0f, 1.0f, 0.0f);
  glRotatef(-13.0f, 1.0f, 0.0f, 0.0f);
  glScalef(0.55f, 0.55f, 0.55f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, cube_pos);
  glNormalPointer(GL_FLOAT, 0, cube_nrm);
  glColorPointer(3, GL_FLOAT, 0, cube_col);
  glClientActiveTexture(GL_TEXTURE0);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_FLOAT, 0, cube_uv0);
  glClientActiveTexture(GL_TEXTURE1);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_FLOAT, 0, cube_uv1);
  glDrawArrays(GL_QUADS, 0, 24);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glClientActiveTexture(GL_TEXTURE0);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glPopMatrix();
  glUseProgram(0);
  check_gl("display");
  glutSwapBuffers();
}

static void make_cube(void) {
  static const float nrm[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  static const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  int f, k, i;
  for (f = 0; f < 6; ++f) {
    /* Two axes spanning the face, chosen so that the corners run counter-clockwise. */
    const float* nn = nrm[f];
    float a[3] = {nn[1] != 0.0f ? 1.0f : 0.0f, 0.0f, 0.0f}, b[3];
    if (nn[0] != 0.0f) a[2] = -nn[0];
    if (nn[2] != 0.0f) a[0] = nn[2];
    if (nn[1] != 0.0f) a[0] = 1.0f;
    b[0] = nn[1] * a[2] - nn[2] * a[1];
    b[1] = nn[2] * a[0] - nn[0] * a[2];
    b[2] = nn[0] * a[1] - nn[1] * a[0];
    for (k = 0; k < 4; ++k) {
      const float sa = uv[k][0] * 2.0f - 1.0f, sb = uv[k][1] * 2.0f - 1.0f;
      const int j = f * 4 + k;
      for (i = 0; i < 3; ++i) {
        cube_pos[j * 3 + i] = nn[i] + sa * a[i] + sb * b[i];
        cube_nrm[j * 3 + i] = nn[i];
      }
      cube_col[j * 3 + 0] = 0.6f + 0.08f * (float)f;
      cube_col[j * 3 + 1] = 0.9f - 0.1f * (float)k;
      cube_col[j * 3 + 2] = 0.5f + 0.1f * (float)((f + k) % 4);
      cube_uv0[j * 2 + 0] = uv[k][0] * 0.5f;
      cube_uv0[j * 2 + 1] = uv[k][1] * 0.5f;
      cube_uv1[j * 2 + 0] = 0.1f + 0.8f * uv[k][0] * (0.3f + 0.1f * (float)f);
      cube_uv1[j * 2 + 1] = 0.2f + 0.6f * uv[k][1];
    }
  }
}

static GLuint make_texture(int size, const unsigned char* rgb) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, size, size, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  return t;
}

int main(int argc, char** argv) {
  static unsigned char bricks[32 * 32 * 3], light[16 * 16 * 3];
  int x, y;
  open_window(&argc, argv, 0, 0, 0, "glsl 1.20 multitexture fixed state");
  prog = link_program(vs, fs);
  glUseProgram(prog);
  glUniform1i(glGetUniformLocation(prog, "base"), 0);
  glUniform1i(glGetUniformLocation(prog, "lightmap"), 1);
  glUseProgram(0);
  /* Bricks: 4 rows of 8-texel courses, mortar lines, shifted every other course. */
  for (y = 0; y < 32; ++y)
    for (x = 0; x < 32; ++x) {
      const int course = y / 8, bx = (x + (course % 2) * 8) % 16;
      const int mortar = (y % 8 == 0) || (bx == 0);
      unsigned char* p = &bricks[(y * 32 + x) * 3];
      p[0] = (unsigned char)(mortar ? 200 : 160 + 20 * (course % 2) + ((x * 7 + y * 3) % 5) * 6);
      p[1] = (unsigned char)(mortar ? 195 : 70 + 15 * ((x / 16 + course) % 3));
      p[2] = (unsigned char)(mortar ? 180 : 50);
    }
  /* The light-map: two soft spots, one warm, one cool, over a dim base. */
  for (y = 0; y < 16; ++y)
    for (x = 0; x < 16; ++x) {
      const float d1 = (float)((x - 4) * (x - 4) + (y - 5) * (y - 5)) / 18.0f;
      const float d2 = (float)((x - 11) * (x - 11) + (y - 10) * (y - 10)) / 24.0f;
      const float w = 1.0f / (1.0f + d1), c = 1.0f / (1.0f + d2);
      unsigned char* p = &light[(y * 16 + x) * 3];
      p[0] = (unsigned char)(60 + 150 * w + 30 * c);
      p[1] = (unsigned char)(60 + 110 * w + 90 * c);
      p[2] = (unsigned char)(70 + 40 * w + 150 * c);
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glActiveTexture(GL_TEXTURE0);
  tex[0] = make_texture(32, bricks);
  glActiveTexture(GL_TEXTURE1);
  tex[1] = make_texture(16, light);
  glActiveTexture(GL_TEXTURE0);
  make_cube();
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
