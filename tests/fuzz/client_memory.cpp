#define GL_GLEXT_PROTOTYPES
#include "tests/fuzz/client_memory.h"

#include <GL/glext.h>

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace pineda::fuzz {

GuardedBytes::GuardedBytes() : page_(size_t(sysconf(_SC_PAGESIZE))) {
  const size_t pages = (kSize + page_ - 1) / page_;
  void* p = mmap(nullptr, (pages + 2) * page_, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) abort();
  mapping_ = static_cast<uint8_t*>(p);
  if (mprotect(mapping_ + page_, pages * page_, PROT_READ | PROT_WRITE) != 0) abort();
  data_ = mapping_ + page_ + pages * page_ - kSize;  // ends where the second guard page starts
}

GuardedBytes::~GuardedBytes() { munmap(mapping_, ((kSize + page_ - 1) / page_ + 2) * page_); }

ClientMemory::ClientMemory() : feedback(4096), selection(4096) {
  for (size_t i = 0; i < arrays.size(); ++i) arrays.data()[i] = uint8_t(i * 37 + 11);
  // The byte pattern never forms a NaN or an infinite float: some floats of every 16 are, so
  // that calls reading floats from here (glPixelMapfv, glTexParameterfv, arrays) meet them.
  constexpr float kSpecial[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                                -1e30f};
  for (size_t i = 0; i + 16 <= arrays.size() / sizeof(float); i += 16)
    std::memcpy(arrays.data() + (i + 5 + i / 16 % 7) * sizeof(float), &kSpecial[i / 16 % 3], sizeof(float));
}

namespace {

// Between glBegin and glEnd the query fails and leaves 0: the call is an error there (or is
// compiled while a list is, which the client pointer path keeps in bounds too).
bool pixel_buffer_bound(GLenum binding) {
  GLint bound = 0;
  glGetIntegerv(binding, &bound);
  return bound != 0;
}

}  // namespace

const void* ClientMemory::image_source(size_t footprint, bool invalid) const {
  if (pixel_buffer_bound(GL_PIXEL_UNPACK_BUFFER_BINDING)) return reinterpret_cast<const void*>(pixel_buffer_offset);
  return invalid || footprint <= arrays.size() ? arrays.data() : nullptr;
}

void* ClientMemory::image_destination(std::vector<uint8_t>& out) const {
  if (pixel_buffer_bound(GL_PIXEL_PACK_BUFFER_BINDING)) return reinterpret_cast<void*>(pixel_buffer_offset);
  return out.data();
}

size_t image_footprint(bool pack, int64_t width, int64_t height, int64_t depth) {
  if (width <= 0 || height <= 0 || depth <= 0) return 0;
  // Between glBegin and glEnd (a list compiled and executed, or a call that is an error there)
  // the queries fail and write nothing: then the footprint is unknown, so as large as can be.
  bool known = true;
  auto get = [&known](GLenum pname) {
    GLint v = -1;
    glGetIntegerv(pname, &v);
    known &= v >= 0;
    return __int128(std::max(v, 0));
  };
  const __int128 alignment = get(pack ? GL_PACK_ALIGNMENT : GL_UNPACK_ALIGNMENT);
  const __int128 row_length = get(pack ? GL_PACK_ROW_LENGTH : GL_UNPACK_ROW_LENGTH);
  const __int128 skip_rows = get(pack ? GL_PACK_SKIP_ROWS : GL_UNPACK_SKIP_ROWS);
  const __int128 skip_pixels = get(pack ? GL_PACK_SKIP_PIXELS : GL_UNPACK_SKIP_PIXELS);
  const __int128 image_height = get(pack ? GL_PACK_IMAGE_HEIGHT : GL_UNPACK_IMAGE_HEIGHT);
  const __int128 skip_images = get(pack ? GL_PACK_SKIP_IMAGES : GL_UNPACK_SKIP_IMAGES);
  if (!known) return SIZE_MAX;
  const __int128 stride = (row_length > 0 ? row_length : width) * 16 + alignment;
  const __int128 rows = image_height > 0 ? image_height : height;
  const __int128 total = ((skip_images + depth) * rows + skip_rows + height + 1) * stride + (skip_pixels + width) * 16;
  return total > __int128(SIZE_MAX) ? SIZE_MAX : size_t(total);
}

}  // namespace pineda::fuzz
