// Figures honest for few images (gui/model/leave_one_out.hpp): below five test images the studio
// says so, and auto-train adds leave-one-image-out figures pooled over every labelled image.
#include <gtest/gtest.h>

#include <vector>

#include "fieldlines/train/protocols.hpp"
#include "gui/model/leave_one_out.hpp"
#include "review_fixture.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;

namespace {

// Labels the first `n` segments of each of the first `images` images with their true labels.
void label_truly(studio_test::ReviewProject& r, std::size_t images, std::size_t n) {
  fs::StudioController& c = *r.controller;
  for (std::size_t img = 0; img < images; ++img) {
    c.select_image(img);
    for (const Label l : {Label::Marking, Label::Boundary, Label::None}) {
      std::vector<std::size_t> of_l;
      for (std::size_t i = 0; i < n; ++i)
        if (r.true_label(img, i) == l) of_l.push_back(i);
      c.label(of_l, l);
    }
  }
}

TEST(StudioLeaveOneOut, FewerThanFiveTestImagesAreNotEnoughToJudge) {
  EXPECT_EQ(fs::not_enough_to_judge(1), "1 test image: not enough to judge");
  EXPECT_EQ(fs::not_enough_to_judge(4), "4 test images: not enough to judge");
  EXPECT_EQ(fs::not_enough_to_judge(5), "");
  EXPECT_EQ(fs::not_enough_to_judge(40), "");
}

TEST(StudioLeaveOneOut, EachLabelledImageIsHeldOutOnceAndItsCountsPooled) {
  studio_test::ReviewProject r;
  label_truly(r, 3, 120);
  const fieldlines::LabelledSet labelled = r.controller->project().labelled();
  std::vector<fieldlines::Segment> all;
  for (const auto& e : r.controller->project().images) all.insert(all.end(), e.segments.begin(), e.segments.end());
  fieldlines::ProposalParams params;
  params.train = fieldlines::protocol_spec(fieldlines::Protocol::Ours).train;
  const fieldlines::Calibration fit = fieldlines::calibrate(all);
  const fs::LeaveOneOut loo = fs::leave_one_image_out(fit, labelled, {}, params);
  EXPECT_EQ(loo.images, 3u);
  // Every labelled marking is counted once, as found or missed, on the image that held it.
  EXPECT_EQ(static_cast<std::size_t>(loo.pooled.marking.tp + loo.pooled.marking.fn), labelled.count(Label::Marking));
  EXPECT_EQ(static_cast<std::size_t>(loo.pooled.boundary.tp + loo.pooled.boundary.fn), labelled.count(Label::Boundary));
  EXPECT_GT(loo.pooled.marking.f1(), 0.8);
  // One labelled image has nothing to hold out against.
  EXPECT_EQ(fs::leave_one_image_out(fit, labelled.subset(std::vector<std::size_t>{0, 1, 2}), {}, params).images, 0u);
}

TEST(StudioLeaveOneOut, AutoTrainGivesLeaveOneOutFiguresWhileTheTestSplitHasTooFewImages) {
  fs::ControllerOptions options;
  options.auto_train = true;
  studio_test::ReviewProject r(options);
  fs::StudioController& c = *r.controller;
  label_truly(r, 3, 60);
  c.wait_for_auto_train();
  ASSERT_LT(c.test_image_count(), fs::kMinTestImages);
  EXPECT_EQ(c.leave_one_out().images, 3u);
  ASSERT_FALSE(c.learning_curve().empty());
  EXPECT_TRUE(c.learning_curve().back().leave_one_out);
  EXPECT_TRUE(c.learning_curve().back().judged);
  EXPECT_EQ(c.learning_curve().back().test, c.leave_one_out().pooled);
}

}  // namespace
