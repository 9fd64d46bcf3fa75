// DESIGN: output is identical, bit for bit, for any worker thread count (PINEDA_THREADS).
#include <cmath>
#include <cstdlib>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

// Many overlapping, blended, smooth-shaded and depth-tested triangles across tile borders.
std::vector<uint8_t> render_with_threads(const char* threads) {
  setenv("PINEDA_THREADS", threads, 1);
  GlSurface surface({211, 157, 24, 8});
  unsetenv("PINEDA_THREADS");
  EXPECT_TRUE(surface.ok()) << surface.error();
  if (!surface.ok()) return {};
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, 211, 0, 157, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 300; ++i) {
    for (int k = 0; k < 3; ++k) {
      const double a = i * 0.37 + k * 2.1;
      glColor4f(float(0.5 + 0.5 * std::sin(a)), float(0.5 + 0.5 * std::cos(a * 1.3)), float((i % 7) / 6.0), 0.6f);
      glVertex3f(float(105 + 100 * std::sin(a * 0.91 + i)), float(78 + 75 * std::cos(a * 1.17 - i)),
                 float(std::sin(i * 0.13 + k)));
    }
  }
  glEnd();
  std::vector<uint8_t> pixels(size_t(211) * 157 * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, 211, 157, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  surface.release();
  return pixels;
}

TEST(ThreadCountTest, ImagesAreIdenticalForOneAndManyThreads) {
  const auto one = render_with_threads("1");
  const auto three = render_with_threads("3");
  const auto eight = render_with_threads("8");
  ASSERT_FALSE(one.empty());
  EXPECT_EQ(one, three);
  EXPECT_EQ(one, eight);
}

}  // namespace
}  // namespace pineda::test
