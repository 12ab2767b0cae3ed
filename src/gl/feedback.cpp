// Feedback mode (GL 2.1 §5.3): glRenderMode(GL_FEEDBACK) and glFeedbackBuffer. Nothing is
// drawn; each point, line and polygon that survives culling and clipping is written to the
// buffer as a token and its vertices after the vertex stage: window x, y (GL_2D), z (GL_3D),
// the colour (GL_3D_COLOR), texture coordinates (GL_3D_COLOR_TEXTURE) and the clip w
// (GL_4D_COLOR_TEXTURE). glRenderMode returns the number of values written, -1 on overflow.
#include <GL/gl.h>

#include <algorithm>

#include "api.hpp"

namespace tessel::gl {

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
  const gpu::ClipPlanes planes = cpu_clip_planes();
  const unsigned all = (1u << planes.count) - 1;
  const gpu::ViewportTransform xf = viewport_transform();
  auto write_vertex = [&](const FFPostVertex& v) {
    const glm::vec3 w = xf.window(glm::vec4(v.pos[0], v.pos[1], v.pos[2], v.pos[3]));
    feedback_value(w.x);
    feedback_value(w.y);
    if (fb_type_ == GL_2D) return;
    feedback_value(w.z);
    if (fb_type_ == GL_4D_COLOR_TEXTURE) feedback_value(v.pos[3]);
    if (fb_type_ == GL_3D) return;
    for (int k = 0; k < 4; ++k) feedback_value(v.front[k]);
    if (fb_type_ == GL_3D_COLOR) return;
    for (int k = 0; k < 4; ++k) feedback_value(v.tex[k]);
  };
  auto clip_pos = [](const FFPostVertex& v) { return glm::vec4(v.pos[0], v.pos[1], v.pos[2], v.pos[3]); };
  auto distance = [&](int i, const FFPostVertex& v) { return gpu::plane_distance(planes, i, clip_pos(v)); };
  auto lerp = [](const FFPostVertex& from, const FFPostVertex& to, float t, FFPostVertex& r) {
    r = lerp_post(from, to, t);
  };
  constexpr int kMaxVertices = 3 + gpu::ClipPlanes::kMax;
  FFPostVertex a[kMaxVertices], b[kMaxVertices];
  std::vector<FFPostVertex> poly;
  for (size_t k = 0; k + per <= idx.size(); k += per) {
    for (size_t j = 0; j < per; ++j) a[j] = post_vertex(verts[idx[k + j]], u, tex != nullptr);
    if (per == 3 && culled(clip_pos(a[0]), clip_pos(a[1]), clip_pos(a[2]))) continue;
    // Clipped with gpu/clip_space.hpp's rules (as Mesa's clipper: a polygon keeps its first
    // vertex first when it is inside).
    poly.clear();
    if (per == 1) {
      if (gpu::clip_code(planes, clip_pos(a[0])) == 0) poly.push_back(a[0]);
    } else if (per == 2) {
      float t0, t1;
      if (gpu::clip_segment(
              planes.count, all, [&](int i, int end) { return distance(i, a[end]); }, t0, t1)) {
        poly.push_back(lerp_post(a[0], a[1], t0));
        poly.push_back(lerp_post(a[1], a[0], t1));
      }
    } else {
      FFPostVertex* out = nullptr;
      const int n = gpu::clip_polygon(planes.count, all, a, 3, b, kMaxVertices, distance, lerp, &out);
      poly.assign(out, out + n);
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
