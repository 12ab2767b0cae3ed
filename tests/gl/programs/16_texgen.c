/* 16_texgen: texture coordinate generation (glTexGen) on lit, textured (GL_MODULATE)
 * objects: GL_OBJECT_LINEAR contour stripes on a sphere (the stripes follow the object),
 * GL_EYE_LINEAR stripes on a tilted torus (the planes are fixed in eye space: set under an
 * identity modelview), and GL_SPHERE_MAP reflection of a sky/ground texture on a sphere.
 * Each generated coordinate has its own plane (GL_S and GL_T). */
#include <GL/glut.h>
#include <math.h>

#define PI 3.14159265358979323846

static GLuint stripes, environment;

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.4 * w / h, 0.4 * w / h, -0.4, 0.4, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
}

static void sphere(double r) {
  const int slices = 36, stacks = 20;
  for (int j = 0; j < stacks; ++j) {
    const double t0 = PI * j / stacks - PI / 2, t1 = PI * (j + 1) / stacks - PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= slices; ++i) {
      const double p = 2 * PI * i / slices;
      glNormal3d(cos(t1) * sin(p), sin(t1), cos(t1) * cos(p));
      glVertex3d(r * cos(t1) * sin(p), r * sin(t1), r * cos(t1) * cos(p));
      glNormal3d(cos(t0) * sin(p), sin(t0), cos(t0) * cos(p));
      glVertex3d(r * cos(t0) * sin(p), r * sin(t0), r * cos(t0) * cos(p));
    }
    glEnd();
  }
}

static void torus(double R, double r) {
  const int sides = 20, rings = 40;
  for (int i = 0; i < rings; ++i) {
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= sides; ++j) {
      for (int k = 1; k >= 0; --k) {
        const double u = 2 * PI * (i + k) / rings, v = 2 * PI * j / sides;
        glNormal3d(cos(v) * cos(u), cos(v) * sin(u), sin(v));
        glVertex3d((R + r * cos(v)) * cos(u), (R + r * cos(v)) * sin(u), r * sin(v));
      }
    }
    glEnd();
  }
}

static void make_textures(void) {
  static GLubyte s[32 * 32 * 3], e[64 * 64 * 3];
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) {
      GLubyte* t = &s[(j * 32 + i) * 3];
      const int band = i < 12, cross = j < 6;
      t[0] = band ? 255 : (cross ? 80 : 230);
      t[1] = band ? 70 : (cross ? 80 : 230);
      t[2] = band ? 40 : (cross ? 255 : 230);
    }
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) {
      GLubyte* t = &e[(j * 64 + i) * 3];
      const int grid = i % 16 == 0 || j % 16 == 0;
      if (j >= 32) {
        t[0] = (GLubyte)(90 + j);
        t[1] = (GLubyte)(140 + j);
        t[2] = 255;
      } else {
        t[0] = (GLubyte)(110 + 2 * j);
        t[1] = (GLubyte)(70 + j);
        t[2] = 40;
      }
      if (grid) t[0] = t[1] = t[2] = 250;
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glGenTextures(1, &stripes);
  glBindTexture(GL_TEXTURE_2D, stripes);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 32, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, s);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glGenTextures(1, &environment);
  glBindTexture(GL_TEXTURE_2D, environment);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, e);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

static void display(void) {
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glLoadIdentity();
  const GLfloat light[4] = {0.3f, 0.6f, 1.0f, 0.0f}, white[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, white);

  /* Object-linear: planes in object space, applied after the object's rotation. */
  const GLfloat s_obj[4] = {2.5f, 0.0f, 0.8f, 0.0f}, t_obj[4] = {0.0f, 2.0f, 0.0f, 0.0f};
  glBindTexture(GL_TEXTURE_2D, stripes);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, s_obj);
  glTexGenfv(GL_T, GL_OBJECT_PLANE, t_obj);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glPushMatrix();
  glTranslatef(-1.5f, 0.0f, -3.3f);
  glRotatef(35, 0, 0, 1);
  glRotatef(-30, 0, 1, 0);
  sphere(0.7);
  glPopMatrix();

  /* Eye-linear: planes given under the identity modelview, so fixed to the eye. */
  const GLfloat s_eye[4] = {2.0f, 0.7f, 0.0f, 0.0f}, t_eye[4] = {0.0f, 1.6f, 0.5f, 0.0f};
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGenfv(GL_S, GL_EYE_PLANE, s_eye);
  glTexGenfv(GL_T, GL_EYE_PLANE, t_eye);
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, -3.3f);
  glRotatef(-55, 1, 0, 0);
  glRotatef(20, 0, 1, 0);
  torus(0.62, 0.25);
  glPopMatrix();

  /* Sphere map. */
  glBindTexture(GL_TEXTURE_2D, environment);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glPushMatrix();
  glTranslatef(1.5f, 0.0f, -3.3f);
  sphere(0.7);
  glPopMatrix();

  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  glDisable(GL_TEXTURE_2D);
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(320, 160);
  glutCreateWindow("16 texgen");
  glDisable(GL_DITHER);
  make_textures();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
