/* 31_glut_text: GLUT text. glutBitmapCharacter with GLUT_BITMAP_8_BY_13, GLUT_BITMAP_9_BY_15,
 * GLUT_BITMAP_HELVETICA_12 and GLUT_BITMAP_TIMES_ROMAN_24 (placed with glRasterPos2i; one line
 * right-aligned with glutBitmapWidth; the raster colour is latched by glRasterPos), and
 * glutStrokeCharacter with GLUT_STROKE_ROMAN (scaled, rotated, centred with glutStrokeWidth)
 * and GLUT_STROKE_MONO_ROMAN. */
#include <GL/glut.h>

static int win_w = 320, win_h = 240;

static void reshape(int w, int h) {
  win_w = w;
  win_h = h;
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, w, 0, h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void bitmap_text(void* font, int x, int y, const char* s) {
  glRasterPos2i(x, y);
  for (; *s; ++s) glutBitmapCharacter(font, *s);
}

static int bitmap_width(void* font, const char* s) {
  int w = 0;
  for (; *s; ++s) w += glutBitmapWidth(font, *s);
  return w;
}

static void stroke_text(void* font, const char* s) {
  for (; *s; ++s) glutStrokeCharacter(font, *s);
}

static float stroke_width(void* font, const char* s) {
  float w = 0;
  for (; *s; ++s) w += (float)glutStrokeWidth(font, *s);
  return w;
}

static void display(void) {
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glLoadIdentity();

  /* A bar behind the first lines, so the bitmaps' transparent pixels show. */
  glColor3f(0.25f, 0.2f, 0.35f);
  glRecti(0, 190, win_w, 240);

  glColor3f(1.0f, 1.0f, 1.0f);
  bitmap_text(GLUT_BITMAP_8_BY_13, 4, 226, "8x13: The quick brown fox {0123}");
  glColor3f(0.4f, 1.0f, 0.5f);
  bitmap_text(GLUT_BITMAP_9_BY_15, 4, 208, "9x15: jumps over @#$%&*");
  glColor3f(1.0f, 0.8f, 0.3f);
  {
    const char* s = "Helvetica 12: right-aligned, 1234567890";
    bitmap_text(GLUT_BITMAP_HELVETICA_12, win_w - 4 - bitmap_width(GLUT_BITMAP_HELVETICA_12, s), 194, s);
  }
  glColor3f(0.5f, 0.8f, 1.0f);
  bitmap_text(GLUT_BITMAP_TIMES_ROMAN_24, 6, 164, "Times Roman 24 Qgy!");

  /* Stroke text: the Roman font is about 119 units tall; scale to ~36 pixels and centre. */
  glColor3f(1.0f, 0.6f, 0.6f);
  glPushMatrix();
  {
    const char* s = "Tessel GL";
    const float scale = 0.3f;
    glTranslatef((win_w - stroke_width(GLUT_STROKE_ROMAN, s) * scale) / 2.0f, 104.0f, 0.0f);
    glScalef(scale, scale, 1.0f);
    stroke_text(GLUT_STROKE_ROMAN, s);
  }
  glPopMatrix();

  glColor3f(0.7f, 0.7f, 1.0f);
  glPushMatrix();
  glTranslatef(16.0f, 14.0f, 0.0f);
  glRotatef(8.0f, 0.0f, 0.0f, 1.0f);
  glScalef(0.2f, 0.3f, 1.0f);
  stroke_text(GLUT_STROKE_ROMAN, "abc xyz 42");
  glPopMatrix();

  glColor3f(0.9f, 0.9f, 0.4f);
  glPushMatrix();
  glTranslatef(190.0f, 60.0f, 0.0f);
  glScalef(0.14f, 0.16f, 1.0f);
  stroke_text(GLUT_STROKE_MONO_ROMAN, "MONO 1.0");
  glPopMatrix();

  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(win_w, win_h);
  glutCreateWindow("31 GLUT text");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
