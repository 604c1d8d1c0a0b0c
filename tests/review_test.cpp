// The review loop's core (fieldlines/train/review.hpp): where proposals come from, and the
// decision margin that orders segments uncertain-first.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/train/calibrate.hpp"
#include "fieldlines/train/review.hpp"
#include "known_features.hpp"

namespace fl = fieldlines;

namespace {

std::vector<fl::Segment> unlabelled(std::vector<fl::Segment> s) {
  for (fl::Segment& x : s) x.label = fl::Label::Unlabelled;
  return s;
}

TEST(Review, ProposalsComeFromCalibrationUntilAClassHasEnoughLabels) {
  const fl::test::KnownField k = fl::test::known_field(4);
  const std::vector<fl::Segment> all = unlabelled(k.segments);
  // No label at all: both classes label-free, equal to calibrating directly.
  const fl::ProposalThresholds none = fl::proposal_thresholds(all, {}, fl::Thresholds{});
  EXPECT_EQ(none.marking, fl::ProposalSource::LabelFree);
  EXPECT_EQ(none.boundary, fl::ProposalSource::LabelFree);
  EXPECT_EQ(none.thresholds, fl::calibrated_thresholds(fl::calibrate(all)));
  // 30 markings and 30 non-features labelled (no boundary): markings trained, boundary label-free.
  std::vector<fl::Segment> labelled(k.segments.begin(), k.segments.begin() + 30);
  labelled.insert(labelled.end(), k.segments.end() - 30, k.segments.end());
  const fl::ProposalThresholds some = fl::proposal_thresholds(all, labelled, fl::Thresholds{});
  EXPECT_EQ(some.marking, fl::ProposalSource::Trained);
  EXPECT_EQ(some.boundary, fl::ProposalSource::LabelFree);
  EXPECT_EQ(some.thresholds.boundary, none.thresholds.boundary);
  // The trained markings classify the labelled ones right.
  int right = 0;
  for (const fl::Segment& s : labelled) right += fl::classify(s, some.thresholds) == s.label;
  EXPECT_GE(right, 58);
  // Grey edges only: nothing to calibrate; the start thresholds stay, with the reasons.
  const std::vector<fl::Segment> grey(all.begin() + k.markings + k.boundaries, all.end());
  const fl::ProposalThresholds lost = fl::proposal_thresholds(grey, {}, fl::Thresholds{});
  EXPECT_EQ(lost.marking, fl::ProposalSource::Start);
  EXPECT_EQ(lost.thresholds.marking, fl::Thresholds{}.marking);
  EXPECT_NE(lost.note.find("marking"), std::string::npos) << lost.note;
  EXPECT_FALSE(lost.marking_refused.empty());
  // The boundary calibration refuses is disabled, as `fieldlines calibrate` writes it.
  EXPECT_EQ(lost.boundary, fl::ProposalSource::Disabled);
  EXPECT_EQ(lost.thresholds.boundary.thresholds, fl::disabled_class());
  EXPECT_FALSE(lost.boundary_refused.empty());
}

TEST(Review, AClassCalibrationRefusesIsTrainedFromAFewLabels) {
  const fl::test::KnownField k = fl::test::known_field(4);
  const std::vector<fl::Segment> all = unlabelled(k.segments);
  const std::vector<fl::Segment> grey(all.begin() + k.markings + k.boundaries, all.end());
  // Three markings and three non-features: too few to train a class calibration fits (10), enough
  // for one it refuses.
  std::vector<fl::Segment> labelled(k.segments.begin(), k.segments.begin() + 3);
  labelled.insert(labelled.end(), k.segments.end() - 3, k.segments.end());
  const fl::ProposalThresholds few = fl::proposal_thresholds(grey, labelled, fl::Thresholds{});
  EXPECT_EQ(few.marking, fl::ProposalSource::Trained);
  EXPECT_TRUE(few.marking_refused.empty());
  for (const fl::Segment& s : labelled) EXPECT_EQ(fl::classify(s, few.thresholds), s.label);
  EXPECT_EQ(fl::proposal_thresholds(all, labelled, fl::Thresholds{}).marking, fl::ProposalSource::LabelFree);
}

TEST(Review, AClassSwitchedOffStaysOff) {
  const fl::test::KnownField k = fl::test::known_field(4);
  fl::Thresholds start;
  start.boundary.thresholds = fl::disabled_class();
  // Enough boundary labels to train it: still off.
  const fl::ProposalThresholds made = fl::proposal_thresholds(unlabelled(k.segments), k.segments, start);
  EXPECT_EQ(made.boundary, fl::ProposalSource::Disabled);
  EXPECT_EQ(made.thresholds.boundary.thresholds, fl::disabled_class());
  EXPECT_TRUE(made.boundary_refused.empty());
  EXPECT_NE(made.marking, fl::ProposalSource::Disabled);
  EXPECT_EQ(fl::to_string(fl::ProposalSource::Disabled), "disabled");
}

TEST(Review, EachClassIsTrainedOnItsCandidatesAlone) {
  const fl::test::KnownField k = fl::test::known_field(4);
  const std::vector<fl::Segment> all = unlabelled(k.segments);
  // 30 markings and 30 non-features labelled, then 30 more nones with the markings' very colours:
  // what the stripes check refuses (a white wall's foot), labelled none after a proposal.
  std::vector<fl::Segment> labelled(k.segments.begin(), k.segments.begin() + 30);
  labelled.insert(labelled.end(), k.segments.end() - 30, k.segments.end());
  const std::size_t kept = labelled.size();
  for (std::size_t i = 0; i < 30; ++i) {
    fl::Segment copy = k.segments[i];
    copy.label = fl::Label::None;
    labelled.push_back(copy);
  }
  std::vector<std::uint8_t> may(labelled.size(), 1);
  std::fill(may.begin() + static_cast<std::ptrdiff_t>(kept), may.end(), 0);
  const fl::Calibration fit = fl::calibrate(all);
  const fl::ProposalThresholds gated =
      fl::proposal_thresholds(fit, labelled, fl::Thresholds{}, {}, {}, fl::LabelledCandidates{may, may});
  const fl::ProposalThresholds without_copies =
      fl::proposal_thresholds(fit, std::span(labelled).first(kept), fl::Thresholds{});
  const fl::ProposalThresholds ungated = fl::proposal_thresholds(fit, labelled, fl::Thresholds{});
  EXPECT_EQ(gated.marking, fl::ProposalSource::Trained);
  // The refused copies say nothing about the box: as though they were not labelled at all.
  EXPECT_EQ(gated.thresholds, without_copies.thresholds);
  // Counted as nones they pull the box off the markings.
  int gated_right = 0, ungated_right = 0;
  for (std::size_t i = 0; i < 30; ++i) {
    gated_right += fl::classify(k.segments[i], gated.thresholds) == fl::Label::Marking;
    ungated_right += fl::classify(k.segments[i], ungated.thresholds) == fl::Label::Marking;
  }
  EXPECT_GE(gated_right, 28);
  EXPECT_LT(ungated_right, gated_right);
  // A mismatched length is no candidates at all.
  const std::vector<std::uint8_t> short_list(3, 0);
  EXPECT_EQ(fl::proposal_thresholds(fit, labelled, fl::Thresholds{}, {}, {}, {short_list, short_list}).thresholds,
            ungated.thresholds);
}

TEST(Review, TheMarginIsZeroOnABoundaryAndGrowsAwayFromIt) {
  fl::Thresholds t;
  t.boundary.thresholds = {1000.f, 0.f, 100000.f};  // never a boundary: only the marking test matters
  t.marking.thresholds = {20.f, 30.f, 100.f};
  const auto features = [&](double angle, float length) {
    return fl::compute_features(fl::test::segment_with(fl::test::marking_gradient(100, angle), length, fl::Label::None), t);
  };
  const double inside = fl::decision_margin(features(20, 300), t);
  const double near = fl::decision_margin(features(29, 300), t);
  const double edge_length = fl::decision_margin(features(20, 100), t);
  const double outside = fl::decision_margin(features(40, 300), t);
  EXPECT_EQ(fl::classify(features(20, 300), t), fl::Label::Marking);
  EXPECT_EQ(fl::classify(features(40, 300), t), fl::Label::None);
  EXPECT_GT(inside, near);
  EXPECT_GT(near, 0);
  EXPECT_NEAR(near, 0.5, 0.01);         // 1 degree inside the 30-degree cut, 2 degrees per unit
  EXPECT_NEAR(edge_length, 0.0, 1e-6);  // exactly at min length
  EXPECT_NEAR(outside, 5.0, 0.01);      // 10 degrees outside
  EXPECT_GT(outside, near);
}

}  // namespace
