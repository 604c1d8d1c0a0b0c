// The stripes' centre lines against truth lines (centre_line_score.hpp): a centre line counts
// anywhere on the paint give or take a pixel, only when parallel; thin truth counts for
// precision but not for recall.
#include <gtest/gtest.h>

#include "fieldlines/synth/centre_line_score.hpp"

namespace fieldlines::synth {
namespace {

TruthFeature line(float x0, float y0, float x1, float y1, float width) {
  TruthFeature f;
  f.label = Label::Marking;
  f.name = "line";
  f.points = {{x0, y0, width}, {x1, y1, width}};
  return f;
}

GroundTruth two_lines() {
  GroundTruth t;
  t.features = {line(10, 100, 210, 100, 4), line(10, 200, 110, 200, 20)};  // 200 + 100 px visible
  return t;
}

TEST(CentreLines, RecallIsTheDrawnCentresLengthNearAStripeAndPrecisionTheStripesOnALine) {
  const GroundTruth t = two_lines();
  // Half the thin line, on its centre; the wide one 8 px off its centre (inside its paint).
  const std::vector<Marking> found{{10, 100, 110, 100, 4}, {10, 208, 110, 208, 20}};
  const CentreLineScore s = score_centre_lines(t, found);
  EXPECT_NEAR(s.truth_px, 300, 1e-3);
  EXPECT_NEAR(s.covered_px, 203, 1e-3) << "100 + the 3 px its end reaches, and 100";
  EXPECT_NEAR(s.recall(), 203.0 / 300, 1e-6);
  EXPECT_NEAR(s.detected_px, 200, 1e-3);
  EXPECT_NEAR(s.precision(), 1.0, 1e-6);
}

TEST(CentreLines, APointCountsWithinHalfTheWidthAndAPixelAndOnlyWhenParallel) {
  const GroundTruth t = two_lines();
  const auto covered = [&](const Marking& m) { return score_centre_lines(t, std::vector<Marking>{m}).covered_px; };
  EXPECT_NEAR(covered({10, 102.9f, 210, 102.9f, 2}), 200, 1e-3) << "within 2 + 1 px";
  EXPECT_NEAR(covered({10, 103.2f, 210, 103.2f, 2}), 0, 1e-3) << "beyond";
  EXPECT_NEAR(covered({100, 60, 100, 140, 4}), 0, 1e-3) << "across the line";
  const CentreLineScore off = score_centre_lines(t, std::vector<Marking>{{10, 150, 210, 150, 4}});
  EXPECT_NEAR(off.precision(), 0, 1e-6);
  EXPECT_NEAR(off.detected_px, 200, 1e-3);
}

TEST(CentreLines, ThinTruthCountsForPrecisionOnlyAndNothingFoundIsZero) {
  GroundTruth t;
  t.features = {line(10, 100, 210, 100, 0.5f)};  // under min_width_px
  const CentreLineScore s = score_centre_lines(t, std::vector<Marking>{{10, 100, 210, 100, 1}});
  EXPECT_EQ(s.truth_px, 0);
  EXPECT_NEAR(s.precision(), 1.0, 1e-6);
  const CentreLineScore none = score_centre_lines(two_lines(), {});
  EXPECT_EQ(none.recall(), 0);
  EXPECT_EQ(none.precision(), 0);
  CentreLineScore sum = s;
  sum += none;
  EXPECT_NEAR(sum.truth_px, 300, 1e-3);
  EXPECT_NEAR(sum.on_line_px, 200, 1e-3);
}

}  // namespace
}  // namespace fieldlines::synth
