// Scoring against ground truth: truth labels of segments, precision and edge-length recall.
#include <gtest/gtest.h>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/synth/gt_eval.hpp"

namespace fieldlines {
namespace {

synth::GroundTruth truth_with(float width) {
  synth::GroundTruth t;
  synth::TruthFeature line;
  line.label = Label::Marking;
  line.name = "horizontal line";
  line.points = {{100, 200, width}, {300, 200, width}};  // 200 px long at y = 200
  synth::TruthFeature wall;
  wall.label = Label::Boundary;
  wall.name = "wall";
  wall.points = {{0, 50, 0}, {400, 50, 0}};
  t.features = {line, wall};
  return t;
}

Segment seg(float x0, float y0, float x1, float y1, Label label = Label::Marking) {
  Segment s;
  s.x0 = x0, s.y0 = y0, s.x1 = x1, s.y1 = y1, s.label = label;
  return s;
}

TEST(GtEval, TruthLabelFollowsTheNearestParallelEdge) {
  const GtEdges edges(truth_with(10));
  EXPECT_EQ(edges.truth_label(seg(120, 195, 280, 195)), Label::Marking);   // upper edge
  EXPECT_EQ(edges.truth_label(seg(120, 205.5f, 280, 205.5f)), Label::Marking);  // lower edge, 0.5 px off
  EXPECT_EQ(edges.truth_label(seg(120, 200, 280, 200)), Label::None);      // centre of a 10 px line
  EXPECT_EQ(edges.truth_label(seg(200, 150, 200, 250)), Label::None);      // crossing it
  EXPECT_EQ(edges.truth_label(seg(10, 51, 390, 49)), Label::Boundary);
  EXPECT_EQ(edges.truth_label(seg(250, 195, 450, 195)), Label::None);      // only 25% on the line
}

TEST(GtEval, WhenAFarLineAndTheWallFootNearlyMeetTheNearerWins) {
  synth::GroundTruth t = truth_with(1);
  t.features[1].points = {{0, 202.5f, 0}, {400, 202.5f, 0}};  // wall foot 2.5 px below the line
  const GtEdges edges(t);
  EXPECT_EQ(edges.truth_label(seg(120, 200, 280, 200)), Label::Marking);
  EXPECT_EQ(edges.truth_label(seg(120, 202.4f, 280, 202.4f)), Label::Boundary);
}

TEST(GtEval, WideLinesNeedBothEdgesForFullRecall) {
  const GtEdges edges(truth_with(10));
  const std::vector<Segment> one{seg(100, 195, 300, 195)};
  const GtScore a = edges.score(one);
  EXPECT_NEAR(a.marking.recall(), 0.5, 0.01);
  EXPECT_EQ(a.marking.predicted, 1);
  EXPECT_EQ(a.marking.correct, 1);
  const std::vector<Segment> both{seg(100, 195, 300, 195), seg(300, 205, 100, 205)};
  EXPECT_NEAR(edges.score(both).marking.recall(), 1.0, 0.01);
}

TEST(GtEval, AThinLineIsCoveredByOneCentredSegment) {
  const GtEdges edges(truth_with(2));
  const std::vector<Segment> one{seg(100, 200, 200, 200)};
  const GtScore s = edges.score(one);
  EXPECT_NEAR(s.marking.recall(), 0.5, 0.02);  // half the length (+ the match distance), both edges
  EXPECT_DOUBLE_EQ(s.marking.precision(), 1.0);
}

TEST(GtEval, WrongLabelsCountAgainstPrecisionAndDoNotCover) {
  const GtEdges edges(truth_with(2));
  const std::vector<Segment> wrong{seg(100, 200, 300, 200, Label::Boundary), seg(0, 50, 400, 50, Label::Marking)};
  const GtScore s = edges.score(wrong);
  EXPECT_EQ(s.boundary.predicted, 1);
  EXPECT_EQ(s.boundary.correct, 0);
  EXPECT_EQ(s.marking.correct, 0);
  EXPECT_DOUBLE_EQ(s.marking.recall(), 0.0);
  EXPECT_DOUBLE_EQ(s.boundary.recall(), 0.0);
  EXPECT_NEAR(s.boundary.visible_px, 400, 1e-3);
}

TEST(GtEval, OnlyTrueMembersCoverALine) {
  const GtEdges edges(truth_with(10));
  // Predicted marking along the upper edge but mostly beyond the line: its truth is none (a false
  // positive), so the part of it on the line covers nothing.
  const Segment overhang = seg(250, 195, 450, 195);
  ASSERT_EQ(edges.truth_label(overhang), Label::None);
  const GtScore s = edges.score(std::vector<Segment>{overhang});
  EXPECT_EQ(s.marking.predicted, 1);
  EXPECT_EQ(s.marking.correct, 0);
  EXPECT_DOUBLE_EQ(s.marking.recall(), 0.0);
  // The same place covered by a true member counts.
  EXPECT_NEAR(edges.score(std::vector<Segment>{seg(250, 195, 300, 195)}).marking.recall(), 0.125, 0.01);
}

TEST(GtEval, TooThinPartsAreNotVisible) {
  GtMatchParams p;
  p.min_width_px = 3;
  const GtEdges edges(truth_with(2), p);
  const GtScore s = edges.score(std::vector<Segment>{});
  EXPECT_DOUBLE_EQ(s.marking.visible_px, 0.0);
  EXPECT_DOUBLE_EQ(s.marking.recall(), 0.0);
}

TEST(GtEval, LabelFromTruthRelabelsAndCounts) {
  std::vector<Segment> segs{seg(120, 199, 280, 199, Label::None), seg(0, 300, 50, 300, Label::Marking),
                            seg(5, 50, 300, 50, Label::None)};
  const auto counts = label_from_truth(segs, truth_with(2));
  EXPECT_EQ(segs[0].label, Label::Marking);
  EXPECT_EQ(segs[1].label, Label::None);
  EXPECT_EQ(segs[2].label, Label::Boundary);
  EXPECT_EQ(counts[0], 1);
  EXPECT_EQ(counts[1], 1);
  EXPECT_EQ(counts[2], 1);
}

TEST(GtEval, BadParamsThrow) {
  GtMatchParams p;
  p.max_distance_px = 0;
  EXPECT_THROW(GtEdges(truth_with(2), p), Error);
  p = GtMatchParams{};
  p.min_match = 1.5f;
  EXPECT_THROW(GtEdges(truth_with(2), p), Error);
}

}  // namespace
}  // namespace fieldlines
