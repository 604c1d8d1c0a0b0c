#pragma once
// Synthetic segment features with known classes, for calibration and review tests: markings and
// boundaries at known angle distributions, grey edges at each class's achromatic angle.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "fieldlines/detect/segment.hpp"

namespace fieldlines::test {

namespace fl = fieldlines;

constexpr double kDeg = std::numbers::pi / 180;

// A horizontal segment whose grad_y is `g` (so the normal gradient is g; grad_x is zero).
inline fl::Segment segment_with(const fl::Rgb& g, float saliency, fl::Label label) {
  fl::Segment s;
  s.x0 = 10, s.y0 = 100, s.x1 = 210, s.y1 = 101;
  s.grad_y = g;
  s.saliency = saliency;
  s.label = label;
  return s;
}

// Gradient of magnitude m at `angle` from the marking transition (white -> green, (-1,0,-1)/sqrt2)
// towards grey (-1,-1,-1), which lies at 35.26 degrees.
inline fl::Rgb marking_gradient(double m, double angle_deg) {
  const double c = std::cos(angle_deg * kDeg), s = std::sin(angle_deg * kDeg);
  return {float(m * -c / std::sqrt(2.0)), float(m * -s), float(m * -c / std::sqrt(2.0))};
}
// Gradient at `angle` from the boundary transition (black -> green, (0,1,0)) towards (1,0,1).
inline fl::Rgb boundary_gradient(double m, double angle_deg) {
  const double c = std::cos(angle_deg * kDeg), s = std::sin(angle_deg * kDeg);
  return {float(m * s / std::sqrt(2.0)), float(m * c), float(m * s / std::sqrt(2.0))};
}

struct KnownField {
  std::vector<fl::Segment> segments;
  double marking_mean = 26, marking_sd = 2;
  double boundary_mean = 42, boundary_sd = 3;
  double grey_sd = 0.6;  // grey edges: the achromatic direction, slightly tinted
  int markings = 600, boundaries = 250, greys = 900;
};

// Classes with known angle distributions; grey edges at the achromatic angle of each class.
inline KnownField known_field(unsigned seed) {
  KnownField k;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> magnitude(40, 160), length(60, 600), short_length(20, 300);
  std::normal_distribution<double> noise(0, 1);
  for (int i = 0; i < k.markings; ++i)
    k.segments.push_back(segment_with(marking_gradient(magnitude(rng), k.marking_mean + k.marking_sd * noise(rng)),
                                      float(length(rng)), fl::Label::Marking));
  for (int i = 0; i < k.boundaries; ++i)
    k.segments.push_back(segment_with(boundary_gradient(magnitude(rng), k.boundary_mean + k.boundary_sd * noise(rng)),
                                      float(length(rng)), fl::Label::Boundary));
  for (int i = 0; i < k.greys; ++i) {
    // Grey edges of either sign: (1,1,1) or (-1,-1,-1), tinted by a small random rotation.
    const double m = magnitude(rng) * (i % 2 ? 1 : -1) / std::sqrt(3.0);
    k.segments.push_back(segment_with({float(m * (1 + 0.01 * k.grey_sd * noise(rng))),
                                       float(m * (1 + 0.01 * k.grey_sd * noise(rng))),
                                       float(m * (1 + 0.01 * k.grey_sd * noise(rng)))},
                                      float(short_length(rng)), fl::Label::None));
  }
  return k;
}

}  // namespace fieldlines::test
