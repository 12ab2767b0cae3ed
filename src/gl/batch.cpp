// Batches of fixed-function primitives into gpu draws: the generated fixed-function shaders
// (one template instance per flat / textured / discarding combination), the draw of a batch,
// the vertex stage on the CPU (post_vertex) for the paths that need transformed vertices, and
// stippled lines cut into their dashes.
#include "context.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace tessel::gl {

FFPostVertex lerp_post(const FFPostVertex& a, const FFPostVertex& b, float t) {
  FFPostVertex r;
  const float* pa = &a.pos[0];
  const float* pb = &b.pos[0];
  float* pr = &r.pos[0];
  for (size_t k = 0; k < sizeof(FFPostVertex) / sizeof(float); ++k) pr[k] = pa[k] + (pb[k] - pa[k]) * t;
  return r;
}

namespace {
template <bool Flat, bool Textured, bool Discards>
void draw_ff(gpu::Context& g, const FFUniforms& u, const gpu::VertexLayout& layout,
             const gpu::RenderState& rs, const gpu::DrawCall& call) {
  g.draw(FixedFunction<Flat, Textured, Discards>{}, u, layout, rs, call);
}
template <bool Flat, bool Discards>
void draw_lean(gpu::Context& g, const FFUniforms& u, const gpu::VertexLayout& layout,
               const gpu::RenderState& rs, const gpu::DrawCall& call) {
  g.draw(FixedFunction<Flat, false, Discards, true>{}, u, layout, rs, call);
}
using DrawFn = void (*)(gpu::Context&, const FFUniforms&, const gpu::VertexLayout&, const gpu::RenderState&,
                        const gpu::DrawCall&);
constexpr DrawFn kDraw[8] = {
    draw_ff<false, false, false>, draw_ff<false, false, true>, draw_ff<false, true, false>,
    draw_ff<false, true, true>,   draw_ff<true, false, false>, draw_ff<true, false, true>,
    draw_ff<true, true, false>,   draw_ff<true, true, true>,
};
// Draws that need only the front colour (no texture, fog, two-sided lighting or edges).
constexpr DrawFn kDrawLean[4] = {draw_lean<false, false>, draw_lean<false, true>, draw_lean<true, false>,
                                 draw_lean<true, true>};
}  // namespace

void Context::send_batch() {
  guarded([&] { send_batch_unchecked(); });
}

void Context::send_batch_unchecked() {
  Batch b;
  std::swap(b, batch_);
  if (b.indices.empty()) return;
  if (!bind_draw_target()) return;
  if (b.cls == PrimClass::Lines && s.line.stipple) return send_stippled_lines(b.verts, b.indices);
  std::unique_ptr<gpu::Buffer> own;
  if (!b.shared) own = std::make_unique<gpu::Buffer>(b.verts.v.data(), b.verts.size() * sizeof(FFVertex));
  const gpu::Buffer& vbuf = b.shared ? *b.shared : *own;
  auto ib = std::make_unique<gpu::Buffer>(b.indices.data(), b.indices.size() * sizeof(uint32_t));
  if (executable) {
    // A GLSL program reads the batch's vertices as the compatibility attributes.
    const gpu::DrawCall call = b.call(*ib);
    gpu::RenderState rs = render_state(false);
    rs.edge_flag_varying = -1;
    draw_program_batch(executable_run(), vbuf, b.verts.x, call, rs);
  } else {
    draw_fixed_function(b, vbuf, *ib);
  }
  transient_bytes_ += vbuf.size() + ib->size();
  if (own)
    transient_buffers_.push_back(std::move(own));
  else
    transient_shared_.push_back(b.shared);
  transient_buffers_.push_back(std::move(ib));
  if (transient_bytes_ > kTransientFlushBytes) {
    gpu_->finish();
    release_transient();
  }
}

void Context::draw_fixed_function(const Batch& b, const gpu::Buffer& vbuf, const gpu::Buffer& ib) {
  FFProgramKey key;
  TextureObject* tex = nullptr;  // the key's look at unit 0 is the C++ shader's texture
  if (ff_program_key(b.cls, key, tex)) return draw_ff_program(key, b, vbuf, ib);
  gpu::VertexLayout layout;
  constexpr uint32_t stride = sizeof(FFVertex);
  layout.attrib(0, vbuf, 4, gpu::AttribType::F32, stride, offsetof(FFVertex, pos));
  layout.attrib(1, vbuf, 3, gpu::AttribType::F32, stride, offsetof(FFVertex, normal));
  layout.attrib(2, vbuf, 4, gpu::AttribType::F32, stride, offsetof(FFVertex, color));
  layout.attrib(3, vbuf, 4, gpu::AttribType::F32, stride, offsetof(FFVertex, tex));
  layout.attrib(4, vbuf, 1, gpu::AttribType::F32, stride, offsetof(FFVertex, edge));
  auto u = std::make_unique<FFUniforms>();
  build_uniforms(*u, tex);
  gpu::RenderState rs = render_state(false);
  rs.edge_flag_varying = kEdgeFlagVarying;
  const gpu::DrawCall call = b.call(ib);
  const bool flat = s.light.shade_model == GL_FLAT;
  const bool discards = u->alpha_test || (u->stipple && b.cls == PrimClass::Triangles);
  if (b.cls != PrimClass::Triangles) u->stipple = false;
  const bool lean =
      !tex && !u->fog && !(u->lighting && u->two_side) &&
      (b.cls != PrimClass::Triangles || (s.polygon.mode_front == GL_FILL && s.polygon.mode_back == GL_FILL));
  if (lean) rs.edge_flag_varying = -1;
  const DrawFn draw = lean ? kDrawLean[(flat ? 2 : 0) + (discards ? 1 : 0)]
                           : kDraw[(flat ? 4 : 0) + (tex ? 2 : 0) + (discards ? 1 : 0)];
  draw(*gpu_, *u, layout, rs, call);
}

// The fixed-function vertex stage on one lane (the same shader the draws use).
FFPostVertex Context::post_vertex(const FFVertex& v, const FFUniforms& u, bool textured) const {
  gpu::VertexIn<float> in{};
  in.attr[0] = gpu::Vec4<float>(v.pos[0], v.pos[1], v.pos[2], v.pos[3]);
  in.attr[1] = gpu::Vec4<float>(v.normal[0], v.normal[1], v.normal[2], 0.0f);
  in.attr[2] = gpu::Vec4<float>(v.color[0], v.color[1], v.color[2], v.color[3]);
  in.attr[3] = gpu::Vec4<float>(v.tex[0], v.tex[1], v.tex[2], v.tex[3]);
  in.attr[4] = gpu::Vec4<float>(v.edge, 0.0f, 0.0f, 1.0f);
  FFVaryings<float> out;
  const gpu::Vec4<float> p = textured ? FixedFunction<false, true, false>{}.vertex(u, in, out)
                                      : FixedFunction<false, false, false>{}.vertex(u, in, out);
  FFPostVertex o;
  const float pv[4] = {p.x, p.y, p.z, p.w};
  const float fv[4] = {out.front.x, out.front.y, out.front.z, out.front.w};
  const float bv[4] = {out.back.x, out.back.y, out.back.z, out.back.w};
  const float tv[4] = {out.tex.x, out.tex.y, out.tex.z, out.tex.w};
  std::memcpy(o.pos, pv, sizeof pv);
  std::memcpy(o.front, fv, sizeof fv);
  std::memcpy(o.back, bv, sizeof bv);
  std::memcpy(o.tex, tv, sizeof tv);
  o.edge = v.edge;
  o.fog = out.fog;
  return o;
}

// Stippled lines (GL 2.1 §3.4.2) are cut into their drawn pieces on the CPU, as Mesa's draw
// module does: each vertex goes through the fixed-function vertex stage (the same shader on
// one lane), each segment is clipped to the view volume and taken to window coordinates,
// and the pieces where the pattern is on are drawn as pre-transformed lines. The counter
// steps once per pixel along the major axis and carries over between the segments of a
// strip; the pieces' ends are interpolated linearly in window space.
void Context::send_stippled_lines(const FFVertices& verts, const std::vector<uint32_t>& indices) {
  TextureObject* tex = texture_for_draw();
  FFUniforms u;
  build_uniforms(u, tex);
  u.stipple = false;
  // The vertex stage on one lane for every vertex the lines use.
  std::vector<FFPostVertex> post(verts.size());
  std::vector<bool> done(verts.size(), false);
  auto process = [&](uint32_t i) -> const FFPostVertex& {
    if (!done[i]) {
      post[i] = post_vertex(verts[i], u, tex != nullptr);
      done[i] = true;
    }
    return post[i];
  };
  const auto lerp = lerp_post;

  const gpu::ViewportTransform xf = viewport_transform();
  const gpu::ClipPlanes planes = cpu_clip_planes();
  const unsigned all = (1u << planes.count) - 1;
  const float fw = float(fb_.width()), fh = float(fb_.height());
  // Window coordinates of a clip-space vertex; the pieces are drawn in the clip space of the
  // whole framebuffer (viewport = framebuffer, depth range [0, 1], w = 1).
  auto to_window = [&](const FFPostVertex& c) {
    return xf.window(glm::vec4(c.pos[0], c.pos[1], c.pos[2], c.pos[3]));
  };
  const bool flat = s.light.shade_model == GL_FLAT;
  std::vector<FFPostVertex> out;
  float counter = 0.0f;  // pixels along the major axis so far; whole pixels select the bit
  const int factor = std::max(1, s.line.stipple_factor);
  const unsigned pattern = s.line.stipple_pattern;
  for (size_t k = 0; k + 1 < indices.size(); k += 2) {
    const FFVertex& src0 = verts[indices[k]];
    FFPostVertex a = process(indices[k]), b = process(indices[k + 1]);
    if (src0.edge != 0.0f) counter = 0.0f;
    if (flat) {
      std::memcpy(a.front, b.front, sizeof a.front);
      std::memcpy(a.back, b.back, sizeof a.back);
    }
    // Clipped against the view volume and the user planes (gpu/clip_space.hpp).
    float t0, t1;
    const FFPostVertex* ends[2] = {&a, &b};
    if (!gpu::clip_segment(
            planes.count, all,
            [&](int i, int end) {
              const float* p = ends[end]->pos;
              return gpu::plane_distance(planes, i, glm::vec4(p[0], p[1], p[2], p[3]));
            },
            t0, t1))
      continue;
    const FFPostVertex ca = lerp(a, b, t0), cb = lerp(b, a, t1);
    const glm::vec3 wa = to_window(ca), wb = to_window(cb);
    // In window space from here on: the pieces interpolate linearly between the ends.
    FFPostVertex sa = ca, sb = cb;
    const float ws[2][3] = {{wa.x, wa.y, wa.z}, {wb.x, wb.y, wb.z}};
    FFPostVertex* e[2] = {&sa, &sb};
    for (int j = 0; j < 2; ++j) {
      e[j]->pos[0] = ws[j][0] * 2.0f / fw - 1.0f;
      e[j]->pos[1] = ws[j][1] * 2.0f / fh - 1.0f;
      e[j]->pos[2] = ws[j][2] * 2.0f - 1.0f;
      e[j]->pos[3] = 1.0f;
    }
    const float length = std::max(std::fabs(wb.x - wa.x), std::fabs(wb.y - wa.y));
    bool on = false;
    float start = 0.0f;
    auto piece = [&](float p0, float p1) {
      out.push_back(lerp(sa, sb, p0 / length));
      out.push_back(lerp(sa, sb, p1 / length));
    };
    for (int i = 0; float(i) < length; ++i) {
      const unsigned bit = unsigned((int(counter) + i) / factor) & 15u;
      const bool result = (pattern >> bit) & 1u;
      if (result != on) {
        if (on) {
          if (start != float(i)) piece(start, float(i));
        } else {
          start = float(i);
        }
        on = result;
      }
    }
    if (on && start < length) piece(start, length);
    counter += length;
  }
  if (out.empty()) return;
  auto vb = std::make_unique<gpu::Buffer>(out.data(), out.size() * sizeof(FFPostVertex));
  gpu::VertexLayout layout;
  constexpr uint32_t stride = sizeof(FFPostVertex);
  layout.attrib(0, *vb, 4, gpu::AttribType::F32, stride, offsetof(FFPostVertex, pos));
  layout.attrib(1, *vb, 4, gpu::AttribType::F32, stride, offsetof(FFPostVertex, back));
  layout.attrib(2, *vb, 4, gpu::AttribType::F32, stride, offsetof(FFPostVertex, front));
  layout.attrib(3, *vb, 4, gpu::AttribType::F32, stride, offsetof(FFPostVertex, tex));
  layout.attrib(4, *vb, 2, gpu::AttribType::F32, stride, offsetof(FFPostVertex, edge));
  u.pretransformed = true;
  gpu::RenderState rs = render_state(false);
  rs.viewport = {0, 0, fb_.width(), fb_.height()};
  rs.depth_near = 0.0f;
  rs.depth_far = 1.0f;
  rs.clip_plane_enable = 0;
  gpu::DrawCall call;
  call.topology = gpu::Topology::Lines;
  call.count = uint32_t(out.size());
  const bool discards = u.alpha_test;
  kDraw[(flat ? 4 : 0) + (tex ? 2 : 0) + (discards ? 1 : 0)](*gpu_, u, layout, rs, call);
  transient_bytes_ += vb->size();
  transient_buffers_.push_back(std::move(vb));
}

}  // namespace tessel::gl
