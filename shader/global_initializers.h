// A global variable initialized in several shaders of one stage linked together must have
// the same constant initializer in each (as Mesa: "global variable has multiple initializers"
// when one is not constant, even the same expression; "differing values" when the constants
// differ). glslang's linker does not check it.
#pragma once
#include <string>
#include <vector>

#include <glslang/MachineIndependent/localintermediate.h>

namespace pineda::shader {

// False, with a line appended to `log`, when two of `units` (the shaders of one stage)
// initialize the same global variable differently.
bool global_initializers_unique(const std::vector<const glslang::TIntermediate*>& units, std::string& log);

}  // namespace pineda::shader
