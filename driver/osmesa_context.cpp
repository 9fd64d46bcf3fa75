#include "driver/osmesa_context.h"

#include <algorithm>

void osmesa_context::attach(uint8_t* pixels, int width, int height) {
  const size_t count = static_cast<size_t>(width) * height;
  if (count != depth.size() && depth_bits) depth.assign(count, 0);
  if (count != stencil.size() && stencil_bits) stencil.assign(count, 0);
  if (!pineda::osmesa::renders_in_place(format)) copy.resize(count * 4);
  user.pixels = pixels;
  user.format = format;
  user.width = width;
  user.height = height;
  relayout();
}

void osmesa_context::relayout() {
  // A row length shorter than the width would make rows overlap: the width wins.
  const int row_pixels = std::max(row_length, user.width);
  user.row_bytes = static_cast<ptrdiff_t>(row_pixels) * pineda::osmesa::bytes_per_pixel(format);
  if (!pineda::osmesa::renders_in_place(format)) pineda::osmesa::load(copy.data(), user);
  describe_framebuffer();
}

void osmesa_context::describe_framebuffer() {
  pineda::raster::Framebuffer& fb = drawable.framebuffer;
  fb.width = user.width;
  fb.height = user.height;
  if (pineda::osmesa::renders_in_place(format)) {
    // Row 0 of the framebuffer is the bottom row: with Y_UP off it is the last in memory.
    fb.color.base = user.row(0);
    fb.color.stride = user.y_up ? user.row_bytes : -user.row_bytes;
    fb.color.format = format == OSMESA_BGRA ? pineda::raster::ColorFormat::BGRA8
                                            : pineda::raster::ColorFormat::RGBA8;
  } else {
    fb.color = {copy.data(), static_cast<ptrdiff_t>(user.width) * 4, pineda::raster::ColorFormat::RGBA8, {}, 0};
  }
  fb.depth = {depth_bits ? depth.data() : nullptr, user.width, depth_bits};
  fb.stencil = {stencil_bits ? stencil.data() : nullptr, user.width, stencil_bits};
  const bool has_alpha = format != OSMESA_RGB && format != OSMESA_BGR;
  drawable.red_bits = drawable.green_bits = drawable.blue_bits = 8;
  drawable.alpha_bits = has_alpha ? 8 : 0;
  drawable.double_buffered = false;
}

void osmesa_context::update_user_image() {
  if (!user.pixels) return;
  gl->finish();
  if (!pineda::osmesa::renders_in_place(format)) pineda::osmesa::store(copy.data(), user);
}
