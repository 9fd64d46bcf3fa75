// Shader and program objects: names, deferred deletion, queries and their errors
// (GL 2.0 2.15.1, 2.15.2, 6.1.14).
#include <cstring>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

const char* kVs = "void main() { gl_Position = gl_Vertex; }\n";
const char* kFs = "void main() { gl_FragColor = vec4(1.0, 0.0, 0.0, 1.0); }\n";

using ShaderObjectsTest = ProgramTest;

TEST_F(ShaderObjectsTest, CreateShaderRejectsOtherTypes) {
  EXPECT_EQ(glCreateShader(GL_TEXTURE_2D), 0u);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(ShaderObjectsTest, ShadersAndProgramsShareOneNameSpace) {
  const GLuint s = glCreateShader(GL_VERTEX_SHADER);
  const GLuint p = glCreateProgram();
  EXPECT_NE(s, 0u);
  EXPECT_NE(p, 0u);
  EXPECT_NE(s, p);
  EXPECT_TRUE(glIsShader(s));
  EXPECT_FALSE(glIsProgram(s));
  EXPECT_TRUE(glIsProgram(p));
  EXPECT_FALSE(glIsShader(p));
  EXPECT_FALSE(glIsShader(0));
  EXPECT_FALSE(glIsProgram(12345));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ShaderObjectsTest, WrongKindIsInvalidOperationUnknownNameInvalidValue) {
  const GLuint s = glCreateShader(GL_VERTEX_SHADER);
  const GLuint p = glCreateProgram();
  GLint v = 0;
  glGetShaderiv(p, GL_SHADER_TYPE, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glGetShaderiv(9999, GL_SHADER_TYPE, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGetProgramiv(s, GL_LINK_STATUS, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glGetProgramiv(9999, GL_LINK_STATUS, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCompileShader(p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glLinkProgram(s);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glAttachShader(p, p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glAttachShader(s, s);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glAttachShader(p, 9999);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glUseProgram(s);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glUseProgram(9999);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDeleteShader(p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDeleteProgram(s);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDeleteShader(0);
  glDeleteProgram(0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ShaderObjectsTest, ShaderQueriesBeforeAndAfterCompile) {
  const GLuint s = glCreateShader(GL_FRAGMENT_SHADER);
  EXPECT_EQ(shader_int(s, GL_SHADER_TYPE), GL_FRAGMENT_SHADER);
  EXPECT_EQ(shader_int(s, GL_COMPILE_STATUS), GL_FALSE);
  EXPECT_EQ(shader_int(s, GL_DELETE_STATUS), GL_FALSE);
  EXPECT_EQ(shader_int(s, GL_SHADER_SOURCE_LENGTH), 0);
  EXPECT_EQ(shader_int(s, GL_INFO_LOG_LENGTH), 0);
  const char* parts[2] = {"void main() { gl_FragColor = vec4(1.0); }", "\n// tail"};
  const GLint lengths[2] = {-1, 4};  // the second string is cut to "\n// "
  glShaderSource(s, 2, parts, lengths);
  const std::string expected = std::string(parts[0]) + "\n// ";
  EXPECT_EQ(shader_int(s, GL_SHADER_SOURCE_LENGTH), GLint(expected.size() + 1));
  char buf[256];
  GLsizei length = -1;
  glGetShaderSource(s, sizeof buf, &length, buf);
  EXPECT_EQ(std::string(buf), expected);
  EXPECT_EQ(length, GLsizei(expected.size()));
  glGetShaderSource(s, 5, &length, buf);  // 4 characters and the NUL
  EXPECT_STREQ(buf, "void");
  EXPECT_EQ(length, 4);
  glCompileShader(s);
  EXPECT_EQ(shader_int(s, GL_COMPILE_STATUS), GL_TRUE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glGetShaderiv(s, GL_LINK_STATUS, &length);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetShaderSource(s, -1, &length, buf);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glShaderSource(s, -1, parts, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(ShaderObjectsTest, FailedCompileHasALogAndNoError) {
  const GLuint s = compile(GL_VERTEX_SHADER, "void main() { gl_Position = undeclared; }\n");
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(shader_int(s, GL_COMPILE_STATUS), GL_FALSE);
  const GLint log_length = shader_int(s, GL_INFO_LOG_LENGTH);
  ASSERT_GT(log_length, 1);
  std::string log(size_t(log_length), '\0');
  GLsizei written = 0;
  glGetShaderInfoLog(s, log_length, &written, log.data());
  EXPECT_EQ(written, log_length - 1);
  EXPECT_NE(log.find("undeclared"), std::string::npos) << log;
}

TEST_F(ShaderObjectsTest, AttachDetachAndAttachedShaders) {
  const GLuint p = glCreateProgram();
  const GLuint vs = compile(GL_VERTEX_SHADER, kVs), fs = compile(GL_FRAGMENT_SHADER, kFs);
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glAttachShader(p, vs);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(program_int(p, GL_ATTACHED_SHADERS), 2);
  GLuint names[4] = {};
  GLsizei count = -1;
  glGetAttachedShaders(p, 4, &count, names);
  EXPECT_EQ(count, 2);
  EXPECT_EQ(names[0], vs);
  EXPECT_EQ(names[1], fs);
  glGetAttachedShaders(p, 1, &count, names);
  EXPECT_EQ(count, 1);
  glGetAttachedShaders(p, -1, &count, names);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDetachShader(p, vs);
  EXPECT_EQ(program_int(p, GL_ATTACHED_SHADERS), 1);
  glDetachShader(p, vs);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(ShaderObjectsTest, DeletedShaderLivesWhileAttached) {
  const GLuint p = glCreateProgram();
  const GLuint vs = compile(GL_VERTEX_SHADER, kVs);
  glAttachShader(p, vs);
  glDeleteShader(vs);
  EXPECT_TRUE(glIsShader(vs));
  EXPECT_EQ(shader_int(vs, GL_DELETE_STATUS), GL_TRUE);
  glDetachShader(p, vs);
  EXPECT_FALSE(glIsShader(vs));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ShaderObjectsTest, DeletedProgramLivesWhileCurrentAndFreesItsDeletedShaders) {
  const GLuint vs = compile(GL_VERTEX_SHADER, kVs), fs = compile(GL_FRAGMENT_SHADER, kFs);
  const GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  glLinkProgram(p);
  ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
  glUseProgram(p);
  glDeleteShader(vs);
  glDeleteProgram(p);
  EXPECT_TRUE(glIsProgram(p));
  EXPECT_EQ(program_int(p, GL_DELETE_STATUS), GL_TRUE);
  GLint current = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  EXPECT_EQ(GLuint(current), p);
  glUseProgram(0);
  EXPECT_FALSE(glIsProgram(p));
  EXPECT_FALSE(glIsShader(vs));  // deleted and no longer attached anywhere
  EXPECT_TRUE(glIsShader(fs));
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  EXPECT_EQ(current, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ShaderObjectsTest, UseProgramNeedsASuccessfulLink) {
  const GLuint p = glCreateProgram();
  glUseProgram(p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  const GLuint bad = link(kVs, "void main() { gl_FragColor = nope; }\n");
  EXPECT_EQ(program_int(bad, GL_LINK_STATUS), GL_FALSE);
  EXPECT_GT(program_int(bad, GL_INFO_LOG_LENGTH), 1);
  glUseProgram(bad);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(ShaderObjectsTest, FailedRelinkKeepsTheExecutableInUse) {
  const GLuint vs = compile(GL_VERTEX_SHADER, kVs);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, "uniform vec4 c; void main() { gl_FragColor = c; }\n");
  const GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  glLinkProgram(p);
  ASSERT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
  glUseProgram(p);
  const GLint c = glGetUniformLocation(p, "c");
  ASSERT_GE(c, 0);
  const GLuint broken = compile(GL_VERTEX_SHADER, "void main() { broken }\n");
  glDetachShader(p, vs);
  glAttachShader(p, broken);
  glLinkProgram(p);
  EXPECT_EQ(program_int(p, GL_LINK_STATUS), GL_FALSE);
  glUniform4f(c, 1, 0, 0, 1);  // still the old executable's uniform
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLint current = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  EXPECT_EQ(GLuint(current), p);
}

TEST_F(ShaderObjectsTest, InfoLogCopiesAtMostBufSizeMinusOne) {
  const GLuint p = glCreateProgram();
  glValidateProgram(p);  // not linked: fails with a log
  EXPECT_EQ(program_int(p, GL_VALIDATE_STATUS), GL_FALSE);
  const GLint n = program_int(p, GL_INFO_LOG_LENGTH);
  ASSERT_GT(n, 4);
  char buf[4] = {'x', 'x', 'x', 'x'};
  GLsizei length = -1;
  glGetProgramInfoLog(p, 4, &length, buf);
  EXPECT_EQ(length, 3);
  EXPECT_EQ(buf[3], '\0');
  glGetProgramInfoLog(p, 0, &length, buf);
  EXPECT_EQ(length, 0);
  glGetProgramInfoLog(p, -1, &length, buf);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(ShaderObjectsTest, ShaderCallsInsideBeginEndAreInvalidOperation) {
  glBegin(GL_POINTS);
  const GLuint s = glCreateShader(GL_VERTEX_SHADER);
  glEnd();
  EXPECT_EQ(s, 0u);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(ShaderObjectsTest, LimitsAndDefaults) {
  GLint v = 0;
  glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &v);
  EXPECT_EQ(v, 16);
  glGetIntegerv(GL_MAX_VARYING_FLOATS, &v);
  EXPECT_EQ(v, 64);
  glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &v);
  EXPECT_EQ(v, 8);
  glGetIntegerv(GL_CURRENT_PROGRAM, &v);
  EXPECT_EQ(v, 0);
  EXPECT_FALSE(glIsEnabled(GL_VERTEX_PROGRAM_POINT_SIZE));
  glEnable(GL_VERTEX_PROGRAM_POINT_SIZE);
  EXPECT_TRUE(glIsEnabled(GL_VERTEX_PROGRAM_POINT_SIZE));
  EXPECT_FALSE(glIsEnabled(GL_VERTEX_PROGRAM_TWO_SIDE));
  EXPECT_STREQ(reinterpret_cast<const char*>(glGetString(GL_SHADING_LANGUAGE_VERSION)), "1.20");
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Both program enables belong to the enable attribute group (GL 2.1 table 6.36).
TEST_F(ShaderObjectsTest, ProgramEnablesArePushedWithTheEnableBit) {
  glEnable(GL_VERTEX_PROGRAM_POINT_SIZE);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_VERTEX_PROGRAM_POINT_SIZE);
  glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
  glPopAttrib();
  EXPECT_TRUE(glIsEnabled(GL_VERTEX_PROGRAM_POINT_SIZE));
  EXPECT_FALSE(glIsEnabled(GL_VERTEX_PROGRAM_TWO_SIDE));
  glPushAttrib(GL_CURRENT_BIT);  // another group leaves them alone
  glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
  glPopAttrib();
  EXPECT_TRUE(glIsEnabled(GL_VERTEX_PROGRAM_TWO_SIDE));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
