// A window's clear skips the tiles that still hold its value (raster/cleared_tiles.h): every
// other way of writing the buffers between two clears must still be cleared away. An EGL
// pbuffer (whose buffers only Pineda writes), 150x100: six tiles, partial ones at the edges.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <functional>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

constexpr Rgba kRed = {255, 0, 0, 255};

class RepeatedClearTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {150, 100, 24, 8, true}; }

  void clear_red() {
    glClearColor(1, 0, 0, 1);
    glClearDepth(1.0);
    glClearStencil(3);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  }

  // Clears, lets `write` change the buffers, clears the same again: every pixel is cleared.
  void expect_cleared_after(const std::function<void()>& write) {
    pixel_projection();
    clear_red();
    glFinish();
    read_all();
    write();
    glFinish();
    EXPECT_LT(count_pixels(kRed), width() * height()) << "the write changed nothing";
    clear_red();
    EXPECT_EQ(count_pixels(kRed), width() * height());
    std::vector<GLuint> depth(size_t(width()) * height()), stencil(depth.size());
    glReadPixels(0, 0, width(), height(), GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth.data());
    glReadPixels(0, 0, width(), height(), GL_STENCIL_INDEX, GL_UNSIGNED_INT, stencil.data());
    for (size_t i = 0; i < depth.size(); ++i) {
      ASSERT_EQ(depth[i], 0xffffffffu) << i;
      ASSERT_EQ(stencil[i], 3u) << i;
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
};

TEST_F(RepeatedClearTest, Triangles) {
  expect_cleared_after([] {
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glColor3f(0, 0, 1);
    glBegin(GL_TRIANGLES);
    glVertex3f(10, 10, 0), glVertex3f(140, 20, 0), glVertex3f(70, 90, 0);
    glEnd();
  });
}

TEST_F(RepeatedClearTest, DrawPixelsOfEachBuffer) {
  expect_cleared_after([] {
    const std::vector<GLubyte> blue(20 * 20 * 4, 200);
    const std::vector<GLuint> zero(20 * 20, 0);
    glRasterPos2i(55, 55);  // across four tiles
    glDrawPixels(20, 20, GL_RGBA, GL_UNSIGNED_BYTE, blue.data());
    glDrawPixels(20, 20, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zero.data());
    glDrawPixels(20, 20, GL_STENCIL_INDEX, GL_UNSIGNED_INT, zero.data());
  });
}

TEST_F(RepeatedClearTest, Bitmap) {
  expect_cleared_after([] {
    const std::vector<GLubyte> ones(16 * 4, 0xff);  // rows of 2 bytes padded to GL_UNPACK_ALIGNMENT 4
    glColor3f(0, 1, 0);
    glRasterPos2i(140, 90);
    glBitmap(16, 16, 0, 0, 0, 0, ones.data());
  });
}

TEST_F(RepeatedClearTest, CopyPixels) {
  expect_cleared_after([] {
    glColor3f(0, 0, 1);
    glRecti(0, 0, 10, 10);
    glFinish();
    glRasterPos2i(100, 70);
    glCopyPixels(0, 0, 10, 10, GL_COLOR);
  });
}

TEST_F(RepeatedClearTest, AccumReturn) {
  expect_cleared_after([] {
    glClearAccum(0, 0, 1, 1);
    glClear(GL_ACCUM_BUFFER_BIT);
    glAccum(GL_RETURN, 1.0f);
  });
}

TEST_F(RepeatedClearTest, BlitFromAFramebufferObject) {
  expect_cleared_after([] {
    GLuint fbo = 0, rb = 0;
    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 40, 40);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    glClearColor(0, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, 40, 40, 100, 50, 140, 90, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &rb);
  });
}

TEST_F(RepeatedClearTest, ScissoredAndMaskedClears) {
  expect_cleared_after([] {
    glEnable(GL_SCISSOR_TEST);
    glScissor(5, 5, 30, 30);
    glClearColor(0, 1, 0, 1);
    glClearDepth(0.25);
    glClearStencil(7);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_TRUE, GL_FALSE);
    glStencilMask(0x0c);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilMask(0xff);
  });
}

// Frames of moving triangles, each after a clear, give the same pixels on the pbuffer (whose
// clears skip tiles) as on an OSMesa buffer (whose clears never do).
std::vector<std::vector<uint8_t>> animate(GlSurface& surface) {
  make_current_with_pixel_projection(surface);
  const int w = surface.width(), h = surface.height();
  glEnable(GL_DEPTH_TEST);
  std::vector<std::vector<uint8_t>> frames;
  for (int f = 0; f < 12; ++f) {
    glClearColor(0.1f, 0.2f, f < 6 ? 0.3f : 0.4f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0.5f, 0);
    const float x = 12.f * static_cast<float>(f);
    glVertex3f(x, 5, 0.5f), glVertex3f(x + 30, 10, -0.5f), glVertex3f(x + 10, 60, 0);
    glEnd();
    std::vector<uint8_t> pixels(size_t(w) * h * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    frames.push_back(std::move(pixels));
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  return frames;
}

TEST(RepeatedClearFrames, SameAsABufferWhoseClearsSkipNothing) {
  GlSurface egl({150, 100, 24, 8, true});
  ASSERT_TRUE(egl.ok()) << egl.error();
  const auto from_egl = animate(egl);
  egl.release();
  GlSurface osmesa({150, 100, 24, 8, false});
  ASSERT_TRUE(osmesa.ok()) << osmesa.error();
  if (!osmesa.is_osmesa()) GTEST_SKIP() << "OSMesa not in use (not exported, or PINEDA_TEST_SURFACE=egl)";
  const auto from_osmesa = animate(osmesa);
  osmesa.release();
  ASSERT_EQ(from_egl.size(), from_osmesa.size());
  for (size_t f = 0; f < from_egl.size(); ++f) EXPECT_EQ(from_egl[f], from_osmesa[f]) << "frame " << f;
}

}  // namespace
}  // namespace pineda::test
