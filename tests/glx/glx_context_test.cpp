// Contexts: glXCreateContextAttribsARB's versions and profiles, queries, glXCopyContext,
// and make-current errors (bad context, context current in another thread, bad drawables).
#include "glx_fixture.h"

#include <string>
#include <thread>
#include <tuple>

namespace pineda_test {
namespace {

using GlxContextTest = GlxTest;

GLXContext create_attribs(Display* dpy, GLXFBConfig config, std::vector<int> attribs) {
  attribs.push_back(None);
  return glXCreateContextAttribsARB(dpy, config, nullptr, True, attribs.data());
}

TEST_F(GlxContextTest, CreateContextAttribsVersions) {
  GLXFBConfig config = rgba8(true, true);
  for (auto [major, minor] : {std::pair{1, 0}, {1, 1}, {1, 2}, {1, 3}, {1, 4}, {1, 5}, {2, 0}, {2, 1}}) {
    GLXContext ctx = create_attribs(dpy, config, {GLX_CONTEXT_MAJOR_VERSION_ARB, major,
                                                  GLX_CONTEXT_MINOR_VERSION_ARB, minor});
    EXPECT_NE(ctx, nullptr) << major << "." << minor;
    if (ctx) glXDestroyContext(dpy, ctx);
  }
  GLXContext plain = create_attribs(dpy, config, {});
  ASSERT_NE(plain, nullptr);
  glXDestroyContext(dpy, plain);
  EXPECT_TRUE(take_errors().empty());

  // Versions above the implemented one are GLXBadFBConfig; ones GL never had BadMatch.
  for (auto [major, minor, error] : {std::tuple{3, 0, glx_error_base() + GLXBadFBConfig},
                                     {3, 3, glx_error_base() + GLXBadFBConfig},
                                     {1, 6, int{BadMatch}}, {4, 7, int{BadMatch}}}) {
    EXPECT_EQ(create_attribs(dpy, config, {GLX_CONTEXT_MAJOR_VERSION_ARB, major,
                                           GLX_CONTEXT_MINOR_VERSION_ARB, minor}),
              nullptr);
    auto errors = take_errors();
    ASSERT_EQ(errors.size(), 1u) << major << "." << minor;
    EXPECT_EQ(errors[0].error_code, error) << major << "." << minor;
  }
  EXPECT_EQ(create_attribs(dpy, config, {GLX_CONTEXT_PROFILE_MASK_ARB, 0x10}), nullptr);
  auto errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, glx_error_base() + GLXBadProfileARB);
  EXPECT_EQ(create_attribs(dpy, config, {0x7777, 1}), nullptr);
  errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, BadValue);
  // Forward-compatible contexts exist from GL 3.0.
  EXPECT_EQ(create_attribs(dpy, config, {GLX_CONTEXT_FLAGS_ARB, GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB}),
            nullptr);
  errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, BadMatch);
  GLXContext debug = create_attribs(dpy, config, {GLX_CONTEXT_FLAGS_ARB, GLX_CONTEXT_DEBUG_BIT_ARB,
                                                  GLX_CONTEXT_PROFILE_MASK_ARB,
                                                  GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB});
  EXPECT_NE(debug, nullptr);
  if (debug) glXDestroyContext(dpy, debug);
  EXPECT_EQ(glXCreateContextAttribsARB(dpy, nullptr, nullptr, True, nullptr), nullptr);
  errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, glx_error_base() + GLXBadFBConfig);
}

// GLX_ARB_create_context_robustness: the context reports what was asked (Pineda's contexts
// are robust and never reset anyway); shared contexts have one reset strategy.
TEST_F(GlxContextTest, CreateContextRobustness) {
  const std::string extensions = glXQueryExtensionsString(dpy, screen);
  EXPECT_NE((extensions + " ").find("GLX_ARB_create_context_robustness "), std::string::npos);
  GLXFBConfig config = rgba8(true, false);
  Window w = window(config, 8, 8);
  const std::vector<int> lose = {GLX_CONTEXT_RESET_NOTIFICATION_STRATEGY_ARB, GLX_LOSE_CONTEXT_ON_RESET_ARB};
  for (auto [attribs, robust, strategy] :
       {std::tuple{std::vector<int>{}, GL_FALSE, GL_NO_RESET_NOTIFICATION_ARB},
        {std::vector<int>{GLX_CONTEXT_FLAGS_ARB, GLX_CONTEXT_ROBUST_ACCESS_BIT_ARB}, GL_TRUE, GL_NO_RESET_NOTIFICATION_ARB},
        {lose, GL_FALSE, GL_LOSE_CONTEXT_ON_RESET_ARB},
        {std::vector<int>{GLX_CONTEXT_RESET_NOTIFICATION_STRATEGY_ARB, GLX_NO_RESET_NOTIFICATION_ARB}, GL_FALSE,
         GL_NO_RESET_NOTIFICATION_ARB}}) {
    GLXContext ctx = create_attribs(dpy, config, attribs);
    ASSERT_NE(ctx, nullptr);
    ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
    GLint robust_access = -1, reset_strategy = -1;
    glGetIntegerv(GL_CONTEXT_ROBUST_ACCESS, &robust_access);
    glGetIntegerv(GL_RESET_NOTIFICATION_STRATEGY_ARB, &reset_strategy);
    EXPECT_EQ(robust_access, robust);
    EXPECT_EQ(reset_strategy, strategy);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
    glXDestroyContext(dpy, ctx);
  }
  EXPECT_TRUE(take_errors().empty());

  EXPECT_EQ(create_attribs(dpy, config, {GLX_CONTEXT_RESET_NOTIFICATION_STRATEGY_ARB, 0x1234}), nullptr);
  auto errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, BadMatch);

  std::vector<int> with_none = lose;
  with_none.push_back(None);
  GLXContext first = glXCreateContextAttribsARB(dpy, config, nullptr, True, with_none.data());
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(glXCreateContextAttribsARB(dpy, config, first, True, std::vector<int>{None}.data()), nullptr);
  errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, BadMatch);
  GLXContext second = glXCreateContextAttribsARB(dpy, config, first, True, with_none.data());
  EXPECT_NE(second, nullptr);
  EXPECT_TRUE(take_errors().empty());
  if (second) glXDestroyContext(dpy, second);
  glXDestroyContext(dpy, first);
}

// GLX_EXT_create_context_es_profile / es2_profile: ES 1.1 and 2.0 contexts that draw into GLX
// drawables; versions ES never had are GLXBadProfileARB, ES 3.0 (which Pineda does not have)
// GLXBadFBConfig.
TEST_F(GlxContextTest, CreateContextEsProfiles) {
  const std::string extensions = std::string(glXQueryExtensionsString(dpy, screen)) + " ";
  EXPECT_NE(extensions.find("GLX_EXT_create_context_es2_profile "), std::string::npos);
  EXPECT_NE(extensions.find("GLX_EXT_create_context_es_profile "), std::string::npos);
  GLXFBConfig config = rgba8(true, false);
  Window w = window(config, 8, 8);
  for (auto [major, minor, version] : {std::tuple{2, 0, "OpenGL ES 2.0"}, {1, 1, "OpenGL ES-CM 1.1"},
                                       {1, 0, "OpenGL ES-CM 1.1"}}) {
    GLXContext ctx = create_attribs(dpy, config, {GLX_CONTEXT_MAJOR_VERSION_ARB, major, GLX_CONTEXT_MINOR_VERSION_ARB,
                                                  minor, GLX_CONTEXT_PROFILE_MASK_ARB, GLX_CONTEXT_ES_PROFILE_BIT_EXT});
    ASSERT_NE(ctx, nullptr) << major << "." << minor;
    ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
    const std::string got = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    EXPECT_EQ(got.rfind(version, 0), 0u) << got;
    glClearColor(0.f, 1.f, 0.f, 1.f);
    glClear(GL_COLOR_BUFFER_BIT);
    GLubyte pixel[4] = {};
    glReadPixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    EXPECT_EQ(pixel[0], 0);
    EXPECT_EQ(pixel[1], 255);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    glBegin(GL_POINTS);  // not an ES command
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
    ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
    glXDestroyContext(dpy, ctx);
  }
  EXPECT_TRUE(take_errors().empty());
  const int bad_profile = glx_error_base() + GLXBadProfileARB;
  for (auto [major, minor, error] : {std::tuple{2, 1, bad_profile}, {1, 2, bad_profile}, {0, 9, bad_profile},
                                     {3, 3, bad_profile}, {3, 0, glx_error_base() + GLXBadFBConfig}}) {
    EXPECT_EQ(create_attribs(dpy, config, {GLX_CONTEXT_MAJOR_VERSION_ARB, major, GLX_CONTEXT_MINOR_VERSION_ARB, minor,
                                           GLX_CONTEXT_PROFILE_MASK_ARB, GLX_CONTEXT_ES_PROFILE_BIT_EXT}),
              nullptr);
    auto errors = take_errors();
    ASSERT_EQ(errors.size(), 1u) << major << "." << minor;
    EXPECT_EQ(errors[0].error_code, error) << major << "." << minor;
  }
  // The ES bit with a desktop profile bit is no profile at all.
  EXPECT_EQ(create_attribs(dpy, config, {GLX_CONTEXT_MAJOR_VERSION_ARB, 2, GLX_CONTEXT_PROFILE_MASK_ARB,
                                         GLX_CONTEXT_ES_PROFILE_BIT_EXT | GLX_CONTEXT_CORE_PROFILE_BIT_ARB}),
            nullptr);
  auto errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, glx_error_base() + GLXBadProfileARB);
}

TEST_F(GlxContextTest, QueryContext) {
  GLXFBConfig config = rgba8(true, true);
  GLXContext ctx = context(config);
  int id = 0, value = 0;
  glXGetFBConfigAttrib(dpy, config, GLX_FBCONFIG_ID, &id);
  EXPECT_EQ(glXQueryContext(dpy, ctx, GLX_FBCONFIG_ID, &value), Success);
  EXPECT_EQ(value, id);
  EXPECT_EQ(glXQueryContext(dpy, ctx, GLX_RENDER_TYPE, &value), Success);
  EXPECT_EQ(value, GLX_RGBA_TYPE);
  EXPECT_EQ(glXQueryContext(dpy, ctx, GLX_SCREEN, &value), Success);
  EXPECT_EQ(value, screen);
  EXPECT_EQ(glXQueryContext(dpy, ctx, 0x7777, &value), GLX_BAD_ATTRIBUTE);
  EXPECT_TRUE(take_errors().empty());
}

TEST_F(GlxContextTest, CopyContext) {
  GLXFBConfig config = rgba8(true, false);
  GLXContext a = context(config), b = context(config);
  Window w = window(config, 8, 8);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, a));
  glClearColor(0.5f, 0.25f, 1, 1);
  ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
  glXCopyContext(dpy, a, b, GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, b));
  GLfloat clear[4] = {};
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
  EXPECT_EQ(clear[0], 0.5f);
  EXPECT_EQ(clear[1], 0.25f);
  EXPECT_TRUE(take_errors().empty());
  // The destination may not be current.
  glXCopyContext(dpy, a, b, GL_COLOR_BUFFER_BIT);
  auto errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, BadAccess);
}

TEST_F(GlxContextTest, MakeCurrentErrors) {
  GLXFBConfig config = rgba8(true, true);
  Window w = window(config, 8, 8);
  GLXContext ctx = context(config);

  int bogus = 0;
  EXPECT_FALSE(glXMakeCurrent(dpy, w, reinterpret_cast<GLXContext>(&bogus)));
  auto errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, glx_error_base() + GLXBadContext);

  // A drawable without a context.
  EXPECT_FALSE(glXMakeCurrent(dpy, w, nullptr));
  errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, BadMatch);

  // Not a drawable at all.
  EXPECT_FALSE(glXMakeCurrent(dpy, 0x7ffffff, ctx));
  errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, glx_error_base() + GLXBadDrawable);

  // A destroyed GLX window.
  GLXWindow gw = glXCreateWindow(dpy, config, w, nullptr);
  glXDestroyWindow(dpy, gw);
  EXPECT_FALSE(glXMakeContextCurrent(dpy, gw, gw, ctx));
  errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, glx_error_base() + GLXBadDrawable);
  glXDestroyWindow(dpy, gw);
  errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, glx_error_base() + GLXBadWindow);

  // A config with other buffers than the drawable's.
  GLXContext other = context(rgba8(true, false));
  GLXWindow gw2 = glXCreateWindow(dpy, config, w, nullptr);
  EXPECT_FALSE(glXMakeContextCurrent(dpy, gw2, gw2, other));
  errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, BadMatch);
  // One GLXWindow per window.
  EXPECT_EQ(glXCreateWindow(dpy, config, w, nullptr), None);
  errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, BadAlloc);
  glXDestroyWindow(dpy, gw2);

  glXDestroyContext(dpy, reinterpret_cast<GLXContext>(&bogus));
  errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, glx_error_base() + GLXBadContext);
}

TEST_F(GlxContextTest, ContextCurrentInAnotherThreadIsBadAccess) {
  GLXFBConfig config = rgba8(true, true);
  Window w = window(config, 8, 8);
  GLXContext ctx = context(config);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
  Bool other_thread = True;
  std::thread([&] { other_thread = glXMakeCurrent(dpy, w, ctx); }).join();
  EXPECT_FALSE(other_thread);
  auto errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, BadAccess);

  // Released here, it can be bound there; a thread that ends lets go of its context.
  ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
  std::thread([&] {
    other_thread = glXMakeCurrent(dpy, w, ctx);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glXSwapBuffers(dpy, w);
  }).join();
  EXPECT_TRUE(other_thread);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
  EXPECT_EQ(gl_pixel(1, 1), 0x0000ffu);
  EXPECT_TRUE(take_errors().empty());
}

TEST_F(GlxContextTest, DestroyedCurrentContextLivesUntilReleased) {
  GLXFBConfig config = rgba8(true, true);
  Window w = window(config, 8, 8);
  GLXContext ctx = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
  glXDestroyContext(dpy, ctx);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(gl_pixel(0, 0), 0xff0000u);
  EXPECT_EQ(glXGetCurrentContext(), ctx);
  // Still current, it can be made current again, and destroying it again is harmless.
  ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
  glXDestroyContext(dpy, ctx);
  EXPECT_TRUE(take_errors().empty());
  EXPECT_EQ(gl_pixel(0, 0), 0xff0000u);
  ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
  // Released, it is gone.
  EXPECT_FALSE(glXMakeCurrent(dpy, w, ctx));
  auto errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, glx_error_base() + GLXBadContext);
  EXPECT_TRUE(take_errors().empty());
}

TEST_F(GlxContextTest, DestroyingTheXWindowDestroysTheGlxWindow) {
  GLXFBConfig config = rgba8(false, false);
  Window w = window(config, 8, 8);
  GLXWindow gw = glXCreateWindow(dpy, config, w, nullptr);
  GLXContext ctx = context(config);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, gw, gw, ctx));
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  XDestroyWindow(dpy, w);
  windows.clear();
  XSync(dpy, False);
  // The implicit flush of a single-buffered window that is gone raises nothing.
  ASSERT_TRUE(glXMakeContextCurrent(dpy, None, None, nullptr));
  EXPECT_TRUE(take_errors().empty());
  glXDestroyWindow(dpy, gw);
  auto errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, glx_error_base() + GLXBadWindow);
}

TEST_F(GlxContextTest, PbufferOfAnotherConnectionToTheSameServer) {
  Display* other = XOpenDisplay(DisplayString(dpy));
  ASSERT_NE(other, nullptr);
  GLXFBConfig config = rgba8(true, true);
  const int attribs[] = {GLX_PBUFFER_WIDTH, 16, GLX_PBUFFER_HEIGHT, 16, None};
  GLXPbuffer pb = glXCreatePbuffer(dpy, config, attribs);
  int n = 0, id = 0;
  glXGetFBConfigAttrib(dpy, config, GLX_FBCONFIG_ID, &id);
  const int by_id[] = {GLX_FBCONFIG_ID, id, None};
  GLXFBConfig* other_configs = glXChooseFBConfig(other, DefaultScreen(other), by_id, &n);
  ASSERT_EQ(n, 1);
  GLXContext ctx = glXCreateNewContext(other, other_configs[0], GLX_RGBA_TYPE, nullptr, True);
  XFree(other_configs);
  ASSERT_TRUE(glXMakeContextCurrent(other, pb, pb, ctx));
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(gl_pixel(15, 15), 0x00ff00u);
  ASSERT_TRUE(glXMakeContextCurrent(other, None, None, nullptr));
  glXDestroyContext(other, ctx);
  glXDestroyPbuffer(dpy, pb);
  XCloseDisplay(other);
  EXPECT_TRUE(take_errors().empty());
}

TEST_F(GlxContextTest, ShareListsShareTexturesAndLists) {
  GLXFBConfig config = rgba8(true, true);
  GLXContext a = context(config);
  GLXContext b = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, a, True);
  ASSERT_NE(b, nullptr);
  const int size[] = {GLX_PBUFFER_WIDTH, 16, GLX_PBUFFER_HEIGHT, 16, None};
  GLXPbuffer pb = glXCreatePbuffer(dpy, config, size);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, pb, pb, a));
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glClearColor(0, 0, 1, 1);
  glEndList();
  ASSERT_TRUE(glXMakeContextCurrent(dpy, pb, pb, b));
  EXPECT_EQ(glIsList(list), GL_TRUE);
  glCallList(list);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(gl_pixel(15, 15), 0x0000ffu);
  // A share context that does not exist is GLXBadContext.
  glXMakeContextCurrent(dpy, None, None, nullptr);
  glXDestroyContext(dpy, b);
  EXPECT_EQ(glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, b, True), nullptr);
  auto errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  glXDestroyPbuffer(dpy, pb);
}

}  // namespace
}  // namespace pineda_test
