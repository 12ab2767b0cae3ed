#include "tessel/gpu/framebuffer.hpp"

#include <algorithm>
#include <climits>

namespace tessel::gpu {

std::string Framebuffer::incomplete_reason() const {
  bool any = false;
  auto check = [&](const Attachment& a, const std::string& name, bool want_depth) -> std::string {
    if (!a.texture) return {};
    any = true;
    if (a.level < 0 || a.level >= a.texture->levels())
      return name + ": level " + std::to_string(a.level) + " does not exist (the texture has " +
             std::to_string(a.texture->levels()) + ")";
    if (is_depth_format(a.texture->format()) != want_depth)
      return name + ": format " + format_info(a.texture->format()).name + " is not a " +
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
    if (a.texture) w = std::min(w, a.texture->width(a.level));
  if (depth.texture) w = std::min(w, depth.texture->width(depth.level));
  return w == INT_MAX ? 0 : w;
}

int Framebuffer::height() const {
  int h = INT_MAX;
  for (const auto& a : color)
    if (a.texture) h = std::min(h, a.texture->height(a.level));
  if (depth.texture) h = std::min(h, depth.texture->height(depth.level));
  return h == INT_MAX ? 0 : h;
}

}  // namespace tessel::gpu
