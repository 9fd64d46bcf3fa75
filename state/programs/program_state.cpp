#include "state/programs/program_state.h"

namespace pineda {

void ProgramState::use(GLuint program, std::shared_ptr<LinkedProgram> exec) {
  const GLuint previous = current;
  if (ProgramObject* p = objects.program(program)) ++p->contexts_using;
  current = program;
  current_exec = std::move(exec);
  if (ProgramObject* p = objects.program(previous)) {
    --p->contexts_using;
    objects.destroy_program_if_unused(previous);
  }
}

}  // namespace pineda
