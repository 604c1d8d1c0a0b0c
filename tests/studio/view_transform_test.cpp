#include <gtest/gtest.h>

#include "gui/model/view_transform.hpp"

namespace fs = fieldlines::studio;

TEST(ViewTransform, ImageToScreenRoundTripsAtAnyScale) {
  fs::ViewTransform view;
  for (const float scale : {0.1f, 1.0f, 3.7f, 40.0f}) {
    view.set(scale, {12.5f, -7.0f});
    const fs::Vec2 p{123.25f, 45.75f};
    const fs::Vec2 back = view.screen_to_image(view.image_to_screen(p));
    EXPECT_NEAR(back.x, p.x, 1e-3f);
    EXPECT_NEAR(back.y, p.y, 1e-3f);
  }
  view.set(2, {10, 20});
  EXPECT_EQ(view.image_to_screen({5, 6}), (fs::Vec2{20, 32}));
}

TEST(ViewTransform, ZoomKeepsThePointUnderTheCursor) {
  fs::ViewTransform view;
  view.set(1.5f, {30, 40});
  const fs::Vec2 cursor{400, 250};
  const fs::Vec2 before = view.screen_to_image(cursor);
  view.zoom_at(cursor, 1.25f);
  EXPECT_FLOAT_EQ(view.scale(), 1.5f * 1.25f);
  const fs::Vec2 after = view.screen_to_image(cursor);
  EXPECT_NEAR(after.x, before.x, 1e-3f);
  EXPECT_NEAR(after.y, before.y, 1e-3f);
  // A point elsewhere did move: zooming is not a no-op.
  EXPECT_NE(view.image_to_screen({0, 0}), (fs::Vec2{30, 40}));
}

TEST(ViewTransform, ZoomIsClampedAndIgnoresBadFactors) {
  fs::ViewTransform view({0.5f, 4.0f});
  view.zoom_at({0, 0}, 1000);
  EXPECT_FLOAT_EQ(view.scale(), 4.0f);
  view.zoom_at({0, 0}, 1e-6f);
  EXPECT_FLOAT_EQ(view.scale(), 0.5f);
  view.zoom_at({0, 0}, 0);
  view.zoom_at({0, 0}, -2);
  view.zoom_at({0, 0}, std::numeric_limits<float>::quiet_NaN());
  EXPECT_FLOAT_EQ(view.scale(), 0.5f);
}

TEST(ViewTransform, PanMovesByScreenPixels) {
  fs::ViewTransform view;
  view.set(3, {0, 0});
  view.pan({15, -4});
  EXPECT_EQ(view.offset(), (fs::Vec2{15, -4}));
  EXPECT_EQ(view.image_to_screen({1, 1}), (fs::Vec2{18, -1}));
}

TEST(ViewTransform, FitCentresTheWholeImage) {
  fs::ViewTransform view;
  // 640x480 into a 1000x500 viewport at (100, 50): height-limited.
  view.fit({640, 480}, {{100, 50}, {1100, 550}});
  EXPECT_FLOAT_EQ(view.scale(), 500.0f / 480.0f);
  const fs::Vec2 top_left = view.image_to_screen({0, 0});
  const fs::Vec2 bottom_right = view.image_to_screen({640, 480});
  EXPECT_NEAR(top_left.y, 50, 1e-3f);
  EXPECT_NEAR(bottom_right.y, 550, 1e-3f);
  EXPECT_NEAR((top_left.x + bottom_right.x) / 2, 600, 1e-3f);  // centred horizontally
  EXPECT_GE(top_left.x, 100);
  EXPECT_LE(bottom_right.x, 1100);
}

TEST(ViewTransform, FitIgnoresDegenerateInput) {
  fs::ViewTransform view;
  view.set(2, {5, 5});
  view.fit({0, 480}, {{0, 0}, {100, 100}});
  view.fit({640, 480}, {{0, 0}, {0, 100}});
  EXPECT_FLOAT_EQ(view.scale(), 2);
  EXPECT_EQ(view.offset(), (fs::Vec2{5, 5}));
}
