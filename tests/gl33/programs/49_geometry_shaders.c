/*
 * Geometry shaders (GL 3.2, GLSL 1.50 and 3.30) in a 3.3 core context (GLUT + GLEW), six
 * panels of 106x120 pixels:
 *   top left      points in, a triangle strip of five vertices out: a "house" per point, its
 *                 colour from an input interface block (LearnOpenGL's first geometry shader),
 *                 the roof vertex coloured by the shader itself
 *   top middle    triangles in, line strips out: each face normal of a lit sphere drawn as a
 *                 line, over the sphere drawn by a second program without a geometry stage
 *   top right     triangles in, three shrunken triangles out each (EndPrimitive between
 *                 them), coloured by gl_PrimitiveIDIn; the fragment shader reads the
 *                 gl_PrimitiveID the geometry shader writes, and noperspective and flat outputs
 *   bottom left   GL_TRIANGLES_ADJACENCY and GL_TRIANGLE_STRIP_ADJACENCY: lines from the
 *                 centre of each triangle to each of its six inputs, coloured by input index,
 *                 so any other order of gl_in[] shows
 *   bottom middle GL_LINES_ADJACENCY and GL_LINE_STRIP_ADJACENCY likewise, and a GLSL 1.50
 *                 shader that emits points (gl_PointSize with GL_PROGRAM_POINT_SIZE)
 *   bottom right  the adjacency topologies drawn without a geometry shader: the adjacent
 *                 vertices are ignored (GL 3.3 §2.6.1)
 * It also checks what GL reports: the GL_GEOMETRY_* program queries and the
 * GL_INVALID_OPERATION of a mode the geometry shader does not take.
 */
#include <math.h>

#include "common.h"

#define W 106
#define H 120

static const char* house_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 aPos;\n"
    "layout(location = 1) in vec3 aColor;\n"
    "out VS_OUT { vec3 color; } vs_out;\n"
    "void main() {\n"
    "  vs_out.color = aColor;\n"
    "  gl_Position = vec4(aPos, 0.0, 1.0);\n"
    "}\n";
static const char* house_gs =
    "#version 330 core\n"
    "layout(points) in;\n"
    "layout(triangle_strip, max_vertices = 5) out;\n"
    "in VS_OUT { vec3 color; } gs_in[];\n"
    "out vec3 fColor;\n"
    "void build_house(vec4 position) {\n"
    "  fColor = gs_in[0].color;\n"
    "  gl_Position = position + vec4(-0.2, -0.2, 0.0, 0.0); EmitVertex();\n"
    "  gl_Position = position + vec4( 0.2, -0.2, 0.0, 0.0); EmitVertex();\n"
    "  gl_Position = position + vec4(-0.2,  0.2, 0.0, 0.0); EmitVertex();\n"
    "  gl_Position = position + vec4( 0.2,  0.2, 0.0, 0.0); EmitVertex();\n"
    "  gl_Position = position + vec4( 0.0,  0.4, 0.0, 0.0);\n"
    "  fColor = vec3(1.0, 1.0, 1.0);\n"
    "  EmitVertex();\n"
    "  EndPrimitive();\n"
    "}\n"
    "void main() { build_house(gl_in[0].gl_Position); }\n";
static const char* color_fs =
    "#version 330 core\n"
    "in vec3 fColor;\n"
    "out vec4 FragColor;\n"
    "void main() { FragColor = vec4(fColor, 1.0); }\n";

static const char* sphere_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 position;\n"
    "uniform mat4 mvp;\n"
    "out vec3 normal;\n"
    "void main() {\n"
    "  normal = position;\n"
    "  gl_Position = mvp * vec4(position, 1.0);\n"
    "}\n";
static const char* sphere_fs =
    "#version 330 core\n"
    "in vec3 normal;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  float d = max(dot(normalize(normal), normalize(vec3(0.4, 0.6, 0.7))), 0.0);\n"
    "  frag = vec4(vec3(0.15, 0.2, 0.35) + d * vec3(0.5, 0.55, 0.6), 1.0);\n"
    "}\n";
static const char* normals_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 position;\n"
    "out vec3 objpos;\n"
    "void main() { objpos = position; gl_Position = vec4(position, 1.0); }\n";
static const char* normals_gs =
    "#version 330 core\n"
    "layout(triangles) in;\n"
    "layout(line_strip, max_vertices = 2) out;\n"
    "in vec3 objpos[];\n"
    "uniform mat4 mvp;\n"
    "uniform float magnitude;\n"
    "out vec3 fColor;\n"
    "void main() {\n"
    "  vec3 c = (objpos[0] + objpos[1] + objpos[2]) / 3.0;\n"
    "  vec3 n = normalize(cross(objpos[1] - objpos[0], objpos[2] - objpos[0]));\n"
    "  if (dot(n, c) < 0.0) n = -n;\n"
    "  if (dot(n, vec3(0.0, 0.0, 1.0)) < 0.2) return;\n"
    "  fColor = vec3(1.0, 0.9, 0.2);\n"
    "  gl_Position = mvp * vec4(c, 1.0); EmitVertex();\n"
    "  fColor = vec3(1.0, 0.3, 0.1);\n"
    "  gl_Position = mvp * vec4(c + n * magnitude, 1.0); EmitVertex();\n"
    "  EndPrimitive();\n"
    "}\n";

static const char* shrink_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 position;\n"
    "out vec2 uv;\n"
    "void main() { uv = position * 0.5 + 0.5; gl_Position = vec4(position, 0.0, 1.0); }\n";
static const char* shrink_gs =
    "#version 330 core\n"
    "layout(triangles) in;\n"
    "layout(triangle_strip, max_vertices = 9) out;\n"
    "in vec2 uv[];\n"
    "out vec2 st;\n"
    "noperspective out float edge;\n"
    "flat out int sub;\n"
    "void main() {\n"
    "  vec4 c = (gl_in[0].gl_Position + gl_in[1].gl_Position + gl_in[2].gl_Position) / 3.0;\n"
    "  for (int k = 0; k < 3; ++k) {\n"
    "    for (int i = 0; i < 3; ++i) {\n"
    "      int j = (i + k) % 3;\n"
    "      vec4 p = i == 0 ? c : mix(c, gl_in[j].gl_Position, 0.85);\n"
    "      gl_Position = p;\n"
    "      st = i == 0 ? (uv[0] + uv[1] + uv[2]) / 3.0 : uv[j];\n"
    "      edge = i == 0 ? 1.0 : 0.0;\n"
    "      sub = k;\n"
    "      gl_PrimitiveID = gl_PrimitiveIDIn * 3 + k;\n"
    "      EmitVertex();\n"
    "    }\n"
    "    EndPrimitive();\n"
    "  }\n"
    "}\n";
static const char* shrink_fs =
    "#version 330 core\n"
    "in vec2 st;\n"
    "noperspective in float edge;\n"
    "flat in int sub;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  float h = fract(float(gl_PrimitiveID) * 0.618);\n"
    "  vec3 base = vec3(h, 1.0 - h, 0.5 + 0.5 * float(sub) / 2.0);\n"
    "  frag = vec4(base * (0.5 + 0.5 * edge) + vec3(st, 0.0) * 0.2, 1.0);\n"
    "}\n";

static const char* adj_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 position;\n"
    "void main() { gl_Position = vec4(position, 0.0, 1.0); }\n";
/* Lines from the centre of the primitive's main vertices to each input vertex. */
static const char* tri_adj_gs =
    "#version 330 core\n"
    "layout(triangles_adjacency) in;\n"
    "layout(line_strip, max_vertices = 12) out;\n"
    "out vec3 fColor;\n"
    "const vec3 palette[6] = vec3[6](vec3(1, 0.2, 0.2), vec3(0.2, 1, 0.2), vec3(0.3, 0.4, 1),\n"
    "    vec3(1, 1, 0.2), vec3(1, 0.3, 1), vec3(0.2, 1, 1));\n"
    "void main() {\n"
    "  vec4 c = (gl_in[0].gl_Position + gl_in[2].gl_Position + gl_in[4].gl_Position) / 3.0;\n"
    "  for (int i = 0; i < 6; ++i) {\n"
    "    fColor = palette[i];\n"
    "    gl_Position = c; EmitVertex();\n"
    "    gl_Position = mix(c, gl_in[i].gl_Position, 0.9); EmitVertex();\n"
    "    EndPrimitive();\n"
    "  }\n"
    "}\n";
static const char* line_adj_gs =
    "#version 150\n"
    "layout(lines_adjacency) in;\n"
    "layout(line_strip, max_vertices = 8) out;\n"
    "out vec3 fColor;\n"
    "void main() {\n"
    "  vec4 c = (gl_in[1].gl_Position + gl_in[2].gl_Position) * 0.5;\n"
    "  for (int i = 0; i < 4; ++i) {\n"
    "    fColor = vec3(float(i == 0 || i == 3), float(i == 1), float(i >= 2));\n"
    "    gl_Position = c; EmitVertex();\n"
    "    gl_Position = mix(c, gl_in[i].gl_Position, 0.9); EmitVertex();\n"
    "    EndPrimitive();\n"
    "  }\n"
    "}\n";
static const char* points_gs =
    "#version 150\n"
    "layout(points) in;\n"
    "layout(points, max_vertices = 3) out;\n"
    "out vec3 fColor;\n"
    "void main() {\n"
    "  for (int i = 0; i < 3; ++i) {\n"
    "    fColor = vec3(0.3 + 0.3 * float(i), 0.8, 0.9 - 0.3 * float(i));\n"
    "    gl_PointSize = 3.0 + 2.0 * float(i);\n"
    "    gl_Position = gl_in[0].gl_Position + vec4(0.25 * float(i), 0.0, 0.0, 0.0);\n"
    "    EmitVertex();\n"
    "  }\n"
    "}\n";
static const char* plain_fs =
    "#version 330 core\n"
    "out vec4 frag;\n"
    "uniform vec3 color;\n"
    "void main() { frag = vec4(color, 1.0); }\n";

static GLuint house, sphere, normals, shrink, tri_adj, line_adj, points, plain;
static GLuint vao[6];
static GLsizei sphere_count;

static void panel(int col, int row) { glViewport(col * W, row * H, W, H); }

static void display(void) {
  float mvp[16], proj[16], view[16], rot[16], tmp[16];
  glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  /* top left: houses */
  panel(0, 1);
  glUseProgram(house);
  glBindVertexArray(vao[0]);
  glDrawArrays(GL_POINTS, 0, 4);

  /* top middle: a sphere and its face normals */
  panel(1, 1);
  glEnable(GL_DEPTH_TEST);
  mat_perspective(proj, 45.0f, (float)W / (float)H, 0.1f, 10.0f);
  mat_translate(view, 0.0f, 0.0f, -3.2f);
  mat_rotate_y(rot, 25.0f);
  mat_mul(tmp, view, rot);
  mat_mul(mvp, proj, tmp);
  glBindVertexArray(vao[1]);
  glUseProgram(sphere);
  glUniformMatrix4fv(glGetUniformLocation(sphere, "mvp"), 1, GL_FALSE, mvp);
  glDrawElements(GL_TRIANGLES, sphere_count, GL_UNSIGNED_SHORT, 0);
  glUseProgram(normals);
  glUniformMatrix4fv(glGetUniformLocation(normals, "mvp"), 1, GL_FALSE, mvp);
  glUniform1f(glGetUniformLocation(normals, "magnitude"), 0.25f);
  glDrawElements(GL_TRIANGLES, sphere_count, GL_UNSIGNED_SHORT, 0);
  glDisable(GL_DEPTH_TEST);

  /* top right: shrunken sub-triangles of a strip */
  panel(2, 1);
  glUseProgram(shrink);
  glBindVertexArray(vao[2]);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 6);

  /* bottom left: triangles and a triangle strip with adjacency */
  panel(0, 0);
  glUseProgram(tri_adj);
  glBindVertexArray(vao[3]);
  glDrawArrays(GL_TRIANGLES_ADJACENCY, 0, 6);
  glDrawArrays(GL_TRIANGLE_STRIP_ADJACENCY, 6, 10);

  /* bottom middle: lines and a line strip with adjacency, and emitted points */
  panel(1, 0);
  glUseProgram(line_adj);
  glBindVertexArray(vao[4]);
  glDrawArrays(GL_LINES_ADJACENCY, 0, 4);
  glDrawArrays(GL_LINE_STRIP_ADJACENCY, 4, 6);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glUseProgram(points);
  glDrawArrays(GL_POINTS, 10, 2);
  glDisable(GL_PROGRAM_POINT_SIZE);

  /* bottom right: the same adjacency topologies without a geometry shader */
  panel(2, 0);
  glUseProgram(plain);
  glBindVertexArray(vao[3]);
  glUniform3f(glGetUniformLocation(plain, "color"), 0.9f, 0.5f, 0.2f);
  glDrawArrays(GL_TRIANGLES_ADJACENCY, 0, 6);
  glUniform3f(glGetUniformLocation(plain, "color"), 0.3f, 0.7f, 0.9f);
  glDrawArrays(GL_TRIANGLE_STRIP_ADJACENCY, 6, 10);
  glBindVertexArray(vao[4]);
  glUniform3f(glGetUniformLocation(plain, "color"), 1.0f, 1.0f, 1.0f);
  glDrawArrays(GL_LINES_ADJACENCY, 0, 4);
  glDrawArrays(GL_LINE_STRIP_ADJACENCY, 4, 6);

  check_gl("display");
  glutSwapBuffers();
}

static void check_queries(void) {
  GLint v = 0;
  glGetProgramiv(house, GL_GEOMETRY_VERTICES_OUT, &v);
  if (v != 5) fprintf(stderr, "GL_GEOMETRY_VERTICES_OUT %d\n", v);
  glGetProgramiv(house, GL_GEOMETRY_INPUT_TYPE, &v);
  if (v != GL_POINTS) fprintf(stderr, "GL_GEOMETRY_INPUT_TYPE 0x%x\n", v);
  glGetProgramiv(house, GL_GEOMETRY_OUTPUT_TYPE, &v);
  if (v != GL_TRIANGLE_STRIP) fprintf(stderr, "GL_GEOMETRY_OUTPUT_TYPE 0x%x\n", v);
  glGetProgramiv(tri_adj, GL_GEOMETRY_INPUT_TYPE, &v);
  if (v != GL_TRIANGLES_ADJACENCY) fprintf(stderr, "GL_GEOMETRY_INPUT_TYPE 0x%x\n", v);
  glGetProgramiv(plain, GL_GEOMETRY_VERTICES_OUT, &v);
  if (glGetError() != GL_INVALID_OPERATION)
    fprintf(stderr, "no GL_INVALID_OPERATION without a geometry shader\n");
  glGetIntegerv(GL_MAX_GEOMETRY_OUTPUT_VERTICES, &v);
  if (v < 256) fprintf(stderr, "GL_MAX_GEOMETRY_OUTPUT_VERTICES %d\n", v);
  /* A mode the geometry shader does not take. */
  glUseProgram(house);
  glBindVertexArray(vao[0]);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  if (glGetError() != GL_INVALID_OPERATION) fprintf(stderr, "no GL_INVALID_OPERATION for GL_TRIANGLES\n");
  glUseProgram(line_adj);
  glDrawArrays(GL_LINES, 0, 2);
  if (glGetError() != GL_INVALID_OPERATION) fprintf(stderr, "no GL_INVALID_OPERATION for GL_LINES\n");
  glUseProgram(0);
}

int main(int argc, char** argv) {
  static const float houses[4 * 5] = {-0.5f, 0.5f,  1.0f, 0.0f, 0.0f, 0.5f,  0.5f,  0.0f, 1.0f, 0.0f,
                                      0.5f,  -0.5f, 0.0f, 0.0f, 1.0f, -0.5f, -0.5f, 1.0f, 1.0f, 0.0f};
  static const float strip[12] = {-0.9f, -0.8f, -0.6f, 0.7f,  -0.2f, -0.9f,
                                  0.1f,  0.8f,  0.5f,  -0.7f, 0.9f,  0.6f};
  /* 0-5: one triangle with adjacency; 6-15: a strip of three triangles with adjacency */
  static const float tri_adj_xy[32] = {-0.9f, 0.25f, -0.75f, 0.85f, -0.55f, 0.3f,   -0.3f,  0.6f,
                                       -0.6f, 0.85f, -0.95f, 0.75f, -0.85f, -0.8f,  -0.95f, -0.35f,
                                       -0.6f, -0.2f, -0.2f,  0.1f,  -0.35f, -0.85f, 0.0f,   -0.9f,
                                       0.0f,  -0.2f, 0.35f,  0.0f,  0.3f,   -0.8f,  0.7f,   -0.5f};
  /* 0-3: a line with adjacency; 4-9: a line strip with adjacency; 10-11: points */
  static const float line_adj_xy[24] = {-0.9f, 0.1f,  -0.6f, 0.7f,  0.0f,  0.6f,  0.4f,  0.9f,
                                        -0.9f, -0.8f, -0.6f, -0.3f, -0.2f, -0.6f, 0.2f,  -0.2f,
                                        0.6f,  -0.5f, 0.9f,  -0.1f, -0.7f, 0.0f,  -0.1f, 0.1f};
  static float sv[SPHERE_VERTS * 3];
  static unsigned short si[SPHERE_INDICES];
  GLuint b;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "geometry shaders");
  house = link_shaders(house_vs, house_gs, color_fs);
  sphere = link_program(sphere_vs, sphere_fs);
  normals = link_shaders(normals_vs, normals_gs, color_fs);
  shrink = link_shaders(shrink_vs, shrink_gs, shrink_fs);
  tri_adj = link_shaders(adj_vs, tri_adj_gs, color_fs);
  line_adj = link_shaders(adj_vs, line_adj_gs, color_fs);
  points = link_shaders(adj_vs, points_gs, color_fs);
  plain = link_program(adj_vs, plain_fs);

  glGenVertexArrays(1, &vao[0]);
  glBindVertexArray(vao[0]);
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, sizeof houses, houses, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void*)(2 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);

  make_sphere(sv, si);
  sphere_count = SPHERE_INDICES;
  glGenVertexArrays(1, &vao[1]);
  glBindVertexArray(vao[1]);
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, sizeof sv, sv, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glEnableVertexAttribArray(0);
  glGenBuffers(1, &b);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof si, si, GL_STATIC_DRAW);

  vao[2] = vertex_array2(strip, 6);
  vao[3] = vertex_array2(tri_adj_xy, 16);
  vao[4] = vertex_array2(line_adj_xy, 12);
  check_gl("setup");
  check_queries();
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
