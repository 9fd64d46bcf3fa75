// The first end-to-end path: compile, link, reflect and run a vertex and a fragment shader
// that share uniforms and pass a varying.
#include "tests/shader/shader_test_util.h"

namespace pineda::shader::test {
namespace {

const char* kVs = R"(
uniform mat4 mvp;
uniform float scale;
attribute vec4 position;
attribute vec2 uv;
varying vec2 v_uv;
void main() {
  v_uv = uv * scale;
  gl_Position = mvp * position;
}
)";
const char* kFs = R"(
uniform vec4 tint;
varying vec2 v_uv;
void main() {
  gl_FragColor = vec4(v_uv, 0.25, 1.0) * tint;
}
)";

TEST(VerticalSlice, ReflectsUniformsAttributesVaryings) {
  auto p = link_ok(kVs, kFs);
  ASSERT_TRUE(p);
  const Uniform* mvp = find_uniform(*p, "mvp");
  ASSERT_TRUE(mvp);
  EXPECT_EQ(mvp->type.base, BaseType::Float);
  EXPECT_EQ(mvp->type.columns, 4);
  EXPECT_EQ(mvp->type.rows, 4);
  EXPECT_EQ(mvp->array_size, 1);
  EXPECT_FALSE(mvp->builtin);
  ASSERT_TRUE(find_uniform(*p, "scale"));
  ASSERT_TRUE(find_uniform(*p, "tint"));
  EXPECT_EQ(p->uniform_floats(), 16 + 1 + 4);
  const Attribute* pos = find_attribute(*p, "position");
  const Attribute* uv = find_attribute(*p, "uv");
  ASSERT_TRUE(pos && uv);
  EXPECT_EQ(pos->type.rows, 4);
  EXPECT_EQ(uv->type.rows, 2);
  EXPECT_NE(pos->location, uv->location);
  EXPECT_GE(pos->location, 0);
  EXPECT_GE(uv->location, 0);
  EXPECT_EQ(p->input_slots(), 2);
  ASSERT_EQ(p->varyings().size(), 1u);
  EXPECT_EQ(p->varyings()[0].name, "v_uv");
  EXPECT_EQ(p->varyings()[0].components, 2);
  EXPECT_EQ(p->varying_floats(), 2);
  EXPECT_EQ(p->draw_buffers_written(), 1);
  EXPECT_TRUE(p->broadcasts_color());
  EXPECT_FALSE(p->uses_discard());
  EXPECT_FALSE(p->writes_depth());
  EXPECT_FALSE(p->writes_point_size());
}

TEST(VerticalSlice, RunsVertexBatch) {
  auto p = link_ok(kVs, kFs);
  ASSERT_TRUE(p);
  VertexRun run(*p);
  // mvp: scale x by 2, translate y by 1 (column-major).
  run.set_uniform(*p, "mvp", {2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 1});
  run.set_uniform(*p, "scale", {0.5f});
  run.set_input(*p, "position", 0, [](int l) { return static_cast<float>(l); });
  run.set_input(*p, "position", 1, [](int l) { return 10.0f + l; });
  run.set_input(*p, "position", 2, [](int) { return 3.0f; });
  run.set_input(*p, "position", 3, [](int) { return 1.0f; });
  run.set_input(*p, "uv", 0, [](int l) { return 2.0f * l; });
  run.set_input(*p, "uv", 1, [](int) { return 8.0f; });
  run.run(*p);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(run.out(kOutPosition + 0, l), 2.0f * l);
    EXPECT_EQ(run.out(kOutPosition + 1, l), 11.0f + l);
    EXPECT_EQ(run.out(kOutPosition + 2, l), 3.0f);
    EXPECT_EQ(run.out(kOutPosition + 3, l), 1.0f);
    EXPECT_EQ(run.out(kOutPointSize, l), 0.0f);
    const Varying* v = find_varying(*p, "v_uv");
    EXPECT_EQ(run.out(kOutFirstVarying + v->offset, l), static_cast<float>(l));
    EXPECT_EQ(run.out(kOutFirstVarying + v->offset + 1, l), 4.0f);
  }
}

TEST(VerticalSlice, RunsFragmentBlock) {
  auto p = link_ok(kVs, kFs);
  ASSERT_TRUE(p);
  FragmentRun run(*p);
  run.set_uniform(*p, "tint", {1.0f, 0.5f, 2.0f, 1.0f});
  run.set_varying(*p, "v_uv", 0, [](int l) { return l / 16.0f; });
  run.set_varying(*p, "v_uv", 1, [](int) { return 0.5f; });
  run.block.live = 0x0FF0;
  run.run(*p);
  EXPECT_EQ(run.block.live, 0x0FF0);
  for (int l = 0; l < kLanes; ++l) {
    if (!(0x0FF0 >> l & 1)) continue;
    // gl_FragColor is colour 0 alone, which the caller reads for every draw buffer.
    EXPECT_EQ(run.block.color[0][0][l], l / 16.0f);
    EXPECT_EQ(run.block.color[0][1][l], 0.25f);
    EXPECT_EQ(run.block.color[0][2][l], 0.5f);
    EXPECT_EQ(run.block.color[0][3][l], 1.0f);
  }
}

}  // namespace
}  // namespace pineda::shader::test
