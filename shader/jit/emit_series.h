// The double-precision series of the library emitters (emit_pow.cpp, emit_sin_cos.cpp):
// coefficients broadcast from a table of doubles whose address is in rax, and Estrin's steps
// in the order lane_pow.inc and lane_sin_cos.inc write them (the same operations, so the same
// bits as the interpreter's).
#pragma once

#include "shader/jit/x86_encoder.h"

namespace pineda::shader::jit {

// z, z^2 and z^4 of the series' variable; t, u and p scratch.
struct SeriesRegisters {
  int z, z2, z4, t, u, p;
};

inline void emit_table_constant(X86Encoder& x, int reg, int index) { x.broadcast64(reg, {rax, 8 * index}); }

// d = c[first] + c[first + 1] z (uses t).
inline void emit_pair(X86Encoder& x, const SeriesRegisters& r, int d, int first) {
  emit_table_constant(x, r.t, first + 1);
  x.vmulpd(r.t, r.t, r.z);
  emit_table_constant(x, d, first);
  x.vaddpd(d, d, r.t);
}

// d = ((c0 + c1 z) + (c2 + c3 z) z2) + ((c4 + c5 z) + (c6 + c7 z) z2) z4, c from `first`
// (uses t, u and p).
inline void emit_eight_terms(X86Encoder& x, const SeriesRegisters& r, int d, int first) {
  emit_pair(x, r, d, first);
  emit_pair(x, r, r.u, first + 2);
  x.vmulpd(r.u, r.u, r.z2);
  x.vaddpd(d, d, r.u);
  emit_pair(x, r, r.p, first + 4);
  emit_pair(x, r, r.u, first + 6);
  x.vmulpd(r.u, r.u, r.z2);
  x.vaddpd(r.p, r.p, r.u);
  x.vmulpd(r.p, r.p, r.z4);
  x.vaddpd(d, d, r.p);
}

}  // namespace pineda::shader::jit
