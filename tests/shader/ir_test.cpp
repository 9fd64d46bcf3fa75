// The IR and its optimizer, seen through dump_ir().
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <thread>

#include "tests/shader/shader_test_util.h"

namespace pineda::shader::test {
namespace {

TEST(Ir, ConstantFoldingRemovesArithmetic) {
  // Everything but the varying read folds to constants: no add/mul/sin survives.
  auto p = link_ok("", "varying float v;\nconst float k = 3.0;\n"
                       "float twice(float x) { return x * 2.0; }\n"
                       "void main() {\n"
                       "  float a = sin(0.0) + twice(k) * 0.5 + pow(2.0, 3.0);\n"
                       "  vec3 n = normalize(vec3(0.0, 3.0, 4.0));\n"
                       "  gl_FragColor = vec4(a, n.y, n.z, v);\n}\n");
  ASSERT_TRUE(p);
  const std::string ir = dump_ir(*p);
  EXPECT_EQ(count_ops(ir, "add"), 0) << ir;
  EXPECT_EQ(count_ops(ir, "mul"), 0) << ir;
  EXPECT_EQ(count_ops(ir, "sin"), 0) << ir;
  EXPECT_EQ(count_ops(ir, "pow"), 0) << ir;
  EXPECT_EQ(count_ops(ir, "mad"), 0) << ir;
  EXPECT_EQ(count_ops(ir, "varying"), 1) << ir;
  EXPECT_EQ(count_ops(ir, "color"), 4) << ir;
  EXPECT_NE(ir.find("color 11 #0"), std::string::npos) << ir;  // 0 + 3*2*0.5 + 8
  FragmentRun run(*p);
  run.run(*p);
  EXPECT_EQ(run.block.color[0][0][0], 11.0f);
  EXPECT_EQ(run.block.color[0][1][0], 0.6f);
  EXPECT_EQ(run.block.color[0][2][0], 0.8f);
}

TEST(Ir, FoldingIsVisibleAgainstUnfoldedShader) {
  auto folded = link_ok("", "uniform float u;\nvoid main() { gl_FragColor = vec4(u * (2.0 + 3.0) * 1.0 + 0.0); }\n");
  ASSERT_TRUE(folded);
  const std::string ir = dump_ir(*folded);
  EXPECT_EQ(count_ops(ir, "mul"), 1) << ir;  // u * 5
  EXPECT_EQ(count_ops(ir, "add"), 0) << ir;
  EXPECT_NE(ir.find("mul r0 5"), std::string::npos) << ir;
}

TEST(Ir, DeadCodeAndUnusedInputsDisappear) {
  auto p = link_ok("attribute vec4 a;\nattribute vec4 b;\nuniform mat4 m;\nvarying vec4 unused_out;\n"
                   "void main() { vec4 dead = m * b; unused_out = dead; gl_Position = a; }\n",
                   "void main() { gl_FragColor = vec4(1.0); }\n");
  ASSERT_TRUE(p);
  const std::string ir = dump_ir(*p);
  EXPECT_EQ(count_ops(ir, "uniform"), 0) << ir;
  EXPECT_EQ(count_ops(ir, "mad"), 0) << ir;
  EXPECT_EQ(count_ops(ir, "input"), 4) << ir;  // a only
}

// A texture lookup weighted by a zero constant (a convolution kernel's zero taps) is not made;
// a lookup weighted by a uniform that happens to be 0 is.
TEST(Ir, TermsTimesZeroDisappearWithTheirLookups) {
  auto p = link_ok("", "uniform sampler2D t;\nuniform float u;\nvarying vec2 c;\nconst float k0 = 0.0;\n"
                       "void main() {\n"
                       "  vec4 sum = texture2D(t, c + vec2(-0.1)) * k0;\n"
                       "  sum += texture2D(t, c) * 2.0;\n"
                       "  sum += k0 * texture2D(t, c + vec2(0.1));\n"
                       "  sum += texture2D(t, c + vec2(0.2)) * u;\n"
                       "  gl_FragColor = sum + c.x * -0.0;\n}\n");
  ASSERT_TRUE(p);
  const std::string ir = dump_ir(*p);
  EXPECT_EQ(count_ops(ir, "texture"), 2) << ir;
  EXPECT_EQ(count_ops(ir, "mad"), 4) << ir;  // the u-weighted lookup added to 2 * the middle one
  EXPECT_EQ(count_ops(ir, "mul"), 4) << ir;
  EXPECT_EQ(count_ops(ir, "add"), 2) << ir;  // c + 0.2 only
}

TEST(Ir, CopiesArePropagated) {
  auto p = link_ok("", "varying vec4 v;\nvoid main() { vec4 a = v; vec4 b = a; vec4 c = b.wzyx; gl_FragColor = c.wzyx; }\n");
  ASSERT_TRUE(p);
  const std::string ir = dump_ir(*p);
  EXPECT_EQ(count_ops(ir, "mov"), 0) << ir;
}

// fract(x) where floor(x) was computed becomes x - floor(x): one rounding sequence, not two.
TEST(Ir, FractAfterFloorOfTheSameValueSubtracts) {
  auto p = link_ok("", "varying vec2 v; void main() { gl_FragColor = vec4(floor(v), fract(v)); }");
  ASSERT_NE(p, nullptr);
  const std::string ir = dump_ir(*p);
  EXPECT_EQ(count_ops(ir, "floor"), 2) << ir;
  EXPECT_EQ(count_ops(ir, "fract"), 0) << ir;
  EXPECT_EQ(count_ops(ir, "sub"), 2) << ir;
}

TEST(Ir, DumpShowsStructuredControlFlow) {
  auto p = link_ok("", "varying float v;\nvoid main() { float s = 0.0; for (int i = 0; i < 4; i++) { if (v > float(i)) break; s += v; } gl_FragColor = vec4(s); }\n");
  ASSERT_TRUE(p);
  const std::string ir = dump_ir(*p);
  EXPECT_EQ(count_ops(ir, "loop"), 1) << ir;
  EXPECT_EQ(count_ops(ir, "endloop"), 1) << ir;
  EXPECT_EQ(count_ops(ir, "break_if_not"), 1) << ir;
  EXPECT_EQ(count_ops(ir, "if"), 1) << ir;
  EXPECT_EQ(count_ops(ir, "break"), 1) << ir;
  EXPECT_NE(ir.find("; fragment shader"), std::string::npos);
  EXPECT_EQ(ir.find("; vertex shader"), std::string::npos);
}

TEST(Ir, DumpEnvironmentVariablePrintsAtLink) {
  setenv("PINEDA_DUMP_IR", "1", 1);
  testing::internal::CaptureStderr();
  auto p = link_ok("", "void main() { gl_FragColor = vec4(0.5); }\n");
  const std::string err = testing::internal::GetCapturedStderr();
  unsetenv("PINEDA_DUMP_IR");
  ASSERT_TRUE(p);
  EXPECT_NE(err.find("; fragment shader"), std::string::npos) << err;
  EXPECT_NE(err.find("color 0.5 #0"), std::string::npos) << err;
}

TEST(Threads, OneProgramRunsOnManyThreadsAndCompilesInParallel) {
  auto p = link_ok("", "varying float v;\nvoid main() { float s = 0.0; for (int i = 0; i < 64; i++) { if (float(i) > v) break; s += float(i); } gl_FragColor = vec4(s); }\n");
  ASSERT_TRUE(p);
  std::vector<std::thread> threads;
  std::vector<int> bad(8, 0);
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      for (int iter = 0; iter < 200; ++iter) {
        FragmentRun run(*p);
        for (int l = 0; l < kLanes; ++l) run.varyings[find_varying(*p, "v")->offset * kLanes + l] = static_cast<float>((l + t + iter) % 40);
        run.run(*p);
        for (int l = 0; l < kLanes; ++l) {
          int n = (l + t + iter) % 40;
          if (run.block.color[0][0][l] != static_cast<float>(n * (n + 1) / 2)) ++bad[t];
        }
      }
      // Compiling and linking from several threads at once.
      CompileResult c = compile(Stage::Fragment, Language::Es100, {"precision mediump float;\nvoid main() { gl_FragColor = vec4(" + std::to_string(t) + ".0); }\n"});
      if (!c.shader) ++bad[t];
      else if (!link(nullptr, c.shader.get(), {}).program) ++bad[t];
    });
  for (auto& th : threads) th.join();
  for (int t = 0; t < 8; ++t) EXPECT_EQ(bad[t], 0) << t;
}

}  // namespace
}  // namespace pineda::shader::test

namespace pineda::shader::test {
namespace {

TEST(Ir, CommonSubexpressionsComputedOnce) {
  auto p = link_ok("", "uniform float u;\nvarying float v;\n"
                       "void main() { float a = u * v; if (v > 0.5) { gl_FragColor = vec4(u * v); } else { gl_FragColor = vec4(a, u * v, u, 1.0); } }\n");
  ASSERT_TRUE(p);
  const std::string ir = dump_ir(*p);
  EXPECT_EQ(count_ops(ir, "mul"), 1) << ir;
  EXPECT_EQ(count_ops(ir, "uniform"), 1) << ir;
  EXPECT_EQ(count_ops(ir, "varying"), 1) << ir;
  FragmentRun run(*p);
  run.set_uniform(*p, "u", {3.0f});
  run.set_varying(*p, "v", 0, [](int l) { return l / 8.0f; });
  run.run(*p);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(run.block.color[0][0][l], 3.0f * (l / 8.0f)) << l;
    EXPECT_EQ(run.block.color[0][2][l], l / 8.0f > 0.5f ? 3.0f * (l / 8.0f) : 3.0f) << l;
  }
}

// A uniform's value reaches every lane bit for bit, whether it is read once for the block (at
// the top level) or in every lane (in a branch): -0.0 stays negative (1 / u is -inf).
TEST(Ir, UniformNegativeZeroKeepsItsSign) {
  auto p = link_ok("", "uniform float u;\nuniform float w;\nvarying float v;\n"
                       "void main() { gl_FragColor = vec4(1.0 / u, u, 0.0, 0.0);\n"
                       "  if (v < 2.0) { gl_FragColor.z = 1.0 / w; gl_FragColor.w = w; } }\n");
  ASSERT_TRUE(p);
  FragmentRun run(*p);
  run.set_uniform(*p, "u", {-0.0f});
  run.set_uniform(*p, "w", {-0.0f});
  run.set_varying(*p, "v", 0, [](int l) { return l / 8.0f; });
  run.run(*p);
  for (int l = 0; l < kLanes; ++l) {
    for (int c : {0, 2}) EXPECT_EQ(run.block.color[0][c][l], -std::numeric_limits<float>::infinity()) << c << " " << l;
    for (int c : {1, 3}) EXPECT_TRUE(std::signbit(run.block.color[0][c][l])) << c << " " << l;
  }
}

}  // namespace
}  // namespace pineda::shader::test
