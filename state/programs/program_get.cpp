#include "state/programs/program_get.h"

#include "state/context.h"
#include "state/programs/program_limits.h"

namespace pineda {

bool query_program_state(Context& ctx, unsigned pname, GetValues& out) {
  if (ctx.es1()) return false;
  switch (pname) {
    case GL_CURRENT_PROGRAM: out = get_ints({double(ctx.programs.current)}); return true;
    case GL_FRAGMENT_SHADER_DERIVATIVE_HINT: out = get_enums({double(ctx.programs.derivative_hint)}); return true;
    case GL_MAX_VERTEX_ATTRIBS: out = get_ints({kMaxVertexAttribs}); return true;
    case GL_MAX_VERTEX_UNIFORM_COMPONENTS: out = get_ints({kMaxUniformComponents}); return true;
    case GL_MAX_FRAGMENT_UNIFORM_COMPONENTS: out = get_ints({kMaxUniformComponents}); return true;
    case GL_MAX_VARYING_FLOATS: out = get_ints({shader::kMaxVaryingFloats}); return true;
    case GL_MAX_TEXTURE_IMAGE_UNITS: out = get_ints({raster::kMaxTextureImageUnits}); return true;
    case GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS: out = get_ints({raster::kMaxTextureImageUnits}); return true;
    case GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS: out = get_ints({raster::kMaxTextureImageUnits}); return true;
    case GL_MAX_TEXTURE_COORDS: out = get_ints({raster::kMaxTextureUnits}); return true;
    default: return false;
  }
}

bool* program_capability(Context& ctx, unsigned cap) {
  if (ctx.es1()) return nullptr;
  switch (cap) {
    case GL_VERTEX_PROGRAM_POINT_SIZE: return &ctx.programs.point_size_from_shader;
    case GL_VERTEX_PROGRAM_TWO_SIDE: return &ctx.programs.two_side;
    default: return nullptr;
  }
}

}  // namespace pineda
