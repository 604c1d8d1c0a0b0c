// The thin-line pass's far lines along the field boundary (DetectorParams::thin_along_boundary,
// along_boundary.hpp): a far line too faint for any one column, a few pixels below a dark wall,
// is found on the profile averaged along the boundary; not without the boundary, not when its
// colours can be no marking's, and not in random pixels.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "painted_field.hpp"

#include "fieldlines/detect/detector.hpp"

namespace fieldlines {
namespace {

// Paint seen 4 % of the way from turf to white: 7 grey levels over the turf, under the thin-line
// pass's ridge threshold (gradient_threshold / 4 = 7.5) once smoothed, over its averaged one (3).
const cv::Scalar kFaintPaint(test::kTurf[0] + 0.04 * (255 - test::kTurf[0]), test::kTurf[1] + 0.04 * (255 - test::kTurf[1]),
                             test::kTurf[2] + 0.04 * (255 - test::kTurf[2]));

// The wall's foot and the line's centre, 7 px below it, 2 px wide from x = 40 to 600.
double wall_foot(double x) { return 90 + 10.0 / 640 * x; }
double centre_y(double x) { return wall_foot(x) + 7; }

cv::Mat far_line_below_a_wall(bool line = true) {
  cv::Mat clean(480, 640, CV_8UC3, test::kTurf);
  const std::vector<cv::Point> wall{{0, 0}, {639, 0}, {639, cvRound(wall_foot(639))}, {0, cvRound(wall_foot(0))}};
  cv::fillConvexPoly(clean, wall, test::kDark);
  if (line)
    cv::line(clean, {40 * 16, cvRound(centre_y(40) * 16)}, {600 * 16, cvRound(centre_y(600) * 16)}, kFaintPaint, 2,
             cv::LINE_AA, 4);
  return test::noisy(clean);
}

// What calibration runs on a venue with far lines (detector_calibration.hpp): the thin-line pass
// at reach 2 over the upper 0.6, the far lines along the boundary within `along` of the height.
DetectorParams venue_detector(double along) {
  DetectorParams p;
  p.gaussian_kernel = 5;
  p.scan_interval = 2;
  p.min_line_length = 25;
  p.thin_reach = 2;
  p.thin_to = 0.6;
  p.thin_along_boundary = along;
  return p;
}

// A marking class that takes the faint line's colours (white over turf, weak), no boundary
// class; markings kept below the field boundary (what calibration writes).
Thresholds faint_markings(bool gate = true) {
  Thresholds t;
  t.marking.thresholds = {2.f, 30.f, 0.f};
  t.boundary.thresholds = {1e6f, 0.f, 1e6f};
  t.field_boundary_gate = gate;
  return t;
}

// The length of the segments whose ends both lie within 1 px of the line's centre.
double on_centre_length(const std::vector<Segment>& segments) {
  double length = 0;
  for (const Segment& s : segments)
    if (std::abs(s.y0 - centre_y(s.x0)) <= 1 && std::abs(s.y1 - centre_y(s.x1)) <= 1)
      length += std::hypot(s.x1 - s.x0, s.y1 - s.y0);
  return length;
}

TEST(AlongBoundary, AFarLineTooFaintForTheThinPassIsFoundBelowTheWall) {
  const cv::Mat frame = far_line_below_a_wall();
  LineDetector without(venue_detector(0), faint_markings()), with(venue_detector(0.05), faint_markings());
  const std::vector<Segment> before = without.detect(frame), after = with.detect(frame);
  ASSERT_FALSE(with.field_boundary().empty());
  EXPECT_EQ(on_centre_length(before), 0) << "no column's ridge reaches the thin pass's threshold";
  EXPECT_GT(on_centre_length(after), 450) << "most of its 560 px";
  // The found pieces are markings, along lines' centres (never a boundary), and come last.
  ASSERT_GT(after.size(), before.size());
  EXPECT_LE(with.centre_lines_from(), before.size());
  for (std::size_t i = before.size(); i < after.size(); ++i) {
    EXPECT_EQ(after[i].label, Label::Marking);
    EXPECT_LE(std::abs(after[i].y0 - centre_y(after[i].x0)), 1);
  }
}

// The same frame without the line: the wall's foot and the turf give nothing along it.
TEST(AlongBoundary, NoLineNoSegment) {
  const cv::Mat frame = far_line_below_a_wall(false);
  LineDetector without(venue_detector(0), faint_markings()), with(venue_detector(0.05), faint_markings());
  EXPECT_EQ(with.detect(frame).size(), without.detect(frame).size());
}

// Without the field boundary (no gate, no features) there is nothing to look along.
TEST(AlongBoundary, NotWithoutTheFieldBoundary) {
  const cv::Mat frame = far_line_below_a_wall();
  LineDetector without(venue_detector(0), faint_markings(false)), with(venue_detector(0.05), faint_markings(false));
  const std::vector<Segment> before = without.detect(frame), after = with.detect(frame);
  EXPECT_TRUE(with.field_boundary().empty());
  EXPECT_EQ(after.size(), before.size());
}

// A piece whose colours can be no marking's (here: no marking class) is not reported: a faint
// ridge the classes call none is the turf's texture as often as paint.
TEST(AlongBoundary, OnlyWhatMayBeAMarkingIsReported) {
  const cv::Mat frame = far_line_below_a_wall();
  Thresholds none = faint_markings();
  none.marking.thresholds = {1e6f, 0.f, 1e6f};
  LineDetector without(venue_detector(0), none), with(venue_detector(0.05), none);
  EXPECT_EQ(with.detect(frame).size(), without.detect(frame).size());
}

// Random pixels: whatever field colour and boundary they yield, the profile's noise (its median
// bend) keeps every window's ridges under the threshold.
TEST(AlongBoundary, RandomPixelsHaveNoLines) {
  Thresholds any = faint_markings();
  any.marking.thresholds = {0.f, 90.f, 0.f};
  LineDetector without(venue_detector(0), any), with(venue_detector(0.05), any);
  cv::Mat noise(240, 320, CV_8UC3);
  cv::RNG rng(11);
  for (int i = 0; i < 4; ++i) {
    rng.fill(noise, cv::RNG::UNIFORM, 0, 255);
    EXPECT_EQ(with.detect(noise).size(), without.detect(noise).size()) << "frame " << i;
  }
}

}  // namespace
}  // namespace fieldlines
