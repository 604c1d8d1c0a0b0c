// End to end on synthetic data: detect, autolabel from the exact ground truth, train the
// thresholds on one seed, and score detection + classification on images of another seed.
// ctest-label: slow

#include <gtest/gtest.h>

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/synth/gt_eval.hpp"
#include "fieldlines/data/labelled_set.hpp"
#include "fieldlines/synth/synth.hpp"
#include "fieldlines/train/training.hpp"

namespace fieldlines {
namespace {

synth::SynthParams ssl_artificial() {
  synth::SynthParams p;
  p.field.scene = synth::Scene::Ssl;
  p.conditions = {synth::Condition::Artificial};
  return p;
}

LabelledSet autolabelled(const synth::SynthParams& p, std::uint64_t seed, int n) {
  LineDetector detector;
  LabelledSet set;
  for (int i = 0; i < n; ++i) {
    const synth::SynthSample s = synth::generate(p, seed, i);
    std::vector<Segment> segments = detector.detect(s.bgr);
    label_from_truth(segments, s.truth);
    for (const Segment& seg : segments) set.add(s.truth.image, seg);
  }
  return set;
}

GtScore score(const synth::SynthParams& p, std::uint64_t seed, int n, const Thresholds& t) {
  LineDetector detector(DetectorParams{}, t);
  GtScore total;
  for (int i = 0; i < n; ++i) {
    const synth::SynthSample s = synth::generate(p, seed, i);
    total += GtEdges(s.truth).score(detector.detect(s.bgr));
  }
  return total;
}

TEST(SynthEndToEnd, ThresholdsTrainedOnOneSeedGeneraliseToAnother) {
  const synth::SynthParams p = ssl_artificial();
  const LabelledSet train_set = autolabelled(p, 101, 40);
  ASSERT_GT(train_set.count(Label::Marking), 50u);
  ASSERT_GT(train_set.count(Label::Boundary), 10u);
  ASSERT_GT(train_set.count(Label::None), 50u);
  // Marking thresholds, trained for precision first (F-beta, beta 0.5): on a robot a false line
  // misleads localisation more than a missed one, and the scene holds white-over-black wall
  // tops whose colour transition sits only ~10 degrees from the carpet-to-paint one.
  TrainParams tp;
  tp.target = TrainClass::Marking;
  tp.objective = parse_objective("fbeta:0.5");
  const TrainResult trained = train(train_set.segments, Thresholds{}, tp);

  const GtScore before = score(p, 202, 40, Thresholds{});
  const GtScore after = score(p, 202, 40, trained.thresholds);
  std::printf("defaults: marking P %.3f R %.3f, boundary P %.3f R %.3f\n", before.marking.precision(),
              before.marking.recall(), before.boundary.precision(), before.boundary.recall());
  std::printf("trained:  marking P %.3f R %.3f, boundary P %.3f R %.3f\n", after.marking.precision(),
              after.marking.recall(), after.boundary.precision(), after.boundary.recall());
  EXPECT_GE(after.marking.precision(), 0.95);
  EXPECT_GE(after.marking.recall(), 0.80);
  EXPECT_GT(after.marking.predicted, 50);  // enough segments for the ratios to mean something
}

}  // namespace
}  // namespace fieldlines
