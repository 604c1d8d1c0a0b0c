// What the detector lets a segment be (gui/model/proposal_gate.hpp): the stripes check and the
// field boundary gate as the review's proposals apply them.
#include <gtest/gtest.h>

#include <vector>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/train/calibrate.hpp"
#include "gui/model/proposal_gate.hpp"
#include "tests/known_features.hpp"

namespace fl = fieldlines;
using fl::Label;
using fl::studio::ProposalGate;
using fl::studio::StripeVerdict;

namespace {

// An unlabelled edge from green towards white paint, `contrast` strong, `angle_deg` off the
// marking's colour transition.
fl::Segment edge_at(double contrast, double angle_deg) {
  return fl::test::segment_with(fl::test::marking_gradient(contrast, angle_deg), 100, Label::Unlabelled);
}

// A marking class of white on green within 25 degrees (grey lies at 35.26).
fl::Thresholds box_within_25_degrees() {
  fl::Thresholds t;
  t.marking.thresholds = {10, 25, 20};
  return t;
}

fl::Segment at_row(float y) {
  fl::Segment s = edge_at(60, 10);
  s.y0 = s.y1 = y;
  return s;
}

fl::FieldBoundary flat_boundary(float y) {
  fl::FieldBoundary b;
  b.points = {{0, y}, {640, y}};
  b.image_height = 480;
  return b;
}

TEST(ProposalGate, MarkingsOnlyAsStripesOnTheFieldBoundariesOnlyAlongIt) {
  // Above, along and below a boundary at row 100; each segment a stripe, unchecked, or not one.
  const std::vector<fl::Segment> segs = {at_row(20), at_row(100), at_row(300), at_row(300), at_row(300)};
  const std::vector<StripeVerdict> verdicts = {StripeVerdict::Stripe, StripeVerdict::Stripe, StripeVerdict::Stripe,
                                               StripeVerdict::NotStripe, StripeVerdict::Unchecked};
  const ProposalGate g = ProposalGate::of(segs, flat_boundary(100), verdicts);
  ASSERT_TRUE(g.covers(5));
  EXPECT_EQ(g.may_mark, (std::vector<std::uint8_t>{0, 1, 1, 0, 1}));
  EXPECT_EQ(g.stripe, (std::vector<std::uint8_t>{0, 1, 1, 0, 0}));
  EXPECT_EQ(g.may_bound, (std::vector<std::uint8_t>{0, 1, 0, 0, 0}));
  EXPECT_EQ(g.apply(0, Label::Marking), Label::None);
  EXPECT_EQ(g.apply(2, Label::Marking), Label::Marking);
  EXPECT_EQ(g.apply(2, Label::Boundary), Label::None);
  EXPECT_EQ(g.apply(1, Label::Boundary), Label::Boundary);
  EXPECT_EQ(g.apply(3, Label::Marking), Label::None);
  EXPECT_EQ(g.apply(4, Label::Marking), Label::Marking);
  // No field in view: nothing is gated by the boundary; no verdicts: nothing by the stripes.
  const ProposalGate open = ProposalGate::of(segs, {}, {});
  EXPECT_EQ(open.may_mark, (std::vector<std::uint8_t>(5, 1)));
  EXPECT_EQ(open.may_bound, (std::vector<std::uint8_t>(5, 1)));
  EXPECT_EQ(open.stripe, (std::vector<std::uint8_t>(5, 0)));
  // A gate of other segments (or none) changes nothing.
  EXPECT_FALSE(g.covers(4));
  EXPECT_EQ(ProposalGate{}.apply(0, Label::Marking), Label::Marking);
}

TEST(ProposalGate, AStripeWhoseColoursLeanToPaintIsAMarkingOutsideTheBox) {
  fl::Thresholds t = box_within_25_degrees();
  const fl::Segment paint = edge_at(60, 30);
  const fl::Segment grey = edge_at(60, 34.8);
  const fl::Segment faint = edge_at(5, 20);
  ASSERT_EQ(fl::classify(paint, t), Label::None);
  const std::vector<fl::Segment> segs = {paint, paint, grey, faint};
  const std::vector<StripeVerdict> verdicts = {StripeVerdict::Stripe, StripeVerdict::Unchecked, StripeVerdict::Stripe,
                                               StripeVerdict::Stripe};
  const ProposalGate g = ProposalGate::of(segs, {}, verdicts);
  EXPECT_EQ(g.propose(0, paint, t), Label::Marking);  // a stripe at 30 degrees: paint
  EXPECT_EQ(g.propose(1, paint, t), Label::None);     // unchecked: the box alone decides
  EXPECT_EQ(g.propose(2, grey, t), Label::None);      // within a degree of grey: no colour to go by
  EXPECT_EQ(g.propose(3, faint, t), Label::None);     // too faint for the box's contrast
  // The box's own members stay markings; a class switched off is never proposed.
  const fl::Segment inside = edge_at(60, 10);
  EXPECT_EQ(g.propose(0, inside, t), Label::Marking);
  t.marking.thresholds = fl::disabled_class();
  EXPECT_EQ(g.propose(0, paint, t), Label::None);
}

TEST(ProposalGate, AThinLineIsProposedAsPaintButLeftOutOfTheMarkingCandidates) {
  // A line too thin for the robot's check (StripeVerdict::ThinLine) below a boundary at row 100,
  // one above it, and an edge that is no stripe even with thin lines accepted.
  fl::Thresholds t = box_within_25_degrees();
  const fl::Segment inside = edge_at(60, 10);
  const fl::Segment leaning = edge_at(60, 30);
  const fl::Segment grey = edge_at(60, 34.8);
  const std::vector<fl::Segment> segs = {at_row(300), at_row(20), at_row(300)};
  const std::vector<StripeVerdict> verdicts = {StripeVerdict::ThinLine, StripeVerdict::ThinLine,
                                               StripeVerdict::NotStripe};
  const ProposalGate g = ProposalGate::of(segs, flat_boundary(100), verdicts);
  EXPECT_EQ(g.thin_line, (std::vector<std::uint8_t>{1, 0, 0}));
  EXPECT_EQ(g.may_mark, (std::vector<std::uint8_t>{0, 0, 0})) << "the detector drops it: no candidate to train on";
  EXPECT_EQ(g.stripe, (std::vector<std::uint8_t>{0, 0, 0}));
  // The thin line's proposal rests on its colours; the others are none whatever they are.
  EXPECT_FALSE(g.decided(0));
  EXPECT_TRUE(g.decided(1));
  EXPECT_TRUE(g.decided(2));
  EXPECT_EQ(g.propose(0, inside, t), Label::Marking);   // the box's colours on a thin line: paint
  EXPECT_EQ(g.propose(0, leaning, t), Label::Marking);  // leaning to paint, as a stripe would
  EXPECT_EQ(g.propose(0, grey, t), Label::None);        // grey: no colour to go by
  EXPECT_EQ(g.propose(1, inside, t), Label::None);      // above the field boundary
  EXPECT_EQ(g.propose(2, inside, t), Label::None);      // no stripe however thin
  t.marking.thresholds = fl::disabled_class();
  EXPECT_EQ(g.propose(0, inside, t), Label::None);      // a class switched off stays off
}

}  // namespace
