// Vertex fetch: every attribute type, normalization, integer attributes, strides, offsets,
// divisors, defaults for missing components and disabled attributes.
#include <gtest/gtest.h>

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
  EXPECT_EQ(out[0][2], 0.0f);   // missing components: (0, 0, 0, 1)
  EXPECT_EQ(out[0][3], 1.0f);
  EXPECT_EQ(out[1][1], 1.0f);
  EXPECT_EQ(out[2][0], -1.0f);
  EXPECT_EQ(out[3][1], 65535.0f);  // not normalized: the integer value as float
  EXPECT_EQ(out[4][0], 1.5f);
  int32_t iv;
  std::memcpy(&iv, &out[5][0], 4);
  EXPECT_EQ(iv, -7);               // integer attribute: the bits
  EXPECT_EQ(out[6][2], 3.0f);
  EXPECT_EQ(out[7][0], 9.0f);      // disabled: the current value
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
