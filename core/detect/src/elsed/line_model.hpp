#pragma once
// Private: a growing line segment fitted by least squares while it is drawn.
//
// The fit regresses the minor coordinate on the major one (y on x for mostly horizontal lines),
// keeping running sums so adding or removing a pixel costs O(1). Pixels live in the drawer's
// shared chain; the model keeps the index range [first_index, last_index] into it.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "elsed_types.hpp"

// Private to the library: hidden, so calls are direct and the compiler may inline them (a
// default-visibility function in a shared library is interposable and never inlined).
#pragma GCC visibility push(hidden)

namespace fieldlines::elsed {

class LineModel {
 public:
  // Fits chain[start..end) from scratch (at least 2 pixels).
  void init(const std::vector<Pixel>& chain, int start);
  // Slides the fitted window two pixels forward along the chain (used while searching for a
  // fit). Leaves equation() stale until fits() returns true; nothing else reads it meanwhile.
  void slide_two(const std::vector<Pixel>& chain);
  void add(Pixel p, int index_in_chain, bool at_end);
  void remove_endpoint(bool at_end);
  void finish();  // computes the endpoints by projecting the extreme pixels on the line

  bool is_inlier(int x, int y, double max_dist) const {
    const double d = eq_[0] * x + eq_[1] * y + eq_[2];
    return (d >= 0 ? d : -d) < max_dist;
  }
  // Mean squared distance of chain[first_index..last_index] to the line (the window the sums
  // hold while searching for a fit).
  double fit_error(const std::vector<Pixel>& chain) const;
  // fit_error(chain) < max_error, decided from the running sums in O(1); only when that is
  // within rounding of max_error does it run the O(n) loop, so the answer is always the loop's.
  // Brings equation() up to date whenever it returns true.
  bool fits(const std::vector<Pixel>& chain, double max_error);

  bool horizontal() const { return horizontal_; }
  std::uint32_t count() const { return n_; }
  const std::array<double, 3>& equation() const { return eq_; }
  const std::array<float, 4>& endpoints() const { return endpoints_; }
  Pixel first() const { return first_; }
  Pixel last() const { return last_; }
  int first_index() const { return first_index_; }
  int last_index() const { return last_index_; }
  bool has_second_side() const { return !sorted_; }

  bool first_side_done = false;   // no further extension past the first endpoint
  bool second_side_done = false;  // idem for the second

 private:
  void refit(const std::vector<Pixel>& chain, int start);
  void accumulate(Pixel p, int sign);
  void update_equation();

  std::int64_t sx_ = 0, sy_ = 0, sxy_ = 0, sxx_ = 0;  // major=x, minor=y in the sums' naming
  std::int64_t syy_ = 0;                              // only for fits()
  std::uint32_t n_ = 0;
  int dx_ = 0, dy_ = 0;  // chain direction, orients the equation's normal consistently
  bool horizontal_ = true;
  std::array<double, 3> eq_{};  // a x + b y + c = 0 with a^2 + b^2 = 1
  std::array<float, 4> endpoints_{};
  Pixel first_, prev_first_, last_, prev_last_;
  int first_index_ = -1, last_index_ = -1;
  bool sorted_ = true;  // all pixels were added at the end (no second side yet)
};

// Hot: once per drawn pixel, so inline.
inline void LineModel::accumulate(Pixel p, int sign) {
  const std::int64_t major = horizontal_ ? p.x : p.y;
  const std::int64_t minor = horizontal_ ? p.y : p.x;
  n_ += sign;
  sx_ += sign * major;
  sy_ += sign * minor;
  sxx_ += sign * major * major;
  sxy_ += sign * major * minor;
  syy_ += sign * minor * minor;
}

inline void LineModel::update_equation() {
  const std::int64_t n = n_;
  const double along = static_cast<double>(n * sxy_ - sx_ * sy_);
  const double across = static_cast<double>(sx_ * sx_ - n * sxx_);
  eq_[2] = static_cast<double>(sy_ * sxx_ - sx_ * sxy_);
  eq_[0] = horizontal_ ? along : across;
  eq_[1] = horizontal_ ? across : along;
  const double norm = std::sqrt(eq_[0] * eq_[0] + eq_[1] * eq_[1]);
  if (norm > 0 && std::isfinite(norm)) {
    for (double& e : eq_) e /= norm;
  } else {
    // Degenerate sums (every pixel on one major coordinate): the axis line through their mean,
    // never a NaN equation.
    const double minor_mean = n > 0 ? static_cast<double>(sy_) / static_cast<double>(n) : 0.0;
    eq_ = horizontal_ ? std::array<double, 3>{0.0, 1.0, -minor_mean} : std::array<double, 3>{1.0, 0.0, -minor_mean};
  }
  // Orient the normal so the line direction (-b, a) follows the drawing direction.
  if (dx_ * -eq_[1] + dy_ * eq_[0] < 0)
    for (double& e : eq_) e = -e;
}

inline void LineModel::add(Pixel p, int index_in_chain, bool at_end) {
  accumulate(p, +1);
  update_equation();
  if (at_end) {
    prev_last_ = last_;
    last_ = p;
  } else {
    prev_first_ = first_;
    first_ = p;
  }
  // Pixels of one segment are contiguous in the chain, so the newest is always the last index.
  last_index_ = index_in_chain;
  sorted_ = sorted_ && at_end;
}

}  // namespace fieldlines::elsed

#pragma GCC visibility pop
