#include "shader/jit/compiled_stage.h"

#include <sys/mman.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>

#include "raster/simd_path.h"
#include "shader/jit/x86_encoder.h"

namespace pineda::shader::jit {

using ir::Op;
using ir::Operand;

namespace {

// Bit patterns the generated code broadcasts: 1.0, the sign bit, all but the sign.
alignas(64) constexpr uint32_t kPool[] = {0x3F800000u, 0x80000000u, 0x7FFFFFFFu};
enum PoolEntry { kOne, kSignBit, kAbsBits };
constexpr uint8_t kFloor = 0x09, kTruncate = 0x0B;  // vrndscaleps modes

// zmm0-27 hold values; 28 and 29 are scratch; 30 holds 1.0 and 31 zero throughout.
constexpr int kValueRegisters = 28;
constexpr int kScratch = 28, kScratch2 = 29, kOneReg = 30, kZeroReg = 31;
constexpr int kBytesPerValue = kLanes * 4;

// Where the frame's pointers live while the code runs.
constexpr Gpr kSpill = rbx, kSlots = rbp, kConstants = r12, kBlock = r13, kLanesIn = r14, kUniforms = r15;

bool natively_emitted(Op op) {
  switch (op) {
    case Op::Mov: case Op::LoadUniform: case Op::LoadInput: case Op::LoadVarying: case Op::LoadFragCoord:
    case Op::LoadPointCoord: case Op::StoreOutput: case Op::StoreColor: case Op::StoreDepth: case Op::Neg:
    case Op::Abs: case Op::Floor: case Op::Fract: case Op::Trunc: case Op::Sqrt: case Op::Not: case Op::ToBool:
    case Op::Add: case Op::Sub: case Op::Mul: case Op::Div: case Op::Min: case Op::Max: case Op::Step:
    case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne: case Op::And: case Op::Or:
    case Op::Xor: case Op::Clamp: case Op::Mix: case Op::Select: case Op::Mad: case Op::GatherUniform:
    case Op::Rsq: case Op::NormScale:
      return true;
    default:
      return false;
  }
}

// The operations run by call_out: every value operation and the loads without a native form.
bool called_out(Op op) {
  return op == Op::Texture || op == Op::LoadFrontFacing ||
         (op >= Op::Neg && op < Op::Count && !natively_emitted(op));
}

class Generator {
 public:
  Generator(const std::vector<ir::Inst>& insts, const std::vector<ir::TextureLookup>& textures, int registers, int slots)
      : insts_(insts), textures_(textures), registers_(registers), slots_(slots) {
    const int constants = constant_count();
    values_ = registers + slots + constants;
    reads_.resize(static_cast<size_t>(values_));
    writes_.resize(static_cast<size_t>(values_));
    where_.assign(static_cast<size_t>(values_), -1);
    zeroed_home_.assign(static_cast<size_t>(values_), false);
    dirty_.assign(static_cast<size_t>(values_), false);
    for (int i = 0; i < static_cast<int>(insts.size()); ++i) {
      for (Operand o : sources(insts[static_cast<size_t>(i)])) reads_[static_cast<size_t>(id(o))].push_back(i);
      for (Operand o : destinations(insts[static_cast<size_t>(i)])) writes_[static_cast<size_t>(id(o))].push_back(i);
    }
    holder_.fill(-1);
  }

  // Null when an instruction has no compiled form (structure, dynamic indexing).
  bool generate(const ir::Inst* stable_insts) {
    prologue();
    const int n = static_cast<int>(insts_.size());
    int last_neighbour_read = -1;  // the last derivative or texture lookup
    for (int i = 0; i < n; ++i)
      if (insts_[static_cast<size_t>(i)].op == Op::Ddx || insts_[static_cast<size_t>(i)].op == Op::Ddy ||
          insts_[static_cast<size_t>(i)].op == Op::Texture)
        last_neighbour_read = i;
    for (int i = 0; i < n; ++i) {
      const ir::Inst& in = insts_[static_cast<size_t>(i)];
      // if (a) discard;  The interpreter's later lanes differ where discarded lanes are not
      // updated, which only derivatives and texture lookups (implicit LOD) could see.
      if (in.op == Op::IfBegin && i + 2 < n && insts_[static_cast<size_t>(i) + 1].op == Op::Discard &&
          insts_[static_cast<size_t>(i) + 2].op == Op::EndIf && last_neighbour_read < i) {
        discard_if(i, in);
        i += 2;
        continue;
      }
      if (in.op <= Op::Discard || in.op == Op::Gather || in.op == Op::Scatter) return false;
      if (called_out(in.op)) call(i, stable_insts + i);
      else native(i, in);
    }
    epilogue();
    return true;
  }

  const std::vector<uint8_t>& bytes() const { return x_.bytes(); }

 private:
  int constant_count() const {
    int n = 0;
    for (const ir::Inst& in : insts_)
      for (Operand o : sources(in))
        if (ir::is_const(o)) n = std::max(n, ir::const_index(o) + 1);
    return n;
  }
  int id(Operand o) const { return ir::is_const(o) ? registers_ + slots_ + ir::const_index(o) : o; }
  std::vector<Operand> destinations(const ir::Inst& in) const {
    if (in.op == Op::Texture) {
      const ir::TextureLookup& t = textures_[static_cast<size_t>(in.i0)];
      return {t.dst[0], t.dst[1], t.dst[2], t.dst[3]};
    }
    if (in.op < Op::Mov || in.op == Op::StoreOutput || in.op == Op::StoreColor || in.op == Op::StoreDepth ||
        in.op == Op::Scatter)
      return {};
    return {in.d};
  }
  std::vector<Operand> sources(const ir::Inst& in) const {
    std::vector<Operand> s;
    if (in.op == Op::Texture) {
      const ir::TextureLookup& t = textures_[static_cast<size_t>(in.i0)];
      for (Operand o : {t.sampler, t.coord[0], t.coord[1], t.coord[2], t.coord[3], t.lod})
        if (o != ir::kNone) s.push_back(o);
      return s;
    }
    for (Operand o : {in.a, in.b, in.c})
      if (o != ir::kNone) s.push_back(o);
    return s;
  }
  Mem home(int value) const {
    if (value < registers_) return {kSpill, value * kBytesPerValue};
    if (value < registers_ + slots_) return {kSlots, (value - registers_) * kBytesPerValue};
    return {kConstants, (value - registers_ - slots_) * kConstantStride * 4};
  }
  // The next instruction after `at` that reads the value `value` holds after `at`, or -1.
  int next_read(int value, int at) const {
    const auto& r = reads_[static_cast<size_t>(value)];
    const auto& w = writes_[static_cast<size_t>(value)];
    const auto read = std::upper_bound(r.begin(), r.end(), at);
    if (read == r.end()) return -1;
    const auto write = std::upper_bound(w.begin(), w.end(), at);
    return (write == w.end() || *read <= *write) ? *read : -1;
  }

  void release(int reg) {
    if (holder_[static_cast<size_t>(reg)] >= 0) {
      where_[static_cast<size_t>(holder_[static_cast<size_t>(reg)])] = -1;
      dirty_[static_cast<size_t>(holder_[static_cast<size_t>(reg)])] = false;
    }
    holder_[static_cast<size_t>(reg)] = -1;
  }
  void spill_if_needed(int reg, int at) {
    const int v = holder_[static_cast<size_t>(reg)];
    if (v >= 0 && dirty_[static_cast<size_t>(v)] && next_read(v, at) >= 0) {
      x_.store(home(v), reg);
      dirty_[static_cast<size_t>(v)] = false;
    }
  }
  // A register for a new value at instruction `at`, not one of `pinned`.
  int allocate(int at, uint32_t pinned) {
    int best = -1;
    long best_score = -1;
    for (int r = 0; r < kValueRegisters; ++r) {
      if (pinned >> r & 1) continue;
      const int v = holder_[static_cast<size_t>(r)];
      if (v < 0) return r;
      const int next = next_read(v, at);
      // Dead values first, then the farthest next read; clean values before dirty ones.
      const long score = (next < 0 ? 1L << 40 : static_cast<long>(next) << 1) + (dirty_[static_cast<size_t>(v)] ? 0 : 1);
      if (score > best_score) best_score = score, best = r;
    }
    spill_if_needed(best, at);
    release(best);
    return best;
  }
  // A register read before anything wrote it holds zero, as in the interpreter's zeroed file.
  bool unwritten(int value, int at) const {
    if (value >= registers_) return false;
    const auto& w = writes_[static_cast<size_t>(value)];
    return w.empty() || w.front() >= at;
  }
  int use(Operand o, int at, uint32_t& pinned) {
    const int v = id(o);
    int r = where_[static_cast<size_t>(v)];
    if (r < 0) {
      r = allocate(at, pinned);
      if (unwritten(v, at)) {
        x_.vmovaps(r, kZeroReg);
        dirty_[static_cast<size_t>(v)] = true;
      } else {
        x_.load(r, home(v));
      }
      holder_[static_cast<size_t>(r)] = v;
      where_[static_cast<size_t>(v)] = r;
    }
    pinned |= 1u << r;
    return r;
  }
  void pool(int reg, PoolEntry e) {
    x_.mov_imm(rax, reinterpret_cast<uint64_t>(kPool));
    x_.broadcast(reg, {rax, static_cast<int32_t>(e * 4)});
  }
  void fixed_registers() {
    x_.vpxord(kZeroReg, kZeroReg, kZeroReg);
    pool(kOneReg, kOne);
  }

  void prologue() {
    for (Gpr r : {rbx, rbp, r12, r13, r14, r15}) x_.push(r);
    x_.add_rsp(-8);  // the stack 16-byte aligned for calls; the frame pointer kept in this slot
    x_.mov_store({rsp, 0}, rdi);
    x_.mov_load(kSpill, {rdi, static_cast<int32_t>(offsetof(Frame, spill))});
    x_.mov_load(kSlots, {rdi, static_cast<int32_t>(offsetof(Frame, slots))});
    x_.mov_load(kConstants, {rdi, static_cast<int32_t>(offsetof(Frame, constants))});
    x_.mov_load(kBlock, {rdi, static_cast<int32_t>(offsetof(Frame, block_or_outputs))});
    x_.mov_load(kLanesIn, {rdi, static_cast<int32_t>(offsetof(Frame, lanes_in))});
    x_.mov_load(kUniforms, {rdi, static_cast<int32_t>(offsetof(Frame, uniforms))});
    fixed_registers();
  }
  void epilogue() {
    x_.add_rsp(8);
    for (Gpr r : {r15, r14, r13, r12, rbp, rbx}) x_.pop(r);
    x_.vzeroupper();
    x_.ret();
  }

  // Everything the call-out reads or what outlives it goes to memory; no register survives.
  void call(int at, const ir::Inst* stable) {
    for (int r = 0; r < kValueRegisters; ++r) {
      const int v = holder_[static_cast<size_t>(r)];
      if (v < 0) continue;
      if (dirty_[static_cast<size_t>(v)] && (next_read(v, at - 1) >= 0)) x_.store(home(v), r);
      release(r);
    }
    for (Operand o : sources(*stable))
      if (unwritten(id(o), at) && !zeroed_home_[static_cast<size_t>(id(o))]) {
        x_.store(home(id(o)), kZeroReg);
        zeroed_home_[static_cast<size_t>(id(o))] = true;
      }
    x_.vzeroupper();
    x_.mov_load(rdi, {rsp, 0});
    x_.mov_imm(rsi, reinterpret_cast<uint64_t>(stable));
    x_.mov_imm(rax, reinterpret_cast<uint64_t>(&call_out));
    x_.call(rax);
    fixed_registers();
  }

  void native(int at, const ir::Inst& in) {
    uint32_t pinned = resident_sources(in);  // a source's load must not evict another
    int a = -1, b = -1, c = -1;
    if (in.a != ir::kNone) a = use(in.a, at, pinned);
    if (in.b != ir::kNone) b = use(in.b, at, pinned);
    if (in.c != ir::kNone) c = use(in.c, at, pinned);
    switch (in.op) {
      case Op::StoreOutput: x_.store({kBlock, in.i0 * kBytesPerValue}, a); return finish_sources(at, in);
      case Op::StoreDepth: x_.store({kBlock, static_cast<int32_t>(offsetof(FragmentBlock, depth))}, a); return finish_sources(at, in);
      case Op::StoreColor: {
        const int32_t color = static_cast<int32_t>(offsetof(FragmentBlock, color));
        for (int buffer = 0; buffer < kMaxDrawBuffers; ++buffer) {
          if (!in.i1 && buffer != in.i0 >> 2) continue;
          x_.store({kBlock, color + (buffer * 4 + (in.i0 & 3)) * kBytesPerValue}, a);
        }
        return finish_sources(at, in);
      }
      default:
        break;
    }
    finish_sources(at, in);
    // The destination's old value ends here; the sequence below writes d last.
    const int dv = id(in.d);
    if (where_[static_cast<size_t>(dv)] >= 0) release(where_[static_cast<size_t>(dv)]);
    const int d = allocate(at, resident_sources(in));
    emit(in, d, a, b, c);
    holder_[static_cast<size_t>(d)] = dv;
    where_[static_cast<size_t>(dv)] = d;
    dirty_[static_cast<size_t>(dv)] = true;
    if (next_read(dv, at) < 0) release(d);
  }
  // Sources read for the last time here free their registers (the destination may take one).
  void finish_sources(int at, const ir::Inst& in) {
    for (Operand o : sources(in)) {
      const int v = id(o);
      if (where_[static_cast<size_t>(v)] >= 0 && next_read(v, at) < 0) release(where_[static_cast<size_t>(v)]);
    }
  }
  uint32_t resident_sources(const ir::Inst& in) const {
    uint32_t pinned = 0;
    for (Operand o : sources(in)) {
      const int r = where_[static_cast<size_t>(id(o))];
      if (r >= 0) pinned |= 1u << r;
    }
    return pinned;
  }

  // The running lanes where a != 0 join the frame's discarded lanes.
  void discard_if(int at, const ir::Inst& in) {
    uint32_t pinned = resident_sources(in);
    const int a = use(in.a, at, pinned);
    x_.vcmpps(1, a, kZeroReg, Cmp::Neq);
    x_.kmovw_to_gpr(rax, 1);
    x_.mov_load(rdx, {rsp, 0});
    x_.or_store32({rdx, static_cast<int32_t>(offsetof(Frame, discarded))}, rax);
    finish_sources(at, in);
  }

  // k1 = a < b or b is NaN (ir::lane_min's choice of a); `greater` for lane_max.
  void min_max(int d, int a, int b, bool greater) {
    x_.vcmpps(1, a, b, greater ? Cmp::Gt : Cmp::Lt);
    x_.vcmpps(2, b, b, Cmp::Unord);
    x_.korw(1, 1, 2);
    x_.vblendmps(d, 1, b, a);
  }
  // d = ir::lane_trunc(a) or ir::lane_floor(a): the rounded value, except that a zero result is
  // +0 (the lane routines convert through an integer) and NaN keeps its bits. d is written last.
  void round_to(int d, int a, uint8_t mode) {
    x_.vrndscaleps(kScratch, a, mode);
    x_.vcmpps(1, kScratch, kZeroReg, Cmp::Eq);
    x_.vmovaps(kScratch, kZeroReg, 1);
    x_.vcmpps(2, a, a, Cmp::Unord);
    x_.vblendmps(d, 2, kScratch, a);
  }
  void compare(int d, int a, int b, Cmp pred) {
    x_.vcmpps(1, a, b, pred);
    x_.vmovaps(d, kOneReg, 1, true);
  }

  void emit(const ir::Inst& in, int d, int a, int b, int c) {
    switch (in.op) {
      case Op::Mov: return x_.vmovaps(d, a);
      case Op::LoadUniform: return x_.broadcast(d, {kUniforms, in.i0 * 4});
      case Op::LoadInput:
      case Op::LoadVarying: return x_.load(d, {kLanesIn, in.i0 * kBytesPerValue});
      case Op::LoadFragCoord:
        return x_.load(d, {kBlock, static_cast<int32_t>(offsetof(FragmentBlock, frag_coord)) + in.i0 * kBytesPerValue});
      case Op::LoadPointCoord:
        return x_.load(d, {kBlock, static_cast<int32_t>(offsetof(FragmentBlock, point_coord)) + in.i0 * kBytesPerValue});
      case Op::Neg: pool(kScratch, kSignBit); return x_.vpxord(d, a, kScratch);
      case Op::Abs: pool(kScratch, kAbsBits); return x_.vpandd(d, a, kScratch);
      case Op::Trunc: return round_to(d, a, kTruncate);
      case Op::Floor: return round_to(d, a, kFloor);
      case Op::Fract:  // a - lane_floor(a)
        round_to(kScratch, a, kFloor);
        return x_.vsubps(d, a, kScratch);
      case Op::Sqrt: return x_.vsqrtps(d, a);
      case Op::Rsq:  // 1 / sqrt(a)
        x_.vsqrtps(kScratch, a);
        return x_.vdivps(d, kOneReg, kScratch);
      case Op::NormScale:  // a > 0 ? 1 / sqrt(a) : 0
        x_.vsqrtps(kScratch, a);
        x_.vdivps(kScratch, kOneReg, kScratch);
        x_.vcmpps(1, a, kZeroReg, Cmp::Gt);
        return x_.vmovaps(d, kScratch, 1, true);
      case Op::GatherUniform: {  // uniforms[i0 + clamp_index(a, i1)]
        x_.vcvttps2dq(kScratch, a);  // out of range: 0x80000000, which the unsigned min clamps
        x_.vcmpps(1, a, kZeroReg, Cmp::Ge);
        x_.vmovaps(kScratch, kScratch, 1, true);  // negative and NaN: 0
        x_.mov_imm32(rax, static_cast<uint32_t>(in.i1));
        x_.vpbroadcastd(kScratch2, rax);
        x_.vpminud(kScratch, kScratch, kScratch2);
        x_.kxnorw(3, 3, 3);
        return x_.vgatherdps(d, 3, kUniforms, kScratch, in.i0 * 4);
      }
      case Op::Not: return compare(d, a, kZeroReg, Cmp::Eq);
      case Op::ToBool: return compare(d, a, kZeroReg, Cmp::Neq);
      case Op::Add: return x_.vaddps(d, a, b);
      case Op::Sub: return x_.vsubps(d, a, b);
      case Op::Mul: return x_.vmulps(d, a, b);
      case Op::Div: return x_.vdivps(d, a, b);
      case Op::Min: return min_max(d, a, b, false);
      case Op::Max: return min_max(d, a, b, true);
      case Op::Step:  // b < a ? 0 : 1
        x_.vcmpps(1, b, a, Cmp::Lt);
        return x_.vblendmps(d, 1, kOneReg, kZeroReg);
      case Op::Lt: return compare(d, a, b, Cmp::Lt);
      case Op::Le: return compare(d, a, b, Cmp::Le);
      case Op::Gt: return compare(d, a, b, Cmp::Gt);
      case Op::Ge: return compare(d, a, b, Cmp::Ge);
      case Op::Eq: return compare(d, a, b, Cmp::Eq);
      case Op::Ne: return compare(d, a, b, Cmp::Neq);
      case Op::And:
        x_.vcmpps(1, a, kZeroReg, Cmp::Neq);
        x_.vcmpps(1, b, kZeroReg, Cmp::Neq, 1);
        return x_.vmovaps(d, kOneReg, 1, true);
      case Op::Or:
      case Op::Xor:
        x_.vcmpps(1, a, kZeroReg, Cmp::Neq);
        x_.vcmpps(2, b, kZeroReg, Cmp::Neq);
        if (in.op == Op::Or) x_.korw(1, 1, 2);
        else x_.kxorw(1, 1, 2);
        return x_.vmovaps(d, kOneReg, 1, true);
      case Op::Clamp:  // lane_min(lane_max(a, b), c)
        min_max(kScratch, a, b, true);
        return min_max(d, kScratch, c, false);
      case Op::Mix:  // a * (1 - c) + b * c
        x_.vsubps(kScratch, kOneReg, c);
        x_.vmulps(kScratch, a, kScratch);
        x_.vmulps(kScratch2, b, c);
        return x_.vaddps(d, kScratch, kScratch2);
      case Op::Select:  // a != 0 ? b : c
        x_.vcmpps(1, a, kZeroReg, Cmp::Neq);
        return x_.vblendmps(d, 1, c, b);
      case Op::Mad:
        x_.vmulps(kScratch, a, b);
        return x_.vaddps(d, kScratch, c);
      default:
        return;
    }
  }

  const std::vector<ir::Inst>& insts_;
  const std::vector<ir::TextureLookup>& textures_;
  int registers_, slots_, values_ = 0;
  std::vector<std::vector<int>> reads_, writes_;
  std::vector<int> where_;
  std::vector<bool> dirty_;
  std::vector<bool> zeroed_home_;  // unwritten registers whose home a call-out reads
  std::array<int, kValueRegisters> holder_;
  X86Encoder x_;
};

}  // namespace

std::unique_ptr<CompiledStage> CompiledStage::compile(const std::vector<ir::Inst>& insts,
                                                      const std::vector<ir::TextureLookup>& textures, int registers,
                                                      int slots) {
  std::unique_ptr<CompiledStage> stage(new CompiledStage);
  stage->insts_ = insts;  // never resized again: the code holds the addresses of its elements
  Generator generator(stage->insts_, textures, registers, slots);
  if (!generator.generate(stage->insts_.data())) return nullptr;
  const std::vector<uint8_t>& bytes = generator.bytes();
  void* memory = mmap(nullptr, bytes.size(), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (memory == MAP_FAILED) return nullptr;
  std::memcpy(memory, bytes.data(), bytes.size());
  if (mprotect(memory, bytes.size(), PROT_READ | PROT_EXEC) != 0) {
    munmap(memory, bytes.size());
    return nullptr;
  }
  stage->memory_ = memory;
  stage->size_ = bytes.size();
  stage->entry_ = reinterpret_cast<Entry>(memory);
  return stage;
}

CompiledStage::~CompiledStage() {
  if (memory_) munmap(memory_, size_);
}

bool compiled_tier_enabled() {
  static const bool enabled = [] {
    const char* v = std::getenv("PINEDA_SHADER_JIT");
    if (v && std::strcmp(v, "0") == 0) return false;
    return raster::uses_avx512(raster::simd_path_from_environment());
  }();
  return enabled;
}

}  // namespace pineda::shader::jit
