// The vertices of a draw of array elements, as draw_array_vertices takes them.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "state/context.h"
#include "state/draw.h"
#include "state/vertex_arrays/vertex_fetch.h"

namespace pineda {

// The vertices of array elements index_of(i), i < count.
template <typename IndexOf>
ArrayVertices array_elements(Context& ctx, size_t count, IndexOf index_of) {
  const auto elements = [index_of](size_t begin, size_t end, uint32_t* out) {
    for (size_t i = begin; i < end; ++i) out[i - begin] = static_cast<uint32_t>(std::min<size_t>(index_of(i), UINT32_MAX - 1));
  };
  if (vertex_shader_reads_generic_attributes_only(ctx)) {
    return {count,
            [&ctx, index_of](size_t begin, size_t end, raster::VertexInput* out) {
              for (size_t i = begin; i < end; ++i) fetch_vertex_source(ctx, index_of(i), out[i - begin]);
            },
            elements};
  }
  if (const StateKey key = ctx.state_key(); key != ctx.vertex_fetch_planned) {
    ctx.vertex_fetch_plan.build(ctx);
    ctx.vertex_fetch_planned = key;
  }
  return {count,
          [&plan = ctx.vertex_fetch_plan, index_of](size_t begin, size_t end, raster::VertexInput* out) {
            for (size_t i = begin; i < end; ++i) plan.fetch(index_of(i), out[i - begin]);
          },
          elements};
}

}  // namespace pineda
