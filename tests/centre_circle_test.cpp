// The centre circle (centre_circle.hpp) on synthetic frames with known answers: a circle seen
// in perspective (an ellipse drawn on turf, the halfway line through it) is one ellipse with its
// centre and axes, also from pieces that lie apart; straight lines and corners are none; bad
// input never crashes.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "painted_field.hpp"

#include "fieldlines/detect/centre_circle.hpp"
#include "fieldlines/detect/detector.hpp"

namespace fieldlines {
namespace {

using test::kPaint, test::kTurf, test::noisy;

DetectorParams circle_on() {
  DetectorParams p;
  p.centre_circle = true;
  return p;
}

FieldFeatures features(const cv::Mat& frame, const DetectorParams& params = circle_on()) {
  LineDetector detector(params);
  std::vector<Segment> segments;
  detector.detect(frame, segments);
  return detector.features();
}

void expect_ellipse(const FieldFeatures& f, cv::Point2f centre, cv::Size2f axes, float angle_deg) {
  ASSERT_EQ(f.ellipses.size(), 1u);
  const MarkingEllipse& e = f.ellipses[0];
  const float radius = 0.5f * std::min(axes.width, axes.height);
  EXPECT_LE(std::hypot(e.cx - centre.x, e.cy - centre.y), 0.1f * radius) << e.cx << ", " << e.cy;
  // Width is along angle_deg: compare the axes as the pair they are.
  const float turn = std::remainder(e.angle_deg - angle_deg, 180.f);
  const bool swapped = std::abs(turn) > 45;
  const float w = swapped ? e.height : e.width, h = swapped ? e.width : e.height;
  EXPECT_NEAR(w, axes.width, 0.1f * axes.width);
  EXPECT_NEAR(h, axes.height, 0.1f * axes.height);
  if (std::abs(axes.width - axes.height) > 0.2f * axes.width) {
    EXPECT_LT(std::abs(std::remainder(turn, 90.f)), 5.f) << e.angle_deg;
  }
  EXPECT_GT(e.confidence, 0.5f);
  EXPECT_LE(e.confidence, 1.f);
}

TEST(CentreCircle, ACircleInPerspectiveWithTheHalfwayLineThroughIt) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const cv::Point2f centre(330, 260);
  const cv::Size2f axes(380, 150);  // full axes: a circle seen from 23 degrees above the turf
  cv::ellipse(clean, cv::RotatedRect(centre, axes, 4), kPaint, 7, cv::LINE_AA);
  cv::line(clean, cv::Point(0, 250), cv::Point(639, 272), kPaint, 7, cv::LINE_AA);
  const FieldFeatures f = features(noisy(clean));
  expect_ellipse(f, centre, axes, 4);
  EXPECT_FALSE(f.markings.empty()) << "the circle's pieces are markings (arcs)";
}

TEST(CentreCircle, ARoundCircleHalfOutOfTheFrame) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const cv::Point2f centre(320, 420);
  const cv::Size2f axes(300, 280);
  cv::ellipse(clean, cv::RotatedRect(centre, axes, 0), kPaint, 6, cv::LINE_AA);
  expect_ellipse(features(noisy(clean, 3)), centre, axes, 0);
}

// A circle whose centre lies beyond the frame's edge shows less than the 150 degrees of its turn
// that a circle inside the frame must: 128 here, all of it drawn.
TEST(CentreCircle, ACircleCutByTheFrameShowsLessOfItsTurn) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const cv::Point2f centre(750, 250);
  const cv::Size2f axes(500, 200);  // x < 640 where cos(t) < -0.44: 128 degrees of the turn
  cv::ellipse(clean, cv::RotatedRect(centre, axes, 0), kPaint, 7, cv::LINE_AA);
  const FieldFeatures f = features(noisy(clean, 5));
  ASSERT_EQ(f.ellipses.size(), 1u);
  const MarkingEllipse& e = f.ellipses[0];
  EXPECT_LE(std::hypot(e.cx - centre.x, e.cy - centre.y), 0.1f * 0.5f * std::sqrt(axes.width * axes.height));
  EXPECT_LT(e.confidence, 150.f / 360) << "its points cover less than a whole circle's minimum";
}

TEST(CentreCircle, StraightLinesAndCornersAreNoCircle) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  cv::line(clean, cv::Point(60, 100), cv::Point(590, 120), kPaint, 8);
  cv::line(clean, cv::Point(60, 300), cv::Point(590, 330), kPaint, 8);
  cv::line(clean, cv::Point(120, 440), cv::Point(300, 160), kPaint, 8);
  cv::line(clean, cv::Point(300, 160), cv::Point(600, 420), kPaint, 8);
  EXPECT_TRUE(features(noisy(clean, 9)).ellipses.empty());
}

// A far, flat circle whose pieces lie apart (faint paint, a robot in front): no two chain, yet
// any two of them give its ellipse, and the halfway line's piece across it is no part of it.
// Pieces of 20 degrees of turn with gaps of 30 (they do not chain) from `first_deg` round an
// ellipse of semi-axes a and b centred on `centre`, turned by `turn_deg`, 3 px wide.
std::vector<Marking> flat_circle_pieces(cv::Point2f centre, float a, float b, float turn_deg, float first_deg) {
  const float turn = turn_deg * std::numbers::pi_v<float> / 180;
  const auto at = [&](float deg) {
    const float t = deg * std::numbers::pi_v<float> / 180;
    const float x = a * std::cos(t), y = b * std::sin(t);
    return cv::Point2f(centre.x + x * std::cos(turn) - y * std::sin(turn), centre.y + x * std::sin(turn) + y * std::cos(turn));
  };
  std::vector<Marking> pieces;
  for (float start = first_deg; start < 360; start += 50) {
    const cv::Point2f p = at(start), q = at(start + 20);
    pieces.push_back({p.x, p.y, q.x, q.y, 3});
  }
  return pieces;
}

TEST(CentreCircle, AFlatCircleOfPiecesThatDoNotChain) {
  const cv::Point2f centre(320, 200);
  const float a = 200, b = 40;  // semi-axes: a circle seen from 11 degrees above the turf
  std::vector<Marking> pieces = flat_circle_pieces(centre, a, b, 0, 0);
  pieces.push_back({315, 120, 325, 280, 4});  // the halfway line
  CircleWorkspace work;
  std::vector<MarkingEllipse> out;
  find_centre_circle(pieces, work, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_LE(std::hypot(out[0].cx - centre.x, out[0].cy - centre.y), 0.1f * std::sqrt(a * b));
  EXPECT_NEAR(std::max(out[0].width, out[0].height), 2 * a, 0.1f * 2 * a);
  EXPECT_NEAR(std::min(out[0].width, out[0].height), 2 * b, 0.2f * 2 * b);
  ASSERT_EQ(work.on_ellipse.size(), pieces.size());
  EXPECT_FALSE(work.on_ellipse.back()) << "the halfway line's piece is no arc";
  EXPECT_TRUE(work.on_ellipse.front());
}

// A circle seen off the camera's axis is an ellipse turned by several degrees: a flat one's
// pieces, fitted with the image's axes, miss its ends.
TEST(CentreCircle, AFlatCircleTurnedOffTheImageAxes) {
  for (const float turn_deg : {-7.f, 5.f}) {
    SCOPED_TRACE(turn_deg);
    const cv::Point2f centre(320, 220);
    const float a = 190, b = 28;
    CircleWorkspace work;
    std::vector<MarkingEllipse> out;
    find_centre_circle(flat_circle_pieces(centre, a, b, turn_deg, 5), work, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_LE(std::hypot(out[0].cx - centre.x, out[0].cy - centre.y), 0.1f * std::sqrt(a * b));
    EXPECT_NEAR(std::max(out[0].width, out[0].height), 2 * a, 0.1f * 2 * a);
  }
}

// ELSED fits a straight line to a curved run of pixels: near a flat ellipse's sharp ends a piece
// is a tangent whose ends stand off the paint, and a fit to the pieces comes out too long. Read
// in the frame, the paint's centre round the ellipse puts it back.
TEST(CentreCircle, TheFitIsRefinedOnThePaint) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const cv::Point2f centre(320, 240);
  const float a = 200, b = 24;  // semi-axes, the image's axes
  cv::ellipse(clean, cv::RotatedRect(centre, cv::Size2f(2 * a, 2 * b), 0), kPaint, 4, cv::LINE_AA);
  const cv::Mat frame = noisy(clean);
  // Tangents at the middle of each 24 degrees of turn, as long as the arc they stand for.
  std::vector<Marking> pieces;
  for (float mid = 0; mid < 360; mid += 36) {
    const float t = mid * std::numbers::pi_v<float> / 180, half_turn = 12 * std::numbers::pi_v<float> / 180;
    const cv::Point2f p(centre.x + a * std::cos(t), centre.y + b * std::sin(t));
    const cv::Point2f tangent = half_turn * cv::Point2f(-a * std::sin(t), b * std::cos(t));  // half the arc, about
    pieces.push_back({p.x - tangent.x, p.y - tangent.y, p.x + tangent.x, p.y + tangent.y, 4});
  }
  CircleWorkspace work;
  std::vector<MarkingEllipse> from_pieces, on_paint;
  find_centre_circle(pieces, work, from_pieces);
  find_centre_circle(pieces, work, on_paint, frame);
  ASSERT_EQ(from_pieces.size(), 1u);
  ASSERT_EQ(on_paint.size(), 1u);
  const auto long_axis = [](const MarkingEllipse& e) { return std::max(e.width, e.height); };
  const auto short_axis = [](const MarkingEllipse& e) { return std::min(e.width, e.height); };
  EXPECT_GT(std::abs(long_axis(from_pieces[0]) - 2 * a), 0.01f * 2 * a) << "the pieces alone: too long";
  EXPECT_LE(std::abs(long_axis(on_paint[0]) - 2 * a), 0.005f * 2 * a) << long_axis(on_paint[0]);
  EXPECT_LE(std::abs(short_axis(on_paint[0]) - 2 * b), 1.f) << short_axis(on_paint[0]);
  EXPECT_LE(std::hypot(on_paint[0].cx - centre.x, on_paint[0].cy - centre.y), 1.f);
  EXPECT_EQ(on_paint[0].confidence, from_pieces[0].confidence) << "the turn covered is the pieces'";
}

// Pieces on one arc of a circle seen close by fix the rest of it poorly: each is fitted to an
// edge a pixel or so off the paint's centre, and the conic extrapolates. The paint, followed
// round the ellipse past the pieces' ends, fixes it.
TEST(CentreCircle, TheFitFollowsThePaintPastThePiecesEnds) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const cv::Point2f centre(320, 420);
  const float a = 300, b = 200;  // semi-axes, the image's axes: the frame's bottom cuts it
  cv::ellipse(clean, cv::RotatedRect(centre, cv::Size2f(2 * a, 2 * b), 0), kPaint, 6, cv::LINE_AA);
  const cv::Mat frame = noisy(clean);
  // Chords of 16 degrees of turn over 135 degrees of the far arc, each 1.5 px to either side of
  // the paint's centre in turn.
  std::vector<Marking> pieces;
  float side = 1.5f;
  for (float deg = 207; deg < 332; deg += 17, side = -side) {
    const auto at = [&](float d) {
      const float t = d * std::numbers::pi_v<float> / 180;
      const cv::Point2f normal(b * std::cos(t), a * std::sin(t));
      return cv::Point2f(centre.x + a * std::cos(t), centre.y + b * std::sin(t)) + side * normal / cv::norm(normal);
    };
    const cv::Point2f p = at(deg), q = at(deg + 16);
    pieces.push_back({p.x, p.y, q.x, q.y, 6});
  }
  CircleWorkspace work;
  std::vector<MarkingEllipse> from_pieces, on_paint;
  find_centre_circle(pieces, work, from_pieces, cv::Mat(480, 640, CV_8UC1));  // the frame's size, no pixels to read
  find_centre_circle(pieces, work, on_paint, frame);
  ASSERT_EQ(from_pieces.size(), 1u);
  ASSERT_EQ(on_paint.size(), 1u);
  const auto centre_error = [&](const MarkingEllipse& e) { return std::hypot(e.cx - centre.x, e.cy - centre.y); };
  EXPECT_GT(centre_error(from_pieces[0]), 4.f) << "the pieces alone";
  EXPECT_LE(centre_error(on_paint[0]), 1.5f) << on_paint[0].cx << ", " << on_paint[0].cy;
  EXPECT_NEAR(std::max(on_paint[0].width, on_paint[0].height), 2 * a, 0.01f * 2 * a);
  EXPECT_NEAR(std::min(on_paint[0].width, on_paint[0].height), 2 * b, 0.01f * 2 * b);
}

// An ellipse the pieces make must lie on paint wherever the frame shows it: the same pieces over
// a frame with only the lower half of their ellipse painted (the upper half bare turf) give
// none; with all of it painted, the ellipse.
TEST(CentreCircle, AnEllipseOverBareTurfIsRefused) {
  const cv::Point2f centre(320, 220);
  const float a = 190, b = 40;
  const std::vector<Marking> pieces = flat_circle_pieces(centre, a, b, 0, 5);
  const cv::Size2f axes(2 * a, 2 * b);
  cv::Mat half_painted(480, 640, CV_8UC3, kTurf), painted(480, 640, CV_8UC3, kTurf);
  cv::ellipse(half_painted, cv::Point(320, 220), cv::Size(190, 40), 0, 0, 180, kPaint, 4, cv::LINE_AA);  // y down: the lower half
  cv::ellipse(painted, cv::RotatedRect(centre, axes, 0), kPaint, 4, cv::LINE_AA);
  const Rgb field{static_cast<float>(kTurf[2]), static_cast<float>(kTurf[1]), static_cast<float>(kTurf[0])};
  CircleWorkspace work;
  std::vector<MarkingEllipse> out;
  find_centre_circle(pieces, work, out, noisy(half_painted), field);
  EXPECT_TRUE(out.empty()) << "half of it over bare turf";
  EXPECT_EQ(std::count(work.on_ellipse.begin(), work.on_ellipse.end(), 1), 0);
  find_centre_circle(pieces, work, out, noisy(painted), field);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_LE(std::hypot(out[0].cx - centre.x, out[0].cy - centre.y), 0.1f * std::sqrt(a * b));
  // Without the field colour there is no turf to tell: the pieces' ellipse stands.
  find_centre_circle(pieces, work, out, noisy(half_painted));
  EXPECT_EQ(out.size(), 1u);
}

TEST(CentreCircle, BadInputGivesNoneAndNeverCrashes) {
  cv::Mat grey(240, 320, CV_8UC3, cv::Scalar(110, 110, 110));  // no green
  cv::ellipse(grey, cv::RotatedRect(cv::Point2f(160, 120), cv::Size2f(200, 90), 0), kPaint, 5);
  EXPECT_TRUE(features(noisy(grey)).ellipses.empty());
  for (const cv::Size size : {cv::Size(640, 1), cv::Size(1, 480), cv::Size(3, 3), cv::Size(640, 3)}) {
    cv::Mat tiny(size, CV_8UC3, kTurf);
    cv::line(tiny, cv::Point(0, 0), cv::Point(size.width - 1, size.height - 1), kPaint, 1);
    EXPECT_NO_THROW(EXPECT_TRUE(features(tiny).ellipses.empty())) << size;
  }
  for (const cv::Scalar& colour : {kTurf, kPaint})
    EXPECT_TRUE(features(noisy(cv::Mat(240, 320, CV_8UC3, colour))).ellipses.empty());
  // Degenerate pieces: zero length, coincident, collinear, not a number.
  CircleWorkspace work;
  std::vector<MarkingEllipse> out;
  const std::vector<Marking> odd{{5, 5, 5, 5, 3}, {5, 5, 5, 5, 3}, {0, 0, 10, 0, 2}, {10, 0, 20, 0, 2},
                                 {20, 0, 30, 0, 2}};
  find_centre_circle(odd, work, out);
  EXPECT_TRUE(out.empty());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<Marking> with_nan(odd);
  for (int k = 0; k < 30; ++k) with_nan.push_back({nan, float(k), 10, float(k), 2});
  find_centre_circle(with_nan, work, out);
  EXPECT_TRUE(out.empty());
  find_centre_circle({}, work, out);
  EXPECT_TRUE(out.empty());
}

TEST(CentreCircle, OffByDefault) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  cv::ellipse(clean, cv::RotatedRect(cv::Point2f(320, 240), cv::Size2f(380, 150), 0), kPaint, 7);
  EXPECT_TRUE(features(noisy(clean), DetectorParams{}).ellipses.empty());
}

}  // namespace
}  // namespace fieldlines
