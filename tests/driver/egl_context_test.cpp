// eglBindAPI/QueryAPI, eglCreateContext with EGL_KHR_create_context, eglDestroyContext,
// eglQueryContext.
#include <thread>

#include "egl_fixture.h"

namespace {

using pineda_test::EglTest;
using EglContext = EglTest;

TEST_F(EglContext, BindApi) {
  EXPECT_EQ(eglQueryAPI(), EGL_OPENGL_API);
  EXPECT_TRUE(eglBindAPI(EGL_OPENGL_ES_API));
  EXPECT_EQ(eglQueryAPI(), EGL_OPENGL_ES_API);
  EXPECT_TRUE(eglBindAPI(EGL_OPENGL_API));
  EXPECT_FALSE(eglBindAPI(EGL_OPENVG_API));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_FALSE(eglBindAPI(0x1234));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_EQ(eglQueryAPI(), EGL_OPENGL_API);
}

TEST_F(EglContext, InitialApiIsES) {
  EGLConfig cfg = config();
  EGLint api = 0, error = 0;
  EGLContext ctx = nullptr;
  std::thread([&] {
    api = eglQueryAPI();
    const EGLint attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
    ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, attribs);
    error = eglGetError();
    if (ctx) eglDestroyContext(dpy, ctx);
  }).join();
  EXPECT_EQ(api, EGL_OPENGL_ES_API);
  if (offers_gles2()) {
    EXPECT_NE(ctx, EGL_NO_CONTEXT);
    EXPECT_EQ(error, EGL_SUCCESS);
  } else {
    // ES 1.1 only: an ES 2.0 context is EGL_BAD_MATCH.
    EXPECT_EQ(ctx, EGL_NO_CONTEXT);
    EXPECT_EQ(error, EGL_BAD_MATCH);
  }
}

TEST_F(EglContext, ES20Contexts) {
  if (!offers_gles2()) GTEST_SKIP() << "OpenGL ES 2.0 is not offered yet";
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_ES_API));
  EGLConfig cfg = config();
  const EGLint es2[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
  EGLContext ctx = context(cfg, es2);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  EGLint value = 0;
  EXPECT_TRUE(eglQueryContext(dpy, ctx, EGL_CONTEXT_CLIENT_TYPE, &value));
  EXPECT_EQ(value, EGL_OPENGL_ES_API);
  EXPECT_TRUE(eglQueryContext(dpy, ctx, EGL_CONTEXT_CLIENT_VERSION, &value));
  EXPECT_EQ(value, 2);
  EGLSurface s = pbuffer(cfg, 8, 8);
  EXPECT_TRUE(eglMakeCurrent(dpy, s, s, ctx));
  // ES 3 is not offered (ES 1.1: tests/es1/).
  const EGLint es3[] = {EGL_CONTEXT_CLIENT_VERSION, 3, EGL_NONE};
  EXPECT_EQ(context(cfg, es3), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  // OpenGL-only attributes.
  const EGLint profile[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_CONTEXT_OPENGL_PROFILE_MASK,
                            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EXPECT_EQ(context(cfg, profile), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_TRUE(eglBindAPI(EGL_OPENGL_API));
}

TEST_F(EglContext, VersionsUpTo15Succeed) {
  EGLConfig cfg = config();
  for (EGLint minor : {0, 1, 2, 3, 4, 5}) {
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, minor,
                              EGL_NONE};
    EXPECT_NE(context(cfg, attribs), EGL_NO_CONTEXT) << "1." << minor;
    EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  }
  EXPECT_NE(context(cfg), EGL_NO_CONTEXT);
  const EGLint flags[] = {EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR,
                          EGL_CONTEXT_OPENGL_PROFILE_MASK,
                          EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
  EXPECT_NE(context(cfg, flags), EGL_NO_CONTEXT);
}

TEST_F(EglContext, HigherOrInvalidVersionsAreBadMatch) {
  EGLConfig cfg = config();
  const EGLint versions[][2] = {{2, 2}, {3, 0}, {3, 3}, {4, 6}, {1, 6}, {0, 9},
                                {5, 0}};
  for (auto [major, minor] : versions) {
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, major, EGL_CONTEXT_MINOR_VERSION, minor,
                              EGL_NONE};
    EXPECT_EQ(context(cfg, attribs), EGL_NO_CONTEXT) << major << "." << minor;
    EXPECT_EQ(eglGetError(), EGL_BAD_MATCH) << major << "." << minor;
  }
}

TEST_F(EglContext, BadAttributes) {
  EGLConfig cfg = config();
  const EGLint unknown[] = {0x7777, 1, EGL_NONE};
  EXPECT_EQ(context(cfg, unknown), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  const EGLint bad_flags[] = {EGL_CONTEXT_FLAGS_KHR, 0x100, EGL_NONE};
  EXPECT_EQ(context(cfg, bad_flags), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  const EGLint bad_profile[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK, 0x10, EGL_NONE};
  EXPECT_EQ(context(cfg, bad_profile), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
}

TEST_F(EglContext, BadConfigAndShareContext) {
  int junk = 0;
  EXPECT_EQ(context(reinterpret_cast<EGLConfig>(&junk)), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);
  EXPECT_EQ(eglCreateContext(dpy, config(), reinterpret_cast<EGLContext>(&junk), nullptr),
            EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
}

TEST_F(EglContext, DestroyTwiceIsBadContext) {
  EGLContext ctx = eglCreateContext(dpy, config(), EGL_NO_CONTEXT, nullptr);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  EXPECT_TRUE(eglDestroyContext(dpy, ctx));
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  EXPECT_FALSE(eglDestroyContext(dpy, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  EXPECT_FALSE(eglDestroyContext(dpy, EGL_NO_CONTEXT));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
}

TEST_F(EglContext, QueryContext) {
  EGLConfig cfg = config(16, 0);
  EGLContext ctx = context(cfg);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  EGLint id = 0, value = 0;
  ASSERT_TRUE(eglGetConfigAttrib(dpy, cfg, EGL_CONFIG_ID, &id));
  EXPECT_TRUE(eglQueryContext(dpy, ctx, EGL_CONFIG_ID, &value));
  EXPECT_EQ(value, id);
  EXPECT_TRUE(eglQueryContext(dpy, ctx, EGL_CONTEXT_CLIENT_TYPE, &value));
  EXPECT_EQ(value, EGL_OPENGL_API);
  EXPECT_TRUE(eglQueryContext(dpy, ctx, EGL_RENDER_BUFFER, &value));
  EXPECT_EQ(value, EGL_NONE);
  EGLSurface s = pbuffer(cfg, 4, 4);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, ctx));
  EXPECT_TRUE(eglQueryContext(dpy, ctx, EGL_RENDER_BUFFER, &value));
  EXPECT_EQ(value, EGL_BACK_BUFFER);
  EXPECT_FALSE(eglQueryContext(dpy, ctx, 0x7777, &value));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_FALSE(eglQueryContext(dpy, EGL_NO_CONTEXT, EGL_CONFIG_ID, &value));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
}

}  // namespace
