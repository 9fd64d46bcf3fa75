// eglQueryString and eglGetProcAddress.
#include <GL/gl.h>

#include <cstring>
#include <string>

#include "egl_fixture.h"
// After gtest: Xlib defines macros (None, Bool) that gtest's headers use as names.
#include <GL/glx.h>

namespace {

using pineda_test::EglTest;
using EglStrings = EglTest;

bool has_extension(const char* list, const std::string& name) {
  std::string padded = " " + std::string(list ? list : "") + " ";
  return padded.find(" " + name + " ") != std::string::npos;
}

TEST(EglClientStrings, ClientExtensionsWithoutDisplay) {
  const char* ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  ASSERT_NE(ext, nullptr);
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  for (const char* name : {"EGL_EXT_client_extensions", "EGL_EXT_platform_base",
                           "EGL_MESA_platform_surfaceless", "EGL_KHR_platform_x11",
                           "EGL_EXT_platform_x11", "EGL_KHR_client_get_all_proc_addresses"})
    EXPECT_TRUE(has_extension(ext, name)) << name;
  EXPECT_FALSE(has_extension(ext, "EGL_KHR_create_context"));
  const char* version = eglQueryString(EGL_NO_DISPLAY, EGL_VERSION);
  ASSERT_NE(version, nullptr);
  EXPECT_EQ(std::strncmp(version, "1.5", 3), 0);
  EXPECT_EQ(eglQueryString(EGL_NO_DISPLAY, EGL_VENDOR), nullptr);
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
}

TEST_F(EglStrings, DisplayStrings) {
  EXPECT_STREQ(eglQueryString(dpy, EGL_VENDOR), "Pineda");
  EXPECT_STREQ(eglQueryString(dpy, EGL_VERSION), "1.5 Pineda");
  EXPECT_STREQ(eglQueryString(dpy, EGL_CLIENT_APIS), "OpenGL OpenGL_ES");
  const char* ext = eglQueryString(dpy, EGL_EXTENSIONS);
  for (const char* name : {"EGL_KHR_create_context", "EGL_KHR_surfaceless_context",
                           "EGL_KHR_get_all_proc_addresses"})
    EXPECT_TRUE(has_extension(ext, name)) << name;
  EXPECT_FALSE(has_extension(ext, "EGL_EXT_client_extensions"));
  EXPECT_EQ(eglQueryString(dpy, 0x7777), nullptr);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

TEST(EglProcAddress, KnownEglAndGlFunctions) {
  EXPECT_EQ(eglGetProcAddress("eglGetPlatformDisplay"),
            reinterpret_cast<__eglMustCastToProperFunctionPointerType>(&eglGetPlatformDisplay));
  EXPECT_EQ(eglGetProcAddress("eglGetPlatformDisplayEXT"),
            reinterpret_cast<__eglMustCastToProperFunctionPointerType>(&eglGetPlatformDisplayEXT));
  EXPECT_EQ(eglGetProcAddress("eglMakeCurrent"),
            reinterpret_cast<__eglMustCastToProperFunctionPointerType>(&eglMakeCurrent));
  EXPECT_EQ(eglGetProcAddress("glClear"),
            reinterpret_cast<__eglMustCastToProperFunctionPointerType>(&glClear));
  EXPECT_EQ(eglGetProcAddress("glGetError"),
            reinterpret_cast<__eglMustCastToProperFunctionPointerType>(&glGetError));
}

// apitrace's eglretrace resolves glXGetCurrentDisplay through eglGetProcAddress (glvnd's libEGL
// answers any gl-prefixed name); the one library has it, so it is handed out.
TEST(EglProcAddress, GlxFunctionsOfTheSameLibrary) {
  auto proc = eglGetProcAddress("glXGetCurrentDisplay");
  EXPECT_EQ(proc, reinterpret_cast<__eglMustCastToProperFunctionPointerType>(&glXGetCurrentDisplay));
  ASSERT_NE(proc, nullptr);
  EXPECT_EQ(reinterpret_cast<Display* (*)()>(proc)(), nullptr);  // no GLX context is current
  EXPECT_EQ(eglGetProcAddress("glXSwapBuffers"),
            reinterpret_cast<__eglMustCastToProperFunctionPointerType>(&glXSwapBuffers));
  EXPECT_EQ(eglGetProcAddress("glXNoSuchFunction"), nullptr);
}

TEST(EglProcAddress, UnknownNamesAreNull) {
  EXPECT_EQ(eglGetProcAddress("glNoSuchFunction"), nullptr);
  EXPECT_EQ(eglGetProcAddress("eglNoSuchFunction"), nullptr);
  EXPECT_EQ(eglGetProcAddress(""), nullptr);
  EXPECT_EQ(eglGetProcAddress("glClea"), nullptr);
  EXPECT_EQ(eglGetProcAddress("glClearX"), nullptr);
  EXPECT_EQ(eglGetProcAddress(nullptr), nullptr);
  // In gl.xml, but not implemented: not offered.
  EXPECT_EQ(eglGetProcAddress("glDispatchCompute"), nullptr);
  EXPECT_EQ(eglGetProcAddress("eglCreateSyncKHR"), nullptr);
}

}  // namespace
