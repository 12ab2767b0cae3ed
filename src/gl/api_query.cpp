// Query objects (GL 3.3 §2.14, §6.1.7): occlusion (GL_SAMPLES_PASSED, GL_ANY_SAMPLES_PASSED),
// GL_PRIMITIVES_GENERATED, GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, timer queries (GL_TIME_ELAPSED,
// glQueryCounter with GL_TIMESTAMP); conditional rendering (§2.15); and sync objects (§5.2).
//
// A query's counts come from the pipeline's counters (gpu::Context::stats) read when it begins
// and when it ends, each after the work before it has run; the result is ready at the end.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <chrono>

#include "api.hpp"

namespace tessel::gl {

namespace {

int query_slot(GLenum target) {
  switch (target) {
    case GL_SAMPLES_PASSED: return 0;
    case GL_ANY_SAMPLES_PASSED: return 1;
    case GL_PRIMITIVES_GENERATED: return 2;
    case GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN: return 3;
    case GL_TIME_ELAPSED: return 4;
    default: return -1;
  }
}

uint64_t now_ns() {
  return uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(
                      std::chrono::steady_clock::now().time_since_epoch())
                      .count());
}

// Counters after all the work so far has run.
gpu::Stats settled(Context& c) {
  c.touch();
  c.finish();
  return c.gpu().stats();
}

QueryObject* query_of(Context& c, GLuint id) {
  auto it = c.queries.find(id);
  return id != 0 && it != c.queries.end() && it->second ? it->second.get() : nullptr;
}

template <class T>
void get_query_object(GLuint id, GLenum pname, T* out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  QueryObject* q = query_of(c, id);
  if (!q) return c.error(GL_INVALID_OPERATION);
  for (const QueryObject* a : c.active_queries)
    if (a == q) return c.error(GL_INVALID_OPERATION);  // §6.1.7: not while active
  if (pname != GL_QUERY_RESULT && pname != GL_QUERY_RESULT_AVAILABLE) return c.error(GL_INVALID_ENUM);
  if (!out) return;
  // Results are ready when the query ends (the work was finished then).
  *out = pname == GL_QUERY_RESULT_AVAILABLE ? T(1) : T(q->result);
}

struct SyncObject {
  GLenum condition = GL_SYNC_GPU_COMMANDS_COMPLETE;
};

}  // namespace

bool Context::conditional_render_skips() {
  if (!conditional_query) return false;
  return conditional_query->result == 0;
}

}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glGenQueries(GLsizei n, GLuint* ids) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = fresh_name(c.queries, c.next_query_name);
    c.queries[name] = nullptr;  // the object is made by glBeginQuery
    if (ids) ids[i] = name;
  }
}
void GLAPIENTRY glDeleteQueries(GLsizei n, const GLuint* ids) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (n < 0) return c.error(GL_INVALID_VALUE);
  if (!ids) return;
  for (GLsizei i = 0; i < n; ++i) {
    auto it = c.queries.find(ids[i]);
    if (ids[i] == 0 || it == c.queries.end()) continue;
    // An active query that is deleted ends, with its result discarded (§2.14).
    for (QueryObject*& a : c.active_queries)
      if (it->second && a == it->second.get()) a = nullptr;
    if (c.conditional_query == it->second) c.conditional_query = nullptr;
    c.queries.erase(it);
  }
}
GLboolean GLAPIENTRY glIsQuery(GLuint id) {
  GL_CONTEXT(GLboolean(GL_FALSE));
  GL_OUTSIDE_BEGIN(GLboolean(GL_FALSE));
  return query_of(c, id) ? GL_TRUE : GL_FALSE;
}
void GLAPIENTRY glBeginQuery(GLenum target, GLuint id) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  const int slot = query_slot(target);
  if (slot < 0) return c.error(GL_INVALID_ENUM);
  if (c.active_queries[size_t(slot)]) return c.error(GL_INVALID_OPERATION);
  auto it = c.queries.find(id);
  if (id == 0 || it == c.queries.end()) return c.error(GL_INVALID_OPERATION);
  if (!it->second) {
    it->second = std::make_shared<QueryObject>();
    it->second->target = target;
  }
  QueryObject& q = *it->second;
  if (q.target != target) return c.error(GL_INVALID_OPERATION);
  // §2.14: the query conditional rendering is using cannot begin again.
  if (c.conditional_query.get() == &q) return c.error(GL_INVALID_OPERATION);
  for (const QueryObject* a : c.active_queries)
    if (a == &q) return c.error(GL_INVALID_OPERATION);
  const tessel::gpu::Stats s = settled(c);
  q.start_samples = s.fragments_written;
  q.start_primitives = s.primitives_generated;
  q.start_written = s.primitives_written;
  q.start_ns = now_ns();
  q.result = 0;
  c.active_queries[size_t(slot)] = &q;
}
void GLAPIENTRY glEndQuery(GLenum target) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  const int slot = query_slot(target);
  if (slot < 0) return c.error(GL_INVALID_ENUM);
  QueryObject* q = c.active_queries[size_t(slot)];
  if (!q) return c.error(GL_INVALID_OPERATION);
  const tessel::gpu::Stats s = settled(c);
  switch (target) {
    case GL_SAMPLES_PASSED: q->result = s.fragments_written - q->start_samples; break;
    case GL_ANY_SAMPLES_PASSED: q->result = s.fragments_written != q->start_samples ? 1 : 0; break;
    case GL_PRIMITIVES_GENERATED: q->result = s.primitives_generated - q->start_primitives; break;
    case GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN: q->result = s.primitives_written - q->start_written; break;
    default: q->result = now_ns() - q->start_ns; break;  // GL_TIME_ELAPSED
  }
  c.active_queries[size_t(slot)] = nullptr;
}
void GLAPIENTRY glQueryCounter(GLuint id, GLenum target) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (target != GL_TIMESTAMP) return c.error(GL_INVALID_ENUM);
  auto it = c.queries.find(id);
  if (id == 0 || it == c.queries.end()) return c.error(GL_INVALID_OPERATION);
  for (const QueryObject* a : c.active_queries)
    if (a && a == it->second.get()) return c.error(GL_INVALID_OPERATION);
  if (!it->second) {
    it->second = std::make_shared<QueryObject>();
    it->second->target = GL_TIMESTAMP;
  }
  if (it->second->target != GL_TIMESTAMP) return c.error(GL_INVALID_OPERATION);
  settled(c);
  it->second->result = now_ns();
}
void GLAPIENTRY glGetQueryiv(GLenum target, GLenum pname, GLint* out) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (target == GL_TIMESTAMP) {
    if (pname != GL_QUERY_COUNTER_BITS) return c.error(GL_INVALID_ENUM);
    if (out) *out = 64;
    return;
  }
  const int slot = query_slot(target);
  if (slot < 0) return c.error(GL_INVALID_ENUM);
  if (!out) return;
  if (pname == GL_CURRENT_QUERY) {
    const QueryObject* q = c.active_queries[size_t(slot)];
    GLuint name = 0;
    for (const auto& [n, r] : c.queries)
      if (q && r.get() == q) name = n;
    *out = GLint(name);
  } else if (pname == GL_QUERY_COUNTER_BITS) {
    *out = target == GL_ANY_SAMPLES_PASSED ? 1 : 64;
  } else {
    c.error(GL_INVALID_ENUM);
  }
}
void GLAPIENTRY glGetQueryObjectiv(GLuint id, GLenum pname, GLint* out) { get_query_object(id, pname, out); }
void GLAPIENTRY glGetQueryObjectuiv(GLuint id, GLenum pname, GLuint* out) {
  get_query_object(id, pname, out);
}
void GLAPIENTRY glGetQueryObjecti64v(GLuint id, GLenum pname, GLint64* out) {
  get_query_object(id, pname, out);
}
void GLAPIENTRY glGetQueryObjectui64v(GLuint id, GLenum pname, GLuint64* out) {
  get_query_object(id, pname, out);
}

// §2.15: draws and clears between these are skipped when the query counted no samples.
void GLAPIENTRY glBeginConditionalRender(GLuint id, GLenum mode) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (mode != GL_QUERY_WAIT && mode != GL_QUERY_NO_WAIT && mode != GL_QUERY_BY_REGION_WAIT &&
      mode != GL_QUERY_BY_REGION_NO_WAIT)
    return c.error(GL_INVALID_ENUM);
  if (c.conditional_query) return c.error(GL_INVALID_OPERATION);
  // GL 3.3 §2.15: a name that is not a query object (never made by glBeginQuery) is
  // GL_INVALID_VALUE; a query of another kind, or still active, GL_INVALID_OPERATION.
  if (id == 0 || !c.queries.count(id) || !c.queries[id]) return c.error(GL_INVALID_VALUE);
  QueryObject* q = query_of(c, id);
  if (!q || (q->target != GL_SAMPLES_PASSED && q->target != GL_ANY_SAMPLES_PASSED))
    return c.error(GL_INVALID_OPERATION);
  for (const QueryObject* a : c.active_queries)
    if (a == q) return c.error(GL_INVALID_OPERATION);
  c.touch();
  c.conditional_query = c.queries[id];
}
void GLAPIENTRY glEndConditionalRender(void) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!c.conditional_query) return c.error(GL_INVALID_OPERATION);
  c.touch();
  c.conditional_query = nullptr;
}

// Sync objects: commands run in order, so a fence is signaled once the work before it has run;
// glFenceSync finishes that work.
GLsync GLAPIENTRY glFenceSync(GLenum condition, GLbitfield flags) {
  GL_CONTEXT(GLsync(nullptr));
  GL_OUTSIDE_BEGIN(GLsync(nullptr));
  if (condition != GL_SYNC_GPU_COMMANDS_COMPLETE) {
    c.error(GL_INVALID_ENUM);
    return nullptr;
  }
  if (flags != 0) {
    c.error(GL_INVALID_VALUE);
    return nullptr;
  }
  settled(c);
  auto s = std::make_unique<SyncObject>();
  GLsync handle = reinterpret_cast<GLsync>(s.get());
  c.syncs[handle] = std::shared_ptr<void>(s.release(), [](void* p) { delete static_cast<SyncObject*>(p); });
  return handle;
}
GLboolean GLAPIENTRY glIsSync(GLsync sync) {
  GL_CONTEXT(GLboolean(GL_FALSE));
  GL_OUTSIDE_BEGIN(GLboolean(GL_FALSE));
  return c.syncs.count(sync) ? GL_TRUE : GL_FALSE;
}
void GLAPIENTRY glDeleteSync(GLsync sync) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!sync) return;
  if (!c.syncs.erase(sync)) c.error(GL_INVALID_VALUE);
}
GLenum GLAPIENTRY glClientWaitSync(GLsync sync, GLbitfield flags, GLuint64) {
  GL_CONTEXT(GLenum(GL_WAIT_FAILED));
  GL_OUTSIDE_BEGIN(GLenum(GL_WAIT_FAILED));
  if (!c.syncs.count(sync) || (flags & ~GLbitfield(GL_SYNC_FLUSH_COMMANDS_BIT))) {
    c.error(GL_INVALID_VALUE);
    return GL_WAIT_FAILED;
  }
  return GL_ALREADY_SIGNALED;
}
void GLAPIENTRY glWaitSync(GLsync sync, GLbitfield flags, GLuint64 timeout) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!c.syncs.count(sync) || flags != 0 || timeout != GL_TIMEOUT_IGNORED) return c.error(GL_INVALID_VALUE);
}
void GLAPIENTRY glGetSynciv(GLsync sync, GLenum pname, GLsizei size, GLsizei* length, GLint* values) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!c.syncs.count(sync)) return c.error(GL_INVALID_VALUE);
  if (size < 0) return c.error(GL_INVALID_VALUE);
  GLint v;
  switch (pname) {
    case GL_OBJECT_TYPE: v = GL_SYNC_FENCE; break;
    case GL_SYNC_STATUS: v = GL_SIGNALED; break;
    case GL_SYNC_CONDITION: v = GL_SYNC_GPU_COMMANDS_COMPLETE; break;
    case GL_SYNC_FLAGS: v = 0; break;
    default: return c.error(GL_INVALID_ENUM);
  }
  if (size >= 1 && values) values[0] = v;
  if (length) *length = size >= 1 ? 1 : 0;
}

}  // extern "C"
