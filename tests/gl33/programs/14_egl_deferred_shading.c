/*
 * Deferred shading, headless through EGL (a pbuffer), as LearnOpenGL's chapter writes it: a
 * G-buffer FBO with three colour textures (view-space position and normal in RGBA16F, albedo
 * and specular in RGBA8) and a depth renderbuffer, filled by one MRT pass over a floor and
 * instanced spheres; a lighting pass over a full-screen quad reading the three textures with
 * eight point lights from a uniform array of structs; then the G-buffer's depth blitted into
 * the default framebuffer (glBlitFramebuffer, GL_DEPTH_BUFFER_BIT) and the lights drawn as
 * small cubes, forward, depth-tested against it. GL 3.3 core; -lEGL -lOpenGL.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 320
#define H 240
#define NLIGHTS 8
#define SLICES 20
#define STACKS 10
#define NV ((SLICES + 1) * (STACKS + 1))
#define NI (SLICES * STACKS * 6)

static const char* gbuffer_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "layout (location = 1) in vec3 aNormal;\n"
    "layout (location = 2) in vec4 aInstance; // xyz offset, w albedo hue\n"
    "out vec3 FragPos;\n"
    "out vec3 Normal;\n"
    "out vec3 Albedo;\n"
    "uniform mat4 view;\n"
    "uniform mat4 projection;\n"
    "uniform float scale;\n"
    "void main() {\n"
    "  vec4 viewPos = view * vec4(aPos * scale + aInstance.xyz, 1.0);\n"
    "  FragPos = viewPos.xyz;\n"
    "  Normal = mat3(view) * aNormal;\n"
    "  float h = aInstance.w;\n"
    "  Albedo = clamp(abs(fract(vec3(h) + vec3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0, 0.0, 1.0);\n"
    "  gl_Position = projection * viewPos;\n"
    "}\n";
static const char* gbuffer_fs =
    "#version 330 core\n"
    "layout (location = 0) out vec4 gPosition;\n"
    "layout (location = 1) out vec4 gNormal;\n"
    "layout (location = 2) out vec4 gAlbedoSpec;\n"
    "in vec3 FragPos;\n"
    "in vec3 Normal;\n"
    "in vec3 Albedo;\n"
    "void main() {\n"
    "  gPosition = vec4(FragPos, 1.0);\n"
    "  gNormal = vec4(normalize(Normal), 0.0);\n"
    "  gAlbedoSpec = vec4(Albedo, 0.6);\n"
    "}\n";
static const char* light_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec2 aPos;\n"
    "out vec2 TexCoords;\n"
    "void main() { TexCoords = aPos * 0.5 + 0.5; gl_Position = vec4(aPos, 0.0, 1.0); }\n";
static const char* light_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "in vec2 TexCoords;\n"
    "uniform sampler2D gPosition;\n"
    "uniform sampler2D gNormal;\n"
    "uniform sampler2D gAlbedoSpec;\n"
    "struct Light {\n"
    "  vec3 Position;\n"
    "  vec3 Color;\n"
    "  float Linear;\n"
    "  float Quadratic;\n"
    "};\n"
    "const int NR_LIGHTS = 8;\n"
    "uniform Light lights[NR_LIGHTS];\n"
    "void main() {\n"
    "  vec4 P = texture(gPosition, TexCoords);\n"
    "  if (P.w == 0.0) { FragColor = vec4(0.02, 0.02, 0.03, 1.0); return; }\n"
    "  vec3 FragPos = P.xyz;\n"
    "  vec3 Normal = texture(gNormal, TexCoords).rgb;\n"
    "  vec3 Diffuse = texture(gAlbedoSpec, TexCoords).rgb;\n"
    "  float Specular = texture(gAlbedoSpec, TexCoords).a;\n"
    "  vec3 lighting = Diffuse * 0.08;\n"
    "  vec3 viewDir = normalize(-FragPos);\n"
    "  for (int i = 0; i < NR_LIGHTS; ++i) {\n"
    "    vec3 lightDir = normalize(lights[i].Position - FragPos);\n"
    "    vec3 diffuse = max(dot(Normal, lightDir), 0.0) * Diffuse * lights[i].Color;\n"
    "    vec3 halfwayDir = normalize(lightDir + viewDir);\n"
    "    float spec = pow(max(dot(Normal, halfwayDir), 0.0), 16.0);\n"
    "    vec3 specular = lights[i].Color * spec * Specular;\n"
    "    float distance = length(lights[i].Position - FragPos);\n"
    "    float attenuation = 1.0 / (1.0 + lights[i].Linear * distance + lights[i].Quadratic * distance * "
    "distance);\n"
    "    lighting += (diffuse + specular) * attenuation;\n"
    "  }\n"
    "  FragColor = vec4(lighting, 1.0);\n"
    "}\n";
static const char* box_vs =
    "#version 330 core\n"
    "layout (location = 0) in vec3 aPos;\n"
    "uniform mat4 projection;\n"
    "uniform mat4 view;\n"
    "uniform vec3 center;\n"
    "void main() { gl_Position = projection * view * vec4(aPos * 0.12 + center, 1.0); }\n";
static const char* box_fs =
    "#version 330 core\n"
    "out vec4 FragColor;\n"
    "uniform vec3 lightColor;\n"
    "void main() { FragColor = vec4(lightColor, 1.0); }\n";

static void die(const char* what) {
  fprintf(stderr, "egl_deferred_shading: %s failed (EGL 0x%04X, GL 0x%04X)\n", what, eglGetError(),
          glGetError());
  exit(1);
}

static GLuint program(const char* v, const char* f) {
  GLuint p = glCreateProgram();
  const char* src[2] = {v, f};
  GLenum type[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
  GLint ok = 0;
  int i;
  for (i = 0; i < 2; ++i) {
    GLuint s = glCreateShader(type[i]);
    glShaderSource(s, 1, &src[i], NULL);
    glCompileShader(s);
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[2048];
      glGetShaderInfoLog(s, sizeof log, NULL, log);
      fprintf(stderr, "%s\n", log);
      die("glCompileShader");
    }
    glAttachShader(p, s);
    glDeleteShader(s);
  }
  glLinkProgram(p);
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) die("glLinkProgram");
  return p;
}

static GLuint color_texture(GLint internal, GLenum type, GLenum attachment) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, internal, W, H, 0, GL_RGBA, type, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, t, 0);
  return t;
}

int main(void) {
  static const EGLint cfg[] = {EGL_SURFACE_TYPE,
                               EGL_PBUFFER_BIT,
                               EGL_RED_SIZE,
                               8,
                               EGL_GREEN_SIZE,
                               8,
                               EGL_BLUE_SIZE,
                               8,
                               EGL_DEPTH_SIZE,
                               24,
                               EGL_RENDERABLE_TYPE,
                               EGL_OPENGL_BIT,
                               EGL_NONE};
  static const EGLint pb[] = {EGL_WIDTH, W, EGL_HEIGHT, H, EGL_NONE};
  static const EGLint ctx_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  static float sphere[NV * 3];
  static unsigned short sidx[NI];
  static const float floor_v[] = {-6, 0, -6, 0, 1, 0, 6, 0, -6, 0, 1, 0, -6, 0, 6, 0, 1, 0, 6, 0, 6, 0, 1, 0};
  static const float floor_inst[4] = {0, -0.5f, 0, 0.1f};
  static const float quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
  static const float cube[] = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                               -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
  static const unsigned short cidx[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                        2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
  float inst[9 * 4], view[16], proj[16], lpos[NLIGHTS][3], lcol[NLIGHTS][3];
  float sverts[NV * 6];
  EGLDisplay dpy;
  EGLConfig config;
  EGLint n;
  EGLSurface surf;
  EGLContext ctx;
  GLuint gbuf, rbo, tex[3], gprog, lprog, bprog, vao[4], vbo[8];
  GLenum attachments[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  int i, j, k = 0;

  dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (!eglInitialize(dpy, NULL, NULL)) die("eglInitialize");
  if (!eglChooseConfig(dpy, cfg, &config, 1, &n) || n < 1) die("eglChooseConfig");
  surf = eglCreatePbufferSurface(dpy, config, pb);
  eglBindAPI(EGL_OPENGL_API);
  ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctx_attribs);
  if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, surf, surf, ctx)) die("context");

  /* Geometry: a unit sphere (positions = normals), a floor, a cube for the lights. */
  for (j = 0; j <= STACKS; ++j)
    for (i = 0; i <= SLICES; ++i) {
      const double th = 3.14159265358979 * j / STACKS, ph = 2.0 * 3.14159265358979 * i / SLICES;
      sphere[k++] = (float)(sin(th) * cos(ph));
      sphere[k++] = (float)cos(th);
      sphere[k++] = (float)(sin(th) * sin(ph));
    }
  for (i = 0; i < NV; ++i) {
    memcpy(&sverts[i * 6], &sphere[i * 3], 3 * sizeof(float));
    memcpy(&sverts[i * 6 + 3], &sphere[i * 3], 3 * sizeof(float));
  }
  k = 0;
  for (j = 0; j < STACKS; ++j)
    for (i = 0; i < SLICES; ++i) {
      const unsigned short a = (unsigned short)(j * (SLICES + 1) + i), b = (unsigned short)(a + SLICES + 1);
      sidx[k++] = a, sidx[k++] = b, sidx[k++] = (unsigned short)(a + 1);
      sidx[k++] = (unsigned short)(a + 1), sidx[k++] = b, sidx[k++] = (unsigned short)(b + 1);
    }
  for (i = 0; i < 9; ++i) {
    inst[i * 4 + 0] = (float)(i % 3 - 1) * 2.2f;
    inst[i * 4 + 1] = 0.2f;
    inst[i * 4 + 2] = (float)(i / 3 - 1) * 2.2f;
    inst[i * 4 + 3] = (float)i / 9.0f;
  }
  for (i = 0; i < NLIGHTS; ++i) {
    const double a = 2.0 * 3.14159265358979 * i / NLIGHTS + 0.3;
    lpos[i][0] = (float)(3.2 * cos(a));
    lpos[i][1] = 0.8f + 0.3f * (float)(i % 3);
    lpos[i][2] = (float)(3.2 * sin(a));
    lcol[i][0] = 0.5f + 0.5f * (float)((i * 37) % 11) / 10.0f;
    lcol[i][1] = 0.5f + 0.5f * (float)((i * 53) % 13) / 12.0f;
    lcol[i][2] = 0.5f + 0.5f * (float)((i * 71) % 7) / 6.0f;
  }
  /* A camera at (0, 5, 8) looking at the origin (gluLookAt's matrix); 50 degrees high. */
  {
    const float e[3] = {0.0f, 5.0f, 8.0f};
    float f[3] = {-e[0], -e[1], -e[2]}, sv[3], u[3], l;
    l = (float)sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (i = 0; i < 3; ++i) f[i] /= l;
    sv[0] = -f[2], sv[1] = 0.0f, sv[2] = f[0]; /* f x (0, 1, 0) */
    l = (float)sqrt(sv[0] * sv[0] + sv[2] * sv[2]);
    sv[0] /= l, sv[2] /= l;
    u[0] = sv[1] * f[2] - sv[2] * f[1];
    u[1] = sv[2] * f[0] - sv[0] * f[2];
    u[2] = sv[0] * f[1] - sv[1] * f[0];
    memset(view, 0, sizeof view);
    for (i = 0; i < 3; ++i) {
      view[i * 4 + 0] = sv[i];
      view[i * 4 + 1] = u[i];
      view[i * 4 + 2] = -f[i];
    }
    view[12] = -(sv[0] * e[0] + sv[1] * e[1] + sv[2] * e[2]);
    view[13] = -(u[0] * e[0] + u[1] * e[1] + u[2] * e[2]);
    view[14] = f[0] * e[0] + f[1] * e[1] + f[2] * e[2];
    view[15] = 1.0f;
  }
  {
    const float f = 1.0f / (float)tan(25.0 * 3.14159265358979 / 180.0), zn = 0.5f, zf = 30.0f;
    memset(proj, 0, sizeof proj);
    proj[0] = f / ((float)W / H), proj[5] = f;
    proj[10] = (zf + zn) / (zn - zf), proj[11] = -1.0f, proj[14] = 2.0f * zf * zn / (zn - zf);
  }

  gprog = program(gbuffer_vs, gbuffer_fs);
  lprog = program(light_vs, light_fs);
  bprog = program(box_vs, box_fs);
  glGenVertexArrays(4, vao);
  glGenBuffers(8, vbo);
  /* vao 0: spheres, instanced; vao 1: the floor, one instance. */
  for (i = 0; i < 2; ++i) {
    glBindVertexArray(vao[i]);
    glBindBuffer(GL_ARRAY_BUFFER, vbo[i * 3]);
    if (i == 0)
      glBufferData(GL_ARRAY_BUFFER, sizeof sverts, sverts, GL_STATIC_DRAW);
    else
      glBufferData(GL_ARRAY_BUFFER, sizeof floor_v, floor_v, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 24, (void*)0);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 24, (void*)12);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glBindBuffer(GL_ARRAY_BUFFER, vbo[i * 3 + 1]);
    if (i == 0)
      glBufferData(GL_ARRAY_BUFFER, sizeof inst, inst, GL_STATIC_DRAW);
    else
      glBufferData(GL_ARRAY_BUFFER, sizeof floor_inst, floor_inst, GL_STATIC_DRAW);
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, 0, (void*)0);
    glVertexAttribDivisor(2, 1);
    glEnableVertexAttribArray(2);
    if (i == 0) {
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, vbo[2]);
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof sidx, sidx, GL_STATIC_DRAW);
    }
  }
  glBindVertexArray(vao[2]);
  glBindBuffer(GL_ARRAY_BUFFER, vbo[6]);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glEnableVertexAttribArray(0);
  glBindVertexArray(vao[3]);
  glBindBuffer(GL_ARRAY_BUFFER, vbo[7]);
  glBufferData(GL_ARRAY_BUFFER, sizeof cube, cube, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, (void*)0);
  glEnableVertexAttribArray(0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, vbo[5]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof cidx, cidx, GL_STATIC_DRAW);

  /* The G-buffer. */
  glGenFramebuffers(1, &gbuf);
  glBindFramebuffer(GL_FRAMEBUFFER, gbuf);
  tex[0] = color_texture(GL_RGBA16F, GL_FLOAT, GL_COLOR_ATTACHMENT0);
  tex[1] = color_texture(GL_RGBA16F, GL_FLOAT, GL_COLOR_ATTACHMENT1);
  tex[2] = color_texture(GL_RGBA, GL_UNSIGNED_BYTE, GL_COLOR_ATTACHMENT2);
  glDrawBuffers(3, attachments);
  glGenRenderbuffers(1, &rbo);
  glBindRenderbuffer(GL_RENDERBUFFER, rbo);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, W, H);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rbo);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) die("G-buffer completeness");

  /* 1. Geometry pass. */
  glViewport(0, 0, W, H);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glUseProgram(gprog);
  glUniformMatrix4fv(glGetUniformLocation(gprog, "view"), 1, GL_FALSE, view);
  glUniformMatrix4fv(glGetUniformLocation(gprog, "projection"), 1, GL_FALSE, proj);
  glUniform1f(glGetUniformLocation(gprog, "scale"), 0.8f);
  glBindVertexArray(vao[0]);
  glDrawElementsInstanced(GL_TRIANGLES, NI, GL_UNSIGNED_SHORT, 0, 9);
  glUniform1f(glGetUniformLocation(gprog, "scale"), 1.0f);
  glBindVertexArray(vao[1]);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, 1);

  /* 2. Lighting pass into the pbuffer. */
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(lprog);
  glUniform1i(glGetUniformLocation(lprog, "gPosition"), 0);
  glUniform1i(glGetUniformLocation(lprog, "gNormal"), 1);
  glUniform1i(glGetUniformLocation(lprog, "gAlbedoSpec"), 2);
  for (i = 0; i < 3; ++i) {
    glActiveTexture(GL_TEXTURE0 + (GLenum)i);
    glBindTexture(GL_TEXTURE_2D, tex[i]);
  }
  for (i = 0; i < NLIGHTS; ++i) {
    char name[64];
    float v[3];
    for (j = 0; j < 3; ++j)
      v[j] = view[j] * lpos[i][0] + view[4 + j] * lpos[i][1] + view[8 + j] * lpos[i][2] + view[12 + j];
    snprintf(name, sizeof name, "lights[%d].Position", i);
    glUniform3fv(glGetUniformLocation(lprog, name), 1, v);
    snprintf(name, sizeof name, "lights[%d].Color", i);
    glUniform3fv(glGetUniformLocation(lprog, name), 1, lcol[i]);
    snprintf(name, sizeof name, "lights[%d].Linear", i);
    glUniform1f(glGetUniformLocation(lprog, name), 0.35f);
    snprintf(name, sizeof name, "lights[%d].Quadratic", i);
    glUniform1f(glGetUniformLocation(lprog, name), 0.44f);
  }
  glBindVertexArray(vao[2]);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);

  /* 3. The G-buffer's depth into the default framebuffer, then the lights, forward. */
  glBindFramebuffer(GL_READ_FRAMEBUFFER, gbuf);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glEnable(GL_DEPTH_TEST);
  glUseProgram(bprog);
  glUniformMatrix4fv(glGetUniformLocation(bprog, "view"), 1, GL_FALSE, view);
  glUniformMatrix4fv(glGetUniformLocation(bprog, "projection"), 1, GL_FALSE, proj);
  glBindVertexArray(vao[3]);
  for (i = 0; i < NLIGHTS; ++i) {
    glUniform3fv(glGetUniformLocation(bprog, "center"), 1, lpos[i]);
    glUniform3fv(glGetUniformLocation(bprog, "lightColor"), 1, lcol[i]);
    glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_SHORT, 0);
  }
  if (glGetError() != GL_NO_ERROR) die("drawing");
  if (!eglSwapBuffers(dpy, surf)) die("eglSwapBuffers");
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglTerminate(dpy);
  return 0;
}
