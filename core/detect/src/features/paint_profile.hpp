#pragma once
// What the profiles across painted lines share (stripes.cpp, edge_lines.cpp): how far a profile
// reaches, a pixel's brightness, grey paint blended into turf, the widest plausible paint per row.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/segment.hpp"

namespace fieldlines::paint {

constexpr int kOuterPx = 2;        // a profile starts this far outside the edge, beyond its blur
constexpr int kMaxBlurPx = 10;     // paint fades into turf over at most this many px (motion blur)
constexpr float kMinWidthPx = 0.5f;
constexpr float kTopWidthShare = 0.25f;  // the widest stripe on the top row, as a share of the bottom's

inline float brightness(const std::uint8_t* p) { return float(p[0] + p[1] + p[2]); }  // exact: one conversion

// Distance of chromaticities r = R / (R + G + B), g = G / (R + G + B) from grey.
inline float greyness_distance(float r, float g) { return std::abs(r - 1.f / 3) + std::abs(g - 1.f / 3); }
// ...of a pixel's.
inline float greyness_distance(const std::uint8_t* p) {
  const float sum = std::max(brightness(p), 1.f);
  return greyness_distance(p[2] / sum, p[1] / sum);
}

// Whether `peak`, brighter than `turf` and still in the field colour, is grey paint blended into
// turf (a line thinner than a pixel, or anti-aliased) rather than brighter turf. Grey light added
// to turf scales its distance from grey by turf / peak brightness; brighter turf keeps it. The
// peak must come at least half-way from the one to the other.
inline bool blended_paint(const std::uint8_t* peak, const std::uint8_t* turf) {
  const float ratio = std::min(1.f, brightness(turf) / std::max(brightness(peak), 1.f));
  return greyness_distance(peak) <= 0.5f * (1 + ratio) * greyness_distance(turf);
}

// Where between steps i and i + 1 of a profile's brightness `b` it crosses `level`, in steps.
inline float crossing(std::span<const float> b, int i, float level) {
  const auto at = [&](int k) { return b[static_cast<std::size_t>(k)]; };
  const float d = at(i + 1) - at(i);
  return d != 0.f ? float(i) + (level - at(i)) / d : float(i) + 0.5f;
}

// The height the largest plausible width scales with at row `y` (stripes.hpp): the frame's own
// at the bottom, kTopWidthShare of it on the top rows.
inline float width_scale(float y, int rows) { return float(rows) * std::max(kTopWidthShare, y / float(rows)); }

// The unit normal of segment s (unit direction (ux, uy)) towards its bright side: the side its
// colour gradient points to; the 8-bit BGR image decides when the gradients say nothing (a
// caller's own segments).
inline std::array<float, 2> bright_side(const cv::Mat& bgr, const Segment& s, float ux, float uy) {
  float nx = -uy, ny = ux, along = 0;
  for (int ch = 0; ch < 3; ++ch) along += s.grad_x[ch] * nx + s.grad_y[ch] * ny;
  if (along == 0.f) {
    const float mx = 0.5f * (s.x0 + s.x1), my = 0.5f * (s.y0 + s.y1);
    const auto at = [&](float t) {
      const int x = std::clamp(static_cast<int>(std::lround(mx + t * nx)), 0, bgr.cols - 1);
      const int y = std::clamp(static_cast<int>(std::lround(my + t * ny)), 0, bgr.rows - 1);
      return brightness(bgr.ptr<std::uint8_t>(y) + 3 * x);
    };
    along = at(1.5f) - at(-1.5f);
  }
  return along < 0 ? std::array{-nx, -ny} : std::array{nx, ny};
}

// The median of the first n values (reordered).
inline float median(std::array<float, 32>& v, int n) {
  std::nth_element(v.begin(), v.begin() + n / 2, v.begin() + n);
  return v[static_cast<std::size_t>(n / 2)];
}

}  // namespace fieldlines::paint
