// GL_KHR_debug: glDebugMessageControl, glDebugMessageInsert, glDebugMessageCallback,
// glGetDebugMessageLog, glPushDebugGroup, glPopDebugGroup.
#include <cstring>

#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {
namespace {

bool valid_source(GLenum s) {
  switch (s) {
    case GL_DEBUG_SOURCE_API: case GL_DEBUG_SOURCE_WINDOW_SYSTEM: case GL_DEBUG_SOURCE_SHADER_COMPILER:
    case GL_DEBUG_SOURCE_THIRD_PARTY: case GL_DEBUG_SOURCE_APPLICATION: case GL_DEBUG_SOURCE_OTHER:
      return true;
    default: return false;
  }
}

bool valid_type(GLenum t) {
  switch (t) {
    case GL_DEBUG_TYPE_ERROR: case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
    case GL_DEBUG_TYPE_PORTABILITY: case GL_DEBUG_TYPE_PERFORMANCE: case GL_DEBUG_TYPE_OTHER:
    case GL_DEBUG_TYPE_MARKER: case GL_DEBUG_TYPE_PUSH_GROUP: case GL_DEBUG_TYPE_POP_GROUP:
      return true;
    default: return false;
  }
}

bool valid_severity(GLenum s) {
  switch (s) {
    case GL_DEBUG_SEVERITY_HIGH: case GL_DEBUG_SEVERITY_MEDIUM: case GL_DEBUG_SEVERITY_LOW:
    case GL_DEBUG_SEVERITY_NOTIFICATION:
      return true;
    default: return false;
  }
}

bool application_source(GLenum s) { return s == GL_DEBUG_SOURCE_APPLICATION || s == GL_DEBUG_SOURCE_THIRD_PARTY; }

// The message's length as the caller gives it (negative: null-terminated), or -1 with
// GL_INVALID_VALUE recorded when it reaches MAX_DEBUG_MESSAGE_LENGTH.
GLsizei message_length(Context& ctx, GLsizei length, const GLchar* buf) {
  if (length < 0) length = buf ? GLsizei(std::strlen(buf)) : 0;
  if (length >= DebugOutput::kMaxMessageLength) {
    ctx.record_error(GL_INVALID_VALUE, [] {
      return "the message is not shorter than GL_MAX_DEBUG_MESSAGE_LENGTH (" +
             std::to_string(DebugOutput::kMaxMessageLength) + ")";
    });
    return -1;
  }
  return length;
}

}  // namespace

void DebugMessageControl(Context& ctx, GLenum source, GLenum type, GLenum severity, GLsizei count,
                         const GLuint* ids, GLboolean enabled) {
  if (source != GL_DONT_CARE && !valid_source(source))
    return ctx.record_error(GL_INVALID_ENUM, "source is not a debug source or GL_DONT_CARE");
  if (type != GL_DONT_CARE && !valid_type(type))
    return ctx.record_error(GL_INVALID_ENUM, "type is not a debug type or GL_DONT_CARE");
  if (severity != GL_DONT_CARE && !valid_severity(severity))
    return ctx.record_error(GL_INVALID_ENUM, "severity is not a debug severity or GL_DONT_CARE");
  if (count < 0) return ctx.record_error(GL_INVALID_VALUE, "count is negative");
  if (count > 0 && (source == GL_DONT_CARE || type == GL_DONT_CARE || severity != GL_DONT_CARE))
    return ctx.record_error(GL_INVALID_OPERATION,
                            "ids are listed, so source and type must be given and severity must be GL_DONT_CARE");
  if (count > 0 && !ids) return ctx.record_error(GL_INVALID_VALUE, "ids is null");
  ctx.debug.control(source, type, severity, std::vector<GLuint>(ids, ids + count), enabled != GL_FALSE);
}

void DebugMessageInsert(Context& ctx, GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                        const GLchar* buf) {
  if (!application_source(source))
    return ctx.record_error(GL_INVALID_ENUM, "source is not GL_DEBUG_SOURCE_APPLICATION or _THIRD_PARTY");
  if (!valid_type(type)) return ctx.record_error(GL_INVALID_ENUM, "type is not a debug type");
  if (!valid_severity(severity)) return ctx.record_error(GL_INVALID_ENUM, "severity is not a debug severity");
  const GLsizei n = message_length(ctx, length, buf);
  if (n < 0) return;
  if (n > 0 && !buf) return ctx.record_error(GL_INVALID_VALUE, "buf is null");
  ctx.debug.emit(source, type, id, severity, std::string_view(buf ? buf : "", size_t(n)));
}

void DebugMessageCallback(Context& ctx, GLDEBUGPROC callback, const void* user_param) {
  ctx.debug.callback = callback;
  ctx.debug.user_param = user_param;
}

GLuint GetDebugMessageLog(Context& ctx, GLuint count, GLsizei buf_size, GLenum* sources, GLenum* types, GLuint* ids,
                          GLenum* severities, GLsizei* lengths, GLchar* message_log) {
  if (buf_size < 0 && message_log) {
    ctx.record_error(GL_INVALID_VALUE, "bufSize is negative and messageLog is not null");
    return 0;
  }
  GLuint fetched = 0;
  size_t remaining = message_log ? size_t(buf_size) : 0;
  while (fetched < count && !ctx.debug.log().empty()) {
    const DebugMessage& m = ctx.debug.log().front();
    if (message_log) {
      if (m.text.size() + 1 > remaining) break;  // the first message that does not fit stays logged
      std::memcpy(message_log, m.text.c_str(), m.text.size() + 1);
      message_log += m.text.size() + 1;
      remaining -= m.text.size() + 1;
    }
    if (sources) sources[fetched] = m.source;
    if (types) types[fetched] = m.type;
    if (ids) ids[fetched] = m.id;
    if (severities) severities[fetched] = m.severity;
    if (lengths) lengths[fetched] = GLsizei(m.text.size() + 1);
    ctx.debug.pop_logged();
    ++fetched;
  }
  return fetched;
}

void PushDebugGroup(Context& ctx, GLenum source, GLuint id, GLsizei length, const GLchar* message) {
  if (!application_source(source))
    return ctx.record_error(GL_INVALID_ENUM, "source is not GL_DEBUG_SOURCE_APPLICATION or _THIRD_PARTY");
  const GLsizei n = message_length(ctx, length, message);
  if (n < 0) return;
  if (n > 0 && !message) return ctx.record_error(GL_INVALID_VALUE, "message is null");
  if (ctx.debug.group_depth() >= DebugOutput::kMaxGroupDepth)
    return ctx.record_error(GL_STACK_OVERFLOW, "the debug group stack is full (GL_MAX_DEBUG_GROUP_STACK_DEPTH)");
  ctx.debug.push_group(source, id, std::string(message ? message : "", size_t(n)));
}

void PopDebugGroup(Context& ctx) {
  if (ctx.debug.group_depth() <= 1)
    return ctx.record_error(GL_STACK_UNDERFLOW, "only the default debug group is on the stack");
  ctx.debug.pop_group();
}

}  // namespace pineda::gl
