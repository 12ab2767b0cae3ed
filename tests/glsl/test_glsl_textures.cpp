// 3D, array, shadow and buffer textures: the same GLSL on Tessel and on Mesa llvmpipe, into
// RGBA32F targets, compared value for value with the tolerance stated per group (as
// test_glsl_mesa.cpp does for 2D and cube textures), and the interpreter against the JIT.
// Several shaders share one gtest test, so that ctest starts few processes.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "mesa_case.hpp"

namespace tessel::testing {
namespace {

// GL enums.
constexpr uint32_t kNearest = 0x2600, kLinear = 0x2601, kNearestMipmapNearest = 0x2700,
                   kLinearMipmapLinear = 0x2703;
constexpr uint32_t kRepeat = 0x2901, kClampToEdge = 0x812F, kMirroredRepeat = 0x8370, kClampToBorder = 0x812D;
constexpr uint32_t kTex1D = 0x0DE0, kTex3D = 0x806F, kTexCube = 0x8513, kTex2DArray = 0x8C1A,
                   kTex1DArray = 0x8C18, kTexBuffer = 0x8C2A;
constexpr uint32_t kDepth32F = 0x8CAC, kRGBA32I = 0x8D82, kRGBA32UI = 0x8D70, kRGBA8 = 0x8058;

// Draws `body` with `tex` on unit 0 (sampler uniform `tex`, declared by `decl`) on both sides.
void run(const std::string& decl, const std::string& body, const reference::GlslTexture& tex, Tolerance tol) {
  SCOPED_TRACE(body);
  reference::GlslDrawSpec spec = quad_spec(kVertex330, fragment330(decl, body));
  spec.textures = {tex};
  spec.uniforms = {{"tex", {}, {0}}};
  run_spec(body, spec, tol);
}

// A colour texture of w x h x d texels (d slices, layers, or 1): red, green and blue ramp
// with x, y and z, alpha tells neighbours apart.
reference::GlslTexture colour_texture(uint32_t target, int w, int h, int d) {
  reference::GlslTexture t;
  t.target = target;
  t.width = w;
  t.height = h;
  t.depth = d;
  for (int z = 0; z < d; ++z)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        t.data.insert(t.data.end(), {float(x) / float(w), float(y) / float(h), float(z + 1) / float(d + 1),
                                     ((x ^ y ^ z) & 1) ? 1.0f : 0.25f});
  return t;
}

// Integer texels (x, y - 3, z, x * y + z), read with NEAREST filtering as integer textures need.
reference::GlslTexture integer_texture(uint32_t target, int w, int h, int d, bool is_unsigned) {
  reference::GlslTexture t;
  t.target = target;
  t.width = w;
  t.height = h;
  t.depth = d;
  t.internal_format = is_unsigned ? kRGBA32UI : kRGBA32I;
  for (int z = 0; z < d; ++z)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        t.data.insert(t.data.end(), {float(x), float(is_unsigned ? y : y - 3), float(z), float(x * y + z)});
  return t;
}

// A depth texture of w x h x d (layers, or 6 cube faces) with values spread over [0, 1].
reference::GlslTexture depth_texture(uint32_t target, int w, int h, int d) {
  reference::GlslTexture t;
  t.target = target;
  t.width = w;
  t.height = h;
  t.depth = target == kTexCube ? 1 : d;
  t.internal_format = kDepth32F;
  for (int k = 0; k < w * h * d; ++k) t.data.push_back(float((k * 37) % 64) / 63.0f);
  t.compare = true;
  t.min_filter = t.mag_filter = kLinear;
  t.wrap = kClampToEdge;
  return t;
}

reference::GlslTexture filtered(reference::GlslTexture t, uint32_t min, uint32_t mag, uint32_t wrap,
                                bool mipmaps = false) {
  t.min_filter = min;
  t.mag_filter = mag;
  t.wrap = wrap;
  t.mipmaps = mipmaps;
  return t;
}

// Float textures filter as llvmpipe does, up to rounding in the order of the arithmetic.
constexpr Tolerance kFiltered{1e-5f, 1e-5f};
// Fetches, sizes, nearest lookups and integer textures: exact.
constexpr Tolerance kExact{0, 0};

// --- sampler3D ---------------------------------------------------------------------------------

// Texel offsets on a mipmapped 2D texture move by texels of the level sampled (GL 3.3
// §3.8.11), for implicit, explicit and gradient LODs, trilinear and nearest-mipmap filters.
// (No LOD at exactly n + 0.5: there llvmpipe's nearest level rounds up, GL's formula down.)
TEST(GlslTextures, Sampler2DOffsetsOnMipLevels) {
  constexpr uint32_t kTex2D = 0x0DE1;
  for (const uint32_t min : {kLinearMipmapLinear, kNearestMipmapNearest}) {
    const auto tex = filtered(colour_texture(kTex2D, 32, 32, 1), min, kLinear, kRepeat, true);
    for (const char* body : {
             "c = textureOffset(tex, p * 3.0, ivec2(1, -2));",
             "c = textureLodOffset(tex, p, 1.3 + 0.9 * t, ivec2(-3, 2));",
             "c = textureGradOffset(tex, p, vec2(0.2, 0.0), vec2(0.0, 0.1 * t), ivec2(2, 1));",
             "c = textureProjOffset(tex, vec3(p * 2.0, 0.5), ivec2(-1, -1));",
             "c = textureOffset(tex, p * 5.0, ivec2(7, -8), 0.5);",
         })
      run("uniform sampler2D tex;", body, tex, kFiltered);
  }
}

TEST(GlslTextures, Sampler3DFiltersAndWraps) {
  const std::string decl = "uniform sampler3D tex;";
  const reference::GlslTexture base = colour_texture(kTex3D, 8, 4, 4);
  for (uint32_t wrap : {kRepeat, kClampToEdge, kMirroredRepeat, kClampToBorder}) {
    SCOPED_TRACE(wrap);
    run(decl, "c = texture(tex, vec3(p * 1.6 - 0.31, t * 1.8 - 0.4));",
        filtered(base, kNearest, kNearest, wrap), kExact);
    run(decl, "c = texture(tex, vec3(p.yx * 1.6 - 0.31, t * 1.8 - 0.4));",
        filtered(base, kLinear, kLinear, wrap), kFiltered);
  }
}

TEST(GlslTextures, Sampler3DFunctions) {
  const std::string decl = "uniform sampler3D tex;";
  const reference::GlslTexture mip =
      filtered(colour_texture(kTex3D, 8, 8, 4), kLinearMipmapLinear, kLinear, kRepeat, true);
  const char* bodies[] = {
      // Implicit LOD from derivatives along all three axes (rho uses the depth too).
      "c = texture(tex, vec3(p.x * 5.0, p.y * 2.0, (p.x + p.y) * 3.0));",
      "c = texture(tex, vec3(p * 0.5, p.x * 9.0));",
      "c = texture(tex, vec3(p * 3.0, t), 0.7);",
      "c = textureLod(tex, vec3(p, 1.0 - t), t * 3.5 - 0.5);",
      "c = textureGrad(tex, vec3(p, t), vec3(t * 0.5, 0.0, 0.0), vec3(0.0, 0.125, t * 0.4));",
      "c = textureProj(tex, vec4(p * 2.0, t * 2.0, 2.0));",
      "c = textureOffset(tex, vec3(p, t), ivec3(1, -2, 1));",
      "c = textureLodOffset(tex, vec3(p, t), 1.0, ivec3(-1, 0, 1));",
      "c = textureProjLod(tex, vec4(p, t, 1.0) * 1.5, 0.5);",
      "c = textureGradOffset(tex, vec3(p, t), vec3(0.2, 0.0, 0.0), vec3(0.0, 0.1, 0.1), ivec3(0, 1, -1));",
  };
  for (const char* body : bodies) run(decl, body, mip, kFiltered);
  const char* exact[] = {
      "c = texelFetch(tex, ivec3(i % 8, (i / 8) % 8, i / 64), 0);",
      "c = texelFetch(tex, ivec3(i % 4, (i / 4) % 4, i / 16 - 7), 1);",  // slices out of range too
      "c = texelFetchOffset(tex, ivec3(i % 4, i / 64, 1), 0, ivec3(2, 1, 1));",
      "c = vec4(textureSize(tex, 0), 0.0) + vec4(textureSize(tex, 1), 0.0) * 100.0 + vec4(0.0, 0.0, 0.0, "
      "textureSize(tex, 3).z);",
      "c = textureLod(tex, vec3(p, t), 2.0 + float(i % 3));",
  };
  for (const char* body : exact)
    run(decl, body, filtered(mip, kNearestMipmapNearest, kNearest, kRepeat, true), kExact);
}

TEST(GlslTextures, Sampler3DIntegerAndOldName) {
  run("uniform isampler3D tex;",
      "c = vec4(texture(tex, vec3(p, t) * 1.2)) + vec4(texelFetch(tex, ivec3(i % 4, 1, i / 64), 0));",
      integer_texture(kTex3D, 4, 4, 4, false), kExact);
  run("uniform usampler3D tex;", "c = vec4(texture(tex, vec3(p.yx, t))) + vec4(textureSize(tex, 0), 0.0);",
      integer_texture(kTex3D, 4, 2, 8, true), kExact);
  // GLSL 1.10's texture3D, in a 1.20 shader.
  reference::GlslDrawSpec spec;
  spec.vertex =
      "#version 120\nattribute vec2 pos;\nvarying vec2 p;\nvoid main() { p = pos * 0.5 + 0.5; gl_Position = "
      "vec4(pos, 0.0, 1.0); }\n";
  spec.fragment =
      "#version 120\nuniform sampler3D tex;\nvarying vec2 p;\nvoid main() {\n"
      "  gl_FragColor = texture3D(tex, vec3(p, p.x * p.y)) + texture3DProj(tex, vec4(p, 0.5, 2.0)) +\n"
      "                 texture3D(tex, vec3(p.yx, 0.3), 0.5);\n}\n";
  spec.attributes.push_back({"pos", 2, {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1}});
  spec.count = 6;
  spec.textures = {filtered(colour_texture(kTex3D, 8, 8, 4), kLinearMipmapLinear, kLinear, kRepeat, true)};
  spec.uniforms = {{"tex", {}, {0}}};
  run_spec("texture3D", spec, kFiltered);
}

// --- sampler2DArray and sampler1DArray ------------------------------------------------------------

TEST(GlslTextures, Sampler2DArray) {
  const std::string decl = "uniform sampler2DArray tex;";
  const reference::GlslTexture base = colour_texture(kTex2DArray, 8, 8, 5);
  // Layers from -1.5 to 5.5 (out of range on both sides), and exactly halfway between layers.
  for (uint32_t wrap : {kRepeat, kClampToEdge, kMirroredRepeat, kClampToBorder}) {
    SCOPED_TRACE(wrap);
    run(decl, "c = texture(tex, vec3(p * 1.6 - 0.31, t * 7.0 - 1.5));",
        filtered(base, kNearest, kNearest, wrap), kExact);
    run(decl, "c = texture(tex, vec3(p.yx * 1.6 - 0.31, t * 7.0 - 1.5));",
        filtered(base, kLinear, kLinear, wrap), kFiltered);
  }
  run(decl, "c = texture(tex, vec3(p, float(i % 16) * 0.5 - 1.5));",
      filtered(base, kNearest, kNearest, kRepeat), kExact);
  run(decl, "c = texture(tex, vec3(p, float(i % 16) * 0.5 - 1.5 + (t - 0.5) * 1e-6));",
      filtered(base, kNearest, kNearest, kRepeat), kExact);
  const reference::GlslTexture mip = filtered(base, kLinearMipmapLinear, kLinear, kRepeat, true);
  const char* bodies[] = {
      "c = texture(tex, vec3(p * 4.0, t * 5.0));",
      "c = texture(tex, vec3(p * 2.0, 2.0), 0.6);",
      "c = textureLod(tex, vec3(p, t * 4.0), t * 3.5 - 0.5);",
      "c = textureGrad(tex, vec3(p, 3.2), vec2(t * 0.5, 0.0), vec2(0.0, 0.25));",
      "c = textureOffset(tex, vec3(p, t * 4.0), ivec2(1, -2));",
      "c = textureLodOffset(tex, vec3(p, 1.0), 1.0, ivec2(-1, 1));",
      "c = textureGradOffset(tex, vec3(p, 4.0), vec2(0.3, 0.0), vec2(0.0, 0.1), ivec2(2, 0));",
  };
  for (const char* body : bodies) run(decl, body, mip, kFiltered);
  const char* exact[] = {
      // Integer layers out of range read 0 as other out-of-range texels do.
      "c = texelFetch(tex, ivec3(i % 8, (i / 8) % 8, i / 32 - 1), 0);",
      "c = texelFetchOffset(tex, ivec3(i % 4, i / 64, i % 5), 1, ivec2(-1, 1));",
      "c = vec4(textureSize(tex, 0), 1.0) + vec4(textureSize(tex, 2), 0.0) * 100.0;",
  };
  for (const char* body : exact)
    run(decl, body, filtered(mip, kNearestMipmapNearest, kNearest, kRepeat, true), kExact);
  run("uniform isampler2DArray tex;",
      "c = vec4(texture(tex, vec3(p * 1.3, t * 6.0 - 1.0))) + vec4(texelFetch(tex, ivec3(i % 4, 2, i / 64), "
      "0));",
      integer_texture(kTex2DArray, 4, 4, 4, false), kExact);
  run("uniform usampler2DArray tex;",
      "c = vec4(texture(tex, vec3(p, t * 3.0))) + vec4(textureSize(tex, 0), 0.0);",
      integer_texture(kTex2DArray, 4, 2, 3, true), kExact);
}

TEST(GlslTextures, Sampler1DArray) {
  const std::string decl = "uniform sampler1DArray tex;";
  // GL_TEXTURE_1D_ARRAY: height is the layer count.
  const reference::GlslTexture base = colour_texture(kTex1DArray, 16, 4, 1);
  for (uint32_t wrap : {kRepeat, kClampToEdge, kMirroredRepeat, kClampToBorder}) {
    SCOPED_TRACE(wrap);
    run(decl, "c = texture(tex, vec2(p.x * 1.6 - 0.31, p.y * 6.0 - 1.0));",
        filtered(base, kNearest, kNearest, wrap), kExact);
    run(decl, "c = texture(tex, vec2(p.y * 1.6 - 0.31, p.x * 6.0 - 1.0));",
        filtered(base, kLinear, kLinear, wrap), kFiltered);
  }
  const reference::GlslTexture mip = filtered(base, kLinearMipmapLinear, kLinear, kRepeat, true);
  const char* bodies[] = {
      "c = texture(tex, vec2(p.x * 6.0, t * 3.0));",
      "c = texture(tex, vec2(p.x, float(i % 8) * 0.5 - 0.5), 1.5);",
      "c = textureLod(tex, vec2(p.x, t * 3.0), t * 4.5 - 0.5);",
      "c = textureGrad(tex, vec2(p.x, 2.0), t * 0.5, 0.0);",
      "c = textureOffset(tex, vec2(p.x, t * 3.0), -3);",
  };
  for (const char* body : bodies) run(decl, body, mip, kFiltered);
  run(decl,
      "c = texelFetch(tex, ivec2(i % 16, i / 16 - 5), 0) + texelFetch(tex, ivec2(i % 8, 1), 1) + "
      "vec4(textureSize(tex, 1), 0.0, 0.0);",
      filtered(mip, kNearestMipmapNearest, kNearest, kRepeat, true), kExact);
  run("uniform usampler1DArray tex;",
      "c = vec4(texture(tex, vec2(p.x, t * 5.0))) + vec4(texelFetch(tex, ivec2(i % 8, i / 64), 0));",
      integer_texture(kTex1DArray, 8, 4, 1, true), kExact);
  run("uniform isampler1DArray tex;",
      "c = vec4(texture(tex, vec2(p.y, t * 5.0))) + vec4(textureSize(tex, 0), 0.0, 0.0);",
      integer_texture(kTex1DArray, 8, 4, 1, false), kExact);
}

// --- shadow samplers --------------------------------------------------------------------------

TEST(GlslTextures, ShadowSamplers) {
  // Nearest and linear (percentage-closer) filtering; each compare function on one of them.
  for (uint32_t filter : {kNearest, kLinear}) {
    SCOPED_TRACE(filter);
    reference::GlslTexture d1 = depth_texture(kTex1D, 16, 1, 1);
    d1.min_filter = d1.mag_filter = filter;
    run("uniform sampler1DShadow tex;",
        "c = vec4(texture(tex, vec3(p.x * 1.2 - 0.1, 0.0, t)), textureProj(tex, vec4(p.y * 2.0, 0.0, 1.0, "
        "2.0)),"
        " textureLod(tex, vec3(p.x, 0.0, 0.5), 0.0), 1.0);",
        d1, kFiltered);
    reference::GlslTexture a2 = depth_texture(kTex2DArray, 8, 8, 3);
    a2.min_filter = a2.mag_filter = filter;
    run("uniform sampler2DArrayShadow tex;",
        "c = vec4(texture(tex, vec4(p * 1.2 - 0.1, t * 4.0 - 0.7, 0.5)), texture(tex, vec4(p.yx, 1.0, t)),"
        " textureGrad(tex, vec4(p, 2.0, 0.4), vec2(0.1, 0.0), vec2(0.0, 0.1)), 1.0);",
        a2, kFiltered);
    reference::GlslTexture a1 = depth_texture(kTex1DArray, 16, 3, 1);
    a1.min_filter = a1.mag_filter = filter;
    run("uniform sampler1DArrayShadow tex;",
        "c = vec4(texture(tex, vec3(p.x, t * 4.0 - 0.5, p.y)), textureLod(tex, vec3(p.y, 1.0, 0.5), 0.0), "
        "0.0, 1.0);",
        a1, kFiltered);
    // Directions with one clearly largest axis (the face of a tie is the implementation's).
    reference::GlslTexture cube = depth_texture(kTexCube, 4, 4, 6);
    cube.min_filter = cube.mag_filter = filter;
    run("uniform samplerCubeShadow tex;",
        "c = vec4(texture(tex, vec4(p * 2.0 - 1.0, 1.7, t)), texture(tex, vec4(1.0, p.yx - 0.5, 0.5)),"
        " texture(tex, vec4(p.x - 0.5, -1.3, p.y - 0.5, 1.0 - t)), texture(tex, vec4(-1.5, p - 0.5, t)));",
        cube, kFiltered);
  }
  for (uint32_t func = 0x0200; func <= 0x0207; ++func) {
    SCOPED_TRACE(func);
    reference::GlslTexture a2 = depth_texture(kTex2DArray, 8, 8, 2);
    a2.compare_func = func;
    run("uniform sampler2DArrayShadow tex;",
        "float v = texture(tex, vec4(p, p.x * 2.0, t)); c = vec4(v, v, v, 1.0);", a2, kFiltered);
    reference::GlslTexture cube = depth_texture(kTexCube, 4, 4, 6);
    cube.compare_func = func;
    cube.min_filter = cube.mag_filter = kNearest;
    run("uniform samplerCubeShadow tex;",
        "float v = texture(tex, vec4(p * 2.0 - 1.0, -1.6, t)); c = vec4(v, 0.0, 0.0, 1.0);", cube, kExact);
  }
  reference::GlslTexture cube = depth_texture(kTexCube, 4, 4, 6);
  run("uniform samplerCubeShadow tex;", "c = vec4(vec2(textureSize(tex, 0)), 0.0, 1.0);", cube, kExact);
}

// --- samplerBuffer ---------------------------------------------------------------------------

TEST(GlslTextures, SamplerBuffer) {
  // 100 texels fetched at -20..235: in range and out of range on both sides.
  reference::GlslTexture buf = colour_texture(kTexBuffer, 100, 1, 1);
  run("uniform samplerBuffer tex;",
      "c = texelFetch(tex, i - 20) + vec4(0.0, 0.0, 0.0, float(textureSize(tex)));", buf, kExact);
  run("uniform isamplerBuffer tex;", "c = vec4(texelFetch(tex, i - 20)) + vec4(float(textureSize(tex)));",
      integer_texture(kTexBuffer, 100, 1, 1, false), kExact);
  run("uniform usamplerBuffer tex;", "c = vec4(texelFetch(tex, 255 - i * 2));",
      integer_texture(kTexBuffer, 100, 1, 1, true), kExact);
}

// RGBA8 3D and array textures: llvmpipe filters them in 8-bit fixed point and returns 8-bit
// results; Tessel filters them in float (its 16-bit fixed-point path is the 2D texture() one),
// so linear results differ by up to about one step of 8-bit colour (measured: 4.6e-3 at most,
// where mip levels of high contrast are blended). Fetches are exact.
TEST(GlslTextures, Rgba8WithinTwoSteps) {
  constexpr Tolerance kTwoSteps{2.0f / 255.0f, 0};
  reference::GlslTexture t3 =
      filtered(colour_texture(kTex3D, 8, 8, 4), kLinearMipmapLinear, kLinear, kRepeat, true);
  t3.internal_format = kRGBA8;
  run("uniform sampler3D tex;", "c = texture(tex, vec3(p.yx * 1.6 - 0.31, t * 1.8 - 0.4));", t3, kTwoSteps);
  run("uniform sampler3D tex;", "c = textureLod(tex, vec3(p.yx * 1.6 - 0.31, t * 1.8 - 0.4), 0.5);", t3,
      kTwoSteps);
  run("uniform sampler3D tex;", "c = texelFetch(tex, ivec3(i % 8, (i / 8) % 8, i / 64), 0);", t3, kExact);
  reference::GlslTexture a =
      filtered(colour_texture(kTex2DArray, 8, 8, 4), kLinearMipmapLinear, kLinear, kRepeat, true);
  a.internal_format = kRGBA8;
  run("uniform sampler2DArray tex;", "c = texture(tex, vec3(p.yx * 1.6 - 0.31, t * 4.0));", a, kTwoSteps);
  run("uniform sampler2DArray tex;", "c = textureLod(tex, vec3(p.yx * 1.6 - 0.31, t * 4.0), 0.4);", a,
      kTwoSteps);
}

// Reflection: the GL type enums of the new sampler types.
TEST(GlslTextures, SamplerTypeEnums) {
  const char* vs = "#version 330\nvoid main() { gl_Position = vec4(0.0); }\n";
  const std::string fs = fragment330(
      "uniform sampler3D a; uniform sampler2DArray b; uniform sampler1DArray c1; uniform sampler1DShadow d;"
      " uniform sampler2DArrayShadow e; uniform samplerCubeShadow f; uniform samplerBuffer g; uniform "
      "isampler3D h;"
      " uniform usampler2DArray k; uniform isamplerBuffer l; uniform usamplerBuffer m; uniform "
      "sampler1DArrayShadow n;",
      "c = texture(a, vec3(t)) + texture(b, vec3(t)) + texture(c1, vec2(t)) + vec4(texture(d, vec3(t)) + "
      "texture(e, vec4(t)) +"
      " texture(f, vec4(t)) + texture(n, vec3(t))) + texelFetch(g, i) + vec4(texture(h, vec3(t))) + "
      "vec4(texture(k, vec3(t))) +"
      " vec4(texelFetch(l, i)) + vec4(texelFetch(m, i));");
  auto v = glsl::Shader::compile(glsl::Stage::Vertex, vs);
  auto f = glsl::Shader::compile(glsl::Stage::Fragment, fs);
  ASSERT_TRUE(f->ok()) << f->info_log();
  auto prog = glsl::Program::link(*v, *f);
  ASSERT_TRUE(prog->ok()) << prog->info_log();
  std::map<std::string, uint32_t> types;
  for (const auto& u : prog->uniforms()) types[u.name] = u.type;
  EXPECT_EQ(types["a"], 0x8B5Fu);   // GL_SAMPLER_3D
  EXPECT_EQ(types["b"], 0x8DC1u);   // GL_SAMPLER_2D_ARRAY
  EXPECT_EQ(types["c1"], 0x8DC0u);  // GL_SAMPLER_1D_ARRAY
  EXPECT_EQ(types["d"], 0x8B61u);   // GL_SAMPLER_1D_SHADOW
  EXPECT_EQ(types["e"], 0x8DC4u);   // GL_SAMPLER_2D_ARRAY_SHADOW
  EXPECT_EQ(types["f"], 0x8DC5u);   // GL_SAMPLER_CUBE_SHADOW
  EXPECT_EQ(types["g"], 0x8DC2u);   // GL_SAMPLER_BUFFER
  EXPECT_EQ(types["h"], 0x8DCBu);   // GL_INT_SAMPLER_3D
  EXPECT_EQ(types["k"], 0x8DD7u);   // GL_UNSIGNED_INT_SAMPLER_2D_ARRAY
  EXPECT_EQ(types["l"], 0x8DD0u);   // GL_INT_SAMPLER_BUFFER
  EXPECT_EQ(types["m"], 0x8DD8u);   // GL_UNSIGNED_INT_SAMPLER_BUFFER
  EXPECT_EQ(types["n"], 0x8DC3u);   // GL_SAMPLER_1D_ARRAY_SHADOW
}

}  // namespace
}  // namespace tessel::testing
