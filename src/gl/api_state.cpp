// Enables, per-fragment and rasterization state, clears, errors and strings, display lists,
// the attribute stacks, glFlush/glFinish.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "api.hpp"
#include "pixels.hpp"

namespace tessel::gl {

namespace {

// The flag behind a glEnable capability, or nullptr when it is not one.
bool* capability(Context& c, GLenum cap) {
  ServerState& s = c.s;
  if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + kMaxLights) return &s.light.enabled[cap - GL_LIGHT0];
  if (cap >= GL_CLIP_PLANE0 && cap < GL_CLIP_PLANE0 + kMaxClipPlanes)
    return &s.transform.clip_enabled[cap - GL_CLIP_PLANE0];
  if (cap >= GL_MAP1_COLOR_4 && cap <= GL_MAP1_VERTEX_4) return &s.eval.map1_enabled[cap - GL_MAP1_COLOR_4];
  if (cap >= GL_MAP2_COLOR_4 && cap <= GL_MAP2_VERTEX_4) return &s.eval.map2_enabled[cap - GL_MAP2_COLOR_4];
  switch (cap) {
    case GL_PROGRAM_POINT_SIZE: return &c.program_point_size;
    case GL_PRIMITIVE_RESTART: return &c.primitive_restart;
    case GL_DEPTH_CLAMP: return &c.depth_clamp;
    case GL_RASTERIZER_DISCARD: return &c.rasterizer_discard;
    case GL_TEXTURE_CUBE_MAP_SEAMLESS: return &c.cube_map_seamless;
    case GL_AUTO_NORMAL: return &s.eval.auto_normal;
    case GL_LIGHTING: return &s.light.lighting;
    case GL_COLOR_MATERIAL: return &s.light.color_material;
    case GL_FOG: return &s.fog.enabled;
    case GL_ALPHA_TEST: return &s.color.alpha_test;
    case GL_BLEND: return &s.color.blend[0];
    case GL_DITHER: return &s.color.dither;
    case GL_COLOR_LOGIC_OP: return &s.color.logic_op;
    case GL_DEPTH_TEST: return &s.depth.test;
    case GL_STENCIL_TEST: return &s.stencil.test;
    case GL_SCISSOR_TEST: return &s.scissor.test;
    case GL_CULL_FACE: return &s.polygon.cull;
    case GL_POLYGON_OFFSET_FILL: return &s.polygon.offset_fill;
    case GL_POLYGON_OFFSET_LINE: return &s.polygon.offset_line;
    case GL_POLYGON_OFFSET_POINT: return &s.polygon.offset_point;
    case GL_POLYGON_SMOOTH: return &s.polygon.smooth;
    case GL_POLYGON_STIPPLE: return &s.polygon.stipple;
    case GL_LINE_SMOOTH: return &s.line.smooth;
    case GL_LINE_STIPPLE: return &s.line.stipple;
    case GL_POINT_SMOOTH: return &s.point.smooth;
    case GL_NORMALIZE: return &s.transform.normalize;
    case GL_RESCALE_NORMAL: return &s.transform.rescale_normal;
    case GL_TEXTURE_1D: return &s.unit().enabled_1d;
    case GL_TEXTURE_2D: return &s.unit().enabled_2d;
    case GL_TEXTURE_3D: return &s.unit().enabled_3d;
    case GL_TEXTURE_CUBE_MAP: return &s.unit().enabled_cube;
    case GL_COLOR_SUM: return &s.fog.color_sum;
    case GL_POINT_SPRITE: return &s.point.sprite;
    case GL_TEXTURE_GEN_S: return &s.unit().gen_enabled[0];
    case GL_TEXTURE_GEN_T: return &s.unit().gen_enabled[1];
    case GL_TEXTURE_GEN_R: return &s.unit().gen_enabled[2];
    case GL_TEXTURE_GEN_Q: return &s.unit().gen_enabled[3];
    default: return nullptr;
  }
}

// Capabilities that are accepted and kept but change nothing Tessel draws (colour-index
// logic op, multisampling, sRGB writes to a linear window).
// (The sample-coverage capabilities act only on multisample buffers, which Tessel's
// framebuffers do not have: GL 3.3 §4.1.3.)
bool* inert_capability(GLenum cap) {
  static bool inert[10] = {};
  switch (cap) {
    case GL_SAMPLE_ALPHA_TO_COVERAGE: return &inert[5];
    case GL_SAMPLE_ALPHA_TO_ONE: return &inert[6];
    case GL_SAMPLE_COVERAGE: return &inert[7];
    case GL_SAMPLE_MASK: return &inert[8];
    case GL_INDEX_LOGIC_OP: return &inert[1];
    case GL_MULTISAMPLE: return &inert[2];
    // The window is not sRGB.
    case GL_FRAMEBUFFER_SRGB: return &inert[4];
    default: return nullptr;
  }
}

// The capabilities of the core profile (GL 3.3 core, table 6.x "Enable"); the others are
// GL_INVALID_ENUM in a core context, as Mesa's are.
bool core_capability(GLenum cap) {
  if (cap >= GL_CLIP_DISTANCE0 && cap < GL_CLIP_DISTANCE0 + kMaxClipPlanes) return true;
  switch (cap) {
    case GL_BLEND:
    case GL_COLOR_LOGIC_OP:
    case GL_CULL_FACE:
    case GL_DEPTH_CLAMP:
    case GL_DEPTH_TEST:
    case GL_DITHER:
    case GL_FRAMEBUFFER_SRGB:
    case GL_LINE_SMOOTH:
    case GL_MULTISAMPLE:
    case GL_POLYGON_OFFSET_FILL:
    case GL_POLYGON_OFFSET_LINE:
    case GL_POLYGON_OFFSET_POINT:
    case GL_POLYGON_SMOOTH:
    case GL_PRIMITIVE_RESTART:
    case GL_PROGRAM_POINT_SIZE:
    case GL_RASTERIZER_DISCARD:
    case GL_SAMPLE_ALPHA_TO_COVERAGE:
    case GL_SAMPLE_ALPHA_TO_ONE:
    case GL_SAMPLE_COVERAGE:
    case GL_SAMPLE_MASK:
    case GL_SCISSOR_TEST:
    case GL_STENCIL_TEST:
    case GL_TEXTURE_CUBE_MAP_SEAMLESS: return true;
    default: return false;
  }
}

// The flag glEnable/glDisable/glIsEnabled name, for this context's profile (nullptr: none).
bool* enable_flag(Context& c, GLenum cap) {
  if (c.core_profile && !core_capability(cap)) return nullptr;
  bool* flag = capability(c, cap);
  return flag ? flag : inert_capability(cap);
}

void alpha_func(Context& c, GLenum func, float ref) {
  GL_OUTSIDE_BEGIN();
  if (func < GL_NEVER || func > GL_ALWAYS) return c.error(GL_INVALID_ENUM);
  c.touch();
  c.s.color.alpha_func = func;
  c.s.color.alpha_ref = std::clamp(ref, 0.0f, 1.0f);
}

bool valid_blend(GLenum f, bool src) {
  switch (f) {
    case GL_ZERO:
    case GL_ONE:
    case GL_SRC_ALPHA:
    case GL_ONE_MINUS_SRC_ALPHA:
    case GL_DST_ALPHA:
    case GL_ONE_MINUS_DST_ALPHA: return true;
    case GL_DST_COLOR:
    case GL_ONE_MINUS_DST_COLOR:
    case GL_SRC_COLOR:
    case GL_ONE_MINUS_SRC_COLOR:
    case GL_CONSTANT_COLOR:
    case GL_ONE_MINUS_CONSTANT_COLOR:
    case GL_CONSTANT_ALPHA:
    case GL_ONE_MINUS_CONSTANT_ALPHA:
    case GL_SRC1_COLOR:  // dual-source blending (GL 3.3 §4.1.8)
    case GL_ONE_MINUS_SRC1_COLOR:
    case GL_SRC1_ALPHA:
    case GL_ONE_MINUS_SRC1_ALPHA: return true;
    case GL_SRC_ALPHA_SATURATE: return src;
    default: return false;
  }
}

void blend_func(Context& c, GLenum sf, GLenum df, GLenum sfa, GLenum dfa) {
  GL_OUTSIDE_BEGIN();
  if (!valid_blend(sf, true) || !valid_blend(df, false) || !valid_blend(sfa, true) ||
      !valid_blend(dfa, false))
    return c.error(GL_INVALID_ENUM);
  c.touch();
  c.s.color.blend_src = sf;
  c.s.color.blend_dst = df;
  c.s.color.blend_src_alpha = sfa;
  c.s.color.blend_dst_alpha = dfa;
}

bool valid_blend_equation(GLenum e) {
  return e == GL_FUNC_ADD || e == GL_FUNC_SUBTRACT || e == GL_FUNC_REVERSE_SUBTRACT || e == GL_MIN ||
         e == GL_MAX;
}

void blend_equation(Context& c, GLenum rgb, GLenum alpha) {
  GL_OUTSIDE_BEGIN();
  if (!valid_blend_equation(rgb) || !valid_blend_equation(alpha)) return c.error(GL_INVALID_ENUM);
  c.touch();
  c.s.color.blend_eq = rgb;
  c.s.color.blend_eq_alpha = alpha;
}

void blend_color(Context& c, float r, float g, float b, float a) {
  GL_OUTSIDE_BEGIN();
  c.touch();
  c.s.color.blend_color = glm::clamp(glm::vec4(r, g, b, a), 0.0f, 1.0f);
}

void depth_func(Context& c, GLenum f) {
  GL_OUTSIDE_BEGIN();
  if (f < GL_NEVER || f > GL_ALWAYS) return c.error(GL_INVALID_ENUM);
  c.touch();
  c.s.depth.func = f;
}

bool valid_stencil_op(GLenum op) {
  return op == GL_KEEP || op == GL_ZERO || op == GL_REPLACE || op == GL_INCR || op == GL_DECR ||
         op == GL_INVERT || op == GL_INCR_WRAP || op == GL_DECR_WRAP;
}

// Which faces a glStencil*Separate call sets; false for a bad face (GL_INVALID_ENUM).
bool stencil_faces(GLenum face, bool& front, bool& back) {
  front = face == GL_FRONT || face == GL_FRONT_AND_BACK;
  back = face == GL_BACK || face == GL_FRONT_AND_BACK;
  return front || back;
}

void stencil_func(Context& c, GLenum face, GLenum f, GLint ref, GLuint mask) {
  GL_OUTSIDE_BEGIN();
  bool front, back;
  if (!stencil_faces(face, front, back) || f < GL_NEVER || f > GL_ALWAYS) return c.error(GL_INVALID_ENUM);
  c.touch();
  StencilState& st = c.s.stencil;
  if (front) st.func = f, st.ref = ref, st.value_mask = mask;
  if (back) st.back_func = f, st.back_ref = ref, st.back_value_mask = mask;
}

void stencil_op(Context& c, GLenum face, GLenum fail, GLenum zfail, GLenum zpass) {
  GL_OUTSIDE_BEGIN();
  bool front, back;
  if (!stencil_faces(face, front, back) || !valid_stencil_op(fail) || !valid_stencil_op(zfail) ||
      !valid_stencil_op(zpass))
    return c.error(GL_INVALID_ENUM);
  c.touch();
  StencilState& st = c.s.stencil;
  if (front) st.fail = fail, st.zfail = zfail, st.zpass = zpass;
  if (back) st.back_fail = fail, st.back_zfail = zfail, st.back_zpass = zpass;
}

void scissor(Context& c, GLint x, GLint y, GLsizei w, GLsizei h) {
  GL_OUTSIDE_BEGIN();
  if (w < 0 || h < 0) return c.error(GL_INVALID_VALUE);
  c.touch();
  c.s.scissor.x = x;
  c.s.scissor.y = y;
  c.s.scissor.width = w;
  c.s.scissor.height = h;
}

void cull_face(Context& c, GLenum mode) {
  GL_OUTSIDE_BEGIN();
  if (mode != GL_FRONT && mode != GL_BACK && mode != GL_FRONT_AND_BACK) return c.error(GL_INVALID_ENUM);
  c.touch();
  c.s.polygon.cull_face = mode;
}

void front_face(Context& c, GLenum mode) {
  GL_OUTSIDE_BEGIN();
  if (mode != GL_CW && mode != GL_CCW) return c.error(GL_INVALID_ENUM);
  c.touch();
  c.s.polygon.front_face = mode;
}

void polygon_mode(Context& c, GLenum face, GLenum mode) {
  GL_OUTSIDE_BEGIN();
  // The core profile has one mode for both faces (GL 3.2 core, appendix E.2.2).
  if ((face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) ||
      (c.core_profile && face != GL_FRONT_AND_BACK) ||
      (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL))
    return c.error(GL_INVALID_ENUM);
  c.touch();
  if (face != GL_BACK) c.s.polygon.mode_front = mode;
  if (face != GL_FRONT) c.s.polygon.mode_back = mode;
}

void polygon_offset(Context& c, float factor, float units) {
  GL_OUTSIDE_BEGIN();
  c.touch();
  c.s.polygon.offset_factor = factor;
  c.s.polygon.offset_units = units;
}

void line_width(Context& c, float w) {
  GL_OUTSIDE_BEGIN();
  if (!(w > 0.0f)) return c.error(GL_INVALID_VALUE);
  c.touch();
  c.s.line.width = w;
}

void point_size(Context& c, float s) {
  GL_OUTSIDE_BEGIN();
  if (!(s > 0.0f)) return c.error(GL_INVALID_VALUE);
  c.touch();
  c.s.point.size = s;
}

// glPointParameter*: `v` holds one value (three for GL_POINT_DISTANCE_ATTENUATION).
void point_parameter(Context& c, GLenum pname, const float* v) {
  GL_OUTSIDE_BEGIN();
  PointState& p = c.s.point;
  // The core profile keeps the fade threshold and the sprite origin (GL 3.3 core §3.4).
  if (c.core_profile && pname != GL_POINT_FADE_THRESHOLD_SIZE && pname != GL_POINT_SPRITE_COORD_ORIGIN)
    return c.error(GL_INVALID_ENUM);
  switch (pname) {
    case GL_POINT_SIZE_MIN:
    case GL_POINT_SIZE_MAX:
    case GL_POINT_FADE_THRESHOLD_SIZE:
      if (!(v[0] >= 0.0f)) return c.error(GL_INVALID_VALUE);
      c.touch();
      (pname == GL_POINT_SIZE_MIN   ? p.size_min
       : pname == GL_POINT_SIZE_MAX ? p.size_max
                                    : p.fade_threshold) = v[0];
      return;
    case GL_POINT_DISTANCE_ATTENUATION:
      c.touch();
      std::copy(v, v + 3, p.attenuation);
      return;
    case GL_POINT_SPRITE_COORD_ORIGIN:
      if (v[0] != float(GL_LOWER_LEFT) && v[0] != float(GL_UPPER_LEFT)) return c.error(GL_INVALID_VALUE);
      c.touch();
      p.sprite_lower_left = v[0] == float(GL_LOWER_LEFT);
      return;
    default: return c.error(GL_INVALID_ENUM);
  }
}

void line_stipple(Context& c, GLint factor, GLushort pattern) {
  GL_OUTSIDE_BEGIN();
  c.touch();
  c.s.line.stipple_factor = std::clamp(factor, 1, 256);
  c.s.line.stipple_pattern = pattern;
}

void polygon_stipple(Context& c, const std::array<uint32_t, 32>& rows) {
  GL_OUTSIDE_BEGIN();
  c.touch();
  c.s.polygon_stipple = rows;
}

void clip_plane(Context& c, GLenum plane, glm::dvec4 eq) {
  GL_OUTSIDE_BEGIN();
  if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + kMaxClipPlanes) return c.error(GL_INVALID_ENUM);
  c.touch();
  // GL 2.1 §2.12: the plane is transformed by the inverse of the model-view matrix.
  const glm::dmat4 inv = glm::inverse(glm::dmat4(c.modelview()));
  c.s.transform.clip_plane[plane - GL_CLIP_PLANE0] = eq * inv;
}

void color_mask(Context& c, bool r, bool g, bool b, bool a) {
  GL_OUTSIDE_BEGIN();
  c.touch();
  c.s.color.color_mask.fill({r, g, b, a});
}

void depth_mask(Context& c, bool m) {
  GL_OUTSIDE_BEGIN();
  c.touch();
  c.s.depth.mask = m;
}

void stencil_mask(Context& c, GLenum face, GLuint m) {
  GL_OUTSIDE_BEGIN();
  bool front, back;
  if (!stencil_faces(face, front, back)) return c.error(GL_INVALID_ENUM);
  c.touch();
  if (front) c.s.stencil.write_mask = m;
  if (back) c.s.stencil.back_write_mask = m;
}

void clear(Context& c, GLbitfield mask) {
  GL_OUTSIDE_BEGIN();
  // The accumulation buffer is not a core-profile bit (GL 3.3 core §4.2.3).
  const GLbitfield accum = c.core_profile ? 0 : GLbitfield(GL_ACCUM_BUFFER_BIT);
  if (mask & ~GLbitfield(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | accum))
    return c.error(GL_INVALID_VALUE);
  c.clear(mask);
  if (mask & GL_ACCUM_BUFFER_BIT) clear_accum_buffer(c);
}

void hint(Context& c, GLenum target, GLenum mode) {
  GL_OUTSIDE_BEGIN();
  if (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE) return c.error(GL_INVALID_ENUM);
  HintState& h = c.s.hint;
  // The core profile keeps the line and polygon smoothing, compression and derivative hints.
  if (c.core_profile && target != GL_LINE_SMOOTH_HINT && target != GL_POLYGON_SMOOTH_HINT &&
      target != GL_TEXTURE_COMPRESSION_HINT && target != GL_FRAGMENT_SHADER_DERIVATIVE_HINT)
    return c.error(GL_INVALID_ENUM);
  switch (target) {
    // Hints Tessel has no choice to make for (one compression, one derivative rule).
    case GL_TEXTURE_COMPRESSION_HINT:
    case GL_FRAGMENT_SHADER_DERIVATIVE_HINT: break;
    case GL_PERSPECTIVE_CORRECTION_HINT: h.perspective = mode; break;
    case GL_POINT_SMOOTH_HINT: h.point = mode; break;
    case GL_LINE_SMOOTH_HINT: h.line = mode; break;
    case GL_POLYGON_SMOOTH_HINT: h.polygon = mode; break;
    case GL_FOG_HINT: h.fog = mode; break;
    case GL_GENERATE_MIPMAP_HINT: break;
    default: c.error(GL_INVALID_ENUM); break;
  }
}

bool window_buffer(GLenum b) {
  return b == GL_FRONT || b == GL_BACK || b == GL_FRONT_AND_BACK || b == GL_LEFT || b == GL_RIGHT ||
         b == GL_FRONT_LEFT || b == GL_FRONT_RIGHT || b == GL_BACK_LEFT || b == GL_BACK_RIGHT || b == GL_AUX0;
}

// The error of naming `b` as the draw or read buffer of a framebuffer object (GL 3.3 §4.2.1,
// §4.3.3): GL_NONE and GL_COLOR_ATTACHMENTi are fine; a window's buffer or an attachment
// past the last is GL_INVALID_OPERATION; anything else GL_INVALID_ENUM.
GLenum fbo_buffer_error(GLenum b) {
  if (b == GL_NONE) return GL_NO_ERROR;
  if (b >= GL_COLOR_ATTACHMENT0 && b < GL_COLOR_ATTACHMENT0 + 16)
    return b < GL_COLOR_ATTACHMENT0 + kMaxColorAttachments ? GL_NO_ERROR : GL_INVALID_OPERATION;
  return window_buffer(b) ? GL_INVALID_OPERATION : GL_INVALID_ENUM;
}

void draw_buffer(Context& c, GLenum b) {
  GL_OUTSIDE_BEGIN();
  if (c.draw_fbo) {
    // A framebuffer object draws to one attachment, or none (GL 3.3 §4.2.1).
    if (const GLenum e = fbo_buffer_error(b); e != GL_NO_ERROR) return c.error(e);
    c.touch();
    c.draw_fbo->draw_buffers = {b};
    return;
  }
  if (b == GL_NONE) {
    c.touch();
    c.s.color.draw_buffer = b;
    return;
  }
  // An attachment named for the default framebuffer is GL_INVALID_OPERATION (GL 4.6 §17.4.1,
  // as Mesa answers); any other non-window name GL_INVALID_ENUM.
  if (b >= GL_COLOR_ATTACHMENT0 && b < GL_COLOR_ATTACHMENT0 + 16) return c.error(GL_INVALID_OPERATION);
  if (!window_buffer(b)) return c.error(GL_INVALID_ENUM);
  if (!c.color_buffer(b)) return c.error(GL_INVALID_OPERATION);
  c.touch();
  c.s.color.draw_buffer = b;
}

void read_buffer(Context& c, GLenum b) {
  GL_OUTSIDE_BEGIN();
  if (c.read_fbo) {
    if (const GLenum e = fbo_buffer_error(b); e != GL_NO_ERROR) return c.error(e);
    c.read_fbo->read_buffer = b;
    return;
  }
  if (b == GL_NONE) {
    c.s.pixel.read_buffer = b;
    return;
  }
  if (b >= GL_COLOR_ATTACHMENT0 && b < GL_COLOR_ATTACHMENT0 + 16) return c.error(GL_INVALID_OPERATION);
  if (!window_buffer(b) || b == GL_FRONT_AND_BACK) return c.error(GL_INVALID_ENUM);
  if (!c.color_buffer(b)) return c.error(GL_INVALID_OPERATION);
  c.s.pixel.read_buffer = b;
}

// --- display lists (GL 2.1 §5.4) ---

void new_list(Context& c, GLuint list, GLenum mode) {
  GL_OUTSIDE_BEGIN();
  if (list == 0) return c.error(GL_INVALID_VALUE);
  if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE) return c.error(GL_INVALID_ENUM);
  if (c.compiling_list != 0) return c.error(GL_INVALID_OPERATION);
  c.touch();
  c.compiling_list = list;
  c.compile_mode = mode;
  c.compiling.clear();
}

void end_list(Context& c) {
  GL_OUTSIDE_BEGIN();
  if (c.compiling_list == 0) return c.error(GL_INVALID_OPERATION);
  c.lists[c.compiling_list] = std::move(c.compiling);
  c.compiling.clear();
  c.compiling_list = 0;
}

}  // namespace

void call_list(Context& c, GLuint list) {
  auto it = c.lists.find(list);
  if (it == c.lists.end()) return;
  if (c.list_depth >= kMaxListNesting) return;  // GL 2.1 §5.4: nesting is limited (MAX_LIST_NESTING)
  ++c.list_depth;
  // The list may be replaced or deleted by its own commands: run a copy.
  const std::vector<ListCommand> cmds = it->second;
  for (const ListCommand& cmd : cmds) cmd();
  --c.list_depth;
}

void enable(Context& c, GLenum cap, bool on) {
  GL_OUTSIDE_BEGIN();
  bool* flag = enable_flag(c, cap);
  if (!flag) return c.error(GL_INVALID_ENUM);
  if (cap == GL_BLEND) {
    c.touch();
    c.s.color.blend.fill(on);  // every draw buffer (GL 3.3 §4.1.8)
    return;
  }
  if (*flag == on) return;
  c.touch();
  *flag = on;
}

namespace {

// --- glPushAttrib / glPopAttrib (GL 2.1 §6.1.14, Table 6.3 onward) ---

void copy_enables(ServerState& to, const ServerState& from) {
  to.color.alpha_test = from.color.alpha_test;
  to.light.color_material = from.light.color_material;
  to.polygon.cull = from.polygon.cull;
  to.depth.test = from.depth.test;
  to.color.dither = from.color.dither;
  to.fog.enabled = from.fog.enabled;
  to.fog.color_sum = from.fog.color_sum;
  to.point.sprite = from.point.sprite;
  to.light.enabled = from.light.enabled;
  to.light.lighting = from.light.lighting;
  to.line.smooth = from.line.smooth;
  to.line.stipple = from.line.stipple;
  to.color.logic_op = from.color.logic_op;
  to.transform.normalize = from.transform.normalize;
  to.transform.rescale_normal = from.transform.rescale_normal;
  to.point.smooth = from.point.smooth;
  to.polygon.offset_fill = from.polygon.offset_fill;
  to.polygon.offset_line = from.polygon.offset_line;
  to.polygon.offset_point = from.polygon.offset_point;
  to.polygon.smooth = from.polygon.smooth;
  to.polygon.stipple = from.polygon.stipple;
  to.scissor.test = from.scissor.test;
  to.stencil.test = from.stencil.test;
  for (size_t i = 0; i < to.units.size(); ++i) {
    to.units[i].enabled_1d = from.units[i].enabled_1d;
    to.units[i].enabled_2d = from.units[i].enabled_2d;
    to.units[i].enabled_3d = from.units[i].enabled_3d;
    to.units[i].enabled_cube = from.units[i].enabled_cube;
    to.units[i].gen_enabled = from.units[i].gen_enabled;
  }
  to.transform.clip_enabled = from.transform.clip_enabled;
  to.color.blend = from.color.blend;
  to.eval.map1_enabled = from.eval.map1_enabled;
  to.eval.map2_enabled = from.eval.map2_enabled;
  to.eval.auto_normal = from.eval.auto_normal;
}

void restore(ServerState& s, const ServerState& o, GLbitfield m) {
  if (m & GL_CURRENT_BIT) s.current = o.current;
  if (m & GL_LIGHTING_BIT) s.light = o.light;
  if (m & GL_FOG_BIT) s.fog = o.fog;
  if (m & GL_COLOR_BUFFER_BIT) {
    const auto logic = s.color.logic_op;
    s.color = o.color;
    if (!(m & GL_ENABLE_BIT)) s.color.logic_op = logic;
  }
  if (m & GL_DEPTH_BUFFER_BIT) s.depth = o.depth;
  if (m & GL_STENCIL_BUFFER_BIT) s.stencil = o.stencil;
  if (m & GL_POLYGON_BIT) s.polygon = o.polygon;
  if (m & GL_POLYGON_STIPPLE_BIT) s.polygon_stipple = o.polygon_stipple;
  if (m & GL_LINE_BIT) s.line = o.line;
  if (m & GL_POINT_BIT) s.point = o.point;
  if (m & GL_SCISSOR_BIT) s.scissor = o.scissor;
  if (m & GL_VIEWPORT_BIT) s.viewport = o.viewport;
  if (m & GL_TRANSFORM_BIT) s.transform = o.transform;
  if (m & GL_TEXTURE_BIT) {
    s.units = o.units;
    s.active_unit = o.active_unit;
  }
  if (m & GL_HINT_BIT) s.hint = o.hint;
  if (m & GL_PIXEL_MODE_BIT) s.pixel = o.pixel;
  if (m & GL_LIST_BIT) s.list_base = o.list_base;
  if (m & GL_ACCUM_BUFFER_BIT) s.accum_clear = o.accum_clear;
  if (m & GL_EVAL_BIT) s.eval = o.eval;
  if (m & GL_ENABLE_BIT) copy_enables(s, o);
}

void push_attrib(Context& c, GLbitfield mask) {
  GL_OUTSIDE_BEGIN();
  if (int(c.attrib_stack.size()) >= kAttribDepth) return c.error(GL_STACK_OVERFLOW);
  c.attrib_stack.push_back({mask, c.s});
}

void pop_attrib(Context& c) {
  GL_OUTSIDE_BEGIN();
  if (c.attrib_stack.empty()) return c.error(GL_STACK_UNDERFLOW);
  c.touch();
  const PushedAttrib top = std::move(c.attrib_stack.back());
  c.attrib_stack.pop_back();
  restore(c.s, top.state, top.mask);
}

}  // namespace
}  // namespace tessel::gl

using namespace tessel::gl;

#define SIMPLE(fn, ...)          \
  GL_CONTEXT();                  \
  GL_LISTED(fn(c, __VA_ARGS__)); \
  fn(c, __VA_ARGS__)

extern "C" {

GLenum GLAPIENTRY glGetError(void) {
  GL_CONTEXT(GLenum(GL_NO_ERROR));
  if (c.in_begin) {
    c.error(GL_INVALID_OPERATION);
    return GL_INVALID_OPERATION;
  }
  return c.take_error();
}

const GLubyte* GLAPIENTRY glGetString(GLenum name) {
  GL_CONTEXT(nullptr);
  if (c.in_begin) {
    c.error(GL_INVALID_OPERATION);
    return nullptr;
  }
  switch (name) {
    case GL_VENDOR: return reinterpret_cast<const GLubyte*>("Tessel");
    case GL_RENDERER: return reinterpret_cast<const GLubyte*>("Tessel software rasterizer (CPU)");
    case GL_VERSION: return reinterpret_cast<const GLubyte*>(c.version_string().c_str());
    case GL_SHADING_LANGUAGE_VERSION:
      return reinterpret_cast<const GLubyte*>(c.glsl_version_string().c_str());
    case GL_EXTENSIONS:
      // A core context lists its extensions with glGetStringi only (GL 3.3 core §6.1.5).
      if (c.core_profile) break;
      return reinterpret_cast<const GLubyte*>(c.extension_string().c_str());
    default: break;
  }
  c.error(GL_INVALID_ENUM);
  return nullptr;
}

const GLubyte* GLAPIENTRY glGetStringi(GLenum name, GLuint index) {
  GL_CONTEXT(nullptr);
  GL_OUTSIDE_BEGIN(nullptr);
  if (name != GL_EXTENSIONS) {
    c.error(GL_INVALID_ENUM);
    return nullptr;
  }
  const auto& list = extensions(c);
  if (index >= list.size()) {
    c.error(GL_INVALID_VALUE);
    return nullptr;
  }
  return reinterpret_cast<const GLubyte*>(list[index]);
}

void GLAPIENTRY glEnable(GLenum cap) { SIMPLE(enable, cap, true); }
void GLAPIENTRY glDisable(GLenum cap) { SIMPLE(enable, cap, false); }
GLboolean GLAPIENTRY glIsEnabled(GLenum cap) {
  GL_CONTEXT(GLboolean(GL_FALSE));
  GL_OUTSIDE_BEGIN(GLboolean(GL_FALSE));
  bool* flag = enable_flag(c, cap);
  if (!flag) {
    // Client-state arrays are queried with glIsEnabled too (not in a core context).
    switch (c.core_profile ? GLenum(0) : cap) {
      case GL_VERTEX_ARRAY: return c.c.vertex.enabled;
      case GL_NORMAL_ARRAY: return c.c.normal.enabled;
      case GL_COLOR_ARRAY: return c.c.color.enabled;
      case GL_TEXTURE_COORD_ARRAY: return c.c.active_tex().enabled;
      case GL_SECONDARY_COLOR_ARRAY: return c.c.secondary.enabled;
      case GL_FOG_COORD_ARRAY: return c.c.fog.enabled;
      case GL_EDGE_FLAG_ARRAY: return c.c.edge.enabled;
      case GL_INDEX_ARRAY: return c.c.index.enabled;
      default: c.error(GL_INVALID_ENUM); return GL_FALSE;
    }
  }
  return *flag ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY glAlphaFunc(GLenum func, GLclampf ref) {
  GL_REMOVED_IN_CORE();
  SIMPLE(alpha_func, func, ref);
}
void GLAPIENTRY glBlendFunc(GLenum s, GLenum d) { SIMPLE(blend_func, s, d, s, d); }
void GLAPIENTRY glBlendFuncSeparate(GLenum s, GLenum d, GLenum sa, GLenum da) {
  SIMPLE(blend_func, s, d, sa, da);
}
void GLAPIENTRY glBlendEquation(GLenum e) { SIMPLE(blend_equation, e, e); }
void GLAPIENTRY glBlendEquationSeparate(GLenum rgb, GLenum alpha) { SIMPLE(blend_equation, rgb, alpha); }
void GLAPIENTRY glBlendColor(GLfloat r, GLfloat g, GLfloat b, GLfloat a) { SIMPLE(blend_color, r, g, b, a); }
void GLAPIENTRY glDepthFunc(GLenum f) { SIMPLE(depth_func, f); }
void GLAPIENTRY glDepthMask(GLboolean m) { SIMPLE(depth_mask, m != GL_FALSE); }
void GLAPIENTRY glStencilFunc(GLenum f, GLint ref, GLuint mask) {
  SIMPLE(stencil_func, GL_FRONT_AND_BACK, f, ref, mask);
}
void GLAPIENTRY glStencilFuncSeparate(GLenum face, GLenum f, GLint ref, GLuint mask) {
  SIMPLE(stencil_func, face, f, ref, mask);
}
void GLAPIENTRY glStencilOpSeparate(GLenum face, GLenum fail, GLenum zfail, GLenum zpass) {
  SIMPLE(stencil_op, face, fail, zfail, zpass);
}
void GLAPIENTRY glStencilMaskSeparate(GLenum face, GLuint m) { SIMPLE(stencil_mask, face, m); }
void GLAPIENTRY glStencilOp(GLenum fail, GLenum zfail, GLenum zpass) {
  SIMPLE(stencil_op, GL_FRONT_AND_BACK, fail, zfail, zpass);
}
void GLAPIENTRY glStencilMask(GLuint m) { SIMPLE(stencil_mask, GL_FRONT_AND_BACK, m); }
void GLAPIENTRY glScissor(GLint x, GLint y, GLsizei w, GLsizei h) { SIMPLE(scissor, x, y, w, h); }
void GLAPIENTRY glCullFace(GLenum mode) { SIMPLE(cull_face, mode); }
void GLAPIENTRY glFrontFace(GLenum mode) { SIMPLE(front_face, mode); }
void GLAPIENTRY glPolygonMode(GLenum face, GLenum mode) { SIMPLE(polygon_mode, face, mode); }
void GLAPIENTRY glPolygonOffset(GLfloat factor, GLfloat units) { SIMPLE(polygon_offset, factor, units); }
void GLAPIENTRY glLineWidth(GLfloat w) { SIMPLE(line_width, w); }
void GLAPIENTRY glPointSize(GLfloat s) { SIMPLE(point_size, s); }
void GLAPIENTRY glPointParameterf(GLenum pname, GLfloat param) {
  const float v[3] = {param, 0.0f, 0.0f};
  GL_CONTEXT();
  // (One value of GL_POINT_DISTANCE_ATTENUATION is not a call the specification has.)
  if (pname == GL_POINT_DISTANCE_ATTENUATION) return c.error(GL_INVALID_ENUM);
  GL_LISTED(point_parameter(c, pname, v));
  point_parameter(c, pname, v);
}
void GLAPIENTRY glPointParameterfv(GLenum pname, const GLfloat* params) {
  GL_CONTEXT();
  if (!params) return c.error(GL_INVALID_VALUE);
  float v[3] = {params[0], 0.0f, 0.0f};
  if (pname == GL_POINT_DISTANCE_ATTENUATION) v[1] = params[1], v[2] = params[2];
  GL_LISTED(point_parameter(c, pname, v));
  point_parameter(c, pname, v);
}
void GLAPIENTRY glPointParameteri(GLenum pname, GLint param) {
  const float v[3] = {float(param), 0.0f, 0.0f};
  GL_CONTEXT();
  if (pname == GL_POINT_DISTANCE_ATTENUATION) return c.error(GL_INVALID_ENUM);
  GL_LISTED(point_parameter(c, pname, v));
  point_parameter(c, pname, v);
}
void GLAPIENTRY glPointParameteriv(GLenum pname, const GLint* params) {
  GL_CONTEXT();
  if (!params) return c.error(GL_INVALID_VALUE);
  float v[3] = {float(params[0]), 0.0f, 0.0f};
  if (pname == GL_POINT_DISTANCE_ATTENUATION) v[1] = float(params[1]), v[2] = float(params[2]);
  GL_LISTED(point_parameter(c, pname, v));
  point_parameter(c, pname, v);
}
void GLAPIENTRY glLineStipple(GLint factor, GLushort pattern) {
  GL_REMOVED_IN_CORE();
  SIMPLE(line_stipple, factor, pattern);
}
void GLAPIENTRY glPolygonStipple(const GLubyte* mask) {
  GL_COMPAT_CONTEXT();
  // A 32x32 bitmap unpacked with the unpack state (GL 2.1 §3.5.2): bit (x, y) of row y.
  std::array<uint32_t, 32> rows{};
  if (mask) {
    std::vector<uint8_t> bits;
    unpack_bitmap(c.c.unpack, 32, 32, mask, bits);
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x)
        if (bits[size_t(y * 32 + x)]) rows[size_t(y)] |= 1u << x;
  }
  GL_LISTED(polygon_stipple(c, rows));
  polygon_stipple(c, rows);
}
void GLAPIENTRY glGetPolygonStipple(GLubyte* mask) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!mask) return;
  // Packed with the pack state as a bitmap: MSB first unless LSB_FIRST.
  const PixelLayout L = pixel_layout(c.c.pack, 32, GL_COLOR_INDEX, GL_BITMAP);
  for (int y = 0; y < 32; ++y) {
    uint8_t* row = mask + L.offset + size_t(y) * L.row_stride;
    for (int x = 0; x < 32; ++x) {
      const int bit = x + c.c.pack.skip_pixels;
      const int shift = c.c.pack.lsb_first ? (bit % 8) : (7 - bit % 8);
      uint8_t& b = row[bit / 8];
      if ((c.s.polygon_stipple[size_t(y)] >> x) & 1u)
        b = uint8_t(b | (1u << shift));
      else
        b = uint8_t(b & ~(1u << shift));
    }
  }
}
void GLAPIENTRY glClipPlane(GLenum plane, const GLdouble* eq) {
  GL_REMOVED_IN_CORE();
  const glm::dvec4 e = eq ? glm::dvec4(eq[0], eq[1], eq[2], eq[3]) : glm::dvec4(0.0);
  SIMPLE(clip_plane, plane, e);
}
void GLAPIENTRY glGetClipPlane(GLenum plane, GLdouble* eq) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + kMaxClipPlanes) return c.error(GL_INVALID_ENUM);
  const glm::dvec4& p = c.s.transform.clip_plane[plane - GL_CLIP_PLANE0];
  if (eq) eq[0] = p.x, eq[1] = p.y, eq[2] = p.z, eq[3] = p.w;
}
void GLAPIENTRY glColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
  SIMPLE(color_mask, r != GL_FALSE, g != GL_FALSE, b != GL_FALSE, a != GL_FALSE);
}
void GLAPIENTRY glClearColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) {
  // Kept as given (GL 3.0 §4.2.3): fixed-point buffers clamp when cleared, float ones do not.
  const glm::vec4 v(r, g, b, a);
  GL_CONTEXT();
  auto set = [v](Context& c) {
    GL_OUTSIDE_BEGIN();
    c.s.color.clear_color = v;
  };
  GL_LISTED(set(c));
  set(c);
}
void GLAPIENTRY glClearDepth(GLclampd d) {
  const double v = std::clamp(d, 0.0, 1.0);
  GL_CONTEXT();
  auto set = [v](Context& c) {
    GL_OUTSIDE_BEGIN();
    c.s.depth.clear = v;
  };
  GL_LISTED(set(c));
  set(c);
}
void GLAPIENTRY glClearStencil(GLint s) {
  GL_CONTEXT();
  auto set = [s](Context& c) {
    GL_OUTSIDE_BEGIN();
    c.s.stencil.clear = s;
  };
  GL_LISTED(set(c));
  set(c);
}
void GLAPIENTRY glClearAccum(GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  GL_REMOVED_IN_CORE();
  const glm::vec4 v = glm::clamp(glm::vec4(r, g, b, a), -1.0f, 1.0f);
  GL_CONTEXT();
  auto set = [v](Context& c) {
    GL_OUTSIDE_BEGIN();
    c.s.accum_clear = v;
  };
  GL_LISTED(set(c));
  set(c);
}
void GLAPIENTRY glClearIndex(GLfloat) { GL_REMOVED_IN_CORE(); }
void GLAPIENTRY glClear(GLbitfield mask) { SIMPLE(clear, mask); }
void GLAPIENTRY glSampleCoverage(GLfloat value, GLboolean invert) {
  GL_CONTEXT();
  auto set = [value, invert](Context& c) {
    GL_OUTSIDE_BEGIN();
    c.s.color.coverage_value = std::isnan(value) ? 0.0f : std::clamp(value, 0.0f, 1.0f);
    c.s.color.coverage_invert = invert != GL_FALSE;
  };
  GL_LISTED(set(c));
  set(c);
}
void GLAPIENTRY glHint(GLenum target, GLenum mode) { SIMPLE(hint, target, mode); }
void GLAPIENTRY glDrawBuffer(GLenum b) { SIMPLE(draw_buffer, b); }
void GLAPIENTRY glReadBuffer(GLenum b) { SIMPLE(read_buffer, b); }
void GLAPIENTRY glLogicOp(GLenum op) {
  GL_CONTEXT();
  auto set = [op](Context& c) {
    GL_OUTSIDE_BEGIN();
    if (op < GL_CLEAR || op > GL_SET) return c.error(GL_INVALID_ENUM);
    c.touch();
    c.s.color.logic_op_mode = op;
  };
  GL_LISTED(set(c));
  set(c);
}

void GLAPIENTRY glFlush(void) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  c.finish();
}
void GLAPIENTRY glFinish(void) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  c.finish();
}

void GLAPIENTRY glNewList(GLuint list, GLenum mode) {
  GL_COMPAT_CONTEXT();
  new_list(c, list, mode);
}
void GLAPIENTRY glEndList(void) {
  GL_COMPAT_CONTEXT();
  end_list(c);
}
void GLAPIENTRY glCallList(GLuint list) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(call_list(c, list));
  call_list(c, list);
}
void GLAPIENTRY glCallLists(GLsizei n, GLenum type, const GLvoid* lists) {
  GL_COMPAT_CONTEXT();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  std::vector<GLuint> names;
  const auto* b = static_cast<const uint8_t*>(lists);
  auto at = [&](int i, int k) { return GLuint(b[i * k]); };
  switch (type) {
    case GL_BYTE:
      for (int i = 0; i < n; ++i) names.push_back(GLuint(GLint(int8_t(b[i]))));
      break;
    case GL_UNSIGNED_BYTE:
      for (int i = 0; i < n; ++i) names.push_back(b[i]);
      break;
    case GL_SHORT:
      for (int i = 0; i < n; ++i) {
        int16_t v;
        std::memcpy(&v, b + 2 * i, 2);
        names.push_back(GLuint(GLint(v)));
      }
      break;
    case GL_UNSIGNED_SHORT:
      for (int i = 0; i < n; ++i) {
        uint16_t v;
        std::memcpy(&v, b + 2 * i, 2);
        names.push_back(v);
      }
      break;
    case GL_INT:
    case GL_UNSIGNED_INT:
      for (int i = 0; i < n; ++i) {
        uint32_t v;
        std::memcpy(&v, b + 4 * i, 4);
        names.push_back(v);
      }
      break;
    case GL_FLOAT:
      for (int i = 0; i < n; ++i) {
        float v;
        std::memcpy(&v, b + 4 * i, 4);
        names.push_back(GLuint(GLint(v)));
      }
      break;
    case GL_2_BYTES:
      for (int i = 0; i < n; ++i) names.push_back(at(2 * i, 1) * 256 + at(2 * i + 1, 1));
      break;
    case GL_3_BYTES:
      for (int i = 0; i < n; ++i)
        names.push_back((at(3 * i, 1) << 16) + (at(3 * i + 1, 1) << 8) + at(3 * i + 2, 1));
      break;
    case GL_4_BYTES:
      for (int i = 0; i < n; ++i)
        names.push_back((at(4 * i, 1) << 24) + (at(4 * i + 1, 1) << 16) + (at(4 * i + 2, 1) << 8) +
                        at(4 * i + 3, 1));
      break;
    default: return c.error(GL_INVALID_ENUM);
  }
  auto run = [names](Context& c) {
    for (GLuint name : names) call_list(c, name + c.s.list_base);
  };
  GL_LISTED(run(c));
  run(c);
}
void GLAPIENTRY glListBase(GLuint base) {
  GL_COMPAT_CONTEXT();
  auto set = [base](Context& c) {
    GL_OUTSIDE_BEGIN();
    c.s.list_base = base;
  };
  GL_LISTED(set(c));
  set(c);
}
GLuint GLAPIENTRY glGenLists(GLsizei range) {
  GL_COMPAT_CONTEXT(0u);
  GL_OUTSIDE_BEGIN(0u);
  if (range < 0) {
    c.error(GL_INVALID_VALUE);
    return 0;
  }
  if (range == 0) return 0;
  // Names are reserved one by one: more than this many at once is more memory than a
  // program can mean to use (GL 2.1 §2.5, OUT_OF_MEMORY).
  if (range > (1 << 24)) {
    c.error(GL_OUT_OF_MEMORY);
    return 0;
  }
  // The first name of `range` consecutive unused names.
  GLuint start = 1;
  for (;;) {
    GLuint k = 0;
    while (k < GLuint(range) && !c.lists.count(start + k)) ++k;
    if (k == GLuint(range)) break;
    start += k + 1;
    if (start > 0xFFFFFFFFu - GLuint(range)) {
      c.error(GL_OUT_OF_MEMORY);
      return 0;
    }
  }
  for (GLuint k = 0; k < GLuint(range); ++k) c.lists[start + k];  // reserved, empty
  return start;
}
void GLAPIENTRY glDeleteLists(GLuint list, GLsizei range) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (range < 0) return c.error(GL_INVALID_VALUE);
  for (GLsizei k = 0; k < range; ++k) c.lists.erase(list + GLuint(k));
}
GLboolean GLAPIENTRY glIsList(GLuint list) {
  GL_COMPAT_CONTEXT(GLboolean(GL_FALSE));
  GL_OUTSIDE_BEGIN(GLboolean(GL_FALSE));
  return c.lists.count(list) ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY glPushAttrib(GLbitfield mask) {
  GL_REMOVED_IN_CORE();
  SIMPLE(push_attrib, mask);
}
void GLAPIENTRY glPopAttrib(void) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(pop_attrib(c));
  pop_attrib(c);
}
void GLAPIENTRY glPushClientAttrib(GLbitfield mask) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (int(c.client_stack.size()) >= kClientAttribDepth) return c.error(GL_STACK_OVERFLOW);
  c.client_stack.push_back({mask, c.c});
}
void GLAPIENTRY glPopClientAttrib(void) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (c.client_stack.empty()) return c.error(GL_STACK_UNDERFLOW);
  const PushedClient top = c.client_stack.back();
  c.client_stack.pop_back();
  if (top.mask & GL_CLIENT_PIXEL_STORE_BIT) {
    c.c.pack = top.state.pack;
    c.c.unpack = top.state.unpack;
  }
  if (top.mask & GL_CLIENT_VERTEX_ARRAY_BIT) {
    c.c.vertex = top.state.vertex;
    c.c.normal = top.state.normal;
    c.c.color = top.state.color;
    c.c.tex = top.state.tex;
    c.c.secondary = top.state.secondary;
    c.c.fog = top.state.fog;
    c.c.edge = top.state.edge;
    c.c.index = top.state.index;
    c.c.client_active_unit = top.state.client_active_unit;  // GL 2.1 Table 6.8
  }
}

}  // extern "C"
