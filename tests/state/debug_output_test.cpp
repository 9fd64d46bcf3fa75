// GL_KHR_debug: messages for API errors naming the call and the rule, the log, the callback,
// control rules, debug groups, object labels, their errors and limits, and PINEDA_DEBUG=1.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdlib>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

struct Logged {
  GLenum source = 0, type = 0;
  GLuint id = 0;
  GLenum severity = 0;
  std::string text;
};

// Every message in the log, oldest first (and empties it).
std::vector<Logged> drain_log() {
  std::vector<Logged> out;
  for (;;) {
    GLint next = 0;
    glGetIntegerv(GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH, &next);
    if (next == 0) return out;
    Logged m;
    std::vector<GLchar> text(size_t(next), 'x');
    GLsizei length = 0;
    EXPECT_EQ(glGetDebugMessageLog(1, next, &m.source, &m.type, &m.id, &m.severity, &length, text.data()), 1u);
    EXPECT_EQ(length, next);
    m.text = text.data();
    out.push_back(m);
  }
}

GLint get_int(GLenum pname) {
  GLint v = -1;
  glGetIntegerv(pname, &v);
  return v;
}

class DebugOutputTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glEnable(GL_DEBUG_OUTPUT);
  }
  void insert(GLuint id, const char* text, GLenum type = GL_DEBUG_TYPE_MARKER,
              GLenum severity = GL_DEBUG_SEVERITY_NOTIFICATION) {
    glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, type, id, severity, -1, text);
  }
};

using DebugDefaultsTest = GlTest;

TEST_F(DebugDefaultsTest, InitialStateAndLimits) {
  EXPECT_EQ(glIsEnabled(GL_DEBUG_OUTPUT), GL_FALSE);  // not a debug context
  EXPECT_EQ(glIsEnabled(GL_DEBUG_OUTPUT_SYNCHRONOUS), GL_FALSE);
  EXPECT_EQ(get_int(GL_MAX_DEBUG_MESSAGE_LENGTH), 1024);
  EXPECT_EQ(get_int(GL_MAX_DEBUG_LOGGED_MESSAGES), 64);
  EXPECT_EQ(get_int(GL_MAX_DEBUG_GROUP_STACK_DEPTH), 64);
  EXPECT_EQ(get_int(GL_MAX_LABEL_LENGTH), 256);
  EXPECT_EQ(get_int(GL_DEBUG_GROUP_STACK_DEPTH), 1);
  EXPECT_EQ(get_int(GL_DEBUG_LOGGED_MESSAGES), 0);
  EXPECT_EQ(get_int(GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH), 0);
  void* p = reinterpret_cast<void*>(1);
  glGetPointerv(GL_DEBUG_CALLBACK_FUNCTION, &p);
  EXPECT_EQ(p, nullptr);
  const std::string extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(extensions.find("GL_KHR_debug "), std::string::npos);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(DebugDefaultsTest, DisabledOutputLogsNothing) {
  glDeleteTextures(-1, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_DEBUG_LOGGED_MESSAGES), 0);
}

class DebugContextTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {.debug_context = true}; }
};

TEST_F(DebugContextTest, OutputStartsEnabled) { EXPECT_EQ(glIsEnabled(GL_DEBUG_OUTPUT), GL_TRUE); }

TEST_F(DebugOutputTest, ErrorMessageNamesTheCallTheErrorAndTheRule) {
  glDeleteTextures(-1, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  const std::vector<Logged> log = drain_log();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0].source, GLenum(GL_DEBUG_SOURCE_API));
  EXPECT_EQ(log[0].type, GLenum(GL_DEBUG_TYPE_ERROR));
  EXPECT_EQ(log[0].id, GLuint(GL_INVALID_VALUE));
  EXPECT_EQ(log[0].severity, GLenum(GL_DEBUG_SEVERITY_HIGH));
  EXPECT_EQ(log[0].text, "glDeleteTextures: GL_INVALID_VALUE: n is negative");
}

TEST_F(DebugOutputTest, EveryErrorIsLoggedNotOnlyTheFirst) {
  glBegin(GL_POINTS);
  glEnable(GL_BLEND);
  glEnd();
  glEnable(0xFFFF);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  const std::vector<Logged> log = drain_log();
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log[0].text, "glEnable: GL_INVALID_OPERATION: called between glBegin and glEnd");
  EXPECT_EQ(log[1].text.rfind("glEnable: GL_INVALID_ENUM", 0), 0u) << log[1].text;
}

void GLAPIENTRY collect(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                        const GLchar* message, const void* user) {
  auto* out = static_cast<std::vector<Logged>*>(const_cast<void*>(user));
  EXPECT_EQ(GLsizei(std::strlen(message)), length);
  out->push_back({source, type, id, severity, message});
}

TEST_F(DebugOutputTest, CallbackReceivesMessagesInsteadOfTheLog) {
  std::vector<Logged> got;
  glDebugMessageCallback(collect, &got);
  void* p = nullptr;
  glGetPointerv(GL_DEBUG_CALLBACK_FUNCTION, &p);
  EXPECT_EQ(p, reinterpret_cast<void*>(&collect));
  glGetPointerv(GL_DEBUG_CALLBACK_USER_PARAM, &p);
  EXPECT_EQ(p, &got);
  insert(7, "hello");
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].source, GLenum(GL_DEBUG_SOURCE_APPLICATION));
  EXPECT_EQ(got[0].type, GLenum(GL_DEBUG_TYPE_MARKER));
  EXPECT_EQ(got[0].id, 7u);
  EXPECT_EQ(got[0].text, "hello");
  EXPECT_EQ(get_int(GL_DEBUG_LOGGED_MESSAGES), 0);
  glDebugMessageCallback(nullptr, nullptr);
  insert(8, "logged");
  EXPECT_EQ(get_int(GL_DEBUG_LOGGED_MESSAGES), 1);
  EXPECT_EQ(get_int(GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH), 7);
}

TEST_F(DebugOutputTest, LowSeverityStartsDisabledAndControlRulesApplyInOrder) {
  insert(1, "low", GL_DEBUG_TYPE_OTHER, GL_DEBUG_SEVERITY_LOW);
  EXPECT_EQ(get_int(GL_DEBUG_LOGGED_MESSAGES), 0);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_LOW, 0, nullptr, GL_TRUE);
  insert(2, "low again", GL_DEBUG_TYPE_OTHER, GL_DEBUG_SEVERITY_LOW);
  // Everything of type MARKER off, then id 4 of it on again.
  glDebugMessageControl(GL_DONT_CARE, GL_DEBUG_TYPE_MARKER, GL_DONT_CARE, 0, nullptr, GL_FALSE);
  const GLuint four = 4;
  glDebugMessageControl(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_MARKER, GL_DONT_CARE, 1, &four, GL_TRUE);
  insert(3, "off");
  insert(4, "on");
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const std::vector<Logged> log = drain_log();
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log[0].text, "low again");
  EXPECT_EQ(log[1].text, "on");
}

TEST_F(DebugOutputTest, ControlAndInsertErrors) {
  glDebugMessageControl(0x1234, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, -1, nullptr, GL_TRUE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  const GLuint id = 1;
  glDebugMessageControl(GL_DONT_CARE, GL_DEBUG_TYPE_MARKER, GL_DONT_CARE, 1, &id, GL_TRUE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDebugMessageControl(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_MARKER, GL_DEBUG_SEVERITY_HIGH, 1, &id, GL_TRUE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDebugMessageInsert(GL_DEBUG_SOURCE_API, GL_DEBUG_TYPE_MARKER, 0, GL_DEBUG_SEVERITY_HIGH, -1, "x");
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DONT_CARE, 0, GL_DEBUG_SEVERITY_HIGH, -1, "x");
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  const std::string too_long(1024, 'a');
  glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_MARKER, 0, GL_DEBUG_SEVERITY_HIGH, -1, too_long.c_str());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_MARKER, 0, GL_DEBUG_SEVERITY_HIGH, 1023, too_long.c_str());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLchar buf[4];
  EXPECT_EQ(glGetDebugMessageLog(1, -1, nullptr, nullptr, nullptr, nullptr, nullptr, buf), 0u);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(DebugOutputTest, LogKeepsAMessageThatDoesNotFitAndHoldsAtMost64) {
  insert(1, "abcdef");
  insert(2, "xy");
  GLchar buf[4];
  GLuint ids[2] = {0, 0};
  EXPECT_EQ(glGetDebugMessageLog(2, sizeof buf, nullptr, nullptr, ids, nullptr, nullptr, buf), 0u);
  EXPECT_EQ(get_int(GL_DEBUG_LOGGED_MESSAGES), 2);
  drain_log();
  for (int i = 0; i < 70; ++i) insert(GLuint(i), "m");
  EXPECT_EQ(get_int(GL_DEBUG_LOGGED_MESSAGES), 64);
  const std::vector<Logged> log = drain_log();
  ASSERT_EQ(log.size(), 64u);
  EXPECT_EQ(log.front().id, 0u);
  EXPECT_EQ(log.back().id, 63u);  // the newest are dropped
  // A null messageLog fetches without text.
  insert(9, "no text");
  GLsizei length = 0;
  EXPECT_EQ(glGetDebugMessageLog(1, 0, nullptr, nullptr, ids, nullptr, &length, nullptr), 1u);
  EXPECT_EQ(ids[0], 9u);
  EXPECT_EQ(length, 8);
}

TEST_F(DebugOutputTest, GroupsLogPushAndPopAndScopeTheControlRules) {
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 11, -1, "pass 1");
  EXPECT_EQ(get_int(GL_DEBUG_GROUP_STACK_DEPTH), 2);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_FALSE);
  insert(1, "silenced");
  glPopDebugGroup();
  insert(2, "heard");
  EXPECT_EQ(get_int(GL_DEBUG_GROUP_STACK_DEPTH), 1);
  const std::vector<Logged> log = drain_log();
  ASSERT_EQ(log.size(), 3u);
  EXPECT_EQ(log[0].type, GLenum(GL_DEBUG_TYPE_PUSH_GROUP));
  EXPECT_EQ(log[0].id, 11u);
  EXPECT_EQ(log[0].severity, GLenum(GL_DEBUG_SEVERITY_NOTIFICATION));
  EXPECT_EQ(log[0].text, "pass 1");
  EXPECT_EQ(log[1].type, GLenum(GL_DEBUG_TYPE_POP_GROUP));
  EXPECT_EQ(log[1].text, "pass 1");
  EXPECT_EQ(log[2].text, "heard");
}

TEST_F(DebugOutputTest, GroupStackLimits) {
  glPopDebugGroup();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_UNDERFLOW));
  glPushDebugGroup(GL_DEBUG_SOURCE_API, 1, -1, "x");
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  for (int i = 1; i < 64; ++i) glPushDebugGroup(GL_DEBUG_SOURCE_THIRD_PARTY, GLuint(i), 1, "g");
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_int(GL_DEBUG_GROUP_STACK_DEPTH), 64);
  glPushDebugGroup(GL_DEBUG_SOURCE_THIRD_PARTY, 64, 1, "g");
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_OVERFLOW));
  EXPECT_EQ(get_int(GL_DEBUG_GROUP_STACK_DEPTH), 64);
}

TEST_F(DebugOutputTest, ObjectLabelsOfTexturesBuffersQueriesAndLists) {
  GLuint tex = 0, buf = 0, query = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glGenBuffers(1, &buf);
  glBindBuffer(GL_ARRAY_BUFFER, buf);
  glGenQueries(1, &query);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  glEndQuery(GL_SAMPLES_PASSED);
  const GLuint list = glGenLists(1);
  glObjectLabel(GL_TEXTURE, tex, -1, "bricks");
  glObjectLabel(GL_BUFFER, buf, 3, "vertices");
  glObjectLabel(GL_QUERY, query, -1, "occlusion");
  glObjectLabel(GL_DISPLAY_LIST, list, -1, "scene");
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLchar text[64];
  GLsizei length = -1;
  glGetObjectLabel(GL_TEXTURE, tex, sizeof text, &length, text);
  EXPECT_STREQ(text, "bricks");
  EXPECT_EQ(length, 6);
  glGetObjectLabel(GL_BUFFER, buf, sizeof text, &length, text);
  EXPECT_STREQ(text, "ver");
  glGetObjectLabel(GL_QUERY, query, 4, &length, text);  // cut to fit, terminated
  EXPECT_STREQ(text, "occ");
  EXPECT_EQ(length, 3);
  glGetObjectLabel(GL_DISPLAY_LIST, list, 0, &length, nullptr);
  EXPECT_EQ(length, 5);
  // A null label removes it; deleting the object forgets it.
  glObjectLabel(GL_TEXTURE, tex, 0, nullptr);
  glGetObjectLabel(GL_TEXTURE, tex, sizeof text, &length, text);
  EXPECT_EQ(length, 0);
  glObjectLabel(GL_BUFFER, buf, -1, "again");
  glDeleteBuffers(1, &buf);
  glBindBuffer(GL_ARRAY_BUFFER, buf);  // the same name, a new object
  glGetObjectLabel(GL_BUFFER, buf, sizeof text, &length, text);
  EXPECT_EQ(length, 0);
  glDeleteLists(list, 1);
  glGetObjectLabel(GL_DISPLAY_LIST, list, sizeof text, &length, text);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(DebugOutputTest, ObjectLabelErrors) {
  glObjectLabel(GL_TEXTURE, 4242, -1, "x");
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glObjectLabel(GL_SAMPLER, 1, -1, "x");
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  const std::string too_long(256, 'a');
  glObjectLabel(GL_TEXTURE, tex, -1, too_long.c_str());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLchar text[4];
  glGetObjectLabel(GL_TEXTURE, tex, -1, nullptr, text);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  int object = 0;
  glObjectPtrLabel(&object, -1, "x");  // Pineda has no sync objects
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  const std::vector<Logged> log = drain_log();
  ASSERT_EQ(log.size(), 5u);
  EXPECT_EQ(log[0].text, "glObjectLabel: GL_INVALID_VALUE: name 4242 is not an object of that identifier");
}

// Every error names the argument and the rule it broke: one case a call, the message read back
// exactly. `setup` makes the state the call needs and records no error.
struct ErrorCase {
  const char* name;
  void (*setup)();
  void (*call)();
  GLenum error;
  const char* text;
};

void PrintTo(const ErrorCase& c, std::ostream* os) { *os << c.name; }

void no_setup() {}

GLuint bound_buffer() {
  GLuint b = 0;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, 16, nullptr, GL_STATIC_DRAW);
  return b;
}

GLuint program_with_shader() {
  const GLuint program = glCreateProgram();
  glAttachShader(program, glCreateShader(GL_VERTEX_SHADER));
  return program;
}

const ErrorCase kErrorCases[] = {
    {"TexImageWidth", no_setup, [] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr); },
     GL_INVALID_VALUE, "glTexImage2D: GL_INVALID_VALUE: width is negative"},
    {"TexImageBorder", no_setup, [] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE, nullptr); },
     GL_INVALID_VALUE, "glTexImage2D: GL_INVALID_VALUE: border is not 0 or 1"},
    {"TexImageFormat", no_setup, [] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, 0x1234, GL_UNSIGNED_BYTE, nullptr); },
     GL_INVALID_ENUM, "glTexImage2D: GL_INVALID_ENUM: format is not a pixel format"},
    {"TexSubImageNoImage", no_setup,
     [] {
       const GLubyte texel[4] = {};
       glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texel);
     },
     GL_INVALID_OPERATION, "glTexSubImage2D: GL_INVALID_OPERATION: the level has no image to replace"},
    {"TexParameterTarget", no_setup, [] { glTexParameteri(0x1234, GL_TEXTURE_MIN_FILTER, GL_NEAREST); },
     GL_INVALID_ENUM, "glTexParameteri: GL_INVALID_ENUM: target is not a texture target"},
    {"GenTextures", no_setup, [] { glGenTextures(-1, nullptr); }, GL_INVALID_VALUE,
     "glGenTextures: GL_INVALID_VALUE: n is negative"},
    {"BindTextureOtherTarget", [] { glBindTexture(GL_TEXTURE_1D, 7); }, [] { glBindTexture(GL_TEXTURE_2D, 7); },
     GL_INVALID_OPERATION, "glBindTexture: GL_INVALID_OPERATION: the texture was first bound to another target"},
    {"BufferDataSize", [] { bound_buffer(); }, [] { glBufferData(GL_ARRAY_BUFFER, -1, nullptr, GL_STATIC_DRAW); },
     GL_INVALID_VALUE, "glBufferData: GL_INVALID_VALUE: size is negative"},
    {"BufferDataTarget", no_setup, [] { glBufferData(0x1234, 4, nullptr, GL_STATIC_DRAW); }, GL_INVALID_ENUM,
     "glBufferData: GL_INVALID_ENUM: target is not a buffer target"},
    {"MapBufferTwice", [] { bound_buffer(), glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY); },
     [] { glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY); }, GL_INVALID_OPERATION,
     "glMapBuffer: GL_INVALID_OPERATION: the buffer is already mapped"},
    {"UnmapUnmapped", [] { bound_buffer(); }, [] { glUnmapBuffer(GL_ARRAY_BUFFER); }, GL_INVALID_OPERATION,
     "glUnmapBuffer: GL_INVALID_OPERATION: the buffer is not mapped"},
    {"CreateShaderType", no_setup, [] { glCreateShader(0x1234); }, GL_INVALID_ENUM,
     "glCreateShader: GL_INVALID_ENUM: shaderType is not GL_VERTEX_SHADER or GL_FRAGMENT_SHADER"},
    {"ShaderSourceCount", [] { glCreateShader(GL_VERTEX_SHADER); }, [] { glShaderSource(1, -1, nullptr, nullptr); },
     GL_INVALID_VALUE, "glShaderSource: GL_INVALID_VALUE: count is negative"},
    {"GetShaderivName", no_setup,
     [] {
       GLint v = 0;
       glGetShaderiv(4242, GL_COMPILE_STATUS, &v);
     },
     GL_INVALID_VALUE, "glGetShaderiv: GL_INVALID_VALUE: shader is not a shader or program object"},
    {"AttachTwice", [] { program_with_shader(); }, [] { glAttachShader(1, 2); }, GL_INVALID_OPERATION,
     "glAttachShader: GL_INVALID_OPERATION: the shader is already attached to the program"},
    {"UseUnlinkedProgram", [] { glCreateProgram(); }, [] { glUseProgram(1); }, GL_INVALID_OPERATION,
     "glUseProgram: GL_INVALID_OPERATION: the program is not linked"},
    {"UniformWithoutProgram", no_setup, [] { glUniform1f(0, 1.f); }, GL_INVALID_OPERATION,
     "glUniform1f: GL_INVALID_OPERATION: no program is current"},
    {"BindFramebufferTarget", no_setup, [] { glBindFramebuffer(0x1234, 0); }, GL_INVALID_ENUM,
     "glBindFramebuffer: GL_INVALID_ENUM: target is not a framebuffer target"},
    {"AttachToDefaultFramebuffer", no_setup,
     [] { glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0); }, GL_INVALID_OPERATION,
     "glFramebufferTexture2D: GL_INVALID_OPERATION: the default framebuffer, which has no attachments, is bound"},
    {"RenderbufferStorageUnbound", no_setup, [] { glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1); },
     GL_INVALID_OPERATION, "glRenderbufferStorage: GL_INVALID_OPERATION: no renderbuffer is bound"},
    {"BlitFilter", no_setup, [] { glBlitFramebuffer(0, 0, 1, 1, 0, 0, 1, 1, GL_COLOR_BUFFER_BIT, 0x1234); },
     GL_INVALID_ENUM, "glBlitFramebuffer: GL_INVALID_ENUM: filter is not GL_NEAREST or GL_LINEAR"},
    {"NewListZero", no_setup, [] { glNewList(0, GL_COMPILE); }, GL_INVALID_VALUE,
     "glNewList: GL_INVALID_VALUE: list is zero"},
    {"EndListOutsideList", no_setup, [] { glEndList(); }, GL_INVALID_OPERATION,
     "glEndList: GL_INVALID_OPERATION: no display list is being compiled"},
    {"CallListsInList", [] { glNewList(1, GL_COMPILE); }, [] { glCallLists(1, 0x1234, nullptr), glEndList(), glCallList(1); },
     GL_INVALID_ENUM, "glCallList: GL_INVALID_ENUM: type is not a list name type"},
    {"BeginMode", no_setup, [] { glBegin(0x1234); }, GL_INVALID_ENUM,
     "glBegin: GL_INVALID_ENUM: mode is not a primitive type"},
    {"EndOutsideBegin", no_setup, [] { glEnd(); }, GL_INVALID_OPERATION,
     "glEnd: GL_INVALID_OPERATION: called outside glBegin and glEnd"},
    {"IsEnabledCap", no_setup, [] { glIsEnabled(0x1234); }, GL_INVALID_ENUM,
     "glIsEnabled: GL_INVALID_ENUM: cap 0x1234 is not a capability"},
    {"GetIntegerPname", no_setup,
     [] {
       GLint v = 0;
       glGetIntegerv(0x1234, &v);
     },
     GL_INVALID_ENUM, "glGetIntegerv: GL_INVALID_ENUM: pname is not a state variable"},
    {"GetStringName", no_setup, [] { glGetString(0x1234); }, GL_INVALID_ENUM,
     "glGetString: GL_INVALID_ENUM: name is not a string name"},
    {"PixelStoreAlignment", no_setup, [] { glPixelStorei(GL_UNPACK_ALIGNMENT, 3); }, GL_INVALID_VALUE,
     "glPixelStorei: GL_INVALID_VALUE: the alignment is not 1, 2, 4 or 8"},
    {"ReadPixelsWidth", no_setup, [] { glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, nullptr); },
     GL_INVALID_VALUE, "glReadPixels: GL_INVALID_VALUE: width or height is negative"},
    {"DrawPixelsType", no_setup, [] { glDrawPixels(1, 1, GL_RGBA, 0x1234, nullptr); }, GL_INVALID_ENUM,
     "glDrawPixels: GL_INVALID_ENUM: type is not a pixel type"},
    {"PopMatrixEmpty", no_setup, [] { glPopMatrix(); }, GL_STACK_UNDERFLOW,
     "glPopMatrix: GL_STACK_UNDERFLOW: the current matrix stack has one matrix only"},
    {"FrustumNear", no_setup, [] { glFrustum(-1, 1, -1, 1, 0, 1); }, GL_INVALID_VALUE,
     "glFrustum: GL_INVALID_VALUE: nearVal or farVal is not positive"},
    {"PopAttribEmpty", no_setup, [] { glPopAttrib(); }, GL_STACK_UNDERFLOW,
     "glPopAttrib: GL_STACK_UNDERFLOW: the attribute stack is empty"},
    {"SpotExponent", no_setup, [] { glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 200.f); }, GL_INVALID_VALUE,
     "glLightf: GL_INVALID_VALUE: GL_SPOT_EXPONENT is outside [0, 128]"},
    {"DrawArraysCount", no_setup, [] { glDrawArrays(GL_POINTS, 0, -1); }, GL_INVALID_VALUE,
     "glDrawArrays: GL_INVALID_VALUE: count is negative"},
    {"MultiDrawArraysDrawcount", no_setup, [] { glMultiDrawArrays(GL_POINTS, nullptr, nullptr, -1); },
     GL_INVALID_VALUE, "glMultiDrawArrays: GL_INVALID_VALUE: drawcount is negative"},
    {"EndQueryInactive", no_setup, [] { glEndQuery(GL_SAMPLES_PASSED); }, GL_INVALID_OPERATION,
     "glEndQuery: GL_INVALID_OPERATION: no query of target is active"},
    {"ClearMask", no_setup, [] { glClear(0x1); }, GL_INVALID_VALUE,
     "glClear: GL_INVALID_VALUE: mask has bits other than the four buffer bits"},
    {"StencilOpSeparateFace", no_setup, [] { glStencilOpSeparate(0x1234, GL_KEEP, GL_KEEP, GL_KEEP); },
     GL_INVALID_ENUM, "glStencilOpSeparate: GL_INVALID_ENUM: face is not GL_FRONT, GL_BACK or GL_FRONT_AND_BACK"},
    {"Map1Order", no_setup,
     [] {
       const GLfloat points[4] = {};
       glMap1f(GL_MAP1_VERTEX_3, 0.f, 1.f, 3, 0, points);
     },
     GL_INVALID_VALUE, "glMap1f: GL_INVALID_VALUE: order is less than 1 or above GL_MAX_EVAL_ORDER"},
};

class ErrorMessageTest : public DebugOutputTest, public ::testing::WithParamInterface<ErrorCase> {};

TEST_P(ErrorMessageTest, NamesTheArgumentAndTheRule) {
  GetParam().setup();
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  drain_log();
  GetParam().call();
  EXPECT_EQ(glGetError(), GetParam().error);
  const std::vector<Logged> log = drain_log();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0].text, GetParam().text);
}

INSTANTIATE_TEST_SUITE_P(Sites, ErrorMessageTest, ::testing::ValuesIn(kErrorCases),
                         [](const ::testing::TestParamInfo<ErrorCase>& info) { return std::string(info.param.name); });

class PineDebugEnvTest : public GlTest {
 protected:
  void SetUp() override {
    setenv("PINEDA_DEBUG", "1", 1);
    GlTest::SetUp();
    unsetenv("PINEDA_DEBUG");
  }
};

TEST_F(PineDebugEnvTest, PrintsErrorsToStderrWithoutAsking) {
  ::testing::internal::CaptureStderr();
  glDeleteQueries(-2, nullptr);
  const std::string printed = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(printed, "pineda: glDeleteQueries: GL_INVALID_VALUE: n is negative\n");
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_DEBUG_LOGGED_MESSAGES), 0);  // DEBUG_OUTPUT stays off
}

}  // namespace
}  // namespace pineda::test
