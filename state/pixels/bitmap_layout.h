// GL 1.5 spec 3.6.4 "Unpacking of bitmaps" and 4.3.2 (packing): one bit per pixel, rows
// padded to the alignment, SKIP_PIXELS counted in bits, most significant bit first unless
// LSB_FIRST.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pineda {

struct PixelStore;

class BitmapLayout {
 public:
  BitmapLayout(const PixelStore& store, int width);
  bool bit(const uint8_t* data, int i, int64_t j) const;
  // Sets or clears one bit, leaving the others of its byte as they are.
  void set_bit(uint8_t* data, int i, int64_t j, bool value) const;
  // Bytes from `data` that a width x height image reads.
  size_t size(int height) const;

 private:
  // The byte of pixel (i, j) and the bit's position in it.
  size_t byte_of(int i, int64_t j) const;
  int shift_of(int i) const;

  size_t row_stride_ = 0;
  size_t first_row_ = 0;
  int skip_bits_ = 0;
  int width_ = 0;
  bool lsb_first_ = false;
};

// A width x height bitmap read under `store`, copied as the default unpack state with
// alignment 1 reads it: rows of whole bytes, most significant bit first.
std::vector<uint8_t> tight_bitmap_copy(const PixelStore& store, int width, int height, const void* data);

}  // namespace pineda
