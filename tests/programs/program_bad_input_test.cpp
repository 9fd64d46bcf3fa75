// Bad input to the programmable pipeline gets its GL error or a defined result, never a
// crash: non-finite values, arrays past their buffer, deleted programs, calls inside
// glBegin/glEnd.
#include <cmath>
#include <limits>
#include <vector>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

class ProgramBadInputTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    clear_to(0, 0, 0, 0);
  }
  GLuint use(const char* vs, const char* fs) {
    const GLuint p = link(vs, fs);
    EXPECT_EQ(program_int(p, GL_LINK_STATUS), GL_TRUE) << program_log(p);
    glUseProgram(p);
    return p;
  }
};

TEST_F(ProgramBadInputTest, NonFinitePositionsDrawNothing) {
  const GLuint p = use("uniform float k; void main() { gl_Position = gl_Vertex * k; }\n",
                       "void main() { gl_FragColor = vec4(1.0); }\n");
  glUniform1f(glGetUniformLocation(p, "k"), std::numeric_limits<float>::quiet_NaN());
  glRectf(-1, -1, 1, 1);
  glUniform1f(glGetUniformLocation(p, "k"), std::numeric_limits<float>::infinity());
  glRectf(-1, -1, 1, 1);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ProgramBadInputTest, TextureLookupsAtNonFiniteCoordinatesGiveDefinedTexels) {
  const GLubyte texel[4] = {10, 20, 30, 40};
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  const GLuint p = use("void main() { gl_Position = gl_Vertex; }\n",
                       "uniform sampler2D t; uniform vec2 c; void main() { gl_FragColor = texture2D(t, c); }\n");
  const GLint c = glGetUniformLocation(p, "c");
  for (float v : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), 1e30f, -1e30f}) {
    glUniform2f(c, v, v);
    glRectf(-1, -1, 1, 1);
    EXPECT_TRUE(near_rgba(pixel(5, 5), {10, 20, 30, 40})) << v;  // a 1x1 texture has one texel
  }
}

TEST_F(ProgramBadInputTest, ArraysPastTheirBufferDropTheDraw) {
  const GLuint p = use("attribute vec4 extra; varying vec4 c; void main() { c = extra; gl_Position = gl_Vertex; }\n",
                       "varying vec4 c; void main() { gl_FragColor = c + vec4(0.0, 0.0, 0.0, 1.0); }\n");
  const GLfloat positions[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, 16, positions, GL_STATIC_DRAW);  // two vec2, not four
  const GLuint extra = GLuint(glGetAttribLocation(p, "extra"));
  glVertexAttribPointer(extra, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(extra);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  glDrawArrays(GL_TRIANGLE_FAN, 0, 2);  // inside the buffer: draws (nothing, a fan of two)
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ProgramBadInputTest, MappedAttributeBufferIsInvalidOperation) {
  const GLuint p = use("attribute vec4 extra; varying vec4 c; void main() { c = extra; gl_Position = gl_Vertex; }\n",
                       "varying vec4 c; void main() { gl_FragColor = c; }\n");
  const GLfloat data[16] = {};
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, sizeof data, data, GL_STATIC_DRAW);
  const GLuint extra = GLuint(glGetAttribLocation(p, "extra"));
  glVertexAttribPointer(extra, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(extra);
  glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
  glVertexPointer(2, GL_FLOAT, 0, data);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(ProgramBadInputTest, DeletedProgramInUseStillDraws) {
  const GLuint p = use("void main() { gl_Position = gl_Vertex; }\n", "void main() { gl_FragColor = vec4(1.0); }\n");
  glDeleteProgram(p);
  glRectf(-1, -1, 1, 1);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ProgramBadInputTest, ProgramCallsInsideBeginEnd) {
  const GLuint p = use("void main() { gl_Position = gl_Vertex; }\n", "uniform vec4 c; void main() { gl_FragColor = c; }\n");
  glBegin(GL_TRIANGLES);
  glUseProgram(0);          // not allowed between glBegin and glEnd
  glVertexAttrib4f(1, 1, 2, 3, 4);  // allowed
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  GLint current = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  EXPECT_EQ(GLuint(current), p);
  GLfloat v[4] = {};
  glGetVertexAttribfv(1, GL_CURRENT_VERTEX_ATTRIB, v);
  EXPECT_EQ(v[3], 4.f);
}

TEST_F(ProgramBadInputTest, NullPointersAreSafe) {
  const GLuint s = glCreateShader(GL_VERTEX_SHADER);
  glShaderSource(s, 1, nullptr, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  const GLuint p = use("void main() { gl_Position = gl_Vertex; }\n", "uniform vec4 c; void main() { gl_FragColor = c; }\n");
  EXPECT_EQ(glGetUniformLocation(p, nullptr), -1);
  EXPECT_EQ(glGetAttribLocation(p, nullptr), -1);
  glUniform4fv(glGetUniformLocation(p, "c"), 1, nullptr);
  glGetProgramiv(p, GL_LINK_STATUS, nullptr);
  glGetShaderInfoLog(s, 10, nullptr, nullptr);
  glVertexAttrib4fv(2, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
