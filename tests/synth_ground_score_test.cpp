// The features scored on the ground (ground_score.hpp): the truth through its own camera scores
// no error; through a camera a degree off, the junctions' error is a share of their distance
// that grows with it, and the circle's centre moves.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "fieldlines/synth/camera.hpp"
#include "fieldlines/synth/feature_truth.hpp"
#include "fieldlines/synth/ground_score.hpp"
#include "fieldlines/synth/synth.hpp"

namespace fieldlines::synth {
namespace {

TEST(GroundScore, TheTruthScoresNoErrorAndAPitchOffByADegreeDoes) {
  SynthParams p;
  p.field.scene = Scene::Kid;
  GroundScore exact, off;
  for (int i = 0; i < 16; ++i) {
    const GroundTruth truth = generate(p, 1, i).truth;
    const FeatureTruth t = feature_truth(truth);
    FieldFeatures detected;
    detected.intersections = t.intersections;
    if (t.circle) detected.ellipses.push_back(t.circle->ellipse);
    const GroundCamera camera = to_ground_camera(truth.intrinsics, truth.pose);
    GroundCamera tilted = camera;
    tilted.pitch_rad += std::numbers::pi / 180;
    for (const auto& [given, score] : {std::pair{camera, &exact}, std::pair{tilted, &off}}) {
      GroundFeatures ground;
      project_features(detected, given, {}, ground);
      *score += score_ground(t, detected, ground, given, camera);
    }
  }
  ASSERT_GT(exact.junction_error_share.size(), 3u) << "the frames must show junctions";
  ASSERT_GT(exact.near_circles, 0) << "and a centre circle within 4 m";
  EXPECT_EQ(exact.junction_error_share.size(), off.junction_error_share.size());
  for (const double e : exact.junction_error_share) EXPECT_LT(e, 1e-4);
  for (const double e : exact.circle_error_m) EXPECT_LT(e, 0.005);
  // A degree of pitch moves a point at distance d about d^2 / h per radian: far ones more.
  for (std::size_t k = 0; k < off.junction_error_share.size(); ++k) EXPECT_GT(off.junction_error_share[k], 0.005);
  EXPECT_GT(*std::max_element(off.circle_error_m.begin(), off.circle_error_m.end()), 0.02);
}

}  // namespace
}  // namespace fieldlines::synth
