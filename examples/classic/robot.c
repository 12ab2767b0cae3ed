/*
 * robot.c -- an articulated robot drawn as a hierarchy of transformations with
 * glPushMatrix/glPopMatrix; keys bend its joints.
 *
 * Based on the lecture slides "Rendering - II" (CS475/675, Siddhartha
 * Chaudhuri; seed 004_dbbad7515d73c5d0.txt), sections "Hierarchical Modeling",
 * "Example: Articulated Robot" (the part tree body > torso, shoulder > head,
 * left/right arm > upper arm > lower arm > hand, hips > left/right leg > upper
 * leg > lower leg > foot) and "Example: Articulated Robot (OpenGL)". The code
 * in display() follows that slide line by line (glTranslatef(0, 1.5, 0),
 * drawTorso(), shoulder at (0, 5, 0), head turned by neck_y and neck_x, left
 * arm at (1.5, 0, 0) turned by l_shoulder_x, elbow 2 below turned by
 * l_elbow_x, ...). The slide stops at "..."; the hand, the right arm, the hips
 * and the legs are completed the same way, the slide's "glRotatef(l_shoulder_x)"
 * gets its axis (1, 0, 0), and the draw functions, camera and keys are added.
 * Parts are boxes drawn with glBegin(GL_QUADS)/glNormal/glColor (no lighting:
 * each face gets a fixed brightness so the shape reads).
 *
 * Keys (lower case bends one way, upper case the other; 5 degrees a press):
 *   n/N nod (neck_x)         h/H turn head (neck_y)
 *   a/A left shoulder        s/S left elbow
 *   d/D right shoulder       f/F right elbow
 *   z/Z left hip             x/X left knee
 *   c/C right hip            v/V right knee
 *   r   back to the start pose      0   all joints straight
 *   arrow keys  turn / tilt the view   q, Esc  quit
 */
#include <GL/glut.h>
#include <stdlib.h>

/* joint angles in degrees */
GLfloat neck_x, neck_y;
GLfloat l_shoulder_x, l_elbow_x, r_shoulder_x, r_elbow_x;
GLfloat l_hip_x, l_knee_x, r_hip_x, r_knee_x;

GLfloat view_y = -55.0f, view_x = 10.0f; /* camera turn and tilt */

/* an axis-aligned box with one colour, each face a little darker or lighter */
void drawBox(GLfloat x0, GLfloat y0, GLfloat z0, GLfloat x1, GLfloat y1, GLfloat z1, const GLfloat* c) {
  glBegin(GL_QUADS);
  glNormal3f(0.0f, 0.0f, 1.0f); /* front */
  glColor3f(c[0] * 0.85f, c[1] * 0.85f, c[2] * 0.85f);
  glVertex3f(x0, y0, z1);
  glVertex3f(x1, y0, z1);
  glVertex3f(x1, y1, z1);
  glVertex3f(x0, y1, z1);
  glNormal3f(0.0f, 0.0f, -1.0f); /* back */
  glColor3f(c[0] * 0.5f, c[1] * 0.5f, c[2] * 0.5f);
  glVertex3f(x1, y0, z0);
  glVertex3f(x0, y0, z0);
  glVertex3f(x0, y1, z0);
  glVertex3f(x1, y1, z0);
  glNormal3f(1.0f, 0.0f, 0.0f); /* right */
  glColor3f(c[0] * 0.65f, c[1] * 0.65f, c[2] * 0.65f);
  glVertex3f(x1, y0, z1);
  glVertex3f(x1, y0, z0);
  glVertex3f(x1, y1, z0);
  glVertex3f(x1, y1, z1);
  glNormal3f(-1.0f, 0.0f, 0.0f); /* left */
  glColor3f(c[0] * 0.7f, c[1] * 0.7f, c[2] * 0.7f);
  glVertex3f(x0, y0, z0);
  glVertex3f(x0, y0, z1);
  glVertex3f(x0, y1, z1);
  glVertex3f(x0, y1, z0);
  glNormal3f(0.0f, 1.0f, 0.0f); /* top */
  glColor3f(c[0], c[1], c[2]);
  glVertex3f(x0, y1, z1);
  glVertex3f(x1, y1, z1);
  glVertex3f(x1, y1, z0);
  glVertex3f(x0, y1, z0);
  glNormal3f(0.0f, -1.0f, 0.0f); /* bottom */
  glColor3f(c[0] * 0.4f, c[1] * 0.4f, c[2] * 0.4f);
  glVertex3f(x0, y0, z0);
  glVertex3f(x1, y0, z0);
  glVertex3f(x1, y0, z1);
  glVertex3f(x0, y0, z1);
  glEnd();
}

const GLfloat body_color[3] = {0.2f, 0.45f, 0.9f};
const GLfloat joint_color[3] = {0.75f, 0.75f, 0.8f};
const GLfloat head_color[3] = {1.0f, 0.8f, 0.55f};
const GLfloat arm_color[3] = {0.95f, 0.35f, 0.25f};
const GLfloat leg_color[3] = {0.3f, 0.75f, 0.35f};
const GLfloat end_color[3] = {0.95f, 0.85f, 0.2f};

/* each part is drawn in its own frame: the joint it hangs from is the origin */
void drawTorso(void) { drawBox(-1.2f, 0.5f, -0.6f, 1.2f, 4.5f, 0.6f, body_color); }
void drawShoulder(void) { drawBox(-1.2f, -0.5f, -0.6f, 1.2f, 0.5f, 0.6f, joint_color); }
void drawHead(void) { drawBox(-0.7f, 0.6f, -0.7f, 0.7f, 2.0f, 0.7f, head_color); }
void drawUpperArm(void) { drawBox(-0.3f, -2.0f, -0.3f, 0.3f, 0.4f, 0.3f, arm_color); }
void drawLowerArm(void) { drawBox(-0.25f, -1.7f, -0.25f, 0.25f, 0.0f, 0.25f, arm_color); }
void drawHand(void) { drawBox(-0.3f, -0.6f, -0.15f, 0.3f, 0.0f, 0.15f, end_color); }
void drawHips(void) { drawBox(-1.2f, -0.5f, -0.6f, 1.2f, 0.5f, 0.6f, joint_color); }
void drawUpperLeg(void) { drawBox(-0.4f, -2.2f, -0.4f, 0.4f, 0.0f, 0.4f, leg_color); }
void drawLowerLeg(void) { drawBox(-0.35f, -2.2f, -0.35f, 0.35f, 0.0f, 0.35f, leg_color); }
void drawFoot(void) { drawBox(-0.4f, -0.4f, -0.4f, 0.4f, 0.0f, 1.0f, end_color); }

/* one arm: side is +1 for the left arm (at +x), -1 for the right arm */
void drawArm(GLfloat side, GLfloat shoulder_x, GLfloat elbow_x) {
  glPushMatrix();
  glTranslatef(1.5f * side, 0, 0);
  glRotatef(shoulder_x, 1, 0, 0);
  drawUpperArm();
  glPushMatrix();
  glTranslatef(0, -2, 0);
  glRotatef(elbow_x, 1, 0, 0);
  drawLowerArm();
  glPushMatrix();
  glTranslatef(0, -1.7f, 0);
  drawHand();
  glPopMatrix();
  glPopMatrix();
  glPopMatrix();
}

/* one leg, hanging from the hips */
void drawLeg(GLfloat side, GLfloat hip_x, GLfloat knee_x) {
  glPushMatrix();
  glTranslatef(0.7f * side, -0.5f, 0);
  glRotatef(hip_x, 1, 0, 0);
  drawUpperLeg();
  glPushMatrix();
  glTranslatef(0, -2.2f, 0);
  glRotatef(knee_x, 1, 0, 0);
  drawLowerLeg();
  glPushMatrix();
  glTranslatef(0, -2.2f, 0);
  drawFoot();
  glPopMatrix();
  glPopMatrix();
  glPopMatrix();
}

void display(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 2.0, 24.0, 0.0, 2.0, 0.0, 0.0, 1.0, 0.0);
  glRotatef(view_x, 1, 0, 0);
  glRotatef(view_y, 0, 1, 0);

  glPushMatrix(); /* body */
  glTranslatef(0, 1.5f, 0);
  drawTorso();
  glPushMatrix(); /* shoulder, head and arms */
  glTranslatef(0, 5, 0);
  drawShoulder();
  glPushMatrix();
  glRotatef(neck_y, 0, 1, 0);
  glRotatef(neck_x, 1, 0, 0);
  drawHead();
  glPopMatrix();
  drawArm(1.0f, l_shoulder_x, l_elbow_x);  /* left arm */
  drawArm(-1.0f, r_shoulder_x, r_elbow_x); /* right arm */
  glPopMatrix();
  glPushMatrix(); /* hips and legs */
  drawHips();
  drawLeg(1.0f, l_hip_x, l_knee_x);  /* left leg */
  drawLeg(-1.0f, r_hip_x, r_knee_x); /* right leg */
  glPopMatrix();
  glPopMatrix();

  glutSwapBuffers();
}

void startPose(void) {
  neck_x = 0.0f;
  neck_y = 20.0f;
  l_shoulder_x = -60.0f;
  l_elbow_x = -50.0f; /* left arm raised forward, elbow bent */
  r_shoulder_x = 25.0f;
  r_elbow_x = -20.0f; /* right arm swung back */
  l_hip_x = -30.0f;
  l_knee_x = 40.0f; /* left leg stepping forward */
  r_hip_x = 15.0f;
  r_knee_x = 10.0f;
}

void straightPose(void) {
  neck_x = neck_y = 0.0f;
  l_shoulder_x = l_elbow_x = r_shoulder_x = r_elbow_x = 0.0f;
  l_hip_x = l_knee_x = r_hip_x = r_knee_x = 0.0f;
}

GLfloat clamp(GLfloat a, GLfloat lo, GLfloat hi) { return a < lo ? lo : (a > hi ? hi : a); }

void keyboard(unsigned char key, int x, int y) {
  const GLfloat d = 5.0f;
  (void)x;
  (void)y;
  switch (key) {
    case 'n': neck_x += d; break;
    case 'N': neck_x -= d; break;
    case 'h': neck_y += d; break;
    case 'H': neck_y -= d; break;
    case 'a': l_shoulder_x -= d; break;
    case 'A': l_shoulder_x += d; break;
    case 's': l_elbow_x -= d; break;
    case 'S': l_elbow_x += d; break;
    case 'd': r_shoulder_x -= d; break;
    case 'D': r_shoulder_x += d; break;
    case 'f': r_elbow_x -= d; break;
    case 'F': r_elbow_x += d; break;
    case 'z': l_hip_x -= d; break;
    case 'Z': l_hip_x += d; break;
    case 'x': l_knee_x += d; break;
    case 'X': l_knee_x -= d; break;
    case 'c': r_hip_x -= d; break;
    case 'C': r_hip_x += d; break;
    case 'v': r_knee_x += d; break;
    case 'V': r_knee_x -= d; break;
    case 'r': startPose(); break;
    case '0': straightPose(); break;
    case 'q':
    case 'Q':
    case 27: exit(0);
    default: return;
  }
  /* joints that only bend one way */
  neck_x = clamp(neck_x, -40.0f, 40.0f);
  neck_y = clamp(neck_y, -80.0f, 80.0f);
  l_elbow_x = clamp(l_elbow_x, -150.0f, 0.0f);
  r_elbow_x = clamp(r_elbow_x, -150.0f, 0.0f);
  l_knee_x = clamp(l_knee_x, 0.0f, 150.0f);
  r_knee_x = clamp(r_knee_x, 0.0f, 150.0f);
  glutPostRedisplay();
}

void special(int key, int x, int y) {
  (void)x;
  (void)y;
  switch (key) {
    case GLUT_KEY_LEFT: view_y -= 5.0f; break;
    case GLUT_KEY_RIGHT: view_y += 5.0f; break;
    case GLUT_KEY_UP: view_x += 5.0f; break;
    case GLUT_KEY_DOWN: view_x -= 5.0f; break;
    default: return;
  }
  glutPostRedisplay();
}

void reshape(int w, int h) {
  if (h == 0) h = 1;
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (GLdouble)w / h, 1.0, 100.0);
  glMatrixMode(GL_MODELVIEW);
}

void init(void) {
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glEnable(GL_DEPTH_TEST);
  startPose();
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(500, 600);
  glutCreateWindow("robot");
  init();
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutKeyboardFunc(keyboard);
  glutSpecialFunc(special);
  glutMainLoop();
  return 0;
}
