// ES 2.0's glGet tables (ES 2.0 tables 6.2-6.20): the values a new context reports.
#include <gtest/gtest.h>

#include "tests/es2/es2_context.h"

namespace pineda::es2_test {
namespace {

GLint get_int(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}

TEST(Es2Get, Defaults) {
  Es2Context context(8, 8);
  ASSERT_TRUE(context.ok()) << context.error();
  struct Row {
    GLenum pname;
    GLint value;
  };
  const Row rows[] = {
      {GL_MAX_VERTEX_ATTRIBS, 16},
      {GL_MAX_VERTEX_UNIFORM_VECTORS, 256},
      {GL_MAX_FRAGMENT_UNIFORM_VECTORS, 256},
      {GL_MAX_VARYING_VECTORS, 16},
      {GL_SHADER_COMPILER, GL_TRUE},
      {GL_NUM_SHADER_BINARY_FORMATS, 0},
      {GL_NUM_COMPRESSED_TEXTURE_FORMATS, 0},
      {GL_IMPLEMENTATION_COLOR_READ_FORMAT, GL_RGBA},
      {GL_IMPLEMENTATION_COLOR_READ_TYPE, GL_UNSIGNED_BYTE},
      {GL_CURRENT_PROGRAM, 0},
      {GL_ACTIVE_TEXTURE, GL_TEXTURE0},
      {GL_ARRAY_BUFFER_BINDING, 0},
      {GL_ELEMENT_ARRAY_BUFFER_BINDING, 0},
      {GL_FRAMEBUFFER_BINDING, 0},
      {GL_RENDERBUFFER_BINDING, 0},
      {GL_TEXTURE_BINDING_2D, 0},
      {GL_TEXTURE_BINDING_CUBE_MAP, 0},
      {GL_CULL_FACE_MODE, GL_BACK},
      {GL_FRONT_FACE, GL_CCW},
      {GL_DEPTH_FUNC, GL_LESS},
      {GL_BLEND_SRC_RGB, GL_ONE},
      {GL_BLEND_DST_ALPHA, GL_ZERO},
      {GL_BLEND_EQUATION_RGB, GL_FUNC_ADD},
      {GL_STENCIL_FUNC, GL_ALWAYS},
      {GL_STENCIL_BACK_FUNC, GL_ALWAYS},
      {GL_STENCIL_VALUE_MASK, -1},
      {GL_UNPACK_ALIGNMENT, 4},
      {GL_PACK_ALIGNMENT, 4},
      {GL_GENERATE_MIPMAP_HINT, GL_DONT_CARE},
      {GL_FRAGMENT_SHADER_DERIVATIVE_HINT_OES, GL_DONT_CARE},
      {GL_SUBPIXEL_BITS, 8},
      {GL_RED_BITS, 8},
      {GL_ALPHA_BITS, 8},
      {GL_DEPTH_BITS, 24},
      {GL_STENCIL_BITS, 8},
      {GL_SAMPLE_BUFFERS, 0},
  };
  for (const Row& r : rows) EXPECT_EQ(get_int(r.pname), r.value) << std::hex << "pname 0x" << r.pname;
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // No binary formats: the list query writes nothing.
  GLint formats = -3;
  glGetIntegerv(GL_SHADER_BINARY_FORMATS, &formats);
  EXPECT_EQ(formats, -3);
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(viewport[2], 8);
  EXPECT_EQ(viewport[3], 8);
  GLboolean enabled[9] = {};
  const GLenum caps[] = {GL_BLEND, GL_CULL_FACE, GL_DEPTH_TEST, GL_POLYGON_OFFSET_FILL, GL_SAMPLE_ALPHA_TO_COVERAGE,
                         GL_SAMPLE_COVERAGE, GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_DITHER};
  for (int i = 0; i < 9; ++i) enabled[i] = glIsEnabled(caps[i]);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(enabled[i], GL_FALSE) << i;
  EXPECT_EQ(enabled[8], GL_TRUE);  // DITHER starts enabled
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::es2_test
