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
  // Lower: the edge keeps the columns from a first one on; Upper: up to a last one; Row: all
  // of a row or none (a horizontal edge).
  enum class Kind : uint8_t { Lower, Upper, Row };

  EdgeRowBound() = default;
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
      step_q_ = n_step;  // (rest_ stays 0 below den_ 1: next() adds step_q_ alone)
    }
  }

  Kind kind() const { return kind_; }
  // In the current row: the first column kept (Lower), the last one (Upper), whether none is (Row).
  int64_t first_column() const { return -quotient_; }
  int64_t last_column() const { return quotient_; }
  bool keeps_no_column() const { return quotient_ > 0; }

  // Without a branch: the carry of the remainder is as likely as not on a slanted edge.
  void next() {
    quotient_ += step_q_;
    rest_ += step_r_;
    const int64_t carry = rest_ >= den_ ? 1 : 0;
    quotient_ += carry;
    rest_ -= den_ & -carry;
  }

 private:
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
