// The GL 2.0-3.3 entry points (buffer objects, vertex array objects, shaders, programs,
// uniforms, the draw calls): each error case GL 3.3 lists gives its error and changes no
// state, draws give the pixels they should, and a randomized sequence of those calls —
// buffers mapped and deleted while in use, objects deleted while bound, draws past the ends
// of buffers — never crashes (this file is also built with AddressSanitizer).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "../../src/gl/context.hpp"
#include "../../src/gl/proc_address.hpp"
#include "gl33_test_util.hpp"

namespace {

struct GL33Test : ::testing::Test {
  tessel::gl::Context ctx{32, 32, false, true, true};
  void SetUp() override { tessel::gl::make_current(&ctx); }
  void TearDown() override { tessel::gl::make_current(nullptr); }
};

// A core 3.3 context, as glutInitContextVersion(3, 3) gives.
struct GL33CoreTest : GL33Test {
  void SetUp() override {
    ctx.set_version(3, 3, true);
    tessel::gl::make_current(&ctx);
  }
};

GLenum err() { return glGetError(); }

using gl33test::get_int;
using gl33test::program;
using gl33test::window_quad;

const char* kVs =
    "#version 330\nlayout(location = 0) in vec2 pos;\nuniform vec2 offset;\n"
    "void main() { gl_Position = vec4(pos + offset, 0.0, 1.0); }\n";
const char* kFs =
    "#version 330\nuniform vec4 color;\nuniform sampler2D tex;\nout vec4 c;\n"
    "void main() { c = color + 0.0 * texture(tex, vec2(0.5)); }\n";

// The centre pixel of the colour buffer, RGBA8.
std::array<GLubyte, 4> centre() {
  std::array<GLubyte, 4> px{};
  glReadPixels(16, 16, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  return px;
}

TEST_F(GL33Test, VersionAndLimits) {
  EXPECT_EQ(get_int(GL_MAJOR_VERSION), 2);
  EXPECT_STREQ(reinterpret_cast<const char*>(glGetString(GL_VERSION)), "2.1 Tessel 0.1");
  EXPECT_EQ(get_int(GL_MAX_VERTEX_ATTRIBS), 16);
  EXPECT_GE(get_int(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS), 48);
  EXPECT_EQ(get_int(GL_NUM_EXTENSIONS), GLint(tessel::gl::extensions(ctx).size()));
  EXPECT_NE(glGetStringi(GL_EXTENSIONS, 0), nullptr);
  EXPECT_EQ(glGetStringi(GL_EXTENSIONS, 1000), nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

// Code from before the calls were core: EXT_framebuffer_object, ARB_vertex_buffer_object and
// ARB_shader_objects by their own names (the registry's aliases, and the hand-written calls),
// listed in the compatibility context's extensions and by GetProcAddress.
TEST_F(GL33Test, ExtensionNamesAreTheCoreCalls) {
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  for (const char* e : {"GL_EXT_framebuffer_object ", "GL_ARB_vertex_buffer_object ",
                        "GL_ARB_shader_objects ", "GL_ARB_multitexture ", "GL_EXT_framebuffer_blit "})
    EXPECT_NE(ext.find(e), std::string::npos) << e;
  EXPECT_NE(tessel::gl::proc_address("glGenFramebuffersEXT"), nullptr);
  EXPECT_NE(tessel::gl::proc_address("glGetObjectParameterivARB"), nullptr);
  EXPECT_EQ(tessel::gl::proc_address("glGenFramebuffersNV"), nullptr);

  // Render to a texture through the EXT names: a name bound without glGen* is made (§4.4.1).
  GLuint tex = 0, depth = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 77);
  EXPECT_EQ(glIsFramebufferEXT(77), GL_TRUE);
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, tex, 0);
  glGenRenderbuffersEXT(1, &depth);
  glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, depth);
  glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, 8, 8);
  glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, depth);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT), GLenum(GL_FRAMEBUFFER_COMPLETE_EXT));
  glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  std::array<GLubyte, 4> px{};
  glReadPixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  EXPECT_EQ(px, (std::array<GLubyte, 4>{0, 255, 0, 255}));
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
  GLuint fbo = 77;
  glDeleteFramebuffersEXT(1, &fbo);
  glDeleteRenderbuffersEXT(1, &depth);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));

  // ARB_shader_objects: handles, the object queries, the log, the current program.
  const char* vs = "void main() { gl_Position = ftransform(); }";
  const char* bad = "void main() { gl_FragColor = nonsense; }";
  const GLhandleARB v = glCreateShaderObjectARB(GL_VERTEX_SHADER_ARB);
  const GLhandleARB f = glCreateShaderObjectARB(GL_FRAGMENT_SHADER_ARB);
  glShaderSourceARB(v, 1, &vs, nullptr);
  glShaderSourceARB(f, 1, &bad, nullptr);
  glCompileShaderARB(v);
  glCompileShaderARB(f);
  GLint status = -1, type = 0, length = 0;
  glGetObjectParameterivARB(v, GL_OBJECT_COMPILE_STATUS_ARB, &status);
  EXPECT_EQ(status, GL_TRUE);
  glGetObjectParameterivARB(f, GL_OBJECT_COMPILE_STATUS_ARB, &status);
  EXPECT_EQ(status, GL_FALSE);
  glGetObjectParameterivARB(f, GL_OBJECT_TYPE_ARB, &type);
  EXPECT_EQ(type, GL_SHADER_OBJECT_ARB);
  glGetObjectParameterivARB(f, GL_OBJECT_SUBTYPE_ARB, &type);
  EXPECT_EQ(type, GL_FRAGMENT_SHADER_ARB);
  glGetObjectParameterivARB(f, GL_OBJECT_INFO_LOG_LENGTH_ARB, &length);
  EXPECT_GT(length, 1);
  std::vector<GLcharARB> log(size_t(length) + 1, 'x');
  glGetInfoLogARB(f, length, nullptr, log.data());
  EXPECT_NE(std::string(log.data()).find("nonsense"), std::string::npos);
  const GLhandleARB p = glCreateProgramObjectARB();
  glAttachObjectARB(p, v);
  glLinkProgramARB(p);
  GLfloat linked = -1.0f;
  glGetObjectParameterfvARB(p, GL_OBJECT_LINK_STATUS_ARB, &linked);
  EXPECT_EQ(linked, 1.0f);
  glGetObjectParameterivARB(p, GL_OBJECT_TYPE_ARB, &type);
  EXPECT_EQ(type, GL_PROGRAM_OBJECT_ARB);
  GLsizei count = 0;
  GLhandleARB attached[2] = {0, 0};
  glGetAttachedObjectsARB(p, 2, &count, attached);
  EXPECT_EQ(count, 1);
  EXPECT_EQ(attached[0], v);
  glUseProgramObjectARB(p);
  EXPECT_EQ(glGetHandleARB(GL_PROGRAM_OBJECT_ARB), p);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  // Errors: a pname the call does not take, a name that is no object (the value untouched).
  GLfloat kept = 5.0f;
  glGetObjectParameterfvARB(9999, GL_OBJECT_TYPE_ARB, &kept);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(kept, 5.0f);
  glGetObjectParameterivARB(p, GL_OBJECT_SUBTYPE_ARB, &type);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glGetHandleARB(GL_VERTEX_SHADER_ARB), 0u);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glUseProgramObjectARB(0);
  glDeleteObjectARB(p);
  glDeleteObjectARB(v);
  glDeleteObjectARB(f);
  EXPECT_EQ(glIsProgram(p), GL_FALSE);
  EXPECT_EQ(glIsShader(f), GL_FALSE);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

TEST_F(GL33CoreTest, CoreVersionStrings) {
  EXPECT_STREQ(reinterpret_cast<const char*>(glGetString(GL_VERSION)), "3.3 (Core Profile) Tessel 0.1");
  EXPECT_STREQ(reinterpret_cast<const char*>(glGetString(GL_SHADING_LANGUAGE_VERSION)), "3.30");
  EXPECT_EQ(get_int(GL_CONTEXT_PROFILE_MASK), GL_CONTEXT_CORE_PROFILE_BIT);
  // The extension string is glGetStringi's alone in a core context (GL 3.3 core §6.1.5).
  EXPECT_EQ(glGetString(GL_EXTENSIONS), nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
}

TEST_F(GL33Test, BufferErrorsChangeNothing) {
  GLuint b = 0;
  glGenBuffers(-1, &b);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glGenBuffers(1, &b);
  EXPECT_FALSE(glIsBuffer(b));  // a name, not yet an object
  glBindBuffer(0x1234, b);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glBindBuffer(GL_ARRAY_BUFFER, b);
  EXPECT_TRUE(glIsBuffer(b));
  const float data[4] = {1, 2, 3, 4};
  glBufferData(GL_ARRAY_BUFFER, -1, data, GL_STATIC_DRAW);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glBufferData(GL_ARRAY_BUFFER, sizeof data, data, 0x1234);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glBufferData(GL_ARRAY_BUFFER, sizeof data, data, GL_STATIC_DRAW);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  GLint size = 0;
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &size);
  EXPECT_EQ(size, 16);
  // Past the end: GL_INVALID_VALUE, the contents unchanged.
  const float two[2] = {9, 9};
  glBufferSubData(GL_ARRAY_BUFFER, 12, sizeof two, two);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  float back[4] = {};
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, sizeof back, back);
  EXPECT_EQ(std::memcmp(back, data, sizeof back), 0);
  // No buffer bound to the target: GL_INVALID_OPERATION.
  glBufferData(GL_COPY_READ_BUFFER, 4, data, GL_STATIC_DRAW);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // Mapping: the flags' rules, then writes through the mapping.
  EXPECT_EQ(glMapBufferRange(GL_ARRAY_BUFFER, 0, 8, 0), nullptr);  // neither read nor write
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(glMapBufferRange(GL_ARRAY_BUFFER, 8, 16, GL_MAP_WRITE_BIT), nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(glMapBufferRange(GL_ARRAY_BUFFER, 0, 8, GL_MAP_READ_BIT | GL_MAP_INVALIDATE_RANGE_BIT), nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  auto* p = static_cast<float*>(glMapBufferRange(GL_ARRAY_BUFFER, 4, 8, GL_MAP_WRITE_BIT));
  ASSERT_NE(p, nullptr);
  p[0] = 7;
  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY), nullptr);  // already mapped
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glBufferSubData(GL_ARRAY_BUFFER, 0, 4, data);  // mapped
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  EXPECT_TRUE(glUnmapBuffer(GL_ARRAY_BUFFER));
  EXPECT_FALSE(glUnmapBuffer(GL_ARRAY_BUFFER));
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, sizeof back, back);
  EXPECT_EQ(back[1], 7.0f);
  // Copies: overlapping ranges of one buffer are GL_INVALID_VALUE.
  glBindBuffer(GL_COPY_READ_BUFFER, b);
  glBindBuffer(GL_COPY_WRITE_BUFFER, b);
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 4, 8);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 8, 8);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, sizeof back, back);
  EXPECT_EQ(back[2], 1.0f);
  EXPECT_EQ(back[3], 7.0f);
  // Deleting unbinds it from the context's binding points.
  glDeleteBuffers(1, &b);
  EXPECT_EQ(get_int(GL_ARRAY_BUFFER_BINDING), 0);
  EXPECT_FALSE(glIsBuffer(b));
}

TEST_F(GL33CoreTest, CoreBindsOnlyGeneratedNames) {
  glBindBuffer(GL_ARRAY_BUFFER, 77);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glBindVertexArray(5);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // No vertex array object bound: attribute state and draws are errors.
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // GL_QUADS is not a core primitive.
  GLuint vao;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  // Indices must be in a buffer.
  const GLubyte idx[3] = {0, 1, 2};
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, idx);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
}

// GL 3.2 core removed the fixed-function, immediate-mode, display-list and client-array calls
// (appendix E.2.2): in a core context each is GL_INVALID_OPERATION and changes nothing, as
// Mesa's core contexts answer; the capabilities, hints and polygon faces the core profile
// dropped are GL_INVALID_ENUM. The same calls work in a compatibility context.
TEST_F(GL33CoreTest, RemovedCallsAreInvalidOperationsAndChangeNothing) {
  // (The state is read from the context: a core context's glGet of it is GL_INVALID_ENUM.)
  const GLenum mode = ctx.s.transform.matrix_mode;
  glMatrixMode(GL_PROJECTION);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(ctx.s.transform.matrix_mode, mode);
  glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(ctx.s.current.color[0], 1.0f);
  glBegin(GL_TRIANGLES);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glVertex3f(0, 0, 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glEnd();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(glGenLists(1), 0u);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(glIsList(1), GLboolean(GL_FALSE));
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(glRenderMode(GL_SELECT), 0);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  float light[4] = {-7, -7, -7, -7};
  glGetLightfv(GL_LIGHT0, GL_POSITION, light);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(light[0], -7.0f);  // nothing written
  glEnableClientState(GL_VERTEX_ARRAY);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glAlphaFunc(GL_LESS, 0.5f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glRectf(0, 0, 1, 1);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glLoadIdentity();
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glShadeModel(GL_FLAT);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(ctx.s.light.shade_model, GLenum(GL_SMOOTH));
  int shade = 0;
  glGetIntegerv(GL_SHADE_MODEL, &shade);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));

  // Capabilities the core profile dropped, and the kept ones.
  for (GLenum cap : {GL_LIGHTING, GL_LIGHT0, GL_TEXTURE_2D, GL_FOG, GL_ALPHA_TEST, GL_COLOR_MATERIAL,
                     GL_NORMALIZE, GL_POINT_SPRITE, GL_TEXTURE_GEN_S, GL_LINE_STIPPLE}) {
    glEnable(cap);
    EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM)) << std::hex << cap;
    EXPECT_EQ(glIsEnabled(cap), GLboolean(GL_FALSE));
    EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM)) << std::hex << cap;
  }
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GLboolean(GL_FALSE));
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  for (GLenum cap : {GL_BLEND, GL_CLIP_DISTANCE0, GL_DEPTH_CLAMP, GL_PROGRAM_POINT_SIZE,
                     GL_SAMPLE_ALPHA_TO_COVERAGE, GL_TEXTURE_CUBE_MAP_SEAMLESS, GL_PRIMITIVE_RESTART}) {
    glEnable(cap);
    EXPECT_EQ(err(), GLenum(GL_NO_ERROR)) << std::hex << cap;
    EXPECT_EQ(glIsEnabled(cap), GLboolean(GL_TRUE));
    glDisable(cap);
  }
  glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glHint(GL_GENERATE_MIPMAP_HINT, GL_NICEST);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_NICEST);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glPolygonMode(GL_FRONT, GL_LINE);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_POLYGON_MODE), GL_FILL);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  // Point parameters: the core profile keeps the fade threshold and the sprite origin.
  glPointParameterf(GL_POINT_SIZE_MIN, 2.0f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_POINT_SPRITE_COORD_ORIGIN), GL_LOWER_LEFT);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_FRONT);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_POINT_SPRITE_COORD_ORIGIN), GL_LOWER_LEFT);
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, -1.0f);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
}

// Each call's error as GL 3.3 lists it and as Mesa's llvmpipe answers it (the same calls were
// run on both through EGL; where they differ, the comment says why Tessel keeps its answer),
// and the state a failed call leaves alone.
#define EXPECT_GL(call, e)                       \
  do {                                           \
    call;                                        \
    EXPECT_EQ(glGetError(), GLenum(e)) << #call; \
  } while (0)

TEST_F(GL33CoreTest, ErrorsOfDrawsBuffersBindingsQueriesSyncsAndFramebuffers) {
  GLuint vao, vbo, ebo;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, 64, nullptr, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glGenBuffers(1, &ebo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, 64, nullptr, GL_STATIC_DRAW);
  const char* vs =
      "#version 330\nlayout(location=0) in vec2 p; layout(std140) uniform B { vec4 k; };\n"
      "void main() { gl_Position = vec4(p, 0, 1) + k; }\n";
  const GLuint pr = program(vs, "#version 330\nout vec4 o; void main() { o = vec4(1); }\n");
  glUseProgram(pr);
  ASSERT_EQ(err(), GLenum(GL_NO_ERROR));

  // Draws.
  EXPECT_GL(glDrawArrays(0x99, 0, 3), GL_INVALID_ENUM);
  EXPECT_GL(glDrawArrays(GL_TRIANGLES, 0, -1), GL_INVALID_VALUE);
  EXPECT_GL(glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, nullptr), GL_INVALID_ENUM);
  EXPECT_GL(glDrawRangeElements(GL_TRIANGLES, 5, 2, 3, GL_UNSIGNED_SHORT, nullptr), GL_INVALID_VALUE);
  EXPECT_GL(glDrawArraysInstanced(GL_TRIANGLES, 0, 3, -1), GL_INVALID_VALUE);
  const GLint first[1] = {0};
  const GLsizei count[1] = {3};
  EXPECT_GL(glMultiDrawArrays(GL_TRIANGLES, first, count, -1), GL_INVALID_VALUE);
  // A mapped buffer in use by a draw: GL 3.3 §2.9.3 makes it GL_INVALID_OPERATION (Mesa draws).
  glMapBufferRange(GL_ARRAY_BUFFER, 0, 16, GL_MAP_WRITE_BIT);
  EXPECT_GL(glDrawArrays(GL_TRIANGLES, 0, 3), GL_INVALID_OPERATION);
  glUnmapBuffer(GL_ARRAY_BUFFER);

  // Mapping.
  EXPECT_GL(glMapBufferRange(GL_ARRAY_BUFFER, 0, 0, GL_MAP_WRITE_BIT), GL_INVALID_OPERATION);
  EXPECT_GL(glMapBufferRange(GL_ARRAY_BUFFER, 0, 16, GL_MAP_READ_BIT | GL_MAP_INVALIDATE_RANGE_BIT),
            GL_INVALID_OPERATION);
  EXPECT_GL(glMapBufferRange(GL_ARRAY_BUFFER, 0, 16, GL_MAP_READ_BIT | GL_MAP_FLUSH_EXPLICIT_BIT),
            GL_INVALID_OPERATION);
  EXPECT_GL(glMapBufferRange(GL_ARRAY_BUFFER, 60, 16, GL_MAP_WRITE_BIT), GL_INVALID_VALUE);
  EXPECT_GL(glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, 4), GL_INVALID_OPERATION);  // not mapped
  glMapBufferRange(GL_ARRAY_BUFFER, 0, 16, GL_MAP_WRITE_BIT);
  EXPECT_GL(glMapBufferRange(GL_ARRAY_BUFFER, 0, 16, GL_MAP_WRITE_BIT), GL_INVALID_OPERATION);
  EXPECT_GL(glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, 4), GL_INVALID_OPERATION);  // no FLUSH_EXPLICIT
  EXPECT_GL(glBufferSubData(GL_ARRAY_BUFFER, 0, 4, first), GL_INVALID_OPERATION);
  EXPECT_GL(glUnmapBuffer(GL_ARRAY_BUFFER), GL_NO_ERROR);
  EXPECT_GL(glUnmapBuffer(GL_ARRAY_BUFFER), GL_INVALID_OPERATION);

  // Indexed uniform buffer bindings and blocks.
  const GLint max_bindings = get_int(GL_MAX_UNIFORM_BUFFER_BINDINGS);
  GLuint ub;
  glGenBuffers(1, &ub);
  glBindBuffer(GL_UNIFORM_BUFFER, ub);
  glBufferData(GL_UNIFORM_BUFFER, 1024, nullptr, GL_DYNAMIC_DRAW);
  EXPECT_GL(glBindBufferRange(GL_UNIFORM_BUFFER, GLuint(max_bindings), ub, 0, 16), GL_INVALID_VALUE);
  EXPECT_GL(glBindBufferRange(GL_UNIFORM_BUFFER, 0, ub, 1, 16), GL_INVALID_VALUE);  // misaligned
  EXPECT_GL(glBindBufferRange(GL_UNIFORM_BUFFER, 0, ub, 0, 0), GL_INVALID_VALUE);
  // A negative offset (GL 4.5 names it; Mesa 22 accepts -256).
  EXPECT_GL(glBindBufferRange(GL_UNIFORM_BUFFER, 0, ub, -256, 16), GL_INVALID_VALUE);
  GLint bound = -1;
  glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 0, &bound);
  EXPECT_EQ(bound, 0);  // none of the failed calls bound it
  EXPECT_GL(glBindBufferBase(GL_ARRAY_BUFFER, 0, ub), GL_INVALID_ENUM);
  EXPECT_GL(glBindBufferBase(GL_UNIFORM_BUFFER, 0, 999), GL_INVALID_OPERATION);
  EXPECT_GL(glUniformBlockBinding(pr, 7, 0), GL_INVALID_VALUE);
  EXPECT_GL(glUniformBlockBinding(pr, 0, GLuint(max_bindings)), GL_INVALID_VALUE);
  GLint v = -5;
  EXPECT_GL(glGetActiveUniformBlockiv(pr, 3, GL_UNIFORM_BLOCK_DATA_SIZE, &v), GL_INVALID_VALUE);
  EXPECT_GL(glGetActiveUniformBlockiv(pr, 0, 0x1234, &v), GL_INVALID_ENUM);
  EXPECT_EQ(v, -5);
  EXPECT_EQ(glGetUniformBlockIndex(pr, "Nope"), GLuint(GL_INVALID_INDEX));
  EXPECT_GL(glVertexAttribDivisor(16, 1), GL_INVALID_VALUE);

  // Queries.
  GLuint q[2];
  glGenQueries(2, q);
  EXPECT_GL(glBeginQuery(0x1234, q[0]), GL_INVALID_ENUM);
  EXPECT_GL(glBeginQuery(GL_SAMPLES_PASSED, 0), GL_INVALID_OPERATION);
  glBeginQuery(GL_SAMPLES_PASSED, q[0]);
  EXPECT_GL(glBeginQuery(GL_SAMPLES_PASSED, q[1]), GL_INVALID_OPERATION);
  EXPECT_GL(glBeginQuery(GL_ANY_SAMPLES_PASSED, q[0]), GL_INVALID_OPERATION);
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_GL(glEndQuery(GL_SAMPLES_PASSED), GL_INVALID_OPERATION);
  EXPECT_GL(glBeginQuery(GL_ANY_SAMPLES_PASSED, q[0]), GL_INVALID_OPERATION);  // made for another target
  GLuint result = 0;
  EXPECT_GL(glGetQueryObjectuiv(q[1], GL_QUERY_RESULT, &result), GL_INVALID_OPERATION);  // never begun
  EXPECT_GL(glQueryCounter(q[0], GL_TIMESTAMP), GL_INVALID_OPERATION);
  EXPECT_GL(glQueryCounter(q[1], GL_SAMPLES_PASSED), GL_INVALID_ENUM);

  // Syncs.
  EXPECT_GL(glFenceSync(0x1234, 0), GL_INVALID_ENUM);
  EXPECT_GL(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 1), GL_INVALID_VALUE);
  GLsync sync = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  EXPECT_GL(glClientWaitSync(sync, 0x8, 0), GL_INVALID_VALUE);
  EXPECT_GL(glWaitSync(sync, 1, GL_TIMEOUT_IGNORED), GL_INVALID_VALUE);
  EXPECT_GL(glWaitSync(sync, 0, 5), GL_INVALID_VALUE);
  EXPECT_GL(glClientWaitSync(reinterpret_cast<GLsync>(0x1234), 0, 0), GL_INVALID_VALUE);
  EXPECT_GL(glDeleteSync(reinterpret_cast<GLsync>(0x1234)), GL_INVALID_VALUE);
  EXPECT_GL(glDeleteSync(nullptr), GL_NO_ERROR);
  GLint sv = 0;
  GLsizei sl = 0;
  EXPECT_GL(glGetSynciv(sync, 0x1234, 1, &sl, &sv), GL_INVALID_ENUM);
  glDeleteSync(sync);

  // Samplers and blending.
  GLuint sm;
  glGenSamplers(1, &sm);
  EXPECT_GL(glSamplerParameteri(777, GL_TEXTURE_MIN_FILTER, GL_LINEAR), GL_INVALID_OPERATION);
  EXPECT_GL(glSamplerParameteri(sm, 0x1234, GL_LINEAR), GL_INVALID_ENUM);
  EXPECT_GL(glSamplerParameteri(sm, GL_TEXTURE_MIN_FILTER, GL_REPEAT), GL_INVALID_ENUM);
  EXPECT_GL(glSamplerParameteri(sm, GL_TEXTURE_WRAP_S, GL_LINEAR), GL_INVALID_ENUM);
  EXPECT_GL(glSamplerParameteri(sm, GL_TEXTURE_COMPARE_MODE, GL_LINEAR), GL_INVALID_ENUM);
  EXPECT_GL(glBindSampler(0, 777), GL_INVALID_OPERATION);
  EXPECT_GL(glBlendFunc(0x1234, GL_ONE), GL_INVALID_ENUM);
  EXPECT_GL(glBlendEquation(0x1234), GL_INVALID_ENUM);
  EXPECT_GL(glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, 0x1234), GL_INVALID_ENUM);
  EXPECT_GL(glBlendEquationSeparate(GL_FUNC_ADD, 0x1234), GL_INVALID_ENUM);
  EXPECT_GL(glEnablei(GL_BLEND, 8), GL_INVALID_VALUE);
  EXPECT_GL(glEnablei(GL_DEPTH_TEST, 0), GL_INVALID_ENUM);
  EXPECT_GL(glColorMaski(8, 1, 1, 1, 1), GL_INVALID_VALUE);

  // Draw and read buffers, clears and attachments.
  EXPECT_GL(glDrawBuffer(GL_COLOR_ATTACHMENT0), GL_INVALID_OPERATION);  // the default framebuffer
  EXPECT_GL(glReadBuffer(GL_COLOR_ATTACHMENT0), GL_INVALID_OPERATION);
  GLuint fb;
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  const GLenum twice[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT0}, back[1] = {GL_BACK};
  EXPECT_GL(glDrawBuffers(2, twice), GL_INVALID_OPERATION);
  EXPECT_GL(glDrawBuffers(1, back), GL_INVALID_ENUM);
  EXPECT_GL(glDrawBuffers(9, twice), GL_INVALID_VALUE);
  EXPECT_GL(glReadBuffer(GL_BACK), GL_INVALID_OPERATION);
  EXPECT_GL(glReadBuffer(GL_COLOR_ATTACHMENT0 + 8), GL_INVALID_OPERATION);
  const float zero[4] = {};
  const GLint izero[4] = {};
  EXPECT_GL(glClearBufferfv(GL_COLOR, 8, zero), GL_INVALID_FRAMEBUFFER_OPERATION);  // incomplete first
  EXPECT_GL(glClearBufferiv(GL_DEPTH, 0, izero), GL_INVALID_FRAMEBUFFER_OPERATION);
  EXPECT_GL(glClearBufferfi(GL_COLOR, 0, 1.0f, 0), GL_INVALID_ENUM);
  GLuint tx;
  glGenTextures(1, &tx);
  glBindTexture(GL_TEXTURE_2D, tx);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_GL(glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 999, 0),
            GL_INVALID_OPERATION);
  EXPECT_GL(
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X, tx, 0),
      GL_INVALID_OPERATION);
  EXPECT_GL(glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tx, -1),
            GL_INVALID_VALUE);
  EXPECT_GL(glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + 8, GL_TEXTURE_2D, tx, 0),
            GL_INVALID_OPERATION);
  EXPECT_GL(glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0),
            GL_INVALID_ENUM);
  GLint type = -1;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  EXPECT_EQ(type, GL_NONE);  // nothing was attached
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  EXPECT_GL(glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_DEPTH_BUFFER_BIT, GL_LINEAR), GL_INVALID_OPERATION);
  EXPECT_GL(glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, 0x10, GL_NEAREST), GL_INVALID_VALUE);
  EXPECT_GL(glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, 0x1234), GL_INVALID_ENUM);
  GLubyte px[4];
  EXPECT_GL(glReadPixels(0, 0, 1, 1, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, px), GL_INVALID_OPERATION);
  GLuint rb;
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  EXPECT_GL(glRenderbufferStorage(GL_RENDERBUFFER, 0x1234, 4, 4), GL_INVALID_ENUM);
  EXPECT_GL(glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, -1, 4), GL_INVALID_VALUE);
  EXPECT_GL(glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 100000, 4), GL_INVALID_VALUE);
  EXPECT_GL(glRenderbufferStorageMultisample(GL_RENDERBUFFER, 64, GL_RGBA8, 4, 4), GL_INVALID_OPERATION);
  EXPECT_GL(glUseProgram(999), GL_INVALID_VALUE);
}

TEST_F(GL33Test, CompatibilityKeepsTheRemovedCalls) {
  glMatrixMode(GL_PROJECTION);
  EXPECT_EQ(get_int(GL_MATRIX_MODE), GL_PROJECTION);
  glEnable(GL_LIGHTING);
  EXPECT_EQ(glIsEnabled(GL_LIGHTING), GLboolean(GL_TRUE));
  glPolygonMode(GL_FRONT, GL_LINE);
  glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
  const GLfloat att[3] = {1.0f, 0.5f, 0.25f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
  glPointParameterf(GL_POINT_SIZE_MAX, 20.0f);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  GLfloat got[3] = {};
  glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, got);
  EXPECT_EQ(got[1], 0.5f);
  glGetFloatv(GL_POINT_SIZE_MAX, got);
  EXPECT_EQ(got[0], 20.0f);
  EXPECT_NE(glGenLists(1), 0u);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

TEST_F(GL33Test, VertexAttribErrorsChangeNothing) {
  GLuint vao, vbo;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  EXPECT_TRUE(glIsVertexArray(vao));
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glVertexAttribPointer(16, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glVertexAttribPointer(1, 5, GL_FLOAT, GL_FALSE, 0, nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, -4, nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glVertexAttribPointer(1, 2, 0x1234, GL_FALSE, 0, nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glVertexAttribIPointer(1, 2, GL_FLOAT, 0, nullptr);  // integer arrays take integer types
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glVertexAttribPointer(1, 3, GL_INT_2_10_10_10_REV, GL_TRUE, 0, nullptr);  // packed: 4 or BGRA
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glVertexAttribPointer(1, 3, GL_SHORT, GL_TRUE, 8, reinterpret_cast<void*>(4));
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  GLint v = 0;
  glGetVertexAttribiv(1, GL_VERTEX_ATTRIB_ARRAY_SIZE, &v);
  EXPECT_EQ(v, 3);
  glGetVertexAttribiv(1, GL_VERTEX_ATTRIB_ARRAY_TYPE, &v);
  EXPECT_EQ(v, GL_SHORT);
  glGetVertexAttribiv(1, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &v);
  EXPECT_EQ(GLuint(v), vbo);
  // A non-zero vertex array object reads buffers only (GL 3.3 §2.8).
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  const float client[2] = {0, 0};
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, 0, client);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // Current values.
  glVertexAttrib4f(3, 1, 2, 3, 4);
  GLfloat f[4] = {};
  glGetVertexAttribfv(3, GL_CURRENT_VERTEX_ATTRIB, f);
  EXPECT_EQ(f[2], 3.0f);
  glVertexAttribI4i(4, -1, 2, -3, 4);
  GLint iv[4] = {};
  glGetVertexAttribIiv(4, GL_CURRENT_VERTEX_ATTRIB, iv);
  EXPECT_EQ(iv[2], -3);
  // Deleting the bound vertex array object binds 0.
  glDeleteVertexArrays(1, &vao);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BINDING), 0);
}

TEST_F(GL33Test, ShaderAndProgramErrors) {
  // A name that is no object: GL_INVALID_VALUE; an object of the other kind: GL_INVALID_OPERATION.
  glCompileShader(999);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  GLuint p = glCreateProgram();
  glCompileShader(p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(glCreateShader(0x1234), 0u);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  // A compile error names the line.
  GLuint s = glCreateShader(GL_FRAGMENT_SHADER);
  const char* bad = "#version 330\nout vec4 c;\nvoid main() { c = undeclared; }\n";
  glShaderSource(s, 1, &bad, nullptr);
  glCompileShader(s);
  GLint ok = 1, len = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  EXPECT_EQ(ok, 0);
  glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
  std::vector<char> log(size_t(std::max(len, 1)));
  glGetShaderInfoLog(s, len, nullptr, log.data());
  EXPECT_NE(std::string(log.data()).find("0:3"), std::string::npos) << log.data();
  // Linking with it fails; using the program is GL_INVALID_OPERATION.
  glAttachShader(p, s);
  glAttachShader(p, s);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glLinkProgram(p);
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  EXPECT_EQ(ok, 0);
  glUseProgram(p);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_CURRENT_PROGRAM), 0);
  EXPECT_EQ(glGetUniformLocation(p, "color"), -1);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // A shader deleted while attached lives until it is detached.
  glDeleteShader(s);
  EXPECT_TRUE(glIsShader(s));
  GLint status = 0;
  glGetShaderiv(s, GL_DELETE_STATUS, &status);
  EXPECT_EQ(status, 1);
  glDetachShader(p, s);
  EXPECT_FALSE(glIsShader(s));
  glBindAttribLocation(p, 16, "pos");
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glBindAttribLocation(p, 0, "gl_Vertex");
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glDeleteProgram(p);
  EXPECT_FALSE(glIsProgram(p));
}

TEST_F(GL33Test, UniformErrorsChangeNothing) {
  GLuint p = program(kVs, kFs);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  ASSERT_EQ(ok, 1);
  const GLint color = glGetUniformLocation(p, "color"), tex = glGetUniformLocation(p, "tex");
  ASSERT_GE(color, 0);
  glUniform4f(color, 1, 0, 0, 1);  // no current program
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glUseProgram(p);
  glUniform4f(color, 0.25f, 0.5f, 0.75f, 1.0f);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glUniform3f(color, 1, 1, 1);  // size mismatch
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glUniform4i(color, 1, 1, 1, 1);  // type mismatch
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glUniform4fv(color, -1, nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glUniform1i(tex, 99);  // no such texture unit
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
  glUniform1f(-1, 2.0f);  // location -1 is ignored
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  GLfloat v[4] = {};
  glGetUniformfv(p, color, v);
  EXPECT_EQ(v[1], 0.5f);
  glGetUniformfv(p, 1234, v);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  // Active uniforms as GL lists them.
  GLint n = 0;
  glGetProgramiv(p, GL_ACTIVE_UNIFORMS, &n);
  EXPECT_EQ(n, 3);
  glGetActiveUniform(p, 99, 0, nullptr, nullptr, nullptr, nullptr);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));
}

// A program drawn over a vertex array object: the pixels it gives; a failed relink keeps
// the executable in use (GL 3.3 §2.11.2).
TEST_F(GL33Test, ProgramDrawsAndFailedRelinkKeepsTheExecutable) {
  GLuint p = program(kVs, kFs);
  glUseProgram(p);
  glUniform4f(glGetUniformLocation(p, "color"), 0.0f, 1.0f, 0.0f, 1.0f);
  const float tri[6] = {-1, -1, 3, -1, -1, 3};
  GLuint vao, vbo;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof tri, tri, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(centre(), (std::array<GLubyte, 4>{0, 255, 0, 255}));
  // Relink with a shader that does not compile: link fails, drawing goes on with the old one.
  GLuint s = glCreateShader(GL_VERTEX_SHADER);
  const char* bad = "#version 330\nvoid main() { gl_Position = nope; }\n";
  glShaderSource(s, 1, &bad, nullptr);
  glCompileShader(s);
  glAttachShader(p, s);
  glLinkProgram(p);
  GLint ok = 1;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  EXPECT_EQ(ok, 0);
  glUniform4f(glGetUniformLocation(p, "color"), 1.0f, 0.0f, 0.0f, 1.0f);  // not linked: -1, ignored
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(centre(), (std::array<GLubyte, 4>{0, 255, 0, 255}));
  // A draw that reads past the end of the buffer is GL_INVALID_OPERATION and draws nothing.
  glClear(GL_COLOR_BUFFER_BIT);
  (void)err();
  glDrawArrays(GL_TRIANGLES, 1, 3);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(centre(), (std::array<GLubyte, 4>{0, 0, 0, 0}));
  // A mapped buffer cannot be drawn from.
  glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glUnmapBuffer(GL_ARRAY_BUFFER);
  // A deleted buffer still attached to the vertex array object? Deleting unbinds it from
  // the bound object: the draw reads the current value instead, and does not crash.
  glDeleteBuffers(1, &vbo);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glFinish();
}

// glGenerateMipmap (GL 3.0) and GL_GENERATE_MIPMAP (GL 1.4) fill every level from the base:
// a 4x2 texture gets 2x1 and 1x1 levels holding its averages.
TEST_F(GL33Test, MipmapsAreGeneratedFromTheBaseLevel) {
  GLuint t[2];
  glGenTextures(2, t);
  const GLubyte texels[4 * 2 * 4] = {0,   0, 0, 255, 100, 0, 0, 255, 200, 0, 0, 255, 40, 0, 0, 255,
                                     100, 0, 0, 255, 0,   0, 0, 255, 0,   0, 0, 255, 0,  0, 0, 255};
  glBindTexture(GL_TEXTURE_2D, t[0]);
  glGenerateMipmap(GL_TEXTURE_2D);  // no base level yet
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glGenerateMipmap(GL_TEXTURE_RECTANGLE);  // rectangles have no mipmaps
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glGenerateMipmap(GL_TEXTURE_3D);  // the 3D texture has no base level
  EXPECT_EQ(err(), GLenum(GL_INVALID_OPERATION));
  glGenerateMipmap(GL_TEXTURE_2D);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  glBindTexture(GL_TEXTURE_2D, t[1]);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  for (GLuint name : t) {
    glBindTexture(GL_TEXTURE_2D, name);
    GLint w = 0, h = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_HEIGHT, &h);
    EXPECT_EQ(w, 2);
    EXPECT_EQ(h, 1);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 2, GL_TEXTURE_WIDTH, &w);
    EXPECT_EQ(w, 1);
    GLubyte level1[2 * 4] = {}, level2[4] = {};
    glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, level1);
    glGetTexImage(GL_TEXTURE_2D, 2, GL_RGBA, GL_UNSIGNED_BYTE, level2);
    EXPECT_EQ(level1[0], 50);  // (0 + 100 + 100 + 0) / 4
    EXPECT_EQ(level1[4], 60);  // (200 + 40 + 0 + 0) / 4
    EXPECT_EQ(level2[0], 55);  // (50 + 60) / 2
  }
}

// GLSL 1.20 with immediate mode: the compatibility attributes and matrices.
TEST_F(GL33Test, CompatibilityProgramDrawsImmediateMode) {
  GLuint p = program(
      "#version 120\nvarying vec4 col;\nvoid main() { col = gl_Color; gl_Position = ftransform(); }\n",
      "#version 120\nvarying vec4 col;\nvoid main() { gl_FragColor = col.bgra; }\n");
  glUseProgram(p);
  glMatrixMode(GL_PROJECTION);
  glOrtho(-1, 1, -1, 1, -1, 1);
  glColor4f(1.0f, 0.0f, 0.5f, 1.0f);
  window_quad();
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  const auto px = centre();
  EXPECT_EQ(px[0], 128);
  EXPECT_EQ(px[1], 0);
  EXPECT_EQ(px[2], 255);
}

// GL 1.3 multitexture and GL 1.4 vertex attributes in a compatibility context: eight texture
// coordinate sets, each with its current value, client array and texture matrix stack, and
// the secondary colour and fog coordinate, all reaching GLSL 1.20's built-ins.
TEST_F(GL33Test, TextureCoordinateSetsSecondaryColourAndFogCoordReachGlsl) {
  EXPECT_EQ(get_int(GL_MAX_TEXTURE_COORDS), 8);
  EXPECT_EQ(get_int(GL_MAX_TEXTURE_UNITS), 8);
  glMultiTexCoord4f(GL_TEXTURE3, 0.1f, 0.2f, 0.3f, 0.4f);
  EXPECT_GL(glMultiTexCoord2f(GL_TEXTURE8, 9.0f, 9.0f), GL_INVALID_ENUM);
  EXPECT_GL(glClientActiveTexture(GL_TEXTURE8), GL_INVALID_ENUM);
  GLfloat v[4] = {};
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, v);
  EXPECT_EQ(v[0], 0.0f);  // set 0 untouched
  glActiveTexture(GL_TEXTURE3);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, v);
  EXPECT_EQ(v[1], 0.2f);
  EXPECT_EQ(v[3], 0.4f);
  // One texture matrix stack per set.
  glMatrixMode(GL_TEXTURE);
  glPushMatrix();
  glTranslatef(3.0f, 0.0f, 0.0f);
  EXPECT_EQ(get_int(GL_TEXTURE_STACK_DEPTH), 2);
  GLfloat m[16];
  glGetFloatv(GL_TEXTURE_MATRIX, m);
  EXPECT_EQ(m[12], 3.0f);
  glActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(get_int(GL_TEXTURE_STACK_DEPTH), 1);
  glGetFloatv(GL_TEXTURE_MATRIX, m);
  EXPECT_EQ(m[12], 0.0f);
  // A unit past GL_MAX_TEXTURE_COORDS has no matrix (Mesa: GL_INVALID_OPERATION).
  glActiveTexture(GL_TEXTURE12);
  EXPECT_GL(glMatrixMode(GL_TEXTURE), GL_INVALID_OPERATION);
  glActiveTexture(GL_TEXTURE3);
  glPopMatrix();
  glLoadIdentity();
  glActiveTexture(GL_TEXTURE0);
  glSecondaryColor3ub(0, 191, 0);
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, v);
  EXPECT_FLOAT_EQ(v[1], 191.0f / 255.0f);
  EXPECT_EQ(v[3], 1.0f);
  glFogCoordf(0.25f);
  glGetFloatv(GL_CURRENT_FOG_COORD, v);
  EXPECT_EQ(v[0], 0.25f);
  ASSERT_EQ(err(), GLenum(GL_NO_ERROR));

  GLuint p = program(
      "#version 120\nvarying float f;\n"
      "void main() {\n"
      "  gl_TexCoord[1] = gl_TextureMatrix[1] * gl_MultiTexCoord1;\n"
      "  gl_TexCoord[5] = gl_MultiTexCoord5;\n"
      "  gl_FrontSecondaryColor = gl_SecondaryColor;\n"
      "  f = gl_FogCoord;\n"
      "  gl_Position = ftransform();\n"
      "}\n",
      "#version 120\nvarying float f;\n"
      "void main() {\n"
      "  gl_FragColor = vec4(gl_TexCoord[1].x, gl_TexCoord[5].y, gl_SecondaryColor.g, f);\n"
      "}\n");
  glUseProgram(p);
  ASSERT_EQ(err(), GLenum(GL_NO_ERROR));
  // Immediate mode: set 1 through its texture matrix, set 5 as given.
  glActiveTexture(GL_TEXTURE1);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.25f, 0.0f, 0.0f);
  glActiveTexture(GL_TEXTURE0);
  glMatrixMode(GL_MODELVIEW);
  glMultiTexCoord2f(GL_TEXTURE1, 0.25f, 0.0f);
  glMultiTexCoord2f(GL_TEXTURE5, 0.0f, 0.75f);
  glSecondaryColor3f(0.0f, 0.5f, 0.0f);
  glFogCoordf(1.0f);
  window_quad();
  auto px = centre();
  EXPECT_NEAR(px[0], 128, 1);  // 0.25 + 0.25
  EXPECT_NEAR(px[1], 191, 1);
  EXPECT_NEAR(px[2], 128, 1);
  EXPECT_EQ(px[3], 255);

  // The defaults again: (0, 0, 0, 1) and a fog coordinate of 0 (set 1's matrix still adds 0.25).
  glMultiTexCoord4f(GL_TEXTURE1, 0, 0, 0, 1);
  glMultiTexCoord4f(GL_TEXTURE5, 0, 0, 0, 1);
  glSecondaryColor3f(0, 0, 0);
  glFogCoordf(0);
  window_quad();
  px = centre();
  EXPECT_NEAR(px[0], 64, 1);
  EXPECT_EQ(px[1], 0);
  EXPECT_EQ(px[2], 0);
  EXPECT_EQ(px[3], 0);

  // Client arrays of two sets (chosen with glClientActiveTexture), the secondary colour and
  // fog coordinate arrays, through glDrawArrays.
  const GLfloat pos[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  const GLfloat set1[8] = {0.5f, 0, 0.5f, 0, 0.5f, 0, 0.5f, 0};
  const GLfloat set5[8] = {0, 0.25f, 0, 0.25f, 0, 0.25f, 0, 0.25f};
  const GLubyte sec[12] = {0, 255, 0, 0, 255, 0, 0, 255, 0, 0, 255, 0};
  const GLfloat fog[4] = {0.5f, 0.5f, 0.5f, 0.5f};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glClientActiveTexture(GL_TEXTURE1);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_FLOAT, 0, set1);
  glClientActiveTexture(GL_TEXTURE5);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_FLOAT, 0, set5);
  EXPECT_EQ(get_int(GL_CLIENT_ACTIVE_TEXTURE), GL_TEXTURE5);
  glClientActiveTexture(GL_TEXTURE0);
  EXPECT_FALSE(glIsEnabled(GL_TEXTURE_COORD_ARRAY));
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, sec);
  glEnableClientState(GL_FOG_COORD_ARRAY);
  glFogCoordPointer(GL_FLOAT, 0, fog);
  EXPECT_GL(glSecondaryColorPointer(2, GL_FLOAT, 0, sec), GL_INVALID_VALUE);
  EXPECT_GL(glFogCoordPointer(GL_INT, 0, fog), GL_INVALID_ENUM);
  glDrawArrays(GL_QUADS, 0, 4);
  px = centre();
  EXPECT_NEAR(px[0], 191, 1);  // 0.5 + 0.25
  EXPECT_NEAR(px[1], 64, 1);
  EXPECT_EQ(px[2], 255);
  EXPECT_NEAR(px[3], 128, 1);
  glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
  glDisableClientState(GL_FOG_COORD_ARRAY);
  glClientActiveTexture(GL_TEXTURE1);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glClientActiveTexture(GL_TEXTURE5);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);

  // A display list keeps the coordinate sets it was given.
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 0.0f);
  glMultiTexCoord2f(GL_TEXTURE5, 0.0f, 1.0f);
  glSecondaryColor3f(0.0f, 0.25f, 0.0f);
  glFogCoordf(0.75f);
  window_quad();
  glEndList();
  glMultiTexCoord2f(GL_TEXTURE5, 0.0f, 0.0f);
  glCallList(list);
  px = centre();
  EXPECT_NEAR(px[0], 64, 1);
  EXPECT_EQ(px[1], 255);
  EXPECT_NEAR(px[2], 64, 1);
  EXPECT_NEAR(px[3], 191, 1);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

// The GL 1.3-2.0 fixed-function texture state: targets enabled per unit, the combine
// environment, the unit LOD bias, point sprite coordinates, the colour sum and fog coordinate
// switches, with the errors GL 2.1 §3.8.13, §2.12.4 and §3.10 name; each error changes nothing.
TEST_F(GL33Test, FixedFunctionTextureStateAndErrors) {
  glActiveTexture(GL_TEXTURE2);
  glEnable(GL_TEXTURE_CUBE_MAP);
  glEnable(GL_TEXTURE_3D);
  glEnable(GL_TEXTURE_1D);
  EXPECT_TRUE(glIsEnabled(GL_TEXTURE_CUBE_MAP));
  EXPECT_TRUE(glIsEnabled(GL_TEXTURE_3D));
  EXPECT_TRUE(glIsEnabled(GL_TEXTURE_1D));
  EXPECT_FALSE(glIsEnabled(GL_TEXTURE_2D));
  glActiveTexture(GL_TEXTURE0);
  EXPECT_FALSE(glIsEnabled(GL_TEXTURE_CUBE_MAP));  // per unit
  glPushAttrib(GL_ENABLE_BIT);
  glEnable(GL_COLOR_SUM);
  glEnable(GL_POINT_SPRITE);
  EXPECT_TRUE(glIsEnabled(GL_COLOR_SUM));
  glPopAttrib();
  EXPECT_FALSE(glIsEnabled(GL_COLOR_SUM));
  EXPECT_FALSE(glIsEnabled(GL_POINT_SPRITE));

  // Coordinate generation: the cube map modes are not for Q.
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  EXPECT_GL(glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP), GL_INVALID_ENUM);
  EXPECT_GL(glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP), GL_INVALID_ENUM);
  GLint v = 0;
  glGetTexGeniv(GL_R, GL_TEXTURE_GEN_MODE, &v);
  EXPECT_EQ(v, GL_REFLECTION_MAP);

  // GL_COMBINE: the initial values (GL 2.1 Table 6.21), then sets and their errors.
  GLint e = 0;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_SRC2_RGB, &e);
  EXPECT_EQ(e, GL_CONSTANT);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_OPERAND2_RGB, &e);
  EXPECT_EQ(e, GL_SRC_ALPHA);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGBA);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_ALPHA, GL_TEXTURE5);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_ONE_MINUS_SRC_ALPHA);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 4.0f);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  EXPECT_GL(glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB), GL_INVALID_ENUM);
  EXPECT_GL(glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB, GL_TEXTURE8), GL_INVALID_ENUM);
  EXPECT_GL(glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_COLOR), GL_INVALID_ENUM);
  EXPECT_GL(glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3.0f), GL_INVALID_VALUE);
  EXPECT_GL(glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 0.5f), GL_INVALID_VALUE);
  EXPECT_GL(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_SUBTRACT), GL_INVALID_ENUM);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &e);
  EXPECT_EQ(e, GL_COMBINE);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_COMBINE_RGB, &e);
  EXPECT_EQ(e, GL_DOT3_RGBA);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, &e);
  EXPECT_EQ(e, GL_MODULATE);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_SRC1_ALPHA, &e);
  EXPECT_EQ(e, GL_TEXTURE5);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_SRC0_RGB, &e);
  EXPECT_EQ(e, GL_TEXTURE);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_OPERAND1_RGB, &e);
  EXPECT_EQ(e, GL_ONE_MINUS_SRC_ALPHA);
  GLfloat f = 0.0f;
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_RGB_SCALE, &f);
  EXPECT_EQ(f, 4.0f);
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_ALPHA_SCALE, &f);
  EXPECT_EQ(f, 1.0f);

  // The unit LOD bias and point sprite coordinates.
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -1.25f);
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &f);
  EXPECT_EQ(f, -1.25f);
  EXPECT_GL(glTexEnvi(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE, GL_ADD), GL_INVALID_ENUM);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &e);
  EXPECT_EQ(e, GL_TRUE);
  EXPECT_GL(glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, 7), GL_INVALID_VALUE);

  // The secondary colour and fog coordinate switches.
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  EXPECT_EQ(get_int(GL_LIGHT_MODEL_COLOR_CONTROL), GL_SEPARATE_SPECULAR_COLOR);
  EXPECT_GL(glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FOG), GL_INVALID_ENUM);
  EXPECT_EQ(get_int(GL_LIGHT_MODEL_COLOR_CONTROL), GL_SEPARATE_SPECULAR_COLOR);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  EXPECT_EQ(get_int(GL_FOG_COORD_SRC), GL_FOG_COORD);
  EXPECT_GL(glFogi(GL_FOG_COORD_SRC, GL_LINEAR), GL_INVALID_ENUM);
  EXPECT_EQ(get_int(GL_FOG_COORD_SRC), GL_FOG_COORD);
}

// Random fixed-function states beyond the C++ shader: every one the generated GLSL program
// covers must compile and draw without an error (a program that failed to compile would make
// the draw GL_INVALID_OPERATION), whatever the units, targets, environments, coordinate
// generation, lighting, fog and alpha test.
TEST_F(GL33Test, RandomFixedFunctionStatesCompileAndDraw) {
  std::mt19937 rng(1234);
  auto pick = [&](std::initializer_list<GLenum> v) { return *(v.begin() + rng() % v.size()); };
  GLuint tex[4];
  glGenTextures(4, tex);
  const GLubyte texel[4 * 4 * 4 * 4] = {200, 100, 50, 255};
  glBindTexture(GL_TEXTURE_1D, tex[0]);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 4, 4, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, texel);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glBindTexture(GL_TEXTURE_3D, tex[2]);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 4, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, texel);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_CUBE_MAP, tex[3]);
  for (int f = 0; f < 6; ++f)
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(f), 0, GL_ALPHA, 4, 4, 0, GL_ALPHA, GL_UNSIGNED_BYTE,
                 texel);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  ASSERT_EQ(err(), GLenum(GL_NO_ERROR));
  const GLenum caps[4] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP};
  for (int round = 0; round < 60; ++round) {
    for (GLenum unit = 0; unit < 4; ++unit) {
      glActiveTexture(GL_TEXTURE0 + unit);
      for (int k = 0; k < 4; ++k) {
        glBindTexture(caps[k], tex[k]);
        if (rng() % 3 == 0)
          glEnable(caps[k]);
        else
          glDisable(caps[k]);
      }
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE,
                GLint(pick({GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD, GL_COMBINE, GL_COMBINE})));
      glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB,
                GLint(pick({GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED, GL_INTERPOLATE, GL_SUBTRACT,
                            GL_DOT3_RGB, GL_DOT3_RGBA})));
      glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA,
                GLint(pick({GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED, GL_INTERPOLATE, GL_SUBTRACT})));
      for (GLenum i = 0; i < 3; ++i) {
        const GLenum src = pick(
            {GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS, GL_TEXTURE0, GL_TEXTURE3, GL_TEXTURE7});
        glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB + i, GLint(src));
        glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_ALPHA + i, GLint(src));
        glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + i,
                  GLint(pick({GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA})));
        glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + i, GLint(pick({GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA})));
      }
      glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, float(1 << (rng() % 3)));
      glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, rng() % 2 ? 0.0f : 0.5f);
      glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GLint(rng() % 2));
      const GLenum coords[3] = {GL_S, GL_T, GL_R};
      for (int cc = 0; cc < 3; ++cc) {
        glTexGeni(coords[cc], GL_TEXTURE_GEN_MODE,
                  GLint(pick({GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_REFLECTION_MAP, GL_NORMAL_MAP,
                              cc < 2 ? GLenum(GL_SPHERE_MAP) : GLenum(GL_EYE_LINEAR)})));
        if (rng() % 2)
          glEnable(GL_TEXTURE_GEN_S + GLenum(cc));
        else
          glDisable(GL_TEXTURE_GEN_S + GLenum(cc));
      }
    }
    glActiveTexture(GL_TEXTURE0);
    for (GLenum cap :
         {GLenum(GL_LIGHTING), GLenum(GL_LIGHT0), GLenum(GL_LIGHT3), GLenum(GL_COLOR_MATERIAL),
          GLenum(GL_FOG), GLenum(GL_COLOR_SUM), GLenum(GL_ALPHA_TEST), GLenum(GL_POLYGON_STIPPLE),
          GLenum(GL_NORMALIZE), GLenum(GL_RESCALE_NORMAL), GLenum(GL_POINT_SPRITE)}) {
      if (rng() % 2)
        glEnable(cap);
      else
        glDisable(cap);
    }
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GLint(pick({GL_SINGLE_COLOR, GL_SEPARATE_SPECULAR_COLOR})));
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GLint(rng() % 2));
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GLint(rng() % 2));
    glColorMaterial(GL_FRONT_AND_BACK, pick({GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION}));
    glFogi(GL_FOG_MODE, GLint(pick({GL_LINEAR, GL_EXP, GL_EXP2})));
    glFogi(GL_FOG_COORD_SRC, GLint(pick({GL_FOG_COORD, GL_FRAGMENT_DEPTH})));
    glAlphaFunc(pick({GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL}), 0.5f);
    glShadeModel(pick({GL_FLAT, GL_SMOOTH}));
    glBegin(pick({GL_TRIANGLES, GL_QUADS, GL_POINTS, GL_LINES}));
    for (int v = 0; v < 4; ++v) {
      glMultiTexCoord4f(GL_TEXTURE0 + GLenum(v), 0.2f * float(v), 0.5f, 0.3f, 1.0f);
      glSecondaryColor3f(0.1f * float(v), 0.2f, 0.3f);
      glFogCoordf(0.25f * float(v));
      glNormal3f(0.0f, 0.0f, 1.0f);
      glVertex2f(v % 3 ? 0.9f : -0.9f, v / 2 ? 0.9f : -0.9f);
    }
    glEnd();
    ASSERT_EQ(err(), GLenum(GL_NO_ERROR)) << "round " << round;
  }
  glFinish();
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

// The packed fixed-function attributes (GL 3.3 compatibility §2.7): colours and normals
// normalized, positions and texture coordinates as integers; another type is GL_INVALID_ENUM
// and changes nothing.
// glSampleCoverage is state of every GL 3.3 context (its value clamped to [0, 1]).
TEST_F(GL33CoreTest, SampleCoverageIsKeptAndQueried) {
  glSampleCoverage(1.5f, GL_TRUE);
  GLfloat v = 0.0f;
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &v);
  EXPECT_EQ(v, 1.0f);
  GLboolean inv = GL_FALSE;
  glGetBooleanv(GL_SAMPLE_COVERAGE_INVERT, &inv);
  EXPECT_EQ(inv, GL_TRUE);
  glSampleCoverage(0.25f, GL_FALSE);
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &v);
  EXPECT_EQ(v, 0.25f);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
}

TEST_F(GL33Test, PackedFixedFunctionAttributes) {
  // x = 1023, y = 0, z = 512, w = 3 (unsigned); as signed: x = -1, z = -512, w = -1.
  const GLuint packed = 1023u | (0u << 10) | (512u << 20) | (3u << 30);
  glColorP4ui(GL_UNSIGNED_INT_2_10_10_10_REV, packed);
  GLfloat v[4] = {};
  glGetFloatv(GL_CURRENT_COLOR, v);
  EXPECT_FLOAT_EQ(v[0], 1.0f);
  EXPECT_FLOAT_EQ(v[2], 512.0f / 1023.0f);
  EXPECT_FLOAT_EQ(v[3], 1.0f);
  glMultiTexCoordP4ui(GL_TEXTURE2, GL_INT_2_10_10_10_REV, packed);
  glActiveTexture(GL_TEXTURE2);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, v);
  EXPECT_EQ(v[0], -1.0f);
  EXPECT_EQ(v[2], -512.0f);
  EXPECT_EQ(v[3], -1.0f);
  glActiveTexture(GL_TEXTURE0);
  glNormalP3ui(GL_INT_2_10_10_10_REV, 511u);  // x = 511: 1.0 signed normalized
  glGetFloatv(GL_CURRENT_NORMAL, v);
  EXPECT_FLOAT_EQ(v[0], 1.0f);
  EXPECT_EQ(v[1], 0.0f);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  EXPECT_GL(glColorP3ui(GL_UNSIGNED_INT, packed), GL_INVALID_ENUM);
  EXPECT_GL(glTexCoordP2ui(GL_FLOAT, packed), GL_INVALID_ENUM);
  glGetFloatv(GL_CURRENT_COLOR, v);
  EXPECT_FLOAT_EQ(v[0], 1.0f);
  EXPECT_FLOAT_EQ(v[3], 1.0f);
}

// A combine environment draws what GL 1.3 Table 3.25 computes: two units, ADD_SIGNED of unit
// 0's texel and the constant colour scaled by 2, then SUBTRACT of unit 1's texel.
TEST_F(GL33Test, CombineEnvironmentComputesTable325) {
  glMatrixMode(GL_PROJECTION);
  glOrtho(-1, 1, -1, 1, -1, 1);
  const GLubyte texel0[4] = {153, 51, 204, 255}, texel1[4] = {51, 51, 0, 255};  // 0.6 0.2 0.8; 0.2 0.2 0
  GLuint t[2];
  glGenTextures(2, t);
  const GLubyte* texels[2] = {texel0, texel1};
  for (int u = 0; u < 2; ++u) {
    glActiveTexture(GL_TEXTURE0 + GLenum(u));
    glBindTexture(GL_TEXTURE_2D, t[u]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels[u]);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  }
  const GLfloat constant[4] = {0.25f, 0.5f, 0.0f, 1.0f};
  glActiveTexture(GL_TEXTURE0);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD_SIGNED);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_RGB, GL_CONSTANT);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0f);
  glActiveTexture(GL_TEXTURE1);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_SUBTRACT);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC0_RGB, GL_PREVIOUS);
  glTexEnvi(GL_TEXTURE_ENV, GL_SRC1_RGB, GL_TEXTURE);
  window_quad();
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  // Unit 0: 2 * (t0 + k - 0.5) = (0.7, 0.4, 0.6); unit 1: minus t1 = (0.5, 0.2, 0.6).
  const auto px = centre();
  EXPECT_NEAR(px[0], 128, 1);
  EXPECT_NEAR(px[1], 51, 1);
  EXPECT_NEAR(px[2], 153, 1);
}

// Random calls of the 3.3 families with random arguments: never a crash or a sanitizer report.
// A core context, where every pointer argument is an offset into a buffer object: in a
// compatibility context a bad client pointer is the program's own fault, in any GL.
TEST_F(GL33CoreTest, RandomCallSequenceNeverCrashes) {
  std::mt19937 rng(1234);
  auto pick = [&](int n) { return int(rng() % unsigned(n)); };
  auto name = [&]() { return GLuint(pick(4)); };
  const GLuint p = program(kVs, kFs);
  // The same program capturing its position and a point size (transform feedback).
  const GLuint tf = glCreateProgram();
  {
    const char* vs =
        "#version 330\nlayout(location = 0) in vec2 pos;\nout float size;\n"
        "void main() { size = pos.x; gl_Position = vec4(pos, 0.0, 1.0); }\n";
    const char* names[] = {"gl_Position", "size"};
    const GLuint v = gl33test::shader(GL_VERTEX_SHADER, vs), f = gl33test::shader(GL_FRAGMENT_SHADER, kFs);
    glAttachShader(tf, v);
    glAttachShader(tf, f);
    glDeleteShader(v);
    glDeleteShader(f);
    glTransformFeedbackVaryings(tf, 2, names, (rng() & 1) ? GL_SEPARATE_ATTRIBS : GL_INTERLEAVED_ATTRIBS);
    glLinkProgram(tf);
  }
  std::vector<unsigned char> bytes(256);
  for (auto& b : bytes) b = static_cast<unsigned char>(rng());
  const GLenum targets[] = {GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER, GL_UNIFORM_BUFFER,
                            GL_TRANSFORM_FEEDBACK_BUFFER, 0x1234};
  const GLenum types[] = {GL_FLOAT,      GL_UNSIGNED_BYTE,      GL_SHORT,       GL_INT, GL_DOUBLE,
                          GL_HALF_FLOAT, GL_INT_2_10_10_10_REV, GL_UNSIGNED_INT};
  const GLenum modes[] = {GL_POINTS,         GL_LINES, GL_LINE_LOOP, GL_TRIANGLES,
                          GL_TRIANGLE_STRIP, GL_QUADS, GL_POLYGON,   99};
  const GLenum itypes[] = {GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT, GL_FLOAT};
  // A starting point that draws: a vertex array object with attribute 0 in a buffer.
  GLuint vao, vbo;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(bytes.size()), bytes.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_UNSIGNED_BYTE, GL_TRUE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, vbo);
  glUseProgram(p);
  int drawn = 0;  // draws without an error
  for (int i = 0; i < 4000; ++i) {
    const GLenum target = targets[pick(5)];
    const int call = pick(26);
    if (call >= 13 && call <= 16) (void)glGetError();
    switch (call) {
      case 0: {
        GLuint b[2];
        glGenBuffers(2, b);
        break;
      }
      case 1: glBindBuffer(target, name()); break;
      case 2: glBufferData(target, pick(300) - 10, pick(2) ? bytes.data() : nullptr, GL_DYNAMIC_DRAW); break;
      case 3: glBufferSubData(target, pick(300) - 10, pick(300) - 10, bytes.data()); break;
      case 4: {
        void* m = glMapBufferRange(target, pick(64), pick(64), GLbitfield(pick(64)));
        if (m && pick(2)) std::memset(m, pick(256), 1);
        break;
      }
      case 5: glUnmapBuffer(target); break;
      case 6: {
        const GLuint n = name();
        if (pick(4) == 0) glDeleteBuffers(1, &n);
        break;
      }
      case 7: {
        GLuint v;
        glGenVertexArrays(1, &v);
        break;
      }
      case 8: glBindVertexArray(name()); break;
      case 9: {
        const GLuint n = name();
        if (pick(4) == 0) glDeleteVertexArrays(1, &n);
        break;
      }
      case 10:
        glVertexAttribPointer(GLuint(pick(18)), pick(6), types[pick(8)], GLboolean(pick(2)), pick(40) - 4,
                              reinterpret_cast<void*>(size_t(pick(80))));
        break;
      case 11: (pick(2) ? glEnableVertexAttribArray : glDisableVertexAttribArray)(GLuint(pick(18))); break;
      case 12: glVertexAttribDivisor(GLuint(pick(18)), GLuint(pick(3))); break;
      case 13: glDrawArrays(modes[pick(8)], pick(10) - 2, pick(40) - 2); break;
      case 14:
        glDrawElements(modes[pick(8)], pick(40) - 2, itypes[pick(4)],
                       reinterpret_cast<void*>(size_t(pick(64))));
        break;
      case 15:
        glDrawElementsInstancedBaseVertex(modes[pick(8)], pick(20), itypes[pick(3)],
                                          reinterpret_cast<void*>(size_t(pick(32))), pick(4),
                                          pick(2000) - 1000);
        break;
      case 16: glDrawArraysInstanced(modes[pick(8)], pick(8), pick(20), pick(5) - 1); break;
      case 17: glUseProgram(pick(4) ? p : 0); break;
      case 18: glUniform4f(GLint(pick(6)) - 1, 0.5f, 0.5f, 0.5f, 1.0f); break;
      case 19:
        glBindBufferRange(GL_UNIFORM_BUFFER, GLuint(pick(40)), name(), pick(64) - 8, pick(64) - 8);
        break;
      case 20: pick(2) ? glEnable(GL_PRIMITIVE_RESTART) : glPrimitiveRestartIndex(GLuint(pick(4))); break;
      case 22:
        if (pick(2))
          glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, GLuint(pick(5)), name());
        else
          glBindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, GLuint(pick(5)), name(), 4 * pick(8) - 4,
                            4 * pick(16) - 4);
        break;
      case 23: pick(3) ? glBeginTransformFeedback(modes[pick(8)]) : glEndTransformFeedback(); break;
      case 24: glUseProgram(tf); break;
      case 25: (pick(2) ? glEnable : glDisable)(GL_RASTERIZER_DISCARD); break;
      default: glVertexAttrib4f(GLuint(pick(18)), 1.0f, 2.0f, 3.0f, 4.0f); break;
    }
    if (call >= 13 && call <= 16 && glGetError() == GL_NO_ERROR) ++drawn;
  }
  EXPECT_GT(drawn, 10);  // the sequence reaches the pipeline, not only the checks
  glEndTransformFeedback();
  glFinish();
  while (glGetError() != GL_NO_ERROR) {
  }
  EXPECT_EQ(get_int(GL_MAX_VERTEX_ATTRIBS), 16);
}

}  // namespace

namespace {

// GL 1.3/1.4/2.0/3.3 calls that restate others: transposed matrices, glWindowPos,
// glMultiTexCoord (one coordinate set), packed attribute values, separate stencil state.
TEST_F(GL33Test, RestatedCallsAndSeparateStencil) {
  const float rows[16] = {1, 0, 0, 5, 0, 1, 0, 6, 0, 0, 1, 7, 0, 0, 0, 1};  // a translation, row-major
  glMatrixMode(GL_MODELVIEW);
  glLoadTransposeMatrixf(rows);
  float m[16] = {};
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_EQ(m[12], 5.0f);
  EXPECT_EQ(m[14], 7.0f);
  glMultTransposeMatrixf(rows);
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_EQ(m[13], 12.0f);
  glGetFloatv(GL_TRANSPOSE_MODELVIEW_MATRIX, m);
  EXPECT_EQ(m[7], 12.0f);
  glLoadIdentity();

  glWindowPos3f(5.0f, 7.0f, 0.5f);
  float rp[4] = {};
  glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
  EXPECT_EQ(rp[0], 5.0f);
  EXPECT_EQ(rp[1], 7.0f);
  EXPECT_FLOAT_EQ(rp[2], 0.5f);
  GLboolean valid = GL_FALSE;
  glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  EXPECT_TRUE(valid);

  glMultiTexCoord2f(GL_TEXTURE0, 0.25f, 0.5f);
  float tc[4] = {};
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, tc);
  EXPECT_EQ(tc[0], 0.25f);
  EXPECT_EQ(tc[3], 1.0f);
  glMultiTexCoord2f(GL_TEXTURE8, 1.0f, 1.0f);  // GL_MAX_TEXTURE_COORDS is 8
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));

  // x = 1023 (1.0), y = 0, z = 512 (~0.5), w = 3 (1.0), unsigned normalized.
  const GLuint packed = 1023u | (0u << 10) | (512u << 20) | (3u << 30);
  glVertexAttribP4ui(1, GL_UNSIGNED_INT_2_10_10_10_REV, GL_TRUE, packed);
  float a[4] = {};
  glGetVertexAttribfv(1, GL_CURRENT_VERTEX_ATTRIB, a);
  EXPECT_FLOAT_EQ(a[0], 1.0f);
  EXPECT_FLOAT_EQ(a[2], 512.0f / 1023.0f);
  EXPECT_FLOAT_EQ(a[3], 1.0f);
  glVertexAttribP4ui(1, GL_FLOAT, GL_TRUE, packed);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  glVertexAttribP4ui(99, GL_UNSIGNED_INT_2_10_10_10_REV, GL_TRUE, packed);
  EXPECT_EQ(err(), GLenum(GL_INVALID_VALUE));

  // Separate stencil: back faces replace with 5, front faces keep.
  glStencilFuncSeparate(GL_BACK, GL_ALWAYS, 5, 0xFF);
  glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_REPLACE);
  glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMaskSeparate(0x1234, 0xFF);
  EXPECT_EQ(err(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_STENCIL_BACK_REF), 5);
  EXPECT_EQ(get_int(GL_STENCIL_BACK_PASS_DEPTH_PASS), GL_REPLACE);
  EXPECT_EQ(get_int(GL_STENCIL_PASS_DEPTH_PASS), GL_KEEP);
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glBegin(GL_TRIANGLES);  // clockwise: back-facing, left half
  glVertex2f(-1, -1);
  glVertex2f(-1, 1);
  glVertex2f(0, -1);
  glEnd();
  glBegin(GL_TRIANGLES);  // counter-clockwise: front-facing, right half
  glVertex2f(0.2f, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glEnd();
  glDisable(GL_STENCIL_TEST);
  GLubyte s[2] = {9, 9};
  glReadPixels(2, 4, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[0]);
  glReadPixels(30, 4, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[1]);
  EXPECT_EQ(s[0], 5);
  EXPECT_EQ(s[1], 0);
  glStencilOp(GL_INCR_WRAP, GL_DECR_WRAP, GL_KEEP);
  EXPECT_EQ(err(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_STENCIL_BACK_FAIL), GL_INCR_WRAP);
}

}  // namespace
