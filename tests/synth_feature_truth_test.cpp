// The junctions and the centre circle a synthetic frame shows (feature_truth.hpp), and their
// scores: the truth scores perfectly against itself, a junction 7 px off or of the wrong type
// does not count, and the circle's ellipse is where its centreline is drawn.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "fieldlines/synth/feature_truth.hpp"
#include "fieldlines/synth/synth.hpp"

namespace fieldlines::synth {
namespace {

constexpr float kTwoPi = 2 * std::numbers::pi_v<float>;

// Twelve Kid frames, rendered once for every test.
const std::vector<GroundTruth>& kid_frames() {
  static const std::vector<GroundTruth> frames = [] {
    SynthParams p;
    p.field.scene = Scene::Kid;
    std::vector<GroundTruth> out;
    for (int i = 0; i < 12; ++i) out.push_back(generate(p, 1, i).truth);
    return out;
  }();
  return frames;
}

FieldFeatures as_detected(const FeatureTruth& t) {
  FieldFeatures f;
  f.intersections = t.intersections;
  // An ellipse where none of the circle shows is a wrong one.
  if (t.circle && t.circle->visible_share > 0) f.ellipses.push_back(t.circle->ellipse);
  return f;
}

TEST(FeatureTruth, JunctionsAreWellFormedAndScorePerfectlyAgainstThemselves) {
  long junctions = 0, circles = 0;
  for (const GroundTruth& truth : kid_frames()) {
    const FeatureTruth t = feature_truth(truth);
    for (const Intersection& j : t.intersections) {
      EXPECT_EQ(j.num_rays, j.type == JunctionType::L ? 2 : (j.type == JunctionType::T ? 3 : 4));
      for (int k = 0; k < j.num_rays; ++k) {
        EXPECT_GE(j.heading_rays[k], 0.f);
        EXPECT_LT(j.heading_rays[k], kTwoPi);
        if (k > 0) {
          EXPECT_LT(j.heading_rays[k - 1], j.heading_rays[k]);
        }
      }
      EXPECT_GE(j.x, -0.5f);
      EXPECT_LT(j.x, truth.intrinsics.width - 0.5f);
    }
    const FeatureScore s = score_features(t, as_detected(t));
    EXPECT_EQ(s.matched, s.truth);
    EXPECT_EQ(s.type_correct, s.truth);
    EXPECT_EQ(s.detected, s.truth);
    EXPECT_EQ(s.circles_found, s.circles);
    EXPECT_EQ(s.ellipses_wrong, 0);
    junctions += s.truth, circles += s.circles;
  }
  EXPECT_GT(junctions, 5) << "the frames must show junctions";
  EXPECT_GT(circles, 0) << "and a centre circle";
}

TEST(FeatureTruth, OffByMoreThanSixPixelsOrOfAnotherTypeIsWrong) {
  for (const GroundTruth& truth : kid_frames()) {
    const FeatureTruth t = feature_truth(truth);
    if (t.intersections.empty()) continue;
    FeatureTruth one = t;
    one.intersections.resize(1);
    one.ignored.clear();
    FieldFeatures d;
    Intersection moved = one.intersections[0];
    moved.x += 7;
    d.intersections = {moved};
    const FeatureScore off = score_features(one, d);
    EXPECT_EQ(off.matched, 0);
    EXPECT_EQ(off.detected, 1);
    moved.x -= 4;  // 3 px off: found
    moved.type = moved.type == JunctionType::L ? JunctionType::T : JunctionType::L;
    d.intersections = {moved};
    const FeatureScore wrong_type = score_features(one, d);
    EXPECT_EQ(wrong_type.matched, 1);
    EXPECT_EQ(wrong_type.type_correct, 0);
    return;
  }
  FAIL() << "no frame with a junction";
}

TEST(FeatureTruth, TheCircleIsWhereItsPaintIs) {
  int checked = 0;
  for (const GroundTruth& truth : kid_frames()) {
    const FeatureTruth t = feature_truth(truth);
    if (!t.circle || t.circle->visible_share < 0.3f) continue;
    // Every visible point of the truth's "centre circle" polylines lies on the ellipse.
    const MarkingEllipse& e = t.circle->ellipse;
    const float a = e.width / 2, b = e.height / 2, th = e.angle_deg * std::numbers::pi_v<float> / 180;
    for (const TruthFeature& f : truth.features) {
      if (f.name != "centre circle") continue;
      for (const TruthPoint& p : f.points) {
        const float dx = p.x - e.cx, dy = p.y - e.cy;
        const float u = (dx * std::cos(th) + dy * std::sin(th)) / a, v = (-dx * std::sin(th) + dy * std::cos(th)) / b;
        EXPECT_NEAR(std::hypot(u, v), 1.f, 0.05f) << p.x << ", " << p.y;
      }
    }
    FieldFeatures far;
    far.ellipses = {e};
    far.ellipses[0].cx += 0.11f * std::sqrt(a * b);  // just over a tenth of the radius off
    EXPECT_EQ(score_features(t, far).circles_found, 0);
    ++checked;
  }
  EXPECT_GT(checked, 0) << "the frames must show a centre circle";
}

}  // namespace
}  // namespace fieldlines::synth
