// Determinism of synthetic images and the ground-truth file format.
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/synth/synth.hpp"

namespace fieldlines::synth {
namespace {

bool same_bytes(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

TEST(SynthDeterminism, SameSeedGivesIdenticalImagesMasksAndTruth) {
  for (const Scene scene : {Scene::Ssl, Scene::Kid}) {
    SynthParams p;
    p.field.scene = scene;
    p.conditions = {all_conditions().begin(), all_conditions().end()};
    for (int i = 0; i < 5; ++i) {
      const SynthSample a = generate(p, 42, i), b = generate(p, 42, i);
      EXPECT_TRUE(same_bytes(a.bgr, b.bgr)) << to_string(scene) << " " << i;
      EXPECT_TRUE(same_bytes(a.mask, b.mask));
      EXPECT_EQ(to_json(a.truth), to_json(b.truth));
    }
  }
}

TEST(SynthDeterminism, OtherSeedsAndIndicesGiveOtherImages) {
  const SynthParams p;
  const SynthSample a = generate(p, 1, 0), b = generate(p, 2, 0), c = generate(p, 1, 1);
  EXPECT_FALSE(same_bytes(a.bgr, b.bgr));
  EXPECT_FALSE(same_bytes(a.bgr, c.bgr));
}

TEST(SynthDeterminism, ImagesHaveTheRequestedSizeAndPlausibleColours) {
  const SynthSample s = generate(SynthParams{}, 3, 0);
  EXPECT_EQ(s.bgr.cols, 640);
  EXPECT_EQ(s.bgr.rows, 480);
  EXPECT_EQ(s.bgr.type(), CV_8UC3);
  EXPECT_EQ(s.mask.type(), CV_8UC1);
  // The carpet is green: G above R and B on average where the mask says carpet.
  const cv::Scalar carpet = cv::mean(s.bgr, s.mask == kMaskCarpet);
  EXPECT_GT(carpet[1], carpet[2] + 30);  // G > R (BGR order)
  EXPECT_GT(carpet[1], carpet[0] + 10);  // G > B
  const cv::Scalar paint = cv::mean(s.bgr, s.mask == kMaskPaint);
  ASSERT_GT(cv::countNonZero(s.mask == kMaskPaint), 0);
  EXPECT_GT(paint[2], carpet[2] + 40);  // white paint is much redder than the carpet
}

TEST(SynthTruthFile, RoundTripsThroughDisk) {
  const auto dir = std::filesystem::temp_directory_path() / ("fieldlines_synth_roundtrip_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const SynthSample s = generate(SynthParams{}, 9, 2);
  const SampleFiles files = write_sample(s, dir);
  EXPECT_TRUE(std::filesystem::exists(files.image));
  EXPECT_TRUE(std::filesystem::exists(files.mask));
  EXPECT_EQ(truth_path(files.image), files.truth);
  const GroundTruth t = load_truth(files.truth);
  EXPECT_EQ(t.image, s.truth.image);
  EXPECT_EQ(t.seed, 9u);
  EXPECT_EQ(t.index, 2);
  ASSERT_EQ(t.features.size(), s.truth.features.size());
  for (std::size_t i = 0; i < t.features.size(); ++i) {
    EXPECT_EQ(t.features[i].name, s.truth.features[i].name);
    ASSERT_EQ(t.features[i].points.size(), s.truth.features[i].points.size());
    EXPECT_NEAR(t.features[i].points[0].x, s.truth.features[i].points[0].x, 1e-3);
  }
  std::filesystem::remove_all(dir);
}

TEST(SynthTruthFile, MalformedFilesGiveClearErrors) {
  const auto dir = std::filesystem::temp_directory_path() / ("fieldlines_synth_bad_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto write = [&](const char* name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  auto message = [](const std::filesystem::path& p) -> std::string {
    try {
      load_truth(p);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message(write("a.json", "{not json")).find("malformed JSON"), std::string::npos);
  EXPECT_NE(message(write("b.json", R"({"schema":"other"})")).find("schema"), std::string::npos);
  nlohmann::json good = to_json(generate(SynthParams{}, 1, 0).truth);
  good["version"] = 99;
  EXPECT_NE(message(write("c.json", good.dump())).find("version 99"), std::string::npos);
  good["version"] = 1;
  good["features"] = nlohmann::json::array({{{"label", "marking"}, {"name", "x"}, {"points", {{1, 2, 3}}}}});
  EXPECT_NE(message(write("d.json", good.dump())).find("features[0]"), std::string::npos);
  good["features"] = nlohmann::json::array({{{"label", "tree"}, {"name", "x"}, {"points", {{1, 2, 3}, {4, 5, 6}}}}});
  EXPECT_NE(message(write("e.json", good.dump())).find("'tree'"), std::string::npos);
  EXPECT_NE(message(dir / "missing.json").find("missing.json"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(SynthParamsCheck, BadParametersThrow) {
  SynthParams p;
  p.field.line_width = 0.5;
  EXPECT_THROW(generate(p, 1, 0), Error);
  p = SynthParams{};
  p.conditions.clear();
  EXPECT_THROW(generate(p, 1, 0), Error);
  p = SynthParams{};
  p.camera = CameraRanges{};
  p.camera->height_min = 2, p.camera->height_max = 1;
  EXPECT_THROW(generate(p, 1, 0), Error);
  EXPECT_THROW(parse_scene("futsal"), Error);
  EXPECT_THROW(parse_condition("sunny"), Error);
}

}  // namespace
}  // namespace fieldlines::synth
