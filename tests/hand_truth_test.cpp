// Hand-drawn truth of real frames (fieldlines/synth/hand_truth.hpp): the committed files parse,
// their features become the truth GtEdges scores against, and bad files are clear errors.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/synth/gt_eval.hpp"
#include "fieldlines/synth/hand_truth.hpp"
#include "test_paths.hpp"

namespace fl = fieldlines;

namespace {

nlohmann::json one_line() {
  return nlohmann::json::parse(R"({"schema": "fieldlines-hand-truth", "version": 1, "image": "x/a.png",
    "width": 200, "height": 100, "annotated_by": "test",
    "features": [
      {"label": "marking", "name": "line", "points": [[10, 50, 6], [190, 50, 6]]},
      {"label": "boundary_edge", "name": "wall foot", "points": [[0, 10, 3], [199, 10, 3]]},
      {"label": "field_boundary", "name": "field boundary", "points": [[0, 8, 0], [199, 8, 0]]}]})");
}

TEST(HandTruth, FeaturesBecomeTheScoredTruth) {
  const fl::synth::HandTruth h = fl::synth::hand_truth_from_json(one_line(), "t.json");
  EXPECT_EQ(h.image, "x/a.png");
  ASSERT_EQ(h.truth.features.size(), 2u);
  EXPECT_EQ(h.truth.features[0].label, fl::Label::Marking);
  EXPECT_EQ(h.truth.features[1].label, fl::Label::Boundary);
  EXPECT_EQ(h.truth.features[1].points[0].width, 0.f);  // an edge, whatever was written
  ASSERT_EQ(h.field_boundary.size(), 1u);
  // A segment along one edge of the painted line (y = 47) is a marking; one along the wall foot a boundary.
  const fl::GtEdges edges(h.truth);
  fl::Segment s;
  s.x0 = 20, s.y0 = 47, s.x1 = 180, s.y1 = 47;
  EXPECT_EQ(edges.truth_label(s), fl::Label::Marking);
  s.y0 = s.y1 = 10;
  EXPECT_EQ(edges.truth_label(s), fl::Label::Boundary);
  s.y0 = s.y1 = 80;
  EXPECT_EQ(edges.truth_label(s), fl::Label::None);
}

TEST(HandTruth, FieldBoundaryRowsFollowTheDrawingAndStopWhereItStops) {
  nlohmann::json j = one_line();
  // Two polylines with a gap (an occluder), the second running past the frame's right edge.
  j["features"][2]["points"] = nlohmann::json::parse("[[0, 10, 0], [50, 20, 0]]");
  j["features"].push_back(nlohmann::json::parse(
      R"({"label": "field_boundary", "name": "right of a robot", "points": [[120, 30, 0], [1e9, 30, 0]]})"));
  const std::vector<float> rows = fl::synth::field_boundary_rows(fl::synth::hand_truth_from_json(j, "t.json"));
  ASSERT_EQ(rows.size(), 200u);
  EXPECT_FLOAT_EQ(rows[0], 10);
  EXPECT_FLOAT_EQ(rows[25], 15);  // linear between the points
  EXPECT_FLOAT_EQ(rows[50], 20);
  EXPECT_EQ(rows[51], -1);  // the gap counts neither way
  EXPECT_EQ(rows[119], -1);
  EXPECT_NEAR(rows[120], 30, 1e-3);
  EXPECT_NEAR(rows[199], 30, 1e-3);
}

TEST(HandTruth, BadFilesAreClearErrors) {
  nlohmann::json j = one_line();
  j["features"][0]["label"] = "goal";
  EXPECT_THROW(fl::synth::hand_truth_from_json(j, "t.json"), fl::Error);
  j = one_line();
  j["features"][0]["points"] = nlohmann::json::array({nlohmann::json::array({1, 2, 3})});
  EXPECT_THROW(fl::synth::hand_truth_from_json(j, "t.json"), fl::Error);
  j = one_line();
  j["width"] = 0;
  EXPECT_THROW(fl::synth::hand_truth_from_json(j, "t.json"), fl::Error);
  j = one_line();
  j["schema"] = "fieldlines-synth-truth";
  try {
    fl::synth::hand_truth_from_json(j, "t.json");
    ADD_FAILURE() << "a synthetic truth file is not a hand truth file";
  } catch (const fl::Error& e) {
    EXPECT_NE(std::string(e.what()).find("t.json"), std::string::npos) << e.what();
  }
}

TEST(HandTruth, EveryCommittedFileLoads) {
  const std::filesystem::path root = fieldlines::test::source_dir() / "tests/data/hand_truth";
  int files = 0;
  for (const char* set : {"msl-delocht", "msl-bangkok", "msl-bordeaux", "humanoid", "ssl"})
    for (const auto& path : fl::synth::list_hand_truth(root / set)) {
      const fl::synth::HandTruth h = fl::synth::load_hand_truth(path);
      EXPECT_FALSE(h.truth.features.empty()) << path;
      ++files;
    }
  EXPECT_GE(files, 20);
}

}  // namespace
