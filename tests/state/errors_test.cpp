// glGetError: the first error is kept until read; calls inside glBegin/glEnd; invalid
// arguments leave the state unchanged.
#include <cmath>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

using ErrorTest = GlTest;

GLint get_int(GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  return v;
}

TEST_F(ErrorTest, NoErrorInitially) { EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)); }

TEST_F(ErrorTest, FirstErrorIsKeptUntilRead) {
  glEnable(0xFFFF);                 // GL_INVALID_ENUM
  glViewport(0, 0, -1, 1);          // GL_INVALID_VALUE
  glPopMatrix();                    // GL_STACK_UNDERFLOW
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ErrorTest, ErrorAfterReadIsRecordedAgain) {
  glViewport(0, 0, -1, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glPopMatrix();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_UNDERFLOW));
}

TEST_F(ErrorTest, EndWithoutBeginIsInvalidOperation) {
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(ErrorTest, BeginWithInvalidModeIsInvalidEnumAndDoesNotBegin) {
  glBegin(GL_POLYGON + 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glEnable(GL_BLEND);  // not inside Begin/End: allowed
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_TRUE);
}

TEST_F(ErrorTest, BeginEndPairIsAccepted) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glNormal3f(0, 0, 1);
  glTexCoord2f(0, 0);
  glEdgeFlag(GL_TRUE);
  glVertex2f(0, 0);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // After glEnd, non-vertex calls work again.
  glEnable(GL_DEPTH_TEST);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_TRUE);
}

TEST_F(ErrorTest, NonVertexCallsInsideBeginEndAreInvalidOperationAndIgnored) {
  glBegin(GL_TRIANGLES);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glMatrixMode(GL_PROJECTION);
  glBegin(GL_POINTS);  // nested glBegin
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_LESS);
  EXPECT_EQ(get_int(GL_MATRIX_MODE), GL_MODELVIEW);
  // The glEnd above ended the primitive: another one is an error.
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(ErrorTest, QueriesInsideBeginEndAreInvalidOperation) {
  glBegin(GL_LINES);
  GLint v = 77;
  glGetIntegerv(GL_DEPTH_FUNC, &v);
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_FALSE);
  glEnd();
  EXPECT_EQ(v, 77);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(ErrorTest, GetErrorInsideBeginEndIsInvalidOperation) {
  glBegin(GL_POINTS);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));  // returns 0 and records the error
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(ErrorTest, InvalidEnumsChangeNothing) {
  glDepthFunc(GL_ALWAYS + 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_LESS);

  glBlendFunc(GL_ONE, GL_LINE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_BLEND_SRC), GL_ONE);
  EXPECT_EQ(get_int(GL_BLEND_DST), GL_ZERO);

  glStencilOp(GL_KEEP, GL_REPLACE, GL_LESS);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_STENCIL_PASS_DEPTH_FAIL), GL_KEEP);

  glCullFace(GL_LEFT);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_CULL_FACE_MODE), GL_BACK);

  glPolygonMode(GL_FRONT, GL_FILL + 7);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint modes[2];
  glGetIntegerv(GL_POLYGON_MODE, modes);
  EXPECT_EQ(modes[0], GL_FILL);
  EXPECT_EQ(modes[1], GL_FILL);

  glMatrixMode(GL_COLOR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_MATRIX_MODE), GL_MODELVIEW);

  glShadeModel(GL_SMOOTH + 5);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_SHADE_MODEL), GL_SMOOTH);

  glLogicOp(GL_SET + 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_LOGIC_OP_MODE), GL_COPY);

  glAlphaFunc(GL_NEVER - 1, 0.5f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_ALPHA_TEST_FUNC), GL_ALWAYS);
  GLfloat ref = -1;
  glGetFloatv(GL_ALPHA_TEST_REF, &ref);
  EXPECT_EQ(ref, 0.f);

  glHint(GL_FOG_HINT, GL_LESS);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_FOG_HINT), GL_DONT_CARE);

  glFrontFace(GL_FRONT);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_FRONT_FACE), GL_CCW);
}

TEST_F(ErrorTest, InvalidValuesChangeNothing) {
  glViewport(1, 2, 3, 4);
  glViewport(5, 6, -7, 8);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLint vp[4];
  glGetIntegerv(GL_VIEWPORT, vp);
  EXPECT_EQ(vp[0], 1);
  EXPECT_EQ(vp[1], 2);
  EXPECT_EQ(vp[2], 3);
  EXPECT_EQ(vp[3], 4);

  glScissor(1, 1, 5, -1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLint box[4];
  glGetIntegerv(GL_SCISSOR_BOX, box);
  EXPECT_EQ(box[2], width());
  EXPECT_EQ(box[3], height());

  glPointSize(0.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glLineWidth(-1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLfloat size = 0;
  glGetFloatv(GL_POINT_SIZE, &size);
  EXPECT_EQ(size, 1.f);
  glGetFloatv(GL_LINE_WIDTH, &size);
  EXPECT_EQ(size, 1.f);

  glClear(0x00100000);  // not a buffer bit
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(ErrorTest, GetWithInvalidPnameIsInvalidEnumAndWritesNothing) {
  GLint i = 42;
  GLfloat f = 42.f;
  GLboolean b = 42;
  GLdouble d = 42.0;
  glGetIntegerv(0x7FFF, &i);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetFloatv(0x7FFF, &f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetBooleanv(0x7FFF, &b);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetDoublev(0x7FFF, &d);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(i, 42);
  EXPECT_EQ(f, 42.f);
  EXPECT_EQ(b, 42);
  EXPECT_EQ(d, 42.0);
  EXPECT_EQ(glIsEnabled(0x7FFF), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glGetString(0x7FFF), nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(ErrorTest, EnableOfNonCapabilityIsInvalidEnum) {
  glEnable(GL_LINE_WIDTH);  // a value, not a capability
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glIsEnabled(GL_LINE_WIDTH), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glEnableClientState(GL_BLEND);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_FALSE);
}

// As in Mesa's compatibility profile: glEnable/glDisable of a client array act as
// glEnableClientState/glDisableClientState.
TEST_F(ErrorTest, EnableOfClientArraySwitchesIt) {
  glEnable(GL_VERTEX_ARRAY);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  glDisable(GL_VERTEX_ARRAY);
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Found by the API fuzzer (UBSan: float to unsigned conversion out of range): an enum given as
// a float that no GLenum holds is GL_INVALID_ENUM and changes nothing.
TEST_F(ErrorTest, EnumAsHugeOrNanFloatIsInvalidEnum) {
  glTexGenf(GL_S, GL_TEXTURE_GEN_MODE, -2.12635e33f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint mode = 0;
  glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &mode);
  EXPECT_EQ(mode, GL_EYE_LINEAR);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, 1e30f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, -1.0f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, std::nanf(""));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glFogf(GL_FOG_MODE, -1e30f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glFogf(GL_FOG_COORDINATE_SOURCE, 1e30f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint fog_mode = 0, tex_env_mode = 0;
  glGetIntegerv(GL_FOG_MODE, &fog_mode);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &tex_env_mode);
  EXPECT_EQ(fog_mode, GL_EXP);
  EXPECT_EQ(tex_env_mode, GL_MODULATE);
}

// Found by the API fuzzer (UBSan: 2^31 converted to int): a texture level given as a float is
// clamped to GLint; NaN is GL_INVALID_VALUE like a negative level.
TEST_F(ErrorTest, TextureLevelAsHugeOrNanFloat) {
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 3e9f);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLint level = 0;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, &level);
  EXPECT_EQ(level, 2147483647);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, std::nanf(""));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, &level);
  EXPECT_EQ(level, 0);
}

// Found by the API fuzzer (UBSan: NaN converted to int): float state that holds NaN reads as 0
// through glGetIntegerv.
TEST_F(ErrorTest, NanStateReadsAsZeroInteger) {
  glPolygonOffset(std::nanf(""), 2.f);
  GLint v[2] = {-1, -1};
  glGetIntegerv(GL_POLYGON_OFFSET_FACTOR, &v[0]);
  glGetIntegerv(GL_POLYGON_OFFSET_UNITS, &v[1]);
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[1], 2);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
