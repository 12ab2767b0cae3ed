/* 38_glu_3d_mipmaps: gluBuild3DMipmaps and gluBuild3DMipmapLevels (GLU 1.3 §3.2).
 * Left: a 10x6x7 RGB volume (not a power of two: GLU scales it to 8x8x8 first) built into
 * every level, shown as slices r = 0.1 .. 0.9 at sizes on screen that make the mipmap filter
 * pick levels 0 to 3 (GL_NEAREST_MIPMAP_NEAREST at the top, GL_LINEAR_MIPMAP_LINEAR below).
 * Right: an 8x8x16 luminance-alpha volume of GL_UNSIGNED_SHORT built with
 * gluBuild3DMipmapLevels into levels 1..3 of the range 1..5 (base level 1), read with skip
 * rows, skip pixels and skip images, blended over a grid.
 * (The reference GLU uploads the first level with the row length and image height reset, and
 * leaves a level whose depth reaches 1 before its width and height unwritten: the volumes here
 * stay clear of both.) glTexImage3D is GL 1.2: the program asks for it through GL/glext.h. */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h> /* before GL/glext.h, which needs its types */
#include <GL/glext.h>
#include <GL/glut.h>

static GLuint tex[2];

/* Five slices of the bound volume; a fraction of a pixel off the lattice, so that no texel
 * boundary falls exactly on a pixel centre (where the choice of texel is a tie). */
static void slices(GLfloat x0, GLfloat y0, GLfloat size) {
  int i;
  x0 += 0.3f;
  y0 += 0.2f;
  for (i = 0; i < 5; ++i) {
    const GLfloat r = 0.1f + 0.2f * (GLfloat)i;
    const GLfloat x = x0 + (GLfloat)i * (size + 2.0f);
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, r);
    glVertex2f(x, y0);
    glTexCoord3f(1, 0, r);
    glVertex2f(x + size, y0);
    glTexCoord3f(1, 1, r);
    glVertex2f(x + size, y0 + size);
    glTexCoord3f(0, 1, r);
    glVertex2f(x, y0 + size);
    glEnd();
  }
}

static void make_textures(void) {
  static GLubyte rgb[7][6][10][3];
  static GLushort la[17][11][11][2]; /* 8x8x16 after 1 image, 2 rows and 3 pixels skipped */
  int x, y, z;
  for (z = 0; z < 7; ++z)
    for (y = 0; y < 6; ++y)
      for (x = 0; x < 10; ++x) {
        rgb[z][y][x][0] = (GLubyte)(25 * x + 7);
        rgb[z][y][x][1] = (GLubyte)(((x + y + z) & 1) ? 230 : 20 + 40 * y);
        rgb[z][y][x][2] = (GLubyte)(40 * z + 3 * x);
      }
  for (z = 0; z < 17; ++z)
    for (y = 0; y < 11; ++y)
      for (x = 0; x < 11; ++x) {
        la[z][y][x][0] = (GLushort)(6000 * (x % 11) + 999 * z);
        la[z][y][x][1] = (GLushort)(((x / 2 + y + z) % 3) * 30000 + 5000);
      }
  glGenTextures(2, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_3D, tex[0]);
  if (gluBuild3DMipmaps(GL_TEXTURE_3D, GL_RGB8, 10, 6, 7, GL_RGB, GL_UNSIGNED_BYTE, rgb) != 0)
    glClearColor(1, 0, 0, 1); /* a failure shows as a red background */
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);

  glBindTexture(GL_TEXTURE_3D, tex[1]);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
  if (gluBuild3DMipmapLevels(GL_TEXTURE_3D, GL_LUMINANCE8_ALPHA8, 8, 8, 16, GL_LUMINANCE_ALPHA,
                             GL_UNSIGNED_SHORT, 1, 1, 3, la) != 0)
    glClearColor(1, 0, 0, 1);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_BASE_LEVEL, 1);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, 3);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

static void display(void) {
  int x, y;
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 320, 0, 240, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_TEXTURE_3D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  glBindTexture(GL_TEXTURE_3D, tex[0]);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  slices(4, 180, 24);   /* about level 0 */
  slices(4, 150, 7);    /* level 1 */
  slices(4, 130, 3.3f); /* level 2 */
  slices(4, 120, 1.5f); /* level 3 */
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  slices(4, 60, 24);
  slices(4, 30, 5);
  slices(4, 10, 2.7f);

  /* A grid, then the luminance-alpha volume blended over it. */
  glDisable(GL_TEXTURE_3D);
  glBegin(GL_QUADS);
  for (y = 0; y < 12; ++y)
    for (x = 0; x < 8; ++x) {
      const GLfloat g = ((x + y) & 1) ? 0.8f : 0.3f;
      glColor3f(g, 0.5f * g, 0.2f);
      glVertex2f(160.0f + 20.0f * (GLfloat)x, 20.0f * (GLfloat)y);
      glVertex2f(180.0f + 20.0f * (GLfloat)x, 20.0f * (GLfloat)y);
      glVertex2f(180.0f + 20.0f * (GLfloat)x, 20.0f + 20.0f * (GLfloat)y);
      glVertex2f(160.0f + 20.0f * (GLfloat)x, 20.0f + 20.0f * (GLfloat)y);
    }
  glEnd();
  glColor3f(1, 1, 1);
  glEnable(GL_TEXTURE_3D);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBindTexture(GL_TEXTURE_3D, tex[1]);
  slices(165, 170, 27); /* level 1 */
  slices(165, 120, 11); /* level 2 */
  slices(165, 90, 5);   /* level 3 */
  glDisable(GL_BLEND);
  glDisable(GL_TEXTURE_3D);
  glFlush();
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE);
  glutInitWindowSize(320, 240);
  glutCreateWindow("gluBuild3DMipmaps");
  glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
  make_textures();
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
