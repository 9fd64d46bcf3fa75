// GL 2.0 2.15.3 (ES 2.0 2.10.4): a sampler2D and a samplerCube on one texture unit make the
// next draw GL_INVALID_OPERATION, which draws nothing, and glValidateProgram fail with a log
// that names the unit and both types, as Mesa's does.
#include <string>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

// No texture is bound: both lookups read (0, 0, 0, 1), and the colour is green.
const char* kTwoTypesFs =
    "uniform sampler2D a;\n"
    "uniform samplerCube b;\n"
    "void main() {\n"
    "  vec3 zero = texture2D(a, vec2(0.5)).rgb + textureCube(b, vec3(1.0, 0.0, 0.0)).rgb;\n"
    "  gl_FragColor = vec4(zero.r, 1.0 - zero.g, zero.b, 1.0);\n"
    "}\n";

class SamplerUnitConflictTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    program_ = link("void main() { gl_Position = gl_Vertex; }\n", kTwoTypesFs);
    ASSERT_EQ(program_int(program_, GL_LINK_STATUS), GL_TRUE) << program_log(program_);
    glUseProgram(program_);
    clear_to(1, 0, 0, 1);
  }
  void TearDown() override {
    glUseProgram(0);
    glDeleteProgram(program_);
    ProgramTest::TearDown();
  }
  void set_units(int a, int b) {
    glUniform1i(glGetUniformLocation(program_, "a"), a);
    glUniform1i(glGetUniformLocation(program_, "b"), b);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
  static void draw_full_screen() {
    static const float corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, corners);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glDisableClientState(GL_VERTEX_ARRAY);
  }
  GLint validate() {
    glValidateProgram(program_);
    return program_int(program_, GL_VALIDATE_STATUS);
  }

  GLuint program_ = 0;
};

TEST_F(SamplerUnitConflictTest, DrawIsInvalidOperationAndDrawsNothing) {
  set_units(3, 3);
  draw_full_screen();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(pixel(5, 5), (Rgba{255, 0, 0, 255}));  // the clear colour
}

TEST_F(SamplerUnitConflictTest, ValidateFailsAndSaysWhy) {
  set_units(3, 3);
  EXPECT_EQ(validate(), GL_FALSE);
  EXPECT_EQ(program_log(program_), "Texture unit 3 is accessed both as sampler2D and samplerCube");
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SamplerUnitConflictTest, DifferentUnitsDrawAndValidate) {
  set_units(3, 4);
  draw_full_screen();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(pixel(5, 5), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(validate(), GL_TRUE);
  EXPECT_EQ(program_log(program_), "");
}

TEST_F(SamplerUnitConflictTest, MovingASamplerAwayEndsTheConflict) {
  set_units(2, 2);
  draw_full_screen();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  set_units(2, 0);
  draw_full_screen();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(pixel(5, 5), (Rgba{0, 255, 0, 255}));
  set_units(0, 0);  // and back: both start at unit 0 after a link too
  EXPECT_EQ(validate(), GL_FALSE);
  glLinkProgram(program_);
  EXPECT_EQ(validate(), GL_FALSE);
  EXPECT_EQ(program_log(program_), "Texture unit 0 is accessed both as sampler2D and samplerCube");
}

}  // namespace
}  // namespace pineda::test
