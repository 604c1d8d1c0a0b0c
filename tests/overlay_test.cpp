// Overlays: each label is drawn in its own colour, any loadable image type works, and odd
// inputs (tiny images, non-finite endpoints) never crash.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "fieldlines/data/overlay.hpp"

namespace {

using fieldlines::Label;
using fieldlines::Segment;

Segment horizontal(float y, Label label) {
  Segment s;
  s.x0 = 100;
  s.x1 = 300;
  s.y0 = s.y1 = y;
  s.label = label;
  return s;
}

cv::Vec3b at(const cv::Mat& img, int x, int y) { return img.at<cv::Vec3b>(y, x); }
cv::Vec3b as_vec(const cv::Scalar& s) {
  return {static_cast<uchar>(s[0]), static_cast<uchar>(s[1]), static_cast<uchar>(s[2])};
}

}  // namespace

TEST(Overlay, EachLabelHasItsOwnColour) {
  const cv::Mat image(240, 320, CV_8UC3, cv::Scalar(0, 0, 0));
  const std::vector<Segment> segments{horizontal(120, Label::Marking), horizontal(160, Label::Boundary),
                                      horizontal(200, Label::None), horizontal(230, Label::Unlabelled)};
  fieldlines::OverlayParams params;
  params.thickness = 5;
  const cv::Mat out = fieldlines::draw_overlay(image, segments, params);
  ASSERT_EQ(out.type(), CV_8UC3);
  ASSERT_EQ(out.size(), image.size());
  EXPECT_EQ(at(out, 200, 120), as_vec(params.marking_colour));
  EXPECT_EQ(at(out, 200, 160), as_vec(params.boundary_colour));
  EXPECT_EQ(at(out, 200, 200), as_vec(params.none_colour));
  EXPECT_EQ(at(out, 200, 230), as_vec(params.unlabelled_colour));
  // The colours are distinct from each other and the input is left untouched.
  EXPECT_NE(params.marking_colour, params.boundary_colour);
  EXPECT_NE(params.marking_colour, params.none_colour);
  EXPECT_NE(params.boundary_colour, params.none_colour);
  EXPECT_EQ(cv::countNonZero(image.reshape(1)), 0);
}

// Above the field boundary (stands, walls, lights) segments are faint by default, hidden at
// opacity 0 and like the rest at 1; on the field they are drawn at full strength either way.
TEST(Overlay, SegmentsAboveTheFieldBoundaryAreFaint) {
  const cv::Mat image(240, 320, CV_8UC3, cv::Scalar(0, 0, 0));
  const std::vector<Segment> segments{horizontal(40, Label::None), horizontal(200, Label::None)};
  fieldlines::FieldBoundary field;
  field.points = {{0, 100}, {319, 100}};
  field.image_height = 240;
  fieldlines::OverlayParams params;
  params.thickness = 5;
  params.legend = false;
  const cv::Vec3b full = as_vec(params.none_colour);
  params.field_boundary = &field;
  const cv::Mat faint = fieldlines::draw_overlay(image, segments, params);
  EXPECT_EQ(at(faint, 200, 200), full) << "on the field";
  const cv::Vec3b above = at(faint, 200, 40);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(above[c], 0.3 * full[c], 2) << "faint above the boundary, channel " << c;
  params.above_opacity = 0;
  EXPECT_EQ(at(fieldlines::draw_overlay(image, segments, params), 200, 40), cv::Vec3b(0, 0, 0)) << "hidden";
  params.above_opacity = 1;
  EXPECT_EQ(at(fieldlines::draw_overlay(image, segments, params), 200, 40), full) << "like the rest";
  params.field_boundary = nullptr;
  params.above_opacity = 0;
  EXPECT_EQ(at(fieldlines::draw_overlay(image, segments, params), 200, 40), full) << "no boundary: all alike";
}

TEST(Overlay, LegendIsDrawnWhenItFitsAndSkippedWhenNot) {
  const cv::Mat bright(480, 640, CV_8UC3, cv::Scalar(200, 200, 200));
  fieldlines::OverlayParams params;
  const cv::Mat with = fieldlines::draw_overlay(bright, {}, params);
  params.legend = false;
  const cv::Mat without = fieldlines::draw_overlay(bright, {}, params);
  // The legend darkens a box in the top-left corner and holds the three label colours.
  EXPECT_LT(cv::mean(with(cv::Rect(0, 0, 60, 40)))[0], 150.0);
  EXPECT_EQ(cv::norm(without, bright, cv::NORM_INF), 0.0);
  for (const Label l : {Label::Marking, Label::Boundary, Label::None}) {
    cv::Mat mask;
    const cv::Scalar c = fieldlines::label_colour(l, params);
    cv::inRange(with, c, c, mask);
    EXPECT_GT(cv::countNonZero(mask), 0) << fieldlines::to_string(l);
  }
  // On a tiny image the legend cannot fit: the image is returned unchanged rather than covered.
  const cv::Mat tiny(12, 12, CV_8UC3, cv::Scalar(200, 200, 200));
  EXPECT_EQ(cv::norm(fieldlines::draw_overlay(tiny, {}, {}), tiny, cv::NORM_INF), 0.0);
}

TEST(Overlay, AcceptsGrey16BitAndAlphaImages) {
  const std::vector<Segment> segments{horizontal(50, Label::Marking)};
  for (const int type : {CV_8UC1, CV_16UC1, CV_16UC3, CV_8UC4}) {
    const cv::Mat image(100, 400, type, cv::Scalar::all(0));
    fieldlines::OverlayParams params;
    params.thickness = 5;
    const cv::Mat out = fieldlines::draw_overlay(image, segments, params);
    EXPECT_EQ(out.type(), CV_8UC3) << type;
    EXPECT_EQ(at(out, 200, 50), as_vec(fieldlines::OverlayParams{}.marking_colour)) << type;
  }
}

TEST(Overlay, NonFiniteAndFarAwayEndpointsDoNotCrash) {
  Segment nan = horizontal(10, Label::Marking);
  nan.x1 = std::numeric_limits<float>::quiet_NaN();
  Segment far = horizontal(20, Label::None);
  far.x0 = -1e30f;
  far.x1 = 1e30f;
  const cv::Mat image(40, 40, CV_8UC3, cv::Scalar::all(0));
  const std::vector<Segment> segments{nan, far};
  cv::Mat out;
  fieldlines::OverlayParams params;
  params.thickness = 5;
  params.legend = false;
  ASSERT_NO_THROW(out = fieldlines::draw_overlay(image, segments, params));
  // The far segment crosses the image and is drawn (clipped); the NaN one is skipped.
  EXPECT_EQ(at(out, 20, 20), as_vec(fieldlines::OverlayParams{}.none_colour));
  EXPECT_EQ(at(out, 30, 10), cv::Vec3b(0, 0, 0));
}

TEST(Overlay, DrawsTheStudiosPaletteOverADarkOutline) {
  // One palette (fieldlines/data/palette.hpp) for the CLI's --draw and the studio.
  const fieldlines::OverlayParams defaults;
  for (const Label l : {Label::Marking, Label::Boundary, Label::None, Label::Unlabelled})
    EXPECT_EQ(fieldlines::label_colour(l, defaults), fieldlines::bgr(fieldlines::palette::label_rgb(l)))
        << fieldlines::to_string(l);
  EXPECT_EQ(defaults.outline_colour, fieldlines::bgr(fieldlines::palette::kOutline));

  // On bright turf, a column across the segment: colour in the middle, outline on both sides.
  const cv::Mat turf(240, 320, CV_8UC3, cv::Scalar(60, 180, 90));
  const std::vector<Segment> segments{horizontal(120, Label::None)};
  fieldlines::OverlayParams params;
  params.thickness = 3;
  params.legend = false;
  // Rows of the column within 30 per channel of the outline colour (edges are anti-aliased).
  const auto outline_rows = [&](const cv::Mat& out) {
    std::vector<int> rows;
    for (int y = 100; y < 140; ++y) {
      const cv::Vec3b p = at(out, 200, y), o = as_vec(params.outline_colour);
      if (std::abs(p[0] - o[0]) <= 30 && std::abs(p[1] - o[1]) <= 30 && std::abs(p[2] - o[2]) <= 30) rows.push_back(y);
    }
    return rows;
  };
  const cv::Mat out = fieldlines::draw_overlay(turf, segments, params);
  EXPECT_EQ(at(out, 200, 120), as_vec(params.none_colour));
  const auto rows = outline_rows(out);
  ASSERT_FALSE(rows.empty());
  EXPECT_LT(rows.front(), 120);
  EXPECT_GT(rows.back(), 120);
  // The endpoint dots have their outline too.
  int darkest_left_of_the_end = 255 * 3;
  for (int x = 88; x < 100; ++x) {
    const cv::Vec3b p = at(out, x, 120);
    darkest_left_of_the_end = std::min(darkest_left_of_the_end, p[0] + p[1] + p[2]);
  }
  EXPECT_LE(darkest_left_of_the_end, 60);
  // Overridable: no outline, or another colour.
  params.outline_px = 0;
  EXPECT_TRUE(outline_rows(fieldlines::draw_overlay(turf, segments, params)).empty());
  params.outline_px = 2;
  params.outline_colour = {255, 255, 255};
  params.none_colour = {1, 2, 3};
  const cv::Mat white = fieldlines::draw_overlay(turf, segments, params);
  EXPECT_EQ(at(white, 200, 120), cv::Vec3b(1, 2, 3));
  EXPECT_TRUE(outline_rows(white).size() >= 2);
}

// The field features: centre lines, the ellipse and each junction (ring, rays, type letter) in
// the feature colour; non-finite values and an empty result draw nothing and never crash.
namespace fieldlines {
namespace {

// Pixels within 40 per channel of `colour` (edges are anti-aliased).
int pixels_of(const cv::Mat& canvas, const cv::Scalar& colour) {
  cv::Mat hit;
  cv::inRange(canvas, colour - cv::Scalar::all(40), colour + cv::Scalar::all(40), hit);
  return cv::countNonZero(hit);
}

TEST(Overlay, FieldFeaturesInTheirColour) {
  const cv::Mat turf(240, 320, CV_8UC3, cv::Scalar(40, 140, 50));
  const cv::Scalar colour = bgr(palette::kFeature);
  OverlayParams params;
  params.thickness = 3;
  cv::Mat canvas = turf.clone();
  draw_field_features(canvas, FieldFeatures{});
  EXPECT_EQ(cv::norm(canvas, turf, cv::NORM_INF), 0) << "nothing to draw";

  FieldFeatures f;
  f.markings.push_back({20, 200, 300, 210, 6});
  f.ellipses.push_back({160, 120, 200, 80, 5, 0.8f});
  Intersection t{.x = 100, .y = 60, .type = JunctionType::T, .num_rays = 3, .heading_rays = {0, 1.5708f, 3.1416f, 0}};
  f.intersections.push_back(t);
  draw_field_features(canvas, f, params);
  EXPECT_GT(pixels_of(canvas, colour), 300);
  // The junction's ring and rays lie around its centre.
  const cv::Mat around = canvas(cv::Rect(80, 40, 40, 40));
  EXPECT_GT(pixels_of(around, colour), 20);

  // The legend says what the colours are, top right (the labels' legend holds the top left):
  // a darkened box with the feature colour's swatch; none when asked for none.
  const cv::Rect top_right(240, 0, 80, 30), top_left(0, 0, 80, 30);
  EXPECT_LT(cv::mean(canvas(top_right))[1], 0.6 * turf.at<cv::Vec3b>(0, 0)[1]);
  EXPECT_GT(pixels_of(canvas(cv::Rect(150, 0, 170, 60)), colour), 0);
  EXPECT_EQ(cv::norm(canvas(top_left), turf(top_left), cv::NORM_INF), 0) << "the top left stays the labels'";
  params.legend = false;
  cv::Mat plain = turf.clone();
  draw_field_features(plain, f, params);
  EXPECT_GT(cv::mean(plain(top_right))[1], 0.8 * turf.at<cv::Vec3b>(0, 0)[1]);

  FieldFeatures bad;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  bad.field_boundary.points = {{0, 200}, {319, 205}};  // far below the legend
  {
    // The field boundary is dashed, and so is its legend's swatch: two equal runs of its colour
    // with a gap, then the text (a solid swatch is one run far longer than the first letter's).
    OverlayParams legend_only;
    legend_only.thickness = 2;
    cv::Mat boundary = turf.clone();
    FieldFeatures only_boundary;
    only_boundary.field_boundary = bad.field_boundary;
    draw_field_features(boundary, only_boundary, legend_only);
    const cv::Mat legend = boundary(cv::Rect(160, 0, 160, 60));
    cv::Mat hit;
    const cv::Scalar blue = bgr(palette::kFieldBoundary);
    cv::inRange(legend, blue - cv::Scalar::all(40), blue + cv::Scalar::all(40), hit);
    std::vector<int> runs;  // lengths of the runs of columns holding the colour, left to right
    bool in_run = false;
    for (int x = 0; x < hit.cols; ++x) {
      const bool any = cv::countNonZero(hit.col(x)) > 0;
      if (any && !in_run) runs.push_back(0);
      if (any) ++runs.back();
      in_run = any;
    }
    ASSERT_GE(runs.size(), 3u);
    EXPECT_GE(runs[0], 4);
    EXPECT_NEAR(runs[0], runs[1], 1);
  }
  bad.field_boundary.points.clear();
  bad.markings.push_back({nan, 0, 10, 10, 1});
  bad.ellipses.push_back({nan, 0, 10, 10, 0, 1});
  bad.ellipses.push_back({10, 10, 0, -5, 0, 1});
  bad.intersections.push_back({.x = nan, .y = 5, .num_rays = 2});
  bad.intersections.push_back({.x = 5, .y = 5, .num_rays = 9});
  cv::Mat other = turf.clone();
  EXPECT_NO_THROW(draw_field_features(other, bad));
}

}  // namespace
}  // namespace fieldlines
