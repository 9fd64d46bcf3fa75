// glGetTexImage as GL_UNSIGNED_BYTE RGBA, BGRA, RGB or BGR moves the stored bytes
// (color_byte_reads.h): it must give what the per-texel path gives, which GL_FLOAT reads show
// (a stored byte k reads as k / 255, so the byte read is round(255 * float)).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class GetTexImageBytesTest : public GlTest {};

struct PackLayout {
  int alignment, row_length, skip_pixels, skip_rows, image_height, skip_images;
};

// Where pixel (x, y, z) of a width x height level lands in client memory under `pack`, for
// `bpp` bytes per pixel (GL 2.1 4.3.2, as for glReadPixels).
size_t packed_offset(const PackLayout& pack, int width, int height, int bpp, int x, int y, int z) {
  const size_t row_pixels = size_t(pack.row_length > 0 ? pack.row_length : width);
  const size_t row_stride = (row_pixels * bpp + pack.alignment - 1) / pack.alignment * pack.alignment;
  const size_t image_stride = row_stride * size_t(pack.image_height > 0 ? pack.image_height : height);
  return image_stride * size_t(pack.skip_images + z) + row_stride * size_t(pack.skip_rows + y) +
         size_t(pack.skip_pixels + x) * bpp;
}

void set_pack(const PackLayout& p) {
  glPixelStorei(GL_PACK_ALIGNMENT, p.alignment);
  glPixelStorei(GL_PACK_ROW_LENGTH, p.row_length);
  glPixelStorei(GL_PACK_SKIP_PIXELS, p.skip_pixels);
  glPixelStorei(GL_PACK_SKIP_ROWS, p.skip_rows);
  glPixelStorei(GL_PACK_IMAGE_HEIGHT, p.image_height);
  glPixelStorei(GL_PACK_SKIP_IMAGES, p.skip_images);
}

// Every internal format family (RGBA4 and R3_G3_B2 keep fewer bits; luminance and intensity
// read into R alone), every byte format, several pack layouts, 2D and 3D: every byte of the
// client memory, the bytes between pixels left as they were.
TEST_F(GetTexImageBytesTest, BytesAreTheRoundedFloatReads) {
  const int w = 5, h = 3, d = 2;
  std::vector<uint8_t> image(size_t(w) * h * d * 4);
  for (size_t i = 0; i < image.size(); ++i) image[i] = uint8_t(i * 89 + (i >> 3) * 5);
  const GLenum internals[] = {GL_RGBA8,  GL_RGB8,           GL_ALPHA8,    GL_LUMINANCE8, GL_LUMINANCE8_ALPHA8,
                              GL_INTENSITY8, GL_RGBA4,       GL_R3_G3_B2};
  struct Format {
    GLenum format;
    int bpp;
    int from[4];  // the client byte of each of R, G, B, A; -1: not written
  };
  const Format formats[] = {{GL_RGBA, 4, {0, 1, 2, 3}},
                            {GL_BGRA, 4, {2, 1, 0, 3}},
                            {GL_RGB, 3, {0, 1, 2, -1}},
                            {GL_BGR, 3, {2, 1, 0, -1}}};
  const PackLayout layouts[] = {{4, 0, 0, 0, 0, 0}, {1, 0, 0, 0, 0, 0}, {8, 7, 1, 2, 0, 0}, {2, 6, 0, 1, 4, 1}};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (const GLenum target : {GL_TEXTURE_2D, GL_TEXTURE_3D}) {
    const int depth = target == GL_TEXTURE_3D ? d : 1;
    for (const GLenum internal : internals) {
      glBindTexture(target, target == GL_TEXTURE_3D ? 2 : 1);
      if (target == GL_TEXTURE_3D)
        glTexImage3D(target, 0, GLint(internal), w, h, d, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
      else
        glTexImage2D(target, 0, GLint(internal), w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
      std::vector<float> floats(size_t(w) * h * depth * 4);
      set_pack({1, 0, 0, 0, 0, 0});
      glGetTexImage(target, 0, GL_RGBA, GL_FLOAT, floats.data());
      ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
      for (const Format& f : formats)
        for (const PackLayout& layout : layouts) {
          PackLayout placed = layout;  // image height and skipped images apply to 3D only
          if (target != GL_TEXTURE_3D) placed.image_height = placed.skip_images = 0;
          const size_t size = packed_offset(placed, w, h, f.bpp, 0, 0, depth) + 64;
          std::vector<uint8_t> got(size, 0xee), want(size, 0xee);
          for (int z = 0; z < depth; ++z)
            for (int y = 0; y < h; ++y)
              for (int x = 0; x < w; ++x) {
                const float* rgba = &floats[((size_t(z) * h + y) * w + x) * 4];
                uint8_t* out = &want[packed_offset(placed, w, h, f.bpp, x, y, z)];
                for (int c = 0; c < 4; ++c)
                  if (f.from[c] >= 0) out[f.from[c]] = uint8_t(std::lround(rgba[c] * 255.0));
              }
          set_pack(layout);
          glGetTexImage(target, 0, f.format, GL_UNSIGNED_BYTE, got.data());
          ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
          EXPECT_EQ(got, want) << std::hex << "target " << target << " internal " << internal << " format "
                               << f.format << std::dec << " alignment " << layout.alignment;
        }
    }
  }
  set_pack({4, 0, 0, 0, 0, 0});
}

// The float reads the test above relies on, pinned by hand: luminance in R only, intensity with
// alpha 1, RGB with alpha 1 (GL 2.1 table 6.1).
TEST_F(GetTexImageBytesTest, BaseFormatsReadAsTheSpecsTableSays) {
  const uint8_t texel[4] = {10, 20, 30, 40};
  struct Case {
    GLenum internal;
    uint8_t rgba[4];
  };
  const Case cases[] = {{GL_RGBA8, {10, 20, 30, 40}},  {GL_RGB8, {10, 20, 30, 255}},
                        {GL_ALPHA8, {0, 0, 0, 40}},    {GL_LUMINANCE8, {10, 0, 0, 255}},
                        {GL_LUMINANCE8_ALPHA8, {10, 0, 0, 40}}, {GL_INTENSITY8, {10, 0, 0, 255}}};
  glBindTexture(GL_TEXTURE_2D, 1);
  for (const Case& c : cases) {
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(c.internal), 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    uint8_t got[4] = {0xee, 0xee, 0xee, 0xee};
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, got);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(got[k], c.rgba[k]) << std::hex << c.internal << " component " << k;
    float f[4] = {};
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, f);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(f[k], c.rgba[k] / 255.f) << std::hex << c.internal << " component " << k;
  }
}

}  // namespace
}  // namespace pineda::test
