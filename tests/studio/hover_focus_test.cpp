// The segment a key chose (Tab) stays hovered while the pointer rests, whatever lies under it;
// a pointer that moves or clicks over another segment takes the hover back.
#include <gtest/gtest.h>

#include <optional>

#include "gui/model/hover_focus.hpp"

using fieldlines::studio::HoverFocus;

TEST(HoverFocus, WithoutAHeldSegmentThePointersPickIsHovered) {
  HoverFocus focus;
  EXPECT_EQ(focus.update(0, 10, 3, false), 3u);
  EXPECT_EQ(focus.update(0, 10, 4, true), 4u);
  EXPECT_FALSE(focus.update(0, 10, std::nullopt, true).has_value());
  EXPECT_FALSE(focus.held().has_value());
}

TEST(HoverFocus, AHeldSegmentSurvivesARestingPointerOverAnotherSegment) {
  HoverFocus focus;
  focus.hold(0, 7);
  // The view was re-centred: segment 2 now lies under the resting pointer, frame after frame.
  for (int frame = 0; frame < 5; ++frame) EXPECT_EQ(focus.update(0, 10, 2, false), 7u);
  // Moving over empty turf, or over the held segment itself, keeps it.
  EXPECT_EQ(focus.update(0, 10, std::nullopt, true), 7u);
  EXPECT_EQ(focus.update(0, 10, 7, true), 7u);
  EXPECT_EQ(focus.held(), 7u);
  // Moving (or pressing a button) over another segment hands the hover to the pointer.
  EXPECT_EQ(focus.update(0, 10, 2, true), 2u);
  EXPECT_FALSE(focus.held().has_value());
  EXPECT_EQ(focus.update(0, 10, 2, false), 2u);
}

TEST(HoverFocus, AnotherImageAReleaseOrAVanishedSegmentEndsTheHold) {
  HoverFocus focus;
  focus.hold(1, 5);
  EXPECT_EQ(focus.update(1, 10, std::nullopt, false), 5u);
  EXPECT_EQ(focus.update(2, 10, std::nullopt, false), std::nullopt);  // next image
  focus.hold(2, 5);
  EXPECT_EQ(focus.update(2, 4, 1, false), 1u);  // re-detected: only 4 segments left
  focus.hold(2, 3);
  focus.release();  // Space: back to the segments under the cursor
  EXPECT_EQ(focus.update(2, 4, 1, false), 1u);
  // A new hold replaces the old one.
  focus.hold(2, 0);
  focus.hold(2, 3);
  EXPECT_EQ(focus.update(2, 4, 1, false), 3u);
}
