// GL_EXT_discard_framebuffer: a hint that the listed buffers' contents are no longer needed.
// Pineda keeps them (the extension allows any contents afterwards); only the errors act.
#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {

void DiscardFramebufferEXT(Context& ctx, GLenum target, GLsizei numAttachments, const GLenum* attachments) {
  if (target != GL_FRAMEBUFFER) return ctx.record_error(GL_INVALID_ENUM, "target is not FRAMEBUFFER");
  if (numAttachments < 0) return ctx.record_error(GL_INVALID_VALUE, "numAttachments is negative");
  if (numAttachments > 0 && !attachments) return;
  const bool object = ctx.framebuffers.draw_object() != nullptr;
  for (GLsizei i = 0; i < numAttachments; ++i) {
    const GLenum a = attachments[i];
    const bool known = object ? (a == GL_COLOR_ATTACHMENT0 || a == GL_DEPTH_ATTACHMENT || a == GL_STENCIL_ATTACHMENT)
                              : (a == GL_COLOR || a == GL_DEPTH || a == GL_STENCIL);
    if (!known) return ctx.record_error(GL_INVALID_ENUM, "not an attachment of the bound framebuffer");
  }
}

}  // namespace pineda::gl
