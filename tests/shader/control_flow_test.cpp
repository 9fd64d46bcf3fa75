// Divergent control flow over lanes: if/else, loops with per-lane break and continue,
// early returns from inlined functions, discard, and the iteration bound.
#include "tests/shader/shader_test_util.h"

namespace pineda::shader::test {
namespace {

float lane_index(int l, int) { return static_cast<float>(l); }

TEST(ControlFlow, IfElsePerLane) {
  ExprResult r = run_fragment(
      "float x;\n"
      "if (a.x < 5.0) x = 1.0; else if (a.x < 10.0) x = 2.0; else x = 3.0;\n"
      "gl_FragColor = vec4(x);",
      lane_index);
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(r.c[0][l], l < 5 ? 1.0f : (l < 10 ? 2.0f : 3.0f)) << l;
}

TEST(ControlFlow, LoopWithDivergentBreak) {
  // Lane l sums i = 0, 1, ... until i reaches l (break), at most 20 iterations.
  ExprResult r = run_fragment(
      "float sum = 0.0; int count = 0;\n"
      "for (int i = 0; i < 20; i++) {\n"
      "  if (float(i) >= a.x) break;\n"
      "  sum += float(i); count++;\n"
      "}\n"
      "gl_FragColor = vec4(sum, float(count), 0.0, 1.0);",
      lane_index);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(r.c[0][l], static_cast<float>(l * (l - 1) / 2)) << l;
    EXPECT_EQ(r.c[1][l], static_cast<float>(l)) << l;
  }
}

TEST(ControlFlow, LoopWithDivergentContinue) {
  // Sum of the i in 0..9 that are not multiples of (lane % 3 + 2).
  ExprResult r = run_fragment(
      "float sum = 0.0; float m = mod(a.x, 3.0) + 2.0;\n"
      "for (int i = 0; i < 10; ++i) {\n"
      "  if (mod(float(i), m) == 0.0) continue;\n"
      "  sum += float(i);\n"
      "}\n"
      "gl_FragColor = vec4(sum);",
      lane_index);
  for (int l = 0; l < kLanes; ++l) {
    int m = l % 3 + 2, sum = 0;
    for (int i = 0; i < 10; ++i)
      if (i % m != 0) sum += i;
    EXPECT_EQ(r.c[0][l], static_cast<float>(sum)) << l;
  }
}

TEST(ControlFlow, WhileAndDoWhile) {
  ExprResult r = run_fragment(
      "float n = a.x; float steps = 0.0;\n"
      "while (n > 1.0) { n = mod(n, 2.0) == 0.0 ? n / 2.0 : 3.0 * n + 1.0; steps += 1.0; }\n"
      "float d = 0.0; do { d += 1.0; } while (d < a.x);\n"
      "gl_FragColor = vec4(steps, d, 0.0, 0.0);",
      lane_index);
  for (int l = 0; l < kLanes; ++l) {
    int n = l, steps = 0;
    while (n > 1) {
      n = n % 2 == 0 ? n / 2 : 3 * n + 1;
      ++steps;
    }
    EXPECT_EQ(r.c[0][l], static_cast<float>(steps)) << l;
    EXPECT_EQ(r.c[1][l], static_cast<float>(l < 1 ? 1 : l)) << l;
  }
}

TEST(ControlFlow, NestedLoopsBreakOnlyInner) {
  ExprResult r = run_fragment(
      "float total = 0.0;\n"
      "for (int i = 0; i < 4; i++) {\n"
      "  for (int j = 0; j < 4; j++) {\n"
      "    if (float(j) > a.x - float(i)) break;\n"
      "    total += 1.0;\n"
      "  }\n"
      "}\n"
      "gl_FragColor = vec4(total);",
      lane_index);
  for (int l = 0; l < kLanes; ++l) {
    int total = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        if (j > l - i) break;
        ++total;
      }
    EXPECT_EQ(r.c[0][l], static_cast<float>(total)) << l;
  }
}

TEST(ControlFlow, EarlyReturnFromFunction) {
  ExprResult s = run_fragment("gl_FragColor = vec4(classify(a.x), classify(a.x + 100.0), 0.0, 0.0);", lane_index, nullptr,
                              "float classify(float x) {\n"
                              "  if (x < 4.0) return -1.0;\n"
                              "  for (int i = 0; i < 16; i++) { if (float(i) == x) return float(i) * 10.0; }\n"
                              "  return 99.0;\n"
                              "}\n");
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(s.c[0][l], l < 4 ? -1.0f : 10.0f * l) << l;
    EXPECT_EQ(s.c[1][l], 99.0f) << l;
  }
}

TEST(ControlFlow, OutAndInoutParameters) {
  ExprResult s = run_fragment("float lo, hi = a.x; split(a.x, lo, hi);\ngl_FragColor = vec4(lo, hi, 0.0, 0.0);", lane_index,
                              nullptr,
                              "void split(float x, out float lo, inout float hi) {\n"
                              "  lo = floor(x / 4.0); hi = hi * 2.0 + lo;\n"
                              "}\n");
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(s.c[0][l], static_cast<float>(l / 4)) << l;
    EXPECT_EQ(s.c[1][l], static_cast<float>(2 * l + l / 4)) << l;
  }
}

TEST(ControlFlow, ReturnFromMain) {
  ExprResult s = run_fragment("gl_FragColor = vec4(1.0);\nif (a.x > 7.0) return;\ngl_FragColor = vec4(2.0);", lane_index);
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(s.c[0][l], l > 7 ? 1.0f : 2.0f) << l;
}

TEST(ControlFlow, DiscardClearsLiveLanes) {
  auto p = link_ok("", "varying float v;\nvoid main() {\n  if (v > 0.5) discard;\n  gl_FragColor = vec4(v);\n}\n");
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->uses_discard());
  FragmentRun run(*p);
  run.set_varying(*p, "v", 0, [](int l) { return (l % 3) == 0 ? 1.0f : 0.0f; });
  run.block.live = 0xFF0F;
  run.run(*p);
  LaneMask expected = 0;
  for (int l = 0; l < kLanes; ++l)
    if ((0xFF0F >> l & 1) && l % 3 != 0) expected |= static_cast<LaneMask>(1 << l);
  EXPECT_EQ(run.block.live, expected);
  for (int l = 0; l < kLanes; ++l) {
    if (expected >> l & 1) {
      EXPECT_EQ(run.block.color[0][0][l], 0.0f);
    }
  }
}

TEST(ControlFlow, DiscardInsideLoopAndFunction) {
  auto p = link_ok("", "varying float v;\n"
                       "void check(float x) { for (int i = 0; i < 8; i++) { if (float(i) == x) discard; } }\n"
                       "void main() { check(v); gl_FragColor = vec4(v); }\n");
  ASSERT_TRUE(p);
  FragmentRun run(*p);
  run.set_varying(*p, "v", 0, [](int l) { return static_cast<float>(l); });
  run.run(*p);
  EXPECT_EQ(run.block.live, 0xFF00);
  for (int l = 8; l < kLanes; ++l) EXPECT_EQ(run.block.color[0][0][l], static_cast<float>(l));
}

TEST(ControlFlow, DiscardEverything) {
  ExprResult s = run_fragment("discard;", lane_index);
  EXPECT_EQ(s.live, 0);
}

TEST(ControlFlow, UnboundedLoopEnds) {
  // An infinite loop stops at the iteration bound instead of hanging.
  ExprResult s = run_fragment("float x = 0.0;\nwhile (a.x >= 0.0) { x += 1.0; }\ngl_FragColor = vec4(x > 1000.0 ? 1.0 : 0.0);",
                              lane_index);
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(s.c[0][l], 1.0f);
}

TEST(ControlFlow, ShortCircuitWithSideEffects) {
  ExprResult s = run_fragment(
      "float n = 0.0;\n"
      "bool t = a.x > 7.0 && bump(n);\n"
      "bool u = a.x > 3.0 || bump(n);\n"
      "gl_FragColor = vec4(n, float(t), float(u), 0.0);",
      lane_index, nullptr, "bool bump(inout float n) { n += 1.0; return true; }\n");
  for (int l = 0; l < kLanes; ++l) {
    float n = (l > 7 ? 1.0f : 0.0f) + (l > 3 ? 0.0f : 1.0f);
    EXPECT_EQ(s.c[0][l], n) << l;
    EXPECT_EQ(s.c[1][l], l > 7 ? 1.0f : 0.0f) << l;
    EXPECT_EQ(s.c[2][l], 1.0f) << l;
  }
}

TEST(ControlFlow, DynamicIndexingOfArraysAndVectors) {
  ExprResult s = run_fragment(
      "float t[4]; t[0] = 10.0; t[1] = 20.0; t[2] = 30.0; t[3] = 40.0;\n"
      "int i = int(mod(a.x, 4.0));\n"
      "t[i] += 1.0;\n"
      "vec4 v = vec4(1.0, 2.0, 3.0, 4.0);\n"
      "v[i] = 0.0;\n"
      "gl_FragColor = vec4(t[i], t[3 - i], v.x + v.y + v.z + v.w, t[int(a.x) + 100]);",
      lane_index);
  for (int l = 0; l < kLanes; ++l) {
    int i = l % 4;
    float t[4] = {10, 20, 30, 40};
    t[i] += 1.0f;
    EXPECT_EQ(s.c[0][l], t[i]) << l;
    EXPECT_EQ(s.c[1][l], t[3 - i]) << l;
    EXPECT_EQ(s.c[2][l], 10.0f - (i + 1)) << l;
    EXPECT_EQ(s.c[3][l], t[3]) << l;  // out of range: clamped to the last element
  }
}

TEST(ControlFlow, SwizzleAssignmentReadsBeforeWriting) {
  ExprResult s = run_fragment("vec4 v = a; v.xy = v.yx; v.zw = v.wz * 2.0; gl_FragColor = v;",
                              [](int l, int c) { return static_cast<float>(l * 4 + c); });
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(s.c[0][l], static_cast<float>(l * 4 + 1));
    EXPECT_EQ(s.c[1][l], static_cast<float>(l * 4 + 0));
    EXPECT_EQ(s.c[2][l], static_cast<float>(2 * (l * 4 + 3)));
    EXPECT_EQ(s.c[3][l], static_cast<float>(2 * (l * 4 + 2)));
  }
}

TEST(ControlFlow, PrePostIncrement) {
  ExprResult s = run_fragment("float x = a.x; float y = x++; float z = ++x; gl_FragColor = vec4(x, y, z, x--);", lane_index);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(s.c[0][l], l + 2.0f);
    EXPECT_EQ(s.c[1][l], l + 0.0f);
    EXPECT_EQ(s.c[2][l], l + 2.0f);
    EXPECT_EQ(s.c[3][l], l + 2.0f);
  }
}

TEST(ControlFlow, GlobalInitializersAndStructs) {
  ExprResult s = run_fragment("S s = S(a.x, vec2(2.0, g));\ns.v.y += 1.0;\ngl_FragColor = vec4(s.f, s.v, g);", lane_index,
                              nullptr, "struct S { float f; vec2 v; };\nfloat g = a.x * 2.0;\n");
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(s.c[0][l], static_cast<float>(l));
    EXPECT_EQ(s.c[1][l], 2.0f);
    EXPECT_EQ(s.c[2][l], 2.0f * l + 1.0f);
    EXPECT_EQ(s.c[3][l], 2.0f * l);
  }
}

}  // namespace
}  // namespace pineda::shader::test

namespace pineda::shader::test {
namespace {

TEST(ControlFlow, DynamicIndexIntoASwizzleWritesTheVariable) {
  ExprResult s = run_fragment(
      "int i = int(mod(a.x, 4.0));\n"
      "vec4 c = vec4(10.0, 20.0, 30.0, 40.0);\n"
      "c.wzyx[i] = -1.0;\n"
      "gl_FragColor = vec4(c.wzyx[i] + c.x, c.y, c.z, c.w);",
      [](int l, int) { return static_cast<float>(l); });
  for (int l = 0; l < kLanes; ++l) {
    float c[4] = {10, 20, 30, 40};
    c[3 - l % 4] = -1.0f;
    EXPECT_EQ(s.c[0][l], -1.0f + c[0]) << l;
    EXPECT_EQ(s.c[1][l], c[1]) << l;
    EXPECT_EQ(s.c[2][l], c[2]) << l;
    EXPECT_EQ(s.c[3][l], c[3]) << l;
  }
}

}  // namespace
}  // namespace pineda::shader::test
