// glXQueryVersion, glXQueryExtension, the strings and glXGetProcAddress.
#include "glx_fixture.h"

#include <cstring>
#include <string>

namespace pineda_test {
namespace {

using GlxQueryTest = GlxTest;

TEST_F(GlxQueryTest, VersionIs14) {
  int major = 0, minor = 0;
  ASSERT_TRUE(glXQueryVersion(dpy, &major, &minor));
  EXPECT_EQ(major, 1);
  EXPECT_EQ(minor, 4);
}

TEST_F(GlxQueryTest, StringsNamePineda) {
  EXPECT_STREQ(glXQueryServerString(dpy, screen, GLX_VENDOR), "Pineda");
  EXPECT_STREQ(glXQueryServerString(dpy, screen, GLX_VERSION), "1.4");
  EXPECT_STREQ(glXGetClientString(dpy, GLX_VENDOR), "Pineda");
  EXPECT_EQ(glXGetClientString(dpy, 0x7777), nullptr);
  const std::string extensions = glXQueryExtensionsString(dpy, screen);
  for (const char* name : {"GLX_ARB_create_context", "GLX_ARB_create_context_profile",
                           "GLX_ARB_get_proc_address", "GLX_EXT_swap_control",
                           "GLX_MESA_swap_control", "GLX_SGI_swap_control"})
    EXPECT_NE(extensions.find(name), std::string::npos) << name;
  EXPECT_EQ(glXQueryExtensionsString(dpy, 99), nullptr);
}

TEST_F(GlxQueryTest, ProcAddressOfKnownAndUnknownNames) {
  auto lookup = [](const char* name) {
    return reinterpret_cast<void*>(glXGetProcAddressARB(reinterpret_cast<const GLubyte*>(name)));
  };
  EXPECT_EQ(lookup("glClear"), reinterpret_cast<void*>(&glClear));
  EXPECT_EQ(lookup("glNewList"), reinterpret_cast<void*>(&glNewList));
  EXPECT_EQ(lookup("glXCreateContextAttribsARB"), reinterpret_cast<void*>(&glXCreateContextAttribsARB));
  EXPECT_EQ(lookup("glXSwapIntervalEXT"), reinterpret_cast<void*>(&glXSwapIntervalEXT));
  EXPECT_EQ(lookup("glXMakeCurrent"), reinterpret_cast<void*>(&glXMakeCurrent));
  EXPECT_EQ(lookup("glNoSuchFunction"), nullptr);
  EXPECT_EQ(lookup("glXNoSuchFunction"), nullptr);
  EXPECT_EQ(lookup(""), nullptr);
  EXPECT_EQ(reinterpret_cast<void*>(glXGetProcAddress(reinterpret_cast<const GLubyte*>("glFinish"))),
            reinterpret_cast<void*>(&glFinish));
}

TEST_F(GlxQueryTest, NothingIsCurrentAtFirst) {
  EXPECT_EQ(glXGetCurrentContext(), nullptr);
  EXPECT_EQ(glXGetCurrentDrawable(), None);
  EXPECT_EQ(glXGetCurrentReadDrawable(), None);
  EXPECT_EQ(glXGetCurrentDisplay(), nullptr);
}

// Null displays and pointers are refused without crashing.
TEST_F(GlxQueryTest, NullArguments) {
  EXPECT_FALSE(glXQueryVersion(nullptr, nullptr, nullptr));
  EXPECT_FALSE(glXQueryExtension(nullptr, nullptr, nullptr));
  EXPECT_TRUE(glXQueryVersion(dpy, nullptr, nullptr));
  EXPECT_EQ(glXQueryExtensionsString(nullptr, 0), nullptr);
  EXPECT_EQ(glXQueryServerString(nullptr, 0, GLX_VENDOR), nullptr);
  EXPECT_EQ(glXGetFBConfigs(nullptr, 0, nullptr), nullptr);
  EXPECT_EQ(glXGetFBConfigs(dpy, 42, nullptr), nullptr);
  EXPECT_EQ(glXChooseFBConfig(nullptr, 0, nullptr, nullptr), nullptr);
  EXPECT_EQ(glXChooseVisual(nullptr, 0, nullptr), nullptr);
  EXPECT_EQ(glXChooseVisual(dpy, screen, nullptr), nullptr);  // no GLX_RGBA: colour index
  int value = 0;
  EXPECT_NE(glXGetConfig(dpy, nullptr, GLX_RGBA, &value), 0);
  EXPECT_NE(glXGetFBConfigAttrib(dpy, nullptr, GLX_RED_SIZE, &value), 0);
  EXPECT_EQ(glXGetVisualFromFBConfig(dpy, nullptr), nullptr);
  EXPECT_EQ(glXCreateContext(dpy, nullptr, nullptr, True), nullptr);
  EXPECT_EQ(glXCreateNewContext(dpy, nullptr, GLX_RGBA_TYPE, nullptr, True), nullptr);
  glXMakeCurrent(nullptr, None, nullptr);  // releasing nothing
  EXPECT_FALSE(glXMakeContextCurrent(nullptr, 1, 1, reinterpret_cast<GLXContext>(&value)));
  glXSwapBuffers(nullptr, 1);
  glXDestroyContext(nullptr, nullptr);
  glXWaitGL();
  glXWaitX();
  int n = 0;
  GLXFBConfig* configs = glXGetFBConfigs(dpy, screen, &n);
  ASSERT_GT(n, 0);
  GLXContext ctx = glXCreateNewContext(dpy, configs[0], GLX_RGBA_TYPE, nullptr, True);
  XFree(configs);
  EXPECT_EQ(glXQueryContext(dpy, ctx, GLX_FBCONFIG_ID, nullptr), GLX_BAD_VALUE);
  glXQueryDrawable(dpy, None, GLX_WIDTH, nullptr);
  glXDestroyContext(dpy, ctx);
  take_errors();
}

}  // namespace
}  // namespace pineda_test
