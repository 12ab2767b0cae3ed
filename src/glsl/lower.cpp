// GLSL (glslang's linked AST) to Tessel's IR: every value is split into its scalar
// components, functions are inlined, control flow stays structured (ir.hpp).
//
// Places: a variable is a run of consecutive registers; a uniform is a run of words in the
// program's uniform layout. An access chain (a[i].b.xy) becomes a place: the variable, the
// offsets of the components it names and, for a dynamic index, a register with a clamped
// offset added to them at run time, so that an index out of range reads or writes an
// element of the same array and never anything else.
#include "lower.hpp"

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include <bit>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <unordered_map>

#include "gl_types.hpp"

namespace tessel::glsl {
namespace {

using glslang::TIntermAggregate;
using glslang::TIntermBinary;
using glslang::TIntermBranch;
using glslang::TIntermConstantUnion;
using glslang::TIntermLoop;

using glslang::TIntermSelection;
using glslang::TIntermSequence;
using glslang::TIntermSwitch;
using glslang::TIntermSymbol;
using glslang::TIntermTyped;
using glslang::TIntermUnary;
using glslang::TType;
using ir::Inst;
using ir::Op;
using ir::Reg;
using Node = ir::Node;
using Kind = ir::Node::Kind;

constexpr Reg kNone = ~0u;

struct LowerError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] void fail(const TIntermNode* n, const std::string& what) {
  std::string where = "0:?";
  if (n) where = "0:" + std::to_string(n->getLoc().line);
  throw LowerError(where + ": error: " + what);
}

Base base_of(const TType& t, const TIntermNode* where) {
  switch (t.getBasicType()) {
    case glslang::EbtFloat: return Base::Float;
    case glslang::EbtInt: return Base::Int;
    case glslang::EbtUint: return Base::Uint;
    case glslang::EbtBool: return Base::Bool;
    case glslang::EbtSampler: return Base::Int;
    case glslang::EbtDouble: fail(where, "double precision is not supported");
    default: fail(where, "type '" + std::string(t.getBasicTypeString().c_str()) + "' is not supported");
  }
}

int array_length(const TType& t) {
  int n = t.getOuterArraySize();
  if (n <= 0) n = t.getImplicitArraySize();
  return n > 0 ? n : 1;
}

// Components of a value of type t (none for a member a gl_PerVertex redeclaration left out:
// glslang keeps it, typed void).
int count(const TType& t) {
  if (t.getBasicType() == glslang::EbtVoid) return 0;
  if (t.isArray()) {
    TType e(t, 0);
    return array_length(t) * count(e);
  }
  if (t.isStruct()) {
    int n = 0;
    for (const auto& m : *t.getStruct()) n += count(*m.type);
    return n;
  }
  if (t.isMatrix()) return t.getMatrixCols() * t.getMatrixRows();
  return std::max(1, t.getVectorSize());
}

// What an index selects in a value of type t: `elems` elements of `size` components each
// (array elements, matrix columns, vector components).
struct Elements {
  int elems, size;
};
Elements elements_of(const TType& t) {
  if (t.isArray()) return {array_length(t), count(TType(t, 0))};
  if (t.isMatrix()) return {t.getMatrixCols(), t.getMatrixRows()};
  return {t.getVectorSize(), 1};
}
// The components of member k of struct type t: from `first`, `count` of them.
struct Range {
  int first, count;
};
Range member_range(const TType& t, int k) {
  const auto& members = *t.getStruct();
  int off = 0;
  for (int i = 0; i < k; ++i) off += count(*members[size_t(i)].type);
  return {off, count(*members[size_t(k)].type)};
}
int const_index(TIntermTyped* n) { return n->getAsConstantUnion()->getConstArray()[0].getIConst(); }

void component_bases(const TType& t, std::vector<Base>& out, const TIntermNode* where) {
  if (t.isArray()) {
    TType e(t, 0);
    for (int i = 0; i < array_length(t); ++i) component_bases(e, out, where);
  } else if (t.isStruct()) {
    for (const auto& m : *t.getStruct()) component_bases(*m.type, out, where);
  } else if (t.getBasicType() != glslang::EbtVoid) {
    const Base b = base_of(t, where);
    for (int i = 0; i < count(t); ++i) out.push_back(b);
  }
}

// A struct's members' names and types, nested structs and array sizes included, without
// qualifiers: what makes two stages' struct variables the same type (GLSL 1.50 §4.3.4).
std::string struct_signature(const TType& t) {
  std::string r;
  for (const auto& m : *t.getStruct()) {
    const TType& mt = *m.type;
    r.append(mt.getFieldName().c_str()).append(":").append(mt.getBasicTypeString().c_str());
    for (const int n :
         {mt.getVectorSize(), mt.getMatrixCols(), mt.getMatrixRows(), mt.isArray() ? array_length(mt) : 0})
      r.append(",").append(std::to_string(n));
    if (mt.isStruct()) r.append("{").append(struct_signature(mt)).append("}");
    r.append(";");
  }
  return r;
}

uint32_t fbits(float f) { return std::bit_cast<uint32_t>(f); }

using Val = std::vector<Reg>;

struct Place {
  enum class Where : uint8_t { Regs, Uniform } where = Where::Regs;
  Reg base = 0;  // first register or uniform word of the variable
  uint32_t size = 0;
  Reg dyn = kNone;  // register with a component offset added at run time
  std::vector<uint32_t> comps;
  bool sampler = false;
  bool block = false;  // in a uniform block: bools are raw words (any non-zero is true)
};

uint32_t round_up(uint32_t x, uint32_t a) { return (x + a - 1) / a * a; }

// std140 (GL 3.3 §2.11.4), in words: the base alignment of t, and its components' offsets.
uint32_t std140_align(const TType& t) {
  if (t.isArray() || t.isStruct() || t.isMatrix()) return 4;
  const int n = std::max(1, t.getVectorSize());
  return n == 1 ? 1 : n == 2 ? 2 : 4;
}
bool member_row_major(const TType& m, bool block_row_major) {
  const auto lm = m.getQualifier().layoutMatrix;
  return lm == glslang::ElmRowMajor || (lm == glslang::ElmNone && block_row_major);
}
// Appends the word offsets of t's components (GLSL order) placed at word `at`; returns its
// size in words.
uint32_t std140_layout(const TType& t, uint32_t at, bool row_major, std::vector<uint32_t>& comps) {
  if (t.isArray()) {
    TType e(t, 0);
    std::vector<uint32_t> scratch;
    const uint32_t stride = round_up(std140_layout(e, 0, row_major, scratch), 4);
    for (int i = 0; i < array_length(t); ++i) std140_layout(e, at + uint32_t(i) * stride, row_major, comps);
    return uint32_t(array_length(t)) * stride;
  }
  if (t.isStruct()) {
    uint32_t off = at;
    for (const auto& m : *t.getStruct()) {
      const bool rm = member_row_major(*m.type, row_major);
      off = round_up(off, std140_align(*m.type));
      off += std140_layout(*m.type, off, rm, comps);
    }
    return round_up(off - at, 4);
  }
  if (t.isMatrix()) {
    const uint32_t cols = uint32_t(t.getMatrixCols()), rows = uint32_t(t.getMatrixRows());
    for (uint32_t c = 0; c < cols; ++c)
      for (uint32_t r = 0; r < rows; ++r) comps.push_back(row_major ? at + r * 4 + c : at + c * 4 + r);
    return (row_major ? rows : cols) * 4;
  }
  const uint32_t n = uint32_t(std::max(1, t.getVectorSize()));
  for (uint32_t i = 0; i < n; ++i) comps.push_back(at + i);
  return n;
}

class Lowerer {
 public:
  Lowerer(const glslang::TIntermediate& in, int stage, UniformLayout& u)
      : in_(in), stage_(stage), uniforms_(u) {}

  LoweredStage run() {
    TIntermNode* root = in_.getTreeRoot();
    if (!root || !root->getAsAggregate()) fail(nullptr, "the shader has no code");
    // Functions by mangled name; global initializers in order; the linker objects declare
    // the interface.
    std::vector<TIntermNode*> globals;
    std::vector<const TIntermSymbol*> outputs;
    TIntermAggregate* main_fn = nullptr;
    for (TIntermNode* n : root->getAsAggregate()->getSequence()) {
      TIntermAggregate* a = n->getAsAggregate();
      if (a && a->getOp() == glslang::EOpFunction) {
        functions_[std::string(a->getName().c_str())] = a;
        if (std::string(a->getName().c_str()) == "main(") main_fn = a;
      } else if (a && a->getOp() == glslang::EOpLinkerObjects) {
        // Declared interface variables; only those the code uses become inputs, outputs
        // and uniforms (GL's active ones).
        for (TIntermNode* o : a->getSequence())
          if (TIntermSymbol* s = o->getAsSymbolNode()) {
            const auto storage = s->getType().getQualifier().storage;
            if (storage == glslang::EvqVaryingOut) out_.declared_outputs.insert(name_of(s));
            if (storage == glslang::EvqVaryingOut || storage == glslang::EvqPosition ||
                storage == glslang::EvqPointSize || storage == glslang::EvqClipVertex)
              outputs.push_back(s);
            // A uniform with an initializer carries its value as a constant.
            if (storage == glslang::EvqUniform && s->getConstArray().size() > 0 &&
                s->getType().getBasicType() != glslang::EbtBlock) {
              std::vector<Base> bases;
              component_bases(s->getType(), bases, s);
              std::vector<uint32_t> words;
              for (size_t i = 0; i < bases.size() && int(i) < s->getConstArray().size(); ++i)
                words.push_back(const_bits(s->getConstArray()[int(i)], bases[i]));
              uniforms_.initial[name_of(s)] = std::move(words);
            }
          }
      } else {
        globals.push_back(n);
      }
    }
    if (!main_fn) fail(nullptr, "missing main()");
    if (stage_ == 2) {
      // Every output the code names, too (built-ins such as gl_PrimitiveID may be missing
      // from the linker objects).
      struct Outputs : glslang::TIntermTraverser {
        std::vector<const TIntermSymbol*>* list;
        void visitSymbol(TIntermSymbol* s) override {
          const auto storage = s->getType().getQualifier().storage;
          if (storage == glslang::EvqVaryingOut || storage == glslang::EvqPosition ||
              storage == glslang::EvqPointSize || storage == glslang::EvqClipVertex)
            list->push_back(s);
        }
      } walk;
      walk.list = &outputs;
      root->traverse(&walk);
      geometry_layout(outputs);
    }
    Node fn;
    fn.kind = Kind::Function;
    blocks_.push_back(&fn.a);
    scopes_.emplace_back();
    for (TIntermNode* g : globals) statement(g);
    const TIntermSequence& seq = main_fn->getSequence();
    if (seq.size() >= 2 && seq[1]) statement(seq[1]);
    scopes_.pop_back();
    blocks_.pop_back();
    out_.ir.body.push_back(std::move(fn));
    out_.ir.registers = next_;
    return std::move(out_);
  }

 private:
  const glslang::TIntermediate& in_;
  int stage_;
  UniformLayout& uniforms_;
  LoweredStage out_;
  Reg next_ = 0;
  std::vector<ir::Block*> blocks_;  // where code goes; back() is the current block
  std::unordered_map<std::string, TIntermAggregate*> functions_;
  std::unordered_map<long long, Place> globals_;
  std::vector<std::unordered_map<long long, Place>> scopes_;  // per inlined function
  std::unordered_map<uint32_t, Reg> consts_;
  std::unordered_map<uint32_t, Reg> uniform_regs_;
  struct Frame {
    Val ret;
  };
  std::vector<Frame> frames_;
  int inline_depth_ = 0;

  // --- the geometry stage ---------------------------------------------------------------
  // Its primitives, and every output made an interface variable before any code, so that
  // each EmitVertex copies the same registers.
  void geometry_layout(const std::vector<const TIntermSymbol*>& outputs) {
    GeometryLayout& g = out_.geometry;
    switch (in_.getInputPrimitive()) {
      case glslang::ElgPoints: g.input_vertices = 1, g.input_primitive = 0x0000; break;
      case glslang::ElgLines: g.input_vertices = 2, g.input_primitive = 0x0001; break;
      case glslang::ElgLinesAdjacency: g.input_vertices = 4, g.input_primitive = 0x000A; break;
      case glslang::ElgTriangles: g.input_vertices = 3, g.input_primitive = 0x0004; break;
      case glslang::ElgTrianglesAdjacency: g.input_vertices = 6, g.input_primitive = 0x000C; break;
      default: fail(nullptr, "the geometry shader declares no input primitive type");
    }
    switch (in_.getOutputPrimitive()) {
      case glslang::ElgPoints: g.output_primitive = 0x0000; break;
      case glslang::ElgLineStrip: g.output_primitive = 0x0003; break;
      case glslang::ElgTriangleStrip: g.output_primitive = 0x0005; break;
      default: fail(nullptr, "the geometry shader declares no output primitive type");
    }
    if (in_.getVertices() == glslang::TQualifier::layoutNotSet)
      fail(nullptr, "the geometry shader declares no max_vertices");
    g.max_vertices = in_.getVertices();
    if (g.max_vertices < 0 || g.max_vertices > kMaxGeometryVertices)
      fail(nullptr, "max_vertices " + std::to_string(g.max_vertices) + " is more than " +
                        std::to_string(kMaxGeometryVertices));
    for (const TIntermSymbol* o : outputs) (void)lookup(o);
    for (const Interface& o : out_.outputs)
      if (!o.block)
        for (int c = 0; c < o.components; ++c) g.emit.push_back(o.reg + Reg(c));
    // (GL_MAX_GEOMETRY_OUTPUT_COMPONENTS: 128 a vertex, as Mesa gives.)
    if (g.emit.size() > 128) fail(nullptr, "the geometry shader writes more than 128 output components");
    g.buffer = fresh(int(g.emit.size()) * std::max(1, g.max_vertices));
    g.starts = fresh(std::max(1, g.max_vertices));
    g.count = fresh(2);  // the count, then whether the next vertex continues a strip
    out_.ir.variables.push_back({g.count, 2});
  }
  void emit_vertex() {
    const GeometryLayout& g = out_.geometry;
    const Reg joined = g.count + 1;
    Node n;
    n.kind = Kind::If;
    n.cond = emit(Op::ILt, g.count, iconst(g.max_vertices));
    blocks_.push_back(&n.a);
    const Reg at = emit(Op::IMul, g.count, iconst(int32_t(g.emit.size())));
    const Reg last = g.buffer + Reg(g.emit.size() * size_t(std::max(1, g.max_vertices))) - 1;
    for (size_t c = 0; c < g.emit.size(); ++c)
      code().push_back(Inst{Op::StoreIndexed, g.buffer + Reg(c), at, g.emit[c], 0, 0, last});
    code().push_back(Inst{Op::StoreIndexed, g.starts, g.count, joined, 0, 0,
                          g.starts + Reg(std::max(1, g.max_vertices)) - 1});
    emit_to(Op::Store, joined, iconst(-1));
    emit_to(Op::Store, g.count, emit(Op::IAdd, g.count, iconst(1)));
    blocks_.pop_back();
    blocks_.back()->push_back(std::move(n));
  }

  // --- emission -------------------------------------------------------------------------
  Reg fresh(int n = 1) {
    const Reg r = next_;
    next_ += Reg(n);
    if (next_ > (1u << 20)) fail(nullptr, "the shader is too large");
    return r;
  }
  std::vector<Inst>& code() {
    ir::Block& b = *blocks_.back();
    if (b.empty() || b.back().kind != Kind::Code) b.push_back(Node{});
    return b.back().code;
  }
  Reg emit(Op op, Reg a = 0, Reg b = 0, Reg c = 0, uint32_t imm = 0) {
    const Reg d = fresh();
    code().push_back(Inst{op, d, a, b, c, 0, imm});
    return d;
  }
  void emit_to(Op op, Reg dst, Reg a, Reg b = 0, Reg c = 0, uint32_t imm = 0) {
    code().push_back(Inst{op, dst, a, b, c, 0, imm});
  }
  Reg konst(uint32_t bits) {
    auto it = consts_.find(bits);
    if (it != consts_.end()) return it->second;
    const Reg r = fresh();
    out_.ir.constants.push_back({r, bits});
    consts_[bits] = r;
    return r;
  }
  Reg fconst(float f) { return konst(fbits(f)); }
  Reg iconst(int32_t i) { return konst(uint32_t(i)); }
  Reg uniform_word(uint32_t w) {
    auto it = uniform_regs_.find(w);
    if (it != uniform_regs_.end()) return it->second;
    const Reg r = fresh();
    out_.ir.uniforms.push_back({r, w});
    uniform_regs_[w] = r;
    return r;
  }

  // --- declarations ---------------------------------------------------------------------
  Place var_place(Reg base, int n) {
    Place p;
    p.base = base;
    p.size = uint32_t(n);
    for (int i = 0; i < n; ++i) p.comps.push_back(uint32_t(i));
    return p;
  }

  static std::string name_of(const TIntermSymbol* s) { return std::string(s->getName().c_str()); }

  // Adds the default-block slots of a uniform of type t named `name` from word w.
  void add_uniform_slots(const TType& t, const std::string& name, uint32_t& w, bool builtin,
                         const TIntermNode* where) {
    if (t.isStruct()) {
      const int n = t.isArray() ? array_length(t) : 1;
      for (int i = 0; i < n; ++i) {
        const std::string el = t.isArray() ? name + "[" + std::to_string(i) + "]" : name;
        for (const auto& m : *t.getStruct())
          add_uniform_slots(*m.type, el + "." + std::string(m.type->getFieldName().c_str()), w, builtin,
                            where);
      }
      return;
    }
    UniformSlot s;
    s.name = name;
    s.builtin = builtin;
    TType e = t.isArray() ? TType(t, 0) : TType();
    const TType& el = t.isArray() ? e : t;
    s.array_size = t.isArray() ? array_length(t) : 1;
    s.components = count(el);
    s.gl_type = gl_type_of(el);
    s.word = w;
    if (el.getBasicType() == glslang::EbtSampler) {
      s.sampler = true;
      const auto& smp = el.getSampler();
      s.shadow = smp.isShadow();
      s.array = smp.isArrayed();
      switch (smp.dim) {
        case glslang::Esd1D: s.dim = ir::SamplerDim::D1; break;
        case glslang::Esd2D: s.dim = ir::SamplerDim::D2; break;
        case glslang::Esd3D: s.dim = ir::SamplerDim::D3; break;
        case glslang::EsdCube: s.dim = ir::SamplerDim::Cube; break;
        case glslang::EsdRect: s.dim = ir::SamplerDim::Rect; break;
        case glslang::EsdBuffer: s.dim = ir::SamplerDim::Buffer; break;
        default: fail(where, "sampler type not supported");
      }
      s.base = Base::Int;
    } else {
      s.base = base_of(el, where);
    }
    w += uint32_t(s.array_size * s.components);
    uniforms_.slots.push_back(s);
  }

  Place uniform_place(const TIntermSymbol* s) {
    const std::string name = name_of(s);
    const TType& t = s->getType();
    if (t.getBasicType() == glslang::EbtBlock) return block_place(s);
    auto it = uniforms_.by_name.find(name);
    if (it == uniforms_.by_name.end()) {
      uint32_t w = uniforms_.words;
      uniforms_.by_name[name] = uniforms_.slots.size();
      add_uniform_slots(t, name, w, name.rfind("gl_", 0) == 0, s);
      uniforms_.words = w;
      it = uniforms_.by_name.find(name);
    }
    const UniformSlot& first = uniforms_.slots[it->second];
    Place p;
    p.where = Place::Where::Uniform;
    p.base = first.word;
    const int n = count(t);
    p.size = uint32_t(n);
    for (int i = 0; i < n; ++i) p.comps.push_back(uint32_t(i));
    p.sampler = t.getBasicType() == glslang::EbtSampler;
    // Mark every slot of this variable active.
    for (size_t i = it->second;
         i < uniforms_.slots.size() && uniforms_.slots[i].word < first.word + uint32_t(n); ++i)
      uniforms_.slots[i].active = true;
    return p;
  }

  // The members of struct (or block) t placed at word `at`, under `prefix` ("" or "name").
  static void add_block_members(const TType& t, const std::string& prefix, uint32_t at, bool row_major,
                                std::vector<BlockMember>& out) {
    uint32_t off = at;
    for (const auto& m : *t.getStruct()) {
      const TType& mt = *m.type;
      const bool rm = member_row_major(mt, row_major);
      off = round_up(off, std140_align(mt));
      std::vector<uint32_t> scratch;
      const uint32_t size = std140_layout(mt, off, rm, scratch);
      const std::string name = (prefix.empty() ? "" : prefix + ".") + std::string(mt.getFieldName().c_str());
      TType e = mt.isArray() ? TType(mt, 0) : TType();
      const TType& el = mt.isArray() ? e : mt;
      const int n = mt.isArray() ? array_length(mt) : 1;
      if (el.isStruct()) {  // a struct, or each element of an array of structs
        for (int i = 0; i < n; ++i)
          add_block_members(el, mt.isArray() ? name + "[" + std::to_string(i) + "]" : name,
                            off + uint32_t(i) * (size / uint32_t(n)), rm, out);
      } else {
        BlockMember bm;
        bm.name = name;
        bm.gl_type = gl_type_of(el);
        bm.array_size = n;
        bm.offset = off * 4;
        if (mt.isArray()) bm.array_stride = size / uint32_t(n) * 4;
        if (el.isMatrix()) bm.matrix_stride = 16;
        bm.row_major = el.isMatrix() && rm;
        out.push_back(bm);
      }
      off += size;
    }
  }

  // A uniform block: its region of uniform words, shared by both stages (by block name).
  Place block_place(const TIntermSymbol* s) {
    const TType& t = s->getType();
    const std::string bname = t.getTypeName().c_str();
    const bool row_major = t.getQualifier().layoutMatrix == glslang::ElmRowMajor;
    std::vector<uint32_t> comps;
    const uint32_t words = round_up(std140_layout(t, 0, row_major, comps), 4);
    // An array of blocks is one block per element ("B[0]", "B[1]", each with its own binding
    // point, as GL 3.3 §2.11.4 lists them), in consecutive regions of `per` words.
    const int n = t.isArray() ? array_length(t) : 1;
    const uint32_t per = words / uint32_t(n);
    auto element_name = [&](int i) { return t.isArray() ? bname + "[" + std::to_string(i) + "]" : bname; };
    size_t index = uniforms_.blocks.size();
    for (size_t i = 0; i < uniforms_.blocks.size(); ++i)
      if (uniforms_.blocks[i].name == element_name(0)) index = i;
    if (index == uniforms_.blocks.size()) {
      // Members as GL names them (GL 3.3 §2.11.4: down to basic types and arrays of them,
      // "s.x", "ss[1].x"), with their std140 offsets and strides.
      const std::string inst = name_of(s);
      const bool anonymous = inst.rfind("anon@", 0) == 0;
      for (int i = 0; i < n; ++i) {
        UniformBlockLayout b;
        b.name = element_name(i);
        b.word = uniforms_.words + uint32_t(i) * per;
        b.bytes = per * 4;
        add_block_members(t, anonymous ? "" : bname, 0, row_major, b.members);
        uniforms_.blocks.push_back(b);
      }
      uniforms_.words += words;
    }
    Place p;
    p.where = Place::Where::Uniform;
    p.base = uniforms_.blocks[index].word;
    p.size = words;
    p.comps = comps;
    p.block = true;
    return p;
  }

  // The type of interface variable f, of element type el (not an array): a GL type, or for a
  // struct (GLSL 1.50 allows them between stages) a signature of its members' names and types
  // that stages match on; a struct counts as integer (so it must be flat) when any member is.
  static void set_type(Interface& f, const TType& el, const TIntermNode* where) {
    if (!el.isStruct()) {
      f.gl_type = gl_type_of(el);
      f.base = base_of(el, where);
      return;
    }
    f.gl_type = 0x80000000u | uint32_t(std::hash<std::string>{}(struct_signature(el)) & 0x7FFFFFFFu);
    std::vector<Base> bases;
    component_bases(el, bases, where);
    f.base = Base::Float;
    for (Base b : bases)
      if (b != Base::Float) f.base = b;
  }

  Interface& interface_for(const TIntermSymbol* s, bool output) {
    auto& list = output ? out_.outputs : out_.inputs;
    const std::string name = name_of(s);
    for (auto& i : list)
      if (i.name == name) return i;
    const TType& t = s->getType();
    if (stage_ == 2 && !output && t.isArray()) return geometry_input(s);
    if (t.getBasicType() == glslang::EbtBlock) {
      // An interface block: its members are interface variables of their own, in
      // consecutive registers. gl_PerVertex's (gl_Position in GLSL 1.50 and later) keep their
      // names; a user block's (GLSL 1.50 §4.3.7) are matched as "Block.member" (the block's
      // name, not the instance's), each with its own interpolation qualifier or the block's.
      // An array of blocks is its elements' members in turn, "Block[i].member".
      const int total = count(t);
      const Reg base = fresh(total);
      const std::string block = t.getTypeName().c_str();
      const bool user = block != "gl_PerVertex";
      const int elements = t.isArray() ? array_length(t) : 1;
      int off = 0;
      for (int e = 0; e < elements; ++e)
        for (const auto& m : *t.getStruct()) {
          const TType& mt = *m.type;
          if (mt.hiddenMember()) continue;
          Interface f;
          const std::string prefix = t.isArray() ? block + "[" + std::to_string(e) + "]." : block + ".";
          f.name = (user ? prefix : std::string()) + std::string(mt.getFieldName().c_str());
          f.components = count(mt);
          f.array_size = mt.isArray() ? array_length(mt) : 0;
          TType e = mt.isArray() ? TType(mt, 0) : TType();
          const TType& el = mt.isArray() ? e : mt;
          set_type(f, el, s);
          f.flat = mt.getQualifier().flat || t.getQualifier().flat;
          f.noperspective = mt.getQualifier().nopersp || t.getQualifier().nopersp;
          f.builtin = f.name.rfind("gl_", 0) == 0;
          f.reg = base + Reg(off);
          off += f.components;
          list.push_back(f);
        }
      Interface whole;
      whole.name = name;
      whole.reg = base;
      whole.components = total;
      whole.builtin = true;
      whole.block = true;
      list.push_back(whole);
      return list.back();
    }
    Interface f;
    f.name = name;
    f.components = count(t);
    f.array_size = t.isArray() ? array_length(t) : 0;
    TType e = t.isArray() ? TType(t, 0) : TType();
    const TType& el = t.isArray() ? e : t;
    set_type(f, el, s);
    const auto& q = t.getQualifier();
    if (q.hasLocation()) f.location = int(q.layoutLocation);
    if (q.hasIndex()) f.index = int(q.getIndex());
    f.flat = q.flat;
    f.noperspective = q.nopersp;
    f.builtin = name.rfind("gl_", 0) == 0;
    f.reg = fresh(f.components);
    list.push_back(f);
    return list.back();
  }

  // A geometry stage's input array (gl_in[], a user block array, or `in T name[]`): one
  // element a vertex; an element's members (or the element) are each an interface variable
  // of `vertices` elements, so that the link fills them from the vertex stage's outputs.
  Interface& geometry_input(const TIntermSymbol* s) {
    const TType& t = s->getType();
    const int V = out_.geometry.input_vertices;
    if (array_length(t) != V)
      fail(s, "input '" + name_of(s) + "' has " + std::to_string(array_length(t)) +
                  " elements; the input primitive has " + std::to_string(V) + " vertices");
    const TType el(t, 0);
    const int per = count(el);
    const Reg base = fresh(V * per);
    auto add = [&](const std::string& name, const TType& mt, int off, bool flat, bool nopersp) {
      Interface f;
      f.name = name;
      f.components = count(mt);
      f.array_size = mt.isArray() ? array_length(mt) : 0;
      TType e = mt.isArray() ? TType(mt, 0) : TType();
      set_type(f, mt.isArray() ? e : mt, s);
      if (mt.getQualifier().hasLocation()) f.location = int(mt.getQualifier().layoutLocation);
      f.flat = flat;
      f.noperspective = nopersp;
      f.builtin = f.name.rfind("gl_", 0) == 0;
      f.reg = base + Reg(off);
      f.vertices = V;
      f.vertex_stride = per;
      f.read = true;
      out_.inputs.push_back(f);
    };
    if (el.getBasicType() == glslang::EbtBlock) {
      const std::string block = el.getTypeName().c_str();
      const bool user = block != "gl_PerVertex";
      int off = 0;
      for (const auto& m : *el.getStruct()) {
        const TType& mt = *m.type;
        if (mt.hiddenMember()) continue;
        add((user ? block + "." : std::string()) + std::string(mt.getFieldName().c_str()), mt, off,
            mt.getQualifier().flat || el.getQualifier().flat,
            mt.getQualifier().nopersp || el.getQualifier().nopersp);
        off += count(mt);
      }
      Interface whole;
      whole.name = name_of(s);
      whole.reg = base;
      whole.components = V * per;
      whole.builtin = true;
      whole.block = true;
      out_.inputs.push_back(whole);
    } else {
      add(name_of(s), el, 0, t.getQualifier().flat, t.getQualifier().nopersp);
    }
    return out_.inputs.back();
  }

  Place lookup(const TIntermSymbol* s) {
    const long long id = s->getId();
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
      auto f = it->find(id);
      if (f != it->end()) return f->second;
    }
    auto g = globals_.find(id);
    if (g != globals_.end()) return g->second;
    const TType& t = s->getType();
    const auto storage = t.getQualifier().storage;
    Place p;
    switch (storage) {
      case glslang::EvqUniform:
        p = uniform_place(s);
        globals_[id] = p;
        return p;
      case glslang::EvqBuffer: fail(s, "buffer blocks are not supported");
      case glslang::EvqConst: {
        // A constant that glslang did not fold (a const array indexed at run time).
        const int n = count(t);
        const glslang::TConstUnionArray& c = s->getConstArray();
        if (c.size() < n) fail(s, "constant '" + name_of(s) + "' has no value");
        std::vector<Base> bases;
        component_bases(t, bases, s);
        const Reg r = fresh(n);
        for (int i = 0; i < n; ++i)
          out_.ir.constants.push_back({r + Reg(i), const_bits(c[i], bases[size_t(i)])});
        p = var_place(r, n);
        globals_[id] = p;
        return p;
      }
      case glslang::EvqVaryingIn:
      case glslang::EvqVertexId:
      case glslang::EvqInstanceId:
      case glslang::EvqFace:
      case glslang::EvqFragCoord:
      case glslang::EvqPointCoord: {
        Interface& f = interface_for(s, false);
        f.read = true;
        p = var_place(f.reg, count(t));
        globals_[id] = p;
        return p;
      }
      case glslang::EvqVaryingOut:
      case glslang::EvqPosition:
      case glslang::EvqPointSize:
      case glslang::EvqClipVertex:
      case glslang::EvqFragColor:
      case glslang::EvqFragDepth: {
        Interface& f = interface_for(s, true);
        f.written = true;
        if (storage == glslang::EvqFragDepth) out_.ir.writes_depth = true;
        p = var_place(f.reg, f.components);
        out_.ir.variables.push_back({f.reg, uint32_t(f.components)});
        globals_[id] = p;
        return p;
      }
      case glslang::EvqGlobal: {
        const int n = count(t);
        p = var_place(fresh(n), n);
        out_.ir.variables.push_back({p.base, uint32_t(n)});
        globals_[id] = p;
        return p;
      }
      default: break;
    }
    // A local variable (or parameter) of the current inlined function.
    const int n = count(t);
    if (t.getBasicType() == glslang::EbtSampler) fail(s, "sampler variables must be uniforms or parameters");
    p = var_place(fresh(n), n);
    out_.ir.variables.push_back({p.base, uint32_t(n)});
    scopes_.back()[id] = p;
    return p;
  }

  static uint32_t const_bits(const glslang::TConstUnion& c, Base want) {
    double d = 0;
    int64_t i = 0;
    bool b = false;
    switch (c.getType()) {
      case glslang::EbtFloat:
      case glslang::EbtDouble:
        d = c.getDConst();
        // A constant converted as the run-time conversion is (interp.cpp f2i/f2u): in range
        // it truncates; out of range, or NaN, gives INT_MIN as an int and all bits as a uint.
        if (want == Base::Uint)
          i = d > -1.0 && d < 4294967296.0 ? int64_t(d) : int64_t(0xFFFFFFFFu);
        else
          i = d > -2147483904.0 && d < 2147483648.0 ? int64_t(d)
                                                    : int64_t(std::numeric_limits<int32_t>::min());
        b = d != 0;
        break;
      case glslang::EbtInt:
        i = c.getIConst();
        d = double(i);
        b = i != 0;
        break;
      case glslang::EbtUint:
        i = c.getUConst();
        d = double(c.getUConst());
        b = i != 0;
        break;
      case glslang::EbtBool:
        b = c.getBConst();
        i = b;
        d = b;
        break;
      default: break;
    }
    switch (want) {
      case Base::Float: return fbits(float(d));
      case Base::Int:
      case Base::Uint: return uint32_t(i);
      case Base::Bool: return b ? ~0u : 0u;
    }
    return 0;
  }

  // --- places and values ------------------------------------------------------------------
  Val read(const Place& p) {
    Val v;
    v.reserve(p.comps.size());
    for (uint32_t c : p.comps) {
      if (p.where == Place::Where::Regs) {
        if (p.dyn == kNone)
          v.push_back(p.base + c);
        else
          v.push_back(emit(Op::LoadIndexed, p.dyn, p.base + c, 0, p.base + p.size - 1));
      } else {
        if (p.dyn == kNone)
          v.push_back(uniform_word(p.base + c));
        else
          v.push_back(emit(Op::UniformIndexed, p.dyn, 0, 0, p.base + c));
      }
    }
    return v;
  }

  // A read of a value of type t: a bool in a uniform block is any non-zero word, alone or as a
  // member of a struct or an element of an array read whole.
  Val read_typed(const Place& p, const TType& t) {
    Val v = read(p);
    if (!p.block) return v;
    std::vector<Base> bases;
    component_bases(t, bases, nullptr);
    for (size_t i = 0; i < v.size() && i < bases.size(); ++i)
      if (bases[i] == Base::Bool) v[i] = emit(Op::INe, v[i], iconst(0));
    return v;
  }

  void write(const Place& p, Val v, const TIntermNode* where) {
    if (p.where != Place::Where::Regs) fail(where, "l-value is not writable");
    if (v.size() != p.comps.size()) fail(where, "internal: assignment of mismatched size");
    // A value that reads registers of the place itself (v = v.yx) is copied first.
    if (p.dyn == kNone) {
      for (Reg& r : v) {
        if (r >= p.base && r < p.base + p.size) r = emit(Op::Mov, r);
      }
      for (size_t i = 0; i < v.size(); ++i) emit_to(Op::Store, p.base + p.comps[i], v[i]);
    } else {
      for (Reg& r : v) {
        if (r >= p.base && r < p.base + p.size) r = emit(Op::Mov, r);
      }
      for (size_t i = 0; i < v.size(); ++i)
        emit_to(Op::StoreIndexed, p.base + p.comps[i], p.dyn, v[i], 0, p.base + p.size - 1);
    }
  }

  Place place(TIntermTyped* n) {
    if (TIntermSymbol* s = n->getAsSymbolNode()) return lookup(s);
    if (TIntermBinary* b = n->getAsBinaryNode()) {
      const auto op = b->getOp();
      if (op == glslang::EOpIndexDirect || op == glslang::EOpIndexIndirect ||
          op == glslang::EOpIndexDirectStruct || op == glslang::EOpVectorSwizzle) {
        Place p = place(b->getLeft());
        const TType& lt = b->getLeft()->getType();
        if (op == glslang::EOpVectorSwizzle) {
          std::vector<uint32_t> c;
          for (TIntermNode* s : b->getRight()->getAsAggregate()->getSequence())
            c.push_back(p.comps.at(size_t(const_index(s->getAsTyped()))));
          p.comps = c;
          return p;
        }
        if (op == glslang::EOpIndexDirectStruct) {
          const int k = const_index(b->getRight());
          const Range m = member_range(lt, k);
          // A member of an output block (gl_PerVertex's gl_PointSize, ...) is written: the
          // link gives pipeline slots only to the built-in outputs a stage writes.
          const TIntermSymbol* whole = b->getLeft()->getAsSymbolNode();
          if (whole && lt.getBasicType() == glslang::EbtBlock &&
              lt.getQualifier().storage == glslang::EvqVaryingOut) {
            const std::string block = lt.getTypeName().c_str();
            std::string member = (*lt.getStruct())[size_t(k)].type->getFieldName().c_str();
            if (block != "gl_PerVertex") member = block + "." + member;
            for (Interface& o : out_.outputs)
              if (!o.block && o.name == member) o.written = true;
          }
          p.comps = std::vector<uint32_t>(p.comps.begin() + m.first, p.comps.begin() + m.first + m.count);
          p.sampler = (*lt.getStruct())[size_t(k)].type->getBasicType() == glslang::EbtSampler;
          return p;
        }
        // Element i of an array, column i of a matrix, component i of a vector.
        const auto [elems, esize] = elements_of(lt);
        if (op == glslang::EOpIndexDirect) {
          const int i = std::clamp(const_index(b->getRight()), 0, elems - 1);
          p.comps = std::vector<uint32_t>(p.comps.begin() + i * esize, p.comps.begin() + (i + 1) * esize);
          return p;
        }
        const Val idx = value(b->getRight());
        if (p.sampler) fail(b, "arrays of samplers can only be indexed with constant expressions");
        // The stride between elements must be the same for all of them (it is for whole
        // variables; a swizzled vector indexed at run time is read through selects).
        int stride = esize;
        if (elems > 1) stride = int(p.comps[size_t(esize)]) - int(p.comps[0]);
        bool uniform_stride = true;
        for (int e = 0; e < elems && uniform_stride; ++e)
          for (int c = 0; c < esize; ++c)
            if (int(p.comps[size_t(e * esize + c)]) != int(p.comps[size_t(c)]) + e * stride)
              uniform_stride = false;
        if (!uniform_stride) fail(b, "run-time index into a swizzle is not supported");
        Reg i = emit(Op::IMax, idx[0], iconst(0));
        i = emit(Op::IMin, i, iconst(elems - 1));
        Reg off = stride == 1 ? i : emit(Op::IMul, i, iconst(stride));
        p.dyn = p.dyn == kNone ? off : emit(Op::IAdd, p.dyn, off);
        p.comps = std::vector<uint32_t>(p.comps.begin(), p.comps.begin() + esize);
        return p;
      }
    }
    fail(n, "expression is not an l-value");
  }

  static bool is_access_chain(TIntermTyped* n) {
    if (n->getAsSymbolNode()) return true;
    if (TIntermBinary* b = n->getAsBinaryNode()) {
      const auto op = b->getOp();
      if (op == glslang::EOpIndexDirect || op == glslang::EOpIndexIndirect ||
          op == glslang::EOpIndexDirectStruct || op == glslang::EOpVectorSwizzle)
        return is_access_chain(b->getLeft());
    }
    return false;
  }

  // Whether evaluating n may have an effect besides its value (then it cannot be evaluated
  // for lanes that do not take its branch).
  static bool has_effects(TIntermNode* n) {
    if (!n) return false;
    if (TIntermBinary* b = n->getAsBinaryNode()) {
      const auto op = b->getOp();
      if (op >= glslang::EOpAssign && op <= glslang::EOpRightShiftAssign) return true;
      return has_effects(b->getLeft()) || has_effects(b->getRight());
    }
    if (TIntermUnary* u = n->getAsUnaryNode()) {
      const auto op = u->getOp();
      if (op == glslang::EOpPostIncrement || op == glslang::EOpPostDecrement ||
          op == glslang::EOpPreIncrement || op == glslang::EOpPreDecrement)
        return true;
      return has_effects(u->getOperand());
    }
    if (TIntermAggregate* a = n->getAsAggregate()) {
      if (a->getOp() == glslang::EOpFunctionCall) return true;
      for (TIntermNode* c : a->getSequence())
        if (has_effects(c)) return true;
      return false;
    }
    if (TIntermSelection* s = n->getAsSelectionNode())
      return has_effects(s->getCondition()) || has_effects(s->getTrueBlock()) ||
             has_effects(s->getFalseBlock());
    return false;
  }

  // The registers of a constant of type t (components converted to t's base types).
  Val constant(const glslang::TConstUnionArray& arr, const TType& t, const TIntermNode* where) {
    std::vector<Base> bases;
    component_bases(t, bases, where);
    if (arr.size() < int(bases.size())) fail(where, "constant without a value");
    Val v;
    for (size_t i = 0; i < bases.size(); ++i) v.push_back(konst(const_bits(arr[int(i)], bases[i])));
    return v;
  }

  // --- conversions --------------------------------------------------------------------
  Reg convert(Reg r, Base from, Base to) {
    if (from == to) return r;
    if ((from == Base::Int && to == Base::Uint) || (from == Base::Uint && to == Base::Int)) return r;
    switch (to) {
      case Base::Float:
        if (from == Base::Int) return emit(Op::I2F, r);
        if (from == Base::Uint) return emit(Op::U2F, r);
        return emit(Op::And, r, fconst(1.0f));  // bool
      case Base::Int:
      case Base::Uint:
        if (from == Base::Float) return emit(to == Base::Int ? Op::F2I : Op::F2U, r);
        return emit(Op::And, r, iconst(1));  // bool
      case Base::Bool:
        if (from == Base::Float) return emit(Op::FNe, r, fconst(0.0f));
        return emit(Op::INe, r, iconst(0));
    }
    return r;
  }

  // --- expressions ----------------------------------------------------------------------
  Val value(TIntermTyped* n) {
    if (TIntermConstantUnion* c = n->getAsConstantUnion())
      return constant(c->getConstArray(), c->getType(), c);
    if (TIntermSymbol* s = n->getAsSymbolNode()) {
      if (s->getType().getQualifier().storage == glslang::EvqConst && s->getConstArray().size() > 0 &&
          !s->getType().isArray())
        return constant(s->getConstArray(), s->getType(), s);
      return read(lookup(s));
    }
    if (TIntermBinary* b = n->getAsBinaryNode()) return binary(b);
    if (TIntermUnary* u = n->getAsUnaryNode()) return unary(u);
    if (TIntermAggregate* a = n->getAsAggregate()) return aggregate(a);
    if (TIntermSelection* s = n->getAsSelectionNode()) return select(s);
    fail(n, "expression not supported");
  }

  static Base base_or_float(const TType& t) {
    switch (t.getBasicType()) {
      case glslang::EbtInt: return Base::Int;
      case glslang::EbtUint: return Base::Uint;
      case glslang::EbtBool: return Base::Bool;
      default: return Base::Float;
    }
  }

  // Repeats a scalar to n components.
  static Val widen(const Val& v, size_t n) {
    if (v.size() == n) return v;
    if (v.size() == 1) return Val(n, v[0]);
    return v;
  }

  Val componentwise(Op op, const Val& a, const Val& b, size_t n) {
    const Val x = widen(a, n), y = widen(b, n);
    Val r;
    for (size_t i = 0; i < n; ++i) r.push_back(emit(op, x.at(i), y.at(i)));
    return r;
  }

  Op arith_op(glslang::TOperator op, Base b, TIntermNode* where) {
    const bool f = b == Base::Float, u = b == Base::Uint;
    switch (op) {
      case glslang::EOpAdd:
      case glslang::EOpAddAssign: return f ? Op::FAdd : Op::IAdd;
      case glslang::EOpSub:
      case glslang::EOpSubAssign: return f ? Op::FSub : Op::ISub;
      case glslang::EOpMul:
      case glslang::EOpMulAssign:
      case glslang::EOpVectorTimesScalar:
      case glslang::EOpVectorTimesScalarAssign:
      case glslang::EOpMatrixTimesScalar:
      case glslang::EOpMatrixTimesScalarAssign: return f ? Op::FMul : Op::IMul;
      case glslang::EOpDiv:
      case glslang::EOpDivAssign: return f ? Op::FDiv : u ? Op::UDiv : Op::IDiv;
      // GLSL leaves % undefined for negative operands; Mesa takes the remainder of the bits
      // as unsigned, and so does Tessel.
      case glslang::EOpMod:
      case glslang::EOpModAssign: return f ? Op::FMod : Op::UMod;
      case glslang::EOpAnd:
      case glslang::EOpAndAssign: return Op::And;
      case glslang::EOpInclusiveOr:
      case glslang::EOpInclusiveOrAssign: return Op::Or;
      case glslang::EOpExclusiveOr:
      case glslang::EOpExclusiveOrAssign: return Op::Xor;
      case glslang::EOpLeftShift:
      case glslang::EOpLeftShiftAssign: return Op::Shl;
      case glslang::EOpRightShift:
      case glslang::EOpRightShiftAssign: return u ? Op::ShrL : Op::ShrA;
      default: fail(where, "operator not supported");
    }
  }

  // a (cols_a x rows) times b; column-major components.
  Val mat_mul(const Val& a, int a_cols, int a_rows, const Val& b, int b_cols) {
    Val r;
    for (int c = 0; c < b_cols; ++c) {
      for (int row = 0; row < a_rows; ++row) {
        Reg acc = emit(Op::FMul, a[size_t(row)], b[size_t(c * a_cols)]);
        for (int k = 1; k < a_cols; ++k)
          acc = mad(a[size_t(k * a_rows + row)], b[size_t(c * a_cols + k)], acc);
        r.push_back(acc);
      }
    }
    return r;
  }

  Val arithmetic(glslang::TOperator op, const TType& rt, TIntermTyped* l, const Val& a, TIntermTyped* r,
                 const Val& b, TIntermNode* where) {
    const TType& lt = l->getType();
    const TType& tt = r->getType();
    switch (op) {
      case glslang::EOpMatrixTimesMatrix:
      case glslang::EOpMatrixTimesMatrixAssign:
        return mat_mul(a, lt.getMatrixCols(), lt.getMatrixRows(), b, tt.getMatrixCols());
      case glslang::EOpMatrixTimesVector: return mat_mul(a, lt.getMatrixCols(), lt.getMatrixRows(), b, 1);
      case glslang::EOpVectorTimesMatrix:
      case glslang::EOpVectorTimesMatrixAssign: {
        // v * M: component c is dot(v, column c).
        const int rows = tt.getMatrixRows(), cols = tt.getMatrixCols();
        Val out;
        for (int c = 0; c < cols; ++c)
          out.push_back(dot(a, Val(b.begin() + c * rows, b.begin() + (c + 1) * rows)));
        return out;
      }
      default: break;
    }
    const Base base = base_or_float(lt.getBasicType() == glslang::EbtBool ? tt : lt);
    const size_t n = size_t(count(rt));
    if (op == glslang::EOpLeftShift || op == glslang::EOpRightShift || op == glslang::EOpLeftShiftAssign ||
        op == glslang::EOpRightShiftAssign) {
      const Base lb = base_or_float(lt);
      return componentwise(arith_op(op, lb, where), a, b, n);
    }
    return componentwise(arith_op(op, base, where), a, b, n);
  }

  // The lane-wise comparison of GLSL's relational operators and functions (lessThan, equal, ...).
  static Op compare_op(glslang::TOperator op, Base b) {
    const bool f = b == Base::Float, u = b == Base::Uint;
    switch (op) {
      case glslang::EOpVectorEqual: return f ? Op::FEq : Op::IEq;
      case glslang::EOpVectorNotEqual: return f ? Op::FNe : Op::INe;
      case glslang::EOpLessThan: return f ? Op::FLt : u ? Op::ULt : Op::ILt;
      case glslang::EOpGreaterThan: return f ? Op::FGt : u ? Op::UGt : Op::IGt;
      case glslang::EOpLessThanEqual: return f ? Op::FLe : u ? Op::ULe : Op::ILe;
      default: return f ? Op::FGe : u ? Op::UGe : Op::IGe;
    }
  }

  Val compare_all(bool equal, const TType& t, const Val& a, const Val& b, TIntermNode* where) {
    std::vector<Base> bases;
    component_bases(t, bases, where);
    Reg acc = kNone;
    for (size_t i = 0; i < a.size(); ++i) {
      const Reg e = emit(bases[i] == Base::Float ? Op::FEq : Op::IEq, a[i], b[i]);
      acc = acc == kNone ? e : emit(Op::And, acc, e);
    }
    if (equal) return {acc};
    return {emit(Op::Not, acc)};
  }

  Val binary(TIntermBinary* b) {
    const auto op = b->getOp();
    switch (op) {
      case glslang::EOpIndexDirect:
      case glslang::EOpIndexIndirect:
      case glslang::EOpIndexDirectStruct:
      case glslang::EOpVectorSwizzle:
        if (is_access_chain(b)) return read_typed(place(b), b->getType());
        return rvalue_access(b);
      case glslang::EOpAssign: {
        Val v = value(b->getRight());
        const Place p = place(b->getLeft());
        write(p, v, b);
        return read(p);
      }
      case glslang::EOpAddAssign:
      case glslang::EOpSubAssign:
      case glslang::EOpMulAssign:
      case glslang::EOpDivAssign:
      case glslang::EOpModAssign:
      case glslang::EOpAndAssign:
      case glslang::EOpInclusiveOrAssign:
      case glslang::EOpExclusiveOrAssign:
      case glslang::EOpLeftShiftAssign:
      case glslang::EOpRightShiftAssign:
      case glslang::EOpVectorTimesMatrixAssign:
      case glslang::EOpVectorTimesScalarAssign:
      case glslang::EOpMatrixTimesScalarAssign:
      case glslang::EOpMatrixTimesMatrixAssign: {
        const Place p = place(b->getLeft());
        const Val cur = read(p);
        const Val rhs = value(b->getRight());
        Val v = arithmetic(op, b->getLeft()->getType(), b->getLeft(), cur, b->getRight(), rhs, b);
        write(p, v, b);
        return read(p);
      }
      case glslang::EOpLogicalAnd:
      case glslang::EOpLogicalOr: {
        const Val a = value(b->getLeft());
        if (!has_effects(b->getRight())) {
          const Val c = value(b->getRight());
          return {emit(op == glslang::EOpLogicalAnd ? Op::And : Op::Or, a[0], c[0])};
        }
        // Short circuit: the right side runs only in the lanes that need it.
        const Reg t = fresh();
        out_.ir.variables.push_back({t, 1});
        emit_to(Op::Store, t, a[0]);
        Node n;
        n.kind = Kind::If;
        n.cond = op == glslang::EOpLogicalAnd ? a[0] : emit(Op::Not, a[0]);
        blocks_.push_back(&n.a);
        const Val c = value(b->getRight());
        emit_to(Op::Store, t, c[0]);
        blocks_.pop_back();
        blocks_.back()->push_back(std::move(n));
        return {emit(Op::Mov, t)};
      }
      case glslang::EOpLogicalXor: {
        const Val a = value(b->getLeft()), c = value(b->getRight());
        return {emit(Op::Xor, a[0], c[0])};
      }
      case glslang::EOpComma: {
        (void)value(b->getLeft());
        return value(b->getRight());
      }
      default: break;
    }
    const Val a = value(b->getLeft());
    const Val c = value(b->getRight());
    const TType& lt = b->getLeft()->getType();
    switch (op) {
      case glslang::EOpEqual: return compare_all(true, lt, a, c, b);
      case glslang::EOpNotEqual: return compare_all(false, lt, a, c, b);
      case glslang::EOpVectorEqual:
      case glslang::EOpVectorNotEqual:
      case glslang::EOpLessThan:
      case glslang::EOpGreaterThan:
      case glslang::EOpLessThanEqual:
      case glslang::EOpGreaterThanEqual: {
        return componentwise(compare_op(op, base_or_float(lt)), a, c, std::max(a.size(), c.size()));
      }
      default: return arithmetic(op, b->getType(), b->getLeft(), a, b->getRight(), c, b);
    }
  }

  // An index or swizzle of a value that is not a variable (a call's result, a constructor).
  Val rvalue_access(TIntermBinary* b) {
    const auto op = b->getOp();
    const Val v = value(b->getLeft());
    const TType& lt = b->getLeft()->getType();
    if (op == glslang::EOpVectorSwizzle) {
      Val r;
      for (TIntermNode* s : b->getRight()->getAsAggregate()->getSequence())
        r.push_back(v.at(size_t(const_index(s->getAsTyped()))));
      return r;
    }
    if (op == glslang::EOpIndexDirectStruct) {
      const Range m = member_range(lt, const_index(b->getRight()));
      return Val(v.begin() + m.first, v.begin() + m.first + m.count);
    }
    const auto [elems, esize] = elements_of(lt);
    if (op == glslang::EOpIndexDirect) {
      const int i = std::clamp(const_index(b->getRight()), 0, elems - 1);
      return Val(v.begin() + i * esize, v.begin() + (i + 1) * esize);
    }
    // Run-time index: a chain of selects over the elements.
    const Val idx = value(b->getRight());
    Val r(v.begin(), v.begin() + esize);
    for (int e = 1; e < elems; ++e) {
      const Reg m = emit(Op::IEq, idx[0], iconst(e));
      for (int c = 0; c < esize; ++c)
        r[size_t(c)] = emit(Op::Select, m, v[size_t(e * esize + c)], r[size_t(c)]);
    }
    return r;
  }

  Val unary(TIntermUnary* u) {
    const auto op = u->getOp();
    TIntermTyped* x = u->getOperand();
    const TType& xt = x->getType();
    const Base xb = base_or_float(xt);
    if (op == glslang::EOpTextureQuerySize) {  // textureSize(samplerBuffer): no level argument
      TIntermAggregate call(op);
      call.getSequence().push_back(x);
      call.setType(u->getType());
      call.setLoc(u->getLoc());
      return texture(&call);
    }
    switch (op) {
      case glslang::EOpTextureQuerySize: {
        // textureSize of a sampler without levels (sampler2DRect) has one argument, so
        // glslang makes it a unary node: the same lowering as with a level.
        glslang::TIntermAggregate call(op);
        call.getSequence().push_back(x);
        call.setType(u->getType());
        call.setLoc(u->getLoc());
        return texture(&call);
      }
      case glslang::EOpPostIncrement:
      case glslang::EOpPostDecrement:
      case glslang::EOpPreIncrement:
      case glslang::EOpPreDecrement: {
        const Place p = place(x);
        Val old = read(p);
        for (Reg& r : old) r = emit(Op::Mov, r);
        const bool inc = op == glslang::EOpPostIncrement || op == glslang::EOpPreIncrement;
        const Reg one = xb == Base::Float ? fconst(1.0f) : iconst(1);
        Val nv;
        for (Reg r : old)
          nv.push_back(
              emit(xb == Base::Float ? (inc ? Op::FAdd : Op::FSub) : (inc ? Op::IAdd : Op::ISub), r, one));
        write(p, nv, u);
        if (op == glslang::EOpPostIncrement || op == glslang::EOpPostDecrement) return old;
        return read(p);
      }
      default: break;
    }
    const Val a = value(x);
    auto each = [&](Op o) {
      Val r;
      for (Reg c : a) r.push_back(emit(o, c));
      return r;
    };
    auto each_f = [&](auto&& f) {
      Val r;
      for (Reg c : a) r.push_back(f(c));
      return r;
    };
    const Base rb = base_or_float(u->getType());
    switch (op) {
      case glslang::EOpNegative: return each(xb == Base::Float ? Op::FNeg : Op::INeg);
      case glslang::EOpLogicalNot:
      case glslang::EOpVectorLogicalNot:
      case glslang::EOpBitwiseNot: return each(Op::Not);
      case glslang::EOpCopyObject: return a;
      case glslang::EOpRadians:
        return each_f([&](Reg c) { return emit(Op::FMul, c, fconst(0.017453292519943295f)); });
      case glslang::EOpDegrees:
        return each_f([&](Reg c) { return emit(Op::FMul, c, fconst(57.29577951308232f)); });
      case glslang::EOpSin: return each_f([&](Reg c) { return mesa_sincos(c, false); });
      case glslang::EOpCos: return each_f([&](Reg c) { return mesa_sincos(c, true); });
      case glslang::EOpTan: return each_f([&](Reg c) { return mesa_tan(c); });
      case glslang::EOpAsin: return each_f([&](Reg c) { return mesa_asin(c); });
      case glslang::EOpAcos: return each_f([&](Reg c) { return mesa_acos(c); });
      case glslang::EOpAtan: return each_f([&](Reg c) { return mesa_atan(c); });
      case glslang::EOpSinh: return each_f([&](Reg c) { return mesa_sinh(c); });
      case glslang::EOpCosh: return each_f([&](Reg c) { return mesa_cosh(c); });
      case glslang::EOpTanh: return each_f([&](Reg c) { return mesa_tanh(c); });
      case glslang::EOpAsinh: return each_f([&](Reg c) { return mesa_asinh(c); });
      case glslang::EOpAcosh: return each_f([&](Reg c) { return mesa_acosh(c); });
      case glslang::EOpAtanh: return each_f([&](Reg c) { return mesa_atanh(c); });
      case glslang::EOpExp: return each_f([&](Reg c) { return mesa_exp(c); });
      case glslang::EOpLog: return each_f([&](Reg c) { return mesa_log(c); });
      case glslang::EOpExp2: return each_f([&](Reg c) { return mesa_exp2(c); });
      case glslang::EOpLog2: return each_f([&](Reg c) { return mesa_log2(c); });
      case glslang::EOpSqrt: return each(Op::FSqrt);
      case glslang::EOpInverseSqrt: return each(Op::FRsq);
      case glslang::EOpAbs: return each(xb == Base::Float ? Op::FAbs : Op::IAbs);
      case glslang::EOpSign: return each(xb == Base::Float ? Op::FSign : Op::ISign);
      case glslang::EOpFloor: return each(Op::FFloor);
      case glslang::EOpTrunc: return each(Op::FTrunc);
      case glslang::EOpRound:
        return each(Op::FRoundEven);  // GLSL leaves .5 to the implementation; Mesa rounds to even
      case glslang::EOpRoundEven: return each(Op::FRoundEven);
      case glslang::EOpCeil: return each(Op::FCeil);
      case glslang::EOpFract: return each(Op::FFract);
      case glslang::EOpIsNan: return each(Op::FIsNan);
      case glslang::EOpIsInf: return each(Op::FIsInf);
      case glslang::EOpFloatBitsToInt:
      case glslang::EOpFloatBitsToUint:
      case glslang::EOpIntBitsToFloat:
      case glslang::EOpUintBitsToFloat: return a;
      case glslang::EOpBitFieldReverse: return each(Op::BitReverse);
      case glslang::EOpBitCount: return each(Op::BitCount);
      case glslang::EOpFindLSB: return each(Op::FindLSB);
      case glslang::EOpFindMSB: return each(xb == Base::Uint ? Op::UFindMSB : Op::IFindMSB);
      case glslang::EOpLength: return {length(a)};
      case glslang::EOpNormalize: {
        if (a.size() == 1) return {fsign(a[0])};
        const Reg inv = emit(Op::FRsq, dot(a, a));
        return each_f([&](Reg c) { return emit(Op::FMul, c, inv); });
      }
      case glslang::EOpAny:
      case glslang::EOpAll: {
        Reg acc = a[0];
        for (size_t i = 1; i < a.size(); ++i) acc = emit(op == glslang::EOpAny ? Op::Or : Op::And, acc, a[i]);
        return {acc};
      }
      case glslang::EOpTranspose: {
        const int cols = xt.getMatrixCols(), rows = xt.getMatrixRows();
        Val r;
        for (int c = 0; c < rows; ++c)
          for (int k = 0; k < cols; ++k) r.push_back(a[size_t(k * rows + c)]);
        return r;
      }
      case glslang::EOpDeterminant: return {determinant(a, xt.getMatrixCols())};
      case glslang::EOpMatrixInverse: return inverse(a, xt.getMatrixCols());
      case glslang::EOpDPdx:
      case glslang::EOpDPdxFine:
      case glslang::EOpDPdxCoarse: out_.ir.uses_derivatives = true; return each(Op::Ddx);
      case glslang::EOpDPdy:
      case glslang::EOpDPdyFine:
      case glslang::EOpDPdyCoarse: out_.ir.uses_derivatives = true; return each(Op::Ddy);
      case glslang::EOpFwidth:
      case glslang::EOpFwidthFine:
      case glslang::EOpFwidthCoarse:
        out_.ir.uses_derivatives = true;
        return each_f([&](Reg c) {
          return emit(Op::FAdd, emit(Op::FAbs, emit(Op::Ddx, c)), emit(Op::FAbs, emit(Op::Ddy, c)));
        });
      case glslang::EOpPackHalf2x16: return {emit(Op::PackHalf, a[0], a[1])};
      case glslang::EOpUnpackHalf2x16: return {emit(Op::UnpackHalfLo, a[0]), emit(Op::UnpackHalfHi, a[0])};
      case glslang::EOpNoise: {
        Val r(size_t(count(u->getType())), fconst(0.0f));
        return r;
      }
      default: break;
    }
    // Conversions: glslang names them EOpConv<From>To<To>.
    if (op >= glslang::EOpConvInt8ToBool && op <= glslang::EOpConvDoubleToFloat) {
      Val r;
      for (Reg c : a) r.push_back(convert(c, xb, rb));
      return r;
    }
    fail(u, "operator '" + std::to_string(int(op)) + "' is not supported");
  }

  // a * b + c with two roundings: llvmpipe does not fuse GLSL's products and sums (only
  // fma() is fused), and matching its results bit for bit matters more than the ulp saved.
  Reg mad(Reg a, Reg b, Reg c) { return emit(Op::FAdd, c, emit(Op::FMul, a, b)); }
  // dot as llvmpipe sums it: from the last component down, ((w w' + z z') + y y') + x x'.
  Reg dot(const Val& a, const Val& b) {
    const size_t n = a.size();
    Reg acc = emit(Op::FMul, a[n - 1], b[n - 1]);
    for (size_t i = n - 1; i-- > 0;) acc = mad(a[i], b[i], acc);
    return acc;
  }
  Reg length(const Val& a) { return emit(Op::FSqrt, dot(a, a)); }
  Reg det2(Reg a, Reg b, Reg c, Reg d) { return emit(Op::FSub, emit(Op::FMul, a, d), emit(Op::FMul, b, c)); }
  // m[c][r] = v[c * n + r]
  Reg determinant(const Val& m, int n) {
    auto at = [&](int c, int r) { return m[size_t(c * n + r)]; };
    if (n == 2) return det2(at(0, 0), at(1, 0), at(0, 1), at(1, 1));
    if (n == 3) {
      Reg r = emit(Op::FMul, at(0, 0), det2(at(1, 1), at(2, 1), at(1, 2), at(2, 2)));
      r = emit(Op::FSub, r, emit(Op::FMul, at(1, 0), det2(at(0, 1), at(2, 1), at(0, 2), at(2, 2))));
      return emit(Op::FAdd, r, emit(Op::FMul, at(2, 0), det2(at(0, 1), at(1, 1), at(0, 2), at(1, 2))));
    }
    // 4x4 by cofactors of the first column.
    Reg acc = kNone;
    for (int r = 0; r < 4; ++r) {
      Val sub;
      for (int c = 1; c < 4; ++c)
        for (int rr = 0; rr < 4; ++rr)
          if (rr != r) sub.push_back(at(c, rr));
      Reg t = emit(Op::FMul, at(0, r), determinant(sub, 3));
      if (acc == kNone)
        acc = t;
      else
        acc = emit((r & 1) ? Op::FSub : Op::FAdd, acc, t);
    }
    return acc;
  }
  // A 3x3 determinant expanded along the first column, s(c, r) its elements: (s00 (s11 s22 -
  // s21 s12) - s01 (s10 s22 - s20 s12)) + s02 (s10 s21 - s20 s11), in the order llvmpipe's
  // inverse() evaluates it.
  template <class At>
  Reg det3_by_column(At s) {
    Reg r = emit(Op::FMul, s(0, 0), det2(s(1, 1), s(2, 1), s(1, 2), s(2, 2)));
    r = emit(Op::FSub, r, emit(Op::FMul, s(0, 1), det2(s(1, 0), s(2, 0), s(1, 2), s(2, 2))));
    return emit(Op::FAdd, r, emit(Op::FMul, s(0, 2), det2(s(1, 0), s(2, 0), s(1, 1), s(2, 1))));
  }
  // The adjugate over the determinant, each element divided (not multiplied by 1 / det), with
  // the cofactors and the determinant in llvmpipe's order of operations.
  Val inverse(const Val& m, int n) {
    auto at = [&](int c, int r) { return m[size_t(c * n + r)]; };
    Val adj(size_t(n * n));
    for (int c = 0; c < n; ++c)
      for (int row = 0; row < n; ++row) {
        // adj[c][row] is the cofactor of m[row][c]: without column `row` and row `c`.
        int cols[3], rows[3], nc = 0, nr = 0;
        for (int k = 0; k < n; ++k) {
          if (k != row) cols[nc++] = k;
          if (k != c) rows[nr++] = k;
        }
        auto s = [&](int i, int j) { return at(cols[i], rows[j]); };
        Reg v = n == 2 ? s(0, 0) : n == 3 ? det2(s(0, 0), s(1, 0), s(0, 1), s(1, 1)) : det3_by_column(s);
        if ((row + c) & 1) v = emit(Op::FNeg, v);
        adj[size_t(c * n + row)] = v;
      }
    Reg det;
    if (n == 2)
      det = det2(at(0, 0), at(1, 0), at(0, 1), at(1, 1));
    else if (n == 3)
      det = det3_by_column(at);
    else {  // m00 adj00 + (m01 adj10 + (m02 adj20 + m03 adj30))
      det = emit(Op::FMul, at(0, 3), adj[size_t(3 * n)]);
      for (int k = 2; k >= 0; --k) det = emit(Op::FAdd, emit(Op::FMul, at(0, k), adj[size_t(k * n)]), det);
    }
    Val r(adj.size());
    for (size_t k = 0; k < adj.size(); ++k) r[k] = emit(Op::FDiv, adj[k], det);
    return r;
  }

  Val select(TIntermSelection* s) {
    // A ?: expression (a selection statement has void type and is handled by statement()).
    const Val c = value(s->getCondition());
    TIntermTyped* t = s->getTrueBlock()->getAsTyped();
    TIntermTyped* f = s->getFalseBlock()->getAsTyped();
    if (!has_effects(t) && !has_effects(f)) {
      const Val a = value(t), b = value(f);
      Val r;
      for (size_t i = 0; i < a.size(); ++i)
        r.push_back(a[i] == b[i] ? a[i] : emit(Op::Select, c[0], a[i], b[i]));
      return r;
    }
    const int n = count(s->getType());
    const Reg tmp = fresh(n);
    out_.ir.variables.push_back({tmp, uint32_t(n)});
    const Place p = var_place(tmp, n);
    Node node;
    node.kind = Kind::If;
    node.cond = c[0];
    blocks_.push_back(&node.a);
    write(p, value(t), s);
    blocks_.pop_back();
    blocks_.push_back(&node.b);
    write(p, value(f), s);
    blocks_.pop_back();
    blocks_.back()->push_back(std::move(node));
    Val r;
    for (int i = 0; i < n; ++i) r.push_back(emit(Op::Mov, tmp + Reg(i)));
    return r;
  }

  // --- aggregates: constructors, calls, built-in functions ------------------------------
  Val construct(TIntermAggregate* a) {
    const TType& t = a->getType();
    const TIntermSequence& args = a->getSequence();
    const int n = count(t);
    if (t.isArray() || t.isStruct()) {
      Val r;
      std::vector<Base> want;
      component_bases(t, want, a);
      for (TIntermNode* arg : args) {
        TIntermTyped* x = arg->getAsTyped();
        const Val v = value(x);
        std::vector<Base> have;
        component_bases(x->getType(), have, a);
        for (size_t i = 0; i < v.size(); ++i) {
          const size_t k = r.size();
          r.push_back(k < want.size() ? convert(v[i], have[i], want[k]) : v[i]);
        }
      }
      r.resize(size_t(n), fconst(0.0f));
      return r;
    }
    const Base want = base_or_float(t);
    // Arguments flattened, converted to the constructed type's base.
    std::vector<Val> vals;
    std::vector<const TType*> types;
    Val flat;
    for (TIntermNode* arg : args) {
      TIntermTyped* x = arg->getAsTyped();
      Val v = value(x);
      const Base have = base_or_float(x->getType());
      for (Reg& r : v) r = convert(r, have, want);
      vals.push_back(v);
      types.push_back(&x->getType());
      flat.insert(flat.end(), v.begin(), v.end());
    }
    if (t.isMatrix()) {
      const int cols = t.getMatrixCols(), rows = t.getMatrixRows();
      const Reg zero = fconst(0.0f), one = fconst(1.0f);
      if (args.size() == 1 && types[0]->isScalar()) {
        Val r;
        for (int c = 0; c < cols; ++c)
          for (int row = 0; row < rows; ++row) r.push_back(c == row ? flat[0] : zero);
        return r;
      }
      if (args.size() == 1 && types[0]->isMatrix()) {
        const int sc = types[0]->getMatrixCols(), sr = types[0]->getMatrixRows();
        Val r;
        for (int c = 0; c < cols; ++c)
          for (int row = 0; row < rows; ++row)
            r.push_back(c < sc && row < sr ? flat[size_t(c * sr + row)] : (c == row ? one : zero));
        return r;
      }
      flat.resize(size_t(n), zero);
      return flat;
    }
    if (flat.size() == 1 && n > 1) return Val(size_t(n), flat[0]);
    flat.resize(size_t(n));
    return flat;
  }

  Val call(TIntermAggregate* a) {
    auto it = functions_.find(std::string(a->getName().c_str()));
    if (it == functions_.end() || it->second->getSequence().size() < 2)
      fail(a, "function '" + std::string(a->getName().c_str()) + "' has no body");
    if (inline_depth_ > 64) fail(a, "recursion or functions nested too deep");
    TIntermAggregate* fn = it->second;
    const TIntermSequence& params = fn->getSequence()[0]->getAsAggregate()->getSequence();
    const TIntermSequence& args = a->getSequence();
    // Arguments are evaluated in the caller's scope, before the callee's scope opens.
    struct Arg {
      Val in;
      Place out;
      bool has_out = false;
      bool sampler = false;
      Place sampler_place;
    };
    std::vector<Arg> vals(args.size());
    for (size_t i = 0; i < args.size() && i < params.size(); ++i) {
      TIntermTyped* x = args[i]->getAsTyped();
      const auto q = params[i]->getAsSymbolNode()->getType().getQualifier().storage;
      if (x->getType().getBasicType() == glslang::EbtSampler) {
        vals[i].sampler = true;
        vals[i].sampler_place = place(x);
        continue;
      }
      if (q == glslang::EvqOut || q == glslang::EvqInOut) {
        vals[i].out = place(x);
        vals[i].has_out = true;
        if (q == glslang::EvqInOut) vals[i].in = read(vals[i].out);
      } else {
        vals[i].in = value(x);
      }
    }
    ++inline_depth_;
    Node node;
    node.kind = Kind::Function;
    blocks_.push_back(&node.a);
    scopes_.emplace_back();
    std::vector<Place> param_places(params.size());
    for (size_t i = 0; i < params.size() && i < args.size(); ++i) {
      TIntermSymbol* ps = params[i]->getAsSymbolNode();
      if (vals[i].sampler) {
        scopes_.back()[ps->getId()] = vals[i].sampler_place;
        continue;
      }
      const Place p = lookup(ps);  // a fresh variable in this scope
      param_places[i] = p;
      if (!vals[i].in.empty()) write(p, vals[i].in, a);
    }
    Frame fr;
    const int rn = fn->getType().getBasicType() == glslang::EbtVoid ? 0 : count(fn->getType());
    if (rn > 0) {
      const Reg r = fresh(rn);
      out_.ir.variables.push_back({r, uint32_t(rn)});
      for (int i = 0; i < rn; ++i) fr.ret.push_back(r + Reg(i));
    }
    frames_.push_back(fr);
    statement(fn->getSequence()[1]);
    frames_.pop_back();
    scopes_.pop_back();
    blocks_.pop_back();
    --inline_depth_;
    blocks_.back()->push_back(std::move(node));
    // out and inout parameters are copied back under the caller's mask.
    for (size_t i = 0; i < args.size() && i < params.size(); ++i)
      if (vals[i].has_out) write(vals[i].out, read(param_places[i]), a);
    Val r;
    for (Reg x : fr.ret) r.push_back(emit(Op::Mov, x));
    return r;
  }

  Val aggregate(TIntermAggregate* a) {
    const auto op = a->getOp();
    if (op == glslang::EOpFunctionCall) {
      // GLSL 1.40's inverse(), which front.cpp declares for glslang: the built-in.
      if (in_.getVersion() == 140 && a->getSequence().size() == 1) {
        const std::string name = a->getName().c_str();
        const int n = name == "inverse(mf22;"   ? 2
                      : name == "inverse(mf33;" ? 3
                      : name == "inverse(mf44;" ? 4
                                                : 0;
        if (n) return inverse(value(a->getSequence()[0]->getAsTyped()), n);
      }
      return call(a);
    }
    if (op == glslang::EOpSequence || op == glslang::EOpComma) {
      Val last;
      for (TIntermNode* n : a->getSequence()) {
        if (TIntermTyped* t = n->getAsTyped())
          last = value(t);
        else
          statement(n);
      }
      return last;
    }
    if (op == glslang::EOpEmitVertex || op == glslang::EOpEndPrimitive) {
      if (stage_ != 2) fail(a, "EmitVertex and EndPrimitive are geometry shader functions");
      if (op == glslang::EOpEmitVertex)
        emit_vertex();
      else
        emit_to(Op::Store, out_.geometry.count + 1, iconst(0));
      return {};
    }
    if (op > glslang::EOpConstructGuardStart && op < glslang::EOpConstructGuardEnd) return construct(a);
    if (op > glslang::EOpSamplingGuardBegin && op < glslang::EOpSamplingGuardEnd) return texture(a);
    if (op == glslang::EOpTextureQuerySize || op == glslang::EOpTextureQueryLevels) return texture(a);
    const TIntermSequence& s = a->getSequence();
    std::vector<Val> v;
    std::vector<TIntermTyped*> x;
    // modf/frexp write through their last argument.
    const bool last_out = op == glslang::EOpModf || op == glslang::EOpFrexp || op == glslang::EOpAddCarry ||
                          op == glslang::EOpSubBorrow || op == glslang::EOpUMulExtended ||
                          op == glslang::EOpIMulExtended;
    for (size_t i = 0; i < s.size(); ++i) {
      x.push_back(s[i]->getAsTyped());
      if (last_out && i + 1 == s.size())
        v.emplace_back();
      else
        v.push_back(value(x.back()));
    }
    const size_t n = size_t(count(a->getType()));
    const Base b = s.empty() ? Base::Float : base_or_float(x[0]->getType());
    auto per = [&](auto&& f) {
      Val r;
      for (size_t i = 0; i < n; ++i) r.push_back(f(i));
      return r;
    };
    auto arg = [&](int k, size_t i) { return widen(v[size_t(k)], n).at(i); };
    switch (op) {
      case glslang::EOpPow: {
        // The rewrites Mesa's compiler makes for constant operands, then exp2(log2(x) y).
        float ey = 0, ex = 0;
        const bool cy = scalar_constant(x[1], ey), cx = scalar_constant(x[0], ex);
        return per([&](size_t i) {
          const Reg b = arg(0, i), e = arg(1, i);
          if (cy && ey == 2.0f) return f_mul(b, b);
          if (cy && ey == 4.0f) {
            const Reg q = f_mul(b, b);
            return f_mul(q, q);
          }
          if (cy && ey == 1.0f) return b;
          if (cx && ex == 1.0f) return fconst(1.0f);
          if (cx && ex == 2.0f) return mesa_exp2(e);
          return mesa_pow(b, e);
        });
      }
      case glslang::EOpAtan: return per([&](size_t i) { return mesa_atan2(arg(0, i), arg(1, i)); });
      case glslang::EOpMod: return per([&](size_t i) { return emit(Op::FMod, arg(0, i), arg(1, i)); });
      case glslang::EOpMin:
        return per([&](size_t i) {
          return emit(b == Base::Float  ? Op::FMin
                      : b == Base::Uint ? Op::UMin
                                        : Op::IMin,
                      arg(0, i), arg(1, i));
        });
      case glslang::EOpMax:
        return per([&](size_t i) {
          return emit(b == Base::Float  ? Op::FMax
                      : b == Base::Uint ? Op::UMax
                                        : Op::IMax,
                      arg(0, i), arg(1, i));
        });
      case glslang::EOpClamp:
        return per([&](size_t i) {
          const Op mx = b == Base::Float ? Op::FMax : b == Base::Uint ? Op::UMax : Op::IMax;
          const Op mn = b == Base::Float ? Op::FMin : b == Base::Uint ? Op::UMin : Op::IMin;
          return emit(mn, emit(mx, arg(0, i), arg(1, i)), arg(2, i));
        });
      case glslang::EOpMix: {
        if (base_or_float(x[2]->getType()) == Base::Bool)
          return per([&](size_t i) { return emit(Op::Select, arg(2, i), arg(1, i), arg(0, i)); });
        // x + a * (y - x), rounded after each step, as llvmpipe computes it; x (1 - a) + y a
        // when a is a constant (Mesa's flrp lowering picks the exact form there).
        float ca = 0;
        if (scalar_constant(x[2], ca))
          return per([&](size_t i) {
            return f_add(f_mul(arg(0, i), f_sub(fconst(1.0f), arg(2, i))), f_mul(arg(1, i), arg(2, i)));
          });
        return per([&](size_t i) { return mad(arg(2, i), emit(Op::FSub, arg(1, i), arg(0, i)), arg(0, i)); });
      }
      case glslang::EOpStep:
        return per(
            [&](size_t i) { return emit(Op::And, emit(Op::FGe, arg(1, i), arg(0, i)), fconst(1.0f)); });
      case glslang::EOpSmoothStep:
        return per([&](size_t i) {
          Reg t = emit(Op::FDiv, emit(Op::FSub, arg(2, i), arg(0, i)), emit(Op::FSub, arg(1, i), arg(0, i)));
          t = minps(maxps(t, fconst(0.0f)), fconst(1.0f));
          // t (t (3 - 2 t)), as llvmpipe orders it
          return f_mul(t, f_mul(t, f_sub(fconst(3.0f), f_mul(fconst(2.0f), t))));
        });
      // llvmpipe does not fuse GLSL's fma() (NIR lowers it to a * b + c).
      case glslang::EOpFma: return per([&](size_t i) { return mad(arg(0, i), arg(1, i), arg(2, i)); });
      case glslang::EOpLdexp: return per([&](size_t i) { return emit(Op::FLdexp, arg(0, i), arg(1, i)); });
      case glslang::EOpModf: {
        const Place p = place(x[1]);
        Val whole, fr;
        for (size_t i = 0; i < n; ++i) {
          const Reg w = emit(Op::FTrunc, arg(0, i));
          whole.push_back(w);
          fr.push_back(emit(Op::FSub, arg(0, i), w));
        }
        write(p, whole, a);
        return fr;
      }
      case glslang::EOpFrexp: {
        const Place p = place(x[1]);
        Val e, m;
        for (size_t i = 0; i < n; ++i) {
          e.push_back(emit(Op::FFrexpExp, arg(0, i)));
          m.push_back(emit(Op::FFrexpMant, arg(0, i)));
        }
        write(p, e, a);
        return m;
      }
      case glslang::EOpDistance: {
        Val d;
        for (size_t i = 0; i < v[0].size(); ++i) d.push_back(emit(Op::FSub, v[0][i], v[1][i]));
        if (d.size() == 1) return {emit(Op::FAbs, d[0])};
        return {length(d)};
      }
      case glslang::EOpDot: return {v[0].size() == 1 ? emit(Op::FMul, v[0][0], v[1][0]) : dot(v[0], v[1])};
      case glslang::EOpCross: {
        const Val& p = v[0];
        const Val& q = v[1];
        return {emit(Op::FSub, emit(Op::FMul, p[1], q[2]), emit(Op::FMul, q[1], p[2])),
                emit(Op::FSub, emit(Op::FMul, p[2], q[0]), emit(Op::FMul, q[2], p[0])),
                emit(Op::FSub, emit(Op::FMul, p[0], q[1]), emit(Op::FMul, q[0], p[1]))};
      }
      case glslang::EOpFaceForward: {
        // dot(Nref, I) < 0 ? N : -N
        const Reg d = v[2].size() == 1 ? emit(Op::FMul, v[2][0], v[1][0]) : dot(v[2], v[1]);
        const Reg m = emit(Op::FLt, d, fconst(0.0f));
        return per([&](size_t i) { return emit(Op::Select, m, v[0][i], emit(Op::FNeg, v[0][i])); });
      }
      case glslang::EOpReflect: {
        // I - 2 dot(N, I) N
        const Reg d = v[1].size() == 1 ? emit(Op::FMul, v[1][0], v[0][0]) : dot(v[1], v[0]);
        const Reg d2 = emit(Op::FMul, d, fconst(2.0f));
        return per([&](size_t i) { return emit(Op::FSub, v[0][i], emit(Op::FMul, d2, v[1][i])); });
      }
      case glslang::EOpRefract: {
        // k = 1 - eta^2 (1 - dot(N,I)^2); k < 0 ? 0 : eta I - (eta dot(N,I) + sqrt(k)) N
        const Reg eta = v[2][0];
        const Reg d = v[1].size() == 1 ? emit(Op::FMul, v[1][0], v[0][0]) : dot(v[1], v[0]);
        // k = 1 - eta (eta (1 - d d))
        const Reg k = f_sub(fconst(1.0f), f_mul(eta, f_mul(eta, f_sub(fconst(1.0f), f_mul(d, d)))));
        const Reg neg = emit(Op::FLt, k, fconst(0.0f));
        const Reg s = emit(Op::FAdd, emit(Op::FMul, eta, d), emit(Op::FSqrt, k));
        return per([&](size_t i) {
          const Reg r = emit(Op::FSub, emit(Op::FMul, eta, v[0][i]), emit(Op::FMul, s, v[1][i]));
          return emit(Op::Select, neg, fconst(0.0f), r);
        });
      }
      case glslang::EOpOuterProduct: {
        Val r;
        for (size_t c = 0; c < v[1].size(); ++c)
          for (size_t row = 0; row < v[0].size(); ++row) r.push_back(emit(Op::FMul, v[0][row], v[1][c]));
        return r;
      }
      case glslang::EOpMul:  // matrixCompMult
        return per([&](size_t i) { return emit(Op::FMul, arg(0, i), arg(1, i)); });
      case glslang::EOpLessThan:
      case glslang::EOpGreaterThan:
      case glslang::EOpLessThanEqual:
      case glslang::EOpGreaterThanEqual:
      case glslang::EOpVectorEqual:
      case glslang::EOpVectorNotEqual: {
        const Op o = compare_op(op, b);
        return per([&](size_t i) { return emit(o, arg(0, i), arg(1, i)); });
      }
      case glslang::EOpBitfieldExtract:
        return per([&](size_t i) {
          return emit(b == Base::Uint ? Op::UBitExtract : Op::IBitExtract, arg(0, i), v[1][0], v[2][0]);
        });
      case glslang::EOpBitfieldInsert:
        return per([&](size_t i) {
          const Reg r = fresh();
          code().push_back(Inst{Op::BitInsert, r, arg(0, i), arg(1, i), v[2][0], v[3][0], 0});
          return r;
        });
      case glslang::EOpAddCarry:
      case glslang::EOpSubBorrow: {
        const Place p = place(x[2]);
        Val carry, r;
        for (size_t i = 0; i < n; ++i) {
          r.push_back(emit(op == glslang::EOpAddCarry ? Op::IAdd : Op::ISub, arg(0, i), arg(1, i)));
          carry.push_back(
              emit(op == glslang::EOpAddCarry ? Op::UAddCarry : Op::USubBorrow, arg(0, i), arg(1, i)));
        }
        write(p, carry, a);
        return r;
      }
      case glslang::EOpUMulExtended:
      case glslang::EOpIMulExtended: fail(a, "umulExtended/imulExtended are not supported");
      case glslang::EOpFtransform: fail(a, "ftransform() is only in compatibility vertex shaders");
      default: break;
    }
    fail(a, "built-in function '" + std::string(a->getName().c_str()) + "' (" + std::to_string(int(op)) +
                ") is not supported");
  }

  // Whether n is a constant whose components are all one float value.
  static bool scalar_constant(TIntermTyped* n, float& out) {
    TIntermConstantUnion* c = n ? n->getAsConstantUnion() : nullptr;
    if (!c || c->getType().getBasicType() != glslang::EbtFloat) return false;
    const auto& arr = c->getConstArray();
    if (arr.size() < 1) return false;
    out = float(arr[0].getDConst());
    for (int i = 1; i < arr.size(); ++i)
      if (float(arr[i].getDConst()) != out) return false;
    return true;
  }

#include "lower_math.inc"

  // --- textures -------------------------------------------------------------------------
  Val texture(TIntermAggregate* a);

  // --- statements -----------------------------------------------------------------------
  void statement(TIntermNode* n) {
    if (!n) return;
    if (TIntermAggregate* a = n->getAsAggregate()) {
      if (a->getOp() == glslang::EOpSequence || a->getOp() == glslang::EOpScope) {
        for (TIntermNode* c : a->getSequence()) statement(c);
        return;
      }
    }
    if (TIntermSelection* s = n->getAsSelectionNode()) {
      if (s->getType().getBasicType() == glslang::EbtVoid) {
        const Val c = value(s->getCondition());
        Node node;
        node.kind = Kind::If;
        node.cond = c[0];
        blocks_.push_back(&node.a);
        statement(s->getTrueBlock());
        blocks_.pop_back();
        blocks_.push_back(&node.b);
        statement(s->getFalseBlock());
        blocks_.pop_back();
        blocks_.back()->push_back(std::move(node));
        return;
      }
    }
    if (TIntermLoop* l = n->getAsLoopNode()) {
      Node node;
      node.kind = Kind::Loop;
      auto break_unless = [&](TIntermTyped* test) {
        const Val c = value(test);
        Node brk;
        brk.kind = Kind::If;
        brk.cond = emit(Op::Not, c[0]);
        Node b;
        b.kind = Kind::Break;
        brk.a.push_back(std::move(b));
        blocks_.back()->push_back(std::move(brk));
      };
      blocks_.push_back(&node.a);
      if (l->testFirst() && l->getTest()) break_unless(l->getTest());
      statement(l->getBody());
      blocks_.pop_back();
      blocks_.push_back(&node.b);
      if (l->getTerminal()) (void)value(l->getTerminal());
      if (!l->testFirst() && l->getTest()) break_unless(l->getTest());
      blocks_.pop_back();
      blocks_.back()->push_back(std::move(node));
      return;
    }
    if (TIntermBranch* b = n->getAsBranchNode()) {
      Node node;
      switch (b->getFlowOp()) {
        case glslang::EOpKill:
        case glslang::EOpTerminateInvocation:
        case glslang::EOpDemote:
          node.kind = Kind::Discard;
          out_.ir.discards = true;
          break;
        case glslang::EOpBreak: node.kind = Kind::Break; break;
        case glslang::EOpContinue: node.kind = Kind::Continue; break;
        case glslang::EOpReturn:
          if (b->getExpression() && !frames_.empty() && !frames_.back().ret.empty()) {
            const Val v = value(b->getExpression());
            write(var_place(frames_.back().ret[0], int(frames_.back().ret.size())), v, b);
          }
          node.kind = Kind::Return;
          break;
        default: fail(b, "statement not supported");
      }
      blocks_.back()->push_back(std::move(node));
      return;
    }
    if (TIntermSwitch* sw = n->getAsSwitchNode()) {
      switch_statement(sw);
      return;
    }
    if (TIntermTyped* t = n->getAsTyped()) {
      (void)value(t);
      return;
    }
    if (TIntermAggregate* a = n->getAsAggregate()) {
      for (TIntermNode* c : a->getSequence()) statement(c);
      return;
    }
  }

  // switch: the lanes whose selector matched a label so far (`taken`) run the statements
  // after it, falling through as C does; `default` takes the lanes that match no label.
  void switch_statement(TIntermSwitch* sw) {
    const Val sel = value(sw->getCondition()->getAsTyped());
    const TIntermSequence& body = sw->getBody()->getSequence();
    Reg none_match = kNone;
    for (TIntermNode* c : body) {
      TIntermBranch* b = c->getAsBranchNode();
      if (b && b->getFlowOp() == glslang::EOpCase) {
        const Val v = value(b->getExpression());
        const Reg m = emit(Op::IEq, sel[0], v[0]);
        none_match = none_match == kNone ? emit(Op::Not, m) : emit(Op::And, none_match, emit(Op::Not, m));
      }
    }
    if (none_match == kNone) none_match = iconst(-1);
    const Reg taken = fresh();
    out_.ir.variables.push_back({taken, 1});
    emit_to(Op::Store, taken, iconst(0));
    Node node;
    node.kind = Kind::Switch;
    blocks_.push_back(&node.a);
    std::vector<TIntermNode*> pending;
    auto flush = [&]() {
      if (pending.empty()) return;
      Node ifn;
      ifn.kind = Kind::If;
      ifn.cond = emit(Op::Mov, taken);
      blocks_.push_back(&ifn.a);
      for (TIntermNode* s : pending) statement(s);
      blocks_.pop_back();
      blocks_.back()->push_back(std::move(ifn));
      pending.clear();
    };
    for (TIntermNode* c : body) {
      TIntermBranch* b = c->getAsBranchNode();
      if (b && (b->getFlowOp() == glslang::EOpCase || b->getFlowOp() == glslang::EOpDefault)) {
        flush();
        Reg m;
        if (b->getFlowOp() == glslang::EOpCase)
          m = emit(Op::IEq, sel[0], value(b->getExpression())[0]);
        else
          m = none_match;
        emit_to(Op::Store, taken, emit(Op::Or, taken, m));
        continue;
      }
      pending.push_back(c);
    }
    flush();
    blocks_.pop_back();
    blocks_.back()->push_back(std::move(node));
  }
};

#include "lower_texture.inc"

}  // namespace

LoweredStage lower_stage(const glslang::TIntermediate& stage, int which, UniformLayout& uniforms) {
  Lowerer l(stage, which, uniforms);
  return l.run();
}

}  // namespace tessel::glsl
