// The junctions and the centre circle a synthetic frame shows (feature_truth.hpp), and their
// scores: the truth scores perfectly against itself, a junction 7 px off or of the wrong type
// does not count, the circle's ellipse is where its centreline is drawn, and paint thinner than
// the minimum width shows no arm and no circle.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "fieldlines/synth/feature_truth.hpp"
#include "fieldlines/synth/synth.hpp"
#include "truth_distance.hpp"

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
  EXPECT_GT(junctions, 3) << "the frames must show junctions";
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

// Paint thinner than the minimum width is not visible (gt_eval.hpp's rule for the segments):
// a line drawn that thin gives the junctions on it no arm, and a circle that thin shows nothing.
TEST(FeatureTruth, PaintThinnerThanTheMinimumWidthShowsNoArmAndNoCircle) {
  const auto rays = [](const FeatureTruth& t) {
    long n = 0;
    for (const Intersection& j : t.intersections) n += j.num_rays;
    return n;
  };
  long fewer = 0, thinned_circles = 0;
  for (const GroundTruth& truth : kid_frames()) {
    const FeatureTruth original = feature_truth(truth);
    for (std::size_t f = 0; f < truth.features.size(); ++f) {
      if (truth.features[f].label != Label::Marking) continue;
      GroundTruth thin = truth;
      for (TruthPoint& p : thin.features[f].points) p.width = 0.5f;
      const FeatureTruth t = feature_truth(thin);
      EXPECT_LE(rays(t), rays(original));
      fewer += rays(t) < rays(original);
      for (const Intersection& j : t.intersections)
        for (int k = 0; k < j.num_rays; ++k) {  // no ray runs along the thinned line
          const float x = j.x + 12 * std::cos(j.heading_rays[k]), y = j.y + 12 * std::sin(j.heading_rays[k]);
          float nearest_other = 1e9f;
          for (std::size_t g = 0; g < truth.features.size(); ++g)
            if (g != f && truth.features[g].label == Label::Marking)
              nearest_other = std::min(nearest_other, test::distance_to(truth.features[g], x, y));
          const float to_thin = test::distance_to(truth.features[f], x, y);
          EXPECT_FALSE(to_thin < 2 && to_thin < nearest_other) << truth.features[f].name << " at " << x << ", " << y;
        }
      if (truth.features[f].name != "centre circle" || !original.circle || original.circle->visible_share <= 0) continue;
      bool rest_of_circle = false;  // a circle cut by a robot or the frame has more than one polyline
      for (std::size_t g = 0; g < truth.features.size(); ++g)
        rest_of_circle |= g != f && truth.features[g].name == "centre circle";
      if (rest_of_circle) continue;
      EXPECT_EQ(t.circle->visible_share, 0.f);
      EXPECT_GE(feature_truth(thin, {}, 0.4f).circle->visible_share, original.circle->visible_share);
      ++thinned_circles;
    }
  }
  EXPECT_GT(fewer, 0) << "thinning a line must take arms from some junction";
  EXPECT_GT(thinned_circles, 0) << "the frames must show a centre circle in one piece";
}

}  // namespace
}  // namespace fieldlines::synth
