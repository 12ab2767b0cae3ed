/*
 * A GL loader in the shape glad generates (the GLFW + glad programs of LearnOpenGL and of
 * courses since 2020 use one): GL/glcorearb.h for the types and enums, a function pointer per
 * entry point under the entry point's own name (a macro, as glad's `#define glGenBuffers
 * glad_glGenBuffers`), and one call that fills them from the window system's GetProcAddress.
 * Include it before GLFW/glfw3.h, as glad's header is.
 */
#ifndef TESSEL_GL33_LOADER_H
#define TESSEL_GL33_LOADER_H

#include <GL/glcorearb.h>
#define __gl_h_ 1 /* glad's header keeps other GL headers out */
#define __GL_H__ 1

#include <stdio.h>

#define LOADER_FUNCTIONS(X)                                      \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                     \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                       \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                           \
  X(PFNGLBINDBUFFERBASEPROC, glBindBufferBase)                   \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                 \
  X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)               \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                         \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                 \
  X(PFNGLBLENDFUNCPROC, glBlendFunc)                             \
  X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)                 \
  X(PFNGLBUFFERDATAPROC, glBufferData)                           \
  X(PFNGLBUFFERSUBDATAPROC, glBufferSubData)                     \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)   \
  X(PFNGLCLEARPROC, glClear)                                     \
  X(PFNGLCLEARCOLORPROC, glClearColor)                           \
  X(PFNGLCLEARSTENCILPROC, glClearStencil)                       \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                     \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                     \
  X(PFNGLCREATESHADERPROC, glCreateShader)                       \
  X(PFNGLCULLFACEPROC, glCullFace)                               \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                       \
  X(PFNGLDEPTHFUNCPROC, glDepthFunc)                             \
  X(PFNGLDEPTHMASKPROC, glDepthMask)                             \
  X(PFNGLDISABLEPROC, glDisable)                                 \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                           \
  X(PFNGLDRAWARRAYSINSTANCEDPROC, glDrawArraysInstanced)         \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                       \
  X(PFNGLENABLEPROC, glEnable)                                   \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray) \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer) \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)       \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                           \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                 \
  X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)               \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                         \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                 \
  X(PFNGLGENERATEMIPMAPPROC, glGenerateMipmap)                   \
  X(PFNGLGETERRORPROC, glGetError)                               \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)             \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                       \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)               \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                         \
  X(PFNGLGETSTRINGPROC, glGetString)                             \
  X(PFNGLGETUNIFORMBLOCKINDEXPROC, glGetUniformBlockIndex)       \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)           \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                         \
  X(PFNGLPOLYGONMODEPROC, glPolygonMode)                         \
  X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage)         \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                       \
  X(PFNGLSTENCILFUNCPROC, glStencilFunc)                         \
  X(PFNGLSTENCILMASKPROC, glStencilMask)                         \
  X(PFNGLSTENCILOPPROC, glStencilOp)                             \
  X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                           \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                     \
  X(PFNGLUNIFORM1FPROC, glUniform1f)                             \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                             \
  X(PFNGLUNIFORM3FPROC, glUniform3f)                             \
  X(PFNGLUNIFORM3FVPROC, glUniform3fv)                           \
  X(PFNGLUNIFORM4FPROC, glUniform4f)                             \
  X(PFNGLUNIFORMBLOCKBINDINGPROC, glUniformBlockBinding)         \
  X(PFNGLUNIFORMMATRIX3FVPROC, glUniformMatrix3fv)               \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)               \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                           \
  X(PFNGLVERTEXATTRIBDIVISORPROC, glVertexAttribDivisor)         \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)         \
  X(PFNGLVIEWPORTPROC, glViewport)

#define LOADER_DECLARE(type, name) static type loader_##name;
LOADER_FUNCTIONS(LOADER_DECLARE)
#undef LOADER_DECLARE

/* What glad's gladLoadGLLoader((GLADloadproc)glfwGetProcAddress) does: 1 when every entry
 * point was found. */
typedef void (*(*loader_proc_fn)(const char* name))(void);
static inline int load_gl(loader_proc_fn get) {
  int ok = 1;
#define LOADER_LOAD(type, name)                     \
  loader_##name = (type)(void (*)(void))get(#name); \
  if (!loader_##name) {                             \
    fprintf(stderr, "loader: no %s\n", #name);      \
    ok = 0;                                         \
  }
  LOADER_FUNCTIONS(LOADER_LOAD)
#undef LOADER_LOAD
  return ok;
}

/* The entry points under their own names, through the pointers. */
#define glActiveTexture loader_glActiveTexture
#define glAttachShader loader_glAttachShader
#define glBindBuffer loader_glBindBuffer
#define glBindBufferBase loader_glBindBufferBase
#define glBindFramebuffer loader_glBindFramebuffer
#define glBindRenderbuffer loader_glBindRenderbuffer
#define glBindTexture loader_glBindTexture
#define glBindVertexArray loader_glBindVertexArray
#define glBlendFunc loader_glBlendFunc
#define glBlitFramebuffer loader_glBlitFramebuffer
#define glBufferData loader_glBufferData
#define glBufferSubData loader_glBufferSubData
#define glCheckFramebufferStatus loader_glCheckFramebufferStatus
#define glClear loader_glClear
#define glClearColor loader_glClearColor
#define glClearStencil loader_glClearStencil
#define glCompileShader loader_glCompileShader
#define glCreateProgram loader_glCreateProgram
#define glCreateShader loader_glCreateShader
#define glCullFace loader_glCullFace
#define glDeleteShader loader_glDeleteShader
#define glDepthFunc loader_glDepthFunc
#define glDepthMask loader_glDepthMask
#define glDisable loader_glDisable
#define glDrawArrays loader_glDrawArrays
#define glDrawArraysInstanced loader_glDrawArraysInstanced
#define glDrawElements loader_glDrawElements
#define glEnable loader_glEnable
#define glEnableVertexAttribArray loader_glEnableVertexAttribArray
#define glFramebufferRenderbuffer loader_glFramebufferRenderbuffer
#define glFramebufferTexture2D loader_glFramebufferTexture2D
#define glGenBuffers loader_glGenBuffers
#define glGenFramebuffers loader_glGenFramebuffers
#define glGenRenderbuffers loader_glGenRenderbuffers
#define glGenTextures loader_glGenTextures
#define glGenVertexArrays loader_glGenVertexArrays
#define glGenerateMipmap loader_glGenerateMipmap
#define glGetError loader_glGetError
#define glGetProgramInfoLog loader_glGetProgramInfoLog
#define glGetProgramiv loader_glGetProgramiv
#define glGetShaderInfoLog loader_glGetShaderInfoLog
#define glGetShaderiv loader_glGetShaderiv
#define glGetString loader_glGetString
#define glGetUniformBlockIndex loader_glGetUniformBlockIndex
#define glGetUniformLocation loader_glGetUniformLocation
#define glLinkProgram loader_glLinkProgram
#define glPolygonMode loader_glPolygonMode
#define glRenderbufferStorage loader_glRenderbufferStorage
#define glShaderSource loader_glShaderSource
#define glStencilFunc loader_glStencilFunc
#define glStencilMask loader_glStencilMask
#define glStencilOp loader_glStencilOp
#define glTexImage2D loader_glTexImage2D
#define glTexParameteri loader_glTexParameteri
#define glUniform1f loader_glUniform1f
#define glUniform1i loader_glUniform1i
#define glUniform3f loader_glUniform3f
#define glUniform3fv loader_glUniform3fv
#define glUniform4f loader_glUniform4f
#define glUniformBlockBinding loader_glUniformBlockBinding
#define glUniformMatrix3fv loader_glUniformMatrix3fv
#define glUniformMatrix4fv loader_glUniformMatrix4fv
#define glUseProgram loader_glUseProgram
#define glVertexAttribDivisor loader_glVertexAttribDivisor
#define glVertexAttribPointer loader_glVertexAttribPointer
#define glViewport loader_glViewport

#endif
