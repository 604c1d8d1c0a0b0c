// The labelling keys in the real window whatever ImGui widget had focus last: a click in the
// side panel gives ImGui's keyboard focus to that panel, where Tab would otherwise move into the
// Label tab's "line width" field and turn it into a text box (every shortcut is off while text
// is typed). And the segment Tab brought up stays the hovered one while the pointer rests on
// another segment: only a pointer that moves takes the hover back.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <thread>

#include <opencv2/imgcodecs.hpp>

#include "fieldlines/data/project.hpp"
#include "x_session.hpp"

using fieldlines::Label;
using namespace std::chrono_literals;

namespace {

using studio_test::run;
using studio_test::wait_for;

class StudioKeysWindow : public studio_test::StudioUnderX {
 protected:
  void SetUp() override {
    StudioUnderX::SetUp();
    use_project(1, 12);
  }
  // Presses Tab and waits until the studio hovers the segment it chose; returns that segment.
  long tab_to_uncertain() {
    const auto before = state()["hovered"];
    EXPECT_EQ(run(x("key Tab")), 0);
    EXPECT_TRUE(wait_for([&] { return state()["hovered"].get<long>() >= 0 && state()["hovered"] != before; }, 10s))
        << "Tab hovered no other segment: " << state().dump();
    std::this_thread::sleep_for(300ms);  // a few frames: the hover must hold, not flicker back
    return state()["hovered"].get<long>();
  }
  Label saved_label(long segment) const {
    return fieldlines::Project::load(project_).images[0].segments[static_cast<std::size_t>(segment)].label;
  }
};

}  // namespace

TEST_F(StudioKeysWindow, TabThenLabelKeysWorkAfterAClickInTheSidePanel) {
  auto studio = start_studio();
  ASSERT_TRUE(studio->running()) << log();
  // Text in the Label tab's shortcut list, below every control: the click only focuses the panel.
  ASSERT_EQ(run(x("mousemove 1180 745 click 1")), 0);
  ASSERT_TRUE(wait_for([&] { return state()["panel"] == "Label" && state()["hovered"] == -1; }, 10s));
  std::this_thread::sleep_for(300ms);

  const long focused = tab_to_uncertain();
  ASSERT_GE(focused, 0);
  EXPECT_FALSE(state()["text_input"].get<bool>()) << "Tab put a text field into edit mode";
  act_and_wait_for_save("key p");  // proposals are saved with the project
  EXPECT_EQ(state()["hovered"], focused);
  act_and_wait_for_save("key m");
  EXPECT_EQ(saved_label(focused), Label::Marking);

  // The next Tab goes on to another unlabelled segment, and N labels that one.
  const long next = tab_to_uncertain();
  ASSERT_GE(next, 0);
  ASSERT_NE(next, focused);
  EXPECT_FALSE(state()["text_input"].get<bool>());
  act_and_wait_for_save("key n");
  EXPECT_EQ(saved_label(next), Label::None);
  EXPECT_EQ(saved_label(focused), Label::Marking);

  ASSERT_EQ(run(x("key ctrl+q")), 0);
  ASSERT_TRUE(wait_for([&] { return !studio->running(); }, 15s));
  EXPECT_EQ(studio->exit_code(), 0) << log();
}

TEST_F(StudioKeysWindow, TabKeepsItsSegmentWhileThePointerRestsOnAnother) {
  auto studio = start_studio();
  ASSERT_TRUE(studio->running()) << log();
  ASSERT_EQ(run(x("mousemove " + std::to_string(kWidth - 60) + " 780")), 0);  // on the status bar
  const long focused = tab_to_uncertain();
  ASSERT_GE(focused, 0);

  // Another segment on screen (in the view Tab centred), well apart from the focused one.
  std::optional<std::size_t> other;
  const auto [fx, fy] = on_screen(static_cast<std::size_t>(focused));
  for (std::size_t i = 0; i < segments_.size() && !other; ++i) {
    const auto [px, py] = on_screen(i);
    const bool inside = px > 20 && px < kWidth - 450 && py > 20 && py < kHeight - 60;
    if (static_cast<long>(i) != focused && inside && std::hypot(px - fx, py - fy) > 40) other = i;
  }
  ASSERT_TRUE(other) << "no second segment on screen";

  // The pointer moves onto it: that one is hovered (moving takes the hover back).
  hover(*other);
  // Tab again, the pointer resting on `other`: the focused segment is hovered and stays so.
  EXPECT_EQ(tab_to_uncertain(), focused);
  std::this_thread::sleep_for(300ms);
  EXPECT_EQ(state()["hovered"], focused);
  act_and_wait_for_save("key b");
  EXPECT_EQ(saved_label(focused), Label::Boundary);
  EXPECT_EQ(saved_label(static_cast<long>(*other)), Label::Unlabelled);

  // A pointer that moves (a pixel, still over `other`) hovers what is under it again.
  const auto [ox, oy] = on_screen(*other);
  ASSERT_EQ(run(x("mousemove " + std::to_string(ox + 1) + " " + std::to_string(oy))), 0);
  ASSERT_TRUE(wait_for([&] { return state()["hovered"] == static_cast<long>(*other); }, 10s)) << state().dump();

  ASSERT_EQ(run(x("key ctrl+q")), 0);
  ASSERT_TRUE(wait_for([&] { return !studio->running(); }, 15s));
  EXPECT_EQ(studio->exit_code(), 0) << log();
}

// A folder of one field picture: the studio detects it with the feature stages, and G I O S
// draw its features over the canvas (the pixels change) and take them off again.
TEST_F(StudioKeysWindow, FeatureKeysDrawTheDetectedFeaturesAndTakeThemOff) {
  fieldlines::Segment across, down;
  across.x0 = 40, across.y0 = 300, across.x1 = 600, across.y1 = 330;
  down.x0 = 300, down.y0 = 120, down.x1 = 330, down.y1 = 470;
  const std::filesystem::path folder = dir() / "frames";
  std::filesystem::create_directories(folder);
  cv::imwrite((folder / "field.png").string(), studio_test::field_image(640, 480, {across, down}));
  project_ = folder;
  auto studio = start_studio();
  ASSERT_TRUE(studio->running()) << log();
  ASSERT_TRUE(wait_for([&] { return state()["features"]["stripes"].get<int>() > 0; }, 30s)) << state().dump();
  EXPECT_TRUE(state()["feature_layers"].empty());  // off until asked for
  std::this_thread::sleep_for(300ms);
  const cv::Mat off = cv::imread(screenshot("features_off").string());

  ASSERT_EQ(run(x("mousemove 5 790 key g i o s")), 0);  // the pointer off the canvas: no hover halo
  ASSERT_TRUE(wait_for([&] { return state()["feature_layers"].size() == 4; }, 10s)) << state().dump();
  std::this_thread::sleep_for(300ms);
  const cv::Mat on = cv::imread(screenshot("features_on").string());
  ASSERT_EQ(on.size(), off.size());
  // The canvas (left of the side panel) changed where the features are drawn.
  const cv::Rect canvas(0, 0, 800, 700);
  cv::Mat diff;
  cv::absdiff(on(canvas), off(canvas), diff);
  EXPECT_GT(cv::countNonZero(diff.reshape(1)), 200) << "the features drew nothing";

  ASSERT_EQ(run(x("key g i o s")), 0);
  ASSERT_TRUE(wait_for([&] { return state()["feature_layers"].empty(); }, 10s)) << state().dump();
  ASSERT_EQ(run(x("key ctrl+q")), 0);
  ASSERT_TRUE(wait_for([&] { return !studio->running(); }, 15s));
  EXPECT_EQ(studio->exit_code(), 0) << log();
}
