#include "state/color_material.h"

#include "state/context.h"

namespace pineda {

void track_color_material(Context& ctx) {
  const raster::ColorMaterial& cm = ctx.lighting.color_material;
  if (!cm.enabled) return;
  const glm::vec4 color(ctx.current_color[0], ctx.current_color[1], ctx.current_color[2], ctx.current_color[3]);
  for (raster::Material* m : {&ctx.lighting.front, &ctx.lighting.back}) {
    if (!(m == &ctx.lighting.front ? cm.front : cm.back)) continue;
    if (cm.ambient) m->ambient = color;
    if (cm.diffuse) m->diffuse = color;
    if (cm.specular) m->specular = color;
    if (cm.emission) m->emission = color;
  }
}

}  // namespace pineda
