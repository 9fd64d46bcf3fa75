// Client images copied into display lists (GL 1.5 spec 5.4): exactly the pixels a call
// reads, tightly packed (alignment 1, no row length or skips, bytes in native order), so the
// list replays them under the default unpack state with alignment 1.
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "state/context.h"

namespace pineda {

// `width` x `height` pixels of `format`/`type`, `depth` slices of them for a 3D image
// (`volume`: slices follow IMAGE_HEIGHT and SKIP_IMAGES), read under `store`. The caller has
// checked that the call reads them: positive sizes, a valid format and type, non-null pixels.
std::vector<uint8_t> pack_client_image(const PixelStore& store, int width, int height, int depth, bool volume,
                                       GLenum format, GLenum type, const void* pixels);

// Runs `call` under the unpack state that reads a packed image; the application's state is
// restored even when the call runs out of memory.
template <typename Call>
void with_packed_unpack(Context& c, Call call) {
  struct Restore {
    Context& c;
    PixelStore saved;
    ~Restore() { c.unpack = saved; }
  } restore{c, c.unpack};
  c.unpack = PixelStore{};
  c.unpack.alignment = 1;
  call();
}

}  // namespace pineda
