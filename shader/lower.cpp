// Lowering of glslang's typed tree to the IR (the parts: shader/lowerer.h).
#include "shader/lower.h"

#include "shader/lowerer.h"

namespace pineda::shader {

bool lower_stage(Stage stage, const glslang::TIntermediate& tree, Interface& iface, ir::Code& code,
                 std::string& error) {
  try {
    lowering::Lowerer(stage, iface, code).run(tree);
    return true;
  } catch (const lowering::LowerError& e) {
    error = e.message;
    return false;
  }
}

}  // namespace pineda::shader
