#include "state/pixels/pixel_rect_draw.h"

#include <algorithm>
#include <cmath>

#include "raster/fragment_ops.h"
#include "raster/pixel_rect.h"
#include "state/draw.h"
#include "state/pixels/color_byte_reads.h"
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

// The image's pixels row by row in runs of framebuffer columns that take one (a column past the
// image, or a pixel a copy found outside its source, ends a run), each run's values (T per
// column) from row j's values row_values(j): emit(x, y, first of the run's values, count). A run
// of consecutive image columns (zoom 1) is emitted in place, others gathered into a row first.
template <typename T, typename RowValues, typename Emit>
void for_each_run(const PixelRectImage& image, const Span& cols, const Span& rows, bool top_down, RowValues row_values,
                  Emit emit) {
  std::vector<T> row(cols.source.size());
  for (size_t n = 0; n < rows.source.size(); ++n) {
    const size_t r = top_down ? rows.source.size() - 1 - n : n;
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

// Row j of a colour image as RGBA8 words or as RGBA: in the image's own vectors, or read by its
// reader into scratch rows kept for the next call (a zoomed image's repeated rows reuse them).
class ColorRows {
 public:
  explicit ColorRows(const PixelRectImage& image)
      : image_(image),
        width_(size_t(image.width)),
        words_(!image.rgba8.empty() || image.source_rows.set() ||
               (image.color_reader && image.color_reader->reads_rgba8())) {}
  // Whether the colours are RGBA8 words (bytes without pixel transfer), which stand for k / 255.
  bool words() const { return words_; }
  // The row's words, or its RGBA as the fragment routines round it (raster::to_rgba8_word).
  const uint32_t* word_row(int j) {
    if (words_ && !image_.color_reader && !image_.source_rows.set()) return &image_.rgba8[size_t(j) * width_];
    if (j == word_row_) return word_data_;
    word_row_ = j;
    word_scratch_.resize(width_);
    if (image_.source_rows.set()) return word_data_ = source_row(j);
    if (words_) return word_data_ = image_.color_reader->rgba8_row_words(j, word_scratch_.data());
    const float* rgba = float_row(j);
    for (size_t i = 0; i < width_; ++i) word_scratch_[i] = raster::to_rgba8_word(rgba + 4 * i);
    return word_data_ = word_scratch_.data();
  }
  // The row's RGBA; only when !words().
  const float* float_row(int j) {
    if (!image_.color_reader) return &image_.color[4 * size_t(j) * width_];
    if (j != float_row_) {
      float_row_ = j;
      float_scratch_.resize(4 * width_);
      image_.color_reader->read_row(j, 0, image_.width, float_scratch_.data());
    }
    return float_scratch_.data();
  }

 private:
  // Row j of the source rows as words (a BGRA8 buffer's with red and blue exchanged), by
  // glReadPixels' row packer.
  const uint32_t* source_row(int j) {
    const PixelRectImage::SourceRows& source = image_.source_rows;
    gl::pack_rgba8_row(source.buffer.base + source.buffer.stride * (source.y + j) + 4 * source.x,
                       source.buffer.format == raster::ColorFormat::BGRA8, GL_RGBA, 0,
                       reinterpret_cast<uint8_t*>(word_scratch_.data()), image_.width, false);
    return word_scratch_.data();
  }

  const PixelRectImage& image_;
  size_t width_;
  bool words_;
  std::vector<uint32_t> word_scratch_;
  std::vector<float> float_scratch_;
  int word_row_ = -1, float_row_ = -1;
  const uint32_t* word_data_ = nullptr;
};

// Colour pixels given as RGBA8 words straight into the colour buffer (through the depth test and
// an integer blend when they are on), a row at a time.
template <typename RowWords>
void write_rgba8_rows(raster::PixelFragmentWriter& writer, const PixelRectImage& image, RowWords row_words,
                      const Span& cols, const Span& rows, bool top_down, double depth) {
  for_each_run<uint32_t>(image, cols, rows, top_down, row_words,
                         [&](int x, int y, const uint32_t* run, int n) { writer.rgba8_row(x, y, run, n, depth); });
}

// Depth pixels of the raster colour, the same way.
void write_depth_rows(raster::PixelFragmentWriter& writer, const PixelRectImage& image, const float color[4],
                      const Span& cols, const Span& rows) {
  const uint32_t word = raster::to_rgba8_word(color);
  for_each_run<double>(image, cols, rows, false, [&](int j) { return &image.depth[size_t(j) * image.width]; },
                       [&](int x, int y, const double* run, int n) { writer.depth_row(x, y, word, run, n); });
}

// Whether the framebuffer rows a copy's source rows land on lie above them (each image row's
// framebuffer row is its source row shifted by one amount at a y zoom of 1).
bool moves_up(const PixelRectImage::SourceRows& source, const Span& rows) {
  for (size_t r = 0; r < rows.source.size(); ++r)
    if (rows.source[r] >= 0) return rows.first + int(r) > source.y + rows.source[r];
  return false;
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
    ColorRows colors(image);
    const bool top_down = image.source_rows.set() && moves_up(image.source_rows, rows);
    if (image.kind == PixelRectImage::Kind::Color && writer.writes_rgba8_rows())
      return write_rgba8_rows(writer, image, [&](int j) { return colors.word_row(j); }, cols, rows, top_down,
                              rp.window[2]);
    if (image.kind == PixelRectImage::Kind::Depth && writer.writes_rgba8_rows())
      return write_depth_rows(writer, image, rp.color, cols, rows);
    const bool color = image.kind == PixelRectImage::Kind::Color;
    for (size_t n = 0; n < rows.source.size(); ++n) {
      const size_t r = top_down ? rows.source.size() - 1 - n : n;
      const int j = rows.source[r];
      if (j < 0) continue;
      const int y = rows.first + int(r);
      const uint32_t* row_words = color && colors.words() ? colors.word_row(j) : nullptr;
      const float* row_rgba = color && !colors.words() ? colors.float_row(j) : nullptr;
      for (size_t c = 0; c < cols.source.size(); ++c) {
        const int i = cols.source[c];
        const int x = cols.first + int(c);
        if (i < 0 || !writer.inside(x, y)) continue;
        const size_t k = size_t(j) * image.width + i;
        if (!image.present.empty() && !image.present[k]) continue;
        switch (image.kind) {
          case PixelRectImage::Kind::Color: {
            if (row_rgba) {
              writer.fragment(x, y, row_rgba + 4 * size_t(i), rp.window[2]);
              break;
            }
            float rgba[4];
            for (int b = 0; b < 4; ++b) rgba[b] = float((row_words[i] >> (8 * b)) & 0xffu) / 255.f;
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
