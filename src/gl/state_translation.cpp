// GL state into the gpu layer's terms: the RenderState of a draw or clear (viewport, culling,
// polygon modes, clip planes in clip space, depth, stencil, blending, masks), the fixed-function
// shader's uniforms (matrices, lights, material, fog, texture environment) and the texture
// and sampler a fixed-function draw reads.
#include "context.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_inverse.hpp>

namespace tessel::gl {

namespace {

gpu::StencilOp stencil_op_of(GLenum op) {
  switch (op) {
    case GL_ZERO: return gpu::StencilOp::Zero;
    case GL_REPLACE: return gpu::StencilOp::Replace;
    case GL_INCR: return gpu::StencilOp::Incr;
    case GL_DECR: return gpu::StencilOp::Decr;
    case GL_INVERT: return gpu::StencilOp::Invert;
    case GL_INCR_WRAP: return gpu::StencilOp::IncrWrap;
    case GL_DECR_WRAP: return gpu::StencilOp::DecrWrap;
    default: return gpu::StencilOp::Keep;
  }
}

gpu::BlendFactor blend_of(GLenum f) {
  using B = gpu::BlendFactor;
  switch (f) {
    case GL_ZERO: return B::Zero;
    case GL_ONE: return B::One;
    case GL_SRC_COLOR: return B::SrcColor;
    case GL_ONE_MINUS_SRC_COLOR: return B::OneMinusSrcColor;
    case GL_DST_COLOR: return B::DstColor;
    case GL_ONE_MINUS_DST_COLOR: return B::OneMinusDstColor;
    case GL_SRC_ALPHA: return B::SrcAlpha;
    case GL_ONE_MINUS_SRC_ALPHA: return B::OneMinusSrcAlpha;
    case GL_DST_ALPHA: return B::DstAlpha;
    case GL_ONE_MINUS_DST_ALPHA: return B::OneMinusDstAlpha;
    case GL_SRC_ALPHA_SATURATE: return B::SrcAlphaSaturate;
    case GL_CONSTANT_COLOR: return B::ConstantColor;
    case GL_ONE_MINUS_CONSTANT_COLOR: return B::OneMinusConstantColor;
    case GL_CONSTANT_ALPHA: return B::ConstantAlpha;
    case GL_ONE_MINUS_CONSTANT_ALPHA: return B::OneMinusConstantAlpha;
    case GL_SRC1_COLOR: return B::Src1Color;
    case GL_ONE_MINUS_SRC1_COLOR: return B::OneMinusSrc1Color;
    case GL_SRC1_ALPHA: return B::Src1Alpha;
    case GL_ONE_MINUS_SRC1_ALPHA: return B::OneMinusSrc1Alpha;
    default: return B::One;
  }
}

gpu::PolygonMode polygon_mode_of(GLenum m) {
  return m == GL_LINE    ? gpu::PolygonMode::Line
         : m == GL_POINT ? gpu::PolygonMode::Point
                         : gpu::PolygonMode::Fill;
}

}  // namespace

std::array<uint8_t, 2> color_material_track(const LightState& L) {
  std::array<uint8_t, 2> track{};
  if (!L.color_material) return track;
  uint8_t bits = 0;
  switch (L.color_material_mode) {
    case GL_AMBIENT: bits = kTrackAmbient; break;
    case GL_DIFFUSE: bits = kTrackDiffuse; break;
    case GL_SPECULAR: bits = kTrackSpecular; break;
    case GL_EMISSION: bits = kTrackEmission; break;
    default: bits = kTrackAmbient | kTrackDiffuse; break;
  }
  if (L.color_material_face != GL_BACK) track[0] = bits;
  if (L.color_material_face != GL_FRONT) track[1] = bits;
  return track;
}

float rescale_factor(const glm::mat4& modelview) {
  // GL 2.1 §2.11.3: f = 1 / sqrt(m31^2 + m32^2 + m33^2) of the inverse model-view matrix.
  const glm::mat3 inv = glm::inverse(glm::mat3(modelview));
  const float l = std::sqrt(inv[0][2] * inv[0][2] + inv[1][2] * inv[1][2] + inv[2][2] * inv[2][2]);
  return l > 0.0f ? 1.0f / l : 1.0f;
}

// The base format the texture environment sees (GL 3.3 compatibility Table 3.25: RED and
// RG act as RGB; depth textures as their GL_DEPTH_TEXTURE_MODE says).
BaseFormat ff_base_format(const TextureObject& t) {
  switch (t.base_image().fmt.base) {
    case TexBase::Alpha: return BaseFormat::Alpha;
    case TexBase::Luminance: return BaseFormat::Luminance;
    case TexBase::LuminanceAlpha: return BaseFormat::LuminanceAlpha;
    case TexBase::Intensity: return BaseFormat::Intensity;
    case TexBase::RGBA: return BaseFormat::RGBA;
    case TexBase::Depth:
    case TexBase::DepthStencil:
      return t.depth_mode == GL_LUMINANCE   ? BaseFormat::Luminance
             : t.depth_mode == GL_INTENSITY ? BaseFormat::Intensity
             : t.depth_mode == GL_ALPHA     ? BaseFormat::Alpha
                                            : BaseFormat::RGB;
    default: return BaseFormat::RGB;
  }
}

gpu::CompareFunc compare_of(GLenum f) {
  switch (f) {
    case GL_NEVER: return gpu::CompareFunc::Never;
    case GL_LESS: return gpu::CompareFunc::Less;
    case GL_EQUAL: return gpu::CompareFunc::Equal;
    case GL_LEQUAL: return gpu::CompareFunc::LessEqual;
    case GL_GREATER: return gpu::CompareFunc::Greater;
    case GL_NOTEQUAL: return gpu::CompareFunc::NotEqual;
    case GL_GEQUAL: return gpu::CompareFunc::GreaterEqual;
    default: return gpu::CompareFunc::Always;
  }
}

TextureObject* Context::texture_for_draw() {
  TexTarget target = TexTarget::T2D;
  TextureObject* t = ff_texture(0, target);
  return t && target == TexTarget::T2D ? t : nullptr;
}

const SamplerParams& Context::sampler_params(int unit, const TextureObject& t) const {
  const SamplerRef& so = s.units[size_t(unit)].sampler;
  return so ? so->p : t.sampler;
}

void Context::build_uniforms(FFUniforms& u, TextureObject* tex) const {
  const glm::mat4& mv = modelview();
  u.modelview = mv;
  u.mvp = projection() * mv;
  const glm::mat3 inv = glm::inverse(glm::mat3(mv));
  u.normal_matrix = glm::transpose(inv);
  u.normalize = s.transform.normalize;
  u.rescale = s.transform.rescale_normal && !s.transform.normalize ? rescale_factor(mv) : 1.0f;
  const LightState& L = s.light;
  u.lighting = L.lighting;
  if (u.lighting) {
    u.two_side = L.two_side;
    u.local_viewer = L.local_viewer;
    u.model_ambient = L.model_ambient;
    u.material = L.material;
    u.light_count = 0;
    for (int i = 0; i < kMaxLights; ++i)
      if (L.enabled[size_t(i)]) u.lights[size_t(u.light_count++)] = L.light[size_t(i)];
    u.track = color_material_track(L);
  }
  if (tex) {
    u.sampler.texture = tex->tex2d.get();
    u.sampler.state = sampler_state_of(sampler_params(0, *tex), *tex);
    u.base_format = ff_base_format(*tex);
    switch (s.units[0].env_mode) {
      case GL_REPLACE: u.env = TexEnv::Replace; break;
      case GL_DECAL: u.env = TexEnv::Decal; break;
      case GL_BLEND: u.env = TexEnv::Blend; break;
      case GL_ADD: u.env = TexEnv::Add; break;
      default: u.env = TexEnv::Modulate; break;
    }
    u.env_color = s.units[0].env_color;
    const glm::mat4& tm = texture_matrix(0);
    u.texture_matrix = tm;
    u.identity_texture_matrix = tm == glm::mat4(1.0f);
    for (int i = 0; i < 4; ++i) {
      u.texgen[size_t(i)] = s.units[0].gen_enabled[size_t(i)];
      const GLenum m = s.units[0].gen_mode[size_t(i)];
      u.texgen_mode[size_t(i)] = m == GL_OBJECT_LINEAR ? TexGenMode::ObjectLinear
                                 : m == GL_SPHERE_MAP  ? TexGenMode::SphereMap
                                                       : TexGenMode::EyeLinear;
      u.object_plane[size_t(i)] = s.units[0].object_plane[size_t(i)];
      u.eye_plane[size_t(i)] = s.units[0].eye_plane[size_t(i)];
    }
  }
  u.fog = s.fog.enabled;
  if (u.fog) {
    u.fog_mode = s.fog.mode == GL_LINEAR ? FogMode::Linear
                 : s.fog.mode == GL_EXP2 ? FogMode::Exp2
                                         : FogMode::Exp;
    u.fog_start = s.fog.start;
    u.fog_end = s.fog.end;
    u.fog_density = s.fog.density;
    u.fog_color = s.fog.color;
  }
  u.alpha_test = s.color.alpha_test && s.color.alpha_func != GL_ALWAYS;
  u.alpha_func = compare_of(s.color.alpha_func);
  u.alpha_ref = std::clamp(s.color.alpha_ref, 0.0f, 1.0f);
  u.stipple = s.polygon.stipple;
  u.stipple_rows = s.polygon_stipple;
}

gpu::RenderState Context::render_state(bool for_clear) const {
  gpu::RenderState r;
  r.rasterizer_discard = rasterizer_discard;
  const TargetInfo target = target_info();
  r.viewport = {s.viewport.x, s.viewport.y, s.viewport.width, s.viewport.height};
  r.depth_near = float(s.viewport.near_);
  r.depth_far = float(s.viewport.far_);
  r.scissor_test = s.scissor.test;
  r.scissor = {s.scissor.x, s.scissor.y, s.scissor.width, s.scissor.height};
  // Fixed-function fragments (and pixel rectangles) go to every draw buffer; any fragment to
  // both buffers of GL_FRONT_AND_BACK.
  r.broadcast_color = !executable || (!draw_fbo && s.color.draw_buffer == GL_FRONT_AND_BACK);
  if (!for_clear) {
    const PolygonState& p = s.polygon;
    r.cull = cull_mode();
    r.front_face = front_face();
    r.polygon_mode = polygon_mode_of(p.mode_front);
    r.polygon_mode_per_face = p.mode_back != p.mode_front;
    r.polygon_mode_back = polygon_mode_of(p.mode_back);
    r.offset_fill = p.offset_fill;
    r.offset_line = p.offset_line;
    r.offset_point = p.offset_point;
    r.offset_factor = p.offset_factor;
    r.offset_units = p.offset_units;
    // Any positive width or size is accepted and used clamped to the supported range
    // (GL 2.1 §3.3, §3.4: ALIASED_POINT_SIZE_RANGE and ALIASED_LINE_WIDTH_RANGE are 1..255).
    r.line_width = std::clamp(s.line.width, 1.0f, 255.0f);
    // Lines are stippled by the gpu layer after the vertex stage, fixed function or a program's,
    // as Mesa's draw module does; immediate mode says where the counter restarts with each
    // segment's edge mask (batch_edge_masks).
    r.line_stipple = s.line.stipple;
    r.line_stipple_pattern = s.line.stipple_pattern;
    r.line_stipple_factor = uint16_t(std::clamp(s.line.stipple_factor, 1, 256));
    r.point_size = std::clamp(s.point.size, 1.0f, 255.0f);
    r.point_sprite_lower_left = s.point.sprite_lower_left;
    // Antialiased points and lines as llvmpipe draws them; Mesa leaves points aliased while
    // point sprites are on, and polygons are aliased (llvmpipe has no smooth polygons).
    r.point_smooth = s.point.smooth && !s.point.sprite;
    r.line_smooth = s.line.smooth;
    for (int i = 0; i < kMaxClipPlanes; ++i) {
      if (!s.transform.clip_enabled[size_t(i)]) continue;
      r.clip_plane_enable |= uint8_t(1u << i);
      r.clip_planes[size_t(i)] = clip_space_plane(i);
    }
    r.depth_test = s.depth.test && target.depth;
    r.depth_func = compare_of(s.depth.func);
  }
  r.depth_write = s.depth.mask && target.depth && (for_clear || s.depth.test);
  r.stencil_test = s.stencil.test && target.stencil;
  const StencilState& st = s.stencil;
  auto face = [](GLenum func, GLint ref, GLuint value_mask, GLuint write_mask, GLenum fail, GLenum zfail,
                 GLenum zpass) {
    gpu::StencilFace f;
    f.func = compare_of(func);
    f.ref = uint8_t(std::clamp(ref, 0, 255));
    f.read_mask = uint8_t(value_mask & 0xFF);
    f.write_mask = uint8_t(write_mask & 0xFF);
    f.fail = stencil_op_of(fail);
    f.depth_fail = stencil_op_of(zfail);
    f.pass = stencil_op_of(zpass);
    return f;
  };
  r.stencil_front = face(st.func, st.ref, st.value_mask, st.write_mask, st.fail, st.zfail, st.zpass);
  r.stencil_back = face(st.back_func, st.back_ref, st.back_value_mask, st.back_write_mask, st.back_fail,
                        st.back_zfail, st.back_zpass);
  auto equation = [](GLenum e) {
    switch (e) {
      case GL_FUNC_SUBTRACT: return gpu::BlendEquation::Subtract;
      case GL_FUNC_REVERSE_SUBTRACT: return gpu::BlendEquation::ReverseSubtract;
      case GL_MIN: return gpu::BlendEquation::Min;
      case GL_MAX: return gpu::BlendEquation::Max;
      default: return gpu::BlendEquation::Add;
    }
  };
  for (int i = 0; i < kMaxDrawBuffers; ++i) {
    gpu::BlendTarget& b = r.blend[size_t(i)];
    const std::array<bool, 4>& m = s.color.color_mask[size_t(i)];
    b.integer = target.integer[size_t(i)];
    b.enabled = !for_clear && s.color.blend[size_t(i)] && !b.integer.integer();
    b.eq_rgb = equation(s.color.blend_eq);
    b.eq_alpha = equation(s.color.blend_eq_alpha);
    b.src_rgb = blend_of(s.color.blend_src);
    b.dst_rgb = blend_of(s.color.blend_dst);
    b.src_alpha = blend_of(s.color.blend_src_alpha);
    b.dst_alpha = blend_of(s.color.blend_dst_alpha);
    // The channels the attachment's format stores (RGB keeps alpha 1, RED only red, ...).
    b.write_mask = uint8_t(((m[0] ? 1 : 0) | (m[1] ? 2 : 0) | (m[2] ? 4 : 0) | (m[3] ? 8 : 0)) &
                           target.channels[size_t(i)]);
  }
  r.blend_color = s.color.blend_color;
  r.logic_op_enabled = !for_clear && s.color.logic_op;
  r.logic_op = gpu::LogicOp(s.color.logic_op_mode - GL_CLEAR);
  r.provoking_first = s.light.provoking_vertex == GL_FIRST_VERTEX_CONVENTION;
  return r;
}

gpu::CullMode Context::cull_mode() const {
  const PolygonState& p = s.polygon;
  if (!p.cull) return gpu::CullMode::None;
  return p.cull_face == GL_FRONT  ? gpu::CullMode::Front
         : p.cull_face == GL_BACK ? gpu::CullMode::Back
                                  : gpu::CullMode::FrontAndBack;
}

gpu::FrontFace Context::front_face() const {
  return s.polygon.front_face == GL_CW ? gpu::FrontFace::CW : gpu::FrontFace::CCW;
}

glm::vec4 Context::clip_space_plane(int i) const {
  // The gpu layer tests planes in clip space: p_clip = p_eye * P^-1 (as a row vector).
  return glm::vec4(s.transform.clip_plane[size_t(i)]) * glm::inverse(projection());
}

gpu::ClipPlanes Context::cpu_clip_planes() const {
  gpu::ClipPlanes planes = gpu::ClipPlanes::view_volume(!depth_clamp);
  for (int i = 0; i < kMaxClipPlanes; ++i)
    if (s.transform.clip_enabled[size_t(i)]) planes.add(clip_space_plane(i));
  return planes;
}

gpu::ViewportTransform Context::viewport_transform() const {
  const ViewportState& v = s.viewport;
  return gpu::ViewportTransform({v.x, v.y, v.width, v.height}, float(v.near_), float(v.far_));
}

// Facing from the window-space area (GL 2.1 §2.14.1, eq. 2.6), before clipping; a triangle
// with a vertex at w <= 0 is not culled here (clipping decides).
bool Context::culled(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) const {
  const gpu::CullMode mode = cull_mode();
  if (mode == gpu::CullMode::None || !(a.w > 0.0f) || !(b.w > 0.0f) || !(c.w > 0.0f)) return false;
  const glm::vec2 w0 = glm::vec2(a) / a.w, w1 = glm::vec2(b) / b.w, w2 = glm::vec2(c) / c.w;
  const float area = (w1.x - w0.x) * (w2.y - w0.y) - (w2.x - w0.x) * (w1.y - w0.y);
  return gpu::culled(mode, gpu::front_facing(front_face(), area > 0.0f));
}

}  // namespace tessel::gl
