// The reference test of the scene engine's Blinn-Phong shader: the same scene rendered by
// Tessel (scene::PhongShader) and by Mesa llvmpipe through a GLSL port of that shader, with
// the same meshes, matrices, lights, materials and texture. The images must agree: at most
// 0.1% of the pixels may differ by more than 2/255 in some channel. A GLSL shininess 10%
// off is shown to fail that.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "../scene/golden.hpp"
#include "../scene/test_scenes.hpp"
#include "headless_gl.hpp"
#include "tessel/gpu/framebuffer.hpp"

using namespace tessel;
using namespace tessel::scene;

namespace {

constexpr int W = 320, H = 160;

const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 vtxPos;
layout(location = 1) in vec3 vtxNorm;
layout(location = 2) in vec2 vtxUV;
uniform mat4 MVP, M, Nmat;
out vec3 wPos;
out vec3 wNormal;
out vec2 uv;
void main() {
  vec4 p = vec4(vtxPos, 1.0);
  wPos = (M * p).xyz;
  wNormal = (Nmat * vec4(vtxNorm, 0.0)).xyz;
  uv = vtxUV;
  gl_Position = MVP * p;
}
)";

const char* kFragment = R"(#version 330 core
struct Light { vec4 pos; vec3 La; vec3 Le; vec3 att; vec3 spot_dir; float spot_cos; float spot_exp; };
uniform Light lights[8];
uniform int nlights;
uniform vec3 ka, kd, ks, emission, eye;
uniform float shine, shine_scale;
uniform bool textured;
uniform sampler2D tex;
in vec3 wPos;
in vec3 wNormal;
in vec2 uv;
out vec4 color;
void main() {
  vec3 N = normalize(wNormal);
  vec3 V = normalize(eye - wPos);
  vec3 ad = vec3(0.0), sp = vec3(0.0);
  for (int i = 0; i < nlights; ++i) {
    vec3 L = normalize(lights[i].pos.xyz - wPos * lights[i].pos.w);
    float spot = 1.0;
    if (lights[i].spot_cos > -1.0) {
      float c = dot(-L, normalize(lights[i].spot_dir));
      spot = c >= lights[i].spot_cos ? (lights[i].spot_exp == 0.0 ? 1.0 : pow(max(c, 0.0), lights[i].spot_exp)) : 0.0;
    }
    if (lights[i].pos.w != 0.0) {
      vec3 d = lights[i].pos.xyz / lights[i].pos.w - wPos;
      spot /= lights[i].att.x + lights[i].att.y * length(d) + lights[i].att.z * dot(d, d);
    }
    float cost = max(dot(N, L), 0.0);
    vec3 Hv = normalize(L + V);
    float cosd = cost > 0.0 ? pow(max(dot(N, Hv), 0.0), shine * shine_scale) : 0.0;
    vec3 Le = lights[i].Le * spot;
    ad += ka * lights[i].La + kd * Le * cost;
    sp += ks * Le * cosd;
  }
  ad += emission;
  if (textured) ad *= texture(tex, uv).rgb;
  color = vec4(ad + sp, 1.0);
}
)";

std::vector<uint8_t> render_tessel(const Scene& s) {
  gpu::Texture2D color(gpu::Format::RGBA8, W, H), depth(gpu::Format::Depth24Stencil8, W, H);
  gpu::Framebuffer fb(&color, &depth);
  gpu::Context ctx(2);
  ctx.bind_framebuffer(&fb);
  s.Render(ctx);
  ctx.finish();
  return gpu::read_rgba8(color);
}

// The same frame through OpenGL: what Scene::Render and PhongShader do, call for call.
std::vector<uint8_t> render_mesa(const Scene& s, float shine_scale) {
  GLuint fbo = 0, rb[2] = {0, 0};
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glGenRenderbuffers(2, rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, W, H);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
  glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, W, H);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, W, H);
  const GLuint prog = gl::build_program(kVertex, kFragment);
  glUseProgram(prog);
  auto loc = [&](const std::string& n) { return glGetUniformLocation(prog, n.c_str()); };

  glClearColor(s.background.r, s.background.g, s.background.b, s.background.a);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUniform1i(loc("nlights"), GLint(s.lights.size()));
  for (size_t i = 0; i < s.lights.size(); ++i) {
    const Light& l = s.lights[i];
    const std::string b = "lights[" + std::to_string(i) + "].";
    glUniform4fv(loc(b + "pos"), 1, glm::value_ptr(l.wLightPos));
    glUniform3fv(loc(b + "La"), 1, glm::value_ptr(l.La));
    glUniform3fv(loc(b + "Le"), 1, glm::value_ptr(l.Le));
    glUniform3fv(loc(b + "att"), 1, glm::value_ptr(l.attenuation));
    glUniform3fv(loc(b + "spot_dir"), 1, glm::value_ptr(l.spot_direction));
    glUniform1f(loc(b + "spot_cos"), l.spot_cos_cutoff);
    glUniform1f(loc(b + "spot_exp"), l.spot_exponent);
  }
  glUniform3fv(loc("eye"), 1, glm::value_ptr(s.camera.eye));
  glUniform1f(loc("shine_scale"), shine_scale);
  glUniform1i(loc("tex"), 0);
  const glm::mat4 VP = s.camera.P() * s.camera.V();
  std::vector<GLuint> objects;
  for (const auto& o : s.objects) {
    const Mesh& m = o->geometry->mesh();
    const std::vector<uint32_t> idx = m.triangle_list();
    GLuint vao = 0, buf[2] = {0, 0}, tex = 0;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(2, buf);
    glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m.vertices.size() * sizeof(VertexData)), m.vertices.data(),
                 GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(VertexData),
                          reinterpret_cast<void*>(offsetof(VertexData, pos)));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(VertexData),
                          reinterpret_cast<void*>(offsetof(VertexData, norm)));
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(VertexData),
                          reinterpret_cast<void*>(offsetof(VertexData, tex)));
    for (GLuint a = 0; a < 3; ++a) glEnableVertexAttribArray(a);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buf[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(idx.size() * 4), idx.data(), GL_STATIC_DRAW);
    const Material& mat = *o->material;
    if (mat.texture) {
      const gpu::Texture2D& t = *mat.texture;
      const std::vector<uint8_t> level0 = gpu::read_rgba8(t);
      glGenTextures(1, &tex);
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D, tex);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, t.width(), t.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   level0.data());
      glGenerateMipmap(GL_TEXTURE_2D);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    const glm::mat4 M = o->transform.world(), Nmat = glm::transpose(o->transform.world_inverse());
    const glm::mat4 MVP = VP * M;
    glUniformMatrix4fv(loc("MVP"), 1, GL_FALSE, glm::value_ptr(MVP));
    glUniformMatrix4fv(loc("M"), 1, GL_FALSE, glm::value_ptr(M));
    glUniformMatrix4fv(loc("Nmat"), 1, GL_FALSE, glm::value_ptr(Nmat));
    glUniform3fv(loc("ka"), 1, glm::value_ptr(mat.ka));
    glUniform3fv(loc("kd"), 1, glm::value_ptr(mat.kd));
    glUniform3fv(loc("ks"), 1, glm::value_ptr(mat.ks));
    glUniform3fv(loc("emission"), 1, glm::value_ptr(mat.emission));
    glUniform1f(loc("shine"), mat.shininess);
    glUniform1i(loc("textured"), mat.texture ? 1 : 0);
    if (o->cull_back_faces)
      glEnable(GL_CULL_FACE);
    else
      glDisable(GL_CULL_FACE);
    glDrawElements(GL_TRIANGLES, GLsizei(idx.size()), GL_UNSIGNED_INT, nullptr);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    glDeleteTextures(1, &tex);
    glDeleteBuffers(2, buf);
    glDeleteVertexArrays(1, &vao);
  }
  std::vector<uint8_t> px(size_t(W) * H * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  glDeleteProgram(prog);
  glDeleteRenderbuffers(2, rb);
  glDeleteFramebuffers(1, &fbo);
  return px;
}

}  // namespace

TEST(SceneMesa, BlinnPhongAgreesWithAGlslPortOnLlvmpipe) {
  std::string why;
  const auto gl = gl::HeadlessContext::create(&why);
  if (!gl) GTEST_SKIP() << "no Mesa llvmpipe context: " << why;
  Scene s = test::make_scene(40.0f, /*gouraud_left=*/false);
  s.camera.aspect = float(W) / float(H);
  const std::vector<uint8_t> tessel_px = render_tessel(s);
  const std::vector<uint8_t> mesa_px = render_mesa(s, 1.0f);
  const test::ImageDiff d = test::diff_rgba(tessel_px, mesa_px);
  std::printf("Blinn-Phong scene %dx%d: %d of %d pixels differ by more than 2/255 (max %d/255)\n", W, H,
              d.differing, d.total, d.max_diff);
  if (!d.passes()) {
    gpu::write_png("scene_phong_tessel.png", W, H, 4, tessel_px.data());
    gpu::write_png("scene_phong_mesa.png", W, H, 4, mesa_px.data());
  }
  EXPECT_TRUE(d.passes()) << d.differing << " of " << d.total << " pixels differ (max " << d.max_diff << ")";
  // The tolerance would catch a wrong specular exponent.
  const test::ImageDiff off = test::diff_rgba(tessel_px, render_mesa(s, 1.1f));
  EXPECT_FALSE(off.passes()) << "a 10% shininess error gives only " << off.differing << " differing pixels";
}
