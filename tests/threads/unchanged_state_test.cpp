// A context that draws twice with no call between the draws sees in the second what another
// context of its share group changed meanwhile on another thread: a draw keeps what it worked out
// from the state while no call changes it (state/state_key.h), and the calls of a share group's
// members count for each of them.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <gtest/gtest.h>

#include <array>
#include <latch>
#include <thread>

#include "tests/threads/test_context.h"

namespace pineda::threads_test {
namespace {

class UnchangedStateDraws : public ::testing::TestWithParam<Api> {};

TEST_P(UnchangedStateDraws, ATextureChangedOnAnotherThreadReachesTheNextDraw) {
  const Api api = GetParam();
  if (!api_available(api)) GTEST_SKIP() << "no X display (DISPLAY)";
  TestContext drawer(api, 8, 8);
  TestContext changer(api, 8, 8, &drawer);
  ASSERT_TRUE(drawer.ok() && changer.ok());
  ASSERT_TRUE(drawer.make_current());
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  const GLubyte red[] = {255, 0, 0, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, red);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  static const GLfloat kWindow[] = {-1, -1, 1, -1, 1, 1, -1, 1};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, kWindow);
  glFinish();

  std::latch drawn(1), changed(1);
  bool changer_current = false;
  std::thread other([&] {
    drawn.wait();
    changer_current = changer.make_current();
    if (changer_current) {
      const GLubyte green[] = {0, 255, 0, 255};
      glBindTexture(GL_TEXTURE_2D, texture);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, green);
      glFinish();
      changer.release();
    }
    changed.count_down();
  });
  glDrawArrays(GL_QUADS, 0, 4);  // red
  drawn.count_down();
  changed.wait();
  glDrawArrays(GL_QUADS, 0, 4);  // green: the texture as the other context left it
  other.join();
  ASSERT_TRUE(changer_current);
  std::array<GLubyte, 4> pixel{};
  glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel.data());
  EXPECT_EQ(pixel, (std::array<GLubyte, 4>{0, 255, 0, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glDeleteTextures(1, &texture);
  drawer.release();
}

INSTANTIATE_TEST_SUITE_P(Apis, UnchangedStateDraws, ::testing::Values(Api::EglPbuffer, Api::OSMesa, Api::GlxPbuffer),
                         [](const auto& info) { return api_name(info.param); });

}  // namespace
}  // namespace pineda::threads_test
