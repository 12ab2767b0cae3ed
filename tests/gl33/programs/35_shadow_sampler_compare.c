/*
 * Depth-compare texture lookups in a GL 3.3 core context (GLUT + GLEW): a spotlight's depth
 * texture (GL_DEPTH_COMPONENT24, 512x512, rendered through an FBO with no colour buffer and a
 * polygon offset) read through a sampler2DShadow. The texture itself has
 * GL_TEXTURE_COMPARE_MODE = GL_COMPARE_REF_TO_TEXTURE, GL_TEXTURE_COMPARE_FUNC = GL_LEQUAL and
 * GL_LINEAR filtering (hardware PCF), so textureProj(shadowMap, coord) on texture unit 0 gives
 * the lit fraction of the floor, the cube and the sphere, with a small bias on the reference
 * depth. The same texture is also bound to unit 1 under a sampler object (glGenSamplers,
 * glSamplerParameteri: compare mode, GL_TEXTURE_COMPARE_FUNC = GL_GREATER, linear filters,
 * clamp to border) that overrides the texture's parameters: the upright panel on the right
 * reads it there, so it glows where it is in shadow and stays dark where the light reaches it.
 */
#include "common.h"

#define SHADOW_SIZE 512

static const char* depth_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 pos;\n"
    "uniform mat4 model, light_vp;\n"
    "void main() { gl_Position = light_vp * model * vec4(pos, 1.0); }\n";
static const char* depth_fs =
    "#version 330 core\n"
    "void main() { }\n";

static const char* vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 pos;\n"
    "layout(location = 1) in vec3 nrm;\n"
    "uniform mat4 model, vp, shadow_matrix;\n"
    "out vec3 wpos, wnrm;\n"
    "out vec4 shadow_coord;\n"
    "void main() {\n"
    "  vec4 w = model * vec4(pos, 1.0);\n"
    "  wpos = w.xyz;\n"
    "  wnrm = mat3(model) * nrm;\n"
    "  shadow_coord = shadow_matrix * w;\n"
    "  gl_Position = vp * w;\n"
    "}\n";
static const char* fs =
    "#version 330 core\n"
    "in vec3 wpos, wnrm;\n"
    "in vec4 shadow_coord;\n"
    "uniform sampler2DShadow shadow_map;\n"
    "uniform vec3 light_pos, light_dir, color;\n"
    "uniform bool inverted;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    "  vec3 n = normalize(wnrm);\n"
    "  vec3 l = normalize(light_pos - wpos);\n"
    "  float spot = smoothstep(0.86, 0.93, dot(-l, light_dir));\n"
    "  float diff = max(dot(n, l), 0.0);\n"
    "  /* The bias is on the reference depth, in window-depth units times w. */\n"
    "  vec4 c = vec4(shadow_coord.xy, shadow_coord.z - 0.0015 * shadow_coord.w, shadow_coord.w);\n"
    "  float s = textureProj(shadow_map, c);\n"
    "  if (inverted) {\n"
    "    /* GL_GREATER: 1 where the reference is behind the stored depth, i.e. in shadow. */\n"
    "    frag = vec4(color * 0.15 + vec3(1.0, 0.55, 0.15) * s * spot, 1.0);\n"
    "  } else {\n"
    "    frag = vec4(color * (0.12 + 0.88 * diff * spot * s), 1.0);\n"
    "  }\n"
    "}\n";

static GLuint depth_prog, prog, fbo, shadow_tex, sampler;
static GLuint vao[4];
static GLsizei counts[4];

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
  /* The floor (y = 0) and the panel (x = 0, facing -x, 2.6 wide and 1.9 high). */
  static const float plane[4 * 6] = {-4.3f, 0, -4.1f, 0, 1, 0, 4.3f,  0, -4.1f, 0, 1, 0,
                                     4.3f,  0, 4.1f,  0, 1, 0, -4.3f, 0, 4.1f,  0, 1, 0};
  static const float panel[4 * 6] = {0, 0,    1.3f,  -1, 0, 0, 0, 0,    -1.3f, -1, 0, 0,
                                     0, 1.9f, -1.3f, -1, 0, 0, 0, 1.9f, 1.3f,  -1, 0, 0};
  static const unsigned short qidx[6] = {0, 2, 1, 0, 3, 2};
  float cube[24 * 6];
  unsigned short cidx[36];
  int i, f, k = 0;
  make_sphere(pos, sidx);
  for (i = 0; i < SPHERE_VERTS; ++i) {
    memcpy(&sphere[i * 6], &pos[i * 3], 3 * sizeof(float));
    memcpy(&sphere[i * 6 + 3], &pos[i * 3], 3 * sizeof(float));
  }
  for (f = 0; f < 6; ++f) {
    const int axis = f / 2;
    const float sgn = (f % 2) ? -1.0f : 1.0f;
    for (i = 0; i < 4; ++i) {
      float* v = &cube[(f * 4 + i) * 6];
      v[axis] = 0.5f * sgn;
      v[(axis + 1) % 3] = ((i == 1 || i == 2) ? 0.5f : -0.5f) * sgn;
      v[(axis + 2) % 3] = (i >= 2) ? 0.5f : -0.5f;
      v[3] = v[4] = v[5] = 0.0f;
      v[3 + axis] = sgn;
    }
    cidx[k++] = (unsigned short)(f * 4), cidx[k++] = (unsigned short)(f * 4 + 1);
    cidx[k++] = (unsigned short)(f * 4 + 2), cidx[k++] = (unsigned short)(f * 4);
    cidx[k++] = (unsigned short)(f * 4 + 2), cidx[k++] = (unsigned short)(f * 4 + 3);
  }
  vao[0] = make_mesh(plane, 4, qidx, 6);
  counts[0] = 6;
  vao[1] = make_mesh(cube, 24, cidx, 36);
  counts[1] = 36;
  vao[2] = make_mesh(sphere, SPHERE_VERTS, sidx, SPHERE_INDICES);
  counts[2] = SPHERE_INDICES;
  vao[3] = make_mesh(panel, 4, qidx, 6);
  counts[3] = 6;
}

static void model_of(int i, float* m) {
  float t[16], r[16];
  int j;
  if (i == 0) {
    mat_identity(m);
  } else if (i == 1) {
    mat_translate(t, -0.63f, 0.61f, 0.37f);
    mat_rotate_y(r, 33.0f);
    mat_mul(m, t, r);
    for (j = 0; j < 11; ++j)
      if (j % 4 != 3) m[j] *= 1.21f;
  } else if (i == 2) {
    mat_translate(m, 0.97f, 1.13f, -0.21f);
    m[0] = m[5] = m[10] = 0.53f;
  } else {
    mat_translate(t, 2.37f, 0.0f, -0.43f);
    mat_rotate_y(r, 41.0f);
    mat_mul(m, t, r);
  }
}

static void draw_scene(GLuint p, const float* light_vp, int shaded) {
  static const float colors[4][3] = {
      {0.75f, 0.75f, 0.7f}, {0.85f, 0.35f, 0.25f}, {0.3f, 0.5f, 0.9f}, {0.5f, 0.5f, 0.55f}};
  static const float B[16] = {0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 0.5f, 0, 0.5f, 0.5f, 0.5f, 1};
  float m[16], sm[16];
  int i;
  mat_mul(sm, B, light_vp);
  for (i = 0; i < 4; ++i) {
    model_of(i, m);
    glUniformMatrix4fv(glGetUniformLocation(p, "model"), 1, GL_FALSE, m);
    if (shaded) {
      glUniformMatrix4fv(glGetUniformLocation(p, "shadow_matrix"), 1, GL_FALSE, sm);
      glUniform3fv(glGetUniformLocation(p, "color"), 1, colors[i]);
      /* The panel reads the shadow map on unit 1, through the GL_GREATER sampler object. */
      glUniform1i(glGetUniformLocation(p, "shadow_map"), i == 3 ? 1 : 0);
      glUniform1i(glGetUniformLocation(p, "inverted"), i == 3);
    }
    glBindVertexArray(vao[i]);
    glDrawElements(GL_TRIANGLES, counts[i], GL_UNSIGNED_SHORT, 0);
  }
}

static void display(void) {
  static const float lp[3] = {-3.53f, 3.31f, 2.17f}, target[3] = {0.61f, 0.35f, -0.47f};
  float lview[16], lproj[16], light_vp[16], view[16], proj[16], vp[16], dir[3], len;
  int i;
  mat_lookat(lview, lp[0], lp[1], lp[2], target[0], target[1], target[2], 0, 1, 0);
  mat_perspective(lproj, 62.0f, 1.0f, 2.5f, 14.0f);
  mat_mul(light_vp, lproj, lview);
  for (i = 0; i < 3; ++i) dir[i] = target[i] - lp[i];
  len = (float)sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  for (i = 0; i < 3; ++i) dir[i] /= len;

  /* Pass 1: depth from the spotlight. */
  glEnable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, SHADOW_SIZE, SHADOW_SIZE);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 4.0f);
  glUseProgram(depth_prog);
  glUniformMatrix4fv(glGetUniformLocation(depth_prog, "light_vp"), 1, GL_FALSE, light_vp);
  draw_scene(depth_prog, light_vp, 0);
  glDisable(GL_POLYGON_OFFSET_FILL);

  /* Pass 2: the camera's view; the same depth texture on units 0 and 1. */
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, 320, 240);
  glClearColor(0.06f, 0.06f, 0.08f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  mat_perspective(proj, 50.0f, 320.0f / 240.0f, 1.0f, 30.0f);
  mat_lookat(view, -0.83f, 4.37f, 6.61f, 0.33f, 0.41f, 0.07f, 0, 1, 0);
  mat_mul(vp, proj, view);
  glUseProgram(prog);
  glUniformMatrix4fv(glGetUniformLocation(prog, "vp"), 1, GL_FALSE, vp);
  glUniform3fv(glGetUniformLocation(prog, "light_pos"), 1, lp);
  glUniform3fv(glGetUniformLocation(prog, "light_dir"), 1, dir);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, shadow_tex);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, shadow_tex);
  glBindSampler(1, sampler);
  glActiveTexture(GL_TEXTURE0);
  draw_scene(prog, light_vp, 1);
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static const GLfloat border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "shadow sampler compare");
  depth_prog = link_program(depth_vs, depth_fs);
  prog = link_program(vs, fs);
  build_meshes();

  /* The depth texture: compared with GL_LEQUAL by its own parameters. */
  glGenTextures(1, &shadow_tex);
  glBindTexture(GL_TEXTURE_2D, shadow_tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, SHADOW_SIZE, SHADOW_SIZE, 0, GL_DEPTH_COMPONENT,
               GL_UNSIGNED_INT, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);

  /* The sampler object for unit 1: every parameter the lookup needs, compare func GL_GREATER. */
  glGenSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  glSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, border);
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_FUNC, GL_GREATER);

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
