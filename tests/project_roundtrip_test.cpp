// A saved project loads back with the same thresholds, detector parameters and labels, and a
// project made by `autolabel` trains (regression: thresholds were once saved as nulls).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"

namespace fieldlines::test {
namespace {

class ProjectRoundTrip : public TempDirTest {};

TEST_F(ProjectRoundTrip, SaveThenLoadKeepsEverything) {
  Project p;
  p.detector.scan_interval = 4;
  p.thresholds.marking.thresholds = {40, 25, 80};
  p.thresholds.mode = GradientMode::Normal;
  ImageEntry e;
  e.path = "frames/a.png";
  e.segments.push_back({1, 2, 3, 4, 50, {1, 2, 3}, {4, 5, 6}, Label::Marking});
  e.segments.push_back({5, 6, 7, 8, 60, {0, 0, 0}, {9, 9, 9}, Label::Unlabelled});
  p.images.push_back(e);
  const auto file = dir_ / "project.json";
  p.save(file);
  const Project q = Project::load(file);
  EXPECT_EQ(q.thresholds, p.thresholds);
  EXPECT_EQ(q.detector, p.detector);
  ASSERT_EQ(q.images.size(), 1u);
  ASSERT_EQ(q.images[0].segments.size(), 2u);
  EXPECT_EQ(q.images[0].segments[0].label, Label::Marking);
  EXPECT_EQ(q.images[0].segments[1].label, Label::Unlabelled);
  EXPECT_EQ(q.labelled_count(), 1u);
  q.save(file);  // a loaded project can be saved over itself
}

// How the detector was chosen from the frames rides along with the project; a file whose record
// is no object is refused by name, never half read.
TEST_F(ProjectRoundTrip, TheDetectorsChoiceIsKeptAndAMalformedOneRefused) {
  Project p;
  const auto file = dir_ / "project.json";
  p.save(file);
  EXPECT_TRUE(Project::load(file).detector_choice.is_null());
  EXPECT_FALSE(nlohmann::json::parse(read_file(file)).contains("detector_choice")) << "none: no key";
  p.detector_choice = {{"calibrated", true}, {"field_texture", 12.5}, {"frames_with_field", 4}};
  p.save(file);
  EXPECT_EQ(Project::load(file).detector_choice, p.detector_choice);
  nlohmann::json j = nlohmann::json::parse(read_file(file));
  j["detector_choice"] = "calibrated";
  write_file_atomically(file, j.dump());
  try {
    Project::load(file);
    ADD_FAILURE() << "a record that is no object loaded";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'detector_choice' must be an object"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("project.json"), std::string::npos) << e.what();
  }
}

TEST_F(ProjectRoundTrip, ProposalsRoundTripAndAreNeverLabels) {
  Project p;
  ImageEntry e;
  e.path = "a.png";
  e.segments.push_back({1, 2, 3, 4, 50, {1, 2, 3}, {4, 5, 6}, Label::Marking});
  e.segments.push_back({5, 6, 7, 8, 60, {0, 0, 0}, {9, 9, 9}, Label::Unlabelled});
  e.proposals = {Label::Unlabelled, Label::Boundary};
  p.images.push_back(e);
  ImageEntry without = e;
  without.path = "b.png";
  without.proposals.clear();
  p.images.push_back(without);
  const auto file = dir_ / "project.json";
  p.save(file);
  Project q = Project::load(file);
  EXPECT_EQ(q.images[0].proposals, e.proposals);
  EXPECT_TRUE(q.images[1].proposals.empty());
  EXPECT_EQ(q.images[1].proposal(1), Label::Unlabelled);
  EXPECT_EQ(q.labelled_count(), 2u);  // one human label per image; the proposal is not one
  EXPECT_EQ(q.labelled().count(Label::Boundary), 0u);
  // Re-detection drops them: they were for the old segments.
  q.replace_segments(0, q.images[0].segments);
  EXPECT_TRUE(q.images[0].proposals.empty());
  // A proposals array of the wrong length or with a bad label is refused with its place.
  const nlohmann::json good = nlohmann::json::parse(read_text(file));
  for (const auto& [edit, where] : {std::pair<const char*, const char*>{"label", "proposals[1]"}, {"length", ".proposals"}}) {
    nlohmann::json bad = good;
    if (std::string(edit) == "label") bad["images"][0]["proposals"][1] = "wall";
    else bad["images"][0]["proposals"].erase(0);
    write_bytes("bad.json", bad.dump());
    try {
      Project::load(dir_ / "bad.json");
      ADD_FAILURE() << "a bad proposals array must not load (" << edit << ")";
    } catch (const Error& err) {
      EXPECT_NE(std::string(err.what()).find(where), std::string::npos) << err.what();
    }
  }
}

TEST_F(ProjectRoundTrip, AutolabelledProjectTrains) {
  ASSERT_EQ(run_cli({"synth", "--scene", "ssl", "--n", "3", "--seed", "5", "-o", (dir_ / "set").string()}, dir_).exit_code, 0);
  const CliRun label = run_cli({"autolabel", (dir_ / "set").string()}, dir_);
  ASSERT_EQ(label.exit_code, 0) << label.err;
  const CliRun train = run_cli({"train", (dir_ / "set" / "project.json").string(), "--iterations", "5", "--particles",
                                "10", "-o", (dir_ / "t.json").string()}, dir_);
  EXPECT_EQ(train.exit_code, 0) << train.err;
  EXPECT_TRUE(std::filesystem::exists(dir_ / "t.json"));
}

}  // namespace
}  // namespace fieldlines::test
