/*
 * Integer colour buffers in a 3.3 core context (GLUT + GLEW): one framebuffer object with four
 * draw buffers - GL_RGBA8 and GL_RGBA8UI textures, a GL_R32I texture and a GL_RG16UI
 * renderbuffer - written by one fragment shader (vec4, uvec4, int and uvec2 outputs) with
 * blending on, which GL applies to the normalized buffer only. Each buffer is first cleared
 * with glClearBuffer{f,ui,i}v, some values out of the format's range (300 in an 8-bit
 * component). Then the integer results travel every way GL offers: glReadPixels with
 * GL_RED_INTEGER / GL_RGBA_INTEGER into client memory and back into textures, a mirrored
 * glBlitFramebuffer between two RGBA8UI buffers (GL_NEAREST), glCopyTexSubImage2D from the
 * RGBA8UI buffer into an RGBA8UI texture. A last pass draws all of them into the window with
 * texelFetch on usampler2D / isampler2D, and a panel that is green where the values read back
 * are the ones GL's rules give (clamped clears, unblended integers) and red where not.
 */
#include "common.h"

#define W 80
#define H 60

static const char* draw_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 position;\n"
    "layout(location = 1) in vec3 color;\n"
    "out vec3 shade;\n"
    "void main() {\n"
    "  shade = color;\n"
    "  gl_Position = vec4(position, 0.0, 1.0);\n"
    "}\n";

static const char* draw_fs =
    "#version 330 core\n"
    "in vec3 shade;\n"
    "layout(location = 0) out vec4 color;\n"
    "layout(location = 1) out uvec4 id;\n"
    "layout(location = 2) out int value;\n"
    "layout(location = 3) out uvec2 wide;\n"
    "void main() {\n"
    "  ivec2 p = ivec2(gl_FragCoord.xy);\n"
    "  color = vec4(shade, 0.5);\n"
    "  // x * 7 passes 255 right of x = 36: stored clamped\n"
    "  id = uvec4(uint(p.x) * 7u, uint(p.y) * 4u, uint(gl_PrimitiveID) * 60u + 20u, 1000u);\n"
    "  value = (p.x - 40) * (p.y + 3) * 65539 - 7;\n"
    "  wide = uvec2(uint(shade.r * 90000.0), uint(p.x * p.y) * 29u);  // both pass 65535\n"
    "}\n";

static const char* show_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec2 position;\n"
    "void main() { gl_Position = vec4(position, 0.0, 1.0); }\n";

static const char* show_fs =
    "#version 330 core\n"
    "uniform sampler2D colors;\n"
    "uniform usampler2D ids;\n"
    "uniform isampler2D values;\n"
    "uniform isampler2D values_read;\n"
    "uniform usampler2D wide_read;\n"
    "uniform usampler2D blitted;\n"
    "uniform usampler2D copied;\n"
    "out vec4 frag;\n"
    "vec3 bytes(int v) {\n"
    "  vec3 c = vec3((v >> 16) & 255, (v >> 8) & 255, v & 255) / 255.0;\n"
    "  return v < 0 ? c * vec3(1.0, 0.5, 0.5) : c;\n"
    "}\n"
    "bool inside(ivec2 t) {  // the pixel of the cleared rectangle left of the triangles\n"
    "  return t.x < 10 && t.y >= 50;\n"
    "}\n"
    "void main() {\n"
    "  ivec2 q = ivec2(gl_FragCoord.xy);\n"
    "  int panel = q.x / 80 + 4 * (q.y / 120);\n"
    "  ivec2 t = ivec2(q.x % 80, (q.y % 120) / 2);\n"
    "  vec3 c;\n"
    "  if (panel == 0) {\n"
    "    c = texelFetch(colors, t, 0).rgb;\n"
    "  } else if (panel == 1) {\n"
    "    c = vec3(texelFetch(ids, t, 0).rgb) / 255.0;\n"
    "  } else if (panel == 2) {\n"
    "    c = bytes(texelFetch(values, t, 0).r);\n"
    "  } else if (panel == 3) {\n"
    "    uvec4 w = texelFetch(wide_read, t, 0);\n"
    "    c = vec3(float(w.r >> 8u), float(w.g >> 8u), float(w.g & 255u)) / 255.0;\n"
    "    if (w.b != 0u || w.a != 1u) c = vec3(1.0, 0.0, 1.0);\n"
    "  } else if (panel == 4) {\n"
    "    c = bytes(texelFetch(values_read, t, 0).r);\n"
    "  } else if (panel == 5) {\n"
    "    c = vec3(texelFetch(blitted, t, 0).rgb) / 255.0;\n"
    "  } else if (panel == 6) {\n"
    "    c = vec3(texelFetch(copied, t, 0).gba) / 255.0;\n"
    "  } else {\n"
    "    // green where GL's rules hold, red where not\n"
    "    uvec4 id = texelFetch(ids, t, 0);\n"
    "    int v = texelFetch(values, t, 0).r;\n"
    "    uvec4 w = texelFetch(wide_read, t, 0);\n"
    "    bool ok = texelFetch(values_read, t, 0).r == v && texelFetch(copied, t, 0) == id;\n"
    "    ok = ok && texelFetch(blitted, ivec2(79 - t.x, t.y), 0) == id;\n"
    "    if (inside(t)) {\n"
    "      ok = ok && id == uvec4(255u, 7u, 255u, 200u) && v == -123456789;\n"
    "      ok = ok && w == uvec4(65535u, 12345u, 0u, 1u);\n"
    "    } else if (id.a != 200u) {  // a triangle wrote here: alpha 1000 clamped, not blended\n"
    "      ok = ok && id.a == 255u && id.r == min(uint(t.x) * 7u, 255u) && id.g == uint(t.y) * 4u;\n"
    "      ok = ok && v == (t.x - 40) * (t.y + 3) * 65539 - 7;\n"
    "      ok = ok && w.g == min(uint(t.x * t.y) * 29u, 65535u);\n"
    "    }\n"
    "    c = ok ? vec3(0.1, 0.8, 0.2) : vec3(0.9, 0.1, 0.1);\n"
    "  }\n"
    "  frag = vec4(c, 1.0);\n"
    "}\n";

static GLuint draw_prog, show_prog, tri_vao, quad_vao;
static GLuint fbo, blit_fbo, color_tex, id_tex, value_tex, wide_rb, blit_tex, copy_tex, value_read_tex,
    wide_read_tex;

static GLuint texture(GLint internal, GLenum format, GLenum type, const void* data) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, internal, W, H, 0, format, type, data);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}

static void render_offscreen(void) {
  static const GLenum buffers[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                    GL_COLOR_ATTACHMENT3};
  const GLfloat clear_color[4] = {0.1f, 0.1f, 0.2f, 1.0f};
  const GLuint clear_id[4] = {300u, 7u, 65535u, 200u};
  const GLint clear_value[4] = {-123456789, 5, 6, 7};
  const GLuint clear_wide[4] = {70000u, 12345u, 9u, 9u};
  static GLint values[W * H];
  static GLuint wides[W * H * 4];

  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glDrawBuffers(4, buffers);
  glViewport(0, 0, W, H);
  glClearBufferfv(GL_COLOR, 0, clear_color);
  glClearBufferuiv(GL_COLOR, 1, clear_id);
  glClearBufferiv(GL_COLOR, 2, clear_value);
  glClearBufferuiv(GL_COLOR, 3, clear_wide);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE);
  glUseProgram(draw_prog);
  glBindVertexArray(tri_vao);
  glDrawArrays(GL_TRIANGLES, 0, 9);
  glDisable(GL_BLEND);
  check_gl("offscreen draw");

  /* Read back the R32I and RG16UI buffers and upload what came back as textures. */
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glReadBuffer(GL_COLOR_ATTACHMENT2);
  glReadPixels(0, 0, W, H, GL_RED_INTEGER, GL_INT, values);
  glReadBuffer(GL_COLOR_ATTACHMENT3);
  glReadPixels(0, 0, W, H, GL_RGBA_INTEGER, GL_UNSIGNED_INT, wides);
  glBindTexture(GL_TEXTURE_2D, value_read_tex);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, W, H, GL_RED_INTEGER, GL_INT, values);
  glBindTexture(GL_TEXTURE_2D, wide_read_tex);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, W, H, GL_RGBA_INTEGER, GL_UNSIGNED_INT, wides);
  check_gl("read back");

  /* RGBA8UI into RGBA8UI: mirrored in x by a blit, and copied into a texture. */
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, blit_fbo);
  glBlitFramebuffer(0, 0, W, H, W, 0, 0, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, copy_tex);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, W, H);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("blit and copy");
}

static void display(void) {
  const GLuint textures[7] = {color_tex,     id_tex,   value_tex, value_read_tex,
                              wide_read_tex, blit_tex, copy_tex};
  int i;
  render_offscreen();
  glViewport(0, 0, 320, 240);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  for (i = 0; i < 7; ++i) {
    glActiveTexture(GL_TEXTURE0 + i);
    glBindTexture(GL_TEXTURE_2D, textures[i]);
  }
  glUseProgram(show_prog);
  glBindVertexArray(quad_vao);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  check_gl("display");
  glutSwapBuffers();
}

static GLuint vertex_array(const float* data, size_t size, int color) {
  GLuint vao, vbo;
  const GLsizei stride = (GLsizei)((color ? 5 : 2) * sizeof(float));
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)size, data, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, (void*)0);
  glEnableVertexAttribArray(0);
  if (color) {
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, (void*)(2 * sizeof(float)));
    glEnableVertexAttribArray(1);
  }
  return vao;
}

int main(int argc, char** argv) {
  static const float triangles[9 * 5] = {
      -0.7f, -0.9f, 0.9f, 0.2f, 0.1f, 0.9f,  -0.6f,  0.1f, 0.8f, 0.3f, -0.2f, 0.8f,  0.2f,  0.3f, 0.9f,
      -0.1f, 0.2f,  0.9f, 0.9f, 0.2f, 0.95f, 0.95f,  0.3f, 0.2f, 0.9f, -0.4f, 0.95f, 0.6f,  0.6f, 0.6f,
      0.0f,  -0.5f, 0.2f, 0.4f, 1.0f, 0.6f,  -0.95f, 0.9f, 0.9f, 0.9f, 0.7f,  0.4f,  0.95f, 0.5f, 0.2f};
  static const float quad[4 * 2] = {-1.0f, -1.0f, 1.0f, -1.0f, -1.0f, 1.0f, 1.0f, 1.0f};
  static const char* names[7] = {"colors", "ids", "values", "values_read", "wide_read", "blitted", "copied"};
  GLuint fbos[2];
  int i;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "integer render targets");
  draw_prog = link_program(draw_vs, draw_fs);
  show_prog = link_program(show_vs, show_fs);
  tri_vao = vertex_array(triangles, sizeof triangles, 1);
  quad_vao = vertex_array(quad, sizeof quad, 0);

  color_tex = texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  id_tex = texture(GL_RGBA8UI, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, NULL);
  value_tex = texture(GL_R32I, GL_RED_INTEGER, GL_INT, NULL);
  value_read_tex = texture(GL_R32I, GL_RED_INTEGER, GL_INT, NULL);
  wide_read_tex = texture(GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, NULL);
  blit_tex = texture(GL_RGBA8UI, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, NULL);
  copy_tex = texture(GL_RGBA8UI, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, NULL);
  glGenRenderbuffers(1, &wide_rb);
  glBindRenderbuffer(GL_RENDERBUFFER, wide_rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RG16UI, W, H);

  glGenFramebuffers(2, fbos);
  fbo = fbos[0];
  blit_fbo = fbos[1];
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_tex, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, id_tex, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, value_tex, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT3, GL_RENDERBUFFER, wide_rb);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    fprintf(stderr, "integer framebuffer incomplete\n");
    return 1;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, blit_fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, blit_tex, 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    fprintf(stderr, "blit framebuffer incomplete\n");
    return 1;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  glUseProgram(show_prog);
  for (i = 0; i < 7; ++i) glUniform1i(glGetUniformLocation(show_prog, names[i]), i);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
