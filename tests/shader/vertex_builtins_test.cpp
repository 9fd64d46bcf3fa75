// Vertex-stage outputs: gl_Position, gl_PointSize, ftransform, and the built-in varyings
// that feed the fragment stage's gl_Color, gl_SecondaryColor, gl_TexCoord, gl_FogFragCoord.
#include "tests/shader/shader_test_util.h"

namespace pineda::shader::test {
namespace {

TEST(VertexBuiltins, FtransformAndPointSize) {
  auto p = link_ok("void main() { gl_Position = ftransform(); gl_PointSize = gl_Vertex.x + 1.0; }\n", "");
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->writes_point_size());
  const Uniform* mvp = find_uniform(*p, "gl_ModelViewProjectionMatrix");
  ASSERT_TRUE(mvp);
  VertexRun run(*p, 7);
  run.set_uniform(*p, "gl_ModelViewProjectionMatrix", {1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 3, 0, 10, 20, 30, 1});
  for (int c = 0; c < 4; ++c) run.set_input(*p, "gl_Vertex", c, [](int l) { return l + 1.0f; });
  run.run(*p);
  for (int l = 0; l < 7; ++l) {
    const float v = l + 1.0f;
    EXPECT_EQ(run.out(kOutPosition + 0, l), v + 10.0f * v);
    EXPECT_EQ(run.out(kOutPosition + 1, l), 2.0f * v + 20.0f * v);
    EXPECT_EQ(run.out(kOutPosition + 2, l), 3.0f * v + 30.0f * v);
    EXPECT_EQ(run.out(kOutPosition + 3, l), v);
    EXPECT_EQ(run.out(kOutPointSize, l), v + 1.0f);
  }
}

TEST(VertexBuiltins, ColoursRouteToFragmentInputsWithBackPair) {
  auto p = link_ok("void main() {\n"
                   "  gl_Position = gl_Vertex;\n"
                   "  gl_FrontColor = vec4(1.0, 0.0, 0.0, 1.0);\n"
                   "  gl_BackColor = vec4(0.0, 1.0, 0.0, 1.0);\n"
                   "  gl_FrontSecondaryColor = vec4(0.5);\n"
                   "  gl_TexCoord[1] = gl_MultiTexCoord1 * 2.0;\n"
                   "  gl_FogFragCoord = 3.0;\n"
                   "}\n",
                   "void main() { gl_FragColor = gl_Color + gl_SecondaryColor + gl_TexCoord[1] + vec4(gl_FogFragCoord); }\n");
  ASSERT_TRUE(p);
  const Varying* color = find_varying(*p, "gl_Color");
  const Varying* secondary = find_varying(*p, "gl_SecondaryColor");
  const Varying* tc1 = find_varying(*p, "gl_TexCoord[1]");
  const Varying* fog = find_varying(*p, "gl_FogFragCoord");
  ASSERT_TRUE(color && secondary && tc1 && fog);
  EXPECT_GE(color->back_offset, 0);
  EXPECT_EQ(secondary->back_offset, -1);  // gl_BackSecondaryColor is not written
  EXPECT_EQ(fog->components, 1);
  VertexRun run(*p);
  run.set_input(*p, "gl_MultiTexCoord1", 2, [](int l) { return static_cast<float>(l); });
  run.run(*p);
  EXPECT_EQ(run.out(kOutFirstVarying + color->offset + 0, 4), 1.0f);
  EXPECT_EQ(run.out(kOutFirstVarying + color->offset + 1, 4), 0.0f);
  EXPECT_EQ(run.out(kOutFirstVarying + color->back_offset + 0, 4), 0.0f);
  EXPECT_EQ(run.out(kOutFirstVarying + color->back_offset + 1, 4), 1.0f);
  EXPECT_EQ(run.out(kOutFirstVarying + secondary->offset + 2, 4), 0.5f);
  EXPECT_EQ(run.out(kOutFirstVarying + tc1->offset + 2, 4), 8.0f);
  EXPECT_EQ(run.out(kOutFirstVarying + fog->offset, 4), 3.0f);
  // Every output float is written (unwritten ones hold 0).
  for (int i = 0; i < kOutFirstVarying + p->varying_floats(); ++i) EXPECT_NE(run.out(i, 0), -99.0f) << i;

  FragmentRun frag(*p);
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < kLanes; ++l) {
      frag.varyings[(color->offset + c) * kLanes + l] = 0.25f;
      frag.varyings[(tc1->offset + c) * kLanes + l] = 1.0f;
    }
  for (int l = 0; l < kLanes; ++l) frag.varyings[fog->offset * kLanes + l] = 2.0f;
  frag.run(*p);
  EXPECT_EQ(frag.block.color[0][0][3], 0.25f + 0.0f + 1.0f + 2.0f);
}

TEST(VertexBuiltins, WithoutFragmentShaderOutputsFeedFixedFunction) {
  auto p = link_ok("void main() { gl_Position = gl_Vertex; gl_FrontColor = gl_Color; gl_TexCoord[0] = gl_MultiTexCoord0; }\n", "");
  ASSERT_TRUE(p);
  const Varying* color = find_varying(*p, "gl_Color");
  ASSERT_TRUE(color);
  EXPECT_EQ(color->back_offset, -1);
  ASSERT_TRUE(find_varying(*p, "gl_TexCoord[0]"));
  VertexRun run(*p);
  run.set_input(*p, "gl_Color", 1, [](int l) { return l * 0.5f; });
  run.run(*p);
  EXPECT_EQ(run.out(kOutFirstVarying + color->offset + 1, 1), 0.5f);
  EXPECT_EQ(run.out(kOutFirstVarying + color->offset + 1, 6), 1.0f);  // 3 clamped (GL 2.0 2.14.7)
}

TEST(VertexBuiltins, FragmentShaderWithoutVertexShaderGetsBothColours) {
  auto p = link_ok("", "void main() { gl_FragColor = gl_Color * gl_TexCoord[0]; }\n");
  ASSERT_TRUE(p);
  const Varying* color = find_varying(*p, "gl_Color");
  ASSERT_TRUE(color);
  EXPECT_GE(color->back_offset, 0);
  EXPECT_LE(color->back_offset + 4, p->varying_floats());
  ASSERT_TRUE(find_varying(*p, "gl_TexCoord[0]"));
}

TEST(VertexBuiltins, LanesPastCountAreNotRequired) {
  auto p = link_ok("attribute float x;\nvoid main() { float s = 0.0; for (int i = 0; i < 100; i++) { if (float(i) > x) break; s += 1.0; } gl_Position = vec4(s); }\n", "");
  ASSERT_TRUE(p);
  VertexRun run(*p, 3);
  run.set_input(*p, "x", 0, [](int l) { return l < 3 ? static_cast<float>(l) : 1e30f; });
  run.run(*p);
  EXPECT_EQ(run.out(kOutPosition, 0), 1.0f);
  EXPECT_EQ(run.out(kOutPosition, 2), 3.0f);
}

TEST(VertexBuiltins, UserVaryingArrays) {
  auto p = link_ok("varying vec2 v[3];\nvoid main() { gl_Position = vec4(0.0); for (int i = 0; i < 3; i++) v[i] = vec2(float(i), 1.0); }\n",
                   "varying vec2 v[3];\nvoid main() { gl_FragColor = vec4(v[0], v[2]); }\n");
  ASSERT_TRUE(p);
  const Varying* v2 = find_varying(*p, "v[2]");
  ASSERT_TRUE(v2);
  EXPECT_EQ(v2->components, 2);
  VertexRun run(*p);
  run.run(*p);
  EXPECT_EQ(run.out(kOutFirstVarying + v2->offset, 0), 2.0f);
  EXPECT_EQ(run.out(kOutFirstVarying + v2->offset + 1, 0), 1.0f);
}

}  // namespace
}  // namespace pineda::shader::test

namespace pineda::shader::test {
namespace {

TEST(VertexBuiltins, UnsizedTexCoordTakesItsHighestIndex) {
  auto p = link_ok("void main() { gl_Position = gl_Vertex; gl_TexCoord[2] = gl_MultiTexCoord2; }\n", "");
  ASSERT_TRUE(p);
  EXPECT_TRUE(find_varying(*p, "gl_TexCoord[2]"));
  EXPECT_EQ(find_varying(*p, "gl_TexCoord[3]"), nullptr);
  EXPECT_EQ(p->varying_floats(), 12);
}

}  // namespace
}  // namespace pineda::shader::test
