// Configs: what glXGetFBConfigs lists, glXChooseFBConfig's matching and sorting,
// glXChooseVisual and glXGetConfig.
#include "glx_fixture.h"

#include <set>

namespace pineda_test {
namespace {

using GlxConfigTest = GlxTest;

int attrib(Display* dpy, GLXFBConfig c, int name) {
  int value = -12345;
  EXPECT_EQ(glXGetFBConfigAttrib(dpy, c, name, &value), Success) << std::hex << name;
  return value;
}

TEST_F(GlxConfigTest, EveryConfigIsRgba8OnATrueColorVisual) {
  int n = 0;
  GLXFBConfig* configs = glXGetFBConfigs(dpy, screen, &n);
  ASSERT_GE(n, 8);
  std::set<int> ids;
  for (int i = 0; i < n; ++i) {
    GLXFBConfig c = configs[i];
    ids.insert(attrib(dpy, c, GLX_FBCONFIG_ID));
    EXPECT_EQ(attrib(dpy, c, GLX_RED_SIZE), 8);
    EXPECT_EQ(attrib(dpy, c, GLX_GREEN_SIZE), 8);
    EXPECT_EQ(attrib(dpy, c, GLX_BLUE_SIZE), 8);
    EXPECT_EQ(attrib(dpy, c, GLX_RENDER_TYPE), GLX_RGBA_BIT);
    EXPECT_EQ(attrib(dpy, c, GLX_DRAWABLE_TYPE), GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT);
    EXPECT_EQ(attrib(dpy, c, GLX_X_RENDERABLE), True);
    EXPECT_EQ(attrib(dpy, c, GLX_X_VISUAL_TYPE), GLX_TRUE_COLOR);
    // Single-sampled, or 4x multisampled and double-buffered.
    const int samples = attrib(dpy, c, GLX_SAMPLES);
    EXPECT_TRUE(samples == 0 || (samples == 4 && attrib(dpy, c, GLX_DOUBLEBUFFER) == True)) << samples;
    EXPECT_EQ(attrib(dpy, c, GLX_SAMPLE_BUFFERS), samples ? 1 : 0);
    EXPECT_EQ(attrib(dpy, c, GLX_CONFIG_CAVEAT), GLX_NONE);
    const int depth = attrib(dpy, c, GLX_DEPTH_SIZE), stencil = attrib(dpy, c, GLX_STENCIL_SIZE);
    // Depth and stencil, neither, or (single-sampled) depth alone.
    EXPECT_TRUE((depth == 24 && stencil == 8) || (depth == 0 && stencil == 0) ||
                (depth == 24 && stencil == 0 && samples == 0))
        << depth << " " << stencil;
    XVisualInfo* vi = glXGetVisualFromFBConfig(dpy, c);
    ASSERT_NE(vi, nullptr);
    EXPECT_EQ(static_cast<int>(vi->visualid), attrib(dpy, c, GLX_VISUAL_ID));
    EXPECT_EQ(vi->c_class, TrueColor);
    EXPECT_TRUE(vi->depth == 24 || vi->depth == 32);
    XFree(vi);
  }
  EXPECT_EQ(static_cast<int>(ids.size()), n);
  XFree(configs);
  for (bool db : {false, true})
    for (bool ds : {false, true}) EXPECT_NE(rgba8(db, ds), nullptr) << db << ds;
}

// Programs that score the configs themselves (glmark2: depth wanted, stencil not) need a
// config with depth and no stencil; GLX sorts the smaller stencil first.
TEST_F(GlxConfigTest, DepthWithoutStencil) {
  for (bool db : {true, false}) {
    int n = 0;
    const int depth_only[] = {GLX_DOUBLEBUFFER, db, GLX_DEPTH_SIZE, 1, GLX_STENCIL_SIZE, 0, None};
    GLXFBConfig* configs = glXChooseFBConfig(dpy, screen, depth_only, &n);
    ASSERT_GT(n, 0);
    EXPECT_EQ(attrib(dpy, configs[0], GLX_DEPTH_SIZE), 24);
    EXPECT_EQ(attrib(dpy, configs[0], GLX_STENCIL_SIZE), 0);
    EXPECT_EQ(attrib(dpy, configs[0], GLX_DOUBLEBUFFER), db ? True : False);
    XFree(configs);
  }
}

TEST_F(GlxConfigTest, MultisampledConfigsSortAfterSingleSampled) {
  int n = 0;
  const int any[] = {GLX_DOUBLEBUFFER, True, None};
  GLXFBConfig* configs = glXChooseFBConfig(dpy, screen, any, &n);
  ASSERT_GT(n, 0);
  EXPECT_EQ(attrib(dpy, configs[0], GLX_SAMPLES), 0);
  // GLX 1.4 table 3.4: after the buffer size and double buffering, fewer samples first.
  int last_samples = 0, last_size = 0, multisampled = 0;
  for (int i = 0; i < n; ++i) {
    const int samples = attrib(dpy, configs[i], GLX_SAMPLES), size = attrib(dpy, configs[i], GLX_BUFFER_SIZE);
    if (size == last_size) {
      EXPECT_GE(samples, last_samples) << i;
    }
    last_samples = samples;
    last_size = size;
    multisampled += samples > 0;
  }
  EXPECT_GT(multisampled, 0);
  XFree(configs);
  for (int asked : {1, 2, 4}) {
    const int ms[] = {GLX_SAMPLE_BUFFERS, 1, GLX_SAMPLES, asked, None};
    configs = glXChooseFBConfig(dpy, screen, ms, &n);
    ASSERT_GT(n, 0) << asked;
    for (int i = 0; i < n; ++i) {
      EXPECT_EQ(attrib(dpy, configs[i], GLX_SAMPLES), 4);
      EXPECT_EQ(attrib(dpy, configs[i], GLX_SAMPLE_BUFFERS), 1);
    }
    XFree(configs);
  }
  const int too_many[] = {GLX_SAMPLES, 8, None};
  configs = glXChooseFBConfig(dpy, screen, too_many, &n);
  EXPECT_EQ(n, 0);
  if (configs) XFree(configs);
}

TEST_F(GlxConfigTest, InvalidConfigAttribute) {
  GLXFBConfig c = rgba8(true, true);
  int value = 0;
  EXPECT_EQ(glXGetFBConfigAttrib(dpy, c, 0x7777, &value), GLX_BAD_ATTRIBUTE);
}

TEST_F(GlxConfigTest, ChooseMatchesAndSorts) {
  const int attribs[] = {GLX_DOUBLEBUFFER, True, GLX_DEPTH_SIZE, 16, GLX_RED_SIZE, 1, None};
  int n = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy, screen, attribs, &n);
  ASSERT_GT(n, 0);
  for (int i = 0; i < n; ++i) {
    EXPECT_EQ(attrib(dpy, configs[i], GLX_DOUBLEBUFFER), True);
    EXPECT_GE(attrib(dpy, configs[i], GLX_DEPTH_SIZE), 16);
  }
  // Alpha is not asked for: the smaller buffer comes first.
  EXPECT_EQ(attrib(dpy, configs[0], GLX_ALPHA_SIZE), 0);
  XFree(configs);

  const int with_alpha[] = {GLX_ALPHA_SIZE, 1, None};
  configs = glXChooseFBConfig(dpy, screen, with_alpha, &n);
  ASSERT_GT(n, 0);
  EXPECT_EQ(attrib(dpy, configs[0], GLX_ALPHA_SIZE), 8);
  // Single-buffered before double-buffered, then the larger depth buffer.
  EXPECT_EQ(attrib(dpy, configs[0], GLX_DOUBLEBUFFER), False);
  EXPECT_EQ(attrib(dpy, configs[0], GLX_DEPTH_SIZE), 24);
  XFree(configs);
}

TEST_F(GlxConfigTest, ChooseByIdAndImpossibleRequests) {
  GLXFBConfig c = rgba8(false, false);
  const int by_id[] = {GLX_FBCONFIG_ID, attrib(dpy, c, GLX_FBCONFIG_ID), GLX_DOUBLEBUFFER, True, None};
  int n = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy, screen, by_id, &n);
  ASSERT_EQ(n, 1);
  EXPECT_EQ(configs[0], c);
  XFree(configs);
  EXPECT_EQ(choose({GLX_SAMPLES, 8}), nullptr);
  EXPECT_EQ(choose({GLX_ACCUM_RED_SIZE, 17}), nullptr);
  EXPECT_NE(choose({GLX_ACCUM_RED_SIZE, 16, GLX_ACCUM_ALPHA_SIZE, 1}), nullptr);  // 16-bit accumulation
  EXPECT_EQ(choose({GLX_RENDER_TYPE, GLX_COLOR_INDEX_BIT}), nullptr);
  EXPECT_EQ(choose({GLX_STENCIL_SIZE, 9}), nullptr);
  EXPECT_EQ(choose({0x7777, 1}), nullptr);
  take_errors();
  EXPECT_NE(choose({GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT | GLX_PIXMAP_BIT}), nullptr);
}

TEST_F(GlxConfigTest, ChooseVisual) {
  int double_depth[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 1, GLX_DEPTH_SIZE, 1, None};
  XVisualInfo* vi = glXChooseVisual(dpy, screen, double_depth);
  ASSERT_NE(vi, nullptr);
  int value = 0;
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_DOUBLEBUFFER, &value), 0);
  EXPECT_EQ(value, True);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_DEPTH_SIZE, &value), 0);
  EXPECT_EQ(value, 24);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_RGBA, &value), 0);
  EXPECT_EQ(value, True);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_USE_GL, &value), 0);
  EXPECT_EQ(value, True);
  XFree(vi);

  // Without GLX_DOUBLEBUFFER only single-buffered visuals; a zero size prefers the smallest.
  int plain[] = {GLX_RGBA, None};
  vi = glXChooseVisual(dpy, screen, plain);
  ASSERT_NE(vi, nullptr);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_DOUBLEBUFFER, &value), 0);
  EXPECT_EQ(value, False);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_DEPTH_SIZE, &value), 0);
  EXPECT_EQ(value, 0);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_ALPHA_SIZE, &value), 0);
  EXPECT_EQ(value, 0);
  XFree(vi);

  // GLX_SAMPLE_BUFFERS and GLX_SAMPLES are minimums: the 4x double-buffered visuals; none above 4
  // samples, and none single-buffered. Without them the single-sampled visual comes first.
  int multisampled[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_SAMPLE_BUFFERS, 1, GLX_SAMPLES, 2, GLX_DEPTH_SIZE, 1, None};
  vi = glXChooseVisual(dpy, screen, multisampled);
  ASSERT_NE(vi, nullptr);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_SAMPLE_BUFFERS, &value), 0);
  EXPECT_EQ(value, 1);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_SAMPLES, &value), 0);
  EXPECT_EQ(value, 4);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_DOUBLEBUFFER, &value), 0);
  EXPECT_EQ(value, True);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_DEPTH_SIZE, &value), 0);
  EXPECT_EQ(value, 24);
  XFree(vi);
  int too_many_samples[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_SAMPLES, 8, None};
  EXPECT_EQ(glXChooseVisual(dpy, screen, too_many_samples), nullptr);
  int single_buffered_multisampled[] = {GLX_RGBA, GLX_SAMPLE_BUFFERS, 1, None};
  EXPECT_EQ(glXChooseVisual(dpy, screen, single_buffered_multisampled), nullptr);
  vi = glXChooseVisual(dpy, screen, double_depth);
  ASSERT_NE(vi, nullptr);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_SAMPLES, &value), 0);
  EXPECT_EQ(value, 0);
  XFree(vi);

  int index[] = {GLX_BUFFER_SIZE, 8, None};  // colour index: none
  EXPECT_EQ(glXChooseVisual(dpy, screen, index), nullptr);
  int stereo[] = {GLX_RGBA, GLX_STEREO, None};
  EXPECT_EQ(glXChooseVisual(dpy, screen, stereo), nullptr);
}

TEST_F(GlxConfigTest, GetConfigOfAVisualWithoutGL) {
  XVisualInfo tmpl{};
  tmpl.screen = screen;
  tmpl.c_class = DirectColor;
  int n = 0;
  XVisualInfo* vi = XGetVisualInfo(dpy, VisualScreenMask | VisualClassMask, &tmpl, &n);
  if (!vi) GTEST_SKIP() << "no DirectColor visual";
  int value = 1;
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_USE_GL, &value), 0);
  EXPECT_EQ(value, False);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_RED_SIZE, &value), GLX_BAD_VISUAL);
  XFree(vi);
}

}  // namespace
}  // namespace pineda_test
