// Per-frame light adaptation (fieldlines/detect/light.hpp): the field colour of a frame, the
// gain onto the calibration's exposure, and a darkened frame keeping its markings with it on.
#include <algorithm>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "cli_test_support.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/light.hpp"
#include "fieldlines/detect/params_json.hpp"

namespace fl = fieldlines;

namespace {

int markings(const std::vector<fl::Segment>& segments) {
  return static_cast<int>(std::count_if(segments.begin(), segments.end(),
                                        [](const fl::Segment& s) { return s.label == fl::Label::Marking; }));
}

TEST(Light, FieldColourIsTheMedianOfTheGreenPixels) {
  const cv::Mat frame = fl::test::synthetic_field(640, 480);  // carpet BGR (50, 140, 40)
  const auto field = fl::estimate_field_colour(frame);
  ASSERT_TRUE(field);
  EXPECT_NEAR((*field)[0], 40, 4);
  EXPECT_NEAR((*field)[1], 140, 4);
  EXPECT_NEAR((*field)[2], 50, 4);
  // No field: grey, black, a sliver of green under the 2 % share, a wrong pixel type.
  EXPECT_FALSE(fl::estimate_field_colour(cv::Mat(480, 640, CV_8UC3, cv::Scalar(128, 128, 128))));
  EXPECT_FALSE(fl::estimate_field_colour(cv::Mat(480, 640, CV_8UC3, cv::Scalar(0, 0, 0))));
  cv::Mat sliver(480, 640, CV_8UC3, cv::Scalar(128, 128, 128));
  sliver.rowRange(0, 4).setTo(cv::Scalar(50, 140, 40));
  EXPECT_FALSE(fl::estimate_field_colour(sliver));
  EXPECT_FALSE(fl::estimate_field_colour(cv::Mat(480, 640, CV_8UC1, cv::Scalar(128))));
  EXPECT_FALSE(fl::estimate_field_colour(cv::Mat()));
}

TEST(Light, GainMapsTheFieldBrightnessAndIsClamped) {
  EXPECT_FLOAT_EQ(fl::light_gain({40, 140, 50}, {20, 70, 25}), 2.f);
  EXPECT_FLOAT_EQ(fl::light_gain({40, 140, 50}, {40, 140, 50}), 1.f);
  EXPECT_FLOAT_EQ(fl::light_gain({40, 140, 50}, {1, 2, 1}), 4.f);
  EXPECT_FLOAT_EQ(fl::light_gain({10, 20, 10}, {200, 250, 200}), 0.25f);
  std::vector<fl::Segment> s(1);
  s[0].grad_x = {1, 2, 3};
  s[0].grad_y = {-4, 5, -6};
  fl::apply_light_gain(s, 2.f);
  EXPECT_EQ(s[0].grad_x, (fl::Rgb{2, 4, 6}));
  EXPECT_EQ(s[0].grad_y, (fl::Rgb{-8, 10, -12}));
}

// Thresholds whose projection floor sits just under the markings' contrast of a well-exposed
// frame (as calibration by contrast gives): at half the exposure the markings fall under it,
// unless the detector maps the frame back onto the calibration's exposure.
TEST(Light, ADarkerFrameKeepsItsMarkingsWithAdaptation) {
  const cv::Mat bright = fl::test::synthetic_field(640, 480, 3);
  fl::Thresholds t;
  t.boundary.thresholds = {1000.f, 0.f, 100000.f};  // markings alone
  t.marking.thresholds = {0.f, 30.f, 40.f};
  std::vector<fl::Segment> found = fl::LineDetector({}, t).detect(bright);
  float weakest = 1e9f;
  for (const fl::Segment& s : found) {
    if (s.label != fl::Label::Marking) continue;
    const fl::SegmentFeatures f = fl::compute_features(s, t);
    float best = 0;
    for (int i = 0; i < f.marking_count; ++i)
      if (f.marking[i].angle_deg <= 30.f) best = std::max(best, f.marking[i].projection);
    weakest = std::min(weakest, best);
  }
  const int bright_markings = markings(found);
  ASSERT_GE(bright_markings, 4);
  t.marking.thresholds.min_projection = 0.8f * weakest;
  ASSERT_EQ(markings(fl::LineDetector({}, t).detect(bright)), bright_markings);

  cv::Mat dark;
  bright.convertTo(dark, -1, 0.5);
  EXPECT_LE(markings(fl::LineDetector({}, t).detect(dark)), bright_markings / 4) << "the test needs a binding floor";
  fl::Thresholds adapted = t;
  adapted.light = {true, *fl::estimate_field_colour(bright)};
  const std::vector<fl::Segment> dark_found = fl::LineDetector({}, adapted).detect(dark);
  EXPECT_GE(markings(dark_found), bright_markings - 1);
  // On the calibration's own exposure the adaptation changes nothing.
  EXPECT_EQ(markings(fl::LineDetector({}, adapted).detect(bright)), bright_markings);
}

TEST(Light, ADarkFieldLowersTheGradientThresholdInProportion) {
  const fl::Rgb field{40, 120, 40};  // R + G + B = 200
  EXPECT_EQ(fl::adapted_gradient_threshold(30, 0, field), 30) << "off";
  EXPECT_EQ(fl::adapted_gradient_threshold(30, 200, field), 30) << "as bright as the reference";
  EXPECT_EQ(fl::adapted_gradient_threshold(30, 100, field), 30) << "brighter: never raised";
  EXPECT_EQ(fl::adapted_gradient_threshold(30, 400, field), 15);
  EXPECT_EQ(fl::adapted_gradient_threshold(30, 4000, field), fl::kMinAdaptedGradient) << "floored";
  EXPECT_EQ(fl::adapted_gradient_threshold(5, 4000, field), 5) << "the floor never raises it";
  EXPECT_EQ(fl::adapted_gradient_threshold(30, 400, std::nullopt), 30) << "no field in view";
}

// The detector's own threshold (here one that binds on the synthetic field's sharp edges): at a
// third of the exposure a frame's edges fall under it and its segments vanish, whatever the
// classes' thresholds; with dark_field the threshold follows the field and the frame keeps them.
TEST(Light, ADarkFrameKeepsItsSegmentsWithDarkField) {
  const cv::Mat bright = fl::test::synthetic_field(640, 480, 3);
  cv::Mat dark;
  bright.convertTo(dark, -1, 0.3);
  fl::DetectorParams p;
  p.gradient_threshold = 200;
  const std::size_t at_full = fl::LineDetector(p).detect(bright).size();
  ASSERT_GE(at_full, 4u);
  ASSERT_LE(fl::LineDetector(p).detect(dark).size(), at_full / 2) << "the test needs a binding threshold";
  const fl::Rgb field = *fl::estimate_field_colour(bright);
  p.dark_field = static_cast<double>(field[0]) + field[1] + field[2];
  fl::LineDetector adapting(p);
  EXPECT_EQ(adapting.detect(bright).size(), at_full) << "a field as bright as dark_field keeps the threshold";
  EXPECT_GE(adapting.detect(dark).size(), at_full - 1);
}

TEST(Light, ThresholdsJsonCarriesItOnlyWhenOn) {
  fl::Thresholds t;
  EXPECT_FALSE(fl::thresholds_to_json(t).contains("light"));
  t.light = {true, {40, 120, 45}};
  const nlohmann::json j = fl::thresholds_to_json(t);
  ASSERT_TRUE(j.contains("light"));
  EXPECT_EQ(fl::thresholds_from_json(j, "t").light, t.light);
  nlohmann::json bad = j;
  bad["light"]["reference_field"] = {1, 2};
  EXPECT_THROW(fl::thresholds_from_json(bad, "t"), fl::Error);
  bad["light"] = "on";
  EXPECT_THROW(fl::thresholds_from_json(bad, "t"), fl::Error);
  bad = j;
  bad["light"]["reference_field"] = {40, 0, 45};
  EXPECT_THROW(fl::thresholds_from_json(bad, "t"), fl::Error);
}

}  // namespace
