#include "state/vertex_arrays/vertex_fetch_plan.h"

#include <algorithm>
#include <cstddef>
#include <cstring>

#include "state/context.h"
#include "state/programs/generic_attribs.h"
#include "state/vertex_arrays/vertex_fetch.h"

namespace pineda {

void VertexFetchPlan::add(const ClientArray& array, bool normalize, size_t field, bool edge_flag) {
  Read& r = reads_[read_count_++];
  r.type = array.type;
  r.size = array.size;
  r.normalize = normalize;
  r.field = field;
  r.edge_flag = edge_flag;
  const size_t bytes = size_t(gl_type_size(array.type)) * size_t(std::max(array.size, 0));
  r.stride = array.stride ? size_t(array.stride) : bytes;
  if (!array.buffer) {
    r.first = static_cast<const uint8_t*>(array.pointer);
    r.count = SIZE_MAX;
  } else {
    const size_t total = array.buffer->data.size(), offset = reinterpret_cast<uintptr_t>(array.pointer);
    r.first = array.buffer->data.data() + std::min(offset, total);
    r.count = elements_inside(*array.buffer, offset, r.stride, bytes);  // array_element's test
  }
}

void VertexFetchPlan::build(const Context& ctx) {
  read_count_ = 0;
  values_ = raster::VertexInput{};
  raster::VertexInput& v = values_;
  generic_position_ = ctx.programs.arrays[0].active() ? &ctx : nullptr;
  if (!generic_position_) {
    if (ctx.vertex_array.active())
      add(ctx.vertex_array, false, offsetof(raster::VertexInput, position));
    else if (ctx.es2())
      std::copy(ctx.programs.current_attrib[0].begin(), ctx.programs.current_attrib[0].end(), v.position);
  }
  if (ctx.color_array.active()) add(ctx.color_array, true, offsetof(raster::VertexInput, color));
  else std::copy(ctx.current_color, ctx.current_color + 4, v.color);
  if (ctx.normal_array.active()) add(ctx.normal_array, true, offsetof(raster::VertexInput, normal));
  else std::copy(ctx.current_normal, ctx.current_normal + 3, v.normal);
  for (int u = 0; u < raster::kMaxTextureUnits; ++u) {
    const TextureUnitState& unit = ctx.texture_units[u];
    if (unit.texcoord_array.active()) {
      v.texcoord[u][3] = 1.f;
      add(unit.texcoord_array, false, offsetof(raster::VertexInput, texcoord) + sizeof(float[4]) * size_t(u));
    } else {
      std::copy(unit.current_texcoord, unit.current_texcoord + 4, v.texcoord[u]);
    }
  }
  if (ctx.secondary_color_array.active())
    add(ctx.secondary_color_array, true, offsetof(raster::VertexInput, secondary_color));
  else
    std::copy(ctx.extras.current_secondary_color, ctx.extras.current_secondary_color + 3, v.secondary_color);
  if (ctx.point_size_array.active()) add(ctx.point_size_array, false, offsetof(raster::VertexInput, point_size));
  if (ctx.fog_coord_array.active()) add(ctx.fog_coord_array, false, offsetof(raster::VertexInput, fog_coord));
  else v.fog_coord = ctx.extras.current_fog_coord;
  v.edge_flag = ctx.current_edge_flag;
  if (ctx.edge_flag_array.active()) {
    ClientArray edge_flags = ctx.edge_flag_array;  // one GLboolean an element
    edge_flags.size = 1;
    edge_flags.type = GL_UNSIGNED_BYTE;
    add(edge_flags, false, offsetof(raster::VertexInput, edge_flag), true);
  }
}

void VertexFetchPlan::fetch(size_t index, raster::VertexInput& out) const {
  std::memcpy(static_cast<void*>(&out), &values_, sizeof out);
  out.source = static_cast<uint32_t>(std::min<size_t>(index, UINT32_MAX - 1));
  if (generic_position_) read_generic_position(*generic_position_, index, out.position);
  for (int i = 0; i < read_count_; ++i) {
    const Read& r = reads_[i];
    if (index >= r.count) continue;  // outside the buffer: the field keeps its value
    const uint8_t* p = r.first + r.stride * index;
    if (r.edge_flag) out.edge_flag = *p != GL_FALSE;
    else read_components(p, r.type, r.size, r.normalize, reinterpret_cast<float*>(reinterpret_cast<unsigned char*>(&out) + r.field));
  }
}

}  // namespace pineda
