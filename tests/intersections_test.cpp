// Intersections (intersections.hpp) on synthetic frames with known answers: a T, an X and an L
// of painted lines on turf, each found once with its type, centre and ray headings; pieces of
// one junction merge; an acute far corner is an L and a curve's chords are none, nor the centre
// circle's; bad input gives none and never crashes.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "painted_field.hpp"

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/intersections.hpp"

namespace fieldlines {
namespace {

using test::kPaint, test::kTurf, test::noisy;
constexpr float kPi = std::numbers::pi_v<float>;

DetectorParams intersections_on() {
  DetectorParams p;
  p.intersections = true;
  return p;
}

std::vector<Intersection> junctions(const cv::Mat& frame, const DetectorParams& params = intersections_on()) {
  LineDetector detector(params);
  std::vector<Segment> segments;
  detector.detect(frame, segments);
  return detector.features().intersections;
}

float heading(cv::Point2f from, cv::Point2f to) {
  const float h = std::atan2(to.y - from.y, to.x - from.x);
  return h < 0 ? h + 2 * kPi : h;
}

float angle_between(float a, float b) {
  const float d = std::abs(a - b);
  return std::min(d, 2 * kPi - d);
}

// One junction at `centre` of `type` whose rays point at `ends` (any order).
void expect_junction(const std::vector<Intersection>& found, cv::Point2f centre, JunctionType type,
                     const std::vector<cv::Point2f>& ends, float width) {
  ASSERT_EQ(found.size(), 1u);
  const Intersection& j = found[0];
  EXPECT_EQ(j.type, type);
  EXPECT_EQ(j.num_rays, static_cast<int>(ends.size()));
  EXPECT_LE(std::hypot(j.x - centre.x, j.y - centre.y), 0.5f * width + 2) << j.x << ", " << j.y;
  EXPECT_GT(j.confidence, 0.5f);
  EXPECT_LE(j.confidence, 1.f);
  for (int k = 1; k < j.num_rays; ++k) EXPECT_LT(j.heading_rays[k - 1], j.heading_rays[k]) << "ascending";
  for (int k = 0; k < j.num_rays; ++k) {
    EXPECT_GE(j.heading_rays[k], 0.f);
    EXPECT_LT(j.heading_rays[k], 2 * kPi);
  }
  for (const cv::Point2f& end : ends) {
    const float want = heading(centre, end);
    float best = 10;
    for (int k = 0; k < j.num_rays; ++k) best = std::min(best, angle_between(j.heading_rays[k], want));
    EXPECT_LT(best, 0.06f) << "no ray towards " << end;
  }
}

TEST(Intersections, AT) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const cv::Point2f left(60, 150), right(590, 170), foot(300, 440);
  const cv::Point2f centre(320, 150 + 20.f * 260 / 530);  // on the bar, above the foot
  cv::line(clean, left, right, kPaint, 8);
  cv::line(clean, centre, foot, kPaint, 8);
  expect_junction(junctions(noisy(clean)), centre, JunctionType::T, {left, right, foot}, 8);
}

TEST(Intersections, AnX) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const cv::Point2f a0(60, 110), a1(590, 380), b0(120, 430), b1(520, 40);
  cv::line(clean, a0, a1, kPaint, 9);
  cv::line(clean, b0, b1, kPaint, 9);
  // Where a0-a1 crosses b0-b1.
  const cv::Point2f da = a1 - a0, db = b1 - b0, w = b0 - a0;
  const float t = (w.x * db.y - w.y * db.x) / (da.x * db.y - da.y * db.x);
  const cv::Point2f centre = a0 + t * da;
  expect_junction(junctions(noisy(clean, 3)), centre, JunctionType::X, {a0, a1, b0, b1}, 9);
}

TEST(Intersections, AnL) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const cv::Point2f corner(120, 380), along(600, 350), up(180, 60);
  cv::line(clean, corner, along, kPaint, 10);
  cv::line(clean, corner, up, kPaint, 10);
  expect_junction(junctions(noisy(clean, 5)), corner, JunctionType::L, {along, up}, 10);
}

// Pale paint whose edges lie between the class's colour cut and the grey angle (a grey-green
// carpet, white balance off): the pieces are stripes, so they still make the junction.
TEST(Intersections, PalePaintBeyondTheColourCutStillMeets) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const cv::Point2f corner(120, 380), along(600, 350), up(180, 60);
  cv::line(clean, corner, along, kPaint, 10);
  cv::line(clean, corner, up, kPaint, 10);
  Thresholds tight;
  const double paint_angle = 21.2;  // kPaint on kTurf, to the white-on-green transition
  tight.marking.thresholds.max_angle_deg = 15;
  ASSERT_LT(tight.marking.thresholds.max_angle_deg, paint_angle);
  ASSERT_GT(achromatic_angle_deg(tight.marking), paint_angle);
  LineDetector detector(intersections_on(), tight);
  std::vector<Segment> segments;
  detector.detect(noisy(clean, 5), segments);
  expect_junction(detector.features().intersections, corner, JunctionType::L, {along, up}, 10);
}

// A far line in haze: paint blended towards the turf's green, too green for the pieces' anchors
// (their grey limit keeps turf texture out), while the detector's own drawing has no such limit.
// Its segments, which no piece lies along, are lines for the junctions too.
// The pieces are drawn for the centre circle, so it is on here.
TEST(Intersections, PaintTooGreenForThePiecesStillMeetsThroughTheDetectorsSegments) {
  const cv::Scalar haze(120, 190, 120);  // B, G, R: brighter than the turf, far from grey
  const double sum = haze[0] + haze[1] + haze[2];
  const double chroma = std::abs(haze[2] / sum - 1.0 / 3) + std::abs(haze[1] / sum - 1.0 / 3);
  ASSERT_GT(chroma, FieldBoundaryParams{}.paint_chroma) << "the pieces' anchors must refuse this paint";
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const cv::Point2f corner(120, 380), along(600, 350), up(180, 60);
  cv::line(clean, corner, along, kPaint, 10);
  cv::line(clean, corner, up, haze, 10);
  const cv::Mat frame = noisy(clean, 5);
  DetectorParams params = intersections_on();
  params.centre_circle = true;
  LineDetector detector(params);
  std::vector<Segment> segments;
  detector.detect(frame, segments);
  const auto runs_up = [&](const Segment& s) {
    return std::abs(s.x1 - s.x0) < 0.3f * std::abs(s.y1 - s.y0) && std::abs(s.y1 - s.y0) > 100;
  };
  ASSERT_TRUE(std::any_of(segments.begin(), segments.end(), runs_up)) << "the detector's drawing finds the hazy line";
  expect_junction(detector.features().intersections, corner, JunctionType::L, {along, up}, 10);
}

// The centre circle in perspective with the halfway line through it, the circle stage off (no
// second drawing: the detector's own segments are the lines): the segments along the ring are
// chords that bend into each other, so they make no junction; the circle's crossings with the
// line count neither way.
TEST(Intersections, TheCirclesChordsMakeNoJunctions) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const cv::Point2f centre(330, 260);
  const cv::Size2f axes(250, 90);
  cv::ellipse(clean, centre, axes, 0, 0, 360, kPaint, 6, cv::LINE_AA);
  cv::line(clean, cv::Point(10, 255), cv::Point(630, 265), kPaint, 6, cv::LINE_AA);
  LineDetector detector(intersections_on());
  std::vector<Segment> segments;
  detector.detect(noisy(clean, 11), segments);
  const auto on_ring = [&](const Segment& s) {
    const auto off = [&](float x, float y) {
      return std::abs(std::hypot((x - centre.x) / axes.width, (y - centre.y) / axes.height) - 1);
    };
    return off(s.x0, s.y0) < 0.05f && off(s.x1, s.y1) < 0.05f;
  };
  ASSERT_GE(std::count_if(segments.begin(), segments.end(), on_ring), 4) << "the detector draws the ring";
  for (const Intersection& j : detector.features().intersections) {
    const bool at_crossing = std::abs(j.y - 260) < 12 && (std::abs(j.x - 80) < 12 || std::abs(j.x - 580) < 12);
    EXPECT_TRUE(at_crossing) << to_string(j.type) << " at " << j.x << ", " << j.y;
  }
}

TEST(Intersections, ParallelAndDistantLinesMeetNowhere) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  cv::line(clean, cv::Point(60, 100), cv::Point(590, 120), kPaint, 8);
  cv::line(clean, cv::Point(60, 300), cv::Point(590, 330), kPaint, 8);
  // Steep, but ending far from where it would meet the lower line.
  cv::line(clean, cv::Point(300, 160), cv::Point(330, 230), kPaint, 8);
  EXPECT_TRUE(junctions(noisy(clean, 9)).empty());
}

// Pieces of centre lines as the stripes give them: an X whose lines are broken at the crossing
// is one X, not four Ls; a T with the bar in two pieces is one T.
TEST(Intersections, PiecesOfOneJunctionMerge) {
  IntersectionWorkspace work;
  std::vector<Intersection> out;
  const std::vector<Marking> x{{100, 200, 194, 200, 6}, {206, 200, 300, 201, 6},
                               {200, 100, 200, 194, 6}, {201, 206, 200, 300, 6}};
  find_intersections(x, intersections_on(), work, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].type, JunctionType::X);
  EXPECT_NEAR(out[0].x, 200, 2);
  EXPECT_NEAR(out[0].y, 200, 2);

  const std::vector<Marking> t{{100, 200, 196, 200, 6}, {300, 200, 204, 200, 6}, {200, 206, 200, 320, 6}};
  find_intersections(t, intersections_on(), work, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].type, JunctionType::T);
  EXPECT_NEAR(out[0].heading_rays[0], 0, 0.02);
  EXPECT_NEAR(out[0].heading_rays[1], kPi / 2, 0.02) << "pi/2 is image down";
  EXPECT_NEAR(out[0].heading_rays[2], kPi, 0.02);

  find_intersections({}, intersections_on(), work, out);
  EXPECT_TRUE(out.empty());
}

// A far corner in perspective: two long arms 20 degrees apart are an L; a short stub 16 degrees
// off an arm (the next chord of a curve overlapping the last) is no junction.
TEST(Intersections, AnAcuteFarCornerIsAnLAndACurveIsNot) {
  IntersectionWorkspace work;
  std::vector<Intersection> out;
  const float t = 20 * kPi / 180;
  const std::vector<Marking> corner{{100, 200, 400, 200, 3}, {100, 200, 100 + 300 * std::cos(t), 200 - 300 * std::sin(t), 3}};
  find_intersections(corner, intersections_on(), work, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].type, JunctionType::L);
  EXPECT_NEAR(out[0].x, 100, 2);
  EXPECT_NEAR(out[0].y, 200, 2);

  const float s = 16 * kPi / 180;
  const std::vector<Marking> chords{{100, 200, 312, 200, 3}, {300, 200, 300 + 100 * std::cos(s), 200 + 100 * std::sin(s), 3}};
  find_intersections(chords, intersections_on(), work, out);
  EXPECT_TRUE(out.empty());
}

TEST(Intersections, OutOfTheFrameIsOutOfView) {
  IntersectionWorkspace work;
  std::vector<Intersection> out;
  const std::vector<Marking> l{{2, 100, 2, 300, 6}, {-10, 100, 200, 100, 6}};  // corner at x = 2
  find_intersections(l, intersections_on(), work, out, cv::Size(320, 240));
  EXPECT_EQ(out.size(), 1u);
  const std::vector<Marking> out_left{{-9, 100, -9, 300, 6}, {-20, 100, 200, 100, 6}};  // corner at x = -9
  find_intersections(out_left, intersections_on(), work, out, cv::Size(320, 240));
  EXPECT_TRUE(out.empty());
  find_intersections(out_left, intersections_on(), work, out);
  EXPECT_EQ(out.size(), 1u) << "without a frame, wherever it is";
}

TEST(Intersections, BadInputGivesNoneAndNeverCrashes) {
  cv::Mat grey(240, 320, CV_8UC3, cv::Scalar(110, 110, 110));  // no green
  cv::line(grey, cv::Point(20, 120), cv::Point(300, 130), kPaint, 6);
  cv::line(grey, cv::Point(160, 20), cv::Point(170, 230), kPaint, 6);
  EXPECT_TRUE(junctions(noisy(grey)).empty());
  for (const cv::Size size : {cv::Size(640, 1), cv::Size(1, 480), cv::Size(3, 3), cv::Size(640, 3)}) {
    cv::Mat tiny(size, CV_8UC3, kTurf);
    cv::line(tiny, cv::Point(0, 0), cv::Point(size.width - 1, size.height - 1), kPaint, 1);
    EXPECT_NO_THROW(EXPECT_TRUE(junctions(tiny).empty())) << size;
  }
  for (const cv::Scalar& colour : {kTurf, kPaint}) EXPECT_TRUE(junctions(noisy(cv::Mat(240, 320, CV_8UC3, colour))).empty());
  // Degenerate centre lines (zero length, NaN-free) are skipped.
  IntersectionWorkspace work;
  std::vector<Intersection> out;
  const std::vector<Marking> odd{{5, 5, 5, 5, 3}, {5, 5, 5, 5, 3}, {0, 0, 100, 0, 0}, {50, -50, 50, 50, 0}};
  find_intersections(odd, intersections_on(), work, out);
  for (const Intersection& i : out) EXPECT_TRUE(std::isfinite(i.x) && std::isfinite(i.y));
}

TEST(Intersections, OffByDefault) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  cv::line(clean, cv::Point(120, 380), cv::Point(600, 350), kPaint, 10);
  cv::line(clean, cv::Point(120, 380), cv::Point(180, 60), kPaint, 10);
  EXPECT_TRUE(junctions(noisy(clean), DetectorParams{}).empty());
}

}  // namespace
}  // namespace fieldlines
