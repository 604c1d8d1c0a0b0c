// assets/default_thresholds.json is the robot's starting point: it must stay equal to the
// built-in defaults (the reference's) and load cleanly.
#include <gtest/gtest.h>

#include "fieldlines/detect/thresholds_file.hpp"
#include "shared_data.hpp"

namespace fieldlines {
namespace {

TEST(Assets, DefaultThresholdsFileEqualsTheBuiltInDefaults) {
  const ThresholdsFile file = load_thresholds_file(test::source_dir() / "assets/default_thresholds.json");
  EXPECT_EQ(file.thresholds, Thresholds{});
  EXPECT_EQ(file.detector, DetectorParams{});
}

}  // namespace
}  // namespace fieldlines
