// The review loop in the real window: a fresh folder of synthetic Kid frames, P to propose,
// Enter once per image, quit. Every segment ends up labelled, and the labels agree with the
// frames' exact ground truth (as `fieldlines autolabel` gives it with the detector the studio
// chose from the frames): 93.4 % on this set (seed 5, 20 frames); asserted at 91 %, because other
// sets of our renderer give 93.6-95.7 % (docs/studio.md).
// ctest-label: slow

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "gui/model/open_project.hpp"
#include "tests/shared_data.hpp"
#include "x_session.hpp"

namespace fs = std::filesystem;
using fieldlines::Label;
using namespace std::chrono_literals;

namespace {

using studio_test::read_state;
using studio_test::run;
using studio_test::wait_for;

class StudioReviewWindow : public studio_test::StudioUnderX {};

TEST_F(StudioReviewWindow, ProposeThenOneEnterPerImageLabelsAFreshFolder) {
  const fs::path frames = dir() / "frames", truth = dir() / "truth.json";
  const std::string cli = fieldlines::test::cli_path().string();
  ASSERT_EQ(run(cli + " synth --scene kid --n 20 --seed 5 --quiet -o " + frames.string() + " >/dev/null"), 0);
  project_ = frames;  // a folder: the studio detects it and makes its project inside
  auto studio = start_studio();
  ASSERT_TRUE(studio->running()) << log();
  ASSERT_TRUE(wait_for([&] {
    const auto st = read_state(state_);
    return !st.is_null() && !st["detecting"].get<bool>() && !st["detection"].get<std::string>().empty();
  }, 60s)) << log();
  const std::size_t segments = read_state(state_)["to_review"].get<std::size_t>();
  ASSERT_GT(segments, 100u);

  int keys = 0;
  act_and_wait_for_save("key p");
  ++keys;
  for (int press = 0; press < 60 && read_state(state_)["to_review"].get<std::size_t>() > 0; ++press) {
    const auto before = read_state(state_);
    ASSERT_EQ(run(x("key Return")), 0);
    ++keys;
    ASSERT_TRUE(wait_for([&] {
      const auto st = read_state(state_);
      return st["to_review"] != before["to_review"] || st["image"] != before["image"];
    }, 10s)) << "Enter did nothing";
  }
  EXPECT_EQ(read_state(state_)["to_review"], 0);
  ASSERT_EQ(run(x("key ctrl+q")), 0);
  ASSERT_TRUE(wait_for([&] { return !studio->running(); }, 15s));
  EXPECT_EQ(studio->exit_code(), 0);

  // Against the ground truth: the same detector (the one the studio chose from the frames, which
  // its project holds) on the same frames gives the same segments.
  const fieldlines::Project labelled = fieldlines::Project::load(frames / fieldlines::studio::kFolderProjectName);
  EXPECT_FALSE(labelled.detector == fieldlines::studio::folder_detector()) << "chosen from the frames";
  const fs::path detector = dir() / "detector.json";
  fieldlines::save_thresholds_file(detector, {labelled.detector, {}, {}});
  ASSERT_EQ(run(cli + " autolabel " + frames.string() + " --thresholds " + detector.string() + " -o " + truth.string() +
                " --quiet"),
            0);
  const fieldlines::Project gt = fieldlines::Project::load(truth);
  std::map<std::string, const fieldlines::ImageEntry*> by_name;
  for (const auto& e : gt.images) by_name[fs::path(e.path).filename().string()] = &e;
  std::size_t total = 0, agree = 0, unlabelled = 0;
  std::map<std::string, int> confusion;  // truth -> accepted
  for (const auto& e : labelled.images) {
    const auto it = by_name.find(fs::path(e.path).filename().string());
    ASSERT_NE(it, by_name.end()) << e.path;
    ASSERT_EQ(it->second->segments.size(), e.segments.size()) << e.path;
    for (std::size_t i = 0; i < e.segments.size(); ++i) {
      ASSERT_FLOAT_EQ(it->second->segments[i].x0, e.segments[i].x0);
      ++total;
      unlabelled += e.segments[i].label == Label::Unlabelled;
      agree += e.segments[i].label == it->second->segments[i].label;
      ++confusion[std::string(to_string(it->second->segments[i].label)) + "->" + std::string(to_string(e.segments[i].label))];
    }
  }
  EXPECT_EQ(total, segments);
  EXPECT_EQ(unlabelled, 0u);
  const double agreement = static_cast<double>(agree) / static_cast<double>(total);
  EXPECT_GE(agreement, 0.91);
  std::printf("review walk-through: %zu segments in %zu images labelled with %d key presses and 0 clicks "
              "(one click per segment: %zu); %.1f %% agree with the ground truth\n",
              total, labelled.images.size(), keys, total, 100 * agreement);
  for (const auto& [pair, n] : confusion) std::printf("  %s: %d\n", pair.c_str(), n);
}

}  // namespace
