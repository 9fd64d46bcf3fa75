#include "state/pixels/pixel_rect_draw.h"

#include <algorithm>
#include <cmath>

#include "raster/fragment_ops.h"
#include "raster/pixel_rect.h"
#include "state/draw.h"

namespace pineda {
namespace {

// The framebuffer columns (or rows) whose centres fall in an image of `size` pixels that
// starts at `origin` and is zoomed by `zoom`, with the image pixel of each: pixel centre c + 0.5
// maps to floor((c + 0.5 - origin) / zoom). Clipped to [0, limit).
struct Span {
  int first = 0;
  std::vector<int> source;  // image index per framebuffer column from `first`, or -1
};

Span zoomed_span(double origin, double zoom, int size, int limit) {
  Span span;
  if (zoom == 0.0 || size <= 0 || !std::isfinite(origin) || !std::isfinite(zoom)) return span;
  const double a = origin, b = origin + zoom * size;
  const double lo = std::max(std::floor(std::min(a, b) - 1.0), 0.0);
  const double hi = std::min(std::ceil(std::max(a, b) + 1.0), double(limit));
  if (lo >= hi) return span;
  span.first = int(lo);
  span.source.resize(size_t(hi - lo));
  for (size_t k = 0; k < span.source.size(); ++k) {
    const double i = std::floor((span.first + double(k) + 0.5 - origin) / zoom);
    span.source[k] = i >= 0 && i < size ? int(i) : -1;
  }
  return span;
}

// RGBA colours as the RGBA8 words the fragment routines store for them.
std::vector<uint32_t> rgba8_words(const std::vector<float>& color) {
  std::vector<uint32_t> words(color.size() / 4);
  for (size_t k = 0; k < words.size(); ++k) words[k] = raster::to_rgba8_word(&color[4 * k]);
  return words;
}

// The image's pixels row by row in runs of framebuffer columns that take one (a column past the
// image, or a pixel a copy found outside its source, ends a run): each run's pixels gathered into
// `row` (T per column) by value(image index), then emit(x, y, first of `row`, count).
template <typename T, typename Value, typename Emit>
void for_each_run(const PixelRectImage& image, const Span& cols, const Span& rows, Value value, Emit emit) {
  std::vector<T> row(cols.source.size());
  for (size_t r = 0; r < rows.source.size(); ++r) {
    const int j = rows.source[r];
    if (j < 0) continue;
    const size_t row_start = size_t(j) * image.width;
    for (size_t c = 0; c < cols.source.size();) {
      auto takes_pixel = [&](size_t k) {
        const int i = cols.source[k];
        return i >= 0 && (image.present.empty() || image.present[row_start + i]);
      };
      if (!takes_pixel(c)) {
        ++c;
        continue;
      }
      const size_t run = c;
      for (; c < cols.source.size() && takes_pixel(c); ++c) row[c] = value(row_start + cols.source[c]);
      emit(cols.first + int(run), rows.first + int(r), &row[run], int(c - run));
    }
  }
}

// Colour pixels given as RGBA8 words straight into the colour buffer (through the depth test and
// an integer blend when they are on), a row at a time.
void write_rgba8_rows(raster::PixelFragmentWriter& writer, const PixelRectImage& image, const uint32_t* words,
                      const Span& cols, const Span& rows, double depth) {
  for_each_run<uint32_t>(image, cols, rows, [&](size_t k) { return words[k]; },
                         [&](int x, int y, const uint32_t* run, int n) { writer.rgba8_row(x, y, run, n, depth); });
}

// Depth pixels of the raster colour, the same way.
void write_depth_rows(raster::PixelFragmentWriter& writer, const PixelRectImage& image, const float color[4],
                      const Span& cols, const Span& rows) {
  const uint32_t word = raster::to_rgba8_word(color);
  for_each_run<double>(image, cols, rows, [&](size_t k) { return image.depth[k]; },
                       [&](int x, int y, const double* run, int n) { writer.depth_row(x, y, word, run, n); });
}

}  // namespace

void draw_pixel_rect(Context& ctx, const PixelRectImage& image) {
  if (!ctx.draw_drawable()) return;
  // Once per colour buffer glDrawBuffer selects, after the queued primitives.
  ctx.render_to_draw_buffers([&] {
    ctx.finish();
    const raster::Framebuffer& fb = ctx.renderer().framebuffer();
    const RasterPosition& rp = ctx.raster_pos;
    raster::PixelFragmentWriter writer(fragment_snapshot(ctx), fb, rp.texcoord, rp.distance);
    const Span cols = zoomed_span(rp.window[0], ctx.pixel_mode.zoom_x, image.width, fb.width);
    const Span rows = zoomed_span(rp.window[1], ctx.pixel_mode.zoom_y, image.height, fb.height);
    const bool words = !image.rgba8.empty();
    if (image.kind == PixelRectImage::Kind::Color && writer.writes_rgba8_rows()) {
      if (words) return write_rgba8_rows(writer, image, image.rgba8.data(), cols, rows, rp.window[2]);
      return write_rgba8_rows(writer, image, rgba8_words(image.color).data(), cols, rows, rp.window[2]);
    }
    if (image.kind == PixelRectImage::Kind::Depth && writer.writes_rgba8_rows())
      return write_depth_rows(writer, image, rp.color, cols, rows);
    for (size_t r = 0; r < rows.source.size(); ++r) {
      const int j = rows.source[r];
      if (j < 0) continue;
      const int y = rows.first + int(r);
      for (size_t c = 0; c < cols.source.size(); ++c) {
        const int i = cols.source[c];
        const int x = cols.first + int(c);
        if (i < 0 || !writer.inside(x, y)) continue;
        const size_t k = size_t(j) * image.width + i;
        if (!image.present.empty() && !image.present[k]) continue;
        switch (image.kind) {
          case PixelRectImage::Kind::Color: {
            if (!words) {
              writer.fragment(x, y, &image.color[4 * k], rp.window[2]);
              break;
            }
            float rgba[4];
            for (int b = 0; b < 4; ++b) rgba[b] = float((image.rgba8[k] >> (8 * b)) & 0xffu) / 255.f;
            writer.fragment(x, y, rgba, rp.window[2]);
            break;
          }
          case PixelRectImage::Kind::Depth: writer.fragment(x, y, rp.color, image.depth[k]); break;
          case PixelRectImage::Kind::Stencil:
            writer.stencil(x, y, static_cast<uint32_t>(image.stencil[k] & 0xffffffff));
            break;
          case PixelRectImage::Kind::DepthStencil:
            writer.depth(x, y, image.depth[k]);
            writer.stencil(x, y, static_cast<uint32_t>(image.stencil[k] & 0xffffffff));
            break;
        }
      }
    }
  });
}

}  // namespace pineda
