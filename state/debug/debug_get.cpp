// The GL_KHR_debug values of glGet* (desktop GL contexts).
#include "state/context.h"
#include "state/get_values.h"

namespace pineda {

bool query_debug(Context& ctx, unsigned pname, GetValues& out) {
  if (ctx.es1()) return false;
  const DebugOutput& d = ctx.debug;
  switch (pname) {
    case GL_MAX_DEBUG_MESSAGE_LENGTH: out = get_ints({DebugOutput::kMaxMessageLength}); return true;
    case GL_MAX_DEBUG_LOGGED_MESSAGES: out = get_ints({DebugOutput::kMaxLoggedMessages}); return true;
    case GL_MAX_DEBUG_GROUP_STACK_DEPTH: out = get_ints({DebugOutput::kMaxGroupDepth}); return true;
    case GL_MAX_LABEL_LENGTH: out = get_ints({DebugOutput::kMaxLabelLength}); return true;
    case GL_DEBUG_LOGGED_MESSAGES: out = get_ints({double(d.log().size())}); return true;
    case GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH:
      out = get_ints({d.log().empty() ? 0.0 : double(d.log().front().text.size() + 1)});
      return true;
    case GL_DEBUG_GROUP_STACK_DEPTH: out = get_ints({double(d.group_depth())}); return true;
    default: return false;
  }
}

}  // namespace pineda
