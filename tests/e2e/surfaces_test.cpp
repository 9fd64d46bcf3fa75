// The same drawing through an OSMesa buffer and an EGL pbuffer gives the same pixels.
#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

std::vector<uint8_t> draw_scene(GlSurface& surface) {
  make_current_with_pixel_projection(surface);
  const int w = surface.width(), h = surface.height();
  glClearColor(0.1f, 0.2f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex3f(2, 2, 0.5f);
  glColor3f(0, 1, 0);
  glVertex3f(40, 5, -0.5f);
  glColor3f(0, 0, 1);
  glVertex3f(20, 30, 0);
  glEnd();
  std::vector<uint8_t> pixels(size_t(w) * h * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  return pixels;
}

TEST(SurfacesTest, EglPbufferMatchesOSMesa) {
  GlSurface egl({45, 33, 24, 8, true});
  ASSERT_TRUE(egl.ok()) << egl.error();
  ASSERT_FALSE(egl.is_osmesa());
  const auto from_egl = draw_scene(egl);
  egl.release();
  GlSurface osmesa({45, 33, 24, 8, false});
  ASSERT_TRUE(osmesa.ok()) << osmesa.error();
  if (!osmesa.is_osmesa()) GTEST_SKIP() << "OSMesa not in use (not exported, or PINEDA_TEST_SURFACE=egl)";
  const auto from_osmesa = draw_scene(osmesa);
  EXPECT_EQ(from_egl, from_osmesa);
  // The OSMesa buffer is the image, bottom row first.
  glFinish();
  EXPECT_TRUE(std::equal(from_osmesa.begin(), from_osmesa.end(), osmesa.osmesa_buffer()));
  osmesa.release();
}

}  // namespace
}  // namespace pineda::test
