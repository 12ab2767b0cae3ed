// Vertex fetch: every attribute type, normalization, integer attributes, strides, offsets,
// divisors, defaults for missing components and disabled attributes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "stages.hpp"
#include "tessel/gpu/buffer.hpp"

using namespace tessel::gpu;
using namespace tessel::gpu::detail;

TEST(VertexFetch, TypesAndNormalization) {
  struct V {
    int8_t i8[2];
    uint8_t u8[2];
    int16_t i16[2];
    uint16_t u16[2];
    uint16_t f16;
    uint16_t pad;
    int32_t i32;
    float f32[3];
  };
  const V v[2] = {{{-128, 127}, {0, 255}, {-32768, 32767}, {0, 65535}, float_to_half(1.5f), 0, -7, {1, 2, 3}},
                  {{64, -64}, {51, 102}, {100, -100}, {1000, 2000}, float_to_half(-0.25f), 0, 9, {4, 5, 6}}};
  const Buffer b(v, sizeof v);
  VertexLayout l;
  const uint32_t s = sizeof(V);
  l.attrib(0, b, 2, AttribType::I8, s, offsetof(V, i8), true);
  l.attrib(1, b, 2, AttribType::U8, s, offsetof(V, u8), true);
  l.attrib(2, b, 2, AttribType::I16, s, offsetof(V, i16), true);
  l.attrib(3, b, 2, AttribType::U16, s, offsetof(V, u16), false);
  l.attrib(4, b, 1, AttribType::F16, s, offsetof(V, f16));
  l.attrib(5, b, 1, AttribType::I32, s, offsetof(V, i32));
  l.attribs[5].integer = true;
  l.attrib(6, b, 3, AttribType::F32, s, offsetof(V, f32));
  l.current[7] = {9, 8, 7, 6};
  float out[kMaxVertexAttribs][4];
  fetch_attributes(l, 0, 0, out);
  EXPECT_EQ(out[0][0], -1.0f);  // -128 clamps to -1 (GL 4.6 eq. 2.2)
  EXPECT_EQ(out[0][1], 1.0f);
  EXPECT_EQ(out[0][2], 0.0f);  // missing components: (0, 0, 0, 1)
  EXPECT_EQ(out[0][3], 1.0f);
  EXPECT_EQ(out[1][1], 1.0f);
  EXPECT_EQ(out[2][0], -1.0f);
  EXPECT_EQ(out[3][1], 65535.0f);  // not normalized: the integer value as float
  EXPECT_EQ(out[4][0], 1.5f);
  int32_t iv;
  std::memcpy(&iv, &out[5][0], 4);
  EXPECT_EQ(iv, -7);  // integer attribute: the bits
  EXPECT_EQ(out[6][2], 3.0f);
  EXPECT_EQ(out[7][0], 9.0f);  // disabled: the current value
  fetch_attributes(l, 1, 0, out);
  EXPECT_NEAR(out[0][0], 64.0f / 127.0f, 1e-7f);
  EXPECT_NEAR(out[1][0], 0.2f, 1e-7f);
  EXPECT_EQ(out[4][0], -0.25f);
  EXPECT_EQ(out[6][0], 4.0f);
}

TEST(VertexFetch, DivisorsAndValidation) {
  const float data[] = {10, 20, 30, 40};
  const Buffer b(data, sizeof data);
  VertexLayout l;
  l.attrib(0, b, 1, AttribType::F32, 0, 0, false, 2);  // one element every 2 instances
  float out[kMaxVertexAttribs][4];
  fetch_attributes(l, 123, 5, out);  // instance 5 -> element 2, whatever the vertex
  EXPECT_EQ(out[0][0], 30.0f);
  EXPECT_NO_THROW(validate_vertex_range(l, 1000000, 8, 0));  // instances 0..7 -> elements 0..3
  EXPECT_THROW(validate_vertex_range(l, 0, 9, 0), Error);    // element 4 is past the end
  VertexLayout p;
  p.attrib(0, b, 2, AttribType::F32, 8, 0);
  EXPECT_NO_THROW(validate_vertex_range(p, 1, 1, 0));
  EXPECT_THROW(validate_vertex_range(p, 2, 1, 0), Error);
  EXPECT_THROW(validate_vertex_range(p, 0, 1, 0b10), Error);  // attribute 1 required, not enabled
}

namespace {

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

// Random bytes (every float bit pattern, NaNs and denormals included).
std::vector<std::byte> random_bytes(size_t n, uint32_t seed) {
  std::vector<std::byte> v(n);
  for (auto& b : v) {
    seed = seed * 1664525u + 1013904223u;
    b = std::byte(seed >> 24);
  }
  return v;
}

// fetch_attributes8 against fetch_attributes, lane by lane and bit for bit.
void expect_same_as_scalar(const VertexLayout& l, const std::vector<uint32_t>& ids, int n,
                           uint32_t instance) {
  VertexIn<Float8> in;
  fetch_attributes8(l, ids.data(), n, instance, in);
  for (int lane = 0; lane < kLanes; ++lane) {
    const uint32_t id = ids[size_t(std::min(lane, n - 1))];
    float want[kMaxVertexAttribs][4];
    fetch_attributes(l, id, instance, want);
    EXPECT_EQ(in.vertex_id[lane], int32_t(id));
    EXPECT_EQ(in.instance_id[lane], int32_t(instance));
    for (int a = 0; a < kMaxVertexAttribs; ++a) {
      const Vec4<Float8>& got = in.attr[size_t(a)];
      const float g[4] = {got.x[lane], got.y[lane], got.z[lane], got.w[lane]};
      for (int c = 0; c < 4; ++c)
        EXPECT_EQ(bits(g[c]), bits(want[a][c])) << "n " << n << " instance " << instance << " lane " << lane
                                                << " location " << a << " component " << c;
    }
  }
}

}  // namespace

TEST(VertexFetch8, MatchesScalarFetchOverMixedLayouts) {
  constexpr uint32_t kVerts = 16, kStride = 52;
  const Buffer inter(random_bytes(kVerts * kStride + 8, 1));  // interleaved, 8 bytes of binding offset
  const Buffer packed(random_bytes(kVerts * 12, 2));          // 3 floats per vertex, tightly packed
  const Buffer per_instance(random_bytes(128, 3));
  VertexLayout l;
  // F32 per vertex: 4, 3 (own buffer, stride 0), 2 and 1 components.
  l.attrib(0, inter, 4, AttribType::F32, kStride, 0);
  l.attrib(1, packed, 3, AttribType::F32, 0, 0);
  l.attrib(2, inter, 2, AttribType::F32, kStride, 16);
  l.attrib(3, inter, 1, AttribType::F32, kStride, 24);
  // F32 per instance, divisor 2; U16 normalized per instance, divisor 1.
  l.attrib(4, per_instance, 2, AttribType::F32, 8, 0, false, 2);
  l.attrib(5, per_instance, 3, AttribType::U16, 0, 40, true, 1);
  // Other types per vertex.
  l.attrib(6, inter, 4, AttribType::U8, kStride, 28, true);  // normalized
  l.attrib(7, inter, 3, AttribType::I16, kStride, 32);       // plain integers as floats
  l.attrib(8, inter, 2, AttribType::I32, kStride, 40);
  l.attribs[8].integer = true;  // integer attribute: the bits
  l.attrib(9, inter, 2, AttribType::F16, kStride, 48);
  l.attrib(10, inter, 1, AttribType::I8, kStride, 50, true);
  l.attrib(11, inter, 4, AttribType::U8, kStride, 28);
  l.attribs[11].integer = true;
  // 12: disabled with a current value; 13..15: disabled, default (0, 0, 0, 1).
  l.current[12] = {9, 8, 7, 6};
  // A binding offset: location 3 reads 4 bytes further on.
  l.bindings[3].offset = 4;
  ASSERT_NO_THROW(validate_vertex_range(l, kVerts - 1, 8, 0));
  const std::vector<uint32_t> ids = {7, 3, 3, 0, 15, 5, 9, 1};
  for (int n : {1, 5, 8})
    for (uint32_t instance : {0u, 1u, 5u, 7u}) expect_same_as_scalar(l, ids, n, instance);
}

TEST(VertexFetch8, LanesPastNRepeatTheLastVertex) {
  const float data[] = {0, 1, 2, 3, 10, 11, 12, 13, 20, 21, 22, 23};
  const Buffer b(data, sizeof data);
  VertexLayout l;
  l.attrib(0, b, 4, AttribType::F32, 0, 0);
  l.current[1] = {5, 6, 7, 8};
  const uint32_t ids[8] = {2, 0, 1, 99, 99, 99, 99, 99};  // only ids[0..3) may be read
  VertexIn<Float8> in;
  fetch_attributes8(l, ids, 3, 4, in);
  const float want_x[8] = {20, 0, 10, 10, 10, 10, 10, 10};
  for (int lane = 0; lane < kLanes; ++lane) {
    EXPECT_EQ(in.attr[0].x[lane], want_x[lane]);
    EXPECT_EQ(in.attr[0].w[lane], want_x[lane] + 3);
    EXPECT_EQ(in.attr[1].y[lane], 6.0f);
    EXPECT_EQ(in.attr[2].w[lane], 1.0f);
    EXPECT_EQ(in.vertex_id[lane], int32_t(ids[std::min(lane, 2)]));
    EXPECT_EQ(in.instance_id[lane], 4);
  }
}
