#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "fieldlines/detect/classifier.hpp"
#include "shared_data.hpp"

namespace fieldlines {
namespace {

Segment horizontal_segment(Rgb grad_y, float saliency) {
  Segment s;
  s.x1 = 100;
  s.grad_y = grad_y;
  s.saliency = saliency;
  return s;
}

TEST(Classifier, WhiteLineOnGreenIsAMarkingFromEitherSide) {
  const Thresholds t;
  // Green (60,140,60) above, white (230,230,230) below: d/dy = white - green.
  EXPECT_EQ(classify(horizontal_segment({170, 90, 170}, 200), t), Label::Marking);
  EXPECT_EQ(classify(horizontal_segment({-170, -90, -170}, 200), t), Label::Marking);
}

TEST(Classifier, BlackWallAboveGreenIsABoundaryButNotBelow) {
  const Thresholds t;
  EXPECT_EQ(classify(horizontal_segment({20, 120, 30}, 200), t), Label::Boundary);
  // Green above, black below: the wrong side for a boundary, and not white either.
  EXPECT_EQ(classify(horizontal_segment({-20, -120, -30}, 200), t), Label::None);
}

TEST(Classifier, ShortOrWeakSegmentsAreNone) {
  const Thresholds t;
  EXPECT_EQ(classify(horizontal_segment({170, 90, 170}, 50), t), Label::None);
  EXPECT_EQ(classify(horizontal_segment({17, 9, 17}, 200), t), Label::None);
}

TEST(Classifier, ZeroGradientIsNoneAndNotNaN) {
  const Thresholds t;
  const SegmentFeatures f = compute_features(horizontal_segment({0, 0, 0}, 500), t);
  EXPECT_FALSE(std::isnan(f.boundary.angle_deg));
  EXPECT_FALSE(std::isnan(f.marking[0].projection));
  EXPECT_EQ(classify(f, t), Label::None);
}

TEST(Classifier, MarkingIsAlsoTestedOnTheXGradient) {
  Segment s;
  s.y1 = 100;  // vertical segment: the transition shows in grad_x
  s.grad_x = {170, 90, 170};
  s.saliency = 200;
  EXPECT_EQ(classify(s, Thresholds{}), Label::Marking);
}

TEST(Classifier, NormalModeSeesAnObliqueLineTheAxesMiss) {
  // A 45-degree white line: each axis sees only ~70% of the transition, at a worse angle.
  Segment s;
  s.x1 = 100;
  s.y1 = 100;
  s.saliency = 200;
  s.grad_x = {-40, -21, -40};
  s.grad_y = {40, 21, 40};
  Thresholds axes;
  axes.marking.thresholds.min_projection = 70;
  Thresholds normal = axes;
  normal.mode = GradientMode::Normal;
  EXPECT_EQ(classify(s, axes), Label::None);
  EXPECT_EQ(classify(s, normal), Label::Marking);
}

// The reference classifier's own test vectors: every labelled annotation row with default or
// random thresholds and the label the reference returned.
TEST(Classifier, AgreesWithReferenceVectors) {
  FIELDLINES_REQUIRE_SHARED("data/elsed-ssl/reference/classification_vectors.csv", csv);
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  int rows = 0, agree_exact_pi = 0, agree_reference_pi = 0;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string cell;
    std::getline(ss, cell, ',');
    std::getline(ss, cell, ',');
    std::vector<double> v;
    while (std::getline(ss, cell, ',')) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), 14u) << line;
    Segment s = horizontal_segment({}, static_cast<float>(v[6]));
    for (int c = 0; c < 3; ++c) {
      s.grad_x[2 - c] = static_cast<float>(v[c]);
      s.grad_y[2 - c] = -static_cast<float>(v[3 + c]);
    }
    Thresholds t;
    t.boundary.thresholds = {float(v[7]), float(v[8]), float(v[9])};
    t.marking.thresholds = {float(v[10]), float(v[11]), float(v[12])};
    const auto expected = static_cast<Label>(static_cast<int>(v[13]));
    agree_exact_pi += classify(s, t) == expected;
    t.reference_pi = true;
    agree_reference_pi += classify(s, t) == expected;
    ++rows;
  }
  std::printf("classification vectors: %d rows, agree %d with pi, %d with the reference's 3.1415\n", rows,
              agree_exact_pi, agree_reference_pi);
  ASSERT_GT(rows, 8000);
  EXPECT_EQ(agree_reference_pi, rows);
  EXPECT_GE(agree_exact_pi, 0.999 * rows);
}

}  // namespace
}  // namespace fieldlines
