// Vertex fetch: reads each attribute of a vertex from its buffer and converts it to floats
// (GL 4.6 §10.2 and §2.3.5.1 for normalized integers). Ranges are validated once per draw
// (validate_vertex_range), so the fetch itself never reads out of bounds.
#include <algorithm>
#include <cstring>
#include <string>

#if defined(__SSE4_1__)
#include <immintrin.h>
#endif

#include "stages.hpp"

namespace tessel::gpu {

size_t attrib_type_size(AttribType t) {
  switch (t) {
    case AttribType::F32:
    case AttribType::I32:
    case AttribType::U32: return 4;
    case AttribType::F16:
    case AttribType::I16:
    case AttribType::U16: return 2;
    case AttribType::I8:
    case AttribType::U8: return 1;
  }
  return 4;
}

void Buffer::update(size_t offset, const void* data, size_t bytes) {
  if (offset > data_.size() || bytes > data_.size() - offset)
    throw Error("Buffer::update: range [" + std::to_string(offset) + ", " + std::to_string(offset + bytes) +
                ") is past the end of a buffer of " + std::to_string(data_.size()) + " bytes");
  before_write();
  max_cache_.clear();
  if (bytes) std::memcpy(data_.data() + offset, data, bytes);
}

uint32_t Buffer::max_u32(size_t offset, size_t count) const {
  for (const RangeMax& r : max_cache_)
    if (r.offset == offset && r.count == count) return r.max;
  const std::byte* p = data_.data() + offset;
  uint32_t m = 0;
  for (size_t i = 0; i < count; ++i) {
    uint32_t v;
    std::memcpy(&v, p + 4 * i, 4);
    m = std::max(m, v);
  }
  if (max_cache_.size() >= 1024) max_cache_.clear();  // bounded: ranges of many different draws
  max_cache_.push_back({offset, count, m});
  return m;
}

namespace detail {
namespace {

template <class T>
inline T read(const std::byte* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

float component(const VertexAttrib& a, const std::byte* p) {
  switch (a.type) {
    case AttribType::F32: return read<float>(p);
    case AttribType::F16: return half_to_float(read<uint16_t>(p));
    case AttribType::I8: {
      const float v = read<int8_t>(p);
      return a.normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case AttribType::U8: {
      const float v = read<uint8_t>(p);
      return a.normalized ? v / 255.0f : v;
    }
    case AttribType::I16: {
      const float v = read<int16_t>(p);
      return a.normalized ? std::max(v / 32767.0f, -1.0f) : v;
    }
    case AttribType::U16: {
      const float v = read<uint16_t>(p);
      return a.normalized ? v / 65535.0f : v;
    }
    case AttribType::I32: {
      const double v = read<int32_t>(p);
      return float(a.normalized ? std::max(v / 2147483647.0, -1.0) : v);
    }
    case AttribType::U32: {
      const double v = read<uint32_t>(p);
      return float(a.normalized ? v / 4294967295.0 : v);
    }
  }
  return 0.0f;
}

int32_t integer_component(const VertexAttrib& a, const std::byte* p) {
  switch (a.type) {
    case AttribType::I8: return read<int8_t>(p);
    case AttribType::U8: return read<uint8_t>(p);
    case AttribType::I16: return read<int16_t>(p);
    case AttribType::U16: return read<uint16_t>(p);
    case AttribType::I32: return read<int32_t>(p);
    case AttribType::U32: return int32_t(read<uint32_t>(p));
    case AttribType::F32: return int32_t(read<float>(p));
    case AttribType::F16: return int32_t(half_to_float(read<uint16_t>(p)));
  }
  return 0;
}

uint32_t effective_stride(const VertexAttrib& a, const VertexBinding& b) {
  return b.stride ? b.stride : uint32_t(attrib_type_size(a.type) * size_t(a.components));
}

// One enabled attribute of the element at p, as fetch_attributes gives it.
void fetch_one(const VertexAttrib& a, const std::byte* p, float out[4]) {
  const size_t cs = attrib_type_size(a.type);
  if (a.integer) {
    int32_t v[4] = {0, 0, 0, 1};
    for (int c = 0; c < a.components; ++c) v[c] = integer_component(a, p + c * cs);
    std::memcpy(out, v, sizeof v);
  } else {
    float v[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    for (int c = 0; c < a.components; ++c) v[c] = component(a, p + c * cs);
    std::memcpy(out, v, sizeof v);
  }
}

// --- eight vertices at once -------------------------------------------------------------------
using f32x4 = float __attribute__((vector_size(16)));
using f32x8 = float __attribute__((vector_size(32)));
static_assert(sizeof(Float8) == sizeof(f32x8));

inline void store_lanes(Float8& dst, f32x8 v) { std::memcpy(&dst, &v, sizeof v); }

// Eight rows (x, y, z, w), one per lane, into the four lane vectors of `out`. Moves only, so
// every bit pattern (integer attributes) survives.
inline void transpose_store(const f32x4 (&r)[8], Vec4<Float8>& out) {
  const f32x8 a0 = __builtin_shufflevector(r[0], r[4], 0, 1, 2, 3, 4, 5, 6, 7);
  const f32x8 a1 = __builtin_shufflevector(r[1], r[5], 0, 1, 2, 3, 4, 5, 6, 7);
  const f32x8 a2 = __builtin_shufflevector(r[2], r[6], 0, 1, 2, 3, 4, 5, 6, 7);
  const f32x8 a3 = __builtin_shufflevector(r[3], r[7], 0, 1, 2, 3, 4, 5, 6, 7);
  // t0 = x0 x1 y0 y1 | x4 x5 y4 y5, t1 = z0 z1 w0 w1 | z4 z5 w4 w5; t2, t3 the same for 2, 3, 6, 7.
  const f32x8 t0 = __builtin_shufflevector(a0, a1, 0, 8, 1, 9, 4, 12, 5, 13);
  const f32x8 t1 = __builtin_shufflevector(a0, a1, 2, 10, 3, 11, 6, 14, 7, 15);
  const f32x8 t2 = __builtin_shufflevector(a2, a3, 0, 8, 1, 9, 4, 12, 5, 13);
  const f32x8 t3 = __builtin_shufflevector(a2, a3, 2, 10, 3, 11, 6, 14, 7, 15);
  store_lanes(out.x, __builtin_shufflevector(t0, t2, 0, 1, 8, 9, 4, 5, 12, 13));
  store_lanes(out.y, __builtin_shufflevector(t0, t2, 2, 3, 10, 11, 6, 7, 14, 15));
  store_lanes(out.z, __builtin_shufflevector(t1, t3, 0, 1, 8, 9, 4, 5, 12, 13));
  store_lanes(out.w, __builtin_shufflevector(t1, t3, 2, 3, 10, 11, 6, 7, 14, 15));
}

// The same four values in every lane.
inline void broadcast_store(const float v[4], Vec4<Float8>& out) {
  f32x4 r;
  std::memcpy(&r, v, sizeof r);
  store_lanes(out.x, __builtin_shufflevector(r, r, 0, 0, 0, 0, 0, 0, 0, 0));
  store_lanes(out.y, __builtin_shufflevector(r, r, 1, 1, 1, 1, 1, 1, 1, 1));
  store_lanes(out.z, __builtin_shufflevector(r, r, 2, 2, 2, 2, 2, 2, 2, 2));
  store_lanes(out.w, __builtin_shufflevector(r, r, 3, 3, 3, 3, 3, 3, 3, 3));
}

// C floats per lane read straight from memory; the rest (0, 0, 0, 1).
// Built in registers: a row written in parts to memory and read back whole would wait for
// each part's store to retire (a failed store-to-load forward), for every lane.
template <int C>
inline f32x4 load_row(const std::byte* p) {
#if defined(__SSE4_1__)
  if constexpr (C == 4) return f32x4(_mm_loadu_ps(reinterpret_cast<const float*>(p)));
  const __m128 one = _mm_set_ss(1.0f);
  if constexpr (C == 1)
    return f32x4(_mm_insert_ps(_mm_load_ss(reinterpret_cast<const float*>(p)), one, 0x30));
  const __m128 xy = _mm_castpd_ps(_mm_load_sd(reinterpret_cast<const double*>(p)));
  if constexpr (C == 2) return f32x4(_mm_insert_ps(xy, one, 0x30));
  const __m128 xyz = _mm_insert_ps(xy, _mm_load_ss(reinterpret_cast<const float*>(p) + 2), 0x20);
  return f32x4(_mm_insert_ps(xyz, one, 0x30));
#else
  f32x4 r = {0.0f, 0.0f, 0.0f, 1.0f};
  std::memcpy(&r, p, sizeof(float) * C);
  return r;
#endif
}

template <int C>
inline void fetch_f32(const std::byte* base, size_t stride, const uint32_t (&ids)[kLanes],
                      Vec4<Float8>& out) {
  f32x4 r[kLanes];
  for (int l = 0; l < kLanes; ++l) r[l] = load_row<C>(base + size_t(ids[l]) * stride);
  transpose_store(r, out);
}

}  // namespace

void fetch_attributes(const VertexLayout& layout, uint32_t id, uint32_t instance, float out[][4]) {
  for (int i = 0; i < kMaxVertexAttribs; ++i) {
    const VertexAttrib& a = layout.attribs[i];
    if (!a.enabled) {
      std::memcpy(out[i], layout.current[i].data(), sizeof(float) * 4);
      continue;
    }
    const VertexBinding& b = layout.bindings[a.binding];
    const uint32_t element = b.divisor ? instance / b.divisor : id;
    fetch_one(a, b.buffer->data() + b.offset + a.offset + size_t(element) * effective_stride(a, b), out[i]);
  }
}

void fetch_attributes8(const VertexLayout& layout, const uint32_t* ids, int n, uint32_t instance,
                       VertexIn<Float8>& in, bool per_vertex_only) {
  uint32_t lane[kLanes];
  for (int l = 0; l < kLanes; ++l) {
    lane[l] = ids[std::min(l, n - 1)];
    in.vertex_id[l] = int32_t(lane[l]);
    in.instance_id[l] = int32_t(instance);
  }
  for (int i = 0; i < kMaxVertexAttribs; ++i) {
    const VertexAttrib& a = layout.attribs[i];
    Vec4<Float8>& out = in.attr[size_t(i)];
    if (per_vertex_only && (!a.enabled || layout.bindings[a.binding].divisor)) continue;
    if (!a.enabled) {
      broadcast_store(layout.current[size_t(i)].data(), out);
      continue;
    }
    const VertexBinding& b = layout.bindings[a.binding];
    const size_t stride = effective_stride(a, b);
    const std::byte* base = b.buffer->data() + b.offset + a.offset;
    if (b.divisor) {  // one element for the whole instance
      float v[4];
      fetch_one(a, base + size_t(instance / b.divisor) * stride, v);
      broadcast_store(v, out);
      continue;
    }
    if (a.type == AttribType::F32 && !a.integer) {
      switch (a.components) {
        case 1: fetch_f32<1>(base, stride, lane, out); continue;
        case 2: fetch_f32<2>(base, stride, lane, out); continue;
        case 3: fetch_f32<3>(base, stride, lane, out); continue;
        case 4: fetch_f32<4>(base, stride, lane, out); continue;
        default: break;
      }
    }
    f32x4 r[kLanes];
    for (int l = 0; l < kLanes; ++l) {
      float v[4];
      fetch_one(a, base + size_t(lane[l]) * stride, v);
      std::memcpy(&r[l], v, sizeof v);
    }
    transpose_store(r, out);
  }
}

void validate_vertex_range(const VertexLayout& layout, uint32_t max_id, uint32_t instance_end,
                           uint32_t required_attribs) {
  for (int i = 0; i < kMaxVertexAttribs; ++i) {
    const VertexAttrib& a = layout.attribs[i];
    const std::string where = "vertex attribute " + std::to_string(i);
    if (!a.enabled) {
      if (required_attribs & (1u << i))
        throw Error(where + " is read by the shader but not enabled in the vertex layout");
      continue;
    }
    if (a.components < 1 || a.components > 4)
      throw Error(where + ": " + std::to_string(a.components) + " components (1 to 4 allowed)");
    if (a.binding < 0 || a.binding >= kMaxVertexBindings)
      throw Error(where + ": binding " + std::to_string(a.binding) + " out of range");
    const VertexBinding& b = layout.bindings[a.binding];
    if (!b.buffer) throw Error(where + ": binding " + std::to_string(a.binding) + " has no buffer");
    const size_t size = attrib_type_size(a.type) * size_t(a.components);
    const size_t stride = effective_stride(a, b);
    const uint64_t elements =
        b.divisor ? (instance_end == 0 ? 0 : (instance_end - 1) / b.divisor + 1) : uint64_t(max_id) + 1;
    if (elements == 0) continue;
    if (a.integer && (a.type == AttribType::F32 || a.type == AttribType::F16))
      throw Error(where + ": an integer attribute must have an integer type");
    // Overflow-safe end of the last element read.
    uint64_t end = 0;
    const bool overflow = __builtin_add_overflow(uint64_t(b.offset), uint64_t(a.offset), &end) ||
                          __builtin_add_overflow(end, (elements - 1) * uint64_t(stride), &end) ||
                          __builtin_add_overflow(end, uint64_t(size), &end);
    if (overflow || end > b.buffer->size())
      throw Error(where + ": reading " + std::to_string(elements) + (b.divisor ? " instances" : " vertices") +
                  " needs " + (overflow ? std::string("more") : std::to_string(end)) +
                  " bytes but the buffer has " + std::to_string(b.buffer->size()));
  }
}

}  // namespace detail
}  // namespace tessel::gpu
