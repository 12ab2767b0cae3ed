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

#define LOADER_FUNCTIONS(X)                                          \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                         \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                           \
  X(PFNGLBINDATTRIBLOCATIONPROC, glBindAttribLocation)               \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                               \
  X(PFNGLBINDBUFFERBASEPROC, glBindBufferBase)                       \
  X(PFNGLBINDBUFFERRANGEPROC, glBindBufferRange)                     \
  X(PFNGLBINDFRAGDATALOCATIONPROC, glBindFragDataLocation)           \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                     \
  X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                   \
  X(PFNGLBINDSAMPLERPROC, glBindSampler)                             \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                             \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                     \
  X(PFNGLBLENDEQUATIONPROC, glBlendEquation)                         \
  X(PFNGLBLENDFUNCPROC, glBlendFunc)                                 \
  X(PFNGLBLENDFUNCSEPARATEPROC, glBlendFuncSeparate)                 \
  X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)                     \
  X(PFNGLBUFFERDATAPROC, glBufferData)                               \
  X(PFNGLBUFFERSUBDATAPROC, glBufferSubData)                         \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)       \
  X(PFNGLCLEARPROC, glClear)                                         \
  X(PFNGLCLEARBUFFERFVPROC, glClearBufferfv)                         \
  X(PFNGLCLEARCOLORPROC, glClearColor)                               \
  X(PFNGLCLEARDEPTHPROC, glClearDepth)                               \
  X(PFNGLCLEARSTENCILPROC, glClearStencil)                           \
  X(PFNGLCOLORMASKPROC, glColorMask)                                 \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                         \
  X(PFNGLCOPYBUFFERSUBDATAPROC, glCopyBufferSubData)                 \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                         \
  X(PFNGLCREATESHADERPROC, glCreateShader)                           \
  X(PFNGLCULLFACEPROC, glCullFace)                                   \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                         \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)               \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                         \
  X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)             \
  X(PFNGLDELETESAMPLERSPROC, glDeleteSamplers)                       \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                           \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                       \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)               \
  X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                 \
  X(PFNGLDEPTHMASKPROC, glDepthMask)                                 \
  X(PFNGLDISABLEPROC, glDisable)                                     \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                               \
  X(PFNGLDRAWARRAYSINSTANCEDPROC, glDrawArraysInstanced)             \
  X(PFNGLDRAWBUFFERSPROC, glDrawBuffers)                             \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                           \
  X(PFNGLDRAWELEMENTSBASEVERTEXPROC, glDrawElementsBaseVertex)       \
  X(PFNGLDRAWELEMENTSINSTANCEDPROC, glDrawElementsInstanced)         \
  X(PFNGLDRAWRANGEELEMENTSPROC, glDrawRangeElements)                 \
  X(PFNGLENABLEPROC, glEnable)                                       \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)     \
  X(PFNGLFINISHPROC, glFinish)                                       \
  X(PFNGLFLUSHMAPPEDBUFFERRANGEPROC, glFlushMappedBufferRange)       \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)     \
  X(PFNGLFRAMEBUFFERTEXTUREPROC, glFramebufferTexture)               \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)           \
  X(PFNGLFRAMEBUFFERTEXTURELAYERPROC, glFramebufferTextureLayer)     \
  X(PFNGLFRONTFACEPROC, glFrontFace)                                 \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                               \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                     \
  X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                   \
  X(PFNGLGENSAMPLERSPROC, glGenSamplers)                             \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                             \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                     \
  X(PFNGLGENERATEMIPMAPPROC, glGenerateMipmap)                       \
  X(PFNGLGETERRORPROC, glGetError)                                   \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                             \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                 \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                           \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                   \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                             \
  X(PFNGLGETSTRINGPROC, glGetString)                                 \
  X(PFNGLGETUNIFORMBLOCKINDEXPROC, glGetUniformBlockIndex)           \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)               \
  X(PFNGLLINEWIDTHPROC, glLineWidth)                                 \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                             \
  X(PFNGLMAPBUFFERRANGEPROC, glMapBufferRange)                       \
  X(PFNGLMULTIDRAWARRAYSPROC, glMultiDrawArrays)                     \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                             \
  X(PFNGLPOLYGONMODEPROC, glPolygonMode)                             \
  X(PFNGLPOLYGONOFFSETPROC, glPolygonOffset)                         \
  X(PFNGLPRIMITIVERESTARTINDEXPROC, glPrimitiveRestartIndex)         \
  X(PFNGLREADBUFFERPROC, glReadBuffer)                               \
  X(PFNGLREADPIXELSPROC, glReadPixels)                               \
  X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage)             \
  X(PFNGLSAMPLERPARAMETERFPROC, glSamplerParameterf)                 \
  X(PFNGLSAMPLERPARAMETERIPROC, glSamplerParameteri)                 \
  X(PFNGLSCISSORPROC, glScissor)                                     \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                           \
  X(PFNGLSTENCILFUNCPROC, glStencilFunc)                             \
  X(PFNGLSTENCILMASKPROC, glStencilMask)                             \
  X(PFNGLSTENCILOPPROC, glStencilOp)                                 \
  X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                               \
  X(PFNGLTEXIMAGE3DPROC, glTexImage3D)                               \
  X(PFNGLTEXPARAMETERFPROC, glTexParameterf)                         \
  X(PFNGLTEXPARAMETERFVPROC, glTexParameterfv)                       \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                         \
  X(PFNGLTEXSUBIMAGE2DPROC, glTexSubImage2D)                         \
  X(PFNGLUNIFORM1FPROC, glUniform1f)                                 \
  X(PFNGLUNIFORM1FVPROC, glUniform1fv)                               \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                                 \
  X(PFNGLUNIFORM1IVPROC, glUniform1iv)                               \
  X(PFNGLUNIFORM2FPROC, glUniform2f)                                 \
  X(PFNGLUNIFORM2FVPROC, glUniform2fv)                               \
  X(PFNGLUNIFORM3FPROC, glUniform3f)                                 \
  X(PFNGLUNIFORM3FVPROC, glUniform3fv)                               \
  X(PFNGLUNIFORM4FPROC, glUniform4f)                                 \
  X(PFNGLUNIFORM4FVPROC, glUniform4fv)                               \
  X(PFNGLUNIFORMBLOCKBINDINGPROC, glUniformBlockBinding)             \
  X(PFNGLUNIFORMMATRIX2FVPROC, glUniformMatrix2fv)                   \
  X(PFNGLUNIFORMMATRIX3FVPROC, glUniformMatrix3fv)                   \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                   \
  X(PFNGLUNMAPBUFFERPROC, glUnmapBuffer)                             \
  X(PFNGLTRANSFORMFEEDBACKVARYINGSPROC, glTransformFeedbackVaryings) \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                               \
  X(PFNGLVERTEXATTRIBDIVISORPROC, glVertexAttribDivisor)             \
  X(PFNGLVERTEXATTRIBIPOINTERPROC, glVertexAttribIPointer)           \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)             \
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
#define glBindAttribLocation loader_glBindAttribLocation
#define glBindBuffer loader_glBindBuffer
#define glBindBufferBase loader_glBindBufferBase
#define glBindBufferRange loader_glBindBufferRange
#define glBindFragDataLocation loader_glBindFragDataLocation
#define glBindFramebuffer loader_glBindFramebuffer
#define glBindRenderbuffer loader_glBindRenderbuffer
#define glBindSampler loader_glBindSampler
#define glBindTexture loader_glBindTexture
#define glBindVertexArray loader_glBindVertexArray
#define glBlendEquation loader_glBlendEquation
#define glBlendFunc loader_glBlendFunc
#define glBlendFuncSeparate loader_glBlendFuncSeparate
#define glBlitFramebuffer loader_glBlitFramebuffer
#define glBufferData loader_glBufferData
#define glBufferSubData loader_glBufferSubData
#define glCheckFramebufferStatus loader_glCheckFramebufferStatus
#define glClear loader_glClear
#define glClearBufferfv loader_glClearBufferfv
#define glClearColor loader_glClearColor
#define glClearDepth loader_glClearDepth
#define glClearStencil loader_glClearStencil
#define glColorMask loader_glColorMask
#define glCompileShader loader_glCompileShader
#define glCopyBufferSubData loader_glCopyBufferSubData
#define glCreateProgram loader_glCreateProgram
#define glCreateShader loader_glCreateShader
#define glCullFace loader_glCullFace
#define glDeleteBuffers loader_glDeleteBuffers
#define glDeleteFramebuffers loader_glDeleteFramebuffers
#define glDeleteProgram loader_glDeleteProgram
#define glDeleteRenderbuffers loader_glDeleteRenderbuffers
#define glDeleteSamplers loader_glDeleteSamplers
#define glDeleteShader loader_glDeleteShader
#define glDeleteTextures loader_glDeleteTextures
#define glDeleteVertexArrays loader_glDeleteVertexArrays
#define glDepthFunc loader_glDepthFunc
#define glDepthMask loader_glDepthMask
#define glDisable loader_glDisable
#define glDrawArrays loader_glDrawArrays
#define glDrawArraysInstanced loader_glDrawArraysInstanced
#define glDrawBuffers loader_glDrawBuffers
#define glDrawElements loader_glDrawElements
#define glDrawElementsBaseVertex loader_glDrawElementsBaseVertex
#define glDrawElementsInstanced loader_glDrawElementsInstanced
#define glDrawRangeElements loader_glDrawRangeElements
#define glEnable loader_glEnable
#define glEnableVertexAttribArray loader_glEnableVertexAttribArray
#define glFinish loader_glFinish
#define glFlushMappedBufferRange loader_glFlushMappedBufferRange
#define glFramebufferRenderbuffer loader_glFramebufferRenderbuffer
#define glFramebufferTexture loader_glFramebufferTexture
#define glFramebufferTexture2D loader_glFramebufferTexture2D
#define glFramebufferTextureLayer loader_glFramebufferTextureLayer
#define glFrontFace loader_glFrontFace
#define glGenBuffers loader_glGenBuffers
#define glGenFramebuffers loader_glGenFramebuffers
#define glGenRenderbuffers loader_glGenRenderbuffers
#define glGenSamplers loader_glGenSamplers
#define glGenTextures loader_glGenTextures
#define glGenVertexArrays loader_glGenVertexArrays
#define glGenerateMipmap loader_glGenerateMipmap
#define glGetError loader_glGetError
#define glGetIntegerv loader_glGetIntegerv
#define glGetProgramInfoLog loader_glGetProgramInfoLog
#define glGetProgramiv loader_glGetProgramiv
#define glGetShaderInfoLog loader_glGetShaderInfoLog
#define glGetShaderiv loader_glGetShaderiv
#define glGetString loader_glGetString
#define glGetUniformBlockIndex loader_glGetUniformBlockIndex
#define glGetUniformLocation loader_glGetUniformLocation
#define glLineWidth loader_glLineWidth
#define glLinkProgram loader_glLinkProgram
#define glMapBufferRange loader_glMapBufferRange
#define glMultiDrawArrays loader_glMultiDrawArrays
#define glPixelStorei loader_glPixelStorei
#define glPolygonMode loader_glPolygonMode
#define glPolygonOffset loader_glPolygonOffset
#define glPrimitiveRestartIndex loader_glPrimitiveRestartIndex
#define glReadBuffer loader_glReadBuffer
#define glReadPixels loader_glReadPixels
#define glRenderbufferStorage loader_glRenderbufferStorage
#define glSamplerParameterf loader_glSamplerParameterf
#define glSamplerParameteri loader_glSamplerParameteri
#define glScissor loader_glScissor
#define glShaderSource loader_glShaderSource
#define glStencilFunc loader_glStencilFunc
#define glStencilMask loader_glStencilMask
#define glStencilOp loader_glStencilOp
#define glTexImage2D loader_glTexImage2D
#define glTexImage3D loader_glTexImage3D
#define glTexParameterf loader_glTexParameterf
#define glTexParameterfv loader_glTexParameterfv
#define glTexParameteri loader_glTexParameteri
#define glTexSubImage2D loader_glTexSubImage2D
#define glUniform1f loader_glUniform1f
#define glUniform1fv loader_glUniform1fv
#define glUniform1i loader_glUniform1i
#define glUniform1iv loader_glUniform1iv
#define glUniform2f loader_glUniform2f
#define glUniform2fv loader_glUniform2fv
#define glUniform3f loader_glUniform3f
#define glUniform3fv loader_glUniform3fv
#define glUniform4f loader_glUniform4f
#define glUniform4fv loader_glUniform4fv
#define glUniformBlockBinding loader_glUniformBlockBinding
#define glUniformMatrix2fv loader_glUniformMatrix2fv
#define glUniformMatrix3fv loader_glUniformMatrix3fv
#define glUniformMatrix4fv loader_glUniformMatrix4fv
#define glUnmapBuffer loader_glUnmapBuffer
#define glTransformFeedbackVaryings loader_glTransformFeedbackVaryings
#define glUseProgram loader_glUseProgram
#define glVertexAttribDivisor loader_glVertexAttribDivisor
#define glVertexAttribIPointer loader_glVertexAttribIPointer
#define glVertexAttribPointer loader_glVertexAttribPointer
#define glViewport loader_glViewport

#endif
