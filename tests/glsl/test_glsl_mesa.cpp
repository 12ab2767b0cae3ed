// The same GLSL on Tessel and on Mesa llvmpipe, into RGBA32F targets, compared value for
// value with a tolerance stated per case. The cases are generated from tables: built-in
// functions across their domains, operators on each type, divergent control flow, arrays,
// structs, matrices, derivatives, textures and flat integers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>

#include "mesa_case.hpp"

namespace tessel::testing {
namespace {

// --- the tables -------------------------------------------------------------------------------

struct Unary {
  const char* fn;
  float lo, hi;
  Tolerance tol;
};
// Tolerance 0: Tessel evaluates these as llvmpipe does, to the bit (docs/glsl.md). atanh's
// input, 1 + (-0.99 + i step), is reassociated by Mesa's optimizer into (1 - 0.99) + i step,
// which Tessel does not do: a few ulp apart at the ends of its domain.
const Unary kUnary[] = {
    {"sin", -10, 10, {0, 0}},       {"cos", -10, 10, {0, 0}},       {"tan", -1.5f, 1.5f, {0, 0}},
    {"asin", -1, 1, {0, 0}},        {"acos", -1, 1, {0, 0}},        {"atan", -20, 20, {0, 0}},
    {"sinh", -5, 5, {0, 0}},        {"cosh", -5, 5, {0, 0}},        {"tanh", -5, 5, {0, 0}},
    {"asinh", -10, 10, {0, 0}},     {"acosh", 1, 20, {0, 0}},       {"atanh", -0.99f, 0.99f, {0, 2e-6f}},
    {"exp", -20, 20, {0, 0}},       {"log", 0.001f, 1000, {0, 0}},  {"exp2", -30, 30, {0, 0}},
    {"log2", 0.001f, 1000, {0, 0}}, {"sqrt", 0, 1000, {0, 0}},      {"inversesqrt", 0.001f, 1000, {0, 0}},
    {"abs", -10, 10, {0, 0}},       {"sign", -10, 10, {0, 0}},      {"floor", -10, 10, {0, 0}},
    {"ceil", -10, 10, {0, 0}},      {"fract", -10, 10, {0, 0}},     {"trunc", -10, 10, {0, 0}},
    {"roundEven", -10, 10, {0, 0}}, {"radians", -720, 720, {0, 0}}, {"degrees", -10, 10, {0, 0}},
};

struct Binary {
  const char* expr;  // over x (t mapped to [lo, hi]) and y (1 - t mapped)
  float lo, hi;
  Tolerance tol;
};
const Binary kBinary[] = {
    {"pow(abs(x) + 0.01, y * 0.3)", -10, 10, {0, 0}},
    {"atan(x, y)", -10, 10, {0, 0}},
    {"mod(x, y)", -10, 10, {0, 0}},
    {"min(x, y)", -10, 10, {0, 0}},
    {"max(x, y)", -10, 10, {0, 0}},
    {"step(y, x)", -10, 10, {0, 0}},
    {"clamp(x, -2.5, y)", -10, 10, {0, 0}},
    {"mix(x, y, t)", -10, 10, {0, 0}},
    {"smoothstep(-3.0, 4.0, x)", -10, 10, {0, 0}},
    {"x / y", -10, 10, {0, 0}},
    {"x * y - x + y", -10, 10, {0, 0}},
    {"distance(vec2(x, 1.0), vec2(y, -2.0))", -10, 10, {0, 0}},
    {"length(vec3(x, y, 2.0))", -10, 10, {0, 0}},
    {"dot(vec4(x, y, 1.0, 2.0), vec4(y, x, -3.0, 0.5))", -10, 10, {0, 0}},
    {"cross(vec3(x, y, 1.0), vec3(y, 2.0, x)).y", -10, 10, {0, 0}},
    {"normalize(vec3(x, y, 1.0)).x", -10, 10, {0, 0}},
    {"reflect(normalize(vec3(x, y, 1.0)), vec3(0.0, 0.6, 0.8)).z", -10, 10, {1e-6f, 1e-6f}},
    {"refract(normalize(vec3(x, -1.0, y)), vec3(0.0, 1.0, 0.0), 0.66).y", -10, 10, {1e-6f, 1e-5f}},
    {"refract(normalize(vec3(x, -0.1, y)), vec3(0.0, 1.0, 0.0), 1.5).x", -10, 10, {1e-6f, 1e-5f}},
    {"faceforward(vec2(1.0, 2.0), vec2(x, y), vec2(1.0, -1.0)).y", -10, 10, {0, 0}},
    {"float(x < y) + 2.0 * float(x == floor(x)) + 4.0 * float(x >= y)", -10, 10, {0, 0}},
    {"(x > 0.0 ^^ y > 0.0) ? 1.0 : -1.0", -10, 10, {0, 0}},
    {"float(isnan(sqrt(x))) + 2.0 * float(isinf(exp(x * 20.0)))", -10, 10, {0, 0}},
    {"intBitsToFloat(floatBitsToInt(x) ^ int(0x80000000))", -10, 10, {0, 0}},
};

// Integer expressions over i (0..255) and j = 127 - i; results are exact.
const char* kInteger[] = {
    "ivec4(i / 7, i % 7, (i - 128) / 5, (i - 128) % 5)",
    "ivec4(i << 3, (i - 128) >> 2, i & 0x5A, i | 0x81)",
    "ivec4(i ^ 0x3C, ~i, -i, abs(i - 100))",
    "ivec4(min(i, 100), max(i - 50, 7), clamp(i, 20, 200), sign(i - 128))",
    "ivec4(uvec4(uint(i) * 2654435761u >> 20u, uint(i) / 3u, uint(i) % 10u, ~uint(i) >> 24u))",
    "ivec4(i > 100 ? 1 : 0, i == 42 ? 7 : -7, int(float(i) * 0.37), int(-float(i) * 0.51))",
};

// Control flow that differs per lane.
struct Flow {
  const char* name;
  const char* decl;
  const char* body;
};
const Flow kFlow[] = {
    {"nested_if", "",
     "float r = 0.0; if (t < 0.5) { if (t < 0.25) r = 1.0; else r = 2.0; } else if (t > 0.9) r = 3.0; else { "
     "r = 4.0 + t; }\n"
     "  c = vec4(r, t, 0.0, 1.0);"},
    {"loop_per_lane_count", "",
     "float s = 0.0; for (int k = 0; k < i % 17; ++k) s += float(k) * 0.5; c = vec4(s, 0.0, 0.0, 1.0);"},
    {"loop_break_continue", "",
     "float s = 0.0; for (int k = 0; k < 40; ++k) { if (k % 3 == 0) continue; if (k > i % 23) break; s += "
     "float(k); }\n"
     "  c = vec4(s, 0.0, 0.0, 1.0);"},
    {"while_and_do", "",
     "int n = i; int steps = 0; while (n != 1 && steps < 200) { n = (n % 2 == 0) ? n / 2 : 3 * n + 1; "
     "++steps; }\n"
     "  int m = 0; do { m += 3; } while (m < i % 11);\n  c = vec4(float(steps), float(m), 0.0, 1.0);"},
    {"early_return",
     "float f(float x) { if (x < 0.3) return -1.0; for (int k = 0; k < 10; ++k) { if (float(k) > x * 10.0) "
     "return float(k); } return 99.0; }",
     "c = vec4(f(t), f(1.0 - t), 0.0, 1.0);"},
    {"discard", "", "if (i % 3 == 1) discard; c = vec4(t, 1.0, 0.0, 1.0);"},
    {"switch_fallthrough", "",
     "float r = 0.0; switch (i % 6) { case 0: r = 1.0; break; case 1: r = 2.0; case 2: r += 3.0; break; case "
     "4: { r = 5.0; break; } default: r = -1.0; }\n"
     "  c = vec4(r, 0.0, 0.0, 1.0);"},
    {"out_params", "void g(in float a, out float b, inout float cc) { b = a * 2.0; cc += a; }",
     "float b = 0.0, d = 1.0; g(t, b, d); c = vec4(b, d, 0.0, 1.0);"},
    {"local_array_dynamic", "",
     "float a[5]; for (int k = 0; k < 5; ++k) a[k] = float(k * k); a[i % 5] += 0.5; c = vec4(a[i % 5], a[(i "
     "+ 2) % 5], a[i % 7], 1.0);"},
    {"struct_and_array_of_struct", "struct S { vec2 v; float w; }; ",
     "S s[3]; for (int k = 0; k < 3; ++k) s[k] = S(vec2(float(k), t), float(k) * 2.0); S q = s[i % 3];\n"
     "  q.v.y += 1.0; c = vec4(q.v, q.w, float(s[1] == S(vec2(1.0, t), 2.0)));"},
    {"swizzles_and_write_masks", "",
     "vec4 v = vec4(t, 2.0 * t, 3.0, 4.0); v.zx = v.xz; v.yw += vec2(1.0); vec3 w = v.wzy; w.xy = w.yx; c = "
     "vec4(w, v.x);"},
    {"matrix_products", "",
     "mat3 m = mat3(1.0, t, 2.0, 0.5, 3.0, -t, 1.0, 1.0, 4.0); vec3 v = vec3(t, 1.0, -2.0);\n"
     "  vec3 a = m * v; vec3 b = v * m; c = vec4(a.x + b.y, a.y - b.z, a.z, (m * m)[1][2]);"},
    {"matrix_functions", "",
     "mat3 m = mat3(2.0, t, 0.5, 0.25, 3.0, -t, 1.0, 0.5, 4.0); mat3 n = inverse(m);\n"
     "  c = vec4(determinant(m), n[0][1], transpose(m)[2][0], outerProduct(vec2(t, 1.0), vec3(2.0, 3.0, "
     "4.0))[2][0]);"},
    {"mat4_inverse", "",
     "mat4 m = mat4(2.0, t, 0.5, 0.0, 0.25, 3.0, -t, 0.1, 1.0, 0.5, 4.0, 0.2, 0.3, 0.0, 1.0, 1.0);\n"
     "  mat4 n = inverse(m); vec4 v = (m * n) * vec4(1.0, 2.0, 3.0, 4.0); c = vec4(v.x, n[3][0], "
     "determinant(m), matrixCompMult(m, m)[1][1]);"},
    {"derivatives", "",
     "float f = p.x * p.x * 40.0 + p.y * 3.0; c = vec4(dFdx(f), dFdy(f), fwidth(f * p.y), 1.0);"},
    {"ternary_with_effects", "",
     "float a = 1.0; float b = t > 0.5 ? (a += 2.0) : (a -= 1.0); c = vec4(a, b, 0.0, 1.0);"},
    {"short_circuit", "float k = 0.0; bool side(float x) { k += 1.0; return x > 0.7; }",
     "bool r = t > 0.5 && side(t); bool q = t < 0.2 || side(t); c = vec4(float(r), float(q), k, 1.0);"},
    {"const_array", "const float K[4] = float[4](1.0, 10.0, 100.0, 1000.0);",
     "c = vec4(K[i % 4], K[3 - i % 4], 0.0, 1.0);"},
    {"global_initializer", "float g = 3.0; vec2 h = vec2(1.0, 2.0);", "g *= t; c = vec4(g, h, 1.0);"},
};

class Functions : public ::testing::TestWithParam<Unary> {};
TEST_P(Functions, MatchMesa) {
  const Unary& u = GetParam();
  char buf[256];
  // Inputs lo + i * step, rounded the same way on both sides (the step is a float literal).
  const float step = (u.hi - u.lo) / 256.0f;
  std::snprintf(buf, sizeof buf, "float x = %.9g + float(i) * %.9g; c = vec4(%s(x), x, 0.0, 1.0);",
                double(u.lo), double(step), u.fn);
  run_case({u.fn, "", buf, u.tol});
}
INSTANTIATE_TEST_SUITE_P(Glsl, Functions, ::testing::ValuesIn(kUnary),
                         [](const auto& info) { return std::string(info.param.fn); });

class Expressions : public ::testing::TestWithParam<Binary> {};
TEST_P(Expressions, MatchMesa) {
  const Binary& b = GetParam();
  char buf[512];
  const float step = (b.hi - b.lo) / 256.0f;
  std::snprintf(buf, sizeof buf,
                "float x = %.9g + float(i) * %.9g; float y = %.9g + float(255 - i) * %.9g + 0.375;\n  c = "
                "vec4(%s, x, y, 1.0);",
                double(b.lo), double(step), double(b.lo), double(step), b.expr);
  run_case({b.expr, "", buf, b.tol});
}
INSTANTIATE_TEST_SUITE_P(Glsl, Expressions, ::testing::ValuesIn(kBinary),
                         [](const auto& info) { return "e" + std::to_string(info.index); });

class Integers : public ::testing::TestWithParam<const char*> {};
TEST_P(Integers, MatchMesa) {
  std::string body = "int j = 127 - i; ivec4 r = ";
  body += GetParam();
  body += ";\n  c = vec4(r);";
  run_case({GetParam(), "", body, {0, 0}});
}
INSTANTIATE_TEST_SUITE_P(Glsl, Integers, ::testing::ValuesIn(kInteger),
                         [](const auto& info) { return "i" + std::to_string(info.index); });

class ControlFlow : public ::testing::TestWithParam<Flow> {};
TEST_P(ControlFlow, MatchMesa) {
  const Flow& f = GetParam();
  run_case({f.name, f.decl, f.body, {1e-5f, 1e-5f}});
}
INSTANTIATE_TEST_SUITE_P(Glsl, ControlFlow, ::testing::ValuesIn(kFlow),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(GlslMesa, UniformsArraysAndStructsByName) {
  Case c{"uniforms",
         "struct L { vec3 pos; float power; }; uniform L lights[2]; uniform float k[3]; uniform mat4 M; "
         "uniform int n;"
         " uniform bool flag;",
         "vec4 v = M * vec4(t, 1.0, 2.0, 1.0); c = vec4(v.x + k[i % 3], lights[i % 2].pos.y * "
         "lights[1].power, float(n) + v.w,"
         " flag ? 1.0 : 0.0);",
         {1e-6f, 1e-6f}};
  c.uniforms = {{"lights[0].pos", {1, 2, 3}},
                {"lights[1].pos", {4, 5, 6}},
                {"lights[0].power", {0.5f}},
                {"lights[1].power", {2.5f}},
                {"k", {10, 20, 30}},
                {"M", {1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 3, 0, 0.5f, 0.25f, 0, 1}},
                {"n", {}, {7}},
                {"flag", {}, {1}}};
  run_case(c);
}

// A uniform block in std140 (vec3 alignment, arrays of floats on vec4 strides, a row-major
// matrix, a struct, a bool) read with constant and run-time indices, against llvmpipe.
TEST(GlslMesa, UniformBlocksStd140) {
  if (!oracle()) GTEST_SKIP() << "Mesa llvmpipe is not available";
  const char* decl = R"(
struct S { vec2 a; float b; };
layout(std140) uniform Params {
  float f;
  vec3 v;
  float arr[3];
  layout(row_major) mat3 m;
  S s;
  bool flag;
  vec4 tail;
};
uniform Other { vec4 o; } other;)";
  const char* body =
      "vec3 mv = m * vec3(1.0, 2.0, 3.0); c = vec4(f + v.z + arr[i % 3], mv.y, s.a.y + s.b + (flag ? 100.0 : "
      "0.0),"
      " tail.w + other.o.x);";
  reference::GlslDrawSpec spec = quad_spec(kVertex330, fragment330(decl, body));
  // std140 offsets (bytes): f 0, v 16, arr 32/48/64, m 80 (3 rows of vec4 when row-major:
  // 80, 96, 112), s.a 128, s.b 136, flag 144, tail 160; size 176.
  std::vector<float> p(44, 0.0f);
  p[0] = 1.5f;
  p[4] = 0.25f, p[5] = 0.5f, p[6] = 0.75f;
  p[8] = 10, p[12] = 20, p[16] = 30;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) p[size_t(20 + r * 4 + c)] = float(r * 3 + c + 1);
  p[32] = 7, p[33] = 8, p[34] = 9;
  const uint32_t yes = 1;
  std::memcpy(&p[36], &yes, 4);
  p[40] = 1, p[41] = 2, p[42] = 3, p[43] = 4;
  std::vector<uint8_t> bytes(p.size() * 4);
  std::memcpy(bytes.data(), p.data(), bytes.size());
  std::vector<uint8_t> other(16);
  const float o[4] = {1000, 0, 0, 0};
  std::memcpy(other.data(), o, 16);
  spec.uniform_buffers = {{"Params", bytes}, {"Other", other}};
  const reference::GlslResult mesa = oracle()->run(spec);
  ASSERT_TRUE(mesa.ok) << mesa.log;
  const TesselResult ours = run_tessel(spec);
  ASSERT_TRUE(ours.ok) << ours.log;
  const Mismatch mm = compare_floats(ours.outputs[0], mesa.outputs[0], spec.width, {0, 0});
  EXPECT_EQ(mm.count, 0) << mm.first;
  // The reflected layout is std140's.
  auto v = glsl::Shader::compile(glsl::Stage::Vertex, kVertex330);
  auto f = glsl::Shader::compile(glsl::Stage::Fragment, spec.fragment);
  auto prog = glsl::Program::link(*v, *f);
  ASSERT_TRUE(prog->ok()) << prog->info_log();
  const int pi = prog->uniform_block_index("Params");
  ASSERT_GE(pi, 0);
  const glsl::UniformBlock& b = prog->uniform_blocks()[size_t(pi)];
  EXPECT_EQ(b.size, 176);
  std::map<std::string, int> off;
  for (const auto& mb : b.members) off[mb.name] = mb.offset;
  EXPECT_EQ(off["v"], 16);
  EXPECT_EQ(off["arr"], 32);
  EXPECT_EQ(off["m"], 80);
  EXPECT_EQ(off["s.a"], 128);  // struct members down to basic types, as GL names them
  EXPECT_EQ(off["s.b"], 136);
  EXPECT_EQ(off["flag"], 144);
  EXPECT_EQ(off["tail"], 160);
  EXPECT_EQ(prog->uniform_blocks()[size_t(prog->uniform_block_index("Other"))].members[0].name, "Other.o");
}

// Structs and arrays of structs in a uniform block, reflected leaf by leaf under GL's names
// ("ts[1].y"), filled through those offsets and read whole (a struct copied out of the block
// with a bool of value 2 in it, which reads as true), against llvmpipe.
TEST(GlslMesa, UniformBlockStructMembersByLeafName) {
  if (!oracle()) GTEST_SKIP() << "Mesa llvmpipe is not available";
  const char* decl = R"(
struct T { float x; bool b; vec2 y; mat2 m; };
layout(std140) uniform Blk { vec3 head; T ts[2]; } blk;)";
  const char* body =
      "T q = blk.ts[i % 2]; c = vec4(q.x + blk.head.z, q.b ? 1.0 : -1.0, q.y.y + q.m[1][0], float(i));";
  reference::GlslDrawSpec spec = quad_spec(kVertex330, fragment330(decl, body));
  auto v = glsl::Shader::compile(glsl::Stage::Vertex, kVertex330);
  auto f = glsl::Shader::compile(glsl::Stage::Fragment, spec.fragment);
  ASSERT_TRUE(f->ok()) << f->info_log();
  auto prog = glsl::Program::link(*v, *f);
  ASSERT_TRUE(prog->ok()) << prog->info_log();
  const glsl::UniformBlock& b = prog->uniform_blocks()[size_t(prog->uniform_block_index("Blk"))];
  std::map<std::string, const glsl::UniformBlockMember*> m;
  for (const auto& mb : b.members) m[mb.name] = &mb;
  // std140: head 0, ts[0] at 16 (x 16, b 20, y 24, m 32 and 48), ts[1] at 64; size 112.
  ASSERT_EQ(b.size, 112);
  ASSERT_TRUE(m.count("Blk.ts[1].y") && m.count("Blk.ts[0].b") && m.count("Blk.ts[1].m")) << b.members.size();
  EXPECT_EQ(m["Blk.ts[0].x"]->offset, 16);
  EXPECT_EQ(m["Blk.ts[0].b"]->offset, 20);
  EXPECT_EQ(m["Blk.ts[0].y"]->offset, 24);
  EXPECT_EQ(m["Blk.ts[0].m"]->offset, 32);
  EXPECT_EQ(m["Blk.ts[0].m"]->matrix_stride, 16);
  EXPECT_EQ(m["Blk.ts[1].x"]->offset, 64);
  std::vector<uint8_t> bytes(size_t(b.size), 0);
  auto put = [&](const std::string& name, int k, auto value) {
    std::memcpy(&bytes[size_t(m.at(name)->offset + 4 * k)], &value, 4);
  };
  put("Blk.head", 2, 0.5f);
  for (int e = 0; e < 2; ++e) {
    const std::string at = "Blk.ts[" + std::to_string(e) + "].";
    put(at + "x", 0, 1.0f + float(e));
    put(at + "b", 0, uint32_t(e == 0 ? 0 : 2));
    put(at + "y", 1, 10.0f * float(e + 1));
    put(at + "m", 4, 100.0f * float(e + 1));  // column 1, row 0
  }
  spec.uniform_buffers = {{"Blk", bytes}};
  run_spec("block structs", spec, {0, 0});
  const TesselResult ours = run_tessel(spec);
  ASSERT_TRUE(ours.ok) << ours.log;
  EXPECT_EQ(ours.outputs[0][4 * 1 + 1], 1.0f);  // pixel 1: ts[1].b = 2 reads as true
}

// An array of uniform blocks is one block per element ("Light[0]", "Light[1]", each read from
// its own binding point), indexed with constants, against llvmpipe.
TEST(GlslMesa, ArraysOfUniformBlocks) {
  const char* decl = R"(
layout(std140) uniform Light { vec4 colour; float power; } lights[2];
layout(std140) uniform Scale { float k; };)";
  const char* body =
      "c = (i % 2 == 0 ? lights[0].colour * lights[0].power : lights[1].colour * lights[1].power) * k;";
  reference::GlslDrawSpec spec = quad_spec(kVertex330, fragment330(decl, body));
  auto block = [](std::vector<float> v) {
    std::vector<uint8_t> b(32, 0);
    std::memcpy(b.data(), v.data(), v.size() * 4);
    return b;
  };
  spec.uniform_buffers = {{"Light[0]", block({1, 0.5f, 0.25f, 1, 2})},
                          {"Light[1]", block({0, 1, 0.75f, 0.5f, 3})},
                          {"Scale", block({0.5f})}};
  run_spec("uniform block arrays", spec, {0, 0});
  auto v = glsl::Shader::compile(glsl::Stage::Vertex, kVertex330);
  auto f = glsl::Shader::compile(glsl::Stage::Fragment, spec.fragment);
  auto prog = glsl::Program::link(*v, *f);
  ASSERT_TRUE(prog->ok()) << prog->info_log();
  ASSERT_GE(prog->uniform_block_index("Light[1]"), 0);
  EXPECT_NE(prog->uniform_block_index("Light[0]"), prog->uniform_block_index("Light[1]"));
  EXPECT_EQ(prog->uniform_blocks()[size_t(prog->uniform_block_index("Light[1]"))].members[1].name,
            "Light.power");
  // The second element's data reaches the odd pixels: pixel 1 is (0, 1, 0.75, 0.5) * 3 * 0.5.
  const TesselResult ours = run_tessel(spec);
  ASSERT_TRUE(ours.ok) << ours.log;
  EXPECT_EQ(ours.outputs[0][4 + 1], 1.5f);
}

// Structs between the stages (GLSL 1.50 §4.3.4): matched by name and member types, each
// member interpolated as a varying of its own type would be (an integer struct flat), against
// llvmpipe; a struct of another shape in the fragment shader is a link error (glslang names
// the struct).
TEST(GlslMesa, StructVaryings) {
  reference::GlslDrawSpec spec;
  spec.vertex = R"(#version 330
layout(location = 0) in vec2 pos;
struct V { vec3 n; float k; vec2 uv[2]; };
struct I { int a; ivec2 b; };
out V v;
flat out I f;
void main() {
  v.n = vec3(pos, 0.5);
  v.k = pos.x * pos.y;
  v.uv[0] = pos * 2.0;
  v.uv[1] = pos.yx;
  f.a = gl_VertexID * 7;
  f.b = ivec2(gl_VertexID, -gl_VertexID);
  gl_Position = vec4(pos, 0.0, 1.0);
})";
  spec.fragment = R"(#version 330
struct V { vec3 n; float k; vec2 uv[2]; };
struct I { int a; ivec2 b; };
in V v;
flat in I f;
out vec4 c;
void main() { c = vec4(v.n.x + v.uv[1].x, v.k + v.uv[0].y, float(f.a + f.b.x), float(f.b.y)); })";
  spec.attributes.push_back({"pos", 2, {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1}});
  spec.count = 6;
  run_spec("struct varyings", spec, {2e-6f, 2e-6f});
  auto vs = glsl::Shader::compile(glsl::Stage::Vertex, spec.vertex);
  std::string other = spec.fragment;
  other.replace(other.find("float k;"), 8, "vec2 k; ");
  other.replace(other.find("v.k +"), 5, "v.k.x +");
  auto fs = glsl::Shader::compile(glsl::Stage::Fragment, other);
  ASSERT_TRUE(fs->ok()) << fs->info_log();
  auto prog = glsl::Program::link(*vs, *fs);
  EXPECT_FALSE(prog->ok());
  EXPECT_NE(prog->info_log().find("V"), std::string::npos) << prog->info_log();
}

// A user interface block between the stages (GLSL 1.50 §4.3.7): matched by the block's name,
// apart from plain varyings of the same member names, each member interpolated by its own
// qualifier (a triangle with different w's, so smooth and noperspective differ), against
// llvmpipe.
TEST(GlslMesa, InterfaceBlocksBetweenStages) {
  reference::GlslDrawSpec spec;
  spec.vertex = R"(#version 150
in vec4 pos;
out float a;
out Blk { flat float a; noperspective float b; float c; } vs_side;
void main() {
  float v = float(gl_VertexID) + 0.25;
  a = -v;
  vs_side.a = v;
  vs_side.b = v * 2.0;
  vs_side.c = v * 3.0;
  gl_Position = pos;
})";
  spec.fragment = R"(#version 150
in float a;
in Blk { flat float a; noperspective float b; float c; } fs_side;
out vec4 c;
void main() { c = vec4(a, fs_side.a, fs_side.b, fs_side.c); })";
  spec.attributes.push_back({"pos", 4, {-1, -1, 0, 1, 2, -2, 0, 2, -1, 3, 0, 3}});
  spec.count = 3;
  run_spec("interface blocks", spec, {2e-6f, 2e-6f});
}

// An RGBA32F checker texture on unit 0 (red and green ramps, blue alternating), read by the
// uniform sampler `tex`.
reference::GlslTexture checker_texture(int w, int h) {
  reference::GlslTexture t;
  t.width = w;
  t.height = h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      t.data.insert(t.data.end(),
                    {float(x) / float(w), float(y) / float(h), ((x ^ y) & 1) ? 1.0f : 0.25f, 1.0f});
  return t;
}

TEST(GlslMesa, TexelFetchAndSize) {
  Case c{"texelFetch",
         "uniform sampler2D tex;",
         "ivec2 s = textureSize(tex, 0); c = texelFetch(tex, ivec2(i % 8, i / 32), 0) + vec4(0.0, 0.0, 0.0, "
         "float(s.x * 100 + s.y));",
         {0, 0}};
  c.textures = {checker_texture(8, 8)};
  c.uniforms = {{"tex", {}, {0}}};
  run_case(c);
}

TEST(GlslMesa, TextureNearestAndLinear) {
  for (uint32_t filter : {0x2600u, 0x2601u}) {
    Case c{"texture",
           "uniform sampler2D tex;",
           "c = texture(tex, p * 1.7 - 0.3) + textureLod(tex, p.yx, 0.0);",
           {2e-6f, 1e-5f}};
    reference::GlslTexture t = checker_texture(8, 8);
    t.min_filter = t.mag_filter = filter;
    c.textures = {t};
    c.uniforms = {{"tex", {}, {0}}};
    SCOPED_TRACE(filter);
    run_case(c);
  }
}

TEST(GlslMesa, TextureFunctionsOn2D) {
  // Mipmapped linear sampling with explicit LOD, gradients, projection, bias and offsets.
  const char* bodies[] = {
      "c = textureLod(tex, p * 3.0 - 1.0, t * 3.0);",
      "c = textureGrad(tex, p, vec2(t * 0.5, 0.0), vec2(0.0, 0.25));",
      "c = textureProj(tex, vec3(p * 2.0, 2.0)) + textureProj(tex, vec4(p, 0.0, 1.0));",
      "c = texelFetch(tex, ivec2(i % 4, i / 64), 1) + vec4(textureSize(tex, 2), 0.0, 0.0);",
  };
  for (const char* body : bodies) {
    Case c{body, "uniform sampler2D tex;", body, {1e-5f, 1e-5f}};
    reference::GlslTexture tx = checker_texture(16, 16);
    tx.mipmaps = true;
    tx.min_filter = 0x2703;  // GL_LINEAR_MIPMAP_LINEAR
    tx.mag_filter = 0x2601;
    c.textures = {tx};
    c.uniforms = {{"tex", {}, {0}}};
    SCOPED_TRACE(body);
    run_case(c);
  }
}

TEST(GlslMesa, ShadowAndCubeSamplers) {
  {
    Case c{"shadow",
           "uniform sampler2DShadow sm;",
           "float v = texture(sm, vec3(p, t)); c = vec4(v, texture(sm, vec3(p.yx, 0.5)), 0.0, 1.0);",
           {1e-5f, 1e-5f}};
    reference::GlslTexture tx;
    tx.width = 8;
    tx.height = 8;
    tx.internal_format = 0x8CAC;  // GL_DEPTH_COMPONENT32F
    for (int k = 0; k < 64; ++k) tx.data.push_back(float((k * 37) % 64) / 63.0f);
    tx.compare = true;
    tx.min_filter = tx.mag_filter = 0x2601;
    tx.wrap = 0x812F;
    c.textures = {tx};
    c.uniforms = {{"sm", {}, {0}}};
    SCOPED_TRACE("sampler2DShadow");
    run_case(c);
  }
  {
    // Directions with one clearly largest axis (the face of a tie is the implementation's).
    Case c{"cube",
           "uniform samplerCube cm;",
           "c = texture(cm, vec3(p * 2.0 - 1.0, 1.7)) + textureLod(cm, vec3(1.0, p.yx - 0.5), 0.0) +"
           " 2.0 * texture(cm, vec3(p.x - 0.5, -1.3, p.y - 0.5));",
           {1e-5f, 1e-5f}};
    reference::GlslTexture tx;
    tx.target = 0x8513;  // GL_TEXTURE_CUBE_MAP
    tx.width = tx.height = 4;
    for (int f = 0; f < 6; ++f)
      for (int k = 0; k < 16; ++k) {
        tx.data.push_back(float(f) / 5.0f);
        tx.data.push_back(float(k % 4) / 3.0f);
        tx.data.push_back(float(k / 4) / 3.0f);
        tx.data.push_back(1.0f);
      }
    tx.min_filter = tx.mag_filter = 0x2600;
    tx.wrap = 0x812F;
    c.textures = {tx};
    c.uniforms = {{"cm", {}, {0}}};
    SCOPED_TRACE("samplerCube");
    run_case(c);
  }
}

// Flat integer varyings keep every bit (they never pass through a float plane), and
// gl_FrontFacing, gl_FragCoord come from the rasterizer as in llvmpipe.
TEST(GlslMesa, FlatIntegersAndBuiltinInputs) {
  if (!oracle()) GTEST_SKIP() << "Mesa llvmpipe is not available";
  reference::GlslDrawSpec spec;
  spec.vertex = R"(#version 330
layout(location = 0) in vec2 pos;
layout(location = 1) in ivec2 bits;
flat out ivec2 vbits;
void main() { vbits = bits; gl_Position = vec4(pos, 0.0, 1.0); })";
  spec.fragment = R"(#version 330
flat in ivec2 vbits;
out vec4 c;
void main() {
  c = vec4(float(vbits.x & 0xFFFF), float((vbits.x >> 16) & 0xFFFF), float(vbits.y & 0xFF),
           (gl_FrontFacing ? 1.0 : 0.0) + gl_FragCoord.x * 0.001);
})";
  spec.attributes.push_back({"pos", 2, {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1}});
  reference::GlslAttribute b{"bits", 2, {}, true, {}};
  // 0x80000000 (the bits of -0.0) and a signalling-NaN pattern must survive.
  for (int v = 0; v < 6; ++v) b.idata.insert(b.idata.end(), {int32_t(0x80000000u), int32_t(0x7f800001 + v)});
  spec.attributes.push_back(b);
  spec.count = 6;
  const reference::GlslResult mesa = oracle()->run(spec);
  ASSERT_TRUE(mesa.ok) << mesa.log;
  const TesselResult ours = run_tessel(spec);
  ASSERT_TRUE(ours.ok) << ours.log;
  const Mismatch m = compare_floats(ours.outputs[0], mesa.outputs[0], spec.width, {0, 0});
  EXPECT_EQ(m.count, 0) << m.first;
}

// ftransform() in a compatibility vertex shader is the fixed-function transform of gl_Vertex:
// a tilted quad through a perspective projection and a modelview with rotation, the varying
// clip position and gl_FragCoord.z compared with Mesa (to a few ulp: perspective-correct
// interpolation and window z round differently from llvmpipe's, as in the conformance set's
// varyings), and the same for the product written out in the shader.
TEST(GlslMesa, FtransformIsTheFixedFunctionTransform) {
  reference::GlslDrawSpec spec;
  spec.fragment = R"(#version 120
varying vec4 q;
void main() { gl_FragColor = vec4(q.xy / q.w, gl_FragCoord.z, q.w); })";
  spec.attributes.push_back({"gl_Vertex", 4, {-1, -1, 0, 1, 1, -1, 0.3f, 1, 1,  1, 0,     1,
                                              -1, -1, 0, 1, 1, 1,  0,    1, -1, 1, -0.4f, 1}});
  spec.count = 6;
  // Column-major: a rotation about y and a translation back; a GL perspective (fovy 60,
  // aspect 1, near 0.5, far 10).
  const float c = 0.8f, s = 0.6f;
  spec.modelview = {c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0.1f, -0.2f, -3.0f, 1};
  const float f = 1.7320508f, n = 0.5f, fa = 10.0f;
  spec.projection = {f, 0, 0, 0, 0, f, 0, 0, 0, 0, (fa + n) / (n - fa), -1, 0, 0, 2 * fa * n / (n - fa), 0};
  for (const char* position : {"ftransform()", "gl_ModelViewProjectionMatrix * gl_Vertex"}) {
    spec.vertex = std::string("#version 120\nvarying vec4 q;\nvoid main() { gl_Position = ") + position +
                  "; q = gl_Position; }\n";
    run_spec(position, spec, {1e-6f, 1e-6f});
  }
}

// inverse() in GLSL 1.40 (section 8.5; glslang's 1.40 symbol table lacks it, front.cpp
// supplies it) for mat2, mat3 and mat4 against llvmpipe, and a 1.40 shader's own function of
// another name still runs as written. Within 1e-6 relative: Mesa folds and reassociates the
// constant entries' products at compile time (docs/glsl.md); the conformance set checks
// inverse on per-pixel matrices with tolerance 0.
TEST(GlslMesa, Inverse140) {
  const char* vs =
      "#version 140\nin vec2 pos;\nout vec2 p;\nvoid main() { p = pos * 0.5 + 0.5; gl_Position = "
      "vec4(pos, 0.0, 1.0); }\n";
  const std::string fs =
      std::string("#version 140\nin vec2 p;\nout vec4 c;\n") +
      "mat2 twice(mat2 m) { return m * 2.0; }\nvoid main() {\n  float t = p.x + 3.0 * p.y;\n"
      "  mat2 a = inverse(twice(mat2(t, 1.0, 0.5, 2.0)));\n"
      "  mat3 b = inverse(mat3(2.0, t, 0.5, 0.25, 3.0, -t, 1.0, 0.5, 4.0));\n"
      "  mat4 d = inverse(mat4(2.0, t, 0.5, 0.0, 0.25, 3.0, -t, 0.1, 1.0, 0.5, 4.0, 0.2, 0.3, 0.0, "
      "1.0, 1.0));\n"
      "  c = vec4(a[0][1], b[2][0], d[3][1], a[1][1] + b[1][1] + d[0][0]);\n}\n";
  run_spec("inverse 1.40", quad_spec(vs, fs), {0, 1e-6f});
}

// gl_ClipDistance clips triangles, lines and points where its plane is enabled (GL 3.3
// §2.19), and reaches the fragment shader interpolated; a distance written but not enabled
// clips no triangle. Against llvmpipe on 32x32: the cut edges cover the same pixels. (Lines
// and points write only enabled distances: llvmpipe culls them by the others too.)
TEST(GlslMesa, ClipDistancesClipTrianglesLinesAndPoints) {
  if (!oracle()) GTEST_SKIP() << "Mesa llvmpipe is not available";
  auto vertex = [](bool third) {
    return std::string(R"(#version 330
layout(location = 0) in vec2 pos;
out vec2 p;
void main() {
  p = pos;
  gl_Position = vec4(pos, 0.0, 1.0);
  gl_ClipDistance[0] = pos.x + 0.37 * pos.y - 0.113;
  gl_ClipDistance[1] = 0.71 - pos.y - 0.2 * pos.x;
)") + (third ? "  gl_ClipDistance[2] = -1.0;\n" : "") +
           "}\n";
  };
  auto fragment = [](int n) {
    return "#version 330\nin vec2 p;\nin float gl_ClipDistance[" + std::to_string(n) +
           "];\nout vec4 c;\nvoid main() { c = vec4(p, gl_ClipDistance[0], gl_ClipDistance[1] + 2.0); }\n";
  };
  reference::GlslDrawSpec spec;
  spec.width = spec.height = 32;
  spec.clip_distances = 0x3;
  // A full-window quad, whose third distance (-1) is not enabled.
  spec.vertex = vertex(true);
  spec.fragment = fragment(3);
  spec.attributes.push_back({"pos", 2, {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1}});
  spec.count = 6;
  run_spec("clip distances, triangles", spec, {2e-6f, 2e-6f});
  // A fan of lines, and a grid of points (size 1).
  spec.vertex = vertex(false);
  spec.fragment = fragment(2);
  std::vector<float> lines;
  for (int i = 0; i < 12; ++i) {
    const float a = 0.5f * float(i) + 0.1f;
    lines.insert(lines.end(), {-0.05f, 0.02f, 0.93f * std::cos(a), 0.91f * std::sin(a)});
  }
  spec.attributes[0].data = lines;
  spec.primitive = 0x0001;  // GL_LINES
  spec.count = 24;
  {
    // Tessel's width-1 lines and llvmpipe's differ at some ends (the diamond-exit rule, which
    // GL 3.3 §3.5 does not require exactly): one pixel an end is let pass; every other pixel
    // must match. Without the clip distances about 200 pixels would differ.
    const reference::GlslResult mesa = oracle()->run(spec);
    ASSERT_TRUE(mesa.ok) << mesa.log;
    const TesselResult ours = run_tessel(spec);
    ASSERT_TRUE(ours.ok) << ours.log;
    const Mismatch m = compare_floats(ours.outputs[0], mesa.outputs[0], spec.width, {2e-6f, 2e-6f});
    EXPECT_LE(m.count, 4 * 24) << m.first;
  }
  std::vector<float> points;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      points.insert(points.end(),
                    {(float(x) * 2.0f + 0.6f) / 16.0f - 1.0f, (float(y) * 2.0f + 0.4f) / 16.0f - 1.0f});
  spec.attributes[0].data = points;
  spec.primitive = 0x0000;  // GL_POINTS
  spec.count = 256;
  run_spec("clip distances, points", spec, {2e-6f, 2e-6f});
}

// A geometry stage (GLSL 3.30 §8.10): two strips emitted per input triangle (EndPrimitive
// between them), inputs read through gl_in[] and an interface block array, smooth, flat and
// noperspective outputs, and gl_PrimitiveID written for the fragment stage from
// gl_PrimitiveIDIn, against llvmpipe.
TEST(GlslMesa, GeometryStageEmitsStrips) {
  reference::GlslDrawSpec spec;
  spec.width = spec.height = 32;
  spec.vertex = R"(#version 330
layout(location = 0) in vec2 pos;
out V { vec3 colour; flat int id; } v;
void main() {
  v.colour = vec3(fract(float(gl_VertexID) * 0.37), pos * 0.5 + 0.5);
  v.id = gl_VertexID;
  gl_Position = vec4(pos, 0.0, 1.0);
})";
  spec.geometry = R"(#version 330
layout(triangles) in;
layout(triangle_strip, max_vertices = 7) out;
in V { vec3 colour; flat int id; } v[];
out vec3 colour;
flat out int ids;
noperspective out float edge;
void main() {
  vec4 c = (gl_in[0].gl_Position + gl_in[1].gl_Position + gl_in[2].gl_Position) / 3.0;
  ids = v[0].id * 100 + v[1].id * 10 + v[2].id;
  for (int i = 0; i < 3; ++i) {
    gl_Position = mix(c, gl_in[i].gl_Position, 0.8) * vec4(1.0, 1.0, 1.0, 1.0 + 0.2 * float(i));
    colour = v[i].colour;
    edge = float(i);
    gl_PrimitiveID = gl_PrimitiveIDIn * 2;
    EmitVertex();
  }
  EndPrimitive();
  for (int i = 0; i < 4; ++i) {
    gl_Position = c + vec4(float(i & 1) * 0.15 - 0.07, float(i >> 1) * 0.15 - 0.07, 0.0, 0.0);
    colour = vec3(0.25 * float(i));
    edge = 4.0;
    gl_PrimitiveID = gl_PrimitiveIDIn * 2 + 1;
    EmitVertex();
  }
})";
  spec.fragment = R"(#version 330
in vec3 colour;
flat in int ids;
noperspective in float edge;
out vec4 c;
void main() { c = vec4(colour.xy + vec2(edge, 0.0), colour.z + float(ids), float(gl_PrimitiveID)); })";
  spec.attributes.push_back(
      {"pos", 2, {-0.9f, -0.9f, -0.7f, 0.8f, 0.1f, -0.8f, 0.3f, 0.9f, 0.9f, -0.6f, 0.8f, 0.7f}});
  spec.primitive = 0x0005;  // GL_TRIANGLE_STRIP: four triangles, the odd ones listed (1, 0, 2)
  spec.count = 6;
  run_spec("geometry stage strips", spec, {2e-6f, 2e-6f});
  // The first convention of flat outputs would give other ids: the tolerance would see it.
  spec.primitive = 0x0004;  // GL_TRIANGLES: two
  run_spec("geometry stage triangles", spec, {1e-5f, 1e-5f});
}

// The order in which the adjacency topologies give their vertices to gl_in[] (GL 3.3 §2.6.1,
// Table 2.4 for triangle strips), seen as vertex ids that each primitive's quad writes, and a
// geometry stage that emits points with gl_PointSize, against llvmpipe.
TEST(GlslMesa, GeometryStageAdjacencyOrder) {
  auto geometry = [](const char* input, int n) {
    std::string s = std::string("#version 150\nlayout(") + input +
                    ") in;\nlayout(triangle_strip, max_vertices = 4) out;\nflat in int id[];\n"
                    "flat out ivec4 a;\nflat out ivec2 b;\nvoid main() {\n  a = ivec4(";
    for (int i = 0; i < 4; ++i)
      s += (i ? ", " : "") + (i < n ? "id[" + std::to_string(i) + "]" : std::string("-1"));
    s += ");\n  b = ivec2(";
    for (int i = 4; i < 6; ++i)
      s += (i > 4 ? ", " : "") + (i < n ? "id[" + std::to_string(i) + "]" : std::string("-1"));
    s += ");\n"
         "  float x = -1.0 + 0.25 * float(gl_PrimitiveIDIn);\n"
         "  for (int k = 0; k < 4; ++k) {\n"
         "    gl_Position = vec4(x + 0.25 * float(k & 1), -1.0 + 2.0 * float(k >> 1), 0.0, 1.0);\n"
         "    EmitVertex();\n  }\n}\n";
    return s;
  };
  reference::GlslDrawSpec spec;
  spec.width = 32;
  spec.height = 4;
  spec.outputs = 2;
  spec.vertex =
      "#version 150\nin vec2 pos;\nflat out int id;\nvoid main() { id = gl_VertexID; gl_Position = vec4(pos, "
      "0.0, 1.0); }\n";
  spec.fragment =
      "#version 150\nflat in ivec4 a;\nflat in ivec2 b;\nout vec4 c0;\nout vec4 c1;\n"
      "void main() { c0 = vec4(a); c1 = vec4(b, 0.0, 1.0); }\n";
  std::vector<float> pos;
  for (int i = 0; i < 24; ++i) pos.insert(pos.end(), {0.05f * float(i) - 0.6f, (i & 1) ? 0.5f : -0.5f});
  spec.attributes.push_back({"pos", 2, pos});
  struct Case {
    uint32_t primitive;
    int count;
    const char* input;
    int vertices;
  };
  for (const Case& k : {Case{0x000A, 12, "lines_adjacency", 4}, Case{0x000B, 10, "lines_adjacency", 4},
                        Case{0x000C, 18, "triangles_adjacency", 6}, Case{0x000D, 6, "triangles_adjacency", 6},
                        Case{0x000D, 7, "triangles_adjacency", 6}, Case{0x000D, 8, "triangles_adjacency", 6},
                        Case{0x000D, 16, "triangles_adjacency", 6}}) {
    spec.geometry = geometry(k.input, k.vertices);
    spec.primitive = k.primitive;
    spec.count = k.count;
    run_spec("adjacency 0x" + std::to_string(k.primitive) + " count " + std::to_string(k.count), spec,
             {0, 0});
  }
  // Points out, sized by the geometry stage's gl_PointSize.
  spec.width = spec.height = 32;
  spec.outputs = 1;
  spec.geometry = R"(#version 150
layout(points) in;
layout(points, max_vertices = 3) out;
flat in int id[];
flat out ivec4 a;
void main() {
  for (int i = 0; i < 3; ++i) {
    a = ivec4(id[0], i, 0, 1);
    gl_PointSize = 1.0 + 2.0 * float(i);
    gl_Position = gl_in[0].gl_Position + vec4(0.0, 0.3 * float(i), 0.0, 0.0);
    EmitVertex();
  }
})";
  spec.fragment =
      "#version 150\nflat in ivec4 a;\nout vec4 c0;\nvoid main() { c0 = vec4(a) + vec4(gl_PointCoord, 0.0, "
      "0.0); }\n";
  spec.primitive = 0x0000;
  spec.count = 8;
  run_spec("geometry stage points", spec, {1e-5f, 1e-5f});
}

// gl_PointSize (with GL_PROGRAM_POINT_SIZE) sizes each point, clamped to 1..255, and
// gl_PointCoord runs from (0, 0) at the upper left to (1, 1) across it (GL 3.3 §3.4): points
// of sizes 0.5 to 9.5 at and off pixel centres, against llvmpipe.
TEST(GlslMesa, PointSizeAndPointCoord) {
  reference::GlslDrawSpec spec;
  spec.width = spec.height = 64;
  spec.vertex = R"(#version 330
layout(location = 0) in vec3 pos_size;
flat out float s;
void main() {
  s = pos_size.z;
  gl_PointSize = pos_size.z;
  gl_Position = vec4(pos_size.xy, 0.0, 1.0);
})";
  spec.fragment = R"(#version 330
flat in float s;
out vec4 c;
void main() { c = vec4(gl_PointCoord, s, 1.0); })";
  std::vector<float> data;
  for (int k = 0; k < 20; ++k) {
    const float size = 0.5f * float(k) + 0.5f;
    const float x = float(4 + (k % 5) * 12) + (k % 3 == 0 ? 0.5f : k % 3 == 1 ? 0.0f : 0.3f);
    const float y = float(6 + (k / 5) * 15) + (k % 2 ? 0.5f : 0.25f);
    data.insert(data.end(), {x / 32.0f - 1.0f, y / 32.0f - 1.0f, size});
  }
  // Two wide points whose centres are just outside the view volume: discarded whole (GL 3.3
  // §2.20), though they would reach into the window.
  data.insert(data.end(), {-1.03f, 0.2f, 9.5f, 0.3f, 1.02f, 7.5f});
  spec.attributes.push_back({"pos_size", 3, data});
  spec.primitive = 0x0000;
  spec.count = 22;
  run_spec("point size and coordinate", spec, {1e-5f, 1e-5f});
}

// A wrong result must fail: the comparison of a shader against a slightly different one.
TEST(GlslMesa, ToleranceCatchesAWrongResult) {
  if (!oracle()) GTEST_SKIP() << "Mesa llvmpipe is not available";
  reference::GlslDrawSpec spec =
      quad_spec(kVertex330, fragment330("", "c = vec4(sin(t * 6.0), t, 0.0, 1.0);"));
  const reference::GlslResult mesa = oracle()->run(spec);
  ASSERT_TRUE(mesa.ok);
  // sin off by one part in 10^4 (a cheap approximation) is caught by the loosest tolerance of
  // the tables (1e-5 absolute + 1e-5 relative, the control-flow cases); the functions' own
  // tolerance is 0.
  spec.fragment = fragment330("", "c = vec4(sin(t * 6.0) * 1.0001, t, 0.0, 1.0);");
  const TesselResult ours = run_tessel(spec);
  ASSERT_TRUE(ours.ok) << ours.log;
  EXPECT_GT(compare_floats(ours.outputs[0], mesa.outputs[0], 16, {1e-5f, 1e-5f}).count, 0);
  EXPECT_EQ(kUnary[0].tol.abs, 0.0f);
}

}  // namespace
}  // namespace tessel::testing
