// The IR interpreter (interp.hpp). Structured control flow under execution masks, as
// ir.hpp describes: `live` is the set of lanes that run a node.
#include "interp.hpp"
#include "texture_avx512.hpp"

#include "tessel/gpu/format.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace tessel::glsl {
namespace {

using ir::Inst;
using ir::Op;
constexpr int L = ir::kLanes;

struct Masks {
  uint32_t ret = 0, brk = 0, cont = 0, kill = 0;
};

inline float f(uint32_t u) { return std::bit_cast<float>(u); }
inline uint32_t u(float x) { return std::bit_cast<uint32_t>(x); }
inline int32_t s(uint32_t x) { return int32_t(x); }
inline uint32_t b(bool x) { return x ? ~0u : 0u; }

uint32_t mask_of(const LaneReg& r) {
  uint32_t m = 0;
  for (int l = 0; l < L; ++l) m |= (r.u[l] >> 31) << l;
  return m;
}

// Integer division with every case defined, as llvmpipe defines it: a signed quotient by 0 is
// 0 and INT_MIN / -1 is INT_MIN; an unsigned quotient or remainder by 0 is all bits set.
int32_t idiv(int32_t a, int32_t d) {
  if (d == 0) return 0;
  if (d == -1) return int32_t(0u - uint32_t(a));
  return a / d;
}
uint32_t udiv(uint32_t a, uint32_t d) { return d == 0 ? ~0u : a / d; }
uint32_t umod(uint32_t a, uint32_t d) { return d == 0 ? ~0u : a % d; }

// Float to integer as x86's cvttps2dq: NaN and out-of-range values give INT_MIN.
int32_t f2i(float x) {
  if (!(x > -2147483904.0f && x < 2147483648.0f)) return std::numeric_limits<int32_t>::min();
  return int32_t(x);
}
// Float to unsigned as llvmpipe converts on an AVX-512 machine (vcvttps2udq): values in
// (-1, 2^32) truncate, everything else (NaN included) gives all bits set. (On AVX2 alone
// llvmpipe's result differs out of range; GLSL leaves it undefined.)
uint32_t f2u(float x) {
  if (!(x > -1.0f && x < 4294967296.0f)) return ~0u;
  return uint32_t(x);
}

// A texel as an integer sampler returns it: integer textures hold each component's 32 bits
// in the float slot (gl/texture_format.hpp), so the bits are the value; with no texture
// there, GL's (0, 0, 0, 1) as integers.
uint32_t integer_texel(const glm::vec4& v, int k, bool texture) {
  if (!texture) return k == 3 ? 1u : 0u;
  return std::bit_cast<uint32_t>(v[k]);
}

int find_msb_u(uint32_t x) { return x == 0 ? -1 : 31 - std::countl_zero(x); }
int find_msb_i(int32_t x) { return find_msb_u(uint32_t(x < 0 ? ~x : x)); }
uint32_t bit_reverse(uint32_t x) {
  uint32_t r = 0;
  for (int i = 0; i < 32; ++i) r |= ((x >> i) & 1u) << (31 - i);
  return r;
}
uint32_t field_mask(uint32_t bits) { return bits >= 32 ? ~0u : ((1u << bits) - 1u); }

// packHalf2x16 / unpackHalf2x16 with the gpu layer's conversions (round to nearest even,
// as F16C's vcvtps2ph).
uint32_t pack_half(float a, float c) {
  return uint32_t(gpu::float_to_half(a)) | (uint32_t(gpu::float_to_half(c)) << 16);
}
float unpack_half(uint32_t h) { return gpu::half_to_float(uint16_t(h)); }

float fsign(float x) { return x > 0.0f ? 1.0f : x < 0.0f ? -1.0f : 0.0f; }
float ffract(float x) { return x - std::floor(x); }
float fmod_glsl(float x, float y) { return x - y * std::floor(x / y); }

}  // namespace

// The operations that the JIT calls out for (bit fields, frexp, halves): one definition for
// both tiers, so that they give the same bits.
void lane_math(ir::Op op, uint32_t* t, const uint32_t* a, const uint32_t* bb, const uint32_t* c,
               const uint32_t* e) {
  auto each = [](uint32_t* out, auto&& fn) {
    for (int l = 0; l < L; ++l) out[l] = fn(l);
  };
  (void)e;
  switch (op) {
#define F1(OP, EXPR)           \
  case Op::OP:                 \
    each(t, [&](int l) {       \
      const float x = f(a[l]); \
      (void)x;                 \
      return u(EXPR);          \
    });                        \
    break;
#define F2(OP, EXPR)                         \
  case Op::OP:                               \
    each(t, [&](int l) {                     \
      const float x = f(a[l]), y = f(bb[l]); \
      return u(EXPR);                        \
    });                                      \
    break;
#define I2(OP, EXPR)                      \
  case Op::OP:                            \
    each(t, [&](int l) {                  \
      const uint32_t x = a[l], y = bb[l]; \
      (void)y;                            \
      return uint32_t(EXPR);              \
    });                                   \
    break;
    case Op::FLdexp:
      each(t, [&](int l) { return u(std::ldexp(f(a[l]), std::clamp(s(bb[l]), -1000, 1000))); });

      break;
    case Op::FFrexpMant:
      each(t, [&](int l) {
        int e;
        return u(std::isfinite(f(a[l])) ? std::frexp(f(a[l]), &e) : f(a[l]));
      });

      break;
    case Op::FFrexpExp:
      each(t, [&](int l) {
        int e = 0;
        if (std::isfinite(f(a[l]))) std::frexp(f(a[l]), &e);
        return uint32_t(e);
      });

      break;
      I2(BitCount, std::popcount(x))
      I2(FindLSB, x == 0 ? -1 : std::countr_zero(x))
      I2(IFindMSB, find_msb_i(s(x)))
      I2(UFindMSB, find_msb_u(x))
      I2(BitReverse, bit_reverse(x))
    case Op::IBitExtract:
    case Op::UBitExtract:
      each(t, [&](int l) {
        const uint32_t off = std::min(bb[l], 32u), bits = std::min(c[l], 32u - off);
        if (bits == 0) return 0u;
        uint32_t v = (a[l] >> (off & 31)) & field_mask(bits);
        if (off >= 32) v = 0;
        if (op == Op::IBitExtract && bits < 32 && ((v >> (bits - 1)) & 1)) v |= ~field_mask(bits);
        return v;
      });

      break;
    case Op::BitInsert: {
      each(t, [&](int l) {
        const uint32_t off = std::min(c[l], 32u), bits = std::min(e[l], 32u - off);
        if (bits == 0 || off >= 32) return a[l];
        const uint32_t m = field_mask(bits) << off;
        return (a[l] & ~m) | ((bb[l] << off) & m);
      });

      break;
    }
      I2(UAddCarry, (x + y) < x ? 1u : 0u)
      I2(USubBorrow, x < y ? 1u : 0u)
    case Op::PackHalf: each(t, [&](int l) { return pack_half(f(a[l]), f(bb[l])); }); break;
    case Op::UnpackHalfLo: each(t, [&](int l) { return u(unpack_half(a[l])); }); break;
    case Op::UnpackHalfHi: each(t, [&](int l) { return u(unpack_half(a[l] >> 16)); }); break;
#undef F1
#undef F2
#undef I2
    default: break;
  }
}

namespace {

class Runner {
 public:
  Runner(const ir::Stage& st, LaneReg* r, const RunInputs& in) : st_(st), r_(r), in_(in) {}

  void block(const ir::Block& bl, uint32_t mask) {
    for (const ir::Node& n : bl) {
      const uint32_t live = mask & ~(m_.ret | m_.brk | m_.cont | m_.kill);
      if (!live) return;
      switch (n.kind) {
        case ir::Node::Kind::Code: code(n.code, live); break;
        case ir::Node::Kind::If: {
          const uint32_t c = mask_of(r_[n.cond]) & live;
          if (c) block(n.a, c);
          const uint32_t e = live & ~c;
          if (e && !n.b.empty()) block(n.b, e);
          break;
        }
        case ir::Node::Kind::Loop: {
          const uint32_t brk = m_.brk, cont = m_.cont;
          m_.brk = 0;
          for (int it = 0; it < ir::kMaxLoopIterations && budget_ < ir::kMaxTotalLoopIterations;
               ++it, ++budget_) {
            m_.cont = 0;
            uint32_t lm = live & ~(m_.ret | m_.brk | m_.kill);
            if (!lm) break;
            block(n.a, lm);
            m_.cont = 0;
            lm = live & ~(m_.ret | m_.brk | m_.kill);
            if (!lm) break;
            block(n.b, lm);
          }
          m_.brk = brk;
          m_.cont = cont;
          break;
        }
        case ir::Node::Kind::Break: m_.brk |= live; break;
        case ir::Node::Kind::Continue: m_.cont |= live; break;
        case ir::Node::Kind::Return: m_.ret |= live; break;
        case ir::Node::Kind::Discard: m_.kill |= live; break;
        case ir::Node::Kind::Function: {
          const uint32_t ret = m_.ret;
          block(n.a, live);
          m_.ret = ret;
          break;
        }
        case ir::Node::Kind::Switch: {
          const uint32_t brk = m_.brk;
          m_.brk = 0;
          block(n.a, live);
          m_.brk = brk;
          break;
        }
      }
    }
  }

  uint32_t killed() const { return m_.kill; }

 private:
  const ir::Stage& st_;
  LaneReg* r_;
  const RunInputs& in_;
  Masks m_;
  uint32_t budget_ = 0;  // loop iterations run so far (ir::kMaxTotalLoopIterations)

  template <class Fn>
  void each(uint32_t* d, Fn&& fn) {
    for (int l = 0; l < L; ++l) d[l] = fn(l);
  }

  void code(const std::vector<Inst>& code, uint32_t live) {
    for (const Inst& i : code) {
      uint32_t* d = r_[i.dst].u;
      const uint32_t* a = r_[i.a].u;
      const uint32_t* bb = r_[i.b].u;
      const uint32_t* c = r_[i.c].u;
      uint32_t t[L];
      switch (i.op) {
        case Op::Mov:
          std::memcpy(t, a, sizeof t);
          std::memcpy(d, t, sizeof t);
          break;
        case Op::Store:
          for (int l = 0; l < L; ++l)
            if ((live >> l) & 1) d[l] = a[l];
          break;
        case Op::UniformIndexed:
          each(t, [&](int l) { return uniform(i.imm + a[l]); });
          std::memcpy(d, t, sizeof t);
          break;
        case Op::LoadIndexed:
          // b + a[l] stays within the variable (i.imm is its last register).
          each(t, [&](int l) { return r_[std::min<uint64_t>(uint64_t(i.b) + a[l], i.imm)].u[l]; });
          std::memcpy(d, t, sizeof t);
          break;
        case Op::StoreIndexed:
          for (int l = 0; l < L; ++l)
            if ((live >> l) & 1) r_[std::min<uint64_t>(uint64_t(i.dst) + a[l], i.imm)].u[l] = bb[l];
          break;
        case Op::Select:
          each(t, [&](int l) { return (a[l] >> 31) ? bb[l] : c[l]; });
          std::memcpy(d, t, sizeof t);
          break;

#define F1(OP, EXPR)             \
  case Op::OP:                   \
    each(t, [&](int l) {         \
      const float x = f(a[l]);   \
      (void)x;                   \
      return u(EXPR);            \
    });                          \
    std::memcpy(d, t, sizeof t); \
    break;
#define F2(OP, EXPR)                         \
  case Op::OP:                               \
    each(t, [&](int l) {                     \
      const float x = f(a[l]), y = f(bb[l]); \
      return u(EXPR);                        \
    });                                      \
    std::memcpy(d, t, sizeof t);             \
    break;
#define FC(OP, EXPR)                         \
  case Op::OP:                               \
    each(t, [&](int l) {                     \
      const float x = f(a[l]), y = f(bb[l]); \
      (void)y;                               \
      return b(EXPR);                        \
    });                                      \
    std::memcpy(d, t, sizeof t);             \
    break;
#define I2(OP, EXPR)                      \
  case Op::OP:                            \
    each(t, [&](int l) {                  \
      const uint32_t x = a[l], y = bb[l]; \
      (void)y;                            \
      return uint32_t(EXPR);              \
    });                                   \
    std::memcpy(d, t, sizeof t);          \
    break;

          F2(FAdd, x + y)
          F2(FSub, x - y)
          F2(FMul, x * y)
          F2(FDiv, x / y)
          F1(FNeg, -x)
          F1(FAbs, std::fabs(x))
          F1(FSign, fsign(x))
          // minps/maxps (x < y ? x : y), and a NaN operand gives the other one, as llvmpipe.
          F2(FMin, std::isnan(y) ? x : std::isnan(x) ? y : (x < y ? x : y))
          F2(FMax, std::isnan(y) ? x : std::isnan(x) ? y : (x > y ? x : y))
        case Op::FFma:
          each(t, [&](int l) { return u(std::fma(f(a[l]), f(bb[l]), f(c[l]))); });
          std::memcpy(d, t, sizeof t);
          break;
          F1(FFloor, std::floor(x))
          F1(FCeil, std::ceil(x))
          F1(FTrunc, std::trunc(x))
          F1(FRoundEven, std::nearbyint(x))
          F1(FFract, ffract(x))
          F2(FMod, fmod_glsl(x, y))
          F1(FSqrt, std::sqrt(x))
          F1(FRsq, 1.0f / std::sqrt(x))
          FC(FLt, x < y)
          FC(FLe, x <= y)
          FC(FGt, x > y)
          FC(FGe, x >= y)
          FC(FEq, x == y)
          FC(FNe, x != y)
          FC(FIsNan, std::isnan(x))
          FC(FIsInf, std::isinf(x))

          I2(IAdd, x + y)
          I2(ISub, x - y)
          I2(IMul, x * y)
          I2(IDiv, idiv(s(x), s(y)))
          I2(UDiv, udiv(x, y))
          I2(UMod, umod(x, y))
          I2(INeg, 0u - x)
          I2(IAbs, s(x) < 0 ? 0u - x : x)
          I2(ISign, s(x) > 0 ? 1 : s(x) < 0 ? -1 : 0)
          I2(IMin, std::min(s(x), s(y)))
          I2(IMax, std::max(s(x), s(y)))
          I2(UMin, std::min(x, y))
          I2(UMax, std::max(x, y))
          I2(And, x & y)
          I2(Or, x | y)
          I2(Xor, x ^ y)
          I2(Not, ~x)
          // Shift counts use their low five bits, as NIR defines the shifts.
          I2(Shl, x << (y & 31))
          I2(ShrA, s(x) >> (y & 31))
          I2(ShrL, x >> (y & 31))
          I2(ILt, b(s(x) < s(y)))
          I2(ILe, b(s(x) <= s(y)))
          I2(IGt, b(s(x) > s(y)))
          I2(IGe, b(s(x) >= s(y)))
          I2(ULt, b(x < y))
          I2(ULe, b(x <= y))
          I2(UGt, b(x > y))
          I2(UGe, b(x >= y))
          I2(IEq, b(x == y))
          I2(INe, b(x != y))
        case Op::I2F:
          each(t, [&](int l) { return u(float(s(a[l]))); });
          std::memcpy(d, t, sizeof t);
          break;
        case Op::U2F:
          each(t, [&](int l) { return u(float(a[l])); });
          std::memcpy(d, t, sizeof t);
          break;
        case Op::F2I:
          each(t, [&](int l) { return uint32_t(f2i(f(a[l]))); });
          std::memcpy(d, t, sizeof t);
          break;
        case Op::F2U:
          each(t, [&](int l) { return f2u(f(a[l])); });
          std::memcpy(d, t, sizeof t);
          break;
        case Op::FLdexp:
        case Op::FFrexpMant:
        case Op::FFrexpExp:
        case Op::BitCount:
        case Op::FindLSB:
        case Op::IFindMSB:
        case Op::UFindMSB:
        case Op::BitReverse:
        case Op::IBitExtract:
        case Op::UBitExtract:
        case Op::BitInsert:
        case Op::UAddCarry:
        case Op::USubBorrow:
        case Op::PackHalf:
        case Op::UnpackHalfLo:
        case Op::UnpackHalfHi:
          lane_math(i.op, t, a, bb, c, r_[i.d].u);
          std::memcpy(d, t, sizeof t);
          break;
        // Inside each 2x2 quad (lanes 4q..4q+3: (0,0) (1,0) (0,1) (1,1)), as llvmpipe takes them.
        case Op::Ddx:
          each(t, [&](int l) { return u(f(a[l | 1]) - f(a[l & ~1])); });
          std::memcpy(d, t, sizeof t);
          break;
        case Op::Ddy:
          each(t, [&](int l) { return u(f(a[l | 2]) - f(a[l & ~2])); });
          std::memcpy(d, t, sizeof t);
          break;
        case Op::Texture: texture(st_.textures[i.imm]); break;
#undef F1
#undef F2
#undef FC
#undef I2
      }
    }
  }

  uint32_t uniform(uint64_t w) const {
    if (in_.uniform_words == 0) return 0;
    return in_.uniforms[std::min<uint64_t>(w, in_.uniform_words - 1)];
  }

  // Gathers a texture instruction's operands into rows, runs it, and scatters the results.
  void texture(const ir::TexOp& t) {
    TexLanes tl;
    std::memset(tl.in, 0, sizeof tl.in);
    auto row = [&](int k, ir::Reg r) {
      if (r != ir::TexOp::kNone) std::memcpy(tl.in[k], r_[r].u, sizeof tl.in[k]);
    };
    for (int i = 0; i < 5; ++i) row(TexLanes::kCoord + i, t.coord[i]);
    row(TexLanes::kLod, t.lod);
    for (int i = 0; i < 3; ++i) {
      row(TexLanes::kDx + i, t.dx[i]);
      row(TexLanes::kDy + i, t.dy[i]);
      row(TexLanes::kOffset + i, t.offset_reg[i]);
    }
    run_texture(t, in_, tl);
    for (int k = 0; k < 4; ++k)
      if (t.dst[k] != ir::TexOp::kNone) std::memcpy(r_[t.dst[k]].u, tl.out[k], sizeof tl.out[k]);
  }
};

// Lane l of three consecutive rows from row k (a derivative or a direction).
glm::vec3 lane_vec3(const TexLanes& tl, int k, int l) {
  return {f(tl.in[k][l]), f(tl.in[k + 1][l]), f(tl.in[k + 2][l])};
}

const TextureUnit* unit_of(const ir::TexOp& t, const RunInputs& in_) {
  const int32_t unit = in_.uniform_words
                           ? s(in_.uniforms[std::min<uint32_t>(uint32_t(t.sampler), in_.uniform_words - 1)])
                           : -1;
  if (unit < 0 || unit >= in_.unit_count) return nullptr;
  return &in_.units[unit];
}

// 3D, array and buffer textures and samplerCubeShadow, lane by lane (run_texture's other
// targets; 1D arrays are height-1 2D arrays, read at t = 0.5).
void run_texture_layered(const ir::TexOp& t, const TextureUnit* unit, const RunInputs& in_, TexLanes& tl) {
  using ir::SamplerDim;
  auto lanef = [&](int k, int l) { return f(tl.in[k][l]); };
  auto lanei = [&](int k, int l) { return s(tl.in[k][l]); };
  const bool d1 = t.dim == SamplerDim::D1, d3 = t.dim == SamplerDim::D3, cube = t.dim == SamplerDim::Cube;
  const gpu::Texture3D* t3 = unit ? unit->texture_3d : nullptr;
  const gpu::Texture2DArray* ta = unit ? unit->texture_2d_array : nullptr;
  const gpu::TextureCube* tc = unit ? unit->texture_cube : nullptr;
  const bool present = t.dim == SamplerDim::Buffer ? unit && unit->texture_buffer
                       : d3                        ? t3 != nullptr
                       : t.array                   ? ta != nullptr
                                                   : tc != nullptr;
  auto put = [&](int l, const glm::vec4& v) {
    for (int k = 0; k < 4; ++k) tl.out[k][l] = t.result == 0 ? u(v[k]) : integer_texel(v, k, present);
  };
  if (t.kind == ir::TexKind::Size) {
    for (int l = 0; l < L; ++l) {
      const int level = lanei(TexLanes::kLod, l);
      glm::ivec3 sz(0);
      if (t.dim == SamplerDim::Buffer) {
        if (unit && unit->texture_buffer) sz.x = unit->texture_buffer->size();
      } else if (d3) {
        if (t3 && level >= 0 && level < t3->levels())
          sz = {t3->width(level), t3->height(level), t3->depth(level)};
      } else if (t.array) {
        if (ta && level >= 0 && level < ta->levels())
          sz = d1 ? glm::ivec3(ta->width(level), ta->layers(), 0)
                  : glm::ivec3(ta->width(level), ta->height(level), ta->layers());
      } else if (tc && level >= 0 && level < tc->levels()) {
        sz = {tc->face(0).width(level), tc->face(0).height(level), 0};
      }
      for (int k = 0; k < 3; ++k) tl.out[k][l] = uint32_t(sz[k]);
      tl.out[3][l] = 0;
    }
    return;
  }
  if (t.kind == ir::TexKind::Fetch) {
    for (int l = 0; l < L; ++l) {
      const int x = lanei(0, l) + t.offset[0], level = lanei(TexLanes::kLod, l);
      if (t.dim == SamplerDim::Buffer)
        put(l, gpu::detail::texel_fetch(unit ? unit->texture_buffer : nullptr, lanei(0, l)));
      else if (d3)
        put(l, gpu::detail::texel_fetch(t3, x, lanei(1, l) + t.offset[1], lanei(2, l) + t.offset[2], level));
      else if (d1)
        put(l, gpu::detail::texel_fetch(ta, x, 0, lanei(1, l), level));
      else
        put(l, gpu::detail::texel_fetch(ta, x, lanei(1, l) + t.offset[1], lanei(2, l), level));
    }
    return;
  }
  // The coordinates: (s, t, r) of a 3D texture, (s, t, layer) of an array (t = 0.5 for 1D),
  // the direction of a cube, then the reference of a shadow lookup.
  alignas(64) float c[4][L];
  const int spatial = cube || d3 ? 3 : d1 ? 1 : 2;
  for (int l = 0; l < L; ++l) {
    const float q = t.proj ? lanef(t.coords - 1, l) : 1.0f;
    int k = 0;
    c[0][l] = lanef(k++, l);
    c[1][l] = spatial >= 2 ? lanef(k++, l) : 0.5f;
    c[2][l] = spatial == 3 || t.array ? lanef(k++, l) : 0.0f;
    c[3][l] = t.shadow ? lanef(k, l) : 0.0f;
    if (t.proj) {  // textureProj: 3D only (arrays and cubes have none)
      for (int i = 0; i < 3; ++i) c[i][l] /= q;
    }
  }
  int w = 1, h = 1, d = 1;
  if (d3 && t3) w = t3->width(), h = t3->height(), d = t3->depth();
  if (t.array && ta) w = ta->width(), h = ta->height();
  if (cube && tc) w = h = tc->size();
  const bool implicit = !t.has_lod && !t.has_grad;
  gpu::SamplerState state = unit ? unit->sampler : gpu::SamplerState{};
  if (t.shadow) state.compare = true;
  for (int l = 0; l < L; ++l) {
    float lod = 0.0f;
    if (t.has_lod) {
      lod = lanef(TexLanes::kLod, l);
    } else if (t.has_grad && cube) {
      lod = gpu::detail::cube_grad_lod({c[0][l], c[1][l], c[2][l]}, lane_vec3(tl, TexLanes::kDx, l),
                                       lane_vec3(tl, TexLanes::kDy, l), w);
    } else if (t.has_grad) {
      const glm::vec3 dx(lanef(TexLanes::kDx, l), spatial >= 2 ? lanef(TexLanes::kDx + 1, l) : 0.0f,
                         d3 ? lanef(TexLanes::kDx + 2, l) : 0.0f);
      const glm::vec3 dy(lanef(TexLanes::kDy, l), spatial >= 2 ? lanef(TexLanes::kDy + 1, l) : 0.0f,
                         d3 ? lanef(TexLanes::kDy + 2, l) : 0.0f);
      lod = d3 ? gpu::detail::lod_from_derivatives_3d(dx, dy, {w, h, d})
               : gpu::detail::lod_from_derivatives(dx.x, dx.y, dy.x, dy.y, w, h);
    } else if (implicit && in_.fragment) {
      // One LOD per 2x2 quad, from its origin and its x and y neighbours.
      const int q = l & ~3;
      const glm::vec3 o(c[0][q], c[1][q], c[2][q]), rx(c[0][q | 1], c[1][q | 1], c[2][q | 1]),
          ry(c[0][q | 2], c[1][q | 2], c[2][q | 2]);
      if (cube)
        lod = gpu::detail::cube_quad_lod(o, rx, ry, w);
      else if (d3)
        lod = gpu::detail::lod_from_derivatives_3d(rx - o, ry - o, {w, h, d});
      else
        lod = gpu::detail::lod_from_derivatives(rx.x - o.x, rx.y - o.y, ry.x - o.x, ry.y - o.y, w, h);
    }
    if (t.has_bias) lod += lanef(TexLanes::kLod, l);
    if (cube) {
      const float v = gpu::detail::sample_cube_compare({tc, state}, c[0][l], c[1][l], c[2][l], c[3][l], lod);
      put(l, glm::vec4(v, v, v, 1.0f));
    } else if (d3) {
      put(l, gpu::detail::sample_3d({t3, state}, c[0][l], c[1][l], c[2][l], lod,
                                    {t.offset[0], t.offset[1], t.offset[2]}));
    } else if (t.shadow) {
      const float v = gpu::detail::sample_2d_array_compare({ta, state}, c[0][l], c[1][l], c[2][l], c[3][l],
                                                           lod, {t.offset[0], t.offset[1]});
      put(l, glm::vec4(v, v, v, 1.0f));
    } else {
      put(l, gpu::detail::sample_2d_array({ta, state}, c[0][l], c[1][l], c[2][l], lod,
                                          {t.offset[0], t.offset[1]}));
    }
  }
}

}  // namespace

// The most common lookup, texture(sampler2D, vec2) with an implicit LOD in a fragment shader
// and a float result: the coordinate rows go to the sixteen-lane sampler and its results to
// the result rows without a pass over single lanes. flatten: the sampler (texture_simd.hpp)
// is inlined here whole, as it is into a C++ shader; run_texture's size kept GCC from it.
// A lane structure's two coordinate rows, and its four result rows.
static gpu::Vec2<gpu::Float16> coord_rows(const TexLanes& tl) {
  return {gpu::Float16::load(reinterpret_cast<const float*>(tl.in[0])),
          gpu::Float16::load(reinterpret_cast<const float*>(tl.in[1]))};
}
static void store_rows(const gpu::Vec4<gpu::Float16>& r, TexLanes& tl) {
  r.x.store(reinterpret_cast<float*>(tl.out[0]));
  r.y.store(reinterpret_cast<float*>(tl.out[1]));
  r.z.store(reinterpret_cast<float*>(tl.out[2]));
  r.w.store(reinterpret_cast<float*>(tl.out[3]));
}
__attribute__((flatten, noinline)) static void texture_2d_rows(const gpu::Sampler2D& s2, TexLanes& tl) {
  if (trilinear_avx512(*s2.texture, s2.state, tl)) return;
  store_rows(gpu::texture(s2, coord_rows(tl)), tl);
}

// Two lane structures' lookups on one texture: thirty-two lanes at once when every quad's LOD
// falls between the same two levels (detail::trilinear32, the bits of two sixteen-lane
// lookups), else one after the other.
__attribute__((flatten, noinline)) static void texture_2d_rows_pair(const gpu::Sampler2D& s2, TexLanes& a,
                                                                    TexLanes& b) {
  if (trilinear_avx512(*s2.texture, s2.state, a, b)) return;
#if defined(__AVX2__)
  gpu::Vec4<gpu::Float16> ra, rb;
  if (gpu::detail::trilinear32(*s2.texture, s2.state, coord_rows(a), coord_rows(b), ra, rb)) {
    store_rows(ra, a);
    store_rows(rb, b);
    return;
  }
#endif
  store_rows(gpu::texture(s2, coord_rows(a)), a);
  store_rows(gpu::texture(s2, coord_rows(b)), b);
}

bool texture_2d_implicit(const ir::TexOp& t) {
  return t.kind == ir::TexKind::Sample && t.dim == ir::SamplerDim::D2 && !t.array && !t.shadow && !t.proj &&
         !t.has_lod && !t.has_bias && !t.has_grad && t.result == 0 && t.offset[0] == 0 && t.offset[1] == 0 &&
         t.offset_reg[0] == ir::TexOp::kNone && t.offset_reg[1] == ir::TexOp::kNone;
}

void run_texture_2d_implicit(const ir::TexOp& t, const RunInputs& in, TexLanes& tl) {
  const TextureUnit* unit = unit_of(t, in);
  if (unit && unit->texture_2d && !unit->swizzled()) {
    texture_2d_rows(gpu::Sampler2D{unit->texture_2d, unit->sampler}, tl);
    return;
  }
  // Any other unit: the general path, which may read the rows the caller did not set.
  for (int k = TexLanes::kCoord + 2; k < TexLanes::kRows; ++k) std::memset(tl.in[k], 0, sizeof tl.in[k]);
  run_texture(t, in, tl);
}

void run_texture_2d_implicit_pair(const ir::TexOp& t, const RunInputs& in, TexLanes& a, TexLanes& b) {
  const TextureUnit* unit = unit_of(t, in);
  if (unit && unit->texture_2d && !unit->swizzled()) {
    texture_2d_rows_pair(gpu::Sampler2D{unit->texture_2d, unit->sampler}, a, b);
    return;
  }
  run_texture_2d_implicit(t, in, a);
  run_texture_2d_implicit(t, in, b);
}

static void run_texture_unswizzled(const ir::TexOp& t, const RunInputs& in_, TexLanes& tl);

// The lookup, then the unit's swizzle (GL 3.3 §3.8.14): on sampled and fetched texels, not on
// textureSize's.
void run_texture(const ir::TexOp& t, const RunInputs& in_, TexLanes& tl) {
  run_texture_unswizzled(t, in_, tl);
  if (t.kind == ir::TexKind::Size) return;
  const TextureUnit* unit = unit_of(t, in_);
  if (!unit || !unit->swizzled()) return;
  alignas(64) uint32_t src[4][ir::kLanes];
  std::memcpy(src, tl.out, sizeof src);
  const uint32_t one = t.result == 0 ? 0x3F800000u : 1u;
  for (int k = 0; k < 4; ++k) {
    const uint8_t sw = unit->swizzle[size_t(k)];
    for (int l = 0; l < L; ++l) tl.out[k][l] = sw < 4 ? src[sw][l] : (sw == 4 ? 0u : one);
  }
}

static void run_texture_unswizzled(const ir::TexOp& t, const RunInputs& in_, TexLanes& tl) {
  if (in_.fragment && texture_2d_implicit(t)) {
    const TextureUnit* unit = unit_of(t, in_);
    if (unit && unit->texture_2d && !unit->swizzled()) {
      texture_2d_rows(gpu::Sampler2D{unit->texture_2d, unit->sampler}, tl);
      return;
    }
  }
  auto lanef = [&](int k, int l) { return f(tl.in[k][l]); };
  auto lanei = [&](int k, int l) { return s(tl.in[k][l]); };
  const TextureUnit* unit = unit_of(t, in_);
  if (t.dim == ir::SamplerDim::D3 || t.dim == ir::SamplerDim::Buffer || t.array ||
      (t.dim == ir::SamplerDim::Cube && t.shadow)) {
    run_texture_layered(t, unit, in_, tl);
    return;
  }
  const gpu::Texture2D* tex2 = unit ? unit->texture_2d : nullptr;
  const gpu::TextureCube* cube = unit ? unit->texture_cube : nullptr;
  const glm::vec4 missing(0.0f, 0.0f, 0.0f, 1.0f);
  const bool present = t.dim == ir::SamplerDim::Cube ? cube != nullptr : tex2 != nullptr;
  auto put = [&](const ir::TexOp& op, int l, const glm::vec4& v) {
    for (int k = 0; k < 4; ++k) tl.out[k][l] = op.result == 0 ? u(v[k]) : integer_texel(v, k, present);
  };
  if (t.kind == ir::TexKind::Size) {
    for (int l = 0; l < L; ++l) {
      const int level = lanei(TexLanes::kLod, l);
      glm::ivec2 sz(0);
      if (t.dim == ir::SamplerDim::Cube) {
        if (cube && level >= 0 && level < cube->levels())
          sz = glm::ivec2(cube->face(0).width(level), cube->face(0).height(level));
      } else if (tex2 && level >= 0 && level < tex2->levels()) {
        sz = glm::ivec2(tex2->width(level), tex2->height(level));
      }
      tl.out[0][l] = uint32_t(sz.x);
      tl.out[1][l] = uint32_t(sz.y);
      tl.out[2][l] = tl.out[3][l] = 0;
    }
    return;
  }
  if (t.kind == ir::TexKind::Fetch) {
    for (int l = 0; l < L; ++l) {
      const int x = lanei(0, l) + t.offset[0] + lanei(TexLanes::kOffset + 0, l);
      const int y =
          t.dim == ir::SamplerDim::D1 ? 0 : lanei(1, l) + t.offset[1] + lanei(TexLanes::kOffset + 1, l);
      put(t, l, gpu::detail::texel_fetch(tex2, x, y, lanei(TexLanes::kLod, l)));
    }
    return;
  }
  if (t.dim == ir::SamplerDim::Cube) {
    if (!cube) {
      for (int l = 0; l < L; ++l) put(t, l, missing);
      return;
    }
    gpu::SamplerCube sc{cube, unit->sampler};
    if (in_.fragment && !t.has_lod && !t.has_grad) {
      gpu::Vec3<gpu::Float16> dir;
      for (int l = 0; l < L; ++l) {
        dir.x[l] = lanef(0, l);
        dir.y[l] = lanef(1, l);
        dir.z[l] = lanef(2, l);
      }
      if (t.has_bias) sc.state.lod_bias += lanef(TexLanes::kLod, 0);
      const gpu::Vec4<gpu::Float16> r = gpu::texture(sc, dir);
      for (int l = 0; l < L; ++l) put(t, l, glm::vec4(r.x[l], r.y[l], r.z[l], r.w[l]));
    } else {
      for (int l = 0; l < L; ++l) {
        const glm::vec3 dir = lane_vec3(tl, 0, l);
        const float lod = t.has_grad
                              ? gpu::detail::cube_grad_lod(dir, lane_vec3(tl, TexLanes::kDx, l),
                                                           lane_vec3(tl, TexLanes::kDy, l), cube->size())
                          : t.has_lod ? lanef(TexLanes::kLod, l)
                                      : 0.0f;
        put(t, l, gpu::detail::sample_cube(sc, dir.x, dir.y, dir.z, lod));
      }
    }
    return;
  }
  // 1D, 2D and rectangle textures (a 1D texture is a 2D texture one texel high).
  if (!tex2) {
    for (int l = 0; l < L; ++l) put(t, l, t.shadow ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) : missing);
    return;
  }
  alignas(64) float uu[L], vv[L], ref[L];
  const bool d1 = t.dim == ir::SamplerDim::D1;
  const float w0 = float(tex2->width()), h0 = float(tex2->height());
  for (int l = 0; l < L; ++l) {
    float x = lanef(0, l), y = d1 ? 0.5f : lanef(1, l);
    float r = 0.0f;
    if (t.shadow) r = lanef(2, l);  // (s, t, ref) for 2D; (s, unused, ref) for 1D
    if (t.proj) {                   // times the reciprocal, as llvmpipe projects
      const float q = 1.0f / lanef(t.coords - 1, l);
      x *= q;
      if (!d1) y *= q;
      r *= q;
    }
    if (t.dim == ir::SamplerDim::Rect) {
      x /= w0;
      y /= h0;
    }
    uu[l] = x;
    vv[l] = y;
    ref[l] = r;
  }
  const bool implicit = !t.has_lod && !t.has_grad;
  // textureOffset: whole texels of each level sampled (1D: s only).
  const glm::ivec2 offset(t.offset[0], d1 ? 0 : t.offset[1]);
  if (t.shadow) {
    gpu::Sampler2DShadow ss{tex2, unit->sampler};
    ss.state.compare = true;
    for (int l = 0; l < L; ++l) {
      float lod = t.has_lod ? lanef(TexLanes::kLod, l) : 0.0f;
      if (implicit && in_.fragment) {
        const int q = l & ~3;
        lod = gpu::detail::lod_from_derivatives(uu[q | 1] - uu[q], vv[q | 1] - vv[q], uu[q | 2] - uu[q],
                                                vv[q | 2] - vv[q], tex2->width(), tex2->height());
        if (t.has_bias) lod += lanef(TexLanes::kLod, l);
      }
      const float v = gpu::detail::sample_2d_compare(ss, uu[l], vv[l], ref[l], lod, offset);
      put(t, l, glm::vec4(v, v, v, 1.0f));
    }
    return;
  }
  gpu::Sampler2D s2{tex2, unit->sampler};
  if (implicit && in_.fragment && !t.has_bias && offset == glm::ivec2(0)) {
    const gpu::Vec4<gpu::Float16> r =
        gpu::texture(s2, gpu::Vec2<gpu::Float16>(gpu::Float16::load(uu), gpu::Float16::load(vv)));
    for (int l = 0; l < L; ++l) put(t, l, glm::vec4(r.x[l], r.y[l], r.z[l], r.w[l]));
    return;
  }
  for (int l = 0; l < L; ++l) {
    float lod;
    if (t.has_lod) {
      lod = lanef(TexLanes::kLod, l);
    } else if (t.has_grad) {
      float dx0 = lanef(TexLanes::kDx + 0, l), dx1 = d1 ? 0.0f : lanef(TexLanes::kDx + 1, l);
      float dy0 = lanef(TexLanes::kDy + 0, l), dy1 = d1 ? 0.0f : lanef(TexLanes::kDy + 1, l);
      if (t.dim == ir::SamplerDim::Rect) {
        dx0 /= w0, dy0 /= w0, dx1 /= h0, dy1 /= h0;
      }
      lod = gpu::detail::lod_from_derivatives(dx0, dx1, dy0, dy1, tex2->width(), tex2->height());
    } else if (in_.fragment) {
      const int q = l & ~3;
      lod = gpu::detail::lod_from_derivatives(uu[q | 1] - uu[q], vv[q | 1] - vv[q], uu[q | 2] - uu[q],
                                              vv[q | 2] - vv[q], tex2->width(), tex2->height());
    } else {
      lod = 0.0f;
    }
    if (t.has_bias) lod += lanef(TexLanes::kLod, l);
    put(t, l, gpu::detail::sample_2d(s2, uu[l], vv[l], lod, offset));
  }
}

uint32_t run_stage(const ir::Stage& stage, LaneReg* regs, uint32_t mask, const RunInputs& in) {
  for (const auto& [r, bits] : stage.constants) std::fill(regs[r].u, regs[r].u + ir::kLanes, bits);
  for (const auto& [r, w] : stage.uniforms) {
    const uint32_t v = in.uniform_words ? in.uniforms[std::min(w, in.uniform_words - 1)] : 0;
    std::fill(regs[r].u, regs[r].u + ir::kLanes, v);
  }
  for (const auto& [r, n] : stage.variables) std::memset(regs + r, 0, sizeof(LaneReg) * n);
  Runner run(stage, regs, in);
  run.block(stage.body, mask);
  return run.killed();
}

}  // namespace tessel::glsl
