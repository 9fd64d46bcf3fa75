// GL_EXT_draw_buffers in GLSL ES 1.00, which glslang 12 does not know: Pineda takes the
// extension's `#extension GL_EXT_draw_buffers : behaviour` directives out of the source itself
// (blanked, so that lines and columns stay) and sizes gl_FragData by what they leave enabled:
// gl_MaxDrawBuffers is kMaxDrawBuffers when enabled, else 1 (ES 2.0's value without it).
// Directives are read line by line, before preprocessing: one inside a false #if still counts.
#pragma once
#include <string>
#include <vector>

namespace pineda::shader {

// Blanks the extension's directives in `sources`; true when the last one enables it
// (enable, require or warn).
bool take_draw_buffers_directives(std::vector<std::string>& sources);

}  // namespace pineda::shader
