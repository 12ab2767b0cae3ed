// The GL 1.x context: every piece of state the specification keeps, grouped as glPushAttrib
// groups them, and the machinery that turns immediate-mode vertices, vertex arrays and
// display lists into draws of the gpu layer.
//
// Entry points (api_*.cpp) validate their arguments and record errors as glGetError
// reports them (GL 2.1 §2.5: a command that generates an error has no other effect), then
// change state here. Drawing goes through `emit()`: vertices in the interleaved FFVertex
// layout plus indices of independent points, lines or triangles. Consecutive emissions
// under unchanged state are merged into one gpu draw (every state change first calls
// `touch()`, which sends what is pending).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <new>
#include <span>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include <GL/gl.h>

#include "ff_shader.hpp"
#include "framebuffer_object.hpp"
#include "objects.hpp"
#include "tessel/gpu/clip_space.hpp"
#include "tessel/gpu/context.hpp"
#include "tessel/gpu/framebuffer.hpp"
#include "tessel/gpu/texture.hpp"
#include "texture_object.hpp"

namespace tessel::gl {

inline constexpr int kMaxLights = 8;
// GL_MAX_CLIP_PLANES == GL_MAX_CLIP_DISTANCES: at least 8 in GL 3.x, as Mesa gives.
inline constexpr int kMaxClipPlanes = gpu::kMaxClipPlanes;
inline constexpr int kModelviewDepth = 32, kProjectionDepth = 32, kTextureDepth = 10;
inline constexpr int kAttribDepth = 16, kClientAttribDepth = 16;
inline constexpr int kMaxListNesting = 64;
// GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS (GL 3.3's minimum, Table 6.37); each stage may use 16.
inline constexpr int kMaxTextureUnits = glsl::kMaxCombinedTextureUnits;
inline constexpr int kMaxStageTextureUnits = glsl::kMaxStageTextureUnits;

// GL_CURRENT_BIT and what glBegin/glEnd reads.
// The texture coordinates of every set, (0, 0, 0, 1) each.
inline std::array<glm::vec4, kMaxTexCoords> initial_tex_coords() {
  std::array<glm::vec4, kMaxTexCoords> t;
  t.fill(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  return t;
}

struct CurrentState {
  glm::vec4 color{1.0f};
  std::array<glm::vec4, kMaxTexCoords> tex = initial_tex_coords();  // glMultiTexCoord, per set
  glm::vec4 secondary{0.0f, 0.0f, 0.0f, 1.0f};                      // glSecondaryColor (GL 1.4)
  float fog_coord = 0.0f;                                           // glFogCoord (GL 1.4)
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  bool edge = true;
  glm::vec4 raster_pos{0.0f, 0.0f, 0.0f, 1.0f};  // window coordinates
  glm::vec4 raster_color{1.0f};
  std::array<glm::vec4, kMaxTexCoords> raster_tex = initial_tex_coords();
  float raster_distance = 0.0f;
  bool raster_valid = true;
};

struct LightState {
  std::array<bool, kMaxLights> enabled{};
  std::array<FFLight, kMaxLights> light{};
  std::array<float, kMaxLights> spot_cutoff{};  // degrees, as set (180 = off)
  std::array<FFMaterial, 2> material{};
  glm::vec4 model_ambient{0.2f, 0.2f, 0.2f, 1.0f};
  bool local_viewer = false, two_side = false;
  bool separate_specular = false;  // GL_LIGHT_MODEL_COLOR_CONTROL (GL 1.2 §2.13.1)
  bool lighting = false;
  bool color_material = false;
  GLenum color_material_face = GL_FRONT_AND_BACK, color_material_mode = GL_AMBIENT_AND_DIFFUSE;
  GLenum shade_model = GL_SMOOTH;
  // glProvokingVertex (GL 3.2 compatibility Table 6.11 keeps it with the lighting state).
  GLenum provoking_vertex = GL_LAST_VERTEX_CONVENTION;
  bool operator==(const LightState&) const = default;
};

struct FogState {
  bool enabled = false;
  GLenum mode = GL_EXP;
  float density = 1.0f, start = 0.0f, end = 1.0f;
  glm::vec4 color{0.0f};
  GLenum coord_src = GL_FRAGMENT_DEPTH;  // GL_FOG_COORD_SRC (GL 1.4 §3.10)
  bool color_sum = false;                // GL_COLOR_SUM (GL 1.4 §3.9)
};

struct ColorBufferState {
  bool alpha_test = false;
  GLenum alpha_func = GL_ALWAYS;
  float alpha_ref = 0.0f;
  // GL_BLEND and the colour write mask per draw buffer (glEnablei, glColorMaski); glEnable
  // and glColorMask set them all, glIsEnabled and glGet read draw buffer 0's.
  std::array<bool, kMaxDrawBuffers> blend{};
  GLenum blend_src = GL_ONE, blend_dst = GL_ZERO;  // the RGB factors
  GLenum blend_src_alpha = GL_ONE, blend_dst_alpha = GL_ZERO;
  GLenum blend_eq = GL_FUNC_ADD, blend_eq_alpha = GL_FUNC_ADD;
  glm::vec4 blend_color{0.0f};
  bool dither = true, logic_op = false;
  GLenum logic_op_mode = GL_COPY;
  // glSampleCoverage (GL 3.3 §4.1.3): kept and queried; it acts on multisample buffers only,
  // which Tessel's framebuffers do not have (they render one sample).
  float coverage_value = 1.0f;
  bool coverage_invert = false;
  glm::vec4 clear_color{0.0f};
  std::array<std::array<bool, 4>, kMaxDrawBuffers> color_mask = [] {
    std::array<std::array<bool, 4>, kMaxDrawBuffers> m;
    for (auto& b : m) b = {true, true, true, true};
    return m;
  }();
  GLenum draw_buffer = GL_BACK;
};

struct DepthState {
  bool test = false;
  GLenum func = GL_LESS;
  double clear = 1.0;
  bool mask = true;
};

struct StencilState {
  bool test = false;
  GLenum func = GL_ALWAYS;
  GLint ref = 0;
  GLuint value_mask = 0xFFFFFFFFu, write_mask = 0xFFFFFFFFu;
  GLenum fail = GL_KEEP, zfail = GL_KEEP, zpass = GL_KEEP;
  GLint clear = 0;
  // Back-facing primitives' state (glStencil*Separate, GL 2.0 §4.1.5); the calls without
  // a face set both.
  GLenum back_func = GL_ALWAYS;
  GLint back_ref = 0;
  GLuint back_value_mask = 0xFFFFFFFFu, back_write_mask = 0xFFFFFFFFu;
  GLenum back_fail = GL_KEEP, back_zfail = GL_KEEP, back_zpass = GL_KEEP;
};

struct PolygonState {
  bool cull = false;
  GLenum cull_face = GL_BACK, front_face = GL_CCW;
  GLenum mode_front = GL_FILL, mode_back = GL_FILL;
  float offset_factor = 0.0f, offset_units = 0.0f;
  bool offset_fill = false, offset_line = false, offset_point = false;
  bool smooth = false, stipple = false;
};

struct LineState {
  float width = 1.0f;
  bool smooth = false, stipple = false;
  GLint stipple_factor = 1;
  GLushort stipple_pattern = 0xFFFF;
};

struct PointState {
  float size = 1.0f;
  bool smooth = false;
  // glPointParameter (GL 2.1 §3.4): the derived-size limits, fade threshold and distance
  // attenuation are kept and queried (Tessel's fixed-function points keep glPointSize's size);
  // the sprite origin places gl_PointCoord.
  float size_min = 0.0f, size_max = 255.0f, fade_threshold = 1.0f;
  float attenuation[3] = {1.0f, 0.0f, 0.0f};
  bool sprite_lower_left = false;
  bool sprite = false;  // GL_POINT_SPRITE (compatibility): units with GL_COORD_REPLACE use gl_PointCoord
};

struct ScissorState {
  bool test = false;
  GLint x = 0, y = 0;
  GLsizei width = 0, height = 0;
};

struct ViewportState {
  GLint x = 0, y = 0;
  GLsizei width = 0, height = 0;
  double near_ = 0.0, far_ = 1.0;
};

struct TransformState {
  GLenum matrix_mode = GL_MODELVIEW;
  bool normalize = false, rescale_normal = false;
  std::array<bool, kMaxClipPlanes> clip_enabled{};
  std::array<glm::dvec4, kMaxClipPlanes> clip_plane{};  // eye space
};

struct TextureUnitState {
  // glEnable(GL_TEXTURE_1D/2D/3D/CUBE_MAP): the fixed-function target of the unit is the
  // highest of those enabled, cube map first (GL 2.1 §3.8.16).
  bool enabled_1d = false, enabled_2d = false, enabled_3d = false, enabled_cube = false;
  // The texture bound to each target (null: the target's default texture, name 0), and the
  // sampler object bound to the unit (null: none, the texture's own parameters).
  std::array<TextureRef, kTexTargetCount> bound{};
  SamplerRef sampler;
  GLenum env_mode = GL_MODULATE;
  glm::vec4 env_color{0.0f};
  std::array<bool, 4> gen_enabled{};  // S, T, R, Q
  std::array<GLenum, 4> gen_mode{GL_EYE_LINEAR, GL_EYE_LINEAR, GL_EYE_LINEAR, GL_EYE_LINEAR};
  std::array<glm::vec4, 4> object_plane{glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0.0f),
                                        glm::vec4(0.0f)};
  std::array<glm::vec4, 4> eye_plane{glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0.0f),
                                     glm::vec4(0.0f)};
  // GL_COMBINE (GL 1.3 §3.8.13 Tables 3.24 and 3.25, GL 1.4's crossbar sources GL_TEXTUREi):
  // the functions, the three sources and operands of each, and the scales.
  GLenum combine_rgb = GL_MODULATE, combine_alpha = GL_MODULATE;
  std::array<GLenum, 3> src_rgb{GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  std::array<GLenum, 3> src_alpha{GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  std::array<GLenum, 3> op_rgb{GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
  std::array<GLenum, 3> op_alpha{GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA};
  float rgb_scale = 1.0f, alpha_scale = 1.0f;
  float lod_bias = 0.0f;       // GL_TEXTURE_FILTER_CONTROL's GL_TEXTURE_LOD_BIAS (GL 1.4 §3.8.8)
  bool coord_replace = false;  // GL_POINT_SPRITE's GL_COORD_REPLACE (GL 2.0 §3.3.1)
};

struct HintState {
  GLenum perspective = GL_DONT_CARE, point = GL_DONT_CARE, line = GL_DONT_CARE, polygon = GL_DONT_CARE,
         fog = GL_DONT_CARE;
};

struct PixelModeState {
  GLenum read_buffer = GL_BACK;
  // glClampColor (GL 3.0 §4.3.2, compatibility §2.19.6 and §3.9): GL_CLAMP_READ_COLOR clamps
  // what glReadPixels returns (GL_FIXED_ONLY: from fixed-point buffers, whose values are in
  // [0, 1] already); the vertex and fragment clamps are kept and queried (Tessel clamps
  // fixed-function colours and fixed-point targets always, float targets never).
  GLenum clamp_read = GL_FIXED_ONLY, clamp_vertex = GL_TRUE, clamp_fragment = GL_FIXED_ONLY;
  float zoom_x = 1.0f, zoom_y = 1.0f;
  bool map_color = false, map_stencil = false;
  GLint index_shift = 0, index_offset = 0;
  float red_scale = 1, red_bias = 0, green_scale = 1, green_bias = 0, blue_scale = 1, blue_bias = 0;
  float alpha_scale = 1, alpha_bias = 0, depth_scale = 1, depth_bias = 0;
};

struct EvalGrid {
  int n = 1;
  double u1 = 0.0, u2 = 1.0;
};

// GL_EVAL_BIT: which maps are on, GL_AUTO_NORMAL, the grids (the maps themselves: eval.cpp).
struct EvalState {
  std::array<bool, 9> map1_enabled{}, map2_enabled{};  // in the order of the GL_MAP1_* enums
  bool auto_normal = false;
  EvalGrid grid1, grid2u, grid2v;
};

// The fixed-function state a GLSL 1.10-1.50 program reads through its gl_ uniforms, as last
// written to a program (draw_glsl.cpp): written again only when it changed.
struct CompatSnapshot {
  glm::mat4 modelview{1.0f}, projection{1.0f};
  std::array<glm::mat4, kMaxTexCoords> texture{};
  std::array<glm::vec4, kMaxTexCoords> env_color{};
  std::array<std::array<glm::vec4, 4>, kMaxTexCoords> eye_plane{}, object_plane{};  // S, T, R, Q
  LightState light;
  glm::vec4 fog_color{0.0f};
  std::array<float, 3> fog{};  // density, start, end
  float point_size = 1.0f;
  std::array<float, 6> point{};  // size min, max, fade threshold, the three attenuations
  std::array<float, 2> depth_range{};
  std::array<glm::vec4, kMaxClipPlanes> clip_planes{};
  bool operator==(const CompatSnapshot&) const = default;
};

// A draw with the generic attribute arrays (glDrawArrays ... glDrawElementsInstancedBaseVertex).
struct GenericDraw {
  GLenum mode = GL_TRIANGLES;
  gpu::Topology topology = gpu::Topology::Triangles;
  bool decompose = false;  // GL_QUADS, GL_QUAD_STRIP, GL_POLYGON: triangulated first
  GLint first = 0;
  GLsizei count = 0, instances = 1;
  bool indexed = false;
  gpu::IndexType index_type = gpu::IndexType::U32;
  const void* indices = nullptr;  // an offset into the element array buffer when one is bound
  GLint base_vertex = 0;
};

// A query object (GL 3.3 §2.14): its target, and the counters when it began.
struct QueryObject {
  GLenum target = 0;
  uint64_t start_samples = 0, start_primitives = 0, start_written = 0, start_ns = 0;
  uint64_t result = 0;
};

// The server state (what glPushAttrib saves), group by group.
struct ServerState {
  CurrentState current;
  LightState light;
  FogState fog;
  ColorBufferState color;
  DepthState depth;
  StencilState stencil;
  PolygonState polygon;
  std::array<uint32_t, 32> polygon_stipple;  // rows of the 32x32 pattern, bit x = column x
  LineState line;
  PointState point;
  ScissorState scissor;
  ViewportState viewport;
  TransformState transform;
  // The texture image units (glActiveTexture): fixed-function texturing reads unit 0, GLSL
  // samplers any of them.
  std::array<TextureUnitState, kMaxTextureUnits> units;
  GLuint active_unit = 0;
  TextureUnitState& unit() { return units[active_unit]; }
  const TextureUnitState& unit() const { return units[active_unit]; }
  HintState hint;
  PixelModeState pixel;
  // The pixel maps (GL 2.1 §3.6.3), in the order of GL_PIXEL_MAP_I_TO_I .. GL_PIXEL_MAP_A_TO_A:
  // one entry of 0 each at first. No attribute group holds them (as in Mesa).
  std::array<std::vector<float>, 10> pixel_maps{std::vector<float>(1, 0.0f), std::vector<float>(1, 0.0f),
                                                std::vector<float>(1, 0.0f), std::vector<float>(1, 0.0f),
                                                std::vector<float>(1, 0.0f), std::vector<float>(1, 0.0f),
                                                std::vector<float>(1, 0.0f), std::vector<float>(1, 0.0f),
                                                std::vector<float>(1, 0.0f), std::vector<float>(1, 0.0f)};
  EvalState eval;
  GLuint list_base = 0;
  glm::vec4 accum_clear{0.0f};
  ServerState() { polygon_stipple.fill(0xFFFFFFFFu); }
};

struct PixelStore {
  bool swap_bytes = false, lsb_first = false;
  GLint row_length = 0, skip_rows = 0, skip_pixels = 0, alignment = 4;
  GLint image_height = 0, skip_images = 0;  // 3D images (GL 1.2 §3.8.1)
};

struct ArrayPointer {
  bool enabled = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  GLsizei stride = 0;
  const void* pointer = nullptr;  // an offset into `buffer` when one was bound (GL 1.5)
  BufferRef buffer;               // GL_ARRAY_BUFFER when the pointer was given
  size_t limit = SIZE_MAX;        // bytes readable from `pointer` (set while a draw reads a buffer)
};

inline ArrayPointer sized_array(GLint size) {
  ArrayPointer a;
  a.size = size;
  return a;
}

struct ClientState {
  PixelStore pack, unpack;
  ArrayPointer vertex, normal, color, edge, index;
  std::array<ArrayPointer, kMaxTexCoords> tex;  // one texture coordinate array per set
  ArrayPointer secondary = sized_array(3), fog = sized_array(1);
  GLuint client_active_unit = 0;  // glClientActiveTexture: the set glTexCoordPointer names
  ArrayPointer& active_tex() { return tex[client_active_unit]; }
  const ArrayPointer& active_tex() const { return tex[client_active_unit]; }
};

// Vertex records as the fixed-function paths build them: FFVertex each and, once any vertex
// has attributes beyond FFVertex's (a texture coordinate set other than 0, a secondary colour
// or a fog coordinate), the FFExtra of each in a parallel array; `x` is empty until then.
struct FFVertices {
  std::vector<FFVertex> v;
  std::vector<FFExtra> x;
  size_t size() const { return v.size(); }
  bool empty() const { return v.empty(); }
  bool wide() const { return !x.empty(); }
  void clear() {
    v.clear();
    x.clear();
  }
  void reserve(size_t n) { v.reserve(n); }
  FFVertex& operator[](size_t i) { return v[i]; }
  const FFVertex& operator[](size_t i) const { return v[i]; }
  // The extra attributes of vertex i (the defaults when the records carry none).
  FFExtra extra(size_t i) const { return wide() ? x[i] : FFExtra::defaults(); }
  void widen() {
    if (!wide() && !v.empty()) x.assign(v.size(), FFExtra::defaults());
  }
  void push(const FFVertex& a) {
    v.push_back(a);
    if (wide()) x.push_back(FFExtra::defaults());
  }
  void push(const FFVertex& a, const FFExtra& e) {
    if (!wide()) {
      x.assign(v.size(), FFExtra::defaults());
      x.reserve(v.capacity());
    }
    v.push_back(a);
    x.push_back(e);
  }
  // Appends vertex i of `from` with the record `a` (vertex i's own, or an edited copy).
  void push_from(const FFVertices& from, size_t i, const FFVertex& a) {
    if (from.wide())
      push(a, from.x[i]);
    else
      push(a);
  }
  void append(const FFVertices& o) {
    if (o.wide() || wide()) {
      widen();
      if (v.empty()) x.clear();
      const size_t n = v.size();
      v.insert(v.end(), o.v.begin(), o.v.end());
      if (o.wide())
        x.insert(x.end(), o.x.begin(), o.x.end());
      else
        x.resize(n + o.v.size(), FFExtra::defaults());
      return;
    }
    v.insert(v.end(), o.v.begin(), o.v.end());
  }
};

// The fixed-function state that decides the code of a generated fixed-function program
// (ff_program.cpp); its bytes are the program's key (no padding: every byte is a field).
struct FFProgramKey {
  struct Unit {
    uint8_t target = 0;  // 0: the unit does not texture; 1D, 2D, 3D, cube map
    uint8_t shadow = 0;  // a depth texture compared (GL_TEXTURE_COMPARE_MODE)
    uint8_t base = 0;    // BaseFormat
    uint8_t unused = 0;
    uint16_t env = 0;               // GL_TEXTURE_ENV_MODE
    std::array<uint16_t, 4> gen{};  // GL_TEXTURE_GEN_MODE of S, T, R, Q when enabled, else 0
    // GL_COMBINE's functions, sources and operands (zero unless env is GL_COMBINE).
    uint16_t combine_rgb = 0, combine_alpha = 0;
    std::array<uint16_t, 3> src_rgb{}, src_alpha{}, op_rgb{}, op_alpha{};
    uint8_t rgb_scale = 0, alpha_scale = 0;
    uint8_t bias = 0;           // a texture LOD bias is given (the uniform ff_biasN)
    uint8_t coord_replace = 0;  // points take gl_PointCoord as (s, t)
  };
  std::array<Unit, kMaxTexCoords> units{};
  uint16_t fog_mode = 0, alpha_func = 0;  // alpha_func 0: no alpha test
  uint8_t lighting = 0, two_side = 0, local_viewer = 0, separate_specular = 0, lights = 0;
  uint8_t normalize = 0, rescale = 0, flat = 0, fog = 0, fog_coord = 0, color_sum = 0, stipple = 0;
  std::array<uint8_t, 2> track{};  // kTrack* bits of the front and back materials
  std::string bytes() const;
};
static_assert(std::has_unique_object_representations_v<FFProgramKey>);
BaseFormat ff_base_format(const TextureObject& t);
// The kTrack* bits of the front and back materials (glColorMaterial; none when it is off).
std::array<uint8_t, 2> color_material_track(const LightState& L);
// GL_RESCALE_NORMAL's factor for a model-view matrix (GL 2.1 §2.11.3).
float rescale_factor(const glm::mat4& modelview);
std::string ff_vertex_source(const FFProgramKey& k);
std::string ff_fragment_source(const FFProgramKey& k);
std::string ff_fragment_source_after_vertex_shader(const FFProgramKey& k);

// The current values of the attributes an FFExtra holds.
void current_extra(const CurrentState& cur, FFExtra& e);

struct PushedAttrib {
  GLbitfield mask;
  ServerState state;
};

struct PushedClient {
  GLbitfield mask;
  ClientState state;
};

using ListCommand = std::function<void()>;

// Independent primitives of one emission: 1, 2 or 3 indices each.
enum class PrimClass : uint8_t { Points, Lines, Triangles };

// Triangles (index triples) that list their provoking vertex last, rotated to list it first:
// (a, b, c) becomes (c, a, b), the winding kept.
void rotate_provoking_first(std::vector<uint32_t>& triangles);

class Context {
 public:
  // `alpha`: whether the window's colour buffers have alpha (GLUT_ALPHA, GLFW_ALPHA_BITS); without
  // it they read alpha 1, as an X visual without alpha bits does (GL 2.1 §4.1.8: the
  // destination alpha of a buffer without alpha is 1), and GL_ALPHA_BITS is 0.
  Context(int width, int height, bool double_buffer, bool depth, bool stencil, bool alpha = true);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // --- errors (GL 2.1 §2.5): the first error is kept until glGetError reads it.
  void error(GLenum e) {
    if (error_ == GL_NO_ERROR) error_ = e;
  }
  GLenum take_error() {
    const GLenum e = error_;
    error_ = GL_NO_ERROR;
    return e;
  }

  // --- the window's buffers
  void resize(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }
  bool double_buffered() const { return double_buffer_; }
  void swap_buffers();
  // The image a viewer sees (the front buffer), RGBA8 rows bottom-up; runs queued work first.
  const gpu::Texture2D& front() {
    finish();
    return *color_[0];
  }
  void finish();
  gpu::Texture2D* color_buffer(GLenum which);  // GL_FRONT / GL_BACK (nullptr if none)
  gpu::Texture2D* depth_buffer() { return depth_.get(); }
  bool has_depth() const { return has_depth_; }
  bool has_alpha() const { return has_alpha_; }
  bool has_stencil() const { return has_stencil_; }

  // --- state
  ServerState s;
  ClientState c;
  std::vector<PushedAttrib> attrib_stack;
  std::vector<PushedClient> client_stack;
  // The matrix stacks: modelview, projection, then the texture matrix of each coordinate set;
  // back() is current.
  std::array<std::vector<glm::mat4>, 2 + kMaxTexCoords> matrices;
  // The stack glMatrixMode selects: the texture stack of the active unit (of the last unit
  // below GL_MAX_TEXTURE_COORDS that was active, as in Mesa, when the active unit has none).
  int matrix_index() const {
    return s.transform.matrix_mode == GL_MODELVIEW    ? 0
           : s.transform.matrix_mode == GL_PROJECTION ? 1
                                                      : 2 + tex_set();
  }
  int texture_stack = 0;  // the last active unit below GL_MAX_TEXTURE_COORDS
  // The coordinate set of the active unit (GL_CURRENT_TEXTURE_COORDS, the texture matrix).
  int tex_set() const { return s.active_unit < GLuint(kMaxTexCoords) ? int(s.active_unit) : texture_stack; }
  const glm::mat4& texture_matrix(int set) const { return matrices[size_t(2 + set)].back(); }
  glm::mat4& top() { return matrices[size_t(matrix_index())].back(); }
  const glm::mat4& modelview() const { return matrices[0].back(); }
  const glm::mat4& projection() const { return matrices[1].back(); }

  // Texture names: null until the name is first bound (glGenTextures reserves it).
  std::unordered_map<GLuint, TextureRef> textures;
  std::array<TextureRef, kTexTargetCount> default_textures;  // name 0 of each target
  GLuint next_texture_name = 1;
  // The texture bound to a target of a unit (the default texture when none is).
  TextureObject& bound_texture(TexTarget t, int unit) {
    const TextureRef& r = s.units[size_t(unit)].bound[size_t(t)];
    return r ? *r : *default_textures[size_t(t)];
  }
  TextureObject& bound_texture(TexTarget t = TexTarget::T2D) { return bound_texture(t, int(s.active_unit)); }
  std::array<TextureRef, kTexTargetCount> proxy_textures;  // GL_PROXY_TEXTURE_*: sizes only
  std::unordered_map<GLuint, SamplerRef> samplers;
  // A texture's name is deleted: every binding of it in the units goes back to 0.
  void texture_deleted(const TextureObject& t);

  // Queries, conditional rendering and sync objects (api_query.cpp). Query names map to null
  // until glBeginQuery makes the object; one active query per target (samples passed, any
  // samples passed, primitives generated, transform feedback primitives, time elapsed).
  std::unordered_map<GLuint, std::shared_ptr<QueryObject>> queries;
  GLuint next_query_name = 1;
  std::array<QueryObject*, 5> active_queries{};
  std::shared_ptr<QueryObject> conditional_query;  // between glBegin/EndConditionalRender
  std::unordered_map<GLsync, std::shared_ptr<void>> syncs;
  // Whether conditional rendering skips draws and clears now (its query counted nothing).
  bool conditional_render_skips();
  // Whether a draw of `draw_mode` gives the primitives the active transform feedback writes
  // (GL 3.3 §2.15.2), after the current program's geometry stage.
  bool feedback_takes(GLenum draw_mode) const;

  // Framebuffer and renderbuffer objects (api_framebuffer.cpp). Names map to null until
  // first bound; draw_fbo/read_fbo null is the default (window) framebuffer.
  std::unordered_map<GLuint, FramebufferRef> framebuffers;
  std::unordered_map<GLuint, RenderbufferRef> renderbuffers;
  GLuint next_framebuffer_name = 1, next_renderbuffer_name = 1;
  FramebufferRef draw_fbo, read_fbo;
  RenderbufferRef bound_renderbuffer;
  // glCheckFramebufferStatus of a framebuffer object: §4.4.4's rules, then what the gpu layer
  // cannot render to (GL_FRAMEBUFFER_UNSUPPORTED: a level outside the texture's level chain,
  // separate depth and stencil images).
  GLenum framebuffer_status(FramebufferObject& f);
  bool draw_framebuffer_complete() {
    return draw_fbo ? framebuffer_status(*draw_fbo) == GL_FRAMEBUFFER_COMPLETE : has_default_framebuffer;
  }
  bool read_framebuffer_complete() {
    return read_fbo ? framebuffer_status(*read_fbo) == GL_FRAMEBUFFER_COMPLETE : has_default_framebuffer;
  }
  // The gpu image of an attachment (texture level, a layer of one, or renderbuffer); false
  // when there is none. A layered attachment (glFramebufferTexture of a cube map, 3D or array
  // texture) gives its layer `layer` (a cube's face).
  bool gpu_image(const Attachment& a, gpu::Attachment& out, int layer = 0);
  // The layers of the draw framebuffer when it is layered (GL 3.3 §4.4.7: the fewest of any
  // attachment), else 0.
  int draw_layers();
  // What pixel reads (glReadPixels, glCopyTex*, glBlitFramebuffer) read: the read
  // framebuffer's read buffer and its depth (or depth-stencil) image.
  gpu::Attachment read_color();
  // The integer range of the read buffer's format (not integer for the default framebuffer).
  gpu::IntegerRange read_color_integer() const;
  gpu::Attachment read_depth();
  bool read_has_stencil();
  // What draws write: whether the draw framebuffer has depth and stencil, the channels each
  // draw buffer's format stores (0 where there is no image), and which are integer formats.
  struct TargetInfo {
    bool depth = false, stencil = false;
    std::array<uint8_t, kMaxDrawBuffers> channels{};
    std::array<gpu::IntegerRange, kMaxDrawBuffers> integer{};
  };
  TargetInfo target_info() const;
  // An object's name is deleted: detached from the bound framebuffers, unbound (§4.4.2.3).
  void renderbuffer_deleted(const RenderbufferObject& r);
  GLuint next_sampler_name = 1;

  // Display lists.
  std::unordered_map<GLuint, std::vector<ListCommand>> lists;
  GLuint compiling_list = 0;  // nonzero inside glNewList
  GLenum compile_mode = GL_COMPILE;
  std::vector<ListCommand> compiling;
  int list_depth = 0;
  // When compiling, stores `cmd` in the list and returns whether it must also run now.
  bool record(ListCommand cmd) {
    if (compiling_list == 0) return true;
    compiling.push_back(std::move(cmd));
    return compile_mode == GL_COMPILE_AND_EXECUTE;
  }
  bool compiling_only() const { return compiling_list != 0 && compile_mode == GL_COMPILE; }

  // Immediate mode.
  bool in_begin = false;
  GLenum begin_mode = GL_POINTS;
  FFVertices prim;  // vertices since glBegin
  // Whether vertices may need FFExtra records: set by every call that gives a texture
  // coordinate set other than 0, a secondary colour or a fog coordinate, or enables their
  // arrays; reset at glBegin when all those are back to their defaults.
  bool extras_touched = false;
  bool extras_live() const;
  void vertex(float x, float y, float z, float w);
  void end();

  // Sends pending vertices under the state they were given with; call before any state change.
  void touch() {
    close_quad_run();
    if (!batch_.indices.empty()) send_batch();
  }
  // Draws vertices as independent primitives of one class (indices into `verts`).
  void emit(PrimClass cls, FFVertices&& verts, std::vector<uint32_t>&& indices);
  // Independent triangles whose vertices are already a gpu buffer of FFVertex records (vertex
  // arrays converted once and reused, api_arrays.cpp). Only for GL_RENDER; not merged.
  void emit_shared(std::shared_ptr<const gpu::Buffer> vertices, std::vector<uint32_t>&& indices);
  // Converts vertices given in glBegin order for `mode` into independent primitives.
  void emit_mode(GLenum mode, FFVertices&& verts);
  // With the first-vertex convention, rotates triangles that list their provoking vertex
  // last so that they list it first (quads and polygons keep theirs in both conventions;
  // rotate_provoking_first).
  void provoking_vertex_first(std::vector<uint32_t>& idx) const;

  // Clears the draw buffer(s) as glClear with the current masks, scissor and values.
  void clear(GLbitfield mask);
  // The value draw buffer i of `target` is cleared to, for a clear colour given as floats or
  // (glClearBuffer{i,ui}v) as integer bits.
  glm::vec4 clear_color_for(const TargetInfo& target, int i, glm::vec4 color) const;

  // Raster-position/pixel rectangles (glBitmap, glDrawPixels): RGBA8 pixels (rows bottom-up)
  // drawn as fragments at window position (x, y), colour replaced by `color` when
  // `use_color` (bitmaps), with `mask` alpha-like coverage (0 = no fragment).
  void draw_pixels_rgba(float x, float y, int w, int h, const std::vector<uint8_t>& rgba, float zoom_x,
                        float zoom_y, const glm::vec4* color);

  // The texture a draw reads, or nullptr when texturing is off or the texture is incomplete.
  TextureObject* texture_for_draw();
  // The sampling parameters of a unit's texture: the unit's sampler object's, else its own.
  const SamplerParams& sampler_params(int unit, const TextureObject& t) const;

  // Selection mode (select.cpp).
  GLenum render_mode() const { return render_mode_; }
  GLint set_render_mode(GLenum mode);  // returns the hit count of the mode being left
  void set_select_buffer(GLuint* buffer, GLsizei size) {
    sel_buffer_ = buffer;
    sel_size_ = size;
  }
  std::vector<GLuint>& name_stack() { return sel_names_; }
  void write_hit_record();
  void select_hit(float window_z);
  // For primitives processed on the CPU (selection, feedback, stippled lines, raster
  // positions), with gpu/clip_space.hpp's rules: the view volume (near and far unless depth
  // clamping) and the enabled user planes in clip space, as the gpu layer tests them; the
  // viewport and depth-range transform; whether culling removes a triangle (clip positions).
  gpu::ClipPlanes cpu_clip_planes() const;
  gpu::ViewportTransform viewport_transform() const;
  bool culled(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) const;
  // glCullFace / glFrontFace as the gpu layer names them (CullMode::None when culling is off).
  gpu::CullMode cull_mode() const;
  gpu::FrontFace front_face() const;
  // User clip plane i (enabled or not) in clip space: p_eye * P^-1, as a row vector.
  glm::vec4 clip_space_plane(int i) const;
  // Feedback mode (feedback.cpp).
  void set_feedback_buffer(GLfloat* buffer, GLsizei size, GLenum type) {
    fb_buffer_ = buffer;
    fb_size_ = size;
    fb_type_ = type;
  }
  void pass_through(float token);

  // --- the version and profile (glutInitContextVersion/Profile, EGL and GLFW attributes)
  int major_version = 2, minor_version = 1;
  // False while the context is current without a surface (EGL_KHR_surfaceless_context):
  // framebuffer 0 is then GL_FRAMEBUFFER_UNDEFINED (GL 3.3 §4.4.4.2) and drawing to it, or
  // reading from it, is GL_INVALID_FRAMEBUFFER_OPERATION.
  bool has_default_framebuffer = true;
  bool core_profile = false;  // GL 3.2+ core: the removed calls are GL_INVALID_OPERATION
  void set_version(int major, int minor, bool core);
  const std::string& version_string() const { return version_string_; }
  const std::string& glsl_version_string() const { return glsl_version_string_; }
  const std::string& extension_string() const { return extension_string_; }

  // --- GL 1.5-3.3 objects (objects.hpp)
  std::unordered_map<GLuint, BufferRef> buffers;  // generated names map to null until bound
  GLuint next_buffer_name = 1;
  BufferRef array_buffer, copy_read_buffer, copy_write_buffer, pixel_pack_buffer, pixel_unpack_buffer,
      uniform_buffer, texture_buffer;
  struct IndexedBuffer {
    BufferRef buffer;
    GLintptr offset = 0;
    GLsizeiptr size = 0;  // 0 with glBindBufferBase: the whole buffer
  };
  std::array<IndexedBuffer, kMaxUniformBufferBindings> uniform_bindings{};
  // Transform feedback (GL 3.3 §2.15): the binding points, and what glBeginTransformFeedback
  // set up (the program and buffers it captures with, kept while it is active).
  BufferRef feedback_buffer;
  std::array<IndexedBuffer, glsl::kMaxFeedbackSeparateAttribs> feedback_bindings{};
  struct Feedback {
    bool active = false;
    GLenum mode = GL_POINTS;
    std::shared_ptr<glsl::Program> program;
    std::vector<BufferRef> buffers;
    gpu::Capture capture;
  } feedback;
  bool rasterizer_discard = false;  // GL_RASTERIZER_DISCARD
  // The indexed binding points of GL_UNIFORM_BUFFER or GL_TRANSFORM_FEEDBACK_BUFFER (empty
  // for any other target).
  std::span<IndexedBuffer> indexed_bindings(GLenum target) {
    if (target == GL_UNIFORM_BUFFER) return uniform_bindings;
    if (target == GL_TRANSFORM_FEEDBACK_BUFFER) return feedback_bindings;
    return {};
  }
  std::unordered_map<GLuint, std::unique_ptr<VertexArrayObject>> vertex_arrays;  // 0: the default
  GLuint next_vertex_array_name = 1;
  GLuint bound_vertex_array = 0;
  VertexArrayObject& vao() { return *vertex_arrays.at(bound_vertex_array); }
  // Current generic attribute values (glVertexAttrib*), as raw words of `generic_type`.
  std::array<std::array<uint32_t, 4>, kMaxVertexAttribs> generic_current{};
  std::array<GLenum, kMaxVertexAttribs> generic_type{};  // GL_FLOAT, GL_INT or GL_UNSIGNED_INT
  GLuint primitive_restart_index = 0;
  bool primitive_restart = false;
  bool program_point_size = false, depth_clamp = false;
  bool cube_map_seamless = false;  // GL_TEXTURE_CUBE_MAP_SEAMLESS (GL 3.3 §3.8.8)
  // glSampleMaski's word (GL 3.3 §4.1.3). Kept and queried: it acts on samples, and Tessel's
  // multisample buffers are stored with one.
  GLbitfield sample_mask = ~GLbitfield(0);
  // Shader and program objects share one name space (GL 3.3 §2.11.1).
  std::unordered_map<GLuint, ShaderObject> shaders;
  std::unordered_map<GLuint, ProgramObject> programs;
  GLuint next_shader_name = 1;
  GLuint current_program = 0;
  // What draws run: the current program's executable as of its last successful link (a
  // failed relink of the current program keeps the old one, GL 3.3 §2.11.2).
  std::shared_ptr<glsl::Program> executable;
  // Draws with the executable (draw_glsl.cpp): the immediate-mode and fixed-function array
  // batches, and the generic attribute arrays of the bound vertex array object.
  // `extra`: the FFExtra of each vertex, or empty when every vertex has the defaults.
  struct CompatCache {
    const glsl::Program* program = nullptr;
    CompatSnapshot state;
  };
  std::unordered_map<GLuint, CompatCache> compat_cache;  // by program name
  // The program a batch or draw runs: the executable, or fixed function's generated program.
  struct ProgramRun {
    glsl::Program& program;
    CompatCache& cache;
  };
  // The executable, or for a compatibility program without a fragment shader, that program
  // linked again with fixed function's fragment stage for the current state (api_program.cpp).
  ProgramRun executable_run(PrimClass cls = PrimClass::Triangles);
  struct VertexOnlyRun {
    std::shared_ptr<glsl::Program> program;
    CompatCache cache;
  };
  // By program name and fixed-function fragment key; a program's go when it is linked again.
  std::map<std::pair<GLuint, std::string>, VertexOnlyRun> vertex_only_runs;
  void draw_program_batch(ProgramRun run, const gpu::Buffer& vertices, const std::vector<FFExtra>& extra,
                          const gpu::DrawCall& call, gpu::RenderState rs);
  void draw_generic(const GenericDraw& d);
  void bind_current_values(gpu::VertexLayout& layout, std::vector<std::unique_ptr<gpu::Buffer>>& keep);
  void run_program(ProgramRun run, const gpu::VertexLayout& layout, const gpu::DrawCall& call,
                   gpu::RenderState rs);
  void run_program_layer(ProgramRun run, const gpu::VertexLayout& layout, const gpu::DrawCall& call,
                         gpu::RenderState rs, int layer);
  void feed_compat_state(ProgramRun run);
  bool texture_units_for_draw(const glsl::Program& program, std::vector<glsl::TextureBinding>& units);
  std::vector<glsl::BufferBinding> uniform_buffers_for_draw() const;
  // Keeps a buffer a queued draw reads until the work has run.
  void keep_until_finished(std::unique_ptr<gpu::Buffer> b);

  gpu::Context& gpu() { return *gpu_; }
  const gpu::Context& gpu() const { return *gpu_; }
  gpu::RenderState render_state(bool for_clear) const;
  // Binds the draw framebuffer for a draw or clear. False (nothing must be drawn) when it is
  // incomplete (GL_INVALID_FRAMEBUFFER_OPERATION is raised) or has no image to draw into.
  // Of a layered framebuffer, `layer` of every attachment is bound.
  bool bind_draw_target(int layer = 0);
  void clear_layer(GLbitfield mask, int layer);
  // Runs clear(layer) for every layer of a layered draw framebuffer (GL 3.3 §4.4.7: a clear
  // clears them all), layer 0 last so that it stays bound; for another framebuffer, once.
  template <class F>
  void for_each_clear_layer(F&& clear) {
    const int layers = draw_layers();
    for (int layer = 1; layer < layers; ++layer) clear(layer);
    clear(0);
  }
  const gpu::Framebuffer& framebuffer() const { return fb_; }

 private:
  struct Batch {
    PrimClass cls = PrimClass::Triangles;
    FFVertices verts;
    std::vector<uint32_t> indices;
    std::shared_ptr<const gpu::Buffer> shared;  // when set: the vertices, instead of `verts`
    // The gpu draw of the batch's indices, 32-bit in `indices` (its class as the topology).
    gpu::DrawCall call(const gpu::Buffer& index_buffer) const {
      gpu::DrawCall c;
      c.topology = cls == PrimClass::Points  ? gpu::Topology::Points
                   : cls == PrimClass::Lines ? gpu::Topology::Lines
                                             : gpu::Topology::Triangles;
      c.count = uint32_t(indices.size());
      c.index_buffer = &index_buffer;
      c.index_type = gpu::IndexType::U32;
      return c;
    }
  };
  void send_batch();
  void send_batch_unchecked();
  void draw_fixed_function(const Batch& b, const gpu::Buffer& vertices, const gpu::Buffer& indices);
  // Fixed function beyond the C++ shader, as a generated GLSL program (ff_program.cpp).
  TextureObject* ff_texture(int unit, TexTarget& target);
  // False when the C++ shader can draw the state; `unit0` is then unit 0's 2D texture, if any.
  bool ff_program_key(PrimClass cls, FFProgramKey& key, TextureObject*& unit0);
  // The generated program's uniforms that are not compatibility state (ff_program.cpp).
  void set_ff_uniforms(glsl::Program& p, const FFProgramKey& k) const;
  void draw_ff_program(const FFProgramKey& key, const Batch& b, const gpu::Buffer& vertices,
                       const gpu::Buffer& indices);
  struct FFProgram {
    std::shared_ptr<glsl::Program> program;
    CompatCache cache;
  };
  std::unordered_map<std::string, FFProgram> ff_programs_;
  // The gpu layer reports what it cannot do by exceptions; a GL program sees them as
  // GL_OUT_OF_MEMORY (no memory) or GL_INVALID_OPERATION (anything else), never as a crash.
  template <class Fn>
  void guarded(Fn&& fn) {
    try {
      fn();
    } catch (const std::bad_alloc&) {
      error(GL_OUT_OF_MEMORY);
    } catch (const std::exception&) {
      error(GL_INVALID_OPERATION);
    }
  }
  std::unique_ptr<gpu::Buffer> batch_edge_masks(const gpu::Buffer& vertices, const gpu::DrawCall& call) const;
  FFPostVertex post_vertex(const FFVertex& v, const FFUniforms& u, bool textured) const;
  void feedback_primitives(PrimClass cls, const FFVertices& verts, const std::vector<uint32_t>& idx);
  void feedback_value(float v);
  void close_quad_run();
  void split_quads(const FFVertices& v, uint32_t n, bool along_v1v3, FFVertices& out,
                   std::vector<uint32_t>& idx) const;
  void select_primitives(PrimClass cls, const FFVertices& verts, const std::vector<uint32_t>& idx);
  void build_uniforms(FFUniforms& u, TextureObject* tex) const;
  void release_transient();

  int width_ = 0, height_ = 0;
  bool double_buffer_ = true, has_depth_ = true, has_stencil_ = true, has_alpha_ = true;
  std::unique_ptr<gpu::Texture2D> color_[2];  // front, back
  std::unique_ptr<gpu::Texture2D> depth_;
  gpu::Framebuffer fb_;
  GLenum fb_target_ = 0;  // which colour buffer fb_ draws to
  std::unique_ptr<gpu::Context> gpu_;
  Batch batch_;
  FFVertices quad_run_;  // immediate-mode quads not yet cut (see split_quads)
  bool quad_run_clipped_ = false;
  // Buffers and textures referenced by queued draws: kept until the work has run.
  std::vector<std::unique_ptr<gpu::Buffer>> transient_buffers_;
  std::vector<std::unique_ptr<gpu::Texture2D>> transient_textures_;
  std::vector<std::shared_ptr<const gpu::Buffer>> transient_shared_;
  size_t transient_bytes_ = 0;
  // Past this many bytes of transient buffers the queued work runs, and they go.
  static constexpr size_t kTransientFlushBytes = size_t(256) << 20;
  GLenum error_ = GL_NO_ERROR;
  std::string version_string_, glsl_version_string_, extension_string_;
  GLenum render_mode_ = GL_RENDER;
  GLuint* sel_buffer_ = nullptr;
  GLsizei sel_size_ = 0;
  size_t sel_written_ = 0;
  GLint sel_hits_ = 0;
  bool sel_overflow_ = false, sel_hit_ = false;
  float sel_zmin_ = 0.0f, sel_zmax_ = 0.0f;
  std::vector<GLuint> sel_names_;
  GLfloat* fb_buffer_ = nullptr;
  GLsizei fb_size_ = 0;
  GLenum fb_type_ = GL_2D;
  size_t fb_written_ = 0;
  bool fb_overflow_ = false;

 public:
  // The last vertex-array range converted by glDrawElements, reused while its source bytes and
  // the attributes baked into it are unchanged (api_arrays.cpp).
  struct ArrayCache {
    std::vector<uint8_t> key;     // array pointers, formats, range, current values
    std::vector<uint8_t> source;  // the bytes the conversion read
    std::shared_ptr<const gpu::Buffer> vertices;
  } array_cache;
};

// The extensions a context has (glGetStringi(GL_EXTENSIONS, i)): those whose whole behaviour
// is implemented, the ARB forms of core features among them.
const std::vector<const char*>& extensions(const Context& c);

// The context GL calls go to (set by GLUT, or by tessel::gl::make_current).
Context* current();
void make_current(Context* c);
inline void make_current_context(Context* c) { make_current(c); }

// The gpu comparison of a GL comparison enum (GL_LESS ...); GL_ALWAYS for anything else.
gpu::CompareFunc compare_of(GLenum f);
// Linear interpolation of every value of two post-transform vertices (clipping, stipple).
FFPostVertex lerp_post(const FFPostVertex& a, const FFPostVertex& b, float t);

// The gpu topology of a GL primitive mode; false for an invalid mode (GL_QUADS, GL_QUAD_STRIP
// and GL_POLYGON are triangulated, `decompose`, and invalid in a core context).
bool topology_of(GLenum mode, bool core, gpu::Topology& out, bool& decompose);

}  // namespace tessel::gl
