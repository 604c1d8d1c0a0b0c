// The review loop walked through on the built-in demo, as a user at a venue would: open it,
// P, then on each image correct the proposals that are wrong (one label key each) and Enter,
// with auto-train retraining in the background after every change. The user's corrections
// come from the frames' exact ground truth, so the project ends fully and correctly labelled;
// the test counts the actions against one per segment, and prints the final test-split figures
// (docs/studio.md, "Reviewing proposals").
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "fieldlines/data/project.hpp"
#include "fieldlines/synth/demo.hpp"
#include "fieldlines/synth/gt_eval.hpp"
#include "fieldlines/synth/synth.hpp"
#include "fixtures.hpp"
#include "gui/model/studio_controller.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;
using fieldlines::Project;

namespace {

// The ground-truth label of every segment of every image.
std::vector<std::vector<Label>> truth_of(const Project& p, const std::filesystem::path& file) {
  std::vector<std::vector<Label>> truth;
  for (const fieldlines::ImageEntry& e : p.images) {
    std::vector<fieldlines::Segment> segs = e.segments;
    const auto gt = fieldlines::synth::load_truth(fieldlines::synth::truth_path(Project::resolve(file, e.path)));
    fieldlines::label_from_truth(segs, gt);
    std::vector<Label>& t = truth.emplace_back();
    for (const auto& s : segs) t.push_back(s.label);
  }
  return truth;
}

TEST(DemoWalkthrough, ProposeCorrectAndAcceptLabelsTheDemoInAFractionOfTheActions) {
  studio_test::TempDir dir("demo-walk");
  fieldlines::DemoParams demo;
  demo.folder = dir.path() / "demo";
  const std::filesystem::path file = fieldlines::ensure_demo(demo);
  const Project start = Project::load(file);
  const auto truth = truth_of(start, file);
  fs::ControllerOptions options;
  options.load_pixels = false;
  options.auto_train = true;
  fs::StudioController c(start, file, options);
  const std::size_t open_at_start = c.to_review();
  ASSERT_GT(open_at_start, 100u);

  std::size_t keys = 1, corrections = 0;  // P
  c.propose();
  for (std::size_t image = 0; image < c.image_count() && c.to_review() > 0; ++image) {
    c.wait_for_auto_train();  // a person takes seconds per image: the retraining is done
    const std::size_t i = c.current();
    for (std::size_t k = 0; k < c.segments().size(); ++k) {
      if (c.segments()[k].label != Label::Unlabelled || c.proposal(k) == truth[i][k]) continue;
      const std::size_t one[] = {k};
      ASSERT_TRUE(c.label(one, truth[i][k]));  // hover + M/B/N
      ++corrections;
    }
    c.accept_proposals();  // Enter
    ++keys;
  }
  c.wait_for_auto_train();
  ASSERT_EQ(c.to_review(), 0u);
  for (std::size_t i = 0; i < c.image_count(); ++i) {
    const auto& segs = c.project().images[i].segments;
    for (std::size_t k = 0; k < segs.size(); ++k) {
      if (i >= static_cast<std::size_t>(demo.labelled_images)) {
        ASSERT_EQ(segs[k].label, truth[i][k]) << i << " " << k;
      }
    }
  }
  const std::size_t actions = keys + corrections;
  const auto& test = c.test_counts();
  std::printf("demo walk-through: %zu unlabelled segments in %zu images; %zu actions (%zu keys, %zu corrections) "
              "against %zu (one per segment); test split (%zu segments): marking P %.3f R %.3f, "
              "boundary P %.3f R %.3f; %s\n",
              open_at_start, c.image_count() - static_cast<std::size_t>(demo.labelled_images), actions, keys,
              corrections, open_at_start, c.test_segment_count(), test.marking.precision(), test.marking.recall(),
              test.boundary.precision(), test.boundary.recall(), c.auto_train_summary().c_str());
  // Measured: 54 actions for 182 segments. The demo's frames hold few segments each (SSL at
  // a distance), so its test split is small (35 markings) and the length bound learned from
  // 46 train markings misses the short far ones there (recall 0.31, docs/studio.md): asserted is what
  // holds with margin, not what we would like.
  EXPECT_LT(actions * 3, open_at_start);
  EXPECT_GT(c.test_segment_count(), 100u);
  EXPECT_GE(test.marking.precision(), 0.9);
  EXPECT_GE(test.boundary.precision(), 0.8);
  EXPECT_GE(test.boundary.recall(), 0.8);
}

}  // namespace
