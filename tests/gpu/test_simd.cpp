// Lane types and GLSL math: the one-lane and eight-lane paths agree, and the functions are
// accurate.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "tessel/gpu/vec.hpp"

using namespace tessel::gpu;

TEST(Lanes, MasksAndSelect) {
  const Mask8 m = Mask8::from_bits(0b10100101);
  EXPECT_EQ(m.bits(), 0b10100101u);
  const Float8 a(1.0f), b(2.0f);
  const Float8 s = select(m, a, b);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(s[i], (0b10100101 >> i) & 1 ? 1.0f : 2.0f);
  EXPECT_TRUE(any(m));
  EXPECT_FALSE(all(m));
  EXPECT_TRUE(none(Mask8(false)));
}

TEST(Lanes, TranscendentalsAreAccurateAndAgreeAcrossWidths) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(-20.0f, 20.0f), pos(1e-6f, 100.0f);
  for (int i = 0; i < 2000; ++i) {
    float x[8], y[8];
    for (int k = 0; k < 8; ++k) {
      x[k] = u(rng);
      y[k] = pos(rng);
    }
    const Float8 X = Float8::load(x), Y = Float8::load(y);
    const Float8 e = exp2(X), l = log2(Y), p = pow(Y, Float8(2.5f)), s = sin(X), c = cos(X);
    for (int k = 0; k < 8; ++k) {
      EXPECT_NEAR(e[k], std::exp2(x[k]), 3e-7f * std::exp2(x[k]));
      EXPECT_NEAR(l[k], std::log2(y[k]), 2e-6f);
      EXPECT_NEAR(p[k], std::pow(y[k], 2.5f), 3e-6f * std::pow(y[k], 2.5f));
      EXPECT_NEAR(s[k], std::sin(x[k]), 2e-6f);
      EXPECT_NEAR(c[k], std::cos(x[k]), 2e-6f);
      // The one-lane path is the same computation.
      EXPECT_EQ(e[k], exp2(x[k]));
      EXPECT_EQ(l[k], log2(y[k]));
      EXPECT_EQ(s[k], tessel::gpu::sin(x[k]));
    }
  }
  EXPECT_EQ(pow(0.0f, 0.0f), 1.0f);
  EXPECT_EQ(pow(0.0f, 3.0f), 0.0f);
  EXPECT_TRUE(std::isinf(log2(0.0f)));
}

TEST(Lanes, GeometricFunctions) {
  const Vec3<float> a(1, 2, 3), b(4, 5, 6);
  EXPECT_EQ(dot(a, b), 32.0f);
  const Vec3<float> c = cross(a, b);
  EXPECT_EQ(c.x, -3.0f);
  EXPECT_EQ(c.y, 6.0f);
  EXPECT_EQ(c.z, -3.0f);
  EXPECT_NEAR(length(normalize(a)), 1.0f, 1e-6f);
  const Vec3<float> r = reflect(Vec3<float>(1, -1, 0), Vec3<float>(0, 1, 0));
  EXPECT_EQ(r.y, 1.0f);
  const Vec3<float> t =
      refract(Vec3<float>(0.8f, -0.6f, 0), Vec3<float>(0, 1, 0), 1.5f);  // total internal reflection
  EXPECT_EQ(t.x, 0.0f);
  EXPECT_EQ(floor(-1.5f), -2.0f);
  EXPECT_EQ(fract(-1.25f), 0.75f);
  EXPECT_EQ(smoothstep(0.0f, 1.0f, 0.5f), 0.5f);
  EXPECT_EQ(clamp(Float8(3.0f), Float8(0.0f), Float8(1.0f))[0], 1.0f);
}

// floor on lanes is one rounding instruction: it must agree with std::floor everywhere,
// including halves, values at and beyond 2^23, the largest floats, infinities and NaN.
TEST(Lanes, FloorMatchesStdFloor) {
  const float v[] = {-2.5f, -1.5f,    -0.5f,   -0.0f,      0.0f,        0.49999997f, 0.5f,
                     1.0f,  2.99999f, -1e-30f, 8388607.5f, -8388607.5f, 8388608.0f,  -8388609.0f,
                     1e20f, -1e20f,   3.4e38f, -3.4e38f,   1.0f / 0.0f, -1.0f / 0.0f};
  for (float x : v) {
    Float8 a(1.0f);
    a[3] = x;
    const float f = floor(a)[3];
    EXPECT_EQ(std::signbit(f), std::signbit(std::floor(x))) << x;
    EXPECT_EQ(f, std::floor(x)) << x;
  }
  EXPECT_TRUE(std::isnan(floor(Float8(std::numeric_limits<float>::quiet_NaN()))[0]));
}

TEST(Lanes, DerivativesAreQuadDifferences) {
  // Lane i is pixel (2*(i/4) + (i&1), (i>>1)&1) of a 4x2 block; v = 3x + 5y.
  Float8 v;
  for (int i = 0; i < 8; ++i) v[i] = 3.0f * float(2 * (i / 4) + (i & 1)) + 5.0f * float((i >> 1) & 1);
  const Float8 dx = dFdx(v), dy = dFdy(v);
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(dx[i], 3.0f);
    EXPECT_EQ(dy[i], 5.0f);
  }
}

// Sixteen lanes are two halves of eight: every function gives, lane for lane, what the
// one-lane path gives (so 16-lane shading of an 8x2 block matches two 8-lane groups).
TEST(Lanes, SixteenLanesAgreeWithOneLane) {
  const Mask16 m = Mask16::from_bits(0xA53Cu);
  EXPECT_EQ(m.bits(), 0xA53Cu);
  EXPECT_TRUE(any(m));
  EXPECT_FALSE(all(m));
  EXPECT_TRUE(all(Mask16(true)));
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.001f, 8.0f);
  Float16 x, y;
  for (int i = 0; i < 16; ++i) {
    x[i] = u(rng);
    y[i] = u(rng) - 4.0f;
  }
  const Float16 s = select(m, x, y), p = pow(x, Float16(32.0f)), e = exp2(y), l = log2(x), r = inversesqrt(x);
  const Float16 f = fma(x, y, Float16(1.5f)), fl = floor(y);
  const Int16 bits = bits_of(x);
  for (int i = 0; i < 16; ++i) {
    EXPECT_EQ(s[i], (0xA53Cu >> i) & 1 ? x[i] : y[i]) << i;
    EXPECT_EQ(p[i], pow(x[i], 32.0f)) << i;
    EXPECT_EQ(e[i], exp2(y[i])) << i;
    EXPECT_EQ(l[i], log2(x[i])) << i;
    EXPECT_EQ(r[i], inversesqrt(x[i])) << i;
    EXPECT_EQ(f[i], fma(x[i], y[i], 1.5f)) << i;
    EXPECT_EQ(fl[i], std::floor(y[i])) << i;
    EXPECT_EQ(bits[i], bits_of(x[i])) << i;
    EXPECT_NEAR(r[i], 1.0f / std::sqrt(x[i]), 3e-7f * r[i]) << i;
  }
  // Derivatives: within each 2x2 quad of each 4x2 half.
  Float16 v;
  for (int i = 0; i < 16; ++i) v[i] = float(i * i);
  const Float16 dx = dFdx(v), dy = dFdy(v);
  EXPECT_EQ(dx[8], 81.0f - 64.0f);
  EXPECT_EQ(dx[14], 225.0f - 196.0f);
  EXPECT_EQ(dy[9], 121.0f - 81.0f);
  EXPECT_EQ(dy[12], 196.0f - 144.0f);
}

// A whole-number exponent shared by all lanes takes repeated squaring; other exponents the
// exp2/log2 route. Both are accurate, and one lane agrees with eight.
TEST(Lanes, PowWithWholeExponents) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (float e : {1.0f, 2.0f, 5.0f, 32.0f, 64.0f, 2.5f, 65.0f}) {
    Float8 x;
    for (int i = 0; i < 8; ++i) x[i] = u(rng);
    const Float8 p = pow(x, Float8(e));
    for (int i = 0; i < 8; ++i) {
      const float want = std::pow(x[i], e);
      EXPECT_NEAR(p[i], want, 4e-6f * want + 1e-30f) << "x " << x[i] << " e " << e;
      EXPECT_EQ(p[i], pow(x[i], e)) << "one lane and eight differ at e " << e;
    }
  }
  EXPECT_EQ(pow(0.0f, 32.0f), 0.0f);
  EXPECT_EQ(pow(0.5f, 1.0f), 0.5f);
  // Exponents that differ between lanes use the general route.
  Float8 y(32.0f);
  y[3] = 8.0f;
  const Float8 p = pow(Float8(0.9f), y);
  EXPECT_NEAR(p[3], std::pow(0.9f, 8.0f), 1e-6f);
  EXPECT_NEAR(p[0], std::pow(0.9f, 32.0f), 1e-6f);
}
