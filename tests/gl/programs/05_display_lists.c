/* 05_display_lists: display lists. glGenLists; glNewList with GL_COMPILE (a seven-segment
 * digit font, one list per digit, each ending with a glTranslatef advance) and
 * GL_COMPILE_AND_EXECUTE (a tile drawn while it is compiled); glCallList; glCallLists with
 * glListBase and GL_UNSIGNED_BYTE / GL_UNSIGNED_SHORT / GL_INT name arrays; nested lists (a
 * row of tiles calls the tile list, a panel calls the row list); lists holding state (colour,
 * shade model, matrices with push/pop); glDeleteLists followed by glCallList of the deleted
 * names (nothing drawn) and glIsList (green marks). Single-buffered (glFlush). */
#include <GL/glut.h>

static GLuint digits; /* 10 lists: '0'..'9' */
static GLuint tile;   /* compiled and executed in display() */
static GLuint row;    /* calls tile 5 times */
static GLuint panel;  /* calls row 3 times */
static GLuint doomed; /* 3 lists deleted after compilation */

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, w, 0, h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* Segments a-g of a digit 12 wide, 24 high, drawn as quads. */
static void segment(int s) {
  static const float box[7][4] = {{2, 21, 10, 24}, {10, 12, 13, 22}, {10, 1, 13, 11},      {2, 0, 10, 3},
                                  {-1, 1, 2, 11},  {-1, 12, 2, 22},  {2, 10.5f, 10, 13.5f}};
  glRectf(box[s][0], box[s][1], box[s][2], box[s][3]);
}

static void build_lists(void) {
  static const unsigned char seg[10] = {0x3f, 0x06, 0x5b, 0x4f, 0x66, 0x6d, 0x7d, 0x07, 0x7f, 0x6f};
  digits = glGenLists(10);
  for (int d = 0; d < 10; ++d) {
    glNewList(digits + d, GL_COMPILE);
    for (int s = 0; s < 7; ++s)
      if (seg[d] & (1 << s)) segment(s);
    glTranslatef(18, 0, 0);
    glEndList();
  }

  tile = glGenLists(3);
  row = tile + 1;
  panel = tile + 2;
  /* row and panel refer to tile before it exists: lists are bound by name at execution. */
  glNewList(row, GL_COMPILE);
  glPushMatrix();
  for (int i = 0; i < 5; ++i) {
    glCallList(tile);
    glTranslatef(24, 0, 0);
  }
  glPopMatrix();
  glEndList();
  glNewList(panel, GL_COMPILE);
  glPushMatrix();
  for (int j = 0; j < 3; ++j) {
    glCallList(row);
    glTranslatef(6, 24, 0);
  }
  glPopMatrix();
  glEndList();

  doomed = glGenLists(3);
  for (int i = 0; i < 3; ++i) {
    glNewList(doomed + i, GL_COMPILE);
    glColor3f(1, 0, 0);
    glRecti(0, 0, 300, 200); /* would cover everything */
    glEndList();
  }
  glDeleteLists(doomed, 3);
}

static void display(void) {
  glClearColor(0.1f, 0.12f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glLoadIdentity();

  /* The tile is (re)compiled and drawn at once, with smooth shading set inside the list. */
  glPushMatrix();
  glTranslatef(12, 150, 0);
  glNewList(tile, GL_COMPILE_AND_EXECUTE);
  glShadeModel(GL_SMOOTH);
  glBegin(GL_QUADS);
  glColor3f(1.0f, 0.8f, 0.2f);
  glVertex2i(0, 0);
  glColor3f(0.9f, 0.3f, 0.1f);
  glVertex2i(20, 0);
  glColor3f(0.2f, 0.4f, 0.9f);
  glVertex2i(20, 20);
  glColor3f(0.3f, 0.9f, 0.5f);
  glVertex2i(0, 20);
  glEnd();
  glEndList();
  glPopMatrix();

  /* Nested lists: panel -> row -> tile, twice, the second time rotated and scaled. */
  glPushMatrix();
  glTranslatef(40, 150, 0);
  glCallList(panel);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(236, 126, 0);
  glRotatef(30, 0, 0, 1);
  glScalef(0.55f, 0.8f, 1);
  glCallList(panel);
  glPopMatrix();

  /* Text through glCallLists and glListBase, with three name types. */
  glColor3f(0.9f, 0.9f, 0.9f);
  glListBase(digits - '0');
  glPushMatrix();
  glTranslatef(10, 100, 0);
  glCallLists(16, GL_UNSIGNED_BYTE, "3141592653589793");
  glPopMatrix();

  glListBase(digits);
  glColor3f(0.3f, 1.0f, 0.8f);
  glPushMatrix();
  glTranslatef(10, 60, 0);
  glScalef(1.4f, 1.0f, 1);
  {
    static const GLushort names[10] = {2, 7, 1, 8, 2, 8, 1, 8, 2, 8};
    glCallLists(10, GL_UNSIGNED_SHORT, names);
  }
  glPopMatrix();

  glListBase(digits + 9);
  glColor3f(1.0f, 0.5f, 0.9f);
  glPushMatrix();
  glTranslatef(10, 20, 0);
  glScalef(1.0f, 1.4f, 1);
  {
    static const GLint names[12] = {-8, -5, -9, -4, -3, -6,
                                    -7, -1, -6, -9, -6, -7}; /* with the base: 140563283032 */
    glCallLists(12, GL_INT, names);
  }
  glPopMatrix();
  glListBase(0);

  /* Deleted lists draw nothing; glIsList says they are gone and the others are there. */
  glCallList(doomed);
  glCallList(doomed + 1);
  glCallList(doomed + 2);
  for (int i = 0; i < 4; ++i) {
    const GLuint name = i < 3 ? doomed + (GLuint)i : panel;
    const GLboolean expect = i == 3;
    glColor3f(glIsList(name) == expect ? 0.2f : 1.0f, glIsList(name) == expect ? 0.9f : 0.0f, 0.2f);
    glRecti(250 + 16 * (i % 2), 200 + 16 * (i / 2), 264 + 16 * (i % 2), 214 + 16 * (i / 2));
  }
  glFlush();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
  glutInitWindowSize(320, 240);
  glutCreateWindow("05 display lists");
  glDisable(GL_DITHER);
  build_lists();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutMainLoop();
  return 0;
}
