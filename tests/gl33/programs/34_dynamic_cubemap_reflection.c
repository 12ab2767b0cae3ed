/*
 * Dynamic environment mapping in a GL 3.3 core context (GLUT + GLEW): a small scene (six
 * coloured cubes on a ring around the origin over a shaded floor) rendered six times into the
 * faces of a cube map texture (GL_RGBA8, 128x128 per face) through one framebuffer object:
 * glFramebufferTexture2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + i) for the colour and a 128x128
 * GL_DEPTH_COMPONENT24 renderbuffer for depth, a 90-degree square perspective per face with
 * the cube-map face orientations (the up vector -Y for the side faces). Then
 * glGenerateMipmap(GL_TEXTURE_CUBE_MAP), GL_LINEAR_MIPMAP_LINEAR filtering and
 * GL_TEXTURE_CUBE_MAP_SEAMLESS, and the scene drawn from the camera with a mirror sphere at
 * the origin that samples the samplerCube with reflect().
 */
#include "common.h"

#define FACE_SIZE 128
#define NUM_CUBES 6

static const char* scene_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 pos;\n"
    "layout(location = 1) in vec3 nrm;\n"
    "uniform mat4 model, view, proj;\n"
    "out vec3 wpos, wnrm;\n"
    "void main() {\n"
    "  wpos = (model * vec4(pos, 1.0)).xyz;\n"
    "  wnrm = mat3(model) * nrm;\n"
    "  gl_Position = proj * view * vec4(wpos, 1.0);\n"
    "}\n";
static const char* scene_fs =
    "#version 330 core\n"
    "in vec3 wpos, wnrm;\n"
    "uniform vec3 color;\n"
    "uniform bool floor_mode;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  vec3 n = normalize(wnrm);\n"
    "  float d = max(dot(n, normalize(vec3(0.4, 0.9, 0.3))), 0.0);\n"
    "  vec3 c = color;\n"
    "  if (floor_mode) {\n"
    "    /* A smooth radial pattern: no hard edges for the mip chain to disagree on. */\n"
    "    float r = length(wpos.xz);\n"
    "    c = mix(vec3(0.75, 0.7, 0.55), vec3(0.25, 0.3, 0.4), 0.5 + 0.5 * sin(r * 2.3));\n"
    "  }\n"
    "  frag = vec4(c * (0.3 + 0.7 * d), 1.0);\n"
    "}\n";
static const char* mirror_fs =
    "#version 330 core\n"
    "in vec3 wpos, wnrm;\n"
    "uniform vec3 eye;\n"
    "uniform samplerCube env;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  vec3 I = normalize(wpos - eye);\n"
    "  vec3 R = reflect(I, normalize(wnrm));\n"
    "  frag = vec4(texture(env, R).rgb * 0.9 + vec3(0.04, 0.05, 0.06), 1.0);\n"
    "}\n";

static GLuint scene_prog, mirror_prog, cube_vao, floor_vao, sphere_vao, fbo, depth_rb, cubemap;

static GLuint make_vao(const float* verts, int nverts, const unsigned short* idx, int nidx) {
  GLuint v, b[2];
  glGenVertexArrays(1, &v);
  glBindVertexArray(v);
  glGenBuffers(2, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(nverts * 6 * sizeof(float)), verts, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)(3 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(nidx * sizeof(unsigned short)), idx, GL_STATIC_DRAW);
  return v;
}

/* The scene without the mirror: the floor and the ring of cubes. */
static void draw_scene(const float* view, const float* proj) {
  static const float colors[NUM_CUBES][3] = {{0.9f, 0.2f, 0.15f},  {0.95f, 0.75f, 0.1f},
                                             {0.2f, 0.8f, 0.25f},  {0.1f, 0.75f, 0.85f},
                                             {0.25f, 0.3f, 0.95f}, {0.85f, 0.3f, 0.85f}};
  float m[16], t[16], r[16];
  int i;
  glUseProgram(scene_prog);
  glUniformMatrix4fv(glGetUniformLocation(scene_prog, "view"), 1, GL_FALSE, view);
  glUniformMatrix4fv(glGetUniformLocation(scene_prog, "proj"), 1, GL_FALSE, proj);
  mat_identity(m);
  glUniformMatrix4fv(glGetUniformLocation(scene_prog, "model"), 1, GL_FALSE, m);
  glUniform1i(glGetUniformLocation(scene_prog, "floor_mode"), 1);
  glBindVertexArray(floor_vao);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, 0);
  glUniform1i(glGetUniformLocation(scene_prog, "floor_mode"), 0);
  glBindVertexArray(cube_vao);
  for (i = 0; i < NUM_CUBES; ++i) {
    const double a = 2.0 * 3.14159265358979 * (i + 0.23) / NUM_CUBES;
    mat_translate(t, (float)(2.4 * cos(a)), -0.55f + 0.37f * (float)(i % 3), (float)(2.4 * sin(a)));
    mat_rotate_y(r, 17.0f + 23.0f * (float)i);
    mat_mul(m, t, r);
    glUniformMatrix4fv(glGetUniformLocation(scene_prog, "model"), 1, GL_FALSE, m);
    glUniform3fv(glGetUniformLocation(scene_prog, "color"), 1, colors[i]);
    glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_SHORT, 0);
  }
}

static void display(void) {
  /* Look direction and up vector of each face, in the order +X, -X, +Y, -Y, +Z, -Z. */
  static const float dirs[6][6] = {{1, 0, 0, 0, -1, 0},  {-1, 0, 0, 0, -1, 0}, {0, 1, 0, 0, 0, 1},
                                   {0, -1, 0, 0, 0, -1}, {0, 0, 1, 0, -1, 0},  {0, 0, -1, 0, -1, 0}};
  static const float eye[3] = {0.31f, 1.43f, 5.17f};
  float view[16], proj[16], m[16];
  int i;
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);

  /* Pass 1: the six faces, from the mirror's centre. */
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, FACE_SIZE, FACE_SIZE);
  mat_perspective(proj, 90.0f, 1.0f, 0.1f, 50.0f);
  for (i = 0; i < 6; ++i) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)i,
                           cubemap, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      fprintf(stderr, "cube face %d framebuffer incomplete\n", i);
      exit(1);
    }
    glClearColor(0.45f, 0.6f, 0.85f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    mat_lookat(view, 0, 0, 0, dirs[i][0], dirs[i][1], dirs[i][2], dirs[i][3], dirs[i][4], dirs[i][5]);
    draw_scene(view, proj);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cubemap);
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);

  /* Pass 2: the camera's view with the mirror sphere. */
  glViewport(0, 0, 320, 240);
  glClearColor(0.45f, 0.6f, 0.85f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  mat_perspective(proj, 50.0f, 320.0f / 240.0f, 0.5f, 50.0f);
  mat_lookat(view, eye[0], eye[1], eye[2], 0.03f, -0.11f, 0.0f, 0, 1, 0);
  draw_scene(view, proj);
  glUseProgram(mirror_prog);
  mat_identity(m);
  m[0] = m[5] = m[10] = 1.13f;
  glUniformMatrix4fv(glGetUniformLocation(mirror_prog, "model"), 1, GL_FALSE, m);
  glUniformMatrix4fv(glGetUniformLocation(mirror_prog, "view"), 1, GL_FALSE, view);
  glUniformMatrix4fv(glGetUniformLocation(mirror_prog, "proj"), 1, GL_FALSE, proj);
  glUniform3fv(glGetUniformLocation(mirror_prog, "eye"), 1, eye);
  glUniform1i(glGetUniformLocation(mirror_prog, "env"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cubemap);
  glBindVertexArray(sphere_vao);
  glDrawElements(GL_TRIANGLES, SPHERE_INDICES, GL_UNSIGNED_SHORT, 0);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static float pos[SPHERE_VERTS * 3], sphere[SPHERE_VERTS * 6], cube[24 * 6];
  static unsigned short sidx[SPHERE_INDICES], cidx[36];
  static const float floor_verts[4 * 6] = {-9, -1.3f, -9, 0, 1, 0, 9,  -1.3f, -9, 0, 1, 0,
                                           9,  -1.3f, 9,  0, 1, 0, -9, -1.3f, 9,  0, 1, 0};
  static const unsigned short floor_idx[6] = {0, 2, 1, 0, 3, 2};
  int i, f, k = 0;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "dynamic cubemap reflection");
  scene_prog = link_program(scene_vs, scene_fs);
  mirror_prog = link_program(scene_vs, mirror_fs);

  make_sphere(pos, sidx);
  for (i = 0; i < SPHERE_VERTS; ++i) {
    memcpy(&sphere[i * 6], &pos[i * 3], 3 * sizeof(float));
    memcpy(&sphere[i * 6 + 3], &pos[i * 3], 3 * sizeof(float));
  }
  /* A cube of half-size 0.45, four vertices per face, counter-clockwise outside. */
  for (f = 0; f < 6; ++f) {
    const int axis = f / 2;
    const float sgn = (f % 2) ? -1.0f : 1.0f;
    for (i = 0; i < 4; ++i) {
      float* v = &cube[(f * 4 + i) * 6];
      v[axis] = 0.45f * sgn;
      v[(axis + 1) % 3] = ((i == 1 || i == 2) ? 0.45f : -0.45f) * sgn;
      v[(axis + 2) % 3] = (i >= 2) ? 0.45f : -0.45f;
      v[3] = v[4] = v[5] = 0.0f;
      v[3 + axis] = sgn;
    }
    cidx[k++] = (unsigned short)(f * 4), cidx[k++] = (unsigned short)(f * 4 + 1);
    cidx[k++] = (unsigned short)(f * 4 + 2), cidx[k++] = (unsigned short)(f * 4);
    cidx[k++] = (unsigned short)(f * 4 + 2), cidx[k++] = (unsigned short)(f * 4 + 3);
  }
  sphere_vao = make_vao(sphere, SPHERE_VERTS, sidx, SPHERE_INDICES);
  cube_vao = make_vao(cube, 24, cidx, 36);
  floor_vao = make_vao(floor_verts, 4, floor_idx, 6);

  /* The cube map: six empty 128x128 RGBA8 faces, mipmapped once rendered. */
  glGenTextures(1, &cubemap);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cubemap);
  for (f = 0; f < 6; ++f)
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_RGBA8, FACE_SIZE, FACE_SIZE, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, NULL);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);

  glGenRenderbuffers(1, &depth_rb);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, FACE_SIZE, FACE_SIZE);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
