/* 22_polygon_mode_offset: glPolygonMode and glPolygonOffset, three viewports.
 *  1. a sphere with glPolygonMode(GL_FRONT, GL_LINE) and (GL_BACK, GL_POINT), points of
 *     size 3 (no depth test: drawn in submission order);
 *  2. an open cup with GL_FRONT filled and GL_BACK as lines (the inside, seen through the
 *     opening, is wireframe), the fill pushed back with GL_POLYGON_OFFSET_FILL;
 *  3. wireframe over solid: a smooth-coloured torus filled with glPolygonOffset(1, 1), then
 *     its edges in GL_LINE mode in black. */
#include <GL/glut.h>
#include <math.h>

#define PI 3.14159265358979323846

static int win_w = 318, win_h = 150;

static void reshape(int w, int h) {
  win_w = w;
  win_h = h;
}

static void sphere(double r) {
  const int slices = 16, stacks = 10;
  for (int j = 0; j < stacks; ++j) {
    const double t0 = PI * j / stacks - PI / 2, t1 = PI * (j + 1) / stacks - PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= slices; ++i) {
      const double p = 2 * PI * i / slices;
      glColor3d(0.5 + 0.5 * sin(p), 0.6 + 0.4 * sin(t1), 0.9);
      glVertex3d(r * cos(t1) * sin(p), r * sin(t1), r * cos(t1) * cos(p));
      glColor3d(0.5 + 0.5 * sin(p), 0.6 + 0.4 * sin(t0), 0.9);
      glVertex3d(r * cos(t0) * sin(p), r * sin(t0), r * cos(t0) * cos(p));
    }
    glEnd();
  }
}

/* A cup: a truncated cone, open at the top, closed at the bottom; outside front-facing. */
static void cup(void) {
  const int n = 18;
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= n; ++i) {
    const double a = 2 * PI * i / n;
    glColor3d(0.9, 0.5 + 0.4 * cos(a), 0.2);
    glVertex3d(1.0 * cos(a), 0.9, -1.0 * sin(a));
    glColor3d(0.6, 0.3 + 0.3 * cos(a), 0.1);
    glVertex3d(0.6 * cos(a), -0.9, -0.6 * sin(a));
  }
  glEnd();
  glColor3f(0.5f, 0.5f, 0.55f);
  glBegin(GL_POLYGON);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * PI * i / n;
    glVertex3d(0.6 * cos(a), -0.9, 0.6 * sin(a));
  }
  glEnd();
}

static void torus(int coloured) {
  const int sides = 12, rings = 20;
  const double R = 0.75, r = 0.35;
  for (int i = 0; i < rings; ++i) {
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= sides; ++j)
      for (int k = 1; k >= 0; --k) {
        const double u = 2 * PI * (i + k) / rings, v = 2 * PI * j / sides;
        if (coloured) glColor3d(0.5 + 0.5 * cos(u), 0.5 + 0.5 * sin(u), 0.5 + 0.5 * cos(v));
        glVertex3d((R + r * cos(v)) * cos(u), (R + r * cos(v)) * sin(u), r * sin(v));
      }
    glEnd();
  }
}

static void view(int i) {
  const int cw = win_w / 3;
  glViewport(i * cw + 1, 1, cw - 2, win_h - 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double aspect = (double)(cw - 2) / (win_h - 2);
  glFrustum(-0.4 * aspect, 0.4 * aspect, -0.4, 0.4, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -3.4f);
}

static void display(void) {
  glClearColor(0.15f, 0.15f, 0.18f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  /* 1: front lines, back points. */
  view(0);
  glRotatef(30, 1, 0, 0);
  glRotatef(20, 0, 1, 0);
  glDisable(GL_DEPTH_TEST);
  glPointSize(3.0f);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  sphere(1.0);
  glPointSize(1.0f);

  /* 2: front filled, back lines, with the fill offset behind the lines. */
  view(1);
  glTranslatef(0, -0.15f, 0);
  glRotatef(45, 1, 0, 0);
  glRotatef(10, 0, 1, 0);
  glScalef(0.85f, 0.85f, 0.85f);
  glEnable(GL_DEPTH_TEST);
  glPolygonMode(GL_FRONT, GL_FILL);
  glPolygonMode(GL_BACK, GL_LINE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  cup();
  glDisable(GL_POLYGON_OFFSET_FILL);

  /* 3: wireframe over solid. */
  view(2);
  glRotatef(-50, 1, 0, 0);
  glRotatef(15, 0, 1, 0);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  torus(1);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glColor3f(0, 0, 0);
  torus(0);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(win_w, win_h);
  glutCreateWindow("22 polygon mode and offset");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
