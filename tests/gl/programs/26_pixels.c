/* 26_pixels: pixel rectangles and bitmaps.
 *  - glDrawPixels of a generated 37x29 RGB image (odd row length: GL_UNPACK_ALIGNMENT 1)
 *    at glRasterPos2i, then again with glPixelZoom(2, 2), and a GL_LUMINANCE image drawn
 *    with the default alignment of 4 (rows padded);
 *  - glReadPixels of a 61x47 part of a drawn scene (GL_PACK_ALIGNMENT 1, GL_RGB), inverted
 *    in memory and drawn back elsewhere; glCopyPixels of another part;
 *  - glBitmap: a 16x16 smiley drawn in a row (xmove advances the raster position; the raster
 *    colour is latched by glRasterPos), a 13-pixel-wide bitmap with rows padded to 4 bytes
 *    and an origin offset, and glBitmap(0, 0, 0, 0, dx, dy, NULL) used to move the raster
 *    position off the window's left edge so a glDrawPixels image is clipped there;
 *  - glRasterPos under a modelview translation and a GL_UNPACK_ROW_LENGTH/SKIP sub-image. */
#include <GL/glut.h>
#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

static GLubyte image[29][37][3];
static GLubyte lum[20 * 24]; /* 22 wide, rows padded to 24 */
static GLubyte smiley[16 * 2], narrow[11 * 4];

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, w, 0, h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void make_images(void) {
  for (int y = 0; y < 29; ++y)
    for (int x = 0; x < 37; ++x) {
      image[y][x][0] = (GLubyte)(x * 7);
      image[y][x][1] = (GLubyte)(y * 8);
      image[y][x][2] = (GLubyte)((x / 4 + y / 4) % 2 ? 255 : 60);
    }
  memset(lum, 0, sizeof lum);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 22; ++x) lum[y * 24 + x] = (GLubyte)((x + y) % 4 == 0 ? 255 : x * 10);
  static const char* face[16] = {
      "....XXXXXXXX....", "..XX........XX..", ".X............X.", "X..............X",
      "X...XX....XX...X", "X...XX....XX...X", "X..............X", "X..............X",
      "X..X........X..X", "X...X......X...X", "X....XXXXXX....X", "X..............X",
      ".X............X.", "..XX........XX..", "....XXXXXXXX....", "................"};
  for (int row = 0; row < 16; ++row) /* bitmaps are stored bottom row first */
    for (int x = 0; x < 16; ++x)
      if (face[15 - row][x] == 'X') smiley[row * 2 + x / 8] |= (GLubyte)(0x80 >> (x % 8));
  for (int row = 0; row < 11; ++row)
    for (int x = 0; x < 13; ++x)
      if ((x + row) % 3 == 0 || x == 0 || row == 0) narrow[row * 4 + x / 8] |= (GLubyte)(0x80 >> (x % 8));
}

static void scene(void) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0.2f, 0.2f);
  glVertex2i(10, 150);
  glColor3f(0.2f, 1, 0.2f);
  glVertex2i(110, 160);
  glColor3f(0.2f, 0.2f, 1);
  glVertex2i(50, 232);
  glEnd();
  glColor3f(1, 0.9f, 0.2f);
  glBegin(GL_TRIANGLE_FAN);
  glVertex2i(90, 200);
  for (int i = 0; i <= 20; ++i) glVertex2d(90 + 22 * cos(2 * PI * i / 20), 200 + 22 * sin(2 * PI * i / 20));
  glEnd();
}

static void display(void) {
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_DITHER);
  scene();

  /* Read back part of the scene, invert it, draw it back at the right. */
  static GLubyte readback[47 * 61 * 3];
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(30, 160, 61, 47, GL_RGB, GL_UNSIGNED_BYTE, readback);
  for (size_t i = 0; i < sizeof readback; ++i) readback[i] = (GLubyte)(255 - readback[i]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(125, 182);
  glDrawPixels(61, 47, GL_RGB, GL_UNSIGNED_BYTE, readback);

  /* Copy another part. */
  glRasterPos2i(195, 150);
  glCopyPixels(10, 150, 60, 50, GL_COLOR);

  /* The generated image, plain and zoomed. */
  glRasterPos2i(260, 195);
  glDrawPixels(37, 29, GL_RGB, GL_UNSIGNED_BYTE, image);
  glPixelZoom(2.0f, 2.0f);
  glRasterPos2i(8, 60);
  glDrawPixels(37, 29, GL_RGB, GL_UNSIGNED_BYTE, image);
  glPixelZoom(1.0f, 1.0f);

  /* Luminance with 4-byte row alignment. */
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glRasterPos2i(90, 100);
  glDrawPixels(22, 20, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);

  /* A sub-image: rows 5.. and columns 10.. of the generated image, 20x15. */
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 37);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 5);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 10);
  glPushMatrix();
  glTranslatef(120, 100, 0); /* the raster position is transformed like a vertex */
  glRasterPos2i(5, 4);
  glDrawPixels(20, 15, GL_RGB, GL_UNSIGNED_BYTE, image);
  glPopMatrix();
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);

  /* Bitmaps: the raster colour is the colour at glRasterPos time. */
  glColor3f(1.0f, 0.9f, 0.3f);
  glRasterPos2i(150, 70);
  glColor3f(0.0f, 0.0f, 1.0f); /* too late: does not change this row's colour */
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int i = 0; i < 8; ++i) glBitmap(16, 16, 0.0f, 0.0f, 20.0f, (float)(i % 2 ? -3 : 3), smiley);
  glColor3f(0.4f, 1.0f, 0.6f);
  glRasterPos2i(150, 40);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (int i = 0; i < 10; ++i) glBitmap(13, 11, 2.0f, 3.0f, 16.0f, 0.0f, narrow);

  /* Move the raster position off the left edge, then draw a clipped image. */
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(4, 8);
  glBitmap(0, 0, 0.0f, 0.0f, -20.0f, 0.0f, NULL);
  glDrawPixels(37, 29, GL_RGB, GL_UNSIGNED_BYTE, image);
  glColor3f(1.0f, 0.5f, 0.8f);
  glRasterPos2i(60, 10);
  glBitmap(0, 0, 0.0f, 0.0f, -70.0f, 0.0f, NULL);
  for (int i = 0; i < 12; ++i) glBitmap(16, 16, 0.0f, 0.0f, 18.0f, 0.0f, smiley);

  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(320, 240);
  glutCreateWindow("26 pixels and bitmaps");
  glDisable(GL_DITHER);
  make_images();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
