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
    accumulate(last_, +1);
    update_equation();
  }
}

void LineModel::add(Pixel p, int index_in_chain, bool at_end) {
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

void LineModel::refit(const std::vector<Pixel>& chain, int start) {
  sx_ = sy_ = sxy_ = sxx_ = 0;
  n_ = 0;
  for (std::size_t i = start; i < chain.size(); ++i) accumulate(chain[i], +1);
  update_equation();
}

void LineModel::accumulate(Pixel p, int sign) {
  const std::int64_t major = horizontal_ ? p.x : p.y;
  const std::int64_t minor = horizontal_ ? p.y : p.x;
  n_ += sign;
  sx_ += sign * major;
  sy_ += sign * minor;
  sxx_ += sign * major * major;
  sxy_ += sign * major * minor;
}

void LineModel::update_equation() {
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

}  // namespace fieldlines::elsed
