#pragma once
// Private: a growing line segment fitted by least squares while it is drawn.
//
// The fit regresses the minor coordinate on the major one (y on x for mostly horizontal lines),
// keeping running sums so adding or removing a pixel costs O(1). Pixels live in the drawer's
// shared chain; the model keeps the index range [first_index, last_index] into it.
#include <array>
#include <cstdint>
#include <vector>

#include "elsed_types.hpp"

namespace fieldlines::elsed {

class LineModel {
 public:
  // Fits chain[start..end) from scratch (at least 2 pixels).
  void init(const std::vector<Pixel>& chain, int start);
  // Slides the fitted window two pixels forward along the chain (used while searching for a fit).
  void slide_two(const std::vector<Pixel>& chain);
  void add(Pixel p, int index_in_chain, bool at_end);
  void remove_endpoint(bool at_end);
  void finish();  // computes the endpoints by projecting the extreme pixels on the line

  bool is_inlier(int x, int y, double max_dist) const {
    const double d = eq_[0] * x + eq_[1] * y + eq_[2];
    return (d >= 0 ? d : -d) < max_dist;
  }
  double fit_error(const std::vector<Pixel>& chain) const;

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
  std::uint32_t n_ = 0;
  int dx_ = 0, dy_ = 0;  // chain direction, orients the equation's normal consistently
  bool horizontal_ = true;
  std::array<double, 3> eq_{};  // a x + b y + c = 0 with a^2 + b^2 = 1
  std::array<float, 4> endpoints_{};
  Pixel first_, prev_first_, last_, prev_last_;
  int first_index_ = -1, last_index_ = -1;
  bool sorted_ = true;  // all pixels were added at the end (no second side yet)
};

}  // namespace fieldlines::elsed
