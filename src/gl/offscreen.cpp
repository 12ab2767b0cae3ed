#include "tessel/gl/offscreen.hpp"

#include <cstring>

#include "context.hpp"

namespace tessel::gl {

Offscreen::Offscreen(int width, int height, int threads, bool depth, bool stencil)
    : ctx_(std::make_unique<Context>(width, height, false, depth, stencil)) {
  if (threads > 0) ctx_->gpu().set_threads(threads);
}

Offscreen::~Offscreen() {
  if (current() == ctx_.get()) make_current_context(nullptr);
}

void Offscreen::make_current() { make_current_context(ctx_.get()); }
int Offscreen::width() const { return ctx_->width(); }
int Offscreen::height() const { return ctx_->height(); }

std::vector<uint8_t> Offscreen::read_rgba8() {
  const gpu::Texture2D& front = ctx_->front();
  const auto& data = front.level(0).data;
  std::vector<uint8_t> out(data.size());
  std::memcpy(out.data(), data.data(), data.size());
  return out;
}

uint64_t Offscreen::fragments_shaded() const { return ctx_->gpu().stats().fragments_shaded; }
void Offscreen::reset_stats() { ctx_->gpu().reset_stats(); }

}  // namespace tessel::gl
