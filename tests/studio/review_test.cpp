// The studio's review loop without a window (gui/model/review.cpp): propose, accept with one
// key (one undo step), proposals never counted as labels, uncertain first, and training taking
// over from label-free proposals once a class has labels.
#include <gtest/gtest.h>

#include <cmath>

#include "fieldlines/data/project.hpp"
#include "review_fixture.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;
using fieldlines::Project;

namespace {

using Review = studio_test::ReviewProject;

TEST(StudioReview, ProposeThenAcceptOneImageAtATimeWithOneUndoStepEach) {
  Review r;
  fs::StudioController& c = *r.controller;
  const std::size_t total = c.to_review();
  ASSERT_GT(total, 1000u);
  const std::string summary = c.propose();
  EXPECT_NE(summary.find("label-free"), std::string::npos) << summary;
  // Proposals are saved, but never labels.
  const Project saved = Project::load(r.file);
  EXPECT_EQ(saved.labelled_count(), 0u);
  EXPECT_EQ(saved.images[0].proposals.size(), saved.images[0].segments.size());
  EXPECT_EQ(c.labelled_total(), 0u);
  EXPECT_EQ(c.to_review(), total);
  std::size_t agree = 0, proposed = 0;
  for (std::size_t i = 0; i < c.segments().size(); ++i) {
    proposed += c.proposal(i) != Label::Unlabelled;
    agree += c.proposal(i) == r.true_label(0, i);
  }
  EXPECT_EQ(proposed, c.segments().size());
  EXPECT_GE(static_cast<double>(agree) / static_cast<double>(proposed), 0.95);

  // Enter on image 0: its segments take their proposals, as one step, and the view moves on.
  ASSERT_EQ(c.current(), 0u);
  const std::size_t on_first = c.segments().size();
  EXPECT_EQ(c.accept_proposals(), on_first);
  EXPECT_EQ(c.current(), 1u);
  EXPECT_EQ(c.to_review(), total - on_first);
  EXPECT_EQ(Project::load(r.file).images[0].segments.size() - Project::load(r.file).labelled_count(), 0u);
  // A labelled segment shows no proposal any more.
  c.select_image(0);
  EXPECT_EQ(c.proposal(0), Label::Unlabelled);
  ASSERT_TRUE(c.undo());
  EXPECT_EQ(c.labelled_total(), 0u);
  EXPECT_EQ(c.proposal(0), Project::load(r.file).images[0].proposals[0]);
  ASSERT_TRUE(c.redo());
  EXPECT_EQ(c.labelled_total(), on_first);
  // A click still overrides a proposal before accepting: segment 0 of image 1 as boundary.
  c.select_image(1);
  const std::size_t first[] = {0};
  ASSERT_TRUE(c.label(first, Label::Boundary));
  EXPECT_EQ(c.accept_proposals(), c.project().images[1].segments.size() - 1);
  EXPECT_EQ(c.project().images[1].segments[0].label, Label::Boundary);
  EXPECT_EQ(c.current(), 2u);
  c.accept_proposals();
  EXPECT_EQ(c.to_review(), 0u);
  EXPECT_FALSE(c.focus_most_uncertain().has_value());
}

TEST(StudioReview, TabVisitsTheLeastCertainSegmentFirst) {
  Review r;
  fs::StudioController& c = *r.controller;
  c.propose();
  const auto focus = c.focus_most_uncertain();
  ASSERT_TRUE(focus.has_value());
  EXPECT_EQ(c.current(), focus->image);
  EXPECT_EQ(c.hovered(), focus->segment);
  EXPECT_EQ(c.take_focus_request(), focus->segment);
  EXPECT_FALSE(c.take_focus_request().has_value());  // taken once
  // Its image is the least certain one.
  for (std::size_t i = 0; i < c.image_count(); ++i)
    EXPECT_LE(c.image_uncertainty(focus->image), c.image_uncertainty(i)) << i;
  EXPECT_TRUE(std::isfinite(c.image_uncertainty(focus->image)));
  // Labelling it moves Tab elsewhere.
  const std::size_t one[] = {focus->segment};
  ASSERT_TRUE(c.label(one, r.true_label(focus->image, focus->segment)));
  const auto next = c.focus_most_uncertain();
  ASSERT_TRUE(next.has_value());
  EXPECT_FALSE(next->image == focus->image && next->segment == focus->segment);
}

TEST(StudioReview, LabelsTakeOverFromLabelFreeProposalsPerClass) {
  Review r;
  fs::StudioController& c = *r.controller;
  // Label 40 segments of image 0 with their true labels (markings and non-features among them).
  std::vector<std::size_t> marking, none;
  for (std::size_t i = 0; i < c.segments().size() && (marking.size() < 20 || none.size() < 20); ++i) {
    const Label t = r.true_label(0, i);
    if (t == Label::Marking && marking.size() < 20) marking.push_back(i);
    if (t == Label::None && none.size() < 20) none.push_back(i);
  }
  ASSERT_TRUE(c.label(marking, Label::Marking));
  ASSERT_TRUE(c.label(none, Label::None));
  const std::string summary = c.propose();
  EXPECT_NE(summary.find("marking trained"), std::string::npos) << summary;
  EXPECT_NE(summary.find("boundary label-free"), std::string::npos) << summary;
  EXPECT_EQ(c.labelled_total(), 40u);
}

}  // namespace

namespace {

TEST(StudioReview, ImageListOrderPutsTheLeastCertainFirstAndReviewedImagesLast) {
  Review r;
  fs::StudioController& c = *r.controller;
  c.propose();
  std::vector<std::size_t> order = c.images_by_uncertainty();
  ASSERT_EQ(order.size(), 3u);
  for (std::size_t k = 1; k < order.size(); ++k)
    EXPECT_LE(c.image_uncertainty(order[k - 1]), c.image_uncertainty(order[k]));
  // Review the least certain image: with nothing left on it, it moves to the end.
  const std::size_t first = order.front();
  c.select_image(first);
  c.accept_proposals();
  order = c.images_by_uncertainty();
  EXPECT_EQ(order.back(), first);
  EXPECT_TRUE(std::isinf(c.image_uncertainty(first)));
}

}  // namespace
