#include "shader/linked_program.h"

namespace pineda::shader {

void LinkedProgram::run_vertices(const float* uniforms, const TextureAccess* textures, VertexBatch& batch) const {
  if (!vertex_ || batch.count <= 0) return;
  const int count = batch.count > kLanes ? kLanes : batch.count;
  const LaneMask mask = static_cast<LaneMask>(count == kLanes ? 0xFFFF : (1u << count) - 1);
  LaneIo io;
  io.uniforms = uniforms;
  io.textures = textures;
  io.inputs = batch.inputs;
  io.outputs = batch.outputs;
  execute(*vertex_, Stage::Vertex, mask, io);
}

void LinkedProgram::run_fragments(const float* uniforms, const TextureAccess* textures, FragmentBlock& block) const {
  if (!fragment_ || block.live == 0) return;
  // Every lane of a quad with a covered pixel runs, so that derivatives and implicit LOD
  // see real neighbours; only covered lanes come out live.
  LaneMask quads = 0;
  for (int q = 0; q < 4; ++q)
    if (block.live >> (4 * q) & 0xF) quads |= static_cast<LaneMask>(0xF << (4 * q));
  LaneIo io;
  io.uniforms = uniforms;
  io.textures = textures;
  io.block = &block;
  io.needed = quads;
  io.slot_lanes = block.uniform_values;
  const LaneMask discarded = execute(*fragment_, Stage::Fragment, block.run ? block.run : quads, io);
  block.live &= static_cast<LaneMask>(~discarded);
}

std::vector<float> LinkedProgram::fragment_uniform_values(const float* uniforms) const {
  if (!fragment_ || fragment_->slots == 0) return {};
  std::vector<float> values(static_cast<size_t>(fragment_->slots) * kLanes);
  fragment_->compute_uniform_ops(uniforms, values.data());
  return values;
}

std::string dump_ir(const Program& program) {
  const auto* p = dynamic_cast<const LinkedProgram*>(&program);
  if (!p) return {};
  std::string out;
  if (p->vertex_) out += "; vertex shader\n" + ir::dump(p->vertex_->code);
  if (p->fragment_) out += "; fragment shader\n" + ir::dump(p->fragment_->code);
  return out;
}

}  // namespace pineda::shader
