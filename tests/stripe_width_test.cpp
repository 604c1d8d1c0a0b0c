// The venue's widest plausible stripe from its own frames (fieldlines/train/stripe_width.hpp):
// a limit from the venue's lines keeps them and drops a wider white bar on the turf (a goal's
// ground bar), which the built-in limit takes for paint.
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "painted_field.hpp"

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/train/calibration_inputs.hpp"
#include "fieldlines/train/detector_calibration.hpp"
#include "fieldlines/train/stripe_width.hpp"

namespace fieldlines {
namespace {

using test::kPaint, test::kTurf, test::noisy;

// Lines across the frame as a camera sees a field's: their width grows with the row (a fiftieth
// of it), shifted by `shift` rows between frames.
cv::Mat venue_frame(int shift, std::uint64_t seed) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  for (const int row : {150, 230, 310, 390}) {
    const int y = row + shift, width = y / 50;
    cv::rectangle(clean, cv::Point(0, y - width / 2), cv::Point(639, y - width / 2 + width - 1), kPaint, cv::FILLED);
  }
  return noisy(clean, seed);
}

// What the stripes stage marks between rows `top` and `bottom`, detected with `params`.
int markings_between(const cv::Mat& frame, const DetectorParams& params, float top, float bottom) {
  LineDetector detector(params, Thresholds{});
  std::vector<Segment> segments;
  detector.detect(frame, segments);
  int n = 0;
  for (const Segment& s : segments) {
    const float y = 0.5f * (s.y0 + s.y1);
    n += s.label == Label::Marking && y > top && y < bottom;
  }
  return n;
}

struct Venue {
  DetectorParams chosen = field_detector(DetectorParams{});
  CalibrationInputs inputs;
  explicit Venue(int frames) {
    LineDetector detector(for_fitting(chosen), Thresholds{});
    inputs.check_stripes(chosen);
    for (int k = 0; k < frames; ++k) inputs.add_image(detector, venue_frame(8 * k, 10 + k));
  }
};

TEST(StripeWidth, TheVenuesLinesBoundItsStripesAndAWiderBarIsNoMarking) {
  Venue venue(4);
  const double given = venue.chosen.stripe_max_width;
  const double limit = calibrated_stripe_width(venue.inputs, Thresholds{}, given);
  // The lines are a fiftieth of their row wide: the limit lies a margin above that.
  EXPECT_GT(limit, 0.02);
  EXPECT_LT(limit, 0.05);

  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  cv::rectangle(clean, cv::Point(0, 228), cv::Point(639, 231), kPaint, cv::FILLED);  // a line, 4 px at row 230
  cv::rectangle(clean, cv::Point(80, 380), cv::Point(560, 415), kPaint, cv::FILLED);  // a bar, 36 px at row 398
  const cv::Mat frame = noisy(clean, 3);
  DetectorParams calibrated = venue.chosen;
  calibrated.stripe_max_width = limit;
  EXPECT_GT(markings_between(frame, venue.chosen, 370, 425), 0) << "the built-in limit takes the bar for paint";
  EXPECT_EQ(markings_between(frame, calibrated, 370, 425), 0);
  EXPECT_GT(markings_between(frame, calibrated, 220, 240), 0) << "the line is kept";
}

// The rule on made-up stripes: the nearer half of the rows only, the widest with company.
TEST(StripeWidth, TheWidestNearStripeWithCompanySetsTheLimit) {
  std::vector<MarkedStripe> stripes;
  for (int i = 0; i < 20; ++i) stripes.push_back({0.01, 100.0 + i});        // far pieces
  for (int i = 0; i < 20; ++i) stripes.push_back({0.03 + 0.0005 * i, 400.0 + i});  // near lines
  EXPECT_NEAR(stripe_width_limit(stripes, 0.15), 1.5 * 0.0395, 1e-9);
  // Far, wide-looking stripes above the middle row say nothing of the near lines.
  std::vector<MarkedStripe> with_far = stripes;
  with_far.push_back({0.2, 50});
  EXPECT_NEAR(stripe_width_limit(with_far, 0.15), 1.5 * 0.0395, 1e-9);
  // A lone near stripe far wider than the rest (a leg) is passed over; two alike are company.
  std::vector<MarkedStripe> with_leg = stripes;
  with_leg.push_back({0.09, 420});
  EXPECT_NEAR(stripe_width_limit(with_leg, 0.15), 1.5 * 0.0395, 1e-9);
  with_leg.push_back({0.085, 425});
  EXPECT_NEAR(stripe_width_limit(with_leg, 0.15), 0.135, 1e-9);
  EXPECT_EQ(stripe_width_limit(with_leg, 0.1), 0.1) << "never above the given limit";
  EXPECT_EQ(stripe_width_limit({stripes.begin(), stripes.begin() + 19}, 0.15), 0.15) << "too few stripes";
}

TEST(StripeWidth, FewStripesOrNoCheckKeepTheGivenLimit) {
  Venue none(0);
  EXPECT_EQ(calibrated_stripe_width(none.inputs, Thresholds{}, 0.15), 0.15);
  CalibrationInputs unchecked;  // no stripe check: no widths measured
  LineDetector detector(for_fitting(none.chosen), Thresholds{});
  unchecked.add_image(detector, venue_frame(0, 1));
  EXPECT_EQ(calibrated_stripe_width(unchecked, Thresholds{}, 0.15), 0.15);
  // Never wider than the given limit: wider paint was never measured.
  Venue venue(2);
  EXPECT_EQ(calibrated_stripe_width(venue.inputs, Thresholds{}, 0.01), 0.01);
}

TEST(StripeWidth, OnlyACalibratedDetectorWithStripesGetsTheVenuesLimit) {
  Venue venue(4);
  DetectorParams kept = venue.chosen;
  nlohmann::json given = {{"calibrated", false}};
  calibrate_stripe_width(kept, given, venue.inputs, Thresholds{});
  EXPECT_EQ(kept.stripe_max_width, venue.chosen.stripe_max_width) << "--keep-detector keeps the limit";
  EXPECT_FALSE(given.contains("stripe_max_width"));

  DetectorParams off = venue.chosen;
  off.stripes = false;
  nlohmann::json chosen = {{"calibrated", true}};
  calibrate_stripe_width(off, chosen, venue.inputs, Thresholds{});
  EXPECT_EQ(off.stripe_max_width, venue.chosen.stripe_max_width);

  DetectorParams on = venue.chosen;
  calibrate_stripe_width(on, chosen, venue.inputs, Thresholds{});
  EXPECT_LT(on.stripe_max_width, venue.chosen.stripe_max_width);
  EXPECT_EQ(chosen.value("stripe_max_width", 0.0), on.stripe_max_width);
}

}  // namespace
}  // namespace fieldlines
