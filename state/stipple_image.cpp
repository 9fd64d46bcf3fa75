#include "state/stipple_image.h"

#include "state/context.h"

namespace pineda {
namespace {

// GL 1.5 section 3.6.4 for bitmaps: rows of row_length (or 32) bits, padded to the alignment
// in bytes; pixel i of a row is bit skip_pixels + i, most significant bit first unless
// LSB_FIRST.
struct BitLayout {
  size_t row_bytes = 0;
  size_t skip_bits = 0;
  bool lsb_first = false;

  explicit BitLayout(const PixelStore& s) {
    const size_t row_bits = s.row_length > 0 ? size_t(s.row_length) : 32;
    const size_t align = s.alignment > 0 ? size_t(s.alignment) : 1;
    row_bytes = (row_bits + 7) / 8;
    row_bytes = (row_bytes + align - 1) / align * align;
    skip_bits = size_t(s.skip_pixels > 0 ? s.skip_pixels : 0);
    base = size_t(s.skip_rows > 0 ? s.skip_rows : 0) * row_bytes;
    lsb_first = s.lsb_first != GL_FALSE;
  }
  size_t byte(int row, int x) const { return base + size_t(row) * row_bytes + (skip_bits + x) / 8; }
  unsigned bit(int x) const {
    const unsigned b = static_cast<unsigned>((skip_bits + x) % 8);
    return lsb_first ? b : 7 - b;
  }

 private:
  size_t base = 0;
};

}  // namespace

StippleRows unpack_stipple(const PixelStore& unpack, const GLubyte* bitmap) {
  const BitLayout l(unpack);
  StippleRows rows{};
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      if ((bitmap[l.byte(y, x)] >> l.bit(x)) & 1u) rows[y] |= 1u << x;
  return rows;
}

void pack_stipple(const PixelStore& pack, const StippleRows& rows, GLubyte* bitmap) {
  const BitLayout l(pack);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      GLubyte& b = bitmap[l.byte(y, x)];
      const GLubyte m = static_cast<GLubyte>(1u << l.bit(x));
      b = ((rows[y] >> x) & 1u) ? (b | m) : (b & ~m);
    }
}

}  // namespace pineda
