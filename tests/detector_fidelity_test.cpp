// Fidelity to the method's reference implementation on the authors' 41 SSL images
// (../shared/data/elsed-ssl), with the configuration they ran.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "fieldlines/detect/detector.hpp"
#include "reference_segments.hpp"
#include "shared_data.hpp"

namespace fieldlines {
namespace {

float endpoint_error(const Segment& a, const Segment& b) {
  const auto d = [](float x0, float y0, float x1, float y1) { return std::hypot(x0 - x1, y0 - y1); };
  const float same = std::max(d(a.x0, a.y0, b.x0, b.y0), d(a.x1, a.y1, b.x1, b.y1));
  const float swapped = std::max(d(a.x0, a.y0, b.x1, b.y1), d(a.x1, a.y1, b.x0, b.y0));
  return std::min(same, swapped);
}

struct Fidelity {
  int reference = 0, ours = 0, matched = 0, gradients_close = 0, saliency_close = 0, same_label = 0;
  float worst_gradient = 0;
};

Fidelity measure(const std::filesystem::path& data) {
  const auto reference = test::read_reference_segments(data / "reference/segments_elsed_ssl.csv");
  LineDetector detector;
  Fidelity f;
  for (const auto& [image, refs] : reference) {
    const cv::Mat bgr = cv::imread((data / "images" / image).string(), cv::IMREAD_COLOR);
    EXPECT_FALSE(bgr.empty()) << image;
    const auto ours = detector.detect(bgr);
    f.reference += static_cast<int>(refs.size());
    f.ours += static_cast<int>(ours.size());
    for (const Segment& r : refs) {
      const Segment* best = nullptr;
      float best_err = 2.f;
      for (const Segment& s : ours) {
        const float e = endpoint_error(r, s);
        if (e <= best_err) best_err = e, best = &s;
      }
      if (!best) continue;
      ++f.matched;
      float worst = 0;
      for (int c = 0; c < 3; ++c) {
        worst = std::max({worst, std::abs(best->grad_x[c] - r.grad_x[c]), std::abs(best->grad_y[c] - r.grad_y[c])});
      }
      f.worst_gradient = std::max(f.worst_gradient, worst);
      f.gradients_close += worst <= 1.5f;
      f.saliency_close += std::abs(best->saliency - r.saliency) <= 0.1f * r.saliency;
      f.same_label += best->label == r.label;
    }
  }
  return f;
}

TEST(DetectorFidelity, MatchesReferenceSegmentsGradientsAndLabels) {
  FIELDLINES_REQUIRE_SHARED("data/elsed-ssl", data);
  const Fidelity f = measure(data);
  const double recall = double(f.matched) / f.reference;
  std::printf("fidelity: reference %d, ours %d (%+.1f%%), matched within 2 px %d (%.1f%%), "
              "gradients within 1.5 %d (worst %.5f), saliency within 10%% %d, same label %d (%.1f%%)\n",
              f.reference, f.ours, 100.0 * (f.ours - f.reference) / f.reference, f.matched, 100 * recall,
              f.gradients_close, f.worst_gradient, f.saliency_close, f.same_label,
              100.0 * f.same_label / std::max(1, f.matched));
  EXPECT_GE(recall, 0.90);
  EXPECT_LE(f.ours, 1.10 * f.reference);
  EXPECT_EQ(f.gradients_close, f.matched);
  EXPECT_EQ(f.saliency_close, f.matched);
  EXPECT_GE(f.same_label, 0.97 * f.matched);
}

// The original ELSED with its own defaults (5x5 Gaussian, scan interval 2, minimum length 15):
// only endpoints are published for it.
TEST(DetectorFidelity, MatchesOriginalElsedWithItsDefaults) {
  FIELDLINES_REQUIRE_SHARED("data/elsed-ssl", data);
  std::ifstream in(data / "reference/segments_elsed_original.csv");
  std::map<std::string, std::vector<Segment>> reference;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string image, cell;
    std::getline(ss, image, ',');
    Segment s;
    float* v[] = {&s.x0, &s.y0, &s.x1, &s.y1};
    for (float* f : v) {
      std::getline(ss, cell, ',');
      *f = std::stof(cell);
    }
    reference[image].push_back(s);
  }
  DetectorParams p;
  p.gaussian_kernel = 5;
  p.scan_interval = 2;
  p.min_line_length = 15;
  LineDetector detector(p);
  int total = 0, ours = 0, matched = 0;
  for (const auto& [image, refs] : reference) {
    const auto segs = detector.detect(cv::imread((data / "images" / image).string(), cv::IMREAD_COLOR));
    total += static_cast<int>(refs.size());
    ours += static_cast<int>(segs.size());
    for (const Segment& r : refs)
      matched += std::any_of(segs.begin(), segs.end(), [&](const Segment& s) { return endpoint_error(r, s) <= 2.f; });
  }
  std::printf("original ELSED fidelity: reference %d, ours %d, matched within 2 px %d (%.1f%%)\n", total, ours,
              matched, 100.0 * matched / total);
  EXPECT_GE(matched, 0.90 * total);
  EXPECT_LE(ours, 1.10 * total);
}

}  // namespace
}  // namespace fieldlines
