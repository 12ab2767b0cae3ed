/* 36_multitexture: GL 1.3/1.4 fixed-function texturing beyond one 2D unit.
 * Top left: three units at once in immediate mode (glActiveTexture, glMultiTexCoord2f): an
 * RGB checkerboard on unit 0 (GL_MODULATE with vertex colours), a luminance light-map on
 * unit 1 turned by unit 1's own texture matrix (GL_MODULATE), a 1D gradient on unit 2 from
 * GL_OBJECT_LINEAR coordinate generation (GL_ADD).
 * Top middle: a lit sphere (two lights, GL_SEPARATE_SPECULAR_COLOR) with a cube map from
 * GL_REFLECTION_MAP coordinates (glEnable(GL_TEXTURE_CUBE_MAP) over GL_TEXTURE_2D).
 * Top right: a 3D texture (glEnable(GL_TEXTURE_3D)) with the r coordinate across the quad.
 * Bottom left: the secondary colour added by GL_COLOR_SUM (glSecondaryColor3f, lighting off)
 * over a textured quad, and linear fog from glFogCoordf (GL_FOG_COORD_SRC = GL_FOG_COORD).
 * Bottom middle: client arrays of two coordinate sets (glClientActiveTexture) through
 * glDrawArrays, unit 0 GL_DECAL of an RGBA texture, unit 1 GL_BLEND with its own colour.
 * Bottom right: GL_NORMAL_MAP coordinates on a torus, unit 0 the cube map, unit 1 the 1D
 * gradient from GL_EYE_LINEAR coordinates (GL_MODULATE).
 * Nearest filtering for the cube map (its face edges), linear without mipmaps elsewhere. */
#define GL_GLEXT_PROTOTYPES 1 /* GL/gl.h then declares the GL 1.4 calls of GL/glext.h */
#include <GL/glut.h>

enum { T_CHECK, T_LIGHT, T_GRAD, T_CUBE, T_VOL, T_RGBA, T_COUNT };
static GLuint tex[T_COUNT];

static void params(GLenum target, GLenum filter) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, (GLint)filter);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, (GLint)filter);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

static void make_textures(void) {
  GLubyte check[8 * 8 * 3], light[16 * 16], grad[16 * 3], vol[4 * 4 * 4 * 3], rgba[8 * 8 * 4];
  glGenTextures(T_COUNT, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      GLubyte* p = &check[(j * 8 + i) * 3];
      const int on = (i + j) % 2;
      p[0] = (GLubyte)(on ? 240 : 60);
      p[1] = (GLubyte)(on ? 220 : 90 + i * 10);
      p[2] = (GLubyte)(on ? 180 : 140);
      GLubyte* q = &rgba[(j * 8 + i) * 4];
      q[0] = (GLubyte)(i * 32);
      q[1] = (GLubyte)(255 - j * 30);
      q[2] = (GLubyte)(90);
      q[3] = (GLubyte)((i / 2 + j / 2) % 2 ? 255 : 70);
    }
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      const int dx = i - 8, dy = j - 8;
      const int d2 = dx * dx + dy * dy;
      light[j * 16 + i] = (GLubyte)(d2 > 64 ? 70 : 255 - d2 * 2);
    }
  for (int i = 0; i < 16; ++i) {
    grad[i * 3 + 0] = (GLubyte)(i * 8);
    grad[i * 3 + 1] = (GLubyte)(i < 8 ? 0 : (i - 8) * 12);
    grad[i * 3 + 2] = (GLubyte)(120 - i * 7);
  }
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        GLubyte* p = &vol[((k * 4 + j) * 4 + i) * 3];
        p[0] = (GLubyte)(i * 80);
        p[1] = (GLubyte)(j * 80);
        p[2] = (GLubyte)(k * 80);
      }
  glBindTexture(GL_TEXTURE_2D, tex[T_CHECK]);
  params(GL_TEXTURE_2D, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, check);
  glBindTexture(GL_TEXTURE_2D, tex[T_LIGHT]);
  params(GL_TEXTURE_2D, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 16, 16, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, light);
  glBindTexture(GL_TEXTURE_2D, tex[T_RGBA]);
  params(GL_TEXTURE_2D, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glBindTexture(GL_TEXTURE_1D, tex[T_GRAD]);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, grad);
  glBindTexture(GL_TEXTURE_3D, tex[T_VOL]);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 4, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, vol);
  /* The cube map: each face a colour with a darker 2x2 pattern. */
  static const GLubyte face_colour[6][3] = {{230, 80, 60},  {70, 200, 90},  {80, 110, 230},
                                            {230, 210, 70}, {200, 90, 210}, {90, 210, 210}};
  glBindTexture(GL_TEXTURE_CUBE_MAP, tex[T_CUBE]);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  for (int f = 0; f < 6; ++f) {
    GLubyte img[4 * 4 * 3];
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c)
          img[(j * 4 + i) * 3 + c] =
              (GLubyte)(((i / 2 + j / 2) % 2) ? face_colour[f][c] : face_colour[f][c] / 2);
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE,
                 img);
  }
}

static void reshape(int w, int h) { glViewport(0, 0, w, h); }

static void ortho(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, 320, 0, 240);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void unit_off(GLenum unit) {
  glActiveTexture(unit);
  glDisable(GL_TEXTURE_1D);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_TEXTURE_3D);
  glDisable(GL_TEXTURE_CUBE_MAP);
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  glDisable(GL_TEXTURE_GEN_R);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

static void three_units(void) {
  const GLfloat plane[4] = {1.0f / 50.0f, 1.0f / 120.0f, 0.0f, 0.0f};
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tex[T_CHECK]);
  glActiveTexture(GL_TEXTURE1);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tex[T_LIGHT]);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(0.5f, 0.5f, 0.0f);
  glRotatef(25.0f, 0.0f, 0.0f, 1.0f);
  glTranslatef(-0.5f, -0.5f, 0.0f);
  glMatrixMode(GL_MODELVIEW);
  glActiveTexture(GL_TEXTURE2);
  glEnable(GL_TEXTURE_1D);
  glBindTexture(GL_TEXTURE_1D, tex[T_GRAD]);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  glEnable(GL_TEXTURE_GEN_S);
  glBegin(GL_QUADS);
  glColor3f(1.0f, 0.6f, 0.6f);
  glMultiTexCoord2f(GL_TEXTURE0, 0, 0);
  glMultiTexCoord2f(GL_TEXTURE1, 0, 0);
  glVertex2i(6, 126);
  glColor3f(0.6f, 1.0f, 0.6f);
  glMultiTexCoord2f(GL_TEXTURE0, 2, 0);
  glMultiTexCoord2f(GL_TEXTURE1, 1, 0);
  glVertex2i(100, 126);
  glColor3f(0.6f, 0.6f, 1.0f);
  glMultiTexCoord2f(GL_TEXTURE0, 2, 2);
  glMultiTexCoord2f(GL_TEXTURE1, 1, 1);
  glVertex2i(100, 234);
  glColor3f(1.0f, 1.0f, 0.7f);
  glMultiTexCoord2f(GL_TEXTURE0, 0, 2);
  glMultiTexCoord2f(GL_TEXTURE1, 0, 1);
  glVertex2i(6, 234);
  glEnd();
  unit_off(GL_TEXTURE2);
  unit_off(GL_TEXTURE1);
  unit_off(GL_TEXTURE0);
}

static void lights(void) {
  const GLfloat pos0[4] = {-2.0f, 3.0f, 4.0f, 1.0f}, pos1[4] = {3.0f, -1.0f, 2.0f, 0.0f};
  const GLfloat white[4] = {1, 1, 1, 1}, dim[4] = {0.5f, 0.45f, 0.4f, 1};
  const GLfloat spec[4] = {0.8f, 0.8f, 0.8f, 1}, diff[4] = {0.7f, 0.7f, 0.7f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, pos0);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glLightfv(GL_LIGHT1, GL_POSITION, pos1);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, dim);
  glLightfv(GL_LIGHT1, GL_SPECULAR, dim);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diff);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 24.0f);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
}

static void perspective_cell(int x, int y) {
  glViewport(x, y, 106, 108);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, 106.0 / 108.0, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.3, 0.4, 4.0, 0, 0, 0, 0, 1, 0);
}

static void reflective_sphere(void) {
  perspective_cell(107, 126);
  lights();
  glEnable(GL_LIGHTING);
  glEnable(GL_DEPTH_TEST);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_TEXTURE_2D); /* the cube map wins over 2D */
  glEnable(GL_TEXTURE_CUBE_MAP);
  glBindTexture(GL_TEXTURE_CUBE_MAP, tex[T_CUBE]);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_GEN_R);
  GLUquadric* q = gluNewQuadric();
  gluQuadricNormals(q, GLU_SMOOTH);
  glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
  gluSphere(q, 1.35, 40, 24);
  gluDeleteQuadric(q);
  unit_off(GL_TEXTURE0);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
}

static void volume_quad(void) {
  glViewport(0, 0, 320, 240);
  ortho();
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_TEXTURE_3D);
  glBindTexture(GL_TEXTURE_3D, tex[T_VOL]);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord3f(0.0f, 0.0f, 0.1f);
  glVertex2i(220, 126);
  glTexCoord3f(1.0f, 0.0f, 0.9f);
  glVertex2i(314, 126);
  glTexCoord3f(1.0f, 1.0f, 0.5f);
  glVertex2i(314, 234);
  glTexCoord3f(0.0f, 1.0f, 0.0f);
  glVertex2i(220, 234);
  glEnd();
  unit_off(GL_TEXTURE0);
}

static void colour_sum_and_fog(void) {
  const GLfloat fog_colour[4] = {0.55f, 0.6f, 0.75f, 1.0f};
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tex[T_CHECK]);
  glEnable(GL_COLOR_SUM);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 1.0f);
  glFogfv(GL_FOG_COLOR, fog_colour);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glBegin(GL_QUADS);
  glColor3f(0.8f, 0.8f, 0.8f);
  glSecondaryColor3f(0.0f, 0.0f, 0.0f);
  glFogCoordf(0.0f);
  glTexCoord2f(0, 0);
  glVertex2i(6, 6);
  glSecondaryColor3f(0.5f, 0.0f, 0.0f);
  glFogCoordf(0.1f);
  glTexCoord2f(1, 0);
  glVertex2i(100, 6);
  glSecondaryColor3f(0.0f, 0.4f, 0.0f);
  glFogCoordf(0.9f);
  glTexCoord2f(1, 1);
  glVertex2i(100, 114);
  glSecondaryColor3f(0.0f, 0.0f, 0.6f);
  glFogCoordf(0.3f);
  glTexCoord2f(0, 1);
  glVertex2i(6, 114);
  glEnd();
  glSecondaryColor3f(0.0f, 0.0f, 0.0f);
  glFogCoordf(0.0f);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glDisable(GL_FOG);
  glDisable(GL_COLOR_SUM);
  unit_off(GL_TEXTURE0);
}

static void two_arrays(void) {
  /* 12 x 13 pixels a texel: texel edges fall on pixel edges, never on pixel centres. */
  static const GLfloat pos[8] = {112, 8, 208, 8, 208, 112, 112, 112};
  static const GLfloat uv0[8] = {0, 0, 1, 0, 1, 1, 0, 1};
  static const GLfloat uv1[8] = {0.2f, 0.1f, 0.9f, 0.1f, 0.9f, 0.9f, 0.1f, 0.8f};
  static const GLubyte col[16] = {255, 120, 120, 255, 120, 255, 120, 255,
                                  120, 120, 255, 255, 250, 250, 120, 255};
  const GLfloat blend_colour[4] = {0.1f, 0.2f, 0.9f, 1.0f};
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tex[T_RGBA]);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glActiveTexture(GL_TEXTURE1);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tex[T_LIGHT]);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, blend_colour);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, col);
  glClientActiveTexture(GL_TEXTURE0);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_FLOAT, 0, uv0);
  glClientActiveTexture(GL_TEXTURE1);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_FLOAT, 0, uv1);
  glDrawArrays(GL_QUADS, 0, 4);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glClientActiveTexture(GL_TEXTURE0);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  unit_off(GL_TEXTURE1);
  unit_off(GL_TEXTURE0);
}

static void normal_mapped_torus(void) {
  const GLfloat plane[4] = {0.0f, 0.35f, 0.0f, 0.5f};
  perspective_cell(214, 6);
  glEnable(GL_DEPTH_TEST);
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_TEXTURE_CUBE_MAP);
  glBindTexture(GL_TEXTURE_CUBE_MAP, tex[T_CUBE]);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_GEN_R);
  glActiveTexture(GL_TEXTURE1);
  glEnable(GL_TEXTURE_1D);
  glBindTexture(GL_TEXTURE_1D, tex[T_GRAD]);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGenfv(GL_S, GL_EYE_PLANE, plane);
  glEnable(GL_TEXTURE_GEN_S);
  glColor3f(1.0f, 1.0f, 1.0f);
  glRotatef(60.0f, 1.0f, 0.0f, 0.0f);
  glutSolidTorus(0.4, 1.0, 20, 32);
  unit_off(GL_TEXTURE1);
  unit_off(GL_TEXTURE0);
  glDisable(GL_DEPTH_TEST);
}

static void display(void) {
  glViewport(0, 0, 320, 240);
  glClearColor(0.2f, 0.2f, 0.25f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ortho();
  three_units();
  colour_sum_and_fog();
  two_arrays();
  volume_quad();
  reflective_sphere();
  normal_mapped_torus();
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(320, 240);
  glutCreateWindow("36 multitexture");
  glDisable(GL_DITHER);
  make_textures();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
