// Pixel buffer objects (GL 2.1 section 4.3.5, GL_ARB_pixel_buffer_object): while a buffer is
// bound to PIXEL_UNPACK_BUFFER (PIXEL_PACK_BUFFER), the pointer argument of every call that
// reads (writes) client pixels is an offset into its store.
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

#include "state/context.h"

namespace pineda {

// Bytes from the pointer argument up to the end of what a width x height image of format/type
// covers under `store`: `depth` slices of it for a 3D image (`volume`: the slices follow
// IMAGE_HEIGHT and SKIP_IMAGES; a 3D bitmap is one tall image, as pack_client_image reads it).
// 0 for an empty image; SIZE_MAX when the extent does not fit in size_t.
size_t client_image_extent(const PixelStore& store, int width, int height, int depth, bool volume, GLenum format,
                           GLenum type);

// Where a call reads the `bytes` of its client pixels: `pixels` itself with no unpack buffer
// bound, else the buffer's store at offset `pixels`. Returns false (GL_INVALID_OPERATION
// recorded, nothing to be read) when the buffer is mapped or the bytes are not all inside its
// store. With a buffer bound and `bytes` 0, `pixels` becomes null: nothing is read.
bool unpack_pixels(Context& ctx, const void*& pixels, size_t bytes);
// The same for a call that writes `bytes` of client pixels, through PIXEL_PACK_BUFFER. With no
// buffer bound, `bytes` past `client_bytes` (the bufSize of a GL_ARB_robustness glGetn*/glReadn*
// call) record GL_INVALID_OPERATION: nothing is written.
bool pack_pixels(Context& ctx, void*& pixels, size_t bytes, size_t client_bytes = SIZE_MAX);

// The bufSize argument of a GL_ARB_robustness call as a byte count (a negative one holds nothing).
inline size_t client_buffer_bytes(GLsizei buf_size) { return buf_size > 0 ? size_t(buf_size) : 0; }

}  // namespace pineda
