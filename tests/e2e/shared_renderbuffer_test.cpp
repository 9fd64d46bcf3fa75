// Renderbuffers are shared by the contexts of a share group (ARB_framebuffer_object; framebuffer
// objects are not): their names, storage and contents; a deletion in one context leaves them
// attached in another; storage respecified by one context while another has rendering queued
// into the old storage (the sanitizer build checks that nothing writes freed memory).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/other_thread_context.h"

namespace pineda::test {
namespace {

// A framebuffer object of this context with `renderbuffer` as colour attachment 0, bound.
GLuint framebuffer_of(GLuint renderbuffer) {
  GLuint fb = 0;
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer);
  return fb;
}

void clear_color_to(float r, float g, float b) {
  glClearColor(r, g, b, 1.f);
  glClear(GL_COLOR_BUFFER_BIT);
}

class SharedRenderbufferTest : public ::testing::TestWithParam<bool> {  // param: force EGL
 protected:
  SurfaceSpec spec(const GlSurface* share = nullptr) const {
    return {.width = 16, .height = 16, .force_egl = GetParam(), .share = share};
  }
};

TEST_P(SharedRenderbufferTest, NamesStorageAndContentsAreShared) {
  GlSurface first(spec());
  ASSERT_TRUE(first.ok()) << first.error();
  GLuint rb = 0;
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 8, 4);
  const GLuint first_fb = framebuffer_of(rb);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  clear_color_to(1, 0, 0);
  EXPECT_EQ(read_rgba(7, 3), (Rgba{255, 0, 0, 255}));

  GlSurface second(spec(&first));  // now current
  ASSERT_TRUE(second.ok()) << second.error();
  EXPECT_EQ(glIsRenderbuffer(rb), GL_TRUE);
  EXPECT_EQ(glIsFramebuffer(first_fb), GL_FALSE);  // framebuffer objects are per context
  GLint bound = -1;
  glGetIntegerv(GL_RENDERBUFFER_BINDING, &bound);
  EXPECT_EQ(bound, 0);  // bindings are per context
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  GLint width = 0, height = 0;
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &width);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_HEIGHT, &height);
  EXPECT_EQ(width, 8);
  EXPECT_EQ(height, 4);
  framebuffer_of(rb);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(read_rgba(7, 3), (Rgba{255, 0, 0, 255}));  // what the first context rendered
  clear_color_to(0, 1, 0);
  glFinish();

  ASSERT_TRUE(first.make_current());
  EXPECT_EQ(read_rgba(0, 0), (Rgba{0, 255, 0, 255}));  // what the second rendered
  // Storage given in this context is what the other's attachment shows.
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 2, 2);
  ASSERT_TRUE(second.make_current());
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &width);
  EXPECT_EQ(width, 2);
  clear_color_to(0, 0, 1);
  EXPECT_EQ(read_rgba(1, 1), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_P(SharedRenderbufferTest, DeletedInOneContextStaysAttachedAndBoundInAnother) {
  GlSurface first(spec());
  ASSERT_TRUE(first.ok()) << first.error();
  GLuint rb = 0;
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 4);

  GlSurface second(spec(&first));
  ASSERT_TRUE(second.ok()) << second.error();
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  framebuffer_of(rb);
  clear_color_to(1, 1, 0);
  glFinish();

  ASSERT_TRUE(first.make_current());
  glDeleteRenderbuffers(1, &rb);
  EXPECT_EQ(glIsRenderbuffer(rb), GL_FALSE);
  GLint bound = -1;
  glGetIntegerv(GL_RENDERBUFFER_BINDING, &bound);
  EXPECT_EQ(bound, 0);  // unbound where it was deleted

  ASSERT_TRUE(second.make_current());
  EXPECT_EQ(glIsRenderbuffer(rb), GL_FALSE);  // the name is gone from the group
  glGetIntegerv(GL_RENDERBUFFER_BINDING, &bound);
  EXPECT_EQ(bound, GLint(rb));  // the other context's binding is left alone
  GLint width = 0;
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &width);
  EXPECT_EQ(width, 4);  // and still names the object
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(read_rgba(3, 3), (Rgba{255, 255, 0, 255}));
  clear_color_to(0, 1, 1);
  EXPECT_EQ(read_rgba(3, 3), (Rgba{0, 255, 255, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_P(SharedRenderbufferTest, ContextsWithoutAShareListHaveTheirOwn) {
  GlSurface first(spec());
  ASSERT_TRUE(first.ok()) << first.error();
  GLuint rb = 0;
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  GlSurface second(spec());
  ASSERT_TRUE(second.ok()) << second.error();
  EXPECT_EQ(glIsRenderbuffer(rb), GL_FALSE);
}

INSTANTIATE_TEST_SUITE_P(OsmesaOrEgl, SharedRenderbufferTest, ::testing::Bool());

// One thread's context queues rendering into a shared renderbuffer; another thread's context
// respecifies the renderbuffer's storage before the first flushes; the first then renders into
// the new storage.
TEST(SharedRenderbufferThreadsTest, StorageRespecifiedWhileAnotherContextHasRenderingQueued) {
  GlSurface owner({.width = 16, .height = 16});
  ASSERT_TRUE(owner.ok()) << owner.error();
  GLuint rb = 0;
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 64, 64);

  Rgba after{};
  GLenum other_error = GL_NO_ERROR;
  auto queue = [&] {
    framebuffer_of(rb);
    glViewport(0, 0, 64, 64);
    clear_color_to(1, 0, 0);
    queue_full_triangle();
  };
  auto finish = [&] {
    clear_color_to(0, 0, 1);
    after = read_rgba(15, 15);
    other_error = glGetError();
  };
  const bool other_ok = change_while_another_thread_has_queued(
      owner, queue, [] { glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 16, 16); }, finish);
  ASSERT_TRUE(other_ok);
  EXPECT_EQ(after, (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(other_error, GLenum(GL_NO_ERROR));
  framebuffer_of(rb);
  EXPECT_EQ(read_rgba(15, 15), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
