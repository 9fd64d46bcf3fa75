// The application memory the fuzzed calls read and write. Every pointer handed to GL covers
// what the call's arguments allow it to touch, so AddressSanitizer reports any access beyond.
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pineda::fuzz {

// Client arrays point at most kArrayOffsetMax bytes into `arrays`, with strides up to
// kArrayStrideMax and elements of up to 32 bytes, so vertices 0 to kMaxVertexIndex are in it.
constexpr int kArrayOffsetMax = 256;
constexpr int kArrayStrideMax = 64;
constexpr int kMaxVertexIndex = 999;

// 64 KiB between two inaccessible pages: a read past either end faults even in code that
// AddressSanitizer does not instrument.
class GuardedBytes {
 public:
  GuardedBytes();
  ~GuardedBytes();
  GuardedBytes(const GuardedBytes&) = delete;
  GuardedBytes& operator=(const GuardedBytes&) = delete;

  uint8_t* data() const { return data_; }
  size_t size() const { return kSize; }

 private:
  static constexpr size_t kSize = 64 * 1024;
  uint8_t* mapping_ = nullptr;
  uint8_t* data_ = nullptr;
  size_t page_ = 0;
};

struct ClientMemory {
  ClientMemory();

  GuardedBytes arrays;  // vertex arrays, images, list names, map points: read only
  std::vector<GLfloat> feedback;  // glFeedbackBuffer's, kept until the next one
  std::vector<GLuint> selection;  // glSelectBuffer's
  int calls_to_lists_in_list = 0;  // glCallList(s) compiled into the list being built
  uintptr_t pixel_buffer_offset = 0;  // the offset pixel calls pass while a pixel buffer is bound

  // Where a call reading an image of up to `footprint` bytes gets its pixels: with a pixel
  // unpack buffer bound, an offset into it (GL checks it); else `arrays` when it fits or when the
  // call is invalid whatever the state (it must read nothing), else null.
  const void* image_source(size_t footprint, bool invalid) const;
  // Where a call writing an image gets its pixels: an offset into the bound pixel pack buffer, or
  // `out`, which the caller sized to the image's footprint.
  void* image_destination(std::vector<uint8_t>& out) const;
};

// An upper bound of the bytes a width x height x depth image spans from its pointer under the
// current pack (or unpack) state: 16 bytes per pixel, the largest pixel of any format and type.
size_t image_footprint(bool pack, int64_t width, int64_t height, int64_t depth);

}  // namespace pineda::fuzz
