#include "scene_render.hpp"

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tessel/gpu/framebuffer.hpp"
#include "tessel/gpu/image.hpp"
#include "tessel/scene/glsl_shaders.hpp"
#include "tessel/scene/scene_file.hpp"

namespace tessel::apps {

namespace {

std::string frame_path(const std::string& out, int frame) {
  char num[16];
  std::snprintf(num, sizeof num, "_%04d", frame);
  const auto dot = out.rfind('.');
  const auto slash = out.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return out + num + ".png";
  return out.substr(0, dot) + num + out.substr(dot);
}

// A JSON object with the counters (more members may be added after them).
nlohmann::ordered_json counters_json(const gpu::Stats& c) {
  return {{"triangles_in", c.primitives_in},          {"culled", c.primitives_culled},
          {"clipped", c.primitives_clipped},          {"triangles_set_up", c.triangles_setup},
          {"vertices_shaded", c.vertices_shaded},     {"fragments_shaded", c.fragments_shaded},
          {"fragments_written", c.fragments_written}, {"fragments_rejected_by_depth", c.fragments_rejected}};
}

void progress(int done, int total) {
  const int width = 30, filled = total ? done * width / total : width;
  std::fprintf(stderr, "\r[%s%s] %d/%d frames", std::string(size_t(filled), '#').c_str(),
               std::string(size_t(width - filled), ' ').c_str(), done, total);
  if (done == total) std::fprintf(stderr, "\n");
}

}  // namespace

int render_scene(const SceneRenderOptions& o) {
  scene::SceneFile file;
  try {
    file = scene::load_scene_file(o.scene);
    if (!o.shading.empty()) {
      const auto shader = o.shading.rfind("glsl-", 0) == 0 ? scene::glsl_shader_by_name(o.shading)
                                                           : scene::shader_by_name(o.shading);
      if (!shader) {
        std::fprintf(stderr,
                     "tessel render: --shading '%s': expected gouraud, phong, normalmap, npr, depth, normal, "
                     "or the GLSL "
                     "glsl-gouraud, glsl-phong, glsl-normalmap, glsl-npr, glsl-depth, glsl-normal\n",
                     o.shading.c_str());
        return 2;
      }
      for (auto& obj : file.scene.objects) obj->shader = shader;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tessel render: %s\n", e.what());
    return 1;
  }
  const int w = o.width ? o.width : file.render.width, h = o.height ? o.height : file.render.height;
  const int threads = o.threads >= 0 ? o.threads : file.render.threads;
  scene::Scene& s = file.scene;
  s.camera.aspect = float(w) / float(h);
  try {
    gpu::Texture2D color(gpu::Format::RGBA8, w, h), depth(gpu::Format::Depth24Stencil8, w, h);
    gpu::Framebuffer fb(&color, &depth);
    gpu::Context ctx(threads);
    ctx.bind_framebuffer(&fb);
    const float dt = 1.0f / file.render.fps;
    // Frames before the first are animated, not drawn.
    for (int f = 0; f < o.first_frame; ++f) s.Animate(dt);
    const int total = o.last_frame - o.first_frame + 1;
    // The frames are streamed into the JSON as they are rendered.
    if (o.stats)
      std::printf("{\"scene\": %s, \"width\": %d, \"height\": %d, \"threads\": %d, \"frames\": [",
                  nlohmann::json(o.scene).dump().c_str(), w, h, ctx.threads());
    for (int f = o.first_frame; f <= o.last_frame; ++f) {
      const gpu::Stats before = ctx.stats();
      std::vector<scene::PassStats> passes;
      const auto t0 = std::chrono::steady_clock::now();
      s.Render(ctx, o.stats ? &passes : nullptr);
      ctx.finish();
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      const std::string path = o.frames ? frame_path(o.output, f) : o.output;
      gpu::write_png(path, color);
      if (o.stats) {
        nlohmann::ordered_json frame = {{"frame", f}, {"file", path}, {"ms", ms}};
        frame.update(counters_json(ctx.stats() - before));
        nlohmann::ordered_json& list = frame["passes"] = nlohmann::ordered_json::array();
        for (const scene::PassStats& p : passes) {
          nlohmann::ordered_json pass = {{"pass", p.name}, {"ms", p.ms}};
          pass.update(counters_json(p.counters));
          list.push_back(std::move(pass));
        }
        std::printf("%s\n  %s", f == o.first_frame ? "" : ",", frame.dump().c_str());
      } else if (!o.frames) {
        std::printf("rendered %s (%d triangles, %dx%d) to %s in %.1f ms\n", o.scene.c_str(), s.triangles(), w,
                    h, path.c_str(), ms);
      }
      if (o.frames && total > 1) progress(f - o.first_frame + 1, total);
      s.Animate(dt);
    }
    if (o.stats)
      std::printf("\n]}\n");
    else if (o.frames)
      std::printf("rendered frames %d..%d of %s (%dx%d) to %s\n", o.first_frame, o.last_frame,
                  o.scene.c_str(), w, h, frame_path(o.output, o.first_frame).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tessel render: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace tessel::apps
