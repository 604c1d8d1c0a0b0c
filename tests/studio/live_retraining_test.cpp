// Live retraining's bookkeeping without the controller: when a run is due, off keeps nothing
// pending, and a finished run adds one point to the learning curve and a summary.
#include <gtest/gtest.h>

#include <vector>

#include "gui/model/auto_train.hpp"

using fieldlines::Label;
using fieldlines::studio::AutoTrainInput;
using fieldlines::studio::LiveRetraining;

namespace {
// Ten markings and ten boundaries with the gradients the default thresholds classify.
AutoTrainInput input() {
  AutoTrainInput in;
  for (int i = 0; i < 20; ++i) {
    fieldlines::Segment s;
    s.x0 = 10, s.x1 = 200, s.y0 = s.y1 = static_cast<float>(10 * i);
    s.saliency = 200;
    const bool marking = i % 2 == 0;
    s.grad_y = marking ? std::array<float, 3>{-200, -100, -200} : std::array<float, 3>{0, 150, 0};
    s.label = marking ? Label::Marking : Label::Boundary;
    (i < 14 ? in.train : in.test).push_back(s);
    in.all.push_back(s);
  }
  return in;
}
}  // namespace

TEST(LiveRetraining, DueOnlyWhenOnAndLabelsChanged) {
  LiveRetraining live(false);
  live.labels_changed();
  EXPECT_FALSE(live.due());  // off: label changes are not remembered
  EXPECT_FALSE(live.busy());
  live.set_on(true);
  EXPECT_TRUE(live.due());  // catches up with the labels made while off
  live.skip();              // nothing to learn from
  EXPECT_FALSE(live.due());
  EXPECT_FALSE(live.busy());
  live.labels_changed();
  EXPECT_TRUE(live.due());
  live.set_on(false);
  EXPECT_FALSE(live.due());
  EXPECT_FALSE(live.poll().has_value());
}

TEST(LiveRetraining, AFinishedRunAddsACurvePointWhileOn) {
  LiveRetraining live(true);
  live.labels_changed();
  live.start(input());
  EXPECT_FALSE(live.due());  // running, and the change is taken
  live.wait();
  const auto result = live.poll();
  ASSERT_TRUE(result.has_value()) << live.summary();
  ASSERT_EQ(live.curve().size(), 1u);
  EXPECT_EQ(live.curve()[0].labelled, 20u);
  EXPECT_EQ(live.curve()[0].test_segments, 6u);
  EXPECT_NE(live.summary().find("retrained on 14 train-split labels"), std::string::npos) << live.summary();
  EXPECT_FALSE(live.poll().has_value());  // once

  // Turned off while a run goes: its result is not adopted and adds no point.
  live.start(input());
  live.set_on(false);
  live.wait();
  EXPECT_FALSE(live.poll().has_value());
  EXPECT_EQ(live.curve().size(), 1u);
}
