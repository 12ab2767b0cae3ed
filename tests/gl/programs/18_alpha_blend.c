/* 18_alpha_blend: the alpha test and blending.
 * Top row: a 16x16 RGBA texture (a ring-shaped alpha pattern, nearest-filtered at 4x so
 * alpha values are exact texel values) drawn with glAlphaFunc GL_GREATER 0.5, GL_LESS 0.5,
 * GL_GEQUAL 0.25 and GL_LEQUAL 0.75 over a striped background.
 * Bottom rows: overlapping discs with glBlendFunc (SRC_ALPHA, ONE_MINUS_SRC_ALPHA),
 * (ONE, ONE), (SRC_ALPHA, ONE), (DST_COLOR, ZERO), (ONE_MINUS_DST_COLOR, ZERO) and
 * (ZERO, ONE_MINUS_SRC_COLOR), each over a colour gradient. */
#include <GL/glut.h>
#include <math.h>

#define PI 3.14159265358979323846

static GLuint ring;

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, w, 0, h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void make_texture(void) {
  GLubyte t[16 * 16 * 4];
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      const double dx = i - 7.5, dy = j - 7.5, d = sqrt(dx * dx + dy * dy);
      GLubyte* p = &t[(j * 16 + i) * 4];
      p[0] = (GLubyte)(255 - i * 12);
      p[1] = (GLubyte)(80 + j * 10);
      p[2] = (GLubyte)(120 + i * 8);
      const double a = 1.0 - fabs(d - 4.5) / 4.5; /* 1 on the ring of radius 4.5 */
      p[3] = (GLubyte)(a < 0 ? 0 : 255 * a);
    }
  glGenTextures(1, &ring);
  glBindTexture(GL_TEXTURE_2D, ring);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

static void disc(double cx, double cy, double r, float red, float green, float blue, float alpha) {
  glColor4f(red, green, blue, alpha);
  glBegin(GL_TRIANGLE_FAN);
  glVertex2d(cx, cy);
  for (int i = 0; i <= 32; ++i) {
    const double a = 2 * PI * i / 32;
    glVertex2d(cx + r * cos(a), cy + r * sin(a));
  }
  glEnd();
}

static void gradient(int x, int y, int w, int h) {
  glBegin(GL_QUADS);
  glColor3f(0.1f, 0.1f, 0.4f);
  glVertex2i(x, y);
  glColor3f(0.9f, 0.3f, 0.2f);
  glVertex2i(x + w, y);
  glColor3f(0.9f, 0.9f, 0.4f);
  glVertex2i(x + w, y + h);
  glColor3f(0.2f, 0.7f, 0.6f);
  glVertex2i(x, y + h);
  glEnd();
}

static void display(void) {
  glClearColor(0.15f, 0.15f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  /* Alpha test. */
  for (int x = 0; x < 320; x += 8) {
    glColor3f(0.3f, 0.3f, 0.35f);
    glRecti(x, 164, x + 4, 240);
  }
  static const GLenum funcs[4] = {GL_GREATER, GL_LESS, GL_GEQUAL, GL_LEQUAL};
  static const GLfloat refs[4] = {0.5f, 0.5f, 0.25f, 0.75f};
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, ring);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_ALPHA_TEST);
  for (int i = 0; i < 4; ++i) {
    glAlphaFunc(funcs[i], refs[i]);
    const int x = 8 + 80 * i, y = 170;
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2i(x, y);
    glTexCoord2f(1, 0);
    glVertex2i(x + 64, y);
    glTexCoord2f(1, 1);
    glVertex2i(x + 64, y + 64);
    glTexCoord2f(0, 1);
    glVertex2i(x, y + 64);
    glEnd();
  }
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_TEXTURE_2D);

  /* Blending. */
  static const GLenum blend[6][2] = {{GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA},
                                     {GL_ONE, GL_ONE},
                                     {GL_SRC_ALPHA, GL_ONE},
                                     {GL_DST_COLOR, GL_ZERO},
                                     {GL_ONE_MINUS_DST_COLOR, GL_ZERO},
                                     {GL_ZERO, GL_ONE_MINUS_SRC_COLOR}};
  for (int i = 0; i < 6; ++i) {
    const int x = 4 + 106 * (i % 3), y = 84 - 82 * (i / 3);
    gradient(x, y, 100, 78);
    glEnable(GL_BLEND);
    glBlendFunc(blend[i][0], blend[i][1]);
    disc(x + 36, y + 46, 26, 1.0f, 0.2f, 0.2f, 0.6f);
    disc(x + 64, y + 46, 26, 0.2f, 1.0f, 0.2f, 0.5f);
    disc(x + 50, y + 24, 26, 0.2f, 0.3f, 1.0f, 0.75f);
    glDisable(GL_BLEND);
  }
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(320, 240);
  glutCreateWindow("18 alpha test and blending");
  glDisable(GL_DITHER);
  make_texture();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
