// A texture shared by two threads' contexts: one renders into it through a framebuffer object
// while the other respecifies or deletes it before the rendering has run. The queued rendering
// writes the storage it was recorded against, kept alive until then (the sanitizer build checks
// that nothing writes freed memory); re-attached, the texture is rendered into anew.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <functional>
#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/other_thread_context.h"

namespace pineda::test {
namespace {

void attach_texture(GLuint texture) {
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
}

// A 64x64 RGBA8 texture of the current context, bound to unit 0.
GLuint make_texture() {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  return texture;
}

struct OtherThreadResult {
  bool started = false;
  GLenum error_after = GL_NO_ERROR;
  Rgba after{};
};

// In a second thread's context sharing with `owner`: queues a red clear and a full-screen
// triangle into `texture`, lets the owner run `change` meanwhile, then re-attaches the texture,
// clears it to blue and reads it back.
OtherThreadResult render_while_changed(const GlSurface& owner, GLuint texture, const std::function<void()>& change) {
  OtherThreadResult result;
  auto queue = [&] {
    GLuint fb = 0;
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    attach_texture(texture);
    glViewport(0, 0, 64, 64);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    queue_full_triangle();
  };
  auto finish = [&] {
    attach_texture(texture);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    result.after = read_rgba(7, 7);
    result.error_after = glGetError();
  };
  result.started = change_while_another_thread_has_queued(owner, queue, change, finish);
  return result;
}

TEST(SharedTextureTargetTest, RespecifiedWhileAnotherContextHasRenderingQueuedIntoIt) {
  GlSurface owner({.width = 16, .height = 16});
  ASSERT_TRUE(owner.ok()) << owner.error();
  const GLuint texture = make_texture();
  const OtherThreadResult other = render_while_changed(owner, texture, [] {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  });
  ASSERT_TRUE(other.started);
  EXPECT_EQ(other.after, (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(other.error_after, GLenum(GL_NO_ERROR));
  // The owner sees the 8x8 level as the other context left it.
  std::vector<uint8_t> texels(8 * 8 * 4, 0);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ((Rgba{texels[0], texels[1], texels[2], texels[3]}), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ((Rgba{texels[252], texels[253], texels[254], texels[255]}), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(SharedTextureTargetTest, DeletedWhileAnotherContextHasRenderingQueuedIntoIt) {
  GlSurface owner({.width = 16, .height = 16});
  ASSERT_TRUE(owner.ok()) << owner.error();
  const GLuint texture = make_texture();
  const OtherThreadResult other = render_while_changed(owner, texture, [&] { glDeleteTextures(1, &texture); });
  ASSERT_TRUE(other.started);
  // Re-attaching a deleted name is an error; the framebuffer has no image left to clear.
  EXPECT_EQ(other.error_after, GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(glIsTexture(texture), GLboolean(GL_FALSE));
}

}  // namespace
}  // namespace pineda::test
