// A multisampled draw shades each pixel once (raster/sample_targets.h): a fragment shader that
// counts the pixels it is run on sees the pixels that any sample of the primitive covers, not
// the covered samples, while every sample still gets its own coverage, depth and write.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <vector>

#include "raster/renderer.h"
#include "raster/shader_draw.h"
#include "tests/raster/test_support.h"

namespace pineda::raster {
namespace {

using test::state_for;
using test::window_vertex;

// A fragment shader of a constant colour that counts the live lanes it is run on (the
// count is the program's own: draws of other programs do not touch it).
class CountingProgram final : public shader::Program {
 public:
  // writes_depth: gl_FragDepth a different value per lane; discards: lanes 5 and 10 discard.
  explicit CountingProgram(float alpha, bool writes_depth = false, bool discards = false)
      : alpha_(alpha), writes_depth_(writes_depth), discards_(discards) {}
  mutable std::atomic<uint64_t> shaded{0};

  const std::vector<shader::Attribute>& attributes() const override { return attributes_; }
  const std::vector<shader::Uniform>& uniforms() const override { return uniforms_; }
  const std::vector<shader::Varying>& varyings() const override { return varyings_; }
  int input_slots() const override { return 0; }
  int varying_floats() const override { return 0; }
  int uniform_floats() const override { return 0; }
  bool writes_point_size() const override { return false; }
  bool writes_depth() const override { return writes_depth_; }
  bool uses_discard() const override { return discards_; }
  int draw_buffers_written() const override { return 1; }
  bool broadcasts_color() const override { return true; }
  bool reads(const char*) const override { return false; }
  bool reads_point_coord() const override { return false; }
  unsigned frag_coord_components() const override { return 0; }
  void run_vertices(const float*, const shader::TextureAccess*, shader::VertexBatch&) const override {}
  void run_vertex_batches(const float*, const shader::TextureAccess*, shader::VertexBatch*, int) const override {}
  void run_fragments(const float* u, const shader::TextureAccess* t, shader::FragmentBlock& block) const override {
    run_fragment_blocks(u, t, &block, 1);
  }
  void run_fragment_blocks(const float*, const shader::TextureAccess*, shader::FragmentBlock* blocks,
                           int count) const override {
    for (int k = 0; k < count; ++k) {
      shaded += static_cast<uint64_t>(__builtin_popcount(blocks[k].live));
      const float rgba[4] = {1.f, 0.f, 0.f, alpha_};
      for (int c = 0; c < 4; ++c)
        for (int l = 0; l < shader::kLanes; ++l) blocks[k].color[0][c][l] = rgba[c];
      for (int l = 0; l < shader::kLanes; ++l) blocks[k].depth[l] = 0.2f + 0.04f * float(l);
      if (discards_) blocks[k].live &= static_cast<shader::LaneMask>(~((1u << 5) | (1u << 10)));
    }
  }
  void fragment_uniform_values(const float*, std::vector<float>& out) const override { out.clear(); }
  void vertex_uniform_values(const float*, std::vector<float>& out) const override { out.clear(); }

 private:
  float alpha_;
  bool writes_depth_, discards_;
  std::vector<shader::Attribute> attributes_;
  std::vector<shader::Uniform> uniforms_;
  std::vector<shader::Varying> varyings_;
};

constexpr int kSize = 32;

// A 4x multisampled framebuffer: each sample a plane of colour, depth and stencil.
struct SampledFramebuffer {
  SampledFramebuffer()
      : color(4 * kPlane * 4), depth(4 * kPlane, 0xffffffu), stencil(4 * kPlane) {
    fb.width = fb.height = kSize;
    fb.samples = 4;
    fb.color = {color.data(), kSize * 4, ColorFormat::RGBA8, {}, kPlane * 4};
    fb.depth = {depth.data(), kSize, 24, kPlane};
    fb.stencil = {stencil.data(), kSize, 8, kPlane};
  }
  bool red(int s, int x, int y) const { return color[size_t(s * kPlane + y * kSize + x) * 4] != 0; }
  // Pixels with at least one red sample, and red samples.
  int pixels() const {
    int n = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) n += red(0, x, y) || red(1, x, y) || red(2, x, y) || red(3, x, y);
    return n;
  }
  int samples() const {
    int n = 0;
    for (int s = 0; s < 4; ++s)
      for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) n += red(s, x, y);
    return n;
  }
  static constexpr int kPlane = kSize * kSize;
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;
  Framebuffer fb;
};

// A triangle whose three edges cross pixels between their samples.
void draw_triangle(Renderer& r, const DrawState& state) {
  const ClipVertex v[3] = {window_vertex(1.3, 2.1, kSize, kSize), window_vertex(29.6, 5.45, kSize, kSize),
                           window_vertex(11.2, 30.7, kSize, kSize)};
  r.draw(state, Primitive::Triangles, v);
  r.flush();
}

// One triangle over the whole framebuffer at depth z (two would shade their shared diagonal's
// pixels twice: once per primitive).
void draw_cover(Renderer& r, const DrawState& state, float z) {
  const ClipVertex v[3] = {window_vertex(0, 0, kSize, kSize, z), window_vertex(2 * kSize, 0, kSize, kSize, z),
                           window_vertex(0, 2 * kSize, kSize, kSize, z)};
  r.draw(state, Primitive::Triangles, v);
  r.flush();
}

DrawState shader_state(const std::shared_ptr<CountingProgram>& program) {
  DrawState s = state_for(kSize, kSize);
  auto sd = std::make_shared<ShaderDraw>();
  sd->program = program;
  s.shader = sd;
  return s;
}

TEST(MultisampleShadeOnce, AFragmentShaderRunsOncePerCoveredPixel) {
  for (int threads : {1, 2}) {
    SampledFramebuffer target;
    Renderer r(threads);
    r.set_framebuffer(target.fb);
    auto program = std::make_shared<CountingProgram>(1.f);
    draw_triangle(r, shader_state(program));
    const int pixels = target.pixels(), samples = target.samples();
    EXPECT_GT(samples, pixels + 20);  // edge pixels with some of their samples: shading per sample would differ
    EXPECT_EQ(program->shaded.load(), uint64_t(pixels)) << threads;
  }
}

// Early depth tests per sample: a pixel is shaded when a sample of it passes, and a sample
// is written where its own depth passes.
TEST(MultisampleShadeOnce, EarlyDepthPerSampleThenOneShade) {
  SampledFramebuffer target;
  Renderer r(1);
  r.set_framebuffer(target.fb);
  // Depth 0.5 in the samples left of x = 10.4 (pixel 10: samples at 10.125 and 10.375).
  for (int s = 0; s < 4; ++s)
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const double sx = x + (s == 0 ? 0.375 : s == 1 ? 0.875 : s == 2 ? 0.125 : 0.625);
        if (sx < 10.4) target.depth[size_t(s * SampledFramebuffer::kPlane + y * kSize + x)] = 0x7fffff;
      }
  auto program = std::make_shared<CountingProgram>(1.f);
  DrawState s = shader_state(program);
  s.depth_test = true;
  s.depth_func = CompareFunc::Less;
  draw_cover(r, s, 0.2f);
  // Columns 0..9 fail everywhere; column 10 has two samples left; 11..31 pass.
  EXPECT_EQ(program->shaded.load(), uint64_t(22 * kSize));
  EXPECT_EQ(target.pixels(), 22 * kSize);
  EXPECT_EQ(target.samples(), (21 * 4 + 2) * kSize);
  EXPECT_TRUE(target.red(1, 10, 7) && target.red(3, 10, 7));
  EXPECT_FALSE(target.red(0, 10, 7) || target.red(2, 10, 7));
}

// Alpha to coverage (alpha 0.5: samples 0 and 1) and the sample coverage mask: one shade per
// pixel, each sample kept by its own threshold and by the mask.
TEST(MultisampleShadeOnce, AlphaToCoverageAndSampleCoverageShadeOnce) {
  for (const bool coverage : {false, true}) {
    SampledFramebuffer target;
    Renderer r(1);
    r.set_framebuffer(target.fb);
    auto program = std::make_shared<CountingProgram>(0.5f);
    DrawState s = shader_state(program);
    s.multisample.alpha_to_coverage = true;
    s.multisample.sample_coverage = coverage;
    s.multisample.coverage_value = 0.25f;
    s.multisample.coverage_invert = true;  // samples 1, 2 and 3
    draw_cover(r, s, 0.f);
    EXPECT_EQ(program->shaded.load(), uint64_t(kSize * kSize)) << coverage;
    for (int smp = 0; smp < 4; ++smp)
      EXPECT_EQ(target.red(smp, 5, 5), smp == 1 || (smp == 0 && !coverage)) << coverage << " " << smp;
  }
}

// Every sample's depth, stencil and colour after random multisampled draws (partial coverage,
// every depth and stencil function and op, both faces, alpha to coverage, the sample coverage
// mask, the alpha test, a shader's discard and depth; early and late tests): the same on every
// SIMD path and thread count.
TEST(MultisampleShadeOnce, EveryPathAndThreadCountLeavesTheSameSamples) {
  auto render = [](const char* simd, int threads) {
    setenv("PINEDA_SIMD", simd, 1);
    SampledFramebuffer target;
    Renderer r(threads);
    unsetenv("PINEDA_SIMD");
    r.set_framebuffer(target.fb);
    std::mt19937 random(3);
    auto pick = [&](int n) { return static_cast<int>(random() % unsigned(n)); };
    auto coordinate = [&] { return -4.0 + 40.0 * (random() % 10000) / 10000.0; };
    for (int draw = 0; draw < 120; ++draw) {
      const int kind = draw % 4;  // fixed function; shader; shader writing depth; shader discarding
      auto program = std::make_shared<CountingProgram>(0.1f + 0.2f * float(pick(5)), kind == 2, kind == 3);
      DrawState s = kind ? shader_state(program) : state_for(kSize, kSize);
      s.depth_test = pick(4) != 0;
      s.depth_func = static_cast<CompareFunc>(pick(8));
      s.depth_write = pick(3) != 0;
      s.stencil_test = pick(2) != 0;
      for (StencilFace* face : {&s.stencil_front, &s.stencil_back}) {
        face->func = static_cast<CompareFunc>(pick(8));
        face->ref = pick(4);
        face->value_mask = pick(2) ? 0xff : 0x3;
        face->write_mask = pick(2) ? 0xff : 0x5;
        face->fail = static_cast<StencilOp>(pick(8));
        face->depth_fail = static_cast<StencilOp>(pick(8));
        face->depth_pass = static_cast<StencilOp>(pick(8));
      }
      s.multisample.alpha_to_coverage = pick(3) == 0;
      s.multisample.sample_coverage = pick(4) == 0;
      s.multisample.coverage_value = 0.25f * float(pick(5));
      s.multisample.coverage_invert = pick(2) != 0;
      s.alpha_test = pick(4) == 0;
      s.alpha_func = CompareFunc::GreaterEqual;
      s.alpha_ref = 0.4f;
      ClipVertex v[3];
      for (ClipVertex& vertex : v) {
        vertex = window_vertex(coordinate(), coordinate(), kSize, kSize, -1.f + 0.02f * float(pick(100)));
        for (int c = 0; c < 4; ++c) vertex.color[c] = vertex.back_color[c] = 0.1f * float(pick(11));
      }
      r.draw(s, Primitive::Triangles, v);
    }
    r.flush();
    return target;
  };
  const SampledFramebuffer expected = render("baseline", 1);
  for (const char* simd : {"baseline", "avx2", "best"})
    for (int threads : {1, 2}) {
      const SampledFramebuffer got = render(simd, threads);
      EXPECT_EQ(got.color, expected.color) << simd << " " << threads;
      EXPECT_EQ(got.depth, expected.depth) << simd << " " << threads;
      EXPECT_EQ(got.stencil, expected.stencil) << simd << " " << threads;
    }
  // The draws did test and write: samples of every kind of value differ from the cleared ones.
  EXPECT_GT(expected.samples(), 100);
  EXPECT_NE(std::count(expected.depth.begin(), expected.depth.end(), 0xffffffu), std::ptrdiff_t(expected.depth.size()));
  EXPECT_NE(std::count(expected.stencil.begin(), expected.stencil.end(), 0), std::ptrdiff_t(expected.stencil.size()));
}

}  // namespace
}  // namespace pineda::raster
