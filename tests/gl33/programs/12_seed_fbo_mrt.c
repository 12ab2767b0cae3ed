/*
 * Seed 001's FBO example (§XI) as the lecture writes it: two RGBA8 textures at
 * GL_COLOR_ATTACHMENT2 and 3, a GL_DEPTH_COMPONENT renderbuffer, glDrawBuffers with the two,
 * each cleared by glClearBufferfv to the lecture's lightGreen and lightRed, a lit sphere
 * rendered into both at once (MRT: the shaded colour and the normal), then the two textures
 * drawn side by side in the window, the second one minified through glGenerateMipmap.
 * GL 3.3 core through GLUT + GLEW.
 */
#include "common.h"

#define FBO_W 256
#define FBO_H 256

static const char* scene_vs =
    "#version 330\n"
    "layout(location = 0) in vec3 VertexPosition;\n"
    "uniform mat4 MVP;\n"
    "uniform mat3 NormalMatrix;\n"
    "out vec3 Normal;\n"
    "void main() {\n"
    "  Normal = NormalMatrix * VertexPosition;\n"
    "  gl_Position = MVP * vec4(VertexPosition, 1.0);\n"
    "}\n";
static const char* scene_fs =
    "#version 330\n"
    "in vec3 Normal;\n"
    "layout(location = 0) out vec4 Shaded;\n"
    "layout(location = 1) out vec4 NormalColor;\n"
    "void main() {\n"
    "  vec3 n = normalize(Normal);\n"
    "  float d = max(dot(n, normalize(vec3(0.5, 0.7, 1.0))), 0.0);\n"
    "  Shaded = vec4(vec3(0.9, 0.6, 0.2) * (0.15 + 0.85 * d), 1.0);\n"
    "  NormalColor = vec4(n * 0.5 + 0.5, 1.0);\n"
    "}\n";
static const char* quad_vs =
    "#version 330\n"
    "layout(location = 0) in vec2 Corner;\n"
    "uniform vec4 Rect; // x0, y0, x1, y1 in NDC\n"
    "out vec2 TexCoord;\n"
    "void main() {\n"
    "  TexCoord = Corner;\n"
    "  gl_Position = vec4(mix(Rect.xy, Rect.zw, Corner), 0.0, 1.0);\n"
    "}\n";
static const char* quad_fs =
    "#version 330\n"
    "in vec2 TexCoord;\n"
    "uniform sampler2D Tex;\n"
    "out vec4 FragColor;\n"
    "void main() { FragColor = texture(Tex, TexCoord); }\n";

static GLuint scene_prog, quad_prog, fboHandle, renderTexA, renderTexB, depthBuf, sphere_vao, quad_vao;

static void renderTextureScene(void) {
  float proj[16], view[16], rot[16], mv[16], mvp[16], nm[9];
  int r, c;
  mat_perspective(proj, 40.0f, 1.0f, 1.0f, 10.0f);
  mat_translate(view, 0.0f, 0.0f, -4.0f);
  mat_rotate_y(rot, 25.0f);
  mat_mul(mv, view, rot);
  mat_mul(mvp, proj, mv);
  for (c = 0; c < 3; ++c)
    for (r = 0; r < 3; ++r) nm[c * 3 + r] = mv[c * 4 + r];
  glUseProgram(scene_prog);
  glUniformMatrix4fv(glGetUniformLocation(scene_prog, "MVP"), 1, GL_FALSE, mvp);
  glUniformMatrix3fv(glGetUniformLocation(scene_prog, "NormalMatrix"), 1, GL_FALSE, nm);
  glBindVertexArray(sphere_vao);
  glDrawElements(GL_TRIANGLES, SPHERE_INDICES, GL_UNSIGNED_SHORT, 0);
}

static void draw_quad(GLuint tex, float x0, float y0, float x1, float y1) {
  glUseProgram(quad_prog);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, tex);
  glUniform1i(glGetUniformLocation(quad_prog, "Tex"), 0);
  glUniform4f(glGetUniformLocation(quad_prog, "Rect"), x0, y0, x1, y1);
  glBindVertexArray(quad_vao);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

/* The lecture's code as it is written (clang-format leaves it so). */
/* clang-format off */
static void display(void) {
  // DRAW TO TEXTURES
  // Bind to texture's FBO
  glBindFramebuffer(GL_FRAMEBUFFER, fboHandle);

  glViewport(0, 0, FBO_W, FBO_H); // Viewport for the texture
  glClear(GL_DEPTH_BUFFER_BIT);

  // Use glClearBufferfv() to individually clear color buffers
  const GLfloat lightGreen[4] = { 0.5f, 1.0f, 0.5f, 1.0f };
  const GLfloat lightRed[4] = { 1.0f, 0.5f, 0.5f, 1.0f };
  glClearBufferfv(GL_COLOR, 0, lightGreen);
  glClearBufferfv(GL_COLOR, 1, lightRed);

  renderTextureScene();

  // DRAW FINAL FRAME
  // Unbind texture's FBO (back to default FB)
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, 320, 240); // Viewport for main window
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  /* The second texture minified 4x: mipmaps made from what was rendered. */
  glBindTexture(GL_TEXTURE_2D, renderTexB);
  glGenerateMipmap(GL_TEXTURE_2D);
  draw_quad(renderTexA, -0.95f, -0.6f, -0.05f, 0.6f);
  draw_quad(renderTexB, 0.05f, -0.3f, 0.45f, 0.233f);
  check_gl("display");
  glutSwapBuffers();
}
/* clang-format on */

int main(int argc, char** argv) {
  static float pos[SPHERE_VERTS * 3];
  static unsigned short idx[SPHERE_INDICES];
  static const float corners[8] = {0, 0, 1, 0, 0, 1, 1, 1};
  GLuint b[3];
  int fboWidth = FBO_W, fboHeight = FBO_H;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "seed fbo mrt");
  scene_prog = link_program(scene_vs, scene_fs);
  quad_prog = link_program(quad_vs, quad_fs);
  make_sphere(pos, idx);
  glGenVertexArrays(1, &sphere_vao);
  glBindVertexArray(sphere_vao);
  glGenBuffers(3, b);
  glBindBuffer(GL_ARRAY_BUFFER, b[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof pos, pos, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, 0);
  glEnableVertexAttribArray(0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
  glGenVertexArrays(1, &quad_vao);
  glBindVertexArray(quad_vao);
  glBindBuffer(GL_ARRAY_BUFFER, b[2]);
  glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, 0);
  glEnableVertexAttribArray(0);
  glEnable(GL_DEPTH_TEST);

  /* clang-format off */
  // Generate and bind the framebuffer
  glGenFramebuffers(1, &fboHandle);
  glBindFramebuffer(GL_FRAMEBUFFER, fboHandle);

  // Create first texture object
  glGenTextures(1, &renderTexA);
  glActiveTexture(GL_TEXTURE0); // Use texture unit 0
  glBindTexture(GL_TEXTURE_2D, renderTexA);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, fboWidth, fboHeight, 0,
    GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

  // Attach first texture to FBO
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2,
    GL_TEXTURE_2D, renderTexA, 0);

  // ... second texture object as above
  glGenTextures(1, &renderTexB);
  glBindTexture(GL_TEXTURE_2D, renderTexB);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, fboWidth, fboHeight, 0,
    GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT3,
    GL_TEXTURE_2D, renderTexB, 0);

  // Create the depth buffer
  glGenRenderbuffers(1, &depthBuf);
  glBindRenderbuffer(GL_RENDERBUFFER, depthBuf);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT,
    fboWidth, fboHeight);

  // Bind the depth buffer to the FBO
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
    GL_RENDERBUFFER, depthBuf);

  // Set the target for the fragment shader outputs
  GLenum drawBufs[] = { GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3 };
  glDrawBuffers(2, drawBufs);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    fprintf(stderr, "framebuffer incomplete\n");
    return 1;
  }

  // Unbind the framebuffer, and revert to default
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  /* clang-format on */
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
