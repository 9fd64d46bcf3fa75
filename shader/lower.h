// Lowering of glslang's typed tree (one linked stage) to Pineda's IR.
#pragma once
#include <string>
#include <vector>

#include "shader/interface.h"
#include "shader/ir.h"

namespace glslang { class TIntermediate; }

namespace pineda::shader {

// Lowers `tree` into `code`, adding the stage's uniforms, inputs and outputs to `iface`.
// The fragment stage is lowered first: the vertex stage then routes its outputs to the
// varyings the fragment stage reads. Returns false with `error` set on a link error.
bool lower_stage(Stage stage, const glslang::TIntermediate& tree, Interface& iface, ir::Code& code,
                 std::string& error);

}  // namespace pineda::shader
