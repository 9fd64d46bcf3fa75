// Two threads, two contexts, rendering different things at the same time.
#include <atomic>
#include <thread>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

struct ThreadResult {
  bool ok = false;
  std::string error;
  int matching_pixels = 0, frames = 0;
  GLenum gl_error = GL_NO_ERROR;
};

// Renders `frames` frames of a rect of one colour over a cleared background and counts the
// pixels of the last frame that are exactly as expected.
void render(ThreadResult& result, int size, const uint8_t colour[3], int rect, std::atomic<int>& ready) {
  GlSurface surface({size, size, 24, 8});
  if (!surface.ok()) {
    result.error = surface.error();
    ++ready;
    return;
  }
  ++ready;
  while (ready.load() < 2) std::this_thread::yield();  // start drawing together
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, size, 0, size, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  std::vector<uint8_t> pixels(size_t(size) * size * 4);
  for (int frame = 0; frame < 50; ++frame) {
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3ub(colour[0], colour[1], colour[2]);
    glRecti(0, 0, rect, rect);
    glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    ++result.frames;
  }
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const uint8_t* p = &pixels[size_t((y * size + x) * 4)];
      const bool inside = x < rect && y < rect;
      const bool match = inside ? (p[0] == colour[0] && p[1] == colour[1] && p[2] == colour[2])
                                : (p[0] == 0 && p[1] == 0 && p[2] == 0);
      result.matching_pixels += match && p[3] == 255;
    }
  result.gl_error = glGetError();
  surface.release();
  result.ok = true;
}

TEST(ThreadsTest, TwoContextsRenderConcurrently) {
  ThreadResult a, b;
  std::atomic<int> ready{0};
  const uint8_t red[3] = {255, 0, 0}, green[3] = {0, 200, 0};
  std::thread ta([&] { render(a, 96, red, 40, ready); });
  std::thread tb([&] { render(b, 64, green, 50, ready); });
  ta.join();
  tb.join();
  ASSERT_TRUE(a.ok) << a.error;
  ASSERT_TRUE(b.ok) << b.error;
  EXPECT_EQ(a.frames, 50);
  EXPECT_EQ(a.matching_pixels, 96 * 96);
  EXPECT_EQ(b.matching_pixels, 64 * 64);
  EXPECT_EQ(a.gl_error, GLenum(GL_NO_ERROR));
  EXPECT_EQ(b.gl_error, GLenum(GL_NO_ERROR));
}

TEST(ThreadsTest, ContextStateIsPerContext) {
  GlSurface first({8, 8, 0, 0});
  ASSERT_TRUE(first.ok()) << first.error();
  glEnable(GL_BLEND);
  glClearColor(1, 0, 0, 1);
  GlSurface second({8, 8, 0, 0});  // now current
  ASSERT_TRUE(second.ok()) << second.error();
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_FALSE);
  GLfloat c[4];
  glGetFloatv(GL_COLOR_CLEAR_VALUE, c);
  EXPECT_EQ(c[0], 0.f);
  ASSERT_TRUE(first.make_current());
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_TRUE);
  first.release();
}

}  // namespace
}  // namespace pineda::test
