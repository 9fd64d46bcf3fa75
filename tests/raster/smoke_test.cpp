#include <gtest/gtest.h>

#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

TEST(Smoke, FullScreenQuadCoversEveryPixel) {
  OwnedFramebuffer fb(100, 70);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  const ClipVertex v[4] = {vertex(-1, -1), vertex(1, -1), vertex(1, 1), vertex(-1, 1)};
  r.draw(state_for(100, 70), Primitive::Quads, v);
  r.flush();
  EXPECT_EQ(fb.count_nonzero_red(), 100 * 70);
}

}  // namespace
}  // namespace pineda::raster::test
