// Micro-benchmarks of the pipeline's stages, through whole draws (Google Benchmark).
// Speed is measured here, never in tests. Run: make bench.
#include <benchmark/benchmark.h>

#include <random>

#include "shaders.hpp"

using namespace tessel::test;

namespace {

std::vector<TestVertex> random_triangles(int n, float size, int W, int H, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<TestVertex> v;
  for (int i = 0; i < n; ++i) {
    const float cx = u(rng) * W, cy = u(rng) * H;
    for (int k = 0; k < 3; ++k) {
      TestVertex t{};
      // Counter-clockwise around the centre.
      const float a = 2.0943951f * k + u(rng) * 0.5f;
      clip_from_window(cx + size * std::cos(a), cy + size * std::sin(a), u(rng) * 2 - 1, 1.0f, W, H, t.pos);
      t.color[0] = u(rng); t.color[1] = u(rng); t.color[2] = u(rng); t.color[3] = 1.0f;
      v.push_back(t);
    }
  }
  return v;
}

// Triangles of a given size (pixels from centre to vertex), Gouraud-shaded, depth-tested.
void BM_Triangles(benchmark::State& state) {
  const int W = 1024, H = 768;
  const int n = int(state.range(0));
  const float size = float(state.range(1));
  const int threads = int(state.range(2));
  Target t(W, H);
  Context ctx(threads);
  ctx.bind_framebuffer(&t.fb);
  Mesh m(random_triangles(n, size, W, H, 1));
  RenderState st;
  st.depth_test = true;
  for (auto _ : state) {
    ctx.clear({.color = {0, 0, 0, 1}});
    ctx.draw(ColorShader{}, {}, m.layout, st, {.count = m.count});
    ctx.finish();
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
  state.counters["threads"] = threads;
}
BENCHMARK(BM_Triangles)
    ->Args({128, 600, 1})->Args({128, 600, 2})      // large triangles: fill rate
    ->Args({8192, 8, 1})->Args({8192, 8, 2})        // ~100 px triangles
    ->Args({262144, 1, 1})->Args({262144, 1, 2})    // tiny triangles: geometry rate
    ->Unit(benchmark::kMillisecond)->UseRealTime();

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
