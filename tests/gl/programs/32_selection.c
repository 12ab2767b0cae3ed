/* 32_selection: picking with glRenderMode(GL_SELECT), glSelectBuffer, the name stack
 * (glInitNames, glPushName, glLoadName, glPopName) and gluPickMatrix. A perspective scene
 * of named objects — overlapping quads at different depths, a triangle, a line, points, a
 * back-facing quad that culling removes, and an object behind the far plane — is drawn, then
 * picked at a 12 x 8 grid of points; each pick draws a marker whose colour says which name
 * is nearest (smallest z min of the hit records) and whose size says how many hits there were. */
#include <GL/glut.h>

static const int W = 320, H = 240;

static void projection(void) { gluPerspective(50.0, (double)W / H, 1.0, 20.0); }

static void scene(void) {
  glLoadName(1); /* a large quad at z = -8 */
  glColor3f(0.2f, 0.3f, 0.8f);
  glBegin(GL_QUADS);
  glVertex3f(-4, -2.5f, -8);
  glVertex3f(1, -2.5f, -8);
  glVertex3f(1, 2.5f, -8);
  glVertex3f(-4, 2.5f, -8);
  glEnd();
  glLoadName(2); /* a nearer quad overlapping it */
  glColor3f(0.8f, 0.3f, 0.2f);
  glBegin(GL_QUADS);
  glVertex3f(-1.5f, -1.5f, -5);
  glVertex3f(1.5f, -1.5f, -5);
  glVertex3f(1.5f, 1, -5);
  glVertex3f(-1.5f, 1, -5);
  glEnd();
  glLoadName(3); /* a tilted triangle crossing both */
  glColor3f(0.2f, 0.8f, 0.3f);
  glBegin(GL_TRIANGLES);
  glVertex3f(0.5f, -2, -4);
  glVertex3f(3.5f, -1, -9);
  glVertex3f(2, 2.5f, -6);
  glEnd();
  glLoadName(4); /* a line */
  glColor3f(1, 1, 0.3f);
  glBegin(GL_LINES);
  glVertex3f(-3.5f, -2.2f, -6);
  glVertex3f(3.5f, 2.2f, -7);
  glEnd();
  glLoadName(5); /* points */
  glPointSize(5);
  glColor3f(1, 0.5f, 1);
  glBegin(GL_POINTS);
  for (int i = 0; i < 6; ++i) glVertex3f(-3.0f + 1.2f * i, 2.0f, -6.5f);
  glEnd();
  glLoadName(6); /* back-facing (clockwise): culled, never a hit */
  glColor3f(1, 1, 1);
  glBegin(GL_QUADS);
  glVertex3f(-3.5f, -2.6f, -4.5f);
  glVertex3f(-3.5f, -0.5f, -4.5f);
  glVertex3f(-1.8f, -0.5f, -4.5f);
  glVertex3f(-1.8f, -2.6f, -4.5f);
  glEnd();
  glPushName(7); /* beyond the far plane: clipped away */
  glBegin(GL_QUADS);
  glVertex3f(-5, -5, -30);
  glVertex3f(5, -5, -30);
  glVertex3f(5, 5, -30);
  glVertex3f(-5, 5, -30);
  glEnd();
  glPopName();
}

static void display(void) {
  static const GLfloat palette[8][3] = {{0.3f, 0.3f, 0.3f}, {0.3f, 0.5f, 1}, {1, 0.4f, 0.3f}, {0.3f, 1, 0.4f},
                                        {1, 1, 0.4f},       {1, 0.6f, 1},    {1, 1, 1},       {0, 0, 0}};
  GLint viewport[4];
  glClearColor(0.08f, 0.08f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glGetIntegerv(GL_VIEWPORT, viewport);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  projection();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glInitNames(); /* ignored in render mode */
  glPushName(0);
  scene();

  /* Pick at a grid of points. */
  for (int gy = 0; gy < 8; ++gy)
    for (int gx = 0; gx < 12; ++gx) {
      const double px = 12 + gx * 27, py = 12 + gy * 30;
      GLuint buffer[512];
      glSelectBuffer(512, buffer);
      glRenderMode(GL_SELECT);
      glInitNames();
      glPushName(0);
      glMatrixMode(GL_PROJECTION);
      glPushMatrix();
      glLoadIdentity();
      gluPickMatrix(px, py, 6, 6, viewport);
      projection();
      glMatrixMode(GL_MODELVIEW);
      scene();
      glMatrixMode(GL_PROJECTION);
      glPopMatrix();
      glMatrixMode(GL_MODELVIEW);
      const GLint hits = glRenderMode(GL_RENDER);
      GLuint nearest = 0, zmin = 0xFFFFFFFFu;
      const GLuint* p = buffer;
      for (GLint h = 0; h < hits; ++h) {
        const GLuint n = p[0];
        if (p[1] <= zmin && n > 0) {
          zmin = p[1];
          nearest = p[3 + n - 1];
        }
        p += 3 + n;
      }
      /* The marker, drawn in window coordinates on top. */
      glMatrixMode(GL_PROJECTION);
      glPushMatrix();
      glLoadIdentity();
      gluOrtho2D(0, W, 0, H);
      glMatrixMode(GL_MODELVIEW);
      glPushMatrix();
      glLoadIdentity();
      glDisable(GL_DEPTH_TEST);
      const float r = 2.0f + 2.0f * (float)(hits < 0 ? 0 : hits);
      glColor3f(0, 0, 0);
      glRectf((float)px - r - 1, (float)py - r - 1, (float)px + r + 1, (float)py + r + 1);
      glColor3fv(palette[nearest & 7]);
      glRectf((float)px - r, (float)py - r, (float)px + r, (float)py + r);
      glEnable(GL_DEPTH_TEST);
      glPopMatrix();
      glMatrixMode(GL_PROJECTION);
      glPopMatrix();
      glMatrixMode(GL_MODELVIEW);
    }
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(W, H);
  glutCreateWindow("32 selection");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
