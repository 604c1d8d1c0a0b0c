// The studio's missed-paint view (gui/model/missed_paint_view.hpp): computed once per image and
// segment set, tinted where paint has no segment, untouched elsewhere.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "fieldlines/data/palette.hpp"
#include "fixtures.hpp"
#include "gui/model/missed_paint_view.hpp"

namespace {

fieldlines::Segment seg(float x0, float y0, float x1, float y1) {
  fieldlines::Segment s;
  s.x0 = x0, s.y0 = y0, s.x1 = x1, s.y1 = y1;
  return s;
}

TEST(MissedPaintView, TintsTheLineWithoutSegmentsAndRecomputesOnlyOnChange) {
  const std::vector<fieldlines::Segment> lines = {seg(20, 60, 300, 60), seg(160, 90, 160, 230)};
  const cv::Mat img = studio_test::field_image(320, 240, lines);
  std::vector<fieldlines::Segment> found = {seg(20, 57, 300, 57), seg(20, 63, 300, 63)};  // the horizontal one
  fieldlines::studio::MissedPaintView view;
  EXPECT_TRUE(view.update(img, found, 1));
  EXPECT_FALSE(view.update(img, found, 1));  // same image, same segments: nothing to do
  EXPECT_EQ(view.found().blobs, 1u);
  constexpr auto c = fieldlines::palette::kMissedPaint;
  EXPECT_EQ(view.tinted().at<cv::Vec3b>(150, 160), cv::Vec3b(c.b, c.g, c.r));  // on the vertical line
  EXPECT_EQ(view.tinted().at<cv::Vec3b>(60, 100), img.at<cv::Vec3b>(60, 100));  // the detected line
  EXPECT_EQ(view.tinted().at<cv::Vec3b>(200, 40), img.at<cv::Vec3b>(200, 40));  // turf
  // Once the vertical line's edges are found too, nothing is tinted.
  found.push_back(seg(157, 90, 157, 230));
  found.push_back(seg(163, 90, 163, 230));
  EXPECT_TRUE(view.update(img, found, 1));
  EXPECT_EQ(view.found().pixels, 0u);
  EXPECT_TRUE(view.update(cv::Mat(), {}, 2));
  EXPECT_TRUE(view.tinted().empty());
}

}  // namespace
