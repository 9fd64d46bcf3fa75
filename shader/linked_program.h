// The Program that link() returns: the interface tables and each stage's code.
#pragma once
#include <optional>
#include <set>
#include <string>

#include "shader/execute.h"
#include "shader/program.h"

namespace pineda::shader {

class LinkedProgram final : public Program {
 public:
  std::vector<Attribute> attributes_;
  std::vector<Uniform> uniforms_;
  std::vector<Varying> varyings_;
  int input_slots_ = 0;
  int varying_floats_ = 0;
  int uniform_floats_ = 0;
  bool writes_point_size_ = false;
  bool writes_depth_ = false;
  bool uses_discard_ = false;
  int draw_buffers_ = 0;
  bool broadcasts_color_ = false;
  std::set<std::string> reads_;
  unsigned frag_coord_components_ = 0;
  bool reads_point_coord_ = false;
  std::optional<StageCode> vertex_;
  std::optional<StageCode> fragment_;

  const std::vector<Attribute>& attributes() const override { return attributes_; }
  const std::vector<Uniform>& uniforms() const override { return uniforms_; }
  const std::vector<Varying>& varyings() const override { return varyings_; }
  int input_slots() const override { return input_slots_; }
  int varying_floats() const override { return varying_floats_; }
  int uniform_floats() const override { return uniform_floats_; }
  bool writes_point_size() const override { return writes_point_size_; }
  bool writes_depth() const override { return writes_depth_; }
  bool uses_discard() const override { return uses_discard_; }
  int draw_buffers_written() const override { return draw_buffers_; }
  bool broadcasts_color() const override { return broadcasts_color_; }
  bool reads(const char* builtin) const override { return reads_.count(builtin) != 0; }
  unsigned frag_coord_components() const override { return frag_coord_components_; }
  bool reads_point_coord() const override { return reads_point_coord_; }
  void run_vertices(const float* uniforms, const TextureAccess* textures, VertexBatch& batch) const override;
  void run_vertex_batches(const float* uniforms, const TextureAccess* textures, VertexBatch* batches,
                          int count) const override;
  void run_fragments(const float* uniforms, const TextureAccess* textures, FragmentBlock& block) const override;
  void run_fragment_blocks(const float* uniforms, const TextureAccess* textures, FragmentBlock* blocks,
                           int count) const override;
  void fragment_uniform_values(const float* uniforms, std::vector<float>& out) const override;
  void vertex_uniform_values(const float* uniforms, std::vector<float>& out) const override;
};

}  // namespace pineda::shader
