// The lane executor: runs one stage's IR over 16 lanes with execution masks.
#pragma once
#include "shader/ir.h"
#include "shader/program.h"

namespace pineda::shader {

// A stage's code ready to run: the IR, and the same instructions with every value operand
// turned into a float offset into one lane buffer (constants, splatted, then registers, then
// the slots of the uniform-only operations, shader/hoist.h), so that the executor reads
// operands without a branch.
struct StageCode {
  ir::Code code;
  std::vector<float> constant_lanes;  // [constant][kLanes]
  std::vector<ir::Inst> exec;         // code.insts without uniform_ops, operands as buffer offsets, then Op::Count
  std::vector<ir::TextureLookup> exec_textures;  // exec's lookups (IR operands, slots included)
  std::vector<ir::Inst> uniform_ops;  // run once per draw or per run; d and register operands: slots
  int slots = 0;                      // slot s is register code.registers + s
  int max_depth = 0;                  // deepest nesting of if/loop/function frames
  bool straight_line = false;         // no structure, every register written before it is read
  void prepare();
  // The slots' values for these uniforms, each splatted over its kLanes floats.
  void compute_uniform_ops(const float* uniforms, float* slot_lanes) const;
  int32_t offset(ir::Operand o) const {
    if (o == ir::kNone) return 0;
    return ir::is_const(o) ? ir::const_index(o) * kLanes
                           : (static_cast<int32_t>(code.constants.size()) + o) * kLanes;
  }
};

struct LaneIo {
  const float* uniforms = nullptr;
  const TextureAccess* textures = nullptr;
  const float* inputs = nullptr;   // vertex inputs [slot][4][kLanes]
  float* outputs = nullptr;        // vertex outputs [float][kLanes]
  FragmentBlock* block = nullptr;  // fragments
  LaneMask needed = 0xFFFF;        // lanes whose results are used (texture lookups read only these)
  const float* slot_lanes = nullptr;  // the stage's compute_uniform_ops values; null: computed per run
};

// Runs `stage` over the lanes of `mask`; returns the lanes that executed discard.
LaneMask execute(const StageCode& stage, Stage kind, LaneMask mask, const LaneIo& io);

}  // namespace pineda::shader
