// Transform feedback (GL 3.3 §2.15): glBeginTransformFeedback / glEndTransformFeedback, and
// what a draw between them must agree with. The varyings are chosen with
// glTransformFeedbackVaryings (api_program.cpp), the buffers bound with glBindBufferBase/Range
// (api_buffer.cpp); the gpu layer captures the primitives (gpu::Capture) and the draws run
// at once, so the buffers hold the results when the draw call returns.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <limits>

#include "api.hpp"

namespace tessel::gl {

bool Context::feedback_takes(GLenum draw_mode) const {
  // The primitives that reach transform feedback: the geometry stage's, or the draw's.
  GLenum out = draw_mode;
  if (const glsl::GeometryInfo* gi = executable ? executable->geometry() : nullptr) out = gi->output_type;
  switch (out) {
    case GL_POINTS: return feedback.mode == GL_POINTS;
    case GL_LINES:
    case GL_LINE_LOOP:
    case GL_LINE_STRIP:
    case GL_LINES_ADJACENCY:
    case GL_LINE_STRIP_ADJACENCY: return feedback.mode == GL_LINES;
    default: return feedback.mode == GL_TRIANGLES;  // triangles, strips, fans, quads, polygons
  }
}

}  // namespace tessel::gl

using namespace tessel::gl;

extern "C" {

void GLAPIENTRY glBeginTransformFeedback(GLenum mode) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (mode != GL_POINTS && mode != GL_LINES && mode != GL_TRIANGLES) return c.error(GL_INVALID_ENUM);
  if (c.feedback.active) return c.error(GL_INVALID_OPERATION);
  // A program in use that captures something, and a buffer at every binding point it writes.
  const tessel::glsl::Program* p = c.executable.get();
  if (!p || p->feedback_varyings().empty()) return c.error(GL_INVALID_OPERATION);
  const auto& words = p->feedback_words();
  for (size_t i = 0; i < words.size(); ++i)
    if (!c.feedback_bindings[i].buffer) return c.error(GL_INVALID_OPERATION);
  c.touch();
  Context::Feedback& f = c.feedback;
  f.active = true;
  f.mode = mode;
  f.program = c.executable;
  f.buffers.clear();
  f.capture = {};
  f.capture.mode = mode == GL_POINTS  ? tessel::gpu::Topology::Points
                   : mode == GL_LINES ? tessel::gpu::Topology::Lines
                                      : tessel::gpu::Topology::Triangles;
  for (size_t i = 0; i < words.size(); ++i) {
    const Context::IndexedBuffer& b = c.feedback_bindings[i];
    f.buffers.push_back(b.buffer);
    tessel::gpu::CaptureBuffer cb;
    cb.buffer = &b.buffer->data;
    cb.offset = size_t(b.offset);
    // glBindBufferBase: to the end of the buffer as it is when written.
    cb.end = b.size ? size_t(b.offset) + size_t(b.size) : std::numeric_limits<size_t>::max();
    cb.words = words[i];
    f.capture.buffers.push_back(std::move(cb));
  }
}

void GLAPIENTRY glEndTransformFeedback(void) {
  GL_CONTEXT();
  GL_OUTSIDE_BEGIN();
  if (!c.feedback.active) return c.error(GL_INVALID_OPERATION);
  c.touch();
  c.feedback = {};
}

}  // extern "C"
