// The detector's fused gradient pass against the OpenCV calls it replaces (cvtColor BGR2GRAY,
// GaussianBlur 8-bit fixed point with BORDER_REFLECT_101, Sobel 3x3 CV_16S with
// BORDER_REPLICATE, |dx| + |dy| below the threshold zeroed): equal bit for bit, on random images
// of awkward sizes, every kernel the parameters allow, and the authors' frames.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "fieldlines/detect/detector.hpp"
#include "shared_data.hpp"

namespace fieldlines {
namespace {

struct Reference {
  cv::Mat dx, dy, magnitude;
};

Reference opencv_gradients(const cv::Mat& bgr, const DetectorParams& p) {
  cv::Mat grey, blurred;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  if (p.gaussian_kernel >= 3) cv::GaussianBlur(grey, blurred, {p.gaussian_kernel, p.gaussian_kernel}, p.gaussian_sigma);
  else blurred = grey;
  Reference r;
  cv::Sobel(blurred, r.dx, CV_16S, 1, 0, 3, 1, 0, cv::BORDER_REPLICATE);
  cv::Sobel(blurred, r.dy, CV_16S, 0, 1, 3, 1, 0, cv::BORDER_REPLICATE);
  cv::Mat sum = cv::abs(r.dx) + cv::abs(r.dy);
  sum.setTo(0, sum < p.gradient_threshold);
  r.magnitude = sum;
  return r;
}

int differing(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type()) return -1;
  return cv::countNonZero(a != b);
}

void expect_same(LineDetector& detector, const cv::Mat& bgr, const std::string& what) {
  const auto ours = detector.compute_gradients(bgr);
  const Reference ref = opencv_gradients(bgr, detector.params());
  EXPECT_EQ(differing(ours.dx, ref.dx), 0) << what << ": dx";
  EXPECT_EQ(differing(ours.dy, ref.dy), 0) << what << ": dy";
  EXPECT_EQ(differing(ours.magnitude, ref.magnitude), 0) << what << ": magnitude";
}

cv::Mat random_bgr(int rows, int cols, std::uint64_t seed) {
  cv::Mat img(rows, cols, CV_8UC3);
  cv::RNG rng(seed);
  rng.fill(img, cv::RNG::UNIFORM, 0, 256);
  // Smooth patches too: ties between |dx| and |dy| and sums near the threshold matter most.
  cv::Mat blocky;
  cv::resize(img(cv::Rect(0, 0, std::max(1, cols / 4), std::max(1, rows / 4))), blocky, img.size(), 0, 0,
             cv::INTER_NEAREST);
  cv::addWeighted(img, 0.2, blocky, 0.8, 0, img);
  return img;
}

TEST(GradientPass, MatchesOpenCvOnAwkwardSizes) {
  LineDetector detector;  // the method's 7x7, sigma 1, threshold 30
  const std::vector<cv::Size> sizes{{3, 3}, {4, 3}, {3, 9}, {7, 5}, {8, 8}, {9, 4}, {15, 17}, {16, 16},
                                    {17, 3}, {31, 33}, {63, 5}, {100, 61}, {641, 479}, {640, 480}};
  std::uint64_t seed = 1;
  for (const cv::Size& s : sizes) expect_same(detector, random_bgr(s.height, s.width, seed++), cv::format("%dx%d", s.width, s.height));
}

TEST(GradientPass, MatchesOpenCvForEveryKernel) {
  for (const int k : {0, 1, 3, 5, 7, 9, 11, 15, 21, 31}) {
    for (const double sigma : {0.3, 0.8, 1.0, 1.5, 2.0, 3.7, 8.0, 20.0}) {
      for (const int threshold : {0, 30, 200}) {
        DetectorParams p;
        p.gaussian_kernel = k;
        p.gaussian_sigma = sigma;
        p.gradient_threshold = threshold;
        LineDetector detector(p);
        const std::string what = cv::format("k=%d sigma=%.2f t=%d", k, sigma, threshold);
        expect_same(detector, random_bgr(37, 53, static_cast<std::uint64_t>(k * 1000 + threshold)), what);
        expect_same(detector, random_bgr(5, 6, 3), what + " small");
      }
    }
  }
}

// This machine may take the AVX2 kernels; the SSE2/NEON ones (what an arm64 robot runs) must
// give the same bits.
TEST(GradientPass, BaselineKernelsMatchOpenCvToo) {
  ::setenv("FIELDLINES_NO_AVX2", "1", 1);
  for (const int k : {0, 3, 5, 7, 9, 13}) {
    DetectorParams p;
    p.gaussian_kernel = k;
    LineDetector detector(p);  // reads the switch when configured
    for (const cv::Size s : {cv::Size(3, 3), cv::Size(9, 5), cv::Size(17, 16), cv::Size(33, 20), cv::Size(641, 479)})
      expect_same(detector, random_bgr(s.height, s.width, 11), cv::format("baseline k=%d %dx%d", k, s.width, s.height));
  }
  ::unsetenv("FIELDLINES_NO_AVX2");
}

TEST(GradientPass, SizesMayChangeBetweenCalls) {
  LineDetector detector;
  expect_same(detector, random_bgr(480, 640, 5), "large first");
  expect_same(detector, random_bgr(20, 30, 6), "then small");
  expect_same(detector, random_bgr(480, 640, 7), "large again");
}

// Row bands (DetectorParams::threads): every band edge is an interior row, so each map must
// still equal OpenCV's whole-image result. Heights around the band minimum (32 rows, or twice
// the kernel), odd ones, frames too short to split, both kernel sets, and sizes changing.
TEST(GradientPass, RowBandsOnSeveralThreadsMatchOpenCv) {
  const std::vector<cv::Size> sizes{{3, 3},   {9, 5},    {17, 31},  {40, 63},    {33, 64},    {50, 65},
                                    {21, 97}, {8, 128},  {100, 129}, {641, 479}, {1280, 720}, {1921, 1081}};
  for (const bool baseline : {false, true}) {
    if (baseline) ::setenv("FIELDLINES_NO_AVX2", "1", 1);
    for (const int k : {0, 3, 5, 7, 15, 31}) {
      for (const int threads : {2, 3, 64}) {
        DetectorParams p;
        p.gaussian_kernel = k;
        p.threads = threads;
        LineDetector detector(p);
        std::uint64_t seed = 40;
        for (const cv::Size& s : sizes) {
          if (threads == 64 && s.area() > 700 * 500) continue;  // enough: 64 is the band count's cap
          expect_same(detector, random_bgr(s.height, s.width, seed++),
                      cv::format("%sk=%d threads=%d %dx%d", baseline ? "baseline " : "", k, threads, s.width, s.height));
        }
      }
    }
    ::unsetenv("FIELDLINES_NO_AVX2");
  }
}

TEST(GradientPass, MatchesOpenCvOnTheAuthorsFrames) {
  FIELDLINES_REQUIRE_SHARED("data/elsed-ssl/images", dir);
  DetectorParams original;  // original ELSED: 5x5 Gaussian
  original.gaussian_kernel = 5;
  LineDetector method, elsed(original);
  int frames = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const cv::Mat bgr = cv::imread(entry.path().string(), cv::IMREAD_COLOR);
    if (bgr.empty()) continue;
    ++frames;
    expect_same(method, bgr, entry.path().filename().string());
    expect_same(elsed, bgr, entry.path().filename().string() + " (5x5)");
  }
  EXPECT_EQ(frames, 41);
}

}  // namespace
}  // namespace fieldlines
