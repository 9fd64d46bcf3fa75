// glEvalCoord: a vertex from the enabled maps (GL 1.1 section 5.1).
#pragma once

namespace pineda {

class Context;

// As glVertex with the enabled maps' values in place of the current colour, normal and
// texture coordinates of unit 0 (the current values do not change). Nothing happens when
// neither vertex map of the dimension is enabled; outside glBegin/glEnd, as for glVertex.
void eval_coord1(Context& ctx, double u);
void eval_coord2(Context& ctx, double u, double v);

}  // namespace pineda
