/* 14_tex_filter_mipmap: texture filtering, mipmaps and wrap modes, on axis-aligned quads
 * whose texel-to-pixel scale is chosen so that no sample falls on a texel boundary and the
 * level of detail is exact:
 *   magnification 9x with GL_NEAREST and GL_LINEAR;
 *   GL_CLAMP (border colour set) and GL_REPEAT with linear filtering over texcoords -0.5..1.5;
 *   GL_CLAMP with nearest filtering;
 *   minification 2.5x with GL_NEAREST and GL_LINEAR (no mipmaps);
 *   a 32x32 texture whose six levels are built one by one with glTexImage2D, each level its
 *   own colour: GL_NEAREST_MIPMAP_NEAREST at lambda 2, GL_LINEAR_MIPMAP_NEAREST at
 *   lambda 1, GL_NEAREST_MIPMAP_LINEAR and GL_LINEAR_MIPMAP_LINEAR at lambda log2(3);
 *   the texture matrix stack (glMatrixMode(GL_TEXTURE)) rotating and scaling a texture. */
#include <GL/glut.h>

static GLuint pattern, mipmapped;

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, w, 0, h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void make_textures(void) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  GLubyte small[8 * 8 * 3];
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      GLubyte* t = &small[(j * 8 + i) * 3];
      t[0] = (GLubyte)(i * 32 + 16);
      t[1] = (GLubyte)(j * 32 + 16);
      t[2] = (GLubyte)((i + j) % 2 ? 255 : 0);
    }
  glGenTextures(1, &pattern);
  glBindTexture(GL_TEXTURE_2D, pattern);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, small);
  const GLfloat border[4] = {1.0f, 0.0f, 0.8f, 1.0f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);

  static const GLubyte level_colour[6][3] = {{230, 70, 60},  {60, 200, 70},  {70, 80, 230},
                                             {220, 220, 60}, {220, 60, 220}, {60, 220, 220}};
  static GLubyte texels[32 * 32 * 3];
  glGenTextures(1, &mipmapped);
  glBindTexture(GL_TEXTURE_2D, mipmapped);
  for (int level = 0, size = 32; size >= 1; ++level, size /= 2) {
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const float shade = (i + j) % 2 ? 1.0f : 0.55f;
        for (int c = 0; c < 3; ++c)
          texels[(j * size + i) * 3 + c] = (GLubyte)(level_colour[level][c] * shade);
      }
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGB, size, size, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

static void quad(int x, int y, int size, float s0, float s1) {
  glBegin(GL_QUADS);
  glTexCoord2f(s0, s0);
  glVertex2i(x, y);
  glTexCoord2f(s1, s0);
  glVertex2i(x + size, y);
  glTexCoord2f(s1, s1);
  glVertex2i(x + size, y + size);
  glTexCoord2f(s0, s1);
  glVertex2i(x, y + size);
  glEnd();
}

static void use(GLuint tex, GLenum min, GLenum mag, GLenum wrap) {
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)min);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)mag);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)wrap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)wrap);
}

static void display(void) {
  glClearColor(0.12f, 0.12f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  /* Top row: magnification and wrap modes. */
  use(pattern, GL_NEAREST, GL_NEAREST, GL_REPEAT);
  quad(6, 162, 72, 0.0f, 1.0f);
  use(pattern, GL_LINEAR, GL_LINEAR, GL_REPEAT);
  quad(84, 162, 72, 0.0f, 1.0f);
  use(pattern, GL_LINEAR, GL_LINEAR, GL_CLAMP);
  quad(162, 166, 64, -0.5f, 1.5f);
  use(pattern, GL_NEAREST, GL_NEAREST, GL_CLAMP);
  quad(238, 166, 64, -0.5f, 1.5f);

  /* Middle row: minification without and with mipmaps. */
  use(mipmapped, GL_NEAREST, GL_NEAREST, GL_REPEAT);
  quad(6, 90, 64, 0.0f, 5.0f); /* 2.5 texels per pixel */
  use(mipmapped, GL_LINEAR, GL_LINEAR, GL_REPEAT);
  quad(84, 90, 64, 0.0f, 5.0f);
  use(mipmapped, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, GL_REPEAT);
  quad(162, 90, 64, 0.0f, 8.0f); /* 4 texels per pixel: lambda = 2 */
  use(mipmapped, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, GL_REPEAT);
  quad(238, 90, 64, 0.0f, 4.0f); /* lambda = 1 */

  /* Bottom row: blending between levels, and the texture matrix. */
  use(mipmapped, GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST, GL_REPEAT);
  quad(6, 12, 64, 0.0f, 6.0f); /* 3 texels per pixel: lambda = log2(3) */
  use(mipmapped, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
  quad(84, 12, 64, 0.0f, 6.0f);
  use(pattern, GL_LINEAR, GL_LINEAR, GL_REPEAT);
  glMatrixMode(GL_TEXTURE);
  glPushMatrix();
  glLoadIdentity();
  glTranslatef(0.5f, 0.5f, 0.0f);
  glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
  glScalef(1.5f, 1.5f, 1.0f);
  glTranslatef(-0.5f, -0.5f, 0.0f);
  glMatrixMode(GL_MODELVIEW);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2i(162, 12);
  glTexCoord2f(1, 0);
  glVertex2i(310, 12);
  glTexCoord2f(1, 1);
  glVertex2i(310, 76);
  glTexCoord2f(0, 1);
  glVertex2i(162, 76);
  glEnd();
  glMatrixMode(GL_TEXTURE);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);

  glDisable(GL_TEXTURE_2D);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(320, 240);
  glutCreateWindow("14 texture filters and mipmaps");
  glDisable(GL_DITHER);
  make_textures();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
