// Library functions in compiled code with the operations of the interpreter's vector routines
// in their order, so that every lane gets the interpreter's bits: pow (lane_pow.inc: squaring
// for whole exponents up to 256, 2^(y log2|x|) in double otherwise, then its special values)
// exp and exp2 (lane_exp, pow's second half), and sin, cos of |x| < 2^17 (lane_sin_cos.inc's
// reduction and series). Each emitter returns the site of a jump (for X86Encoder::patch_jump)
// taken when a running lane needs what it leaves to the call-out, or 0 when it leaves nothing:
// pow a block whose running lanes need both of its ways, sin and cos an |x| of 2^17 or more,
// inf or NaN; otherwise the code falls through with the result.
#pragma once
#include <cstddef>

#include "shader/jit/x86_encoder.h"

namespace pineda::shader::jit {

// The zmm registers of one operation: its operands, scratch registers and the result (all
// different but for x and y, which may be one), the fixed 1.0f and 0 registers, and the mask
// register of the running lanes. Mask registers k1-k6 and rax are clobbered.
constexpr int kLibraryScratch = 13;
struct LibraryOpRegisters {
  int x, y;
  int scratch[kLibraryScratch];
  int result;
  int one, zero, running_mask;
};

// The scratch registers each operation uses (scratch[0] to scratch[n - 1]).
constexpr int kPowScratch = 13, kExpScratch = 13, kSinCosScratch = 11;

size_t emit_pow(X86Encoder& x, const LibraryOpRegisters& r);
size_t emit_exp(X86Encoder& x, const LibraryOpRegisters& r, bool natural);  // e^x, or 2^x
size_t emit_sin_cos(X86Encoder& x, const LibraryOpRegisters& r, bool cosine);

}  // namespace pineda::shader::jit
