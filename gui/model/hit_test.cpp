#include "gui/model/hit_test.hpp"

#include <algorithm>
#include <cmath>

namespace fieldlines::studio {

ScreenSegment to_screen(const Segment& s, const ViewTransform& view) {
  return {view.image_to_screen({s.x0 + 0.5f, s.y0 + 0.5f}), view.image_to_screen({s.x1 + 0.5f, s.y1 + 0.5f})};
}

float distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a, ap = p - a;
  const float len2 = ab.x * ab.x + ab.y * ab.y;
  float t = len2 > 0 ? (ap.x * ab.x + ap.y * ab.y) / len2 : 0.0f;
  t = std::clamp(t, 0.0f, 1.0f);
  const Vec2 closest = a + ab * t;
  return std::hypot(p.x - closest.x, p.y - closest.y);
}

std::optional<std::size_t> nearest_segment(std::span<const Segment> segments, const ViewTransform& view,
                                           Vec2 cursor, float max_distance_px) {
  std::optional<std::size_t> best;
  float best_distance = max_distance_px;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const ScreenSegment s = to_screen(segments[i], view);
    const float d = distance_to_segment(cursor, s.a, s.b);
    if (d < best_distance || (d == best_distance && !best)) {
      best_distance = d;
      best = i;
    }
  }
  return best;
}

void segments_under(std::span<const Segment> segments, const ViewTransform& view, Vec2 cursor, float max_distance_px,
                    std::vector<std::size_t>& out) {
  out.clear();
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const ScreenSegment s = to_screen(segments[i], view);
    if (distance_to_segment(cursor, s.a, s.b) <= max_distance_px) out.push_back(i);
  }
  // Few segments are ever this close, so the distances are recomputed in the comparison rather
  // than kept in a second buffer.
  const auto distance = [&](std::size_t i) {
    const ScreenSegment s = to_screen(segments[i], view);
    return distance_to_segment(cursor, s.a, s.b);
  };
  std::sort(out.begin(), out.end(), [&](std::size_t a, std::size_t b) {
    const float da = distance(a), db = distance(b);
    return da < db || (da == db && a < b);
  });
}

std::vector<std::size_t> segments_under(std::span<const Segment> segments, const ViewTransform& view, Vec2 cursor,
                                        float max_distance_px) {
  std::vector<std::size_t> out;
  segments_under(segments, view, cursor, max_distance_px, out);
  return out;
}

bool segment_intersects_rect(Vec2 a, Vec2 b, const Rect& rect) {
  const Rect r = rect.normalised();
  // Liang-Barsky clipping: the parametric interval of the segment inside every slab.
  float t0 = 0, t1 = 1;
  const float d[2] = {b.x - a.x, b.y - a.y};
  const float lo[2] = {r.min.x - a.x, r.min.y - a.y};
  const float hi[2] = {r.max.x - a.x, r.max.y - a.y};
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0) {
      if (lo[axis] > 0 || hi[axis] < 0) return false;  // parallel and outside this slab
      continue;
    }
    float ta = lo[axis] / d[axis], tb = hi[axis] / d[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

std::vector<std::size_t> segments_in_rect(std::span<const Segment> segments, const ViewTransform& view,
                                          const Rect& screen_rect) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const ScreenSegment s = to_screen(segments[i], view);
    if (segment_intersects_rect(s.a, s.b, screen_rect)) out.push_back(i);
  }
  return out;
}

}  // namespace fieldlines::studio
