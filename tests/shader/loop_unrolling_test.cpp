// Loops with a trip count known at link time become straight-line code (shader/unroll_loops.h),
// and variables assigned several times get a register per value (shader/rename_values.h):
// the IR shrinks and every value stays what the loop computed.
#include <cmath>

#include "tests/shader/shader_test_util.h"

namespace pineda::shader::test {
namespace {

float lane_index(int l, int) { return static_cast<float>(l); }

std::string fragment_ir(const std::string& body) {
  auto p = link_ok("", "varying vec4 a;\nuniform float u;\nvoid main() {\n" + body + "\n}\n");
  return p ? dump_ir(*p) : std::string();
}

TEST(LoopUnrolling, ConstantLoopBecomesStraightLine) {
  const std::string body =
      "float s = 0.0;\n"
      "for (int i = 0; i < 4; i++) s += a.x * float(i);\n"
      "gl_FragColor = vec4(s);";
  const std::string ir = fragment_ir(body);
  EXPECT_EQ(count_ops(ir, "loop"), 0) << ir;
  EXPECT_EQ(count_ops(ir, "break_if_not"), 0) << ir;
  EXPECT_EQ(count_ops(ir, "lt"), 0) << ir;
  ExprResult r = run_fragment(body, lane_index);
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(r.c[0][l], ((0.0f + l * 0.0f) + l * 1.0f + l * 2.0f) + l * 3.0f) << l;
}

TEST(LoopUnrolling, NestedLoopsAndTheCounterAfterTheLoop) {
  const std::string body =
      "float s = 0.0; int i = 0;\n"
      "for (; i < 3; i++) for (int j = 0; j < 2; j++) s += float(i * 2 + j) + a.x;\n"
      "gl_FragColor = vec4(s, float(i), 0.0, 1.0);";
  const std::string ir = fragment_ir(body);
  EXPECT_EQ(count_ops(ir, "loop"), 0) << ir;
  ExprResult r = run_fragment(body, lane_index);
  for (int l = 0; l < kLanes; ++l) {
    float s = 0.0f;
    for (int k = 0; k < 6; ++k) s += static_cast<float>(k) + static_cast<float>(l);
    EXPECT_EQ(r.c[0][l], s) << l;
    EXPECT_EQ(r.c[1][l], 3.0f) << l;
  }
}

TEST(LoopUnrolling, FloatCounterStepsAsTheLoopWould) {
  const std::string body =
      "float n = 0.0;\n"
      "for (float x = 0.0; x < 1.0; x += 0.1) n += 1.0;\n"
      "gl_FragColor = vec4(n);";
  EXPECT_EQ(count_ops(fragment_ir(body), "loop"), 0);
  float n = 0.0f;
  for (float x = 0.0f; x < 1.0f; x += 0.1f) n += 1.0f;
  ExprResult r = run_fragment(body, lane_index);
  EXPECT_EQ(r.c[0][0], n);
}

TEST(LoopUnrolling, LoopsThatCannotBeCountedStay) {
  // A bound from a uniform, a break, a counter changed in the body, too many iterations.
  EXPECT_EQ(count_ops(fragment_ir("float s = 0.0; for (int i = 0; i < int(u); i++) s += 1.0; gl_FragColor = vec4(s);"), "loop"), 1);
  EXPECT_EQ(count_ops(fragment_ir("float s = 0.0; for (int i = 0; i < 8; i++) { if (a.x > s) break; s += 1.0; } gl_FragColor = vec4(s);"), "loop"), 1);
  EXPECT_EQ(count_ops(fragment_ir("float s = 0.0; for (int i = 0; i < 8; i++) { s += 1.0; if (a.x > s) i++; } gl_FragColor = vec4(s);"), "loop"), 1);
  const std::string many = "float s = 0.0; for (int i = 0; i < 1000; i++) s += a.x; gl_FragColor = vec4(s);";
  EXPECT_EQ(count_ops(fragment_ir(many), "loop"), 1);
  ExprResult r = run_fragment(many, lane_index);
  float s = 0.0f;
  for (int i = 0; i < 1000; ++i) s += 5.0f;
  EXPECT_EQ(r.c[0][5], s);
}

TEST(LocalRenaming, ReassignedVariablesNeedNoCopies) {
  // q is written three times: each value gets its own register and no copy survives.
  const std::string body =
      "vec3 q = fract(a.xyx * 0.1031);\n"
      "q += dot(q, q.yzx + 33.33);\n"
      "q = q * 2.0;\n"
      "gl_FragColor = vec4(q, 1.0);";
  const std::string ir = fragment_ir(body);
  EXPECT_EQ(count_ops(ir, "mov"), 0) << ir;
  ExprResult r = run_fragment(body, [](int l, int c) { return static_cast<float>(l * 3 + c); });
  for (int l = 0; l < kLanes; ++l) {
    const float x = static_cast<float>(l * 3), y = static_cast<float>(l * 3 + 1);
    auto fract = [](float v) { return v - std::floor(v); };
    float q[3] = {fract(x * 0.1031f), fract(y * 0.1031f), fract(x * 0.1031f)};
    const float d = q[0] * (q[1] + 33.33f) + q[1] * (q[2] + 33.33f) + q[2] * (q[0] + 33.33f);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(r.c[c][l], (q[c] + d) * 2.0f) << l << " " << c;
  }
}

}  // namespace
}  // namespace pineda::shader::test
