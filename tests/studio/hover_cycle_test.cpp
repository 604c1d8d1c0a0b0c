// Overlapping segments under the cursor: Space cycles the hovered one (wrapping), a new set of
// candidates starts from the nearest, and a label moves the hover to the next unlabelled one.
#include <gtest/gtest.h>

#include <vector>

#include "gui/model/hover_cycle.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;
using fieldlines::Segment;
using Under = std::vector<std::size_t>;

namespace {
std::vector<Segment> unlabelled(std::size_t n) {
  std::vector<Segment> out(n);
  for (Segment& s : out) s.label = Label::Unlabelled;  // a Segment defaults to None
  return out;
}
}  // namespace

TEST(HoverCycle, TheNearestIsHoveredAndSpaceCyclesAndWraps) {
  const auto segs = unlabelled(6);
  fs::HoverCycle cycle;
  EXPECT_FALSE(cycle.update(0, {}, segs).has_value());
  const Under under{4, 1, 5};  // nearest first
  EXPECT_EQ(cycle.update(0, under, segs), 4u);
  EXPECT_EQ(cycle.position(), 0u);
  cycle.next();
  EXPECT_EQ(cycle.update(0, under, segs), 1u);
  EXPECT_EQ(cycle.position(), 1u);
  cycle.next();
  EXPECT_EQ(cycle.update(0, under, segs), 5u);
  cycle.next();
  EXPECT_EQ(cycle.update(0, under, segs), 4u);  // wrapped
  // Two presses before the next frame move twice.
  cycle.next();
  cycle.next();
  EXPECT_EQ(cycle.update(0, under, segs), 5u);
  EXPECT_EQ(cycle.position(), 2u);
  EXPECT_EQ(cycle.candidates().size(), 3u);
}

TEST(HoverCycle, TheChoiceHoldsWhileTheSetIsTheSameAndResetsOnANewOne) {
  const auto segs = unlabelled(6);
  fs::HoverCycle cycle;
  cycle.update(0, Under{2, 3}, segs);
  cycle.next();
  EXPECT_EQ(cycle.update(0, Under{2, 3}, segs), 3u);
  // The pointer moved within the same two: their order flips, the chosen one stays.
  EXPECT_EQ(cycle.update(0, Under{3, 2}, segs), 3u);
  EXPECT_EQ(cycle.position(), 0u);
  // A different set: back to its nearest.
  EXPECT_EQ(cycle.update(0, Under{2, 3, 4}, segs), 2u);
  cycle.next();
  EXPECT_EQ(cycle.update(0, Under{2, 3, 4}, segs), 3u);
  EXPECT_FALSE(cycle.update(0, {}, segs).has_value());  // off every segment
  EXPECT_EQ(cycle.update(0, Under{2, 3, 4}, segs), 2u);  // and back: starts again
  cycle.next();
  EXPECT_EQ(cycle.update(0, Under{2, 3, 4}, segs), 3u);
  EXPECT_EQ(cycle.update(1, Under{2, 3, 4}, segs), 2u);  // same indices on another image
  // One segment, or none: Space does nothing.
  EXPECT_EQ(cycle.update(1, Under{5}, segs), 5u);
  cycle.next();
  EXPECT_EQ(cycle.update(1, Under{5}, segs), 5u);
  // Indices past the image's segments (re-detected) are dropped.
  EXPECT_EQ(cycle.update(1, Under{9, 5}, segs), 5u);
}

TEST(HoverCycle, ALabelMovesTheHoverToTheNextUnlabelledSegmentUnderTheCursor) {
  auto segs = unlabelled(4);
  fs::HoverCycle cycle;
  const Under under{1, 2, 3};
  ASSERT_EQ(cycle.update(0, under, segs), 1u);
  segs[1].label = Label::Marking;  // M on the hovered one
  EXPECT_EQ(cycle.update(0, under, segs), 2u);
  EXPECT_EQ(cycle.update(0, under, segs), 2u);  // and it stays there
  segs[3].label = Label::None;                  // labelled elsewhere (a rectangle): no move
  EXPECT_EQ(cycle.update(0, under, segs), 2u);
  segs[2].label = Label::Boundary;  // the next one; 3 is labelled already, 1 too: stay
  EXPECT_EQ(cycle.update(0, under, segs), 2u);
  segs[2].label = Label::Marking;  // correcting the hovered one keeps it hovered
  EXPECT_EQ(cycle.update(0, under, segs), 2u);
  segs[1].label = Label::Unlabelled;  // 1 is free again, but
  segs[2].label = Label::Unlabelled;  // clearing the hovered one (C, undo) keeps it hovered
  EXPECT_EQ(cycle.update(0, under, segs), 2u);
  segs[2].label = Label::None;  // labelled again: on to 1, the only unlabelled one, wrapping
  EXPECT_EQ(cycle.update(0, under, segs), 1u);
  // Cycling to a segment with another label is not mistaken for a label change.
  segs = unlabelled(4);
  segs[2].label = Label::None;
  fs::HoverCycle fresh;
  ASSERT_EQ(fresh.update(0, under, segs), 1u);
  fresh.next();
  EXPECT_EQ(fresh.update(0, under, segs), 2u);
  EXPECT_EQ(fresh.update(0, under, segs), 2u);
  // The next unlabelled one in cycling order wraps past the end.
  segs = unlabelled(4);
  fs::HoverCycle wrap;
  wrap.update(0, under, segs);
  wrap.next();
  wrap.next();
  ASSERT_EQ(wrap.update(0, under, segs), 3u);
  segs[3].label = Label::Marking;
  EXPECT_EQ(wrap.update(0, under, segs), 1u);
}
