// GL 2.0 2.15.3 / ES 2.0 2.10.4: samplers of different types may not use one texture unit.
// A draw with such a program is INVALID_OPERATION, and glValidateProgram fails.
#pragma once
#include <string>

#include "state/programs/program_objects.h"

namespace pineda {

// Why the executable's samplers cannot run ("Texture unit 0 is accessed both as sampler2D and
// samplerCube", as Mesa), or empty when they can. Kept in LinkedProgram::sampler_conflict,
// computed at link and when a sampler uniform changes, so that draws only read it.
std::string sampler_unit_conflict(const LinkedProgram& exec);

}  // namespace pineda
