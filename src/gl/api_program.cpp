// Shader and program objects (GL 3.3 §2.11), their uniforms (§2.11.4) and queries (§6.1.15),
// over the glsl layer (include/tessel/glsl/program.hpp). Errors as the specification lists
// them: a name that is no object is GL_INVALID_VALUE, an object of the other kind
// GL_INVALID_OPERATION.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "api.hpp"

namespace tessel::gl {

namespace {

ShaderObject* shader_of(Context& c, GLuint name) {
  auto it = c.shaders.find(name);
  if (it != c.shaders.end()) return &it->second;
  c.error(c.programs.count(name) ? GL_INVALID_OPERATION : GL_INVALID_VALUE);
  return nullptr;
}

ProgramObject* program_of(Context& c, GLuint name) {
  auto it = c.programs.find(name);
  if (it != c.programs.end()) return &it->second;
  c.error(c.shaders.count(name) ? GL_INVALID_OPERATION : GL_INVALID_VALUE);
  return nullptr;
}

// A linked program's executable, or GL_INVALID_OPERATION (queries that need a link).
glsl::Program* linked_program(Context& c, GLuint name) {
  ProgramObject* p = program_of(c, name);
  if (!p) return nullptr;
  if (!p->usable()) {
    c.error(GL_INVALID_OPERATION);
    return nullptr;
  }
  return p->linked.get();
}

// glGetAttribLocation, glGetUniformLocation, glGetFragData*: -1 for no name; a program that
// is not linked is GL_INVALID_OPERATION (and -1).
template <class Fn>
GLint location_query(GLuint program, const GLchar* name, Fn&& find) {
  GL_CONTEXT(-1);
  GL_OUTSIDE_BEGIN(-1);
  glsl::Program* p = linked_program(c, program);
  if (!p || !name) return -1;
  return find(*p, name);
}

GLuint fresh_object_name(Context& c) {
  while (c.next_shader_name == 0 || c.shaders.count(c.next_shader_name) ||
         c.programs.count(c.next_shader_name))
    ++c.next_shader_name;
  return c.next_shader_name++;
}

void erase_shader_if_unused(Context& c, GLuint name) {
  auto it = c.shaders.find(name);
  if (it != c.shaders.end() && it->second.delete_pending && it->second.attached == 0) c.shaders.erase(it);
}

void erase_program(Context& c, GLuint name) {
  auto it = c.programs.find(name);
  if (it == c.programs.end()) return;
  for (GLuint s : it->second.attached) {
    auto sh = c.shaders.find(s);
    if (sh != c.shaders.end()) --sh->second.attached;
    erase_shader_if_unused(c, s);
  }
  c.programs.erase(it);
  c.compat_cache.erase(name);
}

// Copies `text` into a caller's buffer as glGet*InfoLog and glGetActive* do: at most
// bufSize - 1 characters and a terminating null; `length` gets the characters written.
void copy_out(const std::string& text, GLsizei size, GLsizei* length, GLchar* out) {
  GLsizei n = 0;
  if (out && size > 0) {
    n = GLsizei(std::min<size_t>(text.size(), size_t(size - 1)));
    std::memcpy(out, text.data(), size_t(n));
    out[n] = '\0';
  }
  if (length) *length = n;
}

GLint log_length(const std::string& log) { return log.empty() ? 0 : GLint(log.size() + 1); }

// What a GL uniform type holds: components per element, and its base type.
enum class Base { Float, Int, Uint, Bool, Sampler };
struct TypeInfo {
  int components = 0;
  Base base = Base::Float;
  int columns = 1, rows = 1;  // matrices
};

TypeInfo type_info(GLenum t) {
  switch (t) {
    case GL_FLOAT: return {1, Base::Float};
    case GL_FLOAT_VEC2: return {2, Base::Float};
    case GL_FLOAT_VEC3: return {3, Base::Float};
    case GL_FLOAT_VEC4: return {4, Base::Float};
    case GL_INT: return {1, Base::Int};
    case GL_INT_VEC2: return {2, Base::Int};
    case GL_INT_VEC3: return {3, Base::Int};
    case GL_INT_VEC4: return {4, Base::Int};
    case GL_UNSIGNED_INT: return {1, Base::Uint};
    case GL_UNSIGNED_INT_VEC2: return {2, Base::Uint};
    case GL_UNSIGNED_INT_VEC3: return {3, Base::Uint};
    case GL_UNSIGNED_INT_VEC4: return {4, Base::Uint};
    case GL_BOOL: return {1, Base::Bool};
    case GL_BOOL_VEC2: return {2, Base::Bool};
    case GL_BOOL_VEC3: return {3, Base::Bool};
    case GL_BOOL_VEC4: return {4, Base::Bool};
    case GL_FLOAT_MAT2: return {4, Base::Float, 2, 2};
    case GL_FLOAT_MAT3: return {9, Base::Float, 3, 3};
    case GL_FLOAT_MAT4: return {16, Base::Float, 4, 4};
    case GL_FLOAT_MAT2x3: return {6, Base::Float, 2, 3};
    case GL_FLOAT_MAT2x4: return {8, Base::Float, 2, 4};
    case GL_FLOAT_MAT3x2: return {6, Base::Float, 3, 2};
    case GL_FLOAT_MAT3x4: return {12, Base::Float, 3, 4};
    case GL_FLOAT_MAT4x2: return {8, Base::Float, 4, 2};
    case GL_FLOAT_MAT4x3: return {12, Base::Float, 4, 3};
    default: return {1, Base::Sampler};  // every other uniform type is a sampler
  }
}

// The GL type of the uniform at `location` of `p` (its element 0 or any element), 0 if none.
GLenum uniform_type_at(const glsl::Program& p, GLint location) {
  for (const glsl::Variable& u : p.uniforms())
    if (location >= u.location && location < u.location + u.size) return u.type;
  return 0;
}

// glUniform*: the current program's executable, or GL_INVALID_OPERATION.
glsl::Program* uniform_target(Context& c, GLsizei count) {
  if (c.in_begin) {
    c.error(GL_INVALID_OPERATION);
    return nullptr;
  }
  if (count < 0) {
    c.error(GL_INVALID_VALUE);
    return nullptr;
  }
  if (!c.executable) {
    c.error(GL_INVALID_OPERATION);
    return nullptr;
  }
  return c.executable.get();
}

template <class T>
void uniform(GLint location, GLsizei count, int components, const T* v) {
  GL_CONTEXT();
  glsl::Program* p = uniform_target(c, count);
  if (!p || location == -1) return;
  if (!v && count > 0) return;
  if constexpr (std::is_same_v<T, GLint>) {
    // GL 3.3 §2.11.4: a sampler takes texture unit numbers, each below the unit count.
    if (type_info(uniform_type_at(*p, location)).base == Base::Sampler)
      for (GLsizei i = 0; i < count * components; ++i)
        if (v[i] < 0 || v[i] >= kMaxTextureUnits) return c.error(GL_INVALID_VALUE);
  }
  c.touch();
  if (!p->set_uniform(location, v, components, count)) c.error(GL_INVALID_OPERATION);
}

void uniform_matrix(GLint location, GLsizei count, GLboolean transpose, int columns, int rows,
                    const GLfloat* v) {
  GL_CONTEXT();
  glsl::Program* p = uniform_target(c, count);
  if (!p || location == -1) return;
  if (!v && count > 0) return;
  const int n = columns * rows;
  std::vector<GLfloat> m(v, v + size_t(count) * size_t(n));
  if (transpose) {
    // Given row by row: element (column j, row i) is at i * columns + j.
    for (GLsizei k = 0; k < count; ++k)
      for (int j = 0; j < columns; ++j)
        for (int i = 0; i < rows; ++i) m[size_t(k * n + j * rows + i)] = v[size_t(k * n + i * columns + j)];
  }
  const GLenum t = uniform_type_at(*p, location);
  const TypeInfo info = type_info(t);
  if (t == 0 || info.columns != columns || info.rows != rows) return c.error(GL_INVALID_OPERATION);
  c.touch();
  if (!p->set_uniform(location, m.data(), n, count)) c.error(GL_INVALID_OPERATION);
}

// Every active uniform as glGetActiveUniform enumerates them: those of the default block,
// then the members of each uniform block.
struct ActiveUniform {
  std::string name;
  GLenum type;
  GLint size;
  GLint block = -1, offset = -1, array_stride = -1, matrix_stride = -1;
  bool row_major = false;
};

std::vector<ActiveUniform> active_uniforms(const glsl::Program& p) {
  std::vector<ActiveUniform> out;
  for (const glsl::Variable& u : p.uniforms()) out.push_back({u.name, u.type, u.size});
  const auto& blocks = p.uniform_blocks();
  for (size_t b = 0; b < blocks.size(); ++b)
    for (const glsl::UniformBlockMember& m : blocks[b].members) {
      const bool matrix = type_info(m.type).columns > 1;
      out.push_back({m.size > 1 ? m.name + "[0]" : m.name, m.type, m.size, GLint(b), m.offset,
                     m.size > 1 ? m.array_stride : 0, matrix ? m.matrix_stride : 0, matrix && m.row_major});
    }
  return out;
}

}  // namespace

extern "C" {

// --- shader objects ---------------------------------------------------------------------

GLuint GLAPIENTRY glCreateShader(GLenum type) {
  GL_CONTEXT(0);
  GL_OUTSIDE_BEGIN(0);
  if (type != GL_VERTEX_SHADER && type != GL_FRAGMENT_SHADER && type != GL_GEOMETRY_SHADER) {
    c.error(GL_INVALID_ENUM);
    return 0;
  }
  const GLuint name = fresh_object_name(c);
  ShaderObject& s = c.shaders[name];
  s.name = name;
  s.type = type;
  return name;
}

void GLAPIENTRY glDeleteShader(GLuint name) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (name == 0) return;
  ShaderObject* s = shader_of(c, name);
  if (!s) return;
  s->delete_pending = true;  // GL 3.3 §2.11.1: deleted once no program has it attached
  erase_shader_if_unused(c, name);
}

GLboolean GLAPIENTRY glIsShader(GLuint name) {
  GL_CONTEXT(GL_FALSE);
  GL_OUTSIDE_BEGIN(GL_FALSE);
  return c.shaders.count(name) ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY glShaderSource(GLuint name, GLsizei count, const GLchar* const* strings,
                               const GLint* lengths) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ShaderObject* s = shader_of(c, name);
  if (!s) return;
  if (count < 0) return c.error(GL_INVALID_VALUE);
  std::vector<std::string> src;
  for (GLsizei i = 0; i < count; ++i) {
    const GLchar* str = strings ? strings[i] : nullptr;
    if (!str) {
      src.emplace_back();
      continue;
    }
    if (lengths && lengths[i] >= 0)
      src.emplace_back(str, size_t(lengths[i]));
    else
      src.emplace_back(str);
  }
  s->source = std::move(src);
}

void GLAPIENTRY glCompileShader(GLuint name) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ShaderObject* s = shader_of(c, name);
  if (!s) return;
  s->compiled = glsl::Shader::compile(s->type == GL_VERTEX_SHADER     ? glsl::Stage::Vertex
                                      : s->type == GL_GEOMETRY_SHADER ? glsl::Stage::Geometry
                                                                      : glsl::Stage::Fragment,
                                      s->joined());
}

void GLAPIENTRY glGetShaderiv(GLuint name, GLenum pname, GLint* out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ShaderObject* s = shader_of(c, name);
  if (!s) return;
  GLint v = 0;
  switch (pname) {
    case GL_SHADER_TYPE: v = GLint(s->type); break;
    case GL_DELETE_STATUS: v = s->delete_pending; break;
    case GL_COMPILE_STATUS: v = s->compiled && s->compiled->ok(); break;
    case GL_INFO_LOG_LENGTH: v = s->compiled ? log_length(s->compiled->info_log()) : 0; break;
    case GL_SHADER_SOURCE_LENGTH: {
      const std::string j = s->joined();
      v = j.empty() ? 0 : GLint(j.size() + 1);
      break;
    }
    default: return c.error(GL_INVALID_ENUM);
  }
  if (out) *out = v;
}

void GLAPIENTRY glGetShaderInfoLog(GLuint name, GLsizei size, GLsizei* length, GLchar* log) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (size < 0) return c.error(GL_INVALID_VALUE);
  ShaderObject* s = shader_of(c, name);
  if (!s) return;
  copy_out(s->compiled ? s->compiled->info_log() : std::string(), size, length, log);
}

void GLAPIENTRY glGetShaderSource(GLuint name, GLsizei size, GLsizei* length, GLchar* source) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (size < 0) return c.error(GL_INVALID_VALUE);
  ShaderObject* s = shader_of(c, name);
  if (!s) return;
  copy_out(s->joined(), size, length, source);
}

// --- program objects --------------------------------------------------------------------

GLuint GLAPIENTRY glCreateProgram(void) {
  GL_CONTEXT(0);
  GL_OUTSIDE_BEGIN(0);
  const GLuint name = fresh_object_name(c);
  c.programs[name].name = name;
  return name;
}

void GLAPIENTRY glDeleteProgram(GLuint name) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (name == 0) return;
  ProgramObject* p = program_of(c, name);
  if (!p) return;
  // The current program lives on until another is made current (GL 3.3 §2.11.3).
  if (c.current_program == name)
    p->delete_pending = true;
  else
    erase_program(c, name);
}

GLboolean GLAPIENTRY glIsProgram(GLuint name) {
  GL_CONTEXT(GL_FALSE);
  GL_OUTSIDE_BEGIN(GL_FALSE);
  return c.programs.count(name) ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY glAttachShader(GLuint program, GLuint shader) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ProgramObject* p = program_of(c, program);
  if (!p) return;
  ShaderObject* s = shader_of(c, shader);
  if (!s) return;
  if (std::find(p->attached.begin(), p->attached.end(), shader) != p->attached.end())
    return c.error(GL_INVALID_OPERATION);
  p->attached.push_back(shader);
  ++s->attached;
}

void GLAPIENTRY glDetachShader(GLuint program, GLuint shader) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ProgramObject* p = program_of(c, program);
  if (!p) return;
  ShaderObject* s = shader_of(c, shader);
  if (!s) return;
  auto it = std::find(p->attached.begin(), p->attached.end(), shader);
  if (it == p->attached.end()) return c.error(GL_INVALID_OPERATION);
  p->attached.erase(it);
  --s->attached;
  erase_shader_if_unused(c, shader);
}

void GLAPIENTRY glGetAttachedShaders(GLuint program, GLsizei max, GLsizei* count, GLuint* shaders) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (max < 0) return c.error(GL_INVALID_VALUE);
  ProgramObject* p = program_of(c, program);
  if (!p) return;
  GLsizei n = 0;
  for (GLuint s : p->attached) {
    if (n >= max || !shaders) break;
    shaders[n++] = s;
  }
  if (count) *count = n;
}

void GLAPIENTRY glBindAttribLocation(GLuint program, GLuint index, const GLchar* name) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (index >= GLuint(kMaxVertexAttribs)) return c.error(GL_INVALID_VALUE);
  ProgramObject* p = program_of(c, program);
  if (!p || !name) return;
  if (std::strncmp(name, "gl_", 3) == 0) return c.error(GL_INVALID_OPERATION);
  p->attribute_bindings[name] = GLint(index);  // takes effect at the next link
}

void GLAPIENTRY glBindFragDataLocation(GLuint program, GLuint color, const GLchar* name) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (color >= GLuint(gpu::kMaxColorAttachments)) return c.error(GL_INVALID_VALUE);
  ProgramObject* p = program_of(c, program);
  if (!p || !name) return;
  if (std::strncmp(name, "gl_", 3) == 0) return c.error(GL_INVALID_OPERATION);
  p->frag_data_bindings[name] = GLint(color);
}

void GLAPIENTRY glBindFragDataLocationIndexed(GLuint program, GLuint color, GLuint index,
                                              const GLchar* name) {
  GL_CONTEXT();
  // GL 3.3 §3.9.2: index 0 or 1, and an index-1 colour below GL_MAX_DUAL_SOURCE_DRAW_BUFFERS (1).
  if (index > 1 || (index == 1 && color >= 1)) return c.error(GL_INVALID_VALUE);
  glBindFragDataLocation(program, color, name);
  ProgramObject* p = program_of(c, program);
  if (p && name && std::strncmp(name, "gl_", 3) != 0) p->frag_data_indices[name] = GLint(index);
}

void GLAPIENTRY glLinkProgram(GLuint program) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ProgramObject* p = program_of(c, program);
  if (!p) return;
  // GL 3.3 §2.15.2: not the program transform feedback is capturing with.
  if (c.feedback.active && program == c.current_program) return c.error(GL_INVALID_OPERATION);
  c.touch();
  std::vector<std::shared_ptr<glsl::Shader>> keep;
  std::vector<const glsl::Shader*> units;
  std::string problem;
  for (GLuint name : p->attached) {
    const ShaderObject& s = c.shaders.at(name);
    if (!s.compiled || !s.compiled->ok()) {
      problem += "error: shader " + std::to_string(name) + " is not compiled\n";
      continue;
    }
    keep.push_back(s.compiled);
    units.push_back(s.compiled.get());
  }
  p->link_attempted = true;
  p->validated = false;
  if (!problem.empty()) {
    p->linked.reset();
    p->log = problem;
    return;
  }
  glsl::LinkOptions options;
  options.feedback_varyings = p->feedback_varyings;
  options.feedback_separate = p->feedback_mode == GL_SEPARATE_ATTRIBS;
  options.attribute_locations = p->attribute_bindings;
  options.frag_data_locations = p->frag_data_bindings;
  options.frag_data_indices = p->frag_data_indices;
  p->linked = glsl::Program::link(units, options);
  p->log = p->linked->info_log();
  c.compat_cache.erase(program);
  // Without a fragment shader, a compatibility context's draws add fixed function's
  // (Context::executable_run): what that needs to link the program again.
  p->vertex_only_shaders.clear();
  std::erase_if(c.vertex_only_runs, [&](const auto& e) { return e.first.first == program; });
  const bool has_fragment = std::any_of(
      units.begin(), units.end(), [](const glsl::Shader* s) { return s->stage() == glsl::Stage::Fragment; });
  if (!has_fragment && p->linked->ok()) {
    p->vertex_only_shaders = keep;
    p->vertex_only_options = options;
  }
  // A successful link of the current program replaces what draws run (GL 3.3 §2.11.2).
  if (c.current_program == program && p->usable()) c.executable = p->linked;
}

void GLAPIENTRY glUseProgram(GLuint program) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (c.feedback.active) return c.error(GL_INVALID_OPERATION);  // GL 3.3 §2.15.2
  std::shared_ptr<glsl::Program> exe;
  if (program != 0) {
    ProgramObject* p = program_of(c, program);
    if (!p) return;
    if (!p->usable()) return c.error(GL_INVALID_OPERATION);
    exe = p->linked;
  }
  c.touch();
  const GLuint old = c.current_program;
  c.current_program = program;
  c.executable = std::move(exe);
  if (old != program) {
    auto it = c.programs.find(old);
    if (it != c.programs.end() && it->second.delete_pending) erase_program(c, old);
  }
}

void GLAPIENTRY glValidateProgram(GLuint program) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ProgramObject* p = program_of(c, program);
  if (!p) return;
  p->validated = p->usable();
  if (!p->validated) p->log = p->link_attempted ? p->log : "error: the program is not linked\n";
}

void GLAPIENTRY glGetProgramiv(GLuint program, GLenum pname, GLint* out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ProgramObject* p = program_of(c, program);
  if (!p) return;
  const glsl::Program* g = p->usable() ? p->linked.get() : nullptr;
  GLint v = 0;
  auto max_name = [](const auto& list, auto name_of) {
    GLint m = 0;
    for (const auto& x : list) m = std::max(m, GLint(name_of(x).size() + 1));
    return m;
  };
  switch (pname) {
    case GL_DELETE_STATUS: v = p->delete_pending; break;
    case GL_LINK_STATUS: v = p->usable(); break;
    case GL_VALIDATE_STATUS: v = p->validated; break;
    case GL_INFO_LOG_LENGTH: v = log_length(p->log); break;
    case GL_ATTACHED_SHADERS: v = GLint(p->attached.size()); break;
    case GL_ACTIVE_ATTRIBUTES: v = g ? GLint(g->attributes().size()) : 0; break;
    case GL_ACTIVE_ATTRIBUTE_MAX_LENGTH:
      v = g ? max_name(g->attributes(), [](const glsl::Variable& x) -> const std::string& { return x.name; })
            : 0;
      break;
    case GL_ACTIVE_UNIFORMS: v = g ? GLint(active_uniforms(*g).size()) : 0; break;
    case GL_ACTIVE_UNIFORM_MAX_LENGTH:
      v = g ? max_name(active_uniforms(*g),
                       [](const ActiveUniform& x) -> const std::string& { return x.name; })
            : 0;
      break;
    case GL_ACTIVE_UNIFORM_BLOCKS: v = g ? GLint(g->uniform_blocks().size()) : 0; break;
    case GL_ACTIVE_UNIFORM_BLOCK_MAX_NAME_LENGTH:
      v = g ? max_name(g->uniform_blocks(),
                       [](const glsl::UniformBlock& x) -> const std::string& { return x.name; })
            : 0;
      break;
    // What glTransformFeedbackVaryings gave, linked or not yet, as Mesa reports it.
    case GL_TRANSFORM_FEEDBACK_BUFFER_MODE: v = GLint(p->feedback_mode); break;
    case GL_TRANSFORM_FEEDBACK_VARYINGS: v = GLint(p->feedback_varyings.size()); break;
    case GL_TRANSFORM_FEEDBACK_VARYING_MAX_LENGTH:
      v = max_name(p->feedback_varyings, [](const std::string& x) -> const std::string& { return x; });
      break;
    // GL 3.3 §6.1.16: a program without a linked geometry shader has none of these.
    case GL_GEOMETRY_VERTICES_OUT:
    case GL_GEOMETRY_INPUT_TYPE:
    case GL_GEOMETRY_OUTPUT_TYPE: {
      const glsl::GeometryInfo* gi = g ? g->geometry() : nullptr;
      if (!gi) return c.error(GL_INVALID_OPERATION);
      v = pname == GL_GEOMETRY_VERTICES_OUT ? gi->max_vertices
          : pname == GL_GEOMETRY_INPUT_TYPE ? GLint(gi->input_type)
                                            : GLint(gi->output_type);
      break;
    }
    default: return c.error(GL_INVALID_ENUM);
  }
  if (out) *out = v;
}

void GLAPIENTRY glGetProgramInfoLog(GLuint program, GLsizei size, GLsizei* length, GLchar* log) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (size < 0) return c.error(GL_INVALID_VALUE);
  ProgramObject* p = program_of(c, program);
  if (!p) return;
  copy_out(p->log, size, length, log);
}

GLint GLAPIENTRY glGetAttribLocation(GLuint program, const GLchar* name) {
  return location_query(program, name,
                        [](const glsl::Program& p, const char* n) { return p.attribute_location(n); });
}

GLint GLAPIENTRY glGetFragDataLocation(GLuint program, const GLchar* name) {
  return location_query(program, name,
                        [](const glsl::Program& p, const char* n) { return p.frag_data_location(n); });
}

GLint GLAPIENTRY glGetFragDataIndex(GLuint program, const GLchar* name) {
  return location_query(program, name,
                        [](const glsl::Program& p, const char* n) { return p.frag_data_index(n); });
}

GLint GLAPIENTRY glGetUniformLocation(GLuint program, const GLchar* name) {
  // The compatibility state is not a user uniform (GLSL 1.20 §7.5: gl_ names are reserved).
  return location_query(program, name, [](const glsl::Program& p, const char* n) {
    return std::strncmp(n, "gl_", 3) == 0 ? -1 : p.uniform_location(n);
  });
}

void GLAPIENTRY glGetActiveAttrib(GLuint program, GLuint index, GLsizei size, GLsizei* length, GLint* count,
                                  GLenum* type, GLchar* name) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (size < 0) return c.error(GL_INVALID_VALUE);
  ProgramObject* po = program_of(c, program);
  if (!po) return;
  if (!po->usable() || index >= po->linked->attributes().size()) return c.error(GL_INVALID_VALUE);
  const glsl::Variable& v = po->linked->attributes()[index];
  copy_out(v.name, size, length, name);
  if (count) *count = v.size;
  if (type) *type = v.type;
}

// GL 3.3 §2.11.8: the outputs transform feedback captures, set for the next link.
void GLAPIENTRY glTransformFeedbackVaryings(GLuint program, GLsizei count, const GLchar* const* varyings,
                                            GLenum mode) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (mode != GL_INTERLEAVED_ATTRIBS && mode != GL_SEPARATE_ATTRIBS) return c.error(GL_INVALID_ENUM);
  ProgramObject* p = program_of(c, program);
  if (!p) return;
  if (count < 0 || (mode == GL_SEPARATE_ATTRIBS && count > glsl::kMaxFeedbackSeparateAttribs))
    return c.error(GL_INVALID_VALUE);
  if (c.feedback.active && program == c.current_program) return c.error(GL_INVALID_OPERATION);
  if (count > 0 && !varyings) return;
  std::vector<std::string> names;
  for (GLsizei i = 0; i < count; ++i) names.emplace_back(varyings[i] ? varyings[i] : "");
  p->feedback_varyings = std::move(names);
  p->feedback_mode = mode;
}

void GLAPIENTRY glGetTransformFeedbackVarying(GLuint program, GLuint index, GLsizei size, GLsizei* length,
                                              GLsizei* count, GLenum* type, GLchar* name) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ProgramObject* po = program_of(c, program);
  if (!po) return;
  if (size < 0) return c.error(GL_INVALID_VALUE);
  if (!po->usable() || index >= po->linked->feedback_varyings().size()) return c.error(GL_INVALID_VALUE);
  const glsl::FeedbackVarying& v = po->linked->feedback_varyings()[index];
  copy_out(v.name, size, length, name);
  if (count) *count = v.size;
  if (type) *type = v.type;
}

void GLAPIENTRY glGetActiveUniform(GLuint program, GLuint index, GLsizei size, GLsizei* length, GLint* count,
                                   GLenum* type, GLchar* name) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (size < 0) return c.error(GL_INVALID_VALUE);
  ProgramObject* po = program_of(c, program);
  if (!po) return;
  const std::vector<ActiveUniform> all =
      po->usable() ? active_uniforms(*po->linked) : std::vector<ActiveUniform>{};
  if (index >= all.size()) return c.error(GL_INVALID_VALUE);
  copy_out(all[index].name, size, length, name);
  if (count) *count = all[index].size;
  if (type) *type = all[index].type;
}

void GLAPIENTRY glGetActiveUniformName(GLuint program, GLuint index, GLsizei size, GLsizei* length,
                                       GLchar* name) {
  glGetActiveUniform(program, index, size, length, nullptr, nullptr, name);
}

void GLAPIENTRY glGetUniformIndices(GLuint program, GLsizei count, const GLchar* const* names,
                                    GLuint* indices) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (count < 0) return c.error(GL_INVALID_VALUE);
  ProgramObject* po = program_of(c, program);
  if (!po || !names || !indices) return;
  const std::vector<ActiveUniform> all =
      po->usable() ? active_uniforms(*po->linked) : std::vector<ActiveUniform>{};
  for (GLsizei i = 0; i < count; ++i) {
    indices[i] = GL_INVALID_INDEX;
    if (!names[i]) continue;
    const std::string n = names[i];
    for (size_t k = 0; k < all.size(); ++k) {
      const std::string& a = all[k].name;
      // "a" names "a[0]" too (GL 3.3 §2.11.4).
      if (a == n ||
          (a.size() > 3 && a.compare(a.size() - 3, 3, "[0]") == 0 && a.substr(0, a.size() - 3) == n)) {
        indices[i] = GLuint(k);
        break;
      }
    }
  }
}

void GLAPIENTRY glGetActiveUniformsiv(GLuint program, GLsizei count, const GLuint* indices, GLenum pname,
                                      GLint* params) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (count < 0) return c.error(GL_INVALID_VALUE);
  ProgramObject* po = program_of(c, program);
  if (!po || !indices) return;
  const std::vector<ActiveUniform> all =
      po->usable() ? active_uniforms(*po->linked) : std::vector<ActiveUniform>{};
  for (GLsizei i = 0; i < count; ++i)
    if (indices[i] >= all.size()) return c.error(GL_INVALID_VALUE);
  switch (pname) {
    case GL_UNIFORM_TYPE:
    case GL_UNIFORM_SIZE:
    case GL_UNIFORM_NAME_LENGTH:
    case GL_UNIFORM_BLOCK_INDEX:
    case GL_UNIFORM_OFFSET:
    case GL_UNIFORM_ARRAY_STRIDE:
    case GL_UNIFORM_MATRIX_STRIDE:
    case GL_UNIFORM_IS_ROW_MAJOR: break;
    default: return c.error(GL_INVALID_ENUM);
  }
  if (!params) return;
  for (GLsizei i = 0; i < count; ++i) {
    const ActiveUniform& u = all[indices[i]];
    GLint v = 0;
    switch (pname) {
      case GL_UNIFORM_TYPE: v = GLint(u.type); break;
      case GL_UNIFORM_SIZE: v = u.size; break;
      case GL_UNIFORM_NAME_LENGTH: v = GLint(u.name.size() + 1); break;
      case GL_UNIFORM_BLOCK_INDEX: v = u.block; break;
      case GL_UNIFORM_OFFSET: v = u.offset; break;
      case GL_UNIFORM_ARRAY_STRIDE: v = u.array_stride; break;
      case GL_UNIFORM_MATRIX_STRIDE: v = u.matrix_stride; break;
      default: v = u.row_major; break;
    }
    params[i] = v;
  }
}

GLuint GLAPIENTRY glGetUniformBlockIndex(GLuint program, const GLchar* name) {
  GL_CONTEXT(GL_INVALID_INDEX);
  GL_OUTSIDE_BEGIN(GL_INVALID_INDEX);
  ProgramObject* po = program_of(c, program);
  if (!po || !name || !po->usable()) return GL_INVALID_INDEX;
  const int i = po->linked->uniform_block_index(name);
  return i < 0 ? GL_INVALID_INDEX : GLuint(i);
}

void GLAPIENTRY glGetActiveUniformBlockiv(GLuint program, GLuint index, GLenum pname, GLint* params) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ProgramObject* po = program_of(c, program);
  if (!po) return;
  if (!po->usable() || index >= po->linked->uniform_blocks().size()) return c.error(GL_INVALID_VALUE);
  const glsl::UniformBlock& b = po->linked->uniform_blocks()[index];
  std::vector<GLint> indices;
  const std::vector<ActiveUniform> all = active_uniforms(*po->linked);
  for (size_t k = 0; k < all.size(); ++k)
    if (all[k].block == GLint(index)) indices.push_back(GLint(k));
  GLint v = 0;
  switch (pname) {
    case GL_UNIFORM_BLOCK_BINDING: v = b.binding; break;
    case GL_UNIFORM_BLOCK_DATA_SIZE: v = b.size; break;
    case GL_UNIFORM_BLOCK_NAME_LENGTH: v = GLint(b.name.size() + 1); break;
    case GL_UNIFORM_BLOCK_ACTIVE_UNIFORMS: v = GLint(indices.size()); break;
    case GL_UNIFORM_BLOCK_ACTIVE_UNIFORM_INDICES:
      if (params) std::copy(indices.begin(), indices.end(), params);
      return;
    // The reflection does not say which stage reads a block: both are reported.
    case GL_UNIFORM_BLOCK_REFERENCED_BY_VERTEX_SHADER:
    case GL_UNIFORM_BLOCK_REFERENCED_BY_FRAGMENT_SHADER: v = 1; break;
    case GL_UNIFORM_BLOCK_REFERENCED_BY_GEOMETRY_SHADER: v = 0; break;
    default: return c.error(GL_INVALID_ENUM);
  }
  if (params) *params = v;
}

void GLAPIENTRY glGetActiveUniformBlockName(GLuint program, GLuint index, GLsizei size, GLsizei* length,
                                            GLchar* name) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (size < 0) return c.error(GL_INVALID_VALUE);
  ProgramObject* po = program_of(c, program);
  if (!po) return;
  if (!po->usable() || index >= po->linked->uniform_blocks().size()) return c.error(GL_INVALID_VALUE);
  copy_out(po->linked->uniform_blocks()[index].name, size, length, name);
}

void GLAPIENTRY glUniformBlockBinding(GLuint program, GLuint index, GLuint binding) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ProgramObject* po = program_of(c, program);
  if (!po) return;
  if (!po->usable() || index >= po->linked->uniform_blocks().size() ||
      binding >= GLuint(kMaxUniformBufferBindings))
    return c.error(GL_INVALID_VALUE);
  c.touch();
  po->linked->set_uniform_block_binding(int(index), int(binding));
}

// --- uniforms ---------------------------------------------------------------------------

#define TESSEL_UNIFORM(N, SUF, T, ...)                                              \
  void GLAPIENTRY glUniform##N##SUF(GLint location, __VA_ARGS__) {                  \
    const T v[] = {TESSEL_ARGS_##N};                                                \
    uniform<T>(location, 1, N, v);                                                  \
  }                                                                                 \
  void GLAPIENTRY glUniform##N##SUF##v(GLint location, GLsizei count, const T* v) { \
    uniform<T>(location, count, N, v);                                              \
  }
#define TESSEL_ARGS_1 v0
#define TESSEL_ARGS_2 v0, v1
#define TESSEL_ARGS_3 v0, v1, v2
#define TESSEL_ARGS_4 v0, v1, v2, v3
TESSEL_UNIFORM(1, f, GLfloat, GLfloat v0)
TESSEL_UNIFORM(2, f, GLfloat, GLfloat v0, GLfloat v1)
TESSEL_UNIFORM(3, f, GLfloat, GLfloat v0, GLfloat v1, GLfloat v2)
TESSEL_UNIFORM(4, f, GLfloat, GLfloat v0, GLfloat v1, GLfloat v2, GLfloat v3)
TESSEL_UNIFORM(1, i, GLint, GLint v0)
TESSEL_UNIFORM(2, i, GLint, GLint v0, GLint v1)
TESSEL_UNIFORM(3, i, GLint, GLint v0, GLint v1, GLint v2)
TESSEL_UNIFORM(4, i, GLint, GLint v0, GLint v1, GLint v2, GLint v3)
TESSEL_UNIFORM(1, ui, GLuint, GLuint v0)
TESSEL_UNIFORM(2, ui, GLuint, GLuint v0, GLuint v1)
TESSEL_UNIFORM(3, ui, GLuint, GLuint v0, GLuint v1, GLuint v2)
TESSEL_UNIFORM(4, ui, GLuint, GLuint v0, GLuint v1, GLuint v2, GLuint v3)
#undef TESSEL_UNIFORM
#undef TESSEL_ARGS_1
#undef TESSEL_ARGS_2
#undef TESSEL_ARGS_3
#undef TESSEL_ARGS_4

#define TESSEL_UNIFORM_MATRIX(NAME, C, R)                                                       \
  void GLAPIENTRY glUniformMatrix##NAME##fv(GLint location, GLsizei count, GLboolean transpose, \
                                            const GLfloat* v) {                                 \
    uniform_matrix(location, count, transpose, C, R, v);                                        \
  }
TESSEL_UNIFORM_MATRIX(2, 2, 2)
TESSEL_UNIFORM_MATRIX(3, 3, 3)
TESSEL_UNIFORM_MATRIX(4, 4, 4)
TESSEL_UNIFORM_MATRIX(2x3, 2, 3)
TESSEL_UNIFORM_MATRIX(3x2, 3, 2)
TESSEL_UNIFORM_MATRIX(2x4, 2, 4)
TESSEL_UNIFORM_MATRIX(4x2, 4, 2)
TESSEL_UNIFORM_MATRIX(3x4, 3, 4)
TESSEL_UNIFORM_MATRIX(4x3, 4, 3)
#undef TESSEL_UNIFORM_MATRIX

}  // extern "C"

namespace {

// glGetUniform*: one element's components, converted as GL 3.3 §6.1.15 says.
template <class T>
void get_uniform(GLuint program, GLint location, T* out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  glsl::Program* p = linked_program(c, program);
  if (!p) return;
  const GLenum t = uniform_type_at(*p, location);
  uint32_t w[16];
  if (t == 0 || !p->get_uniform_words(location, w)) return c.error(GL_INVALID_OPERATION);
  if (!out) return;
  const TypeInfo info = type_info(t);
  for (int i = 0; i < info.components; ++i) {
    double v = 0;
    switch (info.base) {
      case Base::Float: {
        float f;
        std::memcpy(&f, &w[i], 4);
        v = f;
        break;
      }
      case Base::Int:
      case Base::Sampler: v = int32_t(w[i]); break;
      case Base::Uint: v = w[i]; break;
      case Base::Bool: v = w[i] ? 1 : 0; break;
    }
    if constexpr (std::is_integral_v<T>)
      out[i] = T(info.base == Base::Float ? std::lround(v) : (long long)v);
    else
      out[i] = T(v);
  }
}

}  // namespace

extern "C" {

void GLAPIENTRY glGetUniformfv(GLuint program, GLint location, GLfloat* out) {
  get_uniform(program, location, out);
}
void GLAPIENTRY glGetUniformiv(GLuint program, GLint location, GLint* out) {
  get_uniform(program, location, out);
}
void GLAPIENTRY glGetUniformuiv(GLuint program, GLint location, GLuint* out) {
  get_uniform(program, location, out);
}

}  // extern "C"

std::string ShaderObject::joined() const {
  std::string s;
  for (const std::string& part : source) s += part;
  return s;
}

// GL 2.0 §2.15.4 (GL 2.1 §3.11): with no fragment shader in the current program, fixed
// function's fragment processing (texturing, colour sum, fog, alpha test) follows the
// program's vertex shader. A compatibility context links the program's shaders again with
// fixed function's generated fragment stage (ff_fragment_source_after_vertex_shader) for the
// state of the draw, once per state, and gives that program the executable's uniform values.
// A core context draws with the executable, whose fragments then have no colour defined.
Context::ProgramRun Context::executable_run(PrimClass cls) {
  ProgramObject* po = nullptr;
  if (!core_profile) {
    auto it = programs.find(current_program);
    if (it != programs.end() && !it->second.vertex_only_shaders.empty() && it->second.linked == executable)
      po = &it->second;
  }
  if (!po) return {*executable, compat_cache[current_program]};
  FFProgramKey key;
  TextureObject* unit0 = nullptr;
  ff_program_key(cls, key, unit0);
  key.lighting = key.two_side = 0;  // lighting is the vertex shader's
  VertexOnlyRun& run = vertex_only_runs[{current_program, key.bytes()}];
  if (!run.program) {
    std::vector<const glsl::Shader*> units;
    for (const auto& s : po->vertex_only_shaders) units.push_back(s.get());
    const auto fs = glsl::Shader::compile(glsl::Stage::Fragment, ff_fragment_source_after_vertex_shader(key));
    units.push_back(fs.get());
    run.program = glsl::Program::link(units, po->vertex_only_options);
    if (!run.program->ok()) {  // never: the executable linked, and the fragment stage is Tessel's
      vertex_only_runs.erase({current_program, key.bytes()});
      return {*executable, compat_cache[current_program]};
    }
  }
  glsl::Program& p = *run.program;
  // The executable's uniform values, element by element (uniform blocks keep their bindings).
  for (const glsl::Variable& u : executable->uniforms()) {
    const int to = p.uniform_location(u.name);
    if (to < 0) continue;
    const TypeInfo t = type_info(u.type);
    for (int i = 0; i < u.size; ++i) {
      uint32_t words[16] = {};
      if (!executable->get_uniform_words(u.location + i, words)) continue;
      if (t.base == Base::Float)
        p.set_uniform(to + i, reinterpret_cast<const float*>(words), t.components);
      else if (t.base == Base::Uint)
        p.set_uniform(to + i, words, t.components);
      else
        p.set_uniform(to + i, reinterpret_cast<const int32_t*>(words), t.components);
    }
  }
  for (const glsl::UniformBlock& b : executable->uniform_blocks())
    p.set_uniform_block_binding(p.uniform_block_index(b.name), b.binding);
  set_ff_uniforms(p, key);  // fixed function's own, as draw_ff_program sets them
  return {p, run.cache};
}

}  // namespace tessel::gl
