// Where one edge of a triangle crosses each pixel row: the first (or last) pixel column whose
// centre the edge keeps, E >= 0, stepped row by row exactly in integers, with one division for
// the first row only. A triangle's pixels in a row are the columns between its edges' bounds,
// the same pixels as testing the edge functions at every centre.
#pragma once
#include <cstdint>

#include "raster/prim_setup.h"
#include "raster/raster_limits.h"
#include "raster/setup.h"

namespace pineda::raster {

class EdgeRowBound {
 public:
  // The bound in row y; next() moves it to row y + 1.
  EdgeRowBound(const EdgeFunction& e, int y) {
    // a * (256x + 128) + b * (256y + 128) + c >= 0  <=>  256a * x >= n.
    const int64_t n = -(e.b * (int64_t{y} * kSubpixelOne + kSubpixelHalf) + e.c) - kSubpixelHalf * e.a;
    const int64_t n_step = -e.b * kSubpixelOne;  // n's change from one row to the next
    if (e.a > 0) {  // x >= ceil(n / 256a) = -floor(-n / 256a): a lower bound
      kind_ = Kind::Lower;
      start(-n, kSubpixelOne * e.a, -n_step);
    } else if (e.a < 0) {  // x <= floor(n / 256a) = floor(-n / -256a): an upper bound
      kind_ = Kind::Upper;
      start(-n, -kSubpixelOne * e.a, -n_step);
    } else {  // the same for every column: all of the row when n <= 0, none otherwise
      kind_ = Kind::Row;
      quotient_ = n;
      step_q_ = n_step;
    }
  }

  // Narrows the columns [lo, hi] (inclusive) to the ones this edge keeps in the current row.
  void narrow(int64_t& lo, int64_t& hi) const {
    switch (kind_) {
      case Kind::Lower:
        if (-quotient_ > lo) lo = -quotient_;
        break;
      case Kind::Upper:
        if (quotient_ < hi) hi = quotient_;
        break;
      case Kind::Row:
        if (quotient_ > 0) hi = lo - 1;
        break;
    }
  }

  void next() {
    quotient_ += step_q_;
    if (kind_ == Kind::Row) return;
    rest_ += step_r_;
    if (rest_ >= den_) {
      ++quotient_;
      rest_ -= den_;
    }
  }

 private:
  enum class Kind : uint8_t { Lower, Upper, Row };

  // quotient = floor(m / den), m = quotient * den + rest with rest in [0, den); m grows by m_step a row.
  void start(int64_t m, int64_t den, int64_t m_step) {
    den_ = den;
    quotient_ = floor_div(m, den);
    rest_ = m - quotient_ * den;
    step_q_ = floor_div(m_step, den);
    step_r_ = m_step - step_q_ * den;
  }

  Kind kind_ = Kind::Row;
  int64_t quotient_ = 0, rest_ = 0, den_ = 1, step_q_ = 0, step_r_ = 0;
};

}  // namespace pineda::raster
