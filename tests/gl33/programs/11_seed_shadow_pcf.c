/*
 * Seed 001's shadow mapping (§XI): the scene rendered from the light into a depth texture
 * through an FBO (glPolygonOffset against acne, glDrawBuffer(GL_NONE)), then from the camera
 * with the shadow matrix B * P_L * V_L * M, and the lecture's shadeWithShadow() with PCF
 * verbatim: four textureProjOffset lookups of a sampler2DShadow with GL_LINEAR filtering
 * (hardware PCF inside each). GL 3.3 core through GLUT + GLEW.
 */
#include "common.h"

#define SHADOW_SIZE 512

static const char* depth_vs =
    "#version 330\n"
    "layout(location = 0) in vec3 VertexPosition;\n"
    "uniform mat4 MVP;\n"
    "void main() { gl_Position = MVP * vec4(VertexPosition, 1.0); }\n";
static const char* depth_fs =
    "#version 330\n"
    "void main() { }\n";

static const char* vs =
    "#version 330\n"
    "layout(location = 0) in vec3 VertexPosition;\n"
    "layout(location = 1) in vec3 VertexNormal;\n"
    "out vec3 Position;\n"
    "out vec3 Normal;\n"
    "out vec4 ShadowCoord;\n"
    "uniform mat4 ModelViewMatrix;\n"
    "uniform mat3 NormalMatrix;\n"
    "uniform mat4 MVP;\n"
    "uniform mat4 ShadowMatrix;\n"
    "void main() {\n"
    "  Position = (ModelViewMatrix * vec4(VertexPosition, 1.0)).xyz;\n"
    "  Normal = normalize(NormalMatrix * VertexNormal);\n"
    "  ShadowCoord = ShadowMatrix * vec4(VertexPosition, 1.0);\n"
    "  gl_Position = MVP * vec4(VertexPosition, 1.0);\n"
    "}\n";

static const char* fs =
    "#version 330\n"
    "uniform vec4 LightPosition; // eye coordinates\n"
    "uniform vec3 LightIntensity;\n"
    "uniform vec3 Kd, Ka, Ks;\n"
    "uniform float Shininess;\n"
    "uniform sampler2DShadow ShadowMap;\n"
    "in vec3 Position;\n"
    "in vec3 Normal;\n"
    "in vec4 ShadowCoord;\n"
    "layout(location = 0) out vec4 FragColor;\n"
    "\n"
    "vec3 phongModelDiffAndSpec() {\n"
    "  vec3 n = Normal;\n"
    "  if (!gl_FrontFacing) n = -n;\n"
    "  vec3 s = normalize(vec3(LightPosition) - Position);\n"
    "  vec3 v = normalize(-Position.xyz);\n"
    "  vec3 r = reflect(-s, n);\n"
    "  float sDotN = max(dot(s, n), 0.0);\n"
    "  vec3 diffuse = LightIntensity * Kd * sDotN;\n"
    "  vec3 spec = vec3(0.0);\n"
    "  if (sDotN > 0.0) spec = LightIntensity * Ks * pow(max(dot(r, v), 0.0), Shininess);\n"
    "  return diffuse + spec;\n"
    "}\n"
    "\n"
    "// after using PCF\n"
    "void shadeWithShadow()\n"
    "{\n"
    "  vec3 ambient = LightIntensity * Ka; // ambient\n"
    "  vec3 diffSpec = phongModelDiffAndSpec(); // diffuse and specular\n"
    "  \n"
    "  // The sum of the comparisons with nearby texels\n"
    "  float sum = 0.0;\n"
    "  \n"
    "  // Sum contributions from texels around ShadowCoord\n"
    "  sum += textureProjOffset(ShadowMap, ShadowCoord, ivec2(-1,-1));\n"
    "  sum += textureProjOffset(ShadowMap, ShadowCoord, ivec2(-1,1));\n"
    "  sum += textureProjOffset(ShadowMap, ShadowCoord, ivec2(1,1));\n"
    "  sum += textureProjOffset(ShadowMap, ShadowCoord, ivec2(1,-1));\n"
    "  float shadow = sum * 0.25;\n"
    "  \n"
    "  FragColor = vec4(diffSpec * shadow + ambient, 1.0);\n"
    "}\n"
    "\n"
    "void main() { shadeWithShadow(); }\n";

static GLuint depth_prog, prog, fbo, shadow_tex;
static GLuint vao[3];
static GLsizei counts[3];
static float light_view[16], light_proj[16];

/* A mesh of positions and normals (6 floats per vertex), unsigned short indices. */
static GLuint make_mesh(const float* verts, int nverts, const unsigned short* idx, int nidx) {
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

static void build_meshes(void) {
  static float sphere[SPHERE_VERTS * 6], pos[SPHERE_VERTS * 3];
  static unsigned short sidx[SPHERE_INDICES];
  static const float plane[4 * 6] = {-5, 0, -5, 0, 1, 0, 5,  0, -5, 0, 1, 0,
                                     5,  0, 5,  0, 1, 0, -5, 0, 5,  0, 1, 0};
  static const unsigned short pidx[6] = {0, 2, 1, 0, 3, 2};
  float cube[24 * 6];
  unsigned short cidx[36];
  int i, f, k = 0;
  make_sphere(pos, sidx);
  for (i = 0; i < SPHERE_VERTS; ++i) {
    memcpy(&sphere[i * 6], &pos[i * 3], 3 * sizeof(float));
    memcpy(&sphere[i * 6 + 3], &pos[i * 3], 3 * sizeof(float));
  }
  /* A unit cube: four vertices per face with the face normal. */
  for (f = 0; f < 6; ++f) {
    const int axis = f / 2;
    const float sgn = (f % 2) ? -1.0f : 1.0f;
    for (i = 0; i < 4; ++i) {
      float p[3], n[3] = {0, 0, 0};
      const float a = (i == 1 || i == 2) ? 0.5f : -0.5f, b = (i >= 2) ? 0.5f : -0.5f;
      p[axis] = 0.5f * sgn;
      p[(axis + 1) % 3] = a * sgn;
      p[(axis + 2) % 3] = b;
      n[axis] = sgn;
      memcpy(&cube[(f * 4 + i) * 6], p, sizeof p);
      memcpy(&cube[(f * 4 + i) * 6 + 3], n, sizeof n);
    }
    cidx[k++] = (unsigned short)(f * 4);
    cidx[k++] = (unsigned short)(f * 4 + 1);
    cidx[k++] = (unsigned short)(f * 4 + 2);
    cidx[k++] = (unsigned short)(f * 4);
    cidx[k++] = (unsigned short)(f * 4 + 2);
    cidx[k++] = (unsigned short)(f * 4 + 3);
  }
  vao[0] = make_mesh(plane, 4, pidx, 6);
  counts[0] = 6;
  vao[1] = make_mesh(cube, 24, cidx, 36);
  counts[1] = 36;
  vao[2] = make_mesh(sphere, SPHERE_VERTS, sidx, SPHERE_INDICES);
  counts[2] = SPHERE_INDICES;
}

static void model_of(int i, float* m) {
  float t[16], r[16];
  if (i == 0) {
    mat_identity(m);
  } else if (i == 1) {
    mat_translate(t, -1.2f, 0.75f, 0.3f);
    mat_rotate_y(r, 30.0f);
    mat_mul(m, t, r);
    m[0] *= 1.5f, m[1] *= 1.5f, m[2] *= 1.5f;
    m[4] *= 1.5f, m[5] *= 1.5f, m[6] *= 1.5f;
    m[8] *= 1.5f, m[9] *= 1.5f, m[10] *= 1.5f;
  } else {
    mat_translate(m, 1.3f, 0.8f, -0.4f);
    m[0] = m[5] = m[10] = 0.8f;
  }
}

static void draw_scene(int shadow_pass, const float* view, const float* proj) {
  int i;
  for (i = 0; i < 3; ++i) {
    float model[16], mv[16], mvp[16];
    model_of(i, model);
    mat_mul(mv, view, model);
    mat_mul(mvp, proj, mv);
    if (shadow_pass) {
      glUniformMatrix4fv(glGetUniformLocation(depth_prog, "MVP"), 1, GL_FALSE, mvp);
    } else {
      static const float B[16] = {0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 0.5f, 0, 0.5f, 0.5f, 0.5f, 1};
      float shadow[16], nm[9], lvm[16];
      int r, c;
      /* B * P_L * V_L * M */
      mat_mul(lvm, light_view, model);
      mat_mul(shadow, light_proj, lvm);
      mat_mul(shadow, B, shadow);
      /* The normal matrix: the model-view's upper 3x3 (rotations and uniform scales). */
      for (c = 0; c < 3; ++c)
        for (r = 0; r < 3; ++r) nm[c * 3 + r] = mv[c * 4 + r];
      glUniformMatrix4fv(glGetUniformLocation(prog, "ModelViewMatrix"), 1, GL_FALSE, mv);
      glUniformMatrix3fv(glGetUniformLocation(prog, "NormalMatrix"), 1, GL_FALSE, nm);
      glUniformMatrix4fv(glGetUniformLocation(prog, "MVP"), 1, GL_FALSE, mvp);
      glUniformMatrix4fv(glGetUniformLocation(prog, "ShadowMatrix"), 1, GL_FALSE, shadow);
      if (i == 0)
        glUniform3f(glGetUniformLocation(prog, "Kd"), 0.7f, 0.7f, 0.6f);
      else if (i == 1)
        glUniform3f(glGetUniformLocation(prog, "Kd"), 0.8f, 0.3f, 0.2f);
      else
        glUniform3f(glGetUniformLocation(prog, "Kd"), 0.2f, 0.4f, 0.9f);
    }
    glBindVertexArray(vao[i]);
    glDrawElements(GL_TRIANGLES, counts[i], GL_UNSIGNED_SHORT, 0);
  }
}

static void display(void) {
  float view[16], proj[16], lp[4] = {3.0f, 6.0f, 2.0f, 1.0f}, elp[4];
  int i;
  /* Pass 1: depth from the light. */
  mat_lookat(light_view, lp[0], lp[1], lp[2], 0, 0, 0, 0, 1, 0);
  mat_perspective(light_proj, 60.0f, 1.0f, 3.0f, 12.0f);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, SHADOW_SIZE, SHADOW_SIZE);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.5f, 10.0f);
  glUseProgram(depth_prog);
  draw_scene(1, light_view, light_proj);
  glDisable(GL_POLYGON_OFFSET_FILL);
  /* Pass 2: the camera's view, shadowed. */
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, 320, 240);
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  mat_lookat(view, -2.0f, 4.0f, 7.0f, 0.0f, 0.5f, 0.0f, 0, 1, 0);
  mat_perspective(proj, 45.0f, 320.0f / 240.0f, 1.0f, 30.0f);
  glUseProgram(prog);
  for (i = 0; i < 4; ++i)
    elp[i] = view[i] * lp[0] + view[4 + i] * lp[1] + view[8 + i] * lp[2] + view[12 + i] * lp[3];
  glUniform4fv(glGetUniformLocation(prog, "LightPosition"), 1, elp);
  glUniform3f(glGetUniformLocation(prog, "LightIntensity"), 0.85f, 0.85f, 0.85f);
  glUniform3f(glGetUniformLocation(prog, "Ka"), 0.12f, 0.12f, 0.14f);
  glUniform3f(glGetUniformLocation(prog, "Ks"), 0.4f, 0.4f, 0.4f);
  glUniform1f(glGetUniformLocation(prog, "Shininess"), 30.0f);
  glUniform1i(glGetUniformLocation(prog, "ShadowMap"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, shadow_tex);
  draw_scene(0, view, proj);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  GLfloat border[4] = {1.0f, 0.0f, 0.0f, 0.0f};
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "seed shadow map pcf");
  depth_prog = link_program(depth_vs, depth_fs);
  prog = link_program(vs, fs);
  build_meshes();
  glEnable(GL_DEPTH_TEST);

  /* The shadow map: a depth texture compared by the sampler (GL_COMPARE_REF_TO_TEXTURE). */
  glGenTextures(1, &shadow_tex);
  glBindTexture(GL_TEXTURE_2D, shadow_tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, SHADOW_SIZE, SHADOW_SIZE, 0, GL_DEPTH_COMPONENT,
               GL_FLOAT, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LESS);

  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow_tex, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    fprintf(stderr, "shadow framebuffer incomplete\n");
    return 1;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
