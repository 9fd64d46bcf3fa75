// GL_KHR_debug object labels: glObjectLabel, glGetObjectLabel, glObjectPtrLabel, glGetObjectPtrLabel.
#include <algorithm>
#include <cstring>

#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {
namespace {

enum class Lookup { Exists, NoSuchObject, UnknownIdentifier };

// The object kinds this context has; the others are GL_INVALID_ENUM.
Lookup find_object(Context& ctx, GLenum identifier, GLuint name) {
  bool exists = false;
  switch (identifier) {
    case GL_BUFFER: exists = ctx.buffers.names.exists(name); break;
    case GL_TEXTURE: exists = ctx.textures.is_texture(name); break;
    case GL_QUERY: exists = ctx.queries.names.exists(name); break;
    case GL_DISPLAY_LIST: exists = ctx.lists.exists(name); break;
    case GL_SHADER: exists = ctx.programs.objects.shader(name) != nullptr; break;
    case GL_PROGRAM: exists = ctx.programs.objects.program(name) != nullptr; break;
    // A generated name that was never bound counts as an object here.
    case GL_VERTEX_ARRAY: exists = ctx.vertex_array_objects.names.generated(name); break;
    case GL_RENDERBUFFER: exists = name && ctx.framebuffers.renderbuffers.count(name); break;
    case GL_FRAMEBUFFER:
      exists = name && (ctx.framebuffers.framebuffers.count(name) || ctx.framebuffers.generated_framebuffers.count(name));
      break;
    default: return Lookup::UnknownIdentifier;
  }
  return exists ? Lookup::Exists : Lookup::NoSuchObject;
}

bool check_object(Context& ctx, GLenum identifier, GLuint name) {
  switch (find_object(ctx, identifier, name)) {
    case Lookup::Exists: return true;
    case Lookup::NoSuchObject:
      ctx.record_error(GL_INVALID_VALUE, [name] { return "name " + std::to_string(name) + " is not an object of that identifier"; });
      return false;
    case Lookup::UnknownIdentifier:
      ctx.record_error(GL_INVALID_ENUM, "identifier is not an object kind this context has");
      return false;
  }
  return false;
}

// The label as the caller gives it, or nothing (GL_INVALID_VALUE recorded) when too long.
bool read_label(Context& ctx, GLsizei length, const GLchar* label, std::string* out) {
  if (!label) {
    out->clear();
    return true;
  }
  const size_t n = length < 0 ? std::strlen(label) : size_t(length);
  if (n >= size_t(DebugOutput::kMaxLabelLength)) {
    ctx.record_error(GL_INVALID_VALUE, [] {
      return "the label is not shorter than GL_MAX_LABEL_LENGTH (" + std::to_string(DebugOutput::kMaxLabelLength) + ")";
    });
    return false;
  }
  out->assign(label, n);
  return true;
}

void write_label(const std::string* label, GLsizei buf_size, GLsizei* length, GLchar* out) {
  const std::string empty;
  const std::string& text = label ? *label : empty;
  if (!out) {
    if (length) *length = GLsizei(text.size());
    return;
  }
  const size_t n = buf_size > 0 ? std::min(text.size(), size_t(buf_size) - 1) : 0;
  if (buf_size > 0) {
    std::memcpy(out, text.data(), n);
    out[n] = '\0';
  }
  if (length) *length = GLsizei(n);
}

}  // namespace

void ObjectLabel(Context& ctx, GLenum identifier, GLuint name, GLsizei length, const GLchar* label) {
  if (!check_object(ctx, identifier, name)) return;
  std::string text;
  if (!read_label(ctx, length, label, &text)) return;
  ctx.debug.set_label(identifier, name, std::move(text));
}

void GetObjectLabel(Context& ctx, GLenum identifier, GLuint name, GLsizei buf_size, GLsizei* length, GLchar* label) {
  if (buf_size < 0) return ctx.record_error(GL_INVALID_VALUE, "bufSize is negative");
  if (!check_object(ctx, identifier, name)) return;
  write_label(ctx.debug.label(identifier, name), buf_size, length, label);
}

// Pineda has no sync objects (GL_ARB_sync), so no pointer names one.
void ObjectPtrLabel(Context& ctx, const void* ptr, GLsizei length, const GLchar* label) {
  ctx.record_error(GL_INVALID_VALUE, "ptr is not a sync object");
}

void GetObjectPtrLabel(Context& ctx, const void* ptr, GLsizei buf_size, GLsizei* length, GLchar* label) {
  if (buf_size < 0) return ctx.record_error(GL_INVALID_VALUE, "bufSize is negative");
  ctx.record_error(GL_INVALID_VALUE, "ptr is not a sync object");
}

}  // namespace pineda::gl
