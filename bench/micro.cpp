// Micro-benchmarks of the pipeline's stages (Google Benchmark). Speed is measured here, never
// in tests. Run: make bench (or build/bench/tessel_bench_micro --benchmark_filter=...).
//
// Stages that are plain functions (vertex fetch and shading, clipping, setup, texture
// sampling) are called directly on prepared inputs; the stages that only run inside a frame
// (binning, coverage, interpolation, fragment shading, depth test, blending) are measured
// through whole draws shaped so that the one stage dominates. Every benchmark reports items
// per second in its natural unit: vertices, triangles, pixels or samples.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "scene_phong.hpp"
#include "shaders.hpp"
#include "stages.hpp"

using namespace tessel::test;
using namespace tessel::gpu::detail;

namespace {

// --- shaders ----------------------------------------------------------------------------------

// Blinn-Phong lit per pixel in world space: the standard scenes' shader.
using PhongShader = tessel::scenes::ScenePhong<false, false>;

// Clip position straight through, a constant colour out: no shading work. (Varyings cannot
// be empty: one flat float, which the shader ignores.)
struct ConstShader {
  struct Uniforms {
    glm::vec4 color{0.2f, 0.4f, 0.6f, 0.5f};
  };
  template <class F>
  struct Varyings {
    F unused;
  };
  static constexpr uint64_t flat = 0b1;
  static constexpr uint32_t attributes = 0b1;
  template <class F>
  Vec4<F> vertex(const Uniforms&, const VertexIn<F>& in, Varyings<F>& out) const {
    out.unused = F(0.0f);
    return in.attr[0];
  }
  template <class F>
  void fragment(const Uniforms& u, const Varyings<F>&, Fragment<F>& f) const {
    f.color[0] = Vec4<F>(u.color);
  }
};

// K perspective-correct varyings (made from the colour and uv), summed into the colour: the
// cost per pixel is interpolation.
template <int K>
struct VaryingsShader {
  struct Uniforms {};
  template <class F>
  struct Varyings {
    F v[K];
  };
  static constexpr uint32_t attributes = 0b111;
  template <class F>
  Vec4<F> vertex(const Uniforms&, const VertexIn<F>& in, Varyings<F>& out) const {
    for (int k = 0; k < K; ++k)
      out.v[k] = in.attr[1].x * F(float(k + 1)) + in.attr[2].y * F(1.0f / float(k + 1));
    return in.attr[0];
  }
  template <class F>
  void fragment(const Uniforms&, const Varyings<F>& v, Fragment<F>& f) const {
    F s = v.v[0];
    for (int k = 1; k < K; ++k) s = s + v.v[k];
    f.color[0] = Vec4<F>(s * F(1.0f / K), F(0.5f), F(0.5f), F(1.0f));
  }
};

// --- inputs -----------------------------------------------------------------------------------

constexpr int W = 1024, H = 768;

std::vector<TestVertex> random_triangles(int n, float size, int w, int h, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<TestVertex> v;
  for (int i = 0; i < n; ++i) {
    const float cx = u(rng) * w, cy = u(rng) * h;
    for (int k = 0; k < 3; ++k) {
      TestVertex t{};
      // Counter-clockwise around the centre.
      const float a = 2.0943951f * k + u(rng) * 0.5f;
      clip_from_window(cx + size * std::cos(a), cy + size * std::sin(a), u(rng) * 2 - 1, 1.0f, w, h, t.pos);
      t.color[0] = u(rng);
      t.color[1] = u(rng);
      t.color[2] = u(rng);
      t.color[3] = 1.0f;
      v.push_back(t);
    }
  }
  return v;
}

// n quads covering the whole viewport (two triangles each), quad i at NDC depth z(i).
template <class Z>
std::vector<TestVertex> fullscreen_quads(int n, Z z) {
  std::vector<TestVertex> v;
  for (int i = 0; i < n; ++i) {
    const float zi = z(i);
    auto at = [&](float x, float y) {
      TestVertex t{};
      t.pos[0] = x;
      t.pos[1] = y;
      t.pos[2] = zi;
      t.pos[3] = 1.0f;
      t.color[0] = 0.5f * (x + 1.0f);
      t.color[1] = 0.5f * (y + 1.0f);
      t.color[2] = 0.5f;
      t.color[3] = 1.0f;
      t.uv[0] = 0.5f * (x + 1.0f);
      t.uv[1] = 0.5f * (y + 1.0f);
      return t;
    };
    for (const auto& p : {at(-1, -1), at(1, -1), at(1, 1), at(-1, -1), at(1, 1), at(-1, 1)}) v.push_back(p);
  }
  return v;
}

// A 256x256-vertex grid (a bumpy sheet) with position, normal and uv as F32, indexed as
// triangles; `ids` are its vertices in the order the pipeline's post-transform cache first
// meets them, which is what the geometry phase hands to shade_vertices.
struct GridMesh {
  static constexpr int N = 256;
  std::vector<float> vertices;  // 8 floats a vertex
  std::vector<uint32_t> indices, ids;
  Buffer vbo;
  VertexLayout layout;
  GridMesh() {
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i) {
        const float x = float(i) / (N - 1) * 2 - 1, y = float(j) / (N - 1) * 2 - 1;
        const float z = 0.1f * std::sin(6 * x) * std::cos(5 * y);
        const glm::vec3 n = glm::normalize(glm::vec3(-0.6f * std::cos(6 * x) * std::cos(5 * y),
                                                     0.5f * std::sin(6 * x) * std::sin(5 * y), 1.0f));
        vertices.insert(vertices.end(), {x, y, z, n.x, n.y, n.z, float(i) / (N - 1), float(j) / (N - 1)});
      }
    for (int j = 0; j + 1 < N; ++j)
      for (int i = 0; i + 1 < N; ++i) {
        const uint32_t a = uint32_t(j * N + i), b = a + 1, c = a + N + 1, d = a + N;
        indices.insert(indices.end(), {a, b, c, a, c, d});
      }
    std::vector<bool> seen(size_t(N) * N);
    for (uint32_t id : indices)
      if (!seen[id]) {
        seen[id] = true;
        ids.push_back(id);
      }
    vbo.assign(vertices.data(), vertices.size() * sizeof(float));
    const uint32_t stride = 8 * sizeof(float);
    layout.attrib(0, vbo, 3, AttribType::F32, stride, 0);
    layout.attrib(1, vbo, 3, AttribType::F32, stride, 3 * sizeof(float));
    layout.attrib(2, vbo, 2, AttribType::F32, stride, 6 * sizeof(float));
  }
};

// A DrawRecord with the viewport, render area and guard band of a W x H target, as
// Context::submit derives them for the default state (see tests/gpu/test_clip.cpp).
template <class S>
DrawRecord record_for(const S& shader = S{}, const typename S::Uniforms& u = {}) {
  DrawRecord d;
  d.program = std::make_unique<Program<S>>(shader, u);
  d.vp_scale[0] = W * 0.5f;
  d.vp_scale[1] = H * 0.5f;
  d.vp_scale[2] = 0.5f;
  d.vp_offset[0] = W * 0.5f;
  d.vp_offset[1] = H * 0.5f;
  d.vp_offset[2] = 0.5f;
  d.area_x0 = d.area_y0 = 0;
  d.area_x1 = W;
  d.area_y1 = H;
  d.guard_x = (kGuardBand - d.vp_offset[0]) / d.vp_scale[0];
  d.guard_y = (kGuardBand - d.vp_offset[1]) / d.vp_scale[1];
  d.depth_min = 0.0f;
  d.depth_max = 1.0f;
  d.depth_resolution = 1.0f / 16777216.0f;
  return d;
}

// A W x H RGBA8 + depth24-stencil8 target and a context drawing into it.
struct Scene {
  Target target{W, H};
  Context ctx;
  explicit Scene(int threads) : ctx(threads) { ctx.bind_framebuffer(&target.fb); }
};

// --- geometry stages (direct calls) -----------------------------------------------------------

// Vertex fetch alone: eight vertices at a time from three interleaved F32 attributes.
void BM_VertexFetch(benchmark::State& state) {
  const GridMesh m;
  const int n = int(m.ids.size());
  VertexIn<Float8> in;
  for (auto _ : state) {
    for (int i = 0; i < n; i += kLanes) {
      fetch_attributes8(m.layout, m.ids.data() + i, std::min(kLanes, n - i), 0, in);
      benchmark::DoNotOptimize(in);
    }
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
  state.SetBytesProcessed(int64_t(state.iterations()) * n * 8 * int64_t(sizeof(float)));
}
BENCHMARK(BM_VertexFetch);

// Vertex shading: fetch + the Phong vertex shader (mat4 transform, 6 varyings) + the
// scatter of the lanes into clip positions and varyings, as the geometry phase calls it.
void BM_VertexShading(benchmark::State& state) {
  const GridMesh m;
  PhongShader::Uniforms u;
  u.viewproj = glm::mat4(1.0f);
  DrawRecord d = record_for<PhongShader>({}, u);
  d.layout = m.layout;
  const int n = int(m.ids.size());
  const int K = d.program->varyings;
  std::vector<glm::vec4> pos(static_cast<size_t>(n));
  std::vector<float> vars(size_t(n) * size_t(K));
  for (auto _ : state) {
    d.program->shade_vertices(d, m.ids.data(), n, 0, pos.data(), vars.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
  state.SetBytesProcessed(int64_t(state.iterations()) * n * 8 * int64_t(sizeof(float)));
  state.counters["varyings"] = K;
}
BENCHMARK(BM_VertexShading);

// Clip codes and window positions, as the geometry phase computes them (finish_vertices,
// eight vertices at a time): each clip-space position against the near, far, w > 0 and
// guard-band planes (about a tenth are outside near or far), then divided, mapped to the
// viewport and snapped.
void BM_ClipCodes(benchmark::State& state) {
  const DrawRecord d = record_for<ConstShader>();
  const ClipPlanes planes = make_clip_planes(d);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), uw(0.5f, 2.0f);
  const int n = 65536;
  std::vector<float> soa(size_t(n) * 4);  // blocks of 8 x, 8 y, 8 z, 8 w
  for (int i = 0; i < n; ++i) {
    const float w = uw(rng);
    float* b = &soa[size_t(i / 8) * 32 + size_t(i % 8)];
    b[0] = 1.5f * u(rng) * w;
    b[8] = 1.5f * u(rng) * w;
    b[16] = 1.1f * u(rng) * w;
    b[24] = w;
  }
  std::vector<unsigned> codes(static_cast<size_t>(n));
  std::vector<WinVert> win(static_cast<size_t>(n));
  const float vars[1] = {0.0f};
  for (auto _ : state) {
    finish_vertices(d, planes, soa.data(), vars, 0, size_t(n), codes.data(), win.data());
    benchmark::DoNotOptimize(codes.data());
    benchmark::DoNotOptimize(win.data());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
}
BENCHMARK(BM_ClipCodes);

// Polygon clipping: triangles with 8 varyings crossing the near plane (half with one vertex
// behind it, giving quads; half with two, giving triangles).
void BM_ClipPolygon(benchmark::State& state) {
  const DrawRecord d = record_for<ConstShader>();
  const ClipPlanes planes = make_clip_planes(d);
  constexpr int K = 8;
  const int n = 4096;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), uw(0.5f, 2.0f);
  std::vector<ClipVert> tris(size_t(n) * 3);
  std::vector<unsigned> masks(static_cast<size_t>(n));
  for (int t = 0; t < n; ++t) {
    unsigned mask = 0;
    for (int k = 0; k < 3; ++k) {
      ClipVert& v = tris[size_t(t) * 3 + size_t(k)];
      const float w = uw(rng);
      const bool behind = k == 0 || (t % 2 == 1 && k == 1);
      v.pos = {u(rng) * w, u(rng) * w, behind ? -1.5f * w - 0.5f * w * std::fabs(u(rng)) : 0.9f * u(rng) * w,
               w};
      for (int i = 0; i < K; ++i) v.var[i] = u(rng);
      mask |= clip_code(planes, v.pos);
    }
    masks[size_t(t)] = mask;
  }
  // With only the near plane in the mask, clip_polygon reads `a` and writes `b`, so the
  // inputs can be used in place.
  for (unsigned m : masks)
    if (__builtin_popcount(m) != 1) {
      state.SkipWithError("a triangle is outside more than the near plane");
      return;
    }
  ClipVert b[24];
  int64_t out_verts = 0;
  for (auto _ : state) {
    for (int t = 0; t < n; ++t) {
      ClipVert* out;
      out_verts += clip_polygon(planes, masks[size_t(t)], &tris[size_t(t) * 3], 3, b, K, &out);
      benchmark::DoNotOptimize(out);
    }
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
  state.counters["out_verts_per_tri"] =
      double(out_verts) / double(std::max<int64_t>(1, int64_t(state.iterations()) * n));
}
BENCHMARK(BM_ClipPolygon);

// Triangle setup: snapped edges, fill rule, bbox and the planes of depth, 1/w and 11
// varyings, for ~10 px triangles of which half are clockwise and culled (CullMode::Back).
void BM_TriangleSetup(benchmark::State& state) {
  DrawRecord d = record_for<PhongShader>();
  d.state.cull = CullMode::Back;
  const int K = d.program->varyings;
  const int n = 16384;
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> vars(size_t(n) * 3 * size_t(K));
  for (float& v : vars) v = u(rng);
  std::vector<WinVert> verts(size_t(n) * 3);
  for (int t = 0; t < n; ++t) {
    const float cx = u(rng) * W, cy = u(rng) * H, size = 10.0f;
    for (int k = 0; k < 3; ++k) {
      const float a = 2.0943951f * float(t % 2 ? 3 - k : k) + u(rng) * 0.5f;  // odd: clockwise
      WinVert& v = verts[size_t(t) * 3 + size_t(k)];
      v.x = cx + size * std::cos(a);
      v.y = cy + size * std::sin(a);
      v.z = u(rng);
      v.oow = 1.0f / (1.0f + u(rng));
      v.var = &vars[(size_t(t) * 3 + size_t(k)) * size_t(K)];
      snap_vertex(v);
    }
  }
  Arena arena;
  Counters c;
  int64_t kept = 0;
  for (auto _ : state) {
    arena.reset();
    for (int t = 0; t < n; ++t) {
      const WinVert* v = &verts[size_t(t) * 3];
      Prim* p = setup_triangle(d, v[0], v[1], v[2], v[2].var, uint32_t(t), Facing::FromArea, false, arena, c,
                               nullptr);
      kept += p != nullptr;
      benchmark::DoNotOptimize(p);
    }
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
  state.counters["kept"] = double(kept) / double(std::max<int64_t>(1, int64_t(state.iterations()) * n));
}
BENCHMARK(BM_TriangleSetup);

// --- raster stages (whole draws) --------------------------------------------------------------

// Runs clear + `draw()` + finish per iteration; reports `pixels` per iteration as items (and
// 4 bytes of colour each), or the fragments shaded when pixels is 0. The clear is part of
// every frame (as in BM_Triangles); BM_Clear shows its cost.
template <class Draw>
void run_frames(benchmark::State& state, Scene& s, int64_t pixels, Draw draw) {
  s.ctx.reset_stats();
  for (auto _ : state) {
    s.ctx.clear({.color = {0, 0, 0, 1}});
    draw();
    s.ctx.finish();
  }
  const int64_t it = int64_t(state.iterations());
  const Stats& st = s.ctx.stats();
  const int64_t items = pixels ? pixels * it : int64_t(st.fragments_shaded);
  state.SetItemsProcessed(items);
  state.SetBytesProcessed(items * 4);
  if (pixels) {  // the fractions of the pixels that were shaded and written
    state.counters["shaded"] = double(st.fragments_shaded) / double(std::max<int64_t>(1, items));
    state.counters["written"] = double(st.fragments_written) / double(std::max<int64_t>(1, items));
  }
}

// Binning (and the rest of the geometry phase): 64K triangles of ~2 px, constant colour, no
// depth test, at 1 and 2 threads. Items are triangles.
void BM_Binning(benchmark::State& state) {
  const int threads = int(state.range(0)), n = 65536;
  Scene s(threads);
  const Mesh m(random_triangles(n, 2.0f, W, H, 1));
  s.ctx.reset_stats();
  for (auto _ : state) {
    s.ctx.clear({.color = {0, 0, 0, 1}});
    s.ctx.draw(ConstShader{}, {}, m.layout, RenderState{}, {.count = m.count});
    s.ctx.finish();
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
  state.counters["threads"] = threads;
  state.counters["px_per_tri"] =
      double(s.ctx.stats().fragments_shaded) / double(std::max<int64_t>(1, int64_t(state.iterations()) * n));
}
BENCHMARK(BM_Binning)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// Coverage: 64 large triangles (~400 px from centre to vertex), constant colour, no depth
// test: block classification, coverage masks and colour writes. Items are pixels covered.
void BM_Coverage(benchmark::State& state) {
  const int threads = int(state.range(0));
  Scene s(threads);
  const Mesh m(random_triangles(64, 400.0f, W, H, 2));
  run_frames(state, s, 0,
             [&] { s.ctx.draw(ConstShader{}, {}, m.layout, RenderState{}, {.count = m.count}); });
  state.counters["threads"] = threads;
}
BENCHMARK(BM_Coverage)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// Interpolation: 4 full-screen quads with K varyings summed in the shader (compare K = 4
// with K = 16 for the cost of a varying). Items are pixels.
template <int K>
void BM_Interpolation(benchmark::State& state) {
  constexpr int quads = 4;
  Scene s(1);
  const Mesh m(fullscreen_quads(quads, [](int) { return 0.0f; }));
  run_frames(state, s, int64_t(quads) * W * H,
             [&] { s.ctx.draw(VaryingsShader<K>{}, {}, m.layout, RenderState{}, {.count = m.count}); });
  state.counters["varyings"] = K;
}
BENCHMARK_TEMPLATE(BM_Interpolation, 4)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_Interpolation, 16)->Unit(benchmark::kMillisecond)->UseRealTime();

// Fragment shading: 4 full-screen quads with the Blinn-Phong fragment shader (per-pixel
// normalize x4, pow). Items are pixels.
void BM_Shading(benchmark::State& state) {
  constexpr int quads = 4;
  Scene s(1);
  // The quads in clip space with an identity view-projection; normals vary across them.
  std::vector<float> v;
  for (int q = 0; q < quads; ++q)
    for (const auto& [x, y] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}})
      v.insert(v.end(), {float(x), float(y), 0.0f, 0.3f * float(x), 0.3f * float(y), 1.0f, 0.5f * (x + 1.0f),
                         0.5f * (y + 1.0f)});
  const Buffer vbo(v);
  VertexLayout layout;
  layout.attrib(0, vbo, 3, AttribType::F32, 8 * sizeof(float), 0);
  layout.attrib(1, vbo, 3, AttribType::F32, 8 * sizeof(float), 3 * sizeof(float));
  layout.attrib(2, vbo, 2, AttribType::F32, 8 * sizeof(float), 6 * sizeof(float));
  run_frames(state, s, int64_t(quads) * W * H, [&] {
    s.ctx.draw(PhongShader{}, {}, layout, RenderState{}, {.count = uint32_t(v.size() / 8)});
  });
}
BENCHMARK(BM_Shading)->Unit(benchmark::kMillisecond)->UseRealTime();

// Depth test: 8 full-screen quads with depth test and write on. Arg 0: front to back, so
// every quad after the first fails the early test (test cost, no shading); arg 1: back to
// front, so every fragment passes and writes. Items are pixels tested.
void BM_DepthTest(benchmark::State& state) {
  constexpr int quads = 8;
  const bool back_to_front = state.range(0) != 0;
  Scene s(1);
  const Mesh m(
      fullscreen_quads(quads, [&](int i) { return back_to_front ? 0.8f - 0.2f * i : -0.8f + 0.2f * i; }));
  RenderState st;
  st.depth_test = true;
  run_frames(state, s, int64_t(quads) * W * H,
             [&] { s.ctx.draw(ConstShader{}, {}, m.layout, st, {.count = m.count}); });
  state.SetLabel(back_to_front ? "back-to-front (all pass)" : "front-to-back (7/8 fail)");
}
BENCHMARK(BM_DepthTest)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// Blending: 4 full-screen quads of a constant colour with alpha 0.5, blended with
// SrcAlpha / OneMinusSrcAlpha (read, blend, write per pixel). Items are pixels.
void BM_Blending(benchmark::State& state) {
  constexpr int quads = 4;
  Scene s(1);
  const Mesh m(fullscreen_quads(quads, [](int) { return 0.0f; }));
  RenderState st;
  st.blend[0] = {.enabled = true,
                 .src_rgb = BlendFactor::SrcAlpha,
                 .dst_rgb = BlendFactor::OneMinusSrcAlpha,
                 .src_alpha = BlendFactor::SrcAlpha,
                 .dst_alpha = BlendFactor::OneMinusSrcAlpha};
  run_frames(state, s, int64_t(quads) * W * H,
             [&] { s.ctx.draw(ConstShader{}, {}, m.layout, st, {.count = m.count}); });
}
BENCHMARK(BM_Blending)->Unit(benchmark::kMillisecond)->UseRealTime();

// --- texture sampling (direct calls) ----------------------------------------------------------

// texture() over a 512x512-pixel screen region in 4x2 groups, on a 1024x1024 RGBA8 texture
// with its mip chain. Arg: 0 nearest (1 texel/pixel), 1 bilinear (1 texel/pixel), 2 trilinear
// (1.5 texels/pixel, LOD ~0.58, two levels blended). Items are samples.
template <class F>
void BM_TextureSampling(benchmark::State& state) {
  constexpr int N = lane_width<F>;
  static const Texture2D* tex = [] {
    auto* t = new Texture2D(Format::RGBA8, 1024, 1024, 0);
    std::vector<uint8_t> px(size_t(1024) * 1024 * 4);
    std::mt19937 rng(3);
    for (auto& p : px) p = uint8_t(rng());
    t->upload_rgba8(0, px.data(), px.size());
    t->generate_mipmaps();
    return t;
  }();
  const int mode = int(state.range(0));
  Sampler2D s;
  s.texture = tex;
  const Filter min_f[3] = {Filter::Nearest, Filter::Linear, Filter::LinearMipmapLinear};
  const Filter mag_f[3] = {Filter::Nearest, Filter::Linear, Filter::Linear};
  s.state.min_filter = min_f[mode];
  s.state.mag_filter = mag_f[mode];
  const float scale = (mode == 2 ? 1.5f : 1.0f) / 1024.0f;  // uv per pixel
  F dx, dy;  // pixel centres of the lanes in a group (two 4x2 groups side by side for 16)
  for (int l = 0; l < N; ++l) {
    dx[l] = (float(kLaneDx[l % 8] + 4 * (l / 8)) + 0.5f) * scale;
    dy[l] = (float(kLaneDy[l % 8]) + 0.5f) * scale;
  }
  constexpr int R = 512;
  Vec4<F> sum(F(0.0f));
  for (auto _ : state) {
    for (int gy = 0; gy < R; gy += 2)
      for (int gx = 0; gx < R; gx += N / 2) {
        const Vec2<F> uv(F(float(gx) * scale + 0.1f) + dx, F(float(gy) * scale + 0.1f) + dy);
        sum = sum + texture(s, uv);
      }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * R * R);
  const char* names[3] = {"nearest", "bilinear", "trilinear"};
  state.SetLabel(names[mode]);
}
BENCHMARK_TEMPLATE(BM_TextureSampling, Float8)->DenseRange(0, 2);
BENCHMARK_TEMPLATE(BM_TextureSampling, Float16)->DenseRange(0, 2);

// --- whole draws ------------------------------------------------------------------------------

// Triangles of a given size (pixels from centre to vertex), Gouraud-shaded, depth-tested.
void BM_Triangles(benchmark::State& state) {
  const int n = int(state.range(0));
  const float size = float(state.range(1));
  const int threads = int(state.range(2));
  Scene s(threads);
  Mesh m(random_triangles(n, size, W, H, 1));
  RenderState st;
  st.depth_test = true;
  for (auto _ : state) {
    s.ctx.clear({.color = {0, 0, 0, 1}});
    s.ctx.draw(ColorShader{}, {}, m.layout, st, {.count = m.count});
    s.ctx.finish();
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
  state.counters["threads"] = threads;
}
BENCHMARK(BM_Triangles)
    ->Args({128, 600, 1})
    ->Args({128, 600, 2})  // large triangles: fill rate
    ->Args({8192, 8, 1})
    ->Args({8192, 8, 2})  // ~100 px triangles
    ->Args({262144, 1, 1})
    ->Args({262144, 1, 2})  // tiny triangles: geometry rate
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Full-screen clears only.
void BM_Clear(benchmark::State& state) {
  Target t(1920, 1080);
  Context ctx(int(state.range(0)));
  ctx.bind_framebuffer(&t.fb);
  for (auto _ : state) {
    ctx.clear({.color = {0.1f, 0.2f, 0.3f, 1.0f}});
    ctx.finish();
  }
}
BENCHMARK(BM_Clear)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
