// glLinkProgram and glValidateProgram on a program object.
#pragma once
#include <string>

#include "state/programs/program_objects.h"

namespace pineda {

class Context;

// Links the attached shaders with the program's attribute bindings; on success the program
// gets a new executable (uniforms zero), on failure it has none. The info log says why.
void link_program(Context& ctx, ProgramObject& program);

// Whether the program's executable can run with the current state (GL 2.0 2.15.4): linked,
// and no two samplers of different types on one texture unit. `log` says why not.
bool validate_program(const Context& ctx, const ProgramObject& program, std::string& log);

}  // namespace pineda
