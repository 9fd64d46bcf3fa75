// EGL_EXT_create_context_robustness and EGL 1.5's robustness attributes: what eglCreateContext
// accepts and refuses, and what the created context then reports (through GL and
// eglQueryContext). Pineda's contexts are never reset and never access memory out of bounds,
// so every request is granted as asked; the errors follow the specs, with Mesa's choices
// where they leave room.
#include <GL/gl.h>
#include <GL/glext.h>

#include "egl_fixture.h"

namespace pineda_test {
namespace {

struct Reported {
  GLint robust_access = -1;
  GLint strategy = -1;
  GLenum error = GL_NO_ERROR;
};

class EglRobustness : public EglTest {
 protected:
  // The context of `attribs` for `api`, or EGL_NO_CONTEXT with the EGL error in `error`.
  EGLContext create(EGLenum api, std::vector<EGLint> attribs, EGLContext share = EGL_NO_CONTEXT) {
    EXPECT_TRUE(eglBindAPI(api));
    attribs.push_back(EGL_NONE);
    EGLContext ctx = eglCreateContext(dpy, any_config(), share, attribs.data());
    error = eglGetError();
    if (ctx != EGL_NO_CONTEXT) contexts.push_back(ctx);
    return ctx;
  }

  // A config that renders desktop GL and OpenGL ES 1.1 and 2.0.
  EGLConfig any_config() {
    const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                              EGL_OPENGL_BIT | EGL_OPENGL_ES_BIT | EGL_OPENGL_ES2_BIT, EGL_NONE};
    EGLConfig c = nullptr;
    EGLint n = 0;
    EXPECT_TRUE(eglChooseConfig(dpy, attribs, &c, 1, &n));
    EXPECT_EQ(n, 1);
    return c;
  }

  // GL_CONTEXT_ROBUST_ACCESS and GL_RESET_NOTIFICATION_STRATEGY of `ctx` (made current, surfaceless).
  Reported reported(EGLContext ctx) {
    Reported r;
    EXPECT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
    glGetIntegerv(GL_CONTEXT_ROBUST_ACCESS, &r.robust_access);
    glGetIntegerv(GL_RESET_NOTIFICATION_STRATEGY, &r.strategy);
    r.error = glGetError();
    EXPECT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    return r;
  }

  EGLint queried_strategy(EGLContext ctx) {
    EGLint value = -1;
    EXPECT_TRUE(eglQueryContext(dpy, ctx, EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY_EXT, &value));
    return value;
  }

  EGLint error = EGL_SUCCESS;
};

constexpr EGLint kEs2 = 2;

TEST_F(EglRobustness, Advertised) {
  const std::string extensions = eglQueryString(dpy, EGL_EXTENSIONS);
  EXPECT_NE((" " + extensions + " ").find(" EGL_EXT_create_context_robustness "), std::string::npos);
}

TEST_F(EglRobustness, DefaultsAreNoRobustAccessAndNoResetNotification) {
  for (EGLenum api : {EGL_OPENGL_API, EGL_OPENGL_ES_API}) {
    EGLContext ctx = api == EGL_OPENGL_API ? create(api, {}) : create(api, {EGL_CONTEXT_CLIENT_VERSION, kEs2});
    ASSERT_NE(ctx, EGL_NO_CONTEXT) << std::hex << error;
    const Reported r = reported(ctx);
    EXPECT_EQ(r.robust_access, GL_FALSE);
    EXPECT_EQ(r.strategy, GL_NO_RESET_NOTIFICATION);
    EXPECT_EQ(r.error, GLenum(GL_NO_ERROR));
    EXPECT_EQ(queried_strategy(ctx), EGL_NO_RESET_NOTIFICATION_EXT);
  }
}

TEST_F(EglRobustness, Es2ContextReportsWhatTheExtAttributesAsk) {
  for (EGLint robust : {EGL_FALSE, EGL_TRUE}) {
    for (EGLint strategy : {EGL_NO_RESET_NOTIFICATION_EXT, EGL_LOSE_CONTEXT_ON_RESET_EXT}) {
      EGLContext ctx = create(EGL_OPENGL_ES_API, {EGL_CONTEXT_CLIENT_VERSION, kEs2, EGL_CONTEXT_OPENGL_ROBUST_ACCESS_EXT,
                                                  robust, EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY_EXT, strategy});
      ASSERT_NE(ctx, EGL_NO_CONTEXT) << std::hex << error;
      const Reported r = reported(ctx);
      EXPECT_EQ(r.robust_access, robust);
      EXPECT_EQ(r.strategy, strategy == EGL_LOSE_CONTEXT_ON_RESET_EXT ? GL_LOSE_CONTEXT_ON_RESET : GL_NO_RESET_NOTIFICATION);
      EXPECT_EQ(r.error, GLenum(GL_NO_ERROR));
      EXPECT_EQ(queried_strategy(ctx), strategy);
    }
  }
}

TEST_F(EglRobustness, Egl15AttributesForBothApis) {
  for (EGLenum api : {EGL_OPENGL_API, EGL_OPENGL_ES_API}) {
    std::vector<EGLint> attribs = {EGL_CONTEXT_OPENGL_ROBUST_ACCESS, EGL_TRUE,
                                   EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY, EGL_LOSE_CONTEXT_ON_RESET};
    if (api == EGL_OPENGL_ES_API) attribs.insert(attribs.end(), {EGL_CONTEXT_CLIENT_VERSION, kEs2});
    EGLContext ctx = create(api, attribs);
    ASSERT_NE(ctx, EGL_NO_CONTEXT) << std::hex << error;
    const Reported r = reported(ctx);
    EXPECT_EQ(r.robust_access, GL_TRUE);
    EXPECT_EQ(r.strategy, GL_LOSE_CONTEXT_ON_RESET);
    EXPECT_EQ(r.error, GLenum(GL_NO_ERROR));
  }
}

TEST_F(EglRobustness, DesktopGlRobustThroughTheFlagAndTheExtAttribute) {
  for (auto attribs : {std::vector<EGLint>{EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR},
                       std::vector<EGLint>{EGL_CONTEXT_OPENGL_ROBUST_ACCESS_EXT, EGL_TRUE}}) {
    EGLContext ctx = create(EGL_OPENGL_API, attribs);
    ASSERT_NE(ctx, EGL_NO_CONTEXT) << std::hex << error;
    const Reported r = reported(ctx);
    EXPECT_EQ(r.robust_access, GL_TRUE);
    EXPECT_EQ(r.strategy, GL_NO_RESET_NOTIFICATION);
  }
}

TEST_F(EglRobustness, BadValuesAreBadAttribute) {
  const std::vector<EGLint> es2 = {EGL_CONTEXT_CLIENT_VERSION, kEs2};
  for (auto [name, value] : {std::pair{EGL_CONTEXT_OPENGL_ROBUST_ACCESS_EXT, 2},
                             {EGL_CONTEXT_OPENGL_ROBUST_ACCESS, 2},
                             {EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY_EXT, 0x1234},
                             {EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY_EXT, EGL_TRUE},
                             {EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY, 0x1234}}) {
    std::vector<EGLint> attribs = es2;
    attribs.insert(attribs.end(), {name, value});
    EXPECT_EQ(create(EGL_OPENGL_ES_API, attribs), EGL_NO_CONTEXT) << std::hex << name << " " << value;
    EXPECT_EQ(error, EGL_BAD_ATTRIBUTE) << std::hex << name << " " << value;
  }
}

TEST_F(EglRobustness, AttributesOfTheOtherApiAreBadAttribute) {
  // EGL_EXT_create_context_robustness: its reset strategy is for OpenGL ES only.
  EXPECT_EQ(create(EGL_OPENGL_API, {EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY_EXT, EGL_NO_RESET_NOTIFICATION_EXT}),
            EGL_NO_CONTEXT);
  EXPECT_EQ(error, EGL_BAD_ATTRIBUTE);
  // EGL_KHR_create_context issue 10: the robust access flag bit is not for OpenGL ES (nor is
  // the forward-compatible one, which piglit's "invalid flag gles" checks too).
  for (EGLint flag : {EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR, EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR}) {
    EXPECT_EQ(create(EGL_OPENGL_ES_API, {EGL_CONTEXT_CLIENT_VERSION, kEs2, EGL_CONTEXT_FLAGS_KHR, flag}), EGL_NO_CONTEXT);
    EXPECT_EQ(error, EGL_BAD_ATTRIBUTE) << flag;
  }
}

TEST_F(EglRobustness, Es11HasNoRobustnessExtensionSoRobustRequestsAreBadConfig) {
  for (auto [name, value] : {std::pair{EGL_CONTEXT_OPENGL_ROBUST_ACCESS_EXT, EGL_TRUE},
                             {EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY_EXT, EGL_LOSE_CONTEXT_ON_RESET_EXT}}) {
    EXPECT_EQ(create(EGL_OPENGL_ES_API, {EGL_CONTEXT_CLIENT_VERSION, 1, name, value}), EGL_NO_CONTEXT);
    EXPECT_EQ(error, EGL_BAD_CONFIG);
  }
  // What an ES 1.1 context has anyway is no request.
  EXPECT_NE(create(EGL_OPENGL_ES_API, {EGL_CONTEXT_CLIENT_VERSION, 1, EGL_CONTEXT_OPENGL_ROBUST_ACCESS_EXT, EGL_FALSE,
                                       EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY_EXT, EGL_NO_RESET_NOTIFICATION_EXT}),
            EGL_NO_CONTEXT);
}

TEST_F(EglRobustness, SharedContextsHaveOneResetStrategy) {
  const std::vector<EGLint> lose = {EGL_CONTEXT_CLIENT_VERSION, kEs2, EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY_EXT,
                                    EGL_LOSE_CONTEXT_ON_RESET_EXT};
  EGLContext first = create(EGL_OPENGL_ES_API, lose);
  ASSERT_NE(first, EGL_NO_CONTEXT);
  EXPECT_EQ(create(EGL_OPENGL_ES_API, {EGL_CONTEXT_CLIENT_VERSION, kEs2}, first), EGL_NO_CONTEXT);
  EXPECT_EQ(error, EGL_BAD_MATCH);
  EXPECT_NE(create(EGL_OPENGL_ES_API, lose, first), EGL_NO_CONTEXT);
  // Robust access may differ.
  std::vector<EGLint> robust = lose;
  robust.insert(robust.end(), {EGL_CONTEXT_OPENGL_ROBUST_ACCESS_EXT, EGL_TRUE});
  EXPECT_NE(create(EGL_OPENGL_ES_API, robust, first), EGL_NO_CONTEXT);

  EGLContext gl = create(EGL_OPENGL_API, {});
  ASSERT_NE(gl, EGL_NO_CONTEXT);
  EXPECT_EQ(create(EGL_OPENGL_API, {EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY, EGL_LOSE_CONTEXT_ON_RESET}, gl),
            EGL_NO_CONTEXT);
  EXPECT_EQ(error, EGL_BAD_MATCH);
}

}  // namespace
}  // namespace pineda_test
