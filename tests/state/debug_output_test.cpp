// GL_KHR_debug: messages for API errors naming the call and the rule, the log, the callback,
// control rules, debug groups, object labels, their errors and limits, and PINEDA_DEBUG=1.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdlib>
#include <cstring>
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
