// Share lists: contexts created with another as share list see its textures (the default
// ones too), buffer objects and display lists, not its queries or other state; contexts of
// one group render at once from several threads with the images each renders alone.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <EGL/egl.h>

#include <atomic>
#include <thread>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

// A 2x2 texture of four colours, named `name`, bound to GL_TEXTURE_2D.
void make_checker(GLuint name) {
  const uint8_t texels[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  glBindTexture(GL_TEXTURE_2D, name);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
}

// Draws the bound texture over the whole viewport.
void draw_textured_quad() {
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0); glVertex2f(-1, -1);
  glTexCoord2f(1, 0); glVertex2f(1, -1);
  glTexCoord2f(1, 1); glVertex2f(1, 1);
  glTexCoord2f(0, 1); glVertex2f(-1, 1);
  glEnd();
}

void expect_checker() {
  EXPECT_EQ(read_rgba(0, 0), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(read_rgba(15, 0), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(read_rgba(0, 15), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(read_rgba(15, 15), (Rgba{255, 255, 255, 255}));
}

class ShareGroupTest : public ::testing::TestWithParam<bool> {  // param: force EGL
 protected:
  SurfaceSpec spec(const GlSurface* share = nullptr) const {
    return {.width = 16, .height = 16, .force_egl = GetParam(), .share = share};
  }
};

TEST_P(ShareGroupTest, TexturesBuffersAndListsAreShared) {
  GlSurface first(spec());
  ASSERT_TRUE(first.ok()) << first.error();
  make_checker(5);
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  const float data[2] = {1.5f, 2.5f};
  glBufferData(GL_ARRAY_BUFFER, sizeof data, data, GL_STATIC_DRAW);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  draw_textured_quad();
  glEndList();
  GLuint query = 0;
  glGenQueries(1, &query);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  glEndQuery(GL_SAMPLES_PASSED);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));

  GlSurface second(spec(&first));  // now current
  ASSERT_TRUE(second.ok()) << second.error();
  EXPECT_EQ(glIsTexture(5), GL_TRUE);
  EXPECT_EQ(glIsBuffer(buffer), GL_TRUE);
  EXPECT_EQ(glIsList(list), GL_TRUE);
  EXPECT_EQ(glIsQuery(query), GL_FALSE);  // queries are per context
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_2D), GL_FALSE);  // state is per context
  GLint bound = -1;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  EXPECT_EQ(bound, 0);
  glBindTexture(GL_TEXTURE_2D, 5);
  glCallList(list);
  expect_checker();
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  float back[2] = {0, 0};
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, sizeof back, back);
  EXPECT_EQ(back[1], 2.5f);
  // A deletion in one context is seen in the other.
  glDeleteLists(list, 1);
  ASSERT_TRUE(first.make_current());
  EXPECT_EQ(glIsList(list), GL_FALSE);
  EXPECT_EQ(glIsQuery(query), GL_TRUE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_P(ShareGroupTest, TheGroupOutlivesTheContextThatMadeIt) {
  auto first = std::make_unique<GlSurface>(spec());
  ASSERT_TRUE(first->ok()) << first->error();
  make_checker(9);
  GlSurface second(spec(first.get()));
  ASSERT_TRUE(second.ok()) << second.error();
  first.reset();
  ASSERT_TRUE(second.make_current());
  glBindTexture(GL_TEXTURE_2D, 9);
  draw_textured_quad();
  expect_checker();
}

TEST_P(ShareGroupTest, ContextsWithoutAShareListShareNothing) {
  GlSurface first(spec());
  ASSERT_TRUE(first.ok()) << first.error();
  make_checker(5);
  GlSurface second(spec());
  ASSERT_TRUE(second.ok()) << second.error();
  EXPECT_EQ(glIsTexture(5), GL_FALSE);
}

INSTANTIATE_TEST_SUITE_P(OsmesaOrEgl, ShareGroupTest, ::testing::Bool());

TEST(ShareGroupEglTest, ShareContextOfAnotherApiIsBadContext) {
  GlSurface gl({.width = 8, .height = 8, .force_egl = true});
  ASSERT_TRUE(gl.ok()) << gl.error();
  EGLDisplay d = eglGetCurrentDisplay();
  EGLContext gl_context = eglGetCurrentContext();
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT, EGL_NONE};
  EGLConfig config;
  EGLint count = 0;
  ASSERT_TRUE(eglChooseConfig(d, config_attribs, &config, 1, &count) && count == 1);
  eglBindAPI(EGL_OPENGL_ES_API);
  const EGLint es1[] = {EGL_CONTEXT_CLIENT_VERSION, 1, EGL_NONE};
  EXPECT_EQ(eglCreateContext(d, config, gl_context, es1), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  eglBindAPI(EGL_OPENGL_API);
}

// Each thread draws the shared texture through its own context `frames` times while the
// others do the same, then reads its image.
std::vector<uint8_t> render_shared(const GlSurface& share, int frames, std::atomic<int>& started, int threads,
                                   bool* ok) {
  GlSurface surface({.width = 16, .height = 16, .force_egl = !share.is_osmesa(), .share = &share});
  *ok = surface.ok();
  ++started;
  if (!*ok) return {};
  while (started.load() < threads) std::this_thread::yield();
  std::vector<uint8_t> image(16 * 16 * 4);
  for (int i = 0; i < frames; ++i) {
    glClear(GL_COLOR_BUFFER_BIT);
    glBindTexture(GL_TEXTURE_2D, 5);
    // Every thread also creates and deletes shared objects while the others draw.
    GLuint own = 0;
    glGenTextures(1, &own);
    make_checker(own);
    glDeleteTextures(1, &own);
    glBindTexture(GL_TEXTURE_2D, 5);
    draw_textured_quad();
    glReadPixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  }
  *ok = glGetError() == GL_NO_ERROR;
  surface.release();
  return image;
}

TEST(ShareGroupThreadsTest, ThreadsOfOneGroupRenderTheImageOneRendersAlone) {
  GlSurface owner({.width = 16, .height = 16});
  ASSERT_TRUE(owner.ok()) << owner.error();
  make_checker(5);
  draw_textured_quad();
  std::vector<uint8_t> alone(16 * 16 * 4);
  glReadPixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, alone.data());
  owner.release();
  for (int threads : {2, 8}) {
    std::atomic<int> started{0};
    std::vector<std::vector<uint8_t>> images(threads);
    std::vector<char> ok(threads, 0);
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
      pool.emplace_back([&, t] {
        bool fine = false;
        images[t] = render_shared(owner, 40, started, threads, &fine);
        ok[t] = fine;
      });
    for (std::thread& t : pool) t.join();
    for (int t = 0; t < threads; ++t) {
      EXPECT_TRUE(ok[t]) << "thread " << t << " of " << threads;
      EXPECT_EQ(images[t], alone) << "thread " << t << " of " << threads;
    }
  }
}

}  // namespace
}  // namespace pineda::test
