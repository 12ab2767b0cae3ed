// Helpers the GL 3.3 API tests share (test_gl33_api.cpp, test_gl33_errors.cpp): a current
// context's integer state and a program linked from two sources.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <utility>

namespace gl33test {

inline GLint get_int(GLenum name) {
  GLint v[4] = {};
  glGetIntegerv(name, v);
  return v[0];
}

// A shader object compiled from one source.
inline GLuint shader(GLenum type, const char* src) {
  GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  return s;
}

// Compiles and links a vertex and a fragment shader; the shaders are deleted (the program
// keeps them attached until it goes).
inline GLuint program(const char* vs, const char* fs) {
  GLuint p = glCreateProgram();
  for (auto [type, src] :
       {std::pair{GLenum(GL_VERTEX_SHADER), vs}, std::pair{GLenum(GL_FRAGMENT_SHADER), fs}}) {
    GLuint s = shader(type, src);
    glAttachShader(p, s);
    glDeleteShader(s);
  }
  glLinkProgram(p);
  return p;
}

// A quad over the whole of a [-1, 1] view volume, in immediate mode (compatibility contexts).
inline void window_quad() {
  glBegin(GL_QUADS);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEnd();
}

}  // namespace gl33test
