/* 37_tex_env_combine: GL 1.3 GL_COMBINE texture environments, the GL 1.4 crossbar, the
 * unit's LOD bias (GL_TEXTURE_FILTER_CONTROL) and point sprites (GL_COORD_REPLACE).
 * Top row: a light-map (GL_MODULATE with GL_RGB_SCALE 2); GL_INTERPOLATE between unit 0's
 * and unit 1's textures by the primary colour's alpha; DOT3_RGB bump lighting of a normal
 * map against a light vector given as the primary colour.
 * Bottom row: GL_ADD_SIGNED and GL_SUBTRACT with the constant colour and ONE_MINUS operands,
 * unit 1 reading unit 0's texture (GL_TEXTURE0 as a source) with GL_ALPHA_SCALE 2 and
 * GL_DOT3_RGBA; a minified mipmapped quad whose levels are flat colours, with a unit LOD
 * bias of 1.5; point sprites of size 24 with a radial texture on (s, t) = gl_PointCoord. */
#include <GL/glut.h>
#include <math.h>

enum { T_BASE, T_LIGHT, T_NORMAL, T_MIP, T_DOT, T_COUNT };
static GLuint tex[T_COUNT];

static void linear(void) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

static void make_textures(void) {
  GLubyte base[16 * 16 * 4], light[16 * 16], normal[16 * 16 * 3], dot[32 * 32 * 4];
  glGenTextures(T_COUNT, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      GLubyte* b = &base[(j * 16 + i) * 4];
      const int brick = ((j / 4) % 2 ? i + 2 : i) / 4;
      const int mortar = j % 4 == 0 || ((j / 4) % 2 ? i + 2 : i) % 4 == 0;
      b[0] = (GLubyte)(mortar ? 200 : 150 + brick * 20);
      b[1] = (GLubyte)(mortar ? 200 : 70 + brick * 8);
      b[2] = (GLubyte)(mortar ? 190 : 50);
      b[3] = (GLubyte)(i * 16);
      const float dx = (float)i - 7.5f, dy = (float)j - 7.5f;
      const float d = sqrtf(dx * dx + dy * dy);
      light[j * 16 + i] = (GLubyte)(d > 7.5f ? 40 : 255 - (int)(d * 28.0f));
      /* A dome of normals, (n + 1) / 2 in RGB. */
      float nx = dx / 8.0f, ny = dy / 8.0f, nz2 = 1.0f - nx * nx - ny * ny;
      if (nz2 < 0.0f) nx = ny = 0.0f, nz2 = 1.0f;
      GLubyte* n = &normal[(j * 16 + i) * 3];
      n[0] = (GLubyte)(127.5f + 127.0f * nx);
      n[1] = (GLubyte)(127.5f + 127.0f * ny);
      n[2] = (GLubyte)(127.5f + 127.0f * sqrtf(nz2));
    }
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) {
      const float dx = (float)i - 15.5f, dy = (float)j - 15.5f;
      const float d = sqrtf(dx * dx + dy * dy) / 16.0f;
      GLubyte* p = &dot[(j * 32 + i) * 4];
      p[0] = 255;
      p[1] = (GLubyte)(d < 1.0f ? 255 - (int)(d * 200.0f) : 0);
      p[2] = (GLubyte)(d < 0.5f ? 200 : 40);
      p[3] = (GLubyte)(d < 1.0f ? 255 - (int)(d * 255.0f) : 0);
    }
  glBindTexture(GL_TEXTURE_2D, tex[T_BASE]);
  linear();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, base);
  glBindTexture(GL_TEXTURE_2D, tex[T_LIGHT]);
  linear();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 16, 16, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, light);
  glBindTexture(GL_TEXTURE_2D, tex[T_NORMAL]);
  linear();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, normal);
  glBindTexture(GL_TEXTURE_2D, tex[T_DOT]);
  linear();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, dot);
  /* Mipmap levels of flat colours, 64x64 down to 1x1. */
  static const GLubyte level_colour[7][3] = {{250, 40, 40}, {240, 200, 40}, {60, 220, 60},  {40, 200, 230},
                                             {60, 60, 240}, {220, 60, 220}, {240, 240, 240}};
  glBindTexture(GL_TEXTURE_2D, tex[T_MIP]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  static GLubyte level[64 * 64 * 3];
  for (int l = 0, size = 64; size >= 1; ++l, size /= 2) {
    for (int k = 0; k < size * size; ++k)
      for (int c = 0; c < 3; ++c) level[k * 3 + c] = level_colour[l][c];
    glTexImage2D(GL_TEXTURE_2D, l, GL_RGB, size, size, 0, GL_RGB, GL_UNSIGNED_BYTE, level);
  }
}

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, w, 0, h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void bind(GLenum unit, int t) {
  glActiveTexture(unit);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tex[t]);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
}

static void reset(void) {
  for (int u = 1; u >= 0; --u) {
    glActiveTexture(GL_TEXTURE0 + (GLenum)u);
    glDisable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_MODULATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_MODULATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB, GL_TEXTURE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_RGB, GL_PREVIOUS);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC2_RGB, GL_CONSTANT);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_ALPHA, GL_TEXTURE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_ALPHA, GL_PREVIOUS);
    glTexEnvi(GL_TEXTURE_ENV, GL_SRC2_ALPHA, GL_CONSTANT);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_SRC_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_SRC_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_ALPHA);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_ALPHA);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_ALPHA, GL_SRC_ALPHA);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_ALPHA, GL_SRC_ALPHA);
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 1.0f);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 1.0f);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.0f);
  }
}

/* A quad at (x, y), 96 x 104, with both units' coordinates (unit 1's turned a little) and
 * per-corner primary colours. */
static void quad(int x, int y, const GLfloat colours[4][4]) {
  static const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  static const float uv1[4][2] = {{0.1f, 0.0f}, {1.0f, 0.12f}, {0.9f, 1.0f}, {0.0f, 0.86f}};
  const int px[4] = {x, x + 96, x + 96, x}, py[4] = {y, y, y + 104, y + 104};
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) {
    glColor4fv(colours[i]);
    glMultiTexCoord2fv(GL_TEXTURE0, uv[i]);
    glMultiTexCoord2fv(GL_TEXTURE1, uv1[i]);
    glVertex2i(px[i], py[i]);
  }
  glEnd();
}

static void display(void) {
  static const GLfloat grey[4][4] = {
      {0.8f, 0.8f, 0.8f, 0.1f}, {0.9f, 0.7f, 0.7f, 0.4f}, {0.7f, 0.9f, 0.7f, 0.9f}, {0.7f, 0.7f, 0.9f, 0.6f}};
  /* Light vectors (l + 1) / 2 for the DOT3 quad: from the upper left to the right. */
  static const GLfloat light_dir[4][4] = {
      {0.2f, 0.8f, 0.8f, 1}, {0.9f, 0.6f, 0.7f, 1}, {0.8f, 0.2f, 0.75f, 1}, {0.3f, 0.3f, 0.95f, 1}};
  const GLfloat constant[4] = {0.3f, 0.55f, 0.8f, 0.4f};
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  /* Light-map: base * light * 2. */
  bind(GL_TEXTURE0, T_BASE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_REPLACE);
  bind(GL_TEXTURE1, T_LIGHT);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0f);
  quad(6, 130, grey);
  reset();

  /* Interpolate unit 0 and unit 1 by the primary alpha. */
  bind(GL_TEXTURE0, T_BASE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_REPLACE);
  bind(GL_TEXTURE1, T_NORMAL);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB, GL_TEXTURE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_RGB, GL_PREVIOUS);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC2_RGB, GL_PRIMARY_COLOR);
  quad(112, 130, grey);
  reset();

  /* DOT3 bump lighting, then modulated by the base texture on unit 1. */
  bind(GL_TEXTURE0, T_NORMAL);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGB);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB, GL_TEXTURE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_RGB, GL_PRIMARY_COLOR);
  bind(GL_TEXTURE1, T_BASE);
  quad(218, 130, light_dir);
  reset();

  /* ADD_SIGNED with the constant colour, then SUBTRACT of (1 - constant alpha). */
  bind(GL_TEXTURE0, T_BASE);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD_SIGNED);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_RGB, GL_CONSTANT);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);
  bind(GL_TEXTURE1, T_LIGHT);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_SUBTRACT);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB, GL_PREVIOUS);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_RGB, GL_TEXTURE);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_ONE_MINUS_SRC_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_MODULATE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_ALPHA, GL_CONSTANT);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  quad(6, 14, grey);
  glDisable(GL_BLEND);
  reset();

  /* Crossbar: unit 1 reads unit 0's texture; DOT3_RGBA with an alpha scale set. */
  bind(GL_TEXTURE0, T_NORMAL);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_REPLACE);
  bind(GL_TEXTURE1, T_LIGHT);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGBA);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB, GL_TEXTURE0);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_RGB, GL_PRIMARY_COLOR);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 2.0f);
  quad(112, 14, light_dir);
  reset();

  /* LOD bias on a minified, mipmapped quad (64 texels over 40 to 12 pixels). */
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tex[T_MIP]);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 1.5f);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(218.3f, 60.2f);
  glTexCoord2f(1, 0);
  glVertex2f(258.1f, 60.2f);
  glTexCoord2f(1, 1);
  glVertex2f(270.4f, 113.7f);
  glTexCoord2f(0, 1);
  glVertex2f(226.6f, 113.7f);
  glEnd();
  reset();

  /* Point sprites. */
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tex[T_DOT]);
  glEnable(GL_POINT_SPRITE);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glPointSize(24.0f);
  glBegin(GL_POINTS);
  glColor3f(1.0f, 1.0f, 1.0f);
  glVertex2f(236.0f, 36.0f);
  glColor3f(0.4f, 0.8f, 1.0f);
  glVertex2f(266.0f, 30.0f);
  glColor3f(1.0f, 0.6f, 0.3f);
  glVertex2f(300.0f, 40.0f);
  glColor3f(0.7f, 1.0f, 0.5f);
  glVertex2f(296.0f, 88.0f);
  glEnd();
  glDisable(GL_BLEND);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
  glDisable(GL_POINT_SPRITE);
  glDisable(GL_TEXTURE_2D);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(320, 240);
  glutCreateWindow("37 texture combine");
  glDisable(GL_DITHER);
  make_textures();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
