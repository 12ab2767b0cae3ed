/* 04_vertex_arrays: client vertex arrays.
 *  - an interleaved struct array (position, normal, ubyte colour, texcoord) with a stride,
 *    lit and textured, drawn with glDrawArrays(GL_TRIANGLE_STRIP) row by row;
 *  - a cube drawn with glDrawElements(GL_QUADS, GL_UNSIGNED_BYTE) from tightly packed
 *    GLdouble positions and GLfloat colours (glColorPointer(3, GL_FLOAT));
 *  - a disc drawn with glDrawElements(GL_TRIANGLES, GL_UNSIGNED_INT) from GLshort 2D
 *    positions with a stride and 4-component colours;
 *  - a grid of triangles via glDrawElements(GL_TRIANGLES, GL_UNSIGNED_SHORT) from
 *    homogeneous (w != 1) positions;
 *  - a star drawn with glArrayElement inside glBegin(GL_POLYGON)/glBegin(GL_LINE_LOOP). */
#include <GL/glut.h>
#include <math.h>
#include <stddef.h>

#define PI 3.14159265358979323846
#define GRID 12

struct Vertex {
  GLfloat pos[3];
  GLfloat normal[3];
  GLubyte colour[4];
  GLfloat uv[2];
  GLfloat pad; /* the stride is not a multiple of any element's size */
};

static struct Vertex surface[(GRID + 1) * (GRID + 1)];
static GLuint tex;

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.8 * w / h, 0.8 * w / h, -0.8, 0.8, 2.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void build(void) {
  for (int j = 0; j <= GRID; ++j)
    for (int i = 0; i <= GRID; ++i) {
      struct Vertex* v = &surface[j * (GRID + 1) + i];
      const float x = -1.0f + 2.0f * i / GRID, y = -1.0f + 2.0f * j / GRID;
      const float z = 0.25f * sinf(2.5f * x) * cosf(2.0f * y);
      const float dzdx = 0.25f * 2.5f * cosf(2.5f * x) * cosf(2.0f * y);
      const float dzdy = -0.25f * 2.0f * sinf(2.5f * x) * sinf(2.0f * y);
      const float len = sqrtf(dzdx * dzdx + dzdy * dzdy + 1.0f);
      v->pos[0] = x;
      v->pos[1] = y;
      v->pos[2] = z;
      v->normal[0] = -dzdx / len;
      v->normal[1] = -dzdy / len;
      v->normal[2] = 1.0f / len;
      v->colour[0] = (GLubyte)(255 * i / GRID);
      v->colour[1] = (GLubyte)(255 - 255 * j / GRID);
      v->colour[2] = 200;
      v->colour[3] = 255;
      v->uv[0] = 2.0f * i / GRID;
      v->uv[1] = 2.0f * j / GRID;
      v->pad = 0.0f;
    }
  GLubyte texels[8 * 8 * 3];
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      GLubyte* t = &texels[(j * 8 + i) * 3];
      const int on = (i + j) % 2;
      t[0] = on ? 255 : 90;
      t[1] = on ? 255 : 90;
      t[2] = on ? 255 : 160;
    }
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

static void draw_surface(void) {
  const GLsizei stride = sizeof(struct Vertex);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  /* A strip needs two rows interleaved: each row pair is copied into `strip` and drawn with
     glDrawArrays, the arrays pointing into the struct with its stride. */
  static struct Vertex strip[2 * (GRID + 1)];
  glVertexPointer(3, GL_FLOAT, stride, &strip[0].pos);
  glNormalPointer(GL_FLOAT, stride, &strip[0].normal);
  glColorPointer(4, GL_UNSIGNED_BYTE, stride, &strip[0].colour);
  glTexCoordPointer(2, GL_FLOAT, stride, &strip[0].uv);
  for (int j = 0; j < GRID; ++j) {
    for (int i = 0; i <= GRID; ++i) {
      strip[2 * i] = surface[(j + 1) * (GRID + 1) + i];
      strip[2 * i + 1] = surface[j * (GRID + 1) + i];
    }
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 2 * (GRID + 1));
  }
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

static void draw_cube(void) {
  static const GLdouble pos[8 * 3] = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                      -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
  static const GLfloat col[8 * 3] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  static const GLubyte quads[24] = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 2, 3, 7, 6, 1, 2, 6, 5, 0, 4, 7, 3};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_DOUBLE, 0, pos);
  glColorPointer(3, GL_FLOAT, 0, col);
  glDrawElements(GL_QUADS, 24, GL_UNSIGNED_BYTE, quads);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

static void draw_disc(void) {
  /* Positions as 2D shorts (scaled down by the modelview) interleaved with unused data. */
  static GLshort pos[(1 + 24) * 3];
  static GLfloat col[(1 + 24) * 4];
  static GLuint tris[24 * 3];
  pos[0] = 0;
  pos[1] = 0;
  col[0] = 1;
  col[1] = 1;
  col[2] = 1;
  col[3] = 1;
  for (int i = 0; i < 24; ++i) {
    const double a = 2 * PI * i / 24;
    pos[(i + 1) * 3 + 0] = (GLshort)lround(100 * cos(a));
    pos[(i + 1) * 3 + 1] = (GLshort)lround(100 * sin(a));
    pos[(i + 1) * 3 + 2] = 12345; /* skipped by the stride */
    col[(i + 1) * 4 + 0] = (GLfloat)(0.5 + 0.5 * cos(a));
    col[(i + 1) * 4 + 1] = (GLfloat)(0.5 + 0.5 * sin(a));
    col[(i + 1) * 4 + 2] = (GLfloat)(i % 2);
    col[(i + 1) * 4 + 3] = 1.0f;
    tris[i * 3 + 0] = 0;
    tris[i * 3 + 1] = (GLuint)(i + 1);
    tris[i * 3 + 2] = (GLuint)((i + 1) % 24 + 1);
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_SHORT, 3 * sizeof(GLshort), pos);
  glColorPointer(4, GL_FLOAT, 0, col);
  glDrawElements(GL_TRIANGLES, 24 * 3, GL_UNSIGNED_INT, tris);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

static void draw_grid(void) {
  /* 5 x 5 vertices in homogeneous form (x*w, y*w, 0, w), coloured with unsigned bytes. */
  static GLfloat pos[25 * 4];
  static GLubyte col[25 * 3];
  static GLushort tris[16 * 2 * 3];
  int n = 0;
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) {
      const float w = 1.0f + 0.25f * ((i + j) % 3);
      const int k = j * 5 + i;
      pos[k * 4 + 0] = (i - 2) * 0.5f * w;
      pos[k * 4 + 1] = (j - 2) * 0.5f * w;
      pos[k * 4 + 2] = 0.0f;
      pos[k * 4 + 3] = w;
      col[k * 3 + 0] = (GLubyte)(60 * i);
      col[k * 3 + 1] = (GLubyte)(60 * j);
      col[k * 3 + 2] = (GLubyte)(255 - 30 * (i + j));
    }
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      if ((i + j) % 4 == 3) continue; /* leave some holes */
      const GLushort a = (GLushort)(j * 5 + i), b = (GLushort)(a + 1), c = (GLushort)(a + 6),
                     d = (GLushort)(a + 5);
      tris[n++] = a;
      tris[n++] = b;
      tris[n++] = c;
      tris[n++] = a;
      tris[n++] = c;
      tris[n++] = d;
    }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(4, GL_FLOAT, 0, pos);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, col);
  glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_SHORT, tris);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

static void draw_star(void) {
  static GLfloat pos[10 * 2];
  static GLubyte col[10 * 4];
  for (int i = 0; i < 10; ++i) {
    const double a = 2 * PI * i / 10 + PI / 2;
    const double r = i % 2 ? 0.45 : 1.0;
    pos[i * 2 + 0] = (GLfloat)(r * cos(a));
    pos[i * 2 + 1] = (GLfloat)(r * sin(a));
    col[i * 4 + 0] = 255;
    col[i * 4 + 1] = (GLubyte)(i * 25);
    col[i * 4 + 2] = (GLubyte)(i % 2 ? 255 : 0);
    col[i * 4 + 3] = 255;
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, col);
  /* The star's inner pentagon is convex: fill it as a polygon of the odd elements ... */
  glBegin(GL_POLYGON);
  for (int i = 1; i < 10; i += 2) glArrayElement(i);
  glEnd();
  /* ... its five points as triangles, and the outline as a loop. */
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 10; i += 2) {
    glArrayElement((i + 9) % 10);
    glArrayElement(i + 1);
    glArrayElement(i);
  }
  glEnd();
  glDisableClientState(GL_COLOR_ARRAY);
  glColor3f(1, 1, 1);
  glBegin(GL_LINE_LOOP);
  for (int i = 0; i < 10; ++i) glArrayElement(i);
  glEnd();
  glDisableClientState(GL_VERTEX_ARRAY);
}

static void display(void) {
  glClearColor(0.05f, 0.05f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glLoadIdentity();

  /* The lit, textured surface (upper left). */
  glPushMatrix();
  glTranslatef(-1.35f, 0.55f, -6.0f);
  glRotatef(-50, 1, 0, 0);
  glRotatef(20, 0, 0, 1);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  draw_surface();
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_COLOR_MATERIAL);
  glDisable(GL_LIGHTING);
  glPopMatrix();

  /* The cube (upper right). */
  glPushMatrix();
  glTranslatef(1.45f, 0.7f, -6.0f);
  glRotatef(30, 1, 0, 0);
  glRotatef(40, 0, 1, 0);
  glScalef(0.6f, 0.6f, 0.6f);
  draw_cube();
  glPopMatrix();

  /* The disc (lower left), the grid (lower middle), the star (lower right). */
  glPushMatrix();
  glTranslatef(-1.9f, -0.95f, -6.0f);
  glScalef(0.0065f, 0.0065f, 1.0f);
  draw_disc();
  glPopMatrix();

  glPushMatrix();
  glTranslatef(0.05f, -0.95f, -6.0f);
  glRotatef(15, 0, 0, 1);
  glScalef(0.6f, 0.6f, 1.0f);
  draw_grid();
  glPopMatrix();

  glPushMatrix();
  glTranslatef(1.85f, -0.95f, -6.0f);
  glScalef(0.7f, 0.7f, 1.0f);
  draw_star();
  glPopMatrix();

  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(320, 240);
  glutCreateWindow("04 vertex arrays");
  glDisable(GL_DITHER);
  build();
  {
    const GLfloat light_pos[4] = {1.0f, 2.0f, 3.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  }
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
