// pow(x, y) in compiled code for the lanes whose y is a whole number of magnitude at most 256
// (a shininess or another uniform exponent: the common case), with the operations of
// lane_pow.inc's squaring path in its order, so that every lane gets the interpreter's bits.
// Any other exponent in a running lane leaves the block to the call-out.
#pragma once
#include <cstddef>

#include "shader/jit/x86_encoder.h"

namespace pineda::shader::jit {

// The zmm registers of one pow: its operands, five scratch registers and the result (all
// different but for x and y, which may be one), the fixed 1.0f and 0 registers, and the mask
// register of the running lanes. Mask registers k1-k5 are clobbered.
struct PowRegisters {
  int x, y;
  int scratch[5];
  int result;
  int one, zero, running_mask;
};

// Jumps (the returned site, for X86Encoder::patch_jump) when a running lane's y is not a whole
// number of magnitude at most 256 (lane_pow.inc's `multiplied` lanes); else falls through with
// k1 = those lanes and scratch[0] = their exponents' magnitudes.
size_t emit_pow_needs_call_out(X86Encoder& x, const PowRegisters& r);

// After emit_pow_needs_call_out falls through: result = pow(x, y) in every lane that is
// `multiplied` (others: any value).
void emit_pow_of_whole_exponents(X86Encoder& x, const PowRegisters& r);

}  // namespace pineda::shader::jit
