// Each GLfixed entry point of OpenGL ES 1.1 sets the same state as its float form: one ES 1.1
// context takes the float call, another the GLfixed one; their glGetFloatv (or the call's own
// float getter) must agree exactly, and the GLfixed getter must return the exact 16.16 values.
#include <GLES/gl.h>
#include <GLES/glext.h>
#include <gtest/gtest.h>

#include <cctype>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tests/es1/egl_context.h"

namespace pineda::es1_test {
namespace {

constexpr GLfixed X(double v) { return static_cast<GLfixed>(v * 65536.0); }

struct Case {
  std::string name;
  std::function<void()> set_float, set_fixed;
  std::function<std::vector<GLfloat>()> get_float;
  std::function<std::vector<GLfixed>()> get_fixed;
  std::vector<GLfixed> expected;  // what get_fixed returns after set_fixed
};

// glGetFloatv / glGetFixedv of `pname`, `n` values.
std::function<std::vector<GLfloat>()> floats_of(GLenum pname, int n) {
  return [=] {
    std::vector<GLfloat> v(n, -7777.f);
    glGetFloatv(pname, v.data());
    return v;
  };
}
std::function<std::vector<GLfixed>()> fixed_of(GLenum pname, int n) {
  return [=] {
    std::vector<GLfixed> v(n, -7777);
    glGetFixedv(pname, v.data());
    return v;
  };
}

Case by_get(std::string name, std::function<void()> f, std::function<void()> x, GLenum pname,
            std::vector<GLfixed> expected) {
  const int n = static_cast<int>(expected.size());
  return {std::move(name), std::move(f), std::move(x), floats_of(pname, n), fixed_of(pname, n), std::move(expected)};
}

const GLfloat kMatrix[16] = {2, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, -1, 0, 0.25f, -3, 1.5f, 1};
const GLfixed kMatrixX[16] = {X(2), 0, 0, 0, 0, X(0.5), 0, 0, 0, 0, X(-1), 0, X(0.25), X(-3), X(1.5), X(1)};
std::vector<GLfixed> matrix_fixed() { return {kMatrixX, kMatrixX + 16}; }

std::vector<Case> cases() {
  std::vector<Case> c;
  c.push_back(by_get("ClearColorx", [] { glClearColor(0.5f, 0.25f, 0.75f, 1); },
                     [] { glClearColorx(X(0.5), X(0.25), X(0.75), X(1)); }, GL_COLOR_CLEAR_VALUE,
                     {X(0.5), X(0.25), X(0.75), X(1)}));
  c.push_back(by_get("ClearDepthx", [] { glClearDepthf(0.25f); }, [] { glClearDepthx(X(0.25)); },
                     GL_DEPTH_CLEAR_VALUE, {X(0.25)}));
  c.push_back(by_get("DepthRangex", [] { glDepthRangef(0.25f, 0.75f); }, [] { glDepthRangex(X(0.25), X(0.75)); },
                     GL_DEPTH_RANGE, {X(0.25), X(0.75)}));
  c.push_back(by_get("AlphaFuncx", [] { glAlphaFunc(GL_GREATER, 0.5f); }, [] { glAlphaFuncx(GL_GREATER, X(0.5)); },
                     GL_ALPHA_TEST_REF, {X(0.5)}));
  c.push_back(by_get("LineWidthx", [] { glLineWidth(3); }, [] { glLineWidthx(X(3)); }, GL_LINE_WIDTH, {X(3)}));
  c.push_back(by_get("PointSizex", [] { glPointSize(4.5f); }, [] { glPointSizex(X(4.5)); }, GL_POINT_SIZE, {X(4.5)}));
  c.push_back(by_get("PolygonOffsetx", [] { glPolygonOffset(2, -1.5f); }, [] { glPolygonOffsetx(X(2), X(-1.5)); },
                     GL_POLYGON_OFFSET_UNITS, {X(-1.5)}));
  c.push_back(by_get("SampleCoveragex", [] { glSampleCoverage(0.5f, GL_TRUE); },
                     [] { glSampleCoveragex(X(0.5), GL_TRUE); }, GL_SAMPLE_COVERAGE_VALUE, {X(0.5)}));
  c.push_back(by_get("Color4x", [] { glColor4f(0.5f, 0.25f, 0, 1); }, [] { glColor4x(X(0.5), X(0.25), 0, X(1)); },
                     GL_CURRENT_COLOR, {X(0.5), X(0.25), 0, X(1)}));
  c.push_back(by_get("Normal3x", [] { glNormal3f(0, 0.5f, -1); }, [] { glNormal3x(0, X(0.5), X(-1)); },
                     GL_CURRENT_NORMAL, {0, X(0.5), X(-1)}));
  c.push_back(by_get("MultiTexCoord4x",
                     [] { glActiveTexture(GL_TEXTURE1); glMultiTexCoord4f(GL_TEXTURE1, 0.5f, 2, -1, 1); },
                     [] { glActiveTexture(GL_TEXTURE1); glMultiTexCoord4x(GL_TEXTURE1, X(0.5), X(2), X(-1), X(1)); },
                     GL_CURRENT_TEXTURE_COORDS, {X(0.5), X(2), X(-1), X(1)}));
  // A value that names an enum is passed as it is, not as 16.16.
  c.push_back(by_get("Fogx mode", [] { glFogf(GL_FOG_MODE, GL_LINEAR); }, [] { glFogx(GL_FOG_MODE, GL_LINEAR); },
                     GL_FOG_MODE, {GL_LINEAR}));
  c.push_back(by_get("Fogx density", [] { glFogf(GL_FOG_DENSITY, 1.5f); }, [] { glFogx(GL_FOG_DENSITY, X(1.5)); },
                     GL_FOG_DENSITY, {X(1.5)}));
  c.push_back(by_get("Fogxv color",
                     [] { const GLfloat v[] = {0.25f, 0.5f, 0.75f, 1}; glFogfv(GL_FOG_COLOR, v); },
                     [] { const GLfixed v[] = {X(0.25), X(0.5), X(0.75), X(1)}; glFogxv(GL_FOG_COLOR, v); },
                     GL_FOG_COLOR, {X(0.25), X(0.5), X(0.75), X(1)}));
  c.push_back(by_get("Fogxv end", [] { const GLfloat v[] = {10}; glFogfv(GL_FOG_END, v); },
                     [] { const GLfixed v[] = {X(10)}; glFogxv(GL_FOG_END, v); }, GL_FOG_END, {X(10)}));
  c.push_back(by_get("LightModelx two side", [] { glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 1); },
                     [] { glLightModelx(GL_LIGHT_MODEL_TWO_SIDE, 1); }, GL_LIGHT_MODEL_TWO_SIDE, {X(1)}));
  c.push_back(by_get("LightModelxv ambient",
                     [] { const GLfloat v[] = {0.5f, 0.25f, 0, 1}; glLightModelfv(GL_LIGHT_MODEL_AMBIENT, v); },
                     [] { const GLfixed v[] = {X(0.5), X(0.25), 0, X(1)}; glLightModelxv(GL_LIGHT_MODEL_AMBIENT, v); },
                     GL_LIGHT_MODEL_AMBIENT, {X(0.5), X(0.25), 0, X(1)}));
  c.push_back(by_get("PointParameterx", [] { glPointParameterf(GL_POINT_SIZE_MIN, 2); },
                     [] { glPointParameterx(GL_POINT_SIZE_MIN, X(2)); }, GL_POINT_SIZE_MIN, {X(2)}));
  c.push_back(by_get("PointParameterxv",
                     [] { const GLfloat v[] = {1, 0.5f, 0.25f}; glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, v); },
                     [] { const GLfixed v[] = {X(1), X(0.5), X(0.25)}; glPointParameterxv(GL_POINT_DISTANCE_ATTENUATION, v); },
                     GL_POINT_DISTANCE_ATTENUATION, {X(1), X(0.5), X(0.25)}));
  c.push_back(by_get("Orthox", [] { glOrthof(-2, 2, -1, 1, 0.5f, 4); }, [] { glOrthox(X(-2), X(2), X(-1), X(1), X(0.5), X(4)); },
                     GL_MODELVIEW_MATRIX, {X(0.5), 0, 0, 0, 0, X(1), 0, 0, 0, 0, X(-2.0 / 3.5), 0, 0, 0, X(-4.5 / 3.5), X(1)}));
  c.push_back(by_get("Frustumx", [] { glFrustumf(-1, 1, -1, 1, 1, 3); }, [] { glFrustumx(X(-1), X(1), X(-1), X(1), X(1), X(3)); },
                     GL_MODELVIEW_MATRIX, {X(1), 0, 0, 0, 0, X(1), 0, 0, 0, 0, X(-2), X(-1), 0, 0, X(-3), 0}));
  c.push_back(by_get("Translatex", [] { glTranslatef(1.5f, -2, 0.25f); }, [] { glTranslatex(X(1.5), X(-2), X(0.25)); },
                     GL_MODELVIEW_MATRIX, {X(1), 0, 0, 0, 0, X(1), 0, 0, 0, 0, X(1), 0, X(1.5), X(-2), X(0.25), X(1)}));
  c.push_back(by_get("Scalex", [] { glScalef(2, 0.5f, -1); }, [] { glScalex(X(2), X(0.5), X(-1)); },
                     GL_MODELVIEW_MATRIX, {X(2), 0, 0, 0, 0, X(0.5), 0, 0, 0, 0, X(-1), 0, 0, 0, 0, X(1)}));
  c.push_back(by_get("Rotatex", [] { glRotatef(90, 0, 0, 1); }, [] { glRotatex(X(90), 0, 0, X(1)); },
                     GL_MODELVIEW_MATRIX, {0, X(1), 0, 0, X(-1), 0, 0, 0, 0, 0, X(1), 0, 0, 0, 0, X(1)}));
  c.push_back(by_get("LoadMatrixx", [] { glLoadMatrixf(kMatrix); }, [] { glLoadMatrixx(kMatrixX); },
                     GL_MODELVIEW_MATRIX, matrix_fixed()));
  c.push_back(by_get("MultMatrixx", [] { glMultMatrixf(kMatrix); }, [] { glMultMatrixx(kMatrixX); },
                     GL_MODELVIEW_MATRIX, matrix_fixed()));
  c.push_back({"ClipPlanex",
               [] { const GLfloat e[] = {1, 0.5f, 0, -2}; glClipPlanef(GL_CLIP_PLANE0, e); },
               [] { const GLfixed e[] = {X(1), X(0.5), 0, X(-2)}; glClipPlanex(GL_CLIP_PLANE0, e); },
               [] { std::vector<GLfloat> v(4); glGetClipPlanef(GL_CLIP_PLANE0, v.data()); return v; },
               [] { std::vector<GLfixed> v(4); glGetClipPlanex(GL_CLIP_PLANE0, v.data()); return v; },
               {X(1), X(0.5), 0, X(-2)}});
  c.push_back({"Lightxv diffuse",
               [] { const GLfloat v[] = {0.5f, 0.25f, 1, 0.75f}; glLightfv(GL_LIGHT1, GL_DIFFUSE, v); },
               [] { const GLfixed v[] = {X(0.5), X(0.25), X(1), X(0.75)}; glLightxv(GL_LIGHT1, GL_DIFFUSE, v); },
               [] { std::vector<GLfloat> v(4); glGetLightfv(GL_LIGHT1, GL_DIFFUSE, v.data()); return v; },
               [] { std::vector<GLfixed> v(4); glGetLightxv(GL_LIGHT1, GL_DIFFUSE, v.data()); return v; },
               {X(0.5), X(0.25), X(1), X(0.75)}});
  c.push_back({"Lightx spot cutoff",
               [] { glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 45); },
               [] { glLightx(GL_LIGHT2, GL_SPOT_CUTOFF, X(45)); },
               [] { std::vector<GLfloat> v(1); glGetLightfv(GL_LIGHT2, GL_SPOT_CUTOFF, v.data()); return v; },
               [] { std::vector<GLfixed> v(1); glGetLightxv(GL_LIGHT2, GL_SPOT_CUTOFF, v.data()); return v; },
               {X(45)}});
  c.push_back({"Materialx shininess",
               [] { glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 32); },
               [] { glMaterialx(GL_FRONT_AND_BACK, GL_SHININESS, X(32)); },
               [] { std::vector<GLfloat> v(1); glGetMaterialfv(GL_BACK, GL_SHININESS, v.data()); return v; },
               [] { std::vector<GLfixed> v(1); glGetMaterialxv(GL_BACK, GL_SHININESS, v.data()); return v; },
               {X(32)}});
  c.push_back({"Materialxv ambient",
               [] { const GLfloat v[] = {0.25f, 0.5f, 0.75f, 1}; glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, v); },
               [] { const GLfixed v[] = {X(0.25), X(0.5), X(0.75), X(1)}; glMaterialxv(GL_FRONT_AND_BACK, GL_AMBIENT, v); },
               [] { std::vector<GLfloat> v(4); glGetMaterialfv(GL_FRONT, GL_AMBIENT, v.data()); return v; },
               [] { std::vector<GLfixed> v(4); glGetMaterialxv(GL_FRONT, GL_AMBIENT, v.data()); return v; },
               {X(0.25), X(0.5), X(0.75), X(1)}});
  c.push_back({"TexEnvx mode",
               [] { glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL); },
               [] { glTexEnvx(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL); },
               [] { std::vector<GLfloat> v(1); glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, v.data()); return v; },
               [] { std::vector<GLfixed> v(1); glGetTexEnvxv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, v.data()); return v; },
               {GL_DECAL}});
  c.push_back({"TexEnvx rgb scale",
               [] { glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2); },
               [] { glTexEnvx(GL_TEXTURE_ENV, GL_RGB_SCALE, X(2)); },
               [] { std::vector<GLfloat> v(1); glGetTexEnvfv(GL_TEXTURE_ENV, GL_RGB_SCALE, v.data()); return v; },
               [] { std::vector<GLfixed> v(1); glGetTexEnvxv(GL_TEXTURE_ENV, GL_RGB_SCALE, v.data()); return v; },
               {X(2)}});
  c.push_back({"TexEnvxv color",
               [] { const GLfloat v[] = {0.5f, 0, 0.25f, 1}; glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, v); },
               [] { const GLfixed v[] = {X(0.5), 0, X(0.25), X(1)}; glTexEnvxv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, v); },
               [] { std::vector<GLfloat> v(4); glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, v.data()); return v; },
               [] { std::vector<GLfixed> v(4); glGetTexEnvxv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, v.data()); return v; },
               {X(0.5), 0, X(0.25), X(1)}});
  c.push_back({"TexParameterx min filter",
               [] { glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST); },
               [] { glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST); },
               [] { std::vector<GLfloat> v(1); glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, v.data()); return v; },
               [] { std::vector<GLfixed> v(1); glGetTexParameterxv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, v.data()); return v; },
               {GL_NEAREST}});
  c.push_back({"TexParameterxv wrap",
               [] { const GLfloat v[] = {GL_CLAMP_TO_EDGE}; glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, v); },
               [] { const GLfixed v[] = {GL_CLAMP_TO_EDGE}; glTexParameterxv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, v); },
               [] { std::vector<GLfloat> v(1); glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, v.data()); return v; },
               [] { std::vector<GLfixed> v(1); glGetTexParameterxv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, v.data()); return v; },
               {GL_CLAMP_TO_EDGE}});
  return c;
}

class FixedPointState : public ::testing::TestWithParam<Case> {};

TEST_P(FixedPointState, MatchesTheFloatForm) {
  const Case& c = GetParam();
  Es1Context with_float, with_fixed;
  ASSERT_TRUE(with_float.ok()) << with_float.error();
  ASSERT_TRUE(with_fixed.ok()) << with_fixed.error();

  ASSERT_TRUE(with_float.make_current());
  c.set_float();
  const std::vector<GLfloat> expected_floats = c.get_float();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

  ASSERT_TRUE(with_fixed.make_current());
  c.set_fixed();
  EXPECT_EQ(c.get_float(), expected_floats);
  EXPECT_EQ(c.get_fixed(), c.expected);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

INSTANTIATE_TEST_SUITE_P(AllEntryPoints, FixedPointState, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name;
                           for (char ch : info.param.name) name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                           return name;
                         });

// glGetFixedv converts as Mesa does: integers times 65536, enum values as they are, booleans
// to 0 or 1.0.
TEST(GetFixedv, ConvertsEachKindOfValue) {
  Es1Context ctx;
  ASSERT_TRUE(ctx.ok()) << ctx.error();
  GLfixed v[2] = {-7, -7};
  glGetFixedv(GL_MAX_TEXTURE_UNITS, v);
  EXPECT_EQ(v[0], 4 * 65536);
  glGetFixedv(GL_MAX_TEXTURE_SIZE, v);
  EXPECT_EQ(v[0], 8192 * 65536);
  glDepthFunc(GL_GEQUAL);
  glGetFixedv(GL_DEPTH_FUNC, v);
  EXPECT_EQ(v[0], GL_GEQUAL);
  glEnable(GL_DEPTH_TEST);
  glGetFixedv(GL_DEPTH_TEST, v);
  EXPECT_EQ(v[0], 65536);
  glGetFixedv(GL_BLEND, v);
  EXPECT_EQ(v[0], 0);
  glGetFixedv(GL_VIEWPORT + 1000, v);  // not a state
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// A getter that fails leaves the caller's array alone.
TEST(GetFixedv, FailedGettersWriteNothing) {
  Es1Context ctx;
  ASSERT_TRUE(ctx.ok()) << ctx.error();
  GLfixed v[4] = {-7, -7, -7, -7};
  glGetClipPlanex(GL_CLIP_PLANE0 + 6, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetLightxv(GL_LIGHT0, GL_TEXTURE_2D, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(v[0], -7);
  EXPECT_EQ(v[3], -7);
}

}  // namespace
}  // namespace pineda::es1_test
