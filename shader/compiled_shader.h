// What compile() keeps of a shader: its sources and how to parse them. Linking parses them
// again into fresh glslang objects, so that a CompiledShader shares nothing mutable between
// the programs (and threads) that link it.
#pragma once
#include <string>
#include <vector>

#include "shader/program.h"

namespace pineda::shader {

struct CompiledShader {
  Stage stage;
  Language language;
  std::vector<std::string> sources;
};

}  // namespace pineda::shader
