#include "bench.hpp"

#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "fixed_gl.hpp"
#include "scene_phong.hpp"
#include "scenes.hpp"
#include "tessel/gl/offscreen.hpp"
#include "tessel/glsl/program.hpp"
#include "tessel/gpu/context.hpp"
#include "tessel/gpu/image.hpp"

namespace tessel::apps {
using namespace tessel::gpu;
using scenes::ScenePhong;

namespace {

struct Run {
  std::string renderer;  // "tessel" or "llvmpipe"
  std::string scene;
  int width = 0, height = 0, threads = 0;
  std::vector<double> ms;
  double ms_median = 0;
  double peak_rss_mb = 0;
  uint64_t triangles = 0, fragments = 0;
  std::string image;
  std::vector<uint8_t> rgba;   // bottom-up
  double compile_ms = -1;      // GLSL: source to linked program (compile, link, JIT)
  double first_frame_ms = -1;  // GLSL: source to the first frame finished
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Peak resident memory of this process since the last reset_peak_rss(), from /proc.
double peak_rss_mb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::strtod(line.c_str() + 6, nullptr) / 1024.0;
  return 0;
}
void reset_peak_rss() {
  // The heap an earlier run freed goes back to the system first: it is not this run's memory
  // (after spheres-1m, glibc kept about 16 MB that fill's figure then counted).
  malloc_trim(0);
  std::ofstream out("/proc/self/clear_refs");
  out << "5";  // Linux >= 4.0: resets VmHWM to the current RSS
}

// A run of scene s, its identity filled in.
Run start_run(const char* renderer, const scenes::Scene& s, int threads) {
  Run r;
  r.renderer = renderer;
  r.scene = s.name;
  r.width = s.width;
  r.height = s.height;
  r.threads = threads;
  r.triangles = s.triangles();
  return r;
}

// The fixed-function scene on Tessel: the same OpenGL 1.x calls as the peer's
// (bench/scenes/fixed_gl.hpp), through Tessel's GL layer.
Run run_tessel_fixed(const scenes::Scene& s, int threads, int frames, int warmup) {
  reset_peak_rss();
  Run r = start_run("tessel", s, threads);
  tessel::gl::Offscreen gl(s.width, s.height, threads, true, false);
  gl.make_current();
  scenes::fixed_setup(s);
  auto one = [&] {
    scenes::fixed_frame(s);
    glFinish();
  };
  for (int i = 0; i < warmup; ++i) one();
  gl.reset_stats();
  for (int i = 0; i < frames; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    one();
    r.ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  r.ms_median = median(r.ms);
  r.fragments = gl.fragments_shaded() / uint64_t(std::max(1, frames));
  r.rgba = gl.read_rgba8();
  r.peak_rss_mb = peak_rss_mb();
  return r;
}

// What both ways of drawing a scene on Tessel share: the target, the mesh and per-instance
// buffers with their layout (attributes 0-2, and 3-4 per instance when instanced), the
// mipmapped texture of the textured scene, and the pipeline state.
struct SceneTargets {
  Texture2D color, depth;
  Framebuffer fb;
  Context ctx;
  Buffer vbo, ibo, instances;
  VertexLayout layout;
  std::unique_ptr<Texture2D> tex;
  RenderState state;
  bool instanced;

  static std::vector<float> per_instance(const scenes::Scene& s) {
    std::vector<float> v;
    for (const scenes::Draw& d : s.draws)
      v.insert(v.end(), {d.offset.x, d.offset.y, d.offset.z, d.albedo.x, d.albedo.y, d.albedo.z});
    return v;
  }
  SceneTargets(const scenes::Scene& s, int threads, bool want_instanced)
      : color(Format::RGBA8, s.width, s.height),
        depth(Format::Depth24Stencil8, s.width, s.height),
        fb(&color, &depth),
        ctx(threads),
        vbo(s.mesh.vertices),
        ibo(s.mesh.indices),
        instances(per_instance(s)),
        instanced(want_instanced && s.instanceable) {
    ctx.bind_framebuffer(&fb);
    const uint32_t stride = scenes::Mesh::kStride * sizeof(float);
    layout.attrib(0, vbo, 3, AttribType::F32, stride, 0);
    layout.attrib(1, vbo, 3, AttribType::F32, stride, 3 * sizeof(float));
    layout.attrib(2, vbo, 2, AttribType::F32, stride, 6 * sizeof(float));
    if (instanced) {
      layout.attrib(3, instances, 3, AttribType::F32, 6 * sizeof(float), 0, false, 1);
      layout.attrib(4, instances, 3, AttribType::F32, 6 * sizeof(float), 3 * sizeof(float), false, 1);
    }
    if (s.textured) {
      tex = std::make_unique<Texture2D>(Format::RGBA8, scenes::kTextureSize, scenes::kTextureSize, 0);
      const auto px = scenes::texture_rgba8();
      tex->upload_rgba8(0, px.data(), px.size());
      tex->generate_mipmaps();
    }
    state.depth_test = true;
    state.cull = CullMode::Back;
  }
};

// One scene on Tessel with the peer's own GLSL (scenes::scene_*_glsl) through tessel::glsl:
// the same program text, uniforms and draws as llvmpipe gets.
Run run_tessel_glsl(const scenes::Scene& s, int threads, int frames, int warmup, bool instanced) {
  reset_peak_rss();
  Run r = start_run("tessel", s, threads);
  using Clock = std::chrono::steady_clock;
  // Source to first frame is measured cold in this process: the program is not taken from
  // an earlier run's link (the disk cache, when it holds the code, still counts).
  glsl::clear_program_cache();
  const auto t0 = Clock::now();
  instanced = instanced && s.instanceable;
  const bool textured = s.textured;
  auto vs = glsl::Shader::compile(glsl::Stage::Vertex, scenes::scene_vertex_glsl(textured, instanced));
  auto fs = glsl::Shader::compile(glsl::Stage::Fragment, scenes::scene_fragment_glsl(textured, instanced));
  if (!vs->ok() || !fs->ok())
    throw std::runtime_error("GLSL compile failed: " + vs->info_log() + fs->info_log());
  auto prog = glsl::Program::link(*vs, *fs);
  if (!prog->ok()) throw std::runtime_error("GLSL link failed: " + prog->info_log());
  r.compile_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();

  SceneTargets g(s, threads, instanced);
  Context& ctx = g.ctx;
  glsl::TextureBinding unit;
  unit.texture_2d = g.tex.get();
  unit.sampler.min_filter = Filter::LinearMipmapLinear;
  unit.sampler.mag_filter = Filter::Linear;
  const glm::mat4 viewproj = s.projection * s.view;
  prog->set_uniform(prog->uniform_location("u_viewproj"), &viewproj[0][0], 16);
  prog->set_uniform(prog->uniform_location("u_light"), &s.light.x, 3);
  prog->set_uniform(prog->uniform_location("u_eye"), &s.eye.x, 3);
  const int32_t zero = 0;
  prog->set_uniform(prog->uniform_location("u_tex"), &zero, 1);
  const int loc_offset = prog->uniform_location("u_offset"), loc_albedo = prog->uniform_location("u_albedo");
  const std::span<const glsl::TextureBinding> units(&unit, 1);
  auto one = [&] {
    ctx.clear({.color = {0, 0, 0, 1}, .depth = 1.0f});
    if (instanced) {
      const scenes::Draw& d = s.draws.front();
      prog->draw(ctx, g.layout, g.state,
                 {.topology = Topology::Triangles,
                  .first = d.first_index,
                  .count = d.index_count,
                  .index_buffer = &g.ibo,
                  .instance_count = uint32_t(s.draws.size())},
                 units);
    } else {
      for (const scenes::Draw& d : s.draws) {
        prog->set_uniform(loc_offset, &d.offset.x, 3);
        prog->set_uniform(loc_albedo, &d.albedo.x, 3);
        prog->draw(ctx, g.layout, g.state,
                   {.topology = Topology::Triangles,
                    .first = d.first_index,
                    .count = d.index_count,
                    .index_buffer = &g.ibo},
                   units);
      }
    }
    ctx.finish();
  };
  // The first frame starts at once, on the interpreter if the native code is not there yet
  // (glsl::NativeCode::Background); the timed frames run native code.
  one();
  r.first_frame_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  prog->wait_native();
  for (int i = 1; i < warmup; ++i) one();
  ctx.reset_stats();
  for (int i = 0; i < frames; ++i) {
    const auto f0 = Clock::now();
    one();
    r.ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - f0).count());
  }
  r.ms_median = median(r.ms);
  r.fragments = ctx.stats().fragments_shaded / uint64_t(std::max(1, frames));
  r.rgba = read_rgba8(g.color);
  r.peak_rss_mb = peak_rss_mb();
  return r;
}

// One scene on Tessel: `warmup` frames, then `frames` timed frames of clear + draws + finish.
Run run_tessel(const scenes::Scene& s, int threads, int frames, int warmup, bool instanced,
               bool glsl_shaders) {
  if (s.fixed_function) return run_tessel_fixed(s, threads, frames, warmup);
  if (glsl_shaders) return run_tessel_glsl(s, threads, frames, warmup, instanced);
  reset_peak_rss();
  Run r = start_run("tessel", s, threads);
  SceneTargets g(s, threads, instanced);
  Context& ctx = g.ctx;
  instanced = g.instanced;
  const VertexLayout& layout = g.layout;
  const RenderState& state = g.state;
  const Buffer& ibo = g.ibo;
  const std::unique_ptr<Texture2D>& tex = g.tex;

  auto frame = [&]<bool T, bool I>() {
    ctx.clear({.color = {0, 0, 0, 1}, .depth = 1.0f});
    typename ScenePhong<T, I>::Uniforms u{};
    u.viewproj = s.projection * s.view;
    u.eye = s.eye;
    u.light = s.light;
    u.tex.texture = tex.get();
    u.tex.state.min_filter = Filter::LinearMipmapLinear;
    u.tex.state.mag_filter = Filter::Linear;
    if constexpr (I) {
      const scenes::Draw& d = s.draws.front();
      ctx.draw(ScenePhong<T, I>{}, u, layout, state,
               {.topology = Topology::Triangles,
                .first = d.first_index,
                .count = d.index_count,
                .index_buffer = &ibo,
                .instance_count = uint32_t(s.draws.size())});
    } else {
      for (const scenes::Draw& d : s.draws) {
        u.offset = d.offset;
        u.albedo = d.albedo;
        ctx.draw(ScenePhong<T, I>{}, u, layout, state,
                 {.topology = Topology::Triangles,
                  .first = d.first_index,
                  .count = d.index_count,
                  .index_buffer = &ibo});
      }
    }
    ctx.finish();
  };
  auto one = [&] {
    if (s.textured)
      frame.template operator()<true, false>();
    else if (instanced)
      frame.template operator()<false, true>();
    else
      frame.template operator()<false, false>();
  };

  for (int i = 0; i < warmup; ++i) one();
  ctx.reset_stats();
  for (int i = 0; i < frames; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    one();
    r.ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  r.ms_median = median(r.ms);
  r.fragments = ctx.stats().fragments_shaded / uint64_t(std::max(1, frames));
  r.rgba = read_rgba8(g.color);
  r.peak_rss_mb = peak_rss_mb();
  return r;
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The value of "key" in a one-line JSON object (numbers and plain strings only).
std::string json_field(const std::string& json, const std::string& key) {
  const std::string k = "\"" + key + "\":";
  const auto at = json.find(k);
  if (at == std::string::npos) return {};
  size_t i = at + k.size();
  while (i < json.size() && json[i] == ' ') ++i;
  if (i < json.size() && json[i] == '"') {
    std::string v;
    for (++i; i < json.size() && json[i] != '"'; ++i) {
      if (json[i] == '\\' && i + 1 < json.size()) ++i;
      v += json[i];
    }
    return v;
  }
  const auto end = json.find_first_of(",}", i);
  return json.substr(i, end - i);
}

std::string find_peer(const BenchOptions& o) {
  namespace fs = std::filesystem;
  if (!o.peer_path.empty()) return o.peer_path;
  std::error_code ec;
  const fs::path self = fs::canonical("/proc/self/exe", ec);
  if (!ec) {
    for (const fs::path& p :
         {self.parent_path() / "tessel_peer", self.parent_path().parent_path() / "bench/peer/tessel_peer"})
      if (fs::exists(p, ec)) return p.string();
  }
  return "tessel_peer";  // from PATH
}

// The folder of Tessel's libEGL.so.1 and libOpenGL.so.0: --glvnd-path, else the build's.
std::string find_glvnd(const BenchOptions& o) {
  namespace fs = std::filesystem;
  if (!o.glvnd_path.empty()) return o.glvnd_path;
  std::error_code ec;
  const fs::path self = fs::canonical("/proc/self/exe", ec);
  if (!ec)
    for (const fs::path& p : {self.parent_path() / "glvnd", self.parent_path().parent_path() / "glvnd"})
      if (fs::exists(p / "libOpenGL.so.0", ec)) return p.string();
  throw std::runtime_error(
      "--api gl33: Tessel's libOpenGL.so.0 was not found (build the tessel_libegl target, "
      "or give --glvnd-path)");
}

// One scene through the peer program, in a child process (so its memory is its own): on
// llvmpipe, or with `ld_path` on the GL libraries found there (Tessel's).
Run run_peer(const std::string& peer, const scenes::Scene& s, int threads, int frames, int warmup,
             bool instanced, const std::string& image, const std::string& ld_path = "") {
  std::ostringstream cmd;
  if (!ld_path.empty()) cmd << "LD_LIBRARY_PATH=" << quote(ld_path) << " TESSEL_THREADS=" << threads << " ";
  cmd << quote(peer) << " --scene " << quote(s.name) << " --size " << s.width << "x" << s.height
      << " --threads " << threads << " --frames " << frames << " --warmup " << warmup
      << (instanced ? " --instanced" : "") << " --image " << quote(image) << " 2>&1";
  FILE* p = popen(cmd.str().c_str(), "r");
  if (!p) throw std::runtime_error("cannot start the peer " + peer);
  std::string out;
  char buf[4096];
  while (size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int status = pclose(p);
  const auto brace = out.rfind("{\"scene\"");
  if (status != 0 || brace == std::string::npos) {
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
    throw std::runtime_error(std::string(ld_path.empty() ? "the llvmpipe peer" : "the peer on Tessel's GL") +
                             " failed (" + peer + "): " + (out.empty() ? "no output" : out));
  }
  const std::string json = out.substr(brace);
  const std::string renderer = json_field(json, "renderer");
  if (!ld_path.empty() && renderer.find("Tessel") == std::string::npos)
    throw std::runtime_error("the peer did not run on Tessel's GL from " + ld_path +
                             " (renderer: " + renderer + ")");
  Run r = start_run(ld_path.empty() ? "llvmpipe" : "tessel-gl33", s, threads);
  r.ms_median = std::strtod(json_field(json, "ms_median").c_str(), nullptr);
  r.peak_rss_mb = std::strtod(json_field(json, "peak_rss_mb").c_str(), nullptr);
  r.image = image;
  const Image im = load_image(image);
  if (im.width != s.width || im.height != s.height)
    throw std::runtime_error("the peer image " + image + " has the wrong size");
  r.rgba = im.pixels;
  return r;
}

// Pixels where some channel differs by more than `tolerance`.
uint64_t count_differing(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b, int tolerance) {
  uint64_t n = 0;
  for (size_t i = 0; i + 3 < a.size() && i + 3 < b.size(); i += 4) {
    bool d = false;
    for (int c = 0; c < 4; ++c) d = d || std::abs(int(a[i + c]) - int(b[i + c])) > tolerance;
    n += d;
  }
  return n;
}

double mtris(const Run& r) { return r.ms_median > 0 ? double(r.triangles) / (r.ms_median * 1e3) : 0; }
double mpix(const Run& r, uint64_t fragments) {
  return r.ms_median > 0 ? double(fragments) / (r.ms_median * 1e3) : 0;
}

std::string cpu_flags() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, model, flags;
  while (std::getline(in, line)) {
    if (model.empty() && line.rfind("model name", 0) == 0) model = line.substr(line.find(':') + 2);
    if (flags.empty() && line.rfind("flags", 0) == 0) flags = line.substr(line.find(':') + 2);
  }
  std::string simd;
  std::istringstream fs(flags);
  for (std::string f; fs >> f;)
    if (f == "sse4_2" || f == "avx" || f == "avx2" || f == "fma" || f == "f16c" || f == "avx512f" ||
        f == "avx512bw" || f == "avx512vl")
      simd += (simd.empty() ? "" : " ") + f;
  return model + " [" + simd + "]";
}

}  // namespace

int run_bench(const BenchOptions& o) {
  namespace fs = std::filesystem;
  std::vector<std::string> names = o.scenes.empty() ? scenes::scene_names() : o.scenes;
  for (const auto& n : names)
    if (!scenes::is_scene(n)) (void)scenes::make_scene(n, 1, 1);  // throws with the list of names
  const auto sizes = o.sizes.empty() ? std::vector<std::pair<int, int>>{{1920, 1080}, {640, 480}} : o.sizes;
  const auto threads = o.threads.empty() ? std::vector<int>{1, 2} : o.threads;
  const bool several = sizes.size() * threads.size() > 1;

  if (!o.json.empty()) {
    const fs::path parent = fs::absolute(fs::path(o.json)).parent_path();
    if (!fs::is_directory(parent))
      throw std::runtime_error("--json " + o.json + ": folder " + parent.string() + " does not exist");
  }
  std::string image_dir = o.images, temp_dir;
  if (o.peer && image_dir.empty()) {
    char tmpl[] = "/tmp/tessel-bench-XXXXXX";
    if (!mkdtemp(tmpl)) throw std::runtime_error("cannot create a temporary folder for the peer images");
    temp_dir = image_dir = tmpl;
  }
  if (!image_dir.empty()) fs::create_directories(image_dir);
  const bool api_gl33 = o.api == "gl33";
  if (api_gl33 && !o.peer)
    return run_bench([&] {
      BenchOptions p = o;
      p.peer = true;
      return p;
    }());
  const std::string peer = o.peer ? find_peer(o) : "";
  const std::string glvnd = api_gl33 ? find_glvnd(o) : "";

  if (o.shaders != "cpp" && o.shaders != "glsl")
    throw std::runtime_error("--shaders must be cpp or glsl, not " + o.shaders);
  const bool glsl_shaders = o.shaders == "glsl";
  std::printf("CPU: %s\n", cpu_flags().c_str());
  if (api_gl33)
    std::printf("Tessel runs the peer program itself on its libEGL/libOpenGL (%s)\n", glvnd.c_str());
  else if (glsl_shaders)
    std::printf("Tessel runs the peer's GLSL (tessel::glsl); fixed-100k stays fixed function\n");
  std::printf("%d frames after %d warm-up frames; ms = median per frame\n\n", o.frames, o.warmup);
  if (o.peer)
    std::printf("%-13s %9s %3s | %9s %7s %8s %7s | %9s %7s | %6s %7s %9s\n", "scene", "size", "thr",
                "tessel ms", "Mtri/s", "Mpix/s", "MB", "llvmp ms", "MB", "speed", "diff>2", "diff %");
  else
    std::printf("%-13s %9s %3s | %9s %7s %8s %7s\n", "scene", "size", "thr", "ms", "Mtri/s", "Mpix/s", "MB");

  std::ostringstream json;
  json << "[\n";
  bool first_json = true;
  auto add_json = [&](const Run& r, uint64_t fragments, const std::string& extra) {
    json << (first_json ? "" : ",\n") << "  {\"renderer\": \"" << r.renderer << "\", \"scene\": \"" << r.scene
         << "\", \"width\": " << r.width << ", \"height\": " << r.height << ", \"threads\": " << r.threads
         << ", \"ms_median\": " << r.ms_median << ", \"mtris_s\": " << mtris(r)
         << ", \"mpix_s\": " << mpix(r, fragments) << ", \"peak_rss_mb\": " << r.peak_rss_mb
         << ", \"image\": \"" << r.image << "\"";
    if (r.compile_ms >= 0)
      json << ", \"glsl_compile_ms\": " << r.compile_ms << ", \"glsl_first_frame_ms\": " << r.first_frame_ms;
    json << extra << "}";
    first_json = false;
  };

  int failures = 0;
  for (const auto& name : names)
    for (const auto& [w, h] : sizes)
      for (int t : threads) {
        const scenes::Scene s = scenes::make_scene(name, w, h);
        std::string stem = name;
        if (several) stem += "_" + std::to_string(w) + "x" + std::to_string(h) + "_t" + std::to_string(t);
        Run mine;
        if (api_gl33) {
          try {
            mine = run_peer(peer, s, t, o.frames, o.warmup, o.instanced,
                            (fs::path(image_dir) / (stem + ".png")).string(), glvnd);
          } catch (const std::exception& e) {
            std::fprintf(stderr, "tessel bench: %s\n", e.what());
            ++failures;
            continue;
          }
        } else {
          mine = run_tessel(s, t, o.frames, o.warmup, o.instanced, glsl_shaders);
        }
        if (!image_dir.empty() && !api_gl33) {
          mine.image = (fs::path(image_dir) / (stem + ".png")).string();
          write_png(mine.image, w, h, 4, mine.rgba.data());
        }
        char size[32];
        std::snprintf(size, sizeof size, "%dx%d", w, h);
        std::printf("%-13s %9s %3d | %9.2f %7.3g %8.1f %7.1f", name.c_str(), size, t, mine.ms_median,
                    mtris(mine), mpix(mine, mine.fragments), mine.peak_rss_mb);
        if (mine.compile_ms >= 0)
          std::fprintf(
              stderr,
              "  (%s: GLSL compiled and linked in %.1f ms, first frame done %.1f ms after the source)\n",
              name.c_str(), mine.compile_ms, mine.first_frame_ms);
        if (!o.peer) {
          std::printf("\n");
          std::fflush(stdout);
          add_json(mine, mine.fragments, "");
          continue;
        }
        std::fflush(stdout);
        Run theirs;
        try {
          theirs = run_peer(peer, s, t, o.frames, o.warmup, o.instanced,
                            (fs::path(image_dir) / (stem + "_llvmpipe.png")).string());
        } catch (const std::exception& e) {
          std::printf("\n");
          std::fprintf(stderr, "tessel bench: %s\n", e.what());
          ++failures;
          add_json(mine, mine.fragments, "");
          continue;
        }
        const uint64_t diff = count_differing(mine.rgba, theirs.rgba, 2);
        const double pct = 100.0 * double(diff) / (double(w) * h);
        const double speed = mine.ms_median > 0 ? theirs.ms_median / mine.ms_median : 0;
        if (o.max_diff_percent >= 0 && pct > o.max_diff_percent) {
          std::fprintf(stderr,
                       "tessel bench: %s %dx%d: %.3f%% of the pixels differ from llvmpipe by more than 2/255 "
                       "(limit %.3f%%)\n",
                       name.c_str(), w, h, pct, o.max_diff_percent);
          ++failures;
        }
        std::printf(" | %9.2f %7.1f | %5.2fx %7llu %8.3f%%\n", theirs.ms_median, theirs.peak_rss_mb, speed,
                    (unsigned long long)diff, pct);
        std::fflush(stdout);
        std::ostringstream extra;
        extra << ", \"peer_ms_median\": " << theirs.ms_median << ", \"speedup\": " << speed
              << ", \"pixels_differing\": " << diff << ", \"percent_differing\": " << pct;
        add_json(mine, mine.fragments, extra.str());
        add_json(theirs, mine.fragments, "");
      }
  json << "\n]\n";

  if (!o.json.empty()) {
    const std::string tmp = o.json + ".tmp";
    {
      std::ofstream out(tmp);
      out << json.str();
      if (!out) throw std::runtime_error("cannot write " + o.json);
    }
    fs::rename(tmp, o.json);
  }
  if (!temp_dir.empty()) fs::remove_all(temp_dir);
  return failures ? 1 : 0;
}

}  // namespace tessel::apps
