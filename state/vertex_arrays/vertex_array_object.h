// Vertex array objects (GL_ARB_vertex_array_object, GL 3.0 2.10; GL_OES_vertex_array_object):
// per-context objects holding the vertex-array state of GL 2.1 tables 6.6-6.9 except
// ARRAY_BUFFER_BINDING and CLIENT_ACTIVE_TEXTURE. The context's arrays (Context::vertex_array,
// ..., ctx.programs.arrays, ctx.buffers.element_array) are always those of the bound object, so
// every draw path, query and glPushClientAttrib sees them; binding another object stores them
// into the one left and loads the new one's.
#pragma once
#include <GL/gl.h>

#include <array>
#include <memory>

#include "raster/texture.h"
#include "state/buffers/buffer_object.h"
#include "state/object_names.h"
#include "state/programs/program_state.h"
#include "state/vertex_arrays/client_array.h"

namespace pineda {

class Context;

// What a vertex array object holds; default-constructed: the initial state.
struct VertexArrayGroup {
  ClientArray vertex_array, color_array, normal_array;
  std::array<ClientArray, raster::kMaxTextureUnits> texcoord_arrays;
  ClientArray edge_flag_array = initial_array(1, GL_UNSIGNED_BYTE);
  ClientArray fog_coord_array = initial_array(1), secondary_color_array = initial_array(3);
  ClientArray index_array = initial_array(1);
  ClientArray point_size_array = initial_array(1);  // OpenGL ES 1.1 only (which has no objects)
  std::array<GenericArray, kMaxVertexAttribs> generic_arrays;
  std::shared_ptr<BufferObject> element_array_buffer;
};

struct VertexArrayObject {
  explicit VertexArrayObject(GLuint n) : name(n) {}
  GLuint name;
  VertexArrayGroup group;  // the arrays while the object is not bound
};

struct VertexArrayObjects {
  // Generated names; an object is created at its first bind (only then IsVertexArray is true).
  ObjectNames<VertexArrayObject> names;
  GLuint bound = 0;  // VERTEX_ARRAY_BINDING
  VertexArrayGroup default_group;  // object 0's arrays while another is bound
};

// The context's current arrays, copied out, and loaded back.
VertexArrayGroup save_vertex_array_group(const Context& ctx);
void load_vertex_array_group(Context& ctx, const VertexArrayGroup& group);
// Makes `name` (0, or a generated name) the bound vertex array object.
void bind_vertex_array_object(Context& ctx, GLuint name);

}  // namespace pineda
