// The lane executor: runs one stage's IR over the 16 lanes of up to four blocks at once, with
// execution masks.
#pragma once
#include <memory>

#include "shader/ir.h"
#include "shader/program.h"

namespace pineda::shader {

namespace jit {
class CompiledStage;
}

// A whole block's 2D lookup (the common one) by the textures' shorter route
// (TextureAccess::sample_2d_block), if the lookup and the textures allow it: true when done.
inline bool sample_whole_2d_block(const TextureAccess* textures, const ir::TextureLookup& t, const float* const coord[4],
                                  const float* sampler, LaneMask block_mask, LaneMask needed, float* const dst[4]) {
  return textures && t.kind == SamplerKind::Tex2D && t.mode == LodMode::Implicit && block_mask == 0xFFFF && needed &&
         textures->sample_2d_block(sampler_unit(sampler[0]), coord[0], coord[1], needed, dst);
}

// A run executes one instruction over the lanes of several fragment blocks together
// (kMaxBlocksPerRun, program.h), so that each dispatch does more work: lane l of block b is
// lane b * kLanes + l of the run.
using RunMask = uint64_t;

// A stage's code ready to run: the IR, and the same instructions with every value operand
// turned into an offset into one lane buffer (constants, splatted, then registers, then the
// slots of the uniform-only operations, shader/hoist.h), so that the executor reads operands
// without a branch. offset() counts kLanes floats per register; a run of several blocks
// scales it by its block count.
struct StageCode {
  ir::Code code;
  std::vector<float> constant_lanes;  // [constant][kMaxBlocksPerRun * kLanes]
  std::vector<ir::Inst> exec;         // code.insts without uniform_ops, operands as byte_offset()s, then Op::Count
  std::vector<ir::TextureLookup> exec_textures;  // exec's lookups (IR operands, slots included)
  std::vector<ir::Inst> uniform_ops;  // run once per draw or per run; d and register operands: slots
  int slots = 0;                      // slot s is register code.registers + s
  int max_depth = 0;                  // deepest nesting of if/loop/function frames
  bool straight_line = false;         // no structure, every register written before it is read
  // The compiled tier's code (shader/jit/), when it is enabled and takes the stage.
  std::shared_ptr<const jit::CompiledStage> compiled;
  void prepare();
  // The slots' values for these uniforms, each splatted over its kLanes floats.
  void compute_uniform_ops(const float* uniforms, float* slot_lanes) const;
  int32_t offset(ir::Operand o) const {
    if (o == ir::kNone) return 0;
    return ir::is_const(o) ? ir::const_index(o) * kLanes
                           : (static_cast<int32_t>(code.constants.size()) + o) * kLanes;
  }
  // exec's operands d, a, b, c: offset() in bytes, which a run scales by its block count
  // (1, 2 or 4) within one address computation.
  int32_t byte_offset(ir::Operand o) const { return offset(o) * static_cast<int32_t>(sizeof(float)); }
};

// The lane buffer a run keeps on its stack (16 KiB: a GL call may come from a thread with a
// small stack); a run that needs more takes it from the heap.
constexpr int kStackLaneFloats = 256 * kLanes;

// The most blocks a run of `stage` takes with its lane buffer on the stack (1, 2 or 4).
inline int blocks_per_run(const StageCode& stage) {
  const int values = static_cast<int>(stage.code.constants.size()) + stage.code.registers + stage.slots;
  for (int blocks = kMaxBlocksPerRun; blocks > 1; blocks /= 2)
    if (values * blocks * kLanes <= kStackLaneFloats) return blocks;
  return 1;
}

struct LaneIo {
  const float* uniforms = nullptr;
  const TextureAccess* textures = nullptr;
  // Vertices, per batch of the run: inputs [slot][4][kLanes], outputs [float][kLanes].
  const float* inputs[kMaxBlocksPerRun] = {};
  float* outputs[kMaxBlocksPerRun] = {};
  FragmentBlock* blocks[kMaxBlocksPerRun] = {};  // fragments: the run's blocks
  // Per block: the lanes whose results are used (texture lookups read only these).
  LaneMask needed[kMaxBlocksPerRun] = {0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF};
  const float* slot_lanes = nullptr;  // the stage's compute_uniform_ops values; null: computed per run
  bool denormals_flushed = false;     // the first batch's or block's denormals_flushed
};

// Runs `stage` over the lanes of `mask` of `blocks` blocks or vertex batches (1, 2 or 4; 3
// where runs_compiled says so); returns the lanes that executed discard.
RunMask execute(const StageCode& stage, Stage kind, int blocks, RunMask mask, const LaneIo& io);

// Whether execute() takes the compiled code for this run: it runs the blocks one at a time,
// any number of them (the interpreter runs 1, 2 or 4 together).
bool runs_compiled(const StageCode& stage, Stage kind, int blocks, RunMask mask);

}  // namespace pineda::shader
