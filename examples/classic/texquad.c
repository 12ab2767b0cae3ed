/*
 * texquad.c -- texture mapping in OpenGL 1.1: a procedural checkerboard
 * texture on a quad facing the viewer and on a second quad tilted away in
 * perspective.
 *
 * The seed notes have no fixed-function texture program: "NUS SoC SWS3005"
 * (seed 001_5665e12f7de930eb.txt) section X "Texture Mapping & Applications"
 * -> "Surface Parameterization" (texture coordinates (s, t) in [0,1]^2, the
 * texel that maps to each surface point) and section VI "Rasterization &
 * Fragment Processing" (texture access with interpolated texture coordinates,
 * combined with the fragment colour) only describe it, and their only texture
 * code uses shaders and framebuffer objects. This program is written for the
 * notes in the classic style of the OpenGL Programming Guide's checker.c:
 * glGenTextures/glBindTexture/glTexImage2D, glTexCoord2f per vertex,
 * GL_MODULATE with a white glColor.
 *
 * The dark squares of the checkerboard grow redder with s and greener with t,
 * so the picture shows which way the texture is mapped: red towards the right
 * edge, green towards the top edge of each quad.
 *
 * Keys: f  switch GL_NEAREST / GL_LINEAR filtering    q, Esc  quit
 */
#include <GL/glut.h>
#include <stdlib.h>

#define checkImageWidth 64
#define checkImageHeight 64
GLubyte checkImage[checkImageHeight][checkImageWidth][4];

GLuint texName;
int linear = 0;

void makeCheckImage(void) {
  int i, j;
  for (i = 0; i < checkImageHeight; i++) {  /* row i: t = (i + 0.5) / 64 */
    for (j = 0; j < checkImageWidth; j++) { /* column j: s = (j + 0.5) / 64 */
      int white = ((i & 0x8) == 0) ^ ((j & 0x8) == 0);
      checkImage[i][j][0] = (GLubyte)(white ? 255 : j * 4);
      checkImage[i][j][1] = (GLubyte)(white ? 255 : i * 4);
      checkImage[i][j][2] = (GLubyte)(white ? 255 : 64);
      checkImage[i][j][3] = 255;
    }
  }
}

void setFilter(void) {
  GLint f = linear ? GL_LINEAR : GL_NEAREST;
  glBindTexture(GL_TEXTURE_2D, texName);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f);
}

void init(void) {
  glClearColor(0.0, 0.0, 0.0, 0.0);
  glShadeModel(GL_FLAT);
  glEnable(GL_DEPTH_TEST);

  makeCheckImage();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

  glGenTextures(1, &texName);
  glBindTexture(GL_TEXTURE_2D, texName);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  setFilter();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, checkImageWidth, checkImageHeight, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               checkImage);
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

void display(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, texName);
  glColor3f(1.0, 1.0, 1.0);
  glBegin(GL_QUADS);
  /* a quad facing the viewer */
  glTexCoord2f(0.0, 0.0);
  glVertex3f(-2.0, -1.0, 0.0);
  glTexCoord2f(1.0, 0.0);
  glVertex3f(0.0, -1.0, 0.0);
  glTexCoord2f(1.0, 1.0);
  glVertex3f(0.0, 1.0, 0.0);
  glTexCoord2f(0.0, 1.0);
  glVertex3f(-2.0, 1.0, 0.0);
  /* a quad turned 45 degrees away from the viewer */
  glTexCoord2f(0.0, 0.0);
  glVertex3f(1.0, -1.0, 0.0);
  glTexCoord2f(1.0, 0.0);
  glVertex3f(2.41421, -1.0, -1.41421);
  glTexCoord2f(1.0, 1.0);
  glVertex3f(2.41421, 1.0, -1.41421);
  glTexCoord2f(0.0, 1.0);
  glVertex3f(1.0, 1.0, 0.0);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glutSwapBuffers();
}

void reshape(int w, int h) {
  if (h == 0) h = 1;
  glViewport(0, 0, (GLsizei)w, (GLsizei)h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60.0, (GLfloat)w / (GLfloat)h, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0, 0.0, -3.6);
}

void keyboard(unsigned char key, int x, int y) {
  (void)x;
  (void)y;
  switch (key) {
    case 'f':
    case 'F':
      linear = !linear;
      setFilter();
      glutPostRedisplay();
      break;
    case 'q':
    case 'Q':
    case 27: exit(0);
    default: break;
  }
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(500, 500);
  glutInitWindowPosition(100, 100);
  glutCreateWindow("texquad");
  init();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutKeyboardFunc(keyboard);
  glutMainLoop();
  return 0;
}
