// Helpers for the shader/ tests: compile + link from source, run a vertex batch or a
// fragment block, read lanes back.
#pragma once
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "shader/program.h"

namespace pineda::shader::test {

inline std::shared_ptr<const CompiledShader> compile_ok(Stage stage, const std::string& src,
                                                         Language lang = Language::Desktop) {
  CompileResult r = compile(stage, lang, {src});
  EXPECT_NE(r.shader, nullptr) << r.info_log << "\n" << src;
  return r.shader;
}

inline std::shared_ptr<const Program> link_ok(const std::string& vs, const std::string& fs,
                                              Language lang = Language::Desktop,
                                              const std::vector<AttributeBinding>& bindings = {}) {
  auto v = vs.empty() ? nullptr : compile_ok(Stage::Vertex, vs, lang);
  auto f = fs.empty() ? nullptr : compile_ok(Stage::Fragment, fs, lang);
  LinkResult r = link(v.get(), f.get(), bindings);
  EXPECT_NE(r.program, nullptr) << r.info_log;
  return r.program;
}

inline const Uniform* find_uniform(const Program& p, const std::string& name) {
  for (const Uniform& u : p.uniforms())
    if (u.name == name) return &u;
  return nullptr;
}
inline const Attribute* find_attribute(const Program& p, const std::string& name) {
  for (const Attribute& a : p.attributes())
    if (a.name == name) return &a;
  return nullptr;
}
inline const Varying* find_varying(const Program& p, const std::string& name) {
  for (const Varying& v : p.varyings())
    if (v.name == name) return &v;
  return nullptr;
}

// A fragment block run: varyings[v][lane] set by the test, 16 lanes live by default.
struct FragmentRun {
  std::vector<float> uniforms;
  std::vector<float> varyings;
  FragmentBlock block{};
  explicit FragmentRun(const Program& p) : uniforms(p.uniform_floats() + 1, 0.0f), varyings((p.varying_floats() + 1) * kLanes, 0.0f) {
    block.live = 0xFFFF;
    block.front_facing = 0xFFFF;
    for (int l = 0; l < kLanes; ++l) {
      block.frag_coord[0][l] = static_cast<float>((l & 1) + 2 * ((l >> 2) & 1)) + 0.5f;
      block.frag_coord[1][l] = static_cast<float>(((l >> 1) & 1) + 2 * (l >> 3)) + 0.5f;
      block.frag_coord[2][l] = 0.5f;
      block.frag_coord[3][l] = 1.0f;
    }
  }
  void set_uniform(const Program& p, const std::string& name, std::vector<float> values) {
    const Uniform* u = find_uniform(p, name);
    ASSERT_NE(u, nullptr) << name;
    for (size_t i = 0; i < values.size(); ++i) uniforms[u->offset + i] = values[i];
  }
  void set_varying(const Program& p, const std::string& name, int component, float (*f)(int lane)) {
    const Varying* v = find_varying(p, name);
    ASSERT_NE(v, nullptr) << name;
    for (int l = 0; l < kLanes; ++l) varyings[(v->offset + component) * kLanes + l] = f(l);
  }
  void run(const Program& p, const TextureAccess* textures = nullptr) {
    block.varyings = varyings.data();
    p.run_fragments(uniforms.data(), textures, block);
  }
};

struct VertexRun {
  std::vector<float> uniforms;
  std::vector<float> inputs;
  std::vector<float> outputs;
  VertexBatch batch;
  explicit VertexRun(const Program& p, int count = kLanes)
      : uniforms(p.uniform_floats() + 1, 0.0f), inputs((p.input_slots() + 1) * 4 * kLanes, 0.0f),
        outputs((kOutFirstVarying + p.varying_floats()) * kLanes, -99.0f) {
    batch.count = count;
  }
  void set_uniform(const Program& p, const std::string& name, std::vector<float> values) {
    const Uniform* u = find_uniform(p, name);
    ASSERT_NE(u, nullptr) << name;
    for (size_t i = 0; i < values.size(); ++i) uniforms[u->offset + i] = values[i];
  }
  void set_input(const Program& p, const std::string& name, int component, float (*f)(int lane)) {
    const Attribute* a = find_attribute(p, name);
    ASSERT_NE(a, nullptr) << name;
    for (int l = 0; l < kLanes; ++l) inputs[(a->input_slot * 4 + component) * kLanes + l] = f(l);
  }
  float out(int index, int lane) const { return outputs[index * kLanes + lane]; }
  void run(const Program& p, const TextureAccess* textures = nullptr) {
    batch.inputs = inputs.data();
    batch.outputs = outputs.data();
    p.run_vertices(uniforms.data(), textures, batch);
  }
};

}  // namespace pineda::shader::test

namespace pineda::shader::test {

// Runs a desktop fragment shader over 16 lanes with varyings `a` and `b` (vec4 each, lane
// values from the given functions) and returns gl_FragColor[component][lane].
// How many instructions of IR dump `dump` are the operation `op`.
inline int count_ops(const std::string& dump, const std::string& op) {
  std::istringstream in(dump);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    auto eq = line.find(" = ");
    std::string rest = eq == std::string::npos ? line.substr(line.find(':') + 1) : line.substr(eq + 3);
    rest.erase(0, rest.find_first_not_of(' '));
    if (rest.compare(0, op.size() + 1, op + " ") == 0 || rest == op) ++n;
  }
  return n;
}

struct ExprResult {
  float c[4][kLanes];
  LaneMask live;
};
using LaneFn = float (*)(int lane, int component);
inline ExprResult run_fragment(const std::string& body, LaneFn a, LaneFn b = nullptr,
                               const std::string& decls = "", Language lang = Language::Desktop) {
  std::string version, rest = decls;
  if (rest.compare(0, 8, "#version") == 0) {
    version = rest.substr(0, rest.find('\n') + 1);
    rest = rest.substr(version.size());
  }
  std::string src = version + (lang == Language::Es100 ? std::string("precision highp float;\n") : std::string()) +
                    "varying vec4 a;\nvarying vec4 b;\n" + rest + "\nvoid main() {\n" + body + "\n}\n";
  ExprResult r{};
  auto p = link_ok("", src, lang);
  if (!p) return r;
  FragmentRun run(*p);
  const Varying* va = find_varying(*p, "a");
  const Varying* vb = find_varying(*p, "b");
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < kLanes; ++l) {
      if (va) run.varyings[(va->offset + c) * kLanes + l] = a(l, c);
      if (vb && b) run.varyings[(vb->offset + c) * kLanes + l] = b(l, c);
    }
  run.run(*p);
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < kLanes; ++l) r.c[c][l] = run.block.color[0][c][l];
  r.live = run.block.live;
  return r;
}

}  // namespace pineda::shader::test
