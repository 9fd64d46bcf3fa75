#include "state/programs/program_link.h"

#include <algorithm>

#include "state/context.h"
#include "state/programs/sampler_units.h"

namespace pineda {

void link_program(Context& ctx, ProgramObject& p) {
  p.link_status = false;
  p.validate_status = false;
  p.executable.reset();
  p.info_log.clear();
  std::vector<const shader::CompiledShader*> stages[2];  // vertex, fragment: several of a stage link as one
  for (GLuint name : p.attached) {
    const ShaderObject* s = ctx.programs.objects.shader(name);
    if (!s) continue;
    if (!s->compile_status || !s->compiled) {
      p.info_log = "error: shader " + std::to_string(name) + " is not compiled\n";
      return;
    }
    stages[s->type == GL_VERTEX_SHADER ? 0 : 1].push_back(s->compiled.get());
  }
  if (ctx.attribs().gles && (stages[0].empty() || stages[1].empty())) {
    p.info_log = "error: a program needs a vertex and a fragment shader\n";
    return;
  }
  auto exec = std::make_shared<LinkedProgram>();
  exec->vertex_shader = !stages[0].empty();
  exec->fragment_shader = !stages[1].empty();
  if (exec->vertex_shader || exec->fragment_shader) {
    std::vector<shader::AttributeBinding> bindings;
    for (const auto& [name, location] : p.bindings) bindings.push_back({name, static_cast<int>(location)});
    shader::LinkResult result = shader::link(stages[0], stages[1], bindings);
    p.info_log = std::move(result.info_log);
    if (!result.program) return;
    exec->program = std::move(result.program);
    exec->uniforms = UniformTable::build(exec->program->uniforms());
    exec->values.assign(static_cast<size_t>(std::max(exec->program->uniform_floats(), 0)), 0.f);
    for (const shader::Uniform& u : exec->program->uniforms()) {  // GLSL 1.20 initializers
      if (u.initial.empty() || u.offset < 0 || static_cast<size_t>(u.offset) >= exec->values.size()) continue;
      const size_t n = std::min(u.initial.size(), exec->values.size() - static_cast<size_t>(u.offset));
      std::copy(u.initial.begin(), u.initial.begin() + static_cast<std::ptrdiff_t>(n), exec->values.begin() + u.offset);
    }
    const auto& attributes = exec->program->attributes();
    for (size_t i = 0; i < attributes.size(); ++i) exec->attributes.push_back(static_cast<int>(i));
    exec->generic_attributes_only = std::all_of(attributes.begin(), attributes.end(), [](const shader::Attribute& a) {
      return a.builtin == shader::BuiltinAttribute::None;
    });
    exec->sampler_conflict = sampler_unit_conflict(*exec);
  }
  p.executable = std::move(exec);
  p.link_status = true;
}

bool validate_program(const Context&, const ProgramObject& p, std::string& log) {
  if (!p.link_status || !p.executable) {
    log = "error: the program is not linked\n";
    return false;
  }
  log = p.executable->sampler_conflict;
  return log.empty();
}

}  // namespace pineda
