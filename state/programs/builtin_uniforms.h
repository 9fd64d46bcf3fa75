// The built-in state uniforms of desktop GLSL (GLSL 1.20 section 7.5: gl_ModelViewMatrix,
// gl_LightSource[i], gl_Fog, ...), filled from GL state into a draw's uniform values.
#pragma once
#include <vector>

#include "shader/program.h"

namespace pineda {

class Context;

// Writes every built-in uniform of `program` that it lists into `values`; unknown names are
// left as they are (zero).
void fill_builtin_uniforms(const Context& ctx, const shader::Program& program, std::vector<float>& values);

}  // namespace pineda
