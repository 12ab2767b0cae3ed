// The tessel command. `tessel render [SCENE]` renders a scene file (docs/scene-format.md), or
// the built-in demo scene, to PNG; `tessel bench` renders the standard benchmark scenes,
// optionally beside Mesa's llvmpipe.
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include "bench.hpp"
#include "demo.hpp"
#include "scene_render.hpp"
#include "tessel/gpu/format.hpp"

namespace {

bool parse_size(const std::string& s, int& w, int& h) {
  const auto x = s.find('x');
  if (x == std::string::npos) return false;
  try {
    size_t a = 0, b = 0;
    w = std::stoi(s.substr(0, x), &a);
    h = std::stoi(s.substr(x + 1), &b);
    return a == x && b == s.size() - x - 1;
  } catch (...) {
    return false;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Tessel: a real-time 3D rendering pipeline on the CPU"};
  app.require_subcommand(1);

  auto* render =
      app.add_subcommand("render", "Render a scene file (or, without one, the built-in demo scene) to PNG");
  std::string size = "1280x720", out = "out/demo.png", scene_path, shading, frames;
  int threads = 0;
  bool stats = false;
  render->add_option("scene", scene_path,
                     "Scene file (JSON, docs/scene-format.md); without it the built-in demo");
  render->add_option("--size", size, "Image size WxH (default: the scene's render.size; the demo: 1280x720)");
  render
      ->add_option("--threads", threads, "Worker threads (0 = one per hardware thread; default: the scene's)")
      ->check(CLI::Range(0, 64));
  render->add_option("-o,--output", out, "Output PNG file (with --frames: NAME_0001.png ...)")
      ->capture_default_str();
  render->add_option(
      "--shading", shading,
      "Draw every object with this shader: gouraud, phong, normalmap, npr, depth, normal, or a GLSL twin: "
      "glsl-gouraud, glsl-phong, glsl-normalmap, glsl-npr, glsl-depth, glsl-normal");
  render->add_option("--frames", frames,
                     "Render frames A..B of the animation (render.fps a second), numbered files");
  render->add_flag("--stats", stats,
                   "Print the pipeline's counters; with a scene file JSON per frame and per pass (shadow, "
                   "objects, planar_shadows, gbuffer, lighting) with ms");

  auto* bench = app.add_subcommand("bench", "Render the standard scenes and print the time per frame");
  tessel::apps::BenchOptions bo;
  std::vector<std::string> bench_sizes;
  bench->add_option("--scene", bo.scenes,
                    "Scene (repeatable): spheres-100k, spheres-1m, fill, textured; default all");
  bench->add_option("--size", bench_sizes, "Image size WxH (repeatable); default 1920x1080 and 640x480");
  bench->add_option("--threads", bo.threads, "Worker threads (repeatable); default 1 and 2")
      ->check(CLI::Range(1, 64));
  bench->add_option("--frames", bo.frames, "Timed frames per run (the median is reported)")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  bench->add_option("--warmup", bo.warmup, "Untimed frames before timing")
      ->check(CLI::Range(0, 10000))
      ->capture_default_str();
  bench->add_flag("--instanced", bo.instanced,
                  "Draw the sphere grids as one instanced draw instead of 100 draws");
  bench
      ->add_option("--shaders", bo.shaders,
                   "cpp: Tessel's C++ shader; glsl: the peer's GLSL, compiled by tessel::glsl")
      ->check(CLI::IsMember({"cpp", "glsl"}))
      ->capture_default_str();
  bench
      ->add_option("--api", bo.api,
                   "engine: Tessel's engine in this process; gl33: the peer program itself on Tessel's "
                   "libEGL/libOpenGL (same GL calls and GLSL as on llvmpipe; implies --peer)")
      ->check(CLI::IsMember({"engine", "gl33"}))
      ->capture_default_str();
  bench->add_option("--glvnd-path", bo.glvnd_path,
                    "With --api gl33: the folder of Tessel's libEGL.so.1 and libOpenGL.so.0 (default: the "
                    "build's glvnd folder)");
  bench->add_flag("--peer", bo.peer,
                  "Also run each scene on Mesa llvmpipe (tessel_peer), alternating, and compare");
  bench->add_option("--peer-path", bo.peer_path,
                    "The tessel_peer program (default: next to tessel, then PATH)");
  bench->add_option("--json", bo.json, "Write the results as a JSON array to this file");
  bench->add_option("--images", bo.images, "Write each run's image into this folder");
  bench->add_option(
      "--max-diff", bo.max_diff_percent,
      "With --peer: exit with an error when more than this percentage of pixels differ by > 2/255");

  CLI11_PARSE(app, argc, argv);

  if (bench->parsed()) {
    for (const auto& sz : bench_sizes) {
      int w = 0, h = 0;
      if (!parse_size(sz, w, h) || w < 1 || h < 1 || w > 16384 || h > 16384) {
        std::fprintf(stderr, "tessel bench: --size '%s': expected WxH with 1 <= W, H <= 16384\n", sz.c_str());
        return 2;
      }
      bo.sizes.emplace_back(w, h);
    }
    try {
      return tessel::apps::run_bench(bo);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tessel bench: %s\n", e.what());
      return 1;
    }
  }

  if (render->parsed() && !scene_path.empty()) {
    tessel::apps::SceneRenderOptions so;
    so.scene = scene_path;
    so.output = out;
    so.shading = shading;
    so.stats = stats;
    if (render->count("--threads")) so.threads = threads;
    if (render->count("--size") && (!parse_size(size, so.width, so.height) || so.width < 1 || so.height < 1 ||
                                    so.width > 16384 || so.height > 16384)) {
      std::fprintf(stderr, "tessel render: --size '%s': expected WxH with 1 <= W, H <= 16384\n",
                   size.c_str());
      return 2;
    }
    if (render->count("--frames")) {
      const auto dots = frames.find("..");
      try {
        size_t a = 0, b = 0;
        if (dots == std::string::npos) throw std::invalid_argument("no ..");
        so.first_frame = std::stoi(frames.substr(0, dots), &a);
        so.last_frame = std::stoi(frames.substr(dots + 2), &b);
        if (a != dots || b != frames.size() - dots - 2 || so.first_frame < 0 ||
            so.last_frame < so.first_frame || so.last_frame > 1000000)
          throw std::invalid_argument("range");
      } catch (const std::exception&) {
        std::fprintf(stderr, "tessel render: --frames '%s': expected A..B with 0 <= A <= B\n",
                     frames.c_str());
        return 2;
      }
      so.frames = true;
    }
    return tessel::apps::render_scene(so);
  }
  if (render->parsed() && (!shading.empty() || !frames.empty())) {
    std::fprintf(stderr, "tessel render: --shading and --frames need a scene file\n");
    return 2;
  }

  if (render->parsed()) {
    int w = 0, h = 0;
    if (!parse_size(size, w, h) || w < 1 || h < 1 || w > 16384 || h > 16384) {
      std::fprintf(stderr, "tessel render: --size '%s': expected WxH with 1 <= W, H <= 16384\n",
                   size.c_str());
      return 2;
    }
    try {
      const auto r = tessel::apps::render_demo(w, h, threads, out);
      std::printf("rendered the demo scene (%d triangles, %dx%d) to %s in %.1f ms\n", r.triangles, w, h,
                  out.c_str(), r.milliseconds);
      if (stats) {
        const auto& s = r.stats;
        std::printf("  vertices shaded     %llu\n", (unsigned long long)s.vertices_shaded);
        std::printf("  primitives in       %llu\n", (unsigned long long)s.primitives_in);
        std::printf("  clipped             %llu\n", (unsigned long long)s.primitives_clipped);
        std::printf("  culled              %llu\n", (unsigned long long)s.primitives_culled);
        std::printf("  triangles set up    %llu\n", (unsigned long long)s.triangles_setup);
        std::printf("  fragments shaded    %llu\n", (unsigned long long)s.fragments_shaded);
        std::printf("  fragments written   %llu\n", (unsigned long long)s.fragments_written);
        std::printf("  rejected by depth   %llu\n", (unsigned long long)s.fragments_rejected);
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tessel render: %s\n", e.what());
      return 1;
    }
  }
  return 0;
}
