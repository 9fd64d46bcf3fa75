#include "state/pixels/pixel_rect_draw.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "raster/fragment_ops.h"
#include "raster/pixel_rect.h"
#include "state/draw.h"
#include "state/pixels/pixel_unpack.h"

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
// image, or a pixel a copy found outside its source, ends a run), each run's values (T per
// column) from row j's values row_values(j): emit(x, y, first of the run's values, count). A run
// of consecutive image columns (zoom 1) is emitted in place, others gathered into a row first.
template <typename T, typename RowValues, typename Emit>
void for_each_run(const PixelRectImage& image, const Span& cols, const Span& rows, RowValues row_values, Emit emit) {
  std::vector<T> row(cols.source.size());
  for (size_t r = 0; r < rows.source.size(); ++r) {
    const int j = rows.source[r];
    if (j < 0) continue;
    const size_t row_start = size_t(j) * image.width;
    const T* values = nullptr;
    for (size_t c = 0; c < cols.source.size();) {
      auto takes_pixel = [&](size_t k) {
        const int i = cols.source[k];
        return i >= 0 && (image.present.empty() || image.present[row_start + i]);
      };
      if (!takes_pixel(c)) {
        ++c;
        continue;
      }
      if (!values) values = row_values(j);
      const size_t run = c;
      const int first = cols.source[run];
      bool consecutive = true;
      for (; c < cols.source.size() && takes_pixel(c); ++c) consecutive &= cols.source[c] == first + int(c - run);
      if (consecutive) {
        emit(cols.first + int(run), rows.first + int(r), values + first, int(c - run));
        continue;
      }
      for (size_t k = run; k < c; ++k) row[k] = values[cols.source[k]];
      emit(cols.first + int(run), rows.first + int(r), &row[run], int(c - run));
    }
  }
}

// Row j of a colour image as RGBA8 words: in the image's words, or read by its reader (into a
// scratch row kept for the next call, which a zoomed image's repeated rows reuse).
class ColorRowWords {
 public:
  explicit ColorRowWords(const PixelRectImage& image) : image_(image) {
    if (image.rgba8_reader) scratch_.resize(size_t(image.width));
  }
  const uint32_t* operator()(int j) {
    if (!image_.rgba8_reader) return &image_.rgba8[size_t(j) * image_.width];
    if (j != row_) {
      row_ = j;
      words_ = image_.rgba8_reader->rgba8_row_words(j, scratch_.data());
    }
    return words_;
  }

 private:
  const PixelRectImage& image_;
  std::vector<uint32_t> scratch_;
  int row_ = -1;
  const uint32_t* words_ = nullptr;
};

// Colour pixels given as RGBA8 words straight into the colour buffer (through the depth test and
// an integer blend when they are on), a row at a time.
template <typename RowWords>
void write_rgba8_rows(raster::PixelFragmentWriter& writer, const PixelRectImage& image, RowWords row_words,
                      const Span& cols, const Span& rows, double depth) {
  for_each_run<uint32_t>(image, cols, rows, row_words,
                         [&](int x, int y, const uint32_t* run, int n) { writer.rgba8_row(x, y, run, n, depth); });
}

// Depth pixels of the raster colour, the same way.
void write_depth_rows(raster::PixelFragmentWriter& writer, const PixelRectImage& image, const float color[4],
                      const Span& cols, const Span& rows) {
  const uint32_t word = raster::to_rgba8_word(color);
  for_each_run<double>(image, cols, rows, [&](int j) { return &image.depth[size_t(j) * image.width]; },
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
    const bool words = !image.rgba8.empty() || image.rgba8_reader;
    ColorRowWords row_words(image);
    if (image.kind == PixelRectImage::Kind::Color && writer.writes_rgba8_rows()) {
      if (words) return write_rgba8_rows(writer, image, std::ref(row_words), cols, rows, rp.window[2]);
      const std::vector<uint32_t> color_words = rgba8_words(image.color);
      return write_rgba8_rows(
          writer, image, [&](int j) { return &color_words[size_t(j) * image.width]; }, cols, rows, rp.window[2]);
    }
    if (image.kind == PixelRectImage::Kind::Depth && writer.writes_rgba8_rows())
      return write_depth_rows(writer, image, rp.color, cols, rows);
    for (size_t r = 0; r < rows.source.size(); ++r) {
      const int j = rows.source[r];
      if (j < 0) continue;
      const int y = rows.first + int(r);
      const uint32_t* row_rgba8 = image.kind == PixelRectImage::Kind::Color && words ? row_words(j) : nullptr;
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
            for (int b = 0; b < 4; ++b) rgba[b] = float((row_rgba8[i] >> (8 * b)) & 0xffu) / 255.f;
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
