// Program::run_fragment_blocks: blocks shaded together (2, 3 or 4 per run) come out exactly as
// each block run alone, through divergent branches, loops with per-lane exits, discard,
// dynamic indexing, derivatives, gl_FrontFacing and gl_FragCoord, and partly live blocks.
#include <cstring>
#include <random>

#include "tests/shader/shader_test_util.h"

namespace pineda::shader::test {
namespace {

const char* const kShader =
    "varying vec4 a;\n"
    "uniform float u;\n"
    "void main() {\n"
    "  float k[4];\n"
    "  for (int i = 0; i < 4; i++) k[i] = a.y * float(i);\n"
    "  float s = 0.0;\n"
    "  for (int i = 0; i < 12; i++) { if (float(i) > a.x * 3.0) break; s += k[int(mod(float(i), 4.0))]; }\n"
    "  if (a.z < 0.2) discard;\n"
    "  vec4 c;\n"
    "  if (a.w > 0.5) c = vec4(s, dFdx(a.x), dFdy(a.y), u); else c = vec4(-s, gl_FragCoord.xy, 1.0);\n"
    "  if (!gl_FrontFacing) c.w += 10.0;\n"
    "  gl_FragColor = c;\n"
    "}\n";

struct BlockInputs {
  std::vector<float> varyings;
  FragmentBlock block{};
};

BlockInputs make_block(const Program& p, std::mt19937& random, int index) {
  BlockInputs in;
  in.varyings.assign(static_cast<size_t>(p.varying_floats() + 1) * kLanes, 0.0f);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  for (float& v : in.varyings) v = value(random);
  std::uniform_int_distribution<int> bits(0, 0xFFFF);
  in.block.live = static_cast<LaneMask>(index == 1 ? 0x0F0F : bits(random) | 1);  // some quads with no live pixel
  in.block.front_facing = index % 2 ? 0 : 0xFFFF;
  for (int l = 0; l < kLanes; ++l) {
    in.block.frag_coord[0][l] = static_cast<float>(8 * index + (l & 1) + 2 * (l >> 2)) + 0.5f;
    in.block.frag_coord[1][l] = static_cast<float>((l >> 1) & 1) + 0.5f;
    in.block.frag_coord[2][l] = 0.5f;
    in.block.frag_coord[3][l] = 1.0f;
  }
  return in;
}

// A shader with more values than four blocks' lanes fit on the stack: runs of fewer blocks.
const char* const kLargeShader =
    "varying vec4 a;\n"
    "uniform float u;\n"
    "void main() {\n"
    "  float k[100];\n"
    "  for (int i = 0; i < 100; i++) k[i] = a.y * float(i) + u;\n"
    "  float s = 0.0;\n"
    "  for (int i = 0; i < 100; i++) { if (float(i) > a.x * 90.0) break; s += k[int(mod(float(i) * 7.0, 100.0))]; }\n"
    "  if (a.z < 0.2) discard;\n"
    "  gl_FragColor = vec4(s, dFdx(s), a.w, 1.0);\n"
    "}\n";

class BlockRuns : public testing::TestWithParam<const char*> {};

TEST_P(BlockRuns, BlocksShadedTogetherComeOutAsEachAlone) {
  auto p = link_ok("", GetParam());
  ASSERT_TRUE(p);
  std::vector<float> uniforms(static_cast<size_t>(p->uniform_floats() + 1), 0.0f);
  uniforms[static_cast<size_t>(find_uniform(*p, "u")->offset)] = 0.25f;
  std::mt19937 random(3);
  for (int trial = 0; trial < 20; ++trial)
    for (int count = 1; count <= kMaxBlocksPerRun; ++count) {
      std::vector<BlockInputs> inputs;
      for (int k = 0; k < count; ++k) inputs.push_back(make_block(*p, random, k));
      FragmentBlock together[kMaxBlocksPerRun];
      for (int k = 0; k < count; ++k) {
        together[k] = inputs[static_cast<size_t>(k)].block;
        together[k].varyings = inputs[static_cast<size_t>(k)].varyings.data();
      }
      p->run_fragment_blocks(uniforms.data(), nullptr, together, count);
      for (int k = 0; k < count; ++k) {
        FragmentBlock alone = inputs[static_cast<size_t>(k)].block;
        alone.varyings = inputs[static_cast<size_t>(k)].varyings.data();
        p->run_fragments(uniforms.data(), nullptr, alone);
        ASSERT_EQ(together[k].live, alone.live) << count << " " << k;
        for (int l = 0; l < kLanes; ++l) {
          if (!(alone.live >> l & 1)) continue;
          for (int c = 0; c < 4; ++c)
            ASSERT_EQ(std::memcmp(&together[k].color[0][c][l], &alone.color[0][c][l], sizeof(float)), 0)
                << "trial " << trial << " blocks " << count << " block " << k << " lane " << l << " component " << c;
        }
      }
    }
}

// Vertex batches run together (run_vertex_batches) give each batch's outputs as run alone,
// partial batches included.
TEST(VertexBatchRuns, BatchesRunTogetherComeOutAsEachAlone) {
  auto p = link_ok("attribute vec4 position;\nattribute vec4 weights;\nuniform mat4 m;\nvarying vec4 v;\n"
                   "void main() {\n"
                   "  vec4 q = m * position;\n"
                   "  for (int i = 0; i < 3; i++) if (weights[i] > 0.5) q.xy += weights.zw * float(i);\n"
                   "  v = vec4(length(q.xyz), sin(q.x), weights.x > 0.3 ? 1.0 : -1.0, q.w);\n"
                   "  gl_Position = q;\n"
                   "}\n",
                   "varying vec4 v;\nvoid main() { gl_FragColor = v; }\n");
  ASSERT_TRUE(p);
  std::mt19937 random(9);
  std::uniform_real_distribution<float> value(-2.0f, 2.0f);
  std::vector<float> uniforms(static_cast<size_t>(p->uniform_floats() + 1), 0.0f);
  for (float& u : uniforms) u = value(random);
  const size_t in_floats = static_cast<size_t>(p->input_slots() + 1) * 4 * kLanes;
  const size_t out_floats = static_cast<size_t>(kOutFirstVarying + p->varying_floats()) * kLanes;
  for (int count = 1; count <= kMaxBlocksPerRun; ++count) {
    std::vector<float> inputs(in_floats * static_cast<size_t>(count)), together(out_floats * static_cast<size_t>(count), -99.0f);
    for (float& v : inputs) v = value(random);
    VertexBatch batches[kMaxBlocksPerRun];
    for (int k = 0; k < count; ++k) {
      batches[k].count = k == count - 1 ? 16 - 5 * k : kLanes;  // the last batch partly filled
      batches[k].inputs = inputs.data() + in_floats * static_cast<size_t>(k);
      batches[k].outputs = together.data() + out_floats * static_cast<size_t>(k);
    }
    p->run_vertex_batches(uniforms.data(), nullptr, batches, count);
    for (int k = 0; k < count; ++k) {
      std::vector<float> alone(out_floats, -99.0f);
      VertexBatch one = batches[k];
      one.outputs = alone.data();
      p->run_vertices(uniforms.data(), nullptr, one);
      for (size_t f = 0; f < out_floats; ++f) {
        if (static_cast<int>(f % kLanes) >= one.count) continue;
        ASSERT_EQ(std::memcmp(&together[out_floats * static_cast<size_t>(k) + f], &alone[f], sizeof(float)), 0)
            << "batches " << count << " batch " << k << " float " << f;
      }
    }
  }
}

// A draw computes the vertex shader's uniform-only values once (vertex_uniform_values) and its
// batches read them: here values of other uniforms than the run's, to see which ones it reads.
TEST(VertexBatchRuns, BatchesReadTheDrawsUniformValues) {
  auto p = link_ok("attribute vec4 position;\nuniform mat4 a;\nuniform mat4 b;\n"
                   "void main() { gl_Position = (a * b) * position; }\n",
                   "void main() { gl_FragColor = vec4(1.0); }\n");
  ASSERT_TRUE(p);
  std::mt19937 random(5);
  std::uniform_real_distribution<float> value(-2.0f, 2.0f);
  std::vector<float> drawn(static_cast<size_t>(p->uniform_floats()), 0.0f), other(drawn.size());
  for (float& u : drawn) u = value(random);
  for (float& u : other) u = value(random);
  std::vector<float> values(3, -1.0f);  // resized to the program's
  p->vertex_uniform_values(drawn.data(), values);
  ASSERT_FALSE(values.empty());  // a * b
  const size_t in_floats = static_cast<size_t>(p->input_slots()) * 4 * kLanes;
  const size_t out_floats = static_cast<size_t>(kOutFirstVarying + p->varying_floats()) * kLanes;
  std::vector<float> inputs(in_floats * 2), read(out_floats * 2, -99.0f), expected(out_floats * 2, -99.0f);
  for (float& v : inputs) v = value(random);
  VertexBatch batches[2], plain[2];
  for (int k = 0; k < 2; ++k) {
    batches[k].count = plain[k].count = kLanes;
    batches[k].inputs = plain[k].inputs = inputs.data() + in_floats * static_cast<size_t>(k);
    batches[k].outputs = read.data() + out_floats * static_cast<size_t>(k);
    batches[k].uniform_values = values.data();
    plain[k].outputs = expected.data() + out_floats * static_cast<size_t>(k);
  }
  p->run_vertex_batches(other.data(), nullptr, batches, 2);
  p->run_vertex_batches(drawn.data(), nullptr, plain, 2);
  for (size_t f = 0; f < kLanes * 4 * 2; ++f) {
    const size_t at = (f / (kLanes * 4)) * out_floats + kOutPosition * kLanes + f % (kLanes * 4);
    ASSERT_EQ(std::memcmp(&read[at], &expected[at], sizeof(float)), 0) << f;
  }
}

INSTANTIATE_TEST_SUITE_P(Shaders, BlockRuns, testing::Values(kShader, kLargeShader));

}  // namespace
}  // namespace pineda::shader::test
