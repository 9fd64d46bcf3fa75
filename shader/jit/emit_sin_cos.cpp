#include <cstdint>

#include "shader/jit/emit_library_ops.h"
#include "shader/jit/emit_series.h"
#include "shader/jit/lane_series.h"

namespace pineda::shader::jit {

namespace {

using lane_series::kSinCosSeries;

// The constants the code broadcasts, as lane_sin_cos.inc's sin_cos_reduced spells them.
enum SinCosConstant { kTwoOverPi, kRoundingShifter, kHalfPi1, kHalfPi2, kHalfPi3, kSin0, kCos0 = kSin0 + 9, kIntegerOne = kCos0 + 10,
                      kIntegerTwo, kSignBit64, kSinCosConstants };
struct SinCosTable {
  double value[kSinCosConstants];
};
constexpr SinCosTable make_sin_cos_table() {
  SinCosTable t{};
  t.value[kTwoOverPi] = 0.636619772367581343075535053490057448;
  t.value[kRoundingShifter] = 6755399441055744.0;
  t.value[kHalfPi1] = 1.57079632673412561417e+00;
  t.value[kHalfPi2] = 6.07710050630396597660e-11;
  t.value[kHalfPi3] = 2.02226624871116645580e-21;
  for (int k = 0; k < 9; ++k) t.value[kSin0 + k] = kSinCosSeries.sin[k];
  for (int k = 0; k < 10; ++k) t.value[kCos0 + k] = kSinCosSeries.cos[k];
  t.value[kIntegerOne] = __builtin_bit_cast(double, uint64_t{1});
  t.value[kIntegerTwo] = __builtin_bit_cast(double, uint64_t{2});
  t.value[kSignBit64] = __builtin_bit_cast(double, uint64_t{1} << 63);
  return t;
}
alignas(64) constexpr SinCosTable kSinCosTable = make_sin_cos_table();

// One half (8 lanes) of x: its sines or cosines rounded to float into the low half of `out`.
void sin_cos_half(X86Encoder& x, const LibraryOpRegisters& r, int half, bool cosine, int out) {
  const int* s = r.scratch;
  const int xd = s[0], shifted = s[1], k = s[2], reduced = s[3], z = s[4], z2 = s[5], z4 = s[6], z8 = s[7], t = s[8],
            u = s[9], sine = s[10];
  x.mov_imm(rax, reinterpret_cast<uint64_t>(&kSinCosTable));
  auto constant = [&](int reg, int index) { emit_table_constant(x, reg, index); };
  if (half == 0) {
    x.vcvtps2pd(xd, r.x);
  } else {
    x.vextractf32x8(t, r.x, 1);
    x.vcvtps2pd(xd, t);
  }
  // x = k (pi/2) + r.
  constant(t, kTwoOverPi);
  x.vmulpd(t, xd, t);
  constant(u, kRoundingShifter);
  x.vaddpd(shifted, t, u);
  x.vsubpd(k, shifted, u);
  for (int part = 0; part < 3; ++part) {
    constant(t, kHalfPi1 + part);
    x.vmulpd(t, k, t);
    x.vsubpd(reduced, part == 0 ? xd : reduced, t);
  }
  x.vmulpd(z, reduced, reduced);
  x.vmulpd(z2, z, z);
  x.vmulpd(z4, z2, z2);
  x.vmulpd(z8, z4, z4);
  const int p0 = xd;  // free from here, as k
  const SeriesRegisters series{z, z2, z4, t, u, k};
  // sin r = r ((eight terms) + s8 z8).
  emit_eight_terms(x, series, p0, kSin0);
  constant(t, kSin0 + 8);
  x.vmulpd(t, t, z8);
  x.vaddpd(p0, p0, t);
  x.vmulpd(sine, reduced, p0);
  // cos r = (eight terms) + (c8 + c9 z) z8.
  emit_eight_terms(x, series, p0, kCos0);
  emit_pair(x, series, u, kCos0 + 8);
  x.vmulpd(u, u, z8);
  x.vaddpd(p0, p0, u);
  // The quadrant, k mod 4 from the shifted sum's low bits (cos x = sin(x + pi/2)): odd picks
  // the cosine series, the second bit negates.
  if (cosine) {
    constant(t, kIntegerOne);
    x.vpaddq(shifted, shifted, t);
  }
  constant(t, kIntegerOne);
  x.vptestmq(1, shifted, t);
  constant(t, kIntegerTwo);
  x.vptestmq(2, shifted, t);
  x.vblendmpd(sine, 1, sine, p0);
  constant(t, kSignBit64);
  x.vpxorq(sine, sine, t, 2);
  x.vcvtpd2ps(out, sine);
}

}  // namespace

size_t emit_sin_cos(X86Encoder& x, const LibraryOpRegisters& r, bool cosine) {
  const int magnitude = r.scratch[0], limit = r.scratch[1];
  x.mov_imm32(rax, 0x7FFFFFFFu);
  x.vpbroadcastd(magnitude, rax);
  x.vpandd(magnitude, r.x, magnitude);
  x.mov_imm32(rax, 0x48000000u);  // 2^17
  x.vpbroadcastd(limit, rax);
  x.vpcmpd(1, magnitude, limit, IntCmp::Ge, r.running_mask);
  x.kortestw(1, 1);
  const size_t far = x.jump_if_not_zero();
  sin_cos_half(x, r, 0, cosine, r.result);
  const int high = r.scratch[9];
  sin_cos_half(x, r, 1, cosine, high);
  x.vinsertf32x8(r.result, r.result, high, 1);
  return far;
}

}  // namespace pineda::shader::jit
