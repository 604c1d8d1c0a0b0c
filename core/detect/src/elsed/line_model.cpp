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

bool LineModel::fits(const std::vector<Pixel>& chain, double max_error) const {
  // sum (a u + b v + c)^2 expanded over the moments, in coordinates centred on the first pixel
  // so the terms stay near the result (the exact integer moments make the centring exact).
  const std::int64_t n = n_;
  const std::int64_t u0 = horizontal_ ? first_.x : first_.y, v0 = horizontal_ ? first_.y : first_.x;
  const auto su = static_cast<double>(sx_ - n * u0), sv = static_cast<double>(sy_ - n * v0);
  const auto suu = static_cast<double>(sxx_ - 2 * u0 * sx_ + n * u0 * u0);
  const auto svv = static_cast<double>(syy_ - 2 * v0 * sy_ + n * v0 * v0);
  const auto suv = static_cast<double>(sxy_ - u0 * sy_ - v0 * sx_ + n * u0 * v0);
  const double a = horizontal_ ? eq_[0] : eq_[1], b = horizontal_ ? eq_[1] : eq_[0];
  const double c = eq_[2] + a * static_cast<double>(u0) + b * static_cast<double>(v0);
  const double dn = static_cast<double>(n);
  const double t_uu = a * a * suu, t_vv = b * b * svv, t_cc = dn * c * c;
  const double t_uv = 2 * a * b * suv, t_uc = 2 * a * c * su, t_vc = 2 * b * c * sv;
  const double sum = t_uu + t_vv + t_cc + t_uv + t_uc + t_vc;
  // Both this and the loop are off the exact sum by a few ulps of the terms' magnitudes and of
  // n (|c| + |x| + |y|)^2 (every window pixel lies within n steps of the first): 1e-12 of that
  // is thousands of times wider than either error, and still decides all but ties.
  const double k = std::abs(eq_[2]) + std::abs(first_.x) + std::abs(first_.y) + 2 * dn + 1;
  const double margin =
      1e-12 * (t_uu + t_vv + t_cc + std::abs(t_uv) + std::abs(t_uc) + std::abs(t_vc) + dn * k * k);
  const double limit = max_error * dn;
  if (sum < limit - margin) return true;
  if (sum > limit + margin) return false;
  return fit_error(chain) < max_error;
}

void LineModel::refit(const std::vector<Pixel>& chain, int start) {
  sx_ = sy_ = sxy_ = sxx_ = syy_ = 0;
  n_ = 0;
  for (std::size_t i = start; i < chain.size(); ++i) accumulate(chain[i], +1);
  update_equation();
}

}  // namespace fieldlines::elsed
