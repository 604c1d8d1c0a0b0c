#include "fieldlines/detect/turf_colours.hpp"

#include <algorithm>
#include <cmath>

#include "features/paint_profile.hpp"

namespace fieldlines {
namespace {

// Calls f(index) for each of the up to 8 bins beside bin (i, j) and, with `self`, for it too.
template <int kBins, typename F>
void each_beside(int i, int j, bool self, F&& f) {
  for (int a = i - 1; a <= i + 1; ++a)
    for (int b = j - 1; b <= j + 1; ++b)
      if (a >= 0 && b >= 0 && a < kBins && b < kBins && (self || a != i || b != j))
        f(static_cast<std::size_t>(a * kBins + b));
}

}  // namespace

void TurfColours::measure(const cv::Mat& bgr8, const Rgb& field, const TurfColourParams& params) {
  measured_ = false;
  if (bgr8.empty() || bgr8.type() != CV_8UC3) return;
  const float field_sum = std::max(field[0] + field[1] + field[2], 1.f);
  counts_.fill(0);
  const FieldColourParams& s = params.sampling;
  const int row_step = std::max(s.row_step, 1), col_step = std::max(s.col_step, 1);
  std::uint32_t samples = 0;
  int i_lo = kBins, i_hi = -1, j_lo = kBins, j_hi = -1;  // the bins counted lie in this box
  for (int y = row_step / 2; y < bgr8.rows; y += row_step) {
    const std::uint8_t* row = bgr8.ptr<std::uint8_t>(y);
    for (int x = col_step / 2; x < bgr8.cols; x += col_step) {
      const std::uint8_t* p = row + 3 * x;
      if (!s.green(p[0], p[1], p[2])) continue;
      const float sum = float(p[0] + p[1] + p[2]);
      if (!params.brightness.contains(sum, field_sum)) continue;
      const int i = bin(p[2] / sum), j = bin(p[1] / sum);
      ++counts_[static_cast<std::size_t>(i * kBins + j)];
      ++samples;
      i_lo = std::min(i_lo, i), i_hi = std::max(i_hi, i), j_lo = std::min(j_lo, j), j_hi = std::max(j_hi, j);
    }
  }
  if (samples == 0) return;
  // 3 x 3 box over the bins: a mode a few bins wide reads as one hill, not a comb. Only the
  // counted box and one bin around it can be non-zero (a few hundred bins of the 4,096).
  const auto clip = [](int v) { return std::clamp(v, 0, kBins - 1); };
  smoothed_.fill(0);
  std::uint32_t peak = 0;
  std::size_t peak_at = 0;
  for (int i = clip(i_lo - 1); i <= clip(i_hi + 1); ++i)
    for (int j = clip(j_lo - 1); j <= clip(j_hi + 1); ++j) {
      std::uint32_t sum = 0;
      each_beside<kBins>(i, j, true, [&](std::size_t at) { sum += counts_[at]; });
      const auto at = static_cast<std::size_t>(i * kBins + j);
      smoothed_[at] = sum;
      if (sum > peak) peak = sum, peak_at = at;
    }
  // Grow from the peak over the 8 neighbours of each bin taken (breadth first, a fixed queue),
  // through bins as saturated as turf.
  const auto floor = static_cast<std::uint32_t>(params.grow_share * float(peak));
  const float grey_distance = params.min_saturation * paint::greyness_distance(field[0] / field_sum, field[1] / field_sum);
  const auto saturated = [&](int i, int j) {
    return paint::greyness_distance((float(i) + 0.5f) / kBins, (float(j) + 0.5f) / kBins) >= grey_distance;
  };
  turf_.fill(0);
  std::size_t head = 0, tail = 0;
  turf_[peak_at] = 2;  // 2: grown; 1 (below): the one-bin rim
  queue_[tail++] = static_cast<std::uint16_t>(peak_at);
  while (head < tail) {
    const int at = queue_[head++];
    each_beside<kBins>(at / kBins, at % kBins, false, [&](std::size_t next) {
      if (turf_[next] != 0 || smoothed_[next] < std::max<std::uint32_t>(floor, 1) ||
          !saturated(static_cast<int>(next) / kBins, static_cast<int>(next) % kBins))
        return;
      turf_[next] = 2;
      queue_[tail++] = static_cast<std::uint16_t>(next);
    });
  }
  // The rim: every bin beside a grown one (grown bins lie in the box widened by one).
  for (int i = clip(i_lo - 2); i <= clip(i_hi + 2); ++i)
    for (int j = clip(j_lo - 2); j <= clip(j_hi + 2); ++j) {
      const auto at = static_cast<std::size_t>(i * kBins + j);
      if (turf_[at] != 0) continue;
      bool beside = false;
      each_beside<kBins>(i, j, false, [&](std::size_t next) { beside = beside || turf_[next] == 2; });
      if (beside) turf_[at] = 1;
    }
  for (int i = clip(i_lo - 2); i <= clip(i_hi + 2); ++i)
    for (int j = clip(j_lo - 2); j <= clip(j_hi + 2); ++j) {
      std::uint8_t& t = turf_[static_cast<std::size_t>(i * kBins + j)];
      t = t != 0 ? 1 : 0;
    }
  measured_ = true;
}

}  // namespace fieldlines
