// tessel_peer: renders one of the standard benchmark scenes (bench/scenes, defined in
// shared/scenes/README.md) through real OpenGL 3.3 core on Mesa llvmpipe, headless (EGL
// surfaceless + an FBO), times it frame by frame and prints one line of JSON. It is the peer
// that `tessel bench --peer` compares Tessel against.
//
//   tessel_peer --scene NAME --size WxH --threads N [--frames F] [--warmup W] [--instanced]
//               [--image PATH]
//
// Exit codes: 0 success, 1 runtime failure (EGL, GL, I/O), 2 bad arguments.
// The headless context comes from tessel_gl_headless (bench/gl); GL entry points come straight
// from libOpenGL (glvnd), dispatched to the EGL context.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include "fixed_gl.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "headless_gl.hpp"
#include "scenes.hpp"

namespace scenes = tessel::scenes;

namespace {

// ---- Command line --------------------------------------------------------------------------

struct Options {
  std::string scene, image;
  int width = 0, height = 0, threads = 0, frames = 10, warmup = 3;
  bool instanced = false;
};

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const char* const kUsage =
    "usage: tessel_peer --scene NAME --size WxH --threads N [--frames F (10)] [--warmup W (3)]\n"
    "                   [--instanced] [--image PATH]";

// Parses a whole string as a decimal int in [lo, hi].
int parse_int(const std::string& s, int lo, int hi, const std::string& what) {
  int v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size() || v < lo || v > hi)
    throw UsageError(what + " must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                     "], got '" + s + "'");
  return v;
}

Options parse_args(int argc, char** argv) {
  Options o;
  bool have_size = false, have_threads = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    // Every option except --instanced takes one value: the next argument.
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(a + " needs a value");
      return argv[++i];
    };
    if (a == "--scene") {
      o.scene = value();
    } else if (a == "--size") {
      const std::string v = value();
      const size_t x = v.find('x');
      if (x == std::string::npos) throw UsageError("--size must be WxH, got '" + v + "'");
      o.width = parse_int(v.substr(0, x), 1, 16384, "--size width");
      o.height = parse_int(v.substr(x + 1), 1, 16384, "--size height");
      have_size = true;
    } else if (a == "--threads") {
      o.threads = parse_int(value(), 1, 1024, "--threads");
      have_threads = true;
    } else if (a == "--frames") {
      o.frames = parse_int(value(), 1, 100000, "--frames");
    } else if (a == "--warmup") {
      o.warmup = parse_int(value(), 0, 100000, "--warmup");
    } else if (a == "--instanced") {
      o.instanced = true;
    } else if (a == "--image") {
      o.image = value();
      if (o.image.empty()) throw UsageError("--image needs a non-empty path");
    } else {
      throw UsageError("unknown argument '" + a + "'");
    }
  }
  if (o.scene.empty()) throw UsageError("--scene is required");
  if (!have_size) throw UsageError("--size is required");
  if (!have_threads) throw UsageError("--threads is required");
  return o;
}

// ---- Small helpers -------------------------------------------------------------------------

// Throws with the name of the call if GL has recorded an error (draining the queue).
void check_gl(const char* what) {
  GLenum e = glGetError();
  if (e == GL_NO_ERROR) return;
  char buf[96];
  std::snprintf(buf, sizeof buf, "GL error 0x%04X", unsigned(e));
  std::string msg = std::string(buf) + " after " + what;
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
  }
  throw std::runtime_error(msg);
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const unsigned char c : s) {
    if (c == '"')
      out += "\\\"";
    else if (c == '\\')
      out += "\\\\";
    else if (c == '\n')
      out += "\\n";
    else if (c == '\t')
      out += "\\t";
    else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", unsigned(c));
      out += buf;
    } else
      out += char(c);
  }
  return out + "\"";
}

std::string fmt(double v, const char* f = "%.3f") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// Peak resident set size (VmHWM) in MB, or 0 if /proc is unavailable.
double peak_rss_mb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::strtod(line.c_str() + 6, nullptr) / 1024.0;
  return 0.0;
}

// ---- Shaders -------------------------------------------------------------------------------

GLuint build_program(bool textured, bool instanced) {
  // Throws "shader compile failed: <log>" / "program link failed: <log>".
  return tessel::gl::build_program(scenes::scene_vertex_glsl(textured, instanced),
                                   scenes::scene_fragment_glsl(textured, instanced));
}

const void* byte_offset(size_t bytes) { return reinterpret_cast<const void*>(bytes); }

// ---- The benchmark -------------------------------------------------------------------------

// Warm-up and timed frames, the last frame read back (and written to --image), and the one
// line of JSON on stdout.
int measure(const Options& opt, const scenes::Scene& scene, const std::string& renderer, bool instanced,
            const std::function<void()>& frame) {
  const int W = opt.width, H = opt.height;
  for (int i = 0; i < opt.warmup; ++i) frame();
  check_gl("warm-up frames");
  std::vector<double> ms;
  for (int i = 0; i < opt.frames; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    frame();
    const auto t1 = std::chrono::steady_clock::now();
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  check_gl("timed frames");

  // Median (mean of the two middle values for an even count) and minimum.
  std::vector<double> sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  const size_t n = sorted.size();
  const double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);

  // Read back the last frame (rows bottom-up) and write it as a PNG, top row first.
  std::vector<uint8_t> pixels(size_t(W) * size_t(H) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  check_gl("glReadPixels");
  if (!opt.image.empty()) {
    const std::string tmp = opt.image + ".tmp";
    stbi_flip_vertically_on_write(1);
    if (!stbi_write_png(tmp.c_str(), W, H, 4, pixels.data(), W * 4)) {
      std::remove(tmp.c_str());
      throw std::runtime_error("cannot write " + tmp);
    }
    if (std::rename(tmp.c_str(), opt.image.c_str()) != 0) {
      std::remove(tmp.c_str());
      throw std::runtime_error("cannot rename " + tmp + " to " + opt.image + ": " + std::strerror(errno));
    }
  }

  // The result: exactly one line of JSON on stdout.
  std::string ms_list;
  for (const double v : ms) {
    if (!ms_list.empty()) ms_list += ',';
    ms_list += fmt(v);
  }
  std::string json =
      "{\"scene\":" + json_string(scene.name) + ",\"width\":" + std::to_string(W) +
      ",\"height\":" + std::to_string(H) + ",\"threads\":" + std::to_string(opt.threads) +
      ",\"instanced\":" + (instanced ? "true" : "false") + ",\"frames\":" + std::to_string(opt.frames) +
      ",\"ms_median\":" + fmt(median) + ",\"ms_min\":" + fmt(sorted.front()) + ",\"ms\":[" + ms_list +
      "],\"peak_rss_mb\":" + fmt(peak_rss_mb(), "%.1f") +
      ",\"triangles\":" + std::to_string(scene.triangles()) + ",\"renderer\":" + json_string(renderer) +
      ",\"image\":" + json_string(opt.image) + "}\n";
  std::fputs(json.c_str(), stdout);
  std::fflush(stdout);
  return 0;
}

// The fixed-100k scene through OpenGL 1.x fixed function (a compatibility context), with the
// calls of bench/scenes/fixed_gl.hpp and client-side vertex arrays.
int run_fixed(const Options& opt, const scenes::Scene& scene, const std::string& renderer, GLuint fbo,
              const GLuint rb[2]) {
  glDisable(GL_DITHER);
  scenes::fixed_setup(scene);
  check_gl("fixed-function setup");
  const int rc = measure(opt, scene, renderer, false, [&] {
    scenes::fixed_frame(scene);
    glFinish();
  });
  glDeleteRenderbuffers(2, rb);
  glDeleteFramebuffers(1, &fbo);
  return rc;
}

int run(const Options& opt, const scenes::Scene& scene) {
  // EGL surfaceless (or a fallback route), desktop GL 3.3 core, current, on llvmpipe; torn
  // down when `gl` goes out of scope (also on error paths).
  std::string why;
  tessel::gl::HeadlessOptions hopt;
  hopt.compat_profile = scene.fixed_function;  // fixed function needs a compatibility context
  hopt.accept_tessel = true;                   // this binary also runs on Tessel's libraries
  const auto gl = tessel::gl::HeadlessContext::create(&why, hopt);
  if (!gl) throw std::runtime_error(why);
  const std::string renderer = gl->renderer();
  const int W = opt.width, H = opt.height;

  // Framebuffer: RGBA8 colour + DEPTH24_STENCIL8 renderbuffers.
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
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("framebuffer incomplete");
  glViewport(0, 0, W, H);
  check_gl("framebuffer setup");

  // The fixed-function scene: the OpenGL 1.x calls of bench/scenes/fixed_gl.hpp with client
  // vertex arrays, exactly as Tessel gets them.
  if (scene.fixed_function) return run_fixed(opt, scene, renderer, fbo, rb);

  // Geometry: one VAO with the interleaved vertex buffer and the index buffer.
  GLuint vao = 0, buf[3] = {0, 0, 0};  // vertices, indices, instances
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(3, buf);
  glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(scene.mesh.vertices.size() * sizeof(float)),
               scene.mesh.vertices.data(), GL_STATIC_DRAW);
  const GLsizei stride = scenes::Mesh::kStride * sizeof(float);  // 32 bytes
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, byte_offset(0));
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, byte_offset(12));
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, byte_offset(24));
  for (GLuint a = 0; a < 3; ++a) glEnableVertexAttribArray(a);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buf[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(scene.mesh.indices.size() * sizeof(uint32_t)),
               scene.mesh.indices.data(), GL_STATIC_DRAW);

  // Instanced drawing: per-instance offset (attrib 3) and albedo (attrib 4), divisor 1.
  const bool instanced = opt.instanced && scene.instanceable && !scene.draws.empty();
  if (instanced) {
    std::vector<float> inst;
    for (const scenes::Draw& d : scene.draws)
      inst.insert(inst.end(), {d.offset.x, d.offset.y, d.offset.z, d.albedo.x, d.albedo.y, d.albedo.z});
    glBindBuffer(GL_ARRAY_BUFFER, buf[2]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(inst.size() * sizeof(float)), inst.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(3, 3, GL_FLOAT, GL_FALSE, 24, byte_offset(0));
    glVertexAttribPointer(4, 3, GL_FLOAT, GL_FALSE, 24, byte_offset(12));
    for (GLuint a = 3; a < 5; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribDivisor(a, 1);
    }
  }
  check_gl("vertex/index buffer setup");

  // Texture (textured scene): 1024x1024 RGBA8, rows bottom-up, full mipmap chain.
  GLuint tex = 0;
  if (scene.textured) {
    const std::vector<uint8_t> texels = scenes::texture_rgba8();
    glGenTextures(1, &tex);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, scenes::kTextureSize, scenes::kTextureSize, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, texels.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    check_gl("texture setup");
  }

  // Program and per-scene uniforms.
  const GLuint prog = build_program(scene.textured, instanced);
  glUseProgram(prog);
  const glm::mat4 viewproj = scene.projection * scene.view;
  glUniformMatrix4fv(glGetUniformLocation(prog, "u_viewproj"), 1, GL_FALSE, glm::value_ptr(viewproj));
  glUniform3fv(glGetUniformLocation(prog, "u_light"), 1, glm::value_ptr(scene.light));
  glUniform3fv(glGetUniformLocation(prog, "u_eye"), 1, glm::value_ptr(scene.eye));
  if (scene.textured) glUniform1i(glGetUniformLocation(prog, "u_tex"), 0);
  const GLint loc_offset = glGetUniformLocation(prog, "u_offset");  // -1 if unused: ignored
  const GLint loc_albedo = glGetUniformLocation(prog, "u_albedo");
  check_gl("program setup");

  // Fixed state of the scenes README.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  glDisable(GL_BLEND);
  glDisable(GL_DITHER);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClearDepth(1.0);
  check_gl("render state setup");

  // One frame: clear, every draw in order (or one instanced draw), then wait for the GPU.
  auto frame = [&] {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (instanced) {
      const scenes::Draw& d = scene.draws.front();
      glDrawElementsInstanced(GL_TRIANGLES, GLsizei(d.index_count), GL_UNSIGNED_INT,
                              byte_offset(size_t(d.first_index) * sizeof(uint32_t)),
                              GLsizei(scene.draws.size()));
    } else {
      for (const scenes::Draw& d : scene.draws) {
        glUniform3fv(loc_offset, 1, glm::value_ptr(d.offset));
        glUniform3fv(loc_albedo, 1, glm::value_ptr(d.albedo));
        glDrawElements(GL_TRIANGLES, GLsizei(d.index_count), GL_UNSIGNED_INT,
                       byte_offset(size_t(d.first_index) * sizeof(uint32_t)));
      }
    }
    glFinish();
  };

  const int rc = measure(opt, scene, renderer, instanced, frame);
  glDeleteProgram(prog);
  if (tex) glDeleteTextures(1, &tex);
  glDeleteBuffers(3, buf);
  glDeleteVertexArrays(1, &vao);
  glDeleteRenderbuffers(2, rb);
  glDeleteFramebuffers(1, &fbo);

  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  try {
    opt = parse_args(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "tessel_peer: %s\n%s\n", e.what(), kUsage);
    return 2;
  }

  // llvmpipe's thread count, before anything touches EGL/Mesa. (HeadlessContext::create
  // defaults GALLIUM_DRIVER=llvmpipe and LIBGL_ALWAYS_SOFTWARE=1 before it opens EGL.)
  setenv("LP_NUM_THREADS", std::to_string(opt.threads).c_str(), 1);

  scenes::Scene scene;
  try {
    scene = scenes::make_scene(opt.scene, opt.width, opt.height);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "tessel_peer: %s\n", e.what());
    return 2;
  }
  try {
    return run(opt, scene);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tessel_peer: %s\n", e.what());
    return 1;
  }
}
