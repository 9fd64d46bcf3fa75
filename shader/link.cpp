// link(): parse both stages again, link with glslang's TProgram, lower to the IR (fragment
// stage first, so that the vertex stage knows which varyings are read), assign attribute
// locations, optimize.
#include <cstdio>
#include <cstdlib>

#include <glslang/MachineIndependent/localintermediate.h>

#include "shader/es_invariance.h"
#include "shader/front_end.h"
#include "shader/global_initializers.h"
#include "shader/interface.h"
#include "shader/linked_program.h"
#include "shader/lower.h"
#include "shader/optimize.h"

namespace pineda::shader {

namespace {

// A bound on the uniform store (64 KB), far above what GL's limits promise (1024 components
// per stage): large arrays that drivers commonly accept link, absurd ones do not.
constexpr int kMaxUserUniformFloats = 16384;
// Registers one invocation may use (64 bytes each).
constexpr int kMaxRunRegisters = 1 << 14;

Type reported_type(const VarType& t) {
  Type r;
  r.base = t.base;
  r.columns = static_cast<uint8_t>(t.cols);
  r.rows = static_cast<uint8_t>(t.rows);
  return r;
}

// `initial` is the whole variable's initializer (or null); `base` its first float.
void add_uniform_leaves(const std::string& name, const VarType& t, int offset, bool builtin,
                        const std::vector<float>* initial, int base, std::vector<Uniform>& out) {
  if (t.is_struct()) {
    if (t.array) {
      const VarType e = t.element();
      for (int i = 0; i < t.array; ++i)
        add_uniform_leaves(name + "[" + std::to_string(i) + "]", e, offset + i * e.size(), builtin, initial, base, out);
      return;
    }
    int off = offset;
    for (const auto& [member, mt] : t.members) {
      add_uniform_leaves(name + "." + member, mt, off, builtin, initial, base, out);
      off += mt.size();
    }
    return;
  }
  Uniform u;
  u.name = t.array ? name + "[0]" : name;
  u.type = reported_type(t);
  u.array_size = t.array ? t.array : 1;
  u.offset = offset;
  u.stride = t.element_size();
  u.builtin = builtin;
  if (initial)
    u.initial.assign(initial->begin() + (offset - base), initial->begin() + (offset - base) + t.size());
  out.push_back(u);
}

// Generic attributes get glBindAttribLocation's location, or the lowest free ones.
bool assign_locations(const Interface& iface, const std::vector<AttributeBinding>& bindings,
                      std::vector<Attribute>& out, std::string& log) {
  bool used[kMaxVertexAttribs] = {};
  for (const AttributeVar& a : iface.attributes)
    if (a.builtin == BuiltinAttribute::Vertex) used[0] = true;  // gl_Vertex is generic attribute 0
  std::vector<int> location(iface.attributes.size(), -1);
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t i = 0; i < iface.attributes.size(); ++i) {
      const AttributeVar& a = iface.attributes[i];
      if (a.builtin != BuiltinAttribute::None) continue;
      const int slots = a.type.cols * (a.type.array ? a.type.array : 1);
      int bound = -1;
      for (const AttributeBinding& b : bindings)
        if (b.name == a.name) bound = b.location;
      if (pass == 0) {
        if (bound < 0) continue;
        if (bound + slots > kMaxVertexAttribs) {
          log += "error: attribute `" + a.name + "' bound to location " + std::to_string(bound) +
                 " does not fit below GL_MAX_VERTEX_ATTRIBS\n";
          return false;
        }
        location[i] = bound;
        for (int s = 0; s < slots; ++s) used[bound + s] = true;
      } else {
        if (bound >= 0) continue;
        int found = -1;
        for (int l = 0; l + slots <= kMaxVertexAttribs && found < 0; ++l) {
          bool free = true;
          for (int s = 0; s < slots; ++s) free = free && !used[l + s];
          if (free) found = l;
        }
        if (found < 0) {
          log += "error: too many vertex shader inputs (attribute `" + a.name + "' does not fit)\n";
          return false;
        }
        location[i] = found;
        for (int s = 0; s < slots; ++s) used[found + s] = true;
      }
    }
  }
  for (size_t i = 0; i < iface.attributes.size(); ++i) {
    const AttributeVar& a = iface.attributes[i];
    Attribute r;
    r.name = a.name;
    r.type = reported_type(a.type);
    r.array_size = a.type.array ? a.type.array : 1;
    r.location = location[i];
    r.builtin = a.builtin;
    r.input_slot = a.first_slot;
    out.push_back(r);
  }
  return true;
}

// glslang's part under its lock: parse, link, lower. Its objects die before the lock is
// released; the rest of link() runs unlocked.
bool parse_link_lower(const std::vector<const CompiledShader*>& vertex,
                      const std::vector<const CompiledShader*>& fragment, Interface& iface, LinkedProgram& out,
                      std::string& info_log) {
  std::lock_guard<std::mutex> hold(front_end::glslang_lock());
  std::string log;
  std::vector<std::unique_ptr<glslang::TShader>> units;  // declared first: they outlive the TProgram
  glslang::TProgram program;
  for (const auto* stage : {&vertex, &fragment})
    for (const CompiledShader* s : *stage) {
      std::unique_ptr<glslang::TShader> unit = front_end::parse(*s, log);
      if (!unit) {
        info_log = std::string("error: ") + (stage == &vertex ? "vertex" : "fragment") + " shader does not compile\n" + log;
        return false;
      }
      program.addShader(unit.get());
      units.push_back(std::move(unit));
    }
  for (const auto* stage : {&vertex, &fragment}) {
    std::vector<const glslang::TIntermediate*> trees;
    for (const auto& unit : units)
      if ((unit->getStage() == EShLangVertex) == (stage == &vertex)) trees.push_back(unit->getIntermediate());
    if (trees.size() > 1 && !global_initializers_unique(trees, info_log)) return false;
  }
  // A desktop context takes GLSL ES 1.00 shaders too, but not mixed with desktop GLSL (as Mesa).
  const auto is_es = [](const std::unique_ptr<glslang::TShader>& unit) {
    return unit->getIntermediate()->getProfile() == EEsProfile;
  };
  const bool es = !units.empty() && is_es(units.front());
  for (const auto& unit : units)
    if (is_es(unit) != es) {
      info_log = "error: GLSL ES 1.00 and desktop GLSL shaders cannot be linked together\n";
      return false;
    }
  const bool linked = program.link(EShMsgDefault);
  info_log = program.getInfoLog();
  if (!linked) return false;
  const bool vs = !vertex.empty(), fs = !fragment.empty();
  if (es && !es_invariance_ok(vs ? program.getIntermediate(EShLangVertex) : nullptr,
                              fs ? program.getIntermediate(EShLangFragment) : nullptr, info_log))
    return false;
  iface.has_vertex_shader = vs;
  iface.has_fragment_shader = fs;
  std::string error;
  if (fs) {
    out.fragment_.emplace();
    if (!lower_stage(Stage::Fragment, *program.getIntermediate(EShLangFragment), iface, out.fragment_->code, error)) {
      info_log += error;
      return false;
    }
  }
  if (vs) {
    out.vertex_.emplace();
    if (!lower_stage(Stage::Vertex, *program.getIntermediate(EShLangVertex), iface, out.vertex_->code, error)) {
      info_log += error;
      return false;
    }
  }
  return true;
}

}  // namespace

LinkResult link(const CompiledShader* vertex, const CompiledShader* fragment,
                const std::vector<AttributeBinding>& bindings) {
  std::vector<const CompiledShader*> vs, fs;
  if (vertex) vs.push_back(vertex);
  if (fragment) fs.push_back(fragment);
  return link(vs, fs, bindings);
}

LinkResult link(const std::vector<const CompiledShader*>& vertex, const std::vector<const CompiledShader*>& fragment,
                const std::vector<AttributeBinding>& bindings) {
  LinkResult result;
  if (vertex.empty() && fragment.empty()) {
    result.info_log = "error: no shaders attached\n";
    return result;
  }
  for (const CompiledShader* s : vertex)
    if (!s || s->stage != Stage::Vertex) return result.info_log = "error: shader of the wrong stage\n", result;
  for (const CompiledShader* s : fragment)
    if (!s || s->stage != Stage::Fragment) return result.info_log = "error: shader of the wrong stage\n", result;
  Interface iface;
  auto linked_program = std::make_shared<LinkedProgram>();
  if (!parse_link_lower(vertex, fragment, iface, *linked_program, result.info_log)) return result;
  if (iface.varying_floats > kMaxVaryingFloats) {
    result.info_log += "error: too many varyings (" + std::to_string(iface.varying_floats) + " floats, at most " +
                       std::to_string(kMaxVaryingFloats) + ")\n";
    return result;
  }
  int user_uniform_floats = 0;
  for (const UniformVar& u : iface.uniforms)
    if (!u.builtin) user_uniform_floats += u.type.size();
  if (user_uniform_floats > kMaxUserUniformFloats) {
    result.info_log += "error: too many uniform components (" + std::to_string(user_uniform_floats) +
                       ", at most " + std::to_string(kMaxUserUniformFloats) + ")\n";
    return result;
  }
  if (!assign_locations(iface, bindings, linked_program->attributes_, result.info_log)) return result;
  if (!iface.has_vertex_shader)
    for (VaryingVar& v : iface.varyings)
      if (v.name == "gl_Color" || v.name == "gl_SecondaryColor") {
        v.back_offset = iface.varying_floats;
        iface.varying_floats += 4;
      }
  for (const UniformVar& u : iface.uniforms)
    add_uniform_leaves(u.name, u.type, u.offset, u.builtin, u.initial.empty() ? nullptr : &u.initial, u.offset,
                       linked_program->uniforms_);
  for (const VaryingVar& v : iface.varyings) {
    const int es = v.type.element_size();
    if (v.type.array) {
      for (int i = 0; i < v.type.array; ++i)
        linked_program->varyings_.push_back(Varying{v.name + "[" + std::to_string(i) + "]", v.offset + i * es, es, -1});
    } else {
      linked_program->varyings_.push_back(Varying{v.name, v.offset, es, v.back_offset});
    }
  }
  linked_program->input_slots_ = iface.input_slots;
  linked_program->varying_floats_ = iface.varying_floats;
  linked_program->uniform_floats_ = iface.uniform_floats;
  linked_program->writes_point_size_ = iface.writes_point_size;
  linked_program->writes_depth_ = iface.writes_depth;
  linked_program->uses_discard_ = iface.uses_discard;
  linked_program->draw_buffers_ = iface.draw_buffers;
  linked_program->broadcasts_color_ = iface.broadcasts_color;
  linked_program->reads_ = iface.reads;
  linked_program->reads_point_coord_ = iface.reads.count("gl_PointCoord") != 0;
  for (auto* stage : {&linked_program->vertex_, &linked_program->fragment_})
    if (*stage) {
      optimize((*stage)->code);
      if ((*stage)->code.registers > kMaxRunRegisters) {
        result.info_log += "error: shader too large (" + std::to_string((*stage)->code.registers) +
                           " registers after optimization)\n";
        return result;
      }
      (*stage)->prepare();
    }
  if (linked_program->fragment_)
    for (const ir::Inst& in : linked_program->fragment_->code.insts)
      if (in.op == ir::Op::LoadFragCoord && in.i0 >= 0 && in.i0 < 4) linked_program->frag_coord_components_ |= 1u << in.i0;
  const char* dump_env = std::getenv("PINEDA_DUMP_IR");
  if (dump_env && dump_env[0] == '1') std::fprintf(stderr, "%s", dump_ir(*linked_program).c_str());
  result.program = std::move(linked_program);
  return result;
}

}  // namespace pineda::shader
