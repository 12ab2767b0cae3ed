// Buffer objects (GL 3.3 §2.9), vertex array objects (§2.10) and the generic vertex
// attributes (§2.7, §2.8): their entry points, errors as the specification lists them.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <type_traits>

#include "api.hpp"

namespace tessel::gl {

namespace {

// The binding point of a buffer target, or nullptr (GL_INVALID_ENUM).
BufferRef* target_binding(Context& c, GLenum target) {
  switch (target) {
    case GL_ARRAY_BUFFER: return &c.array_buffer;
    case GL_ELEMENT_ARRAY_BUFFER:
      if (!c.vertex_arrays.count(c.bound_vertex_array)) return nullptr;
      return &c.vao().element_buffer;
    case GL_COPY_READ_BUFFER: return &c.copy_read_buffer;
    case GL_COPY_WRITE_BUFFER: return &c.copy_write_buffer;
    case GL_PIXEL_PACK_BUFFER: return &c.pixel_pack_buffer;
    case GL_PIXEL_UNPACK_BUFFER: return &c.pixel_unpack_buffer;
    case GL_UNIFORM_BUFFER: return &c.uniform_buffer;
    case GL_TEXTURE_BUFFER: return &c.texture_buffer;
    case GL_TRANSFORM_FEEDBACK_BUFFER: return &c.feedback_buffer;
    default: return nullptr;
  }
}

bool valid_target(GLenum target) {
  switch (target) {
    case GL_ARRAY_BUFFER:
    case GL_ELEMENT_ARRAY_BUFFER:
    case GL_COPY_READ_BUFFER:
    case GL_COPY_WRITE_BUFFER:
    case GL_PIXEL_PACK_BUFFER:
    case GL_PIXEL_UNPACK_BUFFER:
    case GL_UNIFORM_BUFFER:
    case GL_TEXTURE_BUFFER:
    case GL_TRANSFORM_FEEDBACK_BUFFER: return true;
    default: return false;
  }
}

// The buffer bound to `target`: GL_INVALID_ENUM for a bad target, GL_INVALID_OPERATION when
// none is bound (GL 3.3 §2.9.2).
BufferObject* bound(Context& c, GLenum target) {
  if (!valid_target(target)) {
    c.error(GL_INVALID_ENUM);
    return nullptr;
  }
  BufferRef* b = target_binding(c, target);
  if (!b || !*b) {
    c.error(GL_INVALID_OPERATION);
    return nullptr;
  }
  return b->get();
}

bool valid_usage(GLenum u) {
  switch (u) {
    case GL_STREAM_DRAW:
    case GL_STREAM_READ:
    case GL_STREAM_COPY:
    case GL_STATIC_DRAW:
    case GL_STATIC_READ:
    case GL_STATIC_COPY:
    case GL_DYNAMIC_DRAW:
    case GL_DYNAMIC_READ:
    case GL_DYNAMIC_COPY: return true;
    default: return false;
  }
}

void unmap(BufferObject& b) {
  b.mapped = false;
  b.map_access = 0;
  b.map_offset = b.map_length = 0;
}

GLenum access_of_flags(GLbitfield f) {
  const bool r = f & GL_MAP_READ_BIT, w = f & GL_MAP_WRITE_BIT;
  return r && w ? GL_READ_WRITE : w ? GL_WRITE_ONLY : GL_READ_ONLY;
}

void* map_range(Context& c, BufferObject& b, GLintptr offset, GLsizeiptr length, GLbitfield access) {
  constexpr GLbitfield kAll = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT |
                              GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_FLUSH_EXPLICIT_BIT |
                              GL_MAP_UNSYNCHRONIZED_BIT;
  if (offset < 0 || length < 0 || size_t(offset) + size_t(length) > b.data.size() || (access & ~kAll)) {
    c.error(GL_INVALID_VALUE);
    return nullptr;
  }
  // (A range of no bytes is GL_INVALID_OPERATION on Mesa; GL 4.5 makes it an error too.)
  if (b.mapped || length == 0 || !(access & (GL_MAP_READ_BIT | GL_MAP_WRITE_BIT)) ||
      ((access & GL_MAP_READ_BIT) &&
       (access & (GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_UNSYNCHRONIZED_BIT))) ||
      ((access & GL_MAP_FLUSH_EXPLICIT_BIT) && !(access & GL_MAP_WRITE_BIT))) {
    c.error(GL_INVALID_OPERATION);
    return nullptr;
  }
  c.touch();
  std::byte* p = b.data.writable();
  b.mapped = true;
  b.map_access = access;
  b.map_offset = size_t(offset);
  b.map_length = size_t(length);
  // A mapping of no bytes still returns a pointer that is not null.
  static std::byte empty[16];
  return b.data.size() ? static_cast<void*>(p + offset) : static_cast<void*>(empty);
}

}  // namespace

extern "C" {

// --- buffer objects ---------------------------------------------------------------------

void GLAPIENTRY glGenBuffers(GLsizei n, GLuint* names) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  if (!names) return;
  for (GLsizei i = 0; i < n; ++i) {
    names[i] = fresh_name(c.buffers, c.next_buffer_name);
    c.buffers[names[i]] = nullptr;
  }
}

void GLAPIENTRY glDeleteBuffers(GLsizei n, const GLuint* names) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  if (!names) return;
  c.touch();
  for (GLsizei i = 0; i < n; ++i) {
    auto it = c.buffers.find(names[i]);
    if (names[i] == 0 || it == c.buffers.end()) continue;
    BufferRef b = it->second;
    c.buffers.erase(it);
    if (!b) continue;
    unmap(*b);
    // GL 3.3 §2.9.1: the bindings of the context, and the attachments of the bound vertex
    // array object, that name it revert to zero. Other vertex array objects keep it alive.
    for (BufferRef* r : {&c.array_buffer, &c.copy_read_buffer, &c.copy_write_buffer, &c.pixel_pack_buffer,
                         &c.pixel_unpack_buffer, &c.uniform_buffer, &c.texture_buffer, &c.feedback_buffer})
      if (*r == b) r->reset();
    // (An active transform feedback keeps writing a buffer deleted from its binding point.)
    for (GLenum target : {GL_UNIFORM_BUFFER, GL_TRANSFORM_FEEDBACK_BUFFER})
      for (auto& u : c.indexed_bindings(target))
        if (u.buffer == b) u = {};
    if (c.vertex_arrays.count(c.bound_vertex_array)) {
      VertexArrayObject& va = c.vao();
      if (va.element_buffer == b) va.element_buffer.reset();
      for (AttribArray& a : va.attribs)
        if (a.buffer == b) a.buffer.reset();
    }
  }
}

GLboolean GLAPIENTRY glIsBuffer(GLuint name) {
  GL_CONTEXT(GL_FALSE);
  GL_OUTSIDE_BEGIN(GL_FALSE);
  auto it = c.buffers.find(name);
  return it != c.buffers.end() && it->second ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY glBindBuffer(GLenum target, GLuint name) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!valid_target(target)) return c.error(GL_INVALID_ENUM);
  BufferRef obj;
  if (name != 0) {
    auto it = c.buffers.find(name);
    // A core context binds only generated names (GL 3.3 core §2.9.1); compatibility ones
    // create the object for any name, as GL 2.1 did.
    if (it == c.buffers.end() && c.core_profile) return c.error(GL_INVALID_OPERATION);
    BufferRef& slot = c.buffers[name];
    if (!slot) {
      slot = std::make_shared<BufferObject>();
      slot->name = name;
    }
    obj = slot;
  }
  BufferRef* b = target_binding(c, target);
  if (!b) return c.error(GL_INVALID_OPERATION);  // GL_ELEMENT_ARRAY_BUFFER without a vertex array object
  c.touch();
  *b = obj;
}

void GLAPIENTRY glBufferData(GLenum target, GLsizeiptr size, const void* data, GLenum usage) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!valid_target(target) || !valid_usage(usage)) return c.error(GL_INVALID_ENUM);
  if (size < 0) return c.error(GL_INVALID_VALUE);
  BufferObject* b = bound(c, target);
  if (!b) return;
  c.touch();
  try {
    if (data) {
      b->data.assign(data, size_t(size));
    } else {
      std::vector<std::byte> zero(static_cast<size_t>(size));
      b->data.assign(zero.data(), zero.size());
    }
  } catch (const std::bad_alloc&) {
    return c.error(GL_OUT_OF_MEMORY);
  } catch (const std::length_error&) {
    return c.error(GL_OUT_OF_MEMORY);
  }
  b->usage = usage;
  unmap(*b);
}

void GLAPIENTRY glBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, const void* data) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  BufferObject* b = bound(c, target);
  if (!b) return;
  if (offset < 0 || size < 0 || size_t(offset) + size_t(size) > b->data.size())
    return c.error(GL_INVALID_VALUE);
  if (b->mapped) return c.error(GL_INVALID_OPERATION);
  if (!data || size == 0) return;
  c.touch();
  b->data.update(size_t(offset), data, size_t(size));
}

void GLAPIENTRY glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, void* data) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  BufferObject* b = bound(c, target);
  if (!b) return;
  if (offset < 0 || size < 0 || size_t(offset) + size_t(size) > b->data.size())
    return c.error(GL_INVALID_VALUE);
  if (b->mapped) return c.error(GL_INVALID_OPERATION);
  if (!data || size == 0) return;
  c.finish();  // the buffer as the draws queued before leave it (they only read it)
  std::memcpy(data, b->data.data() + offset, size_t(size));
}

void* GLAPIENTRY glMapBuffer(GLenum target, GLenum access) {
  GL_CONTEXT(nullptr);
  GL_OUTSIDE_BEGIN(nullptr);
  if (!valid_target(target)) {
    c.error(GL_INVALID_ENUM);
    return nullptr;
  }
  GLbitfield flags = 0;
  switch (access) {
    case GL_READ_ONLY: flags = GL_MAP_READ_BIT; break;
    case GL_WRITE_ONLY: flags = GL_MAP_WRITE_BIT; break;
    case GL_READ_WRITE: flags = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT; break;
    default: c.error(GL_INVALID_ENUM); return nullptr;
  }
  BufferObject* b = bound(c, target);
  if (!b) return nullptr;
  return map_range(c, *b, 0, GLsizeiptr(b->data.size()), flags);
}

void* GLAPIENTRY glMapBufferRange(GLenum target, GLintptr offset, GLsizeiptr length, GLbitfield access) {
  GL_CONTEXT(nullptr);
  GL_OUTSIDE_BEGIN(nullptr);
  BufferObject* b = bound(c, target);
  if (!b) return nullptr;
  return map_range(c, *b, offset, length, access);
}

void GLAPIENTRY glFlushMappedBufferRange(GLenum target, GLintptr offset, GLsizeiptr length) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  BufferObject* b = bound(c, target);
  if (!b) return;
  if (!b->mapped || !(b->map_access & GL_MAP_FLUSH_EXPLICIT_BIT)) return c.error(GL_INVALID_OPERATION);
  if (offset < 0 || length < 0 || size_t(offset) + size_t(length) > b->map_length)
    return c.error(GL_INVALID_VALUE);
  // The mapping is the buffer's own memory: what was written is there already.
}

GLboolean GLAPIENTRY glUnmapBuffer(GLenum target) {
  GL_CONTEXT(GL_FALSE);
  GL_OUTSIDE_BEGIN(GL_FALSE);
  BufferObject* b = bound(c, target);
  if (!b) return GL_FALSE;
  if (!b->mapped) {
    c.error(GL_INVALID_OPERATION);
    return GL_FALSE;
  }
  unmap(*b);
  return GL_TRUE;
}

void GLAPIENTRY glCopyBufferSubData(GLenum read_target, GLenum write_target, GLintptr read_offset,
                                    GLintptr write_offset, GLsizeiptr size) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!valid_target(read_target) || !valid_target(write_target)) return c.error(GL_INVALID_ENUM);
  BufferObject* r = bound(c, read_target);
  if (!r) return;
  BufferObject* w = bound(c, write_target);
  if (!w) return;
  if (read_offset < 0 || write_offset < 0 || size < 0 ||
      size_t(read_offset) + size_t(size) > r->data.size() ||
      size_t(write_offset) + size_t(size) > w->data.size())
    return c.error(GL_INVALID_VALUE);
  // GL 3.3 §2.9.5: overlapping ranges of one buffer are an error.
  if (r == w && read_offset < write_offset + size && write_offset < read_offset + size)
    return c.error(GL_INVALID_VALUE);
  if (r->mapped || w->mapped) return c.error(GL_INVALID_OPERATION);
  if (size == 0) return;
  c.touch();
  std::vector<std::byte> tmp(r->data.data() + read_offset, r->data.data() + read_offset + size);
  w->data.update(size_t(write_offset), tmp.data(), tmp.size());
}

}  // extern "C"

namespace {
bool buffer_parameter(Context& c, GLenum target, GLenum pname, GLint64& v) {
  if (c.in_begin) {
    c.error(GL_INVALID_OPERATION);
    return false;
  }
  BufferObject* b = bound(c, target);
  if (!b) return false;
  switch (pname) {
    case GL_BUFFER_SIZE: v = GLint64(b->data.size()); return true;
    case GL_BUFFER_USAGE: v = b->usage; return true;
    case GL_BUFFER_ACCESS: v = b->mapped ? access_of_flags(b->map_access) : GL_READ_WRITE; return true;
    case GL_BUFFER_ACCESS_FLAGS: v = b->map_access; return true;
    case GL_BUFFER_MAPPED: v = b->mapped; return true;
    case GL_BUFFER_MAP_OFFSET: v = GLint64(b->map_offset); return true;
    case GL_BUFFER_MAP_LENGTH: v = GLint64(b->map_length); return true;
    default: c.error(GL_INVALID_ENUM); return false;
  }
}
}  // namespace

extern "C" {

void GLAPIENTRY glGetBufferParameteri64v(GLenum target, GLenum pname, GLint64* out) {
  GL_CONTEXT();
  GLint64 v = 0;
  if (buffer_parameter(c, target, pname, v) && out) *out = v;
}

void GLAPIENTRY glGetBufferParameteriv(GLenum target, GLenum pname, GLint* out) {
  GL_CONTEXT();
  GLint64 v = 0;
  if (buffer_parameter(c, target, pname, v) && out) *out = GLint(std::min<GLint64>(v, 0x7FFFFFFF));
}

void GLAPIENTRY glGetBufferPointerv(GLenum target, GLenum pname, void** out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (pname != GL_BUFFER_MAP_POINTER) return c.error(GL_INVALID_ENUM);
  BufferObject* b = bound(c, target);
  if (!b) return;
  if (out) *out = b->mapped ? const_cast<std::byte*>(b->data.data()) + b->map_offset : nullptr;
}

}  // extern "C"

namespace {

// Indexed binding points: uniform buffers (GL 3.3 §2.11.4) and transform feedback buffers
// (§2.15.2). Each bind sets the target's generic binding too. `whole`: glBindBufferBase, the
// whole buffer however large it becomes.
void bind_indexed(Context& c, GLenum target, GLuint index, GLuint name, GLintptr offset, GLsizeiptr size,
                  bool whole) {
  GL_OUTSIDE_BEGIN();
  const std::span<Context::IndexedBuffer> points = c.indexed_bindings(target);
  if (points.empty()) return c.error(GL_INVALID_ENUM);
  if (index >= points.size()) return c.error(GL_INVALID_VALUE);
  const bool feedback = target == GL_TRANSFORM_FEEDBACK_BUFFER;
  if (feedback && c.feedback.active) return c.error(GL_INVALID_OPERATION);
  // Feedback ranges are of whole words, uniform blocks start at GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT.
  if (name != 0 && !whole &&
      (size <= 0 || offset < 0 || offset % (feedback ? 4 : 16) != 0 || (feedback && size % 4 != 0)))
    return c.error(GL_INVALID_VALUE);
  BufferRef obj;
  if (name != 0) {
    auto it = c.buffers.find(name);
    if (it == c.buffers.end() && c.core_profile) return c.error(GL_INVALID_OPERATION);
    BufferRef& slot = c.buffers[name];
    if (!slot) {
      slot = std::make_shared<BufferObject>();
      slot->name = name;
    }
    obj = slot;
  }
  c.touch();
  points[index] = {obj, obj && !whole ? offset : 0, obj && !whole ? size : 0};
  *target_binding(c, target) = obj;
}

}  // namespace

extern "C" {

void GLAPIENTRY glBindBufferRange(GLenum target, GLuint index, GLuint name, GLintptr offset,
                                  GLsizeiptr size) {
  GL_CONTEXT();
  bind_indexed(c, target, index, name, offset, size, false);
}

void GLAPIENTRY glBindBufferBase(GLenum target, GLuint index, GLuint name) {
  GL_CONTEXT();
  bind_indexed(c, target, index, name, 0, 0, true);
}

// --- vertex array objects --------------------------------------------------------------

void GLAPIENTRY glGenVertexArrays(GLsizei n, GLuint* names) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  if (!names) return;
  for (GLsizei i = 0; i < n; ++i) {
    names[i] = fresh_name(c.vertex_arrays, c.next_vertex_array_name);
    c.vertex_arrays[names[i]] = std::make_unique<VertexArrayObject>();
  }
}

void GLAPIENTRY glDeleteVertexArrays(GLsizei n, const GLuint* names) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  if (!names) return;
  c.touch();
  for (GLsizei i = 0; i < n; ++i) {
    if (names[i] == 0) continue;
    if (c.vertex_arrays.erase(names[i]) && c.bound_vertex_array == names[i]) c.bound_vertex_array = 0;
  }
}

GLboolean GLAPIENTRY glIsVertexArray(GLuint name) {
  GL_CONTEXT(GL_FALSE);
  GL_OUTSIDE_BEGIN(GL_FALSE);
  auto it = c.vertex_arrays.find(name);
  return name != 0 && it != c.vertex_arrays.end() && it->second->bound_once ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY glBindVertexArray(GLuint name) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  auto it = c.vertex_arrays.find(name);
  if (name != 0 && it == c.vertex_arrays.end()) return c.error(GL_INVALID_OPERATION);
  c.touch();
  if (it != c.vertex_arrays.end()) it->second->bound_once = true;
  c.bound_vertex_array = name;
}

}  // extern "C"

// --- generic attribute arrays ----------------------------------------------------------

namespace {

// The attribute array `index` of the bound vertex array object, after the checks every
// glVertexAttrib*Pointer and glEnable/DisableVertexAttribArray makes.
AttribArray* attrib_array(Context& c, GLuint index) {
  if (c.in_begin) {
    c.error(GL_INVALID_OPERATION);
    return nullptr;
  }
  if (index >= GLuint(kMaxVertexAttribs)) {
    c.error(GL_INVALID_VALUE);
    return nullptr;
  }
  if (!c.vertex_arrays.count(c.bound_vertex_array)) {
    c.error(GL_INVALID_OPERATION);  // core profile, no vertex array object bound
    return nullptr;
  }
  return &c.vao().attribs[index];
}

void attrib_pointer(Context& c, GLuint index, GLint size, GLenum type, bool normalized, bool integer,
                    GLsizei stride, const void* pointer) {
  AttribArray* a = attrib_array(c, index);
  if (!a) return;
  bool type_ok = false;
  switch (type) {
    case GL_BYTE:
    case GL_UNSIGNED_BYTE:
    case GL_SHORT:
    case GL_UNSIGNED_SHORT:
    case GL_INT:
    case GL_UNSIGNED_INT: type_ok = true; break;
    case GL_FLOAT:
    case GL_HALF_FLOAT:
    case GL_DOUBLE:
    case GL_INT_2_10_10_10_REV:
    case GL_UNSIGNED_INT_2_10_10_10_REV: type_ok = !integer; break;
    default: break;
  }
  if (!type_ok) return c.error(GL_INVALID_ENUM);
  const bool bgra = size == GL_BGRA && !integer;
  if ((size < 1 || size > 4) && !bgra) return c.error(GL_INVALID_VALUE);
  if (stride < 0) return c.error(GL_INVALID_VALUE);
  // GL 3.3 §2.8: BGRA takes unsigned bytes or the packed types, normalized; the packed types
  // take four components (or BGRA).
  if (bgra && (!normalized || (type != GL_UNSIGNED_BYTE && type != GL_INT_2_10_10_10_REV &&
                               type != GL_UNSIGNED_INT_2_10_10_10_REV)))
    return c.error(GL_INVALID_OPERATION);
  if ((type == GL_INT_2_10_10_10_REV || type == GL_UNSIGNED_INT_2_10_10_10_REV) && size != 4 && !bgra)
    return c.error(GL_INVALID_OPERATION);
  // GL 3.3 §2.8: a vertex array object other than 0 reads only buffers.
  if (c.bound_vertex_array != 0 && !c.array_buffer && pointer) return c.error(GL_INVALID_OPERATION);
  c.touch();
  a->size = size;
  a->type = type;
  a->normalized = normalized;
  a->integer = integer;
  a->stride = stride;
  a->buffer = c.array_buffer;
  a->pointer = pointer;
}

}  // namespace

extern "C" {

void GLAPIENTRY glVertexAttribPointer(GLuint index, GLint size, GLenum type, GLboolean normalized,
                                      GLsizei stride, const void* pointer) {
  GL_CONTEXT();
  attrib_pointer(c, index, size, type, normalized != GL_FALSE, false, stride, pointer);
}

void GLAPIENTRY glVertexAttribIPointer(GLuint index, GLint size, GLenum type, GLsizei stride,
                                       const void* pointer) {
  GL_CONTEXT();
  attrib_pointer(c, index, size, type, false, true, stride, pointer);
}

void GLAPIENTRY glEnableVertexAttribArray(GLuint index) {
  GL_CONTEXT();
  if (AttribArray* a = attrib_array(c, index)) {
    c.touch();
    a->enabled = true;
  }
}

void GLAPIENTRY glDisableVertexAttribArray(GLuint index) {
  GL_CONTEXT();
  if (AttribArray* a = attrib_array(c, index)) {
    c.touch();
    a->enabled = false;
  }
}

void GLAPIENTRY glVertexAttribDivisor(GLuint index, GLuint divisor) {
  GL_CONTEXT();
  if (AttribArray* a = attrib_array(c, index)) {
    c.touch();
    a->divisor = divisor;
  }
}

void GLAPIENTRY glGetVertexAttribPointerv(GLuint index, GLenum pname, void** out) {
  GL_CONTEXT();
  if (pname != GL_VERTEX_ATTRIB_ARRAY_POINTER) return c.error(GL_INVALID_ENUM);
  AttribArray* a = attrib_array(c, index);
  if (a && out) *out = const_cast<void*>(a->pointer);
}

}  // extern "C"

namespace {

// glGetVertexAttrib*: the array state of `index`, or its current value (4 words of `type`).
bool vertex_attrib_state(Context& c, GLuint index, GLenum pname, double* out, int& n, uint32_t* words,
                         GLenum& type) {
  n = 1;
  if (index >= GLuint(kMaxVertexAttribs)) {
    c.error(GL_INVALID_VALUE);
    return false;
  }
  if (pname == GL_CURRENT_VERTEX_ATTRIB) {
    // GL 3.3 §6.1.12: attribute 0 of a compatibility context is the current vertex, which
    // has no current value to query.
    if (index == 0 && !c.core_profile) {
      c.error(GL_INVALID_OPERATION);
      return false;
    }
    std::memcpy(words, c.generic_current[index].data(), 16);
    type = c.generic_type[index];
    n = 4;
    return true;
  }
  if (!c.vertex_arrays.count(c.bound_vertex_array)) {
    c.error(GL_INVALID_OPERATION);
    return false;
  }
  const AttribArray& a = c.vao().attribs[index];
  switch (pname) {
    case GL_VERTEX_ATTRIB_ARRAY_ENABLED: out[0] = a.enabled; break;
    case GL_VERTEX_ATTRIB_ARRAY_SIZE: out[0] = a.size; break;
    case GL_VERTEX_ATTRIB_ARRAY_STRIDE: out[0] = a.stride; break;
    case GL_VERTEX_ATTRIB_ARRAY_TYPE: out[0] = a.type; break;
    case GL_VERTEX_ATTRIB_ARRAY_NORMALIZED: out[0] = a.normalized; break;
    case GL_VERTEX_ATTRIB_ARRAY_INTEGER: out[0] = a.integer; break;
    case GL_VERTEX_ATTRIB_ARRAY_DIVISOR: out[0] = a.divisor; break;
    case GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING: out[0] = a.buffer ? a.buffer->name : 0; break;
    default: c.error(GL_INVALID_ENUM); return false;
  }
  type = 0;
  return true;
}

// Integer queries of an integer current value (glGetVertexAttribIiv/Iuiv) give its words;
// the others convert the value.
template <class T>
void get_vertex_attrib(GLuint index, GLenum pname, T* out, bool words_out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  double v[4] = {0, 0, 0, 0};
  uint32_t words[4] = {0, 0, 0, 0};
  int n = 1;
  GLenum type = 0;
  if (!vertex_attrib_state(c, index, pname, v, n, words, type) || !out) return;
  if (type == 0) {
    for (int i = 0; i < n; ++i) out[i] = T(v[i]);
    return;
  }
  for (int i = 0; i < 4; ++i) {
    if constexpr (sizeof(T) == 4 && std::is_integral_v<T>) {
      if (words_out) {
        std::memcpy(&out[i], &words[i], 4);
        continue;
      }
    }
    float f;
    std::memcpy(&f, &words[i], 4);
    out[i] = type == GL_FLOAT ? T(f) : type == GL_INT ? T(int32_t(words[i])) : T(words[i]);
  }
}

}  // namespace

extern "C" {

void GLAPIENTRY glGetVertexAttribfv(GLuint index, GLenum pname, GLfloat* out) {
  get_vertex_attrib(index, pname, out, false);
}
void GLAPIENTRY glGetVertexAttribdv(GLuint index, GLenum pname, GLdouble* out) {
  get_vertex_attrib(index, pname, out, false);
}
void GLAPIENTRY glGetVertexAttribiv(GLuint index, GLenum pname, GLint* out) {
  get_vertex_attrib(index, pname, out, false);
}
void GLAPIENTRY glGetVertexAttribIiv(GLuint index, GLenum pname, GLint* out) {
  get_vertex_attrib(index, pname, out, true);
}
void GLAPIENTRY glGetVertexAttribIuiv(GLuint index, GLenum pname, GLuint* out) {
  get_vertex_attrib(index, pname, out, true);
}

}  // extern "C"

// --- current generic attribute values (glVertexAttrib*) ---------------------------------

namespace {

void set_generic(Context& c, GLuint index, GLenum type, const uint32_t* words) {
  if (index >= GLuint(kMaxVertexAttribs)) return c.error(GL_INVALID_VALUE);
  if (index == 0 && !c.core_profile && type == GL_FLOAT) {
    // GL 3.3 compatibility §2.7: attribute 0 is the vertex; between glBegin and glEnd it
    // makes one.
    float f[4];
    std::memcpy(f, words, 16);
    if (c.in_begin) return c.vertex(f[0], f[1], f[2], f[3]);
  }
  c.touch();
  std::memcpy(c.generic_current[index].data(), words, 16);
  c.generic_type[index] = type;
}

void set_float(Context& c, GLuint index, float x, float y, float z, float w) {
  const float f[4] = {x, y, z, w};
  uint32_t words[4];
  std::memcpy(words, f, 16);
  set_generic(c, index, GL_FLOAT, words);
}

void set_int(Context& c, GLuint index, GLenum type, uint32_t x, uint32_t y, uint32_t z, uint32_t w) {
  const uint32_t words[4] = {x, y, z, w};
  set_generic(c, index, type, words);
}

template <class T>
float normalized(T v) {
  if constexpr (std::is_signed_v<T>) {
    const double max = double(std::numeric_limits<T>::max());
    return float((2.0 * double(v) + 1.0) / (2.0 * max + 1.0));
  } else {
    return float(double(v) / double(std::numeric_limits<T>::max()));
  }
}

}  // namespace

extern "C" {

void GLAPIENTRY glVertexAttrib1f(GLuint i, GLfloat x) {
  GL_CONTEXT();
  set_float(c, i, x, 0, 0, 1);
}
void GLAPIENTRY glVertexAttrib2f(GLuint i, GLfloat x, GLfloat y) {
  GL_CONTEXT();
  set_float(c, i, x, y, 0, 1);
}
void GLAPIENTRY glVertexAttrib3f(GLuint i, GLfloat x, GLfloat y, GLfloat z) {
  GL_CONTEXT();
  set_float(c, i, x, y, z, 1);
}
void GLAPIENTRY glVertexAttrib4f(GLuint i, GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  GL_CONTEXT();
  set_float(c, i, x, y, z, w);
}
void GLAPIENTRY glVertexAttrib1d(GLuint i, GLdouble x) { glVertexAttrib1f(i, GLfloat(x)); }
void GLAPIENTRY glVertexAttrib2d(GLuint i, GLdouble x, GLdouble y) {
  glVertexAttrib2f(i, GLfloat(x), GLfloat(y));
}
void GLAPIENTRY glVertexAttrib3d(GLuint i, GLdouble x, GLdouble y, GLdouble z) {
  glVertexAttrib3f(i, GLfloat(x), GLfloat(y), GLfloat(z));
}
void GLAPIENTRY glVertexAttrib4d(GLuint i, GLdouble x, GLdouble y, GLdouble z, GLdouble w) {
  glVertexAttrib4f(i, GLfloat(x), GLfloat(y), GLfloat(z), GLfloat(w));
}
void GLAPIENTRY glVertexAttrib1s(GLuint i, GLshort x) { glVertexAttrib1f(i, x); }
void GLAPIENTRY glVertexAttrib2s(GLuint i, GLshort x, GLshort y) { glVertexAttrib2f(i, x, y); }
void GLAPIENTRY glVertexAttrib3s(GLuint i, GLshort x, GLshort y, GLshort z) { glVertexAttrib3f(i, x, y, z); }
void GLAPIENTRY glVertexAttrib4s(GLuint i, GLshort x, GLshort y, GLshort z, GLshort w) {
  glVertexAttrib4f(i, x, y, z, w);
}
#define TESSEL_ATTRIB_V(N, SUF, T)                                  \
  void GLAPIENTRY glVertexAttrib##N##SUF##v(GLuint i, const T* v) { \
    if (!v) return;                                                 \
    GLfloat f[4] = {0, 0, 0, 1};                                    \
    for (int k = 0; k < N; ++k) f[k] = GLfloat(v[k]);               \
    glVertexAttrib4f(i, f[0], f[1], f[2], f[3]);                    \
  }
TESSEL_ATTRIB_V(1, f, GLfloat)
TESSEL_ATTRIB_V(2, f, GLfloat)
TESSEL_ATTRIB_V(3, f, GLfloat)
TESSEL_ATTRIB_V(4, f, GLfloat)
TESSEL_ATTRIB_V(1, d, GLdouble)
TESSEL_ATTRIB_V(2, d, GLdouble)
TESSEL_ATTRIB_V(3, d, GLdouble)
TESSEL_ATTRIB_V(4, d, GLdouble)
TESSEL_ATTRIB_V(1, s, GLshort)
TESSEL_ATTRIB_V(2, s, GLshort)
TESSEL_ATTRIB_V(3, s, GLshort)
TESSEL_ATTRIB_V(4, s, GLshort)
TESSEL_ATTRIB_V(4, b, GLbyte)
TESSEL_ATTRIB_V(4, i, GLint)
TESSEL_ATTRIB_V(4, ub, GLubyte)
TESSEL_ATTRIB_V(4, us, GLushort)
TESSEL_ATTRIB_V(4, ui, GLuint)
#undef TESSEL_ATTRIB_V
#define TESSEL_ATTRIB_NV(SUF, T)                                                                 \
  void GLAPIENTRY glVertexAttrib4N##SUF##v(GLuint i, const T* v) {                               \
    if (!v) return;                                                                              \
    glVertexAttrib4f(i, normalized(v[0]), normalized(v[1]), normalized(v[2]), normalized(v[3])); \
  }
TESSEL_ATTRIB_NV(b, GLbyte)
TESSEL_ATTRIB_NV(s, GLshort)
TESSEL_ATTRIB_NV(i, GLint)
TESSEL_ATTRIB_NV(ub, GLubyte)
TESSEL_ATTRIB_NV(us, GLushort)
TESSEL_ATTRIB_NV(ui, GLuint)
#undef TESSEL_ATTRIB_NV
void GLAPIENTRY glVertexAttrib4Nub(GLuint i, GLubyte x, GLubyte y, GLubyte z, GLubyte w) {
  glVertexAttrib4f(i, normalized(x), normalized(y), normalized(z), normalized(w));
}

void GLAPIENTRY glVertexAttribI4i(GLuint i, GLint x, GLint y, GLint z, GLint w) {
  GL_CONTEXT();
  set_int(c, i, GL_INT, uint32_t(x), uint32_t(y), uint32_t(z), uint32_t(w));
}
void GLAPIENTRY glVertexAttribI4ui(GLuint i, GLuint x, GLuint y, GLuint z, GLuint w) {
  GL_CONTEXT();
  set_int(c, i, GL_UNSIGNED_INT, x, y, z, w);
}
void GLAPIENTRY glVertexAttribI1i(GLuint i, GLint x) { glVertexAttribI4i(i, x, 0, 0, 0); }
void GLAPIENTRY glVertexAttribI2i(GLuint i, GLint x, GLint y) { glVertexAttribI4i(i, x, y, 0, 0); }
void GLAPIENTRY glVertexAttribI3i(GLuint i, GLint x, GLint y, GLint z) { glVertexAttribI4i(i, x, y, z, 0); }
void GLAPIENTRY glVertexAttribI1ui(GLuint i, GLuint x) { glVertexAttribI4ui(i, x, 0, 0, 0); }
void GLAPIENTRY glVertexAttribI2ui(GLuint i, GLuint x, GLuint y) { glVertexAttribI4ui(i, x, y, 0, 0); }
void GLAPIENTRY glVertexAttribI3ui(GLuint i, GLuint x, GLuint y, GLuint z) {
  glVertexAttribI4ui(i, x, y, z, 0);
}
#define TESSEL_ATTRIBI_V(N, SUF, T, FN, U)                           \
  void GLAPIENTRY glVertexAttribI##N##SUF##v(GLuint i, const T* v) { \
    if (!v) return;                                                  \
    U f[4] = {0, 0, 0, 0};                                           \
    for (int k = 0; k < N; ++k) f[k] = U(v[k]);                      \
    FN(i, f[0], f[1], f[2], f[3]);                                   \
  }
TESSEL_ATTRIBI_V(1, i, GLint, glVertexAttribI4i, GLint)
TESSEL_ATTRIBI_V(2, i, GLint, glVertexAttribI4i, GLint)
TESSEL_ATTRIBI_V(3, i, GLint, glVertexAttribI4i, GLint)
TESSEL_ATTRIBI_V(4, i, GLint, glVertexAttribI4i, GLint)
TESSEL_ATTRIBI_V(1, ui, GLuint, glVertexAttribI4ui, GLuint)
TESSEL_ATTRIBI_V(2, ui, GLuint, glVertexAttribI4ui, GLuint)
TESSEL_ATTRIBI_V(3, ui, GLuint, glVertexAttribI4ui, GLuint)
TESSEL_ATTRIBI_V(4, ui, GLuint, glVertexAttribI4ui, GLuint)
#undef TESSEL_ATTRIBI_V
void GLAPIENTRY glVertexAttribI4bv(GLuint i, const GLbyte* v) {
  if (v) glVertexAttribI4i(i, v[0], v[1], v[2], v[3]);
}
void GLAPIENTRY glVertexAttribI4sv(GLuint i, const GLshort* v) {
  if (v) glVertexAttribI4i(i, v[0], v[1], v[2], v[3]);
}
void GLAPIENTRY glVertexAttribI4ubv(GLuint i, const GLubyte* v) {
  if (v) glVertexAttribI4ui(i, v[0], v[1], v[2], v[3]);
}
void GLAPIENTRY glVertexAttribI4usv(GLuint i, const GLushort* v) {
  if (v) glVertexAttribI4ui(i, v[0], v[1], v[2], v[3]);
}

}  // extern "C"

}  // namespace tessel::gl
