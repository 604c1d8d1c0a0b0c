#include "gui/model/shortcut_actions.hpp"

#include <optional>
#include <string>

#include "gui/model/camera_tuning.hpp"

namespace fieldlines::studio {

static_assert(static_cast<int>(Panel::Count) == 7, "the shortcut table's tabs are F1..F7");

void run_shortcut(const Shortcut& shortcut, StudioController& controller, UiState& ui) {
  switch (shortcut.action) {
    case Action::LabelMarking: controller.label_hovered(Label::Marking); break;
    case Action::LabelBoundary: controller.label_hovered(Label::Boundary); break;
    case Action::LabelNone: controller.label_hovered(Label::None); break;
    case Action::LabelClear: controller.label_hovered(Label::Unlabelled); break;
    case Action::NextUnderCursor:
      if (ui.image_view.cycle.next()) ui.image_view.focus.release();  // back to the cursor's segments
      break;
    case Action::Fit: ui.image_view.fit_requested = true; break;
    case Action::PreviousImage: controller.previous_image(); break;
    case Action::NextImage: controller.next_image(); break;
    case Action::NextImageWithErrors: controller.next_image_with_errors(); break;
    case Action::Propose: ui.status_message = controller.propose(); break;
    case Action::AcceptProposals: {
      const std::size_t n = controller.accept_proposals();
      ui.status_message = "accepted " + std::to_string(n) + " proposals";
      break;
    }
    case Action::FocusUncertain:
      if (!controller.focus_most_uncertain()) ui.status_message = "nothing left to review";
      break;
    case Action::ToggleFeatureLayer:
      if (shortcut.layer != FeatureLayer::Count) ui.image_view.settings.features.toggle(shortcut.layer);
      break;
    case Action::NudgeCamera:
      // On the Camera tab, where the grid over the frame shows what the key did.
      ui.show(Panel::Camera);
      if (const std::optional<GroundCamera>& camera = controller.camera())
        controller.set_camera(with_pose(*camera, nudged(pose_of(*camera), shortcut.nudge)));  // clamped: valid
      else
        ui.status_message = "no camera to nudge: load one or start from a typical camera in the Camera tab (F7)";
      break;
    case Action::Undo: controller.undo(); break;
    case Action::Redo: controller.redo(); break;
    case Action::ToggleTraining:
      ui.training.toggle(controller);
      ui.show(Panel::Train);
      break;
    case Action::ShowTab: ui.show(static_cast<Panel>(shortcut.tab)); break;
    case Action::Quit: ui.quit_requested = true; break;
    case Action::Pointer: break;  // mouse inputs are the image view's
  }
}

}  // namespace fieldlines::studio
