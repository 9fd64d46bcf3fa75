// GL 2.0 texture image units: 8 units that shaders sample (their bindings, sampler uniforms,
// the limits), of which the first 4 (MAX_TEXTURE_UNITS, MAX_TEXTURE_COORDS) also have
// fixed-function state; that state of units 4..7 gives GL_INVALID_OPERATION.
#include <string>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

const char* kUnitsPassVs = "void main() { gl_Position = gl_Vertex; }\n";

// Unit i holds a 1x1 texture of (1 << i, 10 * i, 255 - i, 255).
const char* kEightSamplersFs =
    "uniform sampler2D t0, t1, t2, t3, t4, t5, t6, t7;\n"
    "uniform int which;\n"
    "void main() {\n"
    "  vec2 c = vec2(0.5);\n"
    "  vec4 r = texture2D(t0, c);\n"
    "  if (which == 1) r = texture2D(t1, c);\n"
    "  if (which == 2) r = texture2D(t2, c);\n"
    "  if (which == 3) r = texture2D(t3, c);\n"
    "  if (which == 4) r = texture2D(t4, c);\n"
    "  if (which == 5) r = texture2D(t5, c);\n"
    "  if (which == 6) r = texture2D(t6, c);\n"
    "  if (which == 7) r = texture2D(t7, c);\n"
    "  if (which == 8) r = vec4(texture2D(t0, c).r + texture2D(t1, c).r + texture2D(t2, c).r + texture2D(t3, c).r +\n"
    "                           texture2D(t4, c).r + texture2D(t5, c).r + texture2D(t6, c).r + texture2D(t7, c).r,\n"
    "                           0.0, 0.0, 1.0);\n"
    "  gl_FragColor = r;\n"
    "}\n";

class TextureImageUnitsTest : public ProgramTest {
 protected:
  void full_screen() {
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
  }
  void bind_unit_textures() {
    for (int i = 0; i < 8; ++i) {
      const GLubyte texel[4] = {GLubyte(1 << i), GLubyte(10 * i), GLubyte(255 - i), 255};
      glActiveTexture(GL_TEXTURE0 + i);
      glBindTexture(GL_TEXTURE_2D, 100 + i);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    }
    glActiveTexture(GL_TEXTURE0);
  }
  GLint get_int(GLenum pname) {
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
  }
};

TEST_F(TextureImageUnitsTest, Limits) {
  EXPECT_EQ(get_int(GL_MAX_TEXTURE_IMAGE_UNITS), 8);
  EXPECT_EQ(get_int(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS), 8);
  EXPECT_EQ(get_int(GL_MAX_TEXTURE_UNITS), 4);
  EXPECT_EQ(get_int(GL_MAX_TEXTURE_COORDS), 4);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureImageUnitsTest, EightSamplersReadTheirOwnUnits) {
  bind_unit_textures();
  const GLuint p = link(kUnitsPassVs, kEightSamplersFs);
  ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
  glUseProgram(p);
  for (int i = 0; i < 8; ++i) glUniform1i(glGetUniformLocation(p, ("t" + std::to_string(i)).c_str()), i);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const GLint which = glGetUniformLocation(p, "which");
  for (int i = 0; i < 8; ++i) {
    glUniform1i(which, i);
    full_screen();
    EXPECT_TRUE(near_rgba(pixel(5, 5), {uint8_t(1 << i), uint8_t(10 * i), uint8_t(255 - i), 255})) << "unit " << i;
  }
  glUniform1i(which, 8);  // 1 + 2 + ... + 128: every unit read once
  full_screen();
  EXPECT_TRUE(near_rgba(pixel(5, 5), {255, 0, 0, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureImageUnitsTest, SamplerValuesPastTheLastUnitAreInvalid) {
  const GLuint p = link(kUnitsPassVs, kEightSamplersFs);
  ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
  glUseProgram(p);
  const GLint t0 = glGetUniformLocation(p, "t0");
  glUniform1i(t0, 7);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glUniform1i(t0, 8);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLint v = -1;
  glGetUniformiv(p, t0, &v);
  EXPECT_EQ(v, 7);
}

TEST_F(TextureImageUnitsTest, SamplersOfTwoTypesOnUnitSixFailValidation) {
  const GLuint p = link(kUnitsPassVs,
                        "uniform sampler2D a; uniform samplerCube b;\n"
                        "void main() { gl_FragColor = texture2D(a, vec2(0.5)) + textureCube(b, vec3(1.0)); }\n");
  ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
  glUseProgram(p);
  glUniform1i(glGetUniformLocation(p, "a"), 6);
  glUniform1i(glGetUniformLocation(p, "b"), 7);
  glValidateProgram(p);
  EXPECT_EQ(program_int(p, GL_VALIDATE_STATUS), GL_TRUE);
  glUniform1i(glGetUniformLocation(p, "b"), 6);
  glValidateProgram(p);
  EXPECT_EQ(program_int(p, GL_VALIDATE_STATUS), GL_FALSE);
}

TEST_F(TextureImageUnitsTest, ActiveTextureTakesEightUnitsAndClientActiveTextureFour) {
  glActiveTexture(GL_TEXTURE7);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_ACTIVE_TEXTURE), GL_TEXTURE7);
  glActiveTexture(GL_TEXTURE8);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_ACTIVE_TEXTURE), GL_TEXTURE7);
  glClientActiveTexture(GL_TEXTURE4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glMultiTexCoord2f(GL_TEXTURE4, 1, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(TextureImageUnitsTest, BindingsOfEveryTargetPerUnit) {
  glActiveTexture(GL_TEXTURE5);
  glBindTexture(GL_TEXTURE_1D, 11);
  glBindTexture(GL_TEXTURE_2D, 12);
  glBindTexture(GL_TEXTURE_3D, 13);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 14);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_1D), 11);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), 12);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_3D), 13);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_CUBE_MAP), 14);
  glActiveTexture(GL_TEXTURE1);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), 0);
  glActiveTexture(GL_TEXTURE5);
  const GLuint deleted = 12;
  glDeleteTextures(1, &deleted);  // a deleted texture unbinds from unit 5 too
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureImageUnitsTest, FixedFunctionStateOfUnitsPastFourIsInvalidOperation) {
  glActiveTexture(GL_TEXTURE4);
  glMatrixMode(GL_TEXTURE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const GLfloat m[16] = {2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const auto expect_invalid_operation = [](const char* what) {
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION)) << what;
  };
  glLoadIdentity();
  expect_invalid_operation("glLoadIdentity");
  glLoadMatrixf(m);
  expect_invalid_operation("glLoadMatrixf");
  glMultMatrixf(m);
  expect_invalid_operation("glMultMatrixf");
  glRotatef(90, 0, 0, 1);
  expect_invalid_operation("glRotatef");
  glTranslatef(1, 0, 0);
  expect_invalid_operation("glTranslatef");
  glScalef(2, 2, 2);
  expect_invalid_operation("glScalef");
  glOrtho(0, 1, 0, 1, -1, 1);
  expect_invalid_operation("glOrtho");
  glPushMatrix();
  expect_invalid_operation("glPushMatrix");
  glPopMatrix();
  expect_invalid_operation("glPopMatrix");
  GLfloat f[16] = {};
  glGetFloatv(GL_TEXTURE_MATRIX, f);
  expect_invalid_operation("GL_TEXTURE_MATRIX");
  glGetFloatv(GL_TRANSPOSE_TEXTURE_MATRIX, f);
  expect_invalid_operation("GL_TRANSPOSE_TEXTURE_MATRIX");
  glGetFloatv(GL_TEXTURE_STACK_DEPTH, f);
  expect_invalid_operation("GL_TEXTURE_STACK_DEPTH");
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, f);
  expect_invalid_operation("GL_CURRENT_TEXTURE_COORDS");
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, f);
  expect_invalid_operation("GL_CURRENT_RASTER_TEXTURE_COORDS");
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  expect_invalid_operation("glTexEnvi");
  GLint v = -1;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  expect_invalid_operation("glGetTexEnviv");
  EXPECT_EQ(v, -1);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  expect_invalid_operation("glTexGeni");
  glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &v);
  expect_invalid_operation("glGetTexGeniv");
  EXPECT_EQ(v, -1);
  for (GLenum cap : {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_Q}) {
    glEnable(cap);
    expect_invalid_operation("glEnable");
    glDisable(cap);
    expect_invalid_operation("glDisable");
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE);
    expect_invalid_operation("glIsEnabled");
    GLboolean b = GL_TRUE;
    glGetBooleanv(cap, &b);
    expect_invalid_operation("glGetBooleanv");
  }
  // The same calls on unit 3, and the modelview stack on unit 4, work.
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glActiveTexture(GL_TEXTURE3);
  glMatrixMode(GL_TEXTURE);
  glLoadMatrixf(m);
  glGetFloatv(GL_TEXTURE_MATRIX, f);
  EXPECT_EQ(f[0], 2.f);
  glEnable(GL_TEXTURE_2D);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_2D), GL_TRUE);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TextureImageUnitsTest, PushPopAttribRestoresTheBindingsOfUnitsFourToSeven) {
  for (int u = 4; u < 8; ++u) {
    glActiveTexture(GL_TEXTURE0 + u);
    glBindTexture(GL_TEXTURE_2D, 20 + u);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 30 + u);
  }
  glActiveTexture(GL_TEXTURE6);
  glPushAttrib(GL_TEXTURE_BIT);
  for (int u = 4; u < 8; ++u) {
    glActiveTexture(GL_TEXTURE0 + u);
    glBindTexture(GL_TEXTURE_2D, 40 + u);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  }
  glActiveTexture(GL_TEXTURE1);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_ACTIVE_TEXTURE), GL_TEXTURE6);
  for (int u = 4; u < 8; ++u) {
    glActiveTexture(GL_TEXTURE0 + u);
    EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), 20 + u) << "unit " << u;
    EXPECT_EQ(get_int(GL_TEXTURE_BINDING_CUBE_MAP), 30 + u) << "unit " << u;
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
