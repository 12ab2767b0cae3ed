/* 35_feedback: glRenderMode(GL_FEEDBACK) with glFeedbackBuffer(GL_3D_COLOR) and
 * glPassThrough. A lit, perspective scene (a triangle crossing the near plane, a quad partly
 * outside the view, a line strip, points, a culled back face) is fed back instead of drawn;
 * the program then draws what came back: each polygon outlined from its clipped vertices in
 * their fed-back colours, each line, each point as a square, and a marker per pass-through
 * token. The picture is made only from the feedback buffer. */
#include <GL/glut.h>

static const int W = 320, H = 240;
static GLfloat buffer[4096];

static void scene(void) {
  glPassThrough(1.0f);
  glBegin(GL_TRIANGLES); /* crosses the near plane: clipped into a quadrilateral */
  glColor3f(1, 0.3f, 0.2f);
  glVertex3f(-2.5f, -1.5f, -2);
  glColor3f(0.2f, 1, 0.3f);
  glVertex3f(-0.5f, -1.5f, 0.5f);
  glColor3f(0.3f, 0.3f, 1);
  glVertex3f(-1.5f, 1.0f, -4);
  glEnd();
  glPassThrough(2.0f);
  glBegin(GL_QUADS); /* partly outside on the right */
  glColor3f(1, 1, 0.2f);
  glVertex3f(0.5f, -1, -5);
  glVertex3f(4.5f, -1, -5);
  glColor3f(0.2f, 1, 1);
  glVertex3f(4.5f, 1, -5);
  glVertex3f(0.5f, 1, -5);
  glEnd();
  glBegin(GL_QUADS); /* clockwise: culled */
  glVertex3f(-1, 1.2f, -4);
  glVertex3f(-1, 2, -4);
  glVertex3f(1, 2, -4);
  glVertex3f(1, 1.2f, -4);
  glEnd();
  glPassThrough(3.0f);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i < 6; ++i) {
    glColor3f(0.2f * i, 0.5f, 1 - 0.15f * i);
    glVertex3f(-2 + 0.8f * i, (i % 2) ? -2.0f : -1.4f, -5);
  }
  glEnd();
  glBegin(GL_POINTS);
  for (int i = 0; i < 5; ++i) {
    glColor3f(1, 0.5f + 0.1f * i, 1);
    glVertex3f(-2 + i, 1.6f, -6);
  }
  glVertex3f(0, 0, 5); /* behind the eye: clipped */
  glEnd();
}

static void display(void) {
  glClearColor(0.1f, 0.1f, 0.12f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60, (double)W / H, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_CULL_FACE);
  glShadeModel(GL_SMOOTH);
  glFeedbackBuffer(4096, GL_3D_COLOR, buffer);
  glRenderMode(GL_FEEDBACK);
  scene();
  const GLint n = glRenderMode(GL_RENDER);
  glDisable(GL_CULL_FACE);

  /* Draw what came back, in window coordinates. */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, W, 0, H);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  int passes = 0;
  for (GLint i = 0; i < n;) {
    const int token = (int)buffer[i++];
    if (token == GL_PASS_THROUGH_TOKEN) {
      glColor3f(1, 1, 1);
      glRectf(8.0f + 12 * passes, 8, 16.0f + 12 * passes, 8.0f + 8 * buffer[i]);
      ++passes;
      i += 1;
    } else if (token == GL_POLYGON_TOKEN) {
      const int count = (int)buffer[i++];
      glBegin(GL_LINE_LOOP);
      for (int k = 0; k < count; ++k, i += 7) {
        glColor3f(buffer[i + 3], buffer[i + 4], buffer[i + 5]);
        glVertex2f(buffer[i], buffer[i + 1]);
      }
      glEnd();
    } else if (token == GL_LINE_TOKEN || token == GL_LINE_RESET_TOKEN) {
      glBegin(GL_LINES);
      for (int k = 0; k < 2; ++k, i += 7) {
        glColor3f(buffer[i + 3], buffer[i + 4], buffer[i + 5]);
        glVertex2f(buffer[i], buffer[i + 1]);
      }
      glEnd();
      if (token == GL_LINE_RESET_TOKEN) {
        glColor3f(1, 0, 0);
        glRectf(buffer[i - 14] - 3, buffer[i - 13] - 3, buffer[i - 14] + 3, buffer[i - 13] + 3);
      }
    } else if (token == GL_POINT_TOKEN) {
      glColor3f(buffer[i + 3], buffer[i + 4], buffer[i + 5]);
      glRectf(buffer[i] - 3, buffer[i + 1] - 3, buffer[i] + 3, buffer[i + 1] + 3);
      i += 7;
    } else {
      break; /* unexpected: stop */
    }
  }
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(W, H);
  glutCreateWindow("35 feedback");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
