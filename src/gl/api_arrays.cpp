// Vertex arrays (GL 2.1 §2.8, in their GL 1.1 form: client memory): the pointers,
// glEnableClientState, glDrawArrays, glDrawElements, glDrawRangeElements, glArrayElement,
// glInterleavedArrays. Array data is read when the command is issued (or compiled into a
// display list), converted into the vertex records the context draws.
#include <GL/gl.h>

#include <cstring>

#include "api.hpp"

namespace tessel::gl {

namespace {

int component_bytes(GLenum type) {
  switch (type) {
    case GL_BYTE:
    case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT:
    case GL_UNSIGNED_SHORT: return 2;
    case GL_INT:
    case GL_UNSIGNED_INT:
    case GL_FLOAT: return 4;
    case GL_DOUBLE: return 8;
    default: return 0;
  }
}

// One component as float; `normalized` maps integers as GL 2.1 Table 2.9 does for colours and normals.
float read(const uint8_t* p, GLenum type, bool normalized) {
  switch (type) {
    case GL_BYTE: {
      int8_t v;
      std::memcpy(&v, p, 1);
      return normalized ? (2.0f * v + 1.0f) / 255.0f : float(v);
    }
    case GL_UNSIGNED_BYTE: return normalized ? float(*p) / 255.0f : float(*p);
    case GL_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? (2.0f * v + 1.0f) / 65535.0f : float(v);
    }
    case GL_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? float(v) / 65535.0f : float(v);
    }
    case GL_INT: {
      int32_t v;
      std::memcpy(&v, p, 4);
      return normalized ? float((2.0 * v + 1.0) / 4294967295.0) : float(v);
    }
    case GL_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return normalized ? float(v / 4294967295.0) : float(v);
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
    default: return 0.0f;
  }
}

const uint8_t* element(const ArrayPointer& a, int n_components, GLint i) {
  const size_t stride = a.stride ? size_t(a.stride) : size_t(n_components) * size_t(component_bytes(a.type));
  return static_cast<const uint8_t*>(a.pointer) + size_t(i) * stride;
}

// Whether element i of an array with n components lies within the bytes it may read.
bool readable(const ArrayPointer& a, int n_components, GLint i) {
  if (a.limit == SIZE_MAX) return true;
  const size_t cb = size_t(component_bytes(a.type));
  const size_t stride = a.stride ? size_t(a.stride) : size_t(n_components) * cb;
  const size_t at = size_t(i) * stride;
  return at <= a.limit && size_t(n_components) * cb <= a.limit - at;
}

void read_vec(const ArrayPointer& a, GLint i, bool normalized, float* out) {
  const uint8_t* p = element(a, a.size, i);
  if (a.type == GL_FLOAT) {  // the common case, without a conversion per component
    std::memcpy(out, p, size_t(a.size) * sizeof(float));
    return;
  }
  const int cb = component_bytes(a.type);
  for (int k = 0; k < a.size; ++k) out[k] = read(p + k * cb, a.type, normalized);
}

// Every array of the fixed-function vertex (GL 2.1 §2.8; the texture coordinate array of
// each set, GL 1.3 §2.7, the secondary colour and fog coordinate arrays of GL 1.4).
std::vector<ArrayPointer*> vertex_arrays(Context& c) {
  std::vector<ArrayPointer*> all = {&c.c.vertex, &c.c.normal,    &c.c.color,
                                    &c.c.edge,   &c.c.secondary, &c.c.fog};
  for (ArrayPointer& t : c.c.tex) all.push_back(&t);
  return all;
}

// The current attributes updated from the enabled arrays at element i (glArrayElement's
// effect, GL 2.1 §2.8), then the vertex record (and, given `x`, its extra attributes) when the
// vertex array is enabled.
bool fetch(Context& c, GLint i, FFVertex* v, FFExtra* x = nullptr) {
  const ClientState& cs = c.c;
  CurrentState& cur = c.s.current;
  if (cs.edge.enabled && cs.edge.pointer && readable(cs.edge, 1, i)) cur.edge = *element(cs.edge, 1, i) != 0;
  for (size_t u = 0; u < cs.tex.size(); ++u) {
    const ArrayPointer& a = cs.tex[u];
    if (!(a.enabled && a.pointer && readable(a, a.size, i))) continue;
    float t[4] = {0, 0, 0, 1};
    read_vec(a, i, false, t);
    cur.tex[u] = glm::vec4(t[0], t[1], t[2], t[3]);
  }
  if (cs.secondary.enabled && cs.secondary.pointer && readable(cs.secondary, cs.secondary.size, i)) {
    float col[4] = {0, 0, 0, 1};
    read_vec(cs.secondary, i, true, col);
    cur.secondary = glm::vec4(col[0], col[1], col[2], 1.0f);
  }
  if (cs.fog.enabled && cs.fog.pointer && readable(cs.fog, 1, i)) read_vec(cs.fog, i, false, &cur.fog_coord);
  if (cs.color.enabled && cs.color.pointer && readable(cs.color, cs.color.size, i)) {
    float col[4] = {0, 0, 0, 1};
    read_vec(cs.color, i, true, col);
    cur.color = glm::vec4(col[0], col[1], col[2], col[3]);
  }
  if (cs.normal.enabled && cs.normal.pointer && readable(cs.normal, 3, i)) {
    float n[3] = {0, 0, 0};
    read_vec(cs.normal, i, true, n);
    cur.normal = glm::vec3(n[0], n[1], n[2]);
  }
  if (!(cs.vertex.enabled && cs.vertex.pointer && readable(cs.vertex, cs.vertex.size, i))) return false;
  float p[4] = {0, 0, 0, 1};
  read_vec(cs.vertex, i, false, p);
  std::memcpy(v->pos, p, sizeof p);
  std::memcpy(v->normal, &cur.normal[0], sizeof v->normal);
  std::memcpy(v->color, &cur.color[0], sizeof v->color);
  std::memcpy(v->tex, &cur.tex[0][0], sizeof v->tex);
  v->edge = cur.edge ? 1.0f : 0.0f;
  if (x) current_extra(cur, *x);
  return true;
}

bool valid_mode(GLenum mode) { return mode <= GL_POLYGON; }

// Arrays given in buffer objects (GL 1.5 §2.9): for the length of one draw their offsets
// become pointers into the buffers, with the bytes each may read past them. A mapped buffer
// makes the draw an error (GL_INVALID_OPERATION).
class BufferArrays {
 public:
  explicit BufferArrays(Context& c) {
    std::vector<ArrayPointer*> all = vertex_arrays(c);
    all.push_back(&c.c.index);
    for (ArrayPointer* a : all) {
      if (!a->buffer || !a->enabled) continue;
      if (a->buffer->mapped) ok_ = false;
      saved_.push_back({a, a->pointer});
      const size_t off = reinterpret_cast<size_t>(a->pointer), size = a->buffer->data.size();
      a->pointer = off <= size ? a->buffer->data.data() + off : nullptr;
      a->limit = off <= size ? size - off : 0;
    }
    if (!ok_) c.error(GL_INVALID_OPERATION);
  }
  ~BufferArrays() {
    for (auto& [a, p] : saved_) {
      a->pointer = p;
      a->limit = SIZE_MAX;
    }
  }
  BufferArrays(const BufferArrays&) = delete;
  BufferArrays& operator=(const BufferArrays&) = delete;
  bool ok() const { return ok_; }

 private:
  bool ok_ = true;
  std::vector<std::pair<ArrayPointer*, const void*>> saved_;
};

}  // namespace

// Whether a draw call runs the current program over the generic attribute arrays (GL 2.0+)
// instead of the fixed-function arrays: a core context always does; a compatibility one
// when a program is current and it enables a generic array or no vertex array.
bool generic_draw(Context& c) {
  if (c.core_profile) return true;
  if (!c.executable) return false;
  for (const AttribArray& a : c.vao().attribs)
    if (a.enabled) return true;
  return !c.c.vertex.enabled;
}

namespace {

// What a converted range depends on besides the array bytes: the arrays' addresses and
// formats, the range, and the current values used for disabled arrays.
std::vector<uint8_t> array_key(const Context& c, GLuint lo, GLuint hi) {
  std::vector<uint8_t> k;
  k.reserve(256);
  auto add = [&](const void* p, size_t n) {
    const auto* b = static_cast<const uint8_t*>(p);
    k.insert(k.end(), b, b + n);
  };
  add(&lo, sizeof lo);
  add(&hi, sizeof hi);
  for (const ArrayPointer* a : {&c.c.vertex, &c.c.normal, &c.c.color, &c.c.tex[0], &c.c.edge}) {
    const uint8_t on = a->enabled && a->pointer;
    add(&on, 1);
    if (!on) continue;
    add(&a->pointer, sizeof a->pointer);
    add(&a->size, sizeof a->size);
    add(&a->type, sizeof a->type);
    add(&a->stride, sizeof a->stride);
  }
  const CurrentState& cur = c.s.current;
  add(&cur.color, sizeof cur.color);
  add(&cur.normal, sizeof cur.normal);
  add(&cur.tex[0], sizeof cur.tex[0]);
  const uint8_t edge = cur.edge;
  add(&edge, 1);
  return k;
}

// The bytes of elements lo..hi of every enabled array, in order.
template <class Fn>
void for_each_source(const Context& c, GLuint lo, GLuint hi, Fn&& fn) {
  for (const ArrayPointer* a : {&c.c.vertex, &c.c.normal, &c.c.color, &c.c.tex[0], &c.c.edge}) {
    if (!a->enabled || !a->pointer) continue;
    const int n = a == &c.c.edge ? 1 : a == &c.c.normal ? 3 : a->size;
    const size_t elem = size_t(n) * size_t(component_bytes(a->type));
    const uint8_t* first = element(*a, n, GLint(lo));
    const uint8_t* last = element(*a, n, GLint(hi));
    fn(first, size_t(last - first) + elem);
  }
}

std::vector<uint8_t> source_bytes(const Context& c, GLuint lo, GLuint hi) {
  std::vector<uint8_t> out;
  for_each_source(c, lo, hi, [&](const uint8_t* p, size_t n) { out.insert(out.end(), p, p + n); });
  return out;
}

bool same_source(const Context& c, GLuint lo, GLuint hi, const std::vector<uint8_t>& saved) {
  size_t at = 0;
  bool same = true;
  for_each_source(c, lo, hi, [&](const uint8_t* p, size_t n) {
    if (!same) return;
    if (at + n > saved.size() || std::memcmp(p, saved.data() + at, n) != 0) same = false;
    at += n;
  });
  return same && at == saved.size();
}

void set_pointer(Context& c, ArrayPointer& a, GLint size, GLenum type, GLsizei stride, const void* ptr,
                 std::initializer_list<GLint> sizes, std::initializer_list<GLenum> types) {
  GL_OUTSIDE_BEGIN();
  bool size_ok = false, type_ok = false;
  for (GLint s : sizes) size_ok |= s == size;
  for (GLenum t : types) type_ok |= t == type;
  if (!size_ok || stride < 0) return c.error(GL_INVALID_VALUE);
  if (!type_ok) return c.error(GL_INVALID_ENUM);
  a.size = size;
  a.type = type;
  a.stride = stride;
  a.pointer = ptr;
  a.buffer = c.array_buffer;
}

ArrayPointer* client_array(Context& c, GLenum cap) {
  switch (cap) {
    case GL_VERTEX_ARRAY: return &c.c.vertex;
    case GL_NORMAL_ARRAY: return &c.c.normal;
    case GL_COLOR_ARRAY: return &c.c.color;
    case GL_TEXTURE_COORD_ARRAY: return &c.c.active_tex();
    case GL_SECONDARY_COLOR_ARRAY: return &c.c.secondary;
    case GL_FOG_COORD_ARRAY: return &c.c.fog;
    case GL_EDGE_FLAG_ARRAY: return &c.c.edge;
    case GL_INDEX_ARRAY: return &c.c.index;
    default: return nullptr;
  }
}

// Reads elements into vertex records; the current attributes end as the last element left them.
FFVertices gather(Context& c, const std::vector<GLuint>& ids) {
  FFVertices out;
  out.reserve(ids.size());
  FFVertex v;
  if (!c.extras_live()) {
    for (GLuint i : ids)
      if (fetch(c, GLint(i), &v)) out.push(v);
    return out;
  }
  FFExtra x;
  for (GLuint i : ids)
    if (fetch(c, GLint(i), &v, &x)) out.push(v, x);
  return out;
}

void draw_gathered(Context& c, GLenum mode, FFVertices&& verts) {
  GL_OUTSIDE_BEGIN();
  c.emit_mode(mode, std::move(verts));
}

// Indexed triangles, lines or points keep their sharing: vertices are read once each.
void draw_indexed(Context& c, PrimClass cls, FFVertices&& verts, std::vector<uint32_t>&& idx) {
  GL_OUTSIDE_BEGIN();
  c.emit(cls, std::move(verts), std::move(idx));
}

}  // namespace

void draw_arrays(Context& c, GLenum mode, GLint first, GLsizei count) {
  if (!valid_mode(mode)) return c.error(GL_INVALID_ENUM);
  if (count < 0 || first < 0) return c.error(GL_INVALID_VALUE);
  GL_OUTSIDE_BEGIN();
  BufferArrays in_buffers(c);
  if (!in_buffers.ok()) return;
  if (!c.c.vertex.enabled || !c.c.vertex.pointer || count == 0) return;
  std::vector<GLuint> ids(static_cast<size_t>(count));
  for (GLsizei i = 0; i < count; ++i) ids[size_t(i)] = GLuint(first + i);
  FFVertices verts = gather(c, ids);
  GL_LISTED(draw_gathered(c, mode, FFVertices(verts)));
  draw_gathered(c, mode, std::move(verts));
}

void array_element(Context& c, GLint i) {
  if (i < 0) return c.error(GL_INVALID_VALUE);
  BufferArrays in_buffers(c);
  if (!in_buffers.ok()) return;
  FFVertex v;
  const bool has_vertex = fetch(c, i, &v);
  // Recorded as the attribute values it produced (data is read when compiled).
  const CurrentState cur = c.s.current;
  auto run = [cur, v, has_vertex](Context& c) {
    c.s.current.color = cur.color;
    c.s.current.normal = cur.normal;
    c.s.current.tex = cur.tex;
    c.s.current.secondary = cur.secondary;
    c.s.current.fog_coord = cur.fog_coord;
    c.s.current.edge = cur.edge;
    if (c.extras_live()) c.extras_touched = true;
    if (has_vertex) vertex(c, v.pos[0], v.pos[1], v.pos[2], v.pos[3]);
  };
  if (c.compiling_list != 0) {
    c.record([run] {
      if (Context* cc = current()) run(*cc);
    });
    if (c.compiling_only()) return;
  }
  run(c);
}

}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glVertexPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* ptr) {
  GL_COMPAT_CONTEXT();
  set_pointer(c, c.c.vertex, size, type, stride, ptr, {2, 3, 4}, {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
}
void GLAPIENTRY glNormalPointer(GLenum type, GLsizei stride, const GLvoid* ptr) {
  GL_COMPAT_CONTEXT();
  set_pointer(c, c.c.normal, 3, type, stride, ptr, {3}, {GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
}
void GLAPIENTRY glColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* ptr) {
  GL_COMPAT_CONTEXT();
  set_pointer(
      c, c.c.color, size, type, stride, ptr, {3, 4},
      {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE});
}
void GLAPIENTRY glTexCoordPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* ptr) {
  GL_COMPAT_CONTEXT();
  set_pointer(c, c.c.active_tex(), size, type, stride, ptr, {1, 2, 3, 4},
              {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
}
void GLAPIENTRY glSecondaryColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* ptr) {
  GL_COMPAT_CONTEXT();
  set_pointer(
      c, c.c.secondary, size, type, stride, ptr, {3},
      {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE});
}
void GLAPIENTRY glFogCoordPointer(GLenum type, GLsizei stride, const GLvoid* ptr) {
  GL_COMPAT_CONTEXT();
  set_pointer(c, c.c.fog, 1, type, stride, ptr, {1}, {GL_FLOAT, GL_DOUBLE});
}
void GLAPIENTRY glEdgeFlagPointer(GLsizei stride, const GLvoid* ptr) {
  GL_COMPAT_CONTEXT();
  set_pointer(c, c.c.edge, 1, GL_UNSIGNED_BYTE, stride, ptr, {1}, {GL_UNSIGNED_BYTE});
}
void GLAPIENTRY glIndexPointer(GLenum type, GLsizei stride, const GLvoid* ptr) {
  GL_COMPAT_CONTEXT();
  set_pointer(c, c.c.index, 1, type, stride, ptr, {1},
              {GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
}
void GLAPIENTRY glEnableClientState(GLenum cap) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ArrayPointer* a = client_array(c, cap);
  if (!a) return c.error(GL_INVALID_ENUM);
  a->enabled = true;
  c.extras_touched |= a != &c.c.vertex && a != &c.c.normal && a != &c.c.color && a != &c.c.tex[0] &&
                      a != &c.c.edge && a != &c.c.index;
}
void GLAPIENTRY glDisableClientState(GLenum cap) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  ArrayPointer* a = client_array(c, cap);
  if (!a) return c.error(GL_INVALID_ENUM);
  a->enabled = false;
}
void GLAPIENTRY glGetPointerv(GLenum pname, GLvoid** out) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!out) return;
  switch (pname) {
    case GL_VERTEX_ARRAY_POINTER: *out = const_cast<void*>(c.c.vertex.pointer); break;
    case GL_NORMAL_ARRAY_POINTER: *out = const_cast<void*>(c.c.normal.pointer); break;
    case GL_COLOR_ARRAY_POINTER: *out = const_cast<void*>(c.c.color.pointer); break;
    case GL_TEXTURE_COORD_ARRAY_POINTER: *out = const_cast<void*>(c.c.active_tex().pointer); break;
    case GL_SECONDARY_COLOR_ARRAY_POINTER: *out = const_cast<void*>(c.c.secondary.pointer); break;
    case GL_FOG_COORD_ARRAY_POINTER: *out = const_cast<void*>(c.c.fog.pointer); break;
    case GL_EDGE_FLAG_ARRAY_POINTER: *out = const_cast<void*>(c.c.edge.pointer); break;
    case GL_INDEX_ARRAY_POINTER: *out = const_cast<void*>(c.c.index.pointer); break;
    default: c.error(GL_INVALID_ENUM); break;
  }
}

void GLAPIENTRY glDrawArrays(GLenum mode, GLint first, GLsizei count) {
  GL_CONTEXT();
  if (generic_draw(c)) return draw_generic_call(c, mode, first, count, 1, GL_NONE, nullptr, 0);
  draw_arrays(c, mode, first, count);
}

void GLAPIENTRY glDrawElements(GLenum mode, GLsizei count, GLenum type, const GLvoid* indices) {
  GL_CONTEXT();
  if (generic_draw(c)) return draw_generic_call(c, mode, 0, count, 1, type, indices, 0);
  if (!valid_mode(mode)) return c.error(GL_INVALID_ENUM);
  if (count < 0) return c.error(GL_INVALID_VALUE);
  if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT)
    return c.error(GL_INVALID_ENUM);
  GL_OUTSIDE_BEGIN();
  BufferArrays in_buffers(c);
  if (!in_buffers.ok()) return;
  if (const BufferRef& eb = c.vao().element_buffer) {
    // GL 1.5: the indices are at an offset into the element array buffer.
    const size_t per = type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2 : 4;
    const size_t off = reinterpret_cast<size_t>(indices);
    if (eb->mapped || off > eb->data.size() || size_t(count) * per > eb->data.size() - off)
      return c.error(GL_INVALID_OPERATION);
    indices = eb->data.data() + off;
  }
  if (!c.c.vertex.enabled || !c.c.vertex.pointer || count == 0 || !indices) return;
  std::vector<GLuint> ids(static_cast<size_t>(count));
  const auto* b = static_cast<const uint8_t*>(indices);
  for (GLsizei i = 0; i < count; ++i) {
    if (type == GL_UNSIGNED_BYTE)
      ids[size_t(i)] = b[i];
    else if (type == GL_UNSIGNED_SHORT) {
      uint16_t v;
      std::memcpy(&v, b + 2 * i, 2);
      ids[size_t(i)] = v;
    } else {
      uint32_t v;
      std::memcpy(&v, b + 4 * i, 4);
      ids[size_t(i)] = v;
    }
  }
  if (mode == GL_TRIANGLES || mode == GL_LINES || mode == GL_POINTS) {
    GLuint lo = ids[0], hi = ids[0];
    for (GLuint i : ids) lo = std::min(lo, i), hi = std::max(hi, i);
    if (size_t(hi - lo) < size_t(count) * 4 + 64) {
      // Shared vertices stay shared: read the range once, rebase the indices.
      const size_t per = mode == GL_TRIANGLES ? 3 : mode == GL_LINES ? 2 : 1;
      std::vector<GLuint> range(size_t(hi - lo) + 1);
      for (size_t k = 0; k < range.size(); ++k) range[k] = lo + GLuint(k);
      if (mode == GL_TRIANGLES && c.compiling_list == 0 && c.render_mode() == GL_RENDER && !c.extras_live()) {
        // The same arrays drawn again (a mesh drawn many times with other matrices or
        // materials): the converted vertices are reused while the bytes they came from and
        // the current values baked into them are unchanged.
        Context::ArrayCache& cache = c.array_cache;
        std::vector<uint8_t> key = array_key(c, lo, hi);
        const bool hit = cache.vertices && cache.key == key && same_source(c, lo, hi, cache.source);
        if (!hit) {
          FFVertices verts = gather(c, range);
          if (verts.size() == range.size()) {
            cache.key = std::move(key);
            cache.source = source_bytes(c, lo, hi);
            cache.vertices =
                std::make_shared<const tessel::gpu::Buffer>(verts.v.data(), verts.size() * sizeof(FFVertex));
          } else {
            cache.vertices.reset();
          }
        }
        if (cache.vertices) {
          FFVertex last;
          fetch(c, GLint(ids.back()), &last);  // the current values as the draw leaves them
          std::vector<uint32_t> idx(ids.size() - ids.size() % per);
          for (size_t k = 0; k < idx.size(); ++k) idx[k] = ids[k] - lo;
          c.emit_shared(cache.vertices, std::move(idx));
          return;
        }
      }
      // Attributes as the indexed elements leave them: the last index read is the last index.
      FFVertices verts = gather(c, range);
      if (verts.size() == range.size()) {
        FFVertex last;
        fetch(c, GLint(ids.back()), &last);
        std::vector<uint32_t> idx(ids.size() - ids.size() % per);
        for (size_t k = 0; k < idx.size(); ++k) idx[k] = ids[k] - lo;
        const PrimClass cls = mode == GL_TRIANGLES ? PrimClass::Triangles
                              : mode == GL_LINES   ? PrimClass::Lines
                                                   : PrimClass::Points;
        GL_LISTED(draw_indexed(c, cls, FFVertices(verts), std::vector<uint32_t>(idx)));
        draw_indexed(c, cls, std::move(verts), std::move(idx));
        return;
      }
    }
  }
  FFVertices verts = gather(c, ids);
  GL_LISTED(draw_gathered(c, mode, FFVertices(verts)));
  draw_gathered(c, mode, std::move(verts));
}

void GLAPIENTRY glDrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                                    const GLvoid* indices) {
  GL_CONTEXT();
  if (end < start) return c.error(GL_INVALID_VALUE);
  glDrawElements(mode, count, type, indices);
}

void GLAPIENTRY glArrayElement(GLint i) {
  GL_COMPAT_CONTEXT();
  array_element(c, i);
}

// GL 2.1 Table 2.5: the interleaved formats.
void GLAPIENTRY glInterleavedArrays(GLenum format, GLsizei stride, const GLvoid* pointer) {
  GL_COMPAT_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (stride < 0) return c.error(GL_INVALID_VALUE);
  struct Row {
    GLenum f;
    bool et, ec, en;
    int st, sc, sv;
    GLenum tc;
    int pc, pn, pv, s;
  };
  constexpr int F = 4;
  static const Row rows[] = {
      {GL_V2F, false, false, false, 0, 0, 2, 0, 0, 0, 0, 2 * F},
      {GL_V3F, false, false, false, 0, 0, 3, 0, 0, 0, 0, 3 * F},
      {GL_C4UB_V2F, false, true, false, 0, 4, 2, GL_UNSIGNED_BYTE, 0, 0, 4, 4 + 2 * F},
      {GL_C4UB_V3F, false, true, false, 0, 4, 3, GL_UNSIGNED_BYTE, 0, 0, 4, 4 + 3 * F},
      {GL_C3F_V3F, false, true, false, 0, 3, 3, GL_FLOAT, 0, 0, 3 * F, 6 * F},
      {GL_N3F_V3F, false, false, true, 0, 0, 3, 0, 0, 0, 3 * F, 6 * F},
      {GL_C4F_N3F_V3F, false, true, true, 0, 4, 3, GL_FLOAT, 0, 4 * F, 7 * F, 10 * F},
      {GL_T2F_V3F, true, false, false, 2, 0, 3, 0, 0, 0, 2 * F, 5 * F},
      {GL_T4F_V4F, true, false, false, 4, 0, 4, 0, 0, 0, 4 * F, 8 * F},
      {GL_T2F_C4UB_V3F, true, true, false, 2, 4, 3, GL_UNSIGNED_BYTE, 2 * F, 0, 2 * F + 4, 2 * F + 4 + 3 * F},
      {GL_T2F_C3F_V3F, true, true, false, 2, 3, 3, GL_FLOAT, 2 * F, 0, 5 * F, 8 * F},
      {GL_T2F_N3F_V3F, true, false, true, 2, 0, 3, 0, 0, 2 * F, 5 * F, 8 * F},
      {GL_T2F_C4F_N3F_V3F, true, true, true, 2, 4, 3, GL_FLOAT, 2 * F, 6 * F, 9 * F, 12 * F},
      {GL_T4F_C4F_N3F_V4F, true, true, true, 4, 4, 4, GL_FLOAT, 4 * F, 8 * F, 11 * F, 15 * F},
  };
  const Row* r = nullptr;
  for (const Row& x : rows)
    if (x.f == format) r = &x;
  if (!r) return c.error(GL_INVALID_ENUM);
  const GLsizei st = stride ? stride : r->s;
  const auto* base = static_cast<const uint8_t*>(pointer);
  c.c.edge.enabled = false;
  c.c.index.enabled = false;
  c.c.active_tex().enabled = r->et;
  // With a buffer bound, `pointer` is an offset into it (GL 1.5 §2.9).
  if (r->et) c.c.active_tex() = {true, r->st, GL_FLOAT, st, base, c.array_buffer};
  c.c.color.enabled = r->ec;
  if (r->ec) c.c.color = {true, r->sc, r->tc, st, base + r->pc, c.array_buffer};
  c.c.normal.enabled = r->en;
  if (r->en) c.c.normal = {true, 3, GL_FLOAT, st, base + r->pn, c.array_buffer};
  c.c.vertex = {true, r->sv, GL_FLOAT, st, base + r->pv, c.array_buffer};
}

}  // extern "C"
