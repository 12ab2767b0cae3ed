/*
 * squares.c -- "draw a square when the mouse is clicked", with a right-button
 * menu (Clear / Quit).
 *
 * Based on the lecture notes "NUS SoC SWS3005 Real-time 3D Graphics Rendering",
 * section III "Input & Interaction" (seed 001_5665e12f7de930eb.txt):
 *   - "Mouse and Keyboard Callbacks": mymouse() and drawSquare() (the
 *     "E.g. To draw a square when mouse click" example), drawSquare also used
 *     as the motion callback (glutMotionFunc(drawSquare)) so dragging paints;
 *   - the keyboard example mykey() (q/Q quits);
 *   - "Menu": glutCreateMenu(mymenu), entries "Clear" (1) and "Quit" (2),
 *     attached to the right button, and mymenu().
 * The notes give these as fragments; main(), myinit(), myReshape() and
 * display() are completed here in the same style. Changes to the fragments:
 *   - the notes' "y = w - 1 - y" uses the window height, kept in the global wh
 *     that myReshape() updates (the notes' formula y_GL = h - 1 - y_win);
 *   - the colour is written (GLubyte)(rand() % 256) instead of the notes'
 *     (char)rand()%256, which gives the same kind of random byte;
 *   - "key == 'Q' | key == 'q'" is written with || ;
 *   - every square is also remembered in squares[] so that display() can
 *     redraw them when the window is exposed or resized (the notes draw into
 *     the single front buffer only);
 *   - the program starts with a few squares already placed (fixed positions
 *     and colours, see myinit()) so that a run without any mouse input, e.g.
 *     headless, shows something;
 *   - size (half the side of a square) is not given in the notes; 10 pixels.
 * Because the menu is attached to the right button, GLUT gives right-button
 * presses to the menu, so mymouse()'s exit on the right button (kept as in
 * the notes) is in practice replaced by the menu's "Quit".
 */
#include <GL/glut.h>
#include <stdlib.h>

#define MAX_SQUARES 10000

GLsizei ww = 500, wh = 500; /* window size, updated by myReshape() */
GLfloat size = 10.0f;       /* half side length of a square, in pixels */

typedef struct {
  GLfloat x, y;    /* centre, in OpenGL window coordinates (origin bottom left) */
  GLubyte r, g, b; /* colour */
} Square;

Square squares[MAX_SQUARES];
int nsquares = 0;

void fillSquare(const Square* s) {
  glColor3ub(s->r, s->g, s->b);
  glBegin(GL_POLYGON);
  glVertex2f(s->x + size, s->y + size);
  glVertex2f(s->x - size, s->y + size);
  glVertex2f(s->x - size, s->y - size);
  glVertex2f(s->x + size, s->y - size);
  glEnd();
}

/* remember a square and draw it at once (into the single front buffer) */
void addSquare(GLfloat x, GLfloat y, GLubyte r, GLubyte g, GLubyte b) {
  Square s;
  s.x = x;
  s.y = y;
  s.r = r;
  s.g = g;
  s.b = b;
  if (nsquares < MAX_SQUARES) squares[nsquares++] = s;
  fillSquare(&s);
  glFlush();
}

void drawSquare(int x, int y) {
  y = wh - 1 - y; /* invert y position */
  /* a random color */
  addSquare((GLfloat)x, (GLfloat)y, (GLubyte)(rand() % 256), (GLubyte)(rand() % 256),
            (GLubyte)(rand() % 256));
}

void mymouse(int btn, int state, int x, int y) {
  if (btn == GLUT_RIGHT_BUTTON && state == GLUT_DOWN) exit(0);
  if (btn == GLUT_LEFT_BUTTON && state == GLUT_DOWN) drawSquare(x, y);
}

void mykey(unsigned char key, int x, int y) {
  (void)x;
  (void)y;
  if (key == 'Q' || key == 'q') exit(0);
}

void mymenu(int id) {
  if (id == 1) {
    nsquares = 0; /* forget the squares, so that a redraw keeps the window clear */
    glClear(GL_COLOR_BUFFER_BIT);
    glFlush();
  }
  if (id == 2) exit(0);
}

void display(void) {
  int i;
  glClear(GL_COLOR_BUFFER_BIT);
  for (i = 0; i < nsquares; i++) fillSquare(&squares[i]);
  glFlush();
}

/* one pixel per unit, origin at the bottom left corner of the window */
void myReshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0.0, (GLdouble)w, 0.0, (GLdouble)h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  ww = w;
  wh = h;
}

void myinit(void) {
  /* initial squares (not in the notes): a diagonal of six fixed colours,
     so that the window shows something before the first click */
  static const GLubyte colors[6][3] = {{255, 0, 0}, {255, 160, 0}, {255, 255, 0},
                                       {0, 200, 0}, {0, 120, 255}, {160, 0, 255}};
  int i;
  glClearColor(0.0, 0.0, 0.0, 1.0); /* black background */
  for (i = 0; i < 6; i++) {
    Square s;
    s.x = 100.0f + 60.0f * i;
    s.y = 100.0f + 60.0f * i;
    s.r = colors[i][0];
    s.g = colors[i][1];
    s.b = colors[i][2];
    squares[nsquares++] = s;
  }
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
  glutInitWindowSize(ww, wh);
  glutCreateWindow("square");
  myinit();
  glutReshapeFunc(myReshape);
  glutDisplayFunc(display);
  glutMouseFunc(mymouse);
  glutMotionFunc(drawSquare);
  glutKeyboardFunc(mykey);

  glutCreateMenu(mymenu);
  glutAddMenuEntry("Clear", 1);
  glutAddMenuEntry("Quit", 2);
  glutAttachMenu(GLUT_RIGHT_BUTTON);

  glutMainLoop();
  return 0;
}
