#pragma once
// Which segment the pointer is on, measured in SCREEN pixels so the pick radius feels the same
// at every zoom, and which segments a dragged rectangle touches.
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "fieldlines/detect/segment.hpp"
#include "gui/model/geometry.hpp"
#include "gui/model/view_transform.hpp"

namespace fieldlines::studio {

// Segment endpoints are pixel indices (centre of the pixel), so they sit at +0.5 in the view's
// continuous image coordinates. Drawing and picking both use this, so they always agree.
struct ScreenSegment {
  Vec2 a, b;
};
ScreenSegment to_screen(const Segment& segment, const ViewTransform& view);

// Euclidean distance from p to the closed segment [a, b] (a point when a == b).
float distance_to_segment(Vec2 p, Vec2 a, Vec2 b);

// The segment nearest to `cursor` (screen pixels) within `max_distance_px`; ties go to the lower
// index. nullopt when none is that close.
std::optional<std::size_t> nearest_segment(std::span<const Segment> segments, const ViewTransform& view,
                                           Vec2 cursor, float max_distance_px);

// Every segment within `max_distance_px` of `cursor`, nearest first (ties: lower index first),
// so overlapping segments (the two edges of a painted line lie within a pixel) can all be
// reached; the first is nearest_segment's.
std::vector<std::size_t> segments_under(std::span<const Segment> segments, const ViewTransform& view, Vec2 cursor,
                                        float max_distance_px);
// The same into `out` (cleared first): the studio hovers every frame and reuses one buffer, so
// hovering allocates nothing once the buffer has grown.
void segments_under(std::span<const Segment> segments, const ViewTransform& view, Vec2 cursor, float max_distance_px,
                    std::vector<std::size_t>& out);

// Indices (ascending) of the segments with any point inside `screen_rect` (either corner order).
std::vector<std::size_t> segments_in_rect(std::span<const Segment> segments, const ViewTransform& view,
                                          const Rect& screen_rect);

// True when the closed segment [a, b] has a point inside the closed rectangle.
bool segment_intersects_rect(Vec2 a, Vec2 b, const Rect& rect);

}  // namespace fieldlines::studio
