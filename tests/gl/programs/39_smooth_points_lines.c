/* 39_smooth_points_lines: antialiased points, lines and polygons (GL 2.1 §3.4.2, §3.5.2,
 * §3.6.3) with blending, as the classic "antialiasing" examples draw them.
 * Left: GL_POINT_SMOOTH points of sizes 1 to 12 at fractional positions, in a row per size.
 * Middle: GL_LINE_SMOOTH lines of widths 1, 2.5 and 5 in a fan of angles, and a smooth line
 * strip of changing colour (GL_SMOOTH shading).
 * Right: a GL_POLYGON_SMOOTH triangle fan blended with GL_SRC_ALPHA_SATURATE, GL_ONE, as the Red
 * Book does (which draws nothing here: a GLUT_RGBA window has no alpha bits, so the
 * destination alpha is 1), and smooth points and lines without blending.
 * Blending is GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA over a dark background. */
#include <GL/glut.h>
#include <math.h>

static void display(void) {
  int i, k;
  glClearColor(0.1f, 0.1f, 0.15f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 320, 0, 240, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

  /* Points: twelve sizes, five each at fractional positions. */
  glEnable(GL_POINT_SMOOTH);
  glHint(GL_POINT_SMOOTH_HINT, GL_NICEST);
  for (i = 1; i <= 12; ++i) {
    glPointSize((GLfloat)i);
    glBegin(GL_POINTS);
    for (k = 0; k < 5; ++k) {
      glColor4f(1.0f, 0.3f + 0.05f * (GLfloat)i, 0.2f * (GLfloat)k, 1.0f);
      glVertex2f(8.0f + 20.0f * (GLfloat)k + 0.13f * (GLfloat)i,
                 6.0f + 19.0f * (GLfloat)(i - 1) + 0.37f * (GLfloat)k);
    }
    glEnd();
  }
  glDisable(GL_POINT_SMOOTH);

  /* Lines: three widths, a fan of eight angles each. */
  glEnable(GL_LINE_SMOOTH);
  glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
  for (i = 0; i < 3; ++i) {
    static const GLfloat widths[3] = {1.0f, 2.5f, 5.0f};
    const GLfloat cx = 150.0f, cy = 40.0f + 70.0f * (GLfloat)i;
    glLineWidth(widths[i]);
    glBegin(GL_LINES);
    for (k = 0; k < 8; ++k) {
      const GLfloat a = 0.05f + (GLfloat)k * 0.4f;
      glColor4f(0.3f + 0.08f * (GLfloat)k, 1.0f, 0.4f, 1.0f);
      glVertex2f(cx + 6.0f * cosf(a), cy + 6.0f * sinf(a));
      glVertex2f(cx + 32.0f * cosf(a), cy + 30.0f * sinf(a));
    }
    glEnd();
  }
  glLineWidth(1.5f);
  glBegin(GL_LINE_STRIP);
  for (k = 0; k <= 12; ++k) {
    glColor4f(1.0f - 0.07f * (GLfloat)k, 0.5f, 0.07f * (GLfloat)k, 1.0f);
    glVertex2f(200.0f + 4.0f * (GLfloat)k, 20.0f + 40.0f * sinf((GLfloat)k * 0.6f) + 40.0f);
  }
  glEnd();
  glDisable(GL_LINE_SMOOTH);
  glLineWidth(1.0f);

  /* A smooth polygon fan, saturate blending front to back. */
  glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE);
  glEnable(GL_POLYGON_SMOOTH);
  glBegin(GL_TRIANGLE_FAN);
  glColor4f(0.9f, 0.8f, 0.3f, 1.0f);
  glVertex2f(280.0f, 180.0f);
  for (k = 0; k <= 6; ++k) {
    const GLfloat a = (GLfloat)k * 0.9f;
    glColor4f(0.3f + 0.1f * (GLfloat)k, 0.4f, 0.9f - 0.1f * (GLfloat)k, 1.0f);
    glVertex2f(280.0f + 35.0f * cosf(a), 180.0f + 33.0f * sinf(a));
  }
  glEnd();
  glDisable(GL_POLYGON_SMOOTH);

  /* Smooth points and lines without blending: the coverage goes to alpha only. */
  glDisable(GL_BLEND);
  glEnable(GL_POINT_SMOOTH);
  glPointSize(7.0f);
  glBegin(GL_POINTS);
  glColor3f(0.9f, 0.9f, 0.9f);
  glVertex2f(250.3f, 60.6f);
  glVertex2f(270.5f, 60.5f);
  glEnd();
  glDisable(GL_POINT_SMOOTH);
  glEnable(GL_LINE_SMOOTH);
  glLineWidth(3.0f);
  glBegin(GL_LINES);
  glVertex2f(245.0f, 90.0f);
  glVertex2f(310.0f, 120.0f);
  glEnd();
  glDisable(GL_LINE_SMOOTH);
  glFlush();
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE);
  glutInitWindowSize(320, 240);
  glutCreateWindow("smooth points and lines");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
