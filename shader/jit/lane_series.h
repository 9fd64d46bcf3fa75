// The interpreter's library routines (lane_pow.inc, lane_sin_cos.inc), once per translation
// unit: the library emitters read their series' coefficients from them.
#pragma once
#include <cstdint>

namespace pineda::shader::jit::lane_series {
#include "shader/lane_pow.inc"
#include "shader/lane_sin_cos.inc"
}  // namespace pineda::shader::jit::lane_series
