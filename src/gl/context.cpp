// The GL context: its construction and size, the current context, the version and the
// extensions it reports, the transient buffers queued draws keep, and finishing a frame.
// The rest of Context's work is in files of its own: draw_targets.cpp (the framebuffer draws
// and clears go to), decompose.cpp (immediate mode into primitives), state_translation.cpp
// (GL state into gpu RenderState and fixed-function uniforms), batch.cpp (batches into gpu
// draws), draw_glsl.cpp (draws with programs).
#include "context.hpp"

#include <algorithm>

namespace tessel::gl {

namespace {
thread_local Context* g_current = nullptr;
}  // namespace

Context* current() { return g_current; }
void make_current(Context* c) { g_current = c; }

Context::Context(int width, int height, bool double_buffer, bool depth, bool stencil, bool alpha)
    : double_buffer_(double_buffer), has_depth_(depth || stencil), has_stencil_(stencil), has_alpha_(alpha) {
  for (auto& m : matrices) m.assign(1, glm::mat4(1.0f));
  for (int i = 0; i < kTexTargetCount; ++i) default_textures[size_t(i)] = make_texture(0, TexTarget(i));
  s.color.draw_buffer = double_buffer ? GL_BACK : GL_FRONT;
  s.pixel.read_buffer = double_buffer ? GL_BACK : GL_FRONT;
  for (int i = 0; i < kMaxLights; ++i) s.light.spot_cutoff[size_t(i)] = 180.0f;
  s.light.light[0].diffuse = glm::vec4(1.0f);
  s.light.light[0].specular = glm::vec4(1.0f);
  s.light.material[0] = s.light.material[1] = FFMaterial{};
  set_version(2, 1, false);
  generic_type.fill(GL_FLOAT);
  for (auto& g : generic_current) g = {0, 0, 0, 0x3F800000u};  // (0, 0, 0, 1)
  gpu_ = std::make_unique<gpu::Context>();
  resize(width, height);
  s.viewport = {0, 0, width_, height_, 0.0, 1.0};
  s.scissor = {false, 0, 0, width_, height_};
}

Context::~Context() {
  if (g_current == this) g_current = nullptr;
  batch_ = {};
  gpu_->finish();
}

void Context::resize(int width, int height) {
  width = std::clamp(width, 1, gpu::kMaxViewportSize);
  height = std::clamp(height, 1, gpu::kMaxViewportSize);
  if (width == width_ && height == height_ && color_[0]) return;
  touch();
  gpu_->finish();
  fb_ = gpu::Framebuffer();
  fb_target_ = 0;
  gpu_->bind_framebuffer(nullptr);
  width_ = width;
  height_ = height;
  // New buffers start black (alpha 0, or 1 without alpha bits) with depth 1, as a freshly
  // mapped window would.
  for (int i = 0; i < (double_buffer_ ? 2 : 1); ++i) {
    color_[i] = std::make_unique<gpu::Texture2D>(gpu::Format::RGBA8, width, height);
    if (has_alpha_) continue;
    gpu::Framebuffer f(color_[i].get(), nullptr);
    gpu_->bind_framebuffer(&f);
    gpu::ClearValues cv;
    cv.color = {0.0f, 0.0f, 0.0f, 1.0f};
    cv.clear_depth = cv.clear_stencil = false;
    gpu_->clear(cv);
    gpu_->finish();
    gpu_->bind_framebuffer(nullptr);
  }
  if (!double_buffer_) color_[1].reset();
  if (has_depth_) {
    depth_ = std::make_unique<gpu::Texture2D>(gpu::Format::Depth24Stencil8, width, height);
    gpu::Framebuffer f(nullptr, depth_.get());
    gpu_->bind_framebuffer(&f);
    gpu::ClearValues cv;
    cv.clear_color = false;
    gpu_->clear(cv);
    gpu_->finish();
    gpu_->bind_framebuffer(nullptr);
  }
}

const std::vector<const char*>& extensions(const Context& c) {
  // A compatibility context also has the extensions whose entry points old code calls by
  // their ARB and EXT names (ext_aliases.cpp): Mesa lists them too. A core context lists
  // those whose names are the core ones.
  static const std::vector<const char*> compat = [] {
    std::vector<const char*> l = {
#include "ext_names.inc"
    };
    l.push_back("GL_ARB_explicit_attrib_location");  // GLSL only: nothing in the registry to alias
    std::sort(l.begin(), l.end(), [](const char* a, const char* b) { return std::strcmp(a, b) < 0; });
    return l;
  }();
  if (!c.core_profile) return compat;
  static const std::vector<const char*> list = {
      "GL_ARB_copy_buffer",
      "GL_ARB_depth_clamp",
      "GL_ARB_draw_elements_base_vertex",
      "GL_ARB_draw_instanced",
      "GL_ARB_explicit_attrib_location",
      "GL_ARB_fragment_shader",
      "GL_ARB_half_float_vertex",
      "GL_ARB_instanced_arrays",
      "GL_ARB_map_buffer_range",
      "GL_ARB_provoking_vertex",
      "GL_ARB_shader_objects",
      "GL_ARB_shading_language_100",
      "GL_ARB_uniform_buffer_object",
      "GL_ARB_vertex_array_bgra",
      "GL_ARB_vertex_array_object",
      "GL_ARB_vertex_buffer_object",
      "GL_ARB_vertex_shader",
      "GL_ARB_vertex_type_2_10_10_10_rev",
      "GL_EXT_bgra",
  };
  return list;
}

void Context::set_version(int major, int minor, bool core) {
  major_version = major;
  minor_version = minor;
  // Only 3.2 and later have profiles; GL 3.1 has no compatibility parts to remove from.
  core_profile = core && (major > 3 || (major == 3 && minor >= 2));
  // A core context has no default vertex array object (GL 3.3 core §2.10): name 0 is no object.
  if (core_profile)
    vertex_arrays.erase(0);
  else if (!vertex_arrays.count(0))
    vertex_arrays[0] = std::make_unique<VertexArrayObject>();
  version_string_ = std::to_string(major) + "." + std::to_string(minor) +
                    (core_profile                              ? " (Core Profile)"
                     : major > 3 || (major == 3 && minor >= 2) ? " (Compatibility Profile)"
                                                               : "") +
                    " Tessel 0.1";
  // GLSL 3.30 is compiled in every context (GL 3.3 §6.1.5 names the newest the context has).
  glsl_version_string_ = major > 3 || (major == 3 && minor >= 3) ? "3.30" : major == 3 ? "1.30" : "1.20";
  extension_string_.clear();
  for (const char* e : extensions(*this)) extension_string_ += std::string(e) + " ";
}

void Context::keep_until_finished(std::unique_ptr<gpu::Buffer> b) {
  transient_bytes_ += b->size();
  transient_buffers_.push_back(std::move(b));
  if (transient_bytes_ > kTransientFlushBytes) {
    gpu_->finish();
    release_transient();
  }
}

void Context::release_transient() {
  transient_buffers_.clear();
  transient_shared_.clear();
  transient_textures_.clear();
  transient_bytes_ = 0;
}

void Context::finish() {
  touch();
  guarded([&] { gpu_->finish(); });
  release_transient();
}

void Context::swap_buffers() {
  finish();
  if (!double_buffer_) return;
  std::swap(color_[0], color_[1]);
  fb_target_ = 0;  // the attachment pointers changed
  gpu_->bind_framebuffer(nullptr);
}

void Context::texture_deleted(const TextureObject& t) {
  for (TextureUnitState& u : s.units)
    for (TextureRef& r : u.bound)
      if (r.get() == &t) r = nullptr;
  // §4.4.2.3: detached from the bound framebuffers (others keep it until they are changed).
  for (FramebufferRef* fb : {&draw_fbo, &read_fbo}) {
    if (!*fb) continue;
    for (Attachment* a : {&(*fb)->depth, &(*fb)->stencil})
      if (a->texture.get() == &t) *a = Attachment{};
    for (Attachment& a : (*fb)->color)
      if (a.texture.get() == &t) a = Attachment{};
  }
}

}  // namespace tessel::gl
