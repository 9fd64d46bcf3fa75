// The lane executor: runs one stage's IR over 16 lanes with execution masks.
#pragma once
#include "shader/ir.h"
#include "shader/program.h"

namespace pineda::shader {

// A stage's code ready to run: the IR plus its constants splatted to 16 lanes.
struct StageCode {
  ir::Code code;
  std::vector<float> constant_lanes;  // [constant][kLanes]
  void prepare();
};

struct LaneIo {
  const float* uniforms = nullptr;
  const TextureAccess* textures = nullptr;
  const float* inputs = nullptr;   // vertex inputs [slot][4][kLanes]
  float* outputs = nullptr;        // vertex outputs [float][kLanes]
  FragmentBlock* block = nullptr;  // fragments
};

// Runs `stage` over the lanes of `mask`; returns the lanes that executed discard.
LaneMask execute(const StageCode& stage, Stage kind, LaneMask mask, const LaneIo& io);

}  // namespace pineda::shader
