// Stripes (stripes.hpp) on synthetic frames with known answers: painted lines drawn on turf are
// markings with their centre and width; a wall or a post with turf on one side only is not; the
// centre circle's chords are no straight stripes.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "painted_field.hpp"
#include "truth_distance.hpp"

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/light.hpp"
#include "fieldlines/detect/stripes.hpp"
#include "fieldlines/synth/synth.hpp"

namespace fieldlines {
namespace {

using test::distance_to, test::kDark, test::kPaint, test::kTurf, test::noisy;

DetectorParams stripes_on(bool require_twin = false) {
  DetectorParams p;
  p.stripes = true;
  p.stripe_require_twin = require_twin;
  return p;
}

struct Detected {
  std::vector<Segment> segments;
  std::vector<Marking> markings;
};

Detected detect(const cv::Mat& frame, const DetectorParams& params = stripes_on()) {
  LineDetector detector(params);
  Detected r;
  detector.detect(frame, r.segments);
  r.markings = detector.features().markings;
  return r;
}

int count(const std::vector<Segment>& segments, Label label) {
  int n = 0;
  for (const Segment& s : segments) n += s.label == label;
  return n;
}

// Distance of (x, y) from the infinite line through a and b.
float distance_to_line(float x, float y, cv::Point2f a, cv::Point2f b) {
  const float dx = b.x - a.x, dy = b.y - a.y;
  return std::abs((x - a.x) * dy - (y - a.y) * dx) / std::hypot(dx, dy);
}

// A horizontal marking edge on row `y` from x 60 to 580, its paint below it or above.
Segment row_edge(float y, bool paint_below) {
  const float g = paint_below ? 50.f : -50.f;
  return {.x0 = 60, .y0 = y, .x1 = 580, .y1 = y, .grad_y = {g, g, g}, .label = Label::Marking};
}

// The labels find_stripes leaves on `edges`, and the markings it writes into `markings` when given.
std::vector<Label> labels_of(const cv::Mat& frame, const FieldColours& field, std::vector<Segment> edges,
                             const FieldBoundary* on_field = nullptr, std::vector<Marking>* markings = nullptr) {
  StripeWorkspace work;
  std::vector<Marking> out;
  find_stripes(frame, field, edges, stripes_on(), work, out, ThinLines::Level, Shape::Any, on_field);
  if (markings) *markings = out;
  std::vector<Label> labels;
  for (const Segment& s : edges) labels.push_back(s.label);
  return labels;
}

// The labels find_stripes leaves on row_edge()s, one per (row, paint below it).
std::vector<Label> stripe_labels(const cv::Mat& frame, const FieldColours& field,
                                 const std::vector<std::pair<float, bool>>& rows, const FieldBoundary* on_field = nullptr) {
  std::vector<Segment> edges;
  for (const auto& [y, paint_below] : rows) edges.push_back(row_edge(y, paint_below));
  return labels_of(frame, field, std::move(edges), on_field);
}

void expect_centre_line(const Marking& m, cv::Point2f a, cv::Point2f b, float width) {
  const float tolerance = 0.5f * width + 1;
  EXPECT_LE(distance_to_line(m.x0, m.y0, a, b), tolerance);
  EXPECT_LE(distance_to_line(m.x1, m.y1, a, b), tolerance);
  EXPECT_NEAR(m.width, width, 0.5f * width + 1);
}

TEST(Stripes, AWhiteLineOnTurfIsOneMarkingWithItsWidthAndCentre) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const cv::Point2f a(60, 300), b(580, 330);
  constexpr int kWidth = 9;
  cv::line(clean, a, b, kPaint, kWidth);
  const Detected r = detect(noisy(clean));
  ASSERT_EQ(r.markings.size(), 1u);
  expect_centre_line(r.markings[0], a, b, kWidth);
  EXPECT_GT(std::hypot(r.markings[0].x1 - r.markings[0].x0, r.markings[0].y1 - r.markings[0].y0), 300);
  EXPECT_EQ(count(r.segments, Label::Marking), 2) << "both edges stay markings";
}

TEST(Stripes, LinesOfSeveralWidthsAndDirections) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const cv::Point2f a0(80, 120), b0(560, 140), a1(320, 160), b1(220, 460);
  cv::line(clean, a0, b0, kPaint, 4);
  cv::line(clean, a1, b1, kPaint, 14);
  const Detected r = detect(noisy(clean, 11));
  ASSERT_GE(r.markings.size(), 2u);
  for (const Marking& m : r.markings) {
    const bool first = distance_to_line(m.x0, m.y0, a0, b0) < 10;
    SCOPED_TRACE(first ? "thin line" : "wide line");
    if (first) expect_centre_line(m, a0, b0, 4);
    else expect_centre_line(m, a1, b1, 14);
  }
}

// White that is no stripe: the colour test alone calls at least `colour_markings` of its edges
// markings; the stripe check none.
void expect_no_stripe(const cv::Mat& clean, int colour_markings) {
  const cv::Mat frame = noisy(clean);
  const Detected off = detect(frame, DetectorParams{});
  ASSERT_GE(count(off.segments, Label::Marking), colour_markings) << "the colour test alone calls its edges markings";
  const Detected on = detect(frame);
  EXPECT_EQ(count(on.segments, Label::Marking), 0);
  EXPECT_TRUE(on.markings.empty());
}

TEST(Stripes, AWhiteWallAboveTheTurfIsNoMarking) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  cv::rectangle(clean, cv::Point(0, 0), cv::Point(639, 180), kPaint, cv::FILLED);
  expect_no_stripe(clean, 1);  // the wall's foot
}

// A white board or a goal's side panel standing on the field: turf outside each edge, but white
// far beyond any plausible width inside.
TEST(Stripes, AWideWhiteBoardStandingOnTheTurfIsNoMarking) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  cv::rectangle(clean, cv::Point(0, 0), cv::Point(639, 90), kDark, cv::FILLED);
  cv::rectangle(clean, cv::Point(250, 60), cv::Point(420, 300), kPaint, cv::FILLED);
  expect_no_stripe(clean, 3);
}

// A band across the frame from row y0 (left) to y0 + 30 (right), `rows` rows tall.
void band(cv::Mat& frame, int y0, int rows, const cv::Scalar& colour) {
  const std::vector<cv::Point> corners{{0, y0}, {639, y0 + 30}, {639, y0 + 30 + rows}, {0, y0 + rows}};
  cv::fillConvexPoly(frame, corners, colour);
}

// A near wide line seen through a lens with chromatic aberration: a blue fringe along one edge
// and a yellow one along the other, darker than the turf (0.78 of it) but no robot's body.
TEST(Stripes, AWideLineWithALensColourFringeIsAStripe) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  band(clean, 320, 3, cv::Scalar(150, 30, 0));  // blue, B + G + R 180 of the turf's 230
  band(clean, 323, 26, kPaint);
  band(clean, 349, 3, cv::Scalar(0, 100, 80));  // yellow, 180 too
  const Detected r = detect(noisy(clean));
  ASSERT_GE(r.markings.size(), 1u);
  for (const Marking& m : r.markings) expect_centre_line(m, {0, 336}, {639, 366}, 26);
}

// The same line in a fisheye's vignetted corner (MSL Bangkok): the turf past it darkened to 0.6
// of the field colour and the fringe between with it, to 0.55: darker than 0.7 of the field
// colour, but not of the turf beside it. Both edges are the line's.
TEST(Stripes, AWideLineInAVignettedCornerIsAStripe) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  band(clean, 323, 26, kPaint);
  band(clean, 349, 3, cv::Scalar(90, 30, 7));                       // B + G + R 127 of the turf's 230
  band(clean, 352, 200, cv::Scalar(30, 84, 24));                    // the turf at 0.6, the same tint
  const Detected r = detect(noisy(clean));
  ASSERT_GE(r.markings.size(), 1u);
  for (const Marking& m : r.markings) expect_centre_line(m, {0, 336}, {639, 366}, 26);
}

// The same white bar with a robot's dark body (a ninth of the turf's brightness) on one side is
// no stripe, although its other edge's colours are a marking's.
TEST(Stripes, AWhiteBarBesideADarkBodyIsNoMarking) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  band(clean, 300, 23, kDark);
  band(clean, 323, 26, kPaint);
  expect_no_stripe(clean, 1);
}

// The caller's segments: one edge of a line whose other edge was not detected.
TEST(Stripes, ALineWithOneEdgeDetectedIsStillMeasured) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  constexpr int kTop = 240, kBottom = 251;  // paint rows, 12 px
  cv::rectangle(clean, cv::Point(40, kTop), cv::Point(600, kBottom), kPaint, cv::FILLED);
  const cv::Mat frame = noisy(clean);
  const std::optional<Rgb> field = estimate_field_colour(frame);
  ASSERT_TRUE(field);
  StripeWorkspace work;
  std::vector<Marking> out;
  const float edge = kBottom + 0.5f;  // between the last paint row and the first turf row
  const float centre = 0.5f * (kTop + kBottom);
  std::vector<Segment> one{{.x0 = 100, .y0 = edge, .x1 = 500, .y1 = edge, .label = Label::Marking}};
  find_stripes(frame, field, one, stripes_on(), work, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(one[0].label, Label::Marking);
  EXPECT_NEAR(out[0].y0, centre, 1);
  EXPECT_NEAR(out[0].y1, centre, 1);
  EXPECT_NEAR(out[0].width, 12, 1.5);
  EXPECT_FLOAT_EQ(out[0].x0, 100);

  // Both edges: one marking over the union of their lengths.
  const Segment top{.x0 = 80, .y0 = kTop - 0.5f, .x1 = 450, .y1 = kTop - 0.5f, .label = Label::Marking};
  std::vector<Segment> two{one[0], top};
  find_stripes(frame, field, two, stripes_on(), work, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(count(two, Label::Marking), 2);
  EXPECT_NEAR(out[0].y0, centre, 1);
  EXPECT_NEAR(std::min(out[0].x0, out[0].x1), 80, 1);
  EXPECT_NEAR(std::max(out[0].x0, out[0].x1), 500, 1);

  // When twins are required, the lone edge is no marking.
  one[0].label = Label::Marking;
  find_stripes(frame, field, one, stripes_on(true), work, out);
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(one[0].label, Label::None);
}

// A straight line with another line's paint beside its middle (a T's arm, a goal area's short
// side line between two others): the profile there crosses both paints and measures a centre
// far off the line's, which is no bow. Shape::Straight keeps the line; a chord of a curve it
// still refuses (TheCentreCirclesChordsAreNoStraightStripes).
TEST(Stripes, PaintBesideAStraightLineIsNoBow) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  cv::rectangle(clean, cv::Point(200, 230), cv::Point(599, 239), kPaint, cv::FILLED);  // 10 px, rows 230-239
  cv::rectangle(clean, cv::Point(300, 240), cv::Point(309, 259), kPaint, cv::FILLED);  // an arm below, 20 px
  const cv::Mat frame = noisy(clean);
  const std::optional<Rgb> field = estimate_field_colour(frame);
  ASSERT_TRUE(field);
  StripeWorkspace work;
  std::vector<Marking> out;
  // The line's upper edge, from x 205 to 405: its profiles at a tenth, three tenths, ..., of its
  // length; the middle one (x 305) runs down through the line and the arm.
  std::vector<Segment> edge{{.x0 = 205, .y0 = 229.5f, .x1 = 405, .y1 = 229.5f, .label = Label::Marking}};
  find_stripes(frame, field, edge, stripes_on(), work, out, ThinLines::Level, Shape::Straight);
  ASSERT_EQ(out.size(), 1u) << "a straight line";
  EXPECT_EQ(edge[0].label, Label::Marking);
  EXPECT_NEAR(out[0].y0, 234.5f, 1);
  EXPECT_NEAR(out[0].y1, 234.5f, 1);
  EXPECT_NEAR(out[0].width, 10, 1.5);
}

// A line smeared by motion: from the turf a step to 0.3 of the paint's contrast, a ramp to 0.7
// over 10 rows, a step to the paint (24 rows), a sharp lower edge. Its gradient's ridges lie on
// the two steps (rows 299.5 and 309.5), 5 px off the half-way crossing (row 304.5), where the
// edge is: both edges drawn there move onto it and become one, spanning both; the sharp edge
// stays. A chord of a curve, whose profiles' edges lie off any line through them, is not moved.
TEST(Stripes, AnEdgeDrawnOnABlurRampIsMovedOntoThePaintsEdge) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  for (int i = 0; i < 10; ++i) {
    const double a = 0.3 + 0.4 * i / 9.0;
    clean.row(300 + i).setTo(kTurf + (kPaint - kTurf) * a);
  }
  clean.rowRange(310, 334).setTo(kPaint);
  const cv::Mat frame = noisy(clean);
  const std::optional<Rgb> field = estimate_field_colour(frame);
  ASSERT_TRUE(field);
  const float down = 50, up = -50;  // the colour gradient towards the paint
  std::vector<Segment> edges{
      {.x0 = 40, .y0 = 299.5f, .x1 = 600, .y1 = 299.5f, .grad_y = {down, down, down}, .label = Label::Marking},
      {.x0 = 100, .y0 = 309.5f, .x1 = 630, .y1 = 309.5f, .grad_y = {down, down, down}, .label = Label::Marking},
      {.x0 = 40, .y0 = 333.5f, .x1 = 600, .y1 = 333.5f, .grad_y = {up, up, up}, .label = Label::Marking}};
  StripeWorkspace work;
  std::vector<Marking> out;
  find_stripes(frame, field, edges, stripes_on(), work, out);
  EXPECT_EQ(edges[0].label, Label::Marking);
  EXPECT_EQ(edges[1].label, Label::None) << "one painted edge, one segment: the longer spans both";
  EXPECT_NEAR(edges[0].y0, 304.5f, 1);
  EXPECT_NEAR(edges[0].y1, 304.5f, 1);
  EXPECT_NEAR(edges[0].x0, 40, 0.5);
  EXPECT_NEAR(edges[0].x1, 630, 0.5);
  EXPECT_NEAR(edges[1].y0, 304.5f, 1) << "moved as well";
  EXPECT_EQ(edges[2].label, Label::Marking);
  EXPECT_FLOAT_EQ(edges[2].y0, 333.5f) << "a sharp edge stays where it was drawn";
  EXPECT_FLOAT_EQ(edges[2].y1, 333.5f);

  // The outer edge of a ring 12 px wide, radius 300 about (320, 700): its top near row 394. A
  // chord from x 270 to 370 has its ends on the edge and its middle 4 px above it.
  cv::Mat ring(480, 640, CV_8UC3, kTurf);
  cv::circle(ring, {320, 700}, 300, kPaint, 12);
  const cv::Mat ring_frame = noisy(ring);
  const float outer = 306, y_end = 700 - std::sqrt(outer * outer - 50 * 50);
  std::vector<Segment> chord{{.x0 = 270, .y0 = y_end, .x1 = 370, .y1 = y_end, .grad_y = {down, down, down},
                              .label = Label::Marking}};
  find_stripes(ring_frame, estimate_field_colour(ring_frame), chord, stripes_on(), work, out);
  EXPECT_EQ(chord[0].label, Label::Marking);
  EXPECT_FLOAT_EQ(chord[0].y0, y_end) << "a chord is not moved";
  EXPECT_FLOAT_EQ(chord[0].y1, y_end);
}

// A segment drawn inside a motion-blurred line's paint (a ghost step), 9 px below its top edge
// where the edge steps down 3 px half-way along: the profiles put the edge 6-9 px off it and
// disagree by more than a move allows, so it is no edge of that paint. The same segment on the
// edge is one.
TEST(Stripes, ASegmentInsideThePaintFarFromItsEdgeIsNoMarking) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  clean(cv::Rect(0, 200, 360, 20)).setTo(kPaint);
  clean(cv::Rect(360, 203, 280, 17)).setTo(kPaint);
  const float down = 50;  // the colour gradient towards the paint's body
  std::vector<Segment> edges{
      {.x0 = 100, .y0 = 208.5f, .x1 = 540, .y1 = 208.5f, .grad_y = {down, down, down}, .label = Label::Marking},
      {.x0 = 40, .y0 = 199.5f, .x1 = 320, .y1 = 199.5f, .grad_y = {down, down, down}, .label = Label::Marking}};
  const cv::Mat frame = noisy(clean);
  std::vector<Marking> out;
  StripeWorkspace work;
  find_stripes(frame, estimate_field_colour(frame), edges, stripes_on(), work, out);
  EXPECT_EQ(edges[0].label, Label::None);
  EXPECT_EQ(edges[1].label, Label::Marking);
}

// A line seen in perspective widens towards the camera, so its centre drifts away from either
// edge: the centre line follows the paint at both ends, from one edge or from both. (A constant
// offset from the edge, its median, misses the far end by about a quarter of the near width.)
TEST(Stripes, APerspectiveLineKeepsItsCentreAtBothEnds) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  // Paint from 3 px wide on row 40 to 27 px on row 460; its left edge is straight.
  const cv::Point2f left_top(300, 40), left_bottom(180, 460), right_top(303, 40), right_bottom(207, 460);
  const std::vector<cv::Point> quad{left_top, right_top, right_bottom, left_bottom};
  cv::fillConvexPoly(clean, quad, kPaint, cv::LINE_AA);
  const cv::Mat frame = noisy(clean);
  const std::optional<Rgb> field = estimate_field_colour(frame);
  ASSERT_TRUE(field);
  const cv::Point2f centre_top = 0.5f * (left_top + right_top), centre_bottom = 0.5f * (left_bottom + right_bottom);
  const auto edge = [](cv::Point2f a, cv::Point2f b, float shift) {  // rows 80 to 420 of an edge
    const auto at = [&](float y) { return a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x) + shift; };
    return Segment{.x0 = at(80), .y0 = 80, .x1 = at(420), .y1 = 420, .label = Label::Marking};
  };
  const Segment left = edge(left_top, left_bottom, -0.5f), right = edge(right_top, right_bottom, 0.5f);
  StripeWorkspace work;
  std::vector<Marking> out;
  for (const bool twins : {false, true}) {
    SCOPED_TRACE(twins ? "both edges" : "one edge");
    std::vector<Segment> segments{left};
    if (twins) segments.push_back(right);
    find_stripes(frame, field, segments, stripes_on(), work, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(count(segments, Label::Marking), static_cast<int>(segments.size()));
    // Within 1.5 px of the centreline at both ends, where the paint is 5 and 25 px wide.
    EXPECT_LE(distance_to_line(out[0].x0, out[0].y0, centre_top, centre_bottom), 1.5f);
    EXPECT_LE(distance_to_line(out[0].x1, out[0].y1, centre_top, centre_bottom), 1.5f);
  }
}

// A line thinner than a pixel on pale turf (the synthetic SSL field's, a real field's far lines):
// its one row blends a little white into the turf, brighter than the field but still in its
// colour. With thin lines accepted both of its edges are stripes, and neither a row of brighter
// turf of the same colour nor a band of the blend several rows wide is. The detector's default
// (Level) takes the long, level line too, but not the same paint standing upright (a thin grey
// post) nor a short piece of it (a robot's limb).
TEST(Stripes, AThinLineBlendedIntoPaleTurfIsAStripeWhenAcceptedOrLongAndLevel) {
  const cv::Scalar pale_turf(135, 168, 94);  // B, G, R
  // The line on row 240 (column 320 when upright), `half` more rows either side.
  const auto frame_with = [&](const cv::Scalar& colour, bool upright, int half = 0) {
    cv::Mat clean(480, 640, CV_8UC3, pale_turf);
    (upright ? clean.col(320) : clean.rowRange(240 - half, 241 + half)).setTo(colour);
    return noisy(clean);
  };
  // The rising edge before the line and the falling one after it, bright sides facing the line:
  // on the rows (or columns) either side, where a central difference sees it; `from`-`to` along it.
  const auto stripes = [&](const cv::Mat& frame, ThinLines thin, bool upright, float from, float to, int half = 0) {
    const std::optional<Rgb> field = estimate_field_colour(frame);
    EXPECT_TRUE(field);
    std::vector<Segment> edges;
    for (const float side : {-1.f, 1.f}) {
      const float g = -50.f * side, at = side * float(half + 1);
      edges.push_back(upright ? Segment{.x0 = 320 + at, .y0 = from, .x1 = 320 + at, .y1 = to, .grad_x = {g, g, g},
                                        .label = Label::Marking}
                              : Segment{.x0 = from, .y0 = 240 + at, .x1 = to, .y1 = 240 + at, .grad_y = {g, g, g},
                                        .label = Label::Marking});
    }
    StripeWorkspace work;
    std::vector<Marking> out;
    find_stripes(frame, field, edges, stripes_on(), work, out, thin);
    return count(edges, Label::Marking);
  };
  constexpr double kWhite = 0.15;  // the line's share of paint
  const cv::Scalar blend = pale_turf * (1 - kWhite) + kPaint * kWhite;
  const cv::Mat level = frame_with(blend, false), upright = frame_with(blend, true);
  const std::optional<Rgb> field = estimate_field_colour(level);
  ASSERT_TRUE(field);
  // The blended line's chromaticity is within the field pixel rule's tolerance of the field's.
  const double sum = blend[0] + blend[1] + blend[2], field_sum = (*field)[0] + (*field)[1] + (*field)[2];
  ASSERT_LE(std::abs(blend[2] / sum - (*field)[0] / field_sum) + std::abs(blend[1] / sum - (*field)[1] / field_sum),
            FieldBoundaryParams{}.chroma_tolerance);
  EXPECT_EQ(stripes(level, ThinLines::Accepted, false, 60, 580), 2);
  EXPECT_EQ(stripes(level, ThinLines::Level, false, 60, 580), 2) << "a long, level line";
  EXPECT_EQ(stripes(level, ThinLines::Level, false, 300, 330), 0) << "a short piece of it";
  EXPECT_EQ(stripes(level, ThinLines::Accepted, false, 300, 330), 2);
  EXPECT_EQ(stripes(upright, ThinLines::Level, true, 40, 440), 0) << "the same paint standing upright";
  EXPECT_EQ(stripes(upright, ThinLines::Accepted, true, 40, 440), 2);
  const cv::Mat brighter_turf = frame_with(pale_turf * 1.2, false);
  EXPECT_EQ(stripes(brighter_turf, ThinLines::Accepted, false, 60, 580), 0) << "brighter turf keeps the turf's colour";
  // The same blend over 7 rows stays in the field colour too, but paint that wide would leave it:
  // a band of light (a far sun stripe), no line.
  EXPECT_EQ(stripes(frame_with(blend, false, 3), ThinLines::Accepted, false, 60, 580, 3), 0) << "a wide band";
}

// A far line in a wall's shade (the authors' SSL frames): its turf is darker than the frame's
// field colour, and the line, thin and blurred, is not brighter than that colour. Its contrast is
// against the turf beside it; the same paint on the sunlit turf is no brighter than the turf.
TEST(Stripes, AFarLineOnShadedTurfIsMeasuredAgainstTheTurfBesideIt) {
  const cv::Scalar sunlit(70, 170, 60), shaded(45, 110, 38), dull_paint(95, 105, 100);  // B, G, R
  cv::Mat clean(480, 640, CV_8UC3, sunlit);
  clean.rowRange(0, 120).setTo(shaded);
  clean.rowRange(60, 63).setTo(dull_paint);
  clean.rowRange(300, 303).setTo(dull_paint);
  const cv::Mat frame = noisy(clean);
  const std::optional<Rgb> field = estimate_field_colour(frame);
  ASSERT_TRUE(field);
  const double field_sum = (*field)[0] + (*field)[1] + (*field)[2];
  ASSERT_LT(dull_paint[0] + dull_paint[1] + dull_paint[2], 1.1 * field_sum) << "no brighter than the field colour by a tenth";
  // Each line's two edges, bright sides facing the paint.
  const auto stripes_at = [&](float top, float bottom) {
    const std::vector<Label> labels = stripe_labels(frame, field, {{top, true}, {bottom, false}});
    return static_cast<int>(std::count(labels.begin(), labels.end(), Label::Marking));
  };
  EXPECT_EQ(stripes_at(59, 63), 2) << "the line on shaded turf";
  EXPECT_EQ(stripes_at(299, 303), 0) << "the same paint on sunlit turf";
}

// `clean` with noise, its field colour and its turf colours as the detector measures them.
struct TurfFrame {
  cv::Mat frame;
  std::optional<Rgb> field;
  TurfColours turf;
};
TurfFrame turf_frame(const cv::Mat& clean) {
  TurfFrame t{noisy(clean), {}, {}};
  t.field = estimate_field_colour(t.frame);
  if (t.field) t.turf.measure(t.frame, *t.field);
  return t;
}

// Turf whose light changes down the frame (sunlit at the top, bluer shade at the bottom): the
// turf beside a line near the bottom is out of the median colour's tolerance, but among the
// frame's own turf colours (stripe_turf_colours), which the calibration turns on.
TEST(Stripes, ALineOnTurfInASecondLightIsAStripeOnTheTurfsColours) {
  const cv::Vec3f sun(30, 160, 40), shade(80, 105, 25);  // B, G, R
  cv::Mat clean(480, 640, CV_8UC3);
  for (int y = 0; y < clean.rows; ++y) {
    const cv::Vec3f c = sun + (shade - sun) * (float(y) / float(clean.rows - 1));
    clean.row(y).setTo(cv::Scalar(c[0], c[1], c[2]));
  }
  clean.rowRange(440, 447).setTo(kPaint);
  const TurfFrame t = turf_frame(clean);
  ASSERT_TRUE(t.field);
  ASSERT_FALSE(t.turf.empty());
  const std::vector<std::pair<float, bool>> edges{{439.5f, true}, {446.5f, false}};
  const std::vector<Label> median_alone = stripe_labels(t.frame, t.field, edges);
  const std::vector<Label> turf_colours = stripe_labels(t.frame, FieldColours(*t.field, &t.turf), edges);
  EXPECT_EQ(std::count(median_alone.begin(), median_alone.end(), Label::Marking), 0) << "the shade is out of tolerance";
  EXPECT_EQ(std::count(turf_colours.begin(), turf_colours.end(), Label::Marking), 2);
}

// A robot's dark body panel mirrors the turf's chromaticity at a third of its brightness: on the
// turf's colours it is no turf (below 0.4 of the field colour), so a white bar along it is no
// stripe.
TEST(Stripes, ADarkPanelInTheTurfsChromaticityIsNoTurfOnTheTurfsColours) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  clean.rowRange(300, 341).setTo(kTurf * 0.3);
  clean.rowRange(296, 300).setTo(kPaint);
  clean.rowRange(150, 154).setTo(kPaint);  // a line on the turf, for comparison
  const TurfFrame t = turf_frame(clean);
  ASSERT_TRUE(t.field);
  ASSERT_FALSE(t.turf.empty());
  const std::vector<Label> labels =
      stripe_labels(t.frame, FieldColours(*t.field, &t.turf), {{295.5f, true}, {149.5f, true}, {153.5f, false}});
  EXPECT_EQ(labels[0], Label::None) << "the bar beside the panel";
  EXPECT_EQ(labels[1], Label::Marking);
  EXPECT_EQ(labels[2], Label::Marking);
}

// The field's edge at row 200 against a light floor strip 16 px tall, with the next field's turf
// beyond it: turf, "paint", turf, so its edge is a stripe by the profiles alone. Its paint lies
// above the field boundary: with the boundary it is none; a line on the field beside it (rows
// 300-305) stays a marking either way.
TEST(Stripes, AStripeWhosePaintLiesBeyondTheFieldBoundaryIsNone) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  clean.rowRange(0, 140).setTo(kDark);
  clean.rowRange(184, 200).setTo(kPaint);
  clean.rowRange(300, 305).setTo(kPaint);
  const cv::Mat frame = noisy(clean);
  const std::optional<Rgb> field = estimate_field_colour(frame);
  ASSERT_TRUE(field);
  FieldBoundary boundary;
  boundary.image_height = 480;
  boundary.points = {{0, 200}, {639, 200}};
  const std::vector<std::pair<float, bool>> edges{{200, false}, {300, true}};
  EXPECT_EQ(stripe_labels(frame, field, edges), (std::vector<Label>{Label::Marking, Label::Marking}))
      << "both are stripes";
  EXPECT_EQ(stripe_labels(frame, field, edges, &boundary), (std::vector<Label>{Label::None, Label::Marking}));
}

// A line painted along the field's edge (edge_lines.hpp): the field's dark surround above row
// 200, two rows of paint, then turf. The segment drawn at the surround's edge is none by its
// colours; along the field boundary its profiles show surround, paint and turf, so it becomes a
// marking with the paint's centre line. Without the boundary, with no paint, with the paint a few
// rows inside the turf (the turf's own edge outside it), or labelled a boundary edge, it stays.
TEST(Stripes, ALineAlongTheFieldsEdgeIsAMarking) {
  const auto frame_with = [](int paint_row, int paint_rows) {
    cv::Mat clean(480, 640, CV_8UC3, kTurf);
    clean.rowRange(0, 200).setTo(kDark);
    if (paint_rows > 0) clean.rowRange(paint_row, paint_row + paint_rows).setTo(kPaint);
    return noisy(clean);
  };
  FieldBoundary boundary;
  boundary.image_height = 480;
  boundary.points = {{0, 200}, {639, 200}};
  // The label find_stripes leaves on the surround's edge (labelled `label`), and its markings.
  const auto edge_after = [&](const cv::Mat& frame, Label label, const FieldBoundary* on_field) {
    Segment edge = row_edge(199.5f, true);
    edge.label = label;
    std::vector<Marking> out;
    const Label after = labels_of(frame, estimate_field_colour(frame), {edge}, on_field, &out).front();
    return std::pair{after, out};
  };
  const cv::Mat line = frame_with(200, 2);
  const auto [label, markings] = edge_after(line, Label::None, &boundary);
  EXPECT_EQ(label, Label::Marking);
  ASSERT_EQ(markings.size(), 1u);
  expect_centre_line(markings[0], {0, 200.5f}, {639, 200.5f}, 2);
  EXPECT_EQ(edge_after(line, Label::None, nullptr).first, Label::None) << "no field boundary";
  EXPECT_EQ(edge_after(line, Label::Boundary, &boundary).first, Label::Boundary) << "the boundary class's";
  EXPECT_EQ(edge_after(frame_with(0, 0), Label::None, &boundary).first, Label::None) << "no paint";
  EXPECT_EQ(edge_after(frame_with(205, 2), Label::None, &boundary).first, Label::None) << "turf before the paint";
}

// A wide line near the camera along the frame's dark rim (a fisheye's corner, the robot's own
// body at the frame's bottom): turf, paint, then dark to the frame's border. No turf returns,
// but nothing lies beyond the rim: a stripe, from either edge (the edge against the rim has the
// rim outside it). The same paint with turf again past a dark band (a robot's white bar beside
// its dark body) is none from either edge.
TEST(Stripes, AWideLineAlongTheFramesDarkRimIsAStripe) {
  const auto frame_with_dark_until = [](int dark_end) {
    cv::Mat clean(480, 640, CV_8UC3, kTurf);
    clean.rowRange(420, 440).setTo(kPaint);
    clean.rowRange(440, dark_end).setTo(kDark);
    return noisy(clean);
  };
  const cv::Mat rim = frame_with_dark_until(480), body = frame_with_dark_until(465);
  const std::optional<Rgb> field = estimate_field_colour(rim);
  ASSERT_TRUE(field);
  EXPECT_EQ(stripe_labels(rim, field, {{419, true}}), std::vector<Label>{Label::Marking});
  EXPECT_EQ(stripe_labels(rim, field, {{440, false}}), std::vector<Label>{Label::Marking}) << "the edge on the rim";
  EXPECT_EQ(stripe_labels(body, estimate_field_colour(body), {{419, true}}), std::vector<Label>{Label::None});
  EXPECT_EQ(stripe_labels(body, estimate_field_colour(body), {{440, false}}), std::vector<Label>{Label::None});
}

// The studio's one pass (run_with_thin_lines) flags what a run with thin lines taken when level
// and one with them accepted flag, on every segment of synthetic frames of both scenes in every light
// (the SSL field's far lines are thinner than a pixel), each with a thin post added.
TEST(Stripes, OnePassFlagsWhatTheTwoRunsFlag) {
  int thin_only = 0, stripes = 0;
  for (const synth::Scene scene : {synth::Scene::Ssl, synth::Scene::Kid}) {
    synth::SynthParams p;
    p.field.scene = scene;
    p.conditions = {synth::Condition::Artificial, synth::Condition::Natural, synth::Condition::Mixed,
                    synth::Condition::Dim, synth::Condition::Shadows};
    for (int i = 0; i < 10; ++i) {
      synth::SynthSample sample = synth::generate(p, 11, i);
      std::vector<Segment> segments;
      LineDetector(DetectorParams{}).detect(sample.bgr, segments);
      // An upright thin line (a thin grey post) with its two edges: taken only when thin lines
      // are accepted, as the frames' own thin lines are long and level.
      const int x = sample.bgr.cols / 3, top = sample.bgr.rows / 2, rows = sample.bgr.rows / 3;
      cv::Mat post = sample.bgr(cv::Rect(x, top, 1, rows));
      post = post * 0.85 + cv::Scalar::all(0.15 * 255);
      for (const float side : {-1.f, 1.f})
        segments.push_back({.x0 = float(x) + side, .y0 = float(top), .x1 = float(x) + side, .y1 = float(top + rows),
                            .grad_x = {-50 * side, -50 * side, -50 * side}});
      const std::optional<Rgb> field = estimate_field_colour(sample.bgr);
      StripeCheck level, accepted, both;
      ASSERT_EQ(level.run(sample.bgr, field, segments, stripes_on(), ThinLines::Level), field.has_value());
      accepted.run(sample.bgr, field, segments, stripes_on(), ThinLines::Accepted);
      ASSERT_EQ(both.run_with_thin_lines(sample.bgr, field, segments, stripes_on()), field.has_value());
      EXPECT_EQ(both.flags(), level.flags()) << i;
      EXPECT_EQ(both.thin_flags(), accepted.flags()) << i;
      for (std::size_t k = 0; k < level.flags().size(); ++k) {
        stripes += level.flags()[k];
        thin_only += accepted.flags()[k] && !level.flags()[k];
      }
    }
  }
  EXPECT_GT(stripes, 20);
  EXPECT_GT(thin_only, 0) << "the frames must hold lines that only thin lines accepted take";
}

// Shape::Straight on the detector's segments of synthetic Kid frames: of those along the centre
// circle, chords whose paint bows, about half pass (18 of 33); of those along the halfway line
// and the touch lines nearly all (19 of 22). Shape::Any passes every one of both.
TEST(Stripes, TheCentreCirclesChordsAreNoStraightStripes) {
  synth::SynthParams p;
  p.field.scene = synth::Scene::Kid;
  p.conditions.assign(synth::all_conditions().begin(), synth::all_conditions().end());
  int chords = 0, straight_chords = 0, lines = 0, straight_lines = 0;
  for (int i = 0; i < 12; ++i) {
    const synth::SynthSample sample = synth::generate(p, 1, i);
    std::vector<Segment> segments;
    LineDetector(DetectorParams{}).detect(sample.bgr, segments);
    const std::optional<Rgb> field = estimate_field_colour(sample.bgr);
    // Both ends and the middle within 4 px of the named line's centre (a segment lies on an edge).
    const auto along = [&](const Segment& s, std::string_view name) {
      return distance_to(sample.truth, name, s.x0, s.y0) < 4 && distance_to(sample.truth, name, s.x1, s.y1) < 4 &&
             distance_to(sample.truth, name, 0.5f * (s.x0 + s.x1), 0.5f * (s.y0 + s.y1)) < 4;
    };
    for (Segment& s : segments) s.label = Label::Marking;
    std::vector<Segment> any = segments, straight = segments;
    StripeWorkspace work;
    std::vector<Marking> out;
    find_stripes(sample.bgr, field, any, stripes_on(), work, out);
    find_stripes(sample.bgr, field, straight, stripes_on(), work, out, ThinLines::Level, Shape::Straight);
    for (std::size_t k = 0; k < segments.size(); ++k) {
      EXPECT_FALSE(straight[k].label == Label::Marking && any[k].label != Label::Marking) << "Straight keeps a subset";
      if (any[k].label != Label::Marking) continue;
      const bool kept = straight[k].label == Label::Marking;
      if (along(segments[k], "centre circle")) ++chords, straight_chords += kept;
      else if (along(segments[k], "halfway line") || along(segments[k], "touch line +y") ||
               along(segments[k], "touch line -y"))
        ++lines, straight_lines += kept;
    }
  }
  ASSERT_GE(chords, 5) << "the frames must show the centre circle";
  ASSERT_GE(lines, 5) << "and straight lines";
  EXPECT_LE(straight_chords, 0.7 * chords) << straight_chords << " of " << chords << " chords pass as straight";
  EXPECT_GE(straight_lines, 0.8 * lines) << straight_lines << " of " << lines << " lines pass as straight";
}

// The check measures each stripe's width as a share of its row's width scale (width_share): the
// row itself below a quarter of the height, a quarter of the height above it. Plain turf is no
// stripe and measures 0.
TEST(Stripes, TheCheckMeasuresEachStripesWidthAsAShareOfItsRow) {
  EXPECT_FLOAT_EQ(width_share(8, 400, 480), 0.02f);
  EXPECT_FLOAT_EQ(width_share(6, 60, 480), 0.05f);
  EXPECT_EQ(width_share(6, 60, 0), 0.f);
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  cv::rectangle(clean, cv::Point(0, 396), cv::Point(639, 404), kPaint, cv::FILLED);  // 9 px at row 400
  cv::rectangle(clean, cv::Point(0, 98), cv::Point(639, 102), kPaint, cv::FILLED);   // 5 px at row 100
  const cv::Mat frame = noisy(clean);
  const std::vector<Segment> segments{row_edge(395.5f, true), row_edge(404.5f, false), row_edge(97.5f, true),
                                      row_edge(250, true)};
  StripeCheck check;
  ASSERT_TRUE(check.run(frame, estimate_field_colour(frame), segments, stripes_on()));
  ASSERT_EQ(check.width_shares().size(), segments.size());
  EXPECT_NEAR(check.width_shares()[0], 9.f / 400, 1.f / 400);
  EXPECT_NEAR(check.width_shares()[1], 9.f / 400, 1.f / 400);
  EXPECT_NEAR(check.width_shares()[2], 5.f / 120, 1.f / 120);
  EXPECT_EQ(check.width_shares()[3], 0.f) << "plain turf";
}

// The colours may call one edge of a line a marking and leave the other none (its colour angle
// off: the turf beyond it in another light, a lens's fringe): the stripe the marked edge measures
// has that one for its twin, which becomes a marking whatever its colours say. A none edge with no
// marked twin stays none: the geometry confirms a marking, it does not find one alone.
TEST(Stripes, TheOtherEdgeOfAMarkedStripeIsAMarkingWhateverItsColours) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  cv::rectangle(clean, cv::Point(40, 300), cv::Point(600, 309), kPaint, cv::FILLED);
  const cv::Mat frame = noisy(clean);
  const FieldColours field{estimate_field_colour(frame)};
  Segment upper = row_edge(299.5f, true), lower = row_edge(309.5f, false);
  lower.label = Label::None;
  std::vector<Marking> markings;
  EXPECT_EQ(labels_of(frame, field, {upper, lower}, nullptr, &markings),
            (std::vector<Label>{Label::Marking, Label::Marking}));
  ASSERT_EQ(markings.size(), 1u) << "the twins merge into one line";
  EXPECT_NEAR(0.5f * (markings[0].y0 + markings[0].y1), 304.5f, 1.5f);
  EXPECT_NEAR(markings[0].width, 10.f, 2.f);
  upper.label = Label::None;
  EXPECT_EQ(labels_of(frame, field, {upper, lower}), (std::vector<Label>{Label::None, Label::None}));
  // Nor does a marked edge of no stripe (a wall's: turf on one side only) make its none twin one.
  cv::Mat wall(480, 640, CV_8UC3, kTurf);
  cv::rectangle(wall, cv::Point(0, 0), cv::Point(639, 309), kPaint, cv::FILLED);
  const cv::Mat walled = noisy(wall);
  upper.label = Label::Marking;
  EXPECT_EQ(labels_of(walled, FieldColours{estimate_field_colour(walled)}, {upper, lower}),
            (std::vector<Label>{Label::None, Label::None}));
}

TEST(Stripes, OtherLabelsAreLeftAlone) {
  const cv::Mat frame = noisy(cv::Mat(120, 160, CV_8UC3, kTurf));
  StripeWorkspace work;
  std::vector<Marking> out;
  std::vector<Segment> s{{.x0 = 10, .y0 = 60, .x1 = 150, .y1 = 60, .label = Label::Boundary},
                         {.x0 = 10, .y0 = 30, .x1 = 150, .y1 = 30, .label = Label::Marking}};
  find_stripes(frame, estimate_field_colour(frame), s, stripes_on(), work, out);
  EXPECT_EQ(s[0].label, Label::Boundary);
  EXPECT_EQ(s[1].label, Label::None) << "plain turf is no stripe";
  EXPECT_TRUE(out.empty());
}

void expect_sane(const Detected& r, const cv::Mat& frame) {
  for (const Marking& m : r.markings) {
    for (const float v : {m.x0, m.y0, m.x1, m.y1, m.width}) EXPECT_TRUE(std::isfinite(v));
    EXPECT_GT(m.width, 0);
    EXPECT_LE(m.width, frame.rows);
  }
}

TEST(Stripes, BadInputGivesSaneOutput) {
  // No green: a white line on grey concrete has no turf, so nothing is a marking.
  cv::Mat grey(240, 320, CV_8UC3, cv::Scalar(110, 110, 110));
  cv::line(grey, cv::Point(20, 120), cv::Point(300, 130), kPaint, 6);
  const Detected no_green = detect(noisy(grey));
  EXPECT_TRUE(no_green.markings.empty());
  EXPECT_EQ(count(no_green.segments, Label::Marking), 0);

  for (const cv::Scalar& colour : {kTurf, kPaint}) {
    const cv::Mat flat = noisy(cv::Mat(240, 320, CV_8UC3, colour));
    const Detected r = detect(flat);
    EXPECT_TRUE(r.markings.empty());
    expect_sane(r, flat);
  }
  for (const cv::Size size : {cv::Size(640, 1), cv::Size(1, 480), cv::Size(3, 3), cv::Size(640, 3)}) {
    cv::Mat tiny(size, CV_8UC3, kTurf);
    cv::line(tiny, cv::Point(0, 0), cv::Point(size.width - 1, size.height - 1), kPaint, 1);
    EXPECT_NO_THROW(expect_sane(detect(tiny), tiny)) << size;
  }
  // A line wider than the frame is high: paint from border to border, turf in two corners.
  cv::Mat wide(60, 320, CV_8UC3, kTurf);
  cv::line(wide, cv::Point(0, 0), cv::Point(319, 59), kPaint, 90);
  const cv::Mat wide_frame = noisy(wide);
  const Detected r = detect(wide_frame);
  expect_sane(r, wide_frame);
  // Grey and 16-bit frames go through the detector's normalisation first.
  cv::Mat line16;
  noisy(cv::Mat(240, 320, CV_8UC3, kTurf)).convertTo(line16, CV_16UC3, 256);
  EXPECT_NO_THROW(detect(line16));
  // And a frame find_stripes cannot read keeps no marking.
  StripeWorkspace work;
  std::vector<Marking> out;
  std::vector<Segment> s{{.x0 = 10, .y0 = 30, .x1 = 150, .y1 = 30, .label = Label::Marking}};
  find_stripes(cv::Mat(), Rgb{40, 140, 50}, s, stripes_on(), work, out);
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(s[0].label, Label::None);
}

TEST(Stripes, OffByDefaultAndThenLabelsAreUntouched) {
  EXPECT_FALSE(DetectorParams{}.stripes);
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  cv::rectangle(clean, cv::Point(0, 0), cv::Point(639, 180), kPaint, cv::FILLED);
  const Detected off = detect(noisy(clean), DetectorParams{});
  EXPECT_TRUE(off.markings.empty());
  EXPECT_GT(count(off.segments, Label::Marking), 0);
}

}  // namespace
}  // namespace fieldlines
