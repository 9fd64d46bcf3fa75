// Fragment-stage built-ins: derivatives from the quads, gl_FragCoord, gl_FrontFacing,
// gl_PointCoord, gl_FragData, gl_FragDepth, and texture lookups through TextureAccess.
#include <limits>
#include <vector>

#include "tests/shader/shader_test_util.h"

namespace pineda::shader::test {
namespace {

// Pixel position of lane l in the block, as program.h lays lanes out.
int lane_x(int l) { return (l & 1) + 2 * ((l >> 2) & 1); }
int lane_y(int l) { return ((l >> 1) & 1) + 2 * (l >> 3); }

TEST(FragmentBuiltins, DerivativesFromQuadNeighbours) {
  // a.x = x*x + 3y: dFdx within each row pair is the difference across the quad's columns.
  ExprResult r = run_fragment("gl_FragColor = vec4(dFdx(a.x), dFdy(a.x), fwidth(a.x), 0.0);",
                              [](int l, int) { return static_cast<float>(lane_x(l) * lane_x(l) + 3 * lane_y(l)); });
  for (int l = 0; l < kLanes; ++l) {
    const int x0 = lane_x(l) & ~1;
    const float dx = static_cast<float>((x0 + 1) * (x0 + 1) - x0 * x0);
    EXPECT_EQ(r.c[0][l], dx) << l;
    EXPECT_EQ(r.c[1][l], 3.0f) << l;
    EXPECT_EQ(r.c[2][l], dx + 3.0f) << l;
  }
}

TEST(FragmentBuiltins, DerivativesUseUncoveredQuadLanes) {
  auto p = link_ok("", "#extension GL_OES_standard_derivatives : enable\nprecision mediump float;\nvarying float v;\n"
                       "void main() { gl_FragColor = vec4(dFdx(v), dFdy(v), 0.0, 1.0); }\n",
                   Language::Es100);
  ASSERT_TRUE(p);
  FragmentRun run(*p);
  run.set_varying(*p, "v", 0, [](int l) { return static_cast<float>(5 * lane_x(l) + 7 * lane_y(l)); });
  run.block.live = 0x0001;  // one covered pixel: its quad's other lanes still run
  run.run(*p);
  EXPECT_EQ(run.block.live, 0x0001);
  EXPECT_EQ(run.block.color[0][0][0], 5.0f);
  EXPECT_EQ(run.block.color[0][1][0], 7.0f);
}

TEST(FragmentBuiltins, FragCoordFrontFacingPointCoord) {
  auto p = link_ok("", "#version 120\nvoid main() {\n"
                       "  gl_FragColor = vec4(gl_FragCoord.x + 10.0 * gl_FragCoord.y, gl_FrontFacing ? 1.0 : -1.0,\n"
                       "                      gl_PointCoord.x, gl_PointCoord.y + gl_FragCoord.z);\n}\n");
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->reads("gl_FragCoord"));
  EXPECT_TRUE(p->reads("gl_FrontFacing"));
  EXPECT_TRUE(p->reads("gl_PointCoord"));
  FragmentRun run(*p);
  run.block.front_facing = 0x00F0;
  for (int l = 0; l < kLanes; ++l) {
    run.block.point_coord[0][l] = l * 0.125f;
    run.block.point_coord[1][l] = 1.0f;
  }
  run.run(*p);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(run.block.color[0][0][l], lane_x(l) + 0.5f + 10.0f * (lane_y(l) + 0.5f)) << l;
    EXPECT_EQ(run.block.color[0][1][l], (0x00F0 >> l & 1) ? 1.0f : -1.0f) << l;
    EXPECT_EQ(run.block.color[0][2][l], l * 0.125f) << l;
    EXPECT_EQ(run.block.color[0][3][l], 1.5f) << l;
  }
}

TEST(FragmentBuiltins, ProgramWithoutFragCoordDoesNotReadIt) {
  auto p = link_ok("", "void main() { gl_FragColor = vec4(1.0); }\n");
  ASSERT_TRUE(p);
  EXPECT_FALSE(p->reads("gl_FragCoord"));
  EXPECT_FALSE(p->reads("gl_FrontFacing"));
  EXPECT_FALSE(p->reads("gl_PointCoord"));
}

TEST(FragmentBuiltins, FragCoordComponentsReadAfterOptimization) {
  auto xy = link_ok("", "void main() { gl_FragColor = vec4(gl_FragCoord.x * gl_FragCoord.y); }\n");
  ASSERT_TRUE(xy);
  EXPECT_EQ(xy->frag_coord_components(), 3u);
  auto zw = link_ok("", "void main() { vec4 c = gl_FragCoord; gl_FragColor = vec4(c.z, c.w, 0.0, 1.0); }\n");
  ASSERT_TRUE(zw);
  EXPECT_EQ(zw->frag_coord_components(), 12u);
  auto none = link_ok("", "void main() { vec4 c = gl_FragCoord; gl_FragColor = vec4(1.0); }\n");
  ASSERT_TRUE(none);
  EXPECT_EQ(none->frag_coord_components(), 0u);
}

TEST(FragmentBuiltins, FragDataAndDepth) {
  auto p = link_ok("", "varying vec4 v;\nvoid main() {\n"
                       "  gl_FragData[0] = v; gl_FragData[2] = v * 2.0;\n"
                       "  gl_FragDepth = v.x * 0.5;\n}\n");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->draw_buffers_written(), 3);
  EXPECT_FALSE(p->broadcasts_color());
  EXPECT_TRUE(p->writes_depth());
  FragmentRun run(*p);
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < kLanes; ++l) run.varyings[(find_varying(*p, "v")->offset + c) * kLanes + l] = l + c * 0.25f;
  run.block.depth[3] = -5.0f;
  run.run(*p);
  for (int l = 0; l < kLanes; ++l) {
    for (int c = 0; c < 4; ++c) {
      EXPECT_EQ(run.block.color[0][c][l], l + c * 0.25f);
      EXPECT_EQ(run.block.color[1][c][l], 0.0f);  // never written
      EXPECT_EQ(run.block.color[2][c][l], 2.0f * (l + c * 0.25f));
    }
    EXPECT_EQ(run.block.depth[l], l * 0.5f);
  }
}

TEST(FragmentBuiltins, FragDataDynamicIndexCoversAllBuffers) {
  auto p = link_ok("", "uniform int which;\nvoid main() { for (int i = 0; i < 4; i++) gl_FragData[i] = vec4(float(i)); }\n");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->draw_buffers_written(), kMaxDrawBuffers);  // a dynamic index may reach any of them
  FragmentRun run(*p);
  run.run(*p);
  for (int b = 0; b < 4; ++b) EXPECT_EQ(run.block.color[b][1][7], static_cast<float>(b));
}

// Records every lookup and returns (unit, kind, s + t, lod-or-minus-one).
class RecordingTextures : public TextureAccess {
 public:
  struct Call {
    int unit;
    SamplerKind kind;
    LodMode mode;
    float coords[4][kLanes];
    bool has_lod;
    float lod[kLanes];
    LaneMask live;
  };
  mutable std::vector<Call> calls;
  void sample(int unit, SamplerKind kind, const float (*coords)[kLanes], LodMode mode, const float* lod,
              LaneMask live, float (*out)[kLanes]) const override {
    Call c{};
    c.unit = unit;
    c.kind = kind;
    c.mode = mode;
    for (int i = 0; i < 4; ++i)
      for (int l = 0; l < kLanes; ++l) c.coords[i][l] = coords[i][l];
    c.has_lod = lod != nullptr;
    for (int l = 0; l < kLanes && lod; ++l) c.lod[l] = lod[l];
    c.live = live;
    calls.push_back(c);
    for (int l = 0; l < kLanes; ++l) {
      out[0][l] = static_cast<float>(unit);
      out[1][l] = static_cast<float>(kind);
      out[2][l] = coords[0][l] + coords[1][l];
      out[3][l] = lod ? lod[l] : -1.0f;
    }
  }
};

TEST(FragmentBuiltins, TextureLookupsPassCoordinatesAndLod) {
  auto p = link_ok("", "uniform sampler2D s2;\nuniform samplerCube sc;\nvarying vec4 v;\n"
                       "void main() {\n"
                       "  vec4 a = texture2D(s2, v.xy);\n"
                       "  vec4 b = texture2D(s2, v.xy, 1.5);\n"
                       "  vec4 c = texture2DProj(s2, v);\n"
                       "  vec4 d = textureCube(sc, v.xyz);\n"
                       "  gl_FragColor = a + b + c + d;\n}\n");
  ASSERT_TRUE(p);
  const Uniform* s2 = find_uniform(*p, "s2");
  const Uniform* sc = find_uniform(*p, "sc");
  ASSERT_TRUE(s2 && sc);
  EXPECT_EQ(s2->type.base, BaseType::Sampler2D);
  EXPECT_EQ(sc->type.base, BaseType::SamplerCube);
  FragmentRun run(*p);
  run.uniforms[s2->offset] = 3.0f;
  run.uniforms[sc->offset] = 5.0f;
  const int v = find_varying(*p, "v")->offset;
  for (int l = 0; l < kLanes; ++l) {
    run.varyings[(v + 0) * kLanes + l] = l;
    run.varyings[(v + 1) * kLanes + l] = 2.0f;
    run.varyings[(v + 2) * kLanes + l] = 3.0f;
    run.varyings[(v + 3) * kLanes + l] = 4.0f;
  }
  RecordingTextures tex;
  run.run(*p, &tex);
  ASSERT_EQ(tex.calls.size(), 4u);
  EXPECT_EQ(tex.calls[0].unit, 3);
  EXPECT_EQ(tex.calls[0].kind, SamplerKind::Tex2D);
  EXPECT_EQ(tex.calls[0].mode, LodMode::Implicit);
  EXPECT_FALSE(tex.calls[0].has_lod);
  EXPECT_EQ(tex.calls[0].live, 0xFFFF);
  EXPECT_EQ(tex.calls[0].coords[0][9], 9.0f);
  EXPECT_EQ(tex.calls[0].coords[1][9], 2.0f);
  EXPECT_EQ(tex.calls[1].mode, LodMode::Bias);
  EXPECT_EQ(tex.calls[1].lod[4], 1.5f);
  EXPECT_EQ(tex.calls[2].coords[0][8], 8.0f / 4.0f);  // projected: s / q
  EXPECT_EQ(tex.calls[2].coords[1][8], 2.0f / 4.0f);
  EXPECT_EQ(tex.calls[3].unit, 5);
  EXPECT_EQ(tex.calls[3].kind, SamplerKind::Cube);
  EXPECT_EQ(tex.calls[3].coords[2][1], 3.0f);
  // The results come back per lane.
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(run.block.color[0][0][l], 3.0f * 3 + 5.0f);
    EXPECT_EQ(run.block.color[0][2][l], (l + 2.0f) * 2 + (l / 4.0f + 0.5f) + (l + 2.0f));
  }
}

TEST(FragmentBuiltins, ShadowAnd1D3DLookups) {
  auto p = link_ok("", "uniform sampler1D s1;\nuniform sampler3D s3;\nuniform sampler2DShadow sh;\nuniform sampler1DShadow sh1;\n"
                       "varying vec4 v;\n"
                       "void main() {\n"
                       "  gl_FragColor = texture1D(s1, v.x) + texture3DProj(s3, v) + shadow2D(sh, v.xyz) + shadow1DProj(sh1, v);\n}\n");
  ASSERT_TRUE(p);
  FragmentRun run(*p);
  const int v = find_varying(*p, "v")->offset;
  for (int l = 0; l < kLanes; ++l)
    for (int c = 0; c < 4; ++c) run.varyings[(v + c) * kLanes + l] = (c + 1) * 2.0f;
  RecordingTextures tex;
  run.run(*p, &tex);
  ASSERT_EQ(tex.calls.size(), 4u);
  EXPECT_EQ(tex.calls[0].kind, SamplerKind::Tex1D);
  EXPECT_EQ(tex.calls[0].coords[0][0], 2.0f);
  EXPECT_EQ(tex.calls[1].kind, SamplerKind::Tex3D);
  EXPECT_EQ(tex.calls[1].coords[2][0], 6.0f / 8.0f);
  EXPECT_EQ(tex.calls[2].kind, SamplerKind::Shadow2D);
  EXPECT_EQ(tex.calls[2].coords[2][0], 6.0f);  // the reference in r
  EXPECT_EQ(tex.calls[3].kind, SamplerKind::Shadow1D);
  EXPECT_EQ(tex.calls[3].coords[0][0], 2.0f / 8.0f);
  EXPECT_EQ(tex.calls[3].coords[2][0], 6.0f / 8.0f);
}

TEST(FragmentBuiltins, VertexShaderLookupsUseExplicitLod) {
  auto p = link_ok("uniform sampler2D s;\nattribute vec4 p;\n"
                   "void main() { gl_Position = texture2D(s, p.xy) + texture2DLod(s, p.xy, 2.0); }\n",
                   "");
  ASSERT_TRUE(p);
  VertexRun run(*p, 5);
  RecordingTextures tex;
  run.run(*p, &tex);
  ASSERT_EQ(tex.calls.size(), 2u);
  EXPECT_EQ(tex.calls[0].mode, LodMode::Explicit);
  EXPECT_EQ(tex.calls[0].lod[0], 0.0f);
  EXPECT_EQ(tex.calls[1].mode, LodMode::Explicit);
  EXPECT_EQ(tex.calls[1].lod[3], 2.0f);
  EXPECT_EQ(tex.calls[0].live, 0x001F);
}

TEST(FragmentBuiltins, LookupUnderDivergentControlFlowSeesItsLanes) {
  auto p = link_ok("", "uniform sampler2D s;\nvarying float v;\n"
                       "void main() { vec4 c = vec4(0.0); if (v > 0.5) c = texture2D(s, vec2(v)); gl_FragColor = c; }\n");
  ASSERT_TRUE(p);
  FragmentRun run(*p);
  run.set_varying(*p, "v", 0, [](int l) { return l >= 12 ? 1.0f : 0.0f; });
  RecordingTextures tex;
  run.run(*p, &tex);
  ASSERT_EQ(tex.calls.size(), 1u);
  EXPECT_EQ(tex.calls[0].live, 0xF000);
  EXPECT_EQ(run.block.color[0][2][0], 0.0f);
  EXPECT_EQ(run.block.color[0][2][13], 2.0f);
}

}  // namespace
}  // namespace pineda::shader::test

namespace pineda::shader::test {
namespace {

TEST(FragmentBuiltins, NoTextureAccessGivesZeros) {
  auto p = link_ok("", "uniform sampler2D s;\nvoid main() { gl_FragColor = texture2D(s, vec2(0.5)) + vec4(0.25); }\n");
  ASSERT_TRUE(p);
  FragmentRun run(*p);
  run.run(*p, nullptr);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(run.block.color[0][c][7], 0.25f);
}

TEST(FragmentBuiltins, NanAndHugeIndicesStayInsideArrays) {
  auto p = link_ok("", "uniform float t[3];\nvarying float v;\nvoid main() { float l[3]; l[0] = 1.0; l[1] = 2.0; l[2] = 3.0;\n"
                       "  int i = int(v); gl_FragColor = vec4(t[i], l[i], 0.0, 0.0); }\n");
  ASSERT_TRUE(p);
  FragmentRun run(*p);
  run.set_uniform(*p, "t[0]", {10.0f, 20.0f, 30.0f});
  run.set_varying(*p, "v", 0, [](int l) {
    const float values[4] = {std::numeric_limits<float>::quiet_NaN(), 1e30f, -1e30f, 1.0f};
    return values[l & 3];
  });
  run.run(*p);
  for (int l = 0; l < kLanes; ++l) {
    const float expected_t[4] = {10.0f, 30.0f, 10.0f, 20.0f};
    const float expected_l[4] = {1.0f, 3.0f, 1.0f, 2.0f};
    EXPECT_EQ(run.block.color[0][0][l], expected_t[l & 3]) << l;
    EXPECT_EQ(run.block.color[0][1][l], expected_l[l & 3]) << l;
  }
}

}  // namespace
}  // namespace pineda::shader::test
