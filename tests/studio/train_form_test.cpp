// The Train tab's form without a window: Start/Stop, Apply with nothing to apply, and the
// "applied" line, shown while the applied thresholds hold and gone once they change.
#include <gtest/gtest.h>

#include "fieldlines/data/project.hpp"
#include "fixtures.hpp"
#include "gui/model/figures.hpp"
#include "gui/model/studio_controller.hpp"
#include "gui/model/train_form.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;

namespace {
// Six images of twelve segments, every one labelled (markings even, boundaries odd).
struct Labelled {
  Labelled() : dir("train-form"), file(studio_test::write_project(dir.path(), 6, 12)) {
    fieldlines::Project p = fieldlines::Project::load(file);
    for (auto& image : p.images) {
      for (std::size_t i = 0; i < image.segments.size(); ++i) {
        image.segments[i].label = i % 2 ? Label::Boundary : Label::Marking;
        image.segments[i].saliency = static_cast<float>(100 + 20 * i);
      }
    }
    p.save(file);
  }
  studio_test::TempDir dir;
  std::filesystem::path file;
};
}  // namespace

TEST(TrainForm, DefaultsAreTheCliTrainingAndApplyNeedsAResult) {
  Labelled data;
  fs::StudioController c(fieldlines::Project::load(data.file), data.file);
  fs::TrainForm form;
  EXPECT_EQ(form.params.pso.iterations, fieldlines::protocol_spec(fieldlines::Protocol::Ours).train.pso.iterations);
  EXPECT_FALSE(form.apply(c));  // nothing trained yet
  EXPECT_TRUE(form.applied_message(c).empty());
}

TEST(TrainForm, ToggleStartsAndStopsAndApplyReportsUntilTheThresholdsChange) {
  Labelled data;
  fs::StudioController c(fieldlines::Project::load(data.file), data.file);
  auto t = c.thresholds();
  t.marking.thresholds.min_length = 300;  // misses most markings: training lowers it
  c.set_thresholds(t);
  fs::TrainForm form;
  form.params.target = fieldlines::TrainClass::Marking;
  form.params.pso.particles = 10;
  form.params.pso.iterations = 200000;  // far more than the test waits for: only Stop ends it
  form.params.polish = false;
  form.toggle(c);
  ASSERT_TRUE(c.training().running());
  form.toggle(c);  // Stop: ends early with the best so far
  c.training().wait();
  ASSERT_TRUE(c.training().outcome().has_value());
  EXPECT_TRUE(c.training().outcome()->value().run.cancelled);

  form.params.pso.iterations = 10;
  form.toggle(c);
  c.training().wait();
  ASSERT_TRUE(form.apply(c));
  EXPECT_EQ(c.thresholds(), c.training().outcome()->value().run.thresholds);
  ASSERT_GT(c.test_segment_count(), 0u);
  EXPECT_EQ(form.applied_message(c), fs::applied_summary(c.test_counts(), "test"));
  auto moved = c.thresholds();
  moved.boundary.thresholds.min_length += 5;  // a slider: the line no longer describes them
  c.set_thresholds(moved);
  EXPECT_TRUE(form.applied_message(c).empty());
}
