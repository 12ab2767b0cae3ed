// The glsl layer's own rules: info logs, link errors, reflection, uniforms, bad input.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "tessel_runner.hpp"

namespace tessel::testing {
namespace {

using glsl::LinkOptions;
using glsl::NativeCode;
using glsl::Program;
using glsl::Shader;
using glsl::Stage;

const char* kVs = R"(#version 330
layout(location = 0) in vec2 pos;
out vec2 p;
void main() { p = pos * 0.5 + 0.5; gl_Position = vec4(pos, 0.0, 1.0); }
)";

std::shared_ptr<Program> link_fs(const std::string& fs) {
  auto v = Shader::compile(Stage::Vertex, kVs);
  auto f = Shader::compile(Stage::Fragment, fs);
  EXPECT_TRUE(v->ok()) << v->info_log();
  EXPECT_TRUE(f->ok()) << f->info_log();
  return Program::link(*v, *f);
}

// A full-screen quad of width x height drawn with kVs and `fs`.
reference::GlslDrawSpec quad(const std::string& fs, int width = 16, int height = 16) {
  reference::GlslDrawSpec s;
  s.vertex = kVs;
  s.fragment = fs;
  s.width = width;
  s.height = height;
  s.attributes.push_back({"pos", 2, {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1}});
  s.count = 6;
  return s;
}

// Draws a full-screen quad of 16x16 with `fs` and returns output 0.
std::vector<float> draw(const std::string& fs, std::string* log = nullptr) {
  TesselResult r = run_tessel(quad(fs));
  if (log) *log = r.log;
  return r.ok ? r.outputs[0] : std::vector<float>{};
}

TEST(Glsl, CompileErrorNamesTheLine) {
  auto s =
      Shader::compile(Stage::Fragment, "#version 330\nout vec4 c;\nvoid main() {\n  c = vec4(foo);\n}\n");
  EXPECT_FALSE(s->ok());
  // The form GL drivers print: string:line, then the kind.
  EXPECT_EQ(s->info_log().rfind("0:4: error: ", 0), 0u) << s->info_log();
  EXPECT_NE(s->info_log().find("foo"), std::string::npos) << s->info_log();
  EXPECT_EQ(s->info_log().find("ERROR"), std::string::npos) << s->info_log();
  // A program that fails to link says why, in the same form.
  auto vs = Shader::compile(Stage::Vertex, "#version 330\nvoid main() { gl_Position = vec4(0.0); }\n");
  auto fs = Shader::compile(Stage::Fragment, "#version 330\nout vec4 c;\nvoid helper() { c = vec4(1.0); }\n");
  ASSERT_TRUE(vs->ok() && fs->ok()) << fs->info_log();
  auto p = Program::link(*vs, *fs);
  EXPECT_FALSE(p->ok());
  EXPECT_EQ(p->info_log().rfind("error: ", 0), 0u) << p->info_log();
}

TEST(Glsl, VersionsAndCompatibilityBuiltinsCompile) {
  EXPECT_TRUE(Shader::compile(Stage::Vertex, "void main() { gl_Position = ftransform(); }")->ok());
  EXPECT_TRUE(
      Shader::compile(
          Stage::Vertex,
          "#version 120\nattribute vec3 a; varying vec3 n;\nvoid main() { n = gl_NormalMatrix * gl_Normal;"
          " gl_Position = gl_ModelViewProjectionMatrix * vec4(a, 1.0); }")
          ->ok());
  EXPECT_TRUE(
      Shader::compile(Stage::Fragment,
                      "#version 130\nprecision highp float; out vec4 c; void main() { c = vec4(1.0); }")
          ->ok());
  EXPECT_TRUE(
      Shader::compile(Stage::Fragment, "#version 150\nout vec4 c; void main() { c = vec4(1.0); }")->ok());
  // ftransform() is in compatibility vertex shaders only: a core one gets an error on its line.
  auto core = Shader::compile(Stage::Vertex, "#version 330\n\nvoid main() { gl_Position = ftransform(); }\n");
  EXPECT_FALSE(core->ok());
  EXPECT_NE(core->info_log().find("0:3"), std::string::npos) << core->info_log();
}

TEST(Glsl, LinkErrors) {
  // A varying the vertex shader does not write.
  auto p = link_fs("#version 330\nin vec3 missing; out vec4 c; void main() { c = vec4(missing, 1.0); }");
  EXPECT_FALSE(p->ok());
  EXPECT_NE(p->info_log().find("missing"), std::string::npos) << p->info_log();
  // A type mismatch between the stages.
  p = link_fs("#version 330\nin vec3 p; out vec4 c; void main() { c = vec4(p, 1.0); }");
  EXPECT_FALSE(p->ok());
  // No main.
  auto v = Shader::compile(Stage::Vertex, kVs);
  auto f = Shader::compile(Stage::Fragment, "#version 330\nout vec4 c; void f() { c = vec4(1.0); }");
  if (f->ok()) {
    EXPECT_FALSE(Program::link(*v, *f)->ok());
  }
  // An attribute location past GL_MAX_VERTEX_ATTRIBS (found by fuzz_glsl: the location was
  // kept and later shifted past 32 bits) is a link error naming it.
  v = Shader::compile(Stage::Vertex,
                      "#version 330\nlayout(location = 40) in vec4 far;\n"
                      "void main() { gl_Position = far; }\n");
  ASSERT_TRUE(v->ok()) << v->info_log();
  auto far =
      Program::link(*v, *Shader::compile(Stage::Fragment, "void main() { gl_FragColor = vec4(1.0); }"));
  EXPECT_FALSE(far->ok());
  EXPECT_NE(far->info_log().find("'far'"), std::string::npos) << far->info_log();
  // GLSL 1.30 §4.3.7: gl_Color redeclared flat needs gl_FrontColor and gl_BackColor flat
  // too where they are written (and the secondary colours alike); unused ones do not count.
  auto colours = [](const std::string& vs, const std::string& fs) {
    return Program::link(*Shader::compile(Stage::Vertex, "#version 130\n" + vs),
                         *Shader::compile(Stage::Fragment, "#version 130\nout vec4 c;\n" + fs));
  };
  const std::string flat_color = "flat in vec4 gl_Color; void main() { c = gl_Color; }";
  auto mismatch = colours("void main() { gl_Position = vec4(0); gl_BackColor = vec4(1); }", flat_color);
  EXPECT_FALSE(mismatch->ok());
  EXPECT_NE(mismatch->info_log().find("gl_BackColor"), std::string::npos) << mismatch->info_log();
  EXPECT_FALSE(colours("flat out vec4 gl_FrontColor; noperspective out vec4 gl_BackColor;\n"
                       "void main() { gl_Position = vec4(0); gl_FrontColor = gl_BackColor = vec4(1); }",
                       "void main() { c = vec4(1); }")
                   ->ok());
  EXPECT_FALSE(colours("void main() { gl_Position = vec4(0); gl_FrontSecondaryColor = vec4(1); }",
                       "noperspective in vec4 gl_SecondaryColor; void main() { c = gl_SecondaryColor; }")
                   ->ok());
  EXPECT_TRUE(colours("flat out vec4 gl_FrontColor; flat out vec4 gl_BackColor;\n"
                      "void main() { gl_Position = vec4(0); gl_FrontColor = gl_BackColor = vec4(1); }",
                      flat_color)
                  ->ok());
  EXPECT_TRUE(colours("void main() { gl_Position = vec4(0); gl_BackColor = vec4(1); }",
                      "flat in vec4 gl_Color; void main() { c = vec4(1); }")  // gl_Color unused
                  ->ok());
  // Drawing a program that did not link is an error, not a crash.
  gpu::Context ctx(1);
  gpu::Texture2D color(gpu::Format::RGBA8, 4, 4);
  gpu::Framebuffer fb(&color);
  ctx.bind_framebuffer(&fb);
  EXPECT_THROW(p->draw(ctx, gpu::VertexLayout{}, gpu::RenderState{}, {.count = 3}), gpu::Error);
}

// GL_MAX_VARYING_COMPONENTS (64) of varyings link and arrive: the gl_PerVertex members a
// 3.30 vertex shader does not write (gl_PointSize, gl_ClipDistance) take none of them.
// What Mesa accepts and glslang takes only in later versions or with extensions: line
// continuations in any version, gl_PerVertex redeclared in GLSL 1.50; and arrays of interface
// blocks whose members carry interpolation qualifiers of their own.
// gl_TexCoord is sized in each shader by the elements it uses: a vertex shader that writes two
// and a fragment shader that reads one (or three) link, as in Mesa; elements the vertex shader
// does not write read zero.
TEST(Glsl, TexCoordArraysAreSizedPerShader) {
  reference::GlslDrawSpec d = quad("#version 110\nvoid main() { gl_FragColor = gl_TexCoord[0]; }\n");
  d.vertex =
      "#version 110\nattribute vec2 pos;\nvoid main() {\n  gl_Position = vec4(pos, 0.0, 1.0);\n"
      "  gl_TexCoord[0] = vec4(0.25, 0.5, 0.75, 1.0);\n  gl_TexCoord[1] = vec4(1.0);\n}\n";
  TesselResult r = run_tessel(d);
  ASSERT_TRUE(r.ok) << r.log;
  EXPECT_EQ(r.outputs[0][0], 0.25f);
  EXPECT_EQ(r.outputs[0][2], 0.75f);
  d.fragment = "#version 110\nvoid main() { gl_FragColor = gl_TexCoord[1] + gl_TexCoord[2]; }\n";
  r = run_tessel(d);
  ASSERT_TRUE(r.ok) << r.log;
  EXPECT_EQ(r.outputs[0][0], 1.0f);
  EXPECT_EQ(r.outputs[0][3], 1.0f);
}

TEST(Glsl, GlslOneFiftyInterfacesAsMesaTakesThem) {
  // A continued #define; an error after it still names its own line (5).
  auto s = Shader::compile(Stage::Fragment,
                           "#version 150\n#define GREEN vec4(0.0, \\\n  1.0, 0.0, 1.0)\nout vec4 c;\n"
                           "void main() { c = GREEN + foo; }\n");
  EXPECT_FALSE(s->ok());
  EXPECT_NE(s->info_log().find("0:5: error: 'foo'"), std::string::npos) << s->info_log();
  // The same without the error draws green.
  reference::GlslDrawSpec d = quad(
      "#version 150\n#define GREEN vec4(0.0, \\\n  1.0, 0.0, 1.0)\nout vec4 c;\n"
      "void main() { c = GREEN; }\n");
  d.vertex =
      "#version 150\nin vec2 pos;\nout gl_PerVertex {\n  vec4 gl_Position;\n};\n"
      "void main() { gl_Position = vec4(pos, 0.0, 1.0); }\n";
  TesselResult r = run_tessel(d);
  ASSERT_TRUE(r.ok) << r.log;
  EXPECT_EQ(r.outputs[0][0], 0.0f);
  EXPECT_EQ(r.outputs[0][1], 1.0f);
  // An array of blocks: each element's flat, smooth and noperspective members arrive as the
  // loose variables of the same qualifiers (a triangle with three different w).
  reference::GlslDrawSpec t;
  t.vertex = R"(#version 150
in vec4 pos;
flat out float f; smooth out float s; noperspective out float n;
out Blk { flat float f; smooth float s; noperspective float n; } b[2];
void main() {
  gl_Position = pos;
  float v = float(gl_VertexID) * 7.0;
  f = v; s = v; n = v;
  for (int i = 0; i < 2; ++i) { b[i].f = v; b[i].s = v; b[i].n = v; }
})";
  t.fragment = R"(#version 150
flat in float f; smooth in float s; noperspective in float n;
in Blk { flat float f; smooth float s; noperspective float n; } b[2];
out vec4 c;
void main() {
  float err = 0.0;
  for (int i = 0; i < 2; ++i) err += abs(f - b[i].f) + abs(s - b[i].s) + abs(n - b[i].n);
  c = vec4(err, s - n, 1.0, 1.0);
})";
  t.attributes.push_back({"pos", 4, {-1, -1, 0, 1, 0, 2, 0, 2, 3, -3, 0, 3}});
  t.count = 3;
  r = run_tessel(t);
  ASSERT_TRUE(r.ok) << r.log;
  float differs = 0;
  for (size_t i = 0; i < r.outputs[0].size(); i += 4) {
    EXPECT_EQ(r.outputs[0][i], 0.0f) << "pixel " << i / 4;
    differs = std::max(differs, std::fabs(r.outputs[0][i + 1]));
  }
  EXPECT_GT(differs, 0.01f);  // smooth and noperspective do differ here
}

TEST(Glsl, AllSixtyFourVaryingComponentsArrive) {
  reference::GlslDrawSpec s = quad(
      "#version 330\nin vec4 v[15]; in vec2 p; in vec2 q; out vec4 c;\n"
      "void main() { vec4 t = vec4(0.0); for (int i = 0; i < 15; ++i) t += v[i] * float(i + 1);\n"
      " c = vec4(t.x, t.w, p.x + q.y, 1.0); }");
  s.vertex =
      "#version 330\nlayout(location = 0) in vec2 pos; out vec4 v[15]; out vec2 p; out vec2 q;\n"
      "void main() { for (int i = 0; i < 15; ++i) v[i] = vec4(1.0, 0.0, 0.0, 0.5);\n"
      " p = pos * 0.5 + 0.5; q = vec2(0.0, 0.25); gl_Position = vec4(pos, 0.0, 1.0); }";
  const TesselResult r = run_tessel(s);
  ASSERT_TRUE(r.ok) << r.log;
  const float* px = &r.outputs[0][size_t((8 * 16 + 4) * 4)];
  EXPECT_EQ(px[0], 120.0f);  // 1 + 2 + ... + 15
  EXPECT_EQ(px[1], 60.0f);
  EXPECT_NEAR(px[2], 4.5f / 16.0f + 0.25f, 1e-6f);
}

// The built-in constants are the limits the GL layer reports for the same GL_MAX_* queries
// (src/gl/api_get.cpp), not glslang's defaults (64 attributes, 32 draw buffers, ...).
TEST(Glsl, BuiltInConstantsAreTheGlLimits) {
  const std::vector<float> a = draw(
      "#version 150 compatibility\nout vec4 c;\nvoid main() { c = vec4(gl_MaxVertexAttribs, "
      "gl_MaxDrawBuffers,"
      " gl_MaxVaryingComponents, gl_MaxTextureCoords); }");
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a[0], float(gpu::kMaxVertexAttribs));  // 16
  EXPECT_EQ(a[1], 8.0f);
  EXPECT_EQ(a[2], 64.0f);
  EXPECT_EQ(a[3], 8.0f);
  const std::vector<float> b = draw(
      "#version 150 compatibility\nout vec4 c;\nvoid main() { c = vec4(gl_MaxCombinedTextureImageUnits,"
      " gl_MaxTextureImageUnits, gl_MaxClipDistances, gl_MaxClipPlanes); }");
  ASSERT_FALSE(b.empty());
  EXPECT_EQ(b[0], 48.0f);
  EXPECT_EQ(b[1], 16.0f);
  EXPECT_EQ(b[2], 8.0f);
  EXPECT_EQ(b[3], 8.0f);
}

// Several shader objects of one stage (glAttachShader) link as one stage's compilation units:
// main() calls functions another unit defines, a uniform declared in two units is one
// uniform. A function defined nowhere, or main() in two units, is a link error.
TEST(Glsl, SeveralShaderObjectsPerStageLinkAsOne) {
  auto vs_main = Shader::compile(Stage::Vertex, R"(#version 330
layout(location = 0) in vec2 pos;
out vec2 p;
vec4 place(vec2 v);
void main() { p = pos * 0.5 + 0.5; gl_Position = place(pos); })");
  auto vs_lib =
      Shader::compile(Stage::Vertex, "#version 330\nvec4 place(vec2 v) { return vec4(v, 0.0, 1.0); }\n");
  auto fs_main = Shader::compile(Stage::Fragment, R"(#version 330
in vec2 p;
out vec4 c;
uniform float u;
vec4 shade(vec2 q);
void main() { c = shade(p) + vec4(0.0, 0.0, u, 0.0); })");
  auto fs_lib = Shader::compile(Stage::Fragment, R"(#version 330
uniform float u;
vec4 shade(vec2 q) { return vec4(q, u, 1.0); })");
  for (auto* s : {vs_main.get(), vs_lib.get(), fs_main.get(), fs_lib.get()})
    ASSERT_TRUE(s->ok()) << s->info_log();
  const Shader* units[] = {fs_lib.get(), vs_main.get(), fs_main.get(), vs_lib.get()};
  auto prog = Program::link(units);
  ASSERT_TRUE(prog->ok()) << prog->info_log();
  const int u = prog->uniform_location("u");
  ASSERT_GE(u, 0);
  const float quarter = 0.25f;
  ASSERT_TRUE(prog->set_uniform(u, &quarter, 1));
  gpu::Context ctx(2);
  gpu::Texture2D color(gpu::Format::RGBA32F, 8, 8);
  gpu::Framebuffer fb(&color);
  ctx.bind_framebuffer(&fb);
  const float quad_pos[] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
  gpu::Buffer buf(quad_pos, sizeof quad_pos);
  gpu::VertexLayout layout;
  layout.attrib(prog->attribute_location("pos"), buf, 2, gpu::AttribType::F32, 0, 0);
  gpu::RenderState st;
  prog->draw(ctx, layout, st, {.count = 6});
  ctx.finish();
  const glm::vec4 px = color.fetch(0, 2, 5);  // p = ((2.5, 5.5) / 8)
  EXPECT_FLOAT_EQ(px.x, 2.5f / 8.0f);
  EXPECT_FLOAT_EQ(px.y, 5.5f / 8.0f);
  EXPECT_FLOAT_EQ(px.z, 0.5f);  // u in both units is one uniform
  EXPECT_FLOAT_EQ(px.w, 1.0f);
  // Errors: the fragment library without its main, a function defined nowhere, two mains.
  const Shader* no_main[] = {vs_main.get(), vs_lib.get(), fs_lib.get()};
  EXPECT_FALSE(Program::link(no_main)->ok());
  const Shader* undefined[] = {vs_main.get(), fs_main.get(), fs_lib.get()};
  auto p2 = Program::link(undefined);
  EXPECT_FALSE(p2->ok());
  EXPECT_NE(p2->info_log().find("place"), std::string::npos) << p2->info_log();
  const Shader* two_mains[] = {vs_main.get(), vs_lib.get(), vs_main.get(), fs_main.get(), fs_lib.get()};
  EXPECT_FALSE(Program::link(two_mains)->ok());
  const Shader* no_vertex[] = {fs_main.get(), fs_lib.get()};
  EXPECT_FALSE(Program::link(no_vertex)->ok());
}

TEST(Glsl, ReflectionAndLocations) {
  auto v = Shader::compile(Stage::Vertex, R"(#version 330
layout(location = 3) in vec4 fixed_loc;
in vec2 bound;
in mat3 m;
in float unused;
out vec4 col;
void main() { col = fixed_loc + vec4(bound, 0.0, 0.0) + vec4(m[1], 0.0); gl_Position = vec4(bound, 0.0, 1.0); })");
  auto f = Shader::compile(Stage::Fragment, R"(#version 330
in vec4 col;
uniform float k[4];
uniform struct { vec3 a; int b; } s;
uniform sampler2D tex;
uniform float not_used;
layout(location = 1) out vec4 second;
out vec4 first;
void main() { first = col * k[2] + texture(tex, col.xy); second = vec4(s.a, float(s.b)); })");
  ASSERT_TRUE(v->ok()) << v->info_log();
  ASSERT_TRUE(f->ok()) << f->info_log();
  glsl::LinkOptions o;
  o.attribute_locations["bound"] = 7;
  auto p = Program::link(*v, *f, o);
  ASSERT_TRUE(p->ok()) << p->info_log();
  EXPECT_EQ(p->attribute_location("fixed_loc"), 3);
  EXPECT_EQ(p->attribute_location("bound"), 7);
  const int m = p->attribute_location("m");
  EXPECT_GE(m, 0);
  EXPECT_TRUE(m + 2 < 3 || m > 3) << "mat3 takes three locations that must not overlap location 3";
  EXPECT_EQ(p->attribute_location("unused"), -1);  // not active
  EXPECT_EQ(p->frag_data_location("second"), 1);
  EXPECT_EQ(p->frag_data_location("first"), 0);
  EXPECT_GE(p->uniform_location("k"), 0);
  EXPECT_EQ(p->uniform_location("k[2]"), p->uniform_location("k") + 2);
  EXPECT_EQ(p->uniform_location("k[4]"), -1) << p->uniform_location("k");
  EXPECT_GE(p->uniform_location("s.a"), 0);
  EXPECT_GE(p->uniform_location("tex"), 0);
  EXPECT_EQ(p->uniform_location("not_used"), -1);
  // The active uniforms as GL lists them.
  bool found_k = false;
  for (const auto& u : p->uniforms())
    if (u.name == "k[0]") {
      found_k = true;
      EXPECT_EQ(u.type, 0x1406u);  // GL_FLOAT
      EXPECT_EQ(u.size, 4);
    }
  EXPECT_TRUE(found_k);
  // Uniform values: type and size rules.
  const float three[3] = {1, 2, 3};
  const int32_t one = 1;
  EXPECT_TRUE(p->set_uniform(p->uniform_location("s.a"), three, 3));
  EXPECT_FALSE(p->set_uniform(p->uniform_location("s.a"), three, 2));  // size mismatch
  EXPECT_FALSE(p->set_uniform(p->uniform_location("s.b"), three, 1));  // float into int
  EXPECT_TRUE(p->set_uniform(p->uniform_location("s.b"), &one, 1));
  EXPECT_FALSE(p->set_uniform(p->uniform_location("tex"), three, 1));  // samplers take ints
  EXPECT_TRUE(p->set_uniform(-1, three, 3));                           // -1 is ignored
  EXPECT_FALSE(p->set_uniform(12345, three, 3));
  float back[3] = {};
  EXPECT_TRUE(p->get_uniform(p->uniform_location("s.a"), back));
  EXPECT_EQ(back[2], 3.0f);
  const float ks[4] = {5, 6, 7, 8};
  EXPECT_TRUE(p->set_uniform(p->uniform_location("k[1]"), ks, 1, 4));  // the rest past the end is ignored
  EXPECT_TRUE(p->get_uniform(p->uniform_location("k[3]"), back));
  EXPECT_EQ(back[0], 7.0f);
}

TEST(Glsl, DrawsAndIsIdenticalForAnyThreadCount) {
  const std::string fs =
      "#version 330\nin vec2 p; out vec4 c; void main() { c = vec4(p, sin(p.x * 10.0), 1.0); }";
  const reference::GlslDrawSpec s = quad(fs, 37, 23);
  const TesselResult a = run_tessel(s, 1), b = run_tessel(s, 2), c = run_tessel(s, 5);
  ASSERT_TRUE(a.ok) << a.log;
  EXPECT_EQ(a.outputs, b.outputs);
  EXPECT_EQ(a.outputs, c.outputs);
  // The centre pixel holds the interpolated position.
  const float* px = &a.outputs[0][size_t((11 * 37 + 18) * 4)];
  EXPECT_NEAR(px[0], 18.5f / 37.0f, 1e-5f);
  EXPECT_NEAR(px[1], 11.5f / 23.0f, 1e-5f);
}

// The vertex stage runs sixteen vertices a call, two fetched batches of eight: every count
// of vertices from 1 to 40 (whole calls, a lone first batch, a part-filled second one), with
// an attribute per vertex, one per instance and one for both instances, captures each vertex's own
// values in order, and the same bytes on the interpreter.
TEST(Glsl, VertexStageTakesSixteenVerticesACallForEveryCount) {
  auto v = Shader::compile(Stage::Vertex, R"(#version 330
layout(location = 0) in float a;
layout(location = 1) in float per_instance;
layout(location = 2) in vec2 constant;
out vec4 r;
void main() {
  r = vec4(float(gl_VertexID), a * 2.0 + 1.0, per_instance, constant.y - constant.x);
  gl_Position = vec4(a * 0.01, 0.0, 0.0, 1.0);
})");
  auto f = Shader::compile(Stage::Fragment, "#version 330\nout vec4 c;\nvoid main() { c = vec4(1.0); }");
  std::vector<float> a(40), inst = {5.0f, 6.0f};
  for (int i = 0; i < 40; ++i) a[size_t(i)] = float(i * i) * 0.25f;
  gpu::Buffer va(std::vector<uint8_t>(reinterpret_cast<const uint8_t*>(a.data()),
                                      reinterpret_cast<const uint8_t*>(a.data() + a.size())));
  gpu::Buffer vi(std::vector<uint8_t>(reinterpret_cast<const uint8_t*>(inst.data()),
                                      reinterpret_cast<const uint8_t*>(inst.data() + inst.size())));
  gpu::VertexLayout layout;
  layout.attrib(0, va, 1, gpu::AttribType::F32, 4, 0);
  layout.attrib(1, vi, 1, gpu::AttribType::F32, 4, 0, false, 1);
  const float both[2] = {1.5f, 4.0f};
  gpu::Buffer vc(std::vector<uint8_t>(reinterpret_cast<const uint8_t*>(both),
                                      reinterpret_cast<const uint8_t*>(both + 2)));
  layout.attrib(2, vc, 2, gpu::AttribType::F32, 8, 0, false, 2);  // one value for both instances
  for (NativeCode tier : {NativeCode::AtLink, NativeCode::Off}) {
    LinkOptions options;
    options.native_code = tier;
    options.feedback_varyings = {"r"};
    auto prog = Program::link(*v, *f, options);
    ASSERT_TRUE(prog->ok()) << prog->info_log();
    for (uint32_t n = 1; n <= 40; ++n) {
      gpu::Context ctx(2);
      gpu::Texture2D color(gpu::Format::RGBA8, 8, 8);
      gpu::Framebuffer fb(&color);
      ctx.bind_framebuffer(&fb);
      gpu::Buffer out(std::vector<uint8_t>(size_t(n) * 2 * 16, 0));
      gpu::Capture cap;
      cap.mode = gpu::Topology::Points;
      cap.buffers.push_back({&out, 0, out.size(), prog->feedback_words()[0]});
      prog->draw(ctx, layout, gpu::RenderState{},
                 {.topology = gpu::Topology::Points, .count = n, .instance_count = 2, .capture = &cap});
      ctx.finish();
      ASSERT_EQ(cap.written, uint64_t(n) * 2) << n;
      const auto* r = reinterpret_cast<const float*>(out.data());
      for (uint32_t k = 0; k < n * 2; ++k) {
        const uint32_t i = k % n, instance = k / n;
        EXPECT_EQ(r[k * 4 + 0], float(i)) << n << " " << k;
        EXPECT_EQ(r[k * 4 + 1], a[i] * 2.0f + 1.0f) << n << " " << k;
        EXPECT_EQ(r[k * 4 + 2], inst[instance]) << n << " " << k;
        EXPECT_EQ(r[k * 4 + 3], 2.5f) << n << " " << k;
      }
    }
  }
}

// Transform feedback through the gpu layer (gpu::Capture): a triangle strip of several chunks
// and three instances, written as independent triangles in draw order (odd strip triangles
// as (i + 1, i, i + 2), each instance after the one before), the same bytes for any thread
// count; a buffer too small takes the primitives that fit whole and no byte past its range;
// with the rasterizer discarding, nothing is drawn.
TEST(Glsl, TransformFeedbackCapturesInDrawOrderForAnyThreadCount) {
  auto v = Shader::compile(Stage::Vertex, R"(#version 330
flat out int id;
out float half_id;
void main() {
  id = gl_VertexID + 100000 * gl_InstanceID;
  half_id = float(gl_VertexID) * 0.5;
  gl_Position = vec4(gl_VertexID % 2 == 0 ? -1.0 : 1.0, gl_VertexID % 4 < 2 ? -1.0 : 1.0, 0.5, 1.0);
})");
  auto f = Shader::compile(Stage::Fragment, "#version 330\nout vec4 c;\nvoid main() { c = vec4(1.0); }");
  LinkOptions options;
  options.feedback_varyings = {"id", "gl_Position", "half_id"};
  auto prog = Program::link(*v, *f, options);
  ASSERT_TRUE(prog->ok()) << prog->info_log();
  ASSERT_EQ(prog->feedback_words().size(), 1u);
  ASSERT_EQ(prog->feedback_words()[0].size(), 6u);  // id, the position's four, half_id
  EXPECT_EQ(prog->feedback_varyings()[1].name, "gl_Position");
  constexpr uint32_t kVertices = 2600, kInstances = 3, kTriangles = (kVertices - 2) * kInstances;
  auto capture = [&](int threads, size_t bytes, bool discard, uint64_t* written) {
    gpu::Context ctx(threads);
    gpu::Texture2D color(gpu::Format::RGBA8, 8, 8);
    gpu::Framebuffer fb(&color);
    ctx.bind_framebuffer(&fb);
    ctx.clear({.color = {0, 0, 0, 0}});
    gpu::Buffer out(std::vector<uint8_t>(bytes + 64, 0xAB));
    gpu::Capture cap;
    cap.mode = gpu::Topology::Triangles;
    cap.buffers.push_back({&out, 0, bytes, prog->feedback_words()[0]});
    gpu::RenderState st;
    st.rasterizer_discard = discard;
    prog->draw(ctx, gpu::VertexLayout{}, st,
               {.topology = gpu::Topology::TriangleStrip,
                .count = kVertices,
                .instance_count = kInstances,
                .capture = &cap});
    *written = cap.written;
    EXPECT_EQ(cap.written + cap.overflowed, kTriangles);
    EXPECT_EQ(cap.buffers[0].offset, size_t(cap.written) * 3 * 24);
    ctx.finish();
    EXPECT_EQ(color.fetch(0, 4, 4).w, discard ? 0.0f : 1.0f);
    return std::vector<uint8_t>(reinterpret_cast<const uint8_t*>(out.data()),
                                reinterpret_cast<const uint8_t*>(out.data()) + out.size());
  };
  uint64_t written = 0;
  const size_t all = size_t(kTriangles) * 3 * 24;
  const std::vector<uint8_t> one = capture(1, all, true, &written);
  EXPECT_EQ(written, kTriangles);
  EXPECT_EQ(capture(2, all, false, &written), one);
  EXPECT_EQ(capture(5, all, true, &written), one);
  auto id_at = [&](size_t vertex) {
    int32_t id;
    std::memcpy(&id, one.data() + vertex * 24, 4);
    return id;
  };
  const int32_t expect[] = {0, 1, 2, 2, 1, 3, 2, 3, 4};  // even, odd, even
  for (size_t k = 0; k < 9; ++k) EXPECT_EQ(id_at(k), expect[k]) << k;
  // Triangle 2598 of the second instance comes after the first's last.
  EXPECT_EQ(id_at(size_t(kVertices - 2) * 3), 100000);
  EXPECT_EQ(id_at(size_t(kVertices - 2) * 3 - 1), int32_t(kVertices - 1));
  float half;
  std::memcpy(&half, one.data() + 5 * 24 + 20, 4);  // vertex 3's
  EXPECT_EQ(half, 1.5f);
  EXPECT_EQ(one[all], 0xAB);  // nothing past the range
  // Room for 10.5 triangles: 10 are written, whole.
  const std::vector<uint8_t> part = capture(2, 10 * 72 + 36, true, &written);
  EXPECT_EQ(written, 10u);
  EXPECT_TRUE(std::equal(part.begin(), part.begin() + 720, one.begin()));
  EXPECT_EQ(part[720], 0xAB);
  // A capture of points from triangles is refused.
  gpu::Context ctx(1);
  gpu::Texture2D color(gpu::Format::RGBA8, 8, 8);
  gpu::Framebuffer fb(&color);
  ctx.bind_framebuffer(&fb);
  gpu::Buffer out(size_t(64));
  gpu::Capture points;
  points.buffers.push_back({&out, 0, 64, prog->feedback_words()[0]});
  EXPECT_THROW(prog->draw(ctx, gpu::VertexLayout{}, gpu::RenderState{}, {.count = 3, .capture = &points}),
               gpu::Error);
  // Link errors GL names (§2.11.8).
  for (std::vector<std::string> bad :
       {std::vector<std::string>{"nothing"}, {"id", "id"}, {"id[0]"}, {"half_id[1]"}}) {
    options.feedback_varyings = bad;
    EXPECT_FALSE(Program::link(*v, *f, options)->ok()) << bad.back();
  }
}

// The background tier: link() returns before the native code is there, the draws run on the
// interpreter until it is, and the native code gives the same bits.
TEST(Glsl, BackgroundCompileDrawsAtOnceWithTheSameBits) {
  const reference::GlslDrawSpec s = quad(
      "#version 330\nin vec2 p; out vec4 c;\nvoid main() { float a = 0.0;"
      " for (int i = 0; i < 5; ++i) a += pow(p.x + float(i), 1.7);"
      " c = vec4(a, inversesqrt(p.y + 0.1), sin(p.x * 10.0) / (p.y + 0.25), 1.0); }");
  glsl::hold_background_compiles(true);
  const TesselResult held = run_tessel(s, 2, NativeCode::Background);
  glsl::hold_background_compiles(false);
  const TesselResult native = run_tessel(s, 2, NativeCode::AtLink);
  ASSERT_TRUE(held.ok) << held.log;
  ASSERT_TRUE(native.ok) << native.log;
  EXPECT_EQ(held.outputs, native.outputs);

  auto v = Shader::compile(Stage::Vertex, kVs);
  auto f = Shader::compile(Stage::Fragment, s.fragment);
  glsl::clear_program_cache();  // else this link takes the native code linked above
  glsl::hold_background_compiles(true);
  auto p = Program::link(*v, *f);
  ASSERT_TRUE(p->ok()) << p->info_log();
  EXPECT_FALSE(p->native());  // nothing compiles while held
  glsl::hold_background_compiles(false);
  EXPECT_TRUE(p->wait_native());
  EXPECT_TRUE(p->native());
  // Off never compiles, and waiting for it returns at once.
  LinkOptions off;
  off.native_code = NativeCode::Off;
  auto q = Program::link(*v, *f, off);
  EXPECT_FALSE(q->wait_native());
}

// Loops are cut per sixteen lanes (65535 iterations a loop, 2^20 a run) also where the native
// code runs two calls' worth as one 32-lane function: lanes that loop forever next to lanes
// that do not leave those alone, and both tiers agree.
TEST(Glsl, LoopLimitsHoldPerSixteenLanesInPairedCalls) {
  // Columns 0-7 and 16-23 loop forever (cut by the limits), 8-15 and 24-31 three times
  // in each of 40 loops; each row's 4x2 groups are shaded in order, four a time, so a call
  // pair puts the first kind in one half and the second in the other.
  reference::GlslDrawSpec s;
  s.vertex = kVs;
  s.fragment =
      "#version 330\nin vec2 p; out vec4 c;\nvoid main() { int n = 0; bool brief = fract(p.x * 2.0) >= 0.5;\n"
      " for (int j = 0; j < 40; ++j) { int i = 0; while (true) { if (brief && i >= 3) break; ++i; ++n; } }\n"
      " c = vec4(float(n), p.x, 0.0, 1.0); }";
  s.width = 32;
  s.height = 2;
  s.attributes.push_back({"pos", 2, {-1, -1, 3, -1, -1, 3}});  // one triangle over it all
  s.count = 3;
  LinkOptions at_link;
  at_link.native_code = NativeCode::AtLink;
  ASSERT_TRUE(Program::link(*Shader::compile(Stage::Vertex, kVs),
                            *Shader::compile(Stage::Fragment, s.fragment), at_link)
                  ->native());
  const TesselResult jit = run_tessel(s, 1, NativeCode::AtLink);
  const TesselResult interp = run_tessel(s, 1, NativeCode::Off);
  ASSERT_TRUE(jit.ok) << jit.log;
  ASSERT_TRUE(interp.ok) << interp.log;
  EXPECT_EQ(jit.outputs, interp.outputs);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const float n = jit.outputs[0][size_t((y * s.width + x) * 4)];
      if ((x / 8) % 2)
        EXPECT_EQ(n, 120.0f) << x << "," << y;
      else
        EXPECT_LT(n, 40.0f * 65535.0f) << x << "," << y;  // cut
    }
}

// The process's cache: linking the same sources with the same bindings again compiles
// nothing (the second program has native code at once, sharing the first's), gives a program
// with uniform values of its own at their initial state, and draws the same image; other
// sources, other bindings or the interpreter's tier are other programs; 64 are kept.
TEST(Glsl, LinkingTheSameProgramAgainCompilesNothing) {
  glsl::clear_program_cache();
  const std::string fs =
      "#version 330\nin vec2 p; out vec4 c; uniform float k = 2.0; uniform vec3 tint;\n"
      "void main() { c = vec4(sin(p.x * k) * tint.x, p.y, tint.z, 1.0); }";
  auto link = [&](const LinkOptions& o = {}, const std::string& f = "") {
    return Program::link(*Shader::compile(Stage::Vertex, kVs),
                         *Shader::compile(Stage::Fragment, f.empty() ? fs : f), o);
  };
  auto first = link();
  ASSERT_TRUE(first->ok()) << first->info_log();
  EXPECT_EQ(glsl::program_cache_stats().misses, 1u);
  EXPECT_EQ(glsl::program_cache_stats().hits, 0u);
  ASSERT_TRUE(first->wait_native());
  const float k = 7.0f, tint[3] = {0.5f, 0.25f, 0.75f};
  ASSERT_TRUE(first->set_uniform(first->uniform_location("k"), &k, 1));
  ASSERT_TRUE(first->set_uniform(first->uniform_location("tint"), tint, 3));

  auto second = link();
  ASSERT_TRUE(second->ok());
  EXPECT_EQ(glsl::program_cache_stats().hits, 1u);
  EXPECT_TRUE(second->native());  // no compile to wait for
  EXPECT_EQ(second->uniforms().size(), first->uniforms().size());
  EXPECT_EQ(second->attribute_location("pos"), 0);
  float got[3] = {};
  ASSERT_TRUE(second->get_uniform(second->uniform_location("k"), got));
  EXPECT_EQ(got[0], 2.0f);  // its own values, from the initializer: not the first program's 7
  ASSERT_TRUE(second->get_uniform(second->uniform_location("tint"), got));
  EXPECT_EQ(got[2], 0.0f);
  // A drawing through a kept program gives the image of one linked afresh.
  reference::GlslDrawSpec spec = quad(fs);
  spec.uniforms.push_back({.name = "k", .f = {k}});
  spec.uniforms.push_back({.name = "tint", .f = {tint[0], tint[1], tint[2]}});
  const TesselResult warm = run_tessel(spec, 2, NativeCode::Background);
  EXPECT_EQ(glsl::program_cache_stats().hits, 2u);
  glsl::clear_program_cache();
  const TesselResult cold = run_tessel(spec, 2, NativeCode::Background);
  EXPECT_EQ(glsl::program_cache_stats().misses, 1u);
  ASSERT_TRUE(warm.ok && cold.ok) << warm.log << cold.log;
  EXPECT_EQ(warm.outputs, cold.outputs);
  spec.uniforms.pop_back();
  EXPECT_NE(run_tessel(spec, 2, NativeCode::Background).outputs, cold.outputs);  // the values count

  // Other bindings, another source, the interpreter's tier: links of their own.
  LinkOptions bound;
  bound.frag_data_locations["c"] = 1;
  auto rebound = link(bound);
  EXPECT_EQ(rebound->frag_data_location("c"), 1);
  EXPECT_EQ(second->frag_data_location("c"), 0);
  LinkOptions off;
  off.native_code = NativeCode::Off;
  EXPECT_FALSE(link(off)->native());
  EXPECT_TRUE(link({}, fs + " ")->ok());
  EXPECT_EQ(glsl::program_cache_stats().misses, 4u);  // the cold draw's and these three
  // A program that failed to link is not kept: linking it again gives the log again.
  auto bad = link({}, "#version 330\nin vec3 nowhere; out vec4 c; void main() { c = vec4(nowhere, 1.0); }");
  EXPECT_FALSE(bad->ok());
  EXPECT_EQ(link({}, "#version 330\nin vec3 nowhere; out vec4 c; void main() { c = vec4(nowhere, 1.0); }")
                ->info_log(),
            bad->info_log());
  // The least recently linked go first.
  for (int i = 0; i < int(glsl::kProgramCacheEntries); ++i)
    ASSERT_TRUE(link(off, fs + "// " + std::to_string(i))->ok());
  EXPECT_EQ(glsl::program_cache_stats().entries, glsl::kProgramCacheEntries);
  const uint64_t misses = glsl::program_cache_stats().misses;
  EXPECT_TRUE(link()->ok());
  EXPECT_EQ(glsl::program_cache_stats().misses, misses + 1);
  glsl::clear_program_cache();
  EXPECT_EQ(glsl::program_cache_stats().entries, 0u);
}

// The disk cache: a program's second link loads its code; the images are the same; a damaged
// or truncated file is ignored and the program compiled again.
TEST(Glsl, DiskCacheOfCompiledPrograms) {
  const std::string dir = ::testing::TempDir() + "tessel_cache_" + std::to_string(::getpid());
  std::filesystem::remove_all(dir);
  ::setenv("TESSEL_SHADER_CACHE_DIR", dir.c_str(), 1);
  const std::string fs =
      "#version 330\nin vec2 p; out vec4 c; uniform float k; void main() { c = vec4(sin(p.x * k), p.y, 0.5, "
      "1.0); }";
  auto link = [&] {
    glsl::clear_program_cache();  // the disk's, not the process's
    auto v = Shader::compile(Stage::Vertex, kVs);
    auto f = Shader::compile(Stage::Fragment, fs);
    return Program::link(*v, *f);
  };
  auto first = link();
  ASSERT_TRUE(first->ok());
  ASSERT_TRUE(first->wait_native());
  EXPECT_FALSE(first->from_cache());
  auto second = link();
  ASSERT_TRUE(second->wait_native());
  EXPECT_TRUE(second->from_cache());
  const std::vector<float> a = draw(fs), b = draw(fs);
  EXPECT_EQ(a, b);
  // Damage every cached file: the next link compiles again (and rewrites the file).
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    std::fstream f(e.path(), std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(std::streamoff(e.file_size() / 2));
    f.put('\x5a');
    f.put('\xa5');
  }
  auto third = link();
  ASSERT_TRUE(third->ok());
  ASSERT_TRUE(third->wait_native());
  EXPECT_FALSE(third->from_cache());
  EXPECT_EQ(draw(fs), a);
  // Truncated files too.
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file()) std::filesystem::resize_file(e.path(), e.file_size() / 3);
  auto fourth = link();
  ASSERT_TRUE(fourth->wait_native());
  EXPECT_FALSE(fourth->from_cache());
  ::unsetenv("TESSEL_SHADER_CACHE_DIR");
  std::filesystem::remove_all(dir);
}

TEST(Glsl, BadInputGetsALogOrADefinedResult) {
  // Unterminated comment, undefined names, type errors: info logs.
  {
    // The comment swallows main(): a compile error or a link error.
    auto f = Shader::compile(Stage::Fragment, "#version 330\nout vec4 c; /* never closed\nvoid main() {}");
    if (f->ok()) {
      EXPECT_FALSE(Program::link(*Shader::compile(Stage::Vertex, kVs), *f)->ok());
    }
  }
  EXPECT_FALSE(Shader::compile(Stage::Fragment, "#version 330\nout vec4 c; void main() { c = 1; }")->ok());
  {
    auto empty = Shader::compile(Stage::Fragment, "");  // compiles (as in Mesa); has no main to link
    if (empty->ok()) {
      EXPECT_FALSE(Program::link(*Shader::compile(Stage::Vertex, kVs), *empty)->ok());
    }
  }
  // Deep nesting and a huge source.
  std::string deep = "#version 330\nout vec4 c; void main() { float x = ";
  for (int i = 0; i < 10000; ++i) deep += "(";
  deep += "1.0";
  for (int i = 0; i < 10000; ++i) deep += ")";
  deep += "; c = vec4(x); }";
  {
    // A log, or a program that runs: the parentheses are no operations.
    std::string dlog;
    const std::vector<float> dp = draw(deep, &dlog);
    if (dp.empty())
      EXPECT_NE(dlog.find("error"), std::string::npos) << dlog;
    else
      EXPECT_EQ(dp[0], 1.0f);
  }
  std::string huge = "#version 330\nout vec4 c;\n";
  while (huge.size() < 10u * 1024 * 1024)
    huge += "// padding padding padding padding padding padding padding padding\n";
  huge += "void main() { c = vec4(1.0); }\n";
  EXPECT_TRUE(Shader::compile(Stage::Fragment, huge)->ok());
  {
    // An #error of 300,000 characters: the log quotes it whole on one line, and rewriting
    // that line into GL's form must neither recurse per character nor lose it.
    std::string text = "q";
    while (text.size() < 300000) text += " q";
    auto bad =
        Shader::compile(Stage::Fragment, "#version 330\n#error " + text + "\nout vec4 c; void main() {}");
    ASSERT_FALSE(bad->ok());
    EXPECT_EQ(bad->info_log().rfind("0:2: error: ", 0), 0u) << bad->info_log().substr(0, 80);
    EXPECT_NE(bad->info_log().find(text), std::string::npos) << bad->info_log().substr(0, 300);
  }
  // Recursion is a compile or link error.
  auto v = Shader::compile(Stage::Vertex, kVs);
  auto f = Shader::compile(
      Stage::Fragment,
      "#version 330\nin vec2 p; out vec4 c; float r(float x) { return x < 0.0 ? x : r(x - 1.0); }"
      " void main() { c = vec4(r(p.x)); }");
  if (f->ok()) {
    EXPECT_FALSE(Program::link(*v, *f)->ok());
  }
  // An infinite loop ends (cut after 65535 iterations); integer division by zero and indices
  // out of range give defined values.
  std::string log;
  auto px = draw(
      "#version 330\nin vec2 p; out vec4 c; void main() { float s = 0.0; while (true) { s += 1.0; }"
      " c = vec4(s); }",
      &log);
  ASSERT_FALSE(px.empty()) << log;
  EXPECT_EQ(px[0], 65535.0f);
  px = draw(
      "#version 330\nin vec2 p; out vec4 c; uniform int z; void main() { int a = 7 / z; int b = 7 % z;"
      " float arr[3] = float[3](1.0, 2.0, 3.0); int k = int(p.x * 100.0) - 50;"
      " c = vec4(float(a), float(b), arr[k], arr[-k]); }",
      &log);
  ASSERT_FALSE(px.empty()) << log;
  for (float x : px) EXPECT_FALSE(std::isnan(x));
  // Pixel (0, 0): p.x = 1/32, so k = -47. As on llvmpipe (the conformance set compares these
  // edges with Mesa): a signed quotient by 0 is 0, a remainder by 0 all ones; indices are
  // clamped into the array.
  EXPECT_EQ(px[0], 0.0f);
  EXPECT_EQ(px[1], -1.0f);
  EXPECT_EQ(px[2], 1.0f);
  EXPECT_EQ(px[3], 3.0f);
  // A fragment shader that writes no output links (as in Mesa; the colour is undefined by GL)
  // and draws; so does one that discards every fragment.
  EXPECT_FALSE(draw("#version 330\nvoid main() {}", &log).empty()) << log;
  EXPECT_FALSE(draw("#version 110\nvoid main() { discard; }", &log).empty()) << log;
}

}  // namespace
}  // namespace tessel::testing
