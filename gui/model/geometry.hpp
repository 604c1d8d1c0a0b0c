#pragma once
// Plain 2-D value types shared by the studio logic; no ImGui here so the logic is testable
// without a window (the GUI converts to ImVec2 at the drawing boundary).
#include <algorithm>

namespace fieldlines::studio {

struct Vec2 {
  float x = 0, y = 0;
  friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator*(Vec2 a, float s) { return {a.x * s, a.y * s}; }
  bool operator==(const Vec2&) const = default;
};

// Axis-aligned rectangle; `min` need not be the top-left corner until normalised().
struct Rect {
  Vec2 min, max;
  Rect normalised() const {
    return {{std::min(min.x, max.x), std::min(min.y, max.y)}, {std::max(min.x, max.x), std::max(min.y, max.y)}};
  }
  float width() const { return max.x - min.x; }
  float height() const { return max.y - min.y; }
  bool contains(Vec2 p) const { return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y; }
};

}  // namespace fieldlines::studio
