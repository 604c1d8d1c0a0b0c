#pragma once
// Distances to the polylines of a synthetic frame's truth (fieldlines/synth/truth.hpp), for the
// tests that ask which painted line a detected segment or a ray lies along.
#include <algorithm>
#include <cmath>
#include <string_view>

#include "fieldlines/synth/truth.hpp"

namespace fieldlines::test {

// From (x, y) to the polyline `f`, px (1e9 for a polyline of fewer than two points).
inline float distance_to(const synth::TruthFeature& f, float x, float y) {
  float best = 1e9f;
  for (std::size_t i = 1; i < f.points.size(); ++i) {
    const synth::TruthPoint &a = f.points[i - 1], &b = f.points[i];
    const float dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    const float t = len2 > 0 ? std::clamp(((x - a.x) * dx + (y - a.y) * dy) / len2, 0.f, 1.f) : 0.f;
    best = std::min(best, std::hypot(x - a.x - t * dx, y - a.y - t * dy));
  }
  return best;
}

// From (x, y) to the nearest of the truth's polylines named `name`.
inline float distance_to(const synth::GroundTruth& truth, std::string_view name, float x, float y) {
  float best = 1e9f;
  for (const synth::TruthFeature& f : truth.features)
    if (f.name == name) best = std::min(best, distance_to(f, x, y));
  return best;
}

}  // namespace fieldlines::test
