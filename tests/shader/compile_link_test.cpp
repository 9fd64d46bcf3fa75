// Compile and link errors: glslang's info logs, ES against desktop rules, link checks.
#include "tests/shader/shader_test_util.h"

namespace pineda::shader::test {
namespace {

TEST(Compile, SyntaxErrorGivesGlslangLog) {
  CompileResult r = compile(Stage::Fragment, Language::Desktop, {"void main() { gl_FragColor = vec4(1.0) }\n"});
  EXPECT_EQ(r.shader, nullptr);
  EXPECT_NE(r.info_log.find("ERROR: 0:1:"), std::string::npos) << r.info_log;
  EXPECT_NE(r.info_log.find("syntax error"), std::string::npos) << r.info_log;
}

TEST(Compile, UndeclaredIdentifierNamed) {
  CompileResult r = compile(Stage::Vertex, Language::Desktop, {"void main() {\n gl_Position = nothing;\n}\n"});
  EXPECT_EQ(r.shader, nullptr);
  EXPECT_NE(r.info_log.find("ERROR: 0:2: 'nothing' : undeclared identifier"), std::string::npos) << r.info_log;
}

TEST(Compile, SourcesAreConcatenated) {
  CompileResult r = compile(Stage::Fragment, Language::Desktop, {"uniform vec4 c;\nvoid main() ", "{ gl_FragColor = c; }\n"});
  EXPECT_NE(r.shader, nullptr) << r.info_log;
}

TEST(Compile, EsFragmentShaderNeedsFloatPrecision) {
  const char* src = "varying vec4 v;\nvoid main() { gl_FragColor = v; }\n";
  CompileResult es = compile(Stage::Fragment, Language::Es100, {src});
  EXPECT_EQ(es.shader, nullptr);
  EXPECT_NE(es.info_log.find("precision"), std::string::npos) << es.info_log;
  CompileResult es_ok = compile(Stage::Fragment, Language::Es100, {std::string("precision mediump float;\n") + src});
  EXPECT_NE(es_ok.shader, nullptr) << es_ok.info_log;
  CompileResult desktop = compile(Stage::Fragment, Language::Desktop, {src});
  EXPECT_NE(desktop.shader, nullptr) << desktop.info_log;
  // The ES vertex stage has a default float precision.
  CompileResult vs = compile(Stage::Vertex, Language::Es100, {"attribute vec4 p;\nvoid main() { gl_Position = p; }\n"});
  EXPECT_NE(vs.shader, nullptr) << vs.info_log;
}

TEST(Compile, VersionsAcceptedPerLanguage) {
  const char* body = "void main() { gl_Position = vec4(0.0); }\n";
  EXPECT_NE(compile(Stage::Vertex, Language::Desktop, {std::string("#version 110\n") + body}).shader, nullptr);
  EXPECT_NE(compile(Stage::Vertex, Language::Desktop, {std::string("#version 120\n") + body}).shader, nullptr);
  EXPECT_NE(compile(Stage::Vertex, Language::Es100, {std::string("#version 100\n") + body}).shader, nullptr);
  CompileResult v130 = compile(Stage::Vertex, Language::Desktop, {std::string("#version 130\n") + body});
  EXPECT_EQ(v130.shader, nullptr);
  EXPECT_NE(v130.info_log.find("version 130"), std::string::npos) << v130.info_log;
  EXPECT_EQ(compile(Stage::Vertex, Language::Es100, {std::string("#version 120\n") + body}).shader, nullptr);
  // Desktop GL takes GLSL ES 1.00 too (GL_ARB_ES2_compatibility), but no later ES version.
  EXPECT_NE(compile(Stage::Vertex, Language::Desktop, {std::string("#version 100\n") + body}).shader, nullptr);
  EXPECT_EQ(compile(Stage::Vertex, Language::Desktop, {std::string("#version 300 es\n") + body}).shader, nullptr);
}

// GLSL 1.10 7.2: gl_FragColor or gl_FragData, not both; static assignments count, dead or not,
// through out parameters too; reading one while writing the other is allowed.
TEST(Compile, FragColorAndFragDataAreNotBothAssigned) {
  auto fails = [](Language language, const std::string& body) {
    const std::string src = (language == Language::Es100 ? "precision mediump float;\n" : "") + body;
    CompileResult r = compile(Stage::Fragment, language, {src});
    return r.shader == nullptr &&
           r.info_log.find("may assign to gl_FragColor or to gl_FragData, not to both") != std::string::npos;
  };
  for (Language language : {Language::Desktop, Language::Es100}) {
    EXPECT_TRUE(fails(language, "void main() {\n gl_FragColor = vec4(1.0);\n gl_FragData[0] = vec4(1.0);\n}\n"));
    EXPECT_TRUE(fails(language, "void main() {\n if (false) gl_FragData[0].x = 1.0;\n gl_FragColor = vec4(1.0);\n}\n"));
    EXPECT_TRUE(fails(language, "void set(out vec4 c) { c = vec4(1.0); }\n"
                                "void main() {\n set(gl_FragColor);\n gl_FragData[0] += vec4(1.0);\n}\n"));
    EXPECT_FALSE(fails(language, "void main() {\n gl_FragData[0] = vec4(1.0);\n gl_FragData[0].y = 0.5;\n}\n"));
    EXPECT_FALSE(fails(language, "void main() {\n gl_FragColor = vec4(1.0);\n gl_FragColor.y = 0.5;\n}\n"));
    EXPECT_FALSE(fails(language, "void main() {\n gl_FragData[0] = vec4(1.0);\n vec4 c = gl_FragColor;\n}\n"));
  }
}

// GLSL 1.10 4.1.7 and 5.8, which glslang 12 does not check: no sampler (nor a structure holding
// one) as an out or inout parameter or as a return type; no out or inout array parameter before
// GLSL 1.20.
TEST(Compile, SamplersAndArraysAreNoOutParameters) {
  auto error = [](Stage stage, const std::string& src) {
    CompileResult r = compile(stage, Language::Desktop, {src});
    return r.shader ? std::string("compiled") : r.info_log;
  };
  const std::string with_sampler = "struct S { float x; sampler2D t; };\nuniform S u;\n";
  const std::string main_fs = "void main() { gl_FragColor = vec4(1.0); }\n";
  EXPECT_NE(error(Stage::Fragment, with_sampler + "void f(out S s) {}\n" + main_fs)
                .find("ERROR: 0:3: 's' : a sampler or a structure holding one cannot be an out or inout parameter"),
            std::string::npos);
  EXPECT_NE(error(Stage::Fragment, with_sampler + "void f(inout S s) {}\n" + main_fs).find("cannot be an out or inout"),
            std::string::npos);
  EXPECT_NE(error(Stage::Fragment, with_sampler + "S f() { return u; }\n" + main_fs)
                .find("ERROR: 0:3: 'f' : a function cannot return a sampler or a structure holding one"),
            std::string::npos);
  EXPECT_EQ(error(Stage::Fragment, with_sampler + "float f(S s) { return s.x; }\n" + main_fs), "compiled");
  const std::string main_vs = "void main() { gl_Position = vec4(0.0); }\n";
  EXPECT_NE(error(Stage::Vertex, "#version 110\nvoid f(out float x[2]) {}\n" + main_vs)
                .find("ERROR: 0:2: 'x' : an array cannot be an out or inout parameter in GLSL 1.10"),
            std::string::npos);
  EXPECT_NE(error(Stage::Vertex, "void f(inout float x[2]) {}\n" + main_vs).find("in GLSL 1.10"), std::string::npos);
  EXPECT_EQ(error(Stage::Vertex, "#version 120\nvoid f(out float x[2]) { x[0] = 1.0; }\n" + main_vs), "compiled");
  EXPECT_EQ(error(Stage::Vertex, "#version 110\nfloat f(float x[2]) { return x[1]; }\n" + main_vs), "compiled");
}

TEST(Compile, DesktopBuiltinsAbsentInEs) {
  CompileResult es = compile(Stage::Vertex, Language::Es100, {"void main() { gl_Position = gl_Vertex; }\n"});
  EXPECT_EQ(es.shader, nullptr);
  EXPECT_NE(es.info_log.find("'gl_Vertex' : undeclared identifier"), std::string::npos) << es.info_log;
  EXPECT_NE(compile(Stage::Vertex, Language::Desktop, {"void main() { gl_Position = gl_Vertex; }\n"}).shader, nullptr);
}

TEST(Compile, Glsl120FeaturesNeedVersion120) {
  const char* src = "void main() { mat2x3 m = mat2x3(1.0); gl_FragColor = vec4(m[0], 1.0); }\n";
  EXPECT_EQ(compile(Stage::Fragment, Language::Desktop, {src}).shader, nullptr);
  EXPECT_NE(compile(Stage::Fragment, Language::Desktop, {std::string("#version 120\n") + src}).shader, nullptr);
}

TEST(Link, MissingMainIsALinkError) {
  auto vs = compile_ok(Stage::Vertex, "void main() { gl_Position = vec4(0.0); }\n");
  auto fs = compile_ok(Stage::Fragment, "vec4 helper() { return vec4(1.0); }\n");
  LinkResult r = link(vs.get(), fs.get(), {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_NE(r.info_log.find("Missing entry point"), std::string::npos) << r.info_log;
}

TEST(Link, VaryingTypeMismatch) {
  auto vs = compile_ok(Stage::Vertex, "varying vec3 v;\nvoid main() { v = vec3(1.0); gl_Position = vec4(0.0); }\n");
  auto fs = compile_ok(Stage::Fragment, "varying vec4 v;\nvoid main() { gl_FragColor = v; }\n");
  LinkResult r = link(vs.get(), fs.get(), {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_NE(r.info_log.find("Types must match"), std::string::npos) << r.info_log;
  EXPECT_NE(r.info_log.find("\" vec3 v\""), std::string::npos) << r.info_log;
}

TEST(Link, VaryingNotDeclaredByVertexShader) {
  auto vs = compile_ok(Stage::Vertex, "void main() { gl_Position = vec4(0.0); }\n");
  auto fs = compile_ok(Stage::Fragment, "varying vec4 v;\nvoid main() { gl_FragColor = v; }\n");
  LinkResult r = link(vs.get(), fs.get(), {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_NE(r.info_log.find("varying v not written by vertex shader"), std::string::npos) << r.info_log;
}

// As Mesa (piglit glsl-1.10 linker/varying-read-but-not-written): a varying the fragment
// shader reads must be written by the vertex shader, not only declared.
TEST(Link, DeclaredButUnwrittenVaryingIsALinkError) {
  auto vs = compile_ok(Stage::Vertex, "varying vec4 v;\nvoid main() { gl_Position = vec4(1.0); }\n");
  auto fs = compile_ok(Stage::Fragment, "varying vec4 v;\nvoid main() { gl_FragColor = v; }\n");
  LinkResult r = link(vs.get(), fs.get(), {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_NE(r.info_log.find("varying v not written by vertex shader"), std::string::npos) << r.info_log;
}

// A varying the vertex shader reads back without writing is still "written" as far as the
// linker knows; it holds 0.
TEST(Link, VaryingOnlyReadByTheVertexShaderIsZero) {
  auto p = link_ok("varying vec4 v;\nvoid main() { gl_Position = vec4(1.0) + v * 0.0; }\n",
                   "varying vec4 v;\nvoid main() { gl_FragColor = v; }\n");
  ASSERT_TRUE(p);
  VertexRun run(*p);
  run.run(*p);
  const Varying* v = find_varying(*p, "v");
  ASSERT_TRUE(v);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(run.out(kOutFirstVarying + v->offset + c, 3), 0.0f);
  EXPECT_EQ(run.out(kOutPosition + 3, 3), 1.0f);
}

TEST(Link, GlobalInitializedDifferentlyInTwoShadersOfAStageIsALinkError) {
  auto a = compile_ok(Stage::Vertex, "float g = 1.0;\nvoid helper() {}\n");
  auto b = compile_ok(Stage::Vertex, "float g = 2.0;\nvoid main() { gl_Position = vec4(g); }\n");
  LinkResult r = link({a.get(), b.get()}, {}, {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_NE(r.info_log.find("initializers for global variable `g' have differing values"), std::string::npos) << r.info_log;
  auto c = compile_ok(Stage::Vertex, "float g;\nvoid main() { gl_Position = vec4(g); }\n");
  EXPECT_NE(link({a.get(), c.get()}, {}, {}).program, nullptr);  // one initializer is fine
  auto same = compile_ok(Stage::Vertex, "float g = 1.0;\nvoid main() { gl_Position = vec4(g); }\n");
  EXPECT_NE(link({a.get(), same.get()}, {}, {}).program, nullptr);  // the same constant too
  auto u = compile_ok(Stage::Vertex, "uniform float k;\nfloat g = sin(k);\nvoid helper() {}\n");
  auto v = compile_ok(Stage::Vertex, "uniform float k;\nfloat g = sin(k);\nvoid main() { gl_Position = vec4(g); }\n");
  r = link({u.get(), v.get()}, {}, {});
  EXPECT_EQ(r.program, nullptr);  // not a constant: two initializers, even the same expression
  EXPECT_NE(r.info_log.find("global variable `g' has multiple initializers"), std::string::npos) << r.info_log;
}

// As Mesa: an error for desktop GLSL 1.10/1.20, allowed (undefined position) in GLSL ES 1.00.
TEST(Link, VertexShaderMustWriteGlPosition) {
  auto vs = compile_ok(Stage::Vertex, "void main() { gl_FrontColor = vec4(0.3); }\n");
  LinkResult r = link(vs.get(), nullptr, {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_NE(r.info_log.find("vertex shader does not write to `gl_Position'"), std::string::npos) << r.info_log;
  auto es = compile_ok(Stage::Vertex, "void main() {}\n", Language::Es100);
  EXPECT_NE(link(es.get(), nullptr, {}).program, nullptr);
}

TEST(Link, ClipVertexOutputsDefaultToThePosition) {
  auto written = link_ok("void main() { gl_Position = vec4(1.0, 2.0, 3.0, 4.0); gl_ClipVertex = vec4(5.0); }\n", "");
  auto unwritten = link_ok("void main() { gl_Position = vec4(1.0, 2.0, 3.0, 4.0); }\n", "");
  ASSERT_TRUE(written && unwritten);
  VertexRun a(*written), b(*unwritten);
  a.run(*written);
  b.run(*unwritten);
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(a.out(kOutClipVertex + c, 2), 5.0f);
    EXPECT_EQ(b.out(kOutClipVertex + c, 2), static_cast<float>(c + 1));
  }
}

TEST(Link, UniformTypeClashBetweenStages) {
  auto vs = compile_ok(Stage::Vertex, "uniform vec4 u;\nvoid main() { gl_Position = u; }\n");
  auto fs = compile_ok(Stage::Fragment, "uniform vec3 u;\nvoid main() { gl_FragColor = vec4(u, 1.0); }\n");
  LinkResult r = link(vs.get(), fs.get(), {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_NE(r.info_log.find("Types must match"), std::string::npos) << r.info_log;
  EXPECT_NE(r.info_log.find("\" vec3 u\""), std::string::npos) << r.info_log;
}

TEST(Link, TooManyVaryingFloats) {
  std::string decl, use;
  for (int i = 0; i < 17; ++i) {
    decl += "varying vec4 v" + std::to_string(i) + ";\n";
    use += " + v" + std::to_string(i);
  }
  auto vs = compile_ok(Stage::Vertex, decl + "void main() { gl_Position = vec4(0.0)" + use + "; }\n");
  auto fs = compile_ok(Stage::Fragment, decl + "void main() { gl_FragColor = vec4(0.0)" + use + "; }\n");
  ASSERT_TRUE(vs && fs);
  LinkResult r = link(vs.get(), fs.get(), {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_NE(r.info_log.find("too many varyings"), std::string::npos) << r.info_log;
}

TEST(Link, SharedUniformHasOneOffset) {
  auto p = link_ok("uniform vec4 u;\nvoid main() { gl_Position = u; }\n",
                   "uniform vec4 u;\nvoid main() { gl_FragColor = u * 2.0; }\n");
  ASSERT_TRUE(p);
  int count = 0;
  for (const Uniform& u : p->uniforms()) count += u.name == "u";
  EXPECT_EQ(count, 1);
  EXPECT_EQ(p->uniform_floats(), 4);
}

}  // namespace
}  // namespace pineda::shader::test

namespace pineda::shader::test {
namespace {

TEST(Compile, VertexLineNumbersWithVersion) {
  CompileResult r = compile(Stage::Vertex, Language::Desktop, {"#version 120\nuniform vec4 u;\nvoid main() { gl_Position = missing; }\n"});
  EXPECT_EQ(r.shader, nullptr);
  EXPECT_NE(r.info_log.find("ERROR: 0:3: 'missing' : undeclared identifier"), std::string::npos) << r.info_log;
}

TEST(Compile, FragmentShaderHasNoDesktopTextureLod) {
  CompileResult r = compile(Stage::Fragment, Language::Desktop,
                            {"uniform sampler2D s;\nvoid main() { gl_FragColor = texture2DLod(s, vec2(0.0), 1.0); }\n"});
  EXPECT_EQ(r.shader, nullptr);
}

}  // namespace
}  // namespace pineda::shader::test

namespace pineda::shader::test {
namespace {

TEST(Link, HugeLocalArrayIsALinkErrorNotACrash) {
  auto fs = compile_ok(Stage::Fragment, "varying float v;\nvoid main() { float a[10000000]; a[int(v)] = 1.0; gl_FragColor = vec4(a[2]); }\n");
  ASSERT_TRUE(fs);
  LinkResult r = link(nullptr, fs.get(), {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_NE(r.info_log.find("shader too large"), std::string::npos) << r.info_log;
}

TEST(Link, InliningExplosionIsALinkError) {
  std::string src = "varying float v;\nfloat f0(float x) { return x * 1.5 + v; }\n";
  for (int i = 1; i < 24; ++i)
    src += "float f" + std::to_string(i) + "(float x) { return f" + std::to_string(i - 1) + "(x) + f" +
           std::to_string(i - 1) + "(x + 1.0); }\n";
  src += "void main() { gl_FragColor = vec4(f23(v)); }\n";
  auto fs = compile_ok(Stage::Fragment, src);
  ASSERT_TRUE(fs);
  LinkResult r = link(nullptr, fs.get(), {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_NE(r.info_log.find("shader too large"), std::string::npos) << r.info_log;
}

TEST(Link, TooManyUniformComponents) {
  auto fs = compile_ok(Stage::Fragment, "uniform vec4 big[5000];\nuniform int i;\nvoid main() { gl_FragColor = big[i]; }\n");
  ASSERT_TRUE(fs);
  LinkResult r = link(nullptr, fs.get(), {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_NE(r.info_log.find("too many uniform components"), std::string::npos) << r.info_log;
}

TEST(Link, RecursionIsRejected) {
  CompileResult c = compile(Stage::Fragment, Language::Desktop,
                            {"float f(float x) { return x > 0.0 ? f(x - 1.0) : 0.0; }\nvoid main() { gl_FragColor = vec4(f(3.0)); }\n"});
  if (!c.shader) {
    SUCCEED() << "rejected at compile: " << c.info_log;
    return;
  }
  LinkResult r = link(nullptr, c.shader.get(), {});
  EXPECT_EQ(r.program, nullptr);
  EXPECT_FALSE(r.info_log.empty());
}

}  // namespace
}  // namespace pineda::shader::test
