// GLSL language features over lanes: constructors, arrays, structs, matrices, sampler
// arrays, ES 1.00 programs.
#include "tests/shader/shader_test_util.h"

namespace pineda::shader::test {
namespace {

float lane_index(int l, int c) { return static_cast<float>(l + 100 * c); }

TEST(Language, ConstArraysAndArrayConstructors120) {
  ExprResult r = run_fragment(
      "int i = int(mod(a.x, 3.0));\n"
      "float arr[2] = float[](a.x, a.y);\n"
      "gl_FragColor = vec4(k[i], arr[1], k.length(), arr[i > 0 ? 1 : 0]);",
      lane_index, nullptr, "#version 120\nconst float k[3] = float[3](1.0, 2.0, 3.0);\n");
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(r.c[0][l], 1.0f + l % 3) << l;
    EXPECT_EQ(r.c[1][l], l + 100.0f) << l;
    EXPECT_EQ(r.c[2][l], 3.0f) << l;
    EXPECT_EQ(r.c[3][l], l % 3 > 0 ? l + 100.0f : static_cast<float>(l)) << l;
  }
}

TEST(Language, MatrixConstructorsAndArithmetic) {
  ExprResult r = run_fragment(
      "mat4 m4 = mat4(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0, a.x);\n"
      "mat3 m3 = mat3(m4);\n"
      "mat4 back = mat4(mat2(a.x));\n"
      "mat2 sum = mat2(1.0) + mat2(2.0) * 3.0 - mat2(a.x) / 2.0;\n"
      "vec2 v = vec2(1.0, 1.0); v *= mat2(1.0, 2.0, 3.0, 4.0);\n"
      "gl_FragColor = vec4(m3[2][2] + m3[0][1], back[3][3] + back[1][1] + back[2][1], sum[0][0] + sum[1][0], v.y);",
      lane_index, nullptr, "#version 120\n");
  for (int l = 0; l < kLanes; ++l) {
    const float x = static_cast<float>(l);
    EXPECT_EQ(r.c[0][l], 11.0f + 2.0f) << l;
    EXPECT_EQ(r.c[1][l], 1.0f + x + 0.0f) << l;
    EXPECT_EQ(r.c[2][l], (1.0f + 6.0f) - x / 2.0f + 0.0f) << l;
    EXPECT_EQ(r.c[3][l], 7.0f) << l;
  }
}

TEST(Language, VectorConstructorsAndBools) {
  ExprResult r = run_fragment(
      "vec4 v = vec4(a.xy, vec2(3.0));\n"
      "bvec2 b = bvec2(a.x, 0.0);\n"
      "ivec3 iv = ivec3(a.xyz * 0.5);\n"
      "gl_FragColor = vec4(v.w + v.x, float(b.x) + float(b.y) * 10.0, float(iv.x), float(int(true)) + float(a.x > 3.0 ^^ a.x > 8.0));",
      lane_index);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(r.c[0][l], 3.0f + l) << l;
    EXPECT_EQ(r.c[1][l], l != 0 ? 1.0f : 0.0f) << l;
    EXPECT_EQ(r.c[2][l], static_cast<float>(l / 2)) << l;
    EXPECT_EQ(r.c[3][l], 1.0f + (((l > 3) != (l > 8)) ? 1.0f : 0.0f)) << l;
  }
}

TEST(Language, StructEqualityAndNestedCalls) {
  ExprResult r = run_fragment(
      "P p = make(a.x); P q = make(floor(a.x / 2.0) * 2.0);\n"
      "gl_FragColor = vec4(p == q ? 1.0 : 0.0, p != q ? 1.0 : 0.0, twice(twice(a.x)), twice(a.x) + twice(1.0));",
      lane_index, nullptr,
      "struct P { float x; vec2 y; };\n"
      "float twice(float v) { return v * 2.0; }\n"
      "P make(float v) { P p; p.x = v; p.y = vec2(twice(v), 1.0); return p; }\n");
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(r.c[0][l], l % 2 == 0 ? 1.0f : 0.0f) << l;
    EXPECT_EQ(r.c[1][l], l % 2 == 0 ? 0.0f : 1.0f) << l;
    EXPECT_EQ(r.c[2][l], 4.0f * l) << l;
    EXPECT_EQ(r.c[3][l], 2.0f * l + 2.0f) << l;
  }
}

TEST(Language, TernaryAndCommaWithSideEffects) {
  ExprResult r = run_fragment(
      "float n = 0.0;\n"
      "float t = a.x > 7.0 ? (n += 1.0) : (n -= 1.0);\n"
      "float c = (n += 10.0, n * 2.0);\n"
      "gl_FragColor = vec4(n, t, c, 0.0);",
      lane_index);
  for (int l = 0; l < kLanes; ++l) {
    const float n = (l > 7 ? 1.0f : -1.0f) + 10.0f;
    EXPECT_EQ(r.c[0][l], n) << l;
    EXPECT_EQ(r.c[1][l], l > 7 ? 1.0f : -1.0f) << l;
    EXPECT_EQ(r.c[2][l], 2.0f * n) << l;
  }
}

TEST(Language, UniformArrayDynamicIndex) {
  auto p = link_ok("", "uniform vec2 table[4];\nuniform float scale[2];\nvarying float v;\n"
                       "void main() { int i = int(v); gl_FragColor = vec4(table[i], scale[1], table[3 - i].x); }\n");
  ASSERT_TRUE(p);
  FragmentRun run(*p);
  const Uniform* t = find_uniform(*p, "table[0]");
  ASSERT_TRUE(t);
  for (int e = 0; e < 4; ++e) {
    run.uniforms[t->offset + e * t->stride] = 10.0f * e;
    run.uniforms[t->offset + e * t->stride + 1] = 10.0f * e + 1.0f;
  }
  run.set_uniform(*p, "scale[0]", {0.0f, 7.0f});
  run.set_varying(*p, "v", 0, [](int l) { return static_cast<float>(l % 4); });
  run.run(*p);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(run.block.color[0][0][l], 10.0f * (l % 4)) << l;
    EXPECT_EQ(run.block.color[0][1][l], 10.0f * (l % 4) + 1.0f) << l;
    EXPECT_EQ(run.block.color[0][2][l], 7.0f) << l;
    EXPECT_EQ(run.block.color[0][3][l], 10.0f * (3 - l % 4)) << l;
  }
}

TEST(Language, SamplerArrays) {
  auto p = link_ok("", "uniform sampler2D s[2];\nvoid main() { gl_FragColor = texture2D(s[1], vec2(0.0)) + texture2D(s[0], vec2(0.0)); }\n");
  ASSERT_TRUE(p);
  const Uniform* s = find_uniform(*p, "s[0]");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->array_size, 2);
  EXPECT_EQ(s->type.base, BaseType::Sampler2D);
  struct Units : TextureAccess {
    void sample(int unit, SamplerKind, const float (*)[kLanes], LodMode, const float*, LaneMask,
                float (*out)[kLanes]) const override {
      for (int c = 0; c < 4; ++c)
        for (int l = 0; l < kLanes; ++l) out[c][l] = unit == 6 ? 100.0f : (unit == 2 ? 1.0f : -1000.0f);
    }
  } units;
  FragmentRun run(*p);
  run.uniforms[s->offset] = 2.0f;
  run.uniforms[s->offset + 1] = 6.0f;
  run.run(*p, &units);
  EXPECT_EQ(run.block.color[0][0][0], 101.0f);
}

TEST(Language, WhileTrueWithBreakAndFragColorInBranch) {
  ExprResult r = run_fragment(
      "float i = 0.0;\n"
      "while (true) { i += 1.0; if (i > a.x) break; }\n"
      "if (a.x > 10.0) gl_FragColor = vec4(i); else gl_FragColor = vec4(-i);",
      lane_index);
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(r.c[0][l], l > 10 ? l + 1.0f : -(l + 1.0f)) << l;
}

TEST(Language, TexCoordDynamicIndexInFragmentShader) {
  auto p = link_ok("", "varying vec4 gl_TexCoord[6];\nuniform int n;\nvoid main() { gl_FragColor = gl_TexCoord[n]; }\n");
  ASSERT_TRUE(p);
  EXPECT_EQ(find_varying(*p, "gl_TexCoord[6]"), nullptr);
  const Varying* t0 = find_varying(*p, "gl_TexCoord[0]");
  const Varying* t5 = find_varying(*p, "gl_TexCoord[5]");
  ASSERT_TRUE(t0 && t5);
  FragmentRun run(*p);
  run.set_uniform(*p, "n", {5.0f});
  for (int l = 0; l < kLanes; ++l) run.varyings[(t5->offset + 2) * kLanes + l] = 42.0f;
  run.run(*p);
  EXPECT_EQ(run.block.color[0][2][9], 42.0f);
}

TEST(Language, Es100ProgramRuns) {
  const char* vs =
      "attribute vec4 position;\nattribute vec2 texcoord;\nuniform mat4 mvp;\nvarying mediump vec2 uv;\n"
      "void main() { uv = texcoord; gl_Position = mvp * position; }\n";
  const char* fs =
      "precision mediump float;\nvarying vec2 uv;\nuniform vec4 color;\n"
      "void main() {\n"
      "  float d = 0.0;\n"
      "  for (int i = 0; i < 3; i++) d += uv.x;\n"
      "  gl_FragColor = vec4(d, uv.y, 0.0, 1.0) * color;\n"
      "}\n";
  auto p = link_ok(vs, fs, Language::Es100);
  ASSERT_TRUE(p);
  EXPECT_EQ(find_attribute(*p, "position")->builtin, BuiltinAttribute::None);
  FragmentRun run(*p);
  run.set_uniform(*p, "color", {1.0f, 2.0f, 1.0f, 1.0f});
  run.set_varying(*p, "uv", 0, [](int l) { return l * 0.25f; });
  run.set_varying(*p, "uv", 1, [](int) { return 0.5f; });
  run.run(*p);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(run.block.color[0][0][l], l * 0.25f + l * 0.25f + l * 0.25f) << l;
    EXPECT_EQ(run.block.color[0][1][l], 1.0f) << l;
  }
}

TEST(Language, EsFragDataZero) {
  auto p = link_ok("", "precision mediump float;\nvoid main() { gl_FragData[0] = vec4(0.5); }\n", Language::Es100);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->draw_buffers_written(), 1);
}

TEST(Language, DeepExpressionsAndManyRegistersRun) {
  // More registers than the executor keeps on its stack.
  std::string body = "float s = 0.0;\n";
  for (int i = 0; i < 300; ++i) body += "float v" + std::to_string(i) + " = a.x * " + std::to_string(i) + ".0 + a.y;\n";
  body += "s = 0.0";
  for (int i = 0; i < 300; ++i) body += " + v" + std::to_string(i);
  body += ";\ngl_FragColor = vec4(s);";
  ExprResult r = run_fragment(body, [](int, int c) { return c == 0 ? 1.0f : 0.0f; });
  EXPECT_EQ(r.c[0][3], 299.0f * 300.0f / 2.0f);
}

}  // namespace
}  // namespace pineda::shader::test

namespace pineda::shader::test {
namespace {

TEST(Language, UniformWithInitializerStaysAUniform) {
  auto p = link_ok("", "#version 120\nuniform float k = 2.0;\nstruct S { vec2 a; int b; };\n"
                       "uniform S s[2] = S[2](S(vec2(1.0, 2.0), 3), S(vec2(4.0, 5.0), 6));\nuniform float plain;\n"
                       "void main() { gl_FragColor = vec4(k, s[1].a, float(s[0].b) + plain); }\n");
  ASSERT_TRUE(p);
  ASSERT_TRUE(find_uniform(*p, "k"));
  EXPECT_EQ(find_uniform(*p, "k")->initial, std::vector<float>({2.0f}));
  EXPECT_EQ(find_uniform(*p, "s[1].a")->initial, std::vector<float>({4.0f, 5.0f}));
  EXPECT_EQ(find_uniform(*p, "s[0].b")->initial, std::vector<float>({3.0f}));
  EXPECT_TRUE(find_uniform(*p, "plain")->initial.empty());
  FragmentRun run(*p);
  run.set_uniform(*p, "k", {7.0f});
  run.run(*p);
  EXPECT_EQ(run.block.color[0][0][0], 7.0f);
}

}  // namespace
}  // namespace pineda::shader::test
