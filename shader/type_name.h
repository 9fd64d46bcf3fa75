// The GLSL name of a type that state/ reports (Mesa's validation log names sampler types).
#pragma once
#include <string>

#include "shader/program.h"

namespace pineda::shader {

std::string type_name(const Type& type);  // "vec3", "mat2x3", "samplerCube"...

}  // namespace pineda::shader
