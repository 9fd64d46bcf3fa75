#include <cstdint>

#include "shader/jit/emit_library_ops.h"
#include "shader/jit/emit_series.h"
#include "shader/jit/lane_series.h"

namespace pineda::shader::jit {

namespace {

using lane_series::kPowSeries;

// The constants the logarithm path broadcasts, as lane_pow.inc spells them.
enum PowConstant { kLog2Series, kExp2Series = kLog2Series + 10, kDoubleOne = kExp2Series + 14, kShifter, kRangeHigh,
                   kRangeLow, kExponentBias, kLog2OfE, kPowConstants };
struct PowTable {
  double value[kPowConstants];
};
constexpr PowTable make_pow_table() {
  PowTable t{};
  for (int k = 0; k < 10; ++k) t.value[kLog2Series + k] = kPowSeries.log2[k];
  for (int k = 0; k < 14; ++k) t.value[kExp2Series + k] = kPowSeries.exp2[k];
  t.value[kDoubleOne] = 1.0;
  t.value[kShifter] = 6755399441055744.0;
  t.value[kRangeHigh] = 200.0;
  t.value[kRangeLow] = -200.0;
  t.value[kExponentBias] = __builtin_bit_cast(double, uint64_t{1023});
  t.value[kLog2OfE] = 1.44269504088896340735992468100189214;  // lane_exp's kLog2e
  return t;
}
alignas(64) constexpr PowTable kPowTable = make_pow_table();

constexpr uint32_t kMagnitudeMask = 0x7FFFFFFFu, kSignMask = 0x80000000u, kSmallestNormal = 0x00800000u,
                   kInfinity = 0x7F800000u, kQuietNan = 0x7FC00000u;

void broadcast32(X86Encoder& x, int d, uint32_t bits) {
  x.mov_imm32(rax, bits);
  x.vpbroadcastd(d, rax);
}

// Half `half` of the 16 lanes of v as 8 doubles in d: floats (`integers` false) or integers.
void widen_half(X86Encoder& x, int d, int v, int half, bool integers, int scratch) {
  int source = v;
  if (half == 1) {
    x.vextractf32x8(scratch, v, 1);
    source = scratch;
  }
  if (integers) x.vcvtdq2pd(d, source);
  else x.vcvtps2pd(d, source);
}

// pow_by_multiplying for lanes whose every running exponent is whole, |n| <= 256 (k1), then
// finish_power's reciprocal for negative ones: the powers into power[0] and power[1]; k3 the
// lanes of negative exponents, k4 of odd ones.
void powers_by_squaring(X86Encoder& x, const LibraryOpRegisters& r, const int power[2]) {
  const int* s = r.scratch;
  const int magnitude = s[0], ones = s[2], square[2] = {s[4], s[6]};
  // The lanes of other exponents take no bits: the loop ends at the highest bit of the others.
  x.vmovaps(magnitude, magnitude, 1, true);
  x.vcvttps2dq(s[1], r.y);
  x.vpmovd2m(3, s[1]);  // negative exponents: the reciprocal at the end
  broadcast32(x, ones, 1);
  x.vptestmd(4, s[1], ones);  // odd ones
  broadcast32(x, s[3], kMagnitudeMask);
  x.vpandd(s[3], r.x, s[3]);
  x.vcvtps2pd(square[0], s[3]);
  x.vextractf32x8(s[5], s[3], 1);
  x.vcvtps2pd(square[1], s[5]);
  x.mov_imm(rax, reinterpret_cast<uint64_t>(&kPowTable));
  emit_table_constant(x, power[0], kDoubleOne);
  x.vmovaps(power[1], power[0]);
  // lane_pow.inc's powers_by_squaring, a lane's multiplications masked to its set bits
  // (multiplying by 1 is exact, so skipping one is the same); squares past a lane's highest
  // bit are never used.
  const size_t loop = x.size();
  x.vptestmd(1, magnitude, ones);
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
  // (A division costs as much with its mask empty: skipped when no exponent is negative.)
  x.kortestw(3, 3);
  const size_t no_reciprocal = x.jump_if_zero();
  x.kshiftrw(2, 3, 8);
  x.mov_imm(rax, reinterpret_cast<uint64_t>(&kPowTable));
  emit_table_constant(x, s[4], kDoubleOne);
  x.vdivpd(power[0], s[4], power[0], 3);
  x.vdivpd(power[1], s[4], power[1], 2);
  x.patch_jump(no_reciprocal);
}

// exponent_range then exp2_in_double: out = 2^e for e in a double register (clobbered), with the
// table's address in rax; uses scratch[1] and [4] to [10].
void exp2_in_range(X86Encoder& x, const LibraryOpRegisters& r, int e, int out) {
  const int* s = r.scratch;
  const int t = s[1];
  // exponent_range: within [-200, 200], NaN as 0.
  emit_table_constant(x, s[5], kRangeHigh);
  x.vcmppd(5, e, s[5], Cmp::Gt);
  x.vmovapd(e, s[5], 5);
  emit_table_constant(x, s[5], kRangeLow);
  x.vcmppd(5, e, s[5], Cmp::Lt);
  x.vmovapd(e, s[5], 5);
  x.vcmppd(5, e, e, Cmp::Unord);
  x.vmovapd(e, r.zero, 5);
  // exp2_in_double: 2^e = 2^n 2^f.
  const int shifted = s[4], f = e, f2 = s[6], f4 = s[7], f8 = s[8];
  emit_table_constant(x, s[5], kShifter);
  x.vaddpd(shifted, e, s[5]);
  x.vsubpd(s[6], shifted, s[5]);
  x.vsubpd(f, e, s[6]);
  x.vmulpd(f2, f, f);
  x.vmulpd(f4, f2, f2);
  x.vmulpd(f8, f4, f4);
  const SeriesRegisters exp_series{f, f2, f4, s[9], s[10], s[5]};
  emit_eight_terms(x, exp_series, out, kExp2Series);
  emit_pair(x, exp_series, t, kExp2Series + 8);
  emit_pair(x, exp_series, s[10], kExp2Series + 10);
  x.vmulpd(s[10], s[10], f2);
  x.vaddpd(t, t, s[10]);
  emit_pair(x, exp_series, s[10], kExp2Series + 12);
  x.vmulpd(s[10], s[10], f4);
  x.vaddpd(t, t, s[10]);
  x.vmulpd(t, t, f8);
  x.vaddpd(out, out, t);
  emit_table_constant(x, s[5], kExponentBias);
  x.vpaddq(s[5], shifted, s[5]);
  x.vpsllq(s[5], s[5], 52);
  x.vmulpd(out, out, s[5]);
}

// pow_by_logarithm over every lane: 2^(y log2|x|) into power[0] and power[1].
void powers_by_logarithm(X86Encoder& x, const LibraryOpRegisters& r, const int power[2]) {
  const int* s = r.scratch;
  const int mantissa = s[0], exponent = s[2], t = s[1];
  // log2|x| = e + log2(m), m in [sqrt(1/2), sqrt(2)).
  broadcast32(x, s[3], kMagnitudeMask);
  x.vpandd(s[3], r.x, s[3]);
  broadcast32(x, t, 0x007FFFFFu);
  x.vpandd(mantissa, s[3], t);
  broadcast32(x, t, 0x3F800000u);
  x.vpord(mantissa, mantissa, t);
  broadcast32(x, t, 0x3FB504F3u);  // sqrt(2)
  x.vpcmpd(4, mantissa, t, IntCmp::Gt);
  broadcast32(x, t, 0x00800000u);
  x.vpsubd(mantissa, mantissa, t, 4);
  x.vpsrld(exponent, s[3], 23);
  broadcast32(x, t, 127);
  x.vpsubd(exponent, exponent, t);
  broadcast32(x, t, 1);
  x.vpaddd(exponent, exponent, t, 4);
  x.mov_imm(rax, reinterpret_cast<uint64_t>(&kPowTable));
  for (int half = 0; half < 2; ++half) {
    const int m = s[4], z = s[5], z2 = s[6], z4 = s[7], z8 = s[8], sum = s[3];
    widen_half(x, m, mantissa, half, false, s[5]);
    emit_table_constant(x, s[5], kDoubleOne);
    x.vsubpd(s[6], m, s[5]);
    x.vaddpd(s[7], m, s[5]);
    x.vdivpd(m, s[6], s[7]);  // s = (m - 1) / (m + 1)
    x.vmulpd(z, m, m);
    x.vmulpd(z2, z, z);
    x.vmulpd(z4, z2, z2);
    x.vmulpd(z8, z4, z4);
    const SeriesRegisters log_series{z, z2, z4, s[9], s[10], power[half]};
    emit_eight_terms(x, log_series, sum, kLog2Series);
    emit_pair(x, log_series, s[10], kLog2Series + 8);
    x.vmulpd(s[10], s[10], z8);
    x.vaddpd(sum, sum, s[10]);
    widen_half(x, s[5], exponent, half, true, s[6]);
    x.vmulpd(sum, m, sum);
    x.vaddpd(sum, s[5], sum);  // log2|x|
    widen_half(x, s[5], r.y, half, false, s[6]);
    const int e = sum;
    x.vmulpd(e, s[5], e);  // y log2|x|
    exp2_in_range(x, r, e, power[half]);
  }
}

// finish_power's rounding to float and flush below FLT_MIN, into the result; leaves scratch[1]
// the magnitude mask and scratch[2] FLT_MIN's bits.
void round_powers(X86Encoder& x, const LibraryOpRegisters& r, const int power[2]) {
  const int* s = r.scratch;
  x.vcvtpd2ps(r.result, power[0]);
  x.vcvtpd2ps(s[1], power[1]);
  x.vinsertf32x8(r.result, r.result, s[1], 1);
  broadcast32(x, s[1], kMagnitudeMask);
  broadcast32(x, s[2], kSmallestNormal);
  x.vpandd(s[3], r.result, s[1]);
  x.vpcmpd(1, s[3], s[2], IntCmp::Ge);
  x.vmovaps(r.result, r.result, 1, true);
}

// Zero (or denormal) x: 0, or inf for a negative exponent (mask register `negative`); infinite
// x: the other way round. Leaves the zero x lanes in mask register `zero`, the infinite ones in
// `infinite` (which may be `zero`: then the infinite ones); `pick` is clobbered.
void pick_zero_and_infinite_x(X86Encoder& x, const LibraryOpRegisters& r, int xa, int smallest, int infinity,
                              int negative, int zero, int infinite, int pick) {
  x.vpcmpd(zero, xa, smallest, IntCmp::Lt);
  x.kandnw(pick, negative, zero);
  x.vmovaps(r.result, r.zero, pick);
  x.kandw(pick, negative, zero);
  x.vmovaps(r.result, infinity, pick);
  x.vpcmpd(infinite, xa, infinity, IntCmp::Eq);
  x.kandnw(pick, negative, infinite);
  x.vmovaps(r.result, infinity, pick);
  x.kandw(pick, negative, infinite);
  x.vmovaps(r.result, r.zero, pick);
}

// lane_pow's special values for lanes whose exponents are whole and at most 256 in magnitude
// (negative ones in k3, odd ones in k4), after round_powers: what remains of its sequence there.
void finish_whole_powers(X86Encoder& x, const LibraryOpRegisters& r) {
  const int* s = r.scratch;
  const int abs_bits = s[1], smallest = s[2], xa = s[3], infinity = s[4], t = s[5];
  x.vpandd(xa, r.x, abs_bits);
  broadcast32(x, infinity, kInfinity);
  pick_zero_and_infinite_x(x, r, xa, smallest, infinity, 3, 1, 1, 2);
  x.vpmovd2m(1, r.x);  // a negative x to an odd power is negative
  x.kandw(1, 1, 4);
  broadcast32(x, t, kSignMask);
  x.vpxord(r.result, r.result, t, 1);
  x.vpcmpd(1, xa, infinity, IntCmp::Gt);  // NaN x: NaN
  broadcast32(x, t, kQuietNan);
  x.vmovaps(r.result, t, 1);
  // x exactly 1, or y zero (or denormal): 1.
  x.vpcmpd(1, r.x, r.one, IntCmp::Eq);
  x.vpandd(t, r.y, abs_bits);
  x.vpcmpd(2, t, smallest, IntCmp::Lt);
  x.korw(1, 1, 2);
  x.vmovaps(r.result, r.one, 1);
}

// lane_pow's special values in its order, for any exponents, after round_powers.
void finish_powers(X86Encoder& x, const LibraryOpRegisters& r) {
  const int* s = r.scratch;
  const int abs_bits = s[1], smallest = s[2], xa = s[3], ya = s[4], whole = s[5], infinity = s[6], t = s[7];

  x.vpandd(ya, r.y, abs_bits);
  x.vpandd(xa, r.x, abs_bits);
  broadcast32(x, t, 0x4B800000u);  // 2^24
  x.vpcmpd(1, ya, t, IntCmp::Lt);  // small
  x.vpcmpd(3, ya, t, IntCmp::Ge);
  x.vcvttps2dq(whole, r.y, 1, true);
  x.vcvtdq2ps(t, whole);
  x.vcmpps(2, t, r.y, Cmp::Eq);
  x.korw(2, 2, 3);  // integer
  broadcast32(x, t, 1);
  x.vptestmd(4, whole, t, 1);
  x.kandw(4, 4, 2);  // odd
  x.vpmovd2m(5, r.y);
  x.vptestmd(6, ya, ya);
  x.kandw(5, 5, 6);  // y negative
  broadcast32(x, infinity, kInfinity);
  pick_zero_and_infinite_x(x, r, xa, smallest, infinity, 5, 1, 3, 6);
  // A negative x to an odd power is negative.
  x.vpmovd2m(6, r.x);
  x.kandw(4, 6, 4);
  broadcast32(x, t, kSignMask);
  x.vpxord(r.result, r.result, t, 4);
  // NaN: a negative finite x to a power that is not whole, and NaN x or y.
  x.kandnw(6, 1, 6);
  x.kandnw(6, 3, 6);
  x.kandnw(6, 2, 6);
  x.vpcmpd(1, xa, infinity, IntCmp::Gt);
  x.korw(6, 6, 1);
  x.vpcmpd(1, ya, infinity, IntCmp::Gt);
  x.korw(6, 6, 1);
  broadcast32(x, t, kQuietNan);
  x.vmovaps(r.result, t, 6);
  // 1: x exactly 1, |x| 1 to an infinite power, or y zero (or denormal).
  x.vpcmpd(1, r.x, r.one, IntCmp::Eq);
  x.vpcmpd(3, xa, r.one, IntCmp::Eq);
  x.vpcmpd(3, ya, infinity, IntCmp::Eq, 3);
  x.korw(1, 1, 3);
  x.vpcmpd(3, ya, smallest, IntCmp::Lt);
  x.korw(1, 1, 3);
  x.vmovaps(r.result, r.one, 1);
}

}  // namespace

size_t emit_pow(X86Encoder& x, const LibraryOpRegisters& r) {
  const int* s = r.scratch;
  const int magnitude = s[0], t = s[1];
  // k1: lane_pow.inc's `multiplied` lanes, whole y of magnitude at most 256: y converts to an
  // integer and back unchanged (NaN and |y| >= 2^31 do not: those give 0x80000000, whose
  // unsigned magnitude is past 256 anyway).
  x.vcvttps2dq(magnitude, r.y);
  x.vcvtdq2ps(t, magnitude);
  x.vcmpps(1, t, r.y, Cmp::Eq);
  x.vpabsd(magnitude, magnitude);
  broadcast32(x, t, 256);
  x.vpcmpud(1, magnitude, t, IntCmp::Le, 1);
  // Running lanes of both ways call out; of one way, take that way.
  x.kandnw(2, 1, r.running_mask);
  x.kandw(3, 1, r.running_mask);
  const int power[2] = {s[11], s[12]};
  x.kortestw(2, 2);
  const size_t all_multiplied = x.jump_if_zero();
  x.kortestw(3, 3);
  const size_t mixed = x.jump_if_not_zero();
  powers_by_logarithm(x, r, power);
  round_powers(x, r, power);
  finish_powers(x, r);
  const size_t done = x.jump();
  x.patch_jump(all_multiplied);
  powers_by_squaring(x, r, power);
  round_powers(x, r, power);
  finish_whole_powers(x, r);
  x.patch_jump(done);
  return mixed;
}

size_t emit_exp(X86Encoder& x, const LibraryOpRegisters& r, bool natural) {
  const int* s = r.scratch;
  const int power[2] = {s[11], s[12]};
  x.mov_imm(rax, reinterpret_cast<uint64_t>(&kPowTable));
  for (int half = 0; half < 2; ++half) {
    widen_half(x, s[3], r.x, half, false, s[6]);
    if (natural) {
      emit_table_constant(x, s[5], kLog2OfE);
      x.vmulpd(s[3], s[3], s[5]);
    }
    exp2_in_range(x, r, s[3], power[half]);
  }
  round_powers(x, r, power);  // exp_magnitude's rounding and flush are finish_power's
  x.vcmpps(1, r.x, r.x, Cmp::Unord);  // NaN: x itself
  x.vmovaps(r.result, r.x, 1);
  return 0;
}

}  // namespace pineda::shader::jit
