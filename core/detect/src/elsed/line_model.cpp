#include "line_model.hpp"

#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>

namespace fieldlines::elsed {

void LineModel::init(const std::vector<Pixel>& chain, int start) {
  assert(static_cast<int>(chain.size()) - start >= 2);
  dx_ = chain.back().x - chain[start].x;
  dy_ = chain.back().y - chain[start].y;
  horizontal_ = std::abs(dx_) >= std::abs(dy_);
  refit(chain, start);
  first_ = chain[start];
  last_ = chain.back();
  prev_first_ = chain[start + 1];
  prev_last_ = chain[chain.size() - 2];
  first_index_ = start;
  last_index_ = static_cast<int>(chain.size()) - 1;
  sorted_ = true;
  first_side_done = second_side_done = false;
}

void LineModel::slide_two(const std::vector<Pixel>& chain) {
  accumulate(first_, -1);
  accumulate(prev_first_, -1);
  first_index_ += 2;
  last_index_ += 2;
  first_ = chain[first_index_];
  last_ = chain.back();
  prev_first_ = chain[first_index_ + 1];
  prev_last_ = chain[last_index_ - 1];
  dx_ = last_.x - first_.x;
  dy_ = last_.y - first_.y;
  const bool now_horizontal = std::abs(dx_) >= std::abs(dy_);
  if (now_horizontal != horizontal_) {
    // The sums are in the other axis order: start again from the pixels.
    horizontal_ = now_horizontal;
    refit(chain, first_index_);
  } else {
    accumulate(prev_last_, +1);
    accumulate(last_, +1);  // the equation waits for fits(), which mostly needs only the sums
  }
}

void LineModel::remove_endpoint(bool at_end) {
  accumulate(at_end ? last_ : first_, -1);
  update_equation();
  if (at_end) {
    last_ = prev_last_;
    prev_last_ = {-1, -1};
  } else {
    first_ = prev_first_;
    prev_first_ = {-1, -1};
  }
  --last_index_;
}

void LineModel::finish() {
  const float a = static_cast<float>(eq_[0]), b = static_cast<float>(eq_[1]), c = static_cast<float>(eq_[2]);
  const auto project = [&](Pixel p, float& x, float& y) {
    x = b * b * p.x - a * b * p.y - c * a;
    y = a * a * p.y - a * b * p.x - c * b;
  };
  project(first_, endpoints_[0], endpoints_[1]);
  project(last_, endpoints_[2], endpoints_[3]);
}

double LineModel::fit_error(const std::vector<Pixel>& chain) const {
  double sum = 0;
  for (int i = first_index_; i <= last_index_; ++i) {
    const double d = eq_[0] * chain[i].x + eq_[1] * chain[i].y + eq_[2];
    sum += d * d;
  }
  return sum / n_;
}

bool LineModel::fits(const std::vector<Pixel>& chain, double max_error) {
  // The regression line passes through the centroid, so the mean squared distance is
  //   cuu (cuu cvv - cuv^2) / (n^2 (cuv^2 + cuu^2))
  // with c.. = n^2 times the centred second moments: exact integers, the difference included.
  const std::int64_t n = n_;
  const std::int64_t cuu = n * sxx_ - sx_ * sx_, cvv = n * syy_ - sy_ * sy_, cuv = n * sxy_ - sx_ * sy_;
  std::int64_t uv2 = 0, uuvv = 0;
  const bool exact = cuu > 0 && !__builtin_mul_overflow(cuu, cvv, &uuvv) && !__builtin_mul_overflow(cuv, cuv, &uv2);
  if (exact) {
    const auto u = static_cast<double>(cuu), w = static_cast<double>(cuv), dn = static_cast<double>(n);
    const double error = u * static_cast<double>(uuvv - uv2) / (dn * dn * (w * w + u * u));
    // The loop is off the exact value by a few ulps of n (|x| + |y| + |c|) (each pixel lies
    // within n steps of the first, the line passes through their centroid); this is off by a
    // few ulps of itself. 1e-10 of that is far wider than both and still decides all but ties.
    const double k = 2.0 * (std::abs(first_.x) + std::abs(first_.y)) + 4 * dn + 1;
    const double margin = 1e-10 * k * (1 + max_error);
    if (error > max_error + margin) return false;  // the equation may stay stale: a new window follows
    update_equation();
    if (error < max_error - margin) return true;
  } else {
    update_equation();
  }
  return fit_error(chain) < max_error;
}

void LineModel::refit(const std::vector<Pixel>& chain, int start) {
  sx_ = sy_ = sxy_ = sxx_ = syy_ = 0;
  n_ = 0;
  for (std::size_t i = start; i < chain.size(); ++i) accumulate(chain[i], +1);
  update_equation();
}

}  // namespace fieldlines::elsed
