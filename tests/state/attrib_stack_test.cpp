// glPushAttrib/glPopAttrib and glPushClientAttrib/glPopClientAttrib.
#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class AttribStackTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
};

TEST_F(AttribStackTest, PopRestoresOnlyThePushedGroups) {
  glPushAttrib(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  glClearDepth(0.25);
  glEnable(GL_BLEND);  // not in the depth group
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_LESS);
  EXPECT_EQ(get_bool(GL_DEPTH_WRITEMASK), GL_TRUE);
  EXPECT_EQ(get_float(GL_DEPTH_CLEAR_VALUE), 1.f);
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_TRUE);
}

TEST_F(AttribStackTest, ColorBufferGroup) {
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_LESS, 0.5f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE);
  glBlendColor(1, 1, 1, 1);
  glLogicOp(GL_XOR);
  glColorMask(GL_FALSE, GL_FALSE, GL_TRUE, GL_TRUE);
  glClearColor(1, 0, 0, 1);
  glDisable(GL_DITHER);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_ALPHA_TEST), GL_FALSE);
  EXPECT_EQ(get_int(GL_ALPHA_TEST_FUNC), GL_ALWAYS);
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_FALSE);
  EXPECT_EQ(get_int(GL_BLEND_SRC), GL_ONE);
  EXPECT_EQ(get_int(GL_BLEND_DST), GL_ZERO);
  EXPECT_EQ(get_floats(GL_BLEND_COLOR, 4), (std::vector<GLfloat>{0, 0, 0, 0}));
  EXPECT_EQ(get_int(GL_LOGIC_OP_MODE), GL_COPY);
  EXPECT_EQ(get_bools(GL_COLOR_WRITEMASK, 4), (std::vector<GLboolean>{1, 1, 1, 1}));
  EXPECT_EQ(get_floats(GL_COLOR_CLEAR_VALUE, 4), (std::vector<GLfloat>{0, 0, 0, 0}));
  EXPECT_EQ(glIsEnabled(GL_DITHER), GL_TRUE);
}

TEST_F(AttribStackTest, EnableGroupCoversEveryCapability) {
  glPushAttrib(GL_ENABLE_BIT);
  for (GLenum cap : {GL_BLEND, GL_CULL_FACE, GL_LIGHTING, GL_LIGHT3, GL_TEXTURE_2D, GL_FOG, GL_NORMALIZE,
                     GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_CLIP_PLANE2})
    glEnable(cap);
  glDisable(GL_DITHER);
  glDepthFunc(GL_EQUAL);  // not an enable
  glPopAttrib();
  for (GLenum cap : {GL_BLEND, GL_CULL_FACE, GL_LIGHTING, GL_LIGHT3, GL_TEXTURE_2D, GL_FOG, GL_NORMALIZE,
                     GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_CLIP_PLANE2})
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE) << std::hex << cap;
  EXPECT_EQ(glIsEnabled(GL_DITHER), GL_TRUE);
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_EQUAL);
}

TEST_F(AttribStackTest, CurrentViewportScissorTransformHintGroups) {
  glPushAttrib(GL_CURRENT_BIT | GL_VIEWPORT_BIT | GL_SCISSOR_BIT | GL_TRANSFORM_BIT | GL_HINT_BIT);
  glColor3f(0, 1, 0);
  glNormal3f(1, 0, 0);
  glTexCoord2f(3, 4);
  glViewport(1, 2, 3, 4);
  glDepthRange(0.5, 0.75);
  glEnable(GL_SCISSOR_TEST);
  glScissor(5, 6, 7, 8);
  glMatrixMode(GL_TEXTURE);
  glEnable(GL_NORMALIZE);
  glHint(GL_FOG_HINT, GL_NICEST);
  glPopAttrib();
  EXPECT_EQ(get_floats(GL_CURRENT_COLOR, 4), (std::vector<GLfloat>{1, 1, 1, 1}));
  EXPECT_EQ(get_floats(GL_CURRENT_NORMAL, 3), (std::vector<GLfloat>{0, 0, 1}));
  EXPECT_EQ(get_floats(GL_CURRENT_TEXTURE_COORDS, 4), (std::vector<GLfloat>{0, 0, 0, 1}));
  EXPECT_EQ(get_ints(GL_VIEWPORT, 4), (std::vector<GLint>{0, 0, width(), height()}));
  EXPECT_EQ(get_floats(GL_DEPTH_RANGE, 2), (std::vector<GLfloat>{0, 1}));
  EXPECT_EQ(glIsEnabled(GL_SCISSOR_TEST), GL_FALSE);
  EXPECT_EQ(get_ints(GL_SCISSOR_BOX, 4), (std::vector<GLint>{0, 0, width(), height()}));
  EXPECT_EQ(get_int(GL_MATRIX_MODE), GL_MODELVIEW);
  EXPECT_EQ(glIsEnabled(GL_NORMALIZE), GL_FALSE);
  EXPECT_EQ(get_int(GL_FOG_HINT), GL_DONT_CARE);
}

TEST_F(AttribStackTest, LightingPolygonPointLineStencilGroups) {
  glPushAttrib(GL_LIGHTING_BIT | GL_POLYGON_BIT | GL_POINT_BIT | GL_LINE_BIT | GL_STENCIL_BUFFER_BIT);
  const GLfloat red[4] = {1, 0, 0, 1};
  glLightfv(GL_LIGHT0, GL_DIFFUSE, red);
  glMaterialfv(GL_FRONT, GL_EMISSION, red);
  glShadeModel(GL_FLAT);
  glEnable(GL_LIGHTING);
  glCullFace(GL_FRONT);
  glFrontFace(GL_CW);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glPolygonOffset(1, 2);
  glPointSize(4);
  glLineWidth(3);
  glStencilFunc(GL_EQUAL, 3, 0x0f);
  glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
  glStencilMask(0x01);
  glClearStencil(9);
  glPopAttrib();
  GLfloat diffuse[4];
  glGetLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  EXPECT_EQ(diffuse[1], 1.f);
  GLfloat emission[4];
  glGetMaterialfv(GL_FRONT, GL_EMISSION, emission);
  EXPECT_EQ(emission[0], 0.f);
  EXPECT_EQ(get_int(GL_SHADE_MODEL), GL_SMOOTH);
  EXPECT_EQ(glIsEnabled(GL_LIGHTING), GL_FALSE);
  EXPECT_EQ(get_int(GL_CULL_FACE_MODE), GL_BACK);
  EXPECT_EQ(get_int(GL_FRONT_FACE), GL_CCW);
  EXPECT_EQ(get_ints(GL_POLYGON_MODE, 2), (std::vector<GLint>{GL_FILL, GL_FILL}));
  EXPECT_EQ(get_float(GL_POLYGON_OFFSET_UNITS), 0.f);
  EXPECT_EQ(get_float(GL_POINT_SIZE), 1.f);
  EXPECT_EQ(get_float(GL_LINE_WIDTH), 1.f);
  EXPECT_EQ(get_int(GL_STENCIL_FUNC), GL_ALWAYS);
  EXPECT_EQ(get_int(GL_STENCIL_REF), 0);
  EXPECT_EQ(get_int(GL_STENCIL_FAIL), GL_KEEP);
  EXPECT_EQ(get_int(GL_STENCIL_WRITEMASK) & 0xff, 0xff);
  EXPECT_EQ(get_int(GL_STENCIL_CLEAR_VALUE), 0);
}

TEST_F(AttribStackTest, TextureGroupRestoresBindingsEnvAndParameters) {
  glBindTexture(GL_TEXTURE_2D, 5);
  glPushAttrib(GL_TEXTURE_BIT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 6);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), 5);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_2D), GL_FALSE);
  GLint mode = 0, filter = 0;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &mode);
  EXPECT_EQ(mode, GL_MODULATE);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &filter);
  EXPECT_EQ(filter, GL_NEAREST_MIPMAP_LINEAR);
}

TEST_F(AttribStackTest, OverflowAndUnderflow) {
  GLint max = 0;
  glGetIntegerv(GL_MAX_ATTRIB_STACK_DEPTH, &max);
  ASSERT_GE(max, 16);
  glPopAttrib();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_UNDERFLOW));
  for (GLint i = 0; i < max; ++i) glPushAttrib(GL_ALL_ATTRIB_BITS);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glEnable(GL_BLEND);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_OVERFLOW));
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_FALSE);
  for (GLint i = 1; i < max; ++i) glPopAttrib();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glPopAttrib();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_UNDERFLOW));
  glBegin(GL_POINTS);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(AttribStackTest, ClientAttribGroups) {
  const float data[8] = {};
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
  glEnableClientState(GL_VERTEX_ARRAY);
  glPopClientAttrib();
  EXPECT_EQ(get_int(GL_PACK_ALIGNMENT), 4);
  EXPECT_EQ(get_int(GL_UNPACK_ROW_LENGTH), 0);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDisableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_SHORT, 4, data);
  glEnableClientState(GL_COLOR_ARRAY);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  glPopClientAttrib();
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_COLOR_ARRAY), GL_FALSE);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_SIZE), 4);
  EXPECT_EQ(get_int(GL_PACK_ALIGNMENT), 2);
  glPopClientAttrib();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_UNDERFLOW));
  GLint max = 0;
  glGetIntegerv(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, &max);
  for (GLint i = 0; i < max; ++i) glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_OVERFLOW));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

TEST_F(AttribStackTest, StackDepthsAreQueryable) {
  EXPECT_EQ(get_int(GL_ATTRIB_STACK_DEPTH), 0);
  EXPECT_EQ(get_int(GL_CLIENT_ATTRIB_STACK_DEPTH), 0);
  glPushAttrib(GL_CURRENT_BIT);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  EXPECT_EQ(get_int(GL_ATTRIB_STACK_DEPTH), 1);
  EXPECT_EQ(get_int(GL_CLIENT_ATTRIB_STACK_DEPTH), 2);
}

}  // namespace
}  // namespace pineda::test
