// The robot's thresholds file: round trip, version and range checks, clear errors.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "test_paths.hpp"

namespace fl = fieldlines;
namespace fs = std::filesystem;

namespace {

// Named for the running test: ctest runs the tests of this file in parallel processes, and two
// of them writing and removing one "bad.json" read each other's file or none.
fs::path temp(const std::string& name) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  return fs::temp_directory_path() / ("fl_thr_" + test + "_" + name);
}

std::string load_error(const std::string& text) {
  const fs::path p = temp("bad.json");
  std::ofstream(p) << text;
  try {
    fl::load_thresholds_file(p);
  } catch (const fl::Error& e) {
    fs::remove(p);
    return e.what();
  }
  fs::remove(p);
  return "";
}

fl::ThresholdsFile sample() {
  fl::ThresholdsFile f;
  f.detector.gradient_threshold = 42;
  f.detector.junction_sizes = {3, 5};
  f.thresholds.marking.thresholds = {12.5f, 33.25f, 61.f};
  f.thresholds.boundary.thresholds = {20.f, 45.f, 80.f};
  f.thresholds.mode = fl::GradientMode::Normal;
  f.provenance = {{"seed", 3}, {"train", {{"marking", {{"tp", 10}}}}}};
  return f;
}

}  // namespace

TEST(ThresholdsFile, RoundTrips) {
  const fs::path p = temp("ok.json");
  const fl::ThresholdsFile f = sample();
  fl::save_thresholds_file(p, f);
  const fl::ThresholdsFile g = fl::load_thresholds_file(p);
  fs::remove(p);
  EXPECT_EQ(g.detector, f.detector);
  EXPECT_EQ(g.thresholds, f.thresholds);
  EXPECT_EQ(g.provenance, f.provenance);
}

// The stripes stage (stripes.hpp) and its parameters are detector parameters: written and read
// with the others; a file from before them (the shipped default among them) reads with the stage off.
TEST(ThresholdsFile, KeepsTheStripesAndReadsOldFilesWithThemOff) {
  fl::ThresholdsFile f = sample();
  f.detector.stripes = true;
  f.detector.stripe_samples = 9;
  f.detector.stripe_max_width = 0.2;
  f.detector.stripe_require_twin = true;
  const fs::path p = temp("stripes.json");
  fl::save_thresholds_file(p, f);
  const fl::ThresholdsFile g = fl::load_thresholds_file(p);
  fs::remove(p);
  EXPECT_EQ(g.detector, f.detector);
  EXPECT_TRUE(g.detector.stripes);

  nlohmann::json old = fl::to_json(sample());
  for (const char* key : {"stripes", "stripe_samples", "stripe_max_width", "stripe_require_twin"})
    ASSERT_EQ(old["detector"].erase(key), 1u) << key;
  const fl::ThresholdsFile h = fl::thresholds_file_from_json(old, "old.json");
  EXPECT_FALSE(h.detector.stripes);
  EXPECT_EQ(h.detector, sample().detector);
  const fl::ThresholdsFile shipped = fl::load_thresholds_file(fieldlines::test::source_dir() / "assets/default_thresholds.json");
  EXPECT_FALSE(shipped.detector.stripes);

  EXPECT_NE(load_error(R"({"format": "fieldlines-thresholds", "version": 1, "detector": {"stripes": 1},
      "gradient_mode": "axes", "classes": {}})").find("detector.stripes: expected true or false"), std::string::npos);
  EXPECT_NE(load_error(R"({"format": "fieldlines-thresholds", "version": 1, "detector": {"stripe_samples": 0},
      "gradient_mode": "axes", "classes": {}})").find("stripe_samples: 0 is outside [1, 32]"), std::string::npos);
}

TEST(ThresholdsFile, RejectsNewerVersionsMalformedJsonAndBadRanges) {
  nlohmann::json j = fl::to_json(sample());
  j["version"] = fl::kThresholdsFileVersion + 1;
  EXPECT_NE(load_error(j.dump()).find("newer"), std::string::npos);
  EXPECT_NE(load_error("{\"format\": ").find("malformed JSON"), std::string::npos);
  EXPECT_NE(load_error("{}").find("not a fieldlines thresholds file"), std::string::npos);
  j = fl::to_json(sample());
  j["classes"]["marking"]["max_angle_deg"] = 200;
  EXPECT_NE(load_error(j.dump()).find("classes.marking.max_angle_deg"), std::string::npos);
  j = fl::to_json(sample());
  j["classes"]["boundary"].erase("min_length");
  EXPECT_NE(load_error(j.dump()).find("min_length"), std::string::npos);
  j = fl::to_json(sample());
  j["detector"]["scan_interval"] = 0;
  EXPECT_NE(load_error(j.dump()).find("scan_interval"), std::string::npos);
  j = fl::to_json(sample());
  j["gradient_mode"] = "diagonal";
  EXPECT_NE(load_error(j.dump()).find("gradient_mode"), std::string::npos);
  j = fl::to_json(sample());
  j["classes"]["marking"]["from"] = {1, 2};
  EXPECT_NE(load_error(j.dump()).find("from"), std::string::npos);
  EXPECT_NE(load_error("").find("bad.json"), std::string::npos);
}
