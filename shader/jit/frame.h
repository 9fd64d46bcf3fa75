// What a compiled stage reads and writes for one block of 16 lanes (a fragment block or a
// vertex batch), and the C++ side of the operations it calls out to.
#pragma once
#include <cstddef>

#include "shader/ir.h"
#include "shader/program.h"

namespace pineda::shader {
struct StageCode;
}

namespace pineda::shader::jit {

struct Frame {
  float* spill;               // [code.registers][kLanes]: registers' homes
  const float* slots;         // [slot][kLanes]: the uniform-only operations' values
  const float* constants;     // StageCode::constant_lanes: [constant][kMaxBlocksPerRun * kLanes]
  const float* uniforms;
  void* block_or_outputs;     // FragmentBlock* (fragment), or the batch's outputs (vertex)
  const float* lanes_in;      // the block's varyings (fragment), or the batch's inputs (vertex)
  const StageCode* stage;
  const TextureAccess* textures;
  Stage kind;
  LaneMask mask;              // the lanes that run (the code keeps it current in branches)
  LaneMask needed;            // the lanes whose results are used
  uint32_t discarded;         // out: lanes that executed discard (the code ORs them in)
};

// Register operands live at spill + r * kLanes, slots at slots + (r - registers) * kLanes,
// constants at constants + index * kMaxBlocksPerRun * kLanes.
constexpr int kConstantStride = kMaxBlocksPerRun * kLanes;

// Where an IR operand's lanes lie in a frame, found once when the stage is compiled: `offset`
// floats from the frame's pointer `base`.
struct FrameOperand {
  uint32_t base = 0;  // 0: zeros (kNone), 1: constants, 2: spill (registers), 3: slots
  uint32_t offset = 0;
};
FrameOperand frame_operand(ir::Operand o, int registers);

// An operation the compiled code leaves to the interpreter's routines, its operands found.
struct FrameCall {
  ir::Op op = ir::Op::Mov;
  FrameOperand d, a, b, c;
};

// Runs `in` over the frame's lanes in memory, with the interpreter's values for every
// operation.
void call_out(const Frame* frame, const FrameCall* in);

// A texture lookup with its operands found (call_texture).
struct FrameTextureLookup {
  ir::TextureLookup lookup;  // kind and mode
  FrameOperand coord[4], dst[4], sampler, lod;
};

// A texture lookup of the compiled code, as the interpreter does it.
void call_texture(const Frame* frame, const FrameTextureLookup* t);

// Lookups side by side in the code, none reading what an earlier one writes: one call-out for
// all (TextureAccess::sample_2d_blocks when they are 2D lookups of one sampler).
constexpr int kMaxTextureRun = 16;
struct FrameTextureRun {
  int count = 0;
  bool one_2d_sampler = false;  // every lookup Tex2D and Implicit, with the same sampler operand
  const FrameTextureLookup* lookups[kMaxTextureRun] = {};
  // With one_2d_sampler, the lookups' s, t and destinations side by side (read for every block).
  FrameOperand s[kMaxTextureRun], t[kMaxTextureRun], dst[kMaxTextureRun][4];
};

// The run's lookups, as call_texture does each in order.
void call_texture_run(const Frame* frame, const FrameTextureRun* run);

}  // namespace pineda::shader::jit
