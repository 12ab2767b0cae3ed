/*
 * Seed 000's other shaders, verbatim, in its Shader::Create pattern (glBindFragDataLocation
 * before linking): per-vertex (Gouraud) shading with its pass-through pixel shader, and the
 * NPR pixel shader (quantized diffuse and black silhouettes) over the per-pixel vertex
 * shader. As the course framework does, "#version 330" and a precision line come first.
 * GLUT + GLEW with glutInitContextVersion(3, 3) and no profile.
 */
#include "common.h"

#define PRELUDE "#version 330\nprecision highp float;\n"

static const char* gouraud_vs = PRELUDE
    "uniform mat4 MVP, M, Minv; // MVP, Model, Model-inverse\n"
    "uniform vec4 kd, ks, ka; // diffuse, specular, ambient ref\n"
    "uniform float shine; // shininess for specular ref\n"
    "uniform vec4 La, Le; // ambient and point sources\n"
    "uniform vec4 wLiPos; // pos of light source in world\n"
    "uniform vec3 wEye; // pos of eye in world\n"
    "\n"
    "layout(location = 0) in vec3 vtxPos; // pos in modeling space\n"
    "layout(location = 1) in vec3 vtxNorm; // normal in modeling space\n"
    "out vec4 color; // computed vertex color\n"
    "\n"
    "void main() {\n"
    "    gl_Position = vec4(vtxPos, 1) * MVP; // to NDC\n"
    "    vec4 wPos = vec4(vtxPos, 1) * M;\n"
    "    vec3 L = normalize( wLiPos.xyz/wLiPos.w - wPos.xyz/wPos.w );\n"
    "    vec3 V = normalize(wEye - wPos.xyz/wPos.w);\n"
    "    vec4 wNormal = Minv * vec4(vtxNorm, 0);\n"
    "    vec3 N = normalize(wNormal.xyz);\n"
    "    vec3 H = normalize(L + V);\n"
    "    float cost = max(dot(N, L), 0), cosd = max(dot(N, H), 0);\n"
    "    color = ka * La + (kd * cost + ks * pow(cosd, shine)) * Le;\n"
    "}\n";

static const char* gouraud_fs = PRELUDE
    "in vec4 color;           // interpolated color of vertex shader\n"
    "out vec4 fragmentColor; // output goes to frame buffer\n"
    "\n"
    "void main() {\n"
    "    fragmentColor = color;\n"
    "}\n";

static const char* phong_vs = PRELUDE
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

static const char* npr_fs = PRELUDE
    "uniform vec3 kd;           // diffuse ref\n"
    "in  vec3 wNormal, wView, wLight; // interpolated\n"
    "out vec4 fragmentColor;      // output goes to frame buffer\n"
    "\n"
    "void main() {\n"
    "    vec3 N = normalize(wNormal);\n"
    "    vec3 V = normalize(wView);\n"
    "    vec3 L = normalize(wLight);\n"
    "    float y = (dot(N, L) > 0.5) ? 1 : 0.5;\n"
    "    if (abs(dot(N, V)) < 0.2) fragmentColor = vec4(0, 0, 0, 1);\n"
    "    else\n"
    "        fragmentColor = vec4(y * kd, 1);\n"
    "}\n";

/* The seed's Shader::Create. */
static GLuint create(const char* vsSrc, const char* fsSrc, const char* fsOutputName) {
  GLuint vs = compile_shader(GL_VERTEX_SHADER, vsSrc), fs = compile_shader(GL_FRAGMENT_SHADER, fsSrc);
  GLuint shaderProg = glCreateProgram();
  GLint ok = 0;
  glAttachShader(shaderProg, vs);
  glAttachShader(shaderProg, fs);
  glBindFragDataLocation(shaderProg, 0, fsOutputName);
  glLinkProgram(shaderProg);
  glGetProgramiv(shaderProg, GL_LINK_STATUS, &ok);
  if (!ok) exit(1);
  return shaderProg;
}

static GLuint gouraud, npr, vao;

static void set_mat(GLuint prog, const char* name, const float* column_major) {
  glUniformMatrix4fv(glGetUniformLocation(prog, name), 1, GL_TRUE, column_major);
}

static void draw(GLuint prog, float x, float y, float angle, const float* vp) {
  float m[16], t[16], r[16], minv[16], mvp[16];
  mat_rotate_y(r, angle);
  mat_translate(t, x, y, 0.0f);
  mat_mul(m, t, r);
  mat_rotate_y(r, -angle);
  mat_translate(t, -x, -y, 0.0f);
  mat_mul(minv, r, t);
  mat_mul(mvp, vp, m);
  glUseProgram(prog);
  set_mat(prog, "M", m);
  set_mat(prog, "Minv", minv);
  set_mat(prog, "MVP", mvp);
  glUniform4f(glGetUniformLocation(prog, "wLiPos"), 3.0f, 4.0f, 5.0f, 1.0f);
  glUniform3f(glGetUniformLocation(prog, "wEye"), 0.0f, 0.0f, 5.0f);
  glBindVertexArray(vao);
  glDrawElements(GL_TRIANGLES, SPHERE_INDICES, GL_UNSIGNED_SHORT, 0);
}

static void display(void) {
  float proj[16], view[16], vp[16];
  glClearColor(0.85f, 0.85f, 0.8f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  mat_perspective(proj, 45.0f, 320.0f / 240.0f, 1.0f, 20.0f);
  mat_translate(view, 0.0f, 0.0f, -5.0f);
  mat_mul(vp, proj, view);
  glUseProgram(gouraud);
  glUniform4f(glGetUniformLocation(gouraud, "kd"), 0.7f, 0.3f, 0.2f, 1.0f);
  glUniform4f(glGetUniformLocation(gouraud, "ks"), 0.6f, 0.6f, 0.6f, 1.0f);
  glUniform4f(glGetUniformLocation(gouraud, "ka"), 0.15f, 0.05f, 0.05f, 1.0f);
  glUniform1f(glGetUniformLocation(gouraud, "shine"), 30.0f);
  glUniform4f(glGetUniformLocation(gouraud, "La"), 1.0f, 1.0f, 1.0f, 1.0f);
  glUniform4f(glGetUniformLocation(gouraud, "Le"), 1.0f, 1.0f, 1.0f, 1.0f);
  draw(gouraud, -1.2f, 0.0f, 30.0f, vp);
  glUseProgram(npr);
  glUniform3f(glGetUniformLocation(npr, "kd"), 0.2f, 0.5f, 0.9f);
  draw(npr, 1.2f, 0.0f, -20.0f, vp);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static float verts[SPHERE_VERTS * 6], pos[SPHERE_VERTS * 3];
  static unsigned short idx[SPHERE_INDICES];
  GLuint vbo, ibo;
  int i;
  open_window(&argc, argv, 3, 3, 0, "seed gouraud and npr");
  gouraud = create(gouraud_vs, gouraud_fs, "fragmentColor");
  npr = create(phong_vs, npr_fs, "fragmentColor");
  make_sphere(pos, idx);
  for (i = 0; i < SPHERE_VERTS; ++i) {
    memcpy(&verts[i * 6], &pos[i * 3], 3 * sizeof(float));
    memcpy(&verts[i * 6 + 3], &pos[i * 3], 3 * sizeof(float));
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
  glEnable(GL_DEPTH_TEST);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
