#pragma once
// The geometry the scores that match detected lines to truth lines share (gt_eval.cpp,
// centre_line_score.cpp): a piece's direction, when two run parallel, the nearest point of a
// piece to a point, and the walk along a piece in steps of about a pixel.
#include <algorithm>
#include <cmath>

namespace fieldlines::synth {

struct Unit {
  float x, y;
};

// The unit direction a -> b; (1, 0) for a piece of no length.
inline Unit direction(float ax, float ay, float bx, float by) {
  const float dx = bx - ax, dy = by - ay, len = std::hypot(dx, dy);
  return len > 1e-9f ? Unit{dx / len, dy / len} : Unit{1, 0};
}

// The cosine that GtMatchParams::max_angle_deg allows between two parallel lines.
inline float cos_of_degrees(float deg) { return std::cos(deg * 3.14159265f / 180.0f); }

// Whether two directions run within the angle of cosine `cos_max`, either way round.
inline bool parallel(const Unit& a, const Unit& b, float cos_max) { return std::abs(a.x * b.x + a.y * b.y) >= cos_max; }

struct Nearest {
  float t;         // along a-b, in [0, 1] (0 for a piece of no length)
  float distance;  // from the point to a + t (b - a)
};

inline Nearest nearest_on_piece(float px, float py, float ax, float ay, float bx, float by) {
  const float dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
  const float t = len2 > 1e-12f ? std::clamp(((px - ax) * dx + (py - ay) * dy) / len2, 0.0f, 1.0f) : 0.0f;
  return {t, std::hypot(px - (ax + t * dx), py - (ay + t * dy))};
}

// Calls f(x, y, step) at the midpoints of the ceil(length) equal steps along a-b (one step for a
// piece of no length).
template <class F>
void along(float ax, float ay, float bx, float by, F f) {
  const float len = std::hypot(bx - ax, by - ay);
  const int n = std::max(1, static_cast<int>(std::ceil(len)));
  for (int i = 0; i < n; ++i) {
    const float t = (static_cast<float>(i) + 0.5f) / static_cast<float>(n);
    f(ax + t * (bx - ax), ay + t * (by - ay), len / static_cast<float>(n));
  }
}

}  // namespace fieldlines::synth
