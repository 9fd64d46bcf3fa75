// glGenVertexArrays, glDeleteVertexArrays, glBindVertexArray, glIsVertexArray
// (GL_ARB_vertex_array_object; GL_OES_vertex_array_object's names are the same functions).
#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/vertex_arrays/vertex_array_object.h"

namespace pineda {

VertexArrayGroup save_vertex_array_group(const Context& ctx) {
  VertexArrayGroup g;
  g.vertex_array = ctx.vertex_array;
  g.color_array = ctx.color_array;
  g.normal_array = ctx.normal_array;
  for (int u = 0; u < raster::kMaxTextureUnits; ++u) g.texcoord_arrays[u] = ctx.texture_units[u].texcoord_array;
  g.edge_flag_array = ctx.edge_flag_array;
  g.fog_coord_array = ctx.fog_coord_array;
  g.secondary_color_array = ctx.secondary_color_array;
  g.index_array = ctx.index_array;
  g.point_size_array = ctx.point_size_array;
  g.generic_arrays = ctx.programs.arrays;
  g.element_array_buffer = ctx.buffers.element_array;
  return g;
}

void load_vertex_array_group(Context& ctx, const VertexArrayGroup& g) {
  ctx.vertex_array = g.vertex_array;
  ctx.color_array = g.color_array;
  ctx.normal_array = g.normal_array;
  for (int u = 0; u < raster::kMaxTextureUnits; ++u) ctx.texture_units[u].texcoord_array = g.texcoord_arrays[u];
  ctx.edge_flag_array = g.edge_flag_array;
  ctx.fog_coord_array = g.fog_coord_array;
  ctx.secondary_color_array = g.secondary_color_array;
  ctx.index_array = g.index_array;
  ctx.point_size_array = g.point_size_array;
  ctx.programs.arrays = g.generic_arrays;
  ctx.buffers.element_array = g.element_array_buffer;
}

void bind_vertex_array_object(Context& ctx, GLuint name) {
  VertexArrayObjects& vaos = ctx.vertex_array_objects;
  if (name == vaos.bound) return;
  // The object (or object 0) left keeps the current arrays.
  if (vaos.bound == 0) vaos.default_group = save_vertex_array_group(ctx);
  else if (std::shared_ptr<VertexArrayObject> old = vaos.names.find(vaos.bound)) old->group = save_vertex_array_group(ctx);
  if (name == 0) {
    load_vertex_array_group(ctx, vaos.default_group);
    vaos.default_group = VertexArrayGroup{};  // no second reference to its buffers while bound
  } else {
    const std::shared_ptr<VertexArrayObject>& object = vaos.names.get_or_create(name);  // created at its first bind
    load_vertex_array_group(ctx, object->group);
    object->group = VertexArrayGroup{};
  }
  vaos.bound = name;
}

}  // namespace pineda

namespace pineda::gl {

void GenVertexArrays(Context& ctx, GLsizei n, GLuint* arrays) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (arrays) ctx.vertex_array_objects.names.generate(n, arrays);
}

void DeleteVertexArrays(Context& ctx, GLsizei n, const GLuint* arrays) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (!arrays) return;
  VertexArrayObjects& vaos = ctx.vertex_array_objects;
  for (GLsizei i = 0; i < n; ++i) {
    // Zero and names that are not vertex array objects are silently ignored; deleting the bound
    // object binds object 0 (GL 3.0 2.10).
    if (arrays[i] == 0 || !vaos.names.generated(arrays[i])) continue;
    if (arrays[i] == vaos.bound) bind_vertex_array_object(ctx, 0);
    vaos.names.remove(arrays[i]);
    ctx.debug.forget_label(GL_VERTEX_ARRAY, arrays[i]);
  }
}

void BindVertexArray(Context& ctx, GLuint array) {
  if (array != 0 && !ctx.vertex_array_objects.names.generated(array))
    return ctx.record_error(GL_INVALID_OPERATION, "array is not a name returned by glGenVertexArrays (or it was deleted)");
  bind_vertex_array_object(ctx, array);
}

GLboolean IsVertexArray(Context& ctx, GLuint array) {
  return array != 0 && ctx.vertex_array_objects.names.exists(array) ? GL_TRUE : GL_FALSE;
}

}  // namespace pineda::gl
