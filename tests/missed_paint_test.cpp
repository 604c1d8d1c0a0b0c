// Paint with no segment (fieldlines/data/missed_paint.hpp): a line without a segment shows,
// a line with its segments does not, turf texture and off-field white do not.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "fieldlines/data/missed_paint.hpp"
#include "fieldlines/detect/error.hpp"

namespace fl = fieldlines;

namespace {

fl::Segment seg(float x0, float y0, float x1, float y1) {
  fl::Segment s;
  s.x0 = x0, s.y0 = y0, s.x1 = x1, s.y1 = y1;
  return s;
}

// Turf with a little texture, a horizontal and a vertical 6 px white line.
cv::Mat field() {
  cv::Mat img(240, 320, CV_8UC3, cv::Scalar(40, 140, 40));
  cv::Mat noise(img.size(), CV_8UC3);
  cv::randn(noise, cv::Scalar(0, 0, 0), cv::Scalar(6, 6, 6));
  img += noise;
  cv::line(img, {20, 60}, {300, 60}, cv::Scalar(235, 235, 235), 6);
  cv::line(img, {160, 90}, {160, 230}, cv::Scalar(235, 235, 235), 6);
  return img;
}

TEST(MissedPaint, ALineWithoutSegmentsShowsAndOneWithThemDoesNot) {
  const cv::Mat img = field();
  // The horizontal line's two edges are detected, the vertical line is not.
  const fl::Segment edges[] = {seg(20, 57, 300, 57), seg(20, 63, 300, 63)};
  const fl::MissedPaint m = fl::find_missed_paint(img, edges);
  EXPECT_EQ(m.blobs, 1u);
  // Most of the vertical line (6 x 140 px) and nothing of the horizontal one.
  EXPECT_GT(m.pixels, 600u);
  EXPECT_EQ(cv::countNonZero(m.mask.rowRange(50, 70)), 0);
  EXPECT_GT(cv::countNonZero(m.mask.colRange(155, 166).rowRange(95, 225)), 600);
  EXPECT_EQ(static_cast<std::size_t>(cv::countNonZero(m.mask)), m.pixels);
}

TEST(MissedPaint, EverySegmentFoundMeansNothingMissed) {
  const fl::Segment all[] = {seg(20, 57, 300, 57), seg(20, 63, 300, 63), seg(157, 90, 157, 230),
                             seg(163, 90, 163, 230)};
  const fl::MissedPaint m = fl::find_missed_paint(field(), all);
  EXPECT_EQ(m.pixels, 0u);
  EXPECT_EQ(m.blobs, 0u);
}

TEST(MissedPaint, WhiteOffTheFieldAndTinySpecksAreNotPaint) {
  cv::Mat img = field();
  img.rowRange(0, 30).setTo(cv::Scalar(230, 230, 230));  // a white wall above the field
  cv::Mat grey(img.size(), CV_8UC3, cv::Scalar(90, 90, 90));  // no turf at all
  cv::circle(img, {60, 200}, 2, cv::Scalar(255, 255, 255), -1);  // a speck (~13 px)
  const fl::Segment all[] = {seg(20, 57, 300, 57), seg(20, 63, 300, 63), seg(157, 90, 157, 230),
                             seg(163, 90, 163, 230)};
  EXPECT_EQ(cv::countNonZero(fl::find_missed_paint(img, all).mask.rowRange(0, 20)), 0);
  EXPECT_EQ(fl::find_missed_paint(img, all).blobs, 0u);
  cv::line(grey, {0, 100}, {319, 100}, cv::Scalar(250, 250, 250), 6);
  EXPECT_EQ(fl::find_missed_paint(grey, {}).pixels, 0u);
}

TEST(MissedPaint, BadInputIsAnError) {
  EXPECT_THROW(fl::find_missed_paint(cv::Mat(), {}), fl::Error);
  EXPECT_THROW(fl::find_missed_paint(cv::Mat(10, 10, CV_8UC1, cv::Scalar(0)), {}), fl::Error);
  fl::MissedPaintParams even;
  even.window = 30;
  EXPECT_THROW(fl::find_missed_paint(field(), {}, even), fl::Error);
}

}  // namespace
