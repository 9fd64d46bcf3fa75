// Integer queries of float state that GL stores as given, NaN among it: NaN reads as 0 and
// values beyond GLint are clamped, never converted with undefined behaviour. The API fuzzer
// found each of these (UBSan); its inputs are seeds in tests/fuzz/corpus/api/.
#include <limits>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

using NanIntegerQueriesTest = GlTest;

TEST_F(NanIntegerQueriesTest, TexGenPlane) {
  const GLfloat plane[4] = {kNaN, 1e30f, -1e30f, 2.5f};
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  GLint v[4] = {1, 1, 1, 1};
  glGetTexGeniv(GL_S, GL_OBJECT_PLANE, v);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[1], 2147483647);
  EXPECT_EQ(v[2], -2147483647 - 1);
  EXPECT_EQ(v[3], 3);  // rounded
}

}  // namespace
}  // namespace pineda::test
