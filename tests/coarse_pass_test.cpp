// The coarse pass (DetectorParams::coarse_scale): a wide near line on coarse, textured turf, whose
// ragged edges break the full scale's drawing, gets segments along its edges; a far line one
// pixel wide, above the coarse band, is found as before; one painted edge stays one segment.
#include <cmath>
#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "painted_field.hpp"

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/train/detector_calibration.hpp"

namespace fieldlines {
namespace {

// Turf in blocks of 4 px whose brightness varies by 45 % (artificial turf seen up close).
cv::Mat textured_turf(cv::RNG& rng) {
  cv::Mat blocks(121, 161, CV_32F), texture;
  rng.fill(blocks, cv::RNG::NORMAL, 0, 1);
  cv::resize(blocks, texture, cv::Size(644, 484), 0, 0, cv::INTER_NEAREST);
  cv::Mat clean(480, 640, CV_8UC3);
  for (int y = 0; y < 480; ++y)
    for (int x = 0; x < 640; ++x) {
      const float k = 1 + 0.45f * texture.at<float>(y, x);
      clean.at<cv::Vec3b>(y, x) = {cv::saturate_cast<std::uint8_t>(50 * k), cv::saturate_cast<std::uint8_t>(140 * k),
                                   cv::saturate_cast<std::uint8_t>(40 * k)};
    }
  return clean;
}

// That turf with a white line `width` px wide whose top edge runs from row `top` (left) to top +
// 32 (right), its edges jumping by up to 3 px from column to column; no camera noise yet.
cv::Mat turf_with_a_ragged_line(int top, int width) {
  cv::RNG rng(3);
  cv::Mat clean = textured_turf(rng);
  for (int x = 0; x < 640; ++x) {
    const int from = static_cast<int>(top + 0.05 * x) + rng.uniform(-3, 4);
    for (int y = from; y < std::min(from + width, 480); ++y) clean.at<cv::Vec3b>(y, x) = {235, 240, 235};
  }
  return clean;
}

// The near line: 40 px wide from row 380, and camera noise.
cv::Mat textured_turf_with_a_near_line() { return test::noisy(turf_with_a_ragged_line(380, 40)); }

// Length of the segments that run along the edge from (0, y0) to (639, y0 + 32): parallel within
// 5 degrees, both ends within 4 px of it.
float along_edge(const std::vector<Segment>& segments, float y0) {
  float total = 0;
  for (const Segment& s : segments) {
    const auto off = [&](float x, float y) { return std::abs(y - (y0 + 0.05f * x)); };
    const float length = std::hypot(s.x1 - s.x0, s.y1 - s.y0);
    const float slope = std::abs(s.x1 - s.x0) > 0 ? (s.y1 - s.y0) / (s.x1 - s.x0) : 1e9f;
    if (off(s.x0, s.y0) <= 4 && off(s.x1, s.y1) <= 4 && std::abs(std::atan(slope) - std::atan(0.05f)) < 0.087f)
      total += length;
  }
  return total;
}

std::vector<Segment> detect(const cv::Mat& frame, int coarse_scale, double coarse_from = 0.5,
                            double coarse_twins_from = 1) {
  DetectorParams p;
  p.coarse_scale = coarse_scale;
  p.coarse_from = coarse_from;
  p.coarse_twins_from = coarse_twins_from;
  LineDetector detector(p);
  return detector.detect(frame);
}

TEST(CoarsePass, AWideNearLineOnTexturedTurfGetsSegmentsAlongItsEdges) {
  const cv::Mat frame = textured_turf_with_a_near_line();
  const std::vector<Segment> fine = detect(frame, 1), coarse = detect(frame, 3);
  const float fine_length = along_edge(fine, 381) + along_edge(fine, 421);
  const float coarse_length = along_edge(coarse, 381) + along_edge(coarse, 421);
  EXPECT_LT(fine_length, 100) << "the full scale alone breaks up on this turf";
  EXPECT_GT(coarse_length, 900) << "the coarse pass (a third of the size) draws both edges end to end";
}

// A wide curved line near the camera on that turf (an arc of the centre circle: radii 420 and
// 450 px about a centre below the frame): the coarse pass draws its edges, and each of its
// segments along them stays within 3 px of its edge over all its length, as the full scale's
// would; with the full scale's fit tolerance in its own pixels (4.5 px on the frame) it cut
// chords across the curve.
TEST(CoarsePass, ItsSegmentsOnACurvedLineStayOnTheEdge) {
  cv::RNG rng(5);
  cv::Mat clean = textured_turf(rng);
  const cv::Point2f centre(320, 840);
  constexpr float kInner = 420, kOuter = 450;
  for (int y = 0; y < 480; ++y)
    for (int x = 0; x < 640; ++x) {
      const float r = std::hypot(float(x) - centre.x, float(y) - centre.y);
      if (r >= kInner && r <= kOuter) clean.at<cv::Vec3b>(y, x) = {235, 240, 235};
    }
  const cv::Mat frame = test::noisy(clean);
  float along = 0, worst = 0;
  for (const Segment& s : detect(frame, 3)) {
    const float length = std::hypot(s.x1 - s.x0, s.y1 - s.y0);
    const auto off = [&](float x, float y, float radius) { return std::abs(std::hypot(x - centre.x, y - centre.y) - radius); };
    for (const float radius : {kInner, kOuter}) {
      if (off(s.x0, s.y0, radius) > 6 || off(s.x1, s.y1, radius) > 6) continue;  // not along this edge
      along += length;
      for (float t = 0; t <= 1; t += 0.05f)
        worst = std::max(worst, off(s.x0 + t * (s.x1 - s.x0), s.y0 + t * (s.y1 - s.y0), radius));
    }
  }
  EXPECT_GT(along, 400) << "the edges are drawn";
  EXPECT_LE(worst, 3) << "a segment cuts across the curve";
}

// Above the near rows (coarse_twins_from to coarse_from), the coarse pass keeps the lines it
// resolves, both edges drawn, and drops a segment with no such twin: on a line too narrow for
// its scale it blurs both edges into one segment, off either (here: one edge alone, a white
// board's foot). The wide line is the near one's, 24 px wide, raised to rows 180-212.
TEST(CoarsePass, AboveTheNearRowsItKeepsTheLinesItResolves) {
  const auto frame_with = [](bool line) { return test::noisy(turf_with_a_ragged_line(180, line ? 24 : 480)); };
  const cv::Mat line = frame_with(true), board = frame_with(false);
  const auto edges = [](const std::vector<Segment>& segments) {
    return along_edge(segments, 181) + along_edge(segments, 205);
  };
  EXPECT_LT(edges(detect(line, 3)), 100) << "above coarse_from the full scale alone breaks up";
  EXPECT_GT(edges(detect(line, 3, 0.5, 0.25)), 600) << "the coarse pass draws the line's edges end to end";
  EXPECT_GT(along_edge(detect(board, 3, 0.25), 181), 300) << "a coarse pass from there draws the board's foot";
  EXPECT_LT(along_edge(detect(board, 3, 0.5, 0.25), 181), 100) << "which has no twin, and is dropped";
}

// A camera looking down at the turf (a Humanoid robot's head tilted to the ball at its feet) has
// no far rows: the wide line's edges on that turf, 40 px wide in rows 60-132, are drawn by the
// coarse pass from the frame's top when the field boundary is measured and the turf fills the
// top. With a wall across the top rows, the field's edge is in view: those rows are far, and only
// the full scale draws there, which breaks up on this turf.
TEST(CoarsePass, LookingDownAtTheTurfItsBandStartsAtTheFramesTop) {
  const auto frame_with = [](bool wall) {
    cv::Mat clean = turf_with_a_ragged_line(60, 40);
    if (wall) clean(cv::Rect(0, 0, 640, 30)).setTo(cv::Scalar(40, 40, 40));
    return test::noisy(clean);
  };
  const auto edges = [](const cv::Mat& frame, bool boundary, bool* fills_top = nullptr) {
    DetectorParams p;
    p.coarse_scale = 3;
    LineDetector detector(p);
    detector.set_find_field_boundary(boundary);
    const std::vector<Segment> segments = detector.detect(frame);
    if (fills_top) *fills_top = detector.field_boundary().fills_top();
    return along_edge(segments, 61) + along_edge(segments, 101);
  };
  bool fills_top = false;
  EXPECT_GT(edges(frame_with(false), true, &fills_top), 900) << "the coarse pass draws both edges end to end";
  EXPECT_TRUE(fills_top);
  EXPECT_LT(edges(frame_with(false), false), 100) << "without the boundary the band starts at coarse_from";
  EXPECT_LT(edges(frame_with(true), true, &fills_top), 100) << "the field's edge in view: these rows are far";
  EXPECT_FALSE(fills_top);
}

// A painted line's two edges, sharp at the full scale, stay two segments with the coarse pass:
// the coarse ones along them are dropped.
TEST(CoarsePass, OnePaintedEdgeStaysOneSegment) {
  cv::Mat clean(480, 640, CV_8UC3, test::kTurf);
  cv::line(clean, {40, 400}, {600, 430}, test::kPaint, 12);
  const cv::Mat frame = test::noisy(clean);
  EXPECT_EQ(detect(frame, 2).size(), detect(frame, 1).size());
}

// A far line one pixel wide above the coarse band is found exactly as without it.
TEST(CoarsePass, AFarOnePixelLineIsStillFound) {
  cv::Mat clean(480, 640, CV_8UC3, test::kTurf);
  cv::line(clean, {40, 80}, {600, 95}, test::kPaint, 1);
  const cv::Mat frame = test::noisy(clean);
  const std::vector<Segment> fine = detect(frame, 1), coarse = detect(frame, 2);
  ASSERT_FALSE(fine.empty());
  ASSERT_EQ(coarse.size(), fine.size());
  for (std::size_t i = 0; i < fine.size(); ++i) EXPECT_EQ(coarse[i].x0, fine[i].x0);
}

// Calibration turns the coarse pass on where it adds stripes (a wide near line breaking up on
// textured turf) and leaves it off where the full scale draws the lines already.
TEST(CoarsePass, CalibrationChoosesItWhereNearLinesBreakUp) {
  const DetectorCalibrationParams rule;
  FieldContrast textured(rule, DetectorParams{});
  for (int i = 0; i < 2; ++i) textured.add_image(textured_turf_with_a_near_line());
  EXPECT_GE(textured.coarse_gain(), rule.min_coarse_gain);
  const DetectorParams chosen = calibrated_detector(DetectorParams{}, textured, rule);
  EXPECT_EQ(chosen.coarse_scale, rule.coarse_scale);
  EXPECT_EQ(chosen.thin_reach, 0) << "the thin-line pass would draw the turf's blades";
  cv::Mat clean(480, 640, CV_8UC3, test::kTurf);
  cv::line(clean, {40, 400}, {600, 430}, test::kPaint, 12);
  cv::line(clean, {40, 120}, {600, 130}, test::kPaint, 3);
  FieldContrast plain(rule, DetectorParams{});
  plain.add_image(test::noisy(clean));
  EXPECT_LT(plain.coarse_gain(), rule.min_coarse_gain);
  EXPECT_EQ(calibrated_detector(DetectorParams{}, plain, rule).coarse_scale, 1);
  EXPECT_EQ(calibrated_detector(DetectorParams{}, plain, rule).thin_reach, rule.thin_reach);
  // Without the measurement (the one-argument constructor) it is never chosen.
  FieldContrast unmeasured(rule);
  unmeasured.add_image(textured_turf_with_a_near_line());
  EXPECT_EQ(unmeasured.coarse_gain(), 0);
}

// This machine may take the AVX2 kernel for cells of 3 px; the portable one (what an arm64 robot
// runs) must average them to the same bits: the same segments on textured turf, on frames whose
// coarse width is whole blocks of 64 cells and not (the kernel leaves the rest to the other).
TEST(CoarsePass, BaselineCellsAverageWhatAvx2Averages) {
  const cv::Mat frame = textured_turf_with_a_near_line();
  DetectorParams p;
  p.coarse_scale = 3;
  p.coarse_from = 0.3;
  for (const int width : {640, 613, 576, 200, 9}) {
    const cv::Mat cropped = frame(cv::Rect(0, 0, width, 480)).clone();
    LineDetector fast(p);
    ::setenv("FIELDLINES_NO_AVX2", "1", 1);
    LineDetector baseline(p);  // reads the switch when built
    ::unsetenv("FIELDLINES_NO_AVX2");
    const std::vector<Segment> a = fast.detect(cropped), b = baseline.detect(cropped);
    ASSERT_EQ(a.size(), b.size()) << width << " px";
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].x0, b[i].x0) << width << " px, segment " << i;
      EXPECT_EQ(a[i].y1, b[i].y1);
      EXPECT_EQ(a[i].saliency, b[i].saliency);
      EXPECT_EQ(a[i].grad_x, b[i].grad_x);
    }
  }
}

TEST(CoarsePass, BandsTooSmallForTheScaleAreLeftOut) {
  const cv::Mat frame = test::noisy(cv::Mat(480, 640, CV_8UC3, test::kTurf));
  EXPECT_NO_THROW(detect(frame, 8, 1.0));   // an empty band
  EXPECT_NO_THROW(detect(frame, 8, 0.97));  // a band of 1 coarse row
  const cv::Mat tiny = test::noisy(cv::Mat(5, 5, CV_8UC3, test::kTurf));
  EXPECT_NO_THROW(detect(tiny, 2, 0));
}

}  // namespace
}  // namespace fieldlines
