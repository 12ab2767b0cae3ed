// The objects GL 1.5 to 3.3 add to the context: buffer objects, vertex array objects, shader
// and program objects (GL 3.3 core §2.9, §2.10, §2.11). Objects are shared by pointer: a
// buffer deleted while a vertex array object still refers to it lives on until that
// reference goes (GL 3.3 §5.1.2).
#pragma once

#include <GL/gl.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "tessel/glsl/program.hpp"
#include "tessel/gpu/buffer.hpp"

namespace tessel::gl {

inline constexpr int kMaxVertexAttribs = gpu::kMaxVertexAttribs;
inline constexpr int kMaxUniformBufferBindings = 36;  // GL 3.3 Table 6.51: 36

struct BufferObject {
  GLuint name = 0;
  gpu::Buffer data;
  GLenum usage = GL_STATIC_DRAW;
  // glMapBuffer(Range): while mapped, draws that read the buffer are errors (GL 3.3 §2.9.3).
  bool mapped = false;
  GLbitfield map_access = 0;  // GL_MAP_*_BIT
  size_t map_offset = 0, map_length = 0;
};
using BufferRef = std::shared_ptr<BufferObject>;

// One generic attribute array (glVertexAttribPointer) of a vertex array object.
struct AttribArray {
  bool enabled = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  bool normalized = false;
  bool integer = false;  // glVertexAttribIPointer
  GLsizei stride = 0;    // as given (0: tightly packed)
  GLuint divisor = 0;
  // With a buffer bound to GL_ARRAY_BUFFER at glVertexAttribPointer: the buffer and the
  // offset into it. Without one (compatibility contexts, vertex array object 0): client
  // memory at `pointer`.
  BufferRef buffer;
  const void* pointer = nullptr;
  GLsizei effective_stride() const;
};

struct VertexArrayObject {
  bool bound_once = false;  // glIsVertexArray is true once the name was bound
  std::array<AttribArray, kMaxVertexAttribs> attribs{};
  BufferRef element_buffer;  // GL_ELEMENT_ARRAY_BUFFER binding
};

struct ShaderObject {
  GLuint name = 0;
  GLenum type = GL_VERTEX_SHADER;
  std::vector<std::string> source;  // glShaderSource's strings, kept as given
  std::string joined() const;
  std::shared_ptr<glsl::Shader> compiled;  // after glCompileShader
  bool delete_pending = false;
  int attached = 0;  // programs it is attached to
};

struct ProgramObject {
  GLuint name = 0;
  std::vector<GLuint> attached;
  std::map<std::string, int> attribute_bindings, frag_data_bindings;  // applied at link
  std::map<std::string, int> frag_data_indices;                       // glBindFragDataLocationIndexed
  std::shared_ptr<glsl::Program> linked;                              // the last link's result (ok() or not)
  // glTransformFeedbackVaryings: applied at the next link (and what glGetProgramiv reports).
  std::vector<std::string> feedback_varyings;
  GLenum feedback_mode = GL_INTERLEAVED_ATTRIBS;
  std::string log;  // the last link's or validation's info log
  bool link_attempted = false, validated = false;
  bool delete_pending = false;
  bool usable() const { return linked && linked->ok(); }
  // A program linked without a fragment shader: its shaders and options, to link it again
  // with fixed function's fragment stage in a compatibility context (GL 2.0 §2.15.4).
  std::vector<std::shared_ptr<glsl::Shader>> vertex_only_shaders;
  glsl::LinkOptions vertex_only_options;
};

}  // namespace tessel::gl
