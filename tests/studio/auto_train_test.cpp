// Live retraining without a window (gui/model/live_training.cpp): with auto-train on, a label
// change retrains both classes in the background and the thresholds, proposals and learning
// curve follow; with it off, nothing moves.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "fieldlines/detect/classifier.hpp"
#include "review_fixture.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;
using fieldlines::Project;

namespace {

fs::ControllerOptions with_auto_train(bool on) {
  fs::ControllerOptions o;
  o.auto_train = on;
  return o;
}

// The review project, starting from thresholds that predict almost no marking (what auto-train
// has to correct); `start` keeps them.
struct Blind {
  explicit Blind(bool auto_train) : r(with_auto_train(auto_train)), c(*r.controller) {
    fieldlines::Thresholds t = c.thresholds();
    t.marking.thresholds.max_angle_deg = 3;
    c.set_thresholds(t);
    start = c.thresholds();
  }
  studio_test::ReviewProject r;
  fs::StudioController& c;
  fieldlines::Thresholds start;
};

// Labels `per_class` true markings and as many unlabelled non-features of image 0 from segment `from`
// on (two undo steps; image 0 holds its markings first, at 0..199).
std::size_t label_truth(studio_test::ReviewProject& r, std::size_t per_class, std::size_t from = 0) {
  fs::StudioController& c = *r.controller;
  std::vector<std::size_t> marking, none;
  for (std::size_t i = from; i < c.segments().size() && (marking.size() < per_class || none.size() < per_class); ++i) {
    if (c.segments()[i].label != Label::Unlabelled) continue;
    const Label t = r.true_label(0, i);
    if (t == Label::Marking && marking.size() < per_class) marking.push_back(i);
    if (t == Label::None && none.size() < per_class) none.push_back(i);
  }
  EXPECT_TRUE(c.label(marking, Label::Marking));
  EXPECT_TRUE(c.label(none, Label::None));
  return marking.size() + none.size();
}

// Share of image 1's segments (all unlabelled) whose prediction matches the truth, per class.
double marking_recall_on_image1(studio_test::ReviewProject& r) {
  fs::StudioController& c = *r.controller;
  c.select_image(1);
  std::size_t markings = 0, found = 0;
  for (std::size_t i = 0; i < c.segments().size(); ++i) {
    if (r.true_label(1, i) != Label::Marking) continue;
    ++markings;
    found += c.predictions()[i] == Label::Marking;
  }
  c.select_image(0);
  return markings ? static_cast<double>(found) / static_cast<double>(markings) : 0;
}

TEST(StudioAutoTrain, OffLeavesTheThresholdsAlone) {
  Blind b(false);
  auto& [r, c, start] = b;
  label_truth(r, 20);
  c.wait_for_auto_train();
  EXPECT_FALSE(c.auto_train_busy());
  EXPECT_EQ(c.thresholds(), start);
  EXPECT_TRUE(c.learning_curve().empty());
}

TEST(StudioAutoTrain, ALabelChangeRetrainsAndPredictionsFollowTheLabels) {
  Blind b(true);
  auto& [r, c, start] = b;
  const double before = marking_recall_on_image1(r);
  EXPECT_LT(before, 0.2);
  const std::size_t labelled = label_truth(r, 20);
  c.wait_for_auto_train();
  EXPECT_GT(c.thresholds().marking.thresholds.max_angle_deg, 15);
  // Markings of an image no one labelled are now found.
  EXPECT_GT(marking_recall_on_image1(r), 0.9);
  ASSERT_FALSE(c.learning_curve().empty());
  EXPECT_EQ(c.learning_curve().back().labelled, labelled);
  EXPECT_NE(c.auto_train_summary().find("marking trained"), std::string::npos) << c.auto_train_summary();
  // The thresholds reach the project file like any threshold change.
  c.flush();
  EXPECT_EQ(Project::load(r.file).thresholds, c.thresholds());
}

TEST(StudioAutoTrain, ProposalsAreRemadeWithTheRetrainedThresholds) {
  Blind b(true);
  auto& [r, c, start] = b;
  c.propose();
  label_truth(r, 20);
  c.wait_for_auto_train();
  c.select_image(1);
  for (std::size_t i = 0; i < c.segments().size(); ++i)
    ASSERT_EQ(c.proposal(i), fieldlines::classify(c.segments()[i], c.thresholds())) << i;
  // Accepting them labels with what the retrained classifier says.
  const std::size_t open = c.segments().size();
  EXPECT_EQ(c.accept_proposals(), open);
}

TEST(StudioAutoTrain, ALabelChangeDuringARetrainingStartsAnotherWithAllLabels) {
  studio_test::ReviewProject r(with_auto_train(true));
  fs::StudioController& c = *r.controller;
  std::size_t labelled = label_truth(r, 10);
  c.poll();  // starts the first retraining
  EXPECT_TRUE(c.auto_train_busy());
  labelled += label_truth(r, 10, 100);  // while it runs
  c.wait_for_auto_train();
  ASSERT_FALSE(c.learning_curve().empty());
  EXPECT_EQ(c.learning_curve().back().labelled, labelled);
  EXPECT_EQ(c.labelled_total(), labelled);
}

TEST(StudioAutoTrain, TurnedOffWhileRunningKeepsTheUsersThresholds) {
  Blind b(true);
  auto& [r, c, start] = b;
  label_truth(r, 20);
  c.poll();
  c.set_auto_train(false);
  for (int i = 0; i < 10000 && c.auto_train_busy(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    c.poll();
  }
  EXPECT_FALSE(c.auto_train_busy());
  EXPECT_EQ(c.thresholds(), start);
  // Turned on again: it catches up with the labels made meanwhile.
  c.set_auto_train(true);
  c.wait_for_auto_train();
  EXPECT_NE(c.thresholds(), start);
}

TEST(StudioAutoTrain, UndoRetrainsToo) {
  studio_test::ReviewProject r(with_auto_train(true));
  fs::StudioController& c = *r.controller;
  label_truth(r, 20);
  c.wait_for_auto_train();
  const std::size_t points = c.learning_curve().size();
  ASSERT_TRUE(c.undo());
  c.wait_for_auto_train();
  EXPECT_EQ(c.learning_curve().size(), points + 1);
  EXPECT_EQ(c.learning_curve().back().labelled, c.labelled_total());
}

}  // namespace
