// The review loop without a window on synthetic frames from seeds no threshold or test was tuned
// on: `fieldlines synth` makes 20 frames, the folder is opened as the studio opens one
// (open_project, background detection with the feature stages), then P and one Enter per image
// with no correction, auto-train on as in the studio. Scored against the frames' exact ground
// truth (what `fieldlines autolabel` gives): the share of segments labelled, the share agreeing
// with the truth, and the precision of the accepted marking labels. Measured figures and the
// floors' margins: docs/studio.md ("Walk-through figures").

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "fieldlines/data/project.hpp"
#include "fieldlines/synth/gt_eval.hpp"
#include "fieldlines/synth/synth.hpp"
#include "fieldlines/synth/truth.hpp"
#include "fixtures.hpp"
#include "gui/model/open_project.hpp"
#include "gui/model/studio_controller.hpp"
#include "tests/shared_data.hpp"

using fieldlines::Label;

namespace {

struct UnseenSet {
  const char* scene;
  int seed;
  // Floors a little under the figures measured on this set (docs/studio.md): agreement 0.02 to
  // 0.03 under it (a whole percent); marking precision 0.95 where 1.000 was measured (one wrong
  // marking among 20 to 250 costs at most 0.05). The targets are 95 % labelled, 90 % agreeing
  // and 0.90 marking precision.
  double agree_floor, marking_precision_floor;
};

void PrintTo(const UnseenSet& set, std::ostream* os) { *os << set.scene << " seed " << set.seed; }

class ReviewUnseenSeeds : public ::testing::TestWithParam<UnseenSet> {};

TEST_P(ReviewUnseenSeeds, ProposeThenEnterPerImageWithNoCorrection) {
  const UnseenSet set = GetParam();
  studio_test::TempDir dir("unseen-seeds");
  const std::filesystem::path frames = dir.path() / "frames";
  const std::string command = fieldlines::test::cli_path().string() + " synth --scene " + set.scene +
                              " --n 20 --seed " + std::to_string(set.seed) + " --quiet -o " + frames.string() +
                              " > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;

  fieldlines::studio::OpenedProject opened = fieldlines::studio::open_project(frames);
  ASSERT_TRUE(opened.needs_detection);
  fieldlines::studio::ControllerOptions options;
  options.load_pixels = false;
  options.auto_train = true;  // the studio's default
  fieldlines::studio::StudioController c(std::move(opened.project), opened.file, options);
  c.detect_all(true);
  c.detection().wait();
  c.poll();
  ASSERT_EQ(c.detection_report().detected, 20u) << c.detection_report().summary();
  const std::size_t segments = c.to_review();
  ASSERT_GT(segments, 100u);

  c.propose();  // P
  std::size_t enters = 0;
  for (std::size_t image = 0; image < c.image_count() && c.to_review() > 0; ++image) {
    c.wait_for_auto_train();  // a person takes a moment per image: the retraining is done
    c.accept_proposals();     // Enter
    ++enters;
  }
  c.wait_for_auto_train();

  std::size_t total = 0, labelled = 0, agree = 0, marked = 0, marked_right = 0, true_markings = 0;
  std::map<std::string, int> confusion;  // "truth->accepted": where the disagreements are
  for (std::size_t i = 0; i < c.image_count(); ++i) {
    const fieldlines::ImageEntry& e = c.project().images[i];
    std::vector<fieldlines::Segment> truth = e.segments;
    const auto gt = fieldlines::synth::load_truth(
        fieldlines::synth::truth_path(fieldlines::Project::resolve(c.project_file(), e.path)));
    fieldlines::label_from_truth(truth, gt);
    for (std::size_t k = 0; k < e.segments.size(); ++k) {
      const Label got = e.segments[k].label, want = truth[k].label;
      ++total;
      labelled += got != Label::Unlabelled;
      agree += got == want;
      marked += got == Label::Marking;
      marked_right += got == Label::Marking && want == Label::Marking;
      true_markings += want == Label::Marking;
      if (got != want) ++confusion[std::string(to_string(want)) + "->" + std::string(to_string(got))];
    }
  }
  ASSERT_EQ(total, segments);
  const double labelled_share = static_cast<double>(labelled) / static_cast<double>(total);
  const double agreement = static_cast<double>(agree) / static_cast<double>(total);
  const double marking_precision = marked > 0 ? static_cast<double>(marked_right) / static_cast<double>(marked) : 0.0;
  std::printf("%s seed %d: %zu segments, P + %zu Enter: %.1f %% labelled, %.1f %% agree with the truth, "
              "marking precision %.3f (%zu of %zu), marking recall %.3f (of %zu)\n",
              set.scene, set.seed, total, enters, 100 * labelled_share, 100 * agreement, marking_precision,
              marked_right, marked, true_markings > 0 ? static_cast<double>(marked_right) / static_cast<double>(true_markings) : 0.0,
              true_markings);
  for (const auto& [pair, n] : confusion) std::printf("  %s: %d\n", pair.c_str(), n);
  EXPECT_GE(labelled_share, 0.95);
  EXPECT_GE(agreement, set.agree_floor);
  EXPECT_GE(marking_precision, set.marking_precision_floor);
  EXPECT_GT(marked, 0u);
}

INSTANTIATE_TEST_SUITE_P(Seeds, ReviewUnseenSeeds,
                         // Measured (agree, marking precision), with the detector chosen from the
                         // frames: ssl 4242 94.5 %, 1.000; ssl 777 89.5 %, 1.000 (the chosen
                         // detector's denser anchors add the 1 cm lines' short pieces, which the
                         // stripes check refuses: markings labelled right 38 -> 71, agreement 93.9 ->
                         // 89.5 %); kid 4242 94.2 %, 1.000; kid 777 96.2 %, 0.992.
                         ::testing::Values(UnseenSet{"ssl", 4242, 0.92, 0.95}, UnseenSet{"ssl", 777, 0.87, 0.95},
                                           UnseenSet{"kid", 4242, 0.93, 0.95}, UnseenSet{"kid", 777, 0.93, 0.95}),
                         [](const auto& info) {
                           return std::string(info.param.scene) + "_" + std::to_string(info.param.seed);
                         });

}  // namespace
