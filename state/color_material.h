// GL_COLOR_MATERIAL: the material properties that follow the current colour.
#pragma once

namespace pineda {

class Context;

// GL 1.1 spec 2.13.3: while COLOR_MATERIAL is enabled, the selected material properties take
// the current colour whenever it changes (and when tracking starts); they keep it afterwards.
// Call after the current colour, the enable or glColorMaterial changed.
void track_color_material(Context& ctx);

}  // namespace pineda
