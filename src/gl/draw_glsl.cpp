// Draws with a GLSL program (GL 3.3 §2.8.3 and §2.11): the draw calls of GL 1.1 to 3.3 over
// the generic attribute arrays of the bound vertex array object, and the immediate-mode and
// fixed-function array batches when a program is current (compatibility contexts).
//
// Attribute arrays in buffer objects are read in place by the gpu layer, which checks every
// fetch against the buffer's size (a draw past the end is GL_INVALID_OPERATION, never a read
// out of bounds). Arrays in client memory (compatibility vertex array object 0), and types
// the gpu layer does not read (GL_DOUBLE, the packed 2_10_10_10 types, GL_BGRA), are copied
// to floats over the range of vertices the draw reads.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <algorithm>
#include <cstring>
#include <limits>

#include "api.hpp"

namespace tessel::gl {

// The four components of a packed GL_INT_2_10_10_10_REV / GL_UNSIGNED_INT_2_10_10_10_REV
// value (GL 3.3 §2.8.2), x in the low bits.
void unpack_2_10_10_10(uint32_t w, bool is_signed, bool normalized, float* out) {
  const int bits[4] = {10, 10, 10, 2};
  int shift = 0;
  for (int i = 0; i < 4; ++i) {
    const uint32_t raw = (w >> shift) & ((1u << bits[i]) - 1u);
    shift += bits[i];
    if (is_signed) {
      const int32_t v = int32_t(raw << (32 - bits[i])) >> (32 - bits[i]);
      const double max = double((1 << (bits[i] - 1)) - 1);
      out[i] = normalized ? float(std::max(-1.0, v / max)) : float(v);
    } else {
      const double max = double((1u << bits[i]) - 1u);
      out[i] = normalized ? float(raw / max) : float(raw);
    }
  }
}

namespace {

bool gpu_attrib_type(GLenum t, gpu::AttribType& out) {
  switch (t) {
    case GL_FLOAT: out = gpu::AttribType::F32; return true;
    case GL_HALF_FLOAT: out = gpu::AttribType::F16; return true;
    case GL_BYTE: out = gpu::AttribType::I8; return true;
    case GL_UNSIGNED_BYTE: out = gpu::AttribType::U8; return true;
    case GL_SHORT: out = gpu::AttribType::I16; return true;
    case GL_UNSIGNED_SHORT: out = gpu::AttribType::U16; return true;
    case GL_INT: out = gpu::AttribType::I32; return true;
    case GL_UNSIGNED_INT: out = gpu::AttribType::U32; return true;
    default: return false;
  }
}

// One component of a normalized or plain value, as GL 3.3 §2.8 converts it to float.
float component(const uint8_t* p, GLenum type, bool normalized) {
  auto norm = [&](double v, double max, bool is_signed) {
    if (!normalized) return float(v);
    // GL 3.3 Table 2.2 / §2.1.6.1: signed values map to [-1, 1] as (2c + 1) / (2^b - 1).
    return is_signed ? float((2.0 * v + 1.0) / (2.0 * max + 1.0)) : float(v / max);
  };
  switch (type) {
    case GL_BYTE: return norm(double(int8_t(p[0])), 127.0, true);
    case GL_UNSIGNED_BYTE: return norm(double(p[0]), 255.0, false);
    case GL_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return norm(double(v), 32767.0, true);
    }
    case GL_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return norm(double(v), 65535.0, false);
    }
    case GL_INT: {
      int32_t v;
      std::memcpy(&v, p, 4);
      return norm(double(v), 2147483647.0, true);
    }
    case GL_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return norm(double(v), 4294967295.0, false);
    }
    case GL_FLOAT: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case GL_DOUBLE: {
      double v;
      std::memcpy(&v, p, 8);
      return float(v);
    }
    case GL_HALF_FLOAT: {
      uint16_t h;
      std::memcpy(&h, p, 2);
      return gpu::half_to_float(h);
    }
    default: return 0.0f;
  }
}

int component_bytes(GLenum type) {
  switch (type) {
    case GL_BYTE:
    case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT:
    case GL_UNSIGNED_SHORT:
    case GL_HALF_FLOAT: return 2;
    case GL_DOUBLE: return 8;
    default: return 4;
  }
}

bool packed_type(GLenum t) { return t == GL_INT_2_10_10_10_REV || t == GL_UNSIGNED_INT_2_10_10_10_REV; }

}  // namespace

GLsizei AttribArray::effective_stride() const {
  if (stride) return stride;
  if (packed_type(type)) return 4;
  return GLsizei((size == GL_BGRA ? 4 : size) * component_bytes(type));
}

namespace {

// The bytes an attribute array reads from: a buffer object's (size-checked) or client memory.
struct ArraySource {
  const uint8_t* base = nullptr;                      // element 0
  size_t limit = std::numeric_limits<size_t>::max();  // bytes readable from base
};

// Copies elements [lo, hi] of an array into floats, 4 per element, at element index - lo.
// False when an element lies outside its buffer.
bool convert_array(const AttribArray& a, const ArraySource& src, uint32_t lo, uint32_t hi,
                   std::vector<float>& out) {
  const size_t stride = size_t(a.effective_stride());
  const int n = a.size == GL_BGRA ? 4 : a.size;
  const size_t elem = packed_type(a.type) ? 4 : size_t(n) * size_t(component_bytes(a.type));
  out.assign(size_t(hi - lo + 1) * 4, 0.0f);
  for (uint32_t i = lo; i <= hi; ++i) {
    const size_t at = size_t(i) * stride;
    if (at > src.limit || elem > src.limit - at) return false;
    const uint8_t* p = src.base + at;
    float* o = &out[size_t(i - lo) * 4];
    o[3] = 1.0f;
    if (packed_type(a.type)) {
      uint32_t w;
      std::memcpy(&w, p, 4);
      unpack_2_10_10_10(w, a.type == GL_INT_2_10_10_10_REV, a.normalized, o);
      if (n == 3) o[3] = 1.0f;
      continue;
    }
    for (int k = 0; k < n; ++k)
      o[k] = component(p + size_t(k) * size_t(component_bytes(a.type)), a.type, a.normalized);
    if (a.size == GL_BGRA) std::swap(o[0], o[2]);
  }
  return true;
}

uint32_t restart_value(gpu::IndexType t) {
  return t == gpu::IndexType::U8 ? 0xFFu : t == gpu::IndexType::U16 ? 0xFFFFu : 0xFFFFFFFFu;
}

uint32_t read_index(const uint8_t* p, gpu::IndexType t, size_t i) {
  switch (t) {
    case gpu::IndexType::U8: return p[i];
    case gpu::IndexType::U16: {
      uint16_t v;
      std::memcpy(&v, p + 2 * i, 2);
      return v;
    }
    default: {
      uint32_t v;
      std::memcpy(&v, p + 4 * i, 4);
      return v;
    }
  }
}

// GL_QUADS, GL_QUAD_STRIP and GL_POLYGON as independent triangles over vertex numbers
// `ids` (restart entries split the sequence). Each triangle ends with the vertex flat shading
// takes (GL 3.3 compatibility Table 2.15: a quad's fourth vertex, a strip quad's vertex
// 2i + 3, a polygon's first), split along the diagonal Mesa uses; with provoking_first
// (glProvokingVertex(GL_FIRST_VERTEX_CONVENTION), under which Mesa keeps those vertices) each
// triangle begins with it instead, the winding kept.
// `masks` gets each triangle's edge flags (gpu RenderState::edge_masks: bit k for the edge
// from its vertex k to vertex k + 1): the cuts inside a quad or polygon are not boundary
// edges (GL 2.1 §2.6.2).
std::vector<uint32_t> triangulate(GLenum mode, const std::vector<uint32_t>& ids, bool restart,
                                  uint32_t restart_id, bool provoking_first, std::vector<uint8_t>& masks) {
  std::vector<uint32_t> out;
  masks.clear();
  size_t start = 0;
  auto run = [&](size_t b, size_t e) {
    const size_t n = e - b;
    const uint32_t* v = ids.data() + b;
    if (mode == GL_QUADS) {
      for (size_t i = 0; i + 3 < n; i += 4) {
        out.insert(out.end(), {v[i], v[i + 1], v[i + 3], v[i + 1], v[i + 2], v[i + 3]});
        masks.insert(masks.end(), {0b101, 0b011});
      }
    } else if (mode == GL_QUAD_STRIP) {
      for (size_t i = 0; i + 3 < n; i += 2) {
        out.insert(out.end(), {v[i], v[i + 1], v[i + 3], v[i + 2], v[i], v[i + 3]});
        masks.insert(masks.end(), {0b011, 0b101});
      }
    } else {  // GL_POLYGON
      for (size_t i = 1; i + 1 < n; ++i) {
        out.insert(out.end(), {v[i], v[i + 1], v[0]});
        masks.push_back(uint8_t(1u | (i + 2 == n ? 2u : 0u) | (i == 1 ? 4u : 0u)));
      }
    }
  };
  for (size_t i = 0; i <= ids.size(); ++i) {
    if (i == ids.size() || (restart && ids[i] == restart_id)) {
      run(start, i);
      start = i + 1;
    }
  }
  if (provoking_first) {
    rotate_provoking_first(out);  // (a, b, c) becomes (c, a, b): edge c-a comes first
    for (uint8_t& m : masks) m = uint8_t(((m << 1) | (m >> 2)) & 7u);
  }
  return out;
}

}  // namespace

bool topology_of(GLenum mode, bool core, gpu::Topology& out, bool& decompose) {
  decompose = false;
  switch (mode) {
    case GL_POINTS: out = gpu::Topology::Points; return true;
    case GL_LINES: out = gpu::Topology::Lines; return true;
    case GL_LINE_STRIP: out = gpu::Topology::LineStrip; return true;
    case GL_LINE_LOOP: out = gpu::Topology::LineLoop; return true;
    case GL_TRIANGLES: out = gpu::Topology::Triangles; return true;
    case GL_TRIANGLE_STRIP: out = gpu::Topology::TriangleStrip; return true;
    case GL_TRIANGLE_FAN: out = gpu::Topology::TriangleFan; return true;
    case GL_LINES_ADJACENCY: out = gpu::Topology::LinesAdjacency; return true;
    case GL_LINE_STRIP_ADJACENCY: out = gpu::Topology::LineStripAdjacency; return true;
    case GL_TRIANGLES_ADJACENCY: out = gpu::Topology::TrianglesAdjacency; return true;
    case GL_TRIANGLE_STRIP_ADJACENCY: out = gpu::Topology::TriangleStripAdjacency; return true;
    case GL_QUADS:
    case GL_QUAD_STRIP:
    case GL_POLYGON:
      out = gpu::Topology::Triangles;
      decompose = true;
      return !core;
    default: return false;
  }
}

// --- the draw --------------------------------------------------------------------------

// The attribute locations no array feeds read the current values (glVertexAttrib*, GL 3.3
// §2.7): one element each in a small buffer, repeated for every vertex and instance.
void Context::bind_current_values(gpu::VertexLayout& layout,
                                  std::vector<std::unique_ptr<gpu::Buffer>>& keep) {
  auto values = std::make_unique<gpu::Buffer>(generic_current.data(), sizeof generic_current);
  for (int l = 0; l < kMaxVertexAttribs; ++l) {
    if (layout.attribs[size_t(l)].enabled) continue;
    const GLenum t = generic_type[size_t(l)];
    const gpu::AttribType type = t == GL_INT            ? gpu::AttribType::I32
                                 : t == GL_UNSIGNED_INT ? gpu::AttribType::U32
                                                        : gpu::AttribType::F32;
    layout.attribs[size_t(l)] = {true, l, 4, type, false, t != GL_FLOAT, 0};
    layout.bindings[size_t(l)] = {values.get(), size_t(l) * 16, 16, 0xFFFFFFFFu};
  }
  keep.push_back(std::move(values));
}

void Context::draw_generic(const GenericDraw& d) {
  touch();
  if (!executable) return;  // no program: nothing is drawn (the fixed-function path is api_arrays)
  if (d.count == 0 || d.instances == 0) return;
  VertexArrayObject& va = vao();
  std::vector<std::unique_ptr<gpu::Buffer>> keep;

  // The index data: a range of the element array buffer, or client memory copied.
  gpu::DrawCall call;
  call.topology = d.topology;
  call.first = d.indexed ? 0 : uint32_t(d.first);
  call.count = uint32_t(d.count);
  call.instance_count = uint32_t(d.instances);
  call.base_vertex = d.base_vertex;
  const uint8_t* index_bytes = nullptr;
  size_t index_size = 0;
  if (d.indexed) {
    call.index_type = d.index_type;
    index_size = d.index_type == gpu::IndexType::U8 ? 1 : d.index_type == gpu::IndexType::U16 ? 2 : 4;
    const size_t offset = reinterpret_cast<size_t>(d.indices);
    if (va.element_buffer) {
      if (va.element_buffer->mapped) return error(GL_INVALID_OPERATION);
      const gpu::Buffer& eb = va.element_buffer->data;
      if (offset > eb.size() || size_t(d.count) * index_size > eb.size() - offset)
        return error(GL_INVALID_OPERATION);  // reads past the end of the element array buffer
      index_bytes = reinterpret_cast<const uint8_t*>(eb.data()) + offset;
      call.index_buffer = &eb;
      call.index_offset = offset;
    } else {
      if (!d.indices) return;
      index_bytes = static_cast<const uint8_t*>(d.indices);
      keep.push_back(std::make_unique<gpu::Buffer>(index_bytes, size_t(d.count) * index_size));
      call.index_buffer = keep.back().get();
      call.index_offset = 0;
    }
  }
  const uint32_t restart_id = primitive_restart_index;
  const bool restart = primitive_restart && d.indexed;

  // The range of vertices read (for arrays copied from client memory or converted).
  bool have_range = false;
  uint32_t lo = 0, hi = 0;
  auto range = [&]() -> bool {
    if (have_range) return hi >= lo;
    have_range = true;
    if (!d.indexed) {
      lo = uint32_t(d.first);
      hi = uint32_t(d.first + d.count - 1);
      return true;
    }
    lo = std::numeric_limits<uint32_t>::max();
    hi = 0;
    for (size_t i = 0; i < size_t(d.count); ++i) {
      const uint32_t v = read_index(index_bytes, d.index_type, i);
      if (restart && v == restart_id) continue;
      const int64_t at = int64_t(v) + d.base_vertex;
      if (at < 0 || at > int64_t(std::numeric_limits<uint32_t>::max())) continue;
      lo = std::min(lo, uint32_t(at));
      hi = std::max(hi, uint32_t(at));
    }
    return hi >= lo;
  };

  gpu::VertexLayout layout;
  for (int l = 0; l < kMaxVertexAttribs; ++l) {
    const AttribArray& a = va.attribs[size_t(l)];
    if (!a.enabled) continue;
    if (a.buffer && a.buffer->mapped) return error(GL_INVALID_OPERATION);
    gpu::AttribType t = gpu::AttribType::F32;
    const bool direct = gpu_attrib_type(a.type, t) && a.size != GL_BGRA;
    if (a.buffer && direct) {
      layout.bindings[size_t(l)] = {&a.buffer->data, reinterpret_cast<size_t>(a.pointer),
                                    uint32_t(a.effective_stride()), a.divisor};
      layout.attribs[size_t(l)] = {true, l, a.size, t, a.normalized, a.integer, 0};
      continue;
    }
    // Copied (client memory) or converted to floats: over the vertices, or the instances
    // the draw reads.
    ArraySource src;
    if (a.buffer) {
      const size_t off = reinterpret_cast<size_t>(a.pointer);
      if (off > a.buffer->data.size()) return error(GL_INVALID_OPERATION);
      src.base = reinterpret_cast<const uint8_t*>(a.buffer->data.data()) + off;
      src.limit = a.buffer->data.size() - off;
    } else {
      if (!a.pointer) continue;  // nothing to read: the current value
      src.base = static_cast<const uint8_t*>(a.pointer);
    }
    uint32_t first = 0, last = 0;
    if (a.divisor) {
      last = uint32_t((d.instances - 1) / GLsizei(a.divisor));
    } else {
      if (!range()) return;  // every index is a restart: nothing to draw
      first = lo;
      last = hi;
    }
    std::vector<float> floats;
    if (direct && !a.buffer) {
      // Client memory in a type the gpu reads: the bytes of elements [0, last], as they are.
      const size_t stride = size_t(a.effective_stride());
      const size_t bytes = size_t(last) * stride + size_t(a.size) * size_t(component_bytes(a.type));
      keep.push_back(std::make_unique<gpu::Buffer>(src.base, bytes));
      layout.bindings[size_t(l)] = {keep.back().get(), 0, uint32_t(stride), a.divisor};
      layout.attribs[size_t(l)] = {true, l, a.size, t, a.normalized, a.integer, 0};
      continue;
    }
    if (!convert_array(a, src, first, last, floats)) return error(GL_INVALID_OPERATION);
    // Elements [first, last] at index - first: padded in front so that index i is element i.
    std::vector<float> padded(size_t(first) * 4 + floats.size());
    std::copy(floats.begin(), floats.end(), padded.begin() + ptrdiff_t(size_t(first) * 4));
    keep.push_back(std::make_unique<gpu::Buffer>(padded.data(), padded.size() * sizeof(float)));
    layout.bindings[size_t(l)] = {keep.back().get(), 0, 16, a.divisor};
    layout.attribs[size_t(l)] = {true, l, 4, gpu::AttribType::F32, false, false, 0};
  }

  // GL_QUADS, GL_QUAD_STRIP, GL_POLYGON (compatibility): triangles over an index list; a
  // primitive restart index other than the type's largest value: indices rewritten to 32 bits.
  std::vector<uint8_t> masks;
  if (d.decompose || (restart && restart_id != restart_value(d.index_type))) {
    std::vector<uint32_t> ids(size_t(d.count));
    for (size_t i = 0; i < ids.size(); ++i) {
      if (!d.indexed) {
        ids[i] = uint32_t(d.first) + uint32_t(i);
        continue;
      }
      const uint32_t v = read_index(index_bytes, d.index_type, i);
      ids[i] = restart && v == restart_id ? 0xFFFFFFFFu : v;
    }
    if (d.decompose)
      ids = triangulate(d.mode, ids, restart, 0xFFFFFFFFu,
                        s.light.provoking_vertex == GL_FIRST_VERTEX_CONVENTION, masks);
    if (ids.empty()) return;
    keep.push_back(std::make_unique<gpu::Buffer>(ids.data(), ids.size() * sizeof(uint32_t)));
    call.first = 0;
    call.count = uint32_t(ids.size());
    call.index_buffer = keep.back().get();
    call.index_offset = 0;
    call.index_type = gpu::IndexType::U32;
  }

  bind_current_values(layout, keep);
  gpu::RenderState rs = render_state(false);
  rs.primitive_restart = restart;
  // Polygon-mode lines and points draw only boundary edges: not the cuts of decomposed
  // polygons, and none with the current edge flag false (the flag is a vertex attribute the
  // program passes through, GL 2.1 §2.6.2). An edge flag array is not read here.
  const bool unfilled = s.polygon.mode_front != GL_FILL || s.polygon.mode_back != GL_FILL;
  if (unfilled && (d.decompose || !s.current.edge)) {
    const size_t tris = d.decompose ? masks.size() : size_t(d.count) * call.instance_count;
    masks.resize(tris, 0);
    if (!s.current.edge) std::fill(masks.begin(), masks.end(), uint8_t(0));
    keep.push_back(std::make_unique<gpu::Buffer>(masks.data(), masks.size()));
    rs.edge_masks = reinterpret_cast<const uint8_t*>(keep.back()->data());
    rs.edge_mask_count = uint32_t(masks.size());
  }
  using T = gpu::Topology;
  const T t = d.topology;
  const PrimClass cls = t == T::Points ? PrimClass::Points
                        : t == T::Lines || t == T::LineStrip || t == T::LineLoop || t == T::LinesAdjacency ||
                                t == T::LineStripAdjacency
                            ? PrimClass::Lines
                            : PrimClass::Triangles;
  run_program(executable_run(cls), layout, call, rs);
  for (auto& b : keep) keep_until_finished(std::move(b));
}

void Context::draw_program_batch(ProgramRun run, const gpu::Buffer& vbuf, const std::vector<FFExtra>& extra,
                                 const gpu::DrawCall& call, gpu::RenderState rs) {
  gpu::VertexLayout layout;
  constexpr uint32_t stride = sizeof(FFVertex);
  layout.attrib(glsl::kLocationVertex, vbuf, 4, gpu::AttribType::F32, stride, offsetof(FFVertex, pos));
  layout.attrib(glsl::kLocationNormal, vbuf, 3, gpu::AttribType::F32, stride, offsetof(FFVertex, normal));
  layout.attrib(glsl::kLocationColor, vbuf, 4, gpu::AttribType::F32, stride, offsetof(FFVertex, color));
  layout.attrib(glsl::kLocationMultiTexCoord0, vbuf, 4, gpu::AttribType::F32, stride,
                offsetof(FFVertex, tex));
  std::vector<std::unique_ptr<gpu::Buffer>> keep;
  // The other coordinate sets, the secondary colour and the fog coordinate: each vertex's, or
  // the defaults (one record for every vertex) when the batch has none.
  static const FFExtra kDefaults = FFExtra::defaults();
  if (extra.empty())
    keep.push_back(std::make_unique<gpu::Buffer>(&kDefaults, sizeof kDefaults));
  else
    keep.push_back(std::make_unique<gpu::Buffer>(extra.data(), extra.size() * sizeof(FFExtra)));
  const gpu::Buffer& xb = *keep.back();
  constexpr uint32_t xstride = sizeof(FFExtra);
  const uint32_t divisor = extra.empty() ? 0xFFFFFFFFu : 0u;  // the one record for every vertex
  for (int i = 1; i < kMaxTexCoords; ++i)
    layout.attrib(glsl::kLocationMultiTexCoord0 + i, xb, 4, gpu::AttribType::F32, xstride,
                  uint32_t(offsetof(FFExtra, tex) + size_t(i - 1) * sizeof(FFExtra::tex[0])), false, divisor);
  layout.attrib(glsl::kLocationSecondaryColor, xb, 4, gpu::AttribType::F32, xstride,
                uint32_t(offsetof(FFExtra, secondary)), false, divisor);
  layout.attrib(glsl::kLocationFogCoord, xb, 1, gpu::AttribType::F32, xstride,
                uint32_t(offsetof(FFExtra, fog_coord)), false, divisor);
  // Polygon-mode lines and points, and stippled lines: the vertices' edge flags as edge masks,
  // since a program has no varying to carry them.
  if (std::unique_ptr<gpu::Buffer> masks = batch_edge_masks(vbuf, call)) {
    rs.edge_masks = reinterpret_cast<const uint8_t*>(masks->data());
    rs.edge_mask_count = uint32_t(masks->size());
    keep.push_back(std::move(masks));
  }
  bind_current_values(layout, keep);
  run_program(run, layout, call, rs);
  for (auto& b : keep) keep_until_finished(std::move(b));
}

void Context::run_program(ProgramRun run, const gpu::VertexLayout& layout, const gpu::DrawCall& call,
                          gpu::RenderState rs) {
  // A geometry shader that writes gl_Layer into a layered framebuffer: the draw runs once a
  // layer, each run keeping the primitives of its layer (§4.4.7). Other draws into a layered
  // framebuffer render into layer 0.
  const glsl::GeometryInfo* gi = run.program.geometry();
  const int layers = gi && gi->writes_layer ? draw_layers() : 0;
  gpu::DrawCall captured = call;
  if (feedback.active && &run.program == feedback.program.get()) captured.capture = &feedback.capture;
  if (layers > 0) {
    // Transform feedback captures the primitives once, in a run of their own.
    if (captured.capture) {
      gpu::RenderState discard = rs;
      discard.rasterizer_discard = true;
      run_program_layer(run, layout, captured, discard, 0);
      if (rs.rasterizer_discard) return;
    }
    rs.layer_count = layers;
    for (int layer = 0; layer < layers; ++layer) {
      rs.layer = layer;
      run_program_layer(run, layout, call, rs, layer);
    }
    return;
  }
  run_program_layer(run, layout, captured, rs, 0);
}

void Context::run_program_layer(ProgramRun run, const gpu::VertexLayout& layout, const gpu::DrawCall& call,
                                gpu::RenderState rs, int layer) {
  if (!bind_draw_target(layer)) return;
  feed_compat_state(run);
  // GL_PROGRAM_POINT_SIZE is for the application's programs; fixed function's generated ones
  // keep glPointSize's size.
  rs.program_point_size = program_point_size && &run.program == executable.get();
  rs.depth_clamp = depth_clamp;
  rs.dual_source = run.program.dual_source();
  std::vector<glsl::TextureBinding> units;
  if (!texture_units_for_draw(run.program, units)) return error(GL_INVALID_OPERATION);
  const std::vector<glsl::BufferBinding> ubos = uniform_buffers_for_draw();
  guarded([&] { run.program.draw(*gpu_, layout, rs, call, units, ubos); });
}

namespace {

// The texture target a sampler type reads (GL 3.3 Table 2.10); false for other types.
bool sampler_target(uint32_t type, TexTarget& t) {
  switch (type) {
    case GL_SAMPLER_1D:
    case GL_SAMPLER_1D_SHADOW:
    case GL_INT_SAMPLER_1D:
    case GL_UNSIGNED_INT_SAMPLER_1D: t = TexTarget::T1D; return true;
    case GL_SAMPLER_2D:
    case GL_SAMPLER_2D_SHADOW:
    case GL_INT_SAMPLER_2D:
    case GL_UNSIGNED_INT_SAMPLER_2D: t = TexTarget::T2D; return true;
    case GL_SAMPLER_3D:
    case GL_INT_SAMPLER_3D:
    case GL_UNSIGNED_INT_SAMPLER_3D: t = TexTarget::T3D; return true;
    case GL_SAMPLER_CUBE:
    case GL_SAMPLER_CUBE_SHADOW:
    case GL_INT_SAMPLER_CUBE:
    case GL_UNSIGNED_INT_SAMPLER_CUBE: t = TexTarget::Cube; return true;
    case GL_SAMPLER_1D_ARRAY:
    case GL_SAMPLER_1D_ARRAY_SHADOW:
    case GL_INT_SAMPLER_1D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_1D_ARRAY: t = TexTarget::T1DArray; return true;
    case GL_SAMPLER_2D_ARRAY:
    case GL_SAMPLER_2D_ARRAY_SHADOW:
    case GL_INT_SAMPLER_2D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY: t = TexTarget::T2DArray; return true;
    case GL_SAMPLER_2D_RECT:
    case GL_SAMPLER_2D_RECT_SHADOW:
    case GL_INT_SAMPLER_2D_RECT:
    case GL_UNSIGNED_INT_SAMPLER_2D_RECT: t = TexTarget::Rect; return true;
    case GL_SAMPLER_BUFFER:
    case GL_INT_SAMPLER_BUFFER:
    case GL_UNSIGNED_INT_SAMPLER_BUFFER: t = TexTarget::Buffer; return true;
    case GL_SAMPLER_2D_MULTISAMPLE:
    case GL_INT_SAMPLER_2D_MULTISAMPLE:
    case GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE: t = TexTarget::T2DMS; return true;
    case GL_SAMPLER_2D_MULTISAMPLE_ARRAY:
    case GL_INT_SAMPLER_2D_MULTISAMPLE_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE_ARRAY: t = TexTarget::T2DMSArray; return true;
    default: return false;
  }
}

}  // namespace

// The units the current program's samplers read, each with the texture of the sampler's
// target. Two sampler types on one unit make the draw GL_INVALID_OPERATION (GL 3.3 §2.11.7);
// an incomplete texture samples as (0, 0, 0, 1) (§3.8.14). Returns false on the error.
bool Context::texture_units_for_draw(const glsl::Program& program, std::vector<glsl::TextureBinding>& units) {
  units.assign(kMaxTextureUnits, glsl::TextureBinding{});
  std::array<int8_t, kMaxTextureUnits> want;
  want.fill(-1);
  for (const glsl::Variable& v : program.uniforms()) {
    TexTarget target;
    if (!sampler_target(v.type, target)) continue;
    for (int e = 0; e < v.size; ++e) {
      uint32_t unit = 0;
      if (!program.get_uniform_words(v.location + e, &unit) || unit >= uint32_t(kMaxTextureUnits)) continue;
      if (want[unit] >= 0 && want[unit] != int8_t(target)) return false;
      want[unit] = int8_t(target);
    }
  }
  for (int i = 0; i < kMaxTextureUnits; ++i) {
    if (want[size_t(i)] < 0) continue;
    const TexTarget target = TexTarget(want[size_t(i)]);
    TextureObject& t = bound_texture(target, i);
    if (!update_gpu_texture(*this, t)) continue;
    const SamplerParams& p = sampler_params(i, t);
    if (!texture_complete(t, p)) continue;
    glsl::TextureBinding& b = units[size_t(i)];
    b.sampler = sampler_state_of(p, t);
    b.sampler.seamless = cube_map_seamless;
    b.swizzle = swizzle_of(t, core_profile);
    switch (target) {
      case TexTarget::T1D:
      case TexTarget::T2D:
      case TexTarget::Rect:
      case TexTarget::T2DMS: b.texture_2d = t.tex2d.get(); break;
      case TexTarget::T3D: b.texture_3d = t.tex3d.get(); break;
      case TexTarget::Cube: b.texture_cube = t.cube.get(); break;
      case TexTarget::T1DArray:
      case TexTarget::T2DArray:
      case TexTarget::T2DMSArray: b.texture_2d_array = t.array.get(); break;
      case TexTarget::Buffer: b.texture_buffer = t.tbuf.get(); break;
    }
  }
  return true;
}

std::vector<glsl::BufferBinding> Context::uniform_buffers_for_draw() const {
  std::vector<glsl::BufferBinding> out(kMaxUniformBufferBindings);
  for (int i = 0; i < kMaxUniformBufferBindings; ++i) {
    const IndexedBuffer& b = uniform_bindings[size_t(i)];
    if (!b.buffer) continue;
    out[size_t(i)] = {&b.buffer->data, size_t(b.offset), size_t(b.size)};
  }
  return out;
}

// The compatibility state GLSL 1.10-1.50 programs read (GLSL 1.20 §7.5): written to the
// program's gl_ uniforms when it changed since the last draw with that program.
void Context::feed_compat_state(ProgramRun run) {
  if (core_profile) return;
  CompatSnapshot now;
  now.modelview = modelview();
  now.projection = projection();
  for (int i = 0; i < kMaxTexCoords; ++i) now.texture[size_t(i)] = texture_matrix(i);
  now.light = s.light;
  now.fog_color = s.fog.color;
  now.fog = {s.fog.density, s.fog.start, s.fog.end};
  now.point_size = s.point.size;
  now.point = {s.point.size_min,       s.point.size_max,       s.point.fade_threshold,
               s.point.attenuation[0], s.point.attenuation[1], s.point.attenuation[2]};
  for (int i = 0; i < kMaxTexCoords; ++i) {
    const TextureUnitState& u = s.units[size_t(i)];
    now.env_color[size_t(i)] = u.env_color;
    now.eye_plane[size_t(i)] = u.eye_plane;
    now.object_plane[size_t(i)] = u.object_plane;
  }
  now.depth_range = {float(s.viewport.near_), float(s.viewport.far_)};
  for (int i = 0; i < kMaxClipPlanes; ++i)
    now.clip_planes[size_t(i)] = glm::vec4(s.transform.clip_plane[size_t(i)]);
  CompatCache& cache = run.cache;
  if (cache.program == &run.program && cache.state == now) return;
  cache.program = &run.program;
  cache.state = now;
  glsl::Program& g = run.program;
  auto put = [&](const std::string& name, const float* v, int n) {
    const int loc = g.uniform_location(name);
    if (loc >= 0) g.set_uniform(loc, v, n);
  };
  auto put4 = [&](const std::string& name, const glm::vec4& v) { put(name, &v[0], 4); };
  auto put1 = [&](const std::string& name, float v) { put(name, &v, 1); };
  g.set_compat_matrices(now.modelview, now.projection);
  // GLSL 1.20 §7.5: each coordinate set's texture matrix and its derived forms, texture
  // environment colour and coordinate generation planes.
  for (int i = 0; i < kMaxTexCoords; ++i) {
    const std::string n{'[', char('0' + i), ']'};
    const glm::mat4& t = now.texture[size_t(i)];
    const glm::mat4 inv = glm::inverse(t);
    const glm::mat4 tr = glm::transpose(t), it = glm::transpose(inv);
    put(std::string("gl_TextureMatrix").append(n), &t[0][0], 16);
    put(std::string("gl_TextureMatrixInverse").append(n), &inv[0][0], 16);
    put(std::string("gl_TextureMatrixTranspose").append(n), &tr[0][0], 16);
    put(std::string("gl_TextureMatrixInverseTranspose").append(n), &it[0][0], 16);
    put4(std::string("gl_TextureEnvColor").append(n), now.env_color[size_t(i)]);
    for (int k = 0; k < 4; ++k) {
      const char st = "STRQ"[k];
      put4(std::string("gl_EyePlane").append(1, st).append(n), now.eye_plane[size_t(i)][size_t(k)]);
      put4(std::string("gl_ObjectPlane").append(1, st).append(n), now.object_plane[size_t(i)][size_t(k)]);
    }
  }
  const LightState& L = now.light;
  for (int i = 0; i < kMaxLights; ++i) {
    const FFLight& l = L.light[size_t(i)];
    const std::string n = "gl_LightSource[" + std::to_string(i) + "].";
    put4(n + "ambient", l.ambient);
    put4(n + "diffuse", l.diffuse);
    put4(n + "specular", l.specular);
    put4(n + "position", l.position);
    // GLSL 1.20 §7.5: the half vector of an infinite viewer, normalize(VP + (0, 0, 1)).
    const glm::vec3 vp = l.position.w != 0.0f ? glm::vec3(l.position) / l.position.w : glm::vec3(l.position);
    const glm::vec3 h = glm::vec3(glm::normalize(glm::normalize(vp) + glm::vec3(0, 0, 1)));
    put4(n + "halfVector", glm::vec4(h, 0.0f));
    put(n + "spotDirection", &l.spot_direction[0], 3);
    put1(n + "spotExponent", l.spot_exponent);
    put1(n + "spotCutoff", L.spot_cutoff[size_t(i)]);
    put1(n + "spotCosCutoff", l.spot_cos_cutoff);
    put1(n + "constantAttenuation", l.k0);
    put1(n + "linearAttenuation", l.k1);
    put1(n + "quadraticAttenuation", l.k2);
    for (int side = 0; side < 2; ++side) {
      const FFMaterial& m = L.material[size_t(side)];
      const std::string pr =
          std::string(side ? "gl_BackLightProduct[" : "gl_FrontLightProduct[") + std::to_string(i) + "].";
      put4(pr + "ambient", m.ambient * l.ambient);
      put4(pr + "diffuse", m.diffuse * l.diffuse);
      put4(pr + "specular", m.specular * l.specular);
    }
  }
  for (int side = 0; side < 2; ++side) {
    const FFMaterial& m = L.material[size_t(side)];
    const std::string n = side ? "gl_BackMaterial." : "gl_FrontMaterial.";
    put4(n + "emission", m.emission);
    put4(n + "ambient", m.ambient);
    put4(n + "diffuse", m.diffuse);
    put4(n + "specular", m.specular);
    put1(n + "shininess", m.shininess);
    put4(std::string(side ? "gl_BackLightModelProduct" : "gl_FrontLightModelProduct") + ".sceneColor",
         m.emission + m.ambient * L.model_ambient);
  }
  put4("gl_LightModel.ambient", L.model_ambient);
  put1("gl_DepthRange.near", now.depth_range[0]);
  put1("gl_DepthRange.far", now.depth_range[1]);
  put1("gl_DepthRange.diff", now.depth_range[1] - now.depth_range[0]);
  put1("gl_Point.size", now.point_size);
  put1("gl_Point.sizeMin", now.point[0]);
  put1("gl_Point.sizeMax", now.point[1]);
  put1("gl_Point.fadeThresholdSize", now.point[2]);
  put1("gl_Point.distanceConstantAttenuation", now.point[3]);
  put1("gl_Point.distanceLinearAttenuation", now.point[4]);
  put1("gl_Point.distanceQuadraticAttenuation", now.point[5]);
  put4("gl_Fog.color", now.fog_color);
  put1("gl_Fog.density", now.fog[0]);
  put1("gl_Fog.start", now.fog[1]);
  put1("gl_Fog.end", now.fog[2]);
  put1("gl_Fog.scale", now.fog[2] != now.fog[1] ? 1.0f / (now.fog[2] - now.fog[1]) : 0.0f);
  for (int i = 0; i < kMaxClipPlanes; ++i)
    put4("gl_ClipPlane[" + std::to_string(i) + "]", now.clip_planes[size_t(i)]);
}

}  // namespace tessel::gl

namespace tessel::gl {

void draw_generic_call(Context& c, GLenum mode, GLint first, GLsizei count, GLsizei instances, GLenum type,
                       const void* indices, GLint base_vertex) {
  GenericDraw d;
  d.mode = mode;
  if (!topology_of(mode, c.core_profile, d.topology, d.decompose)) return c.error(GL_INVALID_ENUM);
  const bool indexed = type != GL_NONE;
  if (indexed) {
    switch (type) {
      case GL_UNSIGNED_BYTE: d.index_type = gpu::IndexType::U8; break;
      case GL_UNSIGNED_SHORT: d.index_type = gpu::IndexType::U16; break;
      case GL_UNSIGNED_INT: d.index_type = gpu::IndexType::U32; break;
      default: return c.error(GL_INVALID_ENUM);
    }
  }
  if (count < 0 || first < 0 || instances < 0) return c.error(GL_INVALID_VALUE);
  if (c.in_begin) return c.error(GL_INVALID_OPERATION);
  // An incomplete (or, current without a surface, absent) draw framebuffer comes first, as in
  // Mesa's checks.
  if (!c.draw_framebuffer_complete()) return c.error(GL_INVALID_FRAMEBUFFER_OPERATION);
  // GL 3.3 core: no vertex array object bound, or client-side indices, is an error.
  if (!c.vertex_arrays.count(c.bound_vertex_array)) return c.error(GL_INVALID_OPERATION);
  if (indexed && c.core_profile && !c.vao().element_buffer) return c.error(GL_INVALID_OPERATION);
  if (!indexed && int64_t(first) + int64_t(count) > int64_t(std::numeric_limits<int32_t>::max()))
    return c.error(GL_INVALID_VALUE);
  // GL 3.3 §2.12.1: with a geometry shader, the mode must give the primitives it takes
  // (checked after the framebuffer and the counts, as Mesa does).
  if (const glsl::GeometryInfo* gi = c.executable ? c.executable->geometry() : nullptr)
    if (d.decompose || !gpu::geometry_takes(gi->input_vertices, d.topology))
      return c.error(GL_INVALID_OPERATION);
  // §2.15.2: the primitives must be those transform feedback writes, and its buffers unmapped.
  if (c.feedback.active) {
    if (!c.feedback_takes(mode)) return c.error(GL_INVALID_OPERATION);
    for (const BufferRef& b : c.feedback.buffers)
      if (b->mapped) return c.error(GL_INVALID_OPERATION);
  }
  d.first = first;
  d.count = count;
  d.instances = instances;
  d.indexed = indexed;
  d.indices = indices;
  d.base_vertex = base_vertex;
  c.draw_generic(d);
}

}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glDrawArraysInstanced(GLenum mode, GLint first, GLsizei count, GLsizei instances) {
  GL_CONTEXT();
  if (generic_draw(c)) return draw_generic_call(c, mode, first, count, instances, GL_NONE, nullptr, 0);
  if (instances < 0) return c.error(GL_INVALID_VALUE);
  for (GLsizei i = 0; i < instances; ++i) draw_arrays(c, mode, first, count);
}

void GLAPIENTRY glDrawElementsInstanced(GLenum mode, GLsizei count, GLenum type, const void* indices,
                                        GLsizei instances) {
  GL_CONTEXT();
  if (generic_draw(c)) return draw_generic_call(c, mode, 0, count, instances, type, indices, 0);
  if (instances < 0) return c.error(GL_INVALID_VALUE);
  for (GLsizei i = 0; i < instances; ++i) glDrawElements(mode, count, type, indices);
}

void GLAPIENTRY glDrawElementsInstancedBaseVertex(GLenum mode, GLsizei count, GLenum type,
                                                  const void* indices, GLsizei instances, GLint base_vertex) {
  GL_CONTEXT();
  if (generic_draw(c)) return draw_generic_call(c, mode, 0, count, instances, type, indices, base_vertex);
  if (base_vertex != 0) return c.error(GL_INVALID_OPERATION);  // fixed-function arrays: no base vertex
  glDrawElementsInstanced(mode, count, type, indices, instances);
}

void GLAPIENTRY glDrawElementsBaseVertex(GLenum mode, GLsizei count, GLenum type, const void* indices,
                                         GLint base_vertex) {
  glDrawElementsInstancedBaseVertex(mode, count, type, indices, 1, base_vertex);
}

void GLAPIENTRY glDrawRangeElementsBaseVertex(GLenum mode, GLuint start, GLuint end, GLsizei count,
                                              GLenum type, const void* indices, GLint base_vertex) {
  GL_CONTEXT();
  if (end < start) return c.error(GL_INVALID_VALUE);
  glDrawElementsInstancedBaseVertex(mode, count, type, indices, 1, base_vertex);
}

void GLAPIENTRY glMultiDrawArrays(GLenum mode, const GLint* first, const GLsizei* count, GLsizei n) {
  GL_CONTEXT();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  if (!first || !count) return;
  for (GLsizei i = 0; i < n; ++i) glDrawArrays(mode, first[i], count[i]);
}

void GLAPIENTRY glMultiDrawElements(GLenum mode, const GLsizei* count, GLenum type,
                                    const void* const* indices, GLsizei n) {
  GL_CONTEXT();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  if (!count || !indices) return;
  for (GLsizei i = 0; i < n; ++i) glDrawElements(mode, count[i], type, indices[i]);
}

void GLAPIENTRY glMultiDrawElementsBaseVertex(GLenum mode, const GLsizei* count, GLenum type,
                                              const void* const* indices, GLsizei n,
                                              const GLint* base_vertex) {
  GL_CONTEXT();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  if (!count || !indices || !base_vertex) return;
  for (GLsizei i = 0; i < n; ++i) glDrawElementsBaseVertex(mode, count[i], type, indices[i], base_vertex[i]);
}

void GLAPIENTRY glPrimitiveRestartIndex(GLuint index) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  c.touch();
  c.primitive_restart_index = index;
}

}  // extern "C"
