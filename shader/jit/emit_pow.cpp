#include "shader/jit/emit_library_ops.h"

#include <cstdint>

namespace pineda::shader::jit {

namespace {

constexpr uint64_t kDoubleOneBits = 0x3FF0000000000000u;
constexpr uint32_t kMagnitudeMask = 0x7FFFFFFFu, kSignMask = 0x80000000u, kSmallestNormal = 0x00800000u,
                   kInfinity = 0x7F800000u, kQuietNan = 0x7FC00000u;

void broadcast32(X86Encoder& x, int d, uint32_t bits) {
  x.mov_imm32(rax, bits);
  x.vpbroadcastd(d, rax);
}

}  // namespace

size_t emit_pow_needs_call_out(X86Encoder& x, const LibraryOpRegisters& r) {
  const int magnitude = r.scratch[0], t = r.scratch[1];
  // Whole: y converts to an integer and back unchanged (NaN and |y| >= 2^31 do not: those give
  // 0x80000000, whose unsigned magnitude is past 256 anyway).
  x.vcvttps2dq(magnitude, r.y);
  x.vcvtdq2ps(t, magnitude);
  x.vcmpps(1, t, r.y, Cmp::Eq);
  x.vpabsd(magnitude, magnitude);
  broadcast32(x, t, 256);
  x.vpcmpud(1, magnitude, t, IntCmp::Le, 1);
  x.kandnw(2, 1, r.running_mask);
  x.kortestw(2, 2);
  return x.jump_if_not_zero();
}

void emit_pow_of_whole_exponents(X86Encoder& x, const LibraryOpRegisters& r) {
  const int magnitude = r.scratch[0];
  const int square[2] = {r.scratch[1], r.scratch[2]}, power[2] = {r.scratch[3], r.scratch[4]};
  // The lanes of other exponents take no bits: the loop ends at the highest bit of the others.
  x.vmovaps(magnitude, magnitude, 1, true);
  // k3: negative exponents (a reciprocal at the end); k4: odd ones.
  x.vcvttps2dq(square[0], r.y);
  x.vpmovd2m(3, square[0]);
  broadcast32(x, r.result, 1);  // integer 1s while the loop runs
  x.vptestmd(4, square[0], r.result);

  // |x| in double, as two halves of 8 lanes; the powers start at 1.
  broadcast32(x, power[0], kMagnitudeMask);
  x.vpandd(power[0], r.x, power[0]);
  x.vcvtps2pd(square[0], power[0]);
  x.vextractf32x8(power[1], power[0], 1);
  x.vcvtps2pd(square[1], power[1]);
  x.mov_imm(rax, kDoubleOneBits);
  x.vpbroadcastq(power[0], rax);
  x.vmovaps(power[1], power[0]);

  // lane_pow.inc's powers_by_squaring, a lane's multiplications masked to its set bits
  // (multiplying by 1 is exact, so skipping one is the same); squares past a lane's highest
  // bit are never used.
  const size_t loop = x.size();
  x.vptestmd(1, magnitude, r.result);
  x.kshiftrw(2, 1, 8);
  x.vmulpd(power[0], power[0], square[0], 1);
  x.vmulpd(power[1], power[1], square[1], 2);
  x.vpsrld(magnitude, magnitude, 1);
  x.vptestmd(1, magnitude, magnitude);
  x.kortestw(1, 1);
  const size_t done = x.jump_if_zero();
  x.vmulpd(square[0], square[0], square[0]);
  x.vmulpd(square[1], square[1], square[1]);
  x.jump_back(loop);
  x.patch_jump(done);

  // finish_power: the reciprocal for negative exponents, rounding to float once, zero below
  // FLT_MIN.
  // (A division costs as much with its mask empty: skipped when no exponent is negative.)
  x.kortestw(3, 3);
  const size_t no_reciprocal = x.jump_if_zero();
  x.kshiftrw(2, 3, 8);
  x.mov_imm(rax, kDoubleOneBits);
  x.vpbroadcastq(square[0], rax);
  x.vdivpd(power[0], square[0], power[0], 3);
  x.vdivpd(power[1], square[0], power[1], 2);
  x.patch_jump(no_reciprocal);
  x.vcvtpd2ps(r.result, power[0]);
  x.vcvtpd2ps(square[0], power[1]);
  x.vinsertf32x8(r.result, r.result, square[0], 1);
  const int abs_bits = square[1], smallest = power[1], magnitude_bits = power[0], infinity = square[0];
  broadcast32(x, abs_bits, kMagnitudeMask);
  broadcast32(x, smallest, kSmallestNormal);
  x.vpandd(magnitude_bits, r.result, abs_bits);
  x.vpcmpd(1, magnitude_bits, smallest, IntCmp::Ge);
  x.vmovaps(r.result, r.result, 1, true);

  // lane_pow's special values, in its order. Zero (or denormal) x: 0, or inf for a negative
  // exponent; infinite x: the other way round.
  x.vpandd(magnitude_bits, r.x, abs_bits);
  broadcast32(x, infinity, kInfinity);
  x.vpcmpd(1, magnitude_bits, smallest, IntCmp::Lt);
  x.kandnw(2, 3, 1);
  x.vmovaps(r.result, r.zero, 2);
  x.kandw(2, 3, 1);
  x.vmovaps(r.result, infinity, 2);
  x.vpcmpd(1, magnitude_bits, infinity, IntCmp::Eq);
  x.kandnw(2, 3, 1);
  x.vmovaps(r.result, infinity, 2);
  x.kandw(2, 3, 1);
  x.vmovaps(r.result, r.zero, 2);
  // A negative x to an odd power is negative.
  x.vpmovd2m(1, r.x);
  x.kandw(1, 1, 4);
  broadcast32(x, magnitude, kSignMask);
  x.vpxord(r.result, r.result, magnitude, 1);
  // NaN x: NaN.
  x.vpcmpd(1, magnitude_bits, infinity, IntCmp::Gt);
  broadcast32(x, magnitude, kQuietNan);
  x.vmovaps(r.result, magnitude, 1);
  // x exactly 1, or y zero (or denormal): 1.
  x.vpcmpd(1, r.x, r.one, IntCmp::Eq);
  x.vpandd(magnitude_bits, r.y, abs_bits);
  x.vpcmpd(2, magnitude_bits, smallest, IntCmp::Lt);
  x.korw(1, 1, 2);
  x.vmovaps(r.result, r.one, 1);
}

}  // namespace pineda::shader::jit
