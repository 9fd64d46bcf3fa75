// A context joins the share group of a context another thread is drawing with, uses the
// group's namespaces at once, and leaves again, many times: the drawing thread's images stay
// those of the scene, and (under ThreadSanitizer) no call of either races.
#include <gtest/gtest.h>

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include <atomic>
#include <thread>

#include "tests/threads/thread_runs.h"

namespace pineda::threads_test {
namespace {

class ShareGroupJoin : public ::testing::TestWithParam<Api> {};

TEST_P(ShareGroupJoin, JoiningWhileAnotherThreadDrawsRacesNothing) {
  const Api api = GetParam();
  if (!api_available(api)) GTEST_SKIP() << "no X display (DISPLAY)";
  TestContext drawing(api, kWidth, kHeight);
  std::atomic<bool> created{false}, stop{false};
  std::atomic<int> wrong_images{0};
  std::thread drawer([&] {
    if (!drawing.make_current()) return;
    const SceneObjects objects = create_scene_objects();
    const std::vector<uint64_t> reference = render_frames(objects, 4);
    created = true;
    for (int f = 0; !stop.load(); ++f)
      if (image_hash(render_frame(objects, f % 4)) != reference[f % 4]) wrong_images.fetch_add(1);
    delete_scene_objects(objects);
    drawing.release();
  });
  while (!created.load()) std::this_thread::yield();
  const uint8_t texel[4] = {1, 2, 3, 4};
  for (int i = 0; i < 30; ++i) {
    TestContext joining(api, kWidth, kHeight, &drawing);
    ASSERT_TRUE(joining.ok() && joining.make_current());
    GLuint textures[4], buffer = 0;
    glGenTextures(4, textures);
    for (GLuint t : textures) {
      glBindTexture(GL_TEXTURE_2D, t);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    }
    glGenBuffers(1, &buffer);
    glDeleteBuffers(1, &buffer);
    const GLuint list = glGenLists(1);
    glDeleteLists(list, 1);
    glDeleteTextures(4, textures);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    joining.release();
  }
  stop = true;
  drawer.join();
  EXPECT_EQ(wrong_images.load(), 0);
}

INSTANTIATE_TEST_SUITE_P(Apis, ShareGroupJoin,
                         ::testing::Values(Api::EglPbuffer, Api::EglSurfaceless, Api::OSMesa, Api::GlxPbuffer),
                         [](const auto& info) { return api_name(info.param); });

}  // namespace
}  // namespace pineda::threads_test
