// glGetString.
#include <cstring>
#include <string>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

using StringTest = GlTest;

std::string get_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "<null>";
}

TEST_F(StringTest, VersionStartsWithTwoOnePineda) {
  const std::string version = get_string(GL_VERSION);
  EXPECT_EQ(version.rfind("2.1 Pineda", 0), 0u) << version;
}

TEST_F(StringTest, RendererAndVendorNamePineda) {
  EXPECT_NE(get_string(GL_RENDERER).find("Pineda"), std::string::npos) << get_string(GL_RENDERER);
  EXPECT_NE(get_string(GL_VENDOR).find("Pineda"), std::string::npos) << get_string(GL_VENDOR);
}

TEST_F(StringTest, ExtensionsAreSpaceSeparatedGLNames) {
  const std::string ext = get_string(GL_EXTENSIONS);
  ASSERT_NE(ext, "<null>");
  size_t start = 0;
  while (start < ext.size()) {
    size_t end = ext.find(' ', start);
    if (end == std::string::npos) end = ext.size();
    const std::string name = ext.substr(start, end - start);
    if (!name.empty()) {
      EXPECT_EQ(name.rfind("GL_", 0), 0u) << name;
    }
    start = end + 1;
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(StringTest, StringsStayValid) {
  const GLubyte* a = glGetString(GL_VERSION);
  const GLubyte* b = glGetString(GL_VERSION);
  ASSERT_NE(a, nullptr);
  EXPECT_STREQ(reinterpret_cast<const char*>(a), reinterpret_cast<const char*>(b));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// Every extension whose behaviour the e2e tests check is advertised.
TEST_F(StringTest, AdvertisesTheImplementedExtensions) {
  const std::string ext = " " + get_string(GL_EXTENSIONS) + " ";
  for (const char* name : {"GL_EXT_blend_color", "GL_EXT_blend_minmax", "GL_EXT_blend_subtract",
                           "GL_EXT_blend_func_separate", "GL_EXT_blend_equation_separate", "GL_EXT_texture_edge_clamp", "GL_EXT_texture_env_add",
                           "GL_ARB_texture_border_clamp", "GL_ARB_texture_mirrored_repeat",
                           "GL_ARB_multitexture", "GL_ARB_texture_env_add", "GL_ARB_texture_env_combine",
                           "GL_ARB_texture_env_crossbar", "GL_ARB_texture_env_dot3", "GL_EXT_bgra",
                           "GL_SGIS_generate_mipmap", "GL_SGIS_texture_lod", "GL_EXT_texture_lod_bias",
                           "GL_EXT_texture3D", "GL_ARB_texture_cube_map", "GL_EXT_texture_cube_map"})
    EXPECT_NE(ext.find(std::string(" ") + name + " "), std::string::npos) << name;
}

}  // namespace
}  // namespace pineda::test
