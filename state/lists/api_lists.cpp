// Display lists: glNewList/glEndList/glCallList(s)/glGenLists/glDeleteLists/glIsList/glListBase.
#include <vector>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/es1/es1_enums.h"
#include "state/pixels/pixel_state.h"
#include "state/unaligned.h"

namespace pineda::gl {
namespace {

void call_list(Context& ctx, GLuint name) {
  if (ctx.list_depth >= kMaxListNesting) return;
  std::shared_ptr<const DisplayList> list = ctx.lists.find(name);
  if (!list) return;  // calling an undefined list does nothing
  struct Nesting {  // left even when a command runs out of memory
    int& depth;
    explicit Nesting(int& d) : depth(++d) {}
    ~Nesting() { --depth; }
  } nesting(ctx.list_depth);
  for (const ListCommand& command : list->commands) {
    ctx.note_state_changed();  // each command as a call of its own (StateKey)
    command(ctx);
  }
}

// The list-name offsets of glCallLists, decoded by type; false for an invalid type.
bool decode_names(GLsizei n, GLenum type, const void* lists, std::vector<GLuint>& out) {
  const auto* b = static_cast<const uint8_t*>(lists);
  out.resize(n);
  for (GLsizei i = 0; i < n; ++i) {
    switch (type) {
      case GL_BYTE: out[i] = GLuint(GLint(reinterpret_cast<const GLbyte*>(b)[i])); break;
      case GL_UNSIGNED_BYTE: out[i] = b[i]; break;
      case GL_SHORT: out[i] = GLuint(GLint(load_unaligned<GLshort>(b + 2 * i))); break;
      case GL_UNSIGNED_SHORT: out[i] = load_unaligned<GLushort>(b + 2 * i); break;
      case GL_INT: out[i] = GLuint(load_unaligned<GLint>(b + 4 * i)); break;
      case GL_UNSIGNED_INT: out[i] = load_unaligned<GLuint>(b + 4 * i); break;
      case GL_FLOAT: out[i] = GLuint(truncate_int_param(load_unaligned<GLfloat>(b + 4 * i))); break;
      case GL_2_BYTES: out[i] = b[2 * i] * 256u + b[2 * i + 1]; break;
      case GL_3_BYTES: out[i] = (b[3 * i] * 256u + b[3 * i + 1]) * 256u + b[3 * i + 2]; break;
      case GL_4_BYTES:
        out[i] = ((b[4 * i] * 256u + b[4 * i + 1]) * 256u + b[4 * i + 2]) * 256u + b[4 * i + 3];
        break;
      default: return false;
    }
  }
  return true;
}

bool valid_call_lists_type(GLenum type) {
  return (type >= GL_BYTE && type <= GL_FLOAT) || (type >= GL_2_BYTES && type <= GL_4_BYTES);
}

void call_names(Context& ctx, const std::vector<GLuint>& names) {
  for (GLuint offset : names) call_list(ctx, ctx.list_base + offset);
}

}  // namespace

void NewList(Context& ctx, GLuint list, GLenum mode) {
  if (list == 0) return ctx.record_error(GL_INVALID_VALUE, "list is zero");
  if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE)
    return ctx.record_error(GL_INVALID_ENUM, "mode is not GL_COMPILE or GL_COMPILE_AND_EXECUTE");
  if (ctx.compiling_list()) return ctx.record_error(GL_INVALID_OPERATION, "a display list is already being compiled");
  ctx.compilation = {list, mode, std::make_shared<DisplayList>()};
}

void EndList(Context& ctx) {
  if (!ctx.compiling_list()) return ctx.record_error(GL_INVALID_OPERATION, "no display list is being compiled");
  ctx.lists.define(ctx.compilation.name, std::move(ctx.compilation.list));
  ctx.compilation = {};
}

void CallList(Context& ctx, GLuint list) { call_list(ctx, list); }

void CallLists(Context& ctx, GLsizei n, GLenum type, const void* lists) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (!valid_call_lists_type(type)) return ctx.record_error(GL_INVALID_ENUM, "type is not a list name type");
  std::vector<GLuint> names;
  if (lists && decode_names(n, type, lists, names)) call_names(ctx, names);
}

// The names are read now; the list base is the one in effect when the list runs.
void compile_CallLists(Context& ctx, GLsizei n, GLenum type, const void* lists) {
  std::vector<GLuint> names;
  const bool valid = n >= 0 && valid_call_lists_type(type);
  if (valid && lists) decode_names(n, type, lists, names);
  ctx.record_list_command([n, valid, names](Context& c) {  // allowed between glBegin and glEnd
    if (n < 0) return c.record_error(GL_INVALID_VALUE, "n is negative");
    if (!valid) return c.record_error(GL_INVALID_ENUM, "type is not a list name type");
    call_names(c, names);
  });
}

GLuint GenLists(Context& ctx, GLsizei range) {
  if (range < 0) {
    ctx.record_error(GL_INVALID_VALUE, "range is negative");
    return 0;
  }
  return ctx.lists.generate(range);
}

void DeleteLists(Context& ctx, GLuint list, GLsizei range) {
  if (range < 0) return ctx.record_error(GL_INVALID_VALUE, "range is negative");
  if (range > 0) {
    const GLuint last = GLuint(-1) - list < GLuint(range - 1) ? GLuint(-1) : list + GLuint(range - 1);
    ctx.debug.forget_labels(GL_DISPLAY_LIST, list, last);
  }
  ctx.lists.remove(list, range);
}

GLboolean IsList(Context& ctx, GLuint list) { return ctx.lists.exists(list) ? GL_TRUE : GL_FALSE; }

void ListBase(Context& ctx, GLuint base) { ctx.list_base = base; }

size_t list_param_count(GLenum pname) {
  switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_POSITION: case GL_EMISSION:
    case GL_AMBIENT_AND_DIFFUSE: case GL_LIGHT_MODEL_AMBIENT: case GL_TEXTURE_BORDER_COLOR:
    case GL_TEXTURE_ENV_COLOR: case GL_FOG_COLOR: case GL_OBJECT_PLANE: case GL_EYE_PLANE:
    case GL_TEXTURE_CROP_RECT_OES: case GL_TEXTURE_SWIZZLE_RGBA:
      return 4;
    case GL_SPOT_DIRECTION: case GL_COLOR_INDEXES: case GL_POINT_DISTANCE_ATTENUATION: return 3;
    default: return 1;
  }
}

}  // namespace pineda::gl
