// The thin-line pass (DetectorParams::thin_reach): a far line a few pixels below a dark wall,
// whose upper edge the wall's own edge swallows, gets a segment along its centre carrying the
// turf-to-paint colours; where both of a line's edges have segments, or below the pass's band,
// nothing changes; the SSE2 / NEON kernels give what the AVX2 ones give; calibration turns it on.
#include <algorithm>
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

// White paint seen a quarter of the way from turf to white: a far line's low contrast.
const cv::Scalar kFaintPaint(test::kTurf[0] + 0.25 * (255 - test::kTurf[0]), test::kTurf[1] + 0.25 * (255 - test::kTurf[1]),
                             test::kTurf[2] + 0.25 * (255 - test::kTurf[2]));

// The line's centre runs from (40, 100) to (600, 112), 2 px wide; with `wall`, a dark wall ends
// 3 px above it (as the SSL lab's far lines run along the wall's foot).
double centre_y(double x) { return 100 + 12.0 / 560 * (x - 40); }

// With `field_from`, turf only from that row down under a dark band 40 px high: the line lies
// on a turf-green strip off the field (a poster on the wall, the next field beyond a floor strip).
cv::Mat far_line(bool wall, int width = 2, int field_from = 0) {
  cv::Mat clean(480, 640, CV_8UC3, test::kTurf);
  if (wall) {
    const int top = 3 + width / 2 + 1;
    const std::vector<cv::Point> dark{{0, 0}, {639, 0}, {639, cvRound(centre_y(639)) - top}, {0, cvRound(centre_y(0)) - top}};
    cv::fillConvexPoly(clean, dark, test::kDark);
  }
  if (field_from > 40) clean(cv::Rect(0, field_from - 40, 640, 40)).setTo(test::kDark);
  cv::line(clean, {40, 100}, {600, 112}, kFaintPaint, width, cv::LINE_AA);
  return test::noisy(clean);
}

// What calibration runs (detector_calibration.hpp), without and with the pass at `thin_reach`.
DetectorParams venue_detector(int thin_reach, double thin_to = 0.6) {
  DetectorParams p;
  p.gaussian_kernel = 5;
  p.scan_interval = 2;
  p.min_line_length = 25;
  p.thin_reach = thin_reach;
  p.thin_to = thin_to;
  return p;
}

// The segments whose ends both lie within `reach` px of the line's centre.
std::vector<Segment> on_centre(const std::vector<Segment>& segments, double reach) {
  std::vector<Segment> out;
  for (const Segment& s : segments)
    if (std::abs(s.y0 - centre_y(s.x0)) <= reach && std::abs(s.y1 - centre_y(s.x1)) <= reach) out.push_back(s);
  return out;
}

TEST(ThinPass, AFarLineBelowAWallGetsASegmentAlongItsCentre) {
  const cv::Mat frame = far_line(true);
  LineDetector plain(venue_detector(0)), thin(venue_detector(2));
  const std::vector<Segment> without = plain.detect(frame), with = thin.detect(frame);
  EXPECT_TRUE(on_centre(without, 0.75).empty()) << "the edges alone: the wall's and the line's lower one";
  const std::vector<Segment> centre = on_centre(with, 0.75);
  ASSERT_EQ(centre.size(), 1u);
  const Segment& s = centre.front();
  EXPECT_GT(std::hypot(s.x1 - s.x0, s.y1 - s.y0), 500) << "end to end";
  // Its colours are the line's against the turf beside it, along the normal (down): what an
  // edge from turf to paint carries, the red and blue rising more than the green.
  const Rgb rise{static_cast<float>(kFaintPaint[2] - test::kTurf[2]), static_cast<float>(kFaintPaint[1] - test::kTurf[1]),
                 static_cast<float>(kFaintPaint[0] - test::kTurf[0])};
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(s.grad_y[c], 0.4f * rise[c]) << "channel " << c;
    EXPECT_LT(s.grad_y[c], 1.2f * rise[c]) << "channel " << c;
  }
  EXPECT_GT(s.grad_y[0], s.grad_y[1]);
  EXPECT_EQ(with.size(), without.size() + 1) << "the rest as without the pass";
}

// A line's centre is no edge of the field: with a boundary class that takes every colour
// transition (and no marking class), the wall's edge is a boundary and the centre segment none.
TEST(ThinPass, ACentreSegmentIsNeverABoundary) {
  Thresholds any_boundary;
  any_boundary.boundary.two_sided = true;
  any_boundary.boundary.thresholds = {0.f, 90.f, 0.f};
  any_boundary.marking.thresholds = {1e6f, 0.f, 1e6f};
  const cv::Mat frame = far_line(true);
  LineDetector plain(venue_detector(0), any_boundary), thin(venue_detector(2), any_boundary);
  const std::vector<Segment> without = plain.detect(frame), with = thin.detect(frame);
  ASSERT_EQ(with.size(), without.size() + 1);
  EXPECT_TRUE(std::any_of(without.begin(), without.end(), [](const Segment& s) { return s.label == Label::Boundary; }));
  const std::vector<Segment> centre = on_centre(with, 0.75);
  ASSERT_EQ(centre.size(), 1u);
  EXPECT_EQ(centre.front().label, Label::None);
}

// A line whose two edges both have segments gets no third one along its centre: one painted
// edge, one segment.
TEST(ThinPass, ALineWithBothEdgesDrawnGetsNoCentreSegment) {
  const cv::Mat frame = far_line(false, 3);
  LineDetector plain(venue_detector(0)), thin(venue_detector(2));
  const std::vector<Segment> without = plain.detect(frame), with = thin.detect(frame);
  ASSERT_EQ(on_centre(without, 3).size(), 2u) << "both edges drawn";
  EXPECT_EQ(with.size(), without.size());
}

// Below thin_to the pass draws nothing: the same segments as without it.
TEST(ThinPass, BelowItsBandNothingChanges) {
  const cv::Mat frame = far_line(true);
  LineDetector plain(venue_detector(0)), thin(venue_detector(2, 0.15));  // rows above 72: the wall's
  const std::vector<Segment> without = plain.detect(frame), with = thin.detect(frame);
  ASSERT_EQ(with.size(), without.size());
  for (std::size_t i = 0; i < with.size(); ++i) EXPECT_EQ(with[i].x0, without[i].x0);
}

// With the field boundary gating the markings, the pass draws from a band above the field's top
// down (a marking above it would be none): the far line on a strip of turf above the field,
// beyond a dark band, gets no centre segment, and the rest is as without the pass. Without the
// gate it gets one; with the gate and the field reaching up to the wall, it does too.
TEST(ThinPass, WithTheBoundaryGateItDrawsFromTheFieldsTopDown) {
  Thresholds gated;
  gated.field_boundary_gate = true;
  LineDetector plain(venue_detector(0), gated), thin(venue_detector(2), gated), ungated(venue_detector(2));
  const cv::Mat off_field = far_line(true, 2, 200);
  const std::vector<Segment> without = plain.detect(off_field), with = thin.detect(off_field);
  ASSERT_FALSE(thin.field_boundary().empty());
  EXPECT_NEAR(thin.field_boundary().y_at(320), 200, 4) << "the field's top: the strip is off the field";
  EXPECT_TRUE(on_centre(with, 0.75).empty());
  EXPECT_EQ(with.size(), without.size());
  EXPECT_EQ(on_centre(ungated.detect(off_field), 0.75).size(), 1u);
  EXPECT_EQ(on_centre(thin.detect(far_line(true)), 0.75).size(), 1u);
}

// This machine may take the AVX2 ridge rows; the SSE2 / NEON ones (what an arm64 robot runs)
// must draw the same segments, on frames of awkward widths, each reach.
TEST(ThinPass, BaselineKernelsDrawWhatAvx2Draws) {
  for (const int width : {640, 613, 37, 50}) {
    cv::Mat frame = far_line(true);
    frame = frame(cv::Rect(0, 0, width, 200)).clone();
    for (const int reach : {1, 2, 3, 8}) {
      LineDetector fast(venue_detector(reach, 1.0));
      ::setenv("FIELDLINES_NO_AVX2", "1", 1);
      LineDetector baseline(venue_detector(reach, 1.0));  // reads the switch when built
      ::unsetenv("FIELDLINES_NO_AVX2");
      const std::vector<Segment> a = fast.detect(frame), b = baseline.detect(frame);
      ASSERT_EQ(a.size(), b.size()) << width << " px, reach " << reach;
      for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].x0, b[i].x0);
        EXPECT_EQ(a[i].y1, b[i].y1);
        EXPECT_EQ(a[i].saliency, b[i].saliency);
        EXPECT_EQ(a[i].grad_y, b[i].grad_y);
      }
    }
  }
}

// A detector reused on frames of other sizes clears what the last frame left: the segments are
// those of a fresh detector. The widths are no multiples of each other, so that what one frame
// wrote lies elsewhere in the other's rows: beside one frame's line, another's many lines left
// there would be drawn on.
TEST(ThinPass, AReusedDetectorDrawsWhatAFreshOneDraws) {
  LineDetector reused(venue_detector(2));
  const cv::Mat wall = far_line(true), small = far_line(true)(cv::Rect(0, 0, 320, 240)).clone();
  const cv::Mat odd = far_line(true)(cv::Rect(17, 0, 613, 300)).clone();
  cv::Mat lines(480, 640, CV_8UC3, test::kTurf);
  for (int y = 20; y < 280; y += 9) cv::line(lines, {0, y}, {639, y + 40}, kFaintPaint, 2, cv::LINE_AA);
  const cv::Mat many = test::noisy(lines);
  for (const cv::Mat* f : {&wall, &small, &wall, &many, &odd, &small, &many, &odd, &wall}) {
    LineDetector fresh(venue_detector(2));
    const std::vector<Segment> a = reused.detect(*f), b = fresh.detect(*f);
    ASSERT_EQ(a.size(), b.size()) << f->cols;
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].y0, b[i].y0);
  }
}

// The pass's anchors lie on a lattice of the grid's columns and rows (ridge_anchor_lattice):
// a short far line below a wall (as far_line), level or upright, gets its centre segment
// wherever it lies against the lattice, at every offset of the lattice's period along it and
// on every grid row (column) across it. A grid thinned both ways would miss a level line lying
// between its rows. (A level ridge one pixel thick between the grid's own rows has no anchor
// with the whole grid either: the method's grid.)
TEST(ThinPass, AShortLineIsFoundWhereverItLiesAgainstTheAnchorLattice) {
  const DetectorParams params = venue_detector(2);
  // The lattice at the pass's minimum length (18: 0.7 of 25): 12.7 px apart at most.
  const int period = params.scan_interval * 6;
  for (const bool level : {true, false}) {
    for (int offset = 0; offset < period; ++offset) {
      // Drawn level, 40 px long and 2 px wide, the wall's foot 4 px above it; upright: transposed.
      const int along = 200 + offset, across = 1 + params.scan_interval * (50 + offset);
      cv::Mat clean(480, 640, CV_8UC3, test::kTurf);
      cv::rectangle(clean, {0, 0}, {639, across - 5}, test::kDark, cv::FILLED);
      cv::line(clean, {along, across}, {along + 40, across}, kFaintPaint, 2, cv::LINE_AA);
      if (!level) clean = clean.t();
      const std::vector<Segment> found = LineDetector(params).detect(test::noisy(clean));
      const bool centre = std::any_of(found.begin(), found.end(), [&](const Segment& s) {
        const float a0 = level ? s.y0 : s.x0, a1 = level ? s.y1 : s.x1;  // across the line
        return std::abs(a0 - static_cast<float>(across)) <= 1 && std::abs(a1 - static_cast<float>(across)) <= 1 &&
               std::hypot(s.x1 - s.x0, s.y1 - s.y0) >= 25;
      });
      EXPECT_TRUE(centre) << (level ? "level" : "upright") << " line at offset " << offset;
    }
  }
}

// A far line seen between two robots standing on it: a piece shorter than the detector's minimum
// length (25 px) but not than the pass's (0.7 of it) gets its centre segment, below a wall as
// in the lattice's test; the detector's own pass draws nothing there.
TEST(ThinPass, AFarLinesPieceShorterThanTheMinimumLengthIsFound) {
  const int across = 101, from = 201, to = 220;
  cv::Mat clean(480, 640, CV_8UC3, test::kTurf);
  cv::rectangle(clean, {0, 0}, {639, across - 5}, test::kDark, cv::FILLED);
  cv::line(clean, {from, across}, {to, across}, kFaintPaint, 2, cv::LINE_AA);
  cv::rectangle(clean, {from - 60, across - 6}, {from - 3, across + 60}, test::kDark, cv::FILLED);
  cv::rectangle(clean, {to + 3, across - 6}, {to + 60, across + 60}, test::kDark, cv::FILLED);
  const cv::Mat frame = test::noisy(clean);
  const auto pieces = [&](const std::vector<Segment>& found) {
    return std::count_if(found.begin(), found.end(), [&](const Segment& s) {
      return std::abs(s.y0 - float(across)) <= 1 && std::abs(s.y1 - float(across)) <= 1 &&
             std::hypot(s.x1 - s.x0, s.y1 - s.y0) >= 15;
    });
  };
  EXPECT_EQ(pieces(LineDetector(venue_detector(0)).detect(frame)), 0);
  EXPECT_EQ(pieces(LineDetector(venue_detector(2)).detect(frame)), 1);
}

TEST(ThinPass, CalibrationTurnsItOn) {
  const DetectorCalibrationParams rule;
  FieldContrast contrast(rule, DetectorParams{});
  contrast.add_image(far_line(true));
  const DetectorParams chosen = calibrated_detector(DetectorParams{}, contrast, rule);
  EXPECT_EQ(chosen.thin_reach, rule.thin_reach);
  EXPECT_EQ(chosen.thin_to, rule.thin_to);
  EXPECT_EQ(DetectorParams{}.thin_reach, 0) << "the method's detector has no such pass";
}

TEST(ThinPass, TinyFramesAndEmptyBandsAreLeftOut) {
  const cv::Mat tiny = test::noisy(cv::Mat(5, 5, CV_8UC3, test::kTurf));
  EXPECT_NO_THROW(LineDetector(venue_detector(8, 1.0)).detect(tiny));
  EXPECT_NO_THROW(LineDetector(venue_detector(2, 0.0)).detect(far_line(true)));
  const cv::Mat narrow = test::noisy(cv::Mat(480, 9, CV_8UC3, test::kTurf));
  EXPECT_NO_THROW(LineDetector(venue_detector(8, 1.0)).detect(narrow));
}

}  // namespace
}  // namespace fieldlines
