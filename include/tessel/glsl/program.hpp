// GLSL shaders given as text, compiled at run time, and drawn by the gpu pipeline.
//
//   auto vs = glsl::Shader::compile(glsl::Stage::Vertex, vertex_source);
//   auto fs = glsl::Shader::compile(glsl::Stage::Fragment, fragment_source);
//   if (!vs->ok()) std::cerr << vs->info_log();
//   auto prog = glsl::Program::link(*vs, *fs);
//   if (!prog->ok()) std::cerr << prog->info_log();
//   prog->set_uniform(prog->uniform_location("MVP"), glm::value_ptr(mvp), 16);
//   layout.attribs[prog->attribute_location("vtxPos")] = {...};
//   prog->draw(ctx, layout, state, {.topology = gpu::Topology::Triangles, .count = n}, units);
//
// Compiling and linking never throw: errors are reported in info logs, in GL's form
// ("0:12: error: ..."). GLSL 1.10 to 3.30 are accepted, with the compatibility built-ins
// (gl_Vertex, gl_ModelViewMatrix, ...) as attributes and uniforms of those names.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tessel/gpu/context.hpp"
#include "tessel/gpu/texture.hpp"

namespace tessel::glsl {

enum class Stage : uint8_t { Vertex, Fragment, Geometry };

class Shader {
 public:
  // Compiles `source` (its #version line says which GLSL; none means 1.10). Never throws.
  static std::shared_ptr<Shader> compile(Stage stage, std::string source);
  Stage stage() const { return stage_; }
  bool ok() const { return ok_; }
  const std::string& info_log() const { return log_; }
  const std::string& source() const { return source_; }

 private:
  Stage stage_ = Stage::Vertex;
  bool ok_ = false;
  std::string source_, log_;
};

// An active attribute, uniform or fragment output, as GL reports it.
struct Variable {
  std::string name;   // uniforms of arrays end in "[0]", as glGetActiveUniform gives them
  uint32_t type = 0;  // GL type enum (GL_FLOAT_VEC3, GL_SAMPLER_2D, ...)
  int size = 1;       // array elements
  int location = -1;
};

// Locations chosen by the application before linking (glBindAttribLocation,
// glBindFragDataLocation); layout(location) qualifiers take precedence.
// When a program's native code is compiled. Until it is there the interpreter runs the
// program, with the same results bit for bit, so a draw never waits for LLVM.
enum class NativeCode {
  Background,  // on the compiler thread, after link() returns (the default)
  AtLink,      // before link() returns
  Off,         // never: the interpreter only
};

struct LinkOptions {
  std::map<std::string, int> attribute_locations;
  std::map<std::string, int> frag_data_locations;
  // glBindFragDataLocationIndexed's index (0, or 1 for the second source of dual-source
  // blending), by output name; layout(index) takes precedence.
  std::map<std::string, int> frag_data_indices;
  // glTransformFeedbackVaryings: the outputs of the stage before clipping (the geometry
  // stage's, or the vertex stage's) that transform feedback captures, by GL name ("v",
  // "a[2]", "gl_Position", "gl_PointSize", "gl_ClipDistance[1]"), into one buffer in this
  // order, or with feedback_separate each into a buffer of its own (GL_SEPARATE_ATTRIBS).
  std::vector<std::string> feedback_varyings;
  bool feedback_separate = false;
  // TESSEL_GLSL=interp in the environment means Off for every program, TESSEL_GLSL=sync AtLink.
  NativeCode native_code = NativeCode::Background;
};

// A texture unit as the program's samplers see it.
// Each sampler type reads the texture of its kind: sampler1D/2D/2DRect and their shadow
// forms texture_2d, samplerCube(Shadow) texture_cube, sampler3D texture_3d, sampler2DArray,
// sampler1DArray (a height-1 array) and their shadow forms texture_2d_array, samplerBuffer
// texture_buffer (which the sampler state does not apply to). isampler/usampler read the
// same textures, their values converted to integers.
struct TextureBinding {
  const gpu::Texture2D* texture_2d = nullptr;
  const gpu::TextureCube* texture_cube = nullptr;
  gpu::SamplerState sampler;
  const gpu::Texture3D* texture_3d = nullptr;
  const gpu::Texture2DArray* texture_2d_array = nullptr;
  const gpu::TextureBuffer* texture_buffer = nullptr;
  // GL_TEXTURE_SWIZZLE_R..A: result component i is component swizzle[i] of the texel
  // (0-3 = R, G, B, A), or 0 (4) or 1 (5).
  std::array<uint8_t, 4> swizzle{0, 1, 2, 3};
};

// A range of a buffer bound to a uniform buffer binding point (glBindBufferRange).
struct BufferBinding {
  const gpu::Buffer* buffer = nullptr;
  size_t offset = 0;
  size_t size = 0;  // 0: to the end of the buffer
};

// A program's geometry stage (GLSL 1.50 §4.3.8.1 layout qualifiers), as GL reports it
// (GL_GEOMETRY_VERTICES_OUT, GL_GEOMETRY_INPUT_TYPE, GL_GEOMETRY_OUTPUT_TYPE).
struct GeometryInfo {
  int max_vertices = 0;
  int input_vertices = 0;     // of each input primitive: 1, 2, 3, 4 or 6
  uint32_t input_type = 0;    // GL_POINTS, GL_LINES, GL_LINES_ADJACENCY, GL_TRIANGLES, GL_TRIANGLES_ADJACENCY
  uint32_t output_type = 0;   // GL_POINTS, GL_LINE_STRIP, GL_TRIANGLE_STRIP
  bool writes_layer = false;  // gl_Layer: draws into a layered framebuffer pick layers with it
};

// A captured output as glGetTransformFeedbackVarying reports it: its name as given, its GL
// type and how many of them (an array's elements, 1 for an element).
struct FeedbackVarying {
  std::string name;
  uint32_t type = 0;
  int size = 1;
};
// Transform feedback's limits (GL_MAX_TRANSFORM_FEEDBACK_*), those of llvmpipe.
inline constexpr int kMaxFeedbackInterleavedComponents = 64, kMaxFeedbackSeparateAttribs = 4,
                     kMaxFeedbackSeparateComponents = 64;
// Limits the GL layer reports and shaders see as built-in constants (gl_MaxTextureCoords,
// gl_MaxTextureImageUnits, gl_MaxCombinedTextureImageUnits, gl_Max*UniformComponents).
inline constexpr int kMaxTextureCoords = 8, kMaxStageTextureUnits = 16, kMaxCombinedTextureUnits = 48,
                     kMaxUniformComponents = 4096;

// A uniform block as GL reports it (glGetActiveUniformBlock*, glGetActiveUniforms with
// GL_UNIFORM_OFFSET and the strides): std140 layout, which also serves shared and packed.
struct UniformBlockMember {
  // GL's name, down to basic types: "member", "s.x", "ss[1].x", prefixed "Block." when the
  // block has an instance name; an array of a basic type is one member of `size` elements.
  std::string name;
  uint32_t type = 0;
  int size = 1;                                         // array elements
  int offset = 0, array_stride = 0, matrix_stride = 0;  // bytes
  bool row_major = false;
};
struct UniformBlock {
  std::string name;
  int size = 0;     // GL_UNIFORM_BLOCK_DATA_SIZE, bytes
  int binding = 0;  // the binding point it reads (glUniformBlockBinding)
  std::vector<UniformBlockMember> members;
};

// Fixed attribute locations of the compatibility attributes (as NVIDIA aliases them).
inline constexpr int kLocationVertex = 0, kLocationNormal = 2, kLocationColor = 3,
                     kLocationSecondaryColor = 4, kLocationFogCoord = 5, kLocationMultiTexCoord0 = 8;
// The fixed location of the compatibility attribute `name` ("gl_Vertex", "gl_Normal",
// "gl_Color", "gl_SecondaryColor", "gl_FogCoord", "gl_MultiTexCoord0".."7"); -1 for any other
// name. They are not active attributes (attribute_location gives -1 for them, as GL does).
int builtin_attribute_location(std::string_view name);

// Holds back (true) or lets go (false) the compiler thread of NativeCode::Background: while
// it is held no compile starts, so programs run on the interpreter. For tests, and to measure
// the interpreter tier.
void hold_background_compiles(bool hold);

// The programs this process has linked, kept in memory by their sources and LinkOptions:
// linking the same sources with the same bindings again takes the earlier link's result
// (no glslang, no lowering, no native compile) and gives the new program its own uniform
// values, at their initial state. At most kProgramCacheEntries programs are kept, the least
// recently linked dropped first; only programs that linked are kept. Shader::compile keeps
// its results the same way. The disk cache (jit.hpp) is the one that outlives the process.
inline constexpr size_t kProgramCacheEntries = 64;
struct ProgramCacheStats {
  uint64_t hits = 0, misses = 0;  // links that took a kept program, links that did the work
  size_t entries = 0;
};
ProgramCacheStats program_cache_stats();
// Forgets every kept program and compiled shader (programs already linked keep their code)
// and counts from zero again.
void clear_program_cache();

class Program {
 public:
  // Links a vertex and a fragment shader. Never throws; a program that failed to link has
  // ok() false and says why in info_log().
  static std::shared_ptr<Program> link(const Shader& vertex, const Shader& fragment,
                                       const LinkOptions& options = {});
  // Links any number of shader objects (glAttachShader): one or more of each stage, which
  // GL links as one stage's compilation units (exactly one of them defines main()). A vertex
  // and a fragment stage are needed; a geometry stage runs between them when there is one.
  static std::shared_ptr<Program> link(std::span<const Shader* const> shaders,
                                       const LinkOptions& options = {});
  ~Program();

  bool ok() const;
  const std::string& info_log() const;
  // Whether the program runs as native code (LLVM) now, and whether that code came from the
  // disk cache of compiled programs instead of being compiled (jit.hpp says where the cache
  // is). Draws made before the native code is there run on the interpreter, and a draw
  // running when it arrives goes on in native code (the results are the same).
  bool native() const;
  bool from_cache() const;
  // Waits until the native code's compile has finished (at once when it has, or when there is
  // none to wait for) and returns native().
  bool wait_native() const;

  // The geometry stage's layout, when the program has one.
  const GeometryInfo* geometry() const;
  // Transform feedback, as LinkOptions asked for it: the captured outputs, whether each has
  // a buffer of its own, and the words each buffer takes of a vertex (gpu::CaptureBuffer::
  // words: one list, or one per output when separate).
  const std::vector<FeedbackVarying>& feedback_varyings() const;
  bool feedback_separate() const;
  const std::vector<std::vector<int>>& feedback_words() const;

  const std::vector<Variable>& attributes() const;      // active, user-declared
  const std::vector<Variable>& uniforms() const;        // active, user-declared (gl_ state excluded)
  const std::vector<Variable>& outputs() const;         // fragment outputs
  int attribute_location(std::string_view name) const;  // -1 when not an active attribute
  // The location of a uniform, array element or struct member ("m", "k[2]", "l[1].pos"),
  // or -1. Compatibility state has locations too ("gl_ModelViewMatrix").
  int uniform_location(std::string_view name) const;
  int frag_data_location(std::string_view name) const;
  // glGetFragDataIndex: 0 or 1 for an active output, -1 otherwise.
  int frag_data_index(std::string_view name) const;
  // Whether an output of index 1 gives dual-source blending its second colour (it arrives
  // as fragment colour 1, and only draw buffer 0 is written: GL 3.3 §4.1.8).
  bool dual_source() const;

  // Sets count elements from `location` (GL's glUniform*v): `data` holds the components of
  // each element (matrices column by column). The base type must match the uniform's (float,
  // int, uint; bools take any and store "not zero"; samplers take int units). Returns false,
  // changing nothing, where GL would give GL_INVALID_OPERATION (no such location, a type or
  // size mismatch); location -1 is ignored and gives true, as in GL.
  bool set_uniform(int location, const float* data, int components, int count = 1);
  bool set_uniform(int location, const int32_t* data, int components, int count = 1);
  bool set_uniform(int location, const uint32_t* data, int components, int count = 1);
  // Reads one element's components (glGetUniform*), as floats or as raw 32-bit words.
  bool get_uniform(int location, float* out) const;
  bool get_uniform_words(int location, uint32_t* out) const;

  // The compatibility state the GLSL 1.10-1.50 built-in uniforms read (gl_ModelViewMatrix
  // and the rest). Linking sets them to OpenGL's initial state; the GL layer, or any
  // application, sets the matrices here: the derived ones (the products, inverses,
  // transposes and gl_NormalMatrix) follow. Other state (gl_LightSource[i].diffuse, ...)
  // is set with uniform_location/set_uniform under its GLSL name.
  void set_compat_matrices(const glm::mat4& modelview, const glm::mat4& projection);

  const std::vector<UniformBlock>& uniform_blocks() const;
  int uniform_block_index(std::string_view name) const;  // -1 when not an active block
  // glUniformBlockBinding: false for a bad index or a binding outside [0, 36).
  bool set_uniform_block_binding(int index, int binding);

  // The pipeline's view of this program with its current uniforms, the given texture units
  // and the uniform buffer bindings (indexed by binding point; each block's data is copied
  // from its range, and what the range lacks reads as zero): what gpu::Context::draw takes.
  // Valid after the program changes or goes.
  std::shared_ptr<const gpu::RuntimeShader> bind(std::span<const TextureBinding> units = {},
                                                 std::span<const BufferBinding> uniform_buffers = {}) const;
  // Queues a draw (bind() and gpu::Context::draw). Throws gpu::Error as draw does, and for a
  // program that did not link.
  void draw(gpu::Context& ctx, const gpu::VertexLayout& layout, const gpu::RenderState& state,
            const gpu::DrawCall& call, std::span<const TextureBinding> units = {},
            std::span<const BufferBinding> uniform_buffers = {}) const;

  struct Impl;

 private:
  Program();
  void set_compat_defaults();
  std::unique_ptr<Impl> impl_;
};

}  // namespace tessel::glsl
