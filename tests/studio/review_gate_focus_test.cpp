// Tab's "least certain first" (gui/model/review.cpp) on a detected folder: a segment the robot's
// gates decide (proposal_gate.hpp: neither class may be it) is proposed None whatever its
// colours, so Tab visits every segment whose proposal its colours decide first, and the decided
// ones after them.

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "fixtures.hpp"
#include "gui/model/open_project.hpp"
#include "gui/model/studio_controller.hpp"
#include "tests/test_paths.hpp"

using fieldlines::Label;

namespace {

TEST(StudioReview, TabVisitsTheSegmentsTheGatesLeaveOpenFirst) {
  studio_test::TempDir dir("gate-focus");
  const std::filesystem::path frames = dir.path() / "frames";
  const std::string command = fieldlines::test::cli_path().string() + " synth --scene ssl --n 3 --seed 5 --quiet -o " +
                              frames.string() + " > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  fieldlines::studio::OpenedProject opened = fieldlines::studio::open_project(frames);
  fieldlines::studio::ControllerOptions options;
  options.load_pixels = false;
  options.auto_train = false;
  fieldlines::studio::StudioController c(std::move(opened.project), opened.file, options);
  c.detect_all(true);
  c.detection().wait();
  c.poll();
  ASSERT_EQ(c.detection_report().detected, 3u) << c.detection_report().summary();
  c.propose();

  std::size_t open = 0, decided = 0;
  for (std::size_t img = 0; img < c.image_count(); ++img) {
    const auto& gate = c.proposal_gate(img);
    ASSERT_TRUE(gate.covers(c.project().images[img].segments.size()));
    for (std::size_t i = 0; i < c.project().images[img].segments.size(); ++i) (gate.decided(i) ? decided : open) += 1;
  }
  ASSERT_GT(open, 0u);
  ASSERT_GT(decided, 0u) << "the frames give segments the gates decide";

  // Tab, then a label, until every open segment is labelled: never a decided one before.
  for (std::size_t k = 0; k < open; ++k) {
    const auto focus = c.focus_most_uncertain();
    ASSERT_TRUE(focus.has_value());
    ASSERT_FALSE(c.proposal_gate(focus->image).decided(focus->segment)) << "after " << k << " of " << open;
    const std::size_t one[] = {focus->segment};
    ASSERT_TRUE(c.label(one, Label::None));
  }
  // Then the decided ones, still reachable.
  const auto focus = c.focus_most_uncertain();
  ASSERT_TRUE(focus.has_value());
  EXPECT_TRUE(c.proposal_gate(focus->image).decided(focus->segment));
}

}  // namespace
