/* 02_vertex_color_forms: every glVertex{2,3,4}{s,i,f,d}[v] form and every
 * glColor{3,4}{b,s,i,f,d,ub,us,ui}[v] form, one cell each (8 x 7 cells of 40 x 34 pixels).
 * Vertex cells: a skewed quad given through one form (4-forms use w = 2).
 * Colour cells: a quad whose four corners get four colours through one form; blending with
 * SRC_ALPHA / ONE_MINUS_SRC_ALPHA over a striped background makes the 4-forms' alpha visible. */
#include <GL/glut.h>

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, w, 0, h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* One vertex at integer window position (x, y) through vertex form `kind` (0..23). */
static void vertex(int kind, int x, int y) {
  const int v = kind >= 12;
  const int k = kind % 12;
  const int size = 2 + k / 4;      /* 2, 3, 4 */
  const int m = size == 4 ? 2 : 1; /* w = 2 for the 4-forms: homogeneous coordinates */
  GLshort sv[4] = {(GLshort)(x * m), (GLshort)(y * m), (GLshort)(0 * m), (GLshort)m};
  GLint iv[4] = {x * m, y * m, 0, m};
  GLfloat fv[4] = {(GLfloat)(x * m), (GLfloat)(y * m), 0.25f * m, (GLfloat)m};
  GLdouble dv[4] = {x * m, y * m, -0.25 * m, m};
  switch (k) {
    case 0:
      if (v)
        glVertex2sv(sv);
      else
        glVertex2s(sv[0], sv[1]);
      break;
    case 1:
      if (v)
        glVertex2iv(iv);
      else
        glVertex2i(iv[0], iv[1]);
      break;
    case 2:
      if (v)
        glVertex2fv(fv);
      else
        glVertex2f(fv[0], fv[1]);
      break;
    case 3:
      if (v)
        glVertex2dv(dv);
      else
        glVertex2d(dv[0], dv[1]);
      break;
    case 4:
      if (v)
        glVertex3sv(sv);
      else
        glVertex3s(sv[0], sv[1], sv[2]);
      break;
    case 5:
      if (v)
        glVertex3iv(iv);
      else
        glVertex3i(iv[0], iv[1], iv[2]);
      break;
    case 6:
      if (v)
        glVertex3fv(fv);
      else
        glVertex3f(fv[0], fv[1], fv[2]);
      break;
    case 7:
      if (v)
        glVertex3dv(dv);
      else
        glVertex3d(dv[0], dv[1], dv[2]);
      break;
    case 8:
      if (v)
        glVertex4sv(sv);
      else
        glVertex4s(sv[0], sv[1], sv[2], sv[3]);
      break;
    case 9:
      if (v)
        glVertex4iv(iv);
      else
        glVertex4i(iv[0], iv[1], iv[2], iv[3]);
      break;
    case 10:
      if (v)
        glVertex4fv(fv);
      else
        glVertex4f(fv[0], fv[1], fv[2], fv[3]);
      break;
    default:
      if (v)
        glVertex4dv(dv);
      else
        glVertex4d(dv[0], dv[1], dv[2], dv[3]);
      break;
  }
}

/* One colour c (components in [0,1]) through colour form `kind` (0..31):
 * type = kind % 8 (b, s, i, f, d, ub, us, ui), size 3 or 4, plain or v. */
static void colour(int kind, const float c[4]) {
  const int type = kind % 8;
  const int four = (kind / 8) % 2;
  const int v = kind >= 16;
  GLbyte b[4];
  GLshort s[4];
  GLint i[4];
  GLfloat f[4];
  GLdouble d[4];
  GLubyte ub[4];
  GLushort us[4];
  GLuint ui[4];
  for (int n = 0; n < 4; ++n) {
    b[n] = (GLbyte)(c[n] * 127.0f + 0.5f);
    s[n] = (GLshort)(c[n] * 32767.0f + 0.5f);
    i[n] = (GLint)(c[n] * 2147483647.0 + 0.5);
    f[n] = c[n];
    d[n] = c[n];
    ub[n] = (GLubyte)(c[n] * 255.0f + 0.5f);
    us[n] = (GLushort)(c[n] * 65535.0f + 0.5f);
    ui[n] = (GLuint)(c[n] * 4294967295.0 + 0.5);
  }
  if (!four) {
    switch (type) {
      case 0:
        if (v)
          glColor3bv(b);
        else
          glColor3b(b[0], b[1], b[2]);
        break;
      case 1:
        if (v)
          glColor3sv(s);
        else
          glColor3s(s[0], s[1], s[2]);
        break;
      case 2:
        if (v)
          glColor3iv(i);
        else
          glColor3i(i[0], i[1], i[2]);
        break;
      case 3:
        if (v)
          glColor3fv(f);
        else
          glColor3f(f[0], f[1], f[2]);
        break;
      case 4:
        if (v)
          glColor3dv(d);
        else
          glColor3d(d[0], d[1], d[2]);
        break;
      case 5:
        if (v)
          glColor3ubv(ub);
        else
          glColor3ub(ub[0], ub[1], ub[2]);
        break;
      case 6:
        if (v)
          glColor3usv(us);
        else
          glColor3us(us[0], us[1], us[2]);
        break;
      default:
        if (v)
          glColor3uiv(ui);
        else
          glColor3ui(ui[0], ui[1], ui[2]);
        break;
    }
  } else {
    switch (type) {
      case 0:
        if (v)
          glColor4bv(b);
        else
          glColor4b(b[0], b[1], b[2], b[3]);
        break;
      case 1:
        if (v)
          glColor4sv(s);
        else
          glColor4s(s[0], s[1], s[2], s[3]);
        break;
      case 2:
        if (v)
          glColor4iv(i);
        else
          glColor4i(i[0], i[1], i[2], i[3]);
        break;
      case 3:
        if (v)
          glColor4fv(f);
        else
          glColor4f(f[0], f[1], f[2], f[3]);
        break;
      case 4:
        if (v)
          glColor4dv(d);
        else
          glColor4d(d[0], d[1], d[2], d[3]);
        break;
      case 5:
        if (v)
          glColor4ubv(ub);
        else
          glColor4ub(ub[0], ub[1], ub[2], ub[3]);
        break;
      case 6:
        if (v)
          glColor4usv(us);
        else
          glColor4us(us[0], us[1], us[2], us[3]);
        break;
      default:
        if (v)
          glColor4uiv(ui);
        else
          glColor4ui(ui[0], ui[1], ui[2], ui[3]);
        break;
    }
  }
}

static void display(void) {
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  /* A striped background so that alpha shows. */
  glDisable(GL_BLEND);
  for (int x = 0; x < 320; x += 16) {
    glColor3f(0.25f, 0.25f, 0.3f);
    glRecti(x, 0, x + 8, 240);
  }

  /* Rows 0-2 (top): the 24 vertex forms. */
  for (int kind = 0; kind < 24; ++kind) {
    const int cx = (kind % 8) * 40, cy = 240 - 34 * (kind / 8 + 1);
    const float h = (float)kind / 24.0f;
    glBegin(GL_QUADS);
    glColor3f(1.0f - h, 0.3f + 0.7f * h, 0.5f);
    vertex(kind, cx + 2, cy + 2);
    glColor3f(0.9f, 0.9f, 0.2f + 0.8f * h);
    vertex(kind, cx + 38, cy + 6);
    glColor3f(0.2f + 0.8f * h, 0.2f, 1.0f - h);
    vertex(kind, cx + 33, cy + 32);
    glColor3f(0.4f, 1.0f - h, h);
    vertex(kind, cx + 5, cy + 28);
    glEnd();
  }

  /* Rows 3-6: the 32 colour forms. */
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  static const float corners[4][4] = {{1.0f, 0.5f, 0.0f, 1.0f},
                                      {0.0f, 0.75f, 1.0f, 0.5f},
                                      {0.25f, 0.0f, 1.0f, 0.75f},
                                      {1.0f, 1.0f, 0.25f, 0.25f}};
  for (int kind = 0; kind < 32; ++kind) {
    const int cx = (kind % 8) * 40, cy = 240 - 34 * (3 + kind / 8 + 1);
    glBegin(GL_QUADS);
    colour(kind, corners[0]);
    glVertex2i(cx + 2, cy + 2);
    colour(kind, corners[1]);
    glVertex2i(cx + 38, cy + 2);
    colour(kind, corners[2]);
    glVertex2i(cx + 38, cy + 32);
    colour(kind, corners[3]);
    glVertex2i(cx + 2, cy + 32);
    glEnd();
  }
  glDisable(GL_BLEND);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(320, 240);
  glutCreateWindow("02 vertex and colour forms");
  glDisable(GL_DITHER);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
