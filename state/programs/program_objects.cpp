#include "state/programs/program_objects.h"

namespace pineda {

GLuint ShaderProgramNames::next_name() {
  while (exists(next_) || next_ == 0) ++next_;
  return next_++;
}

GLuint ShaderProgramNames::create_shader(GLenum type) {
  const GLuint name = next_name();
  auto s = std::make_unique<ShaderObject>();
  s->type = type;
  shaders_[name] = std::move(s);
  return name;
}

GLuint ShaderProgramNames::create_program() {
  const GLuint name = next_name();
  programs_[name] = std::make_unique<ProgramObject>();
  return name;
}

ShaderObject* ShaderProgramNames::shader(GLuint name) {
  auto it = shaders_.find(name);
  return it == shaders_.end() ? nullptr : it->second.get();
}

ProgramObject* ShaderProgramNames::program(GLuint name) {
  auto it = programs_.find(name);
  return it == programs_.end() ? nullptr : it->second.get();
}

void ShaderProgramNames::destroy_program_if_unused(GLuint name) {
  ProgramObject* p = program(name);
  if (!p || !p->delete_pending || p->contexts_using > 0) return;
  for (GLuint shader_name : p->attached) {
    ShaderObject* s = shader(shader_name);
    if (!s) continue;
    --s->attachments;
    if (s->delete_pending && s->attachments <= 0) remove_shader(shader_name);
  }
  remove_program(name);
}

}  // namespace pineda
