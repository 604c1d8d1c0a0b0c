#pragma once
// The nearest point of a straight piece a-b to a point: one rule for the scores that match
// detected lines to truth lines (gt_eval.cpp, centre_line_score.cpp).
#include <algorithm>
#include <cmath>

namespace fieldlines::synth {

struct Nearest {
  float t;         // along a-b, in [0, 1] (0 for a piece of no length)
  float distance;  // from the point to a + t (b - a)
};

inline Nearest nearest_on_piece(float px, float py, float ax, float ay, float bx, float by) {
  const float dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
  const float t = len2 > 1e-12f ? std::clamp(((px - ax) * dx + (py - ay) * dy) / len2, 0.0f, 1.0f) : 0.0f;
  return {t, std::hypot(px - (ax + t * dx), py - (ay + t * dy))};
}

}  // namespace fieldlines::synth
