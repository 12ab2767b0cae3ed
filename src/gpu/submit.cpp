// Submission: clear() and submit() validate what they are given and record a draw with
// copies of everything it reads (indices read and checked, primitive restart expanded,
// viewport, depth range, guard band and render area worked out once), for flush() to run.
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <string>

#include "frame.hpp"

namespace tessel::gpu {
using namespace detail;

// Expands a strip/fan/loop/list with primitive restart into an independent list.
std::vector<uint32_t> detail::expand_restart(Topology& t, const std::vector<uint32_t>& idx, uint32_t restart,
                                             bool provoking_first) {
  std::vector<uint32_t> out;
  const Topology in = t;
  size_t start = 0;
  auto flush_run = [&](size_t a, size_t b) {  // [a, b)
    const uint32_t n = uint32_t(b - a);
    const uint32_t np = prim_count(in, n);
    uint32_t e[kMaxGeometryInputVertices];
    for (uint32_t p = 0; p < np; ++p) {
      prim_elements(in, p, n, e);
      const int size = prim_size(in);
      // A rotation keeps the winding and brings the provoking vertex where the list has it.
      const int shift = size == 3 && provoking_first ? provoking_element(in, p, true) : 0;
      for (int k = 0; k < size; ++k) out.push_back(idx[a + e[(k + shift) % size]]);
    }
  };
  for (size_t i = 0; i <= idx.size(); ++i) {
    if (i == idx.size() || idx[i] == restart) {
      flush_run(start, i);
      start = i + 1;
    }
  }
  t = list_topology(prim_size(in));
  return out;
}

std::vector<uint32_t> detail::drop_adjacency(Topology& t, const std::vector<uint32_t>& idx) {
  std::vector<uint32_t> out;
  const size_t n = idx.size();
  switch (t) {
    case Topology::LinesAdjacency:  // vertices 1 and 2 of each four
      for (size_t i = 0; i + 4 <= n; i += 4) out.insert(out.end(), {idx[i + 1], idx[i + 2]});
      t = Topology::Lines;
      break;
    case Topology::LineStripAdjacency:  // all but the first and the last
      if (n >= 4) out.assign(idx.begin() + 1, idx.end() - 1);
      t = Topology::LineStrip;
      break;
    case Topology::TrianglesAdjacency:  // vertices 0, 2 and 4 of each six
      for (size_t i = 0; i + 6 <= n; i += 6) out.insert(out.end(), {idx[i], idx[i + 2], idx[i + 4]});
      t = Topology::Triangles;
      break;
    case Topology::TriangleStripAdjacency:  // the even vertices make the strip (Table 2.4)
      if (n >= 6)
        for (size_t i = 0; i < n; i += 2) out.push_back(idx[i]);
      t = Topology::TriangleStrip;
      break;
    default: return idx;
  }
  return out;
}

static Rect render_area(const RenderState& s, int width, int height) {
  Rect r{0, 0, width, height};
  if (s.scissor_test) {
    const int x0 = std::max(r.x, s.scissor.x), y0 = std::max(r.y, s.scissor.y);
    const int x1 =
        std::min<int64_t>(int64_t(r.x) + r.width, int64_t(s.scissor.x) + std::max(0, s.scissor.width));
    const int y1 =
        std::min<int64_t>(int64_t(r.y) + r.height, int64_t(s.scissor.y) + std::max(0, s.scissor.height));
    r = {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
  }
  return r;
}

void Context::clear(const ClearValues& v, const RenderState& state) {
  if (!fb_) throw Error("clear: no framebuffer bound");
  if (!std::isfinite(v.depth)) throw Error("clear: depth value is not finite");
  if (frame_->commands.empty()) frame_->target = make_target();
  const Rect r = render_area(state, frame_->target.width, frame_->target.height);
  if (r.width <= 0 || r.height <= 0) return;
  auto c = std::make_unique<ClearPrim>();
  c->base.kind = PrimKind::Clear;
  c->base.minx = r.x;
  c->base.miny = r.y;
  c->base.maxx = r.x + r.width - 1;
  c->base.maxy = r.y + r.height - 1;
  c->color_mask_bits = v.clear_color ? v.color_attachments : 0;
  for (int i = 0; i < kMaxColorAttachments; ++i) {
    c->color[i] = v.per_attachment ? v.attachment_colors[i] : v.color;
    c->write_mask[i] = state.blend[i].write_mask;
  }
  c->clear_depth = v.clear_depth && state.depth_write;
  c->depth = v.depth;
  c->clear_stencil = v.clear_stencil;
  c->stencil = v.stencil;
  c->stencil_write_mask = state.stencil_front.write_mask;
  frame_->commands.push_back({true, uint32_t(frame_->clears.size())});
  frame_->clears.push_back(std::move(c));
}

void Context::submit(std::unique_ptr<ProgramBase> program, const VertexLayout& layout,
                     const RenderState& state, const DrawCall& call, uint32_t required_attribs) {
  note_draw_submitted();  // from now on earlier resources may be read by queued work
  if (!fb_) throw Error("draw: no framebuffer bound");
  if (unsigned(call.topology) > unsigned(Topology::TriangleStripAdjacency))
    throw Error("draw: invalid topology " + std::to_string(int(call.topology)));
  const int gs_input = program->geometry_input;
  if (gs_input && !geometry_takes(gs_input, call.topology))
    throw Error("draw: the program's geometry stage takes primitives of " + std::to_string(gs_input) +
                " vertices; topology " + std::to_string(int(call.topology)) + " does not give them");
  if (unsigned(state.cull) > unsigned(CullMode::FrontAndBack) || unsigned(state.front_face) > 1 ||
      unsigned(state.polygon_mode) > 2 || unsigned(state.polygon_mode_back) > 2 ||
      unsigned(state.depth_func) > 7)
    throw Error("draw: invalid enum in render state");
  if (!(state.line_width > 0.0f) || !(state.point_size > 0.0f) || state.line_width > 1024.0f ||
      state.point_size > 8192.0f)
    throw Error("draw: line width " + std::to_string(state.line_width) + " / point size " +
                std::to_string(state.point_size) + " out of range");
  if (!std::isfinite(state.depth_near) || !std::isfinite(state.depth_far) ||
      !std::isfinite(state.offset_factor) || !std::isfinite(state.offset_units))
    throw Error("draw: depth range and polygon offset must be finite");
  if (call.count == 0 || call.instance_count == 0) return;
  if (uint64_t(call.base_instance) + call.instance_count > UINT32_MAX)
    throw Error("draw: instance range overflows");
  for (int i = 0; i < kMaxClipPlanes; ++i)
    if ((state.clip_plane_enable >> i) & 1)
      for (int k = 0; k < 4; ++k)
        if (!std::isfinite(state.clip_planes[i][k]) || std::fabs(state.clip_planes[i][k]) > 1e18f)
          throw Error("draw: clip plane " + std::to_string(i) + " is not finite or too large");

  std::unique_ptr<DrawRecord> d;
  if (frame_->spare.empty()) {
    d = std::make_unique<DrawRecord>();
  } else {
    d = std::move(frame_->spare.back());
    frame_->spare.pop_back();
    std::vector<uint32_t> storage = std::move(d->indices);
    *d = DrawRecord{};
    storage.clear();
    d->indices = std::move(storage);
  }
  d->program = std::move(program);
  d->state = state;
  d->layout = layout;
  d->topology = call.topology;
  d->instance_count = call.instance_count;
  d->base_instance = call.base_instance;
  uint32_t max_id = 0;
  if (call.index_buffer) {
    const size_t isz = call.index_type == IndexType::U8 ? 1 : call.index_type == IndexType::U16 ? 2 : 4;
    if (unsigned(call.index_type) > 2) throw Error("draw: invalid index type");
    if (call.index_offset % isz)
      throw Error("draw: index offset " + std::to_string(call.index_offset) +
                  " is not aligned to the index size");
    // Overflow-safe: the indices [first, first + count) must lie in the buffer after the offset.
    const size_t size = call.index_buffer->size();
    const uint64_t available = call.index_offset <= size ? (size - call.index_offset) / isz : 0;
    if (call.index_offset > size || uint64_t(call.first) + call.count > available)
      throw Error("draw: indices [" + std::to_string(call.first) + ", " +
                  std::to_string(uint64_t(call.first) + call.count) + ") at byte offset " +
                  std::to_string(call.index_offset) + " are past the end of an index buffer of " +
                  std::to_string(size) + " bytes");
    const uint64_t begin = uint64_t(call.index_offset) + uint64_t(call.first) * isz;
    const std::byte* src = call.index_buffer->data() + begin;
    const uint32_t restart = isz == 1 ? 0xFFu : isz == 2 ? 0xFFFFu : 0xFFFFFFFFu;
    if (isz == 4 && !state.primitive_restart && call.base_vertex == 0 &&
        (gs_input || !is_adjacency(d->topology))) {
      // The common case: 32-bit indices read where they are, checked against their maximum.
      const uint32_t m = call.index_buffer->max_u32(begin, call.count);
      if (m > uint32_t(INT32_MAX)) {
        for (uint32_t at = 0; at < call.count; ++at) {
          uint32_t id;
          std::memcpy(&id, src + size_t(at) * 4, 4);
          if (id > uint32_t(INT32_MAX))
            throw Error("draw: index " + std::to_string(id) + " at position " + std::to_string(at) +
                        " plus base vertex 0 is out of range");
        }
      }
      max_id = m;
      d->elements = reinterpret_cast<const uint32_t*>(src);  // read with memcpy only
      d->count = call.count;
    }
    std::vector<uint32_t> raw(d->elements ? 0 : call.count);
    for (uint32_t i = 0; i < uint32_t(raw.size()); ++i) {
      uint32_t v = 0;
      std::memcpy(&v, src + size_t(i) * isz, isz);
      raw[i] = v;
    }
    if (state.primitive_restart) raw = expand_restart(d->topology, raw, restart, state.provoking_first);
    if (!gs_input && is_adjacency(d->topology)) raw = drop_adjacency(d->topology, raw);
    if (!raw.empty()) d->indices.resize(raw.size());
    for (size_t i = 0; i < raw.size(); ++i) {
      const int64_t id = int64_t(raw[i]) + call.base_vertex;
      if (id < 0 || id > INT32_MAX)
        throw Error("draw: index " + std::to_string(raw[i]) + " at position " + std::to_string(i) +
                    " plus base vertex " + std::to_string(call.base_vertex) + " is out of range");
      d->indices[i] = uint32_t(id);
      max_id = std::max(max_id, uint32_t(id));
    }
    d->indexed = true;
    if (!d->elements) {
      d->elements = d->indices.data();
      d->count = uint32_t(d->indices.size());
    }
  } else if (!gs_input && is_adjacency(d->topology)) {
    // Adjacency without a geometry stage: the vertices drawn, as indices.
    if (uint64_t(call.first) + call.count > uint64_t(INT32_MAX)) throw Error("draw: vertex range overflows");
    std::vector<uint32_t> all(call.count);
    for (uint32_t i = 0; i < call.count; ++i) all[i] = call.first + i;
    d->indices = drop_adjacency(d->topology, all);
    d->indexed = true;
    d->elements = d->indices.data();
    d->count = uint32_t(d->indices.size());
    max_id = call.first + call.count - 1;
  } else {
    if (uint64_t(call.first) + call.count > uint64_t(INT32_MAX)) throw Error("draw: vertex range overflows");
    d->first = call.first;
    d->count = call.count;
    max_id = call.first + call.count - 1;
  }
  validate_vertex_range(layout, max_id, call.base_instance + call.instance_count, required_attribs);
  if (call.capture) check_capture(*call.capture, *d);
  d->prim_count = prim_count(d->topology, d->count);
  if (d->prim_count == 0) return;
  // One draw runs as one frame, so its size bounds the frame's memory: at most 2^13 chunks
  // of 1024 primitives (about 8 M primitives, instances included). Running huge draws in
  // windows is still to do.
  const uint64_t chunks = uint64_t(d->instance_count) * ((d->prim_count + kChunkPrims - 1) / kChunkPrims);
  if (chunks > (uint64_t(1) << 13))
    throw Error(
        "draw: " + std::to_string(uint64_t(d->prim_count) * d->instance_count) +
        " primitives (instances included) in one draw is more than Tessel runs at once; split the draw");

  if (frame_->commands.empty()) frame_->target = make_target();
  d->target = frame_->target;
  const int W = d->target.width, H = d->target.height;
  Rect vp = state.viewport;
  if (vp.width <= 0 || vp.height <= 0) vp = {0, 0, W, H};
  vp.width = std::min(vp.width, kMaxViewportSize);
  vp.height = std::min(vp.height, kMaxViewportSize);
  vp.x = std::clamp(vp.x, -kMaxViewportSize, kMaxViewportSize);
  vp.y = std::clamp(vp.y, -kMaxViewportSize, kMaxViewportSize);
  const ViewportTransform xf(vp, state.depth_near, state.depth_far);  // GL 4.6 §13.8.1
  for (int k = 0; k < 3; ++k) {
    d->vp_scale[k] = xf.scale[k];
    d->vp_offset[k] = xf.offset[k];
  }
  const float n = std::clamp(state.depth_near, 0.0f, 1.0f), f = std::clamp(state.depth_far, 0.0f, 1.0f);
  d->depth_min = std::min(n, f);
  d->depth_max = std::max(n, f);
  // |x_w| stays under the guard band: |x_ndc * s + o| <= G for |x_ndc| <= (G - |o|) / s.
  d->guard_x = (kGuardBand - std::fabs(d->vp_offset[0])) / d->vp_scale[0];
  d->guard_y = (kGuardBand - std::fabs(d->vp_offset[1])) / d->vp_scale[1];
  // Primitives are clipped against the guard band, not the view volume's sides, so the
  // viewport rectangle bounds the fragments as the sides would (GL 4.6 §13.7); llvmpipe,
  // which also uses a guard band, does the same.
  Rect area = render_area(state, W, H);
  {
    const int x0 = std::max(area.x, vp.x), y0 = std::max(area.y, vp.y);
    const int x1 = std::min<int64_t>(int64_t(area.x) + area.width, int64_t(vp.x) + vp.width);
    const int y1 = std::min<int64_t>(int64_t(area.y) + area.height, int64_t(vp.y) + vp.height);
    area = {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
  }
  d->area_x0 = area.x;
  d->area_y0 = area.y;
  d->area_x1 = area.x + area.width;
  d->area_y1 = area.y + area.height;
  d->raster = area.width > 0 && area.height > 0 && !state.rasterizer_discard;
  d->capture = call.capture;
  if (!d->raster && !d->capture && !gs_input) {
    // Nothing to run: only the primitives to count.
    stats_.primitives_generated += uint64_t(d->prim_count) * d->instance_count;
    return;
  }
  d->depth_float = d->target.depth && d->target.depth_format == Format::Depth32F;
  d->depth_resolution = 1.0f / 16777216.0f;  // 2^-24 for 24-bit depth
  d->early_depth = !d->program->discards && !d->program->writes_depth;
  // Antialiased points and lines get their coverage per fragment (and points discard): not
  // for packed shading, and points not with early depth. Only when the draw rasterizes points
  // or lines (a program may leave GL_LINE_SMOOTH on while it draws triangles).
  if (state.point_smooth || state.line_smooth) {
    const int size = prim_size(gs_input ? emitted_list(d->program->geometry_output) : d->topology);
    auto mode = [&](PolygonMode m) {
      return size == 3 && (state.polygon_mode == m || state.polygon_mode_back == m);
    };
    const bool points = state.point_smooth && (size == 1 || mode(PolygonMode::Point));
    const bool lines = state.line_smooth && (size == 2 || mode(PolygonMode::Line));
    d->state.point_smooth = points;
    d->state.line_smooth = lines;
    if (points) d->early_depth = false;
  }
  d->fast_depth = d->target.depth && d->state.depth_test && !(d->state.stencil_test && d->target.has_stencil);
  d->fast_color = d->target.color_count == 1 && d->target.color[0].data &&
                  d->target.color[0].format == Format::RGBA8 && !d->state.blend[0].enabled &&
                  !d->state.logic_op_enabled && d->state.blend[0].write_mask == 0xF &&
                  d->program->outputs >= 1 && !d->state.point_smooth && !d->state.line_smooth;

  frame_->pending_prims += uint64_t(d->prim_count) * d->instance_count;
  frame_->commands.push_back({false, uint32_t(frame_->draws.size())});
  frame_->draws.push_back(std::move(d));
  if (frame_->pending_prims > kMaxPendingPrims || call.capture) flush();
}

// A transform feedback request that the draw `d` (its program and topology set) can serve.
void Context::check_capture(const Capture& cap, const DrawRecord& d) const {
  if (cap.mode != Topology::Points && cap.mode != Topology::Lines && cap.mode != Topology::Triangles)
    throw Error("draw: transform feedback writes points, lines or triangles, not topology " +
                std::to_string(int(cap.mode)));
  if (cap.buffers.empty() || cap.buffers.size() > size_t(kMaxCaptureBuffers))
    throw Error("draw: transform feedback needs 1 to " + std::to_string(kMaxCaptureBuffers) +
                " buffers, not " + std::to_string(cap.buffers.size()));
  const ProgramBase& prog = *d.program;
  const int size = prim_size(prog.geometry_input ? emitted_list(prog.geometry_output) : d.topology);
  if (size != prim_size(cap.mode))
    throw Error("draw: the draw gives primitives of " + std::to_string(size) +
                " vertices, but transform feedback writes primitives of " +
                std::to_string(prim_size(cap.mode)));
  for (size_t i = 0; i < cap.buffers.size(); ++i) {
    const CaptureBuffer& b = cap.buffers[i];
    if (!b.buffer) throw Error("draw: transform feedback buffer " + std::to_string(i) + " is null");
    if (b.offset % 4)
      throw Error("draw: transform feedback buffer " + std::to_string(i) + " offset is not 4-aligned");
    for (const int w : b.words)
      if (w >= prog.varyings || w < kCapturePosition - 3)
        throw Error("draw: transform feedback word source " + std::to_string(w) +
                    " is not one of the program's " + std::to_string(prog.varyings) +
                    " varying components or its position");
  }
}
}  // namespace tessel::gpu
