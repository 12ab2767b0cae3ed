// The IR compiled to native code with LLVM (jit.hpp).
//
// Each IR register is a stack slot of <16 x i32> that LLVM's mem2reg turns into SSA values;
// registers of a variable indexed at run time share one array so that lanes can address
// them. Structured control flow becomes branches on "any lane": an `if` skips an arm no lane
// takes, a loop runs while a lane is in it (at most ir::kMaxLoopIterations times), and the
// masks (return, break, continue, discard) are slots too, exactly as the interpreter keeps
// them, so both tiers compute the same lanes.
#include "jit.hpp"

#include <llvm/Config/llvm-config.h>
#include <llvm/ExecutionEngine/Orc/ExecutionUtils.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/ExecutionEngine/Orc/ObjectTransformLayer.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Intrinsics.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>
#include <llvm/IR/Verifier.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Support/Host.h>
#include <llvm/Support/MemoryBuffer.h>
#include <llvm/Support/TargetSelect.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

namespace tessel::glsl {
namespace {

using ir::Inst;
using ir::Op;
using ir::Reg;
constexpr int L = ir::kLanes;  // lanes of the lane structures and of the library calls

// The compiled code names a texture instruction by its index (no address of this process is
// baked into it, so that it can be cached on disk and loaded by another process).
extern "C" void tessel_glsl_texture(uint32_t op, const RunInputs* in, TexLanes* lanes) {
  run_texture(in->textures[op], *in, *lanes);
}
// The common 2D lookup (texture_2d_implicit) of one lane structure, or of two at once (the
// 32-lane fragment function): only the coordinate rows are set.
extern "C" void tessel_glsl_texture_2d(uint32_t op, const RunInputs* in, TexLanes* lanes) {
  run_texture_2d_implicit(in->textures[op], *in, *lanes);
}
extern "C" void tessel_glsl_texture_2d_pair(uint32_t op, const RunInputs* in, TexLanes* a, TexLanes* b) {
  run_texture_2d_implicit_pair(in->textures[op], *in, *a, *b);
}
extern "C" void tessel_glsl_lane_math(uint32_t op, uint32_t* t, const uint32_t* a, const uint32_t* b,
                                      const uint32_t* c, const uint32_t* e) {
  lane_math(ir::Op(op), t, a, b, c, e);
}

void init_llvm() {
  static std::once_flag once;
  std::call_once(once, [] {
    llvm::InitializeNativeTarget();
    llvm::InitializeNativeTargetAsmPrinter();
  });
}

// Generates one stage as a function over W lanes: W = 16 (StageFn) reads and writes one lane
// structure; W = 32 (PairFn) runs two lane structures as one 32-lane vector, so that the two
// halves' long dependency chains (square roots, divisions, polynomials) interleave. The
// operations are the same per lane, so the lanes get the same bits either way; the library
// calls (texture, lane_math) take sixteen lanes and are made once per half.
class Codegen {
 public:
  Codegen(llvm::LLVMContext& ctx, llvm::Module& m, const ir::Stage& st, const StageIO& io, int width = L)
      : c_(ctx), m_(m), st_(st), io_(io), b_(ctx), W(width) {
    i32_ = b_.getInt32Ty();
    f32_ = b_.getFloatTy();
    vi_ = llvm::FixedVectorType::get(i32_, W);
    vf_ = llvm::FixedVectorType::get(f32_, W);
    vm_ = llvm::FixedVectorType::get(b_.getInt1Ty(), W);
    vi16_ = llvm::FixedVectorType::get(i32_, L);
    ptr_ = llvm::PointerType::getUnqual(ctx);
    iw_ = b_.getIntNTy(unsigned(W));
  }

  llvm::Function* build(const std::string& name) {
    // StageFn (lanes, uniforms, words, inputs, mask) or PairFn (lanes, lanes_b, uniforms,
    // words, inputs).
    llvm::FunctionType* fty = W == L ? llvm::FunctionType::get(i32_, {ptr_, ptr_, i32_, ptr_, i32_}, false)
                                     : llvm::FunctionType::get(i32_, {ptr_, ptr_, ptr_, i32_, ptr_}, false);
    fn_ = llvm::Function::Create(fty, llvm::Function::ExternalLinkage, name, m_);
    fragment_ = name.rfind("fragment", 0) == 0;
    // The code runs with denormals flushed (program.cpp): LLVM must not fold as if not.
    fn_->addFnAttr("denormal-fp-math", "preserve-sign,preserve-sign");
    auto args = fn_->arg_begin();
    lanes_ = &*args++;
    if (W != L) lanes_b_ = &*args++;
    uniforms_ = &*args++;
    words_ = &*args++;
    rin_ = &*args++;
    entry_ = llvm::BasicBlock::Create(c_, "entry", fn_);
    b_.SetInsertPoint(entry_);
    plan_registers();
    // Constants, uniforms (broadcast), variables zeroed, inputs copied in.
    for (const auto& [r, bits] : st_.constants) store(r, splat(bits));
    for (const auto& [r, w] : st_.uniforms) store(r, b_.CreateVectorSplat(W, uniform_word(b_.getInt32(w))));
    for (const auto& [r, n] : st_.variables)
      for (uint32_t k = 0; k < n; ++k) store(r + k, llvm::Constant::getNullValue(vi_));
    for (const auto& [r, off] : io_.in) store(r, load_row(off));
    for (const auto& [r, off] : io_.in_mask) {
      llvm::Value* bits = b_.CreateLoad(i32_, byte_ptr(lanes_, off));
      if (W != L) {
        // Sixteen bits from each structure: lanes 0-15 from the first, 16-31 from the second.
        llvm::Value* hi = b_.CreateLoad(i32_, byte_ptr(lanes_b_, off));
        bits = b_.CreateOr(b_.CreateAnd(bits, b_.getInt32(0xFFFF)), b_.CreateShl(hi, b_.getInt32(16)));
      }
      store(r, b_.CreateSExt(to_mask(bits), vi_));
    }
    for (int h = 0; h < W / L; ++h) {
      budget_[h] = slot(i32_, "budget");
      b_.CreateStore(b_.getInt32(0), budget_[h]);
    }
    ret_ = slot(vm_, "ret");
    brk_ = slot(vm_, "brk");
    cont_ = slot(vm_, "cont");
    kill_ = slot(vm_, "kill");
    for (llvm::Value* s : {ret_, brk_, cont_, kill_}) b_.CreateStore(llvm::Constant::getNullValue(vm_), s);
    // The pipeline always runs all the lanes (the ones it does not need are helpers for
    // derivatives or repeat a vertex): with the entry mask a constant, LLVM drops the selects
    // of stores outside control flow.
    block(st_.body, llvm::Constant::getAllOnesValue(vm_));
    for (const auto& [r, off] : io_.out) store_row(off, load(r));
    llvm::Value* killed = b_.CreateBitCast(b_.CreateLoad(vm_, kill_), iw_);
    b_.CreateRet(W == 32 ? killed : b_.CreateZExt(killed, i32_));
    return fn_;
  }

 private:
  llvm::LLVMContext& c_;
  llvm::Module& m_;
  const ir::Stage& st_;
  const StageIO& io_;
  llvm::IRBuilder<> b_;
  const int W;  // lanes of every value
  llvm::Type *i32_, *f32_, *ptr_, *iw_;
  llvm::FixedVectorType *vi_, *vf_, *vm_, *vi16_;
  llvm::Function* fn_ = nullptr;
  llvm::BasicBlock* entry_ = nullptr;
  llvm::Value *lanes_, *uniforms_, *words_, *rin_;
  llvm::Value* lanes_b_ = nullptr;  // the second lane structure (W = 32)
  llvm::Value *ret_, *brk_, *cont_, *kill_;
  llvm::Value* budget_[2] = {};  // loop iterations run so far per half (ir::kMaxTotalLoopIterations)
  // Where each register lives: its own slot, or an element of an indexed array.
  struct Home {
    llvm::Value* base = nullptr;  // alloca
    uint32_t index = 0;           // element within an array (0 for a single slot)
    uint32_t first = 0;           // first register of the array
    bool array = false;
  };
  std::vector<Home> homes_;
  llvm::Value* tex_lanes_ = nullptr;
  llvm::Value* tex_lanes_b_ = nullptr;  // the second half's (W = 32)
  bool fragment_ = false;               // the fragment stage (implicit LODs)
  llvm::Value* math_lanes_ = nullptr;

  llvm::Value* slot(llvm::Type* t, const char* name, llvm::Value* count = nullptr) {
    llvm::IRBuilder<> eb(entry_, entry_->begin());
    return eb.CreateAlloca(t, count, name);
  }
  llvm::Value* byte_ptr(llvm::Value* base, uint64_t off) {
    return b_.CreateGEP(b_.getInt8Ty(), base, b_.getInt64(off));
  }
  llvm::Value* splat(uint32_t bits) {
    return llvm::ConstantVector::getSplat(llvm::ElementCount::getFixed(W), b_.getInt32(bits));
  }
  llvm::Value* splatf(float x) {
    return llvm::ConstantVector::getSplat(llvm::ElementCount::getFixed(W), llvm::ConstantFP::get(f32_, x));
  }
  llvm::Value* to_mask(llvm::Value* bits32) {
    if (W == 32) return b_.CreateBitCast(bits32, vm_);
    return b_.CreateBitCast(b_.CreateTrunc(bits32, b_.getInt16Ty()), vm_);
  }
  llvm::Value* any(llvm::Value* m) {
    return b_.CreateICmpNE(b_.CreateBitCast(m, iw_), llvm::ConstantInt::get(iw_, 0));
  }
  // Sixteen lanes of a W-lane value (half h), and a W-lane value from sixteen-lane halves.
  llvm::Value* half(llvm::Value* v, int h) {
    if (W == L) return v;
    llvm::SmallVector<int, 16> idx;
    for (int l = 0; l < L; ++l) idx.push_back(h * L + l);
    return b_.CreateShuffleVector(v, idx);
  }
  llvm::Value* any_half(llvm::Value* m, int h) {
    return b_.CreateICmpNE(b_.CreateBitCast(half(m, h), b_.getInt16Ty()), b_.getInt16(0));
  }
  llvm::Value* join(llvm::Value* lo, llvm::Value* hi) {
    llvm::SmallVector<int, 32> idx;
    for (int l = 0; l < 2 * L; ++l) idx.push_back(l);
    return b_.CreateShuffleVector(lo, hi, idx);
  }
  // A row of the lane structure(s) at byte offset `off`, and a store of one.
  llvm::Value* load_row(uint32_t off) {
    llvm::Value* a = b_.CreateAlignedLoad(vi16_, byte_ptr(lanes_, off), llvm::MaybeAlign(4));
    if (W == L) return a;
    return join(a, b_.CreateAlignedLoad(vi16_, byte_ptr(lanes_b_, off), llvm::MaybeAlign(4)));
  }
  void store_row(uint32_t off, llvm::Value* v) {
    b_.CreateAlignedStore(half(v, 0), byte_ptr(lanes_, off), llvm::MaybeAlign(4));
    if (W != L) b_.CreateAlignedStore(half(v, 1), byte_ptr(lanes_b_, off), llvm::MaybeAlign(4));
  }

  // Registers read by LoadIndexed or written by StoreIndexed are grouped into arrays: the
  // range [b, last] of each such access joins the array of its variable.
  void plan_registers() {
    homes_.assign(st_.registers, Home{});
    std::vector<std::pair<uint32_t, uint32_t>> ranges;
    std::function<void(const ir::Block&)> scan = [&](const ir::Block& bl) {
      for (const ir::Node& n : bl) {
        for (const Inst& i : n.code) {
          if (i.op == Op::LoadIndexed) ranges.push_back({i.b, i.imm});
          if (i.op == Op::StoreIndexed) ranges.push_back({i.dst, i.imm});
        }
        scan(n.a);
        scan(n.b);
      }
    };
    scan(st_.body);
    // Widen each range to the whole variable it lies in.
    for (auto& [lo, hi] : ranges)
      for (const auto& [r, n] : st_.variables)
        if (lo >= r && lo < r + n) lo = std::min(lo, r), hi = std::max(hi, r + n - 1);
    std::sort(ranges.begin(), ranges.end());
    std::vector<std::pair<uint32_t, uint32_t>> merged;
    for (auto rg : ranges) {
      if (!merged.empty() && rg.first <= merged.back().second)
        merged.back().second = std::max(merged.back().second, rg.second);
      else
        merged.push_back(rg);
    }
    for (auto [lo, hi] : merged) {
      llvm::Value* arr = slot(vi_, "arr", b_.getInt32(hi - lo + 1));
      for (uint32_t r = lo; r <= hi && r < st_.registers; ++r) homes_[r] = {arr, r - lo, lo, true};
    }
  }

  // Uniform word w, clamped to the last word as the interpreter clamps it (a clamped offset
  // cannot make imm + offset wrap past 2^32).
  llvm::Value* uniform_word(llvm::Value* w) {
    w = b_.CreateSelect(b_.CreateICmpULT(w, words_), w, b_.CreateSub(words_, b_.getInt32(1)));
    return b_.CreateLoad(i32_, b_.CreateGEP(i32_, uniforms_, w));
  }

  // The lanes of `live` still in a loop: not returned, broken out or discarded.
  llvm::Value* in_loop(llvm::Value* live) {
    llvm::Value* out = b_.CreateOr(b_.CreateOr(b_.CreateLoad(vm_, ret_), b_.CreateLoad(vm_, brk_)),
                                   b_.CreateLoad(vm_, kill_));
    return b_.CreateAnd(live, b_.CreateNot(out));
  }

  llvm::Value* home_ptr(Reg r) {
    Home& h = homes_.at(r);
    if (!h.base) h.base = slot(vi_, "r");
    if (!h.array) return h.base;
    return b_.CreateGEP(vi_, h.base, b_.getInt32(h.index));
  }
  llvm::Value* load(Reg r) { return b_.CreateLoad(vi_, home_ptr(r)); }
  void store(Reg r, llvm::Value* v) {
    if (v->getType() != vi_) v = b_.CreateBitCast(v, vi_);
    b_.CreateStore(v, home_ptr(r));
  }
  llvm::Value* loadf(Reg r) { return b_.CreateBitCast(load(r), vf_); }
  llvm::Value* mask_of(Reg r) { return b_.CreateICmpSLT(load(r), llvm::Constant::getNullValue(vi_)); }
  llvm::Value* sext(llvm::Value* m) { return b_.CreateSExt(m, vi_); }

  llvm::Value* intrinsic(llvm::Intrinsic::ID id, llvm::ArrayRef<llvm::Value*> args) {
    llvm::Function* f = llvm::Intrinsic::getDeclaration(&m_, id, {args[0]->getType()});
    return b_.CreateCall(f, args);
  }

  // The current live lanes: mask less those that returned, broke, continued or were discarded.
  llvm::Value* live_of(llvm::Value* mask) {
    llvm::Value* out = b_.CreateOr(b_.CreateOr(b_.CreateLoad(vm_, ret_), b_.CreateLoad(vm_, brk_)),
                                   b_.CreateOr(b_.CreateLoad(vm_, cont_), b_.CreateLoad(vm_, kill_)));
    return b_.CreateAnd(mask, b_.CreateNot(out));
  }

  void block(const ir::Block& bl, llvm::Value* mask) {
    llvm::BasicBlock* end = nullptr;
    for (size_t k = 0; k < bl.size(); ++k) {
      const ir::Node& n = bl[k];
      llvm::Value* live = live_of(mask);
      if (k > 0 && bl[k - 1].kind != ir::Node::Kind::Code) {
        // After a construct that may have cleared lanes, skip the rest when none is left.
        if (!end) end = llvm::BasicBlock::Create(c_, "end", fn_);
        llvm::BasicBlock* go = llvm::BasicBlock::Create(c_, "go", fn_);
        b_.CreateCondBr(any(live), go, end);
        b_.SetInsertPoint(go);
      }
      node(n, live);
    }
    if (end) {
      b_.CreateBr(end);
      b_.SetInsertPoint(end);
    }
  }

  void node(const ir::Node& n, llvm::Value* live) {
    using K = ir::Node::Kind;
    switch (n.kind) {
      case K::Code:
        for (const Inst& i : n.code) inst(i, live);
        break;
      case K::If: {
        llvm::Value* c = b_.CreateAnd(mask_of(n.cond), live);
        llvm::BasicBlock* then_bb = llvm::BasicBlock::Create(c_, "then", fn_);
        llvm::BasicBlock* else_check = llvm::BasicBlock::Create(c_, "elsecheck", fn_);
        b_.CreateCondBr(any(c), then_bb, else_check);
        b_.SetInsertPoint(then_bb);
        block(n.a, c);
        b_.CreateBr(else_check);
        b_.SetInsertPoint(else_check);
        if (!n.b.empty()) {
          llvm::Value* e = b_.CreateAnd(live, b_.CreateNot(c));
          llvm::BasicBlock* else_bb = llvm::BasicBlock::Create(c_, "else", fn_);
          llvm::BasicBlock* merge = llvm::BasicBlock::Create(c_, "merge", fn_);
          b_.CreateCondBr(any(e), else_bb, merge);
          b_.SetInsertPoint(else_bb);
          block(n.b, e);
          b_.CreateBr(merge);
          b_.SetInsertPoint(merge);
        }
        break;
      }
      case K::Loop: {
        llvm::Value* saved_brk = b_.CreateLoad(vm_, brk_);
        llvm::Value* saved_cont = b_.CreateLoad(vm_, cont_);
        b_.CreateStore(llvm::Constant::getNullValue(vm_), brk_);
        // Iterations are counted per half (W = 32): each half is cut where it would be cut
        // running alone, so both widths give the same lanes.
        const int H = W / L;
        llvm::Value* iter[2] = {};
        for (int h = 0; h < H; ++h) {
          iter[h] = slot(i32_, "iter");
          b_.CreateStore(b_.getInt32(0), iter[h]);
        }
        llvm::BasicBlock* head = llvm::BasicBlock::Create(c_, "loop", fn_);
        llvm::BasicBlock* body = llvm::BasicBlock::Create(c_, "body", fn_);
        llvm::BasicBlock* step = llvm::BasicBlock::Create(c_, "step", fn_);
        llvm::BasicBlock* step_run = llvm::BasicBlock::Create(c_, "steprun", fn_);
        llvm::BasicBlock* exit = llvm::BasicBlock::Create(c_, "exit", fn_);
        b_.CreateBr(head);
        b_.SetInsertPoint(head);
        b_.CreateStore(llvm::Constant::getNullValue(vm_), cont_);
        llvm::Value* more[2] = {};
        for (int h = 0; h < H; ++h)
          more[h] = b_.CreateAnd(
              b_.CreateICmpSLT(b_.CreateLoad(i32_, iter[h]), b_.getInt32(ir::kMaxLoopIterations)),
              b_.CreateICmpULT(b_.CreateLoad(i32_, budget_[h]), b_.getInt32(ir::kMaxTotalLoopIterations)));
        llvm::Value* allow = H == 1
                                 ? b_.CreateVectorSplat(W, more[0])
                                 : join(b_.CreateVectorSplat(L, more[0]), b_.CreateVectorSplat(L, more[1]));
        llvm::Value* in = b_.CreateAnd(in_loop(live), allow);
        b_.CreateCondBr(any(in), body, exit);
        b_.SetInsertPoint(body);
        block(n.a, in);
        b_.CreateBr(step);
        b_.SetInsertPoint(step);
        b_.CreateStore(llvm::Constant::getNullValue(vm_), cont_);
        llvm::Value* in2 = b_.CreateAnd(in_loop(live), allow);
        b_.CreateCondBr(any(in2), step_run, exit);
        b_.SetInsertPoint(step_run);
        block(n.b, in2);
        for (int h = 0; h < H; ++h) {
          // A half counts the iterations it takes part in.
          llvm::Value* inc = H == 1 ? b_.getInt32(1) : b_.CreateZExt(any_half(in2, h), i32_);
          b_.CreateStore(b_.CreateAdd(b_.CreateLoad(i32_, iter[h]), inc), iter[h]);
          b_.CreateStore(b_.CreateAdd(b_.CreateLoad(i32_, budget_[h]), inc), budget_[h]);
        }
        b_.CreateBr(head);
        b_.SetInsertPoint(exit);
        b_.CreateStore(saved_brk, brk_);
        b_.CreateStore(saved_cont, cont_);
        break;
      }
      case K::Break: b_.CreateStore(b_.CreateOr(b_.CreateLoad(vm_, brk_), live), brk_); break;
      case K::Continue: b_.CreateStore(b_.CreateOr(b_.CreateLoad(vm_, cont_), live), cont_); break;
      case K::Return: b_.CreateStore(b_.CreateOr(b_.CreateLoad(vm_, ret_), live), ret_); break;
      case K::Discard: b_.CreateStore(b_.CreateOr(b_.CreateLoad(vm_, kill_), live), kill_); break;
      case K::Function: {
        llvm::Value* saved = b_.CreateLoad(vm_, ret_);
        block(n.a, live);
        b_.CreateStore(saved, ret_);
        break;
      }
      case K::Switch: {
        llvm::Value* saved = b_.CreateLoad(vm_, brk_);
        b_.CreateStore(llvm::Constant::getNullValue(vm_), brk_);
        block(n.a, live);
        b_.CreateStore(saved, brk_);
        break;
      }
    }
  }

  // A library operation through the interpreter's own code (lane_math).
  void call_math(const Inst& i) {
    if (!math_lanes_) math_lanes_ = slot(llvm::ArrayType::get(vi16_, 5), "math");
    auto row = [&](int k) {
      return b_.CreateGEP(llvm::ArrayType::get(vi16_, 5), math_lanes_, {b_.getInt32(0), b_.getInt32(k)});
    };
    auto* fty = llvm::FunctionType::get(b_.getVoidTy(), {i32_, ptr_, ptr_, ptr_, ptr_, ptr_}, false);
    llvm::FunctionCallee f = m_.getOrInsertFunction("tessel_glsl_lane_math", fty);
    llvm::Value* out[2] = {nullptr, nullptr};
    for (int h = 0; h < W / L; ++h) {
      b_.CreateStore(half(load(i.a), h), row(1));
      b_.CreateStore(half(load(i.b), h), row(2));
      b_.CreateStore(half(load(i.c), h), row(3));
      b_.CreateStore(half(load(i.d), h), row(4));
      b_.CreateCall(f, {b_.getInt32(uint32_t(i.op)), row(0), row(1), row(2), row(3), row(4)});
      out[h] = b_.CreateLoad(vi16_, row(0));
    }
    store(i.dst, W == L ? out[0] : join(out[0], out[1]));
  }

  void texture(const Inst& i) {
    const ir::TexOp& t = st_.textures.at(i.imm);
    auto* tl_ty = llvm::ArrayType::get(vi16_, TexLanes::kRows + 4);
    if (!tex_lanes_) tex_lanes_ = slot(tl_ty, "tex");
    if (fragment_ && texture_2d_implicit(t)) {
      // The common lookup: two coordinate rows in, four result rows out, both halves in one
      // call.
      if (W != L && !tex_lanes_b_) tex_lanes_b_ = slot(tl_ty, "texb");
      llvm::Value* tl[2] = {tex_lanes_, tex_lanes_b_};
      auto row = [&](int h, int k) { return b_.CreateGEP(tl_ty, tl[h], {b_.getInt32(0), b_.getInt32(k)}); };
      for (int h = 0; h < W / L; ++h)
        for (int k = 0; k < 2; ++k) b_.CreateStore(half(load(t.coord[k]), h), row(h, TexLanes::kCoord + k));
      if (W == L) {
        auto* fty = llvm::FunctionType::get(b_.getVoidTy(), {i32_, ptr_, ptr_}, false);
        b_.CreateCall(m_.getOrInsertFunction("tessel_glsl_texture_2d", fty),
                      {b_.getInt32(i.imm), rin_, tl[0]});
      } else {
        auto* fty = llvm::FunctionType::get(b_.getVoidTy(), {i32_, ptr_, ptr_, ptr_}, false);
        b_.CreateCall(m_.getOrInsertFunction("tessel_glsl_texture_2d_pair", fty),
                      {b_.getInt32(i.imm), rin_, tl[0], tl[1]});
      }
      for (int k = 0; k < 4; ++k) {
        if (t.dst[k] == ir::TexOp::kNone) continue;
        llvm::Value* lo = b_.CreateLoad(vi16_, row(0, TexLanes::kRows + k));
        store(t.dst[k], W == L ? lo : join(lo, b_.CreateLoad(vi16_, row(1, TexLanes::kRows + k))));
      }
      return;
    }
    auto row = [&](int k) { return b_.CreateGEP(tl_ty, tex_lanes_, {b_.getInt32(0), b_.getInt32(k)}); };
    auto* fty = llvm::FunctionType::get(b_.getVoidTy(), {i32_, ptr_, ptr_}, false);
    llvm::FunctionCallee f = m_.getOrInsertFunction("tessel_glsl_texture", fty);
    llvm::Value* out[4][2] = {};
    for (int h = 0; h < W / L; ++h) {
      auto put = [&](int k, Reg r) {
        b_.CreateStore(r == ir::TexOp::kNone ? llvm::Constant::getNullValue(vi16_) : half(load(r), h),
                       row(k));
      };
      for (int k = 0; k < 5; ++k) put(TexLanes::kCoord + k, t.coord[k]);
      put(TexLanes::kLod, t.lod);
      for (int k = 0; k < 3; ++k) {
        put(TexLanes::kDx + k, t.dx[k]);
        put(TexLanes::kDy + k, t.dy[k]);
        put(TexLanes::kOffset + k, t.offset_reg[k]);
      }
      b_.CreateCall(f, {b_.getInt32(i.imm), rin_, tex_lanes_});
      for (int k = 0; k < 4; ++k)
        if (t.dst[k] != ir::TexOp::kNone) out[k][h] = b_.CreateLoad(vi16_, row(TexLanes::kRows + k));
    }
    for (int k = 0; k < 4; ++k)
      if (t.dst[k] != ir::TexOp::kNone) store(t.dst[k], W == L ? out[k][0] : join(out[k][0], out[k][1]));
  }

  // Lane l of a register that lives in an indexed array, at element `index` (a scalar).
  llvm::Value* lane_ptr(const Home& h, llvm::Value* index, int l) {
    llvm::Value* flat = b_.CreateAdd(b_.CreateMul(index, b_.getInt32(W)), b_.getInt32(l));
    return b_.CreateGEP(i32_, h.base, flat);
  }

  void inst(const Inst& i, llvm::Value* live) {
    auto F = [&](Reg r) { return loadf(r); };
    auto I = [&](Reg r) { return load(r); };
    auto setf = [&](llvm::Value* v) { store(i.dst, v); };
    auto zero = llvm::Constant::getNullValue(vi_);
    switch (i.op) {
      case Op::Mov: store(i.dst, load(i.a)); break;
      case Op::Store: store(i.dst, b_.CreateSelect(live, load(i.a), load(i.dst))); break;
      case Op::UniformIndexed: {
        llvm::Value* a = I(i.a);
        llvm::Value* r = zero;
        for (int l = 0; l < W; ++l) {
          llvm::Value* w = b_.CreateAdd(b_.getInt32(i.imm), b_.CreateExtractElement(a, b_.getInt32(l)));
          r = b_.CreateInsertElement(r, uniform_word(w), b_.getInt32(l));
        }
        store(i.dst, r);
        break;
      }
      case Op::LoadIndexed: {
        const Home& h = homes_.at(i.b);
        llvm::Value* a = I(i.a);
        llvm::Value* r = zero;
        for (int l = 0; l < W; ++l) {
          llvm::Value* e = b_.CreateAdd(b_.getInt32(i.b), b_.CreateExtractElement(a, b_.getInt32(l)));
          e = b_.CreateSelect(b_.CreateICmpULE(e, b_.getInt32(i.imm)), e, b_.getInt32(i.imm));
          e = b_.CreateSub(e, b_.getInt32(h.first));
          r = b_.CreateInsertElement(r, b_.CreateLoad(i32_, lane_ptr(h, e, l)), b_.getInt32(l));
        }
        store(i.dst, r);
        break;
      }
      case Op::StoreIndexed: {
        const Home& h = homes_.at(i.dst);
        llvm::Value* a = I(i.a);
        llvm::Value* v = I(i.b);
        for (int l = 0; l < W; ++l) {
          llvm::Value* e = b_.CreateAdd(b_.getInt32(i.dst), b_.CreateExtractElement(a, b_.getInt32(l)));
          e = b_.CreateSelect(b_.CreateICmpULE(e, b_.getInt32(i.imm)), e, b_.getInt32(i.imm));
          e = b_.CreateSub(e, b_.getInt32(h.first));
          llvm::Value* p = lane_ptr(h, e, l);
          llvm::Value* old = b_.CreateLoad(i32_, p);
          b_.CreateStore(b_.CreateSelect(b_.CreateExtractElement(live, b_.getInt32(l)),
                                         b_.CreateExtractElement(v, b_.getInt32(l)), old),
                         p);
        }
        break;
      }
      case Op::Select: store(i.dst, b_.CreateSelect(mask_of(i.a), I(i.b), I(i.c))); break;
      case Op::FAdd: setf(b_.CreateFAdd(F(i.a), F(i.b))); break;
      case Op::FSub: setf(b_.CreateFSub(F(i.a), F(i.b))); break;
      case Op::FMul: setf(b_.CreateFMul(F(i.a), F(i.b))); break;
      case Op::FDiv: setf(b_.CreateFDiv(F(i.a), F(i.b))); break;
      case Op::FNeg: setf(b_.CreateFNeg(F(i.a))); break;
      case Op::FAbs: setf(intrinsic(llvm::Intrinsic::fabs, {F(i.a)})); break;
      case Op::FSign: {
        llvm::Value* x = F(i.a);
        setf(
            b_.CreateSelect(b_.CreateFCmpOGT(x, splatf(0.0f)), splatf(1.0f),
                            b_.CreateSelect(b_.CreateFCmpOLT(x, splatf(0.0f)), splatf(-1.0f), splatf(0.0f))));
        break;
      }
      case Op::FMin:
      case Op::FMax: {
        // x < y ? x : y (or >), and a NaN operand gives the other one: the interpreter's rule.
        llvm::Value *x = F(i.a), *y = F(i.b);
        llvm::Value* r =
            b_.CreateSelect(i.op == Op::FMin ? b_.CreateFCmpOLT(x, y) : b_.CreateFCmpOGT(x, y), x, y);
        r = b_.CreateSelect(b_.CreateFCmpUNO(x, x), y, r);
        setf(b_.CreateSelect(b_.CreateFCmpUNO(y, y), x, r));
        break;
      }
      case Op::FFma: setf(intrinsic(llvm::Intrinsic::fma, {F(i.a), F(i.b), F(i.c)})); break;
      case Op::FFloor: setf(intrinsic(llvm::Intrinsic::floor, {F(i.a)})); break;
      case Op::FCeil: setf(intrinsic(llvm::Intrinsic::ceil, {F(i.a)})); break;
      case Op::FTrunc: setf(intrinsic(llvm::Intrinsic::trunc, {F(i.a)})); break;
      case Op::FRoundEven: setf(intrinsic(llvm::Intrinsic::nearbyint, {F(i.a)})); break;
      case Op::FFract: {
        llvm::Value* x = F(i.a);
        setf(b_.CreateFSub(x, intrinsic(llvm::Intrinsic::floor, {x})));
        break;
      }
      case Op::FMod: {
        llvm::Value *x = F(i.a), *y = F(i.b);
        setf(b_.CreateFSub(x, b_.CreateFMul(y, intrinsic(llvm::Intrinsic::floor, {b_.CreateFDiv(x, y)}))));
        break;
      }
      case Op::FSqrt: setf(intrinsic(llvm::Intrinsic::sqrt, {F(i.a)})); break;
      case Op::FRsq: setf(b_.CreateFDiv(splatf(1.0f), intrinsic(llvm::Intrinsic::sqrt, {F(i.a)}))); break;
      case Op::FLt: setf(sext(b_.CreateFCmpOLT(F(i.a), F(i.b)))); break;
      case Op::FLe: setf(sext(b_.CreateFCmpOLE(F(i.a), F(i.b)))); break;
      case Op::FGt: setf(sext(b_.CreateFCmpOGT(F(i.a), F(i.b)))); break;
      case Op::FGe: setf(sext(b_.CreateFCmpOGE(F(i.a), F(i.b)))); break;
      case Op::FEq: setf(sext(b_.CreateFCmpOEQ(F(i.a), F(i.b)))); break;
      case Op::FNe: setf(sext(b_.CreateFCmpUNE(F(i.a), F(i.b)))); break;
      case Op::FIsNan: {
        llvm::Value* x = F(i.a);
        setf(sext(b_.CreateFCmpUNO(x, x)));
        break;
      }
      case Op::FIsInf:
        setf(sext(b_.CreateFCmpOEQ(intrinsic(llvm::Intrinsic::fabs, {F(i.a)}), splatf(INFINITY))));
        break;
      case Op::IAdd: setf(b_.CreateAdd(I(i.a), I(i.b))); break;
      case Op::ISub: setf(b_.CreateSub(I(i.a), I(i.b))); break;
      case Op::IMul: setf(b_.CreateMul(I(i.a), I(i.b))); break;
      case Op::IDiv: {
        // A quotient by 0 is 0; dividing by -1 negates (wrapping): no lane can trap.
        llvm::Value *x = I(i.a), *d = I(i.b);
        llvm::Value* z = b_.CreateICmpEQ(d, zero);
        llvm::Value* neg1 = b_.CreateICmpEQ(d, splat(~0u));
        llvm::Value* q = b_.CreateSDiv(x, b_.CreateSelect(b_.CreateOr(z, neg1), splat(1), d));
        setf(b_.CreateSelect(z, zero, b_.CreateSelect(neg1, b_.CreateSub(zero, x), q)));
        break;
      }
      case Op::UDiv:
      case Op::UMod: {
        llvm::Value *x = I(i.a), *d = I(i.b);
        llvm::Value* z = b_.CreateICmpEQ(d, zero);
        llvm::Value* safe = b_.CreateSelect(z, splat(1), d);
        llvm::Value* q = i.op == Op::UDiv ? b_.CreateUDiv(x, safe) : b_.CreateURem(x, safe);
        setf(b_.CreateSelect(z, splat(~0u), q));
        break;
      }
      case Op::INeg: setf(b_.CreateSub(zero, I(i.a))); break;
      case Op::IAbs: {
        llvm::Value* x = I(i.a);
        setf(b_.CreateSelect(b_.CreateICmpSLT(x, zero), b_.CreateSub(zero, x), x));
        break;
      }
      case Op::ISign: {
        llvm::Value* x = I(i.a);
        setf(b_.CreateSelect(b_.CreateICmpSGT(x, zero), splat(1),
                             b_.CreateSelect(b_.CreateICmpSLT(x, zero), splat(~0u), zero)));
        break;
      }
      case Op::IMin: {
        llvm::Value *x = I(i.a), *y = I(i.b);
        setf(b_.CreateSelect(b_.CreateICmpSLT(y, x), y, x));
        break;
      }
      case Op::IMax: {
        llvm::Value *x = I(i.a), *y = I(i.b);
        setf(b_.CreateSelect(b_.CreateICmpSLT(x, y), y, x));
        break;
      }
      case Op::UMin: {
        llvm::Value *x = I(i.a), *y = I(i.b);
        setf(b_.CreateSelect(b_.CreateICmpULT(y, x), y, x));
        break;
      }
      case Op::UMax: {
        llvm::Value *x = I(i.a), *y = I(i.b);
        setf(b_.CreateSelect(b_.CreateICmpULT(x, y), y, x));
        break;
      }
      case Op::And: setf(b_.CreateAnd(I(i.a), I(i.b))); break;
      case Op::Or: setf(b_.CreateOr(I(i.a), I(i.b))); break;
      case Op::Xor: setf(b_.CreateXor(I(i.a), I(i.b))); break;
      case Op::Not: setf(b_.CreateNot(I(i.a))); break;
      case Op::Shl: setf(b_.CreateShl(I(i.a), b_.CreateAnd(I(i.b), splat(31)))); break;
      case Op::ShrA: setf(b_.CreateAShr(I(i.a), b_.CreateAnd(I(i.b), splat(31)))); break;
      case Op::ShrL: setf(b_.CreateLShr(I(i.a), b_.CreateAnd(I(i.b), splat(31)))); break;
      case Op::ILt: setf(sext(b_.CreateICmpSLT(I(i.a), I(i.b)))); break;
      case Op::ILe: setf(sext(b_.CreateICmpSLE(I(i.a), I(i.b)))); break;
      case Op::IGt: setf(sext(b_.CreateICmpSGT(I(i.a), I(i.b)))); break;
      case Op::IGe: setf(sext(b_.CreateICmpSGE(I(i.a), I(i.b)))); break;
      case Op::ULt: setf(sext(b_.CreateICmpULT(I(i.a), I(i.b)))); break;
      case Op::ULe: setf(sext(b_.CreateICmpULE(I(i.a), I(i.b)))); break;
      case Op::UGt: setf(sext(b_.CreateICmpUGT(I(i.a), I(i.b)))); break;
      case Op::UGe: setf(sext(b_.CreateICmpUGE(I(i.a), I(i.b)))); break;
      case Op::IEq: setf(sext(b_.CreateICmpEQ(I(i.a), I(i.b)))); break;
      case Op::INe: setf(sext(b_.CreateICmpNE(I(i.a), I(i.b)))); break;
      case Op::I2F: setf(b_.CreateSIToFP(I(i.a), vf_)); break;
      case Op::U2F: setf(b_.CreateUIToFP(I(i.a), vf_)); break;
      case Op::F2I: {
        // As cvttps2dq: NaN and out of range give INT_MIN.
        llvm::Value* x = F(i.a);
        llvm::Value* in = b_.CreateAnd(b_.CreateFCmpOGT(x, splatf(-2147483904.0f)),
                                       b_.CreateFCmpOLT(x, splatf(2147483648.0f)));
        llvm::Value* v = b_.CreateFPToSI(b_.CreateSelect(in, x, splatf(0.0f)), vi_);
        setf(b_.CreateSelect(in, v, splat(0x80000000u)));
        break;
      }
      case Op::F2U: {
        llvm::Value* x = F(i.a);
        llvm::Value* ok =
            b_.CreateAnd(b_.CreateFCmpOGT(x, splatf(-1.0f)), b_.CreateFCmpOLT(x, splatf(4294967296.0f)));
        llvm::Value* v = b_.CreateFPToUI(b_.CreateSelect(ok, x, splatf(0.0f)), vi_);
        setf(b_.CreateSelect(ok, v, splat(~0u)));
        break;
      }
      case Op::Ddx:
      case Op::Ddy: {
        const int bit = i.op == Op::Ddx ? 1 : 2;
        llvm::SmallVector<int, 16> hi, lo;
        for (int l = 0; l < W; ++l) {
          hi.push_back(l | bit);
          lo.push_back(l & ~bit);
        }
        llvm::Value* x = F(i.a);
        setf(b_.CreateFSub(b_.CreateShuffleVector(x, hi), b_.CreateShuffleVector(x, lo)));
        break;
      }
      case Op::Texture: texture(i); break;
      default: call_math(i); break;
    }
  }
};

// --- the disk cache ------------------------------------------------------------------------

// Two FNV-1a hashes (different offsets) over the program's IR and interface and the machine.
struct Hasher {
  uint64_t a = 14695981039346656037ull, b = 0x84222325cbf29ce4ull;
  void bytes(const void* p, size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) {
      a = (a ^ c[i]) * 1099511628211ull;
      b = (b ^ c[i]) * 0x100000001b3ull + 0x9e3779b97f4a7c15ull;
    }
  }
  void u32(uint32_t v) { bytes(&v, 4); }
  void str(const std::string& s) {
    u32(uint32_t(s.size()));
    bytes(s.data(), s.size());
  }
  void block(const ir::Block& bl) {
    u32(uint32_t(bl.size()));
    for (const ir::Node& n : bl) {
      u32(uint32_t(n.kind));
      u32(n.cond);
      u32(uint32_t(n.code.size()));
      for (const Inst& i : n.code) {
        u32(uint32_t(i.op));
        u32(i.dst), u32(i.a), u32(i.b), u32(i.c), u32(i.d), u32(i.imm);
      }
      block(n.a);
      block(n.b);
    }
  }
  void stage(const ir::Stage& st, const StageIO& io) {
    block(st.body);
    u32(st.registers);
    for (const auto* list : {&st.constants, &st.uniforms, &st.variables}) {
      u32(uint32_t(list->size()));
      for (const auto& [r, v] : *list) u32(r), u32(v);
    }
    u32(uint32_t(st.textures.size()));
    for (const ir::TexOp& t : st.textures) {
      u32(uint32_t(t.kind)), u32(uint32_t(t.dim)), u32(t.array), u32(t.shadow), u32(t.proj);
      u32(t.has_lod), u32(t.has_bias), u32(t.has_grad), u32(uint32_t(t.sampler)), u32(uint32_t(t.coords));
      for (Reg r : t.coord) u32(r);
      u32(t.ref), u32(t.lod);
      for (int k = 0; k < 3; ++k)
        u32(t.dx[k]), u32(t.dy[k]), u32(uint32_t(t.offset[k])), u32(t.offset_reg[k]);
      for (Reg r : t.dst) u32(r);
      u32(uint32_t(t.result));
    }
    for (const auto* list : {&io.in, &io.out, &io.in_mask}) {
      u32(uint32_t(list->size()));
      for (const auto& [r, off] : *list) u32(r), u32(off);
    }
  }
};

// What a cached object was made for: the code generator's version, this format, the CPU.
std::string host_id() {
  std::string id =
      std::string("tessel-jit-5 llvm-") + LLVM_VERSION_STRING + " " + llvm::sys::getHostCPUName().str();
  llvm::StringMap<bool> features;
  if (llvm::sys::getHostCPUFeatures(features)) {
    std::vector<std::string> on;
    for (const auto& f : features)
      if (f.second) on.push_back(f.first().str());
    std::sort(on.begin(), on.end());
    for (const auto& f : on) id += " +" + f;
  }
  return id;
}

std::string cache_dir() {
  if (const char* off = std::getenv("TESSEL_SHADER_CACHE"); off && std::string(off) == "0") return {};
  if (const char* d = std::getenv("TESSEL_SHADER_CACHE_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/tessel";
  if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/tessel";
  return {};
}

constexpr char kMagic[8] = {'T', 'S', 'L', 'J', 'I', 'T', '0', '2'};

uint64_t checksum(const std::string& s) {
  Hasher h;
  h.bytes(s.data(), s.size());
  return h.a ^ (h.b << 1);
}

// The object code cached under `key`, if a file there is whole and was made for this machine.
bool cache_read(const std::string& path, const std::string& host, std::string& object) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string f = ss.str();
  size_t at = 0;
  auto take = [&](void* p, size_t n) {
    if (at + n > f.size()) return false;
    std::memcpy(p, f.data() + at, n);
    at += n;
    return true;
  };
  char magic[8];
  uint32_t host_len = 0;
  uint64_t size = 0, sum = 0;
  if (!take(magic, 8) || std::memcmp(magic, kMagic, 8) != 0 || !take(&host_len, 4) || host_len > 65536)
    return false;
  if (at + host_len > f.size() || f.compare(at, host_len, host) != 0 || host_len != host.size()) return false;
  at += host_len;
  if (!take(&size, 8) || !take(&sum, 8) || size != f.size() - at) return false;
  object = f.substr(at);
  return checksum(object) == sum;
}

void cache_write(const std::string& path, const std::string& host, const std::string& object) {
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  if (ec) return;
  const std::string tmp = path + ".tmp" + std::to_string(uint64_t(reinterpret_cast<uintptr_t>(&object)));
  {
    std::ofstream out(tmp, std::ios::binary);
    const uint32_t host_len = uint32_t(host.size());
    const uint64_t size = object.size(), sum = checksum(object);
    out.write(kMagic, 8);
    out.write(reinterpret_cast<const char*>(&host_len), 4);
    out.write(host.data(), std::streamsize(host.size()));
    out.write(reinterpret_cast<const char*>(&size), 8);
    out.write(reinterpret_cast<const char*>(&sum), 8);
    out.write(object.data(), std::streamsize(object.size()));
    if (!out) {
      std::filesystem::remove(tmp, ec);
      return;
    }
  }
  std::filesystem::rename(tmp, path, ec);  // atomic: a reader sees the old file or the whole new one
  if (ec) std::filesystem::remove(tmp, ec);
}

class LlvmCode final : public JitCode {
 public:
  std::unique_ptr<llvm::orc::LLJIT> jit;
  StageFn fns[2] = {nullptr, nullptr};
  PairFn pair = nullptr;
  StageFn function(int stage) const override { return fns[stage]; }
  PairFn fragment_pair() const override { return pair; }
};

}  // namespace

namespace {

// A JIT with the two helper functions and memset/memcpy from this process.
llvm::Expected<std::unique_ptr<llvm::orc::LLJIT>> make_jit(llvm::orc::JITTargetMachineBuilder jtmb) {
  auto jit = llvm::orc::LLJITBuilder().setJITTargetMachineBuilder(std::move(jtmb)).create();
  if (!jit) return jit.takeError();
  auto& es = (*jit)->getExecutionSession();
  llvm::orc::SymbolMap syms;
  syms[es.intern("tessel_glsl_texture")] = llvm::JITEvaluatedSymbol(
      llvm::pointerToJITTargetAddress(&tessel_glsl_texture), llvm::JITSymbolFlags::Exported);
  syms[es.intern("tessel_glsl_texture_2d")] = llvm::JITEvaluatedSymbol(
      llvm::pointerToJITTargetAddress(&tessel_glsl_texture_2d), llvm::JITSymbolFlags::Exported);
  syms[es.intern("tessel_glsl_texture_2d_pair")] = llvm::JITEvaluatedSymbol(
      llvm::pointerToJITTargetAddress(&tessel_glsl_texture_2d_pair), llvm::JITSymbolFlags::Exported);
  syms[es.intern("tessel_glsl_lane_math")] = llvm::JITEvaluatedSymbol(
      llvm::pointerToJITTargetAddress(&tessel_glsl_lane_math), llvm::JITSymbolFlags::Exported);
  if (auto e = (*jit)->getMainJITDylib().define(llvm::orc::absoluteSymbols(syms))) return e;
  auto process = llvm::orc::DynamicLibrarySearchGenerator::GetForCurrentProcess(
      (*jit)->getDataLayout().getGlobalPrefix());
  if (!process) return process.takeError();
  (*jit)->getMainJITDylib().addGenerator(std::move(*process));
  return jit;
}

bool find_functions(LlvmCode& code) {
  for (int s = 0; s < 2; ++s) {
    auto sym = code.jit->lookup(s == 0 ? "vertex" : "fragment");
    if (!sym) {
      llvm::consumeError(sym.takeError());
      return false;
    }
    code.fns[s] = sym->toPtr<StageFn>();
  }
  auto sym = code.jit->lookup("fragment_pair");
  if (!sym) {
    llvm::consumeError(sym.takeError());
    return false;
  }
  code.pair = sym->toPtr<PairFn>();
  return true;
}

}  // namespace

void jit_warm_up() {
  // A stage with the kinds of operation and control flow the code generator emits (float and
  // integer arithmetic and conversions, selects, derivatives' shuffles, a branch, a loop),
  // compiled as every program is, at both widths.
  using K = ir::Node::Kind;
  ir::Stage st;
  st.registers = 16;
  st.constants = {{0, 0x40000000u}, {1, 3u}};
  ir::Node code;
  auto op = [&](Op o, Reg d, Reg a, Reg b = 0, Reg c = 0) {
    Inst i;
    i.op = o;
    i.dst = d, i.a = a, i.b = b, i.c = c;
    code.code.push_back(i);
  };
  op(Op::FSqrt, 2, 0);
  op(Op::FDiv, 3, 2, 0);
  op(Op::FFma, 4, 3, 2, 0);
  op(Op::FFloor, 5, 4);
  op(Op::FRoundEven, 6, 5);
  op(Op::F2I, 7, 6);
  op(Op::I2F, 8, 7);
  op(Op::IDiv, 9, 7, 1);
  op(Op::UDiv, 10, 7, 1);
  op(Op::FLt, 11, 3, 4);
  op(Op::Select, 12, 11, 3, 4);
  op(Op::Ddx, 13, 12);
  st.body.push_back(code);
  ir::Node branch;
  branch.kind = K::If;
  branch.cond = 11;
  ir::Node add;
  Inst i;
  i.op = Op::FAdd, i.dst = 14, i.a = 13, i.b = 8;
  add.code.push_back(i);
  branch.a.push_back(add);
  st.body.push_back(branch);
  ir::Node loop;
  loop.kind = K::Loop;
  loop.a.push_back(add);
  ir::Node brk;
  brk.kind = K::Break;
  loop.a.push_back(brk);
  st.body.push_back(loop);
  std::string why;
  (void)jit_compile(st, StageIO{}, st, StageIO{}, JitEnvironment{}, &why);
}

JitEnvironment jit_environment() {
  JitEnvironment env;
  env.cache_dir = cache_dir();
  const char* dump = std::getenv("TESSEL_GLSL_DUMP");
  env.dump = dump && *dump == '1';
  return env;
}

std::unique_ptr<JitCode> jit_compile(const ir::Stage& vs, const StageIO& vio, const ir::Stage& fs,
                                     const StageIO& fio, const JitEnvironment& env, std::string* error) {
  init_llvm();
  auto fail = [&](const std::string& e) -> std::unique_ptr<JitCode> {
    if (error) *error = e;
    return nullptr;
  };
  auto jtmb = llvm::orc::JITTargetMachineBuilder::detectHost();
  if (!jtmb) return fail("no native target");
  jtmb->setCodeGenOptLevel(llvm::CodeGenOpt::Default);

  // The disk cache: the key covers the IR of both stages, their interfaces and the machine.
  const std::string& dir = env.cache_dir;
  const std::string host = dir.empty() ? std::string() : host_id();
  std::string path;
  if (!dir.empty()) {
    Hasher h;
    h.str(host);
    h.stage(vs, vio);
    h.stage(fs, fio);
    char name[40];
    std::snprintf(name, sizeof name, "%016llx%016llx.o", (unsigned long long)h.a, (unsigned long long)h.b);
    path = dir + "/glsl/" + name;
    std::string object;
    if (cache_read(path, host, object)) {
      auto jit = make_jit(*jtmb);
      if (jit) {
        auto code = std::make_unique<LlvmCode>();
        code->jit = std::move(*jit);
        code->from_cache = true;
        if (!code->jit->addObjectFile(llvm::MemoryBuffer::getMemBufferCopy(object, path)) &&
            find_functions(*code))
          return code;
      } else {
        llvm::consumeError(jit.takeError());
      }
      // A file that does not load is ignored: the program is compiled again.
    }
  }

  auto ctx = std::make_unique<llvm::LLVMContext>();
  auto mod = std::make_unique<llvm::Module>("tessel_glsl", *ctx);
  Codegen(*ctx, *mod, vs, vio).build("vertex");
  Codegen(*ctx, *mod, fs, fio).build("fragment");
  Codegen(*ctx, *mod, fs, fio, 2 * L).build("fragment_pair");
  std::string verify;
  llvm::raw_string_ostream vos(verify);
  if (llvm::verifyModule(*mod, &vos)) return fail("internal: invalid code: " + vos.str());
  auto tm = jtmb->createTargetMachine();
  if (!tm) return fail("no target machine");
  mod->setDataLayout((*tm)->createDataLayout());
  {
    llvm::LoopAnalysisManager lam;
    llvm::FunctionAnalysisManager fam;
    llvm::CGSCCAnalysisManager cgam;
    llvm::ModuleAnalysisManager mam;
    llvm::PassBuilder pb(tm->get());
    pb.registerModuleAnalyses(mam);
    pb.registerCGSCCAnalyses(cgam);
    pb.registerFunctionAnalyses(fam);
    pb.registerLoopAnalyses(lam);
    pb.crossRegisterProxies(lam, fam, cgam, mam);
    llvm::ModulePassManager mpm = pb.buildPerModuleDefaultPipeline(llvm::OptimizationLevel::O2);
    mpm.run(*mod, mam);
  }
  if (env.dump) mod->print(llvm::errs(), nullptr);
  auto jit = make_jit(*jtmb);
  if (!jit) return fail("cannot create the JIT: " + llvm::toString(jit.takeError()));
  auto code = std::make_unique<LlvmCode>();
  code->jit = std::move(*jit);
  // The object file as it is made, for the cache.
  std::string object;
  if (!path.empty())
    code->jit->getObjTransformLayer().setTransform(
        [&object](
            std::unique_ptr<llvm::MemoryBuffer> obj) -> llvm::Expected<std::unique_ptr<llvm::MemoryBuffer>> {
          object = obj->getBuffer().str();
          return obj;
        });
  if (auto e = code->jit->addIRModule(llvm::orc::ThreadSafeModule(std::move(mod), std::move(ctx))))
    return fail(llvm::toString(std::move(e)));
  if (!find_functions(*code)) return fail("the compiled functions are missing");
  code->jit->getObjTransformLayer().setTransform(nullptr);
  if (!path.empty() && !object.empty()) cache_write(path, host, object);
  return code;
}

}  // namespace tessel::glsl
