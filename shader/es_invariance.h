// GLSL ES 1.00's linkage rule for invariant built-ins (section 4.6.4): gl_FragCoord may be
// declared invariant only if gl_Position is, gl_PointCoord only if gl_PointSize is, and
// gl_FrontFacing never. glslang does not check it.
#pragma once
#include <string>

#include <glslang/MachineIndependent/localintermediate.h>

namespace pineda::shader {

// False, with a line appended to `log`, when the stages break the rule. Either may be null.
bool es_invariance_ok(const glslang::TIntermediate* vertex, const glslang::TIntermediate* fragment,
                      std::string& log);

}  // namespace pineda::shader
