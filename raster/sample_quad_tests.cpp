#include "raster/sample_quad_tests.h"

#include <immintrin.h>

#include <cstring>

#include "raster/draw_record.h"
#include "raster/quad_ops.h"

// The copies pass vectors wider than the baseline's registers but only within one function.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace pineda::raster::sample_tests_sse2 {
namespace {
constexpr int kVectorBytes = 0;
#include "raster/sample_quad_tests_body.inc"
}  // namespace
}  // namespace pineda::raster::sample_tests_sse2

#pragma GCC push_options
#pragma GCC target("avx2")
namespace pineda::raster::sample_tests_avx2 {
namespace {
constexpr int kVectorBytes = kCopiesHaveTheirTargets ? 32 : 0;
#include "raster/sample_quad_tests_body.inc"
}  // namespace
}  // namespace pineda::raster::sample_tests_avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512bw,avx512vl,avx512dq")
namespace pineda::raster::sample_tests_avx512 {
namespace {
constexpr int kVectorBytes = kCopiesHaveTheirTargets ? 64 : 0;
#include "raster/sample_quad_tests_body.inc"
}  // namespace
}  // namespace pineda::raster::sample_tests_avx512
#pragma GCC pop_options

namespace pineda::raster {

SampleQuadTests select_sample_quad_tests(const FragmentKey& key, SimdPath path) {
  if (!key.depth && !key.stencil) return nullptr;
  if (uses_avx512(path)) {
    namespace c = sample_tests_avx512;
    if (!key.stencil) return &c::test_sample_quad<true, false>;
    return key.depth ? &c::test_sample_quad<true, true> : &c::test_sample_quad<false, true>;
  }
  if (uses_avx2(path)) {
    namespace c = sample_tests_avx2;
    if (!key.stencil) return &c::test_sample_quad<true, false>;
    return key.depth ? &c::test_sample_quad<true, true> : &c::test_sample_quad<false, true>;
  }
  namespace c = sample_tests_sse2;
  if (!key.stencil) return &c::test_sample_quad<true, false>;
  return key.depth ? &c::test_sample_quad<true, true> : &c::test_sample_quad<false, true>;
}

}  // namespace pineda::raster
