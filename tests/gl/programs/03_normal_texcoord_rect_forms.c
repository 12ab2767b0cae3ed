/* 03_normal_texcoord_rect_forms: every glNormal3{b,s,i,f,d}[v] form (lit quads, one light,
 * GL_NORMALIZE), every glRect{s,i,f,d}[v] form, and every glTexCoord{1,2,3,4}{s,i,f,d}[v]
 * form (a 4x4 nearest-filtered texture of 16 colours, GL_REPEAT; the 4-forms use a varying
 * q, so the texture is mapped projectively). 8 x 7 cells of 40 x 34 pixels. */
#include <GL/glut.h>

static GLuint tex;

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, w, 0, h, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void normal(int kind, const float n[3]) {
  const int type = kind % 5;
  const int v = kind >= 5;
  GLbyte b[3];
  GLshort s[3];
  GLint i[3];
  GLfloat f[3];
  GLdouble d[3];
  for (int k = 0; k < 3; ++k) {
    b[k] = (GLbyte)(n[k] * 127.0f + (n[k] < 0 ? -0.5f : 0.5f));
    s[k] = (GLshort)(n[k] * 32767.0f + (n[k] < 0 ? -0.5f : 0.5f));
    i[k] = (GLint)(n[k] * 2147483647.0 + (n[k] < 0 ? -0.5 : 0.5));
    f[k] = n[k];
    d[k] = n[k];
  }
  switch (type) {
    case 0:
      if (v)
        glNormal3bv(b);
      else
        glNormal3b(b[0], b[1], b[2]);
      break;
    case 1:
      if (v)
        glNormal3sv(s);
      else
        glNormal3s(s[0], s[1], s[2]);
      break;
    case 2:
      if (v)
        glNormal3iv(i);
      else
        glNormal3i(i[0], i[1], i[2]);
      break;
    case 3:
      if (v)
        glNormal3fv(f);
      else
        glNormal3f(f[0], f[1], f[2]);
      break;
    default:
      if (v)
        glNormal3dv(d);
      else
        glNormal3d(d[0], d[1], d[2]);
      break;
  }
}

/* Texture coordinate (s, t) with q through form `kind` (0..31): size = 1 + kind % 4,
 * type = (kind / 4) % 4 (s, i, f, d), v when kind >= 16. s, t in {0, 2}; q in {1, 2}. */
static void texcoord(int kind, int s, int t, int q) {
  const int size = 1 + kind % 4;
  const int type = (kind / 4) % 4;
  const int v = kind >= 16;
  if (size < 4) q = 1;
  GLshort sv[4] = {(GLshort)(s * q), (GLshort)(t * q), (GLshort)(3 * q), (GLshort)q};
  GLint iv[4] = {s * q, t * q, 3 * q, q};
  GLfloat fv[4] = {(GLfloat)(s * q), (GLfloat)(t * q), 0.5f * q, (GLfloat)q};
  GLdouble dv[4] = {s * q, t * q, 0.75 * q, q};
  switch (size * 4 + type) {
    case 4:
      if (v)
        glTexCoord1sv(sv);
      else
        glTexCoord1s(sv[0]);
      break;
    case 5:
      if (v)
        glTexCoord1iv(iv);
      else
        glTexCoord1i(iv[0]);
      break;
    case 6:
      if (v)
        glTexCoord1fv(fv);
      else
        glTexCoord1f(fv[0]);
      break;
    case 7:
      if (v)
        glTexCoord1dv(dv);
      else
        glTexCoord1d(dv[0]);
      break;
    case 8:
      if (v)
        glTexCoord2sv(sv);
      else
        glTexCoord2s(sv[0], sv[1]);
      break;
    case 9:
      if (v)
        glTexCoord2iv(iv);
      else
        glTexCoord2i(iv[0], iv[1]);
      break;
    case 10:
      if (v)
        glTexCoord2fv(fv);
      else
        glTexCoord2f(fv[0], fv[1]);
      break;
    case 11:
      if (v)
        glTexCoord2dv(dv);
      else
        glTexCoord2d(dv[0], dv[1]);
      break;
    case 12:
      if (v)
        glTexCoord3sv(sv);
      else
        glTexCoord3s(sv[0], sv[1], sv[2]);
      break;
    case 13:
      if (v)
        glTexCoord3iv(iv);
      else
        glTexCoord3i(iv[0], iv[1], iv[2]);
      break;
    case 14:
      if (v)
        glTexCoord3fv(fv);
      else
        glTexCoord3f(fv[0], fv[1], fv[2]);
      break;
    case 15:
      if (v)
        glTexCoord3dv(dv);
      else
        glTexCoord3d(dv[0], dv[1], dv[2]);
      break;
    case 16:
      if (v)
        glTexCoord4sv(sv);
      else
        glTexCoord4s(sv[0], sv[1], sv[2], sv[3]);
      break;
    case 17:
      if (v)
        glTexCoord4iv(iv);
      else
        glTexCoord4i(iv[0], iv[1], iv[2], iv[3]);
      break;
    case 18:
      if (v)
        glTexCoord4fv(fv);
      else
        glTexCoord4f(fv[0], fv[1], fv[2], fv[3]);
      break;
    default:
      if (v)
        glTexCoord4dv(dv);
      else
        glTexCoord4d(dv[0], dv[1], dv[2], dv[3]);
      break;
  }
}

static void rect(int kind, int x1, int y1, int x2, int y2) {
  GLshort s1[2] = {(GLshort)x1, (GLshort)y1}, s2[2] = {(GLshort)x2, (GLshort)y2};
  GLint i1[2] = {x1, y1}, i2[2] = {x2, y2};
  GLfloat f1[2] = {(GLfloat)x1, (GLfloat)y1}, f2[2] = {(GLfloat)x2, (GLfloat)y2};
  GLdouble d1[2] = {x1, y1}, d2[2] = {x2, y2};
  switch (kind) {
    case 0: glRects(s1[0], s1[1], s2[0], s2[1]); break;
    case 1: glRecti(x1, y1, x2, y2); break;
    case 2: glRectf(f1[0], f1[1], f2[0], f2[1]); break;
    case 3: glRectd(d1[0], d1[1], d2[0], d2[1]); break;
    case 4: glRectsv(s1, s2); break;
    case 5: glRectiv(i1, i2); break;
    case 6: glRectfv(f1, f2); break;
    default: glRectdv(d1, d2); break;
  }
}

static void display(void) {
  glClearColor(0.15f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  int cell = 0;

  /* 10 normal forms: lit quads, a different normal at each corner. */
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  static const float normals[4][3] = {
      {0.6f, 0.0f, 0.8f}, {-0.48f, 0.6f, 0.64f}, {0.0f, -0.6f, 0.8f}, {0.28f, 0.96f, 0.0f}};
  for (int kind = 0; kind < 10; ++kind, ++cell) {
    const int cx = (cell % 8) * 40, cy = 240 - 34 * (cell / 8 + 1);
    const GLfloat diffuse[4] = {0.3f + 0.07f * kind, 0.9f - 0.05f * kind, 0.6f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diffuse);
    glBegin(GL_QUADS);
    normal(kind, normals[0]);
    glVertex2i(cx + 2, cy + 2);
    normal(kind, normals[1]);
    glVertex2i(cx + 38, cy + 2);
    normal(kind, normals[2]);
    glVertex2i(cx + 38, cy + 32);
    normal(kind, normals[3]);
    glVertex2i(cx + 2, cy + 32);
    glEnd();
  }
  glDisable(GL_LIGHTING);

  /* 8 rect forms; half of them with the corners given in reverse order. */
  for (int kind = 0; kind < 8; ++kind, ++cell) {
    const int cx = (cell % 8) * 40, cy = 240 - 34 * (cell / 8 + 1);
    glColor3f(0.2f + 0.1f * kind, 0.9f - 0.1f * kind, kind % 2 ? 0.9f : 0.3f);
    if (kind % 2)
      rect(kind, cx + 37, cy + 31, cx + 3 + kind, cy + 3);
    else
      rect(kind, cx + 3, cy + 3 + kind, cx + 37, cy + 31);
  }

  /* 32 texture coordinate forms. */
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  /* The four-component forms come last: Mesa 22.3 keeps a q of 2 from an earlier
   * glTexCoord4 for some later glTexCoord1/2/3 vertices (the current value it reports is
   * right, the vertices it draws are not), which the GL spec does not allow. */
  for (int order = 0; order < 32; ++order, ++cell) {
    const int kind = order < 24 ? (order / 3) * 4 + order % 3 : (order - 24) * 4 + 3;
    const int cx = (cell % 8) * 40, cy = 240 - 34 * (cell / 8 + 1);
    glColor3f(1, 1, 1);
    glBegin(GL_QUADS);
    texcoord(kind, 0, 0, 1);
    glVertex2i(cx + 4, cy + 1);
    texcoord(kind, 2, 0, 2);
    glVertex2i(cx + 36, cy + 1);
    texcoord(kind, 2, 2, 1);
    glVertex2i(cx + 36, cy + 33);
    texcoord(kind, 0, 2, 2);
    glVertex2i(cx + 4, cy + 33);
    glEnd();
  }
  glDisable(GL_TEXTURE_2D);
  glutSwapBuffers();
}

static void init(void) {
  GLubyte texels[4 * 4 * 3];
  for (int i = 0; i < 16; ++i) {
    texels[i * 3 + 0] = (GLubyte)(i % 4 * 80);
    texels[i * 3 + 1] = (GLubyte)(i / 4 * 80);
    texels[i * 3 + 2] = (GLubyte)((i * 7) % 16 * 16 + 15);
  }
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  const GLfloat light_dir[4] = {0.3f, 0.5f, 1.0f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light_dir);
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
  glutInitWindowSize(320, 240);
  glutCreateWindow("03 normal, texcoord and rect forms");
  glDisable(GL_DITHER);
  init();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
