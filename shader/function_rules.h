// Rules on function definitions of GLSL 1.10 that glslang 12 does not check:
// - a sampler, or a structure holding one, is no l-value (GLSL 1.10 section 4.1.7): no out or
//   inout parameter and no return type (piglit's samplers/{out,inout,return}-struct);
// - in GLSL 1.10 an array is no l-value (section 5.8): no out or inout array parameter (GLSL
//   1.20 allows them; piglit's fn-{out,inout}-array-prohibited-cstyle).
#pragma once
#include <glslang/MachineIndependent/localintermediate.h>

#include <string>

namespace pineda::shader {

// False, with an error in `log`, when a function definition of the tree breaks one of them.
bool function_rules_ok(const glslang::TIntermediate* tree, std::string& log);

}  // namespace pineda::shader
