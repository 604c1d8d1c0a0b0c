// The field boundary and the stripes' centre lines of LineDetector's features against the exact
// truth of synthetic frames (feature_truth.hpp) the detector was not tuned on (seeds 4242 and
// 777, SSL and Kid, every light): the boundary within 4 px of the carpet's top on at least 95 %
// of the columns showing it, and the markings within half a line width + 1 px of a painted
// line's centre; the junctions meet their precision, recall and type targets. The truth itself
// is checked too: a boundary drawn from it scores perfectly, one shifted by 5 px scores nothing.
#include <vector>

#include <gtest/gtest.h>

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/synth/feature_truth.hpp"
#include "fieldlines/synth/synth.hpp"

namespace fieldlines::synth {
namespace {

struct Frame {
  Scene scene;
  SynthSample sample;
  FeatureTruth truth;
  FieldFeatures detected;
};

// Ten frames per scene and seed (each light twice), detected once with every feature stage on.
const std::vector<Frame>& held_out_frames() {
  static const std::vector<Frame> frames = [] {
    LineDetector detector(with_every_feature(DetectorParams{}));
    detector.set_find_field_boundary(true);
    std::vector<Frame> out;
    for (const Scene scene : {Scene::Ssl, Scene::Kid})
      for (const std::uint64_t seed : {4242u, 777u}) {
        SynthParams p;
        p.field.scene = scene;
        p.conditions.assign(all_conditions().begin(), all_conditions().end());
        for (int i = 0; i < 10; ++i) {
          SynthSample s = generate(p, seed, i);
          detector.detect(s.bgr);
          FeatureTruth t = feature_truth(s.truth, s.mask);
          out.push_back({scene, std::move(s), std::move(t), detector.features()});
        }
      }
    return out;
  }();
  return frames;
}

TEST(FeatureAccuracy, TheTruthsBoundaryScoresPerfectlyAndFivePixelsOffNothing) {
  for (const Frame& f : held_out_frames()) {
    FieldFeatures exact, off;
    for (std::size_t u = 0; u < f.truth.carpet_top.size(); ++u) {
      if (f.truth.carpet_top[u] < 0) continue;
      exact.field_boundary.points.push_back({float(u), f.truth.carpet_top[u]});
      off.field_boundary.points.push_back({float(u), f.truth.carpet_top[u] + 5});
    }
    const FeatureScore right = score_features(f.truth, exact), wrong = score_features(f.truth, off);
    EXPECT_EQ(right.boundary_right, right.boundary_columns);
    EXPECT_EQ(wrong.boundary_right, 0);
    EXPECT_EQ(score_features(f.truth, FieldFeatures{}).boundary_right, 0) << "no boundary: every column missed";
  }
}

TEST(FeatureAccuracy, TheFieldBoundaryIsWithinFourPixelsOnNinetyFivePercentOfColumns) {
  for (const Scene scene : {Scene::Ssl, Scene::Kid}) {
    FeatureScore s;
    for (const Frame& f : held_out_frames())
      if (f.scene == scene) s += score_features(f.truth, f.detected);
    ASSERT_GT(s.boundary_columns, 10000) << "the frames must show carpet";
    EXPECT_GE(s.boundary_share(), 0.95) << to_string(scene);
  }
}

TEST(FeatureAccuracy, MarkingsLieOnTheCentreLinesOfPaintedLines) {
  for (const Scene scene : {Scene::Ssl, Scene::Kid}) {
    FeatureScore s;
    for (const Frame& f : held_out_frames())
      if (f.scene == scene) s += score_features(f.sample.truth, f.truth, f.detected);
    ASSERT_GT(s.marking_px, 1000) << "the frames must show stripes";
    EXPECT_GE(s.marking_share(), 0.95) << to_string(scene);
  }
}

// The junction targets, both scenes pooled: precision 0.90, recall 0.70, type 0.90; with
// every stage on (the junctions take the circle's second drawing's pieces too) and with the
// circle off (the detector's own segments alone, whose chords of the circle must not meet).
void expect_junction_targets(const FeatureScore& s) {
  ASSERT_GE(s.truth, 15) << "the frames must show junctions";
  EXPECT_GE(s.precision(), 0.90) << s.matched << " of " << s.detected;
  EXPECT_GE(s.recall(), 0.70) << s.matched << " of " << s.truth;
  EXPECT_GE(s.type_accuracy(), 0.90) << s.type_correct << " of " << s.matched;
}

TEST(FeatureAccuracy, JunctionsMeetTheirTargetsWithAndWithoutTheCircle) {
  FeatureScore every_stage, without_circle;
  DetectorParams lines = with_every_feature(DetectorParams{});
  lines.centre_circle = false;
  LineDetector detector(lines);
  for (const Frame& f : held_out_frames()) {
    every_stage += score_features(f.truth, f.detected);
    detector.detect(f.sample.bgr);
    EXPECT_TRUE(detector.features().ellipses.empty());
    without_circle += score_features(f.truth, detector.features());
  }
  {
    SCOPED_TRACE("every stage");
    expect_junction_targets(every_stage);
  }
  SCOPED_TRACE("without the circle");
  expect_junction_targets(without_circle);
}

}  // namespace
}  // namespace fieldlines::synth
