// The glGet* values of framebuffer objects: bindings and limits.
#include "state/context.h"
#include "state/framebuffers/framebuffer_get.h"
#include "state/framebuffers/framebuffer_object.h"

namespace pineda {

bool query_framebuffers(Context& ctx, unsigned pname, GetValues& out) {
  const FramebufferState& fs = ctx.framebuffers;
  switch (pname) {
    case GL_DRAW_FRAMEBUFFER_BINDING: out = get_ints({double(fs.draw_binding)}); return true;  // = FRAMEBUFFER_BINDING
    case GL_READ_FRAMEBUFFER_BINDING: out = get_ints({double(fs.read_binding)}); return true;
    case GL_RENDERBUFFER_BINDING: out = get_ints({double(fs.renderbuffer_binding)}); return true;
    case GL_MAX_RENDERBUFFER_SIZE: out = get_ints({double(kMaxRenderbufferSize)}); return true;
    case GL_MAX_COLOR_ATTACHMENTS: out = get_ints({double(kMaxColorAttachments)}); return true;
    case GL_MAX_SAMPLES: out = get_ints({kMaxSamples}); return true;
    default: return false;
  }
}

}  // namespace pineda
