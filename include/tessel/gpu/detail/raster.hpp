// The per-shader half of the pipeline: vertex shading in batches of eight, and the raster
// loop (tile -> 8x8 block -> 4x2 group of two quads) that interpolates varyings and runs the
// fragment shader. Instantiated once per shader type, so the shader inlines into the loop.
#pragma once

#include <algorithm>
#include <array>
#include <cstring>

#include "tessel/gpu/detail/fast_ops.hpp"
#include "tessel/gpu/detail/pipeline.hpp"
#include "tessel/gpu/runtime_shader.hpp"

namespace tessel::gpu::detail {

template <class S>
class Program final : public ProgramBase {
 public:
  // The floating-point mode of the program's work: a run-time shader may ask for denormals
  // flushed (RuntimeShape::flush_denormals), set once per call here rather than per lane
  // group; C++ shaders run in the caller's mode.
  struct NoMode {};
  auto float_mode() const {
    if constexpr (shader_runtime<S>())
      return shader_.float_mode();
    else
      return NoMode{};
  }
  using Uniforms = typename S::Uniforms;
  template <class F>
  using Varyings = typename S::template Varyings<F>;

  Program(const S& s, const Uniforms& u) : shader_(s), uniforms_(u) {
    varyings = varying_count<S>();
    flat = shader_flat<S>();
    noperspective = shader_noperspective<S>();
    discards = shader_discards<S>();
    writes_depth = shader_writes_depth<S>();
    outputs = shader_outputs<S>();
  }

  void shade_vertices(const DrawRecord& d, const uint32_t* ids, int n, uint32_t instance, glm::vec4* pos,
                      float* vars, float* soa) const override {
    [[maybe_unused]] const auto mode = float_mode();
    constexpr int K = varying_count<S>();
    // One batch's results: m vertices from `base`.
    auto store = [&](int base, int m, const Vec4<Float8>& p, const Varyings<Float8>& out) {
      for (int l = 0; l < m; ++l) pos[base + l] = glm::vec4(p.x[l], p.y[l], p.z[l], p.w[l]);
      if (soa) {
        float* b = soa + size_t(base) * 4;
        p.x.store(b);
        p.y.store(b + 8);
        p.z.store(b + 16);
        p.w.store(b + 24);
      }
      if constexpr (K > 0) {
        Float8 lanes[K];
        std::memcpy(lanes, &out, sizeof lanes);
        for (int l = 0; l < m; ++l)
          for (int k = 0; k < K; ++k) vars[size_t(base + l) * K + k] = lanes[k][l];
      }
    };
    if constexpr (shader_runtime<S>()) {
      // A run-time program has sixteen lanes a call: two batches of eight go in each.
      VertexIn<Float8> in[2];  // the constant locations are written by the first batches only
      for (int base = 0; base < n; base += 2 * kLanes) {
        const int m0 = std::min(kLanes, n - base), m1 = std::clamp(n - base - kLanes, 0, kLanes);
        fetch_attributes8(d.layout, ids + base, m0, instance, in[0], base > 0);
        if (m1 > 0) fetch_attributes8(d.layout, ids + base + kLanes, m1, instance, in[1], base > 0);
        Varyings<Float8> out[2]{};
        Vec4<Float8> p[2];
        shader_.vertex_pair(uniforms_, in, m1 > 0, out, p);
        store(base, m0, p[0], out[0]);
        if (m1 > 0) store(base + kLanes, m1, p[1], out[1]);
      }
    } else {
      VertexIn<Float8> in;  // the constant locations are written by the first batch only
      for (int base = 0; base < n; base += kLanes) {
        const int m = std::min(kLanes, n - base);
        fetch_attributes8(d.layout, ids + base, m, instance, in, base > 0);
        Varyings<Float8> out{};
        store(base, m, shader_.vertex(uniforms_, in, out), out);
      }
    }
  }

  void shade_geometry(GeometryLanes& lanes) const override {
    if constexpr (shader_runtime<S>()) {
      [[maybe_unused]] const auto mode = float_mode();
      shader_.geometry(uniforms_, lanes);
    }
    (void)lanes;
  }

  void raster(const DrawRecord& d, const TargetView& t, const Prim* const* prims, int n, int x0, int y0,
              int x1, int y1, Counters& counters) const override {
    raster_loop<false>(d, t, prims, n, x0, y0, x1, y1, counters);
  }
  // Antialiased points and lines (their Prims carry coverage): a loop of their own, so that the
  // common one has no trace of them.
  void raster_smooth(const DrawRecord& d, const TargetView& t, const Prim* const* prims, int n, int x0,
                     int y0, int x1, int y1, Counters& counters) const override {
    raster_loop<true>(d, t, prims, n, x0, y0, x1, y1, counters);
  }

 private:
  // A run-time shader's two sets of lane rows on this thread (RuntimeBridge::fragment_lanes).
  // They are thread-local: looked up once a loop and passed down, since in a shared library
  // every look-up is a call (__tls_get_addr), which made 2% of a textured frame when made
  // per group. Null for a C++ shader.
  using LaneRows = std::array<FragmentLanes*, 2>;
  static LaneRows lane_rows() {
    if constexpr (shader_runtime<S>())
      return {&S::fragment_lanes(0), &S::fragment_lanes(1)};
    else
      return {nullptr, nullptr};
  }

  template <bool Smooth>
  void raster_loop(const DrawRecord& d, const TargetView& t, const Prim* const* prims, int n, int x0, int y0,
                   int x1, int y1, Counters& counters) const {
    [[maybe_unused]] const auto mode = float_mode();
    const LaneRows rows = lane_rows();
    // Fragment counts are kept in registers here and added to the worker's counters once.
    FragmentCounts c;
    // Covered 4x2 groups are shaded two at a time as sixteen lanes (two independent halves
    // keep both vector pipes busy through the shader's long dependency chains), each half
    // with its own triangle's planes; `pending` waits for a partner, from the same triangle
    // or a later one. The older group is the low half: depth and stencil are tested (and
    // written) for the low half before the high half, and colour is written in that order
    // too, so two groups on the same pixels still meet in submission order.
    // A run-time shader takes four groups at a time (two sixteen-lane calls' worth, made as
    // one: RuntimeShader::fragment_pair), in the same order.
    constexpr int kBatch = shader_runtime<S>() ? 4 : 2;
    Group pending[kBatch];
    int n_pending = 0;
    auto emit = [&](const Prim& p, Pos g, unsigned m) {
      pending[n_pending++] = {&p, g, m};
      if (n_pending < kBatch) return;
      n_pending = 0;
      if constexpr (kBatch == 4)
        shade_pair<Smooth>(d, t, pending, c, rows);
      else
        shade<Float16, Smooth>(d, t, *pending[0].prim, *pending[1].prim, pending[0].pos, pending[1].pos,
                               pending[0].mask | (pending[1].mask << 8), c, rows);
    };
    // (shade<Float16> has one call site for a C++ shader: with two, GCC does not flatten it.)
    auto flush_pending = [&] {
      const Group* g = pending;
      if constexpr (kBatch == 4) {
        if (n_pending == 3) {
          Group four[4] = {g[0], g[1], g[2], {g[2].prim, g[2].pos, 0}};
          shade_pair<Smooth>(d, t, four, c, rows);
        } else if (n_pending == 2) {
          shade<Float16, Smooth>(d, t, *g[0].prim, *g[1].prim, g[0].pos, g[1].pos,
                                 g[0].mask | (g[1].mask << 8), c, rows);
        }
      }
      if (n_pending == 1)
        shade<Float8, Smooth>(d, t, *g[0].prim, *g[0].prim, g[0].pos, g[0].pos, g[0].mask, c, rows);
      n_pending = 0;
    };
    [[maybe_unused]] const bool packed = kPacked && d.fast_color;
    for (int i = 0; i < n && i < kAhead; ++i) prefetch_prim(prims[i]);
    for (int i = 0; i < n; ++i) {
      if (i + kAhead < n) prefetch_prim(prims[i + kAhead]);
      if constexpr (kPacked) {
        if (packed && packable(*prims[i])) {
          // Small triangles from here on are shaded packed (raster_packed).
          flush_pending();
          i = raster_packed(d, t, prims, i, n, x0, y0, x1, y1, c, rows) - 1;
          continue;
        }
      }
      raster_one(*prims[i], x0, y0, x1, y1, emit);
    }
    flush_pending();
    counters.fragments_shaded += c.fragments_shaded;
    counters.fragments_written += c.fragments_written;
    counters.fragments_rejected += c.fragments_rejected;
  }

  struct Pos {
    int x, y;
  };
  struct FragmentCounts {
    uint64_t fragments_shaded = 0, fragments_written = 0, fragments_rejected = 0;
  };
  // A covered 4x2 group waiting to be shaded.
  struct Group {
    const Prim* prim;
    Pos pos;
    unsigned mask;
  };
  // A tile's triangles are a sparse walk through the frame's Prims (which fit no cache), in
  // no pattern the hardware prefetcher follows: each would wait on memory when its turn came,
  // so the one kAhead places on is requested before each (four lines: a Prim with six
  // varyings and edges is 208 bytes).
  static constexpr int kAhead = 8;
  static void prefetch_prim(const Prim* p) {
    const char* q = reinterpret_cast<const char*>(p);
    __builtin_prefetch(q);
    __builtin_prefetch(q + 64);
    __builtin_prefetch(q + 128);
    __builtin_prefetch(q + 192);
  }

  // Pixel centres of a 4x2 group's lanes, from its corner.
  static constexpr Float8 kCentreX{vx::f32x8{0.5f, 1.5f, 0.5f, 1.5f, 2.5f, 3.5f, 2.5f, 3.5f}};
  static constexpr Float8 kCentreY{vx::f32x8{0.5f, 0.5f, 1.5f, 1.5f, 0.5f, 0.5f, 1.5f, 1.5f}};

  // Shaders whose lanes are independent (shader.hpp), with early depth, may be packed.
  static constexpr bool kPacked =
      shader_lanes_independent<S>() && !shader_discards<S>() && !shader_writes_depth<S>();
  // What a packed lane carries: the varyings (value/w for perspective-correct ones), then the
  // pixel centre x and y, window z, 1/w, the facing (mask bits) and the primitive id (integer
  // bits).
  static constexpr int kStaged = varying_count<S>() + 6;
  // Lanes shaded at once: sixteen, or for a run-time shader thirty-two (two calls' worth as
  // one fragment_pair); a group adds up to eight past them.
  static constexpr int kShadeLanes = shader_runtime<S>() ? 32 : 16;
  struct Stage {
    alignas(32) float v[kStaged][kShadeLanes + 16];
    int fill = 0;
  };

  // Packed shading (kPacked, and an unblended RGBA8 target: the order of colour writes is
  // all that must be kept) for small triangles (packable), a few pixels each: each
  // covered 4x2 group is depth-tested and its varyings interpolated as in shade(), then its
  // passing lanes are appended to a stage, and the shader runs when sixteen lanes are
  // staged, so small triangles do not shade empty lanes. Colours are written in staging
  // order, which is submission order; depth is tested and written before any later group's
  // test. Larger triangles, whose groups are mostly full, are shaded by group in raster():
  // it shades its pending group before it calls this, and this shades every staged lane
  // before it returns. Runs prims[i..) while they are packable and returns the index of the
  // first that is not (or n); prefetches kAhead places on, as raster() does.
  __attribute__((noinline)) int raster_packed(const DrawRecord& d, const TargetView& t,
                                              const Prim* const* prims, int i, int n, int x0, int y0, int x1,
                                              int y1, FragmentCounts& c, LaneRows rows) const {
    constexpr int K = varying_count<S>();
    Stage st;
    const bool tests = d.state.depth_test || d.state.stencil_test;
    auto emit_packed = [&](const Prim& p, Pos g, unsigned mask) __attribute__((always_inline)) {
      const Float8 cx = Float8(float(g.x)) + kCentreX, cy = Float8(float(g.y)) + kCentreY;
      const Float8 fx = cx - Float8(p.xr), fy = cy - Float8(p.yr);
      auto plane = [&](const float* q, int stride) {
        return fma(Float8(q[2 * stride]), fy, fma(Float8(q[stride]), fx, Float8(q[0])));
      };
      const Float8 z = clamp(plane(p.z, 1), Float8(d.depth_min), Float8(d.depth_max));
      if (tests) {
        const unsigned covered = mask;
        mask = test8(d, t, g, mask, z, p.front);
        c.fragments_rejected += unsigned(__builtin_popcount(covered & ~mask));
        if (!mask) return;
      }
      const Float8 oow = plane(p.oow, 1);
      // Staged as value/w: the division by 1/w is done on full lanes in shade_staged.
      const Int8 index = pack_index(mask);
      const int at = st.fill;
      const float* pl = p.planes();
      for (int k = 0; k < K; ++k) {
        // A run-time shader's flat components (integers among them) keep their bits: through
        // the plane, -0 would become +0 and a signalling NaN pattern would be quieted.
        if constexpr (shader_runtime<S>()) {
          if ((flat >> k) & 1) {
            Float8(pl[k]).store(&st.v[k][at]);
            continue;
          }
        }
        pack(plane(pl + k, K), index).store(&st.v[k][at]);
      }
      pack(cx, index).store(&st.v[K][at]);
      pack(cy, index).store(&st.v[K + 1][at]);
      pack(z, index).store(&st.v[K + 2][at]);
      pack(oow, index).store(&st.v[K + 3][at]);
      float_from_bits(Int8(p.front ? -1 : 0)).store(&st.v[K + 4][at]);
      float_from_bits(Int8(int32_t(p.prim_id))).store(&st.v[K + 5][at]);
      const int count = __builtin_popcount(mask);
      c.fragments_shaded += unsigned(count);
      c.fragments_written += unsigned(count);
      st.fill = at + count;
      if (st.fill >= kShadeLanes) {
        if constexpr (kShadeLanes == 32)
          shade_staged_pair(t, st, 0xFFFF, rows);
        else
          shade_staged(t, st, 0xFFFF, rows);
        st.fill -= kShadeLanes;
        for (int v = 0; v < kStaged; ++v) Float8::load(&st.v[v][kShadeLanes]).store(&st.v[v][0]);
      }
    };
    for (; i < n && packable(*prims[i]); ++i) {
      if (i + kAhead < n) prefetch_prim(prims[i + kAhead]);
      raster_one(*prims[i], x0, y0, x1, y1, emit_packed);
    }
    if (st.fill > 16)
      shade_staged_pair(t, st, (1u << (st.fill - 16)) - 1, rows);
    else if (st.fill)
      shade_staged(t, st, (1u << st.fill) - 1, rows);
    return i;
  }

  // Triangles shaded packed: those with a cover, and others whose bbox is at most 16 pixels
  // a side (their groups are mostly partly covered too).
  static bool packable(const Prim& p) { return p.cover || (p.maxx - p.minx < 16 && p.maxy - p.miny < 16); }

  // Lane indices that move the lanes set in `mask` to the front, in order.
  static Int8 pack_index(unsigned mask) {
    static constexpr auto table = [] {
      std::array<std::array<uint8_t, 8>, 256> r{};
      for (unsigned m = 0; m < 256; ++m) {
        int n = 0;
        for (int l = 0; l < 8; ++l)
          if ((m >> l) & 1) r[m][size_t(n++)] = uint8_t(l);
      }
      return r;
    }();
    const auto& e = table[mask & 0xFF];
    return Int8(vx::i32x8{e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7]});
  }
  static Float8 pack(Float8 v, Int8 index) {
#if defined(__AVX2__)
    return Float8((vx::f32x8)_mm256_permutevar8x32_ps((__m256)v.v, (__m256i)index.v));
#else
    Float8 r;
    for (int l = 0; l < 8; ++l) r[l] = v[index[l]];
    return r;
#endif
  }

  // Staged lanes [base, base + 16) as a fragment: the varyings divided by 1/w (into a run-time
  // shader's lane rows `into`, else into vary), the centre, depth, facing and id.
  __attribute__((always_inline)) void stage_in(const Stage& st, int base, FragmentLanes* into,
                                               Fragment<Float16>& f, Varyings<Float16>& vary) const {
    constexpr int K = varying_count<S>();
    using F = Float16;
    const F oow = F::load(st.v[K + 3] + base);
    if constexpr (K > 0) {
      const uint64_t linear =
          shader_runtime<S>() ? flat | noperspective : shader_flat<S>() | shader_noperspective<S>();
      const F w = F(1.0f) / oow;
      F lanes[K];
      int n = K;
      if constexpr (shader_runtime<S>()) n = shader_.live_varyings();
      for (int k = 0; k < n; ++k) {
        lanes[k] = F::load(st.v[k] + base);
        if (!((linear >> k) & 1)) lanes[k] = lanes[k] * w;
        // A run-time shader reads its inputs from lane rows: stored there straight away.
        if constexpr (shader_runtime<S>()) lanes[k].store(into->varyings[k]);
      }
      if constexpr (!shader_runtime<S>()) std::memcpy(&vary, lanes, sizeof lanes);
    }
    (void)into;
    (void)vary;
    const F cx = F::load(st.v[K] + base), cy = F::load(st.v[K + 1] + base);
    f.coord = Vec4<F>(cx, cy, F::load(st.v[K + 2] + base), oow);
    const F front = F::load(st.v[K + 4] + base), id = F::load(st.v[K + 5] + base);
    f.front_facing = Mask16(Mask8(bits_of(front.lo).v), Mask8(bits_of(front.hi).v));
    f.primitive_id = Int16(bits_of(id.lo), bits_of(id.hi));
    for (int i = 0; i < shader_outputs<S>(); ++i) f.color[size_t(i)] = Vec4<F>(F(0.0f));
    f.depth = f.coord.z;
    f.killed = MaskOf<F>(false);
  }

  // Writes the colours of the lanes in `mask` (an unblended RGBA8 attachment,
  // DrawRecord::fast_color), in lane order.
  __attribute__((always_inline)) static void stage_out(const TargetView& t, const Fragment<Float16>& f,
                                                       unsigned mask) {
    using F = Float16;
    const Vec4<F>& col = f.color[0];
    const F cx = f.coord.x, cy = f.coord.y;
    alignas(32) int32_t px[16], xs[16], ys[16];
    (to_unorm8(col.x.lo) | (to_unorm8(col.y.lo) << 8) | (to_unorm8(col.z.lo) << 16) |
     (to_unorm8(col.w.lo) << 24))
        .store(px);
    (to_unorm8(col.x.hi) | (to_unorm8(col.y.hi) << 8) | (to_unorm8(col.z.hi) << 16) |
     (to_unorm8(col.w.hi) << 24))
        .store(px + 8);
    to_int(cx.lo).store(xs);
    to_int(cx.hi).store(xs + 8);
    to_int(cy.lo).store(ys);
    to_int(cy.hi).store(ys + 8);
    const ColorTarget& ct = t.color[0];
    for (unsigned m = mask; m; m &= m - 1) {
      const int l = __builtin_ctz(m);
      std::memcpy(ct.data + size_t(ys[l]) * ct.row_bytes + size_t(xs[l]) * 4, &px[l], 4);
    }
  }

  // Runs the shader on the first sixteen staged lanes and writes the colours of the lanes
  // in `mask`.
  __attribute__((flatten, noinline)) void shade_staged(const TargetView& t, const Stage& st, unsigned mask,
                                                       LaneRows rows) const {
    Varyings<Float16> vary;
    Fragment<Float16> f;
    stage_in(st, 0, rows[0], f, vary);
    if constexpr (shader_runtime<S>())
      shader_.fragment_stored(uniforms_, f, *rows[0]);
    else
      shader_.fragment(uniforms_, vary, f);
    stage_out(t, f, mask);
  }

  // A run-time shader on the first thirty-two staged lanes, as one fragment_pair: lanes 0-15
  // all written, lanes 16-31 those in `mask_hi`.
  __attribute__((flatten, noinline)) void shade_staged_pair(const TargetView& t, const Stage& st,
                                                            unsigned mask_hi, LaneRows rows) const {
    if constexpr (shader_runtime<S>()) {
      Varyings<Float16> unused;  // a run-time shader's varyings go to its lane rows
      Fragment<Float16> f0, f1;
      stage_in(st, 0, rows[0], f0, unused);
      stage_in(st, 16, rows[1], f1, unused);
      shader_.fragment_stored_pair(uniforms_, f0, f1, *rows[0], *rows[1]);
      stage_out(t, f0, 0xFFFF);
      stage_out(t, f1, mask_hi);
    }
  }

  // The lanes of the 4x2 group at (gx, gy) inside the bbox [minx, maxx] x [miny, maxy] (all
  // of them, away from its border).
  __attribute__((always_inline)) static unsigned bbox_mask(int gx, int gy, int minx, int miny, int maxx,
                                                           int maxy) {
    if (gx >= minx && gx + 3 <= maxx && gy >= miny && gy + 1 <= maxy) return 0xFF;
    const Int8 lane_dx(vx::i32x8{0, 1, 0, 1, 2, 3, 2, 3}), lane_dy(vx::i32x8{0, 0, 1, 1, 0, 0, 1, 1});
    const Int8 px = Int8(gx) + lane_dx, py = Int8(gy) + lane_dy;
    return ((px >= Int8(minx)) & (px <= Int8(maxx)) & (py >= Int8(miny)) & (py <= Int8(maxy))).bits();
  }

  // The covered groups of a triangle with a cover (found at setup, Prim::cover) in the tile
  // rectangle, as emit(p, group, lane mask): only the cut to the tile is left to do.
  template <class Emit>
  __attribute__((always_inline)) static void raster_cover(const Prim& p, int x0, int y0, int x1, int y1,
                                                          Emit& emit) {
    const int minx = std::max(p.minx, x0), maxx = std::min(p.maxx, x1 - 1);
    const int miny = std::max(p.miny, y0), maxy = std::min(p.maxy, y1 - 1);
    if (minx > maxx || miny > maxy) return;
    const int gx0 = p.minx & ~3, gy0 = p.miny & ~1;
    const bool whole = minx == p.minx && maxx == p.maxx && miny == p.miny && maxy == p.maxy;
    for (uint64_t m = p.cover; m;) {
      const int byte = __builtin_ctzll(m) >> 3;
      const Pos g{gx0 + (byte & 1) * 4, gy0 + (byte >> 1) * 2};
      unsigned gm = unsigned(m >> (8 * byte)) & 0xFF;
      m &= ~(uint64_t(0xFF) << (8 * byte));
      if (!whole) gm &= bbox_mask(g.x, g.y, minx, miny, maxx, maxy);
      if (gm) emit(p, g, gm);
    }
  }

  // The coverage of one triangle in the tile rectangle, as emit(p, group, lane mask) per
  // covered 4x2 group.
  template <class Emit>
  __attribute__((always_inline)) static void raster_one(const Prim& p, int x0, int y0, int x1, int y1,
                                                        Emit& emit) {
    const int minx = std::max(p.minx, x0), maxx = std::min(p.maxx, x1 - 1);
    const int miny = std::max(p.miny, y0), maxy = std::min(p.maxy, y1 - 1);
    if (minx > maxx || miny > maxy) return;
    const Int8 lane_dx(vx::i32x8{0, 1, 0, 1, 2, 3, 2, 3}), lane_dy(vx::i32x8{0, 0, 1, 1, 0, 0, 1, 1});
    auto bbox_mask = [&](int gx, int gy) { return Program::bbox_mask(gx, gy, minx, miny, maxx, maxy); };
    if (p.cover) return raster_cover(p, x0, y0, x1, y1, emit);
    const EdgeEq* pe = p.edges(varying_count<S>());
    // Small triangles (most of a tessellated mesh): no block classification; the 4x2 groups
    // of the bbox are tested directly, in 32-bit lanes (small_edges).
    if (small_edges(pe)) {
      const int gx0 = minx & ~3, gy0 = miny & ~1;
      const SmallEdgeLanes edges(pe, gx0, gy0);
      for (int gy = gy0; gy <= maxy; gy += 2) {
        for (int gx = gx0; gx <= maxx; gx += 4) {
          const unsigned mask = bbox_mask(gx, gy) & edges.at(gx - gx0, gy - gy0);
          if (mask) emit(p, Pos{gx, gy}, mask);
        }
      }
      return;
    }
    // With |a|, |b| < 2^26 an edge that crosses an 8x8 block stays below 2^30 in magnitude
    // inside it, so its values are stepped in 32-bit lanes; larger steps (triangles
    // thousands of pixels across) take the 64-bit per-lane path.
    bool narrow = true;
    for (const EdgeEq& e : {pe[0], pe[1], pe[2]})
      narrow = narrow && e.a > -(int64_t(1) << 26) && e.a < (int64_t(1) << 26) && e.b > -(int64_t(1) << 26) &&
               e.b < (int64_t(1) << 26);
    for (int by = miny & ~7; by <= maxy; by += 8) {
      for (int bx = minx & ~7; bx <= maxx; bx += 8) {
        // Classify the 8x8 block against each edge from its corner pixels: edges that do
        // not cross it need no test inside.
        unsigned crossing = 0;
        bool outside = false;
        int64_t e00[3];
        for (int i = 0; i < 3; ++i) {
          const EdgeEq& e = pe[i];
          e00[i] = e.c + e.a * bx + e.b * by;
          const int64_t lo = e00[i] + std::min<int64_t>(0, e.a * 7) + std::min<int64_t>(0, e.b * 7);
          const int64_t hi = e00[i] + std::max<int64_t>(0, e.a * 7) + std::max<int64_t>(0, e.b * 7);
          if (hi <= 0) {
            outside = true;
            break;
          }
          if (lo <= 0) crossing |= 1u << i;
        }
        if (outside) continue;
        Int8 base[3];
        int32_t step_a[3], step_b[3];
        int ne = 0;
        if (narrow) {
          for (int i = 0; i < 3; ++i) {
            if (!(crossing & (1u << i))) continue;
            step_a[ne] = int32_t(pe[i].a);
            step_b[ne] = int32_t(pe[i].b);
            base[ne] = Int8(int32_t(e00[i])) + Int8(step_a[ne]) * lane_dx + Int8(step_b[ne]) * lane_dy;
            ++ne;
          }
        }
        // The coverage of the 4x2 group at (gx, gy), cut to the bbox.
        auto group_mask = [&](int gx, int gy) -> unsigned {
          if (gx + 3 < minx || gx > maxx) return 0;
          unsigned mask = bbox_mask(gx, gy);
          if (crossing && mask) {
            if (narrow) {
              const int ox = gx - bx, oy = gy - by;
              for (int k = 0; k < ne; ++k)
                mask &= ((base[k] + Int8(step_a[k] * ox + step_b[k] * oy)) > Int8(0)).bits();
            } else {
              for (int l = 0; l < kLanes; ++l) {
                const int px = gx + kLaneDx[l], py = gy + kLaneDy[l];
                for (int i = 0; i < 3; ++i)
                  if ((crossing & (1u << i)) && !(pe[i].c + pe[i].a * px + pe[i].b * py > 0))
                    mask &= ~(1u << l);
              }
            }
          }
          return mask;
        };
        for (int gy = by; gy < by + 8; gy += 2) {
          if (gy + 1 < miny || gy > maxy) continue;
          for (int gx = bx; gx < bx + 8; gx += 4) {
            const unsigned m = group_mask(gx, gy);
            if (m) emit(p, Pos{gx, gy}, m);
          }
        }
      }
    }
  }

  // Depth/stencil test of the 8 lanes of group a, or the 16 of groups a and b.
  __attribute__((always_inline)) static unsigned test8(const DrawRecord& d, const TargetView& t, Pos a,
                                                       unsigned mask, const Float8& z, bool front) {
    if (d.fast_depth && a.x + 4 <= t.width && a.y + 2 <= t.height)
      return depth_test8(d, t, a.x, a.y, mask, z);
    return depth_stencil_test(d, t, a.x, a.y, mask, z, front);
  }
  template <class F>
  __attribute__((always_inline)) static unsigned test(const DrawRecord& d, const TargetView& t, Pos a, Pos b,
                                                      unsigned mask, const F& z, bool front_a, bool front_b) {
    if constexpr (lane_width<F> == 8) {
      return test8(d, t, a, mask, z, front_a);
    } else {
      unsigned lo = mask & 0xFF, hi = mask >> 8;
      if (lo) lo = test8(d, t, a, lo, lo_half(z), front_a);
      if (hi) hi = test8(d, t, b, hi, hi_half(z), front_b);
      return lo | (hi << 8);
    }
  }
  __attribute__((always_inline)) static void write8(const DrawRecord& d, const TargetView& t, Pos a,
                                                    unsigned mask, const Vec4<Float8>* colors, int outputs) {
    if (d.fast_color && a.x + 4 <= t.width && a.y + 2 <= t.height)
      return write_rgba8(t.color[0], a.x, a.y, mask, colors[0]);
    write_colors(d, t, a.x, a.y, mask, colors, outputs);
  }

  // A value per half: x on eight lanes; x in lanes 0-7 and y in lanes 8-15 on sixteen.
  // V is F, MaskOf<F> or IntOf<F>.
  template <class F, class V, class T>
  __attribute__((always_inline)) static V halves(T x, T y) {
    if constexpr (lane_width<F> == 8)
      return V(x);
    else
      return join(decltype(lo_half(V()))(x), decltype(lo_half(V()))(y));
  }
  template <class F>
  __attribute__((always_inline)) static F halves(float x, float y) {
    return halves<F, F>(x, y);
  }

  // The colour outputs the shader writes (a run-time shader's own count, at most its bridge's).
  int output_count() const {
    return shader_runtime<S>() ? std::min(shader_outputs<S>(), ProgramBase::outputs) : shader_outputs<S>();
  }

  // One shade()'s work between its steps: the groups, their lanes and depth (the fragment
  // and varyings are the caller's own variables: in a struct GCC keeps them in memory).
  template <class F>
  struct Shading {
    const Prim *pa = nullptr, *pb = nullptr;
    Pos a{0, 0}, b{0, 0};
    unsigned mask = 0;
    F z;
  };

  // Shades the 4x2 group at a of triangle pa (eight lanes; pb is pa), or also the group at b
  // of triangle pb (sixteen lanes: a in lanes 0-7, b in lanes 8-15). flatten: the shader and
  // every GLSL function it calls are inlined here, so lane values stay in registers (lane values passed to an
  // out-of-line call go through memory); always_inline: with two call sites GCC would outline it.
  template <class F, bool Smooth>
  __attribute__((flatten, always_inline)) inline void shade(const DrawRecord& d, const TargetView& t,
                                                            const Prim& pa, const Prim& pb, Pos a, Pos b,
                                                            unsigned mask, FragmentCounts& c,
                                                            LaneRows rows) const {
    Shading<F> s;
    Fragment<F> f;
    Varyings<F> vary;
    if (!begin_shading(d, t, pa, pb, a, b, mask, c, s, f, vary, rows[0])) return;
    if constexpr (shader_runtime<S>())
      shader_.fragment_stored(uniforms_, f, *rows[0]);
    else
      shader_.fragment(uniforms_, vary, f);
    if constexpr (Smooth) apply_smooth(s, f);
    end_shading(d, t, s, f, c);
  }

  // Four groups of a run-time shader (g[0] and g[1] in lane rows 0, g[2] and g[3] in rows 1; a
  // group may have no lanes), shaded by one fragment_pair call: depth is tested, and colour
  // written, group by group in order, as by two shade() calls.
  template <bool Smooth>
  __attribute__((noinline)) void shade_pair(const DrawRecord& d, const TargetView& t, const Group* g,
                                            FragmentCounts& c, LaneRows rows) const {
    if constexpr (shader_runtime<S>()) {
      Shading<Float16> s0, s1;
      Fragment<Float16> f0, f1;
      Varyings<Float16> v0, v1;
      const bool go0 = begin_shading(d, t, *g[0].prim, *g[1].prim, g[0].pos, g[1].pos,
                                     g[0].mask | (g[1].mask << 8), c, s0, f0, v0, rows[0]);
      const bool go1 = begin_shading(d, t, *g[2].prim, *g[3].prim, g[2].pos, g[3].pos,
                                     g[2].mask | (g[3].mask << 8), c, s1, f1, v1, rows[1]);
      if (go0 && go1)
        shader_.fragment_stored_pair(uniforms_, f0, f1, *rows[0], *rows[1]);
      else if (go0)
        shader_.fragment_stored(uniforms_, f0, *rows[0]);
      else if (go1)
        shader_.fragment_stored(uniforms_, f1, *rows[1]);
      if (go0) {
        if constexpr (Smooth) apply_smooth(s0, f0);
        end_shading(d, t, s0, f0, c);
      }
      if (go1) {
        if constexpr (Smooth) apply_smooth(s1, f1);
        end_shading(d, t, s1, f1, c);
      }
    }
  }

  // The fragment's inputs: lane centres, depth (tested now when the test is early),
  // interpolated varyings (in vary, or for a run-time shader in its lane rows `into`).
  // False when no lane is left.
  template <class F>
  __attribute__((always_inline)) bool begin_shading(const DrawRecord& d, const TargetView& t, const Prim& pa,
                                                    const Prim& pb, Pos a, Pos b, unsigned mask,
                                                    FragmentCounts& c, Shading<F>& s, Fragment<F>& f,
                                                    Varyings<F>& vary, FragmentLanes* into) const {
    constexpr int K = varying_count<S>();
    constexpr int N = lane_width<F>;
    const int outputs = output_count();
    F cx, cy;
    if constexpr (N == 8) {
      cx = Float8(float(a.x)) + kCentreX;
      cy = Float8(float(a.y)) + kCentreY;
    } else {
      cx = join(Float8(float(a.x)) + kCentreX, Float8(float(b.x)) + kCentreX);
      cy = join(Float8(float(a.y)) + kCentreY, Float8(float(b.y)) + kCentreY);
    }
    // A plane (value, d/dx, d/dy, `stride` floats apart) of each half's triangle at the lanes.
    auto plane = [&](const float* qa, const float* qb, int stride, F fx, F fy) {
      return fma(halves<F>(qa[2 * stride], qb[2 * stride]), fy,
                 fma(halves<F>(qa[stride], qb[stride]), fx, halves<F>(qa[0], qb[0])));
    };
    const F fx = cx - halves<F>(pa.xr, pb.xr), fy = cy - halves<F>(pa.yr, pb.yr);
    F z = plane(pa.z, pb.z, 1, fx, fy);
    z = clamp(z, F(d.depth_min), F(d.depth_max));
    const bool tests = d.state.depth_test || d.state.stencil_test;
    if (tests && d.early_depth) {
      const unsigned covered = mask;
      mask = test(d, t, a, b, mask, z, pa.front, pb.front);
      c.fragments_rejected += unsigned(__builtin_popcount(covered & ~mask));
      if (!mask) return false;
    }
    s.pa = &pa;
    s.pb = &pb;
    s.a = a;
    s.b = b;
    s.mask = mask;
    s.z = z;
    const F oow = plane(pa.oow, pb.oow, 1, fx, fy);
    const F w = F(1.0f) / oow;
    if constexpr (K > 0) {
      F lanes[K];
      const float *pla = pa.planes(), *plb = pb.planes();
      // A run-time shader's unused components (its varyings round up to K) are not read.
      int n = K;
      float* rows = nullptr;  // its lane rows, `stride` apart
      size_t stride = 0;
      if constexpr (shader_runtime<S>()) {
        n = shader_.live_varyings();
        rows = &into->varyings[0][0];
        stride = std::size(into->varyings[0]);
      }
      for (int k = 0; k < n; ++k) {
        F v;
        if (shader_runtime<S>() && ((flat >> k) & 1)) {
          v = halves<F>(pla[k], plb[k]);  // bit for bit (see raster_packed)
        } else {
          v = plane(pla + k, plb + k, K, fx, fy);
          if (!(((flat | noperspective) >> k) & 1)) v = v * w;
        }
        if constexpr (shader_runtime<S>())
          v.store(rows + size_t(k) * stride);
        else
          lanes[k] = v;
      }
      if constexpr (!shader_runtime<S>()) std::memcpy(&vary, lanes, sizeof lanes);
    }
    (void)into;
    (void)vary;
    f.coord = Vec4<F>(cx, cy, z, oow);
    f.front_facing = halves<F, MaskOf<F>>(pa.front, pb.front);
    f.primitive_id = halves<F, IntOf<F>>(int32_t(pa.prim_id), int32_t(pb.prim_id));
    // (One output is set even when none is written, so that no path reads it unset.)
    for (int i = 0; i < std::max(outputs, 1); ++i) f.color[size_t(i)] = Vec4<F>(F(0.0f));
    f.depth = z;
    f.killed = MaskOf<F>(false);
    return true;
  }

  // Antialiased points and lines (PrimKind::Smooth): each lane's coverage (SmoothCoverage) at
  // the pixel centres (x, y), of pa's lanes 0-7 and pb's 8-15, and the lanes of a point outside
  // its circle, which are dropped. Out of line, and given values rather than the fragment, so
  // that the shading loop keeps its fragment in registers.
  template <class F>
  struct SmoothResult {
    F coverage;
    unsigned killed;
  };
  template <class F>
  __attribute__((noinline)) static SmoothResult<F> smooth_coverage(const Prim* pa, const Prim* pb, F cx,
                                                                   F cy) {
    constexpr int N = lane_width<F>;
    constexpr int K = varying_count<S>();
    alignas(64) float x[N], y[N], cov[N];
    cx.store(x);
    cy.store(y);
    unsigned killed = 0;
    for (int l = 0; l < N; ++l) {
      const Prim& p = N == 16 && l >= 8 ? *pb : *pa;
      if (p.kind != PrimKind::Smooth) {
        cov[l] = 1.0f;
        continue;
      }
      const SmoothCoverage& sc = *p.smooth(K);
      const float px = x[l] - sc.ox, py = y[l] - sc.oy;
      const float u = px * sc.ux + py * sc.uy, v = px * sc.vx + py * sc.vy;
      if (sc.point) {
        const float dist = u * u + v * v;
        if (dist > 1.0f) killed |= 1u << l;
        cov[l] = sc.a >= dist ? (1.0f / (1.0f - sc.a)) * (1.0f - dist) : 1.0f;
      } else {
        cov[l] = std::clamp(sc.a - std::fabs(u), 0.0f, 1.0f) * std::clamp(sc.b - std::fabs(v), 0.0f, 1.0f);
      }
    }
    return {F::load(cov), killed};
  }
  // The coverage applied: alpha of every colour output multiplied, a point's outside lanes
  // taken out of the shading's mask.
  template <class F>
  __attribute__((always_inline)) void apply_smooth(Shading<F>& s, Fragment<F>& f) const {
    const SmoothResult<F> r = smooth_coverage(s.pa, s.pb, f.coord.x, f.coord.y);
    s.mask &= ~r.killed;
    for (int i = 0; i < std::max(output_count(), 1); ++i)
      f.color[size_t(i)].w = f.color[size_t(i)].w * r.coverage;
  }

  // After the shader: discards, depth tested now when the test is late, colours written.
  template <class F>
  __attribute__((always_inline)) void end_shading(const DrawRecord& d, const TargetView& t,
                                                  const Shading<F>& s, const Fragment<F>& f,
                                                  FragmentCounts& c) const {
    constexpr int N = lane_width<F>;
    constexpr int max_outputs = shader_outputs<S>();
    const int outputs = output_count();
    unsigned mask = s.mask;
    F z = s.z;
    const Pos a = s.a, b = s.b;
    if constexpr (shader_discards<S>()) mask &= ~f.killed.bits();
    if constexpr (shader_writes_depth<S>()) z = clamp(f.depth, F(0.0f), F(1.0f));
    c.fragments_shaded += unsigned(__builtin_popcount(mask));
    const bool tests = d.state.depth_test || d.state.stencil_test;
    if (tests && !d.early_depth) {
      const unsigned shaded = mask;
      mask = test(d, t, a, b, mask, z, s.pa->front, s.pb->front);
      c.fragments_rejected += unsigned(__builtin_popcount(shaded & ~mask));
    }
    if (!mask) return;
    if constexpr (N == 8) {
      write8(d, t, a, mask, f.color.data(), outputs);
    } else {
      Vec4<Float8> half[max_outputs];
      if (mask & 0xFF) {
        for (int i = 0; i < outputs; ++i) half[i] = lo_half(f.color[size_t(i)]);
        write8(d, t, a, mask & 0xFF, half, outputs);
      }
      if (mask >> 8) {
        for (int i = 0; i < outputs; ++i) half[i] = hi_half(f.color[size_t(i)]);
        write8(d, t, b, mask >> 8, half, outputs);
      }
    }
    c.fragments_written += unsigned(__builtin_popcount(mask));
  }

  S shader_;
  Uniforms uniforms_;
};

}  // namespace tessel::gpu::detail
