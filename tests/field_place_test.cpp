// Where the camera stands on the field from the centre circle and the halfway line
// (field_place.hpp): exact on features made from a known place, the half turn resolved by the
// half asked for, none without a circle or a line through it, and on rendered frames through
// their own camera.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/field_place.hpp"
#include "fieldlines/synth/camera.hpp"
#include "fieldlines/synth/synth.hpp"

namespace fl = fieldlines;

namespace {

constexpr double kDeg = std::numbers::pi / 180;

// A field point (metres) in the ground frame of a camera at (x, y) heading `yaw`.
fl::GroundPoint seen(double fx, double fy, double x, double y, double yaw) {
  const double dx = fx - x, dy = fy - y, c = std::cos(yaw), s = std::sin(yaw);
  return {c * dx + s * dy, -s * dx + c * dy, {}};
}

fl::GroundFeatures centre_seen_from(double x, double y, double yaw) {
  fl::GroundFeatures g;
  g.ellipses.push_back({seen(0, 0, x, y, yaw), 1.5, 0.9f});
  g.segments.push_back({seen(0, -2, x, y, yaw), seen(0, 1.5, x, y, yaw), 0.05});  // the halfway line
  g.segments.push_back({seen(-3, -2, x, y, yaw), seen(-3, 2, x, y, yaw), 0.05});  // a line elsewhere
  return g;
}

double angle_between(double a, double b) { return std::abs(std::remainder(a - b, 2 * std::numbers::pi)); }

}  // namespace

TEST(FieldPlace, TheCentreCircleAndTheHalfwayLineGiveThePlace) {
  const auto p = fl::place_from_centre_circle(centre_seen_from(-2.0, 0.5, 20 * kDeg));
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->x_m, -2.0, 1e-9);
  EXPECT_NEAR(p->y_m, 0.5, 1e-9);
  EXPECT_NEAR(angle_between(p->yaw_rad, 20 * kDeg), 0, 1e-9);
  EXPECT_EQ(p->halfway_pieces, 1);
  // The other half: the same view from the mirrored place, turned by half a turn.
  const auto q = fl::place_from_centre_circle(centre_seen_from(-2.0, 0.5, 20 * kDeg), {.negative_half = false});
  ASSERT_TRUE(q.has_value());
  EXPECT_NEAR(q->x_m, 2.0, 1e-9);
  EXPECT_NEAR(q->y_m, -0.5, 1e-9);
  EXPECT_NEAR(angle_between(q->yaw_rad, 200 * kDeg), 0, 1e-9);
}

TEST(FieldPlace, NoneWithoutTheCircleOrALineThroughIt) {
  fl::GroundFeatures g = centre_seen_from(-2.0, 0.5, 20 * kDeg);
  g.ellipses.clear();
  EXPECT_FALSE(fl::place_from_centre_circle(g).has_value());
  g = centre_seen_from(-2.0, 0.5, 20 * kDeg);
  g.segments.erase(g.segments.begin());  // only the line 3 m off the centre is left
  EXPECT_FALSE(fl::place_from_centre_circle(g).has_value());
}

// Kid frames through their own camera: where the detector finds the circle and a piece of the
// halfway line, the place is the truth's (its half named from the truth: the field is symmetric).
TEST(FieldPlace, OnRenderedFramesThroughTheirOwnCamera) {
  fl::synth::SynthParams params;
  params.field.scene = fl::synth::Scene::Kid;
  fl::LineDetector detector(fl::with_every_feature({}));
  int placed = 0;
  for (int index = 0; index < 40 && placed < 4; ++index) {
    const fl::synth::SynthSample s = fl::synth::generate(params, 31, index);
    const fl::synth::Pose& pose = s.truth.pose;
    detector.set_camera(fl::synth::to_ground_camera(s.truth.intrinsics, pose));
    detector.detect(s.bgr);
    const auto p = fl::place_from_centre_circle(detector.ground_features(), {.negative_half = pose.position.x() <= 0});
    if (!p) continue;
    ++placed;
    EXPECT_LT(std::hypot(p->x_m - pose.position.x(), p->y_m - pose.position.y()), 0.15) << "frame " << index;
    EXPECT_LT(angle_between(p->yaw_rad, pose.yaw), 3 * kDeg) << "frame " << index;
  }
  EXPECT_GE(placed, 2) << "the frames must show the centre circle and the halfway line";
}
