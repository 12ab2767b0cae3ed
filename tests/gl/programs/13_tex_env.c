/* 13_tex_env: texture objects (glGenTextures, glBindTexture), glTexImage2D with GL_RGB,
 * GL_RGBA and GL_LUMINANCE unsigned-byte data, and the texture environment modes
 * GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND (with GL_TEXTURE_ENV_COLOR) and GL_ADD.
 * Rows: the RGB, RGBA and LUMINANCE textures; columns: the five modes. Each quad has
 * per-vertex colours with alpha < 1 at some corners and is blended
 * (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) over a checkerboard so the resulting alpha shows.
 * DECAL is undefined for luminance textures; that cell shows a GL_ALPHA texture under
 * GL_MODULATE instead. Nearest filtering at integer magnification (7x, 9x). */
#include <GL/glut.h>

enum { TEX_RGB, TEX_RGBA, TEX_LUM, TEX_ALPHA, TEX_COUNT };
static GLuint tex[TEX_COUNT];

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, w, 0, h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void make_textures(void) {
  GLubyte rgb[8 * 8 * 3], rgba[8 * 8 * 4], lum[8 * 8], alpha[8 * 8];
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const int k = j * 8 + i;
      rgb[k * 3 + 0] = (GLubyte)(i * 36);
      rgb[k * 3 + 1] = (GLubyte)(j * 36);
      rgb[k * 3 + 2] = (GLubyte)((i + j) % 2 ? 230 : 40);
      rgba[k * 4 + 0] = (GLubyte)((i ^ j) & 1 ? 250 : 30);
      rgba[k * 4 + 1] = (GLubyte)(200 - i * 20);
      rgba[k * 4 + 2] = (GLubyte)(60 + j * 25);
      rgba[k * 4 + 3] = (GLubyte)(j * 36);
      lum[k] = (GLubyte)(((i / 2 + j / 2) % 2 ? 200 : 50) + i * 5);
      alpha[k] = (GLubyte)(i == j || i == 7 - j ? 255 : 60 + 20 * i);
    }
  glGenTextures(TEX_COUNT, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int t = 0; t < TEX_COUNT; ++t) {
    glBindTexture(GL_TEXTURE_2D, tex[t]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    switch (t) {
      case TEX_RGB: glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb); break;
      case TEX_RGBA: glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba); break;
      case TEX_LUM:
        glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 8, 8, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
        break;
      default: glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 8, 8, 0, GL_ALPHA, GL_UNSIGNED_BYTE, alpha); break;
    }
  }
  const GLfloat env_colour[4] = {0.2f, 0.4f, 1.0f, 0.5f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_colour);
}

static void display(void) {
  static const GLenum modes[5] = {GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD};
  glClearColor(0.3f, 0.3f, 0.3f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_BLEND);
  glColor3f(0.7f, 0.7f, 0.7f);
  for (int y = 0; y < 240; y += 8)
    for (int x = (y / 8) % 2 * 8; x < 320; x += 16) glRecti(x, y, x + 8, y + 8);

  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_TEXTURE_2D);
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 5; ++col) {
      int t = row;
      GLenum mode = modes[col];
      if (t == TEX_LUM && mode == GL_DECAL) {
        t = TEX_ALPHA;
        mode = GL_MODULATE;
      }
      glBindTexture(GL_TEXTURE_2D, tex[t]);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)mode);
      const int x = col * 64 + 4, y = (2 - row) * 80 + 4;
      glBegin(GL_QUADS);
      glColor4f(1.0f, 0.3f, 0.3f, 1.0f);
      glTexCoord2f(0, 0);
      glVertex2i(x, y);
      glColor4f(0.3f, 1.0f, 0.3f, 0.6f);
      glTexCoord2f(1, 0);
      glVertex2i(x + 56, y);
      glColor4f(0.3f, 0.3f, 1.0f, 1.0f);
      glTexCoord2f(1, 1);
      glVertex2i(x + 56, y + 72);
      glColor4f(1.0f, 1.0f, 0.3f, 0.8f);
      glTexCoord2f(0, 1);
      glVertex2i(x, y + 72);
      glEnd();
    }
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_BLEND);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(320, 240);
  glutCreateWindow("13 texture environment");
  glDisable(GL_DITHER);
  make_textures();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
