// The programmable part of a draw snapshot: the linked program and a copy of its uniform
// values (the draw runs later on worker threads while the application changes them).
#pragma once
#include <memory>
#include <vector>

#include "shader/program.h"

namespace pineda::raster {

struct ShaderDraw {
  std::shared_ptr<const shader::Program> program;
  std::vector<float> uniforms;  // program->uniform_floats() values
  bool two_side = false;        // back-facing polygons read the varyings' back_offset values
  int color_output = 0;         // the gl_FragData index written to the colour buffer
};

}  // namespace pineda::raster
