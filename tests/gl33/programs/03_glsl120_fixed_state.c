/*
 * GLSL 1.20 over the fixed-function state, as textbook code of the GL 2.x years writes it: a
 * compatibility context, gluPerspective and glTranslate/glRotate, glLight and glMaterial read
 * in the shader through gl_LightSource[0], gl_FrontMaterial and gl_FrontLightModelProduct,
 * gl_NormalMatrix and ftransform(). The sphere's arrays are in buffer objects (GL 1.5:
 * glVertexPointer/glNormalPointer with offsets, glDrawElements from an element array
 * buffer); a textured-colour quad is drawn in immediate mode with gl_Color and
 * gl_MultiTexCoord0.
 */
#include "common.h"

#include <GL/glu.h>

static const char* vs =
    "#version 120\n"
    "varying vec3 n, v;\n"
    "void main() {\n"
    "  n = gl_NormalMatrix * gl_Normal;\n"
    "  v = vec3(gl_ModelViewMatrix * gl_Vertex);\n"
    "  gl_Position = ftransform();\n"
    "}\n";

static const char* fs =
    "#version 120\n"
    "varying vec3 n, v;\n"
    "void main() {\n"
    "  vec3 N = normalize(n);\n"
    "  vec3 L = normalize(gl_LightSource[0].position.xyz - v);\n"
    "  vec3 E = normalize(-v);\n"
    "  vec3 R = normalize(-reflect(L, N));\n"
    "  vec4 amb = gl_FrontLightProduct[0].ambient;\n"
    "  vec4 diff = gl_FrontLightProduct[0].diffuse * max(dot(N, L), 0.0);\n"
    "  vec4 spec = gl_FrontLightProduct[0].specular * pow(max(dot(R, E), 0.0), gl_FrontMaterial.shininess);\n"
    "  gl_FragColor = gl_FrontLightModelProduct.sceneColor + amb + diff + spec;\n"
    "}\n";

static const char* vs_quad =
    "#version 120\n"
    "varying vec2 uv;\n"
    "varying vec4 col;\n"
    "void main() { uv = gl_MultiTexCoord0.st; col = gl_Color; gl_Position = gl_ModelViewProjectionMatrix * "
    "gl_Vertex; }\n";

static const char* fs_quad =
    "#version 120\n"
    "varying vec2 uv;\n"
    "varying vec4 col;\n"
    "void main() {\n"
    "  float check = mod(floor(uv.x * 8.0) + floor(uv.y * 8.0), 2.0);\n"
    "  gl_FragColor = mix(col, vec4(1.0) - col, check);\n"
    "}\n";

static GLuint prog, prog_quad, vbo, ibo;

static void display(void) {
  const GLfloat light_pos[4] = {3.0f, 4.0f, 5.0f, 1.0f};
  const GLfloat white[4] = {1, 1, 1, 1}, grey[4] = {0.2f, 0.2f, 0.2f, 1};
  const GLfloat red[4] = {0.8f, 0.15f, 0.1f, 1}, spec[4] = {0.9f, 0.9f, 0.9f, 1};
  const GLfloat blue[4] = {0.15f, 0.3f, 0.85f, 1};
  glClearColor(0.2f, 0.2f, 0.25f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45.0, 320.0 / 240.0, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0, 1, 7, 0, 0, 0, 0, 1, 0);
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos); /* in eye space, as GL stores it */
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glLightfv(GL_LIGHT0, GL_AMBIENT, grey);

  glUseProgram(prog);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, (void*)0);
  glNormalPointer(GL_FLOAT, 0, (void*)0); /* a unit sphere's normals are its positions */

  glPushMatrix();
  glTranslatef(-1.3f, 0.0f, 0.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
  glDrawElements(GL_TRIANGLES, SPHERE_INDICES, GL_UNSIGNED_SHORT, (void*)0);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(1.3f, 0.2f, -0.5f);
  glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
  glScalef(0.9f, 1.2f, 0.9f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
  glMaterialf(GL_FRONT, GL_SHININESS, 8.0f);
  glDrawElements(GL_TRIANGLES, SPHERE_INDICES, GL_UNSIGNED_SHORT, (void*)0);
  glPopMatrix();
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);

  glUseProgram(prog_quad);
  glBegin(GL_QUADS);
  glColor3f(0.9f, 0.7f, 0.2f);
  glTexCoord2f(0, 0);
  glVertex3f(-2.5f, -1.6f, -1.0f);
  glTexCoord2f(1, 0);
  glVertex3f(2.5f, -1.6f, -1.0f);
  glColor3f(0.2f, 0.6f, 0.3f);
  glTexCoord2f(1, 1);
  glVertex3f(2.5f, -1.2f, -3.0f);
  glTexCoord2f(0, 1);
  glVertex3f(-2.5f, -1.2f, -3.0f);
  glEnd();
  glUseProgram(0);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static float pos[SPHERE_VERTS * 3];
  static unsigned short idx[SPHERE_INDICES];
  open_window(&argc, argv, 0, 0, 0, "glsl 1.20 fixed state");
  prog = link_program(vs, fs);
  prog_quad = link_program(vs_quad, fs_quad);
  make_sphere(pos, idx);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof pos, pos, GL_STATIC_DRAW);
  glGenBuffers(1, &ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glEnable(GL_DEPTH_TEST);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
