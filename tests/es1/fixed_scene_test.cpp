// An OpenGL ES 1.1 scene drawn with the GLfixed entry points and GL_FIXED arrays gives the
// same pixels, exactly, as the same scene through GL 1.5's float entry points.
#include <EGL/egl.h>
#include <gtest/gtest.h>

#include "tests/es1/egl_context.h"
#include "tests/es1/scene_data.h"

namespace pineda::es1_test {
namespace {

TEST(FixedScene, SamePixelsAsTheGL15Scene) {
  std::vector<uint8_t> es1, gl15;
  {
    Es1Context ctx(kSceneSize, kSceneSize);
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    es1 = render_es1_fixed_scene();
  }
  {
    const EGLint attribs[] = {EGL_NONE};
    EglContext ctx(EGL_OPENGL_API, attribs, kSceneSize, kSceneSize, EGL_OPENGL_BIT);
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    gl15 = render_gl15_scene();
  }
  ASSERT_EQ(es1.size(), gl15.size());
  int differing = 0;
  for (size_t i = 0; i < es1.size(); ++i) differing += es1[i] != gl15[i];
  EXPECT_EQ(differing, 0);
  // The corner is the clear colour (0.25, 0.5, 0.75, 1), the centre is the lit, textured quad.
  auto pixel = [&](int x, int y) {
    const uint8_t* p = &es1[(size_t(y) * kSceneSize + x) * 4];
    return std::vector<int>{p[0], p[1], p[2], p[3]};
  };
  EXPECT_EQ(pixel(0, 0), (std::vector<int>{64, 128, 191, 255}));
  EXPECT_NE(pixel(kSceneSize / 2, kSceneSize / 2), pixel(0, 0));
}

}  // namespace
}  // namespace pineda::es1_test
