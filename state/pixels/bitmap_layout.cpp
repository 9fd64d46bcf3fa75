#include "state/pixels/bitmap_layout.h"

#include <algorithm>

#include "state/context.h"

namespace pineda {

BitmapLayout::BitmapLayout(const PixelStore& store, int width) : width_(std::max(width, 0)), lsb_first_(store.lsb_first) {
  const size_t row_bits = store.row_length > 0 ? size_t(store.row_length) : size_t(width_);
  const size_t align = size_t(store.alignment);
  row_stride_ = (row_bits + 8 * align - 1) / (8 * align) * align;
  first_row_ = size_t(std::max(store.skip_rows, 0)) * row_stride_;
  skip_bits_ = std::max(store.skip_pixels, 0);
}

size_t BitmapLayout::byte_of(int i, int64_t j) const {
  return first_row_ + row_stride_ * size_t(j) + (size_t(skip_bits_) + size_t(i)) / 8;
}

int BitmapLayout::shift_of(int i) const {
  const int bit = int((size_t(skip_bits_) + size_t(i)) % 8);
  return lsb_first_ ? bit : 7 - bit;
}

bool BitmapLayout::bit(const uint8_t* data, int i, int64_t j) const { return (data[byte_of(i, j)] >> shift_of(i)) & 1; }

void BitmapLayout::set_bit(uint8_t* data, int i, int64_t j, bool value) const {
  uint8_t& byte = data[byte_of(i, j)];
  const uint8_t mask = uint8_t(1u << shift_of(i));
  byte = value ? uint8_t(byte | mask) : uint8_t(byte & ~mask);
}

size_t BitmapLayout::size(int height) const {
  if (height <= 0 || width_ == 0) return 0;
  return first_row_ + row_stride_ * size_t(height - 1) + (size_t(skip_bits_) + size_t(width_) + 7) / 8;
}

std::vector<uint8_t> tight_bitmap_copy(const PixelStore& store, int width, int height, const void* data) {
  PixelStore tight;
  tight.alignment = 1;
  const BitmapLayout from(store, width), to(tight, width);
  std::vector<uint8_t> out(to.size(height), 0);
  const auto* bytes = static_cast<const uint8_t*>(data);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) to.set_bit(out.data(), i, j, from.bit(bytes, i, j));
  return out;
}

}  // namespace pineda
