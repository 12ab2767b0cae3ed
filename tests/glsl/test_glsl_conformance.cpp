// The GLSL conformance set: generated shaders run on Tessel and on Mesa llvmpipe and compared
// value for value (tests/glsl/mesa_case.hpp). Each TEST is one family (a chapter-8 function
// group, the operators of a type class, swizzles, control flow, indexing, derivatives,
// varyings, textures) and runs all its shaders in a loop; every shader also runs on the
// interpreter, which must give the JIT's bits. Inputs are per-pixel: each argument component
// walks a table of edge values (bit patterns: zeros of both signs, infinities, NaN, halves,
// 2^23, the largest float, ...) and then a domain range, indexed by the pixel, so that Mesa
// cannot fold them. Results are written as values (compared with the stated tolerance) and
// their sign bits, or for integers as their two 16-bit halves, so that -0 and every integer
// bit are checked too.
#include <gtest/gtest.h>

#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "mesa_case.hpp"

namespace tessel::testing {
namespace {

std::string fmt(const char* f, ...) __attribute__((format(printf, 1, 2)));
std::string fmt(const char* f, ...) {
  char buf[4096];
  va_list ap;
  va_start(ap, f);
  std::vsnprintf(buf, sizeof buf, f, ap);
  va_end(ap);
  return buf;
}

// A float literal that reads back as exactly v.
std::string lit(float v) {
  std::string s = fmt("%.9g", double(v));
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return s;
}

// Two colour outputs: c (location 0) and c1 (location 1).
// With `signs` false outf() does not write the signs: for hand-written programs, where Mesa's
// optimizer rewrites 0 - x as -x and float(int(floor(x))) as floor(x), which GLSL allows and
// which change the sign of a zero result.
std::string fragment2(const std::string& decl, const std::string& body, bool signs = true) {
  return std::string(
             "#version 330\nin vec2 p;\nlayout(location = 0) out vec4 c;\nlayout(location = 1) out vec4 c1;\n"
             "float sgn_(float x) { return isnan(x) ? 2.0 : (floatBitsToInt(x) < 0 ? 1.0 : 0.0); }\n") +
         (signs ? "void outf(vec4 r) { c = r; c1 = vec4(sgn_(r.x), sgn_(r.y), sgn_(r.z), sgn_(r.w)); }\n"
                : "void outf(vec4 r) { c = r; c1 = vec4(0.0); }\n") +
         "void outi(uvec4 u) { c = vec4(u >> 16u); c1 = vec4(u & 0xFFFFu); }\n"
         "void outb(bvec4 b) { c = vec4(b); c1 = vec4(0.0); }\n" +
         decl +
         "\nvoid main() {\n  int i = int(gl_FragCoord.x) + 16 * int(gl_FragCoord.y);\n  float t = float(i) / "
         "255.0;\n  " +
         body + "\n}\n";
}

void run2(const std::string& name, const std::string& decl, const std::string& body, Tolerance tol,
          bool mesa = true, bool signs = true) {
  SCOPED_TRACE(name);
  reference::GlslDrawSpec spec = quad_spec(kVertex330, fragment2(decl, body, signs));
  spec.outputs = 2;
  run_spec(name, spec, tol, 0xF, mesa);
}

// --- edge values -------------------------------------------------------------------------------

// Float edges as bit patterns.
const uint32_t kFloatEdges[] = {
    0x00000000u, 0x80000000u, 0x7f800000u,
    0xff800000u, 0x7fc00000u,  // 0, -0, +Inf, -Inf, NaN
    0x3f800000u, 0xbf800000u, 0x3f000000u,
    0xbf000000u, 0x3fc00000u,  // 1, -1, 0.5, -0.5, 1.5
    0xbfc00000u, 0x40200000u, 0xc0200000u,
    0x40600000u, 0xc0600000u,  // -1.5, 2.5, -2.5, 3.5, -3.5
    0x3effffffu, 0xbeffffffu, 0x3f7fffffu,
    0x4b000000u, 0x4affffffu,  // 0.49999997, -0.49999997, 0.99999994, 2^23, 2^23 - 0.5
    0xcaffffffu, 0x4b800000u, 0x4b7fffffu,
    0x7f7fffffu, 0xff7fffffu,  // -(2^23 - 0.5), 2^24, 2^24 - 1, max, -max
    0x00800000u, 0x80800000u, 0x4f000000u,
    0xcf000000u, 0x4f800000u,  // min normal, -min normal, 2^31, -2^31, 2^32
    0x40490fdbu, 0x3fc90fdbu, 0xc0490fdbu,
    0x447a0000u, 0xc47a0000u,  // pi, pi/2, -pi, 1000, -1000
    0x35800000u, 0x2edbe6ffu, 0x7149f2cau,
    0xf149f2cau, 0x42b17218u,  // 2^-20, 1e-10, 1e30, -1e30, 88.72
    0x42c80000u, 0xc2c80000u, 0x41200000u,
    0xc1200000u, 0x3dcccccdu,  // 100, -100, 10, -10, 0.1
};
const int kNumFloatEdges = int(sizeof kFloatEdges / sizeof kFloatEdges[0]);

const int32_t kIntEdges[] = {0,          1,
                             -1,         2,
                             -2,         7,
                             -7,         3,
                             -3,         255,
                             -256,       65535,
                             65536,      -65536,
                             0x7fffffff, int32_t(0x80000000u),
                             0x7ffffffe, int32_t(0x80000001u),
                             0x40000000, 123456789,
                             -987654321, 31,
                             32,         33};
const int kNumIntEdges = int(sizeof kIntEdges / sizeof kIntEdges[0]);
const uint32_t kUintEdges[] = {0u,          1u,          2u,          3u,        7u,          31u,
                               32u,         255u,        65535u,      65536u,    0x7fffffffu, 0x80000000u,
                               0xfffffffeu, 0xffffffffu, 0xdeadbeefu, 123456789u};
const int kNumUintEdges = int(sizeof kUintEdges / sizeof kUintEdges[0]);

std::string uint_table(const char* name, const uint32_t* v, int n) {
  std::string s = fmt("const uint %s[%d] = uint[%d](", name, n, n);
  for (int k = 0; k < n; ++k) s += fmt("%s0x%08xu", k ? ", " : "", v[k]);
  return s + ");\n";
}
std::string int_table(const char* name, const int32_t* v, int n) {
  std::string s = fmt("const int %s[%d] = int[%d](", name, n, n);
  for (int k = 0; k < n; ++k) s += fmt("%sint(0x%08xu)", k ? ", " : "", uint32_t(v[k]));
  return s + ");\n";
}

std::string tables() {
  return uint_table("EF", kFloatEdges, kNumFloatEdges) + int_table("EI", kIntEdges, kNumIntEdges) +
         uint_table("EU", kUintEdges, kNumUintEdges);
}

// The generators genf/geni/genu/genb (then `suffix`) of index k in 0..255: the first
// entries are the edges (when `edges`), the rest walk [lo, hi] (floats) or a range of
// integers.
std::string generators(float lo, float hi, bool edges, const char* suffix = "", bool coarse = false) {
  const int ne = edges ? kNumFloatEdges : 0;
  std::string s;
  if (coarse) {  // few distinct values, so that equal arguments are common
    s += fmt(
        "float genf%s(int k) { return k < %d ? uintBitsToFloat(EF[k]) : float((k * 7) %% 9 - 4) * 0.5; }\n",
        suffix, ne);
    s += fmt("int geni%s(int k) { return k < %d ? EI[k] : (k * 7) %% 9 - 4; }\n", suffix,
             edges ? kNumIntEdges : 0);
    s += fmt("uint genu%s(int k) { return k < %d ? EU[k] : uint((k * 7) %% 9); }\n", suffix,
             edges ? kNumUintEdges : 0);
    s += fmt("bool genb%s(int k) { return ((k * 5) & 4) != 0; }\n", suffix);
    return s;
  }
  s += fmt("float genf%s(int k) { return k < %d ? uintBitsToFloat(EF[k]) : %s + float(k - %d) * %s; }\n",
           suffix, ne, lit(lo).c_str(), ne, lit((hi - lo) / float(256 - ne)).c_str());
  s +=
      fmt("int geni%s(int k) { return k < %d ? EI[k] : (k - 140) * 3; }\n", suffix, edges ? kNumIntEdges : 0);
  s += fmt("uint genu%s(int k) { return k < %d ? EU[k] : uint(k) * 977u; }\n", suffix,
           edges ? kNumUintEdges : 0);
  s += fmt("bool genb%s(int k) { return ((k * 5) & 4) != 0; }\n", suffix);
  return s;
}

const char* scalar_name(char base) {
  return base == 'f' ? "float" : base == 'i' ? "int" : base == 'u' ? "uint" : "bool";
}
std::string type_name(char base, int n) {
  if (n == 1) return scalar_name(base);
  const char* p = base == 'f' ? "" : base == 'i' ? "i" : base == 'u' ? "u" : "b";
  return fmt("%svec%d", p, n);
}

// An argument of type (base, n): component j of argument a reads generator index
// (i * m_a + 37 j + 11 a) mod 256, a permutation of the pixels for each component.
std::string arg_expr(char base, int n, int a, const char* suffix = "") {
  static const int mul[] = {1, 3, 5, 7};
  std::string s = type_name(base, n) + "(";
  for (int j = 0; j < n; ++j)
    s += fmt("%sgen%c%s((i * %d + %d) & 255)", j ? ", " : "", base, suffix, mul[a], 37 * j + 11 * a);
  return s + ")";
}

// Writes r of type (base, n) to the outputs (padded to four components).
std::string write_result(char base, int n, const std::string& r) {
  const char* zero = base == 'f' ? "0.0" : base == 'b' ? "false" : base == 'i' ? "0" : "0u";
  std::string padded = r;
  for (int k = n; k < 4; ++k) padded += std::string(", ") + zero;
  if (base == 'f') return "outf(vec4(" + padded + "));";
  if (base == 'b') return "outb(bvec4(" + padded + "));";
  return "outi(uvec4(" + padded + "));";
}

// A chapter-8 function signature. sig: result ':' arguments, each a letter:
//   T the generic type (base, n); s the scalar of its base; f float; F vecN; B bvecN;
//   I ivecN; U uvecN; b bool; Q bvec4; i int.
struct Fn {
  const char* call;  // over the arguments a, b, c
  const char* sig;
  const char* bases;  // which bases T takes: f, i, u, b
  int nmin, nmax;
  float lo, hi;    // the float domain after the edges
  unsigned edges;  // bit k: argument k walks the edge values first; kCoarse: few values
  Tolerance tol;
};
const unsigned kCoarse = 16;

void type_of(char letter, char base, int n, char* rb, int* rn) {
  switch (letter) {
    case 's': *rb = base, *rn = 1; break;
    case 'f': *rb = 'f', *rn = 1; break;
    case 'F': *rb = 'f', *rn = n; break;
    case 'B': *rb = 'b', *rn = n; break;
    case 'I': *rb = 'i', *rn = n; break;
    case 'U': *rb = 'u', *rn = n; break;
    case 'b': *rb = 'b', *rn = 1; break;
    case 'Q': *rb = 'b', *rn = 4; break;
    case 'i': *rb = 'i', *rn = 1; break;
    default: *rb = base, *rn = n;  // T
  }
}

int run_functions(const Fn* fns, size_t count, const std::string& extra = "") {
  int shaders = 0;
  for (size_t f = 0; f < count; ++f) {
    const Fn& fn = fns[f];
    for (const char* bp = fn.bases; *bp; ++bp)
      for (int n = fn.nmin; n <= fn.nmax; ++n) {
        const char base = *bp;
        char rb;
        int rn;
        type_of(fn.sig[0], base, n, &rb, &rn);
        std::string body;
        const std::string args = fn.sig + 2;
        for (size_t a = 0; a < args.size(); ++a) {
          char ab;
          int an;
          type_of(args[a], base, n, &ab, &an);
          const char* suffix = ((fn.edges >> a) & 1) ? "" : "0";
          body += fmt("%s %c = %s; ", type_name(ab, an).c_str(), "abc"[a],
                      arg_expr(ab, an, int(a), suffix).c_str());
        }
        body += "\n  " + type_name(rb, rn) + " r = " + fn.call + ";\n  " + write_result(rb, rn, "r");
        const bool coarse = (fn.edges & kCoarse) != 0;
        const std::string decl = tables() + generators(fn.lo, fn.hi, true, "", coarse) +
                                 generators(fn.lo, fn.hi, false, "0", coarse) + extra;
        run2(fmt("%s on %s", fn.call, type_name(base, n).c_str()), decl, body, fn.tol);
        ++shaders;
      }
  }
  return shaders;
}

// --- 8.1 angle and trigonometry, 8.2 exponential ------------------------------------------------

// Tolerance 0: Tessel's sequences are llvmpipe's (docs/glsl.md).
const Fn kTrigExp[] = {
    {"radians(a)", "T:T", "f", 1, 4, -720, 720, 1, {0, 0}},
    {"degrees(a)", "T:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"sin(a)", "T:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"cos(a)", "T:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"tan(a)", "T:T", "f", 1, 4, -1.5f, 1.5f, 1, {0, 0}},
    {"asin(a)", "T:T", "f", 1, 4, -1, 1, 1, {0, 0}},
    {"acos(a)", "T:T", "f", 1, 4, -1, 1, 1, {0, 0}},
    {"atan(a)", "T:T", "f", 1, 4, -20, 20, 1, {0, 0}},
    {"atan(a, b)", "T:TT", "f", 1, 4, -10, 10, 3, {0, 0}},
    {"sinh(a)", "T:T", "f", 1, 4, -5, 5, 1, {0, 0}},
    {"cosh(a)", "T:T", "f", 1, 4, -5, 5, 1, {0, 0}},
    {"tanh(a)", "T:T", "f", 1, 4, -5, 5, 1, {0, 0}},
    {"asinh(a)", "T:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"acosh(a)", "T:T", "f", 1, 4, 1, 20, 1, {0, 0}},
    {"atanh(a)", "T:T", "f", 1, 4, -0.99f, 0.99f, 1, {0, 0}},
    {"pow(a, b)", "T:TT", "f", 1, 4, 0, 8, 3, {0, 0}},
    {"exp(a)", "T:T", "f", 1, 4, -20, 20, 1, {0, 0}},
    {"log(a)", "T:T", "f", 1, 4, 0.001f, 1000, 1, {0, 0}},
    {"exp2(a)", "T:T", "f", 1, 4, -30, 30, 1, {0, 0}},
    {"log2(a)", "T:T", "f", 1, 4, 0.001f, 1000, 1, {0, 0}},
    {"sqrt(a)", "T:T", "f", 1, 4, 0, 1000, 1, {0, 0}},
    {"inversesqrt(a)", "T:T", "f", 1, 4, 0.001f, 1000, 1, {0, 0}},
};

TEST(GlslConformance, AngleTrigonometryAndExponential) {
  run_functions(kTrigExp, sizeof kTrigExp / sizeof kTrigExp[0]);
}

// --- 8.3 common functions ----------------------------------------------------------------------

const Fn kCommon[] = {
    {"abs(a)", "T:T", "fi", 1, 4, -10, 10, 1, {0, 0}},
    {"sign(a)", "T:T", "fi", 1, 4, -10, 10, 1, {0, 0}},
    {"floor(a)", "T:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"trunc(a)", "T:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"round(a)", "T:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"roundEven(a)", "T:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"ceil(a)", "T:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"fract(a)", "T:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"mod(a, b)", "T:TT", "f", 1, 4, -10, 10, 3, {0, 0}},
    {"mod(a, b)", "T:Ts", "f", 2, 4, -10, 10, 3, {0, 0}},
    {"min(a, b)", "T:TT", "fiu", 1, 4, -10, 10, 3, {0, 0}},
    {"min(a, b)", "T:Ts", "fiu", 2, 4, -10, 10, 3, {0, 0}},
    {"max(a, b)", "T:TT", "fiu", 1, 4, -10, 10, 3, {0, 0}},
    {"max(a, b)", "T:Ts", "fiu", 2, 4, -10, 10, 3, {0, 0}},
    {"clamp(a, b, c)", "T:TTT", "fiu", 1, 4, -10, 10, 7, {0, 0}},
    {"clamp(a, b, c)", "T:Tss", "fiu", 2, 4, -10, 10, 7, {0, 0}},
    {"mix(a, b, c)", "T:TTT", "f", 1, 4, -10, 10, 3, {0, 0}},
    {"mix(a, b, c)", "T:TTs", "f", 2, 4, -10, 10, 3, {0, 0}},
    {"mix(a, b, c)", "T:TTB", "f", 1, 4, -10, 10, 3, {0, 0}},
    {"step(a, b)", "T:TT", "f", 1, 4, -10, 10, 3, {0, 0}},
    {"step(a, b)", "T:sT", "f", 2, 4, -10, 10, 3, {0, 0}},
    // smoothstep is undefined for edge0 >= edge1: the edges are a and a + |b| + 0.25.
    {"smoothstep(a, a + abs(b) + 0.25, c)", "T:TTT", "f", 1, 4, -10, 10, 4, {0, 0}},
    {"smoothstep(a, a + abs(b) + 0.25, c)", "T:ssT", "f", 2, 4, -10, 10, 4, {0, 0}},
    {"isnan(a)", "B:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"isinf(a)", "B:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"floatBitsToInt(a)", "I:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"floatBitsToUint(a)", "U:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    // The bits go back to integers, so NaN payloads and every bit are compared.
    {"floatBitsToUint(intBitsToFloat(a))", "U:T", "i", 1, 4, -10, 10, 1, {0, 0}},
    {"floatBitsToInt(uintBitsToFloat(a))", "I:T", "u", 1, 4, -10, 10, 1, {0, 0}},
    {"intBitsToFloat(a)", "F:T", "i", 1, 4, -10, 10, 0, {0, 0}},
    {"uintBitsToFloat(a * 2654435761u)", "F:T", "u", 1, 4, -10, 10, 0, {0, 0}},
};

TEST(GlslConformance, CommonFunctions) { run_functions(kCommon, sizeof kCommon / sizeof kCommon[0]); }

// modf writes its whole part to an out parameter.
TEST(GlslConformance, Modf) {
  for (int n = 1; n <= 4; ++n) {
    const std::string T = type_name('f', n);
    const std::string body = T + " a = " + arg_expr('f', n, 0) + "; " + T + " w; " + T +
                             " fr = modf(a, w);\n  " + write_result('f', n, "fr") + " if ((i & 1) == 1) " +
                             write_result('f', n, "w");
    run2("modf on " + T, tables() + generators(-10, 10, true), body, {0, 0});
  }
}

// --- 8.4 geometric, 8.5 matrix, 8.6 vector relational -------------------------------------------

// Tolerance 0 where the sequence is llvmpipe's; the geometric functions walk a domain only
// (their results at infinities are sums of infinities).
const Fn kGeometric[] = {
    {"length(a)", "f:T", "f", 1, 4, -10, 10, 0, {0, 0}},
    {"distance(a, b)", "f:TT", "f", 1, 4, -10, 10, 0, {0, 0}},
    {"dot(a, b)", "f:TT", "f", 1, 4, -10, 10, 0, {0, 0}},
    {"cross(a, b)", "T:TT", "f", 3, 3, -10, 10, 0, {0, 0}},
    {"normalize(a)", "T:T", "f", 1, 4, -10, 10, 0, {0, 0}},
    {"faceforward(a, b, c)", "T:TTT", "f", 1, 4, -10, 10, 0, {0, 0}},
    {"reflect(a, normalize(b))", "T:TT", "f", 1, 4, -10, 10, 0, {0, 0}},
    {"refract(normalize(a), normalize(b), c * 0.1)", "T:TTs", "f", 1, 4, -10, 10, 0, {0, 0}},
    {"length(a)", "f:T", "f", 1, 4, -10, 10, 1, {0, 0}},
    {"dot(a, b)", "f:TT", "f", 1, 4, -10, 10, 3, {0, 0}},
};

TEST(GlslConformance, GeometricFunctions) {
  run_functions(kGeometric, sizeof kGeometric / sizeof kGeometric[0]);
}

const Fn kRelational[] = {
    {"lessThan(a, b)", "B:TT", "fiu", 2, 4, -3, 3, 3 | kCoarse, {0, 0}},
    {"lessThanEqual(a, b)", "B:TT", "fiu", 2, 4, -3, 3, 3 | kCoarse, {0, 0}},
    {"greaterThan(a, b)", "B:TT", "fiu", 2, 4, -3, 3, 3 | kCoarse, {0, 0}},
    {"greaterThanEqual(a, b)", "B:TT", "fiu", 2, 4, -3, 3, 3 | kCoarse, {0, 0}},
    {"equal(a, b)", "B:TT", "fiub", 2, 4, -3, 3, 3 | kCoarse, {0, 0}},
    {"notEqual(a, b)", "B:TT", "fiub", 2, 4, -3, 3, 3 | kCoarse, {0, 0}},
    {"any(a)", "b:T", "b", 2, 4, 0, 1, 0, {0, 0}},
    {"all(a)", "b:T", "b", 2, 4, 0, 1, 0, {0, 0}},
    {"not(a)", "T:T", "b", 2, 4, 0, 1, 0, {0, 0}},
};

TEST(GlslConformance, VectorRelationalFunctions) {
  run_functions(kRelational, sizeof kRelational / sizeof kRelational[0]);
}

// --- operators and conversions on scalars and vectors ---------------------------------------------

// Integer division and remainder by zero and INT_MIN / -1 are in the edges: Tessel gives
// llvmpipe's results for them. Shift counts are kept in 0..31 (larger ones are undefined).
const Fn kOperators[] = {
    {"a + b", "T:TT", "fiu", 1, 4, -10, 10, 3, {0, 0}},
    {"a - b", "T:TT", "fiu", 1, 4, -10, 10, 3, {0, 0}},
    {"a * b", "T:TT", "fiu", 1, 4, -10, 10, 3, {0, 0}},
    {"a / b", "T:TT", "fiu", 1, 4, -10, 10, 3, {0, 0}},
    {"a + b", "T:Ts", "fiu", 2, 4, -10, 10, 3, {0, 0}},
    {"b - a", "T:Ts", "fiu", 2, 4, -10, 10, 3, {0, 0}},
    {"b * a", "T:Ts", "fiu", 2, 4, -10, 10, 3, {0, 0}},
    {"a / b", "T:Ts", "fiu", 2, 4, -10, 10, 3, {0, 0}},
    {"b / a", "T:Ts", "fiu", 2, 4, -10, 10, 3, {0, 0}},
    {"-a", "T:T", "fi", 1, 4, -10, 10, 1, {0, 0}},
    {"+a", "T:T", "fi", 1, 4, -10, 10, 1, {0, 0}},
    {"a % b", "T:TT", "iu", 1, 4, -10, 10, 3, {0, 0}},
    {"a % b", "T:Ts", "iu", 2, 4, -10, 10, 3, {0, 0}},
    {"a & b", "T:TT", "iu", 1, 4, -10, 10, 3, {0, 0}},
    {"a | b", "T:TT", "iu", 1, 4, -10, 10, 3, {0, 0}},
    {"a ^ b", "T:TT", "iu", 1, 4, -10, 10, 3, {0, 0}},
    {"(a & b) | (a ^ c)", "T:Tss", "iu", 2, 4, -10, 10, 7, {0, 0}},
    {"~a", "T:T", "iu", 1, 4, -10, 10, 1, {0, 0}},
    {"a << (b & 31)", "T:TI", "iu", 1, 4, -10, 10, 3, {0, 0}},
    {"a >> (b & 31)", "T:TI", "iu", 1, 4, -10, 10, 3, {0, 0}},
    {"a << (b & 31u)", "T:TU", "iu", 1, 4, -10, 10, 3, {0, 0}},
    {"a >> (b & 31u)", "T:TU", "iu", 1, 4, -10, 10, 3, {0, 0}},
    {"a >> (c & 31)", "T:Tsi", "iu", 2, 4, -10, 10, 3, {0, 0}},
    // Compound assignment, increments and decrements.
    {"T_r(a, b)", "T:TT", "fiu", 1, 4, -10, 10, 3, {0, 0}},
    // Comparisons: == and != of whole vectors; relational operators on scalars.
    {"a == b", "b:TT", "fiub", 1, 4, -3, 3, 3 | kCoarse, {0, 0}},
    {"a != b", "b:TT", "fiub", 1, 4, -3, 3, 3 | kCoarse, {0, 0}},
    {"bvec4(a < b, a <= b, a > b, a >= b)", "Q:TT", "fiu", 1, 1, -3, 3, 3 | kCoarse, {0, 0}},
    {"bvec4(a && b, a || b, a ^^ b, !a)", "Q:TT", "b", 1, 1, 0, 1, 0, {0, 0}},
    {"a ? b : c", "T:bTT", "fiub", 1, 4, -10, 10, 6, {0, 0}},
    // Conversions. int(float) and uint(float) out of range are undefined in GLSL; Tessel
    // converts as llvmpipe does on this machine class (interp.cpp f2i/f2u), so they are kept.
    {"I(a)", "I:T", "fu", 1, 4, -300, 300, 1, {0, 0}},
    {"U(a)", "U:T", "i", 1, 4, -300, 300, 1, {0, 0}},
    {"U(abs(a))", "U:T", "f", 1, 4, -300, 300, 0, {0, 0}},
    {"F(a)", "F:T", "iub", 1, 4, -10, 10, 1, {0, 0}},
    {"B(a)", "B:T", "fiu", 1, 4, -3, 3, 1 | kCoarse, {0, 0}},
    {"I(a)", "I:T", "b", 1, 4, -3, 3, 1, {0, 0}},
    {"U(a)", "U:T", "b", 1, 4, -3, 3, 1, {0, 0}},
};

// The T_r / I / U / F / B placeholders of a call: the generic type's compound-assignment
// helper and the conversions to (base, n).
std::string expand(std::string call, char base, int n) {
  auto rep = [&](const std::string& from, const std::string& to) {
    for (size_t pos = 0; (pos = call.find(from, pos)) != std::string::npos; pos += to.size())
      call.replace(pos, from.size(), to);
  };
  rep("T_r(", "compound(");
  rep("I(", type_name('i', n) + "(");
  rep("U(", type_name('u', n) + "(");
  rep("F(", type_name('f', n) + "(");
  rep("B(", type_name('b', n) + "(");
  (void)base;
  return call;
}

// compound(a, b) for type T: +=, -=, *=, /=, pre and post ++ and -- (and %= <<= >>= &= |= ^=
// on integers). No two constant steps follow each other (Mesa would fold (r + 1) - 1).
std::string compound_helper(char base, int n) {
  const std::string T = type_name(base, n);
  std::string s = T + " compound(" + T + " a, " + T + " b) {\n  " + T + " r = a; r += b; r *= b; " + T +
                  " q = r++; r -= a; r *= b; " + T + " w = ++r; r /= b; r--; r *= a; --r; r += q * w;\n";
  if (base != 'f') {
    const std::string one = base == 'i' ? "1" : "1u", m31 = base == 'i' ? "31" : "31u";
    s += "  r %= b; r <<= (b & " + T + "(" + m31 + ")); r ^= a; r >>= " + one + "; r &= ~b; r |= a;\n";
  }
  return s + "  return r;\n}\n";
}

TEST(GlslConformance, OperatorsAndConversions) {
  // run_functions with the placeholders expanded per type.
  int shaders = 0;
  for (const Fn& f : kOperators)
    for (const char* bp = f.bases; *bp; ++bp)
      for (int n = f.nmin; n <= f.nmax; ++n) {
        const std::string call = expand(f.call, *bp, n);
        Fn one = f;
        one.call = call.c_str();
        const char b[2] = {*bp, 0};
        one.bases = b;
        one.nmin = one.nmax = n;
        if (std::string(f.call).find("T_r") != std::string::npos) {
          one.call = "compound(a, b)";
          shaders += run_functions(&one, 1, compound_helper(*bp, n));
        } else {
          shaders += run_functions(&one, 1);
        }
      }
  std::printf("operators: %d shaders\n", shaders);
}

// --- matrices ----------------------------------------------------------------------------------

std::string mat_name(int c, int r) { return fmt("mat%dx%d", c, r); }

// A matCxR argument (domain values only): component j reads index (i * m_a + 37 j + 11 a).
std::string mat_arg(int c, int r, int a) {
  static const int mul[] = {1, 3, 5, 7};
  std::string s = mat_name(c, r) + "(";
  for (int j = 0; j < c * r; ++j)
    s += fmt("%sgenf0((i * %d + %d) & 255)", j ? ", " : "", mul[a], 37 * j + 11 * a);
  return s + ")";
}

// Writes column i % C of a matCxR result.
std::string write_mat(int c, int r, const std::string& m) {
  return write_result('f', r, fmt("%s[i %% %d]", m.c_str(), c));
}

TEST(GlslConformance, MatrixOperatorsAndFunctions) {
  const std::string decl = tables() + generators(-4, 4, true) + generators(-4, 4, false, "0");
  int shaders = 0;
  auto run = [&](const std::string& name, const std::string& body) {
    run2(name, decl, body, {0, 0});
    ++shaders;
  };
  for (int C = 2; C <= 4; ++C)
    for (int R = 2; R <= 4; ++R) {
      const std::string M = mat_name(C, R), A = "  " + M + " a = " + mat_arg(C, R, 0) + "; ",
                        B = M + " b = " + mat_arg(C, R, 1) + "; ",
                        s = "float s = genf0((i * 5 + 3) & 255) + 0.5; ";
      run(M + " a + b", A + B + M + " r = a + b; " + write_mat(C, R, "r"));
      run(M + " a - b", A + B + M + " r = a - b; " + write_mat(C, R, "r"));
      run(M + " a / b", A + B + M + " r = a / b; " + write_mat(C, R, "r"));
      run(M + " -a", A + M + " r = -a; " + write_mat(C, R, "r"));
      run(M + " with a scalar",
          A + s + M + " r = (a * s - s) / s + s * a - (s - a); " + write_mat(C, R, "r"));
      run(M + " compound", A + B + s + M + " r = a; r += b; r *= s; r++; r -= a; r /= s; --r; r *= s; " + M +
                               " q = r--; r += q; " + write_mat(C, R, "r"));
      run(M + " matrixCompMult", A + B + M + " r = matrixCompMult(a, b); " + write_mat(C, R, "r"));
      run(M + " * vec", A + type_name('f', C) + " v = " + arg_expr('f', C, 2, "0") + "; " +
                            type_name('f', R) + " r = a * v; " + write_result('f', R, "r"));
      run("vec * " + M, A + type_name('f', R) + " v = " + arg_expr('f', R, 2, "0") + "; " +
                            type_name('f', C) + " r = v * a; " + write_result('f', C, "r"));
      for (int K = 2; K <= 4; ++K)
        run(M + " * " + mat_name(K, C), A + mat_name(K, C) + " b = " + mat_arg(K, C, 1) + "; " +
                                            mat_name(K, R) + " r = a * b; " + write_mat(K, R, "r"));
      run(M + " transpose", A + mat_name(R, C) + " r = transpose(a); " + write_mat(R, C, "r"));
      run(M + " outerProduct", std::string("  ") + type_name('f', R) + " u = " + arg_expr('f', R, 0, "0") +
                                   "; " + type_name('f', C) + " v = " + arg_expr('f', C, 1, "0") + "; " + M +
                                   " r = outerProduct(u, v); " + write_mat(C, R, "r"));
      run(M + " == !=", A + M + fmt(" b = a; if ((i & 2) == 0) b[i %% %d][(i / 4) %% %d] += 1.0; ", C, R) +
                            "outb(bvec4(a == b, a != b, b == a, a != a));");
      if (C == R) {
        run(M + " *= ", A + B + M + " r = a; r *= b; r *= 0.5; " + write_mat(C, R, "r"));
        run(M + " determinant", A + "outf(vec4(determinant(a), determinant(transpose(a)), 0.0, 0.0));");
        // A well-conditioned matrix: a / 4 plus the identity times 3.
        run(M + " inverse", A + M + " r = inverse(a * 0.25 + " + M + "(3.0)); " + write_mat(C, R, "r"));
      }
    }
  std::printf("matrices: %d shaders\n", shaders);
}

// --- denormals ----------------------------------------------------------------------------------

// llvmpipe flushes denormal results to zero and reads denormal operands as zero; Tessel's
// GLSL programs do the same (docs/glsl.md), while a denormal that is only moved is kept.
TEST(GlslConformance, Denormals) {
  const char* decl =
      "uniform float one; uniform float zero; uniform float big;\n"
      "const uint DN[8] = uint[8](0x00000001u, 0x80000001u, 0x007fffffu, 0x807fffffu, 0x00400000u, "
      "0x00800000u,"
      " 0x80800000u, 0x00000000u);\n";
  const char* bodies[] = {
      "float x = uintBitsToFloat(DN[i % 8]); c = vec4(x * one, x + zero, x * big, x);",
      "float x = uintBitsToFloat(DN[i % 8]); c = vec4(x * 0.5, sqrt(abs(x)), float(x > zero) + 2.0 * float(x "
      "== zero), "
      "floor(x));",
      "float x = uintBitsToFloat(DN[i % 8]); c = vec4(x - x * one, max(x, zero), min(x, zero), sign(x));",
      "float x = uintBitsToFloat(DN[i % 8]); c = vec4(1.0 / x, inversesqrt(abs(x)), exp2(x), mix(x, one, "
      "zero));",
      "float x = uintBitsToFloat(DN[i % 8]) * big; float y = x * (one / big); c = vec4(y, y * big, y / big, "
      "uintBitsToFloat(floatBitsToUint(y) | 1u));",
  };
  for (const char* body : bodies) {
    SCOPED_TRACE(body);
    Case cs{body, decl, body, {0, 0}};
    cs.uniforms = {{"one", {1.0f}}, {"zero", {0.0f}}, {"big", {8388608.0f}}};
    run_case(cs);
  }
  // And Tessel flushes: a denormal times one reads as zero, a moved one is kept.
  reference::GlslDrawSpec spec = quad_spec(kVertex330, fragment330(decl, bodies[0]));
  spec.uniforms = {{"one", {1.0f}}, {"zero", {0.0f}}, {"big", {8388608.0f}}};
  const TesselResult ours = run_tessel(spec);
  ASSERT_TRUE(ours.ok) << ours.log;
  uint32_t bits[4];
  std::memcpy(bits, ours.outputs[0].data(), 16);  // pixel 0: x = the smallest denormal
  EXPECT_EQ(bits[0], 0u);
  EXPECT_EQ(bits[1], 0u);
  EXPECT_EQ(bits[2], 0u);
  EXPECT_EQ(bits[3], 1u);
}

// --- swizzles, write masks and constructors ------------------------------------------------------

TEST(GlslConformance, SwizzlesAndWriteMasks) {
  const std::string decl = tables() + generators(-10, 10, true) + generators(-10, 10, false, "0") +
                           "struct S { float f; vec4 v[2]; ivec3 iv; };\n";
  const char* sets[] = {"xyzw", "rgba", "stpq"};
  int shaders = 0;
  for (char base : {'f', 'i', 'u', 'b'})
    for (int n = 2; n <= 4; ++n) {
      const std::string T = type_name(base, n), T4 = type_name(base, 4);
      const char* set = sets[n - 2];
      auto sw = [&](const char* pattern) {  // a pattern of component numbers in the set of n
        std::string r;
        for (const char* q = pattern; *q; ++q) r += set[(*q - '0') % n];
        return r;
      };
      const std::string v =
          "  " + T + " v = " + arg_expr(base, n, 0) + "; " + T + " u = " + arg_expr(base, n, 1) + "; ";
      // Reads: repeated, reversed and mixed components, of the sizes 1 to 4.
      run2(T + " read swizzles", decl,
           v + T4 + " r = " + T4 + "(v." + sw("1") + ", v." + sw("10") + ", u." + sw("2") + ");\n  " +
               write_result(base, 4, "r") + " if ((i & 1) == 1) " + write_result(base, 4, "v." + sw("3210")),
           {0, 0});
      // Writes through masks, compound ones on non-bool types, of a swizzle of a swizzle.
      std::string w = v + T + " w = v; w." + sw("10") + " = u." + sw("01") + "; ";
      if (base != 'b')
        w += "w." + sw("1") + (base == 'f' ? " *= 2.0; " : base == 'i' ? " *= 2; " : " *= 2u; ");
      if (n >= 3)
        w += "w." + sw("20") + " = w.zxy." + std::string(1, "xyzw"[0]) + std::string(1, "xyzw"[1]) + "; ";
      if (n == 4) w += "w.wy = u.xx; w.z = v.x; ";
      run2(T + " write masks", decl, w + write_result(base, n, "w"), {0, 0});
      ++shaders;
      ++shaders;
      // L-values through arrays and struct members, the index per pixel.
      if (base == 'f') {
        run2(T + " masks through arrays and structs", decl,
             v +
                 "S s[3]; for (int k = 0; k < 3; ++k) { s[k].f = float(k); s[k].v[0] = vec4(float(k)); "
                 "s[k].v[1] = vec4(-1.0); "
                 "s[k].iv = ivec3(k); }\n  s[i % 3].v[i & 1]." +
                 sw("10") + " = v." + sw("01") +
                 "; s[(i + 1) % 3].v[1].w += v.x; s[i % 3].iv.zy = ivec2(i, -i); s[2].f = v.y;\n  " +
                 "vec4 r = s[i % 3].v[0] + s[(i + 1) % 3].v[1] * 2.0 + vec4(s[i % 3].iv, s[2].f); " +
                 write_result('f', 4, "r"),
             {0, 0});
        ++shaders;
      }
    }
  std::printf("swizzles: %d shaders\n", shaders);
}

TEST(GlslConformance, Constructors) {
  const std::string decl = tables() + generators(-10, 10, true) + generators(-10, 10, false, "0");
  int shaders = 0;
  // Every matrix shape from every matrix shape (the rest of the identity fills, or the
  // top-left part is taken), and from a scalar.
  for (int C = 2; C <= 4; ++C)
    for (int R = 2; R <= 4; ++R) {
      const std::string M = mat_name(C, R), src = "  " + M + " a = " + mat_arg(C, R, 0) + "; ";
      for (int C2 = 2; C2 <= 4; ++C2)
        for (int R2 = 2; R2 <= 4; ++R2) {
          if (C2 == C && R2 == R) continue;
          const std::string M2 = mat_name(C2, R2);
          run2(M2 + "(" + M + ")", decl, src + M2 + " r = " + M2 + "(a); " + write_mat(C2, R2, "r"), {0, 0});
          ++shaders;
        }
      run2(M + "(s)", decl, "  float s = genf(i); " + M + " r = " + M + "(s); " + write_mat(C, R, "r"),
           {0, 0});
      ++shaders;
    }
  // Vectors from matrices, mixed and converting constructors.
  const char* bodies[] = {
      "mat2 m = "
      "mat2(genf(i), genf((i + 7) & 255), genf((i * 3) & 255), 1.5); outf(vec4(m));",
      "mat2x3 m = mat2x3(genf(i), 2.0, 3.0, genf((i * 3) & 255), 5.0, 6.0); vec3 v = vec3(m); outf(vec4(v, "
      "vec2(m)));",
      "mat3 m = mat3(vec3(genf(i)), vec3(1.0, 2.0, 3.0), vec3(genf((i * 5) & 255))); outf(vec4(m[1].yz, "
      "m[2].x, "
      "m[0].z));",
      "vec2 a = vec2(genf(i), genf((i * 3) & 255)); outf(vec4(a, a) * vec4(a.x, a.yx, 1.0) - vec4(vec3(a, "
      "2.0), 3.0));",
      "vec4 a = vec4(genf(i), genf((i * 3) & 255), genf((i * 5) & 255), genf((i * 7) & 255)); "
      "outf(vec4(vec3(a), "
      "vec2(a).y) + vec4(float(a.w)));",
      "ivec4 a = ivec4(geni(i), geni((i * 3) & 255), 7, -7); outf(vec4(a) + vec4(ivec2(a.zw), uvec2(3u, "
      "4u)));",
      "vec4 a = vec4(genf0(i) * 30.0, genf0((i * 3) & 255) * 30.0, -3.5, 3.5); outi(uvec4(ivec4(a)) + "
      "uvec4(uvec3(abs(a)), "
      "1u));",
      "bvec4 b = bvec4(genf(i), geni((i * 3) & 255), genu((i * 5) & 255), 0.0); outb(b); c1 = vec4(ivec4(b)) "
      "+ "
      "vec4(uvec4(b));",
      "mat2 m = mat2(vec3(genf(i), 2.0, 3.0), genf((i * 3) & 255)); outf(vec4(m[0], m[1]));",
      "mat4x2 m = mat4x2(ivec2(geni(i), 3), uvec2(5u, genu(i)), bvec2(true, i > 9), vec2(genf(i))); "
      "outf(vec4(m[i % 4], "
      "m[1]));",
      "struct P { vec2 a; int b; float c[2]; }; P q = P(vec2(genf(i)), geni(i), float[2](genf((i * 3) & "
      "255), 1.0)); "
      "outf(vec4(q.a, float(q.b), q.c[0] + q.c[1]));",
      "float a[3] = float[](genf(i), genf((i * 3) & 255), 2.0); vec3 v = vec3(a[0], a[1], a[2]); "
      "outf(vec4(v, "
      "float(a.length())));",
  };
  for (const char* body : bodies) {
    // A struct declared in main is fine in GLSL 3.30.
    run2(body, decl, std::string("  ") + body, {0, 0}, true, false);
    ++shaders;
  }
  std::printf("constructors: %d shaders\n", shaders);
}

// --- divergent control flow ----------------------------------------------------------------------

struct Program {
  const char* name;
  const char* decl;
  const char* body;
};

// Every program's control flow depends on the pixel. Tolerance 0: no reassociation chains.
const Program kFlow[] = {
    {"nested if/else 4 deep", "",
     "float r = 0.0; if (i % 2 == 0) { if (i % 3 == 0) { if (i % 5 == 0) r = 1.0; else { if (i % 7 == 0) r = "
     "2.0; else r = 3.0; } }"
     " else r = 4.0; } else if (i % 3 == 1) { r = 5.0; if (i > 100) r += t; } else { if (i < 50) r = 6.0; } "
     "outf(vec4(r, t, 0.0, "
     "1.0));"},
    {"nested loops, per-lane counts, break and continue", "",
     "float s = 0.0; for (int a = 0; a < i % 7; ++a) { for (int b = 0; b < 10; ++b) { if (b == a) continue; "
     "if (b > (i % 5) + a) "
     "break; s += float(a * 10 + b); } if (s > 200.0) break; } outf(vec4(s, 0.0, 0.0, 1.0));"},
    {"while with a per-lane condition that changes", "",
     "float x = t * 10.0; int n = 0; while (x > 0.1 && n < 100) { x = x * 0.5 - (n % 3 == 0 ? 0.05 : 0.0); "
     "++n; } outf(vec4(x, "
     "float(n), 0.0, 1.0));"},
    {"do-while with continue", "",
     "int k = 0; int s = 0; do { ++k; if ((k & 1) == 0) continue; s += k; } while (k < i % 13); "
     "outi(uvec4(k, s, 0u, 0u));"},
    {"discard in a loop", "",
     "for (int k = 0; k < 8; ++k) { if (k == i % 11) discard; } outf(vec4(t, 1.0, 0.0, 1.0));"},
    {"discard in a function", "void maybe(int k) { if ((k & 6) == 2) discard; }",
     "maybe(i); maybe(i >> 3); outf(vec4(t, 2.0, 0.0, 1.0));"},
    {"early return from nested loops",
     "float f(int n) { for (int a = 0; a < 8; ++a) for (int b = 0; b < 8; ++b) { if (a * 8 + b == n) return "
     "float(a) + 0.125 * "
     "float(b); } return -1.0; }",
     "outf(vec4(f(i % 70), f(i / 4), 0.0, 1.0));"},
    {"switch with default in the middle", "",
     "float r = 0.0; switch (i % 7) { case 0: r = 1.0; break; default: r = -1.0; break; case 3: r = 3.0; "
     "case 4: r += 4.0; break; "
     "case 6: r = 6.0; } outf(vec4(r, 0.0, 0.0, 1.0));"},
    {"switch in a loop with continue and break", "",
     "int s = 0; for (int k = 0; k < 12; ++k) { switch ((k + i) % 4) { case 0: continue; case 1: s += 1; "
     "break; case 2: s += 10; "
     "default: s += 100; } if (s > i) break; } outi(uvec4(s, 0u, 0u, 0u));"},
    {"switch on uint with nested switch", "",
     "uint u = uint(i) % 5u; int r = 0; switch (u) { case 1u: switch (i % 3) { case 0: r = 10; break; "
     "default: r = 11; } break; "
     "case 2u: case 3u: r = 23; break; default: r = -1; } outi(uvec4(r, 0, 0, 0));"},
    {"globals changed under divergent masks",
     "float g = 1.0; int calls = 0; void bump(float x) { g += x; ++calls; }",
     "if (t > 0.3) bump(t); if (i % 4 == 1) { bump(2.0); bump(-0.5); } for (int k = 0; k < i % 3; ++k) "
     "bump(0.25); outf(vec4(g, "
     "float(calls), 0.0, 1.0));"},
    {"out and inout parameters under divergence",
     "void split(in float x, out int w, out float f, inout vec2 acc) { w = int(floor(x)); f = x - floor(x); "
     "acc += vec2(f, "
     "float(w)); }",
     "vec2 acc = vec2(0.0); int w = -1; float f = -1.0; if (i % 3 != 0) split(t * 7.0, w, f, acc); else if "
     "(i % 2 == 0) split(-t "
     "* 3.0 - 0.25, w, f, acc); outf(vec4(float(w), f, acc));"},
    {"out parameter aliasing an array element",
     "void set2(out float a, out float b, float v) { a = v; b = v * 2.0; }",
     "float arr[4] = float[4](0.0, 0.0, 0.0, 0.0); set2(arr[i % 4], arr[(i + 1) % 4], t); outf(vec4(arr[0], "
     "arr[1], arr[2], "
     "arr[3]));"},
    {"loop with returns in a called function under a mask",
     "int steps(int n) { int k = 0; while (true) { if (n <= 1) return k; n = (n & 1) == 0 ? n / 2 : 3 * n + "
     "1; ++k; if (k > 50) "
     "return -k; } }",
     "int r = 0; if (i % 2 == 1) r = steps(i); else r = steps(i / 2) + 1000; outi(uvec4(r, 0, 0, 0));"},
    {"break out of a loop from a nested if chain", "",
     "int k = 0; for (; k < 100; ++k) { if (k > 3) { if ((k ^ i) % 9 == 0) break; else if (k > 40 + i % 20) "
     "{ break; } } } outi(uvec4(k, "
     "0, 0, 0));"},
    {"for loop with a float counter", "",
     "float s = 0.0; for (float x = 0.0; x < t * 4.0; x += 0.25) s += x; outf(vec4(s, 0.0, 0.0, 1.0));"},
    {"ternary chains and short circuits with effects", "int n = 0; bool f(bool b) { ++n; return b; }",
     "bool a = f(i % 2 == 0) && f(i % 3 == 0) || f(i % 5 == 0); float r = a ? (i > 128 ? 1.0 : 2.0) : (i < "
     "10 ? 3.0 : 4.0); "
     "outf(vec4(r, float(n), float(a), 1.0));"},
    {"continue in a while loop", "",
     "int k = 0, s = 0; while (k < 20) { ++k; if (k % (1 + i % 4) == 0) continue; s += k; } outi(uvec4(s, k, "
     "0, 0));"},
    {"nested functions with early returns",
     "float g(float x) { if (x < 0.2) return x; return x * 2.0; } float h(float x) { if (x > 0.8) return "
     "-1.0; float y = g(x); if "
     "(y > 1.0) return y - 1.0; return y + 10.0; }",
     "outf(vec4(h(t), h(1.0 - t), g(t), 1.0));"},
    {"discard then writes in other lanes with a loop after", "",
     "if (i % 5 == 2) discard; float s = 0.0; for (int k = 0; k < i % 9; ++k) s += 1.5; outf(vec4(s, t, 0.0, "
     "1.0));"},
    {"loop whose bound is changed in the body", "",
     "int n = i % 10; int k = 0; for (int a = 0; a < n; ++a) { if (a == 2) n -= 3; ++k; } outi(uvec4(k, n, "
     "0, 0));"},
    {"all lanes leave a loop at different iterations, then converge", "",
     "int a = 0; for (int k = 0; k < 64; ++k) { if (k * k > i) break; a += k; } float r = float(a); if (a > "
     "20) r = -r; "
     "outf(vec4(r, float(a), 0.0, 1.0));"},
};

TEST(GlslConformance, DivergentControlFlow) {
  for (const Program& f : kFlow) run2(f.name, f.decl, std::string("  ") + f.body, {0, 0}, true, false);
}

// --- dynamic indexing -----------------------------------------------------------------------------

const Program kIndexing[] = {
    {"float array", "",
     "float a[7]; for (int k = 0; k < 7; ++k) a[k] = float(k * k) - t; outf(vec4(a[i % 7], a[(i * 3) % 7], "
     "a[6 - i % 7], 1.0));"},
    {"float array written per lane", "",
     "float a[5] = float[5](1.0, 2.0, 3.0, 4.0, 5.0); a[i % 5] = t; a[(i / 5) % 5] += 10.0; outf(vec4(a[0], "
     "a[1], a[2], a[3] + "
     "a[4]));"},
    {"vec array and its components", "",
     "vec3 a[4]; for (int k = 0; k < 4; ++k) a[k] = vec3(k, k * 2, -k) + t; a[i % 4][(i / 4) % 3] = -9.0; "
     "outf(vec4(a[(i + 1) % "
     "4], a[i % 4][i % 3]));"},
    {"matrix columns and elements m[i][j]", "",
     "mat4 m = mat4(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0, 16.0) * "
     "t; int a = i % 4, b "
     "= (i / 4) % 4; m[a][b] = -1.0; outf(vec4(m[a][b], m[b][a], m[(a + 1) % 4].yz));"},
    {"array of matrices", "",
     "mat2 ms[3]; for (int k = 0; k < 3; ++k) ms[k] = mat2(float(k), t, -t, float(k * k)); outf(vec4(ms[i % "
     "3][(i / 3) % 2], "
     "ms[(i + 1) % 3][1][i % 2], 1.0));"},
    {"array of structs with arrays", "struct S { float w[3]; vec2 v; };",
     "S s[4]; for (int k = 0; k < 4; ++k) { s[k].v = vec2(k, t); for (int j = 0; j < 3; ++j) s[k].w[j] = "
     "float(k * 3 + j); } "
     "s[i % 4].w[(i / 4) % 3] *= -1.0; outf(vec4(s[i % 4].w[i % 3], s[(i + 2) % 4].v, s[i % 4].w[(i / 4) % "
     "3]));"},
    {"int and uint arrays", "",
     "int a[6] = int[6](1, -2, 3, -4, 5, -6); uint b[3] = uint[3](7u, 8u, 9u); a[i % 6] *= i; outi(uvec4(a[i "
     "% 6], a[(i + 3) % "
     "6], b[i % 3], b[uint(i) % 3u]));"},
    {"bool array", "",
     "bool a[4] = bool[4](true, false, i > 100, t < 0.5); a[i % 4] = !a[i % 4]; outb(bvec4(a[0], a[1], a[2], "
     "a[3]));"},
    {"uniform float array", "uniform float k[5];",
     "outf(vec4(k[i % 5], k[4 - i % 5], k[(i * 7) % 5], 1.0));"},
    {"uniform vec4 array and matrices", "uniform vec4 v[3]; uniform mat3 m[2];",
     "outf(v[i % 3] + vec4(m[i % 2][(i / 2) % 3], m[(i + 1) % 2][i % 3][(i / 3) % 3]));"},
    {"uniform struct array", "struct L { vec3 p; float w; }; uniform L ls[3];",
     "L l = ls[i % 3]; outf(vec4(l.p * l.w, ls[(i + 1) % 3].p[i % 3]));"},
    {"const arrays of vectors",
     "const vec2 K[3] = vec2[3](vec2(1.0, 2.0), vec2(-3.0, 4.0), vec2(5.0, -6.0));",
     "outf(vec4(K[i % 3], K[(i / 3) % 3].yx));"},
    {"index from a float and a uint", "",
     "float a[4] = float[4](10.0, 20.0, 30.0, 40.0); outf(vec4(a[int(t * 3.99)], a[uint(i) % 4u], "
     "a[int(mod(float(i), 4.0))], "
     "1.0));"},
    {"vector indexed by a variable", "",
     "vec4 v = vec4(1.0, 2.0, 3.0, 4.0) * t; ivec3 w = ivec3(7, 8, 9); v[i % 4] = -1.0; w[i % 3] = i; "
     "outf(vec4(v[(i + 1) % 4], "
     "v[i % 4], float(w[(i / 3) % 3]), float(w.x + w.y + w.z)));"},
};

TEST(GlslConformance, DynamicIndexing) {
  for (const Program& f : kIndexing) {
    SCOPED_TRACE(f.name);
    reference::GlslDrawSpec spec =
        quad_spec(kVertex330, fragment2(f.decl, std::string("  ") + f.body, false));
    spec.outputs = 2;
    spec.uniforms = {{"k", {1.5f, -2.5f, 3.5f, -4.5f, 5.5f}},
                     {"v", {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}},
                     {"m[0]", {1, 2, 3, 4, 5, 6, 7, 8, 9}},
                     {"m[1]", {-1, -2, -3, -4, -5, -6, -7, -8, -9}},
                     {"ls[0].p", {1, 2, 3}},
                     {"ls[0].w", {0.5f}},
                     {"ls[1].p", {4, 5, 6}},
                     {"ls[1].w", {2.0f}},
                     {"ls[2].p", {-7, -8, -9}},
                     {"ls[2].w", {-1.0f}}};
    run_spec(f.name, spec, {0, 0});
  }
}

// Reads and writes out of an array's range are undefined in GLSL: only that they do not crash
// and that both tiers agree is checked (not Mesa).
TEST(GlslConformance, OutOfRangeIndicesAreSafe) {
  const Program cases[] = {
      {"float array read", "",
       "float a[4] = float[4](1.0, 2.0, 3.0, 4.0); outf(vec4(a[i - 128], a[i], a[-i], 0.0));"},
      {"array write", "",
       "float a[3] = float[3](1.0, 2.0, 3.0); a[i % 7 - 2] = 9.0; outf(vec4(a[0], a[1], a[2], 0.0));"},
      {"vector and matrix", "",
       "vec3 v = vec3(t); mat2 m = mat2(t); v[i % 5] = 1.0; outf(vec4(v, m[i % 3][i % 4]));"},
      {"uniform array", "uniform float k[5];", "outf(vec4(k[i], k[i * 1000], k[-1 - i], 0.0));"},
      {"struct array", "struct S { vec2 a; float b; };",
       "S s[2]; s[0] = S(vec2(1.0), 2.0); s[1] = S(vec2(3.0), 4.0); s[i % 4].b = 7.0; outf(vec4(s[i - 3].a, "
       "s[0].b, s[1].b));"},
  };
  for (const Program& f : cases) {
    SCOPED_TRACE(f.name);
    reference::GlslDrawSpec spec = quad_spec(kVertex330, fragment2(f.decl, std::string("  ") + f.body));
    spec.outputs = 2;
    spec.uniforms = {{"k", {1.5f, -2.5f, 3.5f, -4.5f, 5.5f}}};
    run_spec(f.name, spec, {0, 0}, 0xF, false);
  }
}

// --- derivatives ------------------------------------------------------------------------------------

// In uniform control flow only (inside non-uniform flow they are undefined). Tolerance 0:
// differences inside each 2x2 quad, as llvmpipe takes them.
TEST(GlslConformance, Derivatives) {
  const std::pair<const char*, int> exprs[] = {
      {"p.x", 1},
      {"p.y * p.y * 30.0", 1},
      {"sin(p.x * 9.0) * p.y", 1},
      {"vec2(p.x * p.y, p.x - p.y) * 7.0", 2},
      {"vec3(exp2(p.x * 4.0), sqrt(p.y), p.x / (p.y + 0.5))", 3},
      {"vec4(p, p * p) * 100.0", 4},
      {"floor(p.x * 12.0) + fract(p.y * 5.0)", 1},
      {"gl_FragCoord.xy * gl_FragCoord.yx", 2},
      {"float(i) * t", 1},
      {"abs(p.x - 0.5) * 64.0", 1},
      {"max(p.x, p.y) * 16.0", 1},
      {"vec2(length(p - 0.5), atan(p.y - 0.5, p.x - 0.51))", 2},
  };
  const char* fns[] = {"dFdx", "dFdy", "fwidth"};
  for (const auto& [e, n] : exprs)
    for (const char* f : fns)
      run2(fmt("%s(%s)", f, e), "", "  " + write_result('f', n, fmt("%s(%s)", f, e)), {0, 0});
  // Of a value computed in divergent flow, taken after the flow rejoins (uniform flow).
  run2("derivative after divergent flow", "",
       "  float v = p.x; if (i % 3 == 0) v = p.x * p.x * 10.0; else v = p.y * 4.0; outf(vec4(dFdx(v), "
       "dFdy(v), fwidth(v), 0.0));",
       {0, 0});
}

// --- varyings: perspective, noperspective, flat integers, gl_FragCoord, gl_FrontFacing ---------------

// Two triangles with a different w at each vertex (so perspective correction matters), one
// counter-clockwise and one clockwise; the shared edge misses the pixel centres.
reference::GlslDrawSpec varying_spec(const std::string& vs, const std::string& fs) {
  reference::GlslDrawSpec s;
  s.vertex = vs;
  s.fragment = fs;
  const float pos[] = {-1, -1, 1, -1, 1, 0.97f, -1, -0.97f, -1, 1, 1, 1};
  const float w[] = {1.0f, 2.5f, 0.6f, 1.7f, 0.8f, 3.0f};
  reference::GlslAttribute ap{"pos", 4, {}}, acol{"col", 4, {}}, aint{"bits", 4, {}, true, {}};
  for (int v = 0; v < 6; ++v) {
    ap.data.insert(ap.data.end(),
                   {pos[v * 2] * w[v], pos[v * 2 + 1] * w[v], (0.2f * float(v) - 0.5f) * w[v], w[v]});
    acol.data.insert(acol.data.end(), {float(v), 10.0f - float(v * v), 0.125f * float(v), -3.0f + float(v)});
    aint.idata.insert(aint.idata.end(),
                      {v * 1000 - 2500, int32_t(0x80000000u) + v, int32_t(0x7f800001) + v, -v});
  }
  s.attributes = {ap, acol, aint};
  s.count = 6;
  s.outputs = 4;
  return s;
}

TEST(GlslConformance, Varyings) {
  const char* vs = R"(#version 330
in vec4 pos; in vec4 col; in ivec4 bits;
out vec4 sm; noperspective out vec4 np; smooth out vec2 sm2; noperspective out float np1;
flat out int f1; flat out ivec2 f2; flat out uvec3 f3; flat out ivec4 f4; flat out float ff; flat out uvec4 f5;
void main() {
  gl_Position = pos;
  sm = col; np = col * 2.0 - 1.0; sm2 = col.yx; np1 = col.w;
  f1 = bits.x; f2 = bits.yz; f3 = uvec3(bits.zwx); f4 = bits; ff = col.y; f5 = uvec4(bits) * 3u;
})";
  // Tolerance for interpolated values (smooth, noperspective, gl_FragCoord.zw): llvmpipe
  // interpolates from its plane equations, Tessel from its setup's barycentric planes; they
  // differ by an ulp or two. Their derivatives are differences of two such values (up to
  // 10 here, an ulp ~1e-6): 4e-6 absolute. Flat values and gl_FrontFacing are exact.
  const Tolerance interp{2e-6f, 2e-6f};
  struct {
    const char* name;
    const char* body;
    Tolerance tol;
  } cases[] = {
      {"smooth and noperspective", "c = sm; c1 = np; c2 = vec4(sm2, np1, 0.0); c3 = vec4(0.0);", interp},
      {"flat integers of several sizes",
       "c = vec4(f1 >> 16, f1 & 0xFFFF, f2.x >> 16, f2.x & 0xFFFF); c1 = vec4(f2.y >> 16, f2.y & 0xFFFF, "
       "f3.xy >> 16u);"
       " c2 = vec4(f4.zw & 0xFFFF, f3.z >> 16u, ff); c3 = vec4(f5 >> 16u);",
       {0, 0}},
      {"gl_FragCoord and gl_FrontFacing",
       "c = gl_FragCoord; c1 = vec4(gl_FrontFacing ? 1.0 : -1.0, float(gl_FrontFacing), 0.0, 0.0); c2 = "
       "vec4(0.0);"
       " c3 = vec4(1.0 / gl_FragCoord.w);",
       interp},
      {"derivatives of varyings",
       "c = dFdx(sm); c1 = dFdy(np); c2 = vec4(fwidth(sm2), 0.0, 0.0); c3 = vec4(dFdx(gl_FragCoord.w));",
       {4e-6f, 1e-6f}},
  };
  for (const auto& k : cases) {
    SCOPED_TRACE(k.name);
    const std::string fs = std::string(R"(#version 330
in vec4 sm; noperspective in vec4 np; smooth in vec2 sm2; noperspective in float np1;
flat in int f1; flat in ivec2 f2; flat in uvec3 f3; flat in ivec4 f4; flat in float ff; flat in uvec4 f5;
layout(location = 0) out vec4 c; layout(location = 1) out vec4 c1; layout(location = 2) out vec4 c2;
layout(location = 3) out vec4 c3;
void main() { )") + k.body +
                           " }\n";
    run_spec(k.name, varying_spec(vs, fs), k.tol);
  }
}

// --- textures --------------------------------------------------------------------------------------

// A texture of pseudo-random texel values (so each level and filter weight shows).
reference::GlslTexture noise_texture(uint32_t target, int w, int h, int faces = 1) {
  reference::GlslTexture t;
  t.target = target;
  t.width = w;
  t.height = h;
  uint32_t x = 12345;
  for (int k = 0; k < w * h * faces * 4; ++k) {
    x = x * 1664525u + 1013904223u;
    t.data.push_back(float(x >> 8) / 16777216.0f);
  }
  return t;
}

const uint32_t kFilters[] = {0x2600, 0x2601, 0x2700, 0x2701, 0x2702, 0x2703};
const char* filter_name(uint32_t f) {
  switch (f) {
    case 0x2600: return "NEAREST";
    case 0x2601: return "LINEAR";
    case 0x2700: return "NEAREST_MIPMAP_NEAREST";
    case 0x2701: return "LINEAR_MIPMAP_NEAREST";
    case 0x2702: return "NEAREST_MIPMAP_LINEAR";
    default: return "LINEAR_MIPMAP_LINEAR";
  }
}
const uint32_t kWraps[] = {0x2901, 0x812F, 0x8370,
                           0x812D};  // REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT, CLAMP_TO_BORDER

// Tessel applies texel offsets in units of level 0's texels (docs/glsl.md, not yet fixed),
// GLSL in units of the level sampled: with a mipmap filter an offset is only checked tier
// against tier, not against Mesa.
bool offset_on_mip_levels(const std::string& body, const reference::GlslTexture& tx) {
  return body.find("Offset") != std::string::npos && body.find("texelFetch") == std::string::npos &&
         tx.mipmaps && tx.min_filter >= 0x2700;
}

void run_texture(const std::string& name, const std::string& decl, const std::string& body,
                 reference::GlslTexture tx, Tolerance tol, const std::string& version_fs = "") {
  SCOPED_TRACE(name);
  reference::GlslDrawSpec spec;
  if (version_fs.empty()) {
    spec = quad_spec(kVertex330, fragment2(decl, "  " + body));
  } else {
    spec = quad_spec(
        "#version 120\nattribute vec2 pos;\nvarying vec2 p;\nvoid main() { p = pos * 0.5 + 0.5; gl_Position "
        "= "
        "vec4(pos, 0.0, 1.0); }\n",
        version_fs);
  }
  spec.outputs = version_fs.empty() ? 2 : 1;
  spec.textures = {tx};
  spec.uniforms = {{"s", {}, {0}}};
  run_spec(name, spec, tol, 0xF, !offset_on_mip_levels(body, tx));
}

// The coordinates: uv crosses [0, 1] (wrapping) at a scale that grows down the rows, so that
// the implicit level of detail walks the mip chain.
const char* kUv = "vec2 uv = (p - 0.4) * exp2(p.y * 5.0 - 1.0) + 0.5;";

// Tolerance 1e-6 (a few ulp of values in [0, 1]): the mip levels come from glGenerateMipmap
// on one side and Texture2D::generate_mipmaps on the other, whose box filters round the last
// bit differently (NEAREST_MIPMAP_NEAREST on level 1 already differs by one ulp), and linear
// filtering blends in a different order of lerps. Texel choice, wrapping, level selection
// and offsets are exact: any of them wrong moves a result by far more.
const Tolerance kTexTol{1e-6f, 1e-6f};

TEST(GlslConformance, Texture2DFunctionsFiltersAndWraps) {
  const char* funcs[] = {
      "outf(texture(s, uv));",
      "outf(texture(s, uv, p.x * 3.0 - 1.0));",
      "outf(textureProj(s, vec3(uv * (1.0 + p.x), 1.0 + p.x)));",
      "outf(textureProj(s, vec4(uv * 2.0, 0.7, 2.0)));",
      "outf(textureLod(s, uv, p.x * 5.0 - 0.5));",
      "outf(textureOffset(s, uv, ivec2(1, -2)));",
      "outf(textureOffset(s, uv, ivec2(-3, 2), 0.5));",
      "outf(textureProjOffset(s, vec3(uv * 1.5, 1.5), ivec2(2, 1)));",
      "outf(textureLodOffset(s, uv, p.y * 4.0, ivec2(-1, 3)));",
      "outf(textureGrad(s, uv, vec2(p.x * 0.3, 0.01), vec2(0.02, p.y * 0.2)));",
      "outf(textureGradOffset(s, uv, vec2(0.05, p.x * 0.1), vec2(0.0, 0.3 * p.y), ivec2(2, -1)));",
      "outf(textureProjLod(s, vec3(uv, 1.0) * 2.0, p.y * 3.0));",
      "outf(textureProjGrad(s, vec4(uv, 0.0, 1.0) * 1.5, vec2(0.1 * p.x, 0.0), vec2(0.0, 0.07)));",
      "outf(texelFetch(s, ivec2(i % 16, i / 16) >> (i % 3), i % 3));",
      "outf(texelFetchOffset(s, ivec2(i % 8, i / 32), 1, ivec2(-1, 2)));",
      "outf(vec4(textureSize(s, 1), textureSize(s, 3)) + vec4(textureSize(s, 0), textureSize(s, 4)));",
  };
  int shaders = 0;
  for (const char* f : funcs)
    for (uint32_t filter : kFilters) {
      // Fetches and sizes do not filter: one filter for them.
      if ((std::string(f).find("texel") != std::string::npos ||
           std::string(f).find("Size") != std::string::npos) &&
          filter != 0x2703)
        continue;
      reference::GlslTexture tx = noise_texture(0x0DE1, 16, 16);
      tx.mipmaps = true;
      tx.min_filter = filter;
      tx.mag_filter = filter == 0x2600 || filter == 0x2700 || filter == 0x2702 ? 0x2600 : 0x2601;
      run_texture(std::string(f) + " " + filter_name(filter), "uniform sampler2D s;",
                  std::string(kUv) + " " + f, tx, kTexTol);
      ++shaders;
    }
  for (uint32_t wrap : kWraps)
    for (const char* f :
         {"outf(texture(s, uv * 2.0 - 0.5));", "outf(textureOffset(s, uv * 3.0 - 1.0, ivec2(-2, 3)));",
          "outf(textureLod(s, uv * 2.5 - 1.0, p.x * 3.0));"})
      for (uint32_t filter : {0x2600u, 0x2601u, 0x2703u}) {
        reference::GlslTexture tx = noise_texture(0x0DE1, 8, 4);
        tx.mipmaps = true;
        tx.wrap = wrap;
        tx.min_filter = filter;
        tx.mag_filter = filter == 0x2600 ? 0x2600 : 0x2601;
        run_texture(fmt("%s wrap 0x%x %s", f, wrap, filter_name(filter)), "uniform sampler2D s;",
                    std::string(kUv) + " " + f, tx, kTexTol);
        ++shaders;
      }
  std::printf("2D textures: %d shaders\n", shaders);
}

TEST(GlslConformance, Texture1DRectCubeAndShadow) {
  int shaders = 0;
  // sampler1D.
  const char* f1[] = {
      "outf(texture(s, uv.x));",
      "outf(texture(s, uv.x, 1.0));",
      "outf(textureProj(s, vec2(uv.x * 2.0, 2.0)));",
      "outf(textureLod(s, uv.x, p.y * 4.0));",
      "outf(textureOffset(s, uv.x, -3));",
      "outf(textureGrad(s, uv.x, p.x * 0.2, 0.0));",
      "outf(texelFetch(s, i % 16, 0) + vec4(textureSize(s, 1)));",
  };
  for (const char* f : f1)
    for (uint32_t filter : {0x2600u, 0x2703u}) {
      reference::GlslTexture tx = noise_texture(0x0DE0, 16, 1);
      tx.mipmaps = true;
      tx.min_filter = filter;
      tx.mag_filter = filter == 0x2600 ? 0x2600 : 0x2601;
      run_texture(std::string("1D ") + f + filter_name(filter), "uniform sampler1D s;",
                  std::string(kUv) + " " + f, tx, kTexTol);
      ++shaders;
    }
  // sampler2DRect: texel coordinates, no mipmaps.
  const char* fr[] = {
      "outf(texture(s, uv * vec2(12.0, 6.0)));",
      "outf(textureProj(s, vec3(uv * vec2(24.0, 12.0), 2.0)));",
      "outf(textureOffset(s, uv * vec2(12.0, 6.0), ivec2(2, -1)));",
      "outf(texelFetch(s, ivec2(i % 12, i / 48)) + vec4(textureSize(s), 0.0, 0.0));",
      "outf(textureGrad(s, uv * vec2(12.0, 6.0), vec2(1.0, 0.0), vec2(0.0, 3.0)));",
  };
  for (const char* f : fr)
    for (uint32_t filter : {0x2600u, 0x2601u}) {
      reference::GlslTexture tx = noise_texture(0x84F5, 12, 6);
      tx.min_filter = tx.mag_filter = filter;
      tx.wrap = 0x812F;
      run_texture(std::string("Rect ") + f + filter_name(filter), "uniform sampler2DRect s;",
                  std::string(kUv) + " " + f, tx, kTexTol);
      ++shaders;
    }
  // samplerCube: directions with one clearly largest axis (the face of a tie is the
  // implementation's), inside the face (seamless filtering across faces is off).
  const char* fc[] = {
      "outf(texture(s, vec3(p * 2.4 - 1.2, 1.6)));",
      "outf(texture(s, vec3(-1.7, p.yx * 2.0 - 1.0), 0.5));",
      "outf(textureLod(s, vec3(p.x - 0.5, -1.9, p.y - 0.5), p.x * 3.0));",
      "outf(textureGrad(s, vec3(1.8, p - 0.5), vec3(0.0, 0.1 * p.x, 0.0), vec3(0.0, 0.0, 0.05)));",
      // Gradients that minify (LOD 0 to about 3), with a major-axis part: the face's s and t
      // derivatives follow the quotient rule.
      "outf(textureGrad(s, vec3(p.x - 0.5, -1.5, p.y - 0.5), vec3(p.x * 2.0, 0.3, 0.0),"
      " vec3(0.0, -0.2 * p.y, p.y * 1.5)));",
      "outf(texture(s, vec3(p.x - 0.5, 1.1, p.y * 1.8 - 0.9)) + texture(s, vec3(p.yx - 0.5, -1.2)));",
      "outf(vec4(textureSize(s, 1), textureSize(s, 2)) + vec4(textureSize(s, 0), textureSize(s, 3)));",
  };
  for (const char* f : fc)
    for (uint32_t filter : {0x2600u, 0x2601u, 0x2703u}) {
      if (std::string(f).find("Size") != std::string::npos && filter != 0x2703) continue;
      reference::GlslTexture tx = noise_texture(0x8513, 8, 8, 6);
      tx.mipmaps = true;
      tx.min_filter = filter;
      tx.mag_filter = filter == 0x2600 ? 0x2600 : 0x2601;
      tx.wrap = 0x812F;
      run_texture(std::string("Cube ") + f + filter_name(filter), "uniform samplerCube s;",
                  std::string(kUv) + " " + f, tx, kTexTol);
      ++shaders;
    }
  // sampler2DShadow with every compare function.
  const char* fs[] = {
      "outf(vec4(texture(s, vec3(uv, p.x)), texture(s, vec3(uv.yx, 0.5), 0.5), 0.0, 1.0));",
      "outf(vec4(textureProj(s, vec4(uv * 2.0, p.y * 2.0, 2.0)), textureLod(s, vec3(uv, 0.4), 1.0), "
      "textureOffset(s, vec3(uv, p.x), ivec2(1, 1)), textureGrad(s, vec3(uv, 0.6), vec2(0.1, 0.0), vec2(0.0, "
      "0.1))));",
  };
  for (uint32_t func = 0x0200; func <= 0x0207; ++func)
    for (const char* f : fs) {
      reference::GlslTexture tx;
      tx.width = tx.height = 8;
      tx.internal_format = 0x8CAC;
      for (int k = 0; k < 64; ++k) tx.data.push_back(float((k * 37) % 64) / 63.0f);
      tx.compare = true;
      tx.compare_func = func;
      tx.min_filter = tx.mag_filter = func % 2 ? 0x2601 : 0x2600;
      tx.wrap = 0x812F;
      run_texture(fmt("2DShadow func 0x%x %s", func, f), "uniform sampler2DShadow s;",
                  std::string(kUv) + " " + f, tx, kTexTol);
      ++shaders;
    }
  std::printf("1D, Rect, Cube and shadow textures: %d shaders\n", shaders);
}

// The GLSL 1.10/1.20 names, through the compatibility path.
TEST(GlslConformance, TextureLegacyNames) {
  struct {
    uint32_t target;
    const char* decl;
    const char* body;
  } cases[] = {
      {0x0DE1, "uniform sampler2D s;", "gl_FragColor = texture2D(s, uv) + texture2D(s, uv.yx, 1.0);"},
      {0x0DE1, "uniform sampler2D s;",
       "gl_FragColor = texture2DProj(s, vec3(uv, 1.0) * 1.5) + texture2DProj(s, vec4(uv, 0.3, 1.0));"},
      {0x0DE0, "uniform sampler1D s;",
       "gl_FragColor = texture1D(s, uv.x) + texture1DProj(s, vec2(uv.x, 1.0) * 2.0);"},
      {0x8513, "uniform samplerCube s;",
       "gl_FragColor = textureCube(s, vec3(p - 0.5, 1.5)) + textureCube(s, vec3(-1.5, p - 0.5), 1.0);"},
      {0, "uniform sampler2DShadow s;",
       "gl_FragColor = shadow2D(s, vec3(uv, p.x)) + shadow2DProj(s, vec4(uv, p.y, 1.0) * 2.0);"},
  };
  for (const auto& k : cases) {
    reference::GlslTexture tx;
    if (k.target == 0) {
      tx.width = tx.height = 8;
      tx.internal_format = 0x8CAC;
      for (int q = 0; q < 64; ++q) tx.data.push_back(float((q * 29) % 64) / 63.0f);
      tx.compare = true;
    } else {
      tx = noise_texture(k.target, 8, k.target == 0x0DE0 ? 1 : 8, k.target == 0x8513 ? 6 : 1);
      tx.mipmaps = true;
    }
    tx.min_filter = 0x2703;
    tx.mag_filter = 0x2601;
    tx.wrap = 0x812F;
    const std::string fs = std::string("#version 120\nvarying vec2 p;\n") + k.decl + "\nvoid main() {\n  " +
                           kUv + "\n  " + k.body + "\n}\n";
    run_texture(k.body, "", "", tx, kTexTol, fs);
  }
}

// --- the set catches wrong results at the edges ------------------------------------------------------

// A min() that does not return the other operand for a NaN, a roundEven() that rounds halves
// up, and an int() that does not give INT_MIN out of range all differ from Mesa on the edge
// values of the tables, at the tables' tolerance (0).
TEST(GlslConformance, EdgeValuesCatchAWrongResult) {
  if (!oracle()) GTEST_SKIP() << "Mesa llvmpipe is not available";
  const std::string decl = tables() + generators(-10, 10, true) + generators(-10, 10, false, "0");
  const std::pair<const char*, const char*> pairs[] = {
      {"float a = genf(i); float b = genf((i * 3 + 11) & 255); outf(vec4(min(a, b), max(a, b), 0.0, 0.0));",
       "float a = genf(i); float b = genf((i * 3 + 11) & 255); outf(vec4(a < b ? a : b, a > b ? a : b, 0.0, "
       "0.0));"},
      {"float a = genf(i); outf(vec4(roundEven(a), 0.0, 0.0, 0.0));",
       "float a = genf(i); outf(vec4(floor(a + 0.5), 0.0, 0.0, 0.0));"},
      {"float a = genf(i); outi(uvec4(int(a), 0, 0, 0));",
       "float a = genf(i); outi(uvec4(int(clamp(a, -2147483520.0, 2147483520.0)), 0, 0, 0));"},
  };
  for (const auto& [right, wrong] : pairs) {
    SCOPED_TRACE(right);
    reference::GlslDrawSpec spec = quad_spec(kVertex330, fragment2(decl, std::string("  ") + right));
    spec.outputs = 2;
    const reference::GlslResult mesa = oracle()->run(spec);
    ASSERT_TRUE(mesa.ok) << mesa.log;
    const TesselResult ours = run_tessel(spec);
    ASSERT_TRUE(ours.ok) << ours.log;
    EXPECT_EQ(compare_floats(ours.outputs[0], mesa.outputs[0], 16, {0, 0}).count +
                  compare_floats(ours.outputs[1], mesa.outputs[1], 16, {0, 0}).count,
              0);
    spec.fragment = fragment2(decl, std::string("  ") + wrong);
    const TesselResult bad = run_tessel(spec);
    ASSERT_TRUE(bad.ok) << bad.log;
    EXPECT_GT(compare_floats(bad.outputs[0], mesa.outputs[0], 16, {0, 0}).count +
                  compare_floats(bad.outputs[1], mesa.outputs[1], 16, {0, 0}).count,
              0);
  }
}

// How many shaders were compared, when the tests run in one process (not under ctest, which
// runs each test alone).
class CountShaders : public ::testing::Environment {
 public:
  void TearDown() override {
    if (shaders_compared() > 0)
      std::printf("GLSL shaders compared with Mesa or between tiers: %d\n", shaders_compared());
  }
};
[[maybe_unused]] ::testing::Environment* const kCount = ::testing::AddGlobalTestEnvironment(new CountShaders);

}  // namespace
}  // namespace tessel::testing
