// Library functions in compiled code for the lanes where they take the interpreter's vector path,
// with its operations in its order, so that every lane gets the interpreter's bits: pow with
// whole exponents up to 256 (a shininess or another uniform exponent: the common case;
// lane_pow.inc's squaring path) and sin, cos of |x| < 2^17 (lane_sin_cos.inc's reduction and
// series). Each comes as a test that jumps to the call-out when a running lane needs another way,
// and the code for the block otherwise.
#pragma once
#include <cstddef>

#include "shader/jit/x86_encoder.h"

namespace pineda::shader::jit {

// The zmm registers of one operation: its operands, scratch registers and the result (all
// different but for x and y, which may be one), the fixed 1.0f and 0 registers, and the mask
// register of the running lanes. Mask registers k1-k5 and rax are clobbered.
constexpr int kLibraryScratch = 11;
struct LibraryOpRegisters {
  int x, y;
  int scratch[kLibraryScratch];
  int result;
  int one, zero, running_mask;
};

// The scratch registers each operation uses (scratch[0] to scratch[n - 1]).
constexpr int kPowScratch = 5, kSinCosScratch = 11;

// Jumps (the returned site, for X86Encoder::patch_jump) when a running lane's y is not a whole
// number of magnitude at most 256 (lane_pow.inc's `multiplied` lanes); else falls through with
// k1 = those lanes and scratch[0] = their exponents' magnitudes.
size_t emit_pow_needs_call_out(X86Encoder& x, const LibraryOpRegisters& r);
// After emit_pow_needs_call_out falls through: result = pow(x, y) in every `multiplied` lane
// (others: any value).
void emit_pow_of_whole_exponents(X86Encoder& x, const LibraryOpRegisters& r);

// Jumps when a running lane's |x| is 2^17 or more, infinite or NaN (the lanes lane_sin_cos
// leaves to C's sin and cos).
size_t emit_sin_cos_needs_call_out(X86Encoder& x, const LibraryOpRegisters& r);
// result = sin(x) (cos(x) when `cosine`) in every lane of |x| < 2^17.
void emit_sin_cos_reduced(X86Encoder& x, const LibraryOpRegisters& r, bool cosine);

}  // namespace pineda::shader::jit
