// Feedback mode (GL 2.1 §5.3): glRenderMode(GL_FEEDBACK) and glFeedbackBuffer. Nothing is
// drawn; each point, line and polygon that survives culling and clipping is written to the
// buffer as a token and its vertices after the vertex stage: window x, y (GL_2D), z (GL_3D),
// the colour (GL_3D_COLOR), texture coordinates (GL_3D_COLOR_TEXTURE) and the clip w
// (GL_4D_COLOR_TEXTURE). glRenderMode returns the number of values written, -1 on overflow.
#include <GL/gl.h>

#include <algorithm>

#include "api.hpp"

namespace tessel::gl {

namespace {

float dot4(const glm::vec4& p, const float* v) { return p.x * v[0] + p.y * v[1] + p.z * v[2] + p.w * v[3]; }

}  // namespace

void Context::feedback_value(float v) {
  if (fb_overflow_ || fb_written_ >= size_t(std::max(0, fb_size_))) {
    fb_overflow_ = true;
    return;
  }
  fb_buffer_[fb_written_++] = v;
}

void Context::pass_through(float token) {
  if (render_mode_ != GL_FEEDBACK) return;
  feedback_value(float(GL_PASS_THROUGH_TOKEN));
  feedback_value(token);
}

void Context::feedback_primitives(PrimClass cls, const FFVertices& verts, const std::vector<uint32_t>& idx) {
  TextureObject* tex = texture_for_draw();
  FFUniforms u;
  build_uniforms(u, tex);
  const size_t per = cls == PrimClass::Points ? 1 : cls == PrimClass::Lines ? 2 : 3;
  const std::vector<glm::vec4> planes = clip_space_planes();
  const ViewportState& vp = s.viewport;
  auto write_vertex = [&](const FFPostVertex& v) {
    const float iw = 1.0f / v.pos[3];
    feedback_value(float(vp.x) + (v.pos[0] * iw + 1.0f) * 0.5f * float(vp.width));
    feedback_value(float(vp.y) + (v.pos[1] * iw + 1.0f) * 0.5f * float(vp.height));
    if (fb_type_ == GL_2D) return;
    feedback_value(float(vp.near_ + (vp.far_ - vp.near_) * (double(v.pos[2] * iw) + 1.0) * 0.5));
    if (fb_type_ == GL_4D_COLOR_TEXTURE) feedback_value(v.pos[3]);
    if (fb_type_ == GL_3D) return;
    for (int k = 0; k < 4; ++k) feedback_value(v.front[k]);
    if (fb_type_ == GL_3D_COLOR) return;
    for (int k = 0; k < 4; ++k) feedback_value(v.tex[k]);
  };
  std::vector<FFPostVertex> poly, next;
  for (size_t k = 0; k + per <= idx.size(); k += per) {
    poly.clear();
    for (size_t j = 0; j < per; ++j) poly.push_back(post_vertex(verts[idx[k + j]], u, tex != nullptr));
    auto clip_pos = [&](size_t j) {
      return glm::vec4(poly[j].pos[0], poly[j].pos[1], poly[j].pos[2], poly[j].pos[3]);
    };
    if (per == 3 && culled(clip_pos(0), clip_pos(1), clip_pos(2))) continue;
    // Clip (Sutherland–Hodgman; for a segment the same keeps its ends in order).
    for (const glm::vec4& p : planes) {
      if (poly.empty()) break;
      if (per == 1) {
        if (dot4(p, poly[0].pos) < 0.0f) poly.clear();
        continue;
      }
      next.clear();
      const size_t n = poly.size();
      const size_t edges = per == 2 ? 1 : n;
      for (size_t i = 0; i < edges; ++i) {
        const FFPostVertex &a = poly[i], &b = poly[(i + 1) % n];
        const float da = dot4(p, a.pos), db = dot4(p, b.pos);
        if (da >= 0.0f) next.push_back(a);
        if ((da >= 0.0f) != (db >= 0.0f)) next.push_back(lerp_post(a, b, da / (da - db)));
        if (per == 2 && db >= 0.0f) next.push_back(b);
      }
      poly.swap(next);
    }
    if (poly.empty() || (per == 2 && poly.size() < 2) || (per == 3 && poly.size() < 3)) continue;
    if (per == 1) {
      feedback_value(float(GL_POINT_TOKEN));
    } else if (per == 2) {
      // GL_LINE_RESET_TOKEN marks a reset of the stipple counter; with stipple off Mesa writes
      // GL_LINE_TOKEN for every segment (measured), and so does Tessel.
      const bool reset = s.line.stipple && verts[idx[k]].edge != 0.0f;
      feedback_value(float(reset ? GL_LINE_RESET_TOKEN : GL_LINE_TOKEN));
    } else if (poly.size() > 3) {
      // A polygon that clipping made larger is reported as the triangles of a fan, (v_i-1,
      // v_i, v_0) each, as Mesa's clipper emits it (measured).
      for (size_t i = 2; i < poly.size(); ++i) {
        feedback_value(float(GL_POLYGON_TOKEN));
        feedback_value(3.0f);
        write_vertex(poly[i - 1]);
        write_vertex(poly[i]);
        write_vertex(poly[0]);
      }
      continue;
    } else {
      feedback_value(float(GL_POLYGON_TOKEN));
      feedback_value(float(poly.size()));
    }
    for (const FFPostVertex& v : poly) write_vertex(v);
  }
}

}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glFeedbackBuffer(GLsizei size, GLenum type, GLfloat* buffer) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (type != GL_2D && type != GL_3D && type != GL_3D_COLOR && type != GL_3D_COLOR_TEXTURE &&
      type != GL_4D_COLOR_TEXTURE)
    return c.error(GL_INVALID_ENUM);
  if (size < 0) return c.error(GL_INVALID_VALUE);
  if (c.render_mode() == GL_FEEDBACK) return c.error(GL_INVALID_OPERATION);
  c.set_feedback_buffer(buffer, size, type);
}

void GLAPIENTRY glPassThrough(GLfloat token) {
  GL_COMPAT_CONTEXT();
  GL_LISTED(c.pass_through(token));
  GL_OUTSIDE_BEGIN();
  c.pass_through(token);
}

}  // extern "C"
