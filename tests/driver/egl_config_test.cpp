// eglGetConfigs, eglChooseConfig matching and sorting, eglGetConfigAttrib.
#include <vector>

#include "egl_fixture.h"

namespace {

using pineda_test::EglTest;

struct Sizes {
  EGLint depth, stencil;
  bool operator==(const Sizes&) const = default;
};

class EglConfig : public EglTest {
 protected:
  EGLint attrib(EGLConfig c, EGLint name) {
    EGLint value = -12345;
    EXPECT_TRUE(eglGetConfigAttrib(dpy, c, name, &value)) << std::hex << name;
    return value;
  }
  std::vector<Sizes> choose(const std::vector<EGLint>& attribs) {
    EGLConfig configs[32];
    EGLint n = 0;
    EXPECT_TRUE(eglChooseConfig(dpy, attribs.data(), configs, 32, &n));
    std::vector<Sizes> out;
    for (EGLint i = 0; i < n; ++i)
      out.push_back({attrib(configs[i], EGL_DEPTH_SIZE), attrib(configs[i], EGL_STENCIL_SIZE)});
    return out;
  }
};

TEST_F(EglConfig, GetConfigsCountsAndCopies) {
  EGLint n = 0;
  ASSERT_TRUE(eglGetConfigs(dpy, nullptr, 0, &n));
  EXPECT_EQ(n, 9);  // 7 single-sampled, 2 multisampled
  std::vector<EGLConfig> configs(n);
  EGLint got = 0;
  ASSERT_TRUE(eglGetConfigs(dpy, configs.data(), 3, &got));
  EXPECT_EQ(got, 3);
  ASSERT_TRUE(eglGetConfigs(dpy, configs.data(), n, &got));
  EXPECT_EQ(got, n);
  EXPECT_FALSE(eglGetConfigs(dpy, configs.data(), n, nullptr));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

TEST_F(EglConfig, EveryConfigIsRgba8888PbufferOpenGL) {
  EGLint n = 0;
  ASSERT_TRUE(eglGetConfigs(dpy, nullptr, 0, &n));
  std::vector<EGLConfig> configs(n);
  ASSERT_TRUE(eglGetConfigs(dpy, configs.data(), n, &n));
  for (EGLConfig c : configs) {
    EXPECT_EQ(attrib(c, EGL_RED_SIZE), 8);
    EXPECT_EQ(attrib(c, EGL_GREEN_SIZE), 8);
    EXPECT_EQ(attrib(c, EGL_BLUE_SIZE), 8);
    EXPECT_EQ(attrib(c, EGL_ALPHA_SIZE), 8);
    EXPECT_EQ(attrib(c, EGL_BUFFER_SIZE), 32);
    EXPECT_EQ(attrib(c, EGL_SURFACE_TYPE), EGL_PBUFFER_BIT);
    const EGLint apis = EGL_OPENGL_BIT | EGL_OPENGL_ES_BIT | (offers_gles2() ? EGL_OPENGL_ES2_BIT : 0);
    EXPECT_EQ(attrib(c, EGL_RENDERABLE_TYPE), apis);
    EXPECT_EQ(attrib(c, EGL_CONFORMANT), EGL_OPENGL_BIT | EGL_OPENGL_ES_BIT);
    EXPECT_EQ(attrib(c, EGL_COLOR_BUFFER_TYPE), EGL_RGB_BUFFER);
    EXPECT_EQ(attrib(c, EGL_CONFIG_CAVEAT), EGL_NONE);
    const EGLint samples = attrib(c, EGL_SAMPLES);
    EXPECT_TRUE(samples == 0 || samples == 4) << samples;
    EXPECT_EQ(attrib(c, EGL_SAMPLE_BUFFERS), samples ? 1 : 0);
    EXPECT_EQ(attrib(c, EGL_NATIVE_VISUAL_ID), 0);
    EXPECT_EQ(attrib(c, EGL_TRANSPARENT_TYPE), EGL_NONE);
    EXPECT_EQ(attrib(c, EGL_MAX_PBUFFER_WIDTH), 8192);
    EXPECT_EQ(attrib(c, EGL_MAX_PBUFFER_HEIGHT), 8192);
    EXPECT_GT(attrib(c, EGL_CONFIG_ID), 0);
  }
}

TEST_F(EglConfig, DefaultsAskForWindowsAndES) {
  // EGL_SURFACE_TYPE defaults to EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE to EGL_OPENGL_ES_BIT.
  EXPECT_TRUE(choose({EGL_NONE}).empty());
  EGLint n = -1;
  EXPECT_TRUE(eglChooseConfig(dpy, nullptr, nullptr, 0, &n));
  EXPECT_EQ(n, 0);
}

TEST_F(EglConfig, SortsBySmallerDepthThenStencil) {
  auto all = choose({EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                     EGL_NONE});
  // EGL 1.5 3.4.1.2: fewer samples before the depth size, so the 4x configs come last.
  std::vector<Sizes> expected = {{0, 0}, {0, 8}, {16, 0}, {24, 0}, {24, 8}, {32, 0}, {32, 8}, {0, 0}, {24, 8}};
  EXPECT_EQ(all, expected);
}

TEST_F(EglConfig, MatchesAtLeastSizes) {
  auto configs = choose({EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                         EGL_RED_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_NONE});
  std::vector<Sizes> expected = {{24, 8}, {32, 8}, {24, 8}};
  EXPECT_EQ(configs, expected);
  EXPECT_TRUE(choose({EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                      EGL_RED_SIZE, 9, EGL_NONE})
                  .empty());
  EXPECT_EQ(choose({EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SAMPLE_BUFFERS, 1,
                    EGL_SAMPLES, 2, EGL_NONE}),
            (std::vector<Sizes>{{0, 0}, {24, 8}}));
  EXPECT_TRUE(choose({EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                      EGL_SAMPLES, 8, EGL_NONE})
                  .empty());
}

TEST_F(EglConfig, DontCareIgnoresAnAttribute) {
  auto configs = choose({EGL_SURFACE_TYPE, EGL_DONT_CARE, EGL_RENDERABLE_TYPE, EGL_DONT_CARE,
                         EGL_DEPTH_SIZE, 32, EGL_NONE});
  std::vector<Sizes> expected = {{32, 0}, {32, 8}};
  EXPECT_EQ(configs, expected);
}

TEST_F(EglConfig, ES2OnlyWhenOfferedAndNoWindows) {
  EXPECT_EQ(choose({EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT,
                    EGL_NONE})
                .size(),
            offers_gles2() ? 9u : 0u);
  EXPECT_EQ(choose({EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT,
                    EGL_NONE})
                .size(),
            9u);
  EXPECT_TRUE(choose({EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                      EGL_NONE})
                  .empty());
}

TEST_F(EglConfig, ConfigIdOverridesEverythingElse) {
  EGLConfig c = config(16, 0);
  EGLint id = attrib(c, EGL_CONFIG_ID);
  const EGLint attribs[] = {EGL_CONFIG_ID, id, EGL_SURFACE_TYPE, EGL_WINDOW_BIT,
                            EGL_RED_SIZE, 100, EGL_NONE};
  EGLConfig out = nullptr;
  EGLint n = 0;
  ASSERT_TRUE(eglChooseConfig(dpy, attribs, &out, 1, &n));
  ASSERT_EQ(n, 1);
  EXPECT_EQ(out, c);
}

TEST_F(EglConfig, UnknownAttributeIsBadAttribute) {
  const EGLint attribs[] = {0x7777, 1, EGL_NONE};
  EGLint n = 0;
  EXPECT_FALSE(eglChooseConfig(dpy, attribs, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_FALSE(eglChooseConfig(dpy, nullptr, nullptr, 0, nullptr));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

TEST_F(EglConfig, GetConfigAttribErrors) {
  EGLConfig c = config(24, 8);
  EGLint value = 0;
  EXPECT_FALSE(eglGetConfigAttrib(dpy, c, 0x7777, &value));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  int junk = 0;
  EXPECT_FALSE(eglGetConfigAttrib(dpy, reinterpret_cast<EGLConfig>(&junk), EGL_RED_SIZE, &value));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);
  EXPECT_FALSE(eglGetConfigAttrib(dpy, nullptr, EGL_RED_SIZE, &value));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);
  EXPECT_TRUE(eglGetConfigAttrib(dpy, c, EGL_DEPTH_SIZE, &value));
  EXPECT_EQ(value, 24);
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
}

}  // namespace
