// Texture lookups as early as their operands allow: each lookup moves up its stretch of
// straight-line code to just after what it reads, so the lookups of a filter kernel end up side
// by side. Compiled code calls out for every lookup; side by side, the calls' memory reads
// (gathers) overlap instead of each one waiting behind the arithmetic that used the last.
#pragma once
#include "shader/ir.h"

namespace pineda::shader {

// First the arithmetic whose result a later lookup of its stretch reads, directly or through
// other such arithmetic (it may rise above lookups), then every texture lookup, each moves above
// the instructions before it that neither write what it reads nor read or write what it writes,
// stopping at structure (branches, loops, discard), dynamic register indexing and the previous
// one of its kind (so both keep their order). Values are unchanged: a lookup depends only on its
// operands and the lanes that run, which do not change within a stretch. Then each lookup moves
// down to just before the next lookup of its stretch when nothing between them depends on it or
// it on them, so that the stretch's lookups stand side by side (compiled code calls out once for
// such a run). Returns whether anything moved.
bool move_texture_lookups_early(ir::Code& code);

}  // namespace pineda::shader
