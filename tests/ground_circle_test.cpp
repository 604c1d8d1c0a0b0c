// The camera over the turf (ground_camera.hpp) and the centre circle fitted on the turf when the
// camera is known: the projection agrees with the renderer's camera both ways; the arc of a
// circle seen from close by (most of its image ellipse below the frame) is found with the
// camera, exactly or a degree off, where straight lines are no circle; bad cameras are refused.
#include <algorithm>
#include <cmath>
#include <utility>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "painted_field.hpp"

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/ground_camera.hpp"
#include "fieldlines/synth/camera.hpp"

namespace fieldlines {
namespace {

using test::ground_camera, test::kPaint, test::kTurf, test::noisy;

constexpr double kDeg = std::numbers::pi / 180;

TEST(GroundCamera, AgreesWithTheRenderersCameraBothWays) {
  for (const auto& [pitch, roll, height] : {std::tuple{35.0, 0.0, 0.6}, {12.0, 5.0, 0.45}, {44.0, -6.0, 0.9}}) {
    const GroundCamera c = ground_camera(pitch, roll, height);
    const synth::Pose pose{.position = {0, 0, height}, .yaw = 0, .pitch = pitch * kDeg, .roll = roll * kDeg};
    const synth::Camera rendered(synth::Intrinsics{.fx = c.fx, .fy = c.fy, .cx = c.cx, .cy = c.cy}, pose);
    const GroundProjection projection(c);
    for (const cv::Point2d g : {cv::Point2d(1.5, 0.3), cv::Point2d(3, -1), cv::Point2d(0.9, 0)}) {
      const auto expected = rendered.project({g.x, g.y, 0});
      const auto pixel = projection.to_image(g);
      ASSERT_TRUE(expected && pixel);
      EXPECT_NEAR(pixel->x, expected->x(), 1e-6);
      EXPECT_NEAR(pixel->y, expected->y(), 1e-6);
      const auto back = projection.to_ground(pixel->x, pixel->y);
      ASSERT_TRUE(back);
      EXPECT_NEAR(back->x, g.x, 1e-9);
      EXPECT_NEAR(back->y, g.y, 1e-9);
    }
  }
}

TEST(GroundCamera, AboveTheHorizonAndBehindTheCameraAreNothing) {
  const GroundProjection level(ground_camera(0));
  EXPECT_FALSE(level.to_ground(320, 100)) << "above the horizon of a level camera";
  EXPECT_FALSE(level.to_ground(320, 239.5)) << "on the horizon";
  EXPECT_TRUE(level.to_ground(320, 400));
  EXPECT_FALSE(level.to_image({-1, 0})) << "behind the camera";
  EXPECT_FALSE(GroundProjection(ground_camera()).to_ground(std::nan(""), 10));
}

TEST(GroundCamera, BadCamerasAreRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  GroundCamera bad = ground_camera();
  bad.fx = 0;
  EXPECT_THROW(validate(bad), Error);
  bad = ground_camera(), bad.height_m = -0.5;
  EXPECT_THROW(validate(bad), Error);
  bad = ground_camera(), bad.cy = nan;
  EXPECT_THROW(validate(bad), Error);
  EXPECT_THROW(validate(ground_camera(90)), Error);
  EXPECT_NO_THROW(validate(ground_camera()));
  LineDetector detector;
  EXPECT_THROW(detector.set_camera(bad), Error);
  EXPECT_FALSE(detector.camera()) << "a refused camera leaves none";
  detector.set_camera(ground_camera());
  EXPECT_TRUE(detector.camera());
}

// The true image ellipse of the circle: its projected points, fitted.
cv::RotatedRect true_ellipse(const GroundCamera& c, cv::Point2d centre, double radius) {
  const GroundProjection projection(c);
  std::vector<cv::Point2f> points;
  for (int k = 0; k < 64; ++k) {
    const double a = 2 * std::numbers::pi * k / 64;
    const auto p = projection.to_image({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
    points.emplace_back(static_cast<float>(p->x), static_cast<float>(p->y));
  }
  return cv::fitEllipse(points);
}

std::vector<MarkingEllipse> ellipses(const cv::Mat& frame, const std::optional<GroundCamera>& known) {
  DetectorParams params;
  params.centre_circle = true;
  params.centre_circle_radius = 0.75;
  LineDetector detector(params);
  detector.set_camera(known);
  std::vector<Segment> segments;
  detector.detect(frame, segments);
  return detector.features().ellipses;
}

// The median distance (px) from the points of `e` inside the frame (one per degree of its turn)
// to the outline of `truth`, and how many such points there are.
std::pair<double, int> arc_distance(const MarkingEllipse& e, const cv::RotatedRect& truth) {
  std::vector<cv::Point> outline;
  cv::ellipse2Poly(cv::Point(cvRound(truth.center.x), cvRound(truth.center.y)),
                   cv::Size(cvRound(truth.size.width / 2), cvRound(truth.size.height / 2)), cvRound(truth.angle), 0,
                   360, 1, outline);
  std::vector<double> distances;
  for (int k = 0; k < 360; ++k) {
    const double a = k * kDeg, t = e.angle_deg * kDeg;
    const double u = 0.5 * e.width * std::cos(a), v = 0.5 * e.height * std::sin(a);
    const cv::Point2d p(e.cx + u * std::cos(t) - v * std::sin(t), e.cy + u * std::sin(t) + v * std::cos(t));
    if (p.x < 0 || p.y < 0 || p.x >= 640 || p.y >= 480) continue;
    distances.push_back(std::abs(cv::pointPolygonTest(outline, cv::Point2f(p), true)));
  }
  if (distances.empty()) return {std::numeric_limits<double>::infinity(), 0};
  std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
  return {distances[distances.size() / 2], static_cast<int>(distances.size())};
}

// From 0.6 m above the turf, looking 30 degrees down, a circle 0.8 m ahead: the frame shows its
// far arc; its image ellipse is about 1000 x 1300 px, centred below the frame's bottom.
TEST(GroundCircle, TheArcOfACircleCloseByIsFoundOnTheTurf) {
  const GroundCamera c = ground_camera(30, 2);
  const cv::Point2d centre(0.8, 0.05);
  const cv::Mat frame = noisy(test::painted_ground_circle(c, centre, 0.75, 7));
  const cv::RotatedRect truth = true_ellipse(c, centre, 0.75);
  ASSERT_GT(truth.center.y, 600.f) << "the test's premise: the ellipse's centre is far below the frame";
  const double radius = 0.5 * std::sqrt(double(truth.size.width) * truth.size.height);
  // Known exactly: the ellipse's centre within a tenth of its radius.
  const std::vector<MarkingEllipse> found = ellipses(frame, c);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_LE(std::hypot(found[0].cx - truth.center.x, found[0].cy - truth.center.y), 0.1 * radius)
      << found[0].cx << ", " << found[0].cy << " against " << truth.center.x << ", " << truth.center.y;
  EXPECT_GT(found[0].confidence, 0.25f);
  // A robot's estimate, a degree off in pitch and roll and 5 % in height: the circle is found and
  // its arc in the frame lies on the paint, though the centre far below the frame moves with
  // the pitch the arc cannot correct.
  GroundCamera off = c;
  off.pitch_rad += 1 * kDeg, off.roll_rad -= 1 * kDeg, off.height_m *= 1.05;
  const std::vector<MarkingEllipse> near = ellipses(frame, off);
  ASSERT_EQ(near.size(), 1u);
  const auto [median, inside] = arc_distance(near[0], truth);
  EXPECT_GT(inside, 30) << "degrees of the ellipse in the frame";
  EXPECT_LE(median, 3.0);
}

TEST(GroundCircle, StraightLinesAreNoCircleOnTheTurf) {
  const GroundCamera c = ground_camera(30);
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const GroundProjection projection(c);
  // A touch line, the halfway line and a goal area's corner, as they lie on the turf.
  const std::vector<std::pair<cv::Point2d, cv::Point2d>> lines{
      {{1, -3}, {8, -3}}, {{3, -3}, {3, 3}}, {{1.2, 0.5}, {2.2, 0.5}}, {{2.2, 0.5}, {2.2, 1.5}}};
  for (const auto& [a, b] : lines) {
    const auto p = projection.to_image(a), q = projection.to_image(b);
    ASSERT_TRUE(p && q);
    cv::line(clean, cv::Point2d(*p), cv::Point2d(*q), kPaint, 6, cv::LINE_AA);
  }
  EXPECT_TRUE(ellipses(noisy(clean), c).empty());
}

}  // namespace
}  // namespace fieldlines
