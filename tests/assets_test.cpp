// assets/default_thresholds.json is the robot's starting point: it must stay equal to the
// built-in defaults (the reference's), load cleanly, and read as the writer writes it (a
// parameter added to the table shows in the file a robot copies).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "fieldlines/detect/thresholds_file.hpp"
#include "shared_data.hpp"

namespace fieldlines {
namespace {

TEST(Assets, DefaultThresholdsFileEqualsTheBuiltInDefaults) {
  const ThresholdsFile file = load_thresholds_file(test::source_dir() / "assets/default_thresholds.json");
  EXPECT_EQ(file.thresholds, Thresholds{});
  EXPECT_EQ(file.detector, DetectorParams{});
}

TEST(Assets, DefaultThresholdsFileIsWhatTheWriterWrites) {
  const auto path = test::source_dir() / "assets/default_thresholds.json";
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  EXPECT_EQ(bytes.str(), to_json(load_thresholds_file(path)).dump(2) + "\n")
      << "regenerate it: fieldlines' save_thresholds_file over the loaded file";
}

}  // namespace
}  // namespace fieldlines
