// Batches of fixed-function primitives into gpu draws: the generated fixed-function shaders
// (one template instance per flat / textured / discarding combination), the draw of a batch
// with its edge flags, and the vertex stage on the CPU (post_vertex) for feedback mode.
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
  std::unique_ptr<gpu::Buffer> own;
  if (!b.shared) own = std::make_unique<gpu::Buffer>(b.verts.v.data(), b.verts.size() * sizeof(FFVertex));
  const gpu::Buffer& vbuf = b.shared ? *b.shared : *own;
  auto ib = std::make_unique<gpu::Buffer>(b.indices.data(), b.indices.size() * sizeof(uint32_t));
  if (executable) {
    // A GLSL program reads the batch's vertices as the compatibility attributes.
    const gpu::DrawCall call = b.call(*ib);
    gpu::RenderState rs = render_state(false);
    rs.edge_flag_varying = -1;
    draw_program_batch(executable_run(b.cls), vbuf, b.verts.x, call, rs);
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
  // Stippled lines: where the counter restarts (triangles carry their flags in a varying).
  std::unique_ptr<gpu::Buffer> masks = b.cls == PrimClass::Lines ? batch_edge_masks(vbuf, call) : nullptr;
  if (masks) {
    rs.edge_masks = reinterpret_cast<const uint8_t*>(masks->data());
    rs.edge_mask_count = uint32_t(masks->size());
  }
  draw(*gpu_, *u, layout, rs, call);
  if (masks) keep_until_finished(std::move(masks));
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

// The edge masks (gpu RenderState::edge_masks) of a batch drawn as 32-bit indices into its
// FFVertex records, from the vertices' edge flags: for triangles, bit k says whether the edge
// from vertex k is a boundary edge (decomposed polygons have vertices of their own,
// decompose.cpp); for lines, bit 0 whether the stipple counter restarts at the segment (its
// first vertex's flag, emit_mode). Null unless polygon mode or line stipple needs them.
std::unique_ptr<gpu::Buffer> Context::batch_edge_masks(const gpu::Buffer& vbuf,
                                                       const gpu::DrawCall& call) const {
  const bool triangles = call.topology == gpu::Topology::Triangles &&
                         (s.polygon.mode_front != GL_FILL || s.polygon.mode_back != GL_FILL);
  const bool lines = call.topology == gpu::Topology::Lines && s.line.stipple;
  if ((!triangles && !lines) || !call.index_buffer || call.index_type != gpu::IndexType::U32) return nullptr;
  const auto* v = reinterpret_cast<const FFVertex*>(vbuf.data());
  const size_t nv = vbuf.size() / sizeof(FFVertex);
  const auto* idx = reinterpret_cast<const uint32_t*>(call.index_buffer->data() + call.index_offset);
  const unsigned per = triangles ? 3 : 2, corners = triangles ? 3 : 1;
  std::vector<uint8_t> masks(call.count / per);
  for (size_t p = 0; p < masks.size(); ++p) {
    unsigned m = 0;
    for (unsigned k = 0; k < corners; ++k) {
      const uint32_t i = idx[p * per + k];
      if (i < nv && v[i].edge != 0.0f) m |= 1u << k;
    }
    masks[p] = uint8_t(m);
  }
  return std::make_unique<gpu::Buffer>(masks.data(), masks.size());
}

}  // namespace tessel::gl
