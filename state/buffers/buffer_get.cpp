#include "state/buffers/buffer_get.h"

#include "state/context.h"
#include "state/es1/es1_enums.h"

namespace pineda {

bool query_buffer_binding(const Context& ctx, GLenum pname, GLuint& name) {
  const ClientArray* array = nullptr;
  switch (pname) {
    case GL_ARRAY_BUFFER_BINDING: name = buffer_name(ctx.buffers.array); return true;
    case GL_ELEMENT_ARRAY_BUFFER_BINDING: name = buffer_name(ctx.buffers.element_array); return true;
    case GL_PIXEL_PACK_BUFFER_BINDING:
    case GL_PIXEL_UNPACK_BUFFER_BINDING:
      if (ctx.es1()) return false;
      name = buffer_name(pname == GL_PIXEL_PACK_BUFFER_BINDING ? ctx.pack.buffer : ctx.unpack.buffer);
      return true;
    case GL_COPY_READ_BUFFER_BINDING:
    case GL_COPY_WRITE_BUFFER_BINDING:
      if (ctx.es1() || ctx.es2()) return false;
      name = buffer_name(pname == GL_COPY_READ_BUFFER_BINDING ? ctx.buffers.copy_read : ctx.buffers.copy_write);
      return true;
    case GL_INDEX_ARRAY_BUFFER_BINDING: array = &ctx.index_array; break;
    case GL_VERTEX_ARRAY_BUFFER_BINDING: array = &ctx.vertex_array; break;
    case GL_NORMAL_ARRAY_BUFFER_BINDING: array = &ctx.normal_array; break;
    case GL_COLOR_ARRAY_BUFFER_BINDING: array = &ctx.color_array; break;
    case GL_EDGE_FLAG_ARRAY_BUFFER_BINDING: array = &ctx.edge_flag_array; break;
    case GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING: array = &ctx.secondary_color_array; break;
    case GL_FOG_COORD_ARRAY_BUFFER_BINDING: array = &ctx.fog_coord_array; break;
    case GL_POINT_SIZE_ARRAY_BUFFER_BINDING_OES:
      if (!ctx.es1()) return false;
      array = &ctx.point_size_array;
      break;
    case GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING:
      array = &ctx.texture_units[ctx.client_active_texture].texcoord_array;
      break;
    default: return false;
  }
  name = buffer_name(array->buffer);
  return true;
}

}  // namespace pineda
