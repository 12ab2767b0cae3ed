// State queries (GL 2.1 §6.1, the state tables 6.4-6.45 for what GL 1.x keeps): glGet*v,
// glGetLight, glGetMaterial. One function lists the values of a name as doubles; the four
// glGet forms convert them as §6.1.2 describes.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "api.hpp"

namespace tessel::gl {

namespace {

enum class Kind { Plain, Color, Bool };  // Color: integer queries map [-1, 1] to the int range

struct Values {
  std::vector<double> v;
  Kind kind = Kind::Plain;
};

void put(Values& out, std::initializer_list<double> xs) { out.v.insert(out.v.end(), xs); }
void put4(Values& out, const glm::vec4& x) { put(out, {x.x, x.y, x.z, x.w}); }
void put_mat(Values& out, const glm::mat4& m) {
  for (int i = 0; i < 16; ++i) out.v.push_back(glm::value_ptr(m)[i]);
}

// The state GL 2.0 to 3.3 add (GL 3.3 Tables 6.6 to 6.52): bindings, limits, the version.
bool query_gl33(Context& c, GLenum pname, Values& out) {
  auto b = [&](bool x) {
    out.kind = Kind::Bool;
    put(out, {x ? 1.0 : 0.0});
  };
  auto n = [&](double x) { put(out, {x}); };
  auto name_of = [](const BufferRef& r) { return r ? double(r->name) : 0.0; };
  const bool has_vao = c.vertex_arrays.count(c.bound_vertex_array) != 0;
  switch (pname) {
    case GL_MAJOR_VERSION: return n(c.major_version), true;
    case GL_MINOR_VERSION: return n(c.minor_version), true;
    case GL_NUM_EXTENSIONS: return n(double(extensions(c).size())), true;
    case GL_CONTEXT_FLAGS: return n(0), true;
    case GL_CONTEXT_PROFILE_MASK:
      return n(c.core_profile ? GL_CONTEXT_CORE_PROFILE_BIT : GL_CONTEXT_COMPATIBILITY_PROFILE_BIT), true;
    case GL_CURRENT_PROGRAM: return n(c.current_program), true;
    case GL_ARRAY_BUFFER_BINDING: return n(name_of(c.array_buffer)), true;
    case GL_ELEMENT_ARRAY_BUFFER_BINDING: return n(has_vao ? name_of(c.vao().element_buffer) : 0.0), true;
    case GL_COPY_READ_BUFFER:  // its binding (GL 3.3 Table 6.8)
      return n(name_of(c.copy_read_buffer)), true;
    case GL_COPY_WRITE_BUFFER: return n(name_of(c.copy_write_buffer)), true;
    case GL_PIXEL_PACK_BUFFER_BINDING: return n(name_of(c.pixel_pack_buffer)), true;
    case GL_PIXEL_UNPACK_BUFFER_BINDING: return n(name_of(c.pixel_unpack_buffer)), true;
    case GL_UNIFORM_BUFFER_BINDING: return n(name_of(c.uniform_buffer)), true;
    case GL_TEXTURE_BUFFER: return n(name_of(c.texture_buffer)), true;
    case GL_VERTEX_ARRAY_BINDING: return n(c.bound_vertex_array), true;
    case GL_PRIMITIVE_RESTART: return b(c.primitive_restart), true;
    case GL_PRIMITIVE_RESTART_INDEX: return n(c.primitive_restart_index), true;
    case GL_PROGRAM_POINT_SIZE: return b(c.program_point_size), true;
    case GL_DEPTH_CLAMP: return b(c.depth_clamp), true;
    case GL_MAX_VERTEX_ATTRIBS: return n(kMaxVertexAttribs), true;
    case GL_TEXTURE_BINDING_1D:
    case GL_TEXTURE_BINDING_2D:
    case GL_TEXTURE_BINDING_3D:
    case GL_TEXTURE_BINDING_CUBE_MAP:
    case GL_TEXTURE_BINDING_1D_ARRAY:
    case GL_TEXTURE_BINDING_2D_ARRAY:
    case GL_TEXTURE_BINDING_RECTANGLE:
    case GL_TEXTURE_BINDING_BUFFER:
    case GL_TEXTURE_BINDING_2D_MULTISAMPLE:
    case GL_TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY:
      for (int t = 0; t < kTexTargetCount; ++t)
        if (binding_query_of(TexTarget(t)) == pname) {
          const TextureRef& r = c.s.unit().bound[size_t(t)];
          return n(r ? r->name : 0), true;
        }
      return false;
    case GL_DRAW_BUFFER0:
    case GL_DRAW_BUFFER1:
    case GL_DRAW_BUFFER2:
    case GL_DRAW_BUFFER3:
    case GL_DRAW_BUFFER4:
    case GL_DRAW_BUFFER5:
    case GL_DRAW_BUFFER6:
    case GL_DRAW_BUFFER7: {
      const size_t i = pname - GL_DRAW_BUFFER0;
      if (c.draw_fbo) return n(c.draw_fbo->draw_buffers[i]), true;
      return n(i == 0 ? c.s.color.draw_buffer : GL_NONE), true;
    }
    case GL_DRAW_FRAMEBUFFER_BINDING: return n(c.draw_fbo ? c.draw_fbo->name : 0), true;
    case GL_READ_FRAMEBUFFER_BINDING: return n(c.read_fbo ? c.read_fbo->name : 0), true;
    case GL_RENDERBUFFER_BINDING: return n(c.bound_renderbuffer ? c.bound_renderbuffer->name : 0), true;
    case GL_MAX_DRAW_BUFFERS: return n(kMaxDrawBuffers), true;
    case GL_MAX_COLOR_ATTACHMENTS: return n(kMaxColorAttachments), true;
    case GL_MAX_RENDERBUFFER_SIZE: return n(kMaxRenderbufferSize), true;
    case GL_MAX_SAMPLES: return n(kMaxSamples), true;
    case GL_TIMESTAMP:
      c.touch();
      c.finish();
      return n(double(std::chrono::duration_cast<std::chrono::nanoseconds>(
                          std::chrono::steady_clock::now().time_since_epoch())
                          .count())),
             true;
    case GL_SAMPLER_BINDING: return n(c.s.unit().sampler ? c.s.unit().sampler->name : 0), true;
    case GL_MAX_3D_TEXTURE_SIZE: return n(kMax3DTextureSize), true;
    case GL_MAX_ARRAY_TEXTURE_LAYERS: return n(kMaxArrayTextureLayers), true;
    case GL_MAX_CUBE_MAP_TEXTURE_SIZE:
    case GL_MAX_RECTANGLE_TEXTURE_SIZE: return n(kMaxTextureSize), true;
    case GL_MAX_TEXTURE_BUFFER_SIZE: return n(double(gpu::kMaxTextureBufferTexels)), true;
    case GL_MAX_TEXTURE_LOD_BIAS: return n(16), true;
    case GL_MAX_TEXTURE_IMAGE_UNITS:
    case GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS: return n(kMaxStageTextureUnits), true;
    case GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS: return n(kMaxTextureUnits), true;
    case GL_MAX_TEXTURE_COORDS: return n(kMaxTexCoords), true;
    case GL_MAX_UNIFORM_BUFFER_BINDINGS: return n(kMaxUniformBufferBindings), true;
    case GL_MAX_VERTEX_UNIFORM_BLOCKS:
    case GL_MAX_GEOMETRY_UNIFORM_BLOCKS:
    case GL_MAX_FRAGMENT_UNIFORM_BLOCKS: return n(12), true;
    case GL_MAX_COMBINED_UNIFORM_BLOCKS: return n(36), true;
    case GL_MAX_UNIFORM_BLOCK_SIZE: return n(65536), true;
    case GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT: return n(16), true;
    case GL_MAX_VERTEX_UNIFORM_COMPONENTS:
    case GL_MAX_GEOMETRY_UNIFORM_COMPONENTS:
    case GL_MAX_FRAGMENT_UNIFORM_COMPONENTS: return n(glsl::kMaxUniformComponents), true;
    // The geometry stage (GL 3.3 Table 6.42's minimums and more, as Mesa's llvmpipe).
    case GL_MAX_GEOMETRY_INPUT_COMPONENTS: return n(64), true;
    case GL_MAX_GEOMETRY_OUTPUT_COMPONENTS: return n(128), true;
    case GL_MAX_GEOMETRY_OUTPUT_VERTICES: return n(1024), true;
    case GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS: return n(1024), true;
    case GL_MAX_GEOMETRY_TEXTURE_IMAGE_UNITS: return n(kMaxTextureUnits), true;
    case GL_MAX_VARYING_COMPONENTS:  // == GL_MAX_VARYING_FLOATS
    case GL_MAX_VERTEX_OUTPUT_COMPONENTS:
    case GL_MAX_FRAGMENT_INPUT_COMPONENTS: return n(gpu::kMaxVaryings), true;
    case GL_MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS:
      return n(glsl::kMaxFeedbackInterleavedComponents), true;
    case GL_MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS: return n(glsl::kMaxFeedbackSeparateAttribs), true;
    case GL_MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS: return n(glsl::kMaxFeedbackSeparateComponents), true;
    case GL_TRANSFORM_FEEDBACK_BUFFER_BINDING: return n(name_of(c.feedback_buffer)), true;
    case GL_RASTERIZER_DISCARD: return b(c.rasterizer_discard), true;
    case GL_MAX_SERVER_WAIT_TIMEOUT: return n(0), true;  // glWaitSync returns at once
    case GL_MAX_INTEGER_SAMPLES:
    case GL_MAX_COLOR_TEXTURE_SAMPLES:
    case GL_MAX_DEPTH_TEXTURE_SAMPLES: return n(kMaxSamples), true;
    case GL_MAX_SAMPLE_MASK_WORDS:
    case GL_MAX_DUAL_SOURCE_DRAW_BUFFERS: return n(1), true;
    case GL_SAMPLE_MASK_VALUE: return n(double(c.sample_mask)), true;
    // Multisample renderbuffers are stored (and drawn) single-sampled; GL_SAMPLES says what
    // the framebuffer was given (GL 3.3 §4.4.2), as blits and reads check it.
    case GL_SAMPLE_BUFFERS: return n(c.draw_fbo && c.draw_fbo->samples() > 0 ? 1 : 0), true;
    case GL_SAMPLES: return n(c.draw_fbo ? c.draw_fbo->samples() : 0), true;
    case GL_SAMPLE_COVERAGE_VALUE: return n(c.s.color.coverage_value), true;
    case GL_SAMPLE_COVERAGE_INVERT: return b(c.s.color.coverage_invert), true;
    case GL_PROVOKING_VERTEX: return n(double(c.s.light.provoking_vertex)), true;
    // Quads keep their last vertex in both conventions, as in Mesa (which, as a core
    // context has no quads, knows the query only in compatibility contexts).
    case GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION:
      if (c.core_profile) return false;
      return b(false), true;
    case GL_MIN_PROGRAM_TEXEL_OFFSET: return n(-8), true;
    case GL_MAX_PROGRAM_TEXEL_OFFSET: return n(7), true;
    case GL_MAX_CLIP_DISTANCES: return n(kMaxClipPlanes), true;
    case GL_MAX_ELEMENTS_INDICES:
    case GL_MAX_ELEMENTS_VERTICES: return n(1048576), true;
    default: return false;
  }
}

bool query(Context& c, GLenum pname, Values& out) {
  const ServerState& s = c.s;
  auto b = [&](bool x) {
    out.kind = Kind::Bool;
    put(out, {x ? 1.0 : 0.0});
  };
  auto e = [&](GLenum x) { put(out, {double(x)}); };
  if (pname >= GL_LIGHT0 && pname < GL_LIGHT0 + kMaxLights)
    return b(s.light.enabled[pname - GL_LIGHT0]), true;
  if (pname >= GL_CLIP_PLANE0 && pname < GL_CLIP_PLANE0 + kMaxClipPlanes)
    return b(s.transform.clip_enabled[pname - GL_CLIP_PLANE0]), true;
  if (pname >= GL_MAP1_COLOR_4 && pname <= GL_MAP1_VERTEX_4)
    return b(s.eval.map1_enabled[pname - GL_MAP1_COLOR_4]), true;
  if (pname >= GL_MAP2_COLOR_4 && pname <= GL_MAP2_VERTEX_4)
    return b(s.eval.map2_enabled[pname - GL_MAP2_COLOR_4]), true;
  switch (pname) {
    // Current values.
    case GL_CURRENT_COLOR:
      out.kind = Kind::Color;
      put4(out, s.current.color);
      return true;
    case GL_CURRENT_NORMAL:
      out.kind = Kind::Color;
      put(out, {s.current.normal.x, s.current.normal.y, s.current.normal.z});
      return true;
    case GL_CURRENT_TEXTURE_COORDS: put4(out, s.current.tex[size_t(c.tex_set())]); return true;
    case GL_CURRENT_SECONDARY_COLOR:
      out.kind = Kind::Color;
      put4(out, s.current.secondary);
      return true;
    case GL_CURRENT_FOG_COORD: put(out, {s.current.fog_coord}); return true;
    case GL_CURRENT_RASTER_POSITION: put4(out, s.current.raster_pos); return true;
    case GL_CURRENT_RASTER_COLOR:
      out.kind = Kind::Color;
      put4(out, s.current.raster_color);
      return true;
    case GL_CURRENT_RASTER_TEXTURE_COORDS: put4(out, s.current.raster_tex[size_t(c.tex_set())]); return true;
    case GL_CURRENT_RASTER_DISTANCE: put(out, {s.current.raster_distance}); return true;
    case GL_CURRENT_RASTER_POSITION_VALID: b(s.current.raster_valid); return true;
    case GL_EDGE_FLAG: b(s.current.edge); return true;
    // Transformation.
    case GL_MATRIX_MODE: e(s.transform.matrix_mode); return true;
    case GL_MODELVIEW_MATRIX: put_mat(out, c.matrices[0].back()); return true;
    case GL_PROJECTION_MATRIX: put_mat(out, c.matrices[1].back()); return true;
    case GL_TEXTURE_MATRIX: put_mat(out, c.texture_matrix(c.tex_set())); return true;
    // GL 1.3 §6.1.2: the same matrices, row by row.
    case GL_TRANSPOSE_MODELVIEW_MATRIX: put_mat(out, glm::transpose(c.matrices[0].back())); return true;
    case GL_TRANSPOSE_PROJECTION_MATRIX: put_mat(out, glm::transpose(c.matrices[1].back())); return true;
    case GL_TRANSPOSE_TEXTURE_MATRIX:
      put_mat(out, glm::transpose(c.texture_matrix(c.tex_set())));
      return true;
    // No compressed internal format is accepted (GL_COMPRESSED_* ask for none in particular).
    case GL_NUM_COMPRESSED_TEXTURE_FORMATS: put(out, {0.0}); return true;
    case GL_COMPRESSED_TEXTURE_FORMATS: return true;
    case GL_MODELVIEW_STACK_DEPTH: put(out, {double(c.matrices[0].size())}); return true;
    case GL_PROJECTION_STACK_DEPTH: put(out, {double(c.matrices[1].size())}); return true;
    case GL_TEXTURE_STACK_DEPTH: put(out, {double(c.matrices[size_t(2 + c.tex_set())].size())}); return true;
    case GL_VIEWPORT:
      put(out,
          {double(s.viewport.x), double(s.viewport.y), double(s.viewport.width), double(s.viewport.height)});
      return true;
    case GL_DEPTH_RANGE: put(out, {s.viewport.near_, s.viewport.far_}); return true;
    case GL_NORMALIZE: b(s.transform.normalize); return true;
    case GL_RESCALE_NORMAL: b(s.transform.rescale_normal); return true;
    // Colouring and lighting.
    case GL_FOG: b(s.fog.enabled); return true;
    case GL_FOG_COLOR:
      out.kind = Kind::Color;
      put4(out, s.fog.color);
      return true;
    case GL_FOG_DENSITY: put(out, {s.fog.density}); return true;
    case GL_FOG_START: put(out, {s.fog.start}); return true;
    case GL_FOG_END: put(out, {s.fog.end}); return true;
    case GL_FOG_MODE: e(s.fog.mode); return true;
    case GL_FOG_COORD_SRC: e(s.fog.coord_src); return true;
    case GL_COLOR_SUM: b(s.fog.color_sum); return true;
    case GL_POINT_SPRITE: b(s.point.sprite); return true;
    case GL_FOG_INDEX: put(out, {0.0}); return true;
    case GL_SHADE_MODEL: e(s.light.shade_model); return true;
    case GL_LIGHTING: b(s.light.lighting); return true;
    case GL_COLOR_MATERIAL: b(s.light.color_material); return true;
    case GL_COLOR_MATERIAL_PARAMETER: e(s.light.color_material_mode); return true;
    case GL_COLOR_MATERIAL_FACE: e(s.light.color_material_face); return true;
    case GL_LIGHT_MODEL_AMBIENT:
      out.kind = Kind::Color;
      put4(out, s.light.model_ambient);
      return true;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: b(s.light.local_viewer); return true;
    case GL_LIGHT_MODEL_TWO_SIDE: b(s.light.two_side); return true;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
      e(s.light.separate_specular ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
      return true;
    // Rasterization.
    case GL_POINT_SIZE: put(out, {s.point.size}); return true;
    case GL_POINT_SIZE_MIN: put(out, {s.point.size_min}); return true;
    case GL_POINT_SIZE_MAX: put(out, {s.point.size_max}); return true;
    case GL_POINT_DISTANCE_ATTENUATION:
      put(out, {s.point.attenuation[0], s.point.attenuation[1], s.point.attenuation[2]});
      return true;
    case GL_POINT_FADE_THRESHOLD_SIZE: put(out, {s.point.fade_threshold}); return true;
    case GL_POINT_SPRITE_COORD_ORIGIN:
      e(s.point.sprite_lower_left ? GL_LOWER_LEFT : GL_UPPER_LEFT);
      return true;
    case GL_POINT_SMOOTH: b(s.point.smooth); return true;
    case GL_LINE_WIDTH: put(out, {s.line.width}); return true;
    case GL_LINE_SMOOTH: b(s.line.smooth); return true;
    case GL_LINE_STIPPLE: b(s.line.stipple); return true;
    case GL_LINE_STIPPLE_PATTERN: put(out, {double(s.line.stipple_pattern)}); return true;
    case GL_LINE_STIPPLE_REPEAT: put(out, {double(s.line.stipple_factor)}); return true;
    case GL_CULL_FACE: b(s.polygon.cull); return true;
    case GL_CULL_FACE_MODE: e(s.polygon.cull_face); return true;
    case GL_FRONT_FACE: e(s.polygon.front_face); return true;
    case GL_POLYGON_SMOOTH: b(s.polygon.smooth); return true;
    case GL_POLYGON_MODE: put(out, {double(s.polygon.mode_front), double(s.polygon.mode_back)}); return true;
    case GL_POLYGON_OFFSET_FACTOR: put(out, {s.polygon.offset_factor}); return true;
    case GL_POLYGON_OFFSET_UNITS: put(out, {s.polygon.offset_units}); return true;
    case GL_POLYGON_OFFSET_FILL: b(s.polygon.offset_fill); return true;
    case GL_POLYGON_OFFSET_LINE: b(s.polygon.offset_line); return true;
    case GL_POLYGON_OFFSET_POINT: b(s.polygon.offset_point); return true;
    case GL_POLYGON_STIPPLE: b(s.polygon.stipple); return true;
    // Texturing.
    case GL_TEXTURE_1D: b(s.unit().enabled_1d); return true;
    case GL_TEXTURE_2D: b(s.unit().enabled_2d); return true;
    case GL_TEXTURE_3D: b(s.unit().enabled_3d); return true;
    case GL_TEXTURE_CUBE_MAP: b(s.unit().enabled_cube); return true;
    case GL_TEXTURE_GEN_S: b(s.unit().gen_enabled[0]); return true;
    case GL_TEXTURE_GEN_T: b(s.unit().gen_enabled[1]); return true;
    case GL_TEXTURE_GEN_R: b(s.unit().gen_enabled[2]); return true;
    case GL_TEXTURE_GEN_Q: b(s.unit().gen_enabled[3]); return true;
    case GL_ACTIVE_TEXTURE: e(GL_TEXTURE0 + s.active_unit); return true;
    case GL_CLIENT_ACTIVE_TEXTURE: e(GL_TEXTURE0 + c.c.client_active_unit); return true;
    // Pixel operations.
    case GL_SCISSOR_TEST: b(s.scissor.test); return true;
    case GL_SCISSOR_BOX:
      put(out, {double(s.scissor.x), double(s.scissor.y), double(s.scissor.width), double(s.scissor.height)});
      return true;
    case GL_ALPHA_TEST: b(s.color.alpha_test); return true;
    case GL_ALPHA_TEST_FUNC: e(s.color.alpha_func); return true;
    case GL_ALPHA_TEST_REF:
      out.kind = Kind::Color;
      put(out, {s.color.alpha_ref});
      return true;
    case GL_STENCIL_TEST: b(s.stencil.test); return true;
    case GL_STENCIL_FUNC: e(s.stencil.func); return true;
    case GL_STENCIL_VALUE_MASK: put(out, {double(s.stencil.value_mask)}); return true;
    case GL_STENCIL_REF: put(out, {double(s.stencil.ref)}); return true;
    case GL_STENCIL_FAIL: e(s.stencil.fail); return true;
    case GL_STENCIL_PASS_DEPTH_FAIL: e(s.stencil.zfail); return true;
    case GL_STENCIL_PASS_DEPTH_PASS: e(s.stencil.zpass); return true;
    case GL_STENCIL_BACK_FUNC: e(s.stencil.back_func); return true;
    case GL_STENCIL_BACK_VALUE_MASK: put(out, {double(s.stencil.back_value_mask)}); return true;
    case GL_STENCIL_BACK_REF: put(out, {double(s.stencil.back_ref)}); return true;
    case GL_STENCIL_BACK_WRITEMASK: put(out, {double(s.stencil.back_write_mask)}); return true;
    case GL_STENCIL_BACK_FAIL: e(s.stencil.back_fail); return true;
    case GL_STENCIL_BACK_PASS_DEPTH_FAIL: e(s.stencil.back_zfail); return true;
    case GL_STENCIL_BACK_PASS_DEPTH_PASS: e(s.stencil.back_zpass); return true;
    case GL_DEPTH_TEST: b(s.depth.test); return true;
    case GL_DEPTH_FUNC: e(s.depth.func); return true;
    case GL_BLEND: b(s.color.blend[0]); return true;
    case GL_BLEND_SRC:
    case GL_BLEND_SRC_RGB: e(s.color.blend_src); return true;
    case GL_BLEND_DST:
    case GL_BLEND_DST_RGB: e(s.color.blend_dst); return true;
    case GL_BLEND_SRC_ALPHA: e(s.color.blend_src_alpha); return true;
    case GL_BLEND_DST_ALPHA: e(s.color.blend_dst_alpha); return true;
    case GL_BLEND_EQUATION_RGB:  // == GL_BLEND_EQUATION
      e(s.color.blend_eq);
      return true;
    case GL_BLEND_EQUATION_ALPHA: e(s.color.blend_eq_alpha); return true;
    case GL_BLEND_COLOR:
      out.kind = Kind::Color;
      put4(out, s.color.blend_color);
      return true;
    case GL_DITHER: b(s.color.dither); return true;
    case GL_COLOR_LOGIC_OP: b(s.color.logic_op); return true;
    case GL_LOGIC_OP_MODE: e(s.color.logic_op_mode); return true;
    // Framebuffer control.
    case GL_DRAW_BUFFER: e(c.draw_fbo ? c.draw_fbo->draw_buffers[0] : s.color.draw_buffer); return true;
    case GL_READ_BUFFER: e(c.read_fbo ? c.read_fbo->read_buffer : s.pixel.read_buffer); return true;
    case GL_CLAMP_READ_COLOR: e(s.pixel.clamp_read); return true;
    case GL_CLAMP_VERTEX_COLOR: e(s.pixel.clamp_vertex); return true;
    case GL_CLAMP_FRAGMENT_COLOR: e(s.pixel.clamp_fragment); return true;
    case GL_COLOR_WRITEMASK:
      out.kind = Kind::Bool;
      for (bool m : s.color.color_mask[0]) out.v.push_back(m ? 1.0 : 0.0);
      return true;
    case GL_DEPTH_WRITEMASK: b(s.depth.mask); return true;
    case GL_STENCIL_WRITEMASK: put(out, {double(s.stencil.write_mask)}); return true;
    case GL_COLOR_CLEAR_VALUE:
      out.kind = Kind::Color;
      put4(out, s.color.clear_color);
      return true;
    case GL_DEPTH_CLEAR_VALUE: put(out, {s.depth.clear}); return true;
    case GL_STENCIL_CLEAR_VALUE: put(out, {double(s.stencil.clear)}); return true;
    case GL_ACCUM_CLEAR_VALUE:
      out.kind = Kind::Color;
      put4(out, s.accum_clear);
      return true;
    case GL_INDEX_CLEAR_VALUE:
    case GL_INDEX_WRITEMASK: put(out, {0.0}); return true;
    // Pixels.
    case GL_UNPACK_SWAP_BYTES: b(c.c.unpack.swap_bytes); return true;
    case GL_UNPACK_LSB_FIRST: b(c.c.unpack.lsb_first); return true;
    case GL_UNPACK_ROW_LENGTH: put(out, {double(c.c.unpack.row_length)}); return true;
    case GL_UNPACK_SKIP_ROWS: put(out, {double(c.c.unpack.skip_rows)}); return true;
    case GL_UNPACK_SKIP_PIXELS: put(out, {double(c.c.unpack.skip_pixels)}); return true;
    case GL_UNPACK_ALIGNMENT: put(out, {double(c.c.unpack.alignment)}); return true;
    case GL_PACK_SWAP_BYTES: b(c.c.pack.swap_bytes); return true;
    case GL_PACK_LSB_FIRST: b(c.c.pack.lsb_first); return true;
    case GL_PACK_ROW_LENGTH: put(out, {double(c.c.pack.row_length)}); return true;
    case GL_PACK_SKIP_ROWS: put(out, {double(c.c.pack.skip_rows)}); return true;
    case GL_PACK_SKIP_PIXELS: put(out, {double(c.c.pack.skip_pixels)}); return true;
    case GL_PACK_ALIGNMENT: put(out, {double(c.c.pack.alignment)}); return true;
    case GL_UNPACK_IMAGE_HEIGHT: put(out, {double(c.c.unpack.image_height)}); return true;
    case GL_UNPACK_SKIP_IMAGES: put(out, {double(c.c.unpack.skip_images)}); return true;
    case GL_PACK_IMAGE_HEIGHT: put(out, {double(c.c.pack.image_height)}); return true;
    case GL_PACK_SKIP_IMAGES: put(out, {double(c.c.pack.skip_images)}); return true;
    case GL_ZOOM_X: put(out, {s.pixel.zoom_x}); return true;
    case GL_ZOOM_Y: put(out, {s.pixel.zoom_y}); return true;
    case GL_RED_SCALE: put(out, {s.pixel.red_scale}); return true;
    case GL_RED_BIAS: put(out, {s.pixel.red_bias}); return true;
    case GL_GREEN_SCALE: put(out, {s.pixel.green_scale}); return true;
    case GL_GREEN_BIAS: put(out, {s.pixel.green_bias}); return true;
    case GL_BLUE_SCALE: put(out, {s.pixel.blue_scale}); return true;
    case GL_BLUE_BIAS: put(out, {s.pixel.blue_bias}); return true;
    case GL_ALPHA_SCALE: put(out, {s.pixel.alpha_scale}); return true;
    case GL_ALPHA_BIAS: put(out, {s.pixel.alpha_bias}); return true;
    case GL_DEPTH_SCALE: put(out, {s.pixel.depth_scale}); return true;
    case GL_DEPTH_BIAS: put(out, {s.pixel.depth_bias}); return true;
    case GL_MAP_COLOR: b(s.pixel.map_color); return true;
    case GL_MAP_STENCIL: b(s.pixel.map_stencil); return true;
    case GL_PIXEL_MAP_I_TO_I_SIZE:
    case GL_PIXEL_MAP_S_TO_S_SIZE:
    case GL_PIXEL_MAP_I_TO_R_SIZE:
    case GL_PIXEL_MAP_I_TO_G_SIZE:
    case GL_PIXEL_MAP_I_TO_B_SIZE:
    case GL_PIXEL_MAP_I_TO_A_SIZE:
    case GL_PIXEL_MAP_R_TO_R_SIZE:
    case GL_PIXEL_MAP_G_TO_G_SIZE:
    case GL_PIXEL_MAP_B_TO_B_SIZE:
    case GL_PIXEL_MAP_A_TO_A_SIZE:
      put(out, {double(s.pixel_maps[size_t(pname - GL_PIXEL_MAP_I_TO_I_SIZE)].size())});
      return true;
    case GL_INDEX_SHIFT: put(out, {double(s.pixel.index_shift)}); return true;
    case GL_INDEX_OFFSET: put(out, {double(s.pixel.index_offset)}); return true;
    // Hints.
    case GL_PERSPECTIVE_CORRECTION_HINT: e(s.hint.perspective); return true;
    case GL_POINT_SMOOTH_HINT: e(s.hint.point); return true;
    case GL_LINE_SMOOTH_HINT: e(s.hint.line); return true;
    case GL_POLYGON_SMOOTH_HINT: e(s.hint.polygon); return true;
    case GL_FOG_HINT: e(s.hint.fog); return true;
    // Lists and stacks.
    case GL_LIST_BASE: put(out, {double(s.list_base)}); return true;
    case GL_LIST_INDEX: put(out, {double(c.compiling_list)}); return true;
    case GL_LIST_MODE: e(c.compiling_list ? c.compile_mode : 0); return true;
    case GL_ATTRIB_STACK_DEPTH: put(out, {double(c.attrib_stack.size())}); return true;
    case GL_CLIENT_ATTRIB_STACK_DEPTH: put(out, {double(c.client_stack.size())}); return true;
    case GL_RENDER_MODE: e(c.render_mode()); return true;
    case GL_AUTO_NORMAL: b(s.eval.auto_normal); return true;
    case GL_MAP1_GRID_DOMAIN: put(out, {s.eval.grid1.u1, s.eval.grid1.u2}); return true;
    case GL_MAP1_GRID_SEGMENTS: put(out, {double(s.eval.grid1.n)}); return true;
    case GL_MAP2_GRID_DOMAIN:
      put(out, {s.eval.grid2u.u1, s.eval.grid2u.u2, s.eval.grid2v.u1, s.eval.grid2v.u2});
      return true;
    case GL_MAP2_GRID_SEGMENTS: put(out, {double(s.eval.grid2u.n), double(s.eval.grid2v.n)}); return true;
    case GL_NAME_STACK_DEPTH: put(out, {double(c.name_stack().size())}); return true;
    // Vertex arrays.
    case GL_VERTEX_ARRAY: b(c.c.vertex.enabled); return true;
    case GL_VERTEX_ARRAY_SIZE: put(out, {double(c.c.vertex.size)}); return true;
    case GL_VERTEX_ARRAY_TYPE: e(c.c.vertex.type); return true;
    case GL_VERTEX_ARRAY_STRIDE: put(out, {double(c.c.vertex.stride)}); return true;
    case GL_NORMAL_ARRAY: b(c.c.normal.enabled); return true;
    case GL_NORMAL_ARRAY_TYPE: e(c.c.normal.type); return true;
    case GL_NORMAL_ARRAY_STRIDE: put(out, {double(c.c.normal.stride)}); return true;
    case GL_COLOR_ARRAY: b(c.c.color.enabled); return true;
    case GL_COLOR_ARRAY_SIZE: put(out, {double(c.c.color.size)}); return true;
    case GL_COLOR_ARRAY_TYPE: e(c.c.color.type); return true;
    case GL_COLOR_ARRAY_STRIDE: put(out, {double(c.c.color.stride)}); return true;
    case GL_TEXTURE_COORD_ARRAY: b(c.c.active_tex().enabled); return true;
    case GL_TEXTURE_COORD_ARRAY_SIZE: put(out, {double(c.c.active_tex().size)}); return true;
    case GL_TEXTURE_COORD_ARRAY_TYPE: e(c.c.active_tex().type); return true;
    case GL_TEXTURE_COORD_ARRAY_STRIDE: put(out, {double(c.c.active_tex().stride)}); return true;
    case GL_SECONDARY_COLOR_ARRAY: b(c.c.secondary.enabled); return true;
    case GL_SECONDARY_COLOR_ARRAY_SIZE: put(out, {double(c.c.secondary.size)}); return true;
    case GL_SECONDARY_COLOR_ARRAY_TYPE: e(c.c.secondary.type); return true;
    case GL_SECONDARY_COLOR_ARRAY_STRIDE: put(out, {double(c.c.secondary.stride)}); return true;
    case GL_FOG_COORD_ARRAY: b(c.c.fog.enabled); return true;
    case GL_FOG_COORD_ARRAY_TYPE: e(c.c.fog.type); return true;
    case GL_FOG_COORD_ARRAY_STRIDE: put(out, {double(c.c.fog.stride)}); return true;
    case GL_EDGE_FLAG_ARRAY: b(c.c.edge.enabled); return true;
    case GL_EDGE_FLAG_ARRAY_STRIDE: put(out, {double(c.c.edge.stride)}); return true;
    case GL_INDEX_ARRAY: b(c.c.index.enabled); return true;
    // Implementation limits (GL 2.1 Tables 6.36-6.39).
    case GL_MAX_LIGHTS: put(out, {double(kMaxLights)}); return true;
    case GL_MAX_CLIP_PLANES: put(out, {double(kMaxClipPlanes)}); return true;
    case GL_MAX_MODELVIEW_STACK_DEPTH: put(out, {double(kModelviewDepth)}); return true;
    case GL_MAX_PROJECTION_STACK_DEPTH: put(out, {double(kProjectionDepth)}); return true;
    case GL_MAX_TEXTURE_STACK_DEPTH: put(out, {double(kTextureDepth)}); return true;
    case GL_MAX_ATTRIB_STACK_DEPTH: put(out, {double(kAttribDepth)}); return true;
    case GL_MAX_CLIENT_ATTRIB_STACK_DEPTH: put(out, {double(kClientAttribDepth)}); return true;
    case GL_MAX_LIST_NESTING: put(out, {double(kMaxListNesting)}); return true;
    case GL_MAX_TEXTURE_SIZE: put(out, {double(kMaxTextureSize)}); return true;
    case GL_MAX_TEXTURE_UNITS: put(out, {double(kMaxTexCoords)}); return true;
    case GL_MAX_VIEWPORT_DIMS:
      put(out, {double(gpu::kMaxViewportSize), double(gpu::kMaxViewportSize)});
      return true;
    case GL_MAX_EVAL_ORDER: put(out, {8.0}); return true;
    case GL_MAX_PIXEL_MAP_TABLE: put(out, {256.0}); return true;
    case GL_MAX_NAME_STACK_DEPTH: put(out, {64.0}); return true;
    case GL_SUBPIXEL_BITS: put(out, {8.0}); return true;
    case GL_POINT_SIZE_RANGE: put(out, {1.0, 255.0}); return true;
    case GL_POINT_SIZE_GRANULARITY: put(out, {0.125}); return true;
    case GL_LINE_WIDTH_RANGE: put(out, {1.0, 255.0}); return true;
    case GL_LINE_WIDTH_GRANULARITY: put(out, {0.125}); return true;
    case GL_ALIASED_POINT_SIZE_RANGE: put(out, {1.0, 255.0}); return true;
    case GL_ALIASED_LINE_WIDTH_RANGE: put(out, {1.0, 255.0}); return true;
    case GL_RED_BITS:
    case GL_GREEN_BITS:
    case GL_BLUE_BITS: put(out, {8.0}); return true;
    case GL_ALPHA_BITS: put(out, {c.has_alpha() || c.draw_fbo ? 8.0 : 0.0}); return true;
    case GL_DEPTH_BITS: put(out, {c.has_depth() ? 24.0 : 0.0}); return true;
    case GL_STENCIL_BITS: put(out, {c.has_stencil() ? 8.0 : 0.0}); return true;
    case GL_INDEX_BITS:
    case GL_ACCUM_RED_BITS:
    case GL_ACCUM_GREEN_BITS:
    case GL_ACCUM_BLUE_BITS:
    case GL_ACCUM_ALPHA_BITS:
    case GL_AUX_BUFFERS: put(out, {0.0}); return true;
    case GL_RGBA_MODE: b(true); return true;
    case GL_INDEX_MODE: b(false); return true;
    case GL_DOUBLEBUFFER: b(c.double_buffered()); return true;
    case GL_STEREO: b(false); return true;
    default: return query_gl33(c, pname, out);
  }
}

// The state a core context does not have (GL 3.2 Appendix E.2.2), by value.
constexpr GLenum kCoreRemoved[] = {
#include "core_removed_enums.inc"
};

template <class T>
void get(GLenum pname, T* out, auto convert) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  // Mesa 22 still answers these in a core context; GL 3.3 core makes them GL_INVALID_ENUM.
  if (c.core_profile && std::binary_search(std::begin(kCoreRemoved), std::end(kCoreRemoved), pname))
    return c.error(GL_INVALID_ENUM);
  Values v;
  if (!query(c, pname, v)) return c.error(GL_INVALID_ENUM);
  if (!out) return;
  for (size_t i = 0; i < v.v.size(); ++i) out[i] = convert(v.v[i], v.kind);
}

// Indexed state (GL 3.3 §6.1.1): the uniform and transform feedback buffer binding points. False, with the
// error recorded and nothing written, for a name that is not indexed state or an index past it.
bool indexed_value(Context& c, GLenum pname, GLuint index, GLint64& out) {
  if (pname == GL_SAMPLE_MASK_VALUE) {  // one word (GL_MAX_SAMPLE_MASK_WORDS)
    if (index != 0) {
      c.error(GL_INVALID_VALUE);
      return false;
    }
    out = GLint64(c.sample_mask);
    return true;
  }
  // Which binding points, and which of their fields.
  GLenum target = GL_NONE;
  int field = 0;  // buffer name, start, size
  switch (pname) {
    case GL_UNIFORM_BUFFER_SIZE: ++field; [[fallthrough]];
    case GL_UNIFORM_BUFFER_START: ++field; [[fallthrough]];
    case GL_UNIFORM_BUFFER_BINDING: target = GL_UNIFORM_BUFFER; break;
    case GL_TRANSFORM_FEEDBACK_BUFFER_SIZE: ++field; [[fallthrough]];
    case GL_TRANSFORM_FEEDBACK_BUFFER_START: ++field; [[fallthrough]];
    case GL_TRANSFORM_FEEDBACK_BUFFER_BINDING: target = GL_TRANSFORM_FEEDBACK_BUFFER; break;
    default: c.error(GL_INVALID_ENUM); return false;
  }
  const std::span<Context::IndexedBuffer> points = c.indexed_bindings(target);
  if (index >= points.size()) {
    c.error(GL_INVALID_VALUE);
    return false;
  }
  const Context::IndexedBuffer& ib = points[index];
  out = field == 0   ? GLint64(ib.buffer ? ib.buffer->name : 0)
        : field == 1 ? GLint64(ib.offset)
                     : GLint64(ib.size);
  return true;
}

}  // namespace
}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glGetBooleanv(GLenum pname, GLboolean* out) {
  get(pname, out, [](double x, Kind) { return x != 0.0 ? GLboolean(GL_TRUE) : GLboolean(GL_FALSE); });
}
void GLAPIENTRY glGetIntegerv(GLenum pname, GLint* out) {
  get(pname, out, [](double x, Kind k) {
    // GL 2.1 §6.1.2: colours and normals map [-1, 1] linearly onto the integer range.
    if (k == Kind::Color) return GLint(std::lround(std::clamp(x, -1.0, 1.0) * 2147483647.0));
    return GLint(std::lround(std::clamp(x, -2147483648.0, 2147483647.0)));
  });
}
void GLAPIENTRY glGetInteger64v(GLenum pname, GLint64* out) {
  get(pname, out, [](double x, Kind k) {
    if (k == Kind::Color) return GLint64(std::lround(std::clamp(x, -1.0, 1.0) * 2147483647.0));
    return GLint64(std::llround(x));
  });
}
void GLAPIENTRY glGetInteger64i_v(GLenum pname, GLuint index, GLint64* out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  GLint64 v = 0;
  if (indexed_value(c, pname, index, v) && out) *out = v;
}
void GLAPIENTRY glGetIntegeri_v(GLenum pname, GLuint index, GLint* out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  GLint64 v = 0;
  if (indexed_value(c, pname, index, v) && out) *out = GLint(v);
}
void GLAPIENTRY glGetBooleani_v(GLenum pname, GLuint index, GLboolean* out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (pname == GL_COLOR_WRITEMASK || pname == GL_BLEND) {
    if (index >= GLuint(kMaxDrawBuffers)) return c.error(GL_INVALID_VALUE);
    if (!out) return;
    if (pname == GL_BLEND) {
      *out = c.s.color.blend[index] ? GL_TRUE : GL_FALSE;
      return;
    }
    for (int k = 0; k < 4; ++k) out[k] = c.s.color.color_mask[index][size_t(k)] ? GL_TRUE : GL_FALSE;
    return;
  }
  GLint64 v = 0;
  if (indexed_value(c, pname, index, v) && out) *out = v != 0;
}
void GLAPIENTRY glGetFloatv(GLenum pname, GLfloat* out) {
  get(pname, out, [](double x, Kind) { return GLfloat(x); });
}
void GLAPIENTRY glGetDoublev(GLenum pname, GLdouble* out) {
  get(pname, out, [](double x, Kind) { return x; });
}

void GLAPIENTRY glGetLightfv(GLenum light, GLenum pname, GLfloat* out) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (light < GL_LIGHT0 || light >= GL_LIGHT0 + kMaxLights || light_param_count(pname) == 0)
    return c.error(GL_INVALID_ENUM);
  if (!out) return;
  const size_t i = light - GL_LIGHT0;
  const FFLight& L = c.s.light.light[i];
  auto v4 = [&](const glm::vec4& v) {
    for (int k = 0; k < 4; ++k) out[k] = v[k];
  };
  switch (pname) {
    case GL_AMBIENT: v4(L.ambient); break;
    case GL_DIFFUSE: v4(L.diffuse); break;
    case GL_SPECULAR: v4(L.specular); break;
    case GL_POSITION: v4(L.position); break;
    case GL_SPOT_DIRECTION:
      for (int k = 0; k < 3; ++k) out[k] = L.spot_direction[k];
      break;
    case GL_SPOT_EXPONENT: out[0] = L.spot_exponent; break;
    case GL_SPOT_CUTOFF: out[0] = c.s.light.spot_cutoff[i]; break;
    case GL_CONSTANT_ATTENUATION: out[0] = L.k0; break;
    case GL_LINEAR_ATTENUATION: out[0] = L.k1; break;
    case GL_QUADRATIC_ATTENUATION: out[0] = L.k2; break;
    default: break;
  }
}
void GLAPIENTRY glGetLightiv(GLenum light, GLenum pname, GLint* out) {
  GL_REMOVED_IN_CORE();
  GLfloat f[4] = {0, 0, 0, 0};
  glGetLightfv(light, pname, f);
  if (!out) return;
  const int n = light_param_count(pname);
  const bool color = pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR;
  for (int k = 0; k < n; ++k)
    out[k] = color ? GLint(std::lround(std::clamp(double(f[k]), -1.0, 1.0) * 2147483647.0))
                   : GLint(std::lround(f[k]));
}
void GLAPIENTRY glGetMaterialfv(GLenum face, GLenum pname, GLfloat* out) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if ((face != GL_FRONT && face != GL_BACK) || material_param_count(pname) == 0 ||
      pname == GL_AMBIENT_AND_DIFFUSE)
    return c.error(GL_INVALID_ENUM);
  if (!out) return;
  const FFMaterial& m = c.s.light.material[face == GL_FRONT ? 0 : 1];
  auto v4 = [&](const glm::vec4& v) {
    for (int k = 0; k < 4; ++k) out[k] = v[k];
  };
  switch (pname) {
    case GL_AMBIENT: v4(m.ambient); break;
    case GL_DIFFUSE: v4(m.diffuse); break;
    case GL_SPECULAR: v4(m.specular); break;
    case GL_EMISSION: v4(m.emission); break;
    case GL_SHININESS: out[0] = m.shininess; break;
    case GL_COLOR_INDEXES: out[0] = 0, out[1] = 1, out[2] = 1; break;
    default: break;
  }
}
void GLAPIENTRY glGetMaterialiv(GLenum face, GLenum pname, GLint* out) {
  GL_REMOVED_IN_CORE();
  GLfloat f[4] = {0, 0, 0, 0};
  glGetMaterialfv(face, pname, f);
  if (!out) return;
  const int n = material_param_count(pname);
  const bool color = pname != GL_SHININESS && pname != GL_COLOR_INDEXES;
  for (int k = 0; k < n; ++k)
    out[k] = color ? GLint(std::lround(std::clamp(double(f[k]), -1.0, 1.0) * 2147483647.0))
                   : GLint(std::lround(f[k]));
}

}  // extern "C"
