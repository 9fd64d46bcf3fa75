// What link() reports: uniforms (names, types, arrays, offsets, built-ins), attributes
// (locations from bindings, built-ins), varyings (built-in colours with their back pair).
#include "tests/shader/shader_test_util.h"

namespace pineda::shader::test {
namespace {

TEST(Reflection, UniformArraysStructsAndTypes) {
  auto p = link_ok("", "#version 120\n"
                       "struct Light { vec3 color; float k[2]; };\n"
                       "uniform Light lights[2];\n"
                       "uniform vec4 arr[3];\n"
                       "uniform mat3 m;\n"
                       "uniform mat2x4 rect;\n"
                       "uniform ivec2 iv;\n"
                       "uniform bool flag;\n"
                       "uniform float unused;\n"
                       "void main() {\n"
                       "  gl_FragColor = vec4(lights[1].color * lights[0].k[1], 1.0) + arr[2] + vec4(m[1], 0.0)\n"
                       "      + rect[1] + vec4(vec2(iv), float(flag), 0.0);\n"
                       "}\n");
  ASSERT_TRUE(p);
  EXPECT_EQ(find_uniform(*p, "unused"), nullptr);
  const Uniform* arr = find_uniform(*p, "arr[0]");
  ASSERT_TRUE(arr);
  EXPECT_EQ(arr->array_size, 3);
  EXPECT_EQ(arr->stride, 4);
  EXPECT_EQ(arr->type.rows, 4);
  EXPECT_EQ(arr->type.columns, 1);
  const Uniform* c0 = find_uniform(*p, "lights[0].color");
  const Uniform* c1 = find_uniform(*p, "lights[1].color");
  const Uniform* k0 = find_uniform(*p, "lights[0].k[0]");
  const Uniform* k1 = find_uniform(*p, "lights[1].k[0]");
  ASSERT_TRUE(c0 && c1 && k0 && k1);
  EXPECT_EQ(c0->type.rows, 3);
  EXPECT_EQ(k0->array_size, 2);
  EXPECT_EQ(k0->stride, 1);
  EXPECT_EQ(c1->offset - c0->offset, 5);  // vec3 + float[2]
  EXPECT_EQ(k0->offset, c0->offset + 3);
  EXPECT_EQ(k1->offset, c1->offset + 3);
  const Uniform* m = find_uniform(*p, "m");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->type.columns, 3);
  EXPECT_EQ(m->type.rows, 3);
  EXPECT_EQ(m->type.components(), 9);
  const Uniform* rect = find_uniform(*p, "rect");
  ASSERT_TRUE(rect);
  EXPECT_EQ(rect->type.columns, 2);
  EXPECT_EQ(rect->type.rows, 4);
  EXPECT_EQ(find_uniform(*p, "iv")->type.base, BaseType::Int);
  EXPECT_EQ(find_uniform(*p, "iv")->type.rows, 2);
  EXPECT_EQ(find_uniform(*p, "flag")->type.base, BaseType::Bool);
  for (const Uniform& u : p->uniforms()) EXPECT_FALSE(u.builtin) << u.name;
  // Offsets do not overlap and fit the store.
  int total = 0;
  for (const Uniform& u : p->uniforms()) total += u.type.components() * u.array_size;
  EXPECT_EQ(total, p->uniform_floats());

  // The values land where the offsets say.
  FragmentRun run(*p);
  run.uniforms[c1->offset + 0] = 2.0f;
  run.uniforms[k0->offset + 1] = 3.0f;
  run.uniforms[arr->offset + 2 * 4 + 0] = 100.0f;
  run.uniforms[m->offset + 3] = 1000.0f;
  run.uniforms[rect->offset + 4] = 10000.0f;
  run.uniforms[find_uniform(*p, "iv")->offset] = 7.0f;
  run.run(*p);
  EXPECT_EQ(run.block.color[0][0][5], 2.0f * 3.0f + 100.0f + 1000.0f + 10000.0f + 7.0f);
}

TEST(Reflection, BuiltinUniformsHaveGlslNames) {
  auto p = link_ok("void main() {\n"
                   "  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex + gl_LightSource[1].diffuse\n"
                   "      + gl_TextureMatrix[2][0] + vec4(gl_NormalMatrix[0], gl_Point.size)\n"
                   "      + gl_FrontMaterial.emission + vec4(gl_DepthRange.far);\n"
                   "}\n",
                   "");
  ASSERT_TRUE(p);
  const Uniform* mvp = find_uniform(*p, "gl_ModelViewProjectionMatrix");
  ASSERT_TRUE(mvp);
  EXPECT_TRUE(mvp->builtin);
  EXPECT_EQ(mvp->type.columns, 4);
  const Uniform* l0 = find_uniform(*p, "gl_LightSource[0].diffuse");
  const Uniform* l1 = find_uniform(*p, "gl_LightSource[1].diffuse");
  const Uniform* l7 = find_uniform(*p, "gl_LightSource[7].spotCutoff");
  ASSERT_TRUE(l0 && l1 && l7);
  EXPECT_TRUE(l1->builtin);
  EXPECT_EQ(find_uniform(*p, "gl_LightSource[8].diffuse"), nullptr);  // gl_MaxLights is 8
  const Uniform* tm = find_uniform(*p, "gl_TextureMatrix[0]");
  ASSERT_TRUE(tm);
  EXPECT_EQ(tm->array_size, 8);
  EXPECT_EQ(tm->stride, 16);
  ASSERT_TRUE(find_uniform(*p, "gl_NormalMatrix"));
  EXPECT_EQ(find_uniform(*p, "gl_NormalMatrix")->type.columns, 3);
  ASSERT_TRUE(find_uniform(*p, "gl_Point.size"));
  ASSERT_TRUE(find_uniform(*p, "gl_FrontMaterial.emission"));
  ASSERT_TRUE(find_uniform(*p, "gl_DepthRange.far"));
  EXPECT_EQ(find_uniform(*p, "gl_DepthRange.far")->offset, find_uniform(*p, "gl_DepthRange.near")->offset + 1);

  VertexRun run(*p);
  run.uniforms[l1->offset + 2] = 5.0f;
  run.uniforms[tm->offset + 2 * 16 + 2] = 7.0f;
  run.uniforms[find_uniform(*p, "gl_DepthRange.far")->offset] = 0.25f;
  run.run(*p);
  EXPECT_EQ(run.out(kOutPosition + 2, 0), 5.0f + 7.0f + 0.25f);
}

TEST(Reflection, DynamicallyIndexedBuiltinArray) {
  auto p = link_ok("uniform int n;\nvoid main() { gl_Position = gl_LightSource[n].position + gl_ClipPlane[n]; }\n", "");
  ASSERT_TRUE(p);
  const Uniform* l3 = find_uniform(*p, "gl_LightSource[3].position");
  const Uniform* cp = find_uniform(*p, "gl_ClipPlane[0]");
  ASSERT_TRUE(l3 && cp);
  EXPECT_EQ(cp->array_size, 6);
  VertexRun run(*p);
  run.set_uniform(*p, "n", {3.0f});
  run.uniforms[l3->offset + 1] = 4.0f;
  run.uniforms[cp->offset + 3 * 4 + 1] = 0.5f;
  run.run(*p);
  EXPECT_EQ(run.out(kOutPosition + 1, 9), 4.5f);
}

TEST(Reflection, AttributeLocationsFromBindingsAndLinker) {
  auto p = link_ok("attribute vec4 a;\nattribute mat4 m;\nattribute vec2 b;\nattribute float unused;\n"
                   "void main() { gl_Position = m * a + vec4(b, 0.0, 0.0); }\n",
                   "", Language::Desktop, {{"b", 0}, {"m", 2}, {"nonexistent", 9}});
  ASSERT_TRUE(p);
  EXPECT_EQ(find_attribute(*p, "unused"), nullptr);
  const Attribute* a = find_attribute(*p, "a");
  const Attribute* m = find_attribute(*p, "m");
  const Attribute* b = find_attribute(*p, "b");
  ASSERT_TRUE(a && m && b);
  EXPECT_EQ(b->location, 0);
  EXPECT_EQ(m->location, 2);
  EXPECT_EQ(a->location, 1);  // the lowest free location
  EXPECT_EQ(m->type.columns, 4);
  EXPECT_EQ(m->builtin, BuiltinAttribute::None);
  EXPECT_EQ(p->input_slots(), 1 + 4 + 1);
  // input slots are distinct, matrices take one slot per column
  EXPECT_NE(a->input_slot, b->input_slot);
  EXPECT_TRUE(m->input_slot + 4 <= p->input_slots());
}

TEST(Reflection, MatrixAttributeNeedsConsecutiveLocations) {
  auto p = link_ok("attribute vec4 a;\nattribute mat3 m;\nvoid main() { gl_Position = vec4(m * a.xyz, 1.0); }\n",
                   "", Language::Desktop, {{"a", 1}});
  ASSERT_TRUE(p);
  EXPECT_EQ(find_attribute(*p, "m")->location, 2);
}

TEST(Reflection, AttributeBindingPastTheLimitFails) {
  auto vs = compile_ok(Stage::Vertex, "attribute mat4 m;\nvoid main() { gl_Position = m[0]; }\n");
  LinkResult r = link(vs.get(), nullptr, {{"m", 14}});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_NE(r.info_log.find("m"), std::string::npos);
}

TEST(Reflection, BuiltinAttributes) {
  auto p = link_ok("void main() { gl_Position = gl_Vertex + vec4(gl_Normal, gl_FogCoord) + gl_Color + gl_MultiTexCoord5; }\n", "");
  ASSERT_TRUE(p);
  const Attribute* v = find_attribute(*p, "gl_Vertex");
  ASSERT_TRUE(v);
  EXPECT_EQ(v->builtin, BuiltinAttribute::Vertex);
  EXPECT_EQ(v->location, -1);
  EXPECT_EQ(find_attribute(*p, "gl_Normal")->builtin, BuiltinAttribute::Normal);
  EXPECT_EQ(find_attribute(*p, "gl_FogCoord")->builtin, BuiltinAttribute::FogCoord);
  EXPECT_EQ(find_attribute(*p, "gl_Color")->builtin, BuiltinAttribute::Color);
  EXPECT_EQ(static_cast<int>(find_attribute(*p, "gl_MultiTexCoord5")->builtin),
            static_cast<int>(BuiltinAttribute::MultiTexCoord0) + 5);
  VertexRun run(*p);
  run.set_input(*p, "gl_Vertex", 0, [](int l) { return static_cast<float>(l); });
  run.set_input(*p, "gl_MultiTexCoord5", 0, [](int) { return 100.0f; });
  run.set_input(*p, "gl_FogCoord", 0, [](int) { return 0.5f; });
  run.run(*p);
  EXPECT_EQ(run.out(kOutPosition + 0, 6), 106.0f);
  EXPECT_EQ(run.out(kOutPosition + 3, 6), 0.5f);
}

TEST(Reflection, GenericAttributesAvoidLocationZeroWhenGlVertexIsUsed) {
  auto p = link_ok("attribute vec4 extra;\nvoid main() { gl_Position = gl_Vertex + extra; }\n", "");
  ASSERT_TRUE(p);
  EXPECT_EQ(find_attribute(*p, "extra")->location, 1);
}

}  // namespace
}  // namespace pineda::shader::test
