// The ARB and EXT names of GL 1.0 to 3.3 entry points, for code written against the
// extensions before they became core (glGenFramebuffersEXT, glBindBufferARB,
// glActiveTextureARB, ...): each is the core entry point under another name, as the Khronos
// registry's <alias> says (ext_aliases.inc, generated with the headers by
// scripts/gen_gl_headers.py). The extensions all of whose entry points are here are listed
// in a compatibility context's GL_EXTENSIONS (context.cpp, ext_names.inc).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include "api.hpp"

using namespace tessel::gl;

extern "C" {

#define TESSEL_ALIAS(ret, name, core, params, args) \
  ret GLAPIENTRY name params { return core args; }
#include "ext_aliases.inc"
#undef TESSEL_ALIAS

// The two EXT_framebuffer_object calls the registry does not alias: they may bind a name no
// glGen* call returned, making the object (EXT_framebuffer_object §4.4.1, §4.4.2.1), which is
// what glBindFramebuffer and glBindRenderbuffer do in a compatibility context.
void GLAPIENTRY glBindFramebufferEXT(GLenum target, GLuint framebuffer) {
  glBindFramebuffer(target, framebuffer);
}
void GLAPIENTRY glBindRenderbufferEXT(GLenum target, GLuint renderbuffer) {
  glBindRenderbuffer(target, renderbuffer);
}

// ARB_shader_objects' calls over both kinds of object (shaders and programs share one name
// space, as in Mesa): each goes to the shader or the program call of GL 2.0 (ARB_shader_objects
// §2.14.1-2.14.3 and §6.1.14; the GL_OBJECT_*_ARB names of the queries are the GL 2.0 values).
void GLAPIENTRY glDeleteObjectARB(GLhandleARB obj) {
  if (glIsProgram(obj))
    glDeleteProgram(obj);
  else
    glDeleteShader(obj);  // a shader, or GL_INVALID_VALUE for a name that is neither (0 is ignored)
}
GLhandleARB GLAPIENTRY glGetHandleARB(GLenum pname) {
  GL_CONTEXT(0);
  GL_OUTSIDE_BEGIN(0);
  if (pname != GL_PROGRAM_OBJECT_ARB) {
    c.error(GL_INVALID_ENUM);
    return 0;
  }
  GLint current = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  return GLhandleARB(current);
}
void GLAPIENTRY glGetObjectParameterivARB(GLhandleARB obj, GLenum pname, GLint* params) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  const bool program = c.programs.count(obj) != 0, shader = c.shaders.count(obj) != 0;
  if (!program && !shader) return c.error(GL_INVALID_VALUE);
  if (!params) return;
  if (pname == GL_OBJECT_TYPE_ARB) {
    *params = program ? GL_PROGRAM_OBJECT_ARB : GL_SHADER_OBJECT_ARB;
    return;
  }
  if (pname == GL_OBJECT_SUBTYPE_ARB) {
    if (program) return c.error(GL_INVALID_ENUM);
    pname = GL_SHADER_TYPE;
  }
  if (program)
    glGetProgramiv(obj, pname, params);
  else
    glGetShaderiv(obj, pname, params);
}
void GLAPIENTRY glGetObjectParameterfvARB(GLhandleARB obj, GLenum pname, GLfloat* params) {
  GL_CONTEXT();
  // The integer query, written only when it raised no error; the first error is kept.
  const GLenum before = c.take_error();
  GLint v = 0;
  glGetObjectParameterivARB(obj, pname, &v);
  const GLenum err = c.take_error();
  if (err == GL_NO_ERROR && params) *params = GLfloat(v);
  c.error(before != GL_NO_ERROR ? before : err);
}
void GLAPIENTRY glGetInfoLogARB(GLhandleARB obj, GLsizei max_length, GLsizei* length, GLcharARB* log) {
  if (glIsProgram(obj))
    glGetProgramInfoLog(obj, max_length, length, log);
  else
    glGetShaderInfoLog(obj, max_length, length, log);
}
void GLAPIENTRY glGetAttachedObjectsARB(GLhandleARB container, GLsizei max_count, GLsizei* count,
                                        GLhandleARB* objects) {
  glGetAttachedShaders(container, max_count, count, objects);
}

}  // extern "C"
