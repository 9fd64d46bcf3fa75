// Pixel buffer objects (GL 2.1 4.3.5, GL_ARB_pixel_buffer_object): the bindings, and every
// call that reads or writes client pixels taking an offset into the bound buffer, with its
// range and mapping checks.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstring>
#include <numeric>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

const void* offset(size_t bytes) { return reinterpret_cast<const void*>(bytes); }
void* out_offset(size_t bytes) { return reinterpret_cast<void*>(bytes); }

class PixelBufferObjectTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    clear_to(0, 0, 0, 0);
    glGenBuffers(2, buffers_);
  }
  void TearDown() override {
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glDeleteBuffers(2, buffers_);
    GlTest::TearDown();
  }
  GLint get_int(GLenum pname) {
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
  }
  // Binds the unpack buffer with `data` in it.
  void unpack_from(const std::vector<uint8_t>& data) {
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffers_[0]);
    glBufferData(GL_PIXEL_UNPACK_BUFFER, GLsizeiptr(data.size()), data.data(), GL_STREAM_DRAW);
  }
  // Binds the pack buffer with `size` bytes of `fill`.
  void pack_into(size_t size, uint8_t fill) {
    const std::vector<uint8_t> data(size, fill);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, buffers_[1]);
    glBufferData(GL_PIXEL_PACK_BUFFER, GLsizeiptr(size), data.data(), GL_STREAM_READ);
  }
  std::vector<uint8_t> pack_contents(size_t size) {
    std::vector<uint8_t> out(size);
    glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 0, GLsizeiptr(size), out.data());
    return out;
  }
  std::vector<uint8_t> texture_rgba(GLenum target, int texels) {
    std::vector<uint8_t> out(size_t(texels) * 4, 0xEE);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    return out;
  }
  GLuint buffers_[2] = {0, 0};
};

std::vector<uint8_t> counting(size_t n, int start = 1) {
  std::vector<uint8_t> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = uint8_t(start + i);
  return v;
}

TEST_F(PixelBufferObjectTest, BindingsAreQueriedAndKeptWithThePixelStoreGroup) {
  EXPECT_EQ(get_int(GL_PIXEL_PACK_BUFFER_BINDING), 0);
  EXPECT_EQ(get_int(GL_PIXEL_UNPACK_BUFFER_BINDING), 0);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffers_[1]);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffers_[0]);
  EXPECT_EQ(get_int(GL_PIXEL_PACK_BUFFER_BINDING), GLint(buffers_[1]));
  EXPECT_EQ(get_int(GL_PIXEL_UNPACK_BUFFER_BINDING), GLint(buffers_[0]));
  EXPECT_EQ(get_int(GL_ARRAY_BUFFER_BINDING), 0);  // a separate binding point

  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glPopClientAttrib();
  EXPECT_EQ(get_int(GL_PIXEL_UNPACK_BUFFER_BINDING), 0);  // not in the vertex array group

  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffers_[0]);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glPopClientAttrib();
  EXPECT_EQ(get_int(GL_PIXEL_PACK_BUFFER_BINDING), GLint(buffers_[1]));
  EXPECT_EQ(get_int(GL_PIXEL_UNPACK_BUFFER_BINDING), GLint(buffers_[0]));

  glBufferData(GL_PIXEL_UNPACK_BUFFER, 8, nullptr, GL_STREAM_DRAW);
  GLint size = 0;
  glGetBufferParameteriv(GL_PIXEL_UNPACK_BUFFER, GL_BUFFER_SIZE, &size);
  EXPECT_EQ(size, 8);
  glDeleteBuffers(1, &buffers_[0]);
  EXPECT_EQ(get_int(GL_PIXEL_UNPACK_BUFFER_BINDING), 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const char* extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(std::strstr(extensions, "GL_ARB_pixel_buffer_object "), nullptr);
  EXPECT_NE(std::strstr(extensions, "GL_EXT_pixel_buffer_object "), nullptr);
}

TEST_F(PixelBufferObjectTest, TexImageReadsAtTheOffsetUnderThePixelStore) {
  unpack_from(counting(64));
  glBindTexture(GL_TEXTURE_2D, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 3);  // rows of 12 bytes
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, offset(4));
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // Buffer bytes are 1 + index: pixels at 4..11 and 16..23.
  const std::vector<uint8_t> expected = {5, 6, 7, 8, 9, 10, 11, 12, 17, 18, 19, 20, 21, 22, 23, 24};
  EXPECT_EQ(texture_rgba(GL_TEXTURE_2D, 4), expected);

  // Offset 0 is a null pointer, and a valid one with a buffer bound.
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(texture_rgba(GL_TEXTURE_2D, 4)[12], 1);
}

TEST_F(PixelBufferObjectTest, ReadsPastTheEndOrFromAMappedBufferFailAndChangeNothing) {
  unpack_from(counting(16));
  glBindTexture(GL_TEXTURE_2D, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, offset(0));  // exactly 16 bytes
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const std::vector<uint8_t> before = texture_rgba(GL_TEXTURE_2D, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, offset(1));  // one byte too many
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, offset(9));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, offset(SIZE_MAX - 2));  // wraps around
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);  // skips count towards the range
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, offset(0));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  EXPECT_EQ(texture_rgba(GL_TEXTURE_2D, 4), before);

  ASSERT_NE(glMapBuffer(GL_PIXEL_UNPACK_BUFFER, GL_READ_ONLY), nullptr);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, offset(0));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glWindowPos2i(0, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, offset(0));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 0, 0, 0}));
  glUnmapBuffer(GL_PIXEL_UNPACK_BUFFER);
  EXPECT_EQ(texture_rgba(GL_TEXTURE_2D, 4), before);
}

TEST_F(PixelBufferObjectTest, TexImage3DRangeCountsImageHeightAndSkipImages) {
  unpack_from(counting(4 * 2 * 2 * 2 + 4 * 2));  // two 2x2 slices, plus room for one skipped row
  glBindTexture(GL_TEXTURE_3D, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, offset(8));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const std::vector<uint8_t> tex = texture_rgba(GL_TEXTURE_3D, 8);
  EXPECT_EQ(tex[0], 9);
  EXPECT_EQ(tex[31], 40);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 3);  // slices 3 rows apart: 8 bytes more than the buffer holds
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, offset(8));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, offset(0));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  EXPECT_EQ(texture_rgba(GL_TEXTURE_3D, 8), tex);
}

TEST_F(PixelBufferObjectTest, ReadPixelsWritesIntoThePackBuffer) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(1, 0, 1, 1);
  clear_to(1.f, 0.f, 0.f, 1.f);
  glDisable(GL_SCISSOR_TEST);
  pack_into(16, 0xAB);
  glReadPixels(0, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, out_offset(4));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const std::vector<uint8_t> expected = {0xAB, 0xAB, 0xAB, 0xAB, 0, 0, 0, 0, 255, 0, 0, 255, 0xAB, 0xAB, 0xAB, 0xAB};
  EXPECT_EQ(pack_contents(16), expected);

  glReadPixels(0, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, out_offset(9));  // 1 byte past the end
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glReadPixels(0, 0, 2, 3, GL_RGBA, GL_UNSIGNED_BYTE, out_offset(0));  // 24 bytes
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(pack_contents(16), expected);
  ASSERT_NE(glMapBuffer(GL_PIXEL_PACK_BUFFER, GL_READ_ONLY), nullptr);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out_offset(0));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
  EXPECT_EQ(pack_contents(16), expected);

  // Another format through the pack store: one float of red at offset 0.
  glReadPixels(1, 0, 1, 1, GL_RED, GL_FLOAT, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  float red = 0;
  glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 0, 4, &red);
  EXPECT_EQ(red, 1.f);
}

TEST_F(PixelBufferObjectTest, GetTexImageWritesIntoThePackBuffer) {
  const std::vector<uint8_t> texels = counting(8, 100);
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  pack_into(12, 0);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out_offset(4));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const std::vector<uint8_t> expected = {0, 0, 0, 0, 100, 101, 102, 103, 104, 105, 106, 107};
  EXPECT_EQ(pack_contents(12), expected);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out_offset(5));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(pack_contents(12), expected);
}

TEST_F(PixelBufferObjectTest, DrawPixelsAndBitmapReadTheUnpackBuffer) {
  std::vector<uint8_t> data(16, 0);
  const uint8_t rgba[8] = {10, 20, 30, 255, 40, 50, 60, 255};
  std::memcpy(data.data() + 4, rgba, 8);
  data[12] = 0xA0;  // bitmap row: bits 1 0 1
  unpack_from(data);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glWindowPos2i(3, 3);
  glDrawPixels(2, 1, GL_RGBA, GL_UNSIGNED_BYTE, offset(4));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(pixel(3, 3), (Rgba{10, 20, 30, 255}));
  EXPECT_EQ(pixel(4, 3), (Rgba{40, 50, 60, 255}));
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, offset(4));  // 16 bytes from 4
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(pixel(3, 4), (Rgba{0, 0, 0, 0}));

  glColor4f(0.f, 1.f, 0.f, 1.f);
  glWindowPos2i(10, 10);
  glBitmap(3, 1, 0, 0, 5, 0, reinterpret_cast<const GLubyte*>(offset(12)));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(pixel(10, 10), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(pixel(11, 10), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(pixel(12, 10), (Rgba{0, 255, 0, 255}));
  GLint pos[4];
  glGetIntegerv(GL_CURRENT_RASTER_POSITION, pos);
  EXPECT_EQ(pos[0], 15);
  glBitmap(3, 2, 0, 0, 5, 0, reinterpret_cast<const GLubyte*>(offset(15)));  // needs bytes 15 and 16
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glGetIntegerv(GL_CURRENT_RASTER_POSITION, pos);
  EXPECT_EQ(pos[0], 15);  // nothing happened, the raster position included
}

TEST_F(PixelBufferObjectTest, PolygonStippleAndPixelMapsGoThroughBothBuffers) {
  std::vector<uint8_t> stipple(4 + 128);
  for (size_t i = 0; i < 128; ++i) stipple[4 + i] = uint8_t(i * 7 + 1);
  unpack_from(stipple);
  glPolygonStipple(reinterpret_cast<const GLubyte*>(offset(4)));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glPolygonStipple(reinterpret_cast<const GLubyte*>(offset(5)));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  pack_into(132, 0);
  glGetPolygonStipple(reinterpret_cast<GLubyte*>(out_offset(4)));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  std::vector<uint8_t> got = pack_contents(132);
  EXPECT_EQ(std::vector<uint8_t>(got.begin() + 4, got.end()), std::vector<uint8_t>(stipple.begin() + 4, stipple.end()));
  glGetPolygonStipple(reinterpret_cast<GLubyte*>(out_offset(8)));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));

  const GLushort map[4] = {0, 65535, 21845, 43690};
  std::vector<uint8_t> bytes(2 + sizeof map);
  std::memcpy(bytes.data() + 2, map, sizeof map);
  unpack_from(bytes);
  glPixelMapusv(GL_PIXEL_MAP_I_TO_R, 4, static_cast<const GLushort*>(offset(2)));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glPixelMapusv(GL_PIXEL_MAP_I_TO_G, 4, static_cast<const GLushort*>(offset(4)));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(get_int(GL_PIXEL_MAP_I_TO_G_SIZE), 1);
  EXPECT_EQ(get_int(GL_PIXEL_MAP_I_TO_R_SIZE), 4);
  pack_into(20, 0);
  glGetPixelMapfv(GL_PIXEL_MAP_I_TO_R, static_cast<GLfloat*>(out_offset(4)));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  float values[4];
  glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 4, 16, values);
  EXPECT_EQ(values[0], 0.f);
  EXPECT_EQ(values[1], 1.f);
  EXPECT_FLOAT_EQ(values[2], 1.f / 3.f);
  glGetPixelMapfv(GL_PIXEL_MAP_I_TO_R, static_cast<GLfloat*>(out_offset(8)));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(PixelBufferObjectTest, DisplayListsReadTheBufferWhenCompiled) {
  std::vector<uint8_t> data = {10, 20, 30, 255, 70, 80, 90, 255};
  unpack_from(data);
  glBindTexture(GL_TEXTURE_2D, 1);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, offset(0));
  glWindowPos2i(2, 2);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, offset(4));
  glEndList();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // New contents, and no buffer bound when the list runs: the list keeps what it read.
  data = {1, 1, 1, 1, 2, 2, 2, 2};
  glBufferSubData(GL_PIXEL_UNPACK_BUFFER, 0, 8, data.data());
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glCallList(list);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(texture_rgba(GL_TEXTURE_2D, 1), (std::vector<uint8_t>{10, 20, 30, 255}));
  EXPECT_EQ(pixel(2, 2), (Rgba{70, 80, 90, 255}));
  // With the buffer bound again at execution, the list still uses its own copy.
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffers_[0]);
  clear_to(0, 0, 0, 0);
  glCallList(list);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(pixel(2, 2), (Rgba{70, 80, 90, 255}));

  // A range error at compile time is reported then.
  glNewList(list, GL_COMPILE);
  glDrawPixels(2, 1, GL_RGBA, GL_UNSIGNED_BYTE, offset(4));
  glEndList();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDeleteLists(list, 1);
}

}  // namespace
}  // namespace pineda::test
