#include "tessel/gpu/framebuffer.hpp"

#include <algorithm>
#include <climits>

namespace tessel::gpu {

Format Attachment::format() const {
  return texture ? texture->format() : texture_3d ? texture_3d->format() : texture_array->format();
}
int Attachment::levels() const {
  return texture ? texture->levels() : texture_3d ? texture_3d->levels() : texture_array->levels();
}
int Attachment::layers() const {
  if (texture) return 1;
  if (texture_array) return texture_array->layers();
  return level >= 0 && level < texture_3d->levels() ? texture_3d->depth(level) : 0;
}
int Attachment::width() const {
  return texture      ? texture->width(level)
         : texture_3d ? texture_3d->width(level)
                      : texture_array->width(level);
}
int Attachment::height() const {
  return texture      ? texture->height(level)
         : texture_3d ? texture_3d->height(level)
                      : texture_array->height(level);
}
std::byte* Attachment::data() const {
  if (level < 0 || level >= levels()) return nullptr;
  // Attachments are written by the raster phase; the texture is not otherwise changed while a
  // frame runs (any change flushes first).
  if (texture) return const_cast<std::byte*>(texture->level(level).data.data());
  if (layer < 0 || layer >= layers()) return nullptr;
  const Level3D& lv = texture_3d ? texture_3d->level(level) : texture_array->level(level);
  return const_cast<std::byte*>(lv.data.data()) + lv.slice_bytes() * size_t(layer);
}
size_t Attachment::row_bytes() const {
  if (texture) return texture->level(level).row_bytes();
  const Level3D& lv = texture_3d ? texture_3d->level(level) : texture_array->level(level);
  return lv.height > 0 ? lv.slice_bytes() / size_t(lv.height) : 0;
}

glm::vec4 Attachment::fetch(int x, int y) const {
  return texture      ? texture->fetch(level, x, y)
         : texture_3d ? texture_3d->fetch(level, x, y, layer)
                      : texture_array->fetch(level, x, y, layer);
}
void Attachment::store(int x, int y, const glm::vec4& value) const {
  if (texture)
    texture->store(level, x, y, value);
  else if (texture_3d)
    texture_3d->store(level, x, y, layer, value);
  else
    texture_array->store(level, x, y, layer, value);
}

std::string Framebuffer::incomplete_reason() const {
  bool any = false;
  auto check = [&](const Attachment& a, const std::string& name, bool want_depth) -> std::string {
    if (!a) return {};
    any = true;
    if (a.level < 0 || a.level >= a.levels())
      return name + ": level " + std::to_string(a.level) + " does not exist (the texture has " +
             std::to_string(a.levels()) + ")";
    if (!a.texture && (a.layer < 0 || a.layer >= a.layers()))
      return name + ": layer " + std::to_string(a.layer) + " does not exist (the level has " +
             std::to_string(a.layers()) + ")";
    if (is_depth_format(a.format()) != want_depth)
      return name + ": format " + format_info(a.format()).name + " is not a " +
             (want_depth ? "depth" : "colour") + " format";
    return {};
  };
  for (int i = 0; i < kMaxColorAttachments; ++i) {
    std::string r = check(color[i], "colour attachment " + std::to_string(i), false);
    if (!r.empty()) return r;
  }
  std::string r = check(depth, "depth attachment", true);
  if (!r.empty()) return r;
  if (!any) return "no attachments";
  return {};
}

int Framebuffer::width() const {
  int w = INT_MAX;
  for (const auto& a : color)
    if (a) w = std::min(w, a.width());
  if (depth) w = std::min(w, depth.width());
  return w == INT_MAX ? 0 : w;
}

int Framebuffer::height() const {
  int h = INT_MAX;
  for (const auto& a : color)
    if (a) h = std::min(h, a.height());
  if (depth) h = std::min(h, depth.height());
  return h == INT_MAX ? 0 : h;
}

}  // namespace tessel::gpu
