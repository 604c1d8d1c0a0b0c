#include <algorithm>
#include <cmath>

#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli_test_support.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "shared_data.hpp"

namespace fieldlines {
namespace {

// A dark wall above a green carpet with a white line painted across it.
cv::Mat field_image() {
  cv::Mat img(480, 640, CV_8UC3, cv::Scalar(50, 130, 40));               // BGR green
  // Slightly tilted wall edge: anchors are looked for every 10th row, like the method, so a
  // perfectly horizontal edge between scan rows would never be seen.
  const std::vector<cv::Point> wall{{0, 0}, {639, 0}, {639, 112}, {0, 92}};
  cv::fillPoly(img, std::vector<std::vector<cv::Point>>{wall}, cv::Scalar(15, 15, 15), cv::LINE_AA);
  cv::line(img, {40, 300}, {600, 330}, cv::Scalar(235, 235, 235), 9, cv::LINE_AA);
  cv::Mat noise(img.size(), img.type());
  cv::randn(noise, 0, 3);
  img += noise;
  return img;
}

const Segment* longest_with(const std::vector<Segment>& segs, Label label) {
  const Segment* best = nullptr;
  for (const Segment& s : segs)
    if (s.label == label && (!best || s.saliency > best->saliency)) best = &s;
  return best;
}

TEST(Detector, FindsTheWhiteLineAsMarkingAndTheWallAsBoundary) {
  cv::theRNG().state = 7;
  LineDetector detector;
  const auto segs = detector.detect(field_image());
  const Segment* marking = longest_with(segs, Label::Marking);
  ASSERT_NE(marking, nullptr);
  // Both edges of the line lie near y = 300 + 30 * (x - 40) / 560, +-5 px.
  const float expected_y0 = 300 + 30.f * (marking->x0 - 40) / 560;
  EXPECT_NEAR(marking->y0, expected_y0, 6);
  EXPECT_GT(std::abs(marking->x1 - marking->x0), 300);
  // The white-minus-green transition has R and B far stronger than G.
  const float ry = std::abs(marking->grad_y[0]), gy = std::abs(marking->grad_y[1]), by = std::abs(marking->grad_y[2]);
  EXPECT_GT(ry, 1.5f * gy);
  EXPECT_GT(by, 1.5f * gy);

  const Segment* boundary = longest_with(segs, Label::Boundary);
  ASSERT_NE(boundary, nullptr);
  EXPECT_NEAR(boundary->y0, 92 + 20.f * boundary->x0 / 639, 2);
  EXPECT_GT(boundary->grad_y[1], 80);  // green rises going down, image-down convention
}

TEST(Detector, RepeatedCallsGiveIdenticalResults) {
  cv::theRNG().state = 11;
  const cv::Mat img = field_image();
  LineDetector detector;
  const auto first = detector.detect(img);
  std::vector<Segment> again;
  detector.detect(cv::Mat(200, 300, CV_8UC3, cv::Scalar(0, 255, 0)), again);  // a different size in between
  detector.detect(img, again);
  ASSERT_EQ(first.size(), again.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].x0, again[i].x0);
    EXPECT_EQ(first[i].saliency, again[i].saliency);
    EXPECT_EQ(first[i].grad_y, again[i].grad_y);
  }
}

// Regression (found by the detector fuzzer in CI): an anchor whose first branch ended on a
// segment reused the previous anchor's pixels -- after a larger image, pixels outside this one --
// to seed its other side. Every result must be what a fresh detector gives.
TEST(Detector, ResultsNeverDependOnEarlierImages) {
  cv::RNG rng(20261130);
  DetectorParams params;  // the original ELSED's denser scan finds far more anchors
  params.gaussian_kernel = 5;
  params.scan_interval = 2;
  params.min_line_length = 15;
  LineDetector reused(params);
  for (int k = 0; k < 400; ++k) {
    const int w = 8 + rng.uniform(0, 200), h = 8 + rng.uniform(0, 150);
    cv::Mat img(h, w, CV_8UC3);
    if (k % 3 == 0) {
      rng.fill(img, cv::RNG::UNIFORM, 0, 256);  // noise: many short, broken edges
    } else {
      img.setTo(cv::Scalar(50, 130, 40));
      for (int l = 0; l < 1 + k % 5; ++l) {
        const cv::Point a(rng.uniform(0, w), rng.uniform(0, h)), b(rng.uniform(0, w), rng.uniform(0, h));
        cv::line(img, a, b, cv::Scalar(230, 230, 230), 1 + rng.uniform(0, 6));
      }
      cv::Mat noise(img.size(), img.type());
      rng.fill(noise, cv::RNG::NORMAL, 0, 4);
      img += noise;
    }
    LineDetector fresh(params);
    const auto expected = fresh.detect(img);
    const auto got = reused.detect(img);
    ASSERT_EQ(got.size(), expected.size()) << "image " << k << " (" << w << "x" << h << ")";
    for (std::size_t i = 0; i < got.size(); ++i) {
      ASSERT_TRUE(std::isfinite(got[i].x0) && std::isfinite(got[i].y1)) << "image " << k;
      EXPECT_EQ(got[i].x0, expected[i].x0) << "image " << k << ", segment " << i;
      EXPECT_EQ(got[i].y1, expected[i].y1) << "image " << k << ", segment " << i;
      EXPECT_EQ(got[i].saliency, expected[i].saliency) << "image " << k << ", segment " << i;
    }
  }
}

TEST(Detector, AcceptsGreyBgraAnd16BitImages) {
  cv::theRNG().state = 3;
  const cv::Mat bgr = field_image();
  LineDetector detector;
  const auto reference = detector.detect(bgr);
  cv::Mat bgra, wide;
  cv::cvtColor(bgr, bgra, cv::COLOR_BGR2BGRA);
  EXPECT_EQ(detector.detect(bgra).size(), reference.size());
  bgr.convertTo(wide, CV_16UC3, 256.0);
  EXPECT_EQ(detector.detect(wide).size(), reference.size());
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  const auto grey_segs = detector.detect(grey);
  EXPECT_FALSE(grey_segs.empty());
  for (const Segment& s : grey_segs) {
    EXPECT_EQ(s.grad_y[0], s.grad_y[1]);  // one channel replicated: equal colour gradients
    EXPECT_NE(s.label, Label::Marking);   // no colour, so no green-to-white transition
  }
}

TEST(Detector, TinyAndFlatImagesGiveNoSegments) {
  LineDetector detector;
  EXPECT_TRUE(detector.detect(cv::Mat(1, 1, CV_8UC3, cv::Scalar::all(9))).empty());
  EXPECT_TRUE(detector.detect(cv::Mat(2, 500, CV_8UC3, cv::Scalar::all(9))).empty());
  EXPECT_TRUE(detector.detect(cv::Mat(5, 5, CV_8UC3, cv::Scalar::all(9))).empty());
  EXPECT_TRUE(detector.detect(cv::Mat(480, 640, CV_8UC3, cv::Scalar(0, 255, 0))).empty());
}

TEST(Detector, RejectsEmptyAndUnsupportedImagesWithAClearError) {
  LineDetector detector;
  EXPECT_THROW(detector.detect(cv::Mat()), Error);
  try {
    detector.detect(cv::Mat(10, 10, CV_32FC3, cv::Scalar::all(0.5)));
    FAIL() << "float image accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("depth"), std::string::npos);
  }
  EXPECT_THROW(detector.detect(cv::Mat(10, 10, CV_8UC2)), Error);
}

TEST(Detector, ValidatesParameters) {
  DetectorParams p;
  p.gaussian_kernel = 4;
  EXPECT_THROW(LineDetector{p}, Error);
  p = {};
  p.scan_interval = 0;
  EXPECT_THROW(LineDetector{p}, Error);
  p = {};
  p.validation_threshold = std::nan("");
  EXPECT_THROW(LineDetector{p}, Error);
  for (const int threads : {0, -1, 65}) {
    p = {};
    p.threads = threads;
    try {
      LineDetector{p};
      FAIL() << "threads = " << threads << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("detector parameter threads: " + std::to_string(threads) + " is outside [1, 64]"),
                std::string::npos)
          << e.what();
    }
  }
  p = {};
  p.threads = 64;
  EXPECT_NO_THROW(LineDetector{p});
  // set_params validates too, and keeps the parameters it had when it refuses.
  LineDetector detector;
  p = {};
  p.centre_circle_radius = 0;
  EXPECT_THROW(detector.set_params(p), Error);
  EXPECT_EQ(detector.params(), DetectorParams{});
  p.centre_circle_radius = 2;
  detector.set_params(p);
  EXPECT_EQ(detector.params().centre_circle_radius, 2);
}

void expect_same_segments(const std::vector<Segment>& got, const std::vector<Segment>& expected,
                          const std::string& what) {
  ASSERT_EQ(got.size(), expected.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) {
    const Segment &a = got[i], &b = expected[i];
    EXPECT_TRUE(a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1) << what << ", segment " << i;
    EXPECT_EQ(a.saliency, b.saliency) << what << ", segment " << i;
    EXPECT_EQ(a.grad_x, b.grad_x) << what << ", segment " << i;
    EXPECT_EQ(a.grad_y, b.grad_y) << what << ", segment " << i;
    EXPECT_EQ(a.label, b.label) << what << ", segment " << i;
  }
}

// Row bands on several threads give the segments one thread gives, bit for bit: odd heights,
// bands just above the minimum, frames too short to split, sizes changing in between, and the
// original ELSED's denser scan (more anchors near band edges).
TEST(Detector, ThreadsGiveTheSegmentsOfOneThread) {
  const std::vector<cv::Size> sizes{{5, 5},     {40, 31},   {64, 63},   {100, 64},  {101, 65},  {160, 97},
                                    {321, 241}, {640, 480}, {641, 479}, {1280, 720}, {1921, 1081}, {33, 400}};
  for (const int kernel : {7, 5, 31}) {
    DetectorParams one;
    one.gaussian_kernel = kernel;
    if (kernel == 5) one.scan_interval = 2, one.min_line_length = 15;
    DetectorParams two = one, three = one;
    two.threads = 2;
    three.threads = 3;
    LineDetector d1(one), d2(two), d3(three);
    int shift = 0;
    std::size_t segments = 0;
    for (const cv::Size& s : sizes) {
      cv::Mat img = test::synthetic_field(s.width, s.height, shift += 3);
      cv::Mat noise(img.size(), img.type());
      cv::randn(noise, 0, 6);  // many weak edges, some right at band boundaries
      img += noise;
      const std::string what = cv::format("k=%d %dx%d", kernel, s.width, s.height);
      const auto expected = d1.detect(img);
      segments += expected.size();
      expect_same_segments(d2.detect(img), expected, what + " 2 threads");
      expect_same_segments(d3.detect(img), expected, what + " 3 threads");
    }
    EXPECT_GT(segments, 20u) << "k=" << kernel;
  }
}

// The authors' frames as they are and scaled to 1280x720 and 1920x1080 (what --detector-threads
// is for), both parameter sets: two threads give the one-thread segments.
TEST(Detector, ThreadsGiveTheSegmentsOfOneThreadOnTheAuthorsFrames) {
  FIELDLINES_REQUIRE_SHARED("data/elsed-ssl/images", dir);
  DetectorParams method, elsed;
  elsed.gaussian_kernel = 5;  // original ELSED
  int frames = 0;
  for (const DetectorParams& one : {method, elsed}) {
    DetectorParams two = one;
    two.threads = 2;
    LineDetector d1(one), d2(two);
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      const cv::Mat bgr = cv::imread(entry.path().string(), cv::IMREAD_COLOR);
      if (bgr.empty()) continue;
      ++frames;
      for (const cv::Size s : {bgr.size(), cv::Size(1280, 720), cv::Size(1920, 1080)}) {
        if (frames % 4 != 0 && s != bgr.size()) continue;  // scaled: every 4th frame keeps the test short
        cv::Mat img;
        cv::resize(bgr, img, s, 0, 0, cv::INTER_LINEAR);
        const std::string what = cv::format("%s k=%d %dx%d", entry.path().filename().string().c_str(),
                                            one.gaussian_kernel, s.width, s.height);
        expect_same_segments(d2.detect(img), d1.detect(img), what);
      }
    }
  }
  EXPECT_EQ(frames, 82);
}

// A moved detector keeps its threads working; destroying one with started threads joins them.
TEST(Detector, ThreadedDetectorMovesAndDestroysCleanly) {
  DetectorParams p;
  p.threads = 2;
  const cv::Mat img = test::synthetic_field(640, 480);
  const auto expected = LineDetector().detect(img);
  LineDetector first(p);
  expect_same_segments(first.detect(img), expected, "first");
  LineDetector moved(std::move(first));
  expect_same_segments(moved.detect(img), expected, "moved");
  for (int i = 0; i < 20; ++i) {
    LineDetector shortlived(p);
    expect_same_segments(shortlived.detect(img), expected, "short-lived");
  }
}

TEST(Detector, WithoutValidationSaliencyIsTheLength) {
  cv::theRNG().state = 5;
  DetectorParams p;
  p.validate = false;
  LineDetector detector(p);
  const auto segs = detector.detect(field_image());
  ASSERT_FALSE(segs.empty());
  for (const Segment& s : segs) EXPECT_NEAR(s.saliency, std::hypot(s.x1 - s.x0, s.y1 - s.y0), 1e-3);
}

}  // namespace
}  // namespace fieldlines
