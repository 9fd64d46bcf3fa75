// Deeply nested shaders (found by the GLSL fuzzer: a long `a + a + ...` chain overflowed the
// stack in the lowering) are compile or link errors with a log that says why, never a crash.
#include "tests/shader/shader_test_util.h"

namespace pineda::shader::test {
namespace {

std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

std::string sum_shader(int terms) {
  return "uniform float u;\nvoid main() { float a = u; gl_FragColor = vec4(" + repeat("a + ", terms - 1) + "a); }\n";
}

TEST(NestingLimit, LongSumRuns) {
  auto p = link_ok("", sum_shader(400));
  ASSERT_NE(p, nullptr);
  FragmentRun run(*p);
  run.set_uniform(*p, "u", {0.5f});
  run.run(*p);
  EXPECT_EQ(run.block.color[0][0][0], 200.0f);
}

TEST(NestingLimit, TreeDeeperThanTheLimitIsACompileError) {
  CompileResult r = compile(Stage::Fragment, Language::Desktop, {sum_shader(30000)});
  EXPECT_EQ(r.shader, nullptr);
  EXPECT_NE(r.info_log.find("ERROR: 0:0: '' : expressions and statements nested too deeply ("), std::string::npos)
      << r.info_log;
  EXPECT_NE(r.info_log.find(" levels, at most 1024)"), std::string::npos) << r.info_log;
}

TEST(NestingLimit, NestedBuiltInCallsAreALinkError) {
  const std::string fs = "uniform float u;\nvoid main() { gl_FragColor = vec4(" + repeat("sqrt(", 700) + "u" +
                         repeat(")", 700) + "); }\n";
  auto f = compile_ok(Stage::Fragment, fs);
  ASSERT_NE(f, nullptr);
  LinkResult r = link(nullptr, f.get(), {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_EQ(r.info_log, "error: expressions nested too deeply (more than 512 levels, through inlined calls)\n");
}

// Each function is shallow; inlined into each other they are 8 x 100 levels deep.
TEST(NestingLimit, DepthAddsUpThroughInlinedCalls) {
  std::string fs = "uniform float u;\nfloat f0(float x) { return x; }\n";
  for (int i = 1; i <= 8; ++i)
    fs += "float f" + std::to_string(i) + "(float x) { return " + repeat("x + (", 100) + "f" + std::to_string(i - 1) +
          "(x)" + repeat(")", 100) + "; }\n";
  fs += "void main() { gl_FragColor = vec4(f8(u)); }\n";
  auto f = compile_ok(Stage::Fragment, fs);
  ASSERT_NE(f, nullptr);
  LinkResult r = link(nullptr, f.get(), {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_EQ(r.info_log, "error: expressions nested too deeply (more than 512 levels, through inlined calls)\n");
}

}  // namespace
}  // namespace pineda::shader::test
