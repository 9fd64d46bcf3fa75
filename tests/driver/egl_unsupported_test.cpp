// EGL 1.5 entry points for what the surfaceless platform lacks, and fence syncs.
#include "egl_fixture.h"

namespace {

using pineda_test::EglTest;
using EglUnsupported = EglTest;
using EglSync = EglTest;

TEST_F(EglUnsupported, WindowsAndPixmapsAreBadMatch) {
  EGLConfig cfg = config();
  EXPECT_EQ(eglCreateWindowSurface(dpy, cfg, 0, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_EQ(eglCreatePlatformWindowSurface(dpy, cfg, nullptr, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_EQ(eglCreatePixmapSurface(dpy, cfg, 0, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_EQ(eglCreatePlatformPixmapSurface(dpy, cfg, nullptr, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_EQ(eglCreateWindowSurface(dpy, nullptr, 0, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);
}

TEST_F(EglUnsupported, PbufferTexturesAndCopies) {
  EGLSurface s = pbuffer(config(), 4, 4);
  EXPECT_FALSE(eglBindTexImage(dpy, s, EGL_BACK_BUFFER));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_FALSE(eglReleaseTexImage(dpy, s, EGL_BACK_BUFFER));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_FALSE(eglBindTexImage(dpy, EGL_NO_SURFACE, EGL_BACK_BUFFER));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  EXPECT_FALSE(eglCopyBuffers(dpy, s, 0));
  EXPECT_EQ(eglGetError(), EGL_BAD_NATIVE_PIXMAP);
  EXPECT_EQ(eglCreatePbufferFromClientBuffer(dpy, EGL_OPENVG_IMAGE, nullptr, config(), nullptr),
            EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

TEST_F(EglUnsupported, SurfaceAttrib) {
  EGLSurface s = pbuffer(config(), 4, 4);
  EXPECT_TRUE(eglSurfaceAttrib(dpy, s, EGL_SWAP_BEHAVIOR, EGL_BUFFER_DESTROYED));
  EXPECT_TRUE(eglSurfaceAttrib(dpy, s, EGL_MIPMAP_LEVEL, 0));
  EXPECT_FALSE(eglSurfaceAttrib(dpy, s, EGL_MULTISAMPLE_RESOLVE, EGL_MULTISAMPLE_RESOLVE_BOX));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_FALSE(eglSurfaceAttrib(dpy, s, EGL_WIDTH, 8));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
}

TEST_F(EglUnsupported, Images) {
  EXPECT_EQ(eglCreateImage(dpy, EGL_NO_CONTEXT, EGL_GL_TEXTURE_2D, nullptr, nullptr), EGL_NO_IMAGE);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_FALSE(eglDestroyImage(dpy, EGL_NO_IMAGE));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

TEST_F(EglSync, FenceNeedsACurrentContext) {
  EXPECT_EQ(eglCreateSync(dpy, EGL_SYNC_FENCE, nullptr), EGL_NO_SYNC);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, context(config())));
  EXPECT_EQ(eglCreateSync(dpy, EGL_SYNC_REUSABLE_KHR, nullptr), EGL_NO_SYNC);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  const EGLAttrib attribs[] = {EGL_SYNC_STATUS, EGL_SIGNALED, EGL_NONE};
  EXPECT_EQ(eglCreateSync(dpy, EGL_SYNC_FENCE, attribs), EGL_NO_SYNC);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
}

TEST_F(EglSync, FenceIsSignaled) {
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, context(config())));
  EGLSync sync = eglCreateSync(dpy, EGL_SYNC_FENCE, nullptr);
  ASSERT_NE(sync, EGL_NO_SYNC);
  EGLAttrib value = 0;
  EXPECT_TRUE(eglGetSyncAttrib(dpy, sync, EGL_SYNC_TYPE, &value));
  EXPECT_EQ(value, EGL_SYNC_FENCE);
  EXPECT_TRUE(eglGetSyncAttrib(dpy, sync, EGL_SYNC_STATUS, &value));
  EXPECT_EQ(value, EGL_SIGNALED);
  EXPECT_TRUE(eglGetSyncAttrib(dpy, sync, EGL_SYNC_CONDITION, &value));
  EXPECT_EQ(value, EGL_SYNC_PRIOR_COMMANDS_COMPLETE);
  EXPECT_FALSE(eglGetSyncAttrib(dpy, sync, EGL_WIDTH, &value));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_EQ(eglClientWaitSync(dpy, sync, EGL_SYNC_FLUSH_COMMANDS_BIT, EGL_FOREVER),
            EGL_CONDITION_SATISFIED);
  EXPECT_TRUE(eglWaitSync(dpy, sync, 0));
  EXPECT_FALSE(eglWaitSync(dpy, sync, 1));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_TRUE(eglDestroySync(dpy, sync));
  EXPECT_FALSE(eglDestroySync(dpy, sync));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_EQ(eglClientWaitSync(dpy, sync, 0, 0), EGL_FALSE);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

}  // namespace
