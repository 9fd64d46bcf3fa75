#include "shader/linked_program.h"

namespace pineda::shader {

void LinkedProgram::run_vertices(const float* uniforms, const TextureAccess* textures, VertexBatch& batch) const {
  run_vertex_batches(uniforms, textures, &batch, 1);
}

void LinkedProgram::run_vertex_batches(const float* uniforms, const TextureAccess* textures, VertexBatch* batches,
                                       int count) const {
  if (!vertex_ || count <= 0) return;
  const int per_run = blocks_per_run(*vertex_);
  // The interpreter runs three as two and one (a padding batch would need outputs); compiled
  // code takes any number.
  if (count > per_run || (count == 3 && !runs_compiled(*vertex_, Stage::Vertex, count, 0))) {
    const int first = count > per_run ? per_run : 2;
    run_vertex_batches(uniforms, textures, batches, first);
    run_vertex_batches(uniforms, textures, batches + first, count - first);
    return;
  }
  LaneIo io;
  io.uniforms = uniforms;
  io.textures = textures;
  io.slot_lanes = batches[0].uniform_values;
  io.denormals_flushed = batches[0].denormals_flushed;
  RunMask mask = 0;
  for (int k = 0; k < count; ++k) {
    const int lanes = batches[k].count > kLanes ? kLanes : (batches[k].count < 0 ? 0 : batches[k].count);
    mask |= (lanes == kLanes ? RunMask{0xFFFF} : (RunMask{1} << lanes) - 1) << (k * kLanes);
    io.inputs[k] = batches[k].inputs;
    io.outputs[k] = batches[k].outputs;
  }
  if (mask) execute(*vertex_, Stage::Vertex, count, mask, io);
}

namespace {

// Every lane of a quad with a covered pixel runs, so that derivatives and implicit LOD see
// real neighbours; only covered lanes come out live.
LaneMask quads_of(LaneMask live) {
  LaneMask quads = 0;
  for (int q = 0; q < 4; ++q)
    if (live >> (4 * q) & 0xF) quads |= static_cast<LaneMask>(0xF << (4 * q));
  return quads;
}

}  // namespace

void LinkedProgram::run_fragments(const float* uniforms, const TextureAccess* textures, FragmentBlock& block) const {
  run_fragment_blocks(uniforms, textures, &block, 1);
}

void LinkedProgram::run_fragment_blocks(const float* uniforms, const TextureAccess* textures, FragmentBlock* blocks,
                                        int count) const {
  if (!fragment_ || count <= 0) return;
  // A shader with many values runs fewer blocks at a time, its lane buffer on the stack.
  const int per_run = blocks_per_run(*fragment_);
  if (count > per_run) {
    for (int first = 0; first < count; first += per_run)
      run_fragment_blocks(uniforms, textures, blocks + first, count - first < per_run ? count - first : per_run);
    return;
  }
  LaneIo io;
  io.uniforms = uniforms;
  io.textures = textures;
  io.slot_lanes = blocks[0].uniform_values;
  io.denormals_flushed = blocks[0].denormals_flushed;
  RunMask mask = 0;
  int first_live = -1;
  for (int k = 0; k < count; ++k) {
    const LaneMask quads = quads_of(blocks[k].live);
    io.blocks[k] = &blocks[k];
    io.needed[k] = quads;
    if (!quads) continue;
    if (first_live < 0) first_live = k;
    mask |= static_cast<RunMask>(blocks[k].run ? blocks[k].run : quads) << (k * kLanes);
  }
  if (first_live < 0) return;
  // Three blocks run as four in the interpreter: the fourth repeats the first live one's inputs,
  // reads no texture and its results go nowhere. Compiled code runs blocks one by one.
  const int run = count == 3 && !runs_compiled(*fragment_, Stage::Fragment, count, mask) ? 4 : count;
  FragmentBlock pad;
  if (run > count) {
    pad = blocks[first_live];
    io.blocks[3] = &pad;
    io.needed[3] = 0;
    const FragmentBlock& model = blocks[first_live];
    mask |= static_cast<RunMask>(model.run ? model.run : quads_of(model.live)) << (3 * kLanes);
  }
  const RunMask discarded = execute(*fragment_, Stage::Fragment, run, mask, io);
  for (int k = 0; k < count; ++k) blocks[k].live &= static_cast<LaneMask>(~(discarded >> (k * kLanes)));
}

namespace {

// (compute_uniform_ops writes every slot's lanes.)
void uniform_values(const StageCode* stage, const float* uniforms, std::vector<float>& out) {
  out.resize(stage ? static_cast<size_t>(stage->slots) * kLanes : 0);
  if (!out.empty()) stage->compute_uniform_ops(uniforms, out.data());
}

}  // namespace

void LinkedProgram::fragment_uniform_values(const float* uniforms, std::vector<float>& out) const {
  uniform_values(fragment_ ? &*fragment_ : nullptr, uniforms, out);
}

void LinkedProgram::vertex_uniform_values(const float* uniforms, std::vector<float>& out) const {
  uniform_values(vertex_ ? &*vertex_ : nullptr, uniforms, out);
}

std::string dump_ir(const Program& program) {
  const auto* p = dynamic_cast<const LinkedProgram*>(&program);
  if (!p) return {};
  std::string out;
  auto tier = [](const StageCode& stage) {
    return stage.compiled ? std::string("; runs compiled (AVX-512)\n") : std::string("; runs on the interpreter\n");
  };
  if (p->vertex_) out += "; vertex shader\n" + ir::dump(p->vertex_->code) + tier(*p->vertex_);
  if (p->fragment_) out += "; fragment shader\n" + ir::dump(p->fragment_->code) + tier(*p->fragment_);
  return out;
}

}  // namespace pineda::shader
