// Mesa llvmpipe GLSL oracle: see glsl_oracle.hpp.
//
// The headless EGL display and the compatibility-profile context come from tessel_gl_headless
// (bench/gl). GL entry points come straight from libOpenGL (glvnd), which exports every GL
// function (compatibility ones included) and dispatches to the context made current through
// libEGL.
#include "glsl_oracle.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstddef>
#include <cstdlib>
#include <exception>
#include <map>
#include <string>
#include <utility>

#include "headless_gl.hpp"

namespace tessel::reference {
namespace {

using tessel::gl::gl_error_name;
using tessel::gl::hex;

// Mesa's text for each GL error (e.g. "glUniform1fv(count = 2 for non-array uniform)") says
// far more than the bare enum, so API error messages are collected here and attached to the
// error that glGetError reports next.
void GLAPIENTRY debug_callback(GLenum /*source*/, GLenum type, GLuint /*id*/, GLenum /*severity*/,
                               GLsizei length, const GLchar* message, const void* user) {
  // Only errors: Mesa also reports shader compile logs and performance notes here, which the
  // info logs already carry or which do not matter for results.
  if (type != GL_DEBUG_TYPE_ERROR || !message || !user) return;
  auto* pending = static_cast<std::string*>(const_cast<void*>(user));
  if (!pending->empty()) *pending += "; ";
  if (length >= 0)
    pending->append(message, size_t(length));
  else
    pending->append(message);
}

// What a run found wrong, as lines for GlslResult::log.
struct Problems {
  std::string text;
  bool any = false;
  void add(const std::string& line) {
    text += line;
    text += '\n';
    any = true;
  }
};

// A uniform type as the data it takes: base 'f', 'i', 'u' or 'b' and cols x rows components
// (cols > 1: a matrix, column-major). Samplers take one int (the unit).
struct UniformType {
  char base = 0;
  int cols = 1, rows = 1;
};

bool is_sampler(GLenum t) {
  switch (t) {
    case GL_SAMPLER_1D:
    case GL_SAMPLER_2D:
    case GL_SAMPLER_3D:
    case GL_SAMPLER_CUBE:
    case GL_SAMPLER_1D_SHADOW:
    case GL_SAMPLER_2D_SHADOW:
    case GL_SAMPLER_1D_ARRAY:
    case GL_SAMPLER_2D_ARRAY:
    case GL_SAMPLER_1D_ARRAY_SHADOW:
    case GL_SAMPLER_2D_ARRAY_SHADOW:
    case GL_SAMPLER_CUBE_SHADOW:
    case GL_SAMPLER_2D_RECT:
    case GL_SAMPLER_2D_RECT_SHADOW:
    case GL_SAMPLER_BUFFER:
    case GL_SAMPLER_2D_MULTISAMPLE:
    case GL_SAMPLER_2D_MULTISAMPLE_ARRAY:
    case GL_SAMPLER_CUBE_MAP_ARRAY:
    case GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW:
    case GL_INT_SAMPLER_1D:
    case GL_INT_SAMPLER_2D:
    case GL_INT_SAMPLER_3D:
    case GL_INT_SAMPLER_CUBE:
    case GL_INT_SAMPLER_1D_ARRAY:
    case GL_INT_SAMPLER_2D_ARRAY:
    case GL_INT_SAMPLER_2D_RECT:
    case GL_INT_SAMPLER_BUFFER:
    case GL_INT_SAMPLER_2D_MULTISAMPLE:
    case GL_INT_SAMPLER_2D_MULTISAMPLE_ARRAY:
    case GL_INT_SAMPLER_CUBE_MAP_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_1D:
    case GL_UNSIGNED_INT_SAMPLER_2D:
    case GL_UNSIGNED_INT_SAMPLER_3D:
    case GL_UNSIGNED_INT_SAMPLER_CUBE:
    case GL_UNSIGNED_INT_SAMPLER_1D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D_RECT:
    case GL_UNSIGNED_INT_SAMPLER_BUFFER:
    case GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE:
    case GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_CUBE_MAP_ARRAY: return true;
    default: return false;
  }
}

bool uniform_type(GLenum t, UniformType* out) {
  auto set = [&](char base, int cols, int rows) {
    *out = UniformType{base, cols, rows};
    return true;
  };
  switch (t) {
    case GL_FLOAT: return set('f', 1, 1);
    case GL_FLOAT_VEC2: return set('f', 1, 2);
    case GL_FLOAT_VEC3: return set('f', 1, 3);
    case GL_FLOAT_VEC4: return set('f', 1, 4);
    case GL_INT: return set('i', 1, 1);
    case GL_INT_VEC2: return set('i', 1, 2);
    case GL_INT_VEC3: return set('i', 1, 3);
    case GL_INT_VEC4: return set('i', 1, 4);
    case GL_UNSIGNED_INT: return set('u', 1, 1);
    case GL_UNSIGNED_INT_VEC2: return set('u', 1, 2);
    case GL_UNSIGNED_INT_VEC3: return set('u', 1, 3);
    case GL_UNSIGNED_INT_VEC4: return set('u', 1, 4);
    case GL_BOOL: return set('b', 1, 1);
    case GL_BOOL_VEC2: return set('b', 1, 2);
    case GL_BOOL_VEC3: return set('b', 1, 3);
    case GL_BOOL_VEC4: return set('b', 1, 4);
    case GL_FLOAT_MAT2: return set('f', 2, 2);
    case GL_FLOAT_MAT3: return set('f', 3, 3);
    case GL_FLOAT_MAT4: return set('f', 4, 4);
    case GL_FLOAT_MAT2x3: return set('f', 2, 3);
    case GL_FLOAT_MAT2x4: return set('f', 2, 4);
    case GL_FLOAT_MAT3x2: return set('f', 3, 2);
    case GL_FLOAT_MAT3x4: return set('f', 3, 4);
    case GL_FLOAT_MAT4x2: return set('f', 4, 2);
    case GL_FLOAT_MAT4x3: return set('f', 4, 3);
    default:
      if (is_sampler(t)) return set('i', 1, 1);
      return false;
  }
}

template <typename To, typename From>
std::vector<To> convert(const std::vector<From>& v) {
  std::vector<To> out;
  out.reserve(v.size());
  for (const From& x : v) out.push_back(static_cast<To>(x));
  return out;
}

// glUniform* for one uniform of type t at loc. Returns "" or what was wrong with the data.
std::string set_uniform(GLint loc, const UniformType& t, const GlslUniform& u) {
  const int given = int(!u.f.empty()) + int(!u.i.empty()) + int(!u.u.empty());
  if (given != 1)
    return given == 0 ? "no values (f, i and u are all empty)" : "values in more than one of f, i and u";
  const size_t n = !u.f.empty() ? u.f.size() : !u.i.empty() ? u.i.size() : u.u.size();
  const size_t comps = size_t(t.cols * t.rows);
  if (n % comps != 0)
    return std::to_string(n) + " values are not a multiple of the type's " + std::to_string(comps) +
           " components";
  const GLsizei count = GLsizei(n / comps);

  if (t.cols > 1) {  // matrices: column-major, as given
    const std::vector<float> f = !u.f.empty()   ? u.f
                                 : !u.i.empty() ? convert<float>(u.i)
                                                : convert<float>(u.u);
    const float* p = f.data();
    switch (t.cols * 10 + t.rows) {
      case 22: glUniformMatrix2fv(loc, count, GL_FALSE, p); break;
      case 33: glUniformMatrix3fv(loc, count, GL_FALSE, p); break;
      case 44: glUniformMatrix4fv(loc, count, GL_FALSE, p); break;
      case 23: glUniformMatrix2x3fv(loc, count, GL_FALSE, p); break;
      case 24: glUniformMatrix2x4fv(loc, count, GL_FALSE, p); break;
      case 32: glUniformMatrix3x2fv(loc, count, GL_FALSE, p); break;
      case 34: glUniformMatrix3x4fv(loc, count, GL_FALSE, p); break;
      case 42: glUniformMatrix4x2fv(loc, count, GL_FALSE, p); break;
      case 43: glUniformMatrix4x3fv(loc, count, GL_FALSE, p); break;
      default: return "internal: bad matrix shape";
    }
    return "";
  }

  // Bool uniforms take whichever variant was given (GL accepts f, i and u for them); the
  // other base types get their own variant, the values converted if need be.
  char variant = t.base;
  if (variant == 'b') variant = !u.f.empty() ? 'f' : !u.i.empty() ? 'i' : 'u';
  switch (variant) {
    case 'f': {
      const std::vector<float> v = !u.f.empty()   ? u.f
                                   : !u.i.empty() ? convert<float>(u.i)
                                                  : convert<float>(u.u);
      switch (t.rows) {
        case 1: glUniform1fv(loc, count, v.data()); break;
        case 2: glUniform2fv(loc, count, v.data()); break;
        case 3: glUniform3fv(loc, count, v.data()); break;
        default: glUniform4fv(loc, count, v.data()); break;
      }
      break;
    }
    case 'i': {
      const std::vector<GLint> v = !u.i.empty()   ? u.i
                                   : !u.f.empty() ? convert<GLint>(u.f)
                                                  : convert<GLint>(u.u);
      switch (t.rows) {
        case 1: glUniform1iv(loc, count, v.data()); break;
        case 2: glUniform2iv(loc, count, v.data()); break;
        case 3: glUniform3iv(loc, count, v.data()); break;
        default: glUniform4iv(loc, count, v.data()); break;
      }
      break;
    }
    default: {
      const std::vector<GLuint> v = !u.u.empty()   ? u.u
                                    : !u.i.empty() ? convert<GLuint>(u.i)
                                                   : convert<GLuint>(u.f);
      switch (t.rows) {
        case 1: glUniform1uiv(loc, count, v.data()); break;
        case 2: glUniform2uiv(loc, count, v.data()); break;
        case 3: glUniform3uiv(loc, count, v.data()); break;
        default: glUniform4uiv(loc, count, v.data()); break;
      }
      break;
    }
  }
  return "";
}

// The type of the active uniform that `name` (as glGetUniformLocation takes it) falls in.
// glGetActiveUniform lists arrays of basic types once, as "k[0]", but arrays of structs
// member by member ("lights[1].pos"), so "k", "k[2]" and "lights[1].pos" are all found.
bool find_uniform_type(const std::map<std::string, GLenum>& active, const std::string& name, GLenum* type) {
  auto try_name = [&](const std::string& n) {
    auto it = active.find(n);
    if (it == active.end()) return false;
    *type = it->second;
    return true;
  };
  if (try_name(name) || try_name(name + "[0]")) return true;
  if (!name.empty() && name.back() == ']') {
    const size_t open = name.rfind('[');
    if (open != std::string::npos) {
      const std::string base = name.substr(0, open);
      if (try_name(base + "[0]") || try_name(base)) return true;
    }
  }
  return false;
}

bool is_depth_format(GLenum f) {
  return f == GL_DEPTH_COMPONENT || f == GL_DEPTH_COMPONENT16 || f == GL_DEPTH_COMPONENT24 ||
         f == GL_DEPTH_COMPONENT32 || f == GL_DEPTH_COMPONENT32F;
}

// 0: not an integer format; 'i': signed; 'u': unsigned.
char integer_format(GLenum f) {
  switch (f) {
    case GL_R8I:
    case GL_R16I:
    case GL_R32I:
    case GL_RG8I:
    case GL_RG16I:
    case GL_RG32I:
    case GL_RGB8I:
    case GL_RGB16I:
    case GL_RGB32I:
    case GL_RGBA8I:
    case GL_RGBA16I:
    case GL_RGBA32I: return 'i';
    case GL_R8UI:
    case GL_R16UI:
    case GL_R32UI:
    case GL_RG8UI:
    case GL_RG16UI:
    case GL_RG32UI:
    case GL_RGB8UI:
    case GL_RGB16UI:
    case GL_RGB32UI:
    case GL_RGBA8UI:
    case GL_RGBA16UI:
    case GL_RGBA32UI:
    case GL_RGB10_A2UI: return 'u';
    default: return 0;
  }
}

// A matrix attribute type as columns x rows; {1, 1} for anything else.
std::pair<int, int> attribute_matrix_shape(GLenum t) {
  switch (t) {
    case GL_FLOAT_MAT2: return {2, 2};
    case GL_FLOAT_MAT3: return {3, 3};
    case GL_FLOAT_MAT4: return {4, 4};
    case GL_FLOAT_MAT2x3: return {2, 3};
    case GL_FLOAT_MAT2x4: return {2, 4};
    case GL_FLOAT_MAT3x2: return {3, 2};
    case GL_FLOAT_MAT3x4: return {3, 4};
    case GL_FLOAT_MAT4x2: return {4, 2};
    case GL_FLOAT_MAT4x3: return {4, 3};
    default: return {1, 1};
  }
}

std::string shader_log(GLuint s) {
  GLint len = 0;
  glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
  if (len <= 1) return "";
  std::string log(size_t(len), '\0');
  glGetShaderInfoLog(s, len, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

std::string program_log(GLuint p) {
  GLint len = 0;
  glGetProgramiv(p, GL_INFO_LOG_LENGTH, &len);
  if (len <= 1) return "";
  std::string log(size_t(len), '\0');
  glGetProgramInfoLog(p, len, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

// "heading:\n<text>\n" when text is non-empty.
std::string section(const char* heading, std::string text) {
  if (text.empty()) return "";
  if (text.back() != '\n') text += '\n';
  return std::string(heading) + ":\n" + text;
}

const float kIdentity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// Every GL object of one run. The destructor deletes them all and puts back the state the
// run changed, on every path out of run() (a failure half-way included), so the next run
// starts from the same context state.
struct RunObjects {
  GLuint vs = 0, fs = 0, gs = 0, program = 0;
  GLuint fbo = 0, depth_rb = 0, vao = 0;
  std::vector<GLuint> color_rbs, vbos, textures;

  RunObjects() = default;
  RunObjects(const RunObjects&) = delete;
  RunObjects& operator=(const RunObjects&) = delete;
  ~RunObjects() {
    glUseProgram(0);
    glBindVertexArray(0);  // the VAO holds every attribute array and its enables
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    if (program) glDeleteProgram(program);
    if (vs) glDeleteShader(vs);
    if (fs) glDeleteShader(fs);
    if (gs) glDeleteShader(gs);
    if (vao) glDeleteVertexArrays(1, &vao);
    if (!vbos.empty()) glDeleteBuffers(GLsizei(vbos.size()), vbos.data());
    // Deleting a texture also unbinds it from every unit of the current context.
    if (!textures.empty()) glDeleteTextures(GLsizei(textures.size()), textures.data());
    if (fbo) glDeleteFramebuffers(1, &fbo);
    if (!color_rbs.empty()) glDeleteRenderbuffers(GLsizei(color_rbs.size()), color_rbs.data());
    if (depth_rb) glDeleteRenderbuffers(1, &depth_rb);
    glActiveTexture(GL_TEXTURE0);
    glClientActiveTexture(GL_TEXTURE0);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    while (glGetError() != GL_NO_ERROR) {
    }
  }
};

}  // namespace

struct GlslOracle::Impl {
  // Declared first, so destroyed last: ~Impl still has the context.
  std::unique_ptr<tessel::gl::HeadlessContext> gl;
  std::string debug_pending;  // GL_DEBUG_TYPE_ERROR messages since the last check
  GLint max_draw_buffers = 8, max_units = 16, max_attribs = 16, max_tex_coords = 8;

  ~Impl() {
    // The callback points at debug_pending, which is about to go.
    if (gl && gl->make_current()) glDebugMessageCallback(nullptr, nullptr);
  }

  // Reports any queued GL error (with Mesa's messages about it) as a problem.
  void check_gl(const char* what, Problems* p) {
    GLenum first = glGetError();
    if (first == GL_NO_ERROR) {
      debug_pending.clear();
      return;
    }
    std::string msg =
        std::string("GL error after ") + what + ": " + gl_error_name(first) + " (" + hex(first) + ")";
    // Drain any further queued errors so the next check starts clean.
    for (int i = 0; i < 16; ++i) {
      const GLenum e = glGetError();
      if (e == GL_NO_ERROR) break;
      msg += std::string(", ") + gl_error_name(e);
    }
    if (!debug_pending.empty()) msg += " [Mesa: " + debug_pending + "]";
    debug_pending.clear();
    p->add(msg);
  }

  GlslResult run(const GlslDrawSpec& spec);
};

GlslOracle::GlslOracle(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

GlslOracle::~GlslOracle() = default;

std::unique_ptr<GlslOracle> GlslOracle::create(std::string* why) {
  std::string dummy;
  if (!why) why = &dummy;
  why->clear();
  try {
    // Results must come from compiling the source, never from a disk cache filled by another
    // Mesa version or build. LIBGL_ALWAYS_SOFTWARE / GALLIUM_DRIVER are forced to llvmpipe
    // by HeadlessContext::create (unless set).
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);

    auto impl = std::make_unique<Impl>();
    // A compatibility-profile context without a version asked for: Mesa then gives the
    // highest compatibility version it has (4.5 on llvmpipe), so #version 110..330 shaders
    // and the compatibility built-ins all compile.
    tessel::gl::HeadlessOptions gl_options;
    gl_options.compat_profile = true;
    std::string gl_why;
    impl->gl = tessel::gl::HeadlessContext::create(&gl_why, gl_options);
    if (!impl->gl) {
      *why = "GlslOracle: " + gl_why;
      return nullptr;
    }

    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &impl->max_draw_buffers);
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &impl->max_units);
    glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &impl->max_attribs);
    glGetIntegerv(GL_MAX_TEXTURE_COORDS, &impl->max_tex_coords);
    GLenum err = glGetError();
    if (err != GL_NO_ERROR) {
      *why = std::string("GlslOracle: GL error during setup: ") + gl_error_name(err);
      return nullptr;
    }

    // Mesa's error messages, for the log. Not having them is no reason to fail.
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(debug_callback, &impl->debug_pending);
    while (glGetError() != GL_NO_ERROR) {
    }
    impl->debug_pending.clear();
    return std::unique_ptr<GlslOracle>(new GlslOracle(std::move(impl)));
  } catch (const std::exception& e) {
    *why = std::string("GlslOracle: ") + e.what();
    return nullptr;
  }
}

std::string GlslOracle::renderer() const { return impl_->gl->renderer(); }

std::string GlslOracle::version() const { return impl_->gl->version(); }

GlslResult GlslOracle::run(const GlslDrawSpec& spec) {
  try {
    return impl_->run(spec);
  } catch (const std::exception& e) {
    GlslResult r;
    r.log = std::string("GlslOracle: exception: ") + e.what() + "\n";
    return r;
  } catch (...) {
    GlslResult r;
    r.log = "GlslOracle: unknown exception\n";
    return r;
  }
}

GlslResult GlslOracle::Impl::run(const GlslDrawSpec& spec) {
  GlslResult r;
  Problems problems;
  std::string ctx_err;
  if (!gl->make_current(&ctx_err)) {
    r.log = "GlslOracle: " + ctx_err + "\n";
    return r;
  }
  // Whatever an earlier run or caller left queued is not this run's.
  while (glGetError() != GL_NO_ERROR) {
  }
  debug_pending.clear();

  RunObjects obj;  // declared after make_current: its destructor needs the context
  // The logs and problems found so far, then ok; on every return path.
  auto finish = [&]() -> GlslResult& {
    check_gl("the run", &problems);
    r.log += problems.text;
    r.ok = r.compiled && r.linked && !problems.any;
    return r;
  };

  // Compile and link: both stages are always compiled, so both logs are there.
  auto compile = [&](GLenum type, const std::string& src, GLuint* out, const char* heading) {
    *out = glCreateShader(type);
    const char* p = src.c_str();
    glShaderSource(*out, 1, &p, nullptr);
    glCompileShader(*out);
    GLint status = GL_FALSE;
    glGetShaderiv(*out, GL_COMPILE_STATUS, &status);
    r.log += section(heading, shader_log(*out));
    return status == GL_TRUE;
  };
  const bool vs_ok = compile(GL_VERTEX_SHADER, spec.vertex, &obj.vs, "vertex shader");
  const bool fs_ok = compile(GL_FRAGMENT_SHADER, spec.fragment, &obj.fs, "fragment shader");
  const bool gs_ok =
      spec.geometry.empty() || compile(GL_GEOMETRY_SHADER, spec.geometry, &obj.gs, "geometry shader");
  r.compiled = vs_ok && fs_ok && gs_ok;
  if (!r.compiled) return finish();
  obj.program = glCreateProgram();
  glAttachShader(obj.program, obj.vs);
  if (obj.gs) glAttachShader(obj.program, obj.gs);
  glAttachShader(obj.program, obj.fs);
  glLinkProgram(obj.program);
  GLint linked = GL_FALSE;
  glGetProgramiv(obj.program, GL_LINK_STATUS, &linked);
  r.log += section("program", program_log(obj.program));
  r.linked = linked == GL_TRUE;
  if (!r.linked) return finish();
  check_gl("compiling and linking", &problems);

  // The parts of the spec that can be checked before touching GL. A bad spec draws nothing:
  // pixels from missing data would only mislead.
  const int W = spec.width, H = spec.height;
  if (W <= 0 || H <= 0 || W > 16384 || H > 16384)
    problems.add("bad target size " + std::to_string(W) + "x" + std::to_string(H));
  if (spec.outputs < 0 || spec.outputs > max_draw_buffers)
    problems.add("outputs = " + std::to_string(spec.outputs) + ", GL_MAX_DRAW_BUFFERS is " +
                 std::to_string(max_draw_buffers));
  if (spec.outputs == 0 && !spec.depth)
    problems.add("outputs = 0 without depth: the framebuffer would have no attachment");
  if (spec.count < 0) problems.add("count = " + std::to_string(spec.count));
  if (!spec.modelview.empty() && spec.modelview.size() != 16)
    problems.add("modelview has " + std::to_string(spec.modelview.size()) + " floats, not 16");
  if (!spec.projection.empty() && spec.projection.size() != 16)
    problems.add("projection has " + std::to_string(spec.projection.size()) + " floats, not 16");
  if (problems.any) return finish();

  // Context state. Set in full every run (not only once) so that nothing a run or a caller
  // changed can leak into the next one.
  glDisable(GL_DITHER);
  glDisable(GL_MULTISAMPLE);
  glDisable(GL_FRAMEBUFFER_SRGB);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_RASTERIZER_DISCARD);
  glEnable(GL_PROGRAM_POINT_SIZE);  // gl_PointSize is honoured
  glEnable(GL_POINT_SPRITE);        // gl_PointCoord defined for points, as in core GL
  // Raw shader results: the compatibility profile would clamp gl_FrontColor & co. by default.
  glClampColor(GL_CLAMP_VERTEX_COLOR, GL_FALSE);
  glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE);
  glClampColor(GL_CLAMP_READ_COLOR, GL_FALSE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glViewport(0, 0, W, H);
  glDepthRange(0.0, 1.0);
  for (int i = 0; i < 8; ++i) {
    if ((spec.clip_distances >> i) & 1)
      glEnable(GLenum(GL_CLIP_DISTANCE0 + i));
    else
      glDisable(GLenum(GL_CLIP_DISTANCE0 + i));
  }
  if (spec.depth) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  // Current vertex attributes (what a shader input without an array reads), back to their
  // defaults: GL leaves them undefined after drawing from arrays.
  for (GLint i = 0; i < max_attribs; ++i) glVertexAttrib4f(GLuint(i), 0, 0, 0, 1);
  glColor4f(1, 1, 1, 1);
  glSecondaryColor3f(0, 0, 0);
  glNormal3f(0, 0, 1);
  glFogCoordf(0);
  for (GLint i = 0; i < max_tex_coords; ++i) glMultiTexCoord4f(GLenum(GL_TEXTURE0 + i), 0, 0, 0, 1);
  // Fixed-function matrices for gl_ModelViewMatrix, gl_ProjectionMatrix, ...
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(spec.projection.empty() ? kIdentity : spec.projection.data());
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(spec.modelview.empty() ? kIdentity : spec.modelview.data());
  check_gl("setting context state", &problems);

  // Framebuffer: RGBA32F colour renderbuffers (float, so nothing is clamped or quantized)
  // and optionally a DEPTH_COMPONENT32F one.
  glGenFramebuffers(1, &obj.fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, obj.fbo);
  std::vector<GLenum> draw_buffers;
  for (int i = 0; i < spec.outputs; ++i) {
    GLuint rb = 0;
    glGenRenderbuffers(1, &rb);
    obj.color_rbs.push_back(rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, W, H);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_RENDERBUFFER, rb);
    draw_buffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  }
  if (spec.depth) {
    glGenRenderbuffers(1, &obj.depth_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, obj.depth_rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, W, H);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, obj.depth_rb);
  }
  if (draw_buffers.empty()) {
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
  } else {
    glDrawBuffers(GLsizei(draw_buffers.size()), draw_buffers.data());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
  }
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    problems.add("framebuffer incomplete (" + hex(status) + ")");
    return finish();
  }
  check_gl("creating the framebuffer", &problems);

  // Textures.
  for (size_t ti = 0; ti < spec.textures.size(); ++ti) {
    const GlslTexture& t = spec.textures[ti];
    const std::string tname = "texture " + std::to_string(ti) + ": ";
    if (t.unit < 0 || t.unit >= max_units) {
      problems.add(tname + "unit " + std::to_string(t.unit) + " out of range (0.." +
                   std::to_string(max_units - 1) + ")");
      continue;
    }
    if (t.width <= 0 || t.height <= 0 || t.depth <= 0) {
      problems.add(tname + "bad size");
      continue;
    }
    size_t texels = 0;
    switch (t.target) {
      case GL_TEXTURE_1D: texels = size_t(t.width); break;
      case GL_TEXTURE_2D:
      case GL_TEXTURE_RECTANGLE:
      case GL_TEXTURE_1D_ARRAY: texels = size_t(t.width) * size_t(t.height); break;
      case GL_TEXTURE_3D:
      case GL_TEXTURE_2D_ARRAY: texels = size_t(t.width) * size_t(t.height) * size_t(t.depth); break;
      case GL_TEXTURE_CUBE_MAP: texels = size_t(t.width) * size_t(t.height) * 6; break;
      case GL_TEXTURE_BUFFER: texels = size_t(t.width); break;
      default: problems.add(tname + "unsupported target " + hex(t.target)); continue;
    }
    const bool depth_fmt = is_depth_format(t.internal_format);
    const char int_fmt = integer_format(t.internal_format);
    const size_t comps = depth_fmt ? 1 : 4;
    if (t.data.size() < texels * comps) {
      problems.add(tname + "data has " + std::to_string(t.data.size()) + " floats, needs " +
                   std::to_string(texels * comps));
      continue;
    }
    // Integer formats take integer data (GL does not convert floats to them).
    std::vector<GLint> idata;
    std::vector<GLuint> udata;
    GLenum format = depth_fmt ? GL_DEPTH_COMPONENT : GL_RGBA;
    GLenum type = GL_FLOAT;
    const void* pixels = t.data.data();
    size_t texel_bytes = comps * sizeof(float);
    if (int_fmt == 'i') {
      idata = convert<GLint>(t.data);
      format = GL_RGBA_INTEGER;
      type = GL_INT;
      pixels = idata.data();
    } else if (int_fmt == 'u') {
      udata = convert<GLuint>(t.data);
      format = GL_RGBA_INTEGER;
      type = GL_UNSIGNED_INT;
      pixels = udata.data();
    }
    static_assert(sizeof(GLint) == sizeof(float) && sizeof(GLuint) == sizeof(float));

    GLuint tex = 0;
    glGenTextures(1, &tex);
    obj.textures.push_back(tex);
    glActiveTexture(GLenum(GL_TEXTURE0 + t.unit));
    glBindTexture(t.target, tex);
    const GLint ifmt = GLint(t.internal_format);
    switch (t.target) {
      case GL_TEXTURE_1D: glTexImage1D(t.target, 0, ifmt, t.width, 0, format, type, pixels); break;
      case GL_TEXTURE_2D:
      case GL_TEXTURE_RECTANGLE:
      case GL_TEXTURE_1D_ARRAY:
        glTexImage2D(t.target, 0, ifmt, t.width, t.height, 0, format, type, pixels);
        break;
      case GL_TEXTURE_3D:
      case GL_TEXTURE_2D_ARRAY:
        glTexImage3D(t.target, 0, ifmt, t.width, t.height, t.depth, 0, format, type, pixels);
        break;
      case GL_TEXTURE_BUFFER: {
        // The texels as they are laid out in memory, in a buffer object the texture reads.
        GLuint buf = 0;
        glGenBuffers(1, &buf);
        obj.vbos.push_back(buf);  // deleted with the run's other buffers
        glBindBuffer(GL_TEXTURE_BUFFER, buf);
        glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(texels * texel_bytes), pixels, GL_STATIC_DRAW);
        glTexBuffer(GL_TEXTURE_BUFFER, GLenum(ifmt), buf);
        glBindBuffer(GL_TEXTURE_BUFFER, 0);
        break;
      }
      case GL_TEXTURE_CUBE_MAP: {
        // GL_TEXTURE_CUBE_MAP_POSITIVE_X + i runs +X -X +Y -Y +Z -Z, the order of the data.
        const size_t face_bytes = size_t(t.width) * size_t(t.height) * texel_bytes;
        for (int face = 0; face < 6; ++face)
          glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, ifmt, t.width, t.height, 0, format,
                       type, static_cast<const char*>(pixels) + face_bytes * size_t(face));
        break;
      }
    }
    if (t.target == GL_TEXTURE_BUFFER) {  // no sampler state, no levels
      check_gl(("uploading " + tname.substr(0, tname.size() - 2)).c_str(), &problems);
      continue;
    }
    const bool rect = t.target == GL_TEXTURE_RECTANGLE;
    glTexParameteri(t.target, GL_TEXTURE_BASE_LEVEL, 0);
    if (t.mipmaps) {
      glTexParameteri(t.target, GL_TEXTURE_MAX_LEVEL, 1000);
      glGenerateMipmap(t.target);
    } else {
      // Complete even with a *_MIPMAP_* min filter (which then uses level 0).
      glTexParameteri(t.target, GL_TEXTURE_MAX_LEVEL, 0);
    }
    glTexParameteri(t.target, GL_TEXTURE_MIN_FILTER, GLint(t.min_filter));
    glTexParameteri(t.target, GL_TEXTURE_MAG_FILTER, GLint(t.mag_filter));
    // A rectangle texture cannot repeat (GL_INVALID_ENUM); it keeps its CLAMP_TO_EDGE then.
    if (!(rect && (t.wrap == GL_REPEAT || t.wrap == GL_MIRRORED_REPEAT))) {
      glTexParameteri(t.target, GL_TEXTURE_WRAP_S, GLint(t.wrap));
      glTexParameteri(t.target, GL_TEXTURE_WRAP_T, GLint(t.wrap));
      glTexParameteri(t.target, GL_TEXTURE_WRAP_R, GLint(t.wrap));
    }
    glTexParameteri(t.target, GL_TEXTURE_COMPARE_MODE, t.compare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
    glTexParameteri(t.target, GL_TEXTURE_COMPARE_FUNC, GLint(t.compare_func));
    check_gl(("uploading " + tname.substr(0, tname.size() - 2)).c_str(), &problems);
  }
  glActiveTexture(GL_TEXTURE0);
  if (problems.any) return finish();

  // Uniforms, by name; their types from glGetActiveUniform.
  glUseProgram(obj.program);
  std::map<std::string, GLenum> active_uniforms;
  {
    GLint n = 0, max_len = 0;
    glGetProgramiv(obj.program, GL_ACTIVE_UNIFORMS, &n);
    glGetProgramiv(obj.program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &max_len);
    std::vector<char> buf(size_t(max_len) + 1);
    for (GLint i = 0; i < n; ++i) {
      GLsizei len = 0;
      GLint size = 0;
      GLenum type = 0;
      glGetActiveUniform(obj.program, GLuint(i), GLsizei(buf.size()), &len, &size, &type, buf.data());
      active_uniforms[std::string(buf.data(), size_t(len))] = type;
    }
  }
  for (const GlslUniform& u : spec.uniforms) {
    const GLint loc = glGetUniformLocation(obj.program, u.name.c_str());
    if (loc < 0) continue;  // not active (or not there): skipped, as promised
    GLenum gl_type = 0;
    UniformType t;
    if (!find_uniform_type(active_uniforms, u.name, &gl_type)) {
      problems.add("uniform '" + u.name + "': has a location but no active uniform entry");
      continue;
    }
    if (!uniform_type(gl_type, &t)) {
      problems.add("uniform '" + u.name + "': unsupported type " + hex(gl_type));
      continue;
    }
    const std::string err = set_uniform(loc, t, u);
    if (!err.empty()) problems.add("uniform '" + u.name + "': " + err);
    check_gl(("setting uniform '" + u.name + "'").c_str(), &problems);
  }
  if (problems.any) return finish();

  // Attributes: one VBO each, in a VAO of this run (which takes every array pointer and
  // enable with it when deleted).
  glGenVertexArrays(1, &obj.vao);
  glBindVertexArray(obj.vao);
  std::map<std::string, GLenum> active_attribs;
  {
    GLint n = 0, max_len = 0;
    glGetProgramiv(obj.program, GL_ACTIVE_ATTRIBUTES, &n);
    glGetProgramiv(obj.program, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, &max_len);
    std::vector<char> buf(size_t(max_len) + 1);
    for (GLint i = 0; i < n; ++i) {
      GLsizei len = 0;
      GLint size = 0;
      GLenum type = 0;
      glGetActiveAttrib(obj.program, GLuint(i), GLsizei(buf.size()), &len, &size, &type, buf.data());
      active_attribs[std::string(buf.data(), size_t(len))] = type;
    }
  }
  for (const GlslAttribute& a : spec.attributes) {
    const std::string aname = "attribute '" + a.name + "': ";
    const bool builtin = a.name.rfind("gl_", 0) == 0;
    GLint loc = -1;
    if (!builtin) {
      loc = glGetAttribLocation(obj.program, a.name.c_str());
      if (loc < 0) continue;  // inactive: skipped
    }
    const int comps = a.components;
    if (comps < 1) {
      problems.add(aname + "components = " + std::to_string(comps));
      continue;
    }
    const size_t have = a.integer ? a.idata.size() : a.data.size();
    if (have < size_t(spec.count) * size_t(comps)) {
      problems.add(aname + "has " + std::to_string(have) + " values, needs " +
                   std::to_string(size_t(spec.count) * size_t(comps)) + " (" + std::to_string(spec.count) +
                   " vertices x " + std::to_string(comps) + ")");
      continue;
    }
    GLuint vbo = 0;
    glGenBuffers(1, &vbo);
    obj.vbos.push_back(vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    if (a.integer)
      glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(a.idata.size() * sizeof(int32_t)), a.idata.data(),
                   GL_STATIC_DRAW);
    else
      glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(a.data.size() * sizeof(float)), a.data.data(), GL_STATIC_DRAW);

    if (builtin) {
      // Compatibility built-in inputs go through the fixed-function arrays.
      if (a.integer) {
        problems.add(aname + "built-in attributes take floats (integer = true)");
        continue;
      }
      auto need = [&](bool ok, const char* sizes) {
        if (!ok) problems.add(aname + "components must be " + sizes);
        return ok;
      };
      if (a.name == "gl_Vertex") {
        if (!need(comps >= 2 && comps <= 4, "2..4")) continue;
        glVertexPointer(comps, GL_FLOAT, 0, nullptr);
        glEnableClientState(GL_VERTEX_ARRAY);
      } else if (a.name == "gl_Color") {
        if (!need(comps == 3 || comps == 4, "3 or 4")) continue;
        glColorPointer(comps, GL_FLOAT, 0, nullptr);
        glEnableClientState(GL_COLOR_ARRAY);
      } else if (a.name == "gl_SecondaryColor") {
        if (!need(comps == 3, "3")) continue;
        glSecondaryColorPointer(3, GL_FLOAT, 0, nullptr);
        glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
      } else if (a.name == "gl_Normal") {
        if (!need(comps == 3, "3")) continue;
        glNormalPointer(GL_FLOAT, 0, nullptr);
        glEnableClientState(GL_NORMAL_ARRAY);
      } else if (a.name == "gl_FogCoord") {
        if (!need(comps == 1, "1")) continue;
        glFogCoordPointer(GL_FLOAT, 0, nullptr);
        glEnableClientState(GL_FOG_COORD_ARRAY);
      } else if (a.name.rfind("gl_MultiTexCoord", 0) == 0 && a.name.size() == 17 && a.name[16] >= '0' &&
                 a.name[16] < char('0' + max_tex_coords)) {
        if (!need(comps >= 1 && comps <= 4, "1..4")) continue;
        glClientActiveTexture(GLenum(GL_TEXTURE0 + (a.name[16] - '0')));
        glTexCoordPointer(comps, GL_FLOAT, 0, nullptr);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glClientActiveTexture(GL_TEXTURE0);
      } else {
        problems.add(aname + "not a built-in attribute this oracle knows");
        continue;
      }
      check_gl(("setting up " + aname.substr(0, aname.size() - 2)).c_str(), &problems);
      continue;
    }

    // A matrix attribute fills one location per column.
    const auto it = active_attribs.find(a.name);
    const auto [cols, rows] = attribute_matrix_shape(it == active_attribs.end() ? GL_FLOAT_VEC4 : it->second);
    if (cols > 1) {
      if (a.integer || comps != cols * rows) {
        problems.add(aname + "a mat" + std::to_string(cols) + "x" + std::to_string(rows) +
                     " attribute takes " + std::to_string(cols * rows) + " floats per vertex");
        continue;
      }
      for (int c = 0; c < cols; ++c) {
        glVertexAttribPointer(GLuint(loc + c), rows, GL_FLOAT, GL_FALSE, GLsizei(comps * sizeof(float)),
                              reinterpret_cast<const void*>(size_t(c * rows) * sizeof(float)));
        glEnableVertexAttribArray(GLuint(loc + c));
      }
    } else {
      if (comps > 4) {
        problems.add(aname + "components = " + std::to_string(comps) + " (1..4)");
        continue;
      }
      if (a.integer)
        glVertexAttribIPointer(GLuint(loc), comps, GL_INT, 0, nullptr);
      else
        glVertexAttribPointer(GLuint(loc), comps, GL_FLOAT, GL_FALSE, 0, nullptr);
      glEnableVertexAttribArray(GLuint(loc));
    }
    check_gl(("setting up " + aname.substr(0, aname.size() - 2)).c_str(), &problems);
  }
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  if (problems.any) return finish();

  // Clear (glClearBuffer: float values go in as they are, unclamped) and draw.
  for (int i = 0; i < spec.outputs; ++i) glClearBufferfv(GL_COLOR, i, spec.clear);
  if (spec.depth) {
    const GLfloat one = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &one);
  }
  check_gl("clearing", &problems);
  for (size_t i = 0; i < spec.uniform_buffers.size(); ++i) {
    const auto& ub = spec.uniform_buffers[i];
    const GLuint index = glGetUniformBlockIndex(obj.program, ub.block.c_str());
    if (index == GL_INVALID_INDEX) continue;
    GLuint buf = 0;
    glGenBuffers(1, &buf);
    obj.vbos.push_back(buf);  // deleted with the run's other buffers
    glBindBuffer(GL_UNIFORM_BUFFER, buf);
    glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(ub.data.size()), ub.data.data(), GL_STATIC_DRAW);
    glUniformBlockBinding(obj.program, index, GLuint(i));
    glBindBufferBase(GL_UNIFORM_BUFFER, GLuint(i), buf);
  }
  glBindBuffer(GL_UNIFORM_BUFFER, 0);
  check_gl("uniform buffers", &problems);
  if (spec.count > 0) glDrawArrays(spec.primitive, 0, spec.count);
  check_gl("glDrawArrays", &problems);

  // Read back every attachment (glReadPixels waits for the draw).
  const size_t pixels = size_t(W) * size_t(H);
  for (int i = 0; i < spec.outputs; ++i) {
    std::vector<float> out(pixels * 4);
    glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + i));
    glReadPixels(0, 0, W, H, GL_RGBA, GL_FLOAT, out.data());
    r.outputs.push_back(std::move(out));
  }
  if (spec.depth) {
    r.depth.resize(pixels);
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, r.depth.data());
  }
  check_gl("glReadPixels", &problems);
  return finish();
}

}  // namespace tessel::reference
