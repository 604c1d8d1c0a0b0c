#include <gtest/gtest.h>

#include <vector>

#include "gui/model/hit_test.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Segment;

namespace {
Segment seg(float x0, float y0, float x1, float y1) {
  Segment s;
  s.x0 = x0, s.y0 = y0, s.x1 = x1, s.y1 = y1;
  return s;
}
}  // namespace

TEST(HitTest, DistanceToSegmentHandlesInteriorEndsAndPoints) {
  EXPECT_FLOAT_EQ(fs::distance_to_segment({5, 3}, {0, 0}, {10, 0}), 3);
  EXPECT_FLOAT_EQ(fs::distance_to_segment({13, 4}, {0, 0}, {10, 0}), 5);  // past the end
  EXPECT_FLOAT_EQ(fs::distance_to_segment({3, 4}, {0, 0}, {0, 0}), 5);    // degenerate
}

TEST(HitTest, PicksTheNearestWithinTheRadius) {
  const std::vector<Segment> segs{seg(0, 10, 100, 10), seg(0, 20, 100, 20)};
  fs::ViewTransform view;  // scale 1, offset 0: pixel centres at +0.5
  EXPECT_EQ(fs::nearest_segment(segs, view, {50, 12}, 6), 0u);
  EXPECT_EQ(fs::nearest_segment(segs, view, {50, 18}, 6), 1u);
  EXPECT_FALSE(fs::nearest_segment(segs, view, {50, 40}, 6).has_value());
  EXPECT_FALSE(fs::nearest_segment({}, view, {50, 40}, 6).has_value());
}

TEST(HitTest, TiesGoToTheLowerIndex) {
  const std::vector<Segment> segs{seg(0, 10, 100, 10), seg(0, 10, 100, 10)};
  fs::ViewTransform view;
  EXPECT_EQ(fs::nearest_segment(segs, view, {50, 10.5f}, 3), 0u);
}

TEST(HitTest, RadiusIsInScreenPixelsAtEveryZoom) {
  // Two segments 2 image pixels apart (half a screen pixel when zoomed out): the nearest wins.
  const std::vector<Segment> segs{seg(10, 10, 30, 10), seg(10, 12, 30, 12)};
  for (const float scale : {0.25f, 1.0f, 8.0f, 50.0f}) {
    fs::ViewTransform view;
    view.set(scale, {-3, 7});
    // The pointer exactly on each segment's drawn centre line picks that segment.
    for (std::size_t i = 0; i < segs.size(); ++i) {
      const fs::ScreenSegment s = fs::to_screen(segs[i], view);
      const fs::Vec2 mid = (s.a + s.b) * 0.5f;
      EXPECT_EQ(fs::nearest_segment(segs, view, mid, 4), i) << "scale " << scale;
    }
    // 3 screen pixels off the line: a hit; 5 pixels off: a miss, whatever the zoom.
    const fs::ScreenSegment s = fs::to_screen(segs[0], view);
    const fs::Vec2 mid = (s.a + s.b) * 0.5f;
    EXPECT_TRUE(fs::nearest_segment(std::span(segs).first(1), view, mid + fs::Vec2{0, -3}, 4).has_value());
    EXPECT_FALSE(fs::nearest_segment(std::span(segs).first(1), view, mid + fs::Vec2{0, -5}, 4).has_value());
  }
}

TEST(HitTest, PixelExactAtHighZoom) {
  // At 20x, a segment along row 5 is drawn through the centre of the pixel row: screen y 110.
  const std::vector<Segment> segs{seg(0, 5, 10, 5)};
  fs::ViewTransform view;
  view.set(20, {0, 0});
  EXPECT_TRUE(fs::nearest_segment(segs, view, {100, 110 + 1.99f}, 2).has_value());
  EXPECT_FALSE(fs::nearest_segment(segs, view, {100, 110 + 2.01f}, 2).has_value());
  EXPECT_FALSE(fs::nearest_segment(segs, view, {100, 100}, 2).has_value());  // the pixel's top edge
}

TEST(HitTest, RectangleSelectsTouchingSegments) {
  const std::vector<Segment> segs{
      seg(10, 10, 20, 10),    // fully inside
      seg(0, 30, 100, 30),    // crosses the rectangle without an endpoint inside
      seg(200, 200, 300, 300),// far away
      seg(0, 0, 5, 60),       // passes left of the rectangle
  };
  fs::ViewTransform view;
  const fs::Rect drag{{50, 60}, {8, 5}};  // dragged bottom-right to top-left
  EXPECT_EQ(fs::segments_in_rect(segs, view, drag), (std::vector<std::size_t>{0, 1}));
}

TEST(HitTest, SegmentRectIntersectionEdgeCases) {
  const fs::Rect r{{0, 0}, {10, 10}};
  EXPECT_TRUE(fs::segment_intersects_rect({-5, 5}, {15, 5}, r));   // horizontal through
  EXPECT_FALSE(fs::segment_intersects_rect({-5, 11}, {15, 11}, r)); // horizontal below
  EXPECT_TRUE(fs::segment_intersects_rect({5, 5}, {5, 5}, r));     // a point inside
  EXPECT_TRUE(fs::segment_intersects_rect({-1, 12}, {12, -1}, r));   // diagonal through
  EXPECT_FALSE(fs::segment_intersects_rect({-5, 4}, {4, -5}, r));   // cuts past the corner
  EXPECT_TRUE(fs::segment_intersects_rect({10, 10}, {20, 20}, r));  // touches the corner
}

TEST(HitTest, SegmentsUnderListsEveryOverlappingSegmentNearestFirst) {
  // The two edges of a painted line half a pixel apart, another line 5 px away, one far off.
  const std::vector<Segment> segs{seg(0, 20, 100, 20), seg(0, 10, 100, 10), seg(0, 10.5f, 100, 10.5f),
                                  seg(0, 60, 100, 60)};
  fs::ViewTransform view;
  view.set(2, {0, 0});  // 2 screen px per image px: the edges are 1 screen pixel apart
  const fs::Vec2 on_second = (fs::to_screen(segs[2], view).a + fs::to_screen(segs[2], view).b) * 0.5f;
  EXPECT_EQ(fs::segments_under(segs, view, on_second, 8), (std::vector<std::size_t>{2, 1}));
  EXPECT_EQ(fs::segments_under(segs, view, on_second, 30), (std::vector<std::size_t>{2, 1, 0}));
  EXPECT_TRUE(fs::segments_under(segs, view, {50, 300}, 8).empty());
  // Its first is always nearest_segment's, ties included (identical segments: lower index first).
  const std::vector<Segment> twins{seg(0, 10, 100, 10), seg(0, 10, 100, 10)};
  EXPECT_EQ(fs::segments_under(twins, view, on_second, 8), (std::vector<std::size_t>{0, 1}));
  for (const fs::Vec2 p : {on_second, fs::Vec2{40, 30}, fs::Vec2{100, 50}}) {
    const auto all = fs::segments_under(segs, view, p, 12);
    const auto one = fs::nearest_segment(segs, view, p, 12);
    ASSERT_EQ(all.empty(), !one.has_value());
    if (one) {
      EXPECT_EQ(all.front(), *one);
    }
  }
}

TEST(HitTest, SegmentsUnderIntoABufferReusesItsStorage) {
  const std::vector<Segment> segs{seg(0, 20, 100, 20), seg(0, 10, 100, 10), seg(0, 10.5f, 100, 10.5f)};
  fs::ViewTransform view;
  view.set(2, {0, 0});
  const fs::Vec2 on_second = (fs::to_screen(segs[2], view).a + fs::to_screen(segs[2], view).b) * 0.5f;
  std::vector<std::size_t> under{7, 7, 7, 7};  // stale content from an earlier frame is cleared
  fs::segments_under(segs, view, on_second, 30, under);
  EXPECT_EQ(under, fs::segments_under(segs, view, on_second, 30));
  // Later frames (the studio calls it every frame while hovering) write into the same storage.
  const std::size_t* storage = under.data();
  for (const fs::Vec2 p : {on_second, fs::Vec2{40, 30}, fs::Vec2{100, 50}, fs::Vec2{50, 300}}) {
    fs::segments_under(segs, view, p, 30, under);
    EXPECT_EQ(under, fs::segments_under(segs, view, p, 30));
    EXPECT_EQ(under.data(), storage);
  }
}
