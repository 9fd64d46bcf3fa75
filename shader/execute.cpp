#include "shader/execute.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

#include "raster/simd_path.h"
#include "shader/hoist.h"
#include "shader/jit/compiled_stage.h"

// The vector helpers pass 32- and 64-byte vectors but are always inlined into one copy.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace pineda::shader {

using ir::Op;
using ir::Operand;

namespace {

constexpr int kStackFrames = 64;
// Loop iterations one invocation may run in total (all loops together): a shader with an
// unbounded loop ends instead of hanging the draw.
constexpr int kIterationBudget = 1 << 18;

struct Frame {
  Op kind;
  RunMask entry;    // lanes that continue after the construct
  RunMask cond;     // if: lanes that took the then branch
  RunMask running;  // loop: lanes still iterating
};

inline int clamp_index(float x, int limit) {
  if (!(x >= 0.0f)) return 0;  // negative or NaN
  if (x >= static_cast<float>(limit)) return limit;
  return static_cast<int>(x);
}

// Whether straight-line code (no structure, no dynamic indexing) writes every register before
// reading it: run with every lane, it then needs no zeroed register file. Slots (registers
// from `registers` up) are always filled.
bool writes_before_reads(const std::vector<ir::Inst>& insts, const std::vector<ir::TextureLookup>& textures,
                         int registers) {
  std::vector<char> written(static_cast<size_t>(registers), 0);
  auto read_ok = [&](Operand o) { return o == ir::kNone || ir::is_const(o) || o >= registers || written[static_cast<size_t>(o)]; };
  auto write = [&](Operand o) {
    if (o != ir::kNone && o >= 0 && o < registers) written[static_cast<size_t>(o)] = 1;
  };
  for (const ir::Inst& in : insts) {
    if (in.op <= Op::Discard || in.op == Op::Gather || in.op == Op::Scatter) return false;
    if (in.op == Op::Texture) {
      const ir::TextureLookup& t = textures[static_cast<size_t>(in.i0)];
      if (!read_ok(t.sampler) || !read_ok(t.lod)) return false;
      for (Operand c : t.coord)
        if (!read_ok(c)) return false;
      for (Operand d : t.dst) write(d);
      continue;
    }
    if (!read_ok(in.a) || !read_ok(in.b) || !read_ok(in.c)) return false;
    write(in.d);
  }
  return true;
}

}  // namespace

void StageCode::prepare() {
  HoistedCode hoisted = hoist_uniform_operations(code);
  exec = std::move(hoisted.insts);
  exec_textures = std::move(hoisted.textures);
  straight_line = writes_before_reads(exec, exec_textures, code.registers);
  if (jit::compiled_tier_enabled())
    compiled = jit::CompiledStage::compile(exec, exec_textures, code.registers, hoisted.slots);
  uniform_ops = std::move(hoisted.uniform_ops);
  slots = hoisted.slots;
  for (ir::Inst& in : exec) {
    if (in.op == Op::Texture) continue;  // its operands stay in code.textures
    in.d = byte_offset(in.d);
    in.a = byte_offset(in.a);
    in.b = byte_offset(in.b);
    in.c = byte_offset(in.c);
    if (in.op == Op::Gather || in.op == Op::Scatter) in.i0 = offset(in.i0);
  }
  exec.push_back(ir::Inst{Op::Count});  // the executor's end: its handler leaves the run
  int depth = 0;
  max_depth = 0;
  for (const ir::Inst& in : code.insts) {
    if (in.op == Op::IfBegin || in.op == Op::LoopBegin || in.op == Op::FuncBegin) max_depth = std::max(max_depth, ++depth);
    if (in.op == Op::EndIf || in.op == Op::LoopEnd || in.op == Op::FuncEnd) --depth;
  }
  constexpr int kRunLanes = kMaxBlocksPerRun * kLanes;
  constant_lanes.resize(code.constants.size() * kRunLanes);
  for (size_t i = 0; i < code.constants.size(); ++i)
    for (int l = 0; l < kRunLanes; ++l) constant_lanes[i * kRunLanes + l] = code.constants[i];
}

void StageCode::compute_uniform_ops(const float* uniforms, float* slot_lanes) const {
  if (slots == 0) return;
  // The scalar semantics constant folding uses: the same values the lanes would compute.
  const ir::FlushDenormals flush;
  // One float per slot while computing (a slot no operation writes stays 0), splatted at the end.
  constexpr int kStackSlots = 512;
  float stack_values[kStackSlots];
  std::vector<float> heap_values;
  float* const values = slots <= kStackSlots ? stack_values : (heap_values.resize(static_cast<size_t>(slots)), heap_values.data());
  std::fill_n(values, slots, 0.f);
  auto value = [&](Operand o) -> float& { return values[o - code.registers]; };
  auto read = [&](Operand o) { return ir::is_const(o) ? code.const_value(o) : value(o); };
  for (const ir::Inst& in : uniform_ops) {
    float v = 0.0f;
    if (in.op == Op::LoadUniform) v = uniforms[in.i0];
    else if (const int arity = ir::op_arity(in.op); arity == 1) v = ir::eval_unary(in.op, read(in.a));
    else if (arity == 2) v = ir::eval_binary(in.op, read(in.a), read(in.b));
    else v = ir::eval_ternary(in.op, read(in.a), read(in.b), read(in.c));
    value(in.d) = v;
  }
  for (int s = 0; s < slots; ++s) std::fill_n(slot_lanes + static_cast<size_t>(s) * kLanes, kLanes, values[s]);
}

namespace {

// Three copies of the executor: baseline x86-64 (SSE2), AVX2 and AVX-512 (one 16-lane register
// per value), chosen once at run time as raster/simd_path.h chooses (PINEDA_SIMD).
#define PINEDA_EXEC_VECTOR_BYTES 16
namespace exec_baseline {
#include "shader/execute_body.inc"
}  // namespace exec_baseline

#pragma GCC push_options
#pragma GCC target("avx2")
#undef PINEDA_EXEC_VECTOR_BYTES
#define PINEDA_EXEC_VECTOR_BYTES 32
namespace exec_avx2 {
#include "shader/execute_body.inc"
}  // namespace exec_avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512bw,avx512vl,avx512dq,prefer-vector-width=512")
#undef PINEDA_EXEC_VECTOR_BYTES
#define PINEDA_EXEC_VECTOR_BYTES 64
namespace exec_avx512 {
#include "shader/execute_body.inc"
}  // namespace exec_avx512
#pragma GCC pop_options
#undef PINEDA_EXEC_VECTOR_BYTES

using Executor = RunMask (*)(const StageCode&, Stage, RunMask, const LaneIo&);

// Runs of 1, 2 and 4 blocks.
struct Executors {
  Executor one, two, four;
};

Executors choose_executors() {
  const raster::SimdPath path = raster::simd_path_from_environment();
  if (raster::uses_avx512(path)) return {&exec_avx512::run<1>, &exec_avx512::run<2>, &exec_avx512::run<4>};
  if (raster::uses_avx2(path)) return {&exec_avx2::run<1>, &exec_avx2::run<2>, &exec_avx2::run<4>};
  return {&exec_baseline::run<1>, &exec_baseline::run<2>, &exec_baseline::run<4>};
}

}  // namespace

namespace {

// Whether the compiled code gives what the interpreter gives under this mask: every lane's
// value depends only on its own lanes except for derivatives, which read the other lanes of
// their quad (which the interpreter holds at zero when they do not run).
bool compiled_code_fits(Stage kind, int blocks, RunMask mask) {
  if (kind != Stage::Fragment) return true;
  for (int k = 0; k < blocks; ++k) {
    const LaneMask m = static_cast<LaneMask>(mask >> (k * kLanes));
    for (int q = 0; q < 4; ++q) {
      const unsigned quad = m >> (4 * q) & 0xFu;
      if (quad != 0 && quad != 0xFu) return false;
    }
  }
  return true;
}

RunMask run_compiled(const StageCode& stage, Stage kind, int blocks, RunMask mask, const LaneIo& io) {
  const ir::FlushDenormals flush(io.denormals_flushed);
  alignas(64) float stack_spill[kStackLaneFloats];
  std::unique_ptr<float[]> heap_spill;
  float* spill = stack_spill;
  if (static_cast<size_t>(stage.code.registers) * kLanes > static_cast<size_t>(kStackLaneFloats)) {
    heap_spill.reset(new float[static_cast<size_t>(stage.code.registers) * kLanes]);
    spill = heap_spill.get();
  }
  const float* slots = io.slot_lanes;
  std::unique_ptr<float[]> computed;
  if (stage.slots && !slots) {
    computed.reset(new float[static_cast<size_t>(stage.slots) * kLanes]);
    stage.compute_uniform_ops(io.uniforms, computed.get());
    slots = computed.get();
  }
  jit::Frame frame{spill, slots, stage.constant_lanes.data(), io.uniforms, nullptr, nullptr, &stage, io.textures, kind, 0, 0, 0};
  RunMask discarded = 0;
  for (int k = 0; k < blocks; ++k) {
    const LaneMask running = static_cast<LaneMask>(mask >> (k * kLanes));
    if (!running) continue;
    frame.mask = running;  // the code narrows it in branches
    frame.needed = io.needed[k];
    if (kind == Stage::Fragment) {
      frame.block_or_outputs = io.blocks[k];
      frame.lanes_in = io.blocks[k]->varyings;
    } else {
      frame.block_or_outputs = io.outputs[k];
      frame.lanes_in = io.inputs[k];
    }
    frame.discarded = 0;
    stage.compiled->run(frame);
    discarded |= static_cast<RunMask>(frame.discarded & running) << (k * kLanes);
  }
  return discarded;
}

// The frame's lane buffers by jit::FrameOperand::base: an operand's lanes.
struct FrameBases {
  explicit FrameBases(const jit::Frame& frame)
      : at{const_cast<float*>(kZeros), const_cast<float*>(frame.constants), frame.spill, const_cast<float*>(frame.slots)} {}
  float* operator()(jit::FrameOperand o) const { return at[o.base] + o.offset; }
  static constexpr float kZeros[kLanes] = {};
  float* const at[4];
};

// The lanes of an operand of compiled code in its frame.
float* frame_lanes(const jit::Frame& frame, jit::FrameOperand o) { return FrameBases(frame)(o); }

}  // namespace

// Only compiled code calls it (and call_texture), which runs only where the CPU has AVX-512:
// its lane copies are whole-register moves.
#if !defined(__clang__)
__attribute__((target("avx512f,avx512bw,avx512vl,avx512dq")))
#endif
void jit::call_out(const Frame* frame, const FrameCall* in) {
  auto lanes = [&](FrameOperand o) { return frame_lanes(*frame, o); };
  // The running lanes take the result; the others keep their values, as in the interpreter.
  alignas(64) float T[kLanes];
  if (in->op == Op::LoadFrontFacing) {
    const auto* block = static_cast<const FragmentBlock*>(frame->block_or_outputs);
    for (int l = 0; l < kLanes; ++l) T[l] = (block->front_facing >> l & 1) ? 1.0f : 0.0f;
  } else {
    exec_avx512::run_lanes(in->op, frame->kind, T, lanes(in->a), lanes(in->b), lanes(in->c));
  }
  if (frame->mask == 0xFFFF) std::memcpy(lanes(in->d), T, sizeof T);
  else exec_avx512::blend_lanes(lanes(in->d), T, frame->mask, kLanes);
}

jit::FrameOperand jit::frame_operand(ir::Operand o, int registers) {
  if (o == ir::kNone) return {0, 0};
  if (ir::is_const(o)) return {1, static_cast<uint32_t>(ir::const_index(o) * kConstantStride)};
  if (o < registers) return {2, static_cast<uint32_t>(o * kLanes)};
  return {3, static_cast<uint32_t>((o - registers) * kLanes)};
}

namespace {

// call_texture's general route, apart so that the short one's frame stays small (together they
// realigned the stack and saved six registers for every lookup).
#if !defined(__clang__)
__attribute__((target("avx512f,avx512bw,avx512vl,avx512dq")))
#endif
[[gnu::noinline]] void texture_lanes_of_frame(const jit::Frame* frame, const jit::FrameTextureLookup* t) {
  auto lanes = [&](jit::FrameOperand o) { return frame_lanes(*frame, o); };
  const float* coord[4];
  float* dst[4];
  for (int c = 0; c < 4; ++c) {
    coord[c] = lanes(t->coord[c]);
    dst[c] = lanes(t->dst[c]);
  }
  exec_avx512::texture_lanes(frame->textures, t->lookup, coord, lanes(t->sampler),
                             t->lookup.lod == ir::kNone ? nullptr : lanes(t->lod), frame->mask, frame->needed, dst);
}

}  // namespace

void jit::call_texture(const Frame* frame, const FrameTextureLookup* t) {
  auto lanes = [&](FrameOperand o) { return frame_lanes(*frame, o); };
  const float* const coord[4] = {lanes(t->coord[0]), lanes(t->coord[1]), nullptr, nullptr};  // (2D: s and t)
  float* const dst[4] = {lanes(t->dst[0]), lanes(t->dst[1]), lanes(t->dst[2]), lanes(t->dst[3])};
  if (sample_whole_2d_block(frame->textures, t->lookup, coord, lanes(t->sampler), frame->mask, frame->needed, dst)) return;
  texture_lanes_of_frame(frame, t);
}

void jit::call_texture_run(const Frame* frame, const FrameTextureRun* run) {
  if (run->one_2d_sampler && frame->textures && frame->mask == 0xFFFF && frame->needed) {
    const FrameBases lanes(*frame);
    const float* s[kMaxTextureRun];
    const float* t[kMaxTextureRun];
    float* dst[kMaxTextureRun][4];
    for (int k = 0; k < run->count; ++k) {
      s[k] = lanes(run->s[k]);
      t[k] = lanes(run->t[k]);
      for (int c = 0; c < 4; ++c) dst[k][c] = lanes(run->dst[k][c]);
    }
    const int unit = sampler_unit(lanes(run->lookups[0]->sampler)[0]);
    if (frame->textures->sample_2d_blocks(unit, run->count, s, t, frame->needed, dst)) return;
  }
  for (int k = 0; k < run->count; ++k) call_texture(frame, run->lookups[k]);
}

bool runs_compiled(const StageCode& stage, Stage kind, int blocks, RunMask mask) {
  return stage.compiled && compiled_code_fits(kind, blocks, mask);
}

RunMask execute(const StageCode& stage, Stage kind, int blocks, RunMask mask, const LaneIo& io) {
  if (runs_compiled(stage, kind, blocks, mask)) return run_compiled(stage, kind, blocks, mask, io);
  static const Executors run = choose_executors();
  if (blocks >= 4) return run.four(stage, kind, mask, io);
  return blocks == 2 ? run.two(stage, kind, mask, io) : run.one(stage, kind, mask, io);
}

}  // namespace pineda::shader
