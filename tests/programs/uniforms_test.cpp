// Active uniforms and attributes, uniform locations and glUniform* type checks
// (GL 2.0 2.15.3, GL 2.1's non-square matrices).
#include <cstring>
#include <string>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

const char* kUniformsVertex = R"(#version 120
attribute vec4 position;
attribute vec3 normal_in;
attribute mat2 pair;
uniform mat4 mvp;
uniform mat2x3 skew;
varying vec3 v;
void main() {
  v = normal_in + skew * pair[0] + vec3(pair[1], 0.0);
  gl_Position = mvp * position;
}
)";
const char* kUniformsFragment = R"(#version 120
struct Light { vec3 color; float power; };
uniform Light light;
uniform vec4 tint[3];
uniform int mode;
uniform bool on;
uniform bvec2 flags;
uniform sampler2D tex;
varying vec3 v;
void main() {
  vec4 c = texture2D(tex, v.xy) * tint[0] + tint[2];
  if (mode == 2 && on && flags.y) c.rgb += light.color * light.power;
  gl_FragColor = c;
}
)";

class UniformsTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    program_ = link(kUniformsVertex, kUniformsFragment);
    ASSERT_EQ(program_int(program_, GL_LINK_STATUS), GL_TRUE) << program_log(program_);
    glUseProgram(program_);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
  GLint loc(const char* name) { return glGetUniformLocation(program_, name); }
  // name -> (size, type) of the active uniform, or size -1 when it is not listed.
  std::pair<GLint, GLenum> active(const char* wanted) {
    const GLint n = program_int(program_, GL_ACTIVE_UNIFORMS);
    for (GLint i = 0; i < n; ++i) {
      char name[64];
      GLint size = 0;
      GLenum type = 0;
      glGetActiveUniform(program_, GLuint(i), sizeof name, nullptr, &size, &type, name);
      if (std::strcmp(name, wanted) == 0) return {size, type};
    }
    return {-1, 0};
  }
  GLuint program_ = 0;
};

TEST_F(UniformsTest, ActiveUniformsWithGlTypesAndArrayNames) {
  EXPECT_EQ(program_int(program_, GL_ACTIVE_UNIFORMS), 9);
  EXPECT_EQ(active("mvp"), std::make_pair(GLint(1), GLenum(GL_FLOAT_MAT4)));
  EXPECT_EQ(active("skew"), std::make_pair(GLint(1), GLenum(GL_FLOAT_MAT2x3)));
  EXPECT_EQ(active("tint[0]"), std::make_pair(GLint(3), GLenum(GL_FLOAT_VEC4)));
  EXPECT_EQ(active("mode"), std::make_pair(GLint(1), GLenum(GL_INT)));
  EXPECT_EQ(active("on"), std::make_pair(GLint(1), GLenum(GL_BOOL)));
  EXPECT_EQ(active("flags"), std::make_pair(GLint(1), GLenum(GL_BOOL_VEC2)));
  EXPECT_EQ(active("tex"), std::make_pair(GLint(1), GLenum(GL_SAMPLER_2D)));
  EXPECT_EQ(active("light.color"), std::make_pair(GLint(1), GLenum(GL_FLOAT_VEC3)));
  EXPECT_EQ(active("light.power"), std::make_pair(GLint(1), GLenum(GL_FLOAT)));
  // "light.color" is the longest name: 11 characters and the NUL.
  EXPECT_EQ(program_int(program_, GL_ACTIVE_UNIFORM_MAX_LENGTH), 12);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(UniformsTest, GetActiveUniformErrors) {
  char name[8];
  GLint size;
  GLenum type;
  glGetActiveUniform(program_, 9, sizeof name, nullptr, &size, &type, name);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGetActiveUniform(program_, 0, -1, nullptr, &size, &type, name);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLsizei length = -1;
  glGetActiveUniform(program_, 0, 3, &length, &size, &type, name);
  EXPECT_EQ(length, 2);
  EXPECT_EQ(std::strlen(name), 2u);
}

TEST_F(UniformsTest, ActiveAttributes) {
  EXPECT_EQ(program_int(program_, GL_ACTIVE_ATTRIBUTES), 3);
  EXPECT_EQ(program_int(program_, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH), 10);  // "normal_in"
  bool seen_pair = false;
  for (GLuint i = 0; i < 3; ++i) {
    char name[32];
    GLint size = 0;
    GLenum type = 0;
    glGetActiveAttrib(program_, i, sizeof name, nullptr, &size, &type, name);
    EXPECT_EQ(size, 1);
    if (std::strcmp(name, "pair") == 0) {
      seen_pair = true;
      EXPECT_EQ(type, GLenum(GL_FLOAT_MAT2));
    }
  }
  EXPECT_TRUE(seen_pair);
  char name[8];
  glGetActiveAttrib(program_, 3, sizeof name, nullptr, nullptr, nullptr, name);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  const GLint position = glGetAttribLocation(program_, "position");
  const GLint pair = glGetAttribLocation(program_, "pair");
  EXPECT_GE(position, 0);
  EXPECT_GE(pair, 0);
  EXPECT_EQ(glGetAttribLocation(program_, "missing"), -1);
  EXPECT_EQ(glGetAttribLocation(program_, "gl_Vertex"), -1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(UniformsTest, BindAttribLocationTakesEffectAtTheNextLink) {
  glBindAttribLocation(program_, 7, "normal_in");
  EXPECT_NE(glGetAttribLocation(program_, "normal_in"), 7);
  glLinkProgram(program_);
  ASSERT_EQ(program_int(program_, GL_LINK_STATUS), GL_TRUE);
  EXPECT_EQ(glGetAttribLocation(program_, "normal_in"), 7);
  glBindAttribLocation(program_, 16, "position");
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBindAttribLocation(program_, 3, "gl_Normal");
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  const GLuint unlinked = glCreateProgram();
  EXPECT_EQ(glGetAttribLocation(unlinked, "position"), -1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(UniformsTest, LocationsOfElementsAndMembers) {
  const GLint t0 = loc("tint"), t0b = loc("tint[0]"), t2 = loc("tint[2]");
  EXPECT_GE(t0, 0);
  EXPECT_EQ(t0, t0b);
  EXPECT_GE(t2, 0);
  EXPECT_NE(t2, t0);
  EXPECT_EQ(loc("tint[3]"), -1);
  EXPECT_EQ(loc("mode[0]"), -1);
  EXPECT_GE(loc("light.power"), 0);
  EXPECT_EQ(loc("light"), -1);
  EXPECT_EQ(loc("gl_ModelViewMatrix"), -1);
  EXPECT_EQ(loc("nothing"), -1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(UniformsTest, ValuesRoundTripThroughGetUniform) {
  const GLfloat m[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  glUniformMatrix4fv(loc("mvp"), 1, GL_FALSE, m);
  GLfloat got[16] = {};
  glGetUniformfv(program_, loc("mvp"), got);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(got[i], m[i]);
  glUniformMatrix4fv(loc("mvp"), 1, GL_TRUE, m);
  glGetUniformfv(program_, loc("mvp"), got);
  EXPECT_EQ(got[1], 5.f);  // transposed: column 0 is the first row given
  EXPECT_EQ(got[4], 2.f);
  const GLfloat skew[6] = {1, 2, 3, 4, 5, 6};
  glUniformMatrix2x3fv(loc("skew"), 1, GL_FALSE, skew);
  glGetUniformfv(program_, loc("skew"), got);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(got[i], skew[i]);
  const GLfloat tints[8] = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f};
  glUniform4fv(loc("tint[1]"), 5, tints);  // only elements 1 and 2 exist
  glGetUniformfv(program_, loc("tint[2]"), got);
  EXPECT_EQ(got[0], 0.5f);
  EXPECT_EQ(got[3], 0.8f);
  glUniform1i(loc("mode"), -7);
  GLint gi = 0;
  glGetUniformiv(program_, loc("mode"), &gi);
  EXPECT_EQ(gi, -7);
  glUniform1f(loc("on"), 0.5f);  // bools take either form; non-zero is true
  glGetUniformiv(program_, loc("on"), &gi);
  EXPECT_EQ(gi, 1);
  glUniform2i(loc("flags"), 0, 9);
  GLint flags[2] = {-1, -1};
  glGetUniformiv(program_, loc("flags"), flags);
  EXPECT_EQ(flags[0], 0);
  EXPECT_EQ(flags[1], 1);
  glUniform3f(loc("light.color"), 1, 0.5f, 0.25f);
  glGetUniformfv(program_, loc("light.color"), got);
  EXPECT_EQ(got[1], 0.5f);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(UniformsTest, TypeAndSizeMismatchesAreInvalidOperation) {
  glUniform3f(loc("tint"), 1, 2, 3);  // vec4
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glUniform4i(loc("tint"), 1, 2, 3, 4);  // float type with an int call
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glUniform1f(loc("mode"), 1.f);  // int type with a float call
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glUniform1f(loc("tex"), 0.f);  // samplers: glUniform1i(v) only
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  const GLint two[2] = {0, 1};
  glUniform1iv(loc("mode"), 2, two);  // count > 1 on a non-array
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  const GLfloat m[9] = {};
  glUniformMatrix3fv(loc("mvp"), 1, GL_FALSE, m);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glUniformMatrix3x2fv(loc("skew"), 1, GL_FALSE, m);  // skew is 2 columns of 3
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glUniform4f(1000, 1, 2, 3, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glUniform4f(-2, 1, 2, 3, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glUniform4fv(loc("tint"), -1, m);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glUniform1i(loc("tex"), 99);  // beyond the texture units
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLint unit = -1;
  glGetUniformiv(program_, loc("tex"), &unit);
  EXPECT_EQ(unit, 0);
  glUniform1i(loc("tex"), 3);
  glGetUniformiv(program_, loc("tex"), &unit);
  EXPECT_EQ(unit, 3);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(UniformsTest, LocationMinusOneIsIgnoredSilently) {
  glUniform4f(-1, 1, 2, 3, 4);
  glUniform1i(-1, 5);
  const GLfloat m[16] = {};
  glUniformMatrix4fv(-1, 1, GL_FALSE, m);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(UniformsTest, UniformWithoutAProgramInUseIsInvalidOperation) {
  glUseProgram(0);
  glUniform1f(loc("tint"), 1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glUniform1f(-1, 1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(UniformsTest, GetUniformErrors) {
  GLfloat f[16];
  glGetUniformfv(program_, -1, f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glGetUniformfv(program_, 500, f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glGetUniformfv(9999, 0, f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  const GLuint unlinked = glCreateProgram();
  glGetUniformfv(unlinked, 0, f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(glGetUniformLocation(unlinked, "tint"), -1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(UniformsTest, UniformsStartAtZeroAndRelinkResetsThem) {
  GLfloat got[4] = {9, 9, 9, 9};
  glGetUniformfv(program_, loc("tint[1]"), got);
  EXPECT_EQ(got[0], 0.f);
  EXPECT_EQ(got[3], 0.f);
  glUniform4f(loc("tint[1]"), 1, 2, 3, 4);
  glLinkProgram(program_);
  glGetUniformfv(program_, loc("tint[1]"), got);
  EXPECT_EQ(got[0], 0.f);
}

TEST_F(UniformsTest, ValidateReportsSamplersOfTwoTypesOnOneUnit) {
  const GLuint p = link("void main() { gl_Position = gl_Vertex; }\n",
                        "uniform sampler2D a; uniform samplerCube b;\n"
                        "void main() { gl_FragColor = texture2D(a, vec2(0.5)) + textureCube(b, vec3(1.0)); }\n");
  ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
  glValidateProgram(p);
  EXPECT_EQ(program_int(p, GL_VALIDATE_STATUS), GL_FALSE);  // both on unit 0
  glUseProgram(p);
  glUniform1i(glGetUniformLocation(p, "b"), 1);
  glValidateProgram(p);
  EXPECT_EQ(program_int(p, GL_VALIDATE_STATUS), GL_TRUE);
  glUniform1i(glGetUniformLocation(p, "b"), 0);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(1, 0);
  glVertex2f(0, 1);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // detected at the draw
}

TEST_F(UniformsTest, UniformsInADisplayListAreCopiedAtCompileTime) {
  const GLint t = loc("tint[1]");
  GLfloat values[4] = {1, 2, 3, 4};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glUniform4fv(t, 1, values);
  glEndList();
  values[0] = 100;
  GLfloat got[4] = {};
  glGetUniformfv(program_, t, got);
  EXPECT_EQ(got[0], 0.f);  // GL_COMPILE does not execute
  glCallList(list);
  glGetUniformfv(program_, t, got);
  EXPECT_EQ(got[0], 1.f);
  EXPECT_EQ(got[3], 4.f);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

using UniformInitializerTest = ProgramTest;

TEST_F(UniformInitializerTest, Glsl120InitializersAreTheStartingValues) {
  const GLuint p = link("void main() { gl_Position = gl_Vertex; }\n",
                        "#version 120\nuniform vec2 k = vec2(0.25, 0.5); uniform float z;\n"
                        "void main() { gl_FragColor = vec4(k, z, 1.0); }\n");
  ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
  GLfloat got[2] = {};
  glGetUniformfv(p, glGetUniformLocation(p, "k"), got);
  EXPECT_EQ(got[0], 0.25f);
  EXPECT_EQ(got[1], 0.5f);
  glGetUniformfv(p, glGetUniformLocation(p, "z"), got);
  EXPECT_EQ(got[0], 0.f);
}

// An unread uniform with an initializer stays active (as Mesa; piglit uniform-initializer
// *-set-by-API): it has a location and its value; an unread one without is inactive.
TEST_F(UniformInitializerTest, UnreadInitializedUniformsAreActive) {
  const GLuint p = link("void main() { gl_Position = gl_Vertex; }\n",
                        "#version 120\nuniform float unread = 0.75; uniform float plain;\n"
                        "void main() { gl_FragColor = vec4(1.0); }\n");
  ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
  const GLint location = glGetUniformLocation(p, "unread");
  ASSERT_GE(location, 0);
  GLfloat got = 0.f;
  glGetUniformfv(p, location, &got);
  EXPECT_EQ(got, 0.75f);
  EXPECT_EQ(glGetUniformLocation(p, "plain"), -1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
