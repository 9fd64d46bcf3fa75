// GLSL 1.10 section 7.2 (and GLSL ES 1.00 section 7.2): a fragment shader may assign to
// gl_FragColor or to gl_FragData, not to both; a compile-time rule on static assignments
// (dead code counts), which glslang leaves to its linker.
#pragma once
#include <glslang/MachineIndependent/localintermediate.h>

#include <string>

namespace pineda::shader {

// False, with an error in `log`, when the tree assigns to both.
bool fragment_outputs_ok(const glslang::TIntermediate* tree, std::string& log);

}  // namespace pineda::shader
