// glGet* type conversions (GL 1.1 spec 6.1.2) and state read back after it is set.
#include <cmath>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class GetConversionTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
};

// A colour component as an integer: the linear map c * (2^31 - 1), within the precision of
// the single-precision float GL keeps the component in.
void expect_int_color(GLint actual, double c) {
  EXPECT_NEAR(double(actual), c * kIntColorScale, 512.0) << "component " << c;
}

TEST_F(GetConversionTest, ColorsMapToTheIntegerRange) {
  glClearColor(1.f, 0.5f, 0.f, 0.25f);
  const auto ints = get_ints(GL_COLOR_CLEAR_VALUE, 4);
  EXPECT_EQ(ints[0], 2147483647);
  expect_int_color(ints[1], 0.5);
  EXPECT_EQ(ints[2], 0);
  expect_int_color(ints[3], 0.25);
  EXPECT_EQ(get_bools(GL_COLOR_CLEAR_VALUE, 4), (std::vector<GLboolean>{1, 1, 0, 1}));
  EXPECT_EQ(get_doubles(GL_COLOR_CLEAR_VALUE, 4), (std::vector<GLdouble>{1.0, 0.5, 0.0, 0.25}));
}

TEST_F(GetConversionTest, ClearColorIsClampedToZeroOne) {
  glClearColor(-1.f, 2.f, 0.5f, 7.f);
  EXPECT_EQ(get_floats(GL_COLOR_CLEAR_VALUE, 4), (std::vector<GLfloat>{0.f, 1.f, 0.5f, 1.f}));
}

TEST_F(GetConversionTest, CurrentColorFromEveryIntegerType) {
  glColor4ub(255, 0, 51, 102);
  EXPECT_EQ(get_floats(GL_CURRENT_COLOR, 4), (std::vector<GLfloat>{1.f, 0.f, 0.2f, 0.4f}));
  const auto ints = get_ints(GL_CURRENT_COLOR, 4);
  EXPECT_EQ(ints[0], 2147483647);
  EXPECT_EQ(ints[1], 0);
  expect_int_color(ints[2], 0.2);
  expect_int_color(ints[3], 0.4);

  glColor3us(65535, 0, 65535);
  EXPECT_EQ(get_floats(GL_CURRENT_COLOR, 4), (std::vector<GLfloat>{1.f, 0.f, 1.f, 1.f}));
  // Signed types: (2c + 1) / (2^b - 1), so the extremes are -1 and 1.
  glColor3b(127, -128, 0);
  const auto f = get_floats(GL_CURRENT_COLOR, 4);
  EXPECT_FLOAT_EQ(f[0], 1.f);
  EXPECT_FLOAT_EQ(f[1], -1.f);
  EXPECT_FLOAT_EQ(f[2], 1.f / 255.f);
  EXPECT_FLOAT_EQ(f[3], 1.f);
  glColor4ui(4294967295u, 0, 0, 4294967295u);
  EXPECT_EQ(get_floats(GL_CURRENT_COLOR, 4), (std::vector<GLfloat>{1.f, 0.f, 0.f, 1.f}));
  glColor4d(0.25, 0.5, 0.75, 1.0);
  EXPECT_EQ(get_doubles(GL_CURRENT_COLOR, 4), (std::vector<GLdouble>{0.25, 0.5, 0.75, 1.0}));
}

TEST_F(GetConversionTest, NormalsMapToTheIntegerRangeLikeColors) {
  glNormal3f(0.f, 0.5f, -1.f);
  const auto ints = get_ints(GL_CURRENT_NORMAL, 3);
  EXPECT_EQ(ints[0], 0);
  expect_int_color(ints[1], 0.5);
  EXPECT_LE(ints[2], -2147483647);
  glNormal3b(127, 0, -128);
  const auto f = get_floats(GL_CURRENT_NORMAL, 3);
  EXPECT_FLOAT_EQ(f[0], 1.f);
  EXPECT_FLOAT_EQ(f[1], 1.f / 255.f);
  EXPECT_FLOAT_EQ(f[2], -1.f);
}

TEST_F(GetConversionTest, LightModelAmbientMapsToTheIntegerRange) {
  const auto ints = get_ints(GL_LIGHT_MODEL_AMBIENT, 4);
  expect_int_color(ints[0], 0.2);
  expect_int_color(ints[1], 0.2);
  expect_int_color(ints[2], 0.2);
  EXPECT_EQ(ints[3], 2147483647);
}

TEST_F(GetConversionTest, DepthRangeAndClearDepthMapLikeColors) {
  glDepthRange(0.25, 2.0);  // clamped to [0, 1]
  EXPECT_EQ(get_doubles(GL_DEPTH_RANGE, 2), (std::vector<GLdouble>{0.25, 1.0}));
  const auto ints = get_ints(GL_DEPTH_RANGE, 2);
  expect_int_color(ints[0], 0.25);
  EXPECT_EQ(ints[1], 2147483647);
  glClearDepth(0.5);
  expect_int_color(get_int(GL_DEPTH_CLEAR_VALUE), 0.5);
  EXPECT_EQ(get_doubles(GL_DEPTH_CLEAR_VALUE, 1)[0], 0.5);
  glClearDepth(-3.0);
  EXPECT_EQ(get_float(GL_DEPTH_CLEAR_VALUE), 0.f);
}

TEST_F(GetConversionTest, FloatsRoundToNearestInteger) {
  glPointSize(2.6f);
  EXPECT_EQ(get_int(GL_POINT_SIZE), 3);
  EXPECT_FLOAT_EQ(get_float(GL_POINT_SIZE), 2.6f);
  glLineWidth(1.4f);
  EXPECT_EQ(get_int(GL_LINE_WIDTH), 1);
  glPolygonOffset(-2.5f, 3.75f);
  EXPECT_EQ(get_float(GL_POLYGON_OFFSET_FACTOR), -2.5f);
  EXPECT_EQ(get_float(GL_POLYGON_OFFSET_UNITS), 3.75f);
  EXPECT_EQ(get_int(GL_POLYGON_OFFSET_UNITS), 4);
  EXPECT_EQ(get_bool(GL_POLYGON_OFFSET_FACTOR), GL_TRUE);
}

TEST_F(GetConversionTest, IntegersAndEnumsConvertExactly) {
  glViewport(0, 3, 17, 9);
  EXPECT_EQ(get_floats(GL_VIEWPORT, 4), (std::vector<GLfloat>{0, 3, 17, 9}));
  EXPECT_EQ(get_doubles(GL_VIEWPORT, 4), (std::vector<GLdouble>{0, 3, 17, 9}));
  EXPECT_EQ(get_bools(GL_VIEWPORT, 4), (std::vector<GLboolean>{0, 1, 1, 1}));
  glDepthFunc(GL_GEQUAL);
  EXPECT_EQ(get_float(GL_DEPTH_FUNC), float(GL_GEQUAL));
  EXPECT_EQ(get_bool(GL_DEPTH_FUNC), GL_TRUE);
  glStencilFunc(GL_NOTEQUAL, 5, 0x0f);
  EXPECT_EQ(get_int(GL_STENCIL_FUNC), GL_NOTEQUAL);
  EXPECT_EQ(get_int(GL_STENCIL_REF), 5);
  EXPECT_EQ(get_int(GL_STENCIL_VALUE_MASK), 0x0f);
  EXPECT_EQ(get_float(GL_STENCIL_VALUE_MASK), 15.f);
}

TEST_F(GetConversionTest, BooleansConvertToOneAndZero) {
  glEnable(GL_BLEND);
  glDepthMask(GL_FALSE);
  EXPECT_EQ(get_int(GL_BLEND), 1);
  EXPECT_EQ(get_float(GL_BLEND), 1.f);
  EXPECT_EQ(get_double(GL_BLEND), 1.0);
  EXPECT_EQ(get_int(GL_DEPTH_WRITEMASK), 0);
  glColorMask(GL_TRUE, GL_FALSE, 2, GL_FALSE);  // any non-zero is true
  EXPECT_EQ(get_ints(GL_COLOR_WRITEMASK, 4), (std::vector<GLint>{1, 0, 1, 0}));
  EXPECT_EQ(get_bools(GL_COLOR_WRITEMASK, 4), (std::vector<GLboolean>{1, 0, 1, 0}));
}

TEST_F(GetConversionTest, MatrixElementsRound) {
  glScalef(2.6f, -1.5f, 0.4f);
  const auto ints = get_ints(GL_MODELVIEW_MATRIX, 16);
  EXPECT_EQ(ints[0], 3);
  EXPECT_EQ(ints[5], -2);  // round half away from zero
  EXPECT_EQ(ints[10], 0);
  EXPECT_EQ(ints[15], 1);
}

TEST_F(GetConversionTest, SetStateReadsBack) {
  glAlphaFunc(GL_GREATER, 0.75f);
  EXPECT_EQ(get_int(GL_ALPHA_TEST_FUNC), GL_GREATER);
  EXPECT_EQ(get_float(GL_ALPHA_TEST_REF), 0.75f);
  expect_int_color(get_int(GL_ALPHA_TEST_REF), 0.75);
  glAlphaFunc(GL_LESS, 1.5f);
  EXPECT_EQ(get_float(GL_ALPHA_TEST_REF), 1.f);

  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  EXPECT_EQ(get_int(GL_BLEND_SRC), GL_SRC_ALPHA);
  EXPECT_EQ(get_int(GL_BLEND_DST), GL_ONE_MINUS_SRC_ALPHA);
  glLogicOp(GL_XOR);
  EXPECT_EQ(get_int(GL_LOGIC_OP_MODE), GL_XOR);
  glStencilOp(GL_ZERO, GL_INCR, GL_INVERT);
  EXPECT_EQ(get_int(GL_STENCIL_FAIL), GL_ZERO);
  EXPECT_EQ(get_int(GL_STENCIL_PASS_DEPTH_FAIL), GL_INCR);
  EXPECT_EQ(get_int(GL_STENCIL_PASS_DEPTH_PASS), GL_INVERT);
  glStencilMask(0x3c);
  EXPECT_EQ(get_int(GL_STENCIL_WRITEMASK), 0x3c);
  glClearStencil(6);
  EXPECT_EQ(get_int(GL_STENCIL_CLEAR_VALUE), 6);
  glCullFace(GL_FRONT_AND_BACK);
  EXPECT_EQ(get_int(GL_CULL_FACE_MODE), GL_FRONT_AND_BACK);
  glFrontFace(GL_CW);
  EXPECT_EQ(get_int(GL_FRONT_FACE), GL_CW);
  glPolygonMode(GL_BACK, GL_LINE);
  EXPECT_EQ(get_ints(GL_POLYGON_MODE, 2), (std::vector<GLint>{GL_FILL, GL_LINE}));
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  EXPECT_EQ(get_ints(GL_POLYGON_MODE, 2), (std::vector<GLint>{GL_POINT, GL_POINT}));
  glShadeModel(GL_FLAT);
  EXPECT_EQ(get_int(GL_SHADE_MODEL), GL_FLAT);
  glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
  EXPECT_EQ(get_int(GL_PERSPECTIVE_CORRECTION_HINT), GL_NICEST);
  glScissor(2, 3, 4, 5);
  EXPECT_EQ(get_ints(GL_SCISSOR_BOX, 4), (std::vector<GLint>{2, 3, 4, 5}));
  glColorMaterial(GL_BACK, GL_SPECULAR);
  EXPECT_EQ(get_int(GL_COLOR_MATERIAL_FACE), GL_BACK);
  EXPECT_EQ(get_int(GL_COLOR_MATERIAL_PARAMETER), GL_SPECULAR);
  glTexCoord4f(1, 2, 3, 4);
  EXPECT_EQ(get_floats(GL_CURRENT_TEXTURE_COORDS, 4), (std::vector<GLfloat>{1, 2, 3, 4}));
  glTexCoord2s(5, 6);
  EXPECT_EQ(get_floats(GL_CURRENT_TEXTURE_COORDS, 4), (std::vector<GLfloat>{5, 6, 0, 1}));
  glEdgeFlag(GL_FALSE);
  EXPECT_EQ(get_bool(GL_EDGE_FLAG), GL_FALSE);
}

TEST_F(GetConversionTest, EnableDisableEveryCapability) {
  const GLenum caps[] = {GL_ALPHA_TEST, GL_BLEND, GL_COLOR_LOGIC_OP, GL_CULL_FACE, GL_DEPTH_TEST, GL_DITHER,
                         GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE,
                         GL_POLYGON_OFFSET_POINT, GL_LIGHTING, GL_LIGHT0, GL_LIGHT7, GL_COLOR_MATERIAL,
                         GL_NORMALIZE, GL_TEXTURE_1D, GL_TEXTURE_2D, GL_FOG, GL_LINE_STIPPLE, GL_POINT_SMOOTH,
                         GL_LINE_SMOOTH, GL_POLYGON_SMOOTH, GL_POLYGON_STIPPLE, GL_CLIP_PLANE0,
                         GL_TEXTURE_GEN_S, GL_AUTO_NORMAL, GL_MAP1_VERTEX_3, GL_MAP2_VERTEX_4};
  for (GLenum cap : caps) {
    glEnable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_TRUE) << std::hex << cap;
    EXPECT_EQ(get_bool(cap), GL_TRUE) << std::hex << cap;
    glDisable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE) << std::hex << cap;
    EXPECT_EQ(get_int(cap), 0) << std::hex << cap;
  }
  const GLenum arrays[] = {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_INDEX_ARRAY,
                           GL_TEXTURE_COORD_ARRAY, GL_EDGE_FLAG_ARRAY};
  for (GLenum a : arrays) {
    glEnableClientState(a);
    EXPECT_EQ(glIsEnabled(a), GL_TRUE) << std::hex << a;
    glDisableClientState(a);
    EXPECT_EQ(glIsEnabled(a), GL_FALSE) << std::hex << a;
  }
}

TEST_F(GetConversionTest, ClientArrayPointersAndFormats) {
  const float data[64] = {};
  glVertexPointer(3, GL_SHORT, 12, data);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, data + 1);
  glNormalPointer(GL_BYTE, 6, data + 2);
  glTexCoordPointer(1, GL_DOUBLE, 16, data + 3);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_SIZE), 3);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_TYPE), GL_SHORT);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_STRIDE), 12);
  EXPECT_EQ(get_int(GL_COLOR_ARRAY_SIZE), 3);
  EXPECT_EQ(get_int(GL_COLOR_ARRAY_TYPE), GL_UNSIGNED_BYTE);
  EXPECT_EQ(get_int(GL_NORMAL_ARRAY_TYPE), GL_BYTE);
  EXPECT_EQ(get_int(GL_NORMAL_ARRAY_STRIDE), 6);
  EXPECT_EQ(get_int(GL_TEXTURE_COORD_ARRAY_SIZE), 1);
  EXPECT_EQ(get_int(GL_TEXTURE_COORD_ARRAY_TYPE), GL_DOUBLE);
  EXPECT_EQ(get_int(GL_TEXTURE_COORD_ARRAY_STRIDE), 16);
  void* p = nullptr;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, data);
  glGetPointerv(GL_COLOR_ARRAY_POINTER, &p);
  EXPECT_EQ(p, data + 1);
  glGetPointerv(GL_NORMAL_ARRAY_POINTER, &p);
  EXPECT_EQ(p, data + 2);
  glGetPointerv(GL_TEXTURE_COORD_ARRAY_POINTER, &p);
  EXPECT_EQ(p, data + 3);
}

TEST_F(GetConversionTest, ClientArrayPointerErrorsChangeNothing) {
  const float data[4] = {};
  glVertexPointer(3, GL_FLOAT, 0, data);
  glVertexPointer(5, GL_FLOAT, 0, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glVertexPointer(2, GL_UNSIGNED_BYTE, 0, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glVertexPointer(2, GL_FLOAT, -4, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glColorPointer(2, GL_FLOAT, 0, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glNormalPointer(GL_UNSIGNED_INT, 0, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_SIZE), 3);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_TYPE), GL_FLOAT);
  void* p = nullptr;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  EXPECT_EQ(p, data);
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

TEST_F(GetConversionTest, EdgeFlagPointer) {
  const GLboolean flags[4] = {};
  EXPECT_EQ(get_int(GL_EDGE_FLAG_ARRAY_STRIDE), 0);
  glEdgeFlagPointer(4, flags);
  EXPECT_EQ(get_int(GL_EDGE_FLAG_ARRAY_STRIDE), 4);
  void* p = nullptr;
  glGetPointerv(GL_EDGE_FLAG_ARRAY_POINTER, &p);
  EXPECT_EQ(p, flags);
  glEdgeFlagPointer(-1, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_EDGE_FLAG_ARRAY_STRIDE), 4);
}

}  // namespace
}  // namespace pineda::test
