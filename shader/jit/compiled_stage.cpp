#include "shader/jit/compiled_stage.h"

#include <sys/mman.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "raster/simd_path.h"
#include "shader/jit/emit_library_ops.h"
#include "shader/jit/x86_encoder.h"

namespace pineda::shader::jit {

using ir::Op;
using ir::Operand;

namespace {

// Bit patterns the generated code broadcasts: 1.0, the sign bit, all but the sign, 3.0.
alignas(64) constexpr uint32_t kPool[] = {0x3F800000u, 0x80000000u, 0x7FFFFFFFu, 0x40400000u};
enum PoolEntry { kOne, kSignBit, kAbsBits, kThree };
alignas(64) constexpr int32_t kLaneIndex[kLanes] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
constexpr uint8_t kFloor = 0x09, kTruncate = 0x0B;  // vrndscaleps modes

// zmm0-26 hold values; 27 takes a result that a mask then blends in; 28 and 29 are scratch; 30
// holds 1.0 and 31 zero throughout. k7 holds the running lanes (kept in Frame::mask too: calls
// clobber mask registers); operations use k1-k3, the library functions k1-k6.
constexpr int kValueRegisters = 27;
constexpr int kMaskedResult = 27, kScratch = 28, kScratch2 = 29, kOneReg = 30, kZeroReg = 31;
constexpr int kMaskReg = 7;
// Loop iterations one invocation runs in all (as the interpreter's kIterationBudget, but per
// block: only a shader that exhausts it can tell).
constexpr uint32_t kIterationBudget = 1u << 18;
constexpr int kBytesPerValue = kLanes * 4;
// Values a loop keeps in registers (load_resident_values): the rest leave a library operation the
// registers it takes (emit_library_ops.h's scratch, its operands and its result).
constexpr size_t kMaxResident = 10;

// Where the frame's pointers live while the code runs.
constexpr Gpr kSpill = rbx, kSlots = rbp, kConstants = r12, kBlock = r13, kLanesIn = r14, kUniforms = r15;

bool natively_emitted(Op op) {
  switch (op) {
    case Op::Mov: case Op::LoadUniform: case Op::LoadInput: case Op::LoadVarying: case Op::LoadFragCoord:
    case Op::LoadPointCoord: case Op::StoreOutput: case Op::StoreColor: case Op::StoreDepth: case Op::Neg:
    case Op::Abs: case Op::Floor: case Op::Fract: case Op::Trunc: case Op::Sqrt: case Op::Not: case Op::ToBool:
    case Op::Add: case Op::Sub: case Op::Mul: case Op::Div: case Op::Min: case Op::Max: case Op::Step:
    case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne: case Op::And: case Op::Or:
    case Op::Xor: case Op::Clamp: case Op::Mix: case Op::Smoothstep: case Op::Select: case Op::Mad:
    case Op::GatherUniform: case Op::Rsq: case Op::NormScale: case Op::Gather: case Op::Scatter:
      return true;
    default:
      return false;
  }
}

// The library operations emitted natively (emit_library_ops.h), calling out only for blocks whose
// running lanes need what the emitted code leaves out, every register kept around the call.
bool library_op_kind(Op op) { return op == Op::Pow || op == Op::Exp || op == Op::Exp2 || op == Op::Sin || op == Op::Cos; }

// The operations run by call_out: every value operation and the loads without a native form.
bool called_out(Op op) {
  return op == Op::Texture || op == Op::LoadFrontFacing ||
         (op >= Op::Neg && op < Op::Count && !natively_emitted(op));
}

// How many texture lookups from instruction `at` on make one run (FrameTextureRun): those side by
// side, none reading what an earlier one of the run writes.
int texture_run_length(const std::vector<ir::Inst>& insts, const std::vector<ir::TextureLookup>& textures, size_t at) {
  std::vector<Operand> written;
  int n = 0;
  for (size_t i = at; i < insts.size() && n < kMaxTextureRun && insts[i].op == Op::Texture; ++i, ++n) {
    const ir::TextureLookup& t = textures[static_cast<size_t>(insts[i].i0)];
    for (Operand o : {t.sampler, t.coord[0], t.coord[1], t.coord[2], t.coord[3], t.lod})
      if (o != ir::kNone && std::find(written.begin(), written.end(), o) != written.end()) return n;
    written.insert(written.end(), std::begin(t.dst), std::end(t.dst));
  }
  return n;
}

class Generator {
 public:
  // `run_at[i]`: the run of lookups that starts at instruction i (null: none).
  Generator(const std::vector<ir::Inst>& insts, const std::vector<ir::TextureLookup>& textures, int registers, int slots,
            const FrameCall* calls, const FrameTextureLookup* lookups, std::vector<const FrameTextureRun*> run_at)
      : insts_(insts), textures_(textures), calls_(calls), lookups_(lookups), run_at_(std::move(run_at)),
        registers_(registers), slots_(slots) {
    const int constants = constant_count();
    values_ = registers + slots + constants;
    reads_.resize(static_cast<size_t>(values_));
    writes_.resize(static_cast<size_t>(values_));
    where_.assign(static_cast<size_t>(values_), -1);
    zeroed_home_.assign(static_cast<size_t>(values_), false);
    dirty_.assign(static_cast<size_t>(values_), false);
    const int n = static_cast<int>(insts.size());
    for (int i = 0; i < n; ++i) {
      const Op op = insts[static_cast<size_t>(i)].op;
      if (op == Op::Ddx || op == Op::Ddy || op == Op::Texture) last_neighbour_read_ = i;
    }
    masked_from_ = n;
    for (int i = 0; i < n; ++i) {
      if (discard_if_at(i)) i += 2;
      else if (insts[static_cast<size_t>(i)].op <= Op::Discard) masked_from_ = std::min(masked_from_, i);
    }
    std::vector<int> open;
    for (int i = 0; i < n; ++i) {
      const Op op = insts[static_cast<size_t>(i)].op;
      if (op == Op::IfBegin || op == Op::FuncBegin || op == Op::LoopBegin) {
        open.push_back(i);
        max_depth_ = std::max(max_depth_, static_cast<int>(open.size()));
      }
      if ((op == Op::EndIf || op == Op::FuncEnd || op == Op::LoopEnd) && !open.empty()) {
        if (op == Op::LoopEnd) loops_.push_back({open.back(), i});
        open.pop_back();
      }
    }
    for (int i = 0; i < n; ++i) {
      for (Operand o : sources(insts[static_cast<size_t>(i)], i)) reads_[static_cast<size_t>(id(o))].push_back(i);
      for (Operand o : destinations(insts[static_cast<size_t>(i)])) writes_[static_cast<size_t>(id(o))].push_back(i);
    }
    // A value read in a loop is read again by the next iteration: it lives to the loop's end.
    for (const auto& loop : loops_)
      for (auto& r : reads_) {
        const int begin = loop.first, end = loop.second;
        if (std::any_of(r.begin(), r.end(), [&](int at) { return at > begin && at < end; }))
          r.insert(std::upper_bound(r.begin(), r.end(), end), end);
      }
    holder_.fill(-1);
  }

  // False when an instruction has no compiled form: loops, dynamic indexing, a return outside
  // a function, an output stored inside a branch (the interpreter skips it when no lane runs).
  bool generate(const ir::Inst* stable_insts) {
    prologue();
    const int n = static_cast<int>(insts_.size());
    for (int i = 0; i < n; ++i) {
      const ir::Inst& in = insts_[static_cast<size_t>(i)];
      if (i < masked_from_ && discard_if_at(i)) {
        discard_if(i, in);
        i += 2;
        continue;
      }
      switch (in.op) {
        case Op::IfBegin: if_begin(i, in); continue;
        case Op::Else: {
          const Mem entry = entry_slot(top()), cond = cond_slot(top());
          x_.kmovw_load(1, entry);
          x_.kmovw_load(2, cond);
          x_.kandnw(1, 2, 1);
          set_mask(1);
          continue;
        }
        case Op::EndIf:
        case Op::FuncEnd:
          x_.kmovw_load(1, entry_slot(top()));
          stack_.pop_back();
          set_mask(1);
          continue;
        case Op::FuncBegin:
          x_.kmovw_store(entry_slot(static_cast<int>(stack_.size())), kMaskReg);
          stack_.push_back(Op::FuncBegin);
          continue;
        case Op::Return:
          if (std::find(stack_.begin(), stack_.end(), Op::FuncBegin) == stack_.end()) return false;
          x_.kmovw(1, kMaskReg);
          remove_lanes(Op::FuncBegin);
          stop_running();
          continue;
        case Op::Discard: {
          x_.kmovw_to_gpr(rax, kMaskReg);
          x_.mov_load(rdx, {rsp, 0});
          x_.or_store32({rdx, static_cast<int32_t>(offsetof(Frame, discarded))}, rax);
          x_.kmovw(1, kMaskReg);
          remove_lanes(Op::Discard);
          stop_running();
          continue;
        }
        case Op::LoopBegin: loop_begin(i); continue;
        case Op::ContinuePoint:
          x_.kmovw_load(1, cond_slot(top()));  // the loop's running lanes
          set_mask(1);
          continue;
        case Op::LoopEnd: loop_end(i); continue;
        case Op::Break:
          x_.kmovw(1, kMaskReg);
          remove_lanes(Op::LoopBegin);
          stop_running();
          continue;
        case Op::BreakIfNot: {  // the running lanes where a == 0 leave the loop
          uint32_t pinned = resident_sources(in, i);
          const int a = use(in.a, i, pinned);
          x_.vcmpps(1, a, kZeroReg, Cmp::Eq);
          x_.kandw(1, 1, kMaskReg);
          finish_sources(i, in);
          remove_lanes(Op::LoopBegin);
          x_.kandnw(1, 1, kMaskReg);
          set_mask(1);
          continue;
        }
        case Op::Continue:  // the running lanes skip to the loop's continue point
          for (int f = top(); f >= 0 && stack_[static_cast<size_t>(f)] != Op::LoopBegin; --f) {
            x_.kmovw(1, kMaskReg);
            and_not(entry_slot(f));
          }
          stop_running();
          continue;
        case Op::StoreOutput:
        case Op::StoreColor:
        case Op::StoreDepth:
          if (!stack_.empty()) return false;
          break;
        default:
          break;
      }
      if (library_op_kind(in.op))
        library_op(i, stable_insts + i);
      else if (const FrameTextureRun* run = run_at_[static_cast<size_t>(i)]) {
        call_run(i, *run);
        i += run->count - 1;
      } else if (called_out(in.op)) call(i, stable_insts + i);
      else native(i, in);
    }
    epilogue();
    return true;
  }

  const std::vector<uint8_t>& bytes() const { return x_.bytes(); }

 private:
  // if (a) discard;  before any other structure and with no derivative or texture lookup
  // after it, it only adds lanes to the discarded ones: the interpreter's later lanes differ
  // where it stops updating discarded lanes, which only those could see.
  bool discard_if_at(int i) const {
    const size_t at = static_cast<size_t>(i);
    return insts_[at].op == Op::IfBegin && at + 2 < insts_.size() && insts_[at + 1].op == Op::Discard &&
           insts_[at + 2].op == Op::EndIf && last_neighbour_read_ < i;
  }
  // From the first structure on, a value is written only to the running lanes (k7).
  bool masked(int at) const { return at >= masked_from_; }
  int top() const { return static_cast<int>(stack_.size()) - 1; }
  Mem entry_slot(int frame) const { return {rsp, 8 + 4 * frame}; }
  Mem cond_slot(int frame) const { return {rsp, 10 + 4 * frame}; }  // an if's condition, a loop's running lanes
  Mem budget_slot() const { return {rsp, 8 + 4 * max_depth_}; }
  int32_t stack_bytes() const { return 8 + 16 * ((4 * max_depth_ + 4 + 15) / 16); }  // keeps rsp 16-byte aligned
  void set_mask(int k) {
    x_.kmovw(kMaskReg, k);
    x_.mov_load(rdx, {rsp, 0});
    x_.kmovw_store({rdx, static_cast<int32_t>(offsetof(Frame, mask))}, kMaskReg);
  }
  void if_begin(int at, const ir::Inst& in) {
    uint32_t pinned = resident_sources(in, at);
    const int a = use(in.a, at, pinned);
    x_.vcmpps(1, a, kZeroReg, Cmp::Neq);
    x_.kandw(1, 1, kMaskReg);
    const int frame = static_cast<int>(stack_.size());
    x_.kmovw_store(entry_slot(frame), kMaskReg);
    x_.kmovw_store(cond_slot(frame), 1);
    stack_.push_back(Op::IfBegin);
    set_mask(1);
    finish_sources(at, in);
  }
  // The lanes in k1 leave every frame above the innermost one of `stop` kind (all frames for
  // Discard), and that loop's running lanes (the interpreter's remove_lanes).
  void remove_lanes(Op stop) {
    for (int f = top(); f >= 0; --f) {
      const Op kind = stack_[static_cast<size_t>(f)];
      if (kind == stop) {
        if (stop == Op::LoopBegin) and_not(cond_slot(f));
        return;
      }
      and_not(entry_slot(f));
      if (kind == Op::LoopBegin) and_not(cond_slot(f));
    }
  }
  void and_not(Mem slot) {  // slot &= ~k1
    x_.kmovw_load(2, slot);
    x_.kandnw(2, 1, 2);
    x_.kmovw_store(slot, 2);
  }
  void stop_running() {  // no lane runs until a frame ends
    x_.kxorw(1, 1, 1);
    set_mask(1);
  }
  // A register read before anything wrote it holds zero: in its home, for what reads it there.
  void zero_home_if_unwritten(int value, int at) {
    if (!unwritten(value, at)) return;
    x_.store(home(value), kZeroReg);
    zeroed_home_[static_cast<size_t>(value)] = true;
  }
  // Registers hold nothing at a loop's start and at its back edge, so that both agree, nor
  // after a call (which clobbers them all); what instruction `at` or a later one reads goes to
  // its home.
  void flush_registers(int at) {
    for (int r = 0; r < kValueRegisters; ++r) {
      const int v = holder_[static_cast<size_t>(r)];
      if (v < 0 || (resident_registers_ >> r & 1)) continue;
      if (dirty_[static_cast<size_t>(v)] && next_read(v, at - 1) >= 0) x_.store(home(v), r);
      release(r);
    }
  }
  void loop_begin(int at) {
    flush_registers(at);
    int end = at;
    for (auto [b, e] : loops_)
      if (b == at) end = e;
    // A register the loop reads before anything wrote it is zero in the first iteration only.
    for (int v = 0; v < registers_; ++v) {
      const auto& r = reads_[static_cast<size_t>(v)];
      const bool read_inside = std::any_of(r.begin(), r.end(), [&](int q) { return q > at && q < end; });
      if (read_inside) zero_home_if_unwritten(v, at);
    }
    const int frame = static_cast<int>(stack_.size());
    x_.kmovw_store(entry_slot(frame), kMaskReg);
    x_.kmovw_store(cond_slot(frame), kMaskReg);  // a loop frame's running lanes
    stack_.push_back(Op::LoopBegin);
    load_resident_values(at, end);
    loop_starts_.push_back(x_.size());
  }
  // An innermost loop whose body nothing flushes (no call-out that flushes, no inner loop, no
  // indexed registers): the values its body reads most, up to kMaxResident, stay in registers
  // from its start to its end, the same ones at the head and at the back edge, instead of going
  // to their homes at every back edge and coming back (glmark2's loop scene: a five-iteration
  // loop was a third of its frame). Loaded here, before the head.
  void load_resident_values(int at, int end) {
    resident_registers_ = 0;
    std::vector<int> reads(static_cast<size_t>(values_), 0);  // in the body, by value
    std::vector<Operand> operand(static_cast<size_t>(values_), ir::kNone);
    for (int i = at + 1; i < end; ++i) {
      const ir::Inst& in = insts_[static_cast<size_t>(i)];
      if (in.op == Op::LoopBegin || in.op == Op::Gather || in.op == Op::Scatter || in.op == Op::Texture ||
          run_at_[static_cast<size_t>(i)] ||
          (called_out(in.op) && !library_op_kind(in.op)))
        return;
      for (Operand o : sources(in, i)) {
        ++reads[static_cast<size_t>(id(o))];
        operand[static_cast<size_t>(id(o))] = o;
      }
    }
    std::vector<std::pair<int, Operand>> read_counts;  // (reads in the body, operand), most first
    for (int v = 0; v < values_; ++v)
      if (reads[static_cast<size_t>(v)] > 0) read_counts.push_back({reads[static_cast<size_t>(v)], operand[static_cast<size_t>(v)]});
    std::stable_sort(read_counts.begin(), read_counts.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    if (read_counts.size() > kMaxResident) read_counts.resize(kMaxResident);
    uint32_t pinned = 0;
    for (const auto& read : read_counts) {
      const int r = use(read.second, at, pinned);
      // A register value's register may differ from its home from the second iteration on: a
      // call-out that keeps the registers (a library operation's) must store it first.
      if (const int v = id(read.second); v < registers_) dirty_[static_cast<size_t>(v)] = true;
      resident_registers_ |= 1u << r;
    }
  }
  // Again while any lane runs and the invocation's iteration budget lasts; then the lanes that
  // entered the loop go on.
  void loop_end(int at) {
    flush_registers(at);
    const int frame = top();
    x_.kmovw_load(1, cond_slot(frame));
    x_.kortestw(1, 1);
    const size_t none_running = x_.jump_if_zero();
    x_.dec32(budget_slot());
    const size_t budget_spent = x_.jump_if_not_greater();
    set_mask(1);
    x_.jump_back(loop_starts_.back());
    x_.patch_jump(none_running);
    x_.patch_jump(budget_spent);
    loop_starts_.pop_back();
    x_.kmovw_load(1, entry_slot(frame));
    stack_.pop_back();
    set_mask(1);
    resident_registers_ = 0;  // (the values stay held, dirty)
  }

  int constant_count() const {
    int n = 0;
    for (const ir::Inst& in : insts_)
      for (Operand o : sources(in, -1))
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
  // The values instruction `at` reads; under a mask, also the old values of its destinations,
  // which the lanes that do not run keep.
  std::vector<Operand> sources(const ir::Inst& in, int at) const {
    std::vector<Operand> s;
    if (in.op == Op::Texture) {
      const ir::TextureLookup& t = textures_[static_cast<size_t>(in.i0)];
      for (Operand o : {t.sampler, t.coord[0], t.coord[1], t.coord[2], t.coord[3], t.lod})
        if (o != ir::kNone) s.push_back(o);
    } else {
      for (Operand o : {in.a, in.b, in.c})
        if (o != ir::kNone) s.push_back(o);
      if (in.op == Op::Gather || in.op == Op::Scatter)  // the indexed registers, all of them
        for (int k = 0; k <= in.i1; ++k) s.push_back(in.i0 + k);
    }
    if (masked(at))
      for (Operand d : destinations(in)) s.push_back(d);
    return s;
  }
  // The homes of the registers a gather or scatter indexes hold their values (zero for the
  // unwritten); after a scatter (`written`), the homes alone do.
  void sync_indexed_registers(int at, const ir::Inst& in, bool written) {
    for (int v = in.i0; v <= in.i0 + in.i1; ++v) {
      const int r = where_[static_cast<size_t>(v)];
      if (r >= 0 && dirty_[static_cast<size_t>(v)]) {
        x_.store(home(v), r);
        dirty_[static_cast<size_t>(v)] = false;
      }
      if (r >= 0 && written) release(r);
      zero_home_if_unwritten(v, at);
      if (written) zeroed_home_[static_cast<size_t>(v)] = true;
    }
  }
  // kScratch = the lanes' offsets (in floats, from the first indexed register's home) of
  // register i0 + clamp_index(a, i1), as the interpreter's Gather and Scatter index.
  void indexed_lane_offsets(int a, int32_t limit) {
    clamped_index(a, limit);
    x_.vpslld(kScratch, kScratch, 4);  // kLanes floats per register
    x_.mov_imm(rax, reinterpret_cast<uint64_t>(kLaneIndex));
    x_.load(kScratch2, {rax, 0});
    x_.vpaddd(kScratch, kScratch, kScratch2);
  }
  // kScratch = clamp_index(a, limit) per lane: negative and NaN give 0, beyond the limit it.
  void clamped_index(int a, int32_t limit) {
    x_.vcvttps2dq(kScratch, a);  // out of range: 0x80000000, which the unsigned min clamps
    x_.vcmpps(1, a, kZeroReg, Cmp::Ge);
    x_.vmovaps(kScratch, kScratch, 1, true);
    x_.mov_imm32(rax, static_cast<uint32_t>(limit));
    x_.vpbroadcastd(kScratch2, rax);
    x_.vpminud(kScratch, kScratch, kScratch2);
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
  // Before a new value of instruction `at` takes the register: a gather's or scatter's indexed
  // registers are read at `at` itself, from their homes.
  void spill_if_needed(int reg, int at) {
    const int v = holder_[static_cast<size_t>(reg)];
    if (v >= 0 && dirty_[static_cast<size_t>(v)] && next_read(v, at - 1) >= 0) {
      x_.store(home(v), reg);
      dirty_[static_cast<size_t>(v)] = false;
    }
  }
  // A register for a new value at instruction `at`, not one of `pinned`.
  int allocate(int at, uint32_t pinned) {
    pinned |= resident_registers_;
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
    if (value >= registers_ || zeroed_home_[static_cast<size_t>(value)]) return false;
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
    x_.add_rsp(-stack_bytes());  // [rsp]: the frame pointer; then the open frames' lane masks
    x_.mov_store({rsp, 0}, rdi);
    x_.kmovw_load(kMaskReg, {rdi, static_cast<int32_t>(offsetof(Frame, mask))});
    x_.mov_store_imm32(budget_slot(), kIterationBudget);
    x_.mov_load(kSpill, {rdi, static_cast<int32_t>(offsetof(Frame, spill))});
    x_.mov_load(kSlots, {rdi, static_cast<int32_t>(offsetof(Frame, slots))});
    x_.mov_load(kConstants, {rdi, static_cast<int32_t>(offsetof(Frame, constants))});
    x_.mov_load(kBlock, {rdi, static_cast<int32_t>(offsetof(Frame, block_or_outputs))});
    x_.mov_load(kLanesIn, {rdi, static_cast<int32_t>(offsetof(Frame, lanes_in))});
    x_.mov_load(kUniforms, {rdi, static_cast<int32_t>(offsetof(Frame, uniforms))});
    fixed_registers();
  }
  void epilogue() {
    x_.add_rsp(stack_bytes());
    for (Gpr r : {r15, r14, r13, r12, rbp, rbx}) x_.pop(r);
    x_.vzeroupper();
    x_.ret();
  }

  // Everything the call-out reads or what outlives it goes to memory; no register survives.
  void call(int at, const ir::Inst* stable) {
    flush_registers(at);
    for (Operand o : sources(*stable, at)) zero_home_if_unwritten(id(o), at);
    if (stable->op == Op::Texture) emit_call(&call_texture, &lookups_[stable->i0]);
    else emit_call(&call_out, &calls_[at]);
  }
  // A run of lookups from instruction `at` on, as call() makes each in turn.
  void call_run(int at, const FrameTextureRun& run) {
    flush_registers(at);
    for (int k = at; k < at + run.count; ++k)
      for (Operand o : sources(insts_[static_cast<size_t>(k)], k)) zero_home_if_unwritten(id(o), k);
    emit_call(&call_texture_run, &run);
  }
  // function(frame, operands); then the fixed registers and k7 again.
  template <typename Operands>
  void emit_call(void (*function)(const Frame*, const Operands*), const Operands* operands) {
    x_.vzeroupper();
    x_.mov_load(rdi, {rsp, 0});
    x_.mov_imm(rsi, reinterpret_cast<uint64_t>(operands));
    x_.mov_imm(rax, reinterpret_cast<uint64_t>(function));
    x_.call(rax);
    fixed_registers();
    x_.mov_load(rdx, {rsp, 0});
    x_.kmovw_load(kMaskReg, {rdx, static_cast<int32_t>(offsetof(Frame, mask))});
  }

  // pow, sin and cos natively (emit_library_ops.h); a block whose running lanes need what the
  // emitted code leaves out calls out, every register-held value kept around the call.
  void library_op(int at, const ir::Inst* stable) {
    const ir::Inst& in = *stable;
    uint32_t pinned = resident_sources(in, at);
    LibraryOpRegisters r{};
    r.x = use(in.a, at, pinned);
    r.y = in.op == Op::Pow ? use(in.b, at, pinned) : r.x;
    // (A call-out reads the operands, and under a mask the destination's old value, from their
    // homes: emit_call_out_keeping_registers stores them there with every other held value.)
    const int old = masked(at) ? use(in.d, at, pinned) : -1;
    r.scratch[0] = kScratch;
    r.scratch[1] = kScratch2;
    const int scratch = in.op == Op::Pow ? kPowScratch : in.op == Op::Sin || in.op == Op::Cos ? kSinCosScratch : kExpScratch;
    for (int k = 2; k < scratch; ++k) {
      r.scratch[k] = allocate(at, pinned);
      pinned |= 1u << r.scratch[k];
    }
    r.result = kMaskedResult;
    r.one = kOneReg;
    r.zero = kZeroReg;
    r.running_mask = kMaskReg;
    const size_t needs_call = in.op == Op::Pow                         ? emit_pow(x_, r)
                              : in.op == Op::Exp || in.op == Op::Exp2 ? emit_exp(x_, r, in.op == Op::Exp)
                                                                      : emit_sin_cos(x_, r, in.op == Op::Cos);
    if (needs_call) emit_call_out_keeping_registers(at, needs_call);
    finish_sources(at, in);
    const int dv = id(in.d);
    const int d = destination(at, in, dv);
    if (old >= 0) x_.vblendmps(d, kMaskReg, old, kMaskedResult);
    else x_.vmovaps(d, kMaskedResult);
    hold(d, dv, at);
  }
  // The jump at `site` goes to a call-out of instruction `at` (its result into kMaskedResult),
  // around which every register-held value is kept; the code before it goes on after.
  void emit_call_out_keeping_registers(int at, size_t site) {
    const size_t done = x_.jump();
    x_.patch_jump(site);
    for (int reg = 0; reg < kValueRegisters; ++reg) {
      const int v = holder_[static_cast<size_t>(reg)];
      if (v >= 0 && dirty_[static_cast<size_t>(v)]) x_.store(home(v), reg);
    }
    emit_call(&call_out, &calls_[at]);
    for (int reg = 0; reg < kValueRegisters; ++reg) {
      const int v = holder_[static_cast<size_t>(reg)];
      if (v >= 0) x_.load(reg, home(v));
    }
    x_.load(kMaskedResult, home(id(insts_[static_cast<size_t>(at)].d)));
    x_.patch_jump(done);
  }
  // Register d holds value dv, written by instruction `at`.
  void hold(int d, int dv, int at) {
    holder_[static_cast<size_t>(d)] = dv;
    where_[static_cast<size_t>(dv)] = d;
    dirty_[static_cast<size_t>(dv)] = true;
    if (next_read(dv, at) < 0 && !resident(d)) release(d);
  }
  bool resident(int reg) const { return resident_registers_ >> reg & 1; }
  // The register for instruction `at`'s new value of dv: a loop-resident value's own, else one
  // allocated (its old one released first).
  int destination(int at, const ir::Inst& in, int dv) {
    const int held = where_[static_cast<size_t>(dv)];
    if (held >= 0 && resident(held)) return held;
    if (held >= 0) release(held);
    return allocate(at, resident_sources(in, at));
  }

  void native(int at, const ir::Inst& in) {
    uint32_t pinned = resident_sources(in, at);  // a source's load must not evict another
    int a = -1, b = -1, c = -1, old = -1;
    if (in.a != ir::kNone) a = use(in.a, at, pinned);
    if (in.b != ir::kNone) b = use(in.b, at, pinned);
    if (in.c != ir::kNone) c = use(in.c, at, pinned);
    if (masked(at) && !destinations(in).empty()) old = use(in.d, at, pinned);
    switch (in.op) {
      case Op::StoreOutput: x_.store({kBlock, in.i0 * kBytesPerValue}, a); return finish_sources(at, in);
      case Op::StoreDepth: x_.store({kBlock, static_cast<int32_t>(offsetof(FragmentBlock, depth))}, a); return finish_sources(at, in);
      case Op::Scatter:  // register i0 + clamp_index(a, i1) = b in the running lanes
        sync_indexed_registers(at, in, true);
        indexed_lane_offsets(a, in.i1);
        x_.kmovw(3, kMaskReg);
        x_.vscatterdps(kSpill, kScratch, in.i0 * kBytesPerValue, 3, b);
        return finish_sources(at, in);
      case Op::StoreColor: {
        const int32_t color = static_cast<int32_t>(offsetof(FragmentBlock, color));
        x_.store({kBlock, color + in.i0 * kBytesPerValue}, a);  // buffer i0 >> 2, component i0 & 3
        return finish_sources(at, in);
      }
      default:
        break;
    }
    if (in.op == Op::Gather) sync_indexed_registers(at, in, false);
    // A run of uniform gathers with one index (the elements of a matrix in a uniform array:
    // glsl_skinned's bones) clamps it once: kScratch holds it from the gather just before (nothing
    // between two instructions' emissions uses kScratch).
    const ir::Inst* before = at > 0 ? &insts_[static_cast<size_t>(at - 1)] : nullptr;
    gather_index_ready_ = in.op == Op::GatherUniform && before && before->op == Op::GatherUniform &&
                          before->a == in.a && before->i1 == in.i1 && before->d != in.a;
    finish_sources(at, in);
    // The destination's old value ends here; the sequence below writes d last.
    const int dv = id(in.d);
    const int d = destination(at, in, dv);
    if (old >= 0) {  // the running lanes take the result, the others keep the old value
      emit(in, kMaskedResult, a, b, c);
      x_.vblendmps(d, kMaskReg, old, kMaskedResult);
    } else {
      emit(in, d, a, b, c);
    }
    hold(d, dv, at);
  }
  // Sources read for the last time here free their registers (the destination may take one).
  void finish_sources(int at, const ir::Inst& in) {
    for (Operand o : sources(in, at)) {
      const int v = id(o);
      const int r = where_[static_cast<size_t>(v)];
      if (r >= 0 && next_read(v, at) < 0 && !resident(r)) release(r);
    }
  }
  // The registers holding operands the instruction reads from registers (a gather's or
  // scatter's indexed registers are read from their homes): a new value must not take them.
  uint32_t resident_sources(const ir::Inst& in, int at) const {
    uint32_t pinned = 0;
    const std::vector<Operand> all = sources(in, at);
    const bool indexed = in.op == Op::Gather || in.op == Op::Scatter;
    for (Operand o : all) {
      if (indexed && o >= in.i0 && o <= in.i0 + in.i1 && o != in.a && o != in.b && o != in.d) continue;
      const int r = where_[static_cast<size_t>(id(o))];
      if (r >= 0) pinned |= 1u << r;
    }
    return pinned;
  }

  // The running lanes where a != 0 join the frame's discarded lanes.
  void discard_if(int at, const ir::Inst& in) {
    uint32_t pinned = resident_sources(in, at);
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
  // +0 as the lane routines give it (they convert through an integer): adding +0 turns -0 into +0
  // (round to nearest, as shaders run) and leaves every other value, a NaN a NaN. d is written last.
  void round_to(int d, int a, uint8_t mode) {
    x_.vrndscaleps(kScratch, a, mode);
    x_.vaddps(d, kScratch, kZeroReg);
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
      case Op::GatherUniform:  // uniforms[i0 + clamp_index(a, i1)]
        if (!gather_index_ready_) clamped_index(a, in.i1);
        x_.kxnorw(3, 3, 3);
        return x_.vgatherdps(d, 3, kUniforms, kScratch, in.i0 * 4);
      case Op::Gather:  // register i0 + clamp_index(a, i1), from its home
        indexed_lane_offsets(a, in.i1);
        x_.kxnorw(3, 3, 3);
        return x_.vgatherdps(d, 3, kSpill, kScratch, in.i0 * kBytesPerValue);
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
      case Op::Smoothstep:  // t * t * (3 - 2 * t), t = lane_min(lane_max((c - a) / (b - a), 0), 1)
        x_.vsubps(kScratch, c, a);
        x_.vsubps(kScratch2, b, a);
        x_.vdivps(kScratch, kScratch, kScratch2);
        min_max(kScratch, kScratch, kZeroReg, true);
        min_max(kScratch, kScratch, kOneReg, false);
        pool(d, kThree);  // (the operands are read: d may be one of them)
        x_.vaddps(kScratch2, kScratch, kScratch);  // 2 * t, exactly
        x_.vsubps(d, d, kScratch2);
        x_.vmulps(kScratch2, kScratch, kScratch);
        return x_.vmulps(d, kScratch2, d);
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
  const FrameCall* calls_;             // insts_' operands found, at addresses that stay
  const FrameTextureLookup* lookups_;  // textures_' likewise
  const std::vector<const FrameTextureRun*> run_at_;
  int registers_, slots_, values_ = 0;
  std::vector<std::vector<int>> reads_, writes_;
  std::vector<int> where_;
  std::vector<bool> dirty_;
  std::vector<bool> zeroed_home_;  // unwritten registers whose home a call-out reads
  int last_neighbour_read_ = -1;   // the last derivative or texture lookup
  bool gather_index_ready_ = false;  // kScratch holds this GatherUniform's clamped index
  int masked_from_ = 0;            // the first structure instruction (but discard_if_at's)
  int max_depth_ = 0;
  std::vector<Op> stack_;          // the open frames while generating: IfBegin, FuncBegin or LoopBegin
  std::vector<std::pair<int, int>> loops_;  // each loop's LoopBegin and LoopEnd
  std::vector<size_t> loop_starts_;         // the open loops' first instructions in the code
  std::array<int, kValueRegisters> holder_;
  uint32_t resident_registers_ = 0;  // the registers of the loop-resident values (load_resident_values)
  X86Encoder x_;
};

}  // namespace

std::unique_ptr<CompiledStage> CompiledStage::compile(const std::vector<ir::Inst>& insts,
                                                      const std::vector<ir::TextureLookup>& textures, int registers,
                                                      int slots) {
  std::unique_ptr<CompiledStage> stage(new CompiledStage);
  // Never resized again: the code holds the addresses of their elements.
  for (const ir::Inst& in : insts)
    stage->calls_.push_back({in.op, frame_operand(in.d, registers), frame_operand(in.a, registers),
                             frame_operand(in.b, registers), frame_operand(in.c, registers)});
  for (const ir::TextureLookup& t : textures) {
    FrameTextureLookup& f = stage->lookups_.emplace_back();
    f.lookup = t;
    for (int c = 0; c < 4; ++c) {
      f.coord[c] = frame_operand(t.coord[c], registers);
      f.dst[c] = frame_operand(t.dst[c], registers);
    }
    f.sampler = frame_operand(t.sampler, registers);
    f.lod = frame_operand(t.lod, registers);
  }
  std::vector<std::pair<size_t, int>> run_starts;  // first instruction, lookups
  for (size_t i = 0; i < insts.size(); ++i) {
    const int n = insts[i].op == Op::Texture ? texture_run_length(insts, textures, i) : 0;
    if (n > 1) {
      run_starts.emplace_back(i, n);
      i += static_cast<size_t>(n - 1);
    }
  }
  stage->runs_.resize(run_starts.size());  // never resized again: the code holds their addresses
  std::vector<const FrameTextureRun*> run_at(insts.size(), nullptr);
  for (size_t r = 0; r < run_starts.size(); ++r) {
    FrameTextureRun& run = stage->runs_[r];
    const size_t first = run_starts[r].first;
    run.count = run_starts[r].second;
    const ir::TextureLookup& head = textures[static_cast<size_t>(insts[first].i0)];
    run.one_2d_sampler = true;
    for (int k = 0; k < run.count; ++k) {
      const int index = insts[first + static_cast<size_t>(k)].i0;
      const ir::TextureLookup& t = textures[static_cast<size_t>(index)];
      run.lookups[k] = &stage->lookups_[static_cast<size_t>(index)];
      run.s[k] = run.lookups[k]->coord[0];
      run.t[k] = run.lookups[k]->coord[1];
      for (int c = 0; c < 4; ++c) run.dst[k][c] = run.lookups[k]->dst[c];
      run.one_2d_sampler = run.one_2d_sampler && t.kind == SamplerKind::Tex2D && t.mode == LodMode::Implicit &&
                           t.sampler == head.sampler;
    }
    run_at[first] = &run;
  }
  Generator generator(insts, textures, registers, slots, stage->calls_.data(), stage->lookups_.data(), std::move(run_at));
  if (!generator.generate(insts.data())) return nullptr;
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
