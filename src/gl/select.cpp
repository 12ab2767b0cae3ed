// Selection mode (GL 2.1 §5.2): glRenderMode(GL_SELECT), glSelectBuffer and the name stack.
// In selection mode nothing is drawn; every point, line or polygon that survives culling and
// clipping (and every valid glRasterPos) is a hit for the names on the stack, which records
// the smallest and largest window z of what was hit. A hit record — the number of names, the
// minimum and maximum depth scaled to [0, 2^32 - 1], then the names from the bottom of the
// stack — is written when the name stack changes or selection mode ends.
#include <GL/gl.h>

#include <algorithm>
#include <cmath>

#include "api.hpp"

namespace tessel::gl {

namespace {
constexpr int kMaxNameStack = 64;

GLuint scaled_depth(float z) {
  const double d = std::clamp(double(z), 0.0, 1.0);
  return GLuint(std::llround(d * 4294967295.0));
}

}  // namespace

void Context::write_hit_record() {
  if (!sel_hit_) return;
  sel_hit_ = false;
  const size_t need = 3 + sel_names_.size();
  if (sel_overflow_ || sel_written_ + need > size_t(std::max(0, sel_size_))) {
    sel_overflow_ = true;
    return;
  }
  GLuint* p = sel_buffer_ + sel_written_;
  p[0] = GLuint(sel_names_.size());
  p[1] = scaled_depth(sel_zmin_);
  p[2] = scaled_depth(sel_zmax_);
  std::copy(sel_names_.begin(), sel_names_.end(), p + 3);
  sel_written_ += need;
  ++sel_hits_;
}

void Context::select_hit(float z) {
  if (!sel_hit_) {
    sel_hit_ = true;
    sel_zmin_ = sel_zmax_ = z;
  } else {
    sel_zmin_ = std::min(sel_zmin_, z);
    sel_zmax_ = std::max(sel_zmax_, z);
  }
}

// The primitives of one emission, tested instead of drawn: culled as they would be, clipped
// against the view volume and the user planes (gpu/clip_space.hpp); what is left is a hit at
// its window depths.
void Context::select_primitives(PrimClass cls, const FFVertices& verts, const std::vector<uint32_t>& idx) {
  const glm::mat4 mvp = projection() * modelview();
  const size_t per = cls == PrimClass::Points ? 1 : cls == PrimClass::Lines ? 2 : 3;
  const gpu::ClipPlanes planes = cpu_clip_planes();
  const unsigned all = (1u << planes.count) - 1;
  const gpu::ViewportTransform xf = viewport_transform();
  auto hit = [&](const glm::vec4& p) {
    if (p.w != 0.0f) select_hit(xf.window(p).z);
  };
  auto distance = [&](int i, const glm::vec4& v) { return gpu::plane_distance(planes, i, v); };
  auto lerp = [](const glm::vec4& from, const glm::vec4& to, float t, glm::vec4& r) {
    r = from + (to - from) * t;
  };
  constexpr int kMaxVertices = 3 + gpu::ClipPlanes::kMax;
  glm::vec4 a[kMaxVertices], b[kMaxVertices];
  for (size_t k = 0; k + per <= idx.size(); k += per) {
    for (size_t j = 0; j < per; ++j) {
      const FFVertex& v = verts[idx[k + j]];
      a[j] = mvp * glm::vec4(v.pos[0], v.pos[1], v.pos[2], v.pos[3]);
    }
    if (per == 1) {
      if (gpu::clip_code(planes, a[0]) == 0) hit(a[0]);
      continue;
    }
    if (per == 2) {
      float t0, t1;
      if (!gpu::clip_segment(
              planes.count, all, [&](int i, int end) { return distance(i, a[end]); }, t0, t1))
        continue;
      hit(a[0] + (a[1] - a[0]) * t0);
      hit(a[1] + (a[0] - a[1]) * t1);
      continue;
    }
    if (culled(a[0], a[1], a[2])) continue;
    glm::vec4* poly = nullptr;
    const int n = gpu::clip_polygon(planes.count, all, a, 3, b, kMaxVertices, distance, lerp, &poly);
    for (int i = 0; i < n; ++i) hit(poly[i]);
  }
}

namespace {

void name_op(Context& c, int op, GLuint name) {
  GL_OUTSIDE_BEGIN();
  if (c.render_mode() != GL_SELECT) return;  // the name stack is ignored outside selection mode
  c.touch();                                 // quads still waiting to be cut are tested first
  auto& names = c.name_stack();
  switch (op) {
    case 0:  // glInitNames
      c.write_hit_record();
      names.clear();
      break;
    case 1:  // glLoadName
      if (names.empty()) return c.error(GL_INVALID_OPERATION);
      c.write_hit_record();
      names.back() = name;
      break;
    case 2:  // glPushName
      if (int(names.size()) >= kMaxNameStack) return c.error(GL_STACK_OVERFLOW);
      c.write_hit_record();
      names.push_back(name);
      break;
    default:  // glPopName
      if (names.empty()) return c.error(GL_STACK_UNDERFLOW);
      c.write_hit_record();
      names.pop_back();
      break;
  }
}

}  // namespace

GLint Context::set_render_mode(GLenum mode) {
  if (mode != GL_RENDER && mode != GL_SELECT && mode != GL_FEEDBACK) {
    error(GL_INVALID_ENUM);
    return 0;
  }
  if ((mode == GL_SELECT && !sel_buffer_) || (mode == GL_FEEDBACK && !fb_buffer_)) {
    error(GL_INVALID_OPERATION);
    return 0;
  }
  touch();
  GLint result = 0;
  if (render_mode_ == GL_SELECT) {
    write_hit_record();
    result = sel_overflow_ ? -1 : sel_hits_;
  } else if (render_mode_ == GL_FEEDBACK) {
    result = fb_overflow_ ? -1 : GLint(fb_written_);
  }
  fb_written_ = 0;
  fb_overflow_ = false;
  render_mode_ = mode;
  sel_written_ = 0;
  sel_hits_ = 0;
  sel_overflow_ = false;
  sel_hit_ = false;
  if (mode == GL_SELECT) sel_names_.clear();
  return result;
}

}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

GLint GLAPIENTRY glRenderMode(GLenum mode) {
  GL_COMPAT_CONTEXT(0);
  GL_OUTSIDE_BEGIN(0);
  return c.set_render_mode(mode);
}
void GLAPIENTRY glSelectBuffer(GLsizei size, GLuint* buffer) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (size < 0) return c.error(GL_INVALID_VALUE);
  if (c.render_mode() == GL_SELECT) return c.error(GL_INVALID_OPERATION);
  c.set_select_buffer(buffer, size);
}
void GLAPIENTRY glInitNames(void) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(name_op(c, 0, 0));
  name_op(c, 0, 0);
}
void GLAPIENTRY glLoadName(GLuint name) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(name_op(c, 1, name));
  name_op(c, 1, name);
}
void GLAPIENTRY glPushName(GLuint name) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(name_op(c, 2, name));
  name_op(c, 2, name);
}
void GLAPIENTRY glPopName(void) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(name_op(c, 3, 0));
  name_op(c, 3, 0);
}

}  // extern "C"
