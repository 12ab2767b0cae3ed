/*
 * A particle fountain drawn as point sprites in a GL 3.3 core context (GLUT + GLEW): GL_POINTS
 * with gl_PointSize written by the vertex shader (glEnable(GL_PROGRAM_POINT_SIZE)), the size
 * shrinking with distance; round soft sprites from gl_PointCoord in the fragment shader
 * (discard outside the circle, a smooth alpha falloff), additive blending (GL_ONE, GL_ONE),
 * and the depth test on with depth writes off (glDepthMask(GL_FALSE)) so that an opaque lit
 * sphere hides the particles behind it. A second group of large sprites shows the orientation
 * of gl_PointCoord under both GL_POINT_SPRITE_COORD_ORIGIN settings (UPPER_LEFT, the default,
 * and LOWER_LEFT). Particle positions, colours and sizes come from the program's own LCG.
 */
#include "common.h"

#define NUM_PARTICLES 400

static const char* solid_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 pos;\n"
    "uniform mat4 mvp;\n"
    "uniform vec3 center;\n"
    "uniform float radius;\n"
    "out vec3 normal;\n"
    "void main() {\n"
    "  normal = pos;\n"
    "  gl_Position = mvp * vec4(center + radius * pos, 1.0);\n"
    "}\n";
static const char* solid_fs =
    "#version 330 core\n"
    "in vec3 normal;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  float d = max(dot(normalize(normal), normalize(vec3(-0.3, 0.8, 0.6))), 0.0);\n"
    "  frag = vec4(vec3(0.25, 0.3, 0.45) * (0.3 + 0.7 * d), 1.0);\n"
    "}\n";

static const char* particle_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 pos;\n"
    "layout(location = 1) in vec4 color_size;\n"
    "uniform mat4 view, proj;\n"
    "uniform float size_scale;\n"
    "out vec3 pcolor;\n"
    "void main() {\n"
    "  vec4 eye = view * vec4(pos, 1.0);\n"
    "  pcolor = color_size.rgb;\n"
    "  gl_Position = proj * eye;\n"
    "  gl_PointSize = size_scale * color_size.a / -eye.z;\n"
    "}\n";
static const char* particle_fs =
    "#version 330 core\n"
    "in vec3 pcolor;\n"
    "uniform int marker;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  vec2 p = gl_PointCoord * 2.0 - 1.0;\n"
    "  float r2 = dot(p, p);\n"
    "  if (r2 > 1.0) discard;\n"
    "  float a = (1.0 - r2) * (1.0 - r2);\n"
    "  vec3 c = pcolor;\n"
    "  /* The markers: red grows towards gl_PointCoord.x = 1, green towards .y = 1. */\n"
    "  if (marker != 0) {\n"
    "    c = vec3(gl_PointCoord.x, gl_PointCoord.y, 0.35);\n"
    "    a = 1.0 - r2 * r2;\n"
    "  }\n"
    "  frag = vec4(c * a, a);\n"
    "}\n";

static GLuint solid_prog, particle_prog, sphere_vao, particle_vao, marker_vao;
static float view[16], proj[16];

static unsigned int lcg_state = 12345u;
static float lcg(void) { /* uniform in [0, 1) */
  lcg_state = lcg_state * 1664525u + 1013904223u;
  return (float)(lcg_state >> 8) / 16777216.0f;
}

static void display(void) {
  float vp[16];
  glClearColor(0.02f, 0.02f, 0.05f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  mat_mul(vp, proj, view);

  /* The opaque sphere, depth written. */
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glUseProgram(solid_prog);
  glUniformMatrix4fv(glGetUniformLocation(solid_prog, "mvp"), 1, GL_FALSE, vp);
  glUniform3f(glGetUniformLocation(solid_prog, "center"), 0.13f, 0.41f, 0.07f);
  glUniform1f(glGetUniformLocation(solid_prog, "radius"), 0.83f);
  glBindVertexArray(sphere_vao);
  glDrawElements(GL_TRIANGLES, SPHERE_INDICES, GL_UNSIGNED_SHORT, 0);

  /* The particles: additive, depth-tested, no depth writes. */
  glEnable(GL_PROGRAM_POINT_SIZE);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glUseProgram(particle_prog);
  glUniformMatrix4fv(glGetUniformLocation(particle_prog, "view"), 1, GL_FALSE, view);
  glUniformMatrix4fv(glGetUniformLocation(particle_prog, "proj"), 1, GL_FALSE, proj);
  glUniform1f(glGetUniformLocation(particle_prog, "size_scale"), 30.0f);
  glUniform1i(glGetUniformLocation(particle_prog, "marker"), 0);
  glBindVertexArray(particle_vao);
  glDrawArrays(GL_POINTS, 0, NUM_PARTICLES);

  /* Markers: two big sprites with the default upper-left origin, two with lower-left. */
  glUniform1i(glGetUniformLocation(particle_prog, "marker"), 1);
  glBindVertexArray(marker_vao);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
  glDrawArrays(GL_POINTS, 0, 2);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  glDrawArrays(GL_POINTS, 2, 2);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);

  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_PROGRAM_POINT_SIZE);
  check_gl("display");
  glutSwapBuffers();
}

static GLuint make_points(const float* data, int n) {
  GLuint v, b;
  glGenVertexArrays(1, &v);
  glBindVertexArray(v);
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(n * 7 * sizeof(float)), data, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 7 * sizeof(float), (void*)0);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 7 * sizeof(float), (void*)(3 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  return v;
}

int main(int argc, char** argv) {
  static float pos[SPHERE_VERTS * 3], particles[NUM_PARTICLES * 7];
  static unsigned short idx[SPHERE_INDICES];
  /* Marker sprites: position, colour (unused), size; kept well inside the view. */
  static const float markers[4 * 7] = {
      -2.13f, 1.37f,  0.21f, 0, 0, 0, 8.3f, 2.07f, 1.41f,  0.17f, 0, 0, 0, 8.3f,
      -2.11f, -1.29f, 0.23f, 0, 0, 0, 8.3f, 2.09f, -1.33f, 0.19f, 0, 0, 0, 8.3f};
  GLuint b[2];
  int i;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "point sprite particles");
  solid_prog = link_program(solid_vs, solid_fs);
  particle_prog = link_program(particle_vs, particle_fs);

  make_sphere(pos, idx);
  glGenVertexArrays(1, &sphere_vao);
  glBindVertexArray(sphere_vao);
  glGenBuffers(2, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof pos, pos, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, 0);
  glEnableVertexAttribArray(0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);

  /* A fountain: particles in a cone rising from below the sphere, spread in a shell around it,
   * warm colours near the source, cooler higher up. */
  for (i = 0; i < NUM_PARTICLES; ++i) {
    float* p = &particles[i * 7];
    const float t = lcg(), ang = 6.2831853f * lcg(), spread = 0.25f + 1.6f * t * (0.4f + 0.6f * lcg());
    p[0] = 0.1f + spread * (float)cos(ang);
    p[1] = -1.3f + 3.1f * t;
    p[2] = 0.05f + spread * (float)sin(ang) * 0.8f;
    p[3] = 0.2f + 0.3f * (1.0f - t) * lcg();
    p[4] = 0.06f + 0.15f * lcg() + 0.1f * (1.0f - t);
    p[5] = 0.05f + 0.25f * t * lcg();
    p[6] = 1.0f + 2.0f * lcg(); /* world-ish size, divided by the eye distance */
  }
  particle_vao = make_points(particles, NUM_PARTICLES);
  marker_vao = make_points(markers, 4);

  mat_perspective(proj, 52.0f, 320.0f / 240.0f, 0.5f, 30.0f);
  mat_lookat(view, 0.37f, 0.63f, 6.11f, 0.03f, 0.07f, 0.0f, 0, 1, 0);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
