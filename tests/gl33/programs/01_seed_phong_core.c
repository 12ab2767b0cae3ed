/*
 * Seed 000's per-pixel Phong shading, as its engine drives it: a GL 3.3 core context through
 * GLUT + GLEW, a VAO with positions and normals at locations 0 and 1 in one VBO, an index
 * buffer (GL_UNSIGNED_SHORT), row-vector matrices uploaded with transpose = GL_TRUE
 * (`vec4(vtxPos, 1) * MVP`), glBindFragDataLocation, and three objects with their own M,
 * Minv and material. The shaders are the lecture's, with the `ka` uniform it uses declared.
 */
#include "common.h"

static const char* vs =
    "#version 330\n"
    "precision highp float;\n"
    "uniform mat4 MVP, M, Minv; // MVP, Model, Model-inverse\n"
    "uniform vec4 wLiPos;           // pos of light source\n"
    "uniform vec3 wEye;            // pos of eye\n"
    "\n"
    "layout(location = 0) in vec3 vtxPos; // model sp. pos\n"
    "layout(location = 1) in vec3 vtxNorm; // model sp. normal\n"
    "\n"
    "out vec3 wNormal;             // normal in world space\n"
    "out vec3 wView;               // view in world space\n"
    "out vec3 wLight;              // light dir in world space\n"
    "\n"
    "void main() {\n"
    "    gl_Position = vec4(vtxPos, 1) * MVP; // to NDC\n"
    "\n"
    "    vec4 wPos = vec4(vtxPos, 1) * M;\n"
    "    wLight = wLiPos.xyz/wLiPos.w - wPos.xyz/wPos.w;\n"
    "    wView = wEye * wPos.w - wPos.xyz;\n"
    "    wNormal = (Minv * vec4(vtxNorm, 0)).xyz;\n"
    "}\n";

static const char* fs =
    "#version 330\n"
    "precision highp float;\n"
    "uniform vec3 kd, ks, ka; // diffuse, specular, ambient ref\n"
    "uniform vec3 La, Le; // ambient and point source rad\n"
    "uniform float shine; // shininess for specular ref\n"
    "in vec3 wNormal; // interpolated world sp normal\n"
    "in vec3 wView; // interpolated world sp view\n"
    "in vec3 wLight; // interpolated world sp illum dir\n"
    "out vec4 fragmentColor; // output goes to frame buffer\n"
    "\n"
    "void main() {\n"
    "    vec3 N = normalize(wNormal);\n"
    "    vec3 V = normalize(wView);\n"
    "    vec3 L = normalize(wLight);\n"
    "    vec3 H = normalize(L + V);\n"
    "    float cost = max(dot(N,L), 0), cosd = max(dot(N,H), 0);\n"
    "    vec3 color = ka * La +\n"
    "        (kd * cost + ks * pow(cosd,shine)) * Le;\n"
    "    fragmentColor = vec4(color, 1);\n"
    "}\n";

static GLuint prog, vao;

static void set_mat(const char* name, const float* column_major) {
  /* The course's mat4 is row-major with row vectors: the same 16 floats, transposed by GL. */
  glUniformMatrix4fv(glGetUniformLocation(prog, name), 1, GL_TRUE, column_major);
}

static void draw_object(const float* model, const float* model_inv, const float* vp, float r, float g,
                        float b, float shine) {
  float mvp[16];
  mat_mul(mvp, vp, model);
  set_mat("M", model);
  set_mat("Minv", model_inv);
  set_mat("MVP", mvp);
  glUniform3f(glGetUniformLocation(prog, "kd"), r, g, b);
  glUniform3f(glGetUniformLocation(prog, "ka"), r * 0.2f, g * 0.2f, b * 0.2f);
  glUniform1f(glGetUniformLocation(prog, "shine"), shine);
  glBindVertexArray(vao);
  glDrawElements(GL_TRIANGLES, SPHERE_INDICES, GL_UNSIGNED_SHORT, 0);
}

static void display(void) {
  float proj[16], view[16], vp[16], m[16], t[16], r[16], minv[16];
  glClearColor(0.1f, 0.12f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(prog);
  mat_perspective(proj, 50.0f, 320.0f / 240.0f, 1.0f, 20.0f);
  mat_translate(view, 0.0f, 0.0f, -6.0f);
  mat_mul(vp, proj, view);
  glUniform4f(glGetUniformLocation(prog, "wLiPos"), 4.0f, 5.0f, 6.0f, 1.0f);
  glUniform3f(glGetUniformLocation(prog, "wEye"), 0.0f, 0.0f, 6.0f);
  glUniform3f(glGetUniformLocation(prog, "ks"), 0.8f, 0.8f, 0.8f);
  glUniform3f(glGetUniformLocation(prog, "La"), 1.0f, 1.0f, 1.0f);
  glUniform3f(glGetUniformLocation(prog, "Le"), 0.9f, 0.9f, 0.9f);

  /* Rotations and translations only: Minv is the inverse, whose transpose (by GL) turns
   * normals as the lecture does. */
  mat_translate(m, -2.0f, 0.0f, 0.0f);
  mat_translate(minv, 2.0f, 0.0f, 0.0f);
  draw_object(m, minv, vp, 0.9f, 0.2f, 0.2f, 20.0f);

  mat_rotate_y(r, 40.0f);
  mat_translate(t, 0.0f, 0.3f, -1.0f);
  mat_mul(m, t, r);
  mat_rotate_y(r, -40.0f);
  mat_translate(t, 0.0f, -0.3f, 1.0f);
  mat_mul(minv, r, t);
  draw_object(m, minv, vp, 0.2f, 0.8f, 0.3f, 60.0f);

  mat_rotate_x(r, 30.0f);
  mat_translate(t, 2.0f, -0.2f, 0.5f);
  mat_mul(m, t, r);
  mat_rotate_x(r, -30.0f);
  mat_translate(t, -2.0f, 0.2f, -0.5f);
  mat_mul(minv, r, t);
  draw_object(m, minv, vp, 0.25f, 0.35f, 0.95f, 5.0f);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static float verts[SPHERE_VERTS * 6], pos[SPHERE_VERTS * 3];
  static unsigned short idx[SPHERE_INDICES];
  GLuint vbo, ibo;
  int i;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "seed phong core");
  make_sphere(pos, idx);
  for (i = 0; i < SPHERE_VERTS; ++i) {
    memcpy(&verts[i * 6], &pos[i * 3], 3 * sizeof(float));
    memcpy(&verts[i * 6 + 3], &pos[i * 3], 3 * sizeof(float)); /* the unit sphere's normal */
  }
  prog = glCreateProgram();
  {
    GLuint v = compile_shader(GL_VERTEX_SHADER, vs), f = compile_shader(GL_FRAGMENT_SHADER, fs);
    GLint ok = 0;
    glAttachShader(prog, v);
    glAttachShader(prog, f);
    glBindFragDataLocation(prog, 0, "fragmentColor");
    glLinkProgram(prog);
    glGetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
      fprintf(stderr, "link failed\n");
      return 1;
    }
  }
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)0);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)(3 * sizeof(float)));
  glGenBuffers(1, &ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
  glBindVertexArray(0);
  glEnable(GL_DEPTH_TEST);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
