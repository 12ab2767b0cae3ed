// Runs piglit's .shader_test files (Debian package `piglit`) on Tessel's GLSL compiler and
// pipeline, without a window system, and counts pass / fail / skip per GLSL version.
//
//   tessel_piglit [--verbose] [--list-failures] DIR_OR_FILE...
//
// What it understands of the format (piglit's shader_runner): [require] with GLSL and GL
// versions (extensions, GLSL ES and the stages of GL 4 are skipped), [vertex shader],
// [vertex shader passthrough], [geometry shader], [fragment shader], [vertex data], and in
// [test]: uniform,
// clear color, clear, draw rect [ortho], draw arrays, probe rgb/rgba (pixel, rect, all,
// relative), link error / link success, ortho. A test that needs anything else is counted as
// skipped with the reason. The default window is 250x250 RGBA8, probes allow 0.01 per channel
// (piglit's default tolerance).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "tessel/glsl/program.hpp"

namespace fs = std::filesystem;
using namespace tessel;

namespace {

enum class Outcome { Pass, Fail, Skip };
struct Result {
  Outcome outcome = Outcome::Pass;
  std::string why;
};

std::string trim(std::string s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

std::vector<float> numbers(const std::string& s) {
  std::vector<float> v;
  std::string t = s;
  for (char& c : t)
    if (c == '(' || c == ')' || c == ',') c = ' ';
  std::istringstream in(t);
  std::string w;
  while (in >> w) {
    char* end = nullptr;
    if (w.rfind("0x", 0) == 0 || w.rfind("-0x", 0) == 0) {
      v.push_back(float(std::strtoll(w.c_str(), &end, 16)));
    } else {
      v.push_back(std::strtof(w.c_str(), &end));
    }
  }
  return v;
}

enum class ValueKind { Float, Int, Uint, Bool };
ValueKind value_kind(const std::string& type) {
  if (type.find("sampler") != std::string::npos || type == "int" || type.rfind("ivec", 0) == 0)
    return ValueKind::Int;
  if (type == "uint" || type.rfind("uvec", 0) == 0) return ValueKind::Uint;
  if (type == "bool" || type.rfind("bvec", 0) == 0) return ValueKind::Bool;
  return ValueKind::Float;
}

// The 32-bit words of a `uniform` command's values: integers exactly (hex included), floats
// by value or, written in hex, by their bits, bools as 0 or 1.
std::vector<uint32_t> value_words(ValueKind kind, std::string text) {
  for (char& c : text)
    if (c == '(' || c == ')' || c == ',') c = ' ';
  std::istringstream w(text);
  std::vector<uint32_t> words;
  for (std::string tok; w >> tok;) {
    if (kind == ValueKind::Int || kind == ValueKind::Uint) {
      words.push_back(uint32_t(std::strtoll(tok.c_str(), nullptr, 0)));
    } else if (kind == ValueKind::Bool) {
      words.push_back(std::strtof(tok.c_str(), nullptr) != 0.0f);
    } else if (tok.rfind("0x", 0) == 0) {
      words.push_back(uint32_t(std::strtoull(tok.c_str(), nullptr, 16)));
    } else {
      const float x = std::strtof(tok.c_str(), nullptr);
      uint32_t u;
      std::memcpy(&u, &x, 4);
      words.push_back(u);
    }
  }
  return words;
}

struct Test {
  int glsl = 110;  // required GLSL version * 100
  int width = 250, height = 250;
  std::string vs, fs;
  // Further [vertex shader] / [fragment shader] sections: more compilation units of the stage.
  std::vector<std::string> more_vs, more_fs;
  std::vector<std::string> gs;  // [geometry shader] sections, each a compilation unit
  bool passthrough = false;
  std::vector<std::string> vertex_data;
  std::vector<std::string> test;
  std::string skip;
};

Test parse(const std::string& path) {
  Test t;
  std::ifstream in(path);
  std::string line, section;
  while (std::getline(in, line)) {
    const std::string tl = trim(line);
    if (!tl.empty() && tl[0] == '[' && tl.back() == ']') {
      section = tl;
      if (tl == "[vertex shader]" && !t.vs.empty()) t.more_vs.emplace_back();
      if (tl == "[fragment shader]" && !t.fs.empty()) t.more_fs.emplace_back();
      if (tl == "[geometry shader]") t.gs.emplace_back();
      if (section == "[vertex shader passthrough]")
        t.passthrough = true;
      else if (section != "[require]" && section != "[vertex shader]" && section != "[fragment shader]" &&
               section != "[geometry shader]" && section != "[test]" && section != "[vertex data]")
        t.skip = "section " + section;
      continue;
    }
    if (section == "[require]") {
      if (tl.empty() || tl[0] == '#') continue;
      std::istringstream w(tl);
      std::string a, op, ver;
      w >> a;
      if (a == "GLSL") {
        w >> op >> ver;
        if (op == "ES" || ver == "ES")
          t.skip = "GLSL ES";
        else if (op == ">=")
          t.glsl = int(std::lround(std::stod(ver) * 100));
        else if (op != "<" && op != "<=")
          t.skip = "GLSL requirement " + tl;
      } else if (a == "GL") {
        w >> op >> ver;
        if (op == "ES")
          t.skip = "GL ES";
        else if (op == ">=" && std::stod(ver) > 3.3)
          t.skip = "needs " + tl;
      } else if (a == "SIZE") {
        w >> t.width >> t.height;
      } else if (a.rfind("GL_", 0) == 0) {
        t.skip = "extension " + a;
      } else if (a.rfind("GLSL", 0) != 0 && a != "GL" && !a.empty()) {
        // limits such as GL_MAX_... or "rlimit": taken as met
      }
    } else if (section == "[vertex shader]") {
      (t.more_vs.empty() ? t.vs : t.more_vs.back()) += line + "\n";
    } else if (section == "[fragment shader]") {
      (t.more_fs.empty() ? t.fs : t.more_fs.back()) += line + "\n";
    } else if (section == "[geometry shader]") {
      t.gs.back() += line + "\n";
    } else if (section == "[vertex data]") {
      if (!tl.empty() && tl[0] != '#') t.vertex_data.push_back(tl);
    } else if (section == "[test]") {
      std::string cmd = tl;
      if (const auto hash = cmd.find('#'); hash != std::string::npos) cmd = trim(cmd.substr(0, hash));
      if (!cmd.empty()) t.test.push_back(cmd);
    }
  }
  return t;
}

struct Runner {
  Test t;
  std::shared_ptr<glsl::Program> prog;
  gpu::Context ctx{1};
  std::unique_ptr<gpu::Texture2D> color;
  gpu::Framebuffer fb;
  glm::vec4 clear_color{0.0f};

  Result fail(const std::string& why) { return {Outcome::Fail, why}; }
  Result skip(const std::string& why) { return {Outcome::Skip, why}; }

  glm::vec4 pixel(int x, int y) { return color->fetch(0, x, y); }

  bool probe(int x0, int y0, int w, int h, const std::vector<float>& want, int n, std::string& why) {
    for (int y = y0; y < y0 + h; ++y)
      for (int x = x0; x < x0 + w; ++x) {
        if (x < 0 || y < 0 || x >= t.width || y >= t.height) continue;
        const glm::vec4 got = pixel(x, y);
        for (int c = 0; c < n; ++c)
          if (std::fabs(got[c] - want[size_t(c)]) > 0.01f) {
            char buf[256];
            std::snprintf(buf, sizeof buf, "probe at (%d, %d): expected (%g %g %g %g) got (%g %g %g %g)", x,
                          y, double(want[0]), double(want[1]), double(want[2]), n > 3 ? double(want[3]) : 0.0,
                          double(got.r), double(got.g), double(got.b), double(got.a));
            why = buf;
            return false;
          }
      }
    return true;
  }

  gpu::RenderState render_state;  // what enable/disable set
  void draw_quad(float x, float y, float w, float h) {
    const float v[] = {x, y, 0, 1, x + w, y,     0, 1, x + w, y + h, 0, 1,
                       x, y, 0, 1, x + w, y + h, 0, 1, x,     y + h, 0, 1};
    gpu::Buffer vbo(v, sizeof v);
    gpu::VertexLayout layout;
    layout.attrib(0, vbo, 4, gpu::AttribType::F32, 16, 0);
    draw(layout, {.topology = gpu::Topology::Triangles, .count = 6});
  }
  void draw(const gpu::VertexLayout& layout, const gpu::DrawCall& call) {
    gpu::RenderState state = render_state;
    std::vector<glsl::BufferBinding> points;
    block_buffers.clear();
    for (size_t i = 0; i < block_data.size(); ++i) {
      block_buffers.push_back(std::make_unique<gpu::Buffer>(block_data[i].data(), block_data[i].size()));
      prog->set_uniform_block_binding(int(i), int(i));
      points.push_back({block_buffers.back().get(), 0, 0});
    }
    prog->draw(ctx, layout, state, call, {}, points);
    ctx.finish();
  }

  // `draw arrays MODE first count` over the [vertex data] section: its header names each
  // column's attribute, type and size ("vertex/float/3 colour/float/4"; int and uint too).
  Result draw_arrays(const std::string& mode, int first, int count) {
    static const std::map<std::string, gpu::Topology> kModes = {
        {"GL_POINTS", gpu::Topology::Points},           {"GL_LINES", gpu::Topology::Lines},
        {"GL_LINE_STRIP", gpu::Topology::LineStrip},    {"GL_LINE_LOOP", gpu::Topology::LineLoop},
        {"GL_TRIANGLES", gpu::Topology::Triangles},     {"GL_TRIANGLE_STRIP", gpu::Topology::TriangleStrip},
        {"GL_TRIANGLE_FAN", gpu::Topology::TriangleFan}};
    const auto m = kModes.find(mode);
    if (m == kModes.end() || t.vertex_data.empty() || first < 0 || count < 0)
      return skip("command: draw arrays " + mode);
    struct Column {
      int location, size;
      bool integer;
    };
    std::vector<Column> columns;
    std::istringstream head(t.vertex_data[0]);
    std::string spec;
    while (head >> spec) {
      const auto a = spec.find('/'), b = spec.rfind('/');
      if (a == std::string::npos || a == b) return skip("vertex data header: " + spec);
      const std::string name = spec.substr(0, a), type = spec.substr(a + 1, b - a - 1);
      const int size = std::atoi(spec.c_str() + b + 1);
      if (size < 1 || size > 4 || (type != "float" && type != "int" && type != "uint"))
        return skip("vertex data column: " + spec);
      int loc = prog->attribute_location(name);
      if (loc < 0) loc = glsl::builtin_attribute_location(name);
      columns.push_back({loc, size, type != "float"});
    }
    const int rows = int(t.vertex_data.size()) - 1;
    if (first + count > rows) return fail("draw arrays past the vertex data");
    std::vector<std::vector<uint32_t>> data(columns.size());
    for (int r = 1; r <= rows; ++r) {
      std::istringstream in(t.vertex_data[size_t(r)]);
      for (size_t c = 0; c < columns.size(); ++c)
        for (int k = 0; k < columns[c].size; ++k) {
          std::string w;
          in >> w;
          uint32_t bits;
          if (columns[c].integer) {
            bits = uint32_t(std::stoll(w, nullptr, 0));
          } else {
            const float f = std::stof(w);
            std::memcpy(&bits, &f, 4);
          }
          data[c].push_back(bits);
        }
    }
    std::vector<std::unique_ptr<gpu::Buffer>> vbos;
    gpu::VertexLayout layout;
    for (size_t c = 0; c < columns.size(); ++c) {
      if (columns[c].location < 0) continue;  // inactive, as GL skips location -1
      vbos.push_back(std::make_unique<gpu::Buffer>(data[c].data(), data[c].size() * 4));
      layout.attrib(columns[c].location, *vbos.back(), columns[c].size,
                    columns[c].integer ? gpu::AttribType::I32 : gpu::AttribType::F32, 0, 0);
      layout.attribs[size_t(columns[c].location)].integer = columns[c].integer;
    }
    draw(layout, {.topology = m->second, .first = uint32_t(first), .count = uint32_t(count)});
    return {};
  }

  // Uniform blocks get a buffer each, bound at the block's index (as shader_runner does);
  // `uniform` commands for block members write into it at the member's std140 offset.
  std::vector<std::vector<uint8_t>> block_data;
  std::vector<std::unique_ptr<gpu::Buffer>> block_buffers;

  Result set_block_member(const std::string& type, const std::string& name, const std::string& line) {
    std::string base = name;
    int index = 0;
    // A trailing [n] is the element of an array member; brackets before it are part of the
    // member's name (s[0].arr[1].v).
    if (const auto b = name.rfind('[');
        b != std::string::npos && name.back() == ']' && name.find('.', b) == std::string::npos) {
      base = name.substr(0, b);
      index = std::atoi(name.c_str() + b + 1);
    }
    const auto& blocks = prog->uniform_blocks();
    for (size_t bi = 0; bi < blocks.size(); ++bi)
      for (const auto& m : blocks[bi].members) {
        std::string mname = m.name;
        if (const auto dot = mname.find('.'); dot != std::string::npos && base.find('.') == std::string::npos)
          mname = mname.substr(dot + 1);
        if (mname != base) continue;
        std::istringstream in(line);
        std::string kw, t, n, rest;
        in >> kw >> t >> n;
        std::getline(in, rest);
        const std::vector<uint32_t> words = value_words(value_kind(type), rest);
        const bool matrix = type.rfind("mat", 0) == 0;
        const int cols = matrix ? type[3] - '0' : 1;
        const int rows = matrix ? (type.size() > 5 ? type[5] - '0' : cols) : int(words.size());
        size_t off = size_t(m.offset) + size_t(index) * size_t(m.array_stride);
        auto& data = block_data[bi];
        for (int c = 0; c < cols; ++c)
          for (int r = 0; r < rows; ++r) {
            const size_t k = size_t(c * rows + r);
            if (k >= words.size()) continue;
            // Column c, row r: a column-major matrix's columns are matrix_stride apart, a
            // row-major one's rows.
            const size_t stride = size_t(m.matrix_stride ? m.matrix_stride : 16);
            const size_t at = !matrix       ? off + size_t(r) * 4
                              : m.row_major ? off + size_t(r) * stride + size_t(c) * 4
                                            : off + size_t(c) * stride + size_t(r) * 4;
            if (at + 4 <= data.size()) std::memcpy(&data[at], &words[k], 4);
          }
        return {};
      }
    return {};  // inactive uniforms are ignored, as GL ignores location -1
  }

  Result set_uniform(const std::string& line) {
    std::istringstream in(line);
    std::string kw, type, name;
    in >> kw >> type >> name;
    std::string rest;
    std::getline(in, rest);
    const int loc = prog->uniform_location(name);
    if (loc < 0) return set_block_member(type, name, line);
    const ValueKind kind = value_kind(type);
    std::vector<uint32_t> words = value_words(kind, rest);
    if (words.empty()) return skip("uniform without values: " + line);
    bool ok = false;
    if (kind == ValueKind::Uint) {
      ok = prog->set_uniform(loc, words.data(), int(words.size()));
    } else if (kind != ValueKind::Float) {
      std::vector<int32_t> iv(words.begin(), words.end());
      ok = prog->set_uniform(loc, iv.data(), int(iv.size()));
    } else {
      // Missing components of a vector read as 0 (shader_runner's parser).
      const int want = type == "vec2" ? 2 : type == "vec3" ? 3 : type == "vec4" ? 4 : 0;
      if (want && int(words.size()) % want)
        words.resize(words.size() + size_t(want - int(words.size()) % want), 0u);
      std::vector<float> f(words.size());
      std::memcpy(f.data(), words.data(), words.size() * 4);
      ok = prog->set_uniform(loc, f.data(), int(f.size()));
    }
    if (!ok) return fail("could not set uniform: " + line);
    return {};
  }

  Result run() {
    if (!t.skip.empty()) return skip(t.skip);
    if (t.fs.empty() && t.vs.empty()) return skip("no shaders");
    std::string vs = t.vs;
    if (t.passthrough || vs.empty()) {
      if (t.glsl >= 140)
        vs = "#version " + std::to_string(t.glsl) +
             "\nin vec4 piglit_vertex;\nvoid main() { gl_Position = piglit_vertex; }\n";
      else
        vs = "#version 110\nvoid main() { gl_Position = gl_Vertex; }\n";
    }
    std::string fs = t.fs;
    // Without a fragment shader GL's fixed-function fragment stage runs: with texturing and
    // fog off (what the runner sets up), it writes the interpolated primary colour. (As GLSL
    // 1.10, where gl_Color is declared whatever the other stages' versions.)
    if (fs.empty()) fs = "#version 110\nvoid main() { gl_FragColor = gl_Color; }\n";
    // A shader without #version is compiled at the version the test requires, as shader_runner
    // does.
    auto versioned = [&](const std::string& src) {
      if (src.find("#version") != std::string::npos || t.glsl == 110) return src;
      return "#version " + std::to_string(t.glsl) + "\n" + src;
    };
    vs = versioned(vs);
    fs = versioned(fs);
    bool expect_link_error = false;
    for (const std::string& c : t.test)
      if (c == "link error") expect_link_error = true;
    std::vector<std::shared_ptr<glsl::Shader>> shaders = {glsl::Shader::compile(glsl::Stage::Vertex, vs),
                                                          glsl::Shader::compile(glsl::Stage::Fragment, fs)};
    for (const std::string& s : t.more_vs)
      shaders.push_back(glsl::Shader::compile(glsl::Stage::Vertex, versioned(s)));
    for (const std::string& s : t.more_fs)
      shaders.push_back(glsl::Shader::compile(glsl::Stage::Fragment, versioned(s)));
    for (const std::string& s : t.gs)
      shaders.push_back(glsl::Shader::compile(glsl::Stage::Geometry, versioned(s)));
    std::vector<const glsl::Shader*> units;
    for (const auto& s : shaders) {
      if (!s->ok()) {
        if (expect_link_error) return {};
        return fail("compile: " + s->info_log());
      }
      units.push_back(s.get());
    }
    glsl::LinkOptions lo;
    lo.attribute_locations["piglit_vertex"] = 0;
    lo.native_code = glsl::NativeCode::AtLink;  // the native code is what is tested
    prog = glsl::Program::link(units, lo);
    if (expect_link_error) return prog->ok() ? fail("linked, but a link error was expected") : Result{};
    if (!prog->ok()) {
      if (prog->info_log().find("not supported") != std::string::npos)
        return skip("Tessel: " + prog->info_log());
      return fail("link: " + prog->info_log());
    }
    for (const auto& b : prog->uniform_blocks()) block_data.emplace_back(size_t(b.size), uint8_t(0));
    color = std::make_unique<gpu::Texture2D>(gpu::Format::RGBA8, t.width, t.height);
    fb = gpu::Framebuffer(color.get());
    ctx.bind_framebuffer(&fb);
    for (const std::string& c : t.test) {
      std::istringstream in(c);
      std::string w1, w2;
      in >> w1 >> w2;
      try {
        if (w1 == "uniform") {
          Result r = set_uniform(c);
          if (r.outcome != Outcome::Pass) return r;
        } else if (w1 == "clear" && w2 == "color") {
          const auto n = numbers(c.substr(11));
          if (n.size() >= 4) clear_color = glm::vec4(n[0], n[1], n[2], n[3]);
        } else if (w1 == "clear") {
          ctx.clear({.color = clear_color, .clear_depth = false, .clear_stencil = false});
          ctx.finish();
        } else if (w1 == "draw" && w2 == "arrays") {
          std::string mode;
          int first = -1, count = -1;
          in >> mode >> first >> count;
          Result r = draw_arrays(mode, first, count);
          if (r.outcome != Outcome::Pass) return r;
        } else if (w1 == "draw" && w2 == "rect") {
          std::string rest;
          std::getline(in, rest);
          bool ortho = false;
          if (trim(rest).rfind("ortho", 0) == 0) {
            ortho = true;
            rest = trim(rest).substr(5);
          }
          const auto n = numbers(rest);
          if (n.size() < 4) return skip("draw rect form: " + c);
          float x = n[0], y = n[1], w = n[2], h = n[3];
          if (ortho) {
            x = 2.0f * x / float(t.width) - 1.0f;
            y = 2.0f * y / float(t.height) - 1.0f;
            w = 2.0f * w / float(t.width);
            h = 2.0f * h / float(t.height);
          }
          draw_quad(x, y, w, h);
        } else if (w1 == "probe" || w1 == "relative") {
          std::string rest = c;
          const bool relative = w1 == "relative";
          if (relative) rest = trim(rest.substr(8));
          rest = trim(rest.substr(5));  // after "probe"
          std::string kind;
          {
            std::istringstream k(rest);
            k >> kind;
          }
          bool all = false, rect = false;
          if (kind == "all") {
            all = true;
            rest = trim(rest.substr(3));
          } else if (kind == "rect") {
            rect = true;
            rest = trim(rest.substr(4));
          }
          std::istringstream k(rest);
          std::string comps;
          k >> comps;
          int nc = comps == "rgba" ? 4 : comps == "rgb" ? 3 : 0;
          if (!nc) return skip("probe form: " + c);
          std::string tail;
          std::getline(k, tail);
          const auto n = numbers(tail);
          std::string why;
          bool ok;
          if (all) {
            if (int(n.size()) < nc) return skip("probe form: " + c);
            ok = probe(0, 0, t.width, t.height, n, nc, why);
          } else if (rect) {
            if (int(n.size()) < 4 + nc) return skip("probe form: " + c);
            std::vector<float> want(n.begin() + 4, n.end());
            int x = int(n[0]), y = int(n[1]), w = int(n[2]), h = int(n[3]);
            if (relative) {
              x = int(n[0] * float(t.width));
              y = int(n[1] * float(t.height));
              w = int(n[2] * float(t.width));
              h = int(n[3] * float(t.height));
            }
            ok = probe(x, y, w, h, want, nc, why);
          } else {
            if (int(n.size()) < 2 + nc) return skip("probe form: " + c);
            std::vector<float> want(n.begin() + 2, n.end());
            int x = int(n[0]), y = int(n[1]);
            if (relative) {
              x = int(n[0] * float(t.width));
              y = int(n[1] * float(t.height));
            }
            ok = probe(x, y, 1, 1, want, nc, why);
          }
          if (!ok) return fail(why);
        } else if ((w1 == "enable" || w1 == "disable") &&
                   (w2.rfind("GL_CLIP_PLANE", 0) == 0 || w2.rfind("GL_CLIP_DISTANCE", 0) == 0)) {
          // GL_CLIP_DISTANCEi is GL_CLIP_PLANEi: the program's clip distance i where it writes
          // one (planes given with "clip plane", for gl_ClipVertex, are not supported).
          const int i = w2.back() - '0';
          if (i < 0 || i >= gpu::kMaxClipPlanes) return skip("command: " + c);
          render_state.clip_plane_enable =
              uint8_t(w1 == "enable" ? render_state.clip_plane_enable | (1u << i)
                                     : render_state.clip_plane_enable & ~(1u << i));
        } else if ((w1 == "enable" || w1 == "disable") &&
                   (w2 == "GL_PROGRAM_POINT_SIZE" || w2 == "GL_VERTEX_PROGRAM_POINT_SIZE")) {
          render_state.program_point_size = w1 == "enable";
        } else if (w1 == "link") {
          // link success / link error: handled above
        } else if (w1 == "frustum") {
          const auto n = numbers(c.substr(7));
          if (n.size() < 6) return skip("frustum form: " + c);
          prog->set_compat_matrices(glm::mat4(1.0f), glm::frustum(n[0], n[1], n[2], n[3], n[4], n[5]));
        } else if (w1 == "ortho") {
          // glOrtho(left, right, bottom, top, -1, 1) on the projection matrix, as shader_runner
          // does; without numbers (0, w, 0, h).
          const auto n = numbers(c.substr(5));
          const glm::vec4 box = n.size() >= 4 ? glm::vec4(n[0], n[1], n[2], n[3])
                                              : glm::vec4(0.0f, float(t.width), 0.0f, float(t.height));
          prog->set_compat_matrices(glm::mat4(1.0f), glm::ortho(box[0], box[1], box[2], box[3], -1.0f, 1.0f));
        } else {
          return skip("command: " + c);
        }
      } catch (const std::exception& e) {
        return fail(std::string("error: ") + e.what());
      }
    }
    return {};
  }
};

std::string version_of(const std::string& path) {
  const auto at = path.find("glsl-");
  if (at == std::string::npos) return "other";
  return path.substr(at, 9);
}

}  // namespace

int main(int argc, char** argv) {
  bool verbose = false, list_failures = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--verbose")
      verbose = true;
    else if (a == "--list-failures")
      list_failures = true;
    else if (fs::is_directory(a)) {
      for (const auto& e : fs::recursive_directory_iterator(a))
        if (e.path().extension() == ".shader_test") files.push_back(e.path().string());
    } else {
      files.push_back(a);
    }
  }
  std::sort(files.begin(), files.end());
  struct Count {
    int pass = 0, fail = 0, skip = 0;
  };
  std::map<std::string, Count> counts;
  std::map<std::string, int> skip_reasons;
  for (const std::string& f : files) {
    Runner r;
    r.t = parse(f);
    Result res;
    try {
      res = r.run();
    } catch (const std::exception& e) {
      res = {Outcome::Fail, std::string("exception: ") + e.what()};
    }
    Count& c = counts[version_of(f)];
    if (res.outcome == Outcome::Pass)
      ++c.pass;
    else if (res.outcome == Outcome::Fail)
      ++c.fail;
    else {
      ++c.skip;
      std::string key = res.why.substr(0, res.why.find_first_of("\n"));
      if (key.rfind("extension ", 0) == 0) key = "extension";
      if (key.rfind("command: ", 0) == 0) key = "command: " + key.substr(9, key.find(' ', 9) - 9);
      ++skip_reasons[key.substr(0, 60)];
    }
    if ((res.outcome == Outcome::Fail && list_failures) || verbose)
      std::printf("%s %s: %s\n",
                  res.outcome == Outcome::Pass   ? "PASS"
                  : res.outcome == Outcome::Fail ? "FAIL"
                                                 : "SKIP",
                  f.c_str(), res.why.substr(0, 300).c_str());
  }
  std::printf("\n%-10s %6s %6s %6s %8s\n", "version", "pass", "fail", "skip", "pass %");
  Count total;
  for (const auto& [v, c] : counts) {
    const int run = c.pass + c.fail;
    std::printf("%-10s %6d %6d %6d %7.1f%%\n", v.c_str(), c.pass, c.fail, c.skip,
                run ? 100.0 * c.pass / run : 0.0);
    total.pass += c.pass;
    total.fail += c.fail;
    total.skip += c.skip;
  }
  const int run = total.pass + total.fail;
  std::printf("%-10s %6d %6d %6d %7.1f%%\n", "all", total.pass, total.fail, total.skip,
              run ? 100.0 * total.pass / run : 0.0);
  std::printf("\nskipped, by reason:\n");
  std::vector<std::pair<int, std::string>> reasons;
  for (const auto& [k, n] : skip_reasons) reasons.push_back({n, k});
  std::sort(reasons.rbegin(), reasons.rend());
  for (size_t i = 0; i < reasons.size() && i < 25; ++i)
    std::printf("%6d  %s\n", reasons[i].first, reasons[i].second.c_str());
  std::printf("%d passed, %d failed\n", total.pass, total.fail);
  return 0;
}
