// The compiled tier: a stage's IR turned into x86-64 AVX-512 code that runs one block of 16
// lanes with its values in registers. Every operation computes what the
// interpreter computes (the same IEEE operations in the same order; the rare ones call the
// interpreter's own lane routines), so images do not depend on the tier.
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include "shader/ir.h"
#include "shader/jit/frame.h"

namespace pineda::shader::jit {

class CompiledStage {
 public:
  // Null when the code has what only the interpreter runs (a return outside a function, an
  // output stored inside a branch), or executable memory is refused.
  // `insts` are IR operands with slots numbered from `registers` (HoistedCode::insts).
  static std::unique_ptr<CompiledStage> compile(const std::vector<ir::Inst>& insts,
                                                const std::vector<ir::TextureLookup>& textures, int registers,
                                                int slots);
  ~CompiledStage();
  CompiledStage(const CompiledStage&) = delete;
  CompiledStage& operator=(const CompiledStage&) = delete;

  void run(Frame& frame) const { entry_(&frame); }
  size_t code_bytes() const { return size_; }

 private:
  CompiledStage() = default;
  using Entry = void (*)(Frame*);
  std::vector<FrameCall> calls_;               // the call-outs, by instruction: the code holds their addresses
  std::vector<FrameTextureLookup> lookups_;  // likewise, by TextureLookup index
  std::vector<FrameTextureRun> runs_;        // likewise, in the code's order
  void* memory_ = nullptr;
  size_t size_ = 0;
  Entry entry_ = nullptr;
};

// Whether this process compiles stages: AVX-512 on the CPU and chosen (raster/simd_path.h), and
// PINEDA_SHADER_JIT is not 0.
bool compiled_tier_enabled();

}  // namespace pineda::shader::jit
