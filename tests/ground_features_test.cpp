// The field features on the ground (ground_features.hpp): exact through a known camera, in
// perspective (rays and the circle), never above the horizon, with a covariance that grows with
// distance; and the detector's ground stage on rendered frames.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/ground_features.hpp"
#include "fieldlines/synth/camera.hpp"
#include "fieldlines/synth/synth.hpp"

namespace fl = fieldlines;

namespace {

constexpr double kDeg = std::numbers::pi / 180;

fl::GroundCamera kid_camera() {
  fl::GroundCamera c;
  c.fx = c.fy = 640, c.cx = 319.5, c.cy = 239.5;
  c.pitch_rad = 25 * kDeg, c.roll_rad = 3 * kDeg, c.height_m = 0.6;
  return c;
}

cv::Point2d image_of(const fl::GroundProjection& p, cv::Point2d g) {
  const auto i = p.to_image(g);
  EXPECT_TRUE(i.has_value());
  return i.value_or(cv::Point2d{});
}

double heading(cv::Point2d from, cv::Point2d to) {
  const double h = std::atan2(to.y - from.y, to.x - from.x);
  return h < 0 ? h + 2 * std::numbers::pi : h;
}

}  // namespace

TEST(GroundFeatures, MarkingsAndBoundaryComeBackWhereTheyLie) {
  const fl::GroundCamera camera = kid_camera();
  const fl::GroundProjection p(camera);
  fl::FieldFeatures image;
  const cv::Point2d a = image_of(p, {1.5, -0.8}), b = image_of(p, {4.0, 1.1});
  image.markings.push_back({float(a.x), float(a.y), float(b.x), float(b.y), 6});
  const cv::Point2d q = image_of(p, {5.0, 2.0});
  image.field_boundary.points.push_back({float(q.x), float(q.y)});
  fl::GroundFeatures out;
  fl::project_features(image, camera, {}, out);
  ASSERT_EQ(out.segments.size(), 1u);
  EXPECT_NEAR(out.segments[0].start.x, 1.5, 2e-4);
  EXPECT_NEAR(out.segments[0].start.y, -0.8, 2e-4);
  EXPECT_NEAR(out.segments[0].end.x, 4.0, 5e-4);
  EXPECT_NEAR(out.segments[0].end.y, 1.1, 5e-4);
  EXPECT_GT(out.segments[0].width, 0.01);
  ASSERT_EQ(out.field_boundary.size(), 1u);
  EXPECT_NEAR(out.field_boundary[0].x, 5.0, 1e-3);
  EXPECT_NEAR(out.field_boundary[0].y, 2.0, 1e-3);
}

// A 5 cm line 2 m ahead, drawn at its image width: 5 cm on the ground.
TEST(GroundFeatures, AStripesWidthIsMeasuredInMetres) {
  const fl::GroundCamera camera = kid_camera();
  const fl::GroundProjection p(camera);
  // A line across the view (along y) 2 m ahead: its edges at x = 2 -+ 0.025.
  const cv::Point2d a = image_of(p, {2.0, -0.5}), b = image_of(p, {2.0, -0.1}), mid = 0.5 * (a + b);
  // Its image width across, at the middle: the distances to both edges' image lines.
  double width_px = 0;
  for (const double x : {1.975, 2.025}) {
    const cv::Point2d e0 = image_of(p, {x, -0.5}), e1 = image_of(p, {x, -0.1}), e = e1 - e0;
    width_px += std::abs(e.cross(mid - e0)) / std::hypot(e.x, e.y);
  }
  fl::FieldFeatures image;
  image.markings.push_back({float(a.x), float(a.y), float(b.x), float(b.y), float(width_px)});
  fl::GroundFeatures out;
  fl::project_features(image, camera, {}, out);
  ASSERT_EQ(out.segments.size(), 1u);
  EXPECT_NEAR(out.segments[0].width, 0.05, 0.002);
}

// A junction's arms in perspective: the image headings of two perpendicular ground lines are
// not perpendicular, their ground rays are, along the lines' true directions.
TEST(GroundFeatures, JunctionRaysAreTheArmsGroundDirections) {
  const fl::GroundCamera camera = kid_camera();
  const fl::GroundProjection p(camera);
  const cv::Point2d centre(2.5, 0.7);
  const double arm[2] = {20 * kDeg, 110 * kDeg};
  fl::Intersection j;
  const cv::Point2d c = image_of(p, centre);
  j.x = float(c.x), j.y = float(c.y), j.type = fl::JunctionType::L, j.num_rays = 2, j.confidence = 0.8f;
  for (int k = 0; k < 2; ++k)
    j.heading_rays[k] = float(heading(c, image_of(p, centre + 0.5 * cv::Point2d(std::cos(arm[k]), std::sin(arm[k])))));
  const double image_angle = std::abs(j.heading_rays[1] - j.heading_rays[0]) / kDeg;
  EXPECT_GT(std::abs(image_angle - 90), 5) << "the test needs perspective that bends the right angle";
  fl::FieldFeatures image;
  image.intersections.push_back(j);
  fl::GroundFeatures out;
  fl::project_features(image, camera, {}, out);
  ASSERT_EQ(out.intersections.size(), 1u);
  const fl::GroundIntersection& g = out.intersections[0];
  EXPECT_NEAR(g.center.x, centre.x, 1e-3);
  EXPECT_NEAR(g.center.y, centre.y, 1e-3);
  EXPECT_EQ(g.type, fl::JunctionType::L);
  EXPECT_EQ(g.num_rays, 2);
  EXPECT_FLOAT_EQ(g.confidence, 0.8f);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(g.rays[k][0], std::cos(arm[k]), 2e-3) << "ray " << k;
    EXPECT_NEAR(g.rays[k][1], std::sin(arm[k]), 2e-3) << "ray " << k;
  }
}

// The centre circle's image ellipse: its own centre is not the circle's (the near half is drawn
// larger); the circle through its projected points is, with the rules' diameter.
TEST(GroundFeatures, TheCircleIsFittedOnTheGroundNotAtTheEllipsesCentre) {
  const fl::GroundCamera camera = kid_camera();
  const fl::GroundProjection p(camera);
  const cv::Point2d centre(2.2, -0.4);
  const double radius = 0.75;
  std::vector<cv::Point2f> points;
  for (int i = 0; i < 180; ++i) {
    const double t = 2 * std::numbers::pi * i / 180;
    const cv::Point2d q = image_of(p, centre + radius * cv::Point2d(std::cos(t), std::sin(t)));
    points.emplace_back(float(q.x), float(q.y));
  }
  const cv::RotatedRect r = cv::fitEllipse(points);
  fl::FieldFeatures image;
  image.ellipses.push_back({r.center.x, r.center.y, r.size.width, r.size.height, r.angle, 0.9f});
  fl::GroundFeatures out;
  fl::project_features(image, camera, {}, out);
  ASSERT_EQ(out.ellipses.size(), 1u);
  EXPECT_NEAR(out.ellipses[0].center.x, centre.x, 0.01);
  EXPECT_NEAR(out.ellipses[0].center.y, centre.y, 0.01);
  EXPECT_NEAR(out.ellipses[0].diameter, 2 * radius, 0.01);
  const auto naive = p.to_ground(r.center.x, r.center.y);
  ASSERT_TRUE(naive.has_value());
  EXPECT_GT(std::hypot(naive->x - centre.x, naive->y - centre.y), 0.05) << "the ellipse's centre would be off";
}

TEST(GroundFeatures, NothingAboveTheHorizonOrBeyondTheRangeIsProjected) {
  fl::GroundCamera camera = kid_camera();
  camera.roll_rad = 0;
  const fl::GroundProjection p(camera);
  const double horizon = camera.cy - camera.fy * std::tan(camera.pitch_rad);  // its row
  fl::FieldFeatures image;
  // A marking from near the bottom up past the horizon; a junction and a boundary point above it.
  image.markings.push_back({300, 470, 320, float(horizon - 40), 4});
  image.intersections.push_back({320, float(horizon - 10), fl::JunctionType::T, 3, {0, 1, 2}, 1});
  image.field_boundary.points.push_back({100, float(horizon - 5)});
  image.field_boundary.points.push_back({500, 400});
  fl::GroundFeatureParams params;
  params.max_distance_m = 8;
  fl::GroundFeatures out;
  fl::project_features(image, camera, params, out);
  ASSERT_EQ(out.segments.size(), 1u);
  const fl::GroundMarkingSegment& s = out.segments[0];
  EXPECT_LT(std::hypot(s.start.x, s.start.y), 2);
  EXPECT_NEAR(std::hypot(s.end.x, s.end.y), 8, 0.05) << "cut where it leaves the range";
  EXPECT_TRUE(out.intersections.empty());
  ASSERT_EQ(out.field_boundary.size(), 1u);
  EXPECT_GT(out.field_boundary[0].x, 0);
}

TEST(GroundFeatures, CovarianceGrowsWithDistanceAndVanishesWithoutAngleNoise) {
  const fl::GroundCamera camera = kid_camera();
  const fl::GroundProjection p(camera);
  fl::FieldFeatures image;
  for (const double x : {1.0, 6.0}) {
    const cv::Point2d q = image_of(p, {x, 0.2});
    image.field_boundary.points.push_back({float(q.x), float(q.y)});
  }
  fl::GroundFeatures out;
  fl::project_features(image, camera, {}, out);
  ASSERT_EQ(out.field_boundary.size(), 2u);
  const auto& near = out.field_boundary[0].covariance;
  const auto& far = out.field_boundary[1].covariance;
  EXPECT_GT(near[0], 0);
  EXPECT_GT(far[0] + far[2], 10 * (near[0] + near[2]));
  EXPECT_GE(near[0] * near[2] - near[1] * near[1], -1e-12) << "positive semi-definite";
  // One degree of pitch at 6 m and 0.6 m high moves the point by about a metre and a half.
  EXPECT_NEAR(std::sqrt(far[0]), 6.0 * 6.0 / 0.6 * kDeg, 0.4);
  fl::GroundFeatureParams exact;
  exact.angle_sigma_deg = 0;
  fl::project_features(image, camera, exact, out);
  for (const fl::GroundPoint& g : out.field_boundary)
    for (const double v : g.covariance) EXPECT_DOUBLE_EQ(v, 0);
}

TEST(GroundFeatures, BadParametersAreRefused) {
  fl::GroundFeatureParams p;
  p.angle_sigma_deg = NAN;
  EXPECT_THROW(fl::validate(p), fl::Error);
  p = {};
  p.max_distance_m = 0;
  EXPECT_THROW(fl::validate(p), fl::Error);
  fl::LineDetector detector;
  EXPECT_THROW(detector.set_ground_params(p), fl::Error);
  EXPECT_EQ(detector.ground_params().max_distance_m, fl::GroundFeatureParams{}.max_distance_m);
}

// On rendered frames: with the camera the detector's features come out on the ground too, in
// front of the camera; without it, nothing does.
TEST(GroundFeatures, TheDetectorProjectsItsFeaturesWhenTheCameraIsSet) {
  fl::synth::SynthParams params;
  params.field.scene = fl::synth::Scene::Kid;
  fl::LineDetector detector(fl::with_every_feature({}));
  std::size_t segments = 0, boundary = 0;
  for (const int index : {2, 7, 11}) {
    const fl::synth::SynthSample s = fl::synth::generate(params, 5150, index);
    detector.set_camera(std::nullopt);
    detector.detect(s.bgr);
    EXPECT_TRUE(detector.ground_features().segments.empty());
    detector.set_camera(fl::synth::to_ground_camera(s.truth.intrinsics, s.truth.pose));
    detector.detect(s.bgr);
    const fl::GroundFeatures& g = detector.ground_features();
    EXPECT_LE(g.segments.size(), detector.features().markings.size());
    for (const fl::GroundMarkingSegment& m : g.segments) {
      EXPECT_GT(m.start.x, 0);
      EXPECT_LE(std::hypot(m.end.x, m.end.y), detector.ground_params().max_distance_m + 1e-6);
    }
    segments += g.segments.size();
    boundary += g.field_boundary.size();
  }
  EXPECT_GT(segments, 5u);
  EXPECT_GT(boundary, 5u);
}

// A field's lines meet square on the ground: an L whose arms do (though not in the image)
// passes, one 30 degrees off does not, within the tolerance either way.
TEST(GroundFeatures, AJunctionIsSquareOnTheGroundOrNot) {
  const fl::GroundCamera camera = kid_camera();
  const fl::GroundProjection p(camera);
  const cv::Point2d centre(2.0, -0.5);
  const auto junction = [&](double second_arm_deg) {
    fl::Intersection j;
    const cv::Point2d c = image_of(p, centre);
    j.x = float(c.x), j.y = float(c.y), j.num_rays = 2;
    const double arm[2] = {10 * kDeg, second_arm_deg * kDeg};
    for (int k = 0; k < 2; ++k)
      j.heading_rays[k] = float(heading(c, image_of(p, centre + 0.5 * cv::Point2d(std::cos(arm[k]), std::sin(arm[k])))));
    return j;
  };
  EXPECT_TRUE(fl::square_on_ground(junction(100), p, 5));
  EXPECT_TRUE(fl::square_on_ground(junction(190), p, 5)) << "straight on: a T's or an X's opposite arms";
  EXPECT_FALSE(fl::square_on_ground(junction(130), p, 15));
  EXPECT_TRUE(fl::square_on_ground(junction(110), p, 15));
  EXPECT_FALSE(fl::square_on_ground(junction(110), p, 5));
  fl::Intersection above = junction(100);
  above.y = -150;  // above the horizon (row -59 at this pitch): not on the ground
  EXPECT_FALSE(fl::square_on_ground(above, p, 45));
}
