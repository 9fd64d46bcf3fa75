// The glGet values OpenGL ES 2.0 defines and desktop GL has through GL_ARB_ES2_compatibility
// (ES 2.0 table 6.18-6.20: limits counted in vec4s, the shader compiler and binary formats,
// the preferred glReadPixels pair).
#include "shader/program.h"
#include "state/context.h"
#include "state/get_values.h"
#include "state/programs/program_limits.h"

namespace pineda {

bool query_es2(Context& ctx, unsigned pname, GetValues& out) {
  switch (pname) {
    case GL_MAX_VERTEX_UNIFORM_VECTORS: out = get_ints({kMaxUniformComponents / 4}); return true;
    case GL_MAX_FRAGMENT_UNIFORM_VECTORS: out = get_ints({kMaxUniformComponents / 4}); return true;
    case GL_MAX_VARYING_VECTORS: out = get_ints({shader::kMaxVaryingFloats / 4}); return true;
    case GL_SHADER_COMPILER: out = get_bools({1}); return true;
    case GL_NUM_SHADER_BINARY_FORMATS: out = get_ints({0}); return true;
    case GL_SHADER_BINARY_FORMATS: out = get_ints({}); return true;
    // Pineda's colour buffers are RGBA8: the pair every ES implementation takes anyway.
    case GL_IMPLEMENTATION_COLOR_READ_FORMAT: out = get_enums({GL_RGBA}); return true;
    case GL_IMPLEMENTATION_COLOR_READ_TYPE: out = get_enums({GL_UNSIGNED_BYTE}); return true;
    // EXT_clip_cull_distance's MAX_CLIP_DISTANCES_EXT (the same value): no clip distances in
    // ES 2.0. Every piglit shader_runner_gles2 test asks for it (Mesa's ES 2.0 request gives ES
    // 3.2, where it exists), so it is answered rather than INVALID_ENUM (glapi/gen_entry_points.py).
    case GL_MAX_CLIP_PLANES:
      if (!ctx.es2()) return false;  // desktop GL's own value
      out = get_ints({0});
      return true;
    default: return false;
  }
}

}  // namespace pineda
