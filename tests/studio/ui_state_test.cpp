// The studio's window state without a window: what the shortcut table's keys do to the
// controller and the UI state (gui/model/shortcut_actions.hpp), and which picture the canvas's
// texture must hold (CanvasState::picture_to_upload).
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "fieldlines/data/project.hpp"
#include "fixtures.hpp"
#include "gui/model/camera_tuning.hpp"
#include "gui/model/shortcut_actions.hpp"
#include "gui/model/studio_controller.hpp"
#include "gui/model/ui_state.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;
using fieldlines::Project;

namespace {

struct Session {
  Session() : dir("ui-state"), file(studio_test::write_project(dir.path(), 2, 6)), controller(Project::load(file), file) {}
  // Presses the table's key for `action` (the first row that has one).
  void press(fs::Action action, int tab = -1) {
    for (const fs::Shortcut& s : fs::shortcuts()) {
      if (s.action == action && (tab < 0 || s.tab == tab)) return fs::run_shortcut(s, controller, ui);
    }
    FAIL() << "no shortcut for the action";
  }
  studio_test::TempDir dir;
  std::filesystem::path file;
  fs::StudioController controller;
  fs::UiState ui;
};

}  // namespace

TEST(ShortcutActions, LabelKeysLabelTheHoveredSegmentAndUndoRedoFollow) {
  Session s;
  s.controller.set_hovered(3);
  s.press(fs::Action::LabelBoundary);
  EXPECT_EQ(s.controller.segments()[3].label, Label::Boundary);
  s.press(fs::Action::Undo);
  EXPECT_EQ(s.controller.segments()[3].label, Label::Unlabelled);
  s.press(fs::Action::Redo);
  EXPECT_EQ(Project::load(s.file).images[0].segments[3].label, Label::Boundary);
  s.press(fs::Action::LabelClear);
  EXPECT_EQ(s.controller.segments()[3].label, Label::Unlabelled);
}

TEST(ShortcutActions, TabsImagesQuitAndTheStatusLine) {
  Session s;
  s.ui.panel_request_pending = false;
  s.press(fs::Action::ShowTab, 5);
  EXPECT_EQ(s.ui.requested_panel, fs::Panel::Export);
  EXPECT_TRUE(s.ui.panel_request_pending);
  EXPECT_STREQ(fs::panel_name(s.ui.requested_panel), "Export");
  s.press(fs::Action::NextImage);
  EXPECT_EQ(s.controller.current(), 1u);
  s.press(fs::Action::PreviousImage);
  EXPECT_EQ(s.controller.current(), 0u);
  s.ui.image_view.fit_requested = false;
  s.press(fs::Action::Fit);
  EXPECT_TRUE(s.ui.image_view.fit_requested);
  s.press(fs::Action::Propose);
  EXPECT_NE(s.ui.status_message.find("proposals"), std::string::npos) << s.ui.status_message;
  s.press(fs::Action::AcceptProposals);
  EXPECT_EQ(s.ui.status_message, "accepted 6 proposals");
  EXPECT_FALSE(s.ui.quit_requested);
  s.press(fs::Action::Quit);
  EXPECT_TRUE(s.ui.quit_requested);
}

// A nudge key brings up the Camera tab; without a camera it says how to get one and changes
// nothing; with one it moves it one step, and the limits hold however long the key is held.
TEST(ShortcutActions, NudgeKeysMoveTheCameraOneStepOnTheCameraTab) {
  Session s;
  const auto press_nudge = [&](fs::CameraAxis axis, int direction) {
    for (const fs::Shortcut& sc : fs::shortcuts())
      if (sc.action == fs::Action::NudgeCamera && sc.nudge.axis == axis && sc.nudge.direction == direction)
        return fs::run_shortcut(sc, s.controller, s.ui);
    FAIL() << "no nudge key";
  };
  s.ui.panel_request_pending = false;
  press_nudge(fs::CameraAxis::Pitch, -1);
  EXPECT_EQ(s.ui.requested_panel, fs::Panel::Camera);
  EXPECT_TRUE(s.ui.panel_request_pending);
  EXPECT_FALSE(s.controller.camera().has_value());
  EXPECT_NE(s.ui.status_message.find("no camera"), std::string::npos) << s.ui.status_message;
  s.controller.set_camera(fs::typical_camera(320, 240));
  const fs::CameraPose before = fs::pose_of(*s.controller.camera());
  press_nudge(fs::CameraAxis::Pitch, -1);
  press_nudge(fs::CameraAxis::Roll, 1);
  press_nudge(fs::CameraAxis::Height, 1);
  const fs::CameraPose after = fs::pose_of(*s.controller.camera());
  EXPECT_NEAR(after.pitch_deg, before.pitch_deg - fs::kAngleStepDeg, 1e-9);
  EXPECT_NEAR(after.roll_deg, before.roll_deg + fs::kAngleStepDeg, 1e-9);
  EXPECT_NEAR(after.height_cm, before.height_cm + fs::kHeightStepCm, 1e-9);
  for (int held = 0; held < 3000; ++held) press_nudge(fs::CameraAxis::Height, -1);
  EXPECT_NEAR(fs::pose_of(*s.controller.camera()).height_cm, fs::kMinHeightCm, 1e-9);
}

TEST(ShortcutActions, TabHoversTheLeastCertainUntilNothingIsLeft) {
  Session s;
  s.press(fs::Action::FocusUncertain);
  ASSERT_TRUE(s.controller.hovered().has_value());
  EXPECT_TRUE(s.ui.status_message.empty());
  for (std::size_t image = 0; image < 2; ++image) {
    s.controller.select_image(image);
    s.controller.label_rest_as_none();
  }
  s.press(fs::Action::FocusUncertain);
  EXPECT_EQ(s.ui.status_message, "nothing left to review");
}

TEST(ShortcutActions, SpaceReleasesTabsSegmentOnlyWhenItHasAnotherToGoTo) {
  Session s;
  const auto segments = s.controller.segments();
  fs::CanvasState& canvas = s.ui.image_view;
  canvas.focus.hold(0, 4);
  const std::vector<std::size_t> one{1};
  canvas.cycle.update(0, one, segments);
  s.press(fs::Action::NextUnderCursor);  // a single segment under the cursor: nothing to cycle to
  EXPECT_EQ(canvas.focus.held(), 4u);
  const std::vector<std::size_t> two{1, 2};
  canvas.cycle.update(0, two, segments);
  s.press(fs::Action::NextUnderCursor);
  EXPECT_FALSE(canvas.focus.held().has_value());
  EXPECT_EQ(canvas.cycle.update(0, two, segments), 2u);
}

TEST(ShortcutActions, FeatureKeysToggleTheirLayerAndLeaveLabelsAlone) {
  Session s;
  s.controller.set_hovered(0);
  const Project before = s.controller.project();
  fs::FeatureLayers expected;
  for (const fs::FeatureLayer layer : fs::kFeatureLayers) {
    const fs::Shortcut* key = nullptr;
    for (const fs::Shortcut& sc : fs::shortcuts())
      if (sc.action == fs::Action::ToggleFeatureLayer && sc.layer == layer) key = &sc;
    ASSERT_NE(key, nullptr) << fs::feature_layer_name(layer);
    fs::run_shortcut(*key, s.controller, s.ui);
    expected.set(layer, true);
    EXPECT_EQ(s.ui.image_view.settings.features, expected);
  }
  for (const fs::Shortcut& sc : fs::shortcuts())
    if (sc.action == fs::Action::ToggleFeatureLayer) fs::run_shortcut(sc, s.controller, s.ui);
  EXPECT_FALSE(s.ui.image_view.settings.features.any());  // pressed again: off
  EXPECT_EQ(s.controller.hovered(), std::optional<std::size_t>{0});
  ASSERT_EQ(s.controller.project().images[0].segments.size(), before.images[0].segments.size());
  for (std::size_t i = 0; i < before.images[0].segments.size(); ++i)
    EXPECT_EQ(s.controller.project().images[0].segments[i].label, before.images[0].segments[i].label);
  EXPECT_FALSE(s.controller.can_undo());  // a view change, not an edit
}

TEST(CanvasState, HandsOutThePictureOncePerChange) {
  Session s;
  fs::CanvasState canvas;
  const cv::Mat* first = canvas.picture_to_upload(s.controller);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->cols, 320);
  EXPECT_EQ(canvas.picture_to_upload(s.controller), nullptr);  // up to date: no upload per frame
  s.controller.next_image();
  ASSERT_NE(canvas.picture_to_upload(s.controller), nullptr);
  EXPECT_EQ(canvas.picture_to_upload(s.controller), nullptr);
  // "Paint with no segment": the tinted copy, once; off again: the plain image, once.
  canvas.show_missed = true;
  const cv::Mat* tinted = canvas.picture_to_upload(s.controller);
  ASSERT_NE(tinted, nullptr);
  EXPECT_EQ(tinted, &canvas.missed.tinted());
  EXPECT_EQ(canvas.picture_to_upload(s.controller), nullptr);
  canvas.show_missed = false;
  EXPECT_EQ(canvas.picture_to_upload(s.controller), &s.controller.image());
  canvas.reupload();  // a new session
  EXPECT_EQ(canvas.picture_to_upload(s.controller), &s.controller.image());
}
