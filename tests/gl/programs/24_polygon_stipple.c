/* 24_polygon_stipple: glEnable(GL_POLYGON_STIPPLE) with three 32x32 patterns set by
 * glPolygonStipple: a checkerboard of 4x4 blocks, diagonal stripes, and a bullseye uploaded
 * with GL_UNPACK_LSB_FIRST (bit order reversed). The pattern is fixed to window
 * coordinates: the shapes (a rectangle, smooth triangles, a polygon, a quad strip) sit at
 * arbitrary offsets and overlap. Single-buffered (glFlush). */
#include <GL/glut.h>
#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

static GLubyte checker[128], stripes[128], bullseye[128];

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, w, 0, h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* Bit (x, y) of a pattern stored most significant bit first. */
static void set_bit(GLubyte* p, int x, int y, int msb_first) {
  p[y * 4 + x / 8] |= (GLubyte)(msb_first ? 0x80 >> (x % 8) : 1 << (x % 8));
}

static void make_patterns(void) {
  memset(checker, 0, sizeof checker);
  memset(stripes, 0, sizeof stripes);
  memset(bullseye, 0, sizeof bullseye);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      if ((x / 4 + y / 4) % 2) set_bit(checker, x, y, 1);
      if ((x + y) % 8 < 3) set_bit(stripes, x, y, 1);
      const double d = sqrt((x - 11.5) * (x - 11.5) + (y - 15.5) * (y - 15.5)); /* off-centre */
      if ((int)d % 6 < 3) set_bit(bullseye, x, y, 0);
    }
}

static void display(void) {
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_POLYGON_STIPPLE);

  glPolygonStipple(checker);
  glColor3f(0.9f, 0.6f, 0.2f);
  glRecti(13, 117, 151, 231);
  glBegin(GL_TRIANGLES);
  glColor3f(0.2f, 0.9f, 0.3f);
  glVertex2f(90, 130);
  glColor3f(0.2f, 0.3f, 1.0f);
  glVertex2f(230, 150);
  glColor3f(1.0f, 1.0f, 1.0f);
  glVertex2f(160, 236);
  glEnd();

  glPolygonStipple(stripes);
  glBegin(GL_POLYGON);
  for (int i = 0; i < 7; ++i) {
    const double a = 2 * PI * i / 7;
    glColor3d(0.5 + 0.5 * cos(a), 0.3, 0.5 + 0.5 * sin(a));
    glVertex2d(255 + 60 * cos(a), 170 + 60 * sin(a));
  }
  glEnd();
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= 8; ++i) {
    glColor3f(0.9f, 0.9f - 0.1f * i, 0.1f * i);
    glVertex2f(7.0f + 19 * i, 8.0f + (i % 2) * 10);
    glVertex2f(7.0f + 19 * i, 100.0f - (i % 3) * 7);
  }
  glEnd();

  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPolygonStipple(bullseye);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glColor3f(0.4f, 0.8f, 1.0f);
  glRecti(170, 5, 313, 103);
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.3f, 0.6f);
  glVertex2f(120, 20);
  glColor3f(1.0f, 1.0f, 0.3f);
  glVertex2f(250, 60);
  glColor3f(0.5f, 0.2f, 1.0f);
  glVertex2f(140, 120);
  glEnd();

  glDisable(GL_POLYGON_STIPPLE);
  glFlush();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
  glutInitWindowSize(320, 240);
  glutCreateWindow("24 polygon stipple");
  glDisable(GL_DITHER);
  make_patterns();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
