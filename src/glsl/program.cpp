// GLSL programs: compiling with glslang, linking (GL's location rules), uniform storage, and
// the pipeline's view of a program (gpu::RuntimeShader).
//
// A shader travels: source -> glslang (preprocess, parse, type-check, link both stages) ->
// glslang's AST -> lower.cpp (Tessel's IR, scalar components, functions inlined) -> the
// interpreter (interp.cpp), sixteen lanes at a time, called by the pipeline through
// gpu::RuntimeShader.
#include "tessel/glsl/program.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <list>
#include <mutex>
#include <optional>
#include <set>
#include <string_view>
#include <unordered_map>
#if defined(__SSE__) || defined(_M_X64)
#endif

#include "compile_queue.hpp"
#include "front.hpp"
#include "interp.hpp"
#include "jit.hpp"
#include "lower.hpp"

namespace tessel::glsl {
namespace {

struct Copy {
  ir::Reg reg;
  uint32_t offset;  // bytes into VertexLanes / FragmentLanes
};

}  // namespace

// --- What this process has compiled and linked ----------------------------------------------

namespace {

// Results kept by key, the least recently used dropped first beyond kProgramCacheEntries. The
// whole key is compared (its hash only picks the bucket), so two inputs never share a result.
// A key longer than kMaxKeyBytes (sources of megabytes) is not kept.
template <class V>
class Kept {
 public:
  static constexpr size_t kMaxKeyBytes = 256 * 1024;

  std::optional<V> find(const std::string& key) {
    std::lock_guard lock(m_);
    auto it = index_.find(key);
    if (it == index_.end()) {
      ++misses_;
      return std::nullopt;
    }
    order_.splice(order_.begin(), order_, it->second);
    ++hits_;
    return it->second->second;
  }
  void put(std::string key, V value) {
    if (key.size() > kMaxKeyBytes) return;
    std::lock_guard lock(m_);
    if (auto it = index_.find(key); it != index_.end()) {
      order_.erase(it->second);
      index_.erase(it);
    }
    order_.emplace_front(std::move(key), std::move(value));
    index_.emplace(order_.front().first, order_.begin());  // the view is of the list's own string
    while (order_.size() > kProgramCacheEntries) {
      index_.erase(order_.back().first);
      order_.pop_back();
    }
  }
  void clear() {
    std::lock_guard lock(m_);
    index_.clear();
    order_.clear();
    hits_ = misses_ = 0;
  }
  ProgramCacheStats stats() {
    std::lock_guard lock(m_);
    return {hits_, misses_, order_.size()};
  }

 private:
  std::mutex m_;
  std::list<std::pair<std::string, V>> order_;  // most recent first
  std::unordered_map<std::string_view, typename std::list<std::pair<std::string, V>>::iterator> index_;
  uint64_t hits_ = 0, misses_ = 0;
};

// Appends a length and the bytes: keys made of these never run two fields together.
void key_add(std::string& key, std::string_view s) {
  const uint64_t n = s.size();
  key.append(reinterpret_cast<const char*>(&n), sizeof n);
  key.append(s);
}
void key_add(std::string& key, int64_t v) { key.append(reinterpret_cast<const char*>(&v), sizeof v); }

struct CompiledShader {
  bool ok;
  std::string log;
};
Kept<CompiledShader>& compiled_shaders() {
  static Kept<CompiledShader> k;
  return k;
}

}  // namespace

// --- Shader ---------------------------------------------------------------------------------

std::shared_ptr<Shader> Shader::compile(Stage stage, std::string source) {
  auto s = std::make_shared<Shader>();
  s->stage_ = stage;
  s->source_ = std::move(source);
  const int index = stage == Stage::Vertex ? 0 : stage == Stage::Fragment ? 1 : 2;
  std::string key;
  key_add(key, index);
  key_add(key, s->source_);
  if (auto kept = compiled_shaders().find(key)) {
    s->ok_ = kept->ok;
    s->log_ = kept->log;
    return s;
  }
  s->ok_ = front_compile(index, s->source_, s->log_);
  compiled_shaders().put(std::move(key), {s->ok_, s->log_});
  return s;
}

// --- Program --------------------------------------------------------------------------------

struct Linked {
  ir::Stage vs, fs;
  std::vector<Copy> vs_in;                      // attribute rows, vertex and instance ids
  std::vector<Copy> vs_out;                     // position and varyings
  std::vector<Copy> fs_in;                      // varyings, coord, primitive id
  std::vector<ir::Reg> fs_front_facing;         // registers that get gl_FrontFacing
  std::vector<std::pair<ir::Reg, int>> fs_out;  // register, byte offset (colour or depth rows)
  std::vector<ir::Reg> frag_color;              // gl_FragColor's four registers (written to every output)
  gpu::RuntimeShape shape;
  // A geometry stage: its code, the copies into its registers from gpu::GeometryLanes, and
  // which of the components it emits (index into geometry.emit) go to which of the pipeline's
  // (the clip position, then the varyings).
  bool has_gs = false;
  ir::Stage gs;
  GeometryLayout geometry;
  std::vector<Copy> gs_in;
  std::vector<std::pair<uint32_t, uint32_t>> gs_out;
  StageIO vio, fio;    // what the native code's stages read and write
  JitEnvironment env;  // read when the program was linked

  // Native code, when LLVM compiled it: `jit` is written once, by the compile, before the
  // entry points are published; draws read the entry points on every call, so a draw that
  // started on the interpreter goes on in native code as soon as it is there.
  std::unique_ptr<JitCode> jit;
  std::atomic<StageFn> vs_fn{nullptr}, fs_fn{nullptr};
  std::atomic<PairFn> pair_fn{nullptr};
  std::mutex done_m;
  std::condition_variable done_cv;
  bool done = false;  // the compile has finished (or there is none), under done_m

  void finish(std::unique_ptr<JitCode> code) {
    if (code) {
      jit = std::move(code);
      vs_fn.store(jit->function(0), std::memory_order_release);
      pair_fn.store(jit->fragment_pair(), std::memory_order_release);
      fs_fn.store(jit->function(1), std::memory_order_release);
    }
    std::lock_guard lock(done_m);
    done = true;
    done_cv.notify_all();
  }
  void compile() {
    std::string why;
    finish(jit_compile(vs, vio, fs, fio, env, &why));
  }
};

struct Program::Impl {
  bool ok = false;
  std::string log;
  std::shared_ptr<Linked> linked;
  UniformLayout layout;
  std::vector<uint32_t> values;  // uniform words
  std::vector<Variable> attributes, uniforms, outputs;
  std::vector<UniformBlock> blocks;
  struct Location {
    size_t slot;
    int element;
  };
  std::vector<Location> locations;
  std::map<std::string, int, std::less<>> uniform_names;  // slot name (and name[0]) -> location
  std::optional<GeometryInfo> geometry;
  std::vector<FeedbackVarying> feedback;
  std::vector<std::vector<int>> feedback_words;
  bool feedback_separate = false;
  std::map<std::string, int, std::less<>> output_index;  // fragment output name -> index
  bool dual_source = false;
};

namespace {

Kept<std::shared_ptr<const Program::Impl>>& linked_programs() {
  static Kept<std::shared_ptr<const Program::Impl>> k;
  return k;
}

// When a program's native code is made: as the options ask, unless TESSEL_GLSL=interp (never)
// or TESSEL_GLSL=sync (at link) says otherwise.
NativeCode native_mode(const LinkOptions& options) {
  NativeCode when = options.native_code;
  if (const char* mode = std::getenv("TESSEL_GLSL")) {
    if (std::string_view(mode) == "interp") when = NativeCode::Off;
    if (std::string_view(mode) == "sync") when = NativeCode::AtLink;
  }
  return when;
}

// The program cache's key: every stage's sources in order and every binding that changes
// what linking gives. Native code made in the background or at link is the same code.
std::string program_key(const std::vector<std::string> (&sources)[3], const LinkOptions& o, NativeCode when) {
  std::string key;
  for (const auto& stage : sources) {
    key_add(key, int64_t(stage.size()));
    for (const std::string& src : stage) key_add(key, src);
  }
  for (const auto* bindings : {&o.attribute_locations, &o.frag_data_locations, &o.frag_data_indices}) {
    key_add(key, int64_t(bindings->size()));
    for (const auto& [name, value] : *bindings) {
      key_add(key, name);
      key_add(key, value);
    }
  }
  key_add(key, int64_t(o.feedback_varyings.size()));
  for (const std::string& v : o.feedback_varyings) key_add(key, v);
  key_add(key, int64_t(o.feedback_separate));
  key_add(key, int64_t(when == NativeCode::Off));
  return key;
}

}  // namespace

ProgramCacheStats program_cache_stats() { return linked_programs().stats(); }
void clear_program_cache() {
  linked_programs().clear();
  compiled_shaders().clear();
}

namespace {

// llvmpipe runs its shaders with the SSE control register's flush-to-zero and
// denormals-are-zero bits set (denormal results become zero of the same sign, denormal
// operands read as zero), and GLSL allows it. Both tiers run under the same bits, so their
// results agree with llvmpipe's and with each other through denormals. shape().flush_denormals
// asks for them: in a draw the pipeline sets them once around the program's work (its vertex
// batches and its raster loop, interpolation included, as llvmpipe's are one piece of
// generated code), and a direct caller of vertex()/fragment() sets them with
// gpu::ScopedDenormalFlush (reading the control register in every call cost 8% of a
// fill-bound frame). C++ shaders keep IEEE denormals.

class Bound final : public gpu::RuntimeShader {
 public:
  Bound(std::shared_ptr<const Linked> l, std::vector<uint32_t> u, std::vector<TextureUnit> t)
      : l_(std::move(l)), uniforms_(std::move(u)), units_(std::move(t)) {
    if (uniforms_.empty()) uniforms_.push_back(0);  // the code clamps word indices to the last word
    // What every call passes, worked out once: the calls come per sixteen lanes.
    vs_in_ = inputs(false);
    fs_in_ = inputs(true);
  }
  const gpu::RuntimeShape& shape() const override { return l_->shape; }

  void vertex(gpu::VertexLanes& lanes) const override {
    if (const StageFn fn = l_->vs_fn.load(std::memory_order_acquire)) {
      fn(&lanes, vs_in_.uniforms, vs_in_.uniform_words, &vs_in_, 0xFFFFu);
      return;
    }
    LaneReg* r = regs(l_->vs.registers);
    const auto* base = reinterpret_cast<const std::byte*>(&lanes);
    for (const Copy& c : l_->vs_in) std::memcpy(r + c.reg, base + c.offset, sizeof(LaneReg));
    run_stage(l_->vs, r, 0xFFFFu, inputs(false));
    auto* out = reinterpret_cast<std::byte*>(&lanes);
    for (const Copy& c : l_->vs_out) std::memcpy(out + c.offset, r + c.reg, sizeof(LaneReg));
  }

  void fragment(gpu::FragmentLanes& lanes) const override {
    if (const StageFn fn = l_->fs_fn.load(std::memory_order_acquire)) {
      lanes.killed = fn(&lanes, fs_in_.uniforms, fs_in_.uniform_words, &fs_in_, 0xFFFFu);
      return;
    }
    LaneReg* r = regs(l_->fs.registers);
    const auto* base = reinterpret_cast<const std::byte*>(&lanes);
    for (const Copy& c : l_->fs_in) std::memcpy(r + c.reg, base + c.offset, sizeof(LaneReg));
    for (ir::Reg f : l_->fs_front_facing)
      for (int l = 0; l < ir::kLanes; ++l) r[f].u[l] = ((lanes.front_facing >> l) & 1) ? ~0u : 0u;
    lanes.killed = run_stage(l_->fs, r, 0xFFFFu, inputs(true));
    auto* out = reinterpret_cast<std::byte*>(&lanes);
    for (const auto& [reg, off] : l_->fs_out) std::memcpy(out + off, r + reg, sizeof(LaneReg));
    if (!l_->frag_color.empty()) {
      for (int o = 0; o < l_->shape.outputs; ++o)
        for (int c = 0; c < 4; ++c)
          std::memcpy(lanes.color[o][c], r[l_->frag_color[size_t(c)]].u, sizeof(LaneReg));
    }
  }

  void geometry(gpu::GeometryLanes& g) const override {
    const Linked& l = *l_;
    if (!l.has_gs) return;
    LaneReg* r = regs(l.gs.registers);
    const auto* base = reinterpret_cast<const std::byte*>(&g);
    for (const Copy& c : l.gs_in) std::memcpy(r + c.reg, base + c.offset, sizeof(LaneReg));
    const uint32_t mask = g.count >= ir::kLanes ? 0xFFFFu : (1u << std::max(0, g.count)) - 1;
    RunInputs in = inputs(false);
    in.textures = l.gs.textures.data();
    run_stage(l.gs, r, mask, in);
    const GeometryLayout& gl = l.geometry;
    const uint32_t per = uint32_t(gl.emit.size());
    uint32_t most = 0;
    for (int lane = 0; lane < ir::kLanes; ++lane) {
      g.emitted[lane] =
          (mask >> lane) & 1 ? std::min<uint32_t>(r[gl.count].u[lane], uint32_t(gl.max_vertices)) : 0;
      most = std::max(most, g.emitted[lane]);
    }
    for (uint32_t v = 0; v < most; ++v) {
      for (const auto& [index, comp] : l.gs_out)
        std::memcpy(g.out + (size_t(v) * size_t(g.out_stride) + comp) * ir::kLanes,
                    r[gl.buffer + v * per + index].u, sizeof(LaneReg));
      for (int lane = 0; lane < ir::kLanes; ++lane)
        g.strip_start[v * ir::kLanes + uint32_t(lane)] = r[gl.starts + v].u[lane] == 0;
    }
  }

  void fragment_pair(gpu::FragmentLanes& a, gpu::FragmentLanes& b) const override {
    if (const PairFn fn = l_->pair_fn.load(std::memory_order_acquire)) {
      const uint32_t killed = fn(&a, &b, fs_in_.uniforms, fs_in_.uniform_words, &fs_in_);
      a.killed = killed & 0xFFFFu;
      b.killed = killed >> 16;
      return;
    }
    fragment(a);
    fragment(b);
  }

 private:
  std::shared_ptr<const Linked> l_;
  std::vector<uint32_t> uniforms_;
  std::vector<TextureUnit> units_;
  RunInputs vs_in_, fs_in_;

  RunInputs inputs(bool fragment) const {
    RunInputs in;
    in.textures = fragment ? l_->fs.textures.data() : l_->vs.textures.data();
    in.uniforms = uniforms_.data();
    in.uniform_words = uint32_t(uniforms_.size());
    in.units = units_.data();
    in.unit_count = int(units_.size());
    in.fragment = fragment;
    return in;
  }
  static LaneReg* regs(uint32_t n) {
    thread_local std::vector<LaneReg> file;
    if (file.size() < n) file.resize(n);
    return file.data();
  }
};

int locations_of(const Interface& f) {
  // An attribute takes a location per vector: per column of a matrix, per array element.
  const int per = f.gl_type >= 0x8B5A && f.gl_type <= 0x8B5C     ? (f.gl_type - 0x8B5A + 2)
                  : (f.gl_type >= 0x8B65 && f.gl_type <= 0x8B6A) ? (f.gl_type <= 0x8B66   ? 2
                                                                    : f.gl_type <= 0x8B68 ? 3
                                                                                          : 4)
                                                                 : 1;
  return per * std::max(1, f.array_size);
}

// The vertex output a fragment input reads (GL matches by name; the compatibility colours
// pair front colours with gl_Color).
std::string vertex_name_for(const std::string& fs_name) {
  if (fs_name == "gl_Color") return "gl_FrontColor";
  if (fs_name == "gl_SecondaryColor") return "gl_FrontSecondaryColor";
  return fs_name;
}

template <class T, class M>
uint32_t offset_of(M T::*member) {
  return uint32_t(reinterpret_cast<size_t>(&(reinterpret_cast<T*>(0)->*member)));
}

}  // namespace

Program::Program() : impl_(std::make_unique<Impl>()) {}
Program::~Program() = default;

int builtin_attribute_location(std::string_view name) {
  if (name == "gl_Vertex") return kLocationVertex;
  if (name == "gl_Normal") return kLocationNormal;
  if (name == "gl_Color") return kLocationColor;
  if (name == "gl_SecondaryColor") return kLocationSecondaryColor;
  if (name == "gl_FogCoord") return kLocationFogCoord;
  if (name.rfind("gl_MultiTexCoord", 0) == 0 && name.size() == 17)
    return kLocationMultiTexCoord0 + (name[16] - '0');
  return -1;
}

std::shared_ptr<Program> Program::link(const Shader& vertex, const Shader& fragment,
                                       const LinkOptions& options) {
  const Shader* both[2] = {&vertex, &fragment};
  return link(std::span<const Shader* const>(both), options);
}

std::shared_ptr<Program> Program::link(std::span<const Shader* const> shaders, const LinkOptions& options) {
  std::shared_ptr<Program> p(new Program());
  Impl& m = *p->impl_;
  std::vector<std::string> sources[3];
  for (const Shader* s : shaders) {
    if (!s) continue;
    if (!s->ok()) {
      m.log = "error: linking with uncompiled/shader that failed to compile\n";
      return p;
    }
    sources[s->stage() == Stage::Vertex ? 0 : s->stage() == Stage::Fragment ? 1 : 2].push_back(s->source());
  }
  if (sources[0].empty() && !sources[2].empty()) {
    m.log = "error: Geometry shader must be linked with vertex shader\n";  // Mesa's words
    return p;
  }
  if (sources[0].empty()) {
    m.log = "error: a program needs a vertex shader\n";
    return p;
  }
  // Without a fragment shader (a depth-only pass), fragments get no colour (GL 3.3 §3.9:
  // the colour values are undefined): a shader that writes none.
  if (sources[1].empty()) sources[1].push_back("#version 110\nvoid main() {}\n");
  // The same sources and bindings linked before: that link's result, with uniform values of
  // the program's own.
  const NativeCode when = native_mode(options);
  std::string key = program_key(sources, options, when);
  if (auto kept = linked_programs().find(key)) {
    *p->impl_ = **kept;
    if (when == NativeCode::AtLink) p->wait_native();
    return p;
  }
  auto linked = std::make_shared<Linked>();
  LoweredStage vs, fs, gs;
  const bool has_gs = !sources[2].empty();
  if (!front_link(sources[0], sources[1], sources[2], m.layout, vs, fs, gs, m.log)) return p;
  std::string errors, warnings;
  auto error = [&](const std::string& e) { errors += "error: " + e + "\n"; };

  // Attributes: layout(location), then the application's bindings, then the lowest free
  // locations in declaration order; the compatibility attributes have fixed ones.
  using gpu::FragmentLanes;
  using gpu::VertexLanes;
  uint32_t used = 0;
  std::vector<Interface*> unplaced;
  auto place_attr = [&](Interface& a, int loc) {
    const int n = locations_of(a);
    if (loc < 0 || loc + n > gpu::kMaxVertexAttribs) {
      error("attribute '" + a.name + "' has no room at location " + std::to_string(loc));
      a.location = -1;  // never addressed: the link fails
      return;
    }
    a.location = loc;
    for (int i = 0; i < n; ++i) used |= 1u << (loc + i);
  };
  for (Interface& a : vs.inputs) {
    if (a.block) continue;
    if (a.name == "gl_VertexID" || a.name == "gl_InstanceID") continue;
    if (a.builtin) {
      const int loc = builtin_attribute_location(a.name);
      if (loc < 0) {
        error("built-in input '" + a.name + "' is not supported");
        continue;
      }
      place_attr(a, loc);
      continue;
    }
    if (a.location >= 0) {
      place_attr(a, a.location);
      continue;
    }
    auto it = options.attribute_locations.find(a.name);
    if (it != options.attribute_locations.end())
      place_attr(a, it->second);
    else
      unplaced.push_back(&a);
  }
  for (Interface* a : unplaced) {
    const int n = locations_of(*a);
    int loc = 0;
    while (loc + n <= gpu::kMaxVertexAttribs && ((used >> loc) & ((1u << n) - 1))) ++loc;
    if (loc + n > gpu::kMaxVertexAttribs) {
      error("too many vertex attributes ('" + a->name + "')");
      continue;
    }
    place_attr(*a, loc);
  }
  for (const Interface& a : vs.inputs) {
    if (a.name == "gl_VertexID" || a.name == "gl_InstanceID") {
      linked->vs_in.push_back({a.reg, a.name == "gl_VertexID" ? offset_of(&VertexLanes::vertex_id)
                                                              : offset_of(&VertexLanes::instance_id)});
      continue;
    }
    if (a.location < 0) continue;
    // Components: a location's four per vector (column, element).
    const int vectors = locations_of(a);
    const int per = a.components / std::max(1, vectors);
    for (int v = 0; v < vectors; ++v) {
      for (int c = 0; c < per; ++c) {
        linked->vs_in.push_back(
            {a.reg + ir::Reg(v * per + c),
             offset_of(&VertexLanes::attr) + uint32_t(((a.location + v) * 4 + c) * ir::kLanes * 4)});
      }
      linked->shape.attributes |= 1u << (a.location + v);
    }
    if (!a.builtin) m.attributes.push_back({a.name, a.gl_type, std::max(1, a.array_size), a.location});
  }

  // With a geometry stage, the vertex stage's outputs are matched by name to its inputs (each
  // input array takes one vertex's components from consecutive slots of the vertex stage), and
  // its outputs are what the fragment stage's inputs are matched to.
  using gpu::GeometryLanes;
  if (has_gs) {
    linked->has_gs = true;
    int vslot = 0;
    for (const Interface& i : gs.inputs) {
      if (i.block) continue;
      if (i.name == "gl_PrimitiveIDIn") {
        linked->gs_in.push_back({i.reg, offset_of(&GeometryLanes::primitive_id)});
        continue;
      }
      if (i.vertices == 0) {
        error("geometry shader input '" + i.name + "' is not an array");
        continue;
      }
      if (i.name == "gl_Position") {
        for (int v = 0; v < i.vertices; ++v)
          for (int c = 0; c < 4; ++c)
            linked->gs_in.push_back(
                {i.reg + ir::Reg(v * i.vertex_stride + c),
                 offset_of(&GeometryLanes::position) + uint32_t((v * 4 + c) * ir::kLanes * 4)});
        continue;
      }
      const Interface* o = nullptr;
      for (const Interface& c : vs.outputs)
        if (c.name == i.name && !c.block) o = &c;
      if (!o) {
        // Read as zero; Mesa links such a program with a warning.
        if (!i.builtin)
          warnings += "warning: geometry shader varying " + i.name + " not written by vertex shader\n";
        for (int v = 0; v < i.vertices; ++v)
          gs.ir.variables.push_back({i.reg + ir::Reg(v * i.vertex_stride), uint32_t(i.components)});
        continue;
      }
      const int n = std::min(o->components, i.components);
      if (!i.builtin && (o->gl_type != i.gl_type || o->components != i.components)) {
        error("'" + i.name + "' has different types in the vertex and geometry shaders");
        continue;
      }
      if (vslot + n > gpu::kMaxVaryings) {
        error("too many vertex shader output components (at most " + std::to_string(gpu::kMaxVaryings) + ")");
        break;
      }
      for (int c = 0; c < n; ++c)
        linked->vs_out.push_back({o->reg + ir::Reg(c), offset_of(&VertexLanes::varyings) +
                                                           uint32_t((vslot + c) * ir::kLanes * 4)});
      for (int v = 0; v < i.vertices; ++v) {
        for (int c = 0; c < n; ++c)
          linked->gs_in.push_back({i.reg + ir::Reg(v * i.vertex_stride + c),
                                   offset_of(&GeometryLanes::varyings) +
                                       uint32_t((v * gpu::kMaxVaryings + vslot + c) * ir::kLanes * 4)});
        if (n < i.components)
          gs.ir.variables.push_back({i.reg + ir::Reg(v * i.vertex_stride + n), uint32_t(i.components - n)});
      }
      vslot += n;
    }
    linked->shape.vertex_varyings = vslot;
    const GeometryLayout& g = gs.geometry;
    linked->shape.geometry_input = g.input_vertices;
    linked->shape.geometry_output = g.output_primitive == 0x0000   ? gpu::Topology::Points
                                    : g.output_primitive == 0x0003 ? gpu::Topology::LineStrip
                                                                   : gpu::Topology::TriangleStrip;
    linked->shape.geometry_max_vertices = g.max_vertices;
  }
  // The stage that feeds the fragment stage, and where each of its output registers goes.
  const LoweredStage& producer = has_gs ? gs : vs;
  std::map<ir::Reg, uint32_t> emit_index;  // a geometry stage's output register -> its place in `emit`
  for (size_t e = 0; e < gs.geometry.emit.size(); ++e) emit_index[gs.geometry.emit[e]] = uint32_t(e);
  auto produce = [&](ir::Reg reg, uint32_t vertex_offset, uint32_t component) {
    if (has_gs) {
      auto it = emit_index.find(reg);
      if (it != emit_index.end()) linked->gs_out.push_back({it->second, component});
    } else {
      linked->vs_out.push_back({reg, vertex_offset});
    }
  };

  // Varyings: matched by name; each matched fragment input gets consecutive slots.
  int slot = 0;
  std::map<const Interface*, int> slot_of;  // where each of the producer's outputs is, when it has slots
  std::vector<const Interface*> pipeline_inputs;
  // Copies of n components between a stage's registers and varying components first.. of the
  // lane rows; a fragment input's components past n read zero.
  auto to_fragment = [&](const Interface& i, int first, int n) {
    for (int c = 0; c < n; ++c)
      linked->fs_in.push_back(
          {i.reg + ir::Reg(c), offset_of(&FragmentLanes::varyings) + uint32_t((first + c) * ir::kLanes * 4)});
    if (n < i.components) fs.ir.variables.push_back({i.reg + ir::Reg(n), uint32_t(i.components - n)});
  };
  auto from_vertex = [&](const Interface& o, int first, int n) {
    for (int c = 0; c < n; ++c)
      produce(o.reg + ir::Reg(c), offset_of(&VertexLanes::varyings) + uint32_t((first + c) * ir::kLanes * 4),
              uint32_t(4 + first + c));
  };
  for (const Interface& o : vs.outputs) {
    if (o.name == "gl_Position") {
      for (int c = 0; c < 4; ++c)
        linked->vs_out.push_back(
            {o.reg + ir::Reg(c), offset_of(&VertexLanes::position) + uint32_t(c * ir::kLanes * 4)});
    }
  }
  if (has_gs)
    for (const Interface& o : gs.outputs)
      if (o.name == "gl_Position")
        for (int c = 0; c < 4; ++c) produce(o.reg + ir::Reg(c), 0, uint32_t(c));
  for (const Interface& i : fs.inputs) {
    if (i.block) continue;
    if (i.name == "gl_FragCoord") {
      for (int c = 0; c < 4; ++c)
        linked->fs_in.push_back(
            {i.reg + ir::Reg(c), offset_of(&FragmentLanes::coord) + uint32_t(c * ir::kLanes * 4)});
      continue;
    }
    if (i.name == "gl_FrontFacing") {
      linked->fs_front_facing.push_back(i.reg);
      continue;
    }
    if (i.name == "gl_PrimitiveID") {
      linked->fs_in.push_back({i.reg, offset_of(&FragmentLanes::primitive_id)});
      continue;
    }
    if (i.name == "gl_PointCoord" || i.name == "gl_ClipDistance") {
      pipeline_inputs.push_back(&i);  // given components of their own below
      continue;
    }
    const std::string vname = vertex_name_for(i.name);
    const Interface* o = nullptr;
    for (const Interface& c : producer.outputs)
      if (c.name == vname) o = &c;
    if (!o) {
      // A varying the vertex shader declares but never writes, or a compatibility input it
      // does not write, reads as zero; one it does not declare is an error (as in Mesa).
      if (!i.builtin && !producer.declared_outputs.count(vname))
        error("fragment shader input '" + i.name + "' is not written by the " +
              (has_gs ? "geometry" : "vertex") + " shader");
      fs.ir.variables.push_back({i.reg, uint32_t(i.components)});
      continue;
    }
    int n = i.components;
    if (o->gl_type != i.gl_type || o->components != i.components) {
      // gl_TexCoord is sized in each shader by the elements it uses (GLSL 1.10 §7.6, as Mesa
      // links it): the elements both have pass, the fragment shader's others read zero.
      if (!(i.builtin && i.name == "gl_TexCoord" && o->gl_type == i.gl_type)) {
        error("'" + i.name + "' has different types in the " + (has_gs ? "geometry" : "vertex") +
              " and fragment shaders");
        continue;
      }
      n = std::min(o->components, i.components);  // to_fragment zeroes the rest
    }
    if (i.base != Base::Float && !i.flat) {
      error("integer fragment input '" + i.name + "' must be qualified flat");
      continue;
    }
    if (slot + n > gpu::kMaxVaryings) {
      error("too many varying components (at most " + std::to_string(gpu::kMaxVaryings) + ")");
      break;
    }
    from_vertex(*o, slot, n);
    slot_of[o] = slot;
    to_fragment(i, slot, n);
    const uint64_t bits = (n >= 64 ? ~uint64_t(0) : (uint64_t(1) << n) - 1) << slot;
    if (i.flat || i.base != Base::Float) linked->shape.flat |= bits;
    if (i.noperspective) linked->shape.noperspective |= bits;
    slot += n;
  }
  // GLSL 1.30 §4.3.7: when gl_Color is redeclared with an interpolation qualifier, the
  // gl_FrontColor and gl_BackColor the program uses must be redeclared with the same one, and
  // the other way round; likewise the secondary colours. Only variables the shaders use count.
  // GL counts "no qualifier" as a value of its own, unlike smooth said; glslang gives both
  // the same qualifier, so here they are one (piglit's 16 tests of that pairing fail).
  for (const auto& group : {std::array<const char*, 3>{"gl_FrontColor", "gl_BackColor", "gl_Color"},
                            {"gl_FrontSecondaryColor", "gl_BackSecondaryColor", "gl_SecondaryColor"}}) {
    const Interface* first = nullptr;
    auto qualifier = [](const Interface& i) {
      return i.flat ? "flat" : i.noperspective ? "noperspective" : "smooth";
    };
    for (int k = 0; k < 3; ++k)
      for (const Interface& i : k < 2 ? producer.outputs : fs.inputs) {
        if (i.name != group[size_t(k)]) continue;
        if (!first) {
          first = &i;
        } else if (std::string_view(qualifier(i)) != qualifier(*first)) {
          error(i.name + " has " + qualifier(i) + " but " + first->name + " has " + qualifier(*first) +
                ": their interpolation qualifiers must match (GLSL 1.30 section 4.3.7)");
        }
      }
  }
  // Then the components the pipeline reads (gl_PointSize, gl_ClipDistance: only when the
  // stage writes them, as a gl_PerVertex block lists them all) or sets (gl_PointCoord):
  // point coordinates are interpolated linearly in the window.
  auto take = [&](int n) {
    if (slot + n > gpu::kMaxVaryings) {
      error("too many varying components (at most " + std::to_string(gpu::kMaxVaryings) + ")");
      return -1;
    }
    slot += n;
    return slot - n;
  };
  for (const Interface& o : producer.outputs) {
    if (o.block || !o.builtin) continue;
    if ((o.name == "gl_PrimitiveID" || o.name == "gl_Layer") && has_gs) {
      // The geometry stage's gl_PrimitiveID (the pipeline gives it to the fragment stage) and
      // gl_Layer (it picks the layer of a layered framebuffer).
      const int at = take(1);
      if (at < 0) break;
      from_vertex(o, at, 1);
      slot_of[&o] = at;
      (o.name == "gl_Layer" ? linked->shape.layer : linked->shape.primitive_id) = at;
      linked->shape.flat |= uint64_t(1) << at;
    } else if (o.name == "gl_PointSize" && o.written) {
      const int at = take(1);
      if (at < 0) break;
      from_vertex(o, at, 1);
      slot_of[&o] = at;
      linked->shape.point_size = at;
      linked->shape.flat |= uint64_t(1) << at;
    } else if (o.name == "gl_ClipDistance" && o.components > 0 && o.written) {
      const int n = std::min(o.components, gpu::kMaxClipPlanes);
      const int at = take(n);
      if (at < 0) break;
      from_vertex(o, at, n);
      if (n == o.components) slot_of[&o] = at;
      linked->shape.clip_distance = at;
      linked->shape.clip_distances = n;
    }
  }
  for (const Interface* i : pipeline_inputs) {
    if (i->name == "gl_PointCoord") {
      const int at = take(2);
      if (at < 0) break;
      to_fragment(*i, at, 2);
      linked->shape.point_coord = at;
      linked->shape.noperspective |= uint64_t(3) << at;
    } else {  // gl_ClipDistance: the vertex shader's, interpolated; those it does not write read 0
      const int n = std::min(i->components, linked->shape.clip_distances);
      to_fragment(*i, linked->shape.clip_distance, n);
    }
  }
  // Transform feedback (GL 3.3 §2.11.8): each captured output of the producer keeps the
  // slots it has, or gets its own, and each buffer's words name them.
  if (!options.feedback_varyings.empty()) {
    const bool separate = options.feedback_separate;
    std::set<std::string> seen;
    int total = 0;
    m.feedback_words.assign(separate ? options.feedback_varyings.size() : 1, {});
    for (size_t v = 0; v < options.feedback_varyings.size(); ++v) {
      const std::string& full = options.feedback_varyings[v];
      std::vector<int>& words = m.feedback_words[separate ? v : 0];
      if (!seen.insert(full).second) {
        error("Transform feedback varying " + full + " specified more than once.");
        continue;
      }
      // "name" or "name[index]".
      std::string name = full;
      int index = -1;
      if (const size_t open = full.find('['); open != std::string::npos) {
        const std::string digits = full.substr(open + 1, full.size() - open - 2);
        if (full.back() != ']' || digits.empty() || digits.size() > 6 ||
            digits.find_first_not_of("0123456789") != std::string::npos) {
          error("Transform feedback varying " + full + " undeclared.");
          continue;
        }
        name = full.substr(0, open);
        index = std::stoi(digits);
      }
      const Interface* o = nullptr;
      for (const Interface& c : producer.outputs)
        if (c.name == name && !c.block) o = &c;
      if (name == "gl_Position" && o) {
        if (index >= 0) {
          error("Transform feedback varying " + full + " undeclared.");
          continue;
        }
        for (int c = 0; c < 4; ++c) words.push_back(gpu::kCapturePosition - c);
        m.feedback.push_back({full, 0x8B52 /* GL_FLOAT_VEC4 */, 1});
        total += 4;
        continue;
      }
      if (!o) {
        error("Transform feedback varying " + full + " undeclared.");
        continue;
      }
      if (index >= 0 && o->array_size == 0) {
        error("Transform feedback varying " + full + " undeclared.");
        continue;
      }
      if (index >= 0 && index >= o->array_size) {
        error("Transform feedback varying " + full + " has index " + std::to_string(index) +
              ", but the array size is " + std::to_string(o->array_size) + ".");
        continue;
      }
      auto at = slot_of.find(o);
      if (at == slot_of.end()) {
        const int first = take(o->components);
        if (first < 0) break;
        from_vertex(*o, first, o->components);
        if (o->base != Base::Float)
          linked->shape.flat |= (o->components >= 64 ? ~uint64_t(0) : (uint64_t(1) << o->components) - 1)
                                << first;
        at = slot_of.emplace(o, first).first;
      }
      const int per = o->array_size ? o->components / o->array_size : o->components;
      const int from = index >= 0 ? at->second + index * per : at->second;
      const int n = index >= 0 ? per : o->components;
      for (int c = 0; c < n; ++c) words.push_back(from + c);
      m.feedback.push_back({full, o->gl_type, index >= 0 ? 1 : std::max(1, o->array_size)});
      total += n;
      if (separate && n > kMaxFeedbackSeparateComponents)
        error("Transform feedback varying " + full + " exceeds the maximum of " +
              std::to_string(kMaxFeedbackSeparateComponents) + " components in separate mode.");
    }
    if (!separate && total > kMaxFeedbackInterleavedComponents)
      error("Too many feedback components in interleaved mode: " + std::to_string(total) +
            ", the maximum is " + std::to_string(kMaxFeedbackInterleavedComponents) + ".");
    m.feedback_separate = separate;
  }
  linked->shape.varyings = slot;

  // Fragment outputs: layout(location), then the application's bindings, then 0 for a single
  // output; gl_FragColor goes to every output, gl_FragData[i] to output i.
  int outputs = 0;
  std::vector<Interface*> free_outputs;
  bool frag_color = false, frag_data = false;
  for (Interface& o : fs.outputs) {
    if (o.block) continue;
    if (o.name == "gl_FragDepth") {
      linked->fs_out.push_back({o.reg, int(offset_of(&FragmentLanes::depth))});
      continue;
    }
    if (o.name == "gl_FragColor") {
      frag_color = true;
      for (int c = 0; c < 4; ++c) linked->frag_color.push_back(o.reg + ir::Reg(c));
      outputs = std::max(outputs, 1);
      continue;
    }
    if (o.name == "gl_FragData") {
      frag_data = true;
      const int n = std::min(o.array_size, gpu::kMaxColorAttachments);
      for (int e = 0; e < n; ++e)
        for (int c = 0; c < 4; ++c)
          linked->fs_out.push_back({o.reg + ir::Reg(e * 4 + c),
                                    int(offset_of(&FragmentLanes::color)) + (e * 4 + c) * ir::kLanes * 4});
      outputs = std::max(outputs, n);
      continue;
    }
    if (o.builtin) continue;
    if (o.location < 0) {
      auto it = options.frag_data_locations.find(o.name);
      if (it != options.frag_data_locations.end()) {
        o.location = it->second;
        auto ix = options.frag_data_indices.find(o.name);
        if (o.index < 0 && ix != options.frag_data_indices.end()) o.index = ix->second;
      }
    }
    if (o.index < 0) o.index = 0;
    if (o.location < 0) free_outputs.push_back(&o);
  }
  if (frag_color && frag_data) error("a fragment shader may not write both gl_FragColor and gl_FragData");
  for (Interface* o : free_outputs) {
    int loc = 0;
    for (;; ++loc) {
      bool taken = false;
      for (const Interface& q : fs.outputs)
        if (&q != o && q.location >= 0 && q.index == o->index && loc >= q.location &&
            loc < q.location + std::max(1, q.array_size))
          taken = true;
      if (!taken) break;
    }
    o->location = loc;
  }
  // Dual-source blending (GL 3.3 §3.9.2): an output of index 1 is the second colour of
  // location 0 (GL_MAX_DUAL_SOURCE_DRAW_BUFFERS is 1), carried as fragment colour 1; the
  // other outputs must then stay below that maximum too.
  bool dual = false;
  for (const Interface& o : fs.outputs)
    if (!o.builtin && o.index == 1) dual = true;
  for (const Interface& o : fs.outputs) {
    if (o.builtin) continue;
    const int n = std::max(1, o.array_size);
    if (o.index > 1 || (dual && o.location + n > 1)) {
      error("fragment output '" + o.name + "' at location " + std::to_string(o.location) + ", index " +
            std::to_string(o.index) + ": dual-source blending has one draw buffer");
      continue;
    }
    if (o.location < 0 || o.location + n > gpu::kMaxColorAttachments) {
      error("fragment output '" + o.name + "' has no room at location " + std::to_string(o.location));
      continue;
    }
    const int per = o.components / n;
    const int slot = o.index == 1 ? 1 : o.location;
    for (int e = 0; e < n; ++e)
      for (int c = 0; c < per; ++c)
        linked->fs_out.push_back({o.reg + ir::Reg(e * per + c), int(offset_of(&FragmentLanes::color)) +
                                                                    ((slot + e) * 4 + c) * ir::kLanes * 4});
    outputs = std::max(outputs, slot + n);
    m.output_index[o.name] = o.index;
    m.outputs.push_back({o.name, o.gl_type, std::max(1, o.array_size), o.location});
  }
  if (frag_color) outputs = gpu::kMaxColorAttachments;  // gl_FragColor is written to every draw buffer
  linked->shape.outputs = outputs;
  m.dual_source = dual;
  linked->shape.discards = fs.ir.discards;
  linked->shape.writes_depth = fs.ir.writes_depth;
  linked->shape.lanes_independent = !fs.ir.uses_derivatives;
  linked->shape.flush_denormals = true;
  if (!errors.empty()) {
    m.log = errors;
    return p;
  }

  // Uniform locations: each element of each slot, in order.
  for (size_t s = 0; s < m.layout.slots.size(); ++s) {
    const UniformSlot& u = m.layout.slots[s];
    const int base = int(m.locations.size());
    for (int e = 0; e < u.array_size; ++e) m.locations.push_back({s, e});
    m.uniform_names[u.name] = base;
    if (u.array_size > 1 || u.name.back() == ']') m.uniform_names[u.name + "[0]"] = base;
    if (!u.builtin && u.active)
      m.uniforms.push_back({u.array_size > 1 ? u.name + "[0]" : u.name, u.gl_type, u.array_size, base});
  }
  m.values.assign(m.layout.words, 0);
  for (const UniformBlockLayout& b : m.layout.blocks) {
    UniformBlock ub;
    ub.name = b.name;
    ub.size = int(b.bytes);
    for (const BlockMember& bm : b.members)
      ub.members.push_back({bm.name, bm.gl_type, bm.array_size, int(bm.offset), int(bm.array_stride),
                            int(bm.matrix_stride), bm.row_major});
    m.blocks.push_back(std::move(ub));
  }
  linked->vs = std::move(vs.ir);
  linked->fs = std::move(fs.ir);
  if (has_gs) {
    linked->gs = std::move(gs.ir);
    linked->geometry = std::move(gs.geometry);
    m.geometry = {linked->geometry.max_vertices, linked->geometry.input_vertices,
                  linked->geometry.input_primitive, linked->geometry.output_primitive,
                  linked->shape.layer >= 0};
  }
  // Native code for both stages, unless the options or TESSEL_GLSL=interp ask for the
  // interpreter. A program LLVM cannot compile still runs, on the interpreter (same results).
  if (when != NativeCode::Off) {
    linked->env = jit_environment();
    StageIO& vio = linked->vio;
    StageIO& fio = linked->fio;

    for (const Copy& c : linked->vs_in) vio.in.push_back({c.reg, c.offset});
    for (const Copy& c : linked->vs_out) vio.out.push_back({c.reg, c.offset});
    for (const Copy& c : linked->fs_in) fio.in.push_back({c.reg, c.offset});
    for (ir::Reg f : linked->fs_front_facing)
      fio.in_mask.push_back({f, offset_of(&FragmentLanes::front_facing)});
    for (const auto& [reg, off] : linked->fs_out) fio.out.push_back({reg, uint32_t(off)});
    if (!linked->frag_color.empty())
      for (int o = 0; o < linked->shape.outputs; ++o)
        for (int c = 0; c < 4; ++c)
          fio.out.push_back({linked->frag_color[size_t(c)],
                             offset_of(&FragmentLanes::color) + uint32_t((o * 4 + c) * ir::kLanes * 4)});
  }
  if (when == NativeCode::Off) {
    linked->finish(nullptr);
  } else if (when == NativeCode::AtLink) {
    linked->compile();
  } else {
    // The compile job holds the program weakly: a program deleted before its turn is not
    // compiled.
    std::weak_ptr<Linked> weak = linked;
    CompileQueue::instance().submit(linked.get(), [weak](bool run) {
      if (auto l = weak.lock()) {
        if (run)
          l->compile();
        else
          l->finish(nullptr);
      }
    });
  }
  m.linked = std::move(linked);
  m.ok = true;
  m.log = warnings;
  p->set_compat_defaults();
  // Uniform initializers (GLSL 1.20 §4.3.5) give the initial values.
  for (const auto& [name, words] : m.layout.initial) {
    auto it = m.layout.by_name.find(name);
    if (it == m.layout.by_name.end()) continue;
    const uint32_t base = m.layout.slots[it->second].word;
    for (size_t i = 0; i < words.size() && base + i < m.values.size(); ++i) m.values[base + i] = words[i];
  }
  linked_programs().put(std::move(key), std::make_shared<const Impl>(m));
  return p;
}

namespace {
// Writes `n` floats into the compatibility uniform `name` (a whole slot or one element) if the
// program uses it.
void put_builtin(Program& p, const std::string& name, const float* v, int n) {
  const int loc = p.uniform_location(name);
  if (loc >= 0) p.set_uniform(loc, v, n);
}
}  // namespace

void Program::set_compat_defaults() {
  const glm::mat4 id(1.0f);
  set_compat_matrices(id, id);
  for (int i = 0; i < 8; ++i)
    put_builtin(*this, "gl_TextureMatrix[" + std::to_string(i) + "]", &id[0][0], 16);
  // GL 2.1 §2.14.1 Table 2.10 and §6.2: the initial lighting state.
  const float black[4] = {0, 0, 0, 1}, white[4] = {1, 1, 1, 1}, ambient[4] = {0.2f, 0.2f, 0.2f, 1};
  const float diffuse[4] = {0.8f, 0.8f, 0.8f, 1}, zero4[4] = {0, 0, 0, 0};
  const float pos[4] = {0, 0, 1, 0}, dir[3] = {0, 0, -1}, one = 1, cutoff = 180, coscut = -1, zero = 0;
  for (int i = 0; i < 8; ++i) {
    const std::string l = "gl_LightSource[" + std::to_string(i) + "].";
    put_builtin(*this, l + "ambient", black, 4);
    put_builtin(*this, l + "diffuse", i == 0 ? white : zero4, 4);
    put_builtin(*this, l + "specular", i == 0 ? white : zero4, 4);
    put_builtin(*this, l + "position", pos, 4);
    put_builtin(*this, l + "halfVector", pos, 4);
    put_builtin(*this, l + "spotDirection", dir, 3);
    put_builtin(*this, l + "spotExponent", &zero, 1);
    put_builtin(*this, l + "spotCutoff", &cutoff, 1);
    put_builtin(*this, l + "spotCosCutoff", &coscut, 1);
    put_builtin(*this, l + "constantAttenuation", &one, 1);
    put_builtin(*this, l + "linearAttenuation", &zero, 1);
    put_builtin(*this, l + "quadraticAttenuation", &zero, 1);
  }
  for (const char* side : {"gl_FrontMaterial.", "gl_BackMaterial."}) {
    const std::string s = side;
    put_builtin(*this, s + "emission", black, 4);
    put_builtin(*this, s + "ambient", ambient, 4);
    put_builtin(*this, s + "diffuse", diffuse, 4);
    put_builtin(*this, s + "specular", black, 4);
    put_builtin(*this, s + "shininess", &zero, 1);
  }
  put_builtin(*this, "gl_LightModel.ambient", ambient, 4);
  const float range[3] = {0, 1, 1};
  put_builtin(*this, "gl_DepthRange.near", &range[0], 1);
  put_builtin(*this, "gl_DepthRange.far", &range[1], 1);
  put_builtin(*this, "gl_DepthRange.diff", &range[2], 1);
  put_builtin(*this, "gl_Point.size", &one, 1);
  put_builtin(*this, "gl_Point.sizeMin", &zero, 1);
  const float big = 1e30f;
  put_builtin(*this, "gl_Point.sizeMax", &big, 1);
  put_builtin(*this, "gl_Fog.density", &one, 1);
  put_builtin(*this, "gl_Fog.start", &zero, 1);
  put_builtin(*this, "gl_Fog.end", &one, 1);
  put_builtin(*this, "gl_Fog.scale", &one, 1);
  put_builtin(*this, "gl_Fog.color", zero4, 4);
}

void Program::set_compat_matrices(const glm::mat4& mv, const glm::mat4& proj) {
  const glm::mat4 mvp = proj * mv;
  auto put = [&](const char* name, const glm::mat4& x) { put_builtin(*this, name, &x[0][0], 16); };
  put("gl_ModelViewMatrix", mv);
  put("gl_ProjectionMatrix", proj);
  put("gl_ModelViewProjectionMatrix", mvp);
  put("gl_ModelViewMatrixInverse", glm::inverse(mv));
  put("gl_ProjectionMatrixInverse", glm::inverse(proj));
  put("gl_ModelViewProjectionMatrixInverse", glm::inverse(mvp));
  put("gl_ModelViewMatrixTranspose", glm::transpose(mv));
  put("gl_ProjectionMatrixTranspose", glm::transpose(proj));
  put("gl_ModelViewProjectionMatrixTranspose", glm::transpose(mvp));
  put("gl_ModelViewMatrixInverseTranspose", glm::transpose(glm::inverse(mv)));
  put("gl_ProjectionMatrixInverseTranspose", glm::transpose(glm::inverse(proj)));
  put("gl_ModelViewProjectionMatrixInverseTranspose", glm::transpose(glm::inverse(mvp)));
  // GL 2.1 §2.11.3: the normal matrix is the inverse transpose of the upper-left 3x3.
  const glm::mat3 n = glm::transpose(glm::inverse(glm::mat3(mv)));
  put_builtin(*this, "gl_NormalMatrix", &n[0][0], 9);
}

bool Program::ok() const { return impl_->ok; }
void hold_background_compiles(bool hold) { CompileQueue::instance().pause(hold); }

bool Program::native() const {
  return impl_->ok && impl_->linked->fs_fn.load(std::memory_order_acquire) != nullptr;
}
bool Program::from_cache() const { return native() && impl_->linked->jit->from_cache; }
bool Program::wait_native() const {
  if (!impl_->ok) return false;
  Linked& l = *impl_->linked;
  CompileQueue::instance().promote(&l);
  std::unique_lock lock(l.done_m);
  l.done_cv.wait(lock, [&] { return l.done; });
  return native();
}
const std::string& Program::info_log() const { return impl_->log; }
const std::vector<Variable>& Program::attributes() const { return impl_->attributes; }
const GeometryInfo* Program::geometry() const { return impl_->geometry ? &*impl_->geometry : nullptr; }
const std::vector<FeedbackVarying>& Program::feedback_varyings() const { return impl_->feedback; }
bool Program::feedback_separate() const { return impl_->feedback_separate; }
const std::vector<std::vector<int>>& Program::feedback_words() const { return impl_->feedback_words; }
bool Program::dual_source() const { return impl_->dual_source; }
int Program::frag_data_index(std::string_view name) const {
  auto it = impl_->output_index.find(name);
  return it == impl_->output_index.end() ? -1 : it->second;
}
const std::vector<Variable>& Program::uniforms() const { return impl_->uniforms; }
const std::vector<Variable>& Program::outputs() const { return impl_->outputs; }

int Program::attribute_location(std::string_view name) const {
  for (const Variable& v : impl_->attributes)
    if (v.name == name) return v.location;
  return -1;
}

int Program::frag_data_location(std::string_view name) const {
  for (const Variable& v : impl_->outputs)
    if (v.name == name) return v.location;
  return -1;
}

int Program::uniform_location(std::string_view name) const {
  const Impl& m = *impl_;
  if (!m.ok) return -1;
  auto it = m.uniform_names.find(name);
  if (it != m.uniform_names.end())
    return m.layout.slots[m.locations[size_t(it->second)].slot].active ? it->second : -1;
  // "name[i]": element i of an array slot.
  if (!name.empty() && name.back() == ']') {
    const size_t open = name.rfind('[');
    if (open == std::string_view::npos) return -1;
    const std::string_view idx = name.substr(open + 1, name.size() - open - 2);
    if (idx.empty() || idx.size() > 9 || idx.find_first_not_of("0123456789") != std::string_view::npos)
      return -1;
    const int i = std::stoi(std::string(idx));
    auto b = m.uniform_names.find(name.substr(0, open));
    if (b == m.uniform_names.end()) return -1;
    const UniformSlot& s = m.layout.slots[m.locations[size_t(b->second)].slot];
    if (!s.active || i >= s.array_size) return -1;
    return b->second + i;
  }
  return -1;
}

namespace {
template <class T>
bool store_uniform(Program::Impl& m, int location, const T* data, int components, int count, Base given) {
  if (location == -1) return true;
  if (!m.ok || location < 0 || size_t(location) >= m.locations.size() || count < 0 || !data) return false;
  const auto [slot, element] = m.locations[size_t(location)];
  const UniformSlot& u = m.layout.slots[slot];
  if (components != u.components) return false;
  if (u.sampler) {
    if (given != Base::Int) return false;
  } else if (u.base != Base::Bool && u.base != given) {
    return false;
  }
  if (count > 1 && u.array_size == 1) return false;
  const int n = std::min(count, u.array_size - element);
  for (int e = 0; e < n; ++e) {
    for (int c = 0; c < components; ++c) {
      const T v = data[size_t(e * components + c)];
      uint32_t w;
      if (u.base == Base::Bool)
        w = v != T(0) ? ~0u : 0u;
      else
        std::memcpy(&w, &v, 4);
      m.values[u.word + uint32_t((element + e) * components + c)] = w;
    }
  }
  return true;
}
}  // namespace

bool Program::set_uniform(int location, const float* data, int components, int count) {
  return store_uniform(*impl_, location, data, components, count, Base::Float);
}
bool Program::set_uniform(int location, const int32_t* data, int components, int count) {
  return store_uniform(*impl_, location, data, components, count, Base::Int);
}
bool Program::set_uniform(int location, const uint32_t* data, int components, int count) {
  return store_uniform(*impl_, location, data, components, count, Base::Uint);
}

bool Program::get_uniform_words(int location, uint32_t* out) const {
  const Impl& m = *impl_;
  if (!m.ok || location < 0 || size_t(location) >= m.locations.size()) return false;
  const auto [slot, element] = m.locations[size_t(location)];
  const UniformSlot& u = m.layout.slots[slot];
  for (int c = 0; c < u.components; ++c) out[c] = m.values[u.word + uint32_t(element * u.components + c)];
  return true;
}

bool Program::get_uniform(int location, float* out) const {
  const Impl& m = *impl_;
  uint32_t w[16];
  if (!get_uniform_words(location, w)) return false;
  const UniformSlot& u = m.layout.slots[m.locations[size_t(location)].slot];
  for (int c = 0; c < u.components; ++c) {
    switch (u.base) {
      case Base::Float: std::memcpy(&out[c], &w[c], 4); break;
      case Base::Int: out[c] = float(int32_t(w[c])); break;
      case Base::Uint: out[c] = float(w[c]); break;
      case Base::Bool: out[c] = w[c] ? 1.0f : 0.0f; break;
    }
  }
  return true;
}

const std::vector<UniformBlock>& Program::uniform_blocks() const { return impl_->blocks; }

int Program::uniform_block_index(std::string_view name) const {
  for (size_t i = 0; i < impl_->blocks.size(); ++i)
    if (impl_->blocks[i].name == name) return int(i);
  return -1;
}

bool Program::set_uniform_block_binding(int index, int binding) {
  if (index < 0 || size_t(index) >= impl_->blocks.size() || binding < 0 || binding >= 36) return false;
  impl_->blocks[size_t(index)].binding = binding;
  return true;
}

std::shared_ptr<const gpu::RuntimeShader> Program::bind(
    std::span<const TextureBinding> units, std::span<const BufferBinding> uniform_buffers) const {
  const Impl& m = *impl_;
  if (!m.ok) throw gpu::Error("draw: the program is not linked: " + m.log);
  // A program that draws compiles before those that do not yet.
  if (!native()) CompileQueue::instance().promote(m.linked.get());
  std::vector<TextureUnit> u;
  u.reserve(units.size());
  for (const TextureBinding& b : units)
    u.push_back({b.texture_2d, b.texture_cube, b.sampler, b.texture_3d, b.texture_2d_array, b.texture_buffer,
                 b.swizzle});
  std::vector<uint32_t> values = m.values;
  for (size_t i = 0; i < m.blocks.size(); ++i) {
    const UniformBlockLayout& bl = m.layout.blocks[i];
    uint32_t* dst = values.data() + bl.word;
    std::memset(dst, 0, bl.bytes);
    const size_t point = size_t(m.blocks[i].binding);
    if (point >= uniform_buffers.size() || !uniform_buffers[point].buffer) continue;
    const BufferBinding& bb = uniform_buffers[point];
    const size_t total = bb.buffer->size();
    if (bb.offset >= total) continue;
    const size_t avail = bb.size ? std::min(bb.size, total - bb.offset) : total - bb.offset;
    std::memcpy(dst, bb.buffer->data() + bb.offset, std::min<size_t>(avail, bl.bytes));
  }
  return std::make_shared<Bound>(m.linked, std::move(values), std::move(u));
}

void Program::draw(gpu::Context& ctx, const gpu::VertexLayout& layout, const gpu::RenderState& state,
                   const gpu::DrawCall& call, std::span<const TextureBinding> units,
                   std::span<const BufferBinding> uniform_buffers) const {
  ctx.draw(bind(units, uniform_buffers), layout, state, call);
}

}  // namespace tessel::glsl
