/*
 * Transform feedback (GL 3.3 §2.15) in a 3.3 core context (GLUT + GLEW), in the ways course
 * and tutorial code uses it, each panel drawing what was captured:
 *   - a particle system stepped on the GPU: 256 particles (position, velocity) updated by a
 *     vertex shader alone into the other of two buffers, 40 times, with GL_RASTERIZER_DISCARD,
 *     then drawn as points (interleaved attributes);
 *   - a geometry shader that turns points into quads, captured as triangles in separate
 *     buffers (gl_Position and a colour), with the last and the first provoking vertex
 *     conventions, drawn back with flat colours (the order of each triangle's vertices shows);
 *   - a triangle strip, a fan and a line loop captured as independent triangles and lines
 *     with integer vertex ids, drawn back flat, the strip while it is also being rasterized,
 *     the fan with the first vertex convention;
 *   - a strip captured with the first vertex convention into a buffer too small for it,
 *     drawn with the count the GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN query gives, and an
 *     instanced draw captured.
 * It checks the queries, glGetTransformFeedbackVarying and the binding state.
 */
#include "common.h"

#define PARTICLES 256
#define STEPS 40

static const char* update_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 pos;\n"
    "layout(location = 1) in vec2 vel;\n"
    "out vec2 out_pos;\n"
    "out vec2 out_vel;\n"
    "uniform float dt;\n"
    "void main() {\n"
    "  vec2 v = vel + vec2(0.0, -1.5) * dt;\n"
    "  vec2 p = pos + v * dt;\n"
    "  if (p.y < -0.9) { p.y = -1.8 - p.y; v.y = -v.y * 0.7; }\n"
    "  if (abs(p.x) > 0.95) { v.x = -v.x; p.x = clamp(p.x, -0.95, 0.95); }\n"
    "  out_pos = p;\n"
    "  out_vel = v;\n"
    "}\n";
static const char* particle_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 pos;\n"
    "layout(location = 1) in vec2 vel;\n"
    "out vec3 colour;\n"
    "void main() {\n"
    "  colour = vec3(0.5 + 0.5 * vel, 1.0 - length(vel));\n"
    "  gl_PointSize = 3.0;\n"
    "  gl_Position = vec4(pos, 0.0, 1.0);\n"
    "}\n";
static const char* colour_fs =
    "#version 330 core\n"
    "in vec3 colour;\n"
    "out vec4 c;\n"
    "void main() { c = vec4(colour, 1.0); }\n";

static const char* quad_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 pos;\n"
    "out vec3 vcol;\n"
    "void main() {\n"
    "  vcol = vec3(fract(float(gl_VertexID) * 0.31), fract(float(gl_VertexID) * 0.57), 0.6);\n"
    "  gl_Position = vec4(pos, 0.0, 1.0);\n"
    "}\n";
static const char* quad_gs =
    "#version 330 core\n"
    "layout(points) in;\n"
    "layout(triangle_strip, max_vertices = 4) out;\n"
    "in vec3 vcol[];\n"
    "out vec3 gcol;\n"
    "void main() {\n"
    "  for (int i = 0; i < 4; ++i) {\n"
    "    gl_Position = gl_in[0].gl_Position + vec4(float(i & 1) * 0.5 - 0.25, float(i >> 1) * 0.5 - 0.25, 0, "
    "0);\n"
    "    gcol = mix(vcol[0], vec3(float(i & 1), float(i >> 1), 1.0 - float(i) / 3.0), 0.7);\n"
    "    EmitVertex();\n"
    "  }\n"
    "}\n";
/* Draws captured positions (vec4) and colours flat. */
static const char* flat_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec4 p;\n"
    "layout(location = 1) in vec3 c;\n"
    "flat out vec3 fc;\n"
    "void main() { fc = c; gl_Position = p; }\n";
static const char* flat_fs =
    "#version 330 core\n"
    "flat in vec3 fc;\n"
    "out vec4 o;\n"
    "void main() { o = vec4(fc, 1.0); }\n";

/* Captures positions and integer ids of a strip, a fan, a loop, with their own colours. */
static const char* id_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 pos;\n"
    "out vec2 p;\n"
    "flat out int id;\n"
    "out vec3 colour;\n"
    "void main() {\n"
    "  p = pos + vec2(0.0, 0.02 * float(gl_InstanceID));\n"
    "  id = gl_VertexID + 100 * gl_InstanceID;\n"
    "  colour = vec3(0.3, 0.3, 0.3);\n"
    "  gl_Position = vec4(p, 0.0, 1.0);\n"
    "}\n";
/* Draws them back: the colour from the id of each primitive's provoking vertex. */
static const char* id_draw_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 p;\n"
    "layout(location = 1) in int id;\n"
    "flat out vec3 fc;\n"
    "void main() {\n"
    "  fc = vec3(fract(float(id) * 0.23), fract(float(id) * 0.61), float(id % 3) * 0.5);\n"
    "  gl_Position = vec4(p, 0.0, 1.0);\n"
    "}\n";

static GLuint update_prog, particle_prog, quad_prog, flat_prog, id_prog, id_draw_prog;
static GLuint particle_vao[2], particle_buf[2];
static GLuint quad_src_vao, quad_pos_buf[3], quad_col_buf[3], quad_vao[3];
static GLuint strip_vao, fan_vao, loop_vao;
static GLuint cap_buf[4], cap_vao[4];
static GLint cap_count[4];
static int current = 0;

/* A vertex array reading vec2 positions and vec2 velocities interleaved from buffer b. */
static GLuint particle_array(GLuint b) {
  GLuint vao;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 16, (void*)0);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 16, (void*)8);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  return vao;
}

/* Positions (vec4) from one buffer and colours (vec3) from another. */
static GLuint flat_array(GLuint pos, GLuint col) {
  GLuint vao;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, pos);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glBindBuffer(GL_ARRAY_BUFFER, col);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  return vao;
}

/* Interleaved vec2 position and int id, as id_vs captures them. */
static GLuint id_array(GLuint b) {
  GLuint vao;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 12, (void*)0);
  glVertexAttribIPointer(1, 1, GL_INT, 12, (void*)8);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  return vao;
}

static GLuint buffer_of(GLsizeiptr bytes) {
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, bytes, NULL, GL_DYNAMIC_COPY);
  return b;
}

/* Captures one draw of id_prog into cap_buf[slot]; returns the primitives written. */
static GLint capture_ids(int slot, GLuint vao, GLenum prim, GLenum mode, GLint count, GLint instances,
                         GLintptr size) {
  GLuint q[2];
  GLuint generated = 0, written = 0;
  glGenQueries(2, q);
  glUseProgram(id_prog);
  glBindVertexArray(vao);
  if (size)
    glBindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, cap_buf[slot], 0, size);
  else
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, cap_buf[slot]);
  glBeginQuery(GL_PRIMITIVES_GENERATED, q[0]);
  glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, q[1]);
  glBeginTransformFeedback(prim);
  glDrawArraysInstanced(mode, 0, count, instances);
  glEndTransformFeedback();
  glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
  glEndQuery(GL_PRIMITIVES_GENERATED);
  glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &generated);
  glGetQueryObjectuiv(q[1], GL_QUERY_RESULT, &written);
  glDeleteQueries(2, q);
  if (!size && generated != written)
    fprintf(stderr, "slot %d: %u generated, %u written\n", slot, generated, written);
  return (GLint)written;
}

static void setup(void) {
  static const char* const particle_names[] = {"out_pos", "out_vel"};
  static const char* const quad_names[] = {"gl_Position", "gcol"};
  static const char* const id_names[] = {"p", "id"};
  float init[PARTICLES * 4];
  float strip[16], fan[14], loop[10];
  int i, step;
  char name[32];
  GLsizei length = 0, size = 0;
  GLenum type = 0;

  update_prog = link_shaders_feedback(update_vs, NULL, NULL, 2, particle_names, GL_INTERLEAVED_ATTRIBS);
  particle_prog = link_program(particle_vs, colour_fs);
  quad_prog = link_shaders_feedback(quad_vs, quad_gs, NULL, 2, quad_names, GL_SEPARATE_ATTRIBS);
  flat_prog = link_program(flat_vs, flat_fs);
  id_prog = link_shaders_feedback(id_vs, NULL, colour_fs, 2, id_names, GL_INTERLEAVED_ATTRIBS);
  id_draw_prog = link_program(id_draw_vs, flat_fs);
  glGetTransformFeedbackVarying(quad_prog, 1, sizeof name, &length, &size, &type, name);
  if (strcmp(name, "gcol") != 0 || length != 4 || size != 1 || type != GL_FLOAT_VEC3)
    fprintf(stderr, "glGetTransformFeedbackVarying: %s %d %d 0x%x\n", name, length, size, type);

  /* The particle system. */
  for (i = 0; i < PARTICLES; ++i) {
    init[i * 4 + 0] = -0.8f + 1.6f * (float)(i % 16) / 15.0f;
    init[i * 4 + 1] = 0.1f + 0.7f * (float)(i / 16) / 15.0f;
    init[i * 4 + 2] = 0.6f * sinf((float)i * 0.7f);
    init[i * 4 + 3] = 0.4f * cosf((float)i * 1.3f);
  }
  for (i = 0; i < 2; ++i) {
    particle_buf[i] = buffer_of(sizeof init);
    particle_vao[i] = particle_array(particle_buf[i]);
  }
  glBindBuffer(GL_ARRAY_BUFFER, particle_buf[0]);
  glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof init, init);
  glUseProgram(update_prog);
  glUniform1f(glGetUniformLocation(update_prog, "dt"), 0.04f);
  glEnable(GL_RASTERIZER_DISCARD);
  for (step = 0; step < STEPS; ++step) {
    glBindVertexArray(particle_vao[current]);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, particle_buf[1 - current]);
    glBeginTransformFeedback(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, PARTICLES);
    glEndTransformFeedback();
    current = 1 - current;
  }

  /* Quads from a geometry shader: captured with each provoking vertex convention. */
  {
    static const float points[8] = {-0.5f, -0.5f, 0.5f, -0.4f, -0.4f, 0.5f, 0.45f, 0.45f};
    quad_src_vao = vertex_array2(points, 4);
  }
  glUseProgram(quad_prog);
  for (i = 0; i < 3; ++i) {
    quad_pos_buf[i] = buffer_of(4 * 6 * 16);
    quad_col_buf[i] = buffer_of(4 * 6 * 12);
    quad_vao[i] = flat_array(quad_pos_buf[i], quad_col_buf[i]);
    glProvokingVertex(i == 0 ? GL_LAST_VERTEX_CONVENTION : GL_FIRST_VERTEX_CONVENTION);
    glBindVertexArray(quad_src_vao);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, quad_pos_buf[i]);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 1, quad_col_buf[i]);
    glBeginTransformFeedback(GL_TRIANGLES);
    glDrawArrays(GL_POINTS, 0, 4);
    glEndTransformFeedback();
  }
  glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
  glDisable(GL_RASTERIZER_DISCARD);

  /* A strip, a fan and a loop with vertex ids. */
  for (i = 0; i < 8; ++i) {
    strip[i * 2] = -0.9f + 0.25f * (float)i;
    strip[i * 2 + 1] = (i & 1) ? 0.6f : 0.0f;
  }
  for (i = 0; i < 7; ++i) {
    const float a = (float)i * 0.45f;
    fan[i * 2] = i == 0 ? 0.0f : 0.9f * cosf(a);
    fan[i * 2 + 1] = i == 0 ? -0.2f : -0.2f + 0.7f * sinf(a);
  }
  for (i = 0; i < 5; ++i) {
    loop[i * 2] = 0.7f * cosf((float)i * 1.2566f + 0.3f);
    loop[i * 2 + 1] = 0.7f * sinf((float)i * 1.2566f + 0.3f);
  }
  strip_vao = vertex_array2(strip, 8);
  fan_vao = vertex_array2(fan, 7);
  loop_vao = vertex_array2(loop, 5);
  for (i = 0; i < 4; ++i) {
    cap_buf[i] = buffer_of(4096);
    cap_vao[i] = id_array(cap_buf[i]);
  }
  glEnable(GL_RASTERIZER_DISCARD);
  /* The fan and the overflowing strip with the first vertex convention: each triangle is
   * written starting at its provoking vertex (a fan's second, an odd strip triangle's first). */
  glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
  cap_count[1] = 3 * capture_ids(1, fan_vao, GL_TRIANGLES, GL_TRIANGLE_FAN, 7, 1, 0);
  /* Three of six triangles fit (3 vertices of 12 bytes each). */
  cap_count[3] = 3 * capture_ids(3, strip_vao, GL_TRIANGLES, GL_TRIANGLE_STRIP, 8, 1, 3 * 36);
  glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
  cap_count[2] = 2 * capture_ids(2, loop_vao, GL_LINES, GL_LINE_LOOP, 5, 1, 0);
  if (cap_count[3] != 9) fprintf(stderr, "overflowed capture wrote %d vertices\n", cap_count[3]);
  glDisable(GL_RASTERIZER_DISCARD);
  {
    GLint bound = -1;
    glGetIntegeri_v(GL_TRANSFORM_FEEDBACK_BUFFER_BINDING, 0, &bound);
    if (bound != (GLint)cap_buf[2]) fprintf(stderr, "GL_TRANSFORM_FEEDBACK_BUFFER_BINDING %d\n", bound);
  }
  check_gl("setup");
}

static void display(void) {
  int i;
  glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_PROGRAM_POINT_SIZE);

  /* Top left: the particles after STEPS steps. */
  glViewport(0, 120, 160, 120);
  glUseProgram(particle_prog);
  glBindVertexArray(particle_vao[current]);
  glDrawArrays(GL_POINTS, 0, PARTICLES);

  /* Top right: the geometry shader's quads, three ways (captured last / first, drawn with
   * the same convention; captured first, drawn with last). */
  glUseProgram(flat_prog);
  for (i = 0; i < 3; ++i) {
    glViewport(160 + i * 53, 160, 53, 80);
    glProvokingVertex(i == 1 ? GL_FIRST_VERTEX_CONVENTION : GL_LAST_VERTEX_CONVENTION);
    glBindVertexArray(quad_vao[i]);
    glDrawArrays(GL_TRIANGLES, 0, 24);
  }
  glProvokingVertex(GL_LAST_VERTEX_CONVENTION);

  /* Bottom: the strip captured while it is drawn (left), and drawn back from the capture
   * (flat, each triangle the colour of its provoking vertex's id); the fan, the loop, and
   * the overflowed strip (each drawn with the convention it was captured with). */
  glViewport(0, 0, 80, 120);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, cap_buf[0]);
  glUseProgram(id_prog);
  glBindVertexArray(strip_vao);
  glBeginTransformFeedback(GL_TRIANGLES);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 8, 2);
  glEndTransformFeedback();
  cap_count[0] = 3 * 6 * 2;
  glUseProgram(id_draw_prog);
  for (i = 0; i < 4; ++i) {
    glViewport(80 + i * 60, 0, 60, 120);
    glProvokingVertex(i == 1 || i == 3 ? GL_FIRST_VERTEX_CONVENTION : GL_LAST_VERTEX_CONVENTION);
    glBindVertexArray(cap_vao[i]);
    glDrawArrays(i == 2 ? GL_LINES : GL_TRIANGLES, 0, cap_count[i]);
  }
  glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  GLint v = 0;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "transform feedback");
  glGetIntegerv(GL_MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS, &v);
  if (v < 4) fprintf(stderr, "GL_MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS %d\n", v);
  setup();
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
