// Multitexture (GL 1.3 / GL_ARB_multitexture): per-unit coordinates, texture matrices,
// enables, environments, bindings and client arrays; queries, attribute stacks, lists, errors.
#include "tests/e2e/support/gl_test.h"

#include <GL/glext.h>

namespace pineda::test {
namespace {

// Unit 0: texels (200,100,50,255) (10,20,30,255). Unit 1: (255,255,255,255) (128,255,64,128).
// s = 0.25 picks texel 0 and s = 0.75 texel 1 (NEAREST).
constexpr Rgba kUnit0Texel0{200, 100, 50, 255};
constexpr Rgba kUnit0Texel1{10, 20, 30, 255};
// Unit 0's texel 0 modulated by unit 1's texel 1: 200*128/255 = 100.4, 50*64/255 = 12.5.
constexpr Rgba kTexel0TimesTexel1{100, 100, 13, 128};

class MultitextureTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    const uint8_t unit0[] = {200, 100, 50, 255, 10, 20, 30, 255};
    const uint8_t unit1[] = {255, 255, 255, 255, 128, 255, 64, 128};
    load_unit(GL_TEXTURE0, 1, unit0, GL_REPLACE);
    load_unit(GL_TEXTURE1, 2, unit1, GL_MODULATE);
    glActiveTexture(GL_TEXTURE0);
  }

  void load_unit(GLenum unit, GLuint name, const uint8_t* texels, GLint env) {
    glActiveTexture(unit);
    glBindTexture(GL_TEXTURE_2D, name);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, env);
    glEnable(GL_TEXTURE_2D);
  }

  // A 4x4 square at the origin with constant coordinates s0 on unit 0 and s1 on unit 1.
  void square(float s0, float s1) {
    glBegin(GL_QUADS);
    glMultiTexCoord2f(GL_TEXTURE0, s0, 0.5f);
    glMultiTexCoord2f(GL_TEXTURE1, s1, 0.5f);
    glVertex2f(0, 0);
    glVertex2f(4, 0);
    glVertex2f(4, 4);
    glVertex2f(0, 4);
    glEnd();
  }
};

TEST_F(MultitextureTest, SecondUnitModulatesTheFirst) {
  square(0.25f, 0.75f);
  EXPECT_TRUE(near_rgba(pixel(1, 1), kTexel0TimesTexel1));
  EXPECT_TRUE(near_rgba(pixel(5, 5), {0, 0, 0, 0}));
}

TEST_F(MultitextureTest, EachUnitReadsItsOwnCoordinates) {
  square(0.75f, 0.25f);  // unit 1's texel 0 is white: unit 0's texel 1 unchanged
  EXPECT_TRUE(near_rgba(pixel(2, 2), kUnit0Texel1));
}

TEST_F(MultitextureTest, TexCoordSetsUnitZeroOnly) {
  glMultiTexCoord2f(GL_TEXTURE1, 0.75f, 0.5f);
  glTexCoord2f(0.25f, 0.5f);
  float unit1[4] = {};
  glActiveTexture(GL_TEXTURE1);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, unit1);
  EXPECT_EQ(unit1[0], 0.75f);
  glActiveTexture(GL_TEXTURE0);
  float unit0[4] = {};
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, unit0);
  EXPECT_EQ(unit0[0], 0.25f);
  EXPECT_EQ(unit0[3], 1.f);
}

TEST_F(MultitextureTest, DisabledUnitIsSkipped) {
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_TEXTURE_2D);
  glColor4ub(255, 0, 255, 255);
  square(0.25f, 0.75f);  // the fragment colour modulated by unit 1's texel 1
  EXPECT_TRUE(near_rgba(pixel(1, 1), {128, 0, 64, 128}));
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_2D), GL_FALSE);
  glActiveTexture(GL_TEXTURE1);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_2D), GL_TRUE);
}

TEST_F(MultitextureTest, TextureMatrixIsPerUnit) {
  glActiveTexture(GL_TEXTURE1);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.5f, 0, 0);
  glMatrixMode(GL_MODELVIEW);
  square(0.25f, 0.25f);  // unit 1 reads s = 0.75, unit 0 stays at 0.25
  EXPECT_TRUE(near_rgba(pixel(1, 1), kTexel0TimesTexel1));
  float m[16];
  glGetFloatv(GL_TEXTURE_MATRIX, m);
  EXPECT_EQ(m[12], 0.5f);
  glActiveTexture(GL_TEXTURE0);
  glGetFloatv(GL_TEXTURE_MATRIX, m);
  EXPECT_EQ(m[12], 0.f);
}

TEST_F(MultitextureTest, ClientArraysPerUnit) {
  const float vertices[] = {0, 0, 4, 0, 4, 4, 0, 4};
  const float coords0[] = {0.25f, 0.5f, 0.25f, 0.5f, 0.25f, 0.5f, 0.25f, 0.5f};
  const float coords1[] = {0.75f, 0.5f, 0.75f, 0.5f, 0.75f, 0.5f, 0.75f, 0.5f};
  glVertexPointer(2, GL_FLOAT, 0, vertices);
  glEnableClientState(GL_VERTEX_ARRAY);
  glClientActiveTexture(GL_TEXTURE0);
  glTexCoordPointer(2, GL_FLOAT, 0, coords0);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glClientActiveTexture(GL_TEXTURE1);
  glTexCoordPointer(2, GL_FLOAT, 0, coords1);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_TRUE(near_rgba(pixel(1, 1), kTexel0TimesTexel1));

  void* pointer = nullptr;
  glGetPointerv(GL_TEXTURE_COORD_ARRAY_POINTER, &pointer);
  EXPECT_EQ(pointer, coords1);
  glClientActiveTexture(GL_TEXTURE0);
  glGetPointerv(GL_TEXTURE_COORD_ARRAY_POINTER, &pointer);
  EXPECT_EQ(pointer, coords0);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);  // unit 0 now takes its current coordinate
  glMultiTexCoord2f(GL_TEXTURE0, 0.75f, 0.5f);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_TRUE(near_rgba(pixel(1, 1), {5, 20, 8, 128}));  // (10,20,30,255) x (128,255,64,128)
}

TEST_F(MultitextureTest, QueriesAreUnitSelected) {
  GLint v = 0;
  glGetIntegerv(GL_MAX_TEXTURE_UNITS, &v);
  EXPECT_EQ(v, 4);
  glActiveTexture(GL_TEXTURE1);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE1);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &v);
  EXPECT_EQ(v, 2);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  EXPECT_EQ(v, GL_MODULATE);
  glActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &v);
  EXPECT_EQ(v, 1);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  EXPECT_EQ(v, GL_REPLACE);
  glClientActiveTexture(GL_TEXTURE3);
  glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE3);
  glActiveTexture(GL_TEXTURE3);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &v);
  EXPECT_EQ(v, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(MultitextureTest, UnitsBeyondTheLastAreInvalidEnums) {
  glActiveTexture(GL_TEXTURE2);
  glActiveTexture(GL_TEXTURE8);  // past the 8 texture image units
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint v = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE2);
  glClientActiveTexture(GL_TEXTURE0 - 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE0);
  glMultiTexCoord2f(GL_TEXTURE4, 1, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glMultiTexCoord1f(GL_TEXTURE_2D, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(MultitextureTest, IntegerAndVectorVariantsSetAllComponents) {
  const GLshort sv[4] = {1, 2, 3, 4};
  glMultiTexCoord4sv(GL_TEXTURE2, sv);
  glActiveTexture(GL_TEXTURE2);
  float t[4] = {};
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
  EXPECT_EQ(t[0], 1.f);
  EXPECT_EQ(t[1], 2.f);
  EXPECT_EQ(t[2], 3.f);
  EXPECT_EQ(t[3], 4.f);
  glMultiTexCoord3iARB(GL_TEXTURE2, 5, 6, 7);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
  EXPECT_EQ(t[0], 5.f);
  EXPECT_EQ(t[2], 7.f);
  EXPECT_EQ(t[3], 1.f);
  glMultiTexCoord1d(GL_TEXTURE2, 0.5);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
  EXPECT_EQ(t[0], 0.5f);
  EXPECT_EQ(t[1], 0.f);
  EXPECT_EQ(t[2], 0.f);
  EXPECT_EQ(t[3], 1.f);
}

TEST_F(MultitextureTest, PushAttribTextureBitRestoresActiveUnitAndEnvs) {
  glActiveTexture(GL_TEXTURE1);
  glPushAttrib(GL_TEXTURE_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  glDisable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, 7);
  glPopAttrib();
  GLint v = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE1);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  EXPECT_EQ(v, GL_MODULATE);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_2D), GL_TRUE);
  glActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &v);
  EXPECT_EQ(v, 1);
}

TEST_F(MultitextureTest, PushClientAttribRestoresClientActiveUnit) {
  glClientActiveTexture(GL_TEXTURE2);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glClientActiveTexture(GL_TEXTURE3);
  glPopClientAttrib();
  GLint v = 0;
  glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE2);
}

TEST_F(MultitextureTest, DisplayListsRecordActiveTextureAndCoordinates) {
  glNewList(1, GL_COMPILE);
  glActiveTexture(GL_TEXTURE1);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glActiveTexture(GL_TEXTURE0);
  glBegin(GL_QUADS);
  glMultiTexCoord2f(GL_TEXTURE0, 0.25f, 0.5f);
  glMultiTexCoord2f(GL_TEXTURE1, 0.75f, 0.5f);
  glVertex2f(0, 0);
  glVertex2f(4, 0);
  glVertex2f(4, 4);
  glVertex2f(0, 4);
  glEnd();
  glEndList();
  GLint v = 0;
  glActiveTexture(GL_TEXTURE1);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  EXPECT_EQ(v, GL_MODULATE);  // compiled, not executed
  glCallList(1);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  EXPECT_EQ(v, GL_REPLACE);
  EXPECT_TRUE(near_rgba(pixel(1, 1), {128, 255, 64, 128}));  // unit 1 replaces with its texel 1
}

TEST_F(MultitextureTest, FourUnitsAllApply) {
  const uint8_t half[] = {128, 128, 128, 255, 128, 128, 128, 255};
  load_unit(GL_TEXTURE2, 3, half, GL_MODULATE);
  load_unit(GL_TEXTURE3, 4, half, GL_MODULATE);
  glActiveTexture(GL_TEXTURE1);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  square(0.25f, 0.25f);  // (200,100,50) + white = white, then x 128/255 twice: 64.25
  EXPECT_TRUE(near_rgba(pixel(1, 1), {64, 64, 64, 255}));
}

}  // namespace
}  // namespace pineda::test
