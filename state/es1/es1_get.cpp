// The glGet values only OpenGL ES 1.1 defines.
#include "state/context.h"
#include "state/get_values.h"

namespace pineda {

bool query_es1(Context& ctx, unsigned pname, GetValues& out) {
  switch (pname) {
    // OES_read_format: the format and type glReadPixels takes besides RGBA/UNSIGNED_BYTE;
    // Pineda's colour buffers are RGBA8, so the same pair.
    case GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES: out = get_enums({GL_RGBA}); return true;
    case GL_IMPLEMENTATION_COLOR_READ_TYPE_OES: out = get_enums({GL_UNSIGNED_BYTE}); return true;
    default: return false;
  }
}

}  // namespace pineda
