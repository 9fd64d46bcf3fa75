// The stencil and depth tests of a multisampled quad over all its samples' lanes
// (raster/sample_quad_tests.h): on every SIMD path, the same passing lanes and the same depth
// and stencil values as the single-sampled quad operations (quad_ops.h) run on each sample's
// plane, for every depth and stencil function and stencil op, partial coverage, samples the
// draw leaves alone, both faces, 24- and 32-bit depth and a shader's own depth.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "raster/draw_record.h"
#include "raster/quad_ops.h"
#include "raster/sample_quad_tests.h"

namespace pineda::raster {
namespace {

constexpr int kSize = 8;
constexpr int kPlane = kSize * kSize;

struct Planes {
  std::vector<uint32_t> depth = std::vector<uint32_t>(kMaxSamples * kPlane);
  std::vector<uint8_t> stencil = std::vector<uint8_t>(kMaxSamples * kPlane);
  Framebuffer plane(int s) {
    Framebuffer fb;
    fb.width = fb.height = kSize;
    fb.depth = {depth.data() + s * kPlane, kSize, 24, 0};
    fb.stencil = {stencil.data() + s * kPlane, kSize, 8, 0};
    return fb;
  }
};

// The quad operations of one sample, as the routines ran them before lanes: quad_ops's
// depth_stencil (or depth_only), or with a shader's depth the same steps per pixel.
unsigned reference_sample(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, unsigned mask,
                          F4 ox, F4 oy, const uint32_t* fragment_z) {
  using namespace quad_ops;
  if (!mask) return 0;
  if (!fragment_z) {
    if (d.key.stencil)
      return d.key.depth ? depth_stencil<true, true>(d, p, fb, x, y, mask, ox, oy)
                         : depth_stencil<false, true>(d, p, fb, x, y, mask, ox, oy);
    return depth_only(d, p, fb, x, y, mask, ox, oy);
  }
  const DrawState& s = d.state;
  const StencilFace& face = p.back_facing ? s.stencil_back : s.stencil_front;
  const uint8_t ref = d.stencil_ref[p.back_facing ? 1 : 0];
  for (int i = 0; i < 4; ++i) {
    if (!(mask & (1u << i))) continue;
    uint8_t* stencil = fb.stencil.base + (y + (i >> 1)) * fb.stencil.stride + x + (i & 1);
    const uint8_t sv = *stencil;
    auto update = [&](StencilOp op) {
      if (d.key.stencil) *stencil = static_cast<uint8_t>((sv & ~face.write_mask) | (stencil_op(op, sv, ref) & face.write_mask));
    };
    if (d.key.stencil && !compare(face.func, uint8_t(ref & face.value_mask), uint8_t(sv & face.value_mask))) {
      update(face.fail);
      mask &= ~(1u << i);
      continue;
    }
    uint32_t* depth = fb.depth.base + (y + (i >> 1)) * fb.depth.stride + x + (i & 1);
    if (d.key.depth) {
      if (!compare(s.depth_func, fragment_z[i], *depth)) {
        update(face.depth_fail);
        mask &= ~(1u << i);
        continue;
      }
      if (s.depth_write) *depth = fragment_z[i];
    }
    update(face.depth_pass);
  }
  return mask;
}

TEST(SampleQuadTests, EveryPathMatchesEachSamplesQuadOperations) {
  std::mt19937 random(11);
  auto pick = [&](int n) { return static_cast<int>(random() % unsigned(n)); };
  int checked = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    DrawRecord d;
    const int tests = trial % 3;  // depth, stencil, both
    d.key.depth = tests != 1;
    d.key.stencil = tests != 0;
    const bool wide = trial % 7 == 0;  // 32-bit depth
    d.depth_max = wide ? 4294967295.0 : 16777215.0;
    DrawState& s = d.state;
    s.depth_func = static_cast<CompareFunc>(pick(8));
    s.depth_write = pick(4) != 0;
    for (StencilFace* face : {&s.stencil_front, &s.stencil_back}) {
      face->func = static_cast<CompareFunc>(pick(8));
      face->value_mask = pick(3) ? 0xff : static_cast<uint8_t>(random());
      face->write_mask = pick(3) ? 0xff : static_cast<uint8_t>(random());
      face->fail = static_cast<StencilOp>(pick(8));
      face->depth_fail = static_cast<StencilOp>(pick(8));
      face->depth_pass = static_cast<StencilOp>(pick(8));
    }
    d.stencil_ref[0] = static_cast<uint8_t>(pick(3) ? pick(4) : int(random()));
    d.stencil_ref[1] = static_cast<uint8_t>(random());

    PrimSetup prim;
    prim.back_facing = pick(2);
    prim.ref_x = 0.25f * float(pick(16));
    prim.ref_y = 0.25f * float(pick(16));
    // Depths with fractions (where the order of the additions would show), some past the range.
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    prim.z0 = d.depth_max * (pick(5) ? 0.5 : 1.2) + 1000.0 * unit(random);
    prim.dzdx = 2000.0 * unit(random) * (pick(3) ? 1.0 : 1e-3);
    prim.dzdy = 2000.0 * unit(random);
    PrimSetup moved[kMaxSamples];
    SampleTargets t;
    Planes planes;
    const int x = 2 * pick(kSize / 2), y = 2 * pick(kSize / 2);
    const F4 ox = quad_ops::quad_row_ox0(prim, x), oy = quad_ops::quad_row_oy(prim, y);
    for (int smp = 0; smp < kMaxSamples; ++smp) {
      moved[smp] = prim;
      moved[smp].z0 = prim.z0 + 200.0 * unit(random);
      t.draw[smp] = pick(6) ? &d : nullptr;  // glSampleCoverage leaves some samples alone
      t.prim[smp] = &moved[smp];
      t.plane[smp] = planes.plane(smp);
    }
    // Stored depths near the incoming ones (some equal), stencil values at the ends too.
    const U4 centre = quad_ops::quad_depth(d, prim, ox, oy);
    for (uint32_t& v : planes.depth) v = pick(4) ? centre[pick(4)] + uint32_t(pick(400)) - 200u : uint32_t(random());
    for (uint8_t& v : planes.stencil) v = static_cast<uint8_t>(pick(3) ? pick(3) + (pick(2) ? 0 : 253) : int(random()));
    uint32_t shader_z[4];
    const bool given_z = pick(5) == 0;
    for (uint32_t& z : shader_z) z = pick(2) ? centre[pick(4)] : planes.depth[size_t(pick(kMaxSamples * kPlane))];
    const uint16_t lanes = trial % 4 == 0 ? 0xffff
                           : trial % 4 == 1 ? static_cast<uint16_t>(0xf << (4 * pick(4)) | 0xf << (4 * pick(4)))
                                            : static_cast<uint16_t>(random());

    Planes expected = planes;
    unsigned expected_lanes = 0;
    for (int smp = 0; smp < kMaxSamples; ++smp) {
      if (!t.draw[smp]) continue;
      const unsigned mask = (lanes >> (4 * smp)) & 0xfu;
      expected_lanes |= reference_sample(d, moved[smp], expected.plane(smp), x, y, mask, ox, oy,
                                         given_z ? shader_z : nullptr)
                        << (4 * smp);
    }
    for (SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline}) {
      Planes got = planes;
      SampleTargets on = t;
      for (int smp = 0; smp < kMaxSamples; ++smp) on.plane[smp] = got.plane(smp);
      const SampleQuadTests run = select_sample_quad_tests(d.key, path);
      ASSERT_NE(run, nullptr);
      const unsigned passed = run(d, prim, on, x, y, ox, oy, lanes, given_z ? shader_z : nullptr);
      ASSERT_EQ(passed, expected_lanes) << "trial " << trial << " path " << int(path);
      ASSERT_EQ(got.depth, expected.depth) << "trial " << trial << " path " << int(path);
      ASSERT_EQ(got.stencil, expected.stencil) << "trial " << trial << " path " << int(path);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 18000);
}

TEST(SampleQuadTests, NoneWithoutDepthOrStencil) {
  EXPECT_EQ(select_sample_quad_tests(FragmentKey{}, SimdPath::Best), nullptr);
}

}  // namespace
}  // namespace pineda::raster
